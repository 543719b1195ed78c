"""The documented key tables of a scene file: each section's keys with their unit, default, whether
required, allowed values and a one-line meaning.

The readers check a section's keys against its :class:`KeyTable` (``SceneReader.table``), so the set of
keys a scene may write is the table's, and the reference (docs/scene-reference.md, ``drafting keys KIND``)
and the annotated starter scenes (``drafting new KIND``) are generated from the same tables: what is read
and what is documented cannot drift apart.

    CAM = KeyTable("cam", "the cam: its base circle, sense and speed", (
        Key("base_radius", "length", None, "radius of the base circle", required=True),
        Key("sense", "text", "ccw", "the cam's sense of rotation", choices=("ccw", "cw")), ...))

``unit`` is the kind of quantity a value is (a plain number is in the scene's ``[units]`` unit of that
kind, or a string carries its own unit: ``"50 mm"``) or, for a value that is no quantity, what it is
("text", "whole number", "number", "true/false", "point", "list").
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Iterator

QUANTITIES = ("length", "velocity", "acceleration", "angular velocity", "angular acceleration", "angle", "force",
              "torque", "mass", "moment of inertia", "stiffness", "power", "pressure")
"""The kinds of quantity a key's value may be (given in ``[units]``' unit of that kind, or with its own)."""
VALUES = ("text", "whole number", "number", "true/false", "point", "list", "table", "unit")
"""What a key's value is when it is no quantity."""


@dataclass(frozen=True)
class Key:
    """One key of a section: ``name``, the kind of quantity or value it holds (``unit``), its ``default``
    (None: none, or it depends on other keys, as ``meaning`` says), a one-line ``meaning``, whether every
    such section must give it, and its ``choices`` when it is one of a few words."""

    name: str
    unit: str
    default: Any
    meaning: str
    required: bool = False
    choices: tuple[str, ...] = ()


@dataclass(frozen=True)
class KeyTable:
    """The keys of one section.  ``section`` as a scene names it ("cam", "drawing.scale"); ``array``: written
    as ``[[section]]`` tables, one per item; ``named``: its keys are names the scene chooses (``[frame]``
    O1 = [0, 0]), described by the one entry of ``keys`` whose name is a placeholder such as "<name>"."""

    section: str
    meaning: str
    keys: tuple[Key, ...]
    array: bool = False
    named: bool = False

    def __post_init__(self) -> None:
        names = [k.name for k in self.keys]
        if len(set(names)) != len(names):
            raise ValueError(f"{self.section}: a key is listed twice")

    @property
    def allowed(self) -> frozenset[str]:
        """The keys the section may hold (what the reader accepts)."""
        return frozenset(k.name for k in self.keys)

    @property
    def required(self) -> frozenset[str]:
        """The keys every such section must give."""
        return frozenset(k.name for k in self.keys if k.required)

    def __iter__(self) -> Iterator[Key]:
        return iter(self.keys)

    def __contains__(self, name: object) -> bool:
        return any(k.name == name for k in self.keys)

    def key(self, name: str) -> Key:
        """The key ``name`` (KeyError if the section has none)."""
        for k in self.keys:
            if k.name == name:
                return k
        raise KeyError(f"{self.section} has no key {name!r}")

    @property
    def header(self) -> str:
        """How a scene writes the section: ``[cam]``, ``[[segment]]``."""
        return f"[[{self.section}]]" if self.array else f"[{self.section}]"


def shown_default(key: Key) -> str:
    """A key's default as the reference prints it: the TOML value, or "" when it has none."""
    d = key.default
    if d is None:
        return ""
    if isinstance(d, bool):
        return "true" if d else "false"
    if isinstance(d, str):
        return f'"{d}"'
    if isinstance(d, (list, tuple)):
        return "[" + ", ".join(f'"{x}"' if isinstance(x, str) else str(x) for x in d) + "]"
    return f"{d:g}" if isinstance(d, float) else str(d)
