"""Scene files, the lazy study and the `drafting` command, with the bad inputs a user will make."""

from __future__ import annotations

import json
import math
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

from drafting.app.cli import main
from drafting.study.worked import builtin_example
from drafting.scene.reader import SceneError, load_scene, parse_scene
from drafting.study.study import Study

from paths import GALLERY, ROOT
EXAMPLE = builtin_example().read_text()


def write(tmp_path: Path, text: str, name: str = "scene.toml") -> Path:
    p = tmp_path / name
    p.write_text(text)
    return p


def run(args: list[str], capsys) -> tuple[int, str, str]:
    code = main(args)
    out, err = capsys.readouterr()
    return code, out, err


# -- reading scenes -------------------------------------------------------------------------------------

def test_builtin_example_reads_in_si():
    s = load_scene(builtin_example())
    assert s.mechanism.link(1).length == pytest.approx(0.050, rel=1e-15)
    assert s.mechanism.link(2).length == pytest.approx(0.094, rel=1e-15)
    assert s.angle == pytest.approx(math.radians(70), rel=1e-15)
    assert s.omega == pytest.approx(10.0, rel=1e-15)      # 500 mm/s / 50 mm, counter-clockwise
    assert s.analyses == ("velocity",)


@pytest.mark.parametrize("text,omega", [
    ('omega = "120 rpm"', 4 * math.pi),
    ('omega = "-10 rad/s"', -10.0),
    ('omega = "10 rad/s"\nsense = "cw"', -10.0),
    ('tip_speed = "0.5 m/s"\nsense = "cw"', -10.0),
])
def test_input_speed_units(text, omega):
    s = parse_scene(EXAMPLE.replace('tip_speed = "500 mm/s"\nsense = "ccw"', text))
    assert s.omega == pytest.approx(omega, rel=1e-12)


def test_values_may_carry_their_own_units():
    s = parse_scene(EXAMPLE.replace("length = 94", 'length = "3.7 in"'))
    assert s.mechanism.link(2).length == pytest.approx(3.7 * 0.0254, rel=1e-12)


BAD = [
    # (replace this, with this, key named in the message, words in the message)
    ("[input]", "[inputs]", "inputs", "unknown key"),
    ("joints = [\"B\", \"C\"]\nlength = 94", "joints = [\"B\", \"C\"]\nlength = 94\nmass = 3", "link[2].mass", "unknown key"),
    ("length = 94", 'length = "94 mm/s"', "link[2].length", "not a value of length"),
    ('tip_speed = "500 mm/s"', 'tip_speed = "500 mm"', "input.tip_speed", "not a value of velocity"),
    ('angle = "70 deg"', 'angle = "seventy"', "input.angle", "cannot be read"),
    ('C = "ahead of B"', 'C = "somewhere"', "assembly.C", "not a branch"),
    ('C = "ahead of B"', 'C = "left of B->O1"', "assembly", "relative to the joints"),
    ('[assembly]\nC = "ahead of B"', '', "assembly", "choose one"),
    ('joint = "C"', 'joint = "E"', "slider[1].joint", "on no link"),
    ('analyses = ["velocity"]', 'analyses = ["sweeps"]', "ask.analyses", "not an analysis; choose from"),
    ('paper = "A4"', 'paper = "Letter"', "drawing.paper", "not a paper size"),
]


@pytest.mark.parametrize("old,new,key,words", BAD)
def test_bad_scene_names_file_and_key(tmp_path, capsys, old, new, key, words):
    assert old in EXAMPLE
    p = write(tmp_path, EXAMPLE.replace(old, new, 1))
    with pytest.raises(SceneError) as e:
        Study(load_scene(p)).check()          # read, then the family's checks (a linkage's assembly plan)
    assert str(p) in str(e.value) and key in str(e.value) and words in str(e.value)
    code, out, err = run(["solve", str(p)], capsys)
    assert code == 2
    assert err.count("\n") == 1 and err.startswith("drafting: error: ") and key in err
    assert "Traceback" not in err


def test_missing_joint_link(tmp_path, capsys):
    """A slider-crank whose slider table is missing: C hangs on one link."""
    text = EXAMPLE.split("[[slider]]")[0] + "[input]" + EXAMPLE.split("[input]")[1]
    p = write(tmp_path, text)
    code, out, err = run(["solve", str(p)], capsys)
    assert code == 2 and "C is held by link 2 only: join it to another link, put it on a slider" in err \
        and str(p) in err


def test_garbage_toml(tmp_path, capsys):
    p = write(tmp_path, "this is [not toml = = =")
    code, out, err = run(["render", str(p), "-o", str(tmp_path / "out")], capsys)
    assert code == 2 and "is not valid TOML" in err and str(p) in err
    assert not (tmp_path / "out").exists() or not any((tmp_path / "out").iterdir())


def test_missing_file(tmp_path, capsys):
    code, out, err = run(["solve", str(tmp_path / "nope.toml")], capsys)
    assert code == 2 and "no such scene file" in err


def test_link_too_short_to_assemble(tmp_path, capsys):
    """A coupler of 30 mm cannot reach the guide from B, 47 mm above it."""
    p = write(tmp_path, EXAMPLE.replace("length = 94", "length = 30"))
    code, out, err = run(["render", str(p), "-o", str(tmp_path / "out")], capsys)
    assert code == 2
    assert str(p) in err and "crank angle 70 deg" in err and "link 2 (BC = 30 mm)" in err
    assert "do not meet (they miss by 16.98 mm)" in err
    assert not (tmp_path / "out").exists() or not any((tmp_path / "out").iterdir())


def test_singular_position_is_reported(tmp_path, capsys):
    """Offset slider-crank at its limit position: coupler square to the guide."""
    text = EXAMPLE.replace("length = 94", "length = 40").replace('angle = "70 deg"', 'angle = "90 deg"') \
        .replace("through = [0, 0]", "through = [0, 10]")
    p = write(tmp_path, text)
    code, out, err = run(["solve", str(p)], capsys)
    assert code == 3 and "limit position" in err and "crank angle 90 deg" in err     # 3: singular


# -- the lazy study ---------------------------------------------------------------------------------------

def test_velocity_scene_builds_nothing_else(capsys):
    code, out, err = run(["solve", str(builtin_example()), "--json"], capsys)
    assert code == 0
    data = json.loads(out)
    assert data["analyses"] == ["classification", "position", "velocity", "analytic check"]
    assert "acceleration" not in data and "angular_acceleration" not in data and "forces" not in data
    assert not any("force" in a for a in data["analyses"])
    assert data["velocity"]["V_C"]["magnitude"] == pytest.approx(568.536, abs=1e-3)
    assert data["angular_velocity"]["omega_2"]["sense"] == "cw"
    assert data["check"]["agrees"] is True


def test_position_only_scene_draws_no_polygon(tmp_path, capsys):
    p = write(tmp_path, EXAMPLE.replace('analyses = ["velocity"]', 'analyses = ["position"]'))
    study = Study(load_scene(p))
    assert study.velocity is None and study.analytic is None
    assert study.ran == []                    # nothing computed until asked
    study.construction
    assert study.ran == ["classification", "position"]     # the class is cheap and always said
    code, out, err = run(["solve", str(p), "--json"], capsys)
    data = json.loads(out)
    assert data["analyses"] == ["classification", "position"] and "velocity" not in data


def test_find_selects_rows():
    s = parse_scene(EXAMPLE.replace('analyses = ["velocity"]', 'analyses = ["velocity"]\nfind = ["V_C", "omega_2"]'))
    assert [c.name for c in Study(s).comparisons] == ["V_C", "omega_2"]


# -- the notes' worked examples (gallery) -----------------------------------------------------------------

def _values(path: Path) -> dict:
    study = Study(load_scene(path))
    v = study.velocity
    return {"V_C": v.velocities["C"].norm() * 1e3, "V_CB": v.relative[("C", "B")].norm() * 1e3,
            "omega_2": v.angular[2], "omega_3": v.angular.get(3), "study": study}


def test_notes_example_1_within_drawing_accuracy():
    r = _values(GALLERY / "notes-velocity-example-1.toml")
    assert r["V_CB"] == pytest.approx(198, rel=0.02)
    assert r["V_C"] == pytest.approx(569, rel=0.02)
    assert -r["omega_2"] == pytest.approx(2.1, rel=0.02)      # clockwise
    assert not r["study"].disagreements()


def test_notes_example_2_within_drawing_accuracy():
    r = _values(GALLERY / "notes-velocity-example-2.toml")
    assert r["V_CB"] == pytest.approx(101, rel=0.02)
    assert r["V_C"] == pytest.approx(216, rel=0.02)
    assert -r["omega_2"] == pytest.approx(2.89, rel=0.02)     # clockwise
    assert r["omega_3"] == pytest.approx(10.8, rel=0.02)      # counter-clockwise
    assert not r["study"].disagreements()


def test_notes_example_3_toggle_linkage():
    """V_D = 4 m/s to the left, omega_2 and omega_3 counter-clockwise, omega_4 clockwise (notes)."""
    study = Study(load_scene(GALLERY / "notes-velocity-example-3.toml"))
    v = study.velocity
    assert v.velocities["D"].x == pytest.approx(-4.0, rel=0.02) and abs(v.velocities["D"].y) < 1e-12
    assert v.angular[2] > 0 and v.angular[3] > 0 and v.angular[4] < 0
    assert study.model == "dyad chain vector loop" and not study.disagreements()


def test_notes_example_4_velocity_image():
    study = Study(load_scene(GALLERY / "notes-velocity-example-4.toml"))
    v = study.velocity
    # the image bcd is similar to BCD: |bd| / |BD| = |bc| / |BC| = |omega_2|
    P = study.position.positions
    bd = (v.velocities["D"] - v.velocities["B"]).norm() / (P["D"] - P["B"]).norm()
    bc = (v.velocities["C"] - v.velocities["B"]).norm() / (P["C"] - P["B"]).norm()
    assert bd == pytest.approx(bc, rel=1e-12) == pytest.approx(abs(v.angular[2]), rel=1e-12)
    assert not study.disagreements() and any(c.name == "V_D" for c in study.comparisons)


@pytest.mark.parametrize("scene", sorted(GALLERY.glob("*.toml")), ids=lambda p: p.stem)
def test_check_command_passes_on_gallery(scene, capsys):
    code, out, err = run(["check", str(scene)], capsys)
    assert code == 0, err
    assert "agree to 1e-9 relative" in out


def test_help_on_each_command():
    for args in (["--help"], ["render", "--help"], ["solve", "--help"], ["check", "--help"], ["bench", "--help"]):
        r = subprocess.run([sys.executable, "-m", "drafting.app.cli", *args], capture_output=True, text=True,
                           cwd=ROOT, env={**os.environ, "PYTHONPATH": str(ROOT)})
        assert r.returncode == 0 and "usage: drafting" in r.stdout


def test_readme_commands_are_what_ci_runs():
    readme = (ROOT / "README.md").read_text().split("```sh\n", 1)[1].split("```", 1)[0].strip().splitlines()
    ci = (ROOT / ".ci" / "run").read_text()
    assert len(readme) == 2
    for cmd in readme:
        assert cmd in ci


# -- rendering ------------------------------------------------------------------------------------------

def test_output_folder_that_cannot_be_written(tmp_path, capsys):
    blocker = tmp_path / "a-file"
    blocker.write_text("not a folder")
    code, out, err = run(["render", str(builtin_example()), "-o", str(blocker / "out")], capsys)
    assert code == 2 and err.count("\n") == 1 and str(blocker / "out") in err and "Traceback" not in err


def test_one_bad_scene_does_not_stop_the_others(tmp_path, capsys):
    bad = write(tmp_path, EXAMPLE.replace("length = 94", "length = 30"), "bad.toml")
    out_dir = tmp_path / "out"
    code, out, err = run(["render", str(bad), str(builtin_example()), "-o", str(out_dir), "--format", "svg"],
                         capsys)
    assert code == 2 and "bad.toml" in err
    assert sorted(p.name for p in out_dir.iterdir()) == ["notes-velocity-example-1.svg"]


def test_bad_format_is_refused(capsys):
    with pytest.raises(SystemExit) as e:
        main(["render", str(builtin_example()), "--format", "svg,gif"])
    assert e.value.code == 2 and "unknown format 'gif'" in capsys.readouterr().err


@pytest.mark.parametrize("scene", sorted(GALLERY.glob("*.toml")), ids=lambda p: p.stem)
def test_every_gallery_scene_renders(scene, tmp_path, capsys):
    """Every gallery scene renders: one SVG per sheet (stem.svg, or stem-1.svg .. stem-n.svg numbered n/n
    in their title blocks), on its paper, with the notes' labels, every scale and the results."""
    import xml.etree.ElementTree as ET
    code, out, err = run(["render", str(scene), "-o", str(tmp_path), "--format", "svg"], capsys)
    assert code == 0, err
    assert "agree to 1e-9 relative" in out
    s = load_scene(scene)
    one = tmp_path / f"{scene.stem}.svg"
    pages = [one] if one.exists() else sorted(tmp_path.glob(f"{scene.stem}-*.svg"),
                                              key=lambda p: int(p.stem.rsplit("-", 1)[1]))
    assert pages and [p.name for p in pages] == ([one.name] if one.exists() else
                                                 [f"{scene.stem}-{i}.svg" for i in range(1, len(pages) + 1)])
    text = ""
    size = {"A4": ("297mm", "210mm"), "A3": ("420mm", "297mm")}[s.paper]
    for i, svg in enumerate(pages, 1):
        root = ET.parse(svg).getroot()
        page = " ".join("".join(t.itertext()) for t in root.iter("{http://www.w3.org/2000/svg}text"))
        assert f"{i}/{len(pages)}" in page and s.drawing_number in page
        assert (root.get("width"), root.get("height")) == size
        text += " " + page
    labels = ["Results"] + (["Space diagram"] if s.kind in ("linkage", "free body") else [])
    if s.kind == "linkage":
        moving = s.omega != 0                     # at rest the velocity polygon is its pole alone: not drawn
        if moving and ("velocity" in s.analyses or "acceleration" in s.analyses or s.effects.inertial):
            labels += ["Velocity polygon", "Ov"]
        if "acceleration" in s.analyses or s.effects.inertial:
            labels += ["Acceleration polygon", "Oa"]
        if "forces" in s.analyses:
            labels += ["Force polygon", "Free-body diagram", "Of"]
    for label in labels:
        assert label in text, label


def test_gallery_drawing_numbers_are_unique():
    """A drawing number names one drawing: no two gallery scenes share one."""
    seen: dict[str, str] = {}
    for scene in sorted(GALLERY.glob("*.toml")):
        n = load_scene(scene).drawing_number
        assert n not in seen, f"{scene.name} and {seen.get(n)} are both {n}"
        seen[n] = scene.name


def test_default_command_writes_three_formats(tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(tmp_path)
    code, out, err = run([], capsys)
    assert code == 0
    assert "agree to 1e-9 relative" in out and "V_C" in out
    for fmt in ("svg", "pdf", "png"):
        assert (tmp_path / "drafting-output" / f"notes-velocity-example-1.{fmt}").stat().st_size > 1000


def test_a3_override(tmp_path, capsys):
    code, out, err = run(["render", str(builtin_example()), "-o", str(tmp_path), "--format", "svg",
                          "--paper", "A3"], capsys)
    assert code == 0 and 'width="420mm"' in (tmp_path / "notes-velocity-example-1.svg").read_text()


def test_check_exits_1_when_graphical_and_analytic_disagree(monkeypatch, capsys):
    """Perturb the analytic answer by 1e-6 relative: beyond the 1e-9 agreement, so `check` fails."""
    import constructions.check as check
    import drafting.families.linkage.family as linkage_family
    from constructions.geometry import Vec

    real = check.analytic_solution

    def perturbed(m, angle, omega, *args, **kwargs):
        a = real(m, angle, omega, *args, **kwargs)
        vel = dict(a.velocities)
        vel["C"] = vel["C"] + Vec(1e-6 * vel["C"].norm(), 0.0)
        return check.AnalyticSolution(a.model, a.positions, vel, a.angular)

    monkeypatch.setattr(linkage_family, "analytic_solution", perturbed)
    code, out, err = run(["check", str(builtin_example())], capsys)
    assert code == 1 and "DISAGREE" in out


@pytest.mark.parametrize("factor,unit,expect", [(1e-3, "um", "Space diagram 1000:1"), (1.0, "mm", "Space diagram 1:1"),
                                                (1e3, "m", "Space diagram 1:1000")])
def test_sheet_of_a_scaled_mechanism_keeps_its_drawing(factor, unit, expect, tmp_path, capsys):
    """The same slider-crank in micrometres, millimetres and metres: same decisions, an ISO 5455 space
    scale that follows the size (its series extended by powers of ten), and the same velocity polygon
    since V_B is the same."""
    text = EXAMPLE.replace('length = "mm"', f'length = "{unit}"')
    p = write(tmp_path, text)
    code, out, err = run(["render", str(p), "-o", str(tmp_path), "--format", "svg"], capsys)
    assert code == 0, err
    svg = (tmp_path / "scene.svg").read_text()
    assert expect in svg and "velocity scale: 1 mm = 10 mm/s" in svg


# -- small bugs a new user met (issue 11) ------------------------------------------------------------------

def test_a_typo_in_find_is_named_not_dropped(tmp_path, capsys):
    p = write(tmp_path, EXAMPLE.replace('analyses = ["velocity"]', 'analyses = ["velocity"]\nfind = ["V_C", "V_X"]'))
    code, out, err = run(["solve", str(p)], capsys)
    assert code == 2 and "ask.find: 'V_X' is not a quantity this scene measures; it measures V_B" in err


def test_a_signed_omega_against_its_sense_is_refused(tmp_path, capsys):
    p = write(tmp_path, EXAMPLE.replace('tip_speed = "500 mm/s"', 'omega = "-120 rpm"'))
    assert 'sense = "ccw"' in p.read_text()
    code, out, err = run(["solve", str(p)], capsys)
    assert code == 2 and "input.sense: says ccw but omega = '-120 rpm' turns clockwise" in err
    p = write(tmp_path, EXAMPLE.replace('tip_speed = "500 mm/s"', 'omega = "120 rpm"'))
    assert run(["solve", str(p)], capsys)[0] == 0          # agreeing sign and sense are fine


def test_check_goes_on_past_a_bad_scene(tmp_path, capsys):
    code, out, err = run(["check", str(tmp_path / "missing.toml"), str(builtin_example())], capsys)
    assert code == 2 and err.count("\n") == 1 and "missing.toml: no such scene file" in err
    assert "agree to 1e-9 relative" in out                  # the good scene was still checked


def test_an_undeclared_fixed_pivot_is_named(tmp_path, capsys):
    text = (GALLERY / "notes-velocity-example-2.toml").read_text()
    p = write(tmp_path, "\n".join(l for l in text.splitlines() if not l.startswith("O2 = [")))
    code, out, err = run(["solve", str(p)], capsys)
    assert code == 2 and "O2 is held by link 3 only: join it to another link, put it on a slider, or " \
        "declare it a fixed pivot" in err


def test_rendering_several_scenes_shows_progress_on_a_terminal_only(tmp_path, capsys, monkeypatch):
    from drafting.app import progress
    scenes = [str(GALLERY / "notes-velocity-example-1.toml"), str(GALLERY / "notes-velocity-example-2.toml")]
    assert main(["render", *scenes, "-o", str(tmp_path), "--format", "svg"]) == 0
    assert "%" not in capsys.readouterr().err
    monkeypatch.setattr(progress, "is_tty", lambda stream: True)
    assert main(["render", *scenes, "-o", str(tmp_path), "--format", "svg"]) == 0
    err = capsys.readouterr().err
    assert "\rrender [" in err and "100.0 %" in err


def test_the_command_tunes_the_collector_of_its_own_process_only(tmp_path):
    """``drafting`` freezes what it loaded and collects the young generation less often, in its own
    process; called from Python (a notebook, these tests) it leaves the caller's collector alone."""
    import gc
    before = gc.get_threshold(), gc.get_freeze_count()
    assert main(["solve", str(builtin_example())]) == 0
    assert (gc.get_threshold(), gc.get_freeze_count()) == before
    code = ("import gc, sys\nfrom drafting.app.cli import main\n"
            "rc = main(['solve', sys.argv[1]], exiting=True)\n"
            "print(gc.get_threshold()[0], gc.get_freeze_count() > 0, rc)")
    out = subprocess.run([sys.executable, "-c", code, str(builtin_example())], capture_output=True, text=True,
                         check=True).stdout.split()
    from drafting.app.parallel import GC_YOUNG
    assert out[-3:] == [str(GC_YOUNG), "True", "0"]


def test_version(capsys):
    """`drafting --version` names the installed version (issue 24)."""
    with pytest.raises(SystemExit) as e:
        main(["--version"])
    assert e.value.code == 0
    out = capsys.readouterr().out.strip()
    assert re.fullmatch(r"drafting \d+\.\d+\.\d+\S*", out), out
