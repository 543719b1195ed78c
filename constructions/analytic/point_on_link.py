"""A point fixed to a moving link (a coupler point): its position, velocity and acceleration."""

from __future__ import annotations

import numpy as np

from .inputs import point_on_link
from .states import PointState

__all__ = ["coupler_point"]


def coupler_point(Bx, By, VBx, VBy, theta2, omega2, *, distance, angle, ABx=None, ABy=None,
                  alpha2=None):
    """Position, velocity and acceleration of a point D fixed to a link (e.g. the coupler).

    Parameters
    ----------
    Bx, By, VBx, VBy : array_like
        Position (m) and velocity (m/s) of the link's base point B, e.g. from :func:`four_bar`.
    theta2, omega2 : array_like
        Link angle (rad, the direction from B to the link's other joint) and angular velocity
        (rad/s, CCW positive).
    distance : float
        |BD| (m), non-negative.
    angle : float
        Angle of BD measured CCW from the link direction (rad).
    ABx, ABy, alpha2 : array_like, optional
        Acceleration of B (m/s^2) and angular acceleration of the link (rad/s^2, CCW positive).
        Give all three or none; without them ``ADx`` and ``ADy`` are NaN.

    Returns
    -------
    PointState
        ``D = B + distance (cos(theta2 + angle), sin(theta2 + angle))``,
        ``V_D = V_B + omega2 k x r`` and ``A_D = A_B + alpha2 k x r - omega2^2 r`` with r = D - B
        (rigid body; k x (x, y) = (-y, x)), broadcast over the inputs.  NaN inputs give NaN outputs.

    Notes
    -----
    r = D - B turns with the link: r' = omega2 k x r.  Differentiating V_D = V_B + omega2 k x r gives
    A_D = A_B + alpha2 k x r + omega2 k x (omega2 k x r) = A_B + alpha2 k x r - omega2^2 r, i.e.
    (ABx - alpha2 r_y - omega2^2 r_x, ABy + alpha2 r_x - omega2^2 r_y).
    """
    dist, ang, accel = point_on_link(distance, angle, ABx, ABy, alpha2)
    given = (Bx, By, VBx, VBy, theta2, omega2) + ((ABx, ABy, alpha2) if accel else ())
    bx, by, vbx, vby, t2, w2, *acc = np.broadcast_arrays(*(np.asarray(v, dtype=np.float64) for v in given))
    with np.errstate(all="ignore"):
        # r = D - B = distance (cos, sin)(theta2 + angle);  V_D = V_B + omega2 (-r_y, r_x)
        t = t2 + ang
        rx, ry = np.cos(t) * dist, np.sin(t) * dist
        values = dict(Dx=bx + rx, Dy=by + ry, VDx=vbx - w2 * ry, VDy=w2 * rx + vby)
        if accel:
            # A_D = A_B + alpha2 (-r_y, r_x) - omega2^2 (r_x, r_y)
            abx, aby, a2 = acc
            w2sq = w2 * w2
            values.update(ADx=abx - a2 * ry - w2sq * rx, ADy=aby + a2 * rx - w2sq * ry)
        else:
            values.update(ADx=np.full(bx.shape, np.nan), ADy=np.full(bx.shape, np.nan))
    return PointState(**{n: np.array(v, dtype=np.float64) for n, v in values.items()})
