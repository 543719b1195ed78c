"""Viewports: a diagram drawn, centred and labelled in its rectangle of the sheet.

Holds :class:`DiagramSpec`, the choice of the largest ISO 5455 scale at which the space diagram fits,
the spec of a vector polygon at its construction's scale in the sheet's units, and the rendering of
one viewport.
"""

from __future__ import annotations

import functools
import math
import re
from dataclasses import dataclass

from constructions.geometry import Vec
from constructions.record import Diagram, Entity, ScaleBar

from . import layout as L
from .diagram import model_points, draw_entities
from .labels import place_labels
from .layout import LayoutError
from .paper import Command, Rect

VIEW_PAD = 7.0          # room around a drawing for its labels


# ---- units --------------------------------------------------------------------------------------

_VECTOR = {
    Diagram.VELOCITY: ("velocity", "Velocity polygon", "m/s", "mm/s"),
    Diagram.ACCELERATION: ("acceleration", "Acceleration polygon", "m/s^2", "mm/s^2"),
    Diagram.FORCE: ("force", "Force polygon", "N", "N"),
}
_ACCEL = re.compile(r"/\s*s\s*(\^\s*2|\*\*\s*2|2|\u00b2)")


def display_unit(units: str, kind: str) -> str:
    """The unit a vector scale is written in, taken from SheetInfo.units."""
    tokens = [t.strip() for t in re.split(r"[,;]", units) if t.strip()]
    for t in tokens:
        if "rad" in t:
            continue
        if kind == "velocity" and "/s" in t and not _ACCEL.search(t):
            return t
        if kind == "acceleration" and _ACCEL.search(t):
            return t
        if kind == "force" and re.fullmatch(r"[kMm]?N", t):
            return t
    return {"velocity": "mm/s", "acceleration": "mm/s^2", "force": "N"}[kind]


@functools.cache
def _unit_factor(si_unit: str, unit: str) -> float:
    """How many ``unit`` make one ``si_unit``."""
    from .units import registry
    q = registry().Quantity(1.0, si_unit)
    try:
        return float(q.to(unit.replace("\u00b2", "^2")).magnitude)
    except Exception as e:
        raise ValueError(f"the sheet unit {unit!r} cannot express a {si_unit} quantity") from e


# ---- viewports ----------------------------------------------------------------------------------

@dataclass(frozen=True)
class DiagramSpec:
    key: str                        # region key: "space", "velocity" ...
    heading: str
    entities: tuple[Entity, ...]
    scale_text: str                 # for the title block
    unit: str                       # unit of the scale bar
    paper_per_unit: float           # paper mm per unit of the scale bar
    k: float                        # paper mm per model (SI) unit


def fit_space(entities: tuple[Entity, ...], w: float, h: float):
    """The largest ISO 5455 scale at which the space diagram fits a w x h viewport."""
    for ratio in L.ISO_5455:
        k = 1000.0 * L.ratio_factor(ratio)
        dr = draw_entities(entities, k)
        bb = dr.bbox()
        if bb is None:
            continue
        heading = f"Space diagram {L.ratio_text(ratio)}"
        try:
            hh = L.header_height(w, heading, L.ratio_factor(ratio), "mm")
        except LayoutError:
            continue
        need_w = bb.w + 2 * VIEW_PAD + 2
        need_h = bb.h + 2 * VIEW_PAD + 2 + hh
        if need_w <= w and need_h <= h:
            return ratio, need_h
    return None


def vector_spec(diagram: Diagram, entities: tuple[Entity, ...], units: str) -> DiagramSpec:
    kind, heading, si_unit, _ = _VECTOR[diagram]
    scale = next((e for e in entities if isinstance(e, ScaleBar)), None)
    if scale is not None and scale.units_per_mm > 0 and math.isfinite(scale.units_per_mm):
        upm = scale.units_per_mm
    else:
        pts = model_points(entities) or [Vec(0, 0)]
        ext = max(max(p.x for p in pts) - min(p.x for p in pts), max(p.y for p in pts) - min(p.y for p in pts), 1e-300)
        upm = next(v for v in L.nice_values(ext / 110.0, ext / 110.0 * 10.1))
    unit = display_unit(units, kind)
    f = _unit_factor(si_unit, unit)
    per_mm = upm * f
    shown = re.sub(r"\^\s*2|\*\*\s*2", "\u00b2", unit)          # mm/s^2 is printed mm/s²
    return DiagramSpec(diagram.key, heading, entities, f"{kind} 1 mm = {L.number_text(per_mm)} {shown}",
                       shown, 1.0 / per_mm, 1.0 / upm)


def render_viewport(spec: DiagramSpec, rect: Rect, region: str) -> tuple[list[Command], L.Transform]:
    header = L.viewport_header(rect, spec.heading, spec.paper_per_unit, spec.unit, region=region, name=spec.key)
    plot = Rect.from_edges(rect.x + 1.0, rect.y + header.height, rect.right - 1.0, rect.bottom - 1.0)
    dr = draw_entities(spec.entities, spec.k)
    bb = dr.bbox()
    cmds: list[Command] = list(header.commands)
    if bb is None:
        return cmds, L.Transform(spec.k, plot.center[0], plot.center[1])
    if bb.w + 2 * VIEW_PAD > plot.w + 1e-6 or bb.h + 2 * VIEW_PAD > plot.h + 1e-6:
        raise LayoutError(f"the {spec.heading.lower()} needs {bb.w + 2 * VIEW_PAD:.0f} x "
                          f"{bb.h + 2 * VIEW_PAD:.0f} mm and its viewport has {plot.w:.0f} x {plot.h:.0f} mm; "
                          f"use A3")
    dx = plot.center[0] - (bb.x + bb.w / 2)
    dy = plot.center[1] - (bb.y + bb.h / 2)
    moved = dr.moved(dx, dy)
    cmds.extend(moved.commands)
    cmds.extend(place_labels(moved, plot, region))
    return cmds, L.Transform(spec.k, dx, dy)
