"""``drafting sweep SCENE [--steps N | --every 5deg] [--csv FILE]``: a linkage over one turn of its crank.

The crank angles start at the scene's crank angle and cover one turn (N steps, default 72, or every X
degrees or radians).  With ``--csv`` the table is written in the scene's units, units in the header,
empty cells where the mechanism cannot be assembled (gaps), atomically (a temporary file beside the
destination renamed into place).  Without it a short summary is printed.

Errors are :class:`SweepInputError`, which :func:`run_command` turns into the command's one-line
``drafting: error: ...`` and exit 2.
"""

from __future__ import annotations

import csv
import io
import math
from pathlib import Path

import numpy as np

from ..scene import limits
from .progress import Progress
from .solving import UserError
from ..families.registry import families, family
from ..scene.reader import SceneError, load_scene
from ..study.study import Study
from ..scene.textsafe import printable, shown_path
from ..scene.units import UnitError, to_si, unit_symbol, with_unit

DEFAULT_STEPS = 72


class SweepInputError(Exception):
    """Bad input to a sweep: one sentence (the file, the option)."""


def crank_angles(start: float, steps: int | None, every: str | None) -> np.ndarray:
    """One turn of crank angles from ``start`` (rad): ``steps`` equal steps, or one every ``every``
    (a value with an angle unit; a plain number is in degrees).  Raises SweepInputError."""
    turn = 2 * math.pi
    if every is not None:
        try:
            step = to_si(every, "angle", "deg")
        except UnitError as e:
            raise SweepInputError(f"--every: {e}") from None
        if not step > 0:
            raise SweepInputError(f"--every: {printable(every)!r} is not a positive angle")
        count = turn / step                    # inf for a step below the smallest float's turn
        if not count <= limits.MAX_SWEEP_STEPS + 1e-9:
            raise SweepInputError(f"--every: {printable(every)!r} gives more than {limits.MAX_SWEEP_STEPS:,} steps, "
                                  f"the most a sweep may have (use a larger --every or --steps)")
        n = math.ceil(count - 1e-9)
        return start + step * np.arange(n)
    n = DEFAULT_STEPS if steps is None else steps
    problem = limits.sweep_problem(n)
    if problem:
        raise SweepInputError(f"--steps: {problem}")
    return start + turn * np.arange(n) / n


def run_sweep(path: Path, steps: int | None = None, every: str | None = None):
    """(scene, sweep) for the scene file at ``path``, the sweep run by the scene's study (the family's
    sweeping analysis, :attr:`~drafting.families.registry.Family.sweeps`).  Raises SweepInputError."""
    from constructions.errors import ConstructionError
    try:
        scene = load_scene(path)
        Study(scene).check()
    except SceneError as e:
        raise SweepInputError(str(e)) from None
    fam = family(scene.kind)
    if fam.sweeps is None:
        kinds = " or ".join(sorted(k for k, f in families().items() if f.sweeps is not None))
        raise SweepInputError(f"{shown_path(path)}: a sweep needs a {kinds} scene, not a {scene.kind} scene")
    why = fam.cannot_sweep(scene)
    if why is not None:
        raise SweepInputError(f"{shown_path(path)}: {why}")
    thetas = crank_angles(scene.angle, steps, every)
    bar = Progress(thetas.size, "sweep")
    study = Study(scene, {"crank angles": thetas, "progress": lambda i, n: bar.update(i)})
    try:
        result = study.get(fam.sweeps)
    except ConstructionError as e:
        raise SweepInputError(f"{shown_path(path)}: {e}") from None
    finally:
        bar.finish()
    return scene, result


def _unit(units, kind: str) -> str:
    return unit_symbol(units.of(kind))


def table(scene, s) -> tuple[list[str], np.ndarray]:
    """The CSV header and the values (one row per crank angle) in the scene's units (NaN at gaps)."""
    u = scene.units
    ua, ul, uv, uacc = (_unit(u, k) for k in ("angle", "length", "velocity", "acceleration"))
    uw, ual = _unit(u, "angular velocity"), _unit(u, "angular acceleration")
    header = [f"crank angle [{ua}]"]
    turn = u.convert("angle", 2 * math.pi)
    # the crank angle from the scene's own round one turn, written within one turn (375 -> 15)
    cols: list[np.ndarray] = [np.mod(significant(np.array([u.convert("angle", float(t)) for t in s.thetas])), turn)]
    for name in s.positions:
        for label, src, kind, unit in (("", s.positions, "length", ul), ("v", s.velocities, "velocity", uv),
                                       ("a", s.accelerations, "acceleration", uacc)):
            if name not in src:
                continue
            scale = u.convert(kind, 1.0)        # every unit here is linear in SI
            for axis, arr in zip("xy", src[name]):
                header.append(f"{name} {label}{axis} [{unit}]")
                cols.append(np.asarray(arr) * scale)
    for number in s.angular:
        header.append(f"omega_{number} [{uw}]")
        cols.append(np.asarray(s.angular[number]) * u.convert("angular velocity", 1.0))
        if number in s.angular_acceleration:
            header.append(f"alpha_{number} [{ual}]")
            cols.append(np.asarray(s.angular_acceleration[number]) * u.convert("angular acceleration", 1.0))
    return header, np.column_stack(cols) if cols else np.empty((0, 0))


SIGNIFICANT = 12
"""Digits a CSV keeps, counted from the largest value of each column: the engine agrees with the closed forms
to ~1e-9 of a quantity's scale, so 12 digits hold everything it knows and none of the rounding noise of the
last bits (59.99999999999999 is written 60.0, and a velocity of 4.4e-14 mm/s in a column of hundreds 0.0)."""

_EXACT_POWER = 22
"""10**k is a float exactly up to k = 22: dividing or multiplying by it rounds once, to the nearest float of
the decimal, whose shortest repr then has at most :data:`SIGNIFICANT` digits."""


def significant(values: np.ndarray) -> np.ndarray:
    """``values`` (a column, or a table of columns) rounded to a fixed number of decimals per column: those that
    keep :data:`SIGNIFICANT` significant digits of the column's largest finite magnitude.  Non-finite values
    are kept, -0.0 becomes 0.0; a column whose largest value is below 1e-11 is rounded value by value."""
    v = np.array(values, dtype=float)
    cols = v.reshape(v.shape[0], -1) if v.ndim else v.reshape(1, 1)
    for j in range(cols.shape[1]):
        c = cols[:, j]
        finite = np.isfinite(c)
        big = float(np.max(np.abs(c[finite]))) if finite.any() else 0.0
        if big == 0.0:
            continue
        k = SIGNIFICANT - 1 - math.floor(math.log10(big))      # decimals to keep
        with np.errstate(invalid="ignore", over="ignore"):
            if 0 <= k <= _EXACT_POWER:
                r = np.round(c * 10.0 ** k) / 10.0 ** k
            elif -_EXACT_POWER <= k < 0:
                r = np.round(c / 10.0 ** -k) * 10.0 ** -k
            else:                                              # a column of tiny values: digits by text
                r = np.array([float(f"{x:.{SIGNIFICANT}g}") for x in c])
        cols[:, j] = np.where(finite, r + 0.0, c)
    return cols.reshape(v.shape)


def rows_of(values: np.ndarray):
    """The CSV lines of a table's values: shortest round-trip decimals, empty cells at gaps (a row of only
    finite values joined at once, its floats read out of numpy together: a third faster at 1e5 rows; a
    gap's row -- its crank angle and nothing else -- written at once too)."""
    finite = np.isfinite(values)
    whole = finite.all(axis=1).tolist()
    gap = (finite[:, 0] & ~finite[:, 1:].any(axis=1)).tolist() if values.ndim == 2 and values.shape[1] else whole
    empty = "," * (values.shape[1] - 1) if values.ndim == 2 and values.shape[1] else ""
    for full, bare, row in zip(whole, gap, values.tolist()):
        if full:
            yield ",".join(map(repr, row))
        elif bare:
            yield repr(row[0]) + empty
        else:
            yield ",".join(repr(v) if math.isfinite(v) else "" for v in row)


def write_csv(path: Path, header: list[str], values: np.ndarray) -> None:
    """Write atomically: a temporary file beside ``path``, then os.replace, with a progress bar on a
    terminal for long tables.  Raises SweepInputError."""
    path = Path(path)
    folder = path.parent if str(path.parent) else Path(".")
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(header)
    bar = Progress(len(values), "csv")
    for i, line in enumerate(rows_of(significant(values))):
        buf.write(line + "\n")
        if i % 4096 == 0:
            bar.update(i)
    bar.finish()
    data = buf.getvalue().encode("utf-8")
    from ..backends.files import ExportError, prepare_folder, write_outputs
    try:
        if path.is_dir():
            raise ExportError(f"Cannot write {shown_path(path)}: it is a folder.")
        prepare_folder(folder)                 # as solve --csv: the folder made when missing
        write_outputs(folder, path.stem, [(path, lambda: data)])
    except ExportError as e:
        raise SweepInputError(str(e)) from None


def _fmt(v: float) -> str:
    return f"{v:.6g}" if math.isfinite(v) else "-"


def summary(scene, s) -> str:
    """A short summary: angles swept, how many assembled, the gaps' angular ranges, and each link's
    omega and alpha extremes (scene units)."""
    u = scene.units
    ua = u.symbol("angle")
    ang = [u.convert("angle", float(t)) for t in s.thetas]
    n, ok = s.thetas.size, int(np.count_nonzero(s.assembles))
    step = (ang[1] - ang[0]) if n > 1 else 0.0
    turn = u.convert("angle", 2 * math.pi)
    ang = [float(a) for a in np.mod(significant(np.array(ang)), turn)]      # within one turn: 415 -> 55
    lines = [scene.title,
             f"  {n} crank angles from {with_unit(_fmt(ang[0]), ua)} round one turn in steps of "
             f"{with_unit(_fmt(step), ua)} (to {with_unit(_fmt(ang[-1]), ua)}), {s.model}: {ok} assembled"]
    gaps = s.gaps()
    if gaps:
        spans = ", ".join(f"{_fmt(ang[i])}..{with_unit(_fmt(ang[j - 1]), ua)}" for i, j in gaps)
        lines.append(f"  cannot be assembled (gaps, {n - ok} angles): {spans}")
    if s.change_points:
        at = ", ".join(with_unit(_fmt(u.convert('angle', a)), ua) for a in s.change_points)
        lines.append(f"  passes a change point (all links in line) at {at} and stays on its branch")
    uw, ual = u.symbol("angular velocity"), u.symbol("angular acceleration")
    rows = [("link", f"omega min [{uw}]", f"omega max [{uw}]", f"alpha min [{ual}]", f"alpha max [{ual}]")]
    for k, w in s.angular.items():
        a = s.angular_acceleration.get(k)

        def ext(x, kind):
            x = np.asarray(x)[np.isfinite(x)] if x is not None else np.array([])
            if x.size == 0:
                return "-", "-"
            return _fmt(u.convert(kind, float(x.min()))), _fmt(u.convert(kind, float(x.max())))
        rows.append((str(k),) + ext(w, "angular velocity") + ext(a, "angular acceleration"))
    widths = [max(len(r[i]) for r in rows) for i in range(5)]
    for k, r in enumerate(rows):
        lines.append("  " + "  ".join(c.rjust(wd) if k and i else c.ljust(wd)
                                      for i, (c, wd) in enumerate(zip(r, widths))).rstrip())
    return "\n".join(lines)


def write_cycle_sheet(scene, out_dir: Path) -> list[str]:
    """The scene's cycle sheet (analyses = ["sweep"]: charts against the crank angle, coupler curves, limit
    positions) as SVG, PDF and PNG in ``out_dir``, named <scene>-cycle.  Raises SweepInputError."""
    from dataclasses import replace
    from constructions.errors import ConstructionError
    from ..render.errors import LayoutError
    from ..backends.files import ExportError, write_sheets
    from ..study.worked import sheets_for
    study = Study(replace(scene, analyses=("sweep",), find=None))
    try:
        study.run()
        return [str(w) for w in write_sheets(sheets_for(study), out_dir, f"{scene.path.stem}-cycle")]
    except (ExportError, LayoutError, ConstructionError) as e:
        raise SweepInputError(f"{shown_path(scene.path)}: --sheet: {e}") from None


def cmd_sweep(path: Path, steps: int | None, every: str | None, csv_path: Path | None,
              sheet_dir: Path | None = None) -> int:
    """The command: write the CSV (and say so) or print the summary; with ``sheet_dir`` also the cycle
    sheet.  Raises SweepInputError."""
    scene, s = run_sweep(path, steps, every)
    if csv_path is not None:
        header, values = table(scene, s)
        try:
            write_csv(csv_path, header, values)
        except SweepInputError as e:           # named as solve --csv names it: the scene, the option
            raise SweepInputError(f"{shown_path(path)}: --csv: {e}") from None
        gaps = s.thetas.size - int(np.count_nonzero(s.assembles))
        print(f"{scene.title}\n  {s.thetas.size} crank angles ({s.model}), {gaps} not assembled; "
              f"wrote {printable(str(csv_path))}")
    else:
        print(summary(scene, s))
    if sheet_dir is not None:
        for w in write_cycle_sheet(scene, sheet_dir):
            print(f"  wrote {printable(w)}")
    return 0


def run_command(args) -> int:
    try:
        return cmd_sweep(args.scene, args.steps, args.every, args.csv, args.sheet)
    except SweepInputError as e:
        raise UserError(str(e)) from None
