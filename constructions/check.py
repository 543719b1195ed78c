"""Graphical against analytic: every measured value beside its vector-loop value and their difference.

:func:`analytic_solution` evaluates the vector-loop solution: the fast closed forms of
:mod:`constructions.analytic` for a plain four-bar or slider-crank (with points fixed to their links),
and :mod:`constructions.vector_loops` for any other crank-plus-dyads chain (six-bars, toggle linkages).
It reads only the mechanism's dimensions, never the construction.  :func:`compare` lines the two up.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Mapping

from . import analytic
from .geometry import Vec
from .linkage import CircleAndGuide, CrankTip, FixedToLink, Mechanism, TwoCircles, assembly_plan
from .velocity import VelocityAnalysis
from .vector_loops import chain_solution

AGREEMENT = 1e-9
"""Graphical and analytic agree when they differ by less than this, relative to the reference value
(|V| of the crank tip for velocities, |omega| of the crank for angular velocities)."""


@dataclass(frozen=True)
class AnalyticSolution:
    model: str                                  # "four-bar", "slider-crank" or "dyad chain"
    positions: Mapping[str, Vec]
    velocities: Mapping[str, Vec]
    angular: Mapping[int, float]


@dataclass(frozen=True)
class Comparison:
    """One measured quantity.  ``kind`` is "velocity" (Vec values) or "angular velocity" (floats).
    ``analytic`` is None when there is no closed form for the mechanism: then nothing is compared and
    ``difference``, ``relative`` and ``agrees`` are None too."""

    name: str
    kind: str
    graphical: Vec | float
    analytic: Vec | float | None
    reference: float

    @property
    def difference(self) -> float | None:
        if self.analytic is None:
            return None
        if isinstance(self.graphical, Vec):
            return (self.graphical - self.analytic).norm()
        return abs(self.graphical - self.analytic)

    @property
    def relative(self) -> float | None:
        d = self.difference
        return None if d is None else d / self.reference

    @property
    def agrees(self) -> bool | None:
        r = self.relative
        return None if r is None else r <= AGREEMENT


def analytic_solution(m: Mechanism, angle: float, omega: float) -> AnalyticSolution | None:
    """The vector-loop solution of ``m`` at ``angle``, or None where the mechanism does not assemble.

    A plain four-bar or slider-crank (one dyad hung from the crank tip and the frame, points fixed to
    any of its links) is evaluated by the closed forms of :mod:`constructions.analytic`; any other
    crank followed by dyads by the dyad-chain vector loops of :mod:`constructions.vector_loops`."""
    plan = assembly_plan(m)
    crank = plan[0]
    assert isinstance(crank, CrankTip)
    dyads = [s for s in plan if isinstance(s, (TwoCircles, CircleAndGuide))]
    fixed = [s for s in plan if isinstance(s, FixedToLink)]
    b = crank.tip
    # Is it a plain four-bar or slider-crank?  (Topology only; the closed forms below then apply.)
    plain = False
    if len(dyads) == 1:
        d = dyads[0]
        if isinstance(d, TwoCircles):
            arms = {d.first: d.link_a, d.second: d.link_b}
            ground = [c for c in arms if c in m.ground]
            plain = b in arms and len(ground) == 1
        else:
            plain = d.centre == b
        if plain:
            solved = {crank.link.number} | {k.number for k in (arms.values() if isinstance(d, TwoCircles)
                                                               else (d.link,))}
            plain = all(f.point.link in solved for f in fixed)
    if not plain:
        st = chain_solution(m, angle, omega)
        if not bool(st.assembles):
            return None
        at = st.at()
        return AnalyticSolution("dyad chain",
                                {n: Vec(*p) for n, p in at.positions.items()},
                                {n: Vec(*v) for n, v in at.velocities.items()},
                                dict(at.angular))
    d = dyads[0]
    O1 = m.ground[crank.pivot]
    j = d.joint
    pos: dict[str, Vec] = dict(m.ground)
    vel: dict[str, Vec] = {g: Vec(0.0, 0.0) for g in m.ground}
    ang: dict[int, float] = {crank.link.number: omega}
    theta: dict[int, tuple[str, float]] = {crank.link.number: (crank.pivot, angle)}
    if isinstance(d, TwoCircles):
        arms = {d.first: d.link_a, d.second: d.link_b}
        o2 = next(c for c in arms if c in m.ground)
        coupler, rocker = arms[b], arms[o2]
        sign = d.branch.sign if d.branch.reference == (b, o2) else -d.branch.sign
        s = analytic.four_bar(angle, omega, crank_pivot=O1.as_tuple(), rocker_pivot=m.ground[o2].as_tuple(),
                              crank=crank.link.length, coupler=coupler.length, rocker=rocker.length,
                              branch=sign)
        model = "four-bar"
        ang[rocker.number] = float(s.omega3)
        theta[rocker.number] = (o2, float(s.theta3))
    else:
        coupler = d.link
        s = analytic.slider_crank(angle, omega, crank_pivot=O1.as_tuple(), crank=crank.link.length,
                                  coupler=coupler.length, guide_point=d.slide.through.as_tuple(),
                                  guide_angle=d.slide.angle, branch=d.branch.sign)
        model = "slider-crank"
        ang[d.slide.number] = 0.0
    if not bool(s.assembles):
        return None
    pos[b], pos[j] = Vec(float(s.Bx), float(s.By)), Vec(float(s.Cx), float(s.Cy))
    vel[b], vel[j] = Vec(float(s.VBx), float(s.VBy)), Vec(float(s.VCx), float(s.VCy))
    ang[coupler.number] = float(s.omega2)
    theta[coupler.number] = (b, float(s.theta2))
    for f in fixed:
        a = f.point
        start, th = theta[a.link]
        # angle of the direction from a.base to the link's other joint
        direction = th if a.base == start else th + math.pi
        base = pos[a.base]
        p = analytic.coupler_point(base.x, base.y, vel[a.base].x, vel[a.base].y, direction, ang[a.link],
                                   distance=a.distance, angle=a.angle)
        pos[a.name] = Vec(float(p.Dx), float(p.Dy))
        vel[a.name] = Vec(float(p.VDx), float(p.VDy))
    return AnalyticSolution(model, pos, vel, ang)


def compare(m: Mechanism, g: VelocityAnalysis, a: AnalyticSolution | None) -> list[Comparison]:
    """Absolute velocities of the moving joints and points, relative velocities, link angular
    velocities -- each graphical value beside the analytic one (None where there is no closed form)."""
    v_ref = max(v.norm() for v in g.velocities.values())
    w_ref = max(abs(w) for w in g.angular.values())
    out: list[Comparison] = []
    for name, v in g.velocities.items():
        if name not in m.ground:
            out.append(Comparison(f"V_{name}", "velocity", v, a.velocities[name] if a else None, v_ref))
    for (j, p), v in g.relative.items():
        if p not in m.ground:
            out.append(Comparison(f"V_{j}{p}", "velocity", v,
                                  a.velocities[j] - a.velocities[p] if a else None, v_ref))
    driven_or_sliding = {m.crank} | {s.number for s in m.slides}
    for n, w in sorted(g.angular.items()):
        if n not in driven_or_sliding:
            out.append(Comparison(f"omega_{n}", "angular velocity", w, a.angular[n] if a else None, w_ref))
    return out
