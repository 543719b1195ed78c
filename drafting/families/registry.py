"""Scene families and the registry of their analyses.

A family (linkage today; cam, gear pair, gear train next) is one kind of scene: it reads its own
sections of a scene file, names the analyses a scene of its kind may ask for with their dependencies,
and says what goes on its sheets.  The study (:mod:`drafting.study.study`) resolves the analyses a scene asks
for as a dependency chain through this registry, lazily, and records what ran; the CLI and the JSON
output go through it too, never through one analysis by name.  Adding a family means registering one
:class:`Family` from its own module; nothing here or in another family changes.
"""

from __future__ import annotations

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
    sections: frozenset[str] = frozenset()
    """The top-level sections of a scene file this family reads (besides kind, drawing, units, ask)."""
    read: Callable[[Any, Any], dict] = field(default=lambda reader, units: {})
    """``read(reader, units)`` reads the family's sections with the shared reader (whose errors name the
    file and key) and returns the Scene fields of its state (``mechanism``/``angle``/... or ``model``)."""
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


BUILTIN = (
    "drafting.families.linkage.family",
    "drafting.families.free_body.family",
    "drafting.families.gear.family",
    "drafting.families.cam.family",
)
"""The modules of the families this package ships; each registers its family when imported.  Named, not
imported here, so this registry depends on no family (a family depends on it)."""


def builtin_families() -> None:
    """Register the families this package ships (idempotent: a module registers once, on import)."""
    import importlib
    for name in BUILTIN:
        importlib.import_module(name)


def family(kind: str) -> Family:
    builtin_families()
    try:
        return FAMILIES[kind]
    except KeyError:
        raise KeyError(f"no scene family {kind!r}; known: {', '.join(sorted(FAMILIES))}") from None
