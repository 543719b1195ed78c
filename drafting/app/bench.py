"""Benchmarks, side by side in one run: the default sheet to SVG, PDF and PNG, and the analytic sweep.

Run with ``drafting bench`` (or ``python benchmarks/run_all.py``); ``drafting bench --gallery`` times every
gallery sheet stage by stage instead (:mod:`.bench_gallery`).  The figures are written into the
README; they are never asserted in tests.  The peers (matplotlib drawing the same sheets; pylinkage,
mechanism and plain numpy sweeping the four-bar) live in the checkout's ``benchmarks/`` folder, never inside
drafting/, and are loaded from there by :func:`benchmark`.
"""

from __future__ import annotations

import gc
import importlib.util
import statistics
import sys
import time
from pathlib import Path
from types import ModuleType
from typing import Callable

from .bench_gallery import format_gallery_rows, gallery_json, gallery_rows, gallery_scenes
from .bench_sweep import format_table, sweep_rows
from .parallel import GC_YOUNG
from .solving import UserError
from ..backends import cairo as cairo_out
from ..backends.files import PNG_DPI
from ..backends.svg import sheet_to_svg
from ..scene.reader import load_scene
from ..study.study import Study
from ..study.worked import builtin_example, sheets_for


def _median_seconds(fn: Callable[[], object], repeats: int) -> "Timing":
    times = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return Timing(statistics.median(times), min(times))


class Timing(float):
    """A median wall time (the float) that also carries the best run (``best``): this machine's speed
    wanders by up to 2x from run to run, and the best run is what the code costs when nothing else is
    in its way."""

    best: float

    def __new__(cls, median: float, best: float) -> "Timing":
        t = super().__new__(cls, median)
        t.best = best
        return t


CHECKOUT = Path(__file__).resolve().parents[2]
GALLERY = CHECKOUT / "gallery"
BENCHMARKS = CHECKOUT / "benchmarks"


class BenchmarksMissing(Exception):
    """A peer was asked for, and this installation has no ``benchmarks/`` folder (it is not a checkout)."""


def benchmark(name: str) -> ModuleType:
    """The checkout's ``benchmarks/<name>.py`` (``peers``, ``matplotlib_peer``), loaded once by its path:
    the folder is not an installed package.  :class:`BenchmarksMissing` when it is not there."""
    key = f"benchmarks.{name}"
    if key in sys.modules:
        return sys.modules[key]
    path = BENCHMARKS / f"{name}.py"
    if not path.is_file():
        raise BenchmarksMissing(f"the benchmark peers live in the benchmarks folder of a source checkout, and "
                                f"{path} is not there")
    spec = importlib.util.spec_from_file_location(key, path)
    module = importlib.util.module_from_spec(spec)
    sys.modules[key] = module                  # before it runs: its dataclasses look their module up
    try:
        spec.loader.exec_module(module)
    except BaseException:
        del sys.modules[key]
        raise
    return module


def _matplotlib_peer() -> ModuleType | None:
    """The matplotlib peer, or None outside a checkout (the sheet table then says why it has no peer)."""
    try:
        return benchmark("matplotlib_peer")
    except BenchmarksMissing:
        return None


def _reference_work() -> int:
    total = 0
    for i in range(200_000):
        total += i * i
    return total


def machine_speed(repeats: int = 7) -> "Timing":
    """A fixed piece of plain Python (a sum of 200,000 squares) timed as the sheets are: on a machine
    shared with others its time moves with the neighbours, and the sheet figures of the same run move
    with it -- the yardstick that says whether a run fell in a quiet or a busy minute."""
    return _median_seconds(_reference_work, repeats)


def format_machine_speed(t: "Timing") -> str:
    return (f"Machine speed in this run: a fixed loop of plain Python (a sum of 200,000 squares) took "
            f"{t * 1e3:.1f} ms, best {t.best * 1e3:.1f} ms (the sheet figures move with it)")

#: The sheets timed side by side: the velocity-only default sheet, then the same slider-crank with its
#: acceleration polygon, then the toggle six-bar with both polygons (the cost of each analysis).
RENDER_SCENES = (("velocity, slider-crank (default sheet)", None),
                 ("acceleration, slider-crank (notes acc. Ex. 1)", "notes-acceleration-example-1.toml"),
                 ("acceleration, toggle six-bar (notes acc. Ex. 4)", "notes-acceleration-example-4.toml"))


def render_rows(repeats: int = 7) -> list[dict]:
    """Median wall time of each stage (solve, layout of every sheet, SVG/PDF/PNG in memory) for each
    sheet of :data:`RENDER_SCENES` that exists in this checkout, and the same sheets' line art drawn
    through matplotlib when it is installed (``mpl_svg`` ...)."""
    mpl = _matplotlib_peer()
    rows = []
    for label, name in RENDER_SCENES:
        path = builtin_example() if name is None else GALLERY / name
        if not path.exists():
            continue

        def solve() -> Study:
            return Study(load_scene(path)).run()

        study = solve()
        sheets = sheets_for(study)
        row = {"scene": label, "sheets": len(sheets), "solve": _median_seconds(solve, repeats),
               "layout": _median_seconds(lambda: sheets_for(study), repeats),
               "svg": _median_seconds(lambda: [sheet_to_svg(s) for s in sheets], repeats),
               "pdf": _median_seconds(lambda: cairo_out.sheets_to_pdf(sheets), repeats),
               "png": _median_seconds(lambda: [cairo_out.sheet_to_png(s, PNG_DPI) for s in sheets], repeats)}
        if mpl is not None and mpl.available():
            row["artists"] = mpl.artists(sheets)
            if row["artists"] != mpl.command_count(sheets):       # checked before it is timed: the same drawing
                raise RuntimeError(f"the matplotlib peer drew {row['artists']} artists for the sheet's "
                                   f"{mpl.command_count(sheets)} commands; its timings would not compare")
            for fmt in ("svg", "pdf", "png"):
                row["mpl_" + fmt] = _median_seconds(lambda: [mpl.save(s, fmt, PNG_DPI) for s in sheets], repeats)
        rows.append(row)
    return rows


def format_render_rows(rows: list[dict]) -> str:
    def ms(v: float) -> str:
        return f"{v * 1e3:6.1f}ms"

    def both(v: float, best: float) -> str:
        return f"{v * 1e3:5.1f} [{best * 1e3:5.1f}]"
    head = (f"  {'sheet':<50} {'pages':>5} {'solve':>8} {'layout':>8} {'SVG':>8} {'PDF':>8} {'PNG':>8}"
            f"   {'to SVG':>13} {'to PDF':>13}")
    lines = [head]
    for r in rows:
        base = r["solve"] + r["layout"]
        best = getattr(r["solve"], "best", r["solve"]) + getattr(r["layout"], "best", r["layout"])
        lines.append(f"  {r['scene']:<50} {r['sheets']:>5} " + " ".join(ms(r[k]) for k in ("solve", "layout", "svg", "pdf", "png"))
                     + f"   {both(base + r['svg'], best + getattr(r['svg'], 'best', r['svg']))}"
                     + f" {both(base + r['pdf'], best + getattr(r['pdf'], 'best', r['pdf']))}")
    lines.append("  (to SVG and to PDF: the sum of the stages' medians [of their best runs])")
    lines.append("")
    mpl = _matplotlib_peer()
    if mpl is None:
        lines.append(f"  The same line art through matplotlib: not run (its peer lives in the benchmarks folder of a "
                     f"source checkout, and {BENCHMARKS} is not there).")
        return "\n".join(lines)
    version = mpl.available()
    if version is None:
        lines.append("  The same line art through matplotlib: not installed (pip install '.[bench]').")
        return "\n".join(lines)
    lines.append(f"  The same line art through matplotlib {version} (each command an artist, saved by its SVG, PDF "
                 f"and Agg back ends; no solving, no layout):")
    lines.append(f"  {'sheet':<50} {'drawn':>7} {'':>26} {'SVG':>8} {'PDF':>8} {'PNG':>8}")
    for r in rows:
        lines.append(f"  {r['scene']:<50} {r['artists']:>7} {'':>26} " + " ".join(ms(r['mpl_' + k]) for k in ("svg", "pdf", "png")))
    return "\n".join(lines)


def run_benchmarks(quick: bool = False, peers: bool = False) -> str:
    """Every table of one run as text; with ``peers`` the four-bar sweep against its peers too
    (:class:`BenchmarksMissing` at once, before any timing, outside a checkout)."""
    peer_sweep = benchmark("peers") if peers else None
    repeats = 3 if quick else 7
    sizes = (10**3, 10**4, 10**5, 10**6) if quick else (10**3, 10**4, 10**5, 10**6, 10**7)
    collector = ("tuned as in the drafting command" if gc.get_threshold()[0] == GC_YOUNG
                 else "Python's defaults (the drafting command tunes it: drafting.app.parallel.tune_gc)")
    speed = machine_speed(repeats)
    lines = ["Sheets, median of %d runs (solve = scene file -> solved study with the analytic check; layout = "
             "every page's drawing commands; SVG, PDF and PNG (150 dpi) made in memory; to SVG = solve + layout + "
             "SVG; garbage collector: %s):" % (repeats, collector), format_render_rows(render_rows(repeats)),
             format_machine_speed(speed)]
    lines.append("")
    lines.append("Analytic sweep, full states -- positions, velocities and accelerations of every joint "
                 "(numpy; the default call on the default threads, and the four-bar on one thread):")
    lines.append(format_table(sweep_rows(sizes, repeats=3 if quick else 5)))
    if peer_sweep is not None:
        lines.append("")
        lines.append("The four-bar sweep against its peers (positions checked against this engine first):")
        lines.append(peer_sweep.format_rows(*peer_sweep.rows(sizes)))
    return "\n".join(lines)


def run_gallery(quick: bool = False, as_json: bool = False) -> str:
    """Every gallery sheet's stages (:mod:`.bench_gallery`) as a table with the machine's speed beside it,
    or as JSON; :class:`BenchmarksMissing` outside a checkout (the gallery is not installed)."""
    if not GALLERY.is_dir():
        raise BenchmarksMissing(f"the gallery lives in a source checkout, and {GALLERY} is not there")
    repeats = 3 if quick else 7
    speed = machine_speed(repeats)
    rows = gallery_rows(gallery_scenes(GALLERY), repeats)
    if as_json:
        return gallery_json(rows, repeats)
    return "\n".join([format_gallery_rows(rows, repeats), format_machine_speed(speed)])


def cmd_bench(quick: bool, peers: bool = False, gallery: bool = False, as_json: bool = False) -> int:
    if as_json and not gallery:
        raise UserError("bench --json goes with --gallery")
    try:
        print(run_gallery(quick=quick, as_json=as_json) if gallery else run_benchmarks(quick=quick, peers=peers))
    except BenchmarksMissing as e:             # installed without the checkout: one sentence, exit 2
        raise UserError(f"bench {'--gallery' if gallery else '--peers'}: {e}") from None
    return 0


def run_command(args) -> int:
    """``drafting bench [--quick] [--peers] [--gallery [--json]]``."""
    return cmd_bench(args.quick, args.peers, args.gallery, args.json)
