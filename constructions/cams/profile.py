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

import math
from dataclasses import dataclass, field

import numpy as np

from .laws import DWELL, TAU, Program, end_slope

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


def _rot(a: np.ndarray, x: np.ndarray, y: np.ndarray) -> np.ndarray:
    c, s = np.cos(a), np.sin(a)
    return np.stack([c * x - s * y, s * x + c * y])


def _J(v: np.ndarray) -> np.ndarray:
    return np.stack([-v[1], v[0]])


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
        u = _rot(a, np.zeros_like(th), np.ones_like(th))
        w = _rot(a, np.ones_like(th), np.zeros_like(th))
        prof = r * u + sg * d1 * w
        return Evaluation(th, s, d1, d2, d3, None, prof, np.zeros_like(th), None, f.base_radius + s + d2, u)
    if f.kind == OSC_FLAT:
        return _oscillating_face(f, th, s, d1, d2, d3)
    if f.kind == OSCILLATING:
        # the roller centre B = A + l u(gamma0 - psi): the swing psi = s lifts it away from O
        g = f.gamma0 - s
        L = f.arm_length
        u = np.stack([np.cos(g), np.sin(g)])
        q = np.stack([f.pivot_distance + L * u[0], L * u[1]])
        bpsi = -L * _J(u)                      # dB/dpsi
        q1 = bpsi * d1
        q2 = -L * u * d1 ** 2 + bpsi * d2
    else:
        e, d0 = f.offset, f.d0
        q = np.stack([np.full_like(th, e), d0 + s])
        q1 = np.stack([np.zeros_like(th), d1])
        q2 = np.stack([np.zeros_like(th), d2])
    P = _rot(a, q[0], q[1])
    v1 = q1 - sg * _J(q)
    v2 = q2 - 2 * sg * _J(q1) - q
    P1 = _rot(a, v1[0], v1[1])
    P2 = _rot(a, v2[0], v2[1])
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


def face_terms(f: Follower, s, d1, d2=None):
    """An oscillating flat face in the fixed frame, from the swing s = psi and its derivatives:
    ``(beta, c, t, rho, turn)`` -- the arm's angle beta = beta0 + psi at the pivot from the line to O, the
    face's distance c = a sin beta - e_f from O, the contact's place t along the face from the foot of the
    perpendicular from O, the profile's radius of curvature rho (None without s'') and the face's turning
    rate relative to the cam, ``-(sigma + s')`` (see :func:`_oscillating_face`)."""
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


def _oscillating_face(f: Follower, th, s, d1, d2, d3) -> Evaluation:
    """The oscillating flat face's envelope.  The arm is pivoted at A = (a, 0); at swing psi it makes beta =
    beta0 + psi with the line AO, its face's unit normal (away from O) ``n = (sin beta, cos beta)`` and the face
    ``p . n = c``, ``c = a sin beta - e_f``; in the cam frame the normal's angle is ``phi = pi/2 - beta -
    sigma theta``.  The envelope of the lines ``p . N(phi) = c`` is ``C = c N + (dc/dphi) T`` (T = J N: the
    support-function form), with ``dc/dphi = c' / phi' = -a cos(beta) s' / (sigma + s')``; its radius of
    curvature is ``rho = c + d2c/dphi2 = c + a (sigma cos(beta) s'' - sin(beta) s'^2 (sigma + s')) / (sigma + s')^3``."""
    sg = f.sense
    beta, c, t, rho, _ = face_terms(f, s, d1, d2)
    n = np.stack([np.sin(beta), np.cos(beta)])
    jn = _J(n)
    cf = c * n + t * jn                               # the contact in the fixed frame
    a = -sg * th
    N = _rot(a, n[0], n[1])
    prof = _rot(a, cf[0], cf[1])
    # the pressure angle: between the common normal n and the way the follower's point at the contact is
    # driven (the swing turns the arm clockwise about A in the fixed frame: v ~ -J (C - A))
    rx, ry = cf[0] - f.pivot_distance, cf[1]
    vx, vy = ry, -rx
    phi = sg * np.arctan2(vx * n[1] - vy * n[0], vx * n[0] + vy * n[1])
    along = t + f.pivot_distance * np.cos(beta)
    return Evaluation(th, s, d1, d2, d3, None, prof, phi, None, rho, N, c, along)


def convex_curvature_pitch(program: Program, f: Follower, theta) -> np.ndarray:
    """The pitch curve's curvature, positive where convex (finite through inflections)."""
    ev = evaluate(program, f, theta)
    with np.errstate(divide="ignore"):
        return np.where(np.isfinite(ev.rho_pitch), 1.0 / ev.rho_pitch, 0.0)


# -- searching along the cam angle ---------------------------------------------------------------------------

def segment_breaks(program: Program) -> np.ndarray:
    """The cam angles where the program's pieces meet (segment joins and laws' inner joins)."""
    return np.array(sorted({0.0, TAU} | {j.theta for j in program.joins()} | set(program.starts)))


def _grid(program: Program, per_piece: int) -> list[np.ndarray]:
    b = segment_breaks(program)
    return [np.linspace(lo, hi, per_piece) for lo, hi in zip(b[:-1], b[1:]) if hi - lo > 0]


def extremum(program: Program, fn, *, per_piece: int = 256, largest: bool = True) -> tuple[float, float]:
    """The cam angle and value of the largest (or smallest) of ``fn(theta)`` (a vectorised function)
    over the turn: a grid in every piece of the program, refined by narrowing grids round each piece's best
    (every piece at once: one call of ``fn`` per round)."""
    sgn = 1.0 if largest else -1.0

    def f(x: np.ndarray) -> np.ndarray:
        w = sgn * np.asarray(fn(x.ravel()), dtype=float).reshape(x.shape)
        return np.where(np.isfinite(w), w, -math.inf)

    g = np.array(_grid(program, per_piece))                 # pieces x per_piece
    v = f(g)
    rows = np.arange(len(g))
    k = np.argmax(v, axis=1)
    cand_x, cand_v = g[rows, k], v[rows, k]
    lo, hi = g[rows, np.maximum(k - 1, 0)], g[rows, np.minimum(k + 1, per_piece - 1)]
    u = np.linspace(0.0, 1.0, 33)
    for _ in range(8):                  # each round narrows every bracket 16-fold
        x = lo[:, None] + (hi - lo)[:, None] * u[None, :]
        w = f(x)
        j = np.argmax(w, axis=1)
        better = w[rows, j] >= cand_v
        cand_x = np.where(better, x[rows, j], cand_x)
        cand_v = np.where(better, w[rows, j], cand_v)
        lo, hi = x[rows, np.maximum(j - 1, 0)], x[rows, np.minimum(j + 1, 32)]
    b = int(np.argmax(cand_v))
    return float(cand_x[b]), float(sgn * cand_v[b])


def _boundaries(g, a: np.ndarray, b: np.ndarray, ga: np.ndarray) -> np.ndarray:
    """Where ``g`` changes sign inside each bracket [a, b] (g(a) = ga on the one side): every bracket cut in
    16 at once per round (one call of ``g``), to 1e-15 rad."""
    u = np.arange(1, 16) / 16.0
    pos = ga > 0
    for _ in range(16):
        if not np.max(b - a) >= 1e-15:
            break
        x = a[:, None] + (b - a)[:, None] * u[None, :]
        side = (np.asarray(g(x.ravel()), dtype=float).reshape(x.shape) > 0) == pos[:, None]
        # the first point on the far side (16: none, the boundary lies past the last point)
        first = np.where(side.all(axis=1), 15, np.argmin(side, axis=1))
        xa = np.concatenate([a[:, None], x, b[:, None]], axis=1)
        rows = np.arange(len(a))
        a, b = xa[rows, first], xa[rows, first + 1]
    return 0.5 * (a + b)


def spans(program: Program, g, *, per_piece: int = 256) -> list[tuple[float, float]]:
    """The cam-angle intervals where ``g(theta) > 0`` (g vectorised), ends found by cutting their brackets."""
    grid = np.array(_grid(program, per_piece))
    v = np.asarray(g(grid.ravel()), dtype=float).reshape(grid.shape)
    inside = v > 0
    # the brackets of every change of side, found together
    pi, ki = np.nonzero(inside[:, 1:] != inside[:, :-1])
    ends = _boundaries(g, grid[pi, ki], grid[pi, ki + 1], v[pi, ki]) if len(pi) else np.zeros(0)
    out: list[list[float]] = []
    for p in range(len(grid)):
        start = grid[p, 0] if inside[p, 0] else None
        for k, x in zip(ki[pi == p], ends[pi == p]):
            if inside[p, k + 1]:
                start = x
            else:
                out.append([start, x])
                start = None
        if start is not None:
            out.append([start, grid[p, -1]])
    merged: list[list[float]] = []
    for a, b in out:
        if merged and abs(a - merged[-1][1]) < 1e-12:
            merged[-1][1] = b
        else:
            merged.append([a, b])
    if len(merged) > 1 and merged[0][0] <= 1e-12 and merged[-1][1] >= TAU - 1e-12:
        merged[0][0] = merged[-1][0] - TAU
        merged.pop()
    return [(a, b) for a, b in merged]


# -- the analysis ----------------------------------------------------------------------------------------------

CUSP_REL = 1e-9
"""The roller radius is *at* the cusp limit when it equals the pitch curve's smallest convex radius of
curvature within this fraction of the cam's size (designed tangency built from floats reads as equal)."""


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
    phi_t, phi = extremum(program, lambda x: np.abs(evaluate(program, f, x).pressure_angle))
    phi = float(evaluate(program, f, np.array([phi_t])).pressure_angle[0])
    if f.kind == OSC_FLAT:
        check_face(program, f)
    def profile_rho(x):
        e = evaluate(program, f, x)
        return e.rho_profile if f.kind in FACES else np.where(e.rho_pitch > 0, e.rho_profile, np.inf)

    rp_t, rp = extremum(program, profile_rho, largest=False)
    undercut: list[tuple[float, float]] = []
    cusps: list[float] = []
    min_pitch = None
    rb_min = width = None
    if f.kind in FACES:
        # rho = rb + s + s'' must stay positive: rb > max(-(s + s'')) (a translating face)
        if f.kind == FLAT:
            q_t, negq = extremum(program, lambda x: -sum(program.derivatives(x)[0:3:2]))
            rb_min = max(negq, 0.0)
        tol = CUSP_REL * size
        g = lambda x: -evaluate(program, f, x).rho_profile      # noqa: E731
        if abs(rp) <= tol:
            cusps.append(rp_t)
        elif rp < 0:
            undercut = spans(program, g)
        if f.kind == FLAT:
            lo = float(np.min(f.sense * ev.ds)); hi = float(np.max(f.sense * ev.ds))
            lo = min(lo, extremum(program, lambda x: f.sense * program.derivatives(x)[1], largest=False)[1])
            hi = max(hi, extremum(program, lambda x: f.sense * program.derivatives(x)[1])[1])
        else:
            # along the face from the foot of the pivot: a cos(beta) sigma / (sigma + s')
            lo = min(float(np.min(ev.along)), extremum(program, lambda x: evaluate(program, f, x).along,
                                                       largest=False)[1])
            hi = max(float(np.max(ev.along)), extremum(program, lambda x: evaluate(program, f, x).along)[1])
        width = (lo, hi)
    elif f.kind in (ROLLER, OSCILLATING):
        kt, kmax = extremum(program, lambda x: convex_curvature_pitch(program, f, x))
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
    segs, n = program.segments, len(program.segments)

    def slope(i: int, u: float) -> float:
        seg = segs[i]
        return 0.0 if seg.kind == DWELL else seg.sign * seg.lift * end_slope(seg.law, u) / seg.beta
    scale = max(program.lift, 1e-300)
    return [float(program.starts[(i + 1) % n]) for i in range(n)
            if abs(slope(i, 1.0) - slope((i + 1) % n, 0.0)) > 1e-9 * scale]


def check_face(program: Program, f: Follower) -> None:
    """An oscillating flat face must turn against the cam all the turn (sigma + s' keeps the sign of sigma:
    else the face stands still relative to the cam and the envelope runs off) and lift away from it (the
    arm below square to the line of centres: beta0 + psi < 90 deg)."""
    t, k = extremum(program, lambda x: f.sense * program.derivatives(x)[1], largest=False)
    if 1.0 + k <= 1e-9:
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
    return _trim(cp.follower, cp.samples if samples is None else samples, cp.size)


def _trim(f: Follower, ev: Evaluation, size: float) -> np.ndarray:
    C = ev.profile
    n = C.shape[1]
    tol = 1e-9 * size
    keep = np.ones(n, dtype=bool)
    if f.kind in FACES:
        # a point is cut if some face line lies between it and the centre: p . u_j > rb + s_j
        U, r = ev.normal, (f.base_radius + ev.s if ev.support is None else ev.support)
        for lo in range(0, n, 512):
            d = C[:, lo:lo + 512].T @ U - r[None, :]
            keep[lo:lo + 512] = np.max(d, axis=1) <= tol
    else:
        # squared distances against the squared limit (the same decision as the distances, without a root),
        # each run of 128 neighbouring points against only the roller centres inside its bounding box grown
        # by the roller's radius (no centre outside it can come within rr of any of them)
        P = ev.pitch
        rr = f.roller_radius
        limit = (rr - tol) ** 2
        for lo in range(0, n, 128):
            c = C[:, lo:lo + 128]
            near = ((P[0] > c[0].min() - rr) & (P[0] < c[0].max() + rr) &
                    (P[1] > c[1].min() - rr) & (P[1] < c[1].max() + rr))
            if not near.any():
                continue
            q = P[:, near]
            dx = c[0][:, None] - q[0][None, :]
            dy = c[1][:, None] - q[1][None, :]
            dx *= dx
            dy *= dy
            dx += dy
            keep[lo:lo + 128] = np.min(dx, axis=1) >= limit
    if keep.all():
        return C
    if not keep.any():
        raise ValueError("no point of the profile survives: the follower cuts the whole cam away")
    if f.kind in FACES:
        # the cam a flat face leaves is the intersection of the half-planes behind its face lines: convex,
        # so its boundary is the convex hull of the envelope points no face line cuts (shapely; a corner
        # where the envelope folds becomes the chord across it)
        from shapely.geometry import MultiPoint
        hull = MultiPoint(C[:, keep].T).convex_hull
        xy = np.asarray(hull.exterior.coords)[:-1][::-1] if f.sense < 0 else np.asarray(hull.exterior.coords)[:-1]
        return xy.T
    # rotate so that index 0 is kept, then walk the runs
    k0 = int(np.argmax(keep))
    idx = np.roll(np.arange(n), -k0)
    kp = keep[idx]
    pts: list[np.ndarray] = []
    i = 0
    while i < n:
        if kp[i]:
            pts.append(C[:, idx[i]])
            i += 1
            continue
        j = i
        while j < n and not kp[j]:
            j += 1
        a0, a1 = C[:, idx[i - 1]], C[:, idx[i]]
        b0, b1 = C[:, idx[(j - 1) % n]], C[:, idx[j % n]]
        x = _cross_point(a0, a1, b0, b1)
        if x is not None:
            pts.append(x)
        i = j
    return np.array(pts).T


def _cross_point(a0, a1, b0, b1):
    """Where the chords a0-a1 and b0-b1 cross (their lines' crossing, kept if it lies near both)."""
    da, db = a1 - a0, b1 - b0
    den = da[0] * db[1] - da[1] * db[0]
    if den == 0:
        return None
    w = b0 - a0
    t = (w[0] * db[1] - w[1] * db[0]) / den
    return a0 + t * da


__all__ = ["Follower", "KNIFE", "ROLLER", "FLAT", "FOLLOWERS", "evaluate", "analyse", "CamProfile", "Evaluation",
           "OSCILLATING", "OSC_FLAT", "FACES", "face_terms", "check_face", "extremum", "spans", "trim", "cam_size", "profile_samples", "profile_points", "chord_error_rate"]


# the profile alone (export, machining, the benchmark): :mod:`.sampling`, imported last (it uses the above)
from .sampling import chord_error_rate, profile_points, profile_samples  # noqa: E402
