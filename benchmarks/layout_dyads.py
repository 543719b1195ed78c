"""Layout time against the number of dyads: a crank driving a chain of N RRR dyads in series (each dyad's
moving joint hangs from the one before and from a pivot of its own), N = 1, 2, 4, 8, solved for velocities
(with accelerations the results table of 8 dyads outgrows an A3 sheet) and laid out as ``drafting render``
lays it out.  Each figure is the median of several runs after a warm-up, one run after another in one
process; a layout no worse than linear in the dyads keeps its time per dyad level (or falling) as N doubles.

Usage: ``python benchmarks/layout_dyads.py [--repeats 5] [--counts 1,2,4,8]``.
"""

import argparse
import math
import statistics
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))  # run from a checkout, uninstalled

from drafting.backends.svg import sheet_to_svg  # noqa: E402
from drafting.scene.reader import load_scene  # noqa: E402
from drafting.study.study import Study  # noqa: E402
from drafting.study.worked import sheets_for  # noqa: E402

STEP = 60.0           # mm between the dyads' pivots along the frame


def chain_scene(n: int) -> str:
    """The scene text of a crank and ``n`` RRR dyads in series: joint J_k from J_(k-1) (J_0 the crank pin
    B) and from the frame pivot G_k; the lengths are taken off a nominal pose, so every dyad closes."""
    b = (20 * math.cos(math.radians(60)), 20 * math.sin(math.radians(60)))
    joints = {"B": b}
    lines = ["[drawing]", f'title = "Chain of {n} dyads"', 'number = "BENCH-1"', 'paper = "A3"', "",
             "[units]", 'length = "mm"', 'velocity = "mm/s"', 'acceleration = "m/s^2"', "", "[frame]",
             "O1 = [0, 0]"]
    lines += [f"G{k} = [{STEP * k:g}, 0]" for k in range(1, n + 1)]
    links = [("O1", "B", 20.0)]
    prev = "B"
    for k in range(1, n + 1):
        joints[f"J{k}"] = (STEP * k - 15.0, 35.0 + 5.0 * (k % 2))
        links.append((prev, f"J{k}", math.dist(joints[prev], joints[f"J{k}"])))
        links.append((f"G{k}", f"J{k}", math.dist((STEP * k, 0.0), joints[f"J{k}"])))
        prev = f"J{k}"
    for i, (a, c, length) in enumerate(links, 1):
        lines += ["", "[[link]]", f"number = {i}", f'joints = ["{a}", "{c}"]', f"length = {length:.6f}"]
    lines += ["", "[input]", "link = 1", 'angle = "60 deg"', 'omega = "10 rad/s"', 'sense = "ccw"', "",
              "[assembly]"]
    prev = "B"
    for k in range(1, n + 1):
        lines.append(f'J{k} = "left of {prev}->G{k}"')
        prev = f"J{k}"
    lines += ["", "[ask]", 'analyses = ["velocity"]']
    return "\n".join(lines) + "\n"


def time_chain(n: int, repeats: int, folder: Path) -> dict:
    path = folder / f"chain-{n}.toml"
    path.write_text(chain_scene(n))
    runs = []
    for _ in range(repeats + 1):
        t0 = time.perf_counter()
        study = Study(load_scene(path)).run()
        t1 = time.perf_counter()
        sheets = sheets_for(study)
        t2 = time.perf_counter()
        for s in sheets:
            sheet_to_svg(s)
        runs.append((t1 - t0, t2 - t1, time.perf_counter() - t2, len(sheets)))
    runs = runs[1:]
    med = [statistics.median(r[i] for r in runs) for i in range(3)]
    return {"dyads": n, "pages": runs[-1][3], "solve": med[0], "layout": med[1], "svg": med[2]}


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeats", type=int, default=5)
    ap.add_argument("--counts", default="1,2,4,8")
    args = ap.parse_args(argv)
    with tempfile.TemporaryDirectory() as tmp:
        rows = [time_chain(int(n), args.repeats, Path(tmp)) for n in args.counts.split(",")]
    print(f"Chain of N dyads, median of {args.repeats} runs after a warm-up, ms:")
    print(f"  {'dyads':>5} {'pages':>5} {'solve':>8} {'layout':>8} {'SVG':>8} {'layout/dyad':>12}")
    for r in rows:
        print(f"  {r['dyads']:>5} {r['pages']:>5} {r['solve'] * 1e3:8.1f} {r['layout'] * 1e3:8.1f} "
              f"{r['svg'] * 1e3:8.1f} {r['layout'] * 1e3 / r['dyads']:12.1f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
