"""The force results a student is asked for: the inertia forces, couples and offsets (F_I = -m a_G,
C_I = -I_G alpha, h = |C_I| / |F_I|) and the friction forces in the results and the JSON, each against its
closed form; the driving torque named T_12 with whether the motor drives or brakes; the warning when
nothing loads the mechanism."""

from __future__ import annotations

import math

import pytest

from constructions.forces.dalembert import InertiaLoad
from constructions.geometry import Vec
from drafting.api import loads
from drafting.families.linkage.force_output import power_role

R, L, OFFSET = 0.060, 0.240, 0.020          # crank, rod, offset of the line of stroke (m)
W, THETA = 200.0, math.radians(60)
M3, I3, M4, MU = 1.2, 0.006, 0.9, 0.1


def engine(extra: str = "", *, sense: str = "ccw", load: str = 'force = "8 kN"', angle: str = "60 deg") -> str:
    """An offset engine: crank 2 (60 mm), rod 3 (240 mm, 1.2 kg, 0.006 kg m^2), piston 4 (0.9 kg) on a
    line of stroke 20 mm above the crank pivot, mu = 0.1, the gas load P towards the crank."""
    return f"""
[drawing]
title = "Offset engine"
[units]
length = "mm"
acceleration = "m/s^2"
[frame]
O2 = [0, 0]
[[link]]
number = 2
joints = ["O2", "B"]
length = 60
[[link]]
number = 3
joints = ["B", "C"]
length = 240
[[slider]]
number = 4
joint = "C"
through = [0, 20]
angle = "0 deg"
[input]
link = 2
angle = "{angle}"
omega = "200 rad/s"
sense = "{sense}"
[assembly]
C = "ahead of B"
[[mass]]
link = 3
mass = "1.2 kg"
inertia = "0.006 kg*m^2"
[[mass]]
link = 4
mass = "0.9 kg"
[[friction]]
slider = 4
mu = 0.1
[[load]]
name = "P"
link = 4
at = "C"
{load}
angle = "180 deg"
[ask]
analyses = ["forces"]
{extra}"""


def closed_form(theta: float, omega: float):
    """The offset slider-crank by its closed form at constant omega: the piston's x, velocity and
    acceleration, the rod's angle phi (sin phi = (e - r sin theta) / l), its angular velocity and
    acceleration, and the acceleration of the rod's middle."""
    s = R * math.sin(theta)
    root = math.sqrt(L * L - (OFFSET - s) ** 2)
    phi = math.asin((OFFSET - s) / L)
    # phi' and phi'' by differentiating l sin phi = e - r sin theta twice
    dphi = -R * math.cos(theta) * omega / (L * math.cos(phi))
    ddphi = (R * math.sin(theta) * omega**2 + L * math.sin(phi) * dphi**2) / (L * math.cos(phi))
    a_b = Vec(-R * math.cos(theta), -R * math.sin(theta)) * omega**2
    # C = B + l (cos phi, sin phi): a_C = a_B + l (phi'' (-sin, cos) - phi'^2 (cos, sin))
    rel = Vec(-math.sin(phi), math.cos(phi)) * (L * ddphi) - Vec(math.cos(phi), math.sin(phi)) * (L * dphi**2)
    a_c = a_b + rel
    v_c = -R * math.sin(theta) * omega - L * math.sin(phi) * dphi
    return dict(x=R * math.cos(theta) + root, v_c=v_c, a_c=a_c, a_g=a_b + rel * 0.5, alpha=ddphi)


def test_inertia_forces_couples_and_offsets_against_the_closed_form():
    st = loads(engine())
    cf = closed_form(THETA, W)
    res = st.results
    assert res["F_I4"].graphical.x == pytest.approx(-M4 * cf["a_c"].x, rel=1e-9)
    assert abs(res["F_I4"].graphical.y) <= 1e-9 * M4 * cf["a_c"].norm()
    f3 = res["F_I3"].graphical
    assert (f3.x, f3.y) == pytest.approx((-M3 * cf["a_g"].x, -M3 * cf["a_g"].y), rel=1e-9)
    assert res["C_I3"].graphical == pytest.approx(-I3 * cf["alpha"], rel=1e-9)
    assert res["h_I3"].graphical == pytest.approx(I3 * abs(cf["alpha"]) / (M3 * cf["a_g"].norm()), rel=1e-9)
    assert "C_I4" not in res and "h_I4" not in res            # a point mass has no couple
    for name in ("F_I3", "C_I3", "h_I3", "F_I4"):
        assert res[name].agrees, name


def test_friction_force_is_mu_n_against_the_sliding():
    st = loads(engine())
    cf = closed_form(THETA, W)
    res = st.results
    total, fr = res["F_14"].graphical, res["F_14^f"].graphical
    assert fr.y == 0.0 and abs(fr.x) == pytest.approx(MU * abs(total.y), rel=1e-9)   # mu |N| along the guide
    assert math.copysign(1, fr.x) == -math.copysign(1, cf["v_c"])                    # against the sliding
    assert total.x == pytest.approx(fr.x, rel=1e-12) and res["F_14^f"].agrees


def test_the_offset_line_of_the_inertia_force_carries_the_couple():
    il = InertiaLoad(3, "G3", 2.0, Vec(30.0, -40.0), 7.5)
    d = il.shift()
    assert d.dot(il.force) == pytest.approx(0.0, abs=1e-12)           # square to the force
    assert d.cross(il.force) == pytest.approx(il.couple, rel=1e-12)   # its moment about G is the couple
    assert il.offset == pytest.approx(7.5 / 50.0, rel=1e-12) == pytest.approx(d.norm(), rel=1e-12)
    none = InertiaLoad(2, "O2", 1.0, Vec(0.0, 0.0), 3.0)
    assert not none.acting and none.offset == 0.0 and none.shift() == Vec(0.0, 0.0)


def test_json_lists_inertia_and_friction_and_names_the_driver():
    st = loads(engine())
    f = st.to_json()["forces"]
    i3 = f["inertia"]["F_I3"]
    assert i3["mass"] == M3 and i3["centre_of_gravity"] == "G3"
    assert i3["force"]["magnitude"] == pytest.approx(M3 * i3["a_G"]["magnitude"], rel=1e-12)
    assert i3["offset"] == pytest.approx(st.results["h_I3"].graphical * 1000, rel=1e-12)      # in mm
    assert f["inertia"]["F_I4"]["couple"] is None and f["inertia"]["F_I4"]["offset"] is None
    fr = f["friction"]["F_14^f"]
    assert fr["mu"] == MU and fr["part_of"] == "F_14"
    assert "F_I3" not in f["forces"] and "F_14^f" not in f["forces"] and "F_14" in f["forces"]
    t = f["driving_torque"]["T_2"]
    assert t["name"] == "T_12" and "frame (the motor)" in t["meaning"]
    assert t["power_W"] == pytest.approx(t["value"] * W, rel=1e-12)


def test_the_motor_brakes_on_a_power_stroke_and_drives_against_compression():
    stroke = loads(engine())                 # P pushes the piston towards the crank as it moves that way
    t = stroke.to_json()["forces"]["driving_torque"]["T_2"]
    assert closed_form(THETA, W)["v_c"] < 0 and t["value"] < 0 and t["motor"] == "brakes"
    assert "the motor brakes" in t["words"]
    assert "T_2 is T_12, the torque of the frame (the motor) on link 2; T\u03c9 = \u221268.58 kW < 0: the motor brakes." \
        in stroke.notes                                        # T omega = -342.88 N m x 200 rad/s
    # the same crank angle turning the other way: the piston moves out against P, the motor drives
    back = loads(engine(sense="cw")).to_json()["forces"]["driving_torque"]["T_2"]
    assert back["value"] < 0 and back["motor"] == "drives" and "the motor drives" in back["words"]
    assert any(n.endswith("> 0: the motor drives.") for n in loads(engine(sense="cw")).notes)
    assert power_role(2.0, -1.0) == "brakes" and power_role(2.0, 1.0) == "drives" and power_role(2.0, 0.0) == "holds"


NOTHING = "Nothing loads the mechanism"


def test_the_sheet_leaves_the_inertia_and_friction_rows_to_its_steps():
    from constructions.forces.dalembert import off_sheet
    assert [n for n in ("F_I3", "C_I3", "h_I3", "F_14^f") if off_sheet(n)] == ["F_I3", "C_I3", "h_I3", "F_14^f"]
    assert not [n for n in ("F_14", "T_2", "F_32", "P", "A_CB^t") if off_sheet(n)]


def test_a_forces_scene_with_nothing_to_balance_warns_once():
    bare = engine().split("[[mass]]")[0] + '[ask]\nanalyses = ["forces"]\n'
    st = loads(bare)
    assert [w for w in st.warnings if w.startswith(NOTHING)] and len(st.warnings) == 1
    assert st.results["T_2"].graphical == 0.0
    assert not [w for w in loads(engine()).warnings if w.startswith(NOTHING)]
    # friction alone loads nothing either
    assert [w for w in loads(bare.replace("[ask]", "[[friction]]\nslider = 4\nmu = 0.1\n[ask]")).warnings
            if w.startswith(NOTHING)]
