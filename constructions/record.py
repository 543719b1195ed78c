"""The construction record: what was drawn, in which order, and why.

A :class:`Construction` is an ordered, immutable tuple of :class:`Step`.  A step carries the words of the
method with placeholders ("Draw V_B ($v_b) from O_v, perpendicular to O1B"), its values apart from the
words (:class:`Value`, SI, so the drafting layer writes them in the scene's units and a lab sheet can hide
them), the vector equation it works on with known/unknown marks for magnitude and direction, and the
entities it adds.  Every entity has a :class:`Role` and lives in one :class:`Diagram`, named by kind and
name (several force diagrams, one per link).  The entity set is open: points, arrows, trial lines,
bars, plates, pivots, guides, blocks, polygons, arcs, circles, curves, segments, dimensions, angle marks,
notes, charts; how each looks on paper is the drafting layer's business, never the record's.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from enum import Enum
from typing import Callable, Iterator, Mapping

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
    (radians), drawn as an arc of ``radius`` (model units) with its ``text``."""

    vertex: Vec
    radius: float
    start_angle: float
    end_angle: float
    text: str = ""


@dataclass(frozen=True, slots=True)
class Note(Entity):
    """Words placed at a point of a diagram."""

    at: Vec
    text: str


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
class Term:
    """One vector of an equation: quantity V, subscript CB, superscript n/t/c, with known marks.

    ``magnitude_known`` and ``direction_known`` are the notes' ticks and crosses over the symbol.
    """

    quantity: str
    subscript: str
    magnitude_known: bool
    direction_known: bool
    superscript: str = ""

    @property
    def symbol(self) -> str:
        sup = f"^{self.superscript}" if self.superscript else ""
        sub = f"_{self.subscript}" if self.subscript else ""
        return f"{self.quantity}{sub}{sup}"

    @property
    def marks(self) -> str:
        return ("\u2713" if self.magnitude_known else "\u00d7") + ("\u2713" if self.direction_known else "\u00d7")


@dataclass(frozen=True, slots=True)
class VectorEquation:
    """left-hand terms = right-hand terms, e.g. A_C^n + A_C^t = A_B^n + A_B^t + A_CB^n + A_CB^t; with no
    right-hand terms the left ones sum to zero (an equilibrium, P + F_32 + F_KL = 0)."""

    left: tuple[Term, ...]
    right: tuple[Term, ...]

    @property
    def terms(self) -> tuple[Term, ...]:
        return self.left + self.right

    @property
    def unknowns(self) -> int:
        """Scalar unknowns; a planar vector equation solves exactly two."""
        return sum((not t.magnitude_known) + (not t.direction_known) for t in self.terms)

    def text(self, marks: bool = True) -> str:
        def side(terms: tuple[Term, ...]) -> str:
            return " + ".join(t.symbol + (f"({t.marks})" if marks else "") for t in terms)
        return f"{side(self.left)} = {side(self.right) if self.right else '0'}"

    def __str__(self) -> str:
        return self.text()


class StepKind(Enum):
    """What a step is on a worked sheet: the data of the problem, a drawing step, or an answer read
    off the figure (a blank lab sheet hides the answers)."""

    GIVEN = "given"
    CONSTRUCTION = "construction"
    ANSWER = "answer"


@dataclass(frozen=True, slots=True)
class Value:
    """A number a step states, kept apart from its words so units can change and a lab sheet can hide
    it.  ``kind`` is the quantity kind of the SI ``value`` ("length", "velocity", "angular velocity",
    "acceleration", "angle", "number", ...).  Two kinds are filled in by the drawing, which chooses
    the scales: "scale" (``value`` None; ``of`` names the quantity, e.g. "velocity") and "paper length"
    (``value`` the SI magnitude drawn; the drawing divides it by the scale of ``of``)."""

    kind: str
    value: float | None
    of: str = ""


ValueFormatter = Callable[[Value], str]


def si_value_text(v: Value) -> str:
    """The default formatting of a step value: SI units, 4 significant digits."""
    units = {"length": "m", "velocity": "m/s", "acceleration": "m/s^2", "angular velocity": "rad/s",
             "angular acceleration": "rad/s^2", "force": "N", "torque": "N m"}
    if v.value is None:
        return f"(the {v.of} scale)"
    if v.kind == "angle":
        return f"{math.degrees(v.value):.4g} deg"
    if v.kind == "paper length":
        return f"{v.value:.4g} {units.get(v.of, '')} long".replace("  ", " ")
    if v.kind in units:
        return f"{v.value:.4g} {units[v.kind]}"
    return f"{v.value:.4g}"


@dataclass(frozen=True, slots=True)
class Step:
    """One step: its ``words`` with ``$name`` placeholders for its ``values`` (see :class:`Value`), the
    vector equation it works on, the entities it adds, and its :class:`StepKind`."""

    words: str
    equation: VectorEquation | None = None
    entities: tuple[Entity, ...] = ()
    values: tuple[tuple[str, Value], ...] = ()
    kind: StepKind = StepKind.CONSTRUCTION

    def __post_init__(self) -> None:
        names = {k for k, _ in self.values}
        for m in _PLACEHOLDER.finditer(self.words):
            key = m["braced"] or m["plain"]
            if key not in names:
                raise ValueError(f"step words name ${key}, which has no value: {self.words!r}")

    def text(self, fmt: ValueFormatter = si_value_text) -> str:
        """The words with every value written by ``fmt``."""
        vals = dict(self.values)
        return _PLACEHOLDER.sub(lambda m: fmt(vals[m["braced"] or m["plain"]]), self.words)

    @property
    def caption(self) -> str:
        """The words with the values in SI (the drafting layer writes them in the scene's units)."""
        return self.text()

    def value(self, name: str) -> Value:
        return dict(self.values)[name]


_PLACEHOLDER = re.compile(r"\$(?:\{(?P<braced>[A-Za-z_][A-Za-z0-9_]*)\}|(?P<plain>[A-Za-z_][A-Za-z0-9_]*))")


@dataclass(frozen=True, slots=True)
class Construction:
    """An ordered, immutable list of steps; numbers measured off it live beside it, not in it."""

    title: str
    steps: tuple[Step, ...] = ()

    def then(self, words: str, *entities: Entity, equation: VectorEquation | None = None,
             values: Mapping[str, Value] | None = None, kind: StepKind = StepKind.CONSTRUCTION) -> "Construction":
        """A new construction with one more step."""
        return self.with_step(Step(words, equation, tuple(entities), tuple((values or {}).items()), kind))

    def with_step(self, step: Step) -> "Construction":
        names = {e.name for e in self.entities()}
        for e in step.entities:
            if e.name in names:
                raise ValueError(f"entity name {e.name!r} is already used in {self.title!r}")
            names.add(e.name)
        return Construction(self.title, self.steps + (step,))

    def __add__(self, other: "Construction") -> "Construction":
        out = self
        for s in other.steps:
            out = out.with_step(s)
        return out

    def entities(self, diagram: Diagram | None = None, role: Role | None = None) -> Iterator[Entity]:
        for s in self.steps:
            for e in s.entities:
                if (diagram is None or e.diagram == diagram) and (role is None or e.role is role):
                    yield e

    def entity(self, name: str) -> Entity:
        for e in self.entities():
            if e.name == name:
                return e
        raise KeyError(name)

    @property
    def equations(self) -> tuple[VectorEquation, ...]:
        """The distinct equations the steps work on, in the order they first appear."""
        return tuple(dict.fromkeys(s.equation for s in self.steps if s.equation is not None))

    def _repr_html_(self) -> str:
        """Jupyter: the numbered steps (values in SI; a sheet writes them in the scene's units)."""
        from html import escape
        items = "".join(f"<li>{escape(st.text())}</li>" for st in self.steps)
        return f"<div><b>{escape(self.title)}</b><ol>{items}</ol></div>"

    def diagrams(self) -> tuple[Diagram, ...]:
        seen: dict[Diagram, None] = {}
        for e in self.entities():
            seen.setdefault(e.diagram, None)
        return tuple(seen)
