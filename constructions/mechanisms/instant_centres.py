"""Instant centres by Kennedy's theorem, and the velocities they give.

A mechanism of N bodies (the frame, the links, the slider blocks) has N (N - 1) / 2 instant centres, one
for each pair of bodies.  The primary ones are read off the joints:

- bodies pinned together share a centre at the pin;
- a block sliding on a guide (fixed, or a slot of a link) has its centre at infinity, square to the guide;
- a pin running in a slot (a higher pair) puts the centre of its link and the slotted link somewhere on
  the normal to the slot through the pin: one line, not a point.

Kennedy's theorem finds the rest: the three centres of any three bodies lie on one line, so I_ij lies on
the line I_ik I_jk for every body k whose two centres are known; two such lines cross at I_ij.  Points
and lines are homogeneous 3-vectors (a point at infinity has w = 0, the line through two points is their
cross product, the crossing of two lines is theirs), so centres at infinity need no special case: the line
through a finite centre and one at infinity runs in that direction, and two parallel lines cross at
infinity.  Among the lines a pair has, the two crossing at the largest angle are used; where every pair of
lines coincides (a change point, a toggle) the centre is named as not found.

The velocities follow without a polygon: the crank turns about I_1c at omega; for each further body k and
a body j already known, the common centre I_jk has one velocity on both, so omega_k = r x V / |r|^2 with
r = I_jk - I_1k (or, with I_1k at infinity, k translates with the velocity of I_jk; with I_jk at infinity,
omega_k = omega_j).  The values are read off the construction; the linkage family shows them beside the
polygon's and the analytic ones.
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass, field
from typing import Mapping

import numpy as np

from ..entities import Point, Role
from ..geometry import Vec
from ..quantities import Measured
from ..record import Construction, StepKind, Value
from .centre_diagram import circle_diagram, drawn_box, infinity_arrow, kennedy_entities, link_bars
from .centres import DIAGRAM, FAR, Centre, Pair, centre_name, pair
from .model import Mechanism, slide_line
from .pose import Pose
from .topology import Contact, SlotPin, connections, frame_number, moving_bodies, points_of_body

PARALLEL = 1e-9
"""Below this (normalised) crossing two Kennedy lines are one line: the centre is not found from them."""


@dataclass(frozen=True)
class InstantCentres:
    """Every instant centre found (``centres``), those Kennedy could not find (``missing``), and the
    angular velocities and point velocities read off them (SI, CCW positive)."""

    construction: Construction
    frame: int
    bodies: tuple[int, ...]
    centres: Mapping[Pair, Centre]
    missing: tuple[Pair, ...]
    angular: Mapping[int, float]
    velocities: Mapping[str, Vec]
    warnings: tuple[str, ...] = ()
    conditions: Mapping[str, float] = field(default_factory=dict)

    @property
    def worst_condition(self) -> float:
        return min(self.conditions.values(), default=1.0)

    def measured(self, m: Mechanism, suffix: str = " (instant centres)") -> list[Measured]:
        """The velocities of the moving points and the angular velocities of the links (not the crank,
        not blocks), named as the polygon's with ``suffix``."""
        c = self.worst_condition
        out = [Measured(f"V_{n}{suffix}", "velocity", v, c) for n, v in self.velocities.items()
               if n not in m.ground]
        skip = {m.crank} | set(m.blocks())
        out += [Measured(f"omega_{k}{suffix}", "angular velocity", w, c) for k, w in sorted(self.angular.items())
                if k not in skip and k != self.frame]
        return out


def _h(v: Vec, w: float = 1.0) -> np.ndarray:
    return np.array([v.x, v.y, w])


def _unit(h: np.ndarray) -> np.ndarray:
    return h / np.linalg.norm(h)


def instant_centres(m: Mechanism, pose: Pose, omega: float) -> InstantCentres:
    """All instant centres of ``m`` at ``pose`` by Kennedy's theorem, and the velocities at crank speed
    ``omega`` (rad/s, CCW positive) read off them."""
    pos = pose.positions
    f = frame_number(m)
    bodies = (f,) + moving_bodies(m)
    # work in coordinates centred on the mechanism and scaled by its size, so that the homogeneous
    # cross products compare like with like whatever the units
    pts = list(pos.values())
    mid = Vec(sum(p.x for p in pts) / len(pts), sum(p.y for p in pts) / len(pts))
    size = max(m.size, max((p - mid).norm() for p in pts), 1e-300)

    def norm(p: Vec) -> Vec:
        return (p - mid) * (1.0 / size)

    found: dict[Pair, Centre] = {}
    known: dict[Pair, np.ndarray] = {}
    fixed_lines: dict[Pair, list[tuple[np.ndarray, str]]] = {}
    rec = Construction("Instant centres")
    n = len(bodies)
    rec = rec.then(f"Number the bodies: the frame {f}, " + ", ".join(_body(m, b) for b in bodies[1:])
                   + f". {n} bodies have {n} \u00d7 {n - 1} / 2 = {n * (n - 1) // 2} instant centres.",
                   kind=StepKind.GIVEN)

    def place(c: Centre) -> None:
        found[c.bodies] = c
        known[c.bodies] = _unit(np.array([
            (c.point[0] / c.point[2] - mid.x) / size, (c.point[1] / c.point[2] - mid.y) / size, 1.0])
            if c.finite else np.array([c.point[0], c.point[1], 0.0]))

    rec = rec.then("Draw the links where they are.", *link_bars(m, pos), kind=StepKind.GIVEN)
    # primary centres: pins shared by bodies, one step (and one point) per pin
    for p in pos:
        on = [b for b in bodies if p in _points(m, b, f)]
        new = [pair(a, b) for a, b in itertools.combinations(on, 2) if pair(a, b) not in found]
        for q in new:
            place(Centre(q, (pos[p].x, pos[p].y, 1.0), f"the pin {p}"))
        if new:
            names = [centre_name(q) for q in new]
            label = ", ".join(names)
            words = (names[0] + " is") if len(names) == 1 else (", ".join(names[:-1]) + " and " + names[-1] + " are")
            ents = (Point(f"ic {label}", Role.RESULT, DIAGRAM, pos[p], label),) if norm(pos[p]).norm() <= FAR else ()
            rec = rec.then(f"{words} the pin {p}.", *ents, kind=StepKind.CONSTRUCTION)
    for c in connections(m):
        if isinstance(c, Contact):
            line = slide_line(m, c.slide, pos)
            nrm = line.direction.perp()
            q = pair(c.block, c.guide)
            place(Centre(q, (nrm.x, nrm.y, 0.0), f"at infinity, square to the {_guide(m, c.guide, f)} block "
                                                   f"{c.block} slides on"))
            rec = rec.then(f"{centre_name(q)} is {found[q].how}.",
                           infinity_arrow(centre_name(q), pos[c.joint], nrm, "guide" if c.guide == f else "slot",
                                          m.size), kind=StepKind.CONSTRUCTION)
        elif isinstance(c, SlotPin):
            line = slide_line(m, c.slide, pos)
            nrm = line.direction.perp()
            q = pair(c.carrier, c.guide)
            hl = np.cross(_h(norm(pos[c.joint])), np.array([nrm.x, nrm.y, 0.0]))
            fixed_lines.setdefault(q, []).append((_unit(hl), f"the normal to the slot at {c.joint}"))
            rec = rec.then(f"{centre_name(q)} lies on the normal to the slot of link {c.guide} at {c.joint} "
                           f"(the pin of {_body(m, c.carrier)} slides and turns there).", kind=StepKind.CONSTRUCTION)

    # Kennedy's theorem until nothing more is found
    conditions: dict[str, float] = {}
    progress = True
    while progress:
        progress = False
        for i, j in itertools.combinations(bodies, 2):
            q = pair(i, j)
            if q in found:
                continue
            lines: list[tuple[np.ndarray, object]] = list(fixed_lines.get(q, []))
            for k in bodies:
                a, b = pair(i, k), pair(j, k)
                if k in q or a not in known or b not in known:
                    continue
                hl = np.cross(known[a], known[b])
                if np.linalg.norm(hl) > PARALLEL:
                    lines.append((_unit(hl), (a, b)))
            best = None
            for (l1, s1), (l2, s2) in itertools.combinations(lines, 2):
                x = np.cross(l1, l2)
                s = float(np.linalg.norm(x))
                if best is None or s > best[0]:
                    best = (s, x, s1, s2)
            if best is None or best[0] <= PARALLEL:
                continue
            s, x, s1, s2 = best
            x = _unit(x)
            if abs(x[2]) > 1e-12 * np.linalg.norm(x[:2]):
                at = Vec(float(x[0] / x[2]), float(x[1] / x[2])) * size + mid
                point = (at.x, at.y, 1.0)
            else:
                point = (float(x[0]), float(x[1]), 0.0)
            used = tuple(t for t in (s1, s2) if isinstance(t, tuple))
            words = " and ".join(_line_words(t) for t in (s1, s2))
            c = Centre(q, point, f"where {words} cross (Kennedy)", used, float(s))
            place(c)
            conditions[centre_name(q)] = s
            far = c.finite and norm(c.at).norm() > FAR
            rec = rec.then(f"{centre_name(q)} lies on {words} (Kennedy's theorem: the three centres of three "
                           f"bodies are in line); they cross at {centre_name(q)}"
                           + ("" if c.finite else ", at infinity")
                           + (", off the drawing at x = $x, y = $y" if far else "") + ".",
                           *kennedy_entities(c, found, norm, mid, size),
                           values={k: Value("length", v if abs(v) > 1e-12 * size else 0.0)
                                   for k, v in (("x", c.at.x), ("y", c.at.y))} if far else None,
                           kind=StepKind.CONSTRUCTION)
            progress = True
    missing = tuple(pair(*q) for q in itertools.combinations(bodies, 2) if pair(*q) not in found)
    warnings = []
    if missing:
        warnings.append("Kennedy's theorem leaves " + ", ".join(centre_name(q) for q in missing)
                        + " undetermined at this position (their lines coincide: a change point or toggle).")
    rec = circle_diagram(rec, bodies, found, m.size, drawn_box(rec))
    angular, fields = _velocities(m, f, bodies, found, omega, pos)
    velocities = {p: _velocity(fields[b], pos[p]) for p in pos
                  for b in [_body_of(m, p, f, fields)] if b is not None}
    if angular:
        rec = rec.then("Angular velocities from the centres: the common centre I_jk has one velocity on "
                       f"both bodies, V = \u03c9_j \u00d7 (I_jk \u2212 I_{f}j) = \u03c9_k \u00d7 (I_jk \u2212 I_{f}k); "
                       + "; ".join(f"\u03c9_{k} = $w{k} {'CCW' if angular[k] > 0 else 'CW'}" for k in sorted(angular)
                                   if k != f and k != m.crank and k not in m.blocks() and angular[k] != 0)
                       + ".",
                       values={f"w{k}": Value("angular velocity", abs(w)) for k, w in angular.items()},
                       kind=StepKind.ANSWER)
    return InstantCentres(rec, f, bodies, found, missing, angular, velocities, tuple(warnings), conditions)



def _points(m: Mechanism, body: int, frame: int) -> tuple[str, ...]:
    return tuple(m.ground) if body == frame else points_of_body(m, body)


def _body(m: Mechanism, b: int) -> str:
    return f"block {b}" if b in m.blocks() else f"link {b}"


def _guide(m: Mechanism, guide: int, frame: int) -> str:
    return "guide" if guide == frame else f"slot of link {guide}"


def _line_words(source) -> str:
    if isinstance(source, tuple):
        a, b = source
        return f"the line {centre_name(a)} {centre_name(b)}"
    return str(source)


def _velocities(m: Mechanism, f: int, bodies, found, omega: float, pos):
    """Each body's velocity field (omega, reference point, its velocity), from the crank outward."""
    crank = m.link(m.crank)
    pivot = next(j for j in crank.joints if j in m.ground)
    fields: dict[int, tuple[float, Vec, Vec]] = {f: (0.0, Vec(0.0, 0.0), Vec(0.0, 0.0)),
                                                 m.crank: (omega, pos[pivot], Vec(0.0, 0.0))}
    progress = True
    while progress:
        progress = False
        for k in bodies:
            if k in fields or pair(f, k) not in found:
                continue
            fk = found[pair(f, k)]
            for j in list(fields):
                q = pair(j, k)
                if j == f or q not in found:
                    continue
                c = found[q]
                if c.finite:
                    vx = _velocity(fields[j], c.at)
                    if fk.finite:
                        r = c.at - fk.at
                        if r.norm() <= 1e-12 * m.size:
                            continue
                        fields[k] = (r.cross(vx) / r.dot(r), fk.at, Vec(0.0, 0.0))
                    else:
                        fields[k] = (0.0, c.at, vx)
                elif fk.finite:
                    fields[k] = (fields[j][0], fk.at, Vec(0.0, 0.0))
                else:
                    continue
                progress = True
                break
    return {k: w for k, (w, _, _) in fields.items()}, fields


def _velocity(fld: tuple[float, Vec, Vec], p: Vec) -> Vec:
    w, ref, v = fld
    return v + (p - ref).perp() * w


def _body_of(m: Mechanism, p: str, f: int, fields) -> int | None:
    if p in m.ground:
        return f
    for b in fields:
        if b != f and p in points_of_body(m, b):
            return b
    return None
