"""What kind of linkage a mechanism is, before any polygon is drawn (notes, "Condition to form a 4-bar
linkage", "Grashof condition", "Types of linkages", "Transmission angle", "Limiting position").

For the four-bar the crank drives -- frame O1O2 (length g), crank O1B (a), coupler BC (b), rocker O2C
(c) -- with s and l the shortest and longest of the four and p, q the others:

* it closes when l < s + p + q (the notes write <=; at equality the four links only lie flat, one
  position, no motion);
* Grashof when s + l < p + q, a change point when s + l = p + q (the branches meet where all four links
  line up), non-Grashof (a triple rocker) when s + l > p + q;
* a Grashof linkage is a crank-rocker when the shortest link is the crank (next to the frame), a drag
  link (double crank) when it is the frame, a double rocker when it is the coupler (opposite the frame),
  and a rocker-crank when it is the rocker (the crank then rocks and the output turns);
* the transmission angle mu, between coupler and rocker, follows from the law of cosines in the two
  triangles that share the diagonal BO2:  BO2^2 = a^2 + g^2 - 2 a g cos(theta) = b^2 + c^2 - 2 b c cos(mu),
  theta the crank angle from the frame line O1 -> O2.  cos(mu) falls as cos(theta) does, so for a crank
  that turns fully the extremes are at theta = 0 (mu_min, crank along the frame towards O2) and
  theta = 180 deg (mu_max) -- "when the crank aligns with the fixed link", as the notes say;
* the rocker's limit positions are where crank and coupler are in line (O1C = a + b extended, |b - a|
  folded): found here by construction, as circles about O1 and O2 crossing.

Lengths are compared with the scene's one tolerance (constructions.tolerance), so a designed change
point reads as one.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..errors import ConstructionError
from ..geometry import Circle, Contact, Vec, intersect_circles
from ..tolerance import COSINE_SLACK
from .assembly import CrankTip, TwoCircles, assembly_plan
from .model import Branch, Link, Mechanism, mobility


@dataclass(frozen=True)
class LimitPosition:
    """The rocker at a limit of its swing: crank and coupler in line, ``extended`` or folded."""

    extended: bool
    crank_angle: float          # rad, CCW from +x
    rocker_angle: float         # rad, direction O2 -> C, CCW from +x
    C: Vec


@dataclass(frozen=True)
class FourBarClass:
    """The classification of the four-bar the crank drives (frame, crank, coupler, rocker)."""

    joints: tuple[str, str, str, str]                # O1, B, C, O2
    lengths: tuple[float, float, float, float]       # frame g, crank a, coupler b, rocker c
    closes: bool
    grashof: str                                     # "Grashof", "change point", "non-Grashof"
    kind: str                                        # the notes' five types (+ rocker-crank)
    turns_fully: tuple[str, ...]                     # of crank and rocker, those that turn 360 deg
    transmission_min: float | None                   # rad, over the crank's motion
    transmission_max: float | None
    transmission_min_at: float | None                # crank angle (rad, from +x) where it occurs
    transmission_max_at: float | None
    limit_positions: tuple[LimitPosition, ...]
    mobility: tuple[int, str]

    def summary(self, fmt=None, names=("frame", "crank", "coupler", "rocker")) -> str:
        """The class in words with the inequality that decides it, lengths written by ``fmt(length)``
        (default: metres), the four links called ``names``."""
        fmt = fmt or (lambda v: f"{v:.6g} m")
        named = sorted(zip(self.lengths, names))
        (s_, s_name), (p_, _), (q_, _), (l_, l_name) = named
        if not self.closes:
            return (f"the links cannot form a four-bar: the longest, the {l_name} ({fmt(l_)}), is not shorter "
                    f"than the other three together ({fmt(s_ + p_ + q_)})")
        rel = {"Grashof": "<", "change point": "=", "non-Grashof": ">"}[self.grashof]
        why = f"s + l = {fmt(s_ + l_)} {rel} p + q = {fmt(p_ + q_)}"
        s = f"{self.grashof} {self.kind}" if self.grashof == "Grashof" else f"{self.kind} ({self.grashof})"
        role = dict(zip(("frame", "crank", "coupler", "rocker"), names))
        turns = ", ".join(role[t] for t in self.turns_fully) if self.turns_fully else "no link"
        return f"{s} ({why}, the shortest the {s_name}); {turns} {'turn' if len(self.turns_fully) > 1 else 'turns'} fully"


def _same(x: float, y: float, tol: float) -> bool:
    return abs(x - y) <= tol


def classify_four_bar(m: Mechanism) -> FourBarClass | None:
    """The class of the four-bar the crank drives, or None when the crank's first dyad is not hung from
    the crank tip and a second fixed pivot (a slider-crank, say)."""
    plan = assembly_plan(m)
    crank = plan[0]
    assert isinstance(crank, CrankTip)
    step = next((s for s in plan if isinstance(s, TwoCircles)), None)
    if step is None:
        return None
    ends = {step.first: (step.link_a, step.radius_a), step.second: (step.link_b, step.radius_b)}
    if crank.tip not in ends:
        return None
    o2 = next((c for c in ends if c in m.ground), None)
    if o2 is None:
        return None
    O1, O2 = m.ground[crank.pivot], m.ground[o2]
    g, a = O1.distance_to(O2), crank.link.length
    b, c = ends[crank.tip][1] or ends[crank.tip][0].length, ends[o2][1] or ends[o2][0].length
    tol = m.tolerance().length
    ls = sorted(((g, "frame"), (a, "crank"), (b, "coupler"), (c, "rocker")))
    (s, s_name), (p, _), (q, _), (l, _) = ls
    closes = l < s + p + q - tol
    if _same(s + l, p + q, tol):
        grashof, kind = "change point", "change-point linkage"
    elif s + l < p + q:
        grashof = "Grashof"
        kind = {"crank": "crank-rocker", "frame": "drag link (double crank)", "coupler": "double rocker",
                "rocker": "rocker-crank"}[s_name]
    else:
        grashof, kind = "non-Grashof", "triple rocker"
    if grashof == "Grashof":
        turns = {"crank-rocker": ("crank",), "drag link (double crank)": ("crank", "rocker"),
                 "double rocker": (), "rocker-crank": ("rocker",)}[kind]
    elif grashof == "change point":
        turns = ("crank",) if s_name in ("crank", "frame") else ()
    else:
        turns = ()

    # transmission angle over the crank's motion: cos(mu) = (b^2 + c^2 - BO2^2) / (2 b c)
    frame_dir = (O2 - O1).angle()

    def mu_at(theta_rel: float) -> float | None:
        d2 = a * a + g * g - 2 * a * g * math.cos(theta_rel)
        cm = (b * b + c * c - d2) / (2 * b * c)
        return math.acos(max(-1.0, min(1.0, cm))) if abs(cm) <= 1 + COSINE_SLACK else None

    t_min = t_max = at_min = at_max = None
    if closes and "crank" in turns:
        t_min, t_max = mu_at(0.0), mu_at(math.pi)
        at_min, at_max = frame_dir, frame_dir + math.pi
        if t_min is not None and t_max is not None and t_min > t_max:   # an open or crossed assembly
            t_min, t_max, at_min, at_max = t_max, t_min, at_max, at_min

    # the rocker's limit positions: crank and coupler in line (O1C = a + b or |b - a|), by construction
    limits = []
    sign = step.branch.sign if step.branch.reference == (crank.tip, o2) else -step.branch.sign
    if closes:
        for extended, reach in ((True, a + b), (False, abs(b - a))):
            if reach <= tol:
                continue
            hit = intersect_circles(Circle(O1, reach), Circle(O2, c), m.tolerance())
            if hit.contact is Contact.APART:
                continue
            # the crossing on the scene's assembly side of the line O1 -> O2
            C = hit.points[0] if (hit.contact is Contact.TANGENT or sign > 0) else hit.points[1]
            # extended: B on O1C; folded, C = (a - b) u along the crank's direction u: for b > a the crank
            # points away from C, for a > b towards it
            along = (C - O1).angle()
            crank_angle = along if extended or a > b else along + math.pi
            limits.append(LimitPosition(extended, crank_angle, (C - O2).angle(), C))
    return FourBarClass((crank.pivot, crank.tip, step.joint, o2), (g, a, b, c), closes, grashof, kind, turns,
                        t_min, t_max, at_min, at_max, tuple(limits), mobility(m))


@dataclass(frozen=True)
class Loop:
    """A further four-bar loop of a larger mechanism: the link ``input`` turning about its fixed pivot
    drives the dyad that finds ``joint`` against a second fixed pivot; ``k`` is its class with that link
    as the input (frame, input, coupler, output as ``k.joints``)."""

    input: int
    joint: str
    k: FourBarClass


def classify_loops(m: Mechanism) -> tuple[Loop, ...]:
    """The four-bar loops after the crank's own: each two-circle dyad hung from a fixed pivot and from a
    point of a link that turns about a fixed pivot of its own (a rocker driving a second rocker, as in a
    Watt or Stephenson six-bar), classified as a four-bar with that link as its input.  The input's own
    swing may be less than a turn, so "turns fully" is what the loop's lengths allow."""
    out = []
    first = classify_four_bar(m)
    for step in assembly_plan(m)[1:]:
        if not isinstance(step, TwoCircles) or (first is not None and step.joint == first.joints[2]):
            continue
        centres = {step.first: step.link_a, step.second: step.link_b}
        fixed = [c for c in centres if c in m.ground]
        moving = [c for c in centres if c not in m.ground]
        if len(fixed) != 1 or len(moving) != 1:
            continue
        o2, p = fixed[0], moving[0]
        drivers = [k for k in m.links if p in m.points_of(k.number) and k.number != centres[p].number
                   and any(j in m.ground for j in k.joints)]
        for k in drivers:
            q = next(j for j in k.joints if j in m.ground)
            loc = m.local(k.number)
            arm = (loc[p] - loc[q]).norm()
            if arm <= m.tolerance().length or q == o2:
                continue
            radius_a = step.radius_a if step.first == p else step.radius_b
            radius_b = step.radius_b if step.first == p else step.radius_a
            coupler = radius_a or centres[p].length
            output = radius_b or centres[o2].length
            b = step.branch
            sub = Mechanism({q: m.ground[q], o2: m.ground[o2]},
                            (Link(k.number, (q, p), arm), Link(centres[p].number, (p, step.joint), coupler),
                             Link(centres[o2].number, (o2, step.joint), output)), (), (), k.number,
                            {step.joint: Branch(b.sign, b.reference)})
            try:
                got = classify_four_bar(sub)
            except ConstructionError:              # a loop the four-bar rules cannot read: leave it out
                continue
            if got is not None:
                out.append(Loop(k.number, step.joint, got))
    return tuple(out)
