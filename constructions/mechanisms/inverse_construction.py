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
from .inverse_position import InversePosition, SliderAt
from .model import Mechanism

SPAN = math.radians(30)
"""The arc of the coupler's length drawn about the wanted joint, either side of each crossing."""


def _locus(m: Mechanism, inv: InversePosition, plan: tuple[PlanStep, ...]) -> tuple[str, Vec, float, str] | None:
    """(the name of the point the crank tip's locus is drawn about, where it stands, the locus' radius,
    the words that put it there) when the crank tip is one circle away from the target; else None."""
    crank = next(s for s in plan if isinstance(s, CrankTip))
    t = inv.target
    if isinstance(t, SliderAt):
        sl = m.blocks()[t.block]
        if sl.on is not None:                   # a cylinder pivoted at the slotted link's first joint
            first = m.link(sl.on).joints[0]
            if sl.joint == crank.tip and first in m.ground and sl.offset == 0.0 and sl.angle == 0.0:
                return first, m.ground[first], abs(t.position), f"{first}{crank.tip} = $s about {first}"
            return None
        for s in plan:
            if isinstance(s, CircleAndGuide) and s.centre == crank.tip and s.joint == sl.joint:
                at = sl.through + Vec.polar(t.position, sl.angle)
                return (s.joint, at, s.link.length,
                        f"{s.link.label} = $l about {s.joint}, marked at $s along the guide,")
        return None
    for s in plan:
        if isinstance(s, TwoCircles):
            arms = {s.first: s.link_a, s.second: s.link_b}
            if crank.tip in arms and any(c in m.ground and arms[c].number == t.link for c in arms):
                o2 = next(c for c in arms if c in m.ground)
                at = m.ground[o2] + Vec.polar(arms[o2].length, t.angle)
                return (s.joint, at, arms[crank.tip].length,
                        f"{arms[crank.tip].label} = $l about {s.joint}, with link {t.link} drawn at $phi,")
    return None


PRIMES = ("", "'", "''", "'''")


def inverse_step(m: Mechanism, inv: InversePosition, plan: tuple[PlanStep, ...], drawn: int) -> Step:
    """The step that finds the crank angles; ``drawn`` (from 1) is the solution the sheet draws."""
    crank = next(s for s in plan if isinstance(s, CrankTip))
    O1 = m.ground[crank.pivot]
    t = inv.target
    values = {f"t{i}": Value("angle", th) for i, th in enumerate(inv.solutions, 1)}
    listed = ", ".join(f"${k}" for k in values)
    if isinstance(t, SliderAt):
        values["s"] = Value("length", t.position)
        what = f"block {t.block} at $s along {inv.along}"
    else:
        values["phi"] = Value("angle", t.angle)
        what = f"link {t.link} at $phi"
    found = _locus(m, inv, plan)
    if found is None:
        return Step(f"The crank angles that put {what}: turn the crank on the construction until it does -- "
                    f"{listed}; draw solution {drawn}.", values=tuple(values.items()), kind=StepKind.GIVEN)
    name, C, radius, words = found
    values |= {"l": Value("length", radius), "r": Value("length", crank.link.length)}
    tip = crank.tip
    marks: list = [Circle("inverse crank circle", Role.PATH, Diagram.SPACE, O1, crank.link.length),
                   Point(f"inverse {name}", Role.PATH, Diagram.SPACE, C)]
    order = [drawn - 1] + [i for i in range(len(inv.solutions)) if i != drawn - 1]
    for n, i in enumerate(order):
        B = O1 + Vec.polar(crank.link.length, inv.solutions[i])
        a = (B - C).angle()
        marks.append(Arc(f"inverse arc {i + 1}", Role.PATH, Diagram.SPACE, C, radius, a - SPAN / 2, a + SPAN / 2))
        if n:
            marks.append(Point(f"inverse {tip}{PRIMES[min(n, 3)]}", Role.PATH, Diagram.SPACE, B,
                               f"{tip}{PRIMES[min(n, 3)]}"))
    others = "".join(f" and {tip}{PRIMES[min(n, 3)]}" for n in range(1, len(order)))
    text = (f"To put {what}: swing {words} to cut the crank circle ({crank.link.label} = $r about "
            f"{crank.pivot}) at {tip}{others}: \u03b8_{crank.link.number} = {listed}. Draw solution {drawn}.")
    return Step(text, entities=tuple(marks), values=tuple(values.items()), kind=StepKind.GIVEN)


def with_inverse(c: Construction, step: Step) -> Construction:
    """The space diagram's record with ``step`` after its first (drawing the frame)."""
    return Construction(c.title, c.steps[:1] + (step,) + c.steps[1:])
