"""``drafting lint``: the sheet critic (:mod:`drafting.layout.critic`) over each scene's worked sheets -- one
line per finding, then a table of the findings per check for each scene and for all; ``--json`` for the
figures.  Exit 0 when no sheet has a finding, 1 when one has, 2 (or the scene's own code) when a scene
cannot be read, solved or laid out, told in one sentence as ``render`` tells it."""

from __future__ import annotations

import json
import sys
from pathlib import Path
from typing import Sequence

from constructions.errors import ConstructionError

from ..layout.critic import CHECKS, Finding, blank_fraction, criticise, tally
from ..render.errors import LayoutError
from ..study.worked import sheets_for
from .solving import UserError, load_study, located, solve_study
from ..scene.textsafe import shown_path

EXIT_FINDINGS = 1


def lint_scene(path: Path) -> list[tuple[tuple[int, int], float, list[Finding]]]:
    """Each worked sheet of the scene at ``path``: its number n/m, its blank fraction and its findings.
    Raises :class:`UserError` (one sentence naming the file) when the scene cannot be read, solved or
    laid out."""
    study = solve_study(load_study(path))
    try:
        sheets = sheets_for(study)
    except LayoutError as e:
        raise UserError(f"{shown_path(path)}: drawing.paper: {e}") from None
    except ConstructionError as e:
        raise UserError(f"{shown_path(path)}: {located(study, e)}") from None
    return [(s.number, blank_fraction(s), criticise(s)) for s in sheets]


def summary_table(rows: Sequence[tuple[str, dict[str, int]]]) -> str:
    """A plain-text table: one row per (name, counts per check), a column per check and the total."""
    heads = ["scene", *CHECKS, "total"]
    body = [[name, *(str(counts[c]) for c in CHECKS), str(sum(counts.values()))] for name, counts in rows]
    widths = [max(len(r[i]) for r in [heads, *body]) for i in range(len(heads))]

    def line(cells: list[str]) -> str:
        return "  ".join(c.ljust(w) if i == 0 else c.rjust(w) for i, (c, w) in enumerate(zip(cells, widths)))
    return "\n".join([line(heads), *(line(r) for r in body)])


def cmd_lint(scenes: Sequence[Path], as_json: bool = False) -> int:
    """Criticise every scene's sheets; a scene that cannot be read is reported in one line and the others
    are still criticised.  Exit: 2 (or the scene's code) for a scene not read, else 1 with findings, else 0."""
    status = 0
    rows: list[tuple[str, dict[str, int]]] = []
    every: list[Finding] = []
    report = []
    for path in scenes:
        try:
            pages = lint_scene(path)
        except UserError as e:
            print(f"drafting: error: {e}", file=sys.stderr)
            status = max(status, e.code)
            continue
        found = [f for _, _, fs in pages for f in fs]
        every += found
        rows.append((str(path), tally(found)))
        report.append({"scene": str(path), "counts": tally(found),
                       "sheets": [{"sheet": list(n), "blank": round(b, 4), "findings": [f.to_json() for f in fs]}
                                  for n, b, fs in pages]})
        if not as_json:
            for f in found:
                print(f.line(str(path)))
    if rows:
        if as_json:
            print(json.dumps({"checks": list(CHECKS), "scenes": report, "counts": tally(every)}, indent=2))
        else:
            print(summary_table(rows + [("all", tally(every))]))
    if status:
        return status
    return EXIT_FINDINGS if every else 0


def run_command(args) -> int:
    return cmd_lint(args.scenes, args.json)
