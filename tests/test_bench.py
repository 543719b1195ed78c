"""The sheet benchmark's table: medians, and the best runs beside them (timings are never asserted)."""

from __future__ import annotations

import sys

import pytest


def test_the_sheet_table_gives_the_median_and_the_best_runs():
    """'to SVG' is the sum of the stages' medians, and in brackets of their best runs."""
    from drafting.app.bench import Timing, format_render_rows
    t = Timing(0.010, 0.008)
    assert t == 0.010 and t.best == 0.008 and t + 0.005 == pytest.approx(0.015)
    row = {"scene": "s", "sheets": 1, "solve": Timing(0.002, 0.001), "layout": Timing(0.010, 0.009),
           "svg": Timing(0.005, 0.004), "pdf": Timing(0.008, 0.007), "png": Timing(0.04, 0.03),
           "artists": 3, "mpl_svg": 0.3, "mpl_pdf": 0.4, "mpl_png": 0.5}
    line = format_render_rows([row]).splitlines()[1]
    assert line.rstrip().endswith("17.0 [ 14.0]  20.0 [ 17.0]"), line


def test_the_run_says_how_fast_the_machine_was():
    """A fixed loop of plain Python timed beside the sheets: the yardstick of a quiet or a busy minute."""
    from drafting.app.bench import Timing, format_machine_speed, machine_speed
    t = machine_speed(1)
    assert isinstance(t, Timing) and 0 < t.best <= t
    assert format_machine_speed(Timing(0.0123, 0.0101)).endswith(
        "took 12.3 ms, best 10.1 ms (the sheet figures move with it)")


def test_outside_a_checkout_the_peers_are_one_sentence_and_exit_2(tmp_path, monkeypatch, capsys):
    """The peers live in the checkout's benchmarks/ folder: without it ``drafting bench --peers`` says so in
    one line before timing anything, and the sheet table says why it has no matplotlib peer."""
    from drafting.app import bench
    from drafting.app.cli import main
    for name in ("peers", "matplotlib_peer"):
        monkeypatch.delitem(sys.modules, f"benchmarks.{name}", raising=False)
    monkeypatch.setattr(bench, "BENCHMARKS", tmp_path / "benchmarks")
    monkeypatch.setattr(bench, "machine_speed", lambda *a: pytest.fail("timed before refusing"))
    assert main(["bench", "--quick", "--peers"]) == 2
    out, err = capsys.readouterr()
    assert out == "" and err == (f"drafting: error: bench --peers: the benchmark peers live in the benchmarks "
                                 f"folder of a source checkout, and {tmp_path / 'benchmarks' / 'peers.py'} is "
                                 f"not there\n")
    assert bench.format_render_rows([]).splitlines()[-1] == (
        f"  The same line art through matplotlib: not run (its peer lives in the benchmarks folder of a source "
        f"checkout, and {tmp_path / 'benchmarks'} is not there).")


def test_in_a_checkout_the_peers_load_from_the_benchmarks_folder():
    from drafting.app.bench import BENCHMARKS, benchmark
    peers = benchmark("peers")
    assert peers is benchmark("peers") and peers.__file__ == str(BENCHMARKS / "peers.py")
    assert benchmark("matplotlib_peer").__file__ == str(BENCHMARKS / "matplotlib_peer.py")


def _small_gallery(tmp_path, monkeypatch):
    """Two of the gallery's scenes (a linkage and a cam) in a gallery of their own: the command's run, not
    its figures, is what a test can check."""
    from drafting.app import bench
    for name in ("notes-velocity-example-1.toml", "notes-harmonic-example.toml"):
        (tmp_path / name).write_text((bench.GALLERY / name).read_text())
    monkeypatch.setattr(bench, "GALLERY", tmp_path)
    return ("notes-velocity-example-1", "notes-harmonic-example")


def test_the_gallery_table_names_every_scene_and_every_stage(tmp_path, monkeypatch, capsys):
    """``drafting bench --gallery``: a row for every gallery scene, a column for every stage, the slowest
    sheet named; no time is asserted."""
    from drafting.app.cli import main
    scenes = _small_gallery(tmp_path, monkeypatch)
    assert main(["bench", "--gallery", "--quick"]) == 0
    out = capsys.readouterr().out.splitlines()
    head = next(line for line in out if line.lstrip().startswith("scene"))
    assert head.split() == ["scene", "pages", "solve", "layout", "(plan", "labels)", "SVG", "total", "worst"]
    rows = {line.split()[0]: line.split()[1:] for line in out if line.split() and line.split()[0] in scenes}
    assert set(rows) == set(scenes) and all(len(r) == 8 for r in rows.values())
    assert any(line.lstrip().startswith("slowest: ") for line in out)
    assert out[-1].startswith("Machine speed in this run")


def test_the_gallery_figures_as_json(tmp_path, monkeypatch, capsys):
    """``--json``: every scene with every stage in ms, the total the median of the runs' sums (no larger
    than the worst run's)."""
    import json
    from drafting.app.cli import main
    scenes = _small_gallery(tmp_path, monkeypatch)
    assert main(["bench", "--gallery", "--quick", "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["repeats"] == 3 and data["unit"] == "ms"
    assert [s["scene"] for s in data["sheets"]] == sorted(scenes)
    for s in data["sheets"]:
        assert s["pages"] == 1 and all(s[k] > 0 for k in ("solve", "layout", "plan", "labels", "svg", "total"))
        assert s["total"] <= s["worst"] and max(s["plan"], s["labels"]) < s["layout"]     # parts of the layout


def test_json_without_the_gallery_is_one_sentence(capsys):
    from drafting.app.cli import main
    assert main(["bench", "--json"]) == 2
    assert capsys.readouterr().err == "drafting: error: bench --json goes with --gallery\n"
