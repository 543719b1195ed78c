"""The free-body family: one rigid body held by supports, solved by Culmann's method (or three-force
concurrency) and checked against its three equations of equilibrium -- the notes' front-end loader through
the whole pipeline, random bodies, improperly constrained and indeterminate bodies, and bad scenes."""

from __future__ import annotations

from importlib.metadata import entry_points
import json
import math

import numpy as np

import pytest
from hypothesis import HealthCheck, assume, given, settings, strategies as st

from constructions.entities import Role, TrialLine
from constructions.errors import ConstructionError
from constructions.forces.effects import Couple, Load
from constructions.forces.free_body import free_body_analysis
from constructions.forces.rigid_body import (ImproperlyConstrained, RigidBody, StaticallyIndeterminate, Support,
                                             check_supports)
from constructions.forces.free_body_check import equilibrium_matrix, equilibrium_solution
from constructions.geometry import Vec
from drafting.app.cli import main
from drafting.families.registry import GROUP, family
from drafting.scene.reader import SceneError, load_scene, parse_scene
from drafting.study.study import Study
from drafting.study.worked import sheets_for

from paths import GALLERY
LOADER = GALLERY / "notes-front-end-loader.toml"
AGREE = 1e-9


def _deg(a: float) -> Vec:
    return Vec(math.cos(math.radians(a)), math.sin(math.radians(a)))


def _loader_by_hand() -> tuple[float, float, float]:
    """F_c, F_12, F_32 (signed along 57, 38 and 20 deg: positive pushes) from the derivation's lines alone,
    by Ritter's method: moments about the meeting point of two members' lines give the third's force."""
    O, E, D, Q = Vec(0.0, 0.0), Vec(0.0, -0.71), Vec(0.22, -0.90), Vec(2.84, -0.5)
    P = Vec(0.0, -2000.0)
    lines = {"c": (D, _deg(57)), "12": (O, _deg(38)), "32": (E, _deg(20))}

    def meet(a, b):
        (p, u), (q, v) = lines[a], lines[b]
        return p + u * ((q - p).cross(v) / u.cross(v))

    out = {}
    for third, (a, b) in (("c", ("12", "32")), ("12", ("32", "c")), ("32", ("12", "c"))):
        X = meet(a, b)
        p, u = lines[third]
        out[third] = -(Q - X).cross(P) / (p - X).cross(u)
    return out["c"], out["12"], out["32"]


# -- the notes' front-end loader --------------------------------------------------------------------------

def test_loader_scene_gives_the_cylinder_force_of_the_derivation_and_the_notes():
    study = Study(load_scene(LOADER)).run()
    rows = {c.name: c for c in study.comparisons}
    f_c, f_12, f_32 = _loader_by_hand()
    assert f_c == pytest.approx(6593.1, abs=0.05) and f_12 == pytest.approx(-6758.4, abs=0.05)
    assert f_32 == pytest.approx(1846.2, abs=0.05)
    got = study.get("forces")
    assert got.method == "Culmann"
    # the scene's frame points are written to 1e-6 mm: 1e-4 relative against the hand computation
    assert got.axial("F_c") == pytest.approx(f_c, rel=1e-4)
    assert got.axial("F_12") == pytest.approx(f_12, rel=1e-4)
    assert got.axial("F_32") == pytest.approx(f_32, rel=1e-4)
    assert rows["F_c"].graphical.norm() == pytest.approx(6595.0, rel=1e-3)          # the notes' answer
    assert rows["F_12"].graphical.norm() == pytest.approx(6758.0, rel=1e-3)
    # graphical = the linear equilibrium system to 1e-9, relative to the largest force
    assert set(rows) == {"F_12", "F_32", "F_c"} and study.model is not None
    assert all(c.analytic is not None and c.relative <= AGREE and c.agrees for c in rows.values())
    notes = " ".join(study.notes)
    assert "Member 1 (G1O, F_12): 6758 N tension" in notes
    assert "Member 3 (G3E, F_32): 1846 N compression" in notes
    assert "The cylinder (GcD, F_c): 6593 N compression" in notes
    assert not study.warnings


def test_the_notes_6595_comes_from_their_three_digit_equations():
    """The notes' printed equations (cosines to three digits) give 6595 N; exact ones give 6593.1 N."""
    rounded = np.array([[0.545, 0.788, 0.940], [0.839, 0.616, 0.342], [-0.675, 0.0, -0.667]])
    f_c, f_12, f_32 = np.linalg.solve(rounded, [0.0, 2000.0, -5680.0])
    assert round(f_c) == 6595 and round(f_12) == -6758 and round(f_32) == 1842
    assert _loader_by_hand()[0] == pytest.approx(f_c, rel=1e-3)


def test_loader_runs_lazily_and_its_json_names_members_states():
    study = Study(load_scene(LOADER))
    assert study.ran == []
    data = study.to_json()
    assert data["kind"] == "free body"
    assert study.ran == ["force polygon", "equilibrium system"]
    fb = data["free_body"]
    assert fb["method"] == "Culmann" and set(fb["construction_points"]) == {"K", "L"}
    c = fb["supports"]["F_c"]
    assert c["type"] == "member" and c["to"] == "Gc" and c["label"] == "the cylinder"
    assert c["state"] == "compression" and c["axial"]["unit"] == "N"
    assert c["axial"]["value"] == pytest.approx(6593.1, rel=1e-4)
    assert fb["supports"]["F_12"]["state"] == "tension"
    assert fb["supports"]["F_12"]["force"]["angle_deg"] == pytest.approx(218.0, abs=1e-6)
    assert data["check"]["agrees"] is True


def test_solve_json_through_the_cli(capsys):
    assert main(["solve", str(LOADER), "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["analyses"] == ["force polygon", "equilibrium system"]
    assert data["free_body"]["supports"]["F_32"]["state"] == "compression"
    assert data["loads"]["P"]["magnitude"] == pytest.approx(2000.0) and data["check"]["agrees"]


def test_loader_sheet_draws_the_culmann_construction():
    study = Study(load_scene(LOADER)).run()
    sheets = sheets_for(study)
    assert len(sheets) == 1
    words = " ".join("".join(s.text for s in t.spans) for sh in sheets for t in sh.texts())
    for label in ("Space diagram", "Force polygon", "Results", "Vector equations", "Culmann", "K", "L",
                  "\u2225 KL", "tension", "compression"):
        assert label in words, label
    culmann = [c for c in sheets[0].commands if c.name in ("Culmann line", "polygon line a 2")]
    assert len(culmann) == 2 and all(c.style == "hidden" for c in culmann)        # dashed, both diagrams
    rec = study.construction
    lines = [e for e in rec.entities() if isinstance(e, TrialLine) and e.role is Role.AUXILIARY]
    assert {e.name for e in lines} == {"Culmann line", "polygon line a 2"}
    eqs = [str(e) for e in rec.equations]
    assert eqs == ["R(\u2713\u2713) + F_32(\u00d7\u2713) + F_KL(\u00d7\u2713) = 0",
                   "F_KL(\u2713\u2713) = F_12(\u00d7\u2713) + F_c(\u00d7\u2713)"]


def test_family_is_registered_from_its_own_module():
    assert "drafting.families.free_body.family:FREE_BODY" in {ep.value for ep in entry_points(group=GROUP)}
    assert family("free body").askable == ("forces",)
    assert family("linkage").kind == "linkage"


# -- random bodies ----------------------------------------------------------------------------------------

COND_MAX = 1e4
"""Bodies whose scaled equilibrium matrix (rows: force sums, moment over the body's size) has a 2-norm
condition number above this are near an improper constraint (lines nearly concurrent or parallel) and
are skipped; below it the construction and the linear system agree to 1e-9."""

coord = st.integers(-1000, 1000).map(lambda i: i / 1000)     # metres on a 1 mm grid: exact coincidences,
far = st.integers(-2000, 2000).map(lambda i: i / 1000)       # lines and parallels occur, no 1e-185 m gaps
angle = st.floats(0.0, 2 * math.pi, allow_nan=False)
magnitude = st.floats(0.01, 1000.0, allow_nan=False)


@st.composite
def bodies(draw, supports: str = "members"):
    n = draw(st.integers(2, 5))
    pts = {f"P{i}": Vec(draw(coord), draw(coord)) for i in range(n)}
    names = list(pts)
    fixed = {}
    if supports == "members":
        sup = []
        for i in range(3):
            fixed[f"G{i}"] = Vec(draw(far), draw(far))
            sup.append(Support(f"F_{i}", "member", draw(st.sampled_from(names)), f"G{i}"))
        sup = tuple(sup)
    else:
        kind = draw(st.sampled_from(("roller", "guide", "member")))
        at = draw(st.sampled_from(names))
        if kind == "member":
            fixed["G0"] = Vec(draw(far), draw(far))
            other = Support("F_b", "member", at, "G0")
        else:
            other = Support("F_b", kind, at, direction=Vec.polar(1.0, draw(angle)))
        sup = (Support("F_a", "pin", draw(st.sampled_from(names))), other)
    loads = tuple(Load(f"P_{i}", 0, draw(st.sampled_from(names)), Vec.polar(draw(magnitude), draw(angle)))
                  for i in range(draw(st.integers(1, 3))))
    couples = (Couple("C", 0, draw(st.floats(-500.0, 500.0))),) if draw(st.booleans()) else ()
    return RigidBody("body", pts, sup, loads, couples, fixed)


def _agrees(body: RigidBody) -> None:
    try:
        A, _, _ = equilibrium_matrix(body)
        cond = np.linalg.cond(A)
    except (ConstructionError, ValueError, ZeroDivisionError):   # coincident points: a member of zero length
        assume(False)
    assume(cond < COND_MAX)
    got = free_body_analysis(body)
    ref = equilibrium_solution(body)
    big = max(f.norm() for f in ref.forces.values())
    assume(big > 0)
    for name, f in ref.forces.items():
        assert (got.forces[name] - f).norm() <= AGREE * big, (name, got.method)
    # each measured force is what check.compare lines up with the system's value of the same name
    assert {m.name for m in got.measured()} == set(ref.forces)


@settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much])
@given(body=bodies())
def test_random_bodies_on_three_members_agree_with_the_linear_system(body):
    _agrees(body)


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much])
@given(body=bodies("pin"))
def test_random_bodies_on_a_pin_and_one_line_agree_with_the_linear_system(body):
    _agrees(body)


def test_a_load_along_a_support_line_with_the_other_two_parallel_is_solved_by_ritter():
    """R lies on F_2's line and F_0, F_1 are parallel: Culmann has no K and L, moments about L do it
    (found by hypothesis)."""
    body = RigidBody("body", {"P0": Vec(1.0, 1.0), "P1": Vec(1.0, 0.0)},
                     (Support("F_0", "member", "P0", "G0"), Support("F_1", "member", "P1", "G1"),
                      Support("F_2", "member", "P0", "G2")),
                     (Load("P", 0, "P0", Vec(1.0, 0.0)),),
                     fixed={"G0": Vec(0.0, 0.0), "G1": Vec(0.0, 0.0), "G2": Vec(0.0, 1.0)})
    got = free_body_analysis(body)
    assert got.method == "moments" and "L" in got.points
    assert (got.forces["F_2"] - Vec(-1.0, 0.0)).norm() <= 1e-15
    assert got.forces["F_0"].norm() <= 1e-15 and got.forces["F_1"].norm() <= 1e-15
    ref = equilibrium_solution(body).forces
    assert all((got.forces[n] - f).norm() <= AGREE for n, f in ref.items())


# -- improperly constrained and indeterminate bodies -----------------------------------------------------

def _one_sentence(text: str) -> None:
    assert "\n" not in text and text.count(". ") == 0, text


def test_three_members_through_one_point_are_improperly_constrained():
    meet = Vec(1.0, 2.0)
    pts = {"A": Vec(0.0, 0.0), "B": Vec(1.0, 0.0), "C": Vec(2.0, 0.0)}
    fixed = {n: meet + (p - meet) * 1.5 for n, p in (("GA", pts["A"]), ("GB", pts["B"]), ("GC", pts["C"]))}
    body = RigidBody("plate", pts, (Support("F_a", "member", "A", "GA"), Support("F_b", "member", "B", "GB"),
                                    Support("F_c", "member", "C", "GC")),
                     (Load("P", 0, "C", Vec(0.0, -10.0)),), fixed=fixed)
    with pytest.raises(ImproperlyConstrained) as e:
        free_body_analysis(body)
    _one_sentence(str(e.value))
    assert "improperly constrained" in str(e.value) and "all pass through (1 m, 2 m)" in str(e.value)


def test_three_parallel_members_are_improperly_constrained():
    pts = {"A": Vec(0.0, 0.0), "B": Vec(1.0, 0.0), "C": Vec(2.0, 0.5)}
    fixed = {f"G{n}": p + Vec(0.0, 1.0) for n, p in pts.items()}
    body = RigidBody("beam", pts, tuple(Support(f"F_{n}", "member", n, f"G{n}") for n in pts),
                     (Load("P", 0, "B", Vec(1.0, -10.0)),), fixed=fixed)
    with pytest.raises(ImproperlyConstrained, match=r"F_A, F_B and F_C are parallel \(at 90.0 deg\)") as e:
        check_supports(body)
    _one_sentence(str(e.value))


def test_a_pin_and_a_member_through_it_are_improperly_constrained():
    pts = {"A": Vec(0.0, 0.0), "B": Vec(1.0, 0.0)}
    body = RigidBody("lever", pts, (Support("F_a", "pin", "A"), Support("F_b", "member", "B", "G")),
                     (Load("P", 0, "B", Vec(0.0, -1.0)),), fixed={"G": Vec(2.0, 0.0)})
    with pytest.raises(ImproperlyConstrained, match="line of action of F_b passes through the pin A"):
        free_body_analysis(body)


@pytest.mark.parametrize("extra,words", [
    ("", "is not held: its supports bring 2 unknown force components"),
    ('[[member]]\nname = "F_d"\nat = "B"\nto = "G3"\n[[member]]\nname = "F_e"\nat = "A"\nto = "G3"\n',
     "is statically indeterminate: its supports bring 4 unknown force components"),
])
def test_the_wrong_number_of_unknowns_is_named(extra, words):
    with pytest.raises(SceneError) as e:
        parse_scene(PLATE.replace("#MORE", extra), "plate.toml")
    assert words in str(e.value) and str(e.value).startswith("plate.toml: member: ")
    assert "\n" not in str(e.value)


def test_indeterminate_supports_raise_in_the_engine_too():
    body = RigidBody("plate", {"A": Vec(0, 0), "B": Vec(1, 0)},
                     (Support("F_a", "pin", "A"), Support("F_b", "pin", "B")), (Load("P", 0, "B", Vec(0, -1)),))
    with pytest.raises(StaticallyIndeterminate, match="4 unknown force components .F_a .2., F_b .2.."):
        free_body_analysis(body)


# -- the scene file -----------------------------------------------------------------------------------------

PLATE = '''kind = "free body"
[drawing]
title = "A plate"
[units]
length = "mm"
[body]
name = "plate"
[body.points]
A = [0, 0]
B = [400, 0]
C = [200, 300]
[frame]
G1 = [-200, -200]
G2 = [600, -200]
G3 = [350, 650]
[[load]]
name = "P"
at = "C"
force = "500 N"
angle = "-30 deg"
[[member]]
name = "F_a"
at = "A"
to = "G1"
[[member]]
name = "F_b"
at = "B"
to = "G2"
#MORE
'''
THIRD = '[[member]]\nname = "F_c"\nat = "C"\nto = "G3"\n'


def test_a_plate_scene_reads_and_agrees():
    study = Study(parse_scene(PLATE.replace("#MORE", THIRD), "plate.toml")).run()
    assert study.get("forces").method == "Culmann"
    assert all(c.relative <= AGREE for c in study.comparisons) and len(study.comparisons) == 3


def test_pin_and_roller_by_concurrency_and_a_roller_that_would_pull():
    """A lever on a pin at B and a roller under A (pushing up): P at C turns it one way or the other."""
    lever = PLATE.replace('[[member]]\nname = "F_b"\nat = "B"\nto = "G2"\n', "").replace(
        '[[member]]\nname = "F_a"\nat = "A"\nto = "G1"\n', '[[roller]]\nname = "N"\nat = "A"\nnormal = "90 deg"\n'
    ).replace("#MORE", '[[pin]]\nname = "F_p"\nat = "B"\n')
    study = Study(parse_scene(lever.replace('angle = "-30 deg"', 'angle = "150 deg"'), "lever.toml")).run()
    f = study.get("forces")
    assert f.method == "three-force concurrency" and "I" in f.points
    assert all(c.relative <= AGREE for c in study.comparisons)
    assert f.axial("N") > 0 and not study.warnings                 # the roller pushes up
    study = Study(parse_scene(lever, "lever.toml")).run()
    assert study.get("forces").axial("N") < 0
    assert any("would have to pull" in w for w in study.warnings)


def test_a_guide_and_a_pure_couple_are_solved_by_moments():
    scene = PLATE.replace("#MORE", '[[guide]]\nname = "F_g"\nat = "C"\nangle = "30 deg"\n').replace(
        '[[load]]\nname = "P"\nat = "C"\nforce = "500 N"\nangle = "-30 deg"\n',
        '[[couple]]\nname = "M"\ntorque = "40 N m"\nsense = "cw"\n')
    study = Study(parse_scene(scene, "plate.toml")).run()
    assert study.get("forces").method == "moments"
    assert all(c.relative <= AGREE for c in study.comparisons)
    f = study.get("forces").forces["F_g"]
    assert abs(f.dot(Vec(math.cos(math.pi / 6), 0.5))) <= 1e-12 * f.norm()        # square to the slot


def test_improper_scene_is_one_sentence_naming_file_and_key():
    """The lines of F_a (from G1 through A) and F_b (from G2 through B) pass through C, as does F_c's."""
    concurrent = PLATE.replace("#MORE", '[[member]]\nname = "F_c"\nat = "C"\nto = "G3"\n').replace(
        "G1 = [-200, -200]", "G1 = [-200, -300]").replace("G2 = [600, -200]", "G2 = [600, -300]")
    with pytest.raises(SceneError) as e:
        parse_scene(concurrent, "plate.toml")
    msg = str(e.value)
    assert msg.startswith("plate.toml: member: the plate is improperly constrained: the lines of action of "
                          "F_a, F_b and F_c all pass through (200 mm, 300 mm)"), msg
    assert "\n" not in msg


BAD = [
    # (replace, with, key, words)
    ('to = "G2"', "", "member[2].to", "is missing"),
    ('force = "500 N"', 'force = "500 m"', "load[1].force", "not a value of force"),
    ('at = "C"\nforce', 'at = "Z"\nforce', "load[1].at", "Z is not a point of the plate; its points are A, B, C"),
    ('at = "B"\nto', 'at = "Q"\nto', "member[2].at", "Q is not a point of the plate"),
    ('to = "G2"', 'to = "G9"', "member[2].to", "G9 is not a point of [frame]"),
    ('name = "F_b"', 'name = "F_a"', "member[2].name", "F_a is already the name of member[1]"),
    ('name = "F_b"', 'name = "R"', "member[2].name", "names a force of the construction"),
    ('[body]\nname = "plate"', '[body]\nname = "plate"\nmass = 3', "body.mass", "unknown key"),
    ('[[load]]', '[[link]]\nnumber = 2\n[[load]]', "link", "unknown key; a free body scene has"),
    ('force = "500 N"', 'force = "-500 N"', "load[1].force", "is the magnitude"),
]


@pytest.mark.parametrize("old,new,key,words", BAD)
def test_bad_scene_is_one_sentence_with_file_and_key_and_no_traceback(tmp_path, capsys, old, new, key, words):
    text = PLATE.replace("#MORE", THIRD)
    assert old in text
    p = tmp_path / "plate.toml"
    p.write_text(text.replace(old, new, 1))
    code = main(["check", str(p)])
    err = capsys.readouterr().err
    assert code == 2 and err.count("\n") == 1 and "Traceback" not in err
    assert str(p) in err and f": {key}: " in err and words in err, err


# -- whatever is written into a free-body scene ---------------------------------------------------------

def test_any_edit_of_the_loader_gives_a_scene_or_one_clear_sentence():
    """The linkage fuzz (test_scene_fuzz) on the loader's scene: a scene that solves, a SceneError sentence
    naming the file, or a ConstructionError sentence -- never another exception."""
    import copy
    import tomllib

    from hypothesis import given as given_, settings as settings_
    from test_scene_fuzz import _DELETE, _paths, _set, values

    from constructions.errors import ConstructionError
    from drafting.scene.reader import scene_from_data
    from drafting.scene.textsafe import printable

    base = tomllib.loads(LOADER.read_text())
    paths = sorted(_paths(base), key=str)

    @settings_(max_examples=200, deadline=None, suppress_health_check=[HealthCheck.too_slow])
    @given_(edits=st.lists(st.tuples(st.sampled_from(paths), st.one_of(values, st.just(_DELETE))),
                           min_size=1, max_size=3))
    def run(edits):
        data = copy.deepcopy(base)
        for path, value in edits:
            try:
                _set(data, path, value)
            except (KeyError, IndexError, TypeError, AttributeError):
                continue
        try:
            scene = scene_from_data(data, "fuzz.toml")
        except SceneError as e:
            text = str(e)
            assert text.startswith("fuzz.toml: ") and "\n" not in text and printable(text) == text
            return
        try:
            Study(scene).comparisons
        except ConstructionError as e:
            assert "\n" not in str(e) and str(e)
    run()
