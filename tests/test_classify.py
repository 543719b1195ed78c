"""The four-bar's class (notes' Grashof types), its transmission-angle extremes and the rocker's limit
positions -- each checked against a dense analytic sweep of the same four-bar, not against the formula
that produced it."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings

from constructions import analytic
from constructions.geometry import Vec
from constructions.mechanisms.classify import classify_four_bar
from constructions.mechanisms.model import Branch, Link, Mechanism, Slide

from strategies import crank_rockers


def four_bar(g, a, b, c, branch=1, frame_angle=0.0):
    O2 = Vec.polar(g, frame_angle)
    return Mechanism({"O1": Vec(0.0, 0.0), "O2": O2},
                     (Link(1, ("O1", "B"), a), Link(2, ("B", "C"), b), Link(3, ("O2", "C"), c)), (), (), 1,
                     {"C": Branch(branch, ("B", "O2"))})


@pytest.mark.parametrize("lengths,kind,turns", [
    ((0.10, 0.03, 0.09, 0.07), "crank-rocker", ("crank",)),
    ((0.03, 0.06, 0.09, 0.08), "drag link (double crank)", ("crank", "rocker")),
    ((0.08, 0.07, 0.03, 0.09), "double rocker", ()),
    ((0.08, 0.09, 0.07, 0.03), "rocker-crank", ("rocker",)),
    ((0.10, 0.04, 0.10, 0.04), "change-point linkage", ("crank",)),     # s + l = p + q (a parallelogram)
    ((0.12, 0.09, 0.08, 0.07), "triple rocker", ()),                    # s + l = 0.19 > p + q = 0.17
])
def test_the_notes_types(lengths, kind, turns):
    k = classify_four_bar(four_bar(*lengths))
    assert k.closes and k.kind == kind and k.turns_fully == turns


def test_links_that_cannot_close():
    """The sentence names the violated inequality with the lengths: l < s + p + q fails."""
    k = classify_four_bar(four_bar(0.30, 0.05, 0.10, 0.10))
    assert not k.closes and k.summary() == ("the links cannot form a four-bar: the longest, the frame (0.3 m), "
                                            "is not shorter than the other three together (0.25 m)")


def test_the_deciding_inequality_is_named():
    assert "(s + l = 0.19 m > p + q = 0.17 m, the shortest the rocker)" in classify_four_bar(
        four_bar(0.12, 0.09, 0.08, 0.07)).summary()
    assert "s + l = 0.14 m = p + q = 0.14 m" in classify_four_bar(four_bar(0.10, 0.04, 0.10, 0.04)).summary()


def test_a_slider_crank_is_not_a_four_bar():
    m = Mechanism({"O1": Vec(0, 0)}, (Link(1, ("O1", "B"), 0.05), Link(2, ("B", "C"), 0.094)),
                  (Slide(3, "C", Vec(0, 0), 0.0),), (), 1, {"C": Branch(1, ("B",))})
    assert classify_four_bar(m) is None


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(case=crank_rockers())
def test_extremes_and_limits_agree_with_a_sweep(case):
    g, a, b, c, branch, frame_angle = case
    m = four_bar(g, a, b, c, branch, frame_angle)
    k = classify_four_bar(m)
    assert k.kind == "crank-rocker"
    th = np.linspace(-math.pi, math.pi, 20001)
    s = analytic.four_bar(th, 1.0, crank_pivot=(0.0, 0.0), rocker_pivot=m.ground["O2"].as_tuple(), crank=a,
                          coupler=b, rocker=c, branch=branch)
    assert bool(np.all(s.assembles))
    # the transmission angle at C, between C -> B and C -> O2, over the whole turn
    ux, uy = s.Bx - s.Cx, s.By - s.Cy
    vx, vy = m.ground["O2"].x - s.Cx, m.ground["O2"].y - s.Cy
    mu = np.abs(np.arctan2(ux * vy - uy * vx, ux * vx + uy * vy))
    step = 2 * math.pi / 20000
    # the sweep samples the extremes within half a step of crank angle; mu is smooth there (its
    # derivative is zero at an extreme), so the sampled extreme is within O(step^2) of the true one
    assert float(mu.min()) == pytest.approx(k.transmission_min, abs=1e-6)
    assert float(mu.max()) == pytest.approx(k.transmission_max, abs=1e-6)
    i = int(np.argmin(mu))
    assert math.remainder(float(th[i]) - k.transmission_min_at, 2 * math.pi) == pytest.approx(0.0, abs=2 * step)
    # the rocker's swing ends where crank and coupler are in line: the limit positions
    rocker = np.unwrap(s.theta3)
    ends = sorted(lp.rocker_angle for lp in k.limit_positions)
    lo, hi = float(rocker.min()), float(rocker.max())
    got = sorted(math.remainder(x - lo, 2 * math.pi) + lo for x in (ends[0], ends[1]))
    assert got[0] == pytest.approx(lo, abs=1e-6) and got[1] == pytest.approx(hi, abs=1e-6)
    for lp in k.limit_positions:                         # crank and coupler in line there
        B = Vec.polar(a, lp.crank_angle)
        along = (lp.C - B).unit().cross(B.unit())
        assert abs(along) < 1e-9


def test_gallery_four_bar_reads_as_the_notes_would_say():
    from drafting.scene.reader import load_scene
    k = classify_four_bar(load_scene("gallery/notes-velocity-example-2.toml").mechanism)
    assert k.summary(lambda v: f"{v * 1000:g} mm") == (
        "Grashof crank-rocker (s + l = 45 mm < p + q = 50 mm, the shortest the crank); crank turns fully")
    assert k.mobility[0] == 1
    assert 0 < k.transmission_min < k.transmission_max < math.pi


def test_a_second_loop_driven_by_a_rocker_is_classified():
    """A Stephenson six-bar: the rocker O2C carries E, which drives the dyad E-F-O3; its loop
    O2-E-F-O3 is a four-bar with the rocker as input, classified by its own lengths."""
    from constructions.mechanisms.classify import classify_loops
    from constructions.mechanisms.model import Attached
    m = Mechanism({"O1": Vec(0.0, 0.0), "O2": Vec(0.10, 0.0), "O3": Vec(0.16, 0.05)},
                  (Link(1, ("O1", "B"), 0.03), Link(2, ("B", "C"), 0.09), Link(3, ("O2", "C"), 0.07),
                   Link(4, ("E", "F"), 0.08), Link(5, ("O3", "F"), 0.06)), (),
                  (Attached("E", 3, "O2", 0.04, math.radians(-30)),), 1,
                  {"C": Branch(1, ("B", "O2")), "F": Branch(1, ("E", "O3"))})
    (loop,) = classify_loops(m)
    assert loop.input == 3 and loop.joint == "F" and loop.k.joints == ("O2", "E", "F", "O3")
    g = math.hypot(0.06, 0.05)
    assert loop.k.lengths == pytest.approx((g, 0.04, 0.08, 0.06))
    s, l = min(0.04, 0.08, 0.06, g), max(0.04, 0.08, 0.06, g)
    assert (loop.k.grashof == "Grashof") == (s + l < 0.04 + 0.08 + 0.06 + g - s - l)
    assert classify_loops(four_bar(0.10, 0.03, 0.09, 0.07)) == ()      # a plain four-bar has no other loop


STEPHENSON = """
[drawing]
title = "Stephenson six-bar: a rocker drives a second rocker"
number = "T-S"
[units]
length = "mm"
[frame]
O1 = [0, 0]
O2 = [100, 0]
O3 = [160, 50]
[[link]]
number = 1
joints = ["O1", "B"]
length = 30
[[link]]
number = 2
joints = ["B", "C"]
length = 90
[[link]]
number = 3
joints = ["O2", "C"]
length = 70
[[point]]
name = "E"
link = 3
from = "O2"
distance = 40
angle = "-30 deg"
[[link]]
number = 4
joints = ["E", "F"]
length = 80
[[link]]
number = 5
joints = ["O3", "F"]
length = 60
[input]
link = 1
angle = "40 deg"
omega = "10 rad/s"
[assembly]
C = "left of B->O2"
F = "left of E->O3"
"""


def test_the_loop_is_on_the_sheet_and_in_json():
    from drafting.scene.reader import parse_scene
    from drafting.study.study import Study
    s = Study(parse_scene(STEPHENSON, "steph.toml")).run()
    j = s.to_json()
    assert j["loops"] == [{"input_link": 3, "joints": ["O2", "E", "F", "O3"], "closes": True,
                           "grashof": "Grashof", "kind": "crank-rocker", "turns_fully": ["crank"]}]
    assert any(n.startswith("Loop O2-E-F-O3, driven by link 3, by its lengths a Grashof crank-rocker")
               for n in s.notes)
    assert j["analyses"].count("classification") == 1


@pytest.mark.parametrize("scale", [1e-3, 1.0, 1e3])
def test_a_parallelogram_at_its_change_point_is_named_at_every_scale(scale):
    """A parallelogram four-bar at crank angle 0 has its transmission angle at 0 exactly; the law of cosines
    then gives cos(mu) a few ulp past 1 at some sizes (at 0.01/0.03/0.01 mm it was 'math domain error'):
    clamped, the class is a change point and the position is named as one at every scale."""
    k = classify_four_bar(four_bar(0.03 * scale, 0.01 * scale, 0.03 * scale, 0.01 * scale))
    assert k.grashof == "change point"
    assert k.transmission_min == pytest.approx(0.0, abs=1e-6)
