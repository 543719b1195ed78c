"""Friction at a slide, as the force polygons take it: the coefficient the scene sets at a block or a pin in
a slot, the sense of the sliding (from the velocity polygon), and the line of a guide's total reaction,
leaning back from the normal by the friction angle against the sliding, on the face the block bears on.
"""

from __future__ import annotations

import math

from ..errors import IndeterminatePosition
from ..geometry import Vec
from ..mechanisms.model import describe_angle
from ..tolerance import NEGLIGIBLE, PARALLEL_SINE
from .board import ORIGIN, Drawing, meet


def friction_at(d: Drawing, sl) -> float:
    """The coefficient of friction at a slide: keyed by its block, or by the joint for a pin in a slot."""
    return d.effects.friction.get(sl.number if sl.number is not None else sl.joint, 0.0)


def slide_sign(d: Drawing, sl, coincident: str, along: Vec) -> float:
    """+1 or -1 as the joint slides along ``along`` relative to its guide or slot (the slotted link's point
    ``coincident`` under it), 0 -- with a warning that friction is left out -- when it is at rest there."""
    v = d.velocity.velocities[sl.joint]
    if sl.on is not None:
        v = v - d.velocity.velocities[coincident]
    x = v.dot(along)
    tol = NEGLIGIBLE * max(w.norm() for w in d.velocity.velocities.values())
    if abs(x) <= tol:
        label = sl.label
        d.warnings.append(f"{label[:1].upper()}{label[1:]} is momentarily at rest on its "
                          f"{'guide' if sl.on is None else 'slot'}: the friction force is undetermined and left out.")
        return 0.0
    return math.copysign(1.0, x)


def friction_lean(d: Drawing, knowns, normal: Vec, lean: Vec, along_link: Vec, label: str) -> Vec:
    """The line of the guide's total reaction N n - mu |N| sign(v) t: leaning by ``-lean`` when the block
    bears on the face the normal points from (N >= 0), by ``+lean`` on the other face.  The face is the one
    whose polygon closes with a normal part of that sign (a part within rounding of zero fits either)."""
    tip = sum((v for _, v in knowns), ORIGIN)
    floor = NEGLIGIBLE * d.scale
    for direction, face in ((normal - lean, 1.0), (normal + lean, -1.0)):
        if abs(direction.unit().cross(along_link)) < PARALLEL_SINE:
            continue
        x = meet(tip, direction, ORIGIN, along_link)
        if (x - tip).dot(normal) * face >= -floor:
            return direction
    raise IndeterminatePosition(f"friction lock at {label}: with mu the guide's reaction cannot balance "
                                f"it on either face of its guide", position=describe_angle(d.pose.angle),
                                kind="friction lock")
