"""The inverse position problem on a linkage sheet: every crank angle that puts the slider at the scene's
``slider_at`` (or a link at its ``output_angle``), as results -- theta_1, theta_1', theta_1'' ... read off the
construction (:func:`constructions.mechanisms.inverse_position.inverse_position`) beside the closed form
of a plain slider-crank or four-bar (:func:`constructions.closed_forms.closed_form_inverse`) -- and as a
note saying which of them the sheet draws; and a driving slider's crank rates, read off the polygons,
beside the analytic solution's."""

from __future__ import annotations

from constructions.check import NotModelled, analytic_solution
from constructions.closed_forms import closed_form_inverse
from constructions.quantities import Measured


def solution_name(crank: int, i: int) -> str:
    """The results' name of the i-th crank angle (1 = the first from 0 deg CCW), primed as the notes
    prime a second position: theta_1, theta_1', theta_1''."""
    return f"theta_{crank}" + "'" * (i - 1)


def inverse_measured(scene) -> list[Measured]:
    inv = getattr(scene, "inverse", None)
    if inv is None:
        return []
    return [Measured(solution_name(scene.mechanism.crank, i), "angle", t) for i, t in enumerate(inv.solutions, 1)]


def inverse_analytic(scene) -> dict[str, float]:
    """The closed form's crank angles under the same names, when the closed form models the target and
    finds as many (else nothing: the comparison then says there is no analytic value)."""
    inv = getattr(scene, "inverse", None)
    if inv is None:
        return {}
    exact = closed_form_inverse(scene.mechanism, inv.target)
    if exact is None or len(exact) != len(inv.solutions):
        return {}
    return {solution_name(scene.mechanism.crank, i): t for i, t in enumerate(exact, 1)}


def inverse_notes(scene) -> list[str]:
    inv = getattr(scene, "inverse", None)
    if inv is None:
        return []
    line = inv.describe(scene.units.format)
    if len(inv.solutions) > 1:
        line += f" The sheet draws solution {scene.solution} ({scene.units.format('angle', scene.angle)})."
        # (which one is the scene's [input] solution: the README and `drafting keys` say so, not the handout)
    return [line]


def driven_measured(scene) -> list[Measured]:
    """A driving slider's crank rates, read off the polygons (graphical)."""
    dc = getattr(scene, "driven", None)
    if dc is None:
        return []
    n = scene.mechanism.crank
    return [Measured(f"omega_{n}", "angular velocity", dc.omega),
            Measured(f"alpha_{n}", "angular acceleration", dc.alpha)]


def driven_analytic(scene, guess) -> dict[str, float]:
    """The same crank rates from the analytic solution (vector loops or constraint equations): its speed of
    the block along its line at 1 rad/s, and its acceleration at alpha = 0."""
    dc = getattr(scene, "driven", None)
    if dc is None:
        return {}
    from constructions.polygons.driving_slider import along_line
    m, s = scene.mechanism, scene.mechanism.blocks()[dc.block]
    try:
        unit = analytic_solution(m, scene.angle, 1.0, 0.0, accelerations=False, guess=guess)
        if unit is None:
            return {}
        k = along_line(m, s, unit.positions, unit.velocities, unit.angular)[0]
        omega = dc.speed / k
        free = analytic_solution(m, scene.angle, omega, 0.0, guess=guess)
    except NotModelled:
        return {}
    a0 = along_line(m, s, free.positions, free.velocities, free.angular, free.accelerations,
                    free.angular_acceleration)[1]
    return {f"omega_{m.crank}": omega, f"alpha_{m.crank}": (dc.acceleration - a0) / k}


def driven_notes(scene) -> list[str]:
    dc = getattr(scene, "driven", None)
    if dc is None:
        return []
    f, n = scene.units.format, scene.mechanism.crank
    return [f"Block {dc.block} drives the mechanism at {f('velocity', dc.speed)} and {f('acceleration', dc.acceleration)} "
            f"along {scene.inverse.along}: \u03c9_{n} = {f('angular velocity', dc.omega)} and "
            f"\u03b1_{n} = {f('angular acceleration', dc.alpha)} follow (CCW positive)."]
