"""Planets counted: n planets spaced equally round the carrier of a simple planetary train (sun S, planet
P, ring R), as the notes state the two conditions a designer checks before the speeds:

    assembly     (N_S + N_R) / n a whole number: the teeth of sun and ring line up again for the next
                 planet after turning the carrier 360/n deg (equal spacing)
    neighbours   2 (r_S + r_P) sin(pi/n) > d_aP = 2 (r_P + a): the distance between two neighbouring
                 planets' centres exceeds a planet's tip diameter, so their teeth do not touch

and each planet carries 1/n of the tangential load (equal sharing, the usual assumption: with more than
one planet the split is statically indeterminate).  Concentricity, N_R = N_S + 2 N_P, is checked on the
layout (:func:`constructions.gears.trains.layout`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from .trains import FRAME, Train, TrainGear


@dataclass(frozen=True)
class PlanetCheck:
    planets: int
    sun: TrainGear
    planet: TrainGear
    ring: TrainGear | None
    assembly_value: float | None      # (N_S + N_R)/n, None without a ring
    centre_spacing: float             # 2 (r_S + r_P) sin(pi/n): between neighbouring planets' centres
    tip_diameter: float               # d_aP = 2 (r_P + a)

    @property
    def assembles(self) -> bool:
        return self.assembly_value is None or abs(self.assembly_value - round(self.assembly_value)) < 1e-9

    @property
    def clear(self) -> bool:
        return self.planets == 1 or self.centre_spacing > self.tip_diameter

    @property
    def clearance(self) -> float:
        """Centre spacing less the tip diameter: the gap between two neighbouring planets' tips."""
        return self.centre_spacing - self.tip_diameter


def simple_planetary(train: Train) -> tuple[TrainGear, TrainGear, TrainGear | None] | None:
    """(sun, planet, ring) when the train is a simple planetary one (one planet gear meshing a central
    external gear, and perhaps an internal one); None otherwise."""
    carried = [g for g in train.gears if g.carrier != FRAME]
    if len(carried) != 1:
        return None
    planet = carried[0]
    partners = [train.gear(m.b if m.a == planet.name else m.a) for m in train.meshes
                if planet.name in (m.a, m.b)]
    suns = [g for g in partners if not g.internal]
    rings = [g for g in partners if g.internal]
    if len(suns) != 1 or len(rings) > 1:
        return None
    return suns[0], planet, rings[0] if rings else None


def check_planets(train: Train) -> PlanetCheck | None:
    """The assembly and neighbour conditions of the train's ``planets`` (None unless simple planetary)."""
    spr = simple_planetary(train)
    if spr is None:
        return None
    sun, planet, ring = spr
    n = train.planets
    r_s, r_p = train.radius(sun), train.radius(planet)
    value = (sun.teeth + ring.teeth) / n if ring is not None else None
    spacing = 2.0 * (r_s + r_p) * math.sin(math.pi / n) if n > 1 else math.inf
    return PlanetCheck(n, sun, planet, ring, value, spacing, 2.0 * (r_p + train.addendum * train.module))


def assembling_counts(n_sun: int, n_ring: int, most: int = 12) -> list[int]:
    """The planet counts from 2 to ``most`` for which (N_S + N_R)/n is whole."""
    return [n for n in range(2, most + 1) if (n_sun + n_ring) % n == 0]


def planet_refusal(train: Train) -> str | None:
    """One sentence saying why the train's planets cannot be built (None when they can)."""
    if train.planets == 1:
        return None
    pc = check_planets(train)
    if pc is None:
        return (f"{train.planets} planets need a simple planetary train (one planet gear meshing a sun and "
                f"perhaps a ring); give planets = 1 for this one")
    if not pc.assembles:
        ok = assembling_counts(pc.sun.teeth, pc.ring.teeth)
        return (f"{pc.planets} planets cannot be spaced equally: (N_S + N_R)/n = ({pc.sun.teeth} + "
                f"{pc.ring.teeth})/{pc.planets} = {pc.assembly_value:.4g} is not a whole number"
                + (f" (these teeth take {', '.join(map(str, ok))} planets)" if ok else ""))
    if not pc.clear:
        return (f"{pc.planets} planets touch: neighbouring centres 2 (r_S + r_P) sin(180/n deg) = "
                f"{pc.centre_spacing * 1000:.4g} mm apart, less than a planet's tip diameter "
                f"{pc.tip_diameter * 1000:.4g} mm")
    return None
