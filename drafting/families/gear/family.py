"""The gear families: a pair in mesh ("gear pair": contact geometry drawn as the notes draw it, checked
against the closed forms of :mod:`constructions.gears.mesh_check`) and a gear train ("gear train": speeds
by the tabular method and the notes' formula, torques and tooth loads, checked against the pitch-point
velocity-matching and equilibrium systems of :mod:`constructions.gears.train_check`).  Registered in
:mod:`drafting.families.registry`; their scene sections are read by :mod:`drafting.families.gear.scene`."""

from __future__ import annotations

import math
from typing import Any

from constructions.gears.action import action
from constructions.gears.interference import (max_gear_for_pinion, min_equal_gears, min_pinion_with_gear,
                                              min_pinion_with_rack)
from constructions.gears.contact import AT_LIMIT, INTERFERENCE
from constructions.gears.mesh import mesh_analysis
from constructions.gears.planets import check_planets
from constructions.gears.mesh_check import closed_form, notes_contact_ratio
from constructions.gears.train_check import torque_check, velocity_check
from constructions.gears.train_drawing import train_analysis

from ..glue import construction_of, measured_of, model_if_asked
from ..registry import Analysis, Family
from .scene import (PAIR_SECTIONS, PAIR_TABLES, TRAIN_SECTIONS, TRAIN_TABLES, GearPairScene, GearTrainScene,
                    cases_check, pair_check, read_gear_pair, read_gear_train)

PAIR_MODEL = "closed forms of the contact geometry (tangent lengths to the base circles)"
TRAIN_MODEL = "pitch-point velocity matching and member equilibrium (linear systems)"


# -- gear pair -------------------------------------------------------------------------------------------

def _contact(study):
    return mesh_analysis(study.scene.pair, speed=study.scene.speed)


def _closed(study):
    return closed_form(study.scene.pair)


def _closed_action(study):
    cf = closed_form(study.scene.pair)
    return action(study.scene.pair, cf.approach, cf.recess, cf.working_pressure_angle, study.scene.speed)


def _pair_analytic(study):
    if not study.asked("contact"):
        return None
    return closed_form(study.scene.pair).values() | _closed_action(study).values()


def _pair_limits(pair) -> dict[str, Any]:
    s = pair.pinion.system
    phi, k = s.pressure_angle, s.addendum
    out: dict[str, Any] = {"pinion_with_rack": min_pinion_with_rack(phi, k), "equal_gears": min_equal_gears(phi, k),
                           "max_gear_for_pinion": max_gear_for_pinion(pair.pinion.teeth, phi, k)}
    if not pair.rack and not pair.internal:
        out["pinion_with_this_gear"] = min_pinion_with_gear(pair.gear.teeth, phi, k)
    return out


def _pair_notes(study) -> tuple[str, ...]:
    a = study.result("contact")
    if a is None:
        return ()
    pair, g = study.scene.pair, a.geometry
    cf = closed_form(pair)
    u = study.scene.units
    out = [f"Contact ratio {g.contact_ratio:.4f} drawn (AB / p_b = {u.format('length', g.path)} / "
           f"{u.format('length', g.base_pitch)}); {cf.contact_ratio:.4f} by the closed form "
           f"(relative difference {abs(g.contact_ratio - cf.contact_ratio) / cf.contact_ratio:.1e})."]
    if pair.centre_distance is None and not pair.rack and not pair.internal:
        s = pair.pinion.system
        n = notes_contact_ratio(pair.pinion.pitch_radius, pair.gear.pitch_radius, s.a, s.a, s.pressure_angle,
                                s.base_pitch)
        out.append(f"The notes' contact-ratio formula gives {n:.4f} (standard centre distance).")
    if g.verdict != INTERFERENCE:           # (interference is a warning of its own, saying where contact leaves)
        verdict = {"clear": "no interference", AT_LIMIT: "at the limit of interference (contact starts exactly at "
                   "an interference point): no interference"}[g.verdict]
        out.append(f"Interference: {verdict}.")
    lim = _pair_limits(pair)
    phi_deg = math.degrees(pair.pinion.system.pressure_angle)
    words = (("External gears: least" if pair.internal else "Least") + f" pinion free of interference at {phi_deg:g}\u00b0, addendum {pair.pinion.system.addendum:g} module: "
             f"{lim['pinion_with_rack']} teeth with a rack, {lim['equal_gears']} with an equal gear")
    if "pinion_with_this_gear" in lim:
        words += f", {lim['pinion_with_this_gear']} with this {pair.gear.teeth}-tooth gear"
    mg = lim["max_gear_for_pinion"]
    words += ("; this pinion takes any gear or a rack." if mg is None else
              f"; this {pair.pinion.teeth}-tooth pinion takes gears up to {mg} teeth." if mg else
              f"; this {pair.pinion.teeth}-tooth pinion interferes even with an equal gear.")
    out.append(words)
    return tuple(out)


def _pair_json(study) -> dict[str, Any]:
    pair = study.scene.pair
    u = study.scene.units
    L = lambda x: u.convert("length", x)  # noqa: E731

    def gear(g):
        s = g.system
        return {"teeth": g.teeth, "pitch_radius": L(g.pitch_radius), "base_radius": L(g.base_radius),
                "addendum_radius": L(g.addendum_radius), "dedendum_radius": L(g.dedendum_radius),
                "circular_pitch": L(s.circular_pitch), "base_pitch": L(g.base_pitch),
                "tooth_thickness": L(g.thickness_at(g.pitch_radius))}
    s = pair.pinion.system
    out: dict[str, Any] = {"teeth_system": {"module": L(s.module), "pressure_angle_deg": math.degrees(s.pressure_angle),
                                            "addendum": s.addendum, "dedendum": s.dedendum},
                           "gears": {"1": gear(pair.pinion)} | ({} if pair.rack else {"2": gear(pair.gear)}),
                           "rack": pair.rack, "internal": pair.internal, "centre_distance": L(pair.distance),
                           "interference_limits": _pair_limits(pair)}
    a = study.result("contact")
    if a is not None:
        g, cf = a.geometry, closed_form(pair)
        out["contact"] = {"approach": L(g.approach), "recess": L(g.recess), "path": L(g.path),
                          "base_pitch": L(g.base_pitch), "working_pressure_angle_deg": math.degrees(g.working_pressure_angle),
                          "contact_ratio": {"drawn": g.contact_ratio, "closed_form": cf.contact_ratio},
                          "interference": {"start": g.start, "end": g.end, "verdict": g.verdict},
                          "points": {n: [L(p.x), L(p.y)] for n, p in g.points.items()}}
        out["action"] = _action_json(study, a.action, _closed_action(study))
    return out


def _action_json(study, drawn, closed) -> dict[str, Any]:
    """The angles of action per gear and, with the pinion's speed, the pitch-line speed and the sliding
    velocity at the start (A) and end (B) of contact: drawn and by the closed form."""
    u = study.scene.units
    out: dict[str, Any] = {}
    for key, attr in (("angle_of_action_deg", "angle_of_action"), ("approach_angle_deg", "approach_angle"),
                      ("recess_angle_deg", "recess_angle")):
        out[key] = {g: {"drawn": math.degrees(d), "closed_form": math.degrees(c)}
                    for g, d, c in zip(("1", "2"), getattr(drawn, attr), getattr(closed, attr)) if d is not None}
    if drawn.omega is not None:
        out["speed"] = {"1": u.convert("angular velocity", drawn.omega[0]),
                        "2": u.convert("angular velocity", drawn.omega[1])}
        for key, attr in (("pitch_line_speed", "pitch_line_speed"), ("sliding_velocity_start", "sliding_start"),
                          ("sliding_velocity_end", "sliding_end")):
            out[key] = {"drawn": u.convert("velocity", getattr(drawn, attr)),
                        "closed_form": u.convert("velocity", getattr(closed, attr))}
    return out


GEAR_PAIR = Family(
    kind="gear pair",
    analyses={"meshes": Analysis("meshes", (), pair_check, label="contact geometry"),   # recorded with contact
              "contact": Analysis("contact", ("meshes",), _contact, label="contact geometry"),
              "closed forms": Analysis("closed forms", (), _closed, label="closed forms")},
    askable=("contact",),
    measured=measured_of("contact"),
    analytic=_pair_analytic,
    construction=construction_of("contact"),
    json=_pair_json,
    warnings=lambda study: study.result("contact").warnings if study.result("contact") is not None else (),
    model_name=model_if_asked("contact", PAIR_MODEL),
    notes=_pair_notes,
    scene_type=GearPairScene,
    sections=PAIR_SECTIONS, keys=PAIR_TABLES,
    read=read_gear_pair,
    checks=("meshes",),
    default_analyses=("contact",),
)


# -- gear train ------------------------------------------------------------------------------------------

def _rate(study):
    return lambda w: study.scene.units.format("angular velocity", w)


def _speeds(study):
    train, cases = study.scene.train, study.scene.cases
    return train_analysis(train, cases)


def _train_check(study):
    train, cases = study.scene.train, study.scene.cases
    out = []
    for c in cases:
        speeds, rank, res = velocity_check(train, c.givens)
        row: dict[str, Any] = {"speeds": speeds, "rank": rank, "residual": res}
        if c.power is not None:
            held = tuple(g.member for g in c.givens if g.speed == 0.0)
            row["loads"], row["torques"] = torque_check(train, speeds, c.power, c.inp, c.out, held)
        out.append(row)
    return out


def _train_analytic(study):
    if not study.asked("speeds"):
        return None
    a = study.get("speeds")
    chk = study.get("check")
    out: dict[str, float] = {}
    for case, row in zip(a.cases, chk):
        for m, w in row["speeds"].items():
            out[a.quantity(f"omega_{m}", case)] = w
        for m, t in row.get("torques", {}).items():
            out[a.quantity(f"T_{m}", case)] = t
        for mesh, w in row.get("loads", {}).items():
            out[a.quantity(a.load_name(mesh), case)] = w
    return out


def _train_scales(study) -> dict[str, float]:
    train, cases = study.scene.train, study.scene.cases
    return {"angular velocity": max(abs(g.speed) for c in cases for g in c.givens)}


def _train_notes(study) -> tuple[str, ...]:
    a = study.result("speeds")
    if a is None:
        return ()
    train = a.train
    out = []
    if train.coaxial:
        out.append("Reverted: the coaxial shafts' stages have equal sums of pitch radii (r1 + r2 = r3 + r4), checked "
                   "on the layout.")
    if train.planetary:
        out.append(f"Planetary train, carrier {train.carrier}; speeds by the tabular method and the notes' formula, "
                   f"checked by velocity matching at every pitch point.")
    chk = study.get("check")
    for case, row in zip(a.cases, chk):
        if row["rank"] < len(train.members):
            out.append(f"{case.name}: the velocity-matching system has rank {row['rank']} for {len(train.members)} "
                       f"members (not determined).")
    return tuple(out)


def _train_json(study) -> dict[str, Any]:
    train, cases = study.scene.train, study.scene.cases
    u = study.scene.units
    out: dict[str, Any] = {"gears": {g.name: {"teeth": g.teeth, "shaft": g.member, "carrier": g.carrier,
                                              "internal": g.internal,
                                              "pitch_radius": u.convert("length", train.radius(g))} for g in train.gears},
                           "meshes": [m.name for m in train.meshes], "planetary": train.planetary}
    pc = check_planets(train) if train.planets > 1 else None
    if pc is not None:
        out["planets"] = {"count": pc.planets, "assembly_value": pc.assembly_value, "assembles": pc.assembles,
                          "centre_spacing": u.convert("length", pc.centre_spacing),
                          "tip_diameter": u.convert("length", pc.tip_diameter), "clear": pc.clear,
                          "tooth_loads": "per planet (equal sharing)"}
    a = study.result("speeds")
    if a is not None:
        rows = []
        chk = study.get("check")
        for case, sol, row in zip(a.cases, a.solutions, chk):
            r: dict[str, Any] = {"name": case.name,
                                 "speeds": {m: u.rate_json(w, "angular velocity") for m, w in sol.speeds.items()},
                                 "relative_values": sol.values,
                                 "check": {"rank": row["rank"], "residual": row["residual"]}}
            if sol.torques is not None:
                r["power_W"] = case.power
                r["torques"] = {m: u.rate_json(t, "torque") for m, t in sol.torques.items()}
                r["tooth_loads"] = {m: {"tangential": u.convert("force", w),
                                        "radial": u.convert("force", w * math.tan(train.pressure_angle)),
                                        "total": u.convert("force", w / math.cos(train.pressure_angle))}
                                    for m, w in (sol.loads or {}).items()}
            rows.append(r)
        out["cases"] = rows
    return out


GEAR_TRAIN = Family(
    kind="gear train",
    analyses={"cases": Analysis("cases", (), cases_check, label="tabular method"),      # recorded with speeds
              "speeds": Analysis("speeds", ("cases",), _speeds, label="tabular method"),
              "check": Analysis("check", ("cases",), _train_check, label="velocity-matching system")},
    askable=("speeds",),
    measured=measured_of("speeds"),
    analytic=_train_analytic,
    construction=construction_of("speeds"),
    json=_train_json,
    warnings=lambda study: (),
    model_name=model_if_asked("speeds", TRAIN_MODEL),
    scales=_train_scales,
    notes=_train_notes,
    scene_type=GearTrainScene,
    sections=TRAIN_SECTIONS, keys=TRAIN_TABLES,
    read=read_gear_train,
    checks=("cases",),
    default_analyses=("speeds",),
)
