"""Drawing the entities of one diagram as paper commands: the drawers of :mod:`drafting.render.drawers` and
:mod:`drafting.layout.chart` (imported here, so each registers its drawers) run over the diagram's entities in
their phases.  The registry, the Drawing and its context live in :mod:`drafting.render.drawing`.
"""

from __future__ import annotations

from typing import Sequence

from constructions.entities import Entity
from constructions.geometry import Vec

from . import chart  # noqa: F401  (registers the chart drawer)
from ..render.drawers import diagram_facts, draw_pins, trial_crossings
from ..render.drawing import Drawing, DrawContext, TextFn, _plain_text, drawer_for
from ..render.errors import DrawingError
from ..render.transform import Transform


def model_points(entities: Sequence[Entity]) -> list[Vec]:
    """The model points the entities cover (every entity type must have a drawer)."""
    pts: list[Vec] = []
    for e in entities:
        entry = drawer_for(e)
        if entry.points is not None:
            pts.extend(entry.points(e))
    return pts


def draw_entities(entities: Sequence[Entity], k: float, *, text: TextFn | None = None,
                  among: Sequence[Entity] | None = None, extent_only: bool = False) -> Drawing:
    """Every entity of one diagram drawn at ``k`` paper mm per model unit, model origin at (0, 0); laid out
    (a guide's length, the side a hatch takes) among the points of ``among`` when given (a problem
    sheet's frame among the mechanism the student is to draw), else of ``entities``.  With ``extent_only``
    the drawing is made for its extent only (:attr:`~drafting.render.drawing.Drawing.extent_only`).

    Raises :class:`DrawingError` for an entity without a drawer (or a panel entity such as a chart)."""
    entries = []
    for e in entities:
        entry = drawer_for(e)
        if not entry.phases:
            raise DrawingError(f"the {type(e).__name__} {e.name!r} in the {e.diagram} diagram is drawn in a "
                               f"panel of its own, not to a model scale")
        entries.append(entry)
    T = Transform(k)
    d = Drawing(extent_only=extent_only)
    around = entities if among is None else among
    pts = model_points(around)
    paper_pts = T.many(pts)
    paper_pts += T.many(trial_crossings(around, pts))
    pivots, bars, blocks = diagram_facts(entities, T)
    centroid = (sum(p[0] for p in paper_pts) / len(paper_pts), sum(p[1] for p in paper_pts) / len(paper_pts)) \
        if paper_pts else (0.0, 0.0)
    ctx = DrawContext(T, d, entities, paper_pts, centroid, pivots, bars, blocks, text_fn=text or _plain_text)
    for phase in (0, 1, 2):
        for e, entry in zip(entities, entries):
            fn = entry.phases.get(phase)
            if fn is not None:
                fn(e, ctx)
        if phase == 1:
            draw_pins(ctx)
    return d
