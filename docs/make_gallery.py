"""Make docs/gallery/: a PNG of each bundled exercise's main figure.

Run:  python docs/make_gallery.py

The main figure is the worked page when the exercise asks for the polygons, else its first
velocity construction, its instant centres, its limit positions or the mechanism itself:
the figure that shows most of what the exercise is about. Each PNG is 1000 pixels wide at
most, on white. Needs libcairo2 (cairosvg).
"""

from __future__ import annotations

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

import cairosvg  # noqa: E402

import tarsim  # noqa: E402
from tarsim.exercises.catalog import everything  # noqa: E402
from tarsim.graphics.svg import to_svg  # noqa: E402

GALLERY = Path(__file__).resolve().parent / "gallery"
WIDTH = 1000
"""Pixels across a PNG, at most: enough to read the labels, small enough to keep."""

ORDER = ("klein", "worked", "V_", "centres", "limits", "mechanism", "loads", "mesh", "kutzbach",
         "force-polygon", "table", "train-value", "profile", "primary-force", "forces")
"""The kinds of figure in the order one is taken as an exercise's main figure."""


def main_figure(figures: dict):
    """The figure to show for a solution (see :data:`ORDER`): its stem and the figure."""
    for start in ORDER:
        found = [stem for stem in figures if stem.startswith(start)]
        if found:
            return found[0], figures[found[0]]
    return next(iter(figures.items()))


def main() -> None:
    """Solve every bundled exercise and write its main figure as docs/gallery/<id>.png."""
    GALLERY.mkdir(exist_ok=True)
    for name in everything():
        stem, figure = main_figure(tarsim.solve(tarsim.load(name)).figures)
        svg = to_svg(figure)
        width_mm = figure.width
        # 96 px an inch; a page narrower than WIDTH pixels keeps its true size.
        width = min(WIDTH, round(width_mm / 25.4 * 96 * 1.5))
        out = GALLERY / f"{name}.png"
        cairosvg.svg2png(bytestring=svg.encode("utf-8"), write_to=str(out), output_width=width,
                         background_color="white")
        print(f"{out.relative_to(GALLERY.parent.parent)}  ({stem}, {width} px)")


if __name__ == "__main__":
    main()
