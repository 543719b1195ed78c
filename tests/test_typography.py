"""Typography on the sheets (issue 23): the degree sign, no trailing zeros (ISO 129-1), point and member
names set as the notes print them (O4 with its digit below, b' with a prime), Greek result names, ASCII
arrows and dashes set as their signs, and the title block's scale cell."""

from __future__ import annotations

import pytest

from drafting.layout.title_block import scale_cell
from drafting.render.style import rich
from drafting.scene.units import format_value, trimmed, with_unit
from drafting.study.study import display_name


def runs(text: str) -> list[tuple[str, bool]]:
    """(text, set below or above the baseline) of each run ``text`` is set in."""
    return [(s.text, s.shift != 0) for s in rich(text, 3.5)]


@pytest.mark.parametrize("value,kind,unit,shown", [
    (0.05, "length", "mm", "50 mm"), (0.0425, "length", "mm", "42.5 mm"), (1.2217304763960306, "angle", "deg", "70\u00b0"),
    (0.5, "velocity", "m/min", "30 m/min"), (2.1, "angular velocity", "rad/s", "2.1 rad/s"),
    (1e8 * 1e-3, "length", "mm", "1.000e+08 mm")])
def test_values_drop_trailing_zeros_and_set_the_degree_sign_close(value, kind, unit, shown):
    assert format_value(value, kind, unit) == shown


def test_trimmed_and_with_unit():
    assert [trimmed(t) for t in ("70.00", "2.100", "500", "4.4e-13", "0.0500")] == ["70", "2.1", "500", "4.4e-13",
                                                                                   "0.05"]
    assert with_unit("70", "\u00b0") == "70\u00b0" and with_unit("50", "mm") == "50 mm" and with_unit("3", "") == "3"


def test_point_names_take_subscripts_and_primes_and_words_stay_as_written():
    assert runs("O4I") == [("O", False), ("4", True), ("I", False)]
    assert runs("F14 and I02") == [("F", False), ("14", True), (" and I", False), ("02", True)]
    assert runs("From b' draw; meet at c'.") == [("From b\u2032 draw; meet at c\u2032.", False)]
    assert runs("C''") == [("C\u2033", False)]
    assert runs("O2G2 = 30 mm, AG3") == [("O", False), ("2", True), ("G", False), ("2", True), (" = 30 mm, AG", False),
                                         ("3", True)]
    # a name after a slash (a ratio of lengths), not a unit after one
    assert runs("VC/O4C = 2.5") == [("VC/O", False), ("4", True), ("C = 2.5", False)]
    for words in ("D'Alembert force", "Kennedy's theorem", "TOM-A-001", "2026-11-23", "3-4-5 law", "4.4e-13 mm",
                  "Example 1", "step 10.5", "(notes' velocity Example 1)", "the drivers' speeds", "12 kg/m3",
                  "0.5 rad/s2"):
        assert runs(words) == [(words, False)], words


def test_ascii_arrows_and_dashes_become_their_signs():
    assert "".join(t for t, _ in runs("left of A->B -- then")) == "left of A\u2192B \u2013 then"


def test_greek_result_names():
    assert display_name("omega_2") == "\u03c9_2" and display_name("alpha_3") == "\u03b1_3"
    assert display_name("phi'") == "\u03c6'" and display_name("phi_max") == "\u03c6_max"
    assert display_name("V_C") == "V_C" and display_name("physics") == "physics"


def test_the_scale_cell_says_as_shown_when_each_drawing_carries_its_own():
    assert scale_cell([]).startswith("\u2014")
    assert scale_cell(["Space 1:2"]) == "Space 1:2"
    assert scale_cell(["Space 1:2", "velocity 1 mm = 10 mm/s"]) == "As shown"


def test_a_number_keeps_its_unit_on_its_line():
    from drafting.layout.wrap import words_of, wrap_words
    assert words_of("T = 10.7 N × 59.99 mm = 0.6417 N m CW.") == ("T", "=", "10.7 N", "×", "59.99 mm", "=",
                                                                  "0.6417 N m", "CW.")
    assert words_of("V = 500 mm/s, at 70° (12.65 mm)") == ("V", "=", "500 mm/s,", "at", "70°", "(12.65 mm)")
    for width in range(20, 80, 3):                        # however narrow the line, "N m" is never cut
        lines = ["".join(s.text for s in line) for line in wrap_words("so T = 0.6417 N m CW", width, 3.5)]
        assert not any(t.endswith(("N", "0.6417")) for t in lines), lines


def test_a_page_whose_steps_go_on_under_the_space_diagram_reads_out_of_order():
    """Steps run down the text column and then on in the room under the space diagram (read before the
    column) print steps 33-45 above 1-32 (dynamic Example 3, issue 23); the page planner counts such pages
    and prefers, of documents with as many pages, one without."""
    from drafting.layout import reading_order
    from drafting.layout.flow import FlowText
    from drafting.layout.items import Paragraph, Section
    from drafting.layout.page_plans import PagePlan
    from drafting.layout.pages import Document
    sections = FlowText([Section("Construction", tuple(Paragraph(f"step {i}", name=f"step {i}") for i in range(3)))])
    plan = PagePlan(text_slots=[("text:0", None), ("text:1", None)], reclaim=[("text:1", {}, (0, 0, 0, 0))])
    count = reading_order.steps_out_of_order
    # the heading and three steps: the column first, then the room under the space diagram
    assert count(Document([plan], ["0#text:0"] * 3 + ["0#text:1"], 3.0), sections) == 1
    assert count(Document([plan], ["0#text:0"] * 4, 3.0), sections) == 0
    assert count(Document([plan], ["0#text:1"] * 4, 3.0), sections) == 0


def test_text_that_reaches_the_room_under_the_space_diagram_is_set_there_first():
    """The room under the space diagram lies left of the text column and is read before it: when the text
    reaches it, it is flowed first (the slots in reading order), so velocity Example 4 reads the vector
    equations and steps 1-4 there and goes on with step 5 at the top of the column; a room the text never
    reached keeps its place (given back to the diagram)."""
    from drafting.layout import reading_order
    from drafting.layout.page_plans import PagePlan
    from drafting.render.paper import Rect
    column, room = Rect(120, 10, 80, 150), Rect(10, 80, 100, 40)
    plan = PagePlan(text_slots=[("text:0", column), ("text:1", room)], reclaim=[("text:1", {}, (0, 0, 0, 0))])
    slots = [("0#text:0", column), ("0#text:1", room)]
    assert reading_order.reading_slots([plan], slots, {"0#text:0", "0#text:1"}) == slots[::-1]
    assert reading_order.reading_slots([plan], slots, {"0#text:0"}) == slots
    # a room right of the column is read after it: kept in its place
    right = PagePlan(text_slots=[("text:0", room), ("text:1", column)], reclaim=[("text:1", {}, (0, 0, 0, 0))])
    slots = [("0#text:0", room), ("0#text:1", column)]
    assert reading_order.reading_slots([right], slots, {"0#text:0", "0#text:1"}) == slots

    from drafting.api import load
    from tests.paths import GALLERY
    sheets = load(GALLERY / "notes-velocity-example-4.toml").sheets()
    region = {c.name: c.region for c in sheets[0].commands if getattr(c, "name", "").startswith("step ")}
    first = {n: region[f"step {n} number"] for n in (1, 5)}
    assert first[1] == "text:1" and first[5] == "text:0", first              # steps 1-4 under the space diagram, 5 on in the column


def test_a_solution_s_prime_follows_its_subscript_at_full_size():
    """theta_1' is the second solution theta_1-prime: a digit carries no prime, so the prime is set after
    the subscript at full size (a point's prime in a subscript, V_B', stays in it)."""
    from drafting.render.style import rich
    got = rich(display_name("theta_1'"), 3.5)
    assert [(s.text, s.shift > 0) for s in got] == [("\u03b8", False), ("1", True), ("\u2032", False)]
    assert got[2].size == 3.5
    assert [(s.text, s.shift > 0) for s in rich("V_B'", 3.5)] == [("V", False), ("B'", True)]
