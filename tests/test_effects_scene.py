"""The effects a scene declares ([gravity], [[load]], [[couple]], [[mass]], [[spring]], [[friction]]) read
into constructions.forces.effects.Effects in SI, and every bad one refused in one sentence naming the file
and the key (README, "Loads, masses, gravity, springs, friction")."""

from __future__ import annotations

import math
import tomllib

import pytest

from constructions.forces import inertia as I
from constructions.forces.effects import NO_EFFECTS, End
from constructions.geometry import Vec
from constructions.mechanisms.assembly import FixedToLink, assembly_plan
from constructions.mechanisms.model import Attached
from constructions.mechanisms.pose import locate
from drafting.app.cli import main
from drafting.study.worked import builtin_example
from drafting.scene.effects import SECTIONS
from drafting.scene.reader import SceneError, load_scene, parse_scene
from drafting.scene.unitset import Units

from paths import ROOT
EXAMPLE = builtin_example().read_text()
# the built-in slider-crank: link 1 O1-B (50 mm), link 2 B-C (94 mm), block 3 at C on the x axis


def scene(extra: str = "", before: str = ""):
    return parse_scene(before + EXAMPLE + "\n" + extra)


def test_a_scene_without_effects_is_as_before():
    s = scene()
    assert s.effects is NO_EFFECTS and s.effects.empty and not s.effects.inertial
    assert s.effects.gravity is None and s.effects.friction == {} and s.effects.fixed == {}
    assert s.mechanism.attached == ()
    for path in sorted((ROOT / "gallery").glob("*.toml")):
        if not SECTIONS & set(tomllib.loads(path.read_text())):
            got = load_scene(path)            # another family's scene has no effects at all
            assert getattr(got, "effects", NO_EFFECTS) is NO_EFFECTS and (got.kind == "linkage") == hasattr(got, "effects"), path


def test_units_know_the_new_kinds():
    u = Units()
    assert (u.force, u.torque, u.mass, u.moment_of_inertia, u.stiffness) == ("N", "N m", "kg", "kg m^2", "N/mm")
    assert u.of("stiffness") == "N/mm" and u.of("moment of inertia") == "kg m^2"
    s = parse_scene(EXAMPLE.replace('angle = "deg"', 'angle = "deg"\nforce = "kN"\ntorque = "N mm"\nmass = "g"\n'
                                    'moment_of_inertia = "kg cm^2"\nstiffness = "N/m"', 1)
                    + '\n[[load]]\nname = "P"\nlink = 3\nat = "C"\nforce = 2\nangle = "90 deg"\n'
                      '[[couple]]\nname = "M"\nlink = 2\ntorque = 300\n'
                      '[[mass]]\nlink = 2\nmass = 500\ninertia = 20\n'
                      '[[spring]]\nname = "S"\nlink = 3\nat = "C"\nanchor = [150, 0]\nstiffness = 40\n'
                      'free_length = 20\n')
    e = s.effects
    assert e.loads[0].force == Vec(0.0, 2000.0)
    assert e.couples[0].torque == pytest.approx(0.3, rel=1e-14)
    assert e.masses[0].mass == pytest.approx(0.5, rel=1e-14)
    assert e.masses[0].inertia == pytest.approx(0.002, rel=1e-14)
    assert e.springs[0].stiffness == pytest.approx(40.0, rel=1e-14)
    assert e.springs[0].free_length == pytest.approx(0.020, rel=1e-14)
    assert s.units.as_dict()["force"] == "kN"


# -- round trips -------------------------------------------------------------------------------------------

def test_gravity():
    assert scene('[gravity]\ng = "9.81 m/s^2"\n').effects.gravity == Vec(0.0, -9.81)
    assert scene('[gravity]\ng = 9810\n').effects.gravity == Vec(0.0, -9.81)       # plain: scene's mm/s^2
    g = scene('[gravity]\ng = "32.174 ft/s^2"\nangle = "-60 deg"\n').effects.gravity
    assert g.norm() == pytest.approx(32.174 * 0.3048, rel=1e-14)
    assert math.degrees(g.angle()) == pytest.approx(-60.0, rel=1e-13)
    assert scene('[gravity]\ng = "9.81 m/s^2"\nangle = "180 deg"\n').effects.gravity == Vec(-9.81, 0.0)
    e = scene('[gravity]\ng = "9.81 m/s^2"\n').effects
    assert e.empty and not e.inertial            # gravity alone loads nothing: no masses


def test_loads():
    e = scene('[[load]]\nname = "P"\nlink = 3\nat = "C"\nforce = "40 N"\nangle = "180 deg"\n'
              '[[load]]\nname = "Q"\nlink = 2\nat = "B"\nforce = "0.1 kN"\nangle = "30 deg"\n').effects
    p, q = e.loads
    assert (p.name, p.body, p.at, p.force) == ("P", 3, "C", Vec(-40.0, 0.0))       # exact along the axes
    assert (q.name, q.body, q.at) == ("Q", 2, "B")
    assert (q.force.x, q.force.y) == pytest.approx((100 * math.cos(math.pi / 6), 50.0), rel=1e-14)
    assert not e.empty and not e.inertial


@pytest.mark.parametrize("text,torque", [
    ('torque = "2 N m"', 2.0),
    ('torque = "-2 N m"', -2.0),
    ('torque = "2 N m"\nsense = "cw"', -2.0),
    ('torque = "-2 N m"\nsense = "cw"', -2.0),
    ('torque = "2000 N mm"\nsense = "ccw"', 2.0),
    ('torque = "3 J"', 3.0),
])
def test_couples(text, torque):
    c = scene(f'[[couple]]\nname = "M2"\nlink = 2\n{text}\n').effects.couples[0]
    assert (c.name, c.body) == ("M2", 2) and c.torque == pytest.approx(torque, rel=1e-14)


def test_mass_default_centres_are_the_middle_of_a_link_and_the_joint_of_a_block():
    s = scene('[[mass]]\nlink = 2\nmass = "0.5 kg"\ninertia = "0.002 kg m^2"\n'
              '[[mass]]\nlink = 3\nmass = "300 g"\n')
    m2, m3 = s.effects.masses
    assert (m2.body, m2.mass, m2.centre, m2.inertia) == (2, 0.5, "G2", 0.002)
    assert (m3.body, m3.centre, m3.inertia) == (3, "C", 0.0) and m3.mass == pytest.approx(0.3, rel=1e-14)
    assert s.mechanism.attached == (Attached("G2", 2, "B", 0.047, 0.0),)
    assert s.effects.mass_of(2) is m2 and s.effects.mass_of(1) is None and s.effects.inertial
    plan = assembly_plan(s.mechanism)
    assert any(isinstance(step, FixedToLink) and step.name == "G2" for step in plan)
    pose = locate(s.mechanism, s.angle, plan)
    mid = (pose["B"] + pose["C"]) * 0.5
    assert pose["G2"].distance_to(mid) < 1e-15


def test_mass_centre_by_distance_and_angle_adds_a_point():
    s = scene('[[mass]]\nlink = 1\nmass = "0.2 kg"\nfrom = "O1"\ndistance = 20\nangle = "10 deg"\n')
    assert s.effects.masses[0].centre == "G1"
    assert s.mechanism.attached == (Attached("G1", 1, "O1", 0.020, math.radians(10)),)
    pose = locate(s.mechanism, s.angle)
    assert pose["G1"].distance_to(pose["O1"]) == pytest.approx(0.020, rel=1e-14)
    assert math.degrees((pose["G1"] - pose["O1"]).angle()) == pytest.approx(80.0, rel=1e-13)


def test_mass_centre_at_an_existing_point():
    s = scene('[[point]]\nname = "D"\nlink = 2\nfrom = "B"\ndistance = 60\nangle = "40 deg"\n'
              '[[mass]]\nlink = 2\nmass = 1\nat = "D"\n'
              '[[mass]]\nlink = 3\nmass = 1\nat = "C"\n')
    assert [x.centre for x in s.effects.masses] == ["D", "C"]
    assert [a.name for a in s.mechanism.attached] == ["D"]          # nothing added


@pytest.mark.parametrize("text,expected", [
    ('shape = "rod"', I.rod(0.5, 0.094)),                              # the link's own length
    ('shape = "rod"\nlength = 100', I.rod(0.5, 0.100)),
    ('shape = "disc"\nradius = 30', I.disc(0.5, 0.030)),
    ('shape = "disk"\nradius = 30', I.disc(0.5, 0.030)),
    ('shape = "plate"\nwidth = 94\nheight = 20', I.plate(0.5, 0.094, 0.020)),
    ('shape = "ring"\ninner_radius = 10\nouter_radius = "3 cm"', I.ring(0.5, 0.010, 0.030)),
    ('shape = "ring"\ninner_radius = 0\nouter_radius = 30', I.disc(0.5, 0.030)),
    ('shape = "thin ring"\nradius = 30', I.thin_ring(0.5, 0.030)),
    ('shape = "semicircular plate"\nradius = 30', I.semicircular_plate(0.5, 0.030)),
    ('inertia = "5000 kg mm^2"', 0.005),
    ('inertia = "5000 kg mm^2"\ninertia_about = "G2"', 0.005),
    # about B, 47 mm from the middle of BC: I_G = I_B - m d^2
    ('inertia = "0.002 kg m^2"\ninertia_about = "B"', 0.002 - 0.5 * 0.047**2),
    ('inertia = "0 kg m^2"', 0.0),
    ('', 0.0),                                                          # a point mass
])
def test_mass_inertia(text, expected):
    got = scene(f'[[mass]]\nlink = 2\nmass = "0.5 kg"\n{text}\n').effects.masses[0].inertia
    assert got == pytest.approx(expected, rel=1e-12, abs=1e-18)


def test_inertia_about_a_point_of_a_block_is_about_its_joint():
    e = scene('[[mass]]\nlink = 3\nmass = 2\ninertia = "0.01 kg m^2"\ninertia_about = "C"\n').effects
    assert e.masses[0].inertia == 0.01


def test_springs():
    e = scene('[[spring]]\nname = "S"\nlink = 3\nat = "C"\nanchor = [120, "4 cm"]\nstiffness = "2 N/mm"\n'
              'free_length = "50 mm"\n'
              '[[spring]]\nname = "T"\nlink = 2\nat = "B"\nanchor = "O1"\nstiffness = "300 N/m"\n'
              'free_length = 0\n'
              '[[spring]]\nname = "U"\nlink = 1\nat = "B"\nto_link = 3\nto = "C"\nstiffness = 1\n'
              'free_length = 80\n').effects
    s, t, u = e.springs
    assert (s.name, s.a, s.b) == ("S", End(3, "C"), End(None, "S anchor"))
    assert s.stiffness == 2000.0 and s.free_length == pytest.approx(0.050, rel=1e-14)
    assert e.fixed["S anchor"] == Vec(0.120, 0.040)
    assert (t.a, t.b, t.stiffness, t.free_length) == (End(2, "B"), End(None, "O1"), 300.0, 0.0)
    assert e.fixed["O1"] == Vec(0.0, 0.0)
    assert (u.a, u.b, u.stiffness) == (End(1, "B"), End(3, "C"), 1000.0)       # plain: N/mm
    assert u.free_length == pytest.approx(0.080, rel=1e-14)
    assert set(e.fixed) == {"S anchor", "O1"} and not e.empty


def test_friction():
    e = scene('[[friction]]\nslider = 3\nmu = 0.15\n').effects
    assert e.friction == {3: 0.15} and e.empty            # friction alone loads nothing
    assert scene('[[friction]]\nslider = 3\nmu = 0\n').effects.friction == {3: 0.0}


def test_everything_together_still_solves(tmp_path, capsys):
    text = EXAMPLE.replace('analyses = ["velocity"]', 'analyses = ["acceleration"]') + """
[gravity]
g = "9.81 m/s^2"

[[load]]
name = "P"
link = 3
at = "C"
force = "40 N"
angle = "180 deg"

[[couple]]
name = "M2"
link = 2
torque = "2 N m"

[[mass]]
link = 2
mass = "0.5 kg"
shape = "rod"

[[mass]]
link = 1
mass = "0.2 kg"
from = "O1"
distance = 20
angle = "10 deg"

[[spring]]
name = "S"
link = 3
at = "C"
anchor = [200, 0]
stiffness = "2 N/mm"
free_length = "50 mm"

[[friction]]
slider = 3
mu = 0.15
"""
    p = tmp_path / "all.toml"
    p.write_text(text)
    s = load_scene(p)
    assert [a.name for a in s.mechanism.attached] == ["G2", "G1"]
    assert len(s.effects.masses) == 2 and s.effects.gravity == Vec(0.0, -9.81)
    assert main(["check", str(p)]) == 0
    out, err = capsys.readouterr()
    assert "V_G2" in out and "A_G1" in out and err == ""


# -- errors ---------------------------------------------------------------------------------------------

LOAD = '[[load]]\nname = "P"\nlink = 3\nat = "C"\nforce = "40 N"\nangle = "180 deg"\n'
MASS = '[[mass]]\nlink = 2\nmass = "0.5 kg"\n'
SPRING = '[[spring]]\nname = "S"\nlink = 3\nat = "C"\nstiffness = "2 N/mm"\nfree_length = 50\n'
COUPLE = '[[couple]]\nname = "M"\nlink = 2\n'

BAD = [
    # (text appended to the scene, key named, words in the message)
    ('[gravity]\ng = "0 m/s^2"\n', "gravity.g", "must be positive"),
    ('[gravity]\ng = "-9.81 m/s^2"\n', "gravity.g", "must be positive"),
    ('[gravity]\ng = "9.81 m/s"\n', "gravity.g", "not a value of acceleration"),
    ('[gravity]\ng = "9.81*2 m/s^2"\n', "gravity.g", "arithmetic is not read"),
    ('[gravity]\nangle = "270 deg"\n', "gravity.g", "is missing"),
    ('[gravity]\ng = "9.81 m/s^2"\ndirection = "down"\n', "gravity.direction", "unknown key"),
    ('[gravity]\ng = "9.81 m/s^2"\nangle = "down"\n', "gravity.angle", "cannot be read"),
    ('[[load]]\nlink = 3\nat = "C"\nforce = "40 N"\nangle = "0 deg"\n', "load[1].name", "is missing"),
    (LOAD.replace("name = \"P\"", "name = \"P 1\""), "load[1].name", "is not a name"),
    (LOAD.replace("link = 3", "link = 9"), "load[1].link", "there is no link or slider block 9"),
    (LOAD.replace("link = 3", "link = 0"), "load[1].link", "whole number from 1"),
    (LOAD.replace("link = 3", "link = 2").replace('at = "C"', 'at = "Z"'), "load[1].at",
     "Z is not a point of link 2 (B-C); its points are B, C"),
    (LOAD.replace('at = "C"', 'at = "B"'), "load[1].at", "a block's only point is its joint C"),
    (LOAD.replace('"40 N"', '"40 N m"'), "load[1].force", "not a value of force"),
    (LOAD.replace('"40 N"', '"-40 N"'), "load[1].force", "give it positive and turn angle"),
    (LOAD.replace('"40 N"', '"1e20 N"'), "load[1].force", "too large"),
    (LOAD.replace('"40 N"', "nan"), "load[1].force", "is not a number"),
    (LOAD.replace('angle = "180 deg"\n', ''), "load[1].angle", "is missing"),
    (LOAD.replace('angle = "180 deg"', 'angle = "180 N"'), "load[1].angle", "not a value of angle"),
    (LOAD + 'at2 = "C"\n', "load[1].at2", "unknown key"),
    (LOAD + LOAD.replace('at = "C"', 'at = "Q"').replace('"P"', '"P2"'), "load[2].at", "not a point"),
    (LOAD + LOAD, "load[2].name", "P is already the name of load[1]"),
    (LOAD + COUPLE.replace('"M"', '"P"') + 'torque = 1\n', "couple[1].name", "already the name of load[1]"),
    (COUPLE + 'torque = "2 N"\n', "couple[1].torque", "not a value of torque"),
    (COUPLE, "couple[1].torque", "is missing"),
    (COUPLE + 'torque = 2\nsense = "up"\n', "couple[1].sense", "must be \"ccw\" or \"cw\""),
    (COUPLE + 'torque = -2\nsense = "ccw"\n', "couple[1].sense", "says ccw but torque"),
    (COUPLE.replace("link = 2", "link = 5") + 'torque = 2\n', "couple[1].link", "no link or slider block 5"),
    (MASS.replace('"0.5 kg"', '"0 kg"'), "mass[1].mass", "must be positive"),
    (MASS.replace('"0.5 kg"', '"-1 kg"'), "mass[1].mass", "must be positive"),
    (MASS.replace('"0.5 kg"', '"0.5 N"'), "mass[1].mass", "not a value of mass"),
    (MASS.replace('"0.5 kg"', 'inf'), "mass[1].mass", "too large"),
    (MASS.replace('"0.5 kg"', 'nan'), "mass[1].mass", "is not a number"),
    ('[[mass]]\nlink = 2\n', "mass[1].mass", "is missing"),
    (MASS + 'centre = "B"\n', "mass[1].centre", "unknown key"),
    (MASS + MASS, "mass[2].link", "link 2 (B-C) already has a mass (mass[1])"),
    (MASS + 'inertia = "-0.1 kg m^2"\n', "mass[1].inertia", "must not be negative"),
    (MASS + 'inertia = "0.1 kg m"\n', "mass[1].inertia", "not a value of moment of inertia"),
    (MASS + 'inertia = 1\nshape = "rod"\n', "mass[1].shape", "not both"),
    (MASS + 'shape = "cone"\n', "mass[1].shape", "'cone' is not a shape; choose from 'rod', 'disc'"),
    (MASS + 'shape = 3\n', "mass[1].shape", "is not a shape"),
    (MASS + 'shape = "disc"\n', "mass[1].radius", "is missing: a disc needs radius"),
    (MASS + 'shape = "plate"\nwidth = 10\n', "mass[1].height", "a plate needs width and height"),
    (MASS + 'shape = "plate"\nradius = 10\n', "mass[1].radius", "is not a dimension of a plate"),
    (MASS + 'radius = 10\n', "mass[1].radius", "give shape too"),
    (MASS + 'shape = "ring"\ninner_radius = 30\nouter_radius = 20\n', "mass[1].inner_radius",
     "30 mm is larger than outer_radius (20 mm)"),
    (MASS + 'shape = "ring"\ninner_radius = -3\nouter_radius = 20\n', "mass[1].inner_radius", "not be negative"),
    (MASS + 'shape = "disc"\nradius = -5\n', "mass[1].radius", "must be positive"),
    (MASS + 'shape = "disc"\nradius = "5 kg"\n', "mass[1].radius", "not a value of length"),
    ('[[mass]]\nlink = 3\nmass = 1\nshape = "rod"\n', "mass[1].length", "a rod needs length"),
    (MASS + 'inertia_about = "B"\n', "mass[1].inertia_about", "needs inertia"),
    (MASS + 'shape = "disc"\nradius = 5\ninertia_about = "B"\n', "mass[1].inertia_about", "not to a shape"),
    (MASS + 'inertia = 1\ninertia_about = "Z"\n', "mass[1].inertia_about", "Z is not a point of link 2"),
    (MASS + 'inertia = "0.001 kg m^2"\ninertia_about = "B"\n', "mass[1].inertia",
     "0.001 kg m² about B is less than m d^2 = 0.001105 kg m² (B is 47 mm from the centre of gravity G2)"),
    (MASS + 'at = "B"\nfrom = "B"\ndistance = 5\n', "mass[1].from", "not both"),
    (MASS + 'distance = 5\n', "mass[1].distance", "give from too"),
    (MASS + 'angle = "5 deg"\n', "mass[1].angle", "give from too"),
    (MASS + 'from = "O1"\ndistance = 5\n', "mass[1].from", "O1 is not a joint of link 2 (B-C)"),
    (MASS + 'from = "B"\n', "mass[1].distance", "is missing"),
    (MASS + 'from = "B"\ndistance = 0\n', "mass[1].distance", "must be positive (a centre of gravity at B"),
    (MASS + 'at = "O1"\n', "mass[1].at", "O1 is not a point of link 2"),
    ('[[mass]]\nlink = 3\nmass = 1\nfrom = "C"\ndistance = 5\n', "mass[1].from", "is its joint C"),
    ('[[mass]]\nlink = 3\nmass = 1\nat = "B"\n', "mass[1].at", "its joint C"),
    ('[[point]]\nname = "G2"\nlink = 1\nfrom = "O1"\ndistance = 10\n' + MASS, "mass[1].at",
     "the centre of gravity (the middle of B-C) would be the new point G2, but G2 is already a point of link 1"),
    ('[[point]]\nname = "G1"\nlink = 1\nfrom = "O1"\ndistance = 10\n'
     '[[mass]]\nlink = 1\nmass = 1\nfrom = "B"\ndistance = 10\n', "mass[1].from",
     "(10 mm from B) would be the new point G1, but G1 is already a point of link 1"),
    (SPRING, "spring[1].anchor", "is missing: give the other end"),
    (SPRING + 'anchor = [0, 0]\nto_link = 2\nto = "B"\n', "spring[1].anchor", "not both"),
    (SPRING + 'to_link = 2\n', "spring[1].to", "is missing"),
    (SPRING + 'to = "B"\n', "spring[1].to_link", "is missing"),
    (SPRING + 'to_link = 3\nto = "C"\n', "spring[1].to_link", "both ends are on block 3"),
    (SPRING + 'to_link = 2\nto = "O1"\n', "spring[1].to", "O1 is not a point of link 2"),
    (SPRING + 'anchor = [1]\n', "spring[1].anchor", "must be a point [x, y]"),
    (SPRING + 'anchor = "Q"\n', "spring[1].anchor", "Q is not a fixed pivot"),
    (SPRING + 'anchor = ["1 kg", 0]\n', "spring[1].anchor", "not a value of length"),
    (SPRING.replace('"2 N/mm"', '"-2 N/mm"') + 'anchor = [0, 0]\n', "spring[1].stiffness", "must be positive"),
    (SPRING.replace('"2 N/mm"', '"2 N"') + 'anchor = [0, 0]\n', "spring[1].stiffness",
     "not a value of stiffness"),
    (SPRING.replace('free_length = 50', 'free_length = -5') + 'anchor = [0, 0]\n', "spring[1].free_length",
     "must not be negative"),
    (SPRING.replace('free_length = 50\n', '') + 'anchor = [0, 0]\n', "spring[1].free_length", "is missing"),
    ('[[friction]]\nslider = 2\nmu = 0.1\n', "friction[1].slider", "link 2 is not a slider block"),
    ('[[friction]]\nslider = 7\nmu = 0.1\n', "friction[1].slider", "there is no slider block 7"),
    ('[[friction]]\nslider = 3\nmu = -0.1\n', "friction[1].mu", "must be a number from 0 to 10"),
    ('[[friction]]\nslider = 3\nmu = 1e300\n', "friction[1].mu", "a friction angle of at most 84 deg"),
    ('[[friction]]\nslider = 3\nmu = inf\n', "friction[1].mu", "must be a number from 0 to 10"),
    ('[[friction]]\nslider = 3\nmu = "0.15"\n', "friction[1].mu", "write a plain number"),
    ('[[friction]]\nslider = 3\nmu = true\n', "friction[1].mu", "write a plain number"),
    ('[[friction]]\nslider = 3\n', "friction[1].mu", "is missing"),
    ('[[friction]]\nslider = 3\nmu = 0.1\n[[friction]]\nslider = 3\nmu = 0.2\n', "friction[2].slider",
     "block 3 already has its friction (friction[1])"),
]


@pytest.mark.parametrize("extra,key,words", BAD)
def test_bad_effects_name_file_and_key(tmp_path, capsys, extra, key, words):
    p = tmp_path / "scene.toml"
    p.write_text(EXAMPLE + "\n" + extra)
    with pytest.raises(SceneError) as e:
        load_scene(p)
    assert e.value.key == key, str(e.value)
    assert str(e.value).startswith(f"{p}: {key}: ") and words in str(e.value), str(e.value)
    code = main(["solve", str(p)])
    out, err = capsys.readouterr()
    assert code == 2 and out == ""
    assert err.count("\n") == 1 and err.startswith(f"drafting: error: {p}: {key}: ") and words in err, err
    assert "Traceback" not in err


@pytest.mark.parametrize("before,key,words", [
    ("gravity = 9.81\n", "gravity", "must be a table"),
    ("mass = 3\n", "mass", "must be written as [[mass]] tables"),
    ("load = {name = \"P\"}\n", "load", "must be written as [[load]] tables"),
])
def test_sections_of_the_wrong_shape(before, key, words):
    with pytest.raises(SceneError) as e:
        scene(before=before)
    assert e.value.key == key and words in str(e.value)


def test_units_keys_are_checked():
    with pytest.raises(SceneError) as e:
        parse_scene(EXAMPLE.replace('angle = "deg"', 'angle = "deg"\nstiffness = "N"', 1))
    assert e.value.key == "units.stiffness" and "not a unit of stiffness" in str(e.value)
    with pytest.raises(SceneError) as e:
        parse_scene(EXAMPLE.replace('angle = "deg"', 'angle = "deg"\nforce = "kg"', 1))
    assert e.value.key == "units.force" and "not a unit of force" in str(e.value)


@pytest.mark.parametrize("section,make,what", [
    ("load", lambda i: LOAD.replace('"P"', f'"P{i}"'), "loads"),
    ("couple", lambda i: COUPLE.replace('"M"', f'"M{i}"') + "torque = 1\n", "couples"),
    ("spring", lambda i: SPRING.replace('"S"', f'"S{i}"') + "anchor = [0, 0]\n", "springs"),
    ("friction", lambda i: "[[friction]]\nslider = 3\nmu = 0.1\n", "friction tables"),
    ("mass", lambda i: MASS, "masses"),
])
def test_counts_are_capped(section, make, what):
    with pytest.raises(SceneError) as e:
        scene("".join(make(i) for i in range(51)))
    assert e.value.key == section and f"51 {what}; a scene may have at most 50" in str(e.value)


def test_centres_of_gravity_count_with_the_points():
    points = "".join(f'[[point]]\nname = "D{i}"\nlink = 2\nfrom = "B"\ndistance = {i + 1}\n' for i in range(50))
    assert len(scene(points + '[[mass]]\nlink = 2\nmass = 1\nat = "D3"\n').mechanism.attached) == 50
    with pytest.raises(SceneError) as e:
        scene(points + MASS)
    assert e.value.key == "mass[1]" and "would be point number 51; a scene may have at most 50 points" \
        in str(e.value)


def test_the_readme_example_reads():
    """The format as README shows it, appended to the built-in slider-crank."""
    readme = (ROOT / "README.md").read_text()
    part = readme.split("### Loads, masses, gravity, springs, friction", 1)[1]
    block = part.split("```toml\n", 1)[1].split("```", 1)[0]
    e = scene(block).effects
    assert e.gravity == Vec(0.0, -9.81)
    assert e.loads[0].force == Vec(-40.0, 0.0) and e.couples[0].torque == 2.0
    assert e.masses[0].centre == "G2" and e.masses[0].inertia == pytest.approx(I.rod(0.5, 0.094), rel=1e-15)
    assert e.springs[0].b == End(None, "S anchor") and e.fixed["S anchor"] == Vec(0.2, 0.0)
    assert e.friction == {3: 0.15}


def test_loads_and_springs_may_act_at_a_centre_of_gravity_the_scene_adds():
    e = scene(MASS + LOAD.replace("link = 3", "link = 2").replace('at = "C"', 'at = "G2"')
              + SPRING.replace("link = 3", "link = 2").replace('at = "C"', 'at = "G2"') + "anchor = [0, 50]\n").effects
    assert e.loads[0].at == "G2" and e.springs[0].a == End(2, "G2")
