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
from typing import Any

from constructions.errors import DegenerateInput
from constructions.forces.effects import Effects
from constructions.geometry import Vec
from constructions.mechanisms.assembly import assembly_plan
from constructions.mechanisms.model import Attached, Branch, Link, Mechanism, Slide

from ...scene.effects import SECTIONS as EFFECT_SECTIONS, read_effects
from ...scene.reader import Scene, SceneError, SceneReader
from ...scene.unitset import Units


SECTIONS = frozenset({"frame", "link", "slider", "point", "input", "assembly"}) | EFFECT_SECTIONS


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
        r.table(k, {"number", "joints", "length"}, {"number", "joints", "length"}, value=t)
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
        r.table(k, {"name", "link", "from", "distance", "angle"}, {"name", "link", "from", "distance"},
                   value=t)
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
        r.table(k, {"number", "joint", "through", "angle", "on", "offset"}, {"joint"}, value=t)
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

    inp = r.table("input", {"link", "angle", "omega", "tip_speed", "sense", "alpha", "torque"}, {"link", "angle"})
    crank_no = r.number("input.link", inp["link"])
    crank = next((x for x in links if x.number == crank_no), None)
    if crank is None:
        raise r.fail("input.link", f"there is no link {crank_no}")
    if sum(j in ground for j in crank.joints) != 1:
        raise r.fail("input.link", f"link {crank_no} must join one fixed pivot in [frame] to a moving joint")
    angle = r.quantity("input.angle", inp["angle"], "angle", units)
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

    assembly = r.named_table("assembly")
    branches = {r.name(f"assembly.{j}", j): _branch(r, f"assembly.{j}", v) for j, v in assembly.items()}
    for j in branches:
        if j not in points:
            raise r.fail(f"assembly.{j}", f"{j} is not a joint of the mechanism")
    m = Mechanism(ground, tuple(links), tuple(slides), tuple(attached), crank_no, branches)
    m, effects = read_effects(r, units, m)
    if torque is not None and not effects.inertial:
        raise r.fail("input.torque", "a torque on the crank sets its angular acceleration only through "
                                     "masses: give the moving links a [[mass]], or give alpha instead")
    if torque is not None and effects.balance is not None:
        raise r.fail("input.torque", f"the load {effects.balance.load} is already found from a torque on the "
                                     f"crank; give the torque there or here, not both")
    return {"mechanism": m, "angle": angle, "omega": omega, "alpha": alpha, "torque": torque,
            "effects": effects}


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
