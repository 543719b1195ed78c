"""The crank's free body and force polygon: its bearing force closes the polygon of the forces the dyads
handed it, and the driving torque is their resultant times its perpendicular distance from the pivot
(none at a dead centre, where that line passes through the pivot).
"""

from __future__ import annotations


from ..mechanisms.assembly import CrankTip
from ..entities import Arrow, Diagram, Dimension, Point, Role, ScaleBar, TrialLine
from ..record import StepKind, Value
from ..tolerance import DEAD_CENTRE_ARM, DEAD_CENTRE_SINE, DECISION
from .bodies import force_name, torque_name
from .board import ORIGIN, Drawing, body_label, force_value, resultant


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
    if r.dot(r) > 0 and h > DECISION * m.size:               # (a subnormal force squares to 0)
        line_pt = pos[o] + r.perp() * (-(mo - cpl) / r.dot(r))          # foot of the perpendicular from O
        ents.append(TrialLine(f"fbd {body_label(m, n)}: resultant line", Role.TRIAL, fb, line_pt, r, None))
        ents.append(Dimension(f"fbd {body_label(m, n)}: h", Role.DIMENSION, fb, pos[o], line_pt, 0.0, "h"))
    sense = "CCW" if torque > 0 else "CW" if torque < 0 else ""
    if r.norm() > 0 and h <= DEAD_CENTRE_ARM * m.size and cpl == 0.0:
        arm = pos[crank.tip] - pos[o]
        along = abs(arm.cross(r)) <= DEAD_CENTRE_SINE * arm.norm() * r.norm()
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
    d.steps.append((words, tuple(ents), None, vals, StepKind.ANSWER))
    d.torque = torque
    d.record_pin(o, d.frame, n, -r)
