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
from dataclasses import dataclass
from typing import Mapping

from ..errors import DegenerateInput
from ..geometry import ORIGIN, Contact, Line, Tolerance, Vec, intersect_lines
from ..linkage import CircleAndGuide, CrankTip, FixedToLink, Mechanism, Pose, TwoCircles, assembly_plan
from ..quantities import Measured
from ..record import (Arrow, Construction, Diagram, Point, Polygon, Role, ScaleBar, StepKind, Term,
                      TrialLine, Value, VectorEquation)
from .common import (SINGULAR_SINE, WARN_SINE, image_name, image_point, near_singular_warning,
                     rounding_estimate, sense, singular_position)
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
        for comps, sup in ((self.normal, "n"), (self.tangential, "t")):
            out += [Measured(component_name(j, p, sup, m), "acceleration", a, c) for (j, p), a in comps.items()]
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
    for step in plan[1:]:
        if isinstance(step, (TwoCircles, CircleAndGuide)):
            poly.dyad(step)
        elif isinstance(step, FixedToLink):
            poly.image(step)
    return poly.analysis(scale)


def _a(value: float) -> Value:
    return Value("acceleration", value)


class _Polygon:
    """The acceleration polygon while it is drawn."""

    def __init__(self, m: Mechanism, va: VelocityAnalysis, crank: CrankTip, alpha: float) -> None:
        self.m, self.va, self.pose, self.crank, self.alpha = m, va, va.pose, crank, alpha
        pos = self.pose.positions
        self.acc: dict[str, Vec] = {g: ORIGIN for g in m.ground}
        self.normal: dict[tuple[str, str], Vec] = {}
        self.tangential: dict[tuple[str, str], Vec] = {}
        self.ang: dict[int, float] = {s.number: 0.0 for s in m.slides}
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
        entities.append(Point(f"image {tip}", Role.LABEL, Diagram.ACCELERATION, an + at, _img(tip)))
        self.steps.append((words, tuple(entities), None, {"an": _a(an.norm()), "at": _a(at.norm())},
                           StepKind.CONSTRUCTION))

    def _terms_of(self, p: str) -> tuple[Term, ...]:
        """The known acceleration of a joint as the notes write it: the crank tip as A_B^n + A_B^t."""
        if p == self.crank.tip:
            return (Term("A", p, True, True, "n"), Term("A", p, True, True, "t"))
        return (Term("A", p, True, True),)

    def dyad(self, step: TwoCircles | CircleAndGuide) -> None:
        """One vector equation: the known normal components, two trial lines and their crossing j'."""
        m, pos, vel = self.m, self.pose.positions, self.va
        j = step.joint
        guided = isinstance(step, CircleAndGuide)
        arms = [(step.link, step.centre)] if guided else [(step.link_a, step.first), (step.link_b, step.second)]
        eq = self._equation(arms, j, guided)
        self.equations.append((self._equation_words(eq, arms, j, guided), eq))
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
        if guided:
            g = step.slide.line.direction
            trials.append(Line(ORIGIN, g))
            self.steps.append((f"Draw the direction of A_{j} through O_a, parallel to the guide.",
                               (TrialLine(f"trial A_{j}", Role.TRIAL, Diagram.ACCELERATION, ORIGIN, g,
                                          "\u2225 guide"),), eq, {}, StepKind.CONSTRUCTION))
        hit = intersect_lines(trials[0], trials[1], self.tol)
        if hit.contact is not Contact.CROSSING:
            raise singular_position(m, step, self.pose, hit.condition, "acceleration polygon")
        aj = hit.points[0]
        self.acc[j] = aj
        self.cond[j] = hit.condition
        if hit.condition < WARN_SINE:
            self.warnings.append(near_singular_warning(j, hit.condition, "acceleration polygon"))
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
            alphas.append(f"\u03b1_{link.number} = {comp}/{link.label} = $al{i} {sense(al)}")
        measured.append(Arrow(f"result A_{j}", Role.RESULT, Diagram.ACCELERATION, ORIGIN, aj, f"A_{j}"))
        values["a"] = _a(aj.norm())
        self.steps.append((
            f"The trial lines meet at {_img(j)}. Measure {', '.join(parts)} and A_{j} (from O_a to {_img(j)}) = $a; "
            f"{'; '.join(alphas)}.",
            (Point(f"image {j}", Role.LABEL, Diagram.ACCELERATION, aj, _img(j)), *measured),
            eq, values, StepKind.ANSWER))

    def image(self, step: FixedToLink) -> None:
        """Acceleration image of point D on a link PQ: the triangle p'q'd' similar to PQD (notes,
        "Acceleration image"), placed by the similar triangle itself (the complex ratio (D-P)/(Q-P))."""
        pos = self.pose.positions
        a, link = step.point, step.link
        d = a.name
        p, q = link.joints
        ap, aq = self.acc[p], self.acc[q]
        ad, t, _ = image_point(pos[p], pos[q], pos[d], ap, aq)
        ip, iq, idd = _img(p), _img(q), _img(d)
        self.acc[d] = ad
        self.steps.append((
            f"Acceleration image of link {link.number}: on {ip}{iq} draw the triangle {ip}{iq}{idd} similar to "
            f"{p}{q}{d}, in the same order of letters (it is {p}{q}{d} turned and scaled as {ip}{iq} is {p}{q}). "
            f"Join O_a to {idd}: A_{d} = $a.",
            (Polygon(f"acceleration image {p}{q}{d}", Role.IMAGE, Diagram.ACCELERATION, (ap, aq, ad)),
             Point(f"image {d}", Role.LABEL, Diagram.ACCELERATION, ad, idd),
             Arrow(f"result A_{d}", Role.RESULT, Diagram.ACCELERATION, ORIGIN, ad, f"A_{d}")),
            None, {"a": _a(ad.norm())}, StepKind.ANSWER))

    def _equation(self, arms, j: str, guided: bool) -> VectorEquation:
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
        if guided:
            (_, c), = arms
            return VectorEquation((Term("A", j, False, True),), side(c))
        (_, p), (_, q) = arms
        if p in m.ground:
            p, q = q, p
        return VectorEquation(side(q), side(p)) if q in m.ground else VectorEquation(side(p), side(q))

    def _equation_words(self, eq: VectorEquation, arms, j: str, guided: bool) -> str:
        m = self.m
        links = " and ".join(f"link {l.number} ({l.label})" for l, _ in arms)
        dirs = []
        for link, c in arms:
            n, t = component_name(j, c, "n", m), component_name(j, c, "t", m)
            dirs.append(f"{n} \u2225 {c}{j} towards {c}, {t} \u22a5 {c}{j}")
        if guided:
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
                                    scale, tuple(self.warnings), self.alpha)
