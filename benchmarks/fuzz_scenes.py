"""Hostile scenes through every command: mutate the gallery scenes the way an attacker or a careless
user would and run, for each, one ``drafting`` command chosen for its family kind, in-process, with
warnings as errors, counting what goes wrong per kind and per command.

    nice -n 10 python benchmarks/fuzz_scenes.py [-n 1000] [--seed 1] [--kinds cam,vary] [--show 3]

Family kinds and commands: :mod:`fuzz_commands` (solve, --json, --csv; render svg/pdf/png/html and
--lab; check and check --answers with a hostile answers file; lint; sweep --steps/--every/--csv for
linkages; export --tolerance for cams; batch for [vary] scenes; hostile option values: huge, NaN,
negative, 1e300).  Mutations of the scene (none for a quarter of the cases, else one to three,
:mod:`fuzz_mutations`): deep nesting (arrays, inline tables, dotted keys, table headers), huge counts
(pivots, links, sliders, points), huge integers, odd unicode and control characters in every string or
in the title and drawing number, arithmetic in unit strings, percent and dimensionless units, decimal
commas, duplicate sliders and point names, giant and tiny coordinates and lengths, long strings, odd
[vary] ranges, odd file names (spaces, newlines, escapes, bidi overrides, undecodable bytes, long names)
and invalid UTF-8.

For every run (:mod:`fuzz_run`): an exit code its command documents (0..3); no traceback, no exception
out of ``main`` and no Python warning (a numpy RuntimeWarning is "leaked warning"); on failure exactly
one stderr line ``drafting: error: <file>: <key or line or position>: ...`` (or naming the hostile
option) of at most 400 characters; a refusal where the mutation or option makes the case wrong (else
"bad value accepted"); no file in the output folder but the command's own outputs (nothing on failure)
and none added to the input folder; every SVG written parses as XML and carries no script, link or
entity; within the command's seconds (5 s, 10 s for render, lint, sweep and export, 15 s for --lab,
30 s for a batch; else "hang").

The test suite runs the same cases through hypothesis with a fixed seed and a small budget
(tests/test_hostile_fuzz.py); this script runs them at full size and prints the counts.
"""

from __future__ import annotations

import argparse
import random
import resource
import sys
import tempfile
import time
from collections import Counter
from pathlib import Path

HERE = Path(__file__).resolve().parent
if str(HERE) not in sys.path:                   # loaded by its path (the tests): its sibling modules too
    sys.path.insert(0, str(HERE))

from fuzz_commands import KINDS, Command, kind_of, make_command  # noqa: E402
from fuzz_mutations import Case, gallery, make_case  # noqa: E402
from fuzz_run import (HANG_SECONDS, PROBLEMS, Result, check_svg, classify_error, run_argv,  # noqa: E402,F401
                      shown_paths)

ROOT = HERE.parent


def run_case(case: Case, workdir: Path, formats: str = "svg", hang_seconds: float = HANG_SECONDS) -> Result:
    """``drafting render`` of the case (the first round's run)."""
    fmts = formats.split(",")
    allowed = {f"{f}" for f in fmts}

    def ok(stem: str, name: str) -> bool:
        return any(name in (f"{stem}.{f}", *(f"{stem}-{k}.{f}" for k in range(1, 20))) for f in allowed)
    cmd = Command("render " + formats, ["render", "{scene}", "-o", "{out}", "--format", formats], ok,
                  codes=(0, 1, 2, 3), hang_seconds=hang_seconds)
    return run_argv(case, cmd, workdir)


def run_command_case(case: Case, command: Command, workdir: Path) -> Result:
    """One case through its command (:mod:`fuzz_commands`)."""
    return run_argv(case, command, workdir)


def fresh_dir(base: Path, i: int) -> Path:
    d = base / f"case{i}"
    d.mkdir(parents=True)
    return d


def _table(title: str, counts: dict[str, Counter], totals: Counter) -> list[str]:
    cols = [p for p in PROBLEMS]
    rows = [f"| {title} | cases | " + " | ".join(cols) + " |", "|---" * (len(cols) + 2) + "|"]
    for k in sorted(totals):
        rows.append(f"| {k} | {totals[k]} | " + " | ".join(str(counts[k][p]) for p in cols) + " |")
    return rows


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("-n", type=int, default=1000, help="cases of each family kind (default 1000)")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--kinds", default=",".join(KINDS), help=f"comma-separated family kinds ({', '.join(KINDS)})")
    ap.add_argument("--render-only", action="store_true", help="the first round: render svg of any scene")
    ap.add_argument("--show", type=int, default=3, help="examples shown per problem")
    args = ap.parse_args(argv)
    sys.path.insert(0, str(ROOT))
    bases = gallery()
    by_kind: dict[str, list[str]] = {}
    for name, data in bases.items():
        by_kind.setdefault(kind_of(data), []).append(name)
    kinds = [k.strip() for k in args.kinds.split(",") if k.strip()]
    counts = {"kind": {}, "command": {}}
    totals = {"kind": Counter(), "command": Counter()}
    exits: Counter = Counter()
    examples: dict[str, list[Result]] = {}
    slowest: list[tuple[float, str]] = []
    t_all = time.perf_counter()
    with tempfile.TemporaryDirectory(prefix="fuzz-scenes-") as tmp:
        for kind in kinds:
            rng = random.Random(f"{args.seed}-{kind}")
            for i in range(args.n):
                base = rng.choice(sorted(by_kind[kind]))
                muts = [] if rng.random() < 0.25 and not args.render_only else None
                case = make_case(rng, bases, muts, base)
                workdir = fresh_dir(Path(tmp), len(slowest))
                if args.render_only:
                    r = run_case(case, workdir)
                else:
                    r = run_command_case(case, make_command(rng, kind), workdir)
                exits[r.code] += 1
                for axis, key in (("kind", kind), ("command", r.command.label.split(" --format")[0])):
                    totals[axis][key] += 1
                    c = counts[axis].setdefault(key, Counter())
                    for p in set(r.problems):
                        c[p] += 1
                for p in set(r.problems):
                    examples.setdefault(p, []).append(r)
                slowest.append((r.seconds, f"{kind} {r.command.label}: " + ", ".join(case.notes)))
    total = time.perf_counter() - t_all
    rss_mb = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
    print(f"hostile runs: {len(slowest)} ({args.n} of each kind, seed {args.seed}), {total:.1f} s, "
          f"peak RSS {rss_mb:.0f} MB")
    print("exit codes: " + ", ".join(f"{k}: {v}" for k, v in sorted(exits.items(), key=lambda kv: str(kv[0]))))
    print()
    print("\n".join(_table("kind", counts["kind"], totals["kind"])))
    print()
    print("\n".join(_table("command", counts["command"], totals["command"])))
    slowest.sort(reverse=True)
    print("\nslowest: " + "; ".join(f"{s:.2f} s ({n[:80]})" for s, n in slowest[:3]))
    for p, rs in examples.items():
        print(f"\n{p}: {len(rs)}")
        for r in rs[:args.show]:
            print(f"  {r.case.base} + {r.case.notes} | {' '.join(r.command.argv)[:160]!r} -> exit {r.code}, "
                  f"{r.seconds:.2f} s")
            for line in r.stderr.splitlines()[-3:]:
                print("     " + line[:300])
    return 1 if examples else 0


if __name__ == "__main__":
    sys.exit(main())
