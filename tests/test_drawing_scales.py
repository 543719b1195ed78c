"""`[drawing] scale`: a scene states a diagram's scale (issues 23, 24); read without evaluating anything,
held by the sheet, refused in one sentence naming the key."""

from __future__ import annotations

import pytest

from drafting.study.study import Study
from drafting.render.errors import LayoutError
from drafting.scene.reader import SceneError, parse_scene

from paths import GALLERY

BASE = (GALLERY / "notes-velocity-example-1.toml").read_text()


def scene(scale: str):
    return parse_scene(BASE.replace("[drawing]\n", f"[drawing]\nscale = {scale}\n", 1), "scaled.toml")


def test_stated_scales_are_read_as_si_per_paper_mm_and_drawn_so():
    s = scene('{ space = "1:2", velocity = "1 mm = 20 mm/s" }')
    assert dict(s.scales) == pytest.approx({"space": 0.002, "velocity": 0.02})
    (sheet,) = Study(s).sheets()
    scales = sheet.diagram_scales
    assert scales["space"].units_per_mm == pytest.approx(0.002) and scales["velocity"].per_mm == pytest.approx(20)
    assert any(t.plain == "Space diagram 1:2" for t in sheet.texts())
    assert any("1 mm = 20 mm/s" in t.plain for t in sheet.texts())     # the step says the scale it drew at


def test_a_ratio_outside_the_iso_series_is_drawn_as_stated():
    (sheet,) = Study(scene('{ space = "1:2.5" }')).sheets()
    assert sheet.diagram_scales["space"].units_per_mm == pytest.approx(0.0025)
    assert any(t.plain == "Space diagram 1:2.5" for t in sheet.texts())


@pytest.mark.parametrize("scale,key,words", [
    ('{ space = "1 to 2" }', "drawing.scale.space", "is not a ratio"),
    ('{ space = "0:2" }', "drawing.scale.space", "positive"),
    ('{ space = "__import__(\'os\')" }', "drawing.scale.space", "is not a ratio"),
    ('{ velocity = "10 mm/s" }', "drawing.scale.velocity", "what 1 mm stands for"),
    ('{ velocity = "1 mm = 10 N" }', "drawing.scale.velocity", "velocity"),
    ('{ velocity = "1 mm = 2*5 mm/s" }', "drawing.scale.velocity", ""),
    ('{ gears = "1:1" }', "drawing.scale.gears", "unknown key"),
    ('{ space = 2 }', "drawing.scale.space", "must be a string"),
])
def test_a_bad_scale_is_one_sentence_naming_its_key(scale, key, words):
    with pytest.raises(SceneError) as e:
        scene(scale)
    assert str(e.value).startswith(f"scaled.toml: {key}: ") and words in str(e.value), str(e.value)


def test_a_scale_for_a_diagram_the_sheet_does_not_draw_names_its_key():
    with pytest.raises(LayoutError, match=r"drawing\.scale\.acceleration: the sheet draws no acceleration"):
        Study(scene('{ acceleration = "1 mm = 50 mm/s^2" }')).sheets()
