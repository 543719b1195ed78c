"""Accelerations of the independent analytic check: the closed forms (constructions.analytic) and the
dyad-chain vector loops (constructions.analytic.vector_loops).

The two are derived differently (the closed forms differentiate the vector loop
V_B + omega2 k x p = omega3 k x q; the chain differentiates the constant-length constraints
(J - P).(V_J - V_P) = 0 a second time) and share no code, so they check each other.  Both are further
checked against

* central differences of their own velocities in time (the motion theta(t) = theta + omega t +
  alpha t^2 / 2, omega(t) = omega + alpha t is exact, so A = dV/dt with no chain rule to get wrong);
* exact cases derived by hand below (in-line slider-crank at the dead centre and at 90 deg, the
  parallelogram four-bar), the x_C(theta) route to the notes' acceleration Examples 1 and 2;
* the second derivative of every constraint (|J - P|^2 = const, J on its guide);
* linearity: at a given angle every acceleration is a linear function of (omega^2, alpha).
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from constructions import analytic as an
from constructions.analytic import chain_solution, coupler_point, four_bar, slider_crank
from constructions.geometry import Vec
from constructions.mechanisms.model import Attached, Branch, Link, Mechanism, Slide
from mechanisms import six_bar, toggle_linkage as short_toggle_linkage   # the non-Grashof toggle linkage

FAST = settings(max_examples=100, deadline=None)
MM = 1e-3
EPS = np.finfo(np.float64).eps

FB_ACC = ("alpha2", "alpha3", "ABx", "ABy", "ACx", "ACy")
SC_ACC = ("alpha2", "ABx", "ABy", "ACx", "ACy", "slider_acceleration")

length = st.floats(0.2, 5.0)
coord = st.floats(-3.0, 3.0)
turn = st.floats(-math.pi, math.pi)
speed = st.floats(0.5, 50.0) | st.floats(-50.0, -0.5)
accel = st.floats(-500.0, 500.0)
sign = st.sampled_from([1, -1])

THETA = np.linspace(-math.pi, math.pi, 97) + 0.0123


def close(a, b, ref, rtol):
    return np.all(np.abs(np.asarray(a) - np.asarray(b)) <= rtol * np.asarray(ref))


# -- mechanisms -----------------------------------------------------------------------------------------

def four_bar_mechanism(o1, o2, r1, r2, r3, branch, attached=()):
    return Mechanism({"O1": Vec(*o1), "O2": Vec(*o2)},
                     (Link(1, ("O1", "B"), r1), Link(2, ("B", "C"), r2), Link(3, ("O2", "C"), r3)), (),
                     tuple(attached), 1, {"C": Branch(branch, ("B", "O2"))})


def slider_mechanism(o1, g, gamma, r1, r2, branch, attached=()):
    return Mechanism({"O1": Vec(*o1)}, (Link(1, ("O1", "B"), r1), Link(2, ("B", "C"), r2)),
                     (Slide(3, "C", Vec(*g), gamma),), tuple(attached), 1, {"C": Branch(branch, ("B",))})


def toggle_linkage() -> Mechanism:
    """The notes' velocity Example 3 toggle linkage as in gallery/notes-velocity-example-3.toml (a
    Grashof crank-rocker driving the slider: it moves through the whole turn)."""
    return Mechanism(
        ground={"O1": Vec(0, 0), "O2": Vec(60 * MM, 80 * MM)},
        links=(Link(1, ("O1", "B"), 40 * MM), Link(2, ("B", "C"), 100 * MM), Link(3, ("O2", "C"), 60 * MM),
               Link(4, ("C", "D"), 80 * MM)),
        slides=(Slide(5, "D", Vec(0, 0), 0.0),), attached=(Attached("P", 2, "B", 30 * MM, 0.4),), crank=1,
        branches={"C": Branch(-1, ("B", "O2")), "D": Branch(1, ("C",))})


# -- (1) closed forms equal the dyad chain ---------------------------------------------------------------

def acc_rtol(size, shortest, condition):
    """1e-9 relative, or a rounding bound where the mechanism is worse conditioned: the accelerations
    carry the rounding of the positions magnified by kappa^2 (kappa = (size / shortest) / condition,
    the velocity solve's condition number, applied twice: once in V, once more in A)."""
    with np.errstate(divide="ignore", invalid="ignore"):
        kappa = (size / shortest) / condition
    return np.maximum(1e-9, 64 * EPS * kappa * kappa)


@FAST
@given(o1=st.tuples(coord, coord), frame=length, frame_angle=turn, r1=length, r2=length, r3=length,
       branch=sign, omega=speed, alpha=accel, dc=st.floats(0.0, 4.0), ac=turn, dr=st.floats(0.0, 4.0),
       ar=turn)
def test_four_bar_accelerations_equal_the_dyad_chain(o1, frame, frame_angle, r1, r2, r3, branch, omega,
                                                     alpha, dc, ac, dr, ar):
    o2 = (o1[0] + frame * math.cos(frame_angle), o1[1] + frame * math.sin(frame_angle))
    attached = [Attached("P", 2, "B", dc, ac), Attached("R", 3, "O2", dr, ar)]
    m = four_bar_mechanism(o1, o2, r1, r2, r3, branch, attached)
    s = four_bar(THETA, omega, alpha, crank_pivot=o1, rocker_pivot=o2, crank=r1, coupler=r2, rocker=r3,
                 branch=branch)
    c = chain_solution(m, THETA, omega, alpha)
    ok = s.assembles & (s.condition > 0.05) & c.assembles
    assume(ok.any())
    size = r1 + r2 + r3 + frame
    rt = acc_rtol(size, min(r1, r2, r3), s.condition)[ok]
    # reference: the largest acceleration of the crank tip and of C, and the largest alpha * length
    a_ref = np.maximum((omega * omega + abs(alpha)) * r1, np.hypot(s.ACx, s.ACy))[ok]
    al_ref = np.maximum(np.abs(s.alpha2), np.abs(s.alpha3))[ok]
    assert close(c.accelerations["B"][0][ok], s.ABx[ok], a_ref, rt)
    assert close(c.accelerations["B"][1][ok], s.ABy[ok], a_ref, rt)
    assert close(c.accelerations["C"][0][ok], s.ACx[ok], a_ref, rt)
    assert close(c.accelerations["C"][1][ok], s.ACy[ok], a_ref, rt)
    # angular accelerations as the tangential accelerations they give (alpha * length)
    assert close(c.angular_acceleration[2][ok] * r2, s.alpha2[ok] * r2, a_ref, rt)
    assert close(c.angular_acceleration[3][ok] * r3, s.alpha3[ok] * r3, a_ref, rt)
    assert np.all(c.angular_acceleration[1] == alpha)
    # points fixed to the coupler (from B) and the rocker (from O2) against analytic.coupler_point
    w_ref = np.maximum(np.abs(s.omega2), np.abs(s.omega3))[ok]
    for a, (bx, by, vbx, vby, abx, aby, t, w, al) in (
            (attached[0], (s.Bx, s.By, s.VBx, s.VBy, s.ABx, s.ABy, s.theta2, s.omega2, s.alpha2)),
            (attached[1], (o2[0], o2[1], 0.0, 0.0, 0.0, 0.0, s.theta3, s.omega3, s.alpha3))):
        p = coupler_point(bx, by, vbx, vby, t, w, distance=a.distance, angle=a.angle, ABx=abx, ABy=aby,
                          alpha2=al)
        ref = a_ref + a.distance * (al_ref + w_ref ** 2)
        A = c.accelerations[a.name]
        assert close(A[0][ok], p.ADx[ok], ref, rt) and close(A[1][ok], p.ADy[ok], ref, rt), a.name


@FAST
@given(o1=st.tuples(coord, coord), g=st.tuples(coord, coord), gamma=turn, r1=length, r2=length,
       branch=sign, omega=speed, alpha=accel, dc=st.floats(0.0, 4.0), ac=turn)
def test_slider_crank_accelerations_equal_the_dyad_chain(o1, g, gamma, r1, r2, branch, omega, alpha, dc, ac):
    attached = [Attached("P", 2, "C", dc, ac)]
    m = slider_mechanism(o1, g, gamma, r1, r2, branch, attached)
    s = slider_crank(THETA, omega, alpha, crank_pivot=o1, crank=r1, coupler=r2, guide_point=g,
                     guide_angle=gamma, branch=branch)
    c = chain_solution(m, THETA, omega, alpha)
    ok = s.assembles & (s.condition > 0.05) & c.assembles
    assume(ok.any())
    rt = acc_rtol(r1 + r2, min(r1, r2), s.condition)[ok]
    a_ref = np.maximum((omega * omega + abs(alpha)) * r1, np.hypot(s.ACx, s.ACy))[ok]
    for name, (ax, ay) in (("B", (s.ABx, s.ABy)), ("C", (s.ACx, s.ACy))):
        assert close(c.accelerations[name][0][ok], ax[ok], a_ref, rt), name
        assert close(c.accelerations[name][1][ok], ay[ok], a_ref, rt), name
    assert close(c.angular_acceleration[2][ok] * r2, s.alpha2[ok] * r2, a_ref, rt)
    assert np.all(c.angular_acceleration[3] == 0.0) and np.all(c.angular_acceleration[1] == alpha)
    # A_C along the guide, with the signed slider acceleration
    ex, ey = math.cos(gamma), math.sin(gamma)
    assert close(s.ACx[ok], s.slider_acceleration[ok] * ex, a_ref, 1e-15)
    assert close(s.ACy[ok], s.slider_acceleration[ok] * ey, a_ref, 1e-15)
    # a point on the coupler measured from C: through C, direction C -> B
    p = coupler_point(s.Cx, s.Cy, s.VCx, s.VCy, s.theta2 + math.pi, s.omega2, distance=dc, angle=ac,
                      ABx=s.ACx, ABy=s.ACy, alpha2=s.alpha2)
    ref = a_ref + dc * (np.abs(s.alpha2) + s.omega2 ** 2)[ok]
    A = c.accelerations["P"]
    assert close(A[0][ok], p.ADx[ok], ref, rt) and close(A[1][ok], p.ADy[ok], ref, rt)


# -- (2) derivative of the velocities in time ------------------------------------------------------------

STENCIL = (-4, -2, -1, 1, 2, 4)


def _time_steps(theta, omega, alpha, h):
    """Crank angle and speed at t + k h, k in STENCIL, for theta(t) = theta + omega t + alpha t^2 / 2."""
    return [(theta + omega * k * h + 0.5 * alpha * (k * h) ** 2, omega + alpha * k * h) for k in STENCIL]


def _five_point(f, h):
    """Fourth-order central differences of f sampled at STENCIL * h: with step h, and with step 2 h."""
    fm4, fm2, fm1, f1, f2, f4 = f
    return ((fm2 - 8.0 * fm1 + 8.0 * f1 - f2) / (12.0 * h),
            (fm4 - 8.0 * fm2 + 8.0 * f2 - f4) / (24.0 * h))


def matches_derivative(f, h, value, ref, rtol=1e-7):
    """``value`` equals the time derivative of the samples ``f``: |D_h - value| <= rtol ref + |D_h - D_2h|.

    D_h and D_2h are the five-point differences with steps h and 2 h.  Their truncation errors are
    C h^4 and 16 C h^4, so |D_h - D_2h| ~ 15 |C| h^4 bounds the truncation error of D_h fifteen times
    over wherever the motion varies so fast (next to a limit position, a short link on a long one)
    that C h^4 is not small against rtol ref.  A wrong acceleration does not get that allowance:
    D_h and D_2h agree with each other and both disagree with it."""
    d1, d2 = _five_point(f, h)
    return close(d1, value, rtol * np.asarray(ref) + np.abs(d1 - d2), 1.0)


# Step and tolerance.  The natural time unit of the motion is 1 / W with W = sqrt(omega^2 + |alpha|)
# (the crank turns through omega h + alpha h^2 / 2 in a step h), so the step is h = TAU / W and the
# acceleration scale is W^2 L = (omega^2 + |alpha|) L, L the sum of the lengths.
# * Truncation: the five-point difference is off by h^4 / 30 times the fifth time derivative of V,
#   i.e. ~TAU^4 / 30 times the fifth theta-derivative of the positions in units of W^2 L.  That
#   derivative is O(1) in the middle of the range of motion but grows like condition^-9 next to a
#   limit position (the positions go like sqrt(theta - theta_limit), condition ~ sqrt of it too):
#   with the condition > 0.2 enforced over the whole stencil it stays below ~1e7 (measured: the error
#   of a rocker at condition 0.21 falls as TAU^4, 8e-6 at TAU = 1e-3, 8e-10 of W^2 L at TAU = 1e-4).
# * Rounding: ~1.5 eps kappa V / h <= 1.5 eps kappa W^2 L / TAU, kappa = (L / shortest link) /
#   condition <= 25 / 0.2 here: ~4e-10 of W^2 L at TAU = 1e-4.
# TAU = 1e-4 keeps both near 1e-9; asserting 1e-7 of W^2 L leaves two orders of margin and still
# fails at once on a wrong term (a missing omega^2 or alpha term is O(1) of that scale).  Where a
# random mechanism moves faster still (a crank four times its rocker at condition 0.2 reaches 30 W^2 L
# and ~1e-6 of truncation), the difference between the steps h and 2 h states the truncation
# error (matches_derivative).
TAU = 1e-4


def _step(omega, alpha):
    return TAU / math.sqrt(omega * omega + abs(alpha))


@FAST
@given(o1=st.tuples(coord, coord), frame=length, frame_angle=turn, r1=length, r2=length, r3=length,
       branch=sign, omega=speed, alpha=accel)
def test_four_bar_accelerations_are_the_time_derivative_of_the_velocities(o1, frame, frame_angle, r1, r2, r3,
                                                                         branch, omega, alpha):
    o2 = (o1[0] + frame * math.cos(frame_angle), o1[1] + frame * math.sin(frame_angle))
    mech = dict(crank_pivot=o1, rocker_pivot=o2, crank=r1, coupler=r2, rocker=r3, branch=branch)
    m = four_bar_mechanism(o1, o2, r1, r2, r3, branch)
    h = _step(omega, alpha)
    r = four_bar(THETA, omega, alpha, **mech)
    c = chain_solution(m, THETA, omega, alpha)
    steps = [four_bar(t, w, alpha, **mech) for t, w in _time_steps(THETA, omega, alpha, h)]
    ok = r.assembles & (r.condition > 0.2)
    for st_ in steps:
        ok &= st_.assembles & (st_.condition > 0.2)
    assume(ok.any())
    a_ref = (omega * omega + abs(alpha)) * (r1 + r2 + r3 + frame)
    for v, a in (("VBx", "ABx"), ("VBy", "ABy"), ("VCx", "ACx"), ("VCy", "ACy")):
        assert matches_derivative([getattr(s_, v)[ok] for s_ in steps], h, getattr(r, a)[ok], a_ref), a
    # angular accelerations as the tangential accelerations they give (alpha * length)
    for w, a, ln in (("omega2", "alpha2", r2), ("omega3", "alpha3", r3)):
        assert matches_derivative([getattr(s_, w)[ok] * ln for s_ in steps], h, getattr(r, a)[ok] * ln, a_ref), a
    # the chain, differentiated the same way
    steps = [chain_solution(m, t, w, alpha) for t, w in _time_steps(THETA, omega, alpha, h)]
    for name in ("B", "C"):
        for k in (0, 1):
            assert matches_derivative([s_.velocities[name][k][ok] for s_ in steps], h,
                                      c.accelerations[name][k][ok], a_ref), name
    for n, ln in ((2, r2), (3, r3)):
        assert matches_derivative([s_.angular[n][ok] * ln for s_ in steps], h,
                                  c.angular_acceleration[n][ok] * ln, a_ref), n


@FAST
@given(o1=st.tuples(coord, coord), g=st.tuples(coord, coord), gamma=turn, r1=length, r2=length,
       branch=sign, omega=speed, alpha=accel)
def test_slider_accelerations_are_the_time_derivative_of_the_velocities(o1, g, gamma, r1, r2, branch, omega,
                                                                       alpha):
    mech = dict(crank_pivot=o1, crank=r1, coupler=r2, guide_point=g, guide_angle=gamma, branch=branch)
    m = slider_mechanism(o1, g, gamma, r1, r2, branch)
    h = _step(omega, alpha)
    r = slider_crank(THETA, omega, alpha, **mech)
    c = chain_solution(m, THETA, omega, alpha)
    steps = [slider_crank(t, w, alpha, **mech) for t, w in _time_steps(THETA, omega, alpha, h)]
    ok = r.assembles & (r.condition > 0.2)
    for st_ in steps:
        ok &= st_.assembles & (st_.condition > 0.2)
    assume(ok.any())
    a_ref = (omega * omega + abs(alpha)) * (r1 + r2)
    for v, a in (("VBx", "ABx"), ("VBy", "ABy"), ("VCx", "ACx"), ("VCy", "ACy"),
                 ("slider_speed", "slider_acceleration")):
        assert matches_derivative([getattr(s_, v)[ok] for s_ in steps], h, getattr(r, a)[ok], a_ref), a
    assert matches_derivative([s_.omega2[ok] * r2 for s_ in steps], h, r.alpha2[ok] * r2, a_ref)
    steps = [chain_solution(m, t, w, alpha) for t, w in _time_steps(THETA, omega, alpha, h)]
    for k in (0, 1):
        assert matches_derivative([s_.velocities["C"][k][ok] for s_ in steps], h, c.accelerations["C"][k][ok],
                                  a_ref)
    assert matches_derivative([s_.angular[2][ok] * r2 for s_ in steps], h, c.angular_acceleration[2][ok] * r2,
                              a_ref)


@pytest.mark.parametrize("name", ["toggle", "six-bar"])
def test_chain_accelerations_on_compound_mechanisms(name):
    """Six-bars: accelerations and angular accelerations are the time derivatives of the velocities
    (five-point, TAU as above), every constraint holds to second order, and points fixed to links move
    rigidly."""
    m = toggle_linkage() if name == "toggle" else six_bar()
    omega, alpha = -100.0, 2500.0
    th = np.linspace(-math.pi, math.pi, 181)
    h = _step(omega, alpha)
    c = chain_solution(m, th, omega, alpha)
    steps = [chain_solution(m, t, w, alpha) for t, w in _time_steps(th, omega, alpha, h)]
    good = c.assembles.copy()
    for s_ in [c, *steps]:
        good &= s_.assembles
        for cond in s_.conditions.values():
            good &= cond > 0.1
    assert good.sum() >= 60
    a_ref = np.max([np.hypot(*a) for a in c.accelerations.values()], axis=0)[good]
    for n in c.positions:
        for k in (0, 1):
            fd, _ = _five_point([s_.velocities[n][k] for s_ in steps], h)
            assert close(fd[good], c.accelerations[n][k][good], a_ref, 1e-7), n
    L = sum(k.length for k in m.links)
    for k in m.links:
        fd, _ = _five_point([s_.angular[k.number] for s_ in steps], h)
        assert close(fd[good] * L, c.angular_acceleration[k.number][good] * L, a_ref, 1e-7), k.number
    # second time derivative of |J - P|^2 = length^2:  |V_J - V_P|^2 + (J - P).(A_J - A_P) = 0
    P, V, A = c.positions, c.velocities, c.accelerations
    a = c.assembles
    for k in m.links:
        p, j = k.joints
        rx, ry = P[j][0] - P[p][0], P[j][1] - P[p][1]
        vx, vy = V[j][0] - V[p][0], V[j][1] - V[p][1]
        ax, ay = A[j][0] - A[p][0], A[j][1] - A[p][1]
        res = vx * vx + vy * vy + rx * ax + ry * ay
        ok = a & np.isfinite(res)
        scale_ = k.length * np.max([np.hypot(*acc) for acc in A.values()], axis=0)
        assert close(res[ok], 0.0, scale_[ok], 1e-12), k.joints
    # sliders stay on their (straight, fixed) guides: A_J parallel to the guide
    for s in m.slides:
        gx, gy = math.cos(s.angle), math.sin(s.angle)
        ok = a & np.isfinite(A[s.joint][0])
        assert close((gx * A[s.joint][1] - gy * A[s.joint][0])[ok], 0.0, 1e-15 * np.abs(A[s.joint][0][ok]) + 1e-300,
                     1.0)
    # rigid points: (D - base).(A_D - A_base) = -|V_D - V_base|^2  (second derivative of |D - base|^2)
    for pt in m.attached:
        b = pt.base
        rx, ry = P[pt.name][0] - P[b][0], P[pt.name][1] - P[b][1]
        vx, vy = V[pt.name][0] - V[b][0], V[pt.name][1] - V[b][1]
        ax, ay = A[pt.name][0] - A[b][0], A[pt.name][1] - A[b][1]
        res = vx * vx + vy * vy + rx * ax + ry * ay
        ok = a & np.isfinite(res)
        assert close(res[ok], 0.0, (pt.distance * a_ref.max()), 1e-12), pt.name


# -- (3) exact cases by hand -------------------------------------------------------------------------------

@pytest.mark.parametrize("alpha", [0.0, 37.0])
def test_in_line_slider_crank_exact_cases(alpha):
    """In-line slider-crank, guide = x axis through O1, C ahead.  r = crank, l = coupler.

    theta = 0 (outer dead centre): B = (r, 0), C = (r + l, 0), p = C - B = (l, 0).
      V_C . n = 0 with V_B = omega r (0, 1) and omega2 k x p = (0, omega2 l): omega2 = -omega r / l, V_C = 0.
      A_B = (-omega^2 r, alpha r); A_C = A_B + alpha2 (0, l) - omega2^2 (l, 0) with A_C . n = 0:
      alpha2 = -alpha r / l and  A_C = -omega^2 r - omega2^2 l = -omega^2 r (1 + r / l)  exactly
      (the classic r omega^2 (cos t + (r/l) cos 2t) at t = 0 is exact there, with the minus sign of
      our x axis pointing away from O1).
    theta = 90 deg: B = (0, r), C = (sqrt(l^2 - r^2), 0) =: (c, 0), p = (c, -r), k x p = (r, c).
      V_B = omega r (-1, 0) has no n component, so omega2 = 0 and V_C = -omega r.
      A_B = (-alpha r, -omega^2 r); A_C . n = 0: -omega^2 r + alpha2 c = 0, alpha2 = omega^2 r / c;
      A_C = -alpha r + alpha2 r = -alpha r + omega^2 r^2 / sqrt(l^2 - r^2)  exactly
      (leading order: omega^2 r (r / l), the classic formula's r omega^2 (r/l) cos 180 deg with our sign).
    """
    r, l, omega = 0.05, 0.094, 10.0
    mech = dict(crank_pivot=(0.0, 0.0), crank=r, coupler=l, guide_point=(0.0, 0.0), guide_angle=0.0, branch=1)
    m = slider_mechanism((0.0, 0.0), (0.0, 0.0), 0.0, r, l, 1)
    s0 = slider_crank(0.0, omega, alpha, **mech)
    c0 = chain_solution(m, 0.0, omega, alpha).at()
    for got_acc, got_alpha2 in ((float(s0.slider_acceleration), float(s0.alpha2)),
                                (c0.accelerations["C"][0], c0.angular_acceleration[2])):
        assert got_acc == pytest.approx(-omega ** 2 * r * (1 + r / l), rel=1e-14)
        assert got_alpha2 == pytest.approx(-alpha * r / l, rel=1e-14, abs=1e-12)
    assert float(s0.ACy) == 0.0 and abs(c0.accelerations["C"][1]) == 0.0
    assert float(s0.slider_speed) == pytest.approx(0.0, abs=1e-15)

    c = math.sqrt(l * l - r * r)
    s9 = slider_crank(math.pi / 2, omega, alpha, **mech)
    c9 = chain_solution(m, math.pi / 2, omega, alpha).at()
    for got_acc, got_alpha2 in ((float(s9.slider_acceleration), float(s9.alpha2)),
                                (c9.accelerations["C"][0], c9.angular_acceleration[2])):
        assert got_acc == pytest.approx(-alpha * r + omega ** 2 * r * r / c, rel=1e-13)
        assert got_alpha2 == pytest.approx(omega ** 2 * r / c, rel=1e-13)
    # the classic approximation A_C ~ -r omega^2 (cos t + (r/l) cos 2t) is exact at t = 0 and off by
    # r omega^2 (r/l)^3 / 2 + ... at 90 deg, i.e. by a relative (r/l)^2 / 2
    for t, got in ((0.0, float(s0.slider_acceleration)), (math.pi / 2, float(s9.slider_acceleration))):
        if alpha == 0.0:
            approx = -r * omega ** 2 * (math.cos(t) + (r / l) * math.cos(2 * t))
            assert got == pytest.approx(approx, rel=(r / l) ** 2)


@pytest.mark.parametrize("theta", [0.4, 1.9, -0.7, -2.8])
def test_parallelogram_four_bar_translates_its_coupler(theta):
    """O1 = 0, O2 = (g, 0), crank = rocker = r, coupler = g, assembled as the parallelogram
    C = B + (g, 0): the coupler translates (omega2 = alpha2 = 0), the rocker copies the crank
    (omega3 = omega1, alpha3 = alpha1) and A_C = A_B.  cross(O2 - B, C - B) = g r sin(theta), so the
    parallelogram is branch +1 for sin(theta) > 0 and -1 below."""
    g, r, omega, alpha = 0.12, 0.05, 7.0, -30.0
    br = 1 if math.sin(theta) > 0 else -1
    s = four_bar(theta, omega, alpha, crank_pivot=(0.0, 0.0), rocker_pivot=(g, 0.0), crank=r, coupler=g,
                 rocker=r, branch=br)
    c = chain_solution(four_bar_mechanism((0.0, 0.0), (g, 0.0), r, g, r, br), theta, omega, alpha).at()
    a_ref = (omega ** 2 + abs(alpha)) * r
    assert abs(float(s.alpha2)) * g <= 1e-13 * a_ref and abs(c.angular_acceleration[2]) * g <= 1e-13 * a_ref
    assert float(s.alpha3) == pytest.approx(alpha, abs=1e-13 * a_ref / r)
    assert c.angular_acceleration[3] == pytest.approx(alpha, abs=1e-13 * a_ref / r)
    for got in ((float(s.ACx), float(s.ACy)), c.accelerations["C"]):
        assert got[0] == pytest.approx(float(s.ABx), abs=1e-13 * a_ref)
        assert got[1] == pytest.approx(float(s.ABy), abs=1e-13 * a_ref)
    # A_B itself: alpha k x r - omega^2 r
    assert float(s.ABx) == pytest.approx(-alpha * r * math.sin(theta) - omega ** 2 * r * math.cos(theta),
                                         abs=1e-15 * a_ref)
    assert float(s.ABy) == pytest.approx(alpha * r * math.cos(theta) - omega ** 2 * r * math.sin(theta),
                                         abs=1e-15 * a_ref)


def test_accelerations_are_linear_in_omega_squared_and_alpha():
    """At a fixed angle, the acceleration loop is linear with a right-hand side linear in omega1^2
    and alpha1 (omega2, omega3 are proportional to omega1), so A(omega, alpha) = omega^2 A(1, 0) +
    alpha A(0, 1) -- which also fixes the sign conventions of the alpha1 input."""
    th = np.linspace(-math.pi, math.pi, 41) + 0.01
    fb = dict(crank_pivot=(0.01, -0.02), rocker_pivot=(0.11, 0.0), crank=0.03, coupler=0.09, rocker=0.07,
              branch=-1)
    sc = dict(crank_pivot=(0.0, 0.01), crank=0.05, coupler=0.094, guide_point=(0.0, 0.0), guide_angle=0.3,
              branch=1)
    for fn, mech, names in ((four_bar, fb, FB_ACC), (slider_crank, sc, SC_ACC)):
        w, a = -6.0, 25.0
        full, unit_w, unit_a = fn(th, w, a, **mech), fn(th, 1.0, 0.0, **mech), fn(th, 0.0, 1.0, **mech)
        for n in names:
            want = w * w * getattr(unit_w, n) + a * getattr(unit_a, n)
            ref = np.abs(w * w * getattr(unit_w, n)) + np.abs(a * getattr(unit_a, n)) + 1e-300
            assert close(getattr(full, n), want, ref, 1e-13), n
        # constant speed: alpha1 = 0 is the default
        np.testing.assert_array_equal(fn(th, w, **mech).ACx, fn(th, w, 0.0, **mech).ACx)


# -- (4) the notes' acceleration Examples 1 and 2 ----------------------------------------------------------

@pytest.mark.parametrize("alpha1, at_cb, a_c, alpha2", [(0.0, 5180.0, 520.0, 55.1), (40.0, 4400.0, 1750.0, 46.8)])
def test_notes_acceleration_examples_1_and_2(alpha1, at_cb, a_c, alpha2):
    """In-line slider-crank, O1B = 50 mm at 70 deg, BC = 94 mm, omega1 = 10 rad/s CCW (V_B = 500 mm/s),
    C ahead of B along the +x guide through O1.  Example 1: alpha1 = 0; Example 2: alpha1 = 40 CCW.

    Independent route (not a vector loop): with phi the angle of the coupler below +x,
    l sin(phi) = r sin(theta) and x_C = r cos(theta) + l cos(phi).  Differentiating,
      phi'  = r omega cos(theta) / (l cos(phi)),
      phi'' = (r alpha cos(theta) - r omega^2 sin(theta) + l sin(phi) phi'^2) / (l cos(phi)),
      x_C'' = -r alpha sin(theta) - r omega^2 cos(theta) - l sin(phi) phi'' - l cos(phi) phi'^2,
    and the coupler angle is -phi, so omega2 = -phi', alpha2 = -phi''.  By hand (mm): sin(phi) =
    46.985/94 = 0.49984, cos(phi) = 0.86611, phi' = 171.01/81.414 = 2.1005 rad/s;
    Example 1: phi'' = (-4698.5 + 207.3)/81.414 = -55.17, so alpha2 = 55.17 rad/s^2 CCW,
    A_CB^t = 55.17 * 94 = 5186 and x_C'' = -1710.1 + 2592.0 - 359.2 = +522.6 mm/s^2;
    Example 2: phi'' = (684.0 - 4491.2)/81.414 = -46.76 (alpha2 = 46.76 CCW), A_CB^t = 4396,
    x_C'' = -1879.4 - 1710.1 + 2197.2 - 359.2 = -1751.5 mm/s^2.
    The notes read 5180 / 520 / 55.11 and 4400 / 1750 / 46.8 off their polygons: within 0.5 %.
    """
    r, l, omega, th = 50 * MM, 94 * MM, 10.0, math.radians(70.0)
    s = slider_crank(th, omega, alpha1, crank_pivot=(0.0, 0.0), crank=r, coupler=l, guide_point=(0.0, 0.0),
                     guide_angle=0.0, branch=1)
    c = chain_solution(slider_mechanism((0.0, 0.0), (0.0, 0.0), 0.0, r, l, 1), th, omega, alpha1).at()
    # the independent route above, to full precision
    phi = math.asin(r * math.sin(th) / l)
    d1 = r * omega * math.cos(th) / (l * math.cos(phi))
    d2 = (r * alpha1 * math.cos(th) - r * omega ** 2 * math.sin(th) + l * math.sin(phi) * d1 ** 2) / (l * math.cos(phi))
    xdd = -r * alpha1 * math.sin(th) - r * omega ** 2 * math.cos(th) - l * math.sin(phi) * d2 - l * math.cos(phi) * d1 ** 2
    for acc, al2 in ((float(s.slider_acceleration), float(s.alpha2)),
                     (c.accelerations["C"][0], c.angular_acceleration[2])):
        assert acc == pytest.approx(xdd, rel=1e-12)
        assert al2 == pytest.approx(-d2, rel=1e-12)
    # the notes' figures: |A_CB^t| = |alpha2| BC, |A_C|, alpha2 counter-clockwise (> 0), within 2 %
    assert abs(float(s.alpha2)) * l / MM == pytest.approx(at_cb, rel=0.02)
    assert math.hypot(float(s.ACx), float(s.ACy)) / MM == pytest.approx(a_c, rel=0.02)
    assert float(s.alpha2) == pytest.approx(alpha2, rel=0.02) and float(s.alpha2) > 0
    # the given data: A_B^n = omega^2 O1B = 5000 mm/s^2 toward O1, A_B^t = alpha1 O1B = 2000 in Example 2
    bx, by = float(s.Bx), float(s.By)
    a_n = -(float(s.ABx) * bx + float(s.ABy) * by) / math.hypot(bx, by)
    a_t = (-float(s.ABx) * by + float(s.ABy) * bx) / math.hypot(bx, by)
    assert a_n / MM == pytest.approx(5000.0, rel=1e-12) and a_t / MM == pytest.approx(alpha1 * 50.0, abs=1e-9)
    # A_CB^n = omega2^2 BC = 2.1005^2 * 94 = 414.7 mm/s^2 (the notes print 417, 0.6 % more)
    assert float(s.omega2) ** 2 * l / MM == pytest.approx(414.7, rel=1e-3)


# -- (5) singular positions: NaN, never inf ----------------------------------------------------------------

def test_exact_toggle_gives_nan_accelerations_never_inf():
    # coupler and rocker in line (O2 = (4, 0), crank 1, coupler 2, rocker 1 at theta = 0)
    m = dict(crank_pivot=(0.0, 0.0), rocker_pivot=(4.0, 0.0), crank=1.0, coupler=2.0, rocker=1.0, branch=1)
    r = four_bar(0.0, 10.0, 3.0, **m)
    assert bool(r.assembles) and float(r.condition) <= an.SINE_TOL
    for n in ("alpha2", "alpha3", "ACx", "ACy"):
        assert math.isnan(float(getattr(r, n))), n
    assert math.isfinite(float(r.ABx)) and math.isfinite(float(r.ABy))
    c = chain_solution(four_bar_mechanism((0.0, 0.0), (4.0, 0.0), 1.0, 2.0, 1.0, 1), 0.0, 10.0, 3.0).at()
    assert c.assembles and c.conditions["C"] == 0.0
    assert all(math.isnan(v) for v in c.accelerations["C"])
    assert math.isnan(c.angular_acceleration[2]) and math.isnan(c.angular_acceleration[3])
    assert all(math.isfinite(v) for v in c.accelerations["B"])
    # slider lock: coupler square to the guide
    s = slider_crank(-math.pi / 2, 1.0, 2.0, crank_pivot=(0.0, 0.0), crank=1.0, coupler=2.0,
                     guide_point=(0.0, -3.0), guide_angle=0.0, branch=1)
    assert bool(s.assembles) and float(s.condition) == 0.0
    for n in ("alpha2", "ACx", "ACy", "slider_acceleration"):
        assert math.isnan(float(getattr(s, n))), n
    c = chain_solution(slider_mechanism((0.0, 0.0), (0.0, -3.0), 0.0, 1.0, 2.0, 1), -math.pi / 2, 1.0, 2.0).at()
    assert math.isnan(c.accelerations["C"][0]) and math.isnan(c.angular_acceleration[2])


def test_no_inf_in_accelerations_on_sweeps_through_toggles():
    # a change-point four-bar swept finely passes its toggles; a non-Grashof one leaves its range
    th = np.linspace(-np.pi, np.pi, 4001)
    for mech in (dict(crank_pivot=(0.0, 0.0), rocker_pivot=(2.0, 0.0), crank=1.0, coupler=2.0, rocker=1.0, branch=1),
                 dict(crank_pivot=(0.0, 0.0), rocker_pivot=(1.0, 0.0), crank=0.8, coupler=0.5, rocker=0.6,
                      branch=-1)):
        with np.errstate(all="raise"):
            r = four_bar(th, 1.0, 5.0, **mech)
        for n in FB_ACC:
            assert not np.isinf(getattr(r, n)).any(), n
            assert np.isnan(getattr(r, n)[~r.assembles]).all(), n
        c = chain_solution(four_bar_mechanism(mech["crank_pivot"], mech["rocker_pivot"], mech["crank"],
                                              mech["coupler"], mech["rocker"], mech["branch"]), th, 1.0, 5.0)
        assert not any(np.isinf(v).any() for xy in c.accelerations.values() for v in xy)
        assert not any(np.isinf(v).any() for v in c.angular_acceleration.values())
    s = slider_crank(th, 1.0, 5.0, crank_pivot=(0.0, 0.0), crank=0.8, coupler=0.5, guide_point=(0.0, 1.0),
                     guide_angle=0.0, branch=1)
    assert s.assembles.any() and not s.assembles.all()
    for n in SC_ACC:
        assert np.isnan(getattr(s, n)[~s.assembles]).all(), n
        assert np.isfinite(getattr(s, n)[s.assembles & (s.condition > 1e-6)]).all(), n


def test_chain_out_of_reach_is_nan_except_the_inputs():
    m = short_toggle_linkage()
    th = np.linspace(0.0, 2 * np.pi, 361)
    c = chain_solution(m, th, 5.0, np.linspace(-1.0, 1.0, 361))
    bad = ~c.assembles
    assert bad.any() and c.assembles.any()
    for n, (x, y) in c.accelerations.items():
        if n in m.ground:
            assert np.all(x == 0.0) and np.all(y == 0.0)
        else:
            assert np.isnan(x[bad]).all() and np.isnan(y[bad]).all(), n
    np.testing.assert_array_equal(c.angular_acceleration[1], np.linspace(-1.0, 1.0, 361))
    assert np.all(c.angular_acceleration[5] == 0.0)
    for n in (2, 3, 4):
        assert np.isnan(c.angular_acceleration[n][bad]).all()


# -- (6) API: broadcasting, chunking, coupler points --------------------------------------------------------

def test_alpha_broadcasts():
    fb = dict(crank_pivot=(0.0, 0.0), rocker_pivot=(1.0, 0.0), crank=0.8, coupler=0.5, rocker=0.6, branch=-1)
    th = np.linspace(-7.0, 7.0, 1001)
    al = np.linspace(-50.0, 50.0, 1001)
    whole = (four_bar(th, 2.0, al, **fb),)
    # one angle (and alpha) at a time gives the same numbers; alpha broadcast against theta
    for k in (0, 333, 1000):
        one = four_bar(th[k], 2.0, al[k], **fb)
        for f in dataclasses.fields(one):
            np.testing.assert_array_equal(getattr(one, f.name), getattr(whole[0], f.name)[k], err_msg=f.name)
    # omega1 and alpha1 both arrays: the same values as one call per angle (to rounding: a scalar
    # omega1 is folded into the crank length once, an array one is multiplied element by element)
    w = np.linspace(-9.0, 9.0, th.size)
    both = four_bar(th, w, al, **fb)
    for k in list(np.flatnonzero(both.assembles)[::97]) + [333]:      # 333 does not assemble
        one = four_bar(th[k], w[k], al[k], **fb)
        for n in FB_ACC + ("omega2", "omega3", "VCx", "VCy"):
            assert float(getattr(one, n)) == pytest.approx(float(getattr(both, n)[k]), rel=1e-13, abs=1e-13,
                                                           nan_ok=True), n
    grid = four_bar(th[:5, None], 2.0, al[None, :3], **fb)
    assert grid.alpha3.shape == (5, 3) and grid.ACx.flags.writeable is False
    assert chain_solution(toggle_linkage(), 0.3, 2.0, al[:4]).accelerations["D"][0].shape == (4,)
    assert four_bar(np.array([]), 1.0, **fb).alpha2.shape == (0,)


def test_chain_scalar_and_vector_calls_agree():
    m = six_bar()
    th = np.linspace(-3 * math.pi, 3 * math.pi, 20_000)
    omega = np.linspace(-20.0, 30.0, th.size)
    alpha = np.linspace(300.0, -100.0, th.size)
    c = chain_solution(m, th, omega, alpha)
    for i in (0, 1, 4_095, 4_096, 8_191, 8_192, 12_345, 19_999):   # across chunk boundaries
        a, b = c.at(i), chain_solution(m, th[i], omega[i], alpha[i]).at()
        for n in a.accelerations:
            np.testing.assert_allclose(a.accelerations[n], b.accelerations[n], rtol=0,
                                       atol=1e-12 * (1 + omega[i] ** 2 + abs(alpha[i])))
        for n in a.angular_acceleration:
            np.testing.assert_allclose(a.angular_acceleration[n], b.angular_acceleration[n], rtol=0,
                                       atol=1e-10 * (1 + omega[i] ** 2 + abs(alpha[i])))


def test_coupler_point_acceleration():
    fb = dict(crank_pivot=(0.0, 0.0), rocker_pivot=(0.1, 0.02), crank=0.03, coupler=0.09, rocker=0.07, branch=1)
    th = np.linspace(0.0, 2 * np.pi, 50)
    r = four_bar(th, 4.0, -9.0, **fb)
    base = (r.Bx, r.By, r.VBx, r.VBy, r.theta2, r.omega2)
    acc = dict(ABx=r.ABx, ABy=r.ABy, alpha2=r.alpha2)
    atC = coupler_point(*base, distance=0.09, angle=0.0, **acc)
    np.testing.assert_allclose(atC.ADx, r.ACx, rtol=0, atol=1e-13)
    np.testing.assert_allclose(atC.ADy, r.ACy, rtol=0, atol=1e-13)
    atB = coupler_point(*base, distance=0.0, angle=1.0, **acc)
    np.testing.assert_array_equal(atB.ADx, r.ABx)
    # the relative acceleration has the normal part -omega^2 r and the tangential part alpha k x r
    D = coupler_point(*base, distance=0.05, angle=0.7, **acc)
    rx, ry = D.Dx - r.Bx, D.Dy - r.By
    ax, ay = D.ADx - r.ABx, D.ADy - r.ABy
    np.testing.assert_allclose((ax * rx + ay * ry) / 0.05 ** 2, -r.omega2 ** 2, rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose((rx * ay - ry * ax) / 0.05 ** 2, r.alpha2, rtol=1e-12, atol=1e-12)
    # without the base acceleration: NaN, not a guess; all three or none
    assert np.isnan(coupler_point(*base, distance=0.05, angle=0.7).ADx).all()
    with pytest.raises(ValueError, match="together"):
        coupler_point(*base, distance=0.05, angle=0.7, ABx=r.ABx)
