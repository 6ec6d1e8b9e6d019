"""``tarsim serve`` on the command line: it serves, says where, and fails in one line."""

from __future__ import annotations

import json
import os
import socket
import subprocess
import sys
import time
import urllib.request

import pytest
from click.testing import CliRunner

from tarsim.exercises.cli import cli

pytest.importorskip("starlette")
pytest.importorskip("uvicorn")


def _invoke(*args: str):
    return CliRunner().invoke(cli, list(args), prog_name="tarsim")


@pytest.mark.slow
def test_serve_no_browser_serves_the_folder(tmp_path):
    (tmp_path / "mine.toml").write_text('name = "mine"\n', encoding="utf-8")
    proc = subprocess.Popen(
        [sys.executable, "-m", "tarsim", "serve", str(tmp_path), "--port", "0", "--no-browser"],
        stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
        env={**os.environ, "BROWSER": "false"})
    try:
        line = proc.stdout.readline()         # printed once the socket listens
        assert line.startswith("tarsim serve: http://127.0.0.1:"), (line, proc.stderr.read())
        url = line.split()[2]
        for _ in range(100):                  # the server takes the socket in a moment
            try:
                with urllib.request.urlopen(url + "api/exercises", timeout=10) as r:
                    got = json.loads(r.read())
                break
            except OSError:
                time.sleep(0.1)
        else:
            pytest.fail("tarsim serve never answered")
        assert got["files"] == ["mine.toml"]
        assert "four-bar" in {e["id"] for e in got["bundled"]}
    finally:
        proc.terminate()
        proc.wait(timeout=20)


def test_without_the_extra_serve_says_what_to_install(monkeypatch):
    monkeypatch.setitem(sys.modules, "uvicorn", None)         # as if not installed
    r = _invoke("serve", "--no-browser")
    assert r.exit_code == 1
    assert r.output == "Error: tarsim serve needs the serve extra: pip install 'tarsim[serve]'\n"


def test_a_port_in_use_is_one_line():
    with socket.socket() as taken:
        taken.bind(("127.0.0.1", 0))
        taken.listen(1)
        port = taken.getsockname()[1]
        r = _invoke("serve", "--no-browser", "--port", str(port))
    assert r.exit_code == 1 and r.output.count("\n") == 1
    assert r.output.startswith(f"Error: cannot listen on 127.0.0.1:{port}: ")
    assert "choose another --port" in r.output


def test_a_folder_that_is_not_there_is_a_usage_error(tmp_path):
    r = _invoke("serve", str(tmp_path / "nowhere"), "--no-browser")
    assert r.exit_code == 2 and "does not exist" in r.output


def test_listening_beyond_this_machine_is_warned_of_in_one_line():
    with socket.socket() as taken:
        taken.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
        taken.bind(("0.0.0.0", 0))
        taken.listen(1)
        port = taken.getsockname()[1]
        r = _invoke("serve", "--no-browser", "--host", "0.0.0.0", "--port", str(port))
    warning, error = r.output.splitlines()
    assert warning.startswith("warning: listening on 0.0.0.0: anyone who can reach this "
                              "machine can open the app")
    assert error.startswith(f"Error: cannot listen on 0.0.0.0:{port}")
