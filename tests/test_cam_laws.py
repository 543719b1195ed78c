"""Cam motion laws and programs: every derivative equals the numerical derivative of s; joins continuous
where the law promises it and flagged where not."""

import math

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from constructions.cams.charts import svaj_series
from constructions.cams.laws import (CYCLOIDAL, DWELL, HARMONIC, LAWS, PARABOLIC, POLY345, POLY4567, RETURN, RISE,
                                     UNIFORM, Program, Segment, end_slope, law_name, normalised, normalised_low)

D = math.radians


def _numeric(fn, u, h=1e-5):
    return (fn(u + h) - fn(u - h)) / (2 * h)


@pytest.mark.parametrize("law", LAWS)
def test_law_derivatives_equal_numerical_derivatives(law):
    u = np.linspace(0.013, 0.987, 97)
    u = u[np.abs(u - 0.5) > 2e-4]            # the parabola's inner join is a kink of f''
    f = lambda x, k: normalised(law, x)[k]  # noqa: E731
    for k in (1, 2, 3):
        num = _numeric(lambda x: f(x, k - 1), u)
        assert np.allclose(f(u, k), num, rtol=1e-6, atol=1e-6 * (1 + np.max(np.abs(num)))), (law, k)
    f0 = normalised(law, np.array([0.0, 1.0]))[0]
    assert f0[0] == pytest.approx(0, abs=1e-15) and f0[1] == pytest.approx(1, abs=1e-14)
    # odd about the middle: a return by h f(u) from the top is the notes' h f((theta_e - theta)/beta)
    assert np.allclose(normalised(law, 1 - u)[0], 1 - normalised(law, u)[0], atol=1e-14)


def test_harmonic_acceleration_and_jerk_dimensions():
    """The notes' SHM acceleration (L/2)(pi L omega / 2 beta)^2 cos fails a dimension check; ours is
    (L/2)(pi/beta)^2 omega^2 cos and j = -(L/2)(pi/beta)^3 omega^3 sin."""
    L, beta, w = 0.025, D(120), 10.0
    p = Program([Segment(RISE, beta, L, HARMONIC), Segment(DWELL, D(20)), Segment(RETURN, beta, L, HARMONIC),
                 Segment(DWELL, 2 * math.pi - 2 * beta - D(20))])
    th = np.array([0.3, 0.9, 1.7])
    s, v, a, j = p.with_speed(th, w)
    x = math.pi * th / beta
    assert np.allclose(a, L / 2 * (math.pi / beta) ** 2 * w ** 2 * np.cos(x), rtol=1e-13)
    assert np.allclose(j, -L / 2 * (math.pi / beta) ** 3 * w ** 3 * np.sin(x), rtol=1e-13)
    # the time derivatives numerically (theta = w t)
    t, h = th / w, 1e-6
    sv = lambda tt: p.with_speed(tt * w, w)   # noqa: E731
    assert np.allclose((sv(t + h)[0] - sv(t - h)[0]) / (2 * h), v, rtol=1e-6)
    assert np.allclose((sv(t + h)[1] - sv(t - h)[1]) / (2 * h), a, rtol=1e-6)
    assert np.allclose((sv(t + h)[2] - sv(t - h)[2]) / (2 * h), j, rtol=1e-5)


@settings(max_examples=40, deadline=None)
@given(rise=st.sampled_from(LAWS), ret=st.sampled_from(LAWS), b1=st.floats(20, 170), b2=st.floats(20, 170),
       d1=st.floats(0, 100), lift=st.floats(1e-3, 0.1))
def test_program_derivatives_numerically(rise, ret, b1, b2, d1, lift):
    d2 = 360 - b1 - b2 - d1
    if d2 <= 1:
        return
    p = Program([Segment(RISE, D(b1), lift, rise), Segment(DWELL, D(d1)) if d1 > 0.5 else Segment(DWELL, D(d1 + 0.5)),
                 Segment(RETURN, D(b2), lift, ret), Segment(DWELL, D(d2 - (0 if d1 > 0.5 else 0.5)))])
    breaks = np.array(sorted({j.theta for j in p.joins()} | {2 * math.pi}))
    th = np.linspace(0.01, 2 * math.pi - 0.01, 301)
    th = th[np.min(np.abs(th[:, None] - breaks[None, :]), axis=1) > 1e-3]
    h = 1e-6
    for k in (1, 2, 3):
        num = (p.derivatives(th + h)[k - 1] - p.derivatives(th - h)[k - 1]) / (2 * h)
        ref = np.max(np.abs(p.derivatives(th)[k])) + lift
        assert np.max(np.abs(p.derivatives(th)[k] - num)) <= 2e-5 * ref


def _consequences(law):
    p = Program([Segment(DWELL, D(90)), Segment(RISE, D(90), 0.02, law), Segment(DWELL, D(90)),
                 Segment(RETURN, D(90), 0.02, law)])
    return p, [(round(math.degrees(j.theta), 9), j.consequence) for j in p.joins()]


def test_joins_named():
    _, c = _consequences(UNIFORM)
    assert [x for _, x in c] == ["infinite acceleration"] * 4
    _, c = _consequences(PARABOLIC)
    assert c == [(0.0, "infinite jerk"), (90.0, "infinite jerk"), (135.0, "infinite jerk"), (180.0, "infinite jerk"),
                 (270.0, "infinite jerk"), (315.0, "infinite jerk")]
    _, c = _consequences(HARMONIC)
    assert [x for _, x in c] == ["infinite jerk"] * 4
    _, c = _consequences(CYCLOIDAL)
    assert [x for _, x in c] == ["finite jump in jerk"] * 4
    _, c = _consequences(POLY345)
    assert [x for _, x in c] == ["finite jump in jerk"] * 4
    _, c = _consequences(POLY4567)
    assert all(j.continuous for j in _consequences(POLY4567)[0].joins())


def test_rise_into_return_shm_is_continuous_in_acceleration_only_if_equal_curvature():
    # SHM rise straight into an SHM return of the same span: s' = 0 both sides, s'' = -(h/2)(pi/b)^2 both
    # sides, so acceleration is continuous; s''' jumps from 0- to ... both 0: continuous
    p = Program([Segment(RISE, math.pi, 0.01, HARMONIC), Segment(RETURN, math.pi, 0.01, HARMONIC)])
    assert all(j.continuous for j in p.joins())


def test_program_errors():
    with pytest.raises(ValueError, match="one turn"):
        Program([Segment(RISE, D(100), 0.01, HARMONIC), Segment(RETURN, D(100), 0.01, HARMONIC)])
    with pytest.raises(ValueError, match="back at zero"):
        Program([Segment(RISE, D(180), 0.01, HARMONIC), Segment(RETURN, D(180), 0.02 - 0.011, HARMONIC)])
    with pytest.raises(ValueError, match="below zero"):
        Program([Segment(RETURN, D(180), 0.01, HARMONIC), Segment(RISE, D(180), 0.01, HARMONIC)])
    with pytest.raises(ValueError):
        law_name("sinusoid")
    assert law_name("SHM") == HARMONIC and law_name("3-4-5") == POLY345


def test_chart_pieces_keep_their_one_sided_values():
    """Each piece of the s-v-a-j charts ends on its own law's value (the jerk of a cycloidal rise ends at
    +4 pi^2 h / beta^3, not at the dwell's 0), with a break before the next piece's value."""
    p = Program([Segment(RISE, D(120), 0.01, CYCLOIDAL), Segment(DWELL, D(40)), Segment(RETURN, D(120), 0.01, CYCLOIDAL),
                 Segment(DWELL, D(80))])
    x, (s, v, a, j) = svaj_series(p, None)
    x = np.array(x)
    k = int(np.flatnonzero(np.isclose(x, D(120)))[0])
    assert j[k] == pytest.approx(4 * math.pi ** 2 * 0.01 / D(120) ** 3, rel=1e-6)
    assert math.isnan(j[k + 1]) and j[k + 2] == 0.0


def test_profile_shortcuts_equal_the_laws():
    """The profile-only path's f, f' (fewer operations) and its exact slopes at ends and inner joins equal the
    laws' own formulas."""
    u = np.linspace(0.0, 1.0, 1001)
    for law in LAWS:
        f = normalised(law, u)
        lo = normalised_low(law, u)
        assert np.allclose(lo[0], f[0], rtol=0, atol=1e-12) and np.allclose(lo[1], f[1], rtol=0, atol=1e-12)   # Horner
        for x in (0.0, 1.0) + ((0.5,) if law == "parabolic" else ()):
            assert end_slope(law, x) == pytest.approx(float(normalised(law, np.array([x]))[1][0]), abs=1e-14)
