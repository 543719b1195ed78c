"""Label placement: every label of a drawn diagram put where it overlaps no other label or symbol.

``place_labels`` searches candidate positions around each label's anchor and scores them by how much
line they would hide and how well they sit in the gap between the lines at the anchor.  Only the lines,
symbols and labels in the neighbourhood a label's candidates can reach are tested against them (a dense
drawing's lines through the grid of :mod:`drafting.layout.segments`).
"""

from __future__ import annotations

import math
from dataclasses import replace

from ..render.drawing import Drawing, LabelReq, Pt, shifted, angle_gap, incident_directions, unit_vector
from ..render.errors import LayoutError
from ..render.paper import Command, Line, Rect, Rectangle, Text
from ..render.style import LABEL, measure, rich
from .label_kin import NUMBER, Kin, clip_fraction
from .segments import Segments
from .stopwatch import timed
from .leaders import (LONG_LEADER, LONGEST_LEADER, far_leader, far_test, leader_of, led, led_leader, led_test,
                      runs_clear, short, sparing)

LABEL_PAD = 0.4         # white margin of a label's background
LABEL_GAP = 0.3         # mm between two labels' grounds
NUMBER_GAP = 1.5
"""mm between a link number's ground and another label's: set closer, "C 3" reads as C with a subscript."""


def _edge(u: Pt, hw: float, hh: float) -> float:
    """Distance from a box centre to its edge along unit ``u``."""
    cands = []
    if abs(u[0]) > 1e-9:
        cands.append(hw / abs(u[0]))
    if abs(u[1]) > 1e-9:
        cands.append(hh / abs(u[1]))
    return min(cands)


#: The 16 directions a point's label is tried in (measured CCW as seen on paper), their paper angles and
#: the small preference for the upper right (45 deg) each carries.
_DIRS = tuple((math.cos(2 * math.pi * i / 16), -math.sin(2 * math.pi * i / 16)) for i in range(16))
_DIR_ATAN = tuple(math.atan2(u[1], u[0]) for u in _DIRS)
_DIR_LEAN = tuple(0.05 * angle_gap(2 * math.pi * i / 16, math.pi / 4) for i in range(16))


_DISTS = ((0.7, 1.6, 3.0, 4.5), (6.0, 8.0, 11.0, 15.0), (3.0, 4.5, 6.0, 7.4), (8.5, 10.0, 12.0, 14.0))
"""mm from the anchor; then relaxed; then an arrow's label set off by a leader (within LONGEST_LEADER);
then on a long leader (within LONG_LEADER)"""
_ARROW_F = (0.5, 0.4, 0.6, 0.3, 0.7, 0.2, 0.8)                # where along an arrow, best first
_LED_F = _ARROW_F + (0.9, 0.95, 0.1)                          # ... and for a label set off by a leader
_TRIAL_S = (3.0, 6.0, 10.0, 15.0, 22.0)                       # mm in from either end of a trial line
_BEYOND = 1.7                                                 # the cost of a place beyond an arrow's tip


_TAU = 2 * math.pi


def _gaps(incident: list[float]) -> list[float]:
    """For each of the 16 directions, the angle to the nearest line at the anchor (pi when none):
    :func:`~drafting.render.drawing.angle_gap` written out, the same arithmetic."""
    if not incident:
        return [math.pi] * 16
    out = []
    for ap in _DIR_ATAN:
        best = math.inf
        for b in incident:
            d = abs(ap - b) % _TAU
            g = _TAU - d
            if d < g:
                g = d
            if g < best:
                best = g
        out.append(best)
    return out


class _Candidates:
    """The candidate centres of a label box of half sizes hw, hh, as their costs (all at once: the search
    goes cheapest first) and their centres, each made only when the search reaches it.

    In order: a polygon's own anchor first (when not relaxed); a point's 16 directions at each distance;
    an arrow's places along it (middle first) at each distance, left of it then right, then its places
    beyond its tip on its line; a trial line's
    places in from its near end then from its far end, at each distance and side.  The cost of a place is
    its distance, how far it strays from the widest gap between the lines at the anchor (a point), from
    the middle (an arrow) or from the end (a trial line)."""

    __slots__ = ("costs", "centre")

    def __init__(self, req: LabelReq, hw: float, hh: float, incident: list[float], relax: int) -> None:
        dists = _DISTS[relax]
        if req.kind in ("point", "polygon", "note"):
            self._around(req, hw, hh, incident, dists, req.kind in ("polygon", "note") and relax == 0)
        elif req.kind == "arrow":
            self._along_arrow(req, hw, hh, dists[:3] if relax == 0 else dists, _LED_F if relax >= 2 else _ARROW_F)
        elif req.kind == "trial":
            self._along_trial(req, hw, hh, dists[:3] if relax == 0 else dists)
        else:
            self.costs, self.centre = [], None

    def _around(self, req, hw, hh, incident, dists, anchor_first) -> None:
        p, r0 = req.anchor, req.r0
        gaps = _gaps(incident)
        edges = [_edge(u, hw, hh) for u in _DIRS]
        away = [2.0 * (math.pi - gap) for gap in gaps]
        first = [0.0] if anchor_first else []
        self.costs = first + [a + 0.8 * dist + lean for dist in dists for a, lean in zip(away, _DIR_LEAN)]
        skip = len(first)

        def centre(i: int) -> Pt:
            if i < skip:
                return p
            k, j = divmod(i - skip, 16)
            return shifted(p, _DIRS[j], r0 + dists[k] + edges[j])
        self.centre = centre

    def _along_arrow(self, req, hw, hh, dists, fs=_ARROW_F) -> None:
        tail, tip = req.other, req.anchor
        v = (tip[0] - tail[0], tip[1] - tail[1])
        u = unit_vector(v)
        sides = ((-u[1], u[0]), (u[1], -u[0]))
        self.costs = [3.0 * abs(f - 0.5) + 0.8 * dist + side * 0.1
                      for dist in dists for f in fs for side in (0, 1)]
        self.costs += [_BEYOND + 0.8 * dist for dist in dists]
        n_f = len(fs)
        n_along = len(self.costs) - len(dists)

        def centre(i: int) -> Pt:
            if i >= n_along:                    # beyond the tip, on the arrow's line
                return shifted(tip, u, dists[i - n_along] + 0.3 + _edge(u, hw, hh))
            k, rest = divmod(i, 2 * n_f)
            f, side = divmod(rest, 2)
            nn = sides[side]
            return shifted(shifted(tail, v, fs[f]), nn, dists[k] + 0.3 + _edge(nn, hw, hh))
        self.centre = centre

    def _along_trial(self, req, hw, hh, dists) -> None:
        end, start = req.anchor, req.other
        v = unit_vector((start[0] - end[0], start[1] - end[1]))
        sides = ((-v[1], v[0]), (v[1], -v[0]))
        self.costs = [0.1 * s + 0.8 * dist + far * 1.0
                      for dist in dists for s in _TRIAL_S for _ in sides for far in (0, 1)]
        n_s = len(_TRIAL_S)

        def centre(i: int) -> Pt:
            k, rest = divmod(i, 4 * n_s)
            s, rest = divmod(rest, 4)
            side, far = divmod(rest, 2)
            nn = sides[side]
            a = shifted(start, v, -_TRIAL_S[s]) if far else shifted(end, v, _TRIAL_S[s])
            return shifted(a, nn, dists[k] + _edge(nn, hw, hh))
        self.centre = centre


LABEL_KINDS = ("point", "arrow", "trial", "polygon", "note")
"""The kinds of label, placed in this order; a "note" (a note's or a dimension's text) sits at its anchor
where that is clear, else around it, on a note's white ground, named "<owner>:text" -- it names no point,
so no other entity can be mistaken for its own."""


@timed("labels")
def place_labels(d: Drawing, plot: Rect, region: str, size: float = LABEL) -> list[Command]:
    """Put every label where it overlaps no other label, arrowhead or symbol, inside ``plot``.

    A small candidate search: positions around the anchor are scored by how much line they would
    cover (a white background hides it) and how well they sit in the widest gap between the lines at
    the anchor; overlaps with labels, arrowheads, pins and dots are forbidden.  A place that hides part
    of a heavy line (a link, a vector, a load, a guide, a block) is taken only by a mandatory label with
    no other place, and a place as near another entity of the label's kind as its own (see
    :mod:`~drafting.layout.label_kin`) only when no clear one exists.  Optional labels (on arrows, trial
    lines and images) are left out when no free place exists.  A leader ties a short arrow to its label;
    the leaders are drawn first, under every label's white ground.
    """
    placed: list[Rect] = []
    out: list[Command] = []
    leaders: list[Command] = []
    tied: list[tuple[LabelReq, Rect, bool]] = []
    committed: list[Line] = []          # leaders of labels set off their arrows: later labels keep off them
    order = sorted(range(len(d.labels)), key=lambda i: (not d.labels[i].mandatory,
                                                        LABEL_KINDS.index(d.labels[i].kind)))
    segs = Segments(d.segments)
    kin = Kin(d) if d.labels else None
    def search(req: LabelReq, strict: bool):
        """The best candidate of ``req`` through its tiers (when ``strict``, the first tier's nearest places
        only), whether it is placed by its leader, the placed labels near it and the directions of the
        lines at it."""
        incident = (incident_directions(req.anchor, [d.segments[j] for j in segs.around(req.anchor, 0.2)])
                    if req.kind == "point" else [])
        # the neighbourhood every candidate box lies in: only what is in it can collide
        reach = _reach(req, hw, hh)
        near_segs = segs.near(reach)
        near_hard = [h for h in d.hard if h.overlaps(reach, 0.2)]
        gap = NUMBER_GAP if req.name.startswith(NUMBER) else LABEL_GAP
        near_placed = [p for p in placed if p.overlaps(reach, gap)]
        best, by_leader = None, False
        own_kin = None if req.kind == "note" else kin.test(req, reach, LABEL_PAD)
        for heavy_ok, clear, relaxes, by_leader in _tiers(req, own_kin, placed, d):
            if committed:                           # no label over a leader already drawn
                clear = sparing(clear, committed)
            for relax in relaxes[:1] if strict else relaxes:
                best = _best_candidate(_Candidates(req, hw, hh, incident, relax), hw, hh, plot,
                                       near_placed, near_hard, near_segs, heavy_ok, clear, segs, gap)
                if best is not None:
                    break
            if best is not None or strict:
                break
        return best, by_leader, near_placed, incident

    for i in order:
        req = d.labels[i]
        spans = rich(req.markup, size, pivot_digits=req.pivot_digits)
        ext = measure(spans)
        hw, hh = ext.width / 2 + LABEL_PAD, ext.height / 2 + LABEL_PAD
        best, by_leader, near_placed, incident = search(req, strict=bool(req.alternates))
        if best is None and req.alternates:
            # by another point of its entity, clear and unambiguous there; else anywhere by its anchor
            for at in req.alternates:
                moved = replace(req, anchor=at, alternates=())
                best, by_leader, near_placed, incident = search(moved, strict=True)
                if best is not None:
                    req = moved
                    break
            else:
                best, by_leader, near_placed, incident = search(req, strict=False)
        if best is None:
            if not req.mandatory:
                continue
            # last resort: the nearest position inside the plot that overlaps no other label
            for relax in (0, 1):
                cands = _Candidates(req, hw, hh, incident, relax)
                for i, cost in enumerate(cands.costs):
                    centre = cands.centre(i)
                    box = Rect(centre[0] - hw, centre[1] - hh, 2 * hw, 2 * hh)
                    if plot.contains(box) and not any(box.overlaps(o, LABEL_GAP) for o in near_placed):
                        if best is None or cost < best[0]:
                            best = (cost, centre, box)
            if best is None:
                raise LayoutError(f"no room for the label {req.markup!r} in the {region} viewport; use A3")
        _, centre, box = best
        placed.append(box)
        own = led_leader(req, box, by_leader) if by_leader else None    # placed by its leader: drawn, kept clear
        if own is None and led(req, box):
            own = leader_of(req, box)
        if own is None:             # set far off what it names: tied by a long leader where one is clear
            far = far_leader(req, box)
            if far is not None and runs_clear(far, [o for o in placed if o is not box], d):
                own = far
        if own is not None:
            committed.append(own)
        x = centre[0] - ext.width / 2
        y = centre[1] - (ext.top + ext.bottom) / 2
        tag, ground = ("text", "note_bg") if req.kind == "note" else ("label", "label_bg")
        out.append(Rectangle(box.x, box.y, box.w, box.h, ground, f"{req.name}:{tag} bg"))
        out.append(Text(x, y, spans, "label", ext.box(x, y), region, f"{req.name}:{tag}"))
        tied.append((req, box, by_leader, own))
    # once every label is placed, the leaders: one hidden under another's ground would leave a stray
    # stroke, so a far label's goes only where clear (a label placed by its leader was placed where it is)
    for req, box, by_leader, own in tied:
        leader = own if own is not None else leader_of(req, box)
        if leader is None:
            continue
        if by_leader or short(req) or req.kind == "note" or runs_clear(leader, [o for o in placed if o is not box], d):
            leaders.append(leader)
    return leaders + out            # the leaders first: under every label's white ground, never over a text


def _tiers(req: LabelReq, clear, placed: list[Rect], d: Drawing):
    """The searches a label's candidates go through, strictest first, as (heavy_ok, test, relaxes, led):
    hiding no heavy line and unambiguous; for an arrow, a trial line or a point, then set off it by a
    leader that makes it unambiguous (:func:`~drafting.layout.leaders.led_test`); then farther off with no
    leader; then on a long leader; then hiding no heavy line; then (a mandatory label only) anything.
    ``led`` is the longest leader the search may tie the label by (0: none)."""
    if req.kind == "note":          # a note set off its point is tied to it by a leader
        yield False, None, (0, 1), 0.0
        yield True, None, (0,), 0.0
        return
    if clear is not None:
        yield False, clear, (0,), 0.0
        if short(req):              # beside a short arrow, its leader from the arrow's middle counted its own
            yield False, led_test(req, clear, placed, d), (0, 2), LONGEST_LEADER
        ledable = req.kind == "point" or (req.kind in ("arrow", "trial") and req.other is not None and not short(req))
        if ledable:
            yield False, led_test(req, clear, placed, d), (2,), LONGEST_LEADER     # near, on a leader, before far
        # far off with no leader, only where a long leader would be clear (a link's number names the whole
        # link, and a curve's name is measured from one point of it: those are judged by the critic)
        far_tied = (req.kind in ("arrow", "trial") or req.r0 > 0) and ledable and not req.name.startswith(NUMBER)
        yield False, far_test(req, clear, placed, d) if far_tied else clear, (1,), 0.0
        if ledable:
            yield False, led_test(req, clear, placed, d, LONG_LEADER, 2), (3,), LONG_LEADER
    yield False, None, (0, 1), 0.0
    if req.mandatory:
        yield True, None, (0, 1), 0.0


def _best_candidate(cands: _Candidates, hw: float, hh: float, plot: Rect, near_placed: list[Rect],
                    near_hard: list[Rect], near_segs: list[tuple], heavy_ok: bool, clear=None,
                    segs: Segments | None = None, label_gap: float = LABEL_GAP):
    """(score, centre, box) of the best of ``cands`` -- the first of the lowest score in their order --
    or None when every one leaves the plot, overlaps a label or a symbol, hides part of a thick line
    (unless ``heavy_ok``) or fails ``clear(left, top, right, bottom)`` (the ambiguity test, see
    :mod:`~drafting.layout.label_kin`; measured last, and only for a candidate that would win).  A score is the candidate's cost plus what it hides of the lines (never
    negative), so the candidates are tried cheapest first and the search stops at the first whose cost
    exceeds the best score found: most labels are placed by their first few candidates, and only their
    centres are made.  The arithmetic of a score is the exhaustive test's, operation for operation, so
    the choice is the same to the last bit (a property test holds it to the exhaustive search, ties
    included)."""
    costs = cands.costs
    if not costs:
        return None
    centre_of = cands.centre
    tol = 1e-6
    pl, pt, pr, pb = plot.left - tol, plot.top - tol, plot.right + tol, plot.bottom + tol
    obstacles = [(o.left, o.top, o.right + gap, o.bottom + gap, gap)
                 for rects, gap in ((near_placed, label_gap), (near_hard, 0.2)) for o in rects]
    dense = segs is not None and segs.dense
    w, h = 2 * hw, 2 * hh
    best_total, best_i = math.inf, -1
    for i in sorted(range(len(costs)), key=costs.__getitem__):     # cheapest first, ties in their order
        cost = costs[i]
        if cost > best_total:                   # nothing left can score lower (or tie)
            break
        x, y = centre_of(i)
        le, to = x - hw, y - hh
        ri, bo = le + w, to + h
        if not (le >= pl and ri <= pr and to >= pt and bo <= pb):
            continue
        if _hits(obstacles, le, to, ri, bo):        # it overlaps a label or a symbol
            continue
        thin = thick = 0.0
        for x0, y0, x1, y1, a0, a1, dx, dy, heavy, length in (segs.meeting(le, to, ri, bo) if dense
                                                               else near_segs):
            if x0 <= ri and x1 >= le and y0 <= bo and y1 >= to:      # else it adds exactly 0.0
                got = clip_fraction(a0, a1, dx, dy, le, to, ri, bo) * length
                if heavy:
                    thick += got
                else:
                    thin += got
        if not heavy_ok and thick > 0:          # it would hide part of a link or a vector
            continue
        total = cost + 3.0 * thin + 20.0 * thick
        if total < best_total or (total == best_total and i < best_i):
            if clear is not None and not clear(le, to, ri, bo):
                continue                        # as near another entity of its kind as its own
            best_total, best_i = total, i
    if best_i < 0:
        return None
    x, y = centre_of(best_i)
    return best_total, (x, y), Rect(x - hw, y - hh, w, h)


def _hits(obstacles: list[tuple], le: float, to: float, ri: float, bo: float) -> bool:
    """Whether the box (le, to, ri, bo) overlaps one of ``obstacles`` (left, top, right + gap, bottom + gap,
    gap) -- a loop, not any() over a generator: the search asks this of thousands of candidates."""
    for o_l, o_t, o_r, o_b, gap in obstacles:
        if le < o_r and o_l < ri + gap and to < o_b and o_t < bo + gap:
            return True
    return False


_FAR = 15.0 + 1.0       # the farthest candidate distance (relaxed) and a margin


def _reach(req: LabelReq, hw: float, hh: float) -> Rect:
    """A rectangle holding every candidate box of ``req`` (see :class:`_Candidates`)."""
    r = req.r0 + _FAR + 2 * (hw + hh)
    if req.kind in ("point", "polygon", "note") or req.other is None:
        x, y = req.anchor
        return Rect(x - r, y - r, 2 * r, 2 * r)
    a, b = req.anchor, req.other
    if req.kind == "trial":
        r += 22.0               # candidates run up to 22 mm in from either end
    return Rect.from_edges(min(a[0], b[0]) - r, min(a[1], b[1]) - r, max(a[0], b[0]) + r, max(a[1], b[1]) + r)
