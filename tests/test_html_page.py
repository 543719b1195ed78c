"""The step-through HTML page: self-contained, every drawn element tagged with its entity, steps that walk
forward and back -- checked in headless Chromium when it is installed (Debian `chromium`)."""

from __future__ import annotations

import re
import shutil
import subprocess

import pytest

import drafting
from drafting.app.cli import main
from drafting.backends.html_markup import markup_html
from drafting.backends.html_page import entity_of, page_html
from drafting.layout.parts import Ids, part_of

from paths import GALLERY
SCENE = GALLERY / "notes-acceleration-example-1.toml"
CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")


def test_the_page_is_self_contained_and_tagged():
    study = drafting.load(SCENE)
    page = page_html(study, study.sheets())
    assert page.startswith("<!DOCTYPE html>") and page.count("<svg") == len(study.sheets())
    assert not re.search(r"<(link|img|iframe)\b|\bsrc=|url\((?!data:)", page)  # nothing fetched
    assert not re.search(r'href="(?!#)', page)
    tagged = set(re.findall(r'data-entity="([^"]+)"', page))
    ids = Ids(study.sheets()[0].entities)
    drawn = {ids(e.name) for st in study.construction.steps for e in st.entities}
    assert {"link-1", "link-2", "pole-O_a", "results", "step-1", "title-block"} <= tagged
    furniture = {ids(p.owner) for sh in study.sheets() for c in sh.commands
                 if (p := part_of(c.name, sh.entities)).owner not in sh.entities}
    assert tagged <= drawn | furniture
    # the page uses the SVG files' ids: each written once over its sheets
    page_ids = re.findall(r'<g [^>]*\bid="([^"]+)"', page)
    file_ids = {i for sh in study.sheets() for i in re.findall(r'<g [^>]*\bid="([^"]+)"', sh.svg())}
    assert len(page_ids) == len(set(page_ids)) and set(page_ids) == file_ids
    assert len(re.findall(r"<li>", page)) == len(study.construction.steps)


def test_entity_names_and_markup():
    names = {"guide C", "link 1", "link 10"}
    assert entity_of("guide C:rail:hatch", names) == "guide C"
    assert entity_of("link 1", names) == "link 1" and entity_of("link 10", names) == "link 10"
    assert entity_of("link 100", names) is None and entity_of("frame", names) is None
    assert markup_html("A_CB^t = α_2 · BC <x>") == "A<sub>CB</sub><sup>t</sup> = α<sub>2</sub> · BC &lt;x&gt;"


def test_render_writes_the_page_beside_the_sheets(tmp_path, capsys):
    assert main(["render", str(SCENE), "-o", str(tmp_path), "--format", "svg,html"]) == 0
    assert (tmp_path / "notes-acceleration-example-1.html").stat().st_size > 10_000
    assert (tmp_path / "notes-acceleration-example-1-1.svg").exists()
    with pytest.raises(SystemExit):
        main(["render", str(SCENE), "-o", str(tmp_path), "--format", "gif"])
    assert "choose from svg,pdf,png,html" in capsys.readouterr().err


def _chromium(url: str, *args: str) -> str:
    r = subprocess.run([CHROMIUM, "--headless=new", "--no-sandbox", "--disable-gpu", *args, url],
                       capture_output=True, text=True, timeout=120)
    return r.stdout


@pytest.mark.skipif(CHROMIUM is None, reason="headless Chromium (Debian chromium) is not installed")
def test_in_headless_chromium_it_steps_forward_and_back(tmp_path):
    assert main(["render", str(SCENE), "-o", str(tmp_path), "--format", "html"]) == 0
    page = tmp_path / "notes-acceleration-example-1.html"
    dom = _chromium(f"{page.as_uri()}#step=15&selftest", "--dump-dom")
    title = re.search(r"<title>([^<]*)</title>", dom).group(1)
    assert title.startswith("selftest ok step=16")                           # 15 -> 17 -> 16 (the space diagram numbers its links in a step)
    lit = int(re.search(r"lit=(\d+)", title).group(1))
    hidden = int(re.search(r"hidden=(\d+)", title).group(1))
    assert lit > 0 and hidden > 0                                            # step 16 lit, 17-18 hidden
    dom = _chromium(f"{page.as_uri()}#step=16", "--dump-dom")
    current = re.findall(r'<li class="current"[^>]*>(.*?)</li>', dom)
    assert len(current) == 1 and current[0].startswith("From b\u2032 draw A<sub>CB</sub><sup>n</sup>")
    shot = tmp_path / "shot.png"
    _chromium(f"{page.as_uri()}#step=16", f"--screenshot={shot}", "--window-size=1600,1000")
    assert shot.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" and shot.stat().st_size > 50_000


#: What a sheet draws for itself, not for a construction entity: always shown on the page.
FURNITURE = ("heading ", "note ", "results ", "scale bar ", "title", "step ", "equation", "separator", "frame")


@pytest.mark.parametrize("name", ["gear-rack-interference", "notes-acceleration-example-1", "four-bar-dalembert",
                                  "instant-centres-six-bar", "notes-roller-cam", "quick-return-slotted-lever",
                                  "gear-train-three-gears"])
def test_every_drawn_command_shows_and_hides_with_its_entity(name):
    """Every command the diagrams draw belongs to the entity it draws, so the page shows it with that
    entity's step and hides it before: a dimension's arrowheads (they were left on the page, floating,
    before their step), the pin at a joint (with the first link that meets it)."""
    from drafting.scene.reader import load_scene
    from drafting.study.study import Study
    from drafting.study.worked import sheets_for
    study = Study(load_scene(GALLERY / f"{name}.toml")).run()
    names = {e.name for st in study.construction.steps for e in st.entities}
    loose = sorted({c.name for sh in sheets_for(study) for c in sh.commands
                    if entity_of(c.name, names) is None and not c.name.startswith(FURNITURE)})
    assert loose == []


#: Appended to a copy of the page: after the page's own script ran (step 1), the text a reader sees --
#: every visible text node, the sheets' SVG text included -- then the same at the last step.
PROBE = """<script>
(function () {
  function seen() {
    const out = [];
    for (const el of document.querySelectorAll('#panel, #panel *, #sheets text')) {
      if (!el.checkVisibility({visibilityProperty: true, opacityProperty: true})) continue;
      if (el.tagName === 'text') { out.push(el.textContent); continue; }
      for (const n of el.childNodes) if (n.nodeType === 3) out.push(n.data);
    }
    return out.join('\\n');
  }
  const first = seen();
  const lit = document.querySelector('#sheets g.current line');
  const colour = lit ? getComputedStyle(lit).stroke : '';
  const sheet = document.querySelector('#sheets .sheet'), pane = document.getElementById('sheets');
  const width = () => Math.round(sheet.getBoundingClientRect().width);
  const widths = [pane.clientWidth, width()];
  document.getElementById('zoom-in').click();
  widths.push(width());
  document.dispatchEvent(new KeyboardEvent('keydown', {key: '0'}));
  widths.push(width());
  for (let i = 0; i < 200; i++) document.getElementById('next').click();
  const pre = document.createElement('pre');
  pre.id = 'probe';
  pre.textContent = JSON.stringify({first: first, last: seen(), count: document.getElementById('count').textContent,
                                    colour: colour, widths: widths});
  document.body.appendChild(pre);
})();
</script>"""


@pytest.mark.skipif(CHROMIUM is None, reason="headless Chromium (Debian chromium) is not installed")
def test_in_headless_chromium_no_value_shows_before_its_step(tmp_path):
    """At step 1 none of the results (the Results table's values) and none of the values later steps
    measure is anywhere on the page, in the list of steps or on the sheet; at the last step all are.
    Step 1's entities are drawn in colour; the sheet fits the pane's width and zooms (button, key 0)."""
    import html
    import json
    from drafting.layout.formats import SheetFormatter
    from drafting.layout.sections import step_text
    scene = GALLERY / "notes-velocity-example-1.toml"
    assert main(["render", str(scene), "-o", str(tmp_path), "--format", "html"]) == 0
    page = tmp_path / "notes-velocity-example-1.html"
    probed = tmp_path / "probed.html"
    probed.write_text(page.read_text(encoding="utf-8").replace("</body>", PROBE + "</body>"), encoding="utf-8")
    dom = _chromium(probed.as_uri(), "--dump-dom")
    seen = json.loads(html.unescape(re.search(r'<pre id="probe">(.*?)</pre>', dom, re.S).group(1)))
    study = drafting.load(scene)
    results = {v for row in study.table().text for v in row[1:3]}                  # graphical and analytic columns
    fmt = SheetFormatter(study.scene.units, {k: v for sh in study.sheets() for k, v in sh.diagram_scales.items()})
    later = {m for st in study.construction.steps[1:] if any(v.kind not in ("scale", "paper length")
                                                             for _, v in st.values)
             for m in re.findall(r"\d+(?:\.\d+)? (?:mm/s|rad/s)|\d+(?:\.\d+)?\u00b0", step_text(st, fmt))}
    assert len(results) == 4 and {"568.5 mm/s at 180.0\u00b0", "2.1 rad/s CW"} <= results
    assert {"70\u00b0", "500 mm/s", "197.4 mm/s", "568.5 mm/s", "2.1 rad/s"} <= later
    assert "Draw the frame" in seen["first"] and "Space diagram" in seen["first"]     # what step 1 shows
    assert [v for v in sorted(results | later) if v in seen["first"]] == []
    assert seen["count"] == f"{len(study.construction.steps)} / {len(study.construction.steps)}"
    assert [v for v in sorted(results | later) if v not in seen["last"]] == []
    assert seen["colour"] == "rgb(221, 0, 0)"                             # step 1's lines in colour
    pane, fit, zoomed, back = seen["widths"]                                  # fits the width; zooms; 0 fits again
    assert fit <= pane and zoomed == pytest.approx(1.25 * fit, abs=2) and back == fit
