"""``[drawing] scale``: the drawing scales a scene states, one per diagram, read without evaluating
anything (a ratio of two plain numbers; "1 mm = <value>" through the unit parser).

    [drawing]
    scale = { space = "1:2", velocity = "1 mm = 10 mm/s", acceleration = "1 mm = 0.1 m/s^2" }

A length diagram (``space``, ``free-body``) takes a ratio "paper:true" (1:2, 2:1, 1:2.5); a polygon
(``velocity``, ``acceleration``, ``force``: every force polygon) takes what one paper millimetre stands for.
Each is held as SI units per paper millimetre; the sheet draws that diagram at that scale only, and says
so when it cannot fit.
"""

from __future__ import annotations

import re
from typing import Any

from .keys import Key, KeyTable
from .units import UnitError, to_si

LENGTH_DIAGRAMS = ("space", "free-body")
POLYGONS = {"velocity": "velocity", "acceleration": "acceleration", "force": "force"}
RATIO_RANGE = (1e-6, 1e6)
"""paper per true length a ratio may state: 1:1 000 000 to 1 000 000:1 (the scene's own size limits)."""

SCALE = KeyTable("drawing.scale", "the scale of a diagram, stated (the sheet draws it at that scale and says "
                                  "so when it cannot fit)", (
    Key("space", "text", None, "the space diagram: a ratio paper:true, e.g. \"1:2\""),
    Key("free-body", "text", None, "the free-body diagram: a ratio paper:true, e.g. \"1:5\""),
    Key("velocity", "text", None, "the velocity polygon: what 1 mm stands for, e.g. \"1 mm = 10 mm/s\""),
    Key("acceleration", "text", None, "the acceleration polygon: what 1 mm stands for, e.g. "
                                      "\"1 mm = 0.1 m/s^2\""),
    Key("force", "text", None, "every force polygon: what 1 mm stands for, e.g. \"1 mm = 2 N\""),
))

_RATIO = re.compile(r"^\s*(\d+(?:\.\d+)?)\s*:\s*(\d+(?:\.\d+)?)\s*$")
_PER_MM = re.compile(r"^\s*1\s*mm\s*=\s*(.+?)\s*$")


def read_scales(reader, value: Any, units) -> tuple[tuple[str, float], ...]:
    """(diagram key, SI units per paper mm) for each scale ``value`` (the ``drawing.scale`` table) states;
    a SceneError naming ``drawing.scale.<key>`` for anything else."""
    if value is None:
        return ()
    t = reader.table("drawing.scale", SCALE, value=value)
    out = []
    for key, raw in t.items():
        where = f"drawing.scale.{key}"
        if not isinstance(raw, str):
            raise reader.fail(where, 'must be a string, e.g. "1:2" or "1 mm = 10 mm/s"')
        if key in LENGTH_DIAGRAMS:
            m = _RATIO.match(raw)
            if not m:
                raise reader.fail(where, f"{raw[:40]!r} is not a ratio paper:true such as \"1:2\" or \"2:1\"")
            paper, true = float(m[1]), float(m[2])
            if not (paper > 0 and true > 0 and RATIO_RANGE[0] <= paper / true <= RATIO_RANGE[1]):
                raise reader.fail(where, f"{raw!r} must be two positive numbers within a factor "
                                         f"{RATIO_RANGE[1]:g} of each other")
            out.append((key, true / paper / 1000.0))              # metres of the drawing per paper mm
            continue
        m = _PER_MM.match(raw)
        if not m:
            raise reader.fail(where, f"{raw[:40]!r} must say what 1 mm stands for, e.g. \"1 mm = 10 mm/s\"")
        kind = POLYGONS[key]
        try:
            si = to_si(m[1], kind, units.of(kind))
        except (UnitError, KeyError) as e:
            raise reader.fail(where, str(e)) from None
        if not si > 0:
            raise reader.fail(where, "1 mm must stand for a positive value")
        out.append((key, si))
    return tuple(out)
