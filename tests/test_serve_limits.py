"""What tarsim serve may touch: files inside its folder only, bodies up to a size, JSON only,
requests to its own host name."""

from __future__ import annotations

import asyncio
import os
import warnings
from pathlib import Path

import pytest

pytest.importorskip("starlette")
pytest.importorskip("httpx")

with warnings.catch_warnings():       # starlette would rather have httpx2; httpx serves
    warnings.simplefilter("ignore")
    from starlette.testclient import TestClient  # noqa: E402

from tarsim.exercises.serve import make_app  # noqa: E402
from tarsim.exercises.serve.body import json_body  # noqa: E402
from tarsim.exercises.serve.refusals import Refused  # noqa: E402

TEXT = 'name = "mine"\n'


@pytest.fixture
def served(tmp_path) -> tuple[Path, Path]:
    """A served folder inside ``tmp_path``, and a file outside it a link inside leads to."""
    root = tmp_path / "served"
    (root / "sub").mkdir(parents=True)
    (root / "mine.toml").write_text(TEXT, encoding="utf-8")
    outside = tmp_path / "outside.toml"
    outside.write_text("secret = 1\n", encoding="utf-8")
    (root / "link.toml").symlink_to(outside)
    (root / "away").symlink_to(tmp_path)               # a folder link that leads out
    return root, outside


def _client(root: Path, **kw) -> TestClient:
    return TestClient(make_app(root, **kw))


@pytest.mark.parametrize("name", ["../outside.toml", "sub/../../outside.toml", "sub/../mine.toml",
                                  "link.toml", "away/outside.toml", "/etc/passwd",
                                  "C:\\x.toml"])
def test_a_path_out_of_the_folder_is_refused_in_one_line(served, name):
    root, outside = served
    c = _client(root)
    r = c.get("/api/exercise", params={"file": name})
    assert r.status_code == 403, r.text
    assert "\n" not in r.json()["error"] and "secret" not in r.text
    w = c.post("/api/save", json={"file": name, "toml": "x = 1\n", "overwrite": True})
    assert w.status_code == 403
    assert outside.read_text(encoding="utf-8") == "secret = 1\n"      # untouched


def test_the_listing_leaves_out_links_that_lead_out(served):
    root, _ = served
    assert _client(root).get("/api/exercises").json()["files"] == ["mine.toml"]


def test_save_writes_inside_and_keeps_a_file_it_did_not_write(served):
    root, _ = served
    c = _client(root)
    r = c.post("/api/save", json={"file": "sub/new.toml", "toml": TEXT})
    assert r.status_code == 200 and r.json() == {"file": "sub/new.toml"}
    assert (root / "sub" / "new.toml").read_text(encoding="utf-8") == TEXT
    # the app's own file it may write again; another it keeps unless told
    assert c.post("/api/save", json={"file": "sub/new.toml", "toml": "a = 2\n"}).status_code == 200
    kept = c.post("/api/save", json={"file": "mine.toml", "toml": "a = 2\n"})
    assert kept.status_code == 409 and '"overwrite": true' in kept.json()["error"]
    assert (root / "mine.toml").read_text(encoding="utf-8") == TEXT
    assert c.post("/api/save", json={"file": "mine.toml", "toml": "a = 2\n",
                                     "overwrite": True}).status_code == 200
    assert (root / "mine.toml").read_text(encoding="utf-8") == "a = 2\n"
    assert c.post("/api/save", json={"file": "notes.txt", "toml": TEXT}).status_code == 400
    assert c.post("/api/save", json={"file": "none/x.toml", "toml": TEXT}).status_code == 404
    # written atomically: no staging file is left beside it
    assert sorted(p.name for p in root.iterdir()) == ["away", "link.toml", "mine.toml", "sub"]


def test_a_body_over_the_limit_is_refused(served):
    root, _ = served
    c = _client(root, limit=10_000)
    big = {"toml": "#" * 20_000}
    r = c.post("/api/solve", json=big)
    assert r.status_code == 413 and "larger than 10 kB" in r.json()["error"]
    # without a Content-Length, read chunk by chunk
    chunks = (b'{"toml": "' + b"#" * 4096, *[b"#" * 4096] * 5, b'"}')
    r = c.post("/api/solve", content=iter(chunks), headers={"content-type": "application/json"})
    assert r.status_code == 413
    assert c.post("/api/solve", json={"toml": "#" * 5_000, "figures": False}).status_code == 422


def test_the_body_is_read_no_further_than_the_limit():
    """An endless body: refused after the limit's worth of chunks, none held past it."""
    pulled = 0

    class Endless:
        headers = {"content-type": "application/json"}

        async def stream(self):
            nonlocal pulled
            while True:
                pulled += 1
                yield b"x" * 1000

    with pytest.raises(Refused) as e:
        asyncio.run(json_body(Endless(), limit=50_000))
    assert e.value.status == 413
    assert pulled == 51                 # the 51st kB passes the limit; nothing after it is read


def test_only_json_is_taken(served):
    root, _ = served
    r = _client(root).post("/api/save", data={"file": "x.toml", "toml": TEXT})
    assert r.status_code == 415 and not (root / "x.toml").exists()


def test_a_request_to_another_host_name_is_refused(served):
    root, _ = served
    c = _client(root, hosts=["127.0.0.1", "localhost"])
    assert c.get("/api/exercises", headers={"host": "evil.example"}).status_code == 400
    assert c.get("/api/exercises", headers={"host": "127.0.0.1:8765"}).status_code == 200


@pytest.mark.skipif(os.geteuid() == 0, reason="root reads any file")
def test_an_unreadable_file_is_one_line(served):
    root, _ = served
    (root / "mine.toml").chmod(0)
    r = _client(root).get("/api/exercise", params={"file": "mine.toml"})
    assert r.status_code == 422 and "cannot read the file" in r.json()["error"]
