"""Drawing scales: the ISO 5455 series for space diagrams and the 1-2-5 series for vector diagrams,
charts and scale bars.  Pure numbers; nothing here knows about paper or layout."""

from __future__ import annotations

import math

__all__ = ["ISO_5455", "ratio_text", "ratio_factor", "nice_values", "nice_step", "nice_floor", "number_text"]

ISO_5455: tuple[tuple[int, int], ...] = (
    (1000, 1), (500, 1), (200, 1), (100, 1),          # ISO 5455 extends the series by powers of ten
    (50, 1), (20, 1), (10, 1), (5, 1), (2, 1), (1, 1),
    (1, 2), (1, 5), (1, 10), (1, 20), (1, 50), (1, 100), (1, 200), (1, 500),
    (1, 1000), (1, 2000), (1, 5000), (1, 10000),
)
"""The ISO 5455 scales from the largest enlargement to the smallest reduction."""


def ratio_text(ratio: tuple[int, int]) -> str:
    return f"{ratio[0]}:{ratio[1]}"


def ratio_factor(ratio: tuple[int, int]) -> float:
    """Paper length per model length."""
    return ratio[0] / ratio[1]


def nice_values(lo: float, hi: float) -> list[float]:
    """The 1-2-5 series values in [lo, hi], ascending."""
    if not (0 < lo <= hi and math.isfinite(hi)):
        return []
    out = []
    e = math.floor(math.log10(lo)) - 1
    while True:
        for m in (1.0, 2.0, 5.0):
            v = m * 10.0 ** e
            v = float(f"{v:.12g}")
            if v > hi * (1 + 1e-12):
                return out
            if v >= lo * (1 - 1e-12):
                out.append(v)
        e += 1


def nice_step(x: float) -> float:
    """The smallest 1-2-5 value at least ``x`` (> 0)."""
    if not (x > 0 and math.isfinite(x)):
        return 1.0
    e = math.floor(math.log10(x))
    for m in (1.0, 2.0, 5.0, 10.0):
        v = float(f"{m * 10.0 ** e:.12g}")
        if v >= x * (1 - 1e-12):
            return v
    return float(f"{10.0 ** (e + 1):.12g}")


def nice_floor(x: float) -> float:
    """The largest 1-2-5 value at most ``x`` (> 0)."""
    e = math.floor(math.log10(x))
    for m in (5.0, 2.0, 1.0):
        v = float(f"{m * 10.0 ** e:.12g}")
        if v <= x * (1 + 1e-12):
            return v
    return float(f"{0.5 * 10.0 ** e:.12g}")


def number_text(v: float) -> str:
    """A scale number without noise: 10, 0.5, 2.5, 1e-05."""
    s = f"{v:.6g}"
    return "0" if s in ("-0", "0") else s
