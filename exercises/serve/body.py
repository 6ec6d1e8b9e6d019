"""A request's JSON body, read no further than the size limit.

The body is read as it arrives, a chunk at a time, and refused (413) as soon as it passes
the limit, so a huge or endless body is never held whole; a stated Content-Length over
the limit is refused before any of it is read. Only ``application/json`` is taken: a
page of another site can send a form to a local server, but not JSON without asking
first, which this server never grants.
"""

from __future__ import annotations

import json
from typing import Any

from .refusals import Refused

__all__ = ["MOST_BYTES", "json_body"]

MOST_BYTES = 1_000_000
"""The largest request body taken (1 MB): an exercise's TOML is a few kB."""


async def json_body(request, limit: int = MOST_BYTES) -> dict[str, Any]:
    """The JSON object ``request`` carries.

    Raises
    ------
    Refused
        413 over ``limit`` bytes, 415 if it is not JSON, 400 if it is not a JSON object.
    """
    kind = request.headers.get("content-type", "").split(";")[0].strip().lower()
    if kind != "application/json":
        raise Refused(f"send the request as JSON (Content-Type: application/json), not "
                      f"'{kind or 'nothing'}'", 415)
    stated = request.headers.get("content-length", "")
    if stated.isdigit() and int(stated) > limit:
        raise Refused(_too_big(limit), 413)
    chunks, size = [], 0
    async for chunk in request.stream():
        size += len(chunk)
        if size > limit:
            raise Refused(_too_big(limit), 413)
        chunks.append(chunk)
    try:
        data = json.loads(b"".join(chunks).decode("utf-8"))
    except (UnicodeDecodeError, json.JSONDecodeError) as e:
        raise Refused(f"the request is not valid JSON: {e}", 400) from None
    if not isinstance(data, dict):
        raise Refused("the request is a JSON object: {\"toml\": \"...\", ...}", 400)
    return data


def _too_big(limit: int) -> str:
    return (f"the request is larger than {limit // 1000:,} kB, the most this server takes; "
            "an exercise's file takes a few kB")
