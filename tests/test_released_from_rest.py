"""A mechanism at rest and a crank driven by a given torque: the notes' dynamic Example 1 (a rod released
from rest) through the whole pipeline, exactly, and the scene input that goes with it."""

from __future__ import annotations

import math
import re

import pytest

from constructions.entities import Diagram
from constructions.geometry import Vec
from drafting.app.cli import main
from drafting.scene.reader import SceneError, load_scene, parse_scene
from drafting.study.study import Study

from paths import GALLERY
EXAMPLE_1 = GALLERY / "notes-dynamic-example-1.toml"
G, MASS, L = 9.81, 1.0, 1.0


def rod(text: str = None, angle: str = "0 deg") -> Study:
    text = (text or EXAMPLE_1.read_text()).replace('angle = "0 deg"\nomega', f'angle = "{angle}"\nomega')
    return Study(parse_scene(text, GALLERY / "variant.toml")).run()


def values(s: Study) -> dict:
    return {c.name: c for c in s.comparisons}


def test_notes_example_1_exactly():
    """alpha = 12 g / (7 L) clockwise and the pivot force 4 m g / 7 straight up (the notes' answers),
    read off the force polygon drawn with that alpha; the torque it needs is zero, as given."""
    s = Study(load_scene(EXAMPLE_1)).run()
    v = values(s)
    assert v["alpha_2"].graphical == pytest.approx(-12 * G / (7 * L), rel=1e-12)
    assert v["alpha_2"].analytic == pytest.approx(-12 * G / (7 * L), rel=1e-12)   # by virtual work
    f = v["F_12"].graphical                                       # the frame's force on the rod, at A
    assert f.y == pytest.approx(4 * MASS * G / 7, rel=1e-12) and abs(f.x) <= 1e-12 * MASS * G
    assert abs(v["T_2"].graphical) <= 1e-12 * MASS * G * L
    assert all(c.agrees for c in s.comparisons)
    assert "alpha from the torque" in s.ran and "alpha by virtual work" in s.ran
    # at rest the velocity polygon is not drawn, and no normal component is listed as measured
    assert not list(s.construction.entities(Diagram.VELOCITY))
    assert "A_B^n" not in v and "V_B" not in v
    assert "released from rest" in " ".join(s.notes)


@pytest.mark.parametrize("theta", [30.0, -50.0, 120.0])
def test_released_at_an_angle(theta):
    """Released at theta to the horizontal: alpha = -12 g cos(theta) / (7 L) and the pivot force
    m a_G + m g j with a_G = alpha k x AG (no normal part at rest)."""
    s = rod(angle=f"{theta} deg")
    v = values(s)
    t = math.radians(theta)
    alpha = -12 * G * math.cos(t) / (7 * L)
    assert v["alpha_2"].graphical == pytest.approx(alpha, rel=1e-12)
    a_g = Vec(-math.sin(t), math.cos(t)) * (alpha * L / 4)
    want = a_g * MASS + Vec(0.0, MASS * G)
    got = v["F_12"].graphical
    assert (got - want).norm() <= 1e-12 * MASS * G
    assert all(c.agrees for c in s.comparisons)


def test_a_torque_on_the_crank_drives_it():
    """A given couple T on the rod adds T / I_A to alpha (I_A = 7 m L^2 / 48)."""
    text = EXAMPLE_1.read_text().replace('torque = "0 N m"', 'torque = "2 N m"')
    s = rod(text)
    want = (-MASS * G * L / 4 + 2.0) / (7 * MASS * L * L / 48)
    assert values(s)["alpha_2"].graphical == pytest.approx(want, rel=1e-12)
    assert values(s)["T_2"].graphical == pytest.approx(2.0, rel=1e-9)


def test_a_static_scene_at_rest_is_the_static_scene():
    """omega = 0 is allowed; a static analysis does not depend on it."""
    text = (GALLERY / "notes-static-force-sample.toml").read_text()
    moving = Study(parse_scene(text, GALLERY / "a.toml")).run()
    still = Study(parse_scene(text.replace('omega = "10 rad/s"', 'omega = "0 rad/s"'), GALLERY / "b.toml")).run()
    assert values(still)["T_2"].graphical == pytest.approx(values(moving)["T_2"].graphical, rel=1e-12)


def _error(text: str) -> str:
    with pytest.raises(SceneError) as e:
        parse_scene(text, "rod.toml")
    msg = str(e.value)
    assert msg.startswith("rod.toml: ") and "\n" not in msg
    return msg


def test_scene_input_is_checked():
    base = EXAMPLE_1.read_text()
    msg = _error(base.replace('torque = "0 N m"', 'torque = "0 N m"\nalpha = "1 rad/s^2"'))
    assert "input:" in msg and "not both" in msg
    msg = _error(re.sub(r"\[\[mass\]\].*?\n\n", "", base, flags=re.S))
    assert "input.torque" in msg and "[[mass]]" in msg
    msg = _error(base.replace('omega = "0 rad/s"', 'omega = "0 rad/s"\nsense = "cw"'))
    assert "input.sense" in msg and "at rest" in msg
    msg = _error(base.replace('torque = "0 N m"', 'torque = "3 kg"'))
    assert "input.torque" in msg


def test_cli_renders_it_and_sweep_says_why_not(tmp_path, capsys):
    assert main(["render", str(EXAMPLE_1), "-o", str(tmp_path), "--format", "svg"]) == 0
    assert "agree to 1e-9 relative" in capsys.readouterr().out
    assert main(["sweep", str(EXAMPLE_1), "--steps", "4"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "input.torque" in err and "Traceback" not in err
