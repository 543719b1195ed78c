"""The inverse position problem: every crank angle that puts a slider at a stroke position, or an output
link at an angle, found on the construction and checked against the closed forms (the crank circle
crossing the coupler's circle about the wanted joint); "no position" in one sentence when out of reach;
and the scene keys that ask for it."""

from __future__ import annotations

import math

import pytest

from constructions.closed_forms import closed_form_inverse
from constructions.errors import DegenerateInput
from constructions.mechanisms.inverse_position import OutputAngle, SliderAt, inverse_position, quantity
from constructions.mechanisms.pose import locate
from drafting.scene.reader import SceneError, load_scene, parse_scene
from drafting.study.study import Study

from mechanisms import four_bar, quick_return, slider_crank
from paths import GALLERY

SCENE = GALLERY / "inverse-position-slider-crank.toml"
TURN = 2 * math.pi


def _agree(found, exact):
    assert len(found) == len(exact)
    for a, b in zip(found, exact):
        assert abs(math.remainder(a - b, TURN)) <= 1e-9 * TURN


@pytest.mark.parametrize("offset, angle, branch", [(0.0, 0.0, 1), (-0.02, 0.0, 1), (0.015, 0.3, 1),
                                                   (0.01, math.pi, -1)])
def test_slider_positions_match_the_closed_form(offset, angle, branch):
    """Over the stroke, both crank angles (one on the stroke out, one back) agree with the circle crossing
    to 1e-9 of a turn, and at each the construction puts the slider where it was wanted."""
    n = (-math.sin(angle), math.cos(angle))
    m = slider_crank((0.0, 0.0), 0.05, 0.1, (offset * n[0], offset * n[1]), angle, branch)
    for s in (0.06, 0.09, 0.12, 0.135) if branch > 0 else (-0.06, -0.09, -0.12):
        t = SliderAt(3, s)
        found = inverse_position(m, t)
        exact = closed_form_inverse(m, t)
        assert len(found.solutions) == 2
        _agree(found.solutions, exact)
        for th in found.solutions:
            assert quantity(m, t, locate(m, th).positions) == pytest.approx(s, abs=1e-12)


def test_output_angle_matches_the_closed_form():
    m = four_bar((0, 0), (0.08, 0), 0.03, 0.09, 0.07, 1)
    for deg in (80, 95, 110, 125):
        t = OutputAngle(3, math.radians(deg))
        found = inverse_position(m, t)
        _agree(found.solutions, closed_form_inverse(m, t))
        assert len(found.solutions) == 2
        for th in found.solutions:
            assert abs(math.remainder(quantity(m, t, locate(m, th).positions) - t.angle, TURN)) <= 1e-12


def test_out_of_reach_says_so_in_one_sentence_with_the_stroke():
    """The in-line stroke runs from l - r to l + r; beyond it there is no solution and the sentence names
    the travel, its ends found on the construction to 1e-9."""
    m = slider_crank((0, 0), 0.05, 0.1, (0, 0), 0.0, 1)
    found = inverse_position(m, SliderAt(3, 0.2))
    assert found.solutions == () and closed_form_inverse(m, SliderAt(3, 0.2)) == ()
    (lo, hi), = found.reach
    assert lo == pytest.approx(0.05, rel=1e-9) and hi == pytest.approx(0.15, rel=1e-9)
    text = found.describe()
    assert text.startswith("No position:") and text.count(".") == 4 and "0.05 m to 0.15 m" in text


def test_rocker_reach_is_its_swing():
    """A crank-rocker's rocker swings between the positions where crank and coupler lie in line:
    |O1C| = l - r and l + r."""
    o2, r, l, r3 = (0.08, 0.0), 0.03, 0.09, 0.07
    m = four_bar((0, 0), o2, r, l, r3, 1)
    found = inverse_position(m, OutputAngle(3, 0.0))
    assert found.solutions == ()
    (lo, hi), = found.reach

    def rocker_angle(dist):          # C on circle (O1, dist) and (O2, r3), above the frame
        d = o2[0]
        x = (dist ** 2 - r3 ** 2 + d ** 2) / (2 * d)
        return math.atan2(math.sqrt(dist ** 2 - x ** 2), x - d)
    ends = sorted((rocker_angle(l - r), rocker_angle(l + r)))
    assert lo == pytest.approx(ends[0], rel=1e-9) and hi == pytest.approx(ends[1], rel=1e-9)


def test_a_six_bar_ram_by_the_construction():
    """No closed form for the quick-return's ram: the solutions are where the construction puts it there,
    one on the cutting stroke and one on the return."""
    m = quick_return()
    t = SliderAt(5, 0.03)
    found = inverse_position(m, t)
    assert closed_form_inverse(m, t) is None
    assert len(found.solutions) == 2
    for th in found.solutions:
        assert quantity(m, t, locate(m, th).positions) == pytest.approx(0.03, abs=1e-12)


def test_a_target_that_is_no_block_on_a_guide():
    with pytest.raises(DegenerateInput, match="no slider block 7"):
        inverse_position(slider_crank((0, 0), 0.05, 0.1, (0, 0), 0.0, 1), SliderAt(7, 0.1))
    with pytest.raises(DegenerateInput, match="is the crank"):
        inverse_position(four_bar((0, 0), (0.08, 0), 0.03, 0.09, 0.07, 1), OutputAngle(1, 0.1))


# -- the scene ----------------------------------------------------------------------------------------

def test_gallery_scene_lists_both_and_draws_the_first_to_1e_9():
    s = Study(load_scene(SCENE)).run()
    v = {c.name: c for c in s.comparisons}
    a, b = v["theta_1"], v["theta_1'"]
    d = math.hypot(120, 20)                       # the scene header's working: C = (120, -20) mm
    x = (d * d + 50 ** 2 - 100 ** 2) / (2 * d)
    u, w = math.atan2(-20, 120), math.atan2(math.sqrt(50 ** 2 - x * x), x)
    assert a.analytic == pytest.approx(u + w, rel=1e-12) and b.analytic == pytest.approx(u - w + TURN, rel=1e-12)
    assert math.degrees(a.analytic) == pytest.approx(43.66, abs=0.005)
    assert all(c.agrees for c in s.comparisons)
    assert s.scene.angle == a.graphical
    assert any("2 crank angles put block 3 at 120 mm" in n for n in s.notes)


def _scene(**changes) -> str:
    text = SCENE.read_text()
    for old, new in changes.items():
        text = text.replace(old, new)
    return text


def test_solution_2_draws_the_other():
    s = parse_scene(_scene(**{"solution = 1 ": "solution = 2 "}), GALLERY / "variant.toml")
    assert math.degrees(s.angle) == pytest.approx(297.41, abs=0.005) and s.solution == 2


@pytest.mark.parametrize("change, key, words", [
    ({'slider_at = "120 mm"': 'slider_at = "160 mm"'}, "input.slider_at", "No position: over a turn"),
    ({"solution = 1 ": "solution = 3 "}, "input.solution", "must be 1 to 2"),
    ({"solution = 1 ": "solution = 0 "}, "input.solution", "whole number from 1"),
    ({'slider_at = "120 mm"': 'slider_at = "120 mm"\nangle = "30 deg"'}, "input", "exactly one of angle"),
    ({'slider_at = "120 mm"': 'slider_at = "120 mm"\nslider = 4'}, "input.slider", "no block 4"),
    ({'slider_at = "120 mm"': 'output_angle = "10 deg"'}, "input.output", "name the link"),
])
def test_scene_errors_name_the_key(change, key, words):
    with pytest.raises(SceneError) as e:
        parse_scene(_scene(**change), GALLERY / "variant.toml")
    assert e.value.key == key and words in e.value.problem


def test_output_angle_in_a_four_bar_scene():
    text = """
[frame]
O1 = [0, 0]
O2 = [80, 0]
[[link]]
number = 1
joints = ["O1", "B"]
length = 30
[[link]]
number = 2
joints = ["B", "C"]
length = 90
[[link]]
number = 3
joints = ["O2", "C"]
length = 70
[input]
link = 1
output_angle = "100 deg"
solution = 2
omega = "10 rad/s"
[assembly]
C = "left of B->O2"
[ask]
analyses = ["acceleration"]
"""
    s = Study(parse_scene(text, GALLERY / "four-bar.toml")).run()
    v = {c.name: c for c in s.comparisons}
    exact = closed_form_inverse(s.scene.mechanism, OutputAngle(3, math.radians(100)))
    assert s.scene.angle == v["theta_1'"].graphical
    assert v["theta_1'"].analytic == exact[1]
    assert all(c.agrees for c in s.comparisons)
