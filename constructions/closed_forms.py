"""The closed forms applied to a mechanism: which mechanisms they model (a plain four-bar or slider-crank,
with points fixed to its links) and their state over an array of crank angles -- one piece that the
analytic check (:mod:`constructions.check`, one angle) and the sweep (:mod:`constructions.sweep`, many)
both call.  Topology is read from the assembly plan; every number comes from the closed forms given: the
oracle's (:mod:`constructions.analytic`) or the sweep's kernels of the same formulas
(:mod:`constructions.sweep_kernels`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from . import sweep_kernels
from .analytic.inverse import four_bar_inverse, inverted_slider_crank_inverse, slider_crank_inverse
from .mechanisms.assembly import (CircleAndGuide, CrankTip, FixedToLink, SlotThrough, TwoCircles, TwoLines, assembly_plan)
from .mechanisms.model import Mechanism
from .motion_arrays import XY, MotionArrays


@dataclass(frozen=True, eq=False)
class ClosedFormState(MotionArrays):
    """The motion over the crank angles (:class:`~constructions.motion_arrays.MotionArrays`) and the links
    whose rates are inputs or zero (the crank, a slider block on a fixed guide)."""

    fixed_links: frozenset[int] = frozenset()


def closed_form_parts(m: Mechanism):
    """(crank step, dyad, points fixed to its links) when ``m`` is a plain four-bar or slider-crank -- one
    dyad hung from the crank tip and the frame, no other slider, points only on those links -- so the
    closed forms apply; else None.  Topology only."""
    plan = assembly_plan(m)
    crank = plan[0]
    assert isinstance(crank, CrankTip)
    dyads = [s for s in plan if isinstance(s, (TwoCircles, CircleAndGuide, SlotThrough, TwoLines))]
    fixed = [s for s in plan if isinstance(s, FixedToLink)]
    if len(dyads) != 1:
        return None
    d, b = dyads[0], crank.tip
    if isinstance(d, TwoCircles):
        arms = {d.first: d.link_a, d.second: d.link_b}
        ground = [c for c in arms if c in m.ground]
        if not (b in arms and len(ground) == 1 and not m.slides):
            return None
        solved = {crank.link.number} | {k.number for k in arms.values()}
    elif isinstance(d, CircleAndGuide):
        if not (d.centre == b and d.slide.on is None and len(m.slides) == 1):
            return None
        solved = {crank.link.number, d.link.number}
    else:
        return None
    if not all(f.point.link in solved for f in fixed):
        return None
    return crank, d, fixed


def closed_form_state(m: Mechanism, th: np.ndarray, omega: float, alpha: float, parts,
                      forms=sweep_kernels) -> ClosedFormState:
    """The closed forms over the crank angles ``th`` (a 1-d array) for the plain four-bar or slider-crank
    that :func:`closed_form_parts` recognised: every joint and point of it (points fixed to its links by
    ``coupler_point``), every link's rates.  ``forms`` holds ``four_bar``, ``slider_crank`` and
    ``coupler_point``: :mod:`constructions.analytic` or :mod:`constructions.sweep_kernels`."""
    crank, d, fixed = parts
    n = th.size
    O1 = m.ground[crank.pivot]
    b, j = crank.tip, d.joint
    zeros = np.broadcast_to(0.0, (n,))

    def full(v):
        return np.broadcast_to(float(v), (n,))
    pos: dict[str, XY] = {g: (full(p.x), full(p.y)) for g, p in m.ground.items()}
    vel: dict[str, XY] = {g: (zeros, zeros) for g in m.ground}
    acc: dict[str, XY] = {g: (zeros, zeros) for g in m.ground}
    ang: dict[int, np.ndarray] = {crank.link.number: full(omega)}
    alp: dict[int, np.ndarray] = {crank.link.number: full(alpha)}
    theta: dict[int, tuple[str, np.ndarray]] = {crank.link.number: (crank.pivot, th)}
    if isinstance(d, TwoCircles):
        arms = {d.first: d.link_a, d.second: d.link_b}
        o2 = next(c for c in arms if c in m.ground)
        coupler, rocker = arms[b], arms[o2]
        sign = d.branch.sign if d.branch.reference == (b, o2) else -d.branch.sign
        s = forms.four_bar(th, omega, alpha, crank_pivot=O1.as_tuple(), rocker_pivot=m.ground[o2].as_tuple(),
                           crank=crank.link.length, coupler=coupler.length, rocker=rocker.length, branch=sign)
        model = "four-bar"
        ang[rocker.number], alp[rocker.number] = s.omega3, s.alpha3
        theta[rocker.number] = (o2, s.theta3)
    else:
        coupler = d.link
        s = forms.slider_crank(th, omega, alpha, crank_pivot=O1.as_tuple(), crank=crank.link.length,
                               coupler=coupler.length, guide_point=d.slide.through.as_tuple(),
                               guide_angle=d.slide.angle, branch=d.branch.sign)
        model = "slider-crank"
        ang[d.slide.number], alp[d.slide.number] = zeros, zeros
    pos[b], pos[j] = (s.Bx, s.By), (s.Cx, s.Cy)
    vel[b], vel[j] = (s.VBx, s.VBy), (s.VCx, s.VCy)
    acc[b], acc[j] = (s.ABx, s.ABy), (s.ACx, s.ACy)
    ang[coupler.number], alp[coupler.number] = s.omega2, s.alpha2
    theta[coupler.number] = (b, s.theta2)
    for f in fixed:
        a = f.point
        start, t = theta[a.link]
        direction = t if a.base == start else t + np.pi
        bx, by = pos[a.base]
        p = forms.coupler_point(bx, by, vel[a.base][0], vel[a.base][1], direction, ang[a.link],
                                distance=a.distance, angle=a.angle, ABx=acc[a.base][0], ABy=acc[a.base][1],
                                alpha2=alp[a.link])
        pos[a.name], vel[a.name], acc[a.name] = (p.Dx, p.Dy), (p.VDx, p.VDy), (p.ADx, p.ADy)
    ok = np.asarray(s.assembles, dtype=bool).reshape(n)
    fixed_links = {crank.link.number} | ({d.slide.number} if isinstance(d, CircleAndGuide) else set())
    return ClosedFormState(th, pos, vel, acc, ang, alp, ok, model, frozenset(fixed_links))


def closed_form_inverse(m: Mechanism, target) -> tuple[float, ...] | None:
    """The crank angles (rad, in [0, 2 pi), ascending) at which the plain slider-crank's slider, or the
    plain four-bar's rocker, stands at ``target`` (a :class:`~constructions.mechanisms.inverse_position.SliderAt`
    or ``OutputAngle``), by the closed forms of :mod:`constructions.analytic.inverse`; None when ``m`` is
    no plain slider-crank or four-bar, or the target is not its slider or rocker."""
    inverted = _inverted_slider_crank(m, target)
    if inverted is not None:
        return inverted
    parts = closed_form_parts(m)
    if parts is None:
        return None
    crank, d, _ = parts
    O1 = m.ground[crank.pivot].as_tuple()
    if isinstance(d, CircleAndGuide):
        if getattr(target, "block", None) != d.slide.number:
            return None
        return slider_crank_inverse(target.position, crank_pivot=O1, crank=crank.link.length,
                                    coupler=d.link.length, guide_point=d.slide.through.as_tuple(),
                                    guide_angle=d.slide.angle, branch=d.branch.sign)
    b = crank.tip
    arms = {d.first: d.link_a, d.second: d.link_b}
    o2 = next(c for c in arms if c in m.ground)
    rocker = arms[o2]
    if getattr(target, "link", None) != rocker.number:
        return None
    sign = d.branch.sign if d.branch.reference == (b, o2) else -d.branch.sign
    return four_bar_inverse(target.angle, crank_pivot=O1, rocker_pivot=m.ground[o2].as_tuple(),
                            crank=crank.link.length, coupler=arms[b].length, rocker=rocker.length, branch=sign)


def _inverted_slider_crank(m: Mechanism, target) -> tuple[float, ...] | None:
    """The closed form when ``target`` is the cylinder length of an inverted slider-crank: the block on the
    crank tip slides in a slot (offset 0, along its link) of a link pivoted at its first joint."""
    s = m.blocks().get(getattr(target, "block", None))
    if s is None or s.on is None or s.offset != 0.0 or s.angle != 0.0:
        return None
    crank = m.link(m.crank)
    pivot = m.crank_pivot()
    first = m.link(s.on).joints[0]
    branch = m.branches.get(s.joint)
    if crank.other(pivot) != s.joint or first not in m.ground or branch is None or branch.reference != (first,):
        return None
    return inverted_slider_crank_inverse(target.position, crank_pivot=m.ground[pivot].as_tuple(),
                                         crank=crank.length, slot_pivot=m.ground[first].as_tuple(),
                                         branch=branch.sign)
