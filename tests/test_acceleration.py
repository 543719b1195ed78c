"""The acceleration polygon against the analytic solution, the time derivative of the velocity polygon,
the notes' worked examples and the hard cases (near and at a toggle, scaled mechanisms)."""

from __future__ import annotations

import math

import pytest
from hypothesis import HealthCheck, assume, given, settings, strategies as st

from constructions.check import analytic_solution, analytic_values, compare
from constructions.entities import Diagram, Role
from constructions.errors import IndeterminatePosition
from constructions.geometry import Vec
from constructions.mechanisms.model import Attached, Link, Mechanism, Slide
from constructions.mechanisms.pose import locate
from constructions.polygons.acceleration import acceleration_polygon
from constructions.polygons.velocity import velocity_polygon
from constructions.record import StepKind
from test_compound import toggle_linkage
from mechanisms import four_bar, slider_crank
from strategies import four_bars, slider_cranks

alphas = st.one_of(st.just(0.0), st.floats(-5000.0, 5000.0))


def solve(m, theta, omega, alpha):
    va = velocity_polygon(m, locate(m, theta), omega)
    return va, acceleration_polygon(m, va, alpha)


def assert_graphical_equals_analytic(m, theta, omega, alpha):
    va, aa = solve(m, theta, omega, alpha)
    a = analytic_solution(m, theta, omega, alpha)
    assert a is not None
    rows = compare(va.measured(m) + aa.measured(m), analytic_values(m, a), {**va.scales(), **aa.scales()})
    acc = [r for r in rows if r.kind in ("acceleration", "angular acceleration")]
    assert acc and all(r.analytic is not None for r in acc)
    bad = [(r.name, r.relative, r.tolerance) for r in rows if not r.agrees]
    assert not bad
    return va, aa, rows


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(case=four_bars(), alpha=alphas)
def test_random_four_bars_accelerate_as_the_vector_loop_says(case, alpha):
    m, theta, omega = case
    va, aa, rows = assert_graphical_equals_analytic(m, theta, omega, alpha)
    # well conditioned (|sine| >= 0.06 by construction): the tolerance is the plain 1e-9
    assert all(r.tolerance == pytest.approx(1e-9) for r in rows if r.kind == "acceleration")


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(case=slider_cranks(), alpha=alphas)
def test_random_slider_cranks_accelerate_as_the_vector_loop_says(case, alpha):
    m, theta, omega = case
    va, aa, _ = assert_graphical_equals_analytic(m, theta, omega, alpha)
    g = m.slides[0].line.direction
    assert abs(g.cross(aa.accelerations["C"])) <= 1e-12 * max(1.0, aa.accelerations["C"].norm())   # along the guide


@pytest.mark.parametrize("angle_deg", [0.0, 60.0, 135.0, 300.0])
@pytest.mark.parametrize("alpha", [0.0, 750.0, -2000.0])
def test_compound_mechanism_against_the_dyad_chain(angle_deg, alpha):
    m = toggle_linkage()
    va, aa, rows = assert_graphical_equals_analytic(m, math.radians(angle_deg), -100.0, alpha)
    assert {"A_C", "A_D", "A_DC^t", "alpha_2", "alpha_3", "alpha_4"} <= {r.name for r in rows}
    assert [e.text(marks=False) for e in aa.construction.equations] == [
        "A_C^n + A_C^t = A_B^n + A_B^t + A_CB^n + A_CB^t", "A_D = A_C + A_DC^n + A_DC^t"]


def _state(m, theta, omega, alpha):
    return solve(m, theta, omega, alpha)


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(case=st.one_of(four_bars(), slider_cranks()), alpha=alphas)
def test_accelerations_are_the_time_derivative_of_the_velocity_polygon(case, alpha):
    """Central differences in time of the graphical velocities, theta(t) = theta + omega t + alpha t^2/2
    and omega(t) = omega + alpha t, Richardson-extrapolated from steps h and h/2 (error O(h^4)).  The
    higher time derivatives grow like 1/s^9 as the sine s of the trial-line crossing falls, so the
    comparison is made where s >= 0.3 (the near-singular behaviour has tests of its own): with
    h = 1e-3/max(|omega_k|, sqrt|alpha|) the truncation is ~(omega h)^4 / s^9 <= 5e-8 of the scale and the rounding
    ~eps/(omega h s) ~ 1e-12."""
    m, theta, omega = case
    va, aa = solve(m, theta, omega, alpha)
    assume(va.worst_condition >= 0.3)

    def derivative(h):
        plus, _ = solve(m, theta + omega * h + alpha * h * h / 2, omega + alpha * h, alpha)
        minus, _ = solve(m, theta - omega * h + alpha * h * h / 2, omega - alpha * h, alpha)
        lin = {n: (plus.velocities[n] - minus.velocities[n]) / (2 * h) for n in aa.accelerations}
        ang = {n: (plus.angular[n] - minus.angular[n]) / (2 * h) for n in aa.angular}
        return lin, ang
    h = 1e-3 / max(max(abs(w) for w in va.angular.values()), math.sqrt(abs(alpha)))   # the fastest link
    (l1, w1), (l2, w2) = derivative(h), derivative(h / 2)
    tol = 1e-7
    ref = max(a.norm() for a in aa.accelerations.values())
    for name, a in aa.accelerations.items():
        fd = (l2[name] * 4 - l1[name]) / 3
        assert fd.distance_to(a) <= tol * ref, name
    wref = max(max(abs(x) for x in aa.angular.values()), abs(alpha), omega * omega)
    for n, al in aa.angular.items():
        fd = (4 * w2[n] - w1[n]) / 3
        assert fd == pytest.approx(al, abs=tol * wref)


def notes_slider_crank():
    """The notes' slider-crank (velocity and acceleration Examples 1, 2): O1B 50 mm, BC 94 mm, in line."""
    return slider_crank((0.0, 0.0), 0.050, 0.094, (0.0, 0.0), 0.0, 1)


@pytest.mark.parametrize("alpha,a_cb_t,a_c,alpha_2", [(0.0, 5180.0, 520.0, 55.1), (40.0, 4400.0, 1750.0, 46.8)])
def test_notes_examples_1_and_2_within_drawing_accuracy(alpha, a_cb_t, a_c, alpha_2):
    """Crank at 70 deg, omega_1 = 10 rad/s CCW (V_B = 500 mm/s): the notes' answers within 2 %."""
    m = notes_slider_crank()
    va, aa, _ = assert_graphical_equals_analytic(m, math.radians(70), 10.0, alpha)
    assert aa.tangential[("C", "B")].norm() * 1e3 == pytest.approx(a_cb_t, rel=0.02)
    assert aa.accelerations["C"].norm() * 1e3 == pytest.approx(a_c, rel=0.02)
    assert aa.angular[2] == pytest.approx(alpha_2, rel=0.02)              # CCW: positive
    assert aa.normal[("B", "O1")].norm() == pytest.approx(5.0, rel=1e-12)   # omega^2 O1B = 5000 mm/s^2


def test_the_record_reads_as_the_notes_draw_it():
    m = notes_slider_crank()
    _, aa = solve(m, math.radians(70), 10.0, 40.0)
    rec = aa.construction
    eq = rec.equations[0]
    assert eq.text() == ("A_C(\u00d7\u2713) = A_B^n(\u2713\u2713) + A_B^t(\u2713\u2713) + A_CB^n(\u2713\u2713) "
                         "+ A_CB^t(\u00d7\u2713)")
    assert eq.unknowns == 2
    words = [s.words for s in rec.steps]
    assert words[1] == "Choose the pole O_a." and words[2].startswith("Choose the acceleration scale")
    assert rec.steps[2].value("s").kind == "scale" and rec.steps[2].value("s").value is None
    # the notes' order: A_B^n then A_B^t from O_a, then A_CB^n from b', the trial lines, the crossing c'
    names = [e.name for s in rec.steps for e in s.entities]
    assert names.index("A_B^n") < names.index("A_B^t") < names.index("A_CB^n") < names.index("trial A_CB^t") \
        < names.index("trial A_C") < names.index("acceleration image C")
    assert {e.diagram for e in rec.entities()} == {Diagram.ACCELERATION}
    answer = rec.steps[-1]
    assert answer.kind is StepKind.ANSWER and "\u03b1_2" in answer.words and "counter-clockwise" in answer.words
    assert answer.value("al0").value == pytest.approx(aa.angular[2], rel=1e-12)


def test_acceleration_image_is_the_link_turned_and_scaled():
    """b'c'd' is BCD turned by pi - atan(alpha/omega^2) (for alpha, omega^2 > 0 ... the notes' figure)
    and scaled by sqrt(omega^4 + alpha^2): every side of the image is that multiple of the link's side."""
    m = four_bar((0.0, 0.0), (0.08, 0.0), 0.03, 0.09, 0.07, 1, [Attached("D", 2, "B", 0.05, 0.6)])
    va, aa, _ = assert_graphical_equals_analytic(m, math.radians(50), 12.0, 300.0)
    P, A = va.pose.positions, aa.accelerations
    w, al = va.angular[2], aa.angular[2]
    k = math.hypot(w * w, al)
    for p, q in (("B", "C"), ("B", "D"), ("C", "D")):
        assert (A[q] - A[p]).norm() == pytest.approx(k * (P[q] - P[p]).norm(), rel=1e-12)
        # A_qp = (alpha k x - omega^2) r_qp: r turned by atan2(alpha, -omega^2)
        turn = (A[q] - A[p]).angle() - (P[q] - P[p]).angle()
        assert math.remainder(turn - math.atan2(al, -w * w), 2 * math.pi) == pytest.approx(0.0, abs=1e-12)
    assert any(e.role is Role.IMAGE for e in aa.construction.entities())


# -- hard cases ------------------------------------------------------------------------------------------

def toggle_four_bar(delta):
    """A four-bar whose coupler and rocker are within ``delta`` rad of in line at crank angle 90 deg."""
    b = Vec(0.0, 0.03)
    c = b + Vec.polar(0.09, math.radians(10))
    o2 = c + Vec.polar(0.06, math.radians(10) + delta)        # rocker nearly along the coupler
    return four_bar((0.0, 0.0), o2.as_tuple(), 0.03, 0.09, 0.06, 1)


def test_near_a_toggle_values_come_with_a_warning_and_an_estimate():
    m = toggle_four_bar(math.radians(0.3))
    va, aa = solve(m, math.pi / 2, 10.0, 5.0)
    assert any("Near a toggle at C (transmission angle" in w for w in aa.warnings)
    assert aa.relative_error_estimate > 1e-9
    a = analytic_solution(m, math.pi / 2, 10.0, 5.0)
    rows = compare(va.measured(m) + aa.measured(m), analytic_values(m, a), {**va.scales(), **aa.scales()})
    assert all(r.agrees for r in rows)                     # within the widened, stated tolerance
    assert max(r.tolerance for r in rows) > 1e-9


def test_at_a_toggle_the_position_is_named_and_no_number_given():
    m = toggle_four_bar(0.0)
    with pytest.raises(IndeterminatePosition) as e:
        solve(m, math.pi / 2, 10.0, 5.0)
    assert e.value.kind in ("toggle", "change point") and "transmission angle" in str(e.value)


@pytest.mark.parametrize("k", [1e-3, 1e3])
def test_a_scaled_mechanism_takes_the_same_decisions(k):
    base = toggle_linkage()
    scaled = Mechanism({n: p * k for n, p in base.ground.items()},
                       tuple(Link(l.number, l.joints, l.length * k) for l in base.links),
                       tuple(Slide(s.number, s.joint, s.through * k, s.angle) for s in base.slides),
                       (), base.crank, base.branches)
    for deg in (0.0, 60.0, 135.0, 300.0):
        _, a = solve(base, math.radians(deg), -100.0, 300.0)
        _, b = solve(scaled, math.radians(deg), -100.0, 300.0)
        assert len(a.warnings) == len(b.warnings)
        ref = max(x.norm() for x in a.accelerations.values())
        for n, x in a.accelerations.items():
            assert (b.accelerations[n] / k).distance_to(x) <= 1e-9 * ref
        for n, al in a.angular.items():
            assert b.angular[n] == pytest.approx(al, rel=1e-9, abs=1e-9 * max(abs(v) for v in a.angular.values()))
