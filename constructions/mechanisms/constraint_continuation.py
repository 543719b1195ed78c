"""The constraint equations followed over many crank angles: each pose continued from the last, a block
of angles at a time.

The continuation is the one-pose solver's (:func:`.constraint_kinematics.solve_constraints` at each angle
from the previous pose; the first pose, and the first after a gap, from the construction
:func:`.pose.locate`, on the scene's branch), made fast where nothing can go astray:

* From the last solved pose, its coordinates are extrapolated to the next block of angles by their
  Taylor series to second order (q + q_theta d + q_theta2 d^2 / 2, d the angle from it), and the block is
  closed by one stacked Newton-Raphson (:func:`.constraint_batch.close`), 1 to 3 steps.
* A pose of the block is taken only where its equations closed to the one-pose tolerance, its scaled
  Jacobian is far from singular (1-norm condition number below :data:`KAPPA1`, so the 2-norm one the
  one-pose solver tests is below k * KAPPA1, far under 1 / SINGULAR), and the prediction was so close
  (``moved`` times that condition number below :data:`NEAR`) that Newton-Raphson cannot have reached
  any other assembly.  The block is cut at its first other pose.
* That pose is solved alone, as before: :func:`.constraint_kinematics.solve_constraints` from the
  previous pose, or a gap (then :func:`.pose.locate` at the next angles until one assembles -- in
  strides of up to :data:`GAP_STRIDE` on a fine sweep, the gap's end found to one step).  So near a
  toggle, a dead centre or a lock, and at every gap, the continuation is the one-pose solver's, step by
  step; elsewhere it is the same solution to rounding.

Blocks grow while whole blocks are taken (to :data:`LONGEST`) and shrink where they are cut.
``progress(done, total)`` hears how far the continuation has come before every block and every
:data:`REPORT` angles solved one by one: at least every LONGEST angles.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..errors import CannotAssemble, ConstructionError, IndeterminatePosition
from ..geometry import Vec
from .constraint_batch import Closed, close, motion, points
from .constraint_kinematics import TOLERANCE, ConstraintState, solve_constraints
from .constraint_model import Model, build_model
from .model import Mechanism
from .pose import locate

__all__ = ["KAPPA1", "LONGEST", "NEAR", "REPORT", "Turn", "continue_constraints"]

KAPPA1 = 1e4
"""Largest 1-norm condition number of a stacked pose's scaled Jacobian taken from a block."""

NEAR = 1e-2
"""Largest (distance from the prediction, scaled) x (1-norm condition number) of a pose taken from a
block: the prediction lies well inside the region where Newton-Raphson goes to the nearest assembly."""

STEPS = 4
"""Newton-Raphson steps a block gets (a good prediction needs 1 to 3)."""

SHORTEST, FIRST, LONGEST = 4, 16, 1024
"""Block lengths (angles): the least a cut block shrinks to, the first, the most it grows to."""

REPORT = 256
"""Angles solved one by one (at a gap, near a singular position) between two reports of the progress."""


@dataclass(frozen=True)
class Turn:
    """The continuation's result over the angles: ``assembles`` (bool), and name -> (x, y) arrays of the
    positions, velocities and accelerations of every point, body number -> array of the angular velocities
    and accelerations (NaN where it does not assemble; the names of the first pose solved, or none)."""

    assembles: np.ndarray
    positions: dict
    velocities: dict
    accelerations: dict
    angular: dict
    angular_acceleration: dict


class _Out:
    """The output arrays, allocated when the first pose is solved (its model names the points)."""

    def __init__(self, model: Model, n: int) -> None:
        names = list(model.carriers) + list(model.coincident)
        self.model = model
        self.pos = {k: (np.full(n, np.nan), np.full(n, np.nan)) for k in names}
        self.vel = {k: (np.full(n, np.nan), np.full(n, np.nan)) for k in names}
        self.acc = {k: (np.full(n, np.nan), np.full(n, np.nan)) for k in names}
        self.bodies = [(3 * i + 2, b.number) for i, b in enumerate(model.bodies)]
        self.ang = {k: np.full(n, np.nan) for _, k in sorted(self.bodies, key=lambda x: x[1])}
        self.alp = {k: np.full(n, np.nan) for k in self.ang}

    def block(self, i: int, c: Closed, omega: float, alpha: float, take: int) -> None:
        """Store the first ``take`` closed poses from angle i on."""
        q = c.q[:take]
        qd, qdd = motion(c, omega, alpha)
        qd, qdd = qd[:take], qdd[:take]
        j = i + take
        for src, dst in zip(points(self.model, q, qd, qdd), (self.pos, self.vel, self.acc)):
            for name, (x, y) in src.items():
                dst[name][0][i:j], dst[name][1][i:j] = x, y
        for col, k in self.bodies:
            self.ang[k][i:j], self.alp[k][i:j] = qd[:, col], qdd[:, col]

    def state(self, i: int, st: ConstraintState) -> None:
        """Store the one-pose solver's state at angle i."""
        for src, dst in ((st.positions, self.pos), (st.velocities, self.vel), (st.accelerations, self.acc)):
            for name, v in src.items():
                dst[name][0][i], dst[name][1][i] = v.x, v.y
        for k in self.ang:
            self.ang[k][i], self.alp[k][i] = st.angular[k], st.angular_acceleration[k]

    def guess(self, i: int) -> dict:
        """The positions at angle i, as the one-pose solver's guess."""
        return {name: Vec(float(x[i]), float(y[i])) for name, (x, y) in self.pos.items()}


def _coordinates(model: Model, st: ConstraintState) -> np.ndarray:
    """The body coordinates of a solved pose (its frames), as one row."""
    q = np.empty((1, model.unknowns))
    for i, b in enumerate(model.bodies):
        p, phi = st.frames[(b.kind, b.number)]
        q[0, 3 * i:3 * i + 3] = (p.x, p.y, phi)
    return q


class _Anchor:
    """The last pose solved, from which the next block is predicted: its angle and the Taylor
    coefficients of its coordinates."""

    __slots__ = ("theta", "q", "q1", "q2")

    def __init__(self, theta: float, q: np.ndarray, q1: np.ndarray, q2: np.ndarray) -> None:
        self.theta, self.q, self.q1, self.q2 = theta, q, q1, q2

    def predict(self, th: np.ndarray) -> np.ndarray:
        d = (th - self.theta)[:, None]
        return self.q + d * self.q1 + (0.5 * d * d) * self.q2


def _anchor_at(model: Model, theta: float, q: np.ndarray) -> _Anchor | None:
    """The anchor at a pose the one-pose solver found (its derivatives by one stacked solve)."""
    c = close(model, q, np.array([theta]), TOLERANCE, 0)
    if c is None or not np.all(np.isfinite(c.q_theta2)):
        return None
    return _Anchor(theta, c.q[0], c.q_theta[0], c.q_theta2[0])


def _taken(c: Closed) -> int:
    """How many poses of the block, from its first, may be taken."""
    good = c.closed & (c.kappa1 <= KAPPA1) & (c.moved * c.kappa1 <= NEAR)
    bad = np.flatnonzero(~good)
    return int(bad[0]) if bad.size else good.size


GAP_STRIDE = math.radians(0.05)
"""rad: across a gap the construction is tried at angles up to this far apart (a stride of 1, 2, 4...
steps), then back by halves to the first angle that assembles: a gap's end is found to one step, and
only an island of assembly narrower than 0.05 deg inside a gap (an assembly a hair from two toggles) is
passed over.  Coarser sweeps, whose steps are wider than that, try every angle."""


def _skip(th: np.ndarray) -> int:
    """The widest stride, in steps of ``th``, :data:`GAP_STRIDE` allows (at least 1)."""
    if th.size < 2:
        return 1
    step = float(np.min(np.abs(np.diff(th))))
    return max(1, int(GAP_STRIDE / step)) if step > 0 else 1


def _across_gap(m: Mechanism, th: np.ndarray, i: int, skip: int, hear) -> tuple[int, dict | None]:
    """From angle ``i``, where the construction failed, the first later angle where it assembles and its
    positions, or (n, None) when none does: strides of 1, 2, 4... steps up to ``skip``, then halving back
    between the last failure and the first success; ``hear(k)`` at every stride."""
    n, bad, stride = th.size, i, 1
    while True:
        hear(bad)
        nxt = min(n - 1, bad + stride)
        if nxt == bad:
            return n, None
        try:
            good = locate(m, float(th[nxt])).positions
        except ConstructionError:
            bad, stride = nxt, min(2 * stride, skip)
            continue
        hi = nxt
        while hi - bad > 1:
            mid = (bad + hi) // 2
            try:
                good, hi = locate(m, float(th[mid])).positions, mid
            except ConstructionError:
                bad = mid
        return hi, good


def continue_constraints(m: Mechanism, th: np.ndarray, omega: float, alpha: float, progress=None) -> Turn:
    """Solve ``m`` by the constraint equations at every crank angle of ``th`` (rad, a flat array), each
    pose continued from the previous one (module docstring).  Raises what the one-pose solver raises
    other than CannotAssemble and IndeterminatePosition (those are gaps)."""
    n = th.size
    skip = _skip(th)
    ok = np.zeros(n, dtype=bool)
    out: _Out | None = None
    anchor: _Anchor | None = None
    guess = None
    length, i, reported = FIRST, 0, -REPORT

    def hear(k: int) -> None:                   # across a gap: every REPORT angles, as one by one
        nonlocal reported
        if progress is not None and k - reported >= REPORT:
            progress(k, n)
            reported = k
    while i < n:
        if progress is not None and (anchor is not None or i - reported >= REPORT) and i > reported:
            progress(i, n)
            reported = i
        if anchor is not None:
            j = min(n, i + length)
            c = close(out.model, anchor.predict(th[i:j]), th[i:j], TOLERANCE, STEPS)
            take = _taken(c) if c is not None else 0
            if take:
                out.block(i, c, omega, alpha, take)
                ok[i:i + take] = True
                k = take - 1
                anchor = _Anchor(float(th[i + k]), c.q[k], c.q_theta[k], c.q_theta2[k])
                guess = None
                length = min(2 * length, LONGEST) if take == j - i else max(SHORTEST, length // 2)
                i += take
                continue
            length = SHORTEST
            guess = out.guess(i - 1)
        t = float(th[i])
        if guess is None:                              # first angle, or after a gap: the scene's branch
            try:
                guess = locate(m, t).positions
            except ConstructionError:
                i, guess = _across_gap(m, th, i, skip, hear)
                if guess is None:
                    break
                t = float(th[i])
        try:
            st = solve_constraints(m, t, omega, alpha, guess)
        except (CannotAssemble, IndeterminatePosition):
            guess, anchor = None, None
            i += 1
            continue
        if out is None:
            out = _Out(build_model(m), n)
        out.state(i, st)
        ok[i] = True
        anchor = _anchor_at(out.model, t, _coordinates(out.model, st))
        guess = None if anchor is not None else st.positions
        i += 1
    if out is None:
        return Turn(ok, {}, {}, {}, {}, {})
    return Turn(ok, out.pos, out.vel, out.acc, out.ang, out.alp)
