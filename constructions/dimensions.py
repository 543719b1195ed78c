"""The space diagram dimensioned as a drafter dimensions a linkage (ISO 129): every link's length between
its joints, each fixed pivot's position from the crank's pivot, and a guide's offset from it.

Dimension lines stand off on the side of each link away from the mechanism's middle, so they do not
cross the links they measure; the crank angle is already on the space diagram.  The texts are values
("$l") the sheet writes in the scene's units.
"""

from __future__ import annotations

from .entities import Diagram, Dimension, Role
from .geometry import Vec
from .mechanisms.model import Mechanism
from .mechanisms.pose import Pose
from .record import Construction, Value
from .tolerance import DECISION

STANDOFF = 0.12
"""How far a dimension line stands off its link, as a fraction of the mechanism's size."""


def dimension_links(m: Mechanism, pose: Pose) -> Construction:
    """``pose``'s construction with one more step: the links, fixed pivots and guide offsets dimensioned."""
    pos = pose.positions
    pts = list(pos.values())
    mid = Vec(sum(p.x for p in pts) / len(pts), sum(p.y for p in pts) / len(pts))
    off = STANDOFF * m.size
    ents = []
    values = {}
    for k in sorted(m.links, key=lambda k: k.number):
        a, b = (pos[j] for j in k.joints)
        if (b - a).norm() <= 0:
            continue
        ents.append(Dimension(f"dimension link {k.number}", Role.DIMENSION, Diagram.SPACE, *_outward(a, b, mid),
                              off, f"$l{k.number}"))
        values[f"l{k.number}"] = Value("length", k.length)
    crank = m.link(m.crank)
    o1 = next(j for j in crank.joints if j in m.ground)
    for g, p in sorted(m.ground.items()):
        if g == o1 or (p - m.ground[o1]).norm() <= 0:
            continue
        ents.append(Dimension(f"dimension {o1}{g}", Role.DIMENSION, Diagram.SPACE,
                              *_outward(m.ground[o1], p, mid), off, f"$g{g}"))
        values[f"g{g}"] = Value("length", (p - m.ground[o1]).norm())
    for s in m.slides:
        if s.on is not None:
            continue
        foot = s.line.foot(m.ground[o1])
        if (foot - m.ground[o1]).norm() <= DECISION * m.size:
            continue
        ents.append(Dimension(f"dimension offset {s.joint}", Role.DIMENSION, Diagram.SPACE,
                              m.ground[o1], foot, 0.0, f"e $e{s.joint}"))
        values[f"e{s.joint}"] = Value("length", (foot - m.ground[o1]).norm())
    if not ents:
        return pose.construction
    what = ["the links (joint to joint)"]
    if any(e.name.startswith(f"dimension {o1}") for e in ents):
        what.append(f"the fixed pivots from {o1}")
    if any(e.name.startswith("dimension offset") for e in ents):
        what.append("the guides' offsets")
    words = ", ".join(what[:-1]) + " and " + what[-1] if len(what) > 1 else what[0]
    return pose.construction.then(f"Dimension {words}.", *ents, values=values)


def _outward(a: Vec, b: Vec, mid: Vec) -> tuple[Vec, Vec]:
    """(start, end) ordered so that the dimension's left side (where it stands off) faces away from
    ``mid``."""
    left = (b - a).perp()
    centre = (a + b) * 0.5
    return (a, b) if left.dot(centre - mid) >= 0 else (b, a)
