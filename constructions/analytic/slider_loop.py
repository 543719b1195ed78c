"""The (offset) slider-crank's vector loop in closed form: positions, velocities and accelerations over
crank angles."""

from __future__ import annotations

import numpy as np

from .inputs import angles, slider_crank_links
from .parts import crank_tip, gap_factors, gaps_to_nan, solvable
from .states import SliderCrankState

__all__ = ["slider_crank"]


def slider_crank(theta1, omega1, alpha1=0.0, *, crank_pivot, crank, coupler, guide_point, guide_angle,
                 branch):
    """Closed-form positions, velocities and accelerations of an (offset) slider-crank, vectorised.

    Parameters
    ----------
    theta1, omega1, alpha1 : float or array_like
        Crank angle(s) (rad, direction O1 -> B), angular velocity (rad/s) and angular acceleration
        (rad/s^2, default 0), CCW positive, broadcast against each other: as for
        :func:`~constructions.analytic.four_bar`.
    crank_pivot : pair of float
        Fixed pivot O1 (m).
    crank, coupler : float
        Link lengths |O1B| and |BC| (m), positive.
    guide_point : pair of float
        A point G on the straight guide of the slider pin C (m).
    guide_angle : float
        Direction of the guide (rad); ``e = (cos, sin)`` of it is the positive slider direction.
    branch : {+1, -1}
        +1: C lies AHEAD of the foot of the perpendicular from B onto the guide, measured along e;
        -1: behind.

    Returns
    -------
    SliderCrankState
        Arrays of the broadcast shape of ``theta1``, ``omega1`` and ``alpha1``.

    Notes
    -----
    Position (line-circle).  Let e = (cos g, sin g), n = k x e = (-sin g, cos g) and
    y = (B - G) . n the signed distance of B from the guide.  The foot of the perpendicular is
    F = B - y n, and C = F + branch h e with the half-chord h = sqrt((l - y)(l + y)), l = coupler
    (cancellation-free; the loop closes iff |y| <= l).  So p = C - B = -y n + branch h e.
    y is formed as y0 + crank sin(theta1 - g) with y0 = (O1 - G) . n, i.e. from
    crank (s cos g - c sin g), to keep the digits of a small offset.

    Velocity.  V_C = V_B + omega2 k x p with V_C parallel to e, i.e. V_C . n = 0.  Since
    (k x p) . n = p . e = branch h, omega2 = -(V_B . n) / (branch h).  The slider speed is
    V_C . e = V_B . e + omega2 (k x p) . e and (k x p) . e = cross(p, e) = y, so
    slider_speed = V_B . e + omega2 y and V_C = slider_speed e.  The condition measure is
    |p . e| / l = h / l.  Checked against finite differences and complex-step derivatives of
    the positions in the tests.

    Acceleration.  Differentiate V_C = V_B + omega2 k x p once more (p' = omega2 k x p,
    k x (k x p) = -p): A_C = A_B + alpha2 k x p - omega2^2 p, with A_C = sddot e parallel to the
    guide (the guide is fixed and straight, so there is no Coriolis or normal term for the block).
    Put R = A_B - omega2^2 p.  Dotting with n removes A_C: R . n + alpha2 (k x p) . n = 0, and
    (k x p) . n = p . e = branch h as for the velocities, so alpha2 = -(R . n) / (branch h), with
    R . n = A_B . n + omega2^2 y (p . n = -y).  Dotting with e:
    sddot = R . e + alpha2 (k x p) . e = A_B . e - omega2^2 branch h + alpha2 y.
    Checked against the dyad-chain solver, finite differences of the velocities in time, the exact
    in-line formula and the notes' examples in the tests.
    """
    k = slider_crank_links(crank_pivot, crank, coupler, guide_point, guide_angle, branch)
    th, w1, a1, shape = angles(theta1, omega1, alpha1)
    with np.errstate(all="ignore"):  # NaN where the loop does not close, inf nowhere (see solvable)
        c, s = np.cos(th), np.sin(th)
        Bx, By, VBx, VBy, ABx, ABy = crank_tip(c, s, w1, a1, k.r1, k.o1x, k.o1y)
        # y = y0 + crank (s ex - c ey), the signed distance of B from the guide
        y = s * (k.ex * k.r1) - c * (k.ey * k.r1) + k.y0
        # half-chord h = sqrt((l - y)(l + y)), its factors exact differences near dead centre
        h1, h2, closes = gap_factors(k.l - y, y + k.l, k.tol)
        gap = gaps_to_nan(closes)
        h = np.sqrt(h1 * h2) + gap
        Bx, By, VBx, VBy, ABx, ABy = (v + gap for v in (Bx, By, VBx, VBy, ABx, ABy))
        condition = h * (1.0 / k.l)
        bh = h * k.branch
        # p = C - B = -y n + branch h e
        px, py = y * -k.nx + bh * k.ex, y * -k.ny + bh * k.ey
        # omega2 = -(V_B . n) / (branch h);  slider_speed = V_B . e + omega2 y
        inv = solvable(condition, -1.0 / bh)
        omega2 = (VBx * k.nx + VBy * k.ny) * inv
        speed = VBx * k.ex + VBy * k.ey + omega2 * y
        # alpha2 = -(A_B . n + omega2^2 y) / (branch h);  sddot = A_B . e - omega2^2 (branch h) + alpha2 y
        w2sq = omega2 * omega2
        alpha2 = (ABx * k.nx + ABy * k.ny + w2sq * y) * inv
        sddot = ABx * k.ex + ABy * k.ey - w2sq * bh + alpha2 * y
        values = dict(Bx=Bx, By=By, Cx=Bx + px, Cy=By + py, theta2=np.arctan2(py, px), omega2=omega2,
                      VBx=VBx, VBy=VBy, VCx=speed * k.ex, VCy=speed * k.ey, slider_speed=speed, alpha2=alpha2,
                      ABx=ABx, ABy=ABy, ACx=sddot * k.ex, ACy=sddot * k.ey, slider_acceleration=sddot,
                      condition=condition)
    return SliderCrankState(assembles=closes.reshape(shape), **{n: v.reshape(shape) for n, v in values.items()})
