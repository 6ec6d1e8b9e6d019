"""What each primitive of a figure stands on, so that a page can move the figure with the
mechanism it draws.

A figure drawn at one position is the template of every other. A page that turns the
crank is sent, for each position, only the named points of each view (the joints and
instant centres of the space diagram, the pole and tips of a polygon, in the world units
of the view), and moves each point ``v`` of a primitive with the named point ``P`` it
stands on, turning it with the line through two named points ``Q`` and ``R`` or not at
all:

    v′ = P′ + rot(∠Q′R′ − ∠QR) · (v − P)        (on paper)

So a block turns with its slotted lever and slides with its pin, a ground symbol stays
put, an arrowhead turns with its vector and a Kennedy line's ends keep to its centres.

What a point stands on is found, not declared: the figure is drawn again a little further
on (:func:`anchors` is given both drawings), and of every named point and line, the one
that carries the point to where the second drawing put it (to :data:`EXACT`) is taken; of
several, the simplest (no turn, then the line through its own point, then another) and
then the nearest. A primitive the second drawing draws otherwise (a construction that
takes another course there) keeps to the named points it is drawn on, if it is drawn on
them alone (a dot at a centre); a label whose place is chosen afresh at each position
keeps to what it names, by its owner (:attr:`~.figure.Text.owner`), as it stands beside
it in the template, unless what it names are points that coincide at the template's
position alone ("I₂₃ ≡ I₂₄" at a dead centre). Whatever is carried by none (a caption's
words, the input's angle, a construction on points the page is not sent) is the
template's own position's alone.
"""

from __future__ import annotations

from difflib import SequenceMatcher

import numpy as np

from .figure import Circle, Figure, Path, Text

__all__ = ["anchors", "Named", "Anchor", "EXACT"]

Named = dict[str, list[tuple[float, float] | None]]
"""The named points of each view, by the view's name (as a figure's ``views``), in the
order the page is sent them, in the view's world units; None where one is at infinity."""

Anchor = tuple[str, list[tuple[int, int, int]]]
"""Where a primitive stands: its view, and for each of its points (one triple for all,
if they share it) the index of the named point P and of the two, Q and R, whose line it
turns with (-1, -1: it does not turn)."""

EXACT = 1e-4
"""How near (paper mm) a point must be carried to where the second drawing put it. Both
drawings compute it in double precision from the same kind of sums, and what a figure
sizes from its whole drawing (a guide as long as the drawing is wide, a caption under it)
moves a few micrometres a radian; a wrong choice misses by the turn of a link over the
step between the drawings times the point's distance from what it stands on, a
millimetre a radian or more: over a step of 0.05° (the page's), some thousandths of a
millimetre."""

FARTHER = 1e-3
"""How near (paper mm) a farther drawing must find a point for the way that carries it
there to be taken before one that does not; of those that do, the nearest. What a figure
sizes from its whole drawing moves a micrometre or so over some degrees, a block that a
way does not turn with its lever misses by hundredths of a millimetre."""

_LINE = 1.0
"""The least paper length (mm) of a line a point may turn with: a shorter one's
direction is rounding."""


def anchors(first: Figure, later: list[Figure], named: list[Named]) -> list[Anchor | None]:
    """For each primitive of ``first``, what it stands on (None: nothing).

    ``later`` is the same figure drawn further on: first a little (:data:`EXACT` holds a
    point's way there), then, if given, farther. A farther drawing chooses between ways
    that carry a point a little alike: at a limit position a slotted lever stands still,
    and only a drawing farther on tells a block that turns with it from one that does not;
    there a point is carried to within :data:`FARTHER`. ``named`` holds the named points
    of ``first`` and then of each of ``later``.

    Examples
    --------
    A pin drawn at a joint, and a tick 5 mm right of the other end of the link, which
    turns a quarter turn about the first:

    >>> import math
    >>> from tarsim.graphics.figure import View
    >>> def drawn(b):
    ...     fig = Figure(50.0, 50.0, views={"space": View(10.0, (20.0, 30.0))})
    ...     fig.add(Circle(fig.views["space"]((0.0, 0.0)), 1.0, "pin"))
    ...     at = fig.views["space"](b)
    ...     u = (b[0] / math.hypot(*b), -b[1] / math.hypot(*b))
    ...     fig.add(Path((at, (at[0] + 5 * u[0], at[1] + 5 * u[1])), "link"))
    ...     return fig
    >>> anchors(drawn((1.0, 0.0)), [drawn((0.0, 1.0))],
    ...         [{"space": [(0.0, 0.0), (1.0, 0.0)]}, {"space": [(0.0, 0.0), (0.0, 1.0)]}])
    [('space', [(0, -1, -1)]), ('space', [(1, -1, -1), (1, 0, 1)])]
    """
    out: list[Anchor | None] = [None] * len(first.items)
    near = _matched(first.items, later[0].items)
    rows = [(k, j, z) for k in sorted(near) for j, z in enumerate(_points(first.items[k]))]
    if rows:
        item = np.array([k for k, _, _ in rows])
        z0 = np.array([complex(*z) for _, _, z in rows])
        there = [np.array([m[k][j] if k in m else np.nan for k, j, _ in rows], dtype=complex)
                 for m in [near] + [_matched(first.items, f.items) for f in later[1:]]]
        found = _carried(z0, there, [_paper(f, n) for f, n in zip([first, *later], named)])
        for k in near:
            mine = [found[j] for j in np.flatnonzero(item == k)]
            if all(f is not None for f in mine) and len({f[0] for f in mine}) == 1:
                triples = [f[1] for f in mine]
                out[k] = (mine[0][0], triples[:1] if len(set(triples)) == 1 else triples)
    here = _paper(first, named[0])
    there = [_paper(f, n) for f, n in zip(later, named[1:])]
    for k, it in enumerate(first.items):
        if out[k] is None:
            out[k] = _on_points(_points(it), here)
        if out[k] is None and isinstance(it, Text) and it.owner:
            out[k] = _owner(it.owner, here)
        if (isinstance(it, Text) and it.owner and "≡" in it.text + it.sub + it.tail
                and _parting(it.owner[-1], here, there)):
            out[k] = None
    return out


def _parting(p: tuple[float, float], here: dict[str, np.ndarray],
             there: list[dict[str, np.ndarray]]) -> bool:
    """True if the named points at ``p`` (two or more) part in a later drawing: a label
    that joins them with the figures' sign of coincidence ("I₂₃ ≡ I₂₄", "o ≡ b") says what
    holds at the template's position alone, and is not carried to another. Points that
    stay together (a pin and the centre it is) keep their joined label."""
    for view, points in here.items():
        together = np.flatnonzero(np.abs(points - complex(*p)) <= EXACT)
        if len(together) > 1:
            return any(np.nanmax(np.abs(t[view][together] - t[view][together[0]])) > EXACT
                       for t in there if view in t)
    return False


def _points(item: Path | Circle | Text) -> tuple[tuple[float, float], ...]:
    """The paper points a primitive is placed by: a path's, a circle's centre, a text's
    anchor."""
    if isinstance(item, Path):
        return item.points
    return (item.centre,) if isinstance(item, Circle) else (item.at,)


def _shape(item: Path | Circle | Text) -> tuple:
    """What must agree for two drawings' primitives to be one: kind, style and count of
    points; a circle's radius; a text's words."""
    if isinstance(item, Path):
        return ("p", item.style, item.closed, len(item.points))
    if isinstance(item, Circle):
        return ("c", item.style, round(item.radius, 6))
    return ("t", item.text, item.sub, item.tail, item.size)


def _matched(first: list, other: list) -> dict[int, list[complex]]:
    """The points of each primitive of ``first`` that ``other`` draws too, where ``other``
    puts them, by the primitive's index: the drawings are matched primitive for primitive,
    in order."""
    a, b = [_shape(it) for it in first], [_shape(it) for it in other]
    out = {}
    for i, j, n in SequenceMatcher(None, a, b, autojunk=False).get_matching_blocks():
        for k in range(n):
            out[i + k] = [complex(*p) for p in _points(other[j + k])]
    return out


def _paper(fig: Figure, named: Named) -> dict[str, np.ndarray]:
    """The named points of each view the figure has, on its paper (nan where none)."""
    out = {}
    for view, points in named.items():
        v = fig.views.get(view)
        if v is not None:
            out[view] = np.array([complex(v.origin[0] + v.scale * p[0],
                                          v.origin[1] - v.scale * p[1]) if p else np.nan
                                  for p in points], dtype=complex)
    return out


def _carried(z0: np.ndarray, there: list[np.ndarray], paper: list[dict[str, np.ndarray]]
             ) -> list[tuple[str, tuple[int, int, int]] | None]:
    """For each point (``z0`` on the first drawing, ``there`` on each later one, nan where
    it is not drawn), the simplest named point and line that carry it, by view:
    (view, (P, Q, R)); None if none does."""
    best = np.full(len(z0), np.inf)
    choice: list = [None] * len(z0)
    for view in set.intersection(*(set(p) for p in paper)):
        pts = [p[view] for p in paper]
        ok = np.flatnonzero(np.isfinite(pts[0]) & np.isfinite(pts[1]))
        pairs = [(-1, -1)] + [(int(q), int(r)) for i, q in enumerate(ok) for r in ok[i + 1:]
                              if all(abs(p[r] - p[q]) > _LINE for p in pts[:2])]
        q_, r_ = np.array([t[0] for t in pairs]), np.array([t[1] for t in pairs])
        turns = [_turns(pts[0], p, pairs) for p in pts[1:]]
        for p in ok:
            d = z0 - pts[0][p]
            rank = np.where(q_ < 0, 0.0, np.where((q_ == p) | (r_ == p), 1.0, 2.0))
            key = rank[None, :] * 1e9 + np.abs(d)[:, None]
            for k, (z, rho, at) in enumerate(zip(there, turns, pts[1:])):
                miss = np.abs(at[p] + rho[None, :] * d[:, None] - z[:, None])
                if k == 0:
                    key = np.where(miss <= EXACT, key, np.inf)
                else:      # the nearest there first; no word from one that lacks the point
                    key = key + np.where(miss > FARTHER, 1e12,
                                         np.where(np.isnan(miss), 0.0, miss * 1e6))
            t = np.argmin(key, axis=1)
            k = key[np.arange(len(z0)), t]
            for j in np.flatnonzero(k < best):
                best[j] = k[j]
                choice[j] = (view, (int(p), int(q_[t[j]]), int(r_[t[j]])))
    return choice


def _turns(was: np.ndarray, now: np.ndarray, pairs: list[tuple[int, int]]) -> np.ndarray:
    """How each line through two named points has turned from ``was`` to ``now``, as a
    unit complex number (nan where either drawing lacks a point or their line)."""
    out = np.ones(len(pairs), dtype=complex)
    for i, (q, r) in enumerate(pairs):
        if q >= 0:
            u0, u1 = was[r] - was[q], now[r] - now[q]
            out[i] = (u1 / abs(u1)) / (u0 / abs(u0)) if abs(u0) > 0 and abs(u1) > 0 else np.nan
    return out


def _at(p: tuple[float, float], paper: dict[str, np.ndarray]) -> tuple[str, int] | None:
    """The named point (its view and index) drawn at ``p``, if one is."""
    for view, points in paper.items():
        near = np.abs(points - complex(*p))
        if np.any(near <= EXACT):
            return view, int(np.nanargmin(near))
    return None


def _on_points(points: tuple[tuple[float, float], ...], paper: dict[str, np.ndarray]
               ) -> Anchor | None:
    """A primitive drawn on named points alone (a dot at a centre, a bar from pin to pin),
    which the second drawing does not draw alike: each point keeps to its own."""
    found = [_at(p, paper) for p in points]
    if not all(found) or len({f[0] for f in found}) != 1:
        return None
    triples = [(f[1], -1, -1) for f in found]
    return found[0][0], triples[:1] if len(set(triples)) == 1 else triples


def _owner(owner: tuple[tuple[float, float], ...], paper: dict[str, np.ndarray]
           ) -> Anchor | None:
    """A label kept beside what it names: the named point its owner (a point, or a
    vector's tip, then its tail) stands on, without turning."""
    for p in reversed(owner):
        found = _at(p, paper)
        if found:
            return found[0], [(found[1], -1, -1)]
    return None
