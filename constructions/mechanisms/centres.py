"""An instant centre: the point two bodies turn about relative to each other, and its name.

Bodies are numbered as the notes number them (the frame, the links, the slider blocks); a centre is
named by its pair of bodies, I_13.  A centre is a homogeneous point, so one at infinity (a block sliding
on a straight guide) is no special case.  :mod:`.instant_centres` finds them, :mod:`.centre_diagram`
draws them.
"""

from __future__ import annotations

from dataclasses import dataclass

from ..entities import Diagram
from ..geometry import Vec

DIAGRAM = Diagram("instant centres")
CIRCLE = DIAGRAM
"""The circle diagram is drawn beside the centres, in their diagram."""
FAR = 2.5
"""Centres farther than this many mechanism sizes from its middle are named, not drawn."""

Pair = tuple[int, int]


def pair(i: int, j: int) -> Pair:
    return (i, j) if i < j else (j, i)


def centre_name(p: Pair) -> str:
    """I_13 (I_1,12 when a number has two digits)."""
    sep = "," if p[0] >= 10 or p[1] >= 10 else ""
    return f"I_{p[0]}{sep}{p[1]}"


@dataclass(frozen=True)
class Centre:
    """The instant centre of ``bodies``: ``point`` homogeneous (w = 1 finite, w = 0 at infinity), ``how``
    it was found, the two ``lines`` (pairs of centres) Kennedy crossed, and the sine they crossed at."""

    bodies: Pair
    point: tuple[float, float, float]
    how: str
    lines: tuple[tuple[Pair, Pair], ...] = ()
    condition: float = 1.0

    @property
    def finite(self) -> bool:
        return self.point[2] != 0.0

    @property
    def at(self) -> Vec:
        x, y, w = self.point
        return Vec(x / w, y / w)

    @property
    def direction(self) -> Vec:
        """The direction of a centre at infinity."""
        return Vec(self.point[0], self.point[1]).unit()

