"""A scene family that lives outside drafting/ (the tests' plug-in): a rod, its length doubled and checked.
It is found the way an installed family is, through the "drafting.families" entry points (tests/test_families.py
writes the distribution's metadata); nothing in drafting/ names it."""

from __future__ import annotations

from dataclasses import dataclass

from constructions.geometry import Vec
from constructions.quantities import Measured
from constructions.entities import Diagram, Note, Role, Segment
from constructions.record import Construction, Value
from drafting.families.registry import Analysis, Family
from drafting.scene.reader import Scene


@dataclass(frozen=True)
class RodScene(Scene):
    """A rod scene: the rod's ``length`` (m)."""

    length: float


def _read(r, units):
    t = r.table("rod", {"length"}, {"length"})
    length = r.quantity("rod.length", t["length"], "length", units)
    if length <= 0:
        raise r.fail("rod.length", "must be positive")
    return {"length": length}


def _drawing(study):
    length = study.scene.length
    rec = Construction("Rod").then("Draw the rod, $l long.",
                                   Segment("rod", Role.GIVEN, Diagram.SPACE, Vec(0, 0), Vec(length, 0)),
                                   Note("note", Role.NOTE, Diagram.SPACE, Vec(length / 2, length / 10), "rod"),
                                   values={"l": Value("length", length)})
    return rec


def _doubled(study):
    return 2 * study.get("rod")


ROD = Family(
    kind="rod (test)",
    analyses={"rod": Analysis("rod", (), lambda study: study.scene.length),
              "doubled": Analysis("doubled", ("rod",), _doubled, label="doubled rod")},
    askable=("rod", "doubled"),
    measured=lambda study: ([Measured("L2", "length", study.get("doubled"))] if study.asked("doubled") else []),
    analytic=lambda study: {"L2": 2 * study.scene.length},
    construction=_drawing,
    json=lambda study: {"doubled_mm": study.scene.units.convert("length", study.get("doubled"))}
    if study.asked("doubled") else {},
    warnings=lambda study: (),
    model_name=lambda study: "twice the length",
    sections=frozenset({"rod"}),
    scene_type=RodScene,
    read=_read,
    default_analyses=("rod",),
)
