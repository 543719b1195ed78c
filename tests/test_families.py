"""A new scene family plugs in as a package of its own, found through the "drafting.families" entry points:
its own sections, analyses with dependencies, measured and analytic values, construction and JSON -- read,
solved lazily, checked, rendered and exported by the same scene reader, study, CLI and sheets, with no
module of drafting/ touched.  The family is tests/rod_plugin/rod_family.py; the fixture writes the
metadata of a distribution declaring it (a dist-info folder with entry_points.txt) onto sys.path."""

from __future__ import annotations

import json
import sys
from importlib.metadata import entry_points
from pathlib import Path

import pytest

from drafting.families import registry
from drafting.families.registry import FAMILIES, GROUP, family
from drafting.scene.reader import SceneError, parse_scene
from drafting.study.study import Study

PLUGIN = Path(__file__).resolve().parent / "rod_plugin"
KIND = "rod (test)"


SCENE = '''kind = "rod (test)"
[drawing]
title = "A rod"
[rod]
length = 40
[ask]
analyses = ["doubled"]
'''


@pytest.fixture
def rod_family(tmp_path, monkeypatch):
    """The rod family installed as a distribution of its own: its module on sys.path and a dist-info
    declaring it under the entry-point group; drafting finds it when a scene names its kind."""
    info = tmp_path / "rod_family-0.1.dist-info"
    info.mkdir()
    (info / "METADATA").write_text("Metadata-Version: 2.1\nName: rod-family\nVersion: 0.1\n")
    (info / "entry_points.txt").write_text(f"[{GROUP}]\nrod = rod_family:ROD\n")
    monkeypatch.syspath_prepend(str(PLUGIN))
    monkeypatch.syspath_prepend(str(tmp_path))
    assert KIND not in FAMILIES
    yield family(KIND)
    del FAMILIES[KIND]
    sys.modules.pop("rod_family", None)


def test_the_family_is_found_through_its_entry_point(rod_family):
    (ep,) = [ep for ep in entry_points(group=GROUP) if ep.name == "rod"]
    assert ep.value == "rod_family:ROD" and ep.load() is rod_family and rod_family.kind == KIND
    assert registry.families()[KIND] is rod_family
    assert not Path(sys.modules["rod_family"].__file__).is_relative_to(Path(registry.__file__).parents[1])


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


def test_the_built_in_families_are_those_pyproject_declares():
    """A scene of this package's own kinds loads its family without reading the entry points
    (registry.BUILT_IN): the table names the objects of the package's entry points, each under its kind."""
    import tomllib
    pyproject = tomllib.loads((Path(__file__).resolve().parents[1] / "pyproject.toml").read_text())
    assert sorted(registry.BUILT_IN.values()) == sorted(pyproject["project"]["entry-points"][GROUP].values())
    assert all(family(kind).kind == kind for kind in registry.BUILT_IN)
