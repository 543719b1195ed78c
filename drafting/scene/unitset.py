"""The units a scene is written and answered in, as one object that travels with the scene.

Every part of a sheet -- captions, results table, scale bars, title block -- asks this object for the
unit of a quantity kind, so a scene in m/min gets m/min everywhere (never a joined string to re-parse).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, fields
from typing import Any

from .keys import Key, KeyTable
from .units import DEFAULT_UNITS, format_value, from_si, unit_symbol

# scene key (under [units]) -> quantity kind
KEYS: dict[str, str] = {
    "length": "length",
    "velocity": "velocity",
    "acceleration": "acceleration",
    "angular_velocity": "angular velocity",
    "angular_acceleration": "angular acceleration",
    "angle": "angle",
    "force": "force",
    "torque": "torque",
    "mass": "mass",
    "moment_of_inertia": "moment of inertia",
    "stiffness": "stiffness",
}


def _default(kind: str, fallback: str) -> str:
    return DEFAULT_UNITS.get(kind, fallback)


_EXAMPLES = {"angular_velocity": " (or \"rpm\")", "length": " (or \"m\", \"in\")"}

UNITS = KeyTable("units", "the unit of each kind of quantity: plain numbers are read in it and results "
                          "printed in it (pint spellings)", tuple(
    Key(key, "unit", _default(kind, ""), f"the unit of every {kind}{_EXAMPLES.get(key, '')}")
    for key, kind in KEYS.items()))
"""``[units]``: one key per quantity kind of :data:`KEYS`."""


@dataclass(frozen=True)
class Units:
    """The unit of each quantity kind (pint spellings, e.g. "mm/s", "rpm", "deg")."""

    length: str = _default("length", "mm")
    velocity: str = _default("velocity", "mm/s")
    acceleration: str = _default("acceleration", "mm/s^2")
    angular_velocity: str = _default("angular velocity", "rad/s")
    angular_acceleration: str = _default("angular acceleration", "rad/s^2")
    angle: str = _default("angle", "deg")
    force: str = _default("force", "N")
    torque: str = _default("torque", "N m")
    mass: str = _default("mass", "kg")
    moment_of_inertia: str = _default("moment of inertia", "kg m^2")
    stiffness: str = _default("stiffness", "N/mm")

    def of(self, kind: str) -> str:
        """The unit of quantity ``kind`` ("length", "angular velocity", ...); a ratio has none ("")."""
        if kind == "ratio":
            return ""
        for key, k in KEYS.items():
            if k == kind:
                return getattr(self, key)
        raise KeyError(f"no unit for the quantity kind {kind!r}")

    def symbol(self, kind: str) -> str:
        """How the unit of ``kind`` is printed: mm/s, mm/s², deg."""
        return unit_symbol(self.of(kind)).replace("^2", "\u00b2").replace("**2", "\u00b2")

    def format(self, kind: str, value: float) -> str:
        """An SI value in this scene's unit of ``kind`` (the engine's Formatter signature)."""
        return format_value(value, kind, self.of(kind)).replace("^2", "\u00b2")

    def convert(self, kind: str, value: float) -> float:
        """An SI value as a number in this scene's unit of ``kind``."""
        return from_si(value, kind, self.of(kind))

    def as_dict(self) -> dict[str, str]:
        return {f.name: getattr(self, f.name) for f in fields(self)}

    def summary(self, kinds=("length", "velocity", "angular velocity")) -> str:
        """The units a title block names, e.g. "mm, mm/s, rad/s"."""
        return ", ".join(dict.fromkeys(self.symbol(k) for k in kinds))

    def vector_json(self, v, kind: str) -> dict[str, float]:
        """A vector (SI) as JSON in this unit of ``kind``: components, magnitude and direction."""
        return {"x": self.convert(kind, v.x), "y": self.convert(kind, v.y),
                "magnitude": self.convert(kind, v.norm()), "angle_deg": direction_deg(v)}

    def rate_json(self, w: float, kind: str) -> dict[str, Any]:
        """An angular rate (SI, CCW positive) as JSON: value in this unit and its sense."""
        return {"value": self.convert(kind, w), "sense": "ccw" if w > 0 else "cw" if w < 0 else "none"}


def direction_deg(v) -> float:
    """Direction CCW from +x in [0, 360), rounded so that 180 never prints as -180 or 360."""
    if v.norm() == 0:
        return 0.0
    d = round(math.degrees(v.angle()), 9) % 360.0
    return 0.0 if d >= 360.0 else d
