"""Benchmarks, side by side in one run: the default sheet to SVG, PDF and PNG, and the analytic sweep.

Run with ``drafting bench`` (or ``python benchmarks/run_all.py``).  The figures are written into the
README; they are never asserted in tests.
"""

from __future__ import annotations

import statistics
import tempfile
import time
from pathlib import Path
from typing import Callable

from .bench_sweep import format_table, sweep_rows


def _median_seconds(fn: Callable[[], object], repeats: int) -> float:
    times = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return statistics.median(times)


def render_rows(repeats: int = 7) -> list[dict]:
    """Median wall time of each stage for the built-in example sheet."""
    from .cli import builtin_example, sheet_for
    from .export import write_sheet
    from .scene import load_scene
    from .study import Study

    path = builtin_example()

    def solve() -> Study:
        s = Study(load_scene(path))
        s.comparisons
        return s

    study = solve()
    sheet = sheet_for(study)
    rows = [{"stage": "scene -> solved study (position, velocity, analytic check)",
             "median_seconds": _median_seconds(solve, repeats)},
            {"stage": "study -> sheet layout", "median_seconds": _median_seconds(lambda: sheet_for(study), repeats)}]
    with tempfile.TemporaryDirectory() as tmp:
        for fmt in ("svg", "pdf", "png"):
            rows.append({"stage": f"sheet -> {fmt.upper()} file",
                         "median_seconds": _median_seconds(lambda: write_sheet(sheet, Path(tmp), "bench", [fmt]),
                                                           repeats)})
    return rows


def chain_rows(sizes=(10**3, 10**4, 10**5, 10**6), repeats: int = 3) -> list[dict]:
    """The dyad-chain vector loop (compound mechanisms) over crank-angle arrays: the notes' toggle
    linkage of gallery Example 3 (two dyads, a slider)."""
    import numpy as np

    from constructions.vector_loops import chain_solution
    from .scene import load_scene

    root = Path(__file__).resolve().parents[1] / "gallery" / "notes-velocity-example-3.toml"
    if not root.exists():
        return []
    m = load_scene(root).mechanism
    rows = []
    for n in sizes:
        theta = np.linspace(0.0, 2 * np.pi, n)
        t = _median_seconds(lambda: chain_solution(m, theta, 100.0), repeats)
        rows.append({"n": n, "median_seconds": t, "angles_per_second": n / t})
    return rows


def run_benchmarks(quick: bool = False) -> str:
    repeats = 3 if quick else 7
    sizes = (10**3, 10**4, 10**5, 10**6) if quick else (10**3, 10**4, 10**5, 10**6, 10**7)
    lines = ["Default sheet (notes velocity Example 1), median of %d runs:" % repeats]
    for r in render_rows(repeats):
        lines.append(f"  {r['stage']:<62} {r['median_seconds'] * 1e3:8.1f} ms")
    lines.append("")
    lines.append("Analytic sweep, positions and velocities (one core, numpy):")
    lines.append(format_table(sweep_rows(sizes, repeats=3 if quick else 5)))
    chain = chain_rows((10**3, 10**4, 10**5) if quick else (10**3, 10**4, 10**5, 10**6))
    if chain:
        lines.append("")
        lines.append("Dyad-chain vector loop, toggle linkage (gallery Example 3), positions and velocities:")
        for r in chain:
            lines.append(f"  {r['n']:>9.0e} angles  {r['median_seconds'] * 1e3:9.2f} ms  "
                         f"{r['angles_per_second']:9.3g} angles/s")
    return "\n".join(lines)
