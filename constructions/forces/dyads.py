"""The force polygons of the dyads of two pinned links, drawn as the notes draw them.

- RRR (:func:`rrr`): a link with no load between its two pins is a two-force member; with one two-force
  link the other is a three-force member solved by concurrency (where its triangle closes at an angle of
  more than WARN_SINE: not when the load's line lies far off, a small force with a large couple), else
  each link's outer pin force is split into a tangential part (moments about the middle joint) and a part
  along the link, and the polygon closes on the two directions along the links.
- RRP (:func:`rrp`): a block on a guide (or a pin in a slot) and the link pinned to it: the guide pushes
  square to the guide (tilted by the friction angle against the sliding), the polygon closes along the
  link and the guide's reaction.

The dyads a slot or two lines place (RPR, PRP) are in :mod:`.slotted`, the crank in :mod:`.crank`.  Each
solved force's reaction is carried to the body at the other side as a known force of its later polygon
(:meth:`.board.Drawing.record_pin`).
"""

from __future__ import annotations

from ..mechanisms.assembly import CircleAndGuide, TwoCircles
from ..entities import Diagram, Point, Role, TrialLine
from ..record import StepKind, Value
from ..tolerance import NEGLIGIBLE, WARN_SINE
from .bodies import force_name
from .board import (ORIGIN, Drawing, Force, answer, body_label, close, contact, is_loaded, meet, moment_step,
                    outer_carrier, resultant, resultant_line, two_force_words)
from .friction import friction_at, friction_lean, slide_sign


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
        if line is not None and line[1].norm() > NEGLIGIBLE * d.scale and \
                abs(line[1].unit().cross(along.unit())) > WARN_SINE:
            at, r = line
            conc = meet(at, r, pos[j], along)
            third = conc - pos[l_outer]
            # and the triangle must close at an angle: a small load with a large couple (a flywheel's
            # inertia) has its line far away, where the third force runs nearly along the two-force line
            # -- a drafter takes moments about the joint then, as below
            if third.norm() > NEGLIGIBLE * d.m.size and abs(third.unit().cross(along.unit())) > WARN_SINE:
                fb = Diagram("free-body", body_label(d.m, loaded))
                d.steps.append((
                    f"Link {loaded} is a three-force member: the line of its load and the line of the force "
                    f"from link {free} (along {f_outer}{j}) meet at one point, I (link {loaded}), so {l_name} passes "
                    f"through {l_outer} and I.",
                    (TrialLine(f"fbd {body_label(d.m, loaded)}: load line", Role.TRIAL, fb, at, r, None),
                     TrialLine(f"fbd {body_label(d.m, loaded)}: two-force line", Role.TRIAL, fb, pos[j], along, None),
                     TrialLine(f"fbd {body_label(d.m, loaded)}: third line", Role.TRIAL, fb, pos[l_outer], third, None),
                     Point(f"fbd {body_label(d.m, loaded)}: I", Role.LABEL, fb, conc, f"I (link {loaded})")),
                    None, {}, StepKind.CONSTRUCTION))
                n_free_on_loaded = force_name(free, loaded)
                c = close(d, key, what, [(x.label, x.vector) for x in d.known(loaded)],
                           (l_name, third, f"\u2225 {l_outer}I (link {loaded})"),
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
    mu = friction_at(d, sl)
    sliding = slide_sign(d, sl, step.coincident, g_dir) if mu else 0.0
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
    if mu and sliding:
        direction = friction_lean(d, knowns, normal, g_dir * (mu * sliding), en_a, sl.label)
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
    if blk is not None and abs(couple) > NEGLIGIBLE * d.scale * m.size and n_total.norm() > 0:
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
