"""Sweeps over one turn of the crank (constructions.sweep, ``drafting sweep``): equal to the one-pose
analytic solution, gaps exactly where the mechanism cannot be assembled, continuation on the scene's
branch, and the CSV in the scene's units."""

from __future__ import annotations

import csv
import math

import numpy as np
import pytest

from constructions.check import analytic_solution
from constructions.mechanisms.pose import locate
from constructions.sweep import sweep
from drafting.app import cli
from drafting.scene.reader import load_scene

from paths import GALLERY
FOUR_BAR = GALLERY / "notes-velocity-example-2.toml"
QUICK_RETURN = GALLERY / "quick-return-slotted-lever.toml"


def _turn(scene, n):
    return scene.angle + 2 * math.pi * np.arange(n) / n


def _agree(s, i, a, rel=1e-9):
    for kind in ("positions", "velocities", "accelerations"):
        ref = getattr(a, kind)
        scale = max(v.norm() for v in ref.values()) or 1.0
        for name, v in ref.items():
            x, y = getattr(s, kind)[name]
            assert math.hypot(x[i] - v.x, y[i] - v.y) <= rel * scale, (kind, name, i)
    for kind in ("angular", "angular_acceleration"):
        ref = getattr(a, kind)
        scale = max(abs(w) for w in ref.values()) or 1.0
        for k, w in ref.items():
            assert abs(getattr(s, kind)[k][i] - w) <= rel * scale, (kind, k, i)


def test_four_bar_sweep_equals_analytic_solution():
    sc = load_scene(FOUR_BAR)
    th = _turn(sc, 72)
    s = sweep(sc.mechanism, th, sc.omega, sc.alpha)
    assert s.model == "four-bar" and s.assembles.all() and s.thetas.shape == (72,)
    for i in (0, 11, 30, 53, 71):
        _agree(s, i, analytic_solution(sc.mechanism, th[i], sc.omega, sc.alpha))


@pytest.mark.parametrize("name, model", [("notes-velocity-example-1", "slider-crank"),
                                         ("notes-acceleration-example-4", "dyad chain")])
def test_other_vectorised_sweeps_equal_analytic_solution(name, model):
    sc = load_scene(GALLERY / f"{name}.toml")
    th = _turn(sc, 36)
    s = sweep(sc.mechanism, th, sc.omega, sc.alpha)
    assert s.model == model and s.assembles.all()
    for i in (0, 7, 20, 35):
        _agree(s, i, analytic_solution(sc.mechanism, th[i], sc.omega, sc.alpha))


def test_four_bar_that_cannot_assemble_has_gaps_exactly_there(tmp_path):
    text = FOUR_BAR.read_text().replace("length = 10\n", "length = 28\n", 1)
    path = tmp_path / "part-turn.toml"
    path.write_text(text)
    sc = load_scene(path)
    th = _turn(sc, 72)
    s = sweep(sc.mechanism, th, sc.omega, sc.alpha)
    expected = np.array([analytic_solution(sc.mechanism, t, sc.omega, sc.alpha) is not None for t in th])
    assert 0 < expected.sum() < 72
    assert np.array_equal(s.assembles, expected)
    bad = ~expected
    for name in ("B", "C"):
        for arr in s.positions[name] + s.velocities[name] + s.accelerations[name]:
            assert np.isnan(arr[bad]).all() and np.isfinite(arr[expected]).all()
    assert np.isnan(s.angular[3][bad]).all() and np.isfinite(s.angular[3][expected]).all()
    assert np.all(s.positions["O2"][0] == 30e-3)                 # the frame stays where it is
    for i in np.flatnonzero(expected)[::5]:
        _agree(s, i, analytic_solution(sc.mechanism, th[i], sc.omega, sc.alpha))
    # gap ranges: consecutive runs of the failing angles
    assert sum(j - i for i, j in s.gaps()) == int(bad.sum())


def test_quick_return_stays_on_its_branch_over_a_turn():
    sc = load_scene(QUICK_RETURN)
    n = 180
    th = _turn(sc, n)
    s = sweep(sc.mechanism, th, sc.omega, sc.alpha)
    assert s.model == "constraint equations" and s.assembles.all()
    dt = (2 * math.pi / n) / abs(sc.omega)          # time per step
    for name, (x, y) in s.positions.items():
        vx, vy = s.velocities[name]
        vmax = float(np.max(np.hypot(vx, vy)))
        step = np.hypot(np.diff(np.append(x, x[0])), np.diff(np.append(y, y[0])))
        assert step.max() <= 2.0 * vmax * dt + 1e-12, name
    for i in (0, 37, 90, 151):
        a = analytic_solution(sc.mechanism, th[i], sc.omega, sc.alpha, guess=locate(sc.mechanism, th[i]).positions)
        _agree(s, i, a)


def _run(capsys, *argv):
    code = cli.main(["sweep", *map(str, argv)])
    out, err = capsys.readouterr()
    return code, out, err


def test_csv_has_units_and_parses_back(tmp_path, capsys):
    dest = tmp_path / "qr.csv"
    code, out, err = _run(capsys, QUICK_RETURN, "--steps", 12, "--csv", dest)
    assert code == 0 and err == "" and str(dest) in out
    rows = list(csv.reader(dest.open(newline="", encoding="utf-8")))
    header, body = rows[0], rows[1:]
    assert len(body) == 12
    assert header[0] == "crank angle [\u00b0]"
    assert "Q vx [mm/s]" in header and "Q ax [m/s^2]" in header and "omega_3 [rad/s]" in header
    assert "alpha_4 [rad/s^2]" in header
    assert all(len(r) == len(header) for r in body)
    assert float(body[0][0]) == pytest.approx(30.0)
    assert float(body[1][0]) == pytest.approx(60.0)
    assert float(body[0][header.index("omega_1 [rad/s]")]) == pytest.approx(10.0)
    assert not [p for p in tmp_path.iterdir() if p.name.startswith(".drafting-tmp-")]


def test_csv_gaps_are_empty_cells(tmp_path, capsys):
    scene = tmp_path / "part.toml"
    scene.write_text(FOUR_BAR.read_text().replace("length = 10\n", "length = 28\n", 1))
    dest = tmp_path / "part.csv"
    code, _, _ = _run(capsys, scene, "--csv", dest)
    assert code == 0
    rows = list(csv.DictReader(dest.open(newline="", encoding="utf-8")))
    assert len(rows) == 72
    gaps = [r for r in rows if r["C x [mm]"] == ""]
    assert gaps and all(r["omega_3 [rad/s]"] == "" and r["O2 x [mm]"] == "30.0" for r in gaps)


def test_every_5deg_gives_72_rows(tmp_path, capsys):
    dest = tmp_path / "fb.csv"
    code, _, _ = _run(capsys, FOUR_BAR, "--every", "5deg", "--csv", dest)
    assert code == 0
    rows = list(csv.reader(dest.open(newline="", encoding="utf-8")))
    assert len(rows) == 73
    assert [float(r[0]) for r in rows[1:3]] == pytest.approx([45.0, 50.0])


def test_summary_without_csv(capsys):
    code, out, _ = _run(capsys, FOUR_BAR, "--steps", 36)
    assert code == 0
    assert "36 crank angles" in out and "36 assembled" in out and "omega min" in out


@pytest.mark.parametrize("args, word", [
    (["--every", "5mm"], "--every"),
    (["--every", "0deg"], "--every"),
    (["--every", "banana"], "--every"),
    (["--steps", "0"], "--steps"),
    (["--steps", "10000001"], "--steps"),
])
def test_bad_options_are_one_line_exit_2(capsys, args, word):
    code, out, err = _run(capsys, FOUR_BAR, *args)
    assert code == 2 and out == ""
    assert err.count("\n") == 1 and err.startswith("drafting: error: ") and word in err
    assert "Traceback" not in err


def test_bad_scene_is_one_line_exit_2(tmp_path, capsys):
    code, _, err = _run(capsys, tmp_path / "missing.toml")
    assert code == 2 and err.count("\n") == 1 and err.startswith("drafting: error: ")


# -- a change point: the branch kept where the two assemblies meet ----------------------------------------

PARALLELOGRAM = '''
[drawing]
title = "Parallelogram four-bar"
number = "T-P"
[units]
length = "mm"
[frame]
O1 = [0, 0]
O2 = [100, 0]
[[link]]
number = 2
joints = ["O1", "B"]
length = 40
[[link]]
number = 3
joints = ["B", "C"]
length = 100
[[link]]
number = 4
joints = ["O2", "C"]
length = 40
[input]
link = 2
angle = "30 deg"
omega = "10 rad/s"
[assembly]
C = "left of B->O2"
[ask]
analyses = ["sweep"]
'''


def test_a_parallelogram_stays_a_parallelogram_through_its_change_points(tmp_path, capsys):
    """Where crank, coupler and rocker lie along the frame the two assemblies meet; a fixed assembly sign
    would turn the parallelogram into an antiparallelogram there (what a closed form with one sign does).
    The sweep keeps C = B + O1O2 over the whole turn, and says where it passed the change points."""
    from drafting.scene.reader import parse_scene
    sc = parse_scene(PARALLELOGRAM, tmp_path / "p.toml")
    assert load_classification(sc).grashof == "change point"
    th = sc.angle + 2 * math.pi * np.arange(7201) / 7200
    s = sweep(sc.mechanism, th, sc.omega, sc.alpha)
    (bx, by), (cx, cy) = s.positions["B"], s.positions["C"]
    assert s.assembles.all()
    assert np.nanmax(np.hypot(cx - bx - 0.1, cy - by)) < 1e-12          # C = B + (100 mm, 0) throughout
    assert np.degrees(s.change_points) == pytest.approx([180.0, 360.0])
    w3 = np.asarray(s.angular[3])
    assert np.nanmax(np.abs(w3)) < 1e-9                                  # the coupler only translates
    # on the antiparallelogram branch the same holds for that branch: it stays crossed
    crossed = parse_scene(PARALLELOGRAM.replace('"left of B->O2"', '"right of B->O2"'), tmp_path / "a.toml")
    s2 = sweep(crossed.mechanism, th, crossed.omega)
    (bx, by), (cx, cy) = s2.positions["B"], s2.positions["C"]
    assert np.count_nonzero(np.hypot(cx - bx - 0.1, cy - by) > 1e-6) > 0.99 * th.size   # never parallel
    vx, vy = s2.velocities["C"]
    jumps = np.hypot(np.diff(vx), np.diff(vy))
    assert np.nanmax(jumps) < 0.01 * np.nanmax(np.hypot(vx, vy))         # velocities run on smoothly
    path = tmp_path / "p.toml"
    path.write_text(PARALLELOGRAM)
    assert cli.main(["sweep", str(path), "--steps", "72"]) == 0
    out = capsys.readouterr().out
    assert "passes a change point (all links in line) at 180\u00b0, 360\u00b0 and stays on its branch" in out


def load_classification(scene):
    from constructions.mechanisms.classify import classify_four_bar
    return classify_four_bar(scene.mechanism)


def test_a_long_sweep_shows_progress_on_a_terminal_only(tmp_path, capsys, monkeypatch):
    """The bar goes to stderr when it is a terminal (faked here) and the job is long; piped, nothing."""
    from drafting.app import progress
    assert cli.main(["sweep", str(QUICK_RETURN), "--steps", "300", "--csv", str(tmp_path / "a.csv")]) == 0
    assert "%" not in capsys.readouterr().err                           # not a terminal: no bar
    monkeypatch.setattr(progress, "LONG", 100)
    monkeypatch.setattr(progress, "_is_terminal", lambda stream: True)
    assert cli.main(["sweep", str(QUICK_RETURN), "--steps", "300", "--csv", str(tmp_path / "b.csv")]) == 0
    err = capsys.readouterr().err
    assert "\rsweep [" in err and "\rcsv [" in err and "100.0 %" in err and err.endswith("\n")
    assert (tmp_path / "a.csv").read_text() == (tmp_path / "b.csv").read_text()


def test_sweep_draws_the_cycle_sheet_on_request(tmp_path, capsys):
    assert cli.main(["sweep", str(FOUR_BAR), "--steps", "36", "--sheet", str(tmp_path)]) == 0
    out = capsys.readouterr().out
    svgs = sorted(tmp_path.glob("notes-velocity-example-2-cycle*.svg"))
    assert svgs and (tmp_path / "notes-velocity-example-2-cycle.pdf").stat().st_size > 1000
    text = " ".join(p.read_text() for p in svgs)
    assert "Transmission angle" in text and "Angular velocities" in text and "wrote" in out
    bad = tmp_path / "a-file"
    bad.write_text("x")
    assert cli.main(["sweep", str(FOUR_BAR), "--sheet", str(bad / "sub")]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "--sheet" in err and "Traceback" not in err


def test_the_csv_goes_round_one_turn_from_the_scene_angle_without_float_noise(tmp_path, capsys):
    """From the scene's crank angle (60 deg) round one turn in 45 deg steps, written within the turn (375 ->
    15), and every number to 12 significant digits: 60.0, not 59.99999999999999 (issue 24)."""
    dest = tmp_path / "cycle.csv"
    code, _, _ = _run(capsys, GALLERY / "cycle-four-bar.toml", "--steps", 8, "--csv", dest)
    assert code == 0
    body = list(csv.reader(dest.open(newline="", encoding="utf-8")))[1:]
    assert [r[0] for r in body] == ["60.0", "105.0", "150.0", "195.0", "240.0", "285.0", "330.0", "15.0"]
    cells = [c for r in body for c in r if c]
    assert all(len(c.lstrip("-").replace(".", "").lstrip("0").split("e")[0]) <= 12 for c in cells), cells
    from drafting.app.sweep_cmd import significant
    # 12 digits of the column's largest value: -1e-300 beside 60 is rounding noise, written 0.0 (not -0.0)
    assert significant(np.array([59.99999999999999, 10.000000000000007, 0.0, -1e-300, np.nan])).tolist()[:4] == \
        [60.0, 10.0, 0.0, 0.0]


def test_rounding_keeps_twelve_digits_of_each_column_and_no_noise_near_zero():
    """Each column to 12 significant digits of its largest value: a velocity of -4.44e-14 mm/s in a column of
    hundreds is 0.0, the nearest float of each 12-digit decimal has a short repr, large and tiny columns
    alike, and a column's rounding does not reach into another's."""
    from drafting.app.sweep_cmd import rows_of, significant
    table = np.array([[60.30000000000001, -4.4408920984999995e-14, 123456789.01234567, 3.0000000000000004e-12],
                      [359.99999999999994, 567.8901234567891, -0.5, 1.2345678901234567e-12],
                      [np.nan, 1e-300, 987654321.0987654, np.inf]])
    out = significant(table)
    assert out[0].tolist() == [60.3, 0.0, 123456789.012, 3e-12]
    assert out[1].tolist() == [360.0, 567.890123457, -0.5, 1.23456789012e-12]
    assert math.isnan(out[2, 0]) and out[2, 1] == 0.0 and out[2, 2] == 987654321.099 and out[2, 3] == math.inf
    big = significant(np.array([1.0000000000000002e20, 123456789012345.67, -3.3333333333333333e19]))
    assert big.tolist() == [1e20, 123457000000000.0, -3.3333333333e19]
    assert next(rows_of(out[:1])) == "60.3,0.0,123456789.012,3e-12"


def test_a_scene_at_zero_runs_0_to_355_and_the_summary_stays_within_the_turn(tmp_path, capsys):
    """Starting at 0 the angle column runs 0, 5, ..., 355 (one turn in the step); the printed summary names
    the start, the step and the last angle within the turn (60, step 5, to 55 -- not 415)."""
    text = (GALLERY / "cycle-four-bar.toml").read_text()
    assert 'angle = "60 deg"' in text
    scene = tmp_path / "at-zero.toml"
    scene.write_text(text.replace('angle = "60 deg"', 'angle = "0 deg"'))
    dest = tmp_path / "zero.csv"
    code, _, _ = _run(capsys, scene, "--csv", dest)
    body = list(csv.reader(dest.open(newline="", encoding="utf-8")))[1:]
    assert code == 0 and [r[0] for r in body] == [f"{5 * k}.0" for k in range(72)]
    code, out, _ = _run(capsys, GALLERY / "cycle-four-bar.toml")
    assert code == 0 and "72 crank angles from 60\u00b0 round one turn in steps of 5\u00b0 (to 55\u00b0)" in out
    dest = tmp_path / "tenth.csv"
    code, _, _ = _run(capsys, GALLERY / "cycle-four-bar.toml", "--every", "0.1deg", "--csv", dest)
    first = [r[0] for r in list(csv.reader(dest.open(newline="", encoding="utf-8")))[1:]]
    assert code == 0 and len(first) == 3600 and first[:2] == ["60.0", "60.1"] and first[-1] == "59.9"
    assert first[2998:3002] == ["359.8", "359.9", "0.0", "0.1"]
    assert all(len(c.split(".")[1]) == 1 for c in first)                     # 0.1 steps, not 60.30000000000001


@pytest.mark.parametrize("name", ["notes-velocity-example-2", "notes-velocity-example-1"])
def test_a_long_sweep_runs_on_the_default_threads_with_the_same_numbers(name, monkeypatch):
    """sweep() of a four-bar or slider-crank gives its kernel the default thread count (here two, by
    DRAFTING_SWEEP_THREADS): the pool is asked for, and the numbers are the one-thread run's, bit for bit."""
    from constructions import sweep_threads
    sc = load_scene(GALLERY / f"{name}.toml")
    th = _turn(sc, 4 * sweep_threads.THREADED_FROM + 3)
    monkeypatch.setattr(sweep_threads, "_process_threads", None)
    monkeypatch.setenv(sweep_threads.ENV, "1")
    one = sweep(sc.mechanism, th, sc.omega, sc.alpha)
    asked = []
    executor = sweep_threads._executor
    monkeypatch.setattr(sweep_threads, "_executor", lambda: asked.append(1) or executor())
    monkeypatch.setenv(sweep_threads.ENV, "2")
    two = sweep(sc.mechanism, th, sc.omega, sc.alpha)
    assert asked and one.model == two.model
    for kind in ("positions", "velocities", "accelerations"):
        for n, (x, y) in getattr(one, kind).items():
            assert x.tobytes() == getattr(two, kind)[n][0].tobytes() and y.tobytes() == getattr(two, kind)[n][1].tobytes()
    for kind in ("angular", "angular_acceleration"):
        for k, w in getattr(one, kind).items():
            assert w.tobytes() == getattr(two, kind)[k].tobytes()
