"""The drawer registry and the drawers of the open entity set, checked on their drawing commands.

Every entity type has exactly one drawer (found through its MRO); an entity without one is an error
naming its type and diagram, never silently dropped; every Role has a line and an area style.  The new
entities (circles, curves, segments, ISO 129 dimensions, angle marks, notes, charts) are drawn and
measured here without a solver.
"""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET
from dataclasses import dataclass

import pytest

from constructions.entities import (AngleMark, Chart, Circle, Curve, Diagram, Dimension, Entity, Note, Point, Role,
                                    Segment, Series)
from constructions.geometry import Vec
from constructions.record import Construction, Step, Value
from drafting.render import drawing as D
from drafting.layout.diagram import draw_entities, model_points
from drafting.render.drawing import drawer, drawer_for
from drafting.render.errors import DrawingError, StyleError
from drafting.render.annotations import _text_half
from drafting.render.paper import Circle as CircleCmd, Line, Polygon, Polyline, Rect, Rectangle, Text
from drafting.layout.sheet import SheetInfo, compose_sheets
from drafting.render.style import AREA_STYLES, LINE_STYLES, area_style_for, line_style_for, long_dash_dot, style, styles
from drafting.backends.svg import sheet_to_svg

S = Diagram.SPACE


# ---- styles -------------------------------------------------------------------------------------------

def test_every_role_has_a_line_and_an_area_style():
    for role in Role:
        assert line_style_for(role) in styles(), role
        assert area_style_for(role) in styles(), role
    assert set(LINE_STYLES) == set(Role) and set(AREA_STYLES) == set(Role)
    assert line_style_for(Role.CENTRE_LINE) == "centre" and style("centre").dash == long_dash_dot(0.25)
    assert style(line_style_for(Role.PATH)).width == 0.25
    assert style(line_style_for(Role.LOAD)).width == 0.5


def test_an_unknown_role_or_style_names_itself():
    with pytest.raises(StyleError, match="spring"):
        line_style_for("spring")                                   # type: ignore[arg-type]
    with pytest.raises(StyleError, match="spring"):
        area_style_for("spring")                                   # type: ignore[arg-type]
    with pytest.raises(StyleError, match="no style named 'wavy'") as e:
        style("wavy")
    assert not str(e.value).startswith("\"")                       # a sentence, not a KeyError repr


# ---- the registry ---------------------------------------------------------------------------------

@dataclass(frozen=True, slots=True)
class Spring(Entity):
    """An entity type the drawing layer has never heard of."""

    start: Vec
    end: Vec


@dataclass(frozen=True, slots=True)
class TaggedPoint(Point):
    """A subclass of a drawable type: drawn by its base's drawer."""

    tag: str = ""


def test_an_entity_without_a_drawer_is_an_error_naming_its_type_and_diagram():
    spring = Spring("spring 1", Role.GIVEN, Diagram("free body", "link 3"), Vec(0, 0), Vec(1, 0))
    with pytest.raises(DrawingError, match=r"Spring.*'spring 1'.*free body: link 3"):
        draw_entities([spring], 1000.0)
    with pytest.raises(DrawingError, match="Spring"):
        model_points([spring])
    c = Construction("t").then("A spring.", spring)
    with pytest.raises(DrawingError, match="Spring"):
        compose_sheets(c, SheetInfo("t", "n", date="2026-11-22"))


def test_subclasses_are_drawn_by_their_base_drawer():
    d = draw_entities([TaggedPoint("p", Role.LABEL, S, Vec(0.01, 0.02), "P", "x")], 1000.0)
    assert [c.name for c in d.commands] == ["p"]
    assert d.labels[0].markup == "P"
    assert drawer_for(TaggedPoint) is drawer_for(Point)


def test_a_new_type_plugs_in_with_the_decorator():
    @dataclass(frozen=True, slots=True)
    class Rod(Entity):
        start: Vec
        end: Vec

    @drawer(Rod, points=lambda e: (e.start, e.end))
    def draw_rod(e, ctx):
        ctx.d.add(D.LINKS, Line(*ctx.T(e.start), *ctx.T(e.end), line_style_for(e.role), e.name))

    try:
        d = draw_entities([Rod("rod", Role.GIVEN, S, Vec(0, 0), Vec(0.05, 0))], 1000.0)
        (ln,) = d.commands
        assert (ln.x1, ln.x2, ln.style) == (0.0, 50.0, "link")
        assert model_points([Rod("r", Role.GIVEN, S, Vec(0, 0), Vec(0.05, 0))]) == [Vec(0, 0), Vec(0.05, 0)]
        with pytest.raises(ValueError, match="already has"):
            drawer(Rod)(draw_rod)
    finally:
        D._REGISTRY.pop(Rod, None)


# ---- circles, curves, segments ---------------------------------------------------------------------

def test_circles_by_role():
    ents = [Circle("pitch", Role.CENTRE_LINE, S, Vec(0, 0), 0.04), Circle("locus", Role.PATH, S, Vec(0, 0), 0.02),
            Circle("roller", Role.GIVEN, S, Vec(0.1, 0), 0.01, "R")]
    d = draw_entities(ents, 1000.0)
    circles = {c.name: c for c in d.commands if isinstance(c, CircleCmd)}
    assert circles["pitch"].style == "centre" and circles["pitch"].r == pytest.approx(40.0)
    assert circles["locus"].style == "path" and style("path").width == 0.25
    assert circles["roller"].style == "link" and style("link").width == 0.5
    # labels avoid circles: their outlines are segments of the drawing
    assert len(d.segments) >= 3 * 24
    bb = d.bbox()
    assert bb.w == pytest.approx(40 + 110) and bb.h == pytest.approx(80)
    pts = model_points(ents)
    assert Vec(0.11, 0) in pts and Vec(0, 0.04) in pts


def test_curves_thick_or_thin_and_closed():
    pts = tuple(Vec(0.01 * i, 0.001 * i * i) for i in range(6))
    d = draw_entities([Curve("profile", Role.GIVEN, S, pts, closed=True),
                       Curve("involute", Role.PATH, S, pts + (Vec(float("nan"), 0),))], 1000.0)
    (profile,) = [c for c in d.commands if c.name == "profile"]
    (involute,) = [c for c in d.commands if c.name == "involute"]
    assert isinstance(profile, Polygon) and profile.style == "link"
    assert isinstance(involute, Polyline) and involute.style == "path" and len(involute.points) == 6


def test_segments():
    d = draw_entities([Segment("line of action", Role.CENTRE_LINE, S, Vec(0, 0), Vec(0.03, 0.04), "LoA")], 1000.0)
    (ln,) = d.commands
    assert ln.style == "centre" and ln.length == pytest.approx(50.0)
    assert d.labels[0].kind == "arrow" and d.labels[0].markup == "LoA"


# ---- annotations --------------------------------------------------------------------------------

def _values_text(values):
    def text(entity, words):
        return Step(words, values=tuple(values.items())).text(lambda v: f"{v.value * 1000:.0f} mm")
    return text


def test_iso_129_dimension():
    dim = Dimension("dim O1B", Role.DIMENSION, S, Vec(0, 0), Vec(0.1, 0), 0.02, "$l")
    d = draw_entities([dim], 1000.0, text=_values_text({"l": Value("length", 0.1)}))
    lines = {c.name: c for c in d.commands if isinstance(c, Line)}
    ext_a, ext_b, main = lines["dim O1B:extension a"], lines["dim O1B:extension b"], lines["dim O1B"]
    # the dimension line 20 mm to the left of start -> end (model y up: above it, paper y down)
    assert main.y1 == pytest.approx(-20.0) and main.y2 == pytest.approx(-20.0)
    assert (main.x1, main.x2) == pytest.approx((0.0, 100.0))
    # extension lines: a small gap at the feature, and 2 mm past the dimension line
    for ext, x in ((ext_a, 0.0), (ext_b, 100.0)):
        assert ext.x1 == pytest.approx(x) and ext.x2 == pytest.approx(x)
        assert ext.y1 == pytest.approx(-1.0) and ext.y2 == pytest.approx(-22.0)
        assert style(ext.style).width == 0.25
    # filled arrowheads with their apexes on the extension lines, pointing outwards
    heads = [c for c in d.commands if isinstance(c, Polygon) and c.style == "arrowhead"]
    assert sorted(round(h.points[0][0], 6) for h in heads) == [0.0, 100.0]
    for h in heads:
        apex, others = h.points[0], h.points[1:]
        inward = 1 if apex[0] == pytest.approx(0.0) else -1
        assert all((p[0] - apex[0]) * inward > 0 for p in others)
    # the value, horizontal, above the middle of the line: a mandatory note handed to the label placer
    # (which sets it there where clear, else beside, on a white note ground)
    (req,) = [r for r in d.labels if r.name == "dim O1B"]
    assert req.kind == "note" and req.markup == "100 mm" and req.mandatory
    assert req.anchor[0] == pytest.approx(50.0) and req.anchor[1] < -20.0
    assert style("note_bg").fill == "white"


def test_angle_mark_arc_arrow_and_text():
    m = AngleMark("theta", Role.DIMENSION, S, Vec(0, 0), 0.02, 0.0, math.radians(60), "\u03b8 = 60\u00b0")
    d = draw_entities([m], 1000.0)
    (arc,) = [c for c in d.commands if isinstance(c, Polyline)]
    for x, y in arc.points:
        assert math.hypot(x, y) == pytest.approx(20.0)
    (head,) = [c for c in d.commands if isinstance(c, Polygon)]
    end = (20 * math.cos(math.radians(60)), -20 * math.sin(math.radians(60)))
    assert head.points[0] == pytest.approx(end)
    # the value is a mandatory label at the middle of the arc, placed by the label placer off the lines
    (req,) = [r for r in d.labels if r.name == "theta"]
    assert req.markup == "\u03b8 = 60\u00b0" and req.mandatory
    assert req.anchor == pytest.approx((20 * math.cos(math.radians(30)), -20 * math.sin(math.radians(30))))


def test_note_on_a_white_ground():
    d = draw_entities([Note("note", Role.NOTE, S, Vec(0.05, 0.05), "toggle")], 1000.0)
    (req,) = d.labels                       # the placer sets it there on a note ground where clear
    assert req.kind == "note" and req.markup == "toggle" and req.mandatory
    assert req.anchor == pytest.approx((50.0, -50.0))
    assert model_points([Note("n", Role.NOTE, S, Vec(1, 2), "x")]) == [Vec(1, 2)]


# ---- charts ---------------------------------------------------------------------------------------

def chart() -> Chart:
    n = 73
    x = tuple(2 * math.pi * i / (n - 1) for i in range(n))
    s = tuple(0.02 * (1 - math.cos(t)) for t in x)
    v = tuple(float("nan") if 30 <= i <= 34 else 0.02 * math.sin(t) for i, t in enumerate(x))
    return Chart("cam chart", Role.CHART, Diagram("chart", "Follower motion"), "angle", "cam angle",
                 (Series("lift s", x, s, "length"), Series("s' (per rad)", x, v, "length")),
                 bands=((0.035, 0.045, "dwell"),))


def test_a_chart_in_a_panel_of_its_own():
    c = Construction("Cam").then("Plot the follower motion.", chart())
    (sheet,) = compose_sheets(c, SheetInfo("Cam", "TOM-C-1", date="2026-11-22"))
    key = "viewport:chart: Follower motion"
    assert key in sheet.regions
    panel = sheet.regions[key]
    cmds = [c for c in sheet.commands if c.name.startswith("cam chart:")]
    # one polyline per finite run: the NaN gap splits the second series
    runs = [c for c in cmds if isinstance(c, Polyline)]
    assert sorted(c.name for c in runs) == ["cam chart:series 1 run 1", "cam chart:series 2 run 1",
                                            "cam chart:series 2 run 2"]
    assert runs[0].style != runs[1].style or runs[0].name.split()[2] == runs[1].name.split()[2]
    assert {c.style for c in runs} == {"series 1", "series 2"}
    # x ticks in degrees at a division of the turn (30, 45, 90 ...), y in mm
    xs = [float(t.plain) for t in cmds if isinstance(t, Text) and t.name == "cam chart:number x"]
    steps = {round(b - a, 9) for a, b in zip(xs, xs[1:])}
    assert len(steps) == 1 and steps.pop() in (30.0, 45.0, 90.0) and xs[0] <= 0 and xs[-1] >= 360
    ys = [float(t.plain) for t in cmds if isinstance(t, Text) and t.name == "cam chart:number y"]
    assert min(ys) <= -20 and max(ys) >= 45
    units = {t.plain for t in cmds if isinstance(t, Text)}
    assert "mm" in units and "cam angle (\u00b0)" in units and "dwell" in units
    assert [c for c in cmds if isinstance(c, Rectangle) and c.style == "band"]
    legend = [t.plain for t in cmds if isinstance(t, Text) and ":legend" in t.name]
    assert legend == ["lift s", "s\u2032 (per rad)"]
    for cmd in cmds:
        from drafting.render.paper import command_points
        for x, y in command_points(cmd):
            assert panel.contains_point(x, y, tol=0.01), cmd.name
    texts = [t for t in sheet.texts() if t.region == key]
    for i, a in enumerate(texts):
        for b in texts[i + 1:]:
            assert not a.box.overlaps(b.box), (a.plain, b.plain)
    ET.fromstring(sheet_to_svg(sheet))


def test_a_sheet_with_every_new_entity_renders():
    c = (Construction("Drafting entities")
         .then("Base circle and a roller.", Circle("base", Role.CENTRE_LINE, S, Vec(0, 0), 0.03),
               Circle("roller", Role.GIVEN, S, Vec(0.045, 0.0), 0.008, "R"))
         .then("The profile.", Curve("profile", Role.GIVEN, S, tuple(Vec.polar(0.035 + 0.005 * math.sin(3 * t), t)
                                                                      for t in (i * 0.1 for i in range(63))), True))
         .then("Line of action, $r from the centre.", Segment("loa", Role.TRIAL, S, Vec(-0.05, 0.01), Vec(0.05, 0.01)),
               Dimension("dim r", Role.DIMENSION, S, Vec(0, 0), Vec(0, -0.03), 0.05, "$r"),
               AngleMark("phi", Role.DIMENSION, S, Vec(0, 0), 0.015, 0.0, 1.0, "\u03c6"),
               Note("note", Role.NOTE, S, Vec(-0.04, 0.04), "prime circle"),
               values={"r": Value("length", 0.03)}))
    (sheet,) = compose_sheets(c, SheetInfo("Entities", "TOM-X-2", date="2026-11-22"))
    texts = {t.plain for t in sheet.texts()}
    assert {"30 mm", "\u03c6", "prime circle", "R"} <= texts
    assert any("30 mm from the centre" in t for t in texts)
    root = ET.fromstring(sheet_to_svg(sheet))
    assert root.iter("{http://www.w3.org/2000/svg}circle")


def test_notes_close_together_are_set_clear_of_each_other_the_least_way():
    """Names of circles a few mm apart (a gear's pitch, base, addendum circles): each note that would cover
    one set before it moves up or down just clear of it, whichever is nearer; a note with room stays put."""
    notes = [Note("pitch", Role.NOTE, S, Vec(0.0, 0.0), "pitch circle"),
             Note("base", Role.NOTE, S, Vec(0.001, -0.002), "base circle"),          # 2 mm lower: overlaps
             Note("addendum", Role.NOTE, S, Vec(-0.002, 0.0045), "addendum circle"),  # 4.5 mm higher: just touches
             Note("far", Role.NOTE, S, Vec(0.2, 0.2), "far away")]
    d = draw_entities(notes, 1000.0)
    # each note's point handed to the label placer (which keeps it there where no heavy line runs)
    grounds = {}
    for r in d.labels:
        hw, hh = _text_half(r.markup)
        grounds[r.name] = Rect(r.anchor[0] - hw, r.anchor[1] - hh, 2 * hw, 2 * hh)
    names = list(grounds)
    for i, a in enumerate(names):
        for b in names[i + 1:]:
            assert not grounds[a].overlaps(grounds[b], 0.3 - 1e-9), (a, b)
    assert grounds["pitch"].center == pytest.approx((0.0, 0.0), abs=1e-9)          # the first stays
    assert grounds["far"].center == pytest.approx((200.0, -200.0), abs=1e-9)       # room: stays put
    assert grounds["base"].top == pytest.approx(grounds["pitch"].bottom + 0.3, abs=1e-5)     # just below
    assert grounds["addendum"].bottom == pytest.approx(grounds["pitch"].top - 0.3, abs=1e-5)  # just above


@pytest.mark.parametrize("scene", ["notes-roller-cam.toml", "oscillating-flat-faced-cam.toml", "gear-pair-20-40.toml",
                                   "notes-dynamic-example-3.toml", "cycle-four-bar.toml"])
def test_a_drawing_made_for_its_extent_has_the_whole_drawing_s_extent(scene):
    """The page planner measures a diagram at each scale it tries from a drawing made for its extent only
    (no segments for the labels, a curve by its extreme points): the same box, bit for bit, as the whole
    drawing's, at every scale of every panel -- a NaN in a curve's points included."""
    from drafting.scene.reader import load_scene
    from drafting.study.study import Study
    from paths import GALLERY
    study = Study(load_scene(GALLERY / scene)).run()
    by_diagram: dict = {}
    for e in study.construction.entities():
        if not D.is_panel_entity(e):              # (charts are drawn in panels of their own)
            by_diagram.setdefault(e.diagram, []).append(e)
    assert by_diagram
    for ents in by_diagram.values():
        for k in (0.1, 0.5, 1.0, 2.0, 1000.0, 12345.678):
            whole, extent = draw_entities(ents, k), draw_entities(ents, k, extent_only=True)
            assert extent.bbox() == whole.bbox() and not extent.segments
    holes = Curve("holed", Role.GIVEN, Diagram.SPACE, (Vec(0, 0), Vec(float("nan"), 1), Vec(3, -2), Vec(1, 5)))
    assert draw_entities([holes], 2.0, extent_only=True).bbox() == draw_entities([holes], 2.0).bbox()
