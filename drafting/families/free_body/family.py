"""The free-body family: one rigid body held by supports (two-force members, pins, rollers, guides) under
known loads -- the support forces found graphically by Culmann's method or three-force concurrency
(:mod:`constructions.forces.free_body`) and checked against the body's three equations of equilibrium
solved as a linear system (:mod:`constructions.forces.free_body_check`).  Registered in
:mod:`drafting.families.registry`; its scene sections are read by :mod:`drafting.families.free_body.scene`."""

from __future__ import annotations

from typing import Any

from constructions.forces.free_body import free_body_analysis
from constructions.forces.rigid_body import MEMBER, PIN, ROLLER
from constructions.forces.free_body_check import equilibrium_solution
from constructions.record import Construction

from ..glue import measured_of, model_if_asked, scales_of
from ..registry import Analysis, Family
from .scene import SECTIONS, TABLES, FreeBodyScene, read_free_body

MODEL = "equilibrium of the body (3 x 3 linear system)"


def _forces(study):
    s = study.scene
    return free_body_analysis(s.body, fmt=s.units.format)


def _equilibrium(study):
    return equilibrium_solution(study.scene.body)


def _analytic(study):
    if not study.asked("forces"):
        return None
    return dict(study.get("equilibrium").forces)


def _construction(study) -> Construction:
    return study.get("forces").construction


def _state(body, name: str, t: float) -> str:
    s = next(x for x in body.supports if x.name == name)
    if s.kind == MEMBER:
        return "compression" if t > 0 else "tension" if t < 0 else "unloaded"
    if s.kind == ROLLER:
        return "pushes" if t > 0 else "would pull (lifts off)" if t < 0 else "unloaded"
    return "along the normal" if t > 0 else "against the normal" if t < 0 else "unloaded"


def _notes(study) -> tuple[str, ...]:
    f = study.result("forces")
    if f is None:
        return ()
    b, u = study.scene.body, study.scene.units
    out = []
    for s in b.supports:
        if s.kind != MEMBER:
            continue
        t = f.axial(s.name)
        what = s.what[:1].upper() + s.what[1:]
        where = f"{s.end}{s.at}, " if s.label else ""          # an unlabelled member is named by its ends
        out.append(f"{what} ({where}{s.name}): {u.format('force', abs(t))} {_state(b, s.name, t)}.")
    method = {"Culmann": "Culmann's method", "three-force concurrency": "three-force concurrency",
              "moments": "moments", "no load": "no load"}[f.method]
    out.append(f"Solved by {method}; checked against the body's three equations of equilibrium.")
    return tuple(out)


def _warnings(study) -> tuple[str, ...]:
    f = study.result("forces")
    return f.warnings if f is not None else ()


def _json(study) -> dict[str, Any]:
    s, u = study.scene, study.scene.units
    b = s.body
    pt = lambda p: [u.convert("length", p.x), u.convert("length", p.y)]  # noqa: E731
    out: dict[str, Any] = {"body": {"name": b.name, "points": {n: pt(p) for n, p in b.points.items()},
                                    "fixed": {n: pt(p) for n, p in b.fixed.items()}},
                           "loads": {ld.name: {"at": ld.at, **u.vector_json(ld.force, "force")} for ld in b.loads},
                           "couples": {c.name: u.rate_json(c.torque, "torque") for c in b.couples}}
    f = study.result("forces")
    if f is not None:
        sup = {}
        for x in b.supports:
            row: dict[str, Any] = {"type": x.kind, "at": x.at, "force": u.vector_json(f.forces[x.name], "force")}
            if x.label:
                row["label"] = x.label
            if x.kind == MEMBER:
                row["to"] = x.end
            if x.kind != PIN:
                t = f.axial(x.name)
                row["axial"] = {"value": u.convert("force", abs(t)), "unit": u.force}
                row["state"] = _state(b, x.name, t)
            sup[x.name] = row
        out["free_body"] = {
            "method": f.method,
            "resultant": {**u.vector_json(f.resultant, "force"),
                          "through": pt(f.resultant_through) if f.resultant_through is not None else None},
            "construction_points": {n: pt(p) for n, p in f.points.items()},
            "condition": f.condition,
            "supports": sup}
        if study.asked("forces"):
            eq = study.get("equilibrium")
            out["free_body"]["equilibrium_system"] = {"condition_number": eq.condition, "residual": eq.residual}
    return out


FREE_BODY = Family(
    kind="free body",
    analyses={
        "forces": Analysis("forces", (), _forces, label="force polygon"),
        "equilibrium": Analysis("equilibrium", (), _equilibrium, label="equilibrium system"),
    },
    askable=("forces",),
    measured=measured_of("forces"),
    analytic=_analytic,
    construction=_construction,
    json=_json,
    warnings=_warnings,
    model_name=model_if_asked("forces", MODEL),
    scales=scales_of("forces"),
    notes=_notes,
    scene_type=FreeBodyScene,
    sections=SECTIONS, keys=TABLES,
    read=read_free_body,
    default_analyses=("forces",),
)
