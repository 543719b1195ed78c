"""A mechanism over many crank angles: positions, velocities and accelerations of every joint and point,
angular velocities and accelerations of every link (SI, CCW positive).

The solver is chosen as :func:`constructions.check.analytic_solution` chooses it, but over arrays:

- a plain four-bar or slider-crank (one dyad hung from the crank tip and the frame, points fixed to its
  links): the vectorised closed forms of :mod:`constructions.analytic`;
- any other crank followed by RRR/RRP dyads: :func:`constructions.vector_loops.chain_solution`;
- anything else (a slot in a moving link, a ternary link joined at its third point): the constraint
  equations (:func:`constructions.constraint_kinematics.solve_constraints`) angle by angle, each pose
  started from the previous one (continuation keeps the assembly branch).  The first pose, and the first
  after a gap, starts from the construction (:func:`constructions.linkage.locate`), which is on the branch
  the scene chose.

Where the mechanism cannot be assembled every moving quantity is NaN and ``assembles`` is False: a gap,
never a clamped or borrowed value.
"""

from __future__ import annotations

from dataclasses import dataclass
from types import MappingProxyType
from typing import Mapping

import numpy as np

from . import analytic
from .check import closed_form_parts
from .constraint_kinematics import solve_constraints
from .errors import CannotAssemble, ConstructionError, DegenerateInput, IndeterminatePosition
from .linkage import CircleAndGuide, Mechanism, TwoCircles, locate
from .vector_loops import chain_solution

XY = tuple[np.ndarray, np.ndarray]


@dataclass(frozen=True, eq=False)
class Sweep:
    """A mechanism over crank angles ``thetas`` (rad).

    positions, velocities, accelerations : name -> (x array, y array), m, m/s, m/s^2
    angular, angular_acceleration : link number -> array, rad/s, rad/s^2
    assembles : bool array (False at a gap, where every moving quantity is NaN)
    model : "four-bar", "slider-crank", "dyad chain" or "constraint equations"
    """

    thetas: np.ndarray
    positions: Mapping[str, XY]
    velocities: Mapping[str, XY]
    accelerations: Mapping[str, XY]
    angular: Mapping[int, np.ndarray]
    angular_acceleration: Mapping[int, np.ndarray]
    assembles: np.ndarray
    model: str

    def gaps(self) -> list[tuple[int, int]]:
        """Index ranges [start, stop) of consecutive angles that do not assemble."""
        out: list[tuple[int, int]] = []
        bad = ~self.assembles
        i, n = 0, bad.size
        while i < n:
            if bad[i]:
                j = i
                while j < n and bad[j]:
                    j += 1
                out.append((i, j))
                i = j
            else:
                i += 1
        return out


def _closed_form(m: Mechanism, th: np.ndarray, omega: float, alpha: float, parts) -> Sweep:
    crank, d, fixed = parts
    n = th.size
    O1 = m.ground[crank.pivot]
    b, j = crank.tip, d.joint
    zeros = np.broadcast_to(0.0, (n,))

    def full(v):
        return np.broadcast_to(float(v), (n,))
    pos: dict[str, XY] = {g: (full(p.x), full(p.y)) for g, p in m.ground.items()}
    vel: dict[str, XY] = {g: (zeros, zeros) for g in m.ground}
    acc: dict[str, XY] = {g: (zeros, zeros) for g in m.ground}
    ang: dict[int, np.ndarray] = {crank.link.number: full(omega)}
    alp: dict[int, np.ndarray] = {crank.link.number: full(alpha)}
    theta: dict[int, tuple[str, np.ndarray]] = {crank.link.number: (crank.pivot, th)}
    if isinstance(d, TwoCircles):
        arms = {d.first: d.link_a, d.second: d.link_b}
        o2 = next(c for c in arms if c in m.ground)
        coupler, rocker = arms[b], arms[o2]
        sign = d.branch.sign if d.branch.reference == (b, o2) else -d.branch.sign
        s = analytic.four_bar(th, omega, alpha, crank_pivot=O1.as_tuple(), rocker_pivot=m.ground[o2].as_tuple(),
                              crank=crank.link.length, coupler=coupler.length, rocker=rocker.length, branch=sign)
        model = "four-bar"
        ang[rocker.number], alp[rocker.number] = s.omega3, s.alpha3
        theta[rocker.number] = (o2, s.theta3)
    else:
        coupler = d.link
        s = analytic.slider_crank(th, omega, alpha, crank_pivot=O1.as_tuple(), crank=crank.link.length,
                                  coupler=coupler.length, guide_point=d.slide.through.as_tuple(),
                                  guide_angle=d.slide.angle, branch=d.branch.sign)
        model = "slider-crank"
        ang[d.slide.number], alp[d.slide.number] = zeros, zeros
    pos[b], pos[j] = (s.Bx, s.By), (s.Cx, s.Cy)
    vel[b], vel[j] = (s.VBx, s.VBy), (s.VCx, s.VCy)
    acc[b], acc[j] = (s.ABx, s.ABy), (s.ACx, s.ACy)
    ang[coupler.number], alp[coupler.number] = s.omega2, s.alpha2
    theta[coupler.number] = (b, s.theta2)
    for f in fixed:
        a = f.point
        start, t = theta[a.link]
        direction = t if a.base == start else t + np.pi
        bx, by = pos[a.base]
        p = analytic.coupler_point(bx, by, vel[a.base][0], vel[a.base][1], direction, ang[a.link],
                                   distance=a.distance, angle=a.angle, ABx=acc[a.base][0], ABy=acc[a.base][1],
                                   alpha2=alp[a.link])
        pos[a.name], vel[a.name], acc[a.name] = (p.Dx, p.Dy), (p.VDx, p.VDy), (p.ADx, p.ADy)
    ok = np.asarray(s.assembles, dtype=bool).reshape(n)
    moving = set(pos) - set(m.ground)
    fixed_links = {crank.link.number} | ({d.slide.number} if isinstance(d, CircleAndGuide) else set())
    return _finish(th, pos, vel, acc, ang, alp, ok, model, moving, fixed_links)


def _finish(th, pos, vel, acc, ang, alp, ok, model, moving, fixed_links) -> Sweep:
    """Read-only arrays, NaN for every moving quantity where the mechanism does not assemble.  A solver's
    read-only array of the right shape is shared, not copied, when it needs no NaN."""
    bad = ~np.asarray(ok, dtype=bool)
    gaps = bool(bad.any())
    n = th.size

    def own(a, masked: bool) -> np.ndarray:
        a = np.asarray(a, dtype=np.float64)
        if not (masked and gaps):
            if a.shape == (n,) and not a.flags.writeable:
                return a
            if a.size == 1 or a.strides == (0,):      # a constant (the frame): a read-only view, no memory
                return np.broadcast_to(a.reshape(-1)[:1], (n,))
        a = np.array(np.broadcast_to(a, (n,)), dtype=np.float64)
        if masked:
            a[bad] = np.nan
        a.flags.writeable = False
        return a

    def vec(src):
        return MappingProxyType({name: (own(x, name in moving), own(y, name in moving))
                                 for name, (x, y) in src.items()})

    def sca(src):
        return MappingProxyType({k: own(src[k], k not in fixed_links) for k in sorted(src)})

    ok = ~bad
    ok.flags.writeable = False
    return Sweep(own(th, False), vec(pos), vec(vel), vec(acc), sca(ang), sca(alp), ok, model)


def _constraints(m: Mechanism, th: np.ndarray, omega: float, alpha: float) -> Sweep:
    n = th.size
    states: list = [None] * n
    guess = None
    for i, t in enumerate(th):
        t = float(t)
        if guess is None:                      # first angle, or after a gap: the scene's branch
            try:
                guess = locate(m, t).positions
            except ConstructionError:
                continue
        try:
            st = solve_constraints(m, t, omega, alpha, guess)
        except (CannotAssemble, IndeterminatePosition):
            guess = None
            continue
        states[i] = st
        guess = st.positions
    ok = np.array([s is not None for s in states], dtype=bool)
    first = next((s for s in states if s is not None), None)
    names = list(first.positions) if first else list(m.ground)
    numbers = sorted(first.angular) if first else [m.crank]

    def vectors(attr):
        out = {}
        for name in names:
            x, y = np.full(n, np.nan), np.full(n, np.nan)
            for i, s in enumerate(states):
                if s is not None:
                    v = getattr(s, attr)[name]
                    x[i], y[i] = v.x, v.y
            out[name] = (x, y)
        return out

    def scalars(attr):
        out = {}
        for k in numbers:
            w = np.full(n, np.nan)
            for i, s in enumerate(states):
                if s is not None:
                    w[i] = getattr(s, attr)[k]
            out[k] = w
        return out

    pos = vectors("positions")
    for g, p in m.ground.items():                 # fixed pivots are there at every angle, gaps too
        pos[g] = (np.full(n, p.x), np.full(n, p.y))
    vel, acc = vectors("velocities"), vectors("accelerations")
    for g in m.ground:
        vel[g] = acc[g] = (np.zeros(n), np.zeros(n))
    return _finish(th, pos, vel, acc, scalars("angular"), scalars("angular_acceleration"), ok,
                   "constraint equations", set(names) - set(m.ground), set())   # every body is NaN at a gap


def sweep(m: Mechanism, thetas, omega: float, alpha: float = 0.0) -> Sweep:
    """Solve ``m`` at every crank angle of ``thetas`` (rad) with the crank turning at ``omega`` (rad/s)
    and angular acceleration ``alpha`` (rad/s^2).  Raises DegenerateInput for a mechanism none of the
    solvers models (e.g. not one degree of freedom)."""
    th = np.array(thetas, dtype=np.float64).reshape(-1)
    omega, alpha = float(omega), float(alpha)
    parts = closed_form_parts(m)
    if parts is not None:
        return _closed_form(m, th, omega, alpha, parts)
    try:
        st = chain_solution(m, th, omega, alpha)
    except DegenerateInput:
        return _constraints(m, th, omega, alpha)
    ok = np.asarray(st.assembles, dtype=bool).reshape(-1)
    fixed_links = {m.crank} | {s.number for s in m.slides if s.number is not None and s.on is None}
    return _finish(th, dict(st.positions), dict(st.velocities), dict(st.accelerations), dict(st.angular),
                   dict(st.angular_acceleration), ok, "dyad chain", set(st.positions) - set(m.ground),
                   fixed_links)
