"""The exact cam profile of a disk cam with a translating or oscillating follower: the analytic envelope.

Frames.  In the *fixed frame* the cam turns about the origin O; the follower's axis is parallel to +y at
the signed offset ``e`` along +x; the roller centre (the *pitch point*) is at ``q = (e, d0 + s)`` with
``d0 = sqrt(Rp^2 - e^2)``, ``Rp = rb + rr`` the prime circle's radius (``rr = 0`` for a knife edge).  The
profile lives in the *cam frame*: with the cam turned through ``theta`` in its sense ``sigma`` (+1 CCW,
-1 CW), the follower is seen from the cam laid out the opposite way, ``P(theta) = R(-sigma theta) q``
(the notes' "successive positions laid out opposite to the cam's rotation").

Derivatives of the pitch curve (``J`` the quarter turn CCW, ``R = R(-sigma theta)``)::

    P'   = R (q' - sigma J q)
    P''  = R (q'' - 2 sigma J q' - q)
    P''' = R (q''' - 3 sigma J q'' - 3 q' + sigma J q)

The pitch curve is run clockwise for a CCW cam (and the other way for a CW cam), so its outward normal
is ``n = sigma J t`` (``t`` the unit tangent) and its radius of curvature, positive where convex, is
``rho_p = -sigma |P'|^3 / (P' x P'')``.  The roller profile is the inner envelope of the roller circles,
``C = P - rr n``, whose radius of curvature is ``rho_p - rr``; where ``0 < rho_p < rr`` the envelope
folds back (undercut, a swallowtail), at ``rho_p = rr`` it has a cusp.

The flat-faced follower's face is square to its axis at ``rb + s`` from O; in the cam frame the face
lines are ``p . u = rb + s`` with ``u = R(-sigma theta) (0, 1)``; their envelope (``p . u' = s'``) touches
each face at ``sigma s'`` from the axis's foot: ``C = (rb + s) u + sigma s' w``, ``w = R(-sigma theta)(1, 0)``
(for a CW cam this is the notes' ``x = -(rb + s) sin theta - s' cos theta``, ``y = (rb + s) cos theta -
s' sin theta``), with radius of curvature ``rb + s + s''`` (needs > 0: rb > max(-(s + s''))).

The oscillating flat face.  The arm is pivoted at A = (a, 0); its face is a straight line fixed to it,
parallel to the arm's line through A and ``e_f`` from it towards the cam.  With ``beta`` the angle at A
between the line AO and the arm (the arm above OA), the face's unit normal away from O is ``n = (sin beta,
cos beta)`` (square to the arm's direction ``J n = (-cos beta, sin beta)``, which points from A over the
cam), and the face is the line ``p . n = c`` with ``c = n . A - e_f = a sin beta - e_f``, its distance from
O.  At zero lift it touches the base circle: ``a sin beta0 = rb + e_f``; the swing ``psi = s`` lifts it,
``beta = beta0 + psi`` (``c`` grows while ``beta < 90 deg``).  In the cam frame the normal's angle is
``phi = pi/2 - beta - sigma theta``, so the faces are the lines ``p . N(phi) = c`` with ``N = (cos phi, sin
phi)``.  A family of lines ``p . N = h`` has the envelope ``C = h N + (dh/dphi) T`` (``T = J N``; from
``C . N = h`` and, differentiating, ``C . T = dh/dphi`` since ``C' . N = 0`` on the envelope), and its radius
of curvature is ``h + d2h/dphi2`` (the support function's).  Here ``phi' = -(sigma + s')`` and ``c' = a cos
beta s'``, so the contact lies ``t = c'/phi' = -a cos(beta) s' / (sigma + s')`` along the face from the foot
of the perpendicular from O, and

    rho = c + t'/phi' = c + a (sigma cos(beta) s'' - sin(beta) s'^2 (sigma + s')) / (sigma + s')^3

(checked against numerical derivatives in the tests).  Along the face from the foot of the perpendicular
from A (``A - e_f n``) the contact is ``t + a cos beta = sigma a cos(beta) / (sigma + s')`` away: the face's
reach.  ``sigma + s'`` must keep the sign of sigma (the arm never turns as fast as the cam, else the face
stands still against it and has no envelope).  Independently, by Kennedy's theorem the common normal (n,
through the contact) passes through the instant centre of cam and arm on the line of centres, where both
move alike: ``sigma x_I = -s' (x_I - a)`` (the arm turns at ``-s'`` times the cam's speed), ``x_I = s' a /
(sigma + s')``; the contact is the foot of the perpendicular from ``(x_I, 0)`` to the face, whose place along
it, ``J n . (x_I, 0) = -x_I cos beta``, is ``t`` again (:mod:`.check` uses this form).

Pressure angle (the angle between the follower's axis and the common normal at the contact): relative to
the cam the pitch point moves along ``(sigma (d0 + s), s' - sigma e)``, so ``tan phi = (s' - sigma e) /
(d0 + s)`` -- the offset counts, and the roller does not (it sits on the prime circle).  A flat face
square to its axis has phi = 0.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .follower import FLAT, OSC_FLAT, OSCILLATING, Follower, face_terms
from .frames import pair as _pair, quarter_turn as _J, rotate as _rot, rotated as _rotated
from .laws import Program


@dataclass
class Evaluation:
    """The profile quantities at cam angles ``theta`` (arrays, SI; points as 2 x N arrays)."""

    theta: np.ndarray
    s: np.ndarray
    ds: np.ndarray
    d2s: np.ndarray
    d3s: np.ndarray
    pitch: np.ndarray | None          # roller centre (knife: contact) in the cam frame
    profile: np.ndarray               # the envelope point (contact with the cam)
    pressure_angle: np.ndarray
    rho_pitch: np.ndarray | None      # radius of curvature of the pitch curve (convex +)
    rho_profile: np.ndarray           # radius of curvature of the profile (convex +)
    normal: np.ndarray                # outward unit normal of the profile at the contact
    support: np.ndarray | None = None  # a face's distance from O (the face line p . normal = support)
    along: np.ndarray | None = None   # oscillating flat face: the contact's distance along the face from the
                                      # foot of the pivot (towards the cam)


def evaluate(program: Program, f: Follower, theta) -> Evaluation:
    th = np.asarray(theta, dtype=float)
    s, d1, d2, d3 = program.derivatives(th)
    sg = f.sense
    a = -sg * th
    if f.kind == FLAT:
        r = f.base_radius + s
        ca, sa = np.cos(a), np.sin(a)
        u = _rotated(ca, sa, np.zeros_like(th), np.ones_like(th))
        w = _rotated(ca, sa, np.ones_like(th), np.zeros_like(th))
        prof = r * u + sg * d1 * w
        return Evaluation(th, s, d1, d2, d3, None, prof, np.zeros_like(th), None, f.base_radius + s + d2, u)
    if f.kind == OSC_FLAT:
        return _oscillating_face(f, th, s, d1, d2, d3)
    if f.kind == OSCILLATING:
        # the roller centre B = A + l u(gamma0 - psi): the swing psi = s lifts it away from O
        g = f.gamma0 - s
        L = f.arm_length
        u = _pair(np.cos(g), np.sin(g))
        q = _pair(f.pivot_distance + L * u[0], L * u[1])
        bpsi = -L * _J(u)                      # dB/dpsi
        q1 = bpsi * d1
        q2 = -L * u * d1 ** 2 + bpsi * d2
    else:
        e, d0 = f.offset, f.d0
        q = _pair(np.full_like(th, e), d0 + s)
        q1 = _pair(np.zeros_like(th), d1)
        q2 = _pair(np.zeros_like(th), d2)
    ca, sa = np.cos(a), np.sin(a)                  # one turn for the point and its derivatives
    P = _rotated(ca, sa, q[0], q[1])
    v1 = q1 - sg * _J(q)
    v2 = q2 - 2 * sg * _J(q1) - q
    P1 = _rotated(ca, sa, v1[0], v1[1])
    P2 = _rotated(ca, sa, v2[0], v2[1])
    speed = np.hypot(P1[0], P1[1])
    cross = P1[0] * P2[1] - P1[1] * P2[0]
    with np.errstate(divide="ignore", invalid="ignore"):
        rho = -sg * speed ** 3 / cross
    t = P1 / speed
    n = sg * _J(t)
    prof = P - f.roller_radius * n
    if f.kind == OSCILLATING:
        # between the common normal and the roller centre's path (square to the arm, the way of lift)
        nf = _rot(-a, n[0], n[1])
        dirn = -_J(u)
        phi = sg * np.arctan2(dirn[0] * nf[1] - dirn[1] * nf[0], dirn[0] * nf[0] + dirn[1] * nf[1])
    else:
        phi = np.arctan2(d1 - sg * e, d0 + s)
    return Evaluation(th, s, d1, d2, d3, P, prof, phi, rho, rho - f.roller_radius, n)


def _oscillating_face(f: Follower, th, s, d1, d2, d3) -> Evaluation:
    """The oscillating flat face's envelope.  The arm is pivoted at A = (a, 0); at swing psi it makes beta =
    beta0 + psi with the line AO, its face's unit normal (away from O) ``n = (sin beta, cos beta)`` and the face
    ``p . n = c``, ``c = a sin beta - e_f``; in the cam frame the normal's angle is ``phi = pi/2 - beta -
    sigma theta``.  The envelope of the lines ``p . N(phi) = c`` is ``C = c N + (dc/dphi) T`` (T = J N: the
    support-function form), with ``dc/dphi = c' / phi' = -a cos(beta) s' / (sigma + s')``; its radius of
    curvature is ``rho = c + d2c/dphi2 = c + a (sigma cos(beta) s'' - sin(beta) s'^2 (sigma + s')) / (sigma + s')^3``."""
    sg = f.sense
    beta, c, t, rho, _ = face_terms(f, s, d1, d2)
    n = _pair(np.sin(beta), np.cos(beta))
    jn = _J(n)
    cf = c * n + t * jn                               # the contact in the fixed frame
    a = -sg * th
    ca, sa = np.cos(a), np.sin(a)
    N = _rotated(ca, sa, n[0], n[1])
    prof = _rotated(ca, sa, cf[0], cf[1])
    # the pressure angle: between the common normal n and the way the follower's point at the contact is
    # driven (the swing turns the arm clockwise about A in the fixed frame: v ~ -J (C - A))
    rx, ry = cf[0] - f.pivot_distance, cf[1]
    vx, vy = ry, -rx
    phi = sg * np.arctan2(vx * n[1] - vy * n[0], vx * n[0] + vy * n[1])
    along = t + f.pivot_distance * np.cos(beta)
    return Evaluation(th, s, d1, d2, d3, None, prof, phi, None, rho, N, c, along)


def convex_curvature_pitch(program: Program, f: Follower, theta) -> np.ndarray:
    """The pitch curve's curvature, positive where convex (finite through inflections)."""
    return convex_curvature(evaluate(program, f, theta))


def convex_curvature(ev: Evaluation) -> np.ndarray:
    """:func:`convex_curvature_pitch` read off an evaluation."""
    with np.errstate(divide="ignore"):
        return np.where(np.isfinite(ev.rho_pitch), 1.0 / ev.rho_pitch, 0.0)
