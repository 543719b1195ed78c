"""Spur gears: the involute, a pair in mesh drawn Cartesian against the closed forms, the interference
limits against a brute-force search, and exactly-at-the-limit cases (constructions/gears)."""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings, strategies as st

from constructions.errors import ConstructionError
from constructions.gears.contact import AT_LIMIT, CLEAR, INTERFERENCE, Pair, contact_geometry
from constructions.gears.generation import cut_flank, fewest_uncut
from constructions.gears.interference import (interferes, max_gear_for_pinion, min_equal_gears, min_pinion_with_gear,
                                              min_pinion_with_rack, minimum_teeth_table, search_max_gear,
                                              search_min_pinion)
from constructions.gears.mesh import mesh_analysis
from constructions.gears.mesh_check import closed_form, notes_contact_ratio
from constructions.gears.tooth import (Gear, ToothSystem, inv, involute_point, roll_angle, unwinding_points)
from constructions.geometry import Vec
from constructions.entities import Dimension

REL = 1e-9
DEG = math.pi / 180


def system(m=0.005, phi=20.0, ka=1.0, kd=1.25):
    return ToothSystem(m, phi * DEG, ka, kd)


def agree(a, b, scale):
    assert abs(a - b) <= REL * scale, (a, b)


def check_pair(pair):
    geo, _ = contact_geometry(pair)
    cf = closed_form(pair)
    L = pair.size
    for name, drawn, closed in (("AP", geo.approach, cf.approach), ("PB", geo.recess, cf.recess),
                                ("AB", geo.path, cf.path), ("PT1", geo.limits[0], cf.pt1)):
        agree(drawn, closed, L)
    if math.isfinite(cf.pt2):
        agree(geo.limits[1], cf.pt2, L)
    else:
        assert math.isinf(geo.limits[1])
    assert abs(geo.working_pressure_angle - cf.working_pressure_angle) <= REL
    assert abs(geo.contact_ratio - cf.contact_ratio) <= REL * cf.contact_ratio
    return geo, cf


# -- the involute -------------------------------------------------------------------------------------------

def test_the_thread_construction_lands_on_the_exact_involute_and_its_normal_touches_the_base_circle():
    rb = 0.047
    for touch, end, u in unwinding_points(rb, 0.3, 0.07, 8):
        exact = involute_point(rb, 0.3, u)
        assert end.distance_to(exact) <= 1e-15 * 10
        assert abs(end.norm() - rb * math.sqrt(1 + u * u)) <= 1e-15
        # the thread (the involute's normal) is square to the radius at its touching point
        assert abs((end - touch).dot(touch)) <= 1e-15
        # polar angle theta0 + inv(alpha), tan(alpha) = u
        assert abs((end.angle() - 0.3) - inv(math.atan(u))) <= 1e-12


def test_circles_pitches_and_thickness_of_a_20_tooth_module_5_gear():
    g = Gear(20, system())
    assert g.pitch_radius == pytest.approx(0.05, rel=1e-15)
    assert g.base_radius == pytest.approx(0.05 * math.cos(20 * DEG), rel=1e-15)
    assert (g.addendum_radius, g.dedendum_radius) == pytest.approx((0.055, 0.04375), rel=1e-15)
    assert g.base_pitch == pytest.approx(math.pi * 0.005 * math.cos(20 * DEG), rel=1e-14)
    assert g.thickness_at(g.pitch_radius) == pytest.approx(math.pi * 0.005 / 2, rel=1e-14)   # t = pi m / 2
    # the tooth thins towards the tip and is wider at the base circle
    assert g.thickness_at(g.addendum_radius) < g.thickness_at(g.pitch_radius) < g.thickness_at(g.base_radius)


def test_diametral_pitch_gives_the_module():
    s = ToothSystem.from_diametral_pitch(8, 20 * DEG)
    assert s.module == pytest.approx(0.0254 / 8, rel=1e-15)        # m / 25.4 mm = 1 / P


def test_the_drawn_pinion_flank_passes_through_the_pitch_point():
    pair = Pair(Gear(20, system()), Gear(40, system()))
    a = mesh_analysis(pair)
    g = pair.pinion
    theta0 = g.flank_start(g.half_tooth_angle, -1)        # the tooth in contact, centred a half tooth above P
    u = roll_angle(g.base_radius, g.pitch_radius)
    p = involute_point(g.base_radius, theta0, u)
    assert p.distance_to(a.geometry.points["P"]) <= 1e-15
    teeth = a.construction.entity("teeth 1").points
    assert min(q.distance_to(Vec(0, 0)) for q in teeth) == pytest.approx(g.dedendum_radius, rel=1e-12)


# -- the pair: construction against closed forms ---------------------------------------------------------

def test_20_40_module_5_contact_geometry_against_hand_numbers():
    """Derived by hand: AP = sqrt(105^2 - 93.969^2) - 100 sin 20, PB = sqrt(55^2 - 46.985^2) - 50 sin 20."""
    pair = Pair(Gear(20, system()), Gear(40, system()))
    geo, cf = check_pair(pair)
    s = math.sin(20 * DEG)
    ap = math.sqrt(0.105 ** 2 - (0.1 * math.cos(20 * DEG)) ** 2) - 0.1 * s
    pb = math.sqrt(0.055 ** 2 - (0.05 * math.cos(20 * DEG)) ** 2) - 0.05 * s
    assert geo.approach == pytest.approx(ap, rel=1e-12) and geo.recess == pytest.approx(pb, rel=1e-12)
    assert geo.contact_ratio == pytest.approx(1.6352, abs=5e-5)
    assert geo.verdict == CLEAR
    # the notes' printed formula agrees at the standard distance
    s5 = pair.pinion.system
    n = notes_contact_ratio(0.05, 0.1, s5.a, s5.a, s5.pressure_angle, s5.base_pitch)
    assert n == pytest.approx(cf.contact_ratio, rel=1e-12)


def test_a_larger_centre_distance_gives_the_working_pressure_angle_and_a_smaller_contact_ratio():
    s = system()
    std = Pair(Gear(20, s), Gear(40, s))
    wide = Pair(Gear(20, s), Gear(40, s), 0.152)
    g0, _ = check_pair(std)
    g1, cf = check_pair(wide)
    assert math.cos(g1.working_pressure_angle) == pytest.approx((std.pinion.base_radius + std.gear.base_radius) / 0.152,
                                                                rel=1e-14)
    assert g1.working_pressure_angle > 20 * DEG and g1.contact_ratio < g0.contact_ratio
    assert g1.working_radii[0] == pytest.approx(0.152 / 3, rel=1e-14)


def test_a_centre_distance_shorter_than_standard_is_refused():
    s = system()
    with pytest.raises(ConstructionError, match="jam"):
        contact_geometry(Pair(Gear(20, s), Gear(40, s), 0.149))


pairs = st.builds(lambda n1, extra, phi, k, stretch: (n1, n1 + extra, phi, k, stretch),
                  st.integers(8, 60), st.integers(0, 200), st.sampled_from([14.5, 20.0, 22.5, 25.0]),
                  st.sampled_from([1.0, 0.8]), st.sampled_from([0.0, 0.0, 0.002, 0.01, 0.03]))


@settings(max_examples=120, deadline=None)
@given(pairs)
def test_random_pairs_drawn_agree_with_the_closed_forms(case):
    n1, n2, phi, k, stretch = case
    s = ToothSystem(0.004, phi * DEG, k, 1.25)
    c = None if stretch == 0 else 0.002 * (n1 + n2) * (1 + stretch)
    pair = Pair(Gear(n1, s), Gear(n2, s), c)
    try:
        geo, _ = contact_geometry(pair)
    except ConstructionError:
        return                        # pulled so far apart the addendum circles miss the pitch point
    check_pair(pair)
    # the three-way verdict matches the notes' inequality r_a2 <= sqrt(r_b2^2 + (C sin phi')^2) = O2T1
    O2T1 = math.hypot(pair.gear.base_radius, pair.distance * math.sin(geo.working_pressure_angle))
    gap = O2T1 - pair.gear.addendum_radius
    if abs(gap) > 1e-6 * pair.size:
        assert (geo.start == INTERFERENCE) == (gap < 0)


@settings(max_examples=60, deadline=None)
@given(st.integers(6, 80), st.sampled_from([14.5, 20.0, 25.0]), st.sampled_from([0.0, 0.001]))
def test_random_racks_drawn_agree_with_the_closed_forms(n, phi, pulled):
    s = ToothSystem(0.003, phi * DEG)
    pair = Pair(Gear(n, s), None, None if not pulled else 0.0015 * n + pulled)
    check_pair(pair)


# -- interference ------------------------------------------------------------------------------------------

def test_the_minimum_teeth_table_closed_forms_agree_with_brute_force_everywhere():
    for angle, name, rack, equal in minimum_teeth_table():
        phi, k = angle * DEG, (1.0 if name == "full depth" else 0.8)
        assert search_min_pinion(None, phi, k) == rack
        # with an equal gear: the least N with N meshing N
        n = next(n for n in range(3, 100) if not _interferes_equal(n, phi, k))
        assert n == equal
        for n2 in (equal, equal + 1, 20, 40, 100, 300):
            want = min_pinion_with_gear(n2, phi, k)
            if want <= n2:
                assert search_min_pinion(n2, phi, k) == want, (angle, name, n2)
        for n1 in range(equal, rack + 1):
            assert search_max_gear(n1, phi, k) == max_gear_for_pinion(n1, phi, k), (angle, name, n1)


def _interferes_equal(n, phi, k):
    return interferes(n, n, phi, k)


def test_the_table_numbers_derived_from_the_rack_condition():
    """N >= 2k/sin^2 phi, rounded up (derived, and the notes' formula): 32, 18, 12 full depth; 14 stub 20 deg."""
    assert [min_pinion_with_rack(a * DEG) for a in (14.5, 20, 25)] == [32, 18, 12]
    assert min_pinion_with_rack(20 * DEG, 0.8) == 14
    assert min_equal_gears(20 * DEG) == 13
    # the largest gear each pinion below 18 teeth takes at 20 deg full depth
    assert [max_gear_for_pinion(n, 20 * DEG) for n in range(13, 19)] == [16, 26, 45, 101, 1309, None]


def test_rack_exactly_at_the_limit_is_at_the_limit_never_interference():
    """phi = 30 deg, k = 1: 2k/sin^2 phi = 8 exactly, so the 8-tooth pinion's contact starts at T1."""
    s = system(0.01, 30.0)
    verdicts = {n: contact_geometry(Pair(Gear(n, s)))[0].start for n in (7, 8, 9)}
    assert verdicts == {7: INTERFERENCE, 8: AT_LIMIT, 9: CLEAR}
    geo, cf = check_pair(Pair(Gear(8, s)))
    assert geo.approach == pytest.approx(geo.limits[0], rel=1e-12)


@pytest.mark.parametrize("n1,n2,phi", [(14, 30, 20.0), (12, 25, 25.0), (20, 61, 14.5), (10, 10, 20.0)])
def test_a_gear_pair_built_at_the_limit_reads_at_the_limit_and_one_tooth_off_interferes(n1, n2, phi):
    """The addendum constant that puts gear 2's tip exactly through T1 (solved from (N2 + 2k)^2 =
    N2^2 cos^2 phi + (N1 + N2)^2 sin^2 phi): at the limit; one pinion tooth fewer or one gear tooth more
    interferes; one pinion tooth more or one gear tooth fewer is clear."""
    p = phi * DEG
    k = (math.sqrt(n2 ** 2 * math.cos(p) ** 2 + (n1 + n2) ** 2 * math.sin(p) ** 2) - n2) / 2
    s = ToothSystem(0.005, p, k, max(1.25, k + 0.25))
    verdict = lambda a, b: contact_geometry(Pair(Gear(a, s), Gear(b, s)))[0].start  # noqa: E731
    assert verdict(n1, n2) == AT_LIMIT
    assert verdict(n1 - 1, n2) == INTERFERENCE and verdict(n1, n2 + 1) == INTERFERENCE
    assert verdict(n1 + 1, n2) == CLEAR
    if n2 > n1:
        assert verdict(n1, n2 - 1) == CLEAR
    a = mesh_analysis(Pair(Gear(n1, s), Gear(n2, s)))
    assert a.geometry.verdict == AT_LIMIT and not any("Interference" in w for w in a.warnings)


# -- internal gears ----------------------------------------------------------------------------------------

@settings(max_examples=80, deadline=None)
@given(st.integers(8, 40), st.integers(40, 160), st.sampled_from([14.5, 20.0, 25.0]), st.sampled_from([0.0, 0.001]))
def test_random_internal_pairs_drawn_agree_with_the_closed_forms(n1, n2, phi, pulled):
    s = ToothSystem(0.002, phi * DEG)
    if n2 - n1 < 8 or 0.001 * n2 * (1 - math.cos(phi * DEG)) <= s.a:
        return                       # the ring needs its tips outside its base circle
    c = None if not pulled else 0.001 * (n2 - n1) + pulled * 0.01
    pair = Pair(Gear(n1, s), Gear(n2, s), c, internal=True)
    try:
        contact_geometry(pair)
    except ConstructionError:
        return
    geo, _ = check_pair(pair)
    assert geo.end == CLEAR and math.isinf(geo.limits[1])


@pytest.mark.parametrize("n1,n2,phi", [(18, 72, 20.0), (20, 60, 25.0), (12, 90, 20.0)])
def test_an_internal_pair_built_at_the_limit(n1, n2, phi):
    """The ring's addendum circle r2 - a through T1: (N2/2 - k)^2 = (N2 cos(phi)/2)^2 + ((N2 - N1) sin(phi)/2)^2."""
    p = phi * DEG
    k = (n2 - math.sqrt(n2 ** 2 * math.cos(p) ** 2 + (n2 - n1) ** 2 * math.sin(p) ** 2)) / 2
    s = ToothSystem(0.005, p, k, 1.25)
    verdict = lambda a, b: contact_geometry(Pair(Gear(a, s), Gear(b, s), internal=True))[0].start  # noqa: E731
    assert verdict(n1, n2) == AT_LIMIT
    assert verdict(n1 + 1, n2) == CLEAR and verdict(n1 - 1, n2) == INTERFERENCE
    check_pair(Pair(Gear(n1, s), Gear(n2, s), internal=True))


@pytest.mark.parametrize("n1,n2,start,end", [(7, None, True, False), (8, None, False, False), (9, None, False, False),
                                             (10, 10, True, True), (30, 60, False, False)])
def test_interference_is_dimensioned_on_the_drawing(n1, n2, start, end):
    """Where contact runs off the involutes the stretch is dimensioned on the path of contact: A to T1
    (AP - PT1), T2 to B (PB - PT2); none at the limit or clear."""
    s = system(0.01, 30.0 if n2 is None else 20.0)
    pair = Pair(Gear(n1, s)) if n2 is None else Pair(Gear(n1, s), Gear(n2, s))
    a = mesh_analysis(pair)
    geo = a.geometry
    dims = {e.name: (e, st) for st in a.construction.steps for e in st.entities
            if isinstance(e, Dimension) and e.name.startswith("interference")}
    assert ("interference at A" in dims) == start and ("interference at B" in dims) == end
    assert (geo.start == INTERFERENCE) == start and (geo.end == INTERFERENCE) == end
    said = " ".join(a.warnings)
    assert ("starts before T1" in said) == start and ("ends after T2" in said) == end
    if start:
        dim, st = dims["interference at A"]
        assert (dim.start, dim.end) == (geo.points["A"], geo.points["T1"])
        assert st.value("i1").value == pytest.approx(dim.start.distance_to(dim.end), rel=1e-9)
        assert st.value("i1").value == pytest.approx(geo.approach - geo.limits[0], rel=1e-12)
    if end:
        dim, st = dims["interference at B"]
        assert (dim.start, dim.end) == (geo.points["T2"], geo.points["B"])
        assert st.value("i2").value == pytest.approx(dim.start.distance_to(dim.end), rel=1e-9)


def test_an_undercut_pinion_is_drawn_and_said_as_generated():
    """A pinion with fewer teeth than its rack cutter allows is drawn as the cutter leaves it (its teeth
    the generated outline: on the involute down to R_X, then the fillet), in the space diagram and in
    the involute diagram, and a step of its own says so with R_X (blank on a problem sheet: it is worked
    out, not given); a pinion of 20 teeth is drawn and said as before."""
    s = ToothSystem(0.010, math.radians(30.0))
    pair = Pair(Gear(7, s), None, rack_system=s)
    a = mesh_analysis(pair)
    g = pair.pinion
    cut = cut_flank(g)
    step = next(st for st in a.construction.steps if "undercut" in st.words)
    assert "gear 1" in step.words and not step.entities               # a step of its own, after the teeth
    assert step.value("rx").value == cut.involute_from
    assert step.value("nmin").value == fewest_uncut(g) and 7 < fewest_uncut(g)
    assert a.geometry.points["O1"] == Vec(0, 0)
    for name in ("teeth 1", "terms teeth"):                  # both drawn about O1 = the origin
        radii = sorted(q.norm() for q in a.construction.entity(name).points)
        assert radii[0] == pytest.approx(g.dedendum_radius, abs=1e-12)
        # every fillet radius but the crossing's appears twice per tooth (both flanks)
        fillet_radii = [r for r, _ in cut.fillet[1:]]
        assert all(sum(1 for q in radii if abs(q - r) <= 1e-12) >= 2 for r in fillet_radii)
    s20 = ToothSystem(0.005, math.radians(20.0))
    plain = mesh_analysis(Pair(Gear(20, s20), Gear(40, s20)))
    assert not any("undercut" in st.words for st in plain.construction.steps)


def test_a_tooth_the_cutter_would_sever_is_said_and_drawn_as_involutes():
    """Three teeth with a deep dedendum: the cutter's tip round crosses the tooth's centre line -- it
    would cut the tooth off at its root.  The sheet says so in one warning and draws the involute teeth,
    not a self-crossing outline."""
    s = ToothSystem(0.010, math.radians(14.71), 1.146, 1.408)
    pair = Pair(Gear(3, s), None, rack_system=s)
    assert cut_flank(pair.pinion).severed
    a = mesh_analysis(pair)
    said = [w for w in a.warnings if "cut through at their root" in w]
    assert len(said) == 1 and "gear 1" in said[0]
    assert not any("undercut" in st.words and "Cut by generation" in st.words for st in a.construction.steps)
    plain = pair.pinion.teeth_outline(Vec(0, 0), pair.pinion.half_tooth_angle - 2 * 2 * math.pi / 3, 5, 24)
    assert list(a.construction.entity("teeth 1").points) == plain
    assert not cut_flank(Gear(7, ToothSystem(0.010, math.radians(30.0)))).severed
