"""The mechanism's drawn symbols, on paper: a fixed pivot's ground (triangle, ground line, hatching, pin)
turned to the side away from its links, the hatching of a fixed line, and the size of a slider block.  The
sheets' drawers (:mod:`drafting.render.drawers`) and the sweep card of the step-through page
(:mod:`drafting.backends.sweep_mechanism`) draw the same symbols with them.
"""

from __future__ import annotations

import math
from typing import Sequence

from .drawing import PIN_R, Pt, angle_gap, shifted
from .paper import Circle, Command, Line, Polygon, Rect, Strokes

BLOCK_L = 10.0          # a slider block, mm along its guide ...
BLOCK_H = 6.0           # ... and across it
HATCH_STEP = 1.6        # hatching: a stroke every HATCH_STEP mm ...
HATCH_LEN = 1.8         # ... leaning back this far
GROUND_SIDES = ((0.0, 1.0), (-1.0, 0.0), (1.0, 0.0), (0.0, -1.0))
"""The sides a ground symbol may stand on (paper, y down), down first: the drafter's habit."""
SIDE_TIE = 1e-9
"""rad: a side must leave the links more room than this before it displaces one met earlier."""


def ground_side(incident: Sequence[float]) -> Pt:
    """Of down, left, right and up (paper), the side furthest in angle from the ``incident`` directions
    (paper angles of the lines leaving the pivot)."""
    best, best_gap = GROUND_SIDES[0], -1.0
    for cand in GROUND_SIDES:
        a = math.atan2(cand[1], cand[0])
        gap = min((angle_gap(a, b) for b in incident), default=math.pi)
        if gap > best_gap + SIDE_TIE:
            best, best_gap = cand, gap
    return best


def ground_symbol(p: Pt, u: Pt, name: str) -> tuple[list[Command], Rect]:
    """A fixed pivot at paper point ``p`` grounded on the side of unit ``u``: ground triangle, ground line,
    hatching and pin, and the box of the ground (which labels must not cover)."""
    n = (-u[1], u[0])
    c = shifted(p, u, 4.0)
    tri = (p, shifted(c, n, 3.0), shifted(c, n, -3.0))
    a, b = shifted(c, n, -4.5), shifted(c, n, 4.5)
    pts = list(tri) + [a, b]
    strokes = []
    s = -4.5 + HATCH_STEP / 2
    while s <= 4.5:
        q = shifted(c, n, s)
        r = shifted(shifted(q, u, HATCH_LEN), n, -HATCH_LEN)
        strokes.append((q, r))
        pts.append(r)
        s += HATCH_STEP
    pts += [(p[0] - PIN_R, p[1] - PIN_R), (p[0] + PIN_R, p[1] + PIN_R)]        # the pin, whole
    return ([Polygon(tri, "ground", f"{name}:ground"), Line(*a, *b, "link", f"{name}:ground line"),
             Strokes(tuple(strokes), "hatch", f"{name}:hatch"), Circle(*p, PIN_R, "pin", f"{name}:pin")],
            Rect.bounding(pts))


def hatching(a: Pt, u: Pt, length: float, side: Pt, name: str) -> Strokes | None:
    """The hatching of a line ``length`` mm long from ``a`` along the unit vector ``u``: a stroke every
    HATCH_STEP, leaning back from the line towards the unit vector ``side``; None when the line is too
    short for one."""
    s = HATCH_STEP / 2
    ux, uy, sx, sy = u[0], u[1], side[0] * HATCH_LEN, side[1] * HATCH_LEN
    back_x, back_y = ux * -HATCH_LEN, uy * -HATCH_LEN
    strokes = []
    while s < length:
        qx, qy = a[0] + ux * s, a[1] + uy * s                    # shifted(a, u, s)
        strokes.append(((qx, qy), (qx + sx + back_x, qy + sy + back_y)))
        s += HATCH_STEP
    return Strokes(tuple(strokes), "hatch", name) if strokes else None


__all__ = ["BLOCK_L", "BLOCK_H", "ground_side", "ground_symbol", "hatching"]
