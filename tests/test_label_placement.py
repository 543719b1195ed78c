"""Label placement: the clip is shapely's, the candidates are the plain generator's to the last bit, and
the pruned search picks what the exhaustive one picks."""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings, strategies as st

from drafting.layout.segments import Segments


def clip_len(a, b, left, top, right, bottom) -> float:
    """Length of segment ab inside a rectangle (Liang-Barsky), one box at a time: the reference."""
    dx, dy = b[0] - a[0], b[1] - a[1]
    t0, t1 = 0.0, 1.0
    for p, q in ((-dx, a[0] - left), (dx, right - a[0]), (-dy, a[1] - top), (dy, bottom - a[1])):
        if abs(p) < 1e-12:
            if q < 0:
                return 0.0
            continue
        t = q / p
        if p < 0:
            t0 = max(t0, t)
        else:
            t1 = min(t1, t)
        if t0 > t1:
            return 0.0
    return (t1 - t0) * math.hypot(dx, dy)


coord = st.floats(-50, 50, allow_nan=False).map(lambda v: round(v, 2))      # ties and shared edges happen
segment = st.tuples(st.tuples(coord, coord), st.tuples(coord, coord), st.booleans())
box = st.tuples(coord, coord, st.floats(0.5, 30).map(lambda v: round(v, 1)), st.floats(0.5, 30).map(lambda v: round(v, 1)))


@settings(max_examples=300, deadline=None)
@given(segment, box)
def test_the_clipped_length_is_the_length_shapely_cuts(seg, bx):
    """The scalar Liang-Barsky clip against an independent one: shapely's intersection of the segment
    with the box (the reference below is the same algorithm as the code; this one is not)."""
    from shapely.geometry import LineString, box as sbox
    from drafting.layout.label_kin import clip_fraction
    (a0, a1), (b0, b1), _ = seg
    left, top, w, h = bx
    got = clip_fraction(a0, a1, b0 - a0, b1 - a1, left, top, left + w, top + h) * math.hypot(b0 - a0, b1 - a1)
    assert got == clip_len((a0, a1), (b0, b1), left, top, left + w, top + h)
    if (a0, a1) != (b0, b1):
        want = LineString([(a0, a1), (b0, b1)]).intersection(sbox(left, top, left + w, top + h)).length
        assert got == pytest.approx(want, rel=1e-9, abs=1e-9)


def test_a_segment_along_an_edge_or_outside_covers_nothing():
    from drafting.layout.label_kin import clip_fraction
    assert clip_fraction(0.0, 0.0, 10.0, 0.0, 0.0, 1.0, 5.0, 3.0) == 0.0            # outside, parallel to the box
    assert clip_fraction(0.0, 0.0, 10.0, 0.0, 2.0, -1.0, 6.0, 1.0) == pytest.approx(0.4, rel=1e-12)
    assert clip_fraction(20.0, 5.0, 10.0, 0.0, 0.0, 1.0, 5.0, 3.0) == 0.0


def reference_candidates(req, hw, hh, incident, relax):
    """(centre, cost) of every candidate, in order, written out plainly: the reference."""
    from drafting.render.drawing import angle_gap, shifted, unit_vector
    from drafting.layout.labels import _DIR_ATAN, _DIR_LEAN, _DIRS, _edge
    dists = (0.7, 1.6, 3.0, 4.5) if relax == 0 else (6.0, 8.0, 11.0, 15.0)
    p = req.anchor
    if req.kind in ("point", "polygon"):
        if req.kind == "polygon" and relax == 0:
            yield p, 0.0
        gaps = [min((angle_gap(ap, b) for b in incident), default=math.pi) for ap in _DIR_ATAN]
        edges = [_edge(u, hw, hh) for u in _DIRS]
        for dist in dists:
            for u, gap, edge, lean in zip(_DIRS, gaps, edges, _DIR_LEAN):
                yield shifted(p, u, req.r0 + dist + edge), 2.0 * (math.pi - gap) + 0.8 * dist + lean
    elif req.kind == "arrow":
        tail, tip = req.other, req.anchor
        v = (tip[0] - tail[0], tip[1] - tail[1])
        u = unit_vector(v)
        n = (-u[1], u[0])
        for dist in dists[:3] if relax == 0 else dists:
            for f in (0.5, 0.4, 0.6, 0.3, 0.7, 0.2, 0.8):
                a = shifted(tail, v, f)
                for side in (1.0, -1.0):
                    nn = (n[0] * side, n[1] * side)
                    yield (shifted(a, nn, dist + 0.3 + _edge(nn, hw, hh)),
                           3.0 * abs(f - 0.5) + 0.8 * dist + (side < 0) * 0.1)
        for dist in dists[:3] if relax == 0 else dists:
            yield shifted(tip, u, dist + 0.3 + _edge(u, hw, hh)), 1.7 + 0.8 * dist
    elif req.kind == "trial":
        end, start = req.anchor, req.other
        v = unit_vector((start[0] - end[0], start[1] - end[1]))
        n = (-v[1], v[0])
        for dist in dists[:3] if relax == 0 else dists:
            for s in (3.0, 6.0, 10.0, 15.0, 22.0):
                for side in (1.0, -1.0):
                    nn = (n[0] * side, n[1] * side)
                    yield shifted(shifted(end, v, s), nn, dist + _edge(nn, hw, hh)), 0.1 * s + 0.8 * dist
                    yield shifted(shifted(start, v, -s), nn, dist + _edge(nn, hw, hh)), 0.1 * s + 0.8 * dist + 1.0


@settings(max_examples=150, deadline=None)
@given(st.sampled_from(["point", "polygon", "arrow", "trial"]), coord, coord, coord, coord,
       st.floats(0.0, 2.0), st.floats(0.5, 12.0), st.floats(0.5, 4.0),
       st.lists(st.floats(-math.pi, math.pi), max_size=4), st.sampled_from([0, 1]))
def test_the_candidates_are_the_plain_generators_to_the_last_bit(kind, x, y, ox, oy, r0, hw, hh, incident, relax):
    """Costs made at once and centres made on demand, by index, are the plainly written candidates."""
    from drafting.render.drawing import LabelReq
    from drafting.layout.labels import _Candidates
    other = None if kind in ("point", "polygon") else (ox, oy if (ox, oy) != (x, y) else oy + 1.0)
    req = LabelReq(kind, "A", (x, y), True, "a", r0, other)
    want = list(reference_candidates(req, hw, hh, incident, relax))
    got = _Candidates(req, hw, hh, incident, relax)
    assert [(got.centre(i), c) for i, c in enumerate(got.costs)] == want


class Listed:
    """Candidates given as (x, y, cost) rows."""

    def __init__(self, rows) -> None:
        self.costs = [c for _, _, c in rows]
        self.centre = lambda i: (rows[i][0], rows[i][1])


def exhaustive_best(cands, hw, hh, plot, placed, hard, segments, heavy_ok, clear=None):
    """Every candidate scored with the scalar clip, the first of the lowest score among those that hide
    no heavy line (unless ``heavy_ok``) and pass ``clear``: the reference."""
    best = None
    for x, y, cost in cands:
        left, top, right, bottom = x - hw, y - hh, x - hw + 2 * hw, y - hh + 2 * hh
        if not (left >= plot.left - 1e-6 and right <= plot.right + 1e-6 and top >= plot.top - 1e-6
                and bottom <= plot.bottom + 1e-6):
            continue
        if any(left < r.right + g and r.left < right + g and top < r.bottom + g and r.top < bottom + g
               for rects, g in ((placed, 0.3), (hard, 0.2)) for r in rects):
            continue
        thin = thick = 0.0
        for a, b, heavy in segments:
            got = clip_len(a, b, left, top, right, bottom)
            if heavy:
                thick += got
            else:
                thin += got
        if not heavy_ok and thick > 0:
            continue
        if clear is not None and not clear(left, top, right, bottom):
            continue
        total = cost + 3.0 * thin + 20.0 * thick
        if best is None or total < best[0]:
            best = (total, (x, y))
    return best


rect = st.tuples(coord, coord, st.floats(0.5, 10).map(lambda v: round(v, 1)), st.floats(0.5, 10).map(lambda v: round(v, 1)))


point = st.tuples(coord, coord)
element = point | st.tuples(point, point) | st.tuples(coord, coord, st.floats(0.5, 20).map(lambda v: round(v, 1)))


@settings(max_examples=300, deadline=None)
@given(st.lists(st.tuples(coord, coord, st.sampled_from([0.0, 0.5, 1.0, 2.5]).flatmap(
           lambda c: st.just(c) | st.floats(0, 6).map(lambda v: round(v, 1)))), min_size=1, max_size=40),
       st.floats(0.5, 6.0).map(lambda v: round(v, 1)), st.floats(0.5, 3.0).map(lambda v: round(v, 1)),
       st.lists(segment, max_size=25), st.lists(rect, max_size=4), st.lists(rect, max_size=4), st.booleans(),
       st.none() | st.tuples(st.lists(element, min_size=1, max_size=3), st.lists(element, max_size=6)))
def test_the_pruned_search_picks_what_the_exhaustive_one_picks(cands, hw, hh, segments, placed, hard, heavy_ok,
                                                                kin):
    """Clipping only the candidates that can still win (cheapest first, bounded by the first that
    meets no line) and measuring the ambiguity only of one that would win chooses the same candidate
    with the same score, ties included, as scoring all."""
    from drafting.layout.label_kin import _Clear, _element_bounds
    from drafting.layout.labels import _best_candidate
    from drafting.render.paper import Rect
    plot = Rect(-40.0, -40.0, 80.0, 80.0)
    placed = [Rect(*r) for r in placed]
    hard = [Rect(*r) for r in hard]
    clear = None if kin is None else _Clear(kin[0], [(*_element_bounds(g), g) for g in kin[1]], 0.4)
    want = exhaustive_best(cands, hw, hh, plot, placed, hard, segments, heavy_ok, clear)

    class Gridded(Segments):           # the grid used however few the segments are
        __slots__ = ()
        DENSE = -1
    for index in (Segments(segments), Gridded(segments)):      # every segment tested, then by the grid
        got = _best_candidate(Listed(cands), hw, hh, plot, placed, hard, index.near(plot), heavy_ok, clear, index)
        if want is None:
            assert got is None
        else:
            assert got is not None and (got[0], got[1]) == want


@settings(max_examples=300, deadline=None)
@given(element, box)
def test_the_ambiguity_distances_are_the_distances_shapely_measures(g, bx):
    """A label's distance to a point, a circle's curve or a segment, against shapely's."""
    from shapely.geometry import LineString, Point, box as sbox
    from drafting.layout.label_kin import _distance
    left, top, w, h = bx
    got = _distance(g, left, top, left + w, top + h)
    b = sbox(left, top, left + w, top + h)
    if len(g) == 2 and not isinstance(g[0], tuple):
        want = Point(g).distance(b)
    elif len(g) == 3:
        ring = Point(g[0], g[1]).buffer(g[2], quad_segs=512).exterior
        want = ring.distance(b)
    elif g[0] == g[1]:
        want = Point(g[0]).distance(b)
    else:
        want = LineString(g).distance(b)
    assert got == pytest.approx(want, abs=2e-4 * (1 + (g[2] if len(g) == 3 else 0)))


def test_a_label_pushed_off_its_arrow_is_tied_to_it_by_a_leader_only_where_the_leader_is_clear():
    """A label whose places beside its arrow are taken stands off it: from 2.5 mm to 8 mm it gets a thin
    leader from the nearest point of the shaft, unless the leader would run through another label, a mark
    or across another heavy line (it would seem to name that one); a label beside its arrow gets none."""
    from drafting.layout.leaders import FAR_LABEL, LONGEST_LEADER, clear_line, crosses_heavy, leader_of
    from drafting.render.drawing import LabelReq
    from drafting.render.paper import Rect
    req = LabelReq(anchor=(70.0, 50.0), kind="arrow", markup="V_B", mandatory=False, name="V_B", other=(40.0, 50.0))
    assert leader_of(req, Rect(50, 45, 6, 4)) is None                  # 1 mm above the shaft
    lead = leader_of(req, Rect(50, 41, 6, 4))                           # 5 mm above it
    assert lead is not None and lead.name == "V_B:leader" and lead.style == "dimension"
    assert (lead.x1, lead.y1, lead.x2, lead.y2) == pytest.approx((53.0, 50.0, 53.0, 45.0))
    assert FAR_LABEL < 5.0 < LONGEST_LEADER
    assert leader_of(req, Rect(50, 30, 6, 4)) is None                   # 16 mm off: a leader would not serve
    assert clear_line(lead, [Rect(60, 40, 5, 5)]) and not clear_line(lead, [Rect(52, 46, 3, 2)])
    assert crosses_heavy(lead, [((40.0, 47.0), (70.0, 47.0), True)])          # another vector between
    assert not crosses_heavy(lead, [((40.0, 47.0), (70.0, 47.0), False)])    # a thin line is no matter
    assert not crosses_heavy(lead, [((40.0, 50.0), (70.0, 50.0), True)])     # its own shaft


def test_a_notes_text_sits_at_its_point_where_clear_else_off_the_heavy_line_through_it():
    """A note's or a dimension's text (kind "note") is set centred on its point when nothing heavy runs
    there, else at the nearest clear place around it -- a tooth across a circle's name moves the name, not
    strikes it; it is drawn on a note's white ground and named "<owner>:text" (it names no point)."""
    from drafting.layout.labels import place_labels
    from drafting.render.drawing import Drawing, LabelReq
    from drafting.render.paper import Rect, Rectangle, Text
    plot = Rect(0, 0, 100, 100)
    d = Drawing()
    d.labels.append(LabelReq("note", "pitch circle", (50.0, 50.0), True, "terms pitch"))
    bg, t = place_labels(d, plot, "space")
    assert isinstance(bg, Rectangle) and bg.style == "note_bg" and bg.name == "terms pitch:text bg"
    assert isinstance(t, Text) and t.name == "terms pitch:text" and t.box.center == pytest.approx((50.0, 50.0), abs=0.3)
    d.segments.append(((50.0, 30.0), (50.0, 70.0), True))          # a tooth flank through the point
    bg, t = place_labels(d, plot, "space")
    r = bg.rect
    assert not (r.x < 50.0 < r.x + r.w and r.y < 70.0 and r.y + r.h > 30.0)    # the flank not hidden
    assert math.dist(t.box.center, (50.0, 50.0)) < 20.0             # still beside its point


def test_a_note_set_off_its_point_gets_a_leader_and_the_drawing_keeps_its_room():
    """A dimension's or note's text is a label (kind "note"): where its place is clear it stays there with
    no leader; set off it by more than 2.5 mm it is tied to the point it names; the drawing's extent counts
    the note's ground at its anchor, as it counted the text there before the placer set it."""
    from drafting.layout.leaders import leader_of
    from drafting.render.drawing import Drawing, LabelReq
    from drafting.render.paper import Line, Rect
    req = LabelReq("note", "PB 15 mm", (50.0, 50.0), True, "recess", other=(50.0, 50.0),
                   ground=Rect(40.0, 48.0, 20.0, 4.0))
    assert leader_of(req, Rect(40.0, 48.0, 20.0, 4.0)) is None            # at its point
    lead = leader_of(req, Rect(40.0, 36.0, 20.0, 4.0))                     # 10 mm above it
    assert lead is not None and lead.name == "recess:leader"
    assert (lead.x1, lead.y1, lead.x2, lead.y2) == pytest.approx((50.0, 50.0, 50.0, 40.0))
    d = Drawing()
    d.add(0, Line(0.0, 0.0, 45.0, 45.0, "link", "bar"))
    d.labels.append(req)
    box = d.bbox()
    assert (box.left, box.top, box.right, box.bottom) == pytest.approx((0.0, 0.0, 60.0, 52.0))
    moved = d.moved(10.0, 0.0)
    assert moved.labels[0].ground.x == pytest.approx(50.0)


def test_an_arrow_label_crowded_by_a_collinear_arrow_is_set_off_by_a_leader_that_names_it():
    """Two arrows from one pole along one line (V_A and V_G2 of one link): no place beside V_G2 is clearly
    nearer it than V_A, so its label stands off with a leader from V_G2's own shaft that names it."""
    from drafting.layout.labels import place_labels
    from drafting.layout.leaders import FAR_LABEL
    from drafting.render.drawing import Drawing, LabelReq, SHAFTS
    from drafting.render.paper import Line, Rect, Text
    d = Drawing()
    for name, tip in (("V_A", (100.0, 50.0)), ("V_G2", (70.0, 50.0))):
        d.add(SHAFTS, Line(40.0, 50.0 + (0.6 if name == "V_G2" else 0.0), *tip, "vector", name))
        d.labels.append(LabelReq("arrow", name, tip, False, name, other=(40.0, 50.0)))
    cmds = place_labels(d, Rect(0, 0, 200, 100), "velocity")
    texts = {c.name: c for c in cmds if isinstance(c, Text)}
    leaders = {c.name: c for c in cmds if isinstance(c, Line) and c.name.endswith(":leader")}
    assert "V_G2:label" in texts and "V_G2:leader" in leaders
    lead = leaders["V_G2:leader"]
    assert 40.0 <= lead.x1 <= 70.0 and abs(lead.y1 - 50.3) < 0.5            # from V_G2's own shaft
    assert abs(lead.y2 - lead.y1) > FAR_LABEL - 1e-9 or abs(lead.x2 - lead.x1) > FAR_LABEL - 1e-9


@settings(max_examples=200, deadline=None)
@given(st.lists(segment, max_size=40), st.lists(st.tuples(coord, coord), min_size=1, max_size=5),
       st.sampled_from([0.0, 0.2, 1.5]))
def test_the_grid_finds_the_segments_around_a_point_that_the_scan_finds(segments, points, margin):
    """A dense drawing's segments around a label's anchor are found through its grid: the same indices, in
    the same order, as testing every segment."""
    from drafting.layout.segments import Segments

    class Gridded(Segments):
        __slots__ = ()
        DENSE = -1
    scan, grid = Segments(segments), Gridded(segments)
    assert grid.dense and not scan.dense
    for p in points:
        assert grid.around(p, margin) == scan.around(p, margin)


def test_a_circle_s_name_goes_to_another_point_of_it_when_its_first_is_crowded():
    """A circle's name is tried up and to the right first; where heavy lines fill that corner it is set by
    another point of the circle (clear and unambiguous there), not pushed far off into the corner."""
    from constructions.entities import Circle, Diagram, Role
    from constructions.geometry import Vec
    from drafting.layout.diagram import draw_entities
    from drafting.layout.labels import place_labels
    from drafting.render.paper import Rect, Text
    from drafting.render.drawing import LINKS
    from drafting.render.paper import Line
    circle = Circle("pitch circle 1", Role.CENTRE_LINE, Diagram.SPACE, Vec(0.0, 0.0), 0.02, "pitch circle")
    d = draw_entities([circle], 1000.0)                            # r = 20 mm about (0, 0) on paper
    (req,) = d.labels
    assert req.anchor == pytest.approx((20 * math.cos(math.pi / 4), -20 * math.sin(math.pi / 4)))
    assert len(req.alternates) == 7
    for k in range(-12, 13):                                       # a hatch of heavy lines over the upper right
        d.add(LINKS, Line(8.0 + 2 * k, -40.0, 48.0 + 2 * k, 0.0, "link", f"bar {k}"))
    d = d.moved(60.0, 60.0)
    (t,) = [c for c in place_labels(d, Rect(0, 0, 120, 120), "space") if isinstance(c, Text)]
    b = t.box
    ring = [(60.0 + 20.0 * math.cos(a / 100), 60.0 + 20.0 * math.sin(a / 100)) for a in range(629)]
    near = min(math.hypot(max(b.x - x, 0.0, x - b.x - b.w), max(b.y - y, 0.0, y - b.y - b.h)) for x, y in ring)
    assert near < 3.0                                              # by the circle, at another point of it
    from drafting.layout.label_kin import clip_fraction
    assert all(clip_fraction(68.0 + 2 * k, 20.0, 40.0, 40.0, b.x, b.y, b.x + b.w, b.y + b.h) == 0.0
               for k in range(-12, 13))                            # and hiding none of the bars


def test_a_link_number_stands_clear_of_the_point_letter_beside_it():
    """A block's point letter and its link's number are both point labels; the number keeps 1.5 mm from the
    letter's ground, so "C 3" never reads as C with a subscript."""
    from drafting.layout.labels import NUMBER_GAP, place_labels
    from drafting.layout.label_kin import NUMBER
    from drafting.render.drawing import Drawing, LabelReq
    from drafting.render.paper import Rect, Rectangle
    d = Drawing()
    d.labels.append(LabelReq("point", "C", (50.0, 50.0), True, "joint C", r0=1.0))
    d.labels.append(LabelReq("point", "3", (50.5, 50.0), True, f"{NUMBER}block 3", r0=1.0))
    grounds = {c.name: c for c in place_labels(d, Rect(0, 0, 100, 100), "space") if isinstance(c, Rectangle)}
    a, b = grounds["joint C:label bg"], grounds[f"{NUMBER}block 3:label bg"]
    dx = max(a.x - (b.x + b.w), b.x - (a.x + a.w), 0.0)
    dy = max(a.y - (b.y + b.h), b.y - (a.y + a.h), 0.0)
    assert max(dx, dy) >= NUMBER_GAP - 1e-9
