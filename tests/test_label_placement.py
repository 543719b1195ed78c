"""Label placement: the clip is shapely's, the candidates are the generator's to the last bit, and the
pruned search picks what the exhaustive one picks."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from drafting.labels import _Segments


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
    from drafting.labels import _clip
    (a0, a1), (b0, b1), _ = seg
    left, top, w, h = bx
    got = _clip(a0, a1, b0 - a0, b1 - a1, left, top, left + w, top + h) * math.hypot(b0 - a0, b1 - a1)
    assert got == clip_len((a0, a1), (b0, b1), left, top, left + w, top + h)
    if (a0, a1) != (b0, b1):
        want = LineString([(a0, a1), (b0, b1)]).intersection(sbox(left, top, left + w, top + h)).length
        assert got == pytest.approx(want, rel=1e-9, abs=1e-9)


def test_a_segment_along_an_edge_or_outside_covers_nothing():
    from drafting.labels import _clip
    assert _clip(0.0, 0.0, 10.0, 0.0, 0.0, 1.0, 5.0, 3.0) == 0.0            # outside, parallel to the box
    assert _clip(0.0, 0.0, 10.0, 0.0, 2.0, -1.0, 6.0, 1.0) == pytest.approx(0.4, rel=1e-12)
    assert _clip(20.0, 5.0, 10.0, 0.0, 0.0, 1.0, 5.0, 3.0) == 0.0


@settings(max_examples=100, deadline=None)
@given(st.sampled_from(["point", "polygon", "arrow", "trial"]), coord, coord, coord, coord,
       st.floats(0.0, 2.0), st.floats(0.5, 12.0), st.floats(0.5, 4.0),
       st.lists(st.floats(-math.pi, math.pi), max_size=4), st.sampled_from([0, 1]))
def test_the_candidate_array_is_the_generator_to_the_last_bit(kind, x, y, ox, oy, r0, hw, hh, incident, relax):
    from drafting.drawing import LabelReq
    from drafting.labels import _candidate_array, _candidates
    other = None if kind in ("point", "polygon") else (ox, oy if (ox, oy) != (x, y) else oy + 1.0)
    req = LabelReq(kind, "A", (x, y), True, "a", r0, other)
    want = [(c[0], c[1], k) for c, k in _candidates(req, hw, hh, incident, relax)]
    got = _candidate_array(req, hw, hh, incident, relax)
    assert [tuple(row) for row in got.tolist()] == want


def exhaustive_best(cands, hw, hh, plot, placed, hard, segments, mandatory):
    """Every candidate scored with the scalar clip, the first of the lowest score: the reference."""
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
        if not mandatory and thick > 0:
            continue
        total = cost + 3.0 * thin + 20.0 * thick
        if best is None or total < best[0]:
            best = (total, (x, y))
    return best


rect = st.tuples(coord, coord, st.floats(0.5, 10).map(lambda v: round(v, 1)), st.floats(0.5, 10).map(lambda v: round(v, 1)))


@settings(max_examples=300, deadline=None)
@given(st.lists(st.tuples(coord, coord, st.sampled_from([0.0, 0.5, 1.0, 2.5]).flatmap(
           lambda c: st.just(c) | st.floats(0, 6).map(lambda v: round(v, 1)))), min_size=1, max_size=40),
       st.floats(0.5, 6.0).map(lambda v: round(v, 1)), st.floats(0.5, 3.0).map(lambda v: round(v, 1)),
       st.lists(segment, max_size=25), st.lists(rect, max_size=4), st.lists(rect, max_size=4), st.booleans())
def test_the_pruned_search_picks_what_the_exhaustive_one_picks(cands, hw, hh, segments, placed, hard, mandatory):
    """Clipping only the candidates that can still win (cheapest first, bounded by the first that
    meets no line) chooses the same candidate with the same score, ties included, as scoring all."""
    from drafting.labels import _best_candidate
    from drafting.paper import Rect
    plot = Rect(-40.0, -40.0, 80.0, 80.0)
    placed = [Rect(*r) for r in placed]
    hard = [Rect(*r) for r in hard]
    got = _best_candidate(np.array(cands, dtype=float).reshape(-1, 3), hw, hh, plot, placed, hard,
                          _Segments(segments), mandatory)
    want = exhaustive_best(cands, hw, hh, plot, placed, hard, segments, mandatory)
    if want is None:
        assert got is None
    else:
        assert got is not None and (got[0], got[1]) == want
