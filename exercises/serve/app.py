"""The routes of ``tarsim serve``: the app page, the exercises, and solving, downloading and
saving one (the contract is docs/howto/app.md's).

Each route reads its request, makes the library's call in a worker thread (so one long
solve does not hold up the others, and each keeps the language it is spoken in) and
answers JSON; a :class:`~tarsim.constructions.errors.TarsimError` is answered as
``{"error": line, "where": {...}}`` (:mod:`.refusals`).
"""

from __future__ import annotations

import threading
from contextlib import asynccontextmanager
from functools import cache
from pathlib import Path, PurePosixPath
from typing import Any
from urllib.parse import quote

from starlette.applications import Starlette
from starlette.concurrency import run_in_threadpool
from starlette.middleware import Middleware
from starlette.middleware.trustedhost import TrustedHostMiddleware
from starlette.requests import Request
from starlette.responses import HTMLResponse, JSONResponse, Response
from starlette.routing import Route

from tarsim.constructions.errors import TarsimError

from .body import MOST_BYTES, json_body
from .folder import Folder
from .page import app_page
from .refusals import Refused, refusal
from .solving import Asked, answer

__all__ = ["make_app"]


def make_app(folder: str | Path = ".", *, limit: int = MOST_BYTES,
             hosts: list[str] | None = None, warm: bool = False) -> Starlette:
    """The app serving ``folder``: it reads and writes there only, takes request bodies of
    ``limit`` bytes at most, and answers only requests to one of ``hosts`` (a page of
    another site reaching the server by a name of its own is refused; None: any). With
    ``warm``, it lists the bundled exercises and solves one as it starts, in a thread of
    its own, so that the page's first answers do not wait for the solver to load.

    Raises
    ------
    FileNotFoundError
        If ``folder`` does not exist.
    """
    served = Folder(folder)

    async def exercises(request: Request) -> Response:
        listed = await run_in_threadpool(_bundled)
        return JSONResponse({"bundled": listed, "files": await run_in_threadpool(served.tomls)})

    async def exercise(request: Request) -> Response:
        q = request.query_params
        if "id" in q:
            text = await run_in_threadpool(_bundled_text, q["id"])
            return JSONResponse({"id": q["id"], "toml": text})
        if "file" in q:
            return JSONResponse({"file": q["file"],
                                 "toml": await run_in_threadpool(served.read, q["file"])})
        raise Refused("name the exercise: /api/exercise?id=four-bar (a bundled one) or "
                      "?file=my.toml (a file in the served folder)", 400)

    async def solve(request: Request) -> Response:
        asked = Asked.of(await json_body(request, limit))
        return JSONResponse(await _solving(answer, asked))

    async def download(request: Request) -> Response:
        body = await json_body(request, limit)
        asked = Asked.of({**body, "figures": True})
        what = body.get("what")
        if what == "toml":
            data, name = asked.toml.encode("utf-8"), PurePosixPath(asked.name).name
        elif what in ("svg", "pdf", "png", "steps"):
            from .downloads import download_file

            data, name = await _solving(download_file, asked, what, body.get("figure"))
        else:
            raise Refused(f'"what" is toml, svg, pdf, png or steps; got {what!r:.40}', 400)
        kind = _TYPES.get(PurePosixPath(name).suffix, "application/octet-stream")
        return Response(data, media_type=kind,
                        headers={"Content-Disposition": _attachment(name)})

    async def save(request: Request) -> Response:
        body = await json_body(request, limit)
        text = body.get("toml")
        if not isinstance(text, str):
            raise Refused('send the exercise\'s text as "toml"', 400)
        overwrite = body.get("overwrite", False) is True
        name = await run_in_threadpool(lambda: served.save(body.get("file"), text,
                                                           overwrite=overwrite))
        return JSONResponse({"file": name})

    async def page(request: Request) -> Response:
        return HTMLResponse(await run_in_threadpool(app_page))

    routes = [Route("/", page), Route("/api/exercises", _answering(exercises)),
              Route("/api/exercise", _answering(exercise)),
              Route("/api/solve", _answering(solve), methods=["POST"]),
              Route("/api/download", _answering(download), methods=["POST"]),
              Route("/api/save", _answering(save), methods=["POST"])]
    middleware = [Middleware(TrustedHostMiddleware, allowed_hosts=hosts)] if hosts else []
    app = Starlette(routes=routes, middleware=middleware, lifespan=_warmed if warm else None)
    app.state.folder = served
    return app


_TYPES = {".toml": "application/toml", ".svg": "image/svg+xml", ".pdf": "application/pdf",
          ".png": "image/png", ".md": "text/markdown; charset=utf-8"}


@asynccontextmanager
async def _warmed(app):
    """The app's life, begun by warming it up in the background (:func:`_warm_up`)."""
    threading.Thread(target=_warm_up, name="tarsim-warm-up", daemon=True).start()
    yield


def _warm_up() -> None:
    """List the bundled exercises and solve the four-bar with its figures: what the page
    asks first, its modules loaded and its listing kept."""
    from ..catalog import everything

    try:
        _bundled()
        answer(Asked(everything()["four-bar"].read_text(encoding="utf-8"), "four-bar.toml"))
    except TarsimError:         # a bundled exercise that fails is its own tests' to say
        pass


def _attachment(name: str) -> str:
    """A download's Content-Disposition: its name as is, and in ASCII for an old browser."""
    plain = "".join(c if c.isascii() and c.isprintable() and c not in '"\\' else "_"
                    for c in name)
    return f"attachment; filename=\"{plain}\"; filename*=UTF-8''{quote(name)}"


class _Unsolvable(Exception):
    """A TarsimError of solving, with the file's name and text to place its line in."""

    def __init__(self, error: TarsimError, asked: Asked):
        self.error, self.asked = error, asked


async def _solving(fn, asked: Asked, *args: Any):
    """``fn(asked, *args)`` in a worker thread, its TarsimError placed in the sent file."""
    def run():
        try:
            return fn(asked, *args)
        except Refused:
            raise
        except TarsimError as e:
            raise _Unsolvable(e, asked) from None
    return await run_in_threadpool(run)


def _answering(route):
    """``route``, its refusals and errors answered as JSON with their status."""
    async def answered(request: Request) -> Response:
        try:
            return await route(request)
        except _Unsolvable as u:
            status, body = refusal(u.error, u.asked.name, u.asked.toml)
        except TarsimError as e:
            status, body = refusal(e)
        return JSONResponse(body, status_code=status)
    return answered


@cache
def _bundled() -> list[dict[str, str]]:
    """Every bundled exercise: its id, title and chapter, in ``tarsim list``'s order."""
    from ..catalog import everything, load
    from ..chapters import chapter_of

    out = []
    for key in everything():
        ex = load(key)
        chapter = chapter_of(ex)
        out.append({"id": key, "title": chapter.title(ex), "chapter": chapter.key})
    return out


def _bundled_text(key: str) -> str:
    """The text of the bundled exercise ``key``.

    Raises
    ------
    Refused
        404 if there is none by that id, with the closest.
    """
    import difflib

    from ..catalog import everything
    from ..toml_source import read_source

    ids = everything()
    if key not in ids:
        close = difflib.get_close_matches(key, list(ids), n=1)
        hint = f"; did you mean '{close[0]}'?" if close else ""
        raise Refused(f"no bundled exercise '{key:.60}'{hint}", 404)
    return read_source(ids[key])
