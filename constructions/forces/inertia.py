"""Mass moments of inertia of plane bodies about their centre of mass, the parallel-axis theorem and
composite bodies.  Pure functions, SI (kg, m, kg m^2); every moment is about the axis square to the
plane of motion.

Each shape is derived from I_G = integral of r^2 dm over the body (the tests integrate the shapes
numerically rather than restating these results):

- slender rod of length L:               I_G = m L^2 / 12
- disc (or cylinder) of radius r:        I_G = m r^2 / 2
- rectangular plate a x b:               I_G = m (a^2 + b^2) / 12
- ring (annulus) of radii r1, r2:        I_G = m (r1^2 + r2^2) / 2
- thin ring of radius r:                 I_G = m r^2
- semicircular plate of radius r:        I_G = m r^2 (1/2 - 16 / (9 pi^2)) ~= 0.3199 m r^2

The course notes swap the semicircular plate's two formulas.  About O, the centre of the full circle
(the middle of the straight edge), every half of a disc has the disc's I_O = m r^2 / 2, with the mass
halved: I_O = m r^2 / 2.  The centre of mass G lies h = 4 r / (3 pi) from O on the axis of symmetry, so
by the parallel-axis theorem I_G = I_O - m h^2 = m r^2 (1/2 - 16 / (9 pi^2)).  The notes write
I_G = m r^2 / 2 and I_O = m r^2 / 2 - m h^2, which would make the moment about the centre of mass the
larger one -- impossible, since I about G is the least of all parallel axes.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Iterable

from ..geometry import Vec
from ..tolerance import NEGLIGIBLE


def _check(mass: float, **dims: float) -> None:
    for name, v in {"mass": mass, **dims}.items():
        if not math.isfinite(v) or v < 0:
            raise ValueError(f"the {name.replace('_', ' ')} must be a finite number, not negative ({v!r})")


def rod(mass: float, length: float) -> float:
    """A slender rod of ``length`` about its middle: m L^2 / 12."""
    _check(mass, length=length)
    return mass * length**2 / 12.0


def disc(mass: float, radius: float) -> float:
    """A solid disc or cylinder about its axis: m r^2 / 2."""
    _check(mass, radius=radius)
    return mass * radius**2 / 2.0


def plate(mass: float, width: float, height: float) -> float:
    """A rectangular plate ``width`` x ``height`` about its centre: m (a^2 + b^2) / 12."""
    _check(mass, width=width, height=height)
    return mass * (width**2 + height**2) / 12.0


def ring(mass: float, inner_radius: float, outer_radius: float) -> float:
    """An annulus (a thick ring, or a hollow cylinder) about its axis: m (r1^2 + r2^2) / 2."""
    _check(mass, inner_radius=inner_radius, outer_radius=outer_radius)
    if inner_radius > outer_radius:
        raise ValueError(f"the inner radius {inner_radius!r} is larger than the outer radius {outer_radius!r}")
    return mass * (inner_radius**2 + outer_radius**2) / 2.0


def thin_ring(mass: float, radius: float) -> float:
    """A thin ring (all its mass at ``radius``) about its axis: m r^2."""
    _check(mass, radius=radius)
    return mass * radius**2


def semicircle_centroid(radius: float) -> float:
    """h = 4 r / (3 pi): how far the centre of mass of a semicircular plate lies from the middle of its
    straight edge (the centre of the full circle)."""
    _check(0.0, radius=radius)
    return 4.0 * radius / (3.0 * math.pi)


def semicircular_plate(mass: float, radius: float) -> float:
    """A semicircular plate about its centre of mass (not about the centre of the full circle, where it is
    m r^2 / 2): m r^2 (1/2 - 16 / (9 pi^2)).  See the module's note on the course notes' formulas."""
    _check(mass, radius=radius)
    return about_centre(disc(mass, radius), mass, semicircle_centroid(radius))


def about_point(inertia_centre: float, mass: float, distance: float) -> float:
    """The parallel-axis theorem: the moment about a point ``distance`` from the centre of mass,
    I_A = I_G + m d^2."""
    _check(mass, inertia=inertia_centre, distance=abs(distance))
    return inertia_centre + mass * distance**2


def about_centre(inertia_point: float, mass: float, distance: float) -> float:
    """The parallel-axis theorem the other way: the moment about the centre of mass from the moment about
    a point ``distance`` from it, I_G = I_A - m d^2.  Raises ValueError when that is negative (I_A is
    smaller than m d^2: no body of that mass has its centre that far from A); a shortfall within
    :data:`~constructions.tolerance.NEGLIGIBLE` of I_A is rounding and gives zero (a point mass given as
    I_A = m d^2 in rounded decimals)."""
    _check(mass, inertia=inertia_point, distance=abs(distance))
    out = inertia_point - mass * distance**2
    if out < 0:
        if -out <= NEGLIGIBLE * max(inertia_point, mass * distance**2):
            return 0.0
        raise ValueError(f"I_A = {inertia_point:.6g} kg m^2 is less than m d^2 = {mass * distance**2:.6g} "
                         f"kg m^2, so the moment about the centre of mass would be negative")
    return out


@dataclass(frozen=True, slots=True)
class Body:
    """A rigid body's mass (kg), centre of mass (m) and moment of inertia about that centre (kg m^2)."""

    mass: float
    centre: Vec
    inertia: float

    def about(self, point: Vec) -> float:
        """The moment of inertia about ``point`` (parallel-axis theorem)."""
        return about_point(self.inertia, self.mass, (point - self.centre).norm())


def composite(parts: Iterable[Body]) -> Body:
    """Parts fixed together as one body: the total mass, the mass-weighted centre, and the sum of every
    part's moment about that common centre (each moved there by the parallel-axis theorem)."""
    parts = tuple(parts)
    if not parts:
        raise ValueError("a composite body needs at least one part")
    mass = math.fsum(p.mass for p in parts)
    if not mass > 0:
        raise ValueError("a composite body needs a positive total mass")
    centre = Vec(math.fsum(p.mass * p.centre.x for p in parts) / mass,
                 math.fsum(p.mass * p.centre.y for p in parts) / mass)
    return Body(mass, centre, math.fsum(p.about(centre) for p in parts))


SHAPES: dict[str, tuple[str, ...]] = {
    "rod": ("length",),
    "disc": ("radius",),
    "plate": ("width", "height"),
    "ring": ("inner_radius", "outer_radius"),
    "thin ring": ("radius",),
    "semicircular plate": ("radius",),
}
"""Each shape a scene may name and the dimensions it needs, in the order :func:`shape_inertia` takes
them."""

_FUNCTIONS = {"rod": rod, "disc": disc, "plate": plate, "ring": ring, "thin ring": thin_ring,
              "semicircular plate": semicircular_plate}


def shape_inertia(shape: str, mass: float, *dimensions: float) -> float:
    """The moment about the centre of mass of a named shape (:data:`SHAPES`) with its dimensions."""
    try:
        f = _FUNCTIONS[shape]
    except KeyError:
        raise ValueError(f"{shape!r} is not a shape; choose from {', '.join(SHAPES)}") from None
    if len(dimensions) != len(SHAPES[shape]):
        raise ValueError(f"a {shape} needs {', '.join(SHAPES[shape])}")
    return f(mass, *dimensions)
