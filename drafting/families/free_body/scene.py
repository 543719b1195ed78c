"""The free-body family's sections of a scene file: one rigid body, its loads and its supports.

    kind = "free body"
    [body]                 name (optional), points (a table of names), outline (optional: the points
                           drawn as its outline, in order; all of them by default)
    [frame]                fixed points the members hang from, by name
    [[load]]               name, at (a point of the body), force (a magnitude), angle (its direction)
    [[couple]]             name, torque, sense (optional: "ccw" or "cw"; else the sign of torque)
    [[member]]             name (its force on the body, e.g. "F_12"), at (its pin on the body), to (its
                           other end, a point of [frame]), label (optional: "member 1", "the cylinder")
    [[pin]]                name, at, label: a pin to the frame (a force of unknown direction)
    [[roller]]             name, at, normal (the direction it pushes the body), label
    [[guide]]              name, at, angle (the direction of the fixed slot), label

``[[load]]`` and ``[[couple]]`` are written as in a linkage scene (:mod:`drafting.scene.effects`), without
the link: a free-body scene has one body.  Read with the shared reader, so every error is one sentence
naming the file and the key; the supports are checked for static determinacy and proper constraint
(:func:`constructions.forces.rigid_body.check_supports`) before anything is drawn.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Any

from constructions.errors import ConstructionError, DegenerateInput
from constructions.forces.effects import Couple, Load
from constructions.forces.rigid_body import GUIDE, MEMBER, PIN, ROLLER, RigidBody, Support, check_supports
from constructions.geometry import Vec

from ...scene import limits
from ...scene.effects import claim_name, polar
from ...scene.keys import Key, KeyTable
from ...scene.reader import Scene, SceneReader
from ...scene.unitset import Units

SUPPORT_SECTIONS = (MEMBER, PIN, ROLLER, GUIDE)
SECTIONS = frozenset({"body", "frame", "load", "couple", *SUPPORT_SECTIONS})
"""The top-level sections of a free-body scene."""

_NAME = Key("name", "text", None, "the force's name, e.g. P, F_12 or F_c (each its own)", required=True)
_AT = Key("at", "text", None, "the point of the body it acts at", required=True)
_LABEL = Key("label", "text", None, "what the support is, in words (\"member 1\", \"the cylinder\")")
BODY_KEYS = KeyTable("body", "the one rigid body", (
    Key("name", "text", "body", "what the body is called on the sheet"),
    Key("points", "table", None, "the body's points by name: [body.points] O = [0, 0]", required=True),
    Key("outline", "list", None, "the points drawn as its outline, in order (default: all of them)"),
))
FRAME_KEYS = KeyTable("frame", "fixed points the members hang from, by name", (
    Key("<name>", "point", None, "a fixed point [x, y], e.g. A = [0, 120]"),
), named=True)
LOAD_KEYS = KeyTable("load", "a given force on a point of the body", (
    _NAME, _AT,
    Key("force", "force", None, "the magnitude", required=True),
    Key("angle", "angle", None, "its direction, CCW from +x", required=True),
), array=True)
COUPLE_KEYS = KeyTable("couple", "a given couple on the body", (
    _NAME,
    Key("torque", "torque", None, "signed, CCW positive; or positive with sense", required=True),
    Key("sense", "text", None, "the sense of a positive torque", choices=("ccw", "cw")),
), array=True)
SUPPORT_KEYS = {
    MEMBER: KeyTable(MEMBER, "a two-force member from a pin on the body to a fixed point: a force along it", (
        _NAME, _AT, Key("to", "text", None, "its other end, a point of [frame]", required=True), _LABEL), array=True),
    PIN: KeyTable(PIN, "a pin to the frame: a force of unknown direction", (_NAME, _AT, _LABEL), array=True),
    ROLLER: KeyTable(ROLLER, "a roller: a force along its normal", (
        _NAME, _AT, Key("normal", "angle", None, "the direction it pushes the body", required=True), _LABEL),
        array=True),
    GUIDE: KeyTable(GUIDE, "a block in a fixed slot: a force square to the slot", (
        _NAME, _AT, Key("angle", "angle", None, "the direction of the slot", required=True), _LABEL), array=True),
}
TABLES = (BODY_KEYS, FRAME_KEYS, LOAD_KEYS, COUPLE_KEYS, *SUPPORT_KEYS.values())
"""The free-body family's key tables (:mod:`drafting.scene.keys`), as the reference lists them."""
CONSTRUCTION_POINTS = ("K", "L", "I")
"""The points Culmann's method and three-force concurrency name on the space diagram."""
CONSTRUCTION_FORCES = ("R", "F_KL")
"""The forces the construction names (the resultant, the Culmann force)."""

_FORCE_NAME = re.compile(r"[A-Za-z][A-Za-z0-9]*(?:_[A-Za-z0-9]+)?")


@dataclass(frozen=True)
class FreeBodyScene(Scene):
    """A free-body scene: the rigid ``body`` with its points, loads, couples and supports."""

    body: RigidBody


def read_free_body(r: SceneReader, units: Units) -> dict:
    """The free-body sections of a scene -> ``{"body": RigidBody}``."""
    return {"body": _FreeBodyReader(r, units).read()}


class _FreeBodyReader:
    def __init__(self, r: SceneReader, units: Units) -> None:
        self.r, self.units = r, units
        self.names: dict[str, str] = {}          # force name -> the key that gave it

    def fail(self, key: str, problem: str):
        return self.r.fail(key, problem)

    def items(self, section: str, keys: KeyTable):
        for i, t in enumerate(self.r.array(section), 1):
            k = f"{section}[{i}]"
            self.r.table(k, keys, value=t)
            yield k, t

    def force_name(self, key: str, value: Any) -> str:
        v = self.r.text(key, value)
        if not _FORCE_NAME.fullmatch(v):
            raise self.fail(key, f"{self.r.shown(v)} is not a force name (a letter, letters or digits, and an "
                                 f"optional subscript after _, e.g. P, F_12 or F_c)")
        if v in CONSTRUCTION_FORCES:
            raise self.fail(key, f"{v} names a force of the construction (R the resultant, F_KL the Culmann "
                                 f"force); call it something else")
        return claim_name(self.names, key, v, self.fail, "every load, couple and support needs a name of its own")

    def label(self, key: str, t: dict) -> str:
        return self.r.text(key, t["label"]) if "label" in t else ""

    def point_name(self, key: str, value: Any) -> str:
        n = self.r.name(key, value)
        if n in CONSTRUCTION_POINTS:
            raise self.fail(key, f"{n} names a point of the construction (K and L in Culmann's method, I in "
                                 f"three-force concurrency); call it something else")
        return n

    def body_point(self, key: str, value: Any) -> str:
        p = self.r.name(key, value)
        if p not in self.points:
            raise self.fail(key, f"{p} is not a point of the {self.body}; its points are {', '.join(self.points)}")
        return p

    # -- sections ----------------------------------------------------------------------------------------
    def read(self) -> RigidBody:
        r, units = self.r, self.units
        if "body" not in r.data:
            raise self.fail("body", "is missing: give the body's points, e.g. [body.points] O = [0, 0]")
        t = r.table("body", BODY_KEYS)
        self.body = r.text("body.name", t["name"]) if "name" in t else "body"
        raw = t["points"]
        if not isinstance(raw, dict) or not raw:
            raise self.fail("body.points", "must be a table of the body's points, e.g. O = [0, 0]")
        cap = limits.MAX_COUNTS["point"]
        if len(raw) > cap:
            raise self.fail("body.points", f"{len(raw)} points; a body may have at most {cap}")
        self.points = {self.point_name(f"body.points.{n}", n): r.point(f"body.points.{n}", p, units)
                       for n, p in raw.items()}
        outline = ()
        if "outline" in t:
            o = t["outline"]
            if not isinstance(o, list) or len(o) < 2:
                raise self.fail("body.outline", "must list the points drawn as the body's outline, e.g. "
                                                "[\"O\", \"E\", \"D\", \"Q\"]")
            outline = tuple(self.body_point("body.outline", n) for n in o)
        frame = r.named_table("frame")
        fixed: dict[str, Vec] = {}
        for n, p in frame.items():
            key = f"frame.{n}"
            name = self.point_name(key, n)
            if name in self.points:
                raise self.fail(key, f"{name} is already a point of the {self.body}; a fixed point needs a name "
                                     f"of its own")
            fixed[name] = r.point(key, p, units)
        self.fixed = fixed
        loads = tuple(self.loads())
        couples = tuple(self.couples())
        supports, keys = self.supports()
        body = RigidBody(self.body, self.points, supports, loads, couples, fixed, outline)
        try:
            body.size
        except DegenerateInput:
            raise self.fail("body.points", f"the points of the {self.body} and [frame] all coincide; a body "
                                           f"needs points apart") from None
        try:
            check_supports(body, units.format)
        except ConstructionError as e:
            key = keys[-1].split("[")[0] if keys else "member"
            raise self.fail(key, e.reason) from None
        return body

    def loads(self):
        for k, t in self.items("load", LOAD_KEYS):
            name = self.force_name(f"{k}.name", t["name"])
            at = self.body_point(f"{k}.at", t["at"])
            force = self.r.quantity(f"{k}.force", t["force"], "force", self.units)
            if force < 0:
                raise self.fail(f"{k}.force", "is the magnitude: give it positive and turn angle by 180 deg")
            angle = self.r.quantity(f"{k}.angle", t["angle"], "angle", self.units)
            yield Load(name, 0, at, polar(force, angle))

    def couples(self):
        for k, t in self.items("couple", COUPLE_KEYS):
            name = self.force_name(f"{k}.name", t["name"])
            torque = self.r.quantity(f"{k}.torque", t["torque"], "torque", self.units)
            torque = self.r.signed(f"{k}.sense", "torque", torque, t["torque"], t.get("sense"))
            yield Couple(name, 0, torque)

    def supports(self) -> tuple[tuple[Support, ...], list[str]]:
        out: list[Support] = []
        keys: list[str] = []
        for kind in SUPPORT_SECTIONS:
            for k, t in self.items(kind, SUPPORT_KEYS[kind]):
                name = self.force_name(f"{k}.name", t["name"])
                at = self.body_point(f"{k}.at", t["at"])
                label = self.label(f"{k}.label", t)
                if kind == MEMBER:
                    end = self.r.name(f"{k}.to", t["to"])
                    if end not in self.fixed:
                        known = ", ".join(self.fixed) or "none"
                        raise self.fail(f"{k}.to", f"{end} is not a point of [frame] (its points: {known}); a "
                                                   f"member runs from its pin on the {self.body} to a fixed point")
                    if self.fixed[end] == self.points[at]:
                        raise self.fail(f"{k}.to", f"{end} stands on the member's pin {at}; a member needs two "
                                                   f"ends apart")
                    out.append(Support(name, MEMBER, at, end=end, label=label))
                elif kind == PIN:
                    out.append(Support(name, PIN, at, label=label))
                else:
                    key = "normal" if kind == ROLLER else "angle"
                    angle = self.r.quantity(f"{k}.{key}", t[key], "angle", self.units)
                    direction = polar(1.0, angle)
                    out.append(Support(name, kind, at, direction=direction if kind == ROLLER else direction.perp(),
                                       label=label))
                keys.append(k)
        if not out:
            raise self.fail("member", "is missing: hold the body with [[member]], [[pin]], [[roller]] or "
                                      "[[guide]] supports (three unknowns in all)")
        return tuple(out), keys


__all__ = ["SECTIONS", "TABLES", "read_free_body"]
