"""Enlarged details: the roller cam records its undercut and cusp as details; the detail's panel draws
only what lies inside its region, at the ISO 5455 enlargement its heading states; the main diagram marks
the region with a thin circle and the letter."""

import math
from pathlib import Path

import numpy as np
import pytest

import drafting
from constructions.cams.envelope import evaluate
from constructions.entities import Detail
from drafting.layout.clip import Disc, clip_command
from drafting.layout.detail_panel import DetailPanel
from drafting.layout.panel import PanelCache
from drafting.layout.panels import SpacePanel, panels_for
from drafting.render.paper import Circle, Line, Polyline, Rect, Text, command_points
from drafting.render.scales import ratio_factor

GALLERY = Path(__file__).resolve().parent.parent / "gallery"


def _study(name):
    return drafting.load(GALLERY / name).run()


def _cam(study):
    return study.get("profile")


@pytest.mark.parametrize("name, n", [("roller-cam-undercut.toml", 2), ("roller-cam-undercut-limit.toml", 1)])
def test_cam_records_a_detail_at_every_undercut_and_cusp(name, n):
    study = _study(name)
    details = [e for e in study.construction.entities() if isinstance(e, Detail)]
    assert [d.letter for d in details] == list("AB")[:n]
    cp = _cam(study).profile
    angles = [(a + b) / 2 for a, b in cp.undercut] + list(cp.cusp_at)
    for d, t in zip(details, sorted(angles)):
        p = evaluate(cp.program, cp.follower, np.array([t])).profile[:, 0]
        assert math.hypot(p[0] - d.centre.x, p[1] - d.centre.y) < 0.1 * d.radius   # the region holds it
        assert d.diagram.key == "cam: profile"


def test_detail_panel_draws_only_inside_its_region_at_its_enlargement():
    study = _study("roller-cam-undercut.toml")
    panels = panels_for(study.construction, study.scene.units, PanelCache())
    space = next(p for p in panels if isinstance(p, SpacePanel) and p.key == "cam: profile")
    det = space.beside.details
    assert isinstance(det, DetailPanel)
    rung = 0
    k = det.k(rung)
    assert k == pytest.approx(1000.0 * ratio_factor(det.ratios[rung]))
    assert det.heading(rung) == "Details A and B 5:1"
    w, h = det.need(rung, 200.0)
    rect = Rect(10.0, 10.0, w, h)
    cmds, _ = det.render(rung, rect, "panel")
    header = det.header(rung, rect, "panel")
    plot = Rect.from_edges(rect.x + 1.0, rect.y + header.height, rect.right - 1.0, rect.bottom - 1.0)
    discs = det.discs(rung, plot)
    assert [round(d.r / k, 12) for d in discs] == [round(x.radius, 12) for x in det.details]
    drawn = [c for c in cmds[len(header.commands):] if not isinstance(c, Text)]
    assert any(isinstance(c, Polyline) and c.name == "profile" for c in drawn)     # the diagram's own entity
    for c in drawn:
        if c.name.startswith("detail "):          # the panel's own: each region's boundary and letter
            continue
        pts = command_points(c) if not isinstance(c, Circle) else ((c.cx, c.cy),)
        assert any(all(d.inside(p, 1e-6) for p in pts) for d in discs), c
    assert {c.plain for c in cmds if isinstance(c, Text)} >= {"A", "B"}


def test_main_diagram_marks_each_region_with_a_thin_circle_and_its_letter():
    study = _study("roller-cam-undercut.toml")
    panels = panels_for(study.construction, study.scene.units, PanelCache())
    space = next(p for p in panels if isinstance(p, SpacePanel) and p.key == "cam: profile")
    rung = space.ratios.index((1, 2))
    k = space.k(rung)
    d = space.figure.drawing(k)
    for det in space.beside.details.details:
        mark = [c for c in d.commands if isinstance(c, Circle) and c.name == det.name]
        assert len(mark) == 1 and mark[0].r == pytest.approx(det.radius * k) and mark[0].style == "dimension"
        assert any(q.markup == det.letter and q.mandatory for q in d.labels)


def test_clipping_keeps_the_inside_of_a_line_and_drops_what_lies_outside():
    disc = Disc(0.0, 0.0, 1.0)
    (cut,) = clip_command(Line(-2.0, 0.0, 2.0, 0.0, "path"), disc)
    assert (cut.x1, cut.x2) == pytest.approx((-1.0, 1.0))
    assert clip_command(Line(-2.0, 2.0, 2.0, 2.0, "path"), disc) == []
    assert clip_command(Circle(5.0, 0.0, 1.0, "path"), disc) == []
    pieces = clip_command(Circle(1.0, 0.0, 1.0, "path"), disc)
    assert pieces and all(disc.inside(p, 1e-9) for c in pieces for p in c.points)


def test_a_sheet_with_details_says_as_shown_in_its_scale_cell():
    """The cam diagram at 1:2 and its details at 5:1: two scales, so the title block's cell says "As
    shown" (each drawing states its own in its heading)."""
    sheet = drafting.load(GALLERY / "roller-cam-undercut.toml").sheets()[0]        # (the drawings' sheet)
    cell = [t.plain for t in sheet.texts() if t.region == "title_block"]
    assert "As shown" in cell and not any(t.startswith("Cam diagram") for t in cell)
