"""Accuracy against time for a cam profile: the analytic envelope, the envelope of N roller circles drawn
as a drafter does (each contact point on the normal of the chord through the neighbouring roller centres),
and a polygon offset (shapely's inward buffer of the pitch polygon), each at several resolutions.

The error is the largest distance between the method's polyline and the exact profile (a symmetric
Hausdorff distance against the analytic envelope at 2^17 points, whose own chord error is below 1e-9 of the
cam size), as a fraction of the cam size (prime circle + lift); the time is the median of 51 runs.  The cam is
the notes' roller cam (base 1.5 in, roller 0.5 in, SHM 0.8 in).  The profile-only path
(:func:`constructions.cams.sampling.profile_points`) is run at several chord tolerances; at 1e-6 of the cam
size it is the default (what the export writes).

Usage: ``python benchmarks/cam_profile.py [--chart gallery/cam-accuracy-time.svg]`` (the chart: log-log, error
against milliseconds, an SVG and a PNG beside it).
"""

import math
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))  # run from a checkout, uninstalled
sys.path.insert(0, str(Path(__file__).resolve().parent))

import loglog_chart as ch  # noqa: E402

import numpy as np  # noqa: E402
from shapely.geometry import Polygon  # noqa: E402

from constructions.cams.laws import DWELL, HARMONIC, RETURN, RISE, TAU, Program, Segment  # noqa: E402
from constructions.cams.envelope import evaluate  # noqa: E402
from constructions.cams.follower import ROLLER, Follower  # noqa: E402
from constructions.cams.sampling import profile_points  # noqa: E402

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


REPEAT = 51


def timed(fn, *a, repeat=REPEAT):
    """(result, median seconds of ``repeat`` runs)."""
    out, ts = None, []
    for _ in range(repeat):
        t0 = time.perf_counter()
        out = fn(*a)
        ts.append(time.perf_counter() - t0)
    return out, float(np.median(ts))


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


SERIES = ("analytic envelope, N even steps", "profile-only path at a tolerance", "envelope of N roller circles",
          "polygon offset (shapely buffer)")
RESOLUTIONS = (36, 144, 576, 2304, 9216)
TOLERANCES = (1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8)


def rows():
    """(method, N or tolerance, points, median ms, error / size) for every method and resolution."""
    p, f = notes_cam()
    size = f.prime_radius + p.lift
    ref = analytic(p, f, 2 ** 17)
    out = []
    for name, fn in ((SERIES[0], analytic), (SERIES[2], roller_circles), (SERIES[3], polygon_offset)):
        for n in RESOLUTIONS:
            pts, t = timed(fn, p, f, n)
            out.append((name, n, len(pts), t * 1e3, error(pts, ref, size)))
    for rel in TOLERANCES:
        pts, t = timed(profile_points, p, f, rel * size)
        out.append((SERIES[1], rel, pts.shape[1], t * 1e3, error(pts.T, ref, size)))
    return out


# -- the chart: error against time, log-log (benchmarks/loglog_chart.py) -----------------------------------

def chart_svg(data, path: Path, default_rel: float = 1e-6) -> None:
    """The log-log chart of error against milliseconds, one line and marker per method."""
    xr, yr = ch.ranges([r[3] for r in data], [r[4] for r in data])
    dwg, g = ch.axes(path, xr, yr)
    # the 1 ms aimed at, and the default tolerance
    x1ms = ch.pos(1.0, 10 ** yr[0], xr, yr)[0]
    g.add(dwg.line((x1ms, ch.Y0), (x1ms, ch.Y1), stroke="black", stroke_width=0.25, stroke_dasharray="2,1"))
    ytol = ch.pos(10 ** xr[0], default_rel, xr, yr)[1]
    g.add(dwg.line((ch.X0, ytol), (ch.X1, ytol), stroke="black", stroke_width=0.25, stroke_dasharray="2,1"))
    ch.lines(dwg, g, [(name, [(r[3], r[4]) for r in data if r[0] == name]) for name in SERIES], xr, yr)
    ch.label(dwg, g, "1 ms", x1ms + 1.2, ch.Y0 + 4.0)
    ch.label(dwg, g, "1e-6 of the cam size", ch.X1 - 2.0, ytol + 4.2, "end")
    # the default: circled, its label at the lower left of the point
    dx, dy = next(ch.pos(r[3], r[4], xr, yr) for r in data if r[0] == SERIES[1] and r[1] == default_rel)
    g.add(dwg.circle((dx, dy), 2.6, fill="none", stroke="black", stroke_width=0.3))
    g.add(dwg.line((dx - 1.9, dy + 1.9), (dx - 8.0, dy + 8.0), stroke="black", stroke_width=0.25))
    ch.label(dwg, g, "the default (1e-6)", dx - 8.5, dy + 11.0, "end")
    ch.legend(dwg, g, SERIES)
    ch.titles(dwg, g, "time per profile (ms, median of %d runs)" % REPEAT, "largest error / cam size (no unit)")
    dwg.save()             # not pretty: whitespace between a number and its exponent would show


def main(argv=None) -> int:
    import argparse
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--chart", type=Path, help="write the log-log chart here (SVG; a PNG beside it)")
    a = ap.parse_args(argv)
    data = rows()
    print(f"{'method':34} {'N / tol':>7} {'points':>7} {'ms':>8} {'error / size':>13}")
    for name, n, m, ms, err in data:
        print(f"{name:34} {n:7.0e} {m:7d} {ms:8.3f} {err:13.2e}" if isinstance(n, float) else
              f"{name:34} {n:7d} {m:7d} {ms:8.3f} {err:13.2e}")
    if a.chart:
        chart_svg(data, a.chart)
        ch.png(a.chart)
        print(f"wrote {a.chart} and {a.chart.with_suffix('.png')}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
