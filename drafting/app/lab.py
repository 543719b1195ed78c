"""Lab sheets: from one solved scene, a problem sheet for the students, the worked solution and the
answer key.

- The **problem sheet** states the given data (a "Given" list, the space diagram -- dimensioned -- and the
  construction steps with every value a student must find written as a blank) and frames each other
  diagram's panel empty, headed with its scale and scale bar, at the size and scale the worked solution
  draws it at, so a student draws the polygon in it at the stated scale (and the worked sheet lays over
  it).  The results table lists the quantities to find with their values blank.  No answer is printed
  anywhere: the space diagram keeps only what the problem states (links, pivots, guides, labels,
  dimensions, loads), a sense of turning found on the way is blanked too, and the scene's notes (which
  may name a result) are left off.
- The **worked solution** is the sheet ``drafting render`` draws.
- The **key** is one compact page (the results, graphical and analytic, each with the tolerance it is
  marked at: :mod:`drafting.app.answers`) and the same as CSV (units in the header).

:func:`lab_for` builds the three documents of a solved study; :func:`write_lab` writes them (with the
key's CSV) together or not at all.
"""

from __future__ import annotations

import copy
import csv
import io
import math
import re
from dataclasses import dataclass, replace
from pathlib import Path
from typing import Sequence

from constructions.entities import Role
from constructions.geometry import Vec
from constructions.record import Construction, Step, StepKind

from .answers import KeyItem, key_items
from ..render.errors import LayoutError
from ..layout.sheet import ResultRow, Sheet, SheetInfo, compose_sheets, sheet_date
from ..families.registry import family
from ..study.study import Study
from ..layout.panel import RoomFigure
from ..layout.panels import held_to
from ..render.drawing import is_panel_entity

BLANK = "________"
"""What a problem sheet writes for a value the student finds."""
ANSWER_LINE = "______________"
"""The room left in the problem sheet's results table for an answer."""

SHOWN_ROLES = frozenset({Role.GIVEN, Role.LABEL, Role.DIMENSION, Role.LOAD, Role.CENTRE_LINE, Role.NOTE})
"""What stays on a problem sheet's space diagram: what the problem states."""
_POSITION_ROLES = SHOWN_ROLES | {Role.PATH}

_SENSE_WORDS = re.compile(r"\b(counter-clockwise|anticlockwise|anti-clockwise|clockwise|CCW|CW)\b")

KEY_CSV_HEADER = ("quantity", "kind", "unit", "answer", "direction (deg)", "sense", "tolerance",
                  "direction tolerance (deg)", "tolerance basis", "as printed")


@dataclass(frozen=True)
class Lab:
    """The three documents of one scene and its key."""

    problem: tuple[Sheet, ...]
    worked: tuple[Sheet, ...]
    key: tuple[Sheet, ...]
    items: tuple[KeyItem, ...]
    given: tuple[str, ...]
    units: object

    def key_csv(self, extra: Sequence[tuple[str, str]] = ()) -> str:
        """The key as CSV in the scene's units, one row per answer (``extra`` (header, value) columns
        first, e.g. a batch's variant number)."""
        buf = io.StringIO()
        w = csv.writer(buf, lineterminator="\n")
        w.writerow([h for h, _ in extra] + list(KEY_CSV_HEADER))
        for i in self.items:
            w.writerow([v for _, v in extra] + item_cells(i, self.units))
        return buf.getvalue()


def item_cells(i: KeyItem, units) -> list[str]:
    """One key row: quantity, kind, unit, answer (magnitude), direction, sense, tolerance, direction
    tolerance, how the tolerance was found (:attr:`KeyItem.basis`), the text as printed."""
    v = i.value
    if isinstance(v, Vec):
        mag, direction, sense = units.convert(i.kind, v.norm()), f"{i.direction:.6g}", ""
    else:
        mag, direction = units.convert(i.kind, abs(float(v))), ""
        sense = ("ccw" if v > 0 else "cw" if v < 0 else "") if i.kind in ("angular velocity", "angular acceleration",
                                                                        "torque") else ""
        if not sense:
            mag = units.convert(i.kind, float(v))
    return [i.name, i.kind, units.symbol(i.kind), f"{mag:.10g}", direction, sense,
            f"{units.convert(i.kind, i.tolerance):.4g}" if i.kind != "angle" else f"{math.degrees(i.tolerance):.4g}",
            f"{i.direction_tolerance:.3g}" if i.direction_tolerance is not None else "", i.basis, i.text]


def _info(study: Study, date: str, title: str, number: str, notes: Sequence[str]) -> SheetInfo:
    s = study.scene
    return SheetInfo(title=title, drawing_number=number, paper=s.paper, orientation=s.orientation, date=date,
                     units=s.units, notes=tuple(notes), scales=s.scales)


def lab_for(study: Study, *, epoch: int | None = None, label: str = "", bare: bool = False) -> Lab:
    """The problem sheet, worked solution and key of a solved ``study`` (run with the space diagram
    dimensioned if the problem sheet is to carry dimensions: :func:`dimensioned`).  ``label`` is added
    to the titles (a batch's "variant 7"); ``bare``: the problem sheet without the construction steps."""
    s = study.scene
    date = sheet_date(epoch)
    suffix = f" ({label})" if label else ""
    worked = compose_sheets(study.construction, _info(study, date, s.title + suffix, s.drawing_number,
                                                        study.notes + study.warnings),
                            [ResultRow(q, g, a, d) for q, g, a, d in study.table().text])
    scales = {k: v for sh in worked for k, v in sh.diagram_scales.items()}
    stated = _stated(study)
    every = key_items(study, scales)
    items = tuple(i for i in every if i.magnitude_text not in stated)    # what the problem states is not asked
    given = tuple(given_lines(study, items))
    problem = problem_sheets(study, scales, given, items, date, suffix, bare=bare)
    comps = {c.name: c for c in study.comparisons}
    key_rows = [ResultRow(i.shown, i.text, i.analytic or "n/a", study.difference_text(comps[i.name]),
                          f"accept {i.tolerance_text}") for i in items]
    drawn = "; ".join(t for sh in worked for _, t in sh.scales)
    told = [f"{i.shown} = {i.text} is stated by the problem (not asked)." for i in every if i not in items]
    key_notes = tuple(told) + ("Accepted at drawing accuracy: 1 mm on paper at the worked sheet's scale for a "
                         "value read off a diagram (its direction within the angle 1 mm subtends, at least "
                         "1\u00b0); a value worked out from readings (V/L, F h) within the error propagated from theirs; the "
                         "sense of a rate must be right.",) \
        + ((f"The worked solution and the problem sheet are drawn at: {drawn}.",) if drawn else ())
    key = compose_sheets(Construction(s.title, ()), _info(study, date, f"{s.title}{suffix} \u2013 answer key",
                                                          f"{s.drawing_number}-K", key_notes), key_rows,
                         given=given[:-1] if items else given,
                         unit_kinds=sorted({v.kind for st in study.construction.steps for _, v in st.values}))
    return Lab(problem, tuple(worked), tuple(key), items, given, s.units)


# ---- the problem sheet ---------------------------------------------------------------------------------

def _stated(study: Study) -> set[str]:
    """The values the problem sheet prints as data, as it prints them ("20.00 deg")."""
    from ..layout.formats import value_text
    _, shown = problem_construction(study.construction, unknown=unknowns(study))
    units = study.scene.units
    out = set()
    for v in shown:
        if v.value is not None and v.kind not in ("scale", "paper length", "number"):
            try:
                out.add(value_text(units, v.kind, abs(v.value)))
            except (ValueError, KeyError):
                continue
    return out


def _given_like(step: Step) -> bool:
    """A step that states the problem: given, or drawing only what the problem states on the space
    diagram (the position found dyad by dyad, the dimensions)."""
    if step.kind is StepKind.GIVEN:
        return True
    if step.kind is StepKind.ANSWER:
        return False
    return bool(step.entities) and all(e.diagram.kind == "space" and e.role in _POSITION_ROLES for e in step.entities)


def unknowns(study: Study) -> frozenset[tuple[str, float]]:
    """The values, as (kind, magnitude), a problem asks for that a worked sheet states as the data of its
    space diagram: an inverse position problem's crank angles (every solution: :mod:`drafting.families.
    linkage.inverse`) and a driving slider's crank rates (omega and alpha, read off the polygons)."""
    s = study.scene
    out: set[tuple[str, float]] = set()
    inv = getattr(s, "inverse", None)
    if inv is not None:
        out.update(("angle", float(t)) for t in inv.solutions)
    dc = getattr(s, "driven", None)
    if dc is not None:
        out.update({("angular velocity", abs(dc.omega)), ("angular acceleration", abs(dc.alpha))})
    return frozenset(out)


def _asked(v, unknown) -> bool:
    return v.value is not None and (v.kind, abs(v.value)) in unknown


def problem_construction(c: Construction, bare: bool = False,
                         unknown: frozenset[tuple[str, float]] = frozenset()) -> tuple[Construction, set]:
    """The construction as a problem sheet shows it, and the values it may print: the space diagram
    keeps what the problem states; a sense of turning in a step that works something out is blanked (the
    crank's own is in the given data).  ``bare``: every step keeps its entities but not its words, equation or table
    (the problem without the recipe: its data are in the Given list).  ``unknown``: values the problem
    asks for (:func:`unknowns`) -- never printed; once a step states an unknown crank angle the space
    diagram keeps nothing more (the frame alone: the links drawn at the answer would give it away)."""
    steps = []
    shown = set()
    posed = False               # a step has stated an unknown crank angle: the pose drawn from here on is an answer
    for st in c.steps:
        given = _given_like(st)
        posed = posed or any(v.kind == "angle" and _asked(v, unknown) for _, v in st.values)
        if given:
            shown.update(v for _, v in st.values if not _asked(v, unknown))
        ents = tuple(e for e in st.entities if e.diagram.kind != "space" or
                     (not posed and e.role in SHOWN_ROLES and (given or e.role is not Role.DIMENSION)))
        words = st.words
        if not given:           # a sense of turning found on the way (the Coriolis rule names omega_3's) is an answer
            words = _SENSE_WORDS.sub(BLANK, words)
        if bare:                # the data are in the Given list; the steps' words are the recipe
            steps.append(replace(st, entities=ents, words="", equation=None, table=()))
            continue
        steps.append(replace(st, entities=ents, words=words))
    return Construction(c.title, tuple(steps)), shown


def _hook(shown: set):
    def values(v, default):
        if v.kind == "scale" or v in shown:
            return default(v)
        return BLANK
    return values


def blank_panel(panel, scale=None):
    """``panel`` framed empty (its heading, scale and scale bar; nothing drawn); held at ``scale`` (a
    DiagramScale of the worked sheet) when given."""
    b = copy.copy(held_to(panel, scale.units_per_mm) if scale is not None else panel)
    b.blank = True
    return b


def problem_sheets(study: Study, scales, given: Sequence[str], items: Sequence[KeyItem], date: str,
                   suffix: str = "", bare: bool = False) -> tuple[Sheet, ...]:
    s = study.scene
    unknown = unknowns(study)
    c, shown = problem_construction(study.construction, bare, unknown)
    rows = [ResultRow(i.shown, ANSWER_LINE, "", "") for i in items]
    info = _info(study, date, f"{s.title}{suffix} \u2013 problem", f"{s.drawing_number}-P", ())
    posed = any(kind == "angle" for kind, _ in unknown)         # the mechanism's pose is asked for

    def room(p):
        """An inverse problem's space diagram: the frame where the worked sheet draws it, in the room of
        the whole mechanism (drawn at the angle to be found)."""
        if not posed or p.key != "space":
            return p
        p = copy.copy(p)
        whole = [e for e in study.construction.entities() if e.diagram.key == p.key and not is_panel_entity(e)]
        p.figure = RoomFigure(p.figure.entities, whole, p.figure.text)
        return p

    def held(panels):
        return [room(held_to(p, scales["space"].units_per_mm) if "space" in scales else p) if p.key == "space"
                else blank_panel(p, scales.get(p.key)) for p in panels]

    def free(panels):
        return [room(p) if p.key == "space" else blank_panel(p) for p in panels]
    try:
        return compose_sheets(c, info, rows, values=_hook(shown), panel_hook=held, given=given)
    except LayoutError:                       # the worked sheet's scales do not fit beside the givens
        return compose_sheets(c, info, rows, values=_hook(shown), panel_hook=free, given=given)


# ---- the given data ------------------------------------------------------------------------------------

def given_lines(study: Study, items: Sequence[KeyItem] = ()) -> list[str]:
    """The data of the problem in words, in the scene's units: what the scene's family states
    (:attr:`~drafting.families.registry.Family.given`: a linkage's links, pivots, points, guides, the
    crank's motion, the loads and masses) and what to find."""
    out = list(study.family.given(study))
    if items:
        out.append("Find: " + ", ".join(i.shown for i in items) + " (vectors with their directions, CCW "
                   "from +x; rates with their sense).")
    return out


# ---- writing -------------------------------------------------------------------------------------------

def lab_plan(lab: Lab, out_dir: Path, stem: str, formats: Sequence[str], *, dpi: float | None = None,
             epoch: int | None = None, csv_extra: Sequence[tuple[str, str]] = ()):
    """The files of one lab, for one :func:`~drafting.backends.files.write_outputs` call: ``stem-problem.*``,
    ``stem.*`` (the worked solution), ``stem-key.*`` and ``stem-key.csv``."""
    from ..backends.files import PNG_DPI, check_names, sheet_plan
    kw = {"dpi": dpi or PNG_DPI, "epoch": epoch}
    plan = sheet_plan(lab.problem, out_dir, f"{stem}-problem", formats, **kw)
    plan += sheet_plan(lab.worked, out_dir, stem, formats, **kw)
    plan += sheet_plan(lab.key, out_dir, f"{stem}-key", formats, **kw)
    key_csv = out_dir / f"{stem}-key.csv"
    check_names([key_csv], stem)
    text = lab.key_csv(csv_extra)
    plan.append((key_csv, lambda: text.encode("utf-8")))
    return plan


def write_lab(lab: Lab, out_dir: Path | str, stem: str, formats: Sequence[str] = ("svg", "pdf", "png"), *,
              epoch: int | None = None) -> list[Path]:
    """Write the lab's files together or not at all (an :class:`~drafting.backends.files.ExportError` names the
    file that could not be written)."""
    from ..backends.files import prepare_folder, remove_stale_temporaries, write_outputs
    out_dir = Path(out_dir)
    plan = lab_plan(lab, out_dir, stem, formats, epoch=epoch)
    prepare_folder(out_dir)
    remove_stale_temporaries(out_dir)
    return write_outputs(out_dir, stem, plan)


def dimensioned(scene):
    """The scene with its space diagram dimensioned: problem sheets are, unless the scene says
    ``[drawing] dimensions = false``."""
    problem = family(scene.kind).dimensioned_problem
    return replace(scene, dimensions=True) if problem and scene.dimensions is None else scene
