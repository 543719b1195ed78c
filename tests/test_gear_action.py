"""The angle of action, the pitch-line speed and the sliding velocity at the tips (issue 24), drawn and by
the closed form, against the textbook's: angle of action = arc of action / pitch radius = C.R. x 360/N;
V = omega_1 r_1; sliding at the start and end of contact (omega_1 + omega_2) x AP and x PB, with AP and PB
from the notes' tangent lengths (omega_1 - omega_2 for an internal gear, omega_1 for a rack)."""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings, strategies as st

import drafting
from constructions.gears.action import action
from constructions.gears.mesh import Pair, mesh_analysis
from constructions.gears.mesh_check import closed_form
from constructions.gears.tooth import Gear, ToothSystem
from drafting.scene.reader import SceneError

from paths import GALLERY

RPM = 2 * math.pi / 60
DEG = math.pi / 180


def notes_tangents(n1, n2, m, phi, c=None):
    """AP, PB and phi' from the teeth only (external pair, addendum one module)."""
    c = c or m * (n1 + n2) / 2
    rb1, rb2 = m * n1 / 2 * math.cos(phi), m * n2 / 2 * math.cos(phi)
    ra1, ra2 = m * n1 / 2 + m, m * n2 / 2 + m
    phiw = math.acos((rb1 + rb2) / c)
    ap = math.sqrt(ra2 ** 2 - rb2 ** 2) - rb2 * math.tan(phiw)
    pb = math.sqrt(ra1 ** 2 - rb1 ** 2) - rb1 * math.tan(phiw)
    return ap, pb, phiw


def test_the_20_40_pair_at_1000_rpm_against_hand_numbers():
    """Module 5, 20 deg: C.R. 1.6352, so 29.43 deg and 14.72 deg; V = 104.72 x 0.05 = 5.236 m/s; sliding
    157.08 rad/s x 12.646 mm = 1.986 m/s at A and x 11.490 mm = 1.805 m/s at B."""
    study = drafting.load(GALLERY / "gear-pair-20-40.toml")
    res = study.results
    cr = res["C.R."].graphical
    assert math.degrees(res["delta_1"].graphical) == pytest.approx(cr * 360 / 20, rel=1e-12)
    assert math.degrees(res["delta_2"].graphical) == pytest.approx(cr * 360 / 40, rel=1e-12)
    assert math.degrees(res["delta_1"].graphical) == pytest.approx(29.43, abs=0.005)
    w1 = 1000 * RPM
    assert res["V_p"].graphical == pytest.approx(w1 * 0.05, rel=1e-12)
    ap, pb, _ = notes_tangents(20, 40, 0.005, 20 * DEG)
    assert res["v_s A"].graphical == pytest.approx(1.5 * w1 * ap, rel=1e-12)
    assert res["v_s B"].graphical == pytest.approx(1.5 * w1 * pb, rel=1e-12)
    assert res["v_s A"].graphical == pytest.approx(1.986, abs=5e-4)
    for q in res.values():
        assert abs(q.graphical - q.analytic) <= 1e-9 * max(1.0, abs(q.analytic))
    words = " ".join(s.caption for s in study.construction.steps)
    assert "Angle of action" in words and "pitch-line speed" in words
    act = study.to_json()["action"]
    assert act["angle_of_action_deg"]["1"]["drawn"] == pytest.approx(cr * 18, rel=1e-12)
    assert act["angle_of_action_deg"]["2"]["closed_form"] == pytest.approx(cr * 9, rel=1e-9)
    assert act["speed"] == {"1": pytest.approx(1000), "2": pytest.approx(500)}
    assert act["sliding_velocity_start"]["drawn"] == pytest.approx(1.5 * w1 * ap, rel=1e-12)   # m/s, as the scene says


@settings(max_examples=60, deadline=None)
@given(st.integers(12, 60), st.integers(0, 80), st.sampled_from([14.5, 20.0, 25.0]), st.floats(0.0, 0.3),
       st.floats(10.0, 5000.0))
def test_random_external_pairs_angle_of_action_and_sliding(n1, extra, phi, pulled, rpm):
    """Drawn (read off the construction) against the notes' closed forms, at standard and larger centre
    distances: angle of action = (AB / cos phi') / r' with r' the working pitch radius."""
    n2 = n1 + extra
    m = 0.004
    c = m * (n1 + n2) / 2 + pulled * m
    s = ToothSystem(m, phi * DEG)
    pair = Pair(Gear(n1, s), Gear(n2, s), c if pulled else None)
    a = mesh_analysis(pair, thread=False, teeth_drawn=1, flank_points=8, speed=rpm * RPM)
    ap, pb, phiw = notes_tangents(n1, n2, m, phi * DEG, c)
    r1w, r2w = c * n1 / (n1 + n2), c * n2 / (n1 + n2)
    arc = (ap + pb) / math.cos(phiw)
    act = a.action
    assert act.angle_of_action[0] == pytest.approx(arc / r1w, rel=1e-9)
    assert act.angle_of_action[1] == pytest.approx(arc / r2w, rel=1e-9)
    assert act.angle_of_action[0] == pytest.approx(a.geometry.contact_ratio * 2 * math.pi / n1, rel=1e-9)
    w1 = rpm * RPM
    w2 = w1 * n1 / n2
    assert act.pitch_line_speed == pytest.approx(w1 * r1w, rel=1e-9)
    assert act.pitch_line_speed == pytest.approx(w2 * r2w, rel=1e-9)
    assert act.sliding_start == pytest.approx((w1 + w2) * ap, rel=1e-9, abs=1e-12)
    assert act.sliding_end == pytest.approx((w1 + w2) * pb, rel=1e-9, abs=1e-12)
    cf = closed_form(pair)
    closed = action(pair, cf.approach, cf.recess, cf.working_pressure_angle, w1)
    assert closed.values() == pytest.approx(act.values(), rel=1e-9, abs=1e-12)


def test_an_internal_pair_slides_at_the_difference_of_the_speeds():
    """Pinion 20 in a 60-tooth ring, module 4: the ring turns the same way at omega_1/3, the relative
    speed is omega_1 (1 - 1/3); AP = PT2 - sqrt(r_a2^2 - r_b2^2) with r_a2 = r_2 - a."""
    s = ToothSystem(0.004, 20 * DEG)
    pair = Pair(Gear(20, s), Gear(60, s), internal=True)
    w1 = 600 * RPM
    a = mesh_analysis(pair, thread=False, speed=w1)
    phi = 20 * DEG
    rb1, rb2 = 0.04 * math.cos(phi), 0.12 * math.cos(phi)
    ap = 0.12 * math.sin(phi) - math.sqrt(0.116 ** 2 - rb2 ** 2)
    pb = math.sqrt(0.044 ** 2 - rb1 ** 2) - 0.04 * math.sin(phi)
    assert a.action.omega == pytest.approx((w1, w1 / 3), rel=1e-12)
    assert a.action.sliding_start == pytest.approx(w1 * 2 / 3 * ap, rel=1e-9)
    assert a.action.sliding_end == pytest.approx(w1 * 2 / 3 * pb, rel=1e-9)
    assert a.action.angle_of_action[1] == pytest.approx((ap + pb) / rb2, rel=1e-9)


def test_a_rack_has_one_angle_of_action_and_slides_at_the_pinion_speed():
    s = ToothSystem(0.005, 20 * DEG)
    pair = Pair(Gear(24, s))
    w1 = 100 * RPM
    a = mesh_analysis(pair, thread=False, speed=w1)
    g = a.geometry
    assert set(a.action.values()) == {"delta_1", "V_p", "v_s A", "v_s B"}
    assert a.action.angle_of_action[0] == pytest.approx(g.path / (0.06 * math.cos(20 * DEG)), rel=1e-12)
    assert a.action.sliding_start == pytest.approx(w1 * g.approach, rel=1e-12)
    assert a.action.pitch_line_speed == pytest.approx(w1 * 0.06, rel=1e-12)


def test_without_a_speed_only_the_angles_of_action():
    s = ToothSystem(0.005, 20 * DEG)
    a = mesh_analysis(Pair(Gear(20, s), Gear(40, s)), thread=False)
    assert set(a.action.values()) == {"delta_1", "delta_2"}
    assert "sliding" not in a.construction.steps[-1].caption


@pytest.mark.parametrize("speed, words", [('"-5 rpm"', "must be a positive speed"), ('"5 mm"', "pair.speed")])
def test_a_bad_speed_is_refused_naming_the_key(tmp_path, speed, words):
    p = tmp_path / "g.toml"
    p.write_text(f'kind = "gear pair"\n[teeth]\nmodule = "5 mm"\npressure_angle = "20 deg"\n[pair]\npinion = 20\n'
                 f'gear = 40\nspeed = {speed}\n')
    with pytest.raises(SceneError, match="pair.speed") as e:
        drafting.load(p)
    assert words in str(e.value)
