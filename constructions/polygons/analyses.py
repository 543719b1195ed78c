"""What the vector polygons measure: the velocity and acceleration analyses at one position, the values
read off them as :class:`~constructions.quantities.Measured` and the scales small values are judged
against.  The polygons themselves are drawn in :mod:`.velocity` and :mod:`.acceleration`.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Mapping

from ..geometry import Vec
from ..mechanisms.model import Mechanism
from ..mechanisms.pose import Pose
from ..quantities import Measured
from ..record import Construction
from ..tolerance import CONDITION_FLOOR
from .common import component_name, rounding_estimate


@dataclass(frozen=True)
class VelocityAnalysis:
    """The velocity polygon at one position and the values measured off it (SI, CCW positive).

    ``velocities`` maps every joint and point to its absolute velocity (fixed pivots: zero);
    ``relative[(J, P)]`` is V_JP, the side p->j of the polygon; ``angular`` maps link numbers to their
    angular velocity (slider blocks translate: 0); ``conditions`` maps each joint found by trial lines
    to the sine of the angle at which they crossed; ``warnings`` says what the reader must know;
    ``scale`` is the scale fixed by the caller (SI units per paper mm) or None (the drawing chooses).
    """

    construction: Construction
    pose: Pose
    velocities: Mapping[str, Vec]
    relative: Mapping[tuple[str, str], Vec]
    angular: Mapping[int, float]
    conditions: Mapping[str, float]
    scale: float | None
    warnings: tuple[str, ...]
    omega: float = 0.0

    @property
    def at_rest(self) -> bool:
        """omega = 0: nothing moves, nothing is drawn and nothing is measured."""
        return self.omega == 0.0

    @property
    def worst_condition(self) -> float:
        return min(self.conditions.values(), default=1.0)

    @property
    def relative_error_estimate(self) -> float:
        """Rough relative error of the measured values from rounding, growing as 1/sine^2 near
        singular positions."""
        return rounding_estimate(self.worst_condition)

    def scales(self) -> dict[str, float]:
        """The input's scale of each kind, against which small values are judged: |V_B| and |omega_1|."""
        if self.at_rest:
            return {}
        return {"velocity": max(v.norm() for v in self.velocities.values()),
                "angular velocity": abs(self.omega)}

    def measured(self, m: Mechanism) -> list[Measured]:
        """Absolute velocities of the moving joints and points, relative velocities between moving
        joints, and the angular velocities of the links that are neither the crank nor a slider block (none
        at rest: every one is zero by the scene's own data, not by construction)."""
        if self.at_rest:
            return []
        c = self.worst_condition
        out = [Measured(f"V_{n}", "velocity", v, c) for n, v in self.velocities.items() if n not in m.ground]
        out += [Measured(f"V_{j}{p}", "velocity", v, c) for (j, p), v in self.relative.items()
                if p not in m.ground]
        skip = {m.crank} | {s.number for s in m.slides}
        out += [Measured(f"omega_{n}", "angular velocity", w, c) for n, w in sorted(self.angular.items())
                if n not in skip]
        return out


@dataclass(frozen=True)
class AccelerationAnalysis:
    """The acceleration polygon at one position and the values measured off it (SI, CCW positive).

    ``accelerations`` maps every joint and point to its absolute acceleration (fixed pivots: zero);
    ``normal[(J, P)]`` and ``tangential[(J, P)]`` are the components A_JP^n and A_JP^t of the
    acceleration of J relative to P on the link joining them (P may be a fixed pivot: then they are
    A_J^n and A_J^t); ``angular`` maps link numbers to their angular acceleration (slider blocks: 0);
    ``conditions`` maps each joint found by trial lines to the sine of their crossing; ``scale`` is the
    scale fixed by the caller or None (the drawing chooses).
    """

    construction: Construction
    velocity: VelocityAnalysis
    accelerations: Mapping[str, Vec]
    normal: Mapping[tuple[str, str], Vec]
    tangential: Mapping[tuple[str, str], Vec]
    angular: Mapping[int, float]
    conditions: Mapping[str, float]
    scale: float | None
    warnings: tuple[str, ...]
    alpha: float = 0.0
    coriolis: Mapping[str, Vec] = field(default_factory=dict)   # name (A_A3A^c) -> 2 omega x V_rel
    sliding: Mapping[str, Vec] = field(default_factory=dict)    # name (A_A3A^s) -> along the slot

    @property
    def worst_condition(self) -> float:
        return min(list(self.conditions.values()) + [self.velocity.worst_condition])

    @property
    def relative_error_estimate(self) -> float:
        return rounding_estimate(self.worst_condition) / max(self.worst_condition, CONDITION_FLOOR)

    def scales(self) -> dict[str, float]:
        """The input's scale of each kind: |A_B| for accelerations and max(|alpha_1|, omega_k^2) for angular
        accelerations (alpha and omega^2 share their unit and both set the polygon's size)."""
        w2 = max(w * w for w in self.velocity.angular.values())
        return {"acceleration": max(a.norm() for a in self.accelerations.values()),
                "angular acceleration": max(abs(self.alpha), w2)}

    def measured(self, m: Mechanism) -> list[Measured]:
        """Absolute accelerations of the moving joints and points, the normal and tangential components
        of every dyad (named as in the notes: A_CB^n, A_CB^t; A_C^n, A_C^t about a fixed pivot) and the
        angular accelerations of the links that are neither the crank nor a slider block."""
        c = self.worst_condition
        out = [Measured(f"A_{n}", "acceleration", a, c) for n, a in self.accelerations.items()
               if n not in m.ground]
        rest = self.velocity.at_rest          # no normal or Coriolis parts: zero by the data, not measured
        for comps, sup in ((self.normal, "n"), (self.tangential, "t")):
            if not (rest and sup == "n"):
                out += [Measured(component_name(j, p, sup, m), "acceleration", a, c) for (j, p), a in comps.items()]
        for comps in ((self.sliding,) if rest else (self.coriolis, self.sliding)):
            out += [Measured(name, "acceleration", a, c) for name, a in comps.items()]
        skip = {m.crank} | {s.number for s in m.slides}
        out += [Measured(f"alpha_{n}", "angular acceleration", al, c) for n, al in sorted(self.angular.items())
                if n not in skip]
        return out
