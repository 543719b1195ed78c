"""[drawing] dimensions = true: the space diagram dimensioned (ISO 129) -- every link joint to joint, the
fixed pivots from the crank's pivot, a guide's offset -- with the scene's own lengths; off by default."""

from __future__ import annotations

import re

import pytest

import drafting
from constructions.entities import Diagram, Dimension
from drafting.scene.reader import SceneError, parse_scene

from paths import GALLERY


def dims(study):
    return {e.name: e for e in study.construction.entities(Diagram.SPACE) if isinstance(e, Dimension)}


def without(name: str) -> str:
    return re.sub(r"^dimensions = .*\n", "", (GALLERY / name).read_text(), flags=re.M)


def with_dimensions(name: str, value: str = "true") -> str:
    return without(name).replace('[drawing]\n', f'[drawing]\ndimensions = {value}\n', 1)


def test_a_four_bar_dimensioned():
    s = drafting.loads(with_dimensions("notes-velocity-example-2.toml"))
    d = dims(s)
    assert set(d) == {"dimension link 1", "dimension link 2", "dimension link 3", "dimension O1O2"}
    step = next(st for st in s.construction.steps if any(isinstance(e, Dimension) for e in st.entities))
    assert {k: v.value for k, v in step.values} == pytest.approx({"l1": 0.010, "l2": 0.035, "l3": 0.020, "gO2": 0.030})
    P = s.get("position").positions
    for k, (a, b) in {"dimension link 2": ("B", "C"), "dimension O1O2": ("O1", "O2")}.items():
        assert {d[k].start, d[k].end} == {P[a], P[b]} and d[k].offset > 0
    assert not dims(drafting.loads(without("notes-velocity-example-2.toml")))          # off by default


def test_an_offset_guide_is_dimensioned():
    s = drafting.loads(with_dimensions("notes-acceleration-example-2.toml").replace(
        "through = [0, 0]", "through = [0, -10]"))
    d = dims(s)
    assert "dimension offset C" in d
    assert (d["dimension offset C"].end - d["dimension offset C"].start).norm() == pytest.approx(0.010)


def test_a_bad_value_is_one_sentence():
    with pytest.raises(SceneError, match="drawing.dimensions: must be true or false"):
        parse_scene(with_dimensions("notes-velocity-example-2.toml", '"yes"'), "x.toml")
