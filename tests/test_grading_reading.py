"""A student's SVG read as the programs a class uses write it, and the points its labels name.

Each file in ``tests/data/grading/programs/`` is written the way its program writes SVG:
Inkscape 1.2 (a translated layer, texts in ``sodipodi:role="line"`` tspans, arrowheads as
``marker-end``), LibreOffice Draw 7 (its DOCTYPE, hundredths of a mm, a bounding box round
every shape, texts placed on nested tspans, arrowheads as filled polygons its line runs
into), GeoGebra (canvas2svg's pixel page: its ``DrawVector`` shaft stopping at a filled
arrowhead's base, an index as a text of its own, 0.9 the size and half its size lower), a
CAD plot (y flipped by one group, each text flipped back, open and solid arrowheads, a
slider block of four lines) and a hand-typed file. Every position asserted below is worked
out by hand from the numbers and transforms written in the file, not from tarsim.
"""

from __future__ import annotations

import gzip
import math
import time
import zlib
from pathlib import Path

import pytest
from hypothesis import assume, example, given, settings
from hypothesis import strategies as st

from tarsim.constructions.errors import InputError
from tarsim.exercises.grading.drawing import (MAX_BYTES, NEAR_END, NEAR_END_SMALLER, PRIMES,
                                             SHIFT, SMALLER, Label, _joined, parse_drawing,
                                             read_drawing)
from tarsim.exercises.grading.marks import Kind, marks
from tarsim.exercises.grading.matching import match

PROGRAMS = Path(__file__).parent / "data" / "grading" / "programs"

PX = 25.4 / 96
"""Paper mm a CSS px (96 to the inch): GeoGebra's page is in px, with no viewBox."""

CM = 0.01
"""Paper mm a LibreOffice unit: its page is 21000 × 29700 in a 210 × 297 mm viewport."""


def flip(x, y):
    """A CAD point: its group's matrix(1,0,0,-1,0,297) turns model y up into paper y down."""
    return (x, 297.0 - y)


def layer(x, y):
    """An Inkscape point in its layer, translate(-12.5, 8.25)."""
    return (x - 12.5, y + 8.25)


# Each file: (name, the labels read as (text, anchor, size), the marks a label may name as
# (point, kind), which point each of some labels names, and a point nearer that label's
# letters that a nearest-point reader would take instead).
FILES = {
    "inkscape/velocity-polygon.svg": dict(
        labels=[("o", layer(56.900002, 116.1), 4.23333),
                # transform="scale(0.5)" on x=188 y=219 and on the 8.46667 px letters
                ("a", layer(94.0, 109.5), 4.233335),
                ("b", layer(83.5, 85.25), 4.23333),
                # a<tspan style="font-size:65%;baseline-shift:sub">4</tspan>
                ("a4", layer(63.700001, 90.5), 4.23333),
                # in a group matrix(0.8,0,0,0.8,6,30): (0.8·30 + 6, 0.8·150 + 30)
                ("1 cm = 0.5 m/s", layer(30.0, 150.0), 5.29167 * 0.8)],
        marks={(layer(62.5, 111.75), Kind.DOT), (layer(92.5, 111.75), Kind.TIP),
               (layer(82.5, 86.75), Kind.TIP), (layer(62.5, 91.75), Kind.TIP),
               (layer(84.1, 86.75), Kind.END), (layer(114.1, 66.75), Kind.END)},
        names={"o": layer(62.5, 111.75), "a": layer(92.5, 111.75), "b": layer(82.5, 86.75),
               "a4": layer(62.5, 91.75)},
        decoys={"b": layer(84.1, 86.75)}),          # the dashed line's end 1.6 mm from b
    "libreoffice/velocity-polygon.svg": dict(
        labels=[("o", (4440 * CM, 12435 * CM), 423 * CM),
                ("a", (8150 * CM, 11775 * CM), 423 * CM),
                ("b", (7100 * CM, 9350 * CM), 423 * CM),
                # two TextPositions in one text: "a" and, lower and smaller, "4"
                ("a4", (5120 * CM, 9875 * CM), 423 * CM),
                ("B", (10100 * CM, 18900 * CM), 423 * CM)],
        marks={((50.0, 120.0), Kind.DOT), ((100.0, 195.0), Kind.BLOCK),
               ((80.0, 120.0), Kind.TIP), ((70.0, 95.0), Kind.TIP), ((50.0, 100.0), Kind.TIP)},
        names={"o": (50.0, 120.0), "a": (80.0, 120.0), "b": (70.0, 95.0), "a4": (50.0, 100.0),
               "B": (100.0, 195.0)},
        decoys={"B": (107.5, 190.0)}),               # the block's corner
    "libreoffice/velocity-polygon-tiny.svg": dict(
        labels=[("o", (44.4, 124.35), 4.23), ("a′", (81.5, 117.75), 4.23)],
        marks={((80.0, 120.0), Kind.TIP), ((50.0, 120.0), Kind.END)},
        names={"o": (50.0, 120.0), "a′": (80.0, 120.0)},
        decoys={}),
    "geogebra/velocity-polygon.svg": dict(
        labels=[("o", (182 * PX, 415 * PX), 16 * PX), ("a", (318 * PX, 417 * PX), 16 * PX),
                ("b", (306 * PX, 276 * PX), 16 * PX),
                # drawIndexedString("a_4'"): a at 16 px, 4 at 14 px 7 px lower, ' at 16 px
                ("a4'", (206 * PX, 296 * PX), 16 * PX)],
        marks={((200 * PX, 400 * PX), Kind.DOT), ((340 * PX, 400 * PX), Kind.TIP),
               ((300 * PX, 280 * PX), Kind.TIP), ((200 * PX, 300 * PX), Kind.TIP),
               # the white page behind, a rectangle 800 × 600 px
               ((0.0, 0.0), Kind.JUNCTION), ((800 * PX, 0.0), Kind.JUNCTION),
               ((800 * PX, 600 * PX), Kind.JUNCTION), ((0.0, 600 * PX), Kind.JUNCTION)},
        names={"o": (200 * PX, 400 * PX), "a": (340 * PX, 400 * PX), "b": (300 * PX, 280 * PX),
               "a4'": (200 * PX, 300 * PX)},
        decoys={"a": (323 * PX, 404.25 * PX)}),      # the arrowhead's corner
    "cad/velocity-polygon.svg": dict(
        labels=[("o", flip(44.4, 172.65), 3.5), ("a", flip(76.0, 173.6), 3.5),
                ("b", flip(66.0, 197.5), 3.5),
                # a text "4" of 2.5 mm set just after "a" and 1 mm lower
                ("a4", flip(51.2, 198.25), 3.5), ("B", flip(101.0, 108.0), 3.5),
                ("VELOCITY SCALE 1 cm = 0.2 m/s", flip(20.0, 40.0), 3.5)],
        marks={(flip(50, 177), Kind.DOT), (flip(80, 177), Kind.TIP), (flip(70, 202), Kind.TIP),
               (flip(50, 197), Kind.TIP), (flip(100, 102), Kind.BLOCK),
               (flip(60, 91), Kind.END), (flip(140, 91), Kind.END), (flip(60, 122), Kind.END)},
        names={"o": flip(50, 177), "a": flip(80, 177), "b": flip(70, 202), "a4": flip(50, 197),
               "B": flip(100, 102)},
        decoys={"a": flip(77, 177.5),                # the solid arrowhead's corner
                "b": flip(67.6574, 200.0322),        # the open arrowhead's wing
                "B": flip(107.5, 107)}),             # the block's corner
    "hand/velocity-polygon.svg": dict(
        labels=[("ov", (44.4, 124.35), 4.0), ("a", (81.5, 117.75), 4.0),
                ("b", (71.0, 93.5), 4.0), ("a4′", (51.2, 98.75), 4.0), ("B", (101.0, 189.0), 4.0),
                ("13", (141.2, 188.8), 4.0), ("A", (120.0, 230.0), 4.0),
                ("3", (123.2, 230.0), 4.0), ("b′4", (120.0, 250.0), 4.0),
                # translate(160,150) rotate(90) on x=2 y=0
                ("ω", (160.0, 152.0), 4.0),
                # text-anchor="middle" at x=150: Helvetica's c is 0.5 em wide, 2.5 mm at 5 mm
                ("c", (150.0 - 2.5 / 2, 60.0), 5.0)],
        marks={((50.0, 120.0), Kind.DOT), ((140.0, 190.0), Kind.DOT),
               ((100.0, 195.0), Kind.BLOCK), ((80.0, 120.0), Kind.JUNCTION),
               ((70.0, 95.0), Kind.JUNCTION), ((50.0, 100.0), Kind.END),
               ((71.6, 95.0), Kind.END), ((101.6, 75.0), Kind.END)},
        names={"ov": (50.0, 120.0), "a": (80.0, 120.0), "b": (70.0, 95.0), "a4′": (50.0, 100.0),
               "B": (100.0, 195.0), "13": (140.0, 190.0)},
        decoys={"b": (71.6, 95.0), "B": (107.5, 190.0)}),
}

ROUNDING = 0.01
"""How near (mm) a read position must be to the one worked out by hand: the files write
four decimals or fewer, and svgelements reads a mm as 3.7795296 px (a relative error of
1e-6, 0.3 µm across a sheet)."""


def near(p, q, tol: float = ROUNDING) -> bool:
    return math.dist(p, q) <= tol


@pytest.mark.parametrize("name", FILES)
def test_a_programs_labels_are_read_where_it_put_them(name):
    d = read_drawing(PROGRAMS / name)
    want = FILES[name]["labels"]
    assert [label.text for label in d.labels] == [t for t, _, _ in want]
    for label, (text, at, size) in zip(d.labels, want):
        assert near(label.at, at), (text, label.at, at)
        assert label.size == pytest.approx(size, abs=ROUNDING), text
    assert d.notes == []


@pytest.mark.parametrize("name", FILES)
def test_a_programs_marks_are_told_apart(name):
    """Every point a label may name, and what it is: an arrowhead's corners, its shaft's
    end inside it, a V's wings, a block's corners and LibreOffice's invisible bounding boxes
    are none of them."""
    got = marks(read_drawing(PROGRAMS / name))
    want = FILES[name]["marks"]
    assert len(got) == len(want)
    for at, kind in want:
        assert any(near(m.at, at) and m.kind is kind for m in got), (at, kind, got)


def _box_distance(label: Label, p) -> float:
    """How far ``p`` stands from a box over the label's letters, each letter 0.6 of its
    size wide and the box 0.8 of it tall (a reader's eye, apart from tarsim's own)."""
    x0, x1 = label.at[0], label.at[0] + 0.6 * label.size * len(label.text)
    y0, y1 = label.at[1] - 0.8 * label.size, label.at[1]
    return math.hypot(max(x0 - p[0], 0.0, p[0] - x1), max(y0 - p[1], 0.0, p[1] - y1))


@pytest.mark.parametrize("name", FILES)
def test_each_label_names_the_point_a_reader_would(name):
    """An arrow's tip, not its arrowhead's corner; a block's middle, not its corner; where
    strokes meet, not a construction line's end 1.6 mm away; each though the wrong point
    stands nearer the label's letters."""
    d = read_drawing(PROGRAMS / name)
    names, decoys = FILES[name]["names"], FILES[name]["decoys"]
    found = match(d, lambda text: ("p", text) if text in names else None)
    assert set(found) == {("p", text) for text in names}
    for text, at in names.items():
        assert near(found["p", text], at), (text, found["p", text], at)
    labels = {label.text: label for label in d.labels}
    for text, decoy in decoys.items():
        assert _box_distance(labels[text], decoy) < _box_distance(labels[text], names[text])


# ----- DOCTYPE, entities, XInclude ---------------------------------------------------------------
PAGE = ('<svg xmlns="http://www.w3.org/2000/svg" width="100mm" height="100mm" '
        'viewBox="0 0 100 100"><text x="5" y="5">o</text>')
REFUSED = ("s.svg: the SVG declares a DTD, entities or external resources, which a drawing "
           "never needs; export it again as plain SVG")


@pytest.mark.parametrize("head", [
    '<!DOCTYPE svg PUBLIC "-//W3C//DTD SVG 1.1//EN" '
    '"http://www.w3.org/Graphics/SVG/1.1/DTD/svg11.dtd">',
    '<!DOCTYPE svg SYSTEM "file:///etc/passwd">',          # named, never loaded
    "<!DOCTYPE svg [ <!-- nothing declared --> ]>"])
def test_a_doctype_that_declares_nothing_is_read_past(head):
    d = parse_drawing(f'<?xml version="1.0"?>\n{head}\n{PAGE}</svg>'.encode(), "s.svg")
    assert [(label.text, label.at) for label in d.labels] == [("o", pytest.approx((5, 5)))]


@pytest.mark.parametrize("head, says", [
    ('<!DOCTYPE svg [<!ENTITY o "o">]>', REFUSED),
    ('<!DOCTYPE svg PUBLIC "-//W3C//DTD SVG 1.1//EN" "svg11.dtd" [<!ENTITY % p SYSTEM '
     '"http://127.0.0.1:9/x">%p;]>', REFUSED),
    ('<!DOCTYPE svg SYSTEM "svg11.dtd" [<!ATTLIST text x CDATA "1e308">]>', REFUSED),
    ('<!DOCTYPE svg [<!ELEMENT svg ANY>]>', REFUSED),
    ('<!DOCTYPE svg [<!NOTATION n SYSTEM "x">]>', REFUSED),
    ("<!DOCTYPE svg [%p;]>", REFUSED),
], ids=["entity", "external-parameter-entity", "attribute-default", "element", "notation",
        "undeclared-parameter-entity"])
def test_a_doctype_that_declares_anything_is_refused_in_one_line(head, says):
    with pytest.raises(InputError) as refused:
        parse_drawing(f"{head}{PAGE}</svg>".encode(), "s.svg")
    assert str(refused.value) == says


def test_xinclude_is_refused_in_one_line_even_inside_a_text():
    for body in ('<xi:include xmlns:xi="http://www.w3.org/2001/XInclude" href="x.svg"/>',
                 '<text x="1" y="1">b<xi:include xmlns:xi="http://www.w3.org/2001/XInclude" '
                 'href="/etc/passwd" parse="text"/></text>'):
        with pytest.raises(InputError) as refused:
            parse_drawing(f"{PAGE}{body}</svg>".encode(), "s.svg")
        assert str(refused.value) == ("s.svg:1: <include> pulls in another file (XInclude); a "
                                      "drawing must hold all it shows")


# ----- .svgz --------------------------------------------------------------------------------------
def test_a_compressed_drawing_reads_as_the_drawing(tmp_path):
    plain = PROGRAMS / "inkscape/velocity-polygon.svg"
    packed = tmp_path / "velocity-polygon.svgz"
    packed.write_bytes(gzip.compress(plain.read_bytes()))
    a, b = read_drawing(plain), read_drawing(packed)
    assert a.labels == b.labels and a.outlines == b.outlines and b.source == packed.name


def _bomb(megabytes: int, crc: int = 0) -> bytes:
    """A gzip member that unpacks to an SVG of ``megabytes`` MB, nearly all spaces: one
    megabyte's deflate block, the dictionary reset after it so each copy of it unpacks
    alike, written that many times (its CRC ``crc``, 0 unless told: nothing reads that
    far)."""
    pack = zlib.compressobj(9, zlib.DEFLATED, -zlib.MAX_WBITS)
    start = pack.compress(b'<svg xmlns="http://www.w3.org/2000/svg">') + \
        pack.flush(zlib.Z_FULL_FLUSH)
    block = pack.compress(b" " * (1 << 20)) + pack.flush(zlib.Z_FULL_FLUSH)
    end = pack.compress(b"</svg>") + pack.flush()
    size = (megabytes << 20) + 46
    return (b"\x1f\x8b\x08\x00\x00\x00\x00\x00\x00\x03" + start + block * megabytes + end
            + crc.to_bytes(4, "little") + (size % 2 ** 32).to_bytes(4, "little"))


def test_the_bomb_unpacks_as_it_says():
    svg = b'<svg xmlns="http://www.w3.org/2000/svg">' + b" " * (3 << 20) + b"</svg>"
    assert gzip.decompress(_bomb(3, zlib.crc32(svg))) == svg


def test_a_gzip_bomb_is_refused_at_once_in_one_line(tmp_path):
    """A megabyte that would unpack to a gigabyte: refused once the 5 MB a drawing may hold
    are passed, not after a gigabyte."""
    path = tmp_path / "bomb.svgz"
    path.write_bytes(_bomb(1024))
    assert path.stat().st_size < 2_000_000
    start = time.perf_counter()
    with pytest.raises(InputError) as refused:
        read_drawing(path)
    took = time.perf_counter() - start
    assert str(refused.value) == (
        f"bomb.svgz: compressed, it unpacks to more than {MAX_BYTES // 10**6} million bytes, "
        "more than a drawing holds; a page of lines and labels is some kilobytes")
    # Unpacking the 5 MB allowed takes some milliseconds; the whole gigabyte, some seconds.
    assert took < 1.0, took


@pytest.mark.parametrize("data, says", [
    (gzip.compress(b"<svg/>")[:-6], "not a drawing: its gzip data is cut short; export it again"),
    (b"\x1f\x8b\x08\x00\x00\x00\x00\x00\x00\x03\xffgarbage",
     "not a drawing: its gzip data is broken (Error -3 while decompressing data: invalid "
     "block type); export it again"),
    (gzip.compress(b"<svg/>") + b"more", "not a drawing: more follows its gzip data; give one "
                                         "compressed SVG"),
], ids=["cut-short", "broken", "trailing"])
def test_a_broken_gzip_is_refused_in_one_line(data, says):
    with pytest.raises(InputError) as refused:
        parse_drawing(data, "s.svgz")
    assert str(refused.value) == f"s.svgz: {says}"


# ----- a subscript or prime written apart ---------------------------------------------------------
TEXTS = st.sampled_from(["a", "b", "o", "I", "O", "O2", "a4", "B"])
FOLLOWERS = st.sampled_from(["4", "13", "v", "2", "′", "'", "’", "4′", "ab", "24", "x y"])


def _advance_bounds(label: Label) -> tuple[float, float]:
    return label.at[0], label.at[0] + label.width()


@settings(max_examples=400, deadline=None)
@given(base=TEXTS, follower=FOLLOWERS, size=st.floats(2.0, 8.0),
       share=st.floats(0.3, 1.3), dx=st.floats(-1.5, 1.5), dy=st.floats(-1.5, 1.5))
@example(base="I", follower="13", size=4.0, share=0.7, dx=0.0, dy=0.3)
@example(base="A", follower="3", size=4.0, share=1.0, dx=0.1, dy=0.0)
def test_a_text_is_joined_to_a_label_only_as_its_subscript_or_prime(base, follower, size, share,
                                                                    dx, dy):
    """Joined only when the text starts within NEAR_END ems of the label's end (NEAR_END_SMALLER
    if smaller) and is primes
    at the baseline, or smaller and at most a line lower, or lower by SHIFT; a text of the
    label's size on its baseline (a step's number, a centre's 13 beside a point's name) is
    never joined; what is joined keeps the letter's place and size."""
    letter = Label(base, (50.0, 80.0), size)
    end = letter.at[0] + letter.width()
    text = Label(follower, (end + dx * size, letter.at[1] + dy * size), share * size)
    assume(text.at[0] > letter.at[0])           # a text set before the label leads it
    joined = _joined([letter, text])
    primes = set(follower) <= PRIMES
    if len(joined) == 1:
        (got,) = joined
        assert got.text == base + follower and got.at == letter.at and got.size == size
        near = NEAR_END_SMALLER if share <= SMALLER else NEAR_END
        assert abs(text.at[0] - end) <= near * size + 1e-9
        assert " " not in follower
        if primes:
            assert abs(dy) <= 0.5 + 1e-9
        else:
            assert not base[-1].isdigit()
            assert dy <= SHIFT[1] + 1e-9
            assert share <= SMALLER + 1e-9 and dy >= -0.1 - 1e-9 or dy >= SHIFT[0] - 1e-9
    else:
        assert joined == [letter, text]
    if not primes and share > SMALLER and abs(dy) < SHIFT[0]:
        assert len(joined) == 2


# ----- an arrow's tip, however it is turned or drawn ----------------------------------------------
STYLES = ("geogebra", "libreoffice", "cad-solid", "cad-open", "two-lines", "marker", "concave",
          "line-arrow")


def _arrow(style: str, tip, turn: float, shaft: float, head: float, half: float):
    """An arrow's SVG (mm) drawn as ``style`` writes it, its tip, and the points of its
    head a label must not name (corners, wings, the shaft's end inside the head)."""
    u = (math.cos(turn), math.sin(turn))
    n = (-u[1], u[0])

    def at(back: float, side: float = 0.0):
        return (tip[0] - back * u[0] + side * n[0], tip[1] - back * u[1] + side * n[1])
    far = at(shaft)
    c1, c2 = at(head, half), at(head, -half)

    def f(p):
        return f"{p[0]:.6f},{p[1]:.6f}"
    line = '<path fill="none" stroke="#000" d="M {} L {}"/>'
    if style == "geogebra":                    # shaft to the head's base, head filled
        svg = line.format(f(far), f(at(head))) + f'<path d="M {f(tip)} L {f(c1)} L {f(c2)} Z"/>'
        parts = [c1, c2, at(head)]
    elif style == "libreoffice":               # shaft into the head, its first point again
        svg = line.format(f(far), f(at(0.9 * head))) + \
            f'<path d="M {f(tip)} L {f(c1)} {f(c2)} {f(tip)} Z"/>'
        parts = [c1, c2, at(0.9 * head)]
    elif style == "cad-solid":                 # shaft to the tip, a solid head over it
        svg = line.format(f(far), f(tip)) + f'<polygon points="{f(c1)} {f(tip)} {f(c2)}"/>'
        parts = [c1, c2]
    elif style == "cad-open":                  # shaft to the tip, an open V of one polyline
        svg = line.format(f(far), f(tip)) + f'<polyline points="{f(c1)} {f(tip)} {f(c2)}"/>'
        parts = [c1, c2]
    elif style == "two-lines":                 # the V as two lines
        svg = line.format(f(far), f(tip)) + line.format(f(tip), f(c1)) + \
            line.format(f(c2), f(tip))
        parts = [c1, c2]
    elif style == "marker":                    # Inkscape: the head is a marker, not drawn
        svg = f'<path style="stroke:#000;marker-end:url(#m)" d="M {f(far)} {f(tip)}"/>'
        parts = []
    elif style == "line-arrow":                # LibreOffice's "Line Arrow": a V outlined
        back = 0.15 * head
        inner = [at(head + back, half), at(back), at(head + back, -half)]
        svg = line.format(f(far), f(at(back))) + \
            f'<path d="M {f(c1)} L {f(tip)} L {f(c2)} L {f(inner[2])} L {f(inner[1])} L ' \
            f'{f(inner[0])} Z"/>'
        parts = [c1, c2, *inner]
    else:                                      # a concave head: apex, wing, notch, wing
        notch = at(0.6 * head)
        svg = line.format(f(far), f(notch)) + \
            f'<path d="M {f(tip)} L {f(c1)} L {f(notch)} L {f(c2)} Z"/>'
        parts = [c1, c2, notch]
    page = ('<svg xmlns="http://www.w3.org/2000/svg" width="300mm" height="300mm" '
            'viewBox="0 0 300 300"><defs><marker id="m"><path d="M0,0 L4,2 L0,4 z"/></marker>'
            '</defs>')
    return page + svg + "</svg>", parts


@settings(max_examples=300, deadline=None)
@given(style=st.sampled_from(STYLES), x=st.floats(60, 240), y=st.floats(60, 240),
       turn=st.floats(-math.pi, math.pi), shaft=st.floats(25, 60), head=st.floats(2.0, 9.0),
       spread=st.floats(0.25, 0.6))
@example(style="line-arrow", x=60.0, y=60.0, turn=0.0, shaft=25.0, head=9.0, spread=0.6)
def test_any_turned_arrows_tip_is_found_and_named(style, x, y, turn, shaft, head, spread):
    """However an arrow is turned, and whichever program drew its head (up to GeoGebra's
    thickest, 10 mm with the line-arrow's back), its tip is a tip, none of its head's
    corners, wings or its shaft's end inside it is a point at all, and a label set by a
    corner of the head, within reach of the tip, names the tip."""
    svg, parts = _arrow(style, (x, y), turn, shaft, head, spread * head)
    d = parse_drawing(svg.encode(), "arrow.svg")
    found = marks(d)
    assert [m.kind for m in found if near(m.at, (x, y), 1e-3)] == [Kind.TIP]
    for p in parts:
        assert not any(near(m.at, p, 0.1) for m in found), (p, found)
    corner = parts[0] if parts else None
    if corner and math.dist(corner, (x, y)) <= 6.0:     # a label just beyond a corner
        d.labels = [Label("b", (corner[0] + 0.3, corner[1] + 0.3 + 0.8 * 3.0), 3.0)]
        assert near(match(d, lambda t: ("p", t))["p", "b"], (x, y), 1e-3)


def test_a_round_polygon_is_a_dot_and_a_small_polygon_keeps_its_corners():
    """A dot drawn as a 16-gon (as a CAD program plots a circle) is one dot at its middle; a
    polygon drawn as one closed stroke, even one smaller than an arrowhead but with no
    sharp corner and no shaft, keeps every corner as a junction."""
    from tarsim.exercises.grading.drawing import Drawing, Outline

    gon = tuple((100 + math.cos(k * math.pi / 8), 50 + math.sin(k * math.pi / 8))
                for k in range(16))
    quad = ((0.0, 0.0), (10.0, 0.0), (12.0, 8.0), (3.0, 9.0))
    triangle = ((30.0, 0.0), (36.0, 0.0), (33.0, 4.0))        # angles 53°, 53°, 74°
    found = marks(Drawing(outlines=[Outline(gon, closed=True), Outline(quad, closed=True),
                                    Outline(triangle, closed=True)]))
    assert {(m.at, m.kind) for m in found} == {
        ((100.0, 50.0), Kind.DOT), *((p, Kind.JUNCTION) for p in quad + triangle)}


def test_two_vectors_drawn_to_one_point_are_two_tips_and_a_halo_is_one_label():
    """V_A and V_A4 equal, drawn to one point (one with a filled head, one a plain line),
    are named by both their labels; each label drawn twice at one place (GeoGebra's white
    halo behind its text) is read once."""
    halo = ('<text x="{x}" y="{y}" font-size="4" fill="none" stroke="#fff">{t}</text>'
            '<text x="{x}" y="{y}" font-size="4">{t}</text>')
    svg = ('<svg xmlns="http://www.w3.org/2000/svg" width="100mm" height="100mm" '
           'viewBox="0 0 100 100"><path d="M 10 50 L 56 50" stroke="#000"/>'
           '<path d="M 60 50 L 56 51.2 L 56 48.8 Z"/><line x1="20" y1="30" x2="60" y2="50" '
           'stroke="#000"/>' + halo.format(x=61, y=48, t="a") + halo.format(x=61, y=54, t="a4")
           + "</svg>")
    d = parse_drawing(svg.encode(), "s.svg")
    assert [label.text for label in d.labels] == ["a", "a4"]
    assert [(m.at, m.kind, m.takes) for m in marks(d) if near(m.at, (60, 50))] == [
        (pytest.approx((60, 50)), Kind.TIP, 2)]
    found = match(d, lambda t: ("v", t))
    assert near(found["v", "a"], (60, 50)) and near(found["v", "a4"], (60, 50))


def test_a_stroke_ending_on_another_is_a_junction_not_a_bare_end():
    """A line drawn up to another (a T) meets it there: a label 2 mm from that meeting and
    1.8 mm from a bare end names the meeting (2 mm against 1.8 + 2 mm); once the lines no
    longer meet, the nearer bare end."""
    from tarsim.exercises.grading.drawing import Drawing

    d = Drawing(segments=[((0.0, 50.0), (100.0, 50.0)),       # the line met
                          ((40.0, 20.0), (40.0, 50.0)),       # the line ending on it
                          ((46.0, 51.0), (80.0, 90.0))],      # a construction line's end
                labels=[Label("n", (42.0, 53.5), 4.0)])
    # The label's letters: x 42–44.2 (n is 0.556 em), y 50.3–53.5 (0.8 em); (40, 50) is
    # 2 mm left of them and 0.3 mm above, (46, 51) 1.8 mm right of them.
    assert near(match(d, lambda t: ("p", t))["p", "n"], (40.0, 50.0))
    d.segments[0] = ((0.0, 40.0), (100.0, 40.0))              # no longer met: a bare end
    assert near(match(d, lambda t: ("p", t))["p", "n"], (46.0, 51.0))


@settings(max_examples=200, deadline=None)
@given(x=st.floats(60, 240), y=st.floats(60, 240), turn=st.floats(-math.pi, math.pi),
       head=st.floats(1.5, 4.5), spread=st.floats(0.2, 0.9), shaft=st.floats(0.0, 0.95),
       onward=st.booleans())
@example(x=177.12, y=168.56, turn=3.36, head=2.8, spread=0.25, shaft=0.86, onward=True)
@example(x=86.38, y=261.84, turn=0.33, head=1.97, spread=0.36, shaft=0.0, onward=True)
def test_a_short_arrows_barbed_head_is_its_tip(x, y, turn, head, spread, shaft, onward):
    """An arrow shorter than its head is long (its shaft ``shaft`` of the head's length, or
    none), with a barbed head (apex, wing, notch at 3/4 of it, wing, as tarsim and Inkscape
    draw it; its apex ``2·atan(spread)`` wide, up to 84°), is a tip at its apex, though no
    shaft longer than the head runs into it; its wings, notch and its shaft's end inside it
    are no points; a label just beyond it names the tip. ``onward``: the next vector leaves from
    the tip (a polygon's next arrow, as Aᵗ_P/C leaves the tip of the short Aⁿ_P/C)."""
    u = (math.cos(turn), math.sin(turn))
    n = (-u[1], u[0])

    def at(back: float, side: float = 0.0):
        return (x - back * u[0] + side * n[0], y - back * u[1] + side * n[1])
    half = spread * head
    c1, notch, c2 = at(head, half), at(0.75 * head), at(head, -half)
    assume(math.dist(c1, c2) <= 6.0 and math.dist(c1, (x, y)) <= 6.0)   # within _ALONE

    def f(p):
        return f"{p[0]:.4f},{p[1]:.4f}"
    svg = [f'<path d="M {f((x, y))} L {f(c1)} L {f(notch)} L {f(c2)} Z"/>']
    inner = at(0.7 * head)                     # the shaft stops inside the head
    if shaft:
        svg.append(f'<path fill="none" stroke="#000" d="M {f(at(head + shaft * head))} '
                   f'L {f(inner)}"/>')
    if onward:
        svg.append(f'<path fill="none" stroke="#000" d="M {f((x, y))} '
                   f'L {f(at(-30.0 * n[0] - 30.0 * u[0], 30.0))}"/>')
    page = ('<svg xmlns="http://www.w3.org/2000/svg" width="300mm" height="300mm" '
            'viewBox="0 0 300 300">' + "".join(svg) + "</svg>")
    d = parse_drawing(page.encode(), "short.svg")
    found = marks(d)
    assert [m.kind for m in found if near(m.at, (x, y), 1e-3)] == [Kind.TIP]
    for p in (c1, c2, notch) + ((inner,) if shaft else ()):
        assert not any(near(m.at, p, 0.1) for m in found), (p, found)
    ahead = at(-3.5)                        # a label set just beyond the apex
    d.labels = [Label("c", (ahead[0] - 0.75, ahead[1] + 1.2), 3.0)]
    assert near(match(d, lambda t: ("p", t))["p", "c"], (x, y), 1e-3)


def test_a_dart_that_is_no_arrowhead_keeps_its_corners():
    """A small quadrilateral with a reflex corner off the line from the opposite corner to
    the middle of the other two (a bent flag, not a barbed head), or with a blunt corner
    there, is no arrowhead: its corners stay junctions."""
    from tarsim.exercises.grading.drawing import Drawing, Outline

    flag = ((0.0, 0.0), (4.0, 1.0), (2.8, 1.3), (0.5, 3.0))     # reflex corner 0.9 mm aside
    blunt = ((20.0, 0.0), (21.0, 1.5), (20.6, 0.0), (21.0, -1.5))   # its apex 112° wide
    found = marks(Drawing(outlines=[Outline(flag, closed=True), Outline(blunt, closed=True)]))
    assert {(m.at, m.kind) for m in found} == {(p, Kind.JUNCTION) for p in flag + blunt}


def test_a_number_in_a_ring_is_a_steps_number_never_a_subscript():
    """A step's number in its ring just after a label's end (``A_C ⑬`` as a worked figure
    sets it, the ring 1.85 mm round the 1.95 mm number) stays a number of its own, and the
    sheet takes it and its ring for a step's; a subscript set as a text of its own beside a
    pin's circle (``a`` ``4``, the circle 1.2 mm, 0.5 mm from where the 4 starts but 1.3 mm
    from its letters' middle) is still the label's, and so is one beside a dot smaller
    than half its size."""
    from tarsim.exercises.grading.sheet import split

    svg = ('<svg xmlns="http://www.w3.org/2000/svg" width="100mm" height="100mm" '
           'viewBox="0 0 100 100">'
           '<text x="10" y="20" font-size="3.4">A<tspan dy="0.95" font-size="2.45">C</tspan>'
           '</text><circle cx="16.8" cy="19.3" r="1.85" fill="none" stroke="#000"/>'
           '<text x="16.8" y="19.98" font-size="1.95" text-anchor="middle">13</text>'
           '<circle cx="51.6" cy="50.6" r="1.2"/><text x="50.1" y="49.7" font-size="3.5">a'
           '</text><text x="52.1" y="50.8" font-size="2.3">4</text>'
           '<circle cx="75.1" cy="49.9" r="0.18"/><text x="74.8" y="51.0" font-size="3.5">b'
           '</text><text x="75.4" y="51.3" font-size="2.3">4</text></svg>')
    d = parse_drawing(svg.encode(), "ring.svg")
    assert sorted(label.text for label in d.labels) == ["13", "AC", "a4", "b4"]
    polygons, space = split(d, ["A", "C"])
    assert "13" not in [label.text for label in polygons.labels + space.labels]
    assert (16.8, 19.3) not in [c for c, _ in polygons.circles]


def test_a_line_run_a_centimetre_past_a_tip_ends_in_nothing_a_label_names():
    """A working line drawn through an arrow's tip and on a centimetre past it, read back a
    few micrometres longer (10.000005 mm, as a mm is read as 3.7795296 px), ends in no
    point: a label by that end (1.1 mm, 3.1 with a bare end's cost) names the tip, 6.4 mm
    off."""
    from tarsim.exercises.grading.drawing import Drawing, Outline

    tip = (50.0, 50.0)
    d = Drawing(outlines=[Outline(((20.0, 50.0), (47.0, 50.0))),
                          Outline((tip, (47.0, 51.0), (47.0, 49.0)), closed=True),
                          Outline(((50.0, 40.0 - 5e-6), (50.0, 60.0 + 5e-6)))],
                labels=[Label("b", (51.0, 59.5), 4.0)])
    found = marks(d)
    assert not [m for m in found if m.kind is Kind.END and m.at[0] == 50.0]
    assert near(match(d, lambda t: ("p", t))["p", "b"], tip)
