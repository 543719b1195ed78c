"""Gear trains: simple with idlers, compound, reverted, planetary (tabular method and the notes' formula)
against the pitch-point velocity-matching system, and tooth loads and torques against the equilibrium
of every member (constructions/gears/trains, train_check)."""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings, strategies as st

from constructions.errors import ConstructionError
from constructions.gears.train_check import torque_check, velocity_check
from constructions.gears.train_drawing import Case, train_analysis
from constructions.gears.trains import Given, Train, TrainGear, TrainMesh, layout, solve_train

from paths import GALLERY

RPM = 2 * math.pi / 60
DEG = math.pi / 180


def chain(*teeth, module=0.01):
    gears = tuple(TrainGear(str(i), n, str(i)) for i, n in enumerate(teeth, 1))
    meshes = tuple(TrainMesh(str(i), str(i + 1)) for i in range(1, len(teeth)))
    return Train(gears, meshes, module, 20 * DEG)


def planetary(ns, np_, nr, module=0.004):
    return Train((TrainGear("S", ns, "S"), TrainGear("P", np_, "P", "C"), TrainGear("R", nr, "R", internal=True)),
                 (TrainMesh("S", "P"), TrainMesh("P", "R")), module, 20 * DEG)


def test_the_notes_three_gear_train_speeds_loads_and_torques():
    """Gear 1 at 1000 rpm CW delivering 30 kW; module 10 mm; 35/45/60 teeth.  By hand: n2 = 35/45 x 1000 =
    777.8 rpm CCW, n3 = 35/60 x 1000 = 583.3 rpm CW; v = omega1 r1 = 104.72 x 0.175 = 18.326 m/s;
    W_t = P / v = 1637.0 N at both meshes; T1 = P / omega1 = 286.48 N m; T3 = W_t r3 = 491.1 N m."""
    t = chain(35, 45, 60)
    w1 = -1000 * RPM
    sol = solve_train(t, (Given("1", w1),), power=30e3, inp="1", out="3")
    assert sol.speeds["2"] / RPM == pytest.approx(1000 * 35 / 45, rel=1e-12)
    assert sol.speeds["3"] / RPM == pytest.approx(-1000 * 35 / 60, rel=1e-12)
    wt = 30e3 / (1000 * RPM * 0.175)
    assert wt == pytest.approx(1637.02, abs=0.01)
    assert sol.loads == pytest.approx({"1-2": wt, "2-3": wt}, rel=1e-12)
    assert sol.torques["1"] == pytest.approx(-30e3 / (1000 * RPM), rel=1e-12)      # CW, with gear 1
    assert sol.torques["2"] == 0.0
    assert sol.torques["3"] == pytest.approx(wt * 0.3, rel=1e-12) == pytest.approx(491.1, abs=0.05)
    assert wt * math.tan(20 * DEG) == pytest.approx(595.8, abs=0.05) and wt / math.cos(20 * DEG) == pytest.approx(1742.1, abs=0.05)
    speeds, rank, res = velocity_check(t, (Given("1", w1),))
    assert rank == 3 and res < 1e-9
    for m in "123":
        assert speeds[m] == pytest.approx(sol.speeds[m], rel=1e-12)
    loads, torques = torque_check(t, speeds, 30e3, "1", "3")
    assert loads == pytest.approx(sol.loads, rel=1e-12)
    assert torques["3"] == pytest.approx(sol.torques["3"], rel=1e-12)


@pytest.mark.parametrize("teeth", [(20, 40), (20, 33, 40), (17, 50, 23, 60), (30, 19, 19, 19, 45)])
def test_idlers_change_only_the_sign(teeth):
    """n_out / n_in = (-1)^meshes N_1 / N_last, whatever the idlers between (the notes' Idler)."""
    t = chain(*teeth)
    sol = solve_train(t, (Given("1", 10.0),))
    last = str(len(teeth))
    assert sol.speeds[last] / 10.0 == pytest.approx((-1) ** (len(teeth) - 1) * teeth[0] / teeth[-1], rel=1e-14)
    speeds, rank, _ = velocity_check(t, (Given("1", 10.0),))
    assert rank == len(teeth) and speeds[last] == pytest.approx(sol.speeds[last], rel=1e-12)


def reverted(n1, n2, n3, n4):
    gears = (TrainGear("1", n1, "a"), TrainGear("2", n2, "b"), TrainGear("3", n3, "b"), TrainGear("4", n4, "c"))
    meshes = (TrainMesh("1", "2", 0.0), TrainMesh("3", "4", math.pi))
    return Train(gears, meshes, 0.003, 20 * DEG, coaxial=(("a", "c"),))


def test_a_reverted_compound_train_double_stage_reducer():
    """The notes' double-stage reducer: n4/n1 = (-N1/N2)(-N3/N4); reverted when N1 + N2 = N3 + N4."""
    t = reverted(20, 60, 25, 55)
    sol = solve_train(t, (Given("a", 100.0),))
    assert sol.speeds["c"] == pytest.approx(100.0 * (20 / 60) * (25 / 55), rel=1e-14)
    centres, _ = layout(t)
    assert centres["4"].distance_to(centres["1"]) < 1e-15
    speeds, rank, _ = velocity_check(t, (Given("a", 100.0),))
    assert speeds["c"] == pytest.approx(sol.speeds["c"], rel=1e-12)


def test_a_reverted_train_whose_stages_differ_is_refused():
    with pytest.raises(ConstructionError, match="coaxial"):
        layout(reverted(20, 60, 25, 54))


def test_a_planet_that_does_not_fit_its_ring_is_refused():
    with pytest.raises(ConstructionError, match="N_ring = N_sun"):
        layout(planetary(20, 30, 81))


@pytest.mark.parametrize("ns,np_", [(20, 30), (24, 18), (30, 21)])
def test_the_notes_locked_carrier_sun_and_ring_ratios(ns, np_):
    nr = ns + 2 * np_
    t = planetary(ns, np_, nr)
    locked_c = solve_train(t, (Given("C", 0.0), Given("S", 7.0)))
    assert locked_c.speeds["R"] / 7.0 == pytest.approx(-ns / nr, rel=1e-14)
    locked_s = solve_train(t, (Given("S", 0.0), Given("C", 7.0)))
    assert locked_s.speeds["R"] / 7.0 == pytest.approx(1 + ns / nr, rel=1e-14)
    locked_r = solve_train(t, (Given("R", 0.0), Given("C", 7.0)))
    assert locked_r.speeds["S"] / 7.0 == pytest.approx(1 + nr / ns, rel=1e-14)
    for sol in (locked_c, locked_s, locked_r):
        speeds, rank, res = velocity_check(t, sol.givens)
        assert rank == 4 and res < 1e-12
        for m, w in sol.speeds.items():
            assert abs(speeds[m] - w) <= 1e-9 * 7.0 * (1 + nr / ns)


members = st.sampled_from(["S", "R", "C"])


@settings(max_examples=80, deadline=None)
@given(st.integers(12, 60), st.integers(12, 60), members, members, st.floats(-500, 500).filter(lambda w: abs(w) > 1e-3),
       st.floats(10, 1e4))
def test_random_planetary_trains_formula_against_velocity_matching_and_equilibrium(ns, np_, held, driven, w, power):
    if held == driven:
        return
    t = planetary(ns, np_, ns + 2 * np_)
    out = next(m for m in "SRC" if m not in (held, driven))
    sol = solve_train(t, (Given(held, 0.0), Given(driven, w)), power=power, inp=driven, out=out)
    # the notes' formula, S to R relative to the carrier
    if abs(sol.speeds["S"] - sol.speeds["C"]) > 1e-9 * abs(w):
        e = (sol.speeds["R"] - sol.speeds["C"]) / (sol.speeds["S"] - sol.speeds["C"])
        assert e == pytest.approx(-ns / (ns + 2 * np_), rel=1e-9)
    speeds, rank, res = velocity_check(t, sol.givens)
    scale = abs(w) * (2 + (ns + 2 * np_) / ns)
    for m in t.members:
        assert abs(speeds[m] - sol.speeds[m]) <= 1e-9 * scale
    loads, torques = torque_check(t, speeds, power, driven, out, (held,))
    for m in t.members:
        assert abs(torques[m] - sol.torques[m]) <= 1e-9 * max(abs(v) for v in sol.torques.values())
    for mesh, f in sol.loads.items():
        assert f == pytest.approx(loads[mesh], rel=1e-9)
    # power balance: what goes in comes out (ideal gears)
    assert sum(sol.torques[m] * sol.speeds[m] for m in t.members) == pytest.approx(0.0, abs=1e-9 * power)


def test_a_planetary_train_needs_two_givens():
    with pytest.raises(ConstructionError, match="2 degrees of freedom"):
        solve_train(planetary(20, 30, 80), (Given("S", 1.0),))


def test_the_tabular_method_is_written_step_by_step():
    t = planetary(20, 30, 80)
    a = train_analysis(t, (Case("ring held", (Given("R", 0.0), Given("C", 10.0))),))
    words = " ".join(s.caption for s in a.construction.steps)
    assert "tabular method" in words and "Row 1, carrier C held" in words and "n_S/n_C = 5" in words
    assert {m.name for m in a.measured()} == {"omega_S", "omega_P", "omega_R", "omega_C"}


def test_the_tabular_method_is_set_out_as_the_textbook_table():
    """Each planetary case's step carries the table (issue 23): a column a member, row 1 e_m x with the
    carrier held, row 2 n_c for all, the total row each member's speed -- equal to the solved speeds -- and
    the sheet sets it under its step as a table."""
    import drafting
    from drafting.layout.sections import text_sections
    from drafting.layout.formats import SheetFormatter
    study = drafting.load(GALLERY / "planetary-each-member-held.toml")
    tabled = [s for s in study.construction.steps if s.table]
    assert len(tabled) == 3
    u = study.scene.units
    for s in tabled:
        head, held, locked, total = s.table
        assert head[0] == "Operation" and head[1].startswith("carrier") and held[1] == "0"
        assert all(c == "n_c" for c in locked[1:])
        vals = dict(s.values)
        speeds = [vals[c[1:]].value for c in total[1:]]
        assert speeds[0] == pytest.approx(vals["nc"].value, abs=1e-12)
        # e_m x + n_c is each member's speed
        x = vals["x"].value
        for e_text, speed in zip(held[2:], speeds[1:]):
            assert float(e_text.split()[0]) * x + vals["nc"].value == pytest.approx(speed, rel=1e-4, abs=1e-9)
    secs = text_sections(study.construction, (), (), SheetFormatter(u))
    tables = [it for sec in secs for it in sec.items if getattr(it, "name", "").endswith(" table")]
    assert len(tables) == 3 and tables[0].rows[-1][0].startswith("total")
