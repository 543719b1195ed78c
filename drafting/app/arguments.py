"""The ``drafting`` command's arguments: the parser of every subcommand and the checks of their values
(whole numbers, seeds, output formats)."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from ..families.cam.tolerance import EXPORT_TOLERANCE
from ..scene.papers import PAPERS

FORMATS = ("svg", "pdf", "png")
DEFAULT_OUT = Path("drafting-output")


def _positive(text: str) -> int:
    try:
        n = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a whole number") from None
    if n < 1:
        raise argparse.ArgumentTypeError(f"{text!r} must be at least 1")
    return n


def _seed(text: str) -> int:
    try:
        n = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a whole number") from None
    if not 0 <= n < 2 ** 63:
        raise argparse.ArgumentTypeError(f"{text!r} must be a whole number from 0 to 2^63 - 1")
    return n


def _formats(text: str) -> list[str]:
    out = [f.strip().lower() for f in text.split(",") if f.strip()]
    known = FORMATS + (PAGE,)
    bad = [f for f in out if f not in known]
    if bad or not out:
        raise argparse.ArgumentTypeError(f"unknown format {bad[0] if bad else text!r}; choose from {','.join(known)}")
    return out


PAGE = "html"
"""The step-through page (drafting.backends.html_page): asked for by --format html beside the sheets' formats."""


def _version() -> str:
    """The installed distribution's version (pyproject.toml's), or "unknown" when run from a bare tree."""
    import importlib.metadata              # slow to load: only for --version
    try:
        return importlib.metadata.version("tom-drafting")
    except importlib.metadata.PackageNotFoundError:
        return "unknown"


class _VersionAction(argparse.Action):
    """``--version`` as argparse's own prints it, the installed version looked up only when asked."""

    def __init__(self, option_strings, dest=argparse.SUPPRESS, default=argparse.SUPPRESS,
                 help="show program's version number and exit"):
        super().__init__(option_strings, dest=dest, default=default, nargs=0, help=help)

    def __call__(self, parser, namespace, values, option_string=None):
        print(f"{parser.prog} {_version()}", file=sys.stdout)
        parser.exit()


class _Parser(argparse.ArgumentParser):
    """argparse's parser with its errors as the command's others: one line ``drafting: error: ...`` and
    exit 2 (argparse prints the usage first, a second and third line)."""

    def error(self, message: str):
        self.exit(2, f"drafting: error: {' '.join(message.split())} (see {self.prog} --help)\n")


def parser() -> argparse.ArgumentParser:
    p = _Parser(prog="drafting", description=(
        "Draw the graphical methods of the theory of machines step by step on true-scale sheets, "
        "checked against the analytic answer. With no command, renders the built-in example "
        "(the notes' slider-crank velocity Example 1) into ./drafting-output."))
    p.add_argument("--version", action=_VersionAction)
    sub = p.add_subparsers(dest="command")
    r = sub.add_parser("render", help="render scene files to sheets (SVG, PDF, PNG)",
                       description="Render each scene to a sheet and print its results table.")
    r.add_argument("scenes", nargs="+", type=Path, metavar="SCENE", help="scene files (TOML)")
    r.add_argument("-o", "--out", type=Path, default=DEFAULT_OUT, help="output folder (default: %(default)s)")
    r.add_argument("--format", type=_formats, default=list(FORMATS),
                   help="comma-separated: svg,pdf,png (default: all), and html for the step-through page")
    r.add_argument("--paper", choices=PAPERS, help="override the scene's paper size")
    r.add_argument("--lab", nargs="?", const="full", choices=("full", "bare"),
                   help="also the problem sheet (SCENE-problem.*: given data, empty panels at the stated "
                        "scales, no answers) and the answer key (SCENE-key.* and SCENE-key.csv); "
                        "--lab bare: the problem sheet without the construction steps")
    r.add_argument("--workers", type=_positive, metavar="N",
                   help="processes for several scenes (default: the cores; 1: one after the other)")
    s = sub.add_parser("solve", help="solve a scene and print its results",
                       description="Solve a scene; with --json print machine-readable results in the "
                                   "scene's units and the list of analyses that ran.")
    s.add_argument("scene", type=Path, metavar="SCENE")
    s.add_argument("--json", action="store_true", help="print JSON")
    s.add_argument("--csv", type=Path, metavar="FILE", help="also write the results as CSV (scene units)")
    c = sub.add_parser("check", help="compare graphical and analytic results",
                       description="Compare every graphical result with the analytic (vector-loop) one; "
                                   "exit 1 if any differs by more than 1e-9 relative.")
    c.add_argument("scenes", nargs="+", type=Path, metavar="SCENE")
    c.add_argument("--answers", type=Path, metavar="FILE",
                   help="mark a student's values (CSV name,value or TOML name = \"value\") against the "
                        "scene's key at drawing accuracy; exit 1 unless every item is right")
    c.add_argument("--variant", type=_positive, metavar="N", help="with --answers: the batch variant N ...")
    c.add_argument("--seed", type=_seed, metavar="S", help="... of the batch with seed S")
    a = sub.add_parser("batch", help="N variants of a scene's lab sheets from its [vary] ranges",
                       description="Draw N variants of the scene from its [vary] ranges (the same seed gives "
                                   "the same files), each a problem sheet, worked solution and answer key, "
                                   "rendered over the cores; every key also in one CSV.")
    a.add_argument("scene", type=Path, metavar="SCENE")
    a.add_argument("--variants", type=int, required=True, metavar="N", help="how many variants")
    a.add_argument("--seed", type=_seed, default=0, metavar="S", help="the seed (default 0)")
    a.add_argument("-o", "--out", type=Path, default=DEFAULT_OUT, help="output folder (default: %(default)s)")
    a.add_argument("--format", type=_formats, default=["pdf"], help="comma-separated: svg,pdf,png (default: pdf)")
    a.add_argument("--workers", type=_positive, metavar="N", help="processes (default: the cores)")
    b = sub.add_parser("bench", help="measure rendering and analytic sweep speed",
                       description="Time the default sheet to SVG/PDF/PNG and the analytic sweep over "
                                   "1e3..1e7 crank angles, side by side in one run.")
    b.add_argument("--quick", action="store_true", help="fewer repeats and sizes up to 1e6")
    b.add_argument("--gallery", action="store_true",
                   help="instead: every gallery scene's sheet, solve / layout / SVG and their total, side by side")
    b.add_argument("--json", action="store_true", help="with --gallery: the figures as JSON (ms)")
    b.add_argument("--peers", action="store_true",
                   help="also the four-bar sweep against pylinkage, mechanism (pip install .[bench]) and "
                        "plain numpy")
    add_export_arguments(sub.add_parser(
        "export", help="a cam's profile for machining (CSV and DXF) and its station table (CSV)",
        description="Write a cam scene's profile as CSV and DXF (units in the file), every chord within the "
                    "tolerance of the exact profile, trimmed where the follower undercuts it; and its station "
                    "table as CSV (s, v, a, j, pressure angle, radii of curvature, contact point at each "
                    "drawn station)."))
    n = sub.add_parser("lint", help="measure each scene's sheets against the sheet critic's checks",
                       description="Lay out each scene's worked sheets and report what the sheet critic finds: "
                                   "labels overlapping, struck by lines, ambiguous or far off with no leader, "
                                   "short arrows without a leader, diagrams filling little of their panel, blank "
                                   "pages, small lettering, long title-block cells. Exit 1 when anything is found.")
    n.add_argument("scenes", nargs="+", type=Path, metavar="SCENE", help="scene files (TOML)")
    n.add_argument("--json", action="store_true", help="print the findings and counts as JSON")
    w = sub.add_parser("sweep", help="a linkage over one turn of its crank (table or CSV)",
                       description="Solve the scene's linkage over one turn of the crank, starting at the "
                                   "scene's crank angle (analytic, vectorised); angles where it cannot be "
                                   "assembled are gaps. Prints a summary, or writes a CSV in the scene's units.")
    w.add_argument("scene", type=Path, metavar="SCENE")
    g = w.add_mutually_exclusive_group()
    g.add_argument("--steps", type=int, metavar="N", help="number of crank angles over the turn (default 72)")
    g.add_argument("--every", metavar="ANGLE", help="one crank angle every ANGLE, e.g. 5deg or 0.1rad")
    w.add_argument("--csv", type=Path, metavar="FILE", help="write the table as CSV (scene units)")
    w.add_argument("--sheet", type=Path, metavar="DIR",
                   help="also draw the cycle sheet (charts, coupler curves, limit positions) into DIR")
    v = sub.add_parser("serve", help="edit a scene in the browser beside its sheets, redrawn as you type",
                       description="A local web app (this machine only, a token in its URL): the scene's text "
                                   "beside its sheets, redrawn as you type and when the file is saved; saves "
                                   "are atomic and keep the previous version as NAME.toml~. Needs the extra "
                                   "(pip install 'tom-drafting[serve]').")
    v.add_argument("target", nargs="?", type=Path, metavar="SCENE|FOLDER",
                   help="a scene file, or a folder whose scenes are listed (default: the current folder)")
    v.add_argument("--port", type=int, default=8470, help="port on 127.0.0.1 (default: %(default)s; 0: any free)")
    k = sub.add_parser("keys", help="the keys of a scene kind: unit, default, meaning",
                       description="Print a scene kind's sections and keys (unit, default, whether required, "
                                   "allowed values, meaning), generated from the readers' own key tables.")
    k.add_argument("kind", nargs="?", metavar="KIND", help="cam, \"gear pair\" (or gear-pair), gear-train, "
                                                            "free-body, linkage; none: the list of kinds")
    k.add_argument("--markdown", action="store_true", help="every kind as Markdown (docs/scene-reference.md)")
    e = sub.add_parser("new", help="write an annotated starter scene of a kind",
                       description="Write a starter scene of KIND that renders, every key commented with its "
                                   "meaning and unit; it refuses to overwrite a file.")
    e.add_argument("kind", metavar="KIND", help="linkage, cam, gear-pair, gear-train or free-body")
    e.add_argument("--example", metavar="NAME", help="which starter (linkage: four-bar, slider-crank; "
                                                    "gear-train: three-gears, planetary)")
    e.add_argument("-o", "--out", type=Path, metavar="FILE", help="the file to write (default: print it)")
    return p


def add_export_arguments(parser: argparse.ArgumentParser) -> argparse.ArgumentParser:
    """The export's arguments on ``parser`` (:mod:`drafting.app.cam_export`'s own command line, or the
    ``drafting export`` subcommand): the scene, the output folder and the relative tolerance."""
    parser.add_argument("scene", help="a cam scene file (kind = \"cam\")")
    parser.add_argument("-o", "--out", default=".", help="the folder for SCENE-profile.csv and .dxf and SCENE-stations.csv")
    parser.add_argument("--tolerance", type=float, default=EXPORT_TOLERANCE,
                        help="chord tolerance relative to the cam's size (default 1e-6)")
    return parser
