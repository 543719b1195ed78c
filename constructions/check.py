"""Graphical against analytic: every measured value beside its vector-loop value and their difference.

:func:`analytic_solution` evaluates the vector-loop solution: the fast closed forms of
:mod:`constructions.analytic` for a plain four-bar or slider-crank (with points fixed to their links),
and :mod:`constructions.vector_loops` for any other crank-plus-dyads chain (six-bars, toggle linkages).
It reads only the mechanism's dimensions, never the construction.  :func:`compare` lines the two up.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Mapping, Sequence

import numpy as np

from .closed_forms import closed_form_parts, closed_form_state
from .errors import CannotAssemble, DegenerateInput, IndeterminatePosition
from .geometry import Vec
from .mechanisms.assembly import SlotThrough, TwoLines, assembly_plan
from .mechanisms.model import Mechanism
from .quantities import Measured
from .tolerance import AGREEMENT, CONDITION_FLOOR, EPSILON, OTHER_ASSEMBLY, SAFETY

_ORDER = {"velocity": 2, "angular velocity": 2, "acceleration": 3, "angular acceleration": 3, "force": 3,
          "torque": 3}
"""Forces are read off polygons built on the accelerations (D'Alembert), so they inherit their order."""


def agreement(kind: str, condition: float) -> float:
    """The relative tolerance for a value of ``kind`` read at a crossing of sine ``condition``.

    Rounding in a crossing of trial lines at sine s grows as eps/s^2 for the velocities (the crossing
    itself and the lines' directions), one power more for accelerations (built on the velocities);
    so the tolerance is max(1e-9, 64 eps / s^p), which is 1e-9 wherever the position is well
    conditioned and widens only where the construction warns that it is near a singular position."""
    p = _ORDER.get(kind, 1)
    c = max(condition, CONDITION_FLOOR)
    return max(AGREEMENT, SAFETY * EPSILON / c ** p)


class NotModelled(Exception):
    """The analytic check has no model of this mechanism (the message says what it lacks)."""


@dataclass(frozen=True)
class AnalyticSolution:
    model: str                                  # "four-bar", "slider-crank" or "dyad chain"
    positions: Mapping[str, Vec]
    velocities: Mapping[str, Vec]
    angular: Mapping[int, float]
    accelerations: Mapping[str, Vec] | None = None
    angular_acceleration: Mapping[int, float] | None = None


@dataclass(frozen=True)
class Comparison:
    """One measured quantity beside its analytic value.  ``analytic`` is None when there is no analytic
    model for the quantity: then nothing is compared and ``difference``, ``relative`` and ``agrees``
    are None too.  ``tolerance`` is relative to ``reference`` (see :func:`agreement`)."""

    name: str
    kind: str
    graphical: Vec | float
    analytic: Vec | float | None
    reference: float
    tolerance: float = AGREEMENT
    diagram: str = ""                    # the diagram it is read off (Measured.diagram)

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
        return None if r is None else r <= self.tolerance


def compare(measured: Sequence[Measured], analytic: Mapping[str, Vec | float] | None,
            scales: Mapping[str, float] | None = None) -> list[Comparison]:
    """Each measured quantity beside the analytic value of the same name (None where there is none).

    The reference of a value is the largest measured value of its kind, or the scale of its kind given
    in ``scales`` if that is larger (the input's: |V_B|, |omega_1|, |A_B|, max(|alpha_1|, omega_1^2)), so
    a quantity that is nearly zero is judged against the scale of the polygon it was read from; the
    tolerance widens with the conditioning of the crossing it was read at."""
    ref: dict[str, float] = dict(scales or {})
    for q in measured:
        ref[q.kind] = max(ref.get(q.kind, 0.0), q.magnitude)
    out = []
    for q in measured:
        a = analytic.get(q.name) if analytic is not None else None
        out.append(Comparison(q.name, q.kind, q.value, a, ref[q.kind] or 1.0, agreement(q.kind, q.condition),
                              q.diagram))
    return out


def analytic_solution(m: Mechanism, angle: float, omega: float, alpha: float = 0.0, *,
                      accelerations: bool = True, guess: Mapping[str, Vec] | None = None) -> AnalyticSolution | None:
    """The vector-loop solution of ``m`` at ``angle`` (crank turning at ``omega`` with angular
    acceleration ``alpha``), or None where the mechanism does not assemble.

    A plain four-bar or slider-crank (one dyad hung from the crank tip and the frame, points fixed to
    any of its links) is evaluated by the closed forms of :mod:`constructions.analytic`; any other
    crank followed by dyads by the dyad-chain vector loops of :mod:`constructions.vector_loops`.
    Mechanisms neither models (a slot in a moving link, a ternary link joined at its third point) are
    solved by the constraint equations of :mod:`constructions.constraint_kinematics` (Newton from
    ``guess``, e.g. the construction's pose, then the linear velocity and acceleration systems); without
    a guess they raise :class:`NotModelled`.  With ``accelerations`` False the acceleration fields are
    left None."""
    parts = closed_form_parts(m)
    if parts is None:
        from .analytic import chain_solution         # the dyad chains' loops: not loaded for a plain four-bar
        try:
            st = chain_solution(m, angle, omega, alpha)
        except DegenerateInput as e:
            if guess is None:
                raise NotModelled(f"the vector-loop check does not model this mechanism ({e})") from None
            return _constraint_solution(m, angle, omega, alpha, guess, accelerations)
        if not bool(st.assembles):
            return None
        at = st.at()
        return AnalyticSolution("dyad chain",
                                {n: Vec(*p) for n, p in at.positions.items()},
                                {n: Vec(*v) for n, v in at.velocities.items()},
                                dict(at.angular),
                                {n: Vec(*a) for n, a in at.accelerations.items()} if accelerations else None,
                                dict(at.angular_acceleration) if accelerations else None)
    st = closed_form_state(m, np.array([angle], dtype=np.float64), omega, alpha, parts)
    if not bool(st.assembles[0]):
        return None

    def vec(xy) -> Vec:
        return Vec(float(xy[0][0]), float(xy[1][0]))
    pos = {n: vec(p) for n, p in st.positions.items()}
    vel = {n: vec(v) for n, v in st.velocities.items()}
    acc = {n: vec(a) for n, a in st.accelerations.items()}
    ang = {n: float(np.reshape(w, -1)[0]) for n, w in st.angular.items()}
    alp = {n: float(np.reshape(w, -1)[0]) for n, w in st.angular_acceleration.items()}
    return AnalyticSolution(st.model, pos, vel, ang, acc if accelerations else None, alp if accelerations else None)


def _constraint_solution(m, angle, omega, alpha, guess, accelerations) -> AnalyticSolution | None:
    """The constraint-equation solution; None where it cannot assemble near the guess."""
    from .mechanisms.constraint_kinematics import solve_constraints
    try:
        st = solve_constraints(m, angle, omega, alpha, guess)
    except CannotAssemble:
        return None
    except IndeterminatePosition as e:
        raise NotModelled(f"the constraint equations are singular here ({e.reason})") from None
    L = m.size
    moved = max((st.positions[n].distance_to(p) for n, p in guess.items() if n in st.positions), default=0.0)
    if moved > OTHER_ASSEMBLY * L:
        raise NotModelled(f"Newton's method settled on another assembly ({moved / L:.1e} L from the "
                          f"construction), so there is nothing to compare")
    return AnalyticSolution("constraint equations", dict(st.positions), dict(st.velocities), dict(st.angular),
                            dict(st.accelerations) if accelerations else None,
                            dict(st.angular_acceleration) if accelerations else None)


def analytic_values(m: Mechanism, a: AnalyticSolution | None) -> dict[str, Vec | float] | None:
    """The analytic solution under the names the constructions measure: V_J, V_JP, omega_n (and, when
    present, A_J, A_JP^t, A_JP^n, alpha_n for every pair of joints on a link)."""
    if a is None:
        return None
    out: dict[str, Vec | float] = {}
    for n, v in a.velocities.items():
        out[f"V_{n}"] = v
    names = list(a.velocities)
    for j in names:
        for p in names:
            if j != p:
                out[f"V_{j}{p}"] = a.velocities[j] - a.velocities[p]
    for n, w in a.angular.items():
        out[f"omega_{n}"] = w
    if a.accelerations is not None:
        for n, v in a.accelerations.items():
            out[f"A_{n}"] = v
        for n, al in (a.angular_acceleration or {}).items():
            out[f"alpha_{n}"] = al
        for k in m.links:
            pts = list(k.joints) + [p.name for p in m.attached if p.link == k.number]
            w, al = a.angular[k.number], (a.angular_acceleration or {}).get(k.number)
            for j in pts:
                for p in pts:
                    if j == p or j not in a.positions or p not in a.positions:
                        continue
                    r = a.positions[j] - a.positions[p]
                    name = f"A_{j}" if p in m.ground else f"A_{j}{p}"      # the notes drop a fixed pivot
                    out[f"{name}^n"] = r * (-w * w)
                    if al is not None:
                        out[f"{name}^t"] = r.perp() * al
                    out[f"A_{j}{p}"] = a.accelerations[j] - a.accelerations[p]
        # at a sliding joint J on the slot of link G (JG: the point of G under J), from the joint's and the
        # point's absolute motion: A_JG = A_J + A^s + 2 omega_G x (V_JG - V_J) for a slot turned through a
        # known joint (SlotThrough), and A_J = A_JG + A^s + 2 omega_G x (V_J - V_JG) where a circle meets
        # the slot (CircleAndGuide on a moving slot) -- the names the construction measures
        sliding = []
        for step in assembly_plan(m):
            if isinstance(step, TwoLines):
                sliding += [(step, sl, jg) for sl, jg in ((step.slide_a, step.coincident_a),
                                                          (step.slide_b, step.coincident_b)) if jg]
            elif getattr(step, "coincident", ""):
                sliding.append((step, step.slide, step.coincident))
        for step, slide, jg in sliding:
            if jg not in a.accelerations:
                continue
            j = step.joint
            w = a.angular[slide.on]
            al = (a.angular_acceleration or {}).get(slide.on)
            for q in m.points_of(slide.on):       # components of the point under J about the link's points
                r = a.positions[jg] - a.positions[q]
                name = f"A_{jg}" if q in m.ground else f"A_{jg}{q}"
                out[f"{name}^n"] = r * (-w * w)
                if al is not None:
                    out[f"{name}^t"] = r.perp() * al
            first, second = (jg, j) if isinstance(step, SlotThrough) else (j, jg)
            cor = (a.velocities[first] - a.velocities[second]).perp() * (2.0 * w)
            out[f"A_{first}{second}^c"] = cor
            out[f"A_{first}{second}^s"] = a.accelerations[first] - a.accelerations[second] - cor
    return out
