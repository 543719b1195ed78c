"""A point fixed to a link as the sweep runs it: the oracle's rigid-body formulas
(:func:`constructions.analytic.coupler_point`) in chunks, with the sweep's own trigonometry."""

from __future__ import annotations

import numpy as np

from ..analytic.inputs import point_on_link
from ..analytic.states import PointState
from ..sweep_threads import in_pieces
from . import shared_steps
from .shared_steps import chunks
from .trig import sincos

__all__ = ["coupler_point"]


def coupler_point(Bx, By, VBx, VBy, theta2, omega2, *, distance, angle, ABx=None, ABy=None,
                  alpha2=None, threads=None) -> PointState:
    """:func:`constructions.analytic.coupler_point` (the same arguments and result, to about 1e-15
    relative), fast over many angles; ``threads`` as for :func:`~.four_bar_kernel.four_bar`."""
    dist, ang, accel = point_on_link(distance, angle, ABx, ABy, alpha2)
    inputs = [Bx, By, VBx, VBy, theta2, omega2] + ([ABx, ABy, alpha2] if accel else [])
    arrs = np.broadcast_arrays(*(np.asarray(v, dtype=np.float64) for v in inputs))
    shape = arrs[0].shape
    flat = [np.ascontiguousarray(v).reshape(-1) for v in arrs]
    bx, by, vbx, vby, t2, w2 = flat[:6]
    n = bx.size
    Dx, Dy, VDx, VDy = (np.empty(n) for _ in range(4))
    if accel:
        abx, aby, a2 = flat[6:]
        ADx, ADy = np.empty(n), np.empty(n)
    else:
        ADx, ADy = np.full(n, np.nan), np.full(n, np.nan)
    def solve(start, stop):  # angles [start, stop) in chunks, on scratch of this piece's own
        with np.errstate(all="ignore"):
            for i, j, (c, s, t, u), _ in chunks(start, stop, 4):
                np.add(t2[i:j], ang, out=t)
                sincos(t, c, s, u, Dx[i:j])  # u and the Dx slice are scratch here
                # r = D - B = distance (c, s);  V_D = V_B + omega2 (-r_y, r_x)
                c *= dist
                s *= dist
                np.add(bx[i:j], c, out=Dx[i:j])
                np.add(by[i:j], s, out=Dy[i:j])
                np.multiply(w2[i:j], s, out=VDx[i:j])
                np.subtract(vbx[i:j], VDx[i:j], out=VDx[i:j])
                np.multiply(w2[i:j], c, out=VDy[i:j])
                VDy[i:j] += vby[i:j]
                if accel:
                    # A_D = A_B + alpha2 (-r_y, r_x) - omega2^2 (r_x, r_y)
                    np.multiply(w2[i:j], w2[i:j], out=t)  # omega2^2
                    np.multiply(a2[i:j], s, out=u)
                    np.subtract(abx[i:j], u, out=ADx[i:j])
                    np.multiply(t, c, out=u)
                    ADx[i:j] -= u
                    np.multiply(a2[i:j], c, out=u)
                    np.add(aby[i:j], u, out=ADy[i:j])
                    np.multiply(t, s, out=u)
                    ADy[i:j] -= u

    in_pieces(solve, n, threads, shared_steps.CHUNK)
    return PointState(Dx=Dx.reshape(shape), Dy=Dy.reshape(shape), VDx=VDx.reshape(shape), VDy=VDy.reshape(shape),
                      ADx=ADx.reshape(shape), ADy=ADy.reshape(shape))
