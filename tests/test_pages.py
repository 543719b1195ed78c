"""Sheets that hold more: several diagrams packed onto one or more pages, each polygon at the largest
1-2-5 scale that fits its panel when its construction leaves the scale to the drawing.

The constructions are built by hand with the record API (no solver): the slider-crank of
``test_sheet`` (crank 100 mm at 60 deg, coupler 300 mm, 10 rad/s) with its velocity polygon; the
"acceleration polygon" here is the same figure copied into Diagram.ACCELERATION with its own scale bar
(a sheet test only needs a second vector diagram, not the right accelerations), and force polygons are
copies in Diagram("force", "link 2") and Diagram("force", "link 3").  The steps carry their scale and
the length of V_B as values, so what the text says can be checked against the scale drawn.
"""

from __future__ import annotations

import dataclasses
import re
import xml.etree.ElementTree as ET

import pytest

from constructions.entities import Diagram, ScaleBar
from constructions.record import Construction, Step, Term, Value, VectorEquation
from drafting.layout.diagram import model_points
from drafting.render.errors import LayoutError
from drafting.render.paper import command_points
from drafting.layout.sheet import SheetInfo, compose_sheet, compose_sheets
from drafting.render.style import MIN_TEXT
from drafting.backends.svg import sheet_to_svg
from drafting.scene.unitset import Units
from drafting.layout.panels import POLYGON_MIN_MM

from test_sheet import result_rows, slider_crank

V, A = Diagram.VELOCITY, Diagram.ACCELERATION
ONE_TWO_FIVE = re.compile(r"^(1|2|5)(0*)$|^0\.(0*)(1|2|5)$")


def is_125(v: float) -> bool:
    s = f"{v:.12g}"
    return bool(ONE_TWO_FIVE.match(s))


def free_scale(c: Construction) -> Construction:
    """The velocity polygon with its scale left to the drawing, and its scale step written with values."""
    steps = []
    vb = c.entity("V_B")
    for s in c.steps:
        if any(isinstance(e, ScaleBar) for e in s.entities):
            bar = next(e for e in s.entities if isinstance(e, ScaleBar))
            s = Step("Choose the velocity scale: 1 mm = $s; V_B is $len.",
                     entities=(dataclasses.replace(bar, units_per_mm=None),),
                     values=(("s", Value("scale", None, "velocity")),
                             ("len", Value("paper length", (vb.tip - vb.tail).norm(), "velocity"))))
        steps.append(s)
    return Construction(c.title, tuple(steps))


def copy_diagram(c: Construction, target: Diagram, quantity: str, prefix: str, *, words: str) -> Construction:
    """The velocity polygon's entities copied into ``target`` with a free scale of ``quantity``."""
    ents = []
    for e in c.entities(V):
        kw: dict = {"name": f"{prefix} {e.name}", "diagram": target}
        if isinstance(e, ScaleBar):
            kw.update(quantity=quantity, units_per_mm=None)
        label = getattr(e, "label", None)
        if label:
            kw["label"] = label + "'"
        ents.append(dataclasses.replace(e, **kw))
    eq = VectorEquation((Term("A", "C", False, True),), (Term("A", "B", True, True), Term("A", "CB", False, True)))
    return c.with_step(Step(words, equation=eq, entities=tuple(ents)))


def three_diagrams() -> Construction:
    c = free_scale(slider_crank())
    c = copy_diagram(c, A, "acceleration", "acc", words="Draw the acceleration polygon from O_a at its scale.")
    return c.with_step(Step("The acceleration scale: 1 mm = $s.",
                            values=(("s", Value("scale", None, "acceleration")),)))


def with_forces(c: Construction) -> Construction:
    for name in ("link 2", "link 3"):
        c = copy_diagram(c, Diagram("force", name), "force", name, words=f"Draw the force polygon of {name}.")
    return c


def info(**kw) -> SheetInfo:
    base = dict(title="Slider-crank: velocity and acceleration", drawing_number="TOM-A-001", date="2026-11-22")
    base.update(kw)
    return SheetInfo(**base)


LAYOUTS = [("A4", "landscape"), ("A3", "landscape"), ("A4", "portrait"), ("A3", "portrait")]


@pytest.fixture(scope="module", params=LAYOUTS, ids=lambda p: f"{p[0]}-{p[1]}")
def document(request):
    paper, orientation = request.param
    con = three_diagrams()
    return con, compose_sheets(con, info(paper=paper, orientation=orientation), result_rows(8))


def panels(sheets):
    """(sheet, key, viewport rect) of every diagram on every page."""
    return [(s, r[len("viewport:"):], rect) for s in sheets for r, rect in s.regions.items()
            if r.startswith("viewport:")]


def extent_mm(con: Construction, diagram: Diagram, k: float) -> tuple[float, float]:
    pts = model_points([e for e in con.entities(diagram) if not isinstance(e, ScaleBar)])
    return ((max(p.x for p in pts) - min(p.x for p in pts)) * k, (max(p.y for p in pts) - min(p.y for p in pts)) * k)


# ---- every diagram gets a panel, on one page or on sheets n/m -------------------------------------

def test_every_diagram_once_and_sheet_numbers(document):
    con, sheets = document
    keys = [k for _, k, _ in panels(sheets)]
    assert sorted(keys) == ["acceleration", "space", "velocity"]
    m = len(sheets)
    assert 1 <= m <= 2
    for i, s in enumerate(sheets):
        assert s.number == (i + 1, m)
        tb = {t.plain for t in s.texts() if t.region == "title_block"}
        assert f"{i + 1}/{m}" in tb and "TOM-A-001" in tb
        root = ET.fromstring(sheet_to_svg(s))
        assert f"{i + 1}/{m}" in ["".join(t.itertext()) for t in root.iter("{http://www.w3.org/2000/svg}text")]


def test_a4_landscape_spills_onto_a_second_sheet_rather_than_failing():
    """Space, velocity, acceleration and two force polygons with 16 steps and 8 result rows do not fit
    one A4 landscape sheet legibly: two sheets, each complete with its title block."""
    con = with_forces(three_diagrams())
    sheets = compose_sheets(con, info(), result_rows(8))
    assert len(sheets) == 2
    assert [s.number for s in sheets] == [(1, 2), (2, 2)]
    assert sorted(k for _, k, _ in panels(sheets)) == ["acceleration", "force: link 2", "force: link 3", "space",
                                                        "velocity"]
    with pytest.raises(LayoutError, match="2 sheets.*A3"):
        compose_sheet(con, info(), result_rows(8))
    # on A3 it all fits one sheet
    assert len(compose_sheets(con, info(paper="A3"), result_rows(8))) == 1


def test_the_text_flows_across_the_sheets_in_order(document):
    _, sheets = document
    numbers = [int(t.plain[:-1]) for s in sheets for t in sorted(
        (t for t in s.texts() if t.name.startswith("step ") and t.name.endswith(" number")),
        key=lambda t: (0 if t.region == "text:0" else 1, t.y))]
    assert sorted(numbers) == list(range(1, len(numbers) + 1))
    rows = [t for s in sheets for t in s.texts() if t.name.startswith("results row")]
    assert rows, "the results table is on one of the sheets"


def test_nothing_overlaps_and_nothing_leaves_its_region(document):
    _, sheets = document
    for s in sheets:
        texts = s.texts()
        for i, a in enumerate(texts):
            assert a.region in s.regions, a
            assert s.regions[a.region].contains(a.box), (a.plain, a.region)
            assert min(a.sizes) >= MIN_TEXT - 1e-9
            for b in texts[i + 1:]:
                assert not a.box.overlaps(b.box), (a.plain, b.plain)
        keys = [k for k in s.regions if k.startswith(("viewport:", "text:")) or k == "title_block"]
        for i, a in enumerate(keys):
            assert s.regions["frame"].contains(s.regions[a]), a
            for b in keys[i + 1:]:
                assert not s.regions[a].overlaps(s.regions[b], -1e-6), (a, b)
        for c in s.commands:
            for x, y in command_points(c):
                assert s.regions["frame"].contains_point(x, y, tol=0.5), c


# ---- scales ----------------------------------------------------------------------------------------

def test_every_polygon_at_a_125_scale_that_fills_its_panel(document):
    con, sheets = document
    for s, key, rect in panels(sheets):
        if key == "space":
            continue
        scale = s.diagram_scales[key]
        assert is_125(scale.per_mm), scale
        assert f"{key} 1 mm = {scale.text}" in dict(s.scales)[key]
        k = s.transforms[key].k
        assert k == pytest.approx(1.0 / scale.units_per_mm)
        w, h = extent_mm(con, V if key == "velocity" else A, k)
        assert max(w, h) >= POLYGON_MIN_MM - 1e-9                      # legible
        # the panel is used: the polygon's larger side against the panel's side along it
        used = w / rect.w if w >= h else h / rect.h
        assert used >= 0.35, (key, used, rect)
        # and it is the largest 1-2-5 scale that fits: one step up would not fit the panel
        step = 2.5 if f"{scale.per_mm:.12g}"[0] == "5" else 2.0
        assert w * step > rect.w - 16 - 20 or h * step > rect.h - 16 - 20


def test_polygons_grow_with_the_paper():
    """A polygon left to the drawing is larger on A3 than on A4, where its panel is larger."""
    con = free_scale(slider_crank())
    sizes = {}
    for paper, orientation in LAYOUTS:
        (s,) = compose_sheets(con, info(paper=paper, orientation=orientation), result_rows(8))
        sizes[paper, orientation] = max(extent_mm(con, V, s.transforms["velocity"].k))
    assert sizes["A3", "landscape"] > sizes["A4", "landscape"] * 1.9
    assert sizes["A3", "portrait"] > sizes["A4", "portrait"] * 1.9
    assert min(sizes.values()) >= POLYGON_MIN_MM


def test_a_fixed_scale_is_kept():
    c = three_diagrams()
    steps = [dataclasses.replace(s, entities=tuple(dataclasses.replace(e, units_per_mm=0.05)
                                                   if isinstance(e, ScaleBar) and e.diagram == A else e
                                                   for e in s.entities)) for s in c.steps]
    sheets = compose_sheets(Construction(c.title, tuple(steps)), info(paper="A3"), result_rows(8))
    (acc,) = [s for s in sheets if "acceleration" in s.diagram_scales]
    assert acc.diagram_scales["acceleration"].per_mm == pytest.approx(50.0)           # 0.05 m/s^2 = 50 mm/s^2
    assert dict(acc.scales)["acceleration"] == "acceleration 1 mm = 50 mm/s\u00b2"


def test_step_values_say_the_scale_drawn():
    sheets = compose_sheets(three_diagrams(), info(), result_rows(8))
    texts = " ".join(t.plain for s in sheets for t in s.texts() if t.name.startswith("step "))
    v = next(s.diagram_scales["velocity"] for s in sheets if "velocity" in s.diagram_scales)
    a = next(s.diagram_scales["acceleration"] for s in sheets if "acceleration" in s.diagram_scales)
    vb = 1.0                                    # |V_B| = 10 rad/s x 0.1 m
    length = vb / v.units_per_mm
    assert f"1 mm = {v.text}; V" in texts and f"is {length:.0f} mm long" in texts
    assert f"1 mm = {a.text}." in texts
    assert "$" not in texts


def test_several_force_diagrams_each_get_a_panel():
    con = with_forces(three_diagrams())
    sheets = compose_sheets(con, info(paper="A3"), result_rows(4))
    keys = sorted(k for _, k, _ in panels(sheets))
    assert keys == ["acceleration", "force: link 2", "force: link 3", "space", "velocity"]
    headings = {t.plain for s in sheets for t in s.texts() if t.name.startswith("heading ")}
    assert {"Force polygon, link 2", "Force polygon, link 3"} <= headings
    for s in sheets:
        for key in ("force: link 2", "force: link 3"):
            if key in s.diagram_scales:
                assert s.diagram_scales[key].unit == "N" and is_125(s.diagram_scales[key].per_mm)
                assert [t.plain for t in s.texts() if t.name == f"scale bar {key} unit"] == ["N"]


def test_scene_units_reach_the_scale_bar_and_the_text():
    """A scene in m/min: the scale bar, the title block's scale and the step values are in m/min."""
    con = free_scale(slider_crank())
    (s,) = compose_sheets(con, info(units=Units(velocity="m/min")), result_rows(2))
    scale = s.diagram_scales["velocity"]
    assert scale.unit == "m/min" and is_125(scale.per_mm)
    assert [t.plain for t in s.texts() if t.name == "scale bar velocity unit"] == ["m/min"]
    assert dict(s.scales)["velocity"] == f"velocity 1 mm = {scale.text}"
    steps = " ".join(t.plain for t in s.texts() if t.name.startswith("step "))
    assert f"1 mm = {scale.text}" in steps and "m/min" in steps
    assert "mm, m/min, rad/s" in {t.plain for t in s.texts() if t.region == "title_block"}


def test_a_block_that_cannot_fit_an_empty_page_is_a_layout_error():
    c = slider_crank()
    steps = [dataclasses.replace(s, entities=tuple(dataclasses.replace(e, units_per_mm=0.0005)
                                                   if isinstance(e, ScaleBar) else e for e in s.entities))
             for s in c.steps]
    with pytest.raises(LayoutError, match="velocity polygon.*empty A4"):
        compose_sheets(Construction(c.title, tuple(steps)), info(), result_rows(2))


def test_long_text_spills_onto_a_text_sheet():
    sheets = compose_sheets(slider_crank(extra_steps=30), info(), result_rows(20))
    assert len(sheets) >= 2
    last = sheets[-1]
    assert not any(k.startswith("viewport:") for k in last.regions)
    assert any(t.name.startswith("results") for s in sheets for t in s.texts())
    assert all(s.text_size >= MIN_TEXT for s in sheets)


class _Block:
    """A panel stand-in: legible from rung ``first`` on, ``mm`` tall at every rung; counts the rungs asked."""

    kind, priority, blank, index = "space", 0, False, 0

    def __init__(self, key: str, mm: float, first: int = 0) -> None:
        self.key, self.title, self.mm, self.first, self.asked = key, f"Block {key}", mm, first, []

    def rungs(self) -> int:
        return 6

    def min_rung(self) -> int:
        return self.first

    def min_width(self) -> float:
        return 50.0

    def need(self, rung: int, width: float):
        self.asked.append(rung)
        return (50.0, self.mm + rung) if width >= 50.0 else None


def test_a_block_too_tall_for_an_empty_page_is_named_and_its_scales_are_not_climbed():
    """The check that every block fits an empty page reads the smallest legible rung only."""
    from drafting.layout.pages import _check_blocks
    from drafting.render.paper import paper
    pp = paper("A4", "landscape")
    fits, tall = _Block("fits", 60.0, first=2), _Block("tall", 500.0, first=1)
    with pytest.raises(LayoutError, match="block tall does not fit an empty A4 landscape sheet.*use A3"):
        _check_blocks(pp, [fits, tall], [], lambda w, panels: 20.0, {})
    assert set(fits.asked) == {2} and set(tall.asked) == {1}
    _check_blocks(pp, [fits], [], lambda w, panels: 20.0, {})           # fits: no error


def test_the_pruned_pick_of_a_one_page_plan_is_the_exhaustive_one(monkeypatch):
    """Flowing only the plans of the best drawings when one keeps comfortable lettering chooses the plan
    (and lettering) flowing every plan chooses, on every gallery scene that is not a lab sheet."""
    from pathlib import Path

    from drafting.layout import pages
    from drafting.scene.reader import load_scene
    from drafting.study.study import Study
    from drafting.study.worked import sheets_for
    pick = pages._pick
    seen = {"pruned": 0, "all": 0}

    def both(plans, document, **kw):
        flowed: list = []

        def counting(plan):
            flowed.append(plan)
            return document(plan)
        got = pick(plans, counting)
        want = pick(plans, document, prune=False)
        assert (got is None) == (want is None)
        if got is not None:
            assert got.pages == want.pages and got.size == want.size and got.text == want.text
        seen["pruned" if len({id(p) for p in flowed}) < len(plans) else "all"] += 1
        return got
    monkeypatch.setattr(pages, "_pick", both)
    gallery = Path(__file__).resolve().parent.parent / "gallery"
    for path in sorted(gallery.glob("*.toml")):
        if path.name.startswith("lab-"):
            continue
        sheets_for(Study(load_scene(path)).run())
    assert seen["pruned"] >= 2 and seen["all"] >= 1, seen          # (the default sheet is pruned)


def test_a_drawing_covers_its_model_points_so_the_packer_may_skip_a_scale_undrawn(monkeypatch):
    """The packer rejects a scale whose model points alone are too wide without drawing it
    (``Figure.least_width``); that changes no decision as long as every drawing is at least that wide:
    held for every drawing of every gallery scene."""
    from pathlib import Path

    from drafting.layout import panel as viewport
    from drafting.scene.reader import load_scene
    from drafting.study.study import Study
    from drafting.study.worked import sheets_for
    seen: list = []
    bbox = viewport.Figure.bbox

    def checked(self, k):
        got = bbox(self, k)
        seen.append(k)
        assert viewport.fit_drawing(got)[0] >= self.least_width(k) + 1e-3 - 1e-9
        return got
    monkeypatch.setattr(viewport.Figure, "bbox", checked)
    gallery = Path(__file__).resolve().parent.parent / "gallery"
    for path in sorted(gallery.glob("*.toml")):
        sheets_for(Study(load_scene(path)).run())
    assert len(seen) > 500


def test_the_pruned_several_page_search_is_the_exhaustive_one(monkeypatch):
    """Flowing a several-page document only when its bound (pages, drawings, lettering) could beat the
    best so far chooses the document flowing every one chooses -- pages, text and lettering -- on every
    gallery scene that is not a lab sheet, and the lab sheets of the lab scene; and it flows fewer."""
    from pathlib import Path

    from drafting.layout import pages
    from drafting.layout import sheet
    from drafting.app.lab import lab_for
    from drafting.scene.reader import load_scene
    from drafting.study.study import Study
    from drafting.study.worked import sheets_for
    plan, document = pages.plan_document, pages._document
    flowed = {"pruned": 0, "all": 0}
    counting = {"on": "pruned"}

    def count(*a, **kw):
        flowed[counting["on"]] += 1
        return document(*a, **kw)

    def both(*a, **kw):
        counting["on"] = "pruned"
        got = plan(*a, **kw)
        counting["on"] = "all"
        want = plan(*a, **{**kw, "cache": {}}, prune=False)
        assert got.pages == want.pages and got.size == want.size and got.text == want.text
        return got
    monkeypatch.setattr(pages, "_document", count)
    monkeypatch.setattr(sheet, "plan_document", both)
    gallery = Path(__file__).resolve().parent.parent / "gallery"
    for path in sorted(gallery.glob("*.toml")):
        study = Study(load_scene(path)).run()
        if path.name.startswith("lab-"):
            lab_for(study)
        else:
            sheets_for(study)
    assert 0 < flowed["pruned"] < flowed["all"] / 2, flowed


def test_a_page_of_diagrams_only_stacks_what_a_text_page_sets_side_by_side():
    """Of arrangements that draw the diagrams alike, a page with text keeps the one that leaves the most
    height (the text goes under it); a page of diagrams only shares what is left among its rows, so it
    takes the one that uses the height: two charts one over the other, not side by side stretched tall."""
    from drafting.layout.page_plans import _best_fill
    from drafting.layout.fills import arrangements
    a, b = _Block("a", 60.0), _Block("b", 60.0)
    for blk in (a, b):
        blk.rungs = lambda: 1                                     # one scale each: they draw alike either way
    with_text = _best_fill(arrangements([a, b]), 120.0, 180.0, climb=True)
    alone = _best_fill(arrangements([a, b]), 120.0, 180.0, climb=True, room=False)
    assert [len(r) for r in with_text.rows] == [2] and with_text.used == pytest.approx(60.0)
    assert [len(r) for r in alone.rows] == [1, 1] and alone.used == pytest.approx(120.0)


def test_a_panel_s_need_is_remembered_for_it_alone_not_for_its_copies():
    """The packer asks a panel's need many times and it is measured once per rung and width; a lab sheet's
    copy of a panel held to another scale measures its own (the memo is not shared through copy.copy)."""
    from drafting.layout.panel import PanelCache
    from drafting.layout.panels import SpacePanel, held_to
    from drafting.scene.reader import load_scene
    from drafting.study.study import Study
    from paths import GALLERY
    study = Study(load_scene(GALLERY / "notes-velocity-example-1.toml")).run()
    ents = [e for e in study.construction.entities() if e.diagram.key == "space"]
    p = SpacePanel("space", "Space diagram", ents, study.scene.units, PanelCache())
    calls = []
    measure = p.measure
    p.measure = lambda r, w: calls.append((r, w)) or measure(r, w)
    r = 0                                                      # the same rung and width as the copy's below
    first = p.need(r, 200.0)
    assert p.need(r, 200.0) == first and calls == [(r, 200.0)]
    held = held_to(p, 0.005)                                   # 1:5 (5 mm of the model per paper mm)
    del held.measure                                           # the class's own measure
    assert held.need(0, 200.0) == SpacePanel.measure(held, 0, 200.0) != first
    assert calls == [(r, 200.0)]                               # the copy measured itself, not through p
