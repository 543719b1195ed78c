"""Scene files (TOML) -> a validated :class:`Scene`.

Every problem is reported as one :class:`SceneError` sentence naming the file, the key and what is
wrong.  The format is documented in README.md ("Scene files").
"""

from __future__ import annotations

import os
import re
import stat
import tomllib
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from constructions.geometry import Vec

from ..families.registry import Family, families, family
from .unitset import KEYS as UNIT_KEYS, UNITS, Units
from .header_keys import ASK, DRAWING, ORIENTATIONS, PAPERS, TOP
from .keys import KeyTable
from . import limits
from .textsafe import cut, one_line, printable, shown_path
from .drawing_scales import read_scales
from .units import UnitError, check_unit, to_si

PLANNED_KINDS = (
)
"""Scene families announced but not built yet: a scene of one of these kinds gets a clear "not yet"."""
COMMON_KEYS = TOP.allowed
"""The sections every scene family shares (:data:`~drafting.scene.header_keys.TOP`); each family adds its own
(Family.sections).  ``[vary]`` (the ranges a batch of lab sheets draws from: :mod:`drafting.scene.vary`, the
keys the family's) is checked here and otherwise left to ``drafting batch``."""


class SceneError(Exception):
    """Bad scene input: ``str(error)`` is one sentence naming the file and the key."""

    def __init__(self, path: Path | str, key: str, problem: str) -> None:
        self.path, self.key, self.problem = str(path), key, problem
        # one line, whatever the file holds: control characters escaped, long names and quoted values
        # cut (textsafe), so the file and the key always show
        where, key = shown_path(path), cut(printable(key), 80)
        problem = one_line(problem)
        super().__init__(f"{where}: {key}: {problem}" if key else f"{where}: {problem}")


@dataclass(frozen=True)
class Scene:
    """The shared header of a read scene: the drawing, the units and what it asks for.  Each family's
    state is a subclass of it (its own typed fields: a linkage's mechanism and input, a cam's model ...),
    named by the family (:attr:`~drafting.families.registry.Family.scene_type`)."""

    path: Path
    title: str
    drawing_number: str
    paper: str
    orientation: str
    units: Units
    analyses: tuple[str, ...]
    find: tuple[str, ...] | None
    kind: str
    dimensions: bool | None          # [drawing] dimensions: the space diagram dimensioned as a drafter would
                                     # (None: not said; a problem sheet dimensions it then)
    scales: tuple[tuple[str, float], ...]   # [drawing] scale: (diagram, SI units per paper mm) it states

    def _repr_html_(self) -> str:
        """Jupyter: what the scene is (a Study shows what it gives)."""
        from html import escape
        return (f"<div><b>{escape(self.title)}</b> ({escape(self.kind)} scene, {escape(self.drawing_number)}, "
                f"{escape(self.paper)})<br>asks for {escape(', '.join(self.analyses))}; from "
                f"{escape(str(self.path))}</div>")


def load_scene(path: Path | str) -> Scene:
    """Read a scene file; the limits (:mod:`drafting.scene.limits`) are checked before anything else."""
    path = Path(path)
    text = _read_text(path)
    return parse_scene(text, path)


def _read_text(path: Path) -> str:
    return read_input_text(path, limits.MAX_FILE_BYTES, "scene file", SceneError)


def read_input_text(path: Path, max_bytes: int, noun: str, error) -> str:
    """An input file (a scene, an answers file) as text: at most ``max_bytes`` are ever read, and every
    failure is one ``error(path, "", sentence)`` that names what the file is (``noun``)."""
    try:
        mode = os.stat(path).st_mode          # before opening: a FIFO would block the open itself
        if stat.S_ISDIR(mode):
            raise IsADirectoryError
        if not stat.S_ISREG(mode):
            raise error(path, "", "is not a regular file")
        with open(path, "rb") as fh:
            raw = fh.read(max_bytes + 1)
    except error:
        raise
    except (FileNotFoundError, NotADirectoryError):
        raise error(path, "", f"no such {noun}") from None
    except IsADirectoryError:
        raise error(path, "", f"is a folder, not {'an' if noun[0] in 'aeiou' else 'a'} {noun}") from None
    except PermissionError:
        raise error(path, "", "cannot be read: permission denied") from None
    except OSError as e:
        raise error(path, "", f"cannot be read: {e.strerror or 'input/output error'}") from None
    if len(raw) > max_bytes:
        raise error(path, "", f"is larger than {max_bytes // 1024} KiB; {'an' if noun[0] in 'aeiou' else 'a'} "
                              f"{noun} may be at most {max_bytes // 1024} KiB")
    try:
        return raw.decode("utf-8").removeprefix("\ufeff")
    except UnicodeDecodeError as e:
        line = raw.count(b"\n", 0, e.start) + 1
        raise error(path, "", f"is not UTF-8 text (byte 0x{raw[e.start]:02x} on line {line}); save "
                              f"it as UTF-8") from None


def parse_scene(text: str, path: Path | str = "<scene>") -> Scene:
    path = Path(path)
    try:
        limits.check_file_size(len(text.encode("utf-8", "surrogatepass")))
        limits.check_text(text)               # nesting and number sizes, before the TOML reader
    except limits.LimitError as e:
        raise SceneError(path, e.key, e.problem) from None
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as e:
        raise SceneError(path, "", f"is not valid TOML ({e})") from None
    except (ValueError, RecursionError, MemoryError):   # int conversion limits, nesting (also scanned)
        raise SceneError(path, "", "is not a TOML file this reader accepts (a value too large or "
                                   "nested too deep)") from None
    return scene_from_data(data, path)


def scene_from_data(data: dict[str, Any], path: Path | str = "<scene>") -> Scene:
    """A scene from already-parsed TOML data (``path`` names it in errors); counts, nesting, string
    lengths and magnitudes are checked first (:mod:`drafting.scene.limits`)."""
    path = Path(path)
    if not isinstance(data, dict):
        raise SceneError(path, "", "must be a TOML table of sections")
    try:
        limits.check_data(data)
    except limits.LimitError as e:
        raise SceneError(path, e.key, e.problem) from None
    reader = SceneReader(path, data)
    scene = reader.scene()
    bad = limits.length_ratio_problem(reader.lengths)
    if bad:
        key, value, other, other_value = bad
        ratio = f"{limits.LENGTH_RATIO:.0e}".replace("e+0", "e").replace("e+", "e")
        size = "large" if value > other_value else "small"
        raise SceneError(path, key, f"{scene.units.format('length', value)} is too {size} beside "
                                    f"{scene.units.format('length', other_value)} at {other}: a scene's non-zero "
                                    f"lengths must lie within a factor {ratio} of each other (write 0 for zero)")
    return scene


class SceneReader:
    """The one reader of a scene's data: the header here, each family's sections by its own section
    reader (``Family.read``) through these helpers, whose every error is one :class:`SceneError` naming
    the file and the key.  ``lengths`` collects every length read, for the limits' length ratio."""

    def __init__(self, path: Path, data: dict[str, Any]) -> None:
        self.path, self.data = path, data
        self.lengths: list[tuple[str, float]] = []     # (key, SI) of every length read: limits

    # -- helpers ---------------------------------------------------------------------------------
    def fail(self, key: str, problem: str) -> SceneError:
        return SceneError(self.path, key, problem)

    def table(self, key: str, allowed: KeyTable | set[str], required: set[str] | None = None, value=None) -> dict:
        """The table at ``key`` (or ``value``), its keys checked against ``allowed``: a section's
        :class:`~drafting.scene.keys.KeyTable` (its keys, and its required ones unless ``required`` says)."""
        if isinstance(allowed, KeyTable):
            allowed, required = allowed.allowed, allowed.required if required is None else required
        required = frozenset() if required is None else required
        t = self.data.get(key, {}) if value is None else value
        if not isinstance(t, dict):
            raise self.fail(key, "must be a table")
        unknown = sorted(set(t) - allowed)
        if unknown:
            raise self.fail(f"{key}.{unknown[0]}", f"unknown key; allowed here: {', '.join(sorted(allowed))}")
        missing = sorted(required - set(t))
        if missing:
            raise self.fail(f"{key}.{missing[0]}", "is missing")
        return t

    def named_table(self, key: str) -> dict:
        """A table whose keys are names the user chooses (pivots, joints)."""
        t = self.data.get(key, {})
        if not isinstance(t, dict):
            raise self.fail(key, "must be a table of names, e.g. O1 = [0, 0]")
        return t

    def array(self, key: str) -> list[dict]:
        v = self.data.get(key, [])
        if not isinstance(v, list) or not all(isinstance(x, dict) for x in v):
            raise self.fail(key, f"must be written as [[{key}]] tables")
        return v

    def quantity(self, key: str, value: Any, kind: str, units: Units) -> float:
        try:
            si = to_si(value, kind, units.of(kind))
        except UnitError as e:
            raise self.fail(key, str(e)) from None
        if kind == "length":
            self.lengths.append((key, si))
        return si

    def point(self, key: str, value: Any, units: Units) -> Vec:
        if not (isinstance(value, list) and len(value) == 2):
            raise self.fail(key, "must be a point [x, y], e.g. [0, 0] or [\"0 mm\", \"25 mm\"]")
        x = self.quantity(key, value[0], "length", units)
        y = self.quantity(key, value[1], "length", units)
        return Vec(x, y)

    def text(self, key: str, value: Any) -> str:
        if not isinstance(value, str) or not value.strip():
            raise self.fail(key, "must be a non-empty string")
        return value.strip()

    def name(self, key: str, value: Any) -> str:
        v = self.text(key, value)
        if not re.fullmatch(r"[A-Za-z][A-Za-z0-9]*", v):
            raise self.fail(key, f"{v!r} is not a joint name (a letter then letters or digits, e.g. B or O2)")
        return v

    @staticmethod
    def shown(value: Any) -> str:
        """A value from the file as an error message quotes it: printable and short."""
        return cut(printable(repr(value)), 40)

    def signed(self, key: str, what: str, value: float, raw: Any, sense: Any) -> float:
        """A rate or couple, CCW positive: as given without a ``sense``; with sense = "ccw" or "cw" its
        magnitude turned that way (a negative value said to turn ccw contradicts itself).  ``key`` is the
        sense's key, ``raw`` the value as the file wrote it."""
        if sense is None:
            return value
        if sense not in ("ccw", "cw"):
            raise self.fail(key, f"{self.shown(sense)} must be \"ccw\" or \"cw\"")
        if value < 0 and sense == "ccw":
            raise self.fail(key, f"says ccw but {what} = {self.shown(raw)} turns clockwise; give {what} positive "
                                 f"with a sense, or signed without one")
        return abs(value) if sense == "ccw" else -abs(value)

    def number(self, key: str, value: Any) -> int:
        if isinstance(value, bool) or not isinstance(value, int) or value < 1:
            raise self.fail(key, "must be a link number, a whole number from 1")
        return value

    # -- sections --------------------------------------------------------------------------------
    def scene(self) -> Scene:
        """The scene: the header, the family's state (its Scene subclass), the [vary] ranges checked."""
        kind = self.data.get("kind", "linkage")
        fam = self._family(kind)
        allowed = COMMON_KEYS | fam.sections
        unknown = sorted(set(self.data) - allowed)
        if unknown:
            raise self.fail(unknown[0], f"unknown key; a {kind} scene has {', '.join(sorted(allowed))}")
        drawing = self.table("drawing", DRAWING)
        title = self.text("drawing.title", drawing.get("title", self.path.stem))
        number = self.text("drawing.number", drawing.get("number", "TOM-000"))
        paper = drawing.get("paper", "A4")
        if paper not in PAPERS:
            raise self.fail("drawing.paper", f"{paper!r} is not a paper size; use {' or '.join(PAPERS)}")
        orientation = drawing.get("orientation", "landscape")
        if orientation not in ORIENTATIONS:
            raise self.fail("drawing.orientation", f"{orientation!r} must be landscape or portrait")
        dimensions = drawing.get("dimensions")
        if dimensions is not None and not isinstance(dimensions, bool):
            raise self.fail("drawing.dimensions", "must be true or false (dimension the space diagram)")
        units = self.units()
        scales = read_scales(self, drawing.get("scale"), units)
        self.ranges(fam, kind, units)
        state = fam.read(self, units)
        ask = self.table("ask", ASK)
        analyses = ask.get("analyses", list(fam.default_analyses))
        if not isinstance(analyses, list) or not all(isinstance(a, str) for a in analyses) or not analyses:
            raise self.fail("ask.analyses", f"must be a list of analyses, e.g. {list(fam.default_analyses)}")
        for a in analyses:
            if a in fam.planned:
                raise self.fail("ask.analyses", f"{a!r} is not available yet; this version draws "
                                                f"{' and '.join(fam.askable)}")
            if a not in fam.askable:
                raise self.fail("ask.analyses", f"{a!r} is not an analysis; choose from {', '.join(fam.askable)}")
        find = ask.get("find")
        if find is not None and (not isinstance(find, list) or not all(isinstance(f, str) for f in find)):
            raise self.fail("ask.find", "must be a list of quantities, e.g. [\"V_C\", \"omega_2\"]")
        return fam.scene_type(self.path, title, number, paper, orientation, units, tuple(dict.fromkeys(analyses)),
                              tuple(find) if find is not None else None, kind, dimensions, scales, **state)

    def ranges(self, fam: Family, kind: str, units: Units) -> tuple:
        """The scene's ``[vary]`` ranges, read by its family (empty when it has none)."""
        vary = self.data.get("vary")
        if vary is None:
            return ()
        if not isinstance(vary, dict):
            raise self.fail("vary", "must be a table of ranges, e.g. crank_angle = [\"30 deg\", \"150 deg\"]")
        if fam.vary is None:
            kinds = " and ".join(sorted(k for k, f in families().items() if f.vary is not None))
            raise self.fail("vary", f"is read for {kinds} scenes; this is a {kind!r} scene")
        if not vary:
            raise self.fail("vary", "is empty; give at least one range, e.g. crank_angle = [\"30 deg\", \"150 deg\"]")
        return fam.vary(self.data, self.path, units)

    def _family(self, kind: Any) -> Family:
        if isinstance(kind, str):
            try:
                return family(kind)
            except KeyError:
                pass
        kinds = ", ".join(sorted(families()))
        if kind in PLANNED_KINDS:
            raise self.fail("kind", f"{kind!r} scenes are not available yet; this version reads {kinds} scenes")
        raise self.fail("kind", f"{kind!r} is not a scene kind; choose from {kinds}")

    def units(self) -> Units:
        t = self.table("units", UNITS)
        out = {}
        for key, kind in UNIT_KEYS.items():
            if key in t:
                try:
                    out[key] = check_unit(self.text(f"units.{key}", t[key]), kind)
                except UnitError as e:
                    raise self.fail(f"units.{key}", str(e)) from None
        return Units(**out)
