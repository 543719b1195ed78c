"""The (offset) slider-crank's closed form as the sweep runs it: the oracle's formulas
(:func:`constructions.analytic.slider_crank`, where they are derived) in chunks, with ``out=`` ufuncs and
the sweep's own trigonometry."""

from __future__ import annotations

import numpy as np

from ..analytic.inputs import angles, slider_crank_links
from ..analytic.states import SLIDER_FIELDS, SliderCrankState
from ..sweep_threads import in_pieces
from . import shared_steps
from .shared_steps import (chunk_of, chunks, crank_motion, nan_at_gaps, nan_where_singular, outputs, products,
                           three_way)
from .trig import atan2

__all__ = ["slider_crank"]


def slider_crank(theta1, omega1, alpha1=0.0, *, crank_pivot, crank, coupler, guide_point, guide_angle,
                 branch, threads=None) -> SliderCrankState:
    """:func:`constructions.analytic.slider_crank` (the same arguments and result, to about 1e-15
    relative), fast over many crank angles; ``threads`` as for :func:`~.four_bar_kernel.four_bar`."""
    k = slider_crank_links(crank_pivot, crank, coupler, guide_point, guide_angle, branch)
    th, w1, a1, shape = angles(theta1, omega1, alpha1)
    n = th.size
    l, tol, ex, ey, nx, ny, y0 = k.l, k.tol, k.ex, k.ey, k.nx, k.ny, k.y0
    inv_l = 1.0 / l
    res = outputs(SLIDER_FIELDS, n)
    asm_all = np.empty(n, dtype=bool)

    def solve(start, stop):  # angles [start, stop) in chunks, on scratch of this piece's own
        with np.errstate(all="ignore"):  # NaN/inf handled explicitly below (the state is per thread)
            for i, j, scratch, bt in chunks(start, stop, 9):
                c, s, y, h, tmp, px, py, inv, e5 = scratch
                (Bx, By, Cx, Cy, t2, om2, VBx, VBy, VCx, VCy, spd,
                 al2, ABx, ABy, ACx, ACy, acc, cond) = (res[name][i:j] for name in SLIDER_FIELDS)
                asm = asm_all[i:j]
                crank_motion(th[i:j], k.r1, k.o1x, k.o1y, chunk_of(w1, i, j), chunk_of(a1, i, j), c, s, px, py,
                             Bx, By, VBx, VBy, ABx, ABy)
                # y = y0 + crank (s ex - c ey)   (signed distance of B from the guide)
                products(y, tmp, (s, ex * k.r1), (-1, c, ey * k.r1))
                y += y0
                # half-chord h = sqrt((l - y)(l + y))
                np.subtract(l, y, out=h)
                np.add(y, l, out=tmp)
                three_way(h, tmp, tol, asm, bt)
                h *= tmp
                np.sqrt(h, out=h)
                nan_at_gaps(asm, tmp, (h, Bx, By, VBx, VBy, ABx, ABy))
                np.multiply(h, inv_l, out=cond)
                # p = C - B = -y n + branch h e
                if k.branch < 0:
                    np.negative(h, out=h)  # h now holds branch*h
                products(px, tmp, (y, -nx), (1, h, ex))
                products(py, tmp, (y, -ny), (1, h, ey))
                np.add(Bx, px, out=Cx)
                np.add(By, py, out=Cy)
                atan2(py, px, t2, c, s, tmp, inv, e5, bt)
                # omega2 = -(V_B . n) / (branch h)
                np.divide(-1.0, h, out=inv)
                nan_where_singular(inv, cond, bt)
                products(om2, tmp, (VBx, nx), (1, VBy, ny))
                om2 *= inv
                # slider_speed = V_B . e + omega2 y;  V_C = slider_speed e
                products(spd, tmp, (VBx, ex), (1, VBy, ey), (1, om2, y))
                np.multiply(spd, ex, out=VCx)
                np.multiply(spd, ey, out=VCy)
                # accelerations, c = omega2^2 (c, s are free after the crank tip):
                # alpha2 = -(A_B . n + omega2^2 y) / (branch h)
                np.multiply(om2, om2, out=c)
                products(al2, tmp, (ABx, nx), (1, ABy, ny), (1, c, y))
                al2 *= inv
                # sddot = A_B . e - omega2^2 (branch h) + alpha2 y;  A_C = sddot e
                products(acc, tmp, (ABx, ex), (1, ABy, ey), (-1, c, h), (1, al2, y))
                np.multiply(acc, ex, out=ACx)
                np.multiply(acc, ey, out=ACy)

    in_pieces(solve, n, threads, shared_steps.CHUNK)

    return SliderCrankState(assembles=asm_all.reshape(shape),
                            **{name: res[name].reshape(shape) for name in SLIDER_FIELDS})
