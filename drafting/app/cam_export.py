"""Export of a cam's profile for machining: CSV and DXF, at a stated tolerance, with the units in the file.

The profile is the exact envelope sampled so that every chord stays within the tolerance of the true
curve (:func:`constructions.cams.sampling.profile_samples`; by default 1e-6 of the cam's size, prime circle
plus lift), trimmed where the follower undercuts it.  Coordinates are in the scene's length unit, in the
cam frame at cam angle 0 (the follower's axis along +y), centred on the cam's axis.

- CSV: comment lines (``#``) name the scene, the unit, the tolerance and the sense, then ``x,y`` rows;
- DXF (ezdxf, R2010): one closed LWPOLYLINE on layer ``CAM_PROFILE``, the base circle on ``BASE_CIRCLE``, the
  drawing's $INSUNITS and $MEASUREMENT set from the unit (mm, cm, m, in, ft), and the tolerance in a TEXT
  on layer ``NOTES``.

Usage: ``drafting export SCENE -o DIR [--tolerance 1e-6]`` (relative to the cam's size), or ``python -m
drafting.app.cam_export`` with the same arguments; both are :func:`add_export_arguments` and :func:`run_export`.
Both files are written together or not at all (drafting.backends.files.write_outputs).
"""

from __future__ import annotations

import argparse
import sys
from dataclasses import replace
from pathlib import Path

import numpy as np

from ..backends.files import ExportError, prepare_folder, write_outputs
from ..scene.reader import SceneError, load_scene

INSUNITS = {"mm": 4, "millimeter": 4, "cm": 5, "centimeter": 5, "m": 6, "meter": 6, "in": 1, "inch": 1,
            "ft": 2, "foot": 2}


def profile_for_export(model, tolerance_rel: float = 1e-6) -> tuple[np.ndarray, float]:
    """(points 2 x N in SI, absolute tolerance in SI) of a cam scene's model: the profile-only path
    (:func:`constructions.cams.sampling.profile_samples`), trimmed where the analysis finds undercut."""
    from constructions.cams.envelope import evaluate   # the cam engine, when used
    from constructions.cams.profile import analyse, trim
    from constructions.cams.sampling import profile_samples
    p, f = model.program, model.follower
    cp = analyse(p, f, samples=1024)
    tol = tolerance_rel * cp.size
    theta, pts = profile_samples(p, f, tol)
    if cp.undercut:
        # the dense points, against the roller centres (face lines) at their own cam angles
        pts = trim(cp, replace(evaluate(p, f, theta[np.isfinite(theta)]), profile=pts))
    return pts, tol


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


def add_export_arguments(parser: argparse.ArgumentParser) -> argparse.ArgumentParser:
    """The export's arguments on ``parser`` (this module's own command line, or a ``drafting export``
    subcommand): the scene, the output folder and the relative tolerance."""
    parser.add_argument("scene", help="a cam scene file (kind = \"cam\")")
    parser.add_argument("-o", "--out", default=".", help="the folder for SCENE-profile.csv and .dxf")
    parser.add_argument("--tolerance", type=float, default=1e-6,
                        help="chord tolerance relative to the cam's size (default 1e-6)")
    return parser


def run_export(args: argparse.Namespace) -> int:
    """Write the CSV and DXF for parsed ``args`` (:func:`add_export_arguments`): 0 when written, 2 on a
    scene or export error or a tolerance out of range (the message on stderr)."""
    if not 0 < args.tolerance < 0.1:
        print("drafting: error: --tolerance must lie between 0 and 0.1 (a fraction of the cam's size)", file=sys.stderr)
        return 2
    try:
        for p in export(args.scene, args.out, args.tolerance):
            print(f"wrote {p}")
    except (SceneError, ExportError) as e:
        print(f"drafting: error: {e}", file=sys.stderr)
        return 2
    return 0


def main(argv=None) -> int:
    ap = add_export_arguments(argparse.ArgumentParser(prog="python -m drafting.app.cam_export",
                                                      description=__doc__.splitlines()[0]))
    return run_export(ap.parse_args(argv))


__all__ = ["export", "profile_for_export", "csv_text", "dxf_bytes", "add_export_arguments", "run_export", "main"]


if __name__ == "__main__":
    sys.exit(main())
