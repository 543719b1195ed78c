"""The sheet benchmark's table: medians, and the best runs beside them (timings are never asserted)."""

from __future__ import annotations

import pytest


def test_the_sheet_table_gives_the_median_and_the_best_runs():
    """'to SVG' is the sum of the stages' medians, and in brackets of their best runs."""
    from drafting.app.bench import Timing, format_render_rows
    t = Timing(0.010, 0.008)
    assert t == 0.010 and t.best == 0.008 and t + 0.005 == pytest.approx(0.015)
    row = {"scene": "s", "sheets": 1, "solve": Timing(0.002, 0.001), "layout": Timing(0.010, 0.009),
           "svg": Timing(0.005, 0.004), "pdf": Timing(0.008, 0.007), "png": Timing(0.04, 0.03),
           "artists": 3, "mpl_svg": 0.3, "mpl_pdf": 0.4, "mpl_png": 0.5}
    line = format_render_rows([row]).splitlines()[1]
    assert line.rstrip().endswith("17.0 [ 14.0]  20.0 [ 17.0]"), line


def test_the_run_says_how_fast_the_machine_was():
    """A fixed loop of plain Python timed beside the sheets: the yardstick of a quiet or a busy minute."""
    from drafting.app.bench import Timing, format_machine_speed, machine_speed
    t = machine_speed(1)
    assert isinstance(t, Timing) and 0 < t.best <= t
    assert format_machine_speed(Timing(0.0123, 0.0101)).endswith(
        "took 12.3 ms, best 10.1 ms (the sheet figures move with it)")
