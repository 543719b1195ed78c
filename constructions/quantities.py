"""What every method returns: quantities measured off its construction.

A :class:`Measured` is one value read off a drawing -- a vector (a side of a polygon) or a scalar (an
angular velocity from a side divided by a link length) -- with its quantity kind and the condition of
the crossing it was read at.  The check (:mod:`constructions.check`) compares any list of them with the
analytic values of the same names, whatever the method; the drafting layer writes them in the scene's
units.  Names follow the notes: V_C, V_CB, omega_2, A_C, A_CB^t, alpha_2.
"""

from __future__ import annotations

from dataclasses import dataclass

from .geometry import Vec

KINDS = ("length", "angle", "velocity", "angular velocity", "acceleration", "angular acceleration",
         "force", "torque", "ratio")
"""The kinds of a measured quantity; a "ratio" is a plain number (a gear pair's contact ratio)."""


@dataclass(frozen=True, slots=True)
class Measured:
    """One quantity read off a construction (SI; vectors as :class:`Vec`, rates CCW positive).

    ``condition`` is the sine of the worst trial-line crossing the value depends on (1 when it was
    drawn directly); near 0 the value is sensitive to the drawing and the check widens its tolerance.
    ``diagram`` is the key of the diagram it is read off (:attr:`~constructions.entities.Diagram.key`), where
    a construction draws several of its kind at different scales; "" when it need not say.
    """

    name: str
    kind: str
    value: Vec | float
    condition: float = 1.0
    diagram: str = ""

    def __post_init__(self) -> None:
        if self.kind not in KINDS:
            raise ValueError(f"{self.name}: {self.kind!r} is not a quantity kind ({', '.join(KINDS)})")

    @property
    def magnitude(self) -> float:
        return self.value.norm() if isinstance(self.value, Vec) else abs(self.value)


def key(name: str) -> str:
    """A spelling-tolerant key for a quantity name: "V_CB", "vcb" and "V CB" match; "A_CB^t" -> "acbt"."""
    return name.replace("_", "").replace(" ", "").replace("^", "").replace("\u03c9", "omega") \
        .replace("\u03b1", "alpha").lower()
