"""The independent check of a gear train: velocity matching at the pitch points, and the equilibrium of
every member, each one linear system in all the members at once (numpy), from the layout's geometry.

Velocities: a gear on member g whose axis rides on carrier c (or the frame) moves its pitch point P at
omega_c k x (O - O_c) + omega_g k x (P - O); two gears in mesh move P alike along the common tangent (no
slip).  One equation a mesh, one a given speed; solved by least squares, with its rank and residual.

Torques: a mesh pushes gear b with F t (t the common tangent's unit vector) at P and gear a with -F t; each
member's moments about its axis, plus the moment about the carrier's pivot of the forces on the gears
it carries, plus its external torque, sum to zero.  Unknowns: the mesh forces, the output's load torque
and the held member's reaction.

With n planets every planet's meshes are written again, turned 360/n deg about the carrier's axis: the
velocity system gains their equations, and the equilibrium their moments, each planet carrying the same
force (equal sharing), so the mesh force found is the load per planet.
"""

from __future__ import annotations

import math

import numpy as np

from ..geometry import Vec
from .trains import FRAME, Given, Train, layout


def _k_cross(r: Vec) -> np.ndarray:
    return np.array([-r.y, r.x])


def _copies(train: Train, m) -> range:
    """The planets at which mesh ``m`` is repeated (each turned 360/n deg about the carrier's axis)."""
    return range(train.planets if train.carried_mesh(m) else 1)


def velocity_check(train: Train, givens: tuple[Given, ...]) -> tuple[dict[str, float], int, float]:
    centres, pitch = layout(train)
    members = list(train.members)
    idx = {m: i for i, m in enumerate(members)}
    rows, rhs = [], []
    origin = Vec(0.0, 0.0)
    for m, k in ((m, k) for m in train.meshes for k in _copies(train, m)):
        turn = 2.0 * math.pi * k / train.planets
        P = pitch[m.name].rotated(turn)
        ga, gb = train.gear(m.a), train.gear(m.b)
        axis = (centres[gb.name] - centres[ga.name]).rotated(turn)
        if axis.norm() == 0:
            continue
        t = np.array([-axis.unit().y, axis.unit().x])
        row = np.zeros(len(members))
        for g, sign in ((ga, 1.0), (gb, -1.0)):
            O = centres[g.name].rotated(turn)
            row[idx[g.member]] += sign * _k_cross(P - O) @ t
            if g.carrier != FRAME:
                row[idx[g.carrier]] += sign * _k_cross(O - origin) @ t
        rows.append(row)
        rhs.append(0.0)
    # the given speeds are substituted (a held member stays exactly at rest); the rest solved together
    A = np.array(rows)
    known = {gv.member: gv.speed for gv in givens}
    free = [m for m in members if m not in known]
    kv = np.array([known.get(m, 0.0) for m in members])
    b = -A @ kv
    Af = A[:, [idx[m] for m in free]]
    sol, _, rank, _ = np.linalg.lstsq(Af, b, rcond=None)
    res = float(np.linalg.norm(Af @ sol - b))
    out = dict(known)
    out.update({m: float(sol[i]) for i, m in enumerate(free)})
    return {m: out[m] for m in members}, int(rank) + len(known), res


def torque_check(train: Train, speeds: dict[str, float], power: float, inp: str, out: str,
                 held: tuple[str, ...] = ()) -> tuple[dict[str, float], dict[str, float]]:
    """Mesh tangential forces (magnitudes) and external torques on every member, by equilibrium."""
    centres, pitch = layout(train)
    members = [m for m in train.members]
    meshes = list(train.meshes)
    unknowns = [f"F:{m.name}" for m in meshes] + [f"T:{out}"] + [f"T:{h}" for h in held if h not in (inp, out)]
    ui = {u: i for i, u in enumerate(unknowns)}
    mi = {m: i for i, m in enumerate(members)}
    A = np.zeros((len(members), len(unknowns)))
    b = np.zeros(len(members))
    origin = Vec(0.0, 0.0)
    for m, k in ((m, k) for m in meshes for k in _copies(train, m)):
        turn = 2.0 * math.pi * k / train.planets      # equal sharing: one force unknown for all n planets
        P = pitch[m.name].rotated(turn)
        ga, gb = train.gear(m.a), train.gear(m.b)
        u = (centres[gb.name] - centres[ga.name]).rotated(turn).unit()
        t = Vec(-u.y, u.x)
        for g, sign in ((gb, 1.0), (ga, -1.0)):
            O = centres[g.name].rotated(turn)
            A[mi[g.member], ui[f"F:{m.name}"]] += sign * (P - O).cross(t)
            if g.carrier != FRAME:              # the force on the gear reaches the carrier through its pin
                A[mi[g.carrier], ui[f"F:{m.name}"]] += sign * (O - origin).cross(t)
    b[mi[inp]] -= power / speeds[inp]
    A[mi[out], ui[f"T:{out}"]] = 1.0
    for h in held:
        if h not in (inp, out):
            A[mi[h], ui[f"T:{h}"]] = 1.0
    x, *_ = np.linalg.lstsq(A, b, rcond=None)
    loads = {m.name: abs(float(x[ui[f"F:{m.name}"]])) for m in meshes}
    torques = {m: 0.0 for m in members}
    torques[inp] = power / speeds[inp]
    torques[out] = float(x[ui[f"T:{out}"]])
    for h in held:
        if h not in (inp, out):
            torques[h] = float(x[ui[f"T:{h}"]])
    return loads, torques
