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

from ..entities import Arrow, Diagram, Point, Role, TrialLine
from ..errors import DegenerateInput
from ..geometry import ORIGIN, Line, Tolerance, Vec
from ..mechanisms.assembly import CrankTip, Dyad, FixedToLink, SlotAlongGuide, SlotThrough, TwoLines, assembly_plan
from ..mechanisms.model import Mechanism, slide_line
from ..record import StepKind, Term, Value, VectorEquation
from ..tolerance import SINGULAR_SINE
from .analyses import AccelerationAnalysis, VelocityAnalysis
from .common import PolygonDrawing, dyad_arms, component_name, image_name, image_point, joined, sense
from .equations import acceleration_caption, acceleration_equation, acceleration_slot_equation

PRIME = "'"


def _img(joint: str) -> str:
    return image_name(joint, PRIME)


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

    what, symbol, pole, diagram = "acceleration polygon", "A", "O_a", Diagram.ACCELERATION

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

    def _normal(self, name: str, j: str, centre: str, number: int, eq) -> tuple[Vec, Line]:
        """From the image of ``centre`` the normal component omega^2 r towards it (r from the centre to the
        joint ``j``, link ``number``), and through its tip the trial line of the tangential component, square
        to the link; components named for ``name`` (J, or the slotted link's point under J).  Returns the
        tip and that line."""
        m = self.m
        r = self.pose.positions[j] - self.pose.positions[centre]
        w = self.va.angular[number]
        an = r * (-w * w)
        start = self.acc[centre]
        tip = start + an
        self.normal[(name, centre)] = an
        comp, trial_name = component_name(name, centre, "n", m), component_name(name, centre, "t", m)
        at = "O_a" if centre in m.ground else _img(centre)
        self.steps.append((
            f"From {at} draw {comp} = \u03c9_{number}\u00b2 \u00b7 {centre}{j} ($an), parallel to "
            f"{centre}{j} towards {centre}; through its tip draw the direction of {trial_name}, "
            f"perpendicular to {centre}{j}.",
            (Arrow(comp, Role.KNOWN, Diagram.ACCELERATION, start, tip, comp),
             TrialLine(f"trial {trial_name}", Role.TRIAL, Diagram.ACCELERATION, tip, r.perp(),
                       f"\u22a5 {centre}{j}")),
            eq, {"an": _a(an.norm())}, StepKind.CONSTRUCTION))
        return tip, Line(tip, r.perp())

    def _sliding_trial(self, name: str, tip: Vec, g: Vec, eq) -> Line:
        """Through ``tip`` (the Coriolis component's) the direction of the sliding component ``name``."""
        return self.parallel_trial(f"Through its tip draw the direction of the sliding component {name}, "
                                   f"parallel to the slot.", f"trial {name}", tip, g, eq, True)

    def slot_trial(self, j: str, jg: str, on: int, g: Vec, eq) -> tuple[Line, Vec]:
        """J in the slot of link ``on``: the acceleration image of the link's point JG under J, the Coriolis
        component from it, and through its tip the trial line of the sliding component.  Returns that line
        and the Coriolis component's tip."""
        a_jg = self._acceleration_on(on, jg)
        self.acc[jg] = a_jg
        self.steps.append((f"Mark {_img(jg)}, the acceleration image of the point {jg} of link {on} "
                           f"under {j} (A_{jg} = $a).",
                           (Point(f"acceleration image {jg}", Role.LABEL, Diagram.ACCELERATION, a_jg, _img(jg)),),
                           eq, {"a": _a(a_jg.norm())}, StepKind.CONSTRUCTION))
        v_rel = self.va.velocities[j] - self.va.velocities[jg]
        tip = self._coriolis(on, v_rel, a_jg, f"A_{j}{jg}^c", f"{j}{jg}", jg, eq)
        return self._sliding_trial(f"A_{j}{jg}^s", tip, g, eq), tip

    def dyad(self, step: Dyad) -> None:
        """One vector equation: the known normal (and Coriolis) components, two trial lines, their crossing."""
        m, pos = self.m, self.pose.positions
        j = step.joint
        guided, on, arms = dyad_arms(step)
        eq = acceleration_equation(m, self.crank.tip, arms, j, guided, step.coincident if on is not None else "")
        self.equations.append((acceleration_caption(m, eq, arms, j, guided, step), eq))
        trials: list[Line] = []
        tips: dict[str, Vec] = {}
        for link, centre in arms:
            tips[centre], line = self._normal(j, j, centre, link.number, eq)
            trials.append(line)
        aj, slide_tip = self.close_dyad(step, trials, eq)
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
        m, pos = self.m, self.pose.positions
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
                trials.append(self.guide_trial(j, g, eq, f"trial A_{j} guide"))
                tips.append(None)
                continue
            line, tip = self.slot_trial(j, jg, sl.on, g, eq)
            trials.append(line)
            tips.append((jg, tip))
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
        eq = acceleration_slot_equation(m, self.crank.tip, j, jg, c)
        n_name, t_name = component_name(jg, c, "n", m), component_name(jg, c, "t", m)
        self.equations.append((
            f"Relative acceleration equation at the sliding joint {j} ({jg} the point of link {k.number} under "
            f"{j}): {eq.text(marks=False)}, with {n_name} \u2225 {c}{j} towards {c}, {t_name} \u22a5 {c}{j}, "
            f"A_{jg}{j}^s \u2225 slot and the Coriolis component A_{jg}{j}^c = 2 \u03c9_{k.number} \u00d7 "
            f"V_{jg}{j}; two unknown magnitudes.", eq))
        tip_n, square = self._normal(jg, j, c, k.number, eq)
        v_rel = vel.velocities[jg] - vel.velocities[j]
        tip_c = self._coriolis(k.number, v_rel, self.acc[j], f"A_{jg}{j}^c", f"{jg}{j}", j, eq)
        a = self._close(step, [square, self._sliding_trial(f"A_{jg}{j}^s", tip_c, g, eq)])
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
             Arrow(f"result A_{jg}", Role.RESULT, Diagram.ACCELERATION, ORIGIN, a, f"A_{jg}")),
            eq, {"t": _a(a_t.norm()), "s": _a((a - tip_c).norm()), "a": _a(a.norm()),
                 "al": Value("angular acceleration", abs(al))}, StepKind.ANSWER))
        self._slotted_image(k.number, c, jg, j)

    def slot_along_guide(self, step: SlotAlongGuide) -> None:
        """The yoke translates, J slides in its slot (JG the yoke's point under J): A_J = A_JG + A_J,JG^s, with
        A_JG along the guide and A_J,JG^s along the slot; the yoke does not turn, so there is no Coriolis
        component (2 omega x V_J,JG = 0) -- through O_a parallel to the guide, through j' parallel to the slot."""
        m = self.m
        j, jg, k = step.joint, step.coincident, step.link
        eq = VectorEquation((Term("A", j, True, True),),
                            (Term("A", jg, False, True), Term("A", f"{j}{jg}", False, True, "s")))
        self.equations.append((
            f"Relative acceleration equation at the sliding joint {j} ({jg} the point of the yoke, link "
            f"{k.number}, under {j}): {eq.text(marks=False)}, with A_{jg} ∥ guide and A_{j}{jg}^s ∥ slot; "
            f"the yoke does not turn (ω_{k.number} = 0), so A_{j}{jg}^c = 2 ω_{k.number} × V_{j}{jg} = 0 "
            f"and it has no normal or tangential parts; two unknown magnitudes.", eq))
        a = self.yoke_crossing(step, eq, f"A_{j}{jg}^s", _img(j), self.acc)
        self.coriolis[f"A_{j}{jg}^c"] = ORIGIN
        self.sliding[f"A_{j}{jg}^s"] = self.acc[j] - a
        for number in (k.number, *(sl.number for sl in (*step.guides, step.slide) if sl.number is not None)):
            self.ang[number] = 0.0
        names = " = ".join(f"A_{x}" for x in m.points_of(k.number))
        self.steps.append((
            f"The trial lines meet at {_img(jg)}. Measure A_{jg} (from O_a to {_img(jg)}) = $a and "
            f"A_{j}{jg}^s (from {_img(jg)} to {_img(j)}) = $s; the yoke does not turn (α_{k.number} = 0), "
            f"so {names} = A_{jg}.",
            (Point(f"acceleration image {jg}", Role.LABEL, Diagram.ACCELERATION, a, _img(jg)),
             Arrow(f"result A_{jg}", Role.RESULT, Diagram.ACCELERATION, ORIGIN, a, f"A_{jg}"),
             Arrow(f"result A_{j}{jg}^s", Role.RESULT, Diagram.ACCELERATION, a, self.acc[j], f"A_{j}{jg}^s")),
            eq, {"a": _a(a.norm()), "s": _a((self.acc[j] - a).norm())}, StepKind.ANSWER))

    def _slotted_image(self, number: int, c: str, jg: str, j: str) -> None:
        """The further points of the slotted link (the lever's end P): each image x' on the link's
        acceleration image through the image of its known point ``c`` and ``jg``', the triangle c'jg'x'
        similar to C JG X, and its vector from O_a."""
        m = self.m
        others = [x for x in m.points_of(number) if x != c and x != jg and x not in m.ground]
        if not others:
            return
        first = "O_a" if c in m.ground else _img(c)
        ents, values, parts = [], {}, []
        for i, x in enumerate(others):
            ents += [Point(f"acceleration image {x}", Role.LABEL, Diagram.ACCELERATION, self.acc[x], _img(x)),
                     Arrow(f"result A_{x}", Role.RESULT, Diagram.ACCELERATION, ORIGIN, self.acc[x], f"A_{x}")]
            values[f"a{i}"] = _a(self.acc[x].norm())
            parts.append(f"{_img(x)} ({joined(first, _img(jg), _img(x))} similar to {c}{j}{x}; "
                         f"A_{x} from O_a to {_img(x)} = $a{i})")
        self.steps.append((f"Acceleration image of link {number}: mark " + ", ".join(parts) + ".",
                           tuple(ents), None, values, StepKind.ANSWER))

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
        self.image_answer(
            f"Acceleration image of link {link.number}: on {joined(ip, iq)} draw the triangle {joined(ip, iq, idd)} "
            f"similar to {p}{q}{d}, in the same order of letters (it is {p}{q}{d} turned and scaled as "
            f"{joined(ip, iq)} is {p}{q}). "
            f"Join O_a to {idd}: A_{d} = $a.", "acceleration image", p, q, d, (ap, aq, ad), idd, {"a": _a(ad.norm())})

    def analysis(self, scale: float | None) -> AccelerationAnalysis:
        """The record in the notes' order: equations, pole, scale, then the drawing steps."""
        rec = self.record("acceleration", scale, self.known)
        return AccelerationAnalysis(rec, self.va, self.acc, self.normal, self.tangential, self.ang, self.cond,
                                    scale, tuple(self.warnings), self.alpha, self.coriolis, self.sliding)
