"""A linkage scene's [[load]] tables -> :class:`Load`, in SI: a force given as force and angle, as a gas
pressure on a piston's bore (F = p \u03c0 d\u00b2/4 along its line of stroke), or -- the inverse static
problem -- as the unknown held by a given driving torque (its force a unit vector along its angle, and the
:class:`Balance` naming it).  Read by :mod:`.effects`' reader ``er`` (its fail, name, body, point and
quantity helpers), so every error names the file and the key."""

from __future__ import annotations

import math
from typing import Any

from constructions.forces.effects import Balance, Load
from constructions.geometry import Vec

from .units import UnitError, format_value, split_value, to_si

PARALLEL = 1e-9
"""How far (as a sine) a pressure load's angle may stand from its piston's line of stroke."""
PRESSURE_UNIT = "MPa"
"""The unit of a pressure given as a plain number."""


def read_loads(er, keys) -> tuple[tuple[Load, ...], Balance | None]:
    """Every [[load]] of the scene (``keys``: its key table), and the one to be found for a given torque
    (None: all are given)."""
    out: list[Load] = []
    balance: tuple[str, Balance] | None = None             # (its key, the balance)
    for k, t in er.items("load", keys):
        name = er.name(f"{k}.name", t["name"])
        body = er.body(f"{k}.link", t["link"])
        at = er.point(f"{k}.at", t["at"], body)
        angle = er.quantity(f"{k}.angle", t["angle"], "angle")
        given = [x for x in ("force", "pressure", "torque") if x in t]
        if len(given) != 1:
            raise er.fail(f"{k}.{given[1] if given else 'force'}",
                          "give the load's force, or pressure and bore (a gas force on a piston), or torque (the "
                          "driving torque it holds: its force is then the unknown), only one of them"
                          if given else "is missing: give force (or pressure and bore, or torque)")
        if "sense" in t and given != ["torque"]:
            raise er.fail(f"{k}.sense", "turns the torque this load holds: give it only with torque")
        if "bore" in t and given != ["pressure"]:
            raise er.fail(f"{k}.bore", "is the bore the pressure acts on: give pressure too")
        if given == ["pressure"]:
            out.append(_pressure_load(er, k, t, name, body, at, angle))
        elif given == ["torque"]:
            if balance is not None:
                raise er.fail(f"{k}.torque", f"{balance[0]} is already the load to be found; a given torque "
                                             f"fixes one unknown load")
            torque = er.quantity(f"{k}.torque", t["torque"], "torque")
            balance = (k, Balance(name, er.r.signed(f"{k}.sense", "torque", torque, t["torque"], t.get("sense"))))
            out.append(Load(name, body, at, polar(1.0, angle)))
        else:
            force = er.quantity(f"{k}.force", t["force"], "force")
            if force < 0:
                raise er.fail(f"{k}.force", "is the magnitude: give it positive and turn angle by 180 deg")
            out.append(Load(name, body, at, polar(force, angle)))
    return tuple(out), (balance[1] if balance else None)


def _pressure_load(er, k: str, t: dict, name: str, body: int, at: str, angle: float) -> Load:
    """A gas force on a piston: F = p \u03c0 d\u00b2 / 4 along the block's fixed line of stroke."""
    if "bore" not in t:
        raise er.fail(f"{k}.bore", "is missing: the force of a pressure is p \u03c0 d\u00b2/4 over the bore d")
    blk = er.blocks.get(body)
    if blk is None or blk.on is not None:
        what = er.what(body) if blk is None else f"block {body} in a slot"
        raise er.fail(f"{k}.pressure", f"acts on a piston along its line of stroke: give link = a slider block "
                                       f"on a fixed guide, not {what}")
    if abs(math.sin(angle - blk.angle)) > PARALLEL:
        line = blk.angle % math.pi
        raise er.fail(f"{k}.angle", f"a pressure pushes along the line of stroke, at "
                                    f"{er.units.format('angle', line)} or {er.units.format('angle', line + math.pi)}: "
                                    f"give the one the gas pushes the piston towards")
    try:                                   # [units] has no pressure: a plain number is in MPa
        p = to_si(t["pressure"], "pressure", PRESSURE_UNIT)
    except UnitError as e:
        raise er.fail(f"{k}.pressure", str(e)) from None
    if p <= 0:
        raise er.fail(f"{k}.pressure", "must be positive (turn angle by 180 deg for a pull)")
    bore = er.positive(f"{k}.bore", t["bore"], "length")
    force = p * math.pi * bore * bore / 4
    along = blk.angle if math.cos(angle - blk.angle) > 0 else blk.angle + math.pi
    words = (f"{name} = p \u03c0 d\u00b2/4 = {format_value(p, 'pressure', pressure_unit(t['pressure']))} \u00d7 "
             f"\u03c0 ({er.units.format('length', bore)})\u00b2/4 = {er.units.format('force', force)} along the "
             f"line of stroke, at {er.units.format('angle', along % (2 * math.pi))}")
    return Load(name, body, at, polar(force, along), words)


def pressure_unit(raw: Any) -> str:
    """The unit a pressure was written in ("2 MPa" -> MPa, "20 bar" -> bar), MPa for a plain number."""
    return (split_value(raw)[1] or PRESSURE_UNIT) if isinstance(raw, str) else PRESSURE_UNIT


def polar(length: float, angle: float) -> Vec:
    """``length`` at ``angle``, exact along the axes (180 deg gives (-F, 0), not (-F, 4.9e-15))."""
    q = angle / (math.pi / 2)
    if abs(q - round(q)) < 1e-12:
        return Vec(*((length, 0.0), (0.0, length), (-length, 0.0), (0.0, -length))[round(q) % 4])
    return Vec.polar(length, angle)
