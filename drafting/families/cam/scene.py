"""The cam family's sections of a scene file: the cam, its follower and its motion program.

    kind = "cam"
    [cam]          base_radius, sense ("cw" or "ccw"), speed (optional: the cam's steady angular speed, for
                   v, a and j; without it the s-v-a-j diagrams are per radian), divisions (how many equal
                   portions of the turn the construction draws, 4..72; default 12) or step (e.g. "10 deg"),
                   limit_margin (optional: how near a limit a roller or a base radius is warned of, a
                   fraction; default 0.05)
    [follower]     type ("knife-edge", "roller", "flat-faced", "oscillating roller", "oscillating
                   flat-faced"), roller_radius or roller_diameter (a roller), offset (optional: the axis to the
                   right of the cam centre, negative to the left; translating knife-edge or roller only),
                   pivot_distance (an oscillating follower: its arm's pivot to the right of the cam centre; the
                   segments' lifts are then the arm's swing, an angle), arm_length (an oscillating roller),
                   face_offset (optional, an oscillating flat face: its distance from the line through the
                   pivot along the arm, towards the cam; default 0)
    [[segment]]    motion ("dwell", "rise", "return"), from, to (cam angles; the segments run on from 0 to
                   360 deg), lift (a rise or return), law ("simple harmonic", "cycloidal", "uniform",
                   "parabolic", "3-4-5 polynomial", "4-5-6-7 polynomial")

Read with the shared reader: every error is one sentence naming the file and the key.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from constructions.cams.laws import LAWS, DWELL, RETURN, RISE, SEGMENT_KINDS, Program, Segment, law_name
from constructions.cams.follower import FLAT, FOLLOWERS, KNIFE, OSC_FLAT, OSCILLATING, ROLLER, Follower
from constructions.cams.profile import check_face

from ...scene.keys import Key, KeyTable
from ...scene.reader import Scene, SceneReader
from ...scene.unitset import Units
from .limits import LIMIT_MARGIN

SECTIONS = frozenset({"cam", "follower", "segment"})
MAX_DIVISIONS = 72
CAM_KEYS = KeyTable("cam", "the cam: its base circle, sense of rotation and speed", (
    Key("base_radius", "length", None, "the radius of the base circle (the cam's smallest)", required=True),
    Key("sense", "text", "ccw", "the cam's sense of rotation", choices=("ccw", "cw")),
    Key("speed", "angular velocity", None, "the cam's steady speed, for v, a and j (without it the s-v-a-j "
                                           "diagrams are per radian)"),
    Key("divisions", "whole number", 12, f"how many equal portions of the turn the construction draws, 4 to "
                                         f"{MAX_DIVISIONS}"),
    Key("step", "angle", None, "or the angle of one portion, e.g. \"10 deg\" (not with divisions)"),
    Key("limit_margin", "number", LIMIT_MARGIN, "how near its limit a roller radius or a flat face's base "
                                                  "radius is warned of, a fraction (0: only at the limit), 0 to below 1"),
))
FOLLOWER_KEYS = KeyTable("follower", "the follower: its type, roller and where its axis or pivot lies", (
    Key("type", "text", None, "the follower", required=True, choices=FOLLOWERS),
    Key("roller_radius", "length", None, "the roller's radius (a roller follower needs it or roller_diameter)"),
    Key("roller_diameter", "length", None, "or the roller's diameter"),
    Key("offset", "length", 0, "the axis to the right of the cam centre, negative to the left (translating "
                               "knife-edge or roller)"),
    Key("pivot_distance", "length", None, "an oscillating follower: its arm's pivot to the right of the cam "
                                          "centre (then every lift is the arm's swing, an angle)"),
    Key("arm_length", "length", None, "an oscillating roller: the arm from its pivot to the roller's centre"),
    Key("face_offset", "length", 0, "an oscillating flat face: its distance from the line through the pivot "
                                    "along the arm, towards the cam"),
))
SEGMENT_KEYS = KeyTable("segment", "one part of the motion program; the segments run on from 0 to 360 deg", (
    Key("motion", "text", None, "what the follower does", required=True, choices=SEGMENT_KINDS),
    Key("from", "angle", None, "the cam angle it starts at (where the one before ended)", required=True),
    Key("to", "angle", None, "the cam angle it ends at", required=True),
    Key("lift", "length", None, "a rise's or return's lift (an angle for an oscillating follower)"),
    Key("law", "text", "simple harmonic", "a rise's or return's motion law (also shm, cycloid, 3-4-5, 4567 ...)",
        choices=tuple(LAWS)),
), array=True)
TABLES = (CAM_KEYS, FOLLOWER_KEYS, SEGMENT_KEYS)
"""The cam family's key tables (:mod:`drafting.scene.keys`), as the reference lists them."""


@dataclass(frozen=True)
class CamModel:
    """A cam scene's model: the program, the follower, the cam's speed (rad/s or None), the number of
    equal portions the construction draws and the margin within which a limit is warned of."""

    program: Program
    follower: Follower
    omega: float | None
    divisions: int
    limit_margin: float = LIMIT_MARGIN


@dataclass(frozen=True)
class CamScene(Scene):
    """A cam scene: its ``model`` (program, follower, speed, divisions)."""

    model: CamModel


def read_cam(r: SceneReader, units: Units) -> dict:
    if "cam" not in r.data:
        raise r.fail("cam", "is missing: give the cam's base_radius and sense, e.g. [cam] base_radius = \"50 mm\"")
    t = r.table("cam", CAM_KEYS)
    rb = r.quantity("cam.base_radius", t["base_radius"], "length", units)
    if rb <= 0:
        raise r.fail("cam.base_radius", "must be positive")
    sense = t.get("sense", "ccw")
    if sense not in ("ccw", "cw"):
        raise r.fail("cam.sense", f"{r.shown(sense)} must be \"ccw\" or \"cw\"")
    sg = 1 if sense == "ccw" else -1
    omega = None
    if "speed" in t:
        omega = abs(r.quantity("cam.speed", t["speed"], "angular velocity", units))
        if omega == 0:
            raise r.fail("cam.speed", "must be non-zero (leave it out for diagrams per radian)")
    if "divisions" in t and "step" in t:
        raise r.fail("cam.step", "give divisions or step, not both")
    divisions = 12
    if "divisions" in t:
        d = t["divisions"]
        if isinstance(d, bool) or not isinstance(d, int) or not 4 <= d <= MAX_DIVISIONS:
            raise r.fail("cam.divisions", f"must be a whole number from 4 to {MAX_DIVISIONS}")
        divisions = d
    elif "step" in t:
        st = r.quantity("cam.step", t["step"], "angle", units)
        n = 2 * math.pi / st if st > 0 else 0
        if not (st > 0 and abs(n - round(n)) < 1e-9 and 4 <= round(n) <= MAX_DIVISIONS):
            raise r.fail("cam.step", f"must divide 360 deg into 4 to {MAX_DIVISIONS} equal portions (e.g. \"10 deg\")")
        divisions = int(round(n))
    margin = t.get("limit_margin", LIMIT_MARGIN)
    if isinstance(margin, bool) or not isinstance(margin, (int, float)) or not 0 <= margin < 1:
        raise r.fail("cam.limit_margin", "must be a fraction from 0 (no warning before the limit) to below 1, "
                                         "e.g. 0.05 for 5 %")

    ft = r.table("follower", FOLLOWER_KEYS)
    kind = ft["type"]
    if kind not in FOLLOWERS:
        raise r.fail("follower.type", f"{r.shown(kind)} is not a follower; choose from {', '.join(FOLLOWERS)}")
    rr = 0.0
    osc = kind in (OSCILLATING, OSC_FLAT)          # the lift is the arm's swing
    needs = {"pivot_distance": osc, "arm_length": kind == OSCILLATING}
    for k, needed in needs.items():
        if needed and k not in ft:
            raise r.fail(f"follower.{k}", f"is missing: an {kind} follower needs its "
                                          f"{'pivot distance and arm length' if kind == OSCILLATING else 'pivot distance'}")
        if not needed and k in ft:
            raise r.fail(f"follower.{k}", "only an oscillating roller has an arm length (an oscillating flat face runs "
                                          "along its arm)" if k == "arm_length" and osc else
                                          "only an oscillating follower has a pivot and an arm")
    if "face_offset" in ft and kind != OSC_FLAT:
        raise r.fail("follower.face_offset", "only an oscillating flat-faced follower has a face offset")
    pivot = r.quantity("follower.pivot_distance", ft["pivot_distance"], "length", units) if osc else 0.0
    arm = r.quantity("follower.arm_length", ft["arm_length"], "length", units) if kind == OSCILLATING else 0.0
    face = r.quantity("follower.face_offset", ft["face_offset"], "length", units) if "face_offset" in ft else 0.0
    if kind in (ROLLER, OSCILLATING):
        if "roller_radius" in ft and "roller_diameter" in ft:
            raise r.fail("follower.roller_diameter", "give roller_radius or roller_diameter, not both")
        if "roller_radius" in ft:
            rr = r.quantity("follower.roller_radius", ft["roller_radius"], "length", units)
        elif "roller_diameter" in ft:
            rr = r.quantity("follower.roller_diameter", ft["roller_diameter"], "length", units) / 2
        else:
            raise r.fail("follower.roller_radius", "is missing: a roller follower needs its roller's radius")
        if rr <= 0:
            raise r.fail("follower.roller_radius", "must be positive")
    else:
        for k in ("roller_radius", "roller_diameter"):
            if k in ft:
                raise r.fail(f"follower.{k}", f"a {kind} follower has no roller")
    e = 0.0
    if "offset" in ft:
        if osc:
            raise r.fail("follower.offset", "an oscillating follower has no offset; its pivot places it")
        if kind == FLAT:
            raise r.fail("follower.offset", "a flat face square to its axis draws the same profile at any offset; "
                                            "leave it out")
        e = r.quantity("follower.offset", ft["offset"], "length", units)
        if abs(e) >= rb + rr:
            raise r.fail("follower.offset", "must be smaller than the prime circle's radius (base + roller)")

    segments = []
    at = 0.0
    items = r.array("segment")
    if not items:
        raise r.fail("segment", "is missing: give the motion program as [[segment]] tables from 0 to 360 deg")
    for i, st in enumerate(items, 1):
        k = f"segment[{i}]"
        r.table(k, SEGMENT_KEYS, value=st)
        motion = st["motion"]
        if motion not in SEGMENT_KINDS:
            raise r.fail(f"{k}.motion", f"{r.shown(motion)} must be dwell, rise or return")
        a = r.quantity(f"{k}.from", st["from"], "angle", units)
        b = r.quantity(f"{k}.to", st["to"], "angle", units)
        if abs(a - at) > 1e-9:
            raise r.fail(f"{k}.from", f"is {math.degrees(a):.6g} deg but the program has reached "
                                      f"{math.degrees(at):.6g} deg; the segments must run on without a gap")
        if not b > a:
            raise r.fail(f"{k}.to", "must come after from")
        if motion == DWELL:
            for key in ("lift", "law"):
                if key in st:
                    raise r.fail(f"{k}.{key}", "a dwell has no lift or law (it stays at the level reached)")
            segments.append(Segment(DWELL, b - a))
        else:
            if "lift" not in st:
                raise r.fail(f"{k}.lift", "is missing")
            h = r.quantity(f"{k}.lift", st["lift"], "angle" if osc else "length", units)
            if h <= 0:
                raise r.fail(f"{k}.lift", "must be positive (a return lowers the follower by its lift)")
            try:
                law = law_name(st.get("law", "simple harmonic"))
            except ValueError as err:
                raise r.fail(f"{k}.law", str(err)) from None
            segments.append(Segment(RISE if motion == RISE else RETURN, b - a, h, law))
        at = b
    if abs(at - 2 * math.pi) > 1e-9:
        raise r.fail(f"segment[{len(items)}].to", f"the program ends at {math.degrees(at):.6g} deg; it must end at "
                                                  f"360 deg")
    try:
        program = Program(segments)
    except ValueError as err:
        raise r.fail("segment", str(err)) from None
    if kind == OSCILLATING:
        if not (pivot > 0 and arm > 0):
            raise r.fail("follower.arm_length", "the pivot distance and the arm must be positive")
        if not abs(pivot - arm) < rb + rr < pivot + arm:
            raise r.fail("follower.arm_length", "the arm cannot reach the prime circle from its pivot: base + roller "
                                                "must lie between |pivot_distance - arm_length| and their sum")
    if kind == OSC_FLAT:
        if not pivot > 0:
            raise r.fail("follower.pivot_distance", "must be positive")
        if not -pivot < rb + face < pivot:
            raise r.fail("follower.face_offset" if face else "follower.pivot_distance",
                         "the face cannot touch the base circle: base_radius + face_offset must lie within "
                         "the pivot distance of zero")
    follower = Follower(kind, rb, rr, e, sg, pivot, arm, face)
    if kind == OSC_FLAT:
        try:
            check_face(program, follower)
        except ValueError as err:
            raise r.fail("follower.pivot_distance", str(err)) from None
    return {"model": CamModel(program, follower, omega, divisions, float(margin))}


__all__ = ["SECTIONS", "TABLES", "read_cam", "CamModel", "KNIFE"]
