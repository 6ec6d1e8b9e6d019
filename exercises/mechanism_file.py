"""Read a mechanism file (TOML) into the SI model, with errors that say file:line.

The format is documented in the README. Lengths are keyed by the two point names
run together, as a textbook writes them (``O2A = 100``, ``AB = 250``).
"""

from __future__ import annotations

import difflib
import math
import re
import sys
import tomllib
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from ..constructions.errors import AssemblyError, BranchError, DeadPoint, InputError
from ..constructions.reference.solver import follow_branches
from ..constructions.model import (LENGTH_UNITS, Arc, Contact, Drive, GivenRate, Link,
                                  Mechanism, Profile, Slide, SlideKind, Units, contact_arc,
                                  contact_slide)
from .toml_depth import check_depth

__all__ = ["load_mechanism", "parse_mechanism", "SourceMap", "read_source", "read_toml",
           "LARGEST", "MOST_BYTES", "MOST_POINTS", "in_range", "radians_in_turn"]

_ON_LINE = 64 * sys.float_info.epsilon
"""A point whose h² off a link's base line is within this many of the largest square of
the lengths that place it lies on the line: that much is the rounding of h² itself."""

LARGEST = 1e30
"""The largest size of a number tarsim takes from a file; its reciprocal is the smallest
non-zero one. Velocities and accelerations multiply and square these (ω² r, |A|²), and
within this range none of them overflows or underflows a float."""

RANGE = "between 1e-30 and 1e30 in size, or 0"
""":data:`LARGEST` as an error message says it."""

MOST_BYTES = 1_000_000
"""The largest file tarsim reads. A textbook mechanism takes a few kilobytes; the cap is
read, not trusted to a file's stated size, so a device or a pipe cannot run it out of
memory."""

MOST_POINTS = 100
"""The most points a mechanism may name. Every point is constructed, labelled and placed
clear of the others on each figure, and that placing grows faster than the count."""

_CONTROL = re.compile("[\x00-\x1f\x7f-\x9f\u202a-\u202e\u2066-\u2069]")
"""Control characters, and the bidirectional overrides that reorder what a figure shows."""

_NAME = re.compile(r"^[A-Za-z][A-Za-z0-9_']*$")
_EXERCISE = ("ask", "lang", "names", "grading", "forces", "mass", "force", "couple")
"""What an exercise file adds to its mechanism, read by exercise_file, loads_file and
names: a mechanism read alone (load_mechanism) leaves it be."""
_TOP = ("name", "source", "description", "units", "frame", "link", "slider", "contact", "input",
        "assembly") + _EXERCISE
_BRANCHES = ("left", "right", "forward", "backward")


def load_mechanism(path: str | Path) -> Mechanism:
    """Read ``path`` and return the mechanism it describes.

    Raises
    ------
    InputError
        If the file cannot be read, is not valid TOML, or describes an
        impossible or incomplete mechanism; the message names file:line.
    """
    return parse_mechanism(read_source(path), str(path))


def line_of(error: AssemblyError, path: str | Path) -> int | None:
    """The line of the file at ``path`` where what ``error`` says is stated, or None.

    A dead point is the input's angle; a missing or unfit branch, the point's key in
    [assembly] (or that table, or with none the first [[link]] that lists the point);
    anything else about a link, that link's [[link]] table. Assembly errors arise after
    the file is read, so it is read again to find the line.
    """
    try:
        text = read_source(path)
        data = read_toml(text, str(path))
    except InputError:
        return None
    where = SourceMap(text)
    if isinstance(error, DeadPoint):
        return where.key("angle", "input")
    raw = data.get("link")
    links = [k if isinstance(k, dict) else {} for k in raw] if isinstance(raw, list) else []

    def table_of(wanted) -> int | None:
        index = next((i for i, k in enumerate(links) if wanted(k)), None)
        return where.header("link", index) if index is not None else None

    if isinstance(error, BranchError):
        if "assembly" in data:
            return where.key(error.joint, "assembly")
        return table_of(lambda k: error.joint in (k.get("points") or ()))
    if error.link is not None:
        return table_of(lambda k: k.get("number") == error.link)
    return None


def parse_mechanism(text: str, filename: str = "<string>") -> Mechanism:
    """Parse TOML text into a :class:`Mechanism` (see :func:`load_mechanism`)."""
    return _Reader(read_toml(text, filename), SourceMap(text), filename).mechanism()


def read_source(path: str | Path) -> str:
    """The text of the file at ``path``.

    Raises
    ------
    InputError
        If it cannot be read, or is not UTF-8 text (naming the line of the first bad byte).
    """
    path = Path(path)
    try:
        with path.open("rb") as f:
            data = f.read(MOST_BYTES + 1)
        if len(data) > MOST_BYTES:
            raise InputError(f"is larger than {MOST_BYTES // 1000:,} kB, the most tarsim reads; "
                             "a mechanism file takes a few kB", file=str(path))
        return data.decode("utf-8-sig")        # a byte-order mark, as Notepad saves, read past
    except UnicodeDecodeError as e:
        raise InputError(f"is not UTF-8 text (byte 0x{e.object[e.start]:02x}); save it as UTF-8",
                         file=str(path), line=e.object[:e.start].count(b"\n") + 1) from None
    except OSError as e:
        raise InputError(f"cannot read the file: {e.strerror or e}", file=str(path)) from None


def read_toml(text: str, filename: str) -> dict[str, Any]:
    """The tables of a TOML text; an InputError at file:line if it is not valid TOML, or
    nests deeper than tomllib reads in good time (:mod:`.toml_depth`)."""
    check_depth(text, filename)
    try:
        return tomllib.loads(text)
    except tomllib.TOMLDecodeError as e:
        raise _toml_error(e, text, filename) from None
    except RecursionError:
        raise InputError("nests arrays or tables too deeply to read as a mechanism",
                         file=filename) from None


def _float(v: int | float) -> float:
    """``v`` as a float; an integer too large for one is infinite."""
    try:
        return float(v)
    except OverflowError:
        return math.inf


SIZES = (1e-6, 1e6)
"""The sizes a cam, rotor or load file's numbers may have (0 aside), in the file's own
units: wide enough for any textbook part, narrow enough that every figure can be drawn."""


def file_number(v, what: str) -> float:
    """A cam, rotor or load file's number: finite, and 0 or of a size within :data:`SIZES`.

    Raises
    ------
    ValueError
        Saying what is wrong, for the caller to place at its file:line.
    """
    if isinstance(v, bool) or not isinstance(v, (int, float)) or not math.isfinite(v):
        raise ValueError(f"{what} must be a number, got {v!r}")
    low, high = SIZES
    if v != 0 and not low <= abs(v) <= high:
        raise ValueError(f"{what} must be between {low:g} and {high:g} in size (or 0), "
                         f"got {v:g}")
    return float(v)


def in_range(x: float) -> bool:
    """True if ``x`` is 0 or finite and of a size within 1/:data:`LARGEST` … :data:`LARGEST`."""
    return x == 0.0 or (math.isfinite(x) and 1.0 / LARGEST <= abs(x) <= LARGEST)


def radians_in_turn(value: float, unit: str) -> float:
    """An angle in ``unit`` ("deg" or "rad") as radians, less whole turns.

    Degrees are reduced before they are converted, where the remainder is exact, so
    θ = 1e9° is the 280° it means; the sign is kept (−90° stays −90°).

    >>> round(math.degrees(radians_in_turn(-1e9, "deg")), 9)
    -280.0
    """
    if unit == "rad":
        return math.fmod(value, math.tau)
    return math.radians(math.fmod(value, 360.0))


def _toml_error(e: tomllib.TOMLDecodeError, text: str, filename: str) -> InputError:
    msg = str(e)
    m = re.search(r"\(at line (\d+), column (\d+)\)", msg)
    if m:
        return InputError(f"not valid TOML: {msg[:m.start()].strip()}", file=filename,
                          line=int(m.group(1)), column=int(m.group(2)))
    m = re.search(r"\(at end of document\)", msg)
    # The file ended too soon: point at its last character.
    return InputError(f"not valid TOML: {msg[:m.start()].strip() if m else msg}", file=filename,
                      line=text.count("\n") + 1, column=len(text) - text.rfind("\n"))


@dataclass
class SourceMap:
    """Finds the line of a table or key, since tomllib keeps no positions."""

    text: str

    def __post_init__(self) -> None:
        self.lines = self.text.splitlines()

    def header(self, table: str, index: int = 0) -> int | None:
        """Line (1-based) of the ``index``-th ``[table]`` or ``[[table]]`` header."""
        pat = re.compile(r"^\s*\[\[?\s*" + re.escape(table) + r"\s*\]\]?\s*(#.*)?$")
        hits = [i + 1 for i, line in enumerate(self.lines) if pat.match(line)]
        return hits[index] if index < len(hits) else None

    def key(self, key: str, table: str | None = None, index: int = 0) -> int | None:
        """Line of ``key`` inside the ``index``-th ``table`` (or the top level)."""
        start = self.header(table, index) if table else 0
        if table and start is None:
            # Written inline (``input = { … }``): the line that opens it.
            return self._assignment(table)
        pat = re.compile(r"(^|[\s{,])" + re.escape(key) + r"\s*=")
        for i in range(start or 0, len(self.lines)):
            line = self.lines[i]
            if i >= (start or 0) + (1 if table else 0) and re.match(r"^\s*\[", line):
                break
            if pat.search(line.split("#", 1)[0]):
                return i + 1
        if not table:
            return self.header(key) or self._assignment(key)
        return start

    def _assignment(self, key: str) -> int | None:
        pat = re.compile(r"^\s*" + re.escape(key) + r"\s*=")
        return next((i + 1 for i, line in enumerate(self.lines) if pat.match(line)), None)


class _Reader:
    def __init__(self, data: dict[str, Any], where: SourceMap, filename: str):
        self.d = data
        self.where = where
        self.file = filename
        self.given: GivenRate | None = None
        self._slides: tuple[Slide, ...] = ()
        self.file_origin = (0.0, 0.0)
        """The frame's first point as the file gives it, the model's (0, 0) (see :meth:`xy`)."""

    # ----- errors --------------------------------------------------------------
    def fail(self, message: str, *, table: str | None = None, index: int = 0,
             key: str | None = None) -> InputError:
        line = (self.where.key(key, table, index) if key
                else self.where.header(table, index) if table else None)
        label = self._entry(table, index) if table else None
        if key:
            # A TOML path for a plain table ("input.link"); "link 3, AB" for a numbered one.
            sep = ", " if table in ("link", "slider", "contact") else "."
            # A key is the file's own text: a bidi override in it would reorder the line.
            key = _CONTROL.sub(lambda m: f"\\u{ord(m.group()):04x}", key)
            label = f"{label}{sep}{key}" if label else key
        return InputError(message, file=self.file, line=line, key=label)

    def _entry(self, table: str, index: int) -> str:
        """How an error names a table: "link 3" by its number, else "slider 2" by its place
        among the ``[[slider]]`` tables; a plain table by its name."""
        if table not in ("link", "slider", "contact"):
            return table
        entries = self.d.get(table)
        entry = entries[index] if isinstance(entries, list) and index < len(entries) else None
        number = entry.get("number") if isinstance(entry, dict) else None
        if table == "link" and isinstance(number, int) and not isinstance(number, bool):
            return f"link {number}"
        return f"{table} {index + 1}"

    def unknown(self, got: str, valid: list[str] | tuple[str, ...], what: str,
                **where) -> InputError:
        close = difflib.get_close_matches(got, list(valid), n=1)
        hint = (f"; did you mean '{close[0]}'?" if close
                else f"; expected one of: {', '.join(valid)}")
        return self.fail(f"unknown {what} '{got}'{hint}", **where)

    # ----- top level -------------------------------------------------------------
    def mechanism(self) -> Mechanism:
        for k in self.d:
            if k not in _TOP:
                raise self.unknown(k, _TOP, "setting", key=k)
        for k in ("source", "description"):
            if k in self.d:
                self.text(self.d[k], k, lines=True, key=k)
        name = self.text(self.d.get("name", Path(self.file).stem), "name", key="name")
        self.units = self.read_units()
        frame = self.read_frame()
        # A curved block gains its pin at the centre of curvature while the sliders
        # are read, so the links are final only after them.
        self.links = {k.number: k for k in [frame] + self.read_links(frame)}
        slides: list[Slide] = []
        arcs: list[Arc] = []
        for i, t in enumerate(self.list_of("slider")):
            joint = self.read_slider(i, t)
            (arcs if isinstance(joint, Arc) else slides).append(joint)
        for i, t in enumerate(self.list_of("contact")):
            c = self.read_contact(i, t)
            if c.face.is_circle:
                arcs.append(contact_arc(c))
            else:
                slides.append(contact_slide(c, self.links[c.face.link]))
        mech_links = tuple(self.links.values())
        named = {n for k in mech_links for n in k.names}
        if len(named) > MOST_POINTS:
            raise self.fail(f"names {len(named):,} points; a mechanism may have at most "
                            f"{MOST_POINTS}, each drawn and labelled on every figure")
        self._slides = tuple(slides)
        drive = self.read_input()
        branches = self.read_assembly(mech_links, tuple(slides))
        ox, oy = self.file_origin
        mech = Mechanism(mech_links, drive, tuple(slides), branches, self.units,
                         name, self.file, tuple(arcs), given=self.given,
                         origin=(ox * self.units.metres + 0.0, oy * self.units.metres + 0.0))
        mech = follow_branches(mech)
        dof, n, f1, f2 = mech.mobility()
        if dof != 1:
            raise self.fail(
                f"the mechanism has {dof} degrees of freedom (Grübler: 3({n} − 1) − 2·{f1} − {f2}"
                f" = {dof}) but [input] drives one link; "
                + ("add a link or joint to constrain it" if dof > 1 else
                   "it cannot move: check the links and joints"), table="input")
        return mech

    def list_of(self, table: str) -> list[dict[str, Any]]:
        v = self.d.get(table, [])
        if not isinstance(v, list) or not all(isinstance(x, dict) for x in v):
            raise self.fail(f"write each {table} as its own [[{table}]] table", table=table)
        return v

    def table(self, name: str, required: bool) -> dict[str, Any]:
        v = self.d.get(name)
        if v is None:
            if required:
                raise InputError(f"the file has no [{name}] table", file=self.file)
            return {}
        if not isinstance(v, dict):
            raise self.fail(f"[{name}] must be a table", key=name)
        return v

    def read_units(self) -> Units:
        u = self.table("units", False)
        allowed = {"length": tuple(LENGTH_UNITS), "angle": ("deg", "rad"),
                   "angular_velocity": ("rad/s", "rpm")}
        for k, v in u.items():
            if k not in allowed:
                raise self.unknown(k, tuple(allowed), "unit setting", table="units", key=k)
            if v not in allowed[k]:
                raise self.unknown(str(v), allowed[k], f"{k} unit", table="units", key=k)
        return Units(u.get("length", "mm"), u.get("angle", "deg"),
                     u.get("angular_velocity", "rad/s"))

    # ----- numbers ---------------------------------------------------------------
    def number(self, v: Any, what: str, *, size: bool = False, bounded: bool = True,
               **where) -> float:
        """A finite number, no larger than :data:`LARGEST` if ``bounded``; with ``size`` (a
        length, a rate) none smaller than its reciprocal either, but 0."""
        if isinstance(v, bool) or not isinstance(v, (int, float)):
            raise self.fail(f"{what} must be a number, got {v!r}", **where)
        x = _float(v)
        if not math.isfinite(x):
            raise self.fail(f"{what} must be a finite number, got {v!r:.40}", **where)
        if (bounded and abs(x) > LARGEST) or (size and not in_range(x)):
            raise self.fail(f"{what} = {x:.4g} is out of the range tarsim takes ({RANGE})",
                            **where)
        return x

    def length(self, v: Any, what: str, **where) -> float:
        x = self.number(v, what, size=True, **where)
        if x <= 0:
            raise self.fail(f"{what} must be a positive length, got {v:g}", **where)
        return x * self.units.metres

    def pair(self, v: Any, what: str, **where) -> tuple[float, float]:
        """A pair [x, y] of numbers, as the file gives it."""
        if not (isinstance(v, list) and len(v) == 2):
            raise self.fail(f"{what} must be a pair [x, y], got {v!r}", **where)
        return (self.number(v[0], what, **where), self.number(v[1], what, **where))

    def xy(self, v: Any, what: str, **where) -> tuple[float, float]:
        """A point the file places, in metres from the frame's first point.

        A line's equation, an intersection's rounding and every conditioning are measured
        from the origin, so a linkage drawn 1 km from it would lose digits, and could even
        pass a check it should fail, that the same linkage at the origin keeps. The model is
        therefore placed about its frame, moved in the file's own units before they are
        turned into metres, so that a file moved whole gives the same model to the bit
        wherever its numbers allow; ``Mechanism.origin`` says points back where the file
        put them.
        """
        (x, y), (ox, oy), s = self.pair(v, what, **where), self.file_origin, self.units.metres
        return ((x - ox) * s + 0.0, (y - oy) * s + 0.0)

    def angle(self, v: Any, what: str, **where) -> float:
        """Any finite angle: it is taken less whole turns (:func:`radians_in_turn`)."""
        return radians_in_turn(self.number(v, what, bounded=False, **where), self.units.angle)

    def text(self, v: Any, what: str, *, lines: bool = False, **where) -> str:
        """A free text (a name, a source): a string with no control character in it."""
        if not isinstance(v, str):
            raise self.fail(f"{what} must be a string, got {v!r:.40}", **where)
        bad = next((c for c in _CONTROL.findall(v) if not (lines and c in "\n\t")), None)
        if bad is not None:
            raise self.fail(f"{what} holds the control character U+{ord(bad):04X}; "
                            "remove it", **where)
        return v

    def name(self, v: Any, what: str, **where) -> str:
        if not (isinstance(v, str) and _NAME.match(v)):
            raise self.fail(f"{what} must be a point name such as \"A\" or \"O2\", got {v!r}",
                            **where)
        return v

    # ----- frame and links -----------------------------------------------------------
    def read_frame(self) -> Link:
        f = self.table("frame", True)
        for k in f:
            self.name(k, "a frame point", table="frame", key=k)
        if not f:
            raise self.fail("names no fixed point", table="frame")
        first = next(iter(f))
        self.file_origin = self.pair(f[first], f"frame point {first}", table="frame", key=first)
        return Link(1, tuple((k, self.xy(v, f"frame point {k}", table="frame", key=k))
                             for k, v in f.items()), "frame")

    def read_links(self, frame: Link) -> list[Link]:
        out: list[Link] = []
        seen = {1}
        for i, t in enumerate(self.list_of("link")):
            where = {"table": "link", "index": i}
            for k in t:
                if k not in ("number", "name", "points", "lengths", "sides"):
                    raise self.unknown(k, ("number", "name", "points", "lengths", "sides"),
                                       "link setting", key=k, **where)
            if "number" not in t:
                raise self.fail("a link needs its number (the frame is 1)", **where)
            n = t["number"]
            if isinstance(n, bool) or not isinstance(n, int) or n < 2:
                raise self.fail(f"a moving link's number is a whole number from 2 up, got {n!r}",
                                key="number", **where)
            if n in seen:
                raise self.fail(f"link {n} is defined twice", key="number", **where)
            seen.add(n)
            names = t.get("points")
            if not (isinstance(names, list) and names):
                raise self.fail(f"link {n} needs points = [\"…\", …]", **where)
            names = [self.name(p, f"a point of link {n}", key="points", **where) for p in names]
            if len(set(names)) != len(names):
                raise self.fail(f"link {n} lists a point twice", key="points", **where)
            local = self.shape(n, names, t, where)
            label = self.text(t.get("name", ""), f"the name of link {n}", key="name", **where)
            out.append(Link(n, tuple(zip(names, local)), label))
        return out

    def shape(self, n: int, names: list[str], t: dict[str, Any],
              where: dict) -> list[tuple[float, float]]:
        lengths = t.get("lengths", {})
        if not isinstance(lengths, dict):
            raise self.fail(f"lengths of link {n} must be a table such as {{ AB = 250 }}",
                            key="lengths", **where)
        table: dict[frozenset[str], float] = {}
        for key, v in lengths.items():
            pair = _split_pair(key, names)
            if pair is None:
                pairs = [a + b for a in names for b in names if a != b]
                raise self.unknown(key, pairs, f"length of link {n}", key=key, **where)
            table[frozenset(pair)] = self.length(v, f"length {key} of link {n}", key=key, **where)
        sides = t.get("sides", {})

        def span(a: str, b: str) -> float:
            v = table.get(frozenset((a, b)))
            if v is None:
                raise self.fail(f"link {n} needs the length {a}{b}", key="lengths", **where)
            return v

        if len(names) == 1:
            return [(0.0, 0.0)]
        base = span(names[0], names[1])
        local = [(0.0, 0.0), (base, 0.0)]
        for p in names[2:]:
            r0, r1 = span(names[0], p), span(names[1], p)
            x = (r0 * r0 - r1 * r1 + base * base) / (2 * base)
            h2 = r0 * r0 - x * x
            if h2 < -1e-9 * base * base:
                raise self.fail(f"the lengths {names[0]}{p}, {names[1]}{p} and "
                                f"{names[0]}{names[1]} of link {n} do not close a triangle",
                                key="lengths", **where)
            # h² is a difference of squares: its rounding is some units of eps in the
            # largest square, so a point within that of the line is on it (h = 3.7e-9 m
            # from h² = 1.4e-17 is rounding, whatever order the points are listed in).
            on_line = h2 <= _ON_LINE * max(r0 * r0, r1 * r1, base * base)
            h = 0.0 if on_line else math.sqrt(h2)
            side = sides.get(p) if isinstance(sides, dict) else None
            if not on_line and side not in ("left", "right"):
                raise self.fail(f"say on which side of {names[0]}→{names[1]} point {p} lies: "
                                f'sides = {{ {p} = "left" }} or "right"', key="lengths", **where)
            local.append((x, h if side == "left" else -h))
        return local

    # ----- sliders, input, assembly ---------------------------------------------------
    def read_slider(self, i: int, t: dict[str, Any]) -> Slide | Arc:
        where = {"table": "slider", "index": i}
        allowed = ("kind", "link", "point", "on", "through", "angle", "offset", "centre",
                   "radius", "side")
        for k in t:
            if k not in allowed:
                raise self.unknown(k, allowed, "slider setting", key=k, **where)
        kind = t.get("kind", "block")
        if kind not in ("block", "pin"):
            raise self.unknown(str(kind), ("block", "pin"), "slider kind", key="kind", **where)
        link = self.link_number(t.get("link"), "link", where)
        point = self.name(t.get("point"), "the sliding point", key="point", **where)
        if point not in self.links[link].names:
            raise self.unknown(point, self.links[link].names, f"point of link {link}",
                               key="point", **where)
        on = self.link_number(t.get("on", 1), "on", where)
        if on == link:
            raise self.fail(f"link {link} cannot slide on itself", key="on", **where)
        if kind == "block" and len(self.links[link].names) != 1:
            raise self.fail(f"a sliding block carries one point; link {link} has "
                            f"{len(self.links[link].names)}", key="link", **where)
        if "centre" in t or "radius" in t:
            return self.curved_guide(kind, link, point, on, t, where)
        if "side" in t:
            raise self.fail("side applies to a curved guide (with centre and radius)",
                            key="side", **where)
        offset = self.number(t.get("offset", 0.0), "offset", key="offset",
                             **where) * self.units.metres
        if on == 1:
            through = t.get("through")
            if isinstance(through, str):
                if through not in self.links[1].names:
                    raise self.unknown(through, self.links[1].names, "frame point",
                                       key="through", **where)
                base = self.links[1].local(through)
            elif through is None:
                raise self.fail("a guide on the frame needs through = \"O2\" or [x, y]", **where)
            else:
                base = self.xy(through, "through", key="through", **where)
            if "angle" not in t:
                raise self.fail("a guide on the frame needs its angle", **where)
            a = self.angle(t["angle"], "angle", key="angle", **where)
            d = (math.cos(a), math.sin(a))
            return Slide(SlideKind(kind), link, point, 1,
                         (base[0] - offset * d[1], base[1] + offset * d[0]), d)
        for k in ("through", "angle"):
            if k in t:
                raise self.fail(f"a slot on moving link {on} runs along its axis; give only "
                                "offset, not " + k, key=k, **where)
        return Slide(SlideKind(kind), link, point, on, (0.0, offset), (1.0, 0.0))

    def curved_guide(self, kind: str, link: int, point: str, on: int, t: dict[str, Any],
                     where: dict) -> Arc:
        """Read a slider on a circular guide: its centre of curvature and radius.

        A block turns with the guide's radius, so it is given a pin at the centre of
        curvature, on the ``side`` of its axis (its local +x, the tangent at its point).
        """
        for k in ("through", "angle", "offset"):
            if k in t:
                raise self.fail(f"a curved guide is given by its centre and radius, not {k}",
                                key=k, **where)
        for k in ("centre", "radius"):
            if k not in t:
                raise self.fail(f"a curved guide needs its {k}: centre = a point of link {on} "
                                f"(the centre of curvature) and radius = its radius", **where)
        guide = self.links[on]
        centre = self.name(t["centre"], "the centre of curvature", key="centre", **where)
        if centre not in guide.names:
            raise self.unknown(centre, guide.names, f"point of link {on}", key="centre", **where)
        radius = self.length(t["radius"], "the guide's radius", key="radius", **where)
        side = t.get("side", "left")
        if side not in ("left", "right"):
            raise self.unknown(str(side), ("left", "right"), "side", key="side", **where)
        if kind == "block":
            block = self.links[link]
            if centre in block.names:
                raise self.fail(f"link {link} already has a point {centre}; the block's pin at "
                                "the centre of curvature takes that name", key="centre", **where)
            across = radius if side == "left" else -radius
            self.links[link] = Link(link, block.points + ((centre, (0.0, across)),), block.name)
        return Arc(SlideKind(kind), link, point, on, centre, radius, side=side)

    def read_contact(self, i: int, t: dict[str, Any]) -> Contact:
        """Read a circle-on-face contact; the caller turns it into its equivalent slide."""
        where = {"table": "contact", "index": i}
        allowed = ("circle", "face", "side", "rolling")
        for k in t:
            if k not in allowed:
                raise self.unknown(k, allowed, "contact setting", key=k, **where)
        for k in ("circle", "face"):
            if k not in t:
                raise self.fail(f"a contact needs its {k}, e.g. "
                                + ('circle = { link = 2, centre = "C", radius = 40 }'
                                   if k == "circle" else
                                   'face = { link = 3, through = "F", angle = 0 }'), **where)
        circle = self.read_profile(t["circle"], "circle", where)
        face = self.read_profile(t["face"], "face", where)
        if circle.link == face.link:
            raise self.fail(f"the circle and the face are both on link {face.link}; a contact "
                            "joins two links", key="face", **where)
        rolling = t.get("rolling", False)
        if not isinstance(rolling, bool):
            raise self.fail(f"rolling must be true or false, got {rolling!r}", key="rolling",
                            **where)
        side = t.get("side")
        if face.is_circle:
            sides = ("outside", "inside")
            side = "outside" if side is None else side
            if rolling and side == "inside" and not circle.radius < face.radius:
                raise self.fail(f"a wheel rolls inside a circle only if it is the smaller: "
                                f"the circle of link {circle.link} is not smaller than that of "
                                f"link {face.link}", key="side", **where)
        else:
            sides = ("left", "right")
            if side is None:
                raise self.fail(f"say on which side of the face of link {face.link} the circle "
                                'lies: side = "left" or "right" of the face\'s direction', **where)
        if side not in sides:
            raise self.unknown(str(side), sides, "side", key="side", **where)
        return Contact(circle, face, side, rolling)

    def read_profile(self, v: Any, key: str, where: dict) -> Profile:
        """Read ``circle = { … }`` or ``face = { … }``: only a circle on a flat face."""
        if not isinstance(v, dict):
            raise self.fail(f"{key} must be an inline table such as "
                            + ('{ link = 2, centre = "C", radius = 40 }' if key == "circle"
                               else '{ link = 3, through = "F", angle = 0 }'), key=key, **where)
        allowed = ("link", "centre", "radius", "through", "angle")
        for k in v:
            if k not in allowed:
                raise self.unknown(k, allowed, f"{key} setting", key=key, **where)
        if "link" not in v:
            raise self.fail(f"the {key} needs the number of the link that carries it, "
                            "e.g. link = 2", key=key, **where)
        link = self.link_number(v["link"], key, where)
        round_, flat = "centre" in v or "radius" in v, "through" in v or "angle" in v
        if round_ and flat:
            raise self.fail(f"the {key} of link {link} is given both a centre and radius (a "
                            "circle) and a point and angle (a flat face): give one", key=key,
                            **where)
        if key == "circle" and flat:
            raise self.fail(f"the circle of link {link} is given a point and an angle: a contact "
                            "puts a circle (centre and radius) on a face or on another circle "
                            "(a roller on a flat cam face is written with the roller as the "
                            "circle)", key=key, **where)
        names = self.links[link].names

        def point(name_key: str, what: str) -> str:
            p = self.name(v[name_key], what, key=key, **where)
            if p not in names:
                raise self.unknown(p, names, f"point of link {link}", key=key, **where)
            return p

        if key == "circle" or round_:
            if "centre" not in v:
                raise self.fail(f"the circular profile of link {link} needs a centre, a point "
                                "of that link (the common normal runs through it)", key=key,
                                **where)
            if "radius" not in v:
                raise self.fail(f"the circular profile of link {link} needs a radius (the "
                                "common normal runs through its centre)", key=key, **where)
            return Profile(link, centre=point("centre", "the circle's centre"),
                           radius=self.length(v["radius"], f"the radius of the circle of link "
                                              f"{link}", key=key, **where))
        if "through" not in v:
            raise self.fail(f"the flat face of link {link} needs a point of that link it runs "
                            "through (through = \"F\")", key=key, **where)
        if "angle" not in v:
            raise self.fail(f"the flat face of link {link} needs an angle in the link's own frame "
                            "(the common normal is perpendicular to it)", key=key, **where)
        return Profile(link, through=point("through", "the face's point"),
                       angle=self.angle(v["angle"], "the face's angle", key=key, **where))

    def link_number(self, v: Any, key: str, where: dict) -> int:
        if isinstance(v, bool) or not isinstance(v, int):
            raise self.fail(f"{key} must be a link number, got {v!r}", key=key, **where)
        if v not in self.links:
            raise self.unknown(str(v), [str(n) for n in sorted(self.links)], "link",
                               key=key, **where)
        return v

    def read_input(self) -> Drive:
        t = self.table("input", True)
        where = {"table": "input"}
        for k in t:
            if k not in ("link", "angle", "omega", "alpha", "speed"):
                raise self.unknown(k, ("link", "angle", "omega", "alpha", "speed"),
                                   "input setting", key=k, **where)
        if "link" not in t:
            raise self.fail("must name the input link, e.g. link = 2", **where)
        link = self.link_number(t["link"], "link", where)
        if link == 1:
            raise self.fail("the frame (link 1) cannot be the input", key="link", **where)
        if "angle" not in t:
            raise self.fail(f"[input] needs the angle of link {link}", **where)
        angle = self.angle(t["angle"], "angle", key="angle", **where)
        self.given = self.read_given(t, link, where)
        if self.given is not None:
            # The input's own rates follow from the member given; 1 rad/s stands in for now.
            return Drive(link, angle, 1.0, 0.0, self.given.second_given)
        omega = self.number(t.get("omega", 0.0), "omega", size=True, key="omega", **where)
        if self.units.angular_velocity == "rpm":
            omega *= 2 * math.pi / 60
        alpha = self.number(t.get("alpha", 0.0), "alpha", size=True, key="alpha", **where)
        return Drive(link, angle, omega, alpha, "alpha" in t)

    def read_given(self, t: dict, link: int, where: dict) -> GivenRate | None:
        """``speed = { point = "C", value = 3000, acceleration = 0 }`` (a point on a frame
        guide, along the guide, in the file's length unit per second) or ``omega = { link =
        3, value = 5, alpha = 0 }`` (another link's ω): the input given by another member."""
        speed, omega = t.get("speed"), t.get("omega")
        if speed is None and not isinstance(omega, dict):
            return None
        if speed is not None and omega is not None:
            raise self.fail("give the input's omega or a speed, not both", key="speed", **where)
        if speed is not None:
            key, spec, allowed = "speed", speed, ("point", "value", "acceleration")
        else:
            key, spec, allowed = "omega", omega, ("link", "value", "alpha")
        if not isinstance(spec, dict) or "value" not in spec:
            raise self.fail(f"{key} = {{ {allowed[0]} = …, value = … }} gives the input by "
                            "another member's motion", key=key, **where)
        for k in spec:
            if k not in allowed:
                raise self.unknown(k, allowed, f"{key} setting", key=key, **where)
        value = self.number(spec["value"], f"{key} value", size=True, key=key, **where)
        if value == 0.0:
            raise self.fail(f"the {key} given is 0, which leaves the mechanism at rest; give a "
                            "nonzero one, or the input's own omega = 0", key=key, **where)
        second_key = allowed[2]
        second = self.number(spec.get(second_key, 0.0), f"{key} {second_key}", size=True,
                             key=key, **where)
        if key == "speed":
            point = spec.get("point")
            on_guide = [s for s in self._slides if s.point == point and s.guide_link == 1]
            if not on_guide:
                runs = sorted({s.point for s in self._slides if s.guide_link == 1})
                raise self.fail(f"speed gives the motion of a point on a frame guide (a piston, "
                                f"a slider, a wheel's centre); '{point}' is none: "
                                f"{', '.join(runs) or 'this mechanism has none'}", key=key,
                                **where)
            m = self.units.metres
            return GivenRate("speed", point, value * m, second * m, second_key in spec)
        target = self.link_number(spec.get("link"), key, where)
        if target in (1, link):
            raise self.fail(f"omega = {{ link = {target}, … }} gives another link's ω; give the "
                            f"input link's own as omega = <number>", key=key, **where)
        if self.units.angular_velocity == "rpm":
            value *= 2 * math.pi / 60
        return GivenRate("omega", target, value, second, second_key in spec)

    def read_assembly(self, links: tuple[Link, ...], slides: tuple[Slide, ...]) -> dict:
        t = self.table("assembly", False)
        names = {n for k in links for n in k.names}
        out: dict[str, str | tuple[float, float]] = {}
        for k, v in t.items():
            if k not in names:
                raise self.unknown(k, sorted(names), "point", table="assembly", key=k)
            if isinstance(v, str):
                if v not in _BRANCHES:
                    raise self.unknown(v, _BRANCHES, "branch", table="assembly", key=k)
                out[k] = v
            else:
                out[k] = self.xy(v, f"the point {k} should be near", table="assembly", key=k)
        return out


def _split_pair(key: str, names: list[str]) -> tuple[str, str] | None:
    """Split "O2A" into ("O2", "A") using the link's point names; None if no unique split."""
    hits = {(a, b) for a in names for b in names if a != b and a + b == key}
    if len(hits) == 1:
        return hits.pop()
    m = re.fullmatch(r"([^-\s]+)\s*-\s*([^-\s]+)", key)
    if m and m.group(1) in names and m.group(2) in names and m.group(1) != m.group(2):
        return (m.group(1), m.group(2))
    return None
