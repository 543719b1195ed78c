"""The line segments of a drawing as the label placer reads them: one row per segment, and for a dense
drawing (a cam's profiles, a gear's teeth) a grid of square cells, so that a label's anchor and each of its
candidate boxes are tested against the few segments around them rather than every one.
"""

from __future__ import annotations

import math

from ..render.drawing import Pt
from ..render.paper import Rect


class Segments:
    """The line segments of a drawing, one row each: the bounding box, the start, the run (end minus
    start), whether the line is heavy and its length; and, for a dense drawing (a cam's profiles, a
    gear's teeth), a grid of square cells naming the rows whose boxes meet each cell, so that a label's
    candidate box is tested against the few segments around it rather than every one in reach."""

    __slots__ = ("rows", "_cells", "dense")

    CELL = 4.0                  # mm, the side of a grid cell
    DENSE = 240                 # a drawing of more segments than this is searched by its grid

    def __init__(self, segments) -> None:
        rows = []
        for a, b, heavy, *_ in segments:
            a0, a1, b0, b1 = float(a[0]), float(a[1]), float(b[0]), float(b[1])
            rows.append((min(a0, b0), min(a1, b1), max(a0, b0), max(a1, b1), a0, a1, b0 - a0, b1 - a1,
                         bool(heavy), math.hypot(b0 - a0, b1 - a1)))
        self.rows = rows
        self._cells = None
        self.dense = len(rows) > self.DENSE

    def around(self, p: Pt, margin: float) -> list[int]:
        """Indices, in order, of the segments whose boxes grown by ``margin`` hold ``p`` (every line
        that can leave ``p`` within a tolerance below ``margin`` / 2 is among them)."""
        x, y = p
        rows = self.rows
        pick = self._indices(x - margin, y - margin, x + margin, y + margin) if self.dense else range(len(rows))
        return [i for i in pick if rows[i][0] - margin <= x <= rows[i][2] + margin
                and rows[i][1] - margin <= y <= rows[i][3] + margin]

    def near(self, reach: Rect) -> list[tuple]:
        """The rows whose boxes meet ``reach``, in their order (every row of a dense drawing: its
        candidates are searched by :meth:`meeting`)."""
        if self.dense:
            return self.rows
        le, to, ri, bo = reach.left, reach.top, reach.right, reach.bottom
        return [r for r in self.rows if r[0] <= ri and r[2] >= le and r[1] <= bo and r[3] >= to]

    def meeting(self, le: float, to: float, ri: float, bo: float) -> list[tuple]:
        """The rows whose boxes meet the box (le, to, ri, bo), in their order (by the grid: only the rows
        of the cells it covers are tested)."""
        rows = self.rows
        return [r for r in (rows[i] for i in self._indices(le, to, ri, bo))
                if r[0] <= ri and r[2] >= le and r[1] <= bo and r[3] >= to]

    def _indices(self, le: float, to: float, ri: float, bo: float) -> list[int]:
        """In order, the rows listed in the grid's cells that the box (le, to, ri, bo) covers."""
        cells = self._cells
        if cells is None:
            cells = self._cells = self._grid()
        c = self.CELL
        found: set[int] = set()
        for gx in range(math.floor(le / c), math.floor(ri / c) + 1):
            for gy in range(math.floor(to / c), math.floor(bo / c) + 1):
                got = cells.get((gx, gy))
                if got is not None:
                    found.update(got)
        return sorted(found)

    def _grid(self) -> dict[tuple[int, int], list[int]]:
        c = self.CELL
        cells: dict[tuple[int, int], list[int]] = {}
        for i, (x0, y0, x1, y1, *_) in enumerate(self.rows):
            for gx in range(math.floor(x0 / c), math.floor(x1 / c) + 1):
                for gy in range(math.floor(y0 / c), math.floor(y1 / c) + 1):
                    cells.setdefault((gx, gy), []).append(i)
        return cells
