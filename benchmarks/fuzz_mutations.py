"""The mutations of the hostile scenes (:mod:`fuzz_scenes`): each edits a gallery scene the way an
attacker or a careless user would, and says whether the scene must now be refused; :func:`make_case`
applies one to three of them to a scene drawn at random."""

from __future__ import annotations

import copy
import os
import random
import tomllib
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Callable

from fuzz_toml import Raw, dumps

GALLERY = Path(__file__).resolve().parents[1] / "gallery"


@dataclass
class Case:
    base: str
    kinds: list[str]
    data: dict[str, Any] | None          # scene data (None once the text was edited directly)
    text: str | bytes = ""
    filename: str = "scene.toml"
    must_refuse: bool = False
    notes: list[str] = field(default_factory=list)

    def source(self) -> str | bytes:
        return dumps(self.data) if self.data is not None else self.text


QUANTITY_KEYS = {"length", "distance", "through", "angle", "omega", "tip_speed", "alpha"}
ODD = ["\x00", "\x07", "\x08", "\x0b", "\x1b[31m", "\x1b]0;pwned\x07", "\x7f", "\x85", "\x9b", "\u2028",
       "\u2029", "\ufffe", "\uffff", "\u202e", "\u2066", "\U0001F600", "\u0301", "e\u0301", "<", ">", "&",
       "]]>", "<!ENTITY x 'y'>", "<script>alert(1)</script>", "&amp;", '"', "'", "\\", "\t", "\n", "\r",
       "\u00a0", "\ufeff", "\U000E0041", "\u200b", "%s%n", "{0}", "${x}"]
ODD_NAMES = ["sp ace", "-dash", "new\nline", "tab\t", "ctl\x1b[31m", "\u202eevil", "\u00e9\u2713", "a&b<c>",
             "quote'\"", "dots..", "x" * 200, "\U0001F600", "bell\x07", "back\\slash", "\ufffe\uffff",
             os.fsdecode(b"bad\xff\xfe"), os.fsdecode(b"half\xe2\x82")]


def _leaves(data: Any, path: tuple = ()):
    if isinstance(data, dict):
        for k, v in data.items():
            yield from _leaves(v, path + (k,))
    elif isinstance(data, list) and data and all(isinstance(x, (dict, list)) for x in data):
        for i, v in enumerate(data):
            yield from _leaves(v, path + (i,))
    else:
        yield path, data


def _set(data: Any, path: tuple, value: Any) -> None:
    node = data
    for k in path[:-1]:
        node = node[k]
    node[path[-1]] = value


def _is_quantity(path: tuple) -> bool:
    keys = [k for k in path if isinstance(k, str)]
    return bool(keys) and (keys[0] == "frame" or keys[-1] in QUANTITY_KEYS) and keys[0] not in ("units", "assembly", "ask", "drawing")


def _quantities(data) -> list[tuple]:
    out = []
    for path, v in _leaves(data):
        if _is_quantity(path):
            if isinstance(v, list):
                out += [path + (i,) for i in range(len(v))]
            else:
                out.append(path)
    return out


def _unit_for(path: tuple) -> tuple[str, str]:
    keys = [k for k in path if isinstance(k, str)]
    last = keys[-1]
    if keys[0] == "frame" or last in ("length", "distance", "through"):
        return "length", "mm"
    if last == "angle":
        return "angle", "deg"
    if last == "omega":
        return "angular velocity", "rad/s"
    if last == "alpha":
        return "angular acceleration", "rad/s^2"
    return "velocity", "mm/s"


def m_deep_nesting(rng: random.Random, c: Case) -> None:
    depth = rng.choice([11, 40, 300, 1000, 5000, 100_000])
    style = rng.choice(["array", "table", "dotted", "header", "mixed"])
    text = c.source() if isinstance(c.source(), str) else c.source().decode("utf-8", "replace")
    if style == "array":
        extra = "deep = " + "[" * depth + "1" + "]" * depth
    elif style == "table":
        extra = "deep = " + "{a = " * depth + "1" + "}" * depth
    elif style == "dotted":
        extra = ".".join(["a"] * depth) + " = 1"
    elif style == "header":
        extra = "[" + ".".join(["k"] * depth) + "]\nx = 1"
    else:
        extra = "deep = " + "[{a = " * (depth // 2) + "1" + "}]" * (depth // 2)
    if style in ("dotted",) or rng.random() < 0.5:
        # into a real section: the frame's first pivot (a nested value where a point belongs)
        if style in ("array", "mixed", "table") and "\n[frame]\n" in text:
            value = extra.split(" = ", 1)[1]
            text = text.replace("\n[frame]\n", f"\n[frame]\nZ9 = {value}\n", 1)
        else:
            text = extra + "\n" + text
    else:
        text = text + "\n" + extra + "\n"
    c.data, c.text = None, text
    c.must_refuse = c.must_refuse or depth > 10
    c.notes.append(f"nesting {style} {depth}")


def m_huge_counts(rng: random.Random, c: Case) -> None:
    if c.data is None:
        return
    n = rng.choice([40, 51, 200, 1000, 10_000])
    what = rng.choice(["frame", "point", "link", "slider"])
    d = c.data
    if what == "frame":
        d.setdefault("frame", {}).update({f"Q{i}": [i % 97, i % 89] for i in range(n)})
    elif what == "point":
        link = d["link"][-1]
        d["point"] = d.get("point", []) + [{"name": f"P{i}", "link": link["number"], "from": link["joints"][0],
                                             "distance": 10 + i % 50, "angle": f"{i % 360} deg"} for i in range(n)]
    elif what == "link":
        d["link"] = d["link"] + [{"number": 100 + i, "joints": [f"J{i}", f"K{i}"], "length": 10 + i % 7}
                                 for i in range(n)]
    else:
        d["slider"] = d.get("slider", []) + [{"number": 100 + i, "joint": f"S{i}", "through": [0, i], "angle": 0}
                                             for i in range(n)]
    total = len(d.get(what, []))
    c.must_refuse = c.must_refuse or total > 50 or what in ("link", "slider")   # new joints are on no link / unsolvable
    c.notes.append(f"{n} more {what}")


def m_huge_int(rng: random.Random, c: Case) -> None:
    if c.data is None:
        return
    leaves = [p for p, v in _leaves(c.data) if not isinstance(v, list)] + _quantities(c.data)
    path = rng.choice(leaves)
    k = rng.choice([19, 30, 308, 309, 400, 4300, 5000])
    value = rng.choice(["", "-"]) + "1" + "0" * k           # 10**k, written out
    _set(c.data, path, Raw(value) if k > 1000 else int(value))
    if _is_quantity(path):
        c.must_refuse = True
    c.notes.append(f"10**{k} at {path}")


def _oddify(rng: random.Random, s: str) -> str:
    parts = list(s) or [""]
    for _ in range(rng.randint(1, 4)):
        parts.insert(rng.randint(0, len(parts)), rng.choice(ODD))
    return "".join(parts)


def m_odd_text(rng: random.Random, c: Case) -> None:
    if c.data is None:
        return
    everywhere = rng.random() < 0.4
    d = c.data
    if everywhere:
        for path, v in list(_leaves(d)):
            if isinstance(v, str):
                _set(d, path, _oddify(rng, v))
            elif isinstance(v, list):
                _set(d, path, [_oddify(rng, x) if isinstance(x, str) else x for x in v])
        if rng.random() < 0.5 and "frame" in d:                      # keys too
            d["frame"] = {(_oddify(rng, k) if rng.random() < 0.5 else k): v for k, v in d["frame"].items()}
        c.notes.append("odd text everywhere")
    else:
        dr = d.setdefault("drawing", {})
        for key, default in (("title", "t"), ("number", "n")):
            old = str(dr.get(key, default))
            dr[key] = _oddify(rng, old)[:200] if len(old) <= 200 else _oddify(rng, old)
        if not dr["title"].strip():
            dr["title"] = "x" + dr["title"]
        if not dr["number"].strip():
            dr["number"] = "x" + dr["number"]
        c.notes.append("odd title and number")


def _replace_quantity(rng: random.Random, c: Case, make: Callable[[str, str], str], note: str) -> None:
    if c.data is None:
        return
    qs = _quantities(c.data)
    if not qs:
        return
    path = rng.choice(qs)
    kind, unit = _unit_for(path)
    _set(c.data, path, make(kind, unit))
    c.must_refuse = True
    c.notes.append(f"{note} at {path}")


def m_expression_unit(rng: random.Random, c: Case) -> None:
    exprs = ["9**9**9 {u}", "2*3 {u}", "10**10 {u}", "(5+5) {u}", "5 {u} + 1 {u}", "1e99**2 {u}", "2^10 {u}",
             "3 * 4 {u}", "4/2 {u}", "9**9**9**9", "__import__('os') {u}", "1 {u}**1000000", "5 {u}^99",
             "5 {u} {u} {u} {u} {u} {u} {u}", "0x10 {u}", "1_000 {u}", "5 {u})"]
    _replace_quantity(rng, c, lambda kind, unit: rng.choice(exprs).format(u=unit), "expression unit")


def m_percent_unit(rng: random.Random, c: Case) -> None:
    if c.data is not None and rng.random() < 0.25:
        c.data.setdefault("units", {})[rng.choice(["length", "velocity", "angle", "angular_velocity"])] = \
            rng.choice(["percent", "%", "dimensionless", "count", "ppm"])
        c.must_refuse = True
        c.notes.append("percent unit in [units]")
        return

    def make(kind: str, unit: str) -> str:
        if kind == "angle":
            return rng.choice(["0 dimensionless", "5 dimensionless", "70 %", "70 percent", "3 count", "1 ppm"])
        if kind == "velocity":
            return rng.choice(["500 percent", "500 %", "5 Hz", "5 mm"])
        if kind == "angular velocity":
            return rng.choice(["10 Hz", "10 percent", "10 1/s", "10 mm/s"])
        return rng.choice(["50 percent", "50 %", "50 dimensionless", "50 count", "50 deg", "50 rad"])
    _replace_quantity(rng, c, make, "percent unit")


def m_decimal_comma(rng: random.Random, c: Case) -> None:
    _replace_quantity(rng, c, lambda kind, unit: f"{rng.randint(0, 200)},{rng.randint(0, 99)} {unit}"
                      if rng.random() < 0.8 else f"{rng.randint(1, 200)},{rng.randint(0, 9)}", "decimal comma")


def m_duplicate(rng: random.Random, c: Case) -> None:
    if c.data is None:
        return
    d = c.data
    used = {x["number"] for x in d.get("link", []) + d.get("slider", [])
            if isinstance(x, dict) and type(x.get("number")) is int} or {10}
    if d.get("slider") and rng.random() < 0.6:
        s = dict(d["slider"][0])
        s["number"] = max(used) + 1
        s["through"] = [0, rng.choice([0, 5, 10])]
        d["slider"].append(s)
        c.notes.append("second slider on one joint")
    elif d.get("point") and rng.random() < 0.5:
        d["point"].append(dict(d["point"][0]))
        c.notes.append("point defined twice")
    else:
        joint = d["link"][-1]["joints"][-1]
        d["slider"] = d.get("slider", []) + [{"number": max(used) + 1 + i, "joint": joint, "through": [0, 0],
                                              "angle": "0 deg"} for i in range(2)]
        c.notes.append("two new sliders on one joint")
    c.must_refuse = True


def _smallest_length(d: dict, replaced: str) -> float:
    """The smallest non-zero plain number among the frame's coordinates (but the x of ``replaced``, which
    the mutation overwrites) and the links' lengths; 1e9 when there is none: a "ratio" mutation puts that
    x beyond 1e6 times it, so beyond the scene's length ratio whatever its other lengths (a fixed 2e8 lay
    within 1e6 of the front-end loader's 220 mm; a replaced smallest leaves a larger one; a frame of one
    pivot at the origin has none)."""
    def plain(x) -> bool:
        return isinstance(x, (int, float)) and not isinstance(x, bool) and x != 0 and abs(x) < 1e300
    nums = [abs(x) for n, p in d.get("frame", {}).items() if isinstance(p, list) for i, x in enumerate(p)
            if not (n == replaced and i == 0) and plain(x)]
    nums += [abs(t["length"]) for t in d.get("link", []) if isinstance(t, dict) and plain(t.get("length"))]
    return float(min(nums, default=1e9))


def m_giant_coordinates(rng: random.Random, c: Case) -> None:
    if c.data is None:
        return
    d = c.data
    how = rng.choice(["pivot", "pivot", "link", "tiny link", "through", "float", "ratio"])
    if how in ("pivot", "float", "ratio") and d.get("frame"):
        name = rng.choice(list(d["frame"]))
        v = {"pivot": rng.choice([1e10, 1e15, 1e30, 1e300, -1e300, 2 ** 1023]), "float": float("inf"),
             "ratio": rng.choice([2e6, 1e7]) * _smallest_length(d, name)}[how]
        d["frame"][name] = [v, d["frame"][name][1] if isinstance(d["frame"][name], list) and len(d["frame"][name]) > 1 else 0]
    elif how == "through" and d.get("slider"):
        d["slider"][0]["through"] = [rng.choice([1e12, 1e300]), 0]
    elif how == "tiny link":
        d["link"][0]["length"] = rng.choice([1e-12, 1e-300, 5e-324, "1e-9 mm", "1e-6 mm"])
    else:
        d["link"][0]["length"] = rng.choice([1e10, 1e300, "1e12 m", "1e300 km"])
    c.must_refuse = True
    c.notes.append(f"giant/tiny {how}")


def m_long_string(rng: random.Random, c: Case) -> None:
    if c.data is None:
        return
    n = rng.choice([201, 1000, 100_000, 1_000_000])
    s = rng.choice(["x", "\u00e9", "\U0001F600", "ab "]) * n
    where = rng.choice(["title", "number", "unit", "name", "branch", "key"])
    d = c.data
    if where in ("title", "number"):
        d.setdefault("drawing", {})[where] = s
    elif where == "unit":
        d.setdefault("units", {})["length"] = s
    elif where == "name":
        d["link"][0]["joints"][1] = s
    elif where == "branch":
        d["assembly"] = {"C": s}
    else:
        d.setdefault("frame", {})[s[:n]] = [0, 0]
    c.must_refuse = True
    c.notes.append(f"string of {n} at {where}")


def m_odd_filename(rng: random.Random, c: Case) -> None:
    c.filename = rng.choice(ODD_NAMES) + rng.choice([".toml", ".TOML", "", ".toml.toml"])
    if c.data is not None and not c.must_refuse and rng.random() < 0.5:
        c.data.get("drawing", {}).pop("title", None)          # the title becomes the file's stem
    c.notes.append(f"file name {c.filename!r}")


def m_bad_bytes(rng: random.Random, c: Case) -> None:
    src = c.source()
    raw = src.encode("utf-8") if isinstance(src, str) else src
    at = rng.randrange(len(raw))
    bad = rng.choice([b"\xff", b"\xfe\xff", b"\xc3", b"\xed\xa0\x80", b"\x00", b"\xef\xbb\xbf"])
    c.data, c.text = None, raw[:at] + bad + raw[at:]
    c.must_refuse = c.must_refuse or bad not in (b"\xef\xbb\xbf",)
    c.notes.append(f"bytes {bad!r} at {at}")


def m_vary(rng: random.Random, c: Case) -> None:
    """An odd [vary] range: reversed, empty, a step of zero or of the smallest float, NaN, infinite, the wrong
    unit, an unknown key, a list of one or of many.  (Plain numbers, {from = 1, to = 2}, are not odd: a
    scene's plain numbers are in its units, so the 1000-per-kind run found it rightly accepted.)"""
    vary = c.data["vary"]                      # a scene without [vary]: KeyError, the mutation is skipped
    key = rng.choice(sorted(vary))
    odd = rng.choice([["150 deg", "30 deg"], {"from": "5 rad/s", "to": "15 rad/s", "step": "0 rad/s"},
                      {"from": "5 rad/s", "to": "15 rad/s", "step": "1e-300 rad/s"},
                      {"from": "nan rad/s", "to": "15 rad/s", "step": "1 rad/s"}, ["inf deg", "30 deg"],
                      ["30 mm", "150 mm"], ["30 deg"], ["30 deg"] * 101, [],
                      {"from": "5 rad/s", "to": "15 rad/s", "step": "-1 rad/s"}, "30 deg", ["1e300 deg", "2e300 deg"]])
    if rng.random() < 0.2:
        key = rng.choice(["length", "link[1].length", "zzz", "crank angle", ""])
    vary[key] = odd
    c.must_refuse = True
    c.notes.append(f"vary {key} = {odd!r:.60}")


MUTATIONS: dict[str, Callable[[random.Random, Case], None]] = {
    "deep nesting": m_deep_nesting, "huge counts": m_huge_counts, "huge int": m_huge_int,
    "odd text": m_odd_text, "expression unit": m_expression_unit, "percent unit": m_percent_unit,
    "decimal comma": m_decimal_comma, "duplicate": m_duplicate, "giant coordinates": m_giant_coordinates,
    "long string": m_long_string, "vary": m_vary, "odd file name": m_odd_filename, "bad bytes": m_bad_bytes,
}
TEXT_LEVEL = ("deep nesting", "bad bytes")           # applied last: they turn the data into text


def gallery() -> dict[str, dict[str, Any]]:
    return {p.stem: tomllib.loads(p.read_text(encoding="utf-8")) for p in sorted(GALLERY.glob("*.toml"))}


def make_case(rng: random.Random, bases: dict[str, dict[str, Any]], kinds: list[str] | None = None,
              base: str | None = None) -> Case:
    """A case from ``base`` (else one drawn from ``bases``) with the mutations ``kinds`` (else one to three
    drawn; ``[]``: none, the scene as it is, for the commands' own hostile options)."""
    base = base if base is not None else rng.choice(sorted(bases))
    if kinds is None:
        kinds = rng.sample(sorted(MUTATIONS), rng.choice([1, 1, 2, 3]))
    kinds = sorted(kinds, key=lambda k: k in TEXT_LEVEL)
    c = Case(base, list(kinds), copy.deepcopy(bases[base]))
    for k in kinds:
        before = (copy.deepcopy(c.data), c.text, c.must_refuse, list(c.notes))
        try:
            MUTATIONS[k](rng, c)
        except (TypeError, KeyError, IndexError, AttributeError, ValueError):
            # an earlier mutation changed the shape this one edits: skip it
            c.data, c.text, c.must_refuse, c.notes = before
            c.notes.append(f"({k} skipped)")
    return c
