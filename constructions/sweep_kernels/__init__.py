"""The sweep's fast kernels: the closed forms of :mod:`constructions.analytic` as the sweep runs them over
millions of crank angles -- in chunks that stay in cache, with ``out=`` ufuncs, the sweep's own
trigonometry (:mod:`.trig`) and, for the four-bar, the caller's output buffers -- and the dyad chain in
chunks.

Each kernel takes the arguments and returns the result of its oracle (the same frozen containers), and
is tested against it: the same numbers to about 1e-15 relative away from singular positions, the same
gaps and toggles.  A large call runs its pieces on the default threads of
:mod:`constructions.sweep_threads` (``threads=`` to choose): the same numbers, bit for bit, on any number.

Modules: ``four_bar_kernel``, ``slider_kernel``, ``point_kernel`` (the closed forms), ``chain_chunks``
(the dyad chain), ``shared_steps`` (chunks, buffers, crank, gap and toggle steps), ``trig``.
"""

from __future__ import annotations

from .chain_chunks import CHAIN_CHUNK, chain_sweep
from .four_bar_kernel import four_bar
from .point_kernel import coupler_point
from .shared_steps import CHUNK, four_bar_buffers
from .slider_kernel import slider_crank

__all__ = ["CHAIN_CHUNK", "CHUNK", "chain_sweep", "coupler_point", "four_bar", "four_bar_buffers", "slider_crank"]
