"""Teeth cut by generation (constructions.gears.generation): the fillet and undercut a rack cutter leaves.

Checked against (1) the closed forms -- the undercut limit 2 k / sin^2 phi (interference.min_pinion_with_rack),
the form radius R_L where the fillet leaves an uncut involute, the root circle r - d, the tip round
rho = c / (1 - sin phi) (ISO 53 profile A: 0.38 m) -- and (2) the drafter's own way of finding the
generated tooth, independent of the envelope: the cutter drawn at many positions as it rolls, each
position's outline cut out of the blank (shapely), and the tooth that is left measured radius by radius.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st
from shapely import affinity
from shapely.geometry import Point, Polygon
from shapely.ops import unary_union

from constructions.gears.generation import (cut_flank, fewest_uncut, form_radius, is_undercut, largest_tip_round,
                                            straight_depth, tip_round)
from constructions.gears.interference import min_pinion_with_rack
from constructions.gears.tooth import STUB, FULL_DEPTH, Gear, ToothSystem, inv, involute_point, roll_angle
from constructions.geometry import Vec

M = 1.0


def gear(n: int, deg: float, system=FULL_DEPTH) -> Gear:
    return Gear(n, ToothSystem(M, math.radians(deg), *system))


def involute_angle(g: Gear, radius: float) -> float:
    """The involute flank's angle from the tooth's centre line at ``radius`` (the closed form)."""
    return g.half_tooth_angle + inv(g.system.pressure_angle) - inv(math.acos(g.base_radius / radius))


def test_iso_53_tip_round():
    assert tip_round(gear(20, 20.0)) == pytest.approx(0.25 / (1 - math.sin(math.radians(20.0))), rel=1e-15)
    assert tip_round(gear(20, 20.0)) == pytest.approx(0.38, abs=0.001)          # ISO 53 profile A, in modules


@pytest.mark.parametrize("deg", [14.5, 20.0])
def test_undercut_exactly_below_the_rack_limit(deg):
    """A full-depth cutter whose tip round fits (c / (1 - sin phi) within the rack tooth's tip) has its
    straight flank reach the working depth k m: it undercuts every pinion with fewer teeth than the least
    that is free of interference with a rack, and no other; the envelope's own finding (the fillet
    passing the base circle inside the involute) says the same."""
    least = min_pinion_with_rack(math.radians(deg), 1.0)
    assert straight_depth(gear(10, deg)) == pytest.approx(M, rel=1e-14)
    assert fewest_uncut(gear(10, deg)) == pytest.approx(2.0 / math.sin(math.radians(deg)) ** 2, rel=1e-12)
    for n in range(5, 90):
        g = gear(n, deg)
        assert is_undercut(g) == (n < least), n
        assert cut_flank(g).undercut == (n < least), n


@pytest.mark.parametrize("deg", [22.5, 25.0, 30.0])
def test_where_the_round_does_not_fit_the_tip_is_one_round(deg):
    """At larger pressure angles the rack tooth's tip is too narrow for c / (1 - sin phi): the two rounds
    meet on its centre line (one full round), the straight flank reaches deeper than k m, and the cutter
    undercuts up to 2 depth / (m sin^2 phi) teeth -- more than the interference limit."""
    g = gear(10, deg)
    phi = math.radians(deg)
    rho = tip_round(g)
    assert rho < 0.25 * M / (1 - math.sin(phi))
    qx = math.pi * M / 4 + ((rho - 1.25 * M) * math.sin(phi) - rho) / math.cos(phi)
    assert qx == pytest.approx(0.0, abs=1e-14)                                # the rounds' centres meet
    assert straight_depth(g) > M
    for n in range(5, 60):
        assert cut_flank(gear(n, deg)).undercut == (n < fewest_uncut(g)) == is_undercut(gear(n, deg)), n


def test_stub_teeth_follow_their_own_limit():
    for n in range(5, 40):
        g = gear(n, 20.0, STUB)
        assert cut_flank(g).undercut == (n < fewest_uncut(g)) == (n < min_pinion_with_rack(math.radians(20.0), 0.8))


@pytest.mark.parametrize("n, deg", [(18, 20.0), (20, 20.0), (40, 20.0), (12, 25.0), (34, 14.5)])
def test_an_uncut_involute_runs_down_to_the_form_radius_and_the_fillet_to_the_root(n, deg):
    g = gear(n, deg)
    f = cut_flank(g)
    assert not f.undercut
    phi = math.radians(deg)
    depth = 1.25 * M - tip_round(g) * (1 - math.sin(phi))                       # where the straight flank ends
    r_l = math.hypot(g.base_radius, g.pitch_radius * math.sin(phi) - depth / math.sin(phi))
    assert f.involute_from == pytest.approx(r_l, abs=1e-12 * M) and form_radius(g) == f.involute_from
    first_r, first_a = f.fillet[0]
    assert first_r == pytest.approx(r_l, abs=1e-12 * M)
    assert first_a == pytest.approx(involute_angle(g, r_l), abs=1e-12)          # the fillet starts on the involute
    assert f.fillet[-1][0] == pytest.approx(g.dedendum_radius, abs=1e-12 * M)   # and ends on the root circle
    # below the form radius the fillet leaves more tooth than the involute would (no undercut)
    for r, a in f.fillet[1:]:
        if r > g.base_radius:
            assert a >= involute_angle(g, r) - 1e-12


@pytest.mark.parametrize("n, deg", [(7, 30.0), (10, 20.0), (12, 20.0), (16, 20.0), (17, 20.0), (8, 14.5)])
def test_an_undercut_flank_meets_the_involute_above_the_base_circle(n, deg):
    g = gear(n, deg)
    f = cut_flank(g)
    assert f.undercut
    r_x, a_x = f.fillet[0]
    assert r_x == f.involute_from and g.base_radius < r_x < g.pitch_radius
    assert a_x == pytest.approx(involute_angle(g, r_x), abs=1e-12)              # the crossing is on the involute
    # and just below it the fillet is inside the involute tooth: material the involute would keep is gone
    r, a = f.fillet[1]
    if r > g.base_radius:
        assert a < involute_angle(g, r)
    assert f.fillet[-1][0] == pytest.approx(g.dedendum_radius, abs=1e-12 * M)


def _generated_by_rolling(g: Gear, positions: int) -> Polygon:
    """The blank (addendum disc) with the rack cutter cut out of it at ``positions`` rolling positions:
    the cutter drawn as a drafter draws it (straight flanks, tip rounds of 40 chords, flat tip), each
    position rolled as the gear turns through theta (translated r theta along the pitch line, turned
    back through theta about the gear's centre)."""
    s = g.system
    phi, d, r, p = s.pressure_angle, s.d, g.pitch_radius, s.circular_pitch
    rho = tip_round(g)
    qx = p / 4 + ((rho - d) * math.sin(phi) - rho) / math.cos(phi)
    qy = r - d + rho
    top = r + 3 * M
    right = [(p / 4 + 3 * M * math.tan(phi), top)]
    right += [(qx + rho * math.cos(a), qy + rho * math.sin(a)) for a in np.linspace(-phi, -math.pi / 2, 40)]
    tooth = [(-x, y) for x, y in reversed(right)] + right
    rack = unary_union([Polygon([(x + k * p, y) for x, y in tooth]) for k in (-1, 0, 1)])
    cuts = [affinity.rotate(affinity.translate(rack, -r * t, 0.0), -t, origin=(0, 0), use_radians=True)
            for t in np.linspace(-0.9, 0.9, positions)]
    return Point(0, 0).buffer(g.addendum_radius, 1000).difference(unary_union(cuts))


def _edge_of(rest: Polygon, radius: float, centre: float, space: float) -> float:
    """How far from the tooth's centre line (an angle) the material that is ``rest`` ends at ``radius``:
    in the material at the centre line, in the space ``space`` round from it; bisected to 1e-12."""
    lo, hi = 0.0, space
    for _ in range(40):
        mid = 0.5 * (lo + hi)
        inside = rest.contains(Point(radius * math.cos(centre + mid), radius * math.sin(centre + mid)))
        lo, hi = (mid, hi) if inside else (lo, mid)
    return lo


@pytest.mark.parametrize("n, deg", [(12, 20.0), (7, 30.0), (20, 20.0)])
def test_the_flank_is_what_rolling_the_cutter_leaves(n, deg):
    """The tooth left by the cutter drawn at 2401 positions, measured at radii from the root to the pitch
    circle (the angle at which a ray from the tooth's centre line leaves the material), against the cut
    flank: within 2e-3 m, what 2401 positions and 40-chord rounds resolve (the fillet read between its
    24 points)."""
    g = gear(n, deg)
    f = cut_flank(g)
    rest = _generated_by_rolling(g, 2401)
    centre = math.pi / 2 - math.pi / n                  # the tooth right of the space on +y
    fillet = sorted(f.fillet)
    for radius in np.linspace(g.dedendum_radius + 0.05 * M, g.pitch_radius, 12):
        edge = _edge_of(rest, radius, centre, math.pi / n)
        ours = (involute_angle(g, radius) if radius >= f.involute_from
                else float(np.interp(radius, [q[0] for q in fillet], [q[1] for q in fillet])))
        assert abs(edge - ours) * radius <= 2e-3 * M, radius


def test_the_tooth_outline_with_its_fillets():
    """Gear.tooth_outline with a cut flank: a simple outline, the root points on the root circle, the
    flanks on the involute down to R_X, the tip where the uncut outline has it, necked below R_X (undercut)."""
    g = gear(12, 20.0)
    f = cut_flank(g)
    cut = g.tooth_outline(Vec(0.0, 0.0), 0.0, 24, f)
    plain = g.tooth_outline(Vec(0.0, 0.0), 0.0, 24)
    assert Polygon([(p.x, p.y) for p in cut] + [(0.0, 0.0)]).is_valid
    assert cut[0].norm() == pytest.approx(g.dedendum_radius, abs=1e-12) and cut[-1].norm() == pytest.approx(
        g.dedendum_radius, abs=1e-12)
    assert cut[0].y < 0 < cut[-1].y                                             # CW flank first, as before
    first_involute = involute_point(g.base_radius, g.flank_start(0.0, -1), roll_angle(g.base_radius, f.involute_from))
    assert min(p.distance_to(first_involute) for p in cut) <= 1e-12
    flanks = [p for p in cut if f.involute_from - 1e-12 <= p.norm() < g.addendum_radius - 1e-9]
    assert len(flanks) >= 46 and all(abs(abs(p.angle()) - involute_angle(g, p.norm())) <= 1e-12 for p in flanks)
    assert max(p.norm() for p in cut) == pytest.approx(max(p.norm() for p in plain), abs=1e-12)
    # below R_X the tooth is necked: narrower than the uncut outline, whose flank runs radially below the
    # base circle at the involute's angle there
    radial = involute_angle(g, g.base_radius)
    assert radial == pytest.approx(max(abs(p.angle()) for p in plain if p.norm() <= g.base_radius + 1e-12), abs=1e-12)
    assert min(abs(p.angle()) for p in cut if p.norm() < f.involute_from - 1e-9) < radial - 1e-3


def test_a_stated_cutter_tip_sets_the_straight_flank_and_the_undercut_limit():
    """A sharp-cornered cutter (cutter_tip 0) runs its straight flank the whole dedendum deep: at 20 deg full
    depth it undercuts up to 2 x 1.25 / sin^2 phi = 21.4 teeth, so a 20-tooth gear it cuts is undercut --
    and what rolling that cutter leaves is still the flank computed (within 2e-3 m)."""
    sharp = Gear(20, ToothSystem(M, math.radians(20.0), 1.0, 1.25, 0.0))
    assert tip_round(sharp) == 0.0 and straight_depth(sharp) == pytest.approx(1.25 * M, rel=1e-15)
    assert fewest_uncut(sharp) == pytest.approx(2.5 / math.sin(math.radians(20.0)) ** 2, rel=1e-12)
    assert cut_flank(sharp).undercut and not cut_flank(gear(20, 20.0)).undercut
    for n in range(15, 25):
        g = Gear(n, ToothSystem(M, math.radians(20.0), 1.0, 1.25, 0.0))
        assert cut_flank(g).undercut == (n < fewest_uncut(g)), n
    f = cut_flank(sharp)
    rest = _generated_by_rolling(sharp, 2401)
    centre = math.pi / 2 - math.pi / 20
    for radius in np.linspace(sharp.base_radius, f.involute_from, 5)[1:-1]:
        edge = _edge_of(rest, radius, centre, math.pi / 20)
        fillet = sorted(f.fillet)
        ours = float(np.interp(radius, [q[0] for q in fillet], [q[1] for q in fillet]))
        assert abs(edge - ours) * radius <= 2e-3 * M and ours < involute_angle(sharp, radius)   # undercut


@settings(max_examples=80, deadline=None)
@given(n=st.integers(3, 150), deg=st.floats(10.0, 38.0), ka=st.floats(0.5, 1.2), clearance=st.floats(0.0, 0.5),
       tip=st.none() | st.floats(0.0, 1.0))
def test_any_system_s_cut_flank_runs_from_the_involute_to_the_root(n, deg, ka, clearance, tip):
    """Whatever the system and cutter (a tip radius up to the most its tooth holds): the fillet starts on
    the involute, ends on the root circle, and the undercut says what the closed form says but within
    half a tooth of the limit; a flank whose fillet crosses the tooth's centre line says it is severed."""
    s0 = ToothSystem(M, math.radians(deg), ka, ka + clearance)
    s = ToothSystem(M, math.radians(deg), ka, ka + clearance,
                    None if tip is None else tip * largest_tip_round(s0))
    g = Gear(n, s)
    f = cut_flank(g)
    if f is None:                                     # no such rack: its tooth pointed above its tip line
        assert math.pi * M / 4 <= (ka + clearance) * M * math.tan(math.radians(deg))
        return
    if f.undercut != is_undercut(g):
        # the closed form decides by the straight flank's end passing T; the drawing by the round's path
        # crossing the involute above the base circle -- which, with a large round, can begin only a
        # fraction of a tooth past the limit (within half a tooth of it here)
        assert abs(n - fewest_uncut(g)) < 0.5, (n, fewest_uncut(g))
    assert f.fillet[-1][0] == pytest.approx(g.dedendum_radius, abs=1e-9 * M)
    r0, a0 = f.fillet[0]
    assert r0 == pytest.approx(f.involute_from, rel=1e-14)
    if r0 >= g.base_radius:
        assert a0 == pytest.approx(involute_angle(g, r0), abs=1e-9)
    assert f.severed == any(a <= 0 for _, a in f.fillet)
