"""``drafting render`` (and ``drafting`` alone, the built-in example): each scene's sheets as SVG, PDF and
PNG, with ``--format html`` its step-through page, with ``--lab`` its problem sheet and answer key."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path
from typing import Sequence

from constructions.errors import ConstructionError

from . import progress
from .arguments import DEFAULT_OUT, FORMATS, PAGE
from .solving import UserError, load_study, located, solve_study, results_text
from ..study.study import Study
from ..study.worked import builtin_example, sheets_for
from ..scene.textsafe import shown_path


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
            raise UserError(f"{shown_path(path)}: {e}") from None
        except LayoutError as e:                  # the sheet: the paper is what the user can change
            raise UserError(f"{shown_path(path)}: drawing.paper: {e}") from None
        except ConstructionError as e:            # raised while drawing: told at its position
            raise UserError(f"{shown_path(path)}: {located(study, e)}") from None
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
    bar = progress.Progress(len(scenes), "render")
    bar.shown = len(scenes) >= 2 and progress.is_tty(sys.stderr)
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


def run_command(args: argparse.Namespace) -> int:
    """``drafting render ...``, or with no command the built-in example into ./drafting-output."""
    if args.command is None:
        return cmd_render([builtin_example()], DEFAULT_OUT, FORMATS, None)
    return cmd_render(args.scenes, args.out, args.format, args.paper, args.lab, workers=args.workers)
