"""The drawers of the drafting annotations: ISO 129 dimensions (extension lines, dimension line with filled
arrowheads, horizontal text on a white ground), angle marks (arc with an arrowhead and text) and notes
(text on a white ground, moved clear of the notes set before).  Registered with the other drawers when
:mod:`drafting.render.drawers` is imported.
"""

from __future__ import annotations

import math

from constructions.geometry import Vec
from constructions.entities import AngleMark, Dimension, Note

from .drawing import ARROW_LEN, HEADS, NOTES, TRIALS, DrawContext, LabelReq, Pt, _dist, arrowhead, drawer, nonzero, \
    shifted, unit_vector
from .paper import Line, Polyline, Rect, Rectangle, Text
from .style import LABEL, measure, rich

NOTE_PAD = 0.4          # white margin around a note or dimension text
DIM_EXT_GAP = 1.0       # ISO 129: a small gap between the feature and its extension line ...
DIM_EXT_OVER = 2.0      # ... which runs this far past the dimension line
DIM_TEXT = LABEL        # lettering of dimensions, angle marks and notes
ANGLE_MIN_R = 6.0       # an angle mark's arc is at least this radius on paper


def _boxed_text(ctx: DrawContext, centre: Pt, words: str, name: str) -> Rect:
    """Horizontal lettering centred on ``centre`` over a white ground (it may cross lines)."""
    spans = rich(words, DIM_TEXT)
    ext = measure(spans)
    x = centre[0] - ext.width / 2
    y = centre[1] - (ext.top + ext.bottom) / 2
    box = ext.box(x, y)
    bg = Rect(box.x - NOTE_PAD, box.y - NOTE_PAD, box.w + 2 * NOTE_PAD, box.h + 2 * NOTE_PAD)
    ctx.d.add(NOTES, Rectangle(bg.x, bg.y, bg.w, bg.h, "note_bg", f"{name}:text bg"))
    ctx.d.add(NOTES, Text(x, y, spans, "label", box, "", f"{name}:text"))
    ctx.d.hard.append(bg)
    return bg


def _text_half(words: str) -> tuple[float, float]:
    ext = measure(rich(words, DIM_TEXT))
    return ext.width / 2 + NOTE_PAD, ext.height / 2 + NOTE_PAD


def _dimension_points(e: Dimension) -> tuple[Vec, ...]:
    d = e.end - e.start
    if not nonzero(d):
        return (e.start, e.end)
    off = d.perp().unit() * e.offset
    return (e.start, e.end, e.start + off, e.end + off)


@drawer(Dimension, points=_dimension_points)
def draw_dimension(e: Dimension, ctx: DrawContext) -> None:
    """ISO 129: extension lines from the feature (with a small gap) to just past the dimension line,
    the dimension line with filled arrowheads touching the extension lines, the value horizontal
    (unidirectional) on a white ground at the middle of the dimension line."""
    T = ctx.T
    a, b = T(e.start), T(e.end)
    if _dist(a, b) < 1e-6:
        return
    u = unit_vector((b[0] - a[0], b[1] - a[1]))
    n = (u[1], -u[0])                     # paper normal that is "left of start -> end" in the model (y up)
    off = e.offset * T.k
    side = 1.0 if off >= 0 else -1.0
    da, db = shifted(a, n, off), shifted(b, n, off)
    for p, q, tag in ((a, da, "a"), (b, db, "b")):
        if abs(off) > DIM_EXT_GAP:
            p0 = shifted(p, n, side * DIM_EXT_GAP)
            p1 = shifted(q, n, side * DIM_EXT_OVER)
            ctx.d.add(TRIALS, Line(*p0, *p1, "dimension", f"{e.name}:extension {tag}"))
    length = _dist(da, db)
    words = ctx.text(e, e.text)
    if length >= 2 * ARROW_LEN + 1.0:
        h1, _ = arrowhead(db, da, f"{e.name}:start")
        h2, _ = arrowhead(da, db, f"{e.name}:end")
        ctx.d.add(TRIALS, Line(*da, *db, "dimension", e.name))
    else:                                  # too short: arrows outside, pointing in
        h1, _ = arrowhead(shifted(da, u, -ARROW_LEN - 2.0), da, f"{e.name}:start")
        h2, _ = arrowhead(shifted(db, u, ARROW_LEN + 2.0), db, f"{e.name}:end")
        ctx.d.add(TRIALS, Line(*shifted(da, u, -ARROW_LEN - 2.0), *shifted(db, u, ARROW_LEN + 2.0),
                               "dimension", e.name))
    for h in (h1, h2):
        ctx.d.layers.setdefault(HEADS, []).append(h)
        ctx.d.hard.append(Rect.bounding(h.points))
    if words:
        mid = line_mid = ((da[0] + db[0]) / 2, (da[1] + db[1]) / 2)
        hw, hh = _text_half(words)
        if length < 2 * hw + 2 * ARROW_LEN + 1.0 or abs(u[1]) < 0.5:
            # beside the dimension line, away from the feature: the text box just clears the line
            reach = abs(n[0]) * hw + abs(n[1]) * hh + 0.6
            mid = shifted(mid, n, side * reach)
        # the value is a label: at the middle of the dimension line where that is clear, else the nearest
        # clear place beside it -- the placer keeps it off heavy lines, arrowheads and pins
        ctx.d.labels.append(LabelReq("note", words, mid, True, e.name, other=line_mid,
                                     ground=Rect(mid[0] - hw, mid[1] - hh, 2 * hw, 2 * hh)))


@drawer(AngleMark, points=lambda e: (e.vertex,))
def draw_angle_mark(e: AngleMark, ctx: DrawContext) -> None:
    """An arc about the vertex from the start direction CCW to the end direction, an arrowhead at its
    end, and the text just outside the middle of the arc."""
    T = ctx.T
    span = e.end_angle - e.start_angle
    if not math.isfinite(span) or abs(span) < 1e-9:
        return
    v = T(e.vertex)
    r = max(abs(e.radius) * T.k, ANGLE_MIN_R, e.least_radius)
    segs = int(min(180, max(8, math.ceil(abs(span) * r / 0.8))))

    def at(angle: float, rr: float = r) -> Pt:
        return (v[0] + rr * math.cos(angle), v[1] - rr * math.sin(angle))
    pts = tuple(at(e.start_angle + span * i / segs) for i in range(segs + 1))
    # the arrowhead: its apex at the end of the arc, along the chord of the last ~ARROW_LEN of arc
    back = min(abs(span), ARROW_LEN / r) * (1 if span > 0 else -1)
    head, _ = arrowhead(at(e.end_angle - back), pts[-1], e.name)
    clear = 0.8 * min(ARROW_LEN, 0.5 * _dist(at(e.end_angle - back), pts[-1]))     # of the arrowhead
    keep = [p for p in pts if _dist(p, pts[-1]) >= clear]
    if len(keep) >= 2:
        ctx.d.add(TRIALS, Polyline(tuple(keep), "dimension", e.name))
    ctx.d.layers.setdefault(HEADS, []).append(head)
    ctx.d.hard.append(Rect.bounding(head.points))
    words = ctx.text(e, e.text)
    if words:
        # the value is a label at the middle of the arc: the label placer keeps it off the lines around
        # (a short crank, a lever crossing the arc) as it does every other label
        mid = e.start_angle + span * e.text_at
        ctx.d.labels.append(LabelReq("point", words, at(mid), True, e.name, r0=0.6))


NOTE_GAP = 0.3
"""The least room between the grounds of two notes, mm."""


@drawer(Note, points=lambda e: (e.at,))
def draw_note(e: Note, ctx: DrawContext) -> None:
    """The words on a white ground centred at the note's point -- where they would cover a note set
    before (names of circles a few mm apart, say), moved up or down just clear of it, the least way."""
    words = ctx.text(e, e.text)
    if not words:
        return
    x, y0 = ctx.T(e.at)
    hw, hh = _text_half(words)

    # only a note over the same stretch of x can cover it, wherever it goes up or down
    left = x - hw
    right = left + 2 * hw
    band = [o for o in ctx.notes if left < o.right + NOTE_GAP and o.left < right + NOTE_GAP]

    def free(y: float) -> bool:
        return not any(Rect(x - hw, y - hh, 2 * hw, 2 * hh).overlaps(o, NOTE_GAP) for o in band)
    clear = NOTE_GAP + hh + 1e-6                # (a hair more: the test is strict)
    ys = [y0] + [v for o in ctx.notes for v in (o.top - clear, o.bottom + clear)]
    y = next(v for v in sorted(ys, key=lambda v: (abs(v - y0), v)) if free(v))      # the nearest free
    ground = Rect(x - hw, y - hh, 2 * hw, 2 * hh)
    ctx.notes.append(ground)
    # set there where it is clear, else at the nearest clear place around: the placer keeps it off heavy
    # lines (the teeth across a circle's name), arrowheads and pins as it does every label
    ctx.d.labels.append(LabelReq("note", words, (x, y), True, e.name, other=(x, y0), ground=ground))
