"""The four-bar's vector loop in closed form: positions, velocities and accelerations over crank angles."""

from __future__ import annotations

import numpy as np

from .inputs import angles, four_bar_links
from .parts import crank_tip, gap_factors, gaps_to_nan, solvable
from .states import FourBarState

__all__ = ["four_bar"]


def four_bar(theta1, omega1, alpha1=0.0, *, crank_pivot, rocker_pivot, crank, coupler, rocker, branch):
    """Closed-form positions, velocities and accelerations of a four-bar, vectorised over crank angles.

    Parameters
    ----------
    theta1 : float or array_like
        Crank angle(s), direction O1 -> B (rad, CCW from +x).
    omega1 : float or array_like
        Crank angular velocity (rad/s, CCW positive); broadcast against ``theta1``.
    alpha1 : float or array_like, optional
        Crank angular acceleration (rad/s^2, CCW positive), default 0 (constant speed); broadcast
        against ``theta1`` and ``omega1``.
    crank_pivot, rocker_pivot : pair of float
        Fixed pivots O1 and O2 (m).
    crank, coupler, rocker : float
        Link lengths |O1B|, |BC|, |O2C| (m), positive.
    branch : {+1, -1}
        Assembly: +1 puts C to the LEFT of the directed line B -> O2
        (``cross(O2 - B, C - B) > 0``), -1 to the right.
    Returns
    -------
    FourBarState
        Arrays of the broadcast shape of ``theta1``, ``omega1`` and ``alpha1``.

    Notes
    -----
    Position (circle-circle, vector form).  With w = O2 - B, d = |w|, u = w/d, n = k x u (u turned
    +90 deg), C lies on the circle (B, coupler) and on the circle (O2, rocker).  Writing
    C - B = a u + h_s n and subtracting the two circle equations gives
    a = (d^2 + coupler^2 - rocker^2) / (2 d), and h = |h_s| is the half-chord.  By Heron,
    2 d h = sqrt(P), P = (S + d)(S - d)(d + T)(d - T), S = coupler + rocker, T = |coupler - rocker|
    (P >= 0 iff the loop closes).  The branch rule makes h_s = branch * h, because
    cross(w, C - B) = d h_s.  Hence C = B + alpha w + beta (k x w) with
    alpha = (d^2 + coupler^2 - rocker^2) / (2 d^2), beta = branch sqrt(P) / (2 d^2).

    Velocity.  V_B = omega1 k x (B - O1).  With p = C - B and q = C - O2 the loop gives
    V_B + omega2 k x p = omega3 k x q.  Dotting with q removes omega3 (since (k x q).q = 0) and
    (k x p).q = cross(p, q); dotting with p removes omega2.  So
    omega2 = -(V_B . q) / cross(p, q), omega3 = -(V_B . p) / cross(p, q), V_C = omega3 k x q.
    With q = p - d u one finds cross(p, q) = d h_s = branch sqrt(P) / 2, so the determinant comes
    straight from the cancellation-free half-chord, and the condition measure
    |cross(p, q)| / (coupler rocker) = sqrt(P) / (2 coupler rocker) is the sine of the angle between
    coupler and rocker.  Checked against finite differences and complex-step derivatives of the
    positions in the tests.

    Acceleration.  Differentiate the velocity loop V_B + omega2 k x p = omega3 k x q once more in
    time.  p and q are fixed in their links, so p' = omega2 k x p and q' = omega3 k x q, and
    k x (k x p) = -p in the plane; hence
    A_B + alpha2 k x p - omega2^2 p = alpha3 k x q - omega3^2 q   (A_B = alpha1 k x r1 - omega1^2 r1).
    Collect the known terms R = A_B - omega2^2 p + omega3^2 q, so R + alpha2 k x p = alpha3 k x q:
    the same 2x2 system as for the velocities with V_B replaced by R.  Dotting with q and with p as
    before: alpha2 = -(R . q) / cross(p, q), alpha3 = -(R . p) / cross(p, q) and
    A_C = alpha3 k x q - omega3^2 q.  With |p| = coupler, |q| = rocker and
    p . q = (coupler^2 + rocker^2 - d^2) / 2 (from |p - q|^2 = |O2 - B|^2 = d^2) the right-hand sides are
    R . q = A_B . q - omega2^2 (p . q) + omega3^2 rocker^2 and
    R . p = A_B . p - omega2^2 coupler^2 + omega3^2 (p . q).  Checked against the dyad-chain solver,
    finite differences of the velocities in time and the notes' examples in the tests.
    """
    k = four_bar_links(crank_pivot, rocker_pivot, crank, coupler, rocker, branch)
    th, w1, a1, shape = angles(theta1, omega1, alpha1)
    with np.errstate(all="ignore"):  # NaN where the loop does not close, inf nowhere (see solvable)
        Bx, By, VBx, VBy, ABx, ABy = crank_tip(np.cos(th), np.sin(th), w1, a1, k.r1, k.o1x, k.o1y)
        # w = O2 - B, d = |w|; the gap factors (S - d) and (d - T) are exact differences near tangency
        wx, wy = k.o2x - Bx, k.o2y - By
        d2 = wx * wx + wy * wy
        d = np.sqrt(d2)
        f1, f2, closes = gap_factors(k.S - d, d - k.T, k.tol)
        if k.check_d0:
            closes &= d2 > 0.0
        gap = gaps_to_nan(closes)
        root = np.sqrt(f1 * (d + k.S) * (f2 * (d + k.T))) + gap     # sqrt(P) = 2 d h
        Bx, By, VBx, VBy, ABx, ABy = (v + gap for v in (Bx, By, VBx, VBy, ABx, ABy))
        condition = root * k.inv_2r2r3
        # p = C - B = alpha w + beta (k x w)
        half_over_d2 = 0.5 / d2
        al = (d2 + k.K) * half_over_d2
        be = root * half_over_d2 * k.branch
        px, py = al * wx - be * wy, al * wy + be * wx
        # q = C - O2 = p - w
        qx, qy = px - wx, py - wy
        # -1 / cross(p, q) = -2 branch / sqrt(P), NaN where the sine is below SINE_TOL
        inv = solvable(condition, -2.0 * k.branch / root)
        omega2 = (VBx * qx + VBy * qy) * inv
        omega3 = (VBx * px + VBy * py) * inv
        # accelerations (see Notes): p . q = (coupler^2 + rocker^2 - d^2) / 2
        w2sq, w3sq = omega2 * omega2, omega3 * omega3
        pq = d2 * -0.5 + k.half_sumsq
        alpha2 = (ABx * qx + ABy * qy - w2sq * pq + w3sq * (k.r3 * k.r3)) * inv
        alpha3 = (ABx * px + ABy * py - w2sq * (k.r2 * k.r2) + w3sq * pq) * inv
        values = dict(Bx=Bx, By=By, Cx=Bx + px, Cy=By + py, theta2=np.arctan2(py, px), theta3=np.arctan2(qy, qx),
                      omega2=omega2, omega3=omega3, VBx=VBx, VBy=VBy, VCx=-(omega3 * qy), VCy=omega3 * qx,
                      alpha2=alpha2, alpha3=alpha3, ABx=ABx, ABy=ABy,
                      ACx=-(alpha3 * qy + w3sq * qx), ACy=alpha3 * qx - w3sq * qy, condition=condition)
    return FourBarState(assembles=closes.reshape(shape), **{n: v.reshape(shape) for n, v in values.items()})
