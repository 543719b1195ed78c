"""Export of a cam's profile for machining: CSV and DXF, at a stated tolerance, with the units in the file.

The profile is the exact envelope sampled so that every chord stays within the tolerance of the true
curve (:func:`constructions.cams.profile.profile_points`; by default 1e-6 of the cam's size, prime circle
plus lift), trimmed where the follower undercuts it.  Coordinates are in the scene's length unit, in the
cam frame at cam angle 0 (the follower's axis along +y), centred on the cam's axis.

- CSV: comment lines (``#``) name the scene, the unit, the tolerance and the sense, then ``x,y`` rows;
- DXF (ezdxf, R2010): one closed LWPOLYLINE on layer ``CAM_PROFILE``, the base circle on ``BASE_CIRCLE``, the
  drawing's $INSUNITS and $MEASUREMENT set from the unit (mm, cm, m, in, ft), and the tolerance in a TEXT
  on layer ``NOTES``.

Usage: ``python -m drafting.cam_export SCENE -o DIR [--tolerance 1e-6]`` (relative to the cam's size).
Both files are written together or not at all (drafting.export.write_outputs).
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numpy as np

from constructions.cams.profile import analyse, profile_points, trim

from .export import ExportError, prepare_folder, write_outputs
from .scene import SceneError, load_scene

INSUNITS = {"mm": 4, "millimeter": 4, "cm": 5, "centimeter": 5, "m": 6, "meter": 6, "in": 1, "inch": 1,
            "ft": 2, "foot": 2}


def profile_for_export(model, tolerance_rel: float = 1e-6) -> tuple[np.ndarray, float]:
    """(points 2 x N in SI, absolute tolerance in SI) of a cam scene's model."""
    p, f = model.program, model.follower
    cp = analyse(p, f, samples=1024)
    tol = tolerance_rel * cp.size
    pts = profile_points(p, f, tol)
    if not cp.undercut_free and cp.undercut:
        from constructions.cams.profile import evaluate, TAU
        n = pts.shape[1]
        cp.samples = evaluate(p, f, np.linspace(0.0, TAU, n, endpoint=False))
        pts = trim(cp)
    return pts, tol


def csv_text(scene, pts: np.ndarray, tol: float) -> str:
    u = scene.units
    unit = u.of("length")
    conv = lambda v: u.convert("length", v)    # noqa: E731
    f = scene.model.follower
    lines = [f"# cam profile of {scene.title}", f"# units: {unit}",
             f"# tolerance: {conv(tol):.6g} {unit} (largest distance of a chord from the exact profile)",
             f"# cam turns {'counter-clockwise' if f.sense > 0 else 'clockwise'}; frame at cam angle 0, follower "
             f"axis along +y; {pts.shape[1]} points, closed", "x,y"]
    lines += [f"{conv(x):.9f},{conv(y):.9f}" for x, y in zip(pts[0], pts[1])]
    return "\n".join(lines) + "\n"


def dxf_bytes(scene, pts: np.ndarray, tol: float) -> bytes:
    import io

    import ezdxf
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


def export(scene_path: str | Path, out_dir: str | Path, tolerance_rel: float = 1e-6) -> list[Path]:
    scene = load_scene(scene_path)
    if scene.kind != "cam":
        raise SceneError(scene.path, "kind", f"is {scene.kind!r}; only a cam scene has a profile to export")
    pts, tol = profile_for_export(scene.model, tolerance_rel)
    out = Path(out_dir)
    prepare_folder(out)
    stem = f"{Path(scene_path).stem}-profile"
    return write_outputs(out, stem, [(out / f"{stem}.csv", lambda: csv_text(scene, pts, tol).encode("utf-8")),
                                     (out / f"{stem}.dxf", lambda: dxf_bytes(scene, pts, tol))])


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(prog="python -m drafting.cam_export", description=__doc__.splitlines()[0])
    ap.add_argument("scene")
    ap.add_argument("-o", "--out", default=".")
    ap.add_argument("--tolerance", type=float, default=1e-6, help="chord tolerance relative to the cam's size")
    a = ap.parse_args(argv)
    if not 0 < a.tolerance < 0.1:
        ap.error("--tolerance must lie between 0 and 0.1 (a fraction of the cam's size)")
    try:
        for p in export(a.scene, a.out, a.tolerance):
            print(f"wrote {p}")
    except (SceneError, ExportError) as e:
        print(f"error: {e}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main())
