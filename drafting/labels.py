"""Label placement: every label of a drawn diagram put where it overlaps no other label or symbol.

``place_labels`` searches candidate positions around each label's anchor and scores them by how much
line they would hide and how well they sit in the gap between the lines at the anchor.  Only the lines,
symbols and labels in the neighbourhood a label's candidates can reach are tested against them.
"""

from __future__ import annotations

import math

import numpy as np

from .drawing import Drawing, LabelReq, Pt, shifted, angle_gap, incident_directions, unit_vector
from .errors import LayoutError
from .paper import Command, Rect, Rectangle, Text
from .style import LABEL, measure, rich

LABEL_PAD = 0.4         # white margin of a label's background


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
_UX, _UY, _LEAN = np.array([u[0] for u in _DIRS]), np.array([u[1] for u in _DIRS]), np.array(_DIR_LEAN)


def _candidates(req: LabelReq, hw: float, hh: float, incident: list[float], relax: int):
    """(centre, cost) candidates for a label box of half sizes hw, hh."""
    dists = (0.7, 1.6, 3.0, 4.5) if relax == 0 else (6.0, 8.0, 11.0, 15.0)
    p = req.anchor
    if req.kind in ("point", "polygon"):
        if req.kind == "polygon" and relax == 0:
            yield p, 0.0
        gaps = [min((angle_gap(ap, b) for b in incident), default=math.pi) for ap in _DIR_ATAN]
        edges = [_edge(u, hw, hh) for u in _DIRS]
        for dist in dists:
            for u, gap, edge, lean in zip(_DIRS, gaps, edges, _DIR_LEAN):
                t = req.r0 + dist + edge
                cost = 2.0 * (math.pi - gap) + 0.8 * dist + lean
                yield shifted(p, u, t), cost
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
                    yield shifted(a, nn, dist + 0.3 + _edge(nn, hw, hh)), 3.0 * abs(f - 0.5) + 0.8 * dist + (side < 0) * 0.1
    elif req.kind == "trial":
        end, start = req.anchor, req.other
        v = unit_vector((start[0] - end[0], start[1] - end[1]))
        n = (-v[1], v[0])
        for dist in dists[:3] if relax == 0 else dists:
            for s in (3.0, 6.0, 10.0, 15.0, 22.0):
                a = shifted(end, v, s)
                for side in (1.0, -1.0):
                    nn = (n[0] * side, n[1] * side)
                    yield shifted(a, nn, dist + _edge(nn, hw, hh)), 0.1 * s + 0.8 * dist
                    # the other end of the line as well
                    b = shifted(start, v, -s)
                    yield shifted(b, nn, dist + _edge(nn, hw, hh)), 0.1 * s + 0.8 * dist + 1.0


def place_labels(d: Drawing, plot: Rect, region: str, size: float = LABEL) -> list[Command]:
    """Put every label where it overlaps no other label, arrowhead or symbol, inside ``plot``.

    A small candidate search: positions around the anchor are scored by how much line they would
    cover (a white background hides it) and how well they sit in the widest gap between the lines at
    the anchor; overlaps with labels, arrowheads, pins and dots are forbidden.  Optional labels
    (on arrows, trial lines and images) are left out when no free place exists.
    """
    placed: list[Rect] = []
    out: list[Command] = []
    order = sorted(range(len(d.labels)), key=lambda i: (not d.labels[i].mandatory,
                                                        ["point", "arrow", "trial", "polygon"].index(d.labels[i].kind)))
    segs = _Segments(d.segments)
    for i in order:
        req = d.labels[i]
        spans = rich(req.markup, size, pivot_digits=req.pivot_digits)
        ext = measure(spans)
        hw, hh = ext.width / 2 + LABEL_PAD, ext.height / 2 + LABEL_PAD
        incident = (incident_directions(req.anchor, [d.segments[j] for j in segs.around(req.anchor, 0.2)])
                    if req.kind == "point" else [])
        # the neighbourhood every candidate box lies in: only what is in it can collide
        reach = _reach(req, hw, hh)
        near_segs = segs.near(reach)
        near_hard = [h for h in d.hard if h.overlaps(reach, 0.2)]
        near_placed = [p for p in placed if p.overlaps(reach, 0.3)]
        best = None
        for relax in (0, 1):
            best = _best_candidate(_candidate_array(req, hw, hh, incident, relax), hw, hh, plot,
                                   near_placed, near_hard, near_segs, req.mandatory)
            if best is not None:
                break
        if best is None:
            if not req.mandatory:
                continue
            # last resort: the nearest position inside the plot that overlaps no other label
            for relax in (0, 1):
                for centre, cost in _candidates(req, hw, hh, incident, relax):
                    box = Rect(centre[0] - hw, centre[1] - hh, 2 * hw, 2 * hh)
                    if plot.contains(box) and not any(box.overlaps(o, 0.3) for o in near_placed):
                        if best is None or cost < best[0]:
                            best = (cost, centre, box)
            if best is None:
                raise LayoutError(f"no room for the label {req.markup!r} in the {region} viewport; use A3")
        _, centre, box = best
        placed.append(box)
        x = centre[0] - ext.width / 2
        y = centre[1] - (ext.top + ext.bottom) / 2
        out.append(Rectangle(box.x, box.y, box.w, box.h, "label_bg", f"{req.name}:label bg"))
        out.append(Text(x, y, spans, "label", ext.box(x, y), region, f"{req.name}:label"))
    return out


def _edges(ux: np.ndarray, uy: np.ndarray, hw: float, hh: float) -> np.ndarray:
    """:func:`_edge` of each unit vector (ux, uy)."""
    ax, ay = np.abs(ux), np.abs(uy)
    with np.errstate(divide="ignore"):
        return np.minimum(np.where(ax > 1e-9, hw / ax, np.inf), np.where(ay > 1e-9, hh / ay, np.inf))


_ATAN = np.array(_DIR_ATAN)
_ARROW_F = np.array((0.5, 0.4, 0.6, 0.3, 0.7, 0.2, 0.8))
_TRIAL_S = np.array((3.0, 6.0, 10.0, 15.0, 22.0))
_SIDES = np.array((1.0, -1.0))


def _candidate_array(req: LabelReq, hw: float, hh: float, incident: list[float], relax: int) -> np.ndarray:
    """:func:`_candidates` as an (n, 3) array of centre x, y and cost, in the same order and to the last
    bit (computed at once, with the generator's arithmetic operation for operation)."""
    dists = np.array((0.7, 1.6, 3.0, 4.5) if relax == 0 else (6.0, 8.0, 11.0, 15.0))
    if req.kind in ("point", "polygon"):
        if incident:
            d = np.abs(_ATAN[:, None] - np.array(incident)[None, :]) % (2 * math.pi)
            gaps = np.minimum(d, 2 * math.pi - d).min(axis=1)
        else:
            gaps = np.full(16, math.pi)
        edges = _edges(_UX, _UY, hw, hh)
        t = (req.r0 + dists)[:, None] + edges[None, :]
        cost = (2.0 * (math.pi - gaps))[None, :] + (0.8 * dists)[:, None] + _LEAN[None, :]
        p = req.anchor
        out = np.stack([(p[0] + _UX[None, :] * t).ravel(), (p[1] + _UY[None, :] * t).ravel(), cost.ravel()], axis=1)
        if req.kind == "polygon" and relax == 0:
            out = np.vstack([np.array([[p[0], p[1], 0.0]]), out])
        return out
    if req.kind == "arrow":
        tail, tip = req.other, req.anchor
        v = (tip[0] - tail[0], tip[1] - tail[1])
        u = unit_vector(v)
        n = (-u[1], u[0])
        dd = dists[:3] if relax == 0 else dists
        e = _edge(n, hw, hh)                            # the same on either side
        t = (dd + 0.3) + e                              # (dist,)
        ax, ay = tail[0] + v[0] * _ARROW_F, tail[1] + v[1] * _ARROW_F      # (f,)
        nx, ny = n[0] * _SIDES, n[1] * _SIDES            # (side,)
        cx = ax[None, :, None] + nx[None, None, :] * t[:, None, None]
        cy = ay[None, :, None] + ny[None, None, :] * t[:, None, None]
        cost = ((3.0 * np.abs(_ARROW_F - 0.5))[None, :, None] + (0.8 * dd)[:, None, None]) \
            + np.array((0.0, 0.1))[None, None, :]
        shape = cx.shape
    elif req.kind == "trial":
        end, start = req.anchor, req.other
        v = unit_vector((start[0] - end[0], start[1] - end[1]))
        n = (-v[1], v[0])
        dd = dists[:3] if relax == 0 else dists
        t = dd + _edge(n, hw, hh)                       # (dist,)
        nx, ny = n[0] * _SIDES, n[1] * _SIDES            # (side,)
        # (dist, s, side, end): from the near end, then from the far end
        bx = np.stack([end[0] + v[0] * _TRIAL_S, start[0] + v[0] * -_TRIAL_S], axis=1)       # (s, end)
        by = np.stack([end[1] + v[1] * _TRIAL_S, start[1] + v[1] * -_TRIAL_S], axis=1)
        cx = bx[None, :, None, :] + nx[None, None, :, None] * t[:, None, None, None]
        cy = by[None, :, None, :] + ny[None, None, :, None] * t[:, None, None, None]
        base = (0.1 * _TRIAL_S)[None, :] + (0.8 * dd)[:, None]                             # (dist, s)
        cost = np.stack([base, base + 1.0], axis=2)[:, :, None, :]
        shape = cx.shape
    else:
        return np.zeros((0, 3))
    return np.stack([cx.ravel(), cy.ravel(), np.broadcast_to(cost, shape).ravel()], axis=1)


def _best_candidate(cands: np.ndarray, hw: float, hh: float, plot: Rect, near_placed: list[Rect],
                    near_hard: list[Rect], near_segs: "_Segments", mandatory: bool):
    """(score, centre, box) of the best of ``cands`` -- the first of the lowest score in their order --
    or None when every one leaves the plot, overlaps a label or a symbol, or (an optional label) hides
    part of a thick line.  A score is the candidate's cost plus what it hides of the lines (never
    negative), so the candidates are tried cheapest first and the search stops at the first whose cost
    exceeds the best score found: most labels are placed by their first few candidates.  The arithmetic
    of a score is the exhaustive test's, operation for operation, so the choice is the same to the last
    bit (a property test holds it to the exhaustive search, ties included)."""
    if not len(cands):
        return None
    cx, cy, cost = cands[:, 0], cands[:, 1], cands[:, 2]
    left, top = cx - hw, cy - hh
    right, bottom = left + 2 * hw, top + 2 * hh
    bx = near_segs.boxes
    # which line boxes each candidate box meets (the others add exactly 0.0 to its sums)
    touch = ((bx[:, 0] <= right[:, None]) & (bx[:, 2] >= left[:, None])
             & (bx[:, 1] <= bottom[:, None]) & (bx[:, 3] >= top[:, None]))
    order = np.argsort(cost, kind="stable").tolist()          # cheapest first, ties in their order
    L, T, R, B, C = left.tolist(), top.tolist(), right.tolist(), bottom.tolist(), cost.tolist()
    tol = 1e-6
    pl, pt, pr, pb = plot.left - tol, plot.top - tol, plot.right + tol, plot.bottom + tol
    obstacles = [(o.left, o.top, o.right + gap, o.bottom + gap, gap)
                 for rects, gap in ((near_placed, 0.3), (near_hard, 0.2)) for o in rects]
    ends, heavy, length = near_segs.ends.tolist(), near_segs.heavy.tolist(), near_segs.length.tolist()
    best_total, best_i = math.inf, -1
    for i in order:
        if C[i] > best_total:                   # nothing left can score lower (or tie)
            break
        le, to, ri, bo = L[i], T[i], R[i], B[i]
        if not (le >= pl and ri <= pr and to >= pt and bo <= pb):
            continue
        if any(le < o_r and o_l < ri + gap and to < o_b and o_t < bo + gap
               for o_l, o_t, o_r, o_b, gap in obstacles):
            continue
        thin = thick = 0.0
        for j in np.flatnonzero(touch[i]).tolist():
            a0, a1, b0, b1 = ends[j]
            got = _clip(a0, a1, b0 - a0, b1 - a1, le, to, ri, bo) * length[j]
            if heavy[j]:
                thick += got
            else:
                thin += got
        if not mandatory and thick > 0:         # an optional label never hides part of a thick line
            continue
        total = C[i] + 3.0 * thin + 20.0 * thick
        if total < best_total or (total == best_total and i < best_i):
            best_total, best_i = total, i
    if best_i < 0:
        return None
    centre = (float(cx[best_i]), float(cy[best_i]))
    return best_total, centre, Rect(centre[0] - hw, centre[1] - hh, 2 * hw, 2 * hh)


class _Segments:
    """The line segments of a drawing as arrays: ends, bounding boxes, lengths and weights."""

    def __init__(self, segments) -> None:
        self.ends = np.array([(a[0], a[1], b[0], b[1]) for a, b, _ in segments], dtype=float).reshape(-1, 4)
        e = self.ends
        self.boxes = np.stack([np.minimum(e[:, 0], e[:, 2]), np.minimum(e[:, 1], e[:, 3]),
                               np.maximum(e[:, 0], e[:, 2]), np.maximum(e[:, 1], e[:, 3])], axis=1)
        self.heavy = np.array([bool(h) for _, _, h in segments], dtype=bool)
        self.length = np.array([math.hypot(b[0] - a[0], b[1] - a[1]) for a, b, _ in segments], dtype=float)

    def around(self, p: Pt, margin: float) -> list[int]:
        """Indices, in order, of the segments whose boxes grown by ``margin`` hold ``p`` (every line
        that can leave ``p`` within a tolerance below ``margin`` / 2 is among them)."""
        b = self.boxes
        keep = ((b[:, 0] - margin <= p[0]) & (p[0] <= b[:, 2] + margin)
                & (b[:, 1] - margin <= p[1]) & (p[1] <= b[:, 3] + margin))
        return np.flatnonzero(keep).tolist()

    def near(self, reach: Rect) -> "_Segments":
        """The segments whose boxes meet ``reach``, in their order."""
        b = self.boxes
        keep = (b[:, 0] <= reach.right) & (b[:, 2] >= reach.left) & (b[:, 1] <= reach.bottom) & (b[:, 3] >= reach.top)
        sub = object.__new__(_Segments)
        sub.ends, sub.boxes, sub.heavy, sub.length = self.ends[keep], b[keep], self.heavy[keep], self.length[keep]
        return sub


def _clip(a0: float, a1: float, dx: float, dy: float, left: float, top: float, right: float,
          bottom: float) -> float:
    """The fraction of the segment from (a0, a1) along (dx, dy) inside a box (Liang-Barsky)."""
    t0, t1 = 0.0, 1.0
    for p, q in ((-dx, a0 - left), (dx, right - a0), (-dy, a1 - top), (dy, bottom - a1)):
        if abs(p) < 1e-12:                      # parallel to this edge: outside, or no limit
            if q < 0:
                return 0.0
            continue
        t = q / p
        if p < 0:
            if t > t0:
                t0 = t
        elif t < t1:
            t1 = t
        if t0 > t1:
            return 0.0
    return t1 - t0


_FAR = 15.0 + 1.0       # the farthest candidate distance (relaxed) and a margin


def _reach(req: LabelReq, hw: float, hh: float) -> Rect:
    """A rectangle holding every candidate box of ``req`` (see :func:`_candidates`)."""
    r = req.r0 + _FAR + 2 * (hw + hh)
    if req.kind in ("point", "polygon") or req.other is None:
        x, y = req.anchor
        return Rect(x - r, y - r, 2 * r, 2 * r)
    a, b = req.anchor, req.other
    if req.kind == "trial":
        r += 22.0               # candidates run up to 22 mm in from either end
    return Rect.from_edges(min(a[0], b[0]) - r, min(a[1], b[1]) - r, max(a[0], b[0]) + r, max(a[1], b[1]) + r)
