"""The gear families through scene files and the CLI: the gallery's numbers, JSON, laziness, the sheets'
labels, and bad input as one sentence naming the file and the key (drafting/gear_scene, gear_family)."""

from __future__ import annotations

from importlib.metadata import entry_points
import json
import math

import pytest

from drafting.app.cli import main
from drafting.families.registry import GROUP, family
from drafting.scene.reader import load_scene
from drafting.study.study import Study
from drafting.study.worked import sheets_for

from paths import GALLERY
PAIR = GALLERY / "gear-pair-20-40.toml"
RACK = GALLERY / "gear-rack-interference-limit.toml"
THREE = GALLERY / "gear-train-three-gears.toml"
PLANETARY = GALLERY / "planetary-each-member-held.toml"


def test_families_are_registered_from_their_own_module():
    names = {ep.value for ep in entry_points(group=GROUP)}
    assert {"drafting.families.gear.family:GEAR_PAIR", "drafting.families.gear.family:GEAR_TRAIN"} <= names
    assert family("gear pair").kind == "gear pair" and family("gear train").kind == "gear train"


def test_the_20_40_pair_scene_agrees_and_reads_its_contact_ratio(capsys):
    study = Study(load_scene(PAIR))
    assert not study.disagreements() and study.model
    r = study.results
    assert r["AP"].graphical == pytest.approx(0.0126464, abs=1e-7) and r["PB"].graphical == pytest.approx(0.0114900, abs=1e-7)
    assert main(["solve", str(PAIR), "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    cr = data["contact"]["contact_ratio"]
    assert abs(cr["drawn"] - cr["closed_form"]) <= 1e-9 * cr["closed_form"] and cr["drawn"] == pytest.approx(1.6352, abs=1e-4)
    assert data["contact"]["interference"]["verdict"] == "clear"
    assert data["interference_limits"] == {"pinion_with_rack": 18, "equal_gears": 13, "max_gear_for_pinion": None,
                                           "pinion_with_this_gear": 15}
    assert data["gears"]["1"]["pitch_radius"] == pytest.approx(50.0) and data["gears"]["2"]["base_radius"] == pytest.approx(93.969, abs=1e-3)
    assert data["analyses"] == ["contact geometry"]
    # the contact ratio is a results row of its own: a plain number beside its closed form
    # the textbook's contact ratio of a standard pair (module 5, 20 deg, addendum one module), written out
    m, phi = 0.005, math.radians(20.0)
    r1, r2 = 20 * m / 2, 40 * m / 2
    path = (math.sqrt((r1 + m) ** 2 - (r1 * math.cos(phi)) ** 2) + math.sqrt((r2 + m) ** 2 - (r2 * math.cos(phi)) ** 2)
            - (r1 + r2) * math.sin(phi))
    assert r["C.R."].graphical == pytest.approx(path / (math.pi * m * math.cos(phi)), rel=1e-12)
    assert abs(r["C.R."].graphical - r["C.R."].analytic) <= 1e-9 * r["C.R."].analytic
    row = next(t for t in study.table().text if t[0] == "C.R.")
    assert row[1:3] == ("1.635", "1.635") and not row[3].endswith(" ")


def test_the_rack_scene_is_at_the_limit_without_a_warning():
    study = Study(load_scene(RACK))
    assert not study.warnings and any("at the limit" in n for n in study.notes)
    r = study.results
    assert r["AP"].graphical == pytest.approx(r["PT_1"].graphical, rel=1e-12) == pytest.approx(0.02, rel=1e-12)


def test_the_pair_sheet_draws_the_notes_labels():
    study = Study(load_scene(PAIR))
    sheets = sheets_for(study)
    text = " ".join(str(c) for s in sheets for c in s.commands)
    for label in ("T1", "T2", "line of action", "AP", "PB", "\u03c6"):
        assert label in text, label


def test_the_three_gear_scene_numbers():
    study = Study(load_scene(THREE))
    assert not study.disagreements()
    r = study.results
    rpm = 2 * math.pi / 60
    assert r["omega_2"].graphical / rpm == pytest.approx(777.78, abs=0.01)
    assert r["omega_3"].graphical / rpm == pytest.approx(-583.33, abs=0.01)
    assert r["W_t 1-2"].graphical == pytest.approx(1637.0, abs=0.05) == r["W_t 2-3"].graphical
    assert r["T_1"].graphical == pytest.approx(-286.48, abs=0.01) and r["T_3"].graphical == pytest.approx(491.1, abs=0.05)


def test_the_planetary_scene_each_member_held():
    study = Study(load_scene(PLANETARY))
    assert not study.disagreements()
    r = study.results
    assert r["omega_R (carrier held)"].graphical / r["omega_S (carrier held)"].graphical == pytest.approx(-0.25, rel=1e-12)
    assert r["omega_R (sun held)"].graphical / r["omega_C (sun held)"].graphical == pytest.approx(1.25, rel=1e-12)
    assert r["omega_S (ring held)"].graphical / r["omega_C (ring held)"].graphical == pytest.approx(5.0, rel=1e-12)
    assert r["W_t S-P (ring held)"].graphical == pytest.approx(477.46, abs=0.01)


PAIR_TEXT = PAIR.read_text()
TRAIN_TEXT = THREE.read_text()

BAD = [
    (PAIR_TEXT, 'module = "5 mm"', 'module = "5 kg"', "teeth.module", "not a value of length"),
    (PAIR_TEXT, 'module = "5 mm"', 'module = "5 mm"\ndiametral_pitch = 5', "teeth.module", "one of them"),
    (PAIR_TEXT, "pinion = 20", "pinion = 2", "pair.pinion", "whole number of teeth from 3"),
    (PAIR_TEXT, "gear = 40", "gear = 12", "pair.gear", "fewer than the pinion's 20"),
    (PAIR_TEXT, "gear = 40", 'gear = 40\ncentre_distance = "140 mm"', "pair.centre_distance", "jam"),
    (PAIR_TEXT, 'system = "full depth"', 'system = "deep"', "teeth.system", "full depth"),
    (PAIR_TEXT, 'pressure_angle = "20 deg"', 'pressure_angle = "60 deg"', "teeth.pressure_angle", "between 5 and 40"),
    (TRAIN_TEXT, 'gears = ["2", "3"]', 'gears = ["2", "9"]', "mesh[2].gears", "9 is not a gear"),
    (TRAIN_TEXT, 'gears = ["2", "3"]', 'gears = ["2", "3"]\n\n[[mesh]]\ngears = ["2", "3"]', "mesh[3].gears",
     "gears 2 and 3 already mesh in mesh[2]"),
    (TRAIN_TEXT, 'gears = ["2", "3"]', 'gears = ["2", "3"]\n\n[[mesh]]\ngears = ["3", "2"]', "mesh[3].gears",
     "gears 3 and 2 already mesh in mesh[2]"),
    (TRAIN_TEXT, 'power = "30 kW"', 'power = "30 N"', "case[1].power", "not a value of power"),
    (TRAIN_TEXT, 'output = "3"', 'output = "1"', "case[1].output", "driven or the held"),
    (TRAIN_TEXT, 'driven = "1"', 'driven = "1"\nheld = "2"', "case[1].held", "one degree of freedom"),
    (TRAIN_TEXT, "teeth = 60", "teeth = 60\nspeed = 3", "gear[3].speed", "unknown key"),
    (PAIR_TEXT, 'system = "full depth"', 'system = "full depth"\ncutter_tip = 0.6', "teeth.cutter_tip",
     "from 0 to 0.472 (the most its tooth holds"),
    (PAIR_TEXT, 'system = "full depth"', 'system = "full depth"\ncutter_tip = "1 mm"', "teeth.cutter_tip",
     "tip radius of the rack cutter in modules"),
]


@pytest.mark.parametrize("text,old,new,key,words", BAD)
def test_bad_gear_scene_is_one_sentence_with_file_and_key(tmp_path, capsys, text, old, new, key, words):
    assert old in text
    p = tmp_path / "gears.toml"
    p.write_text(text.replace(old, new, 1))
    code = main(["check", str(p)])
    err = capsys.readouterr().err
    assert code == 2 and err.count("\n") == 1 and "Traceback" not in err, err
    assert str(p) in err and f": {key}: " in err and words in err, err


def test_a_planet_that_does_not_fit_is_named(tmp_path, capsys):
    p = tmp_path / "planet.toml"
    p.write_text(PLANETARY.read_text().replace("teeth = 80", "teeth = 82", 1))
    assert main(["check", str(p)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and ": mesh: " in err and "N_ring = N_sun + 2 N_planet" in err, err


def test_an_internal_pair_scene_reads_and_agrees(tmp_path):
    p = tmp_path / "ring.toml"
    p.write_text(PAIR_TEXT.replace("pinion = 20\ngear = 40", "pinion = 18\ngear = 72\ninternal = true"))
    study = Study(load_scene(p))
    assert not study.disagreements() and study.results["AP"].analytic is not None
    assert "PT_2" not in study.results                   # no interference point on the recess side
    # 18 in a 72-tooth ring, full depth 20 deg: O2T1 > r2 - a; said once, where contact leaves the involutes
    said = [n for n in study.notes + study.warnings if n.startswith("Interference: ")]
    assert len(said) == 1 and said[0].startswith("Interference: contact starts before T1") and said[0] in study.warnings


def test_the_reverted_reducer_scene():
    """Derived in the scene's header: n_c = 1500 (20/60)(25/55) rpm; W_t = 1061.0 and 2546.5 N; none on b."""
    study = Study(load_scene(GALLERY / "gear-train-reverted-reducer.toml"))
    assert not study.disagreements()
    r = study.results
    rpm = 2 * math.pi / 60
    assert r["omega_c"].graphical / rpm == pytest.approx(1500 * 20 / 60 * 25 / 55, rel=1e-12)
    assert r["W_t 1-2"].graphical == pytest.approx(5000 / (1500 * rpm * 0.03), rel=1e-12)
    assert r["W_t 3-4"].graphical * 0.0375 == pytest.approx(r["W_t 1-2"].graphical * 0.09, rel=1e-12)
    assert r["T_b"].graphical == 0.0


def test_a_reverted_train_whose_stages_differ_is_named(tmp_path, capsys):
    p = tmp_path / "rev.toml"
    p.write_text((GALLERY / "gear-train-reverted-reducer.toml").read_text().replace("teeth = 55", "teeth = 54"))
    assert main(["check", str(p)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and ": train.coaxial: " in err and "must be coaxial" in err, err


def test_a_stated_cutter_tip_is_the_one_the_teeth_are_generated_with(tmp_path):
    """[teeth] cutter_tip states the rack cutter's tip radius in modules: a sharp-cornered cutter (0)
    undercuts the 20-tooth pinion of the 20/40 pair, which the basic rack's 0.38 m round does not; the
    sheet says so with that radius."""
    from drafting.scene.reader import load_scene
    from drafting.study.study import Study
    assert not any("undercut" in st.words for st in Study(load_scene(PAIR)).run().construction.steps)
    p = tmp_path / "sharp.toml"
    p.write_text(PAIR_TEXT.replace('system = "full depth"', 'system = "full depth"\ncutter_tip = 0', 1))
    study = Study(load_scene(p)).run()
    step = next(st for st in study.construction.steps if "undercut" in st.words)
    assert "gear 1" in step.words and step.value("rho").value == 0.0
    assert step.value("hs").value == pytest.approx(1.25 * 0.005, rel=1e-12)
    assert not any("gear 2" in st.words and "undercut" in st.words for st in study.construction.steps)
