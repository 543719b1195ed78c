"""A rigid body held by supports, as a free body is given: its points, loads, couples and supports (each a
force of unknown magnitude along a known line, or a pin's of unknown direction too), whether statics can
hold it (:func:`check_supports`: exactly three unknowns, lines neither concurrent nor all parallel), and
the forces its construction measures (:class:`FreeBodyAnalysis`).  The construction is
:mod:`constructions.forces.free_body`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Mapping

from ..errors import ConstructionError
from ..formatting import Formatter
from ..geometry import Vec
from ..quantities import Measured
from ..record import Construction
from ..tolerance import DECISION, PARALLEL_SINE, scene_size
from .board import Force, meet
from .effects import Couple, Load

MEMBER, PIN, ROLLER, GUIDE = "member", "pin", "roller", "guide"
SUPPORT_KINDS = (MEMBER, PIN, ROLLER, GUIDE)


def si(kind: str, value: float) -> str:
    """An SI value as the free body's messages write it without a scene (angles in degrees)."""
    unit = {"length": "m", "force": "N", "torque": "N m"}.get(kind, "")
    if kind == "angle":
        return f"{math.degrees(value):.4g} deg"
    return f"{value:.4g} {unit}".strip()


AS_DRAWN = "the position given"
"""Where a free body's errors happen (a linkage names its crank angle): the one position it is drawn in."""


class ImproperlyConstrained(ConstructionError):
    """The supports' lines all meet in one point or are all parallel: statics cannot be satisfied for
    a general load (and the forces are indeterminate for the loads it can)."""

    def __init__(self, reason: str, *, position: str | None = AS_DRAWN) -> None:
        super().__init__(reason, position=position)


class StaticallyIndeterminate(ConstructionError):
    """The supports bring more (or fewer) than the three unknowns statics can find."""

    def __init__(self, reason: str, *, position: str | None = AS_DRAWN) -> None:
        super().__init__(reason, position=position)


@dataclass(frozen=True, slots=True)
class Support:
    """One support of the body, named by its force on the body (``F_12``).

    ``at`` is the body's point it acts at.  A member's far end is the fixed point ``end``; a roller's
    ``direction`` is the normal it pushes the body along, a guide's the normal of its slot; a pin has
    neither.  ``label`` says what it is on the sheet ("member 1", "the cylinder")."""

    name: str
    kind: str
    at: str
    end: str | None = None
    direction: Vec | None = None
    label: str = ""

    def __post_init__(self) -> None:
        if self.kind not in SUPPORT_KINDS:
            raise ValueError(f"{self.name}: {self.kind!r} is not a support ({', '.join(SUPPORT_KINDS)})")
        if self.kind == MEMBER and self.end is None:
            raise ValueError(f"{self.name}: a member needs its far end")
        if self.kind in (ROLLER, GUIDE) and self.direction is None:
            raise ValueError(f"{self.name}: a {self.kind} needs its direction")

    @property
    def unknowns(self) -> int:
        return 2 if self.kind == PIN else 1

    @property
    def what(self) -> str:
        if self.label:
            return self.label
        if self.kind == MEMBER:
            return f"member {self.end}{self.at}"
        return f"the {self.kind} at {self.at}"


@dataclass(frozen=True)
class RigidBody:
    """A rigid body: its named ``points`` (SI), the ``fixed`` points its members hang from, its loads and
    couples (:class:`~constructions.forces.effects.Load` and ``Couple``; their ``body`` is ``number``) and
    its supports.  ``outline`` names the points drawn as its outline, in order (all, by default)."""

    name: str
    points: Mapping[str, Vec]
    supports: tuple[Support, ...]
    loads: tuple[Load, ...] = ()
    couples: tuple[Couple, ...] = ()
    fixed: Mapping[str, Vec] = field(default_factory=dict)
    outline: tuple[str, ...] = ()
    number: int = 0

    def __post_init__(self) -> None:
        if not self.points:
            raise ValueError("a body needs points")
        for s in self.supports:
            if s.at not in self.points:
                raise ValueError(f"{s.name}: {s.at} is not a point of the {self.name}")
            if s.kind == MEMBER and s.end not in self.fixed:
                raise ValueError(f"{s.name}: {s.end} is not a fixed point")
        for ld in self.loads:
            if ld.at not in self.points:
                raise ValueError(f"{ld.name}: {ld.at} is not a point of the {self.name}")

    @property
    def size(self) -> float:
        """L: the largest distance between the body's points and the fixed points (tolerances, arrows)."""
        pts = [p.as_tuple() for p in self.points.values()] + [p.as_tuple() for p in self.fixed.values()]
        return scene_size((), pts)

    @property
    def couple(self) -> float:
        return sum(c.torque for c in self.couples)

    def line(self, s: Support) -> tuple[Vec, Vec]:
        """The line of action of a support of known line: (its point on the body, unit direction); for a
        member, the direction from its far end to its pin (so a positive component pushes: compression)."""
        at = self.points[s.at]
        if s.kind == MEMBER:
            return at, (at - self.fixed[s.end]).unit()
        if s.kind in (ROLLER, GUIDE):
            return at, s.direction.unit()
        raise ValueError(f"{s.name}: a pin has no line of action of its own")

    def known_forces(self) -> list[Force]:
        return [Force(ld.name, self.number, self.points[ld.at], ld.force, "load") for ld in self.loads]


@dataclass(frozen=True)
class FreeBodyAnalysis:
    """The construction and the forces measured off it (SI): ``forces[name]`` is each support's force on
    the body.  ``method`` is "Culmann", "three-force concurrency", "moments" or "no load"; ``points`` the
    construction's points (K and L, or I); ``condition`` the sine of its worst crossing."""

    body: RigidBody
    construction: Construction
    forces: Mapping[str, Vec]
    method: str
    resultant: Vec
    resultant_through: Vec | None
    points: Mapping[str, Vec]
    condition: float
    warnings: tuple[str, ...]

    def measured(self) -> list[Measured]:
        return [Measured(name, "force", f, self.condition) for name, f in self.forces.items()]

    def scales(self) -> dict[str, float]:
        """The reference force: the largest load (or the couple over the body's size)."""
        b = self.body
        big = max([ld.force.norm() for ld in b.loads] + [abs(b.couple) / b.size, self.resultant.norm()],
                  default=0.0)
        return {"force": big} if big > 0 else {}

    def axial(self, name: str) -> float:
        """A member's force along it, positive in compression (pushing the body away from its far end);
        a roller's or guide's component along its normal."""
        s = next(x for x in self.body.supports if x.name == name)
        return self.forces[name].dot(self.body.line(s)[1])

def check_supports(body: RigidBody, fmt: Formatter | None = None) -> float:
    """Raise :class:`StaticallyIndeterminate` unless the supports bring exactly three unknowns, and
    :class:`ImproperlyConstrained` when their lines all meet in one point or are all parallel (a pin
    with a support whose line passes through it).  Returns the condition of the supports: the
    determinant of the equilibrium equations of unit forces along them, moments over the body's size
    (1 for three lines square to each other and far apart, 0 when improper)."""
    fmt = fmt or si
    n = sum(s.unknowns for s in body.supports)
    if n != 3:
        parts = ", ".join(f"{s.name} ({s.unknowns})" for s in body.supports) or "no support"
        if n < 3:
            raise StaticallyIndeterminate(
                f"the {body.name} is not held: its supports bring {n} unknown force component"
                f"{'s' if n != 1 else ''} ({parts}) and a rigid body in the plane needs 3, so it can move")
        raise StaticallyIndeterminate(
            f"the {body.name} is statically indeterminate: its supports bring {n} unknown force components "
            f"({parts}) and statics gives only 3 equations")
    L = body.size
    c = centre(body)
    cols = []
    for s in body.supports:
        p = body.points[s.at]
        if s.kind == PIN:
            cols += [(1.0, 0.0, (p - c).cross(Vec(1.0, 0.0)) / L), (0.0, 1.0, (p - c).cross(Vec(0.0, 1.0)) / L)]
        else:
            _, u = body.line(s)
            cols.append((u.x, u.y, (p - c).cross(u) / L))
    (a, b, e), (d, f, g), (h, i, j) = cols
    det = a * (f * j - i * g) - d * (b * j - i * e) + h * (b * g - f * e)
    if abs(det) > DECISION:
        return abs(det)
    names = [s.name for s in body.supports]
    pins = [s for s in body.supports if s.kind == PIN]
    if pins:
        other = next(s for s in body.supports if s.kind != PIN)
        raise ImproperlyConstrained(
            f"the {body.name} is improperly constrained: the line of action of {other.name} passes through "
            f"the pin {pins[0].at}, so nothing balances a moment about {pins[0].at}")
    lines = [body.line(s) for s in body.supports]
    sines = [abs(lines[x][1].cross(lines[y][1])) for x, y in ((0, 1), (0, 2), (1, 2))]
    if max(sines) <= PARALLEL_SINE:
        ang = math.degrees(lines[0][1].angle()) % 180.0
        raise ImproperlyConstrained(
            f"the {body.name} is improperly constrained: the lines of action of {', '.join(names[:-1])} and "
            f"{names[-1]} are parallel (at {ang:.1f} deg), so they cannot balance a force across them")
    x, y = max(((0, 1), (0, 2), (1, 2)), key=lambda t: abs(lines[t[0]][1].cross(lines[t[1]][1])))
    at = meet(lines[x][0], lines[x][1], lines[y][0], lines[y][1])
    raise ImproperlyConstrained(
        f"the {body.name} is improperly constrained: the lines of action of {', '.join(names[:-1])} and "
        f"{names[-1]} all pass through ({fmt('length', at.x)}, {fmt('length', at.y)}), so they cannot "
        f"balance a moment about that point")


def centre(body: RigidBody) -> Vec:
    """The mean of the body's points: the point its couples are drawn about."""
    pts = list(body.points.values())
    return Vec(sum(p.x for p in pts) / len(pts), sum(p.y for p in pts) / len(pts))


def sine(u: Vec, v: Vec) -> float:
    """The sine of the angle between two directions (0 parallel, 1 square)."""
    return abs(u.unit().cross(v.unit()))
