"""How a linkage is put together: the assembly plan, the order of construction the notes follow by hand.

:func:`assembly_plan` starts from the crank tip at the input angle, then, dyad by dyad, finds every joint
from two loci -- two circles (RRR), a circle and a guide or slot (RRP), or the line of a slot through a
known joint (RPR: the slotted link's direction) -- with the assembly branch the scene chose, and places
the points of every link whose position is then fixed.  :func:`.pose.locate` carries the plan out at one
crank angle.
"""

from __future__ import annotations

from dataclasses import dataclass

from ..errors import DegenerateInput
from .model import Attached, Branch, Link, Mechanism, Slide, coincident_name, mobility


@dataclass(frozen=True, slots=True)
class CrankTip:
    link: Link
    pivot: str
    tip: str


@dataclass(frozen=True, slots=True)
class TwoCircles:
    """Joint found where the circle about ``first`` (radius ``radius_a``, on link_a) meets the circle
    about ``second`` (radius ``radius_b``, on link_b)."""

    joint: str
    link_a: Link
    first: str
    link_b: Link
    second: str
    branch: Branch
    radius_a: float = 0.0
    radius_b: float = 0.0


@dataclass(frozen=True, slots=True)
class CircleAndGuide:
    """Joint found where the circle about ``centre`` (radius ``radius``, on ``link``) meets the guide of
    ``slide``, or its slot when the slotted link is already placed."""

    joint: str
    link: Link
    centre: str
    slide: Slide
    branch: Branch
    radius: float = 0.0
    coincident: str = ""          # on a slot: the point of the slotted link under the joint


@dataclass(frozen=True, slots=True)
class SlotThrough:
    """The slotted link ``link`` turns about its known point ``centre`` until its slot passes through the
    known joint ``joint`` (an RPR dyad: inverted slider-crank, slotted lever); ``coincident`` names the
    point of the slotted link under the joint (the notes' A_3 beside A_2)."""

    joint: str
    link: Link
    centre: str
    slide: Slide
    branch: Branch
    coincident: str


@dataclass(frozen=True, slots=True)
class SlotAlongGuide:
    """A translating slotted link (Scotch yoke): ``link`` runs along one fixed guide, its two base joints
    in blocks on it (``guides``), so it cannot turn; it slides along the guide until its slot passes
    through the known joint ``joint``.  Its base line points along the first block's guide; ``coincident``
    names the point of the yoke under the joint (A3 beside A)."""

    joint: str
    link: Link
    slide: Slide
    guides: tuple[Slide, Slide]
    coincident: str


@dataclass(frozen=True, slots=True)
class TwoLines:
    """Joint found where the lines of two slides cross (a PRP dyad): the joint carries two blocks (or
    pins), each sliding on a fixed guide or on the slot of a placed link; ``coincident_a``/``_b`` name the
    point of each slotted link under the joint ("" for a fixed guide)."""

    joint: str
    slide_a: Slide
    slide_b: Slide
    coincident_a: str = ""
    coincident_b: str = ""


@dataclass(frozen=True, slots=True)
class FixedToLink:
    """A point of ``link`` placed once two of its points, ``via``, are known (rigid body)."""

    point: Attached | str
    link: Link
    via: tuple[str, str] = ("", "")

    @property
    def name(self) -> str:
        return self.point if isinstance(self.point, str) else self.point.name


PlanStep = CrankTip | TwoCircles | CircleAndGuide | SlotThrough | SlotAlongGuide | TwoLines | FixedToLink
Dyad = TwoCircles | CircleAndGuide | SlotThrough | TwoLines

def assembly_plan(m: Mechanism) -> tuple[PlanStep, ...]:
    """Order in which the joints are constructed; raises DegenerateInput when the linkage is not 1-DoF or
    is not a crank followed by dyads (it says which joint cannot be reached and why).  Found once per
    mechanism (:meth:`Mechanism.derived`)."""
    return m.derived(_assembly_plan)


def _assembly_plan(m: Mechanism) -> tuple[PlanStep, ...]:
    pivot = m.crank_pivot()
    crank = m.link(m.crank)
    seen: set[str] = set()
    twice: set[str] = set()
    for s in m.slides:
        if s.joint in m.ground:
            raise DegenerateInput(f"slider joint {s.joint} is also a fixed pivot")
        if s.joint in seen and s.joint in twice:
            raise DegenerateInput(f"joint {s.joint} is carried by three sliders; a joint takes at most two")
        if s.joint in seen:
            twice.add(s.joint)
        seen.add(s.joint)
        if s.on is not None:
            m.link(s.on)
            if s.joint in m.points_of(s.on):
                raise DegenerateInput(f"joint {s.joint} cannot slide on link {s.on}, which it belongs to")
    local = {k.number: m.local(k.number) for k in m.links}
    tip = crank.other(pivot)
    plan: list[PlanStep] = [CrankTip(crank, pivot, tip)]
    known = set(m.ground) | {tip}
    posed: set[int] = set()                      # links whose every point is fixed
    slides: dict[str, list[Slide]] = {}
    for sl in m.slides:
        slides.setdefault(sl.joint, []).append(sl)
    everything = set(m.ground) | {j for pts in local.values() for j in pts} | set(slides)

    def pose_points(number: int) -> bool:
        """Once two points of a link are known, place the rest (FixedToLink)."""
        pts = local[number]
        have = [x for x in pts if x in known]
        if len(have) < 2:
            return False
        link = m.link(number)
        via = (link.joints[0], link.joints[1]) if all(j in known for j in link.joints) else (have[0], have[1])
        for x in pts:
            if x not in known:
                att = next((a for a in m.attached if a.name == x and a.link == number), None)
                plan.append(FixedToLink(att if att is not None and set(via) == set(link.joints) else x, link, via))
                known.add(x)
        posed.add(number)
        return True

    def circles(j: str) -> list[tuple[Link, str, float]]:
        """(link, known centre, radius) for every unposed link through j with exactly one known point."""
        out = []
        for k in m.links:
            pts = local[k.number]
            if k.number in posed or j not in pts:
                continue
            have = [x for x in pts if x in known]
            if len(have) == 1:
                out.append((k, have[0], pts[j].distance_to(pts[have[0]])))
        return out

    while True:
        progress = False
        for n in sorted(local):
            if n not in posed and pose_points(n):
                progress = True
        for j in sorted(everything - known):
            cs = circles(j)
            on_lines = slides.get(j, [])
            placed = [sl for sl in on_lines if sl.on is None or sl.on in posed]
            s = placed[0] if placed else (on_lines[0] if on_lines else None)
            if len(on_lines) == 2 and len(placed) == 2:
                a, b = placed
                plan.append(TwoLines(j, a, b,
                                     coincident_name(j, a.on, everything) if a.on is not None else "",
                                     coincident_name(j, b.on, everything) if b.on is not None else ""))
            elif s is None and len(cs) >= 2:
                (ka, a, ra), (kb, b, rb) = cs[:2]
                branch = _branch_for(m, j, (a, b))
                if branch.reference == (b, a):
                    (ka, a, ra), (kb, b, rb) = (kb, b, rb), (ka, a, ra)
                plan.append(TwoCircles(j, ka, a, kb, b, branch, ra, rb))
            elif s is not None and len(on_lines) == 1 and cs and (s.on is None or s.on in posed):
                k, c, r = cs[0]
                plan.append(CircleAndGuide(j, k, c, s, _branch_for(m, j, (c,)), r,
                                           coincident_name(j, s.on, everything) if s.on is not None else ""))
            else:
                continue
            known.add(j)
            progress = True
        for j, s in [(sl.joint, sl) for key in sorted(slides) for sl in slides[key]]:
            if j in known and s.on is not None and s.on not in posed:
                pts = local[s.on]
                have = [x for x in pts if x in known]
                if len(have) == 1:
                    link = m.link(s.on)
                    plan.append(SlotThrough(j, link, have[0], s, _branch_for(m, j, (have[0],)),
                                            coincident_name(j, s.on, everything)))
                    for x in pts:
                        known.add(x)
                    posed.add(s.on)
                    progress = True
                elif not have and _guided_pair(m, s.on, slides) is not None:
                    link = m.link(s.on)
                    plan.append(SlotAlongGuide(j, link, s, _guided_pair(m, s.on, slides),
                                               coincident_name(j, s.on, everything)))
                    known.update(pts)
                    posed.add(s.on)
                    progress = True
        if not progress:
            break
    missing = sorted(everything - known)
    f, working = mobility(m)
    if f != 1:
        loose = (f"; joint {missing[0]} cannot be constructed: it needs two links to known joints, or one "
                 f"link and a guide or placed slot") if missing and f > 1 else ""
        # a joint named on one link only, that nothing else holds, is usually a fixed pivot left undeclared
        held = set(m.ground) | set(slides) | {a.name for a in m.attached}
        on_links: dict[str, list[int]] = {}
        for k in m.links:
            for j in k.joints:
                on_links.setdefault(j, []).append(k.number)
        loose_ends = [j for j in sorted(on_links) if len(on_links[j]) == 1 and j not in held
                      and j != tip and j in missing]
        if f > 1 and loose_ends:
            j = loose_ends[0]
            loose = (f"; {j} is held by link {on_links[j][0]} only: join it to another link, put it on a "
                     f"slider, or declare it a fixed pivot")
        raise DegenerateInput(f"the mechanism has {f} degrees of freedom ({working}); a crank drives only a "
                              f"mechanism with one{loose}")
    if missing:
        raise DegenerateInput(f"joint {missing[0]} cannot be constructed dyad by dyad: it needs two links to "
                              f"known joints, or one link and a guide or placed slot (a loop that must be "
                              f"solved as a whole is not drawn by this method)")
    return tuple(plan)


def _guided_pair(m: Mechanism, number: int, slides: dict[str, list[Slide]]) -> tuple[Slide, Slide] | None:
    """The blocks on fixed guides that carry both base joints of link ``number`` when the two guides are
    one line along the link (a yoke that only translates), else None."""
    link = m.link(number)
    pair = []
    for j in link.joints:
        own = [s for s in slides.get(j, []) if s.on is None and s.number is not None]
        if len(slides.get(j, [])) != 1 or len(own) != 1:
            return None
        pair.append(own[0])
    a, b = pair
    ga, gb = a.line, b.line
    tol = m.tolerance()
    if abs(ga.direction.cross(gb.direction)) > tol.sine or abs(ga.signed_distance(b.through)) > tol.length:
        return None
    return a, b


def _branch_for(m: Mechanism, joint: str, centres: tuple[str, ...]) -> Branch:
    b = m.branches.get(joint)
    expect = (f'"left of {centres[0]}->{centres[1]}" or "right of {centres[0]}->{centres[1]}"'
              if len(centres) == 2 else f'"ahead of {centres[0]}" or "behind {centres[0]}"')
    if b is None:
        raise DegenerateInput(f"joint {joint} has two assemblies; choose one with {expect}")
    if sorted(b.reference) != sorted(centres):
        raise DegenerateInput(f"the branch of {joint} must be given relative to the joints it is found "
                              f"from: {expect}")
    return b

