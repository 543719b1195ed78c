"""The cam results a student is asked for through the whole pipeline: the per-station table and the maxima in
``drafting solve --json``, the station table's CSV from ``drafting export``, the notes' words, and the
warning when a roller or a flat face's base radius comes within the margin of its limit."""

from __future__ import annotations

import csv
import json
import math

import pytest

from drafting.app.cli import main
from drafting.scene.reader import SceneError, parse_scene
from drafting.study.study import Study

from paths import GALLERY

ROLLER = (GALLERY / "notes-roller-cam.toml").read_text()
FLAT = (GALLERY / "notes-flat-faced-cam.toml").read_text()
RHO_MIN_IN = 2.8 ** 2 / 6.4          # the notes' pitch curve's smallest convex radius (prime circle 2 in): 1.225 in


def roller_at(fraction: float, margin: str = "") -> Study:
    """The notes' roller cam with the prime circle kept at 2 in and the roller at ``fraction`` of its limit."""
    rr = fraction * RHO_MIN_IN
    text = ROLLER.replace('roller_diameter = "1 in"', f'roller_radius = "{rr!r} in"')
    text = text.replace('base_radius = "1.5 in"', f'base_radius = "{2 - rr!r} in"' + (f"\n{margin}" if margin else ""))
    return Study(parse_scene(text, GALLERY / "near-limit.toml")).run()


def test_solve_json_has_the_station_table_and_the_maxima(capsys):
    assert main(["solve", str(GALLERY / "notes-roller-cam.toml"), "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    st = data["stations"]
    assert len(st["rows"]) == 36 and st["units"]["s"] == "in" and st["units"]["v"] == "in/rad"
    row = st["rows"][15]                                        # 150 deg: the middle of the harmonic rise
    assert row["theta"] == pytest.approx(150.0) and row["s"] == pytest.approx(0.4, rel=1e-12)
    assert row["v"] == pytest.approx(1.2, rel=1e-12)            # h pi / 2 beta = 0.8 pi / (2 pi / 3)
    assert row["pressure_angle"] == pytest.approx(math.degrees(math.atan(1.2 / 2.4)), rel=1e-12)
    assert row["rho_profile"] == pytest.approx(row["rho_pitch"] - 0.5, rel=1e-12)
    assert math.hypot(row["contact_x"], row["contact_y"]) < 2.4
    mx = data["maxima"]
    phi = mx["overall"]["pressure_angle"]
    assert phi["exact"]["value"] == pytest.approx(math.degrees(math.atan(1.2 / math.sqrt(2.4 ** 2 - 0.4 ** 2))),
                                                  rel=1e-12)
    assert phi["exact"]["at"][0] == pytest.approx(120 + math.degrees(math.acos(0.4 / 2.4)) / 3, abs=1e-6)
    assert phi["at_stations"]["value"] == pytest.approx(26.565051177, rel=1e-9)
    assert phi["at_stations"]["at"] == pytest.approx(150.0)
    assert mx["overall"]["a"]["exact"]["value"] == pytest.approx(0.4 * 9, rel=1e-12)     # (h/2)(pi/beta)^2
    assert mx["overall"]["a"]["exact"]["at"] == pytest.approx([120.0, 180.0])
    assert [s["motion"] for s in mx["segments"]] == ["dwell", "simple harmonic rise", "dwell",
                                                     "simple harmonic return"]
    assert mx["infinite"] == {"a": [], "j": pytest.approx([0.0, 120.0, 180.0, 210.0])}


def test_notes_name_the_exact_and_the_drawn_values():
    notes = " ".join(Study(parse_scene(ROLLER, GALLERY / "x.toml")).run().notes)
    assert "Largest pressure angle, exact: 26.89\u00b0 at 146.8\u00b0; at the 36 drawn stations (the \u03c6_max " \
           "row): 26.57\u00b0 at 150\u00b0." in notes
    assert "Largest d\u00b2s/d\u03b8\u00b2 (acceleration a at a cam speed of 1 rad/s), exact: 3.6 in/rad\u00b2 at " \
           "120\u00b0 and 180\u00b0" in notes
    assert "Rows P_\u03b8 and C_\u03b8: the roller centre P and the point of contact C" in notes


def test_a_roller_at_0_999_of_its_limit_is_warned_of_and_at_0_8_not():
    w = " ".join(roller_at(0.999).warnings)
    assert "Near the undercut limit" in w and "99.9 %" in w and "within the 5 % margin" in w
    assert "Cusp" not in w and "Undercut" not in w
    assert not any("limit" in x for x in roller_at(0.8).warnings)
    assert any("Near the undercut limit" in x for x in roller_at(0.951).warnings)
    assert not any("Near" in x for x in roller_at(0.949).warnings)
    # the scene's own margin
    assert any("within the 25 % margin" in x for x in roller_at(0.8, "limit_margin = 0.25").warnings)
    assert not any("Near" in x for x in roller_at(0.999, "limit_margin = 0").warnings)


def test_a_flat_face_within_the_margin_of_its_smallest_base_radius_is_warned_of():
    near = FLAT.replace('base_radius = "50 mm"', 'base_radius = "3.2 mm"')
    assert near != FLAT
    w = " ".join(Study(parse_scene(near, GALLERY / "x.toml")).run().warnings)
    assert "Near the flat face's limit" in w and "97.66 %" in w          # 3.125 / 3.2
    assert not Study(parse_scene(FLAT, GALLERY / "x.toml")).run().warnings


@pytest.mark.parametrize("value", ["1", "-0.1", "true", "\"5 %\""])
def test_a_bad_limit_margin_names_the_key(value):
    text = ROLLER.replace('base_radius = "1.5 in"', f'base_radius = "1.5 in"\nlimit_margin = {value}')
    with pytest.raises(SceneError, match="cam.limit_margin"):
        parse_scene(text, GALLERY / "x.toml")


def test_export_writes_the_station_table_beside_the_profile(tmp_path, capsys):
    assert main(["export", str(GALLERY / "offset-roller-cycloidal-cam.toml"), "-o", str(tmp_path),
                 "--tolerance", "1e-4"]) == 0
    text = (tmp_path / "offset-roller-cycloidal-cam-stations.csv").read_text()
    rows = list(csv.reader(line for line in text.splitlines() if not line.startswith("#")))
    assert rows[0][:6] == ["station", "cam angle (deg)", "s (mm)", "v (m/s)", "a (m/s^2)", "j (m/s^3)"]
    assert len(rows) == 13
    # station 3 (90 deg) of the cycloidal rise of 30 mm over 150 deg at 300 rpm: v = h w (1 - cos 2 pi u) / beta
    w, beta, u = 300 * math.pi / 30, math.radians(150), 90 / 150
    assert float(rows[4][3]) == pytest.approx(0.030 * w * (1 - math.cos(2 * math.pi * u)) / beta, rel=1e-12)
