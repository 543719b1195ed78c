"""Export: a sheet to SVG, PDF and PNG files, every file written atomically.

Each output is first written to a temporary file in the destination folder (so the final rename stays on
one file system) and moved into place with :func:`os.replace` only when *all* requested formats have
been produced.  On any failure every temporary file is removed and no output is left half-written;
the error is an :class:`ExportError` whose message names the path.

cairosvg converts the SVG; the SVG is sized in mm (1 user unit = 1 mm), so the PDF page is exactly the
paper size and a length of 100 mm on the sheet is 100 mm on the printed PDF.
"""

from __future__ import annotations

import os
import re
import tempfile
import time
from pathlib import Path
from typing import Callable, Sequence

from .sheet import Sheet
from .svg import sheet_to_svg

FORMATS = ("svg", "pdf", "png")
PNG_DPI = 150.0


class ExportError(Exception):
    """An output file or folder cannot be written; the message names the path."""


FONTS_CONF = Path(__file__).resolve().parent / "fonts" / "fonts.conf"


def _cairosvg():
    """cairosvg, with fontconfig told about the bundled DejaVu Sans before cairo first looks for fonts,
    so the PDF/PNG are set in the font the layout measured with (a user's FONTCONFIG_FILE wins)."""
    os.environ.setdefault("FONTCONFIG_FILE", str(FONTS_CONF))
    import cairosvg
    return cairosvg


def _convert_pdf(svg: bytes, fh) -> None:
    fh.write(_reproducible(_cairosvg().svg2pdf(bytestring=svg)))


def _reproducible(pdf: bytes) -> bytes:
    """With SOURCE_DATE_EPOCH set (the reproducible-builds convention), the PDF's creation date is that
    moment, so the same sheet gives the same bytes; cairo itself stamps the wall clock.  The stamp keeps
    its length, so the cross-reference offsets stay valid."""
    epoch = os.environ.get("SOURCE_DATE_EPOCH")
    if not epoch or not epoch.isdigit():
        return pdf
    stamp = time.strftime("D:%Y%m%d%H%M%SZ", time.gmtime(int(epoch))).encode()
    return re.sub(rb"/CreationDate \(D:\d{14}Z\)", b"/CreationDate (" + stamp + b")", pdf, count=1)


def _convert_png(svg: bytes, fh, dpi: float) -> None:
    _cairosvg().svg2png(bytestring=svg, write_to=fh, dpi=dpi)


def _writers(svg: bytes, dpi: float) -> dict[str, Callable[[object], None]]:
    return {
        "svg": lambda fh: fh.write(svg),
        "pdf": lambda fh: _convert_pdf(svg, fh),
        "png": lambda fh: _convert_png(svg, fh, dpi),
    }


def _prepare_folder(out_dir: Path) -> None:
    try:
        out_dir.mkdir(parents=True, exist_ok=True)
    except OSError as e:
        raise ExportError(f"Cannot create the output folder {out_dir}: {e.strerror or e}.") from e
    if not out_dir.is_dir():
        raise ExportError(f"Cannot write to {out_dir}: it is not a folder.")


def write_sheet(sheet: Sheet, out_dir: Path, stem: str, formats: Sequence[str] = FORMATS, *,
                dpi: float = PNG_DPI) -> list[Path]:
    """Write ``sheet`` as ``out_dir/stem.<format>`` for each format; returns the paths written.

    Formats are "svg", "pdf" and "png" (``dpi`` sets the PNG resolution).  All files appear together
    or not at all: each is written to a temporary file beside its destination and renamed into place
    after every conversion succeeded.
    """
    out_dir = Path(out_dir)
    fmts = []
    for f in formats:
        f = f.lower().lstrip(".")
        if f not in FORMATS:
            raise ExportError(f"Cannot write {out_dir / stem}.{f}: unknown format {f!r} (use svg, pdf or png).")
        if f not in fmts:
            fmts.append(f)
    if not stem or Path(stem).name != stem or stem in (".", ".."):
        raise ExportError(f"Cannot write {out_dir / stem}: the file stem must be a plain file name.")
    _prepare_folder(out_dir)
    svg = sheet_to_svg(sheet).encode("utf-8")
    writers = _writers(svg, dpi)
    temps: list[tuple[Path, Path]] = []
    try:
        for f in fmts:
            final = out_dir / f"{stem}.{f}"
            try:
                fd, tmp_name = tempfile.mkstemp(prefix=f".{stem}.", suffix=f".{f}.tmp", dir=out_dir)
            except OSError as e:
                raise ExportError(f"Cannot write to the output folder {out_dir}: {e.strerror or e}.") from e
            tmp = Path(tmp_name)
            temps.append((tmp, final))
            try:
                with os.fdopen(fd, "wb") as fh:
                    writers[f](fh)
                    fh.flush()
                    os.fsync(fh.fileno())
            except ExportError:
                raise
            except Exception as e:
                raise ExportError(f"Cannot write {final}: {e}.") from e
        done: list[Path] = []
        for tmp, final in temps:
            try:
                os.replace(tmp, final)
            except OSError as e:
                raise ExportError(f"Cannot write {final}: {e.strerror or e}.") from e
            done.append(final)
        return done
    finally:
        for tmp, _ in temps:
            try:
                tmp.unlink()
            except FileNotFoundError:
                pass
            except OSError:
                pass
