"""tarsim serve answers requests at once without mixing them: two exercises in two languages,
sent together, each answered as it is answered alone."""

from __future__ import annotations

import asyncio

import pytest

pytest.importorskip("starlette")
httpx = pytest.importorskip("httpx")

from tarsim.exercises.catalog import everything  # noqa: E402
from tarsim.exercises.serve import make_app  # noqa: E402

ASKED = [{"toml": everything()[key].read_text(encoding="utf-8"), "id": key, "lang": lang}
         for key in ("four-bar", "crank-shaper") for lang in ("en", "fa")]


async def _answers(app, bodies: list[dict]) -> list[dict]:
    """Each body's answer, the requests sent all at once (each solve in a worker thread)."""
    transport = httpx.ASGITransport(app=app)
    async with httpx.AsyncClient(transport=transport, base_url="http://127.0.0.1") as client:
        replies = await asyncio.gather(*(client.post("/api/solve", json=b) for b in bodies))
    assert all(r.status_code == 200 for r in replies), [r.text[:200] for r in replies]
    return [r.json() for r in replies]


@pytest.mark.slow
def test_concurrent_solves_in_two_languages_keep_their_own_answers(tmp_path):
    app = make_app(tmp_path)
    alone = [asyncio.run(_answers(app, [b]))[0] for b in ASKED]
    # twice each, interleaved: eight requests in flight at once
    together = asyncio.run(_answers(app, ASKED + ASKED[::-1]))
    assert together == alone + alone[::-1]
    # and they are what they should be, not merely alike: each in its language
    titles = [a["title"] for a in alone]
    assert titles == ["Four-bar crank-rocker", "چهار میله‌ای لنگ - آونگ",
                      "Crank-shaper quick-return mechanism", titles[3]]
    assert titles[3] != titles[2] and any("\u0600" <= ch <= "\u06ff" for ch in titles[3])
    for answer, body in zip(alone, ASKED):
        assert answer["results"]["exercise"] == body["id"]
        persian = any("\u0600" <= ch <= "\u06ff" for f in answer["figures"] for ch in f["svg"])
        assert persian == (body["lang"] == "fa")
    # the four-bar's ω3 and the crank-shaper's are each their own
    assert alone[0]["omega"]["3"] == pytest.approx(-2.578, abs=5e-4)
    assert alone[2]["omega"] != alone[0]["omega"]
