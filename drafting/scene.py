"""Scene files (TOML) -> a validated :class:`Scene`.

Every problem is reported as one :class:`SceneError` sentence naming the file, the key and what is
wrong.  The format is documented in README.md ("Scene files").
"""

from __future__ import annotations

import math
import os
import re
import stat
import tomllib
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from constructions.errors import DegenerateInput
from constructions.geometry import Vec
from constructions.linkage import Attached, Branch, Link, Mechanism, Slide, assembly_plan

from .unitset import KEYS as UNIT_KEYS, Units
from . import limits
from .textsafe import cut, cut_middle, one_line, printable
from .units import UnitError, check_unit, to_si

ANALYSES = ("position", "velocity", "acceleration")
PLANNED = ("forces", "static forces", "dynamic forces", "sweep")
KINDS = ("linkage",)
PLANNED_KINDS = ("cam", "gear pair", "gear train")
PAPERS = ("A4", "A3")
ORIENTATIONS = ("landscape", "portrait")

TOP_KEYS = {"kind", "drawing", "units", "frame", "link", "slider", "point", "input", "assembly", "ask"}


class SceneError(Exception):
    """Bad scene input: ``str(error)`` is one sentence naming the file and the key."""

    def __init__(self, path: Path | str, key: str, problem: str) -> None:
        self.path, self.key, self.problem = str(path), key, problem
        # one line, whatever the file holds: control characters escaped, long names and quoted values
        # cut (textsafe), so the file and the key always show
        where, key = cut_middle(printable(str(path)), 120), cut(printable(key), 80)
        problem = one_line(problem)
        super().__init__(f"{where}: {key}: {problem}" if key else f"{where}: {problem}")


@dataclass(frozen=True)
class Scene:
    path: Path
    title: str
    drawing_number: str
    paper: str
    orientation: str
    units: Units
    mechanism: Mechanism
    angle: float          # crank angle, rad CCW from +x
    omega: float          # crank angular velocity, rad/s CCW positive
    analyses: tuple[str, ...]
    find: tuple[str, ...] | None
    alpha: float = 0.0    # crank angular acceleration, rad/s^2 CCW positive
    kind: str = "linkage"


def load_scene(path: Path | str) -> Scene:
    """Read a scene file; the limits (:mod:`drafting.limits`) are checked before anything else."""
    path = Path(path)
    text = _read_text(path)
    return parse_scene(text, path)


def _read_text(path: Path) -> str:
    """The file as text: at most MAX_FILE_BYTES are ever read, and every failure is one sentence."""
    try:
        mode = os.stat(path).st_mode          # before opening: a FIFO would block the open itself
        if stat.S_ISDIR(mode):
            raise IsADirectoryError
        if not stat.S_ISREG(mode):
            raise SceneError(path, "", "is not a regular file")
        with open(path, "rb") as fh:
            raw = fh.read(limits.MAX_FILE_BYTES + 1)
    except SceneError:
        raise
    except (FileNotFoundError, NotADirectoryError):
        raise SceneError(path, "", "no such scene file") from None
    except IsADirectoryError:
        raise SceneError(path, "", "is a folder, not a scene file") from None
    except PermissionError:
        raise SceneError(path, "", "cannot be read: permission denied") from None
    except OSError as e:
        raise SceneError(path, "", f"cannot be read: {e.strerror or 'input/output error'}") from None
    if len(raw) > limits.MAX_FILE_BYTES:
        raise SceneError(path, "", f"is larger than {limits.MAX_FILE_BYTES // 1024} KiB; a scene file may "
                                   f"be at most {limits.MAX_FILE_BYTES // 1024} KiB")
    try:
        return raw.decode("utf-8").removeprefix("\ufeff")
    except UnicodeDecodeError as e:
        line = raw.count(b"\n", 0, e.start) + 1
        raise SceneError(path, "", f"is not UTF-8 text (byte 0x{raw[e.start]:02x} on line {line}); save "
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
    lengths and magnitudes are checked first (:mod:`drafting.limits`)."""
    path = Path(path)
    if not isinstance(data, dict):
        raise SceneError(path, "", "must be a TOML table of sections")
    try:
        limits.check_data(data)
    except limits.LimitError as e:
        raise SceneError(path, e.key, e.problem) from None
    reader = _Reader(path, data)
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


class _Reader:
    def __init__(self, path: Path, data: dict[str, Any]) -> None:
        self.path, self.data = path, data
        self.lengths: list[tuple[str, float]] = []     # (key, SI) of every length read: limits

    # -- helpers ---------------------------------------------------------------------------------
    def fail(self, key: str, problem: str) -> SceneError:
        return SceneError(self.path, key, problem)

    def table(self, key: str, allowed: set[str], required: set[str] = frozenset(), value=None) -> dict:
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

    def number(self, key: str, value: Any) -> int:
        if isinstance(value, bool) or not isinstance(value, int) or value < 1:
            raise self.fail(key, "must be a link number, a whole number from 1")
        return value

    # -- sections --------------------------------------------------------------------------------
    def scene(self) -> Scene:
        unknown = sorted(set(self.data) - TOP_KEYS)
        if unknown:
            raise self.fail(unknown[0], f"unknown key; a scene has {', '.join(sorted(TOP_KEYS))}")
        kind = self.data.get("kind", "linkage")
        if kind in PLANNED_KINDS:
            raise self.fail("kind", f"{kind!r} scenes are not available yet; this version reads "
                                    f"{', '.join(KINDS)} scenes")
        if kind not in KINDS:
            raise self.fail("kind", f"{kind!r} is not a scene kind; choose from {', '.join(KINDS)}")
        drawing = self.table("drawing", {"title", "number", "paper", "orientation"})
        title = self.text("drawing.title", drawing.get("title", self.path.stem))
        number = self.text("drawing.number", drawing.get("number", "TOM-000"))
        paper = drawing.get("paper", "A4")
        if paper not in PAPERS:
            raise self.fail("drawing.paper", f"{paper!r} is not a paper size; use {' or '.join(PAPERS)}")
        orientation = drawing.get("orientation", "landscape")
        if orientation not in ORIENTATIONS:
            raise self.fail("drawing.orientation", f"{orientation!r} must be landscape or portrait")
        units = self.units()
        mechanism, angle, omega, alpha = self.mechanism(units)
        ask = self.table("ask", {"analyses", "find"})
        analyses = ask.get("analyses", ["velocity"])
        if not isinstance(analyses, list) or not all(isinstance(a, str) for a in analyses) or not analyses:
            raise self.fail("ask.analyses", "must be a list of analyses, e.g. [\"velocity\"]")
        for a in analyses:
            if a in PLANNED:
                raise self.fail("ask.analyses", f"{a!r} is not available yet; this version draws "
                                                f"{' and '.join(ANALYSES)}")
            if a not in ANALYSES:
                raise self.fail("ask.analyses", f"{a!r} is not an analysis; choose from {', '.join(ANALYSES)}")
        find = ask.get("find")
        if find is not None and (not isinstance(find, list) or not all(isinstance(f, str) for f in find)):
            raise self.fail("ask.find", "must be a list of quantities, e.g. [\"V_C\", \"omega_2\"]")
        return Scene(self.path, title, number, paper, orientation, units, mechanism, angle, omega,
                     tuple(dict.fromkeys(analyses)), tuple(find) if find is not None else None, alpha, kind)

    def units(self) -> Units:
        t = self.table("units", set(UNIT_KEYS))
        out = {}
        for key, kind in UNIT_KEYS.items():
            if key in t:
                try:
                    out[key] = check_unit(self.text(f"units.{key}", t[key]), kind)
                except UnitError as e:
                    raise self.fail(f"units.{key}", str(e)) from None
        return Units(**out)

    def mechanism(self, units: Units) -> tuple[Mechanism, float, float, float]:
        frame = self.named_table("frame")
        if not frame:
            raise self.fail("frame", "is missing: name the fixed pivots, e.g. O1 = [0, 0]")
        ground = {self.name(f"frame.{n}", n): self.point(f"frame.{n}", p, units) for n, p in frame.items()}

        links: list[Link] = []
        for i, t in enumerate(self.array("link"), 1):
            k = f"link[{i}]"
            self.table(k, {"number", "joints", "length"}, {"number", "joints", "length"}, value=t)
            n = self.number(f"{k}.number", t["number"])
            joints = t["joints"]
            if not (isinstance(joints, list) and len(joints) == 2):
                raise self.fail(f"{k}.joints", "must name the two joints of the link, e.g. [\"B\", \"C\"]")
            a, b = (self.name(f"{k}.joints", j) for j in joints)
            if a == b:
                raise self.fail(f"{k}.joints", f"a link needs two different joints, not {a} twice")
            length = self.quantity(f"{k}.length", t["length"], "length", units)
            if length <= 0:
                raise self.fail(f"{k}.length", "must be positive")
            if any(x.number == n for x in links):
                raise self.fail(f"{k}.number", f"link {n} is defined twice")
            links.append(Link(n, (a, b), length))
        if not links:
            raise self.fail("link", "is missing: a mechanism needs [[link]] tables")
        joints = {j for x in links for j in x.joints}

        attached: list[Attached] = []
        for i, t in enumerate(self.array("point"), 1):
            k = f"point[{i}]"
            self.table(k, {"name", "link", "from", "distance", "angle"}, {"name", "link", "from", "distance"},
                       value=t)
            nm = self.name(f"{k}.name", t["name"])
            if nm in ground:
                raise self.fail(f"{k}.name", f"{nm} is a fixed pivot")
            if any(a.name == nm for a in attached):
                raise self.fail(f"{k}.name", f"point {nm} is defined twice")
            ln = self.number(f"{k}.link", t["link"])
            link = next((x for x in links if x.number == ln), None)
            if link is None:
                raise self.fail(f"{k}.link", f"there is no link {ln}")
            if nm in link.joints:
                raise self.fail(f"{k}.name", f"{nm} is already a joint of link {ln} ({'-'.join(link.joints)})")
            base = self.name(f"{k}.from", t["from"])
            if base not in link.joints:
                raise self.fail(f"{k}.from", f"{base} is not a joint of link {ln} ({'-'.join(link.joints)})")
            dist = self.quantity(f"{k}.distance", t["distance"], "length", units)
            if dist <= 0:
                raise self.fail(f"{k}.distance", "must be positive")
            attached.append(Attached(nm, ln, base, dist, self.quantity(f"{k}.angle", t.get("angle", 0), "angle", units)))
        points = joints | {a.name for a in attached}

        slides: list[Slide] = []
        for i, t in enumerate(self.array("slider"), 1):
            k = f"slider[{i}]"
            self.table(k, {"number", "joint", "through", "angle", "on", "offset"}, {"joint"}, value=t)
            n = None
            if "number" in t:
                n = self.number(f"{k}.number", t["number"])
                if any(x.number == n for x in links) or any(s.number == n for s in slides):
                    raise self.fail(f"{k}.number", f"link {n} is already used")
            j = self.name(f"{k}.joint", t["joint"])
            if j not in points:
                raise self.fail(f"{k}.joint", f"joint {j} is on no link")
            if j in ground:
                raise self.fail(f"{k}.joint", f"{j} is a fixed pivot and cannot slide")
            if any(s.joint == j for s in slides):      # one guide per joint (the guide is named after it)
                raise self.fail(f"{k}.joint", f"joint {j} already slides on the guide of another slider")
            angle = self.quantity(f"{k}.angle", t.get("angle", 0), "angle", units)
            if "on" in t:
                on = self.number(f"{k}.on", t["on"])
                slotted = next((x for x in links if x.number == on), None)
                if slotted is None:
                    raise self.fail(f"{k}.on", f"there is no link {on} to cut the slot in")
                if j in slotted.joints or any(a.name == j and a.link == on for a in attached):
                    raise self.fail(f"{k}.on", f"{j} is a point of link {on}, so it cannot slide in its slot")
                if "through" in t:
                    raise self.fail(f"{k}.through", "a slot moves with its link: give offset (and angle), "
                                                    "not a fixed point")
                offset = self.quantity(f"{k}.offset", t.get("offset", 0), "length", units)
                slides.append(Slide(n, j, Vec(0.0, 0.0), angle, on, offset))
            else:
                if "through" not in t:
                    raise self.fail(f"{k}.through", "is missing: a fixed guide needs a point it passes through "
                                                    "(or give on = <link> for a slot in a moving link)")
                if "offset" in t:
                    raise self.fail(f"{k}.offset", "applies to a slot in a link (on = <link>)")
                if n is None:
                    raise self.fail(f"{k}.number", "a block on a fixed guide needs its link number")
                slides.append(Slide(n, j, self.point(f"{k}.through", t["through"], units), angle))

        inp = self.table("input", {"link", "angle", "omega", "tip_speed", "sense", "alpha"}, {"link", "angle"})
        crank_no = self.number("input.link", inp["link"])
        crank = next((x for x in links if x.number == crank_no), None)
        if crank is None:
            raise self.fail("input.link", f"there is no link {crank_no}")
        if sum(j in ground for j in crank.joints) != 1:
            raise self.fail("input.link", f"link {crank_no} must join one fixed pivot in [frame] to a moving joint")
        angle = self.quantity("input.angle", inp["angle"], "angle", units)
        sense = inp.get("sense")
        if sense not in (None, "ccw", "cw"):
            raise self.fail("input.sense", f"{sense!r} must be \"ccw\" or \"cw\"")
        if ("omega" in inp) == ("tip_speed" in inp):
            raise self.fail("input", "give exactly one of omega (e.g. \"10 rad/s\", \"120 rpm\") or "
                                     "tip_speed (e.g. \"500 mm/s\")")
        if "omega" in inp:
            omega = self.quantity("input.omega", inp["omega"], "angular velocity", units)
        else:
            speed = self.quantity("input.tip_speed", inp["tip_speed"], "velocity", units)
            if speed < 0:
                raise self.fail("input.tip_speed", "is a speed: give it positive and set sense = \"cw\" or \"ccw\"")
            omega = speed / crank.length
        if sense is not None:
            omega = abs(omega) if sense == "ccw" else -abs(omega)
        if omega == 0 or not math.isfinite(omega):
            raise self.fail("input", "the crank must turn: omega or tip_speed must not be zero")
        alpha = self.quantity("input.alpha", inp.get("alpha", 0), "angular acceleration", units)

        assembly = self.named_table("assembly")
        branches = {self.name(f"assembly.{j}", j): self.branch(f"assembly.{j}", v) for j, v in assembly.items()}
        for j in branches:
            if j not in points:
                raise self.fail(f"assembly.{j}", f"{j} is not a joint of the mechanism")
        m = Mechanism(ground, tuple(links), tuple(slides), tuple(attached), crank_no, branches)
        try:
            assembly_plan(m)
        except DegenerateInput as e:
            key = "assembly" if "branch" in str(e) or "assemblies" in str(e) else "link"
            raise self.fail(key, str(e)) from None
        return m, angle, omega, alpha

    def branch(self, key: str, value: Any) -> Branch:
        v = self.text(key, value)
        m = re.fullmatch(r"(left|right)\s+of\s+([A-Za-z][A-Za-z0-9]*)\s*->\s*([A-Za-z][A-Za-z0-9]*)", v)
        if m:
            return Branch(1 if m[1] == "left" else -1, (m[2], m[3]))
        m = re.fullmatch(r"(ahead of|behind)\s+([A-Za-z][A-Za-z0-9]*)", v)
        if m:
            return Branch(1 if m[1] == "ahead of" else -1, (m[2],))
        raise self.fail(key, f"{v!r} is not a branch; write e.g. \"left of B->O2\", \"right of B->O2\", "
                             f"\"ahead of B\" or \"behind B\"")
