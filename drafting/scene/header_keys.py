"""The key tables of the sections every scene shares: the top level, ``[drawing]``, ``[ask]`` and ``[vary]``
(``[units]`` is :data:`drafting.scene.unitset.UNITS`, ``[drawing] scale`` :data:`drafting.scene.drawing_scales.SCALE`),
read by :mod:`drafting.scene.reader` (see :mod:`drafting.scene.keys`)."""

from __future__ import annotations

from .keys import Key, KeyTable

from .papers import PAPERS
ORIENTATIONS = ("landscape", "portrait")
KINDS = ("linkage", "cam", "gear pair", "gear train", "free body")
"""The scene kinds the reference documents (a test holds them to the registered families)."""

TOP = KeyTable("", "the top level of a scene file: its kind and the sections every kind shares", (
    Key("kind", "text", "linkage", "the scene's family: which sections it has and what it draws", choices=KINDS),
    Key("drawing", "table", None, "the sheet: title, drawing number, paper, scales"),
    Key("units", "table", None, "the units of plain numbers and of the results"),
    Key("ask", "table", None, "what to draw and which results to list"),
    Key("vary", "table", None, "ranges a batch of lab sheets draws each variant's values from (linkage)"),
))

DRAWING = KeyTable("drawing", "the sheet: its title block, paper and the diagrams' scales", (
    Key("title", "text", None, "the title in the title block (default: the file's name)"),
    Key("number", "text", "TOM-000", "the drawing number in the title block"),
    Key("paper", "text", "A4", "the paper size", choices=PAPERS),
    Key("orientation", "text", "landscape", "the paper's orientation", choices=ORIENTATIONS),
    Key("dimensions", "true/false", None, "dimension the space diagram as a drafter would (unset: off on a "
                                          "worked sheet, on on a problem sheet)"),
    Key("scale", "table", None, "a diagram's scale, stated (see [drawing.scale]); unset, each diagram takes "
                                "the largest standard scale that fits its panel"),
))

ASK = KeyTable("ask", "what the scene asks for", (
    Key("analyses", "list", None, "the analyses to draw"),
    Key("find", "list", None, "the rows of the results table, by name, e.g. [\"V_C\", \"omega_2\"] "
                              "(default: every result)"),
))

VARY = KeyTable("vary", "ranges a batch of lab sheets (drafting batch) draws each variant's values from; "
                        "each a pair [low, high] or { from, to, step } with units", (
    Key("crank_angle", "angle", None, "the crank angle ([input] angle)"),
    Key("omega", "angular velocity", None, "the crank's angular velocity ([input] omega)"),
    Key("tip_speed", "velocity", None, "the crank tip's speed ([input] tip_speed)"),
    Key("alpha", "angular acceleration", None, "the crank's angular acceleration ([input] alpha)"),
    Key("torque", "torque", None, "the torque on the crank ([input] torque)"),
    Key("length.<joints>", "length", None, "the length of the link joining two joints, e.g. length.BC"),
    Key("load.<name>", "force", None, "the force of the [[load]] of that name (its magnitude)"),
    Key("mass.<link>", "mass", None, "the mass of the [[mass]] on that link"),
    Key("pivot.<name>.x", "length", None, "a coordinate (.x or .y) of a fixed pivot in [frame]"),
), named=True)
"""``[vary]`` is read by the family (:mod:`drafting.families.linkage.vary`), which checks its keys; this table
documents them."""
