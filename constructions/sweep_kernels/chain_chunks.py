"""The dyad-chain vector loop over many crank angles: :func:`constructions.analytic.chain_solution` a
chunk of angles at a time, so the chain's many temporaries stay in cache."""

from __future__ import annotations

from typing import TYPE_CHECKING

from ..mechanisms.model import Mechanism

if TYPE_CHECKING:
    from ..analytic import ChainState

__all__ = ["CHAIN_CHUNK", "chain_sweep"]

#: Crank angles solved per chunk (measured on the toggle linkage: 2**12 .. 2**14 within ~20 % of each
#: other; unchunked 1e6-angle arrays about twice as slow).
CHAIN_CHUNK = 2**13


def chain_sweep(m: Mechanism, theta, omega, alpha=0.0) -> ChainState:
    """:func:`constructions.analytic.chain_solution` (the same arguments and result, bit for bit), in
    chunks of :data:`CHAIN_CHUNK` angles."""
    from ..analytic import chain_solution        # the dyad chain: loaded by the sweeps that run one
    return chain_solution(m, theta, omega, alpha, chunk=CHAIN_CHUNK)
