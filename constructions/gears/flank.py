"""A tooth's flank as drawn: how many points draw an involute flank, and the flank a rack cutter leaves
(what :mod:`.generation` finds and :meth:`.tooth.Gear.tooth_outline` draws).
"""

from __future__ import annotations

from dataclasses import dataclass

FLANK_POINTS = 24
"""Points per involute flank drawn (benchmarks/involute_flank.py: 24 points leave a chord error of 2.7 um
on a module-5 tooth, ~5 um on paper at 2:1, 1/50 of a thin line; 16 points 6.3 um, 32 points 1.5 um)."""


@dataclass(frozen=True)
class CutFlank:
    """One flank as the rack cutter leaves it: the involute from ``involute_from`` to the tip, then the
    ``fillet`` (radius, angle from the tooth's centre line) from the involute's end down to the root
    circle.  ``undercut`` when the fillet cuts into the involute (``involute_from`` is then R_X, else
    the form radius R_L, where the fillet leaves the involute tangentially)."""

    undercut: bool
    involute_from: float
    fillet: tuple[tuple[float, float], ...]

    @property
    def severed(self) -> bool:
        """The fillet crosses the tooth's centre line: the cutter cuts through the tooth at its root
        (a gear of so few teeth cannot be generated with this cutter)."""
        return any(a <= 0.0 for _, a in self.fillet)
