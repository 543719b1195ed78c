"""The sheet's font inside its SVG, so a sheet looks the same on a machine without DejaVu Sans.

An SVG names its font; a browser or editor without that font substitutes another, whose different widths
break the layout that was measured with DejaVu Sans (labels run into lines).  So every SVG carries the
glyphs it uses: a subset of the shipped DejaVu Sans (and its oblique, for italic symbols) as WOFF in an
``@font-face`` rule under the font's own family name, which a browser prefers to any installed font.

The subset is the engine's repertoire -- printable ASCII and the Greek letters and symbols its sheets
write -- shipped ready-made beside the fonts (``*-repertoire.woff``: subsetting costs ~0.3 s and
importing fontTools as much again, which a one-sheet render would pay every time; a test checks the
shipped files are what :func:`_subset` makes now, and ``python -m drafting.backends.fonts`` remakes them),
plus whatever else a sheet's text holds (a title in another script), made per such set and cached.  PDF and PNG are set by cairo from the same font through
fontconfig (drafting.backends.files), which ignores the rule.
"""

from __future__ import annotations

import base64
import io
import string
from functools import lru_cache
from pathlib import Path

from ..render.style import FONT_DIR, FONT_FAMILY, FONT_FILES
from ..scene.textsafe import xml_safe

FONTS = FONT_DIR
REPERTOIRE = frozenset(string.ascii_letters + string.digits + string.punctuation + " "
                       + "αβγδεζηθικλμνξπρστυφχψωΔΘΛΣΦΨΩ°×·−–—′″²³⊥∥✓✗→←↑↓≈≤≥±√∞…∠µ·")


def _subset(path: Path, chars: frozenset[str]) -> bytes:
    from fontTools import subset
    from fontTools.ttLib import TTFont
    opts = subset.Options()
    opts.flavor = "woff"
    opts.layout_features = ["kern"]
    opts.hinting = False
    opts.name_IDs = [0, 1, 2, 13, 14]          # copyright and licence travel with the glyphs
    opts.notdef_outline = True
    opts.drop_tables += ["FFTM"]                # FontForge's timestamps: nothing a renderer reads
    # the font's own date: same bytes every run; closed when saved (lazy, it holds its file open)
    with TTFont(str(path), lazy=True, recalcTimestamp=False) as font:
        s = subset.Subsetter(opts)
        s.populate(text="".join(sorted(chars)))
        s.subset(font)
        font.flavor = "woff"
        buf = io.BytesIO()
        font.save(buf)
    return buf.getvalue()


def shipped(name: str) -> Path:
    """Where the ready-made repertoire subset of the font file ``name`` is kept."""
    return FONTS / name.replace(".ttf", "-repertoire.woff")


def _repertoire_subset(name: str) -> bytes:
    path = shipped(name)
    return path.read_bytes() if path.exists() else _subset(FONTS / name, REPERTOIRE)


@lru_cache(maxsize=32)
def font_face_css(extra: frozenset[str] = frozenset()) -> str:
    """The @font-face rules (regular and italic) for the repertoire and ``extra`` characters."""
    chars = REPERTOIRE | extra
    rules = []
    for italic, name in FONT_FILES.items():
        woff = _repertoire_subset(name) if not extra else _subset(FONTS / name, chars)
        data = base64.b64encode(woff).decode("ascii")
        rules.append(f"@font-face{{font-family:\"{FONT_FAMILY}\";font-style:{'italic' if italic else 'normal'};"
                     f"src:url(data:font/woff;base64,{data}) format(\"woff\");}}")
    return "".join(rules)


def css_for(texts) -> str:
    """The rules for a sheet whose text is ``texts`` (strings), as the SVG writes them (xml_safe: control
    characters, surrogates and non-characters already replaced)."""
    used = frozenset(xml_safe("".join(texts)))
    return font_face_css(frozenset(c for c in used - REPERTOIRE if c.isprintable()))


def write_shipped() -> list[Path]:
    """Remake the shipped repertoire subsets (after REPERTOIRE or a font changes)."""
    out = []
    for name in FONT_FILES.values():
        path = shipped(name)
        path.write_bytes(_subset(FONTS / name, REPERTOIRE))
        out.append(path)
    return out


if __name__ == "__main__":
    for p in write_shipped():
        print(f"wrote {p}")
