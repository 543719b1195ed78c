"""The inverse static problem in a linkage study: a [[load]] given by the driving torque it holds (``torque``
instead of ``force``) has its magnitude found twice -- from the equilibrium of all links ("load for
torque", the value every force polygon is then drawn with) and by virtual work ("load check", the
independent route) -- and compared in the results like every other value."""

from __future__ import annotations

from constructions.quantities import Measured

from ..registry import Analysis


def _found(study, by: str) -> float:
    from constructions.forces.inverse import load_for_torque
    s = study.scene
    return load_for_torque(s.mechanism, s.angle, s.omega, s.alpha, s.effects,
                           guess=study.get("position").positions, by=by)


def _by_equilibrium(study) -> float:
    """The load's magnitude at which the equilibrium system of all links needs the given torque."""
    return _found(study, "equilibrium")


def _by_virtual_work(study) -> float:
    """The same magnitude by the power balance: the independent check of :func:`_by_equilibrium`."""
    return _found(study, "virtual work")


LOAD_ANALYSES = {
    "load for torque": Analysis("load for torque", ("position",), _by_equilibrium, label="load from the torque"),
    "load check": Analysis("load check", ("position",), _by_virtual_work, label="load by virtual work"),
}


def _balance(study):
    e = getattr(study.scene, "effects", None)
    return e.balance if e is not None and study.asked("forces") else None


def found_load_rows(study, analysis: str) -> list[Measured]:
    """The found load as a result row (its force along the given direction), from ``analysis``; none when
    the scene gives every load."""
    b = _balance(study)
    if b is None:
        return []
    unit = next(ld.force for ld in study.scene.effects.loads if ld.name == b.load)
    return [Measured(b.load, "force", unit * study.get(analysis))]


def found_load_note(study) -> list[str]:
    """The sentence saying what was given and what found, for the notes."""
    b = _balance(study)
    if b is None:
        return []
    s = study.scene
    u, n = s.units, s.mechanism.crank
    f = study.get("load for torque")
    sense = "CCW" if b.torque > 0 else "CW"
    return [f"{b.load} is the unknown: the load the driving torque T_{n} = {u.format('torque', abs(b.torque))} "
            f"{sense} holds, along its given line, is {u.format('force', abs(f))}"
            + (" (against the direction given)" if f < 0 else "")
            + "; its first column from the equilibrium of all links, its second by virtual work, and the force "
              "polygons drawn with it return the given torque."]
