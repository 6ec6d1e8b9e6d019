"""Make docs/gallery/: a PNG of the main figure of a few bundled exercises, and of the
problem sheet of some of them beside their solution.

Run:  python docs/make_gallery.py

The main figure is the worked page when the exercise asks for the polygons, else its first
velocity construction, its instant centres, its limit positions or the mechanism itself:
the figure that shows most of what the exercise is about. A problem sheet is the first
sheet `tarsim handout` writes. Each PNG is 1000 pixels wide at most, on white. The
catalog (docs/make_catalog.py) has a thumbnail of every bundled exercise; the gallery
shows these few large. Needs libcairo2 (cairosvg).
"""

from __future__ import annotations

import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

import cairosvg  # noqa: E402
from click.testing import CliRunner  # noqa: E402

import tarsim  # noqa: E402
from tarsim.exercises.cli import cli  # noqa: E402
from tarsim.graphics.svg import to_svg  # noqa: E402

GALLERY = Path(__file__).resolve().parent / "gallery"
WIDTH = 1000
"""Pixels across a PNG, at most: enough to read the labels, small enough to keep."""

SHOWN = ("four-bar", "whitworth", "six-link-homework-3", "crank-shaper-forces", "planetary-q4",
         "involute-pair", "inline-four", "roller-harmonic-cycloidal", "crank-shaper",
         "punching-press")
"""The exercises whose main figure the gallery shows, a chapter's best or two."""

SHEETS = ("four-bar", "crank-shaper", "planetary-q1", "punching-press")
"""The exercises whose problem sheet stands beside their solution."""

ORDER = ("klein", "worked", "V_", "centres", "limits", "mechanism", "loads", "mesh", "kutzbach",
         "force-polygon", "forces", "table", "train-value", "profile", "primary-force")
"""The kinds of figure in the order one is taken as an exercise's main figure."""


def main_figure(figures: dict):
    """The figure to show for a solution (see :data:`ORDER`): its stem and the figure."""
    for start in ORDER:
        found = [stem for stem in figures if stem.startswith(start)]
        if found:
            return found[0], figures[found[0]]
    return next(iter(figures.items()))


def _png(svg: str, width_mm: float, out: Path) -> None:
    # 96 px an inch; a page narrower than WIDTH pixels keeps its true size.
    width = min(WIDTH, round(width_mm / 25.4 * 96 * 1.5))
    cairosvg.svg2png(bytestring=svg.encode("utf-8"), write_to=str(out), output_width=width,
                     background_color="white")
    print(f"{out.relative_to(GALLERY.parent.parent)}  ({width} px)")


def main() -> None:
    """Write each shown exercise's main figure as docs/gallery/<id>.png, and each problem
    sheet as docs/gallery/<id>-handout.png."""
    GALLERY.mkdir(exist_ok=True)
    for name in SHOWN:
        stem, figure = main_figure(tarsim.solve(tarsim.load(name)).figures)
        sheet = (figure.sheets or [figure])[0]
        _png(to_svg(sheet), sheet.width, GALLERY / f"{name}.png")
    for name in SHEETS:
        with tempfile.TemporaryDirectory() as tmp:
            done = CliRunner().invoke(cli, ["handout", name, "-o", tmp, "--no-pdf"])
            if done.exit_code:
                sys.exit(f"tarsim handout {name}: {done.output}")
            svg = (Path(tmp) / "handout.svg").read_text(encoding="utf-8")
        first = _first_sheet(svg)
        _png(first[0], first[1], GALLERY / f"{name}-handout.png")


def _first_sheet(svg: str) -> tuple[str, float]:
    """The first sheet of a handout's SVG (its sheets stand one under another) and its
    width in mm: the SVG's view box cut to the first sheet's height."""
    import re

    width = float(re.search(r'width="([\d.]+)mm"', svg)[1])
    height = 297.0 if width < 250 else 210.0         # A4, upright or on its side
    svg = re.sub(r'height="[\d.]+mm"', f'height="{height:g}mm"', svg, count=1)
    svg = re.sub(r'viewBox="0 0 ([\d.]+) [\d.]+"', rf'viewBox="0 0 \1 {height:g}"', svg,
                 count=1)
    return svg, width


if __name__ == "__main__":
    main()
