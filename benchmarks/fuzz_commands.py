"""The commands of the hostile runs (:mod:`fuzz_scenes`): each case runs one command chosen for its
scene's family kind, with hostile options now and then, and for ``check --answers`` a hostile answers file.

Kinds (:func:`kind_of`): linkage, forces (a linkage with loads, masses or springs), cam, gear pair, gear
train, free body, vary (a scene with [vary] ranges).  Commands (:func:`make_command`): solve, solve
--json, solve --csv, render (svg, pdf, png, html), render --lab, check, check --answers, lint; sweep
(--steps, --every, --csv) for linkages; export (--tolerance inside and outside its range) for cams;
batch for [vary] scenes.
"""

from __future__ import annotations

import random
from typing import Any

from fuzz_run import Command

KINDS = ("linkage", "forces", "cam", "gear pair", "gear train", "free body", "vary")
LINKAGES = ("linkage", "forces", "vary")
ANSWER_NAMES = ["V_B", "V_C", "V_CB", "V_D", "A_C", "A_B", "omega_2", "omega_3", "alpha_3", "F_14", "T_2", "F_32",
                "PB", "p_b", "contact ratio", "omega_out", "rise", "pressure angle", "s", "R_A"]


def kind_of(data: dict[str, Any] | None) -> str:
    """The family kind of a (gallery) scene's data."""
    k = data.get("kind") if isinstance(data, dict) else None
    if k in ("cam", "gear pair", "gear train", "free body"):
        return k
    if "vary" in data:
        return "vary"
    if any(t in data for t in ("load", "mass", "spring", "gravity")):
        return "forces"
    return "linkage"


def _outputs(*patterns: str):
    """An ``allowed`` test: the file is ``stem`` followed by one of ``patterns`` (a trailing ``*``: any
    ending)."""
    def allowed(stem: str, name: str) -> bool:
        if not name.startswith(stem):
            return False
        rest = name[len(stem):]
        return any(rest == p or (p.endswith("*") and rest.startswith(p[:-1])) for p in patterns)
    return allowed


def _sheets(formats: list[str], prefixes=("",)):
    pats = [f"{p}{k}.{f}" for p in prefixes for f in formats for k in ("", *(f"-{i}" for i in range(1, 20)))]
    return _outputs(*pats, *([f"{p}-key.csv" for p in prefixes] if prefixes != ("",) else []))


# -- hostile options: (text, accepted?) ------------------------------------------------------------------

STEPS = [("1", True), ("2", True), ("72", True), ("1000", True), ("100000", True), ("0", False), ("-5", False),
         ("10000001", False), ("100000000", False), ("1" + "0" * 30, False), ("1e300", False), ("nan", False),
         ("inf", False), ("", False), ("7.5", False)]
EVERY = [("5deg", True), ("0.5 deg", True), ("0.1rad", True), ("10", True), ("0.01deg", True),
         ("1e-300deg", False), ("0deg", False), ("-5deg", False), ("nan deg", False), ("inf deg", False),
         ("1e300 rad", False), ("5 mm", False), ("400deg", None), ("", False), ("5 deg deg", False),
         ("9**9**9 deg", False)]
TOLERANCE = [("1e-6", True), ("1e-3", True), ("0.05", True), ("1e-7", True), ("1e-8", False), ("1e-10", False),
             ("1e-300", False), ("0.1", False), ("0.5", False), ("nan", False), ("-1", False), ("inf", False),
             ("1e300", False), ("0", False), ("abc", False)]
VARIANTS = [("1", True), ("2", True), ("0", False), ("-1", False), ("10001", False), ("1" + "0" * 30, False),
            ("1e300", False), ("nan", False)]
SEEDS = [("0", True), ("7", True), ("-1", False), ("1" + "0" * 30, False), ("nan", False), ("1e300", False)]


def _pick(rng: random.Random, table, hostile: float) -> tuple[str, bool | None]:
    """A value of ``table``: a usual one (the first) unless hostile."""
    return rng.choice(table) if rng.random() < hostile else table[0]


def _opt(argv: list[str], name: str, value: str) -> None:
    argv.append(f"{name}={value}")            # "=": a value starting with '-' is the option's, not a flag


# -- answers files ---------------------------------------------------------------------------------------

def answers_file(rng: random.Random) -> tuple[str, bytes, bool]:
    """A hostile answers file: (file name, bytes, must it be refused?)."""
    names = rng.sample(ANSWER_NAMES, 4)
    how = rng.choice(["fine csv", "fine toml", "wide row", "many rows", "extra fields", "deep toml",
                      "odd units", "odd text", "table value", "huge number", "twice", "binary", "empty",
                      "long name", "header only"])
    if how == "fine csv":
        return "answers.csv", "".join(f"{n},{rng.uniform(-500, 500):.1f}\n" for n in names).encode(), False
    if how == "fine toml":
        return "answers.toml", "".join(f'"{n}" = "{rng.uniform(0, 500):.1f}"\n' for n in names).encode(), False
    if how == "wide row":
        return "answers.csv", (names[0] + ",1" * rng.choice([4, 50, 5000])).encode() + b"\n", True
    if how == "many rows":
        return "answers.csv", b"".join(b"V_C,1\n" for _ in range(rng.choice([20_000, 200_000]))), True
    if how == "extra fields":
        return "answers.csv", f"{names[0]},5 mm/s,180 deg,oops\n".encode(), True
    if how == "deep toml":
        d = rng.choice([11, 500, 50_000])
        body = rng.choice([f"x = {'[' * d}1{']' * d}", f"x = {'{a = ' * d}1{'}' * d}", ".".join(["a"] * d) + " = 1"])
        return "answers.toml", body.encode(), True
    if how == "odd units":
        u = rng.choice(["5 furlong/fortnight", "1e300 mm/s", "nan mm/s", "inf", "-0", "5 mm/s at nan deg",
                        "5 mm/s at 1e300 deg", "9**9**9 mm/s", "5 percent", "1e-320 rad/s cw", "5 deg",
                        "5 mm/s mm/s", "0x10", "1_000", "5 mm/s at 1e309 deg", "1" + "0" * 400])
        return "answers.csv", "".join(f"{n},{u}\n" for n in names).encode(), False
    if how == "odd text":
        s = rng.choice(["\x1b[31m", "\u202e", "\x00", "\ufeff", "\U0001F600", "\r", "\u2028"])
        return "answers.csv", f"{names[0]}{s},1{s}\n{s}{names[1]},2\n".encode("utf-8", "replace"), False
    if how == "table value":
        return "answers.toml", f'"{names[0]}" = {{ a = 1 }}\n"{names[1]}" = [1, 2]\n'.encode(), True
    if how == "huge number":
        return "answers.toml", f'"{names[0]}" = {"9" * rng.choice([50, 101, 5000])}\n'.encode(), True
    if how == "twice":
        return "answers.csv", f"{names[0]},1\n{names[0]},2\n".encode(), False
    if how == "binary":
        return rng.choice(["answers.csv", "answers.toml"]), bytes(rng.randrange(256) for _ in range(300)), True
    if how == "empty":
        return "answers.csv", b"", False
    if how == "long name":
        return "answers.csv", ("V" * rng.choice([201, 10_000]) + ",1\n").encode(), False
    return "answers.csv", b"name,value\n", False


# -- commands --------------------------------------------------------------------------------------------

def commands_for(kind: str) -> list[str]:
    common = ["solve", "solve --json", "solve --csv", "render", "render --lab", "check", "check --answers", "lint"]
    if kind in LINKAGES:
        common += ["sweep", "sweep --every", "sweep --csv"]
    if kind == "cam":
        common += ["export"]
    if kind == "vary":
        common += ["batch"]
    return common


def make_command(rng: random.Random, kind: str, hostile: float = 0.3, name: str | None = None) -> Command:
    """One command for a scene of ``kind`` (``name``, else one drawn from :func:`commands_for`); options
    hostile with probability ``hostile``."""
    name = name or rng.choice(commands_for(kind))
    if name.startswith("solve"):
        argv = ["solve", "{scene}"]
        if name == "solve --json":
            argv.append("--json")
        if name == "solve --csv":
            argv += ["--csv", "{out}/results.csv"]
            return Command(name, argv, lambda s, n: n == "results.csv")
        return Command(name, argv, needs_output=False)
    if name in ("render", "render --lab"):
        formats = rng.sample(["svg", "pdf", "png", "html"], rng.choice([1, 1, 2]))
        argv = ["render", "{scene}", "-o", "{out}", "--format", ",".join(formats), "--workers", "1"]
        label = name
        if name == "render --lab":
            argv.append("--lab")
            return Command(label, argv, _sheets(formats, ("", "-problem", "-key")), hang_seconds=15.0)
        return Command(label, argv, _sheets(formats), codes=(0, 1, 2, 3), hang_seconds=10.0)
    if name == "check":
        return Command(name, ["check", "{scene}"], codes=(0, 1, 2, 3), needs_output=False)
    if name == "lint":
        return Command(name, ["lint", "{scene}"] + (["--json"] if rng.random() < 0.3 else []),
                       codes=(0, 1, 2, 3), needs_output=False, hang_seconds=10.0)
    if name == "check --answers":
        fname, data, refuse = answers_file(rng)
        argv = ["check", "{scene}", "--answers", "{in}/" + fname]
        refuse_opt, option = False, ()
        if kind == "vary" and rng.random() < 0.5:
            v, ok_v = _pick(rng, VARIANTS, hostile)
            s, ok_s = _pick(rng, SEEDS, hostile)
            _opt(argv, "--variant", v)
            _opt(argv, "--seed", s)
            refuse_opt = ok_v is False or ok_s is False
            option = tuple(o for o, ok in (("--variant", ok_v), ("--seed", ok_s)) if ok is False)
        return Command(name, argv, codes=(0, 1, 2, 3), must_refuse=refuse or refuse_opt, option=option,
                       inputs={fname: data}, needs_output=False)
    if name.startswith("sweep"):
        argv = ["sweep", "{scene}"]
        if name == "sweep --every":
            value, ok = _pick(rng, EVERY, hostile)
            _opt(argv, "--every", value)
            option = "--every"
        else:
            value, ok = _pick(rng, STEPS, hostile) if rng.random() < 0.7 else (None, True)
            if value is not None:
                _opt(argv, "--steps", value)
            option = "--steps"
        csv = name == "sweep --csv" or rng.random() < 0.3
        if csv:
            argv += ["--csv", "{out}/sweep.csv"]
        return Command(f"{name}", argv, (lambda s, n: n == "sweep.csv"), must_refuse=ok is False, option=option,
                       needs_output=csv, hang_seconds=10.0)
    if name == "export":
        value, ok = rng.choice(TOLERANCE) if rng.random() < 0.6 else TOLERANCE[0]
        argv = ["export", "{scene}", "-o", "{out}"]
        _opt(argv, "--tolerance", value)
        return Command(name, argv, _outputs("-profile.csv", "-profile.dxf", "-stations.csv"), must_refuse=not ok,
                       option="--tolerance", hang_seconds=10.0)
    if name == "batch":
        v, ok_v = _pick(rng, VARIANTS, hostile)
        s, ok_s = _pick(rng, SEEDS, hostile)
        argv = ["batch", "{scene}", "-o", "{out}", "--format", "svg", "--workers", "1"]
        _opt(argv, "--variants", v)
        _opt(argv, "--seed", s)
        return Command(name, argv, _outputs("-*"), must_refuse=ok_v is False or ok_s is False,
                       option=tuple(o for o, ok in (("--variants", ok_v), ("--seed", ok_s)) if ok is False),
                       hang_seconds=30.0)
    raise ValueError(name)
