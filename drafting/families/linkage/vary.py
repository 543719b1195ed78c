"""The linkage family's ``[vary]`` keys: which of its values a batch of lab sheets varies.

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
four-bar).

The ranges themselves (grids, steps, variants) are :mod:`drafting.scene.vary`'s.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from ...scene.vary import Range, fail, read_range

INPUT_KEYS = {"crank_angle": ("angle", "angle"), "omega": ("omega", "angular velocity"),
              "tip_speed": ("tip_speed", "velocity"), "alpha": ("alpha", "angular acceleration"),
              "torque": ("torque", "torque")}
"""``[vary]`` key -> ([input] key, quantity kind)."""


def read_vary(data: dict[str, Any], path: Path | str, units) -> tuple[Range, ...]:
    """The ranges of a linkage scene's ``[vary]`` (a table, not empty: the scene reader has seen to it),
    checked against the scene's data."""
    vary = data["vary"]
    out: list[Range] = []
    choices = ", ".join(list(INPUT_KEYS) + [f"{k}.<{v[0]}>" for k, v in _NAMED.items()] + ["pivot.<name>.x|y"])
    inp = data.get("input") if isinstance(data.get("input"), dict) else {}
    for name, spec in vary.items():
        if name in _NAMED:
            _, find, table, field, qkind, positive, example = _NAMED[name]
            if not isinstance(spec, dict) or not spec:
                raise fail(path, f"vary.{name}", example)
            for sub_name, sub in spec.items():
                full = f"vary.{name}.{sub_name}"
                r = read_range(path, full, (table, find(data, path, sub_name), field), qkind, sub, units,
                           f"{name}.{sub_name}")
                if positive and not r.low > 0:
                    raise fail(path, full, positive)
                out.append(r)
            continue
        if name == "pivot":
            if not isinstance(spec, dict) or not spec:
                raise fail(path, "vary.pivot", "must name fixed pivots, e.g. pivot.O4.x = [\"180 mm\", \"220 mm\"]")
            for pivot, sub in spec.items():
                _pivot_check(data, path, pivot)
                if not isinstance(sub, dict) or not sub or set(sub) - {"x", "y"}:
                    bad = sorted(set(sub) - {"x", "y"}) if isinstance(sub, dict) else []
                    raise fail(path, f"vary.pivot.{pivot}" + (f".{bad[0]}" if bad else ""),
                                "varies a coordinate of the pivot: pivot.<name>.x or pivot.<name>.y")
                for axis, sub2 in sub.items():
                    out.append(read_range(path, f"vary.pivot.{pivot}.{axis}", ("frame", pivot, "xy".index(axis)),
                                      "length", sub2, units, f"pivot.{pivot}.{axis}"))
            continue
        if name not in INPUT_KEYS:
            shown = name if name.strip() else f'"{name}"'      # an empty key as TOML writes it: vary.""
            raise fail(path, f"vary.{shown}", f"unknown key; choose from {choices}")
        input_key, qkind = INPUT_KEYS[name]
        absent_ok = input_key == "angle" or (input_key == "alpha" and "torque" not in inp)   # alpha defaults to 0
        if not absent_ok and input_key not in inp:
            given = [k for k in ("omega", "tip_speed", "alpha", "torque") if k in inp]
            hint = f"; the scene gives {', '.join('input.' + g for g in given)}" if given else ""
            raise fail(path, f"vary.{name}", f"varies input.{input_key}, which the scene does not give{hint}")
        out.append(read_range(path, f"vary.{name}", ("input", input_key), qkind, spec, units, name))
    keys = [r.key for r in out]
    for r in out:
        if keys.count(r.key) > 1:
            raise fail(path, f"vary.{r.key}", "is given twice")
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
    raise fail(path, f"vary.length.{joints}", f"no link joins the joints {joints!r}{known}")


def _load_index(data, path, name: str) -> int:
    loads = data.get("load") if isinstance(data.get("load"), list) else []
    names = [t.get("name") for t in loads if isinstance(t, dict) and isinstance(t.get("name"), str)]
    for i, t in enumerate(loads):
        if isinstance(t, dict) and t.get("name") == name:
            return i
    known = f"; the loads are {', '.join(names)}" if names else "; the scene has no [[load]]"
    raise fail(path, f"vary.load.{name}", f"no load is named {name!r}{known}")


def _mass_index(data, path, link: str) -> int:
    masses = data.get("mass") if isinstance(data.get("mass"), list) else []
    on = [i for i, t in enumerate(masses) if isinstance(t, dict) and str(t.get("link")) == link]
    if len(on) == 1:
        return on[0]
    if on:
        raise fail(path, f"vary.mass.{link}", f"link {link} carries {len(on)} masses; vary a link that carries one")
    known = sorted({str(t.get("link")) for t in masses if isinstance(t, dict) and "link" in t})
    carried = f"; the links with a mass are {', '.join(known)}" if known else "; the scene has no [[mass]]"
    raise fail(path, f"vary.mass.{link}", f"no [[mass]] is on link {link!r}{carried}")


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
        raise fail(path, f"vary.pivot.{name}", f"no fixed pivot is named {name!r} in [frame]{known}")
