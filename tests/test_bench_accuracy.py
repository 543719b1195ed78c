"""The accuracy-against-time benchmarks (benchmarks/sweep_step.py, continuation_tolerance.py,
html_slider.py) run at a tiny size, and each error falls as the step (or the tolerance) shrinks: a property
of the methods, never a timing."""

import math

from drafting.app.bench import benchmark
from drafting.families.linkage import family
from constructions.mechanisms import constraint_kinematics

sweep_step = benchmark("sweep_step")
continuation = benchmark("continuation_tolerance")
slider = benchmark("html_slider")


def _falls(coarse, fine):
    """Every error of the finer run below the coarser's."""
    return all(f < c for c, f in zip(coarse, fine))


def test_a_sweep_finds_its_extremes_more_closely_at_a_finer_step():
    rows, exact = sweep_step.four_bar_rows(steps=(10.0, 1.0), repeat=1)
    (_, n10, _, coarse), (_, n1, _, fine) = rows
    assert (n10, n1) == (36, 360) and _falls(coarse, fine)
    assert fine[0] < 0.01 and fine[1] < 0.01                   # deg: transmission angle, rocker's limits
    # crank + coupler 75, frame 60, rocker 45 mm: a 3-4-5 triangle, the rocker square to the frame
    assert abs(math.degrees(exact["rocker"][1]) - 90.0) < 1e-9
    rows, exact = sweep_step.slider_rows(steps=(10.0, 1.0), repeat=1)
    assert _falls(rows[0][3], rows[1][3])
    assert exact["x"][0] > exact["x"][1] > 0


def test_the_refined_extreme_is_at_least_every_sample():
    scene = sweep_step.slider_crank()
    ex = sweep_step.slider_exact(scene)
    _, got = sweep_step._slider_found(scene, sweep_step._angles(scene.angle, 0.01))
    assert got["v"] <= ex["v"] and got["a"] <= ex["a"]
    assert (ex["v"] - got["v"]) / ex["v"] < 1e-8


def test_the_continuation_is_closer_at_a_tighter_tolerance_and_restores_it():
    before = constraint_kinematics.TOLERANCE
    for name in ("crank-rocker", "quick-return"):
        data, _ = continuation.rows(name, tolerances=(1e-4, 1e-10), angles=24, repeat=1)
        (_, _, *coarse), (_, _, *fine) = data
        assert fine[1] < coarse[1] and fine[2] < coarse[2]          # velocities, accelerations
        assert fine[0] <= max(coarse[0], 1e-14)
        assert max(fine) < 1e-8                       # the quick-return's closed form agrees with the solver
    assert constraint_kinematics.TOLERANCE == before


def test_the_slider_shows_values_nearer_with_more_poses_and_restores_its_count():
    before = family.SWEEP_STEPS
    data = slider.rows(counts=(36, 72), reference=720, repeat=1)
    (n1, _, size1, coarse), (n2, _, size2, fine) = data
    assert (n1, n2) == (36, 72) and size2 > size1
    assert all(fine[k] < coarse[k] for k in slider.COLUMNS)
    assert family.SWEEP_STEPS == before


def test_a_chart_of_each_section_is_written(tmp_path):
    chart = benchmark("loglog_chart")
    m = slider.rows(counts=(36, 72), reference=720, repeat=1)
    chart.chart(slider.chart_series(m), tmp_path / "slider.svg", "card (kB)", "error")
    svg = (tmp_path / "slider.svg").read_text()
    assert svg.count("<polyline") == 5 and "coupler point D (/ frame)" in svg
    assert (tmp_path / "slider.png").stat().st_size > 1000
