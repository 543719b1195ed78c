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


# polygons, forces and geometry ------------------------------------------------------------------------
# The thresholds of the vector polygons, the force constructions and the check, each with why its value.

SINGULAR_SINE = 1e-4
"""Trial lines crossing at a sine below this mark a singular position (toggle, limit, change point).
The closest crossing a float figure can tell from a tangency (gap 1e-9 L) has a sine near 4.5e-5; the
conditioning of the measured values grows like 1/sine^2, so above 1e-4 they keep at least 7 digits."""

WARN_SINE = 1e-2
"""Below this sine a crossing's values are returned with a warning and an error estimate: they have lost
four of their digits (1/sine^2), still far more than a drawing shows, but the reader must know."""

DEAD_CENTRE_SINE = 1e-9
"""Crank and driven link closer to a line than this (sine of the angle between them) are at dead centre:
the decision tolerance (1e-9 L) as a sine, so a designed in-line position reads as one and a near one not."""

PARALLEL_SINE = 1e-9
"""Below this sine two lines of action are parallel and a force polygon cannot close on them: the same
size as the decision tolerance (1e-9 L), so lines that meet only beyond 1e9 L count as parallel."""

ROUNDING = 4.0 * 2.2e-16
"""Relative rounding of one crossing of well-conditioned trial lines (a few ulp); it grows as 1/sine^2."""

CONDITION_FLOOR = 1e-300
"""A condition (a sine) is never divided by below this: near the smallest normal float, so an exact zero
gives a huge, finite error estimate instead of a division by zero."""

CHANGE_POINT_REL = 1e-6
"""Joints within this fraction of the scene size of one line are a change point: far above the rounding of
positions assembled through a singular dyad (whose error grows as the square root of the gap)."""

NEGLIGIBLE = 1e-12
"""A value within this fraction of its own scale (the largest force, the scene size, the fastest velocity,
the moment it was taken from) is rounding, and zero: a few thousand ulp, above what the sums and products of
a construction leave and far below anything a drawing could show."""

DEAD_CENTRE_ARM = 1e-12
"""Below this arm (relative to the scene size) the crank's resultant passes through its pivot: a dead centre,
no torque.  Rounding-level only: a larger arm is a small torque the check still expects (an arm of 1e-9 of
the scene times a bearing force larger than the loads is a torque beyond the 1e-9 agreement)."""

CONDITION_SHARE = 0.5
"""Of the ways to draw a free body's construction, those conditioned at least this share of the best one
lose at most one binary digit, so among them the one that keeps its points nearest the body is drawn."""

SINGULAR_RCOND = 1e-10
"""Below this reciprocal condition number of the scaled equilibrium system the position is a toggle: two
unknown forces act along one line and the equations have no unique solution (above it the forces keep at
least five digits)."""

SIGN_SLACK = 1e-10
"""A normal force within this fraction of the largest unknown of the equilibrium system agrees with either
sign of its friction: far above the rounding of the scaled solve, far below any force a sheet shows."""

AGREEMENT = 1e-9
"""Graphical and analytic agree when they differ by less than this, relative to the reference value
(the largest measured value of the same kind), at well-conditioned positions."""

SAFETY = 64.0
"""Headroom over the rounding estimate when the tolerance widens near a singular position."""

EPSILON = 2.220446049250313e-16
"""The spacing of doubles at 1 (float64 machine epsilon): the unit of every rounding estimate."""

OTHER_ASSEMBLY = 1e-6
"""A Newton solution that moved a joint more than this fraction of the scene size from the construction's
position settled on another assembly: far above Newton's convergence (1e-12 L), far below a branch's gap."""
