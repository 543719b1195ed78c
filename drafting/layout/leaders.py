"""Leaders: the thin line that ties a label to what it names when the label cannot sit beside it -- a
short arrow's (always); an arrow's, a trial line's or a point's set off 2.5-8 mm (where the leader runs
through no other label or mark and across no other heavy line, and makes the label clearly its entity's);
one set 8-15 mm off where such a leader is clear (:func:`far_leader`, :func:`far_test`); in a crowded
polygon, as the last resort before an ambiguous place, a leader of up to 15 mm that crosses at most two
other heavy lines, each steeply (:func:`crossings_of`); a note's or a dimension's set off its point
(whatever it crosses: the text must be read where it was put).

The label placer (:mod:`drafting.layout.labels`) asks here whether a candidate place would get a leader
and whether that leader is clear; the leaders are drawn under every label's white ground.
"""

from __future__ import annotations

import math

from ..render.drawing import Drawing, LabelReq
from ..render.paper import Line, Rect
from .label_kin import clip_fraction


def led_test(req: LabelReq, clear, placed: list[Rect], d: Drawing, longest: float | None = None,
             crossings: int = 0):
    """The test of a candidate set off its arrow, trial line or point (2.5 mm to ``longest``, by default
    :data:`LONGEST_LEADER`): its leader (:func:`led_leader`) runs through no label or symbol and across no
    other heavy line (or no more than ``crossings`` of them, each steeply: a long leader out of a crowded
    pole), and the text is
    farther from every other entity of its kind than from that leader by the critic's margin -- the
    leader names what the label names."""
    def test(le: float, to: float, ri: float, bo: float) -> bool:
        box = Rect(le, to, ri - le, bo - to)
        leader = led_leader(req, box, longest)
        if leader is None or not runs_clear(leader, placed, d, crossings):
            return False
        return clear.with_ours([leader.points])(le, to, ri, bo)
    return test


def led(req: LabelReq, box: Rect) -> bool:
    """Whether ``req``'s label in ``box`` stands off its arrow or trial line far enough to be drawn with a
    leader (a short arrow's leader is drawn whatever it crosses, and kept clear of nothing)."""
    return req.kind in ("arrow", "trial") and req.other is not None and not short(req) \
        and leader_of(req, box) is not None


def sparing(clear, leaders: list[Line]):
    """``clear`` (or no test) and, besides, a box that hides none of ``leaders``."""
    def test(le: float, to: float, ri: float, bo: float) -> bool:
        box = Rect(le, to, ri - le, bo - to)
        return clear_of(leaders, box) and (clear is None or clear(le, to, ri, bo))
    return test


def clear_of(lines: list[Line], box: Rect) -> bool:
    return all(clear_line(line, [box]) for line in lines)


SHORT_ARROW = 5.0
"""mm: an arrow shorter than this cannot carry its label along it; a leader ties the label to it."""
FAR_LABEL = 2.5
"""mm: a label whose box stands off its own arrow's shaft farther than this (the places beside the arrow
were taken) is tied to it by a leader, as a draughtsman does, so the reader need not guess its arrow --
up to :data:`LONGEST_LEADER`: a longer thin line across a polygon reads as one more construction line."""
LONGEST_LEADER = 8.0
LONG_LEADER = 15.0
"""mm: the longest leader, for a label of a crowded polygon that has no clear place nearer its entity
(better one long leader that names it than a label as near another vector as its own)."""


def clear_line(line: Line, boxes: list[Rect]) -> bool:
    """Whether ``line`` passes through none of ``boxes``."""
    x1, y1 = line.x1, line.y1
    dx, dy = line.x2 - x1, line.y2 - y1
    for o in boxes:                 # (a loop: the placer asks this of every candidate's leader)
        if clip_fraction(x1, y1, dx, dy, o.left, o.top, o.right, o.bottom) > 0:
            return False
    return True


def runs_clear(leader: Line, labels: list[Rect], d: Drawing, crossings: int = 0) -> bool:
    """Whether ``leader`` runs through none of ``labels`` and no mark of ``d`` but the one it starts at, and
    across no more than ``crossings`` of its heavy lines (each steeply: :func:`crossings_of`)."""
    return (clear_line(leader, labels + [h for h in d.hard if not h.contains_point(leader.x1, leader.y1)])
            and crossings_of(leader, d.segments, crossings + 1) <= crossings)


def crosses_heavy(line: Line, segments) -> bool:
    """Whether ``line`` crosses a heavy line (a vector, a link...) other than the one it starts on: a
    leader across another arrow would seem to name that one."""
    return crossings_of(line, segments, 1) > 0


STEEP = math.sin(math.radians(40.0))
"""A leader may cross a heavy line (on a long leader only) at no less than 40 degrees: a shallow crossing
reads as the leader leaving that line."""


def crossings_of(line: Line, segments, enough: int) -> int:
    """How many heavy lines ``line`` crosses, other than the one it starts on, counting up to ``enough``;
    a crossing shallower than :data:`STEEP` counts as ``enough`` at once."""
    p, r = (line.x1, line.y1), (line.x2 - line.x1, line.y2 - line.y1)
    rn = math.hypot(*r)
    n = 0
    for a, b, thick in segments:
        if not thick:
            continue
        q, s = a, (b[0] - a[0], b[1] - a[1])
        den = r[0] * s[1] - r[1] * s[0]
        if abs(den) < 1e-12:
            continue
        wx, wy = q[0] - p[0], q[1] - p[1]
        t, u = (wx * s[1] - wy * s[0]) / den, (wx * r[1] - wy * r[0]) / den
        if 1e-3 < t <= 1.0 and 0.0 <= u <= 1.0:       # (t = 0: the shaft the leader starts on)
            n += 1 if abs(den) >= STEEP * rn * math.hypot(*s) else enough
            if n >= enough:
                return n
    return n


def short(req: LabelReq) -> bool:
    """Whether ``req`` labels an arrow too short to carry its label (its leader is drawn whatever it
    crosses: the label cannot sit on the arrow)."""
    return req.kind == "arrow" and req.other is not None and math.dist(req.anchor, req.other) < SHORT_ARROW


def leader_of(req: LabelReq, box: Rect, longest: float | None = None) -> Line | None:
    """A thin leader to a label's box from the middle of a short arrow, or from the nearest point of a
    long arrow's shaft when the box stands off it by more than :data:`FAR_LABEL` (and less than
    :data:`LONGEST_LEADER`, or ``longest``); None for a label that needs none (not an arrow, or beside its arrow) or that
    a leader would not serve."""
    if req.other is None or req.kind not in ("arrow", "trial", "note"):
        return None
    if req.kind == "note":          # from the point it names (a dimension line's middle), when set off it
        mx, my = req.other
        qx, qy = min(max(mx, box.left), box.right), min(max(my, box.top), box.bottom)
        if math.hypot(qx - mx, qy - my) <= FAR_LABEL:
            return None
        return Line(mx, my, qx, qy, "dimension", f"{req.name}:leader")
    (ax, ay), (bx, by) = req.anchor, req.other
    if not short(req):
        mx, my = nearest_on_segment((ax, ay), (bx, by), (box.x + box.w / 2, box.y + box.h / 2))
        qx, qy = min(max(mx, box.left), box.right), min(max(my, box.top), box.bottom)
        if math.hypot(qx - mx, qy - my) <= FAR_LABEL:
            return None
        mx, my = nearest_on_segment((ax, ay), (bx, by), (qx, qy))
        if math.hypot(qx - mx, qy - my) > (longest or LONGEST_LEADER):
            return None
    else:
        mx, my = (ax + bx) / 2, (ay + by) / 2
    qx, qy = min(max(mx, box.left), box.right), min(max(my, box.top), box.bottom)
    if math.hypot(qx - mx, qy - my) < 0.3:
        return None
    return Line(mx, my, qx, qy, "dimension", f"{req.name}:leader")


def led_leader(req: LabelReq, box: Rect, longest: float | None = None) -> Line | None:
    """The leader of a label set off what it names: an arrow's or a trial line's from the nearest point of
    its line (:func:`leader_of`); a point's (a joint, a pole, an arc's middle) from the edge of its mark
    towards the box, when the box stands off it by more than :data:`FAR_LABEL` and less than
    :data:`LONGEST_LEADER` (or ``longest``)."""
    if req.kind != "point":
        return leader_of(req, box, longest)
    (px, py), r0 = req.anchor, req.r0
    qx, qy = min(max(px, box.left), box.right), min(max(py, box.top), box.bottom)
    gap = math.hypot(qx - px, qy - py)
    if not FAR_LABEL + r0 < gap <= (longest or LONGEST_LEADER) + r0:
        return None
    k = r0 / gap
    return Line(px + (qx - px) * k, py + (qy - py) * k, qx, qy, "dimension", f"{req.name}:leader")


def far_leader(req: LabelReq, box: Rect) -> Line | None:
    """The leader of a label set farther off what it names than a short leader reaches (a place beside it
    was taken): an arrow's or a trial line's up to :data:`LONG_LEADER` from its line, a point's (a
    circle's or a curve's name, a pivot's) when the box stands more than :data:`LONGEST_LEADER` off its
    point; None for one set nearer, or farther than :data:`LONG_LEADER`."""
    if req.kind in ("arrow", "trial"):
        return leader_of(req, box, LONG_LEADER)
    if req.kind != "point":
        return None
    (px, py), r0 = req.anchor, req.r0
    qx, qy = min(max(px, box.left), box.right), min(max(py, box.top), box.bottom)
    if math.hypot(qx - px, qy - py) <= LONGEST_LEADER:
        return None
    return led_leader(req, box, LONG_LEADER)


def off_by(req: LabelReq, box: Rect) -> float:
    """How far ``box`` stands off what ``req`` names: an arrow's or a trial line's line, else its point."""
    if req.kind in ("arrow", "trial") and req.other is not None:
        m = nearest_on_segment(req.anchor, req.other, (box.x + box.w / 2, box.y + box.h / 2))
        q = (min(max(m[0], box.left), box.right), min(max(m[1], box.top), box.bottom))
        m = nearest_on_segment(req.anchor, req.other, q)
        return math.dist(m, q)
    (px, py) = req.anchor
    return math.hypot(min(max(px, box.left), box.right) - px, min(max(py, box.top), box.bottom) - py)


def far_test(req: LabelReq, clear, placed: list[Rect], d: Drawing):
    """``clear``, and a box more than :data:`LONGEST_LEADER` off what it names taken only where its long
    leader (:func:`far_leader`) runs through no label or mark and across no heavy line: a label that far
    off with no leader leaves the reader to guess what it names."""
    def test(le: float, to: float, ri: float, bo: float) -> bool:
        if not clear(le, to, ri, bo):
            return False
        box = Rect(le, to, ri - le, bo - to)
        if off_by(req, box) <= LONGEST_LEADER:
            return True
        far = far_leader(req, box)
        return far is not None and runs_clear(far, placed, d)
    return test


def nearest_on_segment(a: tuple[float, float], b: tuple[float, float], p: tuple[float, float]) -> tuple[float, float]:
    """The point of segment ab nearest ``p``."""
    dx, dy = b[0] - a[0], b[1] - a[1]
    n = dx * dx + dy * dy
    t = 0.0 if n == 0 else min(max(((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / n, 0.0), 1.0)
    return a[0] + t * dx, a[1] + t * dy
