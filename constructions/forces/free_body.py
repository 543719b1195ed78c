"""One rigid body held by supports, solved graphically: Culmann's method, or three-force concurrency.

The body (a boom, a bracket, a lever) carries known loads and couples and is held by supports, each a
force of unknown magnitude along a known line or, for a pin, of unknown direction too:

- a *two-force member* (:data:`MEMBER`) pinned to the body at one point and to a fixed point at the
  other end, with no load between: its force acts along the member (tension or compression);
- a *roller* (:data:`ROLLER`) pushes square to the surface it rolls on, along a given normal (it cannot
  pull: a roller that would have to is reported);
- a *guide* (:data:`GUIDE`), a pin in a fixed slot, pushes square to the slot, either way;
- a *pin* (:data:`PIN`) to the frame: a force of unknown magnitude and direction.

Statics gives three equations, so the supports must bring exactly three unknown scalars, and their lines
must not all meet in one point or all be parallel (then they cannot balance a moment about that point, or
a force across them: *improperly constrained*).  Both are checked first (:func:`check_supports`).

The construction, as a drafter draws it:

1. the resultant R of the known loads, with its line of action (the loads laid off head to tail give
   R; its line lies where R's moment equals the loads' moment, Varignon);
2. three supports of known lines -- *Culmann's method*: R's line meets the line of one support a at K,
   the other two lines meet at L; the body is in equilibrium under R, F_a and the *Culmann force*
   F_b + F_c, which acts through L -- three forces, so they are concurrent and the Culmann force acts
   along KL.  The force triangle R + F_a + F_KL = 0 closes on the directions of a and KL, and F_KL is
   resolved into F_b and F_c along their lines;
3. a pin and one support of known line -- *three-force concurrency*: R's line and the support's line
   meet at I, so the pin force passes through the pin and I; the force triangle closes on those two
   directions.  Where R is (nearly) parallel to the support's line, I runs away: the support's force comes
   from the moments about the pin instead (force x perpendicular distance), as it does when the loads
   reduce to a couple (no line for R);
4. where the loads reduce to a couple, or where no pairing gives Culmann a well-placed K and L (R along one
   support's line with the other two parallel), *Ritter's method*: two supports' lines meet at L, the
   moments about L give the third support's force, and the polygon closes along the other two.

Of the three ways to pair the supports in Culmann's method the best-conditioned is drawn (the sines at K,
at L and of the triangle, and KL not too short), preferring, among those at least half as well
conditioned, the one that keeps K and L nearest the body.  The forces are measured off the polygon (the
:class:`~constructions.quantities.Measured` of each support is its force on the body); the independent
check is :mod:`constructions.forces.free_body_check`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Callable, Mapping

from ..entities import (AngleMark, Arrow, Bar, Block, Circle, Diagram, Guide, Pivot, Plate, Point, Role, ScaleBar,
                        Segment, TrialLine)
from ..errors import ConstructionError
from ..geometry import Vec
from ..polygons.common import WARN_SINE, rounding_estimate
from ..quantities import Measured
from ..record import Construction, StepKind, Term, Value, VectorEquation
from ..tolerance import DECISION, scene_size
from .effects import Couple, Load
# the linkage force polygons' shared pieces: a force on a body, where two lines of action meet, the sum of
# forces with their moment, and the single force equivalent to forces and couples
from .board import PARALLEL_SINE, Force, meet as _cross, resultant, resultant_line as _resultant_line

MEMBER, PIN, ROLLER, GUIDE = "member", "pin", "roller", "guide"
SUPPORT_KINDS = (MEMBER, PIN, ROLLER, GUIDE)
ORIGIN = Vec(0.0, 0.0)
SPACE = Diagram.SPACE
FORCE = Diagram.FORCE
LOAD_ARROW = 0.25
"""A load's arrow on the space diagram, as a fraction of the body's size (not to scale: its magnitude is
written beside it and drawn to scale on the force polygon)."""

ROLLER_RADIUS = 0.04
"""A roller's radius on the space diagram, as a fraction of the body's size."""
COUPLE_RADIUS = 0.15
"""The arc of a couple on the space diagram (about the body's centre), as a fraction of the body's size."""

Formatter = Callable[[str, float], str]


def _si(kind: str, value: float) -> str:
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


# -- is the body held, and held properly? ----------------------------------------------------------------

def check_supports(body: RigidBody, fmt: Formatter | None = None) -> float:
    """Raise :class:`StaticallyIndeterminate` unless the supports bring exactly three unknowns, and
    :class:`ImproperlyConstrained` when their lines all meet in one point or are all parallel (a pin
    with a support whose line passes through it).  Returns the condition of the supports: the
    determinant of the equilibrium equations of unit forces along them, moments over the body's size
    (1 for three lines square to each other and far apart, 0 when improper)."""
    fmt = fmt or _si
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
    c = _centre(body)
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
    meet = _cross(lines[x][0], lines[x][1], lines[y][0], lines[y][1])
    raise ImproperlyConstrained(
        f"the {body.name} is improperly constrained: the lines of action of {', '.join(names[:-1])} and "
        f"{names[-1]} all pass through ({fmt('length', meet.x)}, {fmt('length', meet.y)}), so they cannot "
        f"balance a moment about that point")


def _centre(body: RigidBody) -> Vec:
    pts = list(body.points.values())
    return Vec(sum(p.x for p in pts) / len(pts), sum(p.y for p in pts) / len(pts))


def _sine(u: Vec, v: Vec) -> float:
    return abs(u.unit().cross(v.unit()))


# -- the construction ----------------------------------------------------------------------------------

def _term(name: str, magnitude: bool, direction: bool) -> Term:
    q, _, sub = name.partition("_")
    return Term(q, sub, magnitude, direction)


def _v(value: float) -> Value:
    return Value("force", value)


class _Drawing:
    def __init__(self, body: RigidBody, fmt: Formatter) -> None:
        self.b, self.fmt = body, fmt
        self.size = body.size
        self.rec = Construction(f"Free body: {body.name}")
        self.forces: dict[str, Vec] = {}
        self.points: dict[str, Vec] = {}
        self.conds: list[float] = []
        self.warnings: list[str] = []
        self.knowns = [f for f in body.known_forces() if f.vector.norm() > 0.0]
        self.couple = body.couple
        self.R = sum((f.vector for f in self.knowns), ORIGIN)
        self.tip = self.R                       # the end of the known forces on the polygon
        self.R_line: tuple[Vec, Vec] | None = None
        self.method = ""

    def then(self, words: str, *entities, values=None, kind=StepKind.CONSTRUCTION, equation=None) -> None:
        self.rec = self.rec.then(words, *entities, values=values, kind=kind, equation=equation)

    @staticmethod
    def along(s: Support) -> str:
        """Where a support's line runs, as the polygon labels it: "∥ G1O", "∥ normal at A", "⊥ slot at B"."""
        if s.kind == MEMBER:
            return f"\u2225 {s.end}{s.at}"
        return f"\u2225 normal at {s.at}" if s.kind == ROLLER else f"\u22a5 slot at {s.at}"

    # -- the problem ----------------------------------------------------------------------------------
    def given(self) -> None:
        b = self.b
        pts = b.points
        outline = b.outline or tuple(pts)
        ents: list = []
        if len(outline) >= 3:
            ents.append(Plate(f"body {b.name}", Role.GIVEN, SPACE, tuple(pts[n] for n in outline), b.number))
        elif len(outline) == 2:
            ents.append(Bar(f"body {b.name}", Role.GIVEN, SPACE, pts[outline[0]], pts[outline[1]], b.number))
        for i, s in enumerate(b.supports, 1):
            p = pts[s.at]
            if s.kind == MEMBER:
                ents.append(Bar(f"support {s.name}", Role.GIVEN, SPACE, p, b.fixed[s.end], 100 + i))
            elif s.kind == PIN:
                ents.append(Pivot(f"support {s.name}", Role.GIVEN, SPACE, p, None))
            elif s.kind == ROLLER:            # a roller at the point, on a surface square to its normal
                _, u = b.line(s)
                r = ROLLER_RADIUS * self.size
                foot = p - u * r
                ents.append(Circle(f"support {s.name} roller", Role.GIVEN, SPACE, p, r))
                ents.append(Segment(f"support {s.name} surface", Role.GIVEN, SPACE, foot - u.perp() * (2.5 * r),
                                    foot + u.perp() * (2.5 * r)))
            else:                                  # a pin in a fixed slot: a block between the slot's rails
                _, u = b.line(s)
                ents.append(Guide(f"support {s.name} slot", Role.GIVEN, SPACE, p, u.perp()))
                ents.append(Block(f"support {s.name}", Role.GIVEN, SPACE, p, u.perp(), 100 + i))
        used = {s.end for s in b.supports if s.kind == MEMBER}
        ents += [Pivot(f"fixed {n}", Role.GIVEN, SPACE, q, n) for n, q in b.fixed.items() if n in used]
        ents += [Point(f"point {n}", Role.LABEL, SPACE, q, n) for n, q in pts.items()]
        values: dict[str, Value] = {}
        loads = []
        for i, ld in enumerate(b.loads):
            if ld.force.norm() == 0.0:
                continue
            at = pts[ld.at]
            ents.append(Arrow(f"load {ld.name}", Role.LOAD, SPACE, at - ld.force.unit() * (LOAD_ARROW * self.size),
                              at, ld.name))
            values[f"p{i}"], values[f"a{i}"] = _v(ld.force.norm()), Value("angle", ld.force.angle() % (2 * math.pi))
            loads.append(f"{ld.name} = $p{i} at $a{i} at {ld.at}")
        centre = _centre(b)
        for i, cp in enumerate(b.couples):
            values[f"c{i}"] = Value("torque", abs(cp.torque))
            loads.append(f"the couple {cp.name} = $c{i} {'CCW' if cp.torque > 0 else 'CW'}")
            if cp.torque:                      # an arc about the body's centre, its arrow turning the couple's way
                turn = math.copysign(1.5 * math.pi, cp.torque)
                ents.append(AngleMark(f"couple {cp.name}", Role.LOAD, SPACE, centre, COUPLE_RADIUS * self.size,
                                      math.pi / 4 + i * 0.5, math.pi / 4 + i * 0.5 + turn, cp.name))
        held = _listed([f"{s.what} ({s.name})" for s in b.supports])
        self.then(f"Space diagram: the {b.name} ({', '.join(pts)}) held by {held}; "
                  + (f"{', '.join(loads)}." if loads else "no load."), *ents, values=values, kind=StepKind.GIVEN)

    def free_body(self) -> None:
        """The free-body words and the supports' lines of action."""
        b = self.b
        ents = [TrialLine(f"line {s.name}", Role.TRIAL, SPACE, *b.line(s), s.name)
                for s in b.supports if s.kind != PIN]
        parts = []
        members = [s for s in b.supports if s.kind == MEMBER]
        if members:
            one = len(members) == 1
            parts.append(f"{_listed([s.what for s in members])} {'is a' if one else 'are'} two-force "
                         f"member{'' if one else 's'} (no load between {'its' if one else 'their'} pins): "
                         f"{_listed([s.name for s in members])} act{'s' if one else ''} along "
                         f"{_listed([s.end + s.at for s in members])}")
        for s in b.supports:
            if s.kind == PIN:
                parts.append(f"the pin at {s.at} takes a force {s.name} of unknown direction")
            elif s.kind == ROLLER:
                parts.append(f"the roller at {s.at} pushes along its normal ({s.name})")
            elif s.kind == GUIDE:
                parts.append(f"the slot at {s.at} pushes square to itself ({s.name})")
        self.then(f"Free body of the {b.name}: {'; '.join(parts)}. Three unknowns, three equations.", *ents)

    def resultant(self) -> None:
        """R and its line (from the known forces and the couple): one load is its own resultant."""
        b = self.b
        got = _resultant_line(self.knowns, self.couple, _centre(b))
        if got is None:
            return
        if len(self.knowns) == 1 and self.couple == 0.0:
            k = self.knowns[0]
            self.R_line = (k.at, k.vector.unit())
            at = next(ld.at for ld in b.loads if ld.name == k.label)
            self.then(f"The resultant R of the loads is {k.label}, along its line through {at}.",
                      TrialLine("line R", Role.TRIAL, SPACE, *self.R_line, None))
            return
        self.R_line = (got[0], got[1].unit())
        ref = next(iter(b.points))
        _, mo_ref = resultant(self.knowns, self.couple, b.points[ref])
        cpl = " and couples" if self.couple else ""
        names = " + ".join(f.label for f in self.knowns)
        self.then(f"The resultant of the loads{cpl}: R = {names} = $r at $a; its line lies $h from {ref}, where "
                  f"R \u00d7 h equals the moment of the loads{cpl} about {ref} (Varignon).",
                  TrialLine("line R", Role.TRIAL, SPACE, *self.R_line, "R"),
                  values={"r": _v(self.R.norm()), "a": Value("angle", self.R.angle() % (2 * math.pi)),
                          "h": Value("length", abs(mo_ref) / self.R.norm())})

    # -- the force polygon ------------------------------------------------------------------------------
    def r_term(self) -> tuple[Term, ...]:
        """R in an equation, when the loads have a resultant force (a couple alone has none)."""
        return (_term("R", True, True),) if self.knowns and self.R.norm() > 0 else ()

    def lay_off(self, equation: VectorEquation, then_along: Vec | None = None) -> None:
        """The known forces head to tail from the pole (and R when there are several).  The one least
        parallel to ``then_along`` (the line drawn next through their end) goes last, so that line does not
        run back over a known side."""
        pts = [ORIGIN]
        ents: list = [Point("pole", Role.LABEL, FORCE, ORIGIN, "O_f"),
                      ScaleBar("force scale", Role.SCALE_BAR, FORCE, "force", None)]
        if then_along is not None and len(self.knowns) > 1:
            last = max(range(len(self.knowns)), key=lambda i: (_sine(self.knowns[i].vector, then_along), i))
            self.knowns = self.knowns[:last] + self.knowns[last + 1:] + [self.knowns[last]]
        for i, f in enumerate(self.knowns):
            ents.append(Arrow(f"polygon {f.label} {i}", Role.KNOWN, FORCE, pts[-1], pts[-1] + f.vector, f.label))
            pts.append(pts[-1] + f.vector)
        if len(self.knowns) > 1:
            ents.append(Arrow("polygon R", Role.KNOWN, FORCE, ORIGIN, self.R, "R"))
        self.tip = pts[-1]
        what = f"{self.knowns[0].label} = R" if len(self.knowns) == 1 else \
            f"{' + '.join(f.label for f in self.knowns)} head to tail (R from O_f to the end)"
        self.then(f"From the pole O_f lay off {what} at the force scale 1 mm = $s (R $len).", *ents,
                  values={"s": Value("scale", None, "force"), "len": Value("paper length", self.R.norm(), "force")},
                  equation=equation)

    def close(self, key: str, first: tuple[str, Vec, str], second: tuple[str, Vec, str], start: Vec,
              start_words: str, name: str, intro: str = "", role: Role = Role.TRIAL,
              equation: VectorEquation | None = None) -> Vec:
        """Two lines of action close a triangle: ``first`` (name, direction, where it runs) through
        ``start`` (called ``start_words``), ``second`` through the pole drawn with ``role``; returns where
        they meet (called ``name``)."""
        (n1, u1, l1), (n2, u2, l2) = first, second
        s = _sine(u1, u2)
        if s < PARALLEL_SINE:
            raise ImproperlyConstrained(f"the force polygon of the {self.b.name} cannot close: the lines of "
                                        f"{n1} and {n2} are parallel")
        self.conds.append(s)
        x = _cross(start, u1, ORIGIN, u2)
        self.then(f"{intro}Through {start_words} draw {l1} ({n1}), through O_f {l2} ({n2}); they meet at {name}.",
                  TrialLine(f"polygon line {key} 1", Role.TRIAL, FORCE, start, u1, l1),
                  TrialLine(f"polygon line {key} 2", role, FORCE, ORIGIN, u2, l2),
                  Point(f"polygon {name}", Role.LABEL, FORCE, x, name), equation=equation)
        return x

    def answer(self, sides: list[tuple[str, Vec, Vec]]) -> None:
        """The solved sides of the polygon (name, tail, tip), drawn and measured."""
        arrows, values, parts = [], {}, []
        for i, (name, tail, tip) in enumerate(sides):
            f = tip - tail
            arrows.append(Arrow(f"polygon result {name}", Role.RESULT, FORCE, tail, tip, name))
            self.forces[name] = f
            values[f"f{i}"] = _v(f.norm())
            values[f"d{i}"] = Value("angle", f.angle() % (2 * math.pi) if f.norm() else 0.0)
            parts.append(f"{name} = $f{i} at $d{i}")
        self.then(f"Measure {', '.join(parts)}.", *arrows, values=values, kind=StepKind.ANSWER)

    # -- the methods ------------------------------------------------------------------------------------
    def culmann(self, pairing: tuple) -> None:
        """Culmann's method with ``pairing`` (a, b, c, K, L): R x a = K, b x c = L."""
        b = self.b
        sup = list(b.supports)
        lines = [b.line(s) for s in sup]
        u_r = self.R_line[1]
        ia, ib, ic, K, L = pairing
        a, bb, cc = sup[ia], sup[ib], sup[ic]
        ua, ub, uc = lines[ia][1], lines[ib][1], lines[ic][1]
        self.points.update({"K": K, "L": L})
        self.conds += [_sine(u_r, ua), _sine(ub, uc)]
        self.method = "Culmann"
        self.then(f"Culmann's method: R meets the line of {a.name} at K; the lines of {bb.name} and {cc.name} "
                  f"meet at L. The {b.name} is held by three forces, R, {a.name} and F_KL = {bb.name} + "
                  f"{cc.name} (through L); three forces in equilibrium meet in one point, so F_KL acts along KL, "
                  f"the Culmann line (dashed).",
                  Point("K", Role.LABEL, SPACE, K, "K"), Point("L", Role.LABEL, SPACE, L, "L"),
                  TrialLine("Culmann line", Role.AUXILIARY, SPACE, K, L - K, None))
        self.lay_off(VectorEquation((_term("R", True, True), _term(a.name, False, True),
                                     _term("F_KL", False, True)), ()), ua)
        x = self.close("a", (a.name, ua, self.along(a)), ("F_KL", L - K, "\u2225 KL"), self.tip, "its end", "x",
                       role=Role.AUXILIARY)
        y = self.close("bc", (bb.name, ub, self.along(bb)), (cc.name, uc, self.along(cc)), x, "x", "y",
                       "Resolve F_KL (from x to O_f). ",
                       equation=VectorEquation((_term("F_KL", True, True),),
                                               (_term(bb.name, False, True), _term(cc.name, False, True))))
        self.answer([(a.name, self.tip, x), (bb.name, x, y), (cc.name, y, ORIGIN)])

    def concurrency(self, pin: Support, other: Support) -> None:
        b = self.b
        A = b.points[pin.at]
        pb, ub = b.line(other)
        p_r, u_r = self.R_line
        s = _sine(u_r, ub)
        if s < WARN_SINE:
            self.moments_about_pin(pin, other, f"R is (nearly) parallel to the line of {other.name}, so they "
                                               f"meet too far away to draw. ")
            return
        I = _cross(p_r, u_r, pb, ub)
        self.points["I"] = I
        self.conds.append(s)
        self.method = "three-force concurrency"
        self.then(f"Three forces hold the {b.name}: R, {other.name} and the pin force {pin.name}. R meets the line "
                  f"of {other.name} at I; three forces in equilibrium meet in one point, so {pin.name} acts along "
                  f"{pin.at}I.",
                  Point("I", Role.LABEL, SPACE, I, "I"),
                  TrialLine(f"line {pin.name}", Role.TRIAL, SPACE, A, I - A, pin.name))
        self.lay_off(VectorEquation((_term("R", True, True), _term(other.name, False, True),
                                     _term(pin.name, False, True)), ()), ub)
        x = self.close("pin", (other.name, ub, self.along(other)), (pin.name, I - A, f"\u2225 {pin.at}I"),
                       self.tip, "its end", "x")
        self.answer([(other.name, self.tip, x), (pin.name, x, ORIGIN)])

    def moments_about_pin(self, pin: Support, other: Support, why: str) -> None:
        """The support's force from the moments about the pin (force x perpendicular distance); the pin
        force closes the polygon."""
        b = self.b
        A = b.points[pin.at]
        pb, ub = b.line(other)
        _, mo = resultant(self.knowns, self.couple, A)
        arm = (pb - A).cross(ub)
        f_b = ub * (-mo / arm)
        self.method = "moments"
        self.conds.append(min(1.0, abs(arm) / self.size))
        self.then(f"{why}Moments about the pin {pin.at}: {other.name} \u00d7 its arm $h balances the moment of the "
                  f"loads about {pin.at} ($m), so {other.name} = $f.",
                  values={"h": Value("length", abs(arm)), "m": Value("torque", abs(mo)), "f": _v(f_b.norm())})
        eq = VectorEquation(self.r_term() + (_term(other.name, True, True), _term(pin.name, False, False)), ())
        if self.knowns:
            self.lay_off(eq, ub)
        else:
            self.tip = ORIGIN
            self.then("Pole O_f; force scale 1 mm = $s.", Point("pole", Role.LABEL, FORCE, ORIGIN, "O_f"),
                      ScaleBar("force scale", Role.SCALE_BAR, FORCE, "force", None),
                      values={"s": Value("scale", None, "force")}, equation=eq)
        end = self.tip + f_b
        self.answer([(other.name, self.tip, end), (pin.name, end, ORIGIN)])

    def ritter(self, why: str) -> None:
        """Moments about L (Ritter's method), where the other two supports' lines meet: the third support's
        force times its arm balances the moment of the loads about L; the polygon then closes along the
        other two.  For loads that reduce to a couple, and where Culmann's K or L runs away (R along a
        support's line with the other two parallel)."""
        b = self.b
        sup = list(b.supports)
        lines = [b.line(s) for s in sup]
        _, ia, ib, ic, L, arm = _ritter_pairing(b, lines)
        a, bb, cc = sup[ia], sup[ib], sup[ic]
        _, mo = resultant(self.knowns, self.couple, L)
        f_a = lines[ia][1] * (-mo / arm)
        self.points["L"] = L
        self.conds += [_sine(lines[ib][1], lines[ic][1]), min(1.0, abs(arm) / self.size)]
        self.method = "moments"
        self.then(f"{why}The lines of {bb.name} and {cc.name} meet at L; moments about L: {a.name} \u00d7 its arm $h "
                  f"balances the moment of the loads about L ($m), so {a.name} = $f.",
                  Point("L", Role.LABEL, SPACE, L, "L"),
                  values={"h": Value("length", abs(arm)), "m": Value("torque", abs(mo)), "f": _v(f_a.norm())})
        eq = VectorEquation(self.r_term() + (_term(a.name, True, True), _term(bb.name, False, True),
                                             _term(cc.name, False, True)), ())
        if self.knowns:
            self.lay_off(eq, lines[ib][1])
        else:
            self.tip = ORIGIN
            self.then("Pole O_f; force scale 1 mm = $s.", Point("pole", Role.LABEL, FORCE, ORIGIN, "O_f"),
                      ScaleBar("force scale", Role.SCALE_BAR, FORCE, "force", None),
                      values={"s": Value("scale", None, "force")}, equation=eq)
        start = self.tip
        end = start + f_a
        self.then(f"Lay off {a.name} from {'the end' if self.knowns else 'O_f'}.",
                  Arrow(f"polygon result {a.name}", Role.RESULT, FORCE, start, end, a.name))
        self.tip = end
        y = self.close("bc", (bb.name, lines[ib][1], self.along(bb)), (cc.name, lines[ic][1], self.along(cc)),
                       end, "its end", "y")
        self.forces[a.name] = f_a
        self.answer([(bb.name, end, y), (cc.name, y, ORIGIN)])

    def unloaded(self) -> None:
        self.method = "no load"
        for s in self.b.supports:
            self.forces[s.name] = ORIGIN
        self.then(f"Nothing loads the {self.b.name}: every support force is zero.", kind=StepKind.ANSWER)

    # -- what each support does -------------------------------------------------------------------------
    def senses(self) -> None:
        """Read each member's sense off its arrow: toward its far end it pulls (tension), away it pushes."""
        b = self.b
        pull, push = [], []
        big = max((f.norm() for f in self.forces.values()), default=0.0)
        for s in b.supports:
            f = self.forces[s.name]
            if s.kind == PIN or f.norm() <= 1e-12 * big:
                continue
            t = f.dot(b.line(s)[1])
            if s.kind == ROLLER and t < 0:
                self.warnings.append(f"The roller at {s.at} would have to pull the {b.name} ({s.name} points "
                                     f"against its normal): a roller only pushes, so the {b.name} lifts off it.")
            if s.kind == MEMBER:
                (push if t > 0 else pull).append(s)
        words = []
        if pull:
            words.append(f"{_listed([s.name for s in pull])} point{'s' if len(pull) == 1 else ''} from the pin "
                         f"toward the far end: {_listed([s.what for s in pull])} pull{'s' if len(pull) == 1 else ''} "
                         f"the {b.name} (tension)")
        if push:
            words.append(f"{_listed([s.name for s in push])} point{'s' if len(push) == 1 else ''} away from it: "
                         f"{_listed([s.what for s in push])} push{'es' if len(push) == 1 else ''} (compression)")
        if words:
            self.then("; ".join(words) + ".", kind=StepKind.ANSWER)

    def record(self) -> FreeBodyAnalysis:
        cond = min(self.conds, default=1.0)
        if cond < WARN_SINE:
            self.warnings.append(f"The construction of the {self.b.name} is ill-conditioned: its lines cross at "
                                 f"{math.degrees(math.asin(min(cond, 1.0))):.3g} deg; the forces are sensitive to "
                                 f"the drawing (rounding about {rounding_estimate(cond):.1e} relative).")
        forces = {s.name: self.forces[s.name] for s in self.b.supports}      # in the scene's order
        return FreeBodyAnalysis(self.b, self.rec, forces, self.method, self.R,
                                self.R_line[0] if self.R_line else None, dict(self.points), cond,
                                tuple(self.warnings))


def _listed(items: list[str]) -> str:
    """a; a and b; a, b and c."""
    return items[0] if len(items) == 1 else f"{', '.join(items[:-1])} and {items[-1]}"


def _culmann_pairing(body: RigidBody, lines, p_r: Vec, u_r: Vec):
    """The pairing to draw as (condition, a, b, c, K, L): K = R's line x a, L = b x c; the best conditioned
    (sines at K, at L, of the triangle, |KL| over the body's size), and among those at least half as well
    conditioned the one with K and L nearest the body.  None when no pairing gives both points."""
    size = body.size
    pts = list(body.points.values()) + list(body.fixed.values())
    cands = []
    for ia in range(3):
        ib, ic = [k for k in range(3) if k != ia]
        (pa, ua), (pb, ub), (pc, uc) = lines[ia], lines[ib], lines[ic]
        s_k, s_l = _sine(u_r, ua), _sine(ub, uc)
        if s_k < PARALLEL_SINE or s_l < PARALLEL_SINE:
            continue
        K = _cross(p_r, u_r, pa, ua)
        L = _cross(pb, ub, pc, uc)
        n = (L - K).norm()
        if n <= DECISION * size:
            continue
        cond = min(s_k, s_l, _sine(ua, L - K), n / size)
        every = pts + [K, L]
        extent = math.hypot(max(p.x for p in every) - min(p.x for p in every),
                            max(p.y for p in every) - min(p.y for p in every))
        cands.append((cond, extent, ia, ib, ic, K, L))
    if not cands:
        return None
    best = max(c[0] for c in cands)
    pick = min((c for c in cands if c[0] >= 0.5 * best), key=lambda c: (c[1], c[2]))
    return (pick[0],) + pick[2:]


def _ritter_pairing(body: RigidBody, lines):
    """(condition, a, b, c, L, arm) for moments about L = b x c: the pairing with the best of the sine at L
    and a's arm about L over the body's size (check_supports leaves at least one with both non-zero)."""
    best = None
    for ia in range(3):
        ib, ic = [k for k in range(3) if k != ia]
        s = _sine(lines[ib][1], lines[ic][1])
        if s < PARALLEL_SINE:
            continue
        L = _cross(*lines[ib], *lines[ic])
        arm = (lines[ia][0] - L).cross(lines[ia][1])
        cond = min(s, abs(arm) / body.size)
        if best is None or cond > best[0]:
            best = (cond, ia, ib, ic, L, arm)
    return best


def free_body_analysis(body: RigidBody, fmt: Formatter | None = None) -> FreeBodyAnalysis:
    """Solve ``body`` graphically: the supports are checked (:func:`check_supports`), then Culmann's method
    (three supports of known line), three-force concurrency (a pin and one support of known line), or
    moments (about the pin, or about L by Ritter's method) where the loads reduce to a couple or Culmann's
    points run away; ``fmt(kind, value)`` writes values in error messages."""
    fmt = fmt or _si
    check_supports(body, fmt)
    d = _Drawing(body, fmt)
    d.given()
    d.free_body()
    d.resultant()
    pins = [s for s in body.supports if s.kind == PIN]
    if not d.knowns and d.couple == 0.0:
        d.unloaded()
    elif pins:
        other = next(s for s in body.supports if s.kind != PIN)
        if d.R_line is None:
            d.moments_about_pin(pins[0], other, "The loads reduce to a couple (no resultant force). ")
        else:
            d.concurrency(pins[0], other)
    elif d.R_line is None:
        d.ritter("The loads reduce to a couple (no resultant force). ")
    else:
        lines = [body.line(s) for s in body.supports]
        culmann = _culmann_pairing(body, lines, *d.R_line)
        if culmann is None or culmann[0] < WARN_SINE and _ritter_pairing(body, lines)[0] > culmann[0]:
            d.ritter("R's line meets the supports' lines too far away (or not at all) for Culmann's K and L. ")
        else:
            d.culmann(culmann[1:])
    d.senses()
    return d.record()


__all__ = ["MEMBER", "PIN", "ROLLER", "GUIDE", "SUPPORT_KINDS", "Support", "RigidBody", "FreeBodyAnalysis",
           "ImproperlyConstrained", "StaticallyIndeterminate", "check_supports", "free_body_analysis"]
