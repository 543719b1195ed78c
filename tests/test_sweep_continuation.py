"""The constraint continuation a block of angles at a time (constructions.mechanisms.constraint_continuation
and constraint_batch): the same sweep as the one-pose solver angle by angle -- every value to 1e-9 of its
kind's largest, the same gaps (where nothing assembles, and at singular positions) -- on the gallery's
slotted lever and ternary six-bars, over fine and coarse turns and at random angles; the stacked
equations equal to the one-pose ones; progress heard all along."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from constructions.errors import CannotAssemble, ConstructionError, IndeterminatePosition
from constructions.mechanisms import constraint_batch as batch
from constructions.mechanisms.constraint_continuation import LONGEST, continue_constraints
from constructions.mechanisms.constraint_equations import gamma, jacobian, residual, scales
from constructions.mechanisms.constraint_kinematics import solve_constraints
from constructions.mechanisms.constraint_model import build_model
from constructions.mechanisms.pose import locate
from constructions.sweep import sweep
from drafting.scene.reader import load_scene
from mechanisms import quick_return, watt_six_bar

GALLERY = Path(__file__).resolve().parent.parent / "gallery"
SCENES = ("quick-return-slotted-lever", "watt-six-bar", "stephenson-six-bar")


def one_by_one(m, th, omega, alpha):
    """The continuation angle by angle with the one-pose solver (the sweep before the blocks): each pose
    from the previous one, the first and the first after a gap from the construction."""
    states, guess = [], None
    for t in th:
        t = float(t)
        st = None
        if guess is None:
            try:
                guess = locate(m, t).positions
            except ConstructionError:
                states.append(None)
                continue
        try:
            st = solve_constraints(m, t, omega, alpha, guess)
        except (CannotAssemble, IndeterminatePosition):
            guess = None
        else:
            guess = st.positions
        states.append(st)
    return states


def assert_same(s, states, rel=1e-9):
    ok = np.array([st is not None for st in states])
    assert np.array_equal(np.asarray(s.assembles), ok)
    assert s.model == "constraint equations"
    for kind in ("positions", "velocities", "accelerations"):
        ref = {n: np.array([(getattr(st, kind)[n].x, getattr(st, kind)[n].y) if st else (np.nan, np.nan)
                            for st in states]) for n in getattr(s, kind)}
        scale = max(float(np.nanmax(np.abs(r), initial=0.0)) for r in ref.values()) or 1.0
        for n, (x, y) in getattr(s, kind).items():
            got = np.column_stack([x, y])[ok]
            assert np.all(np.isfinite(got)) and np.max(np.abs(got - ref[n][ok]), initial=0.0) <= rel * scale, (kind, n)
    for kind in ("angular", "angular_acceleration"):
        ref = {k: np.array([getattr(st, kind)[k] if st else np.nan for st in states]) for k in getattr(s, kind)}
        scale = max(float(np.nanmax(np.abs(r), initial=0.0)) for r in ref.values()) or 1.0
        for k, w in getattr(s, kind).items():
            assert np.max(np.abs(w[ok] - ref[k][ok]), initial=0.0) <= rel * scale, (kind, k)
            assert np.all(np.isnan(w[~ok]))


@pytest.mark.parametrize("name", SCENES)
@pytest.mark.parametrize("steps", [90, 360, 1000])
def test_blocks_equal_the_one_pose_solver_over_a_turn(name, steps):
    sc = load_scene(GALLERY / f"{name}.toml")
    th = sc.angle + 2 * math.pi * np.arange(steps) / steps
    s = sweep(sc.mechanism, th, sc.omega, sc.alpha)
    assert_same(s, one_by_one(sc.mechanism, th, sc.omega, sc.alpha))
    if name == "stephenson-six-bar":             # it does not assemble over part of the turn
        assert 0 < (~s.assembles).sum() < steps


@pytest.mark.parametrize("name", SCENES)
def test_blocks_equal_the_one_pose_solver_at_random_angles(name):
    """Sorted, with clusters and jumps; and in random order, where most poses are solved one by one."""
    sc = load_scene(GALLERY / f"{name}.toml")
    rng = np.random.default_rng(SCENES.index(name))
    th = np.sort(np.concatenate([rng.uniform(0, 2 * math.pi, 150), rng.uniform(1.0, 1.01, 150),
                                 rng.uniform(4.0, 4.3, 150)]))
    assert_same(sweep(sc.mechanism, th, sc.omega, sc.alpha), one_by_one(sc.mechanism, th, sc.omega, sc.alpha))
    th = rng.uniform(-2 * math.pi, 4 * math.pi, 60)
    assert_same(sweep(sc.mechanism, th, sc.omega, sc.alpha), one_by_one(sc.mechanism, th, sc.omega, sc.alpha))


def test_blocks_keep_the_branch_and_the_gaps_of_other_mechanisms():
    """A pin in a slot, an offset slot, and a quick-return whose lever passes its dead centres; a crank
    turning backwards with an angular acceleration."""
    for m in (quick_return(offset=0.01, branch=-1, block=False), quick_return(ram=False), watt_six_bar()):
        th = np.linspace(3.0, 3.0 - 2 * math.pi, 400)
        assert_same(sweep(m, th, -7.0, 30.0), one_by_one(m, th, -7.0, 30.0))


def test_nothing_assembles_gives_gaps_everywhere():
    sc = load_scene(GALLERY / "stephenson-six-bar.toml")
    th = sc.angle + 2 * math.pi * np.arange(360) / 360
    gap = th[~sweep(sc.mechanism, th, sc.omega, sc.alpha).assembles]
    s = sweep(sc.mechanism, gap, sc.omega, sc.alpha)
    assert gap.size > 10 and not s.assembles.any() and list(s.angular) == [sc.mechanism.crank]
    assert np.isnan(s.angular[1]).all() and list(s.positions) == list(sc.mechanism.ground)
    assert np.all(s.positions["O2"][0] == sc.mechanism.ground["O2"].x)


def test_progress_is_heard_all_along_a_long_sweep():
    sc = load_scene(GALLERY / "stephenson-six-bar.toml")
    n = 20000
    th = sc.angle + 2 * math.pi * np.arange(n) / n
    heard = []
    t = continue_constraints(sc.mechanism, th, sc.omega, sc.alpha, lambda done, total: heard.append((done, total)))
    done = [d for d, _ in heard]
    assert heard[0] == (0, n) and all(total == n for _, total in heard)
    assert all(b > a for a, b in zip(done, done[1:]))
    assert max(np.diff(done + [n])) <= LONGEST and t.assembles.sum() > n // 2


@pytest.mark.parametrize("make", [quick_return, watt_six_bar, lambda: quick_return(offset=0.02, block=False)])
def test_stacked_equations_equal_the_one_pose_ones(make):
    m = make()
    model = build_model(m)
    rows, cols = scales(model)
    rng = np.random.default_rng(5)
    Q = rng.normal(size=(7, model.unknowns)) * np.tile([0.1, 0.1, 3.0], model.unknowns // 3)
    Qd = rng.normal(size=Q.shape)
    th = rng.uniform(-4, 4, 7)
    r = batch.residual(model, Q, th)
    A = batch.scaled_jacobian(model, Q, rows, cols)
    g = batch.gamma(model, Q, Qd)
    for i in range(Q.shape[0]):
        np.testing.assert_allclose(r[i], residual(model, Q[i].tolist(), th[i]), rtol=0, atol=1e-15)
        np.testing.assert_allclose(A[i], rows[:, None] * jacobian(model, Q[i].tolist()) * cols, rtol=1e-15,
                                   atol=1e-15)
        np.testing.assert_allclose(g[i], gamma(model, Q[i].tolist(), Qd[i].tolist(), 0.0), rtol=1e-14, atol=1e-14)


def test_a_fine_sweep_strides_across_a_gap_and_finds_its_ends_to_one_step():
    """Across a gap a fine sweep tries the construction in strides (up to 0.05 deg) and halves back: the
    same gaps, to the step, as trying every angle -- at both ends of the Stephenson six-bar's gap."""
    from constructions.mechanisms.constraint_continuation import _skip
    sc = load_scene(GALLERY / "stephenson-six-bar.toml")
    th = sc.angle + 2 * math.pi * np.arange(720) / 720
    ok = sweep(sc.mechanism, th, sc.omega, sc.alpha).assembles
    starts = np.flatnonzero(ok[:-1] & ~ok[1:])
    ends = np.flatnonzero(~ok[:-1] & ok[1:])
    assert starts.size and ends.size
    for edge in (th[starts[0]], th[ends[0]]):
        fine = edge - math.radians(0.5) + math.radians(1.5) * np.arange(1500) / 1500     # 0.001 deg steps
        assert _skip(fine) > 10
        s = sweep(sc.mechanism, fine, sc.omega, sc.alpha)
        assert 0 < (~s.assembles).sum() < fine.size
        assert_same(s, one_by_one(sc.mechanism, fine, sc.omega, sc.alpha))
