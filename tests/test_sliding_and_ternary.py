"""Sliders on moving links (inverted slider-crank / slotted lever, a block meeting a moving slot, a pin
in a slot), ternary links, and the mobility count: every velocity equals the time derivative of the
constructed positions, every acceleration (Coriolis included) the time derivative of the velocity
polygon, in both senses of rotation and both directions of sliding."""

from __future__ import annotations

import math

import pytest
from hypothesis import HealthCheck, assume, given, settings, strategies as st

from constructions.entities import Diagram
from constructions.errors import CannotAssemble, DegenerateInput, IndeterminatePosition
from constructions.geometry import Vec
from constructions.mechanisms.assembly import SlotThrough, assembly_plan
from constructions.mechanisms.model import Branch, Link, Mechanism, Slide, mobility
from constructions.mechanisms.pose import locate
from constructions.polygons.acceleration import acceleration_polygon
from constructions.polygons.velocity import velocity_polygon
from mechanisms import (quick_return, rocker_with_slot, slot_and_guide, ternary_posed_by_other_points,
                        watt_six_bar)


MECHANISMS = {"quick-return": quick_return, "slot meets a guide (PRP)": slot_and_guide, "quick-return, offset slot": lambda: quick_return(0.012),
              "quick-return, other branch": lambda: quick_return(-0.01, -1, ram=False),
              "pin in a slot": lambda: quick_return(block=False), "block meets a moving slot": rocker_with_slot,
              "Watt six-bar": watt_six_bar, "ternary posed through its third point": ternary_posed_by_other_points}


def solve(m, theta, omega, alpha):
    va = velocity_polygon(m, locate(m, theta), omega)
    return va, acceleration_polygon(m, va, alpha)


def coincident(m):
    """Names of points that only coincide with a joint for an instant (no time derivative applies)."""
    names = set()
    for s in assembly_plan(m):
        names |= {getattr(s, a, "") for a in ("coincident", "coincident_a", "coincident_b")}
    return names - {""}


@pytest.mark.parametrize("name", MECHANISMS)
def test_one_degree_of_freedom(name):
    f, working = mobility(MECHANISMS[name]())
    assert f == 1, working


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(name=st.sampled_from(sorted(MECHANISMS)), theta=st.floats(-math.pi, math.pi),
       omega=st.floats(1.0, 50.0).flatmap(lambda w: st.sampled_from([w, -w])),
       alpha=st.one_of(st.just(0.0), st.floats(-500.0, 500.0)))
def test_velocities_and_accelerations_are_time_derivatives(name, theta, omega, alpha):
    """V = d/dt of the constructed positions; A = d/dt of the velocity polygon (Richardson-extrapolated
    central differences, as in test_acceleration); sliding joints in both senses of rotation, both
    branches; the Coriolis term is in every acceleration downstream of a slot."""
    m = MECHANISMS[name]()
    try:
        va, aa = solve(m, theta, omega, alpha)
    except (CannotAssemble, IndeterminatePosition):
        assume(False)
    assume(va.worst_condition >= 0.3 and aa.worst_condition >= 0.3)
    skip = coincident(m)
    h = 1e-3 / max(max(abs(w) for w in va.angular.values()), math.sqrt(abs(alpha)))

    def state(dt):
        return solve(m, theta + omega * dt + alpha * dt * dt / 2, omega + alpha * dt, alpha)

    def derivative(step):
        (vp, _), (vm, _) = state(step), state(-step)
        pos = {n: (vp.pose[n] - vm.pose[n]) / (2 * step) for n in va.velocities if n not in skip}
        lin = {n: (vp.velocities[n] - vm.velocities[n]) / (2 * step) for n in aa.accelerations if n not in skip}
        ang = {n: (vp.angular[n] - vm.angular[n]) / (2 * step) for n in aa.angular}
        return pos, lin, ang
    (p1, l1, w1), (p2, l2, w2) = derivative(h), derivative(h / 2)
    vref = max(v.norm() for v in va.velocities.values())
    aref = max(a.norm() for a in aa.accelerations.values())
    for n, v in p1.items():      # at t + dt the crank speed is omega + alpha dt: d/dt positions = V(t)
        assert ((p2[n] * 4 - v) / 3).distance_to(va.velocities[n]) <= 1e-7 * vref, f"V_{n}"
    for n, a in l1.items():
        assert ((l2[n] * 4 - a) / 3).distance_to(aa.accelerations[n]) <= 1e-7 * aref, f"A_{n}"
    wref = max(max(abs(x) for x in aa.angular.values()), abs(alpha), omega * omega)
    for n, a in w1.items():
        assert (4 * w2[n] - a) / 3 == pytest.approx(aa.angular[n], abs=1e-7 * wref), f"alpha_{n}"


@pytest.mark.parametrize("omega", [12.0, -12.0])
@pytest.mark.parametrize("branch", [1, -1])
def test_coriolis_component_in_both_senses_and_both_directions(omega, branch):
    """A^c = 2 omega_3 x V_A3A: square to the slot, magnitude 2 |omega_3| |V_slide|, turned from the
    sliding velocity in the sense of omega_3 -- whichever way the crank turns and the block slides."""
    m = quick_return(0.0, branch, ram=False)
    for deg in (20.0, 100.0, 200.0, 290.0):
        va, aa = solve(m, math.radians(deg), omega, 30.0)
        w3 = va.angular[3]
        v_rel = va.velocities["A3"] - va.velocities["A"]
        ac = aa.coriolis["A_A3A^c"]
        slot = va.pose.lines["A"].direction
        assert abs(ac.dot(slot)) <= 1e-12 * ac.norm()
        assert ac.norm() == pytest.approx(2 * abs(w3) * v_rel.norm(), rel=1e-12)
        assert math.copysign(1, v_rel.cross(ac)) == math.copysign(1, w3)
    # both directions of sliding occur over a turn
    signs = {math.copysign(1, (solve(m, math.radians(d), omega, 0.0)[0].velocities["A3"]
                               - solve(m, math.radians(d), omega, 0.0)[0].velocities["A"]).dot(
        solve(m, math.radians(d), omega, 0.0)[0].pose.lines["A"].direction)) for d in range(0, 360, 30)}
    assert signs == {1.0, -1.0}


def test_the_slotted_lever_reads_as_the_notes_write_it():
    m = quick_return()
    va, aa = solve(m, math.radians(30), 10.0, 20.0)
    plan = assembly_plan(m)
    assert isinstance(plan[1], SlotThrough) and plan[1].coincident == "A3"
    assert [e.text(marks=False) for e in va.construction.equations][0] == "V_A3 = V_A + V_A3A"
    assert [e.text(marks=False) for e in aa.construction.equations][0] == \
        "A_A3^n + A_A3^t = A_A + A_A3A^c + A_A3A^s"
    eq = aa.construction.equations[0]
    assert eq.unknowns == 2 and "A_A3A^c(\u2713\u2713)" in eq.text()
    words = " ".join(s.caption for s in aa.construction.steps)
    assert "Coriolis component A_A3A^c = 2 \u03c9_3 \u00d7 V_A3A" in words and "turned 90\u00b0" in words
    names = {e.name for e in aa.construction.entities(Diagram.ACCELERATION)}
    assert {"A_A3A^c", "trial A_A3A^s", "trial A_A3^t", "result A_A3A^s"} <= names
    # the block turns with the lever
    assert va.angular[2] == va.angular[3] and aa.angular[2] == aa.angular[3]


def test_ternary_links_are_one_plate():
    m = watt_six_bar()
    pose = locate(m, math.radians(40))
    plates = [e for e in pose.construction.entities(Diagram.SPACE) if e.name in ("link 2", "link 3")]
    assert len(plates) == 2 and all(len(p.vertices) == 3 for p in plates)
    # the third points are joints: G hangs from E and F
    assert {s.joint for s in assembly_plan(m) if hasattr(s, "joint")} >= {"C", "G"}


def test_a_two_degree_of_freedom_linkage_is_refused_with_its_count():
    five_bar = Mechanism({"O1": Vec(0, 0), "O2": Vec(0.1, 0)},
                         (Link(1, ("O1", "B"), 0.03), Link(2, ("B", "C"), 0.08), Link(3, ("C", "D"), 0.08),
                          Link(4, ("O2", "D"), 0.03)), (), (), 1, {"C": Branch(1, ("B", "D"))})
    with pytest.raises(DegenerateInput, match=r"2 degrees of freedom \(n = 5, j1 = 5, j2 = 0"):
        assembly_plan(five_bar)


def test_a_structure_is_refused_too():
    m = Mechanism({"O1": Vec(0, 0), "O2": Vec(0.1, 0)},
                  (Link(1, ("O1", "B"), 0.03), Link(2, ("B", "O2"), 0.08)), (), (), 1, {})
    with pytest.raises(DegenerateInput, match="0 degrees of freedom"):
        assembly_plan(m)


def test_a_slot_that_cannot_reach_the_joint_says_so():
    m = quick_return(offset=0.2, ram=False)          # the slot passes 200 mm from O2; A is ~100 mm away
    with pytest.raises(CannotAssemble, match="slot of link 3 passes"):
        locate(m, math.radians(30))


# -- against the analytic check (constraint equations) on random slotted levers and ternary six-bars ----------

@st.composite
def random_slotted_levers(draw):
    """A crank O1A whose block slides in the (offset, slanted) slot of a lever about O2, the lever driving
    a ram through PQ: random proportions, branch and sense."""
    unit = draw(st.floats(0.01, 2.0))
    d = unit * draw(st.floats(1.2, 3.0))                 # O1O2 > crank: the lever oscillates (quick-return)
    r = unit
    offset = unit * draw(st.floats(-0.3, 0.3))
    slant = draw(st.floats(-0.3, 0.3))
    branch = draw(st.sampled_from([1, -1]))
    block = draw(st.booleans())
    m = Mechanism({"O1": Vec(0.0, d), "O2": Vec(0.0, 0.0)},
                  (Link(1, ("O1", "A"), r), Link(3, ("O2", "P"), 2.5 * d)),
                  (Slide(2 if block else None, "A", Vec(0, 0), slant, on=3, offset=offset),), (), 1,
                  {"A": Branch(branch, ("O2",))})
    return m


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(m=st.one_of(random_slotted_levers(), st.sampled_from([watt_six_bar(), ternary_posed_by_other_points(),
                                                            rocker_with_slot(), slot_and_guide()])),
       theta=st.floats(-math.pi, math.pi), omega=st.floats(1.0, 50.0).flatmap(lambda w: st.sampled_from([w, -w])),
       alpha=st.one_of(st.just(0.0), st.floats(-500.0, 500.0)))
def test_graphical_equals_the_constraint_equations(m, theta, omega, alpha):
    from constructions.check import analytic_solution, analytic_values, compare
    try:
        va, aa = solve(m, theta, omega, alpha)
    except (CannotAssemble, IndeterminatePosition):
        assume(False)
    assume(va.worst_condition >= 0.05 and aa.worst_condition >= 0.05)
    a = analytic_solution(m, theta, omega, alpha, guess=va.pose.positions)
    assert a is not None and a.model in ("constraint equations", "dyad chain")
    rows = compare(va.measured(m) + aa.measured(m), analytic_values(m, a), {**va.scales(), **aa.scales()})
    assert all(r.analytic is not None for r in rows)
    bad = [(r.name, r.relative, r.tolerance) for r in rows if not r.agrees]
    assert not bad
    if any(s.on is not None for s in m.slides):
        assert any(r.name.endswith("^c") for r in rows)          # the Coriolis component is checked too


def test_a_joint_carried_along_two_lines_reads_as_the_notes_would_write_it():
    from constructions.mechanisms.assembly import TwoLines
    m = slot_and_guide()
    plan = assembly_plan(m)
    assert isinstance(plan[-1], TwoLines) and plan[-1].coincident_a == "J3"
    va, aa = solve(m, 0.7, 10.0, 30.0)
    assert [e.text(marks=False) for e in va.construction.equations][-1] == "V_J3 + V_JJ3 = V_J"
    assert [e.text(marks=False) for e in aa.construction.equations][-1] == "A_J3 + A_JJ3^c + A_JJ3^s = A_J"
    assert abs(aa.accelerations["J"].x) <= 1e-12 * aa.accelerations["J"].norm()      # along the vertical guide
    assert "A_JJ3^c" in aa.coriolis and aa.angular[6] == 0.0 and aa.angular[5] == aa.angular[3]
