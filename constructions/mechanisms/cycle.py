"""A linkage over its whole cycle, as a record to draw: charts against the crank angle and the paths of
the scene's points on the space diagram.

From a :class:`constructions.sweep.Sweep` (analytic, vectorised; NaN where the mechanism cannot be
assembled) this builds

- the output's motion: the rocker angle of the crank's four-bar, or the slider's travel along its guide;
- the angular velocity and the angular acceleration of every link but the crank;
- the transmission angle of the crank's four-bar with the usual 40-140 deg band shaded;
- the coupler curve of every point the scene fixes to a link ([[point]]), drawn on the space diagram and
  broken where the mechanism cannot be assembled (a gap is never bridged).

Every chart shares the crank angle as its x axis, counted on from the drawn angle through one turn.
"""

from __future__ import annotations

import math

import numpy as np

from ..entities import AngleMark, Chart, Curve, Diagram, Point, Role, Segment, Series
from ..geometry import Vec
from ..record import Construction, StepKind, Value
from ..sweep import Sweep
from .classify import FourBarClass
from .model import Mechanism

BAND = (math.radians(40.0), math.radians(140.0), "40\u2013140\u00b0")
"""The usual range of a transmission angle (notes, "Transmission angle")."""


def chart_diagram(name: str) -> Diagram:
    return Diagram("chart", name)


def transmission_angles(k: FourBarClass, s: Sweep) -> np.ndarray:
    """The angle between coupler and rocker at C (rad, 0..pi) at every swept angle (NaN at gaps)."""
    _, b, c, o2 = k.joints
    bx, by = (np.asarray(a) for a in s.positions[b])
    cx, cy = (np.asarray(a) for a in s.positions[c])
    ox, oy = (np.asarray(a) for a in s.positions[o2]) if o2 in s.positions else (None, None)
    if ox is None:
        raise KeyError(o2)
    ux, uy, vx, vy = bx - cx, by - cy, ox - cx, oy - cy
    return np.abs(np.arctan2(ux * vy - uy * vx, ux * vx + uy * vy))


def _rocker_angle(k: FourBarClass, s: Sweep) -> np.ndarray:
    _, _, c, o2 = k.joints
    cx, cy = (np.asarray(a) for a in s.positions[c])
    ox, oy = (np.asarray(a) for a in s.positions[o2])
    return np.unwrap(np.arctan2(cy - oy, cx - ox)) if np.all(np.isfinite(cx)) else np.arctan2(cy - oy, cx - ox)


def _runs(x: np.ndarray, y: np.ndarray) -> list[tuple[Vec, ...]]:
    """The stretches of a path between gaps (NaN), each as points."""
    out: list[tuple[Vec, ...]] = []
    cur: list[Vec] = []
    for a, b in zip(x, y):
        if math.isfinite(a) and math.isfinite(b):
            cur.append(Vec(float(a), float(b)))
        elif cur:
            out.append(tuple(cur))
            cur = []
    if cur:
        out.append(tuple(cur))
    return out


def one_turn(th: tuple[float, ...]) -> tuple[list[int], tuple[float, ...]]:
    """The sweep's samples in the order a chart draws them over one turn, 0 to 360 deg: the indices and
    the crank angles reduced to [0, 2 pi).  The sweep starts at the drawn pose and its last sample closes
    the turn (the first pose again); a sample at 0 is drawn again at 2 pi, so the curve spans the turn."""
    turn = 2 * math.pi
    n = len(th)
    if n > 1 and abs(th[-1] - th[0] - turn) < 1e-9:
        n -= 1                                          # the closing sample is the first pose again
    phi = [t % turn for t in th[:n]]
    phi = [0.0 if p < 1e-9 or p > turn - 1e-9 else p for p in phi]
    order = sorted(range(n), key=phi.__getitem__)
    xs = [phi[i] for i in order]
    if order and xs[0] < 1e-9:
        order.append(order[0])
        xs.append(turn)
    return order, tuple(xs)


def cycle_record(m: Mechanism, s: Sweep, k: FourBarClass | None, degrees) -> Construction:
    """The charts and coupler curves of the sweep ``s``; ``degrees(rad)`` writes an angle for a caption."""
    th = tuple(float(t) for t in s.thetas)
    n = len(th)
    step = (th[1] - th[0]) if n > 1 else 0.0
    steps = n - 1 if n > 1 and abs(th[-1] - th[0] - 2 * math.pi) < 1e-9 else n
    rec = Construction("Over the cycle").then(
        f"Turn the crank through one turn from {degrees(th[0])} in {steps} steps of {degrees(step)}: at each the "
        f"positions, velocities and accelerations come from the {s.model} (analytic), on the branch the scene "
        f"chose" + (f"; at {', '.join(degrees(a) for a in s.change_points)} all its links lie in line (a change "
                    f"point) and it keeps to that branch, the way on whose velocities run on smoothly"
                    if s.change_points else "") + ".", kind=StepKind.GIVEN)

    order, xs = one_turn(th)

    def series(label: str, y, kind: str) -> Series:
        ys = tuple(float(y[i]) for i in order)
        return Series(label, xs, ys, kind)

    # the output's motion
    blocks = m.blocks()
    if k is not None and k.joints[2] in s.positions and k.joints[3] in s.positions:
        rec = rec.then("The rocker's angle O2C against the crank angle: the output's swing.",
                       Chart("chart rocker angle", Role.GIVEN, chart_diagram("Output angle"), "angle", "crank angle",
                             (series(f"rocker {k.joints[3]}{k.joints[2]}", _rocker_angle(k, s), "angle"),)),
                       kind=StepKind.CONSTRUCTION)
    elif any(b.on is None for b in blocks.values()):
        sl = next(b for b in blocks.values() if b.on is None)    # the output: a block on a fixed guide
        x, y = (np.asarray(a) for a in s.positions[sl.joint])
        d = sl.line.direction
        if d is not None:
            travel = (x - sl.line.point.x) * d.x + (y - sl.line.point.y) * d.y
            rec = rec.then("The slider's travel along its guide against the crank angle (from the point the "
                           "guide is given through).",
                           Chart("chart slider travel", Role.GIVEN, chart_diagram("Slider travel"), "angle",
                                 "crank angle", (series(f"block {sl.number} at {sl.joint}", travel, "length"),)),
                           kind=StepKind.CONSTRUCTION)
    others = [n_ for n_ in sorted(s.angular) if n_ != m.crank and n_ not in blocks]
    if others:
        rec = rec.then("The angular velocities of the links against the crank angle.",
                       Chart("chart omega", Role.GIVEN, chart_diagram("Angular velocities"), "angle", "crank angle",
                             tuple(series(f"\u03c9_{n_}", s.angular[n_], "angular velocity") for n_ in others)),
                       kind=StepKind.CONSTRUCTION)
        acc = [n_ for n_ in others if n_ in s.angular_acceleration]
        if acc:
            rec = rec.then("The angular accelerations of the links against the crank angle.",
                           Chart("chart alpha", Role.GIVEN, chart_diagram("Angular accelerations"), "angle",
                                 "crank angle", tuple(series(f"\u03b1_{n_}", s.angular_acceleration[n_],
                                                             "angular acceleration") for n_ in acc)),
                           kind=StepKind.CONSTRUCTION)
    if k is not None and all(j in s.positions for j in k.joints[1:]):
        mu = transmission_angles(k, s)
        rec = rec.then("The transmission angle between coupler and rocker against the crank angle, the usual "
                       "40\u2013140\u00b0 band shaded.",
                       Chart("chart transmission", Role.GIVEN, chart_diagram("Transmission angle"), "angle",
                             "crank angle", (series("\u03bc", mu, "angle"),), (BAND,)),
                       kind=StepKind.CONSTRUCTION)
    rec = _limit_positions(rec, m, k, s, degrees)
    paths = []
    for a in m.attached:
        if a.name not in s.positions:
            continue
        x, y = (np.asarray(v) for v in s.positions[a.name])
        for i, run in enumerate(_runs(x, y)):
            if len(run) >= 2:
                closed = not s.gaps() and len(run) == n
                paths.append(Curve(f"path of {a.name} {i + 1}", Role.PATH, Diagram.SPACE, run, closed,
                                   f"path of {a.name}" if i == 0 else None))
    if paths:
        names = sorted({p.name.split()[2] for p in paths})
        rec = rec.then(f"The coupler curve{'s' if len(names) > 1 else ''} of {', '.join(names)}: the path over the "
                       f"turn, on the space diagram" + (" (broken where the linkage cannot be assembled)."
                                                         if s.gaps() else "."),
                       *paths, kind=StepKind.CONSTRUCTION)
    return rec


def _limit_positions(rec: Construction, m: Mechanism, k: FourBarClass | None, s: Sweep, degrees) -> Construction:
    """The rocker's two limit positions on the space diagram (crank and coupler in line, found by
    construction in :mod:`constructions.mechanisms.classify`), dashed, with the rocker's swing between them."""
    if k is None or len(k.limit_positions) != 2:
        return rec
    o1, _, c, o2 = k.joints
    O1, O2 = m.ground[o1], m.ground[o2]
    a = k.lengths[1]
    ents = []
    for lp, mark in zip(k.limit_positions, ("'", "''")):
        b = O1 + Vec.polar(a, lp.crank_angle)
        how = "extended" if lp.extended else "folded"
        ents += [Segment(f"limit {how} crank", Role.AUXILIARY, Diagram.SPACE, O1, b),
                 Segment(f"limit {how} coupler", Role.AUXILIARY, Diagram.SPACE, b, lp.C),
                 Segment(f"limit {how} rocker", Role.AUXILIARY, Diagram.SPACE, O2, lp.C),
                 Point(f"limit {how} {c}", Role.LABEL, Diagram.SPACE, lp.C, f"{c}{mark}")]
    r1, r2 = (lp.rocker_angle for lp in k.limit_positions)
    cx, cy = (float(np.asarray(v)[0]) for v in s.positions[c])
    now = math.atan2(cy - O2.y, cx - O2.x)
    lo, hi = (r1, r2) if (now - r1) % (2 * math.pi) <= (r2 - r1) % (2 * math.pi) else (r2, r1)
    swing = (hi - lo) % (2 * math.pi)
    ents.append(AngleMark("rocker swing", Role.DIMENSION, Diagram.SPACE, O2, 0.6 * k.lengths[3], lo, lo + swing,
                          "$swing"))
    return rec.then(f"The rocker's limit positions, {c}' and {c}'': crank and coupler in line, extended "
                    f"({o1}{c}' = crank + coupler) and folded ({o1}{c}'' = coupler \u2212 crank), each where the "
                    f"circle about {o1} meets the rocker's circle about {o2}; between them the rocker swings "
                    f"through $swing.", *ents, values={"swing": Value("angle", swing)},
                    kind=StepKind.CONSTRUCTION)
