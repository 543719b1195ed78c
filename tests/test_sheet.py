"""Sheets: the drawing commands and the SVG structure, checked without rendering pixels.

The constructions are built by hand with the record API (no solver): a slider-crank at 60 deg with
crank O1B = 100 mm, coupler BC = 300 mm and a point D on the coupler, turning at 10 rad/s CCW.  The
velocities are computed here in three lines from V = omega x r (V_B = w2 k x O1B; V_C on the guide from
V_C = V_B + w3 k x BC; V_D = V_B + w3 k x BD), which is all a sheet test needs.
"""

from __future__ import annotations

import math
import re
import xml.etree.ElementTree as ET

import pytest
from hypothesis import HealthCheck, given, settings, strategies as st

from constructions.entities import (Arc, Arrow, Bar, Block, Diagram, Guide, Pivot, Plate, Point,
                                    Polygon as PolygonEntity, Role, ScaleBar, TrialLine)
from constructions.geometry import Vec
from constructions.record import Construction, Term, VectorEquation
from drafting.render.errors import LayoutError
from drafting.render.paper import Line, Polygon, Rectangle
from drafting.layout.sheet import ResultRow, SheetInfo, compose_sheet, compose_sheets
from drafting.render.style import MIN_TEXT, dashed, long_dash_dot, style
from drafting.backends.svg import sheet_to_svg
from drafting.scene.unitset import Units

SVG = "{http://www.w3.org/2000/svg}"
S, V = Diagram.SPACE, Diagram.VELOCITY


def slider_crank(angle_deg: float = 60.0, *, crank: float = 0.1, coupler: float = 0.3, omega: float = 10.0,
                 scale: float | None = None, extra_steps: int = 0) -> Construction:
    O1 = Vec(0.0, 0.0)
    B = Vec.polar(crank, math.radians(angle_deg))
    C = Vec(B.x + math.sqrt(coupler ** 2 - B.y ** 2), 0.0)
    D = B + (C - B) * 0.55 + (C - B).perp().unit() * 0.06
    vB = (B - O1).perp() * omega
    BC = C - B
    w3 = -vB.y / BC.x
    vC = vB + BC.perp() * w3
    vD = vB + (D - B).perp() * w3
    if scale is None:       # the 1-2-5 scale that keeps V_B at most 100 mm and the polygon near 110 mm
        need = max(vB.norm() / 100.0, max(abs(vC.x), abs(vB.x - vC.x), abs(vD.x)) / 110.0)
        scale = next(v for v in (0.005, 0.01, 0.02, 0.05) if v >= need)
    c = Construction("Slider-crank velocity polygon")
    c = c.then("Draw the frame: the fixed pivot O1 and the slider guide at the space scale.",
               Pivot("pivot O1", Role.GIVEN, S, O1, "O1"), Guide("guide C", Role.GIVEN, S, O1, Vec(1, 0)))
    c = c.then("Draw the crank O1B (link 2) at the given angle.", Bar("link 2", Role.GIVEN, S, O1, B, 2),
               Point("joint B", Role.LABEL, S, B, "B"))
    c = c.then("Find C: swing BC about B to meet the guide; take the crossing ahead.",
               Arc("path C about B", Role.PATH, S, B, coupler, BC.angle() - 0.2, BC.angle() + 0.2),
               Bar("link 3", Role.GIVEN, S, B, C, 3), Block("block 4", Role.GIVEN, S, C, Vec(1, 0), 4),
               Point("joint C", Role.LABEL, S, C, "C"))
    c = c.then("Mark D on link 3.", Plate("plate D", Role.GIVEN, S, (B, C, D), 3),
               Point("point D", Role.LABEL, S, D, "D"))
    eq = VectorEquation((Term("V", "C", False, True),), (Term("V", "B", True, True), Term("V", "CB", False, True)))
    c = c.then("Relative velocity equation on link 3 (BC): V_C = V_B + V_CB, with V_CB perpendicular to BC "
               "and V_C parallel to the guide; two unknown magnitudes.", equation=eq)
    c = c.then("Choose the pole O_v.", Point("pole O_v", Role.LABEL, V, Vec(0, 0), "O_v"))
    c = c.then("Choose the velocity scale: 1 mm = 10 mm/s; V_B is 100 mm long.",
               ScaleBar("velocity scale", Role.SCALE_BAR, V, "velocity", scale))
    c = c.then("Draw V_B from O_v, perpendicular to O1B (1000 mm/s, counter-clockwise); its tip is b.",
               Arrow("V_B", Role.KNOWN, V, Vec(0, 0), vB, "V_B"), Point("image B", Role.LABEL, V, vB, "b"))
    c = c.then("Draw the direction of V_CB through b, perpendicular to BC.",
               TrialLine("trial V_CB", Role.TRIAL, V, vB, BC.perp(), "\u22a5 BC"))
    c = c.then("Draw the direction of V_C through O_v, parallel to the guide.",
               TrialLine("trial V_C", Role.TRIAL, V, Vec(0, 0), Vec(1, 0), "\u2225 guide"))
    c = c.then("The trial lines meet at c. Measure V_C = O_v c and V_CB = bc.",
               Point("image C", Role.LABEL, V, vC, "c"),
               Arrow("result V_C", Role.RESULT, V, Vec(0, 0), vC, "V_C"),
               Arrow("result V_CB", Role.RESULT, V, vB, vC, "V_CB"))
    c = c.then("bcd is the velocity image of BCD; join O_v to d to read V_D.",
               PolygonEntity("image BCD", Role.IMAGE, V, (vB, vC, vD), "image of link 3"),
               Point("image D", Role.LABEL, V, vD, "d"))
    for i in range(extra_steps):
        c = c.then(f"Extra remark {i + 1}: check the construction once more against the analytic solution "
                   f"and write the difference into the results table with its sign and unit.")
    return c


def result_rows(n: int = 8) -> list[ResultRow]:
    base = [("V_B", "1000 mm/s", "1000 mm/s", "0.00 %"), ("V_C", "1017 mm/s", "1016.8 mm/s", "0.02 %"),
            ("V_CB", "522.2 mm/s", "522.2 mm/s", "0.00 %"), ("V_D", "876.1 mm/s", "876.1 mm/s", "0.01 %"),
            ("\u03c9_3", "1.741 rad/s", "1.741 rad/s", "0.00 %"), ("V_CB angle", "253.2 deg", "253.2 deg", "0.0 deg"),
            ("V_D angle", "164.2 deg", "164.2 deg", "0.0 deg"), ("V_C angle", "180 deg", "180 deg", "0 deg")]
    return [ResultRow(*r) for r in (base * 3)[:n]]


def info(**kw) -> SheetInfo:
    base = dict(title="Slider-crank: velocity polygon", drawing_number="TOM-V-001", date="2025-01-15")
    base.update(kw)
    return SheetInfo(**base)


@pytest.fixture(scope="module")
def a4():
    """A4 landscape with 12 steps and 8 result rows."""
    sheet = compose_sheet(slider_crank(), info(), result_rows(8))
    return sheet, ET.fromstring(sheet_to_svg(sheet))


@pytest.fixture(scope="module")
def a3():
    sheet = compose_sheet(slider_crank(), info(paper="A3", notes=("Near a toggle: values are sensitive.",)),
                          result_rows(8))
    return sheet, ET.fromstring(sheet_to_svg(sheet))


def svg_texts(root) -> list[ET.Element]:
    return list(root.iter(f"{SVG}text"))


def joined(el: ET.Element) -> str:
    return "".join(el.itertext())


def floats(s: str) -> list[float]:
    return [float(x) for x in re.findall(r"-?\d+(?:\.\d+)?", s)]


# ---- page, frame, title block -------------------------------------------------------------------

def small_construction() -> Construction:
    """Only the velocity polygon and two steps: fits any sheet."""
    c = slider_crank()
    return Construction(c.title, c.steps[5:9])


@pytest.mark.parametrize("paper,orientation,w,h", [
    ("A4", "landscape", 297, 210), ("A4", "portrait", 210, 297),
    ("A3", "landscape", 420, 297), ("A3", "portrait", 297, 420)])
def test_page_size_and_viewbox(paper, orientation, w, h):
    sheet = compose_sheet(small_construction(), info(paper=paper, orientation=orientation), result_rows(2))
    root = ET.fromstring(sheet_to_svg(sheet))
    assert root.get("width") == f"{w}mm" and root.get("height") == f"{h}mm"
    assert floats(root.get("viewBox")) == [0, 0, w, h]
    frame = [c for c in sheet.commands if isinstance(c, Rectangle) and c.style == "frame"]
    assert len(frame) == 1
    f = frame[0]
    assert (f.x, f.y, f.x + f.w, f.y + f.h) == pytest.approx((20, 10, w - 10, h - 10))
    # and in the SVG: a 0.7 rectangle at the frame
    rects = [r for r in root.iter(f"{SVG}rect") if r.get("stroke-width") == "0.7"
             and floats(r.get("x") + " " + r.get("y") + " " + r.get("width") + " " + r.get("height"))
             == pytest.approx([20, 10, w - 30, h - 20])]
    assert rects


def test_title_block_dimensions_and_contents(a4):
    sheet, root = a4
    tb = sheet.regions["title_block"]
    frame = sheet.regions["frame"]
    assert tb.w <= 180 + 1e-9
    assert tb.right == pytest.approx(frame.right) and tb.bottom == pytest.approx(frame.bottom)
    assert frame.contains(tb)
    texts = {t.plain for t in sheet.texts() if t.region == "title_block"}
    for expected in ("Slider-crank: velocity polygon", "TOM-V-001", "2025-01-15", "1/1", "mm, mm/s, rad/s",
                     "drafting", "Scale", "Units", "Drawing no.", "Created by", "Date", "Sheet"):
        assert expected in texts, expected
    box = [c for c in sheet.commands if isinstance(c, Rectangle) and c.style == "title_block"]
    assert box and box[0].rect == tb
    assert style("title_block").width == 0.7 and style("frame").width == 0.7


def test_scale_text_in_title_block(a4):
    sheet, root = a4
    # each drawing carries its own scale (the space diagram's in its heading, the polygon's bar): "As shown"
    scale = [t for t in sheet.texts() if t.region == "title_block" and t.name.endswith("Scale value")] or \
        [t for t in sheet.texts() if t.region == "title_block" and t.plain == "As shown"]
    assert [t.plain for t in scale] == ["As shown"]
    assert "As shown" in [joined(t) for t in svg_texts(root)]
    assert dict(sheet.scales) == {"space": "Space 1:5", "velocity": "velocity 1 mm = 10 mm/s"}
    headings = {t.plain for t in sheet.texts() if t.name.startswith("heading ")}
    assert {"Space diagram 1:5", "Velocity polygon"} <= headings


def test_velocity_unit_taken_from_sheet_units():
    sheet = compose_sheet(small_construction(), info(units=Units(length="m", velocity="m/s")), result_rows(2))
    assert dict(sheet.scales)["velocity"] == "velocity 1 mm = 0.01 m/s"
    units = [t.plain for t in sheet.texts() if t.name == "scale bar velocity unit"]
    assert units == ["m/s"]


# ---- lettering ------------------------------------------------------------------------------------

def test_labels_with_subscripts(a4):
    sheet, root = a4
    texts = svg_texts(root)
    by_text = {joined(t): t for t in texts}
    for plain in ("b", "c", "d", "B", "C", "D"):
        assert plain in by_text, plain
    # O_v and O1: a base letter and a tspan subscript moved down with dy, never baseline-shift
    for full, base, sub in (("Ov", "O", "v"), ("O1", "O", "1")):
        el = by_text[full]
        assert el.text == base
        tspans = list(el)
        assert tspans[0].text == sub and float(tspans[0].get("dy")) > 0
        assert float(tspans[0].get("font-size")) >= MIN_TEXT
    label_plains = {t.plain for t in sheet.texts() if t.name.endswith(":label")}
    assert {"Ov", "b", "c", "d", "O1", "B", "C", "D"} <= label_plains
    svg = sheet_to_svg(sheet)
    for banned in ("baseline-shift", "marker", "paint-order", "context-stroke", "non-scaling-stroke"):
        assert banned not in svg
    assert root.get("font-family") == "DejaVu Sans"                     # said once, inherited by every text
    assert all(t.get("font-family") in (None, "DejaVu Sans") for t in texts)


def test_every_text_is_at_least_2_5_mm(a4, a3):
    for sheet, root in (a4, a3):
        for t in sheet.texts():
            assert min(t.sizes) >= MIN_TEXT - 1e-9, t.plain
        for el in root.iter():
            if el.get("font-size") is not None:
                assert float(el.get("font-size")) >= MIN_TEXT - 1e-9
    assert MIN_TEXT == 2.5


def test_no_text_overlaps_and_none_leaves_its_region(a4, a3):
    for sheet, _ in (a4, a3):
        texts = sheet.texts()
        for i, a in enumerate(texts):
            assert a.region in sheet.regions, a
            assert sheet.regions[a.region].contains(a.box), (a.plain, a.region)
            for b in texts[i + 1:]:
                assert not a.box.overlaps(b.box), (a.plain, b.plain)


def test_lettering_shrinks_on_a4_and_uses_the_room_on_a3(a4, a3):
    assert 2.5 <= a4[0].text_size <= 3.5
    assert a3[0].text_size == 3.5
    # the space diagram is drawn larger on A3 (ISO scale 1:2 instead of 1:5)
    assert dict(a3[0].scales)["space"] == "Space 1:2"
    assert a3[0].regions["viewport:space"].w > a4[0].regions["viewport:space"].w
    notes = [t.plain for t in a3[0].texts() if t.name.startswith("note ")]
    assert notes and "Near a toggle" in notes[0]


def test_equation_marks_over_each_symbol(a4):
    sheet, _ = a4
    eq = [t for t in sheet.texts() if t.name == "equation 1"]
    assert len(eq) == 1 and eq[0].plain == "VC = VB + VCB"
    assert any(s.italic and s.text == "V" for s in eq[0].spans)
    marks = {t.name.split()[-1]: t for t in sheet.texts() if t.name.startswith("equation 1 marks")}
    assert marks["V_C"].plain == "\u00d7\u2713"        # magnitude unknown, direction known
    assert marks["V_B"].plain == "\u2713\u2713"
    assert marks["V_CB"].plain == "\u00d7\u2713"
    for m in marks.values():
        assert m.box.bottom <= eq[0].box.top + 1e-9
        assert eq[0].box.left - 1e-9 <= m.box.center[0] <= eq[0].box.right
    steps = [t for t in sheet.texts() if t.name.endswith(" number") and t.name.startswith("step ")]
    assert [t.plain for t in steps] == [f"{i}." for i in range(1, 13)]


# ---- geometry ----------------------------------------------------------------------------------

def test_viewports_inside_the_frame_and_apart(a4, a3):
    for sheet, _ in (a4, a3):
        frame = sheet.regions["frame"]
        keys = [k for k in sheet.regions if k.startswith(("viewport:", "text:")) or k == "title_block"]
        assert {"viewport:space", "viewport:velocity"} <= set(keys)
        for i, a in enumerate(keys):
            assert frame.contains(sheet.regions[a]), a
            for b in keys[i + 1:]:
                assert not sheet.regions[a].overlaps(sheet.regions[b], -1e-6), (a, b)
        for c in sheet.commands:
            for x, y in L_points(c):
                assert frame.contains_point(x, y, tol=0.5), c


def L_points(c):
    from drafting.render.paper import command_points
    return command_points(c)


def _paper(sheet, key, v: Vec):
    return sheet.transforms[key](v)


def test_arrowheads_are_filled_polygons_with_the_apex_at_the_tip(a4):
    sheet, root = a4
    con = slider_crank()
    arrows = [e for e in con.entities(V) if isinstance(e, Arrow)]
    assert len(arrows) == 3
    for a in arrows:
        heads = [c for c in sheet.commands if isinstance(c, Polygon) and c.name == f"{a.name}:head"]
        assert len(heads) == 1
        head = heads[0]
        assert style(head.style).fill == "black"
        tip, tail = _paper(sheet, "velocity", a.tip), _paper(sheet, "velocity", a.tail)
        assert head.points[0] == pytest.approx(tip, abs=1e-9)
        # the apex is the vertex farthest from the tail: the head points at the tip
        far = max(head.points, key=lambda p: math.dist(p, tail))
        assert far == head.points[0]
        shaft = [c for c in sheet.commands if isinstance(c, Line) and c.name == a.name]
        assert len(shaft) == 1 and style(shaft[0].style).width == 0.5
        assert math.dist((shaft[0].x1, shaft[0].y1), tail) < 1e-9
        assert math.dist((shaft[0].x2, shaft[0].y2), tip) < 3.5
    polys = [p for p in root.iter(f"{SVG}polygon") if p.get("fill") == "black"]
    assert len(polys) >= 3


def test_trial_lines_extend_past_the_intersection(a4):
    sheet, _ = a4
    con = slider_crank()
    c = con.entity("image C").at
    cp = _paper(sheet, "velocity", c)
    for name in ("trial V_CB", "trial V_C"):
        (ln,) = [x for x in sheet.commands if isinstance(x, Line) and x.name == name]
        assert style(ln.style).width == 0.25
        a, b = (ln.x1, ln.y1), (ln.x2, ln.y2)
        # c lies on the drawn line, inside it, and the line runs 8..15 mm past it
        u = ((b[0] - a[0]) / ln.length, (b[1] - a[1]) / ln.length)
        t = (cp[0] - a[0]) * u[0] + (cp[1] - a[1]) * u[1]
        off = abs((cp[0] - a[0]) * u[1] - (cp[1] - a[1]) * u[0])
        assert off < 1e-6
        assert 8.0 <= min(t, ln.length - t) <= 15.0
    # through b (the known point) the V_CB line also runs past b
    (ln,) = [x for x in sheet.commands if isinstance(x, Line) and x.name == "trial V_CB"]
    bp = _paper(sheet, "velocity", con.entity("image B").at)
    ends = [math.dist(bp, (ln.x1, ln.y1)), math.dist(bp, (ln.x2, ln.y2))]
    assert 8.0 <= min(ends) <= 15.0


def test_labels_do_not_cover_arrowheads_or_dots(a4, a3):
    for sheet, _ in (a4, a3):
        heads = [c for c in sheet.commands if isinstance(c, Polygon) and c.style == "arrowhead"]
        dots = [c for c in sheet.commands if c.style in ("dot", "pin")]
        bgs = [c.rect for c in sheet.commands if isinstance(c, Rectangle) and c.style == "label_bg"]
        assert bgs
        from drafting.render.paper import Rect, command_points
        for bg in bgs:
            for h in heads + dots:
                assert not bg.overlaps(Rect.bounding(command_points(h))), h.name
        for i, a in enumerate(bgs):
            for b in bgs[i + 1:]:
                assert not a.overlaps(b)


def test_styles_read_in_black_and_white(a4):
    sheet, root = a4
    paints = set()
    for el in root.iter():
        for attr in ("fill", "stroke"):
            if el.get(attr) is not None:
                paints.add(el.get(attr))
    assert paints <= {"none", "black", "white", "#d9d9d9"}
    assert style("link").width == 0.5 and style("trial").width == 0.25
    assert dashed(0.25) == (3.0, 0.75)
    assert long_dash_dot(0.5)[0] + 0.5 == 24 * 0.5 and long_dash_dot(0.5)[1] - 0.5 == 3 * 0.5
    assert style("image").fill == "#d9d9d9" and style("image").width == 0.25
    # the image polygon is filled light grey with a thin outline
    assert [c for c in sheet.commands if isinstance(c, Polygon) and c.name == "image BCD"][0].style == "image"


def test_scale_bars_are_true_to_their_numbers(a4):
    sheet, _ = a4
    for key, paper_per_unit in (("space", 1 / 5), ("velocity", 1 / 10)):
        segs = [c for c in sheet.commands if isinstance(c, Rectangle) and c.name.startswith(f"scale bar {key} segment")]
        length = sum(s.w for s in segs)
        nums = [t for t in sheet.texts() if t.name.startswith(f"scale bar {key} number")]
        last = max(nums, key=lambda t: t.box.right)
        assert float(last.plain) * paper_per_unit == pytest.approx(length)
        assert 20 <= length <= 100
        ticks = [c for c in sheet.commands if isinstance(c, Line) and c.name.startswith(f"scale bar {key} tick")]
        assert len(ticks) == len(segs) + 1


def test_svg_is_stable_and_rounded(a4):
    sheet, _ = a4
    svg = sheet_to_svg(sheet)
    assert svg == sheet_to_svg(sheet)
    assert not re.search(r"\d\.\d{4,}", svg)


def test_too_much_for_one_a4_sheet_spills_onto_more():
    """30 more steps and 20 result rows: a document of sheets n/m (compose_sheet names the count)."""
    big = slider_crank(extra_steps=30)
    sheets = compose_sheets(big, info(), result_rows(20))
    m = len(sheets)
    assert m >= 2 and [s.number for s in sheets] == [(i + 1, m) for i in range(m)]
    for s in sheets:
        assert f"{s.number[0]}/{m}" in {t.plain for t in s.texts() if t.region == "title_block"}
        assert s.text_size >= MIN_TEXT
    steps = [t for s in sheets for t in s.texts() if t.name.startswith("step ") and t.name.endswith(" number")]
    assert sorted(int(t.plain[:-1]) for t in steps) == list(range(1, 43))
    with pytest.raises(LayoutError, match=f"{m} sheets.*use A3"):
        compose_sheet(big, info(), result_rows(20))


def test_a4_portrait_too_full_for_one_sheet_takes_two():
    sheets = compose_sheets(slider_crank(), info(orientation="portrait"), result_rows(8))
    assert len(sheets) == 2
    assert {k for s in sheets for k in s.regions if k.startswith("viewport:")} == {"viewport:space",
                                                                                   "viewport:velocity"}
    with pytest.raises(LayoutError, match="2 sheets.*use A3"):
        compose_sheet(slider_crank(), info(orientation="portrait"), result_rows(8))


def test_bad_sheet_number_and_paper():
    with pytest.raises(ValueError):
        SheetInfo("t", "n", sheet=(2, 1))
    with pytest.raises(ValueError, match="paper"):
        compose_sheet(small_construction(), info(paper="B5"), ())


@settings(max_examples=12, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(angle=st.floats(20.0, 160.0), crank=st.floats(0.05, 0.12))
def test_random_positions_keep_labels_apart(angle, crank):
    sheet = compose_sheet(slider_crank(angle, crank=crank), info(), result_rows(6))
    texts = sheet.texts()
    for i, a in enumerate(texts):
        assert sheet.regions[a.region].contains(a.box)
        for b in texts[i + 1:]:
            assert not a.box.overlaps(b.box), (a.plain, b.plain)
    for name in ("Ov", "b", "c", "O1", "B", "C"):
        assert name in {t.plain for t in texts if t.name.endswith(":label")}
