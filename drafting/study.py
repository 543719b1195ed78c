"""A lazy study of one scene: only the analyses the scene asks for are ever built.

``Study.ran`` lists what has been computed so far ("position", "velocity", "analytic check"); the JSON
output carries it, so a test can see that a velocity-only scene built nothing for accelerations.
"""

from __future__ import annotations

import math
from functools import cached_property
from typing import Any

from constructions.check import AnalyticSolution, Comparison, analytic_solution, compare
from constructions.geometry import Vec
from constructions.linkage import Pose, assembly_plan, locate
from constructions.record import Construction
from constructions.velocity import VelocityAnalysis, velocity_polygon

from .scene import Scene
from .units import format_value, from_si, unit_symbol


POLYGON_EXTENT_MM = {"A4": 110.0, "A3": 160.0}
"""The largest a vector polygon is drawn on each paper; the 1-2-5 scale is the finest that keeps it so."""


class Study:
    def __init__(self, scene: Scene) -> None:
        self.scene = scene
        self.ran: list[str] = []

    def _mark(self, name: str) -> None:
        if name not in self.ran:
            self.ran.append(name)

    @cached_property
    def pose(self) -> Pose:
        self._mark("position")
        m = self.scene.mechanism
        return locate(m, self.scene.angle, assembly_plan(m), fmt=self.scene.units.format)

    @cached_property
    def velocity(self) -> VelocityAnalysis | None:
        if "velocity" not in self.scene.analyses:
            return None
        pose = self.pose
        self._mark("velocity")
        return velocity_polygon(self.scene.mechanism, pose, self.scene.omega, fmt=self.scene.units.format,
                                max_extent_mm=POLYGON_EXTENT_MM[self.scene.paper])

    @cached_property
    def analytic(self) -> AnalyticSolution | None:
        if self.velocity is None:
            return None
        self._mark("analytic check")
        return analytic_solution(self.scene.mechanism, self.scene.angle, self.scene.omega)

    @cached_property
    def comparisons(self) -> list[Comparison]:
        if self.velocity is None:
            return []
        rows = compare(self.scene.mechanism, self.velocity, self.analytic)
        if self.scene.find is not None:
            wanted = {_key(f) for f in self.scene.find}
            rows = [r for r in rows if _key(r.name) in wanted]
        return rows

    @property
    def construction(self) -> Construction:
        c = self.pose.construction
        if self.velocity is not None:
            c = c + self.velocity.construction
        return c

    @property
    def warnings(self) -> tuple[str, ...]:
        w = list(self.velocity.warnings) if self.velocity is not None else []
        if self.velocity is not None and self.analytic is None:
            w.append("No analytic check: the vector-loop solution does not assemble at this position.")
        return tuple(w)

    def disagreements(self) -> list[Comparison]:
        return [c for c in self.comparisons if c.agrees is False]

    # -- presentation of values in the scene's units -------------------------------------------------
    def value_text(self, c: Comparison, value: Vec | float | None) -> str:
        u = self.scene.units
        if value is None:
            return "n/a"
        if isinstance(value, Vec):
            ang = _direction_deg(value)
            return f"{format_value(value.norm(), 'velocity', u.velocity)} at {ang:.1f}\u00b0"
        sense = "CCW" if value > 0 else "CW" if value < 0 else ""
        return f"{format_value(abs(value), 'angular velocity', u.angular_velocity)} {sense}".strip()

    def difference_text(self, c: Comparison) -> str:
        if c.difference is None:
            return "n/a"
        unit = self.scene.units.velocity if c.kind == "velocity" else self.scene.units.angular_velocity
        return f"{from_si(c.difference, c.kind, unit):.1e} {unit_symbol(unit)}"

    def table(self) -> list[tuple[str, str, str, str]]:
        return [(c.name.replace("omega_", "\u03c9_"), self.value_text(c, c.graphical), self.value_text(c, c.analytic), self.difference_text(c))
                for c in self.comparisons]

    def to_json(self) -> dict[str, Any]:
        """Machine-readable results in the scene's units, and the list of analyses that ran."""
        u = self.scene.units
        out: dict[str, Any] = {"scene": str(self.scene.path), "title": self.scene.title,
                               "units": {"length": u.length, "velocity": u.velocity,
                                         "angular_velocity": u.angular_velocity, "angle": u.angle}}
        pose = self.pose
        out["position"] = {n: [from_si(p.x, "length", u.length), from_si(p.y, "length", u.length)]
                           for n, p in pose.positions.items()}
        v = self.velocity
        if v is not None:
            out["velocity"] = {f"V_{n}": _vec_json(p, u.velocity) for n, p in v.velocities.items()
                               if n not in self.scene.mechanism.ground}
            out["relative_velocity"] = {f"V_{j}{p}": _vec_json(w, u.velocity) for (j, p), w in v.relative.items()}
            out["angular_velocity"] = {
                f"omega_{n}": {"value": from_si(w, "angular velocity", u.angular_velocity),
                               "sense": "ccw" if w > 0 else "cw" if w < 0 else "none"}
                for n, w in sorted(v.angular.items())}
            out["velocity_scale"] = {"per_mm": from_si(v.scale, "velocity", u.velocity), "unit": u.velocity}
            out["check"] = {
                "model": self.analytic.model if self.analytic else None,
                "tolerance_relative": 1e-9,
                "agrees": not self.disagreements() if self.analytic else None,
                "rows": [{"quantity": c.name, "relative_difference": c.relative, "agrees": c.agrees}
                         for c in self.comparisons]}
        out["warnings"] = list(self.warnings)
        out["analyses"] = list(self.ran)
        return out


def _vec_json(v: Vec, unit: str) -> dict[str, float]:
    return {"x": from_si(v.x, "velocity", unit), "y": from_si(v.y, "velocity", unit),
            "magnitude": from_si(v.norm(), "velocity", unit),
            "angle_deg": _direction_deg(v)}


def _direction_deg(v: Vec) -> float:
    """Direction CCW from +x in [0, 360), rounded so that 180 never prints as -180 or 360."""
    if v.norm() == 0:
        return 0.0
    d = round(math.degrees(v.angle()), 9) % 360.0
    return 0.0 if d >= 360.0 else d


def _key(name: str) -> str:
    return name.replace("_", "").replace(" ", "").lower()
