"""What the dyad-chain vector loop returns: every joint's and point's motion and every link's rates
over a set of crank angles, as read-only arrays, and one angle of it as plain floats."""

from __future__ import annotations

from dataclasses import dataclass, field
from types import MappingProxyType
from typing import Mapping

import numpy as np

__all__ = ["KINDS", "VECTORS", "ChainPoint", "ChainState", "chain_state", "readonly"]


def readonly(a: np.ndarray) -> np.ndarray:
    a.flags.writeable = False
    return a


@dataclass(frozen=True)
class ChainPoint:
    """One crank angle of a :class:`ChainState`, as plain floats (no arrays, no Vec)."""

    positions: Mapping[str, tuple[float, float]]
    velocities: Mapping[str, tuple[float, float]]
    angular: Mapping[int, float]
    conditions: Mapping[str, float]
    assembles: bool
    accelerations: Mapping[str, tuple[float, float]] = field(default_factory=lambda: MappingProxyType({}))
    angular_acceleration: Mapping[int, float] = field(default_factory=lambda: MappingProxyType({}))


@dataclass(frozen=True, eq=False)
class ChainState:
    """Positions, velocities, accelerations and link angular velocities and accelerations of a dyad
    chain over a set of crank angles.

    Attributes
    ----------
    positions, velocities, accelerations : mapping of name -> (x array, y array)
        Every fixed pivot, joint and point fixed to a link (m, m/s, m/s^2).
    angular : mapping of link number -> array
        Every link's angular velocity (rad/s, CCW positive); the crank's is the input omega, slider
        blocks translate (0).
    angular_acceleration : mapping of link number -> array
        Every link's angular acceleration (rad/s^2, CCW positive); the crank's is the input alpha,
        slider blocks 0.
    conditions : mapping of joint -> array
        Sine of the angle between the velocity trial lines of each joint found by a dyad (0 at a
        toggle or lock, where its velocity is NaN).
    assembles : bool array
        True where every dyad closes.
    order : tuple of str
        The joints in the order they were solved, then the points fixed to links.
    """

    positions: Mapping[str, tuple[np.ndarray, np.ndarray]]
    velocities: Mapping[str, tuple[np.ndarray, np.ndarray]]
    angular: Mapping[int, np.ndarray]
    conditions: Mapping[str, np.ndarray]
    assembles: np.ndarray
    order: tuple[str, ...] = field(default=())
    accelerations: Mapping[str, tuple[np.ndarray, np.ndarray]] = field(
        default_factory=lambda: MappingProxyType({}))
    angular_acceleration: Mapping[int, np.ndarray] = field(default_factory=lambda: MappingProxyType({}))

    @property
    def shape(self) -> tuple[int, ...]:
        return self.assembles.shape

    def at(self, index=()) -> ChainPoint:
        """Element ``index`` (an int or a tuple; ``()`` for a scalar crank angle) as plain floats."""
        def xy(p):
            return float(p[0][index]), float(p[1][index])
        return ChainPoint(
            positions=MappingProxyType({n: xy(p) for n, p in self.positions.items()}),
            velocities=MappingProxyType({n: xy(v) for n, v in self.velocities.items()}),
            angular=MappingProxyType({n: float(w[index]) for n, w in self.angular.items()}),
            conditions=MappingProxyType({n: float(c[index]) for n, c in self.conditions.items()}),
            assembles=bool(self.assembles[index]),
            accelerations=MappingProxyType({n: xy(a) for n, a in self.accelerations.items()}),
            angular_acceleration=MappingProxyType(
                {n: float(a[index]) for n, a in self.angular_acceleration.items()}))


#: The kinds of arrays of a :class:`ChainState`: the vector ones are (x, y) pairs.
VECTORS = ("positions", "velocities", "accelerations")
KINDS = VECTORS + ("angular", "angular_acceleration", "conditions")


def chain_state(arrays: Mapping[str, Mapping], assembles: np.ndarray, order: tuple[str, ...],
                shape: tuple[int, ...]) -> ChainState:
    """The :class:`ChainState` of flat, writable arrays (``arrays[kind][name]``, an (x, y) pair for the
    :data:`VECTORS` kinds), each reshaped to ``shape`` and made read-only; links in number order."""
    def freeze(a: np.ndarray) -> np.ndarray:
        return readonly(a.reshape(shape))

    def vectors(kind):
        return MappingProxyType({name: (freeze(x), freeze(y)) for name, (x, y) in arrays[kind].items()})

    def scalars(kind, key=None):
        items = arrays[kind].items() if key is None else sorted(arrays[kind].items(), key=key)
        return MappingProxyType({name: freeze(v) for name, v in items})

    return ChainState(
        positions=vectors("positions"),
        velocities=vectors("velocities"),
        angular=scalars("angular", key=lambda kv: kv[0]),
        conditions=scalars("conditions"),
        assembles=readonly(assembles.reshape(shape)),
        order=order,
        accelerations=vectors("accelerations"),
        angular_acceleration=scalars("angular_acceleration", key=lambda kv: kv[0]))
