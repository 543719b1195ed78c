"""The velocity polygon, drawn step by step as in the notes ("Graphical velocity analysis").

From the pole O_v the known velocity of the crank tip is drawn to scale; every joint found by a dyad
gives one vector equation, V_C = V_B + V_CB, solved by two trial lines of known direction whose crossing
is the image point c.  Velocities of points fixed to a link come from its velocity image.  Every value
returned is read off the figure: absolute velocities are the vectors O_v->j, relative velocities the
sides of the polygon, and angular velocities the relative velocities divided by the link lengths.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Mapping

from .errors import DegenerateInput, IndeterminatePosition
from .formatting import Formatter, si_format
from .geometry import ORIGIN, Contact, Line, Tolerance, Vec, intersect_lines
from .linkage import (CircleAndGuide, CrankTip, FixedToLink, Mechanism, Pose, TwoCircles,
                      assembly_plan, describe_angle)
from .record import Arrow, Construction, Diagram, Point, Polygon, Role, ScaleBar, Term, TrialLine, \
    VectorEquation

SINGULAR_SINE = 1e-4
"""Trial lines crossing at a sine below this mark a singular position (toggle, limit, change point).
The closest crossing a float figure can tell from a tangency (gap 1e-9 L) has a sine near 4.5e-5; the
conditioning of the measured values grows like 1/sine^2, so above 1e-4 they keep at least 7 digits."""

WARN_SINE = 1e-2
"""Below this the values are returned with a warning and an error estimate."""

DEAD_CENTRE_SINE = 1e-9
"""Crank and driven link closer to a line than this (sine of the angle between them) are at dead centre."""

SCALE_SERIES = (1.0, 2.0, 5.0)


def vector_scale(known: float, extent: float, *, known_mm: tuple[float, float] = (50.0, 100.0),
                 max_extent_mm: float = 110.0) -> float:
    """The 1-2-5 scale (units per paper mm) for a vector polygon.

    The finest scale at which the known vector is at most ``known_mm[1]`` long and the whole polygon
    (``extent``, its larger bounding-box side) fits in ``max_extent_mm``.  The 1-2-5 series steps by up
    to 2.5x, so with a well-proportioned polygon the known vector comes out 40..100 mm long (50..100
    unless its magnitude is 2.0..2.5 times a power of ten); a scale of 2.5 would close that gap but is not
    a 1-2-5 step, and a student's ruler reads 1-2-5 scales without arithmetic.
    """
    if not (known > 0 and math.isfinite(known) and math.isfinite(extent)):
        raise DegenerateInput("the known vector must be finite and non-zero to choose a scale")
    need = max(known / known_mm[1], extent / max_extent_mm)
    decade = 10.0 ** math.floor(math.log10(need))
    for m in SCALE_SERIES + (10.0,):
        s = m * decade
        if s >= need * (1 - 1e-12):
            return s
    raise AssertionError("unreachable")


@dataclass(frozen=True)
class VelocityAnalysis:
    """The velocity polygon at one position and the values measured off it (SI, CCW positive).

    ``velocities`` maps every joint and point to its absolute velocity (fixed pivots: zero);
    ``relative[(J, P)]`` is V_JP, the side p->j of the polygon; ``angular`` maps link numbers to their
    angular velocity (slider blocks translate: 0); ``conditions`` maps each joint found by trial lines
    to the sine of the angle at which they crossed; ``warnings`` says what the reader must know.
    """

    construction: Construction
    pose: Pose
    velocities: Mapping[str, Vec]
    relative: Mapping[tuple[str, str], Vec]
    angular: Mapping[int, float]
    conditions: Mapping[str, float]
    scale: float
    warnings: tuple[str, ...]

    @property
    def relative_error_estimate(self) -> float:
        """Rough relative error of the measured values from rounding, growing as 1/sine^2 near
        singular positions."""
        worst = min(self.conditions.values(), default=1.0)
        return 4.0 * 2.2e-16 / max(worst, 1e-300) ** 2


def image_name(joint: str) -> str:
    """The notes' lower-case label of a joint's image point: B -> b, O2 -> o2."""
    return joint[0].lower() + joint[1:]


def _sense(omega: float) -> str:
    return "counter-clockwise" if omega > 0 else "clockwise" if omega < 0 else "at rest"


def velocity_polygon(m: Mechanism, pose: Pose, omega: float, *, fmt: Formatter = si_format,
                     scale: float | None = None, max_extent_mm: float = 110.0) -> VelocityAnalysis:
    """Draw the velocity polygon of ``m`` at ``pose`` with crank angular velocity ``omega`` (rad/s,
    CCW positive).  ``scale`` (SI units per paper mm) overrides the 1-2-5 choice, which otherwise keeps
    the polygon within ``max_extent_mm`` of paper."""
    plan = assembly_plan(m)
    if omega == 0.0 or not math.isfinite(omega):
        raise DegenerateInput(f"the crank speed must be finite and non-zero, not {omega!r} rad/s")
    crank = plan[0]
    assert isinstance(crank, CrankTip)
    poly = _Polygon(m, pose, crank, omega, fmt)
    for step in plan[1:]:
        if isinstance(step, (TwoCircles, CircleAndGuide)):
            poly.dyad(step)
        elif isinstance(step, FixedToLink):
            poly.steps.extend(_image_steps(step, pose.positions, poly.vel, poly.rel, fmt))
    return poly.analysis(scale, max_extent_mm)


class _Polygon:
    """The polygon while it is drawn: image points found so far, measured values, pending steps."""

    def __init__(self, m: Mechanism, pose: Pose, crank: CrankTip, omega: float, fmt: Formatter) -> None:
        self.m, self.pose, self.crank, self.fmt = m, pose, crank, fmt
        pos = pose.positions
        self.vel: dict[str, Vec] = {g: ORIGIN for g in m.ground}
        self.rel: dict[tuple[str, str], Vec] = {}
        self.ang: dict[int, float] = {s.number: 0.0 for s in m.slides}
        self.cond: dict[str, float] = {}
        self.warnings: list[str] = []
        self.equations: list[tuple[str, VectorEquation]] = []
        self.steps: list[tuple[str, tuple, VectorEquation | None]] = []
        # the known vector: V_B = omega1 k x O1B, drawn from the pole
        v_tip = (pos[crank.tip] - pos[crank.pivot]).perp() * omega
        self.v_known = v_tip
        self.vel[crank.tip] = v_tip
        self.ang[crank.link.number] = omega
        self.tol = Tolerance(v_tip.norm(), sine=SINGULAR_SINE)
        n, tip, name = crank.link.number, crank.tip, f"{crank.pivot}{crank.tip}"
        self.steps.append((
            f"Draw V_{tip} = \u03c9_{n} \u00d7 {name} from O_v, perpendicular to {name} "
            f"({fmt('velocity', v_tip.norm())}, \u03c9_{n} {_sense(omega)}); its tip is {image_name(tip)}.",
            (Arrow(f"V_{tip}", Role.KNOWN, Diagram.VELOCITY, ORIGIN, v_tip, f"V_{tip}"),
             Point(f"image {tip}", Role.LABEL, Diagram.VELOCITY, v_tip, image_name(tip))),
            None))

    def _what(self, j: str, centre: str) -> str:
        """The velocity a trial line carries: absolute V_J from a fixed centre, else relative V_JP."""
        return f"V_{j}" if centre in self.m.ground else f"V_{j}{centre}"

    def dyad(self, step: TwoCircles | CircleAndGuide) -> None:
        """One vector equation, V_C = V_B + V_CB: two trial lines and their crossing c."""
        m, pos, fmt = self.m, self.pose.positions, self.fmt
        j = step.joint
        guided = isinstance(step, CircleAndGuide)
        arms = [(step.link, step.centre)] if guided else [(step.link_a, step.first), (step.link_b, step.second)]
        eq = _equation(arms, j, m, guided)
        self.equations.append((_equation_caption(eq, arms, j, m, step), eq))
        trials: list[Line] = []
        for link, centre in arms:
            pj = pos[j] - pos[centre]
            trials.append(Line(self.vel[centre], pj.perp()))
            at = "O_v" if centre in m.ground else image_name(centre)
            what = self._what(j, centre)
            self.steps.append((f"Draw the direction of {what} through {at}, perpendicular to {centre}{j}.",
                               (TrialLine(f"trial {what}", Role.TRIAL, Diagram.VELOCITY, self.vel[centre],
                                          pj.perp(), f"\u22a5 {centre}{j}"),), eq))
        if guided:
            g = step.slide.line.direction
            trials.append(Line(ORIGIN, g))
            self.steps.append((f"Draw the direction of V_{j} through O_v, parallel to the guide.",
                               (TrialLine(f"trial V_{j}", Role.TRIAL, Diagram.VELOCITY, ORIGIN, g,
                                          "\u2225 guide"),), eq))
        hit = intersect_lines(trials[0], trials[1], self.tol)
        if hit.contact is not Contact.CROSSING:
            raise _singular(m, step, self.pose, hit.condition)
        vj = hit.points[0]
        self.vel[j] = vj
        self.cond[j] = hit.condition
        if hit.condition < WARN_SINE:
            self.warnings.append(
                f"Near a singular position at {j}: the trial lines cross at "
                f"{math.degrees(math.asin(min(hit.condition, 1.0))):.3g} deg; values are sensitive to the "
                f"drawing (rounding error about {4.0 * 2.2e-16 / hit.condition ** 2:.1e} relative).")
        dead = _dead_centre(pos, self.crank, arms, j)
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
        if guided or all(c not in m.ground for _, c in arms):
            measured.append(Arrow(f"result V_{j}", Role.RESULT, Diagram.VELOCITY, ORIGIN, vj, f"V_{j}"))
        omega_words = "; ".join(
            f"\u03c9_{link.number} = {self._what(j, centre)}/{link.label} = "
            f"{fmt('angular velocity', abs(self.ang[link.number]))} {_sense(self.ang[link.number])}"
            for link, centre in arms)
        values = ", ".join(f"{a.label} = {fmt('velocity', (a.tip - a.tail).norm())}" for a in measured)
        self.steps.append((f"The trial lines meet at {image_name(j)}. Measure {values}; {omega_words}.",
                           (Point(f"image {j}", Role.LABEL, Diagram.VELOCITY, vj, image_name(j)), *measured),
                           eq))

    def analysis(self, scale: float | None, max_extent_mm: float) -> VelocityAnalysis:
        """The record in the notes' order: equations, pole, scale, then the drawing steps."""
        pts = list(self.vel.values())
        extent = max(max(p.x for p in pts) - min(p.x for p in pts), max(p.y for p in pts) - min(p.y for p in pts))
        known = self.v_known.norm()
        s = scale if scale is not None else vector_scale(known, extent, max_extent_mm=max_extent_mm)
        rec = Construction("Velocity polygon")
        for caption, eq in self.equations:
            rec = rec.then(caption, equation=eq)
        rec = rec.then("Choose the pole O_v.", Point("pole O_v", Role.LABEL, Diagram.VELOCITY, ORIGIN, "O_v"))
        rec = rec.then(f"Choose the velocity scale: 1 mm = {self.fmt('velocity', s)}; V_{self.crank.tip} is "
                       f"{known / s:.0f} mm long.",
                       ScaleBar("velocity scale", Role.SCALE_BAR, Diagram.VELOCITY, "velocity", s))
        for caption, entities, eq in self.steps:
            rec = rec.then(caption, *entities, equation=eq)
        return VelocityAnalysis(rec, self.pose, self.vel, self.rel, self.ang, self.cond, s, tuple(self.warnings))


def _image_steps(step: FixedToLink, pos, vel, rel, fmt: Formatter):
    """Velocity image of point D on a link BC: the triangle bcd is similar to BCD (notes, Example 4).

    d is placed by the similar triangle itself (the notes' option 1): d - b = (c - b) z with z the complex
    ratio (D - B) / (C - B), exact for a rigid link and well conditioned wherever D lies.  The notes'
    option 2 -- the perpendiculars to BD through b and to CD through c -- is drawn as the visible
    construction when those lines cross at a readable angle; on (or nearly on) the line BC they are
    parallel and d simply divides bc as D divides BC.
    """
    a, link = step.point, step.link
    d = a.name
    p, q = link.joints
    P, Q, D = pos[p], pos[q], pos[d]
    vp, vq = vel[p], vel[q]
    ip, iq, idd = image_name(p), image_name(q), image_name(d)
    out = []
    pq, pd, qd = Q - P, D - P, D - Q
    t = pd.dot(pq) / pq.dot(pq)           # along BC
    u = pq.cross(pd) / pq.dot(pq)         # square to BC (left positive)
    bc = vq - vp
    vd = vp + bc * t + bc.perp() * u
    crossing = abs(pd.unit().cross(qd.unit())) if pd.norm() > 0 and qd.norm() > 0 else 0.0
    if crossing < WARN_SINE:
        out.append((f"{d} lies on (or next to) the line {p}{q}: mark {idd} dividing {ip}{iq} as {d} "
                    f"divides {p}{q} ({p}{d}/{p}{q} = {t:.4g}).", (), None))
    else:
        out.append((f"Velocity image of link {link.number}: through {ip} draw the perpendicular to {p}{d}, "
                    f"through {iq} the perpendicular to {q}{d}; they meet at {idd}.",
                    (TrialLine(f"trial V_{d}{p}", Role.TRIAL, Diagram.VELOCITY, vp, pd.perp(),
                               f"\u22a5 {p}{d}"),
                     TrialLine(f"trial V_{d}{q}", Role.TRIAL, Diagram.VELOCITY, vq, qd.perp(),
                               f"\u22a5 {q}{d}")), None))
    vel[d] = vd
    rel[(d, p)] = vd - vp
    out.append((f"The shaded triangle {ip}{iq}{idd} is the velocity image of {p}{q}{d}. Join O_v to {idd}: "
                f"V_{d} = {fmt('velocity', vd.norm())}.",
                (Polygon(f"image {p}{q}{d}", Role.IMAGE, Diagram.VELOCITY, (vp, vq, vd)),
                 Point(f"image {d}", Role.LABEL, Diagram.VELOCITY, vd, idd),
                 Arrow(f"result V_{d}", Role.RESULT, Diagram.VELOCITY, ORIGIN, vd, f"V_{d}")), None))
    return out


def _equation(arms, j: str, m: Mechanism, guided: bool) -> VectorEquation:
    """V_J = V_P + V_JP with the notes' marks; both centres moving: V_P + V_JP = V_Q + V_JQ."""
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


def _equation_caption(eq: VectorEquation, arms, j: str, m: Mechanism, step) -> str:
    links = " and ".join(f"link {l.number} ({l.label})" for l, _ in arms)
    dirs = [f"V_{j}{c} \u22a5 {c}{j}" if c not in m.ground else f"V_{j} \u22a5 {c}{j}" for _, c in arms]
    if isinstance(step, CircleAndGuide):
        dirs.append(f"V_{j} \u2225 guide")
    return (f"Relative velocity equation on {links}: {eq.text(marks=False)}, with {', '.join(dirs)}; "
            f"two unknown magnitudes.")


def _singular(m: Mechanism, step, pose: Pose, condition: float) -> IndeterminatePosition:
    j = step.joint
    where = describe_angle(pose.angle)
    if isinstance(step, TwoCircles):
        a, b = step.link_a, step.link_b
        kind = "change point" if _change_point(m, pose) else "toggle"
        reason = (f"{kind}: links {a.number} ({a.label}) and {b.number} ({b.label}) are in line, so the "
                  f"trial lines for {j} are parallel (sine {condition:.1e}) and the velocity polygon "
                  f"cannot close")
    else:
        kind = "limit position"
        reason = (f"limit position (lock): link {step.link.number} ({step.link.label}) is square to the guide "
                  f"of {j}, so the trial lines for V_{j} and V_{j}{step.centre} are parallel "
                  f"(sine {condition:.1e}) and the velocity polygon cannot close")
    return IndeterminatePosition(reason, position=where, kind=kind, condition=condition)


def _dead_centre(pos, crank: CrankTip, arms, j: str) -> str | None:
    """At a dead centre the crank and the link it drives are in line: for a driving crank the
    polygon still closes (the driven joint is momentarily at rest along that link), but the position
    is singular for motion driven from the output, so the reader is told."""
    for link, centre in arms:
        if centre == crank.tip:
            a = pos[crank.tip] - pos[crank.pivot]
            b = pos[j] - pos[centre]
            if abs(a.unit().cross(b.unit())) < DEAD_CENTRE_SINE:
                return (f"Dead centre: crank {crank.pivot}{crank.tip} and link {link.number} "
                        f"({link.label}) are in line; driven by the crank the polygon closes, but the "
                        f"output could not drive the crank from here.")
    return None


def _change_point(m: Mechanism, pose: Pose) -> bool:
    """All joints of the loop in one line (the branches of a four-bar meet); points merely fixed to a
    link do not count."""
    joints = set(m.ground) | {j for k in m.links for j in k.joints}
    pts = [p for n, p in pose.positions.items() if n in joints]
    far = max(pts, key=lambda p: p.distance_to(pts[0]))
    if far == pts[0]:
        return True
    axis = Line.through(pts[0], far)
    return all(abs(axis.signed_distance(p)) <= 1e-6 * m.size for p in pts)
