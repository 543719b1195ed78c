"""The model -> paper transform: one explicit mapping from model units (SI) to paper millimetres.

It lives apart from the layout so that the lowest drawing layers (drawers, viewports, labels) can use it
without importing the layout upward.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from constructions.geometry import Vec

__all__ = ["Transform"]


@dataclass(frozen=True, slots=True)
class Transform:
    """Model -> paper: ``(ox + k x, oy - k y)``; ``k`` is paper mm per model unit.  The y flip is
    applied point by point, never to a group, so lettering is never mirrored."""

    k: float
    ox: float = 0.0
    oy: float = 0.0

    def __call__(self, v: Vec) -> tuple[float, float]:
        return (self.ox + self.k * v.x, self.oy - self.k * v.y)

    def many(self, vs) -> list[tuple[float, float]]:
        """Each of ``vs`` on paper, as calling the transform on each does (the same arithmetic: a curve of
        thousands of points is mapped in one pass)."""
        k, ox, oy = self.k, self.ox, self.oy
        return [(ox + k * v.x, oy - k * v.y) for v in vs]

    def direction(self, v: Vec) -> tuple[float, float]:
        """A model direction as a paper unit vector."""
        n = math.hypot(v.x, v.y)
        return (v.x / n, -v.y / n)

    def moved(self, dx: float, dy: float) -> "Transform":
        """The same scale with the origin moved by ``(dx, dy)`` paper mm."""
        return Transform(self.k, self.ox + dx, self.oy + dy)

    def inverse(self, x: float, y: float) -> Vec:
        """The model point drawn at paper ``(x, y)``."""
        return Vec((x - self.ox) / self.k, (self.oy - y) / self.k)
