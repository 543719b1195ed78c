"""Limits (README, "Scene files" / "Limits") and units read strictly: each refusal is one sentence
naming the file, the key and the limit, with exit 2, in well under a second; and every SVG the test
suite writes is well-formed, inert XML."""

from __future__ import annotations

import math
import time

import pytest

from drafting.scene import limits
from drafting.scene.textsafe import printable
from drafting.app.cli import main
from drafting.study.worked import builtin_example
from drafting.scene.reader import parse_scene
from drafting.scene.units import DEFAULT_UNITS, KINDS, UnitError, check_unit, format_value, from_si, to_si

EXAMPLE = builtin_example().read_text()


def refuse(tmp_path, capsys, text: str | bytes, key: str, *words: str, name: str = "scene.toml") -> str:
    p = tmp_path / name
    p.write_bytes(text.encode("utf-8") if isinstance(text, str) else text)
    to_si("1 mm", "length", "mm")             # one-time start-up (pint's registry) is not the refusal's
    t0 = time.thread_time()               # CPU time: a busy machine's waiting is not the refusal's work
    code = main(["render", str(p), "-o", str(tmp_path / "out"), "--format", "svg"])
    seconds = time.thread_time() - t0
    out, err = capsys.readouterr()
    assert code == 2, err
    assert err.count("\n") == 1 and err.startswith(f"drafting: error: {printable(str(p))}: "), err
    assert key in err, err
    for w in words:
        assert w in err, err
    assert "Traceback" not in err and "Error:" not in err
    assert not (tmp_path / "out").exists() or not any((tmp_path / "out").iterdir())
    assert seconds < 1.0, f"refusal took {seconds:.2f} s of CPU (a hang guard: an unguarded reader takes minutes)"
    return err


# -- limits -----------------------------------------------------------------------------------------------

def test_file_size(tmp_path, capsys):
    refuse(tmp_path, capsys, EXAMPLE + "#" * limits.MAX_FILE_BYTES, "is larger than 256 KiB", "at most 256 KiB")


@pytest.mark.parametrize("extra", [
    "deep = " + "[" * 100_000 + "]" * 100_000,
    "deep = " + "{a = " * 30_000 + "1" + "}" * 30_000,
    ".".join(["a"] * 100_000) + " = 1",
    "[" + ".".join(["k"] * 100_000) + "]",
    "deep = " + "[" * 11 + "]" * 11,
])
def test_nesting_is_refused_before_the_toml_reader_recurses(tmp_path, capsys, extra):
    refuse(tmp_path, capsys, extra + "\n" + EXAMPLE, "line 1", "deeper than 10 levels")


def test_nesting_inside_a_real_key(tmp_path, capsys):
    refuse(tmp_path, capsys, EXAMPLE.replace("O1 = [0, 0]", "O1 = " + "[" * 500 + "]" * 500), "(O1)",
           "nest deeper than 10")


@pytest.mark.parametrize("section,make,what", [
    ("frame", lambda i: f"Q{i} = [{i}, 0]\n", "fixed pivots"),
    ("point", lambda i: f'\n[[point]]\nname = "P{i}"\nlink = 2\nfrom = "B"\ndistance = 5\n', "points"),
    ("link", lambda i: f'\n[[link]]\nnumber = {10 + i}\njoints = ["J{i}", "K{i}"]\nlength = 5\n', "links"),
    ("slider", lambda i: f'\n[[slider]]\nnumber = {10 + i}\njoint = "C"\nthrough = [0, 0]\n', "sliders"),
])
def test_counts(tmp_path, capsys, section, make, what):
    n = 10_000 if section == "frame" else 1000
    body = "".join(make(i) for i in range(n))
    text = EXAMPLE.replace("[frame]\n", "[frame]\n" + body) if section == "frame" else EXAMPLE + body
    if section != "frame":
        text = text.replace("\n[input]", "\n[input]")
    refuse(tmp_path, capsys, text, f": {section}: ", f"{n + (1 if section in ('frame', 'slider') else 2 if section == 'link' else 0):,} {what}",
           "at most 50")


def test_strings_and_keys(tmp_path, capsys):
    refuse(tmp_path, capsys, EXAMPLE.replace('title = "Slider-crank', 'title = "' + "x" * 5000), "drawing.title",
           "5,", "at most 200")
    line = EXAMPLE.split("O1 = [0, 0]")[0].count("\n") + 2
    refuse(tmp_path, capsys, EXAMPLE.replace("O1 = [0, 0]", "O1 = [0, 0]\n" + "Q" * 300 + " = [1, 1]"),
           f"line {line}: ", "a key of 300 characters; keys may have at most 200")
    refuse(tmp_path, capsys, EXAMPLE.replace("O1 = [0, 0]", "O1 = [0, 0]\n\"" + "Q" * 300 + "\" = [1, 1]"),
           'frame."QQQQ', "a key of 300 characters")


def test_a_number_too_long_for_python(tmp_path, capsys):
    refuse(tmp_path, capsys, EXAMPLE.replace("length = 94", "length = 1" + "0" * 5000), "line ",
           "a bare value of 5,001 characters")


@pytest.mark.parametrize("old,new,key,words", [
    ("length = 94", "length = 1" + "0" * 30, "link[2].length", "too large"),
    ("length = 94", "length = 1e300", "link[2].length", "a length may be at most 1e+09 mm"),
    ("length = 94", "length = 1e-9", "link[2].length", "at least 0.001 mm (write 0 for zero)"),
    ("O1 = [0, 0]", "O1 = [1e300, 0]", "frame.O1", "too large"),
    ("O1 = [0, 0]", "O1 = [1e8, 0]", "frame.O1", "1.000e+08 mm is too large beside 50 mm at link[1].length"),
    ("through = [0, 0]", "through = [0, 1e-5]", "slider[1].through", "at least 0.001 mm"),
    ("O1 = [0, 0]", 'O1 = ["0 m", "2e5 m"]', "frame.O1", "within a factor 1e6"),
    ('angle = "70 deg"', 'angle = "1e9 deg"', "input.angle", "too large"),
    ('tip_speed = "500 mm/s"', 'tip_speed = "1e20 m/s"', "input.tip_speed", "too large"),
    ('tip_speed = "500 mm/s"', "tip_speed = inf", "input.tip_speed", "too large"),
    ('tip_speed = "500 mm/s"', "tip_speed = nan", "input.tip_speed", "not a number"),
])
def test_magnitudes(tmp_path, capsys, old, new, key, words):
    assert old in EXAMPLE
    refuse(tmp_path, capsys, EXAMPLE.replace(old, new, 1), key, words)


def test_the_design_span_of_lengths_is_accepted():
    """Links from 1e-3 to 1e3 (the design's hard case) are a factor 1e6 apart: accepted."""
    s = parse_scene(EXAMPLE.replace("O1 = [0, 0]", "O1 = [0, 0]\nFAR = [1000, 0]")
                    .replace("through = [0, 0]", "through = [0, 0.001]"))
    assert s.mechanism.ground["FAR"].x == pytest.approx(1.0)


def test_the_length_named_is_the_odd_one_out():
    lengths = [("a", 0.05), ("b", 0.094), ("c", 0.06), ("zero", 0.0)]
    assert limits.length_ratio_problem(lengths) is None
    assert limits.length_ratio_problem(lengths + [("far", 1e5)]) == ("far", 1e5, "a", 0.05)
    assert limits.length_ratio_problem(lengths + [("tiny", 1e-8)]) == ("tiny", 1e-8, "b", 0.094)


def test_sweep_limit_is_reserved():
    assert limits.sweep_problem(10**7) is None
    assert "at most 10,000,000" in limits.sweep_problem(10**7 + 1)
    assert limits.sweep_problem(0)


# -- units: a number and a unit name, never an expression ---------------------------------------------------

@pytest.mark.parametrize("value,words", [
    ("9**9**9 mm", "arithmetic is not read"),
    ("2*3 mm", "arithmetic is not read"),
    ("2 * 3 mm", "arithmetic is not read"),
    ("10**10", "arithmetic is not read"),
    ("(5) mm", "cannot be read"),
    ("__import__('os') mm", "cannot be read"),
    ("50 percent", "not a value of length"),
    ("50 %", "not a value of length"),
    ("50 dimensionless", "not a value of length"),
    ("50 deg", "not a value of length"),
    ("60,5 mm", "decimal comma; use a decimal point"),
    ("60,5", "decimal comma; use a decimal point"),
    ("5 m^9", "a power must be a whole number"),
    ("5 furlongs per fortnight", "not a value of length"),
    ("5 blargs", "not a known unit name"),
])
def test_length_values_are_read_strictly(value, words):
    with pytest.raises(UnitError, match=None) as e:
        to_si(value, "length", "mm")
    assert words in str(e.value) and "\n" not in str(e.value)


def test_expression_is_refused_fast():
    """A hang guard, in CPU time (evaluating 9**9**9 would take minutes), not a speed assertion."""
    t0 = time.thread_time()
    for v in ("9**9**9 mm", "9**9**9**9", "1 mm**1000000", "10**10**10 mm"):
        with pytest.raises(UnitError):
            to_si(v, "length", "mm")
    assert time.thread_time() - t0 < 0.5


@pytest.mark.parametrize("value,kind,words", [
    ("500 percent", "velocity", "not a value of velocity"),
    ("0 dimensionless", "angle", "not a value of angle"),
    ("70 %", "angle", "not a value of angle"),
    ("10 Hz", "angular velocity", "not a value of angular velocity"),
    ("10 mm", "angle", "not a value of angle"),
    (10**400, "length", "too large to be a length"),
    ("1e400 mm", "length", "too large to be a length"),
    (True, "length", "not a number"),
])
def test_other_kinds_refuse_what_is_not_theirs(value, kind, words):
    with pytest.raises(UnitError) as e:
        to_si(value, kind, DEFAULT_UNITS[kind])
    assert words in str(e.value)


@pytest.mark.parametrize("value,kind,si", [
    ("50 mm", "length", 0.05), ("50mm", "length", 0.05), ("+3.5e1 mm", "length", 0.035), (".5 m", "length", 0.5),
    ("3.7 in", "length", 3.7 * 0.0254), ("500 mm/s", "velocity", 0.5), ("0.5 m per s", "velocity", 0.5),
    ("120 rpm", "angular velocity", 4 * math.pi), ("3 rev/s", "angular velocity", 6 * math.pi),
    ("70 deg", "angle", math.radians(70)), ("70\u00b0", "angle", math.radians(70)),
    ("100 grad", "angle", math.pi / 2), ("60 arcmin", "angle", math.radians(1)),
    ("2000 mm/s^2", "acceleration", 2.0), ("2 m s^-2", "acceleration", 2.0), ("2 m/s**2", "acceleration", 2.0),
    ("5 rad/s^2", "angular acceleration", 5.0), ("100 N", "force", 100.0), ("20 N m", "torque", 20.0),
    ("2.5 kg", "mass", 2.5), ("0.01 kg m^2", "moment of inertia", 0.01), ("50", "length", 0.05), (50, "length", 0.05),
])
def test_good_values(value, kind, si):
    assert to_si(value, kind, DEFAULT_UNITS[kind]) == pytest.approx(si, rel=1e-12)


def test_new_kinds_and_their_defaults():
    for kind in ("acceleration", "angular acceleration", "force", "torque", "mass", "moment of inertia"):
        assert kind in KINDS and check_unit(DEFAULT_UNITS[kind], kind) == DEFAULT_UNITS[kind]
    assert DEFAULT_UNITS["acceleration"] == "mm/s^2" and DEFAULT_UNITS["torque"] == "N m"
    assert from_si(2.0, "acceleration", "mm/s^2") == pytest.approx(2000.0)
    assert format_value(0.05, "length", "mm") == "50 mm"
    assert from_si(0.05, "length", "mm") == 50.0                  # the same rounding as pint's conversion
    with pytest.raises(UnitError):
        check_unit("percent", "length")
    with pytest.raises(UnitError):
        check_unit("Hz", "angular velocity")


def test_units_section_refuses_percent_and_expressions(tmp_path, capsys):
    refuse(tmp_path, capsys, EXAMPLE.replace('length = "mm"', 'length = "percent"'), "units.length",
           "not a unit of length")
    refuse(tmp_path, capsys, EXAMPLE.replace('angle = "deg"', 'angle = "dimensionless"'), "units.angle",
           "not a unit of angle")
    refuse(tmp_path, capsys, EXAMPLE.replace('length = "mm"', 'length = "mm**99"'), "units.length", "power")


# -- every error names the file and the key, in one line ------------------------------------------------

def test_two_sliders_on_one_joint(tmp_path, capsys):
    second = '\n[[slider]]\nnumber = 4\njoint = "C"\nthrough = [0, 10]\n'
    text = EXAMPLE.replace("[input]", second + "\n[input]")
    refuse(tmp_path, capsys, text, "slider[2].joint", "joint C already slides on a fixed guide; a second line "
                                                      "must be a slot in a moving link")


def test_a_point_defined_twice(tmp_path, capsys):
    pt = '\n[[point]]\nname = "D"\nlink = 2\nfrom = "B"\ndistance = 30\n'
    refuse(tmp_path, capsys, EXAMPLE.replace("[input]", pt + pt + "\n[input]"), "point[2].name", "defined twice")


def test_not_utf8_names_the_byte_and_line(tmp_path, capsys):
    line = EXAMPLE.split("Slider")[0].count("\n") + 1
    err = refuse(tmp_path, capsys, EXAMPLE.encode().replace(b"Slider", b"Sl\xffider", 1), "is not UTF-8 text",
                 f"byte 0xff on line {line})")
    assert "codec" not in err and "UnicodeDecodeError" not in err


def test_control_characters_escaped_and_long_values_cut(tmp_path, capsys):
    err = refuse(tmp_path, capsys, EXAMPLE.replace('paper = "A4"', 'paper = "\\u001b[31m' + "A" * 150 + '"'),
                 "drawing.paper", "\\x1b[31m", "\u2026")
    assert "\x1b" not in err and "A" * 70 not in err


def test_odd_file_name_in_messages_is_escaped(tmp_path, capsys):
    err = refuse(tmp_path, capsys, EXAMPLE.replace("length = 94", "length = -94"), "link[2].length", "positive",
                 name="bad\x1b[2J\nname.toml")
    assert "bad\\x1b[2J\\x0aname.toml" in err


def test_construction_errors_without_a_position_get_the_crank_angle(tmp_path, capsys):
    """An engine error raised without a position (e.g. two coincident circles) is told at the scene's
    crank angle: the file, the position, the reason -- one line."""
    from constructions.errors import DegenerateInput
    from drafting.app import cli
    from drafting.study.study import Study

    def broken(self, *a, **k):
        raise DegenerateInput("two coincident circles meet everywhere")

    p = tmp_path / "scene.toml"
    p.write_text(EXAMPLE)
    mp = pytest.MonkeyPatch()
    mp.setattr(Study, "run", broken, raising=False)
    try:
        code = cli.main(["solve", str(p)])
    finally:
        mp.undo()
    err = capsys.readouterr().err
    assert code == 2 and err == (f"drafting: error: {p}: at crank angle 70 deg: two coincident circles meet "
                                 f"everywhere\n")


def test_odd_titles_and_file_names_render_and_the_svg_parses(tmp_path, capsys):
    import xml.etree.ElementTree as ET
    import os
    title = "T\\u0007i\\u001bt\\uFFFEl\\uFFFFe <b>&amp;</b> \\u202Eevil"
    text = EXAMPLE.replace('title = "Slider-crank: velocity polygon (notes, velocity Example 1)"',
                           f'title = "{title}"').replace('number = "TOM-V-001"', 'number = "N\\u0000\\u0008o"')
    name = os.fsdecode(b"odd\xff name\x07.toml")
    p = tmp_path / name
    p.write_text(text)
    out = tmp_path / "out"
    code = main(["render", str(p), "-o", str(out), "--format", "svg"])
    captured = capsys.readouterr()
    assert code == 0, captured.err
    assert "\x07" not in captured.out and "\x1b" not in captured.out and "\\x07" in captured.out
    (svg,) = out.iterdir()
    assert svg.name == os.fsdecode(b"odd\xff name\x07.svg")
    root = ET.parse(svg).getroot()
    text = "".join(root.itertext())
    assert "T\ufffdi\ufffdt\ufffdl\ufffde <b>&amp;</b> \u202eevil" in text and "N\ufffd\ufffdo" in text


CHANGE_POINT = EXAMPLE.split("[frame]")[0] + """[frame]
O1 = [0, 0]
O2 = [0.03, 0]

[[link]]
number = 1
joints = ["O1", "B"]
length = 0.01

[[link]]
number = 2
joints = ["B", "C"]
length = 0.03

[[link]]
number = 3
joints = ["O2", "C"]
length = 0.01

[input]
link = 1
angle = "0 deg"
tip_speed = "300 mm/s"
sense = "ccw"

[assembly]
C = "left of B->O2"

[ask]
analyses = ["velocity"]
"""


def test_solve_render_and_check_give_one_exit_code(tmp_path, capsys):
    """A scene at a singular position (a 0.01/0.03/0.01 mm parallelogram at its change point) exits 3 from
    solve, render and check alike (render said 2), with the same one sentence; a friction coefficient far
    out of range (1e300: numpy's overflow warning and then 'singular') is refused by the reader, exit 2."""
    p = tmp_path / "change-point.toml"
    p.write_text(CHANGE_POINT)
    errs = []
    for cmd in (["solve", str(p)], ["render", str(p), "-o", str(tmp_path / "out")], ["check", str(p)]):
        assert main(cmd) == 3, cmd
        err = capsys.readouterr().err
        assert err.count("\n") == 1 and "change point" in err and "Traceback" not in err, err
        errs.append(err)
    assert len(set(errs)) == 1
    mu = builtin_example().read_text().replace('analyses = ["velocity"]', 'analyses = ["forces"]') + (
        '\n[[load]]\nname = "P"\nlink = 3\nat = "C"\nforce = "40 N"\nangle = "180 deg"\n'
        '\n[[friction]]\nslider = 3\nmu = 1e300\n')
    q = tmp_path / "mu.toml"
    q.write_text(mu)
    for cmd in (["solve", str(q)], ["render", str(q), "-o", str(tmp_path / "out")], ["check", str(q)]):
        assert main(cmd) == 2, cmd
        err = capsys.readouterr().err
        assert err.count("\n") == 1 and "friction[1].mu: 1e+300 must be a number from 0 to 10" in err, err


def test_a_numeric_warning_while_solving_is_the_engine_s_sentence(monkeypatch, capsys):
    """Whatever numpy would warn about while a study runs (an overflow, an invalid value) reaches the user as
    one sentence naming the scene file, exit 2 -- never numpy's two lines with its site-packages path."""
    import numpy as np

    from drafting.study.study import Study
    real_run = Study.run

    def overflowing(self):
        np.multiply(np.float64(1e300), np.float64(1e300))
        return real_run(self)
    monkeypatch.setattr(Study, "run", overflowing)
    with np.errstate(over="warn"):
        assert main(["solve", str(builtin_example())]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "overflow" in err and "site-packages" not in err, err
    assert str(builtin_example()) in err
