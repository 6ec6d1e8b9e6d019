"""A student's drawing, read safely: the strokes, circles and text labels of an SVG as
Inkscape, GeoGebra, LibreOffice Draw or a CAD program writes it (or gzip-compressed, as
``.svgz``), in millimetres of paper.

Drawings come from students, so nothing in one is trusted. :mod:`.safe_svg` parses it with
no entities or external resources, bounds it (its size, its elements, what its ``<use>``
would expand to) and cuts it down to the shapes and texts grading reads; only then does
svgelements read the geometry (groups, transforms, ``<use>``, lines, polylines, paths; a
circle's centre is carried through its transform here, as svgelements leaves it
untransformed). A compressed file is unpacked no further than :data:`MAX_BYTES`. A shape or
label that lands beyond any paper, or at no finite place, is left out and said in
:attr:`Drawing.notes`: nothing that is not a finite number on a sheet reaches a grade.

**Labels.** A label is where its first letter stands (a text anchored at its middle or
end is moved back by about half or all its width), with that letter's size. A subscript
or a prime written as a text of its own beside its letter (as GeoGebra writes ``a_4``, or a
student types it) joins the letter's label as written, ``a`` ``4`` ``′`` reading ``a4′``:
a text that starts within :data:`NEAR_END` of a label's end (:data:`NEAR_END_SMALLER` if
smaller) and is either smaller than it or set lower by less than a line (:func:`follows`),
one subscript to a label (a link's number, or a pole's v or a), primes before or after it.
A number standing apart (a centre's ``13``, a step's number) stays a label of its own, and
so does a number in a ring (:func:`ringed`, a step's number as a worked figure circles
it), however near a label's end it stands.
"""

from __future__ import annotations

import bisect
import io
import math
import re
import zlib
from dataclasses import dataclass, field
from pathlib import Path

from tarsim.constructions.errors import InputError
from .labels import step_number
from .safe_svg import MARK, MAX_ELEMENTS, MAX_POINTS, Kept, Reduced, readable_count, reduce_svg
from .svg_style import MEDIUM

__all__ = ["Drawing", "Label", "Outline", "read_drawing", "parse_drawing", "file_name",
           "printable", "follows", "advance", "MAX_BYTES", "MAX_ELEMENTS", "MAX_POINTS", "PAPER",
           "LETTER", "NEAR_END", "NEAR_END_SMALLER", "SHIFT", "SMALLER", "PRIMES", "RING",
           "ringed"]

MAX_BYTES = 5_000_000
"""The largest drawing read (bytes), compressed or unpacked: a page of lines and labels is
some kilobytes."""

PAPER = 1e6
"""How far from its origin a drawing's points may lie (mm): a kilometre is beyond any
sheet, so a point past it is a number gone wrong, not a drawing."""

_MM = 25.4 / 96.0
"""Paper mm a CSS pixel: svgelements reads every length in pixels at 96 an inch."""

LETTER = MEDIUM * _MM
"""The size of a letter whose size is not said (SVG's ``medium``, 16 px), in mm."""

_LISTED = 3
"""How many elements left out a note names one by one."""

Vec = tuple[float, float]


@dataclass(frozen=True)
class Label:
    """A text on the drawing: what it says (tspans, and a subscript or prime set beside it,
    joined), where its first letter's baseline starts, and that letter's font size (mm)."""

    text: str
    at: Vec
    size: float = LETTER

    def width(self) -> float:
        """About how wide its letters run (mm), by a sans-serif's advances."""
        return advance(self.text) * self.size


@dataclass(frozen=True)
class Outline:
    """One stroke as drawn (a line, a polyline, or one subpath of a path): its corners in
    order (mm), whether it closes on itself, whether any part of it curves (its corners
    are then where its curves join), and whether a marker (an arrowhead) stands at its
    start and at its end."""

    corners: tuple[Vec, ...]
    closed: bool = False
    curved: bool = False
    marked: tuple[bool, bool] = (False, False)


@dataclass
class Drawing:
    """What a drawing holds, in paper mm (y down, as the SVG has it)."""

    segments: list[tuple[Vec, Vec]] = field(default_factory=list)
    """Every straight piece of every stroke (a curve by its chord)."""
    circles: list[tuple[Vec, float]] = field(default_factory=list)
    labels: list[Label] = field(default_factory=list)
    source: str = ""
    notes: list[str] = field(default_factory=list)
    """What was left out of the drawing and why, for the grade's notes."""
    outlines: list[Outline] = field(default_factory=list)
    """The strokes the segments are pieces of, each subpath apart: which close (a polygon,
    an arrowhead, a slider block), which curve, which carry an arrowhead marker."""

    def ends(self) -> list[Vec]:
        """Every segment's two ends."""
        return [p for s in self.segments for p in s]


# ----- how wide letters run ------------------------------------------------------------------
_WIDTHS = {0.19: "'", 0.22: "ijl’′ʹ", 0.28: "ftI ,.:;/", 0.33: "r()-", 0.5: "cksvxyzJ",
           0.61: "FTZ", 0.67: "ABEKPSVXY", 0.72: "wCDHNRU", 0.78: "GOQ", 0.83: "mM",
           0.94: "W", 0.4: "₀₁₂₃₄₅₆₇₈₉″"}
_WIDTH = {c: w for w, cs in _WIDTHS.items() for c in cs}


def advance(text: str) -> float:
    """About how far ``text`` advances, in ems (Helvetica's widths; 0.556 for the rest).

    >>> round(advance("I13"), 3), round(advance("a′"), 3)
    (1.392, 0.776)
    """
    return sum(_WIDTH.get(c, 0.556) for c in text)


# ----- a subscript or prime beside its letter --------------------------------------------------
NEAR_END = 0.3
"""How far (ems of the letter) from a label's end a subscript or prime may start: about
half a letter, more than a width estimated from the letters is off by."""

NEAR_END_SMALLER = 0.6
"""How far (ems) from a label's end a smaller text may start and be its subscript: a
program that sets the subscript as a shape of its own puts it a little apart (LibreOffice
Draw's text box has a margin of its own)."""

SHIFT = (0.15, 1.0)
"""How far below a label's baseline (ems) a text of its size stands to be its subscript:
lower than a baseline drawn by hand wanders, and by less than a line."""

SMALLER = 0.9
"""A text at most this share of a label's size, starting at its end and no more than a
line below, is its subscript (GeoGebra sets an index at int(0.9 × 16 px) = 14 px)."""

PRIMES = frozenset("′'’ʹ″`")
"""What a prime is written with: a text of these alone, at a label's end, is its prime."""

_PART = re.compile(r"[\w′'’ʹ″`,]{1,4}")
"""A subscript or prime: at most four letters, digits or primes, no space."""

_INDEX = re.compile(r"\d[′'’ʹ″`]*|[′'’ʹ″`]*\d")
"""A subscript a course writes: a link's number (``4``), a prime either side; two digits
beside a letter are a centre's label (``35`` by the point B), not its subscript."""

_POLE = re.compile(r"[vVaA][′'’ʹ″`]*")
"""The subscript of a pole, ``o`` with ``v`` or ``a``."""


def follows(label: Label, end: float, text: Label, subscripted: bool = False) -> bool:
    """Whether ``text`` is a subscript or prime of ``label`` whose letters so far end at
    x = ``end`` (``subscripted``: they hold one already, or end in a digit, so only a prime
    may follow): it starts within :data:`NEAR_END` of that end (:data:`NEAR_END_SMALLER` if
    smaller), and is primes alone set
    within half an em of the baseline, or is smaller (:data:`SMALLER`) and at most a line
    below, or is set lower by :data:`SHIFT`.

    >>> a = Label("a", (10.0, 20.0), 4.0)
    >>> follows(a, 12.2, Label("4", (12.3, 21.0), 2.8)), follows(a, 12.2, Label("4", (12.3, 20.0)))
    (True, False)
    """
    em = label.size
    dx, dy = text.at[0] - end, text.at[1] - label.at[1]
    near = NEAR_END_SMALLER if text.size <= SMALLER * em else NEAR_END
    if abs(dx) > near * em or text.at[0] <= label.at[0] or not _PART.fullmatch(text.text):
        return False
    if set(text.text) <= PRIMES:
        return abs(dy) <= 0.5 * em
    if subscripted or not (_INDEX.fullmatch(text.text) or _POLE.fullmatch(text.text)
                           and label.text.strip() in ("o", "O")):
        return False
    if text.size <= SMALLER * em:
        return -0.1 * em <= dy <= SHIFT[1] * em
    return SHIFT[0] * em <= dy <= SHIFT[1] * em


RING = 4.0
"""The largest ring (mm radius) a figure circles a step's number in."""


def ringed(labels: list[Label], circles: list[tuple[Vec, float]]) -> dict[int, int]:
    """The bare numbers of ``labels`` that stand in a ring of ``circles``, as a figure
    circles its steps' numbers: a circle of radius :data:`RING` at most and half the
    number's size at least (a dot beside a subscript is no ring), centred on the number's
    letters (within half its radius; a pin's circle beside a centre's subscript is not).
    Label index → circle index.

    >>> ringed([Label("13", (9.0, 11.0), 2.0), Label("a", (9.0, 11.0))], [((10.0, 10.3), 1.85)])
    {0: 0}
    """
    rings = sorted((c[0], k) for k, (c, r) in enumerate(circles) if r <= RING)
    xs = [x for x, _ in rings]
    out = {}
    for k, lb in enumerate(labels):
        if not step_number(lb.text):
            continue
        middle = (lb.at[0] + lb.width() / 2.0, lb.at[1] - 0.35 * lb.size)
        lo = bisect.bisect_left(xs, middle[0] - RING)
        hi = bisect.bisect_right(xs, middle[0] + RING)
        ring = min((j for _, j in rings[lo:hi] if 0.5 * lb.size <= circles[j][1] and
                    math.dist(circles[j][0], middle) <= 0.5 * circles[j][1] + 0.3), default=None)
        if ring is not None:
            out[k] = ring
    return out


def _joined(labels: list[Label], circles: list[tuple[Vec, float]] = ()) -> list[Label]:
    """``labels`` with each subscript or prime set as a text of its own joined to its
    letter's label (:func:`follows`), kept where the letter is, in the letter's order; a
    number in a ring (:func:`ringed`) joins nothing."""
    apart = set(ringed(labels, list(circles))) if circles else set()
    order = sorted(range(len(labels)), key=lambda k: (labels[k].at[0], k))
    xs = [labels[k].at[0] for k in order]
    used: set[int] = set()
    out: dict[int, Label] = {}
    for k in order:
        if k in used:
            continue
        label = labels[k]
        if k in apart:
            out[k] = label
            continue
        text, end = label.text, label.at[0] + label.width()
        subscripted = text[-1:].isdigit()
        while True:
            lo = bisect.bisect_left(xs, end - NEAR_END_SMALLER * label.size)
            hi = bisect.bisect_right(xs, end + NEAR_END_SMALLER * label.size)
            near = [order[j] for j in range(lo, hi) if order[j] != k and order[j] not in used
                    and order[j] not in apart and follows(label, end, labels[order[j]],
                                                          subscripted)]
            if not near:
                break
            j = min(near, key=lambda j: (abs(labels[j].at[0] - end), j))
            used.add(j)
            text += labels[j].text
            subscripted = subscripted or not set(labels[j].text) <= PRIMES
            end = labels[j].at[0] + labels[j].width()
        out[k] = Label(text, label.at, label.size) if text != label.text else label
    return [out[k] for k in range(len(labels)) if k in out]


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
        Naming the file (and the line where there is one): not an SVG, empty, too big
        (compressed or unpacked), too many elements, or carrying a DTD's declarations, an
        entity or an external reference.
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
    """Read an SVG drawing from its bytes, gzip-compressed or not (see
    :func:`read_drawing`)."""
    if not data.strip():
        raise InputError("the file is empty; give an SVG drawing", file=name)
    if len(data) > MAX_BYTES:
        raise InputError(f"{readable_count(len(data))} bytes is more than a drawing holds "
                         f"(at most {readable_count(MAX_BYTES)})", file=name)
    if data[:2] == b"\x1f\x8b":
        data = _unpacked(data, name)
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


def _unpacked(data: bytes, name: str) -> bytes:
    """A gzip-compressed drawing unpacked, refused as soon as it passes :data:`MAX_BYTES`
    (so a file of kilobytes that would unpack to gigabytes costs a few milliseconds)."""
    inflate = zlib.decompressobj(16 + zlib.MAX_WBITS)
    out, pending = bytearray(), data
    try:
        while True:
            out += inflate.decompress(pending, MAX_BYTES + 1 - len(out))
            if len(out) > MAX_BYTES:
                raise InputError(f"compressed, it unpacks to more than "
                                 f"{readable_count(MAX_BYTES)} bytes, more than a drawing "
                                 "holds; a page of lines and labels is some kilobytes",
                                 file=name)
            pending = inflate.unconsumed_tail
            if inflate.eof or not pending:
                break
    except zlib.error as e:
        raise InputError(f"not a drawing: its gzip data is broken ({e}); export it again",
                         file=name) from None
    if not inflate.eof:
        raise InputError("not a drawing: its gzip data is cut short; export it again",
                         file=name)
    if inflate.unused_data.strip(b"\x00"):
        raise InputError("not a drawing: more follows its gzip data; give one compressed "
                         "SVG", file=name)
    return bytes(out)


def _geometry(reduced: Reduced, name: str) -> Drawing:
    """The strokes, circles and labels svgelements finds in the reduced tree, transforms
    applied, in mm; a shape or label at no finite place on a sheet is left out, noted."""
    from svgelements import SVG, Circle, Path, Shape, SVGText

    out = Drawing(source=name)
    labels: list[Label] = []
    try:
        elements = list(SVG.parse(io.BytesIO(reduced.data), ppi=96.0).elements())
    except (ValueError, ArithmeticError):
        raise InputError("the SVG's shapes cannot be read: a number in them is out of "
                         "range", file=name) from None

    def kept(e) -> Kept:
        return reduced.kept[int(e.values.get(MARK, 0))]
    for e in elements:
        if isinstance(e, SVGText):
            label = _label(e, kept(e))
            if label is None:
                out.notes.append(f"{kept(e).where()} (its place is beyond any paper)")
            elif label.text:
                labels.append(label)
        elif isinstance(e, Circle):
            # svgelements keeps a circle's centre as written: carry it through its transform.
            c = e.transform.point_in_matrix_space((e.cx, e.cy)) if e.transform else (e.cx, e.cy)
            r = abs(float(e.implicit_rx if hasattr(e, "implicit_rx") else e.rx)) * _MM
            if _placed(c[0] * _MM, c[1] * _MM, r):
                out.circles.append(((c[0] * _MM, c[1] * _MM), r))
            else:
                out.notes.append(f"{kept(e).where()} (it lies beyond any paper)")
        elif isinstance(e, Shape):          # lines, polylines, paths, rectangles, polygons
            path = e if isinstance(e, Path) else Path(e)
            path.reify()
            strokes = _strokes(path)         # as many points as safe_svg counted, at most
            if not all(_placed(*p) for o in strokes for p in o.corners):
                out.notes.append(f"{kept(e).where()} (it runs beyond any paper)")
                continue
            start, end = kept(e).marked
            if strokes and (start or end):
                strokes[0] = Outline(strokes[0].corners, strokes[0].closed, strokes[0].curved,
                                     (start, strokes[0].marked[1]))
                strokes[-1] = Outline(strokes[-1].corners, strokes[-1].closed,
                                      strokes[-1].curved, (strokes[-1].marked[0], end))
            out.outlines += strokes
            for o in strokes:
                ring = o.corners + o.corners[:1] if o.closed else o.corners
                out.segments += [(a, b) for a, b in zip(ring, ring[1:]) if a != b]
    # A text drawn again where it stands (GeoGebra's halo behind a label) is one label.
    out.labels = _joined(list(dict.fromkeys(labels)), out.circles)
    return out


def _placed(*xy: float) -> bool:
    return all(math.isfinite(v) and abs(v) <= PAPER for v in xy)


def _label(e, kept: Kept) -> Label | None:
    """The label a reduced ``<text>`` shows, its size carried through its transform;
    None if it stands at no place on a sheet."""
    x, y = e.x + (e.dx or 0.0), e.y + (e.dy or 0.0)
    if kept.anchor:                          # centred or ended there: back to its start
        x -= kept.anchor * advance(kept.words.strip()) * (kept.size or MEDIUM)
    scale = 1.0
    if e.transform is not None:
        x, y = e.transform.point_in_matrix_space((x, y))
        m = e.transform
        scale = math.sqrt(abs(m.a * m.d - m.b * m.c))
    if not _placed(x * _MM, y * _MM):
        return None
    # A size not said is SVG's medium in the text's own units, 16 mm on a page of mm: no
    # one draws letters so, so it is taken as a letter's usual size.
    size = LETTER if kept.size is None else kept.size * scale * _MM
    if not (math.isfinite(size) and 0.0 < size <= PAPER):
        size = LETTER
    return Label(kept.words.strip(), (x * _MM, y * _MM), size)


def _strokes(path) -> list[Outline]:
    """Each subpath of ``path`` as an outline in mm (a close back to its start drawn, a
    corner repeated as the close lands on it dropped)."""
    from svgelements import Close, Line, Move

    out: list[Outline] = []
    corners: list[Vec] = []
    curved = False

    def done(closed: bool) -> None:
        if closed and len(corners) > 1 and corners[-1] == corners[0]:
            corners.pop()
        if len(corners) > 1:
            out.append(Outline(tuple(corners), closed and len(corners) > 2, curved))
    for seg in path:
        if isinstance(seg, Move) or seg.end is None:
            done(False)
            corners, curved = ([] if seg.end is None else [_mm(seg.end)]), False
            continue
        if seg.start is None:
            continue
        if not corners:
            corners = [_mm(seg.start)]
        if isinstance(seg, Close):
            if seg.start != seg.end:
                corners.append(_mm(seg.end))
            done(True)
            corners, curved = [_mm(seg.end)], False
            continue
        curved = curved or not isinstance(seg, Line)
        p = _mm(seg.end)
        if p != corners[-1]:
            corners.append(p)
    done(False)
    return out


def _mm(p) -> Vec:
    return (p.x * _MM, p.y * _MM)
