"""``drafting check``: graphical against analytic for each scene, or a student's answers marked against the
scene's key (or a batch variant's) at drawing accuracy."""

from __future__ import annotations

import argparse
import sys
import tomllib
from pathlib import Path
from typing import Sequence

from .answers import AnswersError, mark, read_answers
from .batch import variant_label, variant_study
from .lab import dimensioned, lab_for
from .solving import EXIT_DISAGREE, UserError, load_study, results_text, solve_study
from ..render.errors import LayoutError
from ..scene.reader import SceneError, _read_text, parse_scene
from ..study.study import Study
from ..scene.textsafe import shown_path


def cmd_check(scenes: Sequence[Path]) -> int:
    """Check every scene; a scene that cannot be read or solved is reported in one line and the others are
    still checked (as render does).  Exit: the worst of 1 (disagreement), 3 (singular), 2 (bad input)."""
    status = 0
    for path in scenes:
        try:
            study = solve_study(load_study(path))
        except UserError as e:
            print(f"drafting: error: {e}", file=sys.stderr)
            status = max(status, e.code)
            continue
        print(results_text(study))
        if study.comparisons and study.model is None:
            print(f"  {shown_path(path)}: no analytic model for this mechanism; nothing checked")
        if study.disagreements():
            status = max(status, EXIT_DISAGREE)
    return status


def cmd_check_answers(path: Path, answers: Path, variant: int | None, seed: int | None) -> int:
    """Mark a student's values against the scene's key (or a batch variant's) at drawing accuracy: one
    line per item, right / wrong / missing with the expected value.  Exit 1 unless every item is right."""
    label = ""
    try:
        rows = read_answers(answers)          # first: a file too large or malformed is refused before solving
    except AnswersError as e:
        raise UserError(str(e)) from None
    if variant is not None:
        if seed is None:
            raise UserError(f"{shown_path(path)}: --variant needs the batch's --seed")
        try:
            text = _read_text(path)
            parse_scene(text, path)
            data = tomllib.loads(text)
        except SceneError as e:
            raise UserError(str(e)) from None
        if "vary" not in data:
            raise UserError(f"{shown_path(path)}: vary: is missing, so the scene has no variants")
        notes: list[str] = []
        try:
            study, _ = variant_study(data, path, seed, variant, notes)
        except SceneError as e:
            raise UserError(str(e)) from None
        if study is None:
            raise UserError(f"{shown_path(path)}: vary: variant {variant} of seed {seed} was skipped by the batch (no draw could "
                            f"be drawn)")
        label = variant_label(variant)
    else:
        study = solve_study(Study(dimensioned(load_study(path).scene)))
    try:
        items = lab_for(study, label=label).items     # the key's scales are the worked sheet's: laid out
    except LayoutError as e:                  # as render says it: the paper is what the user can change
        raise UserError(f"{shown_path(path)}: drawing.paper: {e}") from None
    if not items:
        raise UserError(f"{shown_path(path)}: ask.analyses: the scene has no answers to mark (it asks for "
                        f"{', '.join(study.scene.analyses)})")
    try:
        marks, unknown = mark(items, rows, answers, study.scene.units)
    except AnswersError as e:
        raise UserError(str(e)) from None
    width = max(len(m.item.shown) for m in marks)
    title = study.scene.title + (f" ({label})" if label else "")
    print(f"{title}: {shown_path(answers)} marked at drawing accuracy")
    for m in marks:
        print(m.line(width))
    counts = {v: sum(1 for m in marks if m.verdict == v) for v in ("right", "wrong", "missing")}
    print(f"  {counts['right']} right, {counts['wrong']} wrong, {counts['missing']} missing of {len(marks)}")
    for name in unknown:
        print(f"  note: {shown_path(answers)}: {name!r} is not a quantity of this scene; it asks for "
              f"{', '.join(i.shown for i in items)}")
    return 0 if counts["right"] == len(marks) else EXIT_DISAGREE


def run_command(args: argparse.Namespace) -> int:
    """``drafting check SCENE...``, or with ``--answers`` one scene's answers marked."""
    if args.answers is not None:
        if len(args.scenes) != 1:
            raise UserError("--answers marks the answers to one scene; give one SCENE")
        return cmd_check_answers(args.scenes[0], args.answers, args.variant, args.seed)
    if args.variant is not None or args.seed is not None:
        raise UserError("--variant and --seed go with --answers")
    return cmd_check(args.scenes)
