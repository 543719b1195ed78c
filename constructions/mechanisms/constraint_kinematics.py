"""Kinematics of any 1-DoF mechanism by constraint equations in body coordinates (the multibody method).

The analytic check for every mechanism :class:`~constructions.linkage.Mechanism` accepts -- also those
the closed forms (:mod:`constructions.analytic`) and the dyad chains (:mod:`constructions.vector_loops`)
cannot model: a ternary link whose third point is a joint of another link, a slider block on a slot of
a moving link, a pin in a slot, and loops that must be solved as a whole (an Assur triad).  It reads
only the mechanism's data (pivots, links and :meth:`Mechanism.local`, slides, the crank) and shares no
code with the graphical construction: no assembly plan, no circle or line intersections, no polygon.

Coordinates
-----------
Every moving body has three coordinates q_k = (x_k, y_k, phi_k):

* a link: the position of its first base joint ``joints[0]`` and the angle of its base line (first
  joint to second); a point with body-frame coordinates s (from ``m.local(k)``) stands at
  r_k + R(phi_k) s;
* a slider block (a :class:`Slide` with a number): the position of its pin and its angle.

The frame is no body: its points (the fixed pivots) stand where ``m.ground`` puts them.

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

Solution
--------
* Positions by Newton-Raphson, Phi_q dq = -Phi, from the caller's guess of the point positions (e.g.
  the construction's pose, or the solution at a neighbouring crank angle): the assembly found is the
  one nearest the guess.  Converged when every scaled residual is below :data:`TOLERANCE` (lengths
  relative to the scene size L), then polished by one more step; no convergence in
  :data:`MAX_ITERATIONS` is a :class:`CannotAssemble` that names the worst constraint.
* Velocities from Phi_q q' = -Phi_t, accelerations from Phi_q q'' = gamma.
* Every linear system is solved scaled: coordinates as x/L, y/L and phi ell_k / L (ell_k the body's
  extent, so a short link in a large scene is not mistaken for a singular one), length equations
  divided by L and angle equations multiplied by ell_k / L; every entry of the scaled Jacobian is then
  of order one.  Its smallest singular value ``smallest_singular_value`` and condition number
  ``condition_number`` say how close the position is to a singular one (toggle, dead centre, lock);
  where 1 / condition_number is below :data:`SINGULAR` the velocities are indeterminate
  (:class:`IndeterminatePosition`); the positions alone are still given by :func:`solve_positions`.

Conventions: SI, angles CCW from +x, omega and alpha CCW positive, as everywhere in the engine.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from types import MappingProxyType
from typing import Mapping

import numpy as np

from ..errors import CannotAssemble, DegenerateInput, IndeterminatePosition
from ..geometry import Vec
from .model import Mechanism, coincident_name, describe_angle

__all__ = ["MAX_ITERATIONS", "SINGULAR", "TOLERANCE", "ConstraintPose", "ConstraintState", "constraint_count",
           "solve_constraints", "solve_positions"]

#: Newton-Raphson stops when every scaled residual (lengths / L, angles * ell / L) is below this.
TOLERANCE = 1e-14

#: Reciprocal condition number of the scaled Jacobian (sigma_min / sigma_max) below which the position
#: is singular and :func:`solve_constraints` raises IndeterminatePosition.  Near a fold
#: (toggle) the residual grows only with the square of the distance to the fold, so Newton-Raphson
#: cannot place a position closer than ~sqrt(residual) ~ 1e-7 L to it along the singular direction:
#: below ~1e-6 a computed position cannot be told from an exactly singular one, and the velocities,
#: whose relative error grows as ~1e-14 kappa^2 there, would carry no digit worth reporting.
SINGULAR = 1e-6

MAX_ITERATIONS = 50

_FRAME = -1
_EPS = float(np.finfo(np.float64).eps)


# -- the model: bodies, points, constraints --------------------------------------------------------

@dataclass(frozen=True, slots=True)
class _Body:
    kind: str                                   # "link" or "block"
    number: int
    local: Mapping[str, tuple[float, float]]    # body-frame coordinates of its points
    size: float                                 # ell: scales its angle coordinate

    @property
    def label(self) -> str:
        return f"{self.kind} {self.number}"


@dataclass(frozen=True, slots=True)
class _Revolute:
    point: str
    a: tuple[int, tuple[float, float]]          # (body index or _FRAME, body-frame / world coordinates)
    b: tuple[int, tuple[float, float]]


@dataclass(frozen=True, slots=True)
class _OnLine:
    joint: str
    body: int                                   # the body carrying the point
    s: tuple[float, float]
    slot: int | None                            # the slotted body, or None for a fixed guide
    angle: float
    offset: float
    through: tuple[float, float]                # fixed guide only
    what: str


@dataclass(frozen=True, slots=True)
class _Angle:
    body: int
    other: int | None
    angle: float
    what: str


@dataclass(frozen=True)
class _Model:
    bodies: tuple[_Body, ...]
    carriers: Mapping[str, tuple[tuple[int, tuple[float, float]], ...]]   # point -> bodies carrying it
    revolutes: tuple[_Revolute, ...]
    lines: tuple[_OnLine, ...]
    angles: tuple[_Angle, ...]
    crank: int                                  # body index of the crank
    crank_offset: float                         # c0: phi_crank = theta + c0
    coincident: Mapping[str, tuple[str, int]]   # coincident name -> (joint, body index of the slotted link)
    scale: float                                # L
    unknowns: int
    equations: int

    def rows(self) -> list[tuple[str, float]]:
        """(what each equation says, its row scale), in the order of :func:`_residual`."""
        out: list[tuple[str, float]] = []
        for c in self.revolutes:
            who = " and ".join("the frame" if b == _FRAME else self.bodies[b].label for b, _ in (c.a, c.b))
            out += [(f"joint {c.point} ({who}), x", 1 / self.scale), (f"joint {c.point} ({who}), y", 1 / self.scale)]
        out += [(c.what, 1 / self.scale) for c in self.lines]
        out += [(c.what, self.bodies[c.body].size / self.scale) for c in self.angles]
        out.append((f"crank angle (link {self.bodies[self.crank].number})", self.bodies[self.crank].size / self.scale))
        return out


def _count_message(unknowns: int, equations: int, bodies: int) -> str:
    f = unknowns - (equations - 1)
    return (f"the mechanism has {f} degrees of freedom: {bodies} moving bodies have {unknowns} coordinates and "
            f"their joints give {equations - 1} constraint equations; a crank drives only a mechanism with one")


def _model(m: Mechanism) -> _Model:
    numbers = [k.number for k in m.links]
    if len(set(numbers)) != len(numbers):
        raise DegenerateInput("two links share a number")
    crank = next((k for k in m.links if k.number == m.crank), None)
    if crank is None:
        raise DegenerateInput(f"there is no link {m.crank} to drive")
    pivots = [j for j in crank.joints if j in m.ground]
    if len(pivots) != 1:
        raise DegenerateInput(f"the crank, link {crank.number} ({crank.label}), must join one fixed pivot to one "
                              f"moving joint; fixed pivots are {', '.join(m.ground) or 'none'}")
    bodies: list[_Body] = []
    index: dict[int, int] = {}
    for k in m.links:
        if not (k.length > 0 and math.isfinite(k.length)):
            raise DegenerateInput(f"link {k.number} ({k.label}) must have a positive length, not {k.length!r}")
        local = {n: (p.x, p.y) for n, p in m.local(k.number).items()}
        index[k.number] = len(bodies)
        bodies.append(_Body("link", k.number, MappingProxyType(local), max(math.hypot(*p) for p in local.values())))
    link_points = {n for b in bodies for n in b.local}
    names = set(m.ground) | link_points | {s.joint for s in m.slides}
    count: dict[str, int] = {}
    for s in m.slides:
        if s.joint in m.ground:
            raise DegenerateInput(f"slider joint {s.joint} is also a fixed pivot")
        count[s.joint] = count.get(s.joint, 0) + 1
        if count[s.joint] > 2:              # two: a joint carried along two lines (a PRP dyad)
            raise DegenerateInput(f"joint {s.joint} is carried by three sliders; a joint takes at most two")
        if s.on is not None:
            if s.on not in index:
                raise DegenerateInput(f"joint {s.joint} slides on link {s.on}, which does not exist")
            if s.joint in bodies[index[s.on]].local:
                raise DegenerateInput(f"joint {s.joint} cannot slide on link {s.on}, which it belongs to")
        if s.number is None and s.joint not in link_points:
            raise DegenerateInput(f"pin {s.joint} slides in a slot but no link carries it")
        if s.number is not None and s.number in index:
            raise DegenerateInput(f"block {s.number} has the number of a link")
    blocks = [s for s in m.slides if s.number is not None]
    if len({s.number for s in blocks}) != len(blocks):
        raise DegenerateInput("two slider blocks share a number")

    size = m.size
    extent = max([math.hypot(p.x, p.y) for p in m.ground.values()]
                 + [math.hypot(s.through.x, s.through.y) for s in m.slides if s.on is None] + [0.0])
    scale = max(size, extent)
    if not (scale > 0 and math.isfinite(scale)):
        raise DegenerateInput(f"the scene size must be a positive length, not {scale!r}")
    block_index: dict[int, int] = {}
    for s in blocks:
        block_index[s.number] = len(bodies)
        ell = bodies[index[s.on]].size if s.on is not None else scale
        bodies.append(_Body("block", s.number, MappingProxyType({s.joint: (0.0, 0.0)}), ell))

    # which bodies carry each named point; the frame first, so a revolute pairs every body with it
    carriers: dict[str, list[tuple[int, tuple[float, float]]]] = {}
    for n, p in m.ground.items():
        carriers[n] = [(_FRAME, (p.x, p.y))]
    for i, b in enumerate(bodies):
        for n, s in b.local.items():
            carriers.setdefault(n, []).append((i, s))
    revolutes = tuple(_Revolute(n, cs[0], c) for n, cs in carriers.items() for c in cs[1:])

    lines: list[_OnLine] = []
    angles: list[_Angle] = []
    coincident: dict[str, tuple[str, int]] = {}
    for s in m.slides:
        g = index[s.on] if s.on is not None else None
        if s.number is not None:
            carrier, at = block_index[s.number], (0.0, 0.0)
            where = f"block {s.number}"
        else:
            carrier, at = next((i, b.local[s.joint]) for i, b in enumerate(bodies) if s.joint in b.local)
            where = f"pin {s.joint}"
        line = f"the slot of link {s.on}" if s.on is not None else "its guide"
        lines.append(_OnLine(s.joint, carrier, at, g, s.angle, s.offset if g is not None else 0.0,
                             (s.through.x, s.through.y), f"{s.joint} ({where}) on {line}"))
        if s.number is not None:
            angles.append(_Angle(carrier, g, s.angle, f"angle of block {s.number} ({line})"))
        if g is not None:
            # the name the construction gives the slotted link's point under the joint (A3), primed
            # while it clashes with a point of the mechanism
            name = coincident_name(s.joint, s.on)
            while name in names:
                name += "'"
            coincident[name] = (s.joint, g)

    unknowns = 3 * len(bodies)
    equations = 2 * len(revolutes) + len(lines) + len(angles) + 1
    if unknowns != equations:
        raise DegenerateInput(_count_message(unknowns, equations, len(bodies)))
    return _Model(tuple(bodies), MappingProxyType({n: tuple(c) for n, c in carriers.items()}), revolutes,
                  tuple(lines), tuple(angles), index[crank.number], 0.0 if crank.joints[0] == pivots[0] else math.pi,
                  MappingProxyType(coincident), scale, unknowns, equations)


def constraint_count(m: Mechanism) -> tuple[int, int]:
    """(coordinates, equations including the driver) of ``m``; equal for a 1-DoF mechanism.  Raises
    DegenerateInput (with the count) when they differ or the data describe no mechanism."""
    model = _model(m)
    return model.unknowns, model.equations


# -- Phi, Phi_q, gamma -----------------------------------------------------------------------------

def _wrap(a: float) -> float:
    return math.remainder(a, 2 * math.pi)


def _arm(q, body: int, s: tuple[float, float]) -> tuple[float, float, float, float]:
    """(world point x, y, arm w x, w y) of the point with body-frame coordinates s."""
    if body == _FRAME:
        return s[0], s[1], 0.0, 0.0
    x, y, phi = q[3 * body:3 * body + 3]
    c, sn = math.cos(phi), math.sin(phi)
    wx, wy = c * s[0] - sn * s[1], sn * s[0] + c * s[1]
    return x + wx, y + wy, wx, wy


def _line_frame(model: _Model, q: np.ndarray, c: _OnLine) -> tuple[float, float, float, float, float]:
    """(origin x, y, direction d x, d y, phi_g) of the line ``c`` at q."""
    if c.slot is None:
        return c.through[0], c.through[1], math.cos(c.angle), math.sin(c.angle), 0.0
    x, y, phi = q[3 * c.slot:3 * c.slot + 3]
    return x, y, math.cos(phi + c.angle), math.sin(phi + c.angle), phi


def _residual(model: _Model, q: np.ndarray, theta: float) -> np.ndarray:
    out: list[float] = []
    for c in model.revolutes:
        ax, ay, _, _ = _arm(q, *c.a)
        bx, by, _, _ = _arm(q, *c.b)
        out += [ax - bx, ay - by]
    for c in model.lines:
        px, py, _, _ = _arm(q, c.body, c.s)
        ox, oy, dx, dy, _ = _line_frame(model, q, c)
        out.append(-dy * (px - ox) + dx * (py - oy) + c.offset)          # n = k x d = (-d_y, d_x)
    for c in model.angles:
        other = q[3 * c.other + 2] if c.other is not None else 0.0
        out.append(_wrap(q[3 * c.body + 2] - other - c.angle))
    out.append(_wrap(q[3 * model.crank + 2] - theta - model.crank_offset))
    return np.array(out)


def _jacobian(model: _Model, q: np.ndarray) -> np.ndarray:
    J = np.zeros((model.equations, model.unknowns))
    row = 0
    for c in model.revolutes:
        for sign, (body, s) in ((1.0, c.a), (-1.0, c.b)):
            if body == _FRAME:
                continue
            _, _, wx, wy = _arm(q, body, s)
            col = 3 * body
            J[row, col] += sign
            J[row + 1, col + 1] += sign
            J[row, col + 2] += -sign * wy                # k x w = (-w_y, w_x)
            J[row + 1, col + 2] += sign * wx
        row += 2
    for c in model.lines:
        px, py, wx, wy = _arm(q, c.body, c.s)
        ox, oy, dx, dy, _ = _line_frame(model, q, c)
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
    if body == _FRAME:
        return 0.0, 0.0, 0.0
    return qd[3 * body], qd[3 * body + 1], qd[3 * body + 2]


def _gamma(model: _Model, q: np.ndarray, qd: np.ndarray, alpha: float) -> np.ndarray:
    """The right-hand side of Phi_q q'' = gamma (derivations in the module docstring)."""
    out: list[float] = []
    for c in model.revolutes:
        gx = gy = 0.0
        for sign, (body, s) in ((1.0, c.a), (-1.0, c.b)):
            if body == _FRAME:
                continue
            _, _, wx, wy = _arm(q, body, s)
            w2 = qd[3 * body + 2] ** 2
            gx += sign * w2 * wx                         # gamma = phi_i'^2 w_i - phi_j'^2 w_j
            gy += sign * w2 * wy
        out += [gx, gy]
    for c in model.lines:
        px, py, wx, wy = _arm(q, c.body, c.s)
        ox, oy, dx, dy, _ = _line_frame(model, q, c)
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

def _scales(model: _Model) -> tuple[np.ndarray, np.ndarray]:
    """(row scale R, column scale C): the scaled Jacobian is R J C, with q = C z."""
    L = model.scale
    cols = np.empty(model.unknowns)
    for i, b in enumerate(model.bodies):
        cols[3 * i:3 * i + 3] = (L, L, L / b.size)
    rows = np.array([r for _, r in model.rows()])
    return rows, cols


def _solve(model: _Model, J: np.ndarray, rhs: np.ndarray, rows: np.ndarray, cols: np.ndarray) -> np.ndarray:
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


def _initial(model: _Model, m: Mechanism, guess: Mapping[str, object]) -> np.ndarray:
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
    q[3 * model.crank + 2] = _wrap(q[3 * model.crank + 2])
    return q


# -- results ---------------------------------------------------------------------------------------

@dataclass(frozen=True)
class ConstraintPose:
    """The solved position at one crank angle.

    Attributes
    ----------
    angle : float
        The crank angle (rad).
    positions : mapping of name -> Vec
        Every fixed pivot, every point of every link, every slider pin, and every coincident point
        (the slotted link's point under a sliding joint: ``coincident_name(J, G)``, e.g. A3).
    frames : mapping of (kind, number) -> (Vec, float)
        Each body's coordinates: ("link", k) the position of its first base joint and its base line's
        angle; ("block", b) its pin and its angle (rad, wrapped into (-pi, pi]).
    coincident : mapping of name -> (joint, link number)
        Every coincident point: the sliding joint it lies under and the slotted link it belongs to.
    smallest_singular_value, condition_number : float
        Of the scaled Jacobian (module docstring; its largest singular value is of order one): 0 and inf
        at a singular position.
    residual : float
        Largest scaled constraint residual at the solution.
    iterations : int
        Newton-Raphson steps taken.
    coordinates, equations : int
        The count: equal for a 1-DoF mechanism (the driver is one of the equations).
    """

    angle: float
    positions: Mapping[str, Vec]
    frames: Mapping[tuple[str, int], tuple[Vec, float]]
    coincident: Mapping[str, tuple[str, int]]
    smallest_singular_value: float
    condition_number: float
    residual: float
    iterations: int
    coordinates: int
    equations: int


@dataclass(frozen=True)
class ConstraintState:
    """Positions, velocities and accelerations at one crank angle (SI, CCW positive).

    Attributes
    ----------
    angle, omega, alpha : float
        The crank's input.
    positions, velocities, accelerations : mapping of name -> Vec
        Every fixed pivot (velocity and acceleration exactly zero), every point of every link, every
        slider pin, and every coincident point (the point of the slotted link G under a sliding joint J,
        named ``coincident_name(J, G)`` as the construction names it, e.g. A3: at J's position, with G's
        velocity and acceleration there).
    angular, angular_acceleration : mapping of number -> float
        Every link and every slider block (a block on a slot turns with its link; one on a fixed guide
        has 0 to rounding).
    sliding_velocity, sliding_acceleration : mapping of joint -> float
        For each sliding joint J: s' and s'' of its distance s along its line, measured in the line's
        direction ``slide_directions[J]`` and relative to the line's body (the frame for a guide).  On a
        slot of G, V_J - V_JG = s' d and A_J = A_JG + 2 omega_G k x (s' d) + s'' d, so the notes'
        sliding component of the coincident point relative to the joint is A_JGJ^s = -s'' d.
    slide_directions : mapping of joint -> Vec
        The unit direction d of each sliding joint's line at this position.
    frames, coincident, smallest_singular_value, condition_number, residual, iterations, coordinates,
    equations
        As in :class:`ConstraintPose`.
    """

    angle: float
    omega: float
    alpha: float
    positions: Mapping[str, Vec]
    velocities: Mapping[str, Vec]
    accelerations: Mapping[str, Vec]
    angular: Mapping[int, float]
    angular_acceleration: Mapping[int, float]
    sliding_velocity: Mapping[str, float]
    sliding_acceleration: Mapping[str, float]
    slide_directions: Mapping[str, Vec]
    frames: Mapping[tuple[str, int], tuple[Vec, float]]
    coincident: Mapping[str, tuple[str, int]]
    smallest_singular_value: float
    condition_number: float
    residual: float
    iterations: int
    coordinates: int
    equations: int

    @property
    def velocity_error_estimate(self) -> float:
        """A rough upper bound of the velocities' relative error: the positions carry the residual (at
        the rounding floor, ~eps) times kappa, and the velocity solve magnifies an error of the matrix
        by kappa again: (residual + eps) kappa^2.  Measured errors are far smaller where kappa < 100."""
        k = self.condition_number
        return (self.residual + _EPS) * k * k

    @property
    def acceleration_error_estimate(self) -> float:
        """A rough upper bound of the accelerations' relative error: one more solve, one more factor
        kappa."""
        return self.velocity_error_estimate * self.condition_number


# -- the solution ----------------------------------------------------------------------------------

def _newton(model: _Model, q: np.ndarray, theta: float, where: str) -> tuple[np.ndarray, float, int]:
    rows, cols = _scales(model)

    def size(q_: np.ndarray) -> float:
        r = np.abs(rows * _residual(model, q_, theta))
        return float(r.max()) if np.all(np.isfinite(r)) else math.inf

    res = size(q)
    polished = False
    for it in range(MAX_ITERATIONS + 1):
        if res <= TOLERANCE:
            if polished:
                return q, res, it
            polished = True
        elif it == MAX_ITERATIONS or not math.isfinite(res):
            break
        dq = _solve(model, _jacobian(model, q), -_residual(model, q, theta), rows, cols)
        if not np.all(np.isfinite(dq)):
            break
        # full step, halved while it makes the residual worse (far from the solution only)
        step, trial, tres = 1.0, q + dq, size(q + dq)
        while res > TOLERANCE and tres > res and step > 1 / 256:
            step /= 2
            trial = q + step * dq
            tres = size(trial)
        if polished and tres > res:      # rounding floor reached: keep the converged point
            return q, res, it + 1
        q, res = trial, tres
    r = np.abs(rows * _residual(model, q, theta)) if np.all(np.isfinite(q)) else None
    if r is not None and np.all(np.isfinite(r)):
        worst = int(np.argmax(r))
        what = f"; the worst is {model.rows()[worst][0]}, off by {r[worst]:.3g} (relative to the scene size)"
    else:
        what = ""
    raise CannotAssemble(f"Newton-Raphson did not close the constraint equations from the given guess in "
                         f"{MAX_ITERATIONS} steps{what}: the mechanism does not assemble here, or the guess is "
                         f"too far from an assembly", position=where)


def _pose(model: _Model, m: Mechanism, theta: float, guess: Mapping[str, object]) -> tuple:
    where = describe_angle(theta)
    if not math.isfinite(theta):
        raise DegenerateInput(f"the crank angle must be finite, not {theta!r}")
    q, res, its = _newton(model, _initial(model, m, guess), theta, where)
    q = q.tolist()                                    # plain floats from here on
    J = _jacobian(model, q)
    rows, cols = _scales(model)
    sv = np.linalg.svd(rows[:, None] * J * cols[None, :], compute_uv=False)
    smin, kappa = float(sv[-1]), (float(sv[0] / sv[-1]) if sv[-1] > 0 else math.inf)
    positions: dict[str, Vec] = {}
    for n, cs in model.carriers.items():
        x, y, _, _ = _arm(q, *cs[0])
        positions[n] = Vec(x, y)
    for n, (joint, _) in model.coincident.items():
        positions[n] = positions[joint]
    frames = {(b.kind, b.number): (Vec(q[3 * i], q[3 * i + 1]), _wrap(q[3 * i + 2]))
              for i, b in enumerate(model.bodies)}
    coincident = {n: (j, model.bodies[g].number) for n, (j, g) in model.coincident.items()}
    pose = ConstraintPose(theta, MappingProxyType(positions), MappingProxyType(frames), MappingProxyType(coincident),
                          smin, kappa, res, its, model.unknowns, model.equations)
    return pose, q, J, rows, cols


def solve_positions(m: Mechanism, theta: float, guess: Mapping[str, object]) -> ConstraintPose:
    """The position of ``m`` at crank angle ``theta`` (rad, direction pivot -> tip, CCW from +x), by
    Newton-Raphson from ``guess`` (point name -> Vec or (x, y); at least two points of every link and
    the pin of every block).  Also at a singular position (see ``smallest_singular_value``).

    Raises DegenerateInput when the mechanism is not 1-DoF (with the count) or the guess is incomplete,
    CannotAssemble when Newton-Raphson does not converge."""
    return _pose(_model(m), m, float(theta), guess)[0]


def solve_constraints(m: Mechanism, theta: float, omega: float, alpha: float,
                      guess: Mapping[str, object]) -> ConstraintState:
    """Positions, velocities and accelerations of ``m`` with the crank at ``theta`` (rad, direction
    pivot -> tip, CCW from +x) turning at ``omega`` (rad/s) with angular acceleration ``alpha``
    (rad/s^2), by the constraint equations in body coordinates (module docstring).

    ``guess`` maps point names to positions (Vec or (x, y)) near the wanted assembly -- e.g. the
    construction's pose, or the solution at a neighbouring angle; coincident names are accepted and
    ignored.  Raises DegenerateInput (not 1-DoF, with the count; incomplete guess), CannotAssemble (no
    convergence) and IndeterminatePosition (smallest singular value of the scaled Jacobian below
    :data:`SINGULAR`: toggle, dead centre, lock)."""
    theta, omega, alpha = float(theta), float(omega), float(alpha)
    for name, v in (("angular velocity", omega), ("angular acceleration", alpha)):
        if not math.isfinite(v):
            raise DegenerateInput(f"the crank's {name} must be finite, not {v!r}")
    model = _model(m)
    pose, q, J, rows, cols = _pose(model, m, theta, guess)
    if not pose.condition_number * SINGULAR <= 1.0:
        # which coordinates move when the crank is held: the null vector of the scaled Jacobian
        A = rows[:, None] * J * cols[None, :]
        null = np.abs(np.linalg.svd(A)[2][-1])
        moving = sorted({model.bodies[i // 3].label for i in np.flatnonzero(null > 0.3 * null.max())})
        raise IndeterminatePosition(
            f"the constraint equations are singular (condition number {pose.condition_number:.3g} of the scaled "
            f"Jacobian): {' and '.join(moving)} can move while the crank is held, so the velocities are "
            f"indeterminate (toggle, dead centre or lock)", position=describe_angle(theta),
            kind="singular position", condition=1.0 / pose.condition_number)
    nu = np.zeros(model.equations)
    nu[-1] = omega                                    # -Phi_t: only the driver depends on time
    qd = _solve(model, J, nu, rows, cols).tolist()
    qdd = _solve(model, J, _gamma(model, q, qd, alpha), rows, cols).tolist()

    def point(body: int, s: tuple[float, float]) -> tuple[Vec, Vec]:
        if body == _FRAME:
            return Vec(0.0, 0.0), Vec(0.0, 0.0)
        _, _, wx, wy = _arm(q, body, s)
        vx, vy, w = qd[3 * body:3 * body + 3]
        ax, ay, a = qdd[3 * body:3 * body + 3]
        # V = r' + phi' k x w;  A = r'' + phi'' k x w - phi'^2 w
        return Vec(vx - w * wy, vy + w * wx), Vec(ax - a * wy - w * w * wx, ay + a * wx - w * w * wy)

    velocities: dict[str, Vec] = {}
    accelerations: dict[str, Vec] = {}
    for n, cs in model.carriers.items():
        velocities[n], accelerations[n] = point(*cs[0])
    for n, (joint, g) in model.coincident.items():
        p = pose.positions[joint]
        x, y, phi = q[3 * g:3 * g + 3]
        c, sn = math.cos(-phi), math.sin(-phi)
        s = (c * (p.x - x) - sn * (p.y - y), sn * (p.x - x) + c * (p.y - y))   # J in G's frame
        velocities[n], accelerations[n] = point(g, s)
    angular = {b.number: float(qd[3 * i + 2]) for i, b in enumerate(model.bodies)}
    angular_acc = {b.number: float(qdd[3 * i + 2]) for i, b in enumerate(model.bodies)}

    sliding_v: dict[str, float] = {}
    sliding_a: dict[str, float] = {}
    directions: dict[str, Vec] = {}
    for c in model.lines:
        ox, oy, dx, dy, _ = _line_frame(model, q, c)
        nx, ny = -dy, dx
        px, py, _, _ = _arm(q, c.body, c.s)
        v, a = point(c.body, c.s)
        rx, ry = px - ox, py - oy
        if c.slot is None:
            wg = ag = 0.0
            gv, ga = (0.0, 0.0), (0.0, 0.0)
        else:
            gv, ga = qd[3 * c.slot:3 * c.slot + 2], qdd[3 * c.slot:3 * c.slot + 2]
            wg, ag = qd[3 * c.slot + 2], qdd[3 * c.slot + 2]
        # s = d . r with r = P - r_g:  s' = d'.r + d.r',  s'' = d''.r + 2 d'.r' + d.r''
        # d' = phi_g' n,  d'' = phi_g'' n - phi_g'^2 d
        rdx, rdy = v.x - gv[0], v.y - gv[1]
        rddx, rddy = a.x - ga[0], a.y - ga[1]
        sliding_v[c.joint] = wg * (nx * rx + ny * ry) + dx * rdx + dy * rdy
        sliding_a[c.joint] = (ag * (nx * rx + ny * ry) - wg * wg * (dx * rx + dy * ry)
                              + 2 * wg * (nx * rdx + ny * rdy) + dx * rddx + dy * rddy)
        directions[c.joint] = Vec(dx, dy)

    ro = MappingProxyType
    return ConstraintState(theta, omega, alpha, pose.positions, ro(velocities), ro(accelerations), ro(angular),
                           ro(angular_acc), ro(sliding_v), ro(sliding_a), ro(directions), pose.frames,
                           pose.coincident, pose.smallest_singular_value, pose.condition_number, pose.residual,
                           pose.iterations, pose.coordinates, pose.equations)
