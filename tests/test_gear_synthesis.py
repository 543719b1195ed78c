"""Tooth numbers from a wanted ratio (issue 24): every candidate the search returns is drawn as a train
and solved by the tabular method (not the search's own formula), laid out (the ring concentric, a reverted
train's shafts coaxial) and, with n planets, assembled and cleared by the closed forms; and no better
candidate exists (brute force over a small range)."""

from __future__ import annotations

import math

import pytest

from constructions.errors import ConstructionError
from constructions.gears.planets import check_planets
from constructions.gears.synthesis import planetary_ratio, planetary_teeth, reverted_teeth
from constructions.gears.trains import Given, Train, TrainGear, TrainMesh, layout, solve_train

DEG = math.pi / 180


def planetary(ns, np_, nr, n):
    return Train((TrainGear("S", ns, "S"), TrainGear("P", np_, "P", "C"), TrainGear("R", nr, "R", internal=True)),
                 (TrainMesh("S", "P"), TrainMesh("P", "R")), 0.002, 20 * DEG, planets=n)


@pytest.mark.parametrize("ratio, held, driven, output, planets", [
    (5.0, "R", "S", "C", 3), (5.5, "R", "S", "C", 4), (1.4, "S", "R", "C", 3), (-3.2, "C", "S", "R", 1),
    (0.2, "R", "C", "S", 3), (4.1, "R", "S", "C", 5)])
def test_planetary_candidates_solve_to_the_ratio_they_claim(ratio, held, driven, output, planets):
    found = planetary_teeth(ratio, held, driven, output, planets=planets, most=120)
    assert found
    for c in found:
        assert c.ring == c.sun + 2 * c.planet                 # concentric
        t = planetary(c.sun, c.planet, c.ring, planets)
        layout(t)                                             # raises if the planet does not fit
        sol = solve_train(t, (Given(held, 0.0), Given(driven, 1.0)))
        assert sol.speeds[driven] / sol.speeds[output] == pytest.approx(c.ratio, rel=1e-12)
        assert abs(c.ratio - ratio) / abs(ratio) == pytest.approx(abs(c.error), abs=1e-12) and abs(c.error) <= 0.01
        pc = check_planets(t)
        assert pc.assembles and pc.clear
        assert all(17 <= n <= 120 for n in (c.sun, c.planet, c.ring))
    errors = [abs(c.error) for c in found]
    assert errors == sorted(errors)


def test_no_planetary_candidate_is_better_than_the_first():
    """Brute force over every sun and planet from 17 to 60 with the ring from 17 to 100."""
    wanted = 6.37
    first = planetary_teeth(wanted, planets=3, most=100)[0]
    best = min(abs((2 + 2 * p / s) - wanted) for s in range(17, 61) for p in range(17, 61)
               if s + 2 * p <= 100 and (2 * s + 2 * p) % 3 == 0 and (s + p) * math.sin(math.pi / 3) > p + 2)
    assert abs(first.ratio - wanted) == pytest.approx(best, abs=1e-12)


def test_the_notes_ring_held_ratio():
    """Ring held, sun in, carrier out: n_S/n_C = 1 + N_R/N_S."""
    assert planetary_ratio(20, 80, "R", "S", "C") == pytest.approx(5.0, rel=1e-15)
    assert planetary_ratio(20, 80, "C", "S", "R") == pytest.approx(-4.0, rel=1e-15)
    assert planetary_ratio(20, 80, "S", "C", "R") == pytest.approx(0.8, rel=1e-15)


@pytest.mark.parametrize("ratio", [12.0, 9.5, 2.7, 30.0])
def test_reverted_candidates_are_coaxial_and_give_the_ratio(ratio):
    found = reverted_teeth(ratio, most=100)
    assert found
    for c in found:
        n1, n2, n3, n4 = c.teeth
        assert n1 + n2 == n3 + n4
        t = Train((TrainGear("1", n1, "a"), TrainGear("2", n2, "b"), TrainGear("3", n3, "b"), TrainGear("4", n4, "c")),
                  (TrainMesh("1", "2", 90 * DEG), TrainMesh("3", "4", -90 * DEG)), 0.003, 20 * DEG, (("a", "c"),))
        layout(t)                                             # raises unless a and c are coaxial
        sol = solve_train(t, (Given("a", 1.0),))
        assert 1.0 / sol.speeds["c"] == pytest.approx(c.ratio, rel=1e-12)
        assert abs(c.ratio - ratio) / ratio <= 0.01


def test_no_reverted_candidate_is_better_than_the_first():
    wanted = 5.37
    first = reverted_teeth(wanted, least=17, most=45)[0]
    best = min(abs(n2 * n4 / (n1 * n3) - wanted) for n1 in range(17, 46) for n2 in range(17, 46)
               for n3 in range(17, 46) if 17 <= n1 + n2 - n3 <= 45 for n4 in (n1 + n2 - n3,))
    assert abs(first.ratio - wanted) == pytest.approx(best, abs=1e-12)


def test_an_impossible_ratio_is_one_sentence():
    with pytest.raises(ConstructionError, match="no sun, planet and ring from 17 to 150 teeth give 1.5 within 1%"):
        planetary_teeth(1.5)                                  # ring held, sun in: always above 2
    with pytest.raises(ConstructionError, match="held, driven and output must be"):
        planetary_teeth(3.0, held="S", driven="S")
    with pytest.raises(ConstructionError, match="positive"):
        reverted_teeth(-2.0)
