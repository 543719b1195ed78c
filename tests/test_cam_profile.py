"""The exact cam profile: the envelope against closed forms and numerical geometry, curvature, pressure
angle with the offset, the flat face's minimum base radius (the notes' 0.25 cm), and undercut at, just
below and just above the limit."""

import math

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st
from shapely.geometry import LinearRing, Polygon

from constructions.cams.check import closed_form_point, min_base_radius_flat
from constructions.cams.construction import construct
from constructions.cams.laws import CYCLOIDAL, DWELL, HARMONIC, LAWS, POLY345, RETURN, RISE, Program, Segment
from constructions.cams.profile import FLAT, KNIFE, ROLLER, Follower, analyse, evaluate

D = math.radians
IN = 0.0254


def notes_program():
    return Program([Segment(DWELL, D(120)), Segment(RISE, D(60), 0.8 * IN, HARMONIC), Segment(DWELL, D(30)),
                    Segment(RETURN, D(150), 0.8 * IN, HARMONIC)])


def test_notes_flat_faced_minimum_base_radius():
    """Notes, "Avoiding any cusps": harmonic return over pi..5pi/3, lift 2 cm -> r_b > 0.25 cm."""
    L = 0.02
    p = Program([Segment(RISE, D(120), L, HARMONIC), Segment(DWELL, D(60)), Segment(RETURN, D(120), L, HARMONIC),
                 Segment(DWELL, D(60))])
    # the return alone, over [pi, 5 pi / 3]
    assert min_base_radius_flat(p, math.pi, 5 * math.pi / 3) == pytest.approx(0.0025, rel=1e-9)
    cp = analyse(p, Follower(FLAT, 0.05, sense=-1))
    assert cp.min_base_radius == pytest.approx(0.0025, rel=1e-9)   # rise and return alike
    # the closed form: at the top of the return s = L, s'' = -(L/2)(pi/beta)^2, so -(s + s'') = L((pi/beta)^2/2 - 1)
    assert cp.min_base_radius == pytest.approx(L * (1.5 ** 2 / 2 - 1), rel=1e-12)
    # at, just above and just below: a cusp, nothing, undercut spans
    at = analyse(p, Follower(FLAT, cp.min_base_radius, sense=-1))
    assert at.cusp_at and not at.undercut
    assert analyse(p, Follower(FLAT, cp.min_base_radius * 1.01, sense=-1)).undercut_free
    below = analyse(p, Follower(FLAT, cp.min_base_radius * 0.9, sense=-1))
    assert below.undercut and LinearRing(below.trimmed.T).is_simple


def test_flat_face_profile_is_the_notes_formula_and_envelope():
    p = notes_program()
    f = Follower(FLAT, 0.05, sense=-1)
    th = np.linspace(0, 2 * math.pi, 73)[:-1]
    ev = evaluate(p, f, th)
    s, ds = p.derivatives(th)[:2]
    x = -(0.05 + s) * np.sin(th) - ds * np.cos(th)
    y = (0.05 + s) * np.cos(th) - ds * np.sin(th)
    assert np.allclose(ev.profile, np.stack([x, y]), atol=1e-15)
    # every contact point lies on its face line; the profile's radius of curvature r_b + s + s''
    assert np.allclose(np.sum(ev.profile * ev.normal, axis=0), 0.05 + s, atol=1e-15)
    h = 1e-5
    a, b, c = (evaluate(p, f, th + k * h).profile for k in (-1, 0, 1))
    d1, d2 = (c - a) / (2 * h), (c - 2 * b + a) / h ** 2
    rho = np.hypot(*d1) ** 3 / np.abs(d1[0] * d2[1] - d1[1] * d2[0])
    joins = np.array([0, D(120), D(180), D(210), 2 * math.pi])
    ok = (np.min(np.abs(th[:, None] - joins[None, :]), axis=1) > 3 * h) & (ev.rho_profile > 0)
    assert ok.sum() > 60
    assert np.allclose(rho[ok], ev.rho_profile[ok], rtol=1e-4)


@settings(max_examples=25, deadline=None)
@given(law=st.sampled_from(LAWS), e=st.floats(-0.015, 0.015), rr=st.floats(0.002, 0.01), sense=st.sampled_from([1, -1]),
       n=st.sampled_from([12, 18, 36]))
def test_construction_points_equal_closed_forms(law, e, rr, sense, n):
    p = Program([Segment(DWELL, D(60)), Segment(RISE, D(120), 0.02, law), Segment(DWELL, D(30)),
                 Segment(RETURN, D(150), 0.02, law)])
    f = Follower(ROLLER, 0.04, rr, e, sense)
    c = construct(p, f, n, samples=256)
    size = c.profile.size
    for i, t in enumerate(c.stations):
        cf = closed_form_point(p, f, float(t))
        assert np.hypot(*(c.centres[:, i] - cf["P"])) <= 1e-9 * size
        assert np.hypot(*(c.contacts[:, i] - cf["C"])) <= 1e-9 * size
    phi = next(m for m in c.measured if m.name == "phi_max")
    assert phi.value == pytest.approx(closed_form_point(p, f, float(c.stations[c.station_names["phi_max"]]))["phi"],
                                      rel=1e-9, abs=1e-12)


def test_roller_envelope_geometry():
    """Each contact point is rr from its roller centre, on the pitch curve's normal, and the profile's
    tangent there is square to that radius (a true envelope); curvature equals the numerical one."""
    p = notes_program()
    for e, sense in ((0.0, 1), (0.01, 1), (-0.008, -1)):
        f = Follower(ROLLER, 1.5 * IN, 0.5 * IN, e, sense)
        th = np.linspace(0.05, 2 * math.pi - 0.05, 200)
        ev = evaluate(p, f, th)
        r = ev.pitch - ev.profile
        assert np.allclose(np.hypot(*r), 0.5 * IN, rtol=1e-13)
        h = 1e-6
        tang = (evaluate(p, f, th + h).profile - evaluate(p, f, th - h).profile) / (2 * h)
        cosang = np.sum(tang * r, axis=0) / (np.hypot(*tang) * np.hypot(*r))
        assert np.max(np.abs(cosang)) < 1e-6
        h = 1e-4
        a, b, c = (evaluate(p, f, th + k * h).pitch for k in (-1, 0, 1))
        d1, d2 = (c - a) / (2 * h), (c - 2 * b + a) / h ** 2
        rho = -sense * np.hypot(*d1) ** 3 / (d1[0] * d2[1] - d1[1] * d2[0])
        joins = np.array([D(120), D(180), D(210), 0, 2 * math.pi])
        away = np.min(np.abs(th[:, None] - joins[None, :]), axis=1) > 3 * h
        assert np.allclose(rho[away], ev.rho_pitch[away], rtol=1e-5)
        # pressure angle: the closed form with the offset (never without it)
        s, ds = p.derivatives(th)[:2]
        d0 = math.sqrt((2 * IN) ** 2 - e * e)
        assert np.allclose(ev.pressure_angle, np.arctan((ds - sense * e) / (d0 + s)), atol=1e-14)


def test_notes_roller_cam_exact_values():
    cp = analyse(notes_program(), Follower(ROLLER, 1.5 * IN, 0.5 * IN))
    # at the top of the rise, s' = 0: rho = r^2 / (r - r'') with r = 2.8 in, r'' = -(0.4)(3)^2 = -3.6 in
    assert cp.min_rho_pitch[1] == pytest.approx(2.8 ** 2 / (2.8 + 3.6) * IN, rel=1e-9)
    assert math.degrees(cp.min_rho_pitch[0]) == pytest.approx(180, abs=1e-6)
    # largest pressure angle: max atan(1.2 sin x / (2 + 0.4(1 - cos x))) over the rise, x = 3(theta-120deg)
    x = np.linspace(0, math.pi, 2000001)
    ref = np.max(np.arctan(1.2 * np.sin(x) / (2.4 - 0.4 * np.cos(x))))
    assert abs(cp.max_pressure_angle[1]) == pytest.approx(ref, abs=1e-10)
    assert cp.undercut_free


def _cycloid_pitch_limit():
    p = Program([Segment(RISE, D(90), 0.03, CYCLOIDAL), Segment(DWELL, D(30)), Segment(RETURN, D(90), 0.03, CYCLOIDAL),
                 Segment(DWELL, D(150))])
    Rp = 0.035
    probe = analyse(p, Follower(ROLLER, Rp - 0.001, 0.001))
    return p, Rp, probe.min_rho_pitch[1], probe.min_rho_pitch[0]


def test_undercut_at_below_and_above_the_limit():
    """The pitch curve is fixed (prime circle fixed); the roller at, just below and just above its
    smallest convex radius of curvature."""
    p, Rp, rho, t = _cycloid_pitch_limit()
    below = analyse(p, Follower(ROLLER, Rp - rho * 0.999, rho * 0.999))
    assert below.undercut_free and LinearRing(below.trimmed.T).is_simple
    at = analyse(p, Follower(ROLLER, Rp - rho, rho))
    assert at.cusp_at and not at.undercut and abs(at.cusp_at[0] - t) < 1e-6
    above = analyse(p, Follower(ROLLER, Rp - rho * 1.05, rho * 1.05))
    assert above.undercut and not above.cusp_at
    (a, b), = [sp for sp in above.undercut if sp[0] <= t <= sp[1]]
    assert a < t < b
    # the raw envelope crosses itself; the trimmed profile does not, and no roller cuts into it
    raw = LinearRing(above.samples.profile.T)
    assert not raw.is_simple
    ring = LinearRing(above.trimmed.T)
    assert ring.is_simple
    P = above.samples.pitch
    d = np.min(np.hypot(above.trimmed[0][:, None] - P[0][None, :], above.trimmed[1][:, None] - P[1][None, :]), axis=1)
    assert np.min(d) >= rho * 1.05 * (1 - 1e-3)
    # the trimmed cam is the material left by the roller swept round the pitch curve (shapely, areas only)
    swept = Polygon(P.T).buffer(-rho * 1.05, quad_segs=64)
    assert abs(Polygon(above.trimmed.T).area - swept.area) < 2e-3 * swept.area


def test_knife_edge_and_errors():
    p = notes_program()
    cp = analyse(p, Follower(KNIFE, 0.04, offset=0.005))
    assert np.allclose(cp.samples.profile, cp.samples.pitch)
    with pytest.raises(ValueError):
        Follower(ROLLER, 0.04, 0.0)
    with pytest.raises(ValueError):
        Follower(ROLLER, 0.01, 0.005, offset=0.02)
    with pytest.raises(ValueError):
        Follower(FLAT, 0.04, 0.01)


@settings(max_examples=25, deadline=None)
@given(law=st.sampled_from(LAWS), swing=st.floats(5, 25), a=st.floats(0.07, 0.12), arm=st.floats(0.05, 0.09),
       sense=st.sampled_from([1, -1]))
def test_oscillating_roller_equals_kennedy(law, swing, a, arm, sense):
    """The oscillating roller's envelope (derivatives of the rotated pitch curve) against the contact point
    found through the instant centre of cam and arm (Kennedy), at every construction station."""
    from constructions.cams.profile import OSCILLATING
    rb, rr = 0.035, 0.007
    if not abs(a - arm) < rb + rr < a + arm:
        return
    p = Program([Segment(RISE, D(120), D(swing), law), Segment(DWELL, D(40)), Segment(RETURN, D(120), D(swing), law),
                 Segment(DWELL, D(80))])
    f = Follower(OSCILLATING, rb, rr, sense=sense, pivot_distance=a, arm_length=arm)
    c = construct(p, f, 18, samples=256)
    size = c.profile.size
    for i, t in enumerate(c.stations):
        s, ds = (float(v[0]) for v in p.derivatives(np.array([t]))[:2])
        if abs(sense + ds) < 0.05:          # the instant centre runs off to infinity: Kennedy's form is ill-posed
            continue
        cf = closed_form_point(p, f, float(t))
        assert np.hypot(*(c.centres[:, i] - cf["P"])) <= 1e-9 * size
        assert np.hypot(*(c.contacts[:, i] - cf["C"])) <= 1e-9 * size
    k = c.station_names["phi_max"]
    phi = next(m for m in c.measured if m.name == "phi_max").value
    assert phi == pytest.approx(closed_form_point(p, f, float(c.stations[k]))["phi"], abs=1e-9)
    # the roller centre stays on the arm's circle about its laid-out pivot
    A = np.stack([a * np.cos(-sense * c.stations), a * np.sin(-sense * c.stations)])
    assert np.allclose(np.hypot(*(c.centres - A)), arm, rtol=1e-12)
