"""A scene loaded and solved for a command: what goes wrong told as one :class:`UserError` line with its
exit code, and the results table as plain text (what ``render``, ``solve`` and ``check`` print)."""

from __future__ import annotations

import warnings
from dataclasses import replace
from pathlib import Path

from constructions.errors import ConstructionError, IndeterminatePosition

from ..scene.reader import SceneError, load_scene
from ..scene.textsafe import one_line, shown_path
from ..scene.units import from_si, unit_symbol
from ..study.study import Study

EXIT_DISAGREE = 1
EXIT_INPUT = 2
EXIT_SINGULAR = 3


class UserError(Exception):
    """Anything the user can fix; printed as one line.  ``code`` is the exit code: 2 for bad input,
    3 for a singular position (toggle, change point, limit position) where a polygon cannot close."""

    def __init__(self, message: str, code: int = EXIT_INPUT) -> None:
        super().__init__(one_line(message, cut_quotes=False))    # escaped and bounded: one line
        self.code = code


def load_study(path: Path, paper: str | None = None) -> Study:
    try:
        scene = load_scene(path)
    except SceneError as e:
        raise UserError(str(e)) from None
    return Study(scene if paper is None else replace(scene, paper=paper))


def solve_study(study: Study) -> Study:
    """Run what the scene asks for; construction errors become one sentence naming the file (exit 3 at
    a singular position, whose message names its kind, else 2), and so does a numeric warning (an overflow
    or an invalid value numpy would print with its own path), exit 2."""
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("error", RuntimeWarning)     # numpy's overflow or invalid value: no raw warning
            study.run()
    except RuntimeWarning as e:
        raise UserError(f"{shown_path(study.scene.path)}: solving this scene went out of the numbers' range ({e}); a value "
                        f"of the scene is far from what a mechanism has") from None
    except SceneError as e:                  # what the scene asks for, found wrong once solved (ask.find)
        raise UserError(str(e)) from None
    except IndeterminatePosition as e:
        raise UserError(f"{shown_path(study.scene.path)}: {located(study, e)}", EXIT_SINGULAR) from None
    except ConstructionError as e:
        raise UserError(f"{shown_path(study.scene.path)}: {located(study, e)}") from None
    return study


def located(study: Study, e: ConstructionError) -> str:
    """The error with the position it happened at: the engine's, else the scene's crank angle."""
    if e.position:
        return str(e)
    try:
        u = study.scene.units.angle
        sym = unit_symbol(u)                       # written as the engine's own messages write it
        where = f"crank angle {from_si(study.scene.angle, 'angle', u):.6g} {'deg' if sym == chr(0xb0) else sym}"
    except Exception:
        where = "the given crank angle"
    return f"at {where}: {e}"


def results_text(study: Study) -> str:
    """The results table as aligned plain text."""
    table = study.table()
    if not len(table):
        return f"{study.scene.title}\n  (no results to compare: the scene asks for {', '.join(study.scene.analyses)})"
    lines = [study.scene.title] + ["  " + line for line in table.lines()]
    bad = study.disagreements()
    model = study.model
    if model:
        widest = max(c.tolerance for c in study.comparisons)
        agree = "agree to 1e-9 relative" if widest <= 1e-9 else \
            f"agree within tolerances widened near the singular position (up to {widest:.0e} relative)"
        lines.append(f"  graphical vs analytic ({model}): "
                     + (agree if not bad else f"{len(bad)} DISAGREE beyond their tolerance"))
    for n in study.notes:
        lines.append(f"  note: {n}")
    for w in study.warnings:
        lines.append(f"  warning: {w}")
    return "\n".join(lines)
