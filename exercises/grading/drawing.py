"""A student's drawing, read safely: the line ends, circles and text labels of an SVG as
Inkscape, GeoGebra, LibreOffice Draw or a CAD program writes it, in millimetres of paper.

Drawings come from students, so nothing in one is trusted: the XML is parsed by defusedxml
first (no DTD, no entities, no external resources), the file's size and element count are
capped, and only then does svgelements read the geometry (groups, transforms, ``<use>``,
lines, polylines, paths; a circle's centre is carried through its transform here, as
svgelements leaves it untransformed).
"""

from __future__ import annotations

import io
import math
import re
from dataclasses import dataclass, field
from pathlib import Path

from ...constructions.errors import InputError

__all__ = ["Drawing", "Label", "read_drawing", "MAX_BYTES", "MAX_ELEMENTS"]

MAX_BYTES = 5_000_000
"""The largest drawing read (bytes): a page of lines and labels is some kilobytes."""

MAX_ELEMENTS = 20_000
"""The most elements a drawing may hold: far past any hand-made polygon."""

MAX_POINTS = 200_000
"""The most path points a drawing may hold, all its paths together."""

MAX_PATH_CHARS = 1_000_000
"""The longest its paths' data may run, all together (characters), checked before any
geometry is read."""

_MM = 25.4 / 96.0
"""Paper mm a CSS pixel: svgelements reads every length in pixels at 96 an inch."""


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

    def ends(self) -> list[tuple[float, float]]:
        """Every segment's two ends."""
        return [p for s in self.segments for p in s]


def read_drawing(path: str | Path) -> Drawing:
    """Read the drawing at ``path``.

    Raises
    ------
    InputError
        Naming the file: not an SVG, empty, too big, too many elements, or carrying a DTD,
        an entity or an external reference.
    """
    path = Path(path)
    name = path.name
    try:
        size = path.stat().st_size
        if size > MAX_BYTES:
            raise InputError(f"{name}: {size:,} bytes is more than a drawing holds (at most "
                             f"{MAX_BYTES:,})")
        data = path.read_bytes()
    except OSError as e:
        raise InputError(f"{name}: cannot be read ({e.strerror or e})") from None
    return parse_drawing(data, name)


def parse_drawing(data: bytes, name: str = "drawing.svg") -> Drawing:
    """Read an SVG drawing from its bytes (see :func:`read_drawing`)."""
    import defusedxml.ElementTree as safe
    from defusedxml import DefusedXmlException

    if not data.strip():
        raise InputError(f"{name}: the file is empty; give an SVG drawing")
    if len(data) > MAX_BYTES:
        raise InputError(f"{name}: {len(data):,} bytes is more than a drawing holds")
    try:
        root = safe.fromstring(data, forbid_dtd=True, forbid_entities=True,
                               forbid_external=True)
    except DefusedXmlException:
        raise InputError(f"{name}: the SVG declares a DTD, entities or external resources, "
                         "which a drawing never needs; export it again as plain SVG") from None
    except Exception:                       # any XML fault: one line, not its traceback
        raise InputError(f"{name}: not an SVG drawing (its XML cannot be read)") from None
    if not root.tag.endswith("svg"):
        raise InputError(f"{name}: not an SVG drawing (its root is <{_local(root.tag)}>)")
    count = sum(1 for _ in root.iter())
    if count > MAX_ELEMENTS:
        raise InputError(f"{name}: {count:,} elements are more than a drawing holds (at most "
                         f"{MAX_ELEMENTS:,})")
    path_chars = sum(len(e.get("d", "")) + len(e.get("points", "")) for e in root.iter())
    if path_chars > MAX_PATH_CHARS:
        raise InputError(f"{name}: its paths run to {path_chars:,} characters, more than a "
                         f"drawing holds (at most {MAX_PATH_CHARS:,})")
    if re.search(rb"(?:xlink:)?href\s*=\s*[\"'](?!#)", data):
        raise InputError(f"{name}: the SVG links to outside resources; a drawing must hold "
                         "all it shows")
    # The words of each <text>, its tspans in document order (svgelements gives a text's
    # tspans one by one, innermost first).
    words = ["".join(t.itertext()) for t in root.iter() if _local(t.tag) == "text"]
    return _geometry(data, name, words)


def _geometry(data: bytes, name: str, words: list[str]) -> Drawing:
    """The segments, circles and labels svgelements finds, transforms applied, in mm; each
    label says what ``words`` has for its <text>, in order."""
    from svgelements import SVG, Circle, Close, Move, Path, Shape, SVGText

    out = Drawing(source=name)
    points = 0
    runs: list = []                          # a text's tspans, which svgelements gives first
    texts = iter(words)
    try:
        svg = SVG.parse(io.BytesIO(data), ppi=96.0)
        elements = list(svg.elements())
    except Exception:
        raise InputError(f"{name}: the SVG's shapes cannot be read") from None
    for e in elements:
        if isinstance(e, SVGText):
            if e.values.get("tag") == "tspan":
                runs.append(e)
                continue
            text = next(texts, "").strip()
            where = runs[-1] if runs and not (e.x or e.y) else e
            runs = []
            if text:
                x, y = where.x, where.y
                if where.transform is not None:
                    x, y = where.transform.point_in_matrix_space((x, y))
                out.labels.append(Label(text, (x * _MM, y * _MM)))
        elif isinstance(e, Circle):
            # svgelements keeps a circle's centre as written: carry it through its transform.
            c = e.transform.point_in_matrix_space((e.cx, e.cy)) if e.transform else (e.cx, e.cy)
            r = e.implicit_rx if hasattr(e, "implicit_rx") else e.rx
            out.circles.append(((c[0] * _MM, c[1] * _MM), abs(float(r)) * _MM))
        elif isinstance(e, Shape):          # lines, polylines, paths, rectangles, polygons
            path = e if isinstance(e, Path) else Path(e)
            path.reify()
            for seg in path:
                points += 1
                if points > MAX_POINTS:
                    raise InputError(f"{name}: its paths hold more than {MAX_POINTS:,} "
                                     "points, more than a drawing needs")
                if isinstance(seg, Move) or seg.start is None or seg.end is None or \
                        isinstance(seg, Close) and seg.start == seg.end:
                    continue
                a, b = (seg.start.x * _MM, seg.start.y * _MM), (seg.end.x * _MM,
                                                                 seg.end.y * _MM)
                if all(math.isfinite(v) for v in (*a, *b)) and a != b:
                    out.segments.append((a, b))
    return out


def _local(tag: str) -> str:
    return tag.rsplit("}", 1)[-1]
