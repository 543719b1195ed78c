"""Names of the forces between bodies and of the driving torque (the bodies themselves and their joints:
:mod:`constructions.bodies`)."""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from ..mechanisms.model import Mechanism


def force_name(by: int, on: int) -> str:
    """F_ij, the force of body i on body j (F_10,12 when a number has two digits)."""
    sep = "," if by >= 10 or on >= 10 else ""
    return f"F_{by}{sep}{on}"


def torque_name(m: Mechanism) -> str:
    """The driving torque on the crank: T_2."""
    return f"T_{m.crank}"
