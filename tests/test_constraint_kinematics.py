"""The constraint solver in body coordinates (constructions.mechanisms.constraint_kinematics): the
analytic check of every mechanism the model accepts.

Checked (1) against the closed forms of constructions.analytic (four-bar, slider-crank, coupler points)
and against the dyad chains of constructions.analytic.vector_loops (toggle linkage, six-bars of binary links) on
random cases; (2) on the mechanisms neither of those models -- slotted-lever quick-return with a block
and with a pin in a slot, offset slots, a block meeting a moving slot, a Watt six-bar with ternary
links, a ternary link found through its third point, and an Assur triad that cannot be drawn dyad by
dyad at all -- against Richardson-extrapolated time derivatives of its own positions and velocities,
and by the Coriolis relation between a sliding joint and the slotted link's coincident point; (3)
against the graphical construction (velocity and acceleration polygons) at well-conditioned positions;
(4) the stated behaviour at a lock, where nothing assembles, for a mechanism that is not 1-DoF, and
with links spanning 1e-3 .. 1e3.
"""

from __future__ import annotations

import functools
import math

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

from constructions import analytic
from constructions.analytic import chain_solution
from constructions.mechanisms.constraint_kinematics import (SINGULAR, TOLERANCE, ConstraintState, solve_constraints, solve_positions)
from constructions.mechanisms.constraint_model import constraint_count
from constructions.errors import CannotAssemble, DegenerateInput, IndeterminatePosition
from constructions.geometry import Vec
from constructions.mechanisms.assembly import assembly_plan
from constructions.mechanisms.model import Attached, Branch, Link, Mechanism, Slide
from constructions.mechanisms.pose import locate
from mechanisms import (quick_return, rocker_with_slot, six_bar, slanted_slot, ternary_posed_by_other_points,
                        toggle_linkage, watt_chain, watt_six_bar)

EPS = float(np.finfo(np.float64).eps)


# -- mechanisms -------------------------------------------------------------------------------------
# the mechanisms come from tests/mechanisms.py, shared with the construction's and dyad chain's tests

TRIAD_ANGLE = math.radians(60)


def assur_triad(scale: float = 1.0) -> tuple[Mechanism, dict[str, Vec]]:
    """Crank O1A drives the ternary link BCD (link 3) through AB; the ternary link hangs from the fixed
    pivots O2 and O3 by the rockers O2C and O3D.  No joint of the triad is reachable from two known
    ones, so it cannot be drawn dyad by dyad (assembly_plan refuses it); the constraint solver needs no
    order.  The lengths are measured off the assembly returned with it (at TRIAD_ANGLE); over a turn
    the condition number stays between 11 and 21."""
    O1, O2, O3 = Vec(0, 0), Vec(0.10, -0.06) * scale, Vec(0.0, 0.08) * scale
    A = Vec.polar(0.012 * scale, TRIAD_ANGLE)
    B, C, D = Vec(0.06, 0.0) * scale, Vec(0.10, 0.02) * scale, Vec(0.07, 0.06) * scale
    m = Mechanism({"O1": O1, "O2": O2, "O3": O3},
                  (Link(1, ("O1", "A"), 0.012 * scale), Link(2, ("A", "B"), A.distance_to(B)),
                   Link(3, ("B", "C"), B.distance_to(C)), Link(4, ("O2", "C"), O2.distance_to(C)),
                   Link(5, ("O3", "D"), O3.distance_to(D))),
                  (), (Attached("D", 3, "B", B.distance_to(D), (D - B).angle() - (C - B).angle()),), 1, {})
    return m, {"A": A, "B": B, "C": C, "D": D}


SLIDING = {"quick-return": quick_return, "quick-return, offset slot": lambda: quick_return(0.012),
           "quick-return, other branch": lambda: quick_return(-0.01, -1, ram=False),
           "pin in a slot": lambda: quick_return(block=False), "pin in an offset slot":
           lambda: quick_return(0.015, block=False), "block meets a moving slot": rocker_with_slot,
           "block meets a slanted offset slot": slanted_slot, "Watt six-bar": watt_six_bar,
           "ternary posed through its third point": ternary_posed_by_other_points}
COMPOUND = {"toggle": toggle_linkage, "toggle crossed": lambda: toggle_linkage(1, -1), "six-bar": six_bar,
            "six-bar other E": lambda: six_bar(1), "Watt chain": watt_chain}
DRAWN = {**SLIDING, **COMPOUND}
EVERY = sorted(DRAWN) + ["Assur triad"]


@functools.lru_cache(maxsize=None)
def _triad_track() -> tuple[tuple[float, dict[str, Vec]], ...]:
    """The triad's assembly every 10 deg over a turn, each solved from its neighbour (continuation)."""
    m, guess = assur_triad()
    out = []
    for k in range(36):
        th = TRIAD_ANGLE + math.radians(10 * k)
        guess = dict(solve_positions(m, th, guess).positions)
        out.append((th, guess))
    return tuple(out)


def mechanism_and_guess(name: str, theta: float) -> tuple[Mechanism, dict[str, Vec]]:
    """The mechanism and a guess of its assembly at theta: the construction's pose for the drawn ones
    (moved off by 1e-3 L, so that Newton-Raphson has work to do), the nearest point of the continuation
    track for the triad.  Assumes the example away where the construction does not assemble."""
    if name == "Assur triad":
        m, _ = assur_triad()
        d = lambda th: abs(math.remainder(th - theta, 2 * math.pi))   # noqa: E731
        return m, dict(min(_triad_track(), key=lambda t: d(t[0]))[1])
    m = DRAWN[name]()
    try:
        pose = locate(m, theta)
    except (CannotAssemble, IndeterminatePosition):
        assume(False)
    nudge = 1e-3 * m.size
    return m, {n: p + Vec(nudge, -nudge / 2) for n, p in pose.positions.items() if n not in m.ground}


def rel(a: Vec, b: Vec, ref: float) -> float:
    return a.distance_to(b) / ref


# -- counts and refusals ----------------------------------------------------------------------------

@pytest.mark.parametrize("name", EVERY)
def test_as_many_equations_as_coordinates(name):
    m = assur_triad()[0] if name == "Assur triad" else DRAWN[name]()
    unknowns, equations = constraint_count(m)
    assert unknowns == equations == 3 * (len(m.links) + len(m.blocks()))


def test_a_two_degree_of_freedom_linkage_is_refused_with_its_count():
    five_bar = Mechanism({"O1": Vec(0, 0), "O2": Vec(0.1, 0)},
                         (Link(1, ("O1", "B"), 0.03), Link(2, ("B", "C"), 0.08), Link(3, ("C", "D"), 0.08),
                          Link(4, ("O2", "D"), 0.03)), (), (), 1, {"C": Branch(1, ("B", "D"))})
    with pytest.raises(DegenerateInput, match=r"2 degrees of freedom: 4 moving bodies have 12 coordinates "
                                              r"and their joints give 10 constraint equations"):
        solve_constraints(five_bar, 0.3, 1.0, 0.0, {})


def test_a_structure_is_refused_too():
    m = Mechanism({"O1": Vec(0, 0), "O2": Vec(0.1, 0)},
                  (Link(1, ("O1", "B"), 0.03), Link(2, ("B", "O2"), 0.08)), (), (), 1, {})
    with pytest.raises(DegenerateInput, match="0 degrees of freedom"):
        constraint_count(m)


def test_an_incomplete_or_foreign_guess_is_refused():
    m = quick_return()
    pose = locate(m, 0.4).positions
    with pytest.raises(DegenerateInput, match="at least two points of link 4"):
        solve_constraints(m, 0.4, 1.0, 0.0, {n: p for n, p in pose.items() if n != "Q"})
    with pytest.raises(DegenerateInput, match="'Z', which is no point"):
        solve_constraints(m, 0.4, 1.0, 0.0, {**pose, "Z": Vec(0, 0)})
    # the coincident point A3 and the fixed pivots may be in it (the construction's pose has them)
    assert solve_constraints(m, 0.4, 1.0, 0.0, pose).iterations >= 1


def test_the_triad_is_no_chain_of_dyads_but_solves():
    m, guess = assur_triad()
    with pytest.raises(DegenerateInput, match="cannot be constructed dyad by dyad"):
        assembly_plan(m)
    s = solve_constraints(m, TRIAD_ANGLE, 10.0, 0.0, guess)
    assert all(s.positions[n].distance_to(p) <= 1e-15 for n, p in guess.items())
    # the continuation comes back to the same assembly after a whole turn
    back = solve_positions(m, TRIAD_ANGLE + 2 * math.pi, _triad_track()[-1][1])
    assert all(back.positions[n].distance_to(p) <= 1e-14 for n, p in guess.items())
    assert max(solve_positions(m, th, g).condition_number for th, g in _triad_track()) < 25


# -- (1) the closed forms and the dyad chains ------------------------------------------------------

length = st.floats(0.2, 5.0)
coord = st.floats(-3.0, 3.0)
turn = st.floats(-math.pi, math.pi)
speed = st.floats(0.5, 50.0) | st.floats(-50.0, -0.5)
sign = st.sampled_from([1, -1])
THETA = np.linspace(-math.pi, math.pi, 7)[:-1] + 0.1

# Tolerance of the comparisons with the other analytic solutions: 1e-9 of the largest value of each
# kind.  Both sides are exact methods in floating point.  The constraint solver's error is bounded by
# about eps kappa^2 (velocities) and eps kappa^3 (accelerations) -- velocity_error_estimate and
# acceleration_error_estimate -- and the closed forms carry 64 ulp L / r_short / condition
# (tests/test_vector_loops.py).  Measured over ~34,000 positions of these tests (condition > 0.05,
# kappa up to 260): positions within 2e-14 L, velocities within 3e-13 and accelerations within 7e-12
# of the largest value (the worst at kappa > 100); at kappa < 30, 2e-14 and 6e-14.  Kappa grows as
# one over the worst dyad condition: over 20,001 crank angles of each compound mechanism (condition >
# 0.01) kappa x condition stays below 13.7 (toggle, crossed), hence KAPPA_X_CONDITION.  Where the
# construction is compared (conditions >= 0.3) that keeps kappa below KAPPA; where the dyad chain is
# (conditions > 0.05), below 300.
KAPPA = 100.0
KAPPA_X_CONDITION = 15.0
AGREE = 1e-9


def compare_point(s: ConstraintState, name: str, p, v, a, L: float, vref: float, aref: float) -> None:
    assert rel(s.positions[name], Vec(*p), L) <= AGREE, f"position of {name}"
    assert rel(s.velocities[name], Vec(*v), vref) <= AGREE, f"V_{name}"
    assert rel(s.accelerations[name], Vec(*a), aref) <= AGREE, f"A_{name}"


def nudged(points: dict[str, tuple[float, float]], m: Mechanism, condition: float,
           rng: np.random.Generator) -> dict[str, tuple]:
    """The reference positions moved off by up to 1e-2 of the shortest link times the condition (the
    sine of the transmission angle): a guess, not the answer, but always nearer this assembly than the
    other one, which lies about 2 condition |shortest link| away at worst."""
    r = 1e-2 * min(k.length for k in m.links) * condition
    return {n: (x + rng.uniform(-r, r), y + rng.uniform(-r, r)) for n, (x, y) in points.items()}


@settings(max_examples=60, deadline=None)
@given(o1=st.tuples(coord, coord), frame=length, frame_angle=turn, r1=length, r2=length, r3=length,
       branch=sign, omega=speed, alpha=st.floats(-500.0, 500.0), dc=st.floats(0.0, 4.0), ac=turn,
       dr=st.floats(0.0, 4.0), ar=turn, from_c=st.booleans(), seed=st.integers(0, 2**32 - 1))
def test_equals_four_bar_closed_form(o1, frame, frame_angle, r1, r2, r3, branch, omega, alpha, dc, ac, dr, ar,
                                     from_c, seed):
    O1 = Vec(*o1)
    O2 = O1 + Vec.polar(frame, frame_angle)
    attached = []
    if dc > 0:
        attached.append(Attached("P", 2, "C" if from_c else "B", dc, ac))
    if dr > 0:
        attached.append(Attached("R", 3, "O2" if from_c else "C", dr, ar))
    m = Mechanism({"O1": O1, "O2": O2}, (Link(1, ("O1", "B"), r1), Link(2, ("B", "C"), r2),
                                         Link(3, ("C", "O2"), r3)), (), tuple(attached), 1,
                  {"C": Branch(branch, ("B", "O2"))})
    s = analytic.four_bar(THETA, omega, alpha, crank_pivot=o1, rocker_pivot=O2.as_tuple(), crank=r1, coupler=r2,
                          rocker=r3, branch=branch)
    ok = np.flatnonzero(s.assembles & (s.condition > 0.05))
    assume(ok.size)
    rng = np.random.default_rng(seed)
    L = m.size
    reach = max([a.distance for a in attached] + [0.0])
    for i in ok:
        B, C = (float(s.Bx[i]), float(s.By[i])), (float(s.Cx[i]), float(s.Cy[i]))
        guess = nudged({"B": B, "C": C}, m, float(s.condition[i]), rng)
        c = solve_constraints(m, float(THETA[i]), omega, alpha, guess)
        w_ref = max(abs(omega), abs(s.omega2[i]), abs(s.omega3[i]))
        al_ref = max(abs(alpha), abs(s.alpha2[i]), abs(s.alpha3[i]), w_ref ** 2)
        vref = max(abs(omega) * r1, math.hypot(s.VCx[i], s.VCy[i])) + reach * w_ref
        aref = max(math.hypot(s.ABx[i], s.ABy[i]), math.hypot(s.ACx[i], s.ACy[i])) + reach * al_ref
        compare_point(c, "B", B, (s.VBx[i], s.VBy[i]), (s.ABx[i], s.ABy[i]), L, vref, aref)
        compare_point(c, "C", C, (s.VCx[i], s.VCy[i]), (s.ACx[i], s.ACy[i]), L, vref, aref)
        for k, w, al in ((1, omega, alpha), (2, s.omega2[i], s.alpha2[i]), (3, s.omega3[i], s.alpha3[i])):
            assert c.angular[k] == pytest.approx(w, abs=AGREE * w_ref), k
            assert c.angular_acceleration[k] == pytest.approx(al, abs=AGREE * al_ref), k
        # points fixed to the coupler and the rocker: analytic.coupler_point from the joint each is
        # measured from, in the direction from that joint to the link's other joint (the closed form's
        # theta2 is B -> C and theta3 is O2 -> C)
        state = {"B": (B, (s.VBx[i], s.VBy[i]), (s.ABx[i], s.ABy[i])),
                 "C": (C, (s.VCx[i], s.VCy[i]), (s.ACx[i], s.ACy[i])), "O2": (O2.as_tuple(), (0, 0), (0, 0))}
        toward = {(2, "B"): s.theta2[i], (2, "C"): s.theta2[i] + math.pi,
                  (3, "O2"): s.theta3[i], (3, "C"): s.theta3[i] + math.pi}
        for a in attached:
            (bx, by), (vbx, vby), (abx, aby) = state[a.base]
            w, al = (s.omega2[i], s.alpha2[i]) if a.link == 2 else (s.omega3[i], s.alpha3[i])
            p = analytic.coupler_point(bx, by, vbx, vby, toward[(a.link, a.base)], w, distance=a.distance,
                                       angle=a.angle, ABx=abx, ABy=aby, alpha2=al)
            compare_point(c, a.name, (float(p.Dx), float(p.Dy)), (float(p.VDx), float(p.VDy)),
                          (float(p.ADx), float(p.ADy)), L, vref, aref)


@settings(max_examples=60, deadline=None)
@given(o1=st.tuples(coord, coord), g=st.tuples(coord, coord), gamma=turn, r1=length, r2=length, branch=sign,
       omega=speed, alpha=st.floats(-500.0, 500.0), dc=st.floats(0.0, 4.0), ac=turn, from_c=st.booleans(),
       seed=st.integers(0, 2**32 - 1))
def test_equals_slider_crank_closed_form(o1, g, gamma, r1, r2, branch, omega, alpha, dc, ac, from_c, seed):
    attached = (Attached("P", 2, "C" if from_c else "B", dc, ac),) if dc > 0 else ()
    m = Mechanism({"O1": Vec(*o1)}, (Link(1, ("O1", "B"), r1), Link(2, ("C", "B"), r2)),
                  (Slide(3, "C", Vec(*g), gamma),), attached, 1, {"C": Branch(branch, ("B",))})
    s = analytic.slider_crank(THETA, omega, alpha, crank_pivot=o1, crank=r1, coupler=r2, guide_point=g,
                              guide_angle=gamma, branch=branch)
    ok = np.flatnonzero(s.assembles & (s.condition > 0.05))
    assume(ok.size)
    rng = np.random.default_rng(seed)
    L = m.size
    e = Vec.polar(1.0, gamma)
    for i in ok:
        B, C = (float(s.Bx[i]), float(s.By[i])), (float(s.Cx[i]), float(s.Cy[i]))
        guess = nudged({"B": B, "C": C}, m, float(s.condition[i]), rng)
        c = solve_constraints(m, float(THETA[i]), omega, alpha, guess)
        w_ref = max(abs(omega), abs(s.omega2[i]))
        al_ref = max(abs(alpha), abs(s.alpha2[i]), w_ref ** 2)
        vref = max(abs(omega) * r1, math.hypot(s.VCx[i], s.VCy[i])) + dc * w_ref
        aref = max(math.hypot(s.ABx[i], s.ABy[i]), math.hypot(s.ACx[i], s.ACy[i])) + dc * al_ref
        compare_point(c, "B", B, (s.VBx[i], s.VBy[i]), (s.ABx[i], s.ABy[i]), L, vref, aref)
        compare_point(c, "C", C, (s.VCx[i], s.VCy[i]), (s.ACx[i], s.ACy[i]), L, vref, aref)
        assert c.angular[2] == pytest.approx(s.omega2[i], abs=AGREE * w_ref)
        assert c.angular_acceleration[2] == pytest.approx(s.alpha2[i], abs=AGREE * al_ref)
        assert abs(c.angular[3]) <= AGREE * w_ref and abs(c.angular_acceleration[3]) <= AGREE * al_ref
        assert c.sliding_velocity["C"] == pytest.approx(s.slider_speed[i], abs=AGREE * vref)
        assert c.sliding_acceleration["C"] == pytest.approx(s.slider_acceleration[i], abs=AGREE * aref)
        assert c.slide_directions["C"].distance_to(e) <= 1e-15
        for a in attached:
            # measured from B toward C (the closed form's theta2) or from C toward B
            if a.base == "B":
                p = analytic.coupler_point(s.Bx[i], s.By[i], s.VBx[i], s.VBy[i], s.theta2[i], s.omega2[i],
                                           distance=a.distance, angle=a.angle, ABx=s.ABx[i], ABy=s.ABy[i],
                                           alpha2=s.alpha2[i])
            else:
                p = analytic.coupler_point(s.Cx[i], s.Cy[i], s.VCx[i], s.VCy[i], s.theta2[i] + math.pi,
                                           s.omega2[i], distance=a.distance, angle=a.angle, ABx=s.ACx[i],
                                           ABy=s.ACy[i], alpha2=s.alpha2[i])
            compare_point(c, a.name, (float(p.Dx), float(p.Dy)), (float(p.VDx), float(p.VDy)),
                          (float(p.ADx), float(p.ADy)), L, vref, aref)


@settings(max_examples=40, deadline=None)
@given(name=st.sampled_from(sorted(COMPOUND)), theta=turn, omega=speed, alpha=st.floats(-500.0, 500.0),
       seed=st.integers(0, 2**32 - 1))
def test_equals_the_dyad_chain(name, theta, omega, alpha, seed):
    """Every point, velocity, acceleration, angular velocity and acceleration equal to
    vector_loops.chain_solution's, started from the chain's positions moved off a little (nudged)."""
    m = COMPOUND[name]()
    ch = chain_solution(m, theta, omega, alpha).at()
    assume(ch.assembles and min(ch.conditions.values()) > 0.05)
    L = m.size
    pts = {n: p for n, p in ch.positions.items() if n not in m.ground}
    guess = nudged(pts, m, min(ch.conditions.values()), np.random.default_rng(seed))
    c = solve_constraints(m, theta, omega, alpha, guess)
    assert c.condition_number <= KAPPA_X_CONDITION / min(ch.conditions.values())
    vref = max(math.hypot(*v) for v in ch.velocities.values())
    aref = max(math.hypot(*a) for a in ch.accelerations.values())
    assert set(ch.positions) <= set(c.positions)
    for n in ch.positions:
        compare_point(c, n, ch.positions[n], ch.velocities[n], ch.accelerations[n], L, vref, aref)
    w_ref = max(abs(w) for w in ch.angular.values())
    al_ref = max([abs(a) for a in ch.angular_acceleration.values()] + [w_ref ** 2])
    for k, w in ch.angular.items():
        assert c.angular[k] == pytest.approx(w, abs=AGREE * w_ref), k
        assert c.angular_acceleration[k] == pytest.approx(ch.angular_acceleration[k], abs=AGREE * al_ref), k


# -- (2) time derivatives of its own positions and velocities, and the Coriolis relation -------------

def material_point(s: ConstraintState, m: Mechanism, link: int, p_local: Vec) -> tuple[Vec, Vec]:
    """Position and velocity of the point of ``link`` with body-frame coordinates ``p_local``."""
    origin, phi = s.frames[("link", link)]
    arm = p_local.rotated(phi)
    first = m.link(link).joints[0]
    return origin + arm, s.velocities[first] + arm.perp() * s.angular[link]


def line_coordinate(s: ConstraintState, m: Mechanism, joint: str) -> float:
    """s: the distance of the sliding joint along its line from the line body's origin (the slotted
    link's first joint, or the guide's point)."""
    slide = next(x for x in m.slides if x.joint == joint)
    origin = slide.through if slide.on is None else s.frames[("link", slide.on)][0]
    return (s.positions[joint] - origin).dot(s.slide_directions[joint])


# Richardson-extrapolated central differences, (4 D(h/2) - D(h)) / 3, with the fastest body turned by
# 1e-4 rad over h.  The truncation error, ~ (omega h)^4 ~ 1e-16 of the value times the ratio of the
# fifth derivative to the first (which grows with the condition number; kappa <= 200 here), is
# negligible; the rounding error dominates: the positions carry ~ eps kappa L, divided by h that is
# ~ 1e-12 kappa / 1e-4 ~ 1e-10 of a velocity (more where every point moves slowly against the fastest
# link), and the velocities' ~ 1e-14 divided by omega h ~ 1e-10 of an acceleration.  (With 1e-3 rad
# the truncation reached 1.6e-9 and 1.5e-8 at kappa ~ 100.)  Measured worst over 5,600 random cases:
# 7.4e-10 (velocities, angular velocities and sliding rates) and 1.0e-10 (accelerations); asserted:
FD_TURN = 1e-4
FD_VELOCITY = 1e-8
FD_ACCELERATION = 1e-8


@settings(max_examples=50, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(name=st.sampled_from(EVERY), theta=turn,
       omega=st.floats(1.0, 50.0).flatmap(lambda w: st.sampled_from([w, -w])),
       alpha=st.one_of(st.just(0.0), st.floats(-500.0, 500.0)))
def test_velocities_and_accelerations_are_time_derivatives(name, theta, omega, alpha):
    """V = d/dt of the solved positions, A = d/dt of the solved velocities, omega and alpha likewise for
    every link and block, the sliding rates likewise for every sliding joint; a coincident point (A3)
    by the derivative of the slotted link's material point under the joint at this instant."""
    m, guess = mechanism_and_guess(name, theta)
    s0 = solve_constraints(m, theta, omega, alpha, guess)
    assume(s0.condition_number <= 200)
    h = FD_TURN / max(max(abs(w) for w in s0.angular.values()), math.sqrt(abs(alpha)))

    def state(dt):
        # the crank at t + dt turns at omega + alpha dt: d/dt of the positions is V(t)
        return solve_constraints(m, theta + omega * dt + alpha * dt * dt / 2, omega + alpha * dt, alpha,
                                 s0.positions)

    under = {n: (j, k, (s0.positions[j] - s0.frames[("link", k)][0]).rotated(-s0.frames[("link", k)][1]))
             for n, (j, k) in s0.coincident.items()}

    def rates(step):
        sp, sm = state(step), state(-step)
        dp, dv, dw, da, ds, dsv = {}, {}, {}, {}, {}, {}
        for n in s0.positions:
            if n in under:
                j, k, local = under[n]
                (pp, vp), (pm, vm) = material_point(sp, m, k, local), material_point(sm, m, k, local)
            else:
                pp, vp, pm, vm = sp.positions[n], sp.velocities[n], sm.positions[n], sm.velocities[n]
            dp[n], dv[n] = (pp - pm) / (2 * step), (vp - vm) / (2 * step)
        for k in s0.angular:
            dw[k] = math.remainder(sp.frames[key(s0, k)][1] - sm.frames[key(s0, k)][1], 2 * math.pi) / (2 * step)
            da[k] = (sp.angular[k] - sm.angular[k]) / (2 * step)
        for j in s0.sliding_velocity:
            ds[j] = (line_coordinate(sp, m, j) - line_coordinate(sm, m, j)) / (2 * step)
            dsv[j] = (sp.sliding_velocity[j] - sm.sliding_velocity[j]) / (2 * step)
        return dp, dv, dw, da, ds, dsv

    coarse, fine = rates(h), rates(h / 2)
    rich = [{n: (f[n] * 4 - c[n]) / 3 for n in c} for c, f in zip(coarse, fine)]
    dp, dv, dw, da, ds, dsv = rich
    vref = max(v.norm() for v in s0.velocities.values())
    aref = max(a.norm() for a in s0.accelerations.values())
    wref = max(abs(w) for w in s0.angular.values())
    alref = max(max(abs(a) for a in s0.angular_acceleration.values()), abs(alpha), wref * wref)
    for n in s0.positions:
        assert rel(dp[n], s0.velocities[n], vref) <= FD_VELOCITY, f"V_{n}"
        assert rel(dv[n], s0.accelerations[n], aref) <= FD_ACCELERATION, f"A_{n}"
    for k in s0.angular:
        assert abs(dw[k] - s0.angular[k]) <= FD_VELOCITY * wref, f"omega_{k}"
        assert abs(da[k] - s0.angular_acceleration[k]) <= FD_ACCELERATION * alref, f"alpha_{k}"
    for j in s0.sliding_velocity:
        assert abs(ds[j] - s0.sliding_velocity[j]) <= FD_VELOCITY * vref, f"sliding velocity of {j}"
        assert abs(dsv[j] - s0.sliding_acceleration[j]) <= FD_ACCELERATION * aref, f"sliding acceleration of {j}"


def key(s: ConstraintState, number: int) -> tuple[str, int]:
    return ("link", number) if ("link", number) in s.frames else ("block", number)


SLOTTED = ["quick-return", "quick-return, offset slot", "quick-return, other branch", "pin in a slot",
           "pin in an offset slot", "block meets a moving slot", "block meets a slanted offset slot"]


@pytest.mark.parametrize("omega", [12.0, -12.0])
@pytest.mark.parametrize("name", SLOTTED)
def test_coriolis_relation_between_the_joint_and_the_coincident_point(name, omega):
    """A_JG = A_J + A^s + 2 omega_G x (V_JG - V_J), A^s = -s'' d the sliding acceleration of the slotted
    link's point relative to the joint, and V_JG - V_J along the slot: the normal component of this is
    the second derivative of the point-on-line constraint, so it checks that constraint's gamma (the
    rotating line's terms) directly.  A block on a slot turns with its link."""
    for deg in range(0, 360, 15):
        m, guess = DRAWN[name](), None
        try:
            guess = locate(m, math.radians(deg)).positions
        except (CannotAssemble, IndeterminatePosition):
            continue
        s = solve_constraints(m, math.radians(deg), omega, 40.0, guess)
        aref = max(a.norm() for a in s.accelerations.values())
        vref = max(v.norm() for v in s.velocities.values())
        for name_jg, (j, g) in s.coincident.items():
            d, w = s.slide_directions[j], s.angular[g]
            v_rel = s.velocities[name_jg] - s.velocities[j]
            assert abs(v_rel.cross(d)) <= 1e-13 * vref
            assert v_rel.dot(d) == pytest.approx(-s.sliding_velocity[j], abs=1e-13 * vref)
            a_s = d * -s.sliding_acceleration[j]
            coriolis = v_rel.perp() * (2 * w)
            assert rel(s.accelerations[name_jg], s.accelerations[j] + a_s + coriolis, aref) <= 1e-12
            assert abs((s.accelerations[name_jg] - s.accelerations[j] - coriolis).cross(d)) <= 1e-12 * aref
            slide = next(x for x in m.slides if x.joint == j)
            if slide.number is not None:
                assert s.angular[slide.number] == pytest.approx(w, abs=1e-13 * abs(omega))
                assert s.angular_acceleration[slide.number] == pytest.approx(s.angular_acceleration[g],
                                                                             abs=1e-12 * omega * omega)


# -- (3) the graphical construction ----------------------------------------------------------------

@settings(max_examples=50, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(name=st.sampled_from(sorted(DRAWN)), theta=turn,
       omega=st.floats(1.0, 50.0).flatmap(lambda w: st.sampled_from([w, -w])),
       alpha=st.one_of(st.just(0.0), st.floats(-500.0, 500.0)))
def test_equals_the_velocity_and_acceleration_polygons(name, theta, omega, alpha):
    """va.velocities, aa.accelerations, va.angular and aa.angular equal the constraint solution to 1e-9
    of the largest value of each kind where both trial-line conditions are >= 0.3 (the construction's
    own rounding estimate is then < 4e-14; measured over 4,000 random cases: within 3e-15 of each
    other).  The coincident points (A3) by their names."""
    from constructions.polygons.acceleration import acceleration_polygon
    from constructions.polygons.velocity import velocity_polygon
    m = DRAWN[name]()
    try:
        pose = locate(m, theta)
        va = velocity_polygon(m, pose, omega)
        aa = acceleration_polygon(m, va, alpha)
    except (CannotAssemble, IndeterminatePosition):
        assume(False)
    assume(va.worst_condition >= 0.3 and aa.worst_condition >= 0.3)
    nudge = 1e-3 * m.size
    s = solve_constraints(m, theta, omega, alpha, {n: p + Vec(-nudge, nudge) for n, p in pose.positions.items()})
    assert s.condition_number <= KAPPA
    assert set(va.velocities) == set(s.velocities) and set(aa.accelerations) == set(s.accelerations)
    vref = max(v.norm() for v in va.velocities.values())
    aref = max(a.norm() for a in aa.accelerations.values())
    for n, p in pose.positions.items():
        assert rel(s.positions[n], p, m.size) <= AGREE, n
    for n, v in va.velocities.items():
        assert rel(s.velocities[n], v, vref) <= AGREE, f"V_{n}"
    for n, a in aa.accelerations.items():
        assert rel(s.accelerations[n], a, aref) <= AGREE, f"A_{n}"
    wref = max(abs(w) for w in va.angular.values())
    alref = max(max(abs(a) for a in aa.angular.values()), wref * wref)
    assert set(va.angular) == set(s.angular) == set(aa.angular)
    for k, w in va.angular.items():
        assert s.angular[k] == pytest.approx(w, abs=AGREE * wref), f"omega_{k}"
        assert s.angular_acceleration[k] == pytest.approx(aa.angular[k], abs=AGREE * alref), f"alpha_{k}"


# -- (4) hard cases --------------------------------------------------------------------------------

def locking_four_bar() -> Mechanism:
    """|O1B| 30, |BC| 80, |O2C| 10, |O1O2| 100 mm: at crank angle 0, |BO2| = 70 = |BC| - |O2C|, the
    rocker folds onto the coupler (a lock: the crank cannot turn on)."""
    return Mechanism({"O1": Vec(0, 0), "O2": Vec(0.1, 0)},
                     (Link(1, ("O1", "B"), 0.03), Link(2, ("B", "C"), 0.08), Link(3, ("O2", "C"), 0.01)),
                     (), (), 1, {"C": Branch(1, ("B", "O2"))})


def test_a_lock_is_an_indeterminate_position_but_has_a_position():
    m = locking_four_bar()
    guess = {"B": Vec(0.03, 0.0), "C": Vec(0.11, 0.002)}
    with pytest.raises(IndeterminatePosition, match="link 2 and link 3 can move while the crank is held") as e:
        solve_constraints(m, 0.0, 1.0, 0.0, guess)
    assert e.value.condition < SINGULAR and e.value.position == "crank angle 0 deg"
    p = solve_positions(m, 0.0, guess)
    # Newton-Raphson converges only linearly onto a fold: the residual goes as the square of the distance
    assert p.residual <= TOLERANCE and p.condition_number > 1 / SINGULAR
    assert p.positions["C"].distance_to(Vec(0.11, 0.0)) <= 1e-7 * m.size
    # a little way off the lock the answer is finite, agrees with the closed form, and says how good it is
    th = 1e-3
    s = solve_constraints(m, th, 1.0, 0.0, guess)
    fb = analytic.four_bar(th, 1.0, crank_pivot=(0, 0), rocker_pivot=(0.1, 0), crank=0.03, coupler=0.08,
                           rocker=0.01, branch=1)
    vref = abs(float(fb.omega3)) * 0.01
    err = rel(s.velocities["C"], Vec(float(fb.VCx), float(fb.VCy)), vref)
    assert 1e2 < s.condition_number < 1e4 and err <= s.velocity_error_estimate


def test_where_the_mechanism_does_not_assemble_newton_says_so():
    m = locking_four_bar()
    with pytest.raises(CannotAssemble, match=r"at crank angle 180 deg: Newton-Raphson did not close the "
                                             r"constraint equations .* the worst is joint C"):
        solve_constraints(m, math.pi, 1.0, 0.0, {"B": Vec(-0.03, 0.0), "C": Vec(0.05, 0.03)})


def test_a_dead_centre_is_regular():
    """The rocker's extreme (crank and coupler in line): the rocker stops, the Jacobian is regular."""
    m = Mechanism({"O1": Vec(0, 0), "O2": Vec(0.1, 0)},
                  (Link(1, ("O1", "B"), 0.03), Link(2, ("B", "C"), 0.08), Link(3, ("O2", "C"), 0.06)),
                  (), (), 1, {"C": Branch(1, ("B", "O2"))})
    # C on the circle of radius 0.11 about O1 and 0.06 about O2, B on the line O1C
    x = (0.11 ** 2 - 0.06 ** 2 + 0.1 ** 2) / 0.2
    C = Vec(x, math.sqrt(0.11 ** 2 - x * x))
    th = C.angle()
    s = solve_constraints(m, th, 10.0, 0.0, {"B": Vec.polar(0.03, th), "C": C + Vec(1e-3, 0)})
    assert s.condition_number < 20
    assert s.velocities["C"].norm() <= 1e-13 and abs(s.angular[3]) <= 1e-12
    fb = analytic.four_bar(th, 10.0, crank_pivot=(0, 0), rocker_pivot=(0.1, 0), crank=0.03, coupler=0.08,
                           rocker=0.06, branch=1)
    assert rel(s.accelerations["C"], Vec(float(fb.ACx), float(fb.ACy)), 3.0) <= 1e-12


def test_links_from_a_millimetre_to_a_kilometre():
    """A 1 mm crank on a 1 km coupler with the guide 400 m away: the column scaling by each body's own size
    keeps the Jacobian's condition near the mechanism's, and the answer equals the closed form."""
    r1, r2 = 1e-3, 1e3
    m = Mechanism({"O1": Vec(0, 0)}, (Link(1, ("O1", "B"), r1), Link(2, ("B", "C"), r2)),
                  (Slide(3, "C", Vec(0, 400.0), 0.0),), (), 1, {"C": Branch(1, ("B",))})
    for th in np.linspace(0.1, 6.2, 7):
        s_ = analytic.slider_crank(th, 30.0, 5.0, crank_pivot=(0, 0), crank=r1, coupler=r2, guide_point=(0, 400.0),
                                   guide_angle=0.0, branch=1)
        c = solve_constraints(m, th, 30.0, 5.0, {"B": (float(s_.Bx), float(s_.By)),
                                                 "C": (float(s_.Cx) + 3.0, 400.0)})
        assert c.condition_number < 1e3
        assert rel(c.velocities["C"], Vec(float(s_.VCx), float(s_.VCy)), 30.0 * r1) <= 1e-9
        assert rel(c.accelerations["C"], Vec(float(s_.ACx), float(s_.ACy)), 900.0 * r1) <= 1e-9


@pytest.mark.parametrize("factor", [1e-3, 1e3])
def test_scaling_the_mechanism_scales_the_answer(factor):
    m1, g1 = assur_triad()
    mk, gk = assur_triad(factor)
    for th in (0.3, 2.0, 4.5):
        guess = min(_triad_track(), key=lambda t: abs(math.remainder(t[0] - th, 2 * math.pi)))[1]
        a = solve_constraints(m1, th, 7.0, -20.0, guess)
        b = solve_constraints(mk, th, 7.0, -20.0, {n: p * factor for n, p in guess.items()})
        assert b.condition_number == pytest.approx(a.condition_number, rel=1e-9)
        vref = max(v.norm() for v in a.velocities.values())
        aref = max(v.norm() for v in a.accelerations.values())
        for n in a.positions:
            assert rel(b.velocities[n] / factor, a.velocities[n], vref) <= 1e-12
            assert rel(b.accelerations[n] / factor, a.accelerations[n], aref) <= 1e-12
        for k in a.angular:
            assert b.angular[k] == pytest.approx(a.angular[k], rel=1e-12, abs=1e-12)


def test_newton_converges_from_a_rough_guess_to_the_nearest_assembly():
    """From the construction's pose moved off by up to 2 % of the scene size the solver returns to it,
    quadratically (a handful of steps), with the residual at the rounding floor."""
    rng = np.random.default_rng(7)
    for name in sorted(DRAWN):
        m = DRAWN[name]()
        for th in (0.7, 2.9):
            try:
                pose = locate(m, th)
            except (CannotAssemble, IndeterminatePosition):
                continue
            L = m.size
            guess = {n: p + Vec(*rng.uniform(-0.02, 0.02, 2)) * L for n, p in pose.positions.items()}
            p = solve_positions(m, th, guess)
            assert p.iterations <= 8 and p.residual <= TOLERANCE, name
            assert all(p.positions[n].distance_to(x) <= 1e-12 * L for n, x in pose.positions.items()), name
