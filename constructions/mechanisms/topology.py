"""The bodies of a mechanism and the joints between them: the topology the force analysis and the instant
centres share.

Bodies are the frame, the links and the slider blocks.  The frame is numbered 1, as in the notes, unless
the scene uses 1 for a moving link; then it is 0.  A force is named ``F_ij``: the force body i exerts on
body j (the notes' F_21 on the crank is the force of link 2 on link 1).

Where several bodies meet at one pin, the pin belongs to its *carrier*, the body that located it (the
crank for its tip, the first link of the dyad that found the joint, the link a point is fixed to, the
frame for a fixed pivot); every other body there is pinned to the carrier.  The forces each pair carries
are then determinate, and the graphical method and the equilibrium system share this one topology.

A connection is one of:

- :class:`Pin`: a revolute pair, two unknown components;
- :class:`Contact`: a slider block on a fixed guide or on a slot of a moving link: the guide's normal
  force (with Coulomb friction along the guide when the scene sets mu) and the couple that places its line
  of action, two unknowns;
- :class:`SlotPin`: a pin in a slot (a higher pair): the normal force only, one unknown.
"""

from __future__ import annotations

from dataclasses import dataclass

from ..errors import DegenerateInput
from .assembly import CircleAndGuide, CrankTip, FixedToLink, SlotThrough, TwoCircles, TwoLines, assembly_plan
from .model import Mechanism


def frame_number(m: Mechanism) -> int:
    """1, the notes' number of the frame, unless a moving body already uses it (then 0)."""
    used = {k.number for k in m.links} | set(m.blocks())
    return 0 if 1 in used else 1


def moving_bodies(m: Mechanism) -> tuple[int, ...]:
    """Links then slider blocks, by number."""
    return tuple(sorted(k.number for k in m.links)) + tuple(sorted(m.blocks()))


def points_of_body(m: Mechanism, body: int) -> tuple[str, ...]:
    """The points of a link (joints and attached points), or the joint of a block."""
    blocks = m.blocks()
    if body in blocks:
        return (blocks[body].joint,)
    return m.points_of(body)


def carriers(m: Mechanism) -> dict[str, int]:
    """The body each point belongs to as a pin (see the module's note): the one that located it."""
    f = frame_number(m)
    out: dict[str, int] = {g: f for g in m.ground}
    for step in assembly_plan(m):
        if isinstance(step, CrankTip):
            out.setdefault(step.tip, step.link.number)
        elif isinstance(step, TwoCircles):
            out.setdefault(step.joint, step.link_a.number)
        elif isinstance(step, (CircleAndGuide, SlotThrough)):
            out.setdefault(step.joint, step.link.number)
        elif isinstance(step, TwoLines):
            block = step.slide_a.number if step.slide_a.number is not None else step.slide_b.number
            if block is None:
                raise DegenerateInput(f"joint {step.joint} slides on two lines but no block carries it")
            out.setdefault(step.joint, block)
        elif isinstance(step, FixedToLink):
            out.setdefault(step.name, step.link.number)
    for k in m.links:                                 # a point no step named: its lowest-numbered link
        for p in m.points_of(k.number):
            out.setdefault(p, k.number)
    return out


@dataclass(frozen=True, slots=True)
class Pin:
    """Body ``other`` pinned at ``joint`` to the body ``carrier`` that carries the pin."""

    joint: str
    carrier: int
    other: int


@dataclass(frozen=True, slots=True)
class Contact:
    """Slider block ``block`` at ``joint`` on a guide of body ``guide`` (the frame for a fixed guide, else
    the slotted link ``slide.on``)."""

    joint: str
    block: int
    guide: int
    slide: object


@dataclass(frozen=True, slots=True)
class SlotPin:
    """The pin ``joint`` of body ``carrier`` in the slot of link ``guide`` (no block)."""

    joint: str
    carrier: int
    guide: int
    slide: object


Connection = Pin | Contact | SlotPin


def connections(m: Mechanism) -> tuple[Connection, ...]:
    """Every joint that carries a force, in a stable order: pins (by point, then body), then slides."""
    f = frame_number(m)
    carry = carriers(m)
    out: list[Connection] = []
    at: dict[str, list[int]] = {}
    for k in sorted(m.links, key=lambda k: k.number):
        for p in m.points_of(k.number):
            at.setdefault(p, []).append(k.number)
    for s in sorted(m.slides, key=lambda s: (s.joint, s.number if s.number is not None else -1)):
        if s.number is not None:
            at.setdefault(s.joint, []).append(s.number)
    for p, bodies in at.items():
        c = carry.get(p)
        if c is None:
            continue
        if p in m.ground:
            c = f
        for b in bodies:
            if b != c:
                out.append(Pin(p, c, b))
    for s in m.slides:
        guide = f if s.on is None else s.on
        if s.number is not None:
            out.append(Contact(s.joint, s.number, guide, s))
        else:
            out.append(SlotPin(s.joint, carry[s.joint], guide, s))
    return tuple(out)
