"""A study's results as values that know their unit: ``study.results["V_C"].graphical.to("mm/s")``.

Each result (:class:`Result`) is a compared quantity (:class:`~constructions.check.Comparison`) whose
``graphical`` and ``analytic`` values are still the SI numbers the engine works in -- a float, or a
:class:`~constructions.geometry.Vec` for a vector -- so arithmetic, ``pytest.approx`` and ``.norm()`` work
as before; besides they carry their quantity kind and the scene's units:

    v = study.results["V_C"].graphical      # Vector: v.x, v.y in m/s, v.norm() ...
    v.to("mm/s")                            # <Quantity(568.5, 'millimeter / second')>: the magnitude
    v.in_scene_units()                      # the same in the unit the scene's [units] give velocities
    v.direction_deg                         # 180.0: CCW from +x, as the table prints it
    study.results["omega_3"].graphical.to("rpm")   # a rate keeps its sign: CCW positive

``to`` and ``in_scene_units`` give pint Quantities (``.magnitude``, ``.units``, ``f"{q:~P}"``); a unit of
another kind ("mm/s" for an angular velocity) is a :class:`~drafting.scene.units.UnitError` naming it.
"""

from __future__ import annotations

from typing import Any

from constructions.check import Comparison
from constructions.geometry import Vec

from ..scene.units import KINDS, quantity
from ..scene.unitset import Units, direction_deg
from .table import scene_unit


class _Valued:
    """What a scalar and a vector value share: their kind, SI unit and the scene's units."""

    kind: str
    units: Units

    @property
    def unit(self) -> str:
        """The SI unit the value is in ("m/s", "rad/s", "N m"; "" for a ratio)."""
        return KINDS[self.kind][0]

    def _number(self) -> float:
        raise NotImplementedError

    def to(self, unit: str) -> Any:
        """The value as a pint Quantity in ``unit`` (a vector's magnitude; a rate signed, CCW positive)."""
        return quantity(self._number(), self.kind, unit)

    def in_scene_units(self) -> Any:
        """The value as a pint Quantity in the unit the scene's ``[units]`` give its kind."""
        return self.to(scene_unit(self.units, self.kind))


class Scalar(_Valued, float):
    """An SI float (a length, a rate CCW positive, a torque, a ratio) that knows its kind and the scene's
    units."""

    def __new__(cls, value: float, kind: str, units: Units) -> "Scalar":
        self = super().__new__(cls, value)
        self.kind, self.units = kind, units
        return self

    def _number(self) -> float:
        return float(self)

    def __reduce__(self):
        return (Scalar, (float(self), self.kind, self.units))


class Vector(_Valued, Vec):
    """An SI vector (a velocity, an acceleration, a force) that knows its kind and the scene's units;
    ``to`` gives its magnitude, :attr:`direction_deg` its direction.  Equal to a plain Vec of the same
    components."""

    def __init__(self, v: Vec, kind: str, units: Units) -> None:
        object.__setattr__(self, "x", v.x)
        object.__setattr__(self, "y", v.y)
        object.__setattr__(self, "kind", kind)
        object.__setattr__(self, "units", units)

    def _number(self) -> float:
        return self.norm()

    @property
    def direction_deg(self) -> float:
        """The direction in degrees CCW from +x, in [0, 360)."""
        return direction_deg(self)

    def __eq__(self, other: object) -> bool:
        if isinstance(other, Vec):
            return (self.x, self.y) == (other.x, other.y)
        return NotImplemented

    __hash__ = Vec.__hash__

    def __repr__(self) -> str:
        return f"Vector(x={self.x!r}, y={self.y!r}, kind={self.kind!r})"

    def __reduce__(self):
        return (Vector, (Vec(self.x, self.y), self.kind, self.units))


def valued(value: Vec | float | None, kind: str, units: Units) -> Scalar | Vector | None:
    """``value`` (SI) with its kind and the scene's units; None stays None."""
    if value is None:
        return None
    if isinstance(value, Vec):
        return Vector(value, kind, units)
    return Scalar(value, kind, units)


class Result:
    """One result of a study: the :class:`Comparison` (``name``, ``kind``, ``difference``, ``relative``,
    ``tolerance``, ``agrees``, ``diagram``) with ``graphical``, ``analytic`` and ``difference`` as values
    that convert (:class:`Scalar`, :class:`Vector`)."""

    __slots__ = ("comparison", "units")

    def __init__(self, comparison: Comparison, units: Units) -> None:
        self.comparison, self.units = comparison, units

    def __getattr__(self, name: str) -> Any:
        if name == "comparison":          # not yet set (a copy being made): no recursion
            raise AttributeError(name)
        return getattr(self.comparison, name)

    @property
    def graphical(self) -> Scalar | Vector:
        """The value read off the construction (SI; ``.to(unit)``, ``.in_scene_units()``)."""
        return valued(self.comparison.graphical, self.comparison.kind, self.units)

    @property
    def analytic(self) -> Scalar | Vector | None:
        """The closed-form value (SI), or None where the scene has no analytic model of it."""
        return valued(self.comparison.analytic, self.comparison.kind, self.units)

    @property
    def difference(self) -> Scalar | None:
        """|graphical - analytic| (SI), or None."""
        return valued(self.comparison.difference, self.comparison.kind, self.units)

    @property
    def unit(self) -> str:
        """The scene's unit of this result ("mm/s")."""
        return scene_unit(self.units, self.comparison.kind)

    def __repr__(self) -> str:
        g = self.graphical.in_scene_units()
        return f"<Result {self.comparison.name}: {g:.6g~P} graphical, agrees={self.comparison.agrees}>"
