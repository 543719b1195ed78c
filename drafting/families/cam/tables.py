"""The cam results a student is asked for, in the scene's units: the per-station table (JSON and CSV) and the
largest velocity, acceleration, jerk and pressure angle, per segment and over the turn, exact and as read at
the drawn stations (JSON and the sheet's notes).  The numbers are the engine's
(:mod:`constructions.cams.stations`, :mod:`constructions.cams.maxima`), computed by the cam family's
"station table" and "maxima" analyses; this module only words and converts them."""

from __future__ import annotations

import csv
import io
import math
from typing import Any, Callable

from constructions.cams.follower import FLAT, OSC_FLAT, OSCILLATING
from constructions.cams.maxima import (Peak, motion_maxima, overall, pressure_maxima, station_peaks,
                                       unbounded)
from constructions.cams.stations import StationTable, station_table

from ...scene.units import UnitError, from_si


def run_station_table(study) -> StationTable:
    """The "station table" analysis: the table at the construction's stations."""
    m, c = study.scene.model, study.get("profile")
    return station_table(m.program, m.follower, c.stations, m.omega)


def run_maxima(study) -> dict[str, Any]:
    """The "maxima" analysis: each segment's exact peaks, the overall ones, the joins where a or j is
    infinite and the largest values at the drawn stations (SI)."""
    m = study.scene.model
    seg = motion_maxima(m.program, m.omega)
    phi = pressure_maxima(m.program, m.follower)
    if phi is not None:
        seg["pressure_angle"] = phi
    return {"segments": seg, "overall": {k: overall(v) for k, v in seg.items()},
            "unbounded": unbounded(m.program), "stations": station_peaks(study.get("station table"))}


Column = tuple[str, str, str, Callable[[float], float]]
"""(key, heading, unit, SI -> scene unit)."""


def columns(u, f, per_radian: bool) -> list[Column]:
    """The table's columns in the scene's units (an oscillating follower's s is its swing, an angle)."""
    osc = f.kind in (OSCILLATING, OSC_FLAT)
    L, A = u.of("length"), u.of("angle")
    conv = lambda kind: (lambda v: u.convert(kind, v))      # noqa: E731
    same = lambda v: v                                      # noqa: E731
    sym = "\u03c8" if osc else "s"
    if per_radian:
        if osc:
            vaj = [("1", same), ("1/rad", same), ("1/rad^2", same)]
        else:
            vaj = [(f"{L}/rad", conv("length")), (f"{L}/rad^2", conv("length")), (f"{L}/rad^3", conv("length"))]
        heads = [f"d{sym}/d\u03b8", f"d\u00b2{sym}/d\u03b8\u00b2", f"d\u00b3{sym}/d\u03b8\u00b3"]
    else:
        if osc:
            vaj = [(u.of("angular velocity"), conv("angular velocity")),
                   (u.of("angular acceleration"), conv("angular acceleration")), ("rad/s^3", same)]
        else:
            J = _jerk_length(u)
            vaj = [(u.of("velocity"), conv("velocity")), (u.of("acceleration"), conv("acceleration")),
                   (f"{J}/s^3", lambda v: from_si(v, "length", J))]
        heads = ["\u03c9" if osc else "v", "\u03b1" if osc else "a", "d\u03b1/dt" if osc else "j"]
    out: list[Column] = [("theta", "cam angle", A, conv("angle")),
                         ("s", sym, A if osc else L, conv("angle" if osc else "length"))]
    out += [(k, h, unit, fn) for k, h, (unit, fn) in zip(("v", "a", "j"), heads, vaj)]
    out += [("pressure_angle", "pressure angle", A, conv("angle")),
            ("rho_pitch", "radius of curvature, pitch curve", L, conv("length")),
            ("rho_profile", "radius of curvature, profile", L, conv("length")),
            ("contact_x", "contact x", L, conv("length")), ("contact_y", "contact y", L, conv("length"))]
    return out


def _jerk_length(u) -> str:
    """The length unit jerk is given in: the velocity's (m/s -> m/s^3), else the scene's length unit."""
    head, _, tail = u.of("velocity").partition("/")
    try:
        from_si(1.0, "length", head)
    except UnitError:                    # "kph": no length before the stroke
        return u.of("length")
    return head if tail.strip() == "s" else u.of("length")


def _values(t: StationTable, i: int) -> dict[str, float | None]:
    return {"theta": t.theta[i], "s": t.s[i], "v": t.v[i], "a": t.a[i], "j": t.j[i],
            "pressure_angle": t.pressure_angle[i], "rho_pitch": None if t.rho_pitch is None else t.rho_pitch[i],
            "rho_profile": t.rho_profile[i], "contact_x": t.contact[0, i], "contact_y": t.contact[1, i]}


def _finite(v: float | None) -> float | None:
    """A number JSON can hold: an infinite radius (a straight stretch) or no value is null."""
    return float(v) if v is not None and math.isfinite(v) else None


def basis(study) -> str:
    m = study.scene.model
    if m.omega:
        return f"with the cam turning steadily at {study.scene.units.format('angular velocity', m.omega)}"
    return ("per radian of cam angle (no cam speed given): v, a, j are ds/d\u03b8, d\u00b2s/d\u03b8\u00b2, "
            "d\u00b3s/d\u03b8\u00b3, the follower's velocity, acceleration and jerk at 1 rad/s")


def stations_json(study) -> dict[str, Any]:
    """The per-station table: its columns' units and a row per station (null: no value, or infinite)."""
    t, s = study.get("station table"), study.scene
    cols = columns(s.units, s.model.follower, t.per_radian)
    flat = s.model.follower.kind in (FLAT, OSC_FLAT)
    rows = []
    for i in range(len(t)):
        vals = _values(t, i)
        rows.append({"station": i, **{k: _finite(None if vals[k] is None else fn(vals[k])) for k, _, _, fn in cols}})
    return {"basis": basis(study), "units": {k: unit for k, _, unit, _ in cols},
            "notes": "a station on a join takes the later segment's values; contact x, y in the cam frame at cam "
                     "angle 0" + ("; a flat face has no pitch curve (rho_pitch null)" if flat else
                                  "; null radius: a straight stretch (infinite)"),
            "rows": rows}


def stations_csv(study) -> str:
    """The per-station table as CSV: ``#`` lines naming the scene and the basis, a header with each column's
    unit, a row per station."""
    t, s = study.get("station table"), study.scene
    cols = columns(s.units, s.model.follower, t.per_radian)
    buf = io.StringIO()
    buf.write(f"# station table of {s.title}\n# {basis(study)}\n# a station on a join takes the later "
              f"segment's values; contact x, y in the cam frame at cam angle 0; empty: no value or infinite\n")
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(["station"] + [f"{h} ({unit})" for _, h, unit, _ in cols])
    for i in range(len(t)):
        vals = _values(t, i)
        w.writerow([i] + ["" if _finite(vals[k]) is None else repr(_finite(fn(vals[k]))) for k, _, _, fn in cols])
    return buf.getvalue()


def _convert_for(study) -> dict[str, Callable[[float], float]]:
    s = study.scene
    return {k: fn for k, _, _, fn in columns(s.units, s.model.follower, not s.model.omega)}


def _peak_json(p: Peak, A, fn) -> dict[str, Any]:
    """A peak: ``at`` its cam angles, or with ``throughout`` the [start, end] spans it holds over."""
    if p.throughout:
        return {"value": fn(p.value), "throughout": [[A(a), A(b)] for a, b in zip(p.at[::2], p.at[1::2])]}
    return {"value": fn(p.value), "at": [A(a) for a in p.at]}


def maxima_json(study) -> dict[str, Any]:
    """The maxima, in the scene's units: per segment and overall, exact (``at``: cam angles; ``throughout``:
    the value holds over the span ``at``) and at the drawn stations."""
    mx, s = study.get("maxima"), study.scene
    fns, A = _convert_for(study), (lambda v: s.units.convert("angle", v))
    prog = s.model.program
    segs = []
    for i, seg in enumerate(prog.segments):
        row: dict[str, Any] = {"segment": i + 1, "motion": seg.describe(), "from": A(prog.starts[i]),
                               "to": A(prog.starts[i] + seg.beta)}
        for q, peaks in mx["segments"].items():
            row[q] = _peak_json(peaks[i], A, fns[q])
        segs.append(row)
    whole = {}
    for q, p in mx["overall"].items():
        st = mx["stations"][q]
        whole[q] = {"exact": _peak_json(p, A, fns[q]),
                    "at_stations": {"value": fns[q](st.value), "at": A(st.at), "station": st.index}}
    return {"basis": basis(study), "method": METHOD, "segments": segs, "overall": whole,
            "infinite": {"a": [A(t) for t in mx["unbounded"]["a"]], "j": [A(t) for t in mx["unbounded"]["j"]]}}


METHOD = {"v, a, j": "exact: each law's closed form at the cam angle where it peaks (constructions.cams.maxima)",
          "pressure_angle": "a search on each piece of the program (256 points, then 8 rounds narrowing the "
                            "bracket 16-fold): the value to rounding, the cam angle to about 1e-8 rad",
          "at_stations": "the largest magnitude among the drawn stations (the station table)"}


_WORDS = {"v": ("velocity v", "ds/d\u03b8"), "a": ("acceleration a", "d\u00b2s/d\u03b8\u00b2"),
          "j": ("jerk j", "d\u00b3s/d\u03b8\u00b3")}
_SWING = {"v": ("angular velocity of the arm", "d\u03c8/d\u03b8"),
          "a": ("angular acceleration of the arm", "d\u00b2\u03c8/d\u03b8\u00b2"),
          "j": ("angular jerk of the arm", "d\u00b3\u03c8/d\u03b8\u00b3")}


def _unit(unit: str) -> str:
    return "" if unit == "1" else " " + unit.replace("^2", "\u00b2").replace("^3", "\u00b3")


def _where(u, p: Peak) -> str:
    """Where a peak occurs, in words: "at 120° and 180°", or "from 0° to 90°" for a value held throughout."""
    if p.throughout:
        return " and ".join(f"from {u.format('angle', a)} to {u.format('angle', b)}"
                            for a, b in zip(p.at[::2], p.at[1::2]))
    shown = [u.format("angle", a) for a in p.at]
    return "at " + (shown[0] if len(shown) == 1 else ", ".join(shown[:-1]) + " and " + shown[-1])


def maxima_notes(study) -> list[str]:
    """The sheet's notes on the maxima: each quantity's largest, exact and at the drawn stations, labelled."""
    mx, s = study.get("maxima"), study.scene
    u, f = s.units, s.model.follower
    cols = {k: (unit, fn) for k, _, unit, fn in columns(u, f, not s.model.omega)}
    n = len(study.get("station table"))
    out = []
    if "pressure_angle" in mx["overall"]:
        p, st = mx["overall"]["pressure_angle"], mx["stations"]["pressure_angle"]
        row = " (the \u03c6_max row)" if "phi_max" in study.get("profile").station_names else ""
        out.append(f"Largest pressure angle, exact: {u.format('angle', p.value)} {_where(u, p)}"
                   + (f", the offset {u.format('length', f.offset)} included" if f.offset else "")
                   + f"; at the {n} drawn stations{row}: {u.format('angle', st.value)} at {u.format('angle', st.at)}.")
    words = _SWING if f.kind in (OSCILLATING, OSC_FLAT) else _WORDS
    for q in ("v", "a", "j"):
        p, st = mx["overall"][q], mx["stations"][q]
        unit, fn = cols[q]
        name = words[q][0] if s.model.omega else f"{words[q][1]} ({words[q][0]} at a cam speed of 1 rad/s)"
        out.append(f"Largest {name}, exact: {fn(p.value):.4g}{_unit(unit)} {_where(u, p)}; at the {n} drawn stations: "
                   f"{fn(st.value):.4g}{_unit(unit)} at {u.format('angle', st.at)}.")
    return out


_POINTS = {"knife-edge": "the knife edge P (on the profile itself, so C = P)",
           "roller": "the roller centre P and the point of contact C",
           "oscillating roller": "the roller centre P and the point of contact C",
           "flat-faced": "the foot P of the face line on the follower's line and the point of contact C",
           "oscillating flat-faced": "the foot P of the perpendicular from O to the face and the point of contact C"}


def rows_note(study) -> str:
    """What the results table's P_theta and C_theta rows are, in words."""
    return (f"Rows P_\u03b8 and C_\u03b8: {_POINTS[study.scene.model.follower.kind]} at the station where a segment "
            f"of the program begins, at cam angle \u03b8; read off the construction and checked against the "
            f"closed form.")
