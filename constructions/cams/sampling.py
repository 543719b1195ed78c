"""The profile alone, for export, machining and the benchmark: the exact envelope at just enough cam angles
that every chord between neighbouring points stays within a tolerance of the true curve.

The chord error.  A chord over a step ``h`` of the parameter of a smooth curve ``C(theta)`` strays from the
curve by ``h^2 g / 8`` to leading order, with the *chord-error rate* ``g = |C' x C''| / |C'|`` (length per
rad^2; ``|C'|^2`` times the curvature).  Rotation leaves ``|C'|`` and ``C' x C''`` alone, so the fixed frame
(the follower's) serves; with the pitch point ``q(theta)`` there, ``v1 = q' - sigma J q`` and ``v2 = q'' -
2 sigma J q' - q`` are the cam-frame ``P'``, ``P''`` turned back (:mod:`.envelope`).

- Roller (knife edge: ``rr = 0``): ``C = P - rr n`` with ``n`` the pitch curve's outward normal, so ``C' = (1 -
  rr k) P'`` with ``k = -sigma c / v^3`` its convex curvature (``c = v1 x v2``, ``v = |v1|``), and ``C' x C''
  = (1 - rr k)^2 c``: ``g = |c| / v * |1 + sigma rr c / v^3|``.  For a translating follower ``q = (e, r)``,
  ``r = d0 + s``: ``v1 = (sigma r, s' - sigma e)``, ``v2 = (2 sigma s' - e, s'' - r)``.  In a dwell ``g`` is
  the radius of the profile's arc, ``|sqrt(e^2 + r^2) - rr|``.
- Flat face: ``C = (rb + s) u + sigma s' w`` gives ``C' = sigma rho w`` and ``C'' = sigma rho' w - rho u``
  (``rho = rb + s + s''``, :mod:`.envelope`), so ``g = |rho|``.  An oscillating flat face's normal turns at
  ``phi' = -(sigma + s')`` against the cam, so ``|C'| = |rho phi'|`` and ``g = |rho| (sigma + s')^2``.

The sampling.  The program is cut into its smooth pieces (segments; a parabola's two halves), each stepped
evenly on its own with its ends as samples (a join, where s'' and the curvature jump, is always a point):
the step is ``sqrt(8 tol / g_max)`` with ``g_max`` the piece's largest rate, searched on a grid of
:data:`GRID` points (one-sided at the ends), refined by the parabola through the best point and its
neighbours and raised by :data:`~constructions.tolerance.CHORD_MARGIN`.  A dwell's rate is its arc's
radius, exactly.  The points need only s and s' (no s'', curvature, pressure angle or jerk, which
:func:`.envelope.evaluate` computes for the drawing and the checks).  The tests measure the chord error of the result against the exact curve
between every pair of neighbours.

Corners.  Where s' jumps (uniform motion meeting a dwell) the pitch curve has a corner.  A roller's
profile there is, at a reflex corner, an arc of the roller circle about the corner (sampled at the same
tolerance); at a convex corner the branches cross, and the loop between them is trimmed away
(the two polylines cut where they cross).  A flat face's contact slides along the face line between the two one-sided
points (a straight piece, exact as a chord), or slides back (a fold, trimmed).  A knife edge keeps the
corner itself.
"""

from __future__ import annotations

import math
import numpy as np

from ..tolerance import CHORD_MARGIN, CORNER_SLOPE_REL, ONE_SIDED_INSET
from .follower import FLAT, KNIFE, OSC_FLAT, OSCILLATING, Follower, face_terms
from .frames import quarter_turn as _J
from .laws import DWELL, INNER_JOINS, NORMALISED, Program, normalised_low

GRID = 48
"""Grid points per smooth piece on which the largest chord-error rate is searched."""


def pieces(program: Program) -> list[tuple[int, float, float, float, float]]:
    """(segment, u0, u1, theta0, theta1) of every smooth piece of the program: its segments, a parabolic
    segment split at its middle (where s'' jumps)."""
    out = []
    for i, seg in enumerate(program.segments):
        cuts = (0.0,) + (INNER_JOINS.get(seg.law, ()) if seg.kind != DWELL else ()) + (1.0,)
        t0 = program.starts[i]
        for u0, u1 in zip(cuts[:-1], cuts[1:]):
            out.append((i, u0, u1, t0 + u0 * seg.beta, t0 + u1 * seg.beta))
    return out


def _fixed_frame(f: Follower, s, d1, d2=None):
    """The pitch point q and its derivatives q', q'' against the cam angle in the fixed frame (2 x N)."""
    if f.kind == OSCILLATING:
        g = f.gamma0 - s
        L = f.arm_length
        c, sn = np.cos(g), np.sin(g)
        q = np.stack([f.pivot_distance + L * c, L * sn])
        q1 = np.stack([L * sn * d1, -L * c * d1])              # dq/dpsi = -L J u, times s'
        q2 = None if d2 is None else np.stack([-L * c * d1 * d1 + L * sn * d2, -L * sn * d1 * d1 - L * c * d2])
        return q, q1, q2
    e, d0 = (f.offset, f.d0) if f.kind != FLAT else (0.0, f.base_radius)
    z = np.zeros_like(s)
    q = np.stack([np.full_like(s, e), d0 + s])
    return q, np.stack([z, d1]), None if d2 is None else np.stack([z, d2])


def chord_error_rate(f: Follower, s, d1, d2) -> np.ndarray:
    """``g = |C' x C''| / |C'|`` of the profile at the given s, s', s'' (arrays; SI length per rad^2): a chord
    over a step ``h`` of cam angle strays ``h^2 g / 8`` from the profile (see the module's notes)."""
    sg = f.sense
    if f.kind == FLAT:
        return np.abs(f.base_radius + s + d2)
    if f.kind == OSC_FLAT:
        _, _, _, rho, turn = face_terms(f, s, d1, d2)
        return np.abs(rho) * turn * turn
    if f.kind == OSCILLATING:
        q, q1, q2 = _fixed_frame(f, s, d1, d2)
        v1 = q1 - sg * _J(q)
        v2 = q2 - 2 * sg * _J(q1) - q
        c = v1[0] * v2[1] - v1[1] * v2[0]
        v = np.hypot(v1[0], v1[1])
    else:
        e = f.offset
        r = f.d0 + s
        w = d1 - sg * e
        c = sg * r * (d2 - r) - w * (2 * sg * d1 - e)
        v = np.sqrt(r * r + w * w)
    return np.abs(c) / v * np.abs(1.0 + sg * f.roller_radius * c / (v * v * v))


def _dwell_rate(f: Follower, level: float) -> float:
    """A dwell's profile is an arc about O: its radius."""
    if f.kind == FLAT:
        return abs(f.base_radius + level)
    if f.kind == OSC_FLAT:
        return abs(f.pivot_distance * math.sin(f.beta0 + level) - f.face_offset)
    if f.kind == OSCILLATING:
        a, L, g = f.pivot_distance, f.arm_length, f.gamma0 - level
        return abs(math.sqrt(a * a + L * L + 2 * a * L * math.cos(g)) - f.roller_radius)
    return abs(math.hypot(f.offset, f.d0 + level) - f.roller_radius)


def rate_max(program: Program, f: Follower, cuts) -> list[float]:
    """The largest chord-error rate on each piece: a dwell's exactly, a motion's on a grid just inside its
    ends (one-sided values), the best grid point refined by the parabola through it and its neighbours."""
    moving = [k for k, pc in enumerate(cuts) if program.segments[pc[0]].kind != DWELL]
    out = [_dwell_rate(f, program.levels[pc[0]]) for pc in cuts]
    if not moving:
        return out
    x = np.linspace(ONE_SIDED_INSET, 1.0 - ONE_SIDED_INSET, GRID)
    ss, d1s, d2s = [], [], []
    for k in moving:
        i, u0, u1 = cuts[k][:3]
        seg = program.segments[i]
        fv = NORMALISED[seg.law](u0 + (u1 - u0) * x)
        h = seg.sign * seg.lift
        ss.append(program.levels[i] + h * fv[0])
        d1s.append((h / seg.beta) * fv[1])
        d2s.append((h / seg.beta ** 2) * fv[2])
    g = chord_error_rate(f, np.concatenate(ss), np.concatenate(d1s), np.concatenate(d2s)).reshape(len(moving), GRID)
    ks = np.argmax(g, axis=1)
    for row, k, j in zip(g, ks, moving):
        best = float(row[k])
        if 0 < k < GRID - 1:
            a, b, c = float(row[k - 1]), best, float(row[k + 1])
            den = a - 2 * b + c
            if den < 0:
                best = max(best, b - (c - a) ** 2 / (8 * den))
        out[j] = best
    return out


def profile_samples(program: Program, f: Follower, tolerance: float) -> tuple[np.ndarray, np.ndarray]:
    """The exact envelope at just enough cam angles: ``(theta, points)``, the points 2 x N in the cam frame
    (closed: the last point is not repeated) at the cam angles ``theta``, every chord between neighbours
    within ``tolerance`` (SI length) of the true profile (see the module's notes).  ``theta`` repeats along
    a roller's arc at a corner, and is NaN at the crossing where a fold is cut (no cam angle of its own)."""
    if not tolerance > 0:
        raise ValueError("the tolerance must be positive")
    cuts = pieces(program)
    gmax = rate_max(program, f, cuts)
    n = len(cuts)
    # a corner after piece k where s' jumps: keep the piece's own end point there too (a knife edge's point
    # is the corner itself, the same from either side)
    corner = [f.kind != KNIFE and abs(program.end_velocity(cuts[k][0], cuts[k][2])
                                    - program.end_velocity(cuts[(k + 1) % n][0], cuts[(k + 1) % n][1]))
              > CORNER_SLOPE_REL * program.lift for k in range(n)]
    ss, dd, tt, first = [], [], [], []
    at = 0
    for k, (pc, g) in enumerate(zip(cuts, gmax)):
        i, u0, u1, t0, t1 = pc
        width = t1 - t0
        m = max(2, math.ceil(width * math.sqrt(g * CHORD_MARGIN / (8.0 * tolerance)))) if g > 0 else 2
        j = np.arange(m + 1 if corner[k] else m) / m
        first.append(at)
        at += len(j)
        tt.append(t0 + width * j)
        seg = program.segments[i]
        if seg.kind == DWELL:
            ss.append(np.full(len(j), program.levels[i]))
            dd.append(np.zeros(len(j)))
            continue
        f0, f1 = normalised_low(seg.law, u0 + (u1 - u0) * j)
        h = seg.sign * seg.lift
        ss.append(program.levels[i] + h * f0)
        dd.append((h / seg.beta) * f1)
    s, d1, th = np.concatenate(ss), np.concatenate(dd), np.concatenate(tt)
    sg = f.sense
    # the contact point in the fixed frame (x, y), then turned back through the cam angle
    if f.kind == FLAT:
        x, y = sg * d1, f.base_radius + s
    elif f.kind == OSC_FLAT:
        beta, c, t, _, _ = face_terms(f, s, d1)
        cb, sb = np.cos(beta), np.sin(beta)
        x, y = c * sb - t * cb, c * cb + t * sb          # c n + t J n, n = (sin beta, cos beta)
    elif f.kind == OSCILLATING:
        q, q1, _ = _fixed_frame(f, s, d1)
        v1 = q1 - sg * _J(q)
        k = f.roller_radius * sg / np.hypot(v1[0], v1[1])
        x, y = q[0] + k * v1[1], q[1] - k * v1[0]
    else:
        # q = (e, r), v1 = (sigma r, s' - sigma e): C = q - rr sigma J v1 / |v1|
        e = f.offset
        r = f.d0 + s
        if f.kind == KNIFE:
            x, y = np.full_like(s, e), r
        else:
            w = d1 - sg * e
            k = f.roller_radius / np.sqrt(r * r + w * w)
            x, y = e + sg * k * w, r - k * r
    c, sn = np.cos(th), sg * np.sin(th)
    C = np.stack([c * x + sn * y, c * y - sn * x])
    if not any(corner):
        return th, C
    return _corners(program, f, tolerance, th, C, s, d1, first, corner)


def _corners(program, f, tol, th, C, s, d1, first, corner):
    """Where s' jumps: a roller's arc at a reflex corner; where the profile folds back (a roller's convex
    corner, a flat face's contact sliding back), the two branches cut at their crossing."""
    sg, n, N = f.sense, len(first), len(th)
    parts: list[list[np.ndarray]] = []            # [theta, points] of each piece, then of each arc
    folds: list[int] = []                          # indices into parts of a piece whose end folds into the next
    for k in range(n):
        lo, hi = first[k], first[k + 1] if k + 1 < n else N
        parts.append([th[lo:hi], C[:, lo:hi]])
        if not corner[k]:
            continue
        e, j = hi - 1, hi % N                       # the piece's end and the next piece's start
        if f.kind == FLAT:
            if d1[j] < d1[e]:                       # the contact slides back along the face
                folds.append(len(parts) - 1)
            continue
        if f.kind == OSC_FLAT:
            t = face_terms(f, s[[e, j]], d1[[e, j]])[2]
            if sg * (t[1] - t[0]) > 0:              # the contact slides back along the face
                folds.append(len(parts) - 1)
            continue
        q, q1, _ = _fixed_frame(f, s[[e, j]], d1[[e, j]])
        v1 = q1 - sg * _J(q)
        if sg * (v1[0, 0] * v1[1, 1] - v1[1, 0] * v1[0, 1]) < 0:     # a convex corner: the branches cross
            folds.append(len(parts) - 1)
            continue
        # a reflex corner: the roller circle's arc about it, from one normal to the other
        nl, nr = sg * _J(v1[:, 0]), sg * _J(v1[:, 1])
        a0, a1 = math.atan2(nl[1], nl[0]), math.atan2(nr[1], nr[0])
        da = (a1 - a0 + math.pi) % (2 * math.pi) - math.pi
        rr = f.roller_radius
        m = max(1, math.ceil(abs(da) / math.sqrt(8.0 * tol / (rr * CHORD_MARGIN))))
        phi = a0 + da * np.arange(1, m) / m
        x, y = q[0, 0] - rr * np.cos(phi), q[1, 0] - rr * np.sin(phi)
        c, sn = math.cos(th[e]), sg * math.sin(th[e])
        parts.append([np.full(m - 1, th[e]), np.stack([c * x + sn * y, c * y - sn * x])])
    for i in folds:
        left, right = parts[i], parts[(i + 1) % len(parts)]
        a, b, X = _branch_crossing(left[1], right[1])
        left[0] = np.append(left[0][:a + 1], math.nan)
        left[1] = np.concatenate([left[1][:, :a + 1], X[:, None]], axis=1)
        right[0], right[1] = right[0][b + 1:], right[1][:, b + 1:]
    return np.concatenate([p[0] for p in parts]), np.concatenate([p[1] for p in parts], axis=1)


def _branch_crossing(L: np.ndarray, R: np.ndarray) -> tuple[int, int, np.ndarray]:
    """Where the polyline L (ending at a fold) crosses the polyline R (starting there): ``(a, b, X)`` with the
    crossing X on L's chord a..a+1 and R's chord b..b+1 (the one nearest the fold), searched over the last
    and first 16, 64, 256 ... chords; if the chords never cross (a fold smaller than a chord), L's last chord
    and R's first are extended to meet."""
    nl, nr = L.shape[1] - 1, R.shape[1] - 1
    w = 16
    while True:
        wl, wr = min(w, nl), min(w, nr)
        p, r = L[:, nl - wl:nl], L[:, nl - wl + 1:nl + 1] - L[:, nl - wl:nl]
        q, v = R[:, :wr], R[:, 1:wr + 1] - R[:, :wr]
        den = r[0][:, None] * v[1][None, :] - r[1][:, None] * v[0][None, :]
        dx, dy = q[0][None, :] - p[0][:, None], q[1][None, :] - p[1][:, None]
        with np.errstate(divide="ignore", invalid="ignore"):
            t = (dx * v[1][None, :] - dy * v[0][None, :]) / den
            u = (dx * r[1][:, None] - dy * r[0][:, None]) / den
        ok = (t >= 0) & (t <= 1) & (u >= 0) & (u <= 1) & (den != 0)
        if ok.any():
            ii, jj = np.nonzero(ok)
            k = int(np.argmin((wl - 1 - ii) + jj))
            i, j = int(ii[k]), int(jj[k])
            return nl - wl + i, j, p[:, i] + t[i, j] * r[:, i]
        if wl == nl and wr == nr:
            break
        w *= 4
    a0, a1, b0, b1 = L[:, -2], L[:, -1], R[:, 0], R[:, 1]
    d, e = a1 - a0, b1 - b0
    den = d[0] * e[1] - d[1] * e[0]
    t = ((b0 - a0)[0] * e[1] - (b0 - a0)[1] * e[0]) / den
    return nl - 1, 0, a0 + t * d


def profile_points(program: Program, f: Follower, tolerance: float) -> np.ndarray:
    """The exact envelope, dense enough that the polyline through the points stays within ``tolerance``
    (SI length) of the true profile (2 x N, closed: the last point is not repeated).  Every point is exact
    (or, where a fold is trimmed, the crossing of two chords); only the chords between them approximate.
    See :func:`profile_samples`."""
    return profile_samples(program, f, tolerance)[1]


__all__ = ["profile_samples", "profile_points", "chord_error_rate", "pieces", "rate_max", "GRID"]
