"""Accuracy against size and time for the step-through page's crank slider: how many poses the page carries
against the error of the values it shows for a crank angle between two of them, the card's size and the
time to build it.

The slider moves from pose to pose (:data:`drafting.families.linkage.family.SWEEP_STEPS`, 360 by default:
1 deg); for a crank angle between two poses the page shows the nearest one.  The error is the largest, over
a reference of 36,000 angles (0.01 deg, the closed form), of the difference between the value at the angle
and the value at the nearest pose: the rocker's angle and the transmission angle (deg), the pins' positions
(mm on the mechanism), the angular velocities and accelerations of coupler and rocker (as a fraction of
their largest).  The readout prints 4 significant figures, a rounding of up to 5e-4 of each value beside
it.  The card (its SVG, the JSON of every pose, the script) is built for the gallery's crank-rocker
(``cycle-four-bar.toml``) with the benchmark setting ``SWEEP_STEPS`` (and putting it back); its time is the
sweep analysis and the card, median of 3 runs; its size is the card's HTML in UTF-8.

Usage: ``python benchmarks/html_slider.py``.
"""

from __future__ import annotations

import math
import sys
from contextlib import contextmanager
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

import numpy as np  # noqa: E402

from accuracy_common import crank_rocker, e, machine, markdown, ms, timed  # noqa: E402
from constructions.mechanisms.classify import classify_four_bar  # noqa: E402
from constructions.mechanisms.cycle import transmission_angles  # noqa: E402
from constructions.sweep import sweep  # noqa: E402
from drafting.backends.html_page import page_html  # noqa: E402
from drafting.backends.html_sweep import sweep_section  # noqa: E402
from drafting.families.linkage import family  # noqa: E402
from drafting.study.study import Study  # noqa: E402
from drafting.study.worked import sheets_for  # noqa: E402

POSES = (36, 72, 180, 360, 720, 1440)
REFERENCE = 36_000


@contextmanager
def poses(n: int):
    """The sheets' sweep (and so the page's slider) set to ``n`` poses a turn."""
    old = family.SWEEP_STEPS
    family.SWEEP_STEPS = n
    try:
        yield
    finally:
        family.SWEEP_STEPS = old


def _values(scene, k, th) -> dict[str, np.ndarray]:
    """What the card shows at crank angles ``th``: angles in deg, pins in mm, rates as they are."""
    s = sweep(scene.mechanism, th, scene.omega, 0.0)
    _, _, c, o2 = k.joints
    (cx, cy), (ox, oy) = s.positions[c], s.positions[o2]
    out = {"rocker angle": np.degrees(np.unwrap(np.arctan2(np.asarray(cy) - oy, np.asarray(cx) - ox))),
           "transmission angle": np.degrees(transmission_angles(k, s))}
    for name in ("B", "C", "D"):
        x, y = s.positions[name]
        out[f"pin {name}"] = np.stack([np.asarray(x), np.asarray(y)]) * 1e3
    for link in (3, 4):
        out[f"omega_{link}"] = np.asarray(s.angular[link])
        out[f"alpha_{link}"] = np.asarray(s.angular_acceleration[link])
    return out


def _between(fine: dict, poses_: dict, nearest: np.ndarray) -> dict[str, float]:
    """The largest difference between each value and its nearest pose's."""
    out = {}
    for key, v in fine.items():
        p = poses_[key][..., nearest]
        d = np.hypot(*(v - p)) if v.ndim == 2 else np.abs(v - p)
        scale = float(np.max(np.abs(v))) if key.startswith(("omega", "alpha")) else 1.0
        out[key] = float(np.max(d)) / scale
    return out


def _card(path_scene):
    study = Study(path_scene).run()
    return sweep_section(study)


def rows(counts=POSES, reference: int = REFERENCE, repeat: int = 3):
    """(poses, card ms, card bytes, errors by value) for each number of poses."""
    scene = crank_rocker()
    k = classify_four_bar(scene.mechanism)
    start = scene.angle
    fine_th = start + 2 * math.pi * np.arange(reference) / reference
    fine = _values(scene, k, fine_th)
    out = []
    for n in counts:
        with poses(n):
            card, t = timed(_card, scene, repeat=repeat)
        assert card.data["count"] == n
        th = start + 2 * math.pi * np.arange(n) / n
        nearest = np.rint((fine_th - start) / (2 * math.pi / n)).astype(int) % n
        out.append((n, t, len(card.html.encode()), _between(fine, _values(scene, k, th), nearest)))
    return out


def page_bytes() -> int:
    """The whole page of the crank-rocker (its sheets, steps and card) at the default poses, UTF-8 bytes."""
    study = Study(crank_rocker()).run()
    return len(page_html(study, sheets_for(study)).encode())


COLUMNS = ("rocker angle", "transmission angle", "pin C", "pin D", "omega_4", "alpha_4", "omega_3", "alpha_3")


def table(measured) -> str:
    head = ["poses (step)", "card (ms)", "card (kB)", "rocker angle (deg)", "transmission angle (deg)",
            "pin C (mm)", "coupler point D (mm)", "omega_4 (/ largest)", "alpha_4 (/ largest)",
            "omega_3 (/ largest)", "alpha_3 (/ largest)"]
    return markdown(head, [[f"{n} ({360 / n:g} deg)", ms(t), f"{size / 1e3:.0f}"] + [e(err[c]) for c in COLUMNS]
                           for n, t, size, err in measured])


def chart_series(measured):
    """(name, [(card kB, error), ...]): the rates as a fraction of their largest, the coupler point's
    position of the frame's length (60 mm)."""
    out = [(f"{c} (/ largest)", [(size / 1e3, err[c]) for _, _, size, err in measured])
           for c in ("omega_4", "alpha_4", "omega_3", "alpha_3")]
    return out + [("coupler point D (/ frame)", [(size / 1e3, err["pin D"] / 60.0) for _, _, size, err in measured])]


def report(measured) -> str:
    """The table and the whole page's size at the default poses."""
    return (f"{table(measured)}\n\nThe whole page at {family.SWEEP_STEPS} poses (sheet, steps and card): "
            f"{page_bytes() / 1e3:.0f} kB")


if __name__ == "__main__":
    print(machine())
    print(report(rows()))
