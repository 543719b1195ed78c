"""Lab sheets (issue 11): the problem sheet holds no answer, its polygon panels are empty but framed at
the worked sheet's scales, its space diagram is dimensioned; the key is one compact page and a CSV."""

from __future__ import annotations

import csv
import io
import re
import xml.etree.ElementTree as ET

import pytest

from drafting.app.cli import main
from drafting.app.lab import BLANK, dimensioned, lab_for, problem_construction
from drafting.backends.svg import sheet_to_svg
from drafting.scene.reader import load_scene
from drafting.study.study import Study

from paths import ROOT
SCENES = ["notes-velocity-example-1", "notes-velocity-example-4", "notes-acceleration-example-1",
          "notes-static-force-sample", "gear-pair-20-40", "notes-front-end-loader",
          "inverse-position-slider-crank", "hydraulic-cylinder-boom"]


def svg_texts(svg: str) -> list[str]:
    """Every text element of an SVG as it reads (its tspans joined)."""
    root = ET.fromstring(svg)
    return ["".join(t.itertext()) for t in root.iter() if t.tag.endswith("}text") or t.tag == "text"]


def found(item, texts: list[str]) -> list[str]:
    """The texts where a key item shows: its printed value, its magnitude with unit, or its number as a
    number of its own (not part of a longer one)."""
    number = re.compile(rf"(?<![\d.]){re.escape(item.number_text)}(?![\d])")
    return [t for t in texts if item.text in t or item.magnitude_text in t or number.search(t)]


@pytest.fixture(scope="module", params=SCENES)
def lab(request):
    study = Study(dimensioned(load_scene(ROOT / "gallery" / f"{request.param}.toml"))).run()
    return lab_for(study)


def printed(sheets) -> list[str]:
    """Every text of ``sheets`` as its SVG reads, but a scale bar's graduations: a graduation may read
    500 where an answer is 500 mm/s; it is the scale, not the answer."""
    out = []
    for s in sheets:
        graduations = {t.plain for t in s.texts() if t.name.startswith("scale bar") and " number " in t.name}
        out += [t for t in svg_texts(sheet_to_svg(s)) if t not in graduations]
    return out


def test_the_problem_sheet_holds_no_value_of_the_key(lab):
    assert lab.items
    problem = printed(lab.problem)
    worked = printed(lab.worked)
    for item in lab.items:
        assert found(item, worked), f"the search cannot see {item.text} even on the worked sheet"
        assert found(item, problem) == [], (item.name, item.text, found(item, problem))


def test_the_problem_sheet_writes_blanks_where_answers_go(lab):
    texts = [t for s in lab.problem for t in svg_texts(sheet_to_svg(s))]
    assert any(BLANK in t for t in texts)
    assert any(t.startswith("Find:") or "Find:" in t for t in texts)


def test_no_sense_of_turning_found_on_the_way_is_printed():
    """The Coriolis step of the quick-return names omega_3's sense ("turned 90 deg counter-clockwise, the
    sense of omega_3"): an answer; only the crank's own sense (given) may show."""
    study = Study(dimensioned(load_scene(ROOT / "gallery" / "quick-return-slotted-lever.toml"))).run()
    worked = [s.words for s in study.construction.steps]
    assert any("counter-clockwise, the sense of" in w for w in worked)
    shown, _ = problem_construction(study.construction)
    for step in shown.steps:
        if step.kind.value != "given":
            assert not re.search(r"\b(counter-)?clockwise\b", step.words), step.words
    assert any("Coriolis" in s.words and BLANK in s.words for s in shown.steps)


def test_polygon_panels_are_empty_and_framed_at_the_worked_scales(lab):
    worked = {k: v for s in lab.worked for k, v in s.diagram_scales.items()}
    problem = {k: v for s in lab.problem for k, v in s.diagram_scales.items()}
    assert set(problem) == set(worked)
    for key, scale in worked.items():
        assert problem[key].units_per_mm == pytest.approx(scale.units_per_mm, rel=1e-12), key
    for sheet in lab.problem:
        for key in sheet.diagram_scales:
            if key == "space":
                continue
            region = f"viewport:{key}"
            texts = ["".join(sp.text for sp in t.spans) for t in sheet.texts() if t.region == region]
            heading = [t for t in texts if not re.fullmatch(r"[\d.]+|[A-Za-z/²·]+", t)]
            assert len(heading) == 1, (key, texts)               # the heading and the scale bar only
            frames = [c for c in sheet.commands if c.name == f"{key} drawing area"]
            assert len(frames) == 1
            assert sheet.regions[region].w >= frames[0].w


def test_the_space_diagram_is_dimensioned_and_keeps_only_the_given():
    study = Study(dimensioned(load_scene(ROOT / "gallery" / "notes-velocity-example-1.toml"))).run()
    lab = lab_for(study)
    texts = [t for s in lab.problem for t in svg_texts(sheet_to_svg(s))]
    assert "94 mm" in texts and "50 mm" in texts                  # the links' dimensions
    def space_roles(c):
        return {e.role.value for st in c.steps for e in st.entities if e.diagram.kind == "space"}
    assert "path" in space_roles(study.construction)                 # the locus of C, on the worked sheet ...
    shown, _ = problem_construction(study.construction)
    assert space_roles(shown) == {"given", "label", "dimension"}     # ... not on the problem sheet


def test_the_key_is_one_page_and_a_csv_with_units(lab):
    assert len(lab.key) == 1
    rows = list(csv.reader(io.StringIO(lab.key_csv())))
    assert rows[0][:4] == ["quantity", "kind", "unit", "answer"]
    assert [r[0] for r in rows[1:]] == [i.name for i in lab.items]
    assert all(r[2] or r[1] == "ratio" for r in rows[1:])              # every answer has its unit (a ratio none)
    key_texts = [t for t in svg_texts(sheet_to_svg(lab.key[0]))]
    for item in lab.items:
        assert any(item.text in t for t in key_texts), item.text


def test_render_lab_writes_the_three_documents_and_the_key_csv(tmp_path, capsys):
    scene = ROOT / "gallery" / "notes-velocity-example-1.toml"
    assert main(["render", str(scene), "--lab", "--format", "svg", "-o", str(tmp_path)]) == 0
    stem = scene.stem
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted(
        [f"{stem}-problem.svg", f"{stem}.svg", f"{stem}-key.svg", f"{stem}-key.csv"])
    assert "wrote" in capsys.readouterr().out


def test_a_scene_that_says_dimensions_false_keeps_its_problem_sheet_undimensioned(tmp_path):
    """Problem sheets are dimensioned by default; ``[drawing] dimensions = false`` is honoured."""
    src = (ROOT / "gallery" / "notes-velocity-example-1.toml").read_text()
    assert "dimensions" not in src
    said = tmp_path / "said.toml"
    said.write_text(src.replace("[drawing]\n", "[drawing]\ndimensions = false\n", 1))
    unsaid = load_scene(ROOT / "gallery" / "notes-velocity-example-1.toml")
    assert unsaid.dimensions is None and dimensioned(unsaid).dimensions is True
    scene = load_scene(said)
    assert scene.dimensions is False and dimensioned(scene).dimensions is False
    texts = [t for s in lab_for(Study(dimensioned(scene)).run()).problem for t in svg_texts(sheet_to_svg(s))]
    assert "94 mm" not in texts and "50 mm" not in texts
    with pytest.raises(Exception, match="drawing.dimensions"):
        bad = tmp_path / "bad.toml"
        bad.write_text(src.replace("[drawing]\n", '[drawing]\ndimensions = "yes"\n', 1))
        load_scene(bad)


def test_lab_bare_writes_the_problem_sheet_without_the_step_recipe(tmp_path, capsys):
    """--lab bare: the given data, the dimensioned space diagram and the empty panels; no "Construction"
    steps and no vector equations (``--lab`` keeps them)."""
    scene = ROOT / "gallery" / "notes-velocity-example-1.toml"
    assert main(["render", str(scene), "--lab", "bare", "--format", "svg", "-o", str(tmp_path / "bare")]) == 0
    assert main(["render", str(scene), "--lab", "--format", "svg", "-o", str(tmp_path / "full")]) == 0
    capsys.readouterr()
    bare = " ".join(svg_texts((tmp_path / "bare" / "notes-velocity-example-1-problem.svg").read_text()))
    full = " ".join(svg_texts((tmp_path / "full" / "notes-velocity-example-1-problem.svg").read_text()))
    for words in ("Construction", "Vector equations", "Relative velocity equation", "Draw the crank"):
        assert words in full and words not in bare, words
    for words in ("Given", "Links: O", "Find: V", "Velocity polygon", "94 mm"):
        assert words in bare, words
    assert (tmp_path / "bare" / "notes-velocity-example-1-key.csv").read_text() == \
        (tmp_path / "full" / "notes-velocity-example-1-key.csv").read_text()


def _owners_in(sheet, region: str) -> set[str]:
    """The owners of the commands drawn inside a region of a sheet."""
    from drafting.render.paper import command_points
    r = sheet.regions[region]
    return {c.name.split(":")[0] for c in sheet.commands
            if any(r.contains_point(*p) for p in command_points(c))}


def test_an_inverse_problem_asks_for_its_crank_angles_and_draws_the_frame_alone():
    """The crank angles that put the block at 120 mm are the question: on the problem sheet they are
    blanks and asked for (in Find, the results and the key), and its space diagram draws the frame alone --
    the links drawn at the answer would give it away -- in the room the worked sheet's mechanism takes."""
    study = Study(dimensioned(load_scene(ROOT / "gallery" / "inverse-position-slider-crank.toml"))).run()
    lab = lab_for(study)
    assert {"theta_1", "theta_1'"} <= {i.name for i in lab.items}
    assert any("\u03b8_1" in line for line in lab.given if line.startswith("Find:"))
    space = next(sh for sh in lab.problem if "viewport:space" in sh.regions)
    owners = _owners_in(space, "viewport:space")
    assert {"pivot O1", "guide C"} <= owners
    assert not owners & {"link 1", "link 2", "block 3", "joint B", "crank angle", "inverse crank circle"}
    worked = next(sh for sh in lab.worked if "viewport:space" in sh.regions)
    w_bb = _bounds(worked, "viewport:space", lambda o: o.startswith(("link", "block", "pivot", "guide")))
    p_box = space.regions["viewport:space"]
    assert p_box.w >= w_bb[0] and p_box.h >= w_bb[1]        # room for what the student draws


def _bounds(sheet, region, keep) -> tuple[float, float]:
    from drafting.render.paper import Rect, command_points
    r = sheet.regions[region]
    pts = [p for c in sheet.commands if keep(c.name.split(":")[0]) for p in command_points(c) if r.contains_point(*p)]
    bb = Rect.bounding(pts)
    return bb.w, bb.h


def test_a_driving_slider_problem_asks_for_the_crank_rates():
    """The boom's crank turns as the cylinder drives it: omega_1 and alpha_1 are read off the polygons,
    so the problem sheet asks for them (the worked sheet states them in its numbering step)."""
    study = Study(dimensioned(load_scene(ROOT / "gallery" / "hydraulic-cylinder-boom.toml"))).run()
    lab = lab_for(study)
    assert {"theta_1", "omega_1", "alpha_1"} <= {i.name for i in lab.items}
