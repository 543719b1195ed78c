"""The Python API (drafting.load / loads), notebook display (Study, Scene, Sheet, Construction), and the
gallery's notebook run as Jupyter would run it."""

from __future__ import annotations

import importlib.util
import json
import subprocess
import sys

import pytest

import drafting
from drafting.backends.files import ExportError
from drafting.scene.reader import SceneError, load_scene

from paths import GALLERY, ROOT
EXAMPLE = GALLERY / "notes-velocity-example-1.toml"
DICT = {"drawing": {"title": "Slider-crank", "number": "T-1"}, "frame": {"O1": [0, 0]},
        "link": [{"number": 1, "joints": ["O1", "B"], "length": 50},
                 {"number": 2, "joints": ["B", "C"], "length": 94}],
        "slider": [{"number": 3, "joint": "C", "through": [0, 0]}],
        "input": {"link": 1, "angle": "70 deg", "tip_speed": "500 mm/s", "sense": "ccw"},
        "assembly": {"C": "ahead of B"}}


def test_load_a_path_a_dict_text_or_a_scene_alike():
    a = drafting.load(EXAMPLE)
    b = drafting.load(str(EXAMPLE))
    c = drafting.load(DICT)
    d = drafting.loads(EXAMPLE.read_text())
    e = drafting.load(load_scene(EXAMPLE), paper="A3")
    v = a.results["V_C"].graphical
    for s in (b, c, d, e):
        assert s.results["V_C"].graphical == v and s.results["V_C"].agrees
    assert e.scene.paper == "A3" and "velocity" in a.ran and "acceleration" not in a.ran


def test_bad_input_is_one_sentence():
    with pytest.raises(SceneError) as err:
        drafting.load({**DICT, "input": {"link": 9, "angle": "70 deg", "omega": "1 rad/s"}})
    assert str(err.value).startswith("<dict>: input.link: ") and "\n" not in str(err.value)
    with pytest.raises(SceneError, match="no such scene file"):
        drafting.load(GALLERY / "missing.toml")
    with pytest.raises(TypeError, match="path, a dict or a Scene"):
        drafting.load(42)
    with pytest.raises(ValueError, match="paper"):
        drafting.load(EXAMPLE, paper="Letter")
    with pytest.raises(AttributeError):
        drafting.nothing_here


def test_sheets_save_by_suffix(tmp_path):
    sheet = drafting.load(EXAMPLE).sheets()[0]
    for suffix, magic in ((".svg", b"<svg"), (".pdf", b"%PDF"), (".png", b"\x89PNG")):
        path = sheet.save(tmp_path / f"x{suffix}")
        assert path == tmp_path / f"x{suffix}" and path.read_bytes().startswith(magic)
    with pytest.raises(ExportError, match="suffix"):
        sheet.save(tmp_path / "x.gif")


def test_everything_displays_itself():
    study = drafting.load(EXAMPLE)
    html = study._repr_html_()
    assert "<table>" in html and "V_C" in html and "568.5 mm/s" in html and "<svg" in html
    svg = study.sheets()[0]._repr_svg_()
    assert svg.startswith("<svg") and 'width="100%"' in svg and "viewBox" in svg
    assert "asks for velocity" in study.scene._repr_html_()
    assert "<ol><li>Draw the frame" in study.construction._repr_html_()


def test_import_drafting_stays_light():
    """The command line imports the package; the API comes only when asked for."""
    code = "import sys, drafting; print('drafting.api' in sys.modules, 'drafting.study.study' in sys.modules)"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT).stdout
    assert out.split() == ["False", "False"]


def _runner():
    spec = importlib.util.spec_from_file_location("run_notebook", GALLERY / "run_notebook.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def test_the_gallery_notebook_runs_and_shows_a_sheet_inline():
    path = GALLERY / "api-example.ipynb"
    ran = _runner().run(path)
    stored = json.loads(path.read_text())
    for nb in (ran, stored):                     # as run now, and as committed (what a reader sees)
        outs = [o for c in nb["cells"] if c["cell_type"] == "code" for o in c["outputs"]]
        text = json.dumps(outs)
        assert "V_C read off the polygon: 568.54 mm/s, analytic 568.54 mm/s, agrees: True" in text
        shown = [d for o in outs for k, d in o.get("data", {}).items() if k in ("text/html", "image/svg+xml")]
        assert sum("<svg" in "".join(d) for d in shown) >= 2 and "longer-rod.pdf True" in text


def test_results_as_csv_in_the_scenes_units(tmp_path, capsys):
    import csv
    from drafting.app.cli import main
    out = tmp_path / "r" / "results.csv"
    assert main(["solve", str(GALLERY / "notes-velocity-example-2.toml"), "--csv", str(out)]) == 0
    rows = list(csv.DictReader(out.open()))
    by = {r["quantity"]: r for r in rows}
    assert by["V_C"]["unit"] == "mm/s" and float(by["V_C"]["graphical"]) == pytest.approx(217.2, abs=0.05)
    assert by["omega_3"]["unit"] == "rad/s" and float(by["omega_3"]["graphical"]) > 0 and by["omega_3"]["graphical x"] == ""
    assert all(r["agrees"] == "yes" for r in rows)
    study = drafting.load(GALLERY / "notes-velocity-example-2.toml")
    assert len(rows) == len(study.comparisons)
    blocker = tmp_path / "file"
    blocker.write_text("x")
    assert main(["solve", str(GALLERY / "notes-velocity-example-2.toml"), "--csv", str(blocker / "r.csv")]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "--csv" in err and "Traceback" not in err


def test_the_lab_and_batch_functions_are_on_the_api():
    """The README's Python route to a scene's lab sheets and to a batch goes through drafting.api."""
    import drafting.api as api
    from drafting.app.batch import run_batch
    from drafting.app.lab import dimensioned, lab_for, write_lab
    assert (api.lab_for, api.write_lab, api.dimensioned, api.run_batch) == (lab_for, write_lab, dimensioned, run_batch)
    with pytest.raises(AttributeError, match="no attribute 'nothing'"):
        api.nothing
