"""Parameter ranges in a scene (``[vary]``) and the variants drawn from them.

A linkage scene may say which of its values a batch of lab sheets varies, each over a range with units::

    [vary]
    crank_angle = ["30 deg", "150 deg"]                 # the crank angle ([input] angle)
    omega = { from = "5 rad/s", to = "15 rad/s", step = "0.5 rad/s" }
    length.BC = ["90 mm", "110 mm"]                     # the length of the link joining B and C
    load.P = ["30 N", "50 N"]                           # the force of the [[load]] named P

Keys: ``crank_angle``, ``omega``, ``tip_speed``, ``alpha``, ``torque`` (the [input] value the scene
gives: a scene that gives ``tip_speed`` varies ``tip_speed``, not ``omega``; ``alpha`` unless the scene
gives a torque instead), ``length.<joints>``
(the link between two joints, named as the notes name it: ``length.O1B``, ``length.BC``) and
``load.<name>`` (the force of a ``[[load]]``, its magnitude: the range must stay positive; its angle
stays as given), ``mass.<link>`` (the mass of the one ``[[mass]]`` on that link: its moment of inertia follows
when the scene gives a shape and stays as given when it gives ``inertia``; given ``inertia_about`` a
point, I_G = I_O - m d^2 follows the mass, and a draw that makes it negative is drawn again) and
``pivot.<name>.x`` / ``pivot.<name>.y`` (a coordinate of a fixed pivot in ``[frame]``: the frame link of a
four-bar).  A range is
``[from, to]`` or ``{ from, to, step }``; plain numbers are in the scene's ``[units]``.  A variant takes
each value on the grid ``from + k step`` (k = 0, 1, ...; never beyond ``to``), so the numbers on a sheet
are round; without a step, the step is the largest of 1, 2, 5 x 10^n units of ``from`` that divides the
range into at least 20 parts (30 .. 150 deg: 5 deg).

Variant ``i`` of seed ``S`` draws its values with ``numpy.random.default_rng([S, i])``, in the order the
keys are written: the same seed and index always give the same values, whatever else the batch does.  A
draw that cannot be assembled (or sits at a singular position) is drawn again from the same generator;
the batch says so.

Every problem with ``[vary]`` is one :class:`~drafting.scene.reader.SceneError` sentence naming the file and
the key, and is found when the scene is read (``render`` and ``solve`` read the scene's own values and
check its ranges).
"""

from __future__ import annotations

import copy
from dataclasses import dataclass
from decimal import Decimal
from pathlib import Path
from typing import Any

from ..render.scales import nice_floor
from .units import UnitError, from_si, split_value, to_si, unit_symbol

INPUT_KEYS = {"crank_angle": ("angle", "angle"), "omega": ("omega", "angular velocity"),
              "tip_speed": ("tip_speed", "velocity"), "alpha": ("alpha", "angular acceleration"),
              "torque": ("torque", "torque")}
"""``[vary]`` key -> ([input] key, quantity kind)."""
STEPS_AT_LEAST = 20
MAX_STEPS = 10_000_000


@dataclass(frozen=True)
class Range:
    """One varied value: its ``[vary]`` key, where it goes in the scene, its kind, and the grid
    ``low + k step`` (k = 0 .. count - 1) in ``unit``."""

    key: str
    where: tuple            # ("input", "angle"), ("link", index in [[link]], "length"), ("load", index, "force"),
                            # ("mass", index in [[mass]], "mass") or ("frame", pivot name, 0 for x | 1 for y)
    kind: str
    unit: str
    low: Decimal
    step: Decimal
    count: int

    def value(self, k: int) -> Decimal:
        return self.low + self.step * k

    def text(self, k: int) -> str:
        """The value as the scene file would write it ("35 deg")."""
        return f"{_plain(self.value(k))} {self.unit}"

    @property
    def header(self) -> str:
        """A CSV column header with the unit: "crank_angle (deg)"."""
        return f"{self.key} ({unit_symbol(self.unit)})"


def _plain(d: Decimal) -> str:
    s = format(d.normalize(), "f")
    return s if s != "-0" else "0"


def _fail(path, key: str, problem: str):
    from .reader import SceneError
    return SceneError(path, key, problem)


def read_vary(data: dict[str, Any], path: Path | str, units) -> tuple[Range, ...]:
    """The ranges of a scene's ``[vary]`` (empty when it has none), checked against the scene's data."""
    vary = data.get("vary")
    if vary is None:
        return ()
    if not isinstance(vary, dict):
        raise _fail(path, "vary", "must be a table of ranges, e.g. crank_angle = [\"30 deg\", \"150 deg\"]")
    kind = data.get("kind", "linkage")
    if kind != "linkage":
        raise _fail(path, "vary", f"is read for linkage scenes; this is a {kind!r} scene")
    if not vary:
        raise _fail(path, "vary", "is empty; give at least one range, e.g. crank_angle = [\"30 deg\", \"150 deg\"]")
    out: list[Range] = []
    choices = ", ".join(list(INPUT_KEYS) + [f"{k}.<{v[0]}>" for k, v in _NAMED.items()] + ["pivot.<name>.x|y"])
    inp = data.get("input") if isinstance(data.get("input"), dict) else {}
    for name, spec in vary.items():
        if name in _NAMED:
            _, find, table, field, qkind, positive, example = _NAMED[name]
            if not isinstance(spec, dict) or not spec:
                raise _fail(path, f"vary.{name}", example)
            for sub_name, sub in spec.items():
                full = f"vary.{name}.{sub_name}"
                r = _range(path, full, (table, find(data, path, sub_name), field), qkind, sub, units,
                           f"{name}.{sub_name}")
                if positive and not r.low > 0:
                    raise _fail(path, full, positive)
                out.append(r)
            continue
        if name == "pivot":
            if not isinstance(spec, dict) or not spec:
                raise _fail(path, "vary.pivot", "must name fixed pivots, e.g. pivot.O4.x = [\"180 mm\", \"220 mm\"]")
            for pivot, sub in spec.items():
                _pivot_check(data, path, pivot)
                if not isinstance(sub, dict) or not sub or set(sub) - {"x", "y"}:
                    bad = sorted(set(sub) - {"x", "y"}) if isinstance(sub, dict) else []
                    raise _fail(path, f"vary.pivot.{pivot}" + (f".{bad[0]}" if bad else ""),
                                "varies a coordinate of the pivot: pivot.<name>.x or pivot.<name>.y")
                for axis, sub2 in sub.items():
                    out.append(_range(path, f"vary.pivot.{pivot}.{axis}", ("frame", pivot, "xy".index(axis)),
                                      "length", sub2, units, f"pivot.{pivot}.{axis}"))
            continue
        if name not in INPUT_KEYS:
            raise _fail(path, f"vary.{name}", f"unknown key; choose from {choices}")
        input_key, qkind = INPUT_KEYS[name]
        absent_ok = input_key == "angle" or (input_key == "alpha" and "torque" not in inp)   # alpha defaults to 0
        if not absent_ok and input_key not in inp:
            given = [k for k in ("omega", "tip_speed", "alpha", "torque") if k in inp]
            hint = f"; the scene gives {', '.join('input.' + g for g in given)}" if given else ""
            raise _fail(path, f"vary.{name}", f"varies input.{input_key}, which the scene does not give{hint}")
        out.append(_range(path, f"vary.{name}", ("input", input_key), qkind, spec, units, name))
    keys = [r.key for r in out]
    for r in out:
        if keys.count(r.key) > 1:
            raise _fail(path, f"vary.{r.key}", "is given twice")
    return tuple(out)


def _link_index(data, path, joints: str) -> int:
    links = data.get("link") if isinstance(data.get("link"), list) else []
    names = []
    for i, t in enumerate(links):
        js = t.get("joints") if isinstance(t, dict) else None
        if isinstance(js, list) and len(js) == 2 and all(isinstance(j, str) for j in js):
            names.append("".join(js))
            if joints in ("".join(js), "".join(reversed(js))):
                return i
    known = f"; the links are {', '.join(names)}" if names else ""
    raise _fail(path, f"vary.length.{joints}", f"no link joins the joints {joints!r}{known}")


def _load_index(data, path, name: str) -> int:
    loads = data.get("load") if isinstance(data.get("load"), list) else []
    names = [t.get("name") for t in loads if isinstance(t, dict) and isinstance(t.get("name"), str)]
    for i, t in enumerate(loads):
        if isinstance(t, dict) and t.get("name") == name:
            return i
    known = f"; the loads are {', '.join(names)}" if names else "; the scene has no [[load]]"
    raise _fail(path, f"vary.load.{name}", f"no load is named {name!r}{known}")


def _mass_index(data, path, link: str) -> int:
    masses = data.get("mass") if isinstance(data.get("mass"), list) else []
    on = [i for i, t in enumerate(masses) if isinstance(t, dict) and str(t.get("link")) == link]
    if len(on) == 1:
        return on[0]
    if on:
        raise _fail(path, f"vary.mass.{link}", f"link {link} carries {len(on)} masses; vary a link that carries one")
    known = sorted({str(t.get("link")) for t in masses if isinstance(t, dict) and "link" in t})
    carried = f"; the links with a mass are {', '.join(known)}" if known else "; the scene has no [[mass]]"
    raise _fail(path, f"vary.mass.{link}", f"no [[mass]] is on link {link!r}{carried}")


#: The [vary] keys that name a row of a scene table: key -> (what names the row, finds the row's index,
#: the table, the row's field, the quantity, what to say when the range does not stay above 0 (None: it
#: may), the example a key without a name is told)
_NAMED = {
    "length": ("joints", _link_index, "link", "length", "length", None,
               "must name links by their joints, e.g. length.BC = [\"90 mm\", \"110 mm\"]"),
    "load": ("name", _load_index, "load", "force", "force",
             "varies the load's magnitude: the range must stay above 0 (turn its angle by 180 deg for the other sense)",
             "must name loads, e.g. load.P = [\"30 N\", \"50 N\"]"),
    "mass": ("link", _mass_index, "mass", "mass", "mass", "the range must stay above 0 kg",
             "must name links by number, e.g. mass.3 = [\"0.8 kg\", \"1.6 kg\"]"),
}


def _pivot_check(data, path, name: str) -> None:
    frame = data.get("frame") if isinstance(data.get("frame"), dict) else {}
    if not isinstance(frame.get(name), list) or len(frame[name]) != 2:
        known = f"; the fixed pivots are {', '.join(frame)}" if frame else ""
        raise _fail(path, f"vary.pivot.{name}", f"no fixed pivot is named {name!r} in [frame]{known}")


def _range(path, full: str, where: tuple, kind: str, spec, units, key_name: str) -> Range:
    if isinstance(spec, list):
        if len(spec) != 2:
            raise _fail(path, full, "must be a range [from, to], e.g. [\"30 deg\", \"150 deg\"]")
        lo_raw, hi_raw, step_raw = spec[0], spec[1], None
    elif isinstance(spec, dict):
        unknown = sorted(set(spec) - {"from", "to", "step"})
        if unknown:
            raise _fail(path, f"{full}.{unknown[0]}", "unknown key; a range has from, to and step")
        if "from" not in spec or "to" not in spec:
            raise _fail(path, f"{full}.{'from' if 'from' not in spec else 'to'}", "is missing")
        lo_raw, hi_raw, step_raw = spec["from"], spec["to"], spec.get("step")
    else:
        raise _fail(path, full, "must be a range [from, to] or { from = ..., to = ..., step = ... }")
    default_unit = units.of(kind)
    unit = default_unit
    if isinstance(lo_raw, str):
        try:
            unit = split_value(lo_raw)[1] or default_unit
        except UnitError as e:
            raise _fail(path, full, str(e)) from None

    def si(raw, what):
        try:
            return to_si(raw, kind, default_unit)
        except UnitError as e:
            raise _fail(path, f"{full}" + (f".{what}" if isinstance(spec, dict) else ""), str(e)) from None
    lo, hi = si(lo_raw, "from"), si(hi_raw, "to")
    if not hi > lo:
        raise _fail(path, full, f"the range must go up: from {_shown(lo, kind, unit)} to {_shown(hi, kind, unit)}")
    lo_u = Decimal(f"{from_si(lo, kind, unit):.12g}")      # 12 digits: the round trip through SI
    hi_u = Decimal(f"{from_si(hi, kind, unit):.12g}")
    span = hi_u - lo_u
    if step_raw is None:
        step = Decimal(f"{nice_floor(float(span) / STEPS_AT_LEAST):.12g}")   # the largest 1-2-5 x 10^n
    else:
        st = si(step_raw, "step")
        if not st > 0:
            raise _fail(path, f"{full}.step", "must be positive")
        step = Decimal(f"{from_si(st, kind, unit):.12g}")
        if step > span:
            raise _fail(path, f"{full}.step", f"{_shown(st, kind, unit)} is larger than the range "
                                             f"({_plain(span)} {unit_symbol(unit)})")
    count = int(span / step) + 1
    if count > MAX_STEPS:
        raise _fail(path, f"{full}.step", f"makes {count} values; at most {MAX_STEPS} are allowed")
    return Range(key_name, where, kind, unit, lo_u, step, count)


def _shown(si: float, kind: str, unit: str) -> str:
    return f"{from_si(si, kind, unit):g} {unit_symbol(unit)}"


# ---- variants ----------------------------------------------------------------------------------------

def draw(ranges, rng) -> list[int]:
    """One draw: a grid index per range, in the ranges' order."""
    return [int(rng.integers(0, r.count)) for r in ranges]


def variant_data(data: dict[str, Any], ranges, ks, index: int) -> dict[str, Any]:
    """The scene's data with the drawn values written in, its ``[vary]`` removed and its drawing number
    marked with the variant (TOM-V-001-007)."""
    out = copy.deepcopy(data)
    out.pop("vary", None)
    for r, k in zip(ranges, ks):
        if r.where[0] == "input":
            out.setdefault("input", {})[r.where[1]] = r.text(k)
        else:             # ("link", i, "length"), ("load", i, "force"), ("mass", i, "mass") or ("frame", pivot, 0 | 1)
            out[r.where[0]][r.where[1]][r.where[2]] = r.text(k)
    drawing = out.setdefault("drawing", {})
    if isinstance(drawing, dict):
        drawing["number"] = f"{drawing.get('number', 'TOM-000')}-{index:03d}"
    return out
