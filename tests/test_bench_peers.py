"""The peers benchmark compares like with like: the plain numpy reference equals this engine's closed form
(positions, velocities, accelerations to 1e-9), a peer that is not installed is named and not timed, and a
peer that disagrees is refused.  No timing is asserted."""

from __future__ import annotations

import numpy as np
import pytest

from drafting.app.bench import benchmark

bp = benchmark("peers")


def test_the_numpy_reference_is_the_engine_to_1e_9():
    th = np.linspace(0.0, 2 * np.pi, 997, endpoint=False)
    st, ref = bp.engine(th), bp.numpy_reference(th)
    for mine, (x, y) in (((st.Cx, st.Cy), ref["C"]), ((st.VCx, st.VCy), ref["V_C"]), ((st.ACx, st.ACy), ref["A_C"])):
        scale = np.max(np.hypot(*mine))
        assert np.max(np.hypot(mine[0] - x, mine[1] - y)) <= 1e-9 * scale
    assert np.allclose(st.omega3, ref["omega"][1], rtol=0, atol=1e-9 * np.max(np.abs(st.omega3)))
    assert np.allclose(st.alpha2, ref["alpha"][0], rtol=0, atol=1e-9 * np.max(np.abs(st.alpha2)))


def test_missing_peers_are_named_and_a_disagreeing_one_is_not_timed(monkeypatch):
    def absent():
        raise ImportError("no")
    monkeypatch.setattr(bp, "PEERS", {"pylinkage": absent, "wrong": lambda: (lambda th: (np.cos(th), np.sin(th)))})
    monkeypatch.setitem(bp.LARGEST, "wrong", 10**3)
    found, missing = bp.rows(sizes=(100,), repeats=1)
    assert {r["solver"] for r in found} == {"this engine", "plain numpy"}
    assert "not installed" in missing["pylinkage"] and "disagrees" in missing["wrong"]
    text = bp.format_rows(found, missing)
    assert "this engine" in text and "pylinkage: not installed" in text


@pytest.mark.parametrize("name", ["pylinkage", "mechanism"])
def test_an_installed_peer_agrees_with_the_engine(name):
    found, _ = bp.solvers()
    if name not in found:
        pytest.skip(f"{name} is an optional benchmark extra")
    assert bp.check(name, found[name]) < 1e-9
