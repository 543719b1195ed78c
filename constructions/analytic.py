"""The independent analytic check: vector-loop closed forms, vectorised over crank angles.

This module is the yardstick for the graphical velocity- and acceleration-polygon constructions, so it
deliberately
shares no code with them: it is pure numpy and imports nothing from :mod:`constructions` but the
tolerance policy (:mod:`constructions.tolerance`: the one scene size and the snapping tolerance), and
nothing from :mod:`drafting`.  Every formula below is derived here from first principles (the derivations are in
the comments next to the code); none is copied from the course notes, whose vector-loop section has
known sign and matrix mistakes (its four-bar acceleration matrix among them).

Conventions
-----------
* SI throughout: metres, radians, rad/s, rad/s^2.  Angles are measured CCW from +x; omega and alpha
  are CCW positive.
* ``theta1``, ``omega1`` and ``alpha1`` may be scalars or numpy arrays; they are broadcast against
  each other and every returned field is a float64 (or bool) array of the broadcast shape (a 0-d
  array for scalars).  The returned arrays are read-only; the containers are frozen dataclasses.
* A crank angle at which the loop cannot close gives NaN for every position, velocity and
  acceleration field (including B, V_B and A_B: the mechanism has no configuration there), NaN
  ``condition`` and ``assembles == False``.
* ``condition`` is the sine of the angle between the two velocity trial lines.  Where it is below
  :data:`SINE_TOL` (1e-12) the velocity solution is indeterminate (toggle / dead centre) and every
  velocity and acceleration that depends on the solve is NaN -- never inf, never a huge number.  V_B
  and A_B stay finite.  The acceleration loop has the same 2x2 matrix as the velocity loop (only the
  right-hand side differs), so it is singular exactly where the velocity loop is; near a toggle the
  accelerations grow like 1/condition^3 (the velocities like 1/condition).

Numerical notes
---------------
* Circle-circle and line-circle intersections use the cancellation-free product form of the
  half-chord (Heron's formula written as a product of sums and differences), so near tangency the
  small factor is an exact floating-point difference (Sterbenz) and keeps its digits.
* The assembly decision is three-way with a tolerance ``tol = ASSEMBLY_RTOL * L`` relative to the
  one scene size ``L`` of :mod:`constructions.tolerance` (the largest link length or distance between
  the pivots -- or of the crank pivot from the guide -- which does not move with the origin).
  Each small gap factor of the half-chord (``S - d`` and ``d - T`` for the four-bar, ``l -+ y`` for
  the slider) is classified: ``> tol`` crossing, ``|gap| <= tol`` tangent (snapped to exactly 0:
  assembles, C on the line of centres, condition 0, velocities NaN), ``< -tol`` apart (no assembly).
  So a designed toggle built from rotated float coordinates reads as a toggle whichever way the
  rounding fell.  ``ASSEMBLY_RTOL`` is 64 ulp; the snap moves C by at most about
  ``sqrt(2 * tol * L)`` ~ 2e-7 L, which is inside the band that the rounding of the inputs already
  leaves undetermined at a tangency (the half-chord has infinite slope there).
  Consequence: apart from exact zeros, a computed ``condition`` is never below roughly 1e-7, so the
  1e-12 ``SINE_TOL`` rule only ever fires at (snapped) tangencies; the velocities next to a toggle
  are finite and honest but large -- inspect ``condition`` before trusting them.
* Sine and cosine of the crank angle come from a quarter-angle tangent (``tan`` is SIMD-vectorised in
  numpy and four to ten times cheaper than ``sin`` + ``cos`` here) after a three-part Cody-Waite
  reduction modulo 4 pi; the result agrees with ``np.cos``/``np.sin`` to about 1e-15 absolute and
  depends on each angle alone, never on the batch it came in.  Angles beyond 1e6 rad use
  ``np.cos``/``np.sin``.
* The link angles theta2, theta3 come from the module's own atan2 (a rational approximation after
  octant reduction, within 2 ulp of ``np.arctan2``): numpy's arctan2 is a scalar libm loop on CPUs
  without AVX-512 and cost as much as all the rest of the four-bar's arithmetic.
* Work is done in chunks of :data:`CHUNK` angles with preallocated scratch buffers and ``out=``
  ufuncs, so the working set stays in cache.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, fields

import numpy as np

from .tolerance import ASSEMBLY_RTOL, scene_size, snap_tolerance

__all__ = [
    "ASSEMBLY_RTOL",
    "CHUNK",
    "SINE_TOL",
    "FourBarState",
    "PointState",
    "SliderCrankState",
    "coupler_point",
    "four_bar",
    "slider_crank",
]

#: Threshold on the sine of the angle between the velocity trial lines: below it the velocity
#: solve is indeterminate (toggle / dead centre) and velocities are NaN.
SINE_TOL = 1e-12

# ASSEMBLY_RTOL (constructions.tolerance, times the scene size L): a gap factor of an intersection
# within +-ASSEMBLY_RTOL * L of zero is rounding noise at a tangency and is snapped to exactly zero.

#: Number of crank angles processed per chunk (tuned on a Xeon with 2 MB of L2 per core;
#: 2**13 .. 2**15 measure within noise of each other).
CHUNK = 2**14

# pi split into three parts for Cody-Waite argument reduction (half of a 2 pi split derived from
# 60+ digits of pi with ``decimal``): _PI_1 and _PI_2 carry 30 significant bits each, so k*_PI_1 and
# k*_PI_2 are exact for |k| < 2**23; _PI_3 is the rest rounded to double.  The kernel reduces the
# quarter angle th/4 by k pi, i.e. th by k 4pi.
_PI_1 = 6.283185310661793 / 2.0
_PI_2 = -3.4822062768002926e-09 / 2.0
_PI_3 = -1.401373759235972e-18 / 2.0
_INV_FOUR_PI = 0.07957747154594767
_NO_REDUCTION = 6.28  # |th| <= this: k = rint(th / 4pi) is certainly 0, reduction is the identity
_FAST_TRIG_LIMIT = 1.0e6  # |theta| up to this uses the fast path (|k| < 2**17, products exact)


# --------------------------------------------------------------------------------------------
# Result containers
# --------------------------------------------------------------------------------------------


def _freeze(obj) -> None:
    for f in fields(obj):
        value = getattr(obj, f.name)
        if isinstance(value, np.ndarray):
            value.flags.writeable = False


@dataclass(frozen=True, eq=False)
class FourBarState:
    """Positions, velocities and accelerations of a four-bar O1-B-C-O2 over a set of crank angles.

    Attributes
    ----------
    Bx, By : ndarray
        Crank pin B (m).
    Cx, Cy : ndarray
        Coupler-rocker pin C (m).
    theta2 : ndarray
        Coupler angle, direction B -> C (rad, in (-pi, pi]).
    theta3 : ndarray
        Rocker angle, direction O2 -> C (rad, in (-pi, pi]).
    omega2, omega3 : ndarray
        Coupler and rocker angular velocities (rad/s, CCW positive).
    VBx, VBy, VCx, VCy : ndarray
        Absolute velocities of B and C (m/s).
    alpha2, alpha3 : ndarray
        Coupler and rocker angular accelerations (rad/s^2, CCW positive).
    ABx, ABy, ACx, ACy : ndarray
        Absolute accelerations of B and C (m/s^2).
    assembles : ndarray of bool
        True where the loop closes at this crank angle.
    condition : ndarray
        ``|sin|`` of the angle between coupler and rocker (the sine of the transmission angle);
        0 at a toggle, where the velocities and accelerations are NaN.
    """

    Bx: np.ndarray
    By: np.ndarray
    Cx: np.ndarray
    Cy: np.ndarray
    theta2: np.ndarray
    theta3: np.ndarray
    omega2: np.ndarray
    omega3: np.ndarray
    VBx: np.ndarray
    VBy: np.ndarray
    VCx: np.ndarray
    VCy: np.ndarray
    alpha2: np.ndarray
    alpha3: np.ndarray
    ABx: np.ndarray
    ABy: np.ndarray
    ACx: np.ndarray
    ACy: np.ndarray
    assembles: np.ndarray
    condition: np.ndarray

    def __post_init__(self) -> None:
        _freeze(self)


@dataclass(frozen=True, eq=False)
class SliderCrankState:
    """Positions, velocities and accelerations of an (offset) slider-crank O1-B-C, C on a straight guide.

    Attributes
    ----------
    Bx, By : ndarray
        Crank pin B (m).
    Cx, Cy : ndarray
        Slider pin C (m), on the guide.
    theta2 : ndarray
        Coupler angle, direction B -> C (rad, in (-pi, pi]).
    omega2 : ndarray
        Coupler angular velocity (rad/s, CCW positive).
    VBx, VBy, VCx, VCy : ndarray
        Absolute velocities of B and C (m/s); V_C is parallel to the guide.
    slider_speed : ndarray
        Signed speed of C along the guide direction ``(cos guide_angle, sin guide_angle)`` (m/s).
    alpha2 : ndarray
        Coupler angular acceleration (rad/s^2, CCW positive).
    ABx, ABy, ACx, ACy : ndarray
        Absolute accelerations of B and C (m/s^2); A_C is parallel to the guide.
    slider_acceleration : ndarray
        Signed acceleration of C along the guide direction (m/s^2).
    assembles : ndarray of bool
        True where the coupler reaches the guide at this crank angle.
    condition : ndarray
        Sine of the angle between the two velocity trial lines (V_CB perpendicular to BC, V_C along
        the guide) ``= |unit(C - B) . e|``; 0 when the coupler is perpendicular to the guide.
    """

    Bx: np.ndarray
    By: np.ndarray
    Cx: np.ndarray
    Cy: np.ndarray
    theta2: np.ndarray
    omega2: np.ndarray
    VBx: np.ndarray
    VBy: np.ndarray
    VCx: np.ndarray
    VCy: np.ndarray
    slider_speed: np.ndarray
    alpha2: np.ndarray
    ABx: np.ndarray
    ABy: np.ndarray
    ACx: np.ndarray
    ACy: np.ndarray
    slider_acceleration: np.ndarray
    assembles: np.ndarray
    condition: np.ndarray

    def __post_init__(self) -> None:
        _freeze(self)


@dataclass(frozen=True, eq=False)
class PointState:
    """Position, velocity and acceleration of a point D fixed to a link.

    Attributes
    ----------
    Dx, Dy : ndarray
        Position of D (m).
    VDx, VDy : ndarray
        Absolute velocity of D (m/s).
    ADx, ADy : ndarray
        Absolute acceleration of D (m/s^2); NaN when the base point's acceleration and the link's
        angular acceleration were not given.
    """

    Dx: np.ndarray
    Dy: np.ndarray
    VDx: np.ndarray
    VDy: np.ndarray
    ADx: np.ndarray
    ADy: np.ndarray

    def __post_init__(self) -> None:
        _freeze(self)


# --------------------------------------------------------------------------------------------
# Input handling
# --------------------------------------------------------------------------------------------


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


def _angles(theta1, omega1, alpha1):
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


def _outputs(names, n):
    """One (len(names), n) block, a row per field: a single allocation, which for large n the
    allocator maps in huge pages (numpy asks for them from 4 MB up), so the first touch of the output
    costs a few page faults instead of one per 4 kB (measured ~15 % of a 1e6-angle four-bar).  The
    returned arrays are views of the block and keep all of it alive."""
    block = np.empty((len(names), n))
    return {name: block[k] for k, name in enumerate(names)}


def _given_outputs(given, names, n):
    """The caller's buffers (``(block, assembles)``, checked) as the fields' views, or fresh ones."""
    if given is None:
        return _outputs(names, n), np.empty(n, dtype=bool)
    try:
        block, asm = given
    except (TypeError, ValueError):
        raise ValueError("out must be a pair (float block, bool assembles)") from None
    if not (isinstance(block, np.ndarray) and block.dtype == np.float64 and block.shape == (len(names), n)
            and block.flags.c_contiguous and block.flags.writeable):
        raise ValueError(f"out[0] must be a writable C-contiguous float64 array of shape ({len(names)}, {n})")
    if not (isinstance(asm, np.ndarray) and asm.dtype == np.bool_ and asm.shape == (n,) and asm.flags.writeable):
        raise ValueError(f"out[1] must be a writable bool array of shape ({n},)")
    return {name: block[k] for k, name in enumerate(names)}, asm


def four_bar_buffers(n: int) -> tuple[np.ndarray, np.ndarray]:
    """Output buffers for :func:`four_bar` over ``n`` crank angles (pass them as ``out=``)."""
    return np.empty((len(_FOURBAR_FIELDS), n)), np.empty(n, dtype=bool)


def _chunk_of(w, i, j):
    return w if isinstance(w, float) else w[i:j]


# --------------------------------------------------------------------------------------------
# Sine and cosine of the crank angle
# --------------------------------------------------------------------------------------------


def _sincos(th, c, s, t, u):
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


# --------------------------------------------------------------------------------------------
# Direction angles of the links
# --------------------------------------------------------------------------------------------

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


def _atan2(y, x, out, a, b, c, d, e, m) -> None:
    """out = atan2(y, x) in [-pi, pi] for 1-D arrays; a .. e (float) and m (bool) are scratch.

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
    np.minimum(a, b, out=c)
    np.maximum(a, b, out=d)
    c /= d  # z
    a -= b  # a < 0 where |y| > |x|
    np.greater(c, 0.66, out=m)
    np.add(c, 1.0, out=d)
    np.subtract(c, 1.0, out=b)
    b /= d
    np.copyto(c, b, where=m)  # z, now in [-0.205, 0.66]
    np.multiply(m, _QUARTER_PI, out=out)  # pi/4 where reduced
    np.multiply(c, c, out=d)  # w = z^2
    p0, p1, p2, p3, p4 = _ATAN_P
    np.multiply(d, p0, out=b)
    b += p1
    for k in (p2, p3, p4):
        b *= d
        b += k
    q0, q1, q2, q3, q4 = _ATAN_Q
    np.add(d, q0, out=e)
    for k in (q1, q2, q3, q4):
        e *= d
        e += k
    b *= d
    b /= e
    b *= c
    b += c  # atan(z)
    out += b
    np.less(a, 0.0, out=m)
    np.subtract(_HALF_PI, out, out=b)
    np.copyto(out, b, where=m)
    np.less(x, 0.0, out=m)
    np.subtract(math.pi, out, out=b)
    np.copyto(out, b, where=m)
    np.copysign(out, y, out=out)


# --------------------------------------------------------------------------------------------
# Four-bar
# --------------------------------------------------------------------------------------------

FOURBAR_FIELDS = _FOURBAR_FIELDS = ("Bx", "By", "Cx", "Cy", "theta2", "theta3", "omega2", "omega3",
                   "VBx", "VBy", "VCx", "VCy", "alpha2", "alpha3", "ABx", "ABy", "ACx", "ACy",
                   "condition")


def _crank_tip(c, s, r1, o1x, o1y, w, Bx, By, VBx, VBy) -> None:
    """B = O1 + r1 (cos, sin) and V_B = omega1 k x (B - O1) = omega1 r1 (-sin, cos), into the out arrays."""
    np.multiply(c, r1, out=Bx)
    if o1x:
        Bx += o1x
    np.multiply(s, r1, out=By)
    if o1y:
        By += o1y
    if isinstance(w, float):
        np.multiply(s, -w * r1, out=VBx)
        np.multiply(c, w * r1, out=VBy)
    else:
        np.multiply(s, w, out=VBx)
        VBx *= -r1
        np.multiply(c, w, out=VBy)
        VBy *= r1


def _crank_tip_acceleration(c, s, r1, w, a, ABx, ABy, t, u) -> None:
    """A_B = d/dt V_B into ABx, ABy; t and u are scratch.

    V_B = omega1 r1 (-sin, cos)(theta1) with theta1' = omega1 and omega1' = alpha1, so
    A_B = alpha1 r1 (-sin, cos) - omega1^2 r1 (cos, sin) = alpha1 k x r - omega1^2 r, r = B - O1:
    the tangential part square to the crank, the normal part towards O1.
    """
    if isinstance(w, float):
        nrm = -w * w * r1
    else:
        np.multiply(w, w, out=t)
        t *= -r1
        nrm = t
    np.multiply(c, nrm, out=ABx)  # -omega1^2 r1 cos
    np.multiply(s, nrm, out=ABy)  # -omega1^2 r1 sin
    if not isinstance(a, float) or a != 0.0:
        # the same operations for a scalar and an array alpha1: each element's value does not
        # depend on how alpha1 was given
        np.multiply(s, a, out=u)
        u *= -r1
        ABx += u
        np.multiply(c, a, out=u)
        u *= r1
        ABy += u


def four_bar(theta1, omega1, alpha1=0.0, *, crank_pivot, rocker_pivot, crank, coupler, rocker, branch,
             out=None):
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
    out : (ndarray, ndarray), optional
        The caller's output buffers, reused from call to call: a C-contiguous float64 array of shape
        ``(len(FOURBAR_FIELDS), n)`` (a row per field, in the order of :data:`FOURBAR_FIELDS`) and a bool
        array of ``n`` for ``assembles``; the result's arrays are views of them.  A long sweep repeated
        into the same buffers pays no page faults for fresh memory (see :func:`four_bar_buffers`).

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
    o1x, o1y = _point("crank_pivot", crank_pivot)
    o2x, o2y = _point("rocker_pivot", rocker_pivot)
    r1 = _length("crank", crank)
    r2 = _length("coupler", coupler)
    r3 = _length("rocker", rocker)
    br = _branch(branch)
    th, w1, a1, shape = _angles(theta1, omega1, alpha1)
    n = th.size

    scale = scene_size((r1, r2, r3), ((o1x, o1y), (o2x, o2y)))   # the one scene size
    tol = snap_tolerance(scale, max(abs(o1x), abs(o1y), abs(o2x), abs(o2y)))
    S = r2 + r3
    T = abs(r2 - r3)
    K = (r2 - r3) * (r2 + r3)  # coupler^2 - rocker^2 without squaring cancellation
    inv_2r2r3 = 1.0 / (2.0 * r2 * r3)
    check_d0 = T <= tol  # only then can d = 0 pass the gap test
    r2sq, r3sq = r2 * r2, r3 * r3
    half_sumsq = 0.5 * (r2sq + r3sq)  # p . q = half_sumsq - d^2 / 2

    out, asm_all = _given_outputs(out, _FOURBAR_FIELDS, n)
    m = min(CHUNK, max(n, 1))
    c, s, wx, wy, d2, d, f1, f2, tmp, inv, al, be = (np.empty(m) for _ in range(12))
    bt = np.empty(m, dtype=bool)

    with np.errstate(all="ignore"):  # NaN/inf handled explicitly below
        for i in range(0, n, CHUNK):
            j = min(i + CHUNK, n)
            k = j - i
            if k != m:  # last, short chunk: views of the scratch buffers
                c, s, wx, wy, d2, d, f1, f2, tmp, inv, al, be = (
                    a[:k] for a in (c, s, wx, wy, d2, d, f1, f2, tmp, inv, al, be))
                bt = bt[:k]
                m = k
            (Bx, By, Cx, Cy, t2, t3, om2, om3, VBx, VBy, VCx, VCy,
             al2, al3, ABx, ABy, ACx, ACy, cond) = (out[name][i:j] for name in _FOURBAR_FIELDS)
            asm = asm_all[i:j]
            w = _chunk_of(w1, i, j)
            a = _chunk_of(a1, i, j)

            _sincos(th[i:j], c, s, wx, wy)
            _crank_tip(c, s, r1, o1x, o1y, w, Bx, By, VBx, VBy)
            _crank_tip_acceleration(c, s, r1, w, a, ABx, ABy, wx, wy)
            # w = O2 - B, d
            np.subtract(o2x, Bx, out=wx)
            np.subtract(o2y, By, out=wy)
            np.multiply(wx, wx, out=d2)
            np.multiply(wy, wy, out=tmp)
            d2 += tmp
            np.sqrt(d2, out=d)
            # gap factors (S - d) and (d - T): exact differences near tangency
            np.subtract(S, d, out=f1)
            np.subtract(d, T, out=f2)
            if f1.min() > tol and f2.min() > tol:
                asm.fill(True)  # fast path: clearly closed at every angle of the chunk
            else:
                # three-way: gap < -tol apart (no assembly), |gap| <= tol tangent (snap to 0)
                np.greater_equal(f1, -tol, out=asm)
                np.greater_equal(f2, -tol, out=bt)
                asm &= bt
                if check_d0:
                    np.greater(d2, 0.0, out=bt)
                    asm &= bt
                np.less_equal(f1, tol, out=bt)
                np.copyto(f1, 0.0, where=bt)
                np.less_equal(f2, tol, out=bt)
                np.copyto(f2, 0.0, where=bt)
            np.add(d, S, out=tmp)
            f1 *= tmp
            np.add(d, T, out=tmp)
            f2 *= tmp
            f1 *= f2
            np.sqrt(f1, out=f1)  # f1 = sqrt(P) = 2 d h >= 0
            if not asm.all():
                # z = 0 where the loop closes, NaN elsewhere; NaN then propagates everywhere
                np.copyto(tmp, asm)
                np.divide(0.0, tmp, out=tmp)
                f1 += tmp
                Bx += tmp
                By += tmp
                VBx += tmp
                VBy += tmp
                ABx += tmp
                ABy += tmp
            np.multiply(f1, inv_2r2r3, out=cond)
            # p = C - B = alpha w + beta (k x w)
            np.divide(0.5, d2, out=inv)
            np.add(d2, K, out=al)
            al *= inv
            np.multiply(f1, inv, out=be)
            if br < 0:
                np.negative(be, out=be)
            np.multiply(al, wx, out=f2)  # f2 = px
            np.multiply(be, wy, out=tmp)
            f2 -= tmp
            np.multiply(al, wy, out=d)  # d = py (d no longer needed)
            np.multiply(be, wx, out=tmp)
            d += tmp
            np.add(Bx, f2, out=Cx)
            np.add(By, d, out=Cy)
            _atan2(d, f2, t2, c, s, tmp, inv, al, bt)
            # q = C - O2 = p - w  (into wx, wy)
            np.subtract(f2, wx, out=wx)
            np.subtract(d, wy, out=wy)
            _atan2(wy, wx, t3, c, s, tmp, inv, al, bt)
            # -1 / cross(p, q) = -2 branch / sqrt(P), NaN where the sine is below SINE_TOL
            np.divide(-2.0 * br, f1, out=inv)
            if not cond.min() >= SINE_TOL:  # (NaN min also lands here)
                np.less(cond, SINE_TOL, out=bt)
                np.copyto(inv, np.nan, where=bt)
            # omega2 = -(V_B . q)/cross(p,q);  omega3 = -(V_B . p)/cross(p,q)
            np.multiply(VBx, wx, out=om2)
            np.multiply(VBy, wy, out=tmp)
            om2 += tmp
            om2 *= inv
            np.multiply(VBx, f2, out=om3)
            np.multiply(VBy, d, out=tmp)
            om3 += tmp
            om3 *= inv
            # V_C = omega3 k x q
            np.multiply(om3, wy, out=VCx)
            np.negative(VCx, out=VCx)
            np.multiply(om3, wx, out=VCy)
            # accelerations (see Notes): al = omega2^2, be = omega3^2, c = p . q
            np.multiply(om2, om2, out=al)
            np.multiply(om3, om3, out=be)
            np.multiply(d2, -0.5, out=c)
            c += half_sumsq
            # alpha2 = -(R . q)/cross(p, q),  R . q = A_B . q - omega2^2 (p . q) + omega3^2 rocker^2
            np.multiply(ABx, wx, out=al2)
            np.multiply(ABy, wy, out=tmp)
            al2 += tmp
            np.multiply(al, c, out=tmp)
            al2 -= tmp
            np.multiply(be, r3sq, out=tmp)
            al2 += tmp
            al2 *= inv
            # alpha3 = -(R . p)/cross(p, q),  R . p = A_B . p - omega2^2 coupler^2 + omega3^2 (p . q)
            np.multiply(ABx, f2, out=al3)
            np.multiply(ABy, d, out=tmp)
            al3 += tmp
            np.multiply(al, r2sq, out=tmp)
            al3 -= tmp
            np.multiply(be, c, out=tmp)
            al3 += tmp
            al3 *= inv
            # A_C = alpha3 k x q - omega3^2 q = (-alpha3 q_y - omega3^2 q_x, alpha3 q_x - omega3^2 q_y)
            np.multiply(al3, wy, out=ACx)
            np.multiply(be, wx, out=tmp)
            ACx += tmp
            np.negative(ACx, out=ACx)
            np.multiply(al3, wx, out=ACy)
            np.multiply(be, wy, out=tmp)
            ACy -= tmp

    res = {name: out[name].reshape(shape) for name in _FOURBAR_FIELDS}
    return FourBarState(assembles=asm_all.reshape(shape), **res)


# --------------------------------------------------------------------------------------------
# Slider-crank
# --------------------------------------------------------------------------------------------

_SLIDER_FIELDS = ("Bx", "By", "Cx", "Cy", "theta2", "omega2", "VBx", "VBy", "VCx", "VCy",
                  "slider_speed", "alpha2", "ABx", "ABy", "ACx", "ACy", "slider_acceleration",
                  "condition")


def slider_crank(theta1, omega1, alpha1=0.0, *, crank_pivot, crank, coupler, guide_point, guide_angle,
                 branch):
    """Closed-form positions, velocities and accelerations of an (offset) slider-crank, vectorised.

    Parameters
    ----------
    theta1 : float or array_like
        Crank angle(s), direction O1 -> B (rad, CCW from +x).
    omega1 : float or array_like
        Crank angular velocity (rad/s, CCW positive); broadcast against ``theta1``.
    alpha1 : float or array_like, optional
        Crank angular acceleration (rad/s^2, CCW positive), default 0 (constant speed); broadcast
        against ``theta1`` and ``omega1``.
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
    o1x, o1y = _point("crank_pivot", crank_pivot)
    gx, gy = _point("guide_point", guide_point)
    r1 = _length("crank", crank)
    l = _length("coupler", coupler)
    g = float(guide_angle)
    if not math.isfinite(g):
        raise ValueError(f"guide_angle must be finite, got {guide_angle!r}")
    br = _branch(branch)
    th, w1, a1, shape = _angles(theta1, omega1, alpha1)
    n = th.size

    ex, ey = math.cos(g), math.sin(g)
    nx, ny = -ey, ex
    y0 = (o1x - gx) * nx + (o1y - gy) * ny
    scale = scene_size((r1, l), ((o1x, o1y),), (((gx, gy), g),))   # the one scene size
    tol = snap_tolerance(scale, max(abs(o1x), abs(o1y), abs(gx), abs(gy)))
    inv_l = 1.0 / l

    out = _outputs(_SLIDER_FIELDS, n)
    asm_all = np.empty(n, dtype=bool)
    m = min(CHUNK, max(n, 1))
    c, s, y, h, tmp, px, py, inv, e5 = (np.empty(m) for _ in range(9))
    bt = np.empty(m, dtype=bool)

    with np.errstate(all="ignore"):  # NaN/inf handled explicitly below
        for i in range(0, n, CHUNK):
            j = min(i + CHUNK, n)
            k = j - i
            if k != m:
                c, s, y, h, tmp, px, py, inv, e5 = (
                    a[:k] for a in (c, s, y, h, tmp, px, py, inv, e5))
                bt = bt[:k]
                m = k
            (Bx, By, Cx, Cy, t2, om2, VBx, VBy, VCx, VCy, spd,
             al2, ABx, ABy, ACx, ACy, acc, cond) = (out[name][i:j] for name in _SLIDER_FIELDS)
            asm = asm_all[i:j]
            w = _chunk_of(w1, i, j)
            a = _chunk_of(a1, i, j)

            _sincos(th[i:j], c, s, px, py)
            _crank_tip(c, s, r1, o1x, o1y, w, Bx, By, VBx, VBy)
            _crank_tip_acceleration(c, s, r1, w, a, ABx, ABy, px, py)
            # y = y0 + crank (s ex - c ey)   (signed distance of B from the guide)
            np.multiply(s, ex * r1, out=y)
            np.multiply(c, ey * r1, out=tmp)
            y -= tmp
            y += y0
            # half-chord h = sqrt((l - y)(l + y))
            np.subtract(l, y, out=h)
            np.add(y, l, out=tmp)
            if h.min() > tol and tmp.min() > tol:
                asm.fill(True)  # fast path: C clearly reaches the guide at every angle
            else:
                # three-way: gap < -tol apart (no assembly), |gap| <= tol tangent (snap to 0)
                np.greater_equal(h, -tol, out=asm)
                np.greater_equal(tmp, -tol, out=bt)
                asm &= bt
                np.less_equal(h, tol, out=bt)
                np.copyto(h, 0.0, where=bt)
                np.less_equal(tmp, tol, out=bt)
                np.copyto(tmp, 0.0, where=bt)
            h *= tmp
            np.sqrt(h, out=h)
            if not asm.all():
                np.copyto(tmp, asm)
                np.divide(0.0, tmp, out=tmp)
                h += tmp
                Bx += tmp
                By += tmp
                VBx += tmp
                VBy += tmp
                ABx += tmp
                ABy += tmp
            np.multiply(h, inv_l, out=cond)
            # p = C - B = -y n + branch h e
            if br < 0:
                np.negative(h, out=h)  # h now holds branch*h
            np.multiply(y, -nx, out=px)
            np.multiply(h, ex, out=tmp)
            px += tmp
            np.multiply(y, -ny, out=py)
            np.multiply(h, ey, out=tmp)
            py += tmp
            np.add(Bx, px, out=Cx)
            np.add(By, py, out=Cy)
            _atan2(py, px, t2, c, s, tmp, inv, e5, bt)
            # omega2 = -(V_B . n) / (branch h)
            np.divide(-1.0, h, out=inv)
            if not cond.min() >= SINE_TOL:  # (NaN min also lands here)
                np.less(cond, SINE_TOL, out=bt)
                np.copyto(inv, np.nan, where=bt)
            np.multiply(VBx, nx, out=om2)
            np.multiply(VBy, ny, out=tmp)
            om2 += tmp
            om2 *= inv
            # slider_speed = V_B . e + omega2 y;  V_C = slider_speed e
            np.multiply(VBx, ex, out=spd)
            np.multiply(VBy, ey, out=tmp)
            spd += tmp
            np.multiply(om2, y, out=tmp)
            spd += tmp
            np.multiply(spd, ex, out=VCx)
            np.multiply(spd, ey, out=VCy)
            # accelerations (see Notes), c = omega2^2 (c, s are free after the crank tip):
            # alpha2 = -(A_B . n + omega2^2 y) / (branch h)
            np.multiply(om2, om2, out=c)
            np.multiply(ABx, nx, out=al2)
            np.multiply(ABy, ny, out=tmp)
            al2 += tmp
            np.multiply(c, y, out=tmp)
            al2 += tmp
            al2 *= inv
            # sddot = A_B . e - omega2^2 (branch h) + alpha2 y;  A_C = sddot e
            np.multiply(ABx, ex, out=acc)
            np.multiply(ABy, ey, out=tmp)
            acc += tmp
            np.multiply(c, h, out=tmp)
            acc -= tmp
            np.multiply(al2, y, out=tmp)
            acc += tmp
            np.multiply(acc, ex, out=ACx)
            np.multiply(acc, ey, out=ACy)

    res = {name: out[name].reshape(shape) for name in _SLIDER_FIELDS}
    return SliderCrankState(assembles=asm_all.reshape(shape), **res)


# --------------------------------------------------------------------------------------------
# Coupler point
# --------------------------------------------------------------------------------------------


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
    accel = all(given)
    inputs = [Bx, By, VBx, VBy, theta2, omega2] + ([ABx, ABy, alpha2] if accel else [])
    arrs = np.broadcast_arrays(*(np.asarray(v, dtype=np.float64) for v in inputs))
    shape = arrs[0].shape
    flat = [np.ascontiguousarray(v).reshape(-1) for v in arrs]
    bx, by, vbx, vby, t2, w2 = flat[:6]
    n = bx.size
    Dx, Dy, VDx, VDy = (np.empty(n) for _ in range(4))
    if accel:
        abx, aby, a2 = flat[6:]
        ADx, ADy = np.empty(n), np.empty(n)
    else:
        ADx = ADy = None
    m = min(CHUNK, max(n, 1))
    c, s, t, u = (np.empty(m) for _ in range(4))
    with np.errstate(all="ignore"):
        for i in range(0, n, CHUNK):
            j = min(i + CHUNK, n)
            k = j - i
            if k != m:
                c, s, t, u = (v[:k] for v in (c, s, t, u))
                m = k
            np.add(t2[i:j], ang, out=t)
            _sincos(t, c, s, u, Dx[i:j])  # u and the Dx slice are scratch here
            # r = D - B = distance (c, s);  V_D = V_B + omega2 (-r_y, r_x)
            c *= dist
            s *= dist
            np.add(bx[i:j], c, out=Dx[i:j])
            np.add(by[i:j], s, out=Dy[i:j])
            np.multiply(w2[i:j], s, out=VDx[i:j])
            np.subtract(vbx[i:j], VDx[i:j], out=VDx[i:j])
            np.multiply(w2[i:j], c, out=VDy[i:j])
            VDy[i:j] += vby[i:j]
            if accel:
                # A_D = A_B + alpha2 (-r_y, r_x) - omega2^2 (r_x, r_y)
                np.multiply(w2[i:j], w2[i:j], out=t)  # omega2^2
                np.multiply(a2[i:j], s, out=u)
                np.subtract(abx[i:j], u, out=ADx[i:j])
                np.multiply(t, c, out=u)
                ADx[i:j] -= u
                np.multiply(a2[i:j], c, out=u)
                np.add(aby[i:j], u, out=ADy[i:j])
                np.multiply(t, s, out=u)
                ADy[i:j] -= u
    if not accel:
        ADx = np.full(n, np.nan)
        ADy = np.full(n, np.nan)
    return PointState(Dx=Dx.reshape(shape), Dy=Dy.reshape(shape),
                      VDx=VDx.reshape(shape), VDy=VDy.reshape(shape),
                      ADx=ADx.reshape(shape), ADy=ADy.reshape(shape))
