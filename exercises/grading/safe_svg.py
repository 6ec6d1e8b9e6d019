"""A student's SVG parsed with no trust, and cut down to what grading reads.

The file is parsed with no entities and nothing loaded (:mod:`.svg_xml`), each element's
line kept for the messages. Then, before svgelements reads any geometry:

- the tree is bounded: its elements, how deep they nest, and what its ``<use>`` elements
  would expand to, counted on the tree (a ``<use>`` renders as many elements as its target,
  a loop is refused), so a file of a kilobyte cannot ask for millions;
- nothing may be pulled in: XInclude, or a ``<use>`` or image linked outside the file;
- the page must have a size: a viewBox, width or height of zero, below zero or not a
  finite number is refused;
- only what grading reads goes on: groups, ``<use>``, shapes and texts, with their
  geometry, ids and transforms (each rewritten as one finite matrix). Styles, scripts,
  markers, clip paths, hidden layers and metadata are left out, and so is an element with
  a number that is no number or beyond any drawing, with a word (:attr:`Reduced.notes`),
  and silently a shape that paints nothing (its fill and stroke none, as LibreOffice's
  bounding boxes). A text keeps where its first letter stands (the tspans that place it
  read here, so LibreOffice's nested ones are as good as a plain ``<text x y>``), its
  words and its font size; a shape keeps whether a marker (an arrowhead) starts or ends it.

svgelements then expands a bounded tree whose every number it can read. Each element
carries its index in :attr:`Reduced.kept` as the attribute :data:`MARK`, so a shape
svgelements returns is traced back to its line.
"""

from __future__ import annotations

import math
import re
import xml.etree.ElementTree as ET
from dataclasses import dataclass, field

from tarsim.constructions.errors import InputError
from .svg_style import Inherited, first_letter, inherit
from .svg_xml import parse_xml
from .svg_transform import PX, matrix, times

__all__ = ["Kept", "Reduced", "reduce_svg", "readable_count", "MARK", "MAX_ELEMENTS", "MAX_DEPTH",
           "MAX_POINTS", "MAX_TRANSFORM_WORK"]

MAX_ELEMENTS = 10_000
"""The most elements a drawing may hold, as written and with its ``<use>`` expanded: a page
of polygons and a space diagram, LibreOffice's four elements a shape, holds some
thousand."""

MAX_DEPTH = 64
"""How deep its elements may nest, ``<use>`` expanded (Inkscape's layers nest a dozen)."""

MAX_POINTS = 50_000
"""The most points its paths and polylines may hold, all together and ``<use>`` expanded
(a pair of numbers a point): a curve GeoGebra exports holds a few thousand."""

MAX_TRANSFORM_WORK = 100_000
"""The most transforms svgelements may apply, each element's whole chain counted: a
thousand elements under a dozen transformed groups apply some ten thousand."""

MAX_NUMBER = 1e12
"""The largest number an attribute may hold, in its own units."""

MAX_ATTRIBUTE = 1_000
"""The longest any attribute but a path's data may be (characters)."""

MARK = "tarsim-n"
"""The attribute giving a kept element's index in :attr:`Reduced.kept`."""

_SVG, _XLINK = "http://www.w3.org/2000/svg", "http://www.w3.org/1999/xlink"
_XINCLUDE = "http://www.w3.org/2001/XInclude"
_GROUPS = {"g": "g", "a": "g", "switch": "g", "defs": "defs", "use": "use", "svg": "svg",
           "symbol": "symbol"}
_GEOMETRY = {"svg": ("x", "y", "width", "height", "viewBox", "preserveAspectRatio"),
             "use": (), "g": (), "defs": (), "symbol": (),
             "line": ("x1", "y1", "x2", "y2"), "polyline": ("points",),
             "polygon": ("points",), "rect": ("x", "y", "width", "height", "rx", "ry"),
             "circle": ("cx", "cy", "r"), "ellipse": ("cx", "cy", "rx", "ry"),
             "path": ("d",), "text": ("x", "y", "dx", "dy")}
_LENGTH = re.compile(r"\s*([+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?)\s*"
                     r"(px|pt|pc|mm|cm|in|em|ex|%)?\s*")
_NUMBER = re.compile(r"[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?")


@dataclass(frozen=True)
class Kept:
    """An element passed on to svgelements: its tag, its line, a text's words, its first
    letter's font size (user units) and where its x stands along its letters (0 at their
    start, 1 at their end), and whether a marker starts or ends a shape."""

    tag: str
    line: int
    words: str = ""
    size: float | None = None
    marked: tuple[bool, bool] = (False, False)
    anchor: float = 0.0

    def where(self) -> str:
        """The element as a message names it: ``<circle> at line 4``."""
        return f"<{self.tag}> at line {self.line}"


@dataclass
class Reduced:
    """The tree svgelements reads (as bytes), the elements kept, and those left out."""

    data: bytes
    kept: list[Kept] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)
    """Each element left out, and why: ``<circle> at line 4 (r is not a number)``."""


def reduce_svg(data: bytes, name: str) -> Reduced:
    """Parse the drawing ``data`` (the file ``name``) and cut it down to what grading reads.

    Raises
    ------
    InputError
        Naming the file and, where there is one, the line: XML that cannot be read, a DTD
        or an entity, no ``<svg>`` root, too many elements or too deep, ``<use>`` that loops
        or expands past the bounds, anything linked from outside, a page with no size.

    Examples
    --------
    >>> r = reduce_svg(b'<svg width="10mm" height="10mm"><style>*{}</style>'
    ...                b'<line x1="0" y1="0" x2="3" y2="4" stroke="red"/></svg>', "s.svg")
    >>> r.data.decode().split("><")[1]
    'line tarsim-n="1" x1="0" y1="0" x2="3" y2="4" /'
    >>> r.kept[1]
    Kept(tag='line', line=1, words='', size=None, marked=(False, False), anchor=0.0)
    """
    root, lines = parse_xml(data, name)
    if _local(root.tag) != "svg":
        raise InputError(f"not an SVG drawing (its root is <{_local(root.tag)}>)", file=name)
    if _space(root.tag) not in ("", _SVG):
        raise InputError(f"not an SVG drawing (its <svg> is of the namespace "
                         f"{_space(root.tag)[:60]!r}, not SVG's)", file=name)
    count = sum(1 for _ in root.iter())
    if count > MAX_ELEMENTS:
        raise InputError(f"{count:,} elements are more than a drawing holds (at most "
                         f"{MAX_ELEMENTS:,})", file=name)
    _check_depth(root, lines, name)
    out = Reduced(b"")
    tree = _Reducer(name, lines, out).element(root, None, Inherited())
    if tree is None:
        raise InputError("the drawing is hidden whole (its <svg> has display none)",
                         file=name, line=1)
    _Expansion(tree, out.kept, name).check()
    out.data = ET.tostring(tree, encoding="unicode").encode("utf-8")
    return out


def _check_depth(root: ET.Element, lines: dict, name: str) -> None:
    """Refuse elements nested past :data:`MAX_DEPTH`, at the first that is."""
    stack = [(root, 1)]
    while stack:
        element, depth = stack.pop()
        if depth > MAX_DEPTH:
            raise InputError(f"<{_local(element.tag)}> is nested {depth} deep, deeper than a "
                             f"drawing's elements go (at most {MAX_DEPTH})", file=name,
                             line=lines.get(element))
        stack.extend((child, depth + 1) for child in element)


class _Reducer:
    """Builds the tree svgelements reads from the parsed one."""

    def __init__(self, name: str, lines: dict, out: Reduced):
        self.name, self.lines, self.out = name, lines, out

    def fail(self, element, message: str) -> InputError:
        return InputError(f"<{_local(element.tag)}> {message}", file=self.name,
                          line=self.lines.get(element))

    def leave_out(self, element, why: str) -> None:
        self.out.notes.append(f"<{_local(element.tag)}> at line {self.lines.get(element)} "
                              f"({why})")

    def element(self, e: ET.Element, parent: ET.Element | None,
                outer: Inherited) -> ET.Element | None:
        """The kept copy of ``e`` under ``parent`` (None if left out), ``outer`` the
        presentation it inherits."""
        space, tag = _space(e.tag), _local(e.tag)
        if space == _XINCLUDE:
            raise self.fail(e, "pulls in another file (XInclude); a drawing must hold all it "
                               "shows")
        href = e.get(f"{{{_XLINK}}}href", e.get("href"))
        if href and href.strip() and tag in ("use", "image") and not href.startswith("#") \
                and not (tag == "image" and href.startswith("data:")):
            raise self.fail(e, f"links to {href[:60]!r} outside the drawing; a drawing must "
                               "hold all it shows")
        if space not in ("", _SVG) or _hidden(e) or (tag not in _GROUPS and
                                                     tag not in _GEOMETRY):
            return None
        here = inherit(e, outer)
        kind = _GROUPS.get(tag, tag)
        if kind not in _GROUPS.values() and here.unseen:
            return None                      # it paints nothing: a bounding box
        attributes = self.attributes(e, kind, href)
        if attributes is None or kind == "text" and not self.place(e, attributes):
            return None
        index = len(self.out.kept)
        if kind == "text":
            letter = here
            for span in first_letter(e, space)[1:]:
                letter = inherit(span, letter)
            for inner in e.iter():
                if _space(inner.tag) == _XINCLUDE:
                    raise self.fail(inner, "pulls in another file (XInclude); a drawing "
                                           "must hold all it shows")
            kept = Kept(tag, self.lines.get(e, 0), "".join(e.itertext()), letter.size,
                        anchor=letter.anchor)
        else:
            kept = Kept(tag, self.lines.get(e, 0), marked=here.marked)
        self.out.kept.append(kept)
        attributes = {MARK: str(index), **attributes}
        if kind == "symbol":                 # drawn only through a <use>: a group in defs
            holder = ET.Element("defs") if parent is None else ET.SubElement(parent, "defs")
            copy = ET.SubElement(holder, "g", attributes)
        else:
            copy = ET.Element(kind, attributes) if parent is None else \
                ET.SubElement(parent, kind, attributes)
        if kind != "text":                   # a text's letters are in its words
            for child in e:
                self.element(child, copy, here)
        return copy

    def place(self, text: ET.Element, attributes: dict) -> bool:
        """Put in ``attributes`` where ``text``'s first letter stands: the x and y of the
        innermost element placing it that has them, and the dx and dy of them all (px). A
        tspan whose place is no length is not held to, with a note; False (and a note) if
        the text's own dx or dy is in no fixed unit."""
        shift = {"dx": 0.0, "dy": 0.0}
        for k, e in enumerate(first_letter(text, _space(text.tag))):
            values = {}
            for key in ("x", "y", "dx", "dy"):
                value = e.get(key)
                if value is None or k == 0 and key in ("x", "y"):
                    continue                 # the text's own x and y are checked already
                value = (re.split(r"[\s,]+", value.strip()) or [""])[0]
                length = _length(value)
                if length is None or key in shift and length[1] not in PX:
                    why = _fault(value) if length is None else "is not a length in a fixed unit"
                    self.leave_out(e, f"{key}={value[:24]!r} {why}")
                    if k == 0:
                        return False
                    break
                values[key] = length[0] * PX[length[1]] if key in shift else value
            else:
                for key, value in values.items():
                    if key in shift:
                        shift[key] += value
                    else:
                        attributes[key] = value
        for key, value in shift.items():
            if value:
                attributes[key] = repr(value)
            else:
                attributes.pop(key, None)
        return True

    def attributes(self, e: ET.Element, kind: str, href: str | None) -> dict | None:
        """The attributes svgelements is given, checked; None (and a note) if ``e`` holds
        a number that is no number or beyond any drawing."""
        out = {}
        if e.get("id") is not None and len(e.get("id")) <= MAX_ATTRIBUTE:
            out["id"] = e.get("id")
        for key in _GEOMETRY.get(kind, ()):
            value = e.get(key)
            if value is None:
                continue
            if key in ("d", "points"):
                bad = _huge_number(value)
                if bad:
                    self.leave_out(e, f"{key} holds {bad[:24]}, beyond any drawing")
                    return None
                out[key] = value
                continue
            if kind == "svg":
                out[key] = self.page(e, key, value)
                continue
            if kind == "text":                   # a list of glyph positions: the first
                value = (re.split(r"[\s,]+", value.strip()) or [""])[0]
            if _length(value) is None:
                self.leave_out(e, f"{key}={value[:24]!r} {_fault(value)}")
                return None
            out[key] = value.strip()
        moved = self.transform(e, kind)
        if moved is False:
            return None
        if moved is not None:
            out["transform"] = "matrix(" + " ".join(repr(v) for v in moved) + ")"
        if kind == "use" and href is not None:
            out["href"] = href
        return out

    def page(self, e: ET.Element, key: str, value: str) -> str:
        """A ``<svg>``'s size or viewBox, refused unless it has one."""
        if key == "preserveAspectRatio":
            return value if re.fullmatch(r"[A-Za-z ]{0,40}", value) else "xMidYMid"
        if key == "viewBox":
            parts = [p for p in re.split(r"[\s,]+", value.strip()) if p]
            numbers = [_length(p) for p in parts]
            if len(parts) != 4 or any(n is None or n[1] is not None for n in numbers) or \
                    numbers[2][0] <= 0 or numbers[3][0] <= 0:
                raise self.fail(e, f"viewBox={value[:40]!r} gives the page no size; a "
                                   "drawing's viewBox is four numbers, its width and height "
                                   "above zero")
            return value
        if key in ("width", "height") and value.strip() == "auto":
            return "100%"
        size = _length(value)
        if size is None or (key in ("width", "height") and size[0] <= 0):
            raise self.fail(e, f"{key}={value[:40]!r} is no size for a page; export the "
                               "drawing again")
        return value.strip()

    def transform(self, e: ET.Element, kind: str):
        """``e``'s transform (a ``<use>``'s x and y included) as six numbers, None for
        none, False (and a note) if it cannot be read or is beyond any drawing."""
        text = e.get("transform")
        found = None
        if text is not None and text.strip():
            found = matrix(text) if len(text) <= MAX_ATTRIBUTE else None
            if found is None:
                self.leave_out(e, f"its transform {text[:24]!r} cannot be read")
                return False
        if kind == "use" and (e.get("x") or e.get("y")):
            shift = [_length(e.get(k) or "0") for k in ("x", "y")]
            for key, s in zip(("x", "y"), shift):
                if s is None or s[1] not in PX:
                    value = e.get(key)
                    self.leave_out(e, f"{key}={value[:24]!r} " + (
                        _fault(value) if s is None else "is not a length in a fixed unit"))
                    return False
            move = (1.0, 0.0, 0.0, 1.0, shift[0][0] * PX[shift[0][1]],
                    shift[1][0] * PX[shift[1][1]])
            found = times(found or (1.0, 0.0, 0.0, 1.0, 0.0, 0.0), move)
        if found is not None and not all(math.isfinite(v) and abs(v) <= MAX_NUMBER
                                         for v in found):
            self.leave_out(e, "its transform goes beyond any drawing")
            return False
        return found


class _Expansion:
    """What svgelements would make of the tree, counted on it before it is made."""

    def __init__(self, tree: ET.Element, kept: list[Kept], name: str):
        self.tree, self.kept, self.name = tree, kept, name
        self.ids = {e.get("id"): e for e in tree.iter() if e.get("id") is not None}
        self.memo: dict[ET.Element, tuple[int, int, int, int]] = {}
        self.open: set[ET.Element] = set()

    def check(self) -> None:
        """Refuse a ``<use>`` loop, or a tree that expands past the bounds.

        Raises
        ------
        InputError
            Naming the file, the line of the ``<use>`` and the bound.
        """
        count, points, work, _ = self.measure(self.tree, 1)
        work += count                              # the page's own viewport transform
        bounds = ((count, MAX_ELEMENTS, "it holds {} elements",
                   "its <use> elements expand it to {} elements"),
                  (points, MAX_POINTS, "its paths hold {} points",
                   "its <use> elements expand its paths to {} points"),
                  (work, MAX_TRANSFORM_WORK, "its shapes lie under {} transforms in all",
                   "its <use> elements put its shapes under {} transforms in all"))
        for axis, (total, most, alone, used) in enumerate(bounds):
            if total <= most:
                continue
            uses = [e for e in self.memo if e.tag == "use"]
            past = f", more than a drawing needs (at most {readable_count(most)})"
            if not uses:
                raise InputError(alone.format(readable_count(total)) + past, file=self.name)
            use = max(uses, key=lambda u: self.memo[u][axis])
            raise InputError(used.format(readable_count(total)) + past
                             + f"; this <use> of {use.get('href', '')[:40]} alone makes "
                             f"{readable_count(self.memo[use][axis])}", file=self.name,
                             line=self.line(use))

    def line(self, e: ET.Element) -> int:
        return self.kept[int(e.get(MARK))].line

    def measure(self, e: ET.Element, depth: int) -> tuple[int, int, int, int]:
        """(elements, path points, transforms applied, depth) of ``e`` expanded."""
        if e in self.memo:
            if depth + self.memo[e][3] - 1 > MAX_DEPTH:
                raise InputError(f"<{e.tag}> is nested more than {MAX_DEPTH} deep once its "
                                 "<use> elements are expanded", file=self.name,
                                 line=self.line(e))
            return self.memo[e]
        if depth > MAX_DEPTH:
            raise InputError(f"<{e.tag}> is nested more than {MAX_DEPTH} deep once its "
                             "<use> elements are expanded", file=self.name, line=self.line(e))
        self.open.add(e)
        count, points, work, deep = 1, self.points(e), 0, 0
        parts = list(e)
        if e.tag == "use":
            target = self.ids.get((e.get("href") or "#")[1:])
            if target in self.open:
                raise InputError(f"<use> of {e.get('href', '')[:40]} refers to an element "
                                 "that holds it: a <use> may not loop", file=self.name,
                                 line=self.line(e))
            if target is not None:
                parts.append(target)
        for part in parts:
            c, p, w, d = self.measure(part, depth + 1)
            count, points, work, deep = count + c, points + p, work + w, max(deep, d)
        work += count * (e.get("transform") is not None)
        self.open.discard(e)
        self.memo[e] = (count, points, work, deep + 1)
        return self.memo[e]

    @staticmethod
    def points(e: ET.Element) -> int:
        """The points ``e``'s own path data or polyline holds: half its numbers."""
        text = e.get("d") or e.get("points")
        return len(_NUMBER.findall(text)) // 2 if text else 0


def readable_count(n: int) -> str:
    """A count as a message gives it, every figure readable: in full below a million, then
    in millions to three figures, past a billion as a power of ten.

    >>> readable_count(917_447), readable_count(2_400_006), readable_count(2 ** 40)
    ('917,447', '2.4 million', '1.1e+12')
    """
    if n < 1_000_000:
        return f"{n:,}"
    return f"{n / 1e6:.3g} million" if n < 1e9 else f"{n:.2g}"


def _length(text: str) -> tuple[float, str | None] | None:
    """A length's number and unit, if it is one a drawing holds (finite, under
    :data:`MAX_NUMBER`)."""
    m = _LENGTH.fullmatch(text) if len(text) <= MAX_ATTRIBUTE else None
    if m is None or m[2] in ("em", "ex"):     # a font's size, which svgelements leaves unread
        return None
    value = float(m[1])
    return (value, m[2]) if math.isfinite(value) and abs(value) <= MAX_NUMBER else None


def _fault(text: str) -> str:
    """What is wrong with a length :func:`_length` refuses."""
    m = _LENGTH.fullmatch(text[:MAX_ATTRIBUTE + 1])
    if m is None:
        return "is not a length"
    return "is not a length in a fixed unit" if m[2] in ("em", "ex") else "is beyond any drawing"


def _huge_number(text: str) -> str | None:
    """The first number in path data beyond :data:`MAX_NUMBER` (or not finite), if any."""
    for m in _NUMBER.finditer(text):
        if "e" in m[0].lower() or len(m[0]) > 12:
            value = float(m[0])
            if not (math.isfinite(value) and abs(value) <= MAX_NUMBER):
                return m[0]
    return None


def _hidden(e: ET.Element) -> bool:
    """Whether ``e`` is not drawn (display none, as an attribute or in its style)."""
    if (e.get("display") or "").strip().lower() == "none":
        return True
    style = (e.get("style") or "")[:MAX_ATTRIBUTE * 10]
    return re.search(r"(?:^|;)\s*display\s*:\s*none\s*(?:;|$)", style, re.IGNORECASE) \
        is not None


def _local(tag: str) -> str:
    return tag.rsplit("}", 1)[-1] if isinstance(tag, str) else ""


def _space(tag: str) -> str:
    return tag[1:].split("}", 1)[0] if isinstance(tag, str) and tag.startswith("{") else ""
