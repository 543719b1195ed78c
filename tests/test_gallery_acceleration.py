"""The notes' "Graphical acceleration analysis" Examples 1-4, as gallery/notes-acceleration-example-*.toml.

Each scene is loaded, studied and checked against the numbers the notes give, within drawing accuracy
(2 %), with the senses of rotation, graphical = analytic on every row of its results table, and the
same numbers carried by ``drafting solve SCENE --json``.  The notes' figures are missing and the
dimensions were derived from their numbers (each scene's header and gallery/README.md say how); the
derivations are reproduced here too.  Where the notes' numbers cannot all be met (Example 3: they are
mutually inconsistent; Example 4: velocity Example 3's V_D = 4 m/s), the test asserts what the scene
reaches and reproduces the reason.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest

from constructions.analytic import four_bar
from drafting.app.cli import main
from drafting.scene.reader import load_scene
from drafting.study.study import Study

from paths import GALLERY
MM = 1e3            # m, m/s, m/s^2 -> mm, mm/s, mm/s^2
DRAWING = 0.02      # drawing accuracy, relative


def scene(n: int) -> Path:
    return GALLERY / f"notes-acceleration-example-{n}.toml"


def studied(n: int) -> Study:
    return Study(load_scene(scene(n))).run()


def assert_checked(study: Study) -> None:
    """graphical = analytic on every row the scene asks for, and every row has an analytic value."""
    assert [c.name for c in study.comparisons] == list(study.scene.find)
    assert all(c.analytic is not None for c in study.comparisons)
    assert not study.disagreements()
    assert study.acceleration.warnings == ()


def solve_json(n: int, capsys) -> dict:
    code = main(["solve", str(scene(n)), "--json"])
    out, err = capsys.readouterr()
    assert code == 0, err
    d = json.loads(out)
    assert d["units"]["acceleration"] == "mm/s^2" and d["units"]["angular_acceleration"] == "rad/s^2"
    assert "acceleration" in d["analyses"]
    assert d["check"]["agrees"] is True
    assert [r["quantity"] for r in d["check"]["rows"]] == list(load_scene(scene(n)).find)
    assert all(r["relative_difference"] is not None and r["agrees"] for r in d["check"]["rows"])
    return d


def link_length(study: Study, number: int) -> float:
    return study.scene.mechanism.link(number).length * MM


# -- Example 1: slider-crank, alpha_1 = 0 --------------------------------------------------------------

def test_example_1_is_the_velocity_example_1_mechanism():
    a, v = load_scene(scene(1)), load_scene(GALLERY / "notes-velocity-example-1.toml")
    assert a.mechanism == v.mechanism and a.angle == v.angle and a.omega == v.omega
    assert a.alpha == 0.0


def test_example_1_within_drawing_accuracy():
    study = studied(1)
    acc = study.acceleration
    assert acc.normal[("B", "O1")].norm() * MM == pytest.approx(5000, rel=DRAWING)      # A_B^n
    assert acc.tangential[("B", "O1")].norm() == 0.0                                   # alpha_1 = 0
    assert acc.normal[("C", "B")].norm() * MM == pytest.approx(417, rel=DRAWING)       # A_CB^n
    assert acc.tangential[("C", "B")].norm() * MM == pytest.approx(5180, rel=DRAWING)  # A_CB^t
    assert acc.accelerations["C"].norm() * MM == pytest.approx(520, rel=DRAWING)       # A_C
    assert acc.angular[2] == pytest.approx(55.11, rel=DRAWING) and acc.angular[2] > 0  # CCW
    assert_checked(study)


def test_example_1_solve_json(capsys):
    d = solve_json(1, capsys)
    assert d["acceleration"]["A_C"]["magnitude"] == pytest.approx(520, rel=DRAWING)
    assert d["acceleration_components"]["A_CB^t"]["magnitude"] == pytest.approx(5180, rel=DRAWING)
    assert d["acceleration_components"]["A_CB^n"]["magnitude"] == pytest.approx(417, rel=DRAWING)
    assert d["angular_acceleration"]["alpha_2"]["value"] == pytest.approx(55.11, rel=DRAWING)
    assert d["angular_acceleration"]["alpha_2"]["sense"] == "ccw"


# -- Example 2: slider-crank, alpha_1 = 40 rad/s^2 CCW -----------------------------------------------------

def test_example_2_is_the_velocity_example_1_mechanism():
    a, v = load_scene(scene(2)), load_scene(GALLERY / "notes-velocity-example-1.toml")
    assert a.mechanism == v.mechanism and a.angle == v.angle
    assert a.omega == pytest.approx(10.0, rel=1e-12) == pytest.approx(v.omega, rel=1e-12)
    assert a.alpha == 40.0


def test_example_2_within_drawing_accuracy():
    study = studied(2)
    acc = study.acceleration
    o1b = link_length(study, 1)
    w1, a1 = study.scene.omega, study.scene.alpha
    # the notes' step 3 writes "A_B^t = omega_1^2 O1B = 2000": the 2000 is alpha_1 O1B; omega_1^2 O1B is A_B^n
    assert acc.tangential[("B", "O1")].norm() * MM == pytest.approx(a1 * o1b, rel=1e-12)
    assert a1 * o1b == pytest.approx(2000, rel=1e-12) != w1 ** 2 * o1b
    assert acc.normal[("B", "O1")].norm() * MM == pytest.approx(w1 ** 2 * o1b, rel=1e-12)
    assert w1 ** 2 * o1b == pytest.approx(5000, rel=DRAWING)
    assert acc.normal[("C", "B")].norm() * MM == pytest.approx(417, rel=DRAWING)       # A_CB^n
    assert acc.tangential[("C", "B")].norm() * MM == pytest.approx(4400, rel=DRAWING)  # A_CB^t
    assert acc.accelerations["C"].norm() * MM == pytest.approx(1750, rel=DRAWING)      # A_C
    assert acc.angular[2] == pytest.approx(46.8, rel=DRAWING) and acc.angular[2] > 0   # CCW
    assert_checked(study)


def test_example_2_solve_json(capsys):
    d = solve_json(2, capsys)
    assert d["acceleration"]["A_C"]["magnitude"] == pytest.approx(1750, rel=DRAWING)
    assert d["acceleration_components"]["A_CB^t"]["magnitude"] == pytest.approx(4400, rel=DRAWING)
    assert d["acceleration_components"]["A_B^t"]["magnitude"] == pytest.approx(2000, rel=DRAWING)
    assert d["angular_acceleration"]["alpha_1"] == {"value": pytest.approx(40.0), "sense": "ccw"}
    assert d["angular_acceleration"]["alpha_2"]["value"] == pytest.approx(46.8, rel=DRAWING)
    assert d["angular_acceleration"]["alpha_2"]["sense"] == "ccw"


# -- Example 3: four-bar, omega_1 = 30 rad/s, alpha_1 = 200 rad/s^2, both CCW -------------------------------

def test_example_3_lengths_follow_from_the_notes_numbers():
    study = studied(3)
    assert link_length(study, 1) == pytest.approx(4660 / 30 ** 2, rel=1e-3)    # O1B = A_B^n / omega_1^2
    assert link_length(study, 2) == pytest.approx(18600 / 266, rel=2e-3)       # BC = A_CB^t / alpha_2
    assert link_length(study, 3) == pytest.approx(22200 / 555, rel=1e-3)       # O3C = A_C^t / alpha_3


def test_example_3_within_drawing_accuracy_where_the_notes_allow():
    study = studied(3)
    acc = study.acceleration
    assert acc.normal[("B", "O1")].norm() * MM == pytest.approx(4660, rel=DRAWING)     # A_B^n
    assert acc.tangential[("B", "O1")].norm() * MM == pytest.approx(200 * link_length(study, 1), rel=1e-12)
    assert acc.normal[("C", "B")].norm() * MM == pytest.approx(580, rel=DRAWING)       # A_CB^n
    assert acc.angular[2] > 0 and acc.angular[3] > 0                                  # both CCW
    # The notes' A_CB^n = 580, alpha_2 = 266 and alpha_3 = 555 cannot all hold (see the next test), so
    # no frame pivot brings A_CB^t, A_C^t, alpha_2 and alpha_3 within 2 %.  The scene takes the best
    # compromise on a 0.1 mm grid; these are the values it reaches, and their distance from the notes:
    a_cb_t = acc.tangential[("C", "B")].norm() * MM
    a_c_t = acc.tangential[("C", "O3")].norm() * MM
    assert a_cb_t == pytest.approx(19244, rel=1e-4) and a_cb_t / 18600 - 1 == pytest.approx(0.035, abs=1e-3)
    assert a_c_t == pytest.approx(21268, rel=1e-4) and a_c_t / 22200 - 1 == pytest.approx(-0.042, abs=1e-3)
    assert acc.angular[2] == pytest.approx(274.9, rel=1e-3) and acc.angular[2] / 266 - 1 < 0.035
    assert acc.angular[3] == pytest.approx(531.7, rel=1e-3) and acc.angular[3] / 555 - 1 > -0.043
    # the polygon is ill-conditioned: its trial lines cross at about 14 deg (coupler and rocker 14 deg
    # from the toggle), which is why the notes' measured A_CB^t and A_C^t can be several per cent out
    assert math.degrees(math.asin(acc.conditions["C"])) == pytest.approx(13.9, abs=0.1)
    assert_checked(study)


def _example_3_at(pivot_mm):
    """The notes' Example 3 four-bar (the scene's lengths and branch) with the rocker pivot at pivot_mm."""
    m = load_scene(scene(3))
    s = four_bar(m.angle, m.omega, m.alpha, crank_pivot=(0.0, 0.0),
                 rocker_pivot=(pivot_mm[0] / MM, pivot_mm[1] / MM), crank=m.mechanism.link(1).length,
                 coupler=m.mechanism.link(2).length, rocker=m.mechanism.link(3).length, branch=1)
    coupler, rocker = m.mechanism.link(2).length * MM, m.mechanism.link(3).length * MM
    return {"A_CB^n": float(s.omega2) ** 2 * coupler, "alpha_2": float(s.alpha2), "alpha_3": float(s.alpha3),
            "A_CB^t": abs(float(s.alpha2)) * coupler, "A_C^t": abs(float(s.alpha3)) * rocker,
            "omega_2": float(s.omega2)}


def _pivot_meeting(targets: dict[str, float], start) -> dict[str, float]:
    """Newton's method on the rocker pivot (mm) for two of the notes' numbers exactly."""
    p = np.array(start, dtype=float)
    names = list(targets)

    def f(q):
        r = _example_3_at(q)
        return np.array([r[k] / targets[k] - 1 for k in names])
    for _ in range(50):
        r = f(p)
        if np.abs(r).max() < 1e-12:
            break
        h = 1e-7
        jac = np.column_stack([(f(p + h * e) - r) / h for e in np.eye(2)])
        step = np.linalg.solve(jac, -r)
        p += step * min(1.0, 0.5 / np.abs(step).max())
    assert np.abs(f(p)).max() < 1e-9
    return _example_3_at(p)


def test_example_3_notes_numbers_are_mutually_inconsistent():
    """With O1B, BC and O3C as derived, the frame pivot has two coordinates for three numbers: meeting
    any two of A_CB^n = 580, alpha_2 = 266, alpha_3 = 555 exactly misses the third by far more than 2 %
    (the numbers quoted in the scene's header and gallery/README.md).  Newton's method finds the pivots
    next to the scene's; a search from seeds all over the plane (both branches) found no pivot closer
    to the third number, and the next test bounds all three at once over every pivot."""
    r = _pivot_meeting({"A_CB^n": 580, "alpha_2": 266}, (19.4, 32.3))
    assert r["alpha_3"] == pytest.approx(516.5, abs=0.1) and r["alpha_3"] / 555 - 1 < -0.06
    assert 1900 < r["A_C^t"] - r["A_CB^t"] < 2100               # the notes': 22200 - 18600 = 3600
    r = _pivot_meeting({"A_CB^n": 580, "alpha_3": 555}, (19.4, 32.3))
    assert r["alpha_2"] == pytest.approx(289.0, abs=0.1) and r["alpha_2"] / 266 - 1 > 0.08
    assert 1900 < r["A_C^t"] - r["A_CB^t"] < 2100
    r = _pivot_meeting({"alpha_2": 266, "alpha_3": 555}, (9.0, 36.0))
    assert r["A_CB^n"] == pytest.approx(2572, abs=1) and abs(r["omega_2"]) == pytest.approx(6.06, abs=0.01)


def test_example_3_no_frame_pivot_meets_the_notes_within_drawing_accuracy():
    """Over every rocker pivot and both branches, the largest of the relative errors of A_CB^n, alpha_2
    and alpha_3 is at least 3.8 % (the scene's 0.1 mm pivot reaches 4.2 %).  Magnitudes do not depend on
    how the drawing is turned, so the pivot is put on the x axis at distance d and the crank angle swept
    instead (every relative position); the best points of the sweep are then refined."""
    m = load_scene(scene(3))
    r1, r2, r3 = (m.mechanism.link(n).length for n in (1, 2, 3))

    def worst(theta, d_mm, branch):
        s = four_bar(theta, m.omega, m.alpha, crank_pivot=(0.0, 0.0), rocker_pivot=(d_mm / MM, 0.0),
                     crank=r1, coupler=r2, rocker=r3, branch=branch)
        e = np.maximum.reduce([np.abs(s.omega2 ** 2 * r2 * MM / 580 - 1), np.abs(s.alpha2 / 266 - 1),
                               np.abs(s.alpha3 / 555 - 1)])
        return np.where(np.isfinite(e), e, np.inf)

    theta = np.radians(np.arange(0, 360, 0.1))
    reach = (r1 + r2 + r3) * MM                      # beyond this the loop cannot close
    found = []
    for branch in (1, -1):
        for d in np.arange(0.25, reach + 0.25, 0.25):
            e = worst(theta, d, branch)
            found.append((float(e.min()), branch, float(d), float(theta[np.argmin(e)])))
    found.sort()
    best = np.inf
    for _, branch, d0, t0 in found[:10]:
        sd, st = 0.25, math.radians(0.1)
        for _ in range(8):
            ts = t0 + np.linspace(-st, st, 21)
            e, d0, t0 = min((float(w.min()), d, float(ts[np.argmin(w)]))
                            for d in d0 + np.linspace(-sd, sd, 21) for w in [worst(ts, d, branch)])
            sd, st = sd / 4, st / 4
        best = min(best, e)
    assert best == pytest.approx(0.038, abs=0.001) and best > DRAWING


def test_example_3_solve_json(capsys):
    d = solve_json(3, capsys)
    comp = d["acceleration_components"]
    assert comp["A_B^n"]["magnitude"] == pytest.approx(4660, rel=DRAWING)
    assert comp["A_CB^n"]["magnitude"] == pytest.approx(580, rel=DRAWING)
    # reached values (the notes' 18600 and 22200 are out of reach, see above)
    assert comp["A_CB^t"]["magnitude"] == pytest.approx(19244, rel=1e-4)
    assert comp["A_C^t"]["magnitude"] == pytest.approx(21268, rel=1e-4)
    alpha = d["angular_acceleration"]
    assert alpha["alpha_2"]["value"] == pytest.approx(274.9, rel=1e-3) and alpha["alpha_2"]["sense"] == "ccw"
    assert alpha["alpha_3"]["value"] == pytest.approx(531.7, rel=1e-3) and alpha["alpha_3"]["sense"] == "ccw"
    assert alpha["alpha_1"] == {"value": pytest.approx(200.0), "sense": "ccw"}


# -- Example 4: the toggle linkage, omega_1 = 100 rad/s CW, alpha_1 = 0 ---------------------------------------

def test_example_4_within_drawing_accuracy():
    study = studied(4)
    acc, vel = study.acceleration, study.velocity
    assert study.scene.omega == -100.0 and study.scene.alpha == 0.0
    assert link_length(study, 1) * 100 ** 2 == pytest.approx(100000, rel=1e-12)       # O1B = A_B^n / omega_1^2
    assert acc.normal[("B", "O1")].norm() * MM == pytest.approx(100000, rel=1e-12)     # A_B^n
    assert acc.normal[("C", "B")].norm() * MM == pytest.approx(3600, rel=DRAWING)      # A_CB^n
    assert acc.normal[("C", "O2")].norm() * MM == pytest.approx(31300, rel=DRAWING)    # A_C^n
    assert acc.accelerations["C"].norm() * MM == pytest.approx(43000, rel=DRAWING)     # A_C
    assert acc.accelerations["D"].norm() * MM == pytest.approx(75000, rel=DRAWING)     # A_D
    assert acc.angular[2] > 0 and acc.angular[3] < 0 and acc.angular[4] > 0             # CCW, CW, CCW
    # velocity Example 3's senses: omega_2, omega_3 CCW, omega_4 CW, V_D to the left
    assert vel.angular[2] > 0 and vel.angular[3] > 0 and vel.angular[4] < 0
    assert vel.velocities["D"].x < 0 and abs(vel.velocities["D"].y) < 1e-12
    # a well-conditioned linkage: trial lines 78 deg apart at C and 35 deg at D
    assert acc.conditions["C"] > 0.97 and acc.conditions["D"] > 0.56
    assert study.model == "dyad chain vector loop"
    assert_checked(study)


def test_example_4_cannot_also_give_velocity_example_3_speed():
    """V_D = 4 m/s (velocity Example 3) is not reached: V_D is 1.07 m/s, and cannot be 4 m/s with these
    accelerations unless CD is within 15 deg of square to the guide (an ill-conditioned slider)."""
    study = studied(4)
    vel, acc = study.velocity, study.acceleration
    P = study.position.positions
    vc, vd = vel.velocities["C"], vel.velocities["D"]
    assert vd.norm() == pytest.approx(1.073, abs=1e-3)
    # A_C^n = V_C^2 / O2C: the notes' 31300 mm/s^2 with O2C = 30 mm holds V_C near 1 m/s
    assert vc.norm() == pytest.approx(math.sqrt(acc.normal[("C", "O2")].norm() * link_length(study, 3) / MM),
                                      rel=1e-12)
    assert math.sqrt(31300 * 30) / MM == pytest.approx(vc.norm(), rel=DRAWING)
    # along CD the speeds of C and D agree: |V_D| |cos(CD, guide)| = |V_C . CD/|CD||, so |V_D| <= |V_C| / |cos|
    cd = P["D"] - P["C"]
    u = cd * (1 / cd.norm())
    cos_cd = abs(u.x)                                   # the guide is along x
    assert vd.norm() * cos_cd == pytest.approx(abs(vc.x * u.x + vc.y * u.y), rel=1e-12)
    # so 4 m/s would need |cos(CD, guide)| <= |V_C| / 4 m/s, i.e. CD within 15 deg of square to the guide
    assert math.degrees(math.acos(vc.norm() / 4.0)) > 75.0 and cos_cd > vc.norm() / 4.0


def test_example_4_solve_json(capsys):
    d = solve_json(4, capsys)
    comp, acc = d["acceleration_components"], d["acceleration"]
    assert comp["A_B^n"]["magnitude"] == pytest.approx(100000, rel=DRAWING)
    assert comp["A_CB^n"]["magnitude"] == pytest.approx(3600, rel=DRAWING)
    assert comp["A_C^n"]["magnitude"] == pytest.approx(31300, rel=DRAWING)
    assert acc["A_C"]["magnitude"] == pytest.approx(43000, rel=DRAWING)
    assert acc["A_D"]["magnitude"] == pytest.approx(75000, rel=DRAWING)
    senses = {k: v["sense"] for k, v in d["angular_acceleration"].items()}
    assert (senses["alpha_2"], senses["alpha_3"], senses["alpha_4"]) == ("ccw", "cw", "ccw")
    senses = {k: v["sense"] for k, v in d["angular_velocity"].items()}
    assert (senses["omega_1"], senses["omega_2"], senses["omega_3"], senses["omega_4"]) == ("cw", "ccw", "ccw", "cw")
    assert d["velocity"]["V_D"]["x"] < 0
