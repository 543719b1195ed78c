"""What a linkage study writes about its forces: the joint forces, the driving torque named as the torque the
frame (the motor) must apply to the crank and whether it drives or brakes, the inertia forces and couples,
the friction forces -- as JSON in the scene's units, and the sentence of the notes on the driving torque."""

from __future__ import annotations

from typing import Any

from constructions.forces.bodies import force_name, torque_name
from constructions.forces.dalembert import friction_name, inertia_name
from constructions.mechanisms.topology import frame_number

from ...scene.units import format_value


def driver_name(m) -> str:
    """T_12: the torque of the frame (link 1, the motor) on the crank (link 2), named as F_12 is."""
    return "T" + force_name(frame_number(m), m.crank)[1:]


def power_role(torque: float, omega: float) -> str:
    """"drives" when the torque turns with the crank (T omega > 0: the motor puts power in), "brakes" when
    against it (the motor absorbs power: the loads drive the crank, as on a power stroke), "holds" when
    the crank is at rest or no torque is needed."""
    p = torque * omega
    return "drives" if p > 0 else "brakes" if p < 0 else "holds"


def _power(p: float) -> str:
    return format_value(p, "power", "kW" if abs(p) >= 1000 else "W")


def driving_torque_words(study) -> str:
    """The driving torque in words: who applies it to which link, its sense, its power and whether the
    motor drives or brakes."""
    s, f = study.scene, study.result("forces")
    m, u = s.mechanism, s.units
    t, w, n = f.torque, s.omega, m.crank
    sense = "CCW" if t > 0 else "CW"
    head = (f"{torque_name(m)} is {driver_name(m)}, the torque the frame (the motor) must apply to link {n}: "
            f"{u.format('torque', abs(t))} {sense}")
    if t == 0:
        return f"{torque_name(m)} = 0: link {n} needs no torque from the frame (the motor) here."
    if w == 0:
        return head + f"; the crank is at rest, so it holds the mechanism and does no work."
    rot = "CCW" if w > 0 else "CW"
    if power_role(t, w) == "drives":
        return head + (f", with \u03c9_{n} {rot}: its power T\u03c9 = {_power(t * w)} is positive, so the motor "
                       f"drives the mechanism.")
    return head + (f", against \u03c9_{n} {rot}: its power T\u03c9 = \u2212{_power(-t * w)} is negative, so the motor "
                   f"brakes: it absorbs the power with which the loads drive the crank.")


def driving_torque_note(study) -> str:
    """The notes' one line on the driving torque: who applies it, and whether the motor drives or brakes."""
    s, f = study.scene, study.result("forces")
    m, t, w = s.mechanism, f.torque, s.omega
    head = f"{torque_name(m)} is {driver_name(m)}, the torque of the frame (the motor) on link {m.crank}"
    role = power_role(t, w)
    if role == "holds":
        return head + ": it does no work here."
    return head + (f"; T\u03c9 = {_power(t * w)} > 0: the motor drives." if role == "drives" else
                   f"; T\u03c9 = \u2212{_power(-t * w)} < 0: the motor brakes.")


def forces_json(study) -> dict[str, Any]:
    """The force analysis as JSON: joint forces, the driving torque with its driver and power, the inertia
    force, couple and offset of every body with mass, and the friction force at every slide with mu."""
    s, f = study.scene, study.result("forces")
    m, u = s.mechanism, s.units
    rows = {x.name: x.value for x in f.measured(m)}
    extra = {inertia_name(il.body) for il in f.inertia} | {friction_name(c) for c in f.friction}
    t = f.torque
    out: dict[str, Any] = {
        "dynamic": f.inertial,
        "forces": {k: u.vector_json(v, "force") for k, v in rows.items()
                   if not isinstance(v, float) and k not in extra},
        "driving_torque": {torque_name(m): {
            **u.rate_json(t, "torque"), "name": driver_name(m),
            "meaning": f"the torque the frame (the motor) must apply to link {m.crank}",
            "power_W": t * s.omega, "motor": power_role(t, s.omega), "words": driving_torque_words(study)}}}
    b = s.effects.balance
    if b is not None:
        found = next(ld for ld in s.effects.loads if ld.name == b.load)
        out["found_load"] = {b.load: {**u.vector_json(found.force * study.get("load for torque"), "force"),
                                      "magnitude_by_virtual_work": u.convert("force", study.get("load check")),
                                      "for_torque": u.rate_json(b.torque, "torque")}}
    if f.inertia:
        out["inertia"] = {
            inertia_name(il.body): {
                "link": il.body, "centre_of_gravity": il.centre, "mass": u.convert("mass", il.mass),
                "a_G": u.vector_json(il.force * (-1.0 / il.mass), "acceleration"),
                "force": u.vector_json(il.force, "force"),
                "couple": u.rate_json(il.couple + 0.0, "torque") if il.turns else None,
                "offset": u.convert("length", il.offset) if il.turns and il.acting else None}
            for il in f.inertia}
    if f.friction:
        mu = s.effects.friction
        out["friction"] = {
            friction_name(c): {**u.vector_json(v, "force"),
                               "mu": mu.get(c.slide.number if c.slide.number is not None else c.joint),
                               "part_of": friction_name(c)[:-2]}
            for c, v in f.friction.items()}
    return out
