"""Planets counted (issue 24): n planets share the load (W_t per planet = T_S / (n r_S)), the assembly
condition (N_S + N_R)/n whole and the neighbours' clearance 2 (r_S + r_P) sin(pi/n) > d_aP, each against
its closed form, and the velocity and equilibrium systems written at all n planets."""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings, strategies as st

from constructions.gears.planets import assembling_counts, check_planets, planet_refusal
from constructions.gears.train_check import torque_check, velocity_check
from constructions.gears.trains import Given, Train, TrainGear, TrainMesh, solve_train
from drafting.scene.reader import SceneError

import drafting
from paths import GALLERY

RPM = 2 * math.pi / 60
DEG = math.pi / 180


def planetary(ns, np_, nr, n, module=0.003):
    return Train((TrainGear("S", ns, "S"), TrainGear("P", np_, "P", "C"), TrainGear("R", nr, "R", internal=True)),
                 (TrainMesh("S", "P"), TrainMesh("P", "R")), module, 20 * DEG, planets=n)


@settings(max_examples=40, deadline=None)
@given(st.integers(12, 40), st.integers(12, 40), st.sampled_from([1, 2, 3, 4, 5]),
       st.sampled_from(["R", "C", "S"]), st.floats(200, 3000), st.floats(100, 20e3))
def test_the_load_per_planet_is_the_sun_torque_over_n_sun_radius(ns, np_, n, held, rpm, power):
    """W_t per planet = |T_S| / (n r_S) by the balance of power (the construction) and by the equilibrium of
    every member with n planets each carrying the same force (the check); the speeds alike with the
    velocity-matching equations written at every planet."""
    t = planetary(ns, np_, ns + 2 * np_, n)
    driven, out = {"R": ("S", "C"), "C": ("S", "R"), "S": ("C", "R")}[held]
    sol = solve_train(t, (Given(held, 0.0), Given(driven, rpm * RPM)), power=power, inp=driven, out=out)
    r_s = t.module * ns / 2
    per_planet = abs(sol.torques["S"]) / (n * r_s)
    assert sol.loads["S-P"] == pytest.approx(per_planet, rel=1e-12)
    assert sol.loads["P-R"] == pytest.approx(per_planet, rel=1e-12)
    speeds, rank, res = velocity_check(t, (Given(held, 0.0), Given(driven, rpm * RPM)))
    assert rank == len(t.members) and res < 1e-9 * rpm
    for m in t.members:
        assert speeds[m] == pytest.approx(sol.speeds[m], rel=1e-9, abs=1e-9 * rpm)
    loads, torques = torque_check(t, speeds, power, driven, out, (held,))
    assert loads["S-P"] == pytest.approx(per_planet, rel=1e-9)
    assert loads["P-R"] == pytest.approx(per_planet, rel=1e-9)
    for m in t.members:
        assert torques[m] == pytest.approx(sol.torques[m], rel=1e-9, abs=1e-9 * abs(sol.torques["S"]))


@pytest.mark.parametrize("ns, np_, n, whole", [(24, 18, 3, True), (24, 18, 4, True), (24, 18, 5, False),
                                              (20, 30, 4, True), (20, 30, 3, False), (21, 21, 3, True)])
def test_the_assembly_condition(ns, np_, n, whole):
    nr = ns + 2 * np_
    pc = check_planets(planetary(ns, np_, nr, n))
    assert pc.assembly_value == pytest.approx((ns + nr) / n, rel=1e-15)
    assert pc.assembles is whole
    assert ((ns + nr) % n == 0) is whole
    assert n in assembling_counts(ns, nr) if whole else n not in assembling_counts(ns, nr)


@pytest.mark.parametrize("ns, np_, n", [(24, 18, 3), (24, 18, 6), (12, 40, 3), (16, 40, 4), (20, 20, 5)])
def test_neighbouring_planets_clear_by_the_closed_form(ns, np_, n):
    """2 (r_S + r_P) sin(pi/n) against d_aP = (N_P + 2) m, full depth."""
    m = 0.003
    pc = check_planets(planetary(ns, np_, ns + 2 * np_, n, m))
    spacing = m * (ns + np_) * math.sin(math.pi / n)
    assert pc.centre_spacing == pytest.approx(spacing, rel=1e-14)
    assert pc.tip_diameter == pytest.approx((np_ + 2) * m, rel=1e-14)
    assert pc.clear is (spacing > (np_ + 2) * m)


def test_large_planets_clear_or_not_as_the_closed_form_says():
    """12-tooth sun, 40-tooth planets: spacing 52 m sin(60) = 45.03 m > 42 m for three; for four
    52 m sin 45 = 36.77 m < 42 m: they touch, and the refusal says so in one sentence."""
    assert check_planets(planetary(12, 40, 92, 3)).clear
    why = planet_refusal(planetary(12, 40, 92, 4))
    assert why.startswith("4 planets touch") and "126 mm" in why and why.count(".") <= 2


def test_a_count_that_does_not_assemble_is_refused_naming_the_counts_that_do():
    why = planet_refusal(planetary(20, 30, 80, 3))
    assert "(N_S + N_R)/n = (20 + 80)/3 = 33.33 is not a whole number" in why
    assert "take 2, 4, 5, 10 planets" in why


def scene(planets, ns=24, np_=18):
    return f"""kind = "gear train"
[teeth]
module = "3 mm"
pressure_angle = "20 deg"
[[gear]]
name = "S"
teeth = {ns}
[[gear]]
name = "P"
teeth = {np_}
carrier = "C"
[[gear]]
name = "R"
teeth = {ns + 2 * np_}
internal = true
[[mesh]]
gears = ["S", "P"]
[[mesh]]
gears = ["P", "R"]
[train]
planets = {planets}
[[case]]
held = "R"
driven = "S"
speed = "1500 rpm"
"""


@pytest.mark.parametrize("planets, words", [(5, "5 planets cannot be spaced equally"), (0, "from 1 to 24"),
                                            ("3", "from 1 to 24")])
def test_the_scene_refuses_planets_in_one_sentence_naming_the_key(tmp_path, planets, words):
    p = tmp_path / "p.toml"
    p.write_text(scene(f'"{planets}"' if isinstance(planets, str) else planets))
    with pytest.raises(SceneError, match="train.planets") as e:
        drafting.load(p)
    assert words in str(e.value)


def test_the_gallery_planetary_with_three_planets():
    """Ring held, sun in at 1500 rpm with 7.5 kW: n_C = 1500 x 24/84 = 428.57 rpm; T_S = 47.746 N m;
    442.09 N per planet at both meshes; graphical = analytic to 1e-9; the JSON states the conditions."""
    study = drafting.load(GALLERY / "planetary-three-planets.toml")
    res = study.results
    w_s = 1500 * RPM
    assert res["omega_C"].graphical == pytest.approx(w_s * 24 / 84, rel=1e-12)
    t_s = 7500 / w_s
    assert res["T_S"].graphical == pytest.approx(t_s, rel=1e-12)
    for mesh in ("S-P", "P-R"):
        q = res[f"W_t {mesh} per planet"]
        assert q.graphical == pytest.approx(t_s / (3 * 0.036), rel=1e-12)
    for q in res.values():
        assert abs(q.graphical - q.analytic) <= 1e-9 * max(1.0, abs(q.analytic))
    words = " ".join(s.caption for s in study.construction.steps)
    assert "(N_S + N_R)/n = (24 + 60)/3 = 28, a whole number" in words
    assert "1/3 of the load" in words


def test_planets_on_an_ordinary_train_are_refused_naming_the_key(tmp_path):
    p = tmp_path / "o.toml"
    p.write_text('kind = "gear train"\n[teeth]\nmodule = "3 mm"\npressure_angle = "20 deg"\n[[gear]]\nname = "1"\n'
                 'teeth = 20\n[[gear]]\nname = "2"\nteeth = 40\n[[mesh]]\ngears = ["1", "2"]\n[train]\nplanets = 3\n'
                 '[[case]]\ndriven = "1"\nspeed = "100 rpm"\n')
    with pytest.raises(SceneError) as e:
        drafting.load(p)
    assert e.value.key == "train.planets" and "no planets" in e.value.problem


def test_compound_planets_are_refused_as_not_a_simple_planetary():
    t = Train((TrainGear("S", 20, "S"), TrainGear("P", 30, "P", "C"), TrainGear("Q", 20, "P", "C"),
               TrainGear("R", 70, "R", internal=True)),
              (TrainMesh("S", "P"), TrainMesh("Q", "R")), 0.003, 20 * DEG, planets=3)
    assert check_planets(t) is None
    assert planet_refusal(t).startswith("3 planets need a simple planetary train")
