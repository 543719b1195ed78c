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

from ..entities import Arrow, Diagram, Point, Role, TrialLine
from ..errors import DegenerateInput
from ..geometry import ORIGIN, Line, Tolerance, Vec
from ..mechanisms.assembly import CrankTip, Dyad, FixedToLink, SlotAlongGuide, SlotThrough, TwoLines, assembly_plan
from ..mechanisms.model import Mechanism, slide_line
from ..mechanisms.pose import Pose
from ..record import Construction, StepKind, Term, Value, VectorEquation
from ..tolerance import SINGULAR_SINE, WARN_SINE
from .analyses import VelocityAnalysis
from .common import PolygonDrawing, dyad_arms, dead_centre, image_name, image_point, joined, sense
from .equations import velocity_caption, velocity_equation, velocity_slot_equation


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

    what, symbol, pole, diagram = "velocity polygon", "V", "O_v", Diagram.VELOCITY

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

    def _square_trial(self, what: str, centre: str, j: str, r: Vec, eq) -> Line:
        """The direction of ``what``, the velocity of J about ``centre`` (``r`` from it to J): through the image
        of the centre, square to the link."""
        at = "O_v" if centre in self.m.ground else image_name(centre)
        self.steps.append((f"Draw the direction of {what} through {at}, perpendicular to {centre}{j}.",
                           (TrialLine(f"trial {what}", Role.TRIAL, Diagram.VELOCITY, self.vel[centre],
                                      r.perp(), f"\u22a5 {centre}{j}"),), eq, {}, StepKind.CONSTRUCTION))
        return Line(self.vel[centre], r.perp())

    def slot_trial(self, j: str, jg: str, on: int, g: Vec, eq) -> tuple[Line, Vec]:
        """J in the slot of link ``on``: the image of the link's point JG under J, and through it the direction
        of V_J,JG along the slot.  Returns that line and V_JG."""
        v_jg = self._velocity_on(on, jg)
        self.vel[jg] = v_jg
        line = self.parallel_trial(
            f"Mark {image_name(jg)}, the image of the point {jg} of link {on} under {j} "
            f"(V_{jg} = $vg); through it draw the direction of V_{j}{jg}, parallel to the slot.",
            f"trial V_{j}{jg}", v_jg, g, eq, True,
            Point(f"image {jg}", Role.LABEL, Diagram.VELOCITY, v_jg, image_name(jg)),
            values={"vg": _v(v_jg.norm())})
        return line, v_jg

    def dyad(self, step: Dyad) -> None:
        """One vector equation, V_C = V_B + V_CB: two trial lines and their crossing c."""
        m, pos = self.m, self.pose.positions
        j = step.joint
        guided, on, arms = dyad_arms(step)
        eq = velocity_equation(arms, j, m, guided, step.coincident if on is not None else "")
        self.equations.append((velocity_caption(eq, arms, j, m, step), eq))
        trials = [self._square_trial(self._what(j, centre), centre, j, pos[j] - pos[centre], eq)
                  for _, centre in arms]
        vj, slide_v = self.close_dyad(step, trials, eq)
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
        eq = velocity_slot_equation(j, jg, c, m)
        self.equations.append((
            f"Relative velocity equation at the sliding joint {j} (the point {jg} of link {k.number} under "
            f"{j}): {eq.text(marks=False)}, with {self._what(jg, c)} \u22a5 {c}{j} and V_{jg}{j} \u2225 slot; "
            f"two unknown magnitudes.", eq))
        square = self._square_trial(self._what(jg, c), c, j, r, eq)
        slot = self.parallel_trial(f"Draw the direction of V_{jg}{j} through {image_name(j)}, parallel to the "
                                   f"slot.", f"trial V_{jg}{j}", self.vel[j], g, eq, True)
        v = self._close(step, [square, slot])
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
                                                      f"and scaled by \u03c9_{k.number}; V_{x} from O_v to "
                                                      f"{image_name(x)})" for x in others) + ".",
                tuple(e for x in others for e in (
                    Point(f"image {x}", Role.LABEL, Diagram.VELOCITY, self.vel[x], image_name(x)),
                    Arrow(f"result V_{x}", Role.RESULT, Diagram.VELOCITY, ORIGIN, self.vel[x], f"V_{x}"))),
                None, {}, StepKind.CONSTRUCTION))

    def slot_along_guide(self, step: SlotAlongGuide) -> None:
        """The yoke translates along its guide, J slides in its slot (JG the yoke's point under J): every
        point of the yoke has one velocity, along the guide, and V_J = V_JG + V_J,JG (along the slot) --
        through O_v parallel to the guide, through j parallel to the slot."""
        m = self.m
        j, jg, k = step.joint, step.coincident, step.link
        b = k.joints[0]
        eq = VectorEquation((Term("V", j, True, True),), (Term("V", jg, False, True), Term("V", f"{j}{jg}", False, True)))
        self.equations.append((
            f"Relative velocity equation at the sliding joint {j} ({jg} the point of the yoke, link {k.number}, "
            f"under {j}): {eq.text(marks=False)}, with V_{jg} = V_{b} ∥ guide (the yoke does not turn) and "
            f"V_{j}{jg} ∥ slot; two unknown magnitudes.", eq))
        v = self.yoke_crossing(step, eq, f"V_{j}{jg}", image_name(j), self.vel)
        self.rel[(j, jg)] = self.vel[j] - v
        self.ang[k.number] = 0.0
        for sl in (*step.guides, step.slide):
            if sl.number is not None:
                self.ang[sl.number] = 0.0
        measured = [Arrow(f"result V_{jg}", Role.RESULT, Diagram.VELOCITY, ORIGIN, v, f"V_{jg}"),
                    Arrow(f"result V_{j}{jg}", Role.RESULT, Diagram.VELOCITY, v, self.vel[j], f"V_{j}{jg}")]
        self._answer(jg, measured, [], eq, image=image_name(jg))
        self.steps.append((
            f"The yoke does not turn (ω_{k.number} = 0): its velocity image is the single point "
            f"{image_name(jg)}, so V_{' = V_'.join(m.points_of(k.number))} = V_{jg}.", (), None, {},
            StepKind.CONSTRUCTION))

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
        self.image_answer(f"The shaded triangle {joined(ip, iq, idd)} is the velocity image of {p}{q}{d}. Join O_v "
                          f"to {idd}: V_{d} = $v.", "image", p, q, d, (vp, vq, vd), idd, {"v": _v(vd.norm())})

    def analysis(self, scale: float | None) -> VelocityAnalysis:
        """The record in the notes' order: equations, pole, scale, then the drawing steps."""
        rec = self.record("velocity", scale, self.v_known.norm())
        return VelocityAnalysis(rec, self.pose, self.vel, self.rel, self.ang, self.cond, scale,
                                tuple(self.warnings), self.omega)
