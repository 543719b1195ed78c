"""The pieces every drawer works with: the registry of drawers, the layered Drawing and its context.

Every entity type of the record has exactly one drawer, registered with the :func:`drawer` decorator
(``@drawer(Arrow)``) and found by the entity's type (its MRO, so a subclass of a drawable type is
drawable).  An entity whose type has no drawer raises :class:`~drafting.render.errors.DrawingError` naming the
type and the diagram: nothing is ever silently left out of a sheet.  A new entity type plugs in by
registering a drawer in its own module; nothing here changes.

A drawer is called as ``fn(entity, ctx)`` with a :class:`DrawContext`: the model -> paper transform, the
:class:`Drawing` being filled (layered commands, label requests, symbols labels must not cover, line
segments they should avoid) and what the diagram as a whole knows (its points on paper, pivots, bars,
blocks, pins; the text of the entity with its step's values written in).  Drawers run in phases:
phase 0 draws links and blocks (which decide where pins go), phase 1 everything else, phase 2 the
points and labels that sit on pins.  Each registration may also give ``points(entity)``, the model
points the entity covers, used to size and centre the diagram.

Panel entities (a :class:`~constructions.record.Chart`) are not drawn to a model scale; they are drawn
into a chart panel of their own (:mod:`drafting.layout.chart`), and ``draw_entities`` refuses them.

The drawers themselves live in :mod:`drafting.render.drawers` (mechanism and vector entities, circles, curves,
segments, dimensions, angle marks, notes) and :mod:`drafting.layout.chart`; :mod:`drafting.layout.diagram` runs them
over a diagram.  This module imports neither, so they can import it.
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass, field
from typing import Callable, Iterable, Sequence

from constructions.entities import Entity
from constructions.geometry import Vec

from .errors import DrawingError
from .paper import Command, Line, Polygon, Polyline, Rect, Strokes, command_points, translated
from .transform import Transform

__all__ = ["LabelReq", "Drawing", "DrawContext", "drawer", "panel_drawer", "drawer_for", "drawable",
           "arrowhead", "Pt"]

ARROW_LEN = 3.5
ARROW_HALF = 0.9
PIN_R = 1.2
DOT_R = 0.55

Pt = tuple[float, float]


@dataclass
class LabelReq:
    kind: str                       # point, arrow, trial, polygon, note (layout.labels.LABEL_KINDS)
    markup: str
    anchor: Pt
    mandatory: bool
    name: str
    r0: float = 0.0                 # radius of the symbol drawn at the anchor
    other: Pt | None = None         # arrow tail / trial far end
    pivot_digits: bool = False
    ground: Rect | None = None      # a note's ground at its anchor: the drawing's extent counts it
    alternates: tuple[Pt, ...] = () # other points of the same entity (a circle's, a curve's) where its name
    # may go when it cannot be set clear and unambiguous by its anchor, tried in order


THICK_STYLES = frozenset({"vector", "link", "guide", "load", "block"})
NO_SEGMENT_STYLES = frozenset({"arrowhead", "dot", "note_bg", "label_bg", "band"})


@dataclass
class Drawing:
    layers: dict[int, list[Command]] = field(default_factory=dict)
    labels: list[LabelReq] = field(default_factory=list)
    hard: list[Rect] = field(default_factory=list)
    segments: list[tuple[Pt, Pt, bool]] = field(default_factory=list)     # (a, b, thick)
    extent_only: bool = False
    """Made only for its extent (:meth:`bbox`), at a scale a page planner tries: no segments for the label
    placer, and a drawer may put down only the points that bound what it draws (a curve its extreme points)."""

    def add(self, layer: int, cmd: Command) -> None:
        got = self.layers.get(layer)
        if got is None:
            got = self.layers[layer] = []
        got.append(cmd)
        if self.extent_only:
            return
        thick = cmd.style in THICK_STYLES
        if type(cmd) is Line:
            self.segments.append(((cmd.x1, cmd.y1), (cmd.x2, cmd.y2), thick))
        elif type(cmd) is Strokes:
            self.segments.extend((a, b, thick) for a, b in cmd.segments)
        elif isinstance(cmd, (Polyline, Polygon)) and cmd.style not in NO_SEGMENT_STYLES:
            pts = list(cmd.points) + ([cmd.points[0]] if isinstance(cmd, Polygon) else [])
            self.segments.extend(zip(pts[:-1], pts[1:], itertools.repeat(thick)))

    def add_segments(self, points: Sequence[Pt], thick: bool, closed: bool = False) -> None:
        """Line segments labels should avoid, for a command that is not made of segments (a circle)."""
        if self.extent_only:
            return
        pts = list(points) + ([points[0]] if closed and points else [])
        self.segments.extend(zip(pts[:-1], pts[1:], itertools.repeat(thick)))

    @property
    def commands(self) -> list[Command]:
        return [c for k in sorted(self.layers) for c in self.layers[k]]

    def bbox(self) -> Rect | None:
        """The extent of the commands and of the notes' grounds at their anchors (a note is set by the
        label placer, at its anchor where that is clear: the drawing reserves its room there)."""
        pts = [p for c in self.commands for p in command_points(c)]
        pts += [q for r in self.labels if r.ground is not None for q in ((r.ground.left, r.ground.top),
                                                                         (r.ground.right, r.ground.bottom))]
        return Rect.bounding(pts) if pts else None

    def moved(self, dx: float, dy: float, region: str | None = None) -> "Drawing":
        """The drawing moved by ``(dx, dy)`` mm, its texts put in ``region`` when given."""
        d = Drawing({k: [translated(c, dx, dy, region) for c in v] for k, v in self.layers.items()})
        d.labels = [LabelReq(r.kind, r.markup, (r.anchor[0] + dx, r.anchor[1] + dy), r.mandatory, r.name, r.r0,
                             None if r.other is None else (r.other[0] + dx, r.other[1] + dy), r.pivot_digits,
                             None if r.ground is None else r.ground.translated(dx, dy),
                             tuple((x + dx, y + dy) for x, y in r.alternates))
                    for r in self.labels]
        d.hard = [h.translated(dx, dy) for h in self.hard]
        d.segments = [((a[0] + dx, a[1] + dy), (b[0] + dx, b[1] + dy), t) for a, b, t in self.segments]
        return d


# layers, bottom to top
IMAGES, PATHS, TRIALS, LINKS, BLOCKS, SHAFTS, HEADS, PINS, DOTS, NOTES = range(10)


def unit_vector(v: Pt) -> Pt:
    n = math.hypot(*v)
    return (v[0] / n, v[1] / n)


def shifted(p: Pt, v: Pt, k: float = 1.0) -> Pt:
    return (p[0] + v[0] * k, p[1] + v[1] * k)


def _dist(a: Pt, b: Pt) -> float:
    return math.hypot(a[0] - b[0], a[1] - b[1])


def angle_gap(a: float, b: float) -> float:
    d = abs(a - b) % (2 * math.pi)
    return min(d, 2 * math.pi - d)


def incident_directions(p: Pt, segments: Sequence[tuple], tol: float = 0.05) -> list[float]:
    """Paper angles (atan2 of y-down vectors) of the lines that leave ``p``."""
    out = []
    for a, b, *_ in segments:
        ab = (b[0] - a[0], b[1] - a[1])
        n = math.hypot(*ab)
        if n < 1e-9:
            continue
        t = ((p[0] - a[0]) * ab[0] + (p[1] - a[1]) * ab[1]) / (n * n)
        if t < -tol / n or t > 1 + tol / n:
            continue
        foot = (a[0] + ab[0] * t, a[1] + ab[1] * t)
        if _dist(foot, p) > tol:
            continue
        if t * n > tol:
            out.append(math.atan2(a[1] - p[1], a[0] - p[0]))
        if (1 - t) * n > tol:
            out.append(math.atan2(b[1] - p[1], b[0] - p[0]))
    return out


def arrowhead(tail: Pt, tip: Pt, name: str, style: str = "arrowhead") -> tuple[Polygon, Pt]:
    """A filled arrowhead with its apex exactly at ``tip``; returns it and where the shaft stops."""
    length = _dist(tail, tip)
    hl = min(ARROW_LEN, 0.5 * length)
    hw = ARROW_HALF * hl / ARROW_LEN
    u = unit_vector((tip[0] - tail[0], tip[1] - tail[1]))
    n = (-u[1], u[0])
    base = shifted(tip, u, -hl)
    poly = Polygon((tip, shifted(base, n, hw), shifted(base, n, -hw)), style, f"{name}:head")
    return poly, shifted(tip, u, -0.8 * hl)


def nonzero(v: Vec) -> bool:
    return math.isfinite(v.x) and math.isfinite(v.y) and math.hypot(v.x, v.y) > 0


# ---- the registry -------------------------------------------------------------------------------------

DrawFn = Callable[[Entity, "DrawContext"], None]
PointsFn = Callable[[Entity], Iterable[Vec]]
PanelFn = Callable[..., list]


@dataclass
class _Entry:
    type: type
    phases: dict[int, DrawFn] = field(default_factory=dict)
    points: PointsFn | None = None
    panel: PanelFn | None = None


_REGISTRY: dict[type, _Entry] = {}


def drawer(entity_type: type, *, phase: int = 1, points: PointsFn | None = None):
    """Register the decorated ``fn(entity, ctx)`` as the drawer of ``entity_type`` in ``phase``
    (0 links and blocks, 1 everything else, 2 points and labels on pins).  ``points(entity)`` gives the
    model points the entity covers (for sizing the diagram).  A type may register one function per
    phase; registering a phase twice is an error."""
    def register(fn: DrawFn) -> DrawFn:
        entry = _REGISTRY.setdefault(entity_type, _Entry(entity_type))
        if phase in entry.phases:
            raise ValueError(f"{entity_type.__name__} already has a phase {phase} drawer")
        entry.phases[phase] = fn
        if points is not None:
            entry.points = points
        return fn
    return register


def panel_drawer(entity_type: type):
    """Register ``fn(entity, rect, ctx)`` drawing ``entity_type`` into a panel of its own (a chart)."""
    def register(fn: PanelFn) -> PanelFn:
        entry = _REGISTRY.setdefault(entity_type, _Entry(entity_type))
        entry.panel = fn
        return fn
    return register


def _lookup(entity_type: type) -> _Entry | None:
    for t in entity_type.__mro__:
        e = _REGISTRY.get(t)
        if e is not None and (e.phases or e.panel):
            return e
    return None


def drawer_for(entity: Entity | type) -> _Entry:
    """The registry entry of an entity (or entity type); raises :class:`DrawingError` naming the type
    and the entity's diagram when there is none."""
    t = entity if isinstance(entity, type) else type(entity)
    e = _lookup(t)
    if e is None:
        where = ""
        if not isinstance(entity, type):
            name = getattr(entity, "name", "")
            diagram = getattr(entity, "diagram", None)
            where = f" ({name!r} in the {diagram} diagram)" if diagram is not None else f" ({name!r})"
        raise DrawingError(f"no drawer for the entity type {t.__name__}{where}; register one with "
                           f"@drawer({t.__name__}) in drafting.render.drawers")
    return e


def drawable(entity_type: type) -> bool:
    return _lookup(entity_type) is not None


def is_panel_entity(entity: Entity) -> bool:
    """True for entities drawn in a panel of their own (charts), not to a model scale."""
    e = drawer_for(entity)
    return e.panel is not None and not e.phases




# ---- drawing a diagram ----------------------------------------------------------------------------

TextFn = Callable[[Entity, str], str]


def _plain_text(entity: Entity, words: str) -> str:
    return words


@dataclass
class DrawContext:
    """What a drawer needs: the transform, the drawing it adds to, and the diagram as a whole."""

    T: Transform
    d: Drawing
    entities: Sequence[Entity]
    paper_pts: list[Pt]                   # the diagram's points on paper (and crossings of trial lines)
    centroid: Pt
    pivots: list[Pt]
    bars: list[tuple[Pt, Pt]]
    blocks: list[Pt]
    pins: dict[Pt, str] = field(default_factory=dict)    # each pin and the entity that first met it
    text_fn: TextFn = _plain_text
    notes: list[Rect] = field(default_factory=list)      # the grounds of the notes set so far

    def add_pin(self, p: Pt, owner: str) -> None:
        """A pin at ``p``, the joint of entity ``owner`` (drawn with it: its command is "<owner>:pin");
        one pin where several links meet, and none on a fixed pivot."""
        if all(_dist(p, q) > 0.01 for q in self.marks):
            self.pins[p] = owner

    def text(self, entity: Entity, words: str) -> str:
        """``words`` of ``entity`` with the values of its step written in."""
        return self.text_fn(entity, words)

    @property
    def marks(self) -> list[Pt]:
        return list(self.pins) + self.pivots
