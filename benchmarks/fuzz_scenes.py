"""Hostile scenes: mutate the gallery scenes the way an attacker or a careless user would and run the
``drafting`` command on each, in-process, counting what goes wrong.

    python benchmarks/fuzz_scenes.py [-n 1000] [--seed 1] [--formats svg] [--show 3]

Mutations (each case applies one to three): deep nesting (arrays, inline tables, dotted keys, table
headers), huge counts (pivots, links, sliders, points), huge integers, odd unicode and control
characters in every string or in the title and drawing number, arithmetic in unit strings, percent and
dimensionless units, decimal commas, duplicate sliders and point names, giant and tiny coordinates and
lengths, long strings, odd file names (spaces, newlines, escapes, bidi overrides, undecodable bytes,
long names) and invalid UTF-8.

For every run: exit code 0, 1, 2 or 3 (3 = singular position); no traceback and no exception out of
``main``; on failure exactly one stderr line ``drafting: error: <file>: <key or line or position>: ...``;
a refusal where the mutation makes the scene wrong (else "bad value accepted"); no file in the output
folder but the scene's own outputs (no temporary file, nothing on failure); every SVG written parses
as XML and carries no script, link or entity; at most 5 s per scene (else "hang").

The test suite runs the same cases through hypothesis with a fixed seed and a small budget
(tests/test_hostile_fuzz.py); this script runs them at full size and prints the counts.
"""

from __future__ import annotations

import argparse
import contextlib
import io
import os
import random
import re
import resource
import signal
import sys
import tempfile
import time
import xml.etree.ElementTree as ET
from collections import Counter
from dataclasses import dataclass
from pathlib import Path

HERE = Path(__file__).resolve().parent
if str(HERE) not in sys.path:                   # loaded by its path (the tests): its sibling modules too
    sys.path.insert(0, str(HERE))

from fuzz_mutations import Case, gallery, make_case  # noqa: E402

ROOT = HERE.parent
HANG_SECONDS = 5.0
KILL_SECONDS = 60.0

PROBLEMS = ("traceback", "hang", "invalid svg", "bad value accepted", "error without key", "not one line",
            "stray file", "bad exit code")


# -- running ---------------------------------------------------------------------------------------------

@dataclass
class Result:
    case: Case
    code: int | None
    stdout: str
    stderr: str
    seconds: float
    problems: list[str]
    written: list[str]


class _Hang(BaseException):
    pass


_KEYED = re.compile(
    r"(?:[A-Za-z_][\w\-]*(?:\[\d+\])*(?:\.[^:]+)?"              # link[2].length, frame.O1, input, frame.a b
    r"|line \d+(?: \([^)]*\))?"                                   # line 3 (a.b)
    r"|at [^:]+"                                                  # at crank angle 70 deg
    r"): \S")
_FILE_LEVEL = re.compile(r"(?:is not valid TOML \(.*line \d+|is larger than \d+ KiB|is not UTF-8 text \(byte "
                         r"0x[0-9a-f]{2} on line \d+\)|no such scene file|is a folder|is not a regular file|"
                         r"Cannot write |Cannot create the output folder )")


def classify_error(line: str, shown_paths: list[str]) -> str | None:
    """None if ``line`` is one well-formed error naming the file (as one of ``shown_paths``) and a key,
    a line or a position."""
    prefix = "drafting: error: "
    if not line.startswith(prefix):
        return "not one line"
    rest = line[len(prefix):]
    for shown in shown_paths:
        if rest.startswith(shown + ": "):
            after = rest[len(shown) + 2:]
            if _KEYED.match(after) or _FILE_LEVEL.match(after):
                return None
    return "error without key"


def _shown(path: Path) -> list[str]:
    """How a message may show the scene's path: escaped, and cut in the middle when long."""
    from drafting.scene.textsafe import cut_middle, printable
    return [printable(str(path)), cut_middle(printable(str(path)), 120)]


FONT_FACES = re.compile(r'(@font-face\{font-family:"DejaVu Sans";font-style:(normal|italic);'
                        r'src:url\(data:font/woff;base64,[A-Za-z0-9+/=]+\) format\("woff"\);\})+')
"""The one <style> a sheet may hold: its font (drafting.backends.fonts), nothing that fetches or runs."""


def check_svg(path: Path) -> str | None:
    """None if the file is well-formed, inert SVG; else why not."""
    data = path.read_bytes()
    try:
        root = ET.fromstring(data)
    except ET.ParseError as e:
        return f"not well-formed: {e}"
    if b"<!DOCTYPE" in data or b"<!ENTITY" in data:
        return "has a DOCTYPE or entity"
    for el in root.iter():
        tag = el.tag.rsplit("}", 1)[-1]
        if tag == "style" and FONT_FACES.fullmatch(el.text or ""):
            continue                           # the embedded font: @font-face rules with data URLs only
        if tag in ("script", "foreignObject", "a", "image", "use", "iframe", "style"):
            return f"has <{tag}>"
        for k, v in el.attrib.items():
            if k.rsplit("}", 1)[-1] in ("href",) or k.startswith("on") or "url(" in v:
                return f"has active attribute {k}"
    return None


def run_case(case: Case, workdir: Path, formats: str = "svg", hang_seconds: float = HANG_SECONDS) -> Result:
    from drafting.app.cli import main
    scene_dir = workdir / "in"
    out = workdir / "out"
    scene_dir.mkdir(parents=True, exist_ok=True)
    path = scene_dir / case.filename
    src = case.source()
    try:
        with open(path, "wb") as fh:
            fh.write(src.encode("utf-8") if isinstance(src, str) else src)
    except OSError as e:                       # the file system refuses the name itself: not our bug
        return Result(case, None, "", f"(cannot create {case.filename!r}: {e.strerror})", 0.0, [], [])
    stdout, stderr = io.StringIO(), io.StringIO()
    problems: list[str] = []
    code = None

    def on_alarm(signum, frame):
        raise _Hang()

    use_alarm = hasattr(signal, "setitimer") and sys.platform != "win32"
    if use_alarm:
        old = signal.signal(signal.SIGALRM, on_alarm)
        signal.setitimer(signal.ITIMER_REAL, KILL_SECONDS)
    t0 = time.perf_counter()
    try:
        with contextlib.redirect_stdout(stdout), contextlib.redirect_stderr(stderr):
            code = main(["render", str(path), "-o", str(out), "--format", formats])
    except _Hang:
        problems.append("hang")
    except SystemExit as e:
        code = e.code if isinstance(e.code, int) else 2
        problems.append("bad exit code")
    except BaseException as e:                 # noqa: BLE001 -- the fuzzer's whole point
        problems.append("traceback")
        stderr.write(f"\n[escaped: {e.__class__.__name__}: {str(e)[:300]}]")
    finally:
        if use_alarm:
            signal.setitimer(signal.ITIMER_REAL, 0)
            signal.signal(signal.SIGALRM, old)
    seconds = time.perf_counter() - t0
    err = stderr.getvalue()
    if seconds > hang_seconds and "hang" not in problems:
        problems.append("hang")
    if "Traceback" in err and "traceback" not in problems:
        problems.append("traceback")
    if code not in (0, 1, 2, 3) and "traceback" not in problems and "hang" not in problems:
        problems.append("bad exit code")
    lines = err.splitlines()
    if code == 0:
        if lines:
            problems.append("not one line")
        if case.must_refuse:
            problems.append("bad value accepted")
    elif code in (2, 3) and "traceback" not in problems:
        if len(lines) != 1:
            problems.append("not one line")
        else:
            why = classify_error(lines[0], _shown(path))
            if why:
                problems.append(why)
    written = sorted(os.listdir(out)) if out.is_dir() else []
    stem = path.stem
    fmts = formats.split(",")
    allowed = {f"{stem}.{f}" for f in fmts} | {f"{stem}-{k}.{f}" for f in fmts for k in range(1, 20)}
    if code == 0:
        if any(w not in allowed for w in written) or not written:
            problems.append("stray file")
    elif written:
        problems.append("stray file")
    for w in written:
        if w.endswith(".svg"):
            if check_svg(out / w):
                problems.append("invalid svg")
                break
    return Result(case, code, stdout.getvalue(), err, seconds, problems, written)


def fresh_dir(base: Path, i: int) -> Path:
    d = base / f"case{i}"
    d.mkdir(parents=True)
    return d


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("-n", type=int, default=1000, help="number of scenes (default 1000)")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--formats", default="svg", help="formats to render (default svg)")
    ap.add_argument("--show", type=int, default=3, help="examples shown per problem")
    args = ap.parse_args(argv)
    sys.path.insert(0, str(ROOT))
    rng = random.Random(args.seed)
    bases = gallery()
    counts: Counter = Counter()
    exits: Counter = Counter()
    kinds: Counter = Counter()
    examples: dict[str, list[Result]] = {}
    slowest: list[tuple[float, str]] = []
    t_all = time.perf_counter()
    with tempfile.TemporaryDirectory(prefix="fuzz-scenes-") as tmp:
        for i in range(args.n):
            case = make_case(rng, bases)
            r = run_case(case, fresh_dir(Path(tmp), i), args.formats)
            exits[r.code] += 1
            for k in case.kinds:
                kinds[k] += 1
            for p in set(r.problems):
                counts[p] += 1
                examples.setdefault(p, []).append(r)
            slowest.append((r.seconds, ", ".join(case.notes)))
    total = time.perf_counter() - t_all
    rss_mb = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
    print(f"hostile scenes: {args.n} (seed {args.seed}, formats {args.formats}), {total:.1f} s, "
          f"peak RSS {rss_mb:.0f} MB")
    print("exit codes: " + ", ".join(f"{k}: {v}" for k, v in sorted(exits.items(), key=lambda kv: str(kv[0]))))
    print("mutations:  " + ", ".join(f"{k}: {v}" for k, v in sorted(kinds.items())))
    print()
    print("| problem | scenes |")
    print("|---|---|")
    for p in PROBLEMS:
        print(f"| {p} | {counts[p]} |")
    slowest.sort(reverse=True)
    print("\nslowest: " + "; ".join(f"{s:.2f} s ({n[:60]})" for s, n in slowest[:3]))
    for p, rs in examples.items():
        print(f"\n{p}:")
        for r in rs[:args.show]:
            print(f"  {r.case.base} + {r.case.notes} -> exit {r.code}, {r.seconds:.2f} s")
            for line in r.stderr.splitlines()[:3]:
                print("     " + line[:300])
    return 1 if any(counts[p] for p in PROBLEMS) else 0


if __name__ == "__main__":
    sys.exit(main())
