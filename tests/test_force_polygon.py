"""The graphical force analysis (free bodies, two- and three-force members, force polygons dyad by dyad)
against the global equilibrium system and virtual work, the notes' static sample, and the hard cases:
a dead centre, a polygon that cannot close, effects switched on and off."""

from __future__ import annotations

import math

import pytest
from hypothesis import HealthCheck, given, settings, strategies as st

from constructions.check import compare
from constructions.errors import IndeterminatePosition
from constructions.forces.bodies import frame_number
from constructions.forces.effects import Couple, Effects, Load, Mass
from constructions.forces.equilibrium import equilibrium, virtual_work_torque
from constructions.forces.polygon import force_analysis
from constructions.geometry import Vec
from constructions.linkage import Branch, Link, Mechanism, Slide, locate
from constructions.polygons.acceleration import acceleration_polygon
from constructions.polygons.velocity import velocity_polygon
from constructions.record import Arrow, Point, TrialLine
from test_linkage_velocity import four_bars, slider_cranks


def compressor(angle_deg: float = 45.0) -> tuple[Mechanism, float]:
    """The notes' compressor: crank O2B = 30 mm, rod BC = 70 mm, piston 4 on a guide through O2."""
    m = Mechanism({"O2": Vec(0.0, 0.0)}, (Link(2, ("O2", "B"), 0.030), Link(3, ("B", "C"), 0.070)),
                  (Slide(4, "C", Vec(0.0, 0.0), 0.0),), (), 2, {"C": Branch(1, ("B",))})
    return m, math.radians(angle_deg)


GAS = Effects(loads=(Load("P", 4, "C", Vec(-40.0, 0.0)),))      # 40 N on the piston, toward the crank


def solve(m, theta, effects, omega=10.0, alpha=0.0):
    pose = locate(m, theta)
    va = velocity_polygon(m, pose, omega) if (effects.inertial or effects.friction) else None
    aa = acceleration_polygon(m, va, alpha) if effects.inertial else None
    return force_analysis(m, pose, effects, velocity=va, acceleration=aa)


def test_notes_static_sample_within_drawing_accuracy():
    m, theta = compressor()
    fa = solve(m, theta, GAS)
    got = {x.name: x.value for x in fa.measured(m)}
    # the notes: T = F_21 h = 42.0 N x 26.6 mm = 1.12 N m (clockwise, against the gas force)
    assert got["T_2"] == pytest.approx(-1.12, rel=0.02)
    assert got["F_32"].norm() == pytest.approx(42.0, rel=0.02)
    beta = math.asin(0.030 * math.sin(theta) / 0.070)
    assert got["F_14"].norm() == pytest.approx(40.0 * math.tan(beta), rel=1e-12)    # the guide's reaction
    assert got["F_14"].x == pytest.approx(0.0, abs=1e-12)                           # square to the guide
    words = " ".join(s.words for s in fa.construction.steps)
    assert "two-force member" in words and "perpendicular distance" in words


def test_static_sample_agrees_with_the_equilibrium_system_and_virtual_work():
    m, theta = compressor()
    fa = solve(m, theta, GAS)
    eq = equilibrium(m, theta, 10.0, 0.0, GAS)
    rows = compare(fa.measured(m), eq.values(m), fa.scales())
    assert rows and all(r.agrees for r in rows)
    assert fa.torque == pytest.approx(virtual_work_torque(m, theta, 10.0, 0.0, GAS), rel=1e-12)


@pytest.mark.parametrize("angle_deg", [0.0, 180.0])
def test_a_dead_centre_needs_no_static_torque(angle_deg):
    m, theta = compressor(angle_deg)
    fa = solve(m, theta, GAS)
    assert fa.torque == 0.0
    assert any("dead centre" in s.words for s in fa.construction.steps)
    assert math.isfinite(next(x.value.norm() for x in fa.measured(m) if x.name == "F_32"))


def test_a_polygon_that_cannot_close_is_named():
    # the rod stands square to the guide: its force and the guide's reaction lie on one line
    m = Mechanism({"O2": Vec(0.0, 0.0)}, (Link(2, ("O2", "B"), 0.1), Link(3, ("B", "C"), 0.05)),
                  (Slide(4, "C", Vec(0.0, 0.05), 0.0),), (), 2, {"C": Branch(1, ("B",))})
    with pytest.raises(IndeterminatePosition) as e:
        solve(m, math.pi / 2, GAS)
    assert "cannot close" in str(e.value) and "parallel" in str(e.value)


def test_three_force_member_by_concurrency():
    from test_linkage_velocity import four_bar
    from constructions.linkage import Attached
    m = four_bar((0, 0), (0.12, 0.01), 0.04, 0.13, 0.09, 1, (Attached("E", 2, "B", 0.08, -0.4),))
    fa = solve(m, 1.2, Effects(loads=(Load("P", 2, "E", Vec(10.0, -30.0)),)))
    lines = [e for e in fa.construction.entities() if isinstance(e, TrialLine) and e.diagram.kind == "free-body"
             and e.diagram.name == "link 2"]
    meet = next(e for e in fa.construction.entities() if isinstance(e, Point) and e.label == "I_2")
    assert len(lines) == 3
    for ln in lines:          # the load's line, the two-force line and the third force all pass through I
        d = ln.direction.unit()
        assert abs(d.cross(meet.at - ln.through)) < 1e-12
    words = " ".join(s.words for s in fa.construction.steps)
    assert "three-force member" in words and "Link 3 carries no load" in words


def _random_effects(m: Mechanism, draw, with_mass: bool) -> Effects:
    bodies = {k.number: m.points_of(k.number) for k in m.links}
    bodies.update({b: (s.joint,) for b, s in m.blocks().items()})
    numbers = sorted(bodies)
    loads = []
    for i in range(draw(st.integers(1, 3))):
        b = draw(st.sampled_from(numbers))
        loads.append(Load(f"P{i}", b, draw(st.sampled_from(bodies[b])),
                          Vec.polar(draw(st.floats(1.0, 100.0)), draw(st.floats(0.0, 2 * math.pi)))))
    couples = tuple(Couple(f"M{b}", b, draw(st.floats(-5.0, 5.0)) * m.size)
                    for b in numbers if draw(st.booleans()))
    masses = ()
    if with_mass:
        masses = tuple(Mass(b, draw(st.floats(0.01, 2.0)), draw(st.sampled_from(bodies[b])),
                            draw(st.floats(0.0, 1.0)) * m.size ** 2)
                       for b in numbers if draw(st.booleans()))
    gravity = Vec(0.0, -9.81) if draw(st.booleans()) else None
    return Effects(loads=tuple(loads), couples=couples, masses=masses, gravity=gravity)


@st.composite
def loaded(draw):
    m, theta, omega = draw(st.one_of(four_bars(), slider_cranks()))
    effects = _random_effects(m, draw, draw(st.booleans()))
    return m, theta, omega, draw(st.floats(-500.0, 500.0)), effects


@settings(max_examples=120, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(case=loaded())
def test_random_loaded_mechanisms_graphical_equals_linear_system_equals_virtual_work(case):
    m, theta, omega, alpha, effects = case
    fa = solve(m, theta, effects, omega, alpha)
    eq = equilibrium(m, theta, omega, alpha, effects)
    rows = compare(fa.measured(m), eq.values(m), fa.scales())
    bad = [(r.name, r.relative, r.tolerance) for r in rows if not r.agrees]
    assert not bad
    vw = virtual_work_torque(m, theta, omega, alpha, effects)
    assert fa.torque == pytest.approx(vw, rel=1e-9, abs=1e-9 * fa.scales()["torque"])


def test_no_masses_no_accelerations_and_gravity_adds_exactly_the_weights():
    m, theta = compressor(60.0)
    static = solve(m, theta, GAS)                       # no velocity or acceleration polygon passed
    assert not static.inertial and static.construction.title == "Static force analysis"
    with pytest.raises(ValueError, match="acceleration"):
        force_analysis(m, locate(m, theta), Effects(masses=(Mass(3, 1.0, "C"),)))
    heavy = Effects(loads=GAS.loads, masses=(Mass(4, 2.0, "C"),))
    weighed = Effects(loads=GAS.loads, masses=(Mass(4, 2.0, "C"),), gravity=Vec(0.0, -9.81))
    a, b = solve(m, theta, heavy, 10.0, 0.0), solve(m, theta, weighed, 10.0, 0.0)
    assert a.inertial and a.construction.title == "D'Alembert force analysis"
    # the block's weight is square to the guide: it changes the guide's reaction by exactly m g, and no torque
    f14 = {x.name: x.value for x in a.measured(m)}["F_14"]
    g14 = {x.name: x.value for x in b.measured(m)}["F_14"]
    assert (g14 - f14).y == pytest.approx(2.0 * 9.81, rel=1e-12)
    assert b.torque == pytest.approx(a.torque, rel=1e-12)


@pytest.mark.parametrize("angle_deg", [60.0, -45.0, 200.0])      # the block bears up, down, down
def test_friction_leans_the_guide_reaction_against_the_sliding(angle_deg):
    m, theta = compressor(angle_deg)
    mu = 0.2
    rough = Effects(loads=GAS.loads, friction={4: mu})
    fa = solve(m, theta, rough, omega=10.0)
    f14 = {x.name: x.value for x in fa.measured(m)}["F_14"]
    va = velocity_polygon(m, locate(m, theta), 10.0)
    assert abs(f14.x) == pytest.approx(mu * abs(f14.y), rel=1e-12)
    assert f14.x * va.velocities["C"].x < 0                       # against the block's motion
    eq = equilibrium(m, theta, 10.0, 0.0, rough)
    rows = compare(fa.measured(m), eq.values(m), fa.scales())
    assert all(r.agrees for r in rows)


def test_frame_is_numbered_as_in_the_notes():
    m, _ = compressor()
    assert frame_number(m) == 1
    fa = solve(m, math.radians(45), GAS)
    assert {"F_12", "F_32", "F_43", "F_14", "T_2"} <= {x.name for x in fa.measured(m)}
    polygon = [e for e in fa.construction.entities() if isinstance(e, Arrow) and e.diagram.kind == "force"]
    assert polygon and any(e.label == "P" for e in polygon)
