"""``drafting batch SCENE --variants N --seed S -o DIR``: N variants of the scene's lab sheets
(:mod:`drafting.app.batch`), each variant's files together or not at all, then every key as one CSV."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path
from typing import Sequence

from . import progress
from .arguments import PAGE
from .batch import run_batch
from .parallel import WorkerLost
from .solving import UserError
from ..backends.files import ExportError
from ..scene.reader import SceneError
from ..scene.textsafe import shown_path


def cmd_batch(path: Path, variants: int, seed: int, out: Path, formats: Sequence[str], workers: int | None,
              executor=None) -> int:
    """N variants of the scene's lab sheets (drafting.app.batch); each variant's files together or not at all,
    then every key as one CSV."""
    if variants < 1:
        raise UserError(f"{shown_path(path)}: --variants must be at least 1, not {variants}")
    if variants > MAX_VARIANTS:
        raise UserError(f"{shown_path(path)}: --variants may be at most {MAX_VARIANTS}, not {variants}")
    bar = progress.Progress(variants, "batch")
    bar.shown = progress.is_tty(sys.stderr)
    formats = [f for f in formats if f != PAGE]
    if not formats:
        raise UserError(f"{shown_path(path)}: --format: a batch writes svg, pdf or png (the html page is one per scene)")
    try:
        results = run_batch(path, variants, seed, out, formats, executor=executor, progress=bar, workers=workers)
    except SceneError as e:
        raise UserError(str(e)) from None
    except ExportError as e:
        raise UserError(f"{shown_path(path)}: {e}") from None
    except WorkerLost as e:
        raise UserError(f"{shown_path(path)}: {e}") from None
    failed = 0
    for r in results:
        for n in r.notes:
            print(f"  note: {n}")
        if r.error:
            print(f"drafting: error: {r.error}", file=sys.stderr)
            failed += 1
    done = [r for r in results if r.files]
    print(f"{shown_path(path)}: {len(done)} of {variants} variants (seed {seed}) written to {out}"
          + (f"; every key in {out / (path.stem + '-keys.csv')}" if done else ""))
    return 2 if failed else 0


MAX_VARIANTS = 10_000


def run_command(args: argparse.Namespace) -> int:
    return cmd_batch(args.scene, args.variants, args.seed, args.out, args.format, args.workers)
