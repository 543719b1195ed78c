"""The sweep's own trigonometry: cosine and sine of the crank angle from one ``tan``, and the direction
angle of a vector from a rational approximation of atan -- both over whole arrays into the caller's
buffers, several times cheaper than numpy's ``cos`` + ``sin`` and ``arctan2`` on these machines.

* Sine and cosine of the crank angle come from a quarter-angle tangent (``tan`` is SIMD-vectorised in
  numpy and four to ten times cheaper than ``sin`` + ``cos`` here) after a three-part Cody-Waite
  reduction modulo 4 pi; the result agrees with ``np.cos``/``np.sin`` to about 1e-15 absolute and
  depends on each angle alone, never on the batch it came in.  Angles beyond 1e6 rad use
  ``np.cos``/``np.sin``.
* The link angles come from :func:`atan2` (a rational approximation after octant reduction, within 2 ulp
  of ``np.arctan2``): numpy's arctan2 is a scalar libm loop on CPUs without AVX-512 and cost as much as
  all the rest of the four-bar's arithmetic.

The oracle (:mod:`constructions.analytic`) uses numpy's own functions; the kernels that use these are
tested against it.
"""

from __future__ import annotations

import math

import numpy as np

__all__ = ["atan2", "atan2_into", "sincos"]

# pi split into three parts for Cody-Waite argument reduction (half of a 2 pi split derived from
# 60+ digits of pi with ``decimal``): _PI_1 and _PI_2 carry 30 significant bits each, so k*_PI_1 and
# k*_PI_2 are exact for |k| < 2**23; _PI_3 is the rest rounded to double.  The kernel reduces the
# quarter angle th/4 by k pi, i.e. th by k 4pi.
_PI_1 = 6.283185310661793 / 2.0
_PI_2 = -3.4822062768002926e-09 / 2.0
_PI_3 = -1.401373759235972e-18 / 2.0
_INV_FOUR_PI = 0.07957747154594767
# |th| <= this (2 pi rounded, the end of a sweep np.linspace(0, 2 pi, n)): th / 4pi rounds to at most 0.5
# (exactly 0.5 at the end), so k = rint(th / 4pi) is 0 (half to even) and the reduction is the identity
_NO_REDUCTION = 2.0 * math.pi
_FAST_TRIG_LIMIT = 1.0e6  # |theta| up to this uses the fast path (|k| < 2**17, products exact)


def sincos(th, c, s, t, u):
    """Write cos(th) into c and sin(th) into s (all 1-D, same length); t, u are scratch.

    Derivation: write th = 4 pi k + r with r in [-2 pi, 2 pi] (4 pi is a period too; Cody-Waite
    with a three-part split, so th/4 - k pi is exact up to the last part).  With tau = tan(r/4),
    |r/4| <= pi/2 (rounded), the half-angle identities give cos(r/2) = (1 - tau^2)/(1 + tau^2),
    sin(r/2) = 2 tau/(1 + tau^2) and the double-angle identities give
    cos r = (cos(r/2) - sin(r/2)) (cos(r/2) + sin(r/2)), sin r = 2 sin(r/2) cos(r/2).
    Each step is a few ulp and stays so as tau grows towards r = +-2 pi (tau <= 1.7e16, no
    overflow); the absolute error is about 1e-15 at most.

    The result is a function of each element alone (not of the batch): for |th| < 2 pi, k = 0 and
    the reduction is the identity exactly, so it is skipped when the whole chunk is inside that band;
    elements beyond 1e6 rad (where k pi is no longer exact) or NaN are redone with np.cos/np.sin.
    """
    if th.size == 0:
        return
    lo = float(th.min())
    hi = float(th.max())
    np.multiply(th, 0.25, out=u)  # exact
    if not (-_NO_REDUCTION <= lo and hi <= _NO_REDUCTION):
        # k = rint(th / 4pi); u = th/4 - k pi, three-part pi, k*_PI_1 and k*_PI_2 exact
        np.multiply(th, _INV_FOUR_PI, out=t)
        np.rint(t, out=t)
        np.multiply(t, _PI_1, out=c)
        u -= c
        np.multiply(t, _PI_2, out=c)
        u -= c
        np.multiply(t, _PI_3, out=c)
        u -= c
    np.tan(u, out=u)  # tau
    np.multiply(u, u, out=t)  # tau^2
    np.add(t, 1.0, out=c)  # 1 + tau^2
    np.subtract(1.0, t, out=t)  # 1 - tau^2
    np.divide(1.0, c, out=c)  # 1 / (1 + tau^2)
    t *= c  # cos(r/2)
    u += u
    u *= c  # sin(r/2)
    np.add(t, u, out=c)
    np.multiply(t, u, out=s)
    s += s  # sin r
    t -= u
    c *= t  # cos r
    if not (-_FAST_TRIG_LIMIT <= lo and hi <= _FAST_TRIG_LIMIT):  # rare; also NaN
        far = ~(np.abs(th) <= _FAST_TRIG_LIMIT)
        c[far] = np.cos(th[far])
        s[far] = np.sin(th[far])


# atan on [0, 0.66]: atan(z) = z + z w P(w) / Q(w), w = z^2, Q monic -- the rational minimax
# approximation of S. L. Moshier's Cephes library (atan.c, documented to about 2e-16 relative).
# Coefficients cannot be derived by hand; they are checked instead: within 2 ulp of np.arctan2 over
# 2e5 directions and lengths 1e-290 .. 1e290 in tests/test_analytic.py.
_ATAN_P = (-8.750608600031904122785e-1, -1.615753718733365076637e1, -7.500855792314704667340e1,
           -1.228866684490136173410e2, -6.485021904942025371773e1)
_ATAN_Q = (2.485846490142306297962e1, 1.650270098316988542046e2, 4.328810604912902668951e2,
           4.853903996359136964868e2, 1.945506571482613964425e2)
_QUARTER_PI = math.pi / 4
_HALF_PI = math.pi / 2


def atan2(y, x, out, a, b, c, d, e, m) -> None:
    """out = atan2(y, x) in [-pi, pi] for arrays of one shape; a .. e (float) and m (bool) are scratch
    (d is not used: see :func:`atan2_into`, which this calls)."""
    atan2_into(y, x, out, a, b, c, e, m, np.empty(m.shape, dtype=bool))


def atan2_into(y, x, out, a, b, c, e, m, swap) -> None:
    """out = atan2(y, x) in [-pi, pi] for arrays of one shape (any strides); a, b, c, e (float) and m,
    swap (bool) are scratch.

    numpy's arctan2 is a scalar libm loop on CPUs without AVX-512 (~40 ns per element on the AMD
    EPYC of these machines, two of them a third of the four-bar's time); this is ~40 vector passes.
    Reduction: z = min(|x|, |y|) / max(|x|, |y|) in [0, 1]; above 0.66, atan(z) = pi/4 +
    atan((z - 1)/(z + 1)) with |(z - 1)/(z + 1)| <= 0.205; then the rational approximation above.
    The octant is restored by atan2 = pi/2 - atan(z) where |y| > |x|, pi minus that where x < 0, and
    the sign of y (so y = +0 with x < 0 gives +pi, as np.arctan2 does).  Each step rounds once, so
    the result is within a few ulp of the true angle.  NaN in gives NaN out; (0, 0) gives NaN
    (np.arctan2 gives 0) -- the links here have positive lengths, so it does not arise.
    """
    np.abs(x, out=a)
    np.abs(y, out=b)
    np.less(a, b, out=swap)  # |y| > |x|
    np.minimum(a, b, out=c)
    np.maximum(a, b, out=a)
    c /= a  # z
    np.greater(c, 0.66, out=m)
    np.add(c, 1.0, out=a)
    np.subtract(c, 1.0, out=b)
    b /= a
    np.copyto(c, b, where=m)  # z, now in [-0.205, 0.66]
    np.multiply(c, c, out=a)  # w = z^2
    p0, p1, p2, p3, p4 = _ATAN_P
    np.multiply(a, p0, out=b)
    b += p1
    for k in (p2, p3, p4):
        b *= a
        b += k
    q0, q1, q2, q3, q4 = _ATAN_Q
    np.add(a, q0, out=e)
    for k in (q1, q2, q3, q4):
        e *= a
        e += k
    b *= a
    b /= e
    b *= c
    np.add(b, c, out=out)  # atan(z)
    np.add(out, _QUARTER_PI, out=out, where=m)  # + pi/4 where reduced
    np.subtract(_HALF_PI, out, out=b)
    np.copyto(out, b, where=swap)
    np.less(x, 0.0, out=m)
    np.subtract(math.pi, out, out=b)
    np.copyto(out, b, where=m)
    np.copysign(out, y, out=out)
