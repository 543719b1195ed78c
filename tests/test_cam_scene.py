"""The cam scene kind through the whole pipeline: the gallery's cams, their warnings, JSON and errors."""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest

from drafting.cli import main
from drafting.scene import SceneError, load_scene, parse_scene
from drafting.study import Study
from drafting.worked import sheets_for

GALLERY = Path(__file__).resolve().parent.parent / "gallery"


def study(name: str) -> Study:
    return Study(load_scene(GALLERY / name)).run()


def test_notes_roller_cam_agrees_and_draws_every_step():
    s = study("notes-roller-cam.toml")
    assert s.comparisons and all(c.agrees for c in s.comparisons)
    assert not s.warnings
    cp = s.get("profile").profile
    assert cp.min_rho_pitch[1] / 0.0254 == pytest.approx(2.8 ** 2 / 6.4, rel=1e-9)
    sheets = sheets_for(s)
    words = " ".join("".join(t.text for t in x.spans) for sh in sheets for x in sh.texts())
    for w in ("base circle", "prime circle", "cam profile", "Displacement s", "infinite jerk", "tabulate"):
        assert w in words


def test_flat_faced_question_values():
    s = study("notes-flat-faced-cam.toml")
    cp = s.get("profile").profile
    assert cp.min_base_radius == pytest.approx(0.025 * (1.5 ** 2 / 2 - 1), rel=1e-9)     # 3.125 mm
    assert cp.min_rho_profile[1] == pytest.approx(0.050 + 0.025 - 0.0125 * 2.25, rel=1e-9)
    assert cp.face_width[1] - cp.face_width[0] == pytest.approx(2 * 0.025 * 1.5 / 2, rel=1e-9)
    assert all(c.agrees for c in s.comparisons)


def test_undercut_scene_warns_with_angles_and_json(capsys):
    s = study("roller-cam-undercut.toml")
    w = " ".join(s.warnings)
    assert "Undercut" in w and "deg to" in w
    assert "loops back there" in " ".join(s.notes)
    assert main(["solve", str(GALLERY / "roller-cam-undercut.toml"), "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    spans = data["profile"]["undercut"]
    assert len(spans) == 2 and all(a < b for a, b in spans)
    assert data["analyses"] == ["cam construction", "cam closed forms"]


def test_offset_cycloidal_scene_has_speed_charts():
    s = study("offset-roller-cycloidal-cam.toml")
    kinds = {e.series[0].y_kind for e in s.construction.entities() if hasattr(e, "series")}
    assert kinds == {"length", "velocity", "acceleration", "jerk"}
    assert all(c.agrees for c in s.comparisons)
    assert "finite jump in jerk" in " ".join(s.notes)


BASE = """kind = "cam"
[cam]
base_radius = "40 mm"
[follower]
type = "roller"
roller_radius = "10 mm"
[[segment]]
motion = "rise"
from = "0 deg"
to = "180 deg"
lift = "20 mm"
[[segment]]
motion = "return"
from = "180 deg"
to = "360 deg"
lift = "20 mm"
"""


@pytest.mark.parametrize("old,new,key", [
    ('to = "360 deg"', 'to = "350 deg"', "segment[2].to"),
    ('from = "180 deg"', 'from = "170 deg"', "segment[2].from"),
    ('lift = "20 mm"\n[[segment]]', 'lift = "20 mm"\nlaw = "sine"\n[[segment]]', "segment[1].law"),
    ('type = "roller"', 'type = "mushroom"', "follower.type"),
    ('roller_radius = "10 mm"', 'roller_radius = "10 N"', "follower.roller_radius"),
    ('lift = "20 mm"\n', 'lift = "25 mm"\n', "segment"),
])
def test_scene_errors_name_the_key(old, new, key):
    text = BASE.replace(old, new, 1)
    with pytest.raises(SceneError) as e:
        parse_scene(text, "cam.toml")
    assert f"cam.toml: {key}" in str(e.value)


def test_base_scene_runs():
    s = Study(parse_scene(BASE, "cam.toml")).run()
    assert s.scene.model.divisions == 12 and all(c.agrees for c in s.comparisons)
    assert math.isclose(s.scene.model.follower.prime_radius, 0.05)


def test_export_csv_and_dxf_at_the_tolerance(tmp_path):
    import ezdxf
    import numpy as np

    from constructions.cams.profile import evaluate
    from drafting.cam_export import export

    scene = GALLERY / "notes-roller-cam.toml"
    csv, dxf = export(scene, tmp_path, 1e-6)
    lines = csv.read_text().splitlines()
    assert "# units: in" in lines
    rows = np.array([[float(v) for v in r.split(",")] for r in lines if r and r[0] not in "#x"]) * 0.0254
    m = load_scene(scene).model
    n = len(rows)
    th = np.linspace(0, 2 * math.pi, n, endpoint=False)
    exact = evaluate(m.program, m.follower, th).profile.T
    assert np.max(np.hypot(*(rows - exact).T)) < 1e-9          # every point exact (9 decimals of an inch)
    # every chord within the tolerance: the exact curve at the middle of each step against the chord
    mid = evaluate(m.program, m.follower, th + math.pi / n).profile.T
    a, b = rows, np.roll(rows, -1, axis=0)
    ab = b - a
    u = np.clip(np.sum((mid - a) * ab, axis=1) / np.sum(ab * ab, axis=1), 0, 1)
    dev = np.hypot(*(mid - (a + u[:, None] * ab)).T)
    size = m.follower.prime_radius + m.program.lift
    assert np.max(dev) <= 1e-6 * size * 1.01
    doc = ezdxf.readfile(dxf)
    assert doc.header["$INSUNITS"] == 1
    poly = list(doc.modelspace().query("LWPOLYLINE"))
    assert len(poly) == 1 and poly[0].closed and len(poly[0]) == n


def test_oscillating_scene():
    s = study("oscillating-roller-cam.toml")
    assert all(c.agrees for c in s.comparisons) and len(s.comparisons) == 9
    f = s.scene.model.follower
    assert math.degrees(f.gamma0) == pytest.approx(math.degrees(math.acos((48 ** 2 - 90 ** 2 - 70 ** 2) / (2 * 90 * 70))))
    text = BASE.replace('type = "roller"', 'type = "oscillating roller"\npivot_distance = "90 mm"')
    with pytest.raises(SceneError, match="follower.arm_length"):
        parse_scene(text, "cam.toml")
    text = BASE.replace('type = "roller"', 'type = "oscillating roller"\npivot_distance = "90 mm"\narm_length = "70 mm"')
    with pytest.raises(SceneError, match="segment\\[1\\].lift"):       # a swing is an angle, not a length
        parse_scene(text, "cam.toml")


def test_harmonic_example_knife_edge():
    s = study("notes-harmonic-example.toml")
    assert all(c.agrees for c in s.comparisons)
    m = s.scene.model
    import numpy as np
    _, d1, d2, _ = m.program.derivatives(np.array([math.radians(150), math.radians(285)]))
    assert d1[0] / 0.0254 == pytest.approx(1.2, rel=1e-12) and d1[1] / 0.0254 == pytest.approx(-0.48, rel=1e-12)
    jumps = {round(math.degrees(j.theta), 6): j.jumps[1] / 0.0254 for j in m.program.joins()}
    assert jumps[120.0] == pytest.approx(3.6) and jumps[180.0] == pytest.approx(3.6)
    assert jumps[210.0] == pytest.approx(-0.576) and jumps[0.0] == pytest.approx(-0.576)
    assert "above the usual 30 deg" in " ".join(s.warnings)
