"""The independent check of a free body: its three equations of equilibrium as one linear system.

Every support contributes its unknowns -- the magnitude along its line for a member, roller or guide, the
two components for a pin -- as columns of unit forces: sum of x components, sum of y components, and
moments about the body's centre divided by the body's size (so the three rows weigh alike).  The known
loads and couples are the right-hand side.  numpy solves it; nothing of the construction (K, L, the
polygon) is used.  ``condition`` is the 2-norm condition number of that scaled matrix: large near an
improperly constrained body (lines nearly concurrent or parallel).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Mapping

import numpy as np

from ..geometry import Vec
from .rigid_body import PIN, RigidBody


@dataclass(frozen=True)
class EquilibriumSolution:
    """Each support's force on the body (SI) by name, the condition number of the scaled system and the
    largest residual of the three equations (N, and N m over the body's size)."""

    forces: Mapping[str, Vec]
    condition: float
    residual: float


def equilibrium_matrix(body: RigidBody) -> tuple[np.ndarray, np.ndarray, list[tuple[str, Vec | None]]]:
    """The scaled system A x = b and, per unknown, (support name, unit direction or None for a pin's
    component: the direction is then the column's own x or y)."""
    pts = list(body.points.values())
    c = Vec(sum(p.x for p in pts) / len(pts), sum(p.y for p in pts) / len(pts))
    L = body.size
    cols: list[tuple[float, float, float]] = []
    unknowns: list[tuple[str, Vec]] = []
    for s in body.supports:
        r = body.points[s.at] - c
        if s.kind == PIN:
            for e in (Vec(1.0, 0.0), Vec(0.0, 1.0)):
                cols.append((e.x, e.y, r.cross(e) / L))
                unknowns.append((s.name, e))
        else:
            _, u = body.line(s)
            cols.append((u.x, u.y, r.cross(u) / L))
            unknowns.append((s.name, u))
    A = np.array(cols, dtype=np.float64).T
    fx = sum(ld.force.x for ld in body.loads)
    fy = sum(ld.force.y for ld in body.loads)
    m = sum((body.points[ld.at] - c).cross(ld.force) for ld in body.loads) + sum(cp.torque for cp in body.couples)
    rhs = -np.array([fx, fy, m / L], dtype=np.float64)
    return A, rhs, unknowns


def equilibrium_solution(body: RigidBody) -> EquilibriumSolution:
    """Solve the body's equilibrium equations (exactly three unknowns; :func:`numpy.linalg.solve`)."""
    A, rhs, unknowns = equilibrium_matrix(body)
    if A.shape != (3, 3):
        raise ValueError(f"the {body.name} has {A.shape[1]} unknowns; the equilibrium system needs 3")
    x = np.linalg.solve(A, rhs)
    forces: dict[str, Vec] = {}
    for (name, e), t in zip(unknowns, x):
        forces[name] = forces.get(name, Vec(0.0, 0.0)) + e * float(t)
    residual = float(np.max(np.abs(A @ x - rhs)))
    return EquilibriumSolution(forces, float(np.linalg.cond(A)), residual)


__all__ = ["EquilibriumSolution", "equilibrium_matrix", "equilibrium_solution"]
