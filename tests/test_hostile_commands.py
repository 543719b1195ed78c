"""Hostile input, round two (issue 22): the minimal cases the fuzzer over every family and command
(benchmarks/fuzz_scenes.py) found, each fixed at its source -- an option's error is one line, an angle
step below the smallest float refused with its range, a sweep's CSV written into a folder it makes, and
no library warning reaching the user."""

from __future__ import annotations

import warnings

import pytest

from drafting.app.cli import main

from paths import GALLERY

LINKAGE = GALLERY / "cycle-four-bar.toml"


def run(capsys, *argv: str) -> tuple[int, str, str]:
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        try:
            code = main([str(a) for a in argv])
        except SystemExit as e:               # argparse's refusal ends the process, exit 2
            code = e.code
    out, err = capsys.readouterr()
    return code, out, err


def one_line(err: str, *words: str) -> None:
    assert err.count("\n") == 1 and err.startswith("drafting: error: "), err
    assert "Traceback" not in err and "usage:" not in err, err
    for w in words:
        assert w in err, err


def test_an_option_argparse_refuses_is_one_line_naming_it(capsys):
    """argparse printed its usage (two more lines) before the error."""
    code, _, err = run(capsys, "sweep", LINKAGE, "--steps", "nan")
    assert code == 2
    one_line(err, "--steps", "'nan'", "drafting sweep --help")
    code, _, err = run(capsys, "batch", GALLERY / "lab-slider-crank.toml", "--variants", "1e300")
    assert code == 2
    one_line(err, "--variants")
    code, _, err = run(capsys, "render")
    assert code == 2
    one_line(err, "SCENE")


def test_every_below_the_smallest_float_step_is_refused_with_the_range(capsys):
    """--every=1e-320deg made an infinite number of steps (OverflowError out of math.ceil); 1e-300deg
    printed the 300-digit count."""
    for every in ("1e-320deg", "1e-300deg", "1e-9 rad"):
        code, _, err = run(capsys, "sweep", LINKAGE, f"--every={every}")
        assert code == 2
        one_line(err, "--every", "10,000,000")
        assert len(err) < 200, err


def test_a_sweep_csv_goes_into_a_folder_it_makes(tmp_path, capsys):
    """solve --csv made the folder, sweep --csv said it could not write to it."""
    dest = tmp_path / "new" / "folder" / "sweep.csv"
    code, _, err = run(capsys, "sweep", LINKAGE, "--steps", "12", "--csv", dest)
    assert code == 0, err
    assert dest.read_text().count("\n") == 13


def test_a_sweep_csv_that_cannot_be_written_names_the_scene_and_option(tmp_path, capsys):
    blocker = tmp_path / "file"
    blocker.write_text("x")
    code, _, err = run(capsys, "sweep", LINKAGE, "--steps", "12", "--csv", blocker / "sweep.csv")
    assert code == 2
    one_line(err, f"{LINKAGE}: --csv: Cannot ")


def test_a_sheet_with_letters_outside_the_repertoire_leaves_no_font_file_open(tmp_path, capsys):
    """The font subsetter (a lazy fontTools font) held its .ttf open: a ResourceWarning when collected."""
    import gc

    from drafting.backends.fonts import font_face_css
    font_face_css.cache_clear()
    with warnings.catch_warnings(record=True) as seen:
        warnings.simplefilter("always")
        css = font_face_css(frozenset("\u0416\u042f"))        # Cyrillic: subset from the .ttf, not shipped
        gc.collect()
    assert css.count("@font-face") == 2
    assert not [w for w in seen if issubclass(w.category, ResourceWarning)], [str(w.message) for w in seen]


def test_check_answers_for_a_scene_whose_sheet_has_no_room_is_one_sentence(tmp_path, capsys):
    """The key's scales come from the laid-out worked sheet: its LayoutError escaped check --answers."""
    text = (GALLERY / "notes-acceleration-example-1.toml").read_text()
    pivots = "".join(f"Q{i} = [{i % 97}, {i % 89}]\n" for i in range(40))
    scene = tmp_path / "crowded.toml"
    scene.write_text(text.replace("[frame]\n", "[frame]\n" + pivots, 1))
    answers = tmp_path / "answers.csv"
    answers.write_text("V_C,1\n")
    code, _, err = run(capsys, "check", scene, "--answers", answers)
    assert code == 2
    one_line(err, f"{scene}: drawing.paper: ")


def test_check_answers_for_a_scene_without_a_key_names_what_it_asks(tmp_path, capsys):
    answers = tmp_path / "answers.csv"
    answers.write_text("omega_out,1\n")
    scene = GALLERY / "planetary-each-member-held.toml"
    code, _, err = run(capsys, "check", scene, "--answers", answers)
    assert code == 2
    one_line(err, f"{scene}: ask.analyses: ", "no answers to mark")


def test_an_empty_vary_key_is_named_as_toml_writes_it(tmp_path, capsys):
    """``"" = [...]`` in [vary] was named ``vary.``: a key that reads as nothing."""
    scene = tmp_path / "lab.toml"
    scene.write_text((GALLERY / "lab-slider-crank.toml").read_text() + '"" = ["1 rad/s", "2 rad/s"]\n')
    code, _, err = run(capsys, "batch", scene, "--variants", "1", "-o", tmp_path / "out", "--workers", "1")
    assert code == 2
    one_line(err, f'{scene}: vary."": unknown key')


def test_an_empty_key_too_long_for_the_limits_is_named_as_toml_writes_it(tmp_path, capsys):
    """The limits' walker named ``"" = [101 items]`` in [vary] ``vary.``."""
    scene = tmp_path / "lab.toml"
    scene.write_text((GALLERY / "lab-slider-crank.toml").read_text() + '"" = [' + ", ".join(["1"] * 101) + "]\n")
    code, _, err = run(capsys, "solve", scene)
    assert code == 2
    one_line(err, f'{scene}: vary."": 101 entries; an array may have at most 100')


@pytest.mark.parametrize("argv", [("sweep", "{s}", "--csv", "{s}.csv/sweep.csv"), ("solve", "{s}", "--csv", "{s}.csv/x.csv"),
                                  ("sweep", "{cam}")])
def test_a_long_file_name_is_cut_in_the_middle_of_a_message(tmp_path, capsys, argv):
    """A 200-character file name, shown twice (the scene and its CSV), made a 450-character refusal."""
    name = "n" * 195
    s = tmp_path / f"{name}.toml"
    s.write_text((GALLERY / "lab-slider-crank.toml").read_text())
    (tmp_path / f"{name}.toml.csv").write_text("a file where a folder should be")
    cam = tmp_path / f"{name}c.toml"
    cam.write_text((GALLERY / "notes-roller-cam.toml").read_text())
    code, _, err = run(capsys, *(a.format(s=s, cam=cam) for a in argv))
    assert code == 2
    one_line(err, "\u2026" + name[-20:])
    assert len(err) <= 400, err


def test_an_answers_csv_that_is_not_csv_is_one_sentence(tmp_path, capsys):
    """A stray carriage return inside an unquoted field made csv raise out of `check --answers` (the
    1000-per-kind fuzz run, seed 11): now one sentence naming the file and line, exit 2."""
    from drafting.app.cli import main
    from paths import GALLERY
    bad = tmp_path / "answers.csv"
    bad.write_bytes(b"V_B,500 mm/s\rx,1\n")
    code = main(["check", str(GALLERY / "offset-roller-cycloidal-cam.toml"), "--answers", str(bad)])
    err = capsys.readouterr().err
    assert code == 2 and err.count("\n") == 1 and f"{bad}: line 1: is not a CSV row" in err, err


def test_an_answers_file_too_large_is_refused_before_the_scene_is_solved(tmp_path, capsys, monkeypatch):
    """The fuzzer's slowest refusal (5.2 s under load): dynamic Example 3 solved and laid out before its
    65 KiB answers file was read and refused.  The answers are read first now."""
    import drafting.app.check_cmd as check_cmd

    def never(*a, **k):
        raise AssertionError("the scene was solved before its answers file was read")
    monkeypatch.setattr(check_cmd, "solve_study", never)
    big = tmp_path / "answers.csv"
    big.write_text("V_C,1\n" * 12000)
    code, _, err = run(capsys, "check", GALLERY / "notes-dynamic-example-3.toml", "--answers", big)
    assert code == 2
    one_line(err, "is larger than 64 KiB")
