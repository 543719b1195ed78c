"""The space diagram's conventions (issue 23): link numbers, the driver's omega and alpha arrows, shaded
plates, a slotted lever through its block, the instant centres off the drawing, and every point of a
vector polygon reached by its vector."""

from __future__ import annotations

import math
from pathlib import Path

from constructions.entities import AngleMark, Arrow, Bar, Block, Diagram, LinkNumber, Plate, Point, Role
from constructions.mechanisms.topology import frame_number
from drafting.layout.diagram import draw_entities
from drafting.render.paper import Line, Polygon
from drafting.scene.reader import load_scene
from drafting.study.study import Study

ROOT = Path(__file__).resolve().parents[1]

WHITWORTH = ROOT / "gallery" / "quick-return-slotted-lever.toml"


def _study(name: str) -> Study:
    return Study(load_scene(ROOT / "gallery" / f"{name}.toml")).run()


def _space(study) -> list:
    return list(study.construction.entities(Diagram.SPACE))


def test_every_link_block_and_the_frame_has_its_number():
    for name in ("stephenson-six-bar", "quick-return-slotted-lever", "notes-acceleration-example-2"):
        s = _study(name)
        m = s.scene.mechanism
        got = {e.number for e in _space(s) if isinstance(e, LinkNumber)}
        want = {k.number for k in m.links} | set(m.blocks()) | {frame_number(m)}
        assert got == want, name
        d = draw_entities(_space(s), 1.0)
        assert {r.markup for r in d.labels if r.name.startswith("number ")} == {str(n) for n in want}


def test_the_omega_arrow_turns_in_the_sense_of_omega(tmp_path):
    text = (ROOT / "gallery" / "notes-acceleration-example-2.toml").read_text()
    for sense, sign in (("ccw", 1.0), ("cw", -1.0)):
        scene = tmp_path / f"{sense}.toml"
        scene.write_text(text.replace('sense = "ccw"', f'sense = "{sense}"'))
        s = Study(load_scene(scene)).run()
        marks = {e.name: e for e in _space(s) if isinstance(e, AngleMark)}
        n = s.scene.mechanism.crank
        w, a = marks[f"omega {n}"], marks[f"alpha {n}"]
        assert math.copysign(1.0, w.end_angle - w.start_angle) == math.copysign(1.0, s.scene.omega) == sign
        assert math.copysign(1.0, a.end_angle - a.start_angle) == math.copysign(1.0, s.scene.alpha)
        assert w.vertex == s.get("position").positions[s.scene.mechanism.crank_pivot()]


def test_no_alpha_arrow_without_alpha():
    s = _study("quick-return-slotted-lever")              # alpha = 0
    names = {e.name for e in _space(s) if isinstance(e, AngleMark)}
    assert "omega 1" in names and "alpha 1" not in names


def test_a_ternary_link_is_a_filled_plate_with_its_outline():
    s = _study("stephenson-six-bar")
    plates = [e for e in _space(s) if isinstance(e, Plate)]
    assert plates
    cmds = draw_entities(_space(s), 1.0).commands
    for p in plates:
        styles = {c.style for c in cmds if isinstance(c, Polygon) and c.name in (p.name, f"{p.name}:plate")}
        assert styles == {"band", "link"}


WHITWORTH_SCENE = """
[drawing]
title = "Whitworth quick-return"
number = "T-W"
paper = "A4"
[units]
length = "mm"
velocity = "mm/s"
acceleration = "m/s^2"
angular_velocity = "rad/s"
angular_acceleration = "rad/s^2"
[frame]
O1 = [0, 40]
O2 = [0, 0]
[[link]]
number = 1
joints = ["O1", "A"]
length = 100
[[link]]
number = 3
joints = ["O2", "P"]
length = 100
[[link]]
number = 4
joints = ["P", "Q"]
length = 220
[[slider]]
number = 2
joint = "A"
on = 3
[[slider]]
number = 5
joint = "Q"
through = [0, 130]
angle = "0 deg"
[input]
link = 1
angle = "-110 deg"
omega = "10 rad/s"
sense = "ccw"
[assembly]
A = "behind O2"
Q = "behind P"
[ask]
analyses = ["velocity"]
"""


def test_the_slotted_lever_runs_through_its_block_beyond_the_pivot(tmp_path):
    scene = tmp_path / "whitworth.toml"
    scene.write_text(WHITWORTH_SCENE)
    s = Study(load_scene(scene)).run()
    pos = s.get("position").positions
    assert (pos["A"] - pos["O2"]).dot(pos["P"] - pos["O2"]) < 0       # the block beyond the pivot
    ents = _space(s)
    k = 2.0
    lever = next(c for c in draw_entities(ents, k).commands if isinstance(c, Line) and c.name == "link 3")
    block = next(e for e in ents if isinstance(e, Block) and e.link == 2)
    bx, by = block.at.x * k, -block.at.y * k
    ax, ay, cx, cy = lever.x1, lever.y1, lever.x2, lever.y2
    ux, uy = cx - ax, cy - ay
    t = ((bx - ax) * ux + (by - ay) * uy) / (ux * ux + uy * uy)
    assert 0.0 < t < 1.0                                                 # the drawn segment holds the block
    assert abs((bx - ax) * uy - (by - ay) * ux) / math.hypot(ux, uy) < 1e-6
    bar = next(e for e in ents if isinstance(e, Bar) and e.name == "link 3")
    assert {bar.start, bar.end} == {pos["O2"], pos["P"]}                 # the record's link is unchanged


def test_a_sliders_centre_at_infinity_and_a_far_centre_are_pointed_at():
    s = _study("instant-centres-slider-crank")
    arrows = {e.name: e for e in s.get("instant centres").construction.entities() if isinstance(e, Arrow)}
    inf = arrows["ic I_03 at infinity"]
    assert "\u221e" in inf.label and "guide" in inf.label
    assert abs((inf.tip - inf.tail).x) < 1e-12                          # square to the horizontal guide
    ic = s.get("instant centres")
    far = ic.centres[(0, 2)]
    off = arrows["ic I_02 off the drawing"]
    assert off.label == "I_02 at ($x, $y)"
    assert (off.tip - off.tail).unit().dot((far.at - off.tail).unit()) > 1 - 1e-9   # towards the centre
    drawn = {e.name for e in ic.construction.entities() if isinstance(e, Point)}
    assert "ic I_02" not in drawn


def test_every_point_of_a_polygon_is_reached_by_its_vector():
    for name in ("quick-return-slotted-lever", "stephenson-six-bar", "notes-acceleration-example-2"):
        s = _study(name)
        for dg in (Diagram.VELOCITY, Diagram.ACCELERATION):
            ents = list(s.construction.entities(dg))
            tips = [e.tip for e in ents if isinstance(e, Arrow)]          # reached: an arrowhead on it
            for p in (e for e in ents if isinstance(e, Point) and e.role is Role.LABEL and not e.name.startswith("pole")):
                assert any((p.at - t).norm() <= 1e-9 * max(1.0, p.at.norm()) for t in tips), (name, dg, p.name)
