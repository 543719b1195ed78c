"""Every SVG the test suite writes is well-formed, inert XML (issue 6): the gallery's sheets, and --
checked when the session ends, after every other test -- each .svg written anywhere under the session's
temporary folders (pytest's tmp_path).  No conftest needed: a session-scoped fixture's teardown runs at
the end of the session, so a bad SVG shows as an error at the teardown of the last test."""

from __future__ import annotations

from pathlib import Path

import pytest

from paths import GALLERY, benchmark_module


def bad_svgs(folder: Path) -> list[tuple[Path, str]]:
    """(path, why) for every .svg under ``folder`` that is not well-formed, inert SVG."""
    check = benchmark_module("fuzz_scenes").check_svg
    return [(p, why) for p in sorted(folder.rglob("*.svg")) if (why := check(p))]


@pytest.fixture(scope="session", autouse=True)
def every_svg_of_the_session(tmp_path_factory):
    yield
    base = tmp_path_factory.getbasetemp()
    bad = bad_svgs(base)
    assert not bad, f"SVGs written by the suite that are not well-formed inert XML: {bad[:5]}"


def test_gallery_svgs_are_well_formed_and_inert():
    svgs = sorted(GALLERY.glob("*.svg"))
    assert svgs
    assert bad_svgs(GALLERY) == []


def test_the_check_catches_a_bad_svg(tmp_path):
    (tmp_path / "sub").mkdir()
    (tmp_path / "sub" / "x.svg").write_bytes(b'<svg xmlns="http://www.w3.org/2000/svg"><text>\x01</text></svg>')
    (tmp_path / "y.svg").write_bytes(b'<!DOCTYPE svg [<!ENTITY e "x">]><svg xmlns="http://www.w3.org/2000/svg"/>')
    (tmp_path / "z.svg").write_bytes(b'<svg xmlns="http://www.w3.org/2000/svg"><a href="http://x"/></svg>')
    # a style sheet other than the embedded font's @font-face rules (data URLs only) is active content
    (tmp_path / "w.svg").write_bytes(b'<svg xmlns="http://www.w3.org/2000/svg"><style>@import url(http://x);'
                                     b'</style></svg>')
    (tmp_path / "v.svg").write_bytes(b'<svg xmlns="http://www.w3.org/2000/svg"><style>@font-face{font-family:'
                                     b'"DejaVu Sans";font-style:normal;src:url(http://x/f.woff) format("woff");}'
                                     b'</style></svg>')
    assert [p.name for p, _ in bad_svgs(tmp_path)] == ["x.svg", "v.svg", "w.svg", "y.svg", "z.svg"]
    for p in tmp_path.rglob("*.svg"):          # leave nothing bad for the end-of-session check
        p.unlink()
