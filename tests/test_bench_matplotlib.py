"""The sheet benchmark's peer draws the same line art: one matplotlib artist for each command (each span
of lettering), on a figure the size of the paper, saved by each back end."""

from __future__ import annotations

import pytest

from drafting import bench_matplotlib as mpl
from drafting.scene import load_scene
from drafting.study import Study
from drafting.worked import builtin_example, sheets_for

pytestmark = pytest.mark.skipif(mpl.available() is None, reason="matplotlib is optional (pip install '.[bench]')")


def test_the_peer_draws_every_command_once_on_the_paper():
    sheets = sheets_for(Study(load_scene(builtin_example())).run())
    assert mpl.artists(sheets) == mpl.command_count(sheets) > 200
    fig = mpl.figure_for(sheets[0])
    assert tuple(round(v * 25.4, 6) for v in fig.get_size_inches()) == (sheets[0].width, sheets[0].height)
    assert mpl.save(sheets[0], "pdf").startswith(b"%PDF") and b"<svg" in mpl.save(sheets[0], "svg")


def test_the_sheet_table_gives_the_median_and_the_best_runs():
    """'to SVG' is the sum of the stages' medians, and in brackets of their best runs."""
    from drafting.bench import Timing, format_render_rows
    t = Timing(0.010, 0.008)
    assert t == 0.010 and t.best == 0.008 and t + 0.005 == pytest.approx(0.015)
    row = {"scene": "s", "sheets": 1, "solve": Timing(0.002, 0.001), "layout": Timing(0.010, 0.009),
           "svg": Timing(0.005, 0.004), "pdf": Timing(0.008, 0.007), "png": Timing(0.04, 0.03),
           "artists": 3, "mpl_svg": 0.3, "mpl_pdf": 0.4, "mpl_png": 0.5}
    line = format_render_rows([row]).splitlines()[1]
    assert line.rstrip().endswith("17.0 [ 14.0]  20.0 [ 17.0]"), line
