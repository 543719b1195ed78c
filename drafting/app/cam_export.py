"""``drafting export``: a cam's profile for machining, CSV and DXF, at a stated tolerance, with the units in
the file; beside them the per-station table (SCENE-stations.csv: s, v, a, j, pressure angle, radii of
curvature and contact point at each drawn station, :func:`drafting.families.cam.tables.stations_csv`).  The profile is the cam family's "machining profile" analysis (every chord within the tolerance
of the exact envelope, by default 1e-6 of the cam's size, prime circle plus lift; trimmed where the
follower undercuts it), written by :mod:`drafting.backends.cam_files`.

Usage: ``drafting export SCENE -o DIR [--tolerance 1e-6]`` (relative to the cam's size), or ``python -m
drafting.app.cam_export`` with the same arguments; both are :func:`add_export_arguments` and :func:`run_export`.
The files are written together or not at all (drafting.backends.files.write_outputs).
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from ..backends.cam_files import csv_text, dxf_bytes
from ..backends.files import ExportError, prepare_folder, write_outputs
from ..scene.reader import SceneError, load_scene
from ..families.cam.tables import stations_csv
from ..families.cam.tolerance import EXPORT_TOLERANCE, EXPORT_TOLERANCE_RANGE
from .arguments import add_export_arguments
from ..study.study import Study


def export(scene_path: str | Path, out_dir: str | Path, tolerance_rel: float = EXPORT_TOLERANCE) -> list[Path]:
    scene = load_scene(scene_path)
    if scene.kind != "cam":
        raise SceneError(scene.path, "kind", f"is {scene.kind!r}; only a cam scene has a profile to export")
    study = Study(scene, options={"export tolerance": tolerance_rel})
    pts, tol = study.get("machining profile")
    out = Path(out_dir)
    prepare_folder(out)
    stem = f"{Path(scene_path).stem}-profile"
    return write_outputs(out, stem, [(out / f"{stem}.csv", lambda: csv_text(scene, pts, tol).encode("utf-8")),
                                     (out / f"{stem}.dxf", lambda: dxf_bytes(scene, pts, tol)),
                                     (out / f"{Path(scene_path).stem}-stations.csv",
                                      lambda: stations_csv(study).encode("utf-8"))])


def run_export(args: argparse.Namespace) -> int:
    """Write the CSV and DXF for parsed ``args`` (:func:`add_export_arguments`): 0 when written, 2 on a
    scene or export error or a tolerance out of range (the message on stderr)."""
    if not EXPORT_TOLERANCE_RANGE[0] <= args.tolerance < EXPORT_TOLERANCE_RANGE[1]:
        print(f"drafting: error: --tolerance must lie between {EXPORT_TOLERANCE_RANGE[0]:g} and "
              f"{EXPORT_TOLERANCE_RANGE[1]:g} (a fraction of the cam's size; a finer one takes minutes to "
              f"sample)", file=sys.stderr)
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


__all__ = ["export", "add_export_arguments", "run_export", "main"]


if __name__ == "__main__":
    sys.exit(main())


run_command = run_export
"""``drafting export``: this module's entry from the command table (drafting.app.cli.COMMANDS)."""
