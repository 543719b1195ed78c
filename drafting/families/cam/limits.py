"""Warnings when a cam comes near a limit without reaching it: a roller within the scene's margin (5 % by
default, ``[cam] limit_margin``) of the pitch curve's smallest radius of curvature (beyond it the profile
undercuts), a flat face's base radius within the margin of the smallest that keeps the profile convex.
At and beyond the limit the cam family's own warnings speak (cusp, undercut); these speak before it."""

from __future__ import annotations

from constructions.cams.follower import FLAT, OSCILLATING, ROLLER

LIMIT_MARGIN = 0.05
"""The default margin: a roller radius above 95 % of its limit, or a smallest base radius above 95 % of the
given one, is warned of."""


def _pct(x: float) -> str:
    return f"{100 * x:.4g} %"


def near_limit(u, cp, f, margin: float) -> list[str]:
    """The near-limit warnings of a solved profile ``cp`` (:class:`constructions.cams.profile.CamProfile`)."""
    if cp.cusp_at or cp.undercut or margin <= 0:
        return []
    out = []
    if f.kind in (ROLLER, OSCILLATING) and cp.min_rho_pitch is not None:
        t, rho = cp.min_rho_pitch
        ratio = f.roller_radius / rho
        if ratio >= 1 - margin:
            out.append(f"Near the undercut limit: the roller radius {u.format('length', f.roller_radius)} is "
                       f"{_pct(ratio)} of the pitch curve's smallest radius of curvature {u.format('length', rho)} "
                       f"(at {u.format('angle', t)}), within the {_pct(margin)} margin; the profile's radius there "
                       f"is only {u.format('length', rho - f.roller_radius)} (a near-sharp edge that wears fast): a "
                       f"smaller roller or a larger base circle keeps clear of it.")
    if f.kind == FLAT and cp.min_base_radius:
        ratio = cp.min_base_radius / f.base_radius
        if ratio >= 1 - margin:
            out.append(f"Near the flat face's limit: the smallest base radius that keeps the profile convex, "
                       f"{u.format('length', cp.min_base_radius)}, is {_pct(ratio)} of the base radius "
                       f"{u.format('length', f.base_radius)}, within the {_pct(margin)} margin; the profile's "
                       f"smallest radius of curvature is only {u.format('length', cp.min_rho_profile[1])} (at "
                       f"{u.format('angle', cp.min_rho_profile[0])}): a larger base circle keeps clear of it.")
    return out


__all__ = ["LIMIT_MARGIN", "near_limit"]
