"""The independent analytic check: vector-loop closed forms, vectorised over crank angles.

This package is the yardstick for the graphical velocity- and acceleration-polygon constructions, so it
deliberately shares no code with them: it is pure numpy.  The closed forms import nothing from
:mod:`constructions` but the tolerance policy (:mod:`constructions.tolerance`: the one scene size and
the snapping tolerance); the dyad chain reads the data of a :class:`~constructions.linkage.Mechanism`
and never its geometry kernel, assembly plan or polygons; nothing comes from :mod:`drafting`.  Every
formula is derived here from first principles (the derivations are in the docstrings and comments next
to the code); none is copied from the course notes, whose vector-loop section has known sign and matrix
mistakes (its four-bar acceleration matrix among them).

Conventions (of the closed forms; the dyad chain's are in :mod:`.vector_loops`)
-------------------------------------------------------------------------------
* SI throughout: metres, radians, rad/s, rad/s^2.  Angles are measured CCW from +x; omega and alpha
  are CCW positive.
* ``theta1``, ``omega1`` and ``alpha1`` may be scalars or numpy arrays; they are broadcast against
  each other and every returned field is a float64 (or bool) array of the broadcast shape (a 0-d
  array for scalars).  The returned arrays are read-only; the containers are frozen dataclasses.
* A crank angle at which the loop cannot close gives NaN for every position, velocity and
  acceleration field (including B, V_B and A_B: the mechanism has no configuration there), NaN
  ``condition`` and ``assembles == False``.
* ``condition`` is the sine of the angle between the two velocity trial lines.  Where it is below
  :data:`SINE_TOL` (1e-12) the velocity solution is indeterminate (toggle / dead centre) and every
  velocity and acceleration that depends on the solve is NaN -- never inf, never a huge number.  V_B
  and A_B stay finite.  The acceleration loop has the same 2x2 matrix as the velocity loop (only the
  right-hand side differs), so it is singular exactly where the velocity loop is; near a toggle the
  accelerations grow like 1/condition^3 (the velocities like 1/condition).

Numerical notes
---------------
* Circle-circle and line-circle intersections use the cancellation-free product form of the
  half-chord (Heron's formula written as a product of sums and differences), so near tangency the
  small factor is an exact floating-point difference (Sterbenz) and keeps its digits.
* The assembly decision is three-way with a tolerance ``tol = ASSEMBLY_RTOL * L`` relative to the
  one scene size ``L`` of :mod:`constructions.tolerance` (the largest link length or distance between
  the pivots -- or of the crank pivot from the guide -- which does not move with the origin).
  Each small gap factor of the half-chord (``S - d`` and ``d - T`` for the four-bar, ``l -+ y`` for
  the slider) is classified: ``> tol`` crossing, ``|gap| <= tol`` tangent (snapped to exactly 0:
  assembles, C on the line of centres, condition 0, velocities NaN), ``< -tol`` apart (no assembly).
  So a designed toggle built from rotated float coordinates reads as a toggle whichever way the
  rounding fell.  ``ASSEMBLY_RTOL`` is 64 ulp; the snap moves C by at most about
  ``sqrt(2 * tol * L)`` ~ 2e-7 L, which is inside the band that the rounding of the inputs already
  leaves undetermined at a tangency (the half-chord has infinite slope there).
  Consequence: apart from exact zeros, a computed ``condition`` is never below roughly 1e-7, so the
  1e-12 ``SINE_TOL`` rule only ever fires at (snapped) tangencies; the velocities next to a toggle
  are finite and honest but large -- inspect ``condition`` before trusting them.
* Every angle's sine, cosine and direction comes from numpy's own ``cos``, ``sin``, ``sqrt`` and
  ``arctan2``, every quantity from one plain array expression: the formulas read as they are derived.
  The fast kernels that the sweep runs over millions of angles (their own trigonometry, chunks, the
  caller's output buffers) live with the sweep, :mod:`constructions.sweep_kernels`, and are tested
  against this package.

Modules
-------
``four_bar_loop``, ``slider_loop``, ``point_on_link``
    The closed forms :func:`four_bar`, :func:`slider_crank` and :func:`coupler_point`.
``vector_loops``, ``chain_order``, ``chain_state``
    The vector loop of any crank followed by RRR/RRP dyads (:func:`chain_solution`), the order it
    solves the joints in, and what it returns.
``yoke_loop``
    The Scotch yoke's closed form :func:`scotch_yoke` (a slot square to the line of stroke).
``inputs``, ``parts``, ``states``
    The checked inputs of the closed forms, the pieces they share (crank tip, the three-way gap
    decision) and their frozen results.

The package's names from the other modules are loaded on first use (:func:`__getattr__`): the analytic
check of a plain four-bar or slider-crank, which needs the inputs and states only, loads neither the
dyad chain nor the closed forms the sweep's kernels stand in for.
"""

import importlib

from ..tolerance import ASSEMBLY_RTOL
from .parts import SINE_TOL
from .states import FourBarState, PointState, SliderCrankState

_FROM = {"solving_order": "chain_order", "ChainPoint": "chain_state", "ChainState": "chain_state",
         "four_bar": "four_bar_loop", "coupler_point": "point_on_link", "slider_crank": "slider_loop",
         "SINGULAR": "vector_loops", "chain_solution": "vector_loops",
         "ScotchYokeState": "yoke_loop", "scotch_yoke": "yoke_loop"}
"""The module of each name the package exports besides the inputs and states."""


def __getattr__(name: str):
    if name not in _FROM:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    value = getattr(importlib.import_module(f".{_FROM[name]}", __name__), name)
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(__all__))


__all__ = [
    "ASSEMBLY_RTOL",
    "SINE_TOL",
    "SINGULAR",
    "ChainPoint",
    "ChainState",
    "FourBarState",
    "PointState",
    "ScotchYokeState",
    "SliderCrankState",
    "chain_solution",
    "coupler_point",
    "four_bar",
    "scotch_yoke",
    "slider_crank",
    "solving_order",
]
