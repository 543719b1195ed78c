"""The closed forms' inputs, checked once: link lengths, pivots, guide and branch of a four-bar or a
slider-crank with the constants derived from them (the one scene size and its snapping tolerance among
them), and the crank angles broadcast against the crank's rates.

The independent oracle (:mod:`constructions.analytic`) and the sweep's fast kernels
(:mod:`constructions.sweep_kernels`) read their mechanism from here, so both refuse the same inputs and
decide tangency with the same tolerance.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..tolerance import scene_size, snap_tolerance

__all__ = ["FourBarLinks", "SliderCrankLinks", "angles", "four_bar_links", "point_on_link", "slider_crank_links"]


def _length(name: str, value) -> float:
    v = float(value)
    if not (math.isfinite(v) and v > 0.0):
        raise ValueError(f"{name} must be a positive finite length, got {value!r}")
    return v


def _point(name: str, value) -> tuple[float, float]:
    try:
        x, y = (float(c) for c in value)
    except (TypeError, ValueError):
        raise ValueError(f"{name} must be a pair (x, y), got {value!r}") from None
    if not (math.isfinite(x) and math.isfinite(y)):
        raise ValueError(f"{name} must be finite, got {value!r}")
    return x, y


def _branch(value) -> float:
    if value not in (1, -1):
        raise ValueError(f"branch must be +1 or -1, got {value!r}")
    return float(value)


def angles(theta1, omega1, alpha1):
    """Broadcast theta1, omega1 and alpha1; return flat theta, omega and alpha (each a float if it
    was given as a scalar, else a flat array) and the shape."""
    th = np.asarray(theta1, dtype=np.float64)
    w = np.asarray(omega1, dtype=np.float64)
    a = np.asarray(alpha1, dtype=np.float64)
    shape = np.broadcast_shapes(th.shape, w.shape, a.shape)
    if th.shape != shape:
        th = np.broadcast_to(th, shape)
    th = np.ascontiguousarray(th).reshape(-1)

    def flat(v):
        if v.ndim == 0:
            return float(v)
        return np.ascontiguousarray(np.broadcast_to(v, shape)).reshape(-1)
    return th, flat(w), flat(a), shape


@dataclass(frozen=True)
class FourBarLinks:
    """A four-bar O1-B-C-O2 (SI): pivots, link lengths, branch (+-1.0), the snapping tolerance ``tol``
    and the constants of the circle-circle intersection (see :func:`constructions.analytic.four_bar`)."""

    o1x: float
    o1y: float
    o2x: float
    o2y: float
    r1: float
    r2: float
    r3: float
    branch: float
    tol: float
    S: float            # coupler + rocker
    T: float            # |coupler - rocker|
    K: float            # coupler^2 - rocker^2, without the cancellation of squaring
    check_d0: bool      # T <= tol: only then can B on O2 (d = 0) pass the gap test

    @property
    def inv_2r2r3(self) -> float:
        return 1.0 / (2.0 * self.r2 * self.r3)

    @property
    def half_sumsq(self) -> float:
        """(coupler^2 + rocker^2) / 2, so that p . q = half_sumsq - d^2 / 2."""
        return 0.5 * (self.r2 * self.r2 + self.r3 * self.r3)


def four_bar_links(crank_pivot, rocker_pivot, crank, coupler, rocker, branch) -> FourBarLinks:
    """The checked four-bar; ValueError names the first input that is not a mechanism."""
    o1x, o1y = _point("crank_pivot", crank_pivot)
    o2x, o2y = _point("rocker_pivot", rocker_pivot)
    r1 = _length("crank", crank)
    r2 = _length("coupler", coupler)
    r3 = _length("rocker", rocker)
    br = _branch(branch)
    scale = scene_size((r1, r2, r3), ((o1x, o1y), (o2x, o2y)))   # the one scene size
    tol = snap_tolerance(scale, max(abs(o1x), abs(o1y), abs(o2x), abs(o2y)))
    T = abs(r2 - r3)
    return FourBarLinks(o1x, o1y, o2x, o2y, r1, r2, r3, br, tol, r2 + r3, T, (r2 - r3) * (r2 + r3), T <= tol)


@dataclass(frozen=True)
class SliderCrankLinks:
    """An (offset) slider-crank O1-B-C (SI): crank pivot, lengths, branch (+-1.0), the snapping tolerance,
    the guide direction e = (ex, ey) and its normal n = (nx, ny), and the signed distance y0 of O1 from
    the guide (see :func:`constructions.analytic.slider_crank`)."""

    o1x: float
    o1y: float
    r1: float
    l: float
    branch: float
    tol: float
    ex: float
    ey: float
    nx: float
    ny: float
    y0: float


def slider_crank_links(crank_pivot, crank, coupler, guide_point, guide_angle, branch) -> SliderCrankLinks:
    """The checked slider-crank; ValueError names the first input that is not a mechanism."""
    o1x, o1y = _point("crank_pivot", crank_pivot)
    gx, gy = _point("guide_point", guide_point)
    r1 = _length("crank", crank)
    l = _length("coupler", coupler)
    g = float(guide_angle)
    if not math.isfinite(g):
        raise ValueError(f"guide_angle must be finite, got {guide_angle!r}")
    br = _branch(branch)
    ex, ey = math.cos(g), math.sin(g)
    nx, ny = -ey, ex
    y0 = (o1x - gx) * nx + (o1y - gy) * ny
    scale = scene_size((r1, l), ((o1x, o1y),), (((gx, gy), g),))   # the one scene size
    tol = snap_tolerance(scale, max(abs(o1x), abs(o1y), abs(gx), abs(gy)))
    return SliderCrankLinks(o1x, o1y, r1, l, br, tol, ex, ey, nx, ny, y0)


def point_on_link(distance, angle, ABx, ABy, alpha2) -> tuple[float, float, bool]:
    """The checked ``(distance, angle, with accelerations)`` of a point fixed to a link: the acceleration
    of the base point and the angular acceleration of the link come all three or not at all."""
    dist = float(distance)
    if not (math.isfinite(dist) and dist >= 0.0):
        raise ValueError(f"distance must be a non-negative finite length, got {distance!r}")
    ang = float(angle)
    if not math.isfinite(ang):
        raise ValueError(f"angle must be finite, got {angle!r}")
    given = [v is not None for v in (ABx, ABy, alpha2)]
    if any(given) and not all(given):
        raise ValueError("give ABx, ABy and alpha2 together (the acceleration of the base point and "
                         "the angular acceleration of the link), or none of them")
    return dist, ang, all(given)
