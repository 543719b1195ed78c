"""The cam scene kind through the whole pipeline: the gallery's cams, their warnings, JSON and errors."""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest

from drafting.app.cli import main
from drafting.scene.reader import SceneError, load_scene, parse_scene
from drafting.study.study import Study
from drafting.study.worked import sheets_for

from paths import GALLERY


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


def test_the_lift_at_every_station_is_set_out_as_a_table_under_its_step():
    """The notes' 36 stations in four column groups of nine, read down each group: station, cam angle and
    the lift at that station (the construction's own value, in the scene's unit), on the same sheet and in
    the same text slot as the step that sets it out."""
    import re
    from constructions.cams.stations import station_rows
    s = study("notes-roller-cam.toml")
    step = next(st for st in s.construction.steps if st.table)
    head, *rows = step.table_text()
    assert head == ("Station", "\u03b8 (\u00b0)", "s") * 4 and len(rows) == 9
    for r, row in enumerate(rows):
        for g in range(4):
            i = 9 * g + r
            assert row[3 * g:3 * g + 2] == (str(i), f"{10 * i}")
            assert float(row[3 * g + 2].split()[0]) == pytest.approx(step.value(f"s{i}").value, rel=5e-4, abs=1e-15)
    assert step.value("s14").value == pytest.approx(0.2 * 0.0254, rel=1e-12)   # 140 deg: 0.2 in of lift
    # the step and its table are set in one slot, the table under the step's words
    sheets = sheets_for(s)
    n = 1 + s.construction.steps.index(step)
    regions = {t.region for sh in sheets for t in sh.texts() if t.name in (f"step {n}", f"step {n} number")}
    table = {t.region for sh in sheets for t in sh.texts() if t.name.startswith(f"step {n} table")}
    assert len(regions) == 1 and table == regions
    # fewer stations, fewer groups; six or fewer in one
    for count, groups, nrows in ((12, 2, 6), (24, 3, 8), (36, 4, 9), (5, 1, 5), (72, 4, 18)):
        got = station_rows([2 * math.pi * i / count for i in range(count)], "s")
        assert len(got[0]) == 3 * groups and len(got) - 1 == nrows
        cells = [c for row in got[1:] for c in row if re.fullmatch(r"\$s\d+", c)]
        assert sorted(cells, key=lambda c: int(c[2:])) == [f"$s{i}" for i in range(count)]


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
    assert "Undercut" in w and "\u00b0 to" in w
    assert "loops back there" in " ".join(s.notes)
    assert main(["solve", str(GALLERY / "roller-cam-undercut.toml"), "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    spans = data["profile"]["undercut"]
    assert len(spans) == 2 and all(a < b for a, b in spans)
    assert data["analyses"] == ["cam construction", "cam closed forms", "cam station table", "cam maxima"]


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
    """The files hold the profile-only path's points (every chord within the tolerance: proved in
    tests/test_cam_profile.py), each on the exact envelope, in the scene's unit."""
    import ezdxf
    import numpy as np

    from constructions.cams.envelope import evaluate
    from constructions.cams.sampling import profile_samples
    from drafting.app.cam_export import export

    scene = GALLERY / "notes-roller-cam.toml"
    csv, dxf, stations = export(scene, tmp_path, 1e-6)
    assert stations.name == "notes-roller-cam-stations.csv"
    lines = csv.read_text().splitlines()
    assert "# units: in" in lines
    rows = np.array([[float(v) for v in r.split(",")] for r in lines if r and r[0] not in "#x"]) * 0.0254
    m = load_scene(scene).model
    size = m.follower.prime_radius + m.program.lift
    theta, pts = profile_samples(m.program, m.follower, 1e-6 * size)
    assert f"# tolerance: {1e-6 * size / 0.0254:.6g} in (largest distance of a chord from the exact profile)" in lines
    assert len(rows) == pts.shape[1]
    exact = evaluate(m.program, m.follower, theta).profile.T
    assert np.max(np.hypot(*(rows - exact).T)) < 1e-9          # every point exact (9 decimals of an inch)
    doc = ezdxf.readfile(dxf)
    assert doc.header["$INSUNITS"] == 1
    poly = list(doc.modelspace().query("LWPOLYLINE"))
    assert len(poly) == 1 and poly[0].closed and len(poly[0]) == len(rows)


def test_export_undercut_cam_is_trimmed_and_the_cli_pieces(tmp_path, capsys):
    """An undercut cam exports its trimmed profile (a simple ring, no roller cutting into it); the
    export's arguments and runner serve any command line; the module still runs on its own."""
    import argparse
    import subprocess
    import sys

    import numpy as np
    from shapely.geometry import LinearRing

    from constructions.cams.profile import analyse
    from drafting.app.cam_export import add_export_arguments, run_export
    from drafting.study.study import Study

    scene = load_scene(GALLERY / "roller-cam-undercut.toml")
    m = scene.model
    pts, tol = Study(scene).get("machining profile")
    assert LinearRing(pts.T).is_simple
    P = analyse(m.program, m.follower, 4096).samples.pitch
    d = np.min(np.hypot(pts[0][:, None] - P[0][None, :], pts[1][:, None] - P[1][None, :]), axis=1)
    assert np.min(d) >= m.follower.roller_radius * (1 - 1e-3)
    ap = add_export_arguments(argparse.ArgumentParser(prog="drafting export"))
    assert run_export(ap.parse_args([str(GALLERY / "notes-roller-cam.toml"), "-o", str(tmp_path)])) == 0
    assert sorted(p.name for p in tmp_path.iterdir()) == ["notes-roller-cam-profile.csv", "notes-roller-cam-profile.dxf",
                                                          "notes-roller-cam-stations.csv"]
    for bad in ("0.5", "1e-10", "1e-300", "nan"):     # 1e-300 was a traceback, 1e-10 ran for ever
        assert run_export(ap.parse_args([str(GALLERY / "notes-roller-cam.toml"), "--tolerance", bad])) == 2
        err = capsys.readouterr().err
        assert err.count("\n") == 1 and "--tolerance must lie between 1e-07 and 0.1" in err, err
    out = tmp_path / "m"
    r = subprocess.run([sys.executable, "-m", "drafting.app.cam_export", str(GALLERY / "notes-flat-faced-cam.toml"),
                        "-o", str(out)], capture_output=True, text=True, cwd=Path(__file__).resolve().parent.parent)
    assert r.returncode == 0 and (out / "notes-flat-faced-cam-profile.dxf").exists()
    # the drafting command's own subcommand; a linkage scene is refused in one sentence
    from drafting.app.cli import main
    assert main(["export", str(GALLERY / "oscillating-roller-cam.toml"), "-o", str(tmp_path / "c")]) == 0
    assert (tmp_path / "c" / "oscillating-roller-cam-profile.csv").exists()
    capsys.readouterr()
    assert main(["export", str(GALLERY / "notes-velocity-example-1.toml"), "-o", str(tmp_path / "c")]) == 2
    err = capsys.readouterr().err
    assert err.startswith("drafting: error: ") and "only a cam scene has a profile to export" in err and err.count("\n") == 1


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
    assert "above the usual 30\u00b0" in " ".join(s.warnings)


def test_oscillating_flat_faced_scene():
    """The oscillating flat face through the pipeline: construction points = Kennedy's closed form, the face's
    reach along the arm in the notes, the swing charted as an angle with named units, the scene's errors."""
    s = study("oscillating-flat-faced-cam.toml")
    assert all(c.agrees for c in s.comparisons) and len(s.comparisons) == 9
    f = s.scene.model.follower
    assert math.degrees(f.beta0) == pytest.approx(30.0, rel=1e-12)                  # asin((40 + 10) / 100)
    assert "The face must reach from" in " ".join(s.notes) and not s.warnings
    labels = {e.series[0].label for e in s.construction.entities() if hasattr(e, "series")}
    assert "d\u03b1/dt (rad/s\u00b3)" in labels
    osc = BASE.replace('type = "roller"\nroller_radius = "10 mm"',
                       'type = "oscillating flat-faced"\npivot_distance = "100 mm"').replace('"20 mm"', '"10 deg"')
    m = parse_scene(osc, "cam.toml").model
    assert m.follower.kind == "oscillating flat-faced" and m.follower.face_offset == 0
    for old, new, key in (('pivot_distance = "100 mm"', 'pivot_distance = "100 mm"\narm_length = "70 mm"',
                           "follower.arm_length"),
                          ('pivot_distance = "100 mm"', 'face_offset = "5 mm"', "follower.pivot_distance"),
                          ('pivot_distance = "100 mm"', 'pivot_distance = "100 mm"\nface_offset = "70 mm"',
                           "follower.face_offset"),
                          ('"10 deg"', '"70 deg"', "follower.pivot_distance")):      # swings past square
        with pytest.raises(SceneError) as e:
            parse_scene(osc.replace(old, new), "cam.toml")
        assert f"cam.toml: {key}" in str(e.value)
    with pytest.raises(SceneError, match="follower.face_offset"):
        parse_scene(BASE.replace('roller_radius = "10 mm"', 'roller_radius = "10 mm"\nface_offset = "1 mm"'), "cam.toml")


def test_gallery_cam_exactly_at_the_undercut_limit():
    """The gallery's limit cam: its roller equals the pitch curve's smallest radius of curvature (the sheet
    warns of the cusp, at the limit, with the angle), the profile is not trimmed, and the same pitch curve
    with the undercut gallery cam's 18 mm roller does undercut."""
    s = study("roller-cam-undercut-limit.toml")
    cp = s.get("profile").profile
    f = s.scene.model.follower
    assert f.roller_radius == pytest.approx(cp.min_rho_pitch[1], rel=1e-12)
    assert f.prime_radius == pytest.approx(0.030, rel=1e-15)
    assert cp.cusp_at and not cp.undercut and cp.trimmed is cp.samples.profile
    w = " ".join(s.warnings)
    assert "Cusp, at the undercut limit" in w and "49.42\u00b0" in w
    assert "zero to rounding" in " ".join(s.notes)
    assert all(c.agrees for c in s.comparisons)
    past = study("roller-cam-undercut.toml").get("profile").profile
    assert past.follower.prime_radius == pytest.approx(0.030, rel=1e-15) and past.undercut
    assert past.min_rho_pitch[1] == pytest.approx(cp.min_rho_pitch[1], rel=1e-12)
