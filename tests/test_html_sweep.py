"""The slider over the crank angle on the page of a swept scene (analyses = ["sweep"]): states computed in
Python and carried as JSON, equal to the analytic solution; the mechanism in a panel of its own beside the
cycle charts, whose cursors sit on the charts' own curves; gaps, change points and limit positions named;
checked in headless Chromium from a file path when Debian `chromium` is installed.  A page without a sweep
has no slider."""

from __future__ import annotations

import json
import math
import re
import shutil
import subprocess

import numpy as np
import pytest

import drafting
from constructions.check import analytic_solution
from constructions.sweep import sweep
from drafting.backends.html_page import page_html
from constructions.sweep import crank_points
from drafting.backends.html_sweep import sweep_section
from drafting.backends.sweep_canvas import HEIGHT, MECH_W, WIDTH
from drafting.render.paper import Polyline
from drafting.scene.reader import parse_scene
from test_sweep import PARALLELOGRAM            # the same parallelogram four-bar

from paths import GALLERY
CYCLE = GALLERY / "cycle-four-bar.toml"
CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")
GAP_TEXT = CYCLE.read_text().replace("length = 20\n", "length = 50\n", 1)      # the crank cannot turn fully


def page_data(page: str) -> dict:
    """The JSON the page carries, as the browser reads it."""
    m = re.search(r'<script type="application/json" id="sweep-data">(.*?)</script>', page, re.S)
    return json.loads(m.group(1).replace("<\\/", "</"))


@pytest.fixture(scope="module")
def cycle():
    study = drafting.load(CYCLE)
    page = page_html(study, study.sheets())
    return study, page, page_data(page)


@pytest.fixture(scope="module")
def gap(tmp_path_factory):
    from drafting.study.study import Study
    study = Study(parse_scene(GAP_TEXT, tmp_path_factory.mktemp("gap") / "gap.toml")).run()
    page = page_html(study, study.sheets())
    return study, page, page_data(page)


def test_the_states_are_the_analytic_sweep(cycle):
    """Every position the page carries is the scene's sweep (1 deg steps) in mm, equal to the closed-form
    solution at that crank angle to 1e-9 of the scene's size; the readout writes the analytic values."""
    study, page, d = cycle
    sc, u = study.scene, study.scene.units
    n = d["count"]
    assert n == 360 and len(d["ok"]) == n and all(d["ok"])
    th = sc.angle + 2 * math.pi * np.arange(n) / n
    s = sweep(sc.mechanism, th, sc.omega, sc.alpha)
    L = 60.0                                                          # mm, the frame: the scene's size
    for name, (x, y) in s.positions.items():
        got = np.array(d["pts"][name], dtype=float)
        assert np.abs(got[:, 0] - 1000 * x).max() < 1e-9 * L and np.abs(got[:, 1] - 1000 * y).max() < 1e-9 * L
    heads = re.findall(r'<span>(.*?) = <span class="v" id="sweep-v(\d+)">', page)
    col = {h: int(j) for h, j in heads}
    for i in range(0, n, 7):
        a = analytic_solution(sc.mechanism, float(th[i]), sc.omega, sc.alpha)
        for name, p in a.positions.items():
            q = d["pts"][name][i]
            assert math.hypot(q[0] - 1000 * p.x, q[1] - 1000 * p.y) < 1e-9 * L, (name, i)
        row = d["readout"][i]
        assert row[col["\u03b8<sub>2</sub>"]] == u.format("angle", float(th[i]) % (2 * math.pi))
        assert row[col["\u03c9<sub>3</sub>"]] == u.format("angular velocity", a.angular[3])
        assert row[col["\u03b1<sub>4</sub>"]] == u.format("angular acceleration", a.angular_acceleration[4])
        b, c, o4 = a.positions["B"], a.positions["C"], a.positions["O4"]
        mu = abs(math.atan2((b - c).cross(o4 - c), (b - c).dot(o4 - c)))     # between coupler and rocker at C
        assert row[col["\u03bc"]].split(" (")[0] == u.format("angle", mu)
        assert ("outside 40-140 deg" in row[col["\u03bc"]]) == (not math.radians(40) <= mu <= math.radians(140))
        assert d["angle"][i].endswith(u.format("angle", float(th[i]) % (2 * math.pi)))


def test_the_mechanism_has_its_own_panel_and_the_cursors_sit_on_the_curves(cycle):
    study, page, d = cycle
    sec = sweep_section(study)
    assert sec.data["pts"] == d["pts"]
    assert d["scale"] == "1:1" and d["k"] == pytest.approx(1.0)           # paper mm per mm, ISO 5455
    xs = [d["ox"] + d["k"] * p[0] for v in d["pts"].values() for p in v]
    ys = [d["oy"] - d["k"] * p[1] for v in d["pts"].values() for p in v]
    assert 5 < min(xs) and max(xs) < MECH_W - 5 and 10 < min(ys) and max(ys) < HEIGHT - 5
    chart_xs = [x for c in sec.commands if c.name.startswith("chart ") for x in
                ([c.x1, c.x2] if hasattr(c, "x1") else [p[0] for p in getattr(c, "points", ())])]
    assert chart_xs and min(chart_xs) > MECH_W and max(chart_xs) <= WIDTH    # the charts stay right of it
    # the cursor and its dots at every angle stand on the vertices draw_chart drew for those angles (a
    # chart runs over the turn from 0 deg, the slider from the drawn pose)
    curves = {c.name: c for c in sec.commands if isinstance(c, Polyline)}
    for ci, name in enumerate(["chart rocker angle", "chart omega", "chart alpha", "chart transmission"]):
        cur = d["charts"][ci]
        for si, dot in enumerate(cur["dots"]):
            pts = curves[f"{name}:series {si + 1} run 1"].points
            assert len(pts) == 361 and all(b[0] > a[0] for a, b in zip(pts, pts[1:]))    # 0 to 360 deg
            for i in range(d["count"]):
                j = min(range(len(pts)), key=lambda j: abs(pts[j][0] - cur["x"][i]))
                assert abs(cur["x"][i] - pts[j][0]) < 2e-3 and abs(dot["y"][i] - pts[j][1]) < 2e-3
    # the controls, the named positions and nothing fetched from anywhere
    assert 'type="range" id="sweep-slider" min="0" max="359"' in page and 'id="sweep-play"' in page
    assert "C&#x27; at 36.87\u00b0" in page and "\u03bc least at 0\u00b0" in page
    i = next(j for j, t in enumerate(d["status"]) if t.startswith("Limit position C'' "))
    assert "crank and coupler in line (folded); the rocker stops and turns back." in d["status"][i]
    assert not re.search(r"<(link|img|iframe)\b|\bsrc=|url\((?!data:)", page)


def test_at_a_gap_only_the_crank_stands(gap):
    """Where the linkage cannot be assembled the page carries no position of the links after the crank
    (nothing borrowed from a neighbouring angle): the crank alone, turned to the crank angle, and a note."""
    study, _, d = gap
    m = study.scene.mechanism
    bad = [i for i, ok in enumerate(d["ok"]) if not ok]
    assert 0 < len(bad) < d["count"]
    for i in bad:
        th = study.scene.angle + 2 * math.pi * i / d["count"]
        assert d["pts"]["C"][i] is None and d["pts"]["D"][i] is None
        bx, by = d["pts"]["B"][i]
        assert math.hypot(bx - 50 * math.cos(th), by - 50 * math.sin(th)) < 1e-9
        assert "cannot be assembled at this crank angle" in d["status"][i]
        assert all(v == "\u2014" for v in d["readout"][i][1:])
    good = next(i for i, ok in enumerate(d["ok"]) if ok)
    cp = crank_points(m, study.scene.angle + 2 * math.pi * good / d["count"])
    assert math.hypot(d["pts"]["B"][good][0] - 1000 * cp["B"].x, d["pts"]["B"][good][1] - 1000 * cp["B"].y) < 1e-9


def test_change_points_are_named(tmp_path):
    from drafting.study.study import Study
    study = Study(parse_scene(PARALLELOGRAM, tmp_path / "p.toml")).run()
    page = page_html(study, study.sheets())
    d = page_data(page)
    assert "change point at 180\u00b0" in page and "change point at 0\u00b0" in page
    i = round((180 - 30) / 360 * d["count"])
    assert "Change point at 180\u00b0: all the links lie in line" in d["status"][i]
    assert f'<option value="{i}">' in page
    assert not any("turns back" in t for t in d["status"])        # on its branch the rocker turns on


def test_a_page_without_a_sweep_has_no_slider():
    study = drafting.load(GALLERY / "notes-acceleration-example-1.toml")
    page = page_html(study, study.sheets())
    assert sweep_section(study) is None
    assert "sweep" not in page and page.count("<script") == 2


def _chromium(url: str, *args: str) -> subprocess.Popen:
    return subprocess.Popen([CHROMIUM, "--headless=new", "--no-sandbox", "--disable-gpu", *args, url],
                            stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)


@pytest.mark.skipif(CHROMIUM is None, reason="headless Chromium (Debian chromium) is not installed")
def test_in_headless_chromium_the_slider_moves_the_mechanism(tmp_path, cycle, gap):
    """The self-test moves the slider a quarter turn through its input event: every pin then stands where
    the analytic solution puts it (paper mm, to 1e-3), the readout changed, an arrow key on the slider left
    the construction's steps alone, play and pause work, and at a gap only the crank is drawn.  The
    screenshot is of the same run: the mechanism at 190 deg beside the charts."""
    study, page, d = cycle
    (tmp_path / "cycle.html").write_text(page, encoding="utf-8")
    (tmp_path / "gap.html").write_text(gap[1], encoding="utf-8")
    shot = tmp_path / "shot.png"
    runs = [_chromium(f"{(tmp_path / 'cycle.html').as_uri()}#selftest-sweep&angle=100", "--dump-dom", f"--screenshot={shot}",
                      "--window-size=1600,1000"),
            _chromium(f"{(tmp_path / 'gap.html').as_uri()}#selftest-sweep", "--dump-dom")]
    out = [r.communicate(timeout=120)[0] for r in runs]
    title = re.search(r"<title>([^<]*)</title>", out[0]).group(1)
    assert title.startswith("selftest-sweep ok i=130 gaps=none"), title          # from 100 deg a quarter on
    sc = study.scene
    a = analytic_solution(sc.mechanism, sc.angle + math.radians(130), sc.omega)
    for name in ("B", "C", "D"):
        x, y = map(float, re.search(rf" {name}=([-0-9.]+),([-0-9.]+)", title).groups())
        p = a.positions[name]
        assert abs(x - (d["ox"] + d["k"] * 1000 * p.x)) < 1e-3 and abs(y - (d["oy"] - d["k"] * 1000 * p.y)) < 1e-3
    assert title.endswith("readout=190\u00b0")
    gap_title = re.search(r"<title>([^<]*)</title>", out[1]).group(1)
    assert gap_title.startswith("selftest-sweep ok") and " gaps=ok:O2B " in gap_title, gap_title
    assert shot.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" and shot.stat().st_size > 50_000


def test_a_slotted_lever_charts_its_slider_travel():
    """The quick-return's first block rides in the slotted lever; the output is the block on the fixed
    guide, and the cycle charts its travel (the position of Q along the guide) for the slider's cursor."""
    from constructions.mechanisms.cycle import cycle_record, one_turn
    from drafting.scene.reader import load_scene
    sc = load_scene(GALLERY / "quick-return-slotted-lever.toml")
    th = sc.angle + 2 * math.pi * np.arange(37) / 36
    s = sweep(sc.mechanism, th, sc.omega, sc.alpha)
    rec = cycle_record(sc.mechanism, s, None, str)
    (chart,) = [e for e in rec.entities() if getattr(e, "name", "") == "chart slider travel"]
    guide = next(sl for sl in sc.mechanism.slides if sl.number == 5)
    assert chart.series[0].label == "block 5 at Q" and guide.on is None and guide.angle == 0
    order, xs = one_turn(tuple(th))                  # the chart runs over the turn from 0 deg
    assert chart.series[0].x == xs and xs[0] == 0.0 and xs[-1] == 2 * math.pi
    assert np.allclose(chart.series[0].y, (np.asarray(s.positions["Q"][0]) - guide.through.x)[order], rtol=0,
                       atol=1e-12)
