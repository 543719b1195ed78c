"""Tooth numbers from a wanted speed ratio: a small search, as the notes set the problem.

A simple planetary train (sun S, planets P on carrier C, ring R), one member held, one driven, one the
output: the ring must be concentric with the sun, N_R = N_S + 2 N_P (one module); with n planets, the
assembly condition (N_S + N_R)/n whole and neighbouring planets clear (:mod:`constructions.gears.planets`).
The speeds follow the notes' formula (n_R - n_C)/(n_S - n_C) = -N_S/N_R.

A reverted (compound, concentric) double-stage train 1-2, 3-4 (gears 2 and 3 on the countershaft): the
ratio n_1/n_4 = (N_2 N_4)/(N_1 N_3), the output coaxial with the input, N_1 + N_2 = N_3 + N_4 (both stages
of one module).

Both searches run every candidate from ``least`` to ``most`` teeth and return the closest ones first
(then the smallest), within a relative ``tolerance`` of the wanted ratio.  A scene then draws and checks
the chosen teeth (``kind = "gear train"``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..errors import ConstructionError


@dataclass(frozen=True)
class PlanetaryTeeth:
    sun: int
    planet: int
    ring: int
    planets: int
    ratio: float          # n_driven / n_output, signed, with these teeth
    error: float          # relative to the wanted ratio


@dataclass(frozen=True)
class RevertedTeeth:
    teeth: tuple[int, int, int, int]     # N_1, N_2 (first stage), N_3, N_4 (second stage)
    ratio: float                         # n_1 / n_4
    error: float


MEMBERS = ("S", "R", "C")


def planetary_ratio(sun: int, ring: int, held: str, driven: str, output: str) -> float:
    """n_driven / n_output with ``held`` fixed, by the notes' formula (members "S", "R", "C")."""
    e = {"S": 1.0, "R": -sun / ring, "C": 0.0}          # speed relative to the carrier, per unit of the sun's
    # n_m = n_c + e_m x; n_held = 0 fixes n_c = -e_held x
    speed = {m: e[m] - e[held] for m in MEMBERS}
    return speed[driven] / speed[output]


def planetary_teeth(ratio: float, held: str = "R", driven: str = "S", output: str = "C", planets: int = 1,
                    least: int = 17, most: int = 150, tolerance: float = 0.01, addendum: float = 1.0,
                    count: int = 10) -> list[PlanetaryTeeth]:
    """Sun, planet and ring teeth giving n_driven/n_output = ``ratio`` (signed: with the carrier held the
    sun and ring turn opposite ways), every gear from ``least`` to ``most`` teeth, the ring concentric,
    ``planets`` of them assembling and clearing (``addendum`` in modules)."""
    if sorted((held, driven, output)) != sorted(MEMBERS):
        raise ConstructionError(f"held, driven and output must be the sun S, the ring R and the carrier C, one "
                                f"each (not {held}, {driven}, {output})")
    if ratio == 0 or not math.isfinite(ratio):
        raise ConstructionError(f"the wanted ratio {ratio} must be a finite number other than zero")
    found = []
    for ns in range(least, most + 1):
        for np_ in range(least, (most - ns) // 2 + 1):
            nr = ns + 2 * np_
            if planets > 1 and ((ns + nr) % planets or (ns + np_) * math.sin(math.pi / planets) <= np_ + 2 * addendum):
                continue
            got = planetary_ratio(ns, nr, held, driven, output)
            err = (got - ratio) / ratio
            if abs(err) <= tolerance:
                found.append(PlanetaryTeeth(ns, np_, nr, planets, got, err))
    if not found:
        raise ConstructionError(f"no sun, planet and ring from {least} to {most} teeth give {ratio:g} within "
                                f"{tolerance:.0%} ({driven} driven, {held} held, {output} out"
                                + (f", {planets} planets assembling and clearing)" if planets > 1 else ")"))
    found.sort(key=lambda c: (round(abs(c.error), 12), c.ring, c.sun))
    return found[:count]


def reverted_teeth(ratio: float, least: int = 17, most: int = 150, tolerance: float = 0.01,
                   count: int = 10) -> list[RevertedTeeth]:
    """N_1..N_4 of a reverted double-stage train with n_1/n_4 = ``ratio`` (> 0; above 1 a reducer),
    N_1 + N_2 = N_3 + N_4, every gear from ``least`` to ``most`` teeth."""
    if not (ratio > 0 and math.isfinite(ratio)):
        raise ConstructionError(f"the wanted ratio {ratio} must be a positive number (n_1/n_4)")
    found: dict[tuple[int, int, int, int], RevertedTeeth] = {}
    for total in range(2 * least, 2 * most + 1):
        for n1 in range(least, min(most, total - least) + 1):
            n2 = total - n1
            if n2 > most:
                continue
            # the second stage must give ratio / (n2/n1) = n4/n3 with n3 + n4 = total
            k = ratio * n1 / n2
            guess = total / (1.0 + k)
            for n3 in {math.floor(guess), math.ceil(guess)}:
                n4 = total - n3
                if not (least <= n3 <= most and least <= n4 <= most):
                    continue
                got = n2 * n4 / (n1 * n3)
                err = (got - ratio) / ratio
                if abs(err) <= tolerance:
                    found[(n1, n2, n3, n4)] = RevertedTeeth((n1, n2, n3, n4), got, err)
    if not found:
        raise ConstructionError(f"no reverted train with gears from {least} to {most} teeth gives {ratio:g} within "
                                f"{tolerance:.0%}")
    return sorted(found.values(), key=lambda c: (round(abs(c.error), 12), c.teeth[0] + c.teeth[1], c.teeth))[:count]
