"""The acceleration polygon, drawn step by step as in the notes ("Graphical acceleration analysis").

It stands on the velocity polygon: every normal component A^n = omega^2 r (towards the centre) is known
from the angular velocities measured there.  From the pole O_a the crank tip's acceleration is drawn as
A_B^n (towards O1) and A_B^t = alpha_1 x O1B; every joint found by a dyad gives one vector equation,

    A_C^n + A_C^t = A_B + A_CB^n + A_CB^t       (four-bar: C on a rocker about O2)
    A_C = A_B + A_CB^n + A_CB^t                 (slider-crank: A_C along the guide)

drawn in the notes' order: the known vectors end to end, then the trial lines of the unknown tangential
components (square to their links) or of the sliding acceleration (parallel to the guide), and their
crossing c' is the answer.  Accelerations of points fixed to a link come from the acceleration image
(the triangle b'c'd' similar to BCD).  Every value returned is read off the figure: absolute
accelerations are the vectors O_a->j', tangential components the sides between the tip of a normal
component and j', and angular accelerations those sides divided by the link lengths (CCW positive).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Mapping

from ..entities import Arrow, Diagram, Point, Polygon, Role, ScaleBar, TrialLine
from ..errors import DegenerateInput
from ..geometry import ORIGIN, Line, Tolerance, Vec
from ..mechanisms.assembly import CircleAndGuide, CrankTip, Dyad, FixedToLink, SlotThrough, TwoLines, assembly_plan
from ..mechanisms.model import Mechanism, slide_line
from ..quantities import Measured
from ..record import Construction, StepKind, Term, Value, VectorEquation
from .common import (SINGULAR_SINE, PolygonDrawing, image_name, image_point, joined, rounding_estimate,
                     sense)
from .velocity import VelocityAnalysis

PRIME = "'"


def _img(joint: str) -> str:
    return image_name(joint, PRIME)


@dataclass(frozen=True)
class AccelerationAnalysis:
    """The acceleration polygon at one position and the values measured off it (SI, CCW positive).

    ``accelerations`` maps every joint and point to its absolute acceleration (fixed pivots: zero);
    ``normal[(J, P)]`` and ``tangential[(J, P)]`` are the components A_JP^n and A_JP^t of the
    acceleration of J relative to P on the link joining them (P may be a fixed pivot: then they are
    A_J^n and A_J^t); ``angular`` maps link numbers to their angular acceleration (slider blocks: 0);
    ``conditions`` maps each joint found by trial lines to the sine of their crossing; ``scale`` is the
    scale fixed by the caller or None (the drawing chooses).
    """

    construction: Construction
    velocity: VelocityAnalysis
    accelerations: Mapping[str, Vec]
    normal: Mapping[tuple[str, str], Vec]
    tangential: Mapping[tuple[str, str], Vec]
    angular: Mapping[int, float]
    conditions: Mapping[str, float]
    scale: float | None
    warnings: tuple[str, ...]
    alpha: float = 0.0
    coriolis: Mapping[str, Vec] = field(default_factory=dict)   # name (A_A3A^c) -> 2 omega x V_rel
    sliding: Mapping[str, Vec] = field(default_factory=dict)    # name (A_A3A^s) -> along the slot

    @property
    def worst_condition(self) -> float:
        return min(list(self.conditions.values()) + [self.velocity.worst_condition])

    @property
    def relative_error_estimate(self) -> float:
        return rounding_estimate(self.worst_condition) / max(self.worst_condition, 1e-300)

    def scales(self) -> dict[str, float]:
        """The input's scale of each kind: |A_B| for accelerations and max(|alpha_1|, omega_k^2) for angular
        accelerations (alpha and omega^2 share their unit and both set the polygon's size)."""
        w2 = max(w * w for w in self.velocity.angular.values())
        return {"acceleration": max(a.norm() for a in self.accelerations.values()),
                "angular acceleration": max(abs(self.alpha), w2)}

    def measured(self, m: Mechanism) -> list[Measured]:
        """Absolute accelerations of the moving joints and points, the normal and tangential components
        of every dyad (named as in the notes: A_CB^n, A_CB^t; A_C^n, A_C^t about a fixed pivot) and the
        angular accelerations of the links that are neither the crank nor a slider block."""
        c = self.worst_condition
        out = [Measured(f"A_{n}", "acceleration", a, c) for n, a in self.accelerations.items()
               if n not in m.ground]
        rest = self.velocity.at_rest          # no normal or Coriolis parts: zero by the data, not measured
        for comps, sup in ((self.normal, "n"), (self.tangential, "t")):
            if not (rest and sup == "n"):
                out += [Measured(component_name(j, p, sup, m), "acceleration", a, c) for (j, p), a in comps.items()]
        for comps in ((self.sliding,) if rest else (self.coriolis, self.sliding)):
            out += [Measured(name, "acceleration", a, c) for name, a in comps.items()]
        skip = {m.crank} | {s.number for s in m.slides}
        out += [Measured(f"alpha_{n}", "angular acceleration", al, c) for n, al in sorted(self.angular.items())
                if n not in skip]
        return out


def component_name(j: str, p: str, sup: str, m: Mechanism) -> str:
    """A_CB^t; about a fixed pivot the notes drop the pivot: A_C^t."""
    return f"A_{j}^{sup}" if p in m.ground else f"A_{j}{p}^{sup}"


def acceleration_polygon(m: Mechanism, va: VelocityAnalysis, alpha: float = 0.0, *,
                         scale: float | None = None) -> AccelerationAnalysis:
    """Draw the acceleration polygon of ``m`` from its velocity analysis ``va`` with the crank's angular
    acceleration ``alpha`` (rad/s^2, CCW positive).  ``scale`` (SI units per paper mm) fixes the scale;
    by default the drawing chooses."""
    if not math.isfinite(alpha):
        raise DegenerateInput(f"the crank's angular acceleration must be finite, not {alpha!r} rad/s^2")
    plan = assembly_plan(m)
    crank = plan[0]
    assert isinstance(crank, CrankTip)
    poly = _Polygon(m, va, crank, alpha)
    poly.draw_plan(plan)
    return poly.analysis(scale)


def _a(value: float) -> Value:
    return Value("acceleration", value)


class _Polygon(PolygonDrawing):
    """The acceleration polygon while it is drawn."""

    what = "acceleration polygon"

    def __init__(self, m: Mechanism, va: VelocityAnalysis, crank: CrankTip, alpha: float) -> None:
        self.m, self.va, self.pose, self.crank, self.alpha = m, va, va.pose, crank, alpha
        pos = self.pose.positions
        self.acc: dict[str, Vec] = {g: ORIGIN for g in m.ground}
        self.normal: dict[tuple[str, str], Vec] = {}
        self.tangential: dict[tuple[str, str], Vec] = {}
        self.ang: dict[int, float] = {s.number: 0.0 for s in m.slides if s.number is not None and s.on is None}
        self.coriolis: dict[str, Vec] = {}
        self.sliding: dict[str, Vec] = {}
        self.cond: dict[str, float] = {}
        self.warnings: list[str] = []
        self.equations: list[tuple[str, VectorEquation]] = []
        self.steps: list[tuple] = []
        # the crank: A_B^n = -omega1^2 O1B (towards O1), A_B^t = alpha1 k x O1B
        n, tip, pivot = crank.link.number, crank.tip, crank.pivot
        r = pos[tip] - pos[pivot]
        omega = va.angular[n]
        an = r * (-omega * omega)
        at = r.perp() * alpha
        self.normal[(tip, pivot)] = an
        self.tangential[(tip, pivot)] = at
        self.acc[tip] = an + at
        self.ang[n] = alpha
        self.known = (an + at).norm()
        self.tol = Tolerance(max(self.known, an.norm()), sine=SINGULAR_SINE)
        name = f"{pivot}{tip}"
        entities = [Arrow(f"A_{tip}^n", Role.KNOWN, Diagram.ACCELERATION, ORIGIN, an, f"A_{tip}^n")]
        if alpha != 0.0:
            entities.append(Arrow(f"A_{tip}^t", Role.KNOWN, Diagram.ACCELERATION, an, an + at, f"A_{tip}^t"))
            if an.norm() > 0 and at.norm() > 0:
                entities.append(Arrow(f"result A_{tip}", Role.RESULT, Diagram.ACCELERATION, ORIGIN, an + at,
                                      f"A_{tip}"))
            words = (f"Draw A_{tip}^n = \u03c9_{n}\u00b2 \u00b7 {name} ($an) from O_a, parallel to {name} towards "
                     f"{pivot}; from its tip draw A_{tip}^t = \u03b1_{n} \u00b7 {name} ($at), perpendicular to "
                     f"{name} (\u03b1_{n} {sense(alpha)}); the end is {_img(tip)}.")
        else:
            words = (f"Draw A_{tip}^n = \u03c9_{n}\u00b2 \u00b7 {name} ($an) from O_a, parallel to {name} towards "
                     f"{pivot}; A_{tip}^t = \u03b1_{n} \u00b7 {name} = 0 since \u03b1_{n} = 0, so its tip is "
                     f"{_img(tip)}.")
        entities.append(Point(f"acceleration image {tip}", Role.LABEL, Diagram.ACCELERATION, an + at, _img(tip)))
        self.steps.append((words, tuple(entities), None, {"an": _a(an.norm()), "at": _a(at.norm())},
                           StepKind.CONSTRUCTION))

    def _terms_of(self, p: str) -> tuple[Term, ...]:
        """The known acceleration of a joint as the notes write it: the crank tip as A_B^n + A_B^t."""
        if p == self.crank.tip:
            return (Term("A", p, True, True, "n"), Term("A", p, True, True, "t"))
        return (Term("A", p, True, True),)

    def _alpha_of(self, number: int) -> float:
        """The angular acceleration of a link whose acceleration image is known at two points."""
        if number not in self.ang:
            pts = [x for x in self.m.points_of(number) if x in self.acc]
            a, b = pts[0], pts[1]
            pos = self.pose.positions
            r = pos[b] - pos[a]
            w = self.va.angular[number]
            self.ang[number] = r.cross(self.acc[b] - self.acc[a] + r * (w * w)) / r.dot(r)
        return self.ang[number]

    def _acceleration_on(self, number: int, point: str) -> Vec:
        """The acceleration of the point of link ``number`` at ``point``'s position:
        A_X = A_K + alpha k x KX - omega^2 KX for a point K of the link whose acceleration is known."""
        pos = self.pose.positions
        k = next(x for x in self.m.points_of(number) if x in self.acc)
        r = pos[point] - pos[k]
        w = self.va.angular[number]
        return self.acc[k] + r.perp() * self._alpha_of(number) - r * (w * w)

    def _coriolis(self, slot_link: int, v_rel: Vec, start: Vec, name: str, moving: str, frame_point: str,
                  eq) -> Vec:
        """Draw the Coriolis component 2 omega x V_rel from ``start``; returns its tip."""
        w = self.va.angular[slot_link]
        ac = v_rel.perp() * (2.0 * w)
        tip = start + ac
        turn = "counter-clockwise" if w > 0 else "clockwise"
        words = (f"From {image_name(frame_point, PRIME) if frame_point not in self.m.ground else 'O_a'} draw the "
                 f"Coriolis component {name} = 2 \u03c9_{slot_link} \u00d7 V_{moving} ($ac): V_{moving} "
                 f"turned 90\u00b0 {turn}, the sense of \u03c9_{slot_link}.") if w != 0 else (
                 f"The Coriolis component {name} = 2 \u03c9_{slot_link} \u00d7 V_{moving} is zero "
                 f"(\u03c9_{slot_link} = 0).")
        self.coriolis[name] = ac
        ent = (Arrow(name, Role.KNOWN, Diagram.ACCELERATION, start, tip, name),) if ac.norm() > 0 else ()
        self.steps.append((words, ent, eq, {"ac": _a(ac.norm())}, StepKind.CONSTRUCTION))
        return tip

    def dyad(self, step: Dyad) -> None:
        """One vector equation: the known normal (and Coriolis) components, two trial lines, their crossing."""
        if isinstance(step, SlotThrough):
            return self.slot_through(step)
        if isinstance(step, TwoLines):
            return self.two_lines(step)
        m, pos, vel = self.m, self.pose.positions, self.va
        j = step.joint
        guided = isinstance(step, CircleAndGuide)
        on = step.slide.on if guided else None
        arms = [(step.link, step.centre)] if guided else [(step.link_a, step.first), (step.link_b, step.second)]
        eq = self._equation(arms, j, guided, step.coincident if on is not None else "")
        self.equations.append((self._equation_words(eq, arms, j, guided, step), eq))
        trials: list[Line] = []
        tips: dict[str, Vec] = {}
        for link, centre in arms:
            r = pos[j] - pos[centre]
            w = vel.angular[link.number]
            an = r * (-w * w)
            start = self.acc[centre]
            tip = start + an
            tips[centre] = tip
            self.normal[(j, centre)] = an
            comp = component_name(j, centre, "n", m)
            at = "O_a" if centre in m.ground else _img(centre)
            trial_name = component_name(j, centre, "t", m)
            self.steps.append((
                f"From {at} draw {comp} = \u03c9_{link.number}\u00b2 \u00b7 {centre}{j} ($an), parallel to "
                f"{centre}{j} towards {centre}; through its tip draw the direction of {trial_name}, "
                f"perpendicular to {centre}{j}.",
                (Arrow(comp, Role.KNOWN, Diagram.ACCELERATION, start, tip, comp),
                 TrialLine(f"trial {trial_name}", Role.TRIAL, Diagram.ACCELERATION, tip, r.perp(),
                           f"\u22a5 {centre}{j}")),
                eq, {"an": _a(an.norm())}, StepKind.CONSTRUCTION))
            trials.append(Line(tip, r.perp()))
        slide_tip = None
        if guided:
            g = self.pose.lines[j].direction
            if on is None:
                trials.append(Line(ORIGIN, g))
                self.steps.append((f"Draw the direction of A_{j} through O_a, parallel to the guide.",
                                   (TrialLine(f"trial A_{j}", Role.TRIAL, Diagram.ACCELERATION, ORIGIN, g,
                                              "\u2225 guide"),), eq, {}, StepKind.CONSTRUCTION))
            else:
                jg = step.coincident
                a_jg = self._acceleration_on(on, jg)
                self.acc[jg] = a_jg
                self.steps.append((f"Mark {_img(jg)}, the acceleration image of the point {jg} of link {on} "
                                   f"under {j} (A_{jg} = $a).",
                                   (Point(f"acceleration image {jg}", Role.LABEL, Diagram.ACCELERATION, a_jg, _img(jg)),),
                                   eq, {"a": _a(a_jg.norm())}, StepKind.CONSTRUCTION))
                v_rel = vel.velocities[j] - vel.velocities[jg]
                tip = self._coriolis(on, v_rel, a_jg, f"A_{j}{jg}^c", f"{j}{jg}", jg, eq)
                trials.append(Line(tip, g))
                self.steps.append((f"Through its tip draw the direction of the sliding component A_{j}{jg}^s, "
                                   f"parallel to the slot.",
                                   (TrialLine(f"trial A_{j}{jg}^s", Role.TRIAL, Diagram.ACCELERATION, tip, g,
                                              "\u2225 slot"),), eq, {}, StepKind.CONSTRUCTION))
                slide_tip = tip
        aj = self._close(step, trials)
        self.acc[j] = aj
        values: dict[str, Value] = {}
        measured: list[Arrow] = []
        parts, alphas = [], []
        for i, (link, centre) in enumerate(arms):
            r = pos[j] - pos[centre]
            a_t = aj - tips[centre]
            self.tangential[(j, centre)] = a_t
            al = r.cross(a_t) / r.dot(r)
            self.ang[link.number] = al
            comp = component_name(j, centre, "t", m)
            measured.append(Arrow(f"result {comp}", Role.RESULT, Diagram.ACCELERATION, tips[centre], aj, comp))
            values[f"t{i}"] = _a(a_t.norm())
            values[f"al{i}"] = Value("angular acceleration", abs(al))
            parts.append(f"{comp} = $t{i}")
            alphas.append(f"\u03b1_{link.number} = {comp}/{centre}{j} = $al{i} {sense(al)}")
        if slide_tip is not None:
            name = f"A_{j}{step.coincident}^s"
            self.sliding[name] = aj - slide_tip
            measured.append(Arrow(f"result {name}", Role.RESULT, Diagram.ACCELERATION, slide_tip, aj, name))
            values["s"] = _a((aj - slide_tip).norm())
            parts.append(f"{name} = $s")
        if guided and step.slide.number is not None:
            self.ang[step.slide.number] = 0.0 if on is None else self._alpha_of(on)
        measured.append(Arrow(f"result A_{j}", Role.RESULT, Diagram.ACCELERATION, ORIGIN, aj, f"A_{j}"))
        values["a"] = _a(aj.norm())
        self.steps.append((
            f"The trial lines meet at {_img(j)}. Measure {', '.join(parts)} and A_{j} (from O_a to {_img(j)}) = $a; "
            f"{'; '.join(alphas)}.",
            (Point(f"acceleration image {j}", Role.LABEL, Diagram.ACCELERATION, aj, _img(j)), *measured),
            eq, values, StepKind.ANSWER))

    def two_lines(self, step: TwoLines) -> None:
        """J carried along two lines: for each, A_J = A_JG + A_J,JG^c + A_J,JG^s (the Coriolis component
        2 omega x V_J,JG of a slot in a turning link; on a fixed guide A_J itself lies along it)."""
        m, pos, vel = self.m, self.pose.positions, self.va
        j = step.joint
        trials, tips = [], []
        eq_terms = []
        for sl, jg in ((step.slide_a, step.coincident_a), (step.slide_b, step.coincident_b)):
            if sl.on is None:
                eq_terms.append((Term("A", j, False, True),))
            else:
                eq_terms.append((Term("A", jg, True, True), Term("A", f"{j}{jg}", True, True, "c"),
                                 Term("A", f"{j}{jg}", False, True, "s")))
        eq = VectorEquation(eq_terms[0], eq_terms[1])
        self.equations.append((f"Relative acceleration equation at {j}, carried along two lines: "
                               f"{eq.text(marks=False)}; two unknown magnitudes.", eq))
        for sl, jg in ((step.slide_a, step.coincident_a), (step.slide_b, step.coincident_b)):
            g = slide_line(m, sl, pos).direction
            if sl.on is None:
                trials.append(Line(ORIGIN, g))
                tips.append(None)
                self.steps.append((f"Draw the direction of A_{j} through O_a, parallel to the guide.",
                                   (TrialLine(f"trial A_{j} guide", Role.TRIAL, Diagram.ACCELERATION, ORIGIN, g,
                                              "\u2225 guide"),), eq, {}, StepKind.CONSTRUCTION))
                continue
            a_jg = self._acceleration_on(sl.on, jg)
            self.acc[jg] = a_jg
            self.steps.append((f"Mark {_img(jg)}, the acceleration image of the point {jg} of link {sl.on} "
                               f"under {j} (A_{jg} = $a).",
                               (Point(f"acceleration image {jg}", Role.LABEL, Diagram.ACCELERATION, a_jg, _img(jg)),),
                               eq, {"a": _a(a_jg.norm())}, StepKind.CONSTRUCTION))
            v_rel = vel.velocities[j] - vel.velocities[jg]
            tip = self._coriolis(sl.on, v_rel, a_jg, f"A_{j}{jg}^c", f"{j}{jg}", jg, eq)
            trials.append(Line(tip, g))
            tips.append((jg, tip))
            self.steps.append((f"Through its tip draw the direction of the sliding component A_{j}{jg}^s, "
                               f"parallel to the slot.",
                               (TrialLine(f"trial A_{j}{jg}^s", Role.TRIAL, Diagram.ACCELERATION, tip, g,
                                          "\u2225 slot"),), eq, {}, StepKind.CONSTRUCTION))
        aj = self._close(step, trials)
        self.acc[j] = aj
        measured = [Arrow(f"result A_{j}", Role.RESULT, Diagram.ACCELERATION, ORIGIN, aj, f"A_{j}")]
        values = {"a": _a(aj.norm())}
        parts = [f"A_{j} (from O_a to {_img(j)}) = $a"]
        for i, t in enumerate(tips):
            if t is None:
                continue
            jg, tip = t
            name = f"A_{j}{jg}^s"
            self.sliding[name] = aj - tip
            measured.append(Arrow(f"result {name}", Role.RESULT, Diagram.ACCELERATION, tip, aj, name))
            values[f"s{i}"] = _a((aj - tip).norm())
            parts.append(f"{name} = $s{i}")
        for sl in (step.slide_a, step.slide_b):
            if sl.number is not None:
                self.ang[sl.number] = 0.0 if sl.on is None else self._alpha_of(sl.on)
        self.steps.append((f"The trial lines meet at {_img(j)}. Measure {', '.join(parts)}.",
                           (Point(f"acceleration image {j}", Role.LABEL, Diagram.ACCELERATION, aj, _img(j)), *measured),
                           eq, values, StepKind.ANSWER))

    def slot_through(self, step: SlotThrough) -> None:
        """The slotted link about its known point P, J sliding in its slot, JG the link's point under J:
        A_JG = A_P + A_JG,P^n + A_JG,P^t = A_J + A_JG,J^s + A_JG,J^c, the Coriolis component
        A^c = 2 omega_G x V_JG,J (the sliding velocity turned 90 deg in the sense of omega_G)."""
        m, pos, vel = self.m, self.pose.positions, self.va
        j, jg, c, k = step.joint, step.coincident, step.centre, step.link
        r = pos[j] - pos[c]
        g = self.pose.lines[j].direction
        w = vel.angular[k.number]
        eq = self._slot_equation(j, jg, c)
        n_name, t_name = component_name(jg, c, "n", m), component_name(jg, c, "t", m)
        self.equations.append((
            f"Relative acceleration equation at the sliding joint {j} ({jg} the point of link {k.number} under "
            f"{j}): {eq.text(marks=False)}, with {n_name} \u2225 {c}{j} towards {c}, {t_name} \u22a5 {c}{j}, "
            f"A_{jg}{j}^s \u2225 slot and the Coriolis component A_{jg}{j}^c = 2 \u03c9_{k.number} \u00d7 "
            f"V_{jg}{j}; two unknown magnitudes.", eq))
        an = r * (-w * w)
        start = self.acc[c]
        tip_n = start + an
        self.normal[(jg, c)] = an
        at = "O_a" if c in m.ground else _img(c)
        self.steps.append((
            f"From {at} draw {n_name} = \u03c9_{k.number}\u00b2 \u00b7 {c}{j} ($an), parallel to {c}{j} towards "
            f"{c}; through its tip draw the direction of {t_name}, perpendicular to {c}{j}.",
            (Arrow(n_name, Role.KNOWN, Diagram.ACCELERATION, start, tip_n, n_name),
             TrialLine(f"trial {t_name}", Role.TRIAL, Diagram.ACCELERATION, tip_n, r.perp(), f"\u22a5 {c}{j}")),
            eq, {"an": _a(an.norm())}, StepKind.CONSTRUCTION))
        v_rel = vel.velocities[jg] - vel.velocities[j]
        tip_c = self._coriolis(k.number, v_rel, self.acc[j], f"A_{jg}{j}^c", f"{jg}{j}", j, eq)
        self.steps.append((f"Through its tip draw the direction of the sliding component A_{jg}{j}^s, parallel "
                           f"to the slot.",
                           (TrialLine(f"trial A_{jg}{j}^s", Role.TRIAL, Diagram.ACCELERATION, tip_c, g,
                                      "\u2225 slot"),), eq, {}, StepKind.CONSTRUCTION))
        a = self._close(step, [Line(tip_n, r.perp()), Line(tip_c, g)])
        self.acc[jg] = a
        a_t = a - tip_n
        self.tangential[(jg, c)] = a_t
        self.sliding[f"A_{jg}{j}^s"] = a - tip_c
        al = r.cross(a_t) / r.dot(r)
        self.ang[k.number] = al
        if step.slide.number is not None:
            self.ang[step.slide.number] = al
        for x in m.points_of(k.number):
            if x not in self.acc:
                rx = pos[x] - pos[c]
                self.acc[x] = self.acc[c] + rx.perp() * al - rx * (w * w)
        self.steps.append((
            f"The trial lines meet at {_img(jg)}. Measure {t_name} = $t, A_{jg}{j}^s = $s and A_{jg} = $a; "
            f"\u03b1_{k.number} = {t_name}/{c}{j} = $al {sense(al)}.",
            (Point(f"acceleration image {jg}", Role.LABEL, Diagram.ACCELERATION, a, _img(jg)),
             Arrow(f"result {t_name}", Role.RESULT, Diagram.ACCELERATION, tip_n, a, t_name),
             Arrow(f"result A_{jg}{j}^s", Role.RESULT, Diagram.ACCELERATION, tip_c, a, f"A_{jg}{j}^s"),
             Arrow(f"result A_{jg}", Role.RESULT, Diagram.ACCELERATION, ORIGIN, a, f"A_{jg}"),
             *[Point(f"acceleration image {x}", Role.LABEL, Diagram.ACCELERATION, self.acc[x], _img(x))
               for x in m.points_of(k.number) if x != c and x not in m.ground]),
            eq, {"t": _a(a_t.norm()), "s": _a((a - tip_c).norm()), "a": _a(a.norm()),
                 "al": Value("angular acceleration", abs(al))}, StepKind.ANSWER))

    def image(self, step: FixedToLink) -> None:
        """Acceleration image of point D of a link placed by two of its points P, Q: the triangle p'q'd'
        similar to PQD (notes, "Acceleration image"), placed by the similar triangle itself."""
        pos = self.pose.positions
        link, d = step.link, step.name
        p, q = step.via
        ap, aq = self.acc[p], self.acc[q]
        ad, t, _ = image_point(pos[p], pos[q], pos[d], ap, aq)
        self._alpha_of(link.number)
        ip, iq, idd = (("O_a" if x in self.m.ground else _img(x)) for x in (p, q, d))
        self.acc[d] = ad
        self.steps.append((
            f"Acceleration image of link {link.number}: on {joined(ip, iq)} draw the triangle {joined(ip, iq, idd)} "
            f"similar to {p}{q}{d}, in the same order of letters (it is {p}{q}{d} turned and scaled as "
            f"{joined(ip, iq)} is {p}{q}). "
            f"Join O_a to {idd}: A_{d} = $a.",
            (Polygon(f"acceleration image {p}{q}{d}", Role.IMAGE, Diagram.ACCELERATION, (ap, aq, ad)),
             Point(f"acceleration image {d}", Role.LABEL, Diagram.ACCELERATION, ad, idd),
             Arrow(f"result A_{d}", Role.RESULT, Diagram.ACCELERATION, ORIGIN, ad, f"A_{d}")),
            None, {"a": _a(ad.norm())}, StepKind.ANSWER))

    def _slot_equation(self, j: str, jg: str, c: str) -> VectorEquation:
        right = (Term("A", j, True, True), Term("A", f"{jg}{j}", True, True, "c"),
                 Term("A", f"{jg}{j}", False, True, "s"))
        if c in self.m.ground:
            left = (Term("A", jg, True, True, "n"), Term("A", jg, False, True, "t"))
        else:
            left = self._terms_of(c) + (Term("A", f"{jg}{c}", True, True, "n"), Term("A", f"{jg}{c}", False, True, "t"))
        return VectorEquation(left, right)

    def _equation(self, arms, j: str, guided: bool, coincident: str = "") -> VectorEquation:
        """The notes' acceleration equations with their marks:
        slider:   A_J(x✓) = A_P + A_JP^n(✓✓) + A_JP^t(x✓)
        rocker:   A_J^n(✓✓) + A_J^t(x✓) = A_P + A_JP^n(✓✓) + A_JP^t(x✓)
        two moving centres: A_P + A_JP^n + A_JP^t = A_Q + A_JQ^n + A_JQ^t."""
        m = self.m

        def side(centre: str) -> tuple[Term, ...]:
            if centre in m.ground:
                return (Term("A", j, True, True, "n"), Term("A", j, False, True, "t"))
            return self._terms_of(centre) + (Term("A", f"{j}{centre}", True, True, "n"),
                                             Term("A", f"{j}{centre}", False, True, "t"))
        if guided and coincident:
            (_, c), = arms
            slot = (Term("A", coincident, True, True), Term("A", f"{j}{coincident}", True, True, "c"),
                    Term("A", f"{j}{coincident}", False, True, "s"))
            if c in m.ground:
                return VectorEquation(side(c), slot)
            return VectorEquation(side(c), slot)
        if guided:
            (_, c), = arms
            return VectorEquation((Term("A", j, False, True),), side(c))
        (_, p), (_, q) = arms
        if p in m.ground:
            p, q = q, p
        return VectorEquation(side(q), side(p)) if q in m.ground else VectorEquation(side(p), side(q))

    def _equation_words(self, eq: VectorEquation, arms, j: str, guided: bool, step=None) -> str:
        m = self.m
        links = " and ".join(f"link {l.number} ({l.label})" for l, _ in arms)
        dirs = []
        for link, c in arms:
            n, t = component_name(j, c, "n", m), component_name(j, c, "t", m)
            dirs.append(f"{n} \u2225 {c}{j} towards {c}, {t} \u22a5 {c}{j}")
        if guided and step is not None and step.slide.on is not None:
            jg = step.coincident
            dirs.append(f"A_{j}{jg}^s \u2225 slot, the Coriolis component A_{j}{jg}^c = 2 \u03c9_{step.slide.on} "
                        f"\u00d7 V_{j}{jg}")
        elif guided:
            dirs.append(f"A_{j} \u2225 guide")
        return (f"Relative acceleration equation on {links}: {eq.text(marks=False)}, with {'; '.join(dirs)}; "
                f"two unknown magnitudes.")

    def analysis(self, scale: float | None) -> AccelerationAnalysis:
        """The record in the notes' order: equations, pole, scale, then the drawing steps."""
        rec = Construction("Acceleration polygon")
        for words, eq in self.equations:
            rec = rec.then(words, equation=eq, kind=StepKind.GIVEN)
        rec = rec.then("Choose the pole O_a.", Point("pole O_a", Role.LABEL, Diagram.ACCELERATION, ORIGIN, "O_a"))
        rec = rec.then(f"Choose the acceleration scale: 1 mm = $s; A_{self.crank.tip} is $len.",
                       ScaleBar("acceleration scale", Role.SCALE_BAR, Diagram.ACCELERATION, "acceleration", scale),
                       values={"s": Value("scale", scale, "acceleration"),
                               "len": Value("paper length", self.known, "acceleration")})
        for words, entities, eq, values, kind in self.steps:
            rec = rec.then(words, *entities, equation=eq, values=values, kind=kind)
        return AccelerationAnalysis(rec, self.va, self.acc, self.normal, self.tangential, self.ang, self.cond,
                                    scale, tuple(self.warnings), self.alpha, self.coriolis, self.sliding)
