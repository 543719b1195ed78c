"""Gear trains: simple (with idlers), compound, reverted and planetary, solved as the notes teach.

A train is gears on *members* (shafts; gears on one member turn together: a compound gear), each gear's
axis held by the frame or by one carrier (the arm of a planetary train), and meshes between pairs of
gears (external, or internal when one of the two is an internal gear, a ring).  Speeds relative to the
carrier pass along the meshes by the teeth (the notes' rule: -N_a/N_b for two external gears,
+N_a/N_b with an internal one), so every member turns, relative to the carrier, at e_m times the
reference member's relative speed x (e_ref = 1, the carrier 0).  The notes' planetary formula
(n_out - n_c)/(n_in - n_c) = e_out/e_in (the train value, the signed product of driving over driven
teeth) and the *tabular method* are then one table: row 1, the carrier held and the reference member
turned x; row 2, everything locked and turned with the carrier n_c; each member's speed the sum
n_c + e_m x.  Two members given (one fixed, one driven; an ordinary train has the frame as its carrier and
one given) fix x and n_c.  Tooth loads from a power P: each member's torque by the balance of power and
of torques (T_in = P/omega_in, T_out = -P/omega_out, the fixed member's reaction -(T_in + T_out)), the
tangential tooth load W_t = |T|/r at a mesh with a member that meshes only there (|T|/(n r) at a planet's
mesh, n planets sharing the load equally), W_r = W_t tan(phi), W = W_t/cos(phi).  Whether n planets can
be assembled and clear each other is :mod:`constructions.gears.planets`.  The independent check is :mod:`constructions.gears.train_check`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from ..errors import ConstructionError, DegenerateInput
from ..geometry import Vec
from ..tolerance import DECISION, STANDSTILL, TRAIN_RATIO_REL

FRAME = "frame"


@dataclass(frozen=True)
class TrainGear:
    name: str
    teeth: int
    member: str
    carrier: str = FRAME           # the member holding the gear's axis
    internal: bool = False


@dataclass(frozen=True)
class TrainMesh:
    a: str
    b: str
    angle: float | None = None     # direction from gear a's centre to the pitch point (rad); None: default

    @property
    def name(self) -> str:
        return f"{self.a}-{self.b}"


@dataclass(frozen=True)
class Train:
    gears: tuple[TrainGear, ...]
    meshes: tuple[TrainMesh, ...]
    module: float
    pressure_angle: float
    coaxial: tuple[tuple[str, str], ...] = ()     # members whose axes must coincide (reverted trains)
    planets: int = 1                              # planets spaced equally round the carrier (each carries the load / n)
    addendum: float = 1.0                         # the addendum constant in modules (a planet's tip radius r + a m)

    def __post_init__(self) -> None:
        names = [g.name for g in self.gears]
        if len(set(names)) != len(names):
            raise DegenerateInput("two gears share a name")
        for m in self.meshes:
            for n in (m.a, m.b):
                if n not in names:
                    raise DegenerateInput(f"mesh {m.name}: no gear {n}")
            ga, gb = self.gear(m.a), self.gear(m.b)
            if ga.internal and gb.internal:
                raise DegenerateInput(f"mesh {m.name}: two internal gears cannot mesh")
            if ga.carrier != gb.carrier and FRAME not in (ga.carrier, gb.carrier):
                raise DegenerateInput(f"mesh {m.name}: gears on two different carriers")
            if ga.internal and ga.teeth <= gb.teeth or gb.internal and gb.teeth <= ga.teeth:
                raise DegenerateInput(f"mesh {m.name}: an internal gear needs more teeth than the gear inside it")
        carriers = {g.carrier for g in self.gears} - {FRAME}
        if len(carriers) > 1:
            raise DegenerateInput(f"more than one carrier ({', '.join(sorted(carriers))}); this version solves one")
        for c in carriers:
            if c in {g.member for g in self.gears}:
                raise DegenerateInput(f"{c} is a carrier and also carries gears on it as a shaft")
        if self.planets < 1 or self.planets > 1 and not carriers:
            raise DegenerateInput(f"{self.planets} planets: a train with a carrier has one or more planets, "
                                  f"an ordinary train none")

    def gear(self, name: str) -> TrainGear:
        return next(g for g in self.gears if g.name == name)

    @property
    def carrier(self) -> str:
        cs = {g.carrier for g in self.gears} - {FRAME}
        return next(iter(cs)) if cs else FRAME

    @property
    def planetary(self) -> bool:
        return self.carrier != FRAME

    @property
    def members(self) -> tuple[str, ...]:
        out = list(dict.fromkeys(g.member for g in self.gears))
        if self.planetary:
            out.append(self.carrier)
        return tuple(out)

    def radius(self, g: TrainGear) -> float:
        return self.module * g.teeth / 2.0

    def internal_mesh(self, m: TrainMesh) -> bool:
        return self.gear(m.a).internal or self.gear(m.b).internal

    def carried_mesh(self, m: TrainMesh) -> bool:
        """Whether a gear of mesh ``m`` rides on the carrier (the mesh is repeated at every planet)."""
        return FRAME != self.gear(m.a).carrier or FRAME != self.gear(m.b).carrier

    def meshes_of(self, member: str) -> list[TrainMesh]:
        return [m for m in self.meshes if member in (self.gear(m.a).member, self.gear(m.b).member)]


@dataclass(frozen=True)
class Given:
    member: str
    speed: float                   # rad/s, CCW positive (0: fixed)


@dataclass
class TrainSolution:
    train: Train
    reference: str
    values: dict[str, float]            # e_m: member speed relative to the carrier per unit of the reference's
    carrier_speed: float
    x: float                            # the reference member's speed relative to the carrier
    speeds: dict[str, float]
    givens: tuple[Given, ...]
    mesh_ratio: dict[str, float] = field(default_factory=dict)      # signed ratio n_b/n_a relative to the carrier
    torques: dict[str, float] | None = None
    loads: dict[str, float] | None = None                            # W_t per mesh
    power: float | None = None
    inp: str | None = None
    out: str | None = None

    def train_value(self, frm: str, to: str) -> float:
        """(n_to - n_c)/(n_frm - n_c): the notes' train value e from one member to another."""
        return self.values[to] / self.values[frm]


def relative_values(train: Train, reference: str) -> tuple[dict[str, float], dict[str, float]]:
    """e_m for every member (relative to the carrier, per unit of the reference member), passed along the
    meshes by the teeth; and each mesh's signed ratio.  A loop of meshes that disagrees is an error (the
    train would lock)."""
    vals: dict[str, float] = {reference: 1.0}
    ratios: dict[str, float] = {}
    if train.planetary:
        vals[train.carrier] = 0.0
    changed = True
    while changed:
        changed = False
        for m in train.meshes:
            ga, gb = train.gear(m.a), train.gear(m.b)
            r = (1.0 if train.internal_mesh(m) else -1.0) * ga.teeth / gb.teeth
            ratios[m.name] = r
            for g1, g2, k in ((ga, gb, r), (gb, ga, 1.0 / r)):
                if g1.member in vals and g2.member not in vals:
                    vals[g2.member] = vals[g1.member] * k
                    changed = True
                elif g1.member in vals and g2.member in vals:
                    want = vals[g1.member] * k
                    if abs(want - vals[g2.member]) > TRAIN_RATIO_REL * max(1.0, abs(want)):
                        raise ConstructionError(f"the meshes form a loop that locks the train (at mesh {m.name})")
    missing = [mb for mb in train.members if mb not in vals]
    if missing:
        raise ConstructionError(f"member {missing[0]} is not connected to {reference} through meshes")
    return vals, ratios


def solve_train(train: Train, givens: tuple[Given, ...], reference: str | None = None,
                power: float | None = None, inp: str | None = None, out: str | None = None) -> TrainSolution:
    """Every member's speed from the givens: one for an ordinary train (its input), two for a planetary
    one (a fixed member and a driven one).  ``power`` (W, delivered at ``inp``) gives torques and loads."""
    ref = reference or train.gears[0].member
    vals, ratios = relative_values(train, ref)
    dof = 2 if train.planetary else 1
    if len(givens) != dof:
        need = "two members (one held, one driven)" if dof == 2 else "one member's speed (the input)"
        raise ConstructionError(f"the train has {dof} degree{'s' if dof > 1 else ''} of freedom: give {need}, "
                                f"not {len(givens)}")
    for gv in givens:
        if gv.member not in vals:
            raise ConstructionError(f"{gv.member} is not a member of the train")
    if dof == 1:
        g = givens[0]
        if vals[g.member] == 0.0:
            raise ConstructionError(f"{g.member} does not turn")
        nc, x = 0.0, g.speed / vals[g.member]
    else:
        (a, b) = givens
        # n = n_c + e x for each: [[1, e_a], [1, e_b]] [n_c, x] = [n_a, n_b]
        det = vals[b.member] - vals[a.member]
        if abs(det) < TRAIN_RATIO_REL:
            raise ConstructionError(f"{a.member} and {b.member} turn together relative to the carrier: they cannot "
                                    f"both be given")
        x = (b.speed - a.speed) / det
        nc = a.speed - vals[a.member] * x
    speeds = {m: nc + vals[m] * x for m in train.members}
    sol = TrainSolution(train, ref, vals, nc, x, speeds, givens, ratios, power=power, inp=inp, out=out)
    if power is not None:
        _loads(sol)
    return sol


def _loads(sol: TrainSolution) -> None:
    t = sol.train
    P, inp, out = sol.power, sol.inp, sol.out
    w_in, w_out = sol.speeds[inp], sol.speeds[out]
    if abs(w_in) < STANDSTILL or abs(w_out) < STANDSTILL:
        raise ConstructionError("the input or output member stands still: no torque follows from the power")
    torques = {m: 0.0 for m in t.members}
    torques[inp] = P / w_in
    torques[out] = -P / w_out
    held = [g.member for g in sol.givens if g.speed == 0.0 and g.member not in (inp, out)]
    for h in held:
        torques[h] = -(torques[inp] + torques[out])
    loads: dict[str, float] = {}
    for m in t.meshes:
        for gname in (m.a, m.b):
            g = t.gear(gname)
            if g.member != t.carrier and len(t.meshes_of(g.member)) == 1 and \
                    sum(1 for x in t.gears if x.member == g.member) == 1:
                share = t.planets if t.carried_mesh(m) else 1      # n planets share a central gear's load
                loads[m.name] = abs(torques[g.member]) / t.radius(g) / share
                break
    # an idler passes its load on unchanged (no torque on its shaft): fill meshes by idlers
    changed = True
    while changed:
        changed = False
        for g in t.gears:
            ms = [m for m in t.meshes if g.name in (m.a, m.b)]
            if torques.get(g.member, 0.0) == 0.0 and sum(1 for x in t.gears if x.member == g.member) == 1 \
                    and len(ms) == 2:
                known = [m for m in ms if m.name in loads]
                if len(known) == 1:
                    other = ms[1] if known[0] is ms[0] else ms[0]
                    loads[other.name] = loads[known[0].name]
                    changed = True
    sol.torques, sol.loads = torques, loads


def layout(train: Train, tol_rel: float = DECISION) -> tuple[dict[str, Vec], dict[str, Vec]]:
    """Gear centres and pitch points: the first gear at the origin, each mesh placing the other gear at its
    angle (default 0; a planet's meshes 90 deg), a compound gear on its member's centre.  The carrier turns
    about the origin.  Raises when a gear would need two places (a planet that does not fit its ring, a
    reverted train whose stages differ: r1 + r2 != r3 + r4)."""
    centres: dict[str, Vec] = {}
    pitch: dict[str, Vec] = {}
    first = train.gears[0]
    centres[first.name] = Vec(0.0, 0.0)
    size = max(train.radius(g) for g in train.gears) * 4
    tol = tol_rel * size

    def place(g: TrainGear, at: Vec, why: str) -> None:
        for other in train.gears:                # a compound gear shares its member's centre
            if other.member == g.member and other.name in centres and other.name != g.name:
                if centres[other.name].distance_to(at) > tol:
                    raise ConstructionError(f"{why} puts gear {g.name} off the axis of its shaft {g.member}")
        if g.name in centres:
            if centres[g.name].distance_to(at) > tol:
                raise ConstructionError(f"{why} puts gear {g.name} {centres[g.name].distance_to(at):.4g} m off the "
                                        f"place its other mesh gives it: the gears do not fit (e.g. a planet and "
                                        f"its ring need N_ring = N_sun + 2 N_planet)")
            return
        centres[g.name] = at
        for other in train.gears:
            if other.member == g.member and other.name not in centres:
                centres[other.name] = at

    for _ in range(len(train.meshes) + 1):
        for m in train.meshes:
            ga, gb = train.gear(m.a), train.gear(m.b)
            ang = m.angle if m.angle is not None else (math.pi / 2 if train.planetary else 0.0)
            u = Vec(math.cos(ang), math.sin(ang))
            ra, rb = train.radius(ga), train.radius(gb)
            if ga.name in centres:
                oa = centres[ga.name]
                p = oa + u * (ra if not ga.internal else ra)
                ob = p - u * rb if train.internal_mesh(m) else p + u * rb
                place(gb, ob, f"mesh {m.name}")
                pitch[m.name] = p
            elif gb.name in centres:
                ob = centres[gb.name]
                # P = O_a + r_a u; O_b = O_a + (r_a -/+ r_b) u  ->  O_a = O_b - (r_a -/+ r_b) u
                oa = ob - u * (ra - rb if train.internal_mesh(m) else ra + rb)
                place(ga, oa, f"mesh {m.name}")
                pitch[m.name] = oa + u * ra
    if train.planetary:                          # central gears turn about the carrier's axis, the origin
        for m in train.meshes:
            ga, gb = train.gear(m.a), train.gear(m.b)
            if (ga.carrier == FRAME) == (gb.carrier == FRAME):
                continue
            central = ga if ga.carrier == FRAME else gb
            off = centres[central.name].norm()
            if off > tol:
                raise ConstructionError(f"mesh {m.name} puts gear {central.name} {off:.4g} m off the carrier's axis: "
                                        f"the gears do not fit (a planet and its ring need N_ring = N_sun + "
                                        f"2 N_planet)")
    for a, b in train.coaxial:
        ca = next(centres[g.name] for g in train.gears if g.member == a)
        cb = next(centres[g.name] for g in train.gears if g.member == b)
        if ca.distance_to(cb) > tol:
            raise ConstructionError(f"shafts {a} and {b} must be coaxial (a reverted train: the sums of the pitch "
                                    f"radii of its two stages equal) but their axes lie {ca.distance_to(cb):.4g} m apart")
    return centres, pitch
