"""The scene reference: docs/scene-reference.md is what the readers' key tables generate, every key a
scene may write is in its section's table (and a key outside it is refused with the table's keys), and
``drafting new KIND`` writes a scene of each kind that renders."""

from __future__ import annotations

import tomllib
from pathlib import Path

import pytest

from drafting.app.cli import main
from drafting.app.keys_cmd import kind_named
from drafting.app.new_cmd import annotated, examples, template
from drafting.app.reference import common_tables, markdown, text
from drafting.families.linkage import vary as linkage_vary
from drafting.families.registry import families
from drafting.scene import drawing_scales, effects, header_keys, unitset
from drafting.scene.effect_keys import MASS_KEYS
from drafting.scene.keys import QUANTITIES, VALUES, Key, KeyTable
from drafting.scene.reader import COMMON_KEYS, SceneError, scene_from_data

ROOT = Path(__file__).resolve().parents[1]
GALLERY = sorted((ROOT / "gallery").glob("*.toml"))
STARTERS = [(kind, name) for kind in sorted(families()) for name in examples(kind)]


def tables_of(kind: str) -> dict[str, KeyTable]:
    fam = families()[kind]
    return {t.section: t for t in (*fam.keys, *common_tables(fam))}


EXTRA = {   # sections no gallery scene or starter writes, added to a starter
    ("linkage", "slider-crank"): """
[drawing.scale]
space = "1:1"
[[couple]]
name = "M"
link = 2
torque = "1 N m"
sense = "cw"
[[friction]]
slider = 3
mu = 0.1
""",
    ("free body", "pin-and-roller"): """
[[couple]]
name = "M"
torque = "10 N m"
""",
}


def scenes() -> list[tuple[str, dict]]:
    """Every gallery scene, every starter and the starters with the EXTRA sections, as data."""
    out = [(p.name, tomllib.loads(p.read_text(encoding="utf-8"))) for p in GALLERY]
    out += [(f"starter {k} {n}", tomllib.loads(template(k, n))) for k, n in STARTERS]
    out += [(f"starter {k} {n} with more", tomllib.loads(template(k, n) + more)) for (k, n), more in EXTRA.items()]
    guided = template("free body", "pin-and-roller").replace("[[roller]]", "[[guide]]").replace('normal = "90 deg"', 'angle = "0 deg"')
    return out + [("starter free body with a guide", tomllib.loads(guided))]


def test_the_reference_is_what_the_tables_generate():
    doc = (ROOT / "docs" / "scene-reference.md").read_text(encoding="utf-8")
    assert doc == markdown(), "docs/scene-reference.md is stale: drafting keys --markdown > docs/scene-reference.md"


def test_every_section_of_every_kind_has_a_table():
    assert TOP_SECTIONS() == COMMON_KEYS
    assert set(header_keys.KINDS) == set(families())
    for kind, fam in families().items():
        assert {t.section for t in fam.keys} == set(fam.sections), kind
        for t in fam.keys:
            assert t.meaning and all(k.meaning for k in t), (kind, t.section)


def TOP_SECTIONS():
    return header_keys.TOP.allowed


def test_every_key_names_its_unit_and_its_default_is_a_choice():
    every = [t for fam in families().values() for t in (*fam.keys, *common_tables(fam))] + [header_keys.TOP]
    for t in every:
        for k in t:
            assert k.unit in QUANTITIES + VALUES, (t.section, k.name, k.unit)
            if k.choices and isinstance(k.default, str):
                assert k.default in k.choices, (t.section, k.name)
            assert not (k.required and k.default is not None), (t.section, k.name)


def test_the_tables_match_what_the_readers_interpret():
    assert drawing_scales.SCALE.allowed == set(drawing_scales.LENGTH_DIAGRAMS) | set(drawing_scales.POLYGONS)
    assert unitset.UNITS.allowed == set(unitset.KEYS)
    assert {k.name: k.default for k in unitset.UNITS} == unitset.Units().as_dict()
    assert set(effects.DIMENSIONS) <= MASS_KEYS.allowed
    shape = MASS_KEYS.key("shape")
    assert {effects.SHAPE_NAMES[c] for c in shape.choices} == set(effects.SHAPE_NAMES.values())
    vary_heads = {k.name.split(".")[0] for k in header_keys.VARY}
    assert vary_heads == set(linkage_vary.INPUT_KEYS) | set(linkage_vary._NAMED) | {"pivot"}


def _check_keys(where: str, tables: dict[str, KeyTable], section: str, value) -> None:
    t = tables.get(section)
    assert t is not None, f"{where}: [{section}] has no key table"
    items = value if t.array else [value]
    for item in items:
        assert isinstance(item, dict)
        if t.named:
            continue
        for key, v in item.items():
            sub = f"{section}.{key}"
            if sub in tables:                         # [drawing.scale], written inline or as a section
                _check_keys(where, tables, sub, v)
            assert key in t, f"{where}: {section}.{key} is not in the key table of [{section}]"


@pytest.mark.parametrize("where,data", scenes(), ids=lambda x: x if isinstance(x, str) else "")
def test_every_key_a_scene_uses_is_in_its_table(where, data):
    kind = data.get("kind", "linkage")
    tables = tables_of(kind)
    for section, value in data.items():
        assert section in header_keys.TOP or section in families()[kind].sections, (where, section)
        if section == "kind":
            continue
        if section == "vary":
            heads = {k.name.split(".")[0] for k in header_keys.VARY}
            assert set(value) <= heads, where
            continue
        _check_keys(where, tables, section, value)


def _sections_present() -> dict[tuple[str, str], tuple[str, dict]]:
    """(kind, section) -> a scene that has the section (not named, not vary)."""
    out: dict[tuple[str, str], tuple[str, dict]] = {}
    for where, data in scenes():
        scene_from_data(data, where)                  # every one reads
        kind = data.get("kind", "linkage")
        sections = list(data) + (["drawing.scale"] if "scale" in data.get("drawing", {}) else [])
        for section in sections:
            t = tables_of(kind).get(section)
            if t is not None and not t.named and (kind, section) not in out:
                out[(kind, section)] = (where, data)
    return out


@pytest.mark.parametrize("kind,section", sorted(_sections_present()))
def test_a_reader_accepts_exactly_its_tables_keys(kind, section):
    """The reader refuses a key outside the table, listing the table's keys as those allowed here."""
    where, data = _sections_present()[(kind, section)]
    t = tables_of(kind)[section]
    bad = {k: (dict(v) if isinstance(v, dict) else [dict(x) for x in v]) if k == section.split(".")[0] else v
           for k, v in data.items()}
    if section == "drawing.scale":
        bad["drawing"]["scale"] = dict(bad["drawing"]["scale"], zz_not_a_key=1)
    else:
        (bad[section][0] if t.array else bad[section])["zz_not_a_key"] = 1
    with pytest.raises(SceneError) as e:
        scene_from_data(bad, where)
    key = f"{section}[1].zz_not_a_key" if t.array else f"{section}.zz_not_a_key"
    assert e.value.key == key
    assert e.value.problem == f"unknown key; allowed here: {', '.join(sorted(t.allowed))}"


def test_every_kind_and_section_is_read_somewhere():
    """Each kind's gallery and starter scenes between them write every section the kind has (so the
    test above holds each reader to its table)."""
    present = _sections_present()
    for kind, fam in families().items():
        for t in fam.keys:
            if not t.named:
                assert (kind, t.section) in present, (kind, t.section)
    for kind in families():
        for section in ("drawing", "drawing.scale", "units", "ask"):
            assert (kind, section) in present or section == "drawing.scale", (kind, section)
    assert ("linkage", "drawing.scale") in present


@pytest.mark.parametrize("kind", sorted(families()))
def test_keys_prints_every_key_of_a_kind(kind, capsys):
    assert main(["keys", kind.replace(" ", "-")]) == 0
    out = capsys.readouterr().out
    assert out == text(kind)
    for t in tables_of(kind).values():
        assert t.header in out
        for k in t:
            assert f"  {k.name} " in out, (t.section, k.name)


def test_keys_names_a_kind_or_refuses_in_one_sentence(capsys):
    assert kind_named("Gear_Pair") == "gear pair"
    assert main(["keys", "gears"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "'gears' is not a scene kind; choose from cam, free body" in err
    assert main(["keys", "--markdown"]) == 0
    assert capsys.readouterr().out == markdown()


@pytest.mark.parametrize("kind,name", STARTERS)
def test_each_starter_scene_renders(kind, name, tmp_path, capsys):
    scene = tmp_path / "starter.toml"
    args = ["new", kind.replace(" ", "-"), "-o", str(scene)] + (["--example", name] if name else [])
    assert main(args) == 0
    written = scene.read_text(encoding="utf-8")
    assert written == annotated(template(kind, name), families()[kind], name)
    assert tomllib.loads(written) == tomllib.loads(template(kind, name))     # the comments change nothing
    assert main(["render", str(scene), "-o", str(tmp_path / "out"), "--format", "svg"]) == 0
    assert main(["check", str(scene)]) == 0                                  # graphical = analytic
    sheets = sorted((tmp_path / "out").glob("starter*.svg"))
    assert sheets and all(p.stat().st_size > 10_000 for p in sheets)


@pytest.mark.parametrize("kind", sorted(families()))
def test_a_starter_comments_every_key_from_its_table(kind):
    name = examples(kind)[0]
    lines = annotated(template(kind, name), families()[kind], name).splitlines()
    tables = tables_of(kind)
    section = ""
    for line in lines:
        if line.startswith("["):
            section = line.split("]")[0].strip("[")
            continue
        if "=" in line and not line.startswith("#") and section in tables and not tables[section].named:
            key = tables[section].key(line.split("=")[0].strip())
            assert "# " + key.meaning[:30] in " ".join(lines[lines.index(line):lines.index(line) + 3]), line


def test_new_refuses_to_overwrite_a_file(tmp_path, capsys):
    f = tmp_path / "mine.toml"
    f.write_text("kind = \"cam\"\n", encoding="utf-8")
    assert main(["new", "cam", "-o", str(f)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "already exists" in err
    assert f.read_text(encoding="utf-8") == "kind = \"cam\"\n"
    assert main(["new", "cam", "--example", "nothing"]) == 2
    assert "cam has no example 'nothing'; choose from roller" in capsys.readouterr().err


def test_key_tables_refuse_a_key_twice():
    with pytest.raises(ValueError):
        KeyTable("x", "x", (Key("a", "text", None, "a"), Key("a", "text", None, "b")))


def test_the_readme_scene_of_each_kind_solves():
    """README "Scene files" shows one scene of each kind; each reads, solves and agrees with its analytic
    check, and they cover every kind."""
    from drafting.study.study import Study
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    assert "docs/scene-reference.md" in readme.split("## Scene files", 1)[1].split("\n## ", 1)[0]
    part = readme.split("### Cams, gears and free bodies", 1)[1].split("\n### ", 1)[0]
    blocks = [b.split("```", 1)[0] for b in part.split("```toml\n")[1:]]
    kinds = set()
    for block in blocks:
        study = Study(scene_from_data(tomllib.loads(block), "README"))
        kinds.add(study.scene.kind)
        study.run()
        assert study.comparisons and not study.disagreements(), study.scene.kind
    assert kinds == set(families()) - {"linkage"}
