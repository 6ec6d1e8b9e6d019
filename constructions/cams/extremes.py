"""A cam's extremes found from its laws, between samples as well as on them.

A segment's law is analytic piece by piece (:func:`..reference.cam_laws.pieces`): y″ jumps
only where two pieces meet. On one piece the pressure angle, the pitch curve's curvature
and a flat face's radius and run are smooth in the cam angle, so their extremes lie at the
piece's ends (each piece's own one-sided limit) or where their derivative vanishes between.

Each piece is sampled in equal parts no wider than ¼° and never fewer than
:data:`PARTS` however short it is, and more densely towards both ends, where a small base
circle under a large lift packs its change. A sample standing above both neighbours
brackets a maximum, which golden-section search then finds on the law itself to rounding;
a level (a roller's curvature 1/r, a flat face's zero) is crossed where the samples and the
extremes between them change side, and bisection finds where.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any

from ..reference.cam_laws import Motion
from ..reference.cam_laws import pieces as law_pieces
from ..reference.cam_profile import Follower, Station, segment_motion, station_at

__all__ = ["Extreme", "Piece", "Scan", "pieces", "samples", "scan", "peaks", "greatest",
           "maxima", "highest", "above"]

SPACING = math.radians(0.25)
"""The widest step between two samples of a piece (rad)."""

PARTS = 32
"""The fewest equal parts a piece is sampled in, however short."""

GRADED = tuple(4.0 ** -j for j in range(2, 26))
"""Fractions of a piece sampled next to each end, down to 1e-15 of it."""

EPS = 2.220446049250313e-16

_GOLDEN = 0.3819660112501051
"""(3 − √5)/2: the part of a bracket golden-section search probes."""


@dataclass(frozen=True)
class Piece:
    """One analytic piece of a segment: the segment's number (from 1) and its data, the cam
    angle it starts at and the lift it starts from, and the piece's span ``t0``–``t1``
    into it (rad) with its index among the law's pieces (None for a dwell)."""

    segment: int
    law: Any
    start: float
    height: float
    t0: float
    t1: float
    index: int | None

    def motion(self, t: float) -> Motion:
        """The follower's motion ``t`` into the segment, by this piece's own formula."""
        return segment_motion(self.law, self.height, t, piece=self.index)


def pieces(segments: Sequence[Any]) -> list[Piece]:
    """The analytic pieces of ``segments`` in turn round the cam."""
    out, start, height = [], 0.0, 0.0
    for k, s in enumerate(segments, start=1):
        dwell = s.kind == "dwell"
        cuts = (0.0, 1.0) if dwell else law_pieces(s.law, s.blend, s.split)
        for i, (a, b) in enumerate(zip(cuts, cuts[1:])):
            out.append(Piece(k, s, start, height, a * s.angle, b * s.angle,
                             None if dwell else i))
        start += s.angle
        height += s.lift if s.kind == "rise" else -s.lift if s.kind == "return" else 0.0
    return out


@dataclass
class Scan:
    """One piece sampled: its sample angles into the segment, the stations there, and
    which of them are its equal parts (the ones a figure draws through)."""

    piece: Piece
    at: Callable[[float], Station]
    ts: list[float]
    stations: list[Station]
    drawn: list[bool]

    @property
    def flat(self) -> bool:
        """A dwell: the follower stands still, and every quantity is constant along it."""
        return self.piece.index is None


def samples(a: float, b: float) -> tuple[list[float], set[float]]:
    """Sample angles over ``a``–``b`` in order, and which of them are its equal parts (see
    the module's docstring)."""
    n = max(PARTS, math.ceil((b - a) / SPACING))
    # Every angle from its fraction of the span, so a fraction both grids hold (1/16) is
    # one angle, not two an ulp apart that would bracket nothing between them.
    equal = {a + (b - a) * (i / n) for i in range(n)} | {b}
    extra = {a + (b - a) * u for u in GRADED} | {a + (b - a) * (1 - u) for u in GRADED}
    out: list[float] = []
    for t in sorted(equal | {t for t in extra if a < t < b}):
        if out and t - out[-1] <= 4 * EPS * abs(t):
            if t in equal:                      # the equal part is drawn: keep it
                out[-1] = t
            continue
        out.append(t)
    return out, equal


def scan(piece: Piece, base_radius: float, f: Follower, sigma: float) -> Scan:
    """Sample ``piece`` (see the module's docstring)."""
    def at(t: float) -> Station:
        return station_at(piece.motion(t), base_radius, f, sigma, piece.start + t)

    ts, equal = samples(piece.t0, piece.t1)
    return Scan(piece, at, ts, [at(t) for t in ts], [t in equal for t in ts])


def _golden(g: Callable[[float], float], a: float, b: float, c: float, gb: float
            ) -> tuple[float, float]:
    """The maximum of ``g`` bracketed by a < b < c, g(b) ≥ g(a), g(c): golden-section
    search until the bracket is a few roundings of its place wide."""
    for _ in range(400):
        if c - a <= 4 * EPS * max(abs(a), abs(c)) + 1e-300:
            break
        x = b - _GOLDEN * (b - a) if b - a > c - b else b + _GOLDEN * (c - b)
        if x in (a, b, c):
            break
        gx = g(x)
        if gx > gb:
            a, c = (a, b) if x < b else (b, c)
            b, gb = x, gx
        elif x < b:
            a = x
        else:
            c = x
    return b, gb


def peaks(g: Callable[[float], float], ts: Sequence[float], vs: Sequence[float]
          ) -> list[tuple[float, float]]:
    """Every local maximum of the smooth ``g`` over ``ts[0]``–``ts[-1]`` as (t, value), from
    its values ``vs`` at the samples ``ts``: the two ends, and each sample above its
    neighbours refined on ``g``. A bracket flat to rounding is its sample's value already."""
    out = [(ts[0], vs[0]), (ts[-1], vs[-1])]
    for i in range(1, len(vs) - 1):
        v, lo = vs[i], min(vs[i - 1], vs[i + 1])
        if not (v >= vs[i - 1] and v >= vs[i + 1] and v > lo):
            continue
        if v - lo <= 8 * EPS * abs(v):
            out.append((ts[i], v))
        else:
            out.append(_golden(g, ts[i - 1], ts[i], ts[i + 1], v))
    return out


def greatest(g: Callable[[float], float], a: float, b: float) -> float:
    """The greatest value of the smooth ``g`` over ``a``–``b``, found between samples."""
    ts = samples(a, b)[0]
    return max(v for _, v in peaks(g, ts, [g(t) for t in ts]))


def maxima(s: Scan, key: Callable[[Station], float]) -> list[tuple[float, float]]:
    """Every local maximum of ``key`` along the piece as (t, value) (see :func:`peaks`);
    a dwell's are its ends."""
    vs = [key(st) for st in s.stations]
    if s.flat:
        return [(s.ts[0], vs[0]), (s.ts[-1], vs[-1])]
    return peaks(lambda t: key(s.at(t)), s.ts, vs)


@dataclass(frozen=True)
class Extreme:
    """Where a quantity is greatest round the cam: the segment (from 1) and the station."""

    segment: int
    station: Station
    value: float


def highest(scans: Sequence[Scan], key: Callable[[Station], float]) -> Extreme:
    """The greatest value of ``key`` round the cam, found between samples."""
    best: tuple[float, float, Scan] | None = None
    for s in scans:
        for t, v in maxima(s, key):
            if best is None or v > best[0]:
                best = (v, t, s)
    v, t, s = best
    return Extreme(s.piece.segment, s.at(t), v)


def _cross(g: Callable[[float], float], level: float, a: float, b: float, high_at_a: bool
           ) -> float:
    """Where ``g`` crosses ``level`` between a and b, by bisection: the last angle on the
    high side."""
    for _ in range(400):
        m = 0.5 * (a + b)
        if m in (a, b):
            break
        if (g(m) > level) == high_at_a:
            a = m
        else:
            b = m
    return a if high_at_a else b


def above(s: Scan, key: Callable[[Station], float], level: float
          ) -> list[tuple[float, float, float, float]]:
    """The spans of the piece where ``key`` stands above ``level``, each as (from, to, the
    greatest value in it, where), in angles into the segment."""
    if s.flat:
        v = key(s.stations[0])
        return [(s.ts[0], s.ts[-1], v, s.ts[0])] if v > level else []
    points = sorted(set(zip(s.ts, (key(st) for st in s.stations))) | set(maxima(s, key))
                    | {(t, -v) for t, v in maxima(s, lambda st: -key(st))})

    def g(t: float) -> float:
        return key(s.at(t))
    out: list[list[float]] = []
    for i, (t, v) in enumerate(points):
        high = v > level
        if i and high != (points[i - 1][1] > level):
            cut = _cross(g, level, points[i - 1][0], t, not high)
            if high:
                out.append([cut, t, v, t])
            else:
                out[-1][1] = cut
        elif high and not out:
            out.append([t, t, v, t])
        if high:
            span = out[-1]
            span[1] = max(span[1], t)
            if v > span[2]:
                span[2], span[3] = v, t
    return [tuple(span) for span in out]
