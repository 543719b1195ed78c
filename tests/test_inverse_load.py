"""A load given as a gas pressure on a bore (F = p pi d^2 / 4 along the line of stroke), and a load as the
unknown a given driving torque holds (the inverse static problem): found by the equilibrium of all links,
checked by virtual work, and returning the given torque when the forward problem is solved with it."""

from __future__ import annotations

import math

import pytest

from constructions.errors import DegenerateInput
from constructions.forces.equilibrium import equilibrium, virtual_work_torque
from constructions.forces.inverse import load_for_torque, with_load
from drafting.api import loads
from drafting.scene.reader import SceneError, parse_scene

from paths import ROOT
from test_force_results import engine

SAMPLE = (ROOT / "gallery" / "notes-static-force-sample.toml").read_text()
# the notes' compressor: P = 40 N on the piston holds T = 1.118 N m CW at 45 deg


def test_pressure_on_a_bore_is_p_pi_d2_over_4_along_the_stroke():
    st = loads(engine(load='pressure = "2 MPa"\nbore = "80 mm"'))
    p = st.scene.effects.loads[0]
    assert p.force.x == pytest.approx(-2e6 * math.pi * 0.080**2 / 4, rel=1e-12) and p.force.y == 0.0
    assert p.given == "P = p \u03c0 d\u00b2/4 = 2 MPa \u00d7 \u03c0 (80 mm)\u00b2/4 = 10053 N along the line of stroke, at 180\u00b0"
    words = st.get("forces").construction.steps[0].words
    assert p.given in words and "along the line of stroke, at 180\u00b0" in words
    same = loads(engine(load='force = "%r N"' % (2e6 * math.pi * 0.080**2 / 4)))
    assert st.results["T_2"].graphical == pytest.approx(same.results["T_2"].graphical, rel=1e-12)
    bar = loads(engine(load='pressure = "20 bar"\nbore = "80 mm"')).scene.effects.loads[0]
    assert bar.force == p.force and "20 bar" in bar.given


@pytest.mark.parametrize("load, key, words", [
    ('pressure = "2 MPa"', "load[1].bore", "is missing"),
    ('pressure = "2 MPa"\nbore = "80 mm"\nforce = "3 N"', "load[1].pressure", "only one of them"),
    ('force = "3 N"\nbore = "80 mm"', "load[1].bore", "give pressure too"),
    ('pressure = "-2 MPa"\nbore = "80 mm"', "load[1].pressure", "must be positive"),
    ('pressure = "2 N"\nbore = "80 mm"', "load[1].pressure", "pressure"),
    ('force = "3 N"\nsense = "cw"', "load[1].sense", "only with torque"),
    ('', "load[1].force", "is missing"),
])
def test_bad_pressure_and_torque_loads_are_one_sentence(load, key, words):
    with pytest.raises(SceneError) as e:
        parse_scene(engine(load=load))
    assert key in str(e.value) and words in str(e.value)


def test_a_pressure_must_push_along_the_line_of_stroke():
    text = engine(load='pressure = "2 MPa"\nbore = "80 mm"').replace('angle = "180 deg"', 'angle = "170 deg"')
    with pytest.raises(SceneError, match=r"load\[1\]\.angle.*line of stroke"):
        parse_scene(text)
    on_link = engine(load='pressure = "2 MPa"\nbore = "80 mm"').replace('link = 4\nat = "C"', 'link = 3\nat = "C"')
    with pytest.raises(SceneError, match=r"load\[1\]\.pressure.*slider block"):
        parse_scene(on_link)


def test_inverse_of_the_notes_compressor_returns_its_load():
    forward = loads(SAMPLE)
    t = forward.results["T_2"].graphical
    assert t == pytest.approx(-1.118, abs=5e-4)                       # the notes' 1.12 N m CW
    inverse = loads(SAMPLE.replace('force = "40 N"', f'torque = "{abs(t)!r} N m"\nsense = "cw"'))
    p = inverse.results["P"]
    assert p.graphical.x == pytest.approx(-40.0, rel=1e-9) and p.analytic.x == pytest.approx(-40.0, rel=1e-9)
    assert inverse.results["T_2"].graphical == pytest.approx(t, rel=1e-9)
    assert all(c.agrees for c in inverse.comparisons)
    assert any(n.startswith("P is the unknown") for n in inverse.notes)


@pytest.mark.parametrize("angle", ["30 deg", "60 deg", "135 deg", "250 deg"])
def test_inverse_then_forward_returns_the_torque_with_friction_and_inertia(angle):
    st = loads(engine(load='torque = "300 N m"\nsense = "cw"', angle=angle))
    s, e = st.scene, st.scene.effects
    guess = st.get("position").positions
    f = load_for_torque(s.mechanism, s.angle, s.omega, s.alpha, e, guess=guess)
    g = load_for_torque(s.mechanism, s.angle, s.omega, s.alpha, e, guess=guess, by="virtual work")
    assert f == pytest.approx(g, rel=1e-9)
    solved = with_load(e, f)
    eq = equilibrium(s.mechanism, s.angle, s.omega, s.alpha, solved, guess=guess)
    vw = virtual_work_torque(s.mechanism, s.angle, s.omega, s.alpha, solved, friction=eq.friction, guess=guess)
    assert eq.torque == pytest.approx(-300.0, rel=1e-9) and vw == pytest.approx(-300.0, rel=1e-9)
    assert st.results["T_2"].graphical == pytest.approx(-300.0, rel=1e-9)          # read off the polygons
    # and the forward scene with that load as a force gives the torque back
    mag, ang = abs(f), "180 deg" if f > 0 else "0 deg"
    fwd = loads(engine(load=f'force = "{mag!r} N"', angle=angle).replace('angle = "180 deg"', f'angle = "{ang}"'))
    assert fwd.results["T_2"].graphical == pytest.approx(-300.0, rel=1e-9)
    assert all(c.agrees for c in st.comparisons)


def test_one_unknown_load_and_no_torque_twice():
    two = engine(load='torque = "3 N m"') + '[[load]]\nname = "Q"\nlink = 3\nat = "B"\ntorque = "1 N m"\nangle = "0 deg"\n'
    with pytest.raises(SceneError, match=r"load\[2\]\.torque.*already the load to be found"):
        parse_scene(two)
    both = engine(load='torque = "3 N m"').replace('sense = "ccw"', 'sense = "ccw"\ntorque = "2 N m"')
    with pytest.raises(SceneError, match=r"input\.torque.*not both"):
        parse_scene(both)


def test_a_load_that_does_no_work_cannot_be_found():
    text = engine().split("[[mass]]")[0] + (     # square to a frictionless guide: the guide takes it all
        '[[load]]\nname = "P"\nlink = 4\nat = "C"\ntorque = "3 N m"\nangle = "90 deg"\n[ask]\nanalyses = ["forces"]\n')
    s = parse_scene(text)
    with pytest.raises(DegenerateInput, match="does no work on the crank"):
        load_for_torque(s.mechanism, s.angle, s.omega, s.alpha, s.effects)
