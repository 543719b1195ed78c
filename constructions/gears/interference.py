"""Interference limits of involute pinions at the standard centre distance: closed forms, and a
brute-force search over tooth numbers that decides every case from the construction itself.

Derivation (module m cancels; k the addendum constant, s = sin phi).  The gear's tip reaches the
pinion's interference point T1 when r_a2 = O2T1, i.e. (N2 + 2k)^2 = N2^2 cos^2 phi + (N1 + N2)^2 s^2:

    with a gear of N2 teeth:   N1 >= sqrt(N2^2 + 4k (N2 + k) / s^2) - N2
    with an equal gear:        N  >= 2k (1 + sqrt(1 + 3 s^2)) / (3 s^2)
    with a rack (N2 -> inf):   N1 >= 2k / s^2                             (the notes' formula)
    the largest gear a pinion N1 < 2k/s^2 takes:  N2 <= (N1^2 s^2 - 4k^2) / (4k - 2 N1 s^2)

(the pinion's tip against T2 is never the tighter one while N1 <= N2).  Each is compared with a
tolerance of 1e-9 relative (WHOLE_REL), so a case exactly at the limit counts as free of interference, as the
construction decides it ("at the limit").
"""

from __future__ import annotations

import math

from ..tolerance import WHOLE_REL
from .contact import AT_LIMIT, CLEAR, INTERFERENCE, Pair, contact_geometry
from .tooth import Gear, ToothSystem


def _ceil(x: float) -> int:
    """The least whole number >= x, treating x within WHOLE_REL of a whole number as that number."""
    n = round(x)
    return n if abs(x - n) <= WHOLE_REL * max(1.0, abs(x)) else math.ceil(x)


def _floor(x: float) -> int:
    n = round(x)
    return n if abs(x - n) <= WHOLE_REL * max(1.0, abs(x)) else math.floor(x)


def min_pinion_with_rack(phi: float, k: float = 1.0) -> int:
    return _ceil(2 * k / math.sin(phi) ** 2)


def min_pinion_with_gear(n_gear: int, phi: float, k: float = 1.0) -> int:
    s2 = math.sin(phi) ** 2
    return _ceil(math.sqrt(n_gear ** 2 + 4 * k * (n_gear + k) / s2) - n_gear)


def min_equal_gears(phi: float, k: float = 1.0) -> int:
    s2 = math.sin(phi) ** 2
    return _ceil(2 * k * (1 + math.sqrt(1 + 3 * s2)) / (3 * s2))


def max_gear_for_pinion(n_pinion: int, phi: float, k: float = 1.0) -> int | None:
    """The largest gear the pinion meshes with free of interference; None when any gear (a rack) will do;
    0 when none will (not even an equal gear)."""
    s2 = math.sin(phi) ** 2
    den = 4 * k - 2 * n_pinion * s2
    if den <= WHOLE_REL * 4 * k:
        return None
    top = _floor((n_pinion ** 2 * s2 - 4 * k * k) / den)
    return top if top >= n_pinion else 0


# -- brute force: the construction decides each tooth number ---------------------------------------------

def interferes(n1: int, n2: int | None, phi: float, k: float = 1.0, kd: float = 1.25) -> bool:
    """Whether the pair (or pinion and rack when n2 is None) interferes, decided by the construction."""
    s = ToothSystem(1.0, phi, k, max(kd, k))
    pair = Pair(Gear(n1, s), None if n2 is None else Gear(n2, s))
    geo, _ = contact_geometry(pair)
    return geo.verdict == INTERFERENCE


def search_min_pinion(n2: int | None, phi: float, k: float = 1.0, upper: int = 200) -> int:
    """The least pinion (3 ..) that meshes with the gear n2 (None: a rack) free of interference, by trying
    every tooth number; with a gear, only pinions up to the gear's size are pinions."""
    top = upper if n2 is None else n2
    for n1 in range(3, top + 1):
        if not interferes(n1, n2, phi, k):
            return n1
    raise ValueError(f"no pinion up to {top} teeth meshes without interference")


def search_max_gear(n1: int, phi: float, k: float = 1.0, upper: int = 5000) -> int | None:
    """The largest gear (>= n1) the pinion n1 meshes with free of interference, by bisection over the
    construction's verdicts (interference only grows with the gear); None if even ``upper`` is free."""
    if not interferes(n1, None, phi, k):
        return None
    if interferes(n1, n1, phi, k):
        return 0
    lo, hi = n1, upper
    if not interferes(n1, hi, phi, k):
        return None
    while hi - lo > 1:
        mid = (lo + hi) // 2
        if interferes(n1, mid, phi, k):
            hi = mid
        else:
            lo = mid
    return lo


def minimum_teeth_table(angles_deg=(14.5, 20.0, 25.0), systems=(("full depth", 1.0), ("stub", 0.8))):
    """Rows of (pressure angle deg, system, min pinion with a rack, with an equal gear) by the closed forms."""
    rows = []
    for a in angles_deg:
        phi = math.radians(a)
        for name, k in systems:
            rows.append((a, name, min_pinion_with_rack(phi, k), min_equal_gears(phi, k)))
    return rows


__all__ = ["CLEAR", "AT_LIMIT", "INTERFERENCE", "min_pinion_with_rack", "min_pinion_with_gear", "min_equal_gears",
           "max_gear_for_pinion", "interferes", "search_min_pinion", "search_max_gear", "minimum_teeth_table"]
