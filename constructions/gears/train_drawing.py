"""A gear train drawn as its kinematic diagram (pitch circles, axes on the frame or on the carrier, the
carrier arm, pitch points) with the solution written as the notes work it: the signed ratio of every
mesh, the train value, and for a planetary train the tabular method (carrier held, then everything
locked), each case (which member held, which driven) a block of steps."""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..entities import AngleMark, Bar, Circle, Diagram, Note, Pivot, Point, Role
from ..geometry import Vec
from ..quantities import Measured
from ..record import Construction, StepKind, Value
from ..tolerance import STANDSTILL
from .planets import check_planets
from .trains import FRAME, Given, Train, TrainSolution, layout, solve_train

KINEMATIC = Diagram("space")


@dataclass(frozen=True)
class Case:
    name: str
    givens: tuple[Given, ...]
    power: float | None = None
    inp: str | None = None
    out: str | None = None


@dataclass
class TrainAnalysis:
    train: Train
    cases: tuple[Case, ...]
    solutions: tuple[TrainSolution, ...]
    construction: Construction

    def quantity(self, base: str, case: Case) -> str:
        return base if len(self.cases) == 1 else f"{base} ({case.name})"

    def load_name(self, mesh: str) -> str:
        """The tangential load's quantity at ``mesh``: per planet where n planets share it."""
        m = next(x for x in self.train.meshes if x.name == mesh)
        return f"W_t {mesh}" + (" per planet" if self.train.planets > 1 and self.train.carried_mesh(m) else "")

    def measured(self) -> list[Measured]:
        out: list[Measured] = []
        for case, sol in zip(self.cases, self.solutions):
            for m in self.train.members:
                out.append(Measured(self.quantity(f"omega_{m}", case), "angular velocity", sol.speeds[m]))
            if sol.torques is not None:
                for m, t in sol.torques.items():
                    out.append(Measured(self.quantity(f"T_{m}", case), "torque", t))
                for mesh, w in (sol.loads or {}).items():
                    out.append(Measured(self.quantity(self.load_name(mesh), case), "force", w))
        return out


def tabular_method(train: Train, sol, vals: dict) -> tuple[tuple[str, ...], ...]:
    """The textbook's table of the tabular method, a column a member (the carrier first): row 1 the
    carrier held and the reference member turned x (each member e_m x), row 2 everything locked and
    turned with the carrier (n_c), the total n = n_c + e_m x as a value (its ``$t<i>`` added to ``vals``)."""
    members = [train.carrier] + [m for m in train.members if m != train.carrier]
    totals = []
    for i, m in enumerate(members):
        vals[f"t{i}"] = Value("angular velocity", sol.speeds[m])
        totals.append(f"$t{i}")
    return (("Operation", *(_member_label(train, m) for m in members)),
            (f"{train.carrier} held, {sol.reference} turned x", *("0" if m == train.carrier else
                                                                  f"{sol.values[m]:+.5g} x" for m in members)),
            ("all locked, turned n_c", *("n_c" for _ in members)),
            ("total n = n_c + e x", *totals))


def _member_label(train: Train, m: str) -> str:
    gs = [g for g in train.gears if g.member == m]
    if not gs:
        return f"carrier {m}"
    if len(gs) == 1 and gs[0].name == m:
        return f"gear {m}"
    return f"shaft {m} (gear{'s' if len(gs) > 1 else ''} {', '.join(g.name for g in gs)})"


def train_analysis(train: Train, cases: tuple[Case, ...], rate_text=None) -> TrainAnalysis:
    rate_text = rate_text or (lambda w: f"{w:.4g} rad/s")
    centres, pitch = layout(train)
    sols = tuple(solve_train(train, c.givens, power=c.power, inp=c.inp, out=c.out) for c in cases)
    rec = Construction("Gear train")
    ents = []
    size = max(train.radius(g) for g in train.gears)
    for g in train.gears:
        O = centres[g.name]
        r = train.radius(g)
        ents.append(Circle(f"pitch circle {g.name}", Role.GIVEN, KINEMATIC, O, r,
                           f"{g.name}: {g.teeth}T" + (" int." if g.internal else "")))
    axes: dict[Vec, str] = {}
    for g in train.gears:
        axes.setdefault(centres[g.name], g.carrier)
    carrier_pins = []
    for i, (O, c) in enumerate(axes.items()):
        if c == FRAME:
            ents.append(Pivot(f"axis {i}", Role.GIVEN, KINEMATIC, O, None))
        else:
            ents.append(Point(f"axis {i}", Role.LABEL, KINEMATIC, O, None))
            carrier_pins.append(O)
    if train.planetary:
        for j, O in enumerate(carrier_pins):
            ents.append(Bar(f"carrier arm {j}", Role.GIVEN, KINEMATIC, Vec(0.0, 0.0), O, 90 + j))
        at = carrier_pins[0] * 0.5 + Vec(0.12 * size, 0.0)
        if train.planets > 1:            # in the gap between the first planet and the last, clear of the arms
            at = carrier_pins[0].rotated(-math.pi / train.planets)
        ents.append(Note("carrier label", Role.NOTE, KINEMATIC, at, f"carrier {train.carrier}"))
    for m in train.meshes:
        ents.append(Point(f"pitch point {m.name}", Role.LABEL, KINEMATIC, pitch[m.name], None))
    ents += _other_planets(train, centres)
    n = train.planets
    rec = rec.then(
        f"Kinematic diagram: {len(train.gears)} gears on {len(train.members)} members"
        + (f", the planets' axes on carrier {train.carrier}" if train.planetary else "")
        + (f" ({n} planets spaced {360 / n:g}\u00b0 apart)" if n > 1 else "")
        + "; pitch circles r = mN/2 touch at the pitch points.", *ents, kind=StepKind.GIVEN)
    if n > 1:
        rec = _planets_step(train, rec)
    # the meshes' ratios
    parts = []
    for m in train.meshes:
        ga, gb = train.gear(m.a), train.gear(m.b)
        sign = "+" if train.internal_mesh(m) else "-"
        parts.append(f"{m.b}/{m.a}: {sign}{ga.teeth}/{gb.teeth}")
    rel = "relative to the carrier " if train.planetary else ""
    rec = rec.then(f"Speed ratio of each mesh {rel}(external -, internal +, driving over driven teeth): "
                   + "; ".join(parts) + ".")
    for case, sol in zip(cases, sols):
        ref = sol.reference
        vals = {}
        if train.planetary:
            words = (f"{case.name}: tabular method (the table). Row 1, carrier {train.carrier} held, "
                     f"{_member_label(train, ref)} turned x; row 2, all locked and turned with the carrier n_c; "
                     f"the total n = n_c + e x. ")
            gv = "; ".join(f"{g.member} = $g{i}" for i, g in enumerate(case.givens))
            for i, g in enumerate(case.givens):
                vals[f"g{i}"] = Value("angular velocity", g.speed)
            words += f"Given {gv}: n_c = $nc, x = $x."
            vals["nc"] = Value("angular velocity", sol.carrier_speed)
            vals["x"] = Value("angular velocity", sol.x)
            rec = rec.then(words, values=vals, table=tabular_method(train, sol, vals))
            held = [g.member for g in case.givens if g.speed == 0.0]
            driven = [g.member for g in case.givens if g.speed != 0.0]
            central = [m for m in train.members if m != train.carrier
                       and all(x.carrier == FRAME for x in train.gears if x.member == m)]
            if held and driven and len(central) >= 2:
                h, d = held[0], driven[0]
                A, B = central[0], central[1]
                e = sol.values
                o = next(m for m in (A, B, train.carrier) if m not in (h, d))
                ratio = sol.speeds[o] / sol.speeds[d]
                rec = rec.then(f"{case.name}: notes' formula (n_{B} \u2212 n_c)/(n_{A} \u2212 n_c) = e = {e[B] / e[A]:+.5g} (the "
                               f"signed product of driving over driven teeth, {A} to {B}); with n_{h} = 0: "
                               f"n_{o}/n_{d} = $ratio.", values={"ratio": Value("number", ratio)}, kind=StepKind.ANSWER)
            elif len(driven) == 2 and len(central) >= 2 and set(driven) <= {central[0], central[1], train.carrier}:
                rec = _willis_step(train, case, sol, central[0], central[1], driven, rec)
        else:
            g = case.givens[0]
            sense = lambda w: "CCW" if w > 0 else "CW"  # noqa: E731
            words = (f"{case.name}: {_member_label(train, g.member)} turns $g0 {sense(g.speed)}; each member "
                     f"n = (train value) x n_{g.member}:")
            vals["g0"] = Value("angular velocity", abs(g.speed))
            for i, m in enumerate(train.members):
                if m == g.member:
                    continue
                vals[f"n{i}"] = Value("angular velocity", abs(sol.speeds[m]))
                words += f" n_{m} = {sol.values[m] / sol.values[g.member]:+.5g} n_{g.member} = $n{i} {sense(sol.speeds[m])};"
            rec = rec.then(words.rstrip(";") + ".", values=vals, kind=StepKind.ANSWER)
        # rotation senses on the diagram (first case only, to keep it legible)
        if case is cases[0]:
            marks = []
            for m in train.members:
                w = sol.speeds[m]
                if abs(w) < STANDSTILL:
                    continue
                gs = [x for x in train.gears if x.member == m]
                if gs:
                    O, r = centres[gs[0].name], train.radius(gs[0]) * (0.45 if not gs[0].internal else 0.92)
                else:
                    O, r = Vec(0.0, 0.0), 0.0
                    continue
                a0, span = math.radians(105.0 if not gs[0].internal else 220.0), math.radians(70.0)
                if gs[0].internal and train.planets > 1:
                    a0, span = _between_planets(train, centres, r)
                span *= 1 if w > 0 else -1
                a0 -= span / 2 if gs[0].internal and train.planets > 1 else 0.0
                marks.append(AngleMark(f"sense {m}", Role.LOAD, KINEMATIC, O, r, a0, a0 + span,
                                       f"n_{m} {'CCW' if w > 0 else 'CW'}"))
            if marks:
                rec = rec.then(f"{case.name}: senses of rotation drawn on the diagram.", *marks)
        if sol.torques is not None:
            vals = {}
            words = (f"{case.name}: power {case.power / 1000:.4g} kW in at {case.inp}. Torques T = P/\u03c9 (balance of power and of torques): ")
            for i, (m, t) in enumerate(sol.torques.items()):
                vals[f"t{i}"] = Value("torque", abs(t))
                idler = (not train.planetary and len(train.meshes_of(m)) == 2
                         and sum(1 for x in train.gears if x.member == m) == 1)
                role = ("in" if m == case.inp else "out" if m == case.out else "held" if t else
                        "none: an idler" if idler else "none")
                words += f"T_{m} = $t{i} ({role}); "
            share = f"; at the planets' meshes per planet, W_t = T/({n} r)" if n > 1 else ""
            words = words.rstrip("; ") + f". Tooth loads (tangential W_t = T/r{share}, radial W_t tan \u03c6, total W_t/cos \u03c6): "
            phi = train.pressure_angle
            for j, (mesh, w) in enumerate((sol.loads or {}).items()):
                vals[f"w{j}"], vals[f"r{j}"], vals[f"f{j}"] = (Value("force", w), Value("force", w * math.tan(phi)),
                                                             Value("force", w / math.cos(phi)))
                words += f"mesh {mesh}: $w{j}, $r{j}, $f{j}; "
            rec = rec.then(words.rstrip("; ") + ".", values=vals, kind=StepKind.ANSWER)
    return TrainAnalysis(train, cases, sols, rec)


def _other_planets(train: Train, centres: dict) -> list:
    """The planets after the first, each turned 360/n deg further about the carrier's axis: pitch circles,
    axes and carrier arms."""
    out = []
    carried = [g for g in train.gears if g.carrier != FRAME]
    for k in range(1, train.planets):
        turn = 2.0 * math.pi * k / train.planets
        for g in carried:
            O = centres[g.name].rotated(turn)
            out.append(Circle(f"pitch circle {g.name} planet {k + 1}", Role.GIVEN, KINEMATIC, O, train.radius(g), None))
        pins = {centres[g.name] for g in carried}
        for j, O in enumerate(pins):
            out.append(Point(f"axis planet {k + 1}.{j}", Role.LABEL, KINEMATIC, O.rotated(turn), None))
            out.append(Bar(f"carrier arm planet {k + 1}.{j}", Role.GIVEN, KINEMATIC, Vec(0.0, 0.0), O.rotated(turn),
                           90 + k))
    return out


def _planets_step(train: Train, rec: Construction) -> Construction:
    """The notes' two conditions on n planets: assembly and neighbours clearing."""
    pc = check_planets(train)
    if pc is None:
        return rec
    vals = {"spacing": Value("length", pc.centre_spacing), "tip": Value("length", pc.tip_diameter),
            "rs": Value("length", train.radius(pc.sun)), "rp": Value("length", train.radius(pc.planet))}
    words = f"{pc.planets} planets. "
    if pc.ring is not None:
        words += (f"Assembly: (N_S + N_R)/n = ({pc.sun.teeth} + {pc.ring.teeth})/{pc.planets} = "
                  f"{pc.assembly_value:.6g}, {'a whole number' if pc.assembles else 'NOT a whole number'}: "
                  f"the planets {'can' if pc.assembles else 'cannot'} be spaced equally. ")
    words += (f"Neighbours: 2 (r_S + r_P) sin(180\u00b0/n) = 2 ($rs + $rp) sin({180 / pc.planets:g}\u00b0) = $spacing "
              f"{'>' if pc.clear else '<='} tip diameter d_aP = $tip: {'clear' if pc.clear else 'they touch'}. "
              f"Each planet carries 1/{pc.planets} of the load (equal sharing).")
    return rec.then(words, values=vals)


def _willis_step(train: Train, case: Case, sol: TrainSolution, A: str, B: str, driven: list, rec: Construction):
    """A differential (two members driven): the notes' formula (Willis) solved for the third member."""
    e = sol.values[B] / sol.values[A]
    o = next(m for m in (A, B, train.carrier) if m not in driven)
    c = train.carrier
    solved = {c: f"n_c = (n_{B} \u2212 e n_{A})/(1 \u2212 e)", B: f"n_{B} = n_c + e (n_{A} \u2212 n_c)",
              A: f"n_{A} = n_c + (n_{B} \u2212 n_c)/e"}[o]
    vals = {"d0": Value("angular velocity", sol.speeds[driven[0]]), "d1": Value("angular velocity", sol.speeds[driven[1]]),
            "out": Value("angular velocity", sol.speeds[o])}
    return rec.then(f"{case.name}: a differential, two members driven. Notes' formula (Willis) (n_{B} \u2212 n_c)/(n_{A} \u2212 "
                    f"n_c) = e = {e:+.5g}; with n_{driven[0]} = $d0 and n_{driven[1]} = $d1: {solved} = $out.",
                    values=vals, kind=StepKind.ANSWER)


def _between_planets(train: Train, centres: dict, r: float) -> tuple[float, float]:
    """The middle and the span (rad) of a ring's sense arrow, radius ``r``, in the gap between the first
    two planets, clear of their pitch circles."""
    carried = [g for g in train.gears if g.carrier != FRAME]
    first = max(carried, key=lambda g: centres[g.name].norm() + train.radius(g))
    O, rp = centres[first.name], train.radius(first)
    half = math.asin(min(1.0, (rp * 1.15) / max(O.norm(), r * 0.5)))     # the planet's angular half-width
    gap = 2.0 * math.pi / train.planets - 2.0 * half
    return O.angle() + math.pi / train.planets, max(min(math.radians(70.0), 0.7 * gap), math.radians(10.0))
