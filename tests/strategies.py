"""Hypothesis strategies the tests share: random linkages (four-bars and slider-cranks with points fixed
to their links, at a transmission angle that assembles), their dimensions for the analytic closed forms
at any scale, and Grashof crank-rockers."""

from __future__ import annotations

import math

from hypothesis import assume
from hypothesis import strategies as st

from constructions.geometry import Vec
from constructions.mechanisms.model import Attached

from mechanisms import four_bar, slider_crank

# -- linkages (constructions.linkage), against the vector loop ---------------------------------------------

sizes = st.floats(0.01, 1.0)                       # a mechanism's unit: 10 mm .. 1 m
proportions = st.floats(0.25, 5.0)                 # its links 0.25..5 units: 2.5 mm .. 5 m, at most 1:20
coords = st.floats(-1.0, 1.0)
angles = st.floats(-math.pi, math.pi)
speeds = st.floats(0.1, 1000.0).flatmap(lambda w: st.sampled_from([w, -w]))
# a point fixed to a link: anywhere, on the line of the link, next to it (1e-10..1e-6 rad) or at a joint
point_angles = st.one_of(st.sampled_from([0.0, math.pi]), angles,
                         st.floats(1e-10, 1e-6).flatmap(lambda a: st.sampled_from([a, -a, math.pi - a])))
point_distances = st.one_of(st.just(0.0), st.floats(0.0, 2.0), st.floats(1e-12, 1e-8))  # x link length


@st.composite
def transmission(draw):
    """An angle between coupler and rocker (or coupler and guide normal) with |sine| >= 0.06."""
    a = draw(st.floats(math.asin(0.06), math.pi - math.asin(0.06)))
    return a if draw(st.booleans()) else -a


@st.composite
def four_bars(draw):
    o1 = (draw(coords), draw(coords))
    unit = draw(sizes)
    crank, coupler, rocker = (unit * draw(proportions) for _ in range(3))
    theta = draw(angles)
    b = Vec(*o1) + Vec.polar(crank, theta)
    phi2 = draw(angles)
    c = b + Vec.polar(coupler, phi2)
    o2 = c - Vec.polar(rocker, phi2 + draw(transmission()))
    natural = 1 if (o2 - b).cross(c - b) > 0 else -1
    branch = natural if draw(st.booleans()) else -natural      # the mirror assembly, too
    points = [Attached("D", 2, draw(st.sampled_from(["B", "C"])), coupler * draw(point_distances),
                       draw(point_angles)),
              Attached("E", 3, draw(st.sampled_from(["O2", "C"])), rocker * draw(st.floats(0.1, 1.5)),
                       draw(point_angles)),
              Attached("A", 1, "O1", crank * draw(st.floats(0.1, 1.5)), draw(point_angles))]
    m = four_bar(o1, o2.as_tuple(), crank, coupler, rocker, branch, points)
    return m, theta, draw(speeds)


@st.composite
def slider_cranks(draw):
    o1 = (draw(coords), draw(coords))
    unit = draw(sizes)
    crank, coupler = unit * draw(proportions), unit * draw(proportions)
    theta = draw(angles)
    g = draw(st.one_of(st.just(0.0), angles))
    if draw(st.booleans()):
        # in-line: the guide passes through O1; a coupler longer than the crank always assembles
        coupler = crank * draw(st.floats(1.06, 6.0))
        through = Vec(*o1) + Vec.polar(unit * draw(st.sampled_from([0.0, 0.3, -2.7])), g)
        natural = draw(st.sampled_from([1, -1]))
    else:
        # offset: C where the coupler meets a guide drawn through it, |cos(coupler, guide)| >= 0.06
        b = Vec(*o1) + Vec.polar(crank, theta)
        c = b + Vec.polar(coupler, g + math.pi / 2 + draw(transmission()))
        through = c + Vec.polar(unit * draw(st.floats(-5.0, 5.0)), g)
        natural = 1 if (c - b).dot(Vec.polar(1.0, g)) > 0 else -1
    branch = natural if draw(st.booleans()) else -natural
    points = [Attached("D", 2, draw(st.sampled_from(["B", "C"])), coupler * draw(point_distances),
                       draw(point_angles)),
              Attached("A", 1, "O1", crank * draw(st.floats(0.1, 1.5)), draw(point_angles))]
    m = slider_crank(o1, crank, coupler, through.as_tuple(), g, branch, points)
    return m, theta, draw(speeds)


# -- dimensions for constructions.analytic: random mechanisms of any scale 1e-3 .. 1e3 -------------------

@st.composite
def four_bar_dimensions(draw):
    """A four-bar as constructions.analytic.four_bar's keywords, of any scale 1e-3 .. 1e3."""
    L = 10.0 ** draw(st.floats(-3.0, 3.0))
    ratio = st.floats(0.1, 2.0)
    mech = dict(
        crank_pivot=(draw(st.floats(-2.0, 2.0)) * L, draw(st.floats(-2.0, 2.0)) * L),
        crank=draw(ratio) * L, coupler=draw(ratio) * L, rocker=draw(ratio) * L,
        branch=draw(st.sampled_from([1, -1])),
    )
    ground = draw(st.floats(0.05, 2.0)) * L
    phi = draw(st.floats(-math.pi, math.pi))
    mech["rocker_pivot"] = (mech["crank_pivot"][0] + ground * math.cos(phi),
                            mech["crank_pivot"][1] + ground * math.sin(phi))
    return mech


@st.composite
def slider_crank_dimensions(draw):
    """A slider-crank as constructions.analytic.slider_crank's keywords, of any scale 1e-3 .. 1e3."""
    L = 10.0 ** draw(st.floats(-3.0, 3.0))
    return dict(
        crank_pivot=(draw(st.floats(-2.0, 2.0)) * L, draw(st.floats(-2.0, 2.0)) * L),
        crank=draw(st.floats(0.1, 2.0)) * L, coupler=draw(st.floats(0.1, 3.0)) * L,
        guide_point=(draw(st.floats(-2.0, 2.0)) * L, draw(st.floats(-2.0, 2.0)) * L),
        guide_angle=draw(st.floats(-math.pi, math.pi)),
        branch=draw(st.sampled_from([1, -1])),
    )


# -- Grashof crank-rockers ----------------------------------------------------------------------------------

@st.composite
def crank_rockers(draw):
    """(ground, crank, coupler, rocker, branch, frame angle) of a Grashof crank-rocker, crank shortest."""
    a = draw(st.floats(0.01, 0.05))
    g = draw(st.floats(0.06, 0.2))
    b = draw(st.floats(0.06, 0.2))
    c = draw(st.floats(0.06, 0.2))
    assume(a + max(g, b, c) < sum(sorted((g, b, c))[:2]) * 0.98)     # Grashof with the crank shortest
    return g, a, b, c, draw(st.sampled_from([1, -1])), draw(st.floats(-math.pi, math.pi))
