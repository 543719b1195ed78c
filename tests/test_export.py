"""Export: PDF page size, true scale on the PDF, PNG output, atomic writes and clear errors.

True scale is measured on the PDF itself: cairo writes the page content as a Flate-compressed stream of
PDF path operators.  The test inflates it with zlib and runs a tiny interpreter over it that keeps the
current transformation matrix (q / Q / cm) and maps every path point (m, l, re) to page space, in PDF
points (1/72 in).  A sheet holding only a 100 mm scale bar must then span 100 mm = 283.465 pt.  The
interpreter does not care which transform cairo chose (cairo writes a y-flip ``cm`` and user-unit
scaling may move into the matrix in other versions), so the check is robust.  The PNG is checked the
same way by rasterising at 254 dpi (10 px per mm) and measuring the black bar in pixels.
"""

from __future__ import annotations

import os
import re
import zlib

import pytest

from constructions.entities import Arrow, Diagram, Point, Role, ScaleBar
from constructions.geometry import Vec
from constructions.record import Construction
from drafting.backends import files as export_mod
from drafting.layout.scale_bar import scale_bar
from drafting.backends.files import ExportError, write_sheet
from drafting.render.paper import Text, paper
from drafting.layout.sheet import ResultRow, Sheet, SheetInfo, compose_sheet

PT_PER_MM = 72 / 25.4


def small_sheet(p: str = "A4", orientation: str = "landscape") -> Sheet:
    V = Diagram.VELOCITY
    c = Construction("Velocity")
    c = c.then("Choose the pole O_v.", Point("pole", Role.LABEL, V, Vec(0, 0), "O_v"))
    c = c.then("Choose the velocity scale.", ScaleBar("scale", Role.SCALE_BAR, V, "velocity", 0.01))
    c = c.then("Draw V_B from O_v; its tip is b.", Arrow("V_B", Role.KNOWN, V, Vec(0, 0), Vec(-0.6, 0.5), "V_B"),
               Point("b", Role.LABEL, V, Vec(-0.6, 0.5), "b"))
    return compose_sheet(c, SheetInfo("Export test", "TOM-X-1", paper=p, orientation=orientation, date="2025-01-15"),
                         [ResultRow("V_B", "781 mm/s", "781 mm/s", "0 %")])


def bar_sheet(length: float = 100.0) -> Sheet:
    """A blank A4 sheet with a single scale bar of ``length`` mm (no lettering, only paths)."""
    cmds, _ = scale_bar(50.0, 50.0, length, length, "mm", name="bar")
    return Sheet(paper("A4"), tuple(c for c in cmds if not isinstance(c, Text)))


def pdf_streams(pdf: bytes) -> list[bytes]:
    out = []
    for m in re.finditer(rb"stream\r?\n(.*?)endstream", pdf, re.S):
        data = m.group(1)
        try:
            out.append(zlib.decompress(data))
        except zlib.error:
            try:
                out.append(zlib.decompressobj().decompress(data))
            except zlib.error:
                out.append(data)
    return out


def mul(a, b):
    """PDF matrices [a b c d e f]: the product a x b (apply a, then b)."""
    return (a[0] * b[0] + a[1] * b[2], a[0] * b[1] + a[1] * b[3],
            a[2] * b[0] + a[3] * b[2], a[2] * b[1] + a[3] * b[3],
            a[4] * b[0] + a[5] * b[2] + b[4], a[4] * b[1] + a[5] * b[3] + b[5])


def path_points(content: bytes) -> list[tuple[float, float]]:
    """Every path point of a content stream in page space (points), following q/Q/cm."""
    ctm = (1.0, 0.0, 0.0, 1.0, 0.0, 0.0)
    stack = []
    operands: list[float] = []
    pts = []

    def page(x, y):
        return (ctm[0] * x + ctm[2] * y + ctm[4], ctm[1] * x + ctm[3] * y + ctm[5])

    for tok in re.findall(rb"[A-Za-z'\"*]+|-?\d*\.?\d+|\[|\]|/[^\s/\[\]()<>]+|\([^)]*\)", content):
        try:
            operands.append(float(tok))
            continue
        except ValueError:
            pass
        op = tok.decode("latin1")
        if op == "q":
            stack.append(ctm)
        elif op == "Q":
            ctm = stack.pop()
        elif op == "cm" and len(operands) >= 6:
            ctm = mul(tuple(operands[-6:]), ctm)
        elif op in ("m", "l") and len(operands) >= 2:
            pts.append(page(*operands[-2:]))
        elif op == "re" and len(operands) >= 4:
            x, y, w, h = operands[-4:]
            pts += [page(x, y), page(x + w, y + h)]
        elif op == "c" and len(operands) >= 6:
            pts += [page(*operands[-2:])]
        operands = []
    return pts


@pytest.mark.parametrize("p,orientation,w_mm,h_mm", [("A4", "landscape", 297, 210), ("A3", "portrait", 297, 420)])
def test_pdf_page_is_exactly_the_paper(tmp_path, p, orientation, w_mm, h_mm):
    paths = write_sheet(small_sheet(p, orientation), tmp_path, "sheet", ("pdf",))
    assert paths == [tmp_path / "sheet.pdf"]
    pdf = paths[0].read_bytes()
    boxes = re.findall(rb"/MediaBox\s*\[\s*([-\d.\s]+)\]", pdf)
    assert boxes
    for b in boxes:
        x0, y0, x1, y1 = (float(v) for v in b.split())
        assert (x1 - x0) == pytest.approx(w_mm * PT_PER_MM, abs=0.01)
        assert (y1 - y0) == pytest.approx(h_mm * PT_PER_MM, abs=0.01)
    assert (297 * PT_PER_MM) == pytest.approx(841.89, abs=0.01)


def test_a_100_mm_scale_bar_is_100_mm_on_the_pdf(tmp_path):
    (pdf_path,) = write_sheet(bar_sheet(100.0), tmp_path, "bar", ("pdf",))
    pts = []
    for s in pdf_streams(pdf_path.read_bytes()):
        pts += path_points(s)
    assert pts, "no path found in the PDF content"
    # the page background rectangle spans the page: leave it out
    bar = [(x, y) for x, y in pts if 0.5 < x < 841.0]
    xs = [x for x, _ in bar]
    span = max(xs) - min(xs)
    assert span == pytest.approx(100 * PT_PER_MM, abs=0.01)
    assert min(xs) == pytest.approx(50 * PT_PER_MM, abs=0.01)
    # the ticks are 20 mm apart (a 100 mm bar has five divisions)
    ticks: list[float] = []
    for x in sorted(xs):
        if not ticks or x - ticks[-1] > 0.05:
            ticks.append(x)
    assert len(ticks) == 6
    assert all(b - a == pytest.approx(20 * PT_PER_MM, abs=0.02) for a, b in zip(ticks, ticks[1:]))


def test_png_is_written_at_true_scale(tmp_path):
    from PIL import Image
    (png,) = write_sheet(bar_sheet(100.0), tmp_path, "bar", ("png",), dpi=254)
    img = Image.open(png).convert("L")
    assert img.size == (2970, 2100)
    # the bar is 1.6 mm high at y 50 + numbers... find the row through the middle of the bar
    w, h = img.size
    px = img.load()
    best_row, best = None, 0
    for y in range(400, 700):
        dark = sum(1 for x in range(0, w, 2) if px[x, y] < 128)
        if dark > best:
            best_row, best = y, dark
    row = [x for x in range(w) if px[x, best_row] < 128]
    width_px = max(row) - min(row) + 1
    # 100 mm at 10 px/mm, plus the 0.25 mm outline (half on each side): 1000..1003 px
    assert 998 <= width_px <= 1004


def test_all_formats_written_and_png_is_a_png(tmp_path):
    from PIL import Image
    out = tmp_path / "new" / "folder"
    paths = write_sheet(small_sheet(), out, "sample")
    assert [p.name for p in paths] == ["sample.svg", "sample.pdf", "sample.png"]
    assert paths[0].read_text(encoding="utf-8").startswith("<svg")
    assert paths[1].read_bytes().startswith(b"%PDF")
    assert paths[2].read_bytes().startswith(b"\x89PNG")
    with Image.open(paths[2]) as img:
        assert img.size == (round(297 / 25.4 * 150), round(210 / 25.4 * 150))
    assert sorted(os.listdir(out)) == ["sample.pdf", "sample.png", "sample.svg"]


def test_failing_conversion_leaves_no_partial_and_no_temp_file(tmp_path, monkeypatch):
    (tmp_path / "sheet.png").write_bytes(b"old")

    def broken(svg, fh, dpi):
        fh.write(b"\x89PNG half a file")
        raise RuntimeError("cairo ran out of memory")

    monkeypatch.setattr(export_mod, "_convert_png", broken)
    with pytest.raises(ExportError) as err:
        write_sheet(small_sheet(), tmp_path, "sheet")
    assert str(tmp_path / "sheet.png") in str(err.value)
    # nothing new appeared (the svg and pdf were not moved in either), no temp file is left,
    # and the old file is untouched
    assert sorted(os.listdir(tmp_path)) == ["sheet.png"]
    assert (tmp_path / "sheet.png").read_bytes() == b"old"


def test_failing_rename_leaves_no_temp_file(tmp_path, monkeypatch):
    def refuse(src, dst):
        raise PermissionError(13, "Permission denied")

    monkeypatch.setattr(export_mod.os, "replace", refuse)
    with pytest.raises(ExportError, match="sheet.svg"):
        write_sheet(small_sheet(), tmp_path, "sheet", ("svg",))
    assert os.listdir(tmp_path) == []


def test_impossible_folder_raises_export_error_naming_it(tmp_path):
    blocker = tmp_path / "a file"
    blocker.write_text("not a folder")
    target = blocker / "out"
    with pytest.raises(ExportError) as err:
        write_sheet(small_sheet(), target, "sheet")
    msg = str(err.value)
    assert str(target) in msg and msg.endswith(".") and msg.count(". ") == 0


@pytest.mark.skipif(hasattr(os, "geteuid") and os.geteuid() == 0, reason="root can write anywhere")
def test_unwritable_folder_raises_export_error_naming_it(tmp_path):
    ro = tmp_path / "ro"
    ro.mkdir()
    ro.chmod(0o500)
    try:
        with pytest.raises(ExportError) as err:
            write_sheet(small_sheet(), ro, "sheet")
        assert str(ro) in str(err.value)
        assert os.listdir(ro) == []
    finally:
        ro.chmod(0o700)


def test_folder_refusing_new_files_raises_export_error_naming_it(tmp_path, monkeypatch):
    """The same as an unwritable folder, but also when the tests run as root."""
    def refuse(*args, **kwargs):
        raise PermissionError(13, "Permission denied")

    monkeypatch.setattr(export_mod, "_create_temp", refuse)
    with pytest.raises(ExportError) as err:
        write_sheet(small_sheet(), tmp_path, "sheet")
    assert str(tmp_path) in str(err.value) and "Permission denied" in str(err.value)
    assert os.listdir(tmp_path) == []


def test_bad_format_and_stem(tmp_path):
    with pytest.raises(ExportError, match="dxf"):
        write_sheet(small_sheet(), tmp_path, "sheet", ("dxf",))
    with pytest.raises(ExportError):
        write_sheet(small_sheet(), tmp_path, "../escape", ("svg",))
    assert os.listdir(tmp_path) == []


def test_pdf_is_set_in_the_bundled_font_only(tmp_path):
    """DESIGN: bundle one font and name only it -- the PDF embeds DejaVu Sans and nothing else."""
    import re
    from drafting.study.worked import builtin_example, sheet_for
    from drafting.scene.reader import load_scene
    from drafting.study.study import Study
    (path,) = write_sheet(sheet_for(Study(load_scene(builtin_example()))), tmp_path, "font", ["pdf"])
    names = set(re.findall(rb"/FontName /[A-Z]{6}\+([A-Za-z-]+)", path.read_bytes()))
    assert names and names <= {b"DejaVuSans", b"DejaVuSans-Oblique"}


def test_source_date_epoch_makes_the_pdf_reproducible(tmp_path, monkeypatch):
    import time as _time
    from drafting.study.worked import builtin_example, sheet_for
    from drafting.scene.reader import load_scene
    from drafting.study.study import Study
    monkeypatch.setenv("SOURCE_DATE_EPOCH", "1700000000")
    sheet = sheet_for(Study(load_scene(builtin_example())))
    (a,) = write_sheet(sheet, tmp_path / "a", "s", ["pdf"])
    _time.sleep(1.1)
    (b,) = write_sheet(sheet, tmp_path / "b", "s", ["pdf"])
    assert a.read_bytes() == b.read_bytes()
    assert b"/CreationDate (D:20231114221320Z)" in a.read_bytes()


def test_source_date_epoch_is_the_sheet_s_date(monkeypatch):
    """The title block's date follows SOURCE_DATE_EPOCH as the PDF's does: the same scene gives the same
    sheet whatever the day it is drawn (the gallery was drawn the day before it was checked again)."""
    from drafting.scene.reader import load_scene
    from drafting.layout.sheet import sheet_date
    from drafting.study.study import Study
    from drafting.study.worked import builtin_example, sheets_for
    monkeypatch.setenv("SOURCE_DATE_EPOCH", "1700000000")
    assert sheet_date() == "2023-11-14" and sheet_date(0) == "1970-01-01"
    texts = [c.plain for c in sheets_for(Study(load_scene(builtin_example())).run())[0].commands
             if hasattr(c, "spans")]
    assert "2023-11-14" in texts
    monkeypatch.delenv("SOURCE_DATE_EPOCH")
    import datetime
    assert sheet_date() == datetime.date.today().isoformat()


# -- several sheets, all-or-nothing, faults ---------------------------------------------------------------

def _pdf_pages(pdf: bytes) -> list[tuple[float, float]]:
    """(width, height) in points of every /Type /Page object."""
    out = []
    for m in re.finditer(rb"/Type\s*/Page\b(?!s)(.*?)>>", pdf, re.S):
        box = re.search(rb"/MediaBox\s*\[\s*([-\d.\s]+)\]", m.group(0))
        if box:
            x0, y0, x1, y1 = (float(v) for v in box.group(1).split())
            out.append((x1 - x0, y1 - y0))
    return out


def test_one_sheet_gives_the_plain_names(tmp_path):
    from drafting.backends.files import write_sheets
    paths = write_sheets([small_sheet()], tmp_path, "one", ("svg", "pdf", "png"))
    assert [p.name for p in paths] == ["one.svg", "one.pdf", "one.png"]
    assert sorted(os.listdir(tmp_path)) == ["one.pdf", "one.png", "one.svg"]


def test_several_sheets_give_numbered_svgs_and_pngs_and_one_pdf_of_all_pages(tmp_path):
    from PIL import Image
    from drafting.backends.files import output_names, write_sheets
    sheets = [small_sheet("A4", "landscape"), small_sheet("A3", "portrait"), bar_sheet(100.0)]
    paths = write_sheets(sheets, tmp_path, "multi", ("svg", "pdf", "png"), dpi=30)
    names = [p.name for p in paths]
    assert names == ["multi-1.svg", "multi-2.svg", "multi-3.svg", "multi.pdf", "multi-1.png", "multi-2.png",
                     "multi-3.png"] == output_names(3, "multi", ("svg", "pdf", "png"))
    assert sorted(os.listdir(tmp_path)) == sorted(names)
    pdf = (tmp_path / "multi.pdf").read_bytes()
    assert b"/Count 3" in pdf
    pages = _pdf_pages(pdf)
    assert len(pages) == 3
    for (w, h), (wm, hm) in zip(pages, [(297, 210), (297, 420), (297, 210)]):
        assert w == pytest.approx(wm * PT_PER_MM, abs=0.01) and h == pytest.approx(hm * PT_PER_MM, abs=0.01)
    with Image.open(tmp_path / "multi-2.png") as img:
        assert img.size == (round(297 / 25.4 * 30), round(420 / 25.4 * 30))
    # the 100 mm bar on page 3 is still 100 mm: true scale holds on every page of the merged PDF
    spans = []
    for st in pdf_streams(pdf):
        xs = [x for x, _ in path_points(st) if 0.5 < x < 841.0]
        if xs and abs(max(xs) - min(xs) - 100 * PT_PER_MM) < 0.01:
            spans.append(st)
    assert spans


def test_a_final_name_that_is_a_folder_writes_nothing(tmp_path):
    (tmp_path / "sheet.png").mkdir()
    with pytest.raises(ExportError) as err:
        write_sheet(small_sheet(), tmp_path, "sheet")
    msg = str(err.value)
    assert str(tmp_path / "sheet.png") in msg and "folder" in msg and "\n" not in msg
    assert sorted(os.listdir(tmp_path)) == ["sheet.png"]          # no svg, no pdf, no temporary file


def test_full_disk_while_writing_leaves_nothing(tmp_path, monkeypatch):
    """ENOSPC from the file system (simulated at fsync; the real one is in test_hostile_faults)."""
    import errno
    calls = []

    def full(fd):
        calls.append(fd)
        if len(calls) == 2:                       # the second file (the PDF) finds the disk full
            raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))

    monkeypatch.setattr(export_mod.os, "fsync", full)
    with pytest.raises(ExportError) as err:
        write_sheet(small_sheet(), tmp_path, "sheet")
    assert str(err.value) == f"Cannot write {tmp_path / 'sheet.pdf'}: No space left on device."
    assert os.listdir(tmp_path) == []


def test_a_failed_rename_puts_back_what_was_there(tmp_path, monkeypatch):
    """The svg is renamed into place, then the pdf's rename fails: the old svg comes back."""
    old = '<svg xmlns="http://www.w3.org/2000/svg"><!-- old --></svg>'
    (tmp_path / "sheet.svg").write_text(old)
    real = os.replace
    seen = []

    def flaky(src, dst):
        seen.append(dst)
        if str(dst).endswith("sheet.pdf"):
            raise PermissionError(13, "Permission denied")
        return real(src, dst)

    monkeypatch.setattr(export_mod.os, "replace", flaky)
    with pytest.raises(ExportError, match="sheet.pdf"):
        write_sheet(small_sheet(), tmp_path, "sheet", ("svg", "pdf"))
    assert sorted(os.listdir(tmp_path)) == ["sheet.svg"]
    assert (tmp_path / "sheet.svg").read_text() == old


def test_stale_temporary_files_are_removed_by_the_next_run(tmp_path):
    import subprocess
    import sys
    import time as _time
    dead = subprocess.Popen([sys.executable, "-c", "pass"])
    dead.wait()
    stale = tmp_path / f".drafting-tmp-{dead.pid}-3-sheet.pdf"          # its process is gone
    old = tmp_path / f".drafting-tmp-{os.getppid()}-1-other.png"        # alive, but two hours old
    alive = tmp_path / f".drafting-tmp-{os.getppid()}-2-busy.pdf"       # alive and recent: in use
    mine = tmp_path / "notes.txt"
    for p in (stale, old, alive, mine):
        p.write_text("x")
    two_hours_ago = _time.time() - 7200
    os.utime(old, (two_hours_ago, two_hours_ago))
    write_sheet(small_sheet(), tmp_path, "sheet", ("svg",))
    assert sorted(os.listdir(tmp_path)) == sorted([alive.name, mine.name, "sheet.svg"])


def test_a_write_another_thread_begins_during_the_sweep_is_not_taken_for_a_leftover(tmp_path, monkeypatch):
    """The sweep for leftovers reads the folder, then asks what this process is writing: a write that a
    second thread registers and begins while the folder is read keeps its temporary (it used to be
    removed under that thread, which then failed with "No such file or directory")."""
    from drafting.backends import faults
    from drafting.backends.files import _create_temp, _temp_name, remove_stale_temporaries
    busy = _temp_name(tmp_path, "other", "svg")
    real_scandir = export_mod.os.scandir

    def scandir_while_another_write_begins(path):
        faults.track(busy)                       # the other thread, as write_outputs does: track, then create
        os.close(_create_temp(busy))
        return real_scandir(path)
    monkeypatch.setattr(export_mod.os, "scandir", scandir_while_another_write_begins)
    try:
        assert remove_stale_temporaries(tmp_path) == []
        assert busy.exists()
    finally:
        faults.untrack(busy)
        busy.unlink(missing_ok=True)             # (an empty .svg: the suite checks every SVG it leaves)


def test_temporary_files_are_tracked_while_they_exist(tmp_path, monkeypatch):
    """While a conversion runs, the temporary files of the formats done so far are registered with
    faults (so a signal handler can remove them) and carry the recognisable name."""
    from drafting.backends import faults
    seen = {}

    def spy(svg, fh, dpi):
        seen["tracked"] = set(faults.tracked())
        seen["files"] = sorted(os.listdir(tmp_path))
        fh.write(b"\x89PNG")

    monkeypatch.setattr(export_mod, "_convert_png", spy)
    write_sheet(small_sheet(), tmp_path, "sheet", ("svg", "png"))
    assert len(seen["files"]) == 1 and re.fullmatch(rf"\.drafting-tmp-{os.getpid()}-\d+-sheet\.svg", seen["files"][0])
    assert {os.path.basename(p) for p in seen["tracked"]} == set(seen["files"])
    assert not faults.tracked()
    assert sorted(os.listdir(tmp_path)) == ["sheet.png", "sheet.svg"]


def test_svg_text_is_made_xml_safe():
    import xml.etree.ElementTree as ET
    from drafting.backends.svg import sheet_to_svg
    from drafting.render.paper import Rect, Span
    nasty = "A\x00B\x07C\x1b[31m\ufffe\uffff\ud800 <script>&amp;\"'"
    spans = (Span(nasty, 3.5), Span(nasty, 2.5, shift=1.0, italic=True))
    sheet = Sheet(paper("A4"), (Text(10, 10, spans, "label", Rect(10, 7, 50, 4), "frame"),))
    svg = sheet_to_svg(sheet)
    root = ET.fromstring(svg)
    text = "".join(root.itertext())
    assert text.count("A\ufffdB\ufffdC\ufffd[31m\ufffd\ufffd\ufffd <script>&amp;\"'") == 2
    assert "<script" not in svg and "<!ENTITY" not in svg and "href" not in svg


@pytest.mark.parametrize("scene_name, extra", [("notes-velocity-example-3.toml", ()),
                                               ("lab-slider-crank.toml", ("--lab",))])
def test_the_page_and_the_sheets_of_one_render_are_written_together(tmp_path, monkeypatch, capsys,
                                                                     scene_name, extra):
    """render --format html,svg (a lab too): a full disk while the page is written (the last file) leaves
    neither the page nor a sheet; before, the sheets stood under their final names and only the page was
    missing."""
    import errno

    from drafting.app.cli import main
    from paths import GALLERY
    scene = GALLERY / scene_name
    calls = []
    real = export_mod.os.fsync

    def counting(fd):
        calls.append(fd)
        real(fd)
    monkeypatch.setattr(export_mod.os, "fsync", counting)
    whole = tmp_path / "whole"
    assert main(["render", str(scene), "--format", "html,svg", "-o", str(whole), *extra]) == 0
    files, last = sorted(os.listdir(whole)), len(calls)             # the page is written last
    calls.clear()

    def full(fd):
        calls.append(fd)
        if len(calls) == last:
            raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))
    monkeypatch.setattr(export_mod.os, "fsync", full)
    out = tmp_path / "out"
    assert main(["render", str(scene), "--format", "html,svg", "-o", str(out), *extra]) == 2
    err = capsys.readouterr().err.splitlines()[-1]
    assert f"Cannot write {out / scene.with_suffix('.html').name}" in err, err
    assert os.listdir(out) == []
    assert scene.with_suffix(".html").name in files and any(f.endswith(".svg") for f in files)
