"""The force analysis while it is drawn: each body's known forces, the state of the drawing, and the
pieces every dyad's construction shares -- laying off known forces from the pole O_f and closing a polygon
on two lines of action (the sine at which they cross is its condition), measuring the solved sides, the
tangential part of a pin force by moments, and the bookkeeping that hands each solved force's reaction to
the body at the other side.  The dyads themselves are drawn in :mod:`.dyads`; :mod:`.polygon` runs them
and records the result."""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..entities import Arrow, Diagram, Point, Role, ScaleBar, TrialLine
from ..errors import ConstructionError, IndeterminatePosition
from ..geometry import Vec
from ..mechanisms.model import Mechanism, describe_angle
from ..mechanisms.pose import Pose
from ..mechanisms.topology import Contact, Pin, SlotPin, carriers, connections, frame_number
from ..polygons.common import rounding_estimate
from ..record import StepKind, Value
from ..tolerance import PARALLEL_SINE, WARN_SINE
from .bodies import force_name
from .dalembert import inertia_loads, inertia_name
from .effects import Effects

ORIGIN = Vec(0.0, 0.0)


class ForcesNotDrawn(ConstructionError):
    """The graphical force analysis has no construction for this kind of dyad (yet)."""


@dataclass(frozen=True, slots=True)
class Force:
    """A force on ``body`` acting along a line through ``at``; ``label`` as the sheet writes it."""

    label: str
    body: int
    at: Vec
    vector: Vec
    kind: str                      # "load", "weight", "inertia", "spring", "joint", "guide"




def force_value(value: float) -> Value:
    return Value("force", value)


def body_label(m: Mechanism, body: int) -> str:
    return f"block {body}" if body in m.blocks() else f"link {body}"


def resultant(forces, couples: float, about: Vec) -> tuple[Vec, float]:
    """The sum of ``forces`` and their moment (with ``couples``) about ``about``."""
    r = ORIGIN
    mo = couples
    for x in forces:
        r = r + x.vector
        mo += (x.at - about).cross(x.vector)
    return r, mo


def known_forces(m: Mechanism, pose: Pose, effects: Effects, acceleration=None
                 ) -> tuple[dict[int, list[Force]], dict[int, float]]:
    """Each body's known forces and the sum of its couples, from the scene's effects (and the
    accelerations read off the polygon for D'Alembert's inertia forces)."""
    pos = dict(pose.positions)
    for name, p in effects.fixed.items():
        pos.setdefault(name, p)
    forces: dict[int, list[Force]] = {}
    couples: dict[int, float] = {}
    for ld in effects.loads:
        forces.setdefault(ld.body, []).append(Force(ld.name, ld.body, pos[ld.at], ld.force, "load"))
    for cp in effects.couples:
        couples[cp.body] = couples.get(cp.body, 0.0) + cp.torque
    for s in effects.springs:
        pull = s.pull(pos[s.a.at], pos[s.b.at])
        for end, f in ((s.a, pull), (s.b, -pull)):
            if end.body is not None:
                forces.setdefault(end.body, []).append(Force(s.name, end.body, pos[end.at], f, "spring"))
    for ms in effects.masses:
        g_at = pos[ms.centre]
        if effects.gravity is not None:
            forces.setdefault(ms.body, []).append(Force(f"W_{ms.body}", ms.body, g_at,
                                                        effects.gravity * ms.mass, "weight"))
    if acceleration is not None:
        for il in inertia_loads(effects, acceleration.accelerations, lambda b: acceleration.angular.get(b, 0.0)):
            if il.acting:                                # one force on the offset line: d x F_I = C_I
                forces.setdefault(il.body, []).append(Force(inertia_name(il.body), il.body,
                                                            pos[il.centre] + il.shift(), il.force, "inertia"))
            elif il.couple != 0.0:
                couples[il.body] = couples.get(il.body, 0.0) + il.couple
    return forces, couples


class Drawing:
    """The force analysis while it is drawn."""

    def __init__(self, m: Mechanism, pose: Pose, effects: Effects, velocity, acceleration) -> None:
        self.m, self.pose, self.effects = m, pose, effects
        self.pos = pose.positions
        self.velocity, self.acceleration = velocity, acceleration
        self.frame = frame_number(m)
        self.carry = carriers(m)
        self.forces, self.couples = known_forces(m, pose, effects, acceleration)
        self.pins: dict[Pin, Vec] = {}
        self.contacts: dict[object, tuple[Vec, float]] = {}
        self.cond: dict[str, float] = {}
        self.warnings: list[str] = []
        self.steps: list[tuple] = []
        self.conns = connections(m)
        mags = [x.vector.norm() for fs in self.forces.values() for x in fs]
        mags += [abs(c) / m.size for c in self.couples.values()]
        self.scale = max(mags, default=0.0) or 1.0
        self.torque = 0.0

    # -- helpers ------------------------------------------------------------------------------------
    def pin(self, joint: str, on: int) -> Pin:
        for c in self.conns:
            if isinstance(c, Pin) and c.joint == joint and (c.other == on or c.carrier == on):
                return c
        raise ForcesNotDrawn(f"no pin joins {body_label(self.m, on)} at {joint}")

    def record_pin(self, joint: str, by: int, on: int, force: Vec) -> None:
        """Record the force of body ``by`` on body ``on`` at ``joint``, and hand its reaction to ``by``."""
        p = self.pin(joint, on)
        self.pins[p] = force if p.other == on else -force
        if by != self.frame:
            self.forces.setdefault(by, []).append(Force(force_name(on, by), by, self.pos[joint], -force, "joint"))
        self.forces.setdefault(on, []).append(Force(force_name(by, on), on, self.pos[joint], force, "joint"))

    def known(self, body: int) -> list[Force]:
        return list(self.forces.get(body, []))

    def tangential(self, body: int, outer: str, middle: str) -> tuple[float, Vec, Vec]:
        """The tangential part of the pin force at ``outer`` on ``body`` from the moments about ``middle``:
        returns (t, e_t, e_n) with the force = t e_t + n e_n, e_n along outer -> middle."""
        r = self.pos[middle] - self.pos[outer]
        e_n = r.unit()
        e_t = e_n.perp()
        _, mo = resultant(self.known(body), self.couples.get(body, 0.0), self.pos[middle])
        return mo / r.norm(), e_t, e_n



# -- the polygon of one group of bodies ------------------------------------------------------------------

def meet(p: Vec, u: Vec, q: Vec, v: Vec) -> Vec:
    """Where the line p + s u meets the line q + t v (not parallel)."""
    return p + u * ((q - p).cross(v) / u.cross(v))


def resultant_line(forces, couples: float, about: Vec) -> tuple[Vec, Vec] | None:
    """The single force equivalent to ``forces`` and ``couples`` as (a point of its line, the force), or
    None when they reduce to a couple or to nothing."""
    r, mo = resultant(forces, couples, about)
    if r.dot(r) == 0.0:                                 # nothing, a couple, or a subnormal force
        return None
    return about + r.perp() * (-mo / r.dot(r)), r


@dataclass
class Closed:
    """A polygon drawn from the pole O_f: the known forces head to tail, then two lines of action closing it."""

    points: list[Vec]            # the pole, then the tip after each known force
    crossing: Vec                # where the two closing lines meet
    last: Vec                    # the side along the line through the last tip (crossing - tip)
    first: Vec                   # the side along the line through the pole (pole - crossing)


def close(d: Drawing, key: str, what: str, knowns: list[tuple[str, Vec]],
           last: tuple[str, Vec, str], first: tuple[str, Vec, str], intro: str) -> Closed:
    """Lay off ``knowns`` from the pole, then close the polygon along ``last`` (through the last tip) and
    ``first`` (through the pole), each given as (name, direction, label of the line); records the steps."""
    dg = Diagram("force", key)
    pts = [ORIGIN]
    arrows = []
    for i, (label, v) in enumerate(knowns):
        if v.norm() == 0.0:
            continue
        arrows.append(Arrow(f"{key}: {label} {i}", Role.KNOWN, dg, pts[-1], pts[-1] + v, label))
        pts.append(pts[-1] + v)
    tip = pts[-1]
    d.steps.append((f"{intro} From the pole O_f lay off the known forces head to tail to the force scale.",
                    (Point(f"{key}: pole", Role.LABEL, dg, ORIGIN, "O_f"),
                     ScaleBar(f"{key}: scale", Role.SCALE_BAR, dg, "force", None), *arrows),
                    None, {}, StepKind.CONSTRUCTION))
    (n_last, u_last, l_last), (n_first, u_first, l_first) = last, first
    s = abs(u_last.unit().cross(u_first.unit()))
    if s < PARALLEL_SINE:
        raise IndeterminatePosition(
            f"the force polygon of {what} cannot close: the lines of action of {n_last} and {n_first} are "
            f"parallel (sine {s:.1e}), so these forces are indeterminate", position=describe_angle(d.pose.angle),
            kind="toggle", condition=s)
    x = meet(tip, u_last, ORIGIN, u_first)
    d.cond[key] = s
    if s < WARN_SINE:
        d.warnings.append(f"Near a toggle in the force polygon of {what} ({describe_angle(d.pose.angle)}): its "
                          f"closing lines cross at {math.degrees(math.asin(s)):.3g} deg; the forces are large "
                          f"and sensitive to the drawing (rounding about {rounding_estimate(s):.1e} relative).")
    d.steps.append((f"Close the polygon: through its end draw the line of action of {n_last} ({l_last}), through "
                    f"O_f that of {n_first} ({l_first}); they meet at x.",
                    (TrialLine(f"{key}: line {n_last}", Role.TRIAL, dg, tip, u_last, l_last),
                     TrialLine(f"{key}: line {n_first}", Role.TRIAL, dg, ORIGIN, u_first, l_first),
                     Point(f"{key}: x", Role.LABEL, dg, x, "x")),
                    None, {}, StepKind.CONSTRUCTION))
    return Closed(pts, x, x - tip, ORIGIN - x)


def answer(d: Drawing, key: str, named: list[tuple[str, Vec, Vec]], extra: str = "", values=None) -> None:
    """The solved forces drawn as sides of the polygon (each from its tail to its tip) and measured."""
    dg = Diagram("force", key)
    vals = dict(values or {})
    parts = []
    arrows = []
    drawn: set[tuple] = set()
    for i, (name, tail, tip) in enumerate(named):
        side = (tail.as_tuple(), tip.as_tuple())
        if side not in drawn:                 # a two-force member's two forces are one side of the polygon
            arrows.append(Arrow(f"{key}: result {name}", Role.RESULT, dg, tail, tip, name))
            drawn.add(side)
        vals[f"f{i}"] = force_value((tip - tail).norm())
        parts.append(f"{name} = $f{i}")
    d.steps.append((f"Measure {', '.join(parts)}{extra}.", tuple(arrows), None, vals, StepKind.ANSWER))


def outer_carrier(d: Drawing, point: str) -> int:
    return d.frame if point in d.m.ground else d.carry[point]


def two_force_words(d: Drawing, body: int, outer: str, j: str, name: str) -> None:
    d.steps.append((f"Link {body} carries no load between its pins {outer} and {j}: a two-force member, so "
                    f"{name} acts along {outer}{j}.", (), None, {}, StepKind.CONSTRUCTION))


def moment_step(d: Drawing, body: int, name: str, outer: str, j: str, t: float) -> None:
    d.steps.append((f"Moments about {j} on link {body}: {name}\u1d57 \u00d7 {outer}{j} balances the moment of the "
                    f"other forces on link {body} (force \u00d7 perpendicular distance), so {name}\u1d57 = $t, "
                    f"square to {outer}{j}.", (), None, {"t": force_value(abs(t))}, StepKind.CONSTRUCTION))


def is_loaded(d: Drawing, body: int) -> bool:
    return bool(d.known(body)) or d.couples.get(body, 0.0) != 0.0



def contact(d: Drawing, joint: str, blk: int | None, guide: int):
    for c in d.conns:
        if isinstance(c, Contact) and c.joint == joint and c.block == blk:
            return c
        if isinstance(c, SlotPin) and blk is None and c.joint == joint and c.guide == guide:
            return c
    raise ForcesNotDrawn(f"no slide at {joint}")
