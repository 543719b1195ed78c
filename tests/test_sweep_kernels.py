"""The sweep's fast kernels (constructions.sweep_kernels) against the independent oracle
(constructions.analytic): the same numbers to 1e-9 relative away from singular positions on random
mechanisms of any scale (the hypothesis strategies of test_analytic), the same gaps; chunking invisible,
the sweep's own trigonometry within 2 ulp of numpy's, the caller's buffers.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest
from hypothesis import given

from constructions import analytic as an
from constructions import sweep_kernels as sk
from constructions.analytic.states import FOURBAR_FIELDS
from constructions import sweep_threads
from constructions.sweep_kernels import chain_chunks, shared_steps, trig
from constructions.sweep_kernels import coupler_point, four_bar, slider_crank
from strategies import four_bar_dimensions, slider_crank_dimensions
from test_analytic import ANGLES, FAST, FB
from test_analytic_acceleration import toggle_linkage

#: Away from singular positions: the sine of the angle between the velocity trial lines at least this.
#: (Closer in, an acceleration is a sum of terms growing like 1/condition^3 that cancel to a moderate
#: value, and the last-ulp differences of the two trigonometries no longer stay within 1e-9 of it:
#: 3e-9 at condition 0.01 on a slider-crank with crank = coupler.)
WELL_CONDITIONED = 0.05
RTOL = 1e-9


def _kind(name: str) -> str:
    """Which quantity a field is (fields of one kind are compared on one scale)."""
    for kind, prefixes in (("velocity", ("V", "slider_speed")), ("acceleration", ("A", "slider_acceleration")),
                           ("omega", ("omega",)), ("alpha", ("alpha",)), ("condition", ("condition",))):
        if name.startswith(prefixes):
            return kind
    return "position"


def _same_as_oracle(kernel, oracle, angle_fields=()):
    """Every field of the kernel's state within RTOL of the oracle's, relative to the largest value of its
    kind (positions, velocities, ...) where the mechanism is well conditioned; the same gaps (a
    disagreement only at a tangency)."""
    differ = kernel.assembles != oracle.assembles
    assert (np.nan_to_num(np.where(oracle.assembles, oracle.condition, kernel.condition))[differ] < 1e-6).all()
    good = kernel.assembles & oracle.assembles & (oracle.condition >= WELL_CONDITIONED)
    names = [f.name for f in dataclasses.fields(oracle) if f.name != "assembles"]
    scale: dict[str, float] = {}
    for n in names:
        if n not in angle_fields and good.any():
            scale[_kind(n)] = max(scale.get(_kind(n), 0.0), float(np.abs(getattr(oracle, n)[good]).max()))
    for n in names:
        a, b = getattr(kernel, n)[good], getattr(oracle, n)[good]
        if a.size == 0:
            continue
        if n in angle_fields:
            np.testing.assert_allclose(np.remainder(a - b + math.pi, 2 * math.pi) - math.pi, 0.0, rtol=0,
                                       atol=RTOL * math.pi, err_msg=n)
        else:
            np.testing.assert_allclose(a, b, rtol=0, atol=RTOL * scale[_kind(n)], err_msg=n)
    return good


@FAST
@given(four_bar_dimensions())
def test_four_bar_kernel_matches_the_oracle(m):
    omega, alpha = 7.0, -30.0
    k, o = four_bar(ANGLES, omega, alpha, **m), an.four_bar(ANGLES, omega, alpha, **m)
    good = _same_as_oracle(k, o, ("theta2", "theta3"))
    # NaN exactly where the oracle has NaN, away from the edges of the gaps
    np.testing.assert_array_equal(np.isnan(k.VCx)[good], np.isnan(o.VCx)[good])


@FAST
@given(slider_crank_dimensions())
def test_slider_kernel_matches_the_oracle(m):
    omega, alpha = -4.0, 12.0
    _same_as_oracle(slider_crank(ANGLES, omega, alpha, **m), an.slider_crank(ANGLES, omega, alpha, **m),
                    ("theta2",))


@FAST
@given(four_bar_dimensions())
def test_coupler_point_kernel_matches_the_oracle(m):
    r = an.four_bar(ANGLES, 3.0, 5.0, **m)
    ok = r.assembles & (r.condition >= WELL_CONDITIONED)
    given = (r.Bx[ok], r.By[ok], r.VBx[ok], r.VBy[ok], r.theta2[ok], r.omega2[ok])
    acc = dict(ABx=r.ABx[ok], ABy=r.ABy[ok], alpha2=r.alpha2[ok])
    point = dict(distance=0.7 * m["coupler"], angle=0.9)
    for extra in (acc, {}):
        k, o = coupler_point(*given, **point, **extra), an.coupler_point(*given, **point, **extra)
        for f in dataclasses.fields(o):
            a, b = getattr(k, f.name), getattr(o, f.name)
            if not extra and f.name in ("ADx", "ADy"):
                assert np.isnan(a).all() and np.isnan(b).all()
            elif b.size:
                np.testing.assert_allclose(a, b, rtol=0, atol=RTOL * np.abs(b).max(), err_msg=f.name)


def test_kernels_and_oracle_agree_on_gaps_and_toggles():
    """A non-Grashof four-bar over angles beyond 2 pi, and a slider-crank whose coupler cannot always
    reach its guide: the same gaps, the same toggles (NaN velocities), the same numbers elsewhere."""
    th = np.linspace(-7.0, 7.0, 1001)
    fb = dict(crank_pivot=(0.0, 0.0), rocker_pivot=(1.0, 0.0), crank=0.8, coupler=0.5, rocker=0.6, branch=-1)
    sc = dict(crank_pivot=(0, 0), crank=0.8, coupler=0.5, guide_point=(0, 1), guide_angle=0.1, branch=1)
    for kernel, oracle, kw, angles in ((four_bar, an.four_bar, fb, ("theta2", "theta3")),
                                       (slider_crank, an.slider_crank, sc, ("theta2",))):
        k, o = kernel(th, 2.0, -3.0, **kw), oracle(th, 2.0, -3.0, **kw)
        np.testing.assert_array_equal(k.assembles, o.assembles)
        assert 0 < o.assembles.sum() < th.size
        _same_as_oracle(k, o, angles)
        for f in dataclasses.fields(o):
            np.testing.assert_array_equal(np.isnan(getattr(k, f.name)), np.isnan(getattr(o, f.name)), f.name)
    designed = dict(crank_pivot=(0.0, 0.0), rocker_pivot=(0.3, 0.0), crank=0.1, coupler=0.25, rocker=0.15, branch=1)
    for fn in (four_bar, an.four_bar):   # the extended toggle, crank at 180 deg: snapped, NaN velocities
        r = fn(math.pi, 1.0, **designed)
        assert bool(r.assembles) and float(r.condition) == 0.0 and math.isnan(float(r.omega2))


def test_chunking_is_invisible(monkeypatch):
    m = dict(crank_pivot=(0.0, 0.0), rocker_pivot=(1.0, 0.0), crank=0.8, coupler=0.5, rocker=0.6,
             branch=-1)
    th = np.linspace(-7.0, 7.0, 1001)           # mixed assembly, angles beyond 2 pi
    whole = four_bar(th, 2.0, **m)
    sc = slider_crank(th, 2.0, crank_pivot=(0, 0), crank=0.8, coupler=0.5, guide_point=(0, 1),
                      guide_angle=0.1, branch=1)
    monkeypatch.setattr(shared_steps, "CHUNK", 7)
    pieces = four_bar(th, 2.0, **m)
    sc2 = slider_crank(th, 2.0, crank_pivot=(0, 0), crank=0.8, coupler=0.5, guide_point=(0, 1),
                       guide_angle=0.1, branch=1)
    for a, b in ((whole, pieces), (sc, sc2)):
        for f in dataclasses.fields(a):
            np.testing.assert_array_equal(getattr(a, f.name), getattr(b, f.name), err_msg=f.name)
    # one angle at a time gives the same numbers
    for k in (0, 250, 500, 1000):
        one = four_bar(th[k], 2.0, **m)
        for f in dataclasses.fields(one):
            np.testing.assert_array_equal(getattr(one, f.name), getattr(whole, f.name)[k])


@pytest.mark.parametrize("four_bar", [sk.four_bar, an.four_bar], ids=["kernel", "oracle"])
def test_large_angles_and_crank_trig(four_bar):
    th = np.array([0.3, 0.3 + 2 * np.pi * 1000, 0.3 - 2 * np.pi * 123456, 2e6 + 0.3, -np.pi, np.pi])
    r = four_bar(th, 1.0, **FB)
    np.testing.assert_allclose(r.Bx, 0.03 * np.cos(th), rtol=0, atol=1e-17)
    np.testing.assert_allclose(r.By, 0.03 * np.sin(th), rtol=0, atol=1e-17)
    rng = np.random.default_rng(5)
    for lo, hi in ((-2 * np.pi, 2 * np.pi), (-1e5, 1e5)):
        t = rng.uniform(lo, hi, 20000)
        r = four_bar(t, 1.0, **{**FB, "crank": 1.0, "rocker_pivot": (3.0, 0.0), "coupler": 2.5,
                                "rocker": 2.0})
        assert np.abs(r.Bx - np.cos(t)).max() <= 2e-15
        assert np.abs(r.By - np.sin(t)).max() <= 2e-15


def test_link_angles_atan2_within_2_ulp_of_numpy():
    """The kernels' own atan2 (a rational approximation, cheaper than libm's scalar loop) against
    np.arctan2 over random directions and lengths spanning 1e-300 .. 1e300, the axes, the diagonals,
    signed zeros and NaN (all finite: no overflow on the way)."""
    rng = np.random.default_rng(7)
    n = 200_000
    x = rng.standard_normal(n) * 10.0 ** rng.uniform(-290, 290, n)
    y = x * np.tan(rng.uniform(-np.pi, np.pi, n)) * 10.0 ** rng.uniform(-4, 4, n)
    y[:1000] = rng.standard_normal(1000) * 10.0 ** rng.uniform(-290, 290, 1000)
    edge = np.array([[1.0, 0.0], [-1.0, 0.0], [0.0, 1.0], [0.0, -1.0], [-1.0, -0.0], [1.0, -0.0],
                     [1.0, 1.0], [-1.0, 1.0], [-1.0, -1.0], [1.0, -1.0], [1.0, 0.66], [1.0, 0.66 + 1e-16],
                     [0.66, 1.0], [3.0, 1e-300], [1e-300, 3.0], [np.nan, 1.0], [1.0, np.nan]])
    x = np.concatenate([x, edge[:, 0]])
    y = np.concatenate([y, edge[:, 1]])
    out, a, b, c, d, e = (np.empty(x.size) for _ in range(6))
    trig.atan2(y, x, out, a, b, c, d, e, np.empty(x.size, dtype=bool))
    ref = np.arctan2(y, x)
    assert np.array_equal(np.isnan(out), np.isnan(ref))
    fin = ~np.isnan(ref)
    ulp = np.abs(out - ref)[fin] / np.spacing(np.abs(ref[fin]))
    assert ulp.max() <= 2.0, ulp.max()
    # exact on the axes, with the sign of zero kept as np.arctan2 keeps it (theta in (-pi, pi])
    k = x.size - edge.shape[0]
    np.testing.assert_array_equal(out[k:k + 6], ref[k:k + 6])
    assert out[k + 4] == -np.pi and out[k + 1] == np.pi




def test_four_bar_into_the_callers_buffers():
    """out=: the same values, bit for bit, written into the caller's buffers (views of them), gaps
    included; buffers of the wrong shape, type or layout refused."""
    kw = dict(crank_pivot=(0.0, 0.0), rocker_pivot=(0.1, 0.02), crank=0.08, coupler=0.09, rocker=0.07, branch=1)
    th = np.linspace(0.0, 2 * np.pi, 5001)              # this crank is long enough to leave gaps
    fresh = four_bar(th, 10.0, 20.0, **kw)
    block, asm = sk.four_bar_buffers(th.size)
    block.fill(123.0)
    got = four_bar(th, 10.0, 20.0, out=(block, asm), **kw)
    assert 0 < fresh.assembles.sum() < th.size
    for f in dataclasses.fields(fresh):
        a, b = getattr(fresh, f.name), getattr(got, f.name)
        assert np.array_equal(a, b, equal_nan=True), f.name
    assert np.shares_memory(got.Cx, block) and np.shares_memory(got.assembles, asm)
    for bad in ((np.empty((len(FOURBAR_FIELDS), 10)), asm), (block.astype(np.float32), asm),
                (np.asfortranarray(block), asm), (block, asm.astype(int)), block):
        with pytest.raises(ValueError, match="out"):
            four_bar(th, 10.0, 20.0, out=bad, **kw)


def test_four_bar_reuses_the_callers_buffers():
    """The same buffers call after call: the result's arrays are read-only views, the buffers stay writable."""
    kw = dict(crank_pivot=(0.0, 0.0), rocker_pivot=(0.1, 0.02), crank=0.03, coupler=0.09, rocker=0.07, branch=1)
    th = np.linspace(0.0, 2 * np.pi, 101)
    block, asm = sk.four_bar_buffers(th.size)
    first = four_bar(th, 10.0, 20.0, out=(block, asm), **kw)
    assert not first.assembles.flags.writeable and not first.Cx.flags.writeable
    assert block.flags.writeable and asm.flags.writeable
    again = four_bar(th + 0.1, 10.0, 20.0, out=(block, asm), **kw)
    np.testing.assert_array_equal(again.Cx, four_bar(th + 0.1, 10.0, 20.0, **kw).Cx)


def test_chain_sweep_is_the_chain_solution_in_chunks(monkeypatch):
    """chain_sweep gives chain_solution's numbers bit for bit, however the angles are chunked."""
    th = np.linspace(-7.0, 7.0, 1001)
    al = np.linspace(-50.0, 50.0, 1001)
    whole = an.chain_solution(toggle_linkage(), th, 2.0, al)
    for chunk in (5, 1000, 2**13):
        monkeypatch.setattr(chain_chunks, "CHAIN_CHUNK", chunk)
        pieces = sk.chain_sweep(toggle_linkage(), th, 2.0, al)
        assert pieces.order == whole.order and pieces.shape == whole.shape
        np.testing.assert_array_equal(pieces.assembles, whole.assembles)
        for kind in ("positions", "velocities", "accelerations"):
            for n, (x, y) in getattr(whole, kind).items():
                np.testing.assert_array_equal(x, getattr(pieces, kind)[n][0], err_msg=n)
                np.testing.assert_array_equal(y, getattr(pieces, kind)[n][1], err_msg=n)
        for kind in ("angular", "angular_acceleration", "conditions"):
            assert list(getattr(pieces, kind)) == list(getattr(whole, kind))
            for n, v in getattr(whole, kind).items():
                np.testing.assert_array_equal(v, getattr(pieces, kind)[n], err_msg=n)
                assert not getattr(pieces, kind)[n].flags.writeable


def test_alpha_chunking_is_invisible(monkeypatch):
    fb = dict(crank_pivot=(0.0, 0.0), rocker_pivot=(1.0, 0.0), crank=0.8, coupler=0.5, rocker=0.6, branch=-1)
    sc = dict(crank_pivot=(0, 0), crank=0.8, coupler=0.5, guide_point=(0, 1), guide_angle=0.1, branch=1)
    th = np.linspace(-7.0, 7.0, 1001)
    al = np.linspace(-50.0, 50.0, 1001)
    whole = four_bar(th, 2.0, al, **fb), slider_crank(th, 2.0, al, **sc)
    monkeypatch.setattr(shared_steps, "CHUNK", 7)
    pieces = four_bar(th, 2.0, al, **fb), slider_crank(th, 2.0, al, **sc)
    for a, b in zip(whole, pieces):
        for f in dataclasses.fields(a):
            np.testing.assert_array_equal(getattr(a, f.name), getattr(b, f.name), err_msg=f.name)
    for k in (0, 333, 1000):      # one angle (and alpha) at a time gives the same numbers
        one = four_bar(th[k], 2.0, al[k], **fb)
        for f in dataclasses.fields(one):
            np.testing.assert_array_equal(getattr(one, f.name), getattr(whole[0], f.name)[k], err_msg=f.name)


def _bits(a, b, what):
    """The same bytes: the same numbers, signs of zero and NaN payloads (not merely equal values)."""
    for f in dataclasses.fields(a):
        x, y = np.asarray(getattr(a, f.name)), np.asarray(getattr(b, f.name))
        assert x.shape == y.shape and x.tobytes() == y.tobytes(), (what, f.name)


def _hard_angles(n):
    """n crank angles beyond 2 pi both ways, with signed zeros, +-pi (toggles), NaN and 1e7 rad among them."""
    th = np.linspace(-9.0, 9.0, n)
    th[::17], th[5::19], th[3::23], th[11::29], th[7::31], th[13::37] = 0.0, -0.0, np.pi, -np.pi, np.nan, 1e7
    return th


@pytest.mark.parametrize("n", [4000, 10_001, 3 * shared_steps.CHUNK + 5])
def test_threads_give_the_same_numbers_bit_for_bit(n, monkeypatch):
    """Any number of threads, fresh output or the caller's buffers: the single-thread run's bytes, over
    gaps, toggles (NaN rates), the extended toggle snapped, NaN angles, signed zeros and large angles
    (threaded from 4000 angles here: halves, and chunks)."""
    monkeypatch.setattr(sweep_threads, "THREADED_FROM", 4000)
    th = _hard_angles(n)
    al = np.linspace(-50.0, 50.0, n)
    fb = dict(crank_pivot=(0.0, 0.0), rocker_pivot=(1.0, 0.0), crank=0.8, coupler=0.5, rocker=0.6, branch=-1)
    designed = dict(crank_pivot=(0.0, 0.0), rocker_pivot=(0.3, 0.0), crank=0.1, coupler=0.25, rocker=0.15,
                    branch=1)
    sc = dict(crank_pivot=(0, 0), crank=0.8, coupler=0.5, guide_point=(0, 1), guide_angle=0.1, branch=-1)
    gaps, toggles = [], []
    for kw in (fb, designed):
        one = four_bar(th, 2.0, al, threads=1, **kw)
        gaps.append(0 < one.assembles.sum() < n)
        toggles.append(np.isnan(one.omega2[one.assembles]).any())
        for t in (2, 3, 8):
            _bits(one, four_bar(th, 2.0, al, threads=t, **kw), t)
            _bits(one, four_bar(th, 2.0, al, threads=t, out=sk.four_bar_buffers(n), **kw), (t, "out"))
        point = dict(distance=0.3, angle=0.9, ABx=one.ABx, ABy=one.ABy, alpha2=one.alpha2)
        given = (one.Bx, one.By, one.VBx, one.VBy, one.theta2, one.omega2)
        _bits(coupler_point(*given, **point, threads=1), coupler_point(*given, **point, threads=2), "point")
    assert gaps == [True, True] and toggles == [False, True]
    one = slider_crank(th, -4.0, al, threads=1, **sc)
    assert 0 < one.assembles.sum() < n
    for t in (2, 3):
        _bits(one, slider_crank(th, -4.0, al, threads=t, **sc), ("slider", t))


def test_the_pieces_of_a_threaded_call(monkeypatch):
    """Each angle in exactly one piece; one piece on the calling thread below THREADED_FROM angles; halves
    where a chunk would hold more than half the angles, chunks beyond; the pieces the same on any number
    of threads, and on two threads both of them at work when a piece takes long enough to wait for."""
    import threading
    import time
    monkeypatch.setattr(sweep_threads, "THREADED_FROM", 4000)

    def pieces(n, threads, most=shared_steps.CHUNK, wait=0.0):
        seen = []

        def solve(i, j):
            seen.append((i, j, threading.current_thread().name))
            time.sleep(wait)
        sweep_threads.in_pieces(solve, n, threads, most)
        return sorted(seen)
    me = threading.current_thread().name
    assert pieces(0, 2) == []
    assert pieces(3999, 2) == [(0, 3999, me)]
    assert [p[:2] for p in pieces(10_000, 2)] == [(0, 5000), (5000, 10_000)]
    assert [p[:2] for p in pieces(10_001, 1)] == [(0, 5001), (5001, 10_001)]
    big = pieces(100_000, 2)
    assert [p[:2] for p in big] == [(i, min(i + shared_steps.CHUNK, 100_000))
                                    for i in range(0, 100_000, shared_steps.CHUNK)]
    assert [p[:2] for p in pieces(100_000, 1)] == [p[:2] for p in big] == [p[:2] for p in pieces(100_000, 5)]
    assert {p[2] for p in pieces(100_000, 1)} == {me}
    names = {p[2] for p in pieces(10_000, 2, wait=0.2)}
    assert me in names and len(names) == 2 and all(n == me or n.startswith(sweep_threads.PREFIX) for n in names)
    assert sweep_threads.pool_threads() >= 1

    def fails(i, j):
        raise ZeroDivisionError(i)
    with pytest.raises(ZeroDivisionError):
        sweep_threads.in_pieces(fails, 10_000, 2, shared_steps.CHUNK)


def test_the_default_thread_count(monkeypatch):
    """min(2, cores) by default; DRAFTING_SWEEP_THREADS (an integer >= 1, anything else ignored); one after
    one_thread(); threads= checked."""
    monkeypatch.setattr(sweep_threads, "_process_threads", None)
    monkeypatch.delenv(sweep_threads.ENV, raising=False)
    default = min(2, sweep_threads._cores())
    assert sweep_threads.default_threads() == default
    for value, expected in (("3", 3), ("1", 1), ("0", default), ("-2", default), ("two", default), ("", default),
                            ("2.5", default)):
        monkeypatch.setenv(sweep_threads.ENV, value)
        assert sweep_threads.default_threads() == expected, value
    sweep_threads.one_thread()
    assert sweep_threads.default_threads() == 1
    assert sweep_threads.threads_for(10**6) == 1
    monkeypatch.setattr(sweep_threads, "_process_threads", None)
    monkeypatch.setenv(sweep_threads.ENV, "4")
    assert sweep_threads.threads_for(10**6) == 4 and sweep_threads.threads_for(10) == 1
    assert sweep_threads.threads_for(10**6, 1) == 1
    for bad in (0, -1, 2.0, True, "2"):
        with pytest.raises(ValueError, match="threads"):
            four_bar(np.zeros(3), 1.0, threads=bad, **FB)


def _worker_threads(_):
    return sweep_threads.default_threads()


def _forked_sweep(n):
    r = four_bar(np.linspace(0.0, 2 * np.pi, n), 10.0, 20.0, threads=2, **FB)
    return float(np.nansum(r.Cx)), sweep_threads.pool_threads()


def test_pool_workers_sweep_on_one_thread_and_a_fork_makes_its_own_pool():
    """The process pool's workers (drafting.app.parallel) run each sweep on their own thread; a child forked
    after this process's sweep pool started makes a pool of its own (the parent's threads are not in it)."""
    import multiprocessing
    from drafting.app import parallel
    if parallel.cores() >= 2:
        assert parallel.run(_worker_threads, [0, 1, 2], workers=2) == [1, 1, 1]
    n = max(10_000, sweep_threads.THREADED_FROM)
    here = _forked_sweep(n)
    assert sweep_threads.pool_threads() >= 1
    with multiprocessing.get_context("fork").Pool(1) as pool:
        total, threads = pool.apply_async(_forked_sweep, (n,)).get(timeout=60)
    assert total == here[0] and threads >= 1
