"""Enough of a TOML writer for the hostile scenes of :mod:`fuzz_scenes`: any key and string escaped as
TOML wants it, numbers too long for Python's int-to-str conversion written as they are (:class:`Raw`),
NaN and infinities, inline arrays and tables."""

from __future__ import annotations

import math
import re
from typing import Any


def _key(k: str) -> str:
    return k if re.fullmatch(r"[A-Za-z0-9_-]+", k) else _string(k)


def _string(s: str) -> str:
    out = []
    for c in s:
        n = ord(c)
        if c == "\\":
            out.append("\\\\")
        elif c == '"':
            out.append('\\"')
        elif n < 0x20 or n == 0x7F:
            out.append(f"\\u{n:04X}")
        elif 0xD800 <= n <= 0xDFFF:
            out.append("\ufffd")            # TOML cannot hold a surrogate
        else:
            out.append(c)
    return '"' + "".join(out) + '"'


class Raw(str):
    """Text written into the TOML as it is (a number too long for Python's int to str conversion)."""


def _value(v: Any) -> str:
    if isinstance(v, Raw):
        return str.__str__(v)
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        if math.isnan(v):
            return "nan"
        if math.isinf(v):
            return "inf" if v > 0 else "-inf"
        return repr(v)
    if isinstance(v, str):
        return _string(v)
    if isinstance(v, list):
        return "[" + ", ".join(_value(x) for x in v) + "]"
    if isinstance(v, dict):
        return "{" + ", ".join(f"{_key(k)} = {_value(x)}" for k, x in v.items()) + "}"
    raise TypeError(v)


def dumps(data: dict[str, Any]) -> str:
    """Enough of a TOML writer for scene data: top-level scalars, tables, arrays of tables."""
    head, body = [], []
    for k, v in data.items():
        if isinstance(v, dict):
            body.append(f"\n[{_key(k)}]")
            body += [f"{_key(a)} = {_value(b)}" for a, b in v.items()]
        elif isinstance(v, list) and v and all(isinstance(x, dict) for x in v):
            for t in v:
                body.append(f"\n[[{_key(k)}]]")
                body += [f"{_key(a)} = {_value(b)}" for a, b in t.items()]
        else:
            head.append(f"{_key(k)} = {_value(v)}")
    return "\n".join(head + body) + "\n"
