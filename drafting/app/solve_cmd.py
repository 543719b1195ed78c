"""``drafting solve SCENE [--json] [--csv FILE]``: the scene's results in its units and the analyses that ran."""

from __future__ import annotations

import argparse
import json
from pathlib import Path

from .solving import UserError, load_study, results_text, solve_study
from ..scene.textsafe import shown_path


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
            raise UserError(f"{shown_path(path)}: --csv: {e}") from None
        if not as_json:
            print(f"  wrote {csv_path}")
    return 0


def run_command(args: argparse.Namespace) -> int:
    return cmd_solve(args.scene, args.json, args.csv)
