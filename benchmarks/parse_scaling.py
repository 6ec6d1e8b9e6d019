"""Reading a mechanism file against its size: linear, and refused past its limits.

Run:  python benchmarks/parse_scaling.py

A four-bar is given N extra frame points (N from 1,000 to 32,000, every file under
:data:`MOST_BYTES`), and ``tarsim.load`` reads it and refuses it for naming more than
:data:`MOST_POINTS` points. The time to reach that refusal is the time to parse: it
should double as N doubles (the ratio column near 2), where a quadratic reader gives 4.
A file over :data:`MOST_BYTES` is refused before it is parsed, at a fixed cost.
Medians of 5 runs in one process.
"""

from __future__ import annotations

import platform
import statistics
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

import tarsim  # noqa: E402
from tarsim.constructions.errors import InputError  # noqa: E402
from tarsim.exercises.linkages.mechanism_file import MOST_POINTS  # noqa: E402
from tarsim.exercises.toml_source import MOST_BYTES  # noqa: E402
from tests.common import four_bar_toml  # noqa: E402


def with_points(n: int) -> str:
    """The bundled four-bar with ``n`` more frame points."""
    extra = "".join(f"P{i} = [{i}, {i % 7}]\n" for i in range(n))
    return four_bar_toml().replace("O4 = [300, 0]\n", "O4 = [300, 0]\n" + extra)


def refusal_time(path: Path, repeat: int = 5) -> tuple[float, str]:
    """Median seconds for ``tarsim.load`` to refuse ``path``, and its message."""
    times, said = [], ""
    for _ in range(repeat):
        t0 = time.perf_counter()
        try:
            tarsim.load(path)
        except InputError as e:
            said = str(e)
        times.append(time.perf_counter() - t0)
    return statistics.median(times), said


def main() -> None:
    """Print the table: points, bytes, median seconds to the refusal, ratio to the last."""
    print(f"{platform.machine()}, {platform.system()}, Python {platform.python_version()}; "
          f"limits {MOST_POINTS} points, {MOST_BYTES:,} bytes")
    print(f"{'points':>8} {'bytes':>10} {'seconds':>9} {'ratio':>6}")
    with tempfile.TemporaryDirectory() as tmp:
        last = None
        for n in (1000, 2000, 4000, 8000, 16000, 32000):
            path = Path(tmp) / f"p{n}.toml"
            path.write_text(with_points(n), encoding="utf-8")
            seconds, said = refusal_time(path)
            ratio = f"{seconds / last:.2f}" if last else ""
            print(f"{n:>8} {path.stat().st_size:>10,} {seconds:>9.4f} {ratio:>6}")
            last = seconds
        big = Path(tmp) / "big.toml"
        big.write_text(with_points(60000), encoding="utf-8")
        seconds, said = refusal_time(big)
        print(f"{'60000':>8} {big.stat().st_size:>10,} {seconds:>9.4f}  (over the byte limit)")
        print(f"refused: {said.replace(tmp, '…')}")


if __name__ == "__main__":
    main()
