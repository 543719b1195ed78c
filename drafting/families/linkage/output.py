"""What a linkage study writes as JSON (its classification, loops, pose, velocities, accelerations,
sweep, instant centres and forces in the scene's units), and the transmission angle as drawn that the
JSON and the notes share."""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from ...scene.unitset import direction_deg
from .force_output import forces_json


def transmission_at_pose(study) -> float | None:
    """The transmission angle (deg) of the crank's four-bar at the drawn pose, between coupler and rocker."""
    k = study.get("classification")
    if k is None:
        return None
    P = study.get("position").positions
    _, b, c, o2 = k.joints
    u, v = P[b] - P[c], P[o2] - P[c]
    return math.degrees(abs(math.atan2(u.cross(v), u.dot(v))))


def linkage_json(study) -> dict[str, Any]:
    s, u = study.scene, study.scene.units
    m = s.mechanism
    out: dict[str, Any] = {}
    pose = study.get("position")
    k = study.get("classification")
    if k is not None:
        deg = math.degrees
        out["classification"] = {
            "joints": list(k.joints), "closes": k.closes, "grashof": k.grashof, "kind": k.kind,
            "turns_fully": list(k.turns_fully), "mobility": k.mobility[0],
            "transmission_angle_deg": {
                "as_drawn": transmission_at_pose(study),
                "min": deg(k.transmission_min) if k.transmission_min is not None else None,
                "max": deg(k.transmission_max) if k.transmission_max is not None else None,
                "min_at_crank_deg": deg(k.transmission_min_at) % 360 if k.transmission_min_at is not None else None,
                "max_at_crank_deg": deg(k.transmission_max_at) % 360 if k.transmission_max_at is not None else None},
            "limit_positions": [{"extended": lp.extended, "crank_angle_deg": deg(lp.crank_angle) % 360,
                                 "rocker_angle_deg": deg(lp.rocker_angle) % 360} for lp in k.limit_positions]}
    loops = study.get("loops")
    if loops:
        out["loops"] = [{"input_link": lp.input, "joints": list(lp.k.joints), "closes": lp.k.closes,
                         "grashof": lp.k.grashof, "kind": lp.k.kind, "turns_fully": list(lp.k.turns_fully)}
                        for lp in loops]
    out["position"] = {n: [u.convert("length", p.x), u.convert("length", p.y)] for n, p in pose.positions.items()}
    v = study.computed("velocity")
    if v is not None:
        out["velocity"] = {f"V_{n}": u.vector_json(p, "velocity") for n, p in v.velocities.items() if n not in m.ground}
        out["relative_velocity"] = {f"V_{j}{p}": u.vector_json(w, "velocity") for (j, p), w in v.relative.items()}
        out["angular_velocity"] = {f"omega_{n}": u.rate_json(w, "angular velocity")
                                   for n, w in sorted(v.angular.items())}
    a = study.computed("acceleration")
    if a is not None:
        from constructions.polygons.acceleration import component_name
        out["acceleration"] = {f"A_{n}": u.vector_json(p, "acceleration") for n, p in a.accelerations.items()
                               if n not in m.ground}
        out["acceleration_components"] = {
            component_name(j, p, sup, m): u.vector_json(x, "acceleration")
            for comps, sup in ((a.normal, "n"), (a.tangential, "t")) for (j, p), x in comps.items()}
        out["angular_acceleration"] = {f"alpha_{n}": u.rate_json(al, "angular acceleration")
                                       for n, al in sorted(a.angular.items())}
    sw = study.computed("sweep")
    if sw is not None:
        res = sw[0]
        out["sweep"] = {"steps": int(res.thetas.size), "model": res.model,
                        "assembled": int(np.count_nonzero(res.assembles)),
                        "gaps_deg": [[math.degrees(float(res.thetas[i])), math.degrees(float(res.thetas[j - 1]))]
                                     for i, j in res.gaps()]}
    ic = study.computed("instant centres")
    if ic is not None:
        from constructions.mechanisms.centres import centre_name
        out["instant_centres"] = {
            centre_name(q): ({"x": u.convert("length", c.at.x), "y": u.convert("length", c.at.y)} if c.finite
                             else {"at_infinity": True, "direction_deg": direction_deg(c.direction) % 180})
            for q, c in sorted(ic.centres.items())}
        out["instant_centres_missing"] = [centre_name(q) for q in ic.missing]
    if study.result("forces") is not None:
        out["forces"] = forces_json(study)
    return out
