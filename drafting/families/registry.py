"""Scene families and the registry of their analyses.

A family (linkage today; cam, gear pair, gear train next) is one kind of scene: it reads its own
sections of a scene file, names the analyses a scene of its kind may ask for with their dependencies,
and says what goes on its sheets.  The study (:mod:`drafting.study.study`) resolves the analyses a scene asks
for as a dependency chain through this registry, lazily, and records what ran; the CLI and the JSON
output go through it too, never through one analysis by name.  Adding a family means registering one
:class:`Family` from its own module; nothing here or in another family changes.
"""

from __future__ import annotations

import importlib
from dataclasses import dataclass, field
from typing import Any, Callable, Mapping


@dataclass(frozen=True)
class Analysis:
    """One analysis of a family: its ``name`` (what a scene asks for, e.g. "acceleration"), the
    analyses it needs first, and ``run(study)`` computing its result from the study (which hands out
    the results of ``requires``).  ``label`` is what ``ran`` records ("velocity polygon")."""

    name: str
    requires: tuple[str, ...]
    run: Callable[[Any], Any]
    label: str = ""


@dataclass(frozen=True)
class Family:
    """A kind of scene.

    ``analyses`` are every analysis the family knows (also internal ones a scene cannot ask for by
    name, such as the analytic check); ``askable`` are those a scene may name under [ask].
    ``measured(study)`` lists the measured quantities, ``analytic(study)`` their analytic values by name
    (or None), ``construction(study)`` the record to draw, ``json(study)`` the family's own JSON fields,
    ``warnings(study)`` what the reader must know.  ``sections`` and ``read`` are the family's part of
    the scene file.
    """

    kind: str
    analyses: Mapping[str, Analysis]
    askable: tuple[str, ...]
    measured: Callable[[Any], list]
    analytic: Callable[[Any], Mapping[str, Any] | None]
    construction: Callable[[Any], Any]
    json: Callable[[Any], dict]
    warnings: Callable[[Any], tuple[str, ...]]
    model_name: Callable[[Any], str | None] = field(default=lambda study: None)
    scales: Callable[[Any], dict] = field(default=lambda study: {})
    scene_type: type = object
    """The family's scene: a subclass of :class:`drafting.scene.reader.Scene` (the shared header) whose own
    fields are the family's typed state."""
    sections: frozenset[str] = frozenset()
    """The top-level sections of a scene file this family reads (besides kind, drawing, units, ask)."""
    keys: tuple = ()
    """The key tables of its sections (:class:`drafting.scene.keys.KeyTable`), which its reader checks keys
    against: the reference (``drafting keys KIND``, docs/scene-reference.md) is generated from them."""
    read: Callable[[Any, Any], dict] = field(default=lambda reader, units: {})
    """``read(reader, units)`` reads the family's sections with the public scene reader
    (:class:`drafting.scene.reader.SceneReader`, whose errors name the file and key) and returns the fields
    of its ``scene_type`` beyond the header.  Reading only reads: what needs solving is an analysis."""
    checks: tuple[str, ...] = ()
    """Analyses that finish checking a scene (a linkage's assembly plan, a train's cases): every run does
    them first, and a scene they find wrong is a SceneError naming the key, as the reader's are."""
    vary: Callable[[dict, Any, Any], tuple] | None = None
    """``vary(data, path, units)``: the ranges of the scene's ``[vary]`` (:mod:`drafting.scene.vary`); None
    for a family that cannot vary (a scene of it with ``[vary]`` is told so)."""
    given: Callable[[Any], list[str]] = field(default=lambda study: [])
    """What a lab's problem sheet states in words (a linkage's links, pivots, input, loads)."""
    dimensioned_problem: bool = False
    """A problem sheet dimensions the space diagram unless the scene says ``dimensions = false``."""
    sweeps: str | None = None
    """The analysis that sweeps the input over a caller's grid (``study.options["crank angles"]``, with a
    ``"progress"`` callback): what ``drafting sweep`` runs; None for a family that cannot sweep."""
    cannot_sweep: Callable[[Any], str | None] = field(default=lambda scene: None)
    """Why a scene of a family that sweeps cannot be swept ("key: sentence"), or None."""
    notes: Callable[[Any], tuple[str, ...]] = field(default=lambda study: ())
    """What the sheet and the results say about the scene besides its warnings (a linkage's class)."""
    default_analyses: tuple[str, ...] = ()
    planned: tuple[str, ...] = ()
    """Analyses announced for this family but not built yet (a scene asking for one is told so)."""


FAMILIES: dict[str, Family] = {}


def register(family: Family) -> Family:
    """Add a family (a module does this once, on import); a kind can be registered only once."""
    if family.kind in FAMILIES:
        raise ValueError(f"a scene family {family.kind!r} is already registered")
    for a in family.analyses.values():
        for r in a.requires:
            if r not in family.analyses:
                raise ValueError(f"{family.kind}: analysis {a.name!r} needs {r!r}, which is not registered")
    FAMILIES[family.kind] = family
    return family


GROUP = "drafting.families"
"""The entry-point group a family is found under: each entry names a :class:`Family` object, e.g.
``linkage = "drafting.families.linkage.family:LINKAGE"`` in pyproject.toml.  A new family is a package that
declares one; nothing in drafting/ changes."""


BUILT_IN = {"linkage": "drafting.families.linkage.family:LINKAGE",
            "free body": "drafting.families.free_body.family:FREE_BODY",
            "gear pair": "drafting.families.gear.family:GEAR_PAIR",
            "gear train": "drafting.families.gear.family:GEAR_TRAIN",
            "cam": "drafting.families.cam.family:CAM"}
"""The families this package ships, by kind: the objects its entry points in pyproject.toml name (a test
holds the two alike).  A scene of one of these kinds loads its family without reading the installed
distributions' entry points (importlib.metadata and its scan of every distribution: some 20 ms of a
cold ``drafting render``).  Every other kind is found through :data:`GROUP`."""


def discover() -> None:
    """Register every family the installed distributions declare under :data:`GROUP` that is not
    registered yet (a kind registered by hand, as a test does, is left as it is)."""
    from importlib.metadata import entry_points
    for ep in entry_points(group=GROUP):
        found = ep.load()
        if found.kind not in FAMILIES:
            register(found)


_discovered = False


def families() -> dict[str, Family]:
    """Every registered family by kind, the installed ones found on first use."""
    global _discovered
    if not _discovered:
        _discovered = True
        discover()
    return FAMILIES


def _discover_named(kind: str) -> None:
    """Register the families of the entry points named ``kind`` (as this package names its own): a scene
    of one kind loads that family's modules only, not every installed family's."""
    from importlib.metadata import entry_points
    for ep in entry_points(group=GROUP, name=kind):
        found = ep.load()
        if found.kind not in FAMILIES:
            register(found)


def family(kind: str) -> Family:
    """The family of ``kind``: one of this package's own from :data:`BUILT_IN`; else the entry point of
    that name first, then (a family declared under another name) every entry point; a kind not known yet
    has the entry points looked at again (a family installed since), then KeyError."""
    if kind not in FAMILIES and kind in BUILT_IN:
        module, _, name = BUILT_IN[kind].partition(":")
        found = getattr(importlib.import_module(module), name)
        if found.kind not in FAMILIES:
            register(found)
    if kind not in FAMILIES:
        _discover_named(kind)
    if kind not in FAMILIES and kind not in families():
        discover()
    try:
        return FAMILIES[kind]
    except KeyError:
        raise KeyError(f"no scene family {kind!r}; known: {', '.join(sorted(FAMILIES))}") from None
