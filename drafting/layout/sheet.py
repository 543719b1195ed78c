"""Sheets: a Construction laid out on paper as drawing commands, on one or more pages.

``compose_sheets(construction, info, results)`` is the whole pipeline up to the recording back end: it
makes one panel per diagram of the construction (the space diagram at an ISO 5455 scale, each vector
polygon at the scale its construction fixed or at the largest 1-2-5 scale that fits its panel, charts),
sets the vector equations, the numbered steps (their values written in the scene's units, scales and
paper lengths from the scales the drawing chose), the results table and the notes, packs all of it onto
as few pages as hold it legibly (:mod:`drafting.layout.pages`) and fills in every page's title block (sheet
n/m).  Each page is a :class:`Sheet`: the paper, a tuple of drawing commands in paper mm (y down) and
named regions, so tests can check what is drawn without rendering.  A Sheet is a plain value: it
neither renders nor saves itself -- :mod:`drafting.backends.svg` writes it as SVG, :mod:`drafting.backends.files`
saves it, and :class:`drafting.backends.public_sheet.Sheet` is the one users hold, which does both.

``compose_sheet`` is the one-page form: it returns the single sheet, and raises :class:`LayoutError`
naming the number of sheets when the content needs more than one.

The parts live in their own modules: :mod:`drafting.layout.diagram` and :mod:`drafting.render.drawers` draw a
diagram's entities, :mod:`drafting.layout.labels` places their labels, :mod:`drafting.layout.panels` makes the
panels and their scales, :mod:`drafting.layout.pages` packs them, :mod:`drafting.layout.formats` writes values.
"""

from __future__ import annotations

import datetime as _dt
import os
import warnings
from dataclasses import dataclass, field, fields, replace
from types import MappingProxyType
from typing import Mapping, Sequence

from constructions.entities import Entity
from constructions.record import Construction, Step

from ..render.errors import LayoutError
from ..render.paper import Command, Line, Paper, Rect, Rectangle, Text, paper as make_paper
from ..render.style import LABEL
from ..render.transform import Transform
from ..scene.units import check_unit
from ..scene.unitset import KEYS, Units
from .flow import TEXT_SIZES, flow_shrinking, slot_page, slot_region
from .formats import DiagramScale, SheetFormatter, ValueHook
from .page_plans import PagePlan
from .pages import Document, plan_document, slots_of
from .reading_order import reading_slots
from .panel import Panel, PanelCache
from .panels import VectorPanel, held_to, panels_for
from .parts import entity_kinds
from .sections import step_formatter, text_sections
from .title_block import scale_cell, title_block, title_block_height

__all__ = ["ResultRow", "SheetInfo", "Sheet", "compose_sheets", "compose_sheet", "LayoutError"]


@dataclass(frozen=True)
class ResultRow:
    """One line of the results table: the value read off the construction and the analytic one."""

    quantity: str
    graphical: str
    analytic: str
    difference: str
    note: str = ""


def source_date_epoch() -> int | None:
    """SOURCE_DATE_EPOCH (the reproducible-builds convention) as whole seconds, or None when unset."""
    epoch = os.environ.get("SOURCE_DATE_EPOCH", "").strip()
    return int(epoch) if epoch.isdigit() else None


def sheet_date(epoch: int | None = None) -> str:
    """The title block's date: ``epoch`` (seconds since 1970, UTC), else SOURCE_DATE_EPOCH when set (the
    same scene gives the same sheet whatever the day), else today."""
    epoch = source_date_epoch() if epoch is None else epoch
    if epoch is None:
        return _dt.date.today().isoformat()
    return _dt.datetime.fromtimestamp(int(epoch), _dt.timezone.utc).date().isoformat()


@dataclass(frozen=True)
class SheetInfo:
    """What the title block says, the sheet's paper and the scene's units.

    ``units`` is the scene's :class:`~drafting.scene.unitset.Units`: the title block names them
    (``units.summary()``), scale bars and every value written on the sheet use them.  (A string such
    as "mm, mm/s, rad/s" is still read, with a DeprecationWarning, for callers not yet passing Units.)
    ``sheet`` is the sheet number of a one-page document; :func:`compose_sheets` numbers its pages.
    """

    title: str
    drawing_number: str
    paper: str = "A4"
    orientation: str = "landscape"
    date: str = field(default_factory=sheet_date)
    sheet: tuple[int, int] = (1, 1)
    units: Units = field(default_factory=Units)
    created_by: str = "drafting"
    notes: tuple[str, ...] = ()
    scales: tuple[tuple[str, float], ...] = ()   # the scales the scene states: (diagram, SI units per paper mm)

    def __post_init__(self) -> None:
        n, m = self.sheet
        if not (1 <= n <= m):
            raise ValueError(f"sheet {n} of {m} is not a sheet number")
        if isinstance(self.units, str):
            warnings.warn("SheetInfo.units should be a drafting.scene.unitset.Units, not a string",
                          DeprecationWarning, stacklevel=3)
            object.__setattr__(self, "units", _units_from_text(self.units))


def _units_from_text(text: str) -> Units:
    """Transitional: "m, m/s, rad/s" -> Units (each unit given to the first kind it measures)."""
    got: dict[str, str] = {}
    for token in (t.strip() for t in text.replace(";", ",").split(",")):
        if not token:
            continue
        for key, kind in KEYS.items():
            if key in got:
                continue
            try:
                check_unit(token, kind)
            except Exception:
                continue
            got[key] = token
            break
    names = {f.name for f in fields(Units)}
    return replace(Units(), **{k: v for k, v in got.items() if k in names})


@dataclass(frozen=True)
class Sheet:
    """A composed page: paper, drawing commands (paper mm, y down) and named regions (a plain value)."""

    paper: Paper
    commands: tuple[Command, ...]
    regions: Mapping[str, Rect] = field(default_factory=dict, compare=False)
    scales: tuple[tuple[str, str], ...] = ()
    text_size: float = LABEL
    transforms: Mapping[str, Transform] = field(default_factory=dict, compare=False)
    """Model -> paper transform of each viewport ("space", "velocity" ...)."""
    number: tuple[int, int] = (1, 1)
    """This page's sheet number n of m."""
    diagram_scales: Mapping[str, DiagramScale] = field(default_factory=dict, compare=False)
    """The scale each diagram on this page is drawn at (SI units per mm and as written)."""
    entities: Mapping[str, tuple[str, str]] = field(default_factory=dict, compare=False)  # name -> (kind, title): .parts

    @property
    def width(self) -> float:
        return self.paper.width

    @property
    def height(self) -> float:
        return self.paper.height

    def texts(self) -> tuple[Text, ...]:
        return tuple(c for c in self.commands if isinstance(c, Text))

    def named(self, prefix: str) -> tuple[Command, ...]:
        return tuple(c for c in self.commands if c.name.startswith(prefix))


# ---- text -------------------------------------------------------------------------------------------

def _entity_text(construction: Construction, fmt: SheetFormatter):
    """Words of an entity (dimension, angle mark, note) with the values of the step that adds it."""
    step_of: dict[str, Step] = {}
    for s in construction.steps:
        for e in s.entities:
            step_of[e.name] = s

    def text(entity: Entity, words: str) -> str:
        s = step_of.get(entity.name)
        if "$" not in words or s is None or not s.values:
            return words
        try:
            return Step(words, values=s.values).text(step_formatter(fmt, s))
        except (ValueError, KeyError):
            return words
    return text


_SUMMARY_ORDER = ("length", "velocity", "acceleration", "angular velocity", "angular acceleration", "force",
                  "torque")


def _units_summary(units: Units, construction: Construction, panels: Sequence[Panel],
                   kinds: Sequence[str] = ()) -> str:
    """The units the title block names: length, velocity, angular velocity, and acceleration (with
    angular acceleration) when the sheet has them (or ``kinds`` says it has)."""
    present = {"length", *kinds}
    present |= {p.quantity for p in panels if isinstance(p, VectorPanel)}
    for s in construction.steps:
        for _, v in s.values:
            present.add(v.kind)
    for e in construction.entities():                  # charts: the units of their series
        for series in getattr(e, "series", ()):
            present.add(series.y_kind)
    if "velocity" in present:
        present.add("angular velocity")
    if "acceleration" in present:
        present.add("angular acceleration")
    if "force" in present:
        present.add("torque")
    kinds = []
    for k in _SUMMARY_ORDER:
        if k in present:
            try:
                units.of(k)
            except (KeyError, AttributeError):
                continue
            kinds.append(k)
    try:
        return units.summary(tuple(kinds))
    except Exception:
        return units.summary()


# ---- the document ---------------------------------------------------------------------------------

def compose_sheets(construction: Construction, info: SheetInfo, results: Sequence[ResultRow] = (), *,
                   values: ValueHook | None = None, panel_hook=None, given: Sequence[str] = (),
                   unit_kinds: Sequence[str] = ()) -> tuple[Sheet, ...]:
    """Lay out ``construction`` with its ``results`` on as few sheets as hold it legibly.

    ``values(value, default)`` may rewrite how a step value is written (``default(value)`` is the
    worked-solution text), e.g. a blank for answers on a lab sheet; ``panel_hook(panels)`` may replace the
    diagram panels before they are packed (a problem sheet frames its polygon panels empty); ``given``
    lines are set first under "Given" (a problem sheet's data); ``unit_kinds`` are quantities the title
    block's units name besides those the construction shows (a key's results).  Raises
    :class:`LayoutError` only when one block cannot fit an empty sheet of the paper in ``info``.
    """
    pp = make_paper(info.paper, info.orientation)
    units = info.units
    cache = PanelCache()
    entity_fmt = SheetFormatter(units, {}, values)
    panels = stated(panels_for(construction, units, cache, _entity_text(construction, entity_fmt)), info.scales)
    if panel_hook is not None:
        panels = list(panel_hook(panels))
    probe = SheetFormatter(units, {}, values, probe=True)
    sections = text_sections(construction, results, info.notes, probe, given)
    summary = _units_summary(units, construction, panels, unit_kinds)

    def tb_fields(scale_text: str, n: int = 1, m: int = 1):
        return [[("Scale", scale_text), ("Units", summary)],
                [("Drawing no.", info.drawing_number), ("Created by", info.created_by), ("Date", info.date),
                 ("Sheet", f"{n}/{m}")]]

    tb_memo: dict[tuple, float] = {}

    def tb_height(width: float, on_page: Sequence[Panel]) -> float:
        # the scales are not known before the rungs are; size the title block with long stand-ins
        probe_text = scale_cell([t for t in (_probe_scale(p) for p in on_page) if t] + _details(on_page))
        key = (round(width, 6), probe_text)
        if key not in tb_memo:
            tb_memo[key] = title_block_height(width, info.title, tb_fields(probe_text, 10, 10))
        return tb_memo[key]

    text_cache: dict = {}
    doc = plan_document(pp, panels, sections, tb_height, cache=text_cache)
    scales = {p.key: p.scale(r) for pg in doc.pages for p, r, _ in pg.panels if p.scale(r) is not None}
    fmt = SheetFormatter(units, scales, values)
    real = text_sections(construction, results, info.notes, fmt, given)
    text_cmds, size = _reflow(real, doc, text_cache)
    m = doc.count
    first = info.sheet if m == 1 else None
    kinds = MappingProxyType(entity_kinds(construction))
    return tuple(replace(_render_page(pp, info, pg, i, m, text_cmds, size, tb_fields, first), entities=kinds)
                 for i, pg in enumerate(doc.pages))


def stated(panels: list[Panel], scales) -> list[Panel]:
    """``panels``, each held to the scale the scene states for its diagram ("force" holds every force
    polygon); a :class:`LayoutError` naming ``drawing.scale.<key>`` when the sheet draws no such diagram."""
    out = list(panels)
    for key, upm in scales:
        hit = [i for i, p in enumerate(out) if p.key == key or p.key.startswith(key + ":")]
        if not hit:
            raise LayoutError(f"drawing.scale.{key}: the sheet draws no {key} diagram (it draws "
                              f"{', '.join(p.key for p in panels)})")
        for i in hit:
            out[i] = held_to(out[i], upm)
    return out


def _details(panels) -> list[str]:
    """A scale for each diagram drawn with enlarged details beside it (they carry their own)."""
    return ["details" for p in panels if getattr(p, "beside", None) is not None]


def _probe_scale(p: Panel) -> str:
    if isinstance(p, VectorPanel):
        return p.scale_text(0) if not p.free else f"{p.label} 1 mm = 0.0005 {p.unit}"
    if hasattr(p, "ratios"):
        return "Space 1:10000" if p.key == "space" else f"{getattr(p, 'title', p.key)} 1:10000"
    return ""


def _reflow(sections, doc: Document, cache) -> tuple[list, float]:
    """The text with its real values, set into the document's slots at the planned size (or smaller)."""
    if not sections:
        return [], doc.size
    slots = slots_of(doc.pages)
    ordered = reading_slots(doc.pages, slots, set(doc.text))
    at = {name: i for i, (name, _) in enumerate(ordered)}
    firsts = [at[name] for name in dict.fromkeys(doc.text) if name in at]
    if firsts == sorted(firsts):                 # the plan was flowed in reading order
        slots = ordered
    sizes = [s for s in TEXT_SIZES if s <= doc.size + 1e-9]
    got = flow_shrinking(sections, slots, sizes=sizes, cache=cache, tagged=True)
    if got is None:
        raise LayoutError("the construction's text with its values does not fit the slots planned for it")
    return got


def _render_page(pp: Paper, info: SheetInfo, pg: PagePlan, index: int, m: int, text_cmds, size: float,
                 tb_fields, number: tuple[int, int] | None) -> Sheet:
    frame = pp.frame
    page = str(index)
    mine = []
    used = set()
    for slot, c in text_cmds:
        if slot_page(slot) == page:
            used.add(slot_region(slot))
            mine.append(c)                       # (its region is the slot's, without the page)
    n_of_m = number or (index + 1, m)
    in_order = sorted(pg.panels, key=lambda t: getattr(t[0], "index", 0))
    scale_list = [(p.key, p.scale_text(r)) for p, r, _ in in_order if p.scale_text(r)]
    scale_text = scale_cell([t for _, t in scale_list] + _details(p for p, _, _ in in_order))
    tb = title_block(frame, pg.title_block.w, info.title, tb_fields(scale_text, *n_of_m))
    regions: dict[str, Rect] = {"page": pp.page, "frame": frame, "title_block": tb.rect}
    cmds: list[Command] = [Rectangle(frame.x, frame.y, frame.w, frame.h, "frame", "frame")]
    rects = {p.key: rc for p, _, rc in pg.panels}
    separators = list(pg.separators)
    slots = list(pg.text_slots)
    for slot, wholes, sep in pg.reclaim:
        if slot in used:
            separators.append(sep)
        else:                                    # an empty slot goes back to its viewports
            rects.update(wholes)
            slots = [(n, r) for n, r in slots if n != slot]
    for x1, y1, x2, y2 in separators:
        cmds.append(Line(x1, y1, x2, y2, "separator", "separator"))
    transforms: dict[str, Transform] = {}
    diagram_scales: dict[str, DiagramScale] = {}
    for p, rung, _ in in_order:
        region = f"viewport:{p.key}"
        rect = rects[p.key]
        regions[region] = rect
        vc, t = p.render(rung, rect, region)
        cmds.extend(vc)
        if t is not None:
            transforms[p.key] = t
        s = p.scale(rung)
        if s is not None:
            diagram_scales[p.key] = s
    for name, r in slots:
        regions[name] = r
    cmds.extend(mine)
    cmds.extend(tb.commands)
    return Sheet(pp, tuple(cmds), MappingProxyType(regions), tuple(scale_list), size,
                 MappingProxyType(transforms), n_of_m, MappingProxyType(diagram_scales))


def compose_sheet(construction: Construction, info: SheetInfo, results: Sequence[ResultRow] = (), *,
                  values: ValueHook | None = None) -> Sheet:
    """The one sheet of ``construction``; raises :class:`LayoutError` naming the number of sheets when
    the content needs more than one (use :func:`compose_sheets` for those, or the larger paper)."""
    sheets = compose_sheets(construction, info, results, values=values)
    if len(sheets) > 1:
        bigger = " or use A3" if info.paper.strip().upper() == "A4" else ""
        raise LayoutError(f"The content needs {len(sheets)} sheets of {info.paper} {info.orientation} to stay "
                          f"legible; compose_sheets draws them as sheets 1/{len(sheets)} to "
                          f"{len(sheets)}/{len(sheets)}{bigger}.")
    return sheets[0]

