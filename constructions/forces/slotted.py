"""The force polygons of the dyads a slot or two lines place, drawn as the notes draw them.

- RPR (:func:`rpr`): a slotted link turned about a known point until its slot passes through a known joint
  (inverted slider-crank, slotted lever): the pin (or block) pushes square to the slot, moments about the
  slotted link's pivot give that force (force x perpendicular distance), and the link's polygon closes with
  the bearing force at the pivot.
- PRP (:func:`prp`): a joint carried along two lines by blocks (or a block and a pin in a slot): each line
  pushes square to itself; the polygon of the blocks closes on the two normals.

Each solved force's reaction is carried to the body at the other side (:meth:`.board.Drawing.record_pin`).
"""

from __future__ import annotations

import math

from ..errors import IndeterminatePosition
from ..geometry import Vec
from ..mechanisms.assembly import SlotThrough, TwoLines
from ..mechanisms.model import describe_angle, slide_line
from ..polygons.common import rounding_estimate
from ..entities import Arrow, Diagram, Dimension, Point, Role, ScaleBar, Segment, TrialLine
from ..record import StepKind, Value
from ..tolerance import NEGLIGIBLE, PARALLEL_SINE, WARN_SINE
from .bodies import force_name
from .board import (ORIGIN, Drawing, Force, ForcesNotDrawn, answer, body_label, close, contact, force_value,
                    outer_carrier, resultant)
from .friction import friction_at, slide_sign


def rpr(d: Drawing, step: SlotThrough) -> None:
    """The slotted link k turned about its known point c until its slot passes through the joint j (an RPR
    dyad: inverted slider-crank, slotted lever).  The pin at j -- or the block on it -- pushes on the slot
    square to the slot (leaning back by the friction angle against the sliding where the scene sets mu);
    its moment about c balances the other forces and couples on link k, which gives its magnitude (force x
    perpendicular distance).  Link k's polygon then closes with the bearing force at c, whichever body
    carries c.  A block on the pin takes the slot's couple (it balances the moment of the block's own
    forces about j) and closes its polygon with the pin force; every reaction goes onto the body at the
    other side."""
    m, pos = d.m, d.pos
    k, c, j, sl = step.link.number, step.centre, step.joint, step.slide
    blk = sl.number
    held = d.carry[j]                                   # the body that carries the pin j
    on = blk if blk is not None else held               # the body the slot pushes on
    by_c = outer_carrier(d, c)
    n_bear, n_on_k, n_k_on = force_name(by_c, k), force_name(on, k), force_name(k, on)
    what = f"link {k} and block {blk}" if blk is not None else f"link {k}"
    key = f"links {k}, {blk}" if blk is not None else f"link {k}"
    fb = Diagram("free-body", body_label(m, k))
    line = d.pose.lines[j]
    couple = 0.0                                        # the slot's couple on the block
    kb = d.known(blk) if blk is not None else []
    if blk is not None:
        couple = -resultant(kb, d.couples.get(blk, 0.0), pos[j])[1]
    known_k = d.known(k)
    mo = resultant(known_k, d.couples.get(k, 0.0), pos[c])[1] - couple     # the block's couple reacts on k
    u, n, s = _slot_force(d, step, what, n_on_k, mo)
    d.cond[key] = s
    if s < WARN_SINE:
        d.warnings.append(f"Near a toggle in the force polygon of {what} ({describe_angle(d.pose.angle)}): the "
                          f"line of {n_on_k} passes {math.degrees(math.asin(s)):.3g} deg from {c}; the forces are "
                          f"large and sensitive to the drawing (rounding about {rounding_estimate(s):.1e} relative).")
    f_k_on = u * n                                      # of link k on the pin (or block), at j
    arm = abs((pos[j] - pos[c]).cross(u)) / u.norm()
    foot = pos[j] + u * ((pos[c] - pos[j]).dot(u) / u.dot(u))
    ends = [line.parameter(pos[j]), line.parameter(pos[c])]
    pad = 0.15 * max(abs(ends[0] - ends[1]), 0.1 * m.size)
    lean = "" if u == line.direction.perp() else (" leaning back from the normal by the friction angle "
                                                  "\u03c6 = atan \u03bc, against the sliding")
    with_block = f" (with the slot's couple on block {blk}, $c)" if couple else ""
    d.steps.append((
        f"The {'block' if blk is not None else 'pin'} at {j} pushes on the slot of link {k} square to the slot"
        f"{lean}: {n_on_k} acts along that line through {j}.  Moments about {c} on link {k}: {n_on_k} \u00d7 h "
        f"balances the moment of the other forces and couples on link {k}{with_block}, $m (force \u00d7 "
        f"perpendicular distance), so {n_on_k} = $m / $h = $f.",
        (Segment(f"fbd {fb.name}: slot", Role.PATH, fb, line.at(min(ends) - pad), line.at(max(ends) + pad)),
         TrialLine(f"fbd {fb.name}: slot force line", Role.TRIAL, fb, pos[j], u, None),
         Dimension(f"fbd {fb.name}: h", Role.DIMENSION, fb, pos[c], foot, 0.0, "h")),
        None, {"m": Value("torque", abs(mo)), "h": Value("length", arm), "f": force_value(abs(n)),
               **({"c": Value("torque", abs(couple))} if couple else {})}, StepKind.CONSTRUCTION))
    # the polygon: link k's known forces from the pole, F_on,k, and the bearing force back to the pole; a block
    # with forces of its own continues from the tail of F_on,k (F_k,block runs back along it)
    sides: list[tuple[str, Vec, Vec, Role]] = []
    p = ORIGIN
    for x in known_k:
        sides.append((x.label, p, p + x.vector, Role.KNOWN))
        p = p + x.vector
    y, x_tip = p, p - f_k_on
    sides += [(n_on_k, y, x_tip, Role.RESULT), (n_bear, x_tip, ORIGIN, Role.RESULT)]
    f_held = None
    if blk is not None:
        n_held = force_name(held, blk)
        for x in kb:
            sides.append((x.label, p, p + x.vector, Role.KNOWN))
            p = p + x.vector
        f_held = x_tip - p                              # of the pin's carrier on the block
        sides.append((n_held, p, x_tip, Role.RESULT))
    sides, spread = _side_by_side(sides)
    dg = Diagram("force", key)
    arrows = [Arrow(f"{key}: {label} {i}", role, dg, tail, tip, label)
              for i, (label, tail, tip, role) in enumerate(sides) if role is Role.KNOWN and tail != tip]
    d.steps.append((f"Force polygon of {what}: from the pole O_f lay off the known forces of link {k} head to tail "
                    f"to the force scale, then {n_on_k} square to the slot; the bearing force {n_bear} at {c} "
                    f"closes the polygon back to O_f."
                    + (f" Block {blk}: {force_name(k, blk)} runs back along {n_on_k}; from its tail lay off the "
                       f"block's own forces; the pin force {n_held} at {j} closes its polygon." if kb else "")
                    + (" The forces are parallel, so their sides are drawn side by side." if spread else ""),
                    (Point(f"{key}: pole", Role.LABEL, dg, ORIGIN, "O_f"),
                     ScaleBar(f"{key}: scale", Role.SCALE_BAR, dg, "force", None), *arrows),
                    None, {}, StepKind.CONSTRUCTION))
    named = [(label, tail, tip) for label, tail, tip, role in sides if role is Role.RESULT]
    extra, values = "", {}
    if blk is not None and abs(couple) > NEGLIGIBLE * d.scale * m.size and n != 0.0:
        extra = f"; the slot's reaction acts $e from {j} along the slot (its moment balances the block's)"
        values = {"e": Value("length", abs(couple) / f_k_on.norm())}
    answer(d, key, named, extra, values)
    d.contacts[contact(d, j, blk, k)] = (f_k_on, couple)
    d.forces.setdefault(on, []).append(Force(n_k_on, on, pos[j], f_k_on, "guide"))
    d.forces.setdefault(k, []).append(Force(n_on_k, k, pos[j], -f_k_on, "guide"))
    if couple:
        d.couples[k] = d.couples.get(k, 0.0) - couple
    if f_held is not None:
        d.record_pin(j, held, blk, f_held)
    d.record_pin(c, by_c, k, f_k_on - sum((x.vector for x in known_k), ORIGIN))


def _slot_force(d: Drawing, step: SlotThrough, what: str, name: str, mo: float) -> tuple[Vec, float, float]:
    """The line of the slot's force on the pin (or block) at j and its size: (u, n, sine) with the force
    n u, from link k's moments about its known point c, mo + (j - c) x (-n u) = 0.  Frictionless u is the
    slot's normal; with mu it leans back against the sliding, to the side of the face the pin bears on (the
    face whose n has the matching sign; a part within rounding of zero fits either).  The sine is the arm
    over the distance from c to j: 0 where the line passes through c, and the force is indeterminate."""
    pos = d.pos
    j, c, sl = step.joint, step.centre, step.slide
    t = d.pose.lines[j].direction
    r = pos[j] - pos[c]
    mu = friction_at(d, sl)
    sign = slide_sign(d, sl, step.coincident, t) if mu else 0.0
    lines = [(t.perp(), 1.0)]
    if sign:
        # N (n - mu sign(N) sign(v) t): the face the pin bears on sets which way the reaction leans
        lines = [(t.perp() - t * (mu * sign), 1.0), (t.perp() + t * (mu * sign), -1.0)]
    best = 0.0
    for u, face in lines:
        arm = r.cross(u)
        s = abs(arm) / (r.norm() * u.norm()) if r.norm() > 0 else 0.0
        best = max(best, s)
        if s < PARALLEL_SINE:
            continue
        n = mo / arm
        if len(lines) == 1 or n * face >= -NEGLIGIBLE * d.scale:
            return u, n, s
    if best < PARALLEL_SINE:
        raise IndeterminatePosition(
            f"the force polygon of {what} cannot close: the line of action of {name} (square to the slot "
            f"through {j}) passes through {c} (sine {best:.1e}), so its moment about {c} cannot balance the other "
            f"forces and {name} is indeterminate", position=describe_angle(d.pose.angle), kind="toggle",
            condition=best)
    raise IndeterminatePosition(f"friction lock at {sl.label}: with mu the slot's reaction cannot balance link "
                                f"{sl.on} with {j} bearing on either face of the slot",
                                position=describe_angle(d.pose.angle), kind="friction lock")


SIDE_BY_SIDE = 0.08
"""The spacing of the sides of a force polygon whose forces are all parallel, as a fraction of its longest
side: drawn on one line they would hide one another."""


def _side_by_side(sides):
    """The polygon's sides as they are drawn: unchanged, or -- when every force is parallel -- each shifted
    square to their line so that no side hides another (a side that repeats an earlier one keeps its
    place).  Returns the sides and whether they were spread."""
    drawn = [x for x in sides if x[1] != x[2]]
    if len(drawn) < 3:
        return sides, False
    longest = max((tip - tail for _, tail, tip, _ in drawn), key=lambda v: v.norm())
    e = longest.unit()
    if any(abs((tip - tail).cross(e)) > PARALLEL_SINE * (tip - tail).norm() for _, tail, tip, _ in drawn):
        return sides, False
    step = e.perp() * (SIDE_BY_SIDE * longest.norm())
    out = []
    seen: dict[tuple, Vec] = {}
    i = 0
    for label, tail, tip, role in sides:
        key = (tail.as_tuple(), tip.as_tuple())
        if key not in seen and tail != tip:
            seen[key] = step * i
            i += 1
        off = seen.get(key, ORIGIN)
        out.append((label, tail + off, tip + off, role))
    return out, True


def prp(d: Drawing, step: TwoLines) -> None:
    """The joint j carried along two lines (a PRP dyad): by two blocks pinned together at j, or by a block
    whose pin also runs in a slot.  Each line pushes square to itself (a block's guide also places its
    reaction by a couple: its moment balances the moment of the block's own forces about j); the polygon of
    the blocks closes on the two normals, and the pin force between two blocks follows from either block's
    balance.  The reactions go onto the slotted links."""
    m, pos = d.m, d.pos
    j = step.joint
    slides = (step.slide_a, step.slide_b)
    for sl in slides:
        if friction_at(d, sl):
            raise ForcesNotDrawn(f"the force polygons of a joint carried along two lines (at {j}) with friction at "
                                 f"{sl.label} are not drawn: each line's reaction leans by the friction angle to a "
                                 f"face that depends on the other's")
    held = d.carry[j]                                   # a block that carries j
    bodies = [sl.number if sl.number is not None else held for sl in slides]
    guides = [d.frame if sl.on is None else sl.on for sl in slides]
    other = next((b for b in bodies if b != held), None)    # the second block, pinned to the first at j
    order = [0, 1] if bodies[1] == held else [1, 0]     # the other block's line through the pole
    f_i, l_i = order                                    # index of the first and the last closing line
    names = [force_name(g, b) for g, b in zip(guides, bodies)]
    line_words = [f"\u22a5 {'guide' if sl.on is None else f'slot of link {sl.on}'}" for sl in slides]
    key = f"blocks {', '.join(str(b) for b in sorted(set(bodies)))}"
    what = f"block{'s' if other is not None else ''} {' and '.join(str(b) for b in sorted(set(bodies)))} at {j}"
    ko = d.known(other) if other is not None else []
    kh = d.known(held)
    knowns = [(x.label, x.vector) for x in ko] + [(x.label, x.vector) for x in kh]
    normals = [slide_line(m, sl, pos).direction.perp() for sl in slides]
    c = close(d, key, what, knowns, (names[l_i], normals[l_i], line_words[l_i]),
              (names[f_i], normals[f_i], line_words[f_i]), f"Force polygon of {what}.")
    forces = [ORIGIN, ORIGIN]
    forces[l_i], forces[f_i] = c.last, c.first
    tip = c.points[-1]
    named = [(names[l_i], tip, c.crossing), (names[f_i], c.crossing, ORIGIN)]
    q = sum((x.vector for x in ko), ORIGIN)
    if other is not None:
        named.append((force_name(held, other), q, c.crossing))
    couples = {b: -resultant(d.known(b), d.couples.get(b, 0.0), pos[j])[1] for b in set(bodies)}
    extra, values = "", {}
    placed = [(b, cp) for b, cp in sorted(couples.items()) if abs(cp) > NEGLIGIBLE * d.scale * m.size]
    if placed:
        extra = "; " + "; ".join(f"the guide of block {b} places its reaction by the couple $c{b} (its moment "
                                 f"balances the block's about {j})" for b, _ in placed)
        values = {f"c{b}": Value("torque", abs(cp)) for b, cp in placed}
    answer(d, key, named, extra, values)
    for sl, body, g, f, name in zip(slides, bodies, guides, forces, names):
        cp = couples[body] if sl.number is not None else 0.0
        d.contacts[contact(d, j, sl.number, g)] = (f, cp)
        d.forces.setdefault(body, []).append(Force(name, body, pos[j], f, "guide"))
        if g != d.frame:                                # the reaction on the slotted link
            d.forces.setdefault(g, []).append(Force(force_name(body, g), g, pos[j], -f, "guide"))
            if cp:
                d.couples[g] = d.couples.get(g, 0.0) - cp
    if other is not None:
        d.record_pin(j, held, other, c.crossing - q)
