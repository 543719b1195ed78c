"""Static and D'Alembert force analysis drawn as the notes draw it, dyad by dyad from the output back to
the crank.

Every body's known forces come first: the scene's loads and couples, springs, weights (only when the
scene sets g) and, where a body has mass, D'Alembert's inertia force -m a_G drawn on its offset line of
action (h = I_G alpha / (m a_G) from G, so that one force stands for the inertia force and couple) --
the accelerations read off the acceleration polygon.  Then the dyads are taken in the reverse of their
assembly order, so each has at most two unknown magnitudes when its polygon is drawn:

- a link with no load between its two pins is a *two-force member*: its force acts along the pins' line;
- an RRR dyad with one two-force link makes the other a *three-force member*: the line of its load and
  the two-force line meet at a point, and the third force passes through it (concurrency); the force
  triangle closes on those two directions;
- otherwise each link's pin force at its outer joint is split into a tangential part, found from the
  moments about the middle joint (force x perpendicular distance), and a part along the link; the force
  polygon of the dyad closes on the two directions along the links;
- a slider block's guide pushes square to the guide (tilted by the friction angle when the scene sets
  mu, against the block's motion along the guide);
- the crank is last: its bearing force closes its polygon and the driving torque is the resultant force
  times its perpendicular distance from the pivot (zero at a dead centre, where that distance is zero).

Each solved pin force is carried to the body at the other side as a known force of its later polygon.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Mapping

from ..errors import ConstructionError, IndeterminatePosition
from ..geometry import Vec
from ..linkage import (CircleAndGuide, CrankTip, FixedToLink, Mechanism, Pose, SlotThrough, TwoCircles,
                       assembly_plan, describe_angle)
from ..polygons.common import WARN_SINE, rounding_estimate
from ..quantities import Measured
from ..record import (Arrow, Bar, Block, Construction, Diagram, Dimension, Plate, Point, Role, ScaleBar, StepKind,
                      TrialLine, Value)
from .bodies import Contact, Pin, SlotPin, carriers, connections, force_name, frame_number, torque_name
from .effects import Effects

ORIGIN = Vec(0.0, 0.0)
PARALLEL_SINE = 1e-9
"""Below this sine two lines of action are parallel: the force polygon cannot close."""


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


@dataclass(frozen=True)
class ForceAnalysis:
    """The force polygons at one pose and the values measured off them (SI, CCW positive).

    ``pins[pin]`` is the force of ``pin.carrier`` on ``pin.other``; ``contacts[c]`` is the total force of the
    guide on the block (or on the pin in a slot) and the guide's couple on the block; ``torque`` is the
    driving torque on the crank.  ``conditions`` maps each polygon to the sine at which its closing lines
    crossed."""

    construction: Construction
    pins: Mapping[Pin, Vec]
    contacts: Mapping[object, tuple[Vec, float]]
    torque: float
    conditions: Mapping[str, float]
    warnings: tuple[str, ...]
    force_scale: float
    length_scale: float
    inertial: bool = False
    acceleration_condition: float = 1.0
    bodies: Mapping[int, tuple[Force, ...]] = field(default_factory=dict)

    @property
    def worst_condition(self) -> float:
        return min(list(self.conditions.values()) + [self.acceleration_condition], default=1.0)

    def scales(self) -> dict[str, float]:
        return {"force": self.force_scale, "torque": self.force_scale * self.length_scale}

    def measured(self, m: Mechanism) -> list[Measured]:
        """Every pin force as the force on the body nearer the crank (bearing forces: of the frame on the
        link), every guide force on its block, and the driving torque."""
        f = frame_number(m)
        c = self.worst_condition
        out = []
        for p, v in self.pins.items():
            if p.carrier == f:
                out.append(Measured(force_name(f, p.other), "force", v, c))
            else:
                out.append(Measured(force_name(p.other, p.carrier), "force", -v, c))
        for k, (v, _) in self.contacts.items():
            body = k.block if isinstance(k, Contact) else k.carrier
            out.append(Measured(force_name(k.guide, body), "force", v, c))
        out.append(Measured(torque_name(m), "torque", self.torque, c))
        return out


def _v(value: float) -> Value:
    return Value("force", value)


def _body_label(m: Mechanism, body: int) -> str:
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
        if acceleration is None:
            continue
        a_g = acceleration.accelerations[ms.centre]
        al = acceleration.angular.get(ms.body, 0.0)
        f_i = a_g * (-ms.mass)
        c_i = -ms.inertia * al
        if f_i.norm() > 0:
            # one force on the offset line: d x F_I = C_I, d square to F_I, h = |C_I| / |F_I|
            d = f_i.perp() * (-c_i / f_i.dot(f_i))
            forces.setdefault(ms.body, []).append(Force(f"F_I{ms.body}", ms.body, g_at + d, f_i, "inertia"))
        elif c_i != 0.0:
            couples[ms.body] = couples.get(ms.body, 0.0) + c_i
    return forces, couples


class _Drawing:
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
        raise ForcesNotDrawn(f"no pin joins {_body_label(self.m, on)} at {joint}")

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



def force_analysis(m: Mechanism, pose: Pose, effects: Effects, *, velocity=None, acceleration=None) -> ForceAnalysis:
    """Draw the free bodies and force polygons of ``m`` at ``pose`` under ``effects``.  ``acceleration``
    (an AccelerationAnalysis) is needed when the effects have masses, ``velocity`` when they have friction."""
    if effects.inertial and acceleration is None:
        raise ValueError("masses make the analysis dynamic: pass the acceleration polygon")
    if effects.friction and velocity is None:
        raise ValueError("friction acts against the sliding velocity: pass the velocity polygon")
    d = _Drawing(m, pose, effects, velocity, acceleration)
    plan = assembly_plan(m)
    for step in reversed(plan[1:]):
        if isinstance(step, FixedToLink):
            continue
        if isinstance(step, TwoCircles):
            _rrr(d, step)
        elif isinstance(step, CircleAndGuide):
            _rrp(d, step)
        else:
            dyad = "a slot turned through a joint (RPR)" if isinstance(step, SlotThrough) else \
                "a joint carried along two lines (PRP)"
            raise ForcesNotDrawn(f"the force polygons of {dyad} at {step.joint} are not drawn yet")
    crank = plan[0]
    assert isinstance(crank, CrankTip)
    _crank(d, crank)
    return _record(d)


# -- the polygon of one group of bodies ------------------------------------------------------------------

def _cross(p: Vec, u: Vec, q: Vec, v: Vec) -> Vec:
    """Where the line p + s u meets the line q + t v (not parallel)."""
    return p + u * ((q - p).cross(v) / u.cross(v))


def _resultant_line(forces, couples: float, about: Vec) -> tuple[Vec, Vec] | None:
    """The single force equivalent to ``forces`` and ``couples`` as (a point of its line, the force), or
    None when they reduce to a couple or to nothing."""
    r, mo = resultant(forces, couples, about)
    if r.norm() == 0.0:
        return None
    return about + r.perp() * (-mo / r.dot(r)), r


@dataclass
class _Closed:
    """A polygon drawn from the pole O_f: the known forces head to tail, then two lines of action closing it."""

    points: list[Vec]            # the pole, then the tip after each known force
    crossing: Vec                # where the two closing lines meet
    last: Vec                    # the side along the line through the last tip (crossing - tip)
    first: Vec                   # the side along the line through the pole (pole - crossing)


def _close(d: _Drawing, key: str, what: str, knowns: list[tuple[str, Vec]],
           last: tuple[str, Vec, str], first: tuple[str, Vec, str], intro: str) -> _Closed:
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
    x = _cross(tip, u_last, ORIGIN, u_first)
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
    return _Closed(pts, x, x - tip, ORIGIN - x)


def _answer(d: _Drawing, key: str, named: list[tuple[str, Vec, Vec]], extra: str = "", values=None) -> None:
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
        vals[f"f{i}"] = _v((tip - tail).norm())
        parts.append(f"{name} = $f{i}")
    d.steps.append((f"Measure {', '.join(parts)}{extra}.", tuple(arrows), None, vals, StepKind.ANSWER))


def _outer_carrier(d: _Drawing, point: str) -> int:
    return d.frame if point in d.m.ground else d.carry[point]


def _two_force_words(d: _Drawing, body: int, outer: str, j: str, name: str) -> None:
    d.steps.append((f"Link {body} carries no load between its pins {outer} and {j}: a two-force member, so "
                    f"{name} acts along {outer}{j}.", (), None, {}, StepKind.CONSTRUCTION))


def _moment_step(d: _Drawing, body: int, name: str, outer: str, j: str, t: float) -> None:
    d.steps.append((f"Moments about {j} on link {body}: {name}\u1d57 \u00d7 {outer}{j} balances the moment of the "
                    f"other forces on link {body} (force \u00d7 perpendicular distance), so {name}\u1d57 = $t, "
                    f"square to {outer}{j}.", (), None, {"t": _v(abs(t))}, StepKind.CONSTRUCTION))


def _loaded(d: _Drawing, body: int) -> bool:
    return bool(d.known(body)) or d.couples.get(body, 0.0) != 0.0


def _rrr(d: _Drawing, step: TwoCircles) -> None:
    """Links a (first-j) and b (second-j): three-force by concurrency when one is a two-force member,
    else tangential parts from the moments about j and the polygon closing along the links."""
    pos = d.pos
    a, b, j = step.link_a.number, step.link_b.number, step.joint
    first, second = step.first, step.second
    by_a, by_b = _outer_carrier(d, first), _outer_carrier(d, second)
    n_a, n_b, n_ab = force_name(by_a, a), force_name(by_b, b), force_name(a, b)
    what, key = f"links {a} and {b}", f"links {a}, {b}"
    la, lb = _loaded(d, a), _loaded(d, b)
    for body, outer, name, loaded in ((a, first, n_a, la), (b, second, n_b, lb)):
        if not loaded:
            _two_force_words(d, body, outer, j, name)
    if la != lb:
        loaded, l_outer, l_name, free, f_outer = (a, first, n_a, b, second) if la else (b, second, n_b, a, first)
        line = _resultant_line(d.known(loaded), d.couples.get(loaded, 0.0), pos[j])
        along = pos[j] - pos[f_outer]
        if line is not None and abs(line[1].unit().cross(along.unit())) > WARN_SINE:
            at, r = line
            conc = _cross(at, r, pos[j], along)
            third = conc - pos[l_outer]
            if third.norm() > 1e-12 * d.m.size:
                fb = Diagram("free-body", _body_label(d.m, loaded))
                d.steps.append((
                    f"Link {loaded} is a three-force member: the line of its load and the line of the force "
                    f"from link {free} (along {f_outer}{j}) meet at I_{loaded}, so {l_name} passes through "
                    f"{l_outer} and I_{loaded}.",
                    (TrialLine(f"fbd {_body_label(d.m, loaded)}: load line", Role.TRIAL, fb, at, r, None),
                     TrialLine(f"fbd {_body_label(d.m, loaded)}: two-force line", Role.TRIAL, fb, pos[j], along, None),
                     TrialLine(f"fbd {_body_label(d.m, loaded)}: third line", Role.TRIAL, fb, pos[l_outer], third, None),
                     Point(f"fbd {_body_label(d.m, loaded)}: I", Role.LABEL, fb, conc, f"I_{loaded}")),
                    None, {}, StepKind.CONSTRUCTION))
                n_free_on_loaded = force_name(free, loaded)
                c = _close(d, key, what, [(x.label, x.vector) for x in d.known(loaded)],
                           (l_name, third, f"\u2225 {l_outer}I"),
                           (n_free_on_loaded, along, f"\u2225 {f_outer}{j}"),
                           f"Force triangle of link {loaded}.")
                f_loaded, f_on_loaded = c.last, c.first
                tip = c.points[-1]
                _answer(d, key, [(l_name, tip, c.crossing), (n_free_on_loaded, c.crossing, ORIGIN)])
                if loaded == a:
                    f_a, f_ab = f_loaded, -f_on_loaded
                    f_b = -f_ab                                     # b is a two-force member
                else:
                    f_b, f_ab = f_loaded, f_on_loaded
                    f_a = f_ab
                d.record_pin(j, a, b, f_ab)
                d.record_pin(first, by_a, a, f_a)
                d.record_pin(second, by_b, b, f_b)
                return
    t_a, et_a, en_a = d.tangential(a, first, j)
    t_b, et_b, en_b = d.tangential(b, second, j)
    if t_a:
        _moment_step(d, a, n_a, first, j, t_a)
    if t_b:
        _moment_step(d, b, n_b, second, j, t_b)
    ka, kb = d.known(a), d.known(b)
    knowns = [(f"{n_a}\u1d57", et_a * t_a)] + [(x.label, x.vector) for x in ka] + \
             [(x.label, x.vector) for x in kb] + [(f"{n_b}\u1d57", et_b * t_b)]
    c = _close(d, key, what, knowns, (f"{n_b}\u207f", en_b, f"\u2225 {second}{j}"),
               (f"{n_a}\u207f", en_a, f"\u2225 {first}{j}"), f"Force polygon of {what}.")
    p1 = et_a * t_a                                     # end of F_a^t
    q = p1 + sum((x.vector for x in ka), ORIGIN)        # end of link a's loads
    start_b = c.points[-1] - et_b * t_b                 # start of F_b^t
    f_a = p1 - c.crossing
    f_b = c.crossing - start_b
    f_ab = q - c.crossing
    _answer(d, key, [(n_a, c.crossing, p1), (n_b, start_b, c.crossing), (n_ab, c.crossing, q)])
    d.record_pin(j, a, b, f_ab)
    d.record_pin(first, by_a, a, f_a)
    d.record_pin(second, by_b, b, f_b)


def _rrp(d: _Drawing, step: CircleAndGuide) -> None:
    """Link a (centre-j) and the block at j on a guide (or the pin j in a slot): the guide's force is
    square to the guide (tilted by the friction angle against the sliding), the pin force at the centre
    split by the moments about j; the polygon closes along the link and the guide's reaction."""
    m, pos = d.m, d.pos
    a, j, first = step.link.number, step.joint, step.centre
    sl = step.slide
    blk = sl.number
    guide = d.frame if sl.on is None else sl.on
    by_a = _outer_carrier(d, first)
    n_a = force_name(by_a, a)
    body_g = blk if blk is not None else a                   # the body the guide pushes on
    n_g = force_name(guide, body_g)
    what = f"link {a} and block {blk}" if blk is not None else f"link {a} (pin {j} in the slot of link {guide})"
    key = f"links {a}, {blk}" if blk is not None else f"link {a}"
    g_dir = d.pose.lines[j].direction
    normal = g_dir.perp()
    mu = d.effects.friction.get(blk, 0.0) if blk is not None else 0.0
    slide_sign = 0.0
    if mu:
        v = d.velocity.velocities[j]
        if sl.on is not None:
            v = v - d.velocity.velocities[step.coincident]
        along = v.dot(g_dir)
        tol = 1e-12 * max(w.norm() for w in d.velocity.velocities.values())
        slide_sign = 0.0 if abs(along) <= tol else math.copysign(1.0, along)
        if slide_sign == 0.0:
            d.warnings.append(f"Block {blk} is momentarily at rest on its guide: the friction force is "
                              f"undetermined and left out.")
    la = _loaded(d, a)
    if not la:
        _two_force_words(d, a, first, j, n_a)
    t_a, et_a, en_a = d.tangential(a, first, j)
    if t_a:
        _moment_step(d, a, n_a, first, j, t_a)
    ka = d.known(a)
    kb = d.known(blk) if blk is not None else []
    knowns = [(f"{n_a}\u1d57", et_a * t_a)] + [(x.label, x.vector) for x in ka] + [(x.label, x.vector) for x in kb]
    direction, intro = normal, f"Force polygon of {what}."
    if mu and slide_sign:
        direction = _friction_lean(d, knowns, normal, g_dir * (mu * slide_sign), en_a, blk)
        intro += (" The guide's reaction leans back from the normal by the friction angle \u03c6 = atan \u03bc, "
                  "against the sliding, on the face the block bears on.")
    c = _close(d, key, what, knowns, (n_g, direction, "\u22a5 guide" if direction is normal else "at \u03c6 to the normal"),
               (f"{n_a}\u207f", en_a, f"\u2225 {first}{j}"), intro)
    p1 = et_a * t_a
    q = p1 + sum((x.vector for x in ka), ORIGIN)
    n_total = c.last
    f_a = p1 - c.crossing
    named = [(n_a, c.crossing, p1), (n_g, c.points[-1], c.crossing)]
    if blk is not None:
        f_ab = q - c.crossing                 # of link a on the block, from the block's balance
        named.append((force_name(a, blk), c.crossing, q))
        # the guide's couple places its reaction: moments about j on the block
        _, mo = resultant(kb, d.couples.get(blk, 0.0), pos[j])
        couple = -mo
    else:
        couple = 0.0
    extra = ""
    values = {}
    if blk is not None and abs(couple) > 1e-12 * d.scale * m.size and n_total.norm() > 0:
        extra = f"; the guide's reaction acts $e from {j} along the guide (its moment balances the block's)"
        values = {"e": Value("length", abs(couple) / n_total.norm())}
    _answer(d, key, named, extra, values)
    d.contacts[_contact(d, j, blk, guide)] = (n_total, couple)
    if blk is not None:
        d.record_pin(j, a, blk, f_ab)
        d.forces.setdefault(blk, []).append(Force(n_g, blk, pos[j], n_total, "guide"))
    else:
        d.forces.setdefault(a, []).append(Force(n_g, a, pos[j], n_total, "guide"))
    if guide != d.frame:                       # the reaction on the slotted link
        d.forces.setdefault(guide, []).append(Force(force_name(body_g, guide), guide, pos[j], -n_total, "guide"))
        if couple:
            d.couples[guide] = d.couples.get(guide, 0.0) - couple
    d.record_pin(first, by_a, a, f_a)


def _friction_lean(d: _Drawing, knowns, normal: Vec, lean: Vec, along_link: Vec, blk: int) -> Vec:
    """The line of the guide's total reaction N n - mu |N| sign(v) t: leaning by ``-lean`` when the block
    bears on the face the normal points from (N >= 0), by ``+lean`` on the other face.  The face is the one
    whose polygon closes with a normal part of that sign (a part within rounding of zero fits either)."""
    tip = sum((v for _, v in knowns), ORIGIN)
    floor = 1e-12 * d.scale
    for direction, face in ((normal - lean, 1.0), (normal + lean, -1.0)):
        if abs(direction.unit().cross(along_link)) < PARALLEL_SINE:
            continue
        x = _cross(tip, direction, ORIGIN, along_link)
        if (x - tip).dot(normal) * face >= -floor:
            return direction
    raise IndeterminatePosition(f"friction lock at block {blk}: with mu the guide's reaction cannot balance "
                                f"the block on either face of its guide", position=describe_angle(d.pose.angle),
                                kind="friction lock")


def _contact(d: _Drawing, joint: str, blk: int | None, guide: int):
    for c in d.conns:
        if isinstance(c, Contact) and c.joint == joint and c.block == blk:
            return c
        if isinstance(c, SlotPin) and blk is None and c.joint == joint and c.guide == guide:
            return c
    raise ForcesNotDrawn(f"no slide at {joint}")


def _crank(d: _Drawing, crank: CrankTip) -> None:
    """The crank: its bearing force closes its polygon; the driving torque is the resultant of the other
    forces times its perpendicular distance from the pivot."""
    m, pos = d.m, d.pos
    n, o = crank.link.number, crank.pivot
    name_o = force_name(d.frame, n)
    t_name = torque_name(m)
    known = d.known(n)
    cpl = d.couples.get(n, 0.0)
    r, mo = resultant(known, cpl, pos[o])
    torque = -mo
    key = f"link {n}"
    fb = Diagram("free-body", _body_label(m, n))
    if len(known) >= 2:
        dg = Diagram("force", key)
        pts = [ORIGIN]
        arrows = []
        for i, x in enumerate(known):
            arrows.append(Arrow(f"{key}: {x.label} {i}", Role.KNOWN, dg, pts[-1], pts[-1] + x.vector, x.label))
            pts.append(pts[-1] + x.vector)
        d.steps.append((f"Force polygon of the crank, link {n}: lay off its known forces from O_f; the bearing "
                        f"force {name_o} closes it.",
                        (Point(f"{key}: pole", Role.LABEL, dg, ORIGIN, "O_f"),
                         ScaleBar(f"{key}: scale", Role.SCALE_BAR, dg, "force", None), *arrows,
                         Arrow(f"{key}: result {name_o}", Role.RESULT, dg, pts[-1], ORIGIN, name_o)),
                        None, {"f": _v(r.norm())}, StepKind.ANSWER))
    else:
        d.steps.append((f"The crank, link {n}, carries {known[0].label if known else 'no force'} and the bearing "
                        f"force: {name_o} = \u2212({known[0].label if known else '0'}) = $f."
                        if len(known) == 1 else f"The crank carries no force: {name_o} = 0.",
                        (), None, {"f": _v(r.norm())}, StepKind.ANSWER))
    h = abs(mo - cpl) / r.norm() if r.norm() > 0 else 0.0
    ents = []
    if r.norm() > 0 and h > 1e-9 * m.size:
        line_pt = pos[o] + r.perp() * (-(mo - cpl) / r.dot(r))          # foot of the perpendicular from O
        ents.append(TrialLine(f"fbd {_body_label(m, n)}: resultant line", Role.TRIAL, fb, line_pt, r, None))
        ents.append(Dimension(f"fbd {_body_label(m, n)}: h", Role.DIMENSION, fb, pos[o], line_pt, 0.0, "h"))
    sense = "CCW" if torque > 0 else "CW" if torque < 0 else ""
    if r.norm() > 0 and h <= 1e-9 * m.size and cpl == 0.0:
        words = (f"The resultant force on the crank passes through {o} (a dead centre): h = 0, so no torque "
                 f"is needed to hold it: {t_name} = 0.")
        torque = 0.0
        vals = {}
    else:
        words = (f"Driving torque: {t_name} = resultant \u00d7 perpendicular distance h from {o}"
                 + (" (with the couples on the crank)" if cpl else "")
                 + f" = $r \u00d7 $h = $t {sense}.")
        vals = {"r": _v(r.norm()), "h": Value("length", h), "t": Value("torque", abs(torque))}
    d.steps.append((words, tuple(ents), None, vals, StepKind.ANSWER))
    d.torque = torque
    d.record_pin(o, d.frame, n, -r)


# -- free-body diagrams and the record ---------------------------------------------------------------

FBD_LONGEST = 0.6
"""The longest force arrow on a free-body diagram, as a fraction of the body's size (arrows are not to scale
on a free body; their magnitudes are written on the force polygons)."""


def _free_bodies(d: _Drawing) -> list[tuple]:
    m, pos = d.m, d.pos
    blocks = m.blocks()
    out = []
    order = [k.number for k in m.links] + sorted(blocks)
    for body in order:
        forces = d.forces.get(body, [])
        dg = Diagram("free-body", _body_label(m, body))
        ents: list = []
        if body in blocks:
            sl = blocks[body]
            ents.append(Block(f"fbd {dg.name}: body", Role.GIVEN, dg, pos[sl.joint], d.pose.lines[sl.joint].direction, body))
        else:
            pts = [pos[x] for x in m.points_of(body)]
            if len(pts) == 2:
                ents.append(Bar(f"fbd {dg.name}: body", Role.GIVEN, dg, pts[0], pts[1], body))
            else:
                ents.append(Plate(f"fbd {dg.name}: body", Role.GIVEN, dg, tuple(pts), body))
        big = max((x.vector.norm() for x in forces), default=0.0)
        pts = [pos[p] for p in (m.points_of(body) if body not in blocks else ())]
        extent = max((p.distance_to(q) for p in pts for q in pts), default=0.0)
        size = max(extent, 0.25 * m.size)
        for i, x in enumerate(forces):
            mag = x.vector.norm()
            if mag == 0.0 or big == 0.0:
                continue
            length = size * FBD_LONGEST * max(0.35, mag / big)
            role = Role.LOAD if x.kind in ("load", "weight", "inertia", "spring") else Role.RESULT
            tail = x.at - x.vector.unit() * length
            ents.append(Arrow(f"fbd {dg.name}: {x.label} {i}", role, dg, tail, x.at, x.label))
        labels = ", ".join(x.label for x in forces) or "no force"
        out.append((f"Free-body diagram of {dg.name}: {labels} (arrows not to scale).", tuple(ents)))
    return out


def _record(d: _Drawing) -> ForceAnalysis:
    m, pos = d.m, d.pos
    title = "D'Alembert force analysis" if d.effects.inertial else "Static force analysis"
    rec = Construction(title)
    loads = []
    for i, ld in enumerate(d.effects.loads):
        if ld.force.norm() == 0.0:
            continue
        at = pos[ld.at]
        loads.append(Arrow(f"space: {ld.name} {i}", Role.LOAD, Diagram.SPACE, at - ld.force.unit() * (0.3 * m.size),
                           at, ld.name))
    if loads:
        rec = rec.then("The loads as given, on the space diagram.", *loads, kind=StepKind.GIVEN)
    if d.effects.inertial:
        for ms in d.effects.masses:
            a_g = d.acceleration.accelerations[ms.centre]
            al = d.acceleration.angular.get(ms.body, 0.0)
            f = a_g.norm() * ms.mass
            c = ms.inertia * abs(al)
            h = c / f if f > 0 else 0.0
            rec = rec.then(f"Inertia of {_body_label(m, ms.body)} (D'Alembert): F_I{ms.body} = \u2212m a_G = $f "
                           f"at {ms.centre}, offset $h so that it also stands for the inertia couple "
                           f"I_G \u03b1 = $c (h = I_G \u03b1 / (m a_G)).",
                           values={"f": _v(f), "h": Value("length", h), "c": Value("torque", c)},
                           kind=StepKind.GIVEN)
    for words, entities, eq, values, kind in d.steps:
        rec = rec.then(words, *entities, equation=eq, values=values, kind=kind)
    for words, ents in _free_bodies(d):
        rec = rec.then(words, *ents, kind=StepKind.CONSTRUCTION)
    acc_cond = d.acceleration.worst_condition if d.acceleration is not None else 1.0
    return ForceAnalysis(rec, dict(d.pins), dict(d.contacts), d.torque, dict(d.cond), tuple(d.warnings),
                         d.scale, m.size, d.effects.inertial, acc_cond,
                         {b: tuple(v) for b, v in d.forces.items()})
