"""A mechanism over many crank angles: positions, velocities and accelerations of every joint and point,
angular velocities and accelerations of every link (SI, CCW positive).

The solver is chosen as :func:`constructions.check.analytic_solution` chooses it, but over arrays:

- a plain four-bar or slider-crank (one dyad hung from the crank tip and the frame, points fixed to its
  links): the closed forms of :mod:`constructions.analytic` as the fast kernels of
  :mod:`constructions.sweep_kernels` run them;
- any other crank followed by RRR/RRP dyads: :func:`constructions.analytic.chain_solution`, in chunks
  (:func:`constructions.sweep_kernels.chain_sweep`);
- anything else (a slot in a moving link, a ternary link joined at its third point): the constraint
  equations, each pose continued from the previous one (continuation keeps the assembly branch), a block
  of angles at a time (:func:`constructions.mechanisms.constraint_continuation.continue_constraints`).
  The first pose, and the first after a gap, starts from the construction
  (:func:`constructions.mechanisms.pose.locate`), which is on the branch the scene chose.

Where the mechanism cannot be assembled every moving quantity is NaN and ``assembles`` is False: a gap,
never a clamped or borrowed value.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from types import MappingProxyType

import numpy as np

from . import sweep_kernels
from .closed_forms import closed_form_parts, closed_form_state
from .errors import DegenerateInput
from .geometry import Vec
from .mechanisms.constraint_continuation import continue_constraints
from .mechanisms.model import Mechanism, place_rigid
from .motion_arrays import MotionArrays
from .sweep_kernels import chain_sweep


@dataclass(frozen=True, eq=False)
class Sweep(MotionArrays):
    """A mechanism over crank angles ``thetas`` (rad).

    positions, velocities, accelerations : name -> (x array, y array), m, m/s, m/s^2
    angular, angular_acceleration : link number -> array, rad/s, rad/s^2
    assembles : bool array (False at a gap, where every moving quantity is NaN)
    model : "four-bar", "slider-crank", "dyad chain" or "constraint equations"
    """

    change_points: tuple[float, ...] = ()
    """Crank angles (rad) where the linkage passed a change point (all links in line, the two assemblies
    meeting) and stayed on its branch: the continuation whose velocities run on smoothly."""

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
    c = closed_form_state(m, th, omega, alpha, parts, sweep_kernels)
    return _finish(th, dict(c.positions), dict(c.velocities), dict(c.accelerations), dict(c.angular),
                   dict(c.angular_acceleration), c.assembles, c.model, set(c.positions) - set(m.ground),
                   set(c.fixed_links))


CHANGE_STEP = 1e-5
"""Half the angle (rad) about a change point over which the velocities of the two ways on are compared."""


def _through_change_points(m: Mechanism, th: np.ndarray, omega: float, alpha: float, parts, own: Sweep) -> Sweep:
    """A change-point four-bar (s + l = p + q) keeps its branch through the positions where all its links
    lie in line.  There the two assemblies meet and a fixed assembly sign (the scene's "left of B->O2")
    would jump to the other one -- a parallelogram would turn into an antiparallelogram.  At each such
    crank angle (the crank along the frame line) the continuation is the assembly whose joint velocities,
    just past it, are nearest those just before it; the sweep follows it, and says where it did."""
    from dataclasses import replace as _replace
    from .mechanisms.classify import classify_four_bar
    from .mechanisms.model import Branch
    k = classify_four_bar(m)
    if k is None or k.grashof != "change point" or th.size == 0:
        return own
    o1, _, c, o2 = k.joints
    if o1 not in m.ground or o2 not in m.ground or c not in m.branches:
        return own
    b = m.branches[c]
    flipped = _replace(m, branches={**m.branches, c: Branch(-b.sign, b.reference)})
    other = _closed_form(flipped, th, omega, alpha, closed_form_parts(flipped))
    frame = m.ground[o2] - m.ground[o1]
    phi = math.atan2(frame.y, frame.x)
    lo, hi = float(th.min()), float(th.max())
    forward = th.size < 2 or th[-1] >= th[0]
    crossings = sorted(a for j in range(math.floor((lo - phi) / math.pi) - 1, math.ceil((hi - phi) / math.pi) + 2)
                       for a in [phi + j * math.pi] if lo < a < hi)
    if not forward:
        crossings.reverse()
    which = 0                                            # the assembly followed now: 0 the scene's own
    use = np.zeros(th.size, dtype=bool)
    passed = []
    step = CHANGE_STEP if forward else -CHANGE_STEP
    for a in crossings:
        before = sweep_at(m if which == 0 else flipped, a - step, omega, alpha)
        after = [sweep_at(x, a + step, omega, alpha) for x in (m, flipped)]
        if before is None or any(x is None for x in after):
            continue
        jump = [sum((x[n] - before[n]).norm() for n in before) for x in after]
        which = 0 if jump[0] <= jump[1] else 1
        passed.append(a)
        beyond = th > a if forward else th < a
        use[beyond] = which == 1
    if not use.any():
        return _replace(own, change_points=tuple(passed))

    def vectors(kind):
        mine, theirs = getattr(own, kind), getattr(other, kind)
        return {n: tuple(np.where(use, t, o) for o, t in zip(mine[n], theirs[n])) for n in mine}

    def scalars(kind):
        mine, theirs = getattr(own, kind), getattr(other, kind)
        return {n: np.where(use, theirs[n], mine[n]) for n in mine}
    pos, vel, acc = vectors("positions"), vectors("velocities"), vectors("accelerations")
    ang, alp = scalars("angular"), scalars("angular_acceleration")
    ok = np.where(use, other.assembles, own.assembles)
    moving = set(own.positions) - set(m.ground)
    out = _finish(th, pos, vel, acc, ang, alp, ok, own.model, moving, {m.crank})
    return _replace(out, change_points=tuple(passed))


def sweep_at(m: Mechanism, theta: float, omega: float, alpha: float):
    """The joint velocities of the plain four-bar ``m`` at one crank angle (None where it does not
    assemble)."""
    from .geometry import Vec
    st = closed_form_state(m, np.array([theta]), omega, alpha, closed_form_parts(m), sweep_kernels)
    if not bool(np.asarray(st.assembles).reshape(-1)[0]):
        return None
    return {n: Vec(float(np.asarray(x).reshape(-1)[0]), float(np.asarray(y).reshape(-1)[0]))
            for n, (x, y) in st.velocities.items() if n not in m.ground}


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


def _constraints(m: Mechanism, th: np.ndarray, omega: float, alpha: float, progress=None) -> Sweep:
    t = continue_constraints(m, th, omega, alpha, progress)
    n = th.size
    names = list(t.positions) or list(m.ground)
    pos = {name: t.positions.get(name) or (np.full(n, np.nan), np.full(n, np.nan)) for name in names}
    vel = {name: t.velocities.get(name) or (np.full(n, np.nan), np.full(n, np.nan)) for name in names}
    acc = {name: t.accelerations.get(name) or (np.full(n, np.nan), np.full(n, np.nan)) for name in names}
    ang = t.angular or {m.crank: np.full(n, np.nan)}
    alp = t.angular_acceleration or {m.crank: np.full(n, np.nan)}
    for g, p in m.ground.items():                 # fixed pivots are there at every angle, gaps too
        pos[g] = (np.full(n, p.x), np.full(n, p.y))
        vel[g] = acc[g] = (np.zeros(n), np.zeros(n))
    return _finish(th, pos, vel, acc, ang, alp, t.assembles, "constraint equations", set(names) - set(m.ground),
                   set())                                            # every body is NaN at a gap


def crank_points(m: Mechanism, theta: float) -> dict[str, Vec] | None:
    """The crank's points (SI) at crank angle ``theta``: its ground joint fixed, the link turned so that
    its other joint lies at ``theta`` from it -- what a drawing shows at a gap, where nothing else stands."""
    k = m.link(m.crank)
    g = next((j for j in k.joints if j in m.ground), None)
    if g is None:
        return None
    local = m.local(m.crank)
    G = m.ground[g]
    return {n: place_rigid(local, g, k.other(g), G, G + Vec.polar(k.length, theta), n) for n in local}


def sweep(m: Mechanism, thetas, omega: float, alpha: float = 0.0, *, progress=None) -> Sweep:
    """Solve ``m`` at every crank angle of ``thetas`` (rad) with the crank turning at ``omega`` (rad/s)
    and angular acceleration ``alpha`` (rad/s^2).  ``progress(done, total)``, if given, hears how far the
    constraint continuation has come, every block of angles (the vectorised solvers finish in one
    stroke).  Raises DegenerateInput for a mechanism none of the solvers models (e.g. not one degree of
    freedom)."""
    th = np.array(thetas, dtype=np.float64).reshape(-1)
    omega, alpha = float(omega), float(alpha)
    parts = closed_form_parts(m)
    if parts is not None:
        return _through_change_points(m, th, omega, alpha, parts, _closed_form(m, th, omega, alpha, parts))
    try:
        st = chain_sweep(m, th, omega, alpha)
    except DegenerateInput:
        return _constraints(m, th, omega, alpha, progress)
    ok = np.asarray(st.assembles, dtype=bool).reshape(-1)
    fixed_links = {m.crank} | {s.number for s in m.slides if s.number is not None and s.on is None}
    return _finish(th, dict(st.positions), dict(st.velocities), dict(st.accelerations), dict(st.angular),
                   dict(st.angular_acceleration), ok, "dyad chain", set(st.positions) - set(m.ground),
                   fixed_links)
