"""The [input] of a linkage scene given by where a slider or an output link stands rather than by the
crank angle (the inverse position problem), and a slider that drives the mechanism: the crank angles
follow from ``slider_at`` or ``output_angle``
(:func:`constructions.mechanisms.inverse_position.inverse_position`), and the crank's omega and alpha
from ``slider_speed`` and ``slider_acceleration``, read off the polygons
(:func:`constructions.polygons.driving_slider.driven_crank`)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from constructions.errors import DegenerateInput
from constructions.mechanisms.assembly import assembly_plan
from constructions.mechanisms.model import Mechanism
from constructions.mechanisms.pose import locate

from ...scene.reader import SceneReader
from ...scene.unitset import Units

if TYPE_CHECKING:      # loaded by the scenes that give these keys: a scene with a crank angle does without
    from constructions.mechanisms.inverse_position import InversePosition
    from constructions.polygons.driving_slider import DrivenCrank


INVERSE_KEYS = frozenset({"slider_at", "slider", "output_angle", "output", "solution"})
"""[input] keys of the inverse position problem, in place of ``angle``: ``slider_at`` (length: the block's
position along its fixed guide from the guide's ``through`` point, in the guide's direction, or along its
slot from the foot of the slotted link's first joint: a cylinder's length) with ``slider`` (the block's
number; default the one block on a fixed guide, or the only block), or ``output_angle`` (angle: a link's
direction from its fixed pivot to its other joint) with ``output`` (the link's number; default the one
link besides the crank that turns about a fixed pivot); ``solution`` (default 1) picks the crank angle
drawn, counted from 0 deg counter-clockwise."""


def read_inverse(r: SceneReader, units: Units, m: Mechanism, inp: dict) -> tuple[InversePosition | None, int]:
    """Every crank angle that puts the mechanism at the [input]'s slider_at or output_angle, and which
    one is drawn; (None, 1) when the mechanism cannot be built dyad by dyad (the family's check says so)."""
    from constructions.mechanisms.inverse_position import OutputAngle, SliderAt, inverse_position
    if "slider_at" in inp:
        if "output" in inp:
            raise r.fail("input.output", "goes with output_angle, not slider_at")
        blocks = m.blocks()
        fixed = sorted(n for n, s in blocks.items() if s.on is None)
        if "slider" in inp:
            n = r.number("input.slider", inp["slider"])
            if n not in blocks:
                raise r.fail("input.slider", f"there is no block {n}"
                             + (f" (the blocks: {', '.join(map(str, sorted(blocks)))})" if blocks else ""))
        elif len(fixed) == 1 or (not fixed and len(blocks) == 1):
            n = fixed[0] if fixed else next(iter(blocks))
        else:
            raise r.fail("input.slider", "name the block whose position is given: "
                         + ("there is no slider block" if not blocks
                            else f"blocks {', '.join(map(str, sorted(blocks)))} could be meant"))
        target: SliderAt | OutputAngle = SliderAt(n, r.quantity("input.slider_at", inp["slider_at"], "length", units))
        key = "input.slider_at"
    else:
        if "slider" in inp:
            raise r.fail("input.slider", "goes with slider_at, not output_angle")
        pivoted = sorted(k.number for k in m.links if k.number != m.crank and any(j in m.ground for j in k.joints))
        if "output" in inp:
            n = r.number("input.output", inp["output"])
            if n == m.crank or all(k.number != n for k in m.links):
                raise r.fail("input.output", f"link {n} is " + ("the crank" if n == m.crank else "no link")
                             + ": name the link whose angle is given")
        elif len(pivoted) == 1:
            n = pivoted[0]
        else:
            raise r.fail("input.output", "name the link whose angle is given (e.g. output = 3)")
        target = OutputAngle(n, r.quantity("input.output_angle", inp["output_angle"], "angle", units))
        key = "input.output_angle"
    solution = inp.get("solution", 1)
    if isinstance(solution, bool) or not isinstance(solution, int) or solution < 1:
        raise r.fail("input.solution", "must be a whole number from 1: which crank angle is drawn, counted "
                                       "from 0 deg counter-clockwise")
    try:
        plan = assembly_plan(m)
    except DegenerateInput:
        return None, 1
    try:
        found = inverse_position(m, target, plan=plan)
    except DegenerateInput as e:
        raise r.fail(key, str(e)) from None
    if not found.solutions:
        raise r.fail(key, found.describe(units.format))
    if not 1 <= solution <= len(found.solutions):
        raise r.fail("input.solution", f"must be 1 to {len(found.solutions)}: {found.describe(units.format)}")
    return found, solution



def read_driving(r: SceneReader, units: Units, m: Mechanism, inp: dict, inverse: InversePosition,
                 angle: float) -> DrivenCrank:
    """The crank's omega and alpha that move the [input]'s block at slider_speed and slider_acceleration
    at the crank angle drawn."""
    from constructions.polygons.driving_slider import driven_crank
    speed = r.quantity("input.slider_speed", inp["slider_speed"], "velocity", units)
    acc = r.quantity("input.slider_acceleration", inp.get("slider_acceleration", 0), "acceleration", units)
    try:
        return driven_crank(m, locate(m, angle), inverse.target.block, speed, acc)
    except DegenerateInput as e:
        raise r.fail("input.slider_speed", str(e)) from None
