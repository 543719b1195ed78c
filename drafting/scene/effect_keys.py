"""The key tables of a linkage scene's effects ([gravity], [[load]], [[couple]], [[mass]], [[spring]],
[[friction]]), read by :mod:`drafting.scene.effects` (see :mod:`drafting.scene.keys`)."""

from __future__ import annotations

from .keys import Key, KeyTable

GRAVITY_KEYS = KeyTable("gravity", "weights: only a scene with this section has them", (
    Key("g", "acceleration", None, "the magnitude of gravity, positive, e.g. \"9.81 m/s^2\"", required=True),
    Key("angle", "angle", "-90 deg", "the direction of gravity (default: straight down, -y)"),
))
LOAD_KEYS = KeyTable("load", "an external force on a point of a body", (
    Key("name", "text", None, "the load's name (loads, couples and springs each need their own)", required=True),
    Key("link", "whole number", None, "the body: a link or slider-block number", required=True),
    Key("at", "text", None, "the point of that body it acts at (a joint or a [[point]])", required=True),
    Key("force", "force", None, "the magnitude (or pressure and bore, or torque: exactly one of them)"),
    Key("angle", "angle", None, "its direction, CCW from +x", required=True),
    Key("pressure", "pressure", None, "a gas pressure on a piston (a block on a fixed guide), with bore: "
                                      "F = p pi d^2/4 along the line of stroke (a plain number is MPa)"),
    Key("bore", "length", None, "the bore the pressure acts on (with pressure)"),
    Key("torque", "torque", None, "the driving torque this load holds: its magnitude is then the unknown, "
                                  "found by equilibrium and checked by virtual work (one such load)"),
    Key("sense", "text", None, "the sense of a positive torque (with torque)", choices=("ccw", "cw")),
), array=True)
COUPLE_KEYS = KeyTable("couple", "an external couple on a body", (
    Key("name", "text", None, "the couple's name", required=True),
    Key("link", "whole number", None, "the body: a link or slider-block number", required=True),
    Key("torque", "torque", None, "signed, CCW positive; or positive with sense", required=True),
    Key("sense", "text", None, "the sense of a positive torque", choices=("ccw", "cw")),
), array=True)
MASS_KEYS = KeyTable("mass", "the mass of a body (at most one per body): its weight and inertia forces", (
    Key("link", "whole number", None, "the body: a link or slider-block number", required=True),
    Key("mass", "mass", None, "the mass, positive", required=True),
    Key("at", "text", None, "the centre of gravity at a point of the body (default: the middle of the link, "
                            "or a block's joint)"),
    Key("from", "text", None, "or the centre measured from this joint of the link ..."),
    Key("distance", "length", None, "... this far ..."),
    Key("angle", "angle", "0 deg", "... at this angle CCW from the link's line"),
    Key("inertia", "moment of inertia", None, "the moment of inertia about the centre of gravity (omitted, "
                                              "with no shape: 0, a point mass)"),
    Key("inertia_about", "text", None, "the point of the body inertia is taken about (parallel-axis theorem)"),
    Key("shape", "text", None, "or the moment of inertia from a shape and its dimensions below",
        choices=("rod", "disc", "plate", "ring", "thin ring", "semicircular plate")),
    Key("length", "length", None, "a rod's length (default: the link's length)"),
    Key("radius", "length", None, "a disc's, thin ring's or semicircular plate's radius"),
    Key("width", "length", None, "a plate's width"),
    Key("height", "length", None, "a plate's height"),
    Key("inner_radius", "length", None, "a ring's inner radius"),
    Key("outer_radius", "length", None, "a ring's outer radius"),
), array=True)
SPRING_KEYS = KeyTable("spring", "a linear spring: tension k (L - L0) pulls its ends together", (
    Key("name", "text", None, "the spring's name", required=True),
    Key("link", "whole number", None, "one end: a body (link or slider-block number) ...", required=True),
    Key("at", "text", None, "... and its point", required=True),
    Key("anchor", "point", None, "the other end: a fixed point [x, y] or a fixed pivot by name, or ..."),
    Key("to_link", "whole number", None, "... a point of another body: its number ..."),
    Key("to", "text", None, "... and its point"),
    Key("stiffness", "stiffness", None, "k, positive", required=True),
    Key("free_length", "length", None, "L0, zero or more", required=True),
), array=True)
FRICTION_KEYS = KeyTable("friction", "Coulomb friction between a slider block and its guide or slot", (
    Key("slider", "whole number", None, "the slider-block number", required=True),
    Key("mu", "number", None, "the coefficient of friction, from 0 to 10", required=True),
), array=True)
TABLES = (GRAVITY_KEYS, LOAD_KEYS, COUPLE_KEYS, MASS_KEYS, SPRING_KEYS, FRICTION_KEYS)
"""The effects' key tables, as the reference lists them."""
