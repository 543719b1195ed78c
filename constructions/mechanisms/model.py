"""The model of a planar linkage: its links, sliding joints, points and the branch of every joint.

A :class:`Mechanism` is a frame with fixed pivots and rigid links.  A link has two base joints a
``length`` apart and any number of further points fixed to it (:class:`Attached`), so a coupler
triangle or a ternary rocker is one link; any of its points may be a joint of other links.  A joint
may also slide along a straight line (:class:`Slide`): a slider block on a fixed guide, a block on a
slot of a moving link (inverted slider-crank, slotted-lever quick-return, Whitworth), or a pin in a
slot.  One link, the crank, is driven from a fixed pivot.  Where a joint has two assemblies the scene
chooses one (:class:`Branch`).

:func:`mobility` counts the degrees of freedom as the notes do (Gruebler/Kutzbach, multiple joints
included).  How the linkage is put together at a crank angle is :mod:`.assembly`'s (the plan, dyad by
dyad) and :mod:`.pose`'s (the construction of the space diagram).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Callable, Collection, Mapping, TypeVar

from ..errors import DegenerateInput
from ..geometry import Line, Tolerance, Vec
from ..tolerance import scene_size

T = TypeVar("T")

@dataclass(frozen=True, slots=True)
class Link:
    """A rigid link ``number`` with base joints ``joints[0]`` and ``joints[1]`` a ``length`` apart; further
    points of the same body are :class:`Attached` to it."""

    number: int
    joints: tuple[str, str]
    length: float

    def other(self, joint: str) -> str:
        return self.joints[1] if joint == self.joints[0] else self.joints[0]

    @property
    def label(self) -> str:
        return "".join(self.joints)


@dataclass(frozen=True, slots=True)
class Slide:
    """Joint ``joint`` sliding along a straight line: in a slider block (link ``number``) pinned at the
    joint, or -- with ``number`` None -- as a pin in a slot.

    The line is a fixed guide when ``on`` is None (through ``through`` at ``angle`` CCW from +x), else a
    slot in link ``on``: the direction of the link's base line (first joint to second) turned by
    ``angle``, passing ``offset`` to the left of the link's first joint (measured square to the slot).
    A block on a slot turns with the slotted link.
    """

    number: int | None
    joint: str
    through: Vec
    angle: float
    on: int | None = None
    offset: float = 0.0

    @property
    def line(self) -> Line:
        """The fixed guide (for a slot use :meth:`slot_line`)."""
        if self.on is not None:
            raise DegenerateInput(f"the slot of {self.joint} moves with link {self.on}; it has no fixed line")
        return Line.at_angle(self.through, self.angle)

    def slot_line(self, first: Vec, second: Vec) -> Line:
        """The slot's line when the slotted link's base joints stand at ``first`` and ``second``."""
        d = (second - first).unit().rotated(self.angle)
        return Line(first - d.perp() * self.offset, d)

    @property
    def label(self) -> str:
        return f"block {self.number}" if self.number is not None else f"pin {self.joint}"


@dataclass(frozen=True, slots=True)
class Attached:
    """A point fixed to link ``link``: ``distance`` from the link's joint ``base``, at ``angle``
    measured counter-clockwise from the direction of the link (from ``base`` to its other joint).
    It may be a joint of other links (a ternary link's third joint)."""

    name: str
    link: int
    base: str
    distance: float
    angle: float


@dataclass(frozen=True, slots=True)
class Branch:
    """Which of two assemblies: ``sign`` +1 is LEFT of the directed line ``reference[0] -> [1]``
    (two circles), or AHEAD of the foot of ``reference[0]`` along the guide or slot (a circle and a
    line; for a slot through a known joint, the joint lies ahead of the slotted link's known point)."""

    sign: int
    reference: tuple[str, ...]

    def describe(self) -> str:
        if len(self.reference) == 2:
            return f"{'left' if self.sign > 0 else 'right'} of {self.reference[0]}->{self.reference[1]}"
        return f"{'ahead of' if self.sign > 0 else 'behind'} {self.reference[0]}"

@dataclass(frozen=True)
class Mechanism:
    ground: Mapping[str, Vec]
    links: tuple[Link, ...]
    slides: tuple[Slide, ...]
    attached: tuple[Attached, ...]
    crank: int
    branches: Mapping[str, Branch]
    _derived: dict = field(default_factory=dict, init=False, repr=False, compare=False)

    def link(self, number: int) -> Link:
        for k in self.links:
            if k.number == number:
                return k
        raise DegenerateInput(f"there is no link {number}")

    def crank_pivot(self) -> str:
        """The fixed pivot the crank turns about; DegenerateInput unless the crank joins one fixed pivot to
        one moving joint."""
        crank = self.link(self.crank)
        pivots = [j for j in crank.joints if j in self.ground]
        if len(pivots) != 1:
            raise DegenerateInput(f"the crank, link {crank.number} ({crank.label}), must join one fixed pivot "
                                  f"to one moving joint; fixed pivots are {', '.join(self.ground) or 'none'}")
        return pivots[0]

    def local(self, number: int) -> dict[str, Vec]:
        """The points of link ``number`` in its own frame: first base joint at the origin, second on +x."""
        k = self.link(number)
        p, q = k.joints
        out = {p: Vec(0.0, 0.0), q: Vec(k.length, 0.0)}
        for a in self.attached:
            if a.link == number:
                if a.base == p:
                    out[a.name] = Vec.polar(a.distance, a.angle)
                elif a.base == q:
                    out[a.name] = out[q] + Vec.polar(a.distance, math.pi + a.angle)
                else:
                    raise DegenerateInput(f"point {a.name} is measured from {a.base}, which is not a joint "
                                          f"of link {number} ({k.label})")
        return out

    def points_of(self, number: int) -> tuple[str, ...]:
        return tuple(self.local(number))

    def blocks(self) -> dict[int, Slide]:
        """Slider blocks by link number."""
        return {s.number: s for s in self.slides if s.number is not None}

    @property
    def size(self) -> float:
        """The scene size L (:func:`constructions.tolerance.scene_size`): link lengths, point distances on
        links, slot offsets, distances between fixed pivots and of fixed pivots from fixed guides --
        tolerances are relative to it, and it does not move with the origin."""
        lengths = [k.length for k in self.links] + [a.distance for a in self.attached]
        lengths += [abs(s.offset) for s in self.slides]
        lines = [(s.through.as_tuple(), s.angle) for s in self.slides if s.on is None]
        return scene_size(lengths, [p.as_tuple() for p in self.ground.values()], lines)

    def tolerance(self) -> Tolerance:
        return Tolerance(self.size)

    def derived(self, compute: Callable[[Mechanism], T]) -> T:
        """``compute(self)``, found once and kept: the mechanism is immutable and a study asks for what
        follows from it (its assembly plan, :func:`.assembly.assembly_plan`) several times."""
        if compute not in self._derived:
            self._derived[compute] = compute(self)
        return self._derived[compute]


def mobility(m: Mechanism) -> tuple[int, str]:
    """Degrees of freedom by the Gruebler/Kutzbach count, F = 3 (n - 1) - 2 j1 - j2, and its working.

    n counts the frame, the links and the slider blocks; a revolute joint shared by k bodies counts as
    k - 1 joints (a multiple joint); every block adds its sliding pair; a pin in a slot is a higher pair
    (j2: it slides and turns)."""
    bodies = 1 + len(m.links) + len(m.blocks())
    at: dict[str, int] = {g: 1 for g in m.ground}              # the frame carries its pivots
    for k in m.links:
        for j in m.points_of(k.number):
            at[j] = at.get(j, 0) + 1
    for s in m.slides:
        if s.number is not None:
            at[s.joint] = at.get(s.joint, 0) + 1                  # the block is pinned at the joint
    j1 = sum(c - 1 for c in at.values() if c > 1)
    j1 += len(m.blocks())                                         # each block's sliding pair
    j2 = sum(1 for s in m.slides if s.number is None)
    f = 3 * (bodies - 1) - 2 * j1 - j2
    return f, f"n = {bodies}, j1 = {j1}, j2 = {j2}: F = 3({bodies} - 1) - 2·{j1} - {j2} = {f}"


def coincident_name(joint: str, link: int, taken: Collection[str] = ()) -> str:
    """The point of link ``link`` under a sliding joint, as the notes write it: A on link 3 is A3; primed
    while it clashes with a name in ``taken`` (the points of the mechanism)."""
    name = f"{joint}{link}"
    while name in taken:
        name += "'"
    return name


def describe_angle(angle: float) -> str:
    return f"crank angle {math.degrees(angle):.6g} deg"


def place_rigid(local: Mapping[str, Vec], a: str, b: str, pa: Vec, pb: Vec, x: str) -> Vec:
    """Where point ``x`` of a rigid body stands when its points ``a`` and ``b`` stand at pa and pb."""
    turn = (pb - pa).angle() - (local[b] - local[a]).angle()
    return pa + (local[x] - local[a]).rotated(turn)


def slide_line(m: Mechanism, s: Slide, pos: Mapping[str, Vec]) -> Line:
    """The line ``s`` slides on at the positions ``pos`` (the guide, or the slot of a placed link)."""
    if s.on is None:
        return s.line
    k = m.link(s.on)
    return s.slot_line(pos[k.joints[0]], pos[k.joints[1]])

