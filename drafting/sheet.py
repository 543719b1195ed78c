"""A sheet: a Construction laid out on paper as drawing commands.

``compose_sheet(construction, info, results)`` is the whole pipeline up to the recording back end:
it draws every entity of every diagram in its viewport (the space diagram at an ISO 5455 scale chosen
to fit, each vector polygon at the scale its construction chose), places the labels, sets the vector
equations, the numbered steps, the results table and the notes, and fills in the title block.  The
result is a :class:`Sheet`: the paper, a tuple of drawing commands in paper mm (y down) and named
regions, so tests can check what is drawn without rendering.  :mod:`drafting.svg` renders it.

The parts live in their own modules: :mod:`drafting.diagram` draws a diagram's entities,
:mod:`drafting.labels` places their labels and :mod:`drafting.viewport` chooses the scales and renders
each viewport; this module plans the sheet and puts the pieces together.
"""

from __future__ import annotations

import datetime as _dt
import re
from dataclasses import dataclass, field
from types import MappingProxyType
from typing import Mapping, Sequence

from constructions.record import Construction, Diagram, ScaleBar

from . import layout as L
from .diagram import draw_entities
from .layout import LayoutError
from .paper import Command, Line, Paper, Rect, Rectangle, Text, paper as make_paper
from .style import LABEL
from .viewport import VIEW_PAD, DiagramSpec, fit_space, render_viewport, vector_spec

__all__ = ["ResultRow", "SheetInfo", "Sheet", "compose_sheet", "LayoutError"]


@dataclass(frozen=True)
class ResultRow:
    """One line of the results table: the value read off the construction and the analytic one."""

    quantity: str
    graphical: str
    analytic: str
    difference: str
    note: str = ""


def _today() -> str:
    return _dt.date.today().isoformat()


@dataclass(frozen=True)
class SheetInfo:
    """What the title block says, and the sheet's paper."""

    title: str
    drawing_number: str
    paper: str = "A4"
    orientation: str = "landscape"
    date: str = field(default_factory=_today)
    sheet: tuple[int, int] = (1, 1)
    units: str = "mm, mm/s, rad/s"
    created_by: str = "drafting"
    notes: tuple[str, ...] = ()

    def __post_init__(self) -> None:
        n, m = self.sheet
        if not (1 <= n <= m):
            raise ValueError(f"sheet {n} of {m} is not a sheet number")


@dataclass(frozen=True)
class Sheet:
    """A composed sheet: paper, drawing commands (paper mm, y down) and named regions."""

    paper: Paper
    commands: tuple[Command, ...]
    regions: Mapping[str, Rect] = field(default_factory=dict, compare=False)
    scales: tuple[tuple[str, str], ...] = ()
    text_size: float = LABEL
    transforms: Mapping[str, L.Transform] = field(default_factory=dict, compare=False)
    """Model -> paper transform of each viewport ("space", "velocity" ...)."""

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


# ---- the sheet ----------------------------------------------------------------------------------

def _sections(construction: Construction, results: Sequence[ResultRow], notes: Sequence[str]) -> list[L.Section]:
    secs: list[L.Section] = []
    eqs = construction.equations
    if eqs:
        items: list[L.Item] = [L.EquationItem(eq, name=f"equation {i + 1}") for i, eq in enumerate(eqs)]
        items.append(L.Paragraph(f"Marks over each vector: magnitude, then direction; "
                                 f"{L.MARK_YES} known, {L.MARK_NO} unknown.", name="equation legend"))
        secs.append(L.Section("Vector equations", tuple(items)))
    steps = [s for s in construction.steps if s.caption.strip()]
    if steps:
        n = len(steps)
        secs.append(L.Section("Construction", tuple(
            L.Paragraph(s.caption.strip(), label=f"{i + 1}.", label_chars=f"{n}.", name=f"step {i + 1}")
            for i, s in enumerate(steps))))
    if results:
        has_note = any(r.note for r in results)
        header = ("Quantity", "Graphical", "Analytic", "Difference") + (("Note",) if has_note else ())
        rows = tuple((r.quantity, r.graphical, r.analytic, r.difference) + ((r.note,) if has_note else ())
                     for r in results)
        align = ("l", "r", "r", "r") + (("l",) if has_note else ())
        secs.append(L.Section("Results", (L.TableItem(header, rows, align, wrap_last=has_note),)))
    if notes:
        secs.append(L.Section("Notes", tuple(
            L.Paragraph(t, label="\u2013", label_chars="\u2013", name=f"note {i + 1}") for i, t in enumerate(notes))))
    return secs


def compose_sheet(construction: Construction, info: SheetInfo, results: Sequence[ResultRow] = ()) -> Sheet:
    """Lay out ``construction`` with its ``results`` on the sheet described by ``info``.

    Raises :class:`LayoutError` when the content does not fit even with 2.5 mm lettering; on A4 the
    message says to use A3.
    """
    pp = make_paper(info.paper, info.orientation)
    try:
        return _compose(construction, info, results, pp)
    except LayoutError as e:
        msg = str(e)
        if pp.name != "A4":                       # A3 is the largest sheet: advise what is left
            msg = re.sub(r"use A3( or landscape)?$", "it does not fit even on A3; split the content over "
                         "more sheets or draw the polygon at a coarser scale", msg)
        raise LayoutError(msg[:1].upper() + msg[1:] + ("" if msg.endswith(".") else ".")) from None


COMFORTABLE_LETTERING = 3.0
"""Lettering below this is taken only when nothing else fits."""


def _best_plan(pp: Paper, tb_height, space_need, vec_needs, space_entities, sections, construction, results):
    """The layout plan and its space scale and text flow.

    Landscape sheets try the default text column and the narrowest one: a narrower column can let the
    space diagram go up an ISO scale (1:2 -> 1:1 on A4 for the notes' slider-crank), which is worth it
    when the text keeps its lettering size, or -- to bring a reduced space diagram up towards true
    scale -- when it stays at least COMFORTABLE_LETTERING.
    """
    if pp.orientation == "landscape":
        plans = [L.plan_landscape(pp, tb_height, space_need, vec_needs),
                 L.plan_landscape(pp, tb_height, space_need, vec_needs, text_width=L.TEXT_COL_MIN)]
    else:
        plans = [L.plan_portrait(pp, tb_height, space_need, vec_needs)]
    options = []
    space_misfit = None
    for plan in plans:
        ratio = None
        if space_entities:
            r = plan.viewports["space"]  # the scale is the same if the viewport later takes an empty slot
            got = fit_space(space_entities, r.w, r.h)
            if got is None:
                space_misfit = space_misfit or (f"the space diagram does not fit its {r.w:.0f} x {r.h:.0f} mm "
                                                f"viewport on {pp.name} {pp.orientation}; use A3")
                continue
            ratio = got[0]
        # text: equations, steps, results, notes -- shrunk from 3.5 to 2.5 mm until they fit
        slots = [(name, r) for name, r in plan.text_slots if r.w > 20 and r.h > 10]
        flowed = L.flow_shrinking(sections, slots)
        if flowed is None:
            continue
        options.append((plan, ratio, slots, flowed))
    if not options and space_misfit:
        raise LayoutError(space_misfit)
    if not options:
        raise LayoutError(f"the equations, {len(construction.steps)} steps and {len(results)} result rows do "
                          f"not fit on {pp.name} {pp.orientation} even with 2.5 mm lettering; use A3")
    first = options[0]
    first_size = first[3][1]
    reduced = first[1] is not None and L.ratio_factor(first[1]) < 1.0

    def acceptable(o) -> bool:
        size = o[3][1]
        return o is first or size >= first_size - 1e-9 or (reduced and size >= COMFORTABLE_LETTERING - 1e-9)
    readable = [o for o in options if acceptable(o)]
    return max(readable, key=lambda o: (L.ratio_factor(o[1]) if o[1] else 0.0, o[3][1]))


def _compose(construction: Construction, info: SheetInfo, results: Sequence[ResultRow], pp: Paper) -> Sheet:
    frame = pp.frame
    space_entities = tuple(e for e in construction.entities(Diagram.SPACE) if not isinstance(e, ScaleBar))
    vector_specs = [
        vector_spec(dg, tuple(construction.entities(dg)), info.units)
        for dg in (Diagram.VELOCITY, Diagram.ACCELERATION, Diagram.FORCE)
        if any(not isinstance(e, ScaleBar) for e in construction.entities(dg))
    ]
    # what each vector viewport needs at its fixed scale
    vec_needs = []
    for spec in vector_specs:
        bb = draw_entities(spec.entities, spec.k).bbox()
        w = (bb.w if bb else 0.0) + 2 * VIEW_PAD + 2
        h = (bb.h if bb else 0.0) + 2 * VIEW_PAD + 2
        w = max(w, 90.0)
        hh = L.header_height(w, spec.heading, spec.paper_per_unit, spec.unit)
        vec_needs.append(L.ViewportNeed(spec.key, size=(w, h + hh)))
    space_need = None
    if space_entities:
        def size_for_width(w: float, h: float):
            got = fit_space(space_entities, w, h)
            return None if got is None else (w, got[1])
        space_need = L.ViewportNeed("space", size_for_width=size_for_width)

    def tb_fields(scale_text: str):
        return [[("Scale", scale_text), ("Units", info.units)],
                [("Drawing no.", info.drawing_number), ("Created by", info.created_by), ("Date", info.date),
                 ("Sheet", f"{info.sheet[0]}/{info.sheet[1]}")]]

    # the scale text is not known before the space scale is; size the title block with a long stand-in
    probe_scale = "; ".join(["Space 1:10000"] + [s.scale_text for s in vector_specs])

    def tb_height(width: float) -> float:
        return L.title_block(frame, width, info.title, tb_fields(probe_scale)).rect.h

    sections = _sections(construction, results, info.notes)
    plan, ratio, slots, (text_cmds, size) = _best_plan(pp, tb_height, space_need, vec_needs, space_entities,
                                                       sections, construction, results)

    specs: dict[str, DiagramSpec] = {s.key: s for s in vector_specs}
    scales: list[tuple[str, str]] = []
    if space_entities:
        specs["space"] = DiagramSpec("space", f"Space diagram {L.ratio_text(ratio)}", space_entities,
                                     f"Space {L.ratio_text(ratio)}", "mm", L.ratio_factor(ratio),
                                     1000.0 * L.ratio_factor(ratio))
        scales.append(("space", f"Space {L.ratio_text(ratio)}"))
    scales += [(s.key, s.scale_text) for s in vector_specs]
    scale_text = "; ".join(t for _, t in scales) or "none"

    tb = L.title_block(frame, plan.title_block.w, info.title, tb_fields(scale_text))
    regions: dict[str, Rect] = {"page": pp.page, "frame": frame, "title_block": tb.rect}
    cmds: list[Command] = [Rectangle(frame.x, frame.y, frame.w, frame.h, "frame", "frame")]
    used = {c.region for c in text_cmds if isinstance(c, Text)}
    viewports = dict(plan.viewports)
    separators = list(plan.separators)
    for slot, key, whole, sep in plan.reclaim:
        if slot in used:
            separators.append(sep)
        else:                                    # an empty slot goes back to its viewport
            viewports[key] = whole
            slots = [(n, r) for n, r in slots if n != slot]
    for x1, y1, x2, y2 in separators:
        cmds.append(Line(x1, y1, x2, y2, "separator", "separator"))
    transforms: dict[str, L.Transform] = {}
    for key, rect in viewports.items():
        region = f"viewport:{key}"
        regions[region] = rect
        vc, transforms[key] = render_viewport(specs[key], rect, region)
        cmds.extend(vc)
    for name, r in slots:
        regions[name] = r
    cmds.extend(text_cmds)
    cmds.extend(tb.commands)
    return Sheet(pp, tuple(cmds), MappingProxyType(regions), tuple(scales), size, MappingProxyType(transforms))
