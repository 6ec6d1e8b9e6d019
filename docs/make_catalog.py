"""Write docs/catalog.md: every bundled exercise, where it comes from, what it asks, and a
thumbnail of its main figure (docs/catalog/<id>.png).

Run:  python docs/make_catalog.py              # the page and every thumbnail
      python docs/make_catalog.py --page-only  # the page alone (the thumbnails kept)

The main figure is the one docs/make_gallery.py chooses. Needs libcairo2 for the PNGs.
"""

from __future__ import annotations

import sys
from pathlib import Path

DOCS = Path(__file__).resolve().parent
PAGE = DOCS / "catalog.md"
THUMBS = DOCS / "catalog"
WIDTH = 480
"""Pixels across a thumbnail: enough to tell the figure, small enough for 80 on a page."""

CHAPTERS = {"linkages": "Linkages", "forces": "Forces and the flywheel",
            "gears": "Gear trains", "cams": "Cams", "balancing": "Balancing"}
"""Each chapter's heading, by its key (exercises/chapters.py), in the course's order."""


def page() -> str:
    """The page's text: a section a chapter, an entry an exercise, in `tarsim list`'s order."""
    from tarsim.exercises.catalog import everything
    from tarsim.exercises.chapters import _parsed, chapter_for, listing

    found = everything()
    by_chapter: dict[str, list[str]] = {key: [] for key in CHAPTERS}
    for name, path in found.items():
        by_chapter[chapter_for(_parsed(Path(path))[1]).key].append(name)
    lines = ["# Catalog", "",
             f"The {len(found)} exercises that come with tarsim. Give an id wherever a command "
             "takes FILE (`tarsim solve four-bar`); `tarsim list` prints this list, and the "
             "files themselves are in the package's `exercises/catalog/` folder, a start for "
             "your own.", ""]
    lines += [f"- [{CHAPTERS[key]}](#{key}) ({len(names)})" for key, names in by_chapter.items()]
    for key, names in by_chapter.items():
        lines += ["", f"## {CHAPTERS[key]} {{ #{key} }}", ""]
        for name in names:
            lines += _entry(name, found[name], listing)
    return "\n".join(lines) + "\n"


def _entry(name: str, path, listing) -> list[str]:
    """One exercise's lines: its id, title, thumbnail, source and asks."""
    shown = listing(path, name)
    lines = [f"### `{name}`", "", f"**{shown.title}**", ""]
    if (THUMBS / f"{name}.png").exists():
        lines += [f"![{shown.title}](catalog/{name}.png){{ width=\"{WIDTH}\" }}", ""]
    if shown.origin:
        lines += [f"From {shown.origin}.", ""]
    lines += [f"Asks: {shown.asks}.", ""]
    return lines


def thumbnails() -> None:
    """Solve each bundled exercise and write its main figure's thumbnail."""
    import cairosvg

    import tarsim
    from tarsim.exercises.catalog import everything
    from tarsim.graphics.svg import to_svg

    sys.path.insert(0, str(DOCS))
    from make_gallery import main_figure

    THUMBS.mkdir(exist_ok=True)
    for i, name in enumerate(everything(), 1):
        stem, figure = main_figure(tarsim.solve(tarsim.load(name)).figures)
        cairosvg.svg2png(bytestring=to_svg(figure).encode("utf-8"),
                         write_to=str(THUMBS / f"{name}.png"), output_width=WIDTH,
                         background_color="white")
        print(f"[{i}] {name}: {stem}", file=sys.stderr)


def main() -> None:
    """Write the thumbnails (unless --page-only), then the page."""
    if "--page-only" not in sys.argv:
        thumbnails()
    PAGE.write_text(page(), encoding="utf-8")
    print(f"wrote {PAGE}")


if __name__ == "__main__":
    main()
