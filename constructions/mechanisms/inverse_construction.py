"""The inverse position problem as the notes draw it: put the wanted joint where it is wanted, swing the
coupler's length about it, and read the crank angles where that arc cuts the crank circle.

:func:`inverse_step` is the step a space diagram takes between drawing the frame and drawing the crank:
for a slider-crank, the piston C marked at its position on the guide; for a four-bar, the output link
O2C drawn at its angle; in both, the arc of radius BC about C crosses the crank circle at B (the solution
drawn) and B', B'' ... (the others).  Where the wanted joint is not one coupler away from the crank tip (a
six-bar's ram), the step says the crank angles were found by turning the crank on the construction.
:func:`with_inverse` puts it into the space diagram's record.
"""

from __future__ import annotations

import math

from ..entities import Arc, Circle, Diagram, Point, Role
from ..geometry import Vec
from ..record import Construction, Step, StepKind, Value
from .assembly import CircleAndGuide, CrankTip, PlanStep, TwoCircles
from .inverse_position import InversePosition, SliderAt, describe_target
from .model import Link, Mechanism

SPAN = math.radians(30)
"""The arc of the coupler's length drawn about the wanted joint, either side of each crossing."""


def _coupler(m: Mechanism, inv: InversePosition, plan: tuple[PlanStep, ...]) -> tuple[str, Link, Vec] | None:
    """(wanted joint, the coupler joining it to the crank tip, where the joint stands) when the target's
    joint is one coupler from the crank tip; else None."""
    crank = next(s for s in plan if isinstance(s, CrankTip))
    t = inv.target
    for s in plan:
        if isinstance(t, SliderAt) and isinstance(s, CircleAndGuide) and s.centre == crank.tip:
            sl = m.blocks()[t.block]
            if s.joint == sl.joint and s.slide.on is None:
                return s.joint, s.link, sl.through + Vec.polar(t.position, sl.angle)
        if not isinstance(t, SliderAt) and isinstance(s, TwoCircles):
            arms = {s.first: s.link_a, s.second: s.link_b}
            if crank.tip in arms and any(c in m.ground and arms[c].number == t.link for c in arms):
                o2 = next(c for c in arms if c in m.ground)
                r3 = s.radius_b if o2 == s.second and s.radius_b else s.radius_a if o2 == s.first and s.radius_a \
                    else arms[o2].length
                return s.joint, arms[crank.tip], m.ground[o2] + Vec.polar(r3, t.angle)
    return None


def inverse_step(m: Mechanism, inv: InversePosition, plan: tuple[PlanStep, ...], drawn: int) -> Step:
    """The step that finds the crank angles; ``drawn`` (from 1) is the solution the sheet draws."""
    crank = next(s for s in plan if isinstance(s, CrankTip))
    O1 = m.ground[crank.pivot]
    angles = {f"t{i}": Value("angle", t) for i, t in enumerate(inv.solutions, 1)}
    listed = ", ".join(f"${k}" for k in angles)
    found = _coupler(m, inv, plan)
    if found is None:
        return Step(f"The crank angles that put {describe_target(inv.target)}: turn the crank on the construction "
                    f"until it does -- {listed}; draw solution {drawn}.", values=tuple(angles.items()),
                    kind=StepKind.GIVEN)
    joint, coupler, C = found
    r, l = crank.link.length, coupler.length
    primes = ["", "'", "''", "'''"]
    tip = crank.tip
    marks: list = [Circle("inverse crank circle", Role.PATH, Diagram.SPACE, O1, r),
                   Point(f"inverse {joint}", Role.LABEL, Diagram.SPACE, C)]
    order = [drawn - 1] + [i for i in range(len(inv.solutions)) if i != drawn - 1]
    for n, i in enumerate(order):
        B = O1 + Vec.polar(r, inv.solutions[i])
        a = (B - C).angle()
        marks.append(Arc(f"inverse arc {i + 1}", Role.PATH, Diagram.SPACE, C, l, a - SPAN / 2, a + SPAN / 2))
        if n:
            marks.append(Point(f"inverse {tip}{primes[min(n, 3)]}", Role.LABEL, Diagram.SPACE, B,
                               f"{tip}{primes[min(n, 3)]}"))
    if isinstance(inv.target, SliderAt):
        where = f"Mark {joint} at $s along the guide"
        values = {"s": Value("length", inv.target.position)}
    else:
        where = f"Draw link {inv.target.link} at $phi: its end {joint}"
        values = {"phi": Value("angle", inv.target.angle)}
    others = "".join(f" and {tip}{primes[min(n, 3)]}" for n in range(1, len(order)))
    words = (f"{where}; swing {coupler.label} = $l about {joint} to cut the crank circle ({crank.link.label} = "
             f"$r about {crank.pivot}) at {tip}{others}: \u03b8_{crank.link.number} = {listed}. Draw solution "
             f"{drawn}.")
    values |= {"l": Value("length", l), "r": Value("length", r)} | angles
    return Step(words, entities=tuple(marks), values=tuple(values.items()), kind=StepKind.GIVEN)


def with_inverse(c: Construction, step: Step) -> Construction:
    """The space diagram's record with ``step`` after its first (drawing the frame)."""
    return Construction(c.title, c.steps[:1] + (step,) + c.steps[1:])
