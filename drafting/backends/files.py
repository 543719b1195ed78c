"""Export: sheets to SVG, PDF and PNG files, all of one scene written together or not at all.

:func:`write_sheets` writes the pages of one scene: one sheet gives ``stem.svg``, ``stem.pdf`` and
``stem.png``; n > 1 sheets give ``stem-1.svg`` .. ``stem-n.svg``, one ``stem.pdf`` of n pages and
``stem-1.png`` .. ``stem-n.png``.  :func:`write_sheet` is the one-sheet case, :func:`save_sheet` one
sheet to one file whose suffix names the format (``sheet.save(path)`` of the API).

How the files are kept whole, whatever happens:

- Before anything is written every final name is checked (an existing folder under a final name
  refuses the whole scene), and every file is produced in memory.
- Each file is written to a temporary file beside its destination, named
  ``.drafting-tmp-<pid>-<n>-<stem>.<format>`` (so the final rename stays on one file system and a
  leftover is recognisable), flushed and fsynced.  The temporary files are registered with
  :mod:`drafting.backends.faults` before they are created, so an interrupt (SIGINT, SIGTERM) removes them.
- Only when all are written are they renamed into place, with interrupts held back for the moment of
  the renames; should a rename fail, the files already renamed are put back as they were.
- Any failure -- a full disk (ENOSPC), a read-only folder, a conversion error -- removes every
  temporary file and raises one :class:`ExportError` sentence naming the path.
- Leftovers of an earlier run that was killed (``kill -9``, a power cut) are removed by the next run
  that writes into the folder: temporary files whose process is gone, or that are older than an hour.

The SVG is written by :mod:`drafting.backends.svg`; the PDF and PNG are the same commands drawn with cairo by
:mod:`drafting.backends.cairo` (not the SVG parsed back).  Every sheet is sized in mm, so the PDF page is
exactly the paper size and a length of 100 mm on the sheet is 100 mm on the printed PDF; the pages of
a multi-page PDF are the pages of one cairo PDF surface.
"""

from __future__ import annotations

import io
import itertools
import os
import re
import stat
import time
from pathlib import Path
from typing import Callable, Sequence

from . import cairo as cairo_out, faults
from ..layout.sheet import Sheet
from .svg import sheet_to_svg
from ..scene.textsafe import printable, shown_path

FORMATS = ("svg", "pdf", "png")
PNG_DPI = 150.0
TEMP_PREFIX = ".drafting-tmp-"
STALE_AFTER_SECONDS = 3600.0
_TEMP_NAME = re.compile(r"\.drafting-tmp-(\d{1,10})-")
_counter = itertools.count(1)


class ExportError(Exception):
    """An output file or folder cannot be written; the message names the path."""


def _convert_pdf_pages(sheets: Sequence[Sheet], fh, epoch: int | None = None) -> None:
    """One PDF with a page per sheet, drawn with cairo straight from the commands (drafting.backends.cairo)."""
    fh.write(cairo_out.sheets_to_pdf(sheets, epoch))


def _convert_png(sheet: Sheet, fh, dpi: float) -> None:
    fh.write(cairo_out.sheet_to_png(sheet, dpi))


# -- temporary files -----------------------------------------------------------------------------------

def _pid_alive(pid: int) -> bool:
    if pid <= 0:
        return False
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        return True                     # it exists, under another user
    except (OSError, OverflowError, ValueError):
        return False
    return True


def remove_stale_temporaries(out_dir: Path | str) -> list[Path]:
    """Remove temporary files an earlier run left in ``out_dir`` (killed with ``kill -9``, a power cut):
    files named ``.drafting-tmp-<pid>-...`` whose process is gone, or that are older than an hour.
    Files this process is writing are left alone.  Returns what was removed."""
    removed: list[Path] = []
    now = time.time()
    try:
        entries = list(os.scandir(out_dir))
    except OSError:
        return removed
    # what this process is writing, asked after the folder was read: a write registers its temporary
    # before creating it, so every temporary of ours seen above is in this set, however the threads ran
    # (asked before, another thread's write begun in between was taken for a leftover and removed)
    ours = faults.tracked()
    for e in entries:
        m = _TEMP_NAME.match(e.name)
        if not m or e.path in ours:
            continue
        try:
            st = e.stat(follow_symlinks=False)
        except OSError:
            continue
        if not stat.S_ISREG(st.st_mode):
            continue
        pid = int(m.group(1))
        if pid != os.getpid() and _pid_alive(pid) and now - st.st_mtime < STALE_AFTER_SECONDS:
            continue
        try:
            os.unlink(e.path)
            removed.append(Path(e.path))
        except OSError:
            pass
    return removed


def _temp_name(out_dir: Path, stem: str, fmt: str) -> Path:
    return out_dir / f"{TEMP_PREFIX}{os.getpid()}-{next(_counter)}-{stem[:40]}.{fmt}"


def _create_temp(path: Path) -> int:
    """Create ``path`` exclusively (it was registered with faults.track first); returns the fd."""
    return os.open(path, os.O_WRONLY | os.O_CREAT | os.O_EXCL | getattr(os, "O_CLOEXEC", 0), 0o666)


def _remove(path: Path) -> None:
    try:
        os.unlink(path)
    except FileNotFoundError:
        pass
    except OSError:
        return
    faults.untrack(path)


def _why(e: BaseException) -> str:
    if isinstance(e, OSError):
        return e.strerror or e.__class__.__name__
    text = str(e).strip().rstrip(".") or e.__class__.__name__
    return printable(text.splitlines()[0] if text else text)[:200]


def _show(path: Path) -> str:
    return shown_path(path)


# -- writing -------------------------------------------------------------------------------------------

def prepare_folder(out_dir: Path) -> None:
    try:
        out_dir.mkdir(parents=True, exist_ok=True)
    except OSError as e:
        raise ExportError(f"Cannot create the output folder {_show(out_dir)}: {_why(e)}.") from e
    if not out_dir.is_dir():
        raise ExportError(f"Cannot write to {_show(out_dir)}: it is not a folder.")


def _formats(formats: Sequence[str], out_dir: Path, stem: str) -> list[str]:
    fmts: list[str] = []
    for f in formats:
        f = str(f).lower().lstrip(".")
        if f not in FORMATS:
            raise ExportError(f"Cannot write {_show(out_dir / stem)}.{printable(f)}: unknown format "
                              f"{printable(repr(f))} (use svg, pdf or png).")
        if f not in fmts:
            fmts.append(f)
    return fmts


def output_names(n_sheets: int, stem: str, formats: Sequence[str]) -> list[str]:
    """The file names :func:`write_sheets` writes for ``n_sheets`` sheets, in order."""
    names: list[str] = []
    for f in formats:
        if n_sheets == 1 or f == "pdf":
            names.append(f"{stem}.{f}")
        else:
            names += [f"{stem}-{k}.{f}" for k in range(1, n_sheets + 1)]
    return names


def write_sheets(sheets: Sequence[Sheet], out_dir: Path | str, stem: str, formats: Sequence[str] = FORMATS, *,
                 dpi: float = PNG_DPI, epoch: int | None = None) -> list[Path]:
    """Write the sheets of one scene; returns the paths written, in the order of ``formats``.

    One sheet gives ``stem.svg`` / ``stem.pdf`` / ``stem.png``; n > 1 sheets give ``stem-1.svg`` ..
    ``stem-n.svg``, one ``stem.pdf`` of n pages and ``stem-1.png`` .. ``stem-n.png`` (``dpi`` sets the
    PNG resolution; ``epoch``, seconds since 1970, the PDF's creation date -- else SOURCE_DATE_EPOCH,
    else the clock).  All files appear together or not at all (module docstring); any failure is an
    :class:`ExportError` naming the path.
    """
    out_dir = Path(out_dir)
    plan = sheet_plan(sheets, out_dir, stem, formats, dpi=dpi, epoch=epoch)
    prepare_folder(out_dir)
    remove_stale_temporaries(out_dir)
    return write_outputs(out_dir, stem, plan)


def sheet_plan(sheets: Sequence[Sheet], out_dir: Path | str, stem: str, formats: Sequence[str] = FORMATS, *,
               dpi: float = PNG_DPI, epoch: int | None = None) -> list[tuple[Path, Callable[[], bytes]]]:
    """The ``(final path, produce)`` pairs :func:`write_sheets` writes for one document, every final name
    checked first; several documents' plans may go to one :func:`write_outputs` call (a lab sheet, its
    worked solution and its key are written together or not at all)."""
    out_dir = Path(out_dir)
    sheets = list(sheets)
    fmts = _formats(formats, out_dir, stem)
    if not stem or Path(stem).name != stem or stem in (".", "..") or "\x00" in stem:
        raise ExportError(f"Cannot write {_show(out_dir / stem)}: the file stem must be a plain file name.")
    if not sheets:
        raise ExportError(f"Cannot write {_show(out_dir / stem)}: there is no sheet to write.")

    # every final name, checked before anything is written
    n = len(sheets)
    plan: list[tuple[str, Path, int | None]] = []          # (format, final path, page index or None)
    for f in fmts:
        if n == 1 or f == "pdf":
            plan.append((f, out_dir / f"{stem}.{f}", None if f == "pdf" else 0))
        else:
            plan += [(f, out_dir / f"{stem}-{k + 1}.{f}", k) for k in range(n)]
    check_names([final for _, final, _ in plan], stem)

    # the SVG text only when SVG files are written (PDF and PNG are drawn from the commands)
    svgs = [sheet_to_svg(s).encode("utf-8") for s in sheets] if "svg" in fmts else []

    def produce(f: str, page: int | None) -> bytes:
        buf = io.BytesIO()
        with faults.deferred():                  # cairo calls back into Python: no exception inside
            if f == "svg":
                buf.write(svgs[page])
            elif f == "pdf":
                _convert_pdf_pages(sheets, buf, epoch)
            else:
                _convert_png(sheets[page], buf, dpi)
        return buf.getvalue()

    return [(final, (lambda f=f, page=page: produce(f, page))) for f, final, page in plan]


def check_names(finals: Sequence[Path], stem: str) -> None:
    """Refuse the whole document when a folder has one of its final names (before anything is written)."""
    for final in finals:
        if os.path.isdir(final):
            raise ExportError(f"Cannot write {_show(final)}: a folder has that name; nothing of "
                              f"{printable(stem)} was written.")


def write_outputs(out_dir: Path, stem: str, plan: Sequence[tuple[Path, Callable[[], bytes]]]) -> list[Path]:
    """Write each ``(final path, produce)`` of ``plan`` (all in ``out_dir``) as the bytes ``produce()``
    returns: every file to a temporary beside it first (fsynced), then all renamed into place together, or
    none (module docstring).  Any failure is an :class:`ExportError` naming the path."""
    temps: list[tuple[Path, Path]] = []
    backups: list[Path] = []
    try:
        for final, produce in plan:
            try:
                data = produce()
            except ExportError:
                raise
            except Exception as e:
                raise ExportError(f"Cannot write {_show(final)}: {_why(e)}.") from e
            tmp = _temp_name(out_dir, stem, final.suffix.lstrip(".") or "out")
            faults.track(tmp)
            try:
                fd = _create_temp(tmp)
            except OSError as e:
                faults.untrack(tmp)
                raise ExportError(f"Cannot write to the output folder {_show(out_dir)}: {_why(e)}.") from e
            temps.append((tmp, final))
            try:
                with os.fdopen(fd, "wb") as fh:
                    fh.write(data)
                    fh.flush()
                    os.fsync(fh.fileno())
            except OSError as e:
                raise ExportError(f"Cannot write {_show(final)}: {_why(e)}.") from e
        with faults.deferred():
            return _put_in_place(temps, backups, out_dir, stem)
    finally:
        for tmp, _ in temps:
            _remove(tmp)
        for b in backups:
            _remove(b)


def _put_in_place(temps: list[tuple[Path, Path]], backups: list[Path], out_dir: Path, stem: str) -> list[Path]:
    """Rename every temporary file to its final name; if one rename fails, undo the others (existing
    files are restored from hard-link backups where the file system allows them)."""
    saved: dict[Path, Path] = {}
    for _, final in temps:
        if os.path.lexists(final):
            b = _temp_name(out_dir, stem, "bak")
            faults.track(b)
            try:
                os.link(final, b, follow_symlinks=False)
            except (OSError, NotImplementedError):
                faults.untrack(b)
                continue
            backups.append(b)
            saved[final] = b
    done: list[Path] = []
    for tmp, final in temps:
        try:
            os.replace(tmp, final)
        except OSError as e:
            for d in done:
                try:
                    if d in saved:
                        os.replace(saved[d], d)
                    else:
                        os.unlink(d)
                except OSError:
                    pass
            raise ExportError(f"Cannot write {_show(final)}: {_why(e)}.") from e
        faults.untrack(tmp)
        done.append(final)
    return done


def write_sheet(sheet: Sheet, out_dir: Path | str, stem: str, formats: Sequence[str] = FORMATS, *,
                dpi: float = PNG_DPI) -> list[Path]:
    """Write one sheet as ``out_dir/stem.<format>`` for each format (see :func:`write_sheets`)."""
    return write_sheets([sheet], out_dir, stem, formats, dpi=dpi)


def save_sheet(sheet: Sheet, path: Path | str, *, dpi: float | None = None) -> Path:
    """Write ``sheet`` as SVG, PDF or PNG (the suffix decides), atomically; returns the Path."""
    path = Path(path)
    fmt = path.suffix.lower().lstrip(".")
    if fmt not in FORMATS:
        raise ExportError(f"Cannot write {path}: the suffix must be .svg, .pdf or .png")
    (written,) = write_sheets([sheet], path.parent if str(path.parent) else Path("."), path.stem, [fmt],
                              dpi=dpi or PNG_DPI)
    return written
