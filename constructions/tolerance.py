"""The one place the engine's tolerances and its scene size are defined.

Every decision is three-way (left/right/on, crossing/tangent/apart, solvable/at a toggle) with a
tolerance relative to ONE scene size L.  L is the largest of the lengths that define the scene -- link
lengths, distances of points on a link, slot offsets, distances between fixed pivots, distances of
fixed pivots from fixed guides -- none of which moves with the origin or with the point a guide is given
through: a mechanism translated, rotated or given its guide through another point takes the same
decisions, and one scaled by any factor takes them at the same relative size.

* :data:`DECISION` (1e-9 L): the construction's kernel -- lengths closer than this are equal.
* :data:`ASSEMBLY_RTOL` (64 ulp of L): the vectorised analytic checks snap a gap factor this close to
  zero to an exact tangency (rounding noise at a designed toggle); :func:`snap_tolerance` adds the
  floating-point floor of coordinates far from the origin (they carry eps |x| of rounding whatever L
  is) -- the only way the origin enters, and it is arithmetic, not the size of the scene.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Iterable

from .errors import DegenerateInput

DECISION = 1e-9
"""Lengths closer than DECISION * L are equal (the construction's decisions)."""

ASSEMBLY_RTOL = 64 * 2.220446049250313e-16
"""Gap factors within ASSEMBLY_RTOL * L of zero are a tangency in the vectorised analytic checks."""

Point = tuple[float, float]


def scene_size(lengths: Iterable[float], points: Iterable[Point] = (),
               lines: Iterable[tuple[Point, float]] = ()) -> float:
    """L: the largest of ``lengths``, of the distances between ``points`` and of the distances of
    ``points`` from ``lines`` (each a point it passes through and its angle).  Raises DegenerateInput when
    that is not a positive finite length."""
    pts = [(float(x), float(y)) for x, y in points]
    spans = [abs(float(v)) for v in lengths]
    spans += [math.hypot(p[0] - q[0], p[1] - q[1]) for i, p in enumerate(pts) for q in pts[i + 1:]]
    for (gx, gy), angle in lines:
        nx, ny = -math.sin(angle), math.cos(angle)
        spans += [abs((x - gx) * nx + (y - gy) * ny) for x, y in pts]
    size = max(spans, default=0.0)
    if not (size > 0.0 and math.isfinite(size)):
        raise DegenerateInput(f"the scene has no positive finite size (largest length {size!r})")
    return size


def snap_tolerance(size: float, far: float = 0.0) -> float:
    """The band within which a gap factor of the analytic checks is a tangency: 64 ulp of the scene size,
    plus 64 ulp of ``far``, the largest coordinate magnitude (the rounding its inputs already carry)."""
    return ASSEMBLY_RTOL * (size + far)


@dataclass(frozen=True, slots=True)
class Tolerance:
    """Decision tolerances relative to the scene size.

    ``length_scale`` is the size L of the figure (the scene size, or the known vector in a polygon).
    Lengths closer than ``rel * L`` are the same length; lines whose directions differ by a sine below
    ``sine`` are parallel.  Scaling a figure and its L by any factor leaves every decision unchanged.
    """

    length_scale: float
    rel: float = DECISION
    sine: float = 1e-9

    def __post_init__(self) -> None:
        if not (self.length_scale > 0.0 and math.isfinite(self.length_scale)):
            raise DegenerateInput(f"the scene size must be a positive length, not {self.length_scale!r}")

    @property
    def length(self) -> float:
        return self.rel * self.length_scale
