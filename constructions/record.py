"""The construction record: what was drawn, in which order, and why.

A :class:`Construction` is an ordered, immutable tuple of :class:`Step`.  A step carries the words of the
method with placeholders ("Draw V_B ($v_b) from O_v, perpendicular to O1B"), its values apart from the
words (:class:`Value`, SI, so the drafting layer writes them in the scene's units and a lab sheet can hide
them), the vector equation it works on with known/unknown marks for magnitude and direction, and the
entities it adds (:mod:`constructions.entities`: each with a role, in one diagram).
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from enum import Enum
from typing import Callable, Iterator, Mapping

from .entities import Diagram, Entity, Role


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
    table: tuple[tuple[str, ...], ...] = ()     # a table the step sets out (its header row first), cells
    # with $name placeholders like the words (the tabular method of a planetary train)

    def __post_init__(self) -> None:
        names = {k for k, _ in self.values}
        for text in (self.words, *(c for row in self.table for c in row)):
            for m in _PLACEHOLDER.finditer(text):
                key = m["braced"] or m["plain"]
                if key not in names:
                    raise ValueError(f"step words name ${key}, which has no value: {text!r}")

    def text(self, fmt: ValueFormatter = si_value_text) -> str:
        """The words with every value written by ``fmt``."""
        return self._filled(self.words, fmt)

    def table_text(self, fmt: ValueFormatter = si_value_text) -> tuple[tuple[str, ...], ...]:
        """The step's table with every value written by ``fmt`` (empty when it sets out none)."""
        return tuple(tuple(self._filled(c, fmt) for c in row) for row in self.table)

    def _filled(self, text: str, fmt: ValueFormatter) -> str:
        vals = dict(self.values)
        return _PLACEHOLDER.sub(lambda m: fmt(vals[m["braced"] or m["plain"]]), text)

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
             values: Mapping[str, Value] | None = None, kind: StepKind = StepKind.CONSTRUCTION,
             table: tuple[tuple[str, ...], ...] = ()) -> "Construction":
        """A new construction with one more step."""
        return self.with_step(Step(words, equation, tuple(entities), tuple((values or {}).items()), kind, table))

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
