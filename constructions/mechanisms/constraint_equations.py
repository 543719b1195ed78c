"""The constraint equations of a :class:`.constraint_model.Model`: Phi, its Jacobian Phi_q and gamma, the
scaled linear solve, and the coordinates of a guessed position.

Constraints Phi(q, t) = 0
-------------------------
Write w = R(phi_i) s for the arm of a point of body i (world frame), k x (x, y) = (-y, x), and note
d/dphi R(phi) s = k x w and d/dt (k x w) = -phi' w.  For each kind of joint, Phi, its Jacobian row(s)
Phi_q, and gamma = -(Phi_q q')_q q' - 2 Phi_qt q' - Phi_tt (the part of d^2 Phi / dt^2 that does not
contain q''), derived by hand:

* Revolute joint (every point named by several bodies coincides; the frame's points are fixed):
  Phi = (r_i + w_i) - (r_j + w_j), 2 rows.  Phi_q: [I, k x w_i] on body i, [-I, -k x w_j] on body j.
  d^2/dt^2 (r + w) = r'' + phi'' k x w - phi'^2 w, so gamma = phi_i'^2 w_i - phi_j'^2 w_j (a frame
  point contributes nothing).
* A point P = r_i + w_i on a line (a block's pin on its guide or slot, or a pin in a slot: a higher
  pair).  A slot of link g follows :meth:`Slide.slot_line`: direction d = u(phi_g + angle), through
  r_g - offset k x d, so with n = k x d and r = P - r_g:  Phi = n . r + offset  (1 row).  A fixed
  guide is the same with r_g := ``through``, phi_g := 0 fixed and offset 0.
  n' = -phi_g' d and d' = phi_g' n, so n'' = -phi_g'' d - phi_g'^2 n, and
  Phi'' = n''.r + 2 n'.r' + n.r''
        = -phi_g'' d.r - phi_g'^2 n.r - 2 phi_g' d.r' + n.(r_i'' + phi_i'' k x w_i - phi_i'^2 w_i - r_g'').
  Phi_q: n on (x_i, y_i), n.(k x w_i) = cross(w_i, n) on phi_i, -n on (x_g, y_g), -d.r on phi_g;
  gamma = phi_g'^2 n.r + 2 phi_g' d.r' + phi_i'^2 n.w_i with r' = V_P - V_{r_g} (the rotating line's
  terms are the first two; a fixed guide keeps only the last).
* A block's angle: phi_b - phi_g - angle = 0 on a slot (it turns with the slotted link),
  phi_b - angle = 0 on a fixed guide.  Phi_q: +1 on phi_b, -1 on phi_g; gamma = 0.
* The driver: phi_c - theta(t) - c0 = 0 (c0 = 0 when the crank's pivot is its first base joint, pi
  when it is the second: theta is the direction pivot -> tip).  Phi_t = -omega, Phi_tt = -alpha, no
  Phi_qt: the velocity right-hand side -Phi_t is omega and gamma = alpha.

Angle residuals are wrapped into (-pi, pi], so a guess a turn away needs no care.  The mechanism is
1-DoF when there are exactly as many equations (driver included) as coordinates; otherwise the count
is an error that says so.

"""

from __future__ import annotations

import math
from typing import Mapping

import numpy as np

from ..errors import DegenerateInput
from .constraint_model import FRAME, Model, OnLine
from .model import Mechanism


def wrap(a: float) -> float:
    return math.remainder(a, 2 * math.pi)


def arm(q, body: int, s: tuple[float, float]) -> tuple[float, float, float, float]:
    """(world point x, y, arm w x, w y) of the point with body-frame coordinates s."""
    if body == FRAME:
        return s[0], s[1], 0.0, 0.0
    x, y, phi = q[3 * body:3 * body + 3]
    c, sn = math.cos(phi), math.sin(phi)
    wx, wy = c * s[0] - sn * s[1], sn * s[0] + c * s[1]
    return x + wx, y + wy, wx, wy


def line_frame(model: Model, q: np.ndarray, c: OnLine) -> tuple[float, float, float, float, float]:
    """(origin x, y, direction d x, d y, phi_g) of the line ``c`` at q."""
    if c.slot is None:
        return c.through[0], c.through[1], math.cos(c.angle), math.sin(c.angle), 0.0
    x, y, phi = q[3 * c.slot:3 * c.slot + 3]
    return x, y, math.cos(phi + c.angle), math.sin(phi + c.angle), phi


def residual(model: Model, q: np.ndarray, theta: float) -> np.ndarray:
    out: list[float] = []
    for c in model.revolutes:
        ax, ay, _, _ = arm(q, *c.a)
        bx, by, _, _ = arm(q, *c.b)
        out += [ax - bx, ay - by]
    for c in model.lines:
        px, py, _, _ = arm(q, c.body, c.s)
        ox, oy, dx, dy, _ = line_frame(model, q, c)
        out.append(-dy * (px - ox) + dx * (py - oy) + c.offset)          # n = k x d = (-d_y, d_x)
    for c in model.angles:
        other = q[3 * c.other + 2] if c.other is not None else 0.0
        out.append(wrap(q[3 * c.body + 2] - other - c.angle))
    out.append(wrap(q[3 * model.crank + 2] - theta - model.crank_offset))
    return np.array(out)


def jacobian(model: Model, q: np.ndarray) -> np.ndarray:
    J = np.zeros((model.equations, model.unknowns))
    row = 0
    for c in model.revolutes:
        for sign, (body, s) in ((1.0, c.a), (-1.0, c.b)):
            if body == FRAME:
                continue
            _, _, wx, wy = arm(q, body, s)
            col = 3 * body
            J[row, col] += sign
            J[row + 1, col + 1] += sign
            J[row, col + 2] += -sign * wy                # k x w = (-w_y, w_x)
            J[row + 1, col + 2] += sign * wx
        row += 2
    for c in model.lines:
        px, py, wx, wy = arm(q, c.body, c.s)
        ox, oy, dx, dy, _ = line_frame(model, q, c)
        nx, ny = -dy, dx
        col = 3 * c.body
        J[row, col] += nx
        J[row, col + 1] += ny
        J[row, col + 2] += wx * ny - wy * nx             # n . (k x w) = cross(w, n)
        if c.slot is not None:
            col = 3 * c.slot
            J[row, col] -= nx
            J[row, col + 1] -= ny
            J[row, col + 2] -= dx * (px - ox) + dy * (py - oy)    # dn/dphi_g = -d:  -d . r
        row += 1
    for c in model.angles:
        J[row, 3 * c.body + 2] += 1.0
        if c.other is not None:
            J[row, 3 * c.other + 2] -= 1.0
        row += 1
    J[row, 3 * model.crank + 2] = 1.0
    return J


def _body_rates(qd: np.ndarray, body: int) -> tuple[float, float, float]:
    if body == FRAME:
        return 0.0, 0.0, 0.0
    return qd[3 * body], qd[3 * body + 1], qd[3 * body + 2]


def gamma(model: Model, q: np.ndarray, qd: np.ndarray, alpha: float) -> np.ndarray:
    """The right-hand side of Phi_q q'' = gamma (derivations in the module docstring)."""
    out: list[float] = []
    for c in model.revolutes:
        gx = gy = 0.0
        for sign, (body, s) in ((1.0, c.a), (-1.0, c.b)):
            if body == FRAME:
                continue
            _, _, wx, wy = arm(q, body, s)
            w2 = qd[3 * body + 2] ** 2
            gx += sign * w2 * wx                         # gamma = phi_i'^2 w_i - phi_j'^2 w_j
            gy += sign * w2 * wy
        out += [gx, gy]
    for c in model.lines:
        px, py, wx, wy = arm(q, c.body, c.s)
        ox, oy, dx, dy, _ = line_frame(model, q, c)
        nx, ny = -dy, dx
        vx, vy, wi = _body_rates(qd, c.body)
        g = wi * wi * (nx * wx + ny * wy)                # phi_i'^2 n . w_i
        if c.slot is not None:
            gvx, gvy, wg = _body_rates(qd, c.slot)
            rx, ry = px - ox, py - oy
            rdx, rdy = vx - wi * wy - gvx, vy + wi * wx - gvy      # r' = V_P - V_{r_g}
            g += wg * wg * (nx * rx + ny * ry) + 2 * wg * (dx * rdx + dy * rdy)
        out.append(g)
    out += [0.0] * len(model.angles)
    out.append(alpha)
    return np.array(out)


# -- scaled linear algebra -------------------------------------------------------------------------

def scales(model: Model) -> tuple[np.ndarray, np.ndarray]:
    """(row scale R, column scale C): the scaled Jacobian is R J C, with q = C z."""
    L = model.scale
    cols = np.empty(model.unknowns)
    for i, b in enumerate(model.bodies):
        cols[3 * i:3 * i + 3] = (L, L, L / b.size)
    rows = np.array([r for _, r in model.rows()])
    return rows, cols


def solve_scaled(model: Model, J: np.ndarray, rhs: np.ndarray, rows: np.ndarray, cols: np.ndarray) -> np.ndarray:
    A = rows[:, None] * J * cols[None, :]
    try:
        z = np.linalg.solve(A, rows * rhs)
    except np.linalg.LinAlgError:
        z = np.linalg.lstsq(A, rows * rhs, rcond=None)[0]
    return cols * z


# -- the guess -------------------------------------------------------------------------------------

def _xy(v) -> tuple[float, float]:
    if hasattr(v, "x") and hasattr(v, "y"):
        return float(v.x), float(v.y)
    x, y = v
    return float(x), float(y)


def initial_coordinates(model: Model, m: Mechanism, guess: Mapping[str, object]) -> np.ndarray:
    known = set(model.carriers) | set(model.coincident)
    for n in guess:
        if n not in known:
            raise DegenerateInput(f"the guess places {n!r}, which is no point of the mechanism")
    g = {n: _xy(v) for n, v in guess.items()}
    for n, p in m.ground.items():
        g.setdefault(n, (p.x, p.y))
    q = np.zeros(model.unknowns)
    for i, b in enumerate(model.bodies):
        if b.kind == "link":
            have = [n for n in b.local if n in g]
            if len(have) < 2:
                raise DegenerateInput(f"the guess must place at least two points of link {b.number} "
                                      f"({', '.join(b.local)})")
            # the two given points farthest apart in the body fix its pose best
            a, c = max(((a, c) for a in have for c in have if a < c),
                       key=lambda ac: math.dist(b.local[ac[0]], b.local[ac[1]]))
            la, lc = b.local[a], b.local[c]
            if math.dist(la, lc) == 0.0:
                raise DegenerateInput(f"points {a} and {c} of link {b.number} coincide in the link")
            phi = (math.atan2(g[c][1] - g[a][1], g[c][0] - g[a][0]) - math.atan2(lc[1] - la[1], lc[0] - la[0]))
            cs, sn = math.cos(phi), math.sin(phi)
            q[3 * i:3 * i + 3] = (g[a][0] - (cs * la[0] - sn * la[1]), g[a][1] - (sn * la[0] + cs * la[1]), phi)
    for i, b in enumerate(model.bodies):
        if b.kind == "block":
            (joint,) = b.local
            if joint not in g:
                raise DegenerateInput(f"the guess must place the pin {joint} of block {b.number}")
            line = next(c for c in model.lines if c.joint == joint)
            phi = line.angle + (q[3 * line.slot + 2] if line.slot is not None else 0.0)
            q[3 * i:3 * i + 3] = (*g[joint], phi)
    q[3 * model.crank + 2] = wrap(q[3 * model.crank + 2])
    return q

