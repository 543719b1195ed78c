"""A planetary train with two members driven (a differential, issue 24): the third member's speed by the
tabular method and by the notes' formula (Willis) solved for it, against the closed form
n_C = (N_S n_S + N_R n_R)/(N_S + N_R) and the velocity matching at every planet's pitch points."""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings, strategies as st

import drafting
from constructions.gears.train_check import velocity_check
from constructions.gears.train_drawing import Case, train_analysis
from constructions.gears.trains import Given, Train, TrainGear, TrainMesh, solve_train
from drafting.scene.reader import SceneError

from paths import GALLERY

RPM = 2 * math.pi / 60
DEG = math.pi / 180


def planetary(ns, np_, n=1):
    return Train((TrainGear("S", ns, "S"), TrainGear("P", np_, "P", "C"),
                  TrainGear("R", ns + 2 * np_, "R", internal=True)),
                 (TrainMesh("S", "P"), TrainMesh("P", "R")), 0.003, 20 * DEG, planets=n)


@settings(max_examples=50, deadline=None)
@given(st.integers(12, 50), st.integers(12, 50), st.floats(-3000, 3000), st.floats(-3000, 3000),
       st.sampled_from([("S", "R"), ("S", "C"), ("C", "R")]))
def test_any_two_members_driven_give_the_third_by_the_closed_form(ns, np_, a, b, pair):
    """n_C (N_S + N_R) = N_S n_S + N_R n_R whichever two are given; the planet by n_P - n_C =
    -(N_S/N_P)(n_S - n_C)."""
    t = planetary(ns, np_)
    nr = ns + 2 * np_
    givens = (Given(pair[0], a * RPM), Given(pair[1], b * RPM))
    sol = solve_train(t, givens)
    n = sol.speeds
    scale = (abs(a) + abs(b) + 1) * RPM * (1 + nr / ns)
    assert n["C"] * (ns + nr) == pytest.approx(ns * n["S"] + nr * n["R"], abs=1e-9 * scale * nr)
    assert n["P"] - n["C"] == pytest.approx(-ns / np_ * (n["S"] - n["C"]), abs=1e-9 * scale * ns)
    speeds, rank, res = velocity_check(t, givens)
    assert rank == 4
    for m in t.members:
        assert speeds[m] == pytest.approx(n[m], abs=1e-9 * scale)


def test_the_willis_step_solves_for_the_third_member():
    t = planetary(24, 18)
    a = train_analysis(t, (Case("diff", (Given("R", -300 * RPM), Given("S", 1200 * RPM))),))
    step = [s for s in a.construction.steps if "differential" in s.caption]
    assert len(step) == 1
    assert "n_c = (n_R \u2212 e n_S)/(1 \u2212 e)" in step[0].caption          # minus signs, not hyphens
    assert dict(step[0].values)["out"].value == pytest.approx((24 * 1200 - 60 * 300) / 84 * RPM, rel=1e-12)


def test_the_gallery_differential():
    """Sun 1200 rpm CCW, ring 300 rpm CW: n_C = (24 x 1200 - 60 x 300)/84 = 128.571 rpm CCW, the planet
    1300 rpm CW; graphical = analytic to 1e-9; the table on the sheet."""
    study = drafting.load(GALLERY / "planetary-differential.toml")
    res = study.results
    assert res["omega_C"].graphical == pytest.approx(10800 / 84 * RPM, rel=1e-12)
    assert res["omega_P"].graphical == pytest.approx(-1300 * RPM, rel=1e-12)
    for q in res.values():
        assert abs(q.graphical - q.analytic) <= 1e-9 * max(1.0, abs(q.analytic))
    assert any(s.table for s in study.construction.steps)


BASE = """kind = "gear train"
[teeth]
module = "3 mm"
pressure_angle = "20 deg"
[[gear]]
name = "S"
teeth = 24
[[gear]]
name = "P"
teeth = 18
carrier = "C"
[[gear]]
name = "R"
teeth = 60
internal = true
[[mesh]]
gears = ["S", "P"]
[[mesh]]
gears = ["P", "R"]
[[case]]
driven = "S"
speed = "1200 rpm"
"""


@pytest.mark.parametrize("extra, key, words", [
    ('driven2 = "R"\n', "case[1].speed2", "is missing"),
    ('speed2 = "5 rpm"\n', "case[1].driven2", "is missing: speed2 belongs"),
    ('driven2 = "S"\nspeed2 = "5 rpm"\n', "case[1].driven2", "already the driven member"),
    ('driven2 = "R"\nspeed2 = "5 rpm"\nheld = "C"\n', "case[1].driven2", "not both"),
    ('driven2 = "R"\nspeed2 = "5 rpm"\npower = "1 kW"\noutput = "C"\n', "case[1].power", "speeds only"),
    ('driven2 = "R"\nspeed2 = "5 rpm"\nsense2 = "up"\n', "case[1].sense2", "must be"),
    ("", "case[1].held", "drive a second one"),
])
def test_a_differential_case_is_refused_in_one_sentence_naming_the_key(tmp_path, extra, key, words):
    p = tmp_path / "d.toml"
    p.write_text(BASE + extra)
    with pytest.raises(SceneError) as e:
        drafting.load(p)
    assert e.value.key == key and words in e.value.problem
