"""The inverse static problem: the magnitude of a load whose line and direction are given (a piston's gas
force, a tool's cutting force) that a given driving torque on the crank holds.

Every known force enters the equilibrium of the links linearly, so the driving torque is affine in the
load's magnitude F: T(F) = T(0) + F (T(1) - T(0)).  Two evaluations fix it and secant steps refine the root
(friction keeps it affine only while the normal forces keep their directions; a step that flips one is
followed by another).  ``by`` chooses whose torque, as :func:`.equilibrium.alpha_for_torque` does: the
linear system of all links, or virtual work (the power balance, no joint forces) -- two independent routes
to the same F.  A negative F is a load acting against the direction the scene gave.
"""

from __future__ import annotations

from dataclasses import replace
from typing import Mapping

from ..errors import DegenerateInput
from ..geometry import Vec
from .effects import Effects
from .equilibrium import equilibrium, virtual_work_torque

STEPS = 8
"""Secant steps at most (a frictionless mechanism needs one, a friction sign flip one or two more)."""
DEAD_ARM = 1e-9
"""A load whose torque per newton on the crank is below this fraction of the scene size does no work there."""
TOLERANCE = 1e-13
"""The driving torque's residual at which the search stops, relative to the largest torque seen."""


def with_load(effects: Effects, magnitude: float) -> Effects:
    """``effects`` with its unknown load (:attr:`Effects.balance`) at ``magnitude`` (N) along its given
    direction, and nothing left to find."""
    name = effects.balance.load
    loads = tuple(replace(ld, force=ld.force * magnitude) if ld.name == name else ld for ld in effects.loads)
    return replace(effects, loads=loads, balance=None)


def torque_with_load(m, angle: float, omega: float, alpha: float, effects: Effects, magnitude: float, *,
                     guess: Mapping[str, Vec] | None = None, by: str = "equilibrium") -> float:
    """The driving torque when the unknown load has ``magnitude``: from the equilibrium of all links, or
    by virtual work (with the friction forces that system finds, where there is friction)."""
    e = with_load(effects, magnitude)
    if by == "virtual work":
        eq = equilibrium(m, angle, omega, alpha, e, guess=guess) if e.friction else None
        return virtual_work_torque(m, angle, omega, alpha, e, guess=guess,
                                   friction=eq.friction if eq is not None else None)
    if by != "equilibrium":
        raise ValueError(f"by must be 'equilibrium' or 'virtual work', not {by!r}")
    return equilibrium(m, angle, omega, alpha, e, guess=guess).torque


def load_for_torque(m, angle: float, omega: float, alpha: float, effects: Effects, *,
                    guess: Mapping[str, Vec] | None = None, by: str = "equilibrium") -> float:
    """The magnitude F (N, signed along the given direction) of the load :attr:`Effects.balance` names at
    which the driving torque on the crank is the balance's torque."""
    if effects.balance is None:
        raise DegenerateInput("no load is to be found: the scene gives every load")
    target = effects.balance.torque

    def t(f: float) -> float:
        return torque_with_load(m, angle, omega, alpha, effects, f, guess=guess, by=by)
    a, ra = 0.0, t(0.0) - target
    b, rb = 1.0, t(1.0) - target
    if abs(rb - ra) <= DEAD_ARM * m.size:          # the torque per newton of the load is its lever arm
        raise DegenerateInput(f"the load {effects.balance.load} does no work on the crank here (as the crank "
                              f"turns, its point moves square to its line): no magnitude of it changes the driving "
                              f"torque, so the torque cannot fix it")
    scale = max(abs(target), abs(ra + target), abs(rb + target))
    for _ in range(STEPS):
        if rb == ra:
            break
        a, ra, b = b, rb, b - rb * (b - a) / (rb - ra)
        rb = t(b) - target
        if abs(rb) <= TOLERANCE * max(scale, abs(target)):
            break
    return b
