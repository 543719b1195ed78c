"""``drafting batch SCENE --variants N --seed S -o DIR``: N deterministic variants of a scene's lab sheets.

Each variant draws the values of the scene's ``[vary]`` ranges (:mod:`drafting.scene.vary`) from
``numpy.random.default_rng([S, i])`` and writes, together or not at all, its problem sheet, worked
solution and key (:mod:`drafting.app.lab`) as ``DIR/<scene>-v007-problem.pdf``, ``DIR/<scene>-v007.pdf``,
``DIR/<scene>-v007-key.pdf`` and ``DIR/<scene>-v007-key.csv``; when all are done, every key as one CSV,
``DIR/<scene>-keys.csv`` (a row per variant: its varied values and each answer, units in the headers).

The same scene and seed give byte-identical files: the values depend only on S and i, the variants are
written by whichever worker but from the same inputs, and every date is one moment fixed before the
batch starts -- SOURCE_DATE_EPOCH when set, else the start of today (UTC), so a batch run twice on one day
is the same.  A draw that cannot be assembled or sits at a singular position is drawn again from the same
generator (up to :data:`TRIES` draws) and the batch notes it; a variant with no good draw is skipped with
a note.  The variants run over any :class:`concurrent.futures.Executor` (:mod:`drafting.app.parallel`).
"""

from __future__ import annotations

import csv
import io
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Sequence
from ..scene.textsafe import shown_path

TRIES = 20
"""Draws a variant may take before it is skipped."""


@dataclass(frozen=True)
class VariantJob:
    data: dict
    path: str
    index: int
    seed: int
    out: str
    stem: str
    formats: tuple[str, ...]
    epoch: int


@dataclass
class VariantResult:
    index: int
    values: list[tuple[str, str]] = field(default_factory=list)     # (header, value in its unit)
    notes: list[str] = field(default_factory=list)
    columns: list[tuple[str, str]] = field(default_factory=list)    # the key as (header, value) cells
    files: list[str] = field(default_factory=list)
    error: str | None = None

    @property
    def skipped(self) -> bool:
        return not self.files and self.error is None


def variant_stem(stem: str, index: int) -> str:
    return f"{stem}-v{index:03d}"


def variant_study(data: dict, path: Path, seed: int, index: int, notes: list[str] | None = None):
    """The solved study of variant ``index`` of seed ``seed`` (its scene dimensioned, as a lab draws it)
    and its varied values ``[(header, value)]``, or ``(None, [])`` when no draw of :data:`TRIES` can be
    drawn.  Each draw drawn again is told in ``notes``."""
    import numpy as np
    from constructions.errors import ConstructionError
    from .lab import dimensioned
    from ..scene.reader import SceneError, scene_from_data
    from ..study.study import Study
    from ..scene.vary import draw, variant_data

    base = scene_from_data(_plain_data(data), path)
    study = Study(base).check()                         # the family's checks of the scene, as a render's
    ranges = study.family.vary(data, path, base.units)
    rng = np.random.default_rng([seed, index])
    for attempt in range(1, TRIES + 1):
        ks = draw(ranges, rng)
        said = ", ".join(f"{r.key} = {r.text(k)}" for r, k in zip(ranges, ks))
        try:
            scene = scene_from_data(variant_data(data, ranges, ks, index), path)
            study = Study(dimensioned(scene)).run()
        except (ConstructionError, SceneError) as e:
            if notes is not None:
                notes.append(f"variant {index}: draw {attempt} ({said}) drawn again: {_short(e)}")
            continue
        return study, [(r.header, r.text(k).split(" ", 1)[0]) for r, k in zip(ranges, ks)]
    if notes is not None:
        notes.append(f"variant {index}: skipped, none of {TRIES} draws could be drawn")
    return None, []


def variant_label(index: int) -> str:
    return f"variant {index}"


def run_variant(job: VariantJob) -> VariantResult:
    """Draw, solve and write one variant (runs in a worker)."""
    from constructions.errors import ConstructionError
    from ..backends.files import ExportError, write_outputs
    from ..render.errors import LayoutError
    from .lab import lab_for, lab_plan

    path = Path(job.path)
    res = VariantResult(job.index)
    study, values = variant_study(job.data, path, job.seed, job.index, res.notes)
    if study is None:
        return res
    res.values = values
    try:
        lab = lab_for(study, epoch=job.epoch, label=variant_label(job.index))
        stem = variant_stem(job.stem, job.index)
        out = Path(job.out)
        extra = [("variant", str(job.index))] + values
        plan = lab_plan(lab, out, stem, job.formats, epoch=job.epoch, csv_extra=extra)
        res.files = [str(p) for p in write_outputs(out, stem, plan)]
    except LayoutError as e:                   # as render says it: the paper is what the user can change
        res.error = f"{shown_path(path)}: variant {job.index}: drawing.paper: {e}"
        return res
    except (ExportError, ConstructionError) as e:
        res.error = f"{shown_path(path)}: variant {job.index}: {e}"
        return res
    res.columns = _key_columns(lab)
    return res


def _plain_data(data: dict) -> dict:
    return {k: v for k, v in data.items() if k != "vary"}


def _short(e: Exception) -> str:
    text = str(e)
    return text.split(": ", 1)[1] if text.startswith(("<", "/")) and ": " in text else text


def _key_columns(lab) -> list[tuple[str, str]]:
    """The key as wide CSV cells: "V_C (mm/s)", "V_C direction (deg)", "omega_2 (rad/s, CCW +)"."""
    from constructions.geometry import Vec
    u = lab.units
    cells: list[tuple[str, str]] = []
    for i in lab.items:
        sym = u.symbol(i.kind)
        if isinstance(i.value, Vec):
            cells.append((f"{i.name} ({sym})", f"{u.convert(i.kind, i.value.norm()):.10g}"))
            cells.append((f"{i.name} direction (deg)", f"{i.direction:.10g}"))
        elif i.kind in ("angular velocity", "angular acceleration", "torque"):
            cells.append((f"{i.name} ({sym}, CCW +)", f"{u.convert(i.kind, float(i.value)):.10g}"))
        else:
            cells.append((f"{i.name} ({sym})", f"{u.convert(i.kind, float(i.value)):.10g}"))
    return cells


def keys_csv(results: Sequence[VariantResult]) -> str:
    """Every variant's key as one CSV: variant, the varied values, each answer (units in the headers)."""
    done = [r for r in results if r.files]
    header: list[str] = ["variant"]
    for r in done:
        for h, _ in r.values + r.columns:
            if h not in header:
                header.append(h)
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(header)
    for r in done:
        row = dict(r.values + r.columns)
        row["variant"] = str(r.index)
        w.writerow([row.get(h, "") for h in header])
    return buf.getvalue()


def batch_epoch() -> int:
    """The moment every file of a batch is dated: SOURCE_DATE_EPOCH, else the start of today (UTC)."""
    from ..layout.sheet import source_date_epoch
    e = source_date_epoch()
    if e is not None:
        return e
    now = int(time.time())
    return now - now % 86400


def run_batch(scene_path: Path | str, variants: int, seed: int, out: Path | str,
              formats: Sequence[str] = ("pdf",), *, executor=None, progress=None, epoch: int | None = None,
              workers: int | None = None) -> list[VariantResult]:
    """Make ``variants`` variants of the scene into ``out`` (see the module docstring) and the combined
    keys CSV; returns each variant's result in order.  ``progress`` has ``update(done)`` and
    ``finish()``.  Raises SceneError for a bad scene (or one without ``[vary]``) and ExportError when the
    output folder cannot be written."""
    import tomllib
    from . import parallel
    from ..backends.files import ExportError, prepare_folder, remove_stale_temporaries, write_outputs
    from ..scene.reader import SceneError, _read_text, parse_scene
    from ..study.study import Study
    path = Path(scene_path)
    text = _read_text(path)
    scene = parse_scene(text, path)                     # every check of the scene, [vary] included
    Study(scene).check()
    data = tomllib.loads(text)
    if "vary" not in data:
        raise SceneError(path, "vary", "is missing: a batch needs the ranges to draw from, e.g. "
                                       "[vary] crank_angle = [\"30 deg\", \"150 deg\"]")
    del scene
    out = Path(out)
    prepare_folder(out)
    remove_stale_temporaries(out)
    epoch = batch_epoch() if epoch is None else epoch
    jobs = [VariantJob(data, str(path), i, seed, str(out), path.stem, tuple(formats), epoch)
            for i in range(1, variants + 1)]
    done = [0]

    def on_done(i, r):
        done[0] += 1
        if progress is not None:
            progress.update(done[0])
    results = parallel.run(run_variant, jobs, executor=executor, on_done=on_done, folders=[out], workers=workers)
    if progress is not None:
        progress.finish()
    text_csv = keys_csv(results)
    keys = out / f"{path.stem}-keys.csv"
    if any(r.files for r in results):
        try:
            write_outputs(out, path.stem, [(keys, lambda: text_csv.encode("utf-8"))])
        except ExportError:
            raise
    return results
