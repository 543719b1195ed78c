"""What the sweep's closed-form kernels do the same way: chunks of crank angles with scratch buffers of
their own, output blocks (or the caller's buffers), the crank tip's motion, the three-way gap decision,
and NaN at gaps and toggles -- all in place, with ``out=`` ufuncs.

Work is done in chunks of :data:`CHUNK` angles with preallocated scratch buffers, so the working set
stays in cache.
"""

from __future__ import annotations

import numpy as np

from ..analytic.parts import SINE_TOL
from ..analytic.states import FOURBAR_FIELDS
from .trig import sincos

__all__ = ["CHUNK", "chunk_of", "chunks", "crank_motion", "four_bar_buffers", "given_block", "given_outputs", "nan_at_gaps",
           "nan_where_singular", "outputs", "products", "three_way"]

#: Number of crank angles processed per chunk (tuned on a Xeon with 2 MB of L2 per core;
#: 2**13 .. 2**15 measure within noise of each other).
CHUNK = 2**14


def outputs(names, n):
    """One (len(names), n) block, a row per field: a single allocation, which for large n the
    allocator maps in huge pages (numpy asks for them from 4 MB up), so the first touch of the output
    costs a few page faults instead of one per 4 kB (measured ~15 % of a 1e6-angle four-bar).  The
    returned arrays are views of the block and keep all of it alive."""
    block = np.empty((len(names), n))
    return {name: block[k] for k, name in enumerate(names)}


def given_block(given, names, n):
    """The caller's buffers (``(block, assembles)``, checked), or a fresh block (a row per field, see
    :func:`outputs`) and assembles."""
    if given is None:
        return np.empty((len(names), n)), np.empty(n, dtype=bool)
    try:
        block, asm = given
    except (TypeError, ValueError):
        raise ValueError("out must be a pair (float block, bool assembles)") from None
    if not (isinstance(block, np.ndarray) and block.dtype == np.float64 and block.shape == (len(names), n)
            and block.flags.c_contiguous and block.flags.writeable):
        raise ValueError(f"out[0] must be a writable C-contiguous float64 array of shape ({len(names)}, {n})")
    if not (isinstance(asm, np.ndarray) and asm.dtype == np.bool_ and asm.shape == (n,) and asm.flags.writeable):
        raise ValueError(f"out[1] must be a writable bool array of shape ({n},)")
    return block, asm


def given_outputs(given, names, n):
    """The caller's buffers (``(block, assembles)``, checked) as the fields' views, or fresh ones."""
    block, asm = given_block(given, names, n)
    return {name: block[k] for k, name in enumerate(names)}, asm


def four_bar_buffers(n: int) -> tuple[np.ndarray, np.ndarray]:
    """Output buffers for :func:`constructions.sweep_kernels.four_bar` over ``n`` crank angles (pass them
    as ``out=``)."""
    return np.empty((len(FOURBAR_FIELDS), n)), np.empty(n, dtype=bool)


def chunk_of(w, i, j):
    """Angles i..j of a crank rate given as a float (the same for all) or a flat array."""
    return w if isinstance(w, float) else w[i:j]


def chunks(start: int, stop: int, floats: int):
    """Yield ``(i, j, scratch, flags)`` for each chunk [i, j) of the angles [start, stop): ``floats`` float
    scratch arrays and one bool array, of the chunk's length (allocated once, views for the last, short
    chunk)."""
    m = min(CHUNK, max(stop - start, 1))
    scratch = [np.empty(m) for _ in range(floats)]
    flags = np.empty(m, dtype=bool)
    for i in range(start, stop, CHUNK):
        j = min(i + CHUNK, stop)
        if j - i != m:  # last, short chunk: views of the scratch buffers
            m = j - i
            scratch = [a[:m] for a in scratch]
            flags = flags[:m]
        yield i, j, scratch, flags


def _crank_tip(c, s, r1, o1x, o1y, w, Bx, By, VBx, VBy) -> None:
    """B = O1 + r1 (cos, sin) and V_B = omega1 k x (B - O1) = omega1 r1 (-sin, cos), into the out arrays."""
    np.multiply(c, r1, out=Bx)
    if o1x:
        Bx += o1x
    np.multiply(s, r1, out=By)
    if o1y:
        By += o1y
    if isinstance(w, float):
        np.multiply(s, -w * r1, out=VBx)
        np.multiply(c, w * r1, out=VBy)
    else:
        np.multiply(s, w, out=VBx)
        VBx *= -r1
        np.multiply(c, w, out=VBy)
        VBy *= r1


def _crank_tip_acceleration(c, s, r1, w, a, ABx, ABy, t, u) -> None:
    """A_B = d/dt V_B into ABx, ABy; t and u are scratch.

    V_B = omega1 r1 (-sin, cos)(theta1) with theta1' = omega1 and omega1' = alpha1, so
    A_B = alpha1 r1 (-sin, cos) - omega1^2 r1 (cos, sin) = alpha1 k x r - omega1^2 r, r = B - O1:
    the tangential part square to the crank, the normal part towards O1.
    """
    if isinstance(w, float):
        nrm = -w * w * r1
    else:
        np.multiply(w, w, out=t)
        t *= -r1
        nrm = t
    np.multiply(c, nrm, out=ABx)  # -omega1^2 r1 cos
    np.multiply(s, nrm, out=ABy)  # -omega1^2 r1 sin
    if not isinstance(a, float) or a != 0.0:
        # the same operations for a scalar and an array alpha1: each element's value does not
        # depend on how alpha1 was given
        np.multiply(s, a, out=u)
        u *= -r1
        ABx += u
        np.multiply(c, a, out=u)
        u *= r1
        ABy += u


def crank_motion(th, r1, o1x, o1y, w, a, c, s, t, u, Bx, By, VBx, VBy, ABx, ABy) -> None:
    """The crank at angles ``th``: cos and sin into c and s, B, V_B and A_B into the out arrays; t and u
    are scratch."""
    sincos(th, c, s, t, u)
    _crank_tip(c, s, r1, o1x, o1y, w, Bx, By, VBx, VBy)
    _crank_tip_acceleration(c, s, r1, w, a, ABx, ABy, t, u)


def three_way(f1, f2, tol, closes, flags) -> None:
    """The three-way decision on the two gap factors of a half-chord, in place: ``closes`` False where
    a factor is below ``-tol`` (apart) or NaN, a factor within ``tol`` of zero snapped to 0 (tangent);
    ``flags`` is scratch."""
    if f1.min() > tol and f2.min() > tol:
        closes.fill(True)  # fast path: clearly closed at every angle of the chunk
        return
    np.greater_equal(f1, -tol, out=closes)
    np.greater_equal(f2, -tol, out=flags)
    closes &= flags
    np.less_equal(f1, tol, out=flags)
    np.copyto(f1, 0.0, where=flags)
    np.less_equal(f2, tol, out=flags)
    np.copyto(f2, 0.0, where=flags)


def nan_at_gaps(closes, tmp, arrays) -> None:
    """Make each of ``arrays`` NaN where the loop does not close (z = 0 where it closes, NaN elsewhere,
    added in; NaN then propagates to everything computed from them); tmp is scratch."""
    if closes.all():
        return
    np.copyto(tmp, closes)
    np.divide(0.0, tmp, out=tmp)
    for a in arrays:
        a += tmp


def nan_where_singular(inv, condition, flags) -> None:
    """NaN into ``inv`` where the sine ``condition`` is below SINE_TOL (toggle, dead centre)."""
    if not condition.min() >= SINE_TOL:  # (NaN min also lands here)
        np.less(condition, SINE_TOL, out=flags)
        np.copyto(inv, np.nan, where=flags)


def products(out, tmp, first, *rest) -> None:
    """out = a0 b0 +- a1 b1 +- ..., summed left to right: ``first`` is (a0, b0), each of ``rest`` is
    (sign, a, b); tmp is scratch."""
    np.multiply(*first, out=out)
    for sign, a, b in rest:
        np.multiply(a, b, out=tmp)
        if sign > 0:
            out += tmp
        else:
            out -= tmp
