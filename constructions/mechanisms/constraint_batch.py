"""The constraint equations of :mod:`.constraint_equations` over a stack of poses: Phi, the scaled
Jacobian and gamma for N crank angles at once, the batched Newton-Raphson that closes them from a
prediction, and the points' positions, velocities and accelerations at every pose.

The same equations, term for term, as the one-pose functions (whose module docstring derives them); a
pose is a row of an (N, k) array of body coordinates q, and the linear systems are (N, k, k) stacks
solved by one call of :func:`numpy.linalg.solve` or :func:`numpy.linalg.inv`.  Results agree with the
one-pose solution to rounding: the same residual tolerance, the same polishing step.
"""

from __future__ import annotations

import math

import numpy as np

from .constraint_equations import scales
from .constraint_model import FRAME, Model

__all__ = ["Closed", "close", "motion", "points"]

TWO_PI = 2 * math.pi


def _wrap(a: np.ndarray) -> np.ndarray:
    """``math.remainder(a, 2 pi)`` element by element: into [-pi, pi]."""
    return a - TWO_PI * np.rint(a / TWO_PI)


def _frames(Q: np.ndarray) -> list[tuple]:
    """(x, y, cos phi, sin phi) of every body at every pose, computed once for all the equations."""
    phi = Q[:, 2::3]
    c, sn = np.cos(phi), np.sin(phi)
    return [(Q[:, 3 * i], Q[:, 3 * i + 1], c[:, i], sn[:, i]) for i in range(phi.shape[1])]


def _arm(F: list[tuple], body: int, s) -> tuple:
    """(x, y, w x, w y) of the point with body-frame coordinates s, at every pose (a frame point: scalars)."""
    if body == FRAME:
        return s[0], s[1], 0.0, 0.0
    x, y, c, sn = F[body]
    wx, wy = c * s[0] - sn * s[1], sn * s[0] + c * s[1]
    return x + wx, y + wy, wx, wy


def _revolute_arms(model: Model, F: list[tuple]):
    """(first row, sign, body, w x, w y) of each moving body's point in each revolute joint's two rows:
    the point of ``a`` with sign +1, that of ``b`` with -1."""
    for i, c in enumerate(model.revolutes):
        for sign, (body, s) in ((1.0, c.a), (-1.0, c.b)):
            if body != FRAME:
                _, _, wx, wy = _arm(F, body, s)
                yield 2 * i, sign, body, wx, wy


def _line(Q: np.ndarray, c) -> tuple:
    """(origin x, y, direction d x, d y) of the line of ``c`` at every pose."""
    if c.slot is None:
        return c.through[0], c.through[1], math.cos(c.angle), math.sin(c.angle)
    phi = Q[:, 3 * c.slot + 2] + c.angle
    return Q[:, 3 * c.slot], Q[:, 3 * c.slot + 1], np.cos(phi), np.sin(phi)


def residual(model: Model, Q: np.ndarray, th: np.ndarray, F: list[tuple] | None = None) -> np.ndarray:
    """Phi at every pose, (N, k), in the rows' order of :meth:`Model.rows` (F: the poses' frames, if known)."""
    F = _frames(Q) if F is None else F
    out = np.empty((Q.shape[0], model.equations))
    row = 0
    for c in model.revolutes:
        ax, ay, _, _ = _arm(F, *c.a)
        bx, by, _, _ = _arm(F, *c.b)
        out[:, row], out[:, row + 1] = ax - bx, ay - by
        row += 2
    for c in model.lines:
        px, py, _, _ = _arm(F, c.body, c.s)
        ox, oy, dx, dy = _line(Q, c)
        out[:, row] = -dy * (px - ox) + dx * (py - oy) + c.offset
        row += 1
    for c in model.angles:
        other = Q[:, 3 * c.other + 2] if c.other is not None else 0.0
        out[:, row] = _wrap(Q[:, 3 * c.body + 2] - other - c.angle)
        row += 1
    out[:, row] = _wrap(Q[:, 3 * model.crank + 2] - th - model.crank_offset)
    return out


def scaled_jacobian(model: Model, Q: np.ndarray, rows: np.ndarray, cols: np.ndarray,
                    F: list[tuple] | None = None) -> np.ndarray:
    """R Phi_q C at every pose, (N, k, k): the Jacobian scaled by :func:`.constraint_equations.scales`,
    each entry scaled as it is written."""
    F = _frames(Q) if F is None else F
    J = np.zeros((Q.shape[0], model.equations, model.unknowns))

    def add(r: int, c: int, v) -> None:
        J[:, r, c] += v * (rows[r] * cols[c])

    for row, sign, body, wx, wy in _revolute_arms(model, F):
        col = 3 * body
        add(row, col, sign)
        add(row + 1, col + 1, sign)
        add(row, col + 2, -sign * wy)
        add(row + 1, col + 2, sign * wx)
    row = 2 * len(model.revolutes)
    for c in model.lines:
        px, py, wx, wy = _arm(F, c.body, c.s)
        ox, oy, dx, dy = _line(Q, c)
        nx, ny = -dy, dx
        col = 3 * c.body
        add(row, col, nx)
        add(row, col + 1, ny)
        add(row, col + 2, wx * ny - wy * nx)
        if c.slot is not None:
            col = 3 * c.slot
            add(row, col, -nx)
            add(row, col + 1, -ny)
            add(row, col + 2, -(dx * (px - ox) + dy * (py - oy)))
        row += 1
    for c in model.angles:
        add(row, 3 * c.body + 2, 1.0)
        if c.other is not None:
            add(row, 3 * c.other + 2, -1.0)
        row += 1
    add(row, 3 * model.crank + 2, 1.0)
    return J


def _rates(Qd: np.ndarray, body: int) -> tuple:
    if body == FRAME:
        return 0.0, 0.0, 0.0
    return Qd[:, 3 * body], Qd[:, 3 * body + 1], Qd[:, 3 * body + 2]


def gamma(model: Model, Q: np.ndarray, Qd: np.ndarray) -> np.ndarray:
    """The right-hand side of Phi_q q'' = gamma at every pose, without the crank's angular acceleration
    (the driver's row is 0: add alpha there)."""
    F = _frames(Q)
    out = np.zeros((Q.shape[0], model.equations))
    for row, sign, body, wx, wy in _revolute_arms(model, F):
        w2 = Qd[:, 3 * body + 2] ** 2
        out[:, row] += sign * w2 * wx
        out[:, row + 1] += sign * w2 * wy
    row = 2 * len(model.revolutes)
    for c in model.lines:
        px, py, wx, wy = _arm(F, c.body, c.s)
        ox, oy, dx, dy = _line(Q, c)
        nx, ny = -dy, dx
        vx, vy, wi = _rates(Qd, c.body)
        g = wi * wi * (nx * wx + ny * wy)
        if c.slot is not None:
            gvx, gvy, wg = _rates(Qd, c.slot)
            rx, ry = px - ox, py - oy
            rdx, rdy = vx - wi * wy - gvx, vy + wi * wx - gvy
            g = g + wg * wg * (nx * rx + ny * ry) + 2 * wg * (dx * rdx + dy * rdy)
        out[:, row] = g
        row += 1
    return out


# -- Newton-Raphson over the stack ---------------------------------------------------------------------

class Closed:
    """The poses :func:`close` found: coordinates ``q``, their first and second derivatives with respect
    to the crank angle ``q_theta``, ``q_theta2`` (the velocities are omega q_theta, the accelerations
    omega^2 q_theta2 + alpha q_theta), the 1-norm condition number ``kappa1`` of each scaled Jacobian, how
    far each pose moved from its prediction ``moved`` (scaled, max norm), and ``closed``: where the
    equations closed to ``tolerance``."""

    __slots__ = ("q", "q_theta", "q_theta2", "kappa1", "moved", "closed")

    def __init__(self, q, q_theta, q_theta2, kappa1, moved, closed) -> None:
        self.q, self.q_theta, self.q_theta2 = q, q_theta, q_theta2
        self.kappa1, self.moved, self.closed = kappa1, moved, closed


def _size(rows: np.ndarray, r: np.ndarray) -> np.ndarray:
    s = np.max(np.abs(rows * r), axis=1)
    s[~np.isfinite(s)] = np.inf
    return s


def close(model: Model, Q0: np.ndarray, th: np.ndarray, tolerance: float, steps: int) -> Closed | None:
    """Newton-Raphson from the predicted coordinates ``Q0`` (N, k) at crank angles ``th`` (N,): full steps
    (a prediction is close; no line search) until every scaled residual is below ``tolerance`` or
    ``steps`` are spent, then one polishing step kept where it does not make the residual worse -- as the
    one-pose solver does.  None when a Jacobian of the stack is exactly singular."""
    rows, cols = scales(model)
    Q = np.array(Q0, dtype=np.float64)
    r = residual(model, Q, th)
    res = _size(rows, r)
    with np.errstate(all="ignore"):
        try:
            for _ in range(steps):
                act = np.flatnonzero(np.isfinite(res) & (res > tolerance))
                if act.size == 0:
                    break
                Qa = Q[act]
                A = scaled_jacobian(model, Qa, rows, cols)
                Qa -= cols * np.linalg.solve(A, (rows * r[act])[:, :, None])[:, :, 0]
                Q[act] = Qa
                r[act] = residual(model, Qa, th[act])
                res[act] = _size(rows, r[act])
            F = _frames(Q)
            A = scaled_jacobian(model, Q, rows, cols, F)
            Ainv = np.linalg.inv(A)
        except np.linalg.LinAlgError:
            return None
        closed = res <= tolerance
        Qp = Q - cols * np.einsum("nij,nj->ni", Ainv, rows * r)
        keep = closed & (_size(rows, residual(model, Qp, th)) <= res)
        Q[keep] = Qp[keep]
        kappa1 = np.max(np.sum(np.abs(A), axis=1), axis=1) * np.max(np.sum(np.abs(Ainv), axis=1), axis=1)
        q_theta = cols * (Ainv[:, :, -1] * rows[-1])             # Phi_q q' = (0, .., 0, 1): the driver
        q_theta2 = cols * np.einsum("nij,nj->ni", Ainv, rows * gamma(model, Q, q_theta))
        moved = np.max(np.abs((Q - Q0) / cols), axis=1)
    ok = closed & np.isfinite(kappa1) & np.all(np.isfinite(q_theta2), axis=1) & np.all(np.isfinite(Q), axis=1)
    return Closed(Q, q_theta, q_theta2, kappa1, moved, ok)


# -- the points ----------------------------------------------------------------------------------------

def points(model: Model, Q: np.ndarray, Qd: np.ndarray, Qdd: np.ndarray) -> tuple[dict, dict, dict]:
    """(positions, velocities, accelerations): name -> (x, y) arrays of every point the one-pose solver
    places (the frame's, every body's, every coincident point), in its order."""
    pos: dict = {}
    vel: dict = {}
    acc: dict = {}

    def motion_of(body: int, wx, wy):
        vx, vy, w = _rates(Qd, body)
        ax, ay, a = _rates(Qdd, body)
        return (vx - w * wy, vy + w * wx), (ax - a * wy - w * w * wx, ay + a * wx - w * w * wy)

    n, F = Q.shape[0], _frames(Q)
    for name, cs in model.carriers.items():
        body, s = cs[0]
        if body == FRAME:
            pos[name] = (np.full(n, s[0]), np.full(n, s[1]))
            vel[name] = acc[name] = (np.zeros(n), np.zeros(n))
            continue
        x, y, wx, wy = _arm(F, body, s)
        pos[name] = (x, y)
        vel[name], acc[name] = motion_of(body, wx, wy)
    for name, (joint, g) in model.coincident.items():
        px, py = pos[joint]
        pos[name] = (px, py)
        # J's arm in G: the world arm p - r_g (no need to turn it into G's frame and back)
        vel[name], acc[name] = motion_of(g, px - Q[:, 3 * g], py - Q[:, 3 * g + 1])
    return pos, vel, acc


def motion(c: Closed, omega: float, alpha: float) -> tuple[np.ndarray, np.ndarray]:
    """(q', q'') in time of the closed poses for the crank's omega and alpha."""
    return omega * c.q_theta, omega * omega * c.q_theta2 + alpha * c.q_theta
