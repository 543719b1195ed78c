"""A slider as the driving input: the crank's omega and alpha read off the polygons from the block's
speed and acceleration along its line, against the slider-crank's closed form (a piston driving the
crank) and the constraint equations (a hydraulic cylinder driving a boom: an inverted slider-crank); the
polygons drawn at those rates give the block the speed and acceleration it was given; the scene keys."""

from __future__ import annotations

import math

import pytest

from constructions.analytic import slider_crank as slider_crank_closed
from constructions.check import analytic_solution
from constructions.errors import DegenerateInput
from constructions.mechanisms.pose import locate
from constructions.polygons.acceleration import acceleration_polygon
from constructions.polygons.driving_slider import along_line, driven_crank
from constructions.polygons.velocity import velocity_polygon
from drafting.scene.reader import SceneError, load_scene, parse_scene
from drafting.study.study import Study

from mechanisms import quick_return, slider_crank
from paths import GALLERY

BOOM = GALLERY / "hydraulic-cylinder-boom.toml"


@pytest.mark.parametrize("theta", [0.4, 1.3, 2.2, 4.0, 5.5])
@pytest.mark.parametrize("v, a", [(-0.5, 2.0), (0.8, 0.0), (0.3, -4.0)])
def test_piston_driving_a_slider_crank_matches_the_closed_form(theta, v, a):
    """omega_1 = v / (ds/dtheta) and alpha_1 = (a - sddot at alpha 0) / (ds/dtheta), the closed form's."""
    m = slider_crank((0, 0), 0.05, 0.12, (0, -0.015), 0.0, 1)
    dc = driven_crank(m, locate(m, theta), 3, v, a)
    kw = dict(crank_pivot=(0, 0), crank=0.05, coupler=0.12, guide_point=(0, -0.015), guide_angle=0.0, branch=1)
    k = float(slider_crank_closed(theta, 1.0, 0.0, **kw).slider_speed)
    omega = v / k
    a0 = float(slider_crank_closed(theta, omega, 0.0, **kw).slider_acceleration)
    assert dc.omega == pytest.approx(omega, rel=1e-9)
    assert dc.alpha == pytest.approx((a - a0) / k, rel=1e-9, abs=1e-9 * omega * omega)
    # the polygons drawn at those rates give the piston what it was given
    va = velocity_polygon(m, locate(m, theta), dc.omega)
    aa = acceleration_polygon(m, va, dc.alpha)
    got = along_line(m, m.blocks()[3], va.pose.positions, va.velocities, va.angular, aa.accelerations, aa.angular)
    assert got[0] == pytest.approx(v, rel=1e-12)
    assert got[1] == pytest.approx(a, abs=1e-9 * max(abs(a), a0, 1.0))


@pytest.mark.parametrize("theta", [0.5, 2.0, 3.5, 5.0])
def test_cylinder_driving_a_crank_matches_the_constraint_equations(theta):
    """The block in the slot of a pivoted link (a cylinder on the crank pin): the rates the polygons give
    make the analytic solution's rod run at the given speed and acceleration along the slot."""
    m = quick_return(ram=False)
    pose = locate(m, theta)
    dc = driven_crank(m, pose, 2, 0.3, -1.0)
    s = m.blocks()[2]
    unit = analytic_solution(m, theta, 1.0, 0.0, accelerations=False, guess=pose.positions)
    k = along_line(m, s, unit.positions, unit.velocities, unit.angular)[0]
    assert dc.rate == pytest.approx(k, rel=1e-9) and dc.omega == pytest.approx(0.3 / k, rel=1e-9)
    sol = analytic_solution(m, theta, dc.omega, dc.alpha, guess=pose.positions)
    v, a = along_line(m, s, sol.positions, sol.velocities, sol.angular, sol.accelerations, sol.angular_acceleration)
    assert v == pytest.approx(0.3, rel=1e-9) and a == pytest.approx(-1.0, rel=1e-9)


def test_a_block_at_dead_centre_cannot_drive():
    m = slider_crank((0, 0), 0.05, 0.12, (0, 0), 0.0, 1)
    with pytest.raises(DegenerateInput, match="dead centre"):
        driven_crank(m, locate(m, 0.0), 3, 0.5)


def test_boom_scene_to_1e_9_and_the_rod_runs_as_given():
    s = Study(load_scene(BOOM)).run()
    v = {c.name: c for c in s.comparisons}
    assert all(c.agrees for c in s.comparisons) and {"omega_1", "alpha_1", "theta_1"} <= set(v)
    for name in ("omega_1", "alpha_1", "theta_1"):
        assert v[name].relative <= 1e-9
    va = s.get("velocity")
    aa = s.get("acceleration")
    m = s.scene.mechanism
    speed, acc = along_line(m, m.blocks()[2], va.pose.positions, va.velocities, va.angular, aa.accelerations,
                            aa.angular)
    assert speed == pytest.approx(0.05, rel=1e-12) and abs(acc) <= 1e-12
    # the boom angle: B on the circle of 600 mm about O1 and of 900 mm about O3 = (200, -500) mm
    d = math.hypot(0.2, -0.5)
    c = (0.6 ** 2 + d * d - 0.9 ** 2) / (2 * 0.6 * d)
    assert v["theta_1"].analytic == pytest.approx(math.atan2(-0.5, 0.2) + math.acos(c), rel=1e-12)
    assert any("Block 2 drives the mechanism at 50 mm/s" in n for n in s.notes)


def test_the_boom_sheet_writes_its_arithmetic_as_a_reader_would():
    """The block's free acceleration is negative: alpha_1 = (0 + 4.615) / 347.8, not (0 - -4.615); and the
    sliding component the polygon closes at is an exact zero left as 8.7e-16 mm/s2 by the arithmetic,
    written 0 (the polygon would draw it 1e-14 mm long)."""
    from drafting.study.worked import sheets_for
    s = Study(load_scene(BOOM)).run()
    words = " ".join(t.plain for sh in sheets_for(s) for t in sh.texts())
    assert "(0 mm/s\u00b2 + 4.615 mm/s\u00b2) \u00f7 347.8 mm/s\u00b2" in words and "\u2212 -" not in words
    assert "AB3Bs = 0 mm/s\u00b2 and AB3 = 8.032 mm/s\u00b2" in words and "e-16 mm/s" not in words


def test_a_value_its_diagram_would_draw_under_a_nanometre_is_written_as_zero():
    from drafting.layout.formats import DiagramScale, SheetFormatter
    from drafting.scene.unitset import Units
    from constructions.record import Value
    fmt = SheetFormatter(Units(), {"acceleration": DiagramScale("acceleration", "acceleration", 1e-4, 0.1, "mm/s^2")})
    assert fmt(Value("acceleration", 8.674e-19)) == fmt(Value("acceleration", 0.0))
    assert fmt(Value("acceleration", 1e-12)) != fmt(Value("acceleration", 0.0))      # 1e-8 mm: drawn, kept
    assert fmt(Value("velocity", 8.674e-19)) != fmt(Value("velocity", 0.0))          # no velocity scale here


@pytest.mark.parametrize("change, key, words", [
    ({'slider_at = "900 mm"': 'angle = "20 deg"'}, "input.slider_at", "needs its stroke position"),
    ({'slider_speed = "50 mm/s"': 'slider_speed = "50 mm/s"\nomega = "1 rad/s"'}, "input.omega",
     "a driving slider sets the crank's motion"),
    ({'slider_speed = "50 mm/s"': 'omega = "1 rad/s"'}, "input.slider_acceleration", "goes with slider_speed"),
])
def test_scene_errors(change, key, words):
    text = BOOM.read_text()
    for old, new in change.items():
        text = text.replace(old, new)
    with pytest.raises(SceneError) as e:
        parse_scene(text, GALLERY / "variant.toml")
    assert e.value.key == key and words in e.value.problem


def test_a_driving_slider_does_not_sweep():
    from drafting.families.linkage.family import _cannot_sweep
    assert "slider_speed" in _cannot_sweep(load_scene(BOOM))
