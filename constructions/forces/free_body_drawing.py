"""A free body while its construction is drawn: the space diagram (the body, its supports and loads), the
free-body words and the supports' lines, the resultant of the loads with its line (Varignon), the force
polygon's pieces -- the known forces laid off from the pole O_f, a triangle closed on two lines of action
(the sine at which they cross is its condition), the solved sides measured -- the members' senses, and the
record.  The methods that use them (Culmann, concurrency, moments) are :mod:`.free_body`.
"""

from __future__ import annotations

import math

from ..formatting import Formatter
from ..geometry import Vec
from ..polygons.common import rounding_estimate
from ..entities import (AngleMark, Arrow, Bar, Block, Circle, Diagram, Guide, Pivot, Plate, Point, Role, ScaleBar, Segment, TrialLine)
from ..record import Construction, StepKind, Term, Value, VectorEquation
from ..tolerance import NEGLIGIBLE, PARALLEL_SINE, WARN_SINE
from .board import force_value, meet, resultant, resultant_line
from .rigid_body import (GUIDE, MEMBER, PIN, ROLLER, FreeBodyAnalysis, ImproperlyConstrained, RigidBody, Support,
                         centre, sine)

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


def term(name: str, magnitude: bool, direction: bool) -> Term:
    """A force in a vector equation, by its name (F_12, R) and its known/unknown marks."""
    q, _, sub = name.partition("_")
    return Term(q, sub, magnitude, direction)


class BodyDrawing:
    """The free body while its construction is drawn: the record so far, the forces measured, the points
    and conditions of the construction, and the known forces with their resultant R."""

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
            values[f"p{i}"] = force_value(ld.force.norm())
            values[f"a{i}"] = Value("angle", ld.force.angle() % (2 * math.pi))
            loads.append(f"{ld.name} = $p{i} at $a{i} at {ld.at}")
        mid = centre(b)
        for i, cp in enumerate(b.couples):
            values[f"c{i}"] = Value("torque", abs(cp.torque))
            loads.append(f"the couple {cp.name} = $c{i} {'CCW' if cp.torque > 0 else 'CW'}")
            if cp.torque:                      # an arc about the body's centre, its arrow turning the couple's way
                turn = math.copysign(1.5 * math.pi, cp.torque)
                ents.append(AngleMark(f"couple {cp.name}", Role.LOAD, SPACE, mid, COUPLE_RADIUS * self.size,
                                      math.pi / 4 + i * 0.5, math.pi / 4 + i * 0.5 + turn, cp.name))
        held = listed([f"{s.what} ({s.name})" for s in b.supports])
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
            parts.append(f"{listed([s.what for s in members])} {'is a' if one else 'are'} two-force "
                         f"member{'' if one else 's'} (no load between {'its' if one else 'their'} pins): "
                         f"{listed([s.name for s in members])} act{'s' if one else ''} along "
                         f"{listed([s.end + s.at for s in members])}")
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
        got = resultant_line(self.knowns, self.couple, centre(b))
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
                  values={"r": force_value(self.R.norm()), "a": Value("angle", self.R.angle() % (2 * math.pi)),
                          "h": Value("length", abs(mo_ref) / self.R.norm())})

    # -- the force polygon ------------------------------------------------------------------------------
    def rterm(self) -> tuple[Term, ...]:
        """R in an equation, when the loads have a resultant force (a couple alone has none)."""
        return (term("R", True, True),) if self.knowns and self.R.norm() > 0 else ()

    def lay_off(self, equation: VectorEquation, then_along: Vec | None = None) -> None:
        """The known forces head to tail from the pole (and R when there are several).  The one least
        parallel to ``then_along`` (the line drawn next through their end) goes last, so that line does not
        run back over a known side."""
        pts = [ORIGIN]
        ents: list = [Point("pole", Role.LABEL, FORCE, ORIGIN, "O_f"),
                      ScaleBar("force scale", Role.SCALE_BAR, FORCE, "force", None)]
        if then_along is not None and len(self.knowns) > 1:
            last = max(range(len(self.knowns)), key=lambda i: (sine(self.knowns[i].vector, then_along), i))
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
        s = sine(u1, u2)
        if s < PARALLEL_SINE:
            raise ImproperlyConstrained(f"the force polygon of the {self.b.name} cannot close: the lines of "
                                        f"{n1} and {n2} are parallel")
        self.conds.append(s)
        x = meet(start, u1, ORIGIN, u2)
        self.then(f"{intro}Through {start_words} draw {l1} ({n1}), through O_f {l2} ({n2}); they meet at {name}.",
                  TrialLine(f"polygon line {key} 1", Role.TRIAL, FORCE, start, u1, l1),
                  TrialLine(f"polygon line {key} 2", role, FORCE, ORIGIN, u2, l2),
                  Point(f"polygon {name}", Role.LABEL, FORCE, x, name), equation=equation)
        return x

    def start_polygon(self, equation: VectorEquation, then_along: Vec) -> None:
        """The polygon's start: the known forces laid off (:meth:`lay_off`), or with no load the pole alone."""
        if self.knowns:
            self.lay_off(equation, then_along)
        else:
            self.tip = ORIGIN
            self.then("Pole O_f; force scale 1 mm = $s.", Point("pole", Role.LABEL, FORCE, ORIGIN, "O_f"),
                      ScaleBar("force scale", Role.SCALE_BAR, FORCE, "force", None),
                      values={"s": Value("scale", None, "force")}, equation=equation)

    def answer(self, sides: list[tuple[str, Vec, Vec]]) -> None:
        """The solved sides of the polygon (name, tail, tip), drawn and measured."""
        arrows, values, parts = [], {}, []
        for i, (name, tail, tip) in enumerate(sides):
            f = tip - tail
            arrows.append(Arrow(f"polygon result {name}", Role.RESULT, FORCE, tail, tip, name))
            self.forces[name] = f
            values[f"f{i}"] = force_value(f.norm())
            values[f"d{i}"] = Value("angle", f.angle() % (2 * math.pi) if f.norm() else 0.0)
            parts.append(f"{name} = $f{i} at $d{i}")
        self.then(f"Measure {', '.join(parts)}.", *arrows, values=values, kind=StepKind.ANSWER)

    # -- the methods ------------------------------------------------------------------------------------

    # -- what each support does -------------------------------------------------------------------------
    def senses(self) -> None:
        """Read each member's sense off its arrow: toward its far end it pulls (tension), away it pushes."""
        b = self.b
        pull, push = [], []
        big = max((f.norm() for f in self.forces.values()), default=0.0)
        for s in b.supports:
            f = self.forces[s.name]
            if s.kind == PIN or f.norm() <= NEGLIGIBLE * big:
                continue
            t = f.dot(b.line(s)[1])
            if s.kind == ROLLER and t < 0:
                self.warnings.append(f"The roller at {s.at} would have to pull the {b.name} ({s.name} points "
                                     f"against its normal): a roller only pushes, so the {b.name} lifts off it.")
            if s.kind == MEMBER:
                (push if t > 0 else pull).append(s)
        words = []
        if pull:
            words.append(f"{listed([s.name for s in pull])} point{'s' if len(pull) == 1 else ''} from the pin "
                         f"toward the far end: {listed([s.what for s in pull])} pull{'s' if len(pull) == 1 else ''} "
                         f"the {b.name} (tension)")
        if push:
            words.append(f"{listed([s.name for s in push])} point{'s' if len(push) == 1 else ''} away from it: "
                         f"{listed([s.what for s in push])} push{'es' if len(push) == 1 else ''} (compression)")
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


def listed(items: list[str]) -> str:
    """a; a and b; a, b and c."""
    return items[0] if len(items) == 1 else f"{', '.join(items[:-1])} and {items[-1]}"
