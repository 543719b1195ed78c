"""The analysis of a cam profile: the extreme pressure angle, the smallest radii of curvature, undercut
and cusps, a flat face's width and smallest base circle, and the valid (trimmed) profile.

The profile itself is the analytic envelope of :mod:`.envelope`; the searches along the cam angle are
:mod:`.search`, the trimming of folds :mod:`.trimming`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from .envelope import Evaluation, convex_curvature, convex_curvature_pitch, evaluate
from .follower import FACES, FLAT, KNIFE, OSC_FLAT, OSCILLATING, ROLLER, Follower
from ..tolerance import CUSP_REL, FACE_TURN_MIN, VELOCITY_JUMP_REL
from .laws import TAU, Program
from .search import extrema, extremum, spans
from .trimming import trim_envelope

@dataclass
class CamProfile:
    """What the analysis finds: the profile sampled at ``samples`` cam angles, the extreme pressure angle,
    the pitch curve's smallest radius of curvature, undercut spans, and the valid (trimmed) profile."""

    program: Program
    follower: Follower
    samples: Evaluation
    size: float
    max_pressure_angle: tuple[float, float]       # (theta, phi) of the largest |phi|
    min_rho_pitch: tuple[float, float] | None      # (theta, rho) of the smallest convex pitch radius
    min_rho_profile: tuple[float, float]           # (theta, rho) of the smallest profile radius
    undercut: list[tuple[float, float]]            # cam-angle spans where the profile folds (roller) or
                                                   # the flat face would need rho <= 0
    cusp_at: list[float]                           # cusp points at the limit
    min_base_radius: float | None                  # flat-faced: the smallest rb with rho > 0
    face_width: tuple[float, float] | None         # flat-faced: contact's reach either side of the axis
    trimmed: np.ndarray = field(repr=False, default=None)   # the valid profile, closed polyline 2 x M
    corners: list[float] = field(default_factory=list)      # joins where s' jumps: the profile turns a corner

    @property
    def undercut_free(self) -> bool:
        return not self.undercut and not self.cusp_at


def cam_size(program: Program, f: Follower) -> float:
    """The cam's size, the length every relative tolerance scales: the prime circle plus the lift (a flat
    face: the base circle plus the lift; an oscillating arm: its reach from the cam centre)."""
    if f.kind in (KNIFE, ROLLER):
        return f.prime_radius + program.lift
    if f.kind == FLAT:
        return f.base_radius + program.lift
    if f.kind == OSC_FLAT:
        return max(f.base_radius, f.pivot_distance)
    return max(f.prime_radius, f.pivot_distance + f.arm_length)


def analyse(program: Program, f: Follower, samples: int = 2048) -> CamProfile:
    th = np.linspace(0.0, TAU, samples, endpoint=False)
    ev = evaluate(program, f, th)
    size = cam_size(program, f)
    at = lambda x: evaluate(program, f, x)                  # noqa: E731
    # the searches along the turn, as many as can be at once in one batch (an oscillating face is checked
    # after its pressure angle and before anything else is searched: as it always was)
    def profile_rho(e):
        return e.rho_profile if f.kind in FACES else np.where(e.rho_pitch > 0, e.rho_profile, np.inf)

    searches = {"phi": (lambda e: np.abs(e.pressure_angle), True), "rho": (profile_rho, False)}
    if f.kind == FLAT:
        searches["negq"] = (lambda e: -sum([e.s, e.d2s]), True)    # rho = rb + s + s'' > 0: rb > max(-(s + s''))
        searches["lo"] = (lambda e: f.sense * e.ds, False)
        searches["hi"] = (lambda e: f.sense * e.ds, True)
    elif f.kind == OSC_FLAT:
        searches["lo"] = (lambda e: e.along, False)
        searches["hi"] = (lambda e: e.along, True)
    elif f.kind in (ROLLER, OSCILLATING):
        searches["k"] = (convex_curvature, True)
    found = {}
    if f.kind == OSC_FLAT:
        found["phi"] = extrema(program, at, [searches.pop("phi")])[0]
        check_face(program, f)
    found.update(zip(searches, extrema(program, at, list(searches.values()))))
    phi_t = found["phi"][0]
    phi = float(evaluate(program, f, np.array([phi_t])).pressure_angle[0])
    rp_t, rp = found["rho"]
    undercut: list[tuple[float, float]] = []
    cusps: list[float] = []
    min_pitch = None
    rb_min = width = None
    if f.kind in FACES:
        if f.kind == FLAT:
            rb_min = max(found["negq"][1], 0.0)
        tol = CUSP_REL * size
        g = lambda x: -evaluate(program, f, x).rho_profile      # noqa: E731
        if abs(rp) <= tol:
            cusps.append(rp_t)
        elif rp < 0:
            undercut = spans(program, g)
        # a flat face: the contact's reach sigma s' either side of the axis; an oscillating face: along it
        # from the foot of the pivot, a cos(beta) sigma / (sigma + s')
        reach = f.sense * ev.ds if f.kind == FLAT else ev.along
        width = (min(float(np.min(reach)), found["lo"][1]), max(float(np.max(reach)), found["hi"][1]))
    elif f.kind in (ROLLER, OSCILLATING):
        kt, kmax = found["k"]
        min_pitch = (kt, 1.0 / kmax) if kmax > 0 else None
        if min_pitch is not None:
            d = f.roller_radius * kmax - 1.0          # > 0: the roller is bigger than the tightest convex bend
            if abs(d) * f.roller_radius <= CUSP_REL * size:
                cusps.append(kt)
            elif d > 0:
                undercut = spans(program, lambda x: f.roller_radius * convex_curvature_pitch(program, f, x) - 1.0)
    out = CamProfile(program, f, ev, size, (phi_t, phi), min_pitch, (rp_t, rp), undercut, cusps, rb_min, width)
    out.corners = [] if f.kind == KNIFE else velocity_jumps(program)
    # a jump in s' (uniform motion) is a corner of the pitch curve: the envelope's branches there cross (a
    # fold to cut) or part (the roller's arc joins them); either way the profile is what the trim keeps
    out.trimmed = trim(out) if undercut or out.corners else ev.profile
    return out


def velocity_jumps(program: Program) -> list[float]:
    """Cam angles of the joins where the follower's velocity s' jumps (uniform motion meeting a dwell or
    another law): corners of the pitch curve."""
    n = len(program.segments)
    return [float(program.starts[(i + 1) % n]) for i in range(n)
            if abs(program.end_velocity(i, 1.0) - program.end_velocity((i + 1) % n, 0.0))
            > VELOCITY_JUMP_REL * program.lift]


def check_face(program: Program, f: Follower) -> None:
    """An oscillating flat face must turn against the cam all the turn (sigma + s' keeps the sign of sigma:
    else the face stands still relative to the cam and the envelope runs off) and lift away from it (the
    arm below square to the line of centres: beta0 + psi < 90 deg)."""
    t, k = extremum(program, lambda x: f.sense * program.derivatives(x)[1], largest=False)
    if 1.0 + k <= FACE_TURN_MIN:
        raise ValueError(f"the arm turns as fast as the cam at {math.degrees(t):.4g} deg (d psi / d theta = "
                         f"{-f.sense:+d}): the face stops turning relative to the cam and has no envelope; swing "
                         f"more slowly (a longer rise) or turn the cam the other way")
    top = f.beta0 + program.lift
    if not top < math.pi / 2:
        raise ValueError(f"the arm swings to {math.degrees(top):.4g} deg from the line of centres; beyond 90 deg the "
                         f"face comes back towards the cam: a longer pivot distance or a smaller swing")


def trim(cp: CamProfile, samples: Evaluation | None = None) -> np.ndarray:
    """The valid profile: envelope points that no roller position cuts into (a roller's centre is on the
    pitch curve, so a point nearer than rr to it is cut away), with each removed loop replaced by the
    crossing of the two branches.  A flat-faced cam with rho <= 0 is trimmed likewise by the face lines.
    ``samples`` (default: the analysis's own ``cp.samples``) gives the points to trim (its ``profile``, e.g.
    the denser set of an export) and the roller centres (its ``pitch``; a flat face: its ``normal`` and
    ``s``) that cut them; the two need not be as many.  ``cp`` is left as it is."""
    return trim_envelope(cp.follower, cp.samples if samples is None else samples, cp.size)
