"""The construction record: what was drawn, in which order, and why.

A :class:`Construction` is an ordered, immutable tuple of :class:`Step`.  A step carries the words of the
method ("Draw the direction of V_CB through b, perpendicular to CB"), the vector equation it works on with
known/unknown marks for magnitude and direction, and the entities it adds.  Every entity has a
:class:`Role` and lives in one :class:`Diagram`; how a role looks on paper is the drafting layer's
business, never the record's.
"""

from __future__ import annotations

from dataclasses import dataclass
from enum import Enum
from typing import Iterator

from .geometry import Vec


class Role(Enum):
    GIVEN = "given"            # what the problem states: links, pivots, guides
    KNOWN = "known"            # a vector known in magnitude and direction, drawn to scale
    TRIAL = "trial"            # a line of known direction through a known point; length unknown
    RESULT = "result"          # a vector measured off the construction
    IMAGE = "image"            # a velocity/acceleration image of a link
    LABEL = "label"            # a point of the construction named as in the notes (O_v, b, c)
    SCALE_BAR = "scale bar"    # the scale a diagram is drawn at
    PATH = "path"              # a locus used to find a position (circle about a joint, guide line)


class Diagram(Enum):
    SPACE = "space"            # the mechanism at its position
    VELOCITY = "velocity"      # the velocity polygon
    ACCELERATION = "acceleration"
    FORCE = "force"


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
    """The scale of a diagram: ``units_per_mm`` SI units of ``quantity`` per millimetre of paper."""

    quantity: str              # "length", "velocity", "acceleration", "force"
    units_per_mm: float


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
        return f"{self.quantity}_{self.subscript}{sup}"

    @property
    def marks(self) -> str:
        return ("\u2713" if self.magnitude_known else "\u00d7") + ("\u2713" if self.direction_known else "\u00d7")


@dataclass(frozen=True, slots=True)
class VectorEquation:
    """left-hand terms = right-hand terms, e.g. A_C^n + A_C^t = A_B^n + A_B^t + A_CB^n + A_CB^t."""

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
        return f"{side(self.left)} = {side(self.right)}"

    def __str__(self) -> str:
        return self.text()


@dataclass(frozen=True, slots=True)
class Step:
    caption: str
    equation: VectorEquation | None = None
    entities: tuple[Entity, ...] = ()


@dataclass(frozen=True, slots=True)
class Construction:
    """An ordered, immutable list of steps; numbers measured off it live beside it, not in it."""

    title: str
    steps: tuple[Step, ...] = ()

    def then(self, caption: str, *entities: Entity, equation: VectorEquation | None = None) -> "Construction":
        """A new construction with one more step."""
        names = {e.name for e in self.entities()}
        for e in entities:
            if e.name in names:
                raise ValueError(f"entity name {e.name!r} is already used in {self.title!r}")
            names.add(e.name)
        return Construction(self.title, self.steps + (Step(caption, equation, tuple(entities)),))

    def __add__(self, other: "Construction") -> "Construction":
        out = self
        for s in other.steps:
            out = out.then(s.caption, *s.entities, equation=s.equation)
        return out

    def entities(self, diagram: Diagram | None = None, role: Role | None = None) -> Iterator[Entity]:
        for s in self.steps:
            for e in s.entities:
                if (diagram is None or e.diagram is diagram) and (role is None or e.role is role):
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

    def diagrams(self) -> tuple[Diagram, ...]:
        seen: dict[Diagram, None] = {}
        for e in self.entities():
            seen.setdefault(e.diagram, None)
        return tuple(seen)
