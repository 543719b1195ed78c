"""``drafting serve [SCENE | FOLDER]``: the live editor on this machine only (127.0.0.1), its URL with a
fresh random token printed.  The web libraries are the optional extra ``.[serve]``, imported only here: the
rest of ``drafting`` runs without them, and without them this command says in one sentence how to install
them."""

from __future__ import annotations

import importlib.util
import socket
import sys
from pathlib import Path

from ..app.solving import UserError

HOST = "127.0.0.1"
DEFAULT_PORT = 8470
NEEDED = ("starlette", "uvicorn", "watchfiles")
INSTALL = ("drafting serve needs the web extra: pip install 'tom-drafting[serve]' "
           "(in a clone: pip install -e '.[serve]')")


def missing() -> list[str]:
    """The extra's modules that are not installed."""
    return [m for m in NEEDED if importlib.util.find_spec(m) is None]


def _bind(port: int) -> socket.socket:
    """A listening socket on 127.0.0.1: ``port``, or any free port if that one is taken (or 0)."""
    for p in ((port, 0) if port else (0,)):
        sock = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
        sock.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
        try:
            sock.bind((HOST, p))
        except OSError:
            sock.close()
            continue
        sock.listen(64)
        return sock
    raise UserError(f"no port on {HOST} could be opened for drafting serve")


def cmd_serve(target: Path | None, port: int = DEFAULT_PORT) -> int:
    """Serve ``target`` (a scene file or a folder; the current folder if None) until interrupted."""
    if missing():
        raise UserError(INSTALL)
    import uvicorn
    from .server import create_app
    from .workspace import Refused
    target = Path(".") if target is None else target
    try:
        sock = _bind(port)
        port = sock.getsockname()[1]
        app = create_app(target, cookie=f"drafting-token-{port}")
    except Refused as e:
        raise UserError(str(e)) from None
    url = f"http://{HOST}:{port}/?token={app.state.token}"
    print(f"drafting serve: {target} at\n  {url}\n(this machine only; Ctrl-C stops it)", flush=True)
    config = uvicorn.Config(app, log_level="warning", timeout_graceful_shutdown=1, lifespan="off")
    try:
        uvicorn.Server(config).run(sockets=[sock])
    finally:
        sock.close()
    print("drafting serve: stopped", file=sys.stderr)
    return 0


__all__ = ["cmd_serve", "missing", "INSTALL"]


def run_command(args) -> int:
    return cmd_serve(args.target, args.port)
