"""The dyad-chain vector loops (constructions.analytic.vector_loops): the analytic check of compound mechanisms.

Checked (1) against the closed forms of constructions.analytic on random four-bars and slider-cranks,
(2) against central differences of its own positions and the loop-closure equations on the notes'
toggle linkage and on six-bars, (3) against the graphical velocity polygon through
constructions.check and the `drafting check` command, and (4) vectorised over 1e5 crank angles
against scalar calls.  Plus the stated behaviour where the chain does not close or locks.
"""

from __future__ import annotations

import ast
import math
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from constructions import analytic
from constructions.analytic import chain_solution, solving_order
from constructions.check import analytic_solution, analytic_values, compare
from constructions.errors import CannotAssemble, DegenerateInput
from constructions.geometry import Vec
from constructions.tolerance import AGREEMENT
from constructions.mechanisms.model import Attached, Branch, Link, Mechanism, Slide
from constructions.mechanisms.pose import locate
from constructions.polygons.velocity import velocity_polygon
from mechanisms import six_bar, toggle_linkage, watt_chain
from drafting.app.cli import main

MM = 1e-3


# -- mechanisms ---------------------------------------------------------------------------------------

COMPOUND = {"toggle": toggle_linkage(), "toggle crossed": toggle_linkage(1, -1), "six-bar": six_bar(),
            "six-bar other E": six_bar(1), "Watt chain": watt_chain()}


def links_of(m: Mechanism):
    return [(k.joints[0], k.joints[1], k.length) for k in m.links]


def scale(m: Mechanism) -> float:
    return sum(k.length for k in m.links) + max(math.hypot(p.x, p.y) for p in m.ground.values())


# -- (1) equal to the closed forms on random four-bars and slider-cranks ----------------------------------

length = st.floats(0.2, 5.0)
coord = st.floats(-3.0, 3.0)
turn = st.floats(-math.pi, math.pi)
speed = st.floats(0.5, 50.0) | st.floats(-50.0, -0.5)
sign = st.sampled_from([1, -1])

THETA = np.linspace(-math.pi, math.pi, 97)


def close(a, b, ref, rtol=1e-12):
    """|a - b| <= rtol * ref elementwise (ref an array or a float)."""
    return np.all(np.abs(np.asarray(a) - np.asarray(b)) <= rtol * np.asarray(ref))


EPS = np.finfo(np.float64).eps


def velocity_rtol(size: float, shortest: float, condition: np.ndarray) -> np.ndarray:
    """1e-12, or 64 ulp times the condition number kappa = (size / shortest link) / condition where
    the mechanism is worse conditioned than that (kappa > 70): the velocity of a joint on a short link
    of a large mechanism carries the rounding of the positions magnified by L / r_short, and near a
    toggle by 1 / condition.  Hypothesis found such cases (a 0.2 coupler on a 4.8 crank at condition
    0.05: kappa 500, the closed forms off by 2e-12); a 60-digit reference shows the chain solver
    within 3e-13 there (test_hard_cases_against_a_60_digit_reference)."""
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.maximum(1e-12, 64 * EPS * (size / shortest) / condition)


def check_assembly_agrees(chain_asm, chain_cond, asm, cond):
    """The two solvers may only differ on assembly within rounding of a tangency."""
    differ = chain_asm != asm
    assert not np.any(differ & asm & (cond > 1e-6))
    assert not np.any(differ & chain_asm & (chain_cond > 1e-6))


@settings(max_examples=150, deadline=None)
@given(o1=st.tuples(coord, coord), frame=length, frame_angle=turn, r1=length, r2=length, r3=length,
       branch=sign, omega=speed, dc=st.floats(0.0, 4.0), ac=turn, dr=st.floats(0.0, 4.0), ar=turn,
       from_c=st.booleans())
def test_equals_four_bar_closed_form(o1, frame, frame_angle, r1, r2, r3, branch, omega, dc, ac, dr, ar, from_c):
    O1 = Vec(*o1)
    O2 = O1 + Vec(frame * math.cos(frame_angle), frame * math.sin(frame_angle))
    attached = []
    if dc > 0:
        attached.append(Attached("P", 2, "C" if from_c else "B", dc, ac))
    if dr > 0:
        attached.append(Attached("R", 3, "O2" if from_c else "C", dr, ar))
    # branch given as seen from O2 -> B half the time (the sign flips with the reference)
    ref, bsign = (("B", "O2"), branch) if from_c else (("O2", "B"), -branch)
    m = Mechanism({"O1": O1, "O2": O2}, (Link(1, ("O1", "B"), r1), Link(2, ("B", "C"), r2),
                                         Link(3, ("C", "O2"), r3)), (), tuple(attached), 1,
                  {"C": Branch(bsign, ref)})
    s = analytic.four_bar(THETA, omega, crank_pivot=o1, rocker_pivot=O2.as_tuple(), crank=r1, coupler=r2,
                          rocker=r3, branch=branch)
    c = chain_solution(m, THETA, omega)
    check_assembly_agrees(c.assembles, c.conditions["C"], s.assembles, s.condition)
    ok = s.assembles & (s.condition > 0.05)
    L = r1 + r2 + r3 + frame + math.hypot(*o1) + 8.0
    rt = velocity_rtol(L - 8.0, min(r1, r2, r3), s.condition)[ok]
    v_ref = np.maximum(abs(omega) * r1, np.hypot(s.VCx, s.VCy))[ok]
    w_ref = np.maximum(np.abs(s.omega2), np.abs(s.omega3))[ok]
    assert np.all(c.assembles[ok])
    for name, (x, y), (vx, vy) in (("B", (s.Bx, s.By), (s.VBx, s.VBy)), ("C", (s.Cx, s.Cy), (s.VCx, s.VCy))):
        assert close(c.positions[name][0][ok], x[ok], L) and close(c.positions[name][1][ok], y[ok], L), name
        assert close(c.velocities[name][0][ok], vx[ok], v_ref, rt) and close(c.velocities[name][1][ok], vy[ok], v_ref, rt)
    # angular velocities as the relative velocities they give, |omega| * length, against v_ref (an
    # error of 1e-13 in C is 1e-13 / r3 in the rocker's direction)
    assert close(c.angular[2][ok] * r2, s.omega2[ok] * r2, v_ref, rt)
    assert close(c.angular[3][ok] * r3, s.omega3[ok] * r3, v_ref, rt)
    assert np.all(c.angular[1] == omega)
    # points fixed to the coupler and the rocker against analytic.coupler_point
    for a in attached:
        if a.link == 2:
            base, (bx, by), (vbx, vby), t, w = ("B", (s.Bx, s.By), (s.VBx, s.VBy), s.theta2, s.omega2)
        else:
            base, (bx, by), (vbx, vby), t, w = ("O2", (O2.x, O2.y), (0.0, 0.0), s.theta3, s.omega3)
        if a.base != base:   # measured from the other end: through that joint, direction reversed
            bx, by, vbx, vby, t = (s.Cx, s.Cy, s.VCx, s.VCy, t + math.pi)
        p = analytic.coupler_point(bx, by, vbx, vby, t, w, distance=a.distance, angle=a.angle)
        D, V = c.positions[a.name], c.velocities[a.name]
        vr = v_ref + a.distance * w_ref
        assert close(D[0][ok], p.Dx[ok], L) and close(D[1][ok], p.Dy[ok], L), a.name
        assert close(V[0][ok], p.VDx[ok], vr, rt) and close(V[1][ok], p.VDy[ok], vr, rt), a.name
    # no assembly: NaN everywhere that moves, never inf
    off = ~c.assembles
    assert np.all(np.isnan(c.positions["C"][0][off])) and np.all(np.isnan(c.velocities["B"][0][off]))
    assert not any(np.isinf(v).any() for xy in c.velocities.values() for v in xy)


@settings(max_examples=150, deadline=None)
@given(o1=st.tuples(coord, coord), g=st.tuples(coord, coord), gamma=turn, r1=length, r2=length,
       branch=sign, omega=speed, dc=st.floats(0.0, 4.0), ac=turn, from_c=st.booleans())
def test_equals_slider_crank_closed_form(o1, g, gamma, r1, r2, branch, omega, dc, ac, from_c):
    attached = (Attached("P", 2, "C" if from_c else "B", dc, ac),) if dc > 0 else ()
    m = Mechanism({"O1": Vec(*o1)}, (Link(1, ("O1", "B"), r1), Link(2, ("C", "B"), r2)),
                  (Slide(3, "C", Vec(*g), gamma),), attached, 1, {"C": Branch(branch, ("B",))})
    s = analytic.slider_crank(THETA, omega, crank_pivot=o1, crank=r1, coupler=r2, guide_point=g,
                              guide_angle=gamma, branch=branch)
    c = chain_solution(m, THETA, omega)
    check_assembly_agrees(c.assembles, c.conditions["C"], s.assembles, s.condition)
    ok = s.assembles & (s.condition > 0.05)
    L = r1 + r2 + math.hypot(*o1) + math.hypot(*g) + 4.0
    rt = velocity_rtol(L - 4.0, min(r1, r2), s.condition)[ok]
    v_ref = np.maximum(abs(omega) * r1, np.hypot(s.VCx, s.VCy))[ok]
    w_ref = np.maximum(abs(omega), np.abs(s.omega2))[ok]
    assert np.all(c.assembles[ok])
    for name, (x, y), (vx, vy) in (("B", (s.Bx, s.By), (s.VBx, s.VBy)), ("C", (s.Cx, s.Cy), (s.VCx, s.VCy))):
        assert close(c.positions[name][0][ok], x[ok], L) and close(c.positions[name][1][ok], y[ok], L), name
        assert close(c.velocities[name][0][ok], vx[ok], v_ref, rt) and close(c.velocities[name][1][ok], vy[ok], v_ref, rt)
    assert close(c.angular[2][ok] * r2, s.omega2[ok] * r2, v_ref, rt)
    assert np.all(c.angular[3] == 0.0) and np.all(c.angular[1] == omega)
    for a in attached:
        if a.base == "B":
            p = analytic.coupler_point(s.Bx, s.By, s.VBx, s.VBy, s.theta2, s.omega2, distance=a.distance,
                                       angle=a.angle)
        else:
            p = analytic.coupler_point(s.Cx, s.Cy, s.VCx, s.VCy, s.theta2 + math.pi, s.omega2,
                                       distance=a.distance, angle=a.angle)
        vr = v_ref + a.distance * w_ref
        D, V = c.positions["P"], c.velocities["P"]
        assert close(D[0][ok], p.Dx[ok], L) and close(D[1][ok], p.Dy[ok], L)
        assert close(V[0][ok], p.VDx[ok], vr, rt) and close(V[1][ok], p.VDy[ok], vr, rt)


# 60-digit references (decimal), derived in vector form: a different route from both solvers.

def _dec_cos_sin(x: float):
    """cos and sin of the float x to ~55 digits by their Taylor series (|x| <= 4 here)."""
    from decimal import Decimal
    x = Decimal(x)
    c = s = Decimal(0)
    t, k = Decimal(1), 0
    while abs(t) > Decimal(10) ** -58:
        if k % 4 == 0:
            c += t
        elif k % 4 == 1:
            s += t
        elif k % 4 == 2:
            c -= t
        else:
            s -= t
        k += 1
        t = t * x / k
    return c, s


def _dec_four_bar(th, w, O1, O2, r1, r2, r3, br):
    """C = B + alpha w + beta k x w (w = O2 - B, alpha = (d^2 + r2^2 - r3^2) / 2 d^2, 2 d^2 beta =
    br sqrt(Heron)); V_C from V_B + omega2 k x p = omega3 k x q dotted with q and with p."""
    from decimal import Decimal, localcontext
    with localcontext() as ctx:
        ctx.prec = 60
        c, s = _dec_cos_sin(th)
        O1x, O1y, O2x, O2y, r1, r2, r3, w = map(Decimal, (*O1, *O2, r1, r2, r3, w))
        Bx, By = O1x + r1 * c, O1y + r1 * s
        VBx, VBy = -w * r1 * s, w * r1 * c
        wx, wy = O2x - Bx, O2y - By
        d2 = wx * wx + wy * wy
        d = d2.sqrt()
        S, T = r2 + r3, abs(r2 - r3)
        alpha = (d2 + r2 * r2 - r3 * r3) / (2 * d2)
        beta = br * ((S + d) * (S - d) * (d + T) * (d - T)).sqrt() / (2 * d2)
        Cx, Cy = Bx + alpha * wx - beta * wy, By + alpha * wy + beta * wx
        px, py, qx, qy = Cx - Bx, Cy - By, Cx - O2x, Cy - O2y
        cr = px * qy - py * qx
        om3 = -(VBx * px + VBy * py) / cr
        return float(Cx), float(Cy), float(-om3 * qy), float(om3 * qx)


def _dec_slider(th, w, O1, G, gam, r1, r2, br):
    """C = F + br h e (F the foot of B, h = sqrt((r2 - y)(r2 + y))); omega2 from V_C . n = 0."""
    from decimal import Decimal, localcontext
    with localcontext() as ctx:
        ctx.prec = 60
        c, s = _dec_cos_sin(th)
        ex, ey = _dec_cos_sin(gam)
        O1x, O1y, Gx, Gy, r1, r2, w = map(Decimal, (*O1, *G, r1, r2, w))
        Bx, By = O1x + r1 * c, O1y + r1 * s
        VBx, VBy = -w * r1 * s, w * r1 * c
        nx, ny = -ey, ex
        y = (Bx - Gx) * nx + (By - Gy) * ny
        h = br * ((r2 - y) * (r2 + y)).sqrt()
        Cx, Cy = Bx - y * nx + h * ex, By - y * ny + h * ey
        om2 = -(VBx * nx + VBy * ny) / h
        speed = VBx * ex + VBy * ey + om2 * y
        return float(Cx), float(Cy), float(speed * ex), float(speed * ey)


HARD_FOUR_BARS = [   # (O1, frame, frame angle, r1, r2, r3, branch): short links on long ones
    ((0.0, 0.0), 0.201171875, 0.0, 4.0, 4.0, 0.201171875, 1),
    ((0.0, 0.0), 0.9775138589673569, -1.8304682861655248, 4.9229247738804265, 0.5, 4.78515625, 1),
]
HARD_SLIDERS = [     # (O1, G, guide angle, r1, r2, branch)
    ((0.0, 0.0), (0.0, 0.0), 0.5, 4.7734375, 0.2, 1),
    ((2.1457130387772114, 0.0), (-0.2229614345173232, 0.0), 1.3125, 2.2593996512742422, 0.2, 1),
]


def test_hard_cases_against_a_60_digit_reference():
    """Where hypothesis found the chain and the closed forms apart by more than 1e-12 (kappa ~ 500),
    the chain solver is the one within 1e-12 of the exact answer, at every angle with condition > 0.05."""
    th = np.linspace(-math.pi, math.pi, 97)
    worst = 0.0
    for O1, frame, fa, r1, r2, r3, br in HARD_FOUR_BARS:
        O2 = (O1[0] + frame * math.cos(fa), O1[1] + frame * math.sin(fa))
        m = Mechanism({"O1": Vec(*O1), "O2": Vec(*O2)}, (Link(1, ("O1", "B"), r1), Link(2, ("B", "C"), r2),
                      Link(3, ("C", "O2"), r3)), (), (), 1, {"C": Branch(br, ("B", "O2"))})
        c = chain_solution(m, th, 1.0)
        for i in np.flatnonzero(c.assembles & (c.conditions["C"] > 0.05)):
            Cx, Cy, VCx, VCy = _dec_four_bar(float(th[i]), 1.0, O1, O2, r1, r2, r3, br)
            v_ref = max(r1, math.hypot(VCx, VCy))
            assert math.hypot(c.positions["C"][0][i] - Cx, c.positions["C"][1][i] - Cy) <= 1e-14 * r1
            worst = max(worst, math.hypot(c.velocities["C"][0][i] - VCx, c.velocities["C"][1][i] - VCy) / v_ref)
    for O1, G, gam, r1, r2, br in HARD_SLIDERS:
        m = Mechanism({"O1": Vec(*O1)}, (Link(1, ("O1", "B"), r1), Link(2, ("B", "C"), r2)),
                      (Slide(3, "C", Vec(*G), gam),), (), 1, {"C": Branch(br, ("B",))})
        c = chain_solution(m, th, 1.0)
        for i in np.flatnonzero(c.assembles & (c.conditions["C"] > 0.05)):
            Cx, Cy, VCx, VCy = _dec_slider(float(th[i]), 1.0, O1, G, gam, r1, r2, br)
            v_ref = max(r1, math.hypot(VCx, VCy))
            assert math.hypot(c.positions["C"][0][i] - Cx, c.positions["C"][1][i] - Cy) <= 1e-14 * r1
            worst = max(worst, math.hypot(c.velocities["C"][0][i] - VCx, c.velocities["C"][1][i] - VCy) / v_ref)
    assert worst <= 1e-12, worst


# -- (2) derivative of its own positions, and loop closure, on compound mechanisms ----------------------

@pytest.mark.parametrize("name", sorted(COMPOUND))
def test_velocities_are_the_derivative_of_the_positions(name):
    m, omega, h = COMPOUND[name], -100.0, 1e-6
    th = np.linspace(-math.pi, math.pi, 181)
    c, ahead, behind = (chain_solution(m, t, omega) for t in (th, th + h, th - h))
    good = c.assembles & ahead.assembles & behind.assembles
    for cond in c.conditions.values():
        good &= cond > 0.05
    assert good.sum() >= 60, "the test mechanism should move over a good part of the cycle"
    v_ref = np.max([np.hypot(*v) for v in c.velocities.values()], axis=0)[good]
    for n in c.positions:
        for k in (0, 1):
            fd = (ahead.positions[n][k] - behind.positions[n][k]) * (omega / (2 * h))
            assert close(c.velocities[n][k][good], fd[good], v_ref, 1e-7), n
    # link angular velocities: derivative of the link's direction angle
    for k in m.links:
        p, j = k.joints
        def angle(s):
            return np.arctan2(s.positions[j][1] - s.positions[p][1], s.positions[j][0] - s.positions[p][0])
        fd = np.angle(np.exp(1j * (angle(ahead) - angle(behind)))) * (omega / (2 * h))
        w_ref = np.max(np.abs([*c.angular.values()]), axis=0)[good]
        assert close(c.angular[k.number][good], fd[good], w_ref, 1e-7), k.number


@pytest.mark.parametrize("name", sorted(COMPOUND))
def test_loop_closure(name):
    m, omega = COMPOUND[name], 7.0
    c = chain_solution(m, np.linspace(-math.pi, math.pi, 721), omega)
    a = c.assembles
    assert a.sum() >= 200
    L = scale(m)
    v_ref = np.max([np.hypot(*v) for v in c.velocities.values()], axis=0)[a]
    for p, j, length in links_of(m):
        (Px, Py), (Jx, Jy) = c.positions[p], c.positions[j]
        assert close(np.hypot(Jx - Px, Jy - Py)[a], length, L), (p, j)
        # the derivative of |J - P|^2 = length^2:  (J - P).(V_J - V_P) = 0
        (VPx, VPy), (VJx, VJy) = c.velocities[p], c.velocities[j]
        dot = (Jx - Px) * (VJx - VPx) + (Jy - Py) * (VJy - VPy)
        ok = a & np.isfinite(dot)
        assert close(dot[ok], 0.0, (length * v_ref)[ok[a]]), (p, j)
    for s in m.slides:
        gx, gy = math.cos(s.angle), math.sin(s.angle)
        Jx, Jy = c.positions[s.joint]
        assert close((gx * (Jy - s.through.y) - gy * (Jx - s.through.x))[a], 0.0, L)
        VJx, VJy = c.velocities[s.joint]
        assert close((gx * VJy - gy * VJx)[a], 0.0, v_ref)
    for pt in m.attached:
        base = c.positions[pt.base]
        D = c.positions[pt.name]
        assert close(np.hypot(D[0] - base[0], D[1] - base[1])[a], pt.distance, L)


def test_branch_conventions_on_the_chain():
    m = six_bar()
    c = chain_solution(m, np.linspace(0, 2 * math.pi, 37), 1.0)
    P = c.positions

    def cross(a, b, j):
        return ((P[b][0] - P[a][0]) * (P[j][1] - P[a][1]) - (P[b][1] - P[a][1]) * (P[j][0] - P[a][0]))
    assert np.all(cross("B", "O2", "C") > 0) and np.all(cross("B", "C", "D") > 0)
    assert np.all(cross("D", "O3", "E") < 0)
    t = toggle_linkage()
    c = chain_solution(t, np.linspace(0, 2 * math.pi, 37), 1.0)
    ok = c.assembles
    assert np.all(c.positions["D"][0][ok] > c.positions["C"][0][ok])   # ahead of the foot of C (+x)
    assert np.all(np.abs(c.positions["D"][1][ok]) == 0.0)
    assert solving_order(m) == ("B", "C", "D", "E", "P", "Q") == chain_solution(m, 0.0, 1.0).order


# -- (3) the graphical polygon agrees with it -----------------------------------------------------------

@pytest.mark.parametrize("name", sorted(COMPOUND))
@pytest.mark.parametrize("angle_deg", [0.0, 30.0, 100.0, 200.0, 330.0])
def test_graphical_polygon_agrees_with_dyad_chain(name, angle_deg):
    m, omega = COMPOUND[name], -100.0
    th = math.radians(angle_deg)
    a = analytic_solution(m, th, omega)
    if a is None:   # out of reach: both sides must say so
        assert not chain_solution(m, th, omega).assembles
        with pytest.raises(CannotAssemble):
            locate(m, th)
        return
    va = velocity_polygon(m, locate(m, th), omega)
    assert a.model == "dyad chain"
    rows = compare(va.measured(m), analytic_values(m, a))
    assert len(rows) >= len(m.links) + 2
    assert all(r.agrees for r in rows), [(r.name, r.relative) for r in rows if not r.agrees]
    assert max(r.relative for r in rows) < AGREEMENT * 1e-3     # in fact to rounding
    # positions too, and the angular velocities of the crank and sliders
    for n, p in locate(m, th).positions.items():
        assert (a.positions[n] - p).norm() <= 1e-12 * scale(m), n
    assert a.angular[1] == omega and all(a.angular[s.number] == 0.0 for s in m.slides)


def test_toggle_linkage_not_assembling_gives_none():
    m = toggle_linkage()
    th = math.radians(200.0)          # non-Grashof: the crank cannot reach here
    assert not chain_solution(m, th, 1.0).assembles
    assert analytic_solution(m, th, 1.0) is None


def test_plain_mechanisms_keep_their_closed_forms():
    four = Mechanism({"O1": Vec(0, 0), "O2": Vec(30 * MM, 0)},
                     (Link(1, ("O1", "B"), 10 * MM), Link(2, ("B", "C"), 35 * MM), Link(3, ("O2", "C"), 20 * MM)),
                     (), (Attached("P", 2, "B", 10 * MM, 0.5),), 1, {"C": Branch(1, ("B", "O2"))})
    assert analytic_solution(four, 0.7, 3.0).model == "four-bar"
    slider = Mechanism({"O1": Vec(0, 0)}, (Link(1, ("O1", "B"), 50 * MM), Link(2, ("B", "C"), 94 * MM)),
                       (Slide(3, "C", Vec(0, 0), 0.0),), (), 1, {"C": Branch(1, ("B",))})
    assert analytic_solution(slider, 0.7, 3.0).model == "slider-crank"
    # the two solvers agree there too (V_B = 30 mm/s)
    c = chain_solution(four, 0.7, 3.0).at()
    a = analytic_solution(four, 0.7, 3.0)
    for n, v in a.velocities.items():
        assert (Vec(*c.velocities[n]) - v).norm() <= 1e-12 * 3.0 * 10 * MM, n


SIX_BAR_SCENE = """\
# A Stephenson six-bar: four-bar O1-B-C-O2 with ternary coupler BCD, then the dyad D-E-O3.
[drawing]
title = "Six-bar: velocity polygon"
number = "TEST-6"
paper = "A4"

[units]
length = "mm"
velocity = "mm/s"
angular_velocity = "rad/s"

[frame]
O1 = [0, 0]
O2 = [60, 0]
O3 = [50, 40]

[[link]]
number = 1
joints = ["O1", "B"]
length = 15

[[link]]
number = 2
joints = ["B", "C"]
length = 55

[[link]]
number = 3
joints = ["O2", "C"]
length = 40

[[link]]
number = 4
joints = ["B", "D"]
length = 40

[[link]]
number = 5
joints = ["C", "D"]
length = 30

[[link]]
number = 6
joints = ["D", "E"]
length = 30

[[link]]
number = 7
joints = ["O3", "E"]
length = 30

[[point]]
name = "P"
link = 6
from = "D"
distance = 20
angle = "30 deg"

[input]
link = 1
angle = "100 deg"
omega = "10 rad/s"
sense = "cw"

[assembly]
C = "left of B->O2"
D = "left of B->C"
E = "right of D->O3"

[ask]
analyses = ["velocity"]
"""


def test_drafting_check_on_a_six_bar_scene(tmp_path, capsys):
    p = tmp_path / "six-bar.toml"
    p.write_text(SIX_BAR_SCENE)
    code = main(["check", str(p)])
    out, err = capsys.readouterr()
    assert code == 0, out + err
    assert "agree to 1e-9 relative" in out and "dyad chain" in out
    assert "n/a" not in out and "nothing checked" not in out
    for q in ("V_E", "V_P", "V_ED", "\u03c9_6", "\u03c9_7"):
        assert q in out


# -- (4) vectorised over 1e5 angles ------------------------------------------------------------------

def test_vectorised_matches_scalar_calls():
    m = six_bar()
    th = np.linspace(-3 * math.pi, 3 * math.pi, 100_000)
    omega = np.linspace(-20.0, 30.0, th.size)
    c = chain_solution(m, th, omega)
    assert c.shape == th.shape and c.assembles.all()
    assert not c.positions["E"][0].flags.writeable
    t = toggle_linkage()
    ct = chain_solution(t, th, 5.0)
    assert 0 < ct.assembles.sum() < th.size
    for i in (0, 1, 12_345, 50_000, 77_777, 99_999):
        for mech, full, w in ((m, c, omega[i]), (t, ct, 5.0)):
            one = chain_solution(mech, th[i], w)
            assert one.shape == ()
            a, b = full.at(i), one.at()
            assert a.assembles == b.assembles
            for n in a.positions:
                np.testing.assert_allclose(a.positions[n], b.positions[n], rtol=0, atol=1e-15)
                np.testing.assert_allclose(a.velocities[n], b.velocities[n], rtol=0, atol=1e-13 * (1 + abs(w)))
            for n in a.angular:
                np.testing.assert_allclose(a.angular[n], b.angular[n], rtol=0, atol=1e-12 * (1 + abs(w)))


# -- hard cases ----------------------------------------------------------------------------------------

@pytest.mark.parametrize("rot", [0.0, 0.3, 1.1, -2.4])
def test_designed_toggle_reads_as_toggle(rot):
    """A non-Grashof four-bar whose coupler and rocker are exactly in line at the crank angle rot + 90 deg
    (a 3-4-5 triangle O1-B-O2, |BO2| = 5 = BC + O2C), built from rotated float coordinates: it
    assembles there, condition 0, velocities NaN (never inf); positions finite and on the line BO2."""
    r1, r2, r3, d = 3.0, 2.0, 3.0, 4.0
    m = Mechanism({"O1": Vec(0, 0), "O2": Vec(d * math.cos(rot), d * math.sin(rot))},
                  (Link(1, ("O1", "B"), r1), Link(2, ("B", "C"), r2), Link(3, ("O2", "C"), r3)), (), (), 1,
                  {"C": Branch(1, ("B", "O2"))})
    th = rot + math.pi / 2
    c = chain_solution(m, th, 2.0).at()
    assert c.assembles and c.conditions["C"] == 0.0
    assert all(math.isnan(v) for v in c.velocities["C"]) and math.isnan(c.angular[2])
    assert all(math.isnan(v) for v in c.velocities["C"]) and math.isnan(c.angular[3])
    B, O2 = Vec(*c.positions["B"]), m.ground["O2"]
    expect = B + (O2 - B) * (r2 / 5.0)
    assert (Vec(*c.positions["C"]) - expect).norm() <= 1e-7 * d
    # just inside the range of motion it is finite (and large); just outside it does not assemble
    near = chain_solution(m, th - 1e-3, 2.0).at()
    assert near.assembles and all(math.isfinite(v) for v in near.velocities["C"])
    assert not chain_solution(m, th + 1e-3, 2.0).assembles


def test_slider_lock_gives_nan_velocity():
    """Coupler square to the guide (offset slider-crank at its limit): assembles, V_C NaN."""
    m = Mechanism({"O1": Vec(0, 0)}, (Link(1, ("O1", "B"), 1.0), Link(2, ("B", "C"), 2.0)),
                  (Slide(3, "C", Vec(0, -3.0), 0.0),), (), 1, {"C": Branch(1, ("B",))})
    c = chain_solution(m, -math.pi / 2, 1.0).at()        # B = (0, -1), C = (0, -3): in line, square
    assert c.assembles and c.conditions["C"] == 0.0
    assert math.isnan(c.velocities["C"][0]) and math.isnan(c.angular[2])
    assert not chain_solution(m, math.pi / 2, 1.0).assembles   # B = (0, 1) is 4 from the guide


@pytest.mark.parametrize("spread", [1e-3, 1.0, 1e3])
def test_links_spanning_orders_of_magnitude(spread):
    """The toggle linkage scaled by 1e-3 .. 1e3: the results scale exactly as they should."""
    base = chain_solution(toggle_linkage(), 1.0, 3.0).at()
    t = toggle_linkage()
    m = Mechanism({n: p * spread for n, p in t.ground.items()},
                  tuple(Link(k.number, k.joints, k.length * spread) for k in t.links),
                  tuple(Slide(s.number, s.joint, s.through * spread, s.angle) for s in t.slides), (), 1,
                  t.branches)
    c = chain_solution(m, 1.0, 3.0).at()
    for n in base.positions:
        np.testing.assert_allclose(c.positions[n], np.array(base.positions[n]) * spread, rtol=1e-13, atol=1e-13 * spread * 0.1)
    for n in c.angular:
        assert c.angular[n] == pytest.approx(base.angular[n], rel=1e-12, abs=1e-12)


def test_not_a_dyad_chain_raises():
    t = toggle_linkage()
    no_branch = Mechanism(t.ground, t.links, t.slides, (), 1, {"C": t.branches["C"]})
    with pytest.raises(DegenerateInput, match="joint D .*no assembly branch"):
        chain_solution(no_branch, 0.0, 1.0)
    dangling = Mechanism(t.ground, t.links, (), (), 1, t.branches)   # D on one link only
    with pytest.raises(DegenerateInput, match="branch of D"):
        chain_solution(dangling, 0.0, 1.0)
    wrong_ref = Mechanism(t.ground, t.links, t.slides, (), 1,
                          {"C": Branch(1, ("O1", "O2")), "D": t.branches["D"]})
    with pytest.raises(DegenerateInput, match="C"):
        chain_solution(wrong_ref, 0.0, 1.0)


def test_slots_in_moving_links_are_not_modelled_and_pins_in_fixed_slots_are():
    """The chain solves straight guides fixed to the frame only: a block in a slot of a moving link
    (which needs the Coriolis term) is refused, not solved as if the slot were fixed.  A pin in a
    fixed slot (no block, number None) moves like a block and adds no angular entry."""
    t = toggle_linkage()
    moving = Mechanism(t.ground, t.links, (Slide(5, "D", Vec(0, 0), 0.0, on=3),), (), 1, t.branches)
    with pytest.raises(DegenerateInput, match="slot of the moving link 3"):
        chain_solution(moving, 0.3, 1.0)
    pin = Mechanism(t.ground, t.links, (Slide(None, "D", Vec(0, 0), 0.0),), (), 1, t.branches)
    a, b = chain_solution(pin, 0.3, 1.0, 2.0).at(), chain_solution(t, 0.3, 1.0, 2.0).at()
    assert a.positions == b.positions and a.accelerations == b.accelerations
    assert set(a.angular) == {1, 2, 3, 4} == set(a.angular_acceleration)


def test_independent_of_the_graphical_code_path():
    """The dyad chain must not reach the geometry kernel, the assembly plan or the velocity polygon."""
    package = Path(__file__).resolve().parents[1] / "constructions" / "analytic"
    imported: set[str] = set()
    for name in ("vector_loops", "chain_order", "chain_state"):
        for node in ast.walk(ast.parse((package / f"{name}.py").read_text())):
            if isinstance(node, ast.ImportFrom):
                imported |= {f"{node.module}.{a.name}" for a in node.names}
                imported.add(str(node.module))
            elif isinstance(node, ast.Import):
                imported |= {a.name for a in node.names}
    assert not any("geometry" in i or "velocity" in i or "locate" in i or "assembly_plan" in i
                   or "intersect" in i for i in imported), imported
