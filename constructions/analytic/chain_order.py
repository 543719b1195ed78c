"""The order in which the dyad-chain vector loop solves a mechanism: the crank, then each joint as an RRR
or RRP dyad of joints already known, then the points fixed to links.  It reads only the data of the
:class:`~constructions.linkage.Mechanism` (pivots, links, guides, branches), never its assembly plan."""

from __future__ import annotations

from dataclasses import dataclass

from ..errors import DegenerateInput
from ..mechanisms.model import Attached, Branch, Link, Mechanism, Slide

__all__ = ["CrankStep", "PointStep", "RRPDyad", "RRRDyad", "chain_plan", "solving_order"]


@dataclass(frozen=True, slots=True)
class CrankStep:
    """The crank: its tip ``joint`` turns about the fixed ``pivot``."""

    joint: str          # the crank tip
    pivot: str
    link: Link


@dataclass(frozen=True, slots=True)
class RRRDyad:
    """J = the joint left (sign +1) or right of P -> Q, |PJ| = link_p.length, |QJ| = link_q.length."""

    joint: str
    p: str
    q: str
    link_p: Link
    link_q: Link
    sign: int


@dataclass(frozen=True, slots=True)
class RRPDyad:
    """J on the guide of ``slide``, |PJ| = link.length, ahead (sign +1) of or behind the foot of P."""

    joint: str
    p: str
    link: Link
    slide: Slide
    sign: int


@dataclass(frozen=True, slots=True)
class PointStep:
    """A point fixed to the binary ``link``."""

    point: Attached
    link: Link


def _links_between(m: Mechanism, a: str, b: str) -> list[Link]:
    return [k for k in m.links if set(k.joints) == {a, b}]


def chain_plan(m: Mechanism) -> tuple[CrankStep, tuple[RRRDyad | RRPDyad, ...], tuple[PointStep, ...]]:
    """Which joint is solvable from which known ones.

    Known at the start: the fixed pivots and the crank tip.  A joint becomes solvable when it is carried
    by a slider block and the joint its branch refers to is known and linked to it (an RRP dyad), or
    when both joints its branch refers to are known and each is linked to it (an RRR dyad).  The
    branch names the two (or one) known joints, so the dyad found does not depend on the order in
    which joints are visited.
    """
    crank = next((k for k in m.links if k.number == m.crank), None)
    if crank is None:
        raise DegenerateInput(f"the crank, link {m.crank}, is not a binary link of the mechanism")
    pivots = [j for j in crank.joints if j in m.ground]
    if len(pivots) != 1:
        raise DegenerateInput(f"the crank, link {crank.number}, must join one fixed pivot to one moving joint")
    tip = crank.other(pivots[0])
    slides: dict[str, Slide] = {}
    for s in m.slides:
        if getattr(s, "on", None) is not None:
            raise DegenerateInput(f"joint {s.joint} slides in a slot of the moving link {s.on}; the dyad "
                                  f"chain models straight guides fixed to the frame only")
        if s.joint in m.ground:
            raise DegenerateInput(f"slider joint {s.joint} is also a fixed pivot")
        if s.joint in slides:
            raise DegenerateInput(f"joint {s.joint} is carried by two slider blocks")
        if s.joint == tip:
            raise DegenerateInput(f"the crank tip {tip} cannot also run on a guide")
        slides[s.joint] = s
    joints = {j for k in m.links for j in k.joints} | set(slides)
    known = set(m.ground) | {tip}
    dyads: list[RRRDyad | RRPDyad] = []
    progress = True
    while progress:
        progress = False
        for j in sorted(joints - known):
            b: Branch | None = m.branches.get(j)
            if b is None or not all(r in known for r in b.reference):
                continue
            if j in slides:
                if len(b.reference) != 1:
                    raise DegenerateInput(f"the branch of slider joint {j} must be \"ahead of\" or "
                                          f"\"behind\" the joint it hangs from")
                (p,) = b.reference
                ks = _links_between(m, p, j)
                if not ks:
                    raise DegenerateInput(f"the branch of {j} refers to {p}, which has no link to {j}")
                dyads.append(RRPDyad(j, p, ks[0], slides[j], 1 if b.sign > 0 else -1))
            else:
                if len(b.reference) != 2:
                    raise DegenerateInput(f"the branch of {j} must be \"left of\" or \"right of\" a line "
                                          f"between the two joints it is found from")
                p, q = b.reference
                kp, kq = _links_between(m, p, j), _links_between(m, q, j)
                if not kp or not kq:
                    raise DegenerateInput(f"the branch of {j} refers to {p} and {q}, but {j} is not linked "
                                          f"to both")
                dyads.append(RRRDyad(j, p, q, kp[0], kq[0], 1 if b.sign > 0 else -1))
            known.add(j)
            progress = True
    missing = sorted(joints - known)
    if missing:
        j = missing[0]
        why = ("it has no assembly branch" if j not in m.branches else
               "it needs two links to known joints, or one link to a known joint and a slider guide")
        raise DegenerateInput(f"joint {j} cannot be solved: {why}")
    points: list[PointStep] = []
    for a in m.attached:
        link = next((k for k in m.links if k.number == a.link), None)
        if link is None:
            raise DegenerateInput(f"point {a.name} is on link {a.link}, which is not a binary link")
        if a.base not in link.joints:
            raise DegenerateInput(f"point {a.name} is measured from {a.base}, which is not a joint of "
                                  f"link {link.number}")
        points.append(PointStep(a, link))
    return CrankStep(tip, pivots[0], crank), tuple(dyads), tuple(points)


def solving_order(m: Mechanism) -> tuple[str, ...]:
    """The joints in the order the chain is solved (crank tip first), then the points fixed to links."""
    crank, dyads, points = chain_plan(m)
    return (crank.joint,) + tuple(d.joint for d in dyads) + tuple(p.point.name for p in points)
