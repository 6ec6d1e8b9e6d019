"""How long tarsim serve takes to answer /api/solve for each bundled linkage.

Run:  python benchmarks/serve_speed.py [--repeat 7] [--figures]

Each request goes through the app as a browser's would (starlette's test client: the
route, the JSON body read and written, the solve in a worker thread), after one warm-up
request of its own. Each column is in ms, medians of ``--repeat``, as wall time and as the
process's CPU time (on a machine shared with other work, the CPU time is what the request
itself costs; the wall time adds the waiting for a core):

* ``figures false``: the numbers, results.json and the table, as the page asks while the
  input turns or a length changes;
* ``and whole false``: the same without what is asked of the mechanism as a whole (DOF,
  Grashof class, time ratio, stroke), which turning the input does not change;
* with ``--figures``, ``figures true``: the worked solution whole, every figure and steps.

The machine and its load are printed first.
"""

from __future__ import annotations

import argparse
import statistics
import sys
import tempfile
import time
import warnings
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from benchmarks.speed import machine  # noqa: E402
from tarsim.exercises.catalog import bundled  # noqa: E402
from tarsim.exercises.serve import make_app  # noqa: E402

with warnings.catch_warnings():          # starlette would rather have httpx2; httpx serves
    warnings.simplefilter("ignore")
    from starlette.testclient import TestClient  # noqa: E402


def _median_ms(client: TestClient, body: dict, repeat: int) -> tuple[float, float]:
    """The median wall and CPU milliseconds of answering ``body``."""
    assert client.post("/api/solve", json=body).status_code == 200     # the warm-up
    wall, cpu = [], []
    for _ in range(repeat):
        t, c = time.perf_counter(), time.process_time()
        r = client.post("/api/solve", json=body)
        wall.append(time.perf_counter() - t)
        cpu.append(time.process_time() - c)
        assert r.status_code == 200, r.text
    return 1000 * statistics.median(wall), 1000 * statistics.median(cpu)


def main(argv: list[str] | None = None) -> None:
    """Print each bundled linkage's answer times and the slowest of each column."""
    args = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    args.add_argument("--repeat", type=int, default=7)
    args.add_argument("--figures", action="store_true", help="also time the whole solution")
    a = args.parse_args(argv)
    print(machine(a.repeat))
    columns = ["figures false", "and whole false"] + (["figures true"] if a.figures else [])
    print(f"{'':28}" + "".join(f"{c:>18}" for c in columns))
    print(f"{'exercise':28}" + f"{'wall':>10}{'cpu':>8}" * len(columns))
    worst = [(0.0, 0.0)] * len(columns)
    with tempfile.TemporaryDirectory() as tmp, TestClient(make_app(tmp)) as client:
        for key, path in bundled().items():
            base = {"toml": path.read_text(encoding="utf-8"), "id": key}
            asks = [{**base, "figures": False}, {**base, "figures": False, "whole": False}]
            asks += [base] if a.figures else []
            ms = [_median_ms(client, body, a.repeat) for body in asks]
            worst = [(max(w[0], m[0]), max(w[1], m[1])) for w, m in zip(worst, ms)]
            print(f"{key:28}" + "".join(f"{w:10.1f}{c:8.1f}" for w, c in ms))
    print(f"{'slowest':28}" + "".join(f"{w:10.1f}{c:8.1f}" for w, c in worst))

if __name__ == "__main__":
    main()
