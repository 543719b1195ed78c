"""The linkage family: planar linkages at one pose -- position, velocity polygon, acceleration polygon,
static and D'Alembert force polygons -- each checked against an independent analytic solution (vector
loops; the global equilibrium system and virtual work for forces).  Registered in
:mod:`drafting.families.registry`."""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
from typing import TYPE_CHECKING, Mapping, NamedTuple

from constructions.mechanisms.classify import classify_four_bar
from constructions.forces.bodies import torque_name
from constructions.forces.effects import NO_EFFECTS
from constructions.geometry import Vec
from constructions.check import NotModelled, analytic_solution, analytic_values
from constructions.mechanisms.pose import locate
from constructions.quantities import Measured
from constructions.polygons.velocity import velocity_polygon
from constructions.record import Construction

if TYPE_CHECKING:
    from constructions.sweep import Sweep

from ..registry import Analysis, Family
from .conventions import conventions
from .force_output import driving_torque_note
from .given import given_lines
from .inverse import driven_analytic, driven_measured, driven_notes, inverse_analytic, inverse_measured, inverse_notes
from .inverse_load import LOAD_ANALYSES, found_load_note, found_load_rows
from .output import linkage_json, transmission_at_pose
from .scene import SECTIONS, TABLES, LinkageScene, assembly_check, read_linkage


def _read_vary(data, path, units):
    """The scene's [vary] (:mod:`.vary`, loaded for such a scene only)."""
    from .vary import read_vary
    return read_vary(data, path, units)


def _classification(study):
    return classify_four_bar(study.scene.mechanism)


def _loops(study):
    """The further four-bar loops (a rocker driving a second rocker), each classified."""
    from constructions.mechanisms.classify import classify_loops
    return classify_loops(study.scene.mechanism)


def _position(study):
    s = study.scene
    pose = locate(s.mechanism, s.angle, study.get("plan"), fmt=s.units.format)
    if getattr(s, "inverse", None) is not None:
        from constructions.mechanisms.inverse_construction import inverse_step, with_inverse
        step = inverse_step(s.mechanism, s.inverse, study.get("plan"), s.solution)
        pose = replace(pose, construction=with_inverse(pose.construction, step))
    if s.dimensions:
        from constructions.dimensions import dimension_links
        pose = replace(pose, construction=dimension_links(s.mechanism, pose))
    return pose


def _velocity(study):
    s = study.scene
    va = velocity_polygon(s.mechanism, study.get("position"), s.omega)
    if getattr(s, "driven", None) is not None:
        from constructions.polygons.driving_slider import driving_steps, with_first
        step = driving_steps(s.driven, s.mechanism.crank, s.inverse.along)[0]
        va = replace(va, construction=with_first(va.construction, step))
    return va


def _alpha(study) -> float:
    """The crank's angular acceleration: the scene's alpha, or (only when the scene gives a torque instead)
    the analysis "crank alpha"."""
    return study.scene.alpha if study.scene.torque is None else study.get("crank alpha")


def _crank_alpha(study) -> float:
    """The alpha at which the torque on the crank is the scene's torque, from the equilibrium system of all
    links (e.g. torque 0 for a body released from rest)."""
    s = study.scene
    from constructions.forces.equilibrium import alpha_for_torque
    return alpha_for_torque(s.mechanism, s.angle, s.omega, _effects(study), s.torque,
                            guess=study.get("position").positions)


def _alpha_by_virtual_work(study) -> float:
    """The same alpha again by the power balance: the independent check of :func:`_crank_alpha`."""
    from constructions.forces.equilibrium import alpha_for_torque
    s = study.scene
    return alpha_for_torque(s.mechanism, s.angle, s.omega, _effects(study), s.torque,
                            guess=study.get("position").positions, by="virtual work")


def _acceleration(study):
    from constructions.polygons.acceleration import acceleration_polygon
    s = study.scene
    aa = acceleration_polygon(s.mechanism, study.get("velocity"), _alpha(study))
    if getattr(s, "driven", None) is not None:
        from constructions.polygons.driving_slider import driving_steps, with_first
        step = driving_steps(s.driven, s.mechanism.crank, s.inverse.along)[1]
        aa = replace(aa, construction=with_first(aa.construction, step))
    return aa


def _instant_centres(study):
    from constructions.mechanisms.instant_centres import instant_centres
    return instant_centres(study.scene.mechanism, study.get("position"), study.scene.omega)


SWEEP_STEPS = 360
"""A sheet's sweep: one turn of the crank in steps of 1 deg (analytic and vectorised: milliseconds)."""


class SweepAnalysis(NamedTuple):
    """The sweep analysis: the solved turn, its charts and coupler curves, the order in which the charts
    draw the turn's samples (constructions.cycle.one_turn: over 0 to 360 deg), and at each angle where
    the linkage cannot be assembled the crank's own points (SI), which stand there all the same."""

    result: Sweep
    record: Construction
    chart_order: tuple[int, ...]
    crank_at_gaps: Mapping[int, Mapping[str, Vec]]


def _sweep(study) -> SweepAnalysis:
    """The linkage over one turn of its crank from the drawn angle, and its charts and coupler curves."""
    from constructions.mechanisms.cycle import cycle_record, one_turn
    from constructions.sweep import crank_points, sweep
    s = study.scene
    thetas = s.angle + 2 * math.pi * np.arange(SWEEP_STEPS + 1) / SWEEP_STEPS
    result = sweep(s.mechanism, thetas, s.omega, _alpha(study))
    deg = s.units.format
    record = cycle_record(s.mechanism, result, study.get("classification"), lambda a: deg("angle", a))
    crank: dict[int, Mapping[str, Vec]] = {}
    for i in np.flatnonzero(~np.asarray(result.assembles, dtype=bool)):
        points = crank_points(s.mechanism, float(result.thetas[i]))
        if points is None:                        # a crank without a fixed joint: nothing stands at a gap
            break
        crank[int(i)] = points
    order = one_turn(tuple(float(t) for t in result.thetas))[0]
    return SweepAnalysis(result, record, tuple(order), crank)


def _turn(study):
    """The linkage at a caller's crank angles (``study.options``: "crank angles", "progress"): ``drafting
    sweep``'s table."""
    from constructions.sweep import sweep
    s = study.scene
    return sweep(s.mechanism, study.options["crank angles"], s.omega, s.alpha, progress=study.options.get("progress"))


def _cannot_sweep(scene) -> str | None:
    if getattr(scene, "driven", None) is not None:
        return ("input.slider_speed: a sweep turns the crank at a steady speed; a slider that drives at a given "
                "speed turns it unsteadily, which this version does not sweep")
    if scene.torque is not None:
        return ("input.torque: a sweep needs the crank's motion (omega and alpha); at a given torque the motion "
                "over the cycle is a simulation, which this version does not run")
    return None


def _effects(study):
    """The scene's effects, with the load a given torque holds at the magnitude found for it."""
    e = getattr(study.scene, "effects", None) or NO_EFFECTS
    if e.balance is None:
        return e
    from constructions.forces.inverse import with_load
    return with_load(e, study.get("load for torque"))


def _forces(study):
    """Static or D'Alembert force polygons: the accelerations only when some body has mass, the velocities
    only when friction needs the sliding direction -- what the scene declares and nothing else."""
    from constructions.forces.polygon import force_analysis
    s, e = study.scene, _effects(study)
    velocity = study.get("velocity") if e.friction else None
    acceleration = study.get("acceleration") if e.inertial else None
    return force_analysis(s.mechanism, study.get("position"), e, velocity=velocity, acceleration=acceleration)


def _force_check(study):
    """The global equilibrium system of all links and the input torque by virtual work (power balance)."""
    from constructions.forces.equilibrium import equilibrium, virtual_work_torque
    s, e = study.scene, _effects(study)
    guess = study.get("position").positions
    alpha = _alpha(study)
    eq = equilibrium(s.mechanism, s.angle, s.omega, alpha, e, guess=guess)
    vw = virtual_work_torque(s.mechanism, s.angle, s.omega, alpha, e, friction=eq.friction or None, guess=guess)
    return eq, vw


def _analytic(study):
    """The vector-loop solution, None where it does not assemble, or the NotModelled reason."""
    s = study.scene
    try:
        return analytic_solution(s.mechanism, s.angle, s.omega, _alpha(study),
                                 accelerations=study.computed("acceleration") is not None,
                                 guess=study.get("position").positions)
    except NotModelled as e:
        return e


VIRTUAL_WORK = " (virtual work)"
INSTANT_CENTRES = " (instant centres)"


def _measured(study) -> list:
    m = study.scene.mechanism
    out = []
    for name in ("velocity", "acceleration", "instant centres"):
        r = study.computed(name)
        if r is not None:
            out += r.measured(m)
    if study.scene.torque is not None:
        out.append(Measured(f"alpha_{m.crank}", "angular acceleration", study.get("crank alpha")))
    out += inverse_measured(study.scene) + driven_measured(study.scene)
    out += found_load_rows(study, "load for torque")
    f = study.result("forces")
    if f is not None:
        got = f.measured(m)
        i = next(i for i, x in enumerate(got) if x.name == torque_name(m))
        out += [*got[:i + 1], replace(got[i], name=got[i].name + VIRTUAL_WORK), *got[i + 1:]]
    return out


def _scales(study) -> dict[str, float]:
    out: dict[str, float] = {}
    for name in ("velocity", "acceleration", "forces"):
        r = study.computed(name)
        if r is not None:
            out.update(r.scales())
    return out


def _solution(study):
    a = study.get("analytic")
    return None if isinstance(a, NotModelled) else a


def _analytic_values(study):
    out: dict = {}
    if study.computed("velocity") is not None:
        out.update(analytic_values(study.scene.mechanism, _solution(study)) or {})
    ic = study.computed("instant centres")
    if ic is not None:
        for x in ic.measured(study.scene.mechanism, suffix=""):
            if x.name in out:
                out[x.name + INSTANT_CENTRES] = out[x.name]
    if study.scene.torque is not None:
        out[f"alpha_{study.scene.mechanism.crank}"] = study.get("alpha check")
    out.update(inverse_analytic(study.scene))
    out.update(driven_analytic(study.scene, study.get("position").positions))
    out.update((x.name, x.value) for x in found_load_rows(study, "load check"))
    if study.asked("forces"):
        eq, vw = study.get("force check")
        out.update(eq.values(study.scene.mechanism))
        out[torque_name(study.scene.mechanism) + VIRTUAL_WORK] = vw
    return out or None


def _construction(study) -> Construction:
    s, pose = study.scene, study.get("position")
    alpha = s.alpha if s.torque is None and study.computed("acceleration") is not None else None
    c = pose.construction + conventions(s.mechanism, pose, s.omega, alpha)
    for name in ("velocity", "acceleration", "forces", "instant centres"):
        r = study.computed(name)
        if r is not None:
            c = c + r.construction
    sw = study.computed("sweep")
    if sw is not None:
        c = c + sw[1]
    return c


def _notes(study) -> tuple[str, ...]:
    w: list[str] = []
    s = study.scene
    if s.torque is not None:
        u, n = s.units, s.mechanism.crank
        w.append(f"\u03b1_{n} follows from the torque on the crank, T_{n} = {u.format('torque', s.torque)}"
                 + (", released from rest" if s.omega == 0 else "")
                 + ": its first column from the equilibrium of all links, its second by virtual work.")
    w += inverse_notes(s) + driven_notes(s)
    k = study.get("classification")
    if k is not None:
        line = k.summary(lambda v: s.units.format("length", v))
        mu = transmission_at_pose(study)
        if k.transmission_min is not None:
            lo, hi = math.degrees(k.transmission_min), math.degrees(k.transmission_max)
            line += f"; transmission angle {lo:.0f}\u2013{hi:.0f}\u00b0"
            if lo < 40 or hi > 140:
                line += " (the usual range is 40\u2013140\u00b0)"
        if mu is not None:
            line += f", {mu:.0f}\u00b0 as drawn"
        w.append(line[:1].upper() + line[1:] + ".")
    w += found_load_note(study)
    if s.torque is None and study.result("forces") is not None:
        w.append(driving_torque_note(study))
    for lp in study.get("loops"):
        q, _, j, o = lp.k.joints
        w.append(f"Loop {q}-{lp.k.joints[1]}-{j}-{o}, driven by link {lp.input}, by its lengths a "
                 + lp.k.summary(lambda v: s.units.format("length", v),
                                ("frame", f"input link {lp.input}", "coupler", "output")) + ".")
    return tuple(w)


def _warnings(study) -> tuple[str, ...]:
    w: list[str] = []
    for name in ("velocity", "acceleration", "forces", "instant centres"):
        r = study.computed(name)
        if r is not None:
            w += [x for x in r.warnings if x not in w]
    sw = study.computed("sweep")
    if sw is not None and sw[0].gaps():
        res, u = sw[0], study.scene.units
        spans = ", ".join(f"{u.format('angle', float(res.thetas[i]))} to {u.format('angle', float(res.thetas[j - 1]))}"
                          for i, j in res.gaps())
        w.append(f"Over the turn the linkage cannot be assembled from {spans}: the charts and paths have gaps "
                 f"there.")
    if study.computed("velocity") is not None:
        a = study.get("analytic")
        if isinstance(a, NotModelled):
            w.append(f"No analytic check: {a}.")
        elif a is None:
            w.append("No analytic check: the vector-loop solution does not assemble at this position.")
    return tuple(w)


def _model(study) -> str | None:
    names = []
    if study.computed("velocity") is not None:
        a = _solution(study)
        if a is not None:
            names.append(a.model if a.model == "constraint equations" else f"{a.model} vector loop")
    if study.asked("forces"):
        names.append("equilibrium of all links and virtual work")
    return "; ".join(names) or None


LINKAGE = Family(
    kind="linkage",
    analyses={
        "plan": Analysis("plan", (), assembly_check, label="classification"),   # recorded with the class
        "classification": Analysis("classification", ("plan",), _classification),
        "loops": Analysis("loops", ("plan",), _loops, label="classification"),     # part of it: one entry in ran
        "position": Analysis("position", ("classification",), _position),
        "velocity": Analysis("velocity", ("position",), _velocity),
        "crank alpha": Analysis("crank alpha", ("position",), _crank_alpha, label="alpha from the torque"),
        "alpha check": Analysis("alpha check", ("position",), _alpha_by_virtual_work,
                                label="alpha by virtual work"),
        "acceleration": Analysis("acceleration", ("velocity",), _acceleration),
        "analytic": Analysis("analytic", ("position",), _analytic, label="analytic check"),
        "forces": Analysis("forces", ("position",), _forces, label="force polygons"),
        "instant centres": Analysis("instant centres", ("velocity",), _instant_centres,
                                    label="instant centres (Kennedy)"),
        "sweep": Analysis("sweep", ("position",), _sweep, label="sweep over the cycle"),
        "force check": Analysis("force check", ("position",), _force_check,
                                label="equilibrium system and virtual work"),
        "turn": Analysis("turn", ("plan",), _turn, label="sweep over the given crank angles"),
        **LOAD_ANALYSES,
    },
    askable=("position", "velocity", "acceleration", "forces", "instant centres", "sweep"),
    measured=_measured,
    analytic=_analytic_values,
    construction=_construction,
    json=linkage_json,
    warnings=_warnings,
    model_name=_model,
    scales=_scales,
    notes=_notes,
    scene_type=LinkageScene,
    sections=SECTIONS, keys=TABLES,
    read=read_linkage,
    checks=("plan",),
    vary=_read_vary,
    given=given_lines,
    dimensioned_problem=True,
    sweeps="turn",
    cannot_sweep=_cannot_sweep,
    default_analyses=("velocity",),
)
