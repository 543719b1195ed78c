"""A compound mechanism (the notes' toggle linkage, velocity Example 3: a four-bar driving a slider
through a second coupler) solved by chaining dyads, checked against the derivative of the constructed
positions and against the dyad-chain vector loop (constructions.vector_loops)."""

from __future__ import annotations

import math

import pytest

from constructions.check import analytic_solution, analytic_values, compare
from constructions.mechanisms.pose import locate
from constructions.polygons.velocity import velocity_polygon
from mechanisms import toggle_linkage


@pytest.mark.parametrize("angle_deg", [0.0, 60.0, 135.0, 300.0])
def test_chained_dyads_match_the_derivative_of_the_positions(angle_deg):
    m, omega, h = toggle_linkage(), -100.0, 1e-6
    th = math.radians(angle_deg)
    va = velocity_polygon(m, locate(m, th), omega)
    ahead, behind = locate(m, th + h).positions, locate(m, th - h).positions
    v_ref = va.velocities["B"].norm()
    for name in ("B", "C", "D"):
        fd = (ahead[name] - behind[name]) * (omega / (2 * h))
        assert (va.velocities[name] - fd).norm() <= 1e-7 * v_ref, name
    # the slider only slides, and every link's omega is its relative velocity over its length
    assert abs(va.velocities["D"].y) <= 1e-12 * v_ref
    P = va.pose.positions
    w4 = (P["D"] - P["C"]).cross(va.relative[("D", "C")]) / (P["D"] - P["C"]).dot(P["D"] - P["C"])
    assert va.angular[4] == pytest.approx(w4, rel=1e-12)


def test_compound_mechanism_is_checked_by_the_dyad_chain():
    """The toggle linkage has no single closed form, but the dyad-chain vector loops solve it: every
    graphical value has its analytic counterpart and they agree."""
    m = toggle_linkage()
    va = velocity_polygon(m, locate(m, math.radians(60)), -100.0)
    a = analytic_solution(m, math.radians(60), -100.0)
    assert a is not None and a.model == "dyad chain"
    rows = compare(va.measured(m), analytic_values(m, a))
    assert {r.name for r in rows} >= {"V_C", "V_D", "V_DC", "omega_4"}
    assert all(r.analytic is not None and r.agrees for r in rows)
    assert [e.text(marks=False) for e in va.construction.equations] == ["V_C = V_B + V_CB", "V_D = V_C + V_DC"]
