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
- a slotted link turned about a known point until its slot passes through a known joint (RPR: inverted
  slider-crank, slotted lever) takes the pin's force square to the slot; its moment about the link's
  pivot gives its size (force x perpendicular distance) and the bearing force closes the link's polygon;
- a joint carried along two lines (PRP) takes a force square to each, closing the blocks' polygon;
- the crank is last: its bearing force closes its polygon and the driving torque is the resultant force
  times its perpendicular distance from the pivot (zero at a dead centre, where that distance is zero).

Each solved pin force is carried to the body at the other side as a known force of its later polygon.
The dyads are drawn in :mod:`.dyads` (RRR, RRP) and :mod:`.slotted` (RPR, PRP), the crank in :mod:`.crank`,
on the shared state of :mod:`.board`; this module runs them in order, draws the free bodies and records the
result.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Mapping

from ..mechanisms.topology import Contact, Pin, frame_number
from ..geometry import Vec
from ..errors import DegenerateInput
from ..mechanisms.assembly import (CircleAndGuide, CrankTip, FixedToLink, SlotAlongGuide, SlotThrough, TwoCircles,
                                   TwoLines, assembly_plan)
from ..mechanisms.model import Mechanism, slide_line
from ..mechanisms.pose import Pose
from ..quantities import Measured
from ..entities import Arrow, Curve, Diagram, Role, Segment
from ..record import Construction, StepKind, Value
from .bodies import force_name, torque_name
from .board import Drawing, Force, ForcesNotDrawn, body_label, force_value, known_forces, resultant
from .crank import driving_crank
from .dalembert import InertiaLoad, friction_rows, inertia_loads, inertia_rows
from .friction import friction_at
from .free_body_links import free_bodies
from .dyads import rrp, rrr
from .effects import Effects, Spring
from .slotted import prp, rpr

__all__ = ["Force", "ForceAnalysis", "ForcesNotDrawn", "force_analysis", "known_forces", "resultant"]


@dataclass(frozen=True)
class ForceAnalysis:
    """The force polygons at one pose and the values measured off them (SI, CCW positive).

    ``pins[pin]`` is the force of ``pin.carrier`` on ``pin.other``; ``contacts[c]`` is the total force of the
    guide on the block (or on the pin in a slot) and the guide's couple on the block; ``torque`` is the
    driving torque on the crank; ``inertia`` each massive body's inertia force and couple (from the
    acceleration polygon); ``friction`` the friction part of the guide's force, along the guide, at every
    slide where mu is set.  ``conditions`` maps each polygon to the sine at which its closing lines
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
    inertia: tuple[InertiaLoad, ...] = ()
    friction: Mapping[object, Vec] = field(default_factory=dict)

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
        return out + inertia_rows(self.inertia, self.acceleration_condition) + friction_rows(self.friction, c)


def force_analysis(m: Mechanism, pose: Pose, effects: Effects, *, velocity=None, acceleration=None) -> ForceAnalysis:
    """Draw the free bodies and force polygons of ``m`` at ``pose`` under ``effects``.  ``acceleration``
    (an AccelerationAnalysis) is needed when the effects have masses, ``velocity`` when they have friction."""
    yoke = next((s for s in assembly_plan(m) if isinstance(s, SlotAlongGuide)), None)
    if yoke is not None:
        raise DegenerateInput(f"the force analysis of a translating slotted link (the yoke, link {yoke.link.number}) "
                              f"is not drawn yet; its velocity and acceleration analyses are")
    if effects.inertial and acceleration is None:
        raise ValueError("masses make the analysis dynamic: pass the acceleration polygon")
    if effects.friction and velocity is None:
        raise ValueError("friction acts against the sliding velocity: pass the velocity polygon")
    d = Drawing(m, pose, effects, velocity, acceleration)
    if not any(x.vector.dot(x.vector) > 0 for fs in d.forces.values() for x in fs) and not any(d.couples.values()):
        d.warnings.append(NOTHING_TO_BALANCE)
    plan = assembly_plan(m)
    for step in reversed(plan[1:]):
        if isinstance(step, FixedToLink):
            continue
        if isinstance(step, TwoCircles):
            rrr(d, step)
        elif isinstance(step, CircleAndGuide):
            rrp(d, step)
        elif isinstance(step, SlotThrough):
            rpr(d, step)
        else:
            assert isinstance(step, TwoLines)
            prp(d, step)
    crank = plan[0]
    assert isinstance(crank, CrankTip)
    driving_crank(d, crank)
    return _record(d)


# -- the record ---------------------------------------------------------------------------------------

NOTHING_TO_BALANCE = ("Nothing loads the mechanism: no load, couple, spring, weight or inertia force acts on it "
                      "here (the scene gives none, or they are all zero at this pose), so every joint force and "
                      "the driving torque are zero.")
"""The warning of a force analysis with nothing to balance."""

SPRING_COILS = 6
"""The zigzags of a spring drawn on the space diagram."""


def _spring(d: Drawing, sp: Spring) -> tuple:
    """A spring on the space diagram, as a zigzag between its ends (a fixed end that is not a pivot of the
    frame as a short wall across it), and the words giving its force."""
    ends = [d.pos[e.at] if e.body is not None else d.effects.fixed[e.at] for e in (sp.a, sp.b)]
    a, b = ends
    length = a.distance_to(b)
    ents: list = []
    if length > 0:
        u = (b - a) / length
        w = u.perp() * (0.08 * length)
        ents += [Segment(f"space: {sp.name} anchor {i}", Role.GIVEN, Diagram.SPACE, p - w * 1.5, p + w * 1.5)
                 for i, (e, p) in enumerate(zip((sp.a, sp.b), ends)) if e.body is None and e.at not in d.m.ground]
        zig = [a, a + u * (0.2 * length)]
        for i in range(2 * SPRING_COILS):
            zig.append(a + u * (length * (0.2 + 0.6 * (i + 0.5) / (2 * SPRING_COILS))) + w * (1 if i % 2 == 0 else -1))
        zig += [a + u * (0.8 * length), b]
        ents.append(Curve(f"space: spring {sp.name}", Role.GIVEN, Diagram.SPACE, tuple(zig), False, sp.name))
    tension = sp.stiffness * (length - sp.free_length)
    words = (f"The spring {sp.name}: $l long, free $l0, so its tension k (L \u2212 L0) = $t "
             + ("pulls its ends together." if tension >= 0 else "is a compression: it pushes its ends apart."))
    return (words, *ents), {"values": {"l": Value("length", length), "l0": Value("length", sp.free_length),
                                       "t": force_value(abs(tension))}}


def _record(d: Drawing) -> ForceAnalysis:
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
        given = "".join(f" {ld.given}." for ld in d.effects.loads if ld.given)
        rec = rec.then("The loads as given, on the space diagram." + given, *loads, kind=StepKind.GIVEN)
    for sp in d.effects.springs:
        args, kw = _spring(d, sp)
        rec = rec.then(*args, **kw, kind=StepKind.GIVEN)
    inertia = inertia_loads(d.effects, d.acceleration.accelerations,
                            lambda b: d.acceleration.angular.get(b, 0.0)) if d.effects.inertial else ()
    for il in inertia:
        what = f"Inertia of {body_label(m, il.body)} (D'Alembert)"
        if il.acting and not il.turns:                 # a point mass (a block): no couple, no offset
            rec = rec.then(f"{what}: F_I{il.body} = \u2212m a_G = $f at {il.centre}.",
                           values={"f": force_value(il.force.norm())}, kind=StepKind.GIVEN)
        elif il.acting:
            rec = rec.then(f"{what}: F_I{il.body} = \u2212m a_G = $f at {il.centre}, offset $h so that it also stands "
                           f"for the inertia couple I_G \u03b1 = $c (h = I_G \u03b1 / (m a_G)).",
                           values={"f": force_value(il.force.norm()), "h": Value("length", il.offset),
                                   "c": Value("torque", abs(il.couple))}, kind=StepKind.GIVEN)
        elif il.couple != 0.0:
            sense = "CCW" if il.couple > 0 else "CW"          # -I_G alpha
            rec = rec.then(f"{what}: its centre of gravity {il.centre} does not accelerate, so there is no inertia "
                           f"force, only the inertia couple \u2212I_G \u03b1 = $c {sense}.",
                           values={"c": Value("torque", abs(il.couple))}, kind=StepKind.GIVEN)
        else:
            rec = rec.then(f"{what}: neither its centre of gravity {il.centre} nor its turning accelerates: no "
                           f"inertia force or couple.", kind=StepKind.GIVEN)
    bodies = free_bodies(d)                       # (moves the lines the constructions drew on the free bodies)
    for words, entities, eq, values, kind in d.steps:
        rec = rec.then(words, *entities, equation=eq, values=values, kind=kind)
    for words, ents in bodies:
        rec = rec.then(words, *ents, kind=StepKind.CONSTRUCTION)
    acc_cond = d.acceleration.worst_condition if d.acceleration is not None else 1.0
    return ForceAnalysis(rec, dict(d.pins), dict(d.contacts), d.torque, dict(d.cond), tuple(d.warnings),
                         d.scale, m.size, d.effects.inertial, acc_cond,
                         {b: tuple(v) for b, v in d.forces.items()}, inertia, _friction(d))


def _friction(d: Drawing) -> dict[object, Vec]:
    """The friction part of each guide's force read off its polygon: its component along the guide."""
    out: dict[object, Vec] = {}
    for c, (f, _) in d.contacts.items():
        if friction_at(d, c.slide):
            t = slide_line(d.m, c.slide, d.pos).direction.unit()
            out[c] = t * f.dot(t)
    return out
