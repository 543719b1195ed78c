"""The velocity polygon, drawn step by step as in the notes ("Graphical velocity analysis").

From the pole O_v the known velocity of the crank tip is drawn to scale; every joint found by a dyad
gives one vector equation, V_C = V_B + V_CB, solved by two trial lines of known direction whose crossing
is the image point c.  Velocities of points fixed to a link come from its velocity image.  Every value
returned is read off the figure: absolute velocities are the vectors O_v->j, relative velocities the
sides of the polygon, and angular velocities the relative velocities divided by the link lengths.

The scale is the drawing's choice (it knows the room it has): the record carries a scale bar whose
value is filled in by the drawing, unless the caller fixes ``scale``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Mapping

from ..entities import Arrow, Diagram, Point, Polygon, Role, ScaleBar, TrialLine
from ..errors import DegenerateInput
from ..geometry import ORIGIN, Line, Tolerance, Vec
from ..mechanisms.assembly import CircleAndGuide, CrankTip, Dyad, FixedToLink, SlotThrough, TwoLines, assembly_plan
from ..mechanisms.model import Mechanism, slide_line
from ..mechanisms.pose import Pose
from ..quantities import Measured
from ..record import Construction, StepKind, Term, Value, VectorEquation
from .common import (SINGULAR_SINE, WARN_SINE, PolygonDrawing, dead_centre, image_name, image_point, joined,
                     rounding_estimate, sense)


@dataclass(frozen=True)
class VelocityAnalysis:
    """The velocity polygon at one position and the values measured off it (SI, CCW positive).

    ``velocities`` maps every joint and point to its absolute velocity (fixed pivots: zero);
    ``relative[(J, P)]`` is V_JP, the side p->j of the polygon; ``angular`` maps link numbers to their
    angular velocity (slider blocks translate: 0); ``conditions`` maps each joint found by trial lines
    to the sine of the angle at which they crossed; ``warnings`` says what the reader must know;
    ``scale`` is the scale fixed by the caller (SI units per paper mm) or None (the drawing chooses).
    """

    construction: Construction
    pose: Pose
    velocities: Mapping[str, Vec]
    relative: Mapping[tuple[str, str], Vec]
    angular: Mapping[int, float]
    conditions: Mapping[str, float]
    scale: float | None
    warnings: tuple[str, ...]
    omega: float = 0.0

    @property
    def at_rest(self) -> bool:
        """omega = 0: nothing moves, nothing is drawn and nothing is measured."""
        return self.omega == 0.0

    @property
    def worst_condition(self) -> float:
        return min(self.conditions.values(), default=1.0)

    @property
    def relative_error_estimate(self) -> float:
        """Rough relative error of the measured values from rounding, growing as 1/sine^2 near
        singular positions."""
        return rounding_estimate(self.worst_condition)

    def scales(self) -> dict[str, float]:
        """The input's scale of each kind, against which small values are judged: |V_B| and |omega_1|."""
        if self.at_rest:
            return {}
        return {"velocity": max(v.norm() for v in self.velocities.values()),
                "angular velocity": abs(self.omega)}

    def measured(self, m: Mechanism) -> list[Measured]:
        """Absolute velocities of the moving joints and points, relative velocities between moving
        joints, and the angular velocities of the links that are neither the crank nor a slider block (none
        at rest: every one is zero by the scene's own data, not by construction)."""
        if self.at_rest:
            return []
        c = self.worst_condition
        out = [Measured(f"V_{n}", "velocity", v, c) for n, v in self.velocities.items() if n not in m.ground]
        out += [Measured(f"V_{j}{p}", "velocity", v, c) for (j, p), v in self.relative.items()
                if p not in m.ground]
        skip = {m.crank} | {s.number for s in m.slides}
        out += [Measured(f"omega_{n}", "angular velocity", w, c) for n, w in sorted(self.angular.items())
                if n not in skip]
        return out


def velocity_polygon(m: Mechanism, pose: Pose, omega: float, *, scale: float | None = None) -> VelocityAnalysis:
    """Draw the velocity polygon of ``m`` at ``pose`` with crank angular velocity ``omega`` (rad/s,
    CCW positive).  ``scale`` (SI units per paper mm) fixes the scale; by default the drawing chooses."""
    plan = assembly_plan(m)
    if not math.isfinite(omega):
        raise DegenerateInput(f"the crank speed must be finite, not {omega!r} rad/s")
    crank = plan[0]
    assert isinstance(crank, CrankTip)
    if omega == 0.0:
        return _rest(m, pose, crank, plan)
    poly = _Polygon(m, pose, crank, omega)
    poly.draw_plan(plan)
    return poly.analysis(scale)


def _rest(m: Mechanism, pose: Pose, crank: CrankTip, plan) -> VelocityAnalysis:
    """The mechanism at rest (omega = 0, e.g. released from rest): every velocity is zero, so the polygon
    shrinks to its pole.  The names are those of the polygon at 1 rad/s (velocities are linear in omega),
    the values exactly zero; the accelerations then have no normal and no Coriolis parts."""
    unit = _Polygon(m, pose, crank, 1.0)
    unit.draw_plan(plan)
    n = crank.link.number
    rec = Construction("Velocity polygon").then(
        f"The mechanism is at rest (\u03c9_{n} = 0): every velocity is zero and the velocity polygon is its "
        f"pole O_v alone.", kind=StepKind.GIVEN)
    return VelocityAnalysis(rec, pose, {k: ORIGIN for k in unit.vel}, {k: ORIGIN for k in unit.rel},
                            {k: 0.0 for k in unit.ang}, {}, None, (), 0.0)


def _v(value: float) -> Value:
    return Value("velocity", value)


def _w(value: float) -> Value:
    return Value("angular velocity", abs(value))


class _Polygon(PolygonDrawing):
    """The polygon while it is drawn: image points found so far, measured values, pending steps."""

    what = "velocity polygon"

    def __init__(self, m: Mechanism, pose: Pose, crank: CrankTip, omega: float) -> None:
        self.m, self.pose, self.crank, self.omega = m, pose, crank, omega
        pos = pose.positions
        self.vel: dict[str, Vec] = {g: ORIGIN for g in m.ground}
        self.rel: dict[tuple[str, str], Vec] = {}
        self.ang: dict[int, float] = {s.number: 0.0 for s in m.slides if s.number is not None and s.on is None}
        self.cond: dict[str, float] = {}
        self.warnings: list[str] = []
        self.equations: list[tuple[str, VectorEquation]] = []
        self.steps: list[tuple] = []          # (words, entities, equation, values, kind)
        # the known vector: V_B = omega1 k x O1B, drawn from the pole
        v_tip = (pos[crank.tip] - pos[crank.pivot]).perp() * omega
        self.v_known = v_tip
        self.vel[crank.tip] = v_tip
        self.ang[crank.link.number] = omega
        self.tol = Tolerance(v_tip.norm(), sine=SINGULAR_SINE)
        n, tip, name = crank.link.number, crank.tip, f"{crank.pivot}{crank.tip}"
        self.steps.append((
            f"Draw V_{tip} = \u03c9_{n} \u00d7 {name} from O_v, perpendicular to {name} "
            f"($v, \u03c9_{n} {sense(omega)}); its tip is {image_name(tip)}.",
            (Arrow(f"V_{tip}", Role.KNOWN, Diagram.VELOCITY, ORIGIN, v_tip, f"V_{tip}"),
             Point(f"image {tip}", Role.LABEL, Diagram.VELOCITY, v_tip, image_name(tip))),
            None, {"v": _v(v_tip.norm())}, StepKind.CONSTRUCTION))

    def _what(self, j: str, centre: str) -> str:
        """The velocity a trial line carries: absolute V_J from a fixed centre, else relative V_JP."""
        return f"V_{j}" if centre in self.m.ground else f"V_{j}{centre}"

    def _omega_of(self, number: int) -> float:
        """The angular velocity of a placed link, from two of its points' velocities if not yet known."""
        if number not in self.ang:
            pts = [x for x in self.m.points_of(number) if x in self.vel]
            a, b = pts[0], pts[1]
            r = self.pose.positions[b] - self.pose.positions[a]
            self.ang[number] = r.cross(self.vel[b] - self.vel[a]) / r.dot(r)
        return self.ang[number]

    def _velocity_on(self, number: int, point: str) -> Vec:
        """The velocity of the point of link ``number`` standing at ``point``'s position (rigid body)."""
        pos = self.pose.positions
        x = next(x for x in self.m.points_of(number) if x in self.vel)
        return self.vel[x] + (pos[point] - pos[x]).perp() * self._omega_of(number)

    def dyad(self, step: Dyad) -> None:
        """One vector equation, V_C = V_B + V_CB: two trial lines and their crossing c."""
        if isinstance(step, SlotThrough):
            return self.slot_through(step)
        if isinstance(step, TwoLines):
            return self.two_lines(step)
        m, pos = self.m, self.pose.positions
        j = step.joint
        guided = isinstance(step, CircleAndGuide)
        on = step.slide.on if guided else None
        arms = [(step.link, step.centre)] if guided else [(step.link_a, step.first), (step.link_b, step.second)]
        eq = _equation(arms, j, m, guided, step.coincident if on is not None else "")
        self.equations.append((_equation_caption(eq, arms, j, m, step), eq))
        trials: list[Line] = []
        for link, centre in arms:
            pj = pos[j] - pos[centre]
            trials.append(Line(self.vel[centre], pj.perp()))
            at = "O_v" if centre in m.ground else image_name(centre)
            what = self._what(j, centre)
            self.steps.append((f"Draw the direction of {what} through {at}, perpendicular to {centre}{j}.",
                               (TrialLine(f"trial {what}", Role.TRIAL, Diagram.VELOCITY, self.vel[centre],
                                          pj.perp(), f"\u22a5 {centre}{j}"),), eq, {}, StepKind.CONSTRUCTION))
        slide_v = None
        if guided:
            g = self.pose.lines[j].direction
            if on is None:
                trials.append(Line(ORIGIN, g))
                self.steps.append((f"Draw the direction of V_{j} through O_v, parallel to the guide.",
                                   (TrialLine(f"trial V_{j}", Role.TRIAL, Diagram.VELOCITY, ORIGIN, g,
                                              "\u2225 guide"),), eq, {}, StepKind.CONSTRUCTION))
            else:
                jg = step.coincident
                v_jg = self._velocity_on(on, jg)
                self.vel[jg] = v_jg
                trials.append(Line(v_jg, g))
                self.steps.append((
                    f"Mark {image_name(jg)}, the image of the point {jg} of link {on} under {j} "
                    f"(V_{jg} = $vg); through it draw the direction of V_{j}{jg}, parallel to the slot.",
                    (Point(f"image {jg}", Role.LABEL, Diagram.VELOCITY, v_jg, image_name(jg)),
                     TrialLine(f"trial V_{j}{jg}", Role.TRIAL, Diagram.VELOCITY, v_jg, g, "\u2225 slot")),
                    eq, {"vg": _v(v_jg.norm())}, StepKind.CONSTRUCTION))
                slide_v = v_jg
        vj = self._close(step, trials)
        self.vel[j] = vj
        dead = dead_centre(pos, self.crank, arms, j)
        if dead:
            self.warnings.append(dead)
        # measure: the sides of the polygon, and the angular velocities they give
        measured = []
        for link, centre in arms:
            v_rel = vj - self.vel[centre]
            self.rel[(j, centre)] = v_rel
            r = pos[j] - pos[centre]
            self.ang[link.number] = r.cross(v_rel) / r.dot(r)
            what = self._what(j, centre)
            measured.append(Arrow(f"result {what}", Role.RESULT, Diagram.VELOCITY, self.vel[centre], vj, what))
        if slide_v is not None:
            self.rel[(j, step.coincident)] = vj - slide_v
            what = f"V_{j}{step.coincident}"
            measured.append(Arrow(f"result {what}", Role.RESULT, Diagram.VELOCITY, slide_v, vj, what))
        if (guided or all(c not in m.ground for _, c in arms)) and all(c not in m.ground for _, c in arms):
            measured.append(Arrow(f"result V_{j}", Role.RESULT, Diagram.VELOCITY, ORIGIN, vj, f"V_{j}"))
        if guided and step.slide.number is not None:
            self.ang[step.slide.number] = 0.0 if on is None else self._omega_of(on)
        self._answer(j, measured, [(link, centre, self._what(j, centre)) for link, centre in arms], eq)

    def _answer(self, j: str, measured: list[Arrow], rates, eq, image: str | None = None) -> None:
        values: dict[str, Value] = {}
        parts = []
        for i, a in enumerate(measured):
            values[f"m{i}"] = _v((a.tip - a.tail).norm())
            parts.append(f"{a.label} = $m{i}")
        omegas = []
        for i, (link, centre, what) in enumerate(rates):
            w = self.ang[link.number]
            values[f"w{i}"] = _w(w)
            omegas.append(f"\u03c9_{link.number} = {what}/{centre}{j} = $w{i} {sense(w)}")
        at = image or image_name(j)
        tail = f"; {'; '.join(omegas)}" if omegas else ""
        self.steps.append((f"The trial lines meet at {at}. Measure {', '.join(parts)}{tail}.",
                           (Point(f"image {j}" if image is None else f"image {image}", Role.LABEL, Diagram.VELOCITY,
                                  measured[0].tip, at), *measured),
                           eq, values, StepKind.ANSWER))

    def two_lines(self, step: TwoLines) -> None:
        """J carried along two lines (a PRP dyad): for each, V_J = V_JG + V_J,JG along it (JG the point of
        the slotted link under J; on a fixed guide V_J itself lies along it) -- two trial lines."""
        m, pos = self.m, self.pose.positions
        j = step.joint
        terms, trials, entities, words, rels = [], [], [], [], []
        for sl, jg in ((step.slide_a, step.coincident_a), (step.slide_b, step.coincident_b)):
            g = slide_line(m, sl, pos).direction
            if sl.on is None:
                terms.append((Term("V", j, False, True),))
                trials.append(Line(ORIGIN, g))
                entities.append(TrialLine(f"trial V_{j} guide", Role.TRIAL, Diagram.VELOCITY, ORIGIN, g, "\u2225 guide"))
                words.append(f"through O_v the direction of V_{j}, parallel to the guide")
            else:
                v_jg = self._velocity_on(sl.on, jg)
                self.vel[jg] = v_jg
                terms.append((Term("V", jg, True, True), Term("V", f"{j}{jg}", False, True)))
                trials.append(Line(v_jg, g))
                entities += [Point(f"image {jg}", Role.LABEL, Diagram.VELOCITY, v_jg, image_name(jg)),
                             TrialLine(f"trial V_{j}{jg}", Role.TRIAL, Diagram.VELOCITY, v_jg, g, "\u2225 slot")]
                words.append(f"through {image_name(jg)} (the image of the point {jg} of link {sl.on} under {j}) "
                             f"the direction of V_{j}{jg}, parallel to its slot")
                rels.append((jg, v_jg))
        eq = VectorEquation(terms[0], terms[1])
        self.equations.append((f"Relative velocity equation at {j}, carried along two lines: "
                               f"{eq.text(marks=False)}; two unknown magnitudes.", eq))
        self.steps.append((f"Draw {words[0]}, and {words[1]}.", tuple(entities), eq, {}, StepKind.CONSTRUCTION))
        vj = self._close(step, trials)
        self.vel[j] = vj
        measured = [Arrow(f"result V_{j}", Role.RESULT, Diagram.VELOCITY, ORIGIN, vj, f"V_{j}")]
        for jg, v_jg in rels:
            self.rel[(j, jg)] = vj - v_jg
            measured.append(Arrow(f"result V_{j}{jg}", Role.RESULT, Diagram.VELOCITY, v_jg, vj, f"V_{j}{jg}"))
        for sl in (step.slide_a, step.slide_b):
            if sl.number is not None:
                self.ang[sl.number] = 0.0 if sl.on is None else self._omega_of(sl.on)
        self._answer(j, measured, [], eq)

    def slot_through(self, step: SlotThrough) -> None:
        """The slotted link turns about its known point P; J slides in its slot.  With JG the point of the
        slotted link under J:  V_JG = V_P + V_JG,P (square to PJ) = V_J + V_JG,J (along the slot)."""
        m, pos = self.m, self.pose.positions
        j, jg, c, k = step.joint, step.coincident, step.centre, step.link
        r = pos[j] - pos[c]
        g = self.pose.lines[j].direction
        eq = _slot_equation(j, jg, c, m)
        self.equations.append((
            f"Relative velocity equation at the sliding joint {j} (the point {jg} of link {k.number} under "
            f"{j}): {eq.text(marks=False)}, with {self._what(jg, c)} \u22a5 {c}{j} and V_{jg}{j} \u2225 slot; "
            f"two unknown magnitudes.", eq))
        at = "O_v" if c in m.ground else image_name(c)
        self.steps.append((f"Draw the direction of {self._what(jg, c)} through {at}, perpendicular to {c}{j}.",
                           (TrialLine(f"trial {self._what(jg, c)}", Role.TRIAL, Diagram.VELOCITY, self.vel[c],
                                      r.perp(), f"\u22a5 {c}{j}"),), eq, {}, StepKind.CONSTRUCTION))
        self.steps.append((f"Draw the direction of V_{jg}{j} through {image_name(j)}, parallel to the slot.",
                           (TrialLine(f"trial V_{jg}{j}", Role.TRIAL, Diagram.VELOCITY, self.vel[j], g,
                                      "\u2225 slot"),), eq, {}, StepKind.CONSTRUCTION))
        v = self._close(step, [Line(self.vel[c], r.perp()), Line(self.vel[j], g)])
        self.vel[jg] = v
        self.rel[(jg, c)] = v - self.vel[c]
        self.rel[(jg, j)] = v - self.vel[j]
        w = r.cross(v - self.vel[c]) / r.dot(r)
        self.ang[k.number] = w
        if step.slide.number is not None:
            self.ang[step.slide.number] = w
        for x in m.points_of(k.number):
            if x not in self.vel:
                self.vel[x] = self.vel[c] + (pos[x] - pos[c]).perp() * w
        measured = [Arrow(f"result {self._what(jg, c)}", Role.RESULT, Diagram.VELOCITY, self.vel[c], v,
                          self._what(jg, c)),
                    Arrow(f"result V_{jg}{j}", Role.RESULT, Diagram.VELOCITY, self.vel[j], v, f"V_{jg}{j}")]
        self._answer(jg, measured, [(k, c, self._what(jg, c))], eq, image=image_name(jg))
        others = [x for x in m.points_of(k.number) if x not in (c,) and x not in m.ground]
        if others:
            first = "the pole O_v" if c in m.ground else image_name(c)
            self.steps.append((
                f"The velocity image of link {k.number} runs from {first} (the image of {c}) through "
                f"{image_name(jg)}: mark " + ", ".join(f"{image_name(x)} ({image_name(x)} is {c}{x} turned 90\u00b0 "
                                                      f"and scaled by \u03c9_{k.number})" for x in others) + ".",
                tuple(Point(f"image {x}", Role.LABEL, Diagram.VELOCITY, self.vel[x], image_name(x)) for x in others),
                None, {}, StepKind.CONSTRUCTION))

    def image(self, step: FixedToLink) -> None:
        """Velocity image of point D of a link placed by two of its points P, Q: the triangle pqd is similar
        to PQD (notes, Example 4).

        d is placed by the similar triangle itself (the notes' option 1), exact for a rigid link and well
        conditioned wherever D lies.  The notes' option 2 -- the perpendiculars to PD through p and to QD
        through q -- is drawn as the visible construction when those lines cross at a readable angle; on
        (or nearly on) the line PQ they are parallel and d simply divides pq as D divides PQ.
        """
        pos, vel = self.pose.positions, self.vel
        link, d = step.link, step.name
        p, q = step.via
        P, Q, D = pos[p], pos[q], pos[d]
        vp, vq = vel[p], vel[q]
        ip, iq, idd = (("O_v" if x in self.m.ground else image_name(x)) for x in (p, q, d))
        vd, t, _ = image_point(P, Q, D, vp, vq)
        self._omega_of(link.number)
        pd, qd = D - P, D - Q
        crossing = abs(pd.unit().cross(qd.unit())) if pd.norm() > 0 and qd.norm() > 0 else 0.0
        if crossing < WARN_SINE:
            self.steps.append((f"{d} lies on (or next to) the line {p}{q}: mark {idd} dividing {joined(ip, iq)} as {d} "
                               f"divides {p}{q} ({p}{d}/{p}{q} = $t).", (), None,
                               {"t": Value("number", t)}, StepKind.CONSTRUCTION))
        else:
            self.steps.append((
                f"Velocity image of link {link.number}: through {ip} draw the perpendicular to {p}{d}, "
                f"through {iq} the perpendicular to {q}{d}; they meet at {idd}.",
                (TrialLine(f"trial V_{d}{p}", Role.TRIAL, Diagram.VELOCITY, vp, pd.perp(), f"\u22a5 {p}{d}"),
                 TrialLine(f"trial V_{d}{q}", Role.TRIAL, Diagram.VELOCITY, vq, qd.perp(), f"\u22a5 {q}{d}")),
                None, {}, StepKind.CONSTRUCTION))
        vel[d] = vd
        self.rel[(d, p)] = vd - vp
        self.steps.append((
            f"The shaded triangle {joined(ip, iq, idd)} is the velocity image of {p}{q}{d}. Join O_v to {idd}: "
            f"V_{d} = $v.",
            (Polygon(f"image {p}{q}{d}", Role.IMAGE, Diagram.VELOCITY, (vp, vq, vd)),
             Point(f"image {d}", Role.LABEL, Diagram.VELOCITY, vd, idd),
             Arrow(f"result V_{d}", Role.RESULT, Diagram.VELOCITY, ORIGIN, vd, f"V_{d}")),
            None, {"v": _v(vd.norm())}, StepKind.ANSWER))

    def analysis(self, scale: float | None) -> VelocityAnalysis:
        """The record in the notes' order: equations, pole, scale, then the drawing steps."""
        known = self.v_known.norm()
        rec = Construction("Velocity polygon")
        for words, eq in self.equations:
            rec = rec.then(words, equation=eq, kind=StepKind.GIVEN)
        rec = rec.then("Choose the pole O_v.", Point("pole O_v", Role.LABEL, Diagram.VELOCITY, ORIGIN, "O_v"))
        rec = rec.then(f"Choose the velocity scale: 1 mm = $s; V_{self.crank.tip} is $len.",
                       ScaleBar("velocity scale", Role.SCALE_BAR, Diagram.VELOCITY, "velocity", scale),
                       values={"s": Value("scale", scale, "velocity"),
                               "len": Value("paper length", known, "velocity")})
        for words, entities, eq, values, kind in self.steps:
            rec = rec.then(words, *entities, equation=eq, values=values, kind=kind)
        return VelocityAnalysis(rec, self.pose, self.vel, self.rel, self.ang, self.cond, scale,
                                tuple(self.warnings), self.omega)


def _equation(arms, j: str, m: Mechanism, guided: bool, coincident: str = "") -> VectorEquation:
    """V_J = V_P + V_JP with the notes' marks; both centres moving: V_P + V_JP = V_Q + V_JQ; on a moving
    slot: V_P + V_JP = V_JG + V_J,JG (JG the slotted link's point under J)."""
    if coincident:
        (_, c), = arms
        left = (Term("V", coincident, True, True), Term("V", f"{j}{coincident}", False, True))
        if c in m.ground:
            return VectorEquation((Term("V", j, False, True),), left)
        return VectorEquation((Term("V", c, True, True), Term("V", f"{j}{c}", False, True)), left)
    moving = [(l, c) for l, c in arms if c not in m.ground]
    fixed = [(l, c) for l, c in arms if c in m.ground]
    if guided or fixed:
        left = (Term("V", j, False, True),)
        (_, c), = moving if moving else fixed[:1]
        if c in m.ground:
            return VectorEquation(left, (Term("V", f"{j}{c}", False, True),))
        return VectorEquation(left, (Term("V", c, True, True), Term("V", f"{j}{c}", False, True)))
    (_, p), (_, q) = moving
    return VectorEquation((Term("V", p, True, True), Term("V", f"{j}{p}", False, True)),
                          (Term("V", q, True, True), Term("V", f"{j}{q}", False, True)))


def _slot_equation(j: str, jg: str, c: str, m: Mechanism) -> VectorEquation:
    """V_JG = V_J + V_JG,J about a fixed centre; V_C + V_JG,C = V_J + V_JG,J about a moving one."""
    right = (Term("V", j, True, True), Term("V", f"{jg}{j}", False, True))
    if c in m.ground:
        return VectorEquation((Term("V", jg, False, True),), right)
    return VectorEquation((Term("V", c, True, True), Term("V", f"{jg}{c}", False, True)), right)


def _equation_caption(eq: VectorEquation, arms, j: str, m: Mechanism, step) -> str:
    links = " and ".join(f"link {l.number} ({l.label})" for l, _ in arms)
    dirs = [f"V_{j}{c} \u22a5 {c}{j}" if c not in m.ground else f"V_{j} \u22a5 {c}{j}" for _, c in arms]
    if isinstance(step, CircleAndGuide):
        dirs.append(f"V_{j} \u2225 guide" if step.slide.on is None else f"V_{j}{step.coincident} \u2225 slot")
    return (f"Relative velocity equation on {links}: {eq.text(marks=False)}, with {', '.join(dirs)}; "
            f"two unknown magnitudes.")
