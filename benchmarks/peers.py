"""The four-bar's full-cycle sweep against its peers, side by side in one run: full states per second
(positions, velocities and accelerations of every joint at each crank angle).

- **this engine**: the vectorised closed form of :mod:`constructions.sweep_kernels` (what ``drafting sweep``
  and the cycle sheet use for a four-bar);
- **plain numpy**: the same mathematics written the obvious way (circle intersection, then the velocity
  and acceleration loop equations by Cramer's rule), the reference a user would script;
- **pylinkage** (``pip install pylinkage``; 1.3 solves with numba, ``step_fast_with_kinematics``);
- **mechanism** (``pip install mechanism``; loop equations solved by ``scipy.optimize.fsolve`` angle by
  angle).

The peers are optional benchmark extras (``pip install .[bench]``); a peer that is not installed is
reported as such, never faked.  Every peer's positions are checked against this engine's before it is
timed, so the table compares like with like.  Timings are reported, never asserted.

Run by ``drafting bench --peers`` (which loads this file from the checkout:
:func:`drafting.app.bench.benchmark`), or alone: ``python benchmarks/peers.py [n ...]`` (default sizes
1e3 .. 1e7; the peers stop at the sizes in :data:`LARGEST`).
"""

from __future__ import annotations

import math
import sys
import time
from pathlib import Path

import numpy as np

if __name__ == "__main__":
    sys.path.insert(0, str(Path(__file__).resolve().parents[1]))  # run from a checkout, uninstalled

from constructions.sweep_kernels import four_bar  # noqa: E402

#: The benchmarked crank-rocker (SI): the same as :data:`drafting.app.bench_sweep.MECHANISMS` "four-bar".
O1, O2 = (0.0, 0.0), (0.1, 0.02)
CRANK, COUPLER, ROCKER, BRANCH = 0.03, 0.09, 0.07, 1
OMEGA, ALPHA = 10.0, 20.0

#: Largest sweep given to each solver: the peers are slow, and a sweep is timed once per size for them.
LARGEST = {"this engine": 10**7, "plain numpy": 10**7, "pylinkage": 10**5, "mechanism": 10**3}


def engine(theta: np.ndarray):
    """This engine's vectorised closed form (a FourBarState)."""
    return four_bar(theta, OMEGA, ALPHA, crank_pivot=O1, rocker_pivot=O2, crank=CRANK, coupler=COUPLER,
                    rocker=ROCKER, branch=BRANCH)


def numpy_reference(theta: np.ndarray) -> dict[str, np.ndarray]:
    """Positions, velocities and accelerations of B and C and the rates of coupler and rocker, the obvious
    way: C where the circles about B (coupler) and O2 (rocker) cross; omega_3, omega_4 from
    V_B + omega_3 k x BC = omega_4 k x O2C, alpha_3, alpha_4 likewise, each 2 x 2 by Cramer's rule."""
    c, s = np.cos(theta), np.sin(theta)
    bx, by = O1[0] + CRANK * c, O1[1] + CRANK * s
    dx, dy = O2[0] - bx, O2[1] - by
    d2 = dx * dx + dy * dy
    d = np.sqrt(d2)
    along = (COUPLER ** 2 - ROCKER ** 2 + d2) / (2 * d)
    h = np.sqrt(COUPLER ** 2 - along ** 2)
    cx = bx + (along * dx - BRANCH * h * dy) / d
    cy = by + (along * dy + BRANCH * h * dx) / d
    r3x, r3y = cx - bx, cy - by                  # B -> C
    r4x, r4y = cx - O2[0], cy - O2[1]            # O2 -> C
    vbx, vby = -OMEGA * CRANK * s, OMEGA * CRANK * c
    # omega_3 (-r3y, r3x) - omega_4 (-r4y, r4x) = -V_B: the matrix [[-r3y, r4y], [r3x, -r4x]]
    m11, m12, m21, m22 = -r3y, r4y, r3x, -r4x
    det = m11 * m22 - m12 * m21

    def cramer(p, q):
        return (p * m22 - m12 * q) / det, (m11 * q - m21 * p) / det
    vbx, vby = -OMEGA * CRANK * s, OMEGA * CRANK * c
    w3, w4 = cramer(-vbx, -vby)
    vcx, vcy = -w4 * r4y, w4 * r4x
    abx = -ALPHA * CRANK * s - OMEGA ** 2 * CRANK * c
    aby = ALPHA * CRANK * c - OMEGA ** 2 * CRANK * s
    # alpha_3 (-r3y, r3x) - alpha_4 (-r4y, r4x) = -A_B + omega_3^2 r3 - omega_4^2 r4
    a3, a4 = cramer(-abx + w3 ** 2 * r3x - w4 ** 2 * r4x, -aby + w3 ** 2 * r3y - w4 ** 2 * r4y)
    acx, acy = -a4 * r4y - w4 ** 2 * r4x, a4 * r4x - w4 ** 2 * r4y
    return {"B": (bx, by), "C": (cx, cy), "V_B": (vbx, vby), "V_C": (vcx, vcy), "A_B": (abx, aby),
            "A_C": (acx, acy), "omega": (w3, w4), "alpha": (a3, a4)}


def _pylinkage():
    import pylinkage as pl                                      # noqa: F401 (optional extra)

    def run(theta: np.ndarray):
        n = theta.size
        o1, o2 = pl.Ground(*O1, name="O1"), pl.Ground(*O2, name="O2")
        step = float(theta[1] - theta[0]) if n > 1 else 0.0
        crank = pl.Crank(anchor=o1, radius=CRANK, angular_velocity=step,   # it turns before it reports
                         initial_angle=float(theta[0]) - step)
        rocker = pl.RRRDyad(crank.output, o2, distance1=COUPLER, distance2=ROCKER, x=_c_start()[0],
                            y=_c_start()[1])
        lk = pl.Linkage([o1, o2, crank, rocker], name="four-bar")
        lk.set_input_velocity(crank, omega=OMEGA, alpha=ALPHA)
        p, v, a = lk.step_fast_with_kinematics(iterations=n)
        return p[:, 3, 0], p[:, 3, 1]                          # C: the dyad's joint
    return run


def _mechanism():
    from mechanism import Mechanism, Vector, get_joints        # optional extra

    def run(theta: np.ndarray):
        o, a_, b_, c_ = get_joints("O A B C")
        va = Vector((o, a_), r=CRANK)
        vb = Vector((a_, b_), r=COUPLER)
        vc = Vector((c_, b_), r=ROCKER)
        vd = Vector((o, c_), r=math.hypot(O2[0] - O1[0], O2[1] - O1[1]),
                    theta=math.atan2(O2[1] - O1[1], O2[0] - O1[0]), style="ground")

        def loops(x, i):
            return va(i) + vb(x[0]) - vc(x[1]) - vd()
        cx, cy = _c_start()
        bx, by = O1[0] + CRANK * math.cos(theta[0]), O1[1] + CRANK * math.sin(theta[0])
        guess = (np.array([math.atan2(cy - by, cx - bx), math.atan2(cy - O2[1], cx - O2[0])]),
                 np.array([1.0, 1.0]), np.array([1.0, 1.0]))
        n = theta.size
        mech = Mechanism(vectors=(va, vb, vc, vd), origin=o, loops=loops, pos=theta,
                         vel=np.full(n, OMEGA), acc=np.full(n, ALPHA), guess=guess)
        mech.iterate()
        return np.asarray(b_.x_positions), np.asarray(b_.y_positions)   # their B is our C
    return run


def _c_start():
    ref = numpy_reference(np.array([0.0]))
    return float(ref["C"][0][0]), float(ref["C"][1][0])


PEERS = {"pylinkage": _pylinkage, "mechanism": _mechanism}


def solvers() -> tuple[dict, dict[str, str]]:
    """(name -> solver of theta, name -> why it is missing) for this engine, the reference and the peers."""
    out = {"this engine": engine, "plain numpy": numpy_reference}
    missing = {}
    for name, make in PEERS.items():
        try:
            out[name] = make()
        except ImportError:
            missing[name] = "not installed (pip install .[bench])"
    return out, missing


def check(name: str, solve, n: int = 1000) -> float:
    """The largest distance (m) between the solver's C and this engine's over one turn in ``n`` steps
    (this engine is checked against the plain numpy reference)."""
    theta = np.linspace(0.0, 2 * np.pi, n, endpoint=False)
    st = engine(theta)
    ref = numpy_reference(theta)["C"] if name == "this engine" else (st.Cx, st.Cy)
    got = _c_of(name, solve(theta))
    return float(np.max(np.hypot(got[0] - ref[0], got[1] - ref[1])))


def _c_of(name: str, out):
    if name == "plain numpy":
        return out["C"]
    if name == "this engine":
        return out.Cx, out.Cy
    return out


def rows(sizes=(10**3, 10**4, 10**5, 10**6, 10**7), repeats: int = 3) -> tuple[list[dict], dict[str, str]]:
    """Median full states per second of each solver at each size (the peers timed once per size, after a
    warm-up that also compiles pylinkage's numba code), and the peers left out with the reason."""
    found, missing = solvers()
    out = []
    for name, solve in found.items():
        err = check(name, solve)
        if not err < 1e-9:
            missing[name] = f"disagrees with this engine by {err:.1e} m: not timed"
            continue
        for n in sizes:
            if n > LARGEST[name]:
                continue
            theta = np.linspace(0.0, 2 * np.pi, n, endpoint=False)
            solve(theta[: min(n, 100)])                          # warm-up (numba compiles here)
            reps = repeats if name in ("this engine", "plain numpy") else 1
            times = []
            for _ in range(reps):
                t0 = time.perf_counter()
                res = solve(theta)
                times.append(time.perf_counter() - t0)
                del res
            med = float(np.median(times))
            out.append({"solver": name, "n": n, "seconds": med, "states_per_second": n / med})
    return out, missing


def format_rows(found: list[dict], missing: dict[str, str]) -> str:
    names = list(dict.fromkeys(r["solver"] for r in found))
    cell = {(r["solver"], r["n"]): r for r in found}
    sizes = sorted({r["n"] for r in found})
    head = ["n"] + names
    lines = [[f"1e{round(math.log10(n))}" if n >= 10 and 10 ** round(math.log10(n)) == n else str(n)]
             + [f"{cell[(m, n)]['states_per_second']:.2e}" if (m, n) in cell else "--" for m in names]
             for n in sizes]
    widths = [max(len(str(x)) for x in col) for col in zip(head, *lines)]
    text = ["four-bar sweep, full states per second (positions, velocities, accelerations), median",
            "  ".join(h.rjust(w) for h, w in zip(head, widths)), "  ".join("-" * w for w in widths)]
    text += ["  ".join(c.rjust(w) for c, w in zip(line, widths)) for line in lines]
    text += [f"{name}: {why}" for name, why in missing.items()]
    return "\n".join(text)


if __name__ == "__main__":
    sizes = tuple(int(float(a)) for a in sys.argv[1:]) or (10**3, 10**4, 10**5, 10**6, 10**7)
    print(format_rows(*rows(sizes)))
