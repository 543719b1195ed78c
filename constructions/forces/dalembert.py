"""D'Alembert's inertia forces and couples of the bodies with mass, as the results list them: the inertia
force F_I = -m a_G at the centre of gravity, the inertia couple C_I = -I_G alpha (CCW positive), and the
offset h = |C_I| / |F_I| of the single force that stands for both -- the same force moved square to itself
so that its moment about G is the couple.  Pure functions of the accelerations handed in: the force
polygons pass the ones read off the acceleration polygon, the equilibrium check the analytic ones.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Callable, Mapping

from ..geometry import Vec
from ..mechanisms.topology import Contact, SlotPin
from ..quantities import Measured
from .bodies import force_name
from .effects import Effects


@dataclass(frozen=True, slots=True)
class InertiaLoad:
    """The inertia force ``force`` (-m a_G, N) of body ``body`` at its centre of gravity ``centre`` and its
    inertia couple ``couple`` (-I_G alpha, N m, CCW positive)."""

    body: int
    centre: str
    mass: float
    force: Vec
    couple: float
    turns: bool = True                 # the body has a moment of inertia (a point mass has no couple)

    @property
    def acting(self) -> bool:
        """True when there is an inertia force (a subnormal force squares to 0: none)."""
        return self.force.dot(self.force) > 0

    @property
    def offset(self) -> float:
        """h = |C_I| / |F_I|: how far the resultant's line stands from G (0 without an inertia force)."""
        return abs(self.couple) / self.force.norm() if self.acting else 0.0

    def shift(self) -> Vec:
        """The vector d from G to the resultant's line, square to F_I, with d x F_I = C_I (zero without an
        inertia force: then the couple stands alone)."""
        if not self.acting:
            return Vec(0.0, 0.0)
        return self.force.perp() * (-self.couple / self.force.dot(self.force))


def inertia_loads(effects: Effects, accelerations: Mapping[str, Vec],
                  angular: Callable[[int], float]) -> tuple[InertiaLoad, ...]:
    """The inertia force and couple of every body with mass, from the accelerations of the centres of
    gravity and ``angular(body)``, each body's angular acceleration (CCW positive)."""
    return tuple(InertiaLoad(ms.body, ms.centre, ms.mass, accelerations[ms.centre] * (-ms.mass),
                             -ms.inertia * angular(ms.body), ms.inertia > 0)
                 for ms in effects.masses)


def inertia_name(body: int) -> str:
    """F_I3: the inertia force of body 3 (C_I3 its couple, h_I3 the offset of its line)."""
    return f"F_I{body}"


def inertia_rows(loads: tuple[InertiaLoad, ...], condition: float = 1.0) -> list[Measured]:
    """The rows of the results for the inertia loads: F_I<n> = -m a_G for every body with mass, and for a
    body with a moment of inertia its couple C_I<n> = -I_G alpha and, where there is an inertia force, the
    offset h_I<n> of the single force that stands for both."""
    out = []
    for il in loads:
        out.append(Measured(inertia_name(il.body), "force", il.force, condition))
        if il.turns:
            out.append(Measured(f"C_I{il.body}", "torque", il.couple, condition))
            if il.acting:
                out.append(Measured(f"h_I{il.body}", "length", il.offset, condition))
    return out


def friction_rows(friction: Mapping[Contact | SlotPin, Vec], condition: float = 1.0) -> list[Measured]:
    """The friction part of each guide's force on its block (or on the pin in its slot), along the guide:
    F_03^f beside the total F_03."""
    return [Measured(friction_name(c), "force", f, condition) for c, f in friction.items()]


def off_sheet(name: str) -> bool:
    """True for the rows :func:`inertia_rows` and :func:`friction_rows` write: the sheet's results table
    leaves them out (its steps state the inertia forces; ``solve``'s table, CSV and JSON list them all)."""
    return name.startswith(("F_I", "C_I", "h_I")) or name.endswith("^f")


def friction_name(c: Contact | SlotPin) -> str:
    """F_03^f: the friction force of the guide 0 on the block 3 (the part of F_03 along the guide)."""
    return force_name(c.guide, c.block if isinstance(c, Contact) else c.carrier) + "^f"
