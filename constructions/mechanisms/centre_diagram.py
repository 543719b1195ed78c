"""The instant-centre diagram: the links where they stand, each centre Kennedy finds with the two lines
that found it (clipped to the region drawn), and the circle diagram beside them."""

from __future__ import annotations

import itertools
import math

from ..entities import Arrow, Bar, Point, Role, Segment
from ..geometry import Vec
from ..record import Construction, StepKind
from .centres import CIRCLE, DIAGRAM, FAR, Centre, centre_name
from .model import Mechanism


def link_bars(m: Mechanism, pos) -> list:
    """Each link as bars between its points (a ternary link as all its sides), faint: the centres matter."""
    out = []
    for k in m.links:
        pts = [p for p in m.points_of(k.number) if p in pos]
        for a, b in itertools.combinations(pts, 2):
            if (pos[a] - pos[b]).norm() > 0:
                out.append(Bar(f"ic link {k.number} {a}{b}", Role.GIVEN, DIAGRAM, pos[a], pos[b], k.number))
    return out



def _centre_entities(c: Centre, norm) -> tuple:
    name = centre_name(c.bodies)
    if c.finite and norm(c.at).norm() <= FAR:
        return (Point(f"ic {name}", Role.RESULT, DIAGRAM, c.at, name),)
    return ()


POINTER = 0.3
"""The arrow towards a centre off the drawing is 0.3 mechanism sizes long."""


def kennedy_entities(c: Centre, found, norm, mid: Vec, size: float) -> tuple:
    """The found centre (if near) and its two lines, from the centres on them toward it, clipped to the
    region the diagram shows.

    The rule for a centre off the drawing: one within FAR mechanism sizes of the middle is drawn (the view
    grows to hold it and the scale stays readable); one farther, or at infinity, gets an arrow on from the
    end of its first line towards it, labelled with its coordinates ("I_02 at (412 mm, -87 mm)", the
    step's values) or "I_02 \u2192 \u221e"."""
    out = list(_centre_entities(c, norm))
    name = centre_name(c.bodies)
    pointer = None
    for idx, (a, b) in enumerate(c.lines):
        ends = [found[x] for x in (a, b)] + [c]
        seg = _clip_line(ends, mid, size)
        if seg is not None:
            out.append(Segment(f"ic {name} line {idx + 1}", Role.AUXILIARY, DIAGRAM, seg[0], seg[1]))
            pointer = pointer or _pointer(c, seg, name, size)
    if not out or isinstance(out[0], Segment):
        out += [pointer] if pointer is not None else []
    return tuple(out)


def _pointer(c: Centre, seg: tuple[Vec, Vec], name: str, size: float) -> Arrow | None:
    """An arrow from the end of the line ``seg`` nearer the centre ``c`` (off the drawing) towards it."""
    if c.finite:
        end = min(seg, key=lambda p: (p - c.at).norm())
        d = c.at - end
        label = f"{name} at ($x, $y)"
    else:
        d = c.direction if (seg[1] - seg[0]).dot(c.direction) >= 0 else c.direction * -1.0
        end = seg[1] if (seg[1] - seg[0]).dot(d) >= 0 else seg[0]
        label = f"{name} \u2192 \u221e"
    if not d.norm() > 0:
        return None
    return Arrow(f"ic {name} off the drawing", Role.DIMENSION, DIAGRAM, end, end + d.unit() * (POINTER * size),
                 label)


def infinity_arrow(name: str, at: Vec, normal: Vec, guide: str, size: float) -> Arrow:
    """A block's centre at infinity: an arrow from the block along the normal to its ``guide`` ("guide",
    "slot"), labelled "I_03 \u2192 \u221e \u22a5 guide"."""
    return Arrow(f"ic {name} at infinity", Role.DIMENSION, DIAGRAM, at, at + normal.unit() * (POINTER * size),
                 f"{name} \u2192 \u221e \u22a5 {guide}")


def _clip_line(centres: list[Centre], mid: Vec, size: float) -> tuple[Vec, Vec] | None:
    """The stretch of the line through ``centres`` that covers the finite ones within the drawn region
    (FAR sizes about the middle), a little past them."""
    near = [c.at for c in centres if c.finite and (c.at - mid).norm() <= FAR * size]
    if not near:
        return None
    far = [c for c in centres if not (c.finite and (c.at - mid).norm() <= FAR * size)]
    if len(near) >= 2:
        d = max(((p, q) for p in near for q in near), key=lambda t: (t[0] - t[1]).norm())
        direction = (d[1] - d[0]).unit() if (d[1] - d[0]).norm() > 0 else None
    else:
        direction = None
    if direction is None and far:
        c = far[0]
        direction = c.direction if not c.finite else (c.at - near[0]).unit()
    if direction is None:
        return None
    ts = [(p - near[0]).dot(direction) for p in near]
    lo, hi = min(ts), max(ts)
    pad = 0.15 * size
    if far:                                            # run on toward the centre off the drawing
        target = far[0]
        toward = target.direction if not target.finite else (target.at - near[0])
        if toward.dot(direction) > 0:
            hi = max(hi, lo) + 0.6 * size
        else:
            lo = min(lo, hi) - 0.6 * size
    return near[0] + direction * (lo - pad), near[0] + direction * (hi + pad)


def drawn_box(rec: Construction) -> tuple[float, float, float, float]:
    """(xmin, ymin, xmax, ymax) of what the instant-centre diagram holds so far."""
    pts: list[Vec] = []
    for e in rec.entities(DIAGRAM):
        for name in ("at", "start", "end"):
            v = getattr(e, name, None)
            if isinstance(v, Vec):
                pts.append(v)
    return (min(p.x for p in pts), min(p.y for p in pts), max(p.x for p in pts), max(p.y for p in pts))


def circle_diagram(rec: Construction, bodies, found, size: float, box) -> Construction:
    """The circle diagram, beside the centres in the same diagram (it has no scale of its own): the bodies
    on a circle, a chord for each centre (solid: from a joint, dashed: by Kennedy)."""
    x0, y0, x1, y1 = box
    r = max(0.2 * max(x1 - x0, y1 - y0), 0.3 * size)
    centre = Vec(x1 + 1.6 * r, 0.5 * (y0 + y1))
    n = len(bodies)
    at = {b: centre + Vec(-r * math.sin(2 * math.pi * i / n), r * math.cos(2 * math.pi * i / n))
          for i, b in enumerate(bodies)}
    ents = [Point(f"circle {b}", Role.LABEL, CIRCLE, at[b], str(b)) for b in bodies]
    for q, c in found.items():
        role = Role.AUXILIARY if c.lines or "Kennedy" in c.how else Role.GIVEN
        ents.append(Segment(f"circle {centre_name(q)}", role, CIRCLE, at[q[0]], at[q[1]]))
    return rec.then("The circle diagram: one chord per centre found, solid where a joint gives it, dashed "
                    "where Kennedy's theorem does (each dashed chord closes two triangles of known chords).",
                    *ents, kind=StepKind.CONSTRUCTION)

