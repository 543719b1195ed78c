"""The regions of a cam diagram too small to read at its scale, recorded as enlarged details
(:class:`~constructions.entities.Detail`): every undercut span (where the roller's envelope loops back
and the profile drawn is trimmed to a point) and every cusp at the undercut limit."""

from __future__ import annotations

import string

import numpy as np

from ..entities import Detail, Diagram, Role
from ..geometry import Vec
from .envelope import evaluate
from .profile import CamProfile

REACH = 0.2             # a detail's radius: this fraction of the roller radius ...
REACH_OF_SIZE = 0.03    # ... or of the cam's size, the larger


def profile_details(cp: CamProfile, diagram: Diagram) -> list[tuple[str, Detail]]:
    """The details of ``cp``'s profile, each with what it shows ("undercut", "cusp"): ``[(what,
    detail)]``, lettered A, B, ... in the order of the cam angle."""
    radius = max(REACH * cp.follower.roller_radius, REACH_OF_SIZE * cp.size)
    spots: list[tuple[float, str, Vec]] = []
    for a, b in cp.undercut:
        pts = evaluate(cp.program, cp.follower, np.linspace(a, b, 33)).profile
        spots.append((a, "undercut", Vec(float(pts[0].mean()), float(pts[1].mean()))))
    for t in cp.cusp_at:
        p = evaluate(cp.program, cp.follower, np.array([t])).profile
        spots.append((t, "cusp", Vec(float(p[0, 0]), float(p[1, 0]))))
    spots.sort(key=lambda s: s[0])
    return [(what, Detail(f"detail {letter}", Role.NOTE, diagram, at, radius, letter))
            for (_, what, at), letter in zip(spots, string.ascii_uppercase)]


def details_words(details: list[tuple[str, Detail]]) -> str:
    """" (the undercut, enlarged in details A and B)", or "" without details."""
    if not details:
        return ""
    whats = list(dict.fromkeys(w for w, _ in details))
    letters = [d.letter for _, d in details]
    named = letters[0] if len(letters) == 1 else ", ".join(letters[:-1]) + " and " + letters[-1]
    return f" ({' and '.join('the ' + w for w in whats)}, enlarged in detail{'s' if len(letters) > 1 else ''} {named})"
