"""The files ``drafting serve`` may touch: one scene, or the ``*.toml`` scenes of one folder (not below it).

A name from the browser is a relative path; it is resolved and refused unless it is one of the served
scenes, its real path (symlinks followed) inside the served folder.  A scene is read through the reader's
own size-limited read (:func:`drafting.scene.reader.read_input_text`).  Its version is a digest of its
bytes: a save names the version it was edited from and is refused (:class:`Conflict`) when the file has
changed since -- another tab or the user's own editor saved it -- so nothing is overwritten unseen.  A save
is atomic (:func:`drafting.backends.files.write_outputs`: a temporary file beside it, fsynced, renamed into
place) and keeps the previous text as ``NAME.toml~``, written in the same step.
"""

from __future__ import annotations

import hashlib
import os
from dataclasses import dataclass
from pathlib import Path

from ..backends.files import ExportError, write_outputs
from ..scene import limits
from ..scene.reader import SceneError, read_input_text
from ..scene.textsafe import printable

BACKUP_SUFFIX = "~"


class Refused(Exception):
    """A name the served folder does not hold, or a file that cannot be read or written: one sentence."""


class Conflict(Exception):
    """The file changed since the version a save was edited from; ``current`` is its version now."""

    def __init__(self, message: str, current: str) -> None:
        super().__init__(message)
        self.current = current


def version_of(data: bytes) -> str:
    """A file's version: the first 16 hex digits of the SHA-256 of its bytes."""
    return hashlib.sha256(data).hexdigest()[:16]


@dataclass(frozen=True)
class Scene:
    name: str          # relative to the served folder, with forward slashes
    path: Path         # the real path
    text: str
    version: str


class Workspace:
    """The served scenes: ``Workspace(path)`` for one scene file or a folder of them."""

    def __init__(self, target: Path | str) -> None:
        target = Path(target)
        real = Path(os.path.realpath(target))
        if real.is_dir():
            self.root, self.only = real, None
        elif real.is_file() and target.suffix == ".toml":
            self.root, self.only = real.parent, real.name
        else:
            raise Refused(f"{printable(str(target))}: is neither a scene file (.toml) nor a folder")

    def names(self) -> list[str]:
        """The served scenes' names, sorted."""
        if self.only is not None:
            return [self.only]
        out = []
        for p in sorted(self.root.glob("*.toml")):
            try:
                self.resolve(p.name)
            except Refused:
                continue
            out.append(p.name)
        return out

    def resolve(self, name: str) -> Path:
        """The real path of the served scene ``name``, or :class:`Refused`."""
        if (not isinstance(name, str) or not name or "\x00" in name or "/" in name or "\\" in name
                or name in (".", "..") or not name.endswith(".toml")
                or (self.only is not None and name != self.only)):
            raise Refused(f"{printable(str(name))[:80]!r} is not a scene this server serves")
        path = self.root / name
        real = Path(os.path.realpath(path))
        if real.parent != self.root and self.root not in real.parents:
            raise Refused(f"{name}: leads outside the served folder; it is not served")
        if not real.is_file():
            raise Refused(f"{name}: no such scene in the served folder")
        return real

    def read(self, name: str) -> Scene:
        path = self.resolve(name)
        try:
            text = read_input_text(path, limits.MAX_FILE_BYTES, "scene file", SceneError)
        except SceneError as e:
            raise Refused(str(e)) from None
        return Scene(name, path, text, version_of(text.encode("utf-8")))

    def version(self, name: str) -> str:
        return self.read(name).version

    def save(self, name: str, text: str, base_version: str) -> str:
        """Write ``text`` as the scene ``name`` if it is still at ``base_version``; the previous text
        becomes ``name~``.  Returns the new version; :class:`Conflict` if the file changed meanwhile."""
        data = text.encode("utf-8")
        if len(data) > limits.MAX_FILE_BYTES:
            raise Refused(f"{name}: the text is larger than {limits.MAX_FILE_BYTES // 1024} KiB; a scene file "
                          f"may be at most {limits.MAX_FILE_BYTES // 1024} KiB")
        old = self.read(name)
        if old.version != base_version:
            raise Conflict(f"{name} was changed since this tab loaded it (by another tab or an editor); "
                           f"nothing was saved. Reload it to see that version, or save again to replace it "
                           f"with yours.", old.version)
        path = old.path
        backup = path.with_name(path.name + BACKUP_SUFFIX)
        old_bytes = old.text.encode("utf-8")
        try:
            write_outputs(path.parent, path.stem, [(backup, lambda: old_bytes), (path, lambda: data)])
        except ExportError as e:
            raise Refused(str(e)) from None
        return version_of(data)


__all__ = ["Workspace", "Scene", "Refused", "Conflict", "version_of", "BACKUP_SUFFIX"]
