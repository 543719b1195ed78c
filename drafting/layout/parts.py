"""What each drawing command of a sheet is part of: an entity of the record, or the sheet's own furniture.

Every command carries a ``name``: an entity's name (``"link 2"``), or the entity's name followed by
``:`` and the part it draws (``"V_B:head"``, ``"pivot O1:hatch"``, ``"V_B:label"``), or a name the
layout gives what it draws for the sheet itself (``"frame"``, ``"step 3 number"``, ``"results row 2 col 1"``,
``"scale bar velocity tick 0"``, ``"title block caption Date"``).  :func:`part_of` says which part a
command belongs to: its owner (the entity, or one piece of furniture: the frame, the title block, the
results table, step 3's words, a scale bar), the owner's kind and title, and whether the command is the
label naming the owner.  This is what the SVG's groups (:mod:`drafting.backends.svg`) and the
step-through page say about a sheet.

The kind of an entity comes from its type in the record (:func:`entity_kinds`: an
:class:`~constructions.entities.Arrow` is a ``vector``, a :class:`~constructions.entities.TrialLine` a
``trial-line``; a type not in the table is named from its class, ``SpringMark`` -> ``spring-mark``),
never from a style name.  :func:`xml_id` and :class:`Ids` make stable, unique XML ids of names.
"""

from __future__ import annotations

import functools
import re
import unicodedata
from typing import Mapping, NamedTuple

from constructions import entities as ent
from constructions.record import Construction

#: An entity type -> (the kind its SVG group's class names, the noun its title uses).
ENTITY_KINDS: dict[type, tuple[str, str]] = {
    ent.Point: ("point", "point"), ent.Arrow: ("vector", "vector"), ent.TrialLine: ("trial-line", "trial line"),
    ent.Bar: ("link", "link"), ent.Plate: ("link", "link (plate)"), ent.Pivot: ("pivot", "fixed pivot"),
    ent.Guide: ("guide", "guide"), ent.Block: ("block", "slider block"), ent.Polygon: ("polygon", "polygon"),
    ent.Arc: ("arc", "arc"), ent.ScaleBar: ("scale-bar", "scale bar"), ent.Circle: ("circle", "circle"),
    ent.Curve: ("curve", "curve"), ent.Segment: ("segment", "line"), ent.Dimension: ("dimension", "dimension"),
    ent.AngleMark: ("angle", "angle"), ent.Note: ("note", "note"), ent.Chart: ("chart", "chart"),
    ent.LinkNumber: ("link-number", "link number"), ent.BodyOutline: ("body", "free body"),
    ent.MomentArc: ("couple", "couple"), ent.RotationArrow: ("rotation", "sense of rotation"),
    ent.FollowerBody: ("follower", "follower"), ent.Detail: ("detail", "detail"),
}

#: Roles a title names before the noun ("V_C -- result vector"); the others say nothing the noun does not.
_ROLE_WORDS = {ent.Role.KNOWN: "known ", ent.Role.RESULT: "result ", ent.Role.IMAGE: "image "}


def entity_kind(entity: ent.Entity) -> tuple[str, str]:
    """The kind (class name) and noun of ``entity``'s type; a type not in :data:`ENTITY_KINDS` is
    named from its class."""
    got = ENTITY_KINDS.get(type(entity))
    if got is None:
        words = re.sub(r"(?<=[a-z0-9])(?=[A-Z])", " ", type(entity).__name__).lower()
        got = (words.replace(" ", "-"), words)
    return got


def entity_kinds(construction: Construction) -> dict[str, tuple[str, str]]:
    """Each entity of ``construction`` by name, in the record's order: (kind, title), the title being what
    it shows and what it is: ``"V_B -- known velocity vector"`` (a polygon's vectors and trial lines),
    ``"link 2 -- link, space diagram"``, ``"c -- image point, velocity diagram"``."""
    out: dict[str, tuple[str, str]] = {}
    for e in construction.entities():
        kind, noun = entity_kind(e)
        shown = getattr(e, "label", None) or e.name
        d = e.diagram
        role = _ROLE_WORDS.get(e.role, "")
        polygon = kind in ("vector", "trial-line") and d.kind in ("velocity", "acceleration", "force") and not d.name
        what = f"{role}{d.kind} {noun}" if polygon else f"{role}{noun}, {d.key} diagram"
        out[e.name] = (kind, f"{shown} -- {what}")
    return out


class Part(NamedTuple):
    """What a command draws: its ``owner`` (an entity's or a piece of furniture's name), the owner's
    ``kind`` and ``title``, and whether the command is the ``label`` naming the owner (a named tuple:
    every command of a sheet has one)."""

    owner: str
    kind: str
    title: str
    label: bool = False


def entity_of(command_name: str, names) -> str | None:
    """The entity a drawing command draws: its name is the entity's, or the entity's followed by ':'."""
    if command_name in names:
        return command_name
    head = command_name
    while ":" in head:
        head = head.rsplit(":", 1)[0]
        if head in names:
            return head
    return None


_LABEL_PARTS = frozenset((":label", ":label bg"))

#: The layout's own names: a pattern whose first group is the owner, the kind and the title (``{0}`` the
#: pattern's second group).
_FURNITURE = tuple((re.compile(p), k, t) for p, k, t in (
    (r"(frame)()", "frame", "Frame"),
    (r"(separator)()", "separator", "Separator"),
    (r"(title block)()(?: .*)?|title", "title-block", "Title block"),
    (r"(scale bar (.+?))(?: (?:number|segment|tick) \d+| outline| unit)", "scale-bar", "Scale bar: {0}"),
    (r"(results)()(?: .*)?", "table", "Results table"),
    (r"(heading (.+))", "heading", "Heading: {0}"),
    (r"(step (\d+) table)(?: .*)?", "table", "Table of construction step {0}"),
    (r"(step (\d+))(?: number)?", "step-text", "Construction step {0}"),
    (r"(note (\d+))(?: number)?", "note", "Note {0}"),
    (r"(given (\d+))(?: number)?", "given", "Given {0}"),
    (r"(equation (\d+))(?: marks .*)?", "equation", "Vector equation {0}"),
    (r"(equation legend)()", "equation", "Legend of the equation marks"),
))


def part_of(name: str, entities: Mapping[str, tuple[str, str]]) -> Part:
    """The part the command named ``name`` draws; ``entities`` is the sheet's entity name -> (kind,
    title) (:attr:`drafting.layout.sheet.Sheet.entities`).  A name neither an entity's nor the layout's
    is its own part of kind ``other``."""
    owner = entity_of(name, entities)
    if owner is not None:
        kind, title = entities[owner]
        return Part(owner, kind, title, name[len(owner):] in _LABEL_PARTS)
    return _furniture(name)


@functools.lru_cache(maxsize=4096)
def _furniture(name: str) -> Part:
    """The piece of furniture a command the layout names draws (remembered: every sheet has the same)."""
    for pattern, kind, title in _FURNITURE:
        m = pattern.fullmatch(name)
        if m is not None:
            return Part(m.group(1) or "title block", kind, title.format(m.group(2)))
    return Part(name, "other", name)


# ---- ids ---------------------------------------------------------------------------------------------

_NOT_ID = re.compile(r"[^A-Za-z0-9_.-]+")


def _id_char(c: str) -> str:
    if c.isascii():
        return c
    plain = "".join(k for k in unicodedata.normalize("NFKD", c) if k.isascii())
    if plain:
        return plain                                                   # ² -> 2, é -> e
    if unicodedata.category(c).startswith("L") and "GREEK" in unicodedata.name(c, ""):
        return "-" + unicodedata.name(c).split()[-1].lower() + "-"      # ω -> omega
    return f"-u{ord(c):04x}-"


@functools.lru_cache(maxsize=4096)
def xml_id(name: str) -> str:
    """``name`` as an XML id that CSS selects without escapes: ASCII letters, digits, ``_ . -``; spaces and
    other signs become ``-``, a prime ``-prime``, a letter with a mark or a superscript its plain form, a
    Greek letter its name, another character its code (``"image b'"`` -> ``image-b-prime``, ``"ω_2"`` ->
    ``omega-_2``, ``"⊥ BC"`` -> ``u22a5-BC``).  Never holds ``--`` (derived ids
    use it), starts with a letter or ``_``."""
    s = "".join(_id_char(c) for c in name.replace("'", "-prime-"))
    s = re.sub(r"-{2,}", "-", _NOT_ID.sub("-", s)).strip("-")
    return s if s[:1].isalpha() or s[:1] == "_" else f"e-{s}".rstrip("-")


class Ids:
    """The ids of one document's parts: unique, and the same on every run.  ``Ids(names)`` takes the
    entities' names first, in order, so an entity's id never depends on what else the document draws; a
    name whose :func:`xml_id` is taken gets ``--2``, ``--3`` ...  :meth:`claim` says whether an id is
    still to be written (a document writes each id once)."""

    def __init__(self, names=()) -> None:
        self._of: dict[str, str] = {}
        self._used: set[str] = set()
        self._written: set[str] = set()
        for n in names:
            self(n)

    def __call__(self, owner: str) -> str:
        got = self._of.get(owner)
        if got is None:
            base = got = xml_id(owner)
            k = 2
            while got in self._used:
                got, k = f"{base}--{k}", k + 1
            self._of[owner] = got
            self._used.add(got)
        return got

    def claim(self, ident: str) -> bool:
        """True the first time ``ident`` is claimed in this document, False after."""
        if ident in self._written:
            return False
        self._written.add(ident)
        return True


__all__ = ["ENTITY_KINDS", "Part", "Ids", "entity_kind", "entity_kinds", "entity_of", "part_of", "xml_id"]
