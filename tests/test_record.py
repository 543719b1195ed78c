"""The construction record: immutable steps, roles, and vector equations with known/unknown marks."""

from __future__ import annotations

import dataclasses
import xml.etree.ElementTree as ET

import pytest

from constructions.entities import Arrow, Diagram, Point, Role
from constructions.geometry import Vec
from constructions.record import Construction, Term, VectorEquation
from drafting.layout.sheet import SheetInfo, compose_sheet, compose_sheets
from drafting.backends.svg import sheet_to_svg


def acceleration_chain() -> VectorEquation:
    """A_C^n + A_C^t = A_B^n + A_B^t + A_CB^n + A_CB^t for a four-bar with a driven crank (the next
    method): A_C^n, A_B^n, A_B^t and A_CB^n are known from the velocities; A_C^t and A_CB^t are known
    in direction only."""
    return VectorEquation(
        (Term("A", "C", True, True, "n"), Term("A", "C", False, True, "t")),
        (Term("A", "B", True, True, "n"), Term("A", "B", True, True, "t"),
         Term("A", "CB", True, True, "n"), Term("A", "CB", False, True, "t")))


def test_the_record_carries_an_acceleration_chain():
    eq = acceleration_chain()
    assert eq.text(marks=False) == "A_C^n + A_C^t = A_B^n + A_B^t + A_CB^n + A_CB^t"
    assert eq.text().startswith("A_C^n(\u2713\u2713) + A_C^t(\u00d7\u2713) = ")
    assert eq.unknowns == 2            # one planar vector equation solves exactly two


def test_steps_are_immutable_and_names_unique():
    c0 = Construction("Velocity polygon")
    p = Point("pole O_v", Role.LABEL, Diagram.VELOCITY, Vec(0, 0), "O_v")
    c1 = c0.then("Choose the pole O_v.", p)
    assert c0.steps == () and len(c1.steps) == 1          # then() returns a new construction
    with pytest.raises(dataclasses.FrozenInstanceError):
        c1.title = "other"
    with pytest.raises(ValueError, match="already used"):
        c1.then("again", p)
    a = Arrow("V_B", Role.KNOWN, Diagram.VELOCITY, Vec(0, 0), Vec(1, 0), "V_B")
    c2 = c1.then("Draw V_B.", a)
    assert [e.name for e in c2.entities(role=Role.KNOWN)] == ["V_B"]
    assert c2.entity("pole O_v") is p and c2.diagrams() == (Diagram.VELOCITY,)


def test_an_acceleration_equation_sets_on_a_sheet():
    c = Construction("Acceleration polygon").then("Write the acceleration equation of C.",
                                                  equation=acceleration_chain())
    svg = sheet_to_svg(compose_sheet(c, SheetInfo(title="t", drawing_number="n", date="2026-11-22")))
    root = ET.fromstring(svg)
    ns = "{http://www.w3.org/2000/svg}"
    line = next(t for t in root.iter(f"{ns}text") if "".join(t.itertext()).startswith("ACn"))
    assert "".join(line.itertext()) == "ACn + ACt = ABn + ABt + ACBn + ACBt"
    spans = list(line.iter(f"{ns}tspan"))
    # subscripts drop (dy > 0) and superscripts rise (dy < 0) by tspan dy, never baseline-shift
    assert [s.text for s in spans[:3]] == ["A", "C", "n"]
    assert float(spans[1].get("dy")) > 0 > float(spans[2].get("dy"))
    assert "baseline-shift" not in svg


def test_step_values_are_written_in_the_scene_units_on_a_sheet():
    """Words with placeholders and values apart: the sheet writes them in the scene's units; a lab
    sheet's hook can blank the answers without touching the record."""
    from constructions.record import StepKind, Value
    from drafting.scene.unitset import Units

    c = (Construction("Velocity polygon")
         .then("Draw V_B ($v, crank at $a) from O_v.", values={"v": Value("velocity", 0.5),
                                                              "a": Value("angle", 1.2217304763960306)})
         .then("Measure V_C = $vc.", values={"vc": Value("velocity", 0.5685)}, kind=StepKind.ANSWER)
         .then("A caption without values."))
    info = SheetInfo(title="t", drawing_number="n", date="2026-11-22", units=Units(velocity="m/min"))
    (sheet,) = compose_sheets(c, info)
    steps = [t.plain for t in sheet.texts() if t.name.startswith("step ") and not t.name.endswith("number")]
    assert steps == ["Draw VB (30 m/min, crank at 70\u00b0) from Ov.", "Measure VC = 34.11 m/min.",
                     "A caption without values."]
    answers = {s.words for s in c.steps if s.kind is StepKind.ANSWER}

    def blank(v, default):
        return "____" if v.kind == "velocity" and v.value == 0.5685 else default(v)
    (lab,) = compose_sheets(c, info, values=blank)
    lab_steps = [t.plain for t in lab.texts() if t.name.startswith("step ") and not t.name.endswith("number")]
    assert lab_steps[1] == "Measure VC = ____." and lab_steps[0] == steps[0]
    assert answers == {"Measure V_C = $vc."}
