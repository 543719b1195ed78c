"""A linkage over its whole cycle on a sheet (analyses = ["sweep"]): charts against the crank angle, the
transmission angle whose extremes are the notes' crank-along-the-frame positions, coupler curves broken at
gaps, and a warning where the linkage cannot be assembled."""

from __future__ import annotations

import math

import numpy as np
import pytest

from constructions.entities import Chart, Curve, Diagram
from constructions.mechanisms.classify import classify_four_bar
from constructions.mechanisms.cycle import BAND, one_turn, transmission_angles
from constructions.sweep import sweep
from drafting.layout.chart import DEGREE_STEPS, ticks
from drafting.scene.reader import load_scene, parse_scene
from drafting.study.study import Study

from paths import GALLERY
CYCLE = GALLERY / "cycle-four-bar.toml"


def test_transmission_extremes_from_the_sweep_are_the_crank_along_the_frame():
    """Swept finely, the transmission angle never passes the classifier's extremes, and at the crank
    angles the notes name (crank along the frame) the sweep's value equals them to 1e-9."""
    sc = load_scene(CYCLE)
    m, k = sc.mechanism, classify_four_bar(sc.mechanism)
    fine = sc.angle + 2 * math.pi * np.arange(7200) / 7200
    mu = transmission_angles(k, sweep(m, fine, sc.omega))
    assert mu.min() >= k.transmission_min - 1e-12 and mu.max() <= k.transmission_max + 1e-12
    at = sweep(m, np.array([k.transmission_min_at, k.transmission_max_at]), sc.omega)
    lo, hi = transmission_angles(k, at)
    assert lo == pytest.approx(k.transmission_min, rel=1e-9) and hi == pytest.approx(k.transmission_max, rel=1e-9)
    assert mu.min() == pytest.approx(k.transmission_min, rel=1e-4)       # 0.05 deg steps, flat at the extreme


def test_the_cycle_sheet_has_its_charts_and_the_coupler_curve():
    s = Study(load_scene(CYCLE)).run()
    charts = {e.diagram.name: e for e in s.construction.entities() if isinstance(e, Chart)}
    assert set(charts) == {"Output angle", "Angular velocities", "Angular accelerations", "Transmission angle"}
    assert charts["Transmission angle"].bands == (BAND,)
    assert {x.label for x in charts["Angular velocities"].series} == {"\u03c9_3", "\u03c9_4"}
    w3 = charts["Angular velocities"].series[0]
    # over one turn from 0 to 360 deg (the sweep starts at the drawn pose, 60 deg)
    assert len(w3.x) == 361 and w3.x[0] == 0.0 and w3.x[-1] == 2 * math.pi and s.scene.angle != 0
    assert all(b > a for a, b in zip(w3.x, w3.x[1:])) and w3.y[0] == w3.y[-1]
    # the chart's omega_3 at the drawn angle is the polygon's
    at = min(range(len(w3.x)), key=lambda j: abs(w3.x[j] - s.scene.angle))
    assert w3.x[at] == pytest.approx(s.scene.angle, abs=1e-12)
    assert w3.y[at] == pytest.approx(s.computed("velocity").angular[3], rel=1e-9)
    paths = [e for e in s.construction.entities(Diagram.SPACE) if isinstance(e, Curve)]
    assert len(paths) == 1 and paths[0].closed and paths[0].label == "path of D"
    assert "sweep over the cycle" in s.ran and s.to_json()["sweep"]["gaps_deg"] == []


def test_a_linkage_that_cannot_turn_fully_has_gaps_and_a_warning():
    """A longer crank: over part of the turn the linkage cannot close; the charts carry NaN there, the
    coupler curve is broken into pieces that never bridge the gap, and the sheet says where."""
    text = CYCLE.read_text().replace("length = 20\n", "length = 50\n", 1)
    s = Study(parse_scene(text, GALLERY / "part.toml")).run()
    res = s.computed("sweep").result
    assert 0 < res.assembles.sum() < res.thetas.size
    charts = {e.diagram.name: e for e in s.construction.entities() if isinstance(e, Chart)}
    mu = np.array(charts["Transmission angle"].series[0].y)
    order, _ = one_turn(tuple(res.thetas))           # the charts' order of the sweep's angles
    assembles = res.assembles[order]
    # where coupler and rocker line up (mu 0 or 180 deg) the rocker cannot be driven: no finite speed
    dead = assembles & (np.minimum(mu, math.pi - mu) < 1e-6)
    for c in charts.values():
        for ser in c.series:
            y = np.array(ser.y)
            assert np.isnan(y[~assembles]).all() and np.isfinite(y[assembles & ~dead]).all()
    paths = [e for e in s.construction.entities(Diagram.SPACE) if isinstance(e, Curve)]
    runs = int(np.count_nonzero(np.diff(res.assembles.astype(int)) == -1)) + int(res.assembles[-1])
    assert len(paths) == runs >= 1
    assert all(not p.closed for p in paths)
    x, y = res.positions["D"]
    for p in paths:                                 # each piece is one run of assembled angles, in order
        first = int(np.flatnonzero(np.isclose(x, p.points[0].x) & np.isclose(y, p.points[0].y))[0])
        assert res.assembles[first:first + len(p.points)].all()
    assert any("cannot be assembled" in w and "gaps" in w for w in s.warnings)


def test_degree_axes_tick_in_divisions_of_a_turn():
    assert ticks(70.0, 430.0, 200.0, 14.0, DEGREE_STEPS) == (60.0, 450.0, 30.0)
    assert ticks(70.0, 430.0, 100.0, 14.0, DEGREE_STEPS) == (0.0, 450.0, 90.0)
    assert ticks(0.0, 1.0, 100.0, 14.0) == (0.0, 1.0, 0.2)


def test_limit_positions_drawn_are_the_ends_of_the_rockers_swing():
    """The limit positions (crank and coupler in line, by construction) are where the sweep's rocker angle
    turns back: at their crank angles the sweep puts C there to 1e-9, and the swing drawn is the chart's
    range."""
    from constructions.entities import AngleMark, Point
    s = Study(load_scene(CYCLE)).run()
    k = s.get("classification")
    res = s.computed("sweep").result
    at = sweep(s.scene.mechanism, np.array([lp.crank_angle for lp in k.limit_positions]), s.scene.omega)
    for i, lp in enumerate(k.limit_positions):
        cx, cy = (np.asarray(v)[i] for v in at.positions["C"])
        assert math.hypot(cx - lp.C.x, cy - lp.C.y) < 1e-9 * s.scene.mechanism.size
    swing = next(e for e in s.construction.entities(Diagram.SPACE) if isinstance(e, AngleMark) and e.name == "rocker swing")
    chart = next(e for e in s.construction.entities() if isinstance(e, Chart) and e.diagram.name == "Output angle")
    y = np.array(chart.series[0].y)
    assert swing.end_angle - swing.start_angle == pytest.approx(y.max() - y.min(), abs=1e-4)
    labels = {e.label for e in s.construction.entities(Diagram.SPACE) if isinstance(e, Point)}
    assert {"C'", "C''"} <= labels


@pytest.mark.parametrize("start_deg, closed", [(60.0, True), (60.5, True), (0.0, True), (-30.0, True), (350.0, False)])
def test_a_chart_runs_over_one_turn_from_0_to_360_deg(start_deg, closed):
    """The sweep starts at the drawn pose; its charts are drawn over the turn from 0: every pose once (the
    closing sample is the first pose again), in order of the crank angle, and where a pose lies at 0 deg
    it closes the curve at 360 deg."""
    n = 36
    th = tuple(math.radians(start_deg) + 2 * math.pi * np.arange(n + 1 if closed else n) / n)
    order, xs = one_turn(th)
    on_grid = (start_deg % 10.0) == 0.0
    assert sorted(set(order)) == list(range(n)) and len(order) == n + on_grid
    assert all(b > a for a, b in zip(xs, xs[1:])) and 0.0 <= xs[0] and xs[-1] <= 2 * math.pi
    if on_grid:
        assert (xs[0], xs[-1]) == (0.0, 2 * math.pi)
    else:
        assert xs[0] == pytest.approx(math.radians(0.5), abs=1e-12) and xs[-1] == pytest.approx(math.radians(350.5))
    for i, x in zip(order, xs):
        d = abs(x - th[i]) % (2 * math.pi)
        assert min(d, 2 * math.pi - d) < 1e-12                       # the same pose
