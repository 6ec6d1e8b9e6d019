"""A student's drawing, read safely: the line ends, circles and text labels of an SVG as
Inkscape, GeoGebra, LibreOffice Draw or a CAD program writes it, in millimetres of paper.

Drawings come from students, so nothing in one is trusted. :mod:`.safe_svg` parses it with
no DTD, entities or external resources, bounds it (its size, its elements, what its
``<use>`` would expand to) and cuts it down to the shapes and texts grading reads; only
then does svgelements read the geometry (groups, transforms, ``<use>``, lines, polylines,
paths; a circle's centre is carried through its transform here, as svgelements leaves it
untransformed). A shape or label that lands beyond any paper, or at no finite place, is
left out and said in :attr:`Drawing.notes`: nothing that is not a finite number on a sheet
reaches a grade.
"""

from __future__ import annotations

import io
import math
from dataclasses import dataclass, field
from pathlib import Path

from ...constructions.errors import InputError
from .safe_svg import MARK, MAX_ELEMENTS, MAX_POINTS, Kept, Reduced, readable_count, reduce_svg

__all__ = ["Drawing", "Label", "read_drawing", "parse_drawing", "file_name", "printable",
           "MAX_BYTES", "MAX_ELEMENTS", "MAX_POINTS", "PAPER"]

MAX_BYTES = 5_000_000
"""The largest drawing read (bytes): a page of lines and labels is some kilobytes."""

PAPER = 1e6
"""How far from its origin a drawing's points may lie (mm): a kilometre is beyond any
sheet, so a point past it is a number gone wrong, not a drawing."""

_MM = 25.4 / 96.0
"""Paper mm a CSS pixel: svgelements reads every length in pixels at 96 an inch."""

_LISTED = 3
"""How many elements left out a note names one by one."""


@dataclass(frozen=True)
class Label:
    """A text on the drawing: what it says (tspans joined) and where its anchor stands."""

    text: str
    at: tuple[float, float]


@dataclass
class Drawing:
    """What a drawing holds, in paper mm (y down, as the SVG has it)."""

    segments: list[tuple[tuple[float, float], tuple[float, float]]] = field(
        default_factory=list)
    circles: list[tuple[tuple[float, float], float]] = field(default_factory=list)
    labels: list[Label] = field(default_factory=list)
    source: str = ""
    notes: list[str] = field(default_factory=list)
    """What was left out of the drawing and why, for the grade's notes."""

    def ends(self) -> list[tuple[float, float]]:
        """Every segment's two ends."""
        return [p for s in self.segments for p in s]


def printable(text: str) -> str:
    r"""``text`` as one readable line: bytes that are no UTF-8 (a file name's, kept by Python
    as surrogates) written ``\xff``, control and direction characters ``\n``, ``\u202e``.

    >>> printable("a\nb\udcff\u202e.svg")
    'a\\nb\\xff\\u202e.svg'
    """
    text = text.encode("utf-8", "surrogateescape").decode("utf-8", "backslashreplace")
    return "".join(c if c.isprintable() else c.encode("unicode_escape").decode("ascii")
                   for c in text)


def file_name(path: str | Path) -> str:
    """A file's name as messages, grades and grades.csv give it (:func:`printable`)."""
    return printable(Path(path).name)


def read_drawing(path: str | Path) -> Drawing:
    """Read the drawing at ``path``.

    Raises
    ------
    InputError
        Naming the file (and the line where there is one): not an SVG, empty, too big,
        too many elements, or carrying a DTD, an entity or an external reference.
    """
    path = Path(path)
    name = file_name(path)
    try:
        if not path.is_file():                # a pipe or a device would be read forever
            raise InputError("not a file (a folder, a pipe or a device); give an SVG "
                             "drawing", file=name)
        size = path.stat().st_size
        if size > MAX_BYTES:
            raise InputError(f"{readable_count(size)} bytes is more than a drawing holds "
                             f"(at most {readable_count(MAX_BYTES)})", file=name)
        data = path.read_bytes()
    except OSError as e:
        raise InputError(f"cannot be read ({e.strerror or e})", file=name) from None
    return parse_drawing(data, name)


def parse_drawing(data: bytes, name: str = "drawing.svg") -> Drawing:
    """Read an SVG drawing from its bytes (see :func:`read_drawing`)."""
    if not data.strip():
        raise InputError("the file is empty; give an SVG drawing", file=name)
    if len(data) > MAX_BYTES:
        raise InputError(f"{readable_count(len(data))} bytes is more than a drawing holds "
                         f"(at most {readable_count(MAX_BYTES)})", file=name)
    reduced = reduce_svg(data, name)
    out = _geometry(reduced, name)
    left_out = reduced.notes + out.notes
    out.notes = []
    if left_out:
        more = len(left_out) - _LISTED
        out.notes.append(f"left out {len(left_out)} element{'s' * (len(left_out) > 1)}: "
                         + "; ".join(left_out[:_LISTED])
                         + (f"; and {more} more" if more > 0 else ""))
    return out


def _geometry(reduced: Reduced, name: str) -> Drawing:
    """The segments, circles and labels svgelements finds in the reduced tree, transforms
    applied, in mm; a shape or label at no finite place on a sheet is left out, noted."""
    from svgelements import SVG, Circle, Close, Move, Path, Shape, SVGText

    out = Drawing(source=name)
    runs: list = []                          # a text's tspans, which svgelements gives first
    try:
        elements = list(SVG.parse(io.BytesIO(reduced.data), ppi=96.0).elements())
    except (ValueError, ArithmeticError):
        raise InputError("the SVG's shapes cannot be read: a number in them is out of "
                         "range", file=name) from None

    def kept(e) -> Kept:
        return reduced.kept[int(e.values.get(MARK, 0))]

    def placed(*xy: float) -> bool:
        return all(math.isfinite(v) and abs(v) <= PAPER for v in xy)
    for e in elements:
        if isinstance(e, SVGText):
            if e.values.get("tag") == "tspan":
                runs.append(e)
                continue
            text = kept(e).words.strip()
            where = runs[-1] if runs and not (e.x or e.y) else e
            runs = []
            if text:
                x, y = where.x, where.y
                if where.transform is not None:
                    x, y = where.transform.point_in_matrix_space((x, y))
                if placed(x * _MM, y * _MM):
                    out.labels.append(Label(text, (x * _MM, y * _MM)))
                else:
                    out.notes.append(f"{kept(e).where()} (its place is beyond any paper)")
        elif isinstance(e, Circle):
            # svgelements keeps a circle's centre as written: carry it through its transform.
            c = e.transform.point_in_matrix_space((e.cx, e.cy)) if e.transform else (e.cx, e.cy)
            r = abs(float(e.implicit_rx if hasattr(e, "implicit_rx") else e.rx)) * _MM
            if placed(c[0] * _MM, c[1] * _MM, r):
                out.circles.append(((c[0] * _MM, c[1] * _MM), r))
            else:
                out.notes.append(f"{kept(e).where()} (it lies beyond any paper)")
        elif isinstance(e, Shape):          # lines, polylines, paths, rectangles, polygons
            path = e if isinstance(e, Path) else Path(e)
            path.reify()
            found = []
            for seg in path:                 # as many as safe_svg counted, MAX_POINTS at most
                if isinstance(seg, Move) or seg.start is None or seg.end is None or \
                        isinstance(seg, Close) and seg.start == seg.end:
                    continue
                found.append(((seg.start.x * _MM, seg.start.y * _MM),
                              (seg.end.x * _MM, seg.end.y * _MM)))
            if all(placed(*a, *b) for a, b in found):
                out.segments += [(a, b) for a, b in found if a != b]
            else:
                out.notes.append(f"{kept(e).where()} (it runs beyond any paper)")
    return out
