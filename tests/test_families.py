"""A new scene family plugs in through the registry alone: its own sections, analyses with dependencies,
measured and analytic values, construction and JSON -- read, solved lazily, checked, rendered and
exported by the same scene reader, study, CLI and sheets, with no linkage module touched."""

from __future__ import annotations

import json

import pytest

from constructions.entities import Diagram, Note, Role, Segment
from constructions.geometry import Vec
from constructions.quantities import Measured
from constructions.record import Construction, Value
from drafting.families.registry import FAMILIES, Analysis, Family, register
from drafting.scene.reader import SceneError, parse_scene
from drafting.study.study import Study


def _read(r, units):
    t = r.table("rod", {"length"}, {"length"})
    length = r.quantity("rod.length", t["length"], "length", units)
    if length <= 0:
        raise r.fail("rod.length", "must be positive")
    return {"model": length}


def _drawing(study):
    length = study.scene.model
    rec = Construction("Rod").then("Draw the rod, $l long.",
                                   Segment("rod", Role.GIVEN, Diagram.SPACE, Vec(0, 0), Vec(length, 0)),
                                   Note("note", Role.NOTE, Diagram.SPACE, Vec(length / 2, length / 10), "rod"),
                                   values={"l": Value("length", length)})
    return rec


def _doubled(study):
    return 2 * study.get("rod")


ROD = Family(
    kind="rod (test)",
    analyses={"rod": Analysis("rod", (), lambda study: study.scene.model),
              "doubled": Analysis("doubled", ("rod",), _doubled, label="doubled rod")},
    askable=("rod", "doubled"),
    measured=lambda study: ([Measured("L2", "length", study.get("doubled"))] if study.asked("doubled") else []),
    analytic=lambda study: {"L2": 2 * study.scene.model},
    construction=_drawing,
    json=lambda study: {"doubled_mm": study.scene.units.convert("length", study.get("doubled"))}
    if study.asked("doubled") else {},
    warnings=lambda study: (),
    model_name=lambda study: "twice the length",
    sections=frozenset({"rod"}),
    read=_read,
    default_analyses=("rod",),
)

SCENE = '''kind = "rod (test)"
[drawing]
title = "A rod"
[rod]
length = 40
[ask]
analyses = ["doubled"]
'''


@pytest.fixture
def rod_family():
    register(ROD)
    yield ROD
    del FAMILIES[ROD.kind]


def test_a_new_family_runs_through_reader_study_check_and_json(rod_family, tmp_path, capsys):
    scene = parse_scene(SCENE)
    study = Study(scene)
    assert study.ran == []
    rows = study.comparisons
    assert study.ran == ["rod", "doubled rod"]                 # its dependency ran first, lazily
    assert [r.name for r in rows] == ["L2"] and rows[0].agrees
    assert study.to_json()["doubled_mm"] == pytest.approx(80.0)
    from drafting.app.cli import main
    p = tmp_path / "rod.toml"
    p.write_text(SCENE)
    assert main(["solve", str(p), "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["kind"] == "rod (test)" and data["analyses"] == ["rod", "doubled rod"] and data["check"]["agrees"]
    assert main(["render", str(p), "-o", str(tmp_path / "out"), "--format", "svg"]) == 0
    assert "rod" in (tmp_path / "out" / "rod.svg").read_text()


def test_a_new_family_keeps_its_own_sections(rod_family):
    with pytest.raises(SceneError, match=r"frame: unknown key; a rod \(test\) scene has"):
        parse_scene(SCENE + "\n[frame]\nO1 = [0, 0]\n")
    with pytest.raises(SceneError, match="rod.length: must be positive"):
        parse_scene(SCENE.replace("length = 40", "length = -1"))
    with pytest.raises(SceneError, match="'velocity' is not an analysis; choose from rod, doubled"):
        parse_scene(SCENE.replace('["doubled"]', '["velocity"]'))


def test_unknown_and_planned_kinds_are_named(monkeypatch):
    import drafting.scene.reader
    monkeypatch.setattr(drafting.scene.reader, "PLANNED_KINDS", ("worm gear",))   # every announced kind is built now
    with pytest.raises(SceneError, match="'worm gear' scenes are not available yet"):
        parse_scene('kind = "worm gear"\n')
    with pytest.raises(SceneError, match="'spring' is not a scene kind; choose from cam, free body, gear pair, gear "
                                         "train, linkage"):
        parse_scene('kind = "spring"\n')
