"""The cam results a student is asked for: the maxima of v, a, j against the laws' closed forms, the pressure
angle's against the radial roller's closed form, the per-station table against the law and the closed-form
check, and the warning near the roller's and the flat face's limits."""

from __future__ import annotations

import math

import numpy as np
import pytest

from constructions.cams.check import closed_form_point
from constructions.cams.follower import Follower
from constructions.cams.laws import Program, Segment
from constructions.cams.maxima import law_peak, motion_maxima, overall, pressure_maxima, station_peaks
from constructions.cams.stations import station_table

H, BETA, OMEGA = 0.025, math.radians(100.0), 12.0
R3 = math.sqrt(3.0)

CLOSED = {
    # law: (v_max, a_max, j_max) for a lift H over BETA at OMEGA, and the u of each peak
    "simple harmonic": ((math.pi * H * OMEGA / (2 * BETA), (0.5,)),
                        (math.pi ** 2 * H * OMEGA ** 2 / (2 * BETA ** 2), (0.0, 1.0)),
                        (math.pi ** 3 * H * OMEGA ** 3 / (2 * BETA ** 3), (0.5,))),
    "cycloidal": ((2 * H * OMEGA / BETA, (0.5,)), (2 * math.pi * H * OMEGA ** 2 / BETA ** 2, (0.25, 0.75)),
                  (4 * math.pi ** 2 * H * OMEGA ** 3 / BETA ** 3, (0.0, 0.5, 1.0))),
    "3-4-5 polynomial": ((15 / 8 * H * OMEGA / BETA, (0.5,)),
                         (10 * R3 / 3 * H * OMEGA ** 2 / BETA ** 2, ((3 - R3) / 6, (3 + R3) / 6)),
                         (60 * H * OMEGA ** 3 / BETA ** 3, (0.0, 1.0))),
    "4-5-6-7 polynomial": ((35 / 16 * H * OMEGA / BETA, (0.5,)),
                           (84 * math.sqrt(5) / 25 * H * OMEGA ** 2 / BETA ** 2,
                            ((5 - math.sqrt(5)) / 10, (5 + math.sqrt(5)) / 10)),
                           (52.5 * H * OMEGA ** 3 / BETA ** 3, (0.5,))),
    "parabolic": ((2 * H * OMEGA / BETA, (0.5,)), (4 * H * OMEGA ** 2 / BETA ** 2, None), (0.0, None)),
}


def program(law: str, rise=BETA, dwell=math.radians(40.0)) -> Program:
    return Program([Segment("dwell", dwell), Segment("rise", rise, H, law), Segment("dwell", dwell),
                    Segment("return", 2 * math.pi - rise - 2 * dwell, H, law)])


@pytest.mark.parametrize("law", sorted(CLOSED))
def test_rise_maxima_are_the_laws_closed_forms(law):
    p = program(law)
    mx = motion_maxima(p, OMEGA)
    start = p.starts[1]
    for q, (value, us) in zip(("v", "a", "j"), CLOSED[law]):
        peak = mx[q][1]
        assert peak.value == pytest.approx(value, rel=1e-12, abs=1e-12)
        if us is None:
            assert peak.throughout and peak.at == pytest.approx((start, start + BETA), abs=1e-15)
        else:
            assert peak.at == pytest.approx(tuple(start + u * BETA for u in us), abs=1e-12)
        assert mx[q][0].value == 0.0 and mx[q][0].throughout              # a dwell


@pytest.mark.parametrize("law", sorted(CLOSED))
def test_law_peaks_are_the_largest_on_a_fine_grid(law):
    """Each law's |f^(n)| on 1e6 points never exceeds the peak found on paper (and reaches it to 1e-9)."""
    from constructions.cams.laws import normalised
    u = np.linspace(0.0, 1.0, 1_000_001)
    f = normalised(law, u)
    for n in (1, 2, 3):
        top = law_peak(law, n)[0]
        grid = float(np.max(np.abs(f[n])))
        assert grid <= top * (1 + 1e-12) + 1e-12 and grid == pytest.approx(top, rel=1e-9, abs=1e-12)


def test_uniform_velocity_holds_throughout_and_overall_lists_every_peak():
    p = program("uniform")
    mx = motion_maxima(p, None)
    assert mx["v"][1].throughout and mx["v"][1].value == pytest.approx(H / BETA, rel=1e-14)
    assert mx["a"][1].value == 0.0
    even = program("uniform", rise=math.radians(140.0))                  # rise and return alike: two spans
    top = overall(motion_maxima(even, None)["v"])
    assert top.throughout and top.at == pytest.approx((math.radians(40), math.radians(180), math.radians(220),
                                                       math.radians(360)), abs=1e-12)
    # the rise over 100 deg is faster than the return over 180 deg
    sym = program("cycloidal", rise=math.radians(140.0))
    top = overall(motion_maxima(sym, 1.0)["a"])
    assert len(top.at) == 4 and top.value == pytest.approx(2 * math.pi * H / math.radians(140.0) ** 2, rel=1e-12)


def test_pressure_angle_maximum_against_the_radial_roller_closed_form():
    """Simple harmonic rise, radial roller: tan phi = k sin x / (A - B cos x), k = pi h / 2 beta, A = d0 + h/2,
    B = h/2; largest where cos x = B/A, tan phi_max = k / sqrt(A^2 - B^2)."""
    for rb, rr, h, b in [(0.0381, 0.0127, 0.02032, 60), (0.04, 0.01, 0.03, 120), (0.05, 0.02, 0.04, 90)]:
        beta = math.radians(b)
        d = math.radians(30)
        p = Program([Segment("dwell", d), Segment("rise", beta, h, "simple harmonic"), Segment("dwell", d),
                     Segment("return", 2 * math.pi - beta - 2 * d, h, "simple harmonic")])
        A, B, k = rb + rr + h / 2, h / 2, h * math.pi / (2 * beta)
        peak = pressure_maxima(p, Follower("roller", rb, rr))[1]
        assert peak.value == pytest.approx(math.atan(k / math.sqrt(A * A - B * B)), rel=1e-12)
        assert peak.at[0] == pytest.approx(d + beta * math.acos(B / A) / math.pi, abs=1e-7)


@pytest.mark.parametrize("kind,rr,e", [("roller", 0.01, 0.012), ("knife-edge", 0.0, 0.0), ("flat-faced", 0.0, 0.0)])
def test_station_table_is_the_law_and_the_closed_form(kind, rr, e):
    p = program("cycloidal")
    f = Follower(kind, 0.04, rr, e, -1)
    th = np.arange(24) * (2 * math.pi / 24)
    t = station_table(p, f, th, OMEGA)
    s, v, a, j = p.with_speed(th, OMEGA)
    for got, want in ((t.s, s), (t.v, v), (t.a, a), (t.j, j)):
        assert np.allclose(got, want, rtol=1e-12, atol=1e-15)
    for i, x in enumerate(th):
        cf = closed_form_point(p, f, float(x))
        assert t.pressure_angle[i] == pytest.approx(cf["phi"], abs=1e-12)
        assert (t.contact[0, i], t.contact[1, i]) == pytest.approx(cf["C"], abs=1e-12)
    # in the first dwell the pitch curve is an arc about O of radius |(e, d0)|, the profile rr inside it
    if kind == "flat-faced":
        assert t.rho_pitch is None and t.rho_profile[0] == pytest.approx(0.04, rel=1e-12)
    else:
        assert t.rho_pitch[0] == pytest.approx(math.hypot(e, f.d0), rel=1e-12)
        assert t.rho_profile[0] == pytest.approx(math.hypot(e, f.d0) - rr, rel=1e-12)
    # per radian: v, a, j are s', s'', s'''
    t1 = station_table(p, f, th)
    assert t1.per_radian and np.allclose(t1.a, p.derivatives(th)[2], rtol=1e-12, atol=1e-15)


def test_station_peaks_read_the_largest_station():
    p = program("simple harmonic")
    th = np.arange(36) * math.radians(10.0)
    t = station_table(p, Follower("roller", 0.04, 0.01), th, OMEGA)
    pk = station_peaks(t)
    k = int(np.argmax(np.abs(t.v)))
    assert pk["v"].value == abs(t.v[k]) and pk["v"].at == th[k] and pk["v"].index == k
    assert pk["v"].value <= motion_maxima(p, OMEGA)["v"][1].value * (1 + 1e-12)
