"""The scene reference, generated from the readers' own key tables (:mod:`drafting.scene.keys`): as Markdown
(docs/scene-reference.md, ``drafting keys --markdown``) and as text for the terminal (``drafting keys KIND``).

A kind's sections are its family's tables (:attr:`~drafting.families.registry.Family.keys`) and the ones every
scene shares (:mod:`drafting.scene.header_keys`, ``[units]``, ``[drawing.scale]``); ``[ask]`` lists the
analyses the family draws and ``[vary]`` is shown for a family that varies.
"""

from __future__ import annotations

import shutil
import textwrap
from dataclasses import replace

from ..families.registry import Family, families
from ..scene.drawing_scales import SCALE
from ..scene.header_keys import ASK, DRAWING, TOP, VARY
from ..scene.keys import Key, KeyTable, shown_default
from ..scene.unitset import UNITS

INTRO = """\
A scene is a TOML file.  Each section below lists its keys: the kind of quantity or value each holds, its
default, whether it is required and what it means.  A plain number is in the scene's `[units]` unit of its
kind (length in mm unless `[units] length` says otherwise); any quantity may instead carry its own unit as a
string (`"94 mm"`, `"3.7 in"`, `"120 rpm"`, `"70 deg"`).  Angles are counter-clockwise from +x.  A
`[[section]]` is written once per item.  `drafting keys KIND` prints a kind's sections on the terminal;
`drafting new KIND` writes an annotated starter scene."""

GENERATED = ("<!-- Generated from the scene readers' key tables by `drafting keys --markdown`; do not edit. "
             "tests/test_scene_reference.py holds this file to them. -->")


def common_tables(fam: Family) -> tuple[KeyTable, ...]:
    """The sections a scene of ``fam`` shares with every kind, ``[ask]`` with the family's analyses."""
    ask = (replace(ASK.keys[0], default=list(fam.default_analyses), choices=fam.askable), *ASK.keys[1:])
    return (DRAWING, SCALE, UNITS, replace(ASK, keys=ask)) + ((VARY,) if fam.vary is not None else ())


def _choices(key: Key) -> str:
    return "one of " + ", ".join(f'"{c}"' for c in key.choices) if key.choices else ""


def _header(table: KeyTable) -> str:
    return f"[{table.section}.points]" if table.section == "body.points" else table.header


# -- Markdown -------------------------------------------------------------------------------------------------
def _md_table(table: KeyTable, level: str = "###") -> list[str]:
    out = [f"{level} `{_header(table)}`", "", table.meaning[:1].upper() + table.meaning[1:] + ".", ""]
    if table.named:
        out += ["Its keys are names the scene chooses:", ""]
    out += ["| key | unit | default | required | meaning |", "|---|---|---|---|---|"]
    for k in table:
        meaning = "; ".join(x for x in (k.meaning, _choices(k)) if x).replace("|", "\\|")
        default = shown_default(k)
        out.append(f"| `{k.name}` | {k.unit} | {f'`{default}`' if default else ''} | "
                   f"{'yes' if k.required else ''} | {meaning} |")
    return out + [""]


def markdown() -> str:
    """docs/scene-reference.md: every key of every kind."""
    fams = families()
    kinds = ", ".join(f"[{k}](#{k.replace(' ', '-')})" for k in sorted(fams))
    out = [GENERATED, "", "# Scene reference", "", INTRO, "", f"Kinds: {kinds}.", "", "## The top level", ""]
    out += _md_table(TOP)[4:]
    first = fams[sorted(fams)[0]]
    out += ["## Every kind", "", "The sections every scene may have (`[ask] analyses` and `[vary]` depend on "
            "the kind: see each kind below).", ""]
    out += [line for t in common_tables(first) if t.section not in ("ask", "vary") for line in _md_table(t)]
    out += _md_table(ASK)
    for kind in sorted(fams):
        fam = fams[kind]
        out += [f"## {kind}", "", f'`kind = "{kind}"`.  `[ask] analyses`: '
                + ", ".join(f'"{a}"' for a in fam.askable)
                + f" (default {', '.join(repr(a).replace(chr(39), chr(34)) for a in fam.default_analyses)})."
                + ("  It may have `[vary]` (below)." if fam.vary is not None else ""), ""]
        out += [line for t in fam.keys for line in _md_table(t)]
        if fam.vary is not None:
            out += _md_table(VARY)
    return "\n".join(out).rstrip() + "\n"


# -- terminal -------------------------------------------------------------------------------------------------
def _text_table(table: KeyTable, width: int) -> list[str]:
    out = [f"{_header(table)}  {table.meaning}" + ("  (keys: names you choose)" if table.named else "")]
    defaults = {k.name: "required" if k.required else (f"= {shown_default(k)}" if shown_default(k) else "")
                for k in table}
    name_w, unit_w = (max(len(k.name) for k in table) + 2, max(len(k.unit) for k in table) + 2)
    default_w = min(24, max(len(d) for d in defaults.values()) + 2)
    for k in table:
        head = f"  {k.name:<{name_w}}{k.unit:<{unit_w}}{defaults[k.name]:<{default_w}}"
        meaning = "; ".join(x for x in (k.meaning, _choices(k)) if x)
        lines = textwrap.wrap(meaning, max(40, width - len(head))) or [""]
        out.append(head + lines[0])
        out += [" " * len(head) + line for line in lines[1:]]
    return out + [""]


def text(kind: str, width: int | None = None) -> str:
    """A kind's reference as terminal text: its own sections, then the ones every scene shares."""
    fam = families()[kind]
    width = width or min(120, shutil.get_terminal_size((100, 24)).columns)
    out = [f'{kind} scene: kind = "{kind}"   (every key: docs/scene-reference.md)', ""]
    out += [line for t in fam.keys for line in _text_table(t, width)]
    out += [line for t in common_tables(fam) for line in _text_table(t, width)]
    return "\n".join(out).rstrip() + "\n"
