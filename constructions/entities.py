"""What a step of a construction adds: the entities, each with a :class:`Role` and a :class:`Diagram`.

Every entity has a role (what it is for: given, known, trial, result, ...) and lives in one diagram, named
by kind and name (several force diagrams, one per link).  The set is open: points, arrows, trial lines,
bars, plates, pivots, guides, blocks, link numbers, polygons, arcs, circles, curves, segments, dimensions, angle marks,
notes, charts; how each looks on paper is the drafting layer's business, never the record's.  The steps
that add them are :mod:`constructions.record`'s.
"""

from __future__ import annotations

from dataclasses import dataclass
from enum import Enum

from .geometry import Vec


class Role(Enum):
    """What an entity is for; the drafting layer maps every role to a line or area style (and fails
    loudly on one it does not know)."""

    GIVEN = "given"            # what the problem states: links, pivots, guides
    KNOWN = "known"            # a vector known in magnitude and direction, drawn to scale
    TRIAL = "trial"            # a line of known direction through a known point; length unknown
    AUXILIARY = "auxiliary"    # an auxiliary line of a method (Culmann's line): thin dashed
    RESULT = "result"          # a vector measured off the construction
    IMAGE = "image"            # a velocity/acceleration image of a link
    LABEL = "label"            # a point of the construction named as in the notes (O_v, b, c)
    SCALE_BAR = "scale bar"    # the scale a diagram is drawn at
    PATH = "path"              # a locus used to find a position (circle about a joint, guide line)
    CENTRE_LINE = "centre line"  # centre lines, pitch and base circles (long-dash-dot)
    DIMENSION = "dimension"    # a dimension or angle mark as a drafter draws it
    NOTE = "note"              # words placed on a diagram
    LOAD = "load"              # an external or inertia force / couple on a free body
    CHART = "chart"            # curves of a chart (s-v-a-j, sweeps)


@dataclass(frozen=True, slots=True)
class Diagram:
    """Which diagram an entity belongs to: a ``kind`` ("space", "velocity", "acceleration", "force",
    "free body", "chart" ...) and a ``name`` telling apart several of one kind ("link 3").

    The common ones are class attributes: ``Diagram.SPACE``, ``Diagram.VELOCITY``,
    ``Diagram.ACCELERATION``, ``Diagram.FORCE``; any other is made with ``Diagram(kind, name)``.
    """

    kind: str
    name: str = ""

    def __post_init__(self) -> None:
        if not self.kind:
            raise ValueError("a diagram needs a kind")

    @property
    def key(self) -> str:
        """A stable identifier: "velocity", or "force: link 3"."""
        return f"{self.kind}: {self.name}" if self.name else self.kind

    def __str__(self) -> str:
        return self.key


Diagram.SPACE = Diagram("space")                      # type: ignore[attr-defined]
Diagram.VELOCITY = Diagram("velocity")                # type: ignore[attr-defined]
Diagram.ACCELERATION = Diagram("acceleration")        # type: ignore[attr-defined]
Diagram.FORCE = Diagram("force")                      # type: ignore[attr-defined]


@dataclass(frozen=True, slots=True)
class Entity:
    """Base of everything a step adds.  ``name`` is unique within a construction."""

    name: str
    role: Role
    diagram: Diagram


@dataclass(frozen=True, slots=True)
class Point(Entity):
    at: Vec
    label: str | None = None


@dataclass(frozen=True, slots=True)
class Arrow(Entity):
    """A vector drawn from ``tail`` to ``tip`` (arrowhead at the tip)."""

    tail: Vec
    tip: Vec
    label: str | None = None


@dataclass(frozen=True, slots=True)
class TrialLine(Entity):
    """A line of known direction through a known point; drawn thin and past the intersection."""

    through: Vec
    direction: Vec
    label: str | None = None


@dataclass(frozen=True, slots=True)
class Bar(Entity):
    """A link of the mechanism between two joints."""

    start: Vec
    end: Vec
    link: int


@dataclass(frozen=True, slots=True)
class Plate(Entity):
    """A link with more than two points (a coupler carrying a point D): a closed outline."""

    vertices: tuple[Vec, ...]
    link: int


@dataclass(frozen=True, slots=True)
class Pivot(Entity):
    """A fixed pivot on the frame (drawn with ground hatching)."""

    at: Vec
    label: str | None = None


@dataclass(frozen=True, slots=True)
class Guide(Entity):
    """A fixed straight guide a slider runs on."""

    through: Vec
    direction: Vec


@dataclass(frozen=True, slots=True)
class Block(Entity):
    """A slider block centred on ``at``, aligned with ``direction``."""

    at: Vec
    direction: Vec
    link: int


@dataclass(frozen=True, slots=True)
class LinkNumber(Entity):
    """A link's number written beside it as the notes do: ``at`` the link's middle (a plate's centre, a
    block's centre; a fixed pivot for the frame)."""

    at: Vec
    number: int


@dataclass(frozen=True, slots=True)
class Polygon(Entity):
    """A closed figure, e.g. the velocity image b-c-d of a link."""

    vertices: tuple[Vec, ...]
    label: str | None = None


@dataclass(frozen=True, slots=True)
class Arc(Entity):
    """A path arc: part of the circle about ``center`` through ``start`` to ``end`` (CCW)."""

    center: Vec
    radius: float
    start_angle: float
    end_angle: float


@dataclass(frozen=True, slots=True)
class ScaleBar(Entity):
    """The scale of a diagram: ``units_per_mm`` SI units of ``quantity`` per millimetre of paper, or
    None when the drawing chooses it from the room it has (vector polygons)."""

    quantity: str              # "length", "velocity", "acceleration", "force"
    units_per_mm: float | None = None


@dataclass(frozen=True, slots=True)
class Circle(Entity):
    """A whole circle: a base, prime or pitch circle, a roller, a locus."""

    center: Vec
    radius: float
    label: str | None = None


@dataclass(frozen=True, slots=True)
class Curve(Entity):
    """A curve given by points in order (an involute, a cam profile, a coupler curve)."""

    points: tuple[Vec, ...]
    closed: bool = False
    label: str | None = None


@dataclass(frozen=True, slots=True)
class Segment(Entity):
    """A plain straight segment (a line of action, a path of contact, a construction chord)."""

    start: Vec
    end: Vec
    label: str | None = None


@dataclass(frozen=True, slots=True)
class Dimension(Entity):
    """A linear dimension between ``start`` and ``end``, its line ``offset`` model units to the left of
    start -> end; ``text`` is the dimension's words ("$l" placeholders filled like step values)."""

    start: Vec
    end: Vec
    offset: float
    text: str


@dataclass(frozen=True, slots=True)
class AngleMark(Entity):
    """An angle at ``vertex`` from direction ``start_angle`` counter-clockwise to ``end_angle``
    (radians), drawn as an arc of ``radius`` (model units) with its ``text`` -- on paper at least
    ``least_radius`` mm out (0: the drawer's own least radius), so marks about one vertex stay apart
    however small the drawing; the text at ``text_at`` of the way along the arc (0.5: its middle)."""

    vertex: Vec
    radius: float
    start_angle: float
    end_angle: float
    text: str = ""
    least_radius: float = 0.0
    text_at: float = 0.5


@dataclass(frozen=True, slots=True)
class Note(Entity):
    """Words placed at a point of a diagram."""

    at: Vec
    text: str


@dataclass(frozen=True, slots=True)
class Detail(Entity):
    """A region of a diagram drawn again enlarged in a panel of its own (ISO 128: "Detail A"): its
    ``centre`` and ``radius`` in model units and its ``letter``; the diagram marks the region with a thin
    circle and the letter, the detail draws the diagram's own entities clipped to it."""

    centre: Vec
    radius: float
    letter: str

    @property
    def title(self) -> str:
        return f"Detail {self.letter}"


@dataclass(frozen=True, slots=True)
class Series:
    """One curve of a chart: y against x, both SI values of the named quantity kinds; NaN marks a gap."""

    label: str
    x: tuple[float, ...]
    y: tuple[float, ...]
    y_kind: str

    def __post_init__(self) -> None:
        if len(self.x) != len(self.y):
            raise ValueError(f"series {self.label!r}: {len(self.x)} x values but {len(self.y)} y values")


@dataclass(frozen=True, slots=True)
class Chart(Entity):
    """A chart: one or more series against a common x quantity (crank angle, cam angle)."""

    x_kind: str
    x_label: str
    series: tuple[Series, ...]
    bands: tuple[tuple[float, float, str], ...] = ()     # (low, high, label) shaded y ranges


@dataclass(frozen=True, slots=True)
class BodyOutline(Entity):
    """A body drawn free of the others, as a free-body diagram draws it: thin against its forces -- a slender
    link around the segment ``outline`` (two points), a shaded plate (three or more), or a block on the
    point ``outline[0]`` along ``direction``; each of ``pins`` (name, point) a small circle, each of
    ``points`` a dot, all lettered; ``caption`` says what the body is ("link 3: two-force member"), written
    under ``caption_at`` (the middle of the bottom of the body with its forces)."""

    outline: tuple[Vec, ...]
    pins: tuple[tuple[str, Vec], ...]
    points: tuple[tuple[str, Vec], ...]
    link: int
    direction: Vec | None = None
    caption: str = ""
    caption_at: Vec | None = None


@dataclass(frozen=True, slots=True)
class MomentArc(Entity):
    """A couple or torque on a body: an arc of ``radius`` about ``centre`` from ``start_angle``, three
    quarters of a turn in the sense of ``moment`` (CCW positive), its arrowhead at the end, and ``label``."""

    centre: Vec
    radius: float
    start_angle: float
    moment: float
    label: str = ""


@dataclass(frozen=True, slots=True)
class RotationArrow(Entity):
    """A body's sense of rotation: an arc of ``radius`` about ``center`` from ``start_angle`` through
    ``sweep`` (radians; positive counter-clockwise, the sense of the rotation), its arrowhead at the end,
    and its ``label`` (omega)."""

    center: Vec
    radius: float
    start_angle: float
    sweep: float
    label: str = "\u03c9"


@dataclass(frozen=True, slots=True)
class FollowerBody(Entity):
    """A translating cam follower as drawn at one station, in true size: its end at ``at`` (a roller's
    centre, a knife's edge, the middle of a flat face) on its axis ``direction`` (from the cam out), of
    ``kind`` "knife", "roller" or "flat" (``radius``: the roller's; ``face``: half the flat face), its stem
    ``width`` wide running ``stem`` from the end, guided over ``guide`` centred ``guide_at`` along the axis
    from the end."""

    at: Vec
    direction: Vec
    kind: str
    stem: float
    width: float
    guide_at: float
    guide: float
    radius: float = 0.0
    face: float = 0.0
