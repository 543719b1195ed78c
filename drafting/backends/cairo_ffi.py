"""cairocffi's C declarations parsed once, not on every start.

``import cairocffi`` parses cairo's header text with pycparser each time (``FFI().cdef``): about 0.1 s of
a cold ``drafting render``, most of its PDF/PNG start.  cffi can write what it parsed as a small Python
module (out-of-line ABI mode, ``emit_python_code``) that loads in about a millisecond; this module keeps
one in the user's cache folder, named by a hash of the installed cairocffi's declarations and of cffi's
version, and hands its ``ffi`` to cairocffi as ``cairocffi.ffi`` before cairocffi is imported.  The
library, its functions and every drawing call are cairocffi's own: only the parsing is skipped.

On Linux cairocffi's search for the library by name (``ctypes.util.find_library``, which runs ``ldconfig``
and ``gcc`` as child processes: seven processes, tens of ms) is skipped while it loads (:func:`loading`):
it then opens ``libcairo.so.2``, its next candidate and the name that search gives on Linux, through the
same dynamic loader.

Anything unusual -- no cache folder, an unwritable one, xcffib installed (cairocffi then adds the XCB
declarations), a cairocffi already imported -- and :func:`install` does nothing: ``import cairocffi``
then parses as it always did.
"""

from __future__ import annotations

import contextlib
import importlib.util
import os
import sys
import types
import zlib
from pathlib import Path

MODULE = "_tom_drafting_cairo_ffi"


def _cache_folder() -> Path:
    base = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return Path(base) / "tom-drafting"


def _load(name: str, path: Path) -> types.ModuleType:
    spec = importlib.util.spec_from_file_location(name, path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def _write(path: Path, headers: str) -> None:
    """cffi's out-of-line module for ``headers``, written beside ``path`` and renamed into place."""
    import tempfile

    import cffi
    builder = cffi.FFI()
    builder.cdef(headers)
    builder.set_source(MODULE, None)
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=".cairo-ffi-", suffix=".py")
    os.close(fd)
    try:
        builder.emit_python_code(tmp)
        os.replace(tmp, path)
    finally:
        if os.path.exists(tmp):
            os.unlink(tmp)


def prebuilt_ffi():
    """The installed cairocffi's ``ffi``, from the cache folder (written there the first time), or None."""
    spec = importlib.util.find_spec("cairocffi")
    if spec is None or spec.origin is None or importlib.util.find_spec("xcffib") is not None:
        return None
    import cffi
    constants = Path(spec.origin).parent / "constants.py"
    key = f"{zlib.crc32(constants.read_bytes() + cffi.__version__.encode()):08x}"   # a CRC names it (hashlib: ~3 ms to load)
    path = _cache_folder() / f"cairo_ffi_{key}.py"
    if not path.exists():
        headers = _load("_tom_drafting_cairocffi_constants", constants)._CAIRO_HEADERS
        _write(path, headers)
    return _load(MODULE, path).ffi


def install() -> bool:
    """Put the prebuilt ``ffi`` in place as ``cairocffi.ffi`` (before the first ``import cairocffi``);
    whether it did."""
    if "cairocffi" in sys.modules or "cairocffi.ffi" in sys.modules:
        return False
    try:
        ffi = prebuilt_ffi()
    except Exception:                   # no cache folder, a read-only one, a cffi that cannot emit: parse
        return False
    if ffi is None:
        return False
    module = types.ModuleType("cairocffi.ffi", "cairocffi's declarations, prebuilt (drafting.backends.cairo_ffi)")
    module.ffi = ffi
    sys.modules["cairocffi.ffi"] = module
    return True


def uninstall() -> None:
    """Forget the prebuilt ``ffi`` and whatever part of cairocffi was imported with it."""
    for name in [m for m in sys.modules if m == "cairocffi" or m.startswith("cairocffi.")]:
        del sys.modules[name]


CAIRO_NAMES = frozenset({"cairo-2", "cairo", "libcairo-2"})
"""The names cairocffi looks cairo up by before it opens ``libcairo.so.2`` (cairocffi/__init__.py)."""


@contextlib.contextmanager
def loading():
    """While cairocffi is imported on Linux: ``find_library`` answers None for cairo's names (any other
    name is looked up as always), so cairocffi opens ``libcairo.so.2`` without running ldconfig."""
    if not sys.platform.startswith("linux"):
        yield
        return
    import ctypes.util
    search = ctypes.util.find_library

    def find_library(name):
        return None if name in CAIRO_NAMES else search(name)
    ctypes.util.find_library = find_library
    try:
        yield
    finally:
        ctypes.util.find_library = search
