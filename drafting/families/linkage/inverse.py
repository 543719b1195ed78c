"""The inverse position problem on a linkage sheet: every crank angle that puts the slider at the scene's
``slider_at`` (or a link at its ``output_angle``), as results -- theta_1 (1), theta_1 (2) ... read off the
construction (:func:`constructions.mechanisms.inverse_position.inverse_position`) beside the closed form
of a plain slider-crank or four-bar (:func:`constructions.closed_forms.closed_form_inverse`) -- and as a
note saying which of them the sheet draws."""

from __future__ import annotations

from constructions.closed_forms import closed_form_inverse
from constructions.quantities import Measured


def solution_name(crank: int, i: int) -> str:
    """The results' name of the i-th crank angle (1 = the first from 0 deg CCW): theta_1 (2)."""
    return f"theta_{crank} ({i})"


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
        line += (f" The sheet draws solution {scene.solution} ({scene.units.format('angle', scene.angle)}); "
                 f"[input] solution = N draws another.")
    return [line]
