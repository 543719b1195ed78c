"""The gear families' sections of a scene file.

A pair in mesh (``kind = "gear pair"``: ``[teeth]``, ``[pair]``) and a gear train (``kind = "gear train"``:
``[teeth]``, ``[[gear]]``, ``[[mesh]]``, ``[train]``, ``[[case]]``); each section's keys, with their units,
defaults and meanings, are the key tables below (:data:`PAIR_TABLES`, :data:`TRAIN_TABLES`), from which
docs/scene-reference.md and ``drafting keys`` are generated.

Read with the public scene reader, so every error is one sentence naming the file and the key.  Reading
only reads: whether the pair meshes and each case of a train can be solved are the families' checks
(:func:`pair_check`, :func:`cases_check`), run first by the study.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

from constructions.errors import ConstructionError, DegenerateInput
from constructions.gears.generation import largest_tip_round
from constructions.gears.mesh import Pair, contact_geometry
from constructions.gears.planets import planet_refusal
from constructions.gears.tooth import INCH, SYSTEMS, Gear, ToothSystem
from constructions.gears.train_drawing import Case
from constructions.gears.trains import FRAME, Given, Train, TrainGear, TrainMesh, layout, solve_train

from ...scene.keys import Key, KeyTable
from ...scene.reader import Scene, SceneError, SceneReader
from ...scene.units import UnitError, to_si
from ...scene.unitset import Units

PAIR_SECTIONS = frozenset({"teeth", "pair"})
TRAIN_SECTIONS = frozenset({"teeth", "gear", "mesh", "train", "case"})
TEETH_KEYS = KeyTable("teeth", "the tooth system every gear of the scene is cut to", (
    Key("module", "length", None, "the module m (pitch diameter / teeth); give it or diametral_pitch"),
    Key("diametral_pitch", "number", None, "or the diametral pitch: teeth per inch of pitch diameter"),
    Key("pressure_angle", "angle", None, "the pressure angle, 5 to 40 deg (14.5, 20 and 25 are usual)",
        required=True),
    Key("system", "text", "full depth", "the tooth proportions (full depth: addendum 1, dedendum 1.25 modules; "
                                        "stub: 0.8 and 1)", choices=tuple(SYSTEMS)),
    Key("addendum", "number", None, "or the addendum constant, in modules"),
    Key("dedendum", "number", None, "and the dedendum constant, in modules"),
    Key("cutter_tip", "number", None, "the rack cutter's tip radius in modules (default c / (1 - sin phi), "
                                      "0.38 at 20 deg full depth): the fillet and undercut drawn"),
))
PAIR_KEYS = KeyTable("pair", "a pair in mesh: gear 1, the pinion, drives gear 2", (
    Key("pinion", "whole number", None, "the pinion's teeth (gear 1, the driver)", required=True),
    Key("gear", "whole number", None, "gear 2's teeth, or \"rack\"", required=True),
    Key("centre_distance", "length", None, "the centre distance (for a rack: O1 to the rack's pitch line); "
                                           "default: the standard one"),
    Key("internal", "true/false", False, "gear 2 is an internal gear, a ring about the pinion"),
    Key("speed", "angular velocity", None, "the pinion's speed (> 0): the pitch-line and sliding speeds"),
))
GEAR_KEYS = KeyTable("gear", "one gear of the train", (
    Key("name", "text", None, "the gear's name, e.g. \"2\"", required=True),
    Key("teeth", "whole number", None, "its number of teeth", required=True),
    Key("shaft", "text", None, "the member it turns with (default: its name; gears on one shaft make a "
                               "compound gear)"),
    Key("carrier", "text", "frame", "the arm holding its axis (a planet's carrier)"),
    Key("internal", "true/false", False, "an internal gear, a ring"),
), array=True)
MESH_KEYS = KeyTable("mesh", "two gears of the train in mesh", (
    Key("gears", "list", None, "the two gears, e.g. [\"1\", \"2\"]", required=True),
    Key("angle", "angle", None, "the direction from the first gear's centre to the pitch point (default 0, "
                                "90 deg in a planetary train)"),
), array=True)
TRAIN_KEYS = KeyTable("train", "the train as a whole", (
    Key("coaxial", "list", None, "pairs of shafts whose axes must coincide (a reverted train), e.g. "
                                 "[[\"1\", \"4\"]]"),
    Key("planets", "whole number", 1, "planets equally spaced round a simple planetary's carrier, 1 to 24"),
))
CASE_KEYS = KeyTable("case", "one way the train is driven (a planetary train's cases: which member is held)", (
    Key("name", "text", None, "the case's name, e.g. \"carrier held\""),
    Key("driven", "text", None, "the driven member (a shaft or the carrier)", required=True),
    Key("speed", "angular velocity", None, "its speed, signed CCW positive or with sense", required=True),
    Key("sense", "text", None, "the sense of a positive speed", choices=("ccw", "cw")),
    Key("held", "text", None, "the member held still (a planetary train needs one: carrier, sun or ring)"),
    Key("power", "power", None, "the power put in at the driven member (for torques and tooth loads)"),
    Key("output", "text", None, "the member the power is taken off (with power)"),
    Key("driven2", "text", None, "a differential: the second driven member (instead of held)"),
    Key("speed2", "angular velocity", None, "the second driven member's speed (with driven2)"),
    Key("sense2", "text", None, "the sense of a positive speed2", choices=("ccw", "cw")),
), array=True)
PAIR_TABLES = (TEETH_KEYS, PAIR_KEYS)
TRAIN_TABLES = (TEETH_KEYS, GEAR_KEYS, MESH_KEYS, TRAIN_KEYS, CASE_KEYS)
"""The gear families' key tables (:mod:`drafting.scene.keys`), as the reference lists them."""
MAX_TEETH = 10000
MAX_GEARS = 30


@dataclass(frozen=True)
class GearPairScene(Scene):
    """A gear pair scene: the ``pair`` in mesh (pinion, gear or rack, centre distance)."""

    pair: Pair
    speed: float | None = None        # the pinion's speed (rad/s, a magnitude): pitch-line speed and sliding


@dataclass(frozen=True)
class GearTrainScene(Scene):
    """A gear train scene: the ``train`` (gears, meshes, shafts) and the ``cases`` it is driven in."""

    train: Train
    cases: tuple[Case, ...]


def pair_check(study) -> None:
    """The gear pair's check: its contact geometry exists at its centre distance (SceneError if not)."""
    s = study.scene
    try:
        contact_geometry(s.pair)
    except ConstructionError as e:
        raise SceneError(s.path, "pair.centre_distance" if s.pair.centre_distance is not None else "pair",
                         e.reason) from None


def cases_check(study) -> None:
    """The gear train's check: each case can be solved, and a case's output turns (SceneError if not)."""
    s = study.scene
    for i, case in enumerate(s.cases, 1):
        try:
            sol = solve_train(s.train, case.givens, power=None)
        except ConstructionError as e:
            raise SceneError(s.path, f"case[{i}]", e.reason) from None
        w = case.givens[-1].speed
        if case.out is not None and abs(sol.speeds[case.out]) < 1e-12 * abs(w):
            raise SceneError(s.path, f"case[{i}].output", f"{case.out} stands still in this case: no power is "
                                                          f"taken off it")


def _teeth_count(r, key: str, value: Any, least: int = 3) -> int:
    if isinstance(value, bool) or not isinstance(value, int) or not (least <= value <= MAX_TEETH):
        raise r.fail(key, f"{r.shown(value)} must be a whole number of teeth from {least} to {MAX_TEETH}")
    return value


def read_teeth(r: SceneReader, units: Units) -> ToothSystem:
    if "teeth" not in r.data:
        raise r.fail("teeth", "is missing: give the module (or diametral pitch) and the pressure angle, e.g. "
                              "[teeth] module = \"5 mm\", pressure_angle = \"20 deg\"")
    t = r.table("teeth", TEETH_KEYS)
    if ("module" in t) == ("diametral_pitch" in t):
        raise r.fail("teeth.module", "give either module (SI, e.g. \"5 mm\") or diametral_pitch (teeth per inch), "
                                     "one of them")
    if "module" in t:
        m = r.quantity("teeth.module", t["module"], "length", units)
        if m <= 0:
            raise r.fail("teeth.module", "must be a positive length")
    else:
        p = t["diametral_pitch"]
        if isinstance(p, bool) or not isinstance(p, (int, float)) or not (0.01 <= p <= 1000):
            raise r.fail("teeth.diametral_pitch", f"{r.shown(p)} must be a number of teeth per inch of pitch "
                                                  f"diameter, from 0.01 to 1000")
        m = INCH / p
    phi = r.quantity("teeth.pressure_angle", t["pressure_angle"], "angle", units)
    if not (math.radians(5) <= phi <= math.radians(40)):
        raise r.fail("teeth.pressure_angle", "must lie between 5 and 40 deg (14.5, 20 and 25 deg are usual)")
    ka, kd = 1.0, 1.25
    if "system" in t:
        if t["system"] not in SYSTEMS:
            raise r.fail("teeth.system", f"{r.shown(t['system'])} must be \"full depth\" or \"stub\"")
        ka, kd = SYSTEMS[t["system"]]
    for key in ("addendum", "dedendum"):
        if key in t:
            v = t[key]
            if isinstance(v, bool) or not isinstance(v, (int, float)) or not (0.1 <= v <= 3.0):
                raise r.fail(f"teeth.{key}", f"{r.shown(v)} must be the {key} constant in modules, from 0.1 to 3 "
                                             f"(full depth: 1 and 1.25; stub: 0.8 and 1)")
    ka, kd = float(t.get("addendum", ka)), float(t.get("dedendum", kd))
    if ka > kd:
        raise r.fail("teeth.dedendum", f"{kd:g} is less than the addendum constant {ka:g}: the tip of one gear would "
                                       f"hit the root of the other (the clearance is their difference)")
    s = ToothSystem(m, phi, ka, kd)
    if "cutter_tip" in t:
        v = t["cutter_tip"]
        most = largest_tip_round(s) / m
        if isinstance(v, bool) or not isinstance(v, (int, float)) or not (0.0 <= v <= most + 1e-12):
            raise r.fail("teeth.cutter_tip", f"{r.shown(v)} must be the tip radius of the rack cutter in modules, from "
                                             f"0 to {most:.3g} (the most its tooth holds at this pressure angle and "
                                             f"dedendum: its two tip rounds meet, or its straight flank ends at the "
                                             f"pitch line; ISO 53 at 20 deg: 0.38)")
        s = ToothSystem(m, phi, ka, kd, float(v))
    return s


def read_gear_pair(r: SceneReader, units: Units) -> dict:
    s = read_teeth(r, units)
    if "pair" not in r.data:
        raise r.fail("pair", "is missing: give the teeth, e.g. [pair] pinion = 20, gear = 40 (or gear = \"rack\")")
    t = r.table("pair", PAIR_KEYS)
    internal = t.get("internal", False)
    if not isinstance(internal, bool):
        raise r.fail("pair.internal", "must be true (gear 2 is an internal gear, a ring) or false")
    n1 = _teeth_count(r, "pair.pinion", t["pinion"])
    g = t["gear"]
    if g == "rack":
        if internal:
            raise r.fail("pair.internal", "a rack is not an internal gear; give gear = its teeth")
        gear = None
    else:
        n2 = _teeth_count(r, "pair.gear", g)
        if n2 <= n1 and internal:
            raise r.fail("pair.gear", f"an internal gear needs more teeth than its {n1}-tooth pinion")
        if n2 < n1:
            raise r.fail("pair.gear", f"{n2} teeth is fewer than the pinion's {n1}: gear 1 is the pinion, the smaller "
                                      f"gear (swap them)")
        gear = Gear(n2, s)
    c = None
    if "centre_distance" in t:
        c = r.quantity("pair.centre_distance", t["centre_distance"], "length", units)
    pair = Pair(Gear(n1, s), gear, c, internal=internal)
    r.lengths.append(("pair", pair.size))
    w = None
    if "speed" in t:
        w = r.quantity("pair.speed", t["speed"], "angular velocity", units)
        if not w > 0:
            raise r.fail("pair.speed", "must be a positive speed of the pinion, e.g. \"1000 rpm\"")
    return {"pair": pair, "speed": w}


def read_gear_train(r: SceneReader, units: Units) -> dict:
    s = read_teeth(r, units)
    gears = []
    names: set[str] = set()
    items = r.array("gear")
    if len(items) < 2:
        raise r.fail("gear", "needs at least two [[gear]] tables (name, teeth)")
    if len(items) > MAX_GEARS:
        raise r.fail("gear", f"{len(items)} gears; a train may have at most {MAX_GEARS}")
    for i, t in enumerate(items, 1):
        k = f"gear[{i}]"
        r.table(k, GEAR_KEYS, value=t)
        name = _member(r, f"{k}.name", t["name"])
        if name in names:
            raise r.fail(f"{k}.name", f"{name} is already the name of a gear")
        names.add(name)
        teeth = _teeth_count(r, f"{k}.teeth", t["teeth"])
        shaft = _member(r, f"{k}.shaft", t.get("shaft", name))
        carrier = _member(r, f"{k}.carrier", t.get("carrier", FRAME))
        internal = t.get("internal", False)
        if not isinstance(internal, bool):
            raise r.fail(f"{k}.internal", "must be true or false")
        gears.append(TrainGear(name, teeth, shaft, carrier, internal))
    meshes = []
    meshed: dict[frozenset, str] = {}          # a pair of gears -> the [[mesh]] that joined them
    for i, t in enumerate(r.array("mesh"), 1):
        k = f"mesh[{i}]"
        r.table(k, MESH_KEYS, value=t)
        g = t["gears"]
        if not (isinstance(g, list) and len(g) == 2 and all(isinstance(x, str) for x in g)) or g[0] == g[1]:
            raise r.fail(f"{k}.gears", "must name two gears, e.g. [\"1\", \"2\"]")
        for x in g:
            if x not in names:
                raise r.fail(f"{k}.gears", f"{x} is not a gear of the train (its gears: {', '.join(sorted(names))})")
        pair = frozenset(g)
        if pair in meshed:
            raise r.fail(f"{k}.gears", f"gears {g[0]} and {g[1]} already mesh in {meshed[pair]}: a pair of gears "
                                       f"meshes once")
        meshed[pair] = k
        ang = r.quantity(f"{k}.angle", t["angle"], "angle", units) if "angle" in t else None
        meshes.append(TrainMesh(g[0], g[1], ang))
    if not meshes:
        raise r.fail("mesh", "is missing: say which gears mesh, e.g. [[mesh]] gears = [\"1\", \"2\"]")
    tr = r.table("train", TRAIN_KEYS)
    coaxial = []
    for pair in tr.get("coaxial", []):
        if not (isinstance(pair, list) and len(pair) == 2 and all(isinstance(x, str) for x in pair)):
            raise r.fail("train.coaxial", "must list pairs of shafts, e.g. [[\"1\", \"4\"]]")
        coaxial.append((pair[0], pair[1]))
    planets = tr.get("planets", 1)
    if isinstance(planets, bool) or not isinstance(planets, int) or not (1 <= planets <= 24):
        raise r.fail("train.planets", f"{r.shown(planets)} must be a whole number of planets from 1 to 24")
    try:
        train = Train(tuple(gears), tuple(meshes), s.module, s.pressure_angle, tuple(coaxial),
                      planets if any(g.carrier != FRAME for g in gears) else 1, s.addendum)
    except DegenerateInput as e:
        raise r.fail("mesh", str(e)) from None
    if planets > 1 and not train.planetary:
        raise r.fail("train.planets", "an ordinary train (no carrier) has no planets; give the planet gears a "
                                      "carrier, e.g. carrier = \"C\"")
    for a, b in coaxial:
        for x in (a, b):
            if x not in train.members:
                raise r.fail("train.coaxial", f"{x} is not a shaft of the train")
    try:
        layout(train)
    except ConstructionError as e:
        raise r.fail("train.coaxial" if "coaxial" in e.reason else "mesh", e.reason) from None
    why = planet_refusal(train)
    if why:
        raise r.fail("train.planets", why)
    cases = []
    items = r.array("case")
    if not items:
        raise r.fail("case", "is missing: say what drives the train, e.g. [[case]] driven = \"1\", speed = \"1000 rpm\"")
    for i, t in enumerate(items, 1):
        k = f"case[{i}]"
        r.table(k, CASE_KEYS, value=t)
        name = r.text(f"{k}.name", t["name"]) if "name" in t else (f"case {i}" if len(items) > 1 else "the train")
        driven = _known_member(r, f"{k}.driven", t["driven"], train)
        w = r.quantity(f"{k}.speed", t["speed"], "angular velocity", units)
        w = r.signed(f"{k}.sense", "speed", w, t["speed"], t.get("sense"))
        if w == 0:
            raise r.fail(f"{k}.speed", "must not be zero: the driven member turns")
        givens = []
        if "held" in t:
            held = _known_member(r, f"{k}.held", t["held"], train)
            if held == driven:
                raise r.fail(f"{k}.held", f"{held} is the driven member; hold another")
            givens.append(Given(held, 0.0))
        second = _second_driven(r, k, t, train, driven, units)
        if second is not None:
            givens.append(second)
        givens.append(Given(driven, w))
        if train.planetary and len(givens) < 2:
            raise r.fail(f"{k}.held", "is missing: a planetary train has two degrees of freedom; hold one member "
                                      "(the carrier, the sun or the ring), or drive a second one (driven2, speed2)")
        if not train.planetary and "held" in t:
            raise r.fail(f"{k}.held", "an ordinary train (no carrier) has one degree of freedom: give only the "
                                      "driven member")
        power = out = None
        if "power" in t and second is not None:
            raise r.fail(f"{k}.power", "with two members driven (a differential) this version gives speeds only; "
                                       "leave power out")
        if "power" in t:
            try:
                power = to_si(t["power"], "power", "kW")
            except UnitError as e:
                raise r.fail(f"{k}.power", str(e)) from None
            if power <= 0:
                raise r.fail(f"{k}.power", "must be positive (the power put in at the driven member)")
            if "output" not in t:
                raise r.fail(f"{k}.output", "is missing: name the member the power is taken off")
            out = _known_member(r, f"{k}.output", t["output"], train)
            if out in (driven, *(g.member for g in givens if g.speed == 0.0)):
                raise r.fail(f"{k}.output", f"{out} is the driven or the held member; take the power off another")
        elif "output" in t:
            raise r.fail(f"{k}.power", "is missing: an output without a power gives no torque")
        cases.append(Case(name, tuple(givens), power, driven if power else None, out))
    return {"train": train, "cases": tuple(cases)}


def _second_driven(r, k: str, t: dict, train: Train, driven: str, units: Units) -> Given | None:
    """The second driven member of a differential (``driven2``, ``speed2``, ``sense2``), or None."""
    if "driven2" not in t:
        for key in ("speed2", "sense2"):
            if key in t:
                raise r.fail(f"{k}.driven2", f"is missing: {key} belongs to a second driven member; name it")
        return None
    if not train.planetary:
        raise r.fail(f"{k}.driven2", "an ordinary train (no carrier) has one degree of freedom: one driven member")
    if "held" in t:
        raise r.fail(f"{k}.driven2", "a planetary train has two degrees of freedom: hold one member or drive a "
                                     "second one, not both")
    if "speed2" not in t:
        raise r.fail(f"{k}.speed2", "is missing: give the second driven member's speed, e.g. \"50 rpm\"")
    d2 = _known_member(r, f"{k}.driven2", t["driven2"], train)
    if d2 == driven:
        raise r.fail(f"{k}.driven2", f"{d2} is already the driven member; drive another")
    w2 = r.quantity(f"{k}.speed2", t["speed2"], "angular velocity", units)
    return Given(d2, r.signed(f"{k}.sense2", "speed2", w2, t["speed2"], t.get("sense2")))


def _member(r, key: str, value: Any) -> str:
    if not isinstance(value, str) or not value.strip() or len(value) > 20 or not value.replace("_", "").isalnum():
        raise r.fail(key, f"{r.shown(value)} must be a member name (letters and digits, e.g. \"2\" or \"C\")")
    return value


def _known_member(r, key: str, value: Any, train: Train) -> str:
    v = _member(r, key, value)
    if v not in train.members:
        raise r.fail(key, f"{v} is not a member of the train (its shafts and carrier: {', '.join(train.members)})")
    return v


__all__ = ["PAIR_SECTIONS", "PAIR_TABLES", "TRAIN_SECTIONS", "TRAIN_TABLES", "GearPairScene", "GearTrainScene", "cases_check", "pair_check",
           "read_gear_pair", "read_gear_train"]
