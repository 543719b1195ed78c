"""Kinematics of any 1-DoF mechanism by constraint equations in body coordinates (the multibody method).

The analytic check for every mechanism :class:`~constructions.mechanisms.model.Mechanism` accepts --
also those the closed forms (:mod:`constructions.analytic`) and the dyad chains
(:mod:`constructions.vector_loops`) cannot model: a ternary link whose third point is a joint of another
link, a slider block on a slot of a moving link, a pin in a slot, and loops that must be solved as a
whole (an Assur triad).  It reads only the mechanism's data (pivots, links and :meth:`Mechanism.local`,
slides, the crank) and shares no code with the graphical construction: no assembly plan, no circle or
line intersections, no polygon.  The bodies and their coordinates q are :mod:`.constraint_model`'s; the
equations Phi(q, t) = 0, derived by hand, :mod:`.constraint_equations`'.

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
from dataclasses import dataclass, fields
from types import MappingProxyType
from typing import Mapping

import numpy as np

from ..errors import CannotAssemble, DegenerateInput, IndeterminatePosition
from ..geometry import Vec
from .constraint_equations import (arm, gamma, initial_coordinates, jacobian, line_frame, residual, scales,
                                   solve_scaled, wrap)
from .constraint_model import FRAME, Model, build_model
from .model import Mechanism, describe_angle

__all__ = ["MAX_ITERATIONS", "SINGULAR", "TOLERANCE", "ConstraintPose", "ConstraintState", "solve_constraints",
           "solve_positions"]

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

_EPS = float(np.finfo(np.float64).eps)


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
class ConstraintState(ConstraintPose):
    """Positions, velocities and accelerations at one crank angle (SI, CCW positive): the solved
    :class:`ConstraintPose` and its rates.

    Attributes
    ----------
    omega, alpha : float
        The crank's input (its angle is the pose's ``angle``).
    velocities, accelerations : mapping of name -> Vec
        Of every point the pose places: every fixed pivot (exactly zero), every point of every link, every
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
    angle, positions, frames, coincident, smallest_singular_value, condition_number, residual, iterations,
    coordinates, equations
        As in :class:`ConstraintPose`.
    """

    omega: float
    alpha: float
    velocities: Mapping[str, Vec]
    accelerations: Mapping[str, Vec]
    angular: Mapping[int, float]
    angular_acceleration: Mapping[int, float]
    sliding_velocity: Mapping[str, float]
    sliding_acceleration: Mapping[str, float]
    slide_directions: Mapping[str, Vec]

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

def _newton(model: Model, q: np.ndarray, theta: float, where: str) -> tuple[np.ndarray, float, int]:
    rows, cols = scales(model)

    def size(q_: np.ndarray) -> float:
        r = np.abs(rows * residual(model, q_, theta))
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
        dq = solve_scaled(model, jacobian(model, q), -residual(model, q, theta), rows, cols)
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
    r = np.abs(rows * residual(model, q, theta)) if np.all(np.isfinite(q)) else None
    if r is not None and np.all(np.isfinite(r)):
        worst = int(np.argmax(r))
        what = f"; the worst is {model.rows()[worst][0]}, off by {r[worst]:.3g} (relative to the scene size)"
    else:
        what = ""
    raise CannotAssemble(f"Newton-Raphson did not close the constraint equations from the given guess in "
                         f"{MAX_ITERATIONS} steps{what}: the mechanism does not assemble here, or the guess is "
                         f"too far from an assembly", position=where)


def _pose(model: Model, m: Mechanism, theta: float, guess: Mapping[str, object]) -> tuple:
    where = describe_angle(theta)
    if not math.isfinite(theta):
        raise DegenerateInput(f"the crank angle must be finite, not {theta!r}")
    q, res, its = _newton(model, initial_coordinates(model, m, guess), theta, where)
    q = q.tolist()                                    # plain floats from here on
    J = jacobian(model, q)
    rows, cols = scales(model)
    sv = np.linalg.svd(rows[:, None] * J * cols[None, :], compute_uv=False)
    smin, kappa = float(sv[-1]), (float(sv[0] / sv[-1]) if sv[-1] > 0 else math.inf)
    positions: dict[str, Vec] = {}
    for n, cs in model.carriers.items():
        x, y, _, _ = arm(q, *cs[0])
        positions[n] = Vec(x, y)
    for n, (joint, _) in model.coincident.items():
        positions[n] = positions[joint]
    frames = {(b.kind, b.number): (Vec(q[3 * i], q[3 * i + 1]), wrap(q[3 * i + 2]))
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
    return _pose(build_model(m), m, float(theta), guess)[0]


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
    model = build_model(m)
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
    qd = solve_scaled(model, J, nu, rows, cols).tolist()
    qdd = solve_scaled(model, J, gamma(model, q, qd, alpha), rows, cols).tolist()

    def point(body: int, s: tuple[float, float]) -> tuple[Vec, Vec]:
        if body == FRAME:
            return Vec(0.0, 0.0), Vec(0.0, 0.0)
        _, _, wx, wy = arm(q, body, s)
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
        ox, oy, dx, dy, _ = line_frame(model, q, c)
        nx, ny = -dy, dx
        px, py, _, _ = arm(q, c.body, c.s)
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
    return ConstraintState(**{f.name: getattr(pose, f.name) for f in fields(ConstraintPose)}, omega=omega,
                           alpha=alpha, velocities=ro(velocities), accelerations=ro(accelerations),
                           angular=ro(angular), angular_acceleration=ro(angular_acc), sliding_velocity=ro(sliding_v),
                           sliding_acceleration=ro(sliding_a), slide_directions=ro(directions))