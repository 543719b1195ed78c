"""The geometry kernel: intersections, their three-way decisions, condition measures and digits.

Every expected value here is computed independently of ``constructions.geometry``: crossing points are
checked by distance to the curves, sides by explicit cross products, condition measures from angles
(``atan2``), and half-chords near tangency with exact rational arithmetic (``fractions``) and a
60-digit ``decimal`` square root on the very float inputs the kernel received.
"""

from __future__ import annotations

import math
from decimal import Decimal, localcontext
from fractions import Fraction

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from constructions.errors import ConstructionError, DegenerateInput
from constructions.geometry import (Circle, Contact, Line, Side, Tolerance, Vec, intersect_circles,
                                    intersect_line_circle, intersect_lines)

EPS = 2.0 ** -52
FAST = settings(max_examples=200, deadline=None)

angles = st.floats(-math.pi, math.pi, allow_nan=False)
unit_lengths = st.floats(0.05, 1.0, allow_nan=False)       # sizes of a figure of scale L ~ 1
offsets = st.floats(-10.0, 10.0, allow_nan=False)           # translations up to 10 L

# Designed clearances, as fractions of the scene size L, with the decision each must produce.
# |gap| = 1e-12 L is rounding-level and must read as touching; 1e-6 L is a thousand tolerances away.
GAPS = {0.0: Contact.TANGENT, 1e-12: Contact.TANGENT, -1e-12: Contact.TANGENT,
        1e-6: Contact.APART, -1e-6: Contact.CROSSING, 1e-3: Contact.APART, -1e-3: Contact.CROSSING,
        0.25: Contact.APART, -0.25: Contact.CROSSING}


def cross(a: Vec, b: Vec) -> float:
    return a.x * b.y - a.y * b.x


def exact_sqrt(q: Fraction) -> float:
    """sqrt of a non-negative rational, correctly rounded to double via 60 significant digits."""
    with localcontext() as ctx:
        ctx.prec = 60
        return float(Decimal(q.numerator).sqrt() / Decimal(q.denominator).sqrt())


def F(v: float) -> Fraction:
    return Fraction(v)


# -- lines -------------------------------------------------------------------------------------------

@FAST
@given(p=st.tuples(offsets, offsets), q=st.tuples(offsets, offsets), a1=angles, a2=angles)
def test_two_lines_cross_at_one_point_and_the_condition_is_the_sine_between_them(p, q, a1, a2):
    sine = abs(math.sin(a1 - a2))
    if sine < 1e-6:
        a2 = a1 + 0.5
        sine = abs(math.sin(a1 - a2))
    la, lb = Line.at_angle(Vec(*p), a1), Line.at_angle(Vec(*q), a2)
    hit = intersect_lines(la, lb, Tolerance(10.0))
    assert hit.contact is Contact.CROSSING
    assert len(hit) == len(hit.points) == 1
    x = hit.points[0]
    size = 10.0 + x.norm()
    for line in (la, lb):
        assert abs(cross(line.direction, x - line.point)) <= 1e-13 * size
    assert hit.condition == pytest.approx(sine, abs=1e-14)


@FAST
@given(p=st.tuples(offsets, offsets), a=angles, along=offsets, reverse=st.booleans(),
       offset=st.sampled_from([0.0, 1e-12, 1e-6, 0.3]))
def test_parallel_lines_give_no_point_and_tell_parallel_from_coincident(p, a, along, reverse, offset):
    la = Line.at_angle(Vec(*p), a)
    # b: through a point `along` the first line, displaced `offset` square to it, same or opposite sense
    through = Vec(*p) + Vec.polar(along, a) + Vec.polar(offset, a + math.pi / 2)
    lb = Line.at_angle(through, a + math.pi if reverse else a)
    hit = intersect_lines(la, lb, Tolerance(10.0))
    assert hit.points == () and len(hit) == 0
    assert hit.condition <= 1e-9
    expected = Contact.COINCIDENT if offset <= 1e-12 else Contact.PARALLEL
    assert hit.contact is expected


def test_side_of_a_line_is_three_way_with_the_tolerance():
    line = Line.through(Vec(0.0, 0.0), Vec(2.0, 0.0))
    tol = Tolerance(2.0)
    assert line.side_of(Vec(1.0, 1e-6), tol) is Side.LEFT
    assert line.side_of(Vec(1.0, -1e-6), tol) is Side.RIGHT
    assert line.side_of(Vec(1.0, 1e-10), tol) is Side.ON
    assert line.side_of(Vec(5.0, -1e-10), tol) is Side.ON


# -- two crossings: which is first -------------------------------------------------------------------

@FAST
@given(c1=st.tuples(offsets, offsets), r1=unit_lengths, r2=unit_lengths, phi=angles,
       t=st.floats(0.05, 0.95))
def test_two_circles_cross_left_then_right_of_the_centre_line(c1, r1, r2, phi, t):
    # a centre distance strictly between |r1 - r2| and r1 + r2
    lo, hi = abs(r1 - r2), r1 + r2
    d = lo + t * (hi - lo)
    a, b = Vec(*c1), Vec(*c1) + Vec.polar(d, phi)
    L = max(r1, r2, d)
    hit = intersect_circles(Circle(a, r1), Circle(b, r2), Tolerance(L))
    assert hit.contact is Contact.CROSSING and len(hit) == 2
    left, right = hit.points
    for p in hit.points:
        assert p.distance_to(a) == pytest.approx(r1, abs=1e-12 * (L + a.norm()))
        assert p.distance_to(b) == pytest.approx(r2, abs=1e-12 * (L + a.norm()))
    assert cross(b - a, left - a) > 0 > cross(b - a, right - a)
    # the sine of the crossing angle = the sine of the angle between the two radii at the crossing
    for p in hit.points:
        between = math.atan2((p - a).y, (p - a).x) - math.atan2((p - b).y, (p - b).x)
        assert hit.condition == pytest.approx(abs(math.sin(between)), abs=1e-9)
    assert hit.gap < 0


@FAST
@given(p=st.tuples(offsets, offsets), a=angles, r=unit_lengths, frac=st.floats(-0.99, 0.99),
       along=st.floats(-3.0, 3.0))
def test_line_and_circle_cross_ahead_then_behind_along_the_line(p, a, r, frac, along):
    line = Line.at_angle(Vec(*p), a)
    centre = Vec(*p) + Vec.polar(along, a) + Vec.polar(frac * r, a + math.pi / 2)
    L = max(r, abs(along), 1.0)
    hit = intersect_line_circle(line, Circle(centre, r), Tolerance(L))
    assert hit.contact is Contact.CROSSING and len(hit) == 2
    ahead, behind = hit.points
    foot_t = line.direction.dot(centre - line.point)
    assert line.direction.dot(ahead - line.point) > foot_t > line.direction.dot(behind - line.point)
    for q in hit.points:
        assert abs(cross(line.direction, q - line.point)) <= 1e-12 * (L + centre.norm())
        assert q.distance_to(centre) == pytest.approx(r, abs=1e-12 * (L + centre.norm()))
        # sine of the angle between the line and the circle's tangent at q = |cos(line, radius)|
        radius_angle = math.atan2((q - centre).y, (q - centre).x)
        assert hit.condition == pytest.approx(abs(math.cos(radius_angle - a)), abs=1e-9)


@pytest.mark.parametrize("case, n", [
    ((Circle(Vec(0, 0), 1.0), Circle(Vec(3.0, 0), 1.0)), 0),        # apart, outside
    ((Circle(Vec(0, 0), 3.0), Circle(Vec(0.5, 0), 1.0)), 0),        # apart, inside
    ((Circle(Vec(0, 0), 1.0), Circle(Vec(0.0, 0), 2.0)), 0),        # concentric: apart, no error
    ((Circle(Vec(0, 0), 1.0), Circle(Vec(2.0, 0), 1.0)), 1),        # external tangency
    ((Circle(Vec(0, 0), 2.0), Circle(Vec(1.0, 0), 1.0)), 1),        # internal tangency
    ((Circle(Vec(0, 0), 1.0), Circle(Vec(1.0, 0), 1.0)), 2),
])
def test_circles_give_zero_one_or_two_points(case, n):
    hit = intersect_circles(*case, Tolerance(3.0))
    assert len(hit) == n
    assert hit.contact is {0: Contact.APART, 1: Contact.TANGENT, 2: Contact.CROSSING}[n]
    if n < 2:
        assert hit.condition == 0.0
    if n == 1:
        assert hit.points[0] == (Vec(2.0, 0.0) if case[0].radius == 2.0 else Vec(1.0, 0.0))


@pytest.mark.parametrize("y, n", [(1.5, 0), (-1.0, 1), (1.0, 1), (0.5, 2)])
def test_line_and_circle_give_zero_one_or_two_points(y, n):
    hit = intersect_line_circle(Line.at_angle(Vec(0.0, y), 0.0), Circle(Vec(0.0, 0.0), 1.0), Tolerance(1.0))
    assert len(hit) == n
    assert hit.contact is {0: Contact.APART, 1: Contact.TANGENT, 2: Contact.CROSSING}[n]
    if n == 1:
        assert hit.points == (Vec(0.0, y),)


# -- designed tangency and designed gaps, in rotated float coordinates --------------------------------

def _circles(kind: str, r1: float, r2: float, gap: float, phi: float, t: Vec, k: float = 1.0):
    """Two circles whose clearance is ``gap`` (>0 apart, <0 overlapping), the second centre placed at
    angle ``phi`` from the first: every coordinate rounded to floats as a user would type them."""
    if kind == "external":
        d = r1 + r2 + gap
    else:  # internal: the smaller inside the larger
        d = abs(r1 - r2) - gap
    a = Vec(t.x * k, t.y * k)
    b = Vec(t.x * k + d * k * math.cos(phi), t.y * k + d * k * math.sin(phi))
    return Circle(a, r1 * k), Circle(b, r2 * k), d


def _line_circle(r: float, gap: float, phi: float, t: Vec, along: float, k: float = 1.0):
    """A line at angle phi through t*k and a circle whose centre is r + gap from it (to its left)."""
    line = Line.at_angle(Vec(t.x * k, t.y * k), phi)
    off = Vec.polar(along, phi) + Vec.polar(r + gap, phi + math.pi / 2)
    return line, Circle(Vec((t.x + off.x) * k, (t.y + off.y) * k), r * k)


circle_kinds = st.sampled_from(["external", "internal"])
gaps = st.sampled_from(sorted(GAPS))


@st.composite
def radii(draw, kind: str):
    """(r1, r2) with L = max = big: for internal circles the smaller is 0.2..0.65 of the larger, for
    external 0.2..1, so every designed clearance of GAPS (up to 0.25 L either way) keeps its kind."""
    big = draw(unit_lengths)
    small = big * draw(st.floats(0.2, 0.65 if kind == "internal" else 1.0))
    return (big, small) if draw(st.booleans()) else (small, big)


@FAST
@given(data=st.data(), kind=circle_kinds, gap=gaps, phi=angles, t=st.builds(Vec, offsets, offsets))
def test_designed_circle_clearance_decides_tangent_apart_or_crossing(data, kind, gap, phi, t):
    r1, r2 = data.draw(radii(kind))
    L = max(r1, r2)
    c1, c2, d = _circles(kind, r1, r2, gap * L, phi, t)
    tol = Tolerance(max(L, d))
    hit = intersect_circles(c1, c2, tol)
    assert hit.contact is GAPS[gap], (kind, r1, r2, gap, phi, t)
    assert len(hit) == {Contact.TANGENT: 1, Contact.APART: 0, Contact.CROSSING: 2}[hit.contact]
    if gap >= -1e-3:   # then the designed clearance is the nearest tangency, the one reported
        assert hit.gap == pytest.approx(gap * L, abs=1e-13 * (L + t.norm()))
    if hit.contact is Contact.TANGENT:
        assert hit.condition == 0.0
        p = hit.points[0]
        # the touching point lies on both circles, on the line of centres
        assert p.distance_to(c1.center) == pytest.approx(r1, abs=2e-12 * (L + t.norm()))
        assert p.distance_to(c2.center) == pytest.approx(r2, abs=2e-12 * (L + t.norm()))
        if kind == "external":           # between the centres
            expect = c1.center + Vec.polar(r1, phi)
        else:                            # beyond the inner centre, on the far side from it
            expect = c1.center + Vec.polar(r1, phi if r1 > r2 else phi + math.pi)
        assert p.distance_to(expect) <= 1e-9 * L
    if hit.contact is Contact.CROSSING:
        assert hit.condition > 0.0


@FAST
@given(r=unit_lengths, gap=gaps, phi=angles, t=st.builds(Vec, offsets, offsets),
       along=st.floats(-2.0, 2.0))
def test_designed_line_circle_clearance_decides_tangent_apart_or_crossing(r, gap, phi, t, along):
    line, circle = _line_circle(r, gap * r, phi, t, along)
    hit = intersect_line_circle(line, circle, Tolerance(r))
    assert hit.contact is GAPS[gap]
    assert len(hit) == {Contact.TANGENT: 1, Contact.APART: 0, Contact.CROSSING: 2}[hit.contact]
    if hit.contact is Contact.TANGENT:
        p = hit.points[0]
        assert hit.condition == 0.0
        assert abs(cross(line.direction, p - line.point)) <= 1e-12 * (r + t.norm())
        assert p.distance_to(circle.center) == pytest.approx(r, abs=1e-11 * (r + t.norm()))


# -- near tangency: the half-chord keeps its digits ---------------------------------------------------
# A crossing of depth ~1e-10 L is below the default decision tolerance (1e-9 L, it would read as
# TANGENT), so these tests ask for a finer tolerance to get the half-chord at all.

FINE = dict(rel=1e-13)
DEPTH = 2.0 ** -33                          # 1.16e-10: exactly representable, as are all sums below


def _h_from_circles(hit, r1, r2, d):
    return hit.condition * r1 * r2 / d     # condition = d h / (r1 r2), rounding error ~3 ulp


@pytest.mark.parametrize("origin", [Vec(0.0, 0.0), Vec(0.375, -1.5), Vec(-7.25, 3.0)])
@pytest.mark.parametrize("offset", [(0.75, 1.0), (-1.0, 0.75), (1.25, 0.0), (0.0, -1.25),
                                    (-0.35, -1.2)])           # |offset| = 1.25 exactly (3-4-5, 7-24-25)
@pytest.mark.parametrize("kind", ["external", "internal", "internal-reversed"])
def test_circle_half_chord_at_depth_1e_10_is_exact_to_rounding(origin, offset, kind):
    a = origin
    b = Vec(origin.x + offset[0], origin.y + offset[1])
    d_exact = (F(b.x) - F(a.x)) ** 2 + (F(b.y) - F(a.y)) ** 2
    if kind == "external":
        r1, r2 = 0.5, 0.75 + DEPTH              # r1 + r2 - d = DEPTH
    elif kind == "internal":
        r1, r2 = 2.0, 0.75 + DEPTH              # d - (r1 - r2) = DEPTH
    else:
        r1, r2 = 0.75 + DEPTH, 2.0              # d - (r2 - r1) = DEPTH
    hit = intersect_circles(Circle(a, r1), Circle(b, r2), Tolerance(2.0, **FINE))
    assert hit.contact is Contact.CROSSING
    # exact: (2 d h)^2 = 4 d^2 r1^2 - (d^2 + r1^2 - r2^2)^2, all in rationals of the float inputs
    R1, R2 = F(r1), F(r2)
    h2 = (4 * d_exact * R1 ** 2 - (d_exact + R1 ** 2 - R2 ** 2) ** 2) / (4 * d_exact)
    h_exact = exact_sqrt(h2)
    d = math.sqrt(float(d_exact))
    h = _h_from_circles(hit, r1, r2, d)
    if offset == (-0.35, -1.2):                 # hypot(-0.35, -1.2) is not an exact input: 1 ulp in d
        assert h == pytest.approx(h_exact, rel=64 * EPS * 2.0 / DEPTH, abs=0)
    else:
        assert h == pytest.approx(h_exact, rel=1e-14, abs=0)
        # the points, too: their distance apart is 2h to the rounding of coordinates ~ 2 L
        assert hit.points[0].distance_to(hit.points[1]) == pytest.approx(2 * h_exact, abs=16 * EPS * 8)
        # witness that the case is hard: the textbook sqrt(r1^2 - a^2) loses about six digits here
        ax = (d * d + r1 * r1 - r2 * r2) / (2 * d)
        naive = math.sqrt(max(r1 * r1 - ax * ax, 0.0))
        assert abs(naive - h_exact) > 1e-9 * h_exact


@pytest.mark.parametrize("direction", [Vec(1.0, 0.0), Vec(0.0, 1.0), Vec(-1.0, 0.0), Vec(0.0, -1.0)])
@pytest.mark.parametrize("r", [1.0, 0.75, 3.0])
def test_line_circle_half_chord_at_depth_1e_10_is_exact_to_rounding(direction, r):
    p = Vec(0.25, -0.5)
    delta = r - DEPTH * r                         # distance of the centre from the line (exact)
    centre = p + direction * 0.625 + direction.perp() * delta
    hit = intersect_line_circle(Line(p, direction), Circle(centre, r), Tolerance(r, **FINE))
    assert hit.contact is Contact.CROSSING
    dist = F(direction.x) * (F(centre.y) - F(p.y)) - F(direction.y) * (F(centre.x) - F(p.x))
    h_exact = exact_sqrt(F(r) ** 2 - dist ** 2)
    assert hit.condition * r == pytest.approx(h_exact, rel=1e-14, abs=0)


@FAST
@given(data=st.data(), kind=circle_kinds, phi=angles, t=st.builds(Vec, offsets, offsets))
def test_rotated_near_tangency_half_chord_is_as_accurate_as_its_float_inputs_allow(data, kind, phi, t):
    """Rotated coordinates are rounded inputs; relative to the exact answer *for those inputs* the
    half-chord may lose only what the problem's conditioning (L / depth) costs: a few ulp of L."""
    r1, r2 = data.draw(radii(kind))
    L = max(r1, r2)
    depth = 1e-10 * L
    c1, c2, _ = _circles(kind, r1, r2, -depth, phi, t)
    hit = intersect_circles(c1, c2, Tolerance(L, **FINE))
    assert hit.contact is Contact.CROSSING
    d2 = (F(c2.center.x) - F(c1.center.x)) ** 2 + (F(c2.center.y) - F(c1.center.y)) ** 2
    R1, R2 = F(c1.radius), F(c2.radius)
    h_exact = exact_sqrt((4 * d2 * R1 ** 2 - (d2 + R1 ** 2 - R2 ** 2) ** 2) / (4 * d2))
    d = math.sqrt(float(d2))
    h = _h_from_circles(hit, c1.radius, c2.radius, d)
    # |dh| <= (few ulp of L) * L / h  <=>  relative error <= few eps * L^2 / h^2 ~ few eps L / depth
    size = L + t.norm()
    assert abs(h - h_exact) <= 16 * EPS * size * L / h_exact


# -- scale invariance ---------------------------------------------------------------------------------

@FAST
@given(data=st.data(), which=st.sampled_from(["external", "internal", "line"]), gap=gaps, phi=angles,
       t=st.builds(Vec, st.floats(-3, 3), st.floats(-3, 3)), along=st.floats(-1.0, 1.0))
def test_scaling_a_figure_by_1e3_or_1e_minus3_keeps_every_decision(data, which, gap, phi, t, along):
    r1, r2 = data.draw(radii("external" if which == "line" else which))
    L = max(r1, r2)
    results = {}
    for k in (1.0, 1e-3, 1e3):
        if which == "line":
            line, circle = _line_circle(r1, gap * r1, phi, t, along, k)
            hit = intersect_line_circle(line, circle, Tolerance(r1 * k))
        else:
            c1, c2, d = _circles(which, r1, r2, gap * L, phi, t, k)
            hit = intersect_circles(c1, c2, Tolerance(max(L, d) * k))
        results[k] = hit
    base = results[1.0]
    assert base.contact is GAPS[gap]
    for k in (1e-3, 1e3):
        hit = results[k]
        assert hit.contact is base.contact
        assert len(hit) == len(base)
        assert hit.condition == pytest.approx(base.condition, rel=1e-6, abs=1e-12)
        for p, q in zip(hit.points, base.points):
            assert p.x / k == pytest.approx(q.x, abs=1e-9 * L)
            assert p.y / k == pytest.approx(q.y, abs=1e-9 * L)


@FAST
@given(p=st.tuples(offsets, offsets), q=st.tuples(offsets, offsets), a1=angles,
       turn=st.sampled_from([0.0, 1e-12, 1e-6, 0.3, math.pi / 2]))
def test_scaling_two_lines_keeps_the_decision(p, q, a1, turn):
    out = []
    for k in (1.0, 1e-3, 1e3):
        la = Line.at_angle(Vec(p[0] * k, p[1] * k), a1)
        lb = Line.at_angle(Vec(q[0] * k, q[1] * k), a1 + turn)
        out.append(intersect_lines(la, lb, Tolerance(10.0 * k)).contact)
    assert out[0] is out[1] is out[2]


# -- degenerate input --------------------------------------------------------------------------------

@pytest.mark.parametrize("a, b", [
    (Circle(Vec(1.0, 2.0), 0.5), Circle(Vec(1.0, 2.0), 0.5)),
    # coincident to rounding: centre and radius built from rotated coordinates
    (Circle(Vec(0.1, 0.2), 0.3), Circle(Vec(0.1 + 0.7 * math.cos(1.1) - 0.7 * math.cos(1.1),
                                             0.2 + 0.7 * math.sin(1.1) - 0.7 * math.sin(1.1)),
                                         0.1 + 0.2)),
])
def test_coincident_circles_raise_degenerate_input(a, b):
    with pytest.raises(DegenerateInput, match="coincident") as err:
        intersect_circles(a, b, Tolerance(1.0))
    assert isinstance(err.value, ConstructionError) and str(err.value)


@pytest.mark.parametrize("direction", [Vec(0.0, 0.0), Vec(math.nan, 1.0), Vec(math.inf, 0.0)])
def test_a_line_needs_a_direction(direction):
    with pytest.raises(DegenerateInput, match="direction"):
        Line(Vec(0.0, 0.0), direction)


def test_a_line_through_one_point_twice_is_degenerate():
    with pytest.raises(DegenerateInput, match="coincident points"):
        Line.through(Vec(0.3, 0.4), Vec(0.3, 0.4))


@pytest.mark.parametrize("radius", [0.0, -1.0, math.nan, math.inf])
def test_a_circle_needs_a_positive_radius(radius):
    with pytest.raises(DegenerateInput, match="positive radius") as err:
        Circle(Vec(0.0, 0.0), radius)
    assert repr(radius) in str(err.value)


def test_zero_vector_has_no_direction_and_a_scene_needs_a_size():
    with pytest.raises(DegenerateInput, match="direction"):
        Vec(0.0, 0.0).unit()
    for size in (0.0, -1.0, math.nan, math.inf):
        with pytest.raises(DegenerateInput, match="scene size"):
            Tolerance(size)


# -- regressions ---------------------------------------------------------------------------------------

def test_a_nearly_unit_direction_is_normalised_before_it_measures_distances():
    """Found by this suite: a direction of norm 1 + 9e-13 used to be kept un-normalised (the cut was
    |n - 1| > 1e-12), which put the depth of a 1e-10 L crossing off by 1 % and its half-chord by 0.4 %."""
    r, y = 1.0, 1.0 - DEPTH
    line = Line(Vec(0.0, 0.0), Vec(1.0 + 2.0 ** -40, 0.0))
    hit = intersect_line_circle(line, Circle(Vec(0.3, y), r), Tolerance(1.0, **FINE))
    h_exact = exact_sqrt(F(r) ** 2 - F(y) ** 2)   # the line is y = 0 whatever the direction's length
    assert hit.condition * r == pytest.approx(h_exact, rel=1e-12, abs=0)


def test_roots_and_inverse_trig_of_computed_values_hold_at_their_limits():
    """A computed cosine a rounding past 1 (a contact on the base circle, C exactly r_b1 + r_b2) or a
    squared length a rounding below 0 gives the limit's value, not a math domain error (issue 22)."""
    from constructions.geometry import acos_clamped, asin_clamped, sqrt_nonneg
    assert sqrt_nonneg(-1e-18) == 0.0 and sqrt_nonneg(4.0) == 2.0
    assert acos_clamped(1.0 + 2e-16) == 0.0 and acos_clamped(-1.0 - 2e-16) == math.pi
    assert asin_clamped(1.0 + 2e-16) == math.pi / 2 and asin_clamped(0.5) == math.asin(0.5)
    r, e = 0.03, 0.03 * (1 + 1e-16)
    assert sqrt_nonneg(r * r - e * e) == 0.0
