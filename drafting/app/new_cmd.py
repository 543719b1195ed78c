"""``drafting new KIND [--example NAME] [-o FILE]``: an annotated starter scene of a kind -- one of the
packaged examples (``drafting/app/examples/starter-<kind>-<name>.toml``, each one that renders), every key
and section commented from the readers' key tables (:mod:`drafting.scene.keys`), so the comments say what
the reference says."""

from __future__ import annotations

import re
import textwrap
from importlib import resources
from pathlib import Path

from ..families.registry import Family, families
from ..scene.header_keys import TOP
from ..scene.keys import QUANTITIES, Key, KeyTable, shown_default
from .keys_cmd import kind_named
from .reference import common_tables
from .solving import UserError

COMMENT_AT = 34
"""The column a key's comment starts at (further right after a longer line)."""
WIDTH = 110
"""The longest line a comment is wrapped to."""

_HEADER = re.compile(r"^\[(\[?)([^\[\]]+)\]\]?\s*$")
_KEY = re.compile(r"^([A-Za-z0-9_\-]+)\s*=")


def examples(kind: str) -> list[str]:
    """The starter examples packaged for ``kind``, the first the default."""
    stem = "starter-" + kind.replace(" ", "-") + "-"
    names = sorted(p.name[len(stem):-len(".toml")] for p in resources.files("drafting.app").joinpath("examples")
                   .iterdir() if p.name.startswith(stem) and p.name.endswith(".toml"))
    return sorted(names, key=lambda n: n != DEFAULTS.get(kind))


DEFAULTS = {"linkage": "four-bar"}
"""The example ``drafting new KIND`` writes without --example (otherwise the first by name)."""


def template(kind: str, example: str) -> str:
    """The starter scene ``example`` of ``kind`` as packaged (no comments)."""
    name = f"starter-{kind.replace(' ', '-')}-{example}.toml"
    return resources.files("drafting.app").joinpath("examples", name).read_text(encoding="utf-8")


def _comment(key: Key) -> str:
    parts = [key.meaning]
    if key.unit in QUANTITIES:
        parts.append(f"[{key.unit}]")
    if key.choices:
        parts.append("one of " + ", ".join(f'"{c}"' for c in key.choices))
    if shown_default(key) and not key.required:
        parts.append(f"default {shown_default(key)}")
    return "; ".join(parts)


def _with_comment(line: str, comment: str) -> list[str]:
    at = max(COMMENT_AT, len(line) + 2)
    lines = textwrap.wrap(comment, max(30, WIDTH - at - 2)) or [""]
    return [f"{line:<{at}}# {lines[0]}"] + [f"{'':<{at}}# {x}" for x in lines[1:]]


def annotated(source: str, fam: Family, example: str) -> str:
    """``source`` (a starter scene of ``fam``) with each section and key commented from its key table, and
    after the first of each section the keys it leaves out."""
    tables: dict[str, KeyTable] = {t.section: t for t in (TOP, *fam.keys, *common_tables(fam))}
    out = [f"# A {fam.kind} scene ({example}): edit it, then drafting render FILE.",
           f"# Every key of a {fam.kind} scene: drafting keys \"{fam.kind}\" (or docs/scene-reference.md).", ""]
    table, used, seen = tables[""], set(), set()
    subtables = {m[2] for m in map(_HEADER.match, source.splitlines()) if m}     # [body.points]: body's points

    def close() -> None:
        left = [k.name for k in table if k.name not in used and not k.name.startswith("<")
                and f"{table.section}.{k.name}" not in subtables]
        if table.section and table.section not in seen and left:
            while out and not out[-1]:
                out.pop()
            out.extend(_with_comment("", "also: " + ", ".join(left)))
        seen.add(table.section)

    for line in source.splitlines():
        head = _HEADER.match(line)
        if head:
            close()
            while out and not out[-1]:
                out.pop()
            out.append("")
            table, used = tables.get(head[2], KeyTable(head[2], "", ())), set()
            out.extend(_with_comment(line, table.meaning) if table.meaning else [line])
            continue
        key = _KEY.match(line)
        if key and table.keys:
            used.add(key[1])
            k = table.keys[0] if table.named else table.key(key[1]) if key[1] in table else None
            if k is not None and "#" not in line:
                out.extend(_with_comment(line, _comment(k) if not table.named else k.meaning.split(", e.g.")[0]))
                continue
        if line.strip() or (out and out[-1]):
            out.append(line)
    close()
    return "\n".join(out).rstrip() + "\n"


def cmd_new(kind: str, example: str | None, out: Path | None) -> int:
    kind = kind_named(kind)
    names = examples(kind)
    example = example or names[0]
    if example not in names:
        raise UserError(f"new: {kind} has no example {example!r}; choose from {', '.join(names)}")
    text = annotated(template(kind, example), families()[kind], example)
    if out is None:
        print(text, end="")
        return 0
    try:
        with open(out, "x", encoding="utf-8") as fh:
            fh.write(text)
    except FileExistsError:
        raise UserError(f"new: {out} already exists; give another file name or remove it first") from None
    except OSError as e:
        raise UserError(f"new: {out} cannot be written: {e.strerror or 'input/output error'}") from None
    print(f"  wrote {out}")
    return 0


def run_command(args) -> int:
    """``drafting new KIND [--example NAME] [-o FILE]``."""
    return cmd_new(args.kind, args.example, args.out)
