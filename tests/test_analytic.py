"""The independent analytic check (vector-loop closed forms), tested against independent references.

The references here share no code with ``constructions.analytic``:

* a scalar Freudenstein-style position solver (law of cosines + ``math.acos``/``math.atan2``) and a
  2x2 ``numpy.linalg.solve`` of the velocity loop, written out per angle;
* complex-step derivatives of a scalar ``cmath`` transcription of the position loop (exact to rounding);
* central and fifth-order finite differences of the vectorised positions;
* exact rational (``fractions``) + 60-digit ``decimal`` half-chords on the very float inputs;
* the notes' slider-crank velocity Example 1, re-derived by hand below (not copied from the notes).
"""

from __future__ import annotations

import cmath
import dataclasses
import math
from decimal import Decimal, localcontext
from fractions import Fraction

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from constructions import analytic as an
from constructions.analytic import coupler_point, four_bar, slider_crank

from strategies import four_bar_dimensions, slider_crank_dimensions

FAST = settings(max_examples=150, deadline=None)

FB_POS = ("Bx", "By", "Cx", "Cy")
FB_VEL = ("VBx", "VBy", "VCx", "VCy")
FB_ANG = ("theta2", "theta3")
FB_OMEGA = ("omega2", "omega3")
SC_POS = ("Bx", "By", "Cx", "Cy")
SC_VEL = ("VBx", "VBy", "VCx", "VCy", "slider_speed")


# ---------------------------------------------------------------------------------------------
# Strategies: random mechanisms of any scale 1e-3 .. 1e3
# ---------------------------------------------------------------------------------------------

def fb_scale(m):
    return (m["crank"] + m["coupler"] + m["rocker"] + math.hypot(*m["crank_pivot"])
            + math.hypot(*m["rocker_pivot"]))


def sc_scale(m):
    return m["crank"] + m["coupler"] + math.hypot(*m["crank_pivot"]) + math.hypot(*m["guide_point"])


ANGLES = np.linspace(-math.pi, math.pi, 97) + 0.0123  # avoids the special angles on purpose


# ---------------------------------------------------------------------------------------------
# Independent references
# ---------------------------------------------------------------------------------------------

def ref_four_bar(theta, omega1, m):
    """Scalar reference: law of cosines at O2 for the rocker, 2x2 solve for the velocities.

    Returns None when |d - rocker| > coupler etc. (no triangle B-C-O2), else a dict.
    """
    o1x, o1y = m["crank_pivot"]
    o2x, o2y = m["rocker_pivot"]
    r1, r2, r3, br = m["crank"], m["coupler"], m["rocker"], m["branch"]
    bx, by = o1x + r1 * math.cos(theta), o1y + r1 * math.sin(theta)
    ux, uy = bx - o2x, by - o2y                     # O2 -> B
    d = math.hypot(ux, uy)
    cg = (d * d + r3 * r3 - r2 * r2) / (2.0 * d * r3)   # cos of the angle B-O2-C
    if not -1.0 <= cg <= 1.0:
        return None
    gamma = math.acos(cg)
    phi = math.atan2(uy, ux)
    # C to the left of B -> O2 means, seen from O2, C is reached by turning O2->B clockwise
    # (cross(O2 - B, C - B) = cross(C - O2, B - O2) > 0 when the turn O2B -> O2C is negative).
    theta3 = phi - br * gamma
    cx, cy = o2x + r3 * math.cos(theta3), o2y + r3 * math.sin(theta3)
    theta2 = math.atan2(cy - by, cx - bx)
    # velocity loop: V_B + w2 k x (C - B) - w3 k x (C - O2) = 0
    vbx, vby = -omega1 * (by - o1y), omega1 * (bx - o1x)
    A = np.array([[-(cy - by), (cy - o2y)], [(cx - bx), -(cx - o2x)]])
    w2, w3 = np.linalg.solve(A, [-vbx, -vby])
    return dict(Bx=bx, By=by, Cx=cx, Cy=cy, theta2=theta2, theta3=theta3, omega2=w2, omega3=w3,
                VBx=vbx, VBy=vby, VCx=-w3 * (cy - o2y), VCy=w3 * (cx - o2x))


def cs_four_bar_C(theta, m):
    """Four-bar C as an analytic (cmath) function of theta, for complex-step differentiation.

    Independent transcription: C is the point at distance coupler from B and rocker from O2,
    written as B + a u + h n with a from the two circle equations and h from a^2 + h^2 = coupler^2.
    """
    o1x, o1y = m["crank_pivot"]
    o2x, o2y = m["rocker_pivot"]
    r1, r2, r3, br = m["crank"], m["coupler"], m["rocker"], m["branch"]
    bx, by = o1x + r1 * cmath.cos(theta), o1y + r1 * cmath.sin(theta)
    wx, wy = o2x - bx, o2y - by
    d = cmath.sqrt(wx * wx + wy * wy)
    a = (d * d + r2 * r2 - r3 * r3) / (2.0 * d)
    h = br * cmath.sqrt(r2 * r2 - a * a)
    ux, uy = wx / d, wy / d
    return bx + a * ux - h * uy, by + a * uy + h * ux, bx, by


def cs_slider_C(theta, m):
    """Slider C as an analytic (cmath) function of theta: solve |C - B| = l with C = G + s e."""
    o1x, o1y = m["crank_pivot"]
    gx, gy = m["guide_point"]
    g, r1, l, br = m["guide_angle"], m["crank"], m["coupler"], m["branch"]
    ex, ey = math.cos(g), math.sin(g)
    bx, by = o1x + r1 * cmath.cos(theta), o1y + r1 * cmath.sin(theta)
    # |G + s e - B|^2 = l^2  ->  s^2 - 2 s (B - G).e + |B - G|^2 - l^2 = 0
    pe = (bx - gx) * ex + (by - gy) * ey
    q = (bx - gx) ** 2 + (by - gy) ** 2 - l * l
    s = pe + br * cmath.sqrt(pe * pe - q)
    return gx + s * ex, gy + s * ey, bx, by


def complex_step(f, theta, m, h=1e-30):
    vals = f(complex(theta, h), m)
    return [v.imag / h for v in vals], [v.real for v in vals]


def wrap(a):
    return (a + np.pi) % (2.0 * np.pi) - np.pi


# ---------------------------------------------------------------------------------------------
# Loop closure and agreement with the scalar reference
# ---------------------------------------------------------------------------------------------

@FAST
@given(four_bar_dimensions())
def test_four_bar_loop_closure(m):
    r = four_bar(ANGLES, 1.0, **m)
    L = fb_scale(m)
    a = r.assembles
    o1x, o1y = m["crank_pivot"]
    o2x, o2y = m["rocker_pivot"]
    assert np.all(np.abs(np.hypot(r.Bx - o1x, r.By - o1y)[a] - m["crank"]) <= 1e-12 * L)
    assert np.all(np.abs(np.hypot(r.Cx - r.Bx, r.Cy - r.By)[a] - m["coupler"]) <= 1e-12 * L)
    assert np.all(np.abs(np.hypot(r.Cx - o2x, r.Cy - o2y)[a] - m["rocker"]) <= 1e-12 * L)
    # the assembly mask is the triangle inequality, away from its boundary
    d = np.hypot(o2x - (o1x + m["crank"] * np.cos(ANGLES)), o2y - (o1y + m["crank"] * np.sin(ANGLES)))
    gap = np.minimum(m["coupler"] + m["rocker"] - d, d - abs(m["coupler"] - m["rocker"]))
    clear = np.abs(gap) > 1e-9 * L
    assert np.array_equal(a[clear], (gap > 0)[clear])
    for name in FB_POS + FB_VEL + FB_ANG + FB_OMEGA + ("condition",):
        assert np.all(np.isnan(getattr(r, name)[~a])), name
        assert np.all(np.isfinite(getattr(r, name)[a & (r.condition > 0)])), name


@FAST
@given(slider_crank_dimensions())
def test_slider_crank_loop_closure(m):
    r = slider_crank(ANGLES, 1.0, **m)
    L = sc_scale(m)
    a = r.assembles
    o1x, o1y = m["crank_pivot"]
    gx, gy = m["guide_point"]
    nx, ny = -math.sin(m["guide_angle"]), math.cos(m["guide_angle"])
    assert np.all(np.abs(np.hypot(r.Bx - o1x, r.By - o1y)[a] - m["crank"]) <= 1e-12 * L)
    assert np.all(np.abs(np.hypot(r.Cx - r.Bx, r.Cy - r.By)[a] - m["coupler"]) <= 1e-12 * L)
    assert np.all(np.abs(((r.Cx - gx) * nx + (r.Cy - gy) * ny)[a]) <= 1e-12 * L)  # C on the guide
    y = (o1x + m["crank"] * np.cos(ANGLES) - gx) * nx + (o1y + m["crank"] * np.sin(ANGLES) - gy) * ny
    gap = m["coupler"] - np.abs(y)
    clear = np.abs(gap) > 1e-9 * L
    assert np.array_equal(a[clear], (gap > 0)[clear])
    for name in SC_POS + SC_VEL + ("theta2", "omega2", "condition"):
        assert np.all(np.isnan(getattr(r, name)[~a])), name


@FAST
@given(four_bar_dimensions(), st.floats(-50.0, 50.0).filter(lambda w: abs(w) > 1e-3))
def test_four_bar_matches_scalar_reference(m, omega1):
    r = four_bar(ANGLES, omega1, **m)
    L = fb_scale(m)
    for k, th in enumerate(ANGLES):
        ref = ref_four_bar(float(th), omega1, m)
        if ref is None or r.condition[k] < 0.05:       # away from toggle and from the range limits
            continue
        assert r.assembles[k]
        c = float(r.condition[k])
        for name in FB_POS:
            assert abs(getattr(r, name)[k] - ref[name]) <= 1e-12 * L / c, name
        for name in FB_ANG:
            assert abs(wrap(getattr(r, name)[k] - ref[name])) <= 1e-12 * L / (c * m["coupler"]
                                                                            if name == "theta2"
                                                                            else c * m["rocker"])
        vs = abs(omega1) * L
        for name in FB_VEL:
            assert abs(getattr(r, name)[k] - ref[name]) <= 1e-12 * vs / c**2, name
        for name, length in (("omega2", m["coupler"]), ("omega3", m["rocker"])):
            assert abs(getattr(r, name)[k] - ref[name]) <= 1e-12 * vs / (c**2 * length), name


# ---------------------------------------------------------------------------------------------
# Velocities against derivatives of positions
# ---------------------------------------------------------------------------------------------

def _interior(fn, th, m, margin=0.02):
    """Angles well inside the range of motion: the loop closes with condition > 0.1 within
    +-margin rad.  Near a limit of motion the position goes like sqrt(theta - theta_limit), so the
    truncation error of a difference quotient grows like a power of 1/distance-to-limit; this
    keeps it far below the asserted tolerances."""
    ok = np.ones(th.shape, dtype=bool)
    for dt in (-margin, -margin / 2, 0.0, margin / 2, margin):
        r = fn(th + dt, 1.0, **m)
        ok &= r.assembles & (r.condition > 0.1)
    return ok


@FAST
@given(four_bar_dimensions())
def test_four_bar_velocities_are_position_derivatives(m):
    th = ANGLES
    r = four_bar(th, 1.0, **m)                       # omega1 = 1: velocity = d(position)/d(theta)
    ok = _interior(four_bar, th, m) & (r.condition > 0.2)
    assume(ok.any())
    L = fb_scale(m)
    # central difference, h = 1e-6: truncation ~ h^2 f'''/6, rounding ~ eps L / h ~ 2e-10 L
    h = 1e-6
    p, q = four_bar(th + h, 1.0, **m), four_bar(th - h, 1.0, **m)
    for name, v in (("Bx", "VBx"), ("By", "VBy"), ("Cx", "VCx"), ("Cy", "VCy")):
        fd = (getattr(p, name) - getattr(q, name)) / (2 * h)
        assert np.all(np.abs(fd - getattr(r, v))[ok] <= 1e-6 * L), v
    for name, w in (("theta2", "omega2"), ("theta3", "omega3")):
        fd = wrap(getattr(p, name) - getattr(q, name)) / (2 * h)
        assert np.all(np.abs(fd - getattr(r, w))[ok] <= 1e-6 * L / min(m["coupler"], m["rocker"])), w
    # fourth-order five-point difference, h = 1e-4: truncation ~ h^4 f^(5)/30
    h = 1e-4
    st_ = [four_bar(th + k * h, 1.0, **m) for k in (-2, -1, 1, 2)]
    for name, v in (("Cx", "VCx"), ("Cy", "VCy")):
        f = [getattr(s, name) for s in st_]
        fd = (f[0] - 8 * f[1] + 8 * f[2] - f[3]) / (12 * h)
        assert np.all(np.abs(fd - getattr(r, v))[ok] <= 1e-7 * L), v


@FAST
@given(four_bar_dimensions())
def test_four_bar_velocities_complex_step(m):
    r = four_bar(ANGLES, 1.0, **m)
    L = fb_scale(m)
    for k in np.flatnonzero(r.assembles & (r.condition > 0.02))[:25]:
        (dcx, dcy, dbx, dby), (cx, cy, bx, by) = complex_step(cs_four_bar_C, float(ANGLES[k]), m)
        assert abs(cx - r.Cx[k]) <= 1e-9 * L and abs(cy - r.Cy[k]) <= 1e-9 * L  # same branch
        for got, want in ((r.VCx[k], dcx), (r.VCy[k], dcy), (r.VBx[k], dbx), (r.VBy[k], dby)):
            assert abs(got - want) <= 1e-9 * L / float(r.condition[k]) ** 2
        # omega2 from the derivative of C - B: omega2 = cross(p, dp) / |p|^2
        px, py = cx - bx, cy - by
        w2 = (px * (dcy - dby) - py * (dcx - dbx)) / (px * px + py * py)
        assert abs(w2 - r.omega2[k]) <= 1e-9 * L / (m["coupler"] * float(r.condition[k]) ** 2)


@FAST
@given(slider_crank_dimensions())
def test_slider_velocities_are_position_derivatives(m):
    th = ANGLES
    r = slider_crank(th, 1.0, **m)
    L = sc_scale(m)
    ex, ey = math.cos(m["guide_angle"]), math.sin(m["guide_angle"])
    h = 1e-6
    p, q = slider_crank(th + h, 1.0, **m), slider_crank(th - h, 1.0, **m)
    ok = _interior(slider_crank, th, m) & (r.condition > 0.2)
    assume(ok.any())
    for name, v in (("Bx", "VBx"), ("By", "VBy"), ("Cx", "VCx"), ("Cy", "VCy")):
        fd = (getattr(p, name) - getattr(q, name)) / (2 * h)
        assert np.all(np.abs(fd - getattr(r, v))[ok] <= 1e-6 * L), v
    fd = ((p.Cx - q.Cx) * ex + (p.Cy - q.Cy) * ey) / (2 * h)
    assert np.all(np.abs(fd - r.slider_speed)[ok] <= 1e-6 * L)
    fd = wrap(p.theta2 - q.theta2) / (2 * h)
    assert np.all(np.abs(fd - r.omega2)[ok] <= 1e-6 * L / m["coupler"])
    # V_C lies along the guide exactly and equals slider_speed * e
    assert np.all(np.abs(r.VCx - r.slider_speed * ex)[ok] <= 1e-14 * L)
    assert np.all(np.abs(r.VCy - r.slider_speed * ey)[ok] <= 1e-14 * L)
    # complex step on an independent quadratic-formula transcription
    for k in np.flatnonzero(ok)[:20]:
        (dcx, dcy, _, _), (cx, cy, _, _) = complex_step(cs_slider_C, float(th[k]), m)
        assert abs(cx - r.Cx[k]) <= 1e-9 * L and abs(cy - r.Cy[k]) <= 1e-9 * L
        tol = 1e-9 * L / float(r.condition[k]) ** 2
        assert abs(dcx - r.VCx[k]) <= tol and abs(dcy - r.VCy[k]) <= tol


def test_velocities_are_linear_in_omega1_and_broadcast():
    m = dict(crank_pivot=(0.01, -0.02), rocker_pivot=(0.11, 0.0), crank=0.03, coupler=0.09,
             rocker=0.07, branch=-1)
    th = np.linspace(0.0, 2 * np.pi, 11)
    w = np.linspace(-20.0, 20.0, 11)
    r = four_bar(th, w, **m)
    r1 = four_bar(th, 1.0, **m)
    for name in FB_VEL + FB_OMEGA:
        np.testing.assert_allclose(getattr(r, name), w * getattr(r1, name), rtol=1e-14, atol=1e-15)
    # broadcasting: one angle, many speeds
    rb = four_bar(0.3, w, **m)
    assert rb.omega2.shape == w.shape and np.allclose(rb.Cx, rb.Cx[0], rtol=0, atol=0)


# ---------------------------------------------------------------------------------------------
# Branch conventions
# ---------------------------------------------------------------------------------------------

@FAST
@given(four_bar_dimensions())
def test_four_bar_branch_is_left_or_right_of_B_to_O2_and_mirrors(m):
    up = four_bar(ANGLES, 1.0, **{**m, "branch": 1})
    dn = four_bar(ANGLES, 1.0, **{**m, "branch": -1})
    o2x, o2y = m["rocker_pivot"]
    L = fb_scale(m)
    assert np.array_equal(up.assembles, dn.assembles)
    ok = up.assembles & (up.condition > 1e-6)
    for r, sign in ((up, 1), (dn, -1)):
        side = (o2x - r.Bx) * (r.Cy - r.By) - (o2y - r.By) * (r.Cx - r.Bx)
        assert np.all(sign * side[ok] > 0)
    # the two assemblies are mirror images in the line B-O2
    ux, uy = o2x - up.Bx, o2y - up.By
    nn = np.hypot(ux, uy)
    ux, uy = ux / nn, uy / nn
    px, py = up.Cx - up.Bx, up.Cy - up.By
    along = px * ux + py * uy
    mx, my = up.Bx + 2 * along * ux - px, up.By + 2 * along * uy - py
    assert np.all(np.abs(mx - dn.Cx)[ok] <= 1e-12 * L / up.condition[ok])
    assert np.all(np.abs(my - dn.Cy)[ok] <= 1e-12 * L / up.condition[ok])
    np.testing.assert_array_equal(up.condition, dn.condition)


@FAST
@given(slider_crank_dimensions())
def test_slider_branch_is_ahead_or_behind_the_foot_and_mirrors(m):
    ahead = slider_crank(ANGLES, 1.0, **{**m, "branch": 1})
    behind = slider_crank(ANGLES, 1.0, **{**m, "branch": -1})
    ex, ey = math.cos(m["guide_angle"]), math.sin(m["guide_angle"])
    L = sc_scale(m)
    assert np.array_equal(ahead.assembles, behind.assembles)
    ok = ahead.assembles & (ahead.condition > 1e-6)
    for r, sign in ((ahead, 1), (behind, -1)):
        along = (r.Cx - r.Bx) * ex + (r.Cy - r.By) * ey      # C - foot, measured along e
        assert np.all(sign * along[ok] > 0)
    # mirror images in the perpendicular from B: the foot is the midpoint of the two C
    gx, gy = m["guide_point"]
    t = (ahead.Bx - gx) * ex + (ahead.By - gy) * ey
    fx, fy = gx + t * ex, gy + t * ey
    assert np.all(np.abs(ahead.Cx + behind.Cx - 2 * fx)[ok] <= 1e-12 * L)
    assert np.all(np.abs(ahead.Cy + behind.Cy - 2 * fy)[ok] <= 1e-12 * L)


def test_branch_examples_by_hand():
    # crank along +x from the origin, rocker pivot at (2, 0): B = (1, 0), B -> O2 points along +x,
    # so "left" is +y.  coupler = rocker = sqrt(2) puts C at (1.5, +-sqrt(2 - 0.25)).
    m = dict(crank_pivot=(0.0, 0.0), rocker_pivot=(2.0, 0.0), crank=1.0, coupler=math.sqrt(2.0),
             rocker=math.sqrt(2.0))
    up = four_bar(0.0, 1.0, branch=1, **m)
    dn = four_bar(0.0, 1.0, branch=-1, **m)
    assert up.Cx == pytest.approx(1.5) and up.Cy == pytest.approx(math.sqrt(1.75))
    assert dn.Cx == pytest.approx(1.5) and dn.Cy == pytest.approx(-math.sqrt(1.75))
    # slider: guide = x axis, B = (0, 1) straight above O1, coupler 2: C = (+-sqrt(3), 0)
    s = dict(crank_pivot=(0.0, 0.0), crank=1.0, coupler=2.0, guide_point=(5.0, 0.0), guide_angle=0.0)
    a = slider_crank(math.pi / 2, 1.0, branch=1, **s)
    b = slider_crank(math.pi / 2, 1.0, branch=-1, **s)
    assert a.Cx == pytest.approx(math.sqrt(3.0)) and b.Cx == pytest.approx(-math.sqrt(3.0))
    # reversing the guide direction swaps what "ahead" means
    c = slider_crank(math.pi / 2, 1.0, branch=1, **{**s, "guide_angle": math.pi})
    assert c.Cx == pytest.approx(-math.sqrt(3.0)) and abs(c.Cy) < 1e-15


# ---------------------------------------------------------------------------------------------
# Non-assembly, toggles and dead centres
# ---------------------------------------------------------------------------------------------

def test_non_grashof_four_bar_outside_its_range_is_nan():
    # s + l = 0.5 + 1.0 > p + q = 0.6 + 0.8: non-Grashof; the crank cannot pass theta = pi
    m = dict(crank_pivot=(0.0, 0.0), rocker_pivot=(1.0, 0.0), crank=0.8, coupler=0.5, rocker=0.6,
             branch=1)
    th = np.linspace(0.0, 2 * np.pi, 721)
    r = four_bar(th, 3.0, **m)
    d = np.hypot(1.0 - 0.8 * np.cos(th), 0.8 * np.sin(th))
    assert np.array_equal(r.assembles, (d <= 1.1) & (d >= 0.1))
    assert r.assembles[0] and not r.assembles[360] and not r.assembles.all()
    out = ~r.assembles
    for name in FB_POS + FB_VEL + FB_ANG + FB_OMEGA + ("condition",):
        assert np.isnan(getattr(r, name)[out]).all(), name
        assert np.isfinite(getattr(r, name)[~out]).all(), name
    assert r.assembles.dtype == bool
    one = four_bar(math.pi, 3.0, **m)
    assert not bool(one.assembles) and math.isnan(float(one.Cx)) and math.isnan(float(one.Bx))


def test_slider_that_cannot_reach_its_guide_is_nan():
    # guide y = 1, crank 0.8, coupler 0.5: reaches only while B is within 0.5 of the guide
    m = dict(crank_pivot=(0.0, 0.0), crank=0.8, coupler=0.5, guide_point=(0.0, 1.0),
             guide_angle=0.0, branch=1)
    th = np.linspace(-np.pi, np.pi, 361)
    r = slider_crank(th, 1.0, **m)
    assert np.array_equal(r.assembles, np.abs(0.8 * np.sin(th) - 1.0) <= 0.5)
    assert r.assembles.any() and not r.assembles.all()
    for name in SC_POS + SC_VEL + ("theta2", "omega2", "condition"):
        assert np.isnan(getattr(r, name)[~r.assembles]).all(), name


def _assert_toggle(r, velocity_names):
    assert bool(r.assembles)
    assert float(r.condition) <= an.SINE_TOL
    for name in velocity_names:
        v = float(getattr(r, name))
        assert math.isnan(v), (name, v)          # NaN: never inf, never a huge number
    for name in ("Bx", "By", "Cx", "Cy", "VBx", "VBy"):
        assert math.isfinite(float(getattr(r, name))), name


def test_four_bar_exact_toggle_gives_nan_velocities():
    # O1 = 0, O2 = (4, 0), crank 1 at theta = 0: B = (1, 0), |O2 - B| = 3 = coupler + rocker.
    # Coupler and rocker collinear (extended): the transmission angle is 180 deg, sine 0.
    m = dict(crank_pivot=(0.0, 0.0), rocker_pivot=(4.0, 0.0), crank=1.0, coupler=2.0, rocker=1.0,
             branch=1)
    r = four_bar(0.0, 10.0, **m)
    _assert_toggle(r, ("omega2", "omega3", "VCx", "VCy"))
    assert float(r.Cx) == 3.0 and float(r.Cy) == 0.0
    # folded toggle: |O2 - B| = 1 = coupler - rocker at theta = 0 with O2 = (2, 0)
    r = four_bar(0.0, 10.0, **{**m, "rocker_pivot": (2.0, 0.0)})
    _assert_toggle(r, ("omega2", "omega3", "VCx", "VCy"))
    assert float(r.Cx) == 3.0


@pytest.mark.parametrize("alpha", [0.3, 1.0, 2.5, -2.2, 4.0])
@pytest.mark.parametrize("scale", [1e-3, 1.0, 1e3])
def test_four_bar_designed_toggle_from_rotated_floats_reads_as_toggle(alpha, scale):
    # Base frame: O1 = 0, O2 = (2, 0), crank 1, so |O2 - B| = sqrt(5 - 4 cos theta) grows with
    # |theta|; coupler + rocker = sqrt(5) makes theta = pi/2 an extended toggle (the limit of the
    # crank's range).  Rotate by alpha, shift and scale: the rounding of the toggle now falls
    # either way, and it must still read as a toggle.
    ca, sa = math.cos(alpha), math.sin(alpha)
    o1 = (0.7 * scale, -0.2 * scale)
    m = dict(crank_pivot=o1, rocker_pivot=(o1[0] + 2.0 * scale * ca, o1[1] + 2.0 * scale * sa),
             crank=1.0 * scale, coupler=1.2 * scale, rocker=(math.sqrt(5.0) - 1.2) * scale, branch=-1)
    toggle = alpha + math.pi / 2
    r = four_bar(toggle, 10.0, **m)
    _assert_toggle(r, ("omega2", "omega3", "VCx", "VCy"))
    # C on the segment B-O2, coupler from B (to within the snap, ~sqrt(tol L))
    bx, by = o1[0] + scale * math.cos(toggle), o1[1] + scale * math.sin(toggle)
    dx, dy = m["rocker_pivot"][0] - bx, m["rocker_pivot"][1] - by
    dn = math.hypot(dx, dy)
    assert float(r.Cx) == pytest.approx(bx + 1.2 * scale * dx / dn, abs=1e-6 * scale)
    assert float(r.Cy) == pytest.approx(by + 1.2 * scale * dy / dn, abs=1e-6 * scale)
    # just inside the range the answer is finite and the condition honest (far above SINE_TOL);
    # just outside, the loop does not close
    near = four_bar(toggle - 1e-6, 10.0, **m)
    assert bool(near.assembles) and 1e-7 < float(near.condition) < 1e-2
    assert math.isfinite(float(near.omega3)) and math.isfinite(float(near.VCx))
    assert not bool(four_bar(toggle + 1e-6, 10.0, **m).assembles)


@pytest.mark.parametrize("gamma", [0.0, 0.3, -2.0, math.pi / 2])
def test_slider_dead_centre_coupler_perpendicular_to_guide(gamma):
    # offset 1.5 below the guide, crank 1, coupler 2.5: at theta = gamma - pi/2 the pin B is 2.5 from
    # the guide, the coupler stands perpendicular to it and the velocity trial lines are parallel.
    e = (math.cos(gamma), math.sin(gamma))
    nvec = (-e[1], e[0])
    g = (0.3, -0.1)
    m = dict(crank_pivot=(g[0] - 1.5 * nvec[0], g[1] - 1.5 * nvec[1]), crank=1.0, coupler=2.5,
             guide_point=g, guide_angle=gamma, branch=1)
    r = slider_crank(gamma - math.pi / 2, 5.0, **m)
    _assert_toggle(r, ("omega2", "VCx", "VCy", "slider_speed"))


def test_no_inf_anywhere_on_a_sweep_through_toggles():
    # a change-point linkage (s + l = p + q) swept finely passes its toggles
    m = dict(crank_pivot=(0.0, 0.0), rocker_pivot=(2.0, 0.0), crank=1.0, coupler=2.0, rocker=1.0,
             branch=1)
    th = np.linspace(-np.pi, np.pi, 4001)
    with np.errstate(all="raise"):  # the module must not leak floating-point warnings either
        r = four_bar(th, 1.0, **m)
    for name in FB_POS + FB_VEL + FB_ANG + FB_OMEGA + ("condition",):
        assert not np.isinf(getattr(r, name)).any(), name


# ---------------------------------------------------------------------------------------------
# Scale invariance
# ---------------------------------------------------------------------------------------------

@pytest.mark.parametrize("k", [1e-3, 1e3])
def test_scaling_a_mechanism_scales_the_answer(k):
    fb = dict(crank_pivot=(0.013, -0.021), rocker_pivot=(0.47, 0.05), crank=0.31, coupler=0.23,
              rocker=0.29, branch=1)                    # non-Grashof: a non-trivial assembly mask
    sc = dict(crank_pivot=(0.01, 0.02), crank=0.05, coupler=0.094, guide_point=(0.3, 0.04),
              guide_angle=0.2, branch=-1)
    th = np.linspace(-np.pi, np.pi, 2001) + 1e-4
    w = 7.5
    for fn, mech, pos, vel, inv in (
            (four_bar, fb, FB_POS, FB_VEL, FB_ANG + FB_OMEGA + ("condition",)),
            (slider_crank, sc, SC_POS, SC_VEL, ("theta2", "omega2", "condition"))):
        big = {key: (tuple(k * c for c in v) if isinstance(v, tuple)
                     else k * v if key in ("crank", "coupler", "rocker") else v)
               for key, v in mech.items()}
        r0, r1 = fn(th, w, **mech), fn(th, w, **big)
        assert np.array_equal(r0.assembles, r1.assembles)
        assert r0.assembles.any() and (fn is slider_crank or not r0.assembles.all())
        a = r0.assembles & (r0.condition > 1e-3)
        for name in pos + vel:
            x0, x1 = getattr(r0, name)[a], getattr(r1, name)[a]
            ref = np.abs(x0).max()
            assert np.all(np.abs(x1 - k * x0) <= 1e-12 * k * ref / r0.condition[a]), name
        for name in inv:
            x0, x1 = getattr(r0, name)[a], getattr(r1, name)[a]
            ref = max(np.abs(x0).max(), 1.0)
            assert np.all(np.abs(x1 - x0) <= 1e-12 * ref / r0.condition[a] ** 2), name


# ---------------------------------------------------------------------------------------------
# Digits near tangency (cancellation-free half-chord)
# ---------------------------------------------------------------------------------------------

def _decimal_sqrt(x: Fraction) -> Fraction:
    """Square root of an exact rational to 60 significant digits."""
    with localcontext() as ctx:
        ctx.prec = 60
        return Fraction((Decimal(x.numerator) / Decimal(x.denominator)).sqrt())


@pytest.mark.parametrize("delta_exp", [-20, -25, -30])
@pytest.mark.parametrize("kind", ["outer", "inner"])
def test_four_bar_half_chord_keeps_its_digits_near_tangency(kind, delta_exp):
    # theta = 0 makes B = (1, 0) exactly, so every input is an exact binary number and the exact
    # half-chord follows from rationals: h^2 = P / (4 d^2).  "inner" is the hard case: two long links
    # (1000.5 and 1000) with |O2 - B| = 0.5 + delta, where coupler^2 - a^2 would lose ~6 digits.
    delta = 2.0 ** delta_exp
    if kind == "outer":
        r2, r3, d = 2.0, 1.0, 3.0 - delta
    else:
        r2, r3, d = 1000.5, 1000.0, 0.5 + delta
    m = dict(crank_pivot=(0.0, 0.0), rocker_pivot=(1.0 + d, 0.0), crank=1.0, coupler=r2, rocker=r3,
             branch=1)
    assert m["rocker_pivot"][0] - 1.0 == d                      # exact inputs
    r = four_bar(0.0, 1.0, **m)
    F = Fraction
    S, T, D = F(r2) + F(r3), abs(F(r2) - F(r3)), F(d)
    P = (S + D) * (S - D) * (D + T) * (D - T)
    h = _decimal_sqrt(P / (4 * D * D))
    a = (D * D + F(r2) ** 2 - F(r3) ** 2) / (2 * D)
    # B -> O2 is +x, so branch +1 puts C at (1 + a, +h)
    assert abs(F(float(r.Cy)) - h) <= 1e-13 * h
    assert abs(F(float(r.Cx)) - 1 - a) <= 4e-16 * (1 + abs(a))
    cond = float(_decimal_sqrt(P) / (2 * F(r2) * F(r3)))
    assert float(r.condition) == pytest.approx(cond, rel=1e-13)


@pytest.mark.parametrize("delta_exp", [-20, -35, -45])
def test_slider_half_chord_keeps_its_digits_near_dead_centre(delta_exp):
    delta = 2.0 ** delta_exp
    l = 0.75
    y0 = l - delta                                             # exact: guide is y = 0
    m = dict(crank_pivot=(0.0, y0), crank=0.5, coupler=l, guide_point=(0.0, 0.0), guide_angle=0.0,
             branch=1)
    r = slider_crank(0.0, 1.0, **m)
    h = _decimal_sqrt((Fraction(l) - Fraction(y0)) * (Fraction(l) + Fraction(y0)))
    # C = B + h along x: Cx carries h to the ulp of Cx (~1e-16), condition = h / l to full precision
    assert abs(Fraction(float(r.Cx)) - Fraction(0.5) - h) <= 2.0 ** -52
    assert float(r.condition) == pytest.approx(float(h / Fraction(l)), rel=1e-13)


def test_gaps_inside_the_rounding_band_are_tangent():
    # the same exact constructions with the gap below ASSEMBLY_RTOL * L: snapped to tangency
    m = dict(crank_pivot=(0.0, 0.0), rocker_pivot=(1.5 + 2.0 ** -40, 0.0), crank=1.0, coupler=1000.5,
             rocker=1000.0, branch=1)
    assert 2.0 ** -40 < an.ASSEMBLY_RTOL * 2001.5
    _assert_toggle(four_bar(0.0, 1.0, **m), ("omega2", "omega3", "VCx", "VCy"))
    m["rocker_pivot"] = (1.5 - 2.0 ** -40, 0.0)                # the other side: still tangent
    _assert_toggle(four_bar(0.0, 1.0, **m), ("omega2", "omega3", "VCx", "VCy"))
    m["rocker_pivot"] = (1.5 - 2.0 ** -20, 0.0)                # well apart: no assembly
    assert not bool(four_bar(0.0, 1.0, **m).assembles)
    s = dict(crank_pivot=(0.0, 0.75 + 2.0 ** -50), crank=0.5, coupler=0.75, guide_point=(0.0, 0.0),
             guide_angle=0.0, branch=1)
    _assert_toggle(slider_crank(0.0, 1.0, **s), ("omega2", "VCx", "VCy", "slider_speed"))


# ---------------------------------------------------------------------------------------------
# The notes' slider-crank velocity Example 1, re-derived
# ---------------------------------------------------------------------------------------------

def test_notes_velocity_example_1_slider_crank():
    # In-line slider-crank, guide through O1 along +x.  Crank r = 50 mm at 70 deg, coupler l = 94 mm,
    # omega1 = +10 rad/s (V_B = 500 mm/s), C ahead of B (branch +1).
    # By hand: B = (50 cos70, 50 sin70) = (17.101, 46.985) mm.  The coupler drops to the guide at
    # an angle phi below +x with l sin(phi) = r sin(70)  ->  sin(phi) = 46.985/94 = 0.49984,
    # phi = 29.99 deg, cos(phi) = 0.86611.  x_C = r cos70 + l cos(phi); differentiating
    # (with l cos(phi) phi' = r cos70 omega1) gives
    #   V_C = -r omega1 (sin70 + cos70 tan(phi)) = -r omega1 sin(70 + phi) / cos(phi)
    #       = -500 * 0.98481 / 0.86611 = -568.5 mm/s (toward -x),
    #   omega2 = -phi' = -r omega1 cos70 / (l cos(phi)) = -171.01 / 81.415 = -2.100 rad/s (CW),
    #   |V_CB| = |omega2| l = 2.100 * 94 = 197.4 mm/s.
    r = slider_crank(math.radians(70.0), 10.0, crank_pivot=(0.0, 0.0), crank=0.050, coupler=0.094,
                     guide_point=(0.0, 0.0), guide_angle=0.0, branch=1)
    assert math.hypot(float(r.VBx), float(r.VBy)) == pytest.approx(0.500, rel=1e-12)
    assert float(r.VCx) == pytest.approx(-0.5685, rel=0.01)
    assert abs(float(r.VCy)) < 1e-15
    assert float(r.slider_speed) == pytest.approx(-0.5685, rel=0.01)
    vcb = math.hypot(float(r.VCx - r.VBx), float(r.VCy - r.VBy))
    assert vcb == pytest.approx(0.1974, rel=0.01)
    assert float(r.omega2) == pytest.approx(-2.10, rel=0.01)
    # and the closed forms above to full precision
    phi = math.asin(0.050 * math.sin(math.radians(70.0)) / 0.094)
    assert float(r.slider_speed) == pytest.approx(
        -0.5 * math.sin(math.radians(70.0) + phi) / math.cos(phi), rel=1e-13)
    assert float(r.theta2) == pytest.approx(-phi, rel=1e-13)


# ---------------------------------------------------------------------------------------------
# Coupler point
# ---------------------------------------------------------------------------------------------

def test_coupler_point_on_C_and_on_B_and_rigid():
    m = dict(crank_pivot=(0.0, 0.0), rocker_pivot=(0.1, 0.02), crank=0.03, coupler=0.09, rocker=0.07,
             branch=1)
    th = np.linspace(0.0, 2 * np.pi, 50)
    r = four_bar(th, 4.0, **m)
    args = (r.Bx, r.By, r.VBx, r.VBy, r.theta2, r.omega2)
    atC = coupler_point(*args, distance=0.09, angle=0.0)
    for got, want in ((atC.Dx, r.Cx), (atC.Dy, r.Cy), (atC.VDx, r.VCx), (atC.VDy, r.VCy)):
        np.testing.assert_allclose(got, want, rtol=0, atol=1e-15 * 10)
    atB = coupler_point(*args, distance=0.0, angle=1.0)
    np.testing.assert_array_equal(atB.Dx, r.Bx)
    np.testing.assert_array_equal(atB.VDy, r.VBy)
    D = coupler_point(*args, distance=0.05, angle=0.7)
    # rigid: V_D - V_B is perpendicular to D - B; distance is kept
    np.testing.assert_allclose(np.hypot(D.Dx - r.Bx, D.Dy - r.By), 0.05, rtol=1e-14)
    dot = (D.VDx - r.VBx) * (D.Dx - r.Bx) + (D.VDy - r.VBy) * (D.Dy - r.By)
    assert np.abs(dot).max() <= 1e-15
    # V_D is the derivative of D (omega1 = 4 -> scale the angle step)
    h = 1e-6
    rp, rq = four_bar(th + h, 4.0, **m), four_bar(th - h, 4.0, **m)
    Dp = coupler_point(rp.Bx, rp.By, rp.VBx, rp.VBy, rp.theta2, rp.omega2, distance=0.05, angle=0.7)
    Dq = coupler_point(rq.Bx, rq.By, rq.VBx, rq.VBy, rq.theta2, rq.omega2, distance=0.05, angle=0.7)
    np.testing.assert_allclose(4.0 * (Dp.Dx - Dq.Dx) / (2 * h), D.VDx, atol=1e-7)
    np.testing.assert_allclose(4.0 * (Dp.Dy - Dq.Dy) / (2 * h), D.VDy, atol=1e-7)
    # NaN in, NaN out
    nanD = coupler_point(np.nan, 0.0, 0.0, 0.0, 0.1, 1.0, distance=1.0, angle=0.0)
    assert math.isnan(float(nanD.Dx))


# ---------------------------------------------------------------------------------------------
# API shape, immutability, chunking, validation
# ---------------------------------------------------------------------------------------------

FB = dict(crank_pivot=(0.0, 0.0), rocker_pivot=(0.1, 0.02), crank=0.03, coupler=0.09, rocker=0.07,
          branch=1)


def test_shapes_dtypes_and_immutability():
    r = four_bar(0.5, 2.0, **FB)
    assert r.Cx.shape == () and r.Cx.dtype == np.float64 and r.assembles.dtype == bool
    th = np.linspace(0, 1, 12).reshape(3, 4)
    r2 = four_bar(th, 2.0, **FB)
    assert all(getattr(r2, f.name).shape == (3, 4) for f in dataclasses.fields(r2))
    with pytest.raises(dataclasses.FrozenInstanceError):
        r2.Cx = None
    with pytest.raises(ValueError):
        r2.Cx[0, 0] = 1.0
    s = slider_crank([0.1, 0.2], 1.0, crank_pivot=(0, 0), crank=1, coupler=3, guide_point=(0, 0),
                     guide_angle=0, branch=1)
    assert s.slider_speed.shape == (2,)
    assert four_bar(np.array([]), 1.0, **FB).Cx.shape == (0,)


@pytest.mark.parametrize("bad", [dict(branch=0), dict(branch=2), dict(crank=-1.0), dict(coupler=0.0),
                                 dict(rocker=float("nan")), dict(crank_pivot=(0.0,)),
                                 dict(rocker_pivot=(0.0, float("inf")))])
def test_invalid_mechanisms_are_rejected(bad):
    with pytest.raises(ValueError):
        four_bar(0.1, 1.0, **{**FB, **bad})


def test_module_is_independent_of_the_constructions():
    """Only the tolerance policy (one scene size, one snapping tolerance) is shared with the engine;
    nothing of the construction path it checks, nor the sweep's own trigonometry: the closed forms
    import numpy and each other."""
    import ast
    from pathlib import Path

    package = Path(an.__file__).parent
    for name in ("four_bar_loop", "slider_loop", "point_on_link", "inputs", "parts", "states"):
        tree = ast.parse((package / f"{name}.py").read_text())
        imported = {alias.name for node in ast.walk(tree) if isinstance(node, ast.Import)
                    for alias in node.names}
        imported |= {node.module or "" for node in ast.walk(tree) if isinstance(node, ast.ImportFrom)}
        assert imported <= {"__future__", "math", "dataclasses", "numpy", "tolerance", "inputs", "parts",
                            "states"}, (name, imported)


@pytest.mark.parametrize("shift", [(0.0, 0.0), (1e3, -2e3), (-5e4, 3e4)])
def test_decisions_do_not_move_with_the_origin(shift):
    """The scene size does not grow with the distance from the origin; only the rounding floor of far
    coordinates widens the snapping band (constructions.tolerance.snap_tolerance).  A four-bar at its
    extended toggle (crank at 180 deg: |B O2| = 0.4 = coupler + rocker) reads as a toggle wherever it is
    put, and its joint translates with it."""
    o2 = (0.3, 0.0)
    r1, r2, r3 = 0.1, 0.25, 0.15
    kw = dict(crank=r1, coupler=r2, rocker=r3, branch=1)
    base = four_bar(math.pi, 1.0, crank_pivot=(0.0, 0.0), rocker_pivot=o2, **kw)
    moved = four_bar(math.pi, 1.0, crank_pivot=shift, rocker_pivot=(o2[0] + shift[0], o2[1] + shift[1]), **kw)
    assert bool(base.assembles) and bool(moved.assembles)
    assert float(base.condition) == float(moved.condition) == 0.0      # both snapped to the toggle
    assert float(moved.Cx) - shift[0] == pytest.approx(float(base.Cx), abs=1e-6)
    from constructions.tolerance import scene_size
    # the same size, up to the rounding the far coordinates carry
    assert scene_size((r1, r2, r3), ((0.0, 0.0), o2)) == pytest.approx(
        scene_size((r1, r2, r3), (shift, (o2[0] + shift[0], o2[1] + shift[1]))), rel=1e-9)
