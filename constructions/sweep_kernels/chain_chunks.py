"""The dyad-chain vector loop over many crank angles: :func:`constructions.analytic.chain_solution` a
chunk of angles at a time, so the chain's many temporaries stay in cache, gathered into one
:class:`~constructions.analytic.ChainState`."""

from __future__ import annotations

import numpy as np

from ..analytic import ChainState, chain_solution
from ..analytic.chain_state import KINDS, VECTORS, chain_state
from ..linkage import Mechanism

__all__ = ["CHAIN_CHUNK", "chain_sweep"]

#: Crank angles solved per chunk (measured on the toggle linkage: 2**12 .. 2**14 within ~20 % of each
#: other; unchunked 1e6-angle arrays about twice as slow).
CHAIN_CHUNK = 2**13


def chain_sweep(m: Mechanism, theta, omega, alpha=0.0) -> ChainState:
    """:func:`constructions.analytic.chain_solution` (the same arguments and result, bit for bit), in
    chunks of :data:`CHAIN_CHUNK` angles."""
    th, w1, a1 = np.broadcast_arrays(*(np.asarray(v, dtype=np.float64) for v in (theta, omega, alpha)))
    shape = th.shape
    th, w1, a1 = (np.ascontiguousarray(v).reshape(-1) for v in (th, w1, a1))
    n = th.size
    if n <= CHAIN_CHUNK:
        return chain_solution(m, th.reshape(shape), w1.reshape(shape), a1.reshape(shape))
    out: dict[str, dict] = {}
    ok = np.empty(n, dtype=bool)
    for i in range(0, n, CHAIN_CHUNK):
        j = min(i + CHAIN_CHUNK, n)
        part = chain_solution(m, th[i:j], w1[i:j], a1[i:j])
        if not out:   # the names are known after the first chunk: allocate the outputs
            out = {kind: {name: ((np.empty(n), np.empty(n)) if kind in VECTORS else np.empty(n))
                          for name in getattr(part, kind)} for kind in KINDS}
        for kind in KINDS:
            for name, v in getattr(part, kind).items():
                if kind in VECTORS:
                    out[kind][name][0][i:j] = v[0]
                    out[kind][name][1][i:j] = v[1]
                else:
                    out[kind][name][i:j] = v
        ok[i:j] = part.assembles
    return chain_state(out, ok, part.order, shape)
