"""The effects a linkage scene declares: [gravity], [[load]], [[couple]], [[mass]], [[spring]] and
[[friction]] (README, "Loads, masses, gravity, springs, friction") -> :class:`Effects`, in SI.

Read after the mechanism, with the shared reader, so every error is one sentence naming the file and the
key (``load[2].at``).  A centre of gravity a scene gives by distance and angle, or leaves to its default
(the middle of a link), becomes the attached point ``G<link>`` of the mechanism, so the polygons find its
velocity and acceleration images; a scene without these sections gets its mechanism back unchanged and
:data:`NO_EFFECTS`.
"""

from __future__ import annotations

import math
import re
from dataclasses import replace
from typing import Any

from constructions.forces import inertia as inertia_of
from constructions.forces.effects import NO_EFFECTS, Balance, Couple, Effects, End, Mass, Spring
from constructions.geometry import Vec
from constructions.mechanisms.model import Attached, Mechanism

from . import limits
from .effect_keys import COUPLE_KEYS, FRICTION_KEYS, GRAVITY_KEYS, LOAD_KEYS, MASS_KEYS, SPRING_KEYS
from .keys import KeyTable
from .loads import polar, read_loads
from .unitset import Units

SECTIONS = frozenset({"gravity", "load", "couple", "mass", "spring", "friction"})
"""The top-level sections of a linkage scene this module reads."""

SHAPE_NAMES = {**{s: s for s in inertia_of.SHAPES}, "disk": "disc", "thin_ring": "thin ring",
               "semicircular_plate": "semicircular plate"}
"""The shapes a [[mass]] may name (:data:`constructions.forces.inertia.SHAPES`), with their spellings."""
DIMENSIONS = ("length", "radius", "width", "height", "inner_radius", "outer_radius")

MU_MAX = 10.0
"""The largest coefficient of friction a scene may give: its friction angle, atan 10 = 84.3 deg, leans a
guide's force within 6 deg of the guide itself; dry rubber on concrete is about 1."""
_NAME = re.compile(r"[A-Za-z][A-Za-z0-9]*")


def read_effects(r, units: Units, m: Mechanism) -> tuple[Mechanism, Effects]:
    """The effects of a scene and its mechanism with the centres of gravity it adds (``m`` itself, and
    :data:`NO_EFFECTS`, when the scene has none of these sections)."""
    if not any(s in r.data for s in SECTIONS):
        return m, NO_EFFECTS
    return _EffectsReader(r, units, m).read()


def claim_name(names: dict[str, str], key: str, v: str, fail, rule: str) -> str:
    """``v`` given at ``key`` registered in ``names`` (name -> the key's table), or ``fail(key, ...)`` naming
    the table that has it already and ``rule``."""
    if v in names:
        raise fail(key, f"{v} is already the name of {names[v]}; {rule}")
    names[v] = key.rsplit(".", 1)[0]
    return v


class _EffectsReader:
    def __init__(self, r, units: Units, m: Mechanism) -> None:
        self.r, self.units, self.m = r, units, m
        self.blocks = m.blocks()
        self.links = {k.number: k for k in m.links}
        self.names: dict[str, str] = {}          # effect name -> the key that gave it
        self.balance: Balance | None = None       # the load to be found for a given torque

    # -- helpers -------------------------------------------------------------------------------------
    def fail(self, key: str, problem: str):
        return self.r.fail(key, problem)

    def name(self, key: str, value: Any) -> str:
        v = self.r.text(key, value)
        if not _NAME.fullmatch(v):
            raise self.fail(key, f"{v!r} is not a name (a letter then letters or digits, e.g. P or M4)")
        return claim_name(self.names, key, v, self.fail, "loads, couples and springs need names of their own")

    def body(self, key: str, value: Any) -> int:
        n = self.r.number(key, value)
        if n not in self.links and n not in self.blocks:
            raise self.fail(key, f"there is no link or slider block {n}")
        return n

    def what(self, body: int) -> str:
        if body in self.blocks:
            return f"block {body}"
        return f"link {body} ({'-'.join(self.links[body].joints)})"

    def points(self, body: int) -> tuple[str, ...]:
        if body in self.blocks:
            return (self.blocks[body].joint,)
        return self.m.points_of(body)

    def point(self, key: str, value: Any, body: int) -> str:
        p = self.r.name(key, value)
        pts = self.points(body)
        if p not in pts:
            if body in self.blocks:
                raise self.fail(key, f"{p} is not a point of block {body}; a block's only point is its "
                                     f"joint {pts[0]}")
            raise self.fail(key, f"{p} is not a point of {self.what(body)}; its points are {', '.join(pts)}")
        return p

    def quantity(self, key: str, value: Any, kind: str) -> float:
        return self.r.quantity(key, value, kind, self.units)

    def positive(self, key: str, value: Any, kind: str, hint: str = "") -> float:
        v = self.quantity(key, value, kind)
        if v <= 0:
            raise self.fail(key, "must be positive" + hint)
        return v

    def not_negative(self, key: str, value: Any, kind: str) -> float:
        v = self.quantity(key, value, kind)
        if v < 0:
            raise self.fail(key, "must not be negative")
        return v

    def items(self, section: str, keys: KeyTable):
        for i, t in enumerate(self.r.array(section), 1):
            k = f"{section}[{i}]"
            self.r.table(k, keys, value=t)
            yield k, t

    # -- sections --------------------------------------------------------------------------------------
    def read(self) -> tuple[Mechanism, Effects]:
        gravity = self.gravity()
        m, masses = self.masses()
        self.m = m
        loads = tuple(self.loads())
        couples = tuple(self.couples())
        springs, fixed = self.springs()
        friction = self.friction()
        return m, Effects(loads, couples, masses, springs, gravity, friction, fixed, self.balance)

    def gravity(self) -> Vec | None:
        if "gravity" not in self.r.data:
            return None
        t = self.r.table("gravity", GRAVITY_KEYS)
        g = self.positive("gravity.g", t["g"], "acceleration",
                          "; it is the magnitude (turn it with angle = \"... deg\", the direction of gravity)")
        if "angle" not in t:
            return Vec(0.0, -g)
        return polar(g, self.quantity("gravity.angle", t["angle"], "angle"))

    def masses(self) -> tuple[Mechanism, tuple[Mass, ...]]:
        tables = list(self.items("mass", MASS_KEYS))
        if not tables:
            return self.m, ()
        taken = set(self.m.ground) | {j for k in self.m.links for j in self.m.points_of(k.number)}
        taken |= {s.joint for s in self.m.slides}
        owner = {p: k.number for k in self.m.links for p in self.m.points_of(k.number)}
        seen: dict[int, str] = {}
        added: list[Attached] = []
        got: list[tuple[str, dict, int, float, str]] = []
        for k, t in tables:
            body = self.body(f"{k}.link", t["link"])
            if body in seen:
                raise self.fail(f"{k}.link", f"{self.what(body)} already has a mass ({seen[body]}); give one "
                                             f"[[mass]] per body")
            seen[body] = k
            mass = self.positive(f"{k}.mass", t["mass"], "mass")
            if "at" in t and "from" in t:
                raise self.fail(f"{k}.from", "give the centre of gravity either at an existing point (at) or "
                                             "from/distance/angle (a new point), not both")
            for d in ("distance", "angle"):
                if d in t and "from" not in t:
                    raise self.fail(f"{k}.{d}", "measures the centre of gravity from a joint: give from too "
                                                "(or at = an existing point)")
            if "at" in t:
                centre = self.point(f"{k}.at", t["at"], body)
            elif body in self.blocks:
                joint = self.blocks[body].joint
                if "from" in t:
                    raise self.fail(f"{k}.from", f"the centre of gravity of block {body} is its joint {joint}; "
                                                 f"leave from out (or write at = \"{joint}\")")
                centre = joint
            else:
                link = self.links[body]
                centre = f"G{body}"
                if "from" in t:
                    key = f"{k}.from"
                    base = self.r.name(key, t["from"])
                    if base not in link.joints:
                        raise self.fail(key, f"{base} is not a joint of link {body} ({'-'.join(link.joints)}); "
                                             f"the centre of gravity is measured from one of them")
                    if "distance" not in t:
                        raise self.fail(f"{k}.distance", f"is missing: how far the centre of gravity lies "
                                                         f"from {base}")
                    dist = self.positive(f"{k}.distance", t["distance"], "length",
                                         f" (a centre of gravity at {base} itself is at = \"{base}\")")
                    att = Attached(centre, body, base, dist,
                                   self.quantity(f"{k}.angle", t.get("angle", 0), "angle"))
                    where = f"{self.units.format('length', dist)} from {base}"
                else:
                    key = f"{k}.at"
                    att = Attached(centre, body, link.joints[0], link.length / 2, 0.0)
                    where = f"the middle of {'-'.join(link.joints)}"
                if centre in taken:
                    held = (f"a point of link {owner[centre]}" if centre in owner else
                            "a fixed pivot" if centre in self.m.ground else "a slider joint")
                    raise self.fail(key, f"the centre of gravity ({where}) would be the new point {centre}, "
                                         f"but {centre} is already {held}; name an existing point of link "
                                         f"{body} with at = \"...\" instead")
                count = len(self.m.attached) + len(added) + 1
                cap = limits.MAX_COUNTS["point"]
                if count > cap:
                    raise self.fail(k, f"its centre of gravity {centre} would be point number {count}; "
                                       f"a scene may have at most {cap} points ([[point]] tables and the "
                                       f"centres of gravity [[mass]] adds)")
                taken.add(centre)
                added.append(att)
            got.append((k, t, body, mass, centre))
        m = self.m
        if added:                               # a point added to a placed link: the plan stays as it was
            m = replace(m, attached=m.attached + tuple(added))
        self.m = m
        return m, tuple(Mass(body, mass, centre, self.inertia(k, t, body, mass, centre))
                        for k, t, body, mass, centre in got)

    def inertia(self, k: str, t: dict, body: int, mass: float, centre: str) -> float:
        """The moment of inertia about the centre of gravity: given, by shape, or about a point."""
        if "shape" in t and "inertia" in t:
            raise self.fail(f"{k}.shape", "give the moment of inertia (inertia) or a shape, not both")
        if "shape" not in t:
            for d in DIMENSIONS:
                if d in t:
                    raise self.fail(f"{k}.{d}", f"is a dimension of a shape: give shape too, e.g. "
                                                f"shape = \"{_shape_of(d)}\"")
        if "inertia_about" in t and "shape" in t:
            raise self.fail(f"{k}.inertia_about", "applies to inertia given about a point, not to a shape")
        if "inertia_about" in t and "inertia" not in t:
            raise self.fail(f"{k}.inertia_about", "needs inertia = the moment of inertia about that point")
        if "shape" in t:
            return self.shape(k, t, body, mass)
        if "inertia" not in t:
            return 0.0
        i = self.not_negative(f"{k}.inertia", t["inertia"], "moment of inertia")
        if "inertia_about" not in t:
            return i
        p = self.point(f"{k}.inertia_about", t["inertia_about"], body)
        d = 0.0
        if body not in self.blocks:
            local = self.m.local(body)
            d = local[p].distance_to(local[centre])
        try:
            return inertia_of.about_centre(i, mass, d)
        except ValueError:
            f = self.units.format
            raise self.fail(f"{k}.inertia", f"{f('moment of inertia', i)} about {p} is less than m d^2 = "
                                            f"{f('moment of inertia', mass * d * d)} ({p} is "
                                            f"{f('length', d)} from the centre of gravity {centre}), so the "
                                            f"moment about the centre would be negative") from None

    def shape(self, k: str, t: dict, body: int, mass: float) -> float:
        raw = t["shape"]
        shape = SHAPE_NAMES.get(raw.strip().lower()) if isinstance(raw, str) else None
        if shape is None:
            raise self.fail(f"{k}.shape", f"{self.r.shown(raw)} is not a shape; choose from "
                                          f"{', '.join(repr(s) for s in inertia_of.SHAPES)}")
        needs = inertia_of.SHAPES[shape]
        for d in DIMENSIONS:
            if d in t and d not in needs:
                raise self.fail(f"{k}.{d}", f"is not a dimension of a {shape}; a {shape} has "
                                            f"{' and '.join(needs)}")
        values = []
        for d in needs:
            key = f"{k}.{d}"
            if d not in t:
                if shape == "rod" and body in self.links:
                    values.append(self.links[body].length)     # the link itself is the rod
                    continue
                raise self.fail(key, f"is missing: a {shape} needs {' and '.join(needs)}")
            if d == "inner_radius":
                values.append(self.not_negative(key, t[d], "length"))
            else:
                values.append(self.positive(key, t[d], "length"))
        if shape == "ring" and values[0] > values[1]:
            raise self.fail(f"{k}.inner_radius", f"{self.units.format('length', values[0])} is larger than "
                                                 f"outer_radius ({self.units.format('length', values[1])})")
        return inertia_of.shape_inertia(shape, mass, *values)

    def loads(self):
        loads, self.balance = read_loads(self, LOAD_KEYS)
        return loads

    def couples(self):
        for k, t in self.items("couple", COUPLE_KEYS):
            name = self.name(f"{k}.name", t["name"])
            body = self.body(f"{k}.link", t["link"])
            torque = self.quantity(f"{k}.torque", t["torque"], "torque")
            torque = self.r.signed(f"{k}.sense", "torque", torque, t["torque"], t.get("sense"))
            yield Couple(name, body, torque)

    def springs(self) -> tuple[tuple[Spring, ...], dict[str, Vec]]:
        out: list[Spring] = []
        fixed: dict[str, Vec] = {}
        for k, t in self.items("spring", SPRING_KEYS):
            name = self.name(f"{k}.name", t["name"])
            body = self.body(f"{k}.link", t["link"])
            a = End(body, self.point(f"{k}.at", t["at"], body))
            other = "to_link" in t or "to" in t
            if "anchor" in t and other:
                raise self.fail(f"{k}.anchor", "give the other end either as anchor (a fixed point) or as "
                                               "to_link and to (a point of a body), not both")
            if "anchor" in t:
                v = t["anchor"]
                if isinstance(v, str):                    # a fixed pivot by name
                    p = self.r.name(f"{k}.anchor", v)
                    if p not in self.m.ground:
                        raise self.fail(f"{k}.anchor", f"{p} is not a fixed pivot in [frame]; give a fixed "
                                                       f"pivot's name or a point [x, y]")
                    fixed[p] = self.m.ground[p]
                    b = End(None, p)
                else:
                    p = f"{name} anchor"
                    fixed[p] = self.r.point(f"{k}.anchor", v, self.units)
                    b = End(None, p)
            elif other:
                for key in ("to_link", "to"):
                    if key not in t:
                        raise self.fail(f"{k}.{key}", "is missing: the other end is point to of body "
                                                      "to_link (or give anchor, a fixed point)")
                to = self.body(f"{k}.to_link", t["to_link"])
                if to == body:
                    raise self.fail(f"{k}.to_link", f"both ends are on {self.what(body)}; a spring between "
                                                    f"two points of one body does nothing")
                b = End(to, self.point(f"{k}.to", t["to"], to))
            else:
                raise self.fail(f"{k}.anchor", "is missing: give the other end as anchor = [x, y] (a fixed "
                                               "point) or as to_link and to (a point of another body)")
            stiffness = self.positive(f"{k}.stiffness", t["stiffness"], "stiffness")
            free = self.not_negative(f"{k}.free_length", t["free_length"], "length")
            out.append(Spring(name, a, b, stiffness, free))
        return tuple(out), fixed

    def friction(self) -> dict[int, float]:
        out: dict[int, float] = {}
        where: dict[int, str] = {}
        for k, t in self.items("friction", FRICTION_KEYS):
            n = self.r.number(f"{k}.slider", t["slider"])
            if n not in self.blocks:
                if n in self.links:
                    raise self.fail(f"{k}.slider", f"link {n} is not a slider block; friction acts between a "
                                                   f"block and its guide or slot")
                raise self.fail(f"{k}.slider", f"there is no slider block {n}")
            if n in out:
                raise self.fail(f"{k}.slider", f"block {n} already has its friction ({where[n]})")
            mu = t["mu"]
            if isinstance(mu, bool) or not isinstance(mu, (int, float)):
                raise self.fail(f"{k}.mu", f"{self.r.shown(mu)} is not a coefficient of friction: write a plain "
                                           f"number, e.g. mu = 0.15")
            if not math.isfinite(mu) or not 0 <= mu <= MU_MAX:
                raise self.fail(f"{k}.mu", f"{self.r.shown(mu)} must be a number from 0 to {MU_MAX:g} (a friction "
                                           f"angle of at most 84 deg), e.g. 0.15")
            out[n], where[n] = float(mu), k
        return out


def _shape_of(dimension: str) -> str:
    return next(s for s, dims in inertia_of.SHAPES.items() if dimension in dims)
