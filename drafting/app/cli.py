"""The ``drafting`` command.

    drafting                      render the built-in example (notes, velocity Example 1)
    drafting render SCENE...      sheets as SVG, PDF and PNG
    drafting solve SCENE --json   results in the scene's units and the analyses that ran
    drafting check SCENE...       graphical against analytic; exit 1 on disagreement
    drafting check SCENE --answers FILE   a student's values marked at drawing accuracy
    drafting render SCENE --lab   problem sheet, worked solution and answer key
    drafting batch SCENE --variants N --seed S -o DIR   N lab-sheet variants from the scene's [vary]
    drafting bench [--peers]      timings of rendering and of the analytic sweep (and its peers)
    drafting lint SCENE... [--json]   the sheet critic's findings; exit 1 when there are any
    drafting bench --gallery      every gallery sheet's solve, layout and SVG times (--json)
    drafting keys KIND            a scene kind's keys: unit, default, meaning (--markdown: every kind)
    drafting new KIND [--example NAME] [-o FILE]   an annotated starter scene that renders

Exit codes: 0 fine, 1 graphical and analytic disagree, 2 bad input (one sentence on stderr).
"""

from __future__ import annotations

import json
import os
import signal
import sys
from pathlib import Path
from typing import Sequence

from constructions.errors import ConstructionError

from ..backends.faults import Interrupted, remove_temporaries, signals_handled
from .arguments import DEFAULT_OUT, FORMATS, PAGE, parser
from .check_cmd import cmd_check, cmd_check_answers
from .parallel import tune_gc
from .solving import UserError, load_study, located, solve_study, results_text
from ..scene.reader import SceneError
from ..study.study import Study
from ..study.worked import builtin_example, sheet_for, sheets_for  # noqa: F401  (sheet_for: API)
from ..scene.textsafe import safe_streams


def render_one(path: Path, out: Path, formats: Sequence[str], paper: str | None,
               lab: str | None = None) -> tuple[str | None, str, int]:
    """Render one scene: ``(error, text, code)`` -- the one-line error (None when it rendered), what to
    print (its results and the files written) and the exit code it stands for (0, or the UserError's: the
    same as ``solve`` and ``check`` give for the scene).  ``lab``: the problem sheet and the answer key beside the worked
    solution (drafting.app.lab), all written together ("bare": the problem sheet without its steps)."""
    from ..backends.files import ExportError
    from ..render.errors import LayoutError
    try:
        study = load_study(path, paper)
        if lab:
            from .lab import dimensioned
            study = Study(dimensioned(study.scene))
        study = solve_study(study)
        try:
            sheet_formats = [f for f in formats if f != PAGE]
            written = _write_together(study, out, path.stem, sheet_formats, PAGE in formats, lab)
        except ExportError as e:                  # names the output file it could not write
            raise UserError(f"{path}: {e}") from None
        except LayoutError as e:                  # the sheet: the paper is what the user can change
            raise UserError(f"{path}: drawing.paper: {e}") from None
        except ConstructionError as e:            # raised while drawing: told at its position
            raise UserError(f"{path}: {located(study, e)}") from None
    except UserError as e:
        return str(e), "", e.code
    return None, "\n".join([results_text(study)] + [f"  wrote {w}" for w in written]), 0


def _write_together(study: Study, out: Path, stem: str, sheet_formats: Sequence[str], page: bool,
                    lab: str | None) -> list[Path]:
    """The sheets of one render (with ``lab``, the problem sheet, worked solution and key) and, with
    ``page``, its step-through page: one plan, all written together or not at all (a full disk or a
    signal while the page is written leaves no sheet either)."""
    from ..backends.files import prepare_folder, remove_stale_temporaries, sheet_plan, write_outputs
    sheets = sheets_for(study) if page or (sheet_formats and not lab) else []     # laid out once
    if lab:
        from ..layout.sheet import source_date_epoch
        from .lab import lab_for, lab_plan
        plan = lab_plan(lab_for(study, epoch=source_date_epoch(), bare=lab == "bare"), out, stem,
                        sheet_formats)
    else:
        plan = sheet_plan(sheets, out, stem, sheet_formats) if sheet_formats else []
    if page:
        from ..backends.html_page import page_plan
        plan += page_plan(study, sheets, out, stem)
    prepare_folder(out)
    remove_stale_temporaries(out)
    return write_outputs(out, stem, plan)


def _render_job(job: tuple) -> tuple[str | None, str, int]:
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
    failed = [0]                           # the highest exit code of a scene that failed
    ready: dict[int, tuple[str | None, str, int]] = {}
    shown = [0]

    def on_done(i: int, result) -> None:
        ready[i] = result
        while shown[0] in ready:
            err, text, code = ready.pop(shown[0])
            if err is not None:
                print(f"drafting: error: {err}", file=sys.stderr)
                failed[0] = max(failed[0], code)
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
    return failed[0]


def _is_tty(stream) -> bool:
    try:
        return bool(getattr(stream, "unescaped", stream).isatty())
    except (AttributeError, ValueError):
        return False


def cmd_solve(path: Path, as_json: bool, csv_path: Path | None = None) -> int:
    study = solve_study(load_study(path))
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


def cmd_bench(quick: bool, peers: bool = False, gallery: bool = False, as_json: bool = False) -> int:
    from .bench import BenchmarksMissing, run_benchmarks, run_gallery
    if as_json and not gallery:
        raise UserError("bench --json goes with --gallery")
    try:
        print(run_gallery(quick=quick, as_json=as_json) if gallery else run_benchmarks(quick=quick, peers=peers))
    except BenchmarksMissing as e:             # installed without the checkout: one sentence, exit 2
        raise UserError(f"bench {'--gallery' if gallery else '--peers'}: {e}") from None
    return 0


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
        if args.command == "lint":
            from .lint_cmd import cmd_lint
            return cmd_lint(args.scenes, args.json)
        if args.command == "bench":
            return cmd_bench(args.quick, args.peers, args.gallery, args.json)
        if args.command == "export":
            from .cam_export import run_export
            return run_export(args)
        if args.command == "serve":
            from ..serve.command import cmd_serve
            return cmd_serve(args.target, args.port)
        if args.command == "keys":
            from .keys_cmd import cmd_keys
            return cmd_keys(args.kind, args.markdown)
        if args.command == "new":
            from .new_cmd import cmd_new
            return cmd_new(args.kind, args.example, args.out)
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
