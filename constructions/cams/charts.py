"""The s-v-a-j diagrams of a motion program against the cam angle, as chart entities.

Each piece of the program (a segment, or half a parabolic one) is sampled on its own, ends included, so a
jump at a join shows as a break in the curve (a NaN between the pieces), never as a drawn vertical line;
the join's consequence (infinite acceleration where the velocity jumps, infinite jerk where the
acceleration jumps) is named in the step's words.  With the cam's speed ``omega`` the curves are v, a and
j in SI; without it, s', s'' and s''' per radian (charted as lengths: m per rad^k).
"""

from __future__ import annotations

import math

import numpy as np

from ..entities import Chart, Curve, Diagram, Note, Point, Role, Segment, Series
from ..geometry import Vec
from ..tolerance import ONE_SIDED_INSET, SVAJ_JUMP_REL
from .laws import Program
from .search import segment_breaks


def chart_diagram(name: str) -> Diagram:
    return Diagram("chart", name)


def svaj_series(program: Program, omega: float | None, per_piece: int = 48):
    """(x, [s, v, a, j]) as tuples with NaN breaks where a value jumps between pieces."""
    b = segment_breaks(program)
    w = abs(omega) if omega else 1.0
    xs: list[float] = []
    ys: list[list[float]] = [[], [], [], []]
    prev_end = None
    for lo, hi in zip(b[:-1], b[1:]):
        if hi - lo <= 0:
            continue
        g = np.linspace(lo, hi, per_piece)
        # evaluate just inside the piece so each end takes this piece's one-sided value
        eps = (hi - lo) * ONE_SIDED_INSET     # well inside: a station within START_SNAP of a start reads that segment
        gi = np.clip(g, lo + eps, hi - eps)
        d = program.derivatives(gi)
        vals = [d[0], d[1] * w, d[2] * w ** 2, d[3] * w ** 3]
        if prev_end is not None:
            jump = [abs(vals[k][0] - prev_end[k]) > SVAJ_JUMP_REL * (1.0 + np.max(np.abs(vals[k]))) for k in range(4)]
            if any(jump):
                xs.append(float(lo))
                for k in range(4):
                    ys[k].append(math.nan if jump[k] else float(vals[k][0]))
        xs.extend(float(x) for x in g)
        for k in range(4):
            ys[k].extend(float(v) for v in vals[k])
        prev_end = [vals[k][-1] for k in range(4)]
    return tuple(xs), [tuple(y) for y in ys]


def svaj_charts(program: Program, omega: float | None, angular: bool = False) -> list[Chart]:
    """The four charts; ``angular`` for an oscillating follower, whose lift is an angle."""
    x, ys = svaj_series(program, omega)
    # a NaN row inserted at a jump must not break curves that do not jump there: fill their value
    out = []
    if angular:
        spec = (("\u03c8", "Swing \u03c8", "angle"),
                ("\u03c9 (rad/s)" if omega else "d\u03c8/d\u03b8", "Angular velocity" if omega else "d\u03c8/d\u03b8",
                 "angular velocity" if omega else "number"),
                ("\u03b1 (rad/s\u00b2)" if omega else "d\u00b2\u03c8/d\u03b8\u00b2", "Angular acceleration" if omega
                 else "d\u00b2\u03c8/d\u03b8\u00b2", "angular acceleration" if omega else "number"),
                ("d\u03b1/dt (rad/s\u00b3)" if omega else "d\u00b3\u03c8/d\u03b8\u00b3", "Angular jerk" if omega
                 else "d\u00b3\u03c8/d\u03b8\u00b3", "number"))
    elif omega:
        spec = (("s", "Displacement s", "length"), ("v", "Velocity v", "velocity"),
                ("a", "Acceleration a", "acceleration"), ("j (m/s\u00b3)", "Jerk j", "jerk"))
    else:
        spec = (("s", "Displacement s", "length"), ("ds/d\u03b8", "ds/d\u03b8 (per rad)", "length"),
                ("d\u00b2s/d\u03b8\u00b2", "d\u00b2s/d\u03b8\u00b2 (per rad\u00b2)", "length"),
                ("d\u00b3s/d\u03b8\u00b3", "d\u00b3s/d\u03b8\u00b3 (per rad\u00b3)", "length"))
    for (label, title, kind), y in zip(spec, ys):
        xx, yy = _fill(x, y)
        out.append(Chart(f"chart {label}", Role.GIVEN, chart_diagram(title), "angle", "cam angle",
                         (Series(label, xx, yy, kind),)))
    return out


def _fill(x, y):
    """Drop the extra row at a join for a curve that is continuous there (its NaN-free duplicate)."""
    xx, yy = [], []
    for i, (a, b) in enumerate(zip(x, y)):
        if i and a == x[i - 1] and not math.isnan(b) and not math.isnan(y[i - 1]) and b == y[i - 1]:
            continue
        xx.append(a)
        yy.append(b)
    return tuple(xx), tuple(yy)




def displacement_diagram(program: Program, stations, table, scale: float, label_every: int, length: float,
                         origin: Vec, diagram: Diagram, axis_x: float | None = None) -> list:
    """The displacement diagram as the notes draw it beside the cam: the cam angle laid out from
    ``origin`` along an abscissa ``length`` long, divided into the construction's stations and numbered as
    on the cam (every ``label_every``-th), the lift ``table`` (times ``scale``: 1 for a translating
    follower, the arm's length for a swing) set up on each station's line and the curve of the program
    through their tops.  With ``axis_x`` (the follower's line at station 0, parallel to the station lines)
    the largest lift is projected across to it."""
    n = len(stations)
    x_of = length / (2 * math.pi)
    tick = 0.02 * length
    ox, oy = origin.x, origin.y
    out: list = [Segment("displacement axis", Role.PATH, diagram, origin, Vec(ox + length, oy))]
    for i in range(n + 1):
        x, y = ox + i * length / n, float(table[i % n]) * scale
        out.append(Segment(f"station tick {i}", Role.PATH, diagram, Vec(x, oy), Vec(x, oy - tick)))
        if abs(y) > 1e-9 * length:
            out.append(Segment(f"station line {i}", Role.AUXILIARY, diagram, Vec(x, oy), Vec(x, oy + y)))
            out.append(Point(f"lift {i}", Role.PATH, diagram, Vec(x, oy + y)))
        if i % label_every == 0:
            out.append(Note(f"station number {i}", Role.LABEL, diagram, Vec(x, oy - 3.5 * tick), f"{i}"))
    xs, ys = svaj_series(program, None)
    pts = tuple(Vec(ox + a * x_of, oy + b * scale) for a, b in zip(xs, ys[0]) if math.isfinite(b))
    out.append(Curve("displacement curve", Role.RESULT, diagram, pts))
    out.append(Note("displacement title", Role.LABEL, diagram, Vec(ox + length / 2, oy - 8 * tick),
                    "displacement diagram"))
    k = int(np.argmax(np.asarray(table)))
    top = float(table[k]) * scale
    if axis_x is not None and top > 0:
        out.append(Segment("lift projection", Role.AUXILIARY, diagram, Vec(ox + k * length / n, oy + top),
                           Vec(axis_x, oy + top)))
    return out

__all__ = ["svaj_charts", "svaj_series", "chart_diagram", "displacement_diagram"]
