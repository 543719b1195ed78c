"""The Scotch yoke: a translating slotted link, carried by two blocks on one fixed guide so that it
cannot turn, with the crank pin's block in its slot.  Its polygons against the closed form
x = r cos(theta), v = -r omega sin(theta), a = -r omega^2 cos(theta) - r alpha sin(theta) to 1e-9, and
against the constraint equations."""

from __future__ import annotations

import math
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings, strategies as st

from constructions.analytic import scotch_yoke
from constructions.check import analytic_solution, analytic_values, compare
from constructions.errors import CannotAssemble
from constructions.geometry import Vec
from constructions.mechanisms.assembly import SlotAlongGuide, assembly_plan
from constructions.mechanisms.model import Link, Mechanism, Slide, mobility
from constructions.mechanisms.pose import locate
from constructions.polygons.acceleration import acceleration_polygon
from constructions.polygons.velocity import velocity_polygon

R, E, STROKE = 0.1, 0.15, 0.0           # crank, slot offset from B (m), guide angle


def yoke(stroke: float = STROKE, slot: float = math.pi / 2, offset: float = E) -> Mechanism:
    """Crank OA (link 1); the yoke BC (link 3) in blocks 4 and 5 on one guide 0.16 m from O along
    ``stroke``; block 2 on the pin A in the yoke's slot, at ``slot`` to the rod, ``offset`` ahead of B."""
    g = Vec.polar(1.0, stroke)
    through = g.perp() * -0.16
    return Mechanism(ground={"O": Vec(0.0, 0.0)},
                     links=(Link(1, ("O", "A"), R), Link(3, ("B", "C"), 0.3)),
                     slides=(Slide(2, "A", Vec(0.0, 0.0), slot, on=3, offset=offset),
                             Slide(4, "B", through, stroke), Slide(5, "C", through, stroke)),
                     attached=(), crank=1, branches={})


def solve(m, theta, omega, alpha):
    va = velocity_polygon(m, locate(m, theta), omega)
    return va, acceleration_polygon(m, va, alpha)


def test_one_degree_of_freedom_and_one_step():
    m = yoke()
    f, working = mobility(m)
    assert f == 1, working
    plan = assembly_plan(m)
    assert isinstance(plan[1], SlotAlongGuide) and plan[1].coincident == "A3" and len(plan) == 2


@settings(max_examples=80, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(theta=st.floats(-math.pi, math.pi), omega=st.floats(0.5, 50.0).flatmap(lambda w: st.sampled_from([w, -w])),
       alpha=st.one_of(st.just(0.0), st.floats(-500.0, 500.0)), stroke=st.sampled_from([0.0, 0.7, -2.0]))
def test_graphical_equals_the_closed_form(theta, omega, alpha, stroke):
    """The yoke's displacement, velocity and acceleration along its stroke, read off the space diagram and
    the polygons, equal the closed form to 1e-9 (relative to r, r omega and r omega^2 + r |alpha|)."""
    m = yoke(stroke)
    va, aa = solve(m, theta, omega, alpha)
    exact = scotch_yoke(theta, omega, alpha, crank=R, stroke_angle=stroke)
    g = Vec.polar(1.0, stroke)
    pos = va.pose.positions
    slot_x = (pos["B"] - Vec(0.0, 0.0)).dot(g) + E             # the slot stands E ahead of B
    assert slot_x == pytest.approx(float(exact.x), abs=1e-9 * R)
    for x in ("B", "C", "A3"):
        v, a = va.velocities[x], aa.accelerations[x]
        assert abs(v.cross(g)) <= 1e-9 * R * abs(omega) and abs(a.cross(g)) <= 1e-9 * R * (omega ** 2 + abs(alpha))
        assert v.dot(g) == pytest.approx(float(exact.v), abs=1e-9 * R * abs(omega))
        assert a.dot(g) == pytest.approx(float(exact.a), abs=1e-9 * R * (omega ** 2 + abs(alpha)))
    assert va.angular[3] == 0.0 and aa.angular[3] == 0.0       # the yoke translates
    assert aa.coriolis["A_AA3^c"] == Vec(0.0, 0.0)
    # the sliding velocity and acceleration along the slot: the crank pin's component square to the stroke
    s = g.perp()
    assert va.relative[("A", "A3")].dot(s) == pytest.approx(R * omega * math.cos(theta - stroke), abs=1e-9 * R * abs(omega))
    assert aa.sliding["A_AA3^s"].dot(s) == pytest.approx(
        -R * omega ** 2 * math.sin(theta - stroke) + R * alpha * math.cos(theta - stroke),
        abs=1e-9 * R * (omega ** 2 + abs(alpha)))


@pytest.mark.parametrize("theta", [0.3, 2.0, -1.2, math.pi])
@pytest.mark.parametrize("omega", [7.0, -7.0])
def test_graphical_equals_the_constraint_equations(theta, omega):
    m = yoke(0.4, math.radians(80), 0.12)                       # a slot not square to the stroke too
    va, aa = solve(m, theta, omega, 30.0)
    a = analytic_solution(m, theta, omega, 30.0, guess=va.pose.positions)
    assert a is not None and a.model == "constraint equations"
    rows = compare(va.measured(m) + aa.measured(m), analytic_values(m, a), {**va.scales(), **aa.scales()})
    assert rows and all(r.analytic is not None for r in rows)
    assert not [(r.name, r.relative) for r in rows if not r.agrees]
    assert {"V_AA3", "A_AA3^s", "A_AA3^c"} <= {r.name for r in rows}


def test_a_slot_along_the_guide_cannot_meet_the_pin():
    with pytest.raises(CannotAssemble, match="runs along its guide"):
        locate(yoke(slot=0.0), 0.5)


def test_the_gallery_scene_agrees_with_the_closed_form():
    from drafting.api import load
    study = load(Path(__file__).parent.parent / "gallery" / "scotch-yoke.toml")
    exact = scotch_yoke(math.radians(30), 10.0, 20.0, crank=R)
    r = study.results
    assert all(x.agrees for x in r.values())
    for name, value in (("V_B", exact.v), ("A_B", exact.a)):          # SI vectors along the +x stroke
        got = r[name].graphical
        assert got.x == pytest.approx(float(value), rel=1e-9) and abs(got.y) <= 1e-9 * abs(float(value))


def test_its_force_analysis_is_refused_in_words():
    from constructions.errors import DegenerateInput
    from constructions.forces.polygon import force_analysis
    m = yoke()
    with pytest.raises(DegenerateInput, match="translating slotted link"):
        force_analysis(m, locate(m, 0.5), None)
