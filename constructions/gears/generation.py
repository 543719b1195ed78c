"""Teeth cut by generation: the flank a rack cutter leaves, its root fillet and its undercut.

The cutter is the basic rack of the gear's tooth system (ISO 53's form): straight flanks at the pressure
angle phi, a tooth p/2 thick on its pitch line, a tip line at the gear's dedendum d below the pitch line
(it cuts the root circle r - d), and a tip round of radius rho = c / (1 - sin phi) tangent to the flank
and to the tip line, c = d - a being the clearance -- so the straight flank ends at the working depth a
(for 20 deg full depth: rho = 0.38 m, ISO 53 profile A).  A system may state its cutter's tip radius
instead (``ToothSystem.cutter_tip``): the straight flank then ends at d - rho (1 - sin phi).  Rolled on
the pitch circle (a rack point X, in the frame where the pitch point is (0, r), is at
Rot(-theta)(X - (r theta, 0)) in the gear's frame), the straight flank generates the involute, and the
tip round the fillet: at each theta the round cuts at the point of its outer arc whose normal passes
through the pitch point (the law of gearing), as long as that normal lies between the flank's and the
tip line's.

The straight flank's lowest point generates the involute down to the form radius
R_L^2 = r_b^2 + (r sin phi - a/sin phi)^2 while it meets the line of action before the interference
point T (a <= r sin^2 phi).  Beyond T (fewer teeth than 2 k / sin^2 phi: 18 at 20 deg full depth) the
fillet cuts into the involute: the tooth is *undercut*, and its flank is the involute from the tip down
to where the fillet crosses it (R_X, found to 1e-12 of the module), then the fillet.

Angles are measured in the tooth's own terms: the polar angle from the tooth's centre line, on its
counter-clockwise flank (the clockwise flank is the mirror image).
"""

from __future__ import annotations

import math
from ..tolerance import ROOT_BITS, UNDERCUT_REL
from .flank import CutFlank
from .tooth import Gear, ToothSystem, inv

FILLET_POINTS = 24
"""Points of the fillet drawn (as many as an involute flank: FLANK_POINTS)."""


def largest_tip_round(s: ToothSystem) -> float:
    """The largest tip radius the cutter's tooth holds: where its two rounds meet on its centre line, or
    where the round meets the straight flank at the pitch line (a larger round leaves no flank to
    generate the involute there), whichever is smaller."""
    phi = s.pressure_angle
    meet = (s.circular_pitch / 4.0 * math.cos(phi) - s.d * math.sin(phi)) / (1.0 - math.sin(phi))
    return max(0.0, min(meet, s.d / (1.0 - math.sin(phi))))


def tip_round(gear: Gear) -> float:
    """The cutter's tip radius: the system's ``cutter_tip`` (in modules) when it states one, else
    rho = c / (1 - sin phi), no larger than the rack tooth's tip allows (:func:`largest_tip_round`); 0
    without clearance."""
    s = gear.system
    if s.cutter_tip is not None:
        return s.cutter_tip * s.module
    c = max(0.0, s.d - s.a)
    return min(c / (1.0 - math.sin(s.pressure_angle)), largest_tip_round(s))


def straight_depth(gear: Gear) -> float:
    """How deep below its pitch line the cutter's straight flank reaches (the working depth a for
    the standard systems)."""
    return gear.system.d - tip_round(gear) * (1.0 - math.sin(gear.system.pressure_angle))


def is_undercut(gear: Gear, tol: float = UNDERCUT_REL) -> bool:
    """The straight flank reaches past the interference point: depth > r sin^2 phi."""
    phi = gear.system.pressure_angle
    return straight_depth(gear) > gear.pitch_radius * math.sin(phi) ** 2 + tol * gear.system.module


def fewest_uncut(gear: Gear) -> float:
    """The number of teeth below which this rack undercuts: 2 depth / (m sin^2 phi), the straight
    flank's depth in modules (2 k / sin^2 phi for the standard systems: 17.1 at 20 deg full depth)."""
    return 2.0 * straight_depth(gear) / (gear.system.module * math.sin(gear.system.pressure_angle) ** 2)


def form_radius(gear: Gear) -> float:
    """R_L, the lowest radius of the involute the straight flank generates when the tooth is not
    undercut: sqrt(r_b^2 + (r sin phi - depth / sin phi)^2)."""
    phi = gear.system.pressure_angle
    s = gear.pitch_radius * math.sin(phi) - straight_depth(gear) / math.sin(phi)
    return math.hypot(gear.base_radius, s)


def cut_flank(gear: Gear, points: int = FILLET_POINTS) -> CutFlank | None:
    """The counter-clockwise flank of a tooth as the rack cutter leaves it; None when the cutter's tooth
    would be pointed above its tip line (a pressure angle too large for the dedendum: no such rack)."""
    s = gear.system
    phi, d, r, n = s.pressure_angle, s.d, gear.pitch_radius, gear.teeth
    if s.circular_pitch / 4.0 - d * math.tan(phi) <= 0.0:
        return None
    rho = tip_round(gear)
    # the round's centre (x along the pitch line from the rack tooth's centre, y from the gear's centre)
    qx = s.circular_pitch / 4.0 + ((rho - d) * math.sin(phi) - rho) / math.cos(phi)
    qy = r - d + rho
    theta_root = qx / r                                  # the round's normal straight down: the root
    theta_low = (qx - (d - rho) / math.tan(phi)) / r     # the normal along the flank's: the form point
    centre_line = math.pi / 2.0 - math.pi / n            # the tooth the round's side cuts
    rb = gear.base_radius
    half = gear.half_tooth_angle + inv(phi)

    def at(theta: float) -> tuple[float, float]:
        cx, cy = qx - r * theta, qy
        wx, wy = cx, cy - r
        # the point of the round's outer arc (it faces down, to the gear) whose normal passes through
        # the pitch point: the far end of the line from it through the centre, or the near end when
        # the centre lies above the pitch line (a round larger than the dedendum)
        k = (rho if wy < 0.0 else -rho) / math.hypot(wx, wy)
        px, py = cx + k * wx, cy + k * wy
        c, sn = math.cos(theta), math.sin(theta)
        gx, gy = c * px + sn * py, -sn * px + c * py      # Rot(-theta)
        return math.hypot(gx, gy), math.atan2(gy, gx) - centre_line

    def inside(theta: float) -> float:
        """How far the fillet point lies inside the involute tooth (> 0: undercut), as an angle (at
        radii from the base circle up)."""
        big_r, delta = at(theta)
        return (half - inv(math.acos(min(1.0, rb / big_r)))) - delta

    def bisect(f, lo: float, hi: float) -> float:
        """The root of f between lo (f <= 0) and hi (f > 0), to the last bits of theta."""
        for _ in range(200):
            mid = 0.5 * (lo + hi)
            if f(mid) > 0.0:
                hi = mid
            else:
                lo = mid
            if hi - lo <= ROOT_BITS * max(1.0, abs(hi)):
                break
        return hi

    undercut, start, involute_from = False, theta_low, form_radius(gear)
    # the fillet runs down from the form point to the root circle; where it passes the base circle
    # inside the tooth's involute, it has cut the involute: the crossing lies above
    if at(theta_root)[0] < rb:
        on_base = bisect(lambda t: rb - at(t)[0], theta_low, theta_root)
        if inside(on_base) > 0.0:
            undercut = True
            start = bisect(inside, theta_low, on_base)
            involute_from = at(start)[0]
    fillet = tuple(at(start + (theta_root - start) * i / (points - 1)) for i in range(points))
    return CutFlank(undercut, involute_from, fillet)


def undercut_flank(gear: Gear) -> CutFlank | None:
    """The flank a rack cutter leaves on ``gear`` when it undercuts it (perhaps so deep that it severs
    the tooth: :attr:`CutFlank.severed`); None when it does not (the teeth are then drawn with the
    involute down to the base circle and radial below it, as the notes draw them).  The closed form
    (:func:`is_undercut`) says where to look; the flank itself decides (with a large tip round the
    cut of the involute can begin a fraction of a tooth past the closed form's limit)."""
    cut = cut_flank(gear) if is_undercut(gear) else None
    return cut if cut is not None and cut.undercut else None


def drawn_flank(cut: CutFlank | None) -> CutFlank | None:
    """The cut flank to draw: none where the cutter severs the tooth (the involute teeth are drawn)."""
    return None if cut is None or cut.severed else cut
