"""The four-bar's closed form as the sweep runs it: the oracle's formulas
(:func:`constructions.analytic.four_bar`, where they are derived) in chunks, with ``out=`` ufuncs, the
sweep's own trigonometry and, if the caller keeps them, the caller's output buffers."""

from __future__ import annotations

import numpy as np

from ..analytic.inputs import angles, four_bar_links
from ..analytic.states import FOURBAR_FIELDS, FourBarState
from .shared_steps import (chunk_of, chunks, crank_motion, given_outputs, nan_at_gaps, nan_where_singular, products,
                           three_way)
from .trig import atan2

__all__ = ["four_bar"]


def four_bar(theta1, omega1, alpha1=0.0, *, crank_pivot, rocker_pivot, crank, coupler, rocker, branch,
             out=None) -> FourBarState:
    """:func:`constructions.analytic.four_bar` (the same arguments and result, to about 1e-15 relative),
    fast over many crank angles.

    out : (ndarray, ndarray), optional
        The caller's output buffers, reused from call to call: a C-contiguous float64 array of shape
        ``(len(FOURBAR_FIELDS), n)`` (a row per field, in the order of
        :data:`~constructions.analytic.states.FOURBAR_FIELDS`) and a bool array of ``n`` for
        ``assembles``; the result's arrays are views of them.  A long sweep repeated into the same
        buffers pays no page faults for fresh memory (see :func:`~.shared_steps.four_bar_buffers`).
    """
    k = four_bar_links(crank_pivot, rocker_pivot, crank, coupler, rocker, branch)
    th, w1, a1, shape = angles(theta1, omega1, alpha1)
    n = th.size
    S, T, K, tol = k.S, k.T, k.K, k.tol
    inv_2r2r3, half_sumsq = k.inv_2r2r3, k.half_sumsq
    r2sq, r3sq = k.r2 * k.r2, k.r3 * k.r3
    res, asm_all = given_outputs(out, FOURBAR_FIELDS, n)

    with np.errstate(all="ignore"):  # NaN/inf handled explicitly below
        for i, j, scratch, bt in chunks(n, 12):
            c, s, wx, wy, d2, d, f1, f2, tmp, inv, al, be = scratch
            (Bx, By, Cx, Cy, t2, t3, om2, om3, VBx, VBy, VCx, VCy,
             al2, al3, ABx, ABy, ACx, ACy, cond) = (res[name][i:j] for name in FOURBAR_FIELDS)
            asm = asm_all[i:j]
            crank_motion(th[i:j], k.r1, k.o1x, k.o1y, chunk_of(w1, i, j), chunk_of(a1, i, j), c, s, wx, wy,
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
            products(f2, tmp, (al, wx), (-1, be, wy))  # f2 = px
            products(d, tmp, (al, wy), (1, be, wx))  # d = py (d no longer needed)
            np.add(Bx, f2, out=Cx)
            np.add(By, d, out=Cy)
            atan2(d, f2, t2, c, s, tmp, inv, al, bt)
            # q = C - O2 = p - w  (into wx, wy)
            np.subtract(f2, wx, out=wx)
            np.subtract(d, wy, out=wy)
            atan2(wy, wx, t3, c, s, tmp, inv, al, bt)
            # -1 / cross(p, q) = -2 branch / sqrt(P), NaN where the sine is below SINE_TOL
            np.divide(-2.0 * k.branch, f1, out=inv)
            nan_where_singular(inv, cond, bt)
            # omega2 = -(V_B . q)/cross(p,q);  omega3 = -(V_B . p)/cross(p,q)
            products(om2, tmp, (VBx, wx), (1, VBy, wy))
            om2 *= inv
            products(om3, tmp, (VBx, f2), (1, VBy, d))
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
            products(al3, tmp, (ABx, f2), (1, ABy, d), (-1, al, r2sq), (1, be, c))
            al3 *= inv
            # A_C = alpha3 k x q - omega3^2 q = (-alpha3 q_y - omega3^2 q_x, alpha3 q_x - omega3^2 q_y)
            products(ACx, tmp, (al3, wy), (1, be, wx))
            np.negative(ACx, out=ACx)
            products(ACy, tmp, (al3, wx), (-1, be, wy))

    return FourBarState(assembles=asm_all.reshape(shape), **{name: res[name].reshape(shape) for name in FOURBAR_FIELDS})
