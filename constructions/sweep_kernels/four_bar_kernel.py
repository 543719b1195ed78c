"""The four-bar's closed form as the sweep runs it: the oracle's formulas
(:func:`constructions.analytic.four_bar`, where they are derived) in chunks, with ``out=`` ufuncs, the
sweep's own trigonometry and, if the caller keeps them, the caller's output buffers."""

from __future__ import annotations

import threading

import numpy as np

from ..analytic.inputs import angles, four_bar_links
from ..analytic.states import FOURBAR_FIELDS, FourBarState
from ..sweep_threads import in_pieces
from . import shared_steps
from .shared_steps import (chunk_of, crank_motion, given_block, nan_at_gaps, nan_where_singular, products,
                           three_way)
from .trig import atan2_into

__all__ = ["four_bar"]

_THETA = slice(FOURBAR_FIELDS.index("theta2"), FOURBAR_FIELDS.index("theta2") + 2)
assert FOURBAR_FIELDS[_THETA] == ("theta2", "theta3")

_held = threading.local()


def _chunks(start: int, stop: int):
    """Yield ``(i, j, scratch, flags, XY, M)`` for each chunk [i, j) of the angles [start, stop) (chunks of
    :data:`~.shared_steps.CHUNK`): twelve float scratch rows (a ``(12, m)`` array, so that neighbouring
    rows make the contiguous ``(2, m)`` scratch of the one atan2 call over both links), a bool row, p and q
    as ``(2, 2, m)`` and a ``(2, 2, m)`` bool.  The arrays are this thread's, kept from call to call for
    the last chunk length asked for; the last, short chunk gets views of them."""
    chunk = shared_steps.CHUNK
    m = min(chunk, max(stop - start, 1))
    held = getattr(_held, "arrays", None)
    if held is None or held[0].shape[1] != m:
        held = _held.arrays = (np.empty((12, m)), np.empty(m, dtype=bool), np.empty((2, 2, m)),
                               np.empty((2, 2, m), dtype=bool))
    sc, flags, XY, M = held
    for i in range(start, stop, chunk):
        j = min(i + chunk, stop)
        if j - i != m:
            m = j - i
            sc, flags, XY, M = sc[:, :m], flags[:m], XY[..., :m], M[..., :m]
        yield i, j, sc, flags, XY, M


def four_bar(theta1, omega1, alpha1=0.0, *, crank_pivot, rocker_pivot, crank, coupler, rocker, branch,
             out=None, threads=None) -> FourBarState:
    """:func:`constructions.analytic.four_bar` (the same arguments and result, to about 1e-15 relative),
    fast over many crank angles.

    out : (ndarray, ndarray), optional
        The caller's output buffers, reused from call to call: a C-contiguous float64 array of shape
        ``(len(FOURBAR_FIELDS), n)`` (a row per field, in the order of
        :data:`~constructions.analytic.states.FOURBAR_FIELDS`) and a bool array of ``n`` for
        ``assembles``; the result's arrays are views of them.  A long sweep repeated into the same
        buffers pays no page faults for fresh memory (see :func:`~.shared_steps.four_bar_buffers`).
    threads : int, optional
        How many threads share the work (None: :func:`constructions.sweep_threads.default_threads`; 1:
        the calling thread only).  Calls over fewer than
        :data:`~constructions.sweep_threads.THREADED_FROM` angles run on the calling thread.  Each thread
        writes its own pieces of the output: the same numbers, bit for bit, on any number of threads.
    """
    k = four_bar_links(crank_pivot, rocker_pivot, crank, coupler, rocker, branch)
    if (type(theta1) is np.ndarray and theta1.dtype == np.float64 and theta1.ndim == 1 and theta1.flags.c_contiguous
            and type(omega1) is float and type(alpha1) is float):
        th, w1, a1, shape = theta1, omega1, alpha1, theta1.shape  # what angles() returns for these, sooner
    else:
        th, w1, a1, shape = angles(theta1, omega1, alpha1)
    n = th.size
    S, T, K, tol = k.S, k.T, k.K, k.tol
    inv_2r2r3, half_sumsq = k.inv_2r2r3, k.half_sumsq
    r2sq, r3sq = k.r2 * k.r2, k.r3 * k.r3
    block, asm_all = given_block(out, FOURBAR_FIELDS, n)
    res = {name: block[row] for row, name in enumerate(FOURBAR_FIELDS)}

    def solve(start, stop):  # angles [start, stop) in chunks, on this thread's scratch
        with np.errstate(all="ignore"):  # NaN/inf handled explicitly below (the state is per thread)
            for i, j, sc, bt, XY, M in _chunks(start, stop):
                c, s, t, u, d, f2, tmp, inv, d2, f1, al, be = sc
                # p = (px, py) and q = (qx, qy) in XY = [[px, qx], [py, qy]], so that one atan2 call over
                # [px, qx], [py, qy] gives both link angles; w = O2 - B first in the places of q
                (px, wx), (py, wy) = XY
                (Bx, By, Cx, Cy, _t2, _t3, om2, om3, VBx, VBy, VCx, VCy,
                 al2, al3, ABx, ABy, ACx, ACy, cond) = (res[name][i:j] for name in FOURBAR_FIELDS)
                asm = asm_all[i:j]
                crank_motion(th[i:j], k.r1, k.o1x, k.o1y, chunk_of(w1, i, j), chunk_of(a1, i, j), c, s, t, u,
                             Bx, By, VBx, VBy, ABx, ABy)
                # w = O2 - B, d
                np.subtract(k.o2x, Bx, out=wx)
                np.subtract(k.o2y, By, out=wy)
                products(d2, tmp, (wx, wx), (1, wy, wy))
                np.sqrt(d2, out=d)
                # gap factors (S - d) and (d - T): exact differences near tangency
                np.subtract(S, d, out=f1)
                np.subtract(d, T, out=f2)
                three_way(f1, f2, tol, asm, bt)
                if k.check_d0:
                    np.greater(d2, 0.0, out=bt)
                    asm &= bt
                np.add(d, S, out=tmp)
                f1 *= tmp
                np.add(d, T, out=tmp)
                f2 *= tmp
                f1 *= f2
                np.sqrt(f1, out=f1)  # f1 = sqrt(P) = 2 d h >= 0
                nan_at_gaps(asm, tmp, (f1, Bx, By, VBx, VBy, ABx, ABy))
                np.multiply(f1, inv_2r2r3, out=cond)
                # p = C - B = alpha w + beta (k x w)
                np.divide(0.5, d2, out=inv)
                np.add(d2, K, out=al)
                al *= inv
                np.multiply(f1, inv, out=be)
                if k.branch < 0:
                    np.negative(be, out=be)
                products(px, tmp, (al, wx), (-1, be, wy))
                products(py, tmp, (al, wy), (1, be, wx))
                np.add(Bx, px, out=Cx)
                np.add(By, py, out=Cy)
                # q = C - O2 = p - w  (into wx, wy)
                np.subtract(px, wx, out=wx)
                np.subtract(py, wy, out=wy)
                # theta2, theta3 in one call over [p, q] (scratch: the first eight rows, now free)
                atan2_into(XY[1], XY[0], block[_THETA, i:j], sc[0:2], sc[2:4], sc[4:6], sc[6:8], M[0], M[1])
                # -1 / cross(p, q) = -2 branch / sqrt(P), NaN where the sine is below SINE_TOL
                np.divide(-2.0 * k.branch, f1, out=inv)
                nan_where_singular(inv, cond, bt)
                # omega2 = -(V_B . q)/cross(p,q);  omega3 = -(V_B . p)/cross(p,q)
                products(om2, tmp, (VBx, wx), (1, VBy, wy))
                om2 *= inv
                products(om3, tmp, (VBx, px), (1, VBy, py))
                om3 *= inv
                # V_C = omega3 k x q
                np.multiply(om3, wy, out=VCx)
                np.negative(VCx, out=VCx)
                np.multiply(om3, wx, out=VCy)
                # accelerations: al = omega2^2, be = omega3^2, c = p . q
                np.multiply(om2, om2, out=al)
                np.multiply(om3, om3, out=be)
                np.multiply(d2, -0.5, out=c)
                c += half_sumsq
                # alpha2 = -(R . q)/cross(p, q),  R . q = A_B . q - omega2^2 (p . q) + omega3^2 rocker^2
                products(al2, tmp, (ABx, wx), (1, ABy, wy), (-1, al, c), (1, be, r3sq))
                al2 *= inv
                # alpha3 = -(R . p)/cross(p, q),  R . p = A_B . p - omega2^2 coupler^2 + omega3^2 (p . q)
                products(al3, tmp, (ABx, px), (1, ABy, py), (-1, al, r2sq), (1, be, c))
                al3 *= inv
                # A_C = alpha3 k x q - omega3^2 q = (-alpha3 q_y - omega3^2 q_x, alpha3 q_x - omega3^2 q_y)
                products(ACx, tmp, (al3, wy), (1, be, wx))
                np.negative(ACx, out=ACx)
                products(ACy, tmp, (al3, wx), (-1, be, wy))

    in_pieces(solve, n, threads, shared_steps.CHUNK)

    if shape == (n,):
        return FourBarState(assembles=asm_all.view(), **res)  # views: freezing them leaves the buffers writable
    return FourBarState(assembles=asm_all.reshape(shape), **{name: res[name].reshape(shape) for name in FOURBAR_FIELDS})
