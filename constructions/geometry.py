"""The geometry kernel: immutable points/vectors, lines, circles, segments and their intersections.

Intersections return a typed :class:`Intersection` with 0, 1 or 2 points, a three-way decision
(:class:`Contact`) taken with a :class:`Tolerance` relative to the scene size, and a condition measure:
the sine of the angle at which the two curves cross (1 = square, 0 = tangent or parallel).  The circle
routines compute the half-chord in a cancellation-free product form, so a designed tangency built from
rotated float coordinates reads as tangent and a near-tangency keeps its digits.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from enum import Enum

from .errors import DegenerateInput
from .tolerance import Tolerance

__all__ = ["Vec", "ORIGIN", "Tolerance", "Side", "Contact", "Line", "Circle", "Segment", "Intersection",
           "intersect_lines", "intersect_line_circle", "intersect_circles"]


@dataclass(frozen=True, slots=True)
class Vec:
    """A point or a free vector in the plane (model units, SI)."""

    x: float
    y: float

    @classmethod
    def polar(cls, length: float, angle: float) -> "Vec":
        return cls(length * math.cos(angle), length * math.sin(angle))

    def __add__(self, other: "Vec") -> "Vec":
        return Vec(self.x + other.x, self.y + other.y)

    def __sub__(self, other: "Vec") -> "Vec":
        return Vec(self.x - other.x, self.y - other.y)

    def __mul__(self, k: float) -> "Vec":
        return Vec(self.x * k, self.y * k)

    __rmul__ = __mul__

    def __truediv__(self, k: float) -> "Vec":
        return Vec(self.x / k, self.y / k)

    def __neg__(self) -> "Vec":
        return Vec(-self.x, -self.y)

    def dot(self, other: "Vec") -> float:
        return self.x * other.x + self.y * other.y

    def cross(self, other: "Vec") -> float:
        """z-component of self x other (positive when other is CCW of self)."""
        return self.x * other.y - self.y * other.x

    def norm(self) -> float:
        return math.hypot(self.x, self.y)

    def angle(self) -> float:
        """Direction, radians CCW from +x, in (-pi, pi]."""
        return math.atan2(self.y, self.x)

    def unit(self) -> "Vec":
        n = self.norm()
        if n == 0.0 or not math.isfinite(n):
            raise DegenerateInput("a zero-length vector has no direction")
        return Vec(self.x / n, self.y / n)

    def perp(self) -> "Vec":
        """This vector turned 90 deg counter-clockwise (k x self)."""
        return Vec(-self.y, self.x)

    def rotated(self, angle: float) -> "Vec":
        c, s = math.cos(angle), math.sin(angle)
        return Vec(c * self.x - s * self.y, s * self.x + c * self.y)

    def distance_to(self, other: "Vec") -> float:
        return math.hypot(self.x - other.x, self.y - other.y)

    def as_tuple(self) -> tuple[float, float]:
        return (self.x, self.y)


ORIGIN = Vec(0.0, 0.0)


class Side(Enum):
    LEFT = 1
    ON = 0
    RIGHT = -1


class Contact(Enum):
    """How two curves meet: the three-way decision of an intersection."""

    CROSSING = "crossing"
    TANGENT = "tangent"
    APART = "apart"
    PARALLEL = "parallel"
    COINCIDENT = "coincident"


@dataclass(frozen=True, slots=True)
class Line:
    """An infinite line through ``point`` along the unit vector ``direction``."""

    point: Vec
    direction: Vec

    def __post_init__(self) -> None:
        n = self.direction.norm()
        if not math.isfinite(n) or n == 0.0:
            raise DegenerateInput("a line needs a non-zero direction")
        if n != 1.0:
            object.__setattr__(self, "direction", self.direction / n)

    @classmethod
    def through(cls, p: Vec, q: Vec) -> "Line":
        if p == q:
            raise DegenerateInput("a line through two coincident points is undefined")
        return cls(p, q - p)

    @classmethod
    def at_angle(cls, p: Vec, angle: float) -> "Line":
        return cls(p, Vec(math.cos(angle), math.sin(angle)))

    def signed_distance(self, p: Vec) -> float:
        """Positive when ``p`` is to the left of the line's direction."""
        return self.direction.cross(p - self.point)

    def side_of(self, p: Vec, tol: Tolerance) -> Side:
        s = self.signed_distance(p)
        if abs(s) <= tol.length:
            return Side.ON
        return Side.LEFT if s > 0 else Side.RIGHT

    def foot(self, p: Vec) -> Vec:
        """Foot of the perpendicular from ``p``."""
        return self.point + self.direction * self.direction.dot(p - self.point)

    def parameter(self, p: Vec) -> float:
        """Signed distance along the line from ``point`` to the foot of ``p``."""
        return self.direction.dot(p - self.point)

    def at(self, t: float) -> Vec:
        return self.point + self.direction * t


@dataclass(frozen=True, slots=True)
class Circle:
    center: Vec
    radius: float

    def __post_init__(self) -> None:
        if not (self.radius > 0.0 and math.isfinite(self.radius)):
            raise DegenerateInput(f"a circle needs a positive radius, not {self.radius!r}")


@dataclass(frozen=True, slots=True)
class Segment:
    start: Vec
    end: Vec

    @property
    def vector(self) -> Vec:
        return self.end - self.start

    @property
    def length(self) -> float:
        return self.vector.norm()

    @property
    def midpoint(self) -> Vec:
        return (self.start + self.end) * 0.5


@dataclass(frozen=True, slots=True)
class Intersection:
    """The meeting of two curves.

    ``points`` holds 0, 1 or 2 points.  For two crossings of a circle the order is fixed and documented
    on each routine, so an assembly branch can pick one.  ``condition`` is the sine of the crossing
    angle (0 when tangent, parallel or apart).  ``gap`` is the signed clearance that was compared with
    the tolerance: positive means apart, zero tangent, negative overlapping (circles only; 0 for lines).
    """

    contact: Contact
    points: tuple[Vec, ...]
    condition: float
    gap: float = 0.0

    def __len__(self) -> int:
        return len(self.points)


def intersect_lines(a: Line, b: Line, tol: Tolerance) -> Intersection:
    """Intersection of two lines.

    The condition is the sine of the angle between them.  Below ``tol.sine`` the lines are parallel
    (no point) or coincident (no single point); the caller decides what that means for its method.
    """
    s = a.direction.cross(b.direction)
    if abs(s) <= tol.sine:
        apart = abs(a.signed_distance(b.point))
        contact = Contact.COINCIDENT if apart <= tol.length else Contact.PARALLEL
        return Intersection(contact, (), abs(s))
    t = (b.point - a.point).cross(b.direction) / s
    return Intersection(Contact.CROSSING, (a.at(t),), abs(s))


def intersect_line_circle(line: Line, circle: Circle, tol: Tolerance) -> Intersection:
    """Intersection of a line and a circle.

    Two crossings come ordered along the line's direction: first the one *ahead* of the foot of the
    centre, then the one *behind*.  The condition is the sine of the angle between the line and the
    circle at a crossing, h / r with h the half-chord.
    """
    foot = line.foot(circle.center)
    delta = abs(line.signed_distance(circle.center))
    r = circle.radius
    gap = delta - r
    if gap > tol.length:
        return Intersection(Contact.APART, (), 0.0, gap)
    if gap >= -tol.length:
        return Intersection(Contact.TANGENT, (foot,), 0.0, gap)
    h = math.sqrt((r - delta) * (r + delta))
    return Intersection(Contact.CROSSING, (foot + line.direction * h, foot - line.direction * h), h / r, gap)


def intersect_circles(c1: Circle, c2: Circle, tol: Tolerance) -> Intersection:
    """Intersection of two circles.

    Two crossings come ordered: first the one to the LEFT of the directed line from ``c1.center`` to
    ``c2.center``, then the one to the right.  The half-chord is computed from the product
    (r1+r2+d)(r1+r2-d)(d+r1-r2)(d-r1+r2), whose small factors are single differences of the inputs, so
    no digits are lost near tangency.  The condition is the sine of the crossing angle, d*h/(r1*r2).
    """
    axis = c2.center - c1.center
    d = axis.norm()
    r1, r2 = c1.radius, c2.radius
    if d <= tol.length:
        if abs(r1 - r2) <= tol.length:
            raise DegenerateInput("two coincident circles meet everywhere")
        return Intersection(Contact.APART, (), 0.0, abs(r1 - r2) - d)
    outer = d - (r1 + r2)          # > 0: each outside the other
    inner = abs(r1 - r2) - d       # > 0: one inside the other
    gap = max(outer, inner)
    u = axis / d
    if gap > tol.length:
        return Intersection(Contact.APART, (), 0.0, gap)
    # foot of the common chord on the axis, measured from c1: a = (d^2 + r1^2 - r2^2) / (2d)
    a = 0.5 * (d + (r1 - r2) * (r1 + r2) / d)
    if gap >= -tol.length:
        if outer >= inner:
            a = r1                                   # external tangency
        else:
            a = r1 if r1 > r2 else -r1               # internal tangency
        return Intersection(Contact.TANGENT, (c1.center + u * a,), 0.0, gap)
    product = (r1 + r2 + d) * (r1 + r2 - d) * (d + r1 - r2) * (d - r1 + r2)
    h = math.sqrt(max(product, 0.0)) / (2.0 * d)
    foot = c1.center + u * a
    n = u.perp()
    return Intersection(Contact.CROSSING, (foot + n * h, foot - n * h), d * h / (r1 * r2), gap)


def sqrt_nonneg(x: float) -> float:
    """The square root of a computed quantity that is >= 0 by the geometry (r_a^2 - r_b^2, a tangent's
    length) but may come out a rounding below 0 at its limit (a contact on the base circle): 0 there, not a
    math domain error.  A value far below 0 is an input the readers refuse before it gets here."""
    return math.sqrt(x) if x > 0.0 else 0.0


def acos_clamped(c: float) -> float:
    """acos of a cosine computed from lengths, which rounding may push a hair past +-1 at a limit."""
    return math.acos(1.0 if c > 1.0 else -1.0 if c < -1.0 else c)


def asin_clamped(s: float) -> float:
    """asin of a sine computed from lengths, which rounding may push a hair past +-1 at a limit."""
    return math.asin(1.0 if s > 1.0 else -1.0 if s < -1.0 else s)
