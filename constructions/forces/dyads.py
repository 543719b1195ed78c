"""The force polygons of each kind of dyad, drawn as the notes draw them, and of the crank.

- RRR (:func:`rrr`): a link with no load between its two pins is a two-force member; with one two-force
  link the other is a three-force member solved by concurrency (where its triangle closes at an angle of
  more than WARN_SINE: not when the load's line lies far off, a small force with a large couple), else
  each link's outer pin force is split into a tangential part (moments about the middle joint) and a part
  along the link, and the polygon closes on the two directions along the links.
- RRP (:func:`rrp`): a block on a guide (or a pin in a slot) and the link pinned to it: the guide pushes
  square to the guide (tilted by the friction angle against the sliding), the polygon closes along the
  link and the guide's reaction.
- RPR (:func:`rpr`): a slotted link turned about a known point until its slot passes through a known joint
  (inverted slider-crank, slotted lever): the pin (or block) pushes square to the slot, moments about the
  slotted link's pivot give that force (force x perpendicular distance), and the link's polygon closes with
  the bearing force at the pivot.
- PRP (:func:`prp`): a joint carried along two lines by blocks (or a block and a pin in a slot): each line
  pushes square to itself; the polygon of the blocks closes on the two normals.
- the crank (:func:`driving_crank`): its bearing force closes its polygon; the driving torque is the
  resultant times its perpendicular distance from the pivot.

Each solved force's reaction is carried to the body at the other side as a known force of its later
polygon (:meth:`.board.Drawing.record_pin`).
"""

from __future__ import annotations

import math

from ..errors import IndeterminatePosition
from ..geometry import Vec
from ..mechanisms.assembly import CircleAndGuide, CrankTip, SlotThrough, TwoCircles, TwoLines
from ..mechanisms.model import describe_angle, slide_line
from ..polygons.common import WARN_SINE, rounding_estimate
from ..entities import AngleMark, Arrow, Diagram, Dimension, Point, Role, ScaleBar, Segment, TrialLine
from ..record import StepKind, Value
from .bodies import force_name, torque_name
from .board import (ORIGIN, PARALLEL_SINE, Drawing, Force, ForcesNotDrawn, answer, body_label, close, contact,
                    force_value, is_loaded, meet, moment_step, outer_carrier, resultant, resultant_line,
                    two_force_words)


def rrr(d: Drawing, step: TwoCircles) -> None:
    """Links a (first-j) and b (second-j): three-force by concurrency when one is a two-force member,
    else tangential parts from the moments about j and the polygon closing along the links."""
    pos = d.pos
    a, b, j = step.link_a.number, step.link_b.number, step.joint
    first, second = step.first, step.second
    by_a, by_b = outer_carrier(d, first), outer_carrier(d, second)
    n_a, n_b, n_ab = force_name(by_a, a), force_name(by_b, b), force_name(a, b)
    what, key = f"links {a} and {b}", f"links {a}, {b}"
    la, lb = is_loaded(d, a), is_loaded(d, b)
    for body, outer, name, loaded in ((a, first, n_a, la), (b, second, n_b, lb)):
        if not loaded:
            two_force_words(d, body, outer, j, name)
    if la != lb:
        loaded, l_outer, l_name, free, f_outer = (a, first, n_a, b, second) if la else (b, second, n_b, a, first)
        line = resultant_line(d.known(loaded), d.couples.get(loaded, 0.0), pos[j])
        along = pos[j] - pos[f_outer]
        # concurrency needs a load of some size whose line crosses the two-force line; a load within rounding
        # of zero (a reaction that came out as 1e-16) has no line to speak of: moments solve it instead
        if line is not None and line[1].norm() > 1e-12 * d.scale and \
                abs(line[1].unit().cross(along.unit())) > WARN_SINE:
            at, r = line
            conc = meet(at, r, pos[j], along)
            third = conc - pos[l_outer]
            # and the triangle must close at an angle: a small load with a large couple (a flywheel's
            # inertia) has its line far away, where the third force runs nearly along the two-force line
            # -- a drafter takes moments about the joint then, as below
            if third.norm() > 1e-12 * d.m.size and abs(third.unit().cross(along.unit())) > WARN_SINE:
                fb = Diagram("free-body", body_label(d.m, loaded))
                d.steps.append((
                    f"Link {loaded} is a three-force member: the line of its load and the line of the force "
                    f"from link {free} (along {f_outer}{j}) meet at I_{loaded}, so {l_name} passes through "
                    f"{l_outer} and I_{loaded}.",
                    (TrialLine(f"fbd {body_label(d.m, loaded)}: load line", Role.TRIAL, fb, at, r, None),
                     TrialLine(f"fbd {body_label(d.m, loaded)}: two-force line", Role.TRIAL, fb, pos[j], along, None),
                     TrialLine(f"fbd {body_label(d.m, loaded)}: third line", Role.TRIAL, fb, pos[l_outer], third, None),
                     Point(f"fbd {body_label(d.m, loaded)}: I", Role.LABEL, fb, conc, f"I_{loaded}")),
                    None, {}, StepKind.CONSTRUCTION))
                n_free_on_loaded = force_name(free, loaded)
                c = close(d, key, what, [(x.label, x.vector) for x in d.known(loaded)],
                           (l_name, third, f"\u2225 {l_outer}I"),
                           (n_free_on_loaded, along, f"\u2225 {f_outer}{j}"),
                           f"Force triangle of link {loaded}.")
                f_loaded, f_on_loaded = c.last, c.first
                tip = c.points[-1]
                answer(d, key, [(l_name, tip, c.crossing), (n_free_on_loaded, c.crossing, ORIGIN)])
                if loaded == a:
                    f_a, f_ab = f_loaded, -f_on_loaded
                    f_b = -f_ab                                     # b is a two-force member
                else:
                    f_b, f_ab = f_loaded, f_on_loaded
                    f_a = f_ab
                d.record_pin(j, a, b, f_ab)
                d.record_pin(first, by_a, a, f_a)
                d.record_pin(second, by_b, b, f_b)
                return
    t_a, et_a, en_a = d.tangential(a, first, j)
    t_b, et_b, en_b = d.tangential(b, second, j)
    if t_a:
        moment_step(d, a, n_a, first, j, t_a)
    if t_b:
        moment_step(d, b, n_b, second, j, t_b)
    ka, kb = d.known(a), d.known(b)
    knowns = [(f"{n_a}\u1d57", et_a * t_a)] + [(x.label, x.vector) for x in ka] + \
             [(x.label, x.vector) for x in kb] + [(f"{n_b}\u1d57", et_b * t_b)]
    c = close(d, key, what, knowns, (f"{n_b}\u207f", en_b, f"\u2225 {second}{j}"),
               (f"{n_a}\u207f", en_a, f"\u2225 {first}{j}"), f"Force polygon of {what}.")
    p1 = et_a * t_a                                     # end of F_a^t
    q = p1 + sum((x.vector for x in ka), ORIGIN)        # end of link a's loads
    start_b = c.points[-1] - et_b * t_b                 # start of F_b^t
    f_a = p1 - c.crossing
    f_b = c.crossing - start_b
    f_ab = q - c.crossing
    answer(d, key, [(n_a, c.crossing, p1), (n_b, start_b, c.crossing), (n_ab, c.crossing, q)])
    d.record_pin(j, a, b, f_ab)
    d.record_pin(first, by_a, a, f_a)
    d.record_pin(second, by_b, b, f_b)


def rrp(d: Drawing, step: CircleAndGuide) -> None:
    """Link a (centre-j) and the block at j on a guide (or the pin j in a slot): the guide's force is
    square to the guide (tilted by the friction angle against the sliding), the pin force at the centre
    split by the moments about j; the polygon closes along the link and the guide's reaction."""
    m, pos = d.m, d.pos
    a, j, first = step.link.number, step.joint, step.centre
    sl = step.slide
    blk = sl.number
    guide = d.frame if sl.on is None else sl.on
    by_a = outer_carrier(d, first)
    n_a = force_name(by_a, a)
    body_g = blk if blk is not None else a                   # the body the guide pushes on
    n_g = force_name(guide, body_g)
    what = f"link {a} and block {blk}" if blk is not None else f"link {a} (pin {j} in the slot of link {guide})"
    key = f"links {a}, {blk}" if blk is not None else f"link {a}"
    g_dir = d.pose.lines[j].direction
    normal = g_dir.perp()
    mu = _mu(d, sl)
    slide_sign = _slide_sign(d, sl, step.coincident, g_dir) if mu else 0.0
    la = is_loaded(d, a)
    if not la:
        two_force_words(d, a, first, j, n_a)
    t_a, et_a, en_a = d.tangential(a, first, j)
    if t_a:
        moment_step(d, a, n_a, first, j, t_a)
    ka = d.known(a)
    kb = d.known(blk) if blk is not None else []
    knowns = [(f"{n_a}\u1d57", et_a * t_a)] + [(x.label, x.vector) for x in ka] + [(x.label, x.vector) for x in kb]
    direction, intro = normal, f"Force polygon of {what}."
    if mu and slide_sign:
        direction = _friction_lean(d, knowns, normal, g_dir * (mu * slide_sign), en_a, sl.label)
        intro += (" The guide's reaction leans back from the normal by the friction angle \u03c6 = atan \u03bc, "
                  "against the sliding, on the face the block bears on.")
    c = close(d, key, what, knowns, (n_g, direction, "\u22a5 guide" if direction is normal else "at \u03c6 to the normal"),
               (f"{n_a}\u207f", en_a, f"\u2225 {first}{j}"), intro)
    p1 = et_a * t_a
    q = p1 + sum((x.vector for x in ka), ORIGIN)
    n_total = c.last
    f_a = p1 - c.crossing
    named = [(n_a, c.crossing, p1), (n_g, c.points[-1], c.crossing)]
    if blk is not None:
        f_ab = q - c.crossing                 # of link a on the block, from the block's balance
        named.append((force_name(a, blk), c.crossing, q))
        # the guide's couple places its reaction: moments about j on the block
        _, mo = resultant(kb, d.couples.get(blk, 0.0), pos[j])
        couple = -mo
    else:
        couple = 0.0
    extra = ""
    values = {}
    if blk is not None and abs(couple) > 1e-12 * d.scale * m.size and n_total.norm() > 0:
        extra = f"; the guide's reaction acts $e from {j} along the guide (its moment balances the block's)"
        values = {"e": Value("length", abs(couple) / n_total.norm())}
    answer(d, key, named, extra, values)
    d.contacts[contact(d, j, blk, guide)] = (n_total, couple)
    if blk is not None:
        d.record_pin(j, a, blk, f_ab)
        d.forces.setdefault(blk, []).append(Force(n_g, blk, pos[j], n_total, "guide"))
    else:
        d.forces.setdefault(a, []).append(Force(n_g, a, pos[j], n_total, "guide"))
    if guide != d.frame:                       # the reaction on the slotted link
        d.forces.setdefault(guide, []).append(Force(force_name(body_g, guide), guide, pos[j], -n_total, "guide"))
        if couple:
            d.couples[guide] = d.couples.get(guide, 0.0) - couple
    d.record_pin(first, by_a, a, f_a)


def _mu(d: Drawing, sl) -> float:
    """The coefficient of friction at a slide: keyed by its block, or by the joint for a pin in a slot."""
    return d.effects.friction.get(sl.number if sl.number is not None else sl.joint, 0.0)


def _slide_sign(d: Drawing, sl, coincident: str, along: Vec) -> float:
    """+1 or -1 as the joint slides along ``along`` relative to its guide or slot (the slotted link's point
    ``coincident`` under it), 0 -- with a warning that friction is left out -- when it is at rest there."""
    v = d.velocity.velocities[sl.joint]
    if sl.on is not None:
        v = v - d.velocity.velocities[coincident]
    x = v.dot(along)
    tol = 1e-12 * max(w.norm() for w in d.velocity.velocities.values())
    if abs(x) <= tol:
        label = sl.label
        d.warnings.append(f"{label[:1].upper()}{label[1:]} is momentarily at rest on its "
                          f"{'guide' if sl.on is None else 'slot'}: the friction force is undetermined and left out.")
        return 0.0
    return math.copysign(1.0, x)


def _friction_lean(d: Drawing, knowns, normal: Vec, lean: Vec, along_link: Vec, label: str) -> Vec:
    """The line of the guide's total reaction N n - mu |N| sign(v) t: leaning by ``-lean`` when the block
    bears on the face the normal points from (N >= 0), by ``+lean`` on the other face.  The face is the one
    whose polygon closes with a normal part of that sign (a part within rounding of zero fits either)."""
    tip = sum((v for _, v in knowns), ORIGIN)
    floor = 1e-12 * d.scale
    for direction, face in ((normal - lean, 1.0), (normal + lean, -1.0)):
        if abs(direction.unit().cross(along_link)) < PARALLEL_SINE:
            continue
        x = meet(tip, direction, ORIGIN, along_link)
        if (x - tip).dot(normal) * face >= -floor:
            return direction
    raise IndeterminatePosition(f"friction lock at {label}: with mu the guide's reaction cannot balance "
                                f"it on either face of its guide", position=describe_angle(d.pose.angle),
                                kind="friction lock")


DEAD_CENTRE_ARM = 1e-12
"""Below this arm (relative to the scene size) the crank's resultant passes through its pivot: a dead centre,
no torque.  Rounding-level only: a larger arm is a small torque the check still expects (an arm of 1e-9 of
the scene times a bearing force larger than the loads is a torque beyond the 1e-9 agreement)."""


TORQUE_ARC = 0.35
"""The radius of the driving torque's arc on the crank's free body, as a fraction of the crank."""


def driving_crank(d: Drawing, crank: CrankTip) -> None:
    """The crank: its bearing force closes its polygon; the driving torque is the resultant of the other
    forces times its perpendicular distance from the pivot."""
    m, pos = d.m, d.pos
    n, o = crank.link.number, crank.pivot
    name_o = force_name(d.frame, n)
    t_name = torque_name(m)
    known = d.known(n)
    cpl = d.couples.get(n, 0.0)
    r, mo = resultant(known, cpl, pos[o])
    torque = -mo
    key = f"link {n}"
    fb = Diagram("free-body", body_label(m, n))
    if len(known) >= 2:
        dg = Diagram("force", key)
        pts = [ORIGIN]
        arrows = []
        for i, x in enumerate(known):
            arrows.append(Arrow(f"{key}: {x.label} {i}", Role.KNOWN, dg, pts[-1], pts[-1] + x.vector, x.label))
            pts.append(pts[-1] + x.vector)
        d.steps.append((f"Force polygon of the crank, link {n}: lay off its known forces from O_f; the bearing "
                        f"force {name_o} closes it.",
                        (Point(f"{key}: pole", Role.LABEL, dg, ORIGIN, "O_f"),
                         ScaleBar(f"{key}: scale", Role.SCALE_BAR, dg, "force", None), *arrows,
                         Arrow(f"{key}: result {name_o}", Role.RESULT, dg, pts[-1], ORIGIN, name_o)),
                        None, {"f": force_value(r.norm())}, StepKind.ANSWER))
    else:
        d.steps.append((f"The crank, link {n}, carries {known[0].label if known else 'no force'} and the bearing "
                        f"force: {name_o} = \u2212({known[0].label if known else '0'}) = $f."
                        if len(known) == 1 else f"The crank carries no force: {name_o} = 0.",
                        (), None, {"f": force_value(r.norm())}, StepKind.ANSWER))
    h = abs(mo - cpl) / r.norm() if r.norm() > 0 else 0.0
    ents = []
    if r.dot(r) > 0 and h > 1e-9 * m.size:               # (a subnormal force squares to 0)
        line_pt = pos[o] + r.perp() * (-(mo - cpl) / r.dot(r))          # foot of the perpendicular from O
        ents.append(TrialLine(f"fbd {body_label(m, n)}: resultant line", Role.TRIAL, fb, line_pt, r, None))
        ents.append(Dimension(f"fbd {body_label(m, n)}: h", Role.DIMENSION, fb, pos[o], line_pt, 0.0, "h"))
    sense = "CCW" if torque > 0 else "CW" if torque < 0 else ""
    if r.norm() > 0 and h <= DEAD_CENTRE_ARM * m.size and cpl == 0.0:
        arm = pos[crank.tip] - pos[o]
        along = abs(arm.cross(r)) <= 1e-9 * arm.norm() * r.norm()
        words = (f"The resultant force on the crank passes through {o}"
                 + (" along the crank (a dead centre)" if along else "")
                 + f": h = 0, so no torque is needed to hold it: {t_name} = 0.")
        torque = 0.0
        vals = {}
    else:
        words = (f"Driving torque: {t_name} = resultant \u00d7 perpendicular distance h from {o}"
                 + (" (with the couples on the crank)" if cpl else "")
                 + f" = $r \u00d7 $h = $t {sense}.")
        vals = {"r": force_value(r.norm()), "h": Value("length", h), "t": Value("torque", abs(torque))}
        arm = pos[crank.tip] - pos[o]
        if torque and arm.norm() > 0:
            # on the crank's free body, an arc about its pivot turning the torque's way, open around the crank
            a = math.atan2(arm.y, arm.x)
            start = a + math.copysign(math.pi / 4, torque)
            ents.append(AngleMark(f"fbd {body_label(m, n)}: {t_name}", Role.RESULT, fb, pos[o],
                                  TORQUE_ARC * arm.norm(), start, start + math.copysign(1.5 * math.pi, torque),
                                  t_name))
    d.steps.append((words, tuple(ents), None, vals, StepKind.ANSWER))
    d.torque = torque
    d.record_pin(o, d.frame, n, -r)


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
    if blk is not None and abs(couple) > 1e-12 * d.scale * m.size and n != 0.0:
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
    mu = _mu(d, sl)
    sign = _slide_sign(d, sl, step.coincident, t) if mu else 0.0
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
        if len(lines) == 1 or n * face >= -1e-12 * d.scale:
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
    if any(abs((tip - tail).cross(e)) > 1e-9 * (tip - tail).norm() for _, tail, tip, _ in drawn):
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
        if _mu(d, sl):
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
    placed = [(b, cp) for b, cp in sorted(couples.items()) if abs(cp) > 1e-12 * d.scale * m.size]
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
