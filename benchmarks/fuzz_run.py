"""One hostile run of a ``drafting`` command, in-process, and what went wrong with it (:func:`run_argv`):
the checks every command of :mod:`fuzz_scenes` is held to.

A run is fine when it exits with a code its command documents (0 done, 1 a difference or a finding for
check and lint, 2 an error, 3 a singular position); no exception leaves ``main`` and no traceback is
printed; no Python warning is raised (the run is made with ``warnings.simplefilter("error")``: a numpy
RuntimeWarning is "leaked warning"); a failure is one stderr line ``drafting: error: <file>: <key, line
or position>: ...`` (an option's own error names the option); a case made wrong is refused; the output
folder holds the command's own files only, and nothing when it failed, and the input folder nothing but
what was put there; every SVG parses and is inert; the run ends within its seconds.
"""

from __future__ import annotations

import contextlib
import gc
import io
import os
import re
import signal
import sys
import time
import warnings
import xml.etree.ElementTree as ET
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable

HANG_SECONDS = 5.0
KILL_SECONDS = 60.0
MAX_MESSAGE = 400
"""An error sentence longer than this (characters) is not read: "long message"."""

PROBLEMS = ("traceback", "leaked warning", "hang", "invalid svg", "bad value accepted", "error without key",
            "not one line", "long message", "stray file", "bad exit code")


@dataclass
class Command:
    """A command line for one case: ``argv`` with ``{scene}``, ``{out}`` and ``{in}`` put in at the run;
    ``allowed(stem, name)`` says whether a file in the output folder is one of its outputs."""

    label: str
    argv: list[str]
    allowed: Callable[[str, str], bool] = lambda stem, name: False
    codes: tuple[int, ...] = (0, 2, 3)
    must_refuse: bool = False
    option: str | tuple[str, ...] | None = None   # hostile options: a refusal may name one instead of the file
    inputs: dict[str, bytes] = field(default_factory=dict)     # more files for the input folder
    hang_seconds: float = HANG_SECONDS
    needs_output: bool = True                 # a success writes at least one file into {out}


@dataclass
class Result:
    case: object
    command: Command
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
    r"|line \d+(?: \(.*?\))?"                                     # line 3 (a.b), a key with brackets in it
    r"|at [^:]+"                                                  # at crank angle 70 deg
    r"): \S")
_FILE_LEVEL = re.compile(r"(?:is not valid TOML \(.*line \d+|is larger than \d+ KiB|is not UTF-8 text \(byte "
                         r"0x[0-9a-f]{2} on line \d+\)|no such scene file|is a folder|is not a regular file|"
                         r"Cannot write |Cannot create the output folder |is \S+ bytes; )")
_OPTION = re.compile(r"drafting: error: (?:.*: )?(?:argument )?--[a-z-]+\b")


def classify_error(line: str, shown_paths: list[str], option: str | tuple[str, ...] | None = None) -> str | None:
    """None if ``line`` is one well-formed error naming the file (as one of ``shown_paths``) and a key,
    a line or a position -- or, for a hostile ``option`` (or several: any of them), naming that option."""
    prefix = "drafting: error: "
    if not line.startswith(prefix):
        return "not one line"
    if len(line) > MAX_MESSAGE:
        return "long message"
    names = (option,) if isinstance(option, str) else tuple(option or ())
    if names and _OPTION.match(line) and any(n in line for n in names):
        return None
    rest = line[len(prefix):]
    for shown in shown_paths:
        if rest.startswith(shown + ": "):
            after = rest[len(shown) + 2:]
            if _KEYED.match(after) or _FILE_LEVEL.match(after):
                return None
    return "error without key"


def shown_paths(*paths: Path) -> list[str]:
    """How a message may show a file's path: escaped, and cut in the middle when long."""
    from drafting.scene.textsafe import cut_middle, printable
    return [s for p in paths for s in (printable(str(p)), cut_middle(printable(str(p)), 120))]


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


def _call(argv: list[str], hang_seconds: float) -> tuple[int | None, str, str, float, list[str]]:
    """``drafting argv`` in-process with warnings as errors and an alarm: (code, stdout, stderr, seconds,
    problems)."""
    from drafting.app.cli import main
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
        with contextlib.redirect_stdout(stdout), contextlib.redirect_stderr(stderr), warnings.catch_warnings():
            warnings.simplefilter("error")
            try:
                code = main(argv)
            finally:
                gc.collect()                   # a file left open warns when collected: here, not in a later case
    except _Hang:
        problems.append("hang")
    except SystemExit as e:                    # argparse: a usage line and the error (two lines)
        code = e.code if isinstance(e.code, int) else 2
        if code != 2:
            problems.append("bad exit code")
    except Warning as e:
        problems.append("leaked warning")
        stderr.write(f"\n[escaped: {e.__class__.__name__}: {str(e)[:300]}]")
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
    if re.search(r"\b\w*Warning\b", err) and "leaked warning" not in problems:
        problems.append("leaked warning")
    if "Traceback" in err and "traceback" not in problems and not (
            "leaked warning" in problems and "Exception ignored" in err):    # a warning raised while collected
        problems.append("traceback")
    return code, stdout.getvalue(), err, seconds, problems


def run_argv(case, command: Command, workdir: Path) -> Result:
    """Write the case's scene (and the command's other inputs) into ``workdir/in``, run the command with
    its output folder ``workdir/out`` and check what it did."""
    scene_dir, out = workdir / "in", workdir / "out"
    scene_dir.mkdir(parents=True, exist_ok=True)
    path = scene_dir / case.filename
    src = case.source()
    try:
        with open(path, "wb") as fh:
            fh.write(src.encode("utf-8") if isinstance(src, str) else src)
    except OSError as e:                       # the file system refuses the name itself: not our bug
        return Result(case, command, None, "", f"(cannot create {case.filename!r}: {e.strerror})", 0.0, [], [])
    for name, data in command.inputs.items():
        (scene_dir / name).write_bytes(data)
    argv = [a.format(scene=path, out=out, **{"in": scene_dir}) for a in command.argv]
    code, stdout, err, seconds, problems = _call(argv, command.hang_seconds)
    fatal = {"traceback", "leaked warning", "hang"} & set(problems)
    if code not in command.codes and not fatal:
        problems.append("bad exit code")
    lines = err.splitlines()
    if code == 0:
        if lines:
            problems.append("not one line")
        if case.must_refuse or command.must_refuse:
            problems.append("bad value accepted")
    elif code in (2, 3) and not fatal:
        if len(lines) != 1:
            problems.append("not one line")
        else:
            extra = [scene_dir / n for n in command.inputs]
            why = classify_error(lines[0], shown_paths(path, *extra), command.option)
            if why:
                problems.append(why)
    written = sorted(os.listdir(out)) if out.is_dir() else []
    stray = [w for w in written if not command.allowed(path.stem, w)]
    if code == 0 and (stray or (command.needs_output and not written)):
        problems.append("stray file")
    elif code not in (0, 1) and written:
        problems.append("stray file")
    if set(os.listdir(scene_dir)) - {case.filename, *command.inputs}:
        problems.append("stray file")
    for w in written:
        if w.endswith(".svg") and (out / w).is_file() and check_svg(out / w):
            problems.append("invalid svg")
            break
    return Result(case, command, code, stdout, err, seconds, problems, written)
