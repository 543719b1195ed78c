"""Trimming a cam profile: the envelope points no roller circle or face line cuts into, each fold cut at the
crossing of its two branches (a flat face's: the convex hull of the points kept).
"""

from __future__ import annotations

import numpy as np

from ..tolerance import DECISION
from .envelope import Evaluation
from .follower import FACES, Follower


def trim_envelope(f: Follower, ev: Evaluation, size: float) -> np.ndarray:
    """The valid profile of ``ev`` (2 x M, closed) for the follower ``f`` on a cam of ``size``: its points that
    no roller circle about ``ev.pitch`` (a face: no face line of ``ev``) cuts into, each removed loop replaced
    by the crossing of its two branches (see :func:`.profile.trim`)."""
    C = ev.profile
    n = C.shape[1]
    tol = DECISION * size
    keep = np.ones(n, dtype=bool)
    if f.kind in FACES:
        # a point is cut if some face line lies between it and the centre: p . u_j > rb + s_j
        U, r = ev.normal, (f.base_radius + ev.s if ev.support is None else ev.support)
        for lo in range(0, n, 512):
            d = C[:, lo:lo + 512].T @ U - r[None, :]
            keep[lo:lo + 512] = np.max(d, axis=1) <= tol
    else:
        # squared distances against the squared limit (the same decision as the distances, without a root),
        # each run of 128 neighbouring points against only the roller centres inside its bounding box grown
        # by the roller's radius (no centre outside it can come within rr of any of them)
        P = ev.pitch
        rr = f.roller_radius
        limit = (rr - tol) ** 2
        for lo in range(0, n, 128):
            c = C[:, lo:lo + 128]
            near = ((P[0] > c[0].min() - rr) & (P[0] < c[0].max() + rr) &
                    (P[1] > c[1].min() - rr) & (P[1] < c[1].max() + rr))
            if not near.any():
                continue
            q = P[:, near]
            dx = c[0][:, None] - q[0][None, :]
            dy = c[1][:, None] - q[1][None, :]
            dx *= dx
            dy *= dy
            dx += dy
            keep[lo:lo + 128] = np.min(dx, axis=1) >= limit
    if keep.all():
        return C
    if not keep.any():
        raise ValueError("no point of the profile survives: the follower cuts the whole cam away")
    if f.kind in FACES:
        # the cam a flat face leaves is the intersection of the half-planes behind its face lines: convex,
        # so its boundary is the convex hull of the envelope points no face line cuts (shapely; a corner
        # where the envelope folds becomes the chord across it)
        from shapely.geometry import MultiPoint
        hull = MultiPoint(C[:, keep].T).convex_hull
        xy = np.asarray(hull.exterior.coords)[:-1][::-1] if f.sense < 0 else np.asarray(hull.exterior.coords)[:-1]
        return xy.T
    # rotate so that index 0 is kept, then take the runs: each run kept whole, each run cut away replaced by
    # the crossing of the chords either side of it
    k0 = int(np.argmax(keep))
    idx = np.roll(np.arange(n), -k0)
    kp = keep[idx]
    cut_from = np.flatnonzero(kp[:-1] & ~kp[1:]) + 1              # first point of each run cut away
    cut_to = np.append(np.flatnonzero(~kp[:-1] & kp[1:]) + 1, n)[:len(cut_from)]   # first point kept after it
    pieces: list[np.ndarray] = []
    i = 0
    for a, b in zip(cut_from, cut_to):
        pieces.append(C[:, idx[i:a]].T)
        x = _cross_point(C[:, idx[a - 1]], C[:, idx[a]], C[:, idx[b - 1]], C[:, idx[b % n]])
        if x is not None:
            pieces.append(x[None, :])
        i = b
    pieces.append(C[:, idx[i:]].T)
    return np.concatenate(pieces).T


def _cross_point(a0, a1, b0, b1):
    """Where the chords a0-a1 and b0-b1 cross (their lines' crossing, kept if it lies near both)."""
    da, db = a1 - a0, b1 - b0
    den = da[0] * db[1] - da[1] * db[0]
    if den == 0:
        return None
    w = b0 - a0
    t = (w[0] * db[1] - w[1] * db[0]) / den
    return a0 + t * da
