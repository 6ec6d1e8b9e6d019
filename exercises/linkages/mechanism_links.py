"""The frame and the links of a mechanism file: each link's points placed in its own axes.

A link is given by its points and the lengths between them, keyed as a textbook writes
them (``O2A = 100``, ``AB = 250``): its first point at the origin, its second on the +x
axis, and each further point by its two lengths and the side of that axis it lies on, or
by its length from one of the first two points and its angle there to the other, as a
book writes "D, 50 mm from B at 30° to BA": ``lengths = { BD = 50 }``, ``angles = { ABD =
30 }`` (the vertex in the middle), with its side.
"""

from __future__ import annotations

import math
import re
import sys
from typing import Any

from tarsim.constructions.model import Link
from .mechanism_values import TableReader

__all__ = ["read_frame", "read_links"]

_ON_LINE = 64 * sys.float_info.epsilon
"""A point whose h² off a link's base line is within this many of the largest square of
the lengths that place it lies on the line: that much is the rounding of h² itself."""


_SETTINGS = ("number", "name", "points", "lengths", "sides", "angles")
"""The settings a ``[[link]]`` takes."""


def read_frame(r: TableReader) -> Link:
    """Read ``[frame]``: the fixed points, the first of them the model's origin."""
    f = r.table("frame", True)
    for k in f:
        r.name(k, "a frame point", table="frame", key=k)
    if not f:
        raise r.fail("names no fixed point", table="frame")
    first = next(iter(f))
    r.file_origin = r.pair(f[first], f"frame point {first}", table="frame", key=first)
    return Link(1, tuple((k, r.xy(v, f"frame point {k}", table="frame", key=k))
                         for k, v in f.items()), "frame")


def read_links(r: TableReader, frame: Link) -> list[Link]:
    """Read every ``[[link]]``: its number, its name and its points in its own axes."""
    out: list[Link] = []
    seen = {1}
    for i, t in enumerate(r.list_of("link")):
        where = {"table": "link", "index": i}
        for k in t:
            if k not in _SETTINGS:
                raise r.unknown(k, _SETTINGS,
                                "link setting", key=k, **where)
        if "number" not in t:
            raise r.fail("a link needs its number (the frame is 1)", **where)
        n = t["number"]
        if isinstance(n, bool) or not isinstance(n, int) or n < 2:
            raise r.fail(f"a moving link's number is a whole number from 2 up, got {n!r}",
                         key="number", **where)
        if n in seen:
            raise r.fail(f"link {n} is defined twice", key="number", **where)
        seen.add(n)
        names = t.get("points")
        if not (isinstance(names, list) and names):
            raise r.fail(f"link {n} needs points = [\"…\", …]", **where)
        names = [r.name(p, f"a point of link {n}", key="points", **where) for p in names]
        if len(set(names)) != len(names):
            raise r.fail(f"link {n} lists a point twice", key="points", **where)
        local = _shape(r, n, names, t, where)
        label = r.text(t.get("name", ""), f"the name of link {n}", key="name", **where)
        out.append(Link(n, tuple(zip(names, local)), label))
    return out


def _shape(r: TableReader, n: int, names: list[str], t: dict[str, Any],
           where: dict) -> list[tuple[float, float]]:
    lengths = t.get("lengths", {})
    if not isinstance(lengths, dict):
        raise r.fail(f"lengths of link {n} must be a table such as {{ AB = 250 }}",
                     key="lengths", **where)
    table: dict[frozenset[str], float] = {}
    for key, v in lengths.items():
        pair = _split_pair(key, names)
        if pair is None:
            pairs = [a + b for a in names for b in names if a != b]
            raise r.unknown(key, pairs, f"length of link {n}", key=key, **where)
        table[frozenset(pair)] = r.length(v, f"length {key} of link {n}", key=key, **where)
    sides = t.get("sides", {})
    angles = _angles(r, n, names, t.get("angles", {}), where)

    def span(a: str, b: str) -> float:
        v = table.get(frozenset((a, b)))
        if v is None:
            raise r.fail(f"link {n} needs the length {a}{b}", key="lengths", **where)
        return v

    if len(names) == 1:
        return [(0.0, 0.0)]
    base = span(names[0], names[1])
    local = [(0.0, 0.0), (base, 0.0)]
    for p in names[2:]:
        if p in angles:
            local.append(_by_angle(r, n, names, p, angles[p], span, sides, where))
            continue
        r0, r1 = span(names[0], p), span(names[1], p)
        x = (r0 * r0 - r1 * r1 + base * base) / (2 * base)
        h2 = r0 * r0 - x * x
        if h2 < -1e-9 * base * base:
            raise r.fail(f"the lengths {names[0]}{p}, {names[1]}{p} and "
                         f"{names[0]}{names[1]} of link {n} do not close a triangle",
                         key="lengths", **where)
        # h² is a difference of squares: its rounding is some units of eps in the
        # largest square, so a point within that of the line is on it (h = 3.7e-9 m
        # from h² = 1.4e-17 is rounding, whatever order the points are listed in).
        on_line = h2 <= _ON_LINE * max(r0 * r0, r1 * r1, base * base)
        h = 0.0 if on_line else math.sqrt(h2)
        side = sides.get(p) if isinstance(sides, dict) else None
        if not on_line and side not in ("left", "right"):
            raise r.fail(f"say on which side of {names[0]}→{names[1]} point {p} lies: "
                         f'sides = {{ {p} = "left" }} or "right"', key="lengths", **where)
        local.append((x, h if side == "left" else -h))
    return local


def _angles(r: TableReader, n: int, names: list[str], table: Any,
            where: dict) -> dict[str, tuple[str, str, float]]:
    """``angles = { ABD = 30 }`` read as {D: (vertex B, arm A, 30° in rad)}: the angle at
    one of the link's first two points, from the other of them to the point it places."""
    if not isinstance(table, dict):
        raise r.fail(f"angles of link {n} must be a table such as {{ ABD = 30 }}",
                     key="angles", **where)
    out: dict[str, tuple[str, str, float]] = {}
    for key, v in table.items():
        hits = {(a, b, c) for a in names for b in names for c in names
                if len({a, b, c}) == 3 and a + b + c == key}
        base = {names[0], names[1]} if len(names) > 2 else set()
        fits = [(a, b, c) for a, b, c in hits if {a, b} == base and c not in base]
        if len(fits) != 1:
            raise r.fail(f"angle {key} of link {n} must name the angle at {names[0]} or "
                         f"{names[1]} (in the middle) from the other to a further point, "
                         f"such as {names[1] + names[0] + (names[2:] or ['D'])[0]}",
                         key=key, table="link", index=where["index"])
        a, b, c = fits[0]
        if c in out:
            raise r.fail(f"link {n} gives two angles for {c}", key=key, table="link",
                         index=where["index"])
        out[c] = (b, a, r.angle(v, f"angle {key} of link {n}", key=key, table="link",
                                index=where["index"]))
    return out


def _by_angle(r: TableReader, n: int, names: list[str], p: str,
              angle: tuple[str, str, float], span, sides: Any,
              where: dict) -> tuple[float, float]:
    """Point ``p`` in the link's axes from its length to the vertex and the angle there."""
    vertex, arm, theta = angle
    length = span(vertex, p)
    base = span(names[0], names[1])
    # the vertex is at x = 0 or x = base, the arm the other: along +x from the first
    x0, sense = (0.0, 1.0) if vertex == names[0] else (base, -1.0)
    x, h = x0 + sense * length * math.cos(theta), abs(length * math.sin(theta))
    if h <= 1e-12 * max(length, base):
        return (x, 0.0)
    side = sides.get(p) if isinstance(sides, dict) else None
    if side not in ("left", "right"):
        raise r.fail(f"say on which side of {names[0]}→{names[1]} point {p} lies: "
                     f'sides = {{ {p} = "left" }} or "right"', key="angles", **where)
    return (x, h if side == "left" else -h)


def _split_pair(key: str, names: list[str]) -> tuple[str, str] | None:
    """Split "O2A" into ("O2", "A") using the link's point names; None if no unique split."""
    hits = {(a, b) for a in names for b in names if a != b and a + b == key}
    if len(hits) == 1:
        return hits.pop()
    m = re.fullmatch(r"([^-\s]+)\s*-\s*([^-\s]+)", key)
    if m and m.group(1) in names and m.group(2) in names and m.group(1) != m.group(2):
        return (m.group(1), m.group(2))
    return None
