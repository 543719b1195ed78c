"""What a linkage lab's problem sheet states in words (:attr:`drafting.families.registry.Family.given`):
the links, pivots, points, guides, the crank's motion, the loads, masses, springs, gravity and friction,
in the scene's units."""

from __future__ import annotations


from ...scene.unitset import direction_deg

_ORDINAL = {1: "first", 2: "second", 3: "third", 4: "fourth"}


def _sense(w: float) -> str:
    return "counter-clockwise" if w > 0 else "clockwise" if w < 0 else ""


def given_lines(study) -> list[str]:
    """The problem's data, one sentence a line."""
    s = study.scene
    u = s.units
    out: list[str] = []
    m = s.mechanism
    f = lambda kind, v: u.format(kind, v)                      # noqa: E731
    out.append("Links: " + ", ".join(f"{''.join(k.joints)} = {f('length', k.length)}"
                                     for k in sorted(m.links, key=lambda k: k.number)) + ".")
    out.append("Fixed pivots: " + ", ".join(
        f"{n} at ({u.convert('length', p.x):.6g}, {u.convert('length', p.y):.6g}) {u.symbol('length')}"
        for n, p in sorted(m.ground.items())) + ".")
    for a in m.attached:
        if a.name.startswith("G") and any(ms.centre == a.name for ms in s.effects.masses):
            continue
        link = m.link(a.link)
        out.append(f"Point {a.name} of link {a.link}: {f('length', a.distance)} from {a.base}, "
                   f"{f('angle', a.angle)} from {a.base}{link.other(a.base)}.")
    for sl in m.slides:
        block = f"block {sl.number} at {sl.joint}" if sl.number is not None else f"pin {sl.joint}"
        if sl.on is None:
            out.append(f"The {block} slides on a guide through ({u.convert('length', sl.through.x):.6g}, "
                       f"{u.convert('length', sl.through.y):.6g}) {u.symbol('length')} at "
                       f"{f('angle', sl.angle)}.")
        else:
            out.append(f"The {block} slides in a slot of link {sl.on}.")
    crank = m.link(m.crank)
    motion = [f"Crank {''.join(crank.joints)} (link {crank.number}) at {f('angle', s.angle)}"]
    inv = getattr(s, "inverse", None)
    if inv is not None:
        from constructions.mechanisms.inverse_position import describe_target
        motion = [f"Crank {''.join(crank.joints)} (link {crank.number}) turned to put "
                  f"{describe_target(inv.target, s.units.format, inv.along)}"
                  + (f" (the {_ORDINAL.get(s.solution, f'{s.solution}th')} crank angle from 0\u00b0 "
                     f"counter-clockwise)" if len(inv.solutions) > 1 else "")]
    dc = getattr(s, "driven", None)
    if dc is not None:                  # a driving slider: the crank's rates are answers, not data
        motion.append(f"block {dc.block} driven at {f('velocity', dc.speed)}"
                      + (f" and {f('acceleration', dc.acceleration)}" if "acceleration" in study.needed else "")
                      + f" along {inv.along} (positive {'out along the slot' if 'slot' in inv.along else 'along the guide'})")
    elif s.omega:
        motion.append(f"\u03c9_{crank.number} = {f('angular velocity', abs(s.omega))} {_sense(s.omega)}")
    else:
        motion.append("at rest")
    if dc is None and any(a in study.needed for a in ("acceleration", "forces")):
        if s.torque is not None:
            motion.append(f"driven by a torque of {f('torque', abs(s.torque))} {_sense(s.torque)}".rstrip())
        else:
            motion.append(f"\u03b1_{crank.number} = {f('angular acceleration', abs(s.alpha))} "
                          f"{_sense(s.alpha)}".rstrip())
    out.append(", ".join(motion) + ".")
    e = s.effects
    for ld in e.loads:
        out.append(f"Load {ld.name}: {f('force', ld.force.norm())} at {direction_deg(ld.force):.1f}\u00b0 on "
                   f"{ld.at} of body {ld.body}.")
    for cp in e.couples:
        out.append(f"Couple {cp.name}: {f('torque', abs(cp.torque))} {_sense(cp.torque)} on body {cp.body}.")
    for ms in e.masses:
        out.append(f"Body {ms.body}: mass {f('mass', ms.mass)}, centre of gravity {ms.centre}"
                   + (f", I_G = {f('moment of inertia', ms.inertia)}" if ms.inertia else "") + ".")
    for sp in e.springs:
        out.append(f"Spring {sp.name}: stiffness {f('stiffness', sp.stiffness)}, free length "
                   f"{f('length', sp.free_length)}.")
    if e.gravity is not None:
        out.append(f"Gravity g = {f('acceleration', e.gravity.norm())} at {direction_deg(e.gravity):.1f}\u00b0.")
    for body, mu in sorted(e.friction.items(), key=lambda t: str(t[0])):
        out.append(f"Friction at {body}: \u03bc = {mu:g}.")
    return out
