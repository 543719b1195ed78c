"""A cam's machining profile as files: CSV and DXF, with the units in the file.

Coordinates are in the scene's length unit, in the cam frame at cam angle 0 (the follower's axis along
+y), centred on the cam's axis.

- CSV: comment lines (``#``) name the scene, the unit, the tolerance and the sense, then ``x,y`` rows;
- DXF (ezdxf, R2010): one closed LWPOLYLINE on layer ``CAM_PROFILE``, the base circle on ``BASE_CIRCLE``, the
  drawing's $INSUNITS and $MEASUREMENT set from the unit (mm, cm, m, in, ft), and the tolerance in a TEXT
  on layer ``NOTES``.
"""

from __future__ import annotations

import io

import numpy as np

INSUNITS = {"mm": 4, "millimeter": 4, "cm": 5, "centimeter": 5, "m": 6, "meter": 6, "in": 1, "inch": 1,
            "ft": 2, "foot": 2}


def csv_text(scene, pts: np.ndarray, tol: float) -> str:
    u = scene.units
    unit = u.of("length")
    conv = lambda v: u.convert("length", v)    # noqa: E731
    f = scene.model.follower
    lines = [f"# cam profile of {scene.title}", f"# units: {unit}",
             f"# tolerance: {conv(tol):.6g} {unit} (largest distance of a chord from the exact profile)",
             f"# cam turns {'counter-clockwise' if f.sense > 0 else 'clockwise'}; frame at cam angle 0, "
             f"{'the arm pivoted on +x' if f.pivot_distance else 'follower axis along +y'}; {pts.shape[1]} points, "
             f"closed", "x,y"]
    lines += [f"{conv(x):.9f},{conv(y):.9f}" for x, y in zip(pts[0], pts[1])]
    return "\n".join(lines) + "\n"


def dxf_bytes(scene, pts: np.ndarray, tol: float) -> bytes:
    import ezdxf                      # loaded only when a DXF is written
    u = scene.units
    unit = u.of("length")
    conv = lambda v: u.convert("length", v)    # noqa: E731
    doc = ezdxf.new("R2010")
    doc.header["$INSUNITS"] = INSUNITS.get(unit.strip().lower(), 0)
    doc.header["$MEASUREMENT"] = 0 if unit.strip().lower() in ("in", "inch", "ft", "foot") else 1
    for name in ("CAM_PROFILE", "BASE_CIRCLE", "NOTES"):
        doc.layers.add(name)
    msp = doc.modelspace()
    msp.add_lwpolyline([(conv(x), conv(y)) for x, y in zip(pts[0], pts[1])], close=True,
                       dxfattribs={"layer": "CAM_PROFILE"})
    msp.add_circle((0.0, 0.0), conv(scene.model.follower.base_radius), dxfattribs={"layer": "BASE_CIRCLE"})
    msp.add_text(f"{scene.title}: units {unit}, tolerance {conv(tol):.3g} {unit}",
                 dxfattribs={"layer": "NOTES", "height": conv(scene.model.follower.base_radius) / 10})
    s = io.StringIO()
    doc.write(s)
    return s.getvalue().encode("utf-8")
