"""Render the gallery, or check that today's code renders it byte for byte as it stands.

    python gallery/build.py            # rewrite every sheet of the gallery
    python gallery/build.py --check    # render into a temporary folder; exit 1 naming each file that differs

Every scene here is rendered with ``drafting render`` (``lab-slider-crank.toml`` with ``--lab``: its
problem sheet, worked solution and key), dated GALLERY_DATE through SOURCE_DATE_EPOCH so the same code
gives the same bytes on any day.  A restructuring that changes no sheet leaves ``--check`` silent.
``cam-accuracy-time`` is a benchmark's figure of measured times and is not re-rendered here.
"""

from __future__ import annotations

import argparse
import datetime as _dt
import filecmp
import os
import subprocess
import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent
GALLERY_DATE = _dt.datetime(2026, 11, 23, tzinfo=_dt.timezone.utc)   # the date every sheet's title block shows
LAB_SCENES = ("lab-slider-crank.toml",)                               # rendered with --lab
NOT_RENDERED = ("cam-accuracy-time",)                                 # a benchmark's figure
DRAFTING = [sys.executable, "-c", "import sys; from drafting.entry import main; sys.exit(main())"]


def render(out: Path) -> None:
    """Every gallery sheet into ``out``."""
    env = dict(os.environ, SOURCE_DATE_EPOCH=str(int(GALLERY_DATE.timestamp())))
    scenes = sorted(p for p in HERE.glob("*.toml") if p.name not in LAB_SCENES)
    cmd = [*DRAFTING, "render", *map(str, scenes), "-o", str(out)]
    subprocess.run(cmd, env=env, check=True, stdout=subprocess.DEVNULL)
    for name in LAB_SCENES:
        cmd = [*DRAFTING, "render", str(HERE / name), "--lab", "-o", str(out)]
        subprocess.run(cmd, env=env, check=True, stdout=subprocess.DEVNULL)


def differences(fresh: Path) -> list[str]:
    """What differs between the sheets rendered into ``fresh`` and the gallery's: one line a file."""
    made = {p.name for p in fresh.iterdir()}
    kept = {p.name for p in HERE.iterdir()
            if p.suffix in (".svg", ".pdf", ".png", ".csv") and not p.stem.startswith(NOT_RENDERED)}
    out = [f"not rendered any more: {n}" for n in sorted(kept - made)]
    out += [f"new: {n}" for n in sorted(made - kept)]
    out += [f"differs: {n}" for n in sorted(made & kept)
            if not filecmp.cmp(fresh / n, HERE / n, shallow=False)]
    return out


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--check", action="store_true", help="compare with the gallery instead of rewriting it")
    args = ap.parse_args(argv)
    if not args.check:
        render(HERE)
        return 0
    with tempfile.TemporaryDirectory() as tmp:
        render(Path(tmp))
        diff = differences(Path(tmp))
    for line in diff:
        print(line)
    print(f"gallery: {len(diff)} difference(s)")
    return 1 if diff else 0


if __name__ == "__main__":
    sys.exit(main())
