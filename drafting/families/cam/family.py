"""The cam family: a disk cam with a translating follower (knife-edge, roller -- radial or offset -- or
flat-faced) or an oscillating one (roller or flat-faced) driven by a motion program of dwells, rises and
returns.  The profile is constructed as the
notes draw it (:mod:`constructions.cams.construction`), its exact envelope and curvature found
analytically (:mod:`constructions.cams.profile`), and the points read off the construction checked against
textbook closed forms (:mod:`constructions.cams.check`).  Registered in :mod:`drafting.families.registry`; its scene
sections are read by :mod:`drafting.families.cam.scene`."""

from __future__ import annotations

import math
from typing import Any

from constructions.cams import check as cam_check
from constructions.cams.construction import construct
from constructions.cams.follower import FLAT, KNIFE, OSC_FLAT, OSCILLATING, ROLLER
from constructions.geometry import Vec

from ..glue import construction_of, model_if_asked
from ..registry import Analysis, Family
from .limits import near_limit
from .machining import machining_profile
from .tables import maxima_json, maxima_notes, rows_note, run_maxima, run_station_table, stations_json
from .scene import SECTIONS, TABLES, CamScene, read_cam

MODEL = "closed-form cam geometry (pressure angle and contact point)"


def _deg(a: float) -> str:
    return f"{math.degrees(a):.4g} deg"


def _profile(study):
    m, u = study.scene.model, study.scene.units
    return construct(m.program, m.follower, m.divisions, omega=m.omega,
                     degrees=lambda a: u.format("angle", a))


def _closed(study):
    m = study.scene.model
    c = study.get("profile")
    out: dict[str, Any] = {}
    for name, i in c.station_names.items():
        cf = cam_check.closed_form_point(m.program, m.follower, float(c.stations[i]))
        if name == "phi_max":
            out[name] = cf["phi"]
        else:
            out[name] = Vec(*cf[name[0]])
    return out


def _measured(study) -> list:
    c = study.result("profile")
    return c.measured if c is not None else []


def _analytic(study):
    return study.get("closed forms") if study.asked("profile") else None


def _scales(study) -> dict[str, float]:
    c = study.result("profile")
    return {"length": c.profile.size} if c is not None else {}


def _spans(u, spans) -> str:
    return ", ".join(f"{u.format('angle', a % (2 * math.pi))} to {u.format('angle', b % (2 * math.pi))}"
                     for a, b in spans)


_FACE_LIMITS = {
    OSC_FLAT: (lambda u, cp: f"Cusp: the profile's radius of curvature comes to zero at "
                             f"{u.format('angle', cp.cusp_at[0])}; the flat face is at its limit there.",
               lambda u, cp: f"The flat face cannot follow: the profile's radius of curvature goes negative from "
                             f"{_spans(u, cp.undercut)} (a larger base circle or a slower swing helps); the profile "
                             f"drawn is trimmed."),
    FLAT: (lambda u, cp: f"Cusp: the base radius is exactly the smallest for a flat face (r_b + s + s'' = 0 at "
                         f"{u.format('angle', cp.cusp_at[0])}).",
           lambda u, cp: f"The flat face cannot follow: r_b + s + s'' < 0 from {_spans(u, cp.undercut)} (needs a base "
                         f"radius above {u.format('length', cp.min_base_radius)}); the profile drawn is trimmed."),
}
"""A flat face's warnings, translating or oscillating: (at the cusp, past it)."""


def _profile_terms(study):
    """The scene's units, the solved profile and the follower: what the warnings and notes speak of."""
    return study.scene.units, study.result("profile").profile, study.scene.model.follower


def _warnings(study) -> tuple[str, ...]:
    if study.result("profile") is None:
        return ()
    u, cp, f = _profile_terms(study)
    out = []
    if f.kind in (ROLLER, OSCILLATING) and cp.min_rho_pitch is not None:
        t, rho = cp.min_rho_pitch
        if cp.cusp_at:
            out.append(f"Cusp, at the undercut limit: the roller radius {u.format('length', f.roller_radius)} equals the "
                       f"pitch curve's smallest radius of curvature ({u.format('length', rho)}, to 1e-9 of the cam's "
                       f"size) at {u.format('angle', t)}; the profile comes to a point there, and any larger roller "
                       f"would undercut it.")
        elif cp.undercut:
            out.append(f"Undercut: the roller radius {u.format('length', f.roller_radius)} exceeds the pitch curve's "
                       f"smallest radius of curvature {u.format('length', rho)} (at {u.format('angle', t)}); the "
                       f"envelope loops back from {_spans(u, cp.undercut)}: the profile drawn is trimmed there and "
                       f"the follower will not follow its program.")
    face = _FACE_LIMITS.get(f.kind)
    if face is not None and (cp.cusp_at or cp.undercut):
        cusp, cannot = face
        out.append(cusp(u, cp) if cp.cusp_at else cannot(u, cp))
    if cp.corners:
        at = ", ".join(u.format("angle", t % (2 * math.pi)) for t in sorted(cp.corners, key=lambda t: t % (2 * math.pi)))
        out.append(f"Corners: the follower's velocity jumps at {at}, so the pitch curve turns a corner there and "
                   f"the envelope's two branches cross or part; the profile drawn is trimmed to what the "
                   f"{'roller' if f.kind in (ROLLER, OSCILLATING) else 'face'} leaves (a sharp edge on the cam, and "
                   f"a shock in the follower).")
    out += near_limit(u, cp, f, study.scene.model.limit_margin)
    phi = abs(cp.max_pressure_angle[1])
    limit = 35 if f.kind in (OSCILLATING, OSC_FLAT) else 30
    if f.kind != FLAT and phi > math.radians(limit):
        out.append(f"The pressure angle reaches {u.format('angle', phi)} at {u.format('angle', cp.max_pressure_angle[0])}"
                   f", above the usual {limit}\u00b0 for {'an oscillating' if limit == 35 else 'a translating'} "
                   f"follower.")
    return tuple(out)


def _notes(study) -> tuple[str, ...]:
    if study.result("profile") is None:
        return ()
    u, cp, f = _profile_terms(study)
    out = maxima_notes(study)
    if cp.min_rho_pitch is not None:
        t, rho = cp.min_rho_pitch
        out.append(f"Smallest radius of curvature of the pitch curve (convex): {u.format('length', rho)} at "
                   f"{u.format('angle', t)}; the roller must be smaller.")
    t, rho = cp.min_rho_profile
    what = ("where the pitch curve is convex" if f.kind in (ROLLER, OSCILLATING) else "")
    loops = (" (zero to rounding: the profile's cusp at the undercut limit)" if cp.cusp_at and abs(rho) <= 1e-9 * cp.size
             else " (negative: the exact envelope loops back there; the profile drawn is trimmed)" if rho < 0 else "")
    out.append(f"Smallest radius of curvature of the profile{' ' + what if what else ''}: {u.format('length', rho)} at "
               f"{u.format('angle', t)}{loops}.")
    if f.kind == OSC_FLAT:
        lo, hi = cp.face_width
        out.append(f"The face must reach from {u.format('length', lo)} to {u.format('length', hi)} along the arm from "
                   f"the foot of the pivot (length {u.format('length', hi - lo)}); at zero lift the arm makes "
                   f"{u.format('angle', f.beta0)} with the line of centres.")
    if f.kind == FLAT:
        lo, hi = cp.face_width
        out.append(f"Smallest base radius for a flat face (r_b + s + s'' > 0): {u.format('length', cp.min_base_radius)}"
                   f"; the face must reach {u.format('length', -lo)} and {u.format('length', hi)} either side of its "
                   f"axis (width {u.format('length', hi - lo)}).")
    for j in study.scene.model.program.joins():
        if j.consequence:
            out.append(f"At {u.format('angle', j.theta)} ({j.before} to {j.after}): {j.consequence}.")
    if study.get("profile").station_names:
        out.append(rows_note(study))
    return tuple(out)


def _json(study) -> dict[str, Any]:
    s, u = study.scene, study.scene.units
    m = s.model
    f = m.follower
    L = lambda v: u.convert("length", v)      # noqa: E731
    A = lambda v: u.convert("angle", v)       # noqa: E731
    prog = []
    for i, seg in enumerate(m.program.segments):
        a = m.program.starts[i]
        row = {"motion": seg.kind, "from": A(a), "to": A(a + seg.beta)}
        if seg.kind != "dwell":
            row.update(lift=A(seg.lift) if f.kind in (OSCILLATING, OSC_FLAT) else L(seg.lift), law=seg.law)
        prog.append(row)
    out: dict[str, Any] = {"cam": {"base_radius": L(f.base_radius), "sense": "ccw" if f.sense > 0 else "cw",
                                   "divisions": m.divisions,
                                   "speed": u.convert("angular velocity", m.omega) if m.omega else None},
                           "follower": {"type": f.kind, "roller_radius": L(f.roller_radius), "offset": L(f.offset),
                                        **({"pivot_distance": L(f.pivot_distance), "arm_length": L(f.arm_length)}
                                           if f.kind == OSCILLATING else {}),
                                        **({"pivot_distance": L(f.pivot_distance), "face_offset": L(f.face_offset)}
                                           if f.kind == OSC_FLAT else {})},
                           "program": prog,
                           "joins": [{"at": A(j.theta), "before": j.before, "after": j.after,
                                      "consequence": j.consequence or "continuous"} for j in m.program.joins()]}
    c = study.result("profile")
    if c is not None:
        cp = c.profile
        out["profile"] = {
            "table": [{"theta": A(t), "s": A(v) if f.kind in (OSCILLATING, OSC_FLAT) else L(v)}
                      for t, v in zip(c.stations, c.table)],
            "max_pressure_angle": {"at": A(cp.max_pressure_angle[0]), "value": A(abs(cp.max_pressure_angle[1]))},
            "min_radius_of_curvature_pitch": ({"at": A(cp.min_rho_pitch[0]), "value": L(cp.min_rho_pitch[1])}
                                              if cp.min_rho_pitch else None),
            "min_radius_of_curvature_profile": {"at": A(cp.min_rho_profile[0]), "value": L(cp.min_rho_profile[1])},
            "undercut": [[A(a), A(b)] for a, b in cp.undercut],
            "cusps": [A(t) for t in cp.cusp_at],
            "min_base_radius_flat": L(cp.min_base_radius) if cp.min_base_radius is not None else None,
            "face_width": L(cp.face_width[1] - cp.face_width[0]) if cp.face_width else None,
            **({"face_reach_along_arm": [L(cp.face_width[0]), L(cp.face_width[1])]} if f.kind == OSC_FLAT else {}),
        }
        out["stations"] = stations_json(study)
        out["maxima"] = maxima_json(study)
    return out


CAM = Family(
    kind="cam",
    analyses={
        "profile": Analysis("profile", (), _profile, label="cam construction"),
        "closed forms": Analysis("closed forms", ("profile",), _closed, label="cam closed forms"),
        "machining profile": Analysis("machining profile", (), machining_profile),
        "station table": Analysis("station table", ("profile",), run_station_table, label="cam station table"),
        "maxima": Analysis("maxima", ("station table",), run_maxima, label="cam maxima"),
    },
    askable=("profile",),
    measured=_measured,
    analytic=_analytic,
    construction=construction_of("profile"),
    json=_json,
    warnings=_warnings,
    model_name=model_if_asked("profile", MODEL),
    scales=_scales,
    notes=_notes,
    scene_type=CamScene,
    sections=SECTIONS, keys=TABLES,
    read=read_cam,
    default_analyses=("profile",),
)

__all__ = ["CAM", "KNIFE"]
