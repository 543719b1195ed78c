"""The independent analytic checks of force analysis: the global equilibrium system and virtual work.

:func:`equilibrium` writes the equations of every moving body at once -- sum Fx = 0, sum Fy = 0 and the
sum of moments about the body's first point = 0, D'Alembert inertia included -- and solves them for the
joint forces and the driving torque.  The unknowns follow the shared topology of :mod:`.bodies`: two
components per :class:`Pin` (the force of the carrier on the other body; the carrier gets minus it),
the normal force and the placing couple per :class:`Contact`, the normal force per :class:`SlotPin`,
and the driving torque on the crank.  For a 1-DoF mechanism Gruebler's count makes the system square.

:func:`virtual_work_torque` finds the driving torque from the power balance alone (no joint forces), with
the virtual velocities of the crank turning at 1 rad/s; :func:`alpha_for_torque` the crank's angular
acceleration at which the driving torque takes a given value (the motion released from rest).

Sign conventions: angles CCW from +x, torques and couples CCW positive, SI throughout.  Positions,
velocities and accelerations come from :func:`constructions.check.analytic_solution` (the vector loops, or
the constraint equations for slots in moving links), never from the graphical construction's values;
accelerations are asked for only when some body has mass.
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass, field
from typing import Mapping

import numpy as np

from ..check import AnalyticSolution, NotModelled, analytic_solution
from ..errors import CannotAssemble, DegenerateInput, IndeterminatePosition
from ..geometry import Vec
from ..mechanisms.assembly import CrankTip, FixedToLink, assembly_plan
from ..mechanisms.model import Mechanism, describe_angle, slide_line
from ..mechanisms.pose import locate
from ..mechanisms.topology import Connection, Contact, Pin, SlotPin, connections, moving_bodies, points_of_body
from ..tolerance import NEGLIGIBLE, SIGN_SLACK, SINGULAR_RCOND
from .bodies import force_name, torque_name
from .dalembert import InertiaLoad, friction_rows, inertia_loads, inertia_rows
from .effects import Effects

ZERO = Vec(0.0, 0.0)


@dataclass(frozen=True)
class Equilibrium:
    """The joint forces and the driving torque that hold every moving body in (dynamic) equilibrium.

    ``pins`` maps each pin to the force of its carrier on the other body (N); ``contacts`` maps each
    slide to the total force of the guide body on the block or pin carrier (normal plus friction) and the
    couple of the guide on the block (N m, 0 for a pin in a slot); ``friction`` holds the friction part of
    that force where friction acts; ``torque`` is the driving torque on the crank by the frame (CCW+);
    ``condition`` the reciprocal condition number of the row- and column-scaled system; ``warnings``
    names the slides whose friction was left out because nothing slides there; ``inertia`` each massive
    body's inertia force and couple from the analytic accelerations."""

    pins: Mapping[Pin, Vec]
    contacts: Mapping[Contact | SlotPin, tuple[Vec, float]]
    torque: float
    condition: float
    friction: Mapping[Contact | SlotPin, Vec] = field(default_factory=dict)
    warnings: tuple[str, ...] = ()
    inertia: tuple[InertiaLoad, ...] = ()

    def values(self, m: Mechanism) -> dict[str, Vec | float]:
        """Every force under the notes' names, both ways round (F_ji = -F_ij), the driving torque, the inertia
        forces and couples and the friction forces."""
        out: dict[str, Vec | float] = {}
        for p, f in self.pins.items():
            out[force_name(p.carrier, p.other)] = f
            out[force_name(p.other, p.carrier)] = -f
        for c, (f, _) in self.contacts.items():
            on = c.block if isinstance(c, Contact) else c.carrier
            out[force_name(c.guide, on)] = f
            out[force_name(on, c.guide)] = -f
        out[torque_name(m)] = self.torque
        out.update((x.name, x.value) for x in inertia_rows(self.inertia) + friction_rows(self.friction))
        return out


# -- kinematics -------------------------------------------------------------------------------------------

def motion(m: Mechanism, angle: float, omega: float, alpha: float, *, accelerations: bool = True,
               guess: Mapping[str, Vec] | None = None) -> AnalyticSolution:
    """The analytic motion at ``angle``: the vector loops, or the constraint equations from ``guess`` (the
    construction's pose when none is given), or -- for a lone crank -- rigid rotation about its pivot."""
    try:
        sol = analytic_solution(m, angle, omega, alpha, accelerations=accelerations, guess=guess)
    except NotModelled:
        if all(isinstance(s, (CrankTip, FixedToLink)) for s in assembly_plan(m)):
            return _rigid_crank(m, angle, omega, alpha, accelerations)
        if guess is not None:
            raise
        guess = dict(locate(m, angle).positions)
        sol = analytic_solution(m, angle, omega, alpha, accelerations=accelerations, guess=guess)
    if sol is None:
        raise CannotAssemble("the mechanism does not assemble here", position=describe_angle(angle))
    return sol


def _rigid_crank(m: Mechanism, angle: float, omega: float, alpha: float, accelerations: bool) -> AnalyticSolution:
    """A crank alone turns about its pivot: its base line (pivot to tip) stands at ``angle``;
    v = omega k x r, a = alpha k x r - omega^2 r."""
    step = assembly_plan(m)[0]
    local = m.local(step.link.number)
    turn = angle - (local[step.tip] - local[step.pivot]).angle()
    o = m.ground[step.pivot]
    r = {x: (p - local[step.pivot]).rotated(turn) for x, p in local.items()}
    n = step.link.number
    acc = {x: q.perp() * alpha - q * (omega * omega) for x, q in r.items()}
    vel = {x: q.perp() * omega for x, q in r.items()}
    return AnalyticSolution("rigid crank", {x: o + q for x, q in r.items()}, vel, {n: omega},
                            acc if accelerations else None, {n: alpha} if accelerations else None)


def _body_rate(m: Mechanism, body: int, rates: Mapping[int, float]) -> float:
    """Angular velocity (or acceleration) of a body: a link's own; a block turns with its slot, or not at
    all on a fixed guide."""
    blocks = m.blocks()
    if body in blocks:
        on = blocks[body].on
        return 0.0 if on is None else rates[on]
    return rates[body]


def _guide_point_velocity(m: Mechanism, c: Contact | SlotPin, kin: AnalyticSolution) -> Vec:
    """Velocity of the guide body's point under the sliding joint (zero on the frame)."""
    if c.slide.on is None:
        return ZERO
    q = m.link(c.slide.on).joints[0]
    r = kin.positions[c.joint] - kin.positions[q]
    return kin.velocities[q] + r.perp() * kin.angular[c.slide.on]


# -- the effects, as forces and couples on bodies ---------------------------------------------------------

def applied(m: Mechanism, effects: Effects, kin: AnalyticSolution) -> list[tuple[int, str | None, Vec, float]]:
    """Every known force and couple as (body, point it acts at or None, force, couple): the loads and
    couples, the spring tensions k (L - L0) pulling the two ends together, the weights m g at the centres
    (only when gravity is set) and the D'Alembert forces -m a_G and couples -I_G alpha (bodies with mass)."""
    bodies = set(moving_bodies(m))
    out: list[tuple[int, str | None, Vec, float]] = []

    def on(body: int | None, at: str | None) -> None:
        if body not in bodies:
            raise DegenerateInput(f"body {body} is not a moving link or slider block")
        if at is not None and at not in kin.positions:
            raise DegenerateInput(f"point {at} of body {body} is not a point of the mechanism")
    for ld in effects.loads:
        on(ld.body, ld.at)
        out.append((ld.body, ld.at, ld.force, 0.0))
    for c in effects.couples:
        on(c.body, None)
        out.append((c.body, None, ZERO, c.torque))
    for s in effects.springs:
        ends = []
        for e in (s.a, s.b):
            if e.body is None:
                ends.append(effects.fixed[e.at] if e.at in effects.fixed else m.ground[e.at])
            else:
                on(e.body, e.at)
                ends.append(kin.positions[e.at])
        pull = s.pull(ends[0], ends[1])                        # on end a, towards b
        for e, f in ((s.a, pull), (s.b, -pull)):
            if e.body is not None:
                out.append((e.body, e.at, f, 0.0))
    for ms in effects.masses:
        on(ms.body, ms.centre)
        if effects.gravity is not None:
            out.append((ms.body, ms.centre, effects.gravity * ms.mass, 0.0))
        if kin.accelerations is None or kin.angular_acceleration is None:
            raise DegenerateInput("inertia forces need the accelerations")
        out.append((ms.body, ms.centre, kin.accelerations[ms.centre] * -ms.mass,
                    -ms.inertia * _body_rate(m, ms.body, kin.angular_acceleration)))
    return out


def _real_motion(m, angle, omega, alpha, effects, given, guess) -> AnalyticSolution:
    """The kinematics given, or found -- with accelerations only when some body has mass."""
    if given is not None and (given.accelerations is not None or not effects.inertial):
        return given
    return motion(m, angle, omega, alpha, accelerations=effects.inertial, guess=guess)


# -- the global system ------------------------------------------------------------------------------------

def equilibrium(m: Mechanism, angle: float, omega: float, alpha: float, effects: Effects, *,
                kinematics: AnalyticSolution | None = None, guess: Mapping[str, Vec] | None = None) -> Equilibrium:
    """Joint forces and driving torque from the equations of equilibrium of all moving bodies at once.

    Coulomb friction (blocks in ``effects.friction`` by number, pins in slots by joint name) acts along the
    guide, mu |N| against the sliding velocity; |N| is non-linear, so the sign of each N is assumed, the
    linear system solved, and the signs flipped until they agree (every sign set is tried before
    giving up: then the mechanism locks).  Where nothing slides, friction is left out with a warning.
    Raises IndeterminatePosition (kind "toggle") where the system is singular."""
    kin = _real_motion(m, angle, omega, alpha, effects, kinematics, guess)
    P = kin.positions
    bodies = moving_bodies(m)
    row = {b: 3 * i for i, b in enumerate(bodies)}
    ref = {b: P[points_of_body(m, b)[0]] for b in bodies}
    conns = connections(m)
    ncol = sum(2 if isinstance(c, (Pin, Contact)) else 1 for c in conns) + 1
    A = np.zeros((3 * len(bodies), ncol))
    rhs = np.zeros(3 * len(bodies))

    def put(M: np.ndarray, col: int | None, body: int, force: Vec, at: Vec, couple: float, k: float = 1.0) -> None:
        if body not in row:                                    # the frame: no equations
            return
        i = row[body]
        v = M[:, col] if col is not None else M
        v[i] += k * force.x
        v[i + 1] += k * force.y
        v[i + 2] += k * ((at - ref[body]).cross(force) + couple)

    for body, at, f, c in applied(m, effects, kin):            # A x + known = 0
        put(rhs, None, body, f, P[at] if at else ref[body], c, -1.0)
    cols: dict[Connection, int] = {}
    normals: dict[Connection, tuple[Vec, Vec]] = {}
    j = 0
    for c in conns:
        cols[c] = j
        at = P[c.joint]
        if isinstance(c, Pin):
            for k, e in enumerate((Vec(1.0, 0.0), Vec(0.0, 1.0))):
                put(A, j + k, c.other, e, at, 0.0)
                put(A, j + k, c.carrier, -e, at, 0.0)
            j += 2
            continue
        t = slide_line(m, c.slide, P).direction
        normals[c] = (t.perp(), t)
        on = c.block if isinstance(c, Contact) else c.carrier
        put(A, j, on, t.perp(), at, 0.0)
        put(A, j, c.guide, -t.perp(), at, 0.0)
        if isinstance(c, Contact):
            put(A, j + 1, on, ZERO, at, 1.0)
            put(A, j + 1, c.guide, ZERO, at, -1.0)
        j += 2 if isinstance(c, Contact) else 1
    put(A, j, m.crank, ZERO, ref[m.crank], 1.0)

    # friction: (contact, mu, direction of the sliding velocity along t)
    warnings: list[str] = []
    rubbing: list[tuple[Connection, float, float]] = []
    scale = abs(omega) * m.size
    for c in conns:
        key = c.block if isinstance(c, Contact) else c.joint if isinstance(c, SlotPin) else None
        mu = effects.friction.get(key) if key is not None else None   # type: ignore[arg-type]
        if not mu:
            continue
        slip = (kin.velocities[c.joint] - _guide_point_velocity(m, c, kin)).dot(normals[c][1])
        if abs(slip) <= NEGLIGIBLE * scale:
            warnings.append(f"{c.slide.label} does not slide here ({describe_angle(angle)}): the friction "
                            f"force is undetermined and left out")
            continue
        rubbing.append((c, mu, math.copysign(1.0, slip)))

    def solve(signs: tuple[float, ...]) -> tuple[np.ndarray, float]:
        B = A.copy()
        for (c, mu, sg), s in zip(rubbing, signs):            # friction -mu s N sg t, linear in N
            on = c.block if isinstance(c, Contact) else c.carrier
            put(B, cols[c], on, normals[c][1], P[c.joint], 0.0, -mu * s * sg)
            put(B, cols[c], c.guide, normals[c][1], P[c.joint], 0.0, mu * s * sg)
        return _solve(B, rhs, m.size, angle)

    def consistent(signs: tuple[float, ...]) -> tuple[np.ndarray, float, tuple[float, ...]]:
        x, rcond = solve(signs)                                # a normal force within rounding of
        tiny = SIGN_SLACK * float(np.max(np.abs(x[:-1]), initial=0.0))   # zero agrees with either sign
        return x, rcond, tuple(s if x[cols[c]] * s >= -tiny else -s for (c, _, _), s in zip(rubbing, signs))

    signs = tuple(1.0 for _ in rubbing)
    x, rcond, got = consistent(signs)                          # without friction's sign: a first guess
    tried: list[tuple[float, ...]] = [signs]
    while got != signs and got not in tried:                   # flip and resolve
        signs = got
        tried.append(signs)
        x, rcond, got = consistent(signs)
    for other in itertools.product((1.0, -1.0), repeat=len(rubbing)):   # then every other sign set
        if got == signs:
            break
        if other not in tried:
            signs = other
            x, rcond, got = consistent(signs)
    if got != signs:
        raise IndeterminatePosition(f"no direction of the normal forces at "
                                    f"{', '.join(c.slide.label for c, _, _ in rubbing)} agrees with the "
                                    f"friction they cause: the mechanism locks", position=describe_angle(angle),
                                    kind="friction lock", condition=rcond)
    along = {c: -mu * s * sg for (c, mu, sg), s in zip(rubbing, signs)}    # friction per unit N
    pins: dict[Pin, Vec] = {}
    contacts: dict[Connection, tuple[Vec, float]] = {}
    friction: dict[Connection, Vec] = {}
    for c in conns:
        i = cols[c]
        if isinstance(c, Pin):
            pins[c] = Vec(float(x[i]), float(x[i + 1]))
            continue
        n, t = normals[c]
        if c in along:
            friction[c] = t * (along[c] * float(x[i]))
        contacts[c] = (n * float(x[i]) + friction.get(c, ZERO), float(x[i + 1]) if isinstance(c, Contact) else 0.0)
    inertia = inertia_loads(effects, kin.accelerations, lambda b: _body_rate(m, b, kin.angular_acceleration)
                            ) if effects.inertial else ()
    return Equilibrium(pins, contacts, float(x[-1]), rcond, friction, tuple(warnings), inertia)


def _solve(A: np.ndarray, rhs: np.ndarray, size: float, angle: float) -> tuple[np.ndarray, float]:
    """Solve A x = rhs with the moment rows divided by the scene size and every column scaled to unit
    length, so that the condition number measures the geometry, not the units."""
    if A.shape[0] != A.shape[1]:
        raise DegenerateInput(f"the equilibrium system has {A.shape[0]} equations for {A.shape[1]} unknowns; "
                              f"only a mechanism of one degree of freedom is determinate")
    w = np.ones(A.shape[0])
    w[2::3] = 1.0 / size
    B = A * w[:, None]
    norms = np.linalg.norm(B, axis=0)
    norms[norms == 0.0] = 1.0
    B = B / norms
    rcond = 1.0 / float(np.linalg.cond(B))
    if not math.isfinite(rcond) or rcond < SINGULAR_RCOND:
        raise IndeterminatePosition(f"toggle: the equilibrium equations are singular (reciprocal condition "
                                    f"{rcond:.1e}): two unknown forces act along one line, so the joint forces "
                                    f"are not determined", position=describe_angle(angle), kind="toggle",
                                    condition=rcond)
    return np.linalg.solve(B, rhs * w) / norms, rcond


# -- virtual work -----------------------------------------------------------------------------------------

def virtual_work_torque(m: Mechanism, angle: float, omega: float, alpha: float, effects: Effects, *,
                        kinematics: AnalyticSolution | None = None,
                        friction: Mapping[Connection, Vec] | None = None,
                        guess: Mapping[str, Vec] | None = None) -> float:
    """The driving torque from the power balance, T w + sum F.v + sum C w_body = 0, over the known forces
    and couples of :func:`applied` (loads, springs, weights, inertia) with the virtual velocities of the
    crank turning at 1 rad/s -- so it holds at rest as well; the inertia forces use the real accelerations.
    No joint force enters: pins and normal forces do no work.  Friction does: pass ``friction`` (slide ->
    friction force of the guide on the block or pin, e.g. :attr:`Equilibrium.friction`); the torque is then
    no longer independent of the linear system that found those forces."""
    kin = _real_motion(m, angle, omega, alpha, effects, kinematics, guess)
    vir = motion(m, angle, 1.0, 0.0, accelerations=False,
                 guess=guess if guess is not None else dict(kin.positions))
    power = 0.0
    for body, at, f, c in applied(m, effects, kin):
        if at is not None:
            power += f.dot(vir.velocities[at])
        power += c * _body_rate(m, body, vir.angular)
    for c, f in (friction or {}).items():
        power += f.dot(vir.velocities[c.joint] - _guide_point_velocity(m, c, vir))
    return -power / vir.angular[m.crank]


def alpha_for_torque(m: Mechanism, angle: float, omega: float, effects: Effects, torque: float = 0.0, *,
                     guess: Mapping[str, Vec] | None = None, by: str = "equilibrium") -> float:
    """The crank's angular acceleration at which the driving torque equals ``torque`` (0: the mechanism
    moves freely, e.g. released from rest).  The torque is affine in alpha (the accelerations are), so two
    evaluations fix it and a third refines the root.  ``by`` chooses whose torque: "equilibrium" (the
    linear system of all links) or "virtual work" (the power balance), two independent routes to the same
    alpha.  With friction it is affine only while the normal forces keep their directions."""
    def t(al: float) -> float:
        if by == "virtual work":
            eq = equilibrium(m, angle, omega, al, effects, guess=guess) if effects.friction else None
            return virtual_work_torque(m, angle, omega, al, effects, guess=guess,
                                       friction=eq.friction if eq is not None else None)
        return equilibrium(m, angle, omega, al, effects, guess=guess).torque
    if by not in ("equilibrium", "virtual work"):
        raise ValueError(f"by must be 'equilibrium' or 'virtual work', not {by!r}")
    t0, t1 = t(0.0), t(1.0)
    slope = t1 - t0
    if not effects.inertial or slope == 0.0:
        raise DegenerateInput("the driving torque does not depend on the crank's angular acceleration: no "
                              "body with mass moves with the crank")
    al = (torque - t0) / slope
    return al - (t(al) - torque) / slope
