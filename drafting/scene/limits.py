"""Limits on a scene, checked before any work so that a hostile or careless file costs well under a
second and is refused in one sentence naming the file, the key and the limit.

The limits (README, "Scene files" / "Limits") and why they are what they are:

- :data:`MAX_FILE_BYTES` (256 KiB).  A scene is a few kilobytes; Python's TOML reader needs ~1 s per
  MB, so this bounds the parse at ~0.3 s whatever the file holds.
- :data:`MAX_DEPTH` (10).  A scene nests three deep (``[[link]]`` -> table -> ``joints = [..]``);
  planned scene kinds need a few more.  The raw text is scanned *before* the TOML reader runs, because
  the reader recurses on nested arrays and inline tables (a few hundred levels exhaust Python's stack)
  and takes quadratic time on long dotted keys.
- :data:`MAX_COUNTS` (50 fixed pivots, links, sliders, points; 50 loads, couples, masses, springs,
  friction tables) and :data:`MAX_ENTRIES` (100 for any other table or array).  A sheet is unreadable
  long before; layout time grows with the number of labelled points (50 points: ~1.5 s, 200 points:
  ~11 s), so the centres of gravity a scene adds count with its points (:data:`MAX_COUNTS` ["point"]).
- :data:`MAX_STRING` (200 characters) for every string and key: a title longer than that cannot be
  lettered in the title block anyway.
- :data:`MAX_NUMBER_TOKEN` (100 characters) for a number in the text: longer integers would make the
  TOML reader fail inside Python's int conversion.
- :data:`MAGNITUDES`: every non-zero length lies within 1 um .. 1000 km, and (:data:`LENGTH_RATIO`) the
  scene's non-zero lengths within a factor 1e6 of each other.  The engine decides "equal" within 1e-9
  of the scene size and graphical and analytic values must agree to 1e-9 relative: a length 1e-6 of
  the largest still carries its direction to ~2e-10 (double rounding 2.2e-16 x 1e6), while at a ratio of
  1e9 a length sits at the tolerance itself and its direction is good to only ~2e-7, so the check would
  report disagreements that are rounding.  1e6 is also the span the design asks the engine to handle
  (links from 1e-3 to 1e3).  Speeds and angular speeds lie within 1e-12 .. 1e12 (SI) and angles within
  +-10,000 turns (beyond, the crank angle itself is known to worse than 1e-11 rad).
- :data:`MAX_SWEEP_STEPS` (1e7): reserved for full-cycle sweeps (about 1 GB of results at the
  analytic sweep's ~105 bytes per angle).
"""

from __future__ import annotations

import math
import re
from typing import Any, Iterable

MAX_FILE_BYTES = 256 * 1024
MAX_DEPTH = 10
MAX_COUNTS = {"frame": 50, "link": 50, "slider": 50, "point": 50,
              "load": 50, "couple": 50, "mass": 50, "spring": 50, "friction": 50}
COUNTED = {"frame": "fixed pivots", "link": "links", "slider": "sliders", "point": "points", "load": "loads",
           "couple": "couples", "mass": "masses", "spring": "springs", "friction": "friction tables"}
"""What each counted section holds, as a refusal names it."""
MAX_ENTRIES = 100
MAX_STRING = 200
MAX_NUMBER_TOKEN = 100
MAX_SWEEP_STEPS = 10**7

# kind -> (smallest non-zero magnitude, largest magnitude), SI
MAGNITUDES: dict[str, tuple[float, float]] = {
    "length": (1e-6, 1e6),
    "velocity": (1e-12, 1e12),
    "angular velocity": (1e-12, 1e12),
    "acceleration": (1e-12, 1e15),
    "angular acceleration": (1e-12, 1e15),
    "force": (1e-12, 1e12),
    "torque": (1e-12, 1e12),
    "mass": (1e-12, 1e12),
    "moment of inertia": (1e-15, 1e12),
    "stiffness": (1e-12, 1e15),
    "power": (1e-12, 1e12),
    "pressure": (1e-12, 1e15),
    "angle": (0.0, 2 * math.pi * 1e4),
}
LENGTH_RATIO = 1e6


class LimitError(ValueError):
    """A limit is exceeded: ``key`` (may be empty) and ``problem`` (one sentence without the key)."""

    def __init__(self, key: str, problem: str) -> None:
        self.key, self.problem = key, problem
        super().__init__(f"{key}: {problem}" if key else problem)


def _size(n: int) -> str:
    return f"{n // 1024} KiB" if n >= 1024 and n % 1024 == 0 else f"{n:,} bytes"


def check_file_size(size: int) -> None:
    if size > MAX_FILE_BYTES:
        raise LimitError("", f"is {size:,} bytes; a scene file may be at most {_size(MAX_FILE_BYTES)}")


# -- the raw text, before the TOML reader ------------------------------------------------------------

_TOKEN = re.compile(r'''
    (?P<mlb>"""(?:[^\\]|\\.)*?"""(?!")|"""(?:[^\\]|\\.)*?""""{1,2})
  | (?P<mll>\'\'\'.*?\'\'\'(?!\')|\'\'\'.*?\'\'\'\'{1,2})
  | (?P<bs>"(?:[^"\\\n]|\\.)*")
  | (?P<ls>'[^'\n]*')
  | (?P<comment>\#[^\n]*)
  | (?P<nl>\n)
  | (?P<ws>[ \t\r]+)
  | (?P<punct>[\[\]{},=.])
  | (?P<word>[^\s"'\#\[\]{},=.]+)
  | (?P<other>.)
''', re.S | re.X)


def check_text(text: str, what: str = "a scene") -> None:
    """Scan TOML text for nesting deeper than :data:`MAX_DEPTH` and over-long numbers, without
    recursion and without running the TOML reader; raises :class:`LimitError` naming the line (and
    the key being written there)."""
    depth = 0                  # open [ and { of values (and of a table header)
    stack: list[str] = []      # the open brackets
    expect_key = True          # a key comes next (line start at top level, after '{' or ',' in '{')
    key_parts = 1              # parts of the dotted key being read
    key_text: list[str] = []
    line = 1
    header = False
    last_key = ""              # (shortened and made printable only when it is named in an error)

    def fail(problem: str) -> LimitError:
        key = _short(last_key) if last_key else ""
        where = f"line {line}" + (f" ({key})" if key else "")
        return LimitError("", f"{where}: {problem}")

    for m in _TOKEN.finditer(text):
        kind = m.lastgroup
        tok = m.group()
        if kind in ("mlb", "mll"):
            line += tok.count("\n")
            if expect_key:
                key_text.append(tok)
            continue
        if kind == "nl":
            line += 1
            if not stack:
                expect_key, key_parts, key_text, header, last_key = True, 1, [], False, ""
            continue
        if kind in ("ws", "comment"):
            continue
        if kind in ("bs", "ls", "word", "other"):
            if kind == "word" and (expect_key or header) and len(tok) > MAX_STRING:
                last_key = ""
                raise fail(f"a key of {len(tok):,} characters; keys may have at most {MAX_STRING}")
            if kind == "word" and not (expect_key or header) and len(tok) > MAX_NUMBER_TOKEN:
                raise fail(f"a bare value of {len(tok):,} characters; numbers may have at most "
                           f"{MAX_NUMBER_TOKEN}")
            if expect_key or header:
                key_text.append(tok)
            continue
        # punctuation
        if tok == ".":
            if expect_key or header:
                key_parts += 1
                key_text.append(".")
                if depth + key_parts > MAX_DEPTH:
                    last_key = "".join(key_text).strip(". ")
                    raise fail(f"the key nests deeper than {MAX_DEPTH} levels; {what} nests at most "
                               f"{MAX_DEPTH} deep")
            continue
        if tok == "=":
            if expect_key:
                last_key = "".join(key_text).strip()
            expect_key = False
            continue
        if tok in "[{":
            if not stack and expect_key and tok == "[" and not key_text:
                header = True          # a table header [a.b] or [[a.b]]
            stack.append(tok)
            depth += 1
            if depth + key_parts - 1 > MAX_DEPTH:
                raise fail(f"values nest deeper than {MAX_DEPTH} levels; {what} nests at most {MAX_DEPTH} deep")
            if tok == "{":
                expect_key, key_parts, key_text = True, 1, []
            elif not header:
                expect_key = False
            continue
        if tok in "]}":
            if stack:
                stack.pop()
                depth -= 1
            if header and not stack:
                last_key = "".join(key_text).strip()
                header = False
                key_parts = 1
                key_text = []
            expect_key = False
            continue
        if tok == ",":
            if stack and stack[-1] == "{":
                expect_key, key_parts, key_text = True, 1, []
            continue


def _short(text: str, limit: int = 40) -> str:
    from .textsafe import cut, printable
    return printable(cut(text, limit))


# -- the parsed data -----------------------------------------------------------------------------------

_BARE_KEY = re.compile(r"[A-Za-z0-9_-]+")


def _key(prefix: str, k: Any) -> str:
    """A dotted key as TOML writes it: a key that is not bare (empty, spaces, dots) in double quotes."""
    if isinstance(k, int):
        return f"{prefix}[{k + 1}]"
    k = str(k)
    if not _BARE_KEY.fullmatch(k):
        k = '"' + k.replace("\\", "\\\\").replace('"', '\\"') + '"'
    return f"{prefix}.{k}" if prefix else k


def check_data(data: dict[str, Any]) -> None:
    """Walk parsed scene data (iteratively, so any depth is safe) and refuse tables or arrays with
    too many entries, strings and keys that are too long, and nesting deeper than :data:`MAX_DEPTH`.
    Array items are named as the scene reader names them: ``link[3]`` is the third ``[[link]]``."""
    for name, limit in MAX_COUNTS.items():
        v = data.get(name)
        if isinstance(v, (dict, list)) and len(v) > limit:
            what = COUNTED[name]
            raise LimitError(name, f"{len(v):,} {what}; a scene may have at most {limit}")
    todo: list[tuple[str, Any, int]] = [("", data, 0)]
    while todo:
        key, value, depth = todo.pop()
        if depth > MAX_DEPTH:
            raise LimitError(key, f"nests deeper than {MAX_DEPTH} levels; a scene nests at most {MAX_DEPTH} deep")
        if isinstance(value, str):
            if len(value) > MAX_STRING:
                raise LimitError(key, f"a text of {len(value):,} characters; texts may have at most {MAX_STRING}")
        elif isinstance(value, dict):
            if len(value) > MAX_ENTRIES and key not in MAX_COUNTS:
                raise LimitError(key or "scene", f"{len(value):,} entries; a table may have at most {MAX_ENTRIES}")
            for k, v in value.items():
                if not isinstance(k, str):              # only from data built in Python, never from TOML
                    raise LimitError(_key(key, str(k)[:40]), "a key must be text")
                if len(k) > MAX_STRING:
                    raise LimitError(_key(key, k[:40] + "\u2026"),
                                     f"a key of {len(k):,} characters; keys may have at most {MAX_STRING}")
                todo.append((_key(key, k), v, depth + 1))
        elif isinstance(value, list):
            if len(value) > MAX_ENTRIES and key not in MAX_COUNTS:
                raise LimitError(key, f"{len(value):,} entries; an array may have at most {MAX_ENTRIES}")
            for i, v in enumerate(value):
                todo.append((_key(key, i), v, depth + 1))


# -- values -----------------------------------------------------------------------------------------------

def magnitude_problem(kind: str, si: float) -> str | None:
    """Why an SI value of ``kind`` is out of range, or None (zero is always in range)."""
    lo, hi = MAGNITUDES.get(kind, (0.0, math.inf))
    a = abs(si)
    if a > hi:
        return "too large"
    if 0 < a < lo:
        return "too small"
    return None


def length_ratio_problem(lengths: Iterable[tuple[str, float]]) -> tuple[str, float, str, float] | None:
    """The non-zero lengths of a scene (key, SI value) must lie within :data:`LENGTH_RATIO` of each
    other.  When they do not, returns (key, value, other key, other value): the extreme (smallest or
    largest) that lies farther from the scene's typical length (the median, on a log scale) -- the one
    most likely mistyped -- and the opposite extreme it was compared with."""
    nz = [(k, abs(v)) for k, v in lengths if v != 0 and math.isfinite(v)]
    if len(nz) < 2:
        return None
    small = min(nz, key=lambda kv: kv[1])
    large = max(nz, key=lambda kv: kv[1])
    if large[1] <= LENGTH_RATIO * small[1]:
        return None
    logs = sorted(math.log10(v) for _, v in nz)
    mid = logs[len(logs) // 2] if len(logs) % 2 else (logs[len(logs) // 2 - 1] + logs[len(logs) // 2]) / 2
    if math.log10(large[1]) - mid > mid - math.log10(small[1]):
        return large[0], large[1], small[0], small[1]
    return small[0], small[1], large[0], large[1]


def sweep_problem(steps: int) -> str | None:
    """For full-cycle sweeps (not in the scene format yet): the number of steps must be 1..1e7."""
    if steps < 1:
        return "a sweep needs at least one step"
    if steps > MAX_SWEEP_STEPS:
        return f"{steps:,} steps; a sweep may have at most {MAX_SWEEP_STEPS:,}"
    return None
