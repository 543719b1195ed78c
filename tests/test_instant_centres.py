"""Instant centres by Kennedy's theorem: located, drawn and read for velocities that agree with the
polygon's and the vector loop's (to 1e-9 relative), on the notes' four-bar and slider-crank, the six-bars,
slotted links and random mechanisms."""

from __future__ import annotations

import itertools

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings

import mechanisms as M
from constructions.geometry import Vec
from constructions.mechanisms.centres import DIAGRAM, FAR, centre_name
from constructions.mechanisms.instant_centres import instant_centres
from constructions.mechanisms.pose import locate
from constructions.polygons.velocity import velocity_polygon
from drafting.scene.reader import load_scene
from drafting.study.study import Study
from mechanisms import four_bar, slider_crank
from strategies import four_bars, slider_cranks

from paths import GALLERY


def _points(m, body):
    from constructions.mechanisms.topology import points_of_body
    return points_of_body(m, body)


def agree(m, theta, omega):
    """All N(N-1)/2 centres found; every velocity and angular velocity read off them equals the
    polygon's to 1e-9 of the largest; every three centres of three bodies in line."""
    pose = locate(m, theta)
    va = velocity_polygon(m, pose, omega)
    ic = instant_centres(m, pose, omega)
    n = len(ic.bodies)
    assert not ic.missing and len(ic.centres) == n * (n - 1) // 2
    scale = max(v.norm() for v in va.velocities.values())
    for p, v in ic.velocities.items():
        assert (v - va.velocities[p]).norm() <= 1e-9 * scale, p
    for k, w in va.angular.items():
        assert ic.angular[k] == pytest.approx(w, rel=1e-9, abs=1e-9 * abs(omega)), k
    size = m.size
    pos = pose.positions

    def rigid(a, b):              # two bodies that do not move relative to each other (a rigid triangle
        if a == ic.frame or b == ic.frame:      # of binary links) have no one relative centre
            return False
        pa = [p for p in pos if p in ic.velocities and p in _points(m, a)]
        return abs(ic.angular[a] - ic.angular[b]) < 1e-12 * abs(omega) and any(
            p in _points(m, b) for p in pa)
    for a, b, c in itertools.combinations(ic.bodies, 3):
        if rigid(a, b) or rigid(a, c) or rigid(b, c):
            continue
        pts = [ic.centres[tuple(sorted(q))] for q in ((a, b), (a, c), (b, c))]
        h = np.array([[p.point[0] / size, p.point[1] / size, p.point[2]] for p in pts])
        h /= np.linalg.norm(h, axis=1)[:, None]
        assert abs(np.dot(h[0], np.cross(h[1], h[2]))) < 1e-7, (a, b, c)   # Kennedy: collinear (det h)
    return ic


def crossing(a, b, c, d) -> Vec:
    """Where the line ab meets the line cd (Cramer's rule, by hand)."""
    r, s = b - a, d - c
    t = (c - a).cross(s) / r.cross(s)
    return a + r * t


def test_four_bar_by_hand():
    """The links are 1, 2, 3, so the frame is 0: the coupler's centre I_02 is where the crank line O1B
    meets the rocker line O2C, and I_13 where the coupler line BC meets the frame line O1O2."""
    m = four_bar((0.0, 0.0), (1.0, 0.0), 0.4, 1.0, 0.8, 1)
    ic = agree(m, 1.0, 3.0)
    P = locate(m, 1.0).positions
    f = ic.frame
    assert f == 0                                    # the links are 1, 2, 3: the frame is 0
    coupler = crossing(P["O1"], P["B"], P["O2"], P["C"])
    other = crossing(P["B"], P["C"], P["O1"], P["O2"])
    assert (ic.centres[(0, 2)].at - coupler).norm() < 1e-12
    assert (ic.centres[(1, 3)].at - other).norm() < 1e-12
    # the coupler turns about I_02: |V_B| = |omega_2| |B - I_02|
    w2 = ic.angular[2]
    assert abs(w2) * (P["B"] - coupler).norm() == pytest.approx(3.0 * 0.4, rel=1e-12)


def test_slider_crank_block_centre_at_infinity():
    m = slider_crank((0.0, 0.0), 0.05, 0.094, (0.0, 0.0), 0.0, 1)
    ic = agree(m, 1.0, 10.0)
    c = ic.centres[(0, 3)]
    assert not c.finite and abs(c.direction.x) < 1e-15       # square to the horizontal guide
    P = locate(m, 1.0).positions
    # the rod's centre: on the crank line and on the normal to the guide through C
    i02 = ic.centres[(0, 2)].at
    assert abs(i02.x - P["C"].x) < 1e-12 and abs((P["B"] - P["O1"]).cross(i02 - P["O1"])) < 1e-15


def test_parallelogram_coupler_translates():
    """Crank and rocker parallel: the coupler's centre is at infinity and it does not turn."""
    m = four_bar((0.0, 0.0), (1.0, 0.0), 0.5, 1.0, 0.5, 1)
    ic = agree(m, 1.0, 2.0)
    assert not ic.centres[(0, 2)].finite and ic.angular[2] == pytest.approx(0.0, abs=1e-12)


@pytest.mark.parametrize("make", [M.quick_return, M.rocker_with_slot, M.slanted_slot, M.watt_six_bar, M.six_bar,
                                  M.watt_chain, M.slot_and_guide], ids=lambda f: f.__name__)
def test_six_bars_and_slots(make):
    agree(make(), 0.7, 3.0)


@settings(max_examples=80, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(case=four_bars())
def test_random_four_bars(case):
    m, theta, omega = case
    agree(m, theta, omega)


@settings(max_examples=80, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(case=slider_cranks())
def test_random_slider_cranks(case):
    m, theta, omega = case
    agree(m, theta, omega)


@pytest.mark.parametrize("name, centres", [("instant-centres-four-bar", 6), ("instant-centres-slider-crank", 6),
                                           ("instant-centres-six-bar", 15)])
def test_gallery_scenes_through_the_pipeline(name, centres):
    s = Study(load_scene(GALLERY / f"{name}.toml")).run()
    rows = {c.name: c for c in s.comparisons}
    assert all(c.agrees for c in s.comparisons)
    ic_rows = [n for n in rows if n.endswith(" (instant centres)")]
    assert ic_rows and all(n.removesuffix(" (instant centres)") in rows for n in ic_rows)
    for n in ic_rows:                                      # beside the polygon's value, to 1e-9
        a, b = rows[n].graphical, rows[n.removesuffix(" (instant centres)")].graphical
        d = (a - b).norm() if isinstance(a, Vec) else abs(a - b)
        assert d <= 1e-9 * max(b.norm() if isinstance(b, Vec) else abs(b), 1e-300) + 1e-12
    j = s.to_json()
    assert len(j["instant_centres"]) == centres and j["instant_centres_missing"] == []
    assert "instant centres (Kennedy)" in s.ran
    drawn = ", ".join(e.label for e in s.construction.entities(DIAGRAM) if getattr(e, "label", None))
    ic = s.computed("instant centres")
    size, pts = s.scene.mechanism.size, list(s.get("position").positions.values())
    mid = Vec(sum(p.x for p in pts) / len(pts), sum(p.y for p in pts) / len(pts))
    for q, c in ic.centres.items():         # every centre near the mechanism is marked, the others named
        near = c.finite and (c.at - mid).norm() <= FAR * max(size, max((p - mid).norm() for p in pts))
        assert (centre_name(q) in drawn.split(", ")) == near, q
    words = " ".join(st.words for st in s.construction.steps)
    assert "Kennedy" in words and "circle diagram" in words
