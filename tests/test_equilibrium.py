"""The global equilibrium system and virtual work against derivations made here by hand: the slider-crank's
closed forms (static, dead centres, friction), the notes' rod released from rest, and -- for random
four-bars, slider-cranks and the slotted mechanisms -- the power balance and every body's equilibrium,
summed in this file from the effects and the vector-loop kinematics, not by the module under test."""

from __future__ import annotations

import math

import pytest
from hypothesis import HealthCheck, assume, given, settings, strategies as st

import constructions.forces.equilibrium as eqm
from constructions.check import NotModelled, analytic_solution
from constructions.errors import IndeterminatePosition
from constructions.forces.effects import Couple, Effects, End, Load, Mass, Spring
from constructions.forces.equilibrium import alpha_for_torque, equilibrium, virtual_work_torque
from constructions.geometry import Vec
from constructions.mechanisms.model import Attached, Link, Mechanism
from constructions.mechanisms.pose import locate
from constructions.mechanisms.topology import Contact, Pin, SlotPin, moving_bodies, points_of_body
from mechanisms import quick_return, rocker_with_slot, slanted_slot, slider_crank, slot_and_guide
from test_acceleration import toggle_four_bar
from strategies import four_bars, slider_cranks

G = Vec(0.0, -9.81)


def inline(r=0.030, l=0.070):
    """O1B = r (link 1), BC = l (link 2), block 3 at C on the x axis, C on +x."""
    return slider_crank((0.0, 0.0), r, l, (0.0, 0.0), 0.0, 1)


def piston(p):
    """P pushing the block towards the crank (-x)."""
    return Effects(loads=(Load("P", 3, "C", Vec(-p, 0.0)),))


def guide_force(q):
    (f, couple), = q.contacts.values()
    return f, couple


# -- the slider-crank by hand -------------------------------------------------------------------------------
# The rod is a two-force member along CB, in compression S; the block: S cos(beta) = P along the guide and
# N = S sin(beta) across it, with sin(beta) = r sin(theta)/l (C below B's height by r sin theta).  The rod
# pushes B along C->B = (-cos beta, sin beta); its moment about O1 is r x S(-cos b, sin b) = P r sin(theta +
# beta)/cos(beta) CCW, so the driver holds the crank with T = -P r sin(theta + beta)/cos(beta) (clockwise for
# 0 < theta < 180).

@pytest.mark.parametrize("deg", [10.0, 45.0, 100.0, 170.0, 200.0, 290.0, 350.0])
def test_static_slider_crank_as_derived_by_hand(deg):
    r, l, p = 0.030, 0.070, 40.0
    th = math.radians(deg)
    beta = math.asin(r * math.sin(th) / l)
    q = equilibrium(inline(r, l), th, 10.0, 0.0, piston(p))
    assert q.torque == pytest.approx(-p * r * math.sin(th + beta) / math.cos(beta), rel=1e-9)
    rod = q.pins[Pin("B", 1, 2)]                             # crank on rod, along B->C (compression)
    assert rod.x == pytest.approx(p, rel=1e-9)
    assert rod.y == pytest.approx(-p * math.tan(beta), rel=1e-9, abs=1e-12 * p)
    assert q.pins[Pin("C", 2, 3)].distance_to(rod) <= 1e-9 * p
    f, couple = guide_force(q)
    assert f.x == pytest.approx(0.0, abs=1e-12 * p)
    assert f.y == pytest.approx(p * math.tan(beta), rel=1e-9)
    assert couple == pytest.approx(0.0, abs=1e-12 * p * r)     # every force on the block passes through C


def test_the_notes_sample_crank_at_45_degrees():
    """OB 30 mm, BC 70 mm, P = 40 N towards the crank: T 1.12 N m (clockwise), rod 42.0 N, guide 12.7 N."""
    m = inline()
    q = equilibrium(m, math.radians(45), 10.0, 0.0, piston(40.0))
    assert q.torque == pytest.approx(-1.118, abs=5e-4)
    assert q.pins[Pin("B", 1, 2)].norm() == pytest.approx(42.0, abs=0.05)
    assert guide_force(q)[0].norm() == pytest.approx(12.7, abs=0.05)
    v = q.values(m)
    assert v["T_1"] == q.torque
    assert v["F_12"] == q.pins[Pin("B", 1, 2)] and v["F_21"] == -q.pins[Pin("B", 1, 2)]
    assert v["F_03"] == guide_force(q)[0] and v["F_30"] == -guide_force(q)[0]
    assert v["F_01"] == q.pins[Pin("O1", 0, 1)]              # the frame on the crank at the main bearing


@pytest.mark.parametrize("deg", [0.0, 180.0])
def test_dead_centres_need_no_torque(deg):
    q = equilibrium(inline(), math.radians(deg), 10.0, 0.0, piston(40.0))
    assert abs(q.torque) < 1e-12 * 40.0 * 0.030
    assert q.pins[Pin("B", 1, 2)].norm() == pytest.approx(40.0, rel=1e-9)


def test_a_toggle_is_named_not_solved():
    m = toggle_four_bar(0.0)                                 # coupler and rocker in line at 90 deg
    with pytest.raises(IndeterminatePosition) as e:
        equilibrium(m, math.pi / 2, 10.0, 0.0, Effects(loads=(Load("P", 3, "C", Vec(5.0, 1.0)),)))
    assert e.value.kind == "toggle"
    assert "crank angle 90 deg" in str(e.value) and "equilibrium equations are singular" in str(e.value)


# -- the notes' dynamic Example 1: a rod released from rest ----------------------------------------------------
# Uniform rod, mass m, length L, pivot O a quarter length from the centre G, horizontal, at rest.
# I_O = m L^2/12 + m (L/4)^2 = 7 m L^2/48; the weight's moment about O is -m g L/4, so alpha = -12 g/(7 L)
# (clockwise: the longer side falls).  a_G = alpha k x (L/4, 0) = (0, -3 g/7), and R - m g = m a_G: the
# pivot holds the rod up with R = 4 m g/7.

def rod(L):
    return Mechanism({"O": Vec(0.0, 0.0)}, (Link(1, ("O", "E"), 0.75 * L),), (),
                     (Attached("G", 1, "O", 0.25 * L, 0.0),), 1, {})


@pytest.mark.parametrize("crank_only_by_hand", [False, True])
def test_a_rod_released_from_rest(crank_only_by_hand, monkeypatch):
    mass, L, g = 2.5, 1.2, 9.81
    m = rod(L)
    if crank_only_by_hand:                                   # the module's own rigid rotation of a lone crank
        def refuse(*a, **k):
            raise NotModelled("not here")
        monkeypatch.setattr(eqm, "analytic_solution", refuse)
    fx = Effects(masses=(Mass(1, mass, "G", mass * L * L / 12),), gravity=Vec(0.0, -g))
    alpha = alpha_for_torque(m, 0.0, 0.0, fx)
    assert alpha == pytest.approx(-12 * g / (7 * L), rel=1e-12)
    q = equilibrium(m, 0.0, 0.0, alpha, fx)
    assert abs(q.torque) <= 1e-12 * mass * g * L
    assert q.pins[Pin("O", 0, 1)].x == pytest.approx(0.0, abs=1e-12 * mass * g)
    assert q.pins[Pin("O", 0, 1)].y == pytest.approx(4 * mass * g / 7, rel=1e-12)
    assert virtual_work_torque(m, 0.0, 0.0, alpha, fx) == pytest.approx(0.0, abs=1e-12 * mass * g * L)


# -- sums made here: every effect, every body's equilibrium, the power of the known forces ------------------

def known(m, fx, kin):
    """(body, point, force, couple) of every load, spring, weight and D'Alembert term, from their definitions."""
    out = [(ld.body, ld.at, ld.force, 0.0) for ld in fx.loads]
    out += [(c.body, None, Vec(0, 0), c.torque) for c in fx.couples]
    for s in fx.springs:
        pa, pb = (kin.positions[e.at] if e.body is not None else fx.fixed.get(e.at, m.ground.get(e.at))
                  for e in (s.a, s.b))
        pull = (pb - pa).unit() * (s.stiffness * ((pb - pa).norm() - s.free_length))
        out += [(s.a.body, s.a.at, pull, 0.0), (s.b.body, s.b.at, -pull, 0.0)]
    for ms in fx.masses:
        blk = m.blocks().get(ms.body)
        turn = ms.body if blk is None else blk.on
        alpha = 0.0 if turn is None else kin.angular_acceleration[turn]
        out.append((ms.body, ms.centre, kin.accelerations[ms.centre] * -ms.mass + (fx.gravity or Vec(0, 0)) * ms.mass,
                    -ms.inertia * alpha))
    return [x for x in out if x[0] is not None]


def scale(m, fx, kin):
    """The size of the torques in play: sum |F| L + |C| over the known effects."""
    return sum(f.norm() * m.size + abs(c) for _, _, f, c in known(m, fx, kin)) or 1.0


def residuals(m, q, fx, kin):
    """Net force and moment about the origin on every moving body, from the solution's joint forces."""
    P = kin.positions
    net = {b: [Vec(0, 0), 0.0] for b in moving_bodies(m)}

    def add(body, at, f, c=0.0):
        if body in net:
            net[body][0] += f
            net[body][1] += (P[at].cross(f) if at else 0.0) + c
    for pin, f in q.pins.items():
        add(pin.other, pin.joint, f)
        add(pin.carrier, pin.joint, -f)
    for c, (f, couple) in q.contacts.items():
        add(c.block if isinstance(c, Contact) else c.carrier, c.joint, f, couple)
        add(c.guide, c.joint, -f, -couple)
    add(m.crank, None, Vec(0, 0), q.torque)
    for body, at, f, c in known(m, fx, kin):
        add(body, at, f, c)
    return net


def assert_balanced(m, q, fx, kin):
    s = scale(m, fx, kin)
    for body, (f, c) in residuals(m, q, fx, kin).items():
        assert f.norm() <= 1e-9 * s / m.size, f"force on body {body}"
        assert abs(c) <= 1e-9 * s * max(1.0, max(p.norm() for p in kin.positions.values()) / m.size), body


def virtual_power(m, fx, kin, vir):
    """Power of the known effects at the virtual velocities (crank at 1 rad/s)."""
    total = 0.0
    for body, at, f, c in known(m, fx, kin):
        blk = m.blocks().get(body)
        turn = body if blk is None else blk.on
        total += (f.dot(vir.velocities[at]) if at else 0.0) + c * (0.0 if turn is None else vir.angular[turn])
    return total


def size(most):
    """0, or between a thousandth of ``most`` and ``most`` (no subnormal forces)."""
    return st.one_of(st.just(0.0), st.floats(1e-3 * most, most))


@st.composite
def effects_on(draw, m):
    bodies = moving_bodies(m)
    force = st.builds(Vec.polar, size(100.0), st.floats(-math.pi, math.pi))
    point = st.sampled_from(bodies).flatmap(lambda b: st.tuples(st.just(b), st.sampled_from(points_of_body(m, b))))
    loads = tuple(Load(f"P{i}", b, at, draw(force)) for i, (b, at) in enumerate(draw(st.lists(point, max_size=3))))
    couples = tuple(Couple(f"C{i}", b, draw(size(20.0)) * draw(st.sampled_from([1, -1])))
                    for i, b in enumerate(draw(st.lists(st.sampled_from(bodies), max_size=2))))
    masses = []
    for b in draw(st.lists(st.sampled_from(bodies), unique=True, max_size=len(bodies))):
        kg = draw(st.floats(0.01, 10.0))
        radius = m.size * draw(st.floats(0, 0.5))                # of gyration
        masses.append(Mass(b, kg, draw(st.sampled_from(points_of_body(m, b))), kg * radius ** 2))
    springs, fixed = (), {}
    if draw(st.booleans()):
        b, at = draw(point)
        fixed = {"S": Vec(draw(st.floats(-1, 1)), draw(st.floats(-1, 1)))}
        springs = (Spring("k", End(b, at), End(None, "S"), draw(size(5000.0)), draw(st.floats(0, 0.5))),)
    gravity = draw(st.sampled_from([None, G, Vec(3.0, 2.0)]))
    return Effects(loads, couples, tuple(masses), springs, gravity, fixed=fixed)


def dyad_sine(m, P):
    """Sine of the transmission at C: coupler against rocker, or coupler against the guide's normal."""
    u = (P["C"] - P["B"]).unit()
    if m.slides:
        return abs(u.dot(m.slides[0].line.direction))
    return abs(u.cross((P["C"] - P["O2"]).unit()))


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(case=st.one_of(four_bars(), slider_cranks()), alpha=st.one_of(st.just(0.0), st.floats(-5000, 5000)),
       data=st.data())
def test_random_mechanisms_the_system_agrees_with_virtual_work(case, alpha, data):
    m, theta, omega = case
    kin = analytic_solution(m, theta, omega, alpha)
    assume(kin is not None and dyad_sine(m, kin.positions) >= 0.2)
    fx = data.draw(effects_on(m))
    q = equilibrium(m, theta, omega, alpha, fx)
    t = virtual_work_torque(m, theta, omega, alpha, fx)
    assert abs(q.torque - t) <= 1e-9 * scale(m, fx, kin)
    assert_balanced(m, q, fx, kin)
    # and against this file's own power balance
    vir = analytic_solution(m, theta, 1.0, 0.0, accelerations=False)
    assert abs(q.torque + virtual_power(m, fx, kin, vir)) <= 1e-9 * scale(m, fx, kin)


# -- what each effect adds ------------------------------------------------------------------------------------

@pytest.mark.parametrize("deg", [30.0, 135.0, 250.0])
def test_gravity_adds_exactly_the_weights_and_a_mass_its_inertia(deg):
    m = slider_crank((0.0, 0.0), 0.05, 0.16, (0.0, -0.01), 0.0, 1, [Attached("G2", 2, "B", 0.06, 0.1)])
    th, w, al = math.radians(deg), 120.0, -800.0
    base = Effects(loads=(Load("P", 3, "C", Vec(-300.0, 0.0)),), couples=(Couple("C", 2, 1.5),),
                   masses=(Mass(1, 0.4, "O1", 2e-4), Mass(3, 0.9, "C")))
    heavy = Effects(base.loads, base.couples, base.masses, gravity=G)
    kin = analytic_solution(m, th, w, al)
    vir = analytic_solution(m, th, 1.0, 0.0, accelerations=False)
    weights = sum(G.dot(vir.velocities[ms.centre]) * ms.mass for ms in base.masses)
    t0, tg = equilibrium(m, th, w, al, base).torque, equilibrium(m, th, w, al, heavy).torque
    assert tg - t0 == pytest.approx(-weights, rel=1e-9, abs=1e-12 * abs(t0))
    rod = Mass(2, 1.3, "G2", 4e-3)
    more = Effects(base.loads, base.couples, base.masses + (rod,))
    inertia = ((kin.accelerations["G2"] * -rod.mass).dot(vir.velocities["G2"])
               - rod.inertia * kin.angular_acceleration[2] * vir.angular[2])
    tm = equilibrium(m, th, w, al, more).torque
    assert tm - t0 == pytest.approx(-inertia, rel=1e-9, abs=1e-12 * abs(t0))


def test_a_static_analysis_never_asks_for_accelerations(monkeypatch):
    asked = []
    real = eqm.analytic_solution

    def spy(*a, **k):
        asked.append(k.get("accelerations", True))
        return real(*a, **k)
    monkeypatch.setattr(eqm, "analytic_solution", spy)
    m = inline()
    fx = Effects(loads=(Load("P", 3, "C", Vec(-40.0, 0.0)),), couples=(Couple("C", 2, 0.2),),
                 springs=(Spring("k", End(2, "B"), End(None, "O1"), 100.0, 0.01),), friction={3: 0.2})
    equilibrium(m, 0.6, 10.0, 50.0, fx)
    virtual_work_torque(m, 0.6, 10.0, 50.0, fx)
    assert asked and not any(asked)
    asked.clear()
    equilibrium(m, 0.6, 10.0, 50.0, Effects(masses=(Mass(2, 1.0, "B"),)))
    assert asked == [True]


# -- friction ---------------------------------------------------------------------------------------------------
# On the block: N n + f t with |f| = mu |N|, f against the block's velocity V_C.  Friction takes power
# -mu |N| |V_C|, which the driver makes up: T_friction - T_frictionless = -f . V_C / omega.

@pytest.mark.parametrize("deg", [20.0, 75.0, 160.0, 215.0, 300.0])
@pytest.mark.parametrize("omega", [30.0, -30.0])
def test_friction_opposes_the_block_and_costs_its_power(deg, omega):
    m, mu = inline(), 0.25
    th, alpha = math.radians(deg), 200.0
    plain = Effects(loads=(Load("P", 3, "C", Vec(-400.0, 0.0)), Load("Q", 2, "B", Vec(20.0, -90.0))),
                    masses=(Mass(2, 0.5, "C", 1e-4), Mass(3, 0.3, "C")), gravity=G)
    rough = Effects(plain.loads, plain.couples, plain.masses, gravity=G, friction={3: mu})
    q0, q = equilibrium(m, th, omega, alpha, plain), equilibrium(m, th, omega, alpha, rough)
    kin = analytic_solution(m, th, omega, alpha)
    v = kin.velocities["C"]
    f, _ = guide_force(q)
    normal, along = f.y, f.x                                  # the guide is the x axis
    assert abs(along) == pytest.approx(mu * abs(normal), rel=1e-12)
    assert along * v.x < 0
    (c, fr), = q.friction.items()
    assert fr == Vec(along, 0.0)
    assert q.torque - q0.torque == pytest.approx(-fr.dot(v) / omega, rel=1e-9)
    assert virtual_work_torque(m, th, omega, alpha, rough, friction=q.friction) == pytest.approx(q.torque, rel=1e-9)
    assert_balanced(m, q, rough, kin)
    assert q.warnings == ()


def test_friction_at_rest_is_left_out_with_a_warning():
    m = inline()
    rough = Effects(loads=(Load("P", 3, "C", Vec(-40.0, 0.0)),), friction={3: 0.3})
    q = equilibrium(m, 0.8, 0.0, 0.0, rough)
    assert q.torque == equilibrium(m, 0.8, 0.0, 0.0, piston(40.0)).torque
    assert q.friction == {} and len(q.warnings) == 1 and "block 3 does not slide" in q.warnings[0]


# -- slots: a block on a moving slot, a pin in a slot, a joint on two lines -------------------------------------

@pytest.mark.parametrize("build", [quick_return, lambda: quick_return(0.012),
                                   lambda: quick_return(-0.01, -1, ram=False), lambda: quick_return(block=False),
                                   lambda: quick_return(0.015, block=False),
                                   rocker_with_slot, slanted_slot, slot_and_guide],
                         ids=["quick-return", "offset slot", "other branch", "pin in slot", "pin in offset slot",
                              "rocker slot", "slanted slot", "slot and guide"])
@pytest.mark.parametrize("deg", [35.0, 150.0, 260.0])
def test_slotted_mechanisms_balance_and_agree_with_virtual_work(build, deg):
    m = build()
    th, w, al = math.radians(deg), 8.0, -30.0
    guess = dict(locate(m, th).positions)
    bodies = moving_bodies(m)
    fx = Effects(loads=tuple(Load(f"P{b}", b, points_of_body(m, b)[-1], Vec(10.0 * b, -7.0)) for b in bodies),
                 couples=(Couple("C", bodies[-1], 2.0),),
                 masses=tuple(Mass(b, 0.2 * b, points_of_body(m, b)[-1], 1e-3) for b in bodies), gravity=G,
                 friction={s.number: 0.15 for s in m.slides if s.number is not None} | {"A": 0.1})
    q = equilibrium(m, th, w, al, fx, guess=guess)
    kin = analytic_solution(m, th, w, al, guess=guess)
    assert_balanced(m, q, fx, kin)
    assert q.friction and not q.warnings
    vw = virtual_work_torque(m, th, w, al, fx, friction=q.friction, guess=guess)
    assert abs(q.torque - vw) <= 1e-9 * scale(m, fx, kin)
    smooth = Effects(fx.loads, fx.couples, fx.masses, gravity=G)
    q0 = equilibrium(m, th, w, al, smooth, guess=guess)
    vir = analytic_solution(m, th, 1.0, 0.0, accelerations=False, guess=guess)
    assert abs(q0.torque + virtual_power(m, smooth, kin, vir)) <= 1e-9 * scale(m, fx, kin)
    assert any(isinstance(c, SlotPin) for c in q.contacts) == any(s.number is None for s in m.slides)
