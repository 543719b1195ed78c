"""Moments of inertia (constructions.forces.inertia) against numerical integration of I = sum r^2 dm over a
fine grid of each shape: the tests find the centre of mass and the moment from the point cloud itself,
so they restate no formula."""

from __future__ import annotations

import math

import numpy as np
import pytest

from constructions.forces import inertia as I
from constructions.geometry import Vec

N = 1500          # cells along each direction of a grid (midpoint rule: relative error ~1/N^2)
REL = 1e-5


def cloud_moment(x, y, w) -> tuple[float, float, float, float]:
    """(mass, centre x, centre y, moment about the centre) of point masses w at (x, y)."""
    x, y, w = (np.ravel(a) for a in np.broadcast_arrays(x, y, w))
    m = w.sum()
    gx, gy = (w * x).sum() / m, (w * y).sum() / m
    return float(m), float(gx), float(gy), float((w * ((x - gx) ** 2 + (y - gy) ** 2)).sum())


def mid(a: float, b: float, n: int = N) -> tuple[np.ndarray, float]:
    """Midpoints of n equal cells over [a, b] and the cell width."""
    h = (b - a) / n
    return a + h * (np.arange(n) + 0.5), h


def polar(mass: float, r1: float, r2: float, t1: float, t2: float):
    """A uniform plate between radii r1..r2 and angles t1..t2 as point masses (cell area rho drho dtheta)."""
    rho, dr = mid(r1, r2)
    th, dt = mid(t1, t2)
    R, T = np.meshgrid(rho, th, indexing="ij")
    area = R * dr * dt
    return R * np.cos(T), R * np.sin(T), mass * area / area.sum()


def test_slender_rod():
    x, h = mid(-0.2, 0.4, 200_000)          # a rod 0.6 m long, not centred on the origin
    m, gx, gy, ig = cloud_moment(x, 0.0, np.full_like(x, 3.0 / x.size))
    assert (m, gx) == pytest.approx((3.0, 0.1), rel=1e-12)
    assert I.rod(3.0, 0.6) == pytest.approx(ig, rel=1e-9)


def test_disc():
    x, y, w = polar(5.0, 0.0, 0.1, 0.0, 2 * math.pi)
    m, gx, gy, ig = cloud_moment(x + 0.3, y - 0.2, w)
    assert (gx, gy) == pytest.approx((0.3, -0.2), abs=1e-12)
    assert I.disc(5.0, 0.1) == pytest.approx(ig, rel=REL)


def test_rectangular_plate():
    a, b = 0.4, 0.15
    xs, _ = mid(0.0, a)
    ys, _ = mid(0.0, b)
    X, Y = np.meshgrid(xs, ys, indexing="ij")
    m, gx, gy, ig = cloud_moment(X, Y, np.full(X.shape, 2.0 / X.size))
    assert (gx, gy) == pytest.approx((a / 2, b / 2), rel=1e-12)
    assert I.plate(2.0, a, b) == pytest.approx(ig, rel=REL)
    # a square plate is the same whichever way it is given
    assert I.plate(2.0, a, b) == I.plate(2.0, b, a)


def test_ring():
    x, y, w = polar(1.5, 0.05, 0.12, 0.0, 2 * math.pi)
    m, gx, gy, ig = cloud_moment(x, y, w)
    assert abs(gx) < 1e-12 and abs(gy) < 1e-12
    assert I.ring(1.5, 0.05, 0.12) == pytest.approx(ig, rel=REL)
    assert I.ring(1.5, 0.0, 0.12) == I.disc(1.5, 0.12)          # no hole: a disc


def test_thin_ring():
    t, _ = mid(0.0, 2 * math.pi, 10_000)
    m, gx, gy, ig = cloud_moment(0.25 * np.cos(t) + 1.0, 0.25 * np.sin(t), np.full_like(t, 0.8 / t.size))
    assert I.thin_ring(0.8, 0.25) == pytest.approx(ig, rel=1e-12)
    # the limit of an annulus whose radii close together
    x, y, w = polar(0.8, 0.25 - 1e-4, 0.25 + 1e-4, 0.0, 2 * math.pi)
    assert I.thin_ring(0.8, 0.25) == pytest.approx(cloud_moment(x, y, w)[3], rel=1e-6)


def test_semicircular_plate_about_its_centre_of_mass():
    """The notes give I_G = m r^2 / 2 and I_O = m r^2 / 2 - m h^2 with the two swapped: integrating the
    half disc puts m r^2 / 2 about O (the middle of the straight edge) and the smaller value about G."""
    m_, r = 2.0, 0.3
    x, y, w = polar(m_, 0.0, r, 0.0, math.pi)
    m, gx, gy, ig = cloud_moment(x, y, w)
    io = float((w * (x**2 + y**2)).sum())                         # about O, the circle's centre
    assert gy == pytest.approx(I.semicircle_centroid(r), rel=REL) and abs(gx) < 1e-12
    assert I.semicircular_plate(m_, r) == pytest.approx(ig, rel=REL)
    assert io == pytest.approx(m_ * r**2 / 2, rel=REL)               # I_O, the notes' "I_G"
    assert I.semicircular_plate(m_, r) < io
    assert I.semicircular_plate(m_, r) == pytest.approx(0.31986 * m_ * r**2, rel=1e-4)


def test_parallel_axis_both_ways():
    # a rod about its end, integrated: I_A = I_G + m (L/2)^2
    x, _ = mid(0.0, 0.6, 200_000)
    about_end = float((np.full_like(x, 3.0 / x.size) * x**2).sum())
    assert I.about_point(I.rod(3.0, 0.6), 3.0, 0.3) == pytest.approx(about_end, rel=1e-9)
    assert I.about_centre(about_end, 3.0, 0.3) == pytest.approx(I.rod(3.0, 0.6), rel=1e-8)
    assert I.about_centre(I.about_point(0.01, 2.0, 0.1), 2.0, 0.1) == pytest.approx(0.01, rel=1e-14)
    # a point mass given by its moment about a point: rounding of I_A = m d^2 is zero, not negative
    assert I.about_centre(2.0 * 0.1**2, 2.0, 0.1) == pytest.approx(0.0, abs=1e-17)
    with pytest.raises(ValueError, match="negative"):
        I.about_centre(0.01, 2.0, 0.1)                    # m d^2 = 0.02 > 0.01
    with pytest.raises(ValueError):
        I.about_point(-0.01, 2.0, 0.1)
    with pytest.raises(ValueError):
        I.disc(-1.0, 0.1)
    with pytest.raises(ValueError):
        I.ring(1.0, 0.2, 0.1)
    with pytest.raises(ValueError):
        I.rod(1.0, math.nan)


def test_the_notes_composite_example():
    """The notes' assembly: a disc (5 kg, r = 0.1 m, centre A) and a rod (3 kg) fixed to it, with
    r_AG = 0.15 m.  The printed working is garbled (m_R + r_AB for m_R r_AB; the disc's line shows only
    I_A; the rod's 1/2 for 1/12; m_D for m_R), so from the data: r_AG = m_R r_AB / (m_R + m_D) = 0.15 m
    gives r_AB = 0.4 m; the rod term (0.6)^2 gives L = 0.6 m, so the rod runs from the disc's rim
    (0.1 m) to C at 0.7 m, r_CG = 0.55 m.  Then
        disc: I_A + m_D r_AG^2 = 0.025 + 0.1125 = 0.1375 kg m^2
        rod:  m_R L^2/12 + m_R r_BG^2 = 0.09 + 3 (0.25)^2 = 0.2775 kg m^2
        I_G = 0.415 kg m^2,  I_C = I_G + 8 (0.55)^2 = 2.835 kg m^2,
    the notes' totals.  Integrated here over the disc's and the rod's point masses together."""
    dx, dy, dw = polar(5.0, 0.0, 0.1, 0.0, 2 * math.pi)
    rx, _ = mid(0.1, 0.7, 200_000)
    x = np.concatenate([dx.ravel(), rx])
    y = np.concatenate([dy.ravel(), np.zeros_like(rx)])
    w = np.concatenate([dw.ravel(), np.full_like(rx, 3.0 / rx.size)])
    m, gx, gy, ig = cloud_moment(x, y, w)
    ic = float((w * ((x - 0.7) ** 2 + y**2)).sum())
    assert m == pytest.approx(8.0) and gx == pytest.approx(0.15, rel=1e-9) and abs(gy) < 1e-12
    assert ig == pytest.approx(0.415, rel=REL) and ic == pytest.approx(2.835, rel=REL)

    body = I.composite([I.Body(5.0, Vec(0.0, 0.0), I.disc(5.0, 0.1)),
                        I.Body(3.0, Vec(0.4, 0.0), I.rod(3.0, 0.6))])
    assert body.mass == 8.0 and body.centre.x == pytest.approx(0.15, rel=1e-15)
    assert body.inertia == pytest.approx(0.415, rel=1e-14) == pytest.approx(ig, rel=REL)
    assert body.about(Vec(0.7, 0.0)) == pytest.approx(2.835, rel=1e-14)
    with pytest.raises(ValueError):
        I.composite([])


def test_shapes_by_name():
    assert I.shape_inertia("rod", 2.0, 0.3) == I.rod(2.0, 0.3)
    assert I.shape_inertia("plate", 2.0, 0.3, 0.1) == I.plate(2.0, 0.3, 0.1)
    assert I.shape_inertia("semicircular plate", 2.0, 0.3) == I.semicircular_plate(2.0, 0.3)
    assert set(I.SHAPES) == {"rod", "disc", "plate", "ring", "thin ring", "semicircular plate"}
    with pytest.raises(ValueError, match="not a shape"):
        I.shape_inertia("cone", 1.0, 0.1)
    with pytest.raises(ValueError, match="needs"):
        I.shape_inertia("ring", 1.0, 0.1)
