"""The force gallery scenes through the whole pipeline: the notes' static sample, the bell crank, the notes'
dynamic Examples 2 and 3, and that a scene runs only the analyses its effects call for."""

from __future__ import annotations

import itertools

import pytest

from constructions.entities import Arrow
from drafting.scene.reader import load_scene, parse_scene
from drafting.study.study import Study

from paths import GALLERY


def study(name: str) -> Study:
    return Study(load_scene(GALLERY / name)).run()


def values(s: Study) -> dict:
    return {c.name: c for c in s.comparisons}


def test_static_sample_scene_reproduces_the_notes_and_agrees_three_ways():
    s = study("notes-static-force-sample.toml")
    v = values(s)
    assert v["T_2"].graphical == pytest.approx(-1.12, rel=0.02)            # notes: 1.12 N m
    assert v["F_32"].graphical.norm() == pytest.approx(42.0, rel=0.02)     # notes: F_21 = 42.0 N
    # the crank's bearing force: equal and opposite to the rod's force on the crank (with T, a couple)
    assert v["F_12"].graphical.norm() == pytest.approx(42.0, rel=0.02)
    assert (v["F_12"].graphical + v["F_32"].graphical).norm() < 1e-12 * 42.0
    assert all(c.agrees for c in s.comparisons)
    assert v["T_2 (virtual work)"].analytic == pytest.approx(v["T_2"].graphical, rel=1e-12)
    assert "acceleration" not in s.ran and "velocity" not in s.ran


def test_bell_crank_is_solved_by_concurrency():
    s = study("bell-crank-three-force.toml")
    assert all(c.agrees for c in s.comparisons)
    words = " ".join(st.words for st in s.construction.steps)
    assert "three-force member" in words and "two-force member" in words


def _with(extra: str) -> Study:
    text = (GALLERY / "notes-static-force-sample.toml").read_text() + extra
    return Study(parse_scene(text, GALLERY / "variant.toml")).run()


def test_a_mass_adds_the_acceleration_analysis_and_exactly_its_inertia_force():
    plain = _with("")
    heavy = _with('\n[[mass]]\nlink = 4\nmass = "0.5 kg"\n')
    assert "acceleration" not in plain.ran
    assert "acceleration" in heavy.ran and "velocity" in heavy.ran
    assert heavy.to_json()["forces"]["dynamic"] is True
    a = heavy.computed("acceleration").accelerations["C"]
    # the piston's inertia force -m a_C lies along the guide: it changes the rod's axial load only
    t0, t1 = values(plain)["T_2"].graphical, values(heavy)["T_2"].graphical
    f0, f1 = values(plain)["F_14"].graphical, values(heavy)["F_14"].graphical
    p_eff = 40.0 + 0.5 * a.x            # along -x: P plus the x-part of -m a_C
    assert t1 / t0 == pytest.approx(p_eff / 40.0, rel=1e-9)
    assert f1.y / f0.y == pytest.approx(p_eff / 40.0, rel=1e-9)
    assert all(c.agrees for c in heavy.comparisons)


def test_gravity_changes_only_the_weight_terms():
    g = '\n[gravity]\ng = "9.81 m/s^2"\n'
    m = '\n[[mass]]\nlink = 4\nmass = "2 kg"\n'
    without, with_g = _with(m), _with(m + g)
    d = values(with_g)["F_14"].graphical - values(without)["F_14"].graphical
    assert d.y == pytest.approx(2.0 * 9.81, rel=1e-9) and abs(d.x) < 1e-9     # the weight, square to the guide
    assert values(with_g)["T_2"].graphical == pytest.approx(values(without)["T_2"].graphical, rel=1e-12)


def test_notes_dynamic_example_2_within_drawing_accuracy():
    """The rebuilt scene reproduces the notes' printed answers.  Its data were fitted to those answers and
    rounded (gallery/forces-derivations.md: lengths and input from the kinematics, weights from the force
    sums, I_G2 from F_Cy and I_G1 from T_1), so this checks the rebuild at drawing accuracy; the
    independent check is the agreement of the three methods, and F_O1 and F_B, which no parameter was
    fitted to alone."""
    s = study("notes-dynamic-example-2.toml")
    v = values(s)
    assert all(c.agrees for c in s.comparisons)
    lbf, inch = 4.4482216152605, 0.0254
    assert v["T_1"].graphical / (lbf * inch) == pytest.approx(2.54, rel=0.02)        # CCW
    f01 = v["F_01"].graphical * (1 / lbf)
    assert (f01.x, f01.y) == (pytest.approx(-1.28, rel=0.02), pytest.approx(-0.224, rel=0.03))
    assert v["F_03"].graphical.norm() / lbf == pytest.approx(0.396, rel=0.02)          # the guide: F_N = F_Cy
    f12 = -v["F_21"].graphical * (1 / lbf)                     # the notes' F_B: of link 1 on link 2, at B
    assert (f12.x, f12.y) == (pytest.approx(-1.09, rel=0.02), pytest.approx(-0.018, abs=0.005))
    # the notes print v_C = -14.85 in/s; with their own omega_2 = -2.1 rad/s it is -22.74 in/s
    assert v["V_C"].graphical.x / inch == pytest.approx(-22.74, rel=1e-3)
    assert v["omega_2"].graphical == pytest.approx(-2.1, rel=1e-3)


def test_notes_dynamic_example_3_as_derived():
    """The notes' six-link mechanism with a roller, rebuilt in gallery/forces-derivations.md section 5 (the
    roller as the pin R of link 2 in a slot of the lever 5 mm below it): the derivation's independent 9x9
    Newton-Euler solve printed the values below; here the graphical construction -- the slot's force from the
    moments about O5, the coupler as a three-force member -- the equilibrium system of all links and virtual
    work must give them, and each other to 1e-9."""
    s = study("notes-dynamic-example-3.toml")
    v = values(s)
    assert all(c.agrees for c in s.comparisons)
    assert v["T_1 (virtual work)"].analytic == pytest.approx(v["T_1"].graphical, rel=1e-9)
    for name in ("F_52", "F_05", "F_32", "F_21", "F_01"):
        assert v[name].graphical.distance_to(v[name].analytic) <= 1e-9 * v[name].graphical.norm()
    assert v["omega_2"].graphical == pytest.approx(-2.2767, abs=5e-5)
    assert v["alpha_2"].graphical == pytest.approx(-40.351, abs=5e-4)
    assert v["alpha_5"].graphical == pytest.approx(-71.872, abs=5e-4)       # CW, not the notes' CCW
    f45 = -v["F_52"].graphical                                  # the roller (pin R) on the lever: up
    assert (f45.x, f45.y) == (pytest.approx(0.0, abs=5e-4), pytest.approx(39.713, abs=5e-4))
    f05 = v["F_05"].graphical
    assert (f05.x, f05.y) == (pytest.approx(0.0, abs=5e-4), pytest.approx(-19.713, abs=5e-4))
    f32 = v["F_32"].graphical                                   # link 3 pushes link 2 along 45 deg
    assert f32.norm() == pytest.approx(63.676, abs=5e-4)
    assert f32.x == pytest.approx(f32.y, abs=5e-4) and f32.x > 0
    f12 = -v["F_21"].graphical                                  # the crank on the coupler at A
    assert (f12.x, f12.y) == (pytest.approx(-44.055, abs=5e-4), pytest.approx(-5.939, abs=5e-4))
    assert v["F_01"].graphical.distance_to(f12) < 5e-4         # G1 at O1 does not accelerate: F01 = F12
    assert v["T_1"].graphical == pytest.approx(0.05839, abs=5e-6)   # CCW
    words = " ".join(st.words for st in s.construction.steps)
    assert "Moments about O5 on link 5" in words and "three-force member" in words
    # the lever's forces are all vertical: its polygon's sides are drawn side by side, none on another
    sides = [e for e in s.construction.entities() if isinstance(e, Arrow) and e.diagram.key == "force: link 5"]
    assert len(sides) == 3
    for a, b in itertools.combinations(sides, 2):
        assert abs((b.tail - a.tail).cross((a.tip - a.tail).unit())) > 1.0      # N apart, square to their line
