"""What every closed form of the oracle does the same way: the crank tip's motion, the three-way
decision on the gap factors of an intersection, and NaN wherever the loop does not close."""

from __future__ import annotations

import numpy as np

__all__ = ["SINE_TOL", "crank_tip", "gap_factors", "gaps_to_nan", "solvable"]

#: Threshold on the sine of the angle between the velocity trial lines: below it the velocity
#: solve is indeterminate (toggle / dead centre) and velocities are NaN.
SINE_TOL = 1e-12


def crank_tip(c, s, w, a, r1, o1x, o1y):
    """Crank pin B = O1 + r1 (cos, sin) at a crank angle of cosine ``c`` and sine ``s`` turning at
    ``w`` with angular acceleration ``a``: (Bx, By, VBx, VBy, ABx, ABy).

    V_B = omega1 k x r = omega1 r1 (-sin, cos), r = B - O1.  Differentiating once more with
    theta1' = omega1 and omega1' = alpha1: A_B = alpha1 r1 (-sin, cos) - omega1^2 r1 (cos, sin)
    = alpha1 k x r - omega1^2 r, the tangential part square to the crank, the normal part towards O1.
    """
    normal = -w * w * r1
    return (c * r1 + o1x, s * r1 + o1y, s * (-w * r1), c * (w * r1),
            c * normal + s * a * -r1, s * normal + c * a * r1)


def gap_factors(f1, f2, tol):
    """The three-way decision on the two small gap factors of a half-chord, which must both be >= 0
    for the intersection to exist: ``(f1, f2, closes)`` with a factor within ``tol`` of zero snapped
    to exactly 0 (tangent) and ``closes`` False where a factor is below ``-tol`` (apart) or NaN."""
    closes = (f1 >= -tol) & (f2 >= -tol)
    return np.where(f1 <= tol, 0.0, f1), np.where(f2 <= tol, 0.0, f2), closes


def gaps_to_nan(closes):
    """0 where the loop closes, NaN elsewhere: added to a quantity it makes it NaN at the gaps."""
    return np.where(closes, 0.0, np.nan)


def solvable(condition, value):
    """``value`` where the sine ``condition`` of the velocity trial lines is at least :data:`SINE_TOL`,
    NaN elsewhere (toggle, dead centre) and where the condition is NaN."""
    return np.where(condition >= SINE_TOL, value, np.nan)
