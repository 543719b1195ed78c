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


# cams and gears -----------------------------------------------------------------------------------------------

CUSP_REL = DECISION
"""A cam's roller radius is *at* the cusp limit (a face's smallest radius of curvature at zero) within this
fraction of the cam's size: a designed tangency built from floats reads as equal, as every length decision."""

TURN_REL = 1e-9
"""A motion program's segment angles cover one turn when their sum is within this fraction of 360 deg: angles
typed to nine digits add up within it, a missing second of arc (5e-6 rad) does not."""

CLOSING_REL = 1e-9
"""A motion program is back at zero lift when it ends within this fraction of its largest lift (and never
below zero by more): lifts written in millimetres to nine digits close within it."""

START_SNAP = 1e-12
"""A cam angle within this fraction of a turn below a segment's start belongs to that segment: a station
built as k equal steps carries a few ulp (3e-14 rad) of rounding, far less than any step."""

JOIN_JUMP_REL = 1e-9
"""A derivative of the follower's motion jumps at a join when it changes by more than this fraction of its
scale (the lift over the shortest segment's angle to its power): exact laws meet within rounding, 1e-16."""

VELOCITY_JUMP_REL = 1e-9
"""s' jumps at a join (a corner of the pitch curve, which the analysis trims at) when its one-sided values,
computed exactly from the laws' end slopes, differ by more than this fraction of the lift per radian."""

CORNER_SLOPE_REL = 1e-12
"""The profile-only sampling keeps both one-sided points at a join where s' differs by more than this
fraction of the lift per radian: exact end slopes are equal to the bit where s' is continuous."""

FACE_TURN_MIN = 1e-9
"""An oscillating flat face must turn against the cam at more than this fraction of the cam's rate (sigma +
s'): nearer to standing still, the contact's place along the face (a ratio over it) is rounding noise."""

SPAN_END_RAD = 1e-15
"""The ends of a span along the cam angle are cut to this many radians: a few ulp of a turn (the spacing of
floats near 2 pi is 9e-16), past which the cam angle has no more bits."""

SPAN_JOIN_RAD = 1e-12
"""Spans along the cam angle whose ends lie closer than this (in radians) are one span, and one that reaches
both 0 and 2 pi within it wraps round: far above the ends' precision, far below any grid step."""

ONE_SIDED_INSET = 1e-9
"""A law's piece is read this fraction of its width inside its ends, so that each end takes the piece's own
one-sided value (at the end itself the neighbouring piece's formula would be read)."""

SVAJ_JUMP_REL = 1e-9
"""The s, v, a, j charts break their curve at a join where the value jumps by more than this fraction of the
curve's largest magnitude (plus one): a continuous law's pieces meet within rounding."""

STATION_REL = 1e-9
"""A join of the program falls on a station of the cam's construction when it lies within this fraction of
a station step of one: segments typed in whole degrees meet the divisions within rounding."""

CHORD_MARGIN = 1.05
"""The largest chord-error rate found on a piece's grid is raised by this factor before its step is chosen:
the grid's best point, refined by a parabola, may still fall a few per cent short of the true largest."""

UNDERCUT_REL = 1e-12
"""A rack cutter's straight flank undercuts a gear when it reaches past the interference point by more than
this many modules: a gear of exactly the limiting number of teeth (a designed limit) reads as not undercut."""

ROOT_BITS = 2e-16
"""The bisections along a rack cutter's roll run until the bracket is this fraction of the angle (one ulp,
at least of 1 rad): the fillet's crossing with the involute to the last bits."""

WHOLE_REL = 1e-9
"""A tooth count from a closed form within this fraction of a whole number is that number (relative to the
count, at least 1): a case exactly at the interference limit counts as free, as the tables do."""

TRAIN_RATIO_REL = 1e-12
"""Speed ratios in a gear train (pure numbers, mostly of order 1) that differ by less than this are the same
(a loop of meshes: this fraction of a ratio above 1): ratios of whole teeth agree to rounding, a lock by far more."""

STANDSTILL = 1e-12
"""A member of a gear train whose speed is below this (rad/s) stands still: no torque follows from a power
there, and no sense of rotation is drawn for it."""

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

COSINE_SLACK = 1e-12
"""A cosine computed from lengths (the law of cosines) that lies outside [-1, 1] by no more than this is
rounding at an extreme (a change point, links in line) and is clamped to it; farther out the triangle does
not close.  Rounding of the squared lengths leaves a few ulp, 1e-15, at every scale."""

