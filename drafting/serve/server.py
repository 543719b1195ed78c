"""The web app of ``drafting serve`` (starlette): the editor page, the drawn pages, saves and downloads,
and the server-sent events that tell the page a served scene changed on disk (watchfiles).

Every request must carry the server's token -- ``?token=`` in the printed URL, then the cookie the first
visit sets (HttpOnly, SameSite=Strict) -- and name this server as its Host (127.0.0.1, localhost or [::1]);
a request with an Origin must come from the page itself.  Anything else is 403 with one sentence.  So
another site open in the same browser can neither read nor drive it (DNS rebinding included).

Routes (the names of scenes are checked by :class:`~drafting.serve.workspace.Workspace`):
``GET /`` the editor; ``GET /api/scenes``; ``GET /api/scene?name=``: text and version;
``POST /api/draw`` ``{name, text}``: the drawing's id, results and warnings and the parts of its page the
shown page takes in place (none for a page with a sweep), or the error with its line and key; ``GET /view/ID``: the drawing's step-through page; ``GET /download/ID/FILE``: its SVG, PDF, PNG;
``POST /api/save`` ``{name, text, version}``: 409 when the file changed since ``version``;
``GET /api/events``: a ``changed`` event with the scene's name and version whenever a served file changes.
"""

from __future__ import annotations

import asyncio
import json
import secrets
import threading
import time
from collections import OrderedDict
from pathlib import Path

from starlette.applications import Starlette
from starlette.concurrency import run_in_threadpool
from starlette.requests import Request
from starlette.responses import HTMLResponse, JSONResponse, PlainTextResponse, Response, StreamingResponse
from starlette.routing import Route
from watchfiles import awatch

from ..scene import limits
from .live import Drawn, draw
from .page import editor_page
from .workspace import Conflict, Refused, Workspace

LOCAL_HOSTS = ("127.0.0.1", "localhost", "[::1]")
KEPT_DRAWINGS = 16
MAX_BODY = 8 * limits.MAX_FILE_BYTES          # a scene's text as JSON (escapes) and its name
HEADERS = {"Content-Security-Policy": "default-src 'self'; script-src 'self' 'unsafe-inline'; "
                                      "style-src 'self' 'unsafe-inline'; img-src 'self' data:; font-src 'self' data:; "
                                      "frame-ancestors 'self'; base-uri 'none'; form-action 'none'",
           "X-Frame-Options": "SAMEORIGIN", "X-Content-Type-Options": "nosniff", "Referrer-Policy": "no-referrer",
           "Cache-Control": "no-store"}
MEDIA = {"svg": "image/svg+xml", "pdf": "application/pdf", "png": "image/png"}


class Guard:
    """The ASGI middleware that checks the token, Host and Origin of every request."""

    def __init__(self, app, token: str, cookie: str) -> None:
        self.app, self.token, self.cookie = app, token, cookie

    def refusal(self, request: Request) -> str | None:
        host = request.headers.get("host", "")
        name = host.rsplit(":", 1)[0] if not host.endswith("]") else host
        if name not in LOCAL_HOSTS:
            return f"the Host {host[:80]!r} is not this local server; open the URL drafting serve printed"
        origin = request.headers.get("origin")
        if origin is not None and origin != f"{request.url.scheme}://{host}":
            return f"a request from {origin[:80]!r} may not use this server; only its own page may"
        given = request.query_params.get("token") or request.cookies.get(self.cookie) or \
            request.headers.get("x-drafting-token") or ""
        if not secrets.compare_digest(given.encode(), self.token.encode()):
            return "this server needs its token: open the full URL drafting serve printed (with ?token=...)"
        return None

    async def __call__(self, scope, receive, send) -> None:
        if scope["type"] != "http":
            return await self.app(scope, receive, send)
        request = Request(scope)
        why = self.refusal(request)
        if why is not None:
            return await PlainTextResponse(f"Forbidden: {why}.\n", 403, headers=HEADERS)(scope, receive, send)

        async def with_headers(message) -> None:
            if message["type"] == "http.response.start":
                have = {k.lower() for k, _ in message.get("headers", [])}
                extra = [(k.lower().encode(), v.encode()) for k, v in HEADERS.items() if k.lower().encode() not in have]
                if request.query_params.get("token"):
                    extra.append((b"set-cookie", f"{self.cookie}={self.token}; Path=/; HttpOnly; "
                                                 f"SameSite=Strict".encode()))
                message = {**message, "headers": list(message.get("headers", [])) + extra}
            await send(message)

        await self.app(scope, receive, with_headers)


class Drawings:
    """The last few drawings by id, for their pages and downloads."""

    def __init__(self) -> None:
        self.kept: OrderedDict[str, Drawn] = OrderedDict()
        self.lock = threading.Lock()

    def add(self, drawn: Drawn) -> str:
        key = secrets.token_hex(8)
        with self.lock:
            self.kept[key] = drawn
            while len(self.kept) > KEPT_DRAWINGS:
                self.kept.popitem(last=False)
        return key

    def get(self, key: str) -> Drawn | None:
        with self.lock:
            return self.kept.get(key)


def _refused(e: Exception, status: int = 404) -> JSONResponse:
    return JSONResponse({"error": str(e)}, status)


async def _body(request: Request) -> dict:
    raw = b""
    async for chunk in request.stream():
        raw += chunk
        if len(raw) > MAX_BODY:
            raise Refused(f"the request is larger than {MAX_BODY // 1024} KiB")
    try:
        data = json.loads(raw)
    except ValueError:
        raise Refused("the request is not JSON") from None
    if not isinstance(data, dict):
        raise Refused("the request is not a JSON object")
    return data


def _text(data: dict, key: str) -> str:
    value = data.get(key)
    if not isinstance(value, str):
        raise Refused(f"the request has no {key!r} text")
    return value


def create_app(target: Path | str, token: str | None = None, cookie: str = "drafting-token") -> Starlette:
    """The app serving the scene or folder ``target``; ``token`` (random if None) is ``app.state.token``."""
    space = Workspace(target)
    drawings = Drawings()
    save_lock = threading.Lock()
    token = token or secrets.token_urlsafe(24)

    async def index(request: Request) -> Response:
        return HTMLResponse(editor_page(space.names(), space.only is None))

    async def scenes(request: Request) -> Response:
        return JSONResponse({"scenes": space.names()})

    async def scene(request: Request) -> Response:
        try:
            s = await run_in_threadpool(space.read, request.query_params.get("name", ""))
        except Refused as e:
            return _refused(e)
        return JSONResponse({"name": s.name, "text": s.text, "version": s.version})

    async def draw_text(request: Request) -> Response:
        try:
            data = await _body(request)
            name, text = _text(data, "name"), _text(data, "text")
            path = space.resolve(name)
        except Refused as e:
            return _refused(e, 400)
        start = time.perf_counter()
        result = await run_in_threadpool(draw, text, path.relative_to(space.root))
        ms = round(1000 * (time.perf_counter() - start), 1)           # the server's share, for the benchmark
        if not isinstance(result, Drawn):
            return JSONResponse({"ok": False, "error": result.error, "key": result.key, "line": result.line, "ms": ms})
        return JSONResponse({"ok": True, "id": drawings.add(result), "sheets": len(result.sheets), "ms": ms,
                             "warnings": list(result.warnings), "results": [list(r) for r in result.results],
                             "parts": result.parts})

    async def view(request: Request) -> Response:
        drawn = drawings.get(request.path_params["id"])
        if drawn is None:
            return PlainTextResponse("This drawing is no longer kept; edit the scene to draw it again.", 404)
        return HTMLResponse(await run_in_threadpool(lambda: drawn.page))

    async def download(request: Request) -> Response:
        drawn = drawings.get(request.path_params["id"])
        stem, _, fmt = request.path_params["file"].rpartition(".")
        if drawn is None or fmt not in MEDIA:
            return PlainTextResponse("No such drawing or format.", 404)
        index = 0
        if fmt != "pdf" and len(drawn.sheets) > 1:
            number = stem.rpartition("-")[2]
            index = int(number) - 1 if number.isdigit() and 1 <= int(number) <= len(drawn.sheets) else 0
        data = await run_in_threadpool(drawn.download, fmt, index)
        return Response(data, media_type=MEDIA[fmt])

    async def save(request: Request) -> Response:
        try:
            data = await _body(request)
            name, text, version = _text(data, "name"), _text(data, "text"), _text(data, "version")

            def guarded() -> str:
                with save_lock:
                    return space.save(name, text, version)
            new = await run_in_threadpool(guarded)
        except Conflict as e:
            return JSONResponse({"error": str(e), "version": e.current}, 409)
        except Refused as e:
            return _refused(e, 400)
        return JSONResponse({"version": new})

    async def events(request: Request) -> Response:
        return StreamingResponse(_changes(space, request), media_type="text/event-stream")

    app = Starlette(routes=[
        Route("/", index), Route("/api/scenes", scenes), Route("/api/scene", scene),
        Route("/api/draw", draw_text, methods=["POST"]), Route("/api/save", save, methods=["POST"]),
        Route("/view/{id}", view), Route("/download/{id}/{file}", download), Route("/api/events", events),
    ])
    app.state.token = token
    guarded = Guard(app, token, cookie)
    guarded.state = app.state
    return guarded


async def _changes(space: Workspace, request: Request):
    """Server-sent events: ``changed`` with a scene's name and version each time a served file changes."""
    stop = asyncio.Event()
    yield ": watching\n\n"
    served = set(space.names())
    try:
        async for changes in awatch(space.root, stop_event=stop, recursive=False, debounce=50, step=20,
                                    yield_on_timeout=True, rust_timeout=1000):
            if await request.is_disconnected():
                break
            names = {Path(p).name for _, p in changes} & (served | set(space.names()))
            for name in sorted(names):
                try:
                    version = space.version(name)
                except Refused:
                    continue
                yield f"event: changed\ndata: {json.dumps({'name': name, 'version': version})}\n\n"
            if not changes:
                yield ": still here\n\n"
    finally:
        stop.set()


__all__ = ["create_app", "Guard", "LOCAL_HOSTS"]
