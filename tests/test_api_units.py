"""Results in the scene's units as well as SI, the results table as named rows, and ``solve --json``'s values
in both (issue 24, item 7)."""

from __future__ import annotations

import csv
import io
import json
import math

import pytest

import drafting
from constructions.geometry import Vec
from drafting.app import cli
from drafting.scene.units import UnitError
from drafting.study.table import CSV_HEADER, Row

from paths import GALLERY

EXAMPLE = GALLERY / "notes-velocity-example-1.toml"        # mm, mm/s, rad/s; V_C = 568.5 mm/s at 180 deg


@pytest.fixture(scope="module")
def study():
    return drafting.load(EXAMPLE)


def test_a_result_converts_to_any_unit_of_its_kind_and_to_the_scenes(study):
    v = study.results["V_C"].graphical
    assert isinstance(v, Vec) and v == Vec(v.x, v.y) and Vec(v.x, v.y) == v       # still the SI vector
    assert v.norm() == pytest.approx(0.5685359809859152, rel=1e-12) and v.unit == "m/s"
    mm = v.to("mm/s")
    assert mm.magnitude == pytest.approx(1000 * v.norm(), rel=1e-15) and f"{mm.units:~P}" == "mm/s"
    assert v.to("in/s").magnitude == pytest.approx(1000 * v.norm() / 25.4, rel=1e-15)
    assert v.in_scene_units() == mm and str(v.in_scene_units()).endswith(" mm/s")
    assert v.direction_deg == pytest.approx(180.0, abs=1e-9)
    w = study.results["omega_2"].graphical
    assert isinstance(w, float) and w < 0                                         # CW: negative, rad/s
    assert w.to("rpm").magnitude == pytest.approx(w * 60 / (2 * math.pi), rel=1e-12)
    assert w.to("deg/s").magnitude == pytest.approx(math.degrees(w), rel=1e-12)
    assert f"{w.in_scene_units():.2f~P}" == "-2.10 rad/s"
    a = study.results["V_C"].analytic
    assert a.to("mm/s").magnitude == pytest.approx(mm.magnitude, rel=1e-9)
    assert study.results["V_C"].difference.to("mm/s").magnitude == pytest.approx(
        1000 * (study.results["V_C"].graphical - a).norm(), rel=1e-12)
    with pytest.raises(UnitError, match="not a unit of angular velocity"):
        w.to("mm/s")
    assert study.results["V_C"].unit == "mm/s" and study.results["V_C"].agrees
    assert "V_C: 568.536 mm/s graphical" in repr(study.results["V_C"])


def test_a_scene_in_other_units_answers_in_them():
    """The same mechanism written in m and m/s with rpm for rates: in_scene_units follows the scene."""
    text = EXAMPLE.read_text()
    assert 'velocity = "mm/s"\nangular_velocity = "rad/s"' in text
    study = drafting.loads(text.replace('velocity = "mm/s"\nangular_velocity = "rad/s"',
                                        'velocity = "m/s"\nangular_velocity = "rpm"'))
    v = study.results["V_C"].graphical.in_scene_units()
    w = study.results["omega_2"].graphical.in_scene_units()
    assert f"{v.units:~P}" == "m/s" and v.magnitude == pytest.approx(0.5685359809859152, rel=1e-12)
    assert f"{w.units:~P}" == "rpm" and w.magnitude == pytest.approx(-2.1004670763599744 * 60 / (2 * math.pi), rel=1e-9)
    row = next(r for r in study.table() if r.quantity == "omega_2")
    assert row.unit == "rpm" and row.graphical == pytest.approx(w.magnitude, rel=1e-12)


def test_the_table_is_named_rows_of_numbers_in_the_scenes_units(study):
    table = study.table()
    assert len(table) == 4 and [r.quantity for r in table] == ["V_B", "V_C", "V_CB", "omega_2"]
    vc = table.rows[1]
    assert isinstance(vc, Row) and vc.unit == "mm/s" and vc.kind == "velocity"
    assert vc.graphical == pytest.approx(568.5359809859152, rel=1e-12) and vc.graphical_angle == pytest.approx(180.0)
    assert (vc.graphical_x, vc.graphical_y) == pytest.approx((-568.5359809859152, 0.0), abs=1e-9)
    assert vc.analytic == pytest.approx(vc.graphical, rel=1e-9) and vc.difference < 1e-9 and vc.agrees is True
    w = table.rows[3]
    assert w.unit == "rad/s" and w.graphical == pytest.approx(-2.1004670763599744, rel=1e-12) and w.graphical_x is None
    assert table.records()[1] == vc._asdict() and list(vc._asdict()) == list(Row._fields)
    # printed as the sheet prints it
    text = str(table).splitlines()
    assert text[0].split() == ["quantity", "graphical", "analytic", "difference"] and set(text[1]) == {"-", " "}
    assert text[3].startswith("V_C") and "568.5 mm/s at 180.0\u00b0" in text[3]
    assert text[5].startswith("\u03c9_2") and "2.1 rad/s CW" in text[5]
    assert table.text[1].graphical == "568.5 mm/s at 180.0\u00b0"


def test_the_tables_csv_reads_back_with_its_units(study):
    rows = list(csv.DictReader(io.StringIO(study.table().to_csv())))
    assert tuple(rows[0]) == CSV_HEADER and [r["quantity"] for r in rows] == ["V_B", "V_C", "V_CB", "omega_2"]
    assert rows[1]["unit"] == "mm/s" and float(rows[1]["graphical"]) == pytest.approx(568.5359809859152, rel=1e-12)
    assert rows[3]["graphical x"] == "" and rows[3]["agrees"] == "yes"
    from drafting.study.study import results_csv
    assert results_csv(study) == study.table().to_csv()


def test_pandas_takes_the_rows(study):
    pd = pytest.importorskip("pandas")
    frame = pd.DataFrame(study.table().rows)
    assert list(frame.columns) == list(Row._fields) and frame.loc[1, "graphical"] == pytest.approx(568.5359809859152)


def test_solve_json_keeps_its_fields_and_adds_each_value_in_scene_units_and_si(capsys):
    assert cli.main(["solve", str(EXAMPLE), "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["units"]["velocity"] == "mm/s" and "scene's units" in data["units_note"]
    assert data["velocity"]["V_C"]["magnitude"] == pytest.approx(568.5359809859152, rel=1e-9)   # as before
    rows = {r["quantity"]: r for r in data["check"]["rows"]}
    vc = rows["V_C"]
    assert {"relative_difference", "tolerance", "agrees"} <= set(vc)                           # as before
    assert vc["unit"] == "mm/s" and vc["graphical"]["magnitude"] == pytest.approx(568.5359809859152, rel=1e-12)
    assert vc["si"]["unit"] == "m/s" and vc["si"]["graphical"]["magnitude"] == pytest.approx(0.5685359809859152, rel=1e-12)
    assert vc["graphical"]["angle_deg"] == pytest.approx(180.0) and vc["si"]["difference"] < 1e-12
    w = rows["omega_2"]
    assert w["kind"] == "angular velocity" and w["unit"] == "rad/s" and w["graphical"] == w["si"]["graphical"] < 0


def test_a_torque_prints_in_the_order_written_and_a_ratio_has_no_unit():
    study = drafting.load(GALLERY / "notes-dynamic-example-1.toml")
    t = study.results["F_12"].graphical
    assert f"{t.in_scene_units().units:~P}" == "N" and t.to("kN").magnitude == pytest.approx(t.norm() / 1000)
    from drafting.scene.units import quantity
    assert str(quantity(2.0, "torque", "N m")) == "2.0 N·m"
    assert quantity(2.0, "torque", "lbf*in").magnitude == pytest.approx(2.0 / (4.4482216152605 * 0.0254), rel=1e-12)
    cr = drafting.load(GALLERY / "gear-pair-20-40.toml").results["C.R."]
    assert cr.unit == "" and cr.graphical.in_scene_units().dimensionless
    assert cr.graphical.in_scene_units().magnitude == pytest.approx(1.6352, abs=1e-4)
