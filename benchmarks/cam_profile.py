"""Accuracy against time for a cam profile: the analytic envelope, the envelope of N roller circles drawn
as a drafter does (each contact point on the normal of the chord through the neighbouring roller centres),
and a polygon offset (shapely's inward buffer of the pitch polygon), each at several resolutions.

The error is the largest distance between the method's polyline and the exact profile (a symmetric
Hausdorff distance against the analytic envelope at 2^17 points, whose own chord error is below 1e-9 of the
cam size), as a fraction of the cam size (prime circle + lift); the time is the best of 7 runs.  The cam is
the notes' roller cam (base 1.5 in, roller 0.5 in, SHM 0.8 in).  The last row is the default: the analytic
envelope sampled for a chord error of 1e-6 of the cam size (:func:`constructions.cams.profile.profile_points`).

Usage: ``python benchmarks/cam_profile.py``
"""

import math
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))  # run from a checkout, uninstalled

import numpy as np  # noqa: E402
from shapely.geometry import Polygon  # noqa: E402

from constructions.cams.laws import DWELL, HARMONIC, RETURN, RISE, TAU, Program, Segment  # noqa: E402
from constructions.cams.profile import ROLLER, Follower, evaluate, profile_points  # noqa: E402

IN = 0.0254
D = math.radians


def notes_cam():
    p = Program([Segment(DWELL, D(120)), Segment(RISE, D(60), 0.8 * IN, HARMONIC), Segment(DWELL, D(30)),
                 Segment(RETURN, D(150), 0.8 * IN, HARMONIC)])
    return p, Follower(ROLLER, 1.5 * IN, 0.5 * IN)


def analytic(p, f, n):
    return evaluate(p, f, np.linspace(0, TAU, n, endpoint=False)).profile.T


def roller_circles(p, f, n):
    """Roller centres from s alone; each contact point on the normal of the chord P(i-1) P(i+1)."""
    th = np.linspace(0, TAU, n, endpoint=False)
    P = evaluate(p, f, th).pitch          # the construction's roller centres (exact, as in the notes' step 7)
    t = np.roll(P, -1, axis=1) - np.roll(P, 1, axis=1)
    t /= np.hypot(*t)
    nrm = f.sense * np.stack([-t[1], t[0]])
    return (P - f.roller_radius * nrm).T


def polygon_offset(p, f, n):
    P = evaluate(p, f, np.linspace(0, TAU, n, endpoint=False)).pitch
    return np.asarray(Polygon(P.T).buffer(-f.roller_radius, quad_segs=8).exterior.coords)


def best(fn, *a, repeat=7):
    out, t = None, math.inf
    for _ in range(repeat):
        t0 = time.perf_counter()
        out = fn(*a)
        t = min(t, time.perf_counter() - t0)
    return out, t


def _to_polyline(q, poly):
    """Distance from each point of q (M x 2) to the closed polyline poly (N x 2); both curves wind once
    round O, so the nearest segments are found by polar angle (the segment spanning the point's angle
    and two either side)."""
    ang = np.unwrap(np.arctan2(poly[:, 1], poly[:, 0]))
    if ang[-1] < ang[0]:
        poly, ang = poly[::-1], ang[::-1]
    ang = ang - ang[0]
    a0 = np.mod(np.arctan2(poly[0, 1], poly[0, 0]), TAU)
    qa = np.mod(np.arctan2(q[:, 1], q[:, 0]) - a0, TAU)
    k = np.searchsorted(ang, qa) - 1
    n = len(poly)
    best_d = np.full(len(q), np.inf)
    for off in range(-3, 4):
        i = np.mod(k + off, n)
        a, b = poly[i], poly[np.mod(i + 1, n)]
        ab = b - a
        u = np.clip(np.sum((q - a) * ab, axis=1) / np.maximum(np.sum(ab * ab, axis=1), 1e-300), 0, 1)
        d = np.hypot(*(q - (a + u[:, None] * ab)).T)
        best_d = np.minimum(best_d, d)
    return best_d


def error(points, exact, size: float) -> float:
    """The symmetric largest distance between the polyline through ``points`` and the exact profile."""
    return max(float(np.max(_to_polyline(exact, points))), float(np.max(_to_polyline(points, exact)))) / size


def rows():
    p, f = notes_cam()
    size = f.prime_radius + p.lift
    exact = analytic(p, f, 2 ** 17)
    ref = exact
    out = []
    for name, fn in (("analytic envelope", analytic), ("envelope of N roller circles", roller_circles),
                     ("polygon offset (shapely buffer)", polygon_offset)):
        for n in (36, 144, 576, 2304, 9216):
            pts, t = best(fn, p, f, n)
            out.append((name, n, len(pts), t * 1e3, error(pts, ref, size)))
    pts, t = best(profile_points, p, f, 1e-6 * size)
    out.append(("default: analytic at 1e-6", pts.shape[1], pts.shape[1], t * 1e3, error(pts.T, ref, size)))
    return out


if __name__ == "__main__":
    print(f"{'method':34} {'N':>6} {'points':>7} {'ms':>8} {'error / size':>13}")
    for name, n, m, ms, err in rows():
        print(f"{name:34} {n:6d} {m:7d} {ms:8.3f} {err:13.2e}")
