"""What a label on a student's sheet names, read as a course writes it.

A polygon's tips are lower-case letters (``b``), a subscript naming the link a point is
taken on (``a4``, ``a₄``, ``a_4``, ``a_{4}``) and, in the acceleration polygon, a prime
before or after the subscript (``a4′``, ``a′4``, ``a₄'``); the pole is ``o`` (``o_v``,
``o_a``, ``o′``). tarsim's own figures write two names at one point with ``≡``
(``a₂ ≡ a₄``, ``o_a ≡ b₅′``). The space diagram's points are written as the exercise's file
names them (``O2``, ``A``), its instant centres ``I13``, ``13`` or ``I₁₃``.

A tip's name is resolved against the polygon tarsim draws (:func:`tip_of`): ``a4`` is the
coincident point A taken on link 4 where the polygon has one, else the point A itself when
link 4 carries it (``a2`` is the crank pin's tip), else an alias the exercise declares.
"""

from __future__ import annotations

import re

__all__ = ["read_label", "read_names", "read_centre", "plain", "tip_of", "step_number"]

_PRIMES = "'′’ʹ`‘´"
_PLAIN = str.maketrans({**{chr(0x2080 + d): str(d) for d in range(10)},
                        "ₐ": "a", "ᵥ": "v", "ₒ": "o", **{p: "'" for p in _PRIMES},
                        "″": "''", "{": "", "}": "", "_": "", " ": "", "\u00a0": "", "\u202f": ""})
_EQUAL = re.compile(r"[≡=]")


def plain(text: str) -> str:
    """``text`` with subscripts, primes and braces written plainly (``a₄′`` → ``a4'``)."""
    return text.strip().translate(_PLAIN)


def _one(part: str) -> tuple[str, str] | None:
    """One name of a label as (kind, name): its primes say the polygon, wherever they stand."""
    primes = part.count("'")
    t = part.replace("'", "").lower()
    if not t or primes > 1:
        return None
    if t in ("o", "ov", "oa"):
        return ("a" if primes or t == "oa" else "v"), "o"
    if re.fullmatch(r"[a-z]\d*", t) and not re.fullmatch(r"i\d\d", t):
        return ("a" if primes else "v"), t
    return None


def read_names(text: str) -> tuple[str, tuple[str, ...]] | None:
    """A label as (kind, names): ``("a", ("o", "b5"))`` for ``o_a ≡ b₅′``; None if any part
    names no polygon point, or its parts belong to different polygons.

    >>> read_names("a₂ ≡ a₄"), read_names("o_a ≡ b₅′"), read_names("a′₄"), read_names("V_B")
    (('v', ('a2', 'a4')), ('a', ('o', 'b5')), ('a', ('a4',)), None)
    """
    parts = [p for p in _EQUAL.split(plain(text)) if p]
    if not parts or len(parts) > 4:
        return None
    read = [_one(p) for p in parts]
    if any(r is None for r in read):
        return None
    kinds = {k for k, _ in read}
    # o ≡ b₅′: one prime on a label of the acceleration polygon names it all.
    kind = kinds.pop() if len(kinds) == 1 else "a"
    return kind, tuple(dict.fromkeys(n for _, n in read))


def read_label(text: str) -> tuple[str, str] | None:
    """A label as (kind, tip): ("v", "b"), ("a", "b4"), ("v", "o") for a pole; None if it
    names no polygon point (the first name of a label that gives several).

    >>> read_label("B₄′"), read_label("o_v"), read_label("oa"), read_label("V_B")
    (('a', 'b4'), ('v', 'o'), ('a', 'o'), None)
    """
    read = read_names(text)
    return None if read is None else (read[0], read[1][0])


def read_centre(text: str) -> str | None:
    """A centre's name as results.json spells it, or None.

    >>> read_centre("I13"), read_centre("13"), read_centre("I₂₄"), read_centre("I1,3")
    ('I13', 'I13', 'I24', 'I13')
    """
    t = plain(text).replace(",", "")
    m = re.fullmatch(r"[Ii]?([1-9])([1-9])", t)       # links count from 1, the frame
    if m is None or m[1] == m[2]:
        return None
    i, j = sorted((int(m[1]), int(m[2])))
    return f"I{i}{j}"


def step_number(text: str) -> bool:
    """True for a bare number, as a figure numbers its steps (``13`` in a ring)."""
    return plain(text).isdigit()


def tip_of(name: str, tips, mech, aliases: dict[str, str] | None = None) -> str | None:
    """The polygon tip (a key of ``tips``, lower case) a label's ``name`` names, or None.

    ``a4`` names the tip ``a4`` (A taken on link 4) if the polygon has it, else ``a`` when
    link 4 carries the point A; an exercise's ``aliases`` map a label to a tip first.
    """
    if aliases and name in aliases:
        name = aliases[name].lower()
    if name in tips:
        return name
    m = re.fullmatch(r"([a-z])(\d+)", name)
    if m is None:
        return None
    points = {p.lower(): p for p in mech.point_names}
    point = points.get(m[1])
    if point is not None and m[1] in tips and int(m[2]) in mech.links_at(point):
        return m[1]
    return None
