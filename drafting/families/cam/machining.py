"""A cam's profile for machining: the exact envelope sampled so that every chord stays within a stated
tolerance of the true curve (:func:`constructions.cams.sampling.profile_samples`), trimmed where the
follower undercuts it.  The cam family's "machining profile" analysis; ``drafting export`` asks for it
with the tolerance as the study's option ``"export tolerance"`` (relative to the cam's size, prime circle
plus lift; 1e-6 by default)."""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from constructions.cams.envelope import evaluate
from constructions.cams.profile import analyse, trim
from constructions.cams.sampling import profile_samples

from .tolerance import EXPORT_TOLERANCE

def machining_profile(study) -> tuple[np.ndarray, float]:
    """(points 2 x N in SI, absolute tolerance in SI): the profile-only sampling of the scene's cam,
    trimmed against the roller centres (face lines) at their own cam angles where the analysis finds
    undercut."""
    model = study.scene.model
    p, f = model.program, model.follower
    cp = analyse(p, f, samples=1024)
    tol = study.options.get("export tolerance", EXPORT_TOLERANCE) * cp.size
    theta, pts = profile_samples(p, f, tol)
    if cp.undercut:
        pts = trim(cp, replace(evaluate(p, f, theta[np.isfinite(theta)]), profile=pts))
    return pts, tol
