"""The ``drafting`` command.

    drafting                      render the built-in example (notes, velocity Example 1)
    drafting render SCENE...      sheets as SVG, PDF and PNG
    drafting solve SCENE --json   results in the scene's units and the analyses that ran
    drafting check SCENE...       graphical against analytic; exit 1 on disagreement
    drafting check SCENE --answers FILE   a student's values marked at drawing accuracy
    drafting render SCENE --lab   problem sheet, worked solution and answer key
    drafting batch SCENE --variants N --seed S -o DIR   N lab-sheet variants from the scene's [vary]
    drafting bench [--peers]      timings of rendering and of the analytic sweep (and its peers)

Exit codes: 0 fine, 1 graphical and analytic disagree, 2 bad input (one sentence on stderr).
"""

from __future__ import annotations

import argparse
import json
import os
import signal
import sys
from dataclasses import replace
from pathlib import Path
from typing import Sequence

from constructions.errors import ConstructionError, IndeterminatePosition

from ..backends.faults import Interrupted, remove_temporaries, signals_handled
from .parallel import tune_gc
from ..scene.reader import PAPERS, SceneError, load_scene
from ..study.study import Study
from ..study.worked import builtin_example, sheet_for, sheets_for  # noqa: F401  (sheet_for: API)
from ..scene.textsafe import one_line, safe_streams
from ..scene.units import from_si, unit_symbol

FORMATS = ("svg", "pdf", "png")
DEFAULT_OUT = Path("drafting-output")


EXIT_DISAGREE = 1
EXIT_INPUT = 2
EXIT_SINGULAR = 3


class UserError(Exception):
    """Anything the user can fix; printed as one line.  ``code`` is the exit code: 2 for bad input,
    3 for a singular position (toggle, change point, limit position) where a polygon cannot close."""

    def __init__(self, message: str, code: int = EXIT_INPUT) -> None:
        super().__init__(one_line(message, cut_quotes=False))    # escaped and bounded: one line
        self.code = code


def _study(path: Path, paper: str | None = None) -> Study:
    try:
        scene = load_scene(path)
    except SceneError as e:
        raise UserError(str(e)) from None
    return Study(scene if paper is None else replace(scene, paper=paper))


def _solve(study: Study) -> Study:
    """Run what the scene asks for; construction errors become one sentence naming the file (exit 3 at
    a singular position, whose message names its kind, else 2)."""
    try:
        study.run()
    except SceneError as e:                  # what the scene asks for, found wrong once solved (ask.find)
        raise UserError(str(e)) from None
    except IndeterminatePosition as e:
        raise UserError(f"{study.scene.path}: {_located(study, e)}", EXIT_SINGULAR) from None
    except ConstructionError as e:
        raise UserError(f"{study.scene.path}: {_located(study, e)}") from None
    return study


def _located(study: Study, e: ConstructionError) -> str:
    """The error with the position it happened at: the engine's, else the scene's crank angle."""
    if e.position:
        return str(e)
    try:
        u = study.scene.units.angle
        where = f"crank angle {from_si(study.scene.angle, 'angle', u):.6g} {unit_symbol(u)}"
    except Exception:
        where = "the given crank angle"
    return f"at {where}: {e}"


def results_text(study: Study) -> str:
    """The results table as aligned plain text."""
    head = ("quantity", "graphical", "analytic", "difference")
    rows = [head] + study.table()
    if len(rows) == 1:
        return f"{study.scene.title}\n  (no results to compare: the scene asks for {', '.join(study.scene.analyses)})"
    widths = [max(len(r[i]) for r in rows) for i in range(4)]
    lines = [study.scene.title]
    for k, r in enumerate(rows):
        lines.append("  " + "  ".join(c.ljust(w) for c, w in zip(r, widths)).rstrip())
        if k == 0:
            lines.append("  " + "  ".join("-" * w for w in widths))
    bad = study.disagreements()
    model = study.model
    if model:
        widest = max(c.tolerance for c in study.comparisons)
        agree = "agree to 1e-9 relative" if widest <= 1e-9 else \
            f"agree within tolerances widened near the singular position (up to {widest:.0e} relative)"
        lines.append(f"  graphical vs analytic ({model}): "
                     + (agree if not bad else f"{len(bad)} DISAGREE beyond their tolerance"))
    for n in study.notes:
        lines.append(f"  note: {n}")
    for w in study.warnings:
        lines.append(f"  warning: {w}")
    return "\n".join(lines)


def render_one(path: Path, out: Path, formats: Sequence[str], paper: str | None,
               lab: bool = False) -> tuple[str | None, str]:
    """Render one scene: ``(error, text)`` -- the one-line error (None when it rendered) and what to print
    (its results and the files written).  ``lab``: the problem sheet and the answer key beside the worked
    solution (drafting.app.lab), all written together."""
    from ..backends.files import ExportError, write_sheets
    from ..render.errors import LayoutError
    try:
        study = _study(path, paper)
        if lab:
            from .lab import dimensioned
            study = Study(dimensioned(study.scene))
        study = _solve(study)
        try:
            sheet_formats = [f for f in formats if f != PAGE]
            if lab:
                from ..layout.sheet import source_date_epoch
                from .lab import lab_for, write_lab
                written = write_lab(lab_for(study, epoch=source_date_epoch()), out, path.stem, sheet_formats)
            else:
                written = write_sheets(sheets_for(study), out, path.stem, sheet_formats) if sheet_formats else []
            if PAGE in formats:
                from ..backends.html_page import write_page
                written.append(write_page(study, sheets_for(study), out, path.stem))
        except ExportError as e:                  # names the output file it could not write
            raise UserError(f"{path}: {e}") from None
        except LayoutError as e:                  # the sheet: the paper is what the user can change
            raise UserError(f"{path}: drawing.paper: {e}") from None
        except ConstructionError as e:            # raised while drawing: told at its position
            raise UserError(f"{path}: {_located(study, e)}") from None
    except UserError as e:
        return str(e), ""
    return None, "\n".join([results_text(study)] + [f"  wrote {w}" for w in written])


def _render_job(job: tuple) -> tuple[str | None, str]:
    """One scene of a parallel render (runs in a worker; module level, so a process pool can send it)."""
    path, out, formats, paper, lab = job
    return render_one(Path(path), Path(out), formats, paper, lab)


def cmd_render(scenes: Sequence[Path], out: Path, formats: Sequence[str], paper: str | None, lab: bool = False,
               executor=None, workers: int | None = None) -> int:
    """Render every scene; a scene that fails is reported in one line and the others still render; a
    progress bar on a terminal when there are several.  Several scenes render over the cores
    (drafting.app.parallel: a process pool from SERIAL_BELOW scenes up, serially below); what each prints
    comes out in the order the scenes were given."""
    from . import parallel
    from .progress import Progress
    bar = Progress(len(scenes), "render")
    bar.shown = len(scenes) >= 2 and _is_tty(sys.stderr)
    failed = [0]
    ready: dict[int, tuple[str | None, str]] = {}
    shown = [0]

    def on_done(i: int, result) -> None:
        ready[i] = result
        while shown[0] in ready:
            err, text = ready.pop(shown[0])
            if err is not None:
                print(f"drafting: error: {err}", file=sys.stderr)
                failed[0] += 1
            else:
                print(text)
            shown[0] += 1
        bar.update(shown[0])
    jobs = [(str(p), str(out), tuple(formats), paper, lab) for p in scenes]
    try:
        parallel.run(_render_job, jobs, executor=executor, on_done=on_done, folders=[out], workers=workers)
    except parallel.WorkerLost as e:
        raise UserError(f"render: {e}") from None
    bar.finish()
    return 2 if failed[0] else 0


def _is_tty(stream) -> bool:
    try:
        return bool(getattr(stream, "unescaped", stream).isatty())
    except (AttributeError, ValueError):
        return False


def cmd_solve(path: Path, as_json: bool, csv_path: Path | None = None) -> int:
    study = _solve(_study(path))
    if as_json:
        print(json.dumps(study.to_json(), indent=2))
    else:
        print(results_text(study))
    if csv_path is not None:
        from ..backends.files import ExportError, prepare_folder, write_outputs
        from ..study.study import results_csv
        folder = csv_path.parent if str(csv_path.parent) else Path(".")
        try:
            prepare_folder(folder)
            write_outputs(folder, csv_path.stem, [(csv_path, lambda: results_csv(study).encode("utf-8"))])
        except ExportError as e:
            raise UserError(f"{path}: --csv: {e}") from None
        if not as_json:
            print(f"  wrote {csv_path}")
    return 0


def cmd_check(scenes: Sequence[Path]) -> int:
    """Check every scene; a scene that cannot be read or solved is reported in one line and the others are
    still checked (as render does).  Exit: the worst of 1 (disagreement), 3 (singular), 2 (bad input)."""
    status = 0
    for path in scenes:
        try:
            study = _solve(_study(path))
        except UserError as e:
            print(f"drafting: error: {e}", file=sys.stderr)
            status = max(status, e.code)
            continue
        print(results_text(study))
        if study.comparisons and study.model is None:
            print(f"  {path}: no analytic model for this mechanism; nothing checked")
        if study.disagreements():
            status = max(status, EXIT_DISAGREE)
    return status


def cmd_check_answers(path: Path, answers: Path, variant: int | None, seed: int | None) -> int:
    """Mark a student's values against the scene's key (or a batch variant's) at drawing accuracy: one
    line per item, right / wrong / missing with the expected value.  Exit 1 unless every item is right."""
    from .answers import AnswersError, mark, read_answers
    from .lab import dimensioned, lab_for
    label = ""
    if variant is not None:
        import tomllib
        from .batch import variant_label, variant_study
        from ..scene.reader import _read_text, parse_scene
        if seed is None:
            raise UserError(f"{path}: --variant needs the batch's --seed")
        try:
            text = _read_text(path)
            parse_scene(text, path)
            data = tomllib.loads(text)
        except SceneError as e:
            raise UserError(str(e)) from None
        if "vary" not in data:
            raise UserError(f"{path}: vary: is missing, so the scene has no variants")
        notes: list[str] = []
        try:
            study, _ = variant_study(data, path, seed, variant, notes)
        except SceneError as e:
            raise UserError(str(e)) from None
        if study is None:
            raise UserError(f"{path}: variant {variant} of seed {seed} was skipped by the batch (no draw could "
                            f"be drawn)")
        label = variant_label(variant)
    else:
        study = _solve(Study(dimensioned(_study(path).scene)))
    items = lab_for(study, label=label).items
    if not items:
        raise UserError(f"{path}: the scene has no answers to mark (it asks for {', '.join(study.scene.analyses)})")
    try:
        marks, unknown = mark(items, read_answers(answers), answers, study.scene.units)
    except AnswersError as e:
        raise UserError(str(e)) from None
    width = max(len(m.item.shown) for m in marks)
    title = study.scene.title + (f" ({label})" if label else "")
    print(f"{title}: {answers} marked at drawing accuracy")
    for m in marks:
        print(m.line(width))
    counts = {v: sum(1 for m in marks if m.verdict == v) for v in ("right", "wrong", "missing")}
    print(f"  {counts['right']} right, {counts['wrong']} wrong, {counts['missing']} missing of {len(marks)}")
    for name in unknown:
        print(f"  note: {answers}: {name!r} is not a quantity of this scene; it asks for "
              f"{', '.join(i.shown for i in items)}")
    return 0 if counts["right"] == len(marks) else EXIT_DISAGREE


def cmd_batch(path: Path, variants: int, seed: int, out: Path, formats: Sequence[str], workers: int | None,
              executor=None) -> int:
    """N variants of the scene's lab sheets (drafting.app.batch); each variant's files together or not at all,
    then every key as one CSV."""
    from .batch import run_batch
    from ..backends.files import ExportError
    from .parallel import WorkerLost
    from .progress import Progress
    if variants < 1:
        raise UserError(f"{path}: --variants must be at least 1, not {variants}")
    if variants > MAX_VARIANTS:
        raise UserError(f"{path}: --variants may be at most {MAX_VARIANTS}, not {variants}")
    bar = Progress(variants, "batch")
    bar.shown = _is_tty(sys.stderr)
    formats = [f for f in formats if f != PAGE]
    if not formats:
        raise UserError(f"{path}: --format: a batch writes svg, pdf or png (the html page is one per scene)")
    try:
        results = run_batch(path, variants, seed, out, formats, executor=executor, progress=bar, workers=workers)
    except SceneError as e:
        raise UserError(str(e)) from None
    except ExportError as e:
        raise UserError(f"{path}: {e}") from None
    except WorkerLost as e:
        raise UserError(f"{path}: {e}") from None
    failed = 0
    for r in results:
        for n in r.notes:
            print(f"  note: {n}")
        if r.error:
            print(f"drafting: error: {r.error}", file=sys.stderr)
            failed += 1
    done = [r for r in results if r.files]
    print(f"{path}: {len(done)} of {variants} variants (seed {seed}) written to {out}"
          + (f"; every key in {out / (path.stem + '-keys.csv')}" if done else ""))
    return 2 if failed else 0


MAX_VARIANTS = 10_000


def cmd_bench(quick: bool, peers: bool = False) -> int:
    from .bench import run_benchmarks
    print(run_benchmarks(quick=quick, peers=peers))
    return 0


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


def parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(prog="drafting", description=(
        "Draw the graphical methods of the theory of machines step by step on true-scale sheets, "
        "checked against the analytic answer. With no command, renders the built-in example "
        "(the notes' slider-crank velocity Example 1) into ./drafting-output."))
    sub = p.add_subparsers(dest="command")
    r = sub.add_parser("render", help="render scene files to sheets (SVG, PDF, PNG)",
                       description="Render each scene to a sheet and print its results table.")
    r.add_argument("scenes", nargs="+", type=Path, metavar="SCENE", help="scene files (TOML)")
    r.add_argument("-o", "--out", type=Path, default=DEFAULT_OUT, help="output folder (default: %(default)s)")
    r.add_argument("--format", type=_formats, default=list(FORMATS),
                   help="comma-separated: svg,pdf,png (default: all), and html for the step-through page")
    r.add_argument("--paper", choices=PAPERS, help="override the scene's paper size")
    r.add_argument("--lab", action="store_true",
                   help="also the problem sheet (SCENE-problem.*: given data, empty panels at the stated "
                        "scales, no answers) and the answer key (SCENE-key.* and SCENE-key.csv)")
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
    b.add_argument("--peers", action="store_true",
                   help="also the four-bar sweep against pylinkage, mechanism (pip install .[bench]) and "
                        "plain numpy")
    from .cam_export import add_export_arguments
    add_export_arguments(sub.add_parser(
        "export", help="a cam's profile for machining (CSV and DXF)",
        description="Write a cam scene's profile as CSV and DXF (units in the file), every chord within the "
                    "tolerance of the exact profile, trimmed where the follower undercuts it."))
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
    return p


def main(argv: Sequence[str] | None = None, *, exiting: bool = False) -> int:
    """The command.  SIGINT and SIGTERM end it cleanly, temporary files removed, with exit code 130 or
    143; whatever reaches the terminal has its control characters escaped (a title cannot move the
    cursor)."""
    with safe_streams():
        try:
            if exiting:                         # the process is the command's own
                tune_gc()
            # the signal may come while the handlers are being put in place: the try holds that too
            # a process about to exit (``exiting``) ignores a late signal: its status is the work's
            with signals_handled(after=signal.SIG_IGN if exiting else None):
                return _main(argv)
        except Interrupted as e:
            return _interrupted(e.name, e.exit_code)
        except KeyboardInterrupt:             # before the handlers were in place
            return _interrupted("SIGINT", 130)
        except BrokenPipeError:               # the reader went away (drafting ... | head): stop quietly
            remove_temporaries()
            _silence_stdout()
            return 141


def _interrupted(name: str, code: int) -> int:
    remove_temporaries()
    print(f"drafting: interrupted by {name}; no file was left half-written", file=sys.stderr)
    return code


def _silence_stdout() -> None:
    """After a broken pipe, point stdout at /dev/null so the interpreter's final flush cannot fail."""
    try:
        fd = os.open(os.devnull, os.O_WRONLY)
        os.dup2(fd, sys.__stdout__.fileno())
    except (OSError, ValueError, AttributeError):
        pass


def _main(argv: Sequence[str] | None) -> int:
    args = parser().parse_args(argv)
    try:
        if args.command is None:
            return cmd_render([builtin_example()], DEFAULT_OUT, FORMATS, None)
        if args.command == "render":
            return cmd_render(args.scenes, args.out, args.format, args.paper, args.lab, workers=args.workers)
        if args.command == "batch":
            return cmd_batch(args.scene, args.variants, args.seed, args.out, args.format, args.workers)
        if args.command == "solve":
            return cmd_solve(args.scene, args.json, args.csv)
        if args.command == "check":
            if args.answers is not None:
                if len(args.scenes) != 1:
                    raise UserError("--answers marks the answers to one scene; give one SCENE")
                return cmd_check_answers(args.scenes[0], args.answers, args.variant, args.seed)
            if args.variant is not None or args.seed is not None:
                raise UserError("--variant and --seed go with --answers")
            return cmd_check(args.scenes)
        if args.command == "bench":
            return cmd_bench(args.quick, args.peers)
        if args.command == "export":
            from .cam_export import run_export
            return run_export(args)
        if args.command == "sweep":
            from .sweep_cmd import SweepInputError, cmd_sweep
            try:
                return cmd_sweep(args.scene, args.steps, args.every, args.csv, args.sheet)
            except SweepInputError as e:
                raise UserError(str(e)) from None
    except UserError as e:
        print(f"drafting: error: {e}", file=sys.stderr)
        return e.code
    return 0


if __name__ == "__main__":
    sys.exit(main(exiting=True))
