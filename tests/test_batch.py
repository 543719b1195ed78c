"""Batches of lab-sheet variants (issue 11): [vary] read strictly, the same seed gives byte-identical files
whatever the executor, a draw that cannot be drawn is drawn again, every key in one CSV, a progress bar."""

from __future__ import annotations

import concurrent.futures as cf
import csv
import io
from pathlib import Path

import pytest

from drafting.app.batch import run_batch
from drafting.app.cli import main
from drafting.app.progress import Progress
from drafting.scene.reader import SceneError, parse_scene

SCENE = """
[drawing]
title = "Slider-crank: velocity polygon"
number = "LAB-V-001"

[units]
length = "mm"
velocity = "mm/s"
angle = "deg"

[frame]
O1 = [0, 0]

[[link]]
number = 1
joints = ["O1", "B"]
length = 50

[[link]]
number = 2
joints = ["B", "C"]
length = 94

[[slider]]
number = 3
joint = "C"
through = [0, 0]
angle = "0 deg"

[input]
link = 1
angle = "70 deg"
omega = "10 rad/s"

[assembly]
C = "ahead of B"

[ask]
analyses = ["velocity"]
"""

VARY = """
[vary]
crank_angle = ["30 deg", "150 deg"]
omega = { from = "5 rad/s", to = "15 rad/s", step = "0.5 rad/s" }
length.BC = ["80 mm", "120 mm"]
"""


def scene_file(tmp_path: Path, vary: str = VARY, name: str = "slider.toml", text: str = SCENE) -> Path:
    p = tmp_path / name
    p.write_text(text + vary)
    return p


def files(folder: Path) -> dict[str, bytes]:
    return {p.name: p.read_bytes() for p in sorted(folder.iterdir())}


def test_the_same_seed_gives_byte_identical_files_over_any_executor(tmp_path):
    scene = scene_file(tmp_path)
    a = run_batch(scene, 3, 11, tmp_path / "a", ("svg", "pdf"))              # the default process pool
    b = run_batch(scene, 3, 11, tmp_path / "b", ("svg", "pdf"), workers=1)   # one after the other
    c = run_batch(scene, 3, 12, tmp_path / "c", ("svg",), executor=cf.ThreadPoolExecutor(2))
    fa, fb = files(tmp_path / "a"), files(tmp_path / "b")
    assert len(fa) == 3 * 7 + 1                       # per variant 3 SVGs, 3 PDFs, the key CSV; all keys
    assert fa == fb
    assert [r.values for r in a] == [r.values for r in b]
    assert [r.values for r in a] != [r.values for r in c]          # another seed, other values
    assert len({tuple(r.values) for r in a}) == 3                  # the variants differ


def test_every_key_in_one_csv_with_units_in_the_headers(tmp_path):
    scene = scene_file(tmp_path)
    results = run_batch(scene, 2, 5, tmp_path / "out", ("svg",), executor=cf.ThreadPoolExecutor(2))
    rows = list(csv.DictReader(io.StringIO((tmp_path / "out" / "slider-keys.csv").read_text())))
    assert [r["variant"] for r in rows] == ["1", "2"]
    header = list(rows[0])
    assert header[:4] == ["variant", "crank_angle (\u00b0)", "omega (rad/s)", "length.BC (mm)"]
    assert "V_C (mm/s)" in header and "V_C direction (deg)" in header and "omega_2 (rad/s, CCW +)" in header
    for r, res in zip(rows, results):
        one = list(csv.DictReader(io.StringIO((tmp_path / "out" / f"slider-v00{r['variant']}-key.csv").read_text())))
        v_c = next(x for x in one if x["quantity"] == "V_C")
        assert float(r["V_C (mm/s)"]) == pytest.approx(float(v_c["answer"]), rel=1e-9)
        assert dict(res.values)["crank_angle (\u00b0)"] == r["crank_angle (\u00b0)"]
        assert float(r["crank_angle (\u00b0)"]) % 5 == 0                # on the grid: 30 .. 150 every 5 deg


def test_a_draw_that_cannot_be_drawn_is_drawn_again_the_same_way(tmp_path):
    # the guide 60 mm above O1: a coupler shorter than 60 - 50 sin(angle) cannot reach it
    text = SCENE.replace('through = [0, 0]', 'through = [0, 60]')
    scene = scene_file(tmp_path, '[vary]\nlength.BC = ["10 mm", "100 mm"]\ncrank_angle = ["0 deg", "350 deg"]\n',
                       text=text)
    a = run_batch(scene, 6, 3, tmp_path / "a", ("svg",), workers=1)
    b = run_batch(scene, 6, 3, tmp_path / "b", ("svg",), executor=cf.ThreadPoolExecutor(2))
    notes = [n for r in a for n in r.notes]
    assert notes and all("drawn again" in n or "skipped" in n for n in notes)
    assert notes == [n for r in b for n in r.notes]
    assert files(tmp_path / "a") == files(tmp_path / "b")
    assert all(r.files for r in a)


def test_a_progress_bar_on_a_terminal(tmp_path):
    class Tty(io.StringIO):
        def isatty(self):
            return True
    stream = Tty()
    bar = Progress(4, "batch", stream)
    bar.shown = stream.isatty()
    run_batch(scene_file(tmp_path), 4, 1, tmp_path / "out", ("svg",), executor=cf.ThreadPoolExecutor(2),
              progress=bar)
    text = stream.getvalue()
    assert "\rbatch [" in text and "100.0 %" in text and text.endswith("\n")


def test_batch_command(tmp_path, capsys):
    scene = scene_file(tmp_path)
    out = tmp_path / "out"
    assert main(["batch", str(scene), "--variants", "2", "--seed", "4", "-o", str(out), "--format", "svg"]) == 0
    said = capsys.readouterr()
    assert "2 of 2 variants (seed 4)" in said.out and said.err == ""   # no bar: stderr is not a terminal
    assert (out / "slider-v002-problem.svg").exists() and (out / "slider-keys.csv").exists()


def test_batch_of_a_scene_without_ranges_is_one_sentence(tmp_path, capsys):
    scene = scene_file(tmp_path, vary="")
    assert main(["batch", str(scene), "--variants", "2", "-o", str(tmp_path / "out")]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and f"{scene}: vary: is missing" in err


@pytest.mark.parametrize("vary, key, words", [
    ('[vary]\ncrank_speed = ["1 rad/s", "2 rad/s"]', "vary.crank_speed", "unknown key; choose from crank_angle"),
    ('[vary]\ncrank_angle = ["150 deg", "30 deg"]', "vary.crank_angle", "the range must go up"),
    ('[vary]\ncrank_angle = ["30 mm", "150 mm"]', "vary.crank_angle", "is not a value of angle"),
    ('[vary]\ncrank_angle = ["30 deg"]', "vary.crank_angle", "must be a range [from, to]"),
    ('[vary]\ncrank_angle = { from = "30 deg", to = "40 deg", step = "20 deg" }', "vary.crank_angle.step",
     "is larger than the range"),
    ('[vary]\ncrank_angle = { from = "30 deg", upto = "40 deg" }', "vary.crank_angle.upto", "unknown key"),
    ('[vary]\nlength.BD = ["80 mm", "90 mm"]', "vary.length.BD", "no link joins the joints 'BD'; the links are O1B, BC"),
    ('[vary]\ntip_speed = ["400 mm/s", "600 mm/s"]', "vary.tip_speed",
     "varies input.tip_speed, which the scene does not give; the scene gives input.omega"),
    ('vary = 3', "vary", "must be a table of ranges"),
])
def test_bad_ranges_are_one_sentence_naming_file_and_key(vary, key, words):
    with pytest.raises(SceneError) as e:
        parse_scene(SCENE + vary if vary.startswith("[") else vary + "\n" + SCENE, "lab.toml")
    text = str(e.value)
    assert text.startswith(f"lab.toml: {key}: ") and words in text and "\n" not in text, text


def test_ranges_belong_to_linkage_scenes():
    cam = (Path(__file__).resolve().parents[1] / "gallery" / "notes-roller-cam.toml").read_text()
    with pytest.raises(SceneError, match=r"cam.toml: vary: is read for linkage scenes"):
        parse_scene(cam + '\n[vary]\ncrank_angle = ["30 deg", "150 deg"]\n', "cam.toml")


def test_several_scenes_render_over_an_executor_in_the_order_given(tmp_path, capsys):
    from drafting.app.render_cmd import cmd_render
    root = Path(__file__).resolve().parents[1] / "gallery"
    scenes = [root / f"notes-velocity-example-{i}.toml" for i in (4, 1, 2)]
    assert cmd_render(scenes, tmp_path, ["svg"], None, executor=cf.ThreadPoolExecutor(2)) == 0
    out = capsys.readouterr().out
    firsts = [out.index(f"wrote {tmp_path / s.stem}.svg") for s in scenes]
    assert firsts == sorted(firsts)                          # printed in the order given, whatever finished first
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted(f"{s.stem}.svg" for s in scenes)


def test_alpha_may_vary_where_the_scene_leaves_it_at_zero(tmp_path):
    text = SCENE.replace('analyses = ["velocity"]', 'analyses = ["acceleration"]')
    scene = scene_file(tmp_path, '[vary]\nalpha = ["-20 rad/s^2", "20 rad/s^2"]\n', text=text)
    (r,) = run_batch(scene, 1, 2, tmp_path / "out", ("svg",), workers=1)
    assert r.files and r.values[0][0] == "alpha (rad/s^2)"
    problem = " ".join(p.read_text() for p in (tmp_path / "out").glob("slider-v001-problem*.svg"))
    from drafting.scene.unitset import Units
    drawn = Units().format("angular acceleration", abs(float(r.values[0][1])))
    assert f"= {drawn.split()[0]}" in problem            # the crank's alpha is given data: on the problem sheet
    with pytest.raises(SceneError, match=r"vary.alpha: varies input.alpha, which the scene does not give"):
        parse_scene(text.replace('omega = "10 rad/s"', 'omega = "10 rad/s"\ntorque = "0 N m"')
                    + '[vary]\nalpha = ["-20 rad/s^2", "20 rad/s^2"]\n', "lab.toml")


STATIC = Path(__file__).resolve().parents[1] / "gallery" / "notes-static-force-sample.toml"     # load P = 40 N


def test_a_load_s_force_is_varied_by_name(tmp_path):
    """``load.P`` varies the magnitude of the [[load]] named P (its angle stays): the variant is solved
    with the drawn force, and its forces scale with it (a static analysis is linear in the load)."""
    import tomllib
    from drafting.app.batch import variant_study
    from drafting.families.linkage.vary import read_vary
    text = STATIC.read_text() + '\n[vary]\nload.P = { from = "20 N", to = "60 N", step = "5 N" }\n'
    data = tomllib.loads(text)
    scene = parse_scene(text, tmp_path / "p.toml")
    (r,) = read_vary(data, "p.toml", scene.units)
    assert (r.key, r.where, r.kind, r.count) == ("load.P", ("load", 0, "force"), "force", 9)
    base = parse_scene(STATIC.read_text(), STATIC)
    from drafting.study.study import Study
    t0 = {q: c.graphical for q, c in Study(base).results.items()}
    study, values = variant_study(data, tmp_path / "p.toml", seed=3, index=1)
    (header, shown), = values
    p = float(shown)
    assert header.startswith("load.P") and 20 <= p <= 60 and (p - 20) % 5 == 0
    t1 = {q: c.graphical for q, c in study.results.items()}
    assert t1["T_2"] == pytest.approx(t0["T_2"] * p / 40.0, rel=1e-9)
    assert t1["F_14"].norm() == pytest.approx(t0["F_14"].norm() * p / 40.0, rel=1e-9)


@pytest.mark.parametrize("vary, key, words", [
    ('[vary]\nload.Q = ["20 N", "60 N"]', "vary.load.Q", "no load is named 'Q'; the loads are P"),
    ('[vary]\nload.P = ["-10 N", "60 N"]', "vary.load.P", "the range must stay above 0"),
    ('[vary]\nload.P = ["20 mm", "60 mm"]', "vary.load.P", "is not a value of force"),
])
def test_a_bad_load_range_is_one_sentence(vary, key, words):
    with pytest.raises(SceneError, match=rf"lab.toml: {key}: .*{words}"):
        parse_scene(STATIC.read_text() + "\n" + vary, "lab.toml")


DALEMBERT = Path(__file__).resolve().parents[1] / "gallery" / "four-bar-dalembert.toml"   # m3 = 1.2 kg, O4 = [200, 0]


@pytest.mark.parametrize("vary, key, where, written", [
    ('mass.3 = { from = "0.5 kg", to = "2 kg", step = "0.1 kg" }', "mass.3", ("mass", 1, "mass"),
     lambda v: ('mass = "1.2 kg"', f'mass = "{v} kg"')),
    ('pivot.O4.x = { from = "180 mm", to = "220 mm", step = "5 mm" }', "pivot.O4.x", ("frame", "O4", 0),
     lambda v: ("O4 = [200, 0]", f'O4 = ["{v} mm", 0]')),
])
def test_a_mass_and_a_pivot_are_varied_where_the_scene_gives_them(tmp_path, vary, key, where, written):
    """``mass.<link>`` and ``pivot.<name>.x|y`` write the drawn value where the scene gives it: the
    variant's study equals the study of the scene file with that value written in by hand (every
    result, to the last bit), and the value differs from the scene's own in some draw."""
    import tomllib
    from drafting.app.batch import variant_study
    from drafting.study.study import Study
    from drafting.families.linkage.vary import read_vary
    base_text = DALEMBERT.read_text()
    text = base_text + f"\n[vary]\n{vary}\n"
    data = tomllib.loads(text)
    (r,) = read_vary(data, "p.toml", parse_scene(text, tmp_path / "p.toml").units)
    assert (r.key, r.where) == (key, where)
    seen = set()
    for index in range(1, 5):
        study, ((header, shown),) = variant_study(data, tmp_path / "p.toml", seed=11, index=index)
        assert header.startswith(key)
        old, new = written(shown)
        assert base_text.count(old) == 1
        by_hand = Study(parse_scene(base_text.replace(old, new), tmp_path / "q.toml")).run()
        assert {q: c.graphical for q, c in study.results.items()} == {q: c.graphical for q, c in by_hand.results.items()}
        seen.add(shown)
    assert len(seen) > 1


@pytest.mark.parametrize("vary, key, words", [
    ('mass.5 = ["1 kg", "2 kg"]', "vary.mass.5", "no \\[\\[mass\\]\\] is on link '5'; the links with a mass are 2, 3, 4"),
    ('mass.3 = ["0 kg", "2 kg"]', "vary.mass.3", "the range must stay above 0 kg"),
    ('mass.3 = ["1 mm", "2 mm"]', "vary.mass.3", "is not a value of mass"),
    ('mass = ["1 kg", "2 kg"]', "vary.mass", "must name links by number"),
    ('pivot.O9.x = ["1 mm", "2 mm"]', "vary.pivot.O9", "no fixed pivot is named 'O9' in \\[frame\\]; the fixed pivots are O2, O4"),
    ('pivot.O4.z = ["1 mm", "2 mm"]', "vary.pivot.O4.z", "pivot.<name>.x or pivot.<name>.y"),
    ('pivot.O4 = ["1 mm", "2 mm"]', "vary.pivot.O4", "pivot.<name>.x or pivot.<name>.y"),
    ('pivot.O4.y = ["1 kg", "2 kg"]', "vary.pivot.O4.y", "is not a value of length"),
])
def test_a_bad_mass_or_pivot_range_is_one_sentence(vary, key, words):
    with pytest.raises(SceneError, match=rf"lab.toml: {key}: .*{words}"):
        parse_scene(DALEMBERT.read_text() + "\n[vary]\n" + vary + "\n", "lab.toml")
