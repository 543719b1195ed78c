"""The follower of a disk cam: its kinds and dimensions, and an oscillating flat face's terms.

A translating follower's axis is parallel to +y at the signed offset ``e`` along +x of the fixed frame;
an oscillating follower's arm is pivoted at A = (a, 0).  How each kind's profile follows from the motion
program is :mod:`.envelope`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..entities import Circle, FollowerBody, Pivot, Role, Segment
from ..geometry import Vec

KNIFE, ROLLER, FLAT, OSCILLATING = "knife-edge", "roller", "flat-faced", "oscillating roller"
OSC_FLAT = "oscillating flat-faced"
FOLLOWERS = (KNIFE, ROLLER, FLAT, OSCILLATING, OSC_FLAT)
FACES = (FLAT, OSC_FLAT)
"""The followers whose profile is the envelope of face lines (support function), not of roller circles."""


@dataclass(frozen=True, slots=True)
class Follower:
    """A follower: its ``kind``, the cam's base circle radius ``rb`` (to the profile), the roller radius ``rr``
    (roller only), the signed ``offset`` e of a translating follower's axis (+x of the fixed frame, the axis
    pointing +y), and the cam's sense ``sense`` (+1 CCW, -1 CW); an oscillating follower's pivot, arm and
    face below."""

    kind: str
    base_radius: float
    roller_radius: float = 0.0
    offset: float = 0.0
    sense: int = 1
    pivot_distance: float = 0.0
    """Oscillating roller: the arm's pivot A at (pivot_distance, 0) from the cam centre."""
    arm_length: float = 0.0
    """Oscillating roller: the arm from its pivot to the roller centre; the program's lift is its swing (rad)."""
    face_offset: float = 0.0
    """Oscillating flat face: the face's distance from the line through the pivot along the arm, towards the
    cam (0: the face runs through the pivot)."""

    def __post_init__(self) -> None:
        if self.kind not in FOLLOWERS:
            raise ValueError(f"{self.kind!r} is not a follower ({', '.join(FOLLOWERS)})")
        if self.sense not in (1, -1):
            raise ValueError("the cam's sense is +1 (CCW) or -1 (CW)")
        if not self.base_radius > 0:
            raise ValueError("the base circle needs a positive radius")
        if self.kind in (ROLLER, OSCILLATING) and not self.roller_radius > 0:
            raise ValueError("a roller follower needs a positive roller radius")
        if self.kind not in (ROLLER, OSCILLATING) and self.roller_radius:
            raise ValueError(f"a {self.kind} follower has no roller")
        if self.kind not in FACES and abs(self.offset) >= self.prime_radius:
            raise ValueError("the offset must be smaller than the prime circle's radius")
        if self.kind != OSC_FLAT and self.face_offset:
            raise ValueError("only an oscillating flat face has a face offset")
        if self.kind == OSC_FLAT:
            a = self.pivot_distance
            if not a > 0:
                raise ValueError("an oscillating flat-faced follower needs its pivot distance")
            if self.arm_length or self.offset:
                raise ValueError("an oscillating flat face has no arm length or axis offset (its pivot and face "
                                 "offset place it)")
            if not -a < self.base_radius + self.face_offset < a:
                raise ValueError("the face cannot touch the base circle: base radius + face offset must lie "
                                 "between -pivot distance and the pivot distance")
        if self.kind == OSCILLATING:
            a, l, rp = self.pivot_distance, self.arm_length, self.prime_radius
            if not (a > 0 and l > 0):
                raise ValueError("an oscillating follower needs its pivot distance and arm length")
            if not abs(a - l) < rp < a + l:
                raise ValueError("the arm cannot reach the prime circle from its pivot: the prime circle's radius "
                                 "must lie between |pivot distance - arm| and pivot distance + arm")
            if self.offset:
                raise ValueError("an oscillating follower has no offset (its pivot places it)")

    @property
    def gamma0(self) -> float:
        """Oscillating roller: the arm's angle at zero lift (from +x, the arm above the line OA)."""
        a, l, rp = self.pivot_distance, self.arm_length, self.prime_radius
        return math.acos((rp * rp - a * a - l * l) / (2 * a * l))

    @property
    def beta0(self) -> float:
        """Oscillating flat face: the angle at the pivot between the line to the cam centre and the arm at
        zero lift, where the face touches the base circle: ``a sin beta0 - e_f = rb``."""
        return math.asin((self.base_radius + self.face_offset) / self.pivot_distance)

    @property
    def prime_radius(self) -> float:
        return self.base_radius + self.roller_radius

    @property
    def d0(self) -> float:
        """The height of the pitch point above O along the axis at zero lift."""
        return math.sqrt(self.prime_radius ** 2 - self.offset ** 2)


def face_terms(f: Follower, s, d1, d2=None):
    """An oscillating flat face in the fixed frame, from the swing s = psi and its derivatives:
    ``(beta, c, t, rho, turn)`` -- the arm's angle beta = beta0 + psi at the pivot from the line to O, the
    face's distance c = a sin beta - e_f from O, the contact's place t along the face from the foot of the
    perpendicular from O, the profile's radius of curvature rho (None without s'') and the face's turning
    rate relative to the cam, ``-(sigma + s')`` (see :mod:`.envelope`)."""
    sg, a = f.sense, f.pivot_distance
    beta = f.beta0 + s
    cb, sb = np.cos(beta), np.sin(beta)
    c = a * sb - f.face_offset
    k = sg + d1
    t = -a * cb * d1 / k
    rho = None
    if d2 is not None:
        rho = c + a * (sg * cb * d2 - sb * d1 * d1 * k) / (k * k * k)
    return beta, c, t, rho, -k



def drawn_follower(f: Follower, diagram, end, reach: float, pivot=None, face=None) -> list:
    """The follower as drawn at station 0, in true size: a translating one's stem, end and guide with its
    end (roller centre, knife edge, foot of the face) at ``end``; an oscillating one's arm about its pivot
    ``pivot`` to the roller centre ``end`` or along the face ``face`` (its two ends, Vecs).  ``reach`` is the
    furthest the follower's end gets from the cam centre (the stem and its guide stand beyond it)."""
    end = Vec(float(end[0]), float(end[1]))
    if f.kind == OSCILLATING:
        A = Vec(float(pivot[0]), float(pivot[1]))
        return [Pivot("follower pivot", Role.GIVEN, diagram, A, "A"),
                Segment("follower arm", Role.GIVEN, diagram, A, end),
                Circle("follower roller", Role.GIVEN, diagram, end, f.roller_radius)]
    if f.kind == OSC_FLAT:
        A = Vec(float(pivot[0]), float(pivot[1]))
        p0, p1 = face
        return [Pivot("follower pivot", Role.GIVEN, diagram, A, "A"),
                Segment("follower arm", Role.GIVEN, diagram, A, p0),
                Segment("follower face", Role.GIVEN, diagram, p0, p1)]
    kind = {ROLLER: "roller", KNIFE: "knife", FLAT: "flat"}[f.kind]
    width = f.roller_radius if f.kind == ROLLER else 0.12 * f.base_radius
    top = 1.5 * reach - end.y
    return [FollowerBody("follower", Role.GIVEN, diagram, end, Vec(0.0, 1.0), kind, top, width,
                         1.3 * reach - end.y, 0.22 * reach, radius=f.roller_radius,
                         face=0.0 if face is None else face)]
