"""Edit to sheet in ``drafting serve``, measured in headless Chromium (Debian ``chromium``) over the
DevTools protocol: the page's own clock from the moment the debounced edit is sent (``draw()``) to the
moment the new sheet is shown in the page, over many edits of the crank angle of a scene (each a new
drawing), with the server's share (its solve, layout and page, as it reports it) beside it.

    python benchmarks/serve_latency.py [SCENE] [-n 20] [--against CHECKOUT]

A benchmark, not a test: it prints the figures the README quotes (median, quartiles, worst) and the
machine's load while it ran; with ``--against`` the same edits are measured first with the server of
another checkout of the project (an earlier commit's working tree), side by side in one run.
"""

from __future__ import annotations

import argparse
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "tests"))          # the DevTools driver the browser tests use
from cdp import CHROMIUM, Browser  # noqa: E402


def _quartiles(xs: list[float]) -> tuple[float, float, float]:
    q = statistics.quantiles(xs, n=4) if len(xs) > 1 else [xs[0]] * 3
    return q[0], statistics.median(xs), q[2]


def measure(scene: Path, n: int, tree: Path | None = None) -> dict:
    """``n`` edits of ``scene``'s crank angle in a served copy: each edit's total and server milliseconds
    (the server run from the checkout ``tree`` when given)."""
    work = Path(tempfile.mkdtemp(prefix="serve-latency-"))
    try:
        copy = work / scene.name
        shutil.copy(scene, copy)
        env = dict(os.environ, PYTHONPATH=str(tree)) if tree is not None else None
        proc = subprocess.Popen([sys.executable, "-m", "drafting.app.cli", "serve", str(copy), "--port", "0"],
                                stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env, cwd=work)
        try:
            lines = [proc.stdout.readline() for _ in range(3)]
            url = re.search(r"http://127\.0\.0\.1:\d+/\?token=[\w-]{20,}", "".join(lines))
            if url is None:
                raise SystemExit(f"drafting serve printed no URL: {lines}")
            angle = re.search(r'angle\s*=\s*"(-?[\d.]+) deg"', copy.read_text())
            if angle is None:
                raise SystemExit(f"{scene}: no crank angle in degrees to edit")
            total, server, reply, swap = [], [], [], []
            with Browser() as b:
                b.open(url.group(0))
                b.wait("window.serveState && serveState.drawn > 0", 60)
                old = angle.group(0)
                for k in range(n + 2):                       # two warm-up edits first
                    new = f'angle = "{float(angle.group(1)) + 1 + k % 40:g} deg"'
                    seq = b.eval("serveState.seq")
                    b.eval("(() => { const t = document.getElementById('text'); "
                           f"t.value = t.value.replace({old!r}, {new!r}); draw(); }})()")
                    b.wait(f"serveState.drawn > {seq}", 30)
                    old = new
                    if k >= 2:
                        total.append(b.eval("serveState.ms"))
                        server.append(b.eval("serveState.server || 0"))
                        reply.append(b.eval("serveState.reply || 0"))
                        swap.append(b.eval("serveState.swap || 0"))
        finally:
            proc.terminate()
            proc.wait(10)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    return {"total": total, "server": server, "reply": reply, "swap": swap}


def _report(label: str, got: dict) -> None:
    t = _quartiles(got["total"])
    print(f"  {label}: total median {t[1]:.0f} ms (quartiles {t[0]:.0f}-{t[2]:.0f}, worst {max(got['total']):.0f})")
    if any(got["server"]):
        s, r, w = (_quartiles(got[k]) for k in ("server", "reply", "swap"))
        print(f"    server {s[1]:.0f} ms (read, solve, lay out, page); reply {r[1]:.0f} ms (the request until its "
              f"answer is read in the page); swap {w[1]:.0f} ms (the new sheets and steps put in the shown page); "
              f"the rest to the paint")


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("scene", nargs="?", default=str(ROOT / "gallery" / "notes-velocity-example-1.toml"))
    ap.add_argument("-n", type=int, default=20)
    ap.add_argument("--against", type=Path, help="another checkout of the project, measured first")
    args = ap.parse_args(argv)
    if CHROMIUM is None:
        print("headless Chromium (Debian chromium) is not installed")
        return 2
    print(f"{Path(args.scene).name}: {args.n} edits of the crank angle, edit (after the debounce) to sheet shown")
    if args.against is not None:
        _report(f"{args.against}", measure(Path(args.scene), args.n, args.against))
    _report("this checkout", measure(Path(args.scene), args.n, ROOT))
    print(f"  load average {os.getloadavg()[0]:.2f} on {os.cpu_count()} cores")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
