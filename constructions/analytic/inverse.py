"""The inverse position problem in closed form: the crank angles that put a slider-crank's slider at a
given stroke position, or a four-bar's output link at a given angle.

An inverted slider-crank (a cylinder pivoted at O3 whose rod is pinned to the crank tip B) is one
crossing too: B on the crank circle and on the circle of radius |O3B| = the cylinder's length about O3.
The others are one circle-circle crossing once the far joint is placed: the slider's pin C stands at
G + s e on its guide (the four-bar's C at O2 + r3 (cos theta3, sin theta3)), and the crank tip B lies on
the crank circle (O1, r1) and on the coupler circle (C, l).  With w = C - O1, d = |w|, u = w / d and
n = k x u, B = O1 + a u + h_s n with a = (d^2 + r1^2 - l^2) / (2 d) and the half-chord
h = sqrt(P) / (2 d), P = (r1 + l + d)(r1 + l - d)(d + |r1 - l|)(d - |r1 - l|) (Heron as a product, so
near tangency the small factor is an exact difference); h_s = +-h gives the two crank angles
theta1 = atan2(B - O1).  Each is kept only when the scene's assembly branch holds there: the slider C
ahead of (branch +1) or behind (-1) the foot of B along e, i.e. sign((C - B) . e) = branch; the four-bar's
C to the left (+1) or right (-1) of B -> O2, i.e. sign(cross(O2 - B, C - B)) = branch.  A crossing on
the other branch is a position of the other assembly, which the scene did not choose.

Pure numpy and math, sharing nothing with the construction (:mod:`constructions.mechanisms.inverse_position`)
that it checks.
"""

from __future__ import annotations

import math

__all__ = ["four_bar_inverse", "inverted_slider_crank_inverse", "slider_crank_inverse"]


def _crank_angles(o1: tuple[float, float], r1: float, c: tuple[float, float], l: float) -> list[tuple[float, tuple[float, float]]]:
    """(theta1, B) where the circle (o1, r1) meets the circle (c, l): none, one (touching) or two."""
    wx, wy = c[0] - o1[0], c[1] - o1[1]
    d = math.hypot(wx, wy)
    if d == 0.0:
        return []
    S, T = r1 + l, abs(r1 - l)
    P = (S + d) * (S - d) * (d + T) * (d - T)
    tol = 64 * 2.0 ** -52 * max(S, d)
    if P < 0.0 and min(S - d, d - T) < -tol:
        return []
    h = math.sqrt(max(P, 0.0)) / (2 * d)
    a = (d * d + r1 * r1 - l * l) / (2 * d)
    ux, uy = wx / d, wy / d
    out = []
    for hs in ((h, -h) if h > 0 else (0.0,)):
        bx, by = o1[0] + a * ux - hs * uy, o1[1] + a * uy + hs * ux
        out.append((math.atan2(by - o1[1], bx - o1[0]) % (2 * math.pi), (bx, by)))
    return out


def slider_crank_inverse(position: float, *, crank_pivot, crank: float, coupler: float, guide_point,
                         guide_angle: float, branch: int) -> tuple[float, ...]:
    """The crank angles (rad, in [0, 2 pi), ascending) at which the slider pin C stands ``position`` (m)
    along the guide from ``guide_point`` (in the guide's direction ``guide_angle``), on the assembly
    ``branch`` (+1: C ahead of the foot of B along the guide, as :func:`~constructions.analytic.slider_crank`);
    empty when the slider cannot reach it."""
    ex, ey = math.cos(guide_angle), math.sin(guide_angle)
    c = (guide_point[0] + position * ex, guide_point[1] + position * ey)
    keep = []
    for th, (bx, by) in _crank_angles(crank_pivot, crank, c, coupler):
        along = (c[0] - bx) * ex + (c[1] - by) * ey
        if along == 0.0 or (along > 0) == (branch > 0):
            keep.append(th)
    return tuple(sorted(keep))


def four_bar_inverse(output_angle: float, *, crank_pivot, rocker_pivot, crank: float, coupler: float,
                     rocker: float, branch: int) -> tuple[float, ...]:
    """The crank angles (rad, in [0, 2 pi), ascending) at which the rocker O2C stands at ``output_angle``
    (rad, direction O2 -> C), on the assembly ``branch`` (+1: C to the left of B -> O2, as
    :func:`~constructions.analytic.four_bar`); empty when no crank angle puts it there."""
    c = (rocker_pivot[0] + rocker * math.cos(output_angle), rocker_pivot[1] + rocker * math.sin(output_angle))
    keep = []
    for th, (bx, by) in _crank_angles(crank_pivot, crank, c, coupler):
        side = (rocker_pivot[0] - bx) * (c[1] - by) - (rocker_pivot[1] - by) * (c[0] - bx)
        if side == 0.0 or (side > 0) == (branch > 0):
            keep.append(th)
    return tuple(sorted(keep))


def inverted_slider_crank_inverse(position: float, *, crank_pivot, crank: float, slot_pivot, branch: int
                                  ) -> tuple[float, ...]:
    """The crank angles (rad, in [0, 2 pi), ascending) at which the crank tip B stands ``position`` (m) along
    the slot of a link pivoted at ``slot_pivot`` O3 (the slot through O3: a hydraulic cylinder pivoted at O3
    whose rod is pinned at B), i.e. |O3B| = |position|: the crank circle (O1, r1) crossing the circle
    (O3, |position|).  The slot runs from O3 towards B on ``branch`` +1 (B ahead of O3), away on -1, so
    only a position of that sign is reached."""
    if position == 0.0 or (position > 0) != (branch > 0):
        return ()
    return tuple(sorted(th for th, _ in _crank_angles(crank_pivot, crank, slot_pivot, abs(position))))
