"""The machine elements the cam and gear sheets draw beside their constructions: the follower in place,
the senses of rotation, the displacement diagram's numbered stations and the line of action's label."""

from __future__ import annotations

import math

import numpy as np

from constructions.cams.construction import construct
from constructions.cams.follower import FLAT, OSCILLATING, ROLLER, Follower
from constructions.cams.laws import DWELL, HARMONIC, RETURN, RISE, Program, Segment as Piece
from constructions.entities import Circle, FollowerBody, Note, RotationArrow, Segment
from constructions.gears.contact import Pair
from constructions.gears.mesh import mesh_analysis
from constructions.gears.tooth import Gear, ToothSystem

D = math.radians
PROGRAM = Program([Piece(DWELL, D(120)), Piece(RISE, D(60), 0.02, HARMONIC), Piece(DWELL, D(30)),
                   Piece(RETURN, D(150), 0.02, HARMONIC)])


def _named(c, name):
    return next(e for e in c.entities() if e.name == name)


def test_translating_follower_stands_on_station_0_in_true_size():
    for kind, rr in ((ROLLER, 0.012), (FLAT, 0.0)):
        f = Follower(kind, 0.04, rr, sense=-1)
        c = construct(PROGRAM, f, 36, samples=256)
        body = _named(c.construction, "follower")
        assert isinstance(body, FollowerBody)
        end = c.centres[:, 0]
        assert math.hypot(body.at.x - end[0], body.at.y - end[1]) <= 1e-12
        assert body.radius == rr and body.direction.x == 0 and body.direction.y > 0
        arrow = _named(c.construction, "cam rotation")
        assert isinstance(arrow, RotationArrow) and arrow.sweep < 0          # clockwise: sense -1


def test_oscillating_follower_arm_about_its_pivot():
    f = Follower(OSCILLATING, 0.04, 0.008, sense=1, pivot_distance=0.09, arm_length=0.07)
    c = construct(PROGRAM, f, 18, samples=256)
    arm, roller = _named(c.construction, "follower arm"), _named(c.construction, "follower roller")
    assert isinstance(arm, Segment) and isinstance(roller, Circle)
    assert math.isclose(arm.start.x, 0.09) and abs(arm.start.y) < 1e-15
    assert math.isclose(math.hypot(arm.end.x - 0.09, arm.end.y), 0.07, rel_tol=1e-12)
    assert roller.radius == 0.008 and _named(c.construction, "cam rotation").sweep > 0


def test_displacement_diagram_numbers_match_the_cam_stations():
    f = Follower(ROLLER, 0.04, 0.012)
    c = construct(PROGRAM, f, 36, samples=256)
    ents = list(c.construction.entities())
    cam_numbers = {e.text for e in ents if isinstance(e, Note) and e.name.startswith("station ")}
    diag_numbers = {e.text for e in ents if isinstance(e, Note) and e.name.startswith("station number ")}
    assert diag_numbers - {"36"} <= cam_numbers and len(diag_numbers) >= 4
    # each station line stands the tabulated lift above the diagram's abscissa
    axis = _named(c.construction, "displacement axis")
    for i in range(36):
        s = float(c.table[i])
        if s > 0:
            line = _named(c.construction, f"station line {i}")
            assert math.isclose(line.end.y - axis.start.y, s, rel_tol=1e-12)
    assert np.isclose(axis.start.y, f.d0)          # the baseline is level with the roller centre at zero lift


def test_line_of_action_label_sits_on_the_pressure_line():
    s = ToothSystem(0.005, D(20.0), 1.0, 1.25)
    a = mesh_analysis(Pair(Gear(20, s), Gear(40, s)))
    labelled = [e for e in a.construction.entities() if getattr(e, "label", None) == "line of action"]
    assert labelled
    P = a.geometry.points["P"]
    for e in labelled:
        d = e.end - e.start
        # through P, at the pressure angle to the common tangent (the y axis), not along O1O2 (the x axis)
        assert abs(d.x * (P.y - e.start.y) - d.y * (P.x - e.start.x)) <= 1e-12 * math.hypot(d.x, d.y)
        assert math.isclose(abs(math.atan2(d.x, -d.y)), D(20.0), abs_tol=1e-12) or \
            math.isclose(abs(math.atan2(-d.x, d.y)), D(20.0), abs_tol=1e-12)
    senses = {e.name: e.sweep for e in a.construction.entities() if isinstance(e, RotationArrow)}
    assert senses["rotation 1"] < 0 < senses["rotation 2"]          # the driver clockwise, an external pair opposite
