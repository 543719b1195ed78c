"""The linkage family's own sections of a scene file: the frame, the links and their points, sliders on
guides and slots, the input and the assembly branches, read into a :class:`LinkageScene`.  Called by the
scene reader (:mod:`drafting.scene.reader`) through the family registry with the public
:class:`~drafting.scene.reader.SceneReader`, whose helpers name the file and key in every error.  Whether
the mechanism can be built dyad by dyad is the family's first analysis (:func:`assembly_check`), not
the reader's."""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from constructions.errors import DegenerateInput
from constructions.forces.effects import Effects
from constructions.geometry import Vec
from constructions.mechanisms.assembly import assembly_plan
from constructions.mechanisms.model import Attached, Branch, Link, Mechanism, Slide

from ...scene.effect_keys import TABLES as EFFECT_TABLES
from ...scene.effects import SECTIONS as EFFECT_SECTIONS, read_effects
from ...scene.keys import Key, KeyTable
from ...scene.reader import Scene, SceneError, SceneReader
from ...scene.unitset import Units
from .input_position import INVERSE_KEYS, read_driving, read_inverse

if TYPE_CHECKING:
    from constructions.mechanisms.inverse_position import InversePosition
    from constructions.polygons.driving_slider import DrivenCrank


SECTIONS = frozenset({"frame", "link", "slider", "point", "input", "assembly"}) | EFFECT_SECTIONS

FRAME_KEYS = KeyTable("frame", "the fixed pivots, by name", (
    Key("<name>", "point", None, "a fixed pivot [x, y], e.g. O1 = [0, 0]"),
), named=True)
LINK_KEYS = KeyTable("link", "a rigid link between two joints", (
    Key("number", "whole number", None, "the link's number as in the notes (1: the input crank)", required=True),
    Key("joints", "list", None, "its two joints by name, e.g. [\"B\", \"C\"]", required=True),
    Key("length", "length", None, "the distance between them", required=True),
), array=True)
POINT_KEYS = KeyTable("point", "a point fixed to a link (its velocity and acceleration images)", (
    Key("name", "text", None, "the point's name", required=True),
    Key("link", "whole number", None, "the link it belongs to", required=True),
    Key("from", "text", None, "measured from this joint of the link ...", required=True),
    Key("distance", "length", None, "... this far ...", required=True),
    Key("angle", "angle", "0 deg", "... at this angle CCW from the link's line (from -> its other joint)"),
), array=True)
SLIDER_KEYS = KeyTable("slider", "a joint sliding along a fixed guide, or in the slot of a moving link", (
    Key("number", "whole number", None, "the block's link number (needed on a fixed guide; omit it for a pin "
                                        "in a slot)"),
    Key("joint", "text", None, "the joint that slides", required=True),
    Key("through", "point", None, "a fixed guide: a point it passes through"),
    Key("angle", "angle", "0 deg", "the guide's direction (a slot's: from its link's line)"),
    Key("on", "whole number", None, "a slot: the moving link it is cut in (a Scotch yoke: a link whose two "
                                    "joints ride in blocks on one fixed guide, so it only translates)"),
    Key("offset", "length", 0, "a slot: how far it passes to the right of its link's first joint"),
), array=True)
INPUT_KEYS = KeyTable("input", "the driving crank and its motion", (
    Key("link", "whole number", None, "the crank: joins a fixed pivot to a moving joint", required=True),
    Key("angle", "angle", None, "the crank angle, CCW from +x (exactly one of angle, slider_at, output_angle)"),
    Key("slider_at", "length", None, "or the inverse problem: a block's position along its fixed guide from the "
                                     "guide's through point, or along its slot from the slotted link's first "
                                     "joint (a cylinder's length); every crank angle that puts it there is found"),
    Key("slider", "whole number", None, "which block slider_at places (default: the one on a fixed guide, else "
                                        "the only block)"),
    Key("output_angle", "angle", None, "or the inverse problem: a link's direction from its fixed pivot to its "
                                       "other joint"),
    Key("output", "whole number", None, "which link output_angle sets (default: the one non-crank link on a "
                                        "fixed pivot)"),
    Key("solution", "whole number", 1, "which of the crank angles found is drawn, counted from 0 deg CCW"),
    Key("slider_speed", "velocity", None, "a driving slider (with slider_at): the block's speed along its guide "
                                          "or out along its slot, signed; in place of omega"),
    Key("slider_acceleration", "acceleration", 0, "a driving slider's acceleration, signed as slider_speed; in "
                                                  "place of alpha"),
    Key("omega", "angular velocity", None, "its angular velocity (signed, CCW +; 0: at rest); or tip_speed"),
    Key("tip_speed", "velocity", None, "or the speed of the crank tip, positive, with sense"),
    Key("sense", "text", None, "the sense of a positive omega or tip_speed", choices=("ccw", "cw")),
    Key("alpha", "angular acceleration", 0, "its angular acceleration (signed, CCW +)"),
    Key("torque", "torque", None, "or the torque on the crank (signed, CCW +): alpha follows from the masses"),
))
ASSEMBLY_KEYS = KeyTable("assembly", "which of the two crossings each constructed joint takes", (
    Key("<joint>", "text", None, "\"left of B->O2\" / \"right of B->O2\" (a four-bar), \"ahead of B\" / "
                                 "\"behind B\" (along a guide)"),
), named=True)
TABLES = (FRAME_KEYS, LINK_KEYS, POINT_KEYS, SLIDER_KEYS, INPUT_KEYS, ASSEMBLY_KEYS, *EFFECT_TABLES)
"""The linkage family's key tables (:mod:`drafting.scene.keys`), as the reference lists them."""


@dataclass(frozen=True)
class LinkageScene(Scene):
    """A linkage scene: the ``mechanism``, its input (``angle``, ``omega``, ``alpha`` or the ``torque`` it
    follows from) and the ``effects`` it declares (loads, masses, gravity, springs, friction; none unless
    the scene gives them)."""

    mechanism: Mechanism
    angle: float            # crank angle, rad CCW from +x
    omega: float            # crank angular velocity, rad/s CCW positive
    alpha: float            # crank angular acceleration, rad/s^2 CCW positive
    torque: float | None    # torque on the crank, N m CCW positive: alpha follows from it (not given)
    effects: Effects
    inverse: InversePosition | None = None   # [input] slider_at / output_angle: every crank angle found
    solution: int = 1       # which of them ``angle`` is (1 = the first from 0 deg CCW)
    driven: DrivenCrank | None = None        # [input] slider_speed: the crank's omega and alpha follow


def assembly_check(study):
    """The order the joints are built in (the family's check of the scene): a mechanism that cannot be
    built dyad by dyad, or whose branches are wrongly given, is a SceneError at [assembly] or [[link]]."""
    s = study.scene
    try:
        return assembly_plan(s.mechanism)
    except DegenerateInput as e:
        text = str(e)
        raise SceneError(s.path, "assembly" if "branch" in text or "assemblies" in text else "link", text) from None


def read_linkage(r: SceneReader, units: Units) -> dict:
    """The linkage sections of a scene: [frame], [[link]], [[point]], [[slider]], [input], [assembly], and
    the effects it declares ([gravity], [[load]], [[couple]], [[mass]], [[spring]], [[friction]]:
    :mod:`drafting.scene.effects`), whose centres of gravity may add points to the mechanism."""
    frame = r.named_table("frame")
    if not frame:
        raise r.fail("frame", "is missing: name the fixed pivots, e.g. O1 = [0, 0]")
    ground = {r.name(f"frame.{n}", n): r.point(f"frame.{n}", p, units) for n, p in frame.items()}

    links: list[Link] = []
    for i, t in enumerate(r.array("link"), 1):
        k = f"link[{i}]"
        r.table(k, LINK_KEYS, value=t)
        n = r.number(f"{k}.number", t["number"])
        joints = t["joints"]
        if not (isinstance(joints, list) and len(joints) == 2):
            raise r.fail(f"{k}.joints", "must name the two joints of the link, e.g. [\"B\", \"C\"]")
        a, b = (r.name(f"{k}.joints", j) for j in joints)
        if a == b:
            raise r.fail(f"{k}.joints", f"a link needs two different joints, not {a} twice")
        length = r.quantity(f"{k}.length", t["length"], "length", units)
        if length <= 0:
            raise r.fail(f"{k}.length", "must be positive")
        if any(x.number == n for x in links):
            raise r.fail(f"{k}.number", f"link {n} is defined twice")
        links.append(Link(n, (a, b), length))
    if not links:
        raise r.fail("link", "is missing: a mechanism needs [[link]] tables")
    joints = {j for x in links for j in x.joints}

    attached: list[Attached] = []
    for i, t in enumerate(r.array("point"), 1):
        k = f"point[{i}]"
        r.table(k, POINT_KEYS, value=t)
        nm = r.name(f"{k}.name", t["name"])
        if nm in ground:
            raise r.fail(f"{k}.name", f"{nm} is a fixed pivot")
        if any(a.name == nm for a in attached):
            raise r.fail(f"{k}.name", f"point {nm} is defined twice")
        ln = r.number(f"{k}.link", t["link"])
        link = next((x for x in links if x.number == ln), None)
        if link is None:
            raise r.fail(f"{k}.link", f"there is no link {ln}")
        if nm in link.joints:
            raise r.fail(f"{k}.name", f"{nm} is already a joint of link {ln} ({'-'.join(link.joints)})")
        base = r.name(f"{k}.from", t["from"])
        if base not in link.joints:
            raise r.fail(f"{k}.from", f"{base} is not a joint of link {ln} ({'-'.join(link.joints)})")
        dist = r.quantity(f"{k}.distance", t["distance"], "length", units)
        if dist <= 0:
            raise r.fail(f"{k}.distance", "must be positive")
        attached.append(Attached(nm, ln, base, dist, r.quantity(f"{k}.angle", t.get("angle", 0), "angle", units)))
    points = joints | {a.name for a in attached}

    slides: list[Slide] = []
    for i, t in enumerate(r.array("slider"), 1):
        k = f"slider[{i}]"
        r.table(k, SLIDER_KEYS, value=t)
        n = None
        if "number" in t:
            n = r.number(f"{k}.number", t["number"])
            if any(x.number == n for x in links) or any(s.number == n for s in slides):
                raise r.fail(f"{k}.number", f"link {n} is already used")
        j = r.name(f"{k}.joint", t["joint"])
        if j in ground:
            raise r.fail(f"{k}.joint", f"{j} is a fixed pivot and cannot slide")
        already = [s for s in slides if s.joint == j]
        if len(already) >= 2:
            raise r.fail(f"{k}.joint", f"joint {j} already slides along two lines; a joint takes at most two")
        if already and already[0].on is None and "on" not in t:
            raise r.fail(f"{k}.joint", f"joint {j} already slides on a fixed guide; a second line must be a "
                                        f"slot in a moving link (on = <link>)")
        angle = r.quantity(f"{k}.angle", t.get("angle", 0), "angle", units)
        if "on" in t:
            on = r.number(f"{k}.on", t["on"])
            slotted = next((x for x in links if x.number == on), None)
            if slotted is None:
                raise r.fail(f"{k}.on", f"there is no link {on} to cut the slot in")
            if j in slotted.joints or any(a.name == j and a.link == on for a in attached):
                raise r.fail(f"{k}.on", f"{j} is a point of link {on}, so it cannot slide in its slot")
            if "through" in t:
                raise r.fail(f"{k}.through", "a slot moves with its link: give offset (and angle), "
                                                "not a fixed point")
            offset = r.quantity(f"{k}.offset", t.get("offset", 0), "length", units)
            slides.append(Slide(n, j, Vec(0.0, 0.0), angle, on, offset))
        else:
            if "through" not in t:
                raise r.fail(f"{k}.through", "is missing: a fixed guide needs a point it passes through "
                                                "(or give on = <link> for a slot in a moving link)")
            if "offset" in t:
                raise r.fail(f"{k}.offset", "applies to a slot in a link (on = <link>)")
            if n is None:
                raise r.fail(f"{k}.number", "a block on a fixed guide needs its link number")
            slides.append(Slide(n, j, r.point(f"{k}.through", t["through"], units), angle))
    for i, sl in enumerate(slides, 1):           # a joint on no link is carried by two blocks (PRP)
        if sl.joint not in points and sum(x.joint == sl.joint for x in slides) < 2:
            raise r.fail(f"slider[{i}].joint", f"joint {sl.joint} is on no link (a joint only blocks carry "
                                               f"needs two of them)")
        if sl.joint not in points and sl.number is None:
            raise r.fail(f"slider[{i}].number", f"joint {sl.joint} is on no link, so it needs a block (a number)")

    inp = r.table("input", INPUT_KEYS)
    crank_no = r.number("input.link", inp["link"])
    crank = next((x for x in links if x.number == crank_no), None)
    if crank is None:
        raise r.fail("input.link", f"there is no link {crank_no}")
    if sum(j in ground for j in crank.joints) != 1:
        raise r.fail("input.link", f"link {crank_no} must join one fixed pivot in [frame] to a moving joint")
    if sum(k in inp for k in ("angle", "slider_at", "output_angle")) != 1:
        raise r.fail("input", "give exactly one of angle (the crank angle), slider_at (the block's position "
                              "along its guide) or output_angle (a link's angle): the crank angles follow from "
                              "either of the last two")
    angle = r.quantity("input.angle", inp["angle"], "angle", units) if "angle" in inp else 0.0
    driving = "slider_speed" in inp
    if driving:
        extra = sorted({"omega", "tip_speed", "sense", "alpha", "torque"} & set(inp))
        if extra:
            raise r.fail(f"input.{extra[0]}", "a driving slider sets the crank's motion: give slider_speed and "
                                              "slider_acceleration, not the crank's")
        if "slider_at" not in inp:
            raise r.fail("input.slider_at", "is missing: a driving slider needs its stroke position too")
        omega = alpha = 0.0
        torque = None
    else:
        if "slider_acceleration" in inp:
            raise r.fail("input.slider_acceleration", "goes with slider_speed (a driving slider)")
        omega, alpha, torque = _crank_motion(r, units, inp, crank)

    assembly = r.named_table("assembly")
    branches = {r.name(f"assembly.{j}", j): _branch(r, f"assembly.{j}", v) for j, v in assembly.items()}
    for j in branches:
        if j not in points:
            raise r.fail(f"assembly.{j}", f"{j} is not a joint of the mechanism")
    m = Mechanism(ground, tuple(links), tuple(slides), tuple(attached), crank_no, branches)
    m, effects = read_effects(r, units, m)
    inverse, solution, driven = None, 1, None
    if "angle" not in inp:
        inverse, solution = read_inverse(r, units, m, inp)
        angle = inverse.solutions[solution - 1] if inverse is not None else angle
        if driving and inverse is not None:
            driven = read_driving(r, units, m, inp, inverse, angle)
            omega, alpha = driven.omega, driven.alpha
    else:
        extra = sorted(INVERSE_KEYS & set(inp))
        if extra:
            raise r.fail(f"input.{extra[0]}", "goes with slider_at or output_angle, not with a crank angle")
    if torque is not None and not effects.inertial:
        raise r.fail("input.torque", "a torque on the crank sets its angular acceleration only through "
                                     "masses: give the moving links a [[mass]], or give alpha instead")
    if torque is not None and effects.balance is not None:
        raise r.fail("input.torque", f"the load {effects.balance.load} is already found from a torque on the "
                                     f"crank; give the torque there or here, not both")
    return {"mechanism": m, "angle": angle, "omega": omega, "alpha": alpha, "torque": torque,
            "effects": effects, "inverse": inverse, "solution": solution, "driven": driven}


def _crank_motion(r: SceneReader, units: Units, inp: dict, crank: Link) -> tuple[float, float, float | None]:
    """(omega, alpha, torque) of the crank from [input]."""
    sense = inp.get("sense")
    if ("omega" in inp) == ("tip_speed" in inp):
        raise r.fail("input", "give exactly one of omega (e.g. \"10 rad/s\", \"120 rpm\"; 0 at rest) or "
                                 "tip_speed (e.g. \"500 mm/s\")")
    if "omega" in inp:
        omega = r.quantity("input.omega", inp["omega"], "angular velocity", units)
    else:
        speed = r.quantity("input.tip_speed", inp["tip_speed"], "velocity", units)
        if speed < 0:
            raise r.fail("input.tip_speed", "is a speed: give it positive and set sense = \"cw\" or \"ccw\"")
        omega = speed / crank.length
    if omega != 0:
        omega = r.signed("input.sense", "omega", omega, inp.get("omega"), sense)
    elif sense is not None:
        raise r.fail("input.sense", "a crank at rest (omega = 0) has no sense of rotation")
    if not math.isfinite(omega):
        raise r.fail("input", "omega or tip_speed must be a finite number")
    if "alpha" in inp and "torque" in inp:
        raise r.fail("input", "give alpha (the crank's angular acceleration) or torque (the torque on the "
                              "crank, from which alpha follows), not both")
    alpha = r.quantity("input.alpha", inp.get("alpha", 0), "angular acceleration", units)
    torque = r.quantity("input.torque", inp["torque"], "torque", units) if "torque" in inp else None
    return omega, alpha, torque


def _branch(r: SceneReader, key: str, value: Any) -> Branch:
    v = r.text(key, value)
    m = re.fullmatch(r"(left|right)\s+of\s+([A-Za-z][A-Za-z0-9]*)\s*->\s*([A-Za-z][A-Za-z0-9]*)", v)
    if m:
        return Branch(1 if m[1] == "left" else -1, (m[2], m[3]))
    m = re.fullmatch(r"(ahead of|behind)\s+([A-Za-z][A-Za-z0-9]*)", v)
    if m:
        return Branch(1 if m[1] == "ahead of" else -1, (m[2],))
    raise r.fail(key, f"{v!r} is not a branch; write e.g. \"left of B->O2\", \"right of B->O2\", "
                         f"\"ahead of B\" or \"behind B\"")
