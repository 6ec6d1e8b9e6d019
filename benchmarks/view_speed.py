"""How big the interactive page is, how long it takes to make and to open, and how long
one redraw takes in the browser while the crank is dragged.

Run:  python benchmarks/view_speed.py [--exercise crank-shaper] [--repeat 3]

The page is the crank-shaper's with both polygons, its centres and 720 frames (0.5°).
Opened from disk in Debian's chromium (headless, driven by playwright, 1400 × 1000):
the time to its first drawing, then every frame shown in turn as a drag would show them:
each redraw timed by the page itself (performance.now around its draw), and the time from
one painted frame to the next when each is asked for on an animation frame, which takes
in the browser's own layout and painting. Medians of
``--repeat`` runs; the machine and its load are printed first.
"""

from __future__ import annotations

import argparse
import statistics
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

import tarsim  # noqa: E402
from benchmarks.speed import machine  # noqa: E402
from tarsim.exercises.linkages.view import view_data  # noqa: E402
from tarsim.graphics.view_page import view_html  # noqa: E402
from tests.browser import chromium  # noqa: E402


def main(argv: list[str] | None = None) -> None:
    """Print the page's size, its making and opening times and its redraw times."""
    args = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    args.add_argument("--exercise", default="crank-shaper")
    args.add_argument("--repeat", type=int, default=3)
    a = args.parse_args(argv)
    print(machine(a.repeat))
    ex = tarsim.load(a.exercise)
    made, opened, redraws, painted = [], [], [], []
    for _ in range(a.repeat):
        t = time.perf_counter()
        html = view_html(view_data(ex))
        made.append(time.perf_counter() - t)
    with tempfile.TemporaryDirectory() as tmp, chromium() as browser:
        path = Path(tmp) / "page.html"
        path.write_text(html, encoding="utf-8")
        for _ in range(a.repeat):
            page = browser.new_page(viewport={"width": 1400, "height": 1000})
            t = time.perf_counter()
            page.goto(path.as_uri())
            page.wait_for_function("window.tarsimView !== undefined")
            opened.append(time.perf_counter() - t)
            n = page.evaluate("tarsimView.data.frames.length")
            page.evaluate(f"for (let k = 0; k < {n}; k++) tarsimView.setFrame(k)")
            redraws += page.evaluate("tarsimView.frameTimes()")[1:]
            painted += page.evaluate(_PAINTED, n)
            page.close()
    ms = sorted(redraws)
    gaps = sorted(painted)
    print(f"page: {len(html.encode()) / 1e6:.2f} MB, {n} frames")
    print(f"made in {statistics.median(made):.2f} s (median of {a.repeat})")
    print(f"opened, to its first drawing, in {1000 * statistics.median(opened):.0f} ms")
    print(f"one redraw: median {statistics.median(ms):.2f} ms, 95th percentile "
          f"{ms[int(0.95 * len(ms))]:.2f} ms, worst {ms[-1]:.2f} ms over {len(ms)} redraws "
          f"(a 60 fps frame is 16.7 ms)")
    print(f"frame to frame, painted (one frame a requestAnimationFrame, as a drag shows them):"
          f" median {statistics.median(gaps):.1f} ms, 95th percentile "
          f"{gaps[int(0.95 * len(gaps))]:.1f} ms: "
          f"{1000 / statistics.median(gaps):.0f} frames a second")


_PAINTED = """n => new Promise(done => {
  const gaps = []; let k = 0, last = null;
  function tick(t) {
    if (last !== null) gaps.push(t - last);
    last = t;
    tarsimView.setFrame(k++);
    if (k < n) requestAnimationFrame(tick); else done(gaps);
  }
  requestAnimationFrame(tick);
})"""


if __name__ == "__main__":
    main()
