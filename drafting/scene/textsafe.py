"""Text that came from a user, made safe for where it goes: XML, a terminal, a one-line message.

Scene files and file names are untrusted.  Three places receive their text:

- an SVG (titles, drawing numbers, names, labels): :func:`xml_safe` replaces every character XML 1.0
  forbids -- C0 controls other than tab, newline and carriage return, U+FFFE/U+FFFF and unpaired
  surrogates -- by U+FFFD, so the document stays well-formed and the damage stays visible;
- a terminal or a log: :func:`printable` writes control characters (C0, DEL, C1), line and paragraph
  separators and unpaired surrogates as Python escapes (``\\x1b``, ``\\udcff``), so a title cannot move
  the cursor, recolour the terminal or split a message over lines;
- an error message: :func:`one_line` does the same and cuts quoted values longer than
  :data:`QUOTE_LIMIT` characters with an ellipsis, so a 700,000-character value is not echoed back.
"""

from __future__ import annotations

import contextlib
import re
import sys
from collections.abc import Iterator

REPLACEMENT = "\ufffd"
QUOTE_LIMIT = 60
"""Quoted values in messages are cut to this many characters (plus an ellipsis)."""
MESSAGE_LIMIT = 1000
"""A message longer than this is cut (whatever survives the quote cutting)."""

# The patterns are kept as text and compiled on first use (``re``'s own cache): compiling their classes of
# surrogates at import cost every start a few ms, and most texts never need them -- every character
# they match is one ``str.isprintable`` refuses (a control, separator, format character, surrogate or
# non-character), so a printable text is passed as it is.
# XML 1.0: Char ::= #x9 | #xA | #xD | [#x20-#xD7FF] | [#xE000-#xFFFD] | [#x10000-#x10FFFF]
_XML_FORBIDDEN = "[\x00-\x08\x0b\x0c\x0e-\x1f\ud800-\udfff\ufffe\uffff]"
# what a terminal must not receive raw: C0 (also tab/newline in a one-line text), DEL, C1,
# the Unicode line/paragraph separators, bidi overrides and unpaired surrogates
_UNPRINTABLE = "[\x00-\x1f\x7f-\x9f\u2028\u2029\u202a-\u202e\u2066-\u2069\ud800-\udfff]"
_UNPRINTABLE_KEEP_LINES = "[\x00-\x08\x0b-\x1f\x7f-\x9f\u2028\u2029\u202a-\u202e\u2066-\u2069\ud800-\udfff]"
_QUOTED = re.compile(r"'(?:[^'\\]|\\.)*'|\"(?:[^\"\\]|\\.)*\"")


def xml_safe(text: str) -> str:
    """``text`` with every character XML 1.0 forbids replaced by U+FFFD (visible, never dropped)."""
    return text if text.isprintable() else re.sub(_XML_FORBIDDEN, REPLACEMENT, text)


def _escape(m: re.Match) -> str:
    c = m.group(0)
    n = ord(c)
    return f"\\x{n:02x}" if n < 0x100 else f"\\u{n:04x}"


def printable(text: str, *, keep_lines: bool = False) -> str:
    """``text`` with control characters and unpaired surrogates escaped (``\\x1b``, ``\\udcff``).

    With ``keep_lines`` newlines and tabs pass (for multi-line output such as a results table)."""
    if text.isprintable() or (keep_lines and text.replace("\n", "").replace("\t", "").isprintable()):
        return text
    return re.sub(_UNPRINTABLE_KEEP_LINES if keep_lines else _UNPRINTABLE, _escape, text)


def cut(text: str, limit: int = QUOTE_LIMIT) -> str:
    """``text`` cut to ``limit`` characters with an ellipsis when longer."""
    return text if len(text) <= limit else text[:limit] + "\u2026"


def cut_middle(text: str, limit: int) -> str:
    """``text`` cut in the middle to ``limit`` characters (a long path keeps its start and its file name)."""
    if len(text) <= limit:
        return text
    head = limit // 3
    return text[:head] + "\u2026" + text[-(limit - head - 1):]


PATH_LIMIT = 120
"""A file name in a message is cut in the middle to this many characters."""


def shown_path(path: object, limit: int = PATH_LIMIT) -> str:
    """A file name for a message: escaped and cut in the middle (its start and its file name kept), so a
    200-character name cannot push the message past a line, nor its reason off the screen."""
    return cut_middle(printable(str(path)), limit)


def quote(value: object, limit: int = QUOTE_LIMIT) -> str:
    """A value quoted for a message: its repr, cut at ``limit`` characters, escaped, one line."""
    r = repr(value)
    if len(r) > limit + 2:
        r = r[:limit + 1] + "\u2026" + r[-1] if r[-1] in "'\"" else r[:limit] + "\u2026"
    return printable(r)


def _cut_quoted(m: re.Match) -> str:
    q = m.group(0)
    if len(q) <= QUOTE_LIMIT + 2:
        return q
    return q[:QUOTE_LIMIT + 1] + "\u2026" + q[-1]


def one_line(message: str, *, cut_quotes: bool = True) -> str:
    """A message fit for one line of stderr: escaped, quoted values cut (unless ``cut_quotes`` is
    false: for a message composed of parts already cut, where a quote in a file name would mislead the
    cutting), the whole bounded to :data:`MESSAGE_LIMIT` characters (cut in the middle)."""
    text = printable(message)
    if cut_quotes:
        text = _QUOTED.sub(_cut_quoted, text)
    return cut_middle(text, MESSAGE_LIMIT)


class _SafeWriter:
    """A text stream that escapes control characters (keeping newlines and tabs) and writes what its
    encoding cannot hold as backslash escapes, instead of failing."""

    def __init__(self, inner) -> None:
        self._inner = inner

    def write(self, text: str) -> int:
        safe = printable(text, keep_lines=True)
        try:
            self._inner.write(safe)
        except UnicodeEncodeError:
            enc = getattr(self._inner, "encoding", None) or "ascii"
            self._inner.write(safe.encode(enc, "backslashreplace").decode(enc, "replace"))
        return len(text)

    @property
    def unescaped(self):
        """The stream underneath, for our own control characters (a progress bar's carriage return)."""
        return self._inner

    def __getattr__(self, name):
        return getattr(self._inner, name)


@contextlib.contextmanager
def safe_streams() -> Iterator[None]:
    """Within the block, sys.stdout and sys.stderr escape control characters (see :func:`printable`)."""
    out, err = sys.stdout, sys.stderr
    sys.stdout, sys.stderr = _SafeWriter(out), _SafeWriter(err)
    try:
        yield
    finally:
        if isinstance(sys.stdout, _SafeWriter):
            sys.stdout = out
        if isinstance(sys.stderr, _SafeWriter):
            sys.stderr = err
