"""Free-body diagrams as textbooks draw them, on the gallery's force sheets: every free body of a sheet at one
scale (one free-body diagram), each body drawn with its pins circled and lettered, every force's arrow at its
point of application (its tip there where it pushes into the body, its tail where it pulls) pointing the
force's way, couples and the driving torque as arcs turning their way, two- and three-force members named.
Checked on the drawing commands in paper coordinates."""

from __future__ import annotations

import math

import pytest

from constructions.entities import Arrow, BodyOutline, MomentArc
from constructions.forces.free_body_links import FREE_BODIES
from drafting.render.paper import Circle, Line, Polygon, Polyline, Text
from drafting.scene.reader import load_scene
from drafting.study.study import Study

from paths import GALLERY

SCENES = ("notes-static-force-sample.toml", "bell-crank-three-force.toml", "four-bar-dalembert.toml")
TOL = 1e-6            # mm on paper


@pytest.fixture(scope="module", params=SCENES)
def drawn(request):
    study = Study(load_scene(GALLERY / request.param)).run()
    return study, study.sheets()


def _free_body_entities(study):
    return [e for e in study.construction.entities() if e.diagram == FREE_BODIES]


def _page_of(sheets):
    (page,) = [s for s in sheets if FREE_BODIES.key in s.diagram_scales]
    return page


def _near(p, q, tol=TOL):
    return math.hypot(p[0] - q[0], p[1] - q[1]) <= tol


def test_every_free_body_of_a_sheet_at_one_scale(drawn):
    """One free-body diagram holds every moving body, so all are drawn at the one ISO 5455 scale it is
    written with; no free body has a diagram (and a scale) of its own."""
    study, sheets = drawn
    fa = study.result("forces")
    outlines = [e for e in _free_body_entities(study) if isinstance(e, BodyOutline)]
    assert {o.link for o in outlines} >= set(fa.bodies)
    scales = [s.diagram_scales[k] for s in sheets for k in s.diagram_scales if k.startswith("free-body")]
    assert len(scales) == 1 and scales[0].quantity == "length"
    assert all(e.diagram == FREE_BODIES for e in study.construction.entities() if e.diagram.kind == "free-body")
    page = _page_of(sheets)
    written = dict(page.scales)[FREE_BODIES.key]
    assert written == f"Free-body diagram {scales[0].text}" or written.startswith("Free-body diagram ") and ":" in written


def test_each_force_at_its_point_of_application_pointing_its_way(drawn):
    """In paper coordinates: the arrowhead's apex is the arrow's tip; the point of application (moved with
    its body) is the tip where the force pushes into the body, the tail where it pulls; the arrow points
    the force's way."""
    study, sheets = drawn
    fa = study.result("forces")
    page = _page_of(sheets)
    T = page.transforms[FREE_BODIES.key]
    cmds = {c.name: c for c in page.commands}
    outlines = {e.link: e for e in _free_body_entities(study) if isinstance(e, BodyOutline)}
    arrows = [e for e in _free_body_entities(study) if isinstance(e, Arrow)]
    checked = 0
    for body, forces in fa.bodies.items():
        o = outlines[body]
        name, at = o.pins[0]
        shift = at - study.get("position").positions[name]          # the free body moved beside the others
        mid = [p for _, p in o.pins + o.points]
        centre = sum(mid[1:], mid[0]) / len(mid)
        for x in forces:
            if x.vector.norm() == 0.0:
                continue
            (arrow,) = [a for a in arrows if a.name.startswith(f"fbd {o.name[4:].split(':')[0]}: {x.label} ")
                        and (a.tip - a.tail).cross(x.vector) == pytest.approx(0.0, abs=1e-9 * x.vector.norm())
                        and ((a.tip - x.at - shift).norm() < 1e-9 or (a.tail - x.at - shift).norm() < 1e-9)]
            p = T(x.at + shift)
            head = cmds[f"{arrow.name}:head"]
            shaft = cmds[arrow.name]
            assert isinstance(head, Polygon) and isinstance(shaft, Line)
            tip, tail = head.points[0], (shaft.x1, shaft.y1)
            # a force on a block's one point pushes or pulls at it: its tip there
            into = x.vector.dot(centre - (x.at + shift)) > 0 or (centre - (x.at + shift)).norm() < 1e-12
            assert _near(tip if into else tail, p), (arrow.name, into)
            # the arrow points the force's way (paper y runs down)
            u = (tip[0] - tail[0], tip[1] - tail[1])
            assert u[0] * x.vector.x - u[1] * x.vector.y > 0
            assert abs(u[0] * -x.vector.y - u[1] * x.vector.x) <= 1e-6 * math.hypot(*u) * x.vector.norm()
            checked += 1
    assert checked >= 6


def test_couple_arcs_turn_the_moment_s_way(drawn):
    """The arc of every couple and torque turns (on paper, y down) the way its moment's sign says, its
    arrowhead at its end; the driving torque is drawn with the sign the analysis measured."""
    study, sheets = drawn
    fa = study.result("forces")
    page = _page_of(sheets)
    T = page.transforms[FREE_BODIES.key]
    cmds = {c.name: c for c in page.commands}
    arcs = [e for e in _free_body_entities(study) if isinstance(e, MomentArc)]
    torque = [a for a in arcs if a.label.startswith("T_")]
    assert len(torque) == (1 if fa.torque else 0)
    if torque:
        assert torque[0].moment == fa.torque
    for a in arcs:
        line, head = cmds[a.name], cmds[f"{a.name}:head"]
        assert isinstance(line, Polyline)
        c = T(a.centre)
        turn = 0.0
        for p, q in zip(line.points[:-1], line.points[1:]):
            turn += math.atan2((p[0] - c[0]) * (q[1] - c[1]) - (p[1] - c[1]) * (q[0] - c[0]),
                               (p[0] - c[0]) * (q[0] - c[0]) + (p[1] - c[1]) * (q[1] - c[1]))
        assert math.copysign(1.0, -turn) == math.copysign(1.0, a.moment)        # y down: CCW turns negative
        assert abs(turn) > math.pi
        # the arrowhead sits at the end the arc turns to
        assert _near(head.points[0], line.points[-1], 3.6)


def test_every_pin_drawn_and_lettered_and_members_named(drawn):
    study, sheets = drawn
    page = _page_of(sheets)
    T = page.transforms[FREE_BODIES.key]
    cmds = {c.name: c for c in page.commands}
    outlines = [e for e in _free_body_entities(study) if isinstance(e, BodyOutline)]
    for o in outlines:
        for n, p in o.pins:
            pin = cmds[f"{o.name}:pin {n}"]
            assert isinstance(pin, Circle) and _near((pin.cx, pin.cy), T(p))
        for n, _ in o.pins + o.points:
            assert isinstance(cmds[f"{o.name}:{n}:label"], Text)
        assert isinstance(cmds[f"{o.name}:caption:text"], Text)
    captions = {o.link: o.caption for o in outlines}
    words = " ".join(s.words for s in study.construction.steps)
    for link, caption in captions.items():
        if "two-force member" in caption:
            assert f"Link {link} carries no load between its pins" in words
    if "concurrency" in study.scene.title:                         # the bell crank
        assert captions[4] == "link 4: three-force member" and captions[3] == "link 3: two-force member"
        (meet,) = [e for e in _free_body_entities(study) if getattr(e, "label", None) == "I (link 4)"]
