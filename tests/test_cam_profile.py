"""The exact cam profile: the envelope against closed forms and numerical geometry, curvature, pressure
angle with the offset, the flat face's minimum base radius (the notes' 0.25 cm), and undercut at, just
below and just above the limit."""

import math

import numpy as np
import pytest
from hypothesis import example, given, settings, strategies as st
from shapely.geometry import LinearRing, Polygon

from constructions.cams.check import closed_form_point, min_base_radius_flat
from constructions.cams.construction import construct
from constructions.cams.envelope import evaluate
from constructions.cams.follower import FLAT, KNIFE, OSC_FLAT, OSCILLATING, ROLLER, Follower
from constructions.cams.laws import CYCLOIDAL, DWELL, HARMONIC, LAWS, RETURN, RISE, UNIFORM, Program, Segment
from constructions.cams.profile import analyse, cam_size, check_face
from constructions.cams.sampling import chord_error_rate, profile_samples

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


def _chord_errors(p, f, th, C, k=24):
    """The largest distance of the exact profile from each chord between neighbouring samples: the curve
    evaluated at k - 1 cam angles inside each step; a step of no cam angle (a corner) is a roller's arc about
    the corner (the chord's sagitta) or a flat face's straight slide (no error)."""
    n = len(th)
    t1 = np.append(th[1:], th[0] + 2 * math.pi)
    C1 = np.roll(C, -1, axis=1)
    out = np.zeros(n)
    same = np.isclose(t1, th, rtol=0, atol=1e-13)
    step = ~same & np.isfinite(th) & np.isfinite(t1)        # a fold's crossing (NaN) is checked apart
    ab = C1 - C
    for j in range(1, k):
        tm = th[step] + (t1[step] - th[step]) * j / k
        M = evaluate(p, f, tm).profile
        a, d = C[:, step], ab[:, step]
        u = np.clip(np.sum((M - a) * d, axis=0) / np.sum(d * d, axis=0), 0, 1)
        out[step] = np.maximum(out[step], np.hypot(*(M - (a + u * d))))
    if same.any() and f.kind not in (FLAT, OSC_FLAT):
        P = evaluate(p, f, th[same]).pitch
        r0, r1 = C[:, same] - P, C1[:, same] - P
        assert np.allclose(np.hypot(*r0), f.roller_radius, rtol=1e-12)     # on the roller circle
        assert np.allclose(np.hypot(*r1), f.roller_radius, rtol=1e-12)
        half = 0.5 * np.arccos(np.clip(np.sum(r0 * r1, axis=0) / f.roller_radius ** 2, -1, 1))
        out[same] = f.roller_radius * (1 - np.cos(half))
    return out


def _sampling_cam(law, kind, e, sense, rb):
    osc = kind == OSCILLATING
    h = D(18) if osc else 0.02
    p = Program([Segment(DWELL, D(50)), Segment(RISE, D(100), h, law), Segment(DWELL, D(40)),
                 Segment(RETURN, D(130), h, law), Segment(DWELL, D(40))])
    if osc:
        return p, Follower(OSCILLATING, rb, 0.006, sense=sense, pivot_distance=0.09, arm_length=0.07)
    if kind == OSC_FLAT:
        p = Program([Segment(DWELL, D(50)), Segment(RISE, D(100), D(10), law), Segment(DWELL, D(40)),
                     Segment(RETURN, D(130), D(10), law), Segment(DWELL, D(40))])
        # clear of undercut: the smallest radius of the profile stays above 17 mm for every law, sense, offset
        return p, Follower(OSC_FLAT, rb + 0.05, sense=sense, pivot_distance=0.15, face_offset=e / 2)
    if kind == FLAT:
        return p, Follower(FLAT, rb + 0.02, sense=sense)          # clear of the smallest base radius
    return p, Follower(kind, rb, 0.008 if kind == ROLLER else 0.0, e, sense)


@settings(max_examples=60, deadline=None)
@given(law=st.sampled_from(LAWS), kind=st.sampled_from([KNIFE, ROLLER, FLAT, "oscillating roller", OSC_FLAT]),
       e=st.floats(-0.012, 0.012), sense=st.sampled_from([1, -1]), rb=st.floats(0.03, 0.05),
       rel=st.sampled_from([1e-4, 1e-6, 1e-7]))
def test_profile_samples_every_chord_within_the_tolerance(law, kind, e, sense, rb, rel):
    """The profile-only path (:mod:`constructions.cams.sampling`): every point on the exact envelope (the
    full evaluation's, at its cam angle), every chord within the tolerance of the exact curve between its
    ends, for every law (uniform's corners included) and every follower."""
    p, f = _sampling_cam(law, kind, e, sense, rb)
    size = cam_size(p, f)
    tol = rel * size
    th, C = profile_samples(p, f, tol)
    if np.isnan(th).any():       # uniform motion folds a roller's profile at its convex corners: cut there
        assert law == "uniform" and kind != KNIFE
    # every point exact: the points with a cam angle of their own equal the full evaluation's
    own = ~(np.isclose(th, np.roll(th, 1), atol=1e-13) | np.isclose(th, np.roll(th, -1), atol=1e-13))
    own &= np.isfinite(th)
    assert np.max(np.hypot(*(evaluate(p, f, th[own]).profile - C[:, own]))) <= 1e-12 * size
    err = _chord_errors(p, f, th, C)
    assert np.max(err) <= tol
    assert np.max(err) > 0.5 * tol            # and not wastefully dense
    assert LinearRing(C.T).is_simple


def test_profile_points_default_on_the_notes_cam():
    """The benchmark's default: the notes' roller cam at 1e-6 of its size, every chord within it, and fewer
    points than one even step everywhere would need (2585 at the tightest bend's step)."""
    p = notes_program()
    f = Follower(ROLLER, 1.5 * IN, 0.5 * IN)
    size = f.prime_radius + p.lift
    th, C = profile_samples(p, f, 1e-6 * size)
    err = _chord_errors(p, f, th, C, k=48)
    assert 0.9e-6 * size < np.max(err) <= 1e-6 * size
    assert C.shape[1] < 2200
    # the dwells are arcs about O: radius r_b (at zero lift) and r_b + 0.8 in
    r = np.hypot(*C)
    dw = (th < D(120)) | ((th > D(180)) & (th < D(210)))
    assert np.allclose(r[dw], np.where(th[dw] < D(120), 1.5 * IN, 2.3 * IN), rtol=1e-14)


def test_chord_error_rate_is_the_curve_s_own():
    """g = |C' x C''| / |C'| from s, s', s'' against numerical derivatives of the exact envelope."""
    for kind in (KNIFE, ROLLER, FLAT, "oscillating roller", OSC_FLAT):
        p, f = _sampling_cam(HARMONIC, kind, 0.007, -1, 0.04)
        th = np.linspace(D(55), D(140), 30)
        h = 1e-4
        a, b, c = (evaluate(p, f, th + k * h).profile for k in (-1, 0, 1))
        d1, d2 = (c - a) / (2 * h), (c - 2 * b + a) / h ** 2
        num = np.abs(d1[0] * d2[1] - d1[1] * d2[0]) / np.hypot(*d1)
        s, ds, dds, _ = p.derivatives(th)
        assert np.allclose(chord_error_rate(f, s, ds, dds), num, rtol=1e-5)


def test_uniform_corners_arcs_and_folds():
    """Uniform motion: s' jumps at its ends, the pitch curve has corners.  A roller's profile takes the
    roller circle's arc at a reflex corner (the start of a rise of a CCW cam) and is trimmed where the
    branches cross (a convex corner); nothing self-intersects."""
    p, f = _sampling_cam(UNIFORM, ROLLER, 0.0, 1, 0.04)
    tol = 1e-6 * (f.prime_radius + p.lift)
    th, C = profile_samples(p, f, tol)
    assert np.isnan(th).sum() == 2 and LinearRing(C.T).is_simple      # the end of the rise, the start of the return
    assert np.max(_chord_errors(p, f, th, C)) <= tol
    # the crossing is where the two branches meet: within the tolerance of both exact branches
    for k in np.nonzero(np.isnan(th))[0]:
        X = C[:, k]
        for t0 in (th[k - 1], th[k + 1]):
            near = evaluate(p, f, np.linspace(t0 - 0.01, t0 + 0.01, 40001)).profile
            assert np.min(np.hypot(*(near - X[:, None]))) < tol
    # the arc at the start of the rise (50 deg): points on the roller circle about the corner's pitch point
    P = evaluate(p, f, np.array([D(50)])).pitch[:, 0]
    on = np.abs(np.hypot(*(C - P[:, None])) - f.roller_radius) < 1e-12
    assert on.sum() > 20
    # the knife edge keeps the corner itself; the flat face's contact slides along the face line
    for kind in (KNIFE, FLAT):
        q, g = _sampling_cam(UNIFORM, kind, 0.0, 1, 0.04)
        t, pts = profile_samples(q, g, 1e-6 * 0.06)
        assert LinearRing(pts.T).is_simple and (np.isnan(t).any() == (kind == FLAT))
        assert np.max(_chord_errors(q, g, t, pts)) <= 1e-6 * 0.06



def test_uniform_corners_are_named_and_the_drawn_profile_trimmed():
    """The analysis behind a sheet finds the joins where s' jumps and draws the profile the trim keeps:
    a uniform-motion cam's profile on the sheet never crosses itself (its raw envelope does)."""
    for kind, sense in ((ROLLER, 1), (ROLLER, -1), (FLAT, 1)):
        p, f = _sampling_cam(UNIFORM, kind, 0.0, sense, 0.04)
        cp = analyse(p, f, samples=2048)
        assert sorted(round(math.degrees(t) % 360, 9) for t in cp.corners) == sorted(
            round(math.degrees(t) % 360, 9) for t in p.starts[1:]), kind      # not 0: a dwell meets a dwell
        assert LinearRing(cp.trimmed.T).is_simple
        if kind == ROLLER:
            assert not LinearRing(cp.samples.profile.T).is_simple        # what was drawn before
    q, g = _sampling_cam(UNIFORM, KNIFE, 0.0, 1, 0.04)
    assert analyse(q, g, samples=512).corners == []                      # a knife edge draws the corner itself
    p, f = _sampling_cam(CYCLOIDAL, ROLLER, 0.0, 1, 0.04)
    assert analyse(p, f, samples=512).corners == []

@settings(max_examples=30, deadline=None)
@given(law=st.sampled_from(LAWS), swing=st.floats(5, 20), a=st.floats(0.08, 0.14), ef=st.floats(-0.015, 0.015),
       sense=st.sampled_from([1, -1]))
@example(law="4-5-6-7 polynomial", swing=13.109375, a=0.12419815552916008, ef=-0.0047047139980408905, sense=-1)
def test_oscillating_flat_face_equals_kennedy(law, swing, a, ef, sense):
    """The oscillating flat face: its envelope (support-function form) against the contact found through the
    instant centre of cam and arm (Kennedy), at every construction station, to 1e-9 of the cam's size; the
    contact on its face line, the profile's tangent square to the face's normal, and its radius of curvature
    against the numerical one."""
    rb = 0.035
    p = Program([Segment(RISE, D(120), D(swing), law), Segment(DWELL, D(40)), Segment(RETURN, D(120), D(swing), law),
                 Segment(DWELL, D(80))])
    f = Follower(OSC_FLAT, rb, sense=sense, pivot_distance=a, face_offset=ef)
    assert math.sin(f.beta0) * a == pytest.approx(rb + ef, rel=1e-15)
    c = construct(p, f, 18, samples=256)
    size = c.profile.size
    for i, t in enumerate(c.stations):
        cf = closed_form_point(p, f, float(t))
        assert np.hypot(*(c.centres[:, i] - cf["P"])) <= 1e-9 * size
        assert np.hypot(*(c.contacts[:, i] - cf["C"])) <= 1e-9 * size
    k = c.station_names["phi_max"]
    phi = next(m for m in c.measured if m.name == "phi_max").value
    assert phi == pytest.approx(closed_form_point(p, f, float(c.stations[k]))["phi"], rel=1e-9, abs=1e-12)
    th = np.linspace(0.02, 2 * math.pi - 0.02, 150)
    ev = evaluate(p, f, th)
    assert np.allclose(np.sum(ev.profile * ev.normal, axis=0), ev.support, rtol=0, atol=1e-15)
    h = 1e-6
    tang = (evaluate(p, f, th + h).profile - evaluate(p, f, th - h).profile) / (2 * h)
    # an envelope: the tangent square to the normal, to 1e-6 of its length -- plus the central difference's
    # own rounding, eps |P| / h, which is all that is left where the profile barely moves (|P'| 8e-6 near a
    # face's limit: hypothesis found the plain relative check at 5e-6 there, on the code before the rooms too)
    floor = 64 * np.finfo(float).eps * np.max(np.hypot(*ev.profile)) / h
    assert np.all(np.abs(np.sum(tang * ev.normal, axis=0)) <= 1e-6 * np.hypot(*tang) + floor)
    h = 1e-3                  # five-point stencils: their error ~h^4, fine where the radius is a millimetre
    qm2, qm1, q0, q1, q2 = (evaluate(p, f, th + j * h).profile for j in (-2, -1, 0, 1, 2))
    d1 = (-q2 + 8 * q1 - 8 * qm1 + qm2) / (12 * h)
    d2 = (-q2 + 16 * q1 - 30 * q0 + 16 * qm1 - qm2) / (12 * h * h)
    rho = np.hypot(*d1) ** 3 / np.abs(d1[0] * d2[1] - d1[1] * d2[0])
    joins = np.array([0, D(120), D(160), D(280), 2 * math.pi])
    away = (np.min(np.abs(th[:, None] - joins[None, :]), axis=1) > 3 * h) & (ev.rho_profile > 1e-3)
    assert np.allclose(rho[away], ev.rho_profile[away], rtol=1e-5)
    # the face's reach: the contact's distance along the arm from the pivot's foot, a cos(beta) sigma / (sigma + s')
    s, ds = p.derivatives(th)[:2]
    assert np.allclose(ev.along, a * np.cos(f.beta0 + s) * sense / (sense + ds), rtol=1e-12)


def test_oscillating_flat_face_limits():
    """A dwell is an arc of the base circle (the face tangent to it); the face that would stop turning against
    the cam, or swing past square, is refused with the reason; undercut is found and trimmed."""
    p = Program([Segment(RISE, D(120), D(15), CYCLOIDAL), Segment(DWELL, D(40)), Segment(RETURN, D(120), D(15),
                 CYCLOIDAL), Segment(DWELL, D(80))])
    f = Follower(OSC_FLAT, 0.04, sense=-1, pivot_distance=0.1, face_offset=0.01)
    ev = evaluate(p, f, np.linspace(D(290), D(350), 7))
    assert np.allclose(np.hypot(*ev.profile), 0.04, rtol=1e-14) and np.allclose(ev.rho_profile, 0.04, rtol=1e-14)
    fast = Program([Segment(RISE, D(10), D(15), CYCLOIDAL), Segment(DWELL, D(40)), Segment(RETURN, D(120), D(15),
                    CYCLOIDAL), Segment(DWELL, D(190))])       # s' up to 3: the arm outruns a CW cam
    with pytest.raises(ValueError, match="stops turning"):
        check_face(fast, f)
    with pytest.raises(ValueError, match="90 deg"):
        check_face(Program([Segment(RISE, D(180), D(70), CYCLOIDAL), Segment(RETURN, D(180), D(70), CYCLOIDAL)]), f)
    with pytest.raises(ValueError):
        Follower(OSC_FLAT, 0.04, pivot_distance=0.03)                               # the face cannot reach
    small = Follower(OSC_FLAT, 0.004, sense=-1, pivot_distance=0.1, face_offset=0.0)
    cp = analyse(p, small)
    assert cp.undercut and cp.min_rho_profile[1] < 0 and LinearRing(cp.trimmed.T).is_simple
    big = analyse(p, f)
    assert big.undercut_free and big.face_width[0] < f.pivot_distance * math.cos(f.beta0) < big.face_width[1]
