"""The space diagram's conventions, as the notes draw them: every link's number beside it (the frame's
at a fixed pivot) and the driver's angular velocity (and angular acceleration, when it has one) as arc
arrows about the driving pivot in their sense.

The numbers are the scene's (the crank is the link the scene drives); the frame takes the number the
instant centres give it (:func:`constructions.mechanisms.topology.frame_number`: 1, or 0 when a moving
link is 1).  Nothing is solved here: the anchors are the joints' positions read off the pose.
"""

from __future__ import annotations

import math

from constructions.entities import AngleMark, Diagram, LinkNumber, Role
from constructions.geometry import Vec
from constructions.mechanisms.model import Mechanism
from constructions.mechanisms.pose import Pose
from constructions.mechanisms.topology import frame_number
from constructions.record import Construction, StepKind, Value

ROTATION_SPAN = math.radians(50.0)
"""The arc of a rotation arrow: 50 deg, straddling the crank."""
OMEGA_REACH = 0.65
"""The omega arrow stands 0.65 of the crank's length out from its pivot (the crank-angle mark at 0.45) ..."""
ALPHA_REACH = 0.85
"""... and the alpha arrow 0.85 out, between it and the crank pin."""
OMEGA_TEXT_AT, ALPHA_TEXT_AT = 0.3, 0.85
"""With both arrows drawn, omega's value 0.3 of the way along its arc and alpha's by its head: either side
of the crank, each by its own arc (the two straddle the crank a few mm apart).  Omega alone: by its middle."""
OMEGA_LEAST, ALPHA_LEAST = 9.0, 14.0
"""mm on paper: however short the crank is drawn, the omega arrow stands at least 9 mm out and the alpha
arrow 14 mm, clear of the crank-angle mark (at least 6 mm: ``render.annotations.ANGLE_MIN_R``) and of
each other, so each arc reads as its own and carries its own value."""


def link_numbers(m: Mechanism, pose: Pose) -> list[LinkNumber]:
    """Each link's number at its middle (a plate's: the centre of its points), each block's at the block,
    the frame's at the crank's fixed pivot."""
    pos = pose.positions
    out = [LinkNumber("number frame", Role.LABEL, Diagram.SPACE, pos[m.crank_pivot()], frame_number(m))]
    for k in m.links:
        pts = [pos[x] for x in m.points_of(k.number) if x in pos]
        if len(pts) < 2:
            continue
        if len(pts) == 2:
            at = (pts[0] + pts[1]) * 0.5
        else:
            at = Vec(sum(p.x for p in pts) / len(pts), sum(p.y for p in pts) / len(pts))
        out.append(LinkNumber(f"number link {k.number}", Role.LABEL, Diagram.SPACE, at, k.number))
    for number, s in sorted(m.blocks().items()):
        if s.joint in pos:
            out.append(LinkNumber(f"number block {number}", Role.LABEL, Diagram.SPACE, pos[s.joint], number))
    return out


def rotation_arrow(name: str, pivot: Vec, tip: Vec, rate: float, text: str, reach: float,
                   least: float = 0.0, text_at: float = 0.5) -> AngleMark:
    """The arc arrow of the crank's ``rate`` (omega or alpha, CCW positive) about its ``pivot``, ``reach`` of
    the crank out (at least ``least`` mm on paper), straddling the crank and pointing in the sense of
    ``rate``, its value at ``text_at`` of the way along it."""
    r = tip - pivot
    half = ROTATION_SPAN / 2 * (1.0 if rate > 0 else -1.0)
    return AngleMark(name, Role.GIVEN, Diagram.SPACE, pivot, reach * r.norm(), r.angle() - half, r.angle() + half,
                     text, least, text_at)


def conventions(m: Mechanism, pose: Pose, omega: float, alpha: float | None) -> Construction:
    """The step that numbers the links and marks the driver's omega (and alpha, when given and not 0)."""
    n = m.crank
    pivot = m.crank_pivot()
    tip = next(j for j in m.link(n).joints if j != pivot)
    pos = pose.positions
    ents: list = link_numbers(m, pose)
    words = f"Number the links as the notes do: the frame {frame_number(m)}, the links and blocks by their numbers"
    values = {}
    if omega != 0:
        ents.append(rotation_arrow(f"omega {n}", pos[pivot], pos[tip], omega, f"\u03c9_{n} = $w", OMEGA_REACH,
                                   OMEGA_LEAST, OMEGA_TEXT_AT if alpha else 0.5))
        words += f"; the crank {pivot}{tip} turns at \u03c9_{n} = $w {'CCW' if omega > 0 else 'CW'}"
        values["w"] = Value("angular velocity", abs(omega))
    if alpha:
        ents.append(rotation_arrow(f"alpha {n}", pos[pivot], pos[tip], alpha, f"\u03b1_{n} = $al", ALPHA_REACH,
                                   ALPHA_LEAST, ALPHA_TEXT_AT))
        words += f", \u03b1_{n} = $al {'CCW' if alpha > 0 else 'CW'}"
        values["al"] = Value("angular acceleration", abs(alpha))
    return Construction("Space diagram").then(words + ".", *ents, values=values, kind=StepKind.GIVEN)
