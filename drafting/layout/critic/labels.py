"""The critic's checks of a diagram's lettering: labels over labels, labels struck by other entities'
lines or hiding their heavy lines, labels nearer another entity of their kind than their own, and short arrows labelled without a
leader.  Each check takes a :class:`~drafting.layout.sheet.Sheet` and returns its findings."""

from __future__ import annotations

import math
from collections import defaultdict

from ...render.paper import Circle, Command, Line, Polygon, Polyline, Rect, Rectangle, Text
from .geometry import (bounding, circle_box_distance, clip_length, fill_meets, is_black_fill, is_heavy, is_stroked, outline,
                       point_box_distance, segment_box_distance)
from .parts import Finding, diagram_texts, owner, part

STRIKE_INSET = 0.15
"""A text's box is shrunk by this much (mm, each side) before a line is tested against it: a line that
only grazes the box's edge (the white space above a capital, below the baseline) does not strike it."""

AMBIGUITY_MARGIN = 1.0
"""A label is ambiguous unless the nearest other entity of its kind is more than this (mm) farther from
its box than its own entity is."""

SHORT_ARROW = 5.0
"""An arrow shorter than this (mm, tail to tip) is too short to carry a label beside it unaided."""

MARK_STYLES = frozenset({"dot", "pin"})


def label_overlaps(sheet) -> list[Finding]:
    """label-overlap: two diagram texts (labels, dimension texts, notes; see
    :func:`~drafting.layout.critic.parts.diagram_texts`) whose measured boxes share area (touching edges
    do not).  Value: the shared area, mm^2."""
    texts = diagram_texts(sheet.commands)
    out = []
    for i, a in enumerate(texts):
        for b in texts[i + 1:]:
            ab = _intersection(a.box, b.box)
            if ab is not None:
                out.append(Finding("label-overlap", sheet.number, f"{a.plain!r} ({a.name}) overlaps "
                                   f"{b.plain!r} ({b.name}) by {ab.w * ab.h:.2f} mm²", ab, ab.w * ab.h))
    return out


def _intersection(a: Rect, b: Rect) -> Rect | None:
    le, to, ri, bo = max(a.left, b.left), max(a.top, b.top), min(a.right, b.right), min(a.bottom, b.bottom)
    return Rect.from_edges(le, to, ri, bo) if ri - le > 1e-6 and bo - to > 1e-6 else None


def crossed_labels(sheet) -> list[Finding]:
    """label-crossed: a diagram text whose box, shrunk by :data:`STRIKE_INSET` each side, is entered by
    the ink of a command of another owner that a reader sees as struck text or a damaged drawing: ink
    drawn over the text's white ground (struck over its letters; a text without a ground, "<text name>
    bg", has all ink over it), or heavy ink under it (:func:`~drafting.layout.critic.geometry.is_heavy`:
    a thick line -- link, vector, load, guide, block, pin -- or a black fill such as an arrowhead, cut by
    the ground: a label never hides part of the mechanism or a vector).  A thin construction line (centre,
    hidden, path, trial, dimension, an image's outline) under the ground is a halo, as textbooks letter
    on a construction, and is fine.  Ink is a stroked path (Line, Polyline, the outline of a stroked
    Polygon, Rectangle or Circle -- a circle as its inscribed polygon within 0.01 mm --, every stroke of a
    Strokes) and a black fill (an arrowhead, a dot, a dark scale-bar cell).  White and grey fills (label
    and note grounds, chart bands, an image's tint) are not ink.  A command of the text's own entity --
    its own shaft, its dimension line, a leader drawn for it -- is not foreign.  One finding per text and
    command, saying which of the two it is; value: the length of the foreign path inside the box, mm."""
    inked = [(i, c, *_edges(bounding([c])), is_heavy(c)) for i, c in enumerate(sheet.commands)
             if type(c) is not Text and (is_stroked(c) or is_black_fill(c))]
    order = {id(c): i for i, c in enumerate(sheet.commands)}
    grounds: dict[str, list[int]] = defaultdict(list)         # the white grounds by name, in drawing order
    for i, c in enumerate(sheet.commands):
        if type(c) is Rectangle and c.name.endswith(" bg"):
            grounds[c.name].append(i)
    segments: dict[int, list] = {}                   # each command's path, made when a box meets it
    out = []
    for t in diagram_texts(sheet.commands):
        box = t.box.inset(STRIKE_INSET)
        if box.w <= 0 or box.h <= 0:
            continue
        mine = owner(t.name)
        ground = max((i for i in grounds.get(t.name + " bg", ()) if i < order[id(t)]), default=-1)
        le, to, ri, bo = _edges(box)
        for i, c, c_le, c_to, c_ri, c_bo, heavy in inked:
            if c_le > ri or c_ri < le or c_to > bo or c_bo < to or owner(c.name) == mine:
                continue
            under = i < ground
            if under and not heavy:
                continue                             # a thin line under the ground: a halo
            if type(c) is Circle and not is_black_fill(c) and circle_box_distance(c.cx, c.cy, c.r, box) > 0:
                continue                             # its stroke stays clear of the box
            if i not in segments:
                segments[i] = outline(c)
            inside = sum(clip_length(s, box) for s in segments[i]) if is_stroked(c) else 0.0
            if inside > 1e-6 or (is_black_fill(c) and fill_meets(c, box)):
                how = "cut by its white ground" if under else "struck over its letters"
                out.append(Finding("label-crossed", sheet.number,
                                   f"{t.plain!r} ({t.name}) is crossed by {c.name or type(c).__name__} "
                                   f"({c.style}, {inside:.2f} mm inside, {how})", t.box, inside))
    return out


def _edges(r: Rect) -> tuple[float, float, float, float]:
    return r.x, r.y, r.x + r.w, r.y + r.h


# ---- which entity a label is nearest ------------------------------------------------------------------

def _entities(sheet) -> dict[str, tuple[str, list, Rect]]:
    """Each owner's kind and its geometry as segments and points: an "arrow" (a shaft Line and an
    arrowhead "<owner>:head"), a "point" (a dot, or a pin "<owner>:pin" of its own), else the type and
    style of its own geometry ("Line trial", "Polyline dimension" for an angle mark's arc...)."""
    own: dict[str, list[Command]] = defaultdict(list)
    leaders: dict[str, list[Command]] = defaultdict(list)
    heads: set[str] = set()
    for c in sheet.commands:
        if type(c) is Text:
            continue
        o, p = owner(c.name), part(c.name)
        if p == "":
            own[o].append(c)
        elif p == "head" and type(c) is Polygon:
            heads.add(o)
            own[o].append(c)
        elif p == "pin" and type(c) is Circle:
            own[o].append(c)
        elif p == "leader" and type(c) is Line:
            leaders[o].append(c)
    out: dict[str, tuple[str, list, Rect]] = {}
    for o, cmds in own.items():
        if o in heads and any(type(c) is Line for c in cmds):
            kind = "arrow"
        elif any(type(c) is Circle and c.style in MARK_STYLES for c in cmds):
            kind = "point"
            cmds = [c for c in cmds if type(c) is Circle and c.style in MARK_STYLES]
        else:
            kind = f"{type(cmds[0]).__name__} {cmds[0].style}"
        if kind == "point":
            geometry = [(c.cx, c.cy) for c in cmds]
        else:
            geometry = []
            for c in cmds:
                geometry.extend([(c.cx, c.cy, c.r)] if type(c) is Circle else outline(c))
        out[o] = (kind, geometry, bounding(cmds))
        if leaders.get(o):                     # a leader ties the label to its own entity: measured from it
            out[LEADER + o] = ("leader", [seg for c in leaders[o] for seg in outline(c)], bounding(leaders[o]))
    return out


def _distance(box: Rect, geometry: list) -> float:
    """From ``box`` to the nearest of ``geometry``: points (x, y), circles (cx, cy, r) and segments."""
    return min((segment_box_distance(g, box) if not isinstance(g[0], (int, float))
                else point_box_distance(g, box) if len(g) == 2 else circle_box_distance(*g, box)
                for g in geometry), default=math.inf)


def _marks(sheet) -> list[tuple[float, float]]:
    """The centres of the page's dots and pins, one per place (0.01 mm)."""
    got: list[tuple[float, float]] = []
    for c in sheet.commands:
        if type(c) is Circle and c.style in MARK_STYLES and all(math.hypot(c.cx - x, c.cy - y) > 0.01 for x, y in got):
            got.append((c.cx, c.cy))
    return got


LEADER = "leader of "
"""The key of a label's leader among :func:`_entities`: the label's own distance is also measured to it."""
NUMBER = "number "
"""A link number's entity is named after its link ("number link 3" numbers the bars and plate "link 3",
"link 3 AB", as the record names a link's parts)."""


def _link_parts(sheet) -> dict[str, tuple[list, Rect]]:
    """Each link's drawn lines and outlines (its pins aside) as segments, and their bounds."""
    parts: dict[str, list[Command]] = defaultdict(list)
    for c in sheet.commands:
        if type(c) in (Line, Polyline, Polygon) and part(c.name) == "" and owner(c.name).startswith("link "):
            parts[owner(c.name)].append(c)
    return {o: ([seg for c in cmds for seg in outline(c)], bounding(cmds)) for o, cmds in parts.items()}


def _number_distances(box: Rect, link: str, links) -> tuple[float, float, str] | None:
    """A link number's distance to its own link's parts and to the nearest part of another link, or None
    when the link has no drawn part (the frame's number sits by a ground symbol)."""
    own = [g for o, (segs, _) in links.items() if o == link or o.startswith(link + " ") for g in segs]
    others = [(o, segs, bb) for o, (segs, bb) in links.items() if not (o == link or o.startswith(link + " "))]
    got = _nearest(box, others) if own else None
    if got is None:
        return None
    return _distance(box, own), got[0], got[1]


def ambiguous_labels(sheet) -> list[Finding]:
    """label-ambiguous: a label ("<owner>:label") whose nearest other entity of the same kind is not
    clearly farther from the label's box than its own entity: other distance <= own distance +
    :data:`AMBIGUITY_MARGIN`.  Distances are from the text's box to the entity's geometry (an arrow's
    shaft and head or the leader drawn to the label, a point's centre, a line's or arc's path).  Kinds: arrows (vectors, loads: a shaft
    with an arrowhead), points (dots and pins, one per place), and otherwise the command type and style
    of the entity's geometry (trial lines with trial lines, angle arcs with angle arcs...).  A label of a
    point drawn only as another entity's pin (a joint on a link's pin: the sheet does not say which pin is
    the joint) takes the nearest mark as its own and is ambiguous when the second nearest is within the
    margin.  Value: the other distance minus the own distance, mm."""
    ents = _entities(sheet)
    marks = links = None
    out = []
    for t in (c for c in diagram_texts(sheet.commands) if part(c.name) == "label"):
        mine = owner(t.name)
        kind, geometry, _ = ents.get(mine, ("point", [], None))
        if mine.startswith(NUMBER):
            links = _link_parts(sheet) if links is None else links
            got = _number_distances(t.box, mine[len(NUMBER):], links)
            if got is None:
                continue
            d_own, d_other, other = got
            kind = "link"
        elif kind == "point" and not geometry:
            marks = _marks(sheet) if marks is None else marks
            if len(marks) < 2:
                continue
            near = sorted((point_box_distance(m, t.box), m) for m in marks)
            d_own, (d_other, where) = near[0][0], near[1]
            other = f"the mark at ({where[0]:.1f}, {where[1]:.1f})"
        else:
            d_own = min(_distance(t.box, geometry), _distance(t.box, ents.get(LEADER + mine, ("", [], None))[1]))
            got = _nearest(t.box, [(o, g, bb) for o, (k, g, bb) in ents.items() if k == kind and o != mine
                                   and not (kind == "point" and _same_place(g, geometry))])
            if got is None:
                continue
            d_other, other = got
        if d_other <= d_own + AMBIGUITY_MARGIN:
            out.append(Finding("label-ambiguous", sheet.number,
                               f"{t.plain!r} ({t.name}) is {d_own:.1f} mm from its own {kind} and {d_other:.1f} mm "
                               f"from {other}", t.box, d_other - d_own))
    return out


FAR_LABEL = 8.0
"""mm: a label farther than this from what it names needs a leader to it (the placer's longest short leader)."""


def far_labels(sheet) -> list[Finding]:
    """label-far: a label ("<owner>:label") whose box is more than :data:`FAR_LABEL` from its own entity's
    geometry (as :func:`ambiguous_labels` measures it: an arrow's shaft and head, a point's centre, a line's
    or arc's path) with no leader drawn for it -- the reader must guess what it names even where nothing
    else of its kind is near.  A link's number and a point drawn only as another entity's pin are left
    to :func:`ambiguous_labels`.  Value: the distance, mm."""
    ents = _entities(sheet)
    out = []
    for t in (c for c in diagram_texts(sheet.commands) if part(c.name) == "label"):
        mine = owner(t.name)
        if mine.startswith(NUMBER) or LEADER + mine in ents:
            continue
        kind, geometry, _ = ents.get(mine, ("point", [], None))
        if not geometry:
            continue
        d = _distance(t.box, geometry)
        if d > FAR_LABEL:
            out.append(Finding("label-far", sheet.number,
                               f"{t.plain!r} ({t.name}) is {d:.1f} mm from its own {kind}, with no leader", t.box, d))
    return out


def _nearest(box: Rect, cands: list) -> tuple[float, str] | None:
    """(distance, owner) of the candidate (owner, geometry, bounds) nearest ``box``: the candidates are
    measured in the order of their bounds' distance, which no part of them can be nearer than."""
    best = None
    for lower, o, g in sorted((_rect_distance(box, bb), o, g) for o, g, bb in cands):
        if best is not None and lower > best[0]:
            break
        d = _distance(box, g)
        if best is None or d < best[0]:
            best = (d, o)
    return best


def _rect_distance(a: Rect, b: Rect) -> float:
    return math.hypot(max(a.left - b.right, 0.0, b.left - a.right), max(a.top - b.bottom, 0.0, b.top - a.bottom))


def _same_place(a: list, b: list) -> bool:
    return any(math.hypot(p[0] - q[0], p[1] - q[1]) <= 0.01 for p in a for q in b)


def short_arrows(sheet) -> list[Finding]:
    """short-arrow: an arrow (a shaft Line "<owner>" with an arrowhead "<owner>:head") shorter than
    :data:`SHORT_ARROW` from the shaft's start (the tail) to the arrowhead's apex (the tip), whose owner
    has a label ("<owner>:label") and no leader (a command "<owner>:leader...").  Value: the length, mm."""
    shafts: dict[str, Line] = {}
    heads: dict[str, Polygon] = {}
    labels: dict[str, Text] = {}
    leaders: set[str] = set()
    for c in sheet.commands:
        o, p = owner(c.name), part(c.name)
        if p == "" and type(c) is Line:
            shafts.setdefault(o, c)
        elif p == "head" and type(c) is Polygon:
            heads[o] = c
        elif p == "label" and type(c) is Text:
            labels[o] = c
        elif p.startswith("leader"):
            leaders.add(o)
    out = []
    for o, head in heads.items():
        shaft, label = shafts.get(o), labels.get(o)
        if shaft is None or label is None or o in leaders:
            continue
        tip = head.points[0]
        length = math.hypot(tip[0] - shaft.x1, tip[1] - shaft.y1)
        if length < SHORT_ARROW:
            where = Rect.bounding([(shaft.x1, shaft.y1), tip])
            out.append(Finding("short-arrow", sheet.number, f"arrow {o} is {length:.1f} mm long and its label "
                               f"{label.plain!r} has no leader", where, length))
    return out
