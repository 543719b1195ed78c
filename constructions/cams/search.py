"""Searching along the cam angle: the largest or smallest of a function over the turn, and the spans where
one is positive, every piece of the motion program searched on its own (a join, where a derivative
jumps, always a grid point), all pieces at once.
"""

from __future__ import annotations

import math

import numpy as np

from ..tolerance import SPAN_END_RAD, SPAN_JOIN_RAD
from .laws import TAU, Program


def segment_breaks(program: Program) -> np.ndarray:
    """The cam angles where the program's pieces meet (segment joins and laws' inner joins)."""
    return np.array(sorted({0.0, TAU} | {j.theta for j in program.joins()} | set(program.starts)))


def _grid(program: Program, per_piece: int) -> list[np.ndarray]:
    b = segment_breaks(program)
    return [np.linspace(lo, hi, per_piece) for lo, hi in zip(b[:-1], b[1:]) if hi - lo > 0]


def extremum(program: Program, fn, *, per_piece: int = 256, largest: bool = True) -> tuple[float, float]:
    """The cam angle and value of the largest (or smallest) of ``fn(theta)`` (a vectorised function)
    over the turn: a grid in every piece of the program, refined by narrowing grids round each piece's best
    (every piece at once: one call of ``fn`` per round)."""
    return extrema(program, lambda x: x, [(fn, largest)], per_piece=per_piece)[0]


def extrema(program: Program, at, searches, *, per_piece: int = 256) -> list[tuple[float, float]]:
    """:func:`extremum` of several functions of one costly quantity at once: ``at(theta)`` computes it
    (an evaluation of the profile) on a flat array of cam angles, and each search is ``(fn, largest)``
    with ``fn`` reading a vectorised function off it.  Every search narrows its own brackets exactly as
    :func:`extremum` does, and all of them share one call of ``at`` per round (the cost of a round is in
    the number of array operations, not in their length); the answers are the same, point for point."""
    out = []
    for found in piece_extrema(program, at, searches, per_piece=per_piece):
        b = max(range(len(found)), key=lambda p: (found[p][2], -p))      # the first piece of the best
        out.append(found[b][:2])
    return out


def piece_extrema(program: Program, at, searches, *, per_piece: int = 256) -> list[list[tuple[float, float, float]]]:
    """Each search's extreme on every piece of the program (:func:`piece_bounds` order): per search, a list
    of ``(theta, value, rank)`` with ``rank`` the value signed so that larger is better (-inf where the
    function is nowhere finite).  A grid of ``per_piece`` points, then 8 rounds each narrowing the bracket
    round the best point 16-fold, to a bracket ``2 / (per_piece - 1) / 16^8`` (2e-12 at 256) of the piece's
    width.  An extreme inside the piece comes out to rounding in its value, but its cam angle only to about
    ``sqrt(eps |f| / |f''|)`` (1e-8 rad for a pressure angle): the curve is flat at its peak, and points that
    far apart differ by rounding; an extreme at an end is exact."""
    k = len(searches)
    sgn = np.array([1.0 if largest else -1.0 for _, largest in searches])

    def f(x: np.ndarray) -> np.ndarray:               # x: searches x pieces x points
        q = at(x.ravel())
        w = np.stack([s * np.asarray(fn(q), dtype=float).reshape(x.shape)[i]
                      for i, (s, (fn, _)) in enumerate(zip(sgn, searches))])
        return np.where(np.isfinite(w), w, -math.inf)

    g1 = np.array(_grid(program, per_piece))                # pieces x per_piece
    g = np.broadcast_to(g1, (k,) + g1.shape)
    v = f(np.ascontiguousarray(g))
    rows = np.arange(len(g1))[None, :]
    srch = np.arange(k)[:, None]
    j = np.argmax(v, axis=2)
    cand_x, cand_v = g[srch, rows, j], v[srch, rows, j]
    lo, hi = g[srch, rows, np.maximum(j - 1, 0)], g[srch, rows, np.minimum(j + 1, per_piece - 1)]
    u = np.linspace(0.0, 1.0, 33)
    for _ in range(8):                  # each round narrows every bracket 16-fold
        x = lo[..., None] + (hi - lo)[..., None] * u
        w = f(x)
        j = np.argmax(w, axis=2)
        better = w[srch, rows, j] >= cand_v
        cand_x = np.where(better, x[srch, rows, j], cand_x)
        cand_v = np.where(better, w[srch, rows, j], cand_v)
        lo, hi = x[srch, rows, np.maximum(j - 1, 0)], x[srch, rows, np.minimum(j + 1, 32)]
    return [[(float(cand_x[i, p]), float(sgn[i] * cand_v[i, p]), float(cand_v[i, p])) for p in range(len(g1))]
            for i in range(k)]


def piece_bounds(program: Program) -> list[tuple[float, float]]:
    """The (start, end) cam angles of the pieces :func:`piece_extrema` searches, in its order."""
    b = segment_breaks(program)
    return [(float(lo), float(hi)) for lo, hi in zip(b[:-1], b[1:]) if hi - lo > 0]


def _boundaries(g, a: np.ndarray, b: np.ndarray, ga: np.ndarray) -> np.ndarray:
    """Where ``g`` changes sign inside each bracket [a, b] (g(a) = ga on the one side): every bracket cut in
    16 at once per round (one call of ``g``), to :data:`~constructions.tolerance.SPAN_END_RAD`."""
    u = np.arange(1, 16) / 16.0
    pos = ga > 0
    for _ in range(16):
        if not np.max(b - a) >= SPAN_END_RAD:
            break
        x = a[:, None] + (b - a)[:, None] * u[None, :]
        side = (np.asarray(g(x.ravel()), dtype=float).reshape(x.shape) > 0) == pos[:, None]
        # the first point on the far side (16: none, the boundary lies past the last point)
        first = np.where(side.all(axis=1), 15, np.argmin(side, axis=1))
        xa = np.concatenate([a[:, None], x, b[:, None]], axis=1)
        rows = np.arange(len(a))
        a, b = xa[rows, first], xa[rows, first + 1]
    return 0.5 * (a + b)


def spans(program: Program, g, *, per_piece: int = 256) -> list[tuple[float, float]]:
    """The cam-angle intervals where ``g(theta) > 0`` (g vectorised), ends found by cutting their brackets."""
    grid = np.array(_grid(program, per_piece))
    v = np.asarray(g(grid.ravel()), dtype=float).reshape(grid.shape)
    inside = v > 0
    # the brackets of every change of side, found together
    pi, ki = np.nonzero(inside[:, 1:] != inside[:, :-1])
    ends = _boundaries(g, grid[pi, ki], grid[pi, ki + 1], v[pi, ki]) if len(pi) else np.zeros(0)
    out: list[list[float]] = []
    for p in range(len(grid)):
        start = grid[p, 0] if inside[p, 0] else None
        for k, x in zip(ki[pi == p], ends[pi == p]):
            if inside[p, k + 1]:
                start = x
            else:
                out.append([start, x])
                start = None
        if start is not None:
            out.append([start, grid[p, -1]])
    merged: list[list[float]] = []
    for a, b in out:
        if merged and abs(a - merged[-1][1]) < SPAN_JOIN_RAD:
            merged[-1][1] = b
        else:
            merged.append([a, b])
    if len(merged) > 1 and merged[0][0] <= SPAN_JOIN_RAD and merged[-1][1] >= TAU - SPAN_JOIN_RAD:
        merged[0][0] = merged[-1][0] - TAU
        merged.pop()
    return [(a, b) for a, b in merged]
