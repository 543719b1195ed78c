"""The sheet benchmark's peer draws the same line art: one matplotlib artist for each command (each span
of lettering), on a figure the size of the paper, saved by each back end."""

from __future__ import annotations

import pytest

from drafting.app.bench import benchmark
from drafting.scene.reader import load_scene
from drafting.study.study import Study
from drafting.study.worked import builtin_example, sheets_for

mpl = benchmark("matplotlib_peer")

pytestmark = pytest.mark.skipif(mpl.available() is None, reason="matplotlib is optional (pip install '.[bench]')")


def test_the_peer_draws_every_command_once_on_the_paper():
    sheets = sheets_for(Study(load_scene(builtin_example())).run())
    assert mpl.artists(sheets) == mpl.command_count(sheets) > 200
    fig = mpl.figure_for(sheets[0])
    assert tuple(round(v * 25.4, 6) for v in fig.get_size_inches()) == (sheets[0].width, sheets[0].height)
    assert mpl.save(sheets[0], "pdf").startswith(b"%PDF") and b"<svg" in mpl.save(sheets[0], "svg")
