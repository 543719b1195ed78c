"""cairocffi's declarations prebuilt in the cache folder (drafting.backends.cairo_ffi): the same PDF and PNG
bytes as cairocffi's own parse, written once and reused, and cairocffi's own parse wherever the cache
folder cannot be used."""

import subprocess
import sys
from pathlib import Path

GALLERY = Path(__file__).resolve().parents[1] / "gallery"
RENDER = ("import sys\n{before}from drafting.app.cli import main\n"
          "rc = main(['render', sys.argv[1], '-o', sys.argv[2], '--format', 'pdf,png'])\n"
          "print(type(sys.modules['cairocffi'].ffi).__module__, rc)")


def _render(tmp_path: Path, out: str, cache: Path, before: str = "") -> str:
    env = {"PATH": "/usr/bin:/bin", "HOME": str(tmp_path), "XDG_CACHE_HOME": str(cache),
           "SOURCE_DATE_EPOCH": "0"}
    r = subprocess.run([sys.executable, "-c", RENDER.format(before=before),
                        str(GALLERY / "notes-velocity-example-1.toml"), str(tmp_path / out)],
                       capture_output=True, text=True, env=env, check=True)
    return r.stdout.split("\n")[-2]


def test_prebuilt_declarations_draw_the_same_bytes(tmp_path):
    cache = tmp_path / "cache"
    _render(tmp_path, "own", cache, before="import cairocffi\n")          # cairocffi's own parse
    assert not cache.exists()
    _render(tmp_path, "first", cache)                                       # writes the prebuilt module
    assert len(list((cache / "tom-drafting").glob("cairo_ffi_*.py"))) == 1
    _render(tmp_path, "again", cache)                                       # reuses it
    for suffix in (".pdf", ".png"):
        own = (tmp_path / "own" / f"notes-velocity-example-1{suffix}").read_bytes()
        assert own == (tmp_path / "first" / f"notes-velocity-example-1{suffix}").read_bytes()
        assert own == (tmp_path / "again" / f"notes-velocity-example-1{suffix}").read_bytes()


def test_an_unusable_cache_folder_falls_back_to_cairocffis_parse(tmp_path):
    blocked = tmp_path / "file"
    blocked.write_text("not a folder")
    assert _render(tmp_path, "out", blocked).endswith(" 0")
    assert (tmp_path / "out" / "notes-velocity-example-1.pdf").stat().st_size > 0
