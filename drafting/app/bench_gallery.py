"""Every gallery sheet timed stage by stage: ``drafting bench --gallery`` (``--json`` for the figures).

For each scene of the checkout's ``gallery/*.toml`` one sheet is made the way ``drafting render`` makes
it -- solve (scene file -> solved Study, the analytic check included), layout (the Study's sheets: every
page's drawing commands) and SVG (every page serialised in memory) -- once to warm up, then ``repeats``
times one run after another in this one process.  Each stage's figure is the median of its runs, the
total the median of the runs' totals, and ``worst`` the slowest run's total.  Nothing is asserted about
the times: they move with the machine (see :func:`drafting.app.bench.machine_speed`).
"""

from __future__ import annotations

import json
import statistics
import time
from pathlib import Path
from typing import Callable, Iterable

from ..backends.svg import sheet_to_svg
from ..layout import stopwatch
from ..scene.reader import load_scene
from ..study.study import Study
from ..study.worked import sheets_for

#: The stages of one sheet, in the order they run.
STAGES = ("solve", "layout", "svg")


def gallery_scenes(gallery: Path) -> list[Path]:
    """The gallery's scene files, by name."""
    return sorted(gallery.glob("*.toml"))


def _timed(fn: Callable[[], object]) -> tuple[object, float]:
    t0 = time.perf_counter()
    value = fn()
    return value, time.perf_counter() - t0


def time_scene(path: Path, repeats: int) -> dict:
    """One scene's stages: ``{"scene", "pages", "solve", "layout", "plan", "labels", "svg", "total",
    "worst"}`` in seconds (medians; ``plan`` and ``labels`` are parts of ``layout``; ``worst`` the slowest
    run's total), after one run that is not counted."""
    runs = []
    parts = []
    pages = 0
    for _ in range(repeats + 1):
        study, solve = _timed(lambda: Study(load_scene(path)).run())
        stopwatch.start()
        sheets, layout = _timed(lambda: sheets_for(study))
        parts.append(stopwatch.stop())
        _, svg = _timed(lambda: [sheet_to_svg(s) for s in sheets])
        runs.append((solve, layout, svg))
        pages = len(sheets)
    runs, parts = runs[1:], parts[1:]                   # the warm-up is not counted
    row = {"scene": path.stem, "pages": pages}
    for i, stage in enumerate(STAGES):
        row[stage] = statistics.median(r[i] for r in runs)
    for part in stopwatch.STAGES:
        row[part] = statistics.median(p[part] for p in parts)
    totals = [sum(r) for r in runs]
    row["total"] = statistics.median(totals)
    row["worst"] = max(totals)
    return row


def gallery_rows(scenes: Iterable[Path], repeats: int = 7) -> list[dict]:
    """:func:`time_scene` for every scene, one after another."""
    return [time_scene(p, repeats) for p in scenes]


def format_gallery_rows(rows: list[dict], repeats: int) -> str:
    """The rows side by side, the slowest sheet named last."""
    def ms(v: float) -> str:
        return f"{v * 1e3:7.1f}"
    width = max([len(r["scene"]) for r in rows] + [5])
    lines = [f"Gallery sheets, median of {repeats} runs after a warm-up, in ms (solve = scene file -> solved "
             f"study; layout = every page's drawing commands, of which plan = the page planner and labels = "
             f"the label placer; SVG = every page serialised in memory; total = median of the runs' sums; "
             f"worst = the slowest run's sum):",
             f"  {'scene':<{width}} {'pages':>5} {'solve':>7} {'layout':>7} {'(plan':>7} {'labels)':>8} "
             f"{'SVG':>7} {'total':>7} {'worst':>7}"]
    for r in rows:
        lines.append(f"  {r['scene']:<{width}} {r['pages']:>5} {ms(r['solve'])} {ms(r['layout'])} "
                     f"{ms(r['plan'])} {ms(r['labels'])} " + " ".join(ms(r[k]) for k in ("svg", "total", "worst")))
    if rows:
        slow = max(rows, key=lambda r: r["total"])
        lines.append(f"  slowest: {slow['scene']}, {slow['total'] * 1e3:.1f} ms median "
                     f"(worst run {slow['worst'] * 1e3:.1f} ms)")
    return "\n".join(lines)


def gallery_json(rows: list[dict], repeats: int) -> str:
    """The rows as JSON, times in milliseconds."""
    keys = (*STAGES, *stopwatch.STAGES, "total", "worst")
    return json.dumps({"repeats": repeats, "unit": "ms",
                       "sheets": [{"scene": r["scene"], "pages": r["pages"],
                                   **{k: round(r[k] * 1e3, 3) for k in keys}} for r in rows]}, indent=2)
