"""Vector-loop solution of any linkage that is a crank followed by dyads, vectorised over crank angles.

This is the analytic check for compound mechanisms (a four-bar driving a slider through a second
coupler, Watt and Stephenson six-bars, ...) that :mod:`constructions.analytic`'s four-bar and slider-crank have no
single closed form for.  It is an independent code path from the graphical construction: it reads only the data of
the :class:`~constructions.linkage.Mechanism` (pivots, link lengths, guides, branches) and never calls
the geometry kernel, the construction's assembly plan, or the velocity polygon.  It orders the joints
itself, and solves each dyad in a different form from the kernel's circle intersections:

* RRR dyad (joint J on a link of length a to a known joint P and a link of length b to a known joint
  Q): the angle form of the law of cosines, theta_PJ = angle(Q - P) +/- A with the triangle angle A
  at P taken as atan2 of its sine and cosine (Heron and the law of cosines, below).
* RRP dyad (joint J on a link of length a to a known joint P, J's block on a fixed straight guide):
  the quadratic in the slider parameter s along the guide.
* Velocities by differentiating the loop-closure (constant-length) equations and solving the
  resulting linear equations (Cramer's rule); link angular velocities from the relative velocities.
* Accelerations by differentiating the constraint equations a second time: the same 2x2 matrix as
  for the velocities, a right-hand side with the squared relative speeds; link angular
  accelerations from the relative accelerations.

Conventions
-----------
* Guides are straight and fixed to the frame: a joint sliding in a slot of a moving link raises
  DegenerateInput (not modelled yet), as does any joint that is not a crank tip, an RRR or an RRP
  dyad (e.g. a joint placed as the third point of a ternary link).  A pin in a fixed slot (a slide
  with no block number) is solved like a block, and has no angular entry.
* SI, angles CCW from +x, omega and alpha CCW positive, as everywhere in the engine.
* ``theta``, ``omega`` and ``alpha`` are broadcast against each other; every array in the result has
  that shape (0-d for scalars) and is read-only.
* Branches follow :class:`~constructions.linkage.Branch`: for two links, sign +1 puts J to the LEFT
  of the directed line reference[0] -> reference[1] (cross(ref1 - ref0, J - ref0) > 0); for a guide,
  +1 puts J AHEAD of the foot of the perpendicular from reference[0], along the guide direction
  (cos angle, sin angle).
* An angle at which some dyad cannot close gives ``assembles == False`` and NaN for every moving
  joint, point, velocity and acceleration, and for every angular velocity and angular acceleration
  except the crank's (the inputs) and the slider blocks' (0).  The fixed pivots keep their
  coordinates and zero velocity and acceleration.
* Decisions are three-way with a tolerance ``ASSEMBLY_RTOL * L`` relative to the one scene size
  ``L = m.size`` (:mod:`constructions.tolerance`; it does not move with the origin): a gap factor within the tolerance of zero is a tangency, snapped to exactly zero -- the
  mechanism assembles, the joint lies on the line of centres (or square to the guide), its
  condition is 0 and its velocities and accelerations are NaN.
* ``conditions[J]`` is the sine of the angle between the two velocity trial lines of J (the sine of
  the angle between the two links at J, or |cos| of the angle between the link and the guide).
  Where it is below :data:`SINGULAR` the velocity system is singular (toggle, lock) and V_J and A_J
  (and everything that depends on them) are NaN -- never inf.  The acceleration system of a joint
  has the same matrix as its velocity system, so it is singular exactly there too.
"""

from __future__ import annotations

import math

import numpy as np

from ..mechanisms.model import Mechanism
from ..tolerance import snap_tolerance
from .chain_order import CrankStep, RRRDyad, chain_plan
from .chain_state import KINDS, VECTORS, ChainState, chain_state

__all__ = ["SINGULAR", "chain_solution"]

#: Relative determinant (sine of the angle between the velocity trial lines) below which the velocity
#: system of a joint is singular and its velocity NaN.
SINGULAR = 1e-12


def _snap(f: np.ndarray, tol: float, ok: np.ndarray, tangent: np.ndarray) -> np.ndarray:
    """Three-way decision on a gap factor f (which must be >= 0 for the dyad to close): f < -tol apart
    (clears ``ok``), |f| <= tol tangent (f := 0, sets ``tangent``), f > tol crossing."""
    ok &= ~(f < -tol)
    touch = np.abs(f) <= tol
    tangent |= touch
    return np.where(touch, 0.0, f)


#: Crank angles solved per chunk, so the chain's many temporaries stay in cache (measured on the


def chain_solution(m: Mechanism, theta, omega, alpha=0.0, *, chunk: int | None = None) -> ChainState:
    """Solve the mechanism ``m`` (a crank followed by dyads) at crank angle(s) ``theta`` (rad, direction
    pivot -> tip, CCW from +x) turning at ``omega`` (rad/s, CCW positive) with angular acceleration
    ``alpha`` (rad/s^2, CCW positive; default 0, constant speed).  ``chunk``, if given, is how many
    angles go through the loop at a time (the sweep's choice, to keep the temporaries in cache; the
    numbers are the same); None: all at once.

    Raises DegenerateInput when the mechanism is not a crank followed by RRR and RRP dyads (it says
    which joint cannot be solved).
    """
    crank, dyads, points = chain_plan(m)
    th, w1, a1 = np.broadcast_arrays(*(np.asarray(v, dtype=np.float64) for v in (theta, omega, alpha)))
    shape = th.shape
    th, w1, a1 = (np.ascontiguousarray(v).reshape(-1) for v in (th, w1, a1))
    n = th.size
    far = max((max(abs(p.x), abs(p.y)) for p in list(m.ground.values()) + [s.through for s in m.slides]),
              default=0.0)
    tol = snap_tolerance(m.size, far)     # the one scene size, plus the rounding of far coordinates

    out: dict[str, dict] = {}
    ok = np.empty(n, dtype=bool)
    step = chunk or max(n, 1)
    for i in range(0, max(n, 1), step):
        j = min(i + step, n)
        res = _solve(m, crank, dyads, points, th[i:j], w1[i:j], a1[i:j], tol)
        if not out:   # the names are known after the first piece: the outputs, arrays of their own
            out = {kind: {name: ((np.empty(n), np.empty(n)) if kind in VECTORS else np.empty(n))
                          for name in res[kind]} for kind in KINDS}
        for kind in KINDS:
            for name, v in res[kind].items():
                if kind in VECTORS:
                    out[kind][name][0][i:j] = v[0]
                    out[kind][name][1][i:j] = v[1]
                else:
                    out[kind][name][i:j] = v
        ok[i:j] = res["ok"]

    # where any dyad fails the mechanism has no configuration: NaN for everything that moves
    if not ok.all():
        bad = ~ok
        for kind in VECTORS:
            for name, (x, y) in out[kind].items():
                if name not in m.ground:
                    x[bad] = np.nan
                    y[bad] = np.nan
        for c in out["conditions"].values():
            c[bad] = np.nan
        fixed = {crank.link.number} | {s_.number for s_ in m.slides if s_.number is not None}
        for kind in ("angular", "angular_acceleration"):
            for number, w in out[kind].items():
                if number not in fixed:
                    w[bad] = np.nan
    order = (crank.joint,) + tuple(d.joint for d in dyads) + tuple(p.point.name for p in points)
    return chain_state(out, ok, order, shape)


def _solve(m: Mechanism, crank: CrankStep, dyads, points, th: np.ndarray, w1: np.ndarray, a1: np.ndarray,
           tol: float) -> dict:
    """:func:`chain_solution` at the angles ``th`` (1-D arrays); fixed pivots as plain floats."""
    k = th.size
    pos: dict[str, tuple] = {}
    vel: dict[str, tuple] = {}
    acc: dict[str, tuple] = {}
    cond: dict[str, np.ndarray] = {}
    ok = np.ones(k, dtype=bool)
    for g, p in m.ground.items():
        pos[g] = (float(p.x), float(p.y))
        vel[g] = (0.0, 0.0)
        acc[g] = (0.0, 0.0)

    with np.errstate(all="ignore"):  # NaN where a dyad does not close, handled explicitly
        # Crank: B = O + r (cos, sin)(theta);  V_B = d/dt of it = omega r (-sin, cos) = omega k x (B - O);
        # A_B = d/dt V_B (theta' = omega, omega' = alpha) = alpha r (-sin, cos) - omega^2 r (cos, sin)
        #     = alpha k x (B - O) - omega^2 (B - O).
        c, s = np.cos(th), np.sin(th)
        r = crank.link.length
        ox, oy = pos[crank.pivot]
        pos[crank.joint] = (ox + r * c, oy + r * s)
        vel[crank.joint] = (-w1 * r * s, w1 * r * c)
        wsq = w1 * w1
        acc[crank.joint] = (-(a1 * s + wsq * c) * r, (a1 * c - wsq * s) * r)

        for d in dyads:
            tangent = np.zeros(k, dtype=bool)
            if isinstance(d, RRRDyad):
                (Px, Py), (Qx, Qy) = pos[d.p], pos[d.q]
                a, b = d.link_p.length, d.link_q.length
                # Position, angle form.  In the triangle P Q J with sides a = |PJ|, b = |QJ|,
                # e = |PQ|, the law of cosines gives 2 a e cos A = a^2 + e^2 - b^2 for the angle A at P,
                # and Heron gives the area: 16 area^2 = (a+b+e)(a+b-e)(e+a-b)(e-a+b) =: H, while
                # area = a e sin A / 2, so 2 a e sin A = sqrt(H).  Hence
                #   A = atan2(sqrt(H), a^2 + (e - b)(e + b))  in [0, pi],
                # both arguments carrying the same factor 2 a e.  The triangle closes iff the three
                # small factors of H are >= 0 (three-way with tol).  J left of P -> Q means
                # cross(Q - P, J - P) = a e sin(+A) > 0, so
                #   theta_PJ = atan2(Q - P) + sign A,   J = P + a (cos, sin)(theta_PJ).
                ex, ey = Qx - Px, Qy - Py
                e = np.hypot(ex, ey)
                ok &= e > tol                      # coincident centres: no definite triangle
                f1 = _snap(a + b - e, tol, ok, tangent)
                f2 = _snap(e + a - b, tol, ok, tangent)
                f3 = _snap(e - a + b, tol, ok, tangent)
                H = (a + b + e) * f1 * f2 * f3
                A = np.arctan2(np.sqrt(H), a * a + (e - b) * (e + b))
                t = np.arctan2(ey, ex) + d.sign * A
                Jx, Jy = Px + a * np.cos(t), Py + a * np.sin(t)
                # Velocity: differentiate |J - P|^2 = a^2 and |J - Q|^2 = b^2 in time:
                #   (J - P).(V_J - V_P) = 0,  (J - Q).(V_J - V_Q) = 0,
                # i.e. the 2x2 system  [r1; r2] V_J = [r1.V_P; r2.V_Q] with r1 = J - P, r2 = J - Q.
                # Cramer: det = cross(r1, r2), V_Jx = (k1 r2y - r1y k2)/det, V_Jy = (r1x k2 - r2x k1)/det.
                # |det| / (|r1| |r2|) is the sine of the angle between the links at J, i.e. between
                # the two velocity trial lines (each square to its link).
                (VPx, VPy), (VQx, VQy) = vel[d.p], vel[d.q]
                r1x, r1y, r2x, r2y = Jx - Px, Jy - Py, Jx - Qx, Jy - Qy
                k1 = r1x * VPx + r1y * VPy
                k2 = r2x * VQx + r2y * VQy
                det = r1x * r2y - r1y * r2x
                sine = np.abs(det) / (np.hypot(r1x, r1y) * np.hypot(r2x, r2y))
                sine = np.where(tangent, 0.0, sine)
                inv = np.where(sine >= SINGULAR, 1.0 / det, np.nan)
                VJx = (k1 * r2y - r1y * k2) * inv
                VJy = (r1x * k2 - r2x * k1) * inv
                # Acceleration: differentiate (J - P).(V_J - V_P) = 0 once more:
                #   |V_J - V_P|^2 + (J - P).(A_J - A_P) = 0,  likewise for Q,
                # i.e. the same matrix [r1; r2] A_J = [r1.A_P - |V_J - V_P|^2; r2.A_Q - |V_J - V_Q|^2]:
                # singular exactly where the velocity system is (inv is NaN there).
                (APx, APy), (AQx, AQy) = acc[d.p], acc[d.q]
                ux, uy = VJx - VPx, VJy - VPy
                k1 = r1x * APx + r1y * APy - (ux * ux + uy * uy)
                ux, uy = VJx - VQx, VJy - VQy
                k2 = r2x * AQx + r2y * AQy - (ux * ux + uy * uy)
                AJx = (k1 * r2y - r1y * k2) * inv
                AJy = (r1x * k2 - r2x * k1) * inv
            else:
                (Px, Py) = pos[d.p]
                a = d.link.length
                gam = d.slide.angle
                gx, gy = math.cos(gam), math.sin(gam)
                Gx, Gy = float(d.slide.through.x), float(d.slide.through.y)
                # Position, quadratic in the slider parameter.  J = G + s g (g the unit guide
                # direction, n = k x g).  |J - P|^2 = a^2 with w = P - G reads
                #   s^2 - 2 (w.g) s + |w|^2 - a^2 = 0,  so  s = w.g +- sqrt((w.g)^2 - |w|^2 + a^2),
                # and since |w|^2 = (w.g)^2 + (w.n)^2 the discriminant is a^2 - y^2 = (a - y)(a + y)
                # with y = w.n (signed distance of P from the guide), free of cancellation.  w.g is
                # the parameter of the foot of P, so AHEAD (+1) takes +sqrt.
                wx, wy = Px - Gx, Py - Gy
                foot = wx * gx + wy * gy
                y = -wx * gy + wy * gx
                h1 = _snap(a - y, tol, ok, tangent)
                h2 = _snap(a + y, tol, ok, tangent)
                sp = foot + d.sign * np.sqrt(h1 * h2)
                Jx, Jy = Gx + sp * gx, Gy + sp * gy
                # Velocity: V_J = sdot g.  Differentiating |J - P|^2 = a^2 gives
                #   (J - P).(sdot g - V_P) = 0  =>  sdot = ((J - P).V_P) / ((J - P).g).
                # |(J - P).g| / |J - P| is the sine of the angle between the trial lines (square to PJ,
                # along g); 0 when the link stands square to the guide (lock).
                VPx, VPy = vel[d.p]
                rx, ry = Jx - Px, Jy - Py
                rg = rx * gx + ry * gy
                sine = np.abs(rg) / np.hypot(rx, ry)
                sine = np.where(tangent, 0.0, sine)
                inv = np.where(sine >= SINGULAR, 1.0 / rg, np.nan)
                sdot = (rx * VPx + ry * VPy) * inv
                VJx, VJy = sdot * gx, sdot * gy
                # Acceleration: the guide is fixed and straight, so A_J = sddot g (no normal or
                # Coriolis term).  Differentiating (J - P).(V_J - V_P) = 0 once more:
                #   |V_J - V_P|^2 + (J - P).(sddot g - A_P) = 0
                #   =>  sddot = ((J - P).A_P - |V_J - V_P|^2) / ((J - P).g),  NaN at a lock.
                APx, APy = acc[d.p]
                ux, uy = VJx - VPx, VJy - VPy
                sddot = (rx * APx + ry * APy - (ux * ux + uy * uy)) * inv
                AJx, AJy = sddot * gx, sddot * gy
            pos[d.joint] = (Jx, Jy)
            vel[d.joint] = (VJx, VJy)
            acc[d.joint] = (AJx, AJy)
            cond[d.joint] = sine

        # Angular velocity of a rigid link P J: V_J - V_P = omega k x (J - P); taking cross(J - P, .)
        # of both sides, cross(r, omega k x r) = omega |r|^2, so omega = cross(r, V_J - V_P) / |r|^2.
        # Angular acceleration: A_J - A_P = alpha k x r - omega^2 r; cross(r, k x r) = |r|^2 and
        # cross(r, r) = 0 (also exactly in floating point: r_x r_y - r_y r_x), so the normal term drops
        # out and alpha = cross(r, A_J - A_P) / |r|^2 (= cross(r, A_J - A_P + omega^2 r) / |r|^2).
        ang: dict[int, np.ndarray] = {}
        angacc: dict[int, np.ndarray] = {}
        for link in m.links:
            if link.number == crank.link.number:
                continue
            p, j = link.joints
            (Px, Py), (Jx, Jy) = pos[p], pos[j]
            (VPx, VPy), (VJx, VJy) = vel[p], vel[j]
            (APx, APy), (AJx, AJy) = acc[p], acc[j]
            rx, ry = Jx - Px, Jy - Py
            rr = rx * rx + ry * ry
            ang[link.number] = (rx * (VJy - VPy) - ry * (VJx - VPx)) / rr
            angacc[link.number] = (rx * (AJy - APy) - ry * (AJx - APx)) / rr
        ang[crank.link.number] = w1
        angacc[crank.link.number] = a1
        for s_ in m.slides:
            if s_.number is not None:   # a slider block translates; a pin in a slot has no body
                ang[s_.number] = 0.0
                angacc[s_.number] = 0.0

        # Points fixed to a link: D = base + distance (cos, sin)(psi + angle), psi the direction from
        # base to the link's other joint; rigid body, r = D - base turning with the link (r' = omega k x r):
        # V_D = V_base + omega k x r and A_D = A_base + alpha k x r - omega^2 r, with k x (x, y) = (-y, x).
        for pt in points:
            a, link = pt.point, pt.link
            (Bx, By), (Ox, Oy) = pos[a.base], pos[link.other(a.base)]
            VBx, VBy = vel[a.base]
            ABx, ABy = acc[a.base]
            psi = np.arctan2(Oy - By, Ox - Bx) + a.angle
            rx, ry = a.distance * np.cos(psi), a.distance * np.sin(psi)
            wl, al = ang[link.number], angacc[link.number]
            pos[a.name] = (Bx + rx, By + ry)
            vel[a.name] = (VBx - wl * ry, VBy + wl * rx)
            wsq = wl * wl
            acc[a.name] = (ABx - al * ry - wsq * rx, ABy + al * rx - wsq * ry)

    return dict(positions=pos, velocities=vel, accelerations=acc, angular=ang,
                angular_acceleration=angacc, conditions=cond, ok=ok)
