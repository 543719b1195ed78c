"""The constraint model of a mechanism: its bodies, their coordinates, and the constraints between them.

Built from the mechanism's data only (pivots, links and :meth:`Mechanism.local`, slides, the crank) for
the constraint check (:mod:`.constraint_kinematics`; the equations are :mod:`.constraint_equations`').

Coordinates
-----------
Every moving body has three coordinates q_k = (x_k, y_k, phi_k):

* a link: the position of its first base joint ``joints[0]`` and the angle of its base line (first
  joint to second); a point with body-frame coordinates s (from ``m.local(k)``) stands at
  r_k + R(phi_k) s;
* a slider block (a :class:`Slide` with a number): the position of its pin and its angle.

The frame is no body: its points (the fixed pivots) stand where ``m.ground`` puts them.

"""

from __future__ import annotations

import math
from dataclasses import dataclass
from types import MappingProxyType
from typing import Mapping

from ..errors import DegenerateInput
from .model import Mechanism, coincident_name

FRAME = -1
"""The body index of the frame, whose points stand where ``m.ground`` puts them."""

@dataclass(frozen=True, slots=True)
class Body:
    kind: str                                   # "link" or "block"
    number: int
    local: Mapping[str, tuple[float, float]]    # body-frame coordinates of its points
    size: float                                 # ell: scales its angle coordinate

    @property
    def label(self) -> str:
        return f"{self.kind} {self.number}"


@dataclass(frozen=True, slots=True)
class Revolute:
    point: str
    a: tuple[int, tuple[float, float]]          # (body index or FRAME, body-frame / world coordinates)
    b: tuple[int, tuple[float, float]]


@dataclass(frozen=True, slots=True)
class OnLine:
    joint: str
    body: int                                   # the body carrying the point
    s: tuple[float, float]
    slot: int | None                            # the slotted body, or None for a fixed guide
    angle: float
    offset: float
    through: tuple[float, float]                # fixed guide only
    what: str


@dataclass(frozen=True, slots=True)
class BlockAngle:
    body: int
    other: int | None
    angle: float
    what: str


@dataclass(frozen=True)
class Model:
    bodies: tuple[Body, ...]
    carriers: Mapping[str, tuple[tuple[int, tuple[float, float]], ...]]   # point -> bodies carrying it
    revolutes: tuple[Revolute, ...]
    lines: tuple[OnLine, ...]
    angles: tuple[BlockAngle, ...]
    crank: int                                  # body index of the crank
    crank_offset: float                         # c0: phi_crank = theta + c0
    coincident: Mapping[str, tuple[str, int]]   # coincident name -> (joint, body index of the slotted link)
    scale: float                                # L
    unknowns: int
    equations: int

    def rows(self) -> list[tuple[str, float]]:
        """(what each equation says, its row scale), in the order of :func:`residual`."""
        out: list[tuple[str, float]] = []
        for c in self.revolutes:
            who = " and ".join("the frame" if b == FRAME else self.bodies[b].label for b, _ in (c.a, c.b))
            out += [(f"joint {c.point} ({who}), x", 1 / self.scale), (f"joint {c.point} ({who}), y", 1 / self.scale)]
        out += [(c.what, 1 / self.scale) for c in self.lines]
        out += [(c.what, self.bodies[c.body].size / self.scale) for c in self.angles]
        out.append((f"crank angle (link {self.bodies[self.crank].number})", self.bodies[self.crank].size / self.scale))
        return out


def _count_message(unknowns: int, equations: int, bodies: int) -> str:
    f = unknowns - (equations - 1)
    return (f"the mechanism has {f} degrees of freedom: {bodies} moving bodies have {unknowns} coordinates and "
            f"their joints give {equations - 1} constraint equations; a crank drives only a mechanism with one")


def build_model(m: Mechanism) -> Model:
    numbers = [k.number for k in m.links]
    if len(set(numbers)) != len(numbers):
        raise DegenerateInput("two links share a number")
    crank = next((k for k in m.links if k.number == m.crank), None)
    if crank is None:
        raise DegenerateInput(f"there is no link {m.crank} to drive")
    pivot = m.crank_pivot()
    bodies: list[Body] = []
    index: dict[int, int] = {}
    for k in m.links:
        if not (k.length > 0 and math.isfinite(k.length)):
            raise DegenerateInput(f"link {k.number} ({k.label}) must have a positive length, not {k.length!r}")
        local = {n: (p.x, p.y) for n, p in m.local(k.number).items()}
        index[k.number] = len(bodies)
        bodies.append(Body("link", k.number, MappingProxyType(local), max(math.hypot(*p) for p in local.values())))
    link_points = {n for b in bodies for n in b.local}
    names = set(m.ground) | link_points | {s.joint for s in m.slides}
    count: dict[str, int] = {}
    for s in m.slides:
        if s.joint in m.ground:
            raise DegenerateInput(f"slider joint {s.joint} is also a fixed pivot")
        count[s.joint] = count.get(s.joint, 0) + 1
        if count[s.joint] > 2:              # two: a joint carried along two lines (a PRP dyad)
            raise DegenerateInput(f"joint {s.joint} is carried by three sliders; a joint takes at most two")
        if s.on is not None:
            if s.on not in index:
                raise DegenerateInput(f"joint {s.joint} slides on link {s.on}, which does not exist")
            if s.joint in bodies[index[s.on]].local:
                raise DegenerateInput(f"joint {s.joint} cannot slide on link {s.on}, which it belongs to")
        if s.number is None and s.joint not in link_points:
            raise DegenerateInput(f"pin {s.joint} slides in a slot but no link carries it")
        if s.number is not None and s.number in index:
            raise DegenerateInput(f"block {s.number} has the number of a link")
    blocks = [s for s in m.slides if s.number is not None]
    if len({s.number for s in blocks}) != len(blocks):
        raise DegenerateInput("two slider blocks share a number")

    size = m.size
    extent = max([math.hypot(p.x, p.y) for p in m.ground.values()]
                 + [math.hypot(s.through.x, s.through.y) for s in m.slides if s.on is None] + [0.0])
    scale = max(size, extent)
    if not (scale > 0 and math.isfinite(scale)):
        raise DegenerateInput(f"the scene size must be a positive length, not {scale!r}")
    block_index: dict[int, int] = {}
    for s in blocks:
        block_index[s.number] = len(bodies)
        ell = bodies[index[s.on]].size if s.on is not None else scale
        bodies.append(Body("block", s.number, MappingProxyType({s.joint: (0.0, 0.0)}), ell))

    # which bodies carry each named point; the frame first, so a revolute pairs every body with it
    carriers: dict[str, list[tuple[int, tuple[float, float]]]] = {}
    for n, p in m.ground.items():
        carriers[n] = [(FRAME, (p.x, p.y))]
    for i, b in enumerate(bodies):
        for n, s in b.local.items():
            carriers.setdefault(n, []).append((i, s))
    revolutes = tuple(Revolute(n, cs[0], c) for n, cs in carriers.items() for c in cs[1:])

    lines: list[OnLine] = []
    angles: list[BlockAngle] = []
    coincident: dict[str, tuple[str, int]] = {}
    for s in m.slides:
        g = index[s.on] if s.on is not None else None
        if s.number is not None:
            carrier, at = block_index[s.number], (0.0, 0.0)
            where = f"block {s.number}"
        else:
            carrier, at = next((i, b.local[s.joint]) for i, b in enumerate(bodies) if s.joint in b.local)
            where = f"pin {s.joint}"
        line = f"the slot of link {s.on}" if s.on is not None else "its guide"
        lines.append(OnLine(s.joint, carrier, at, g, s.angle, s.offset if g is not None else 0.0,
                             (s.through.x, s.through.y), f"{s.joint} ({where}) on {line}"))
        if s.number is not None:
            angles.append(BlockAngle(carrier, g, s.angle, f"angle of block {s.number} ({line})"))
        if g is not None:
            # the name the construction gives the slotted link's point under the joint (A3), primed
            # while it clashes with a point of the mechanism
            coincident[coincident_name(s.joint, s.on, names)] = (s.joint, g)

    unknowns = 3 * len(bodies)
    equations = 2 * len(revolutes) + len(lines) + len(angles) + 1
    if unknowns != equations:
        raise DegenerateInput(_count_message(unknowns, equations, len(bodies)))
    return Model(tuple(bodies), MappingProxyType({n: tuple(c) for n, c in carriers.items()}), revolutes,
                  tuple(lines), tuple(angles), index[crank.number], 0.0 if crank.joints[0] == pivot else math.pi,
                  MappingProxyType(coincident), scale, unknowns, equations)


def constraint_count(m: Mechanism) -> tuple[int, int]:
    """(coordinates, equations including the driver) of ``m``; equal for a 1-DoF mechanism.  Raises
    DegenerateInput (with the count) when they differ or the data describe no mechanism."""
    model = build_model(m)
    return model.unknowns, model.equations

