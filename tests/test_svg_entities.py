"""The semantic SVG: each drawn entity a group with a stable, unique id, a class naming its kind (from the
record's entity type) and a title; labels name their owner; the z-order exactly the sheet's."""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET
from functools import lru_cache

import pytest

from constructions import entities as ent
from drafting.backends.svg import sheet_to_svg
from drafting.layout.parts import ENTITY_KINDS, Ids, entity_kinds, part_of, xml_id
from drafting.scene.reader import load_scene
from drafting.study.study import Study
from drafting.study.worked import sheets_for

from paths import GALLERY

NS = "{http://www.w3.org/2000/svg}"
SCENES = ["notes-velocity-example-1", "notes-acceleration-example-1", "four-bar-dalembert", "notes-roller-cam",
          "gear-rack-interference", "quick-return-slotted-lever"]
NCNAME = re.compile(r"[A-Za-z_][A-Za-z0-9_.-]*")


@lru_cache(maxsize=None)
def _solved(name: str):
    study = Study(load_scene(GALLERY / f"{name}.toml")).run()
    return study, sheets_for(study)


def _groups(svg: str) -> list[ET.Element]:
    root = ET.fromstring(svg)
    assert all(el.tag == f"{NS}g" for el in root if el.tag not in (f"{NS}rect", f"{NS}defs"))
    return root.findall(f"{NS}g")


@pytest.mark.parametrize("name", SCENES)
def test_every_drawn_entity_is_a_group_with_its_kind_id_and_title(name):
    study, sheets = _solved(name)
    record = {e.name: e for e in study.construction.entities()}
    ids = Ids(record)
    seen = set()
    for sheet in sheets:
        svg = sheet_to_svg(sheet)
        assert svg == sheet_to_svg(sheet)                                  # the same on every run
        groups = _groups(svg)
        idents = [g.get("id") for g in groups if g.get("id")]
        assert len(idents) == len(set(idents)) and all(NCNAME.fullmatch(i) for i in idents)
        firsts = {g.get("data-entity"): g for g in groups if g.get("id")}
        assert all(g.get("id") == e for e, g in firsts.items())
        drawn = {part_of(c.name, sheet.entities).owner for c in sheet.commands} & set(record)
        seen |= drawn
        for n in drawn:
            e = record[n]
            g = firsts[ids(n)]                                             # its first run carries its id
            assert ids(n) == xml_id(n) or ids(n).startswith(xml_id(n) + "--")
            assert g.get("class").split()[0] == ENTITY_KINDS[type(e)][0]  # the kind: the record's type
            title = g.find(f"{NS}title").text
            assert title.startswith(f"{getattr(e, 'label', None) or e.name} -- ")
        for g in groups:
            kind = g.get("class").split()
            assert kind[0] != "other", g.attrib                            # every command is some part's
            assert all(r.get("class").split()[0] == kind[0] for r in groups if r.get("data-entity") == g.get("data-entity"))
            assert (g.find(f"{NS}title") is not None) == (g.get("id") is not None)
            if kind[1:] == ["label"]:                                      # a label names its owner
                assert g.get("data-for") == g.get("data-entity") in idents
    assert len(seen) >= 10


def test_a_vector_its_label_and_a_split_entity():
    study, (sheet,) = _solved("notes-velocity-example-1")
    groups = _groups(sheet_to_svg(sheet))
    v_b = [g for g in groups if g.get("data-entity") == "V_B"]
    # the shaft, then (above every shaft) the arrowhead, then (above all lines) the label: three runs
    assert [g.get("class") for g in v_b] == ["vector", "vector", "vector label"]
    assert [g.get("id") for g in v_b] == ["V_B", None, None]
    assert v_b[0].find(f"{NS}title").text == "V_B -- known velocity vector"
    assert v_b[2].get("data-for") == "V_B" and v_b[2].find(f".//{NS}text").text == "V"
    joint = [g for g in groups if g.get("data-entity") == "joint-C"]     # named on the space diagram, no dot
    assert len(joint) == 1 and joint[0].get("id") == "joint-C" and joint[0].get("class") == "point label"
    kinds = {k for g in groups for k in g.get("class").split()}
    assert {"vector", "trial-line", "point", "link", "block", "guide", "pivot", "angle", "label", "frame",
            "title-block", "table", "step-text", "scale-bar", "heading", "equation"} <= kinds
    steps = [g.get("id") for g in groups if g.get("class") == "step-text"]
    assert steps == [f"step-{i}" for i in range(1, len(steps) + 1)] and len(steps) >= 5


@pytest.mark.parametrize("name", SCENES[:3])
def test_the_groups_keep_the_order_and_look_of_every_element(name):
    """Without the groups and titles the document is the element list written before: same elements,
    same attributes, same order (nothing drawn changes, the z-order is kept exactly)."""
    _, sheets = _solved(name)
    for sheet in sheets:
        bare = ET.fromstring(sheet_to_svg(sheet, grouped=False))
        grouped = ET.fromstring(sheet_to_svg(sheet))
        flat = [el for g in grouped for el in (g if g.tag == f"{NS}g" else [g]) if el.tag != f"{NS}title"]
        assert [(el.tag, el.attrib, el.text) for el in flat] == [(el.tag, el.attrib, el.text) for el in bare]
        assert ET.tostring(grouped.find(f"{NS}defs")) == ET.tostring(bare.find(f"{NS}defs"))


def test_every_gallery_command_belongs_to_an_entity_or_the_sheets_furniture():
    loose = set()
    for path in sorted(GALLERY.glob("*.toml")):
        study = Study(load_scene(path)).run()
        for sheet in sheets_for(study):
            assert set(sheet.entities) == {e.name for e in study.construction.entities()}
            loose |= {c.name for c in sheet.commands if part_of(c.name, sheet.entities).kind == "other"}
    assert loose == set()


def test_ids_are_valid_stable_and_unique():
    assert xml_id("image b'") == "image-b-prime" and xml_id("\u03c9_2") == "omega-_2"
    assert xml_id("result V_CB") == "result-V_CB" and xml_id("1st") == "e-1st"
    assert xml_id("heading chart: d\u00b2s/d\u03b8\u00b2") == "heading-chart-d2s-d-theta-2"
    assert NCNAME.fullmatch(xml_id("\u22a5 BC")) and "--" not in xml_id("a -- b")
    ids = Ids(["a b", "a-b"])
    assert (ids("a b"), ids("a-b"), ids("a  b"), ids("a b")) == ("a-b", "a-b--2", "a-b--3", "a-b")
    assert ids.claim("a-b") and not ids.claim("a-b")


def test_the_kind_comes_from_the_record_type():
    from constructions.geometry import Vec
    from constructions.record import Construction, Step

    @__import__("dataclasses").dataclass(frozen=True, slots=True)
    class SpringMark(ent.Entity):
        at: Vec = Vec(0.0, 0.0)
    c = Construction("t", (Step("s", entities=(
        ent.Arrow("V_B", ent.Role.KNOWN, ent.Diagram.VELOCITY, Vec(0, 0), Vec(1, 0), label="V_B"),
        ent.Bar("link 2", ent.Role.GIVEN, ent.Diagram.SPACE, Vec(0, 0), Vec(1, 0), 2),
        ent.Point("image c", ent.Role.IMAGE, ent.Diagram.VELOCITY, Vec(0, 0), label="c"),
        SpringMark("spring", ent.Role.GIVEN, ent.Diagram.SPACE))),))
    assert entity_kinds(c) == {"V_B": ("vector", "V_B -- known velocity vector"),
                               "link 2": ("link", "link 2 -- link, space diagram"),
                               "image c": ("point", "c -- image point, velocity diagram"),
                               "spring": ("spring-mark", "spring -- spring mark, space diagram")}
