"""The laid-out profile held to the closed form, and surveyed round the turn.

The checks are the layout's own acts against :mod:`..reference.cam_profile`: each trace
point drawn where the closed form puts it, each roller circle touching the closed-form
profile (its centre one roller radius off the touch), each face line through its touch;
each to the rounding its acts and the lift it took from the diagram can carry
(:mod:`.rounding`). The survey finds from the laws (:mod:`.extremes`) the pressure angle's
greatest size, the least radius of curvature, the spans where a roller undercuts (the pitch
curve convex and sharper than the roller) or a flat face meets a concave profile, and how
far along a flat face the touch runs: at a segment's ends, where its derivative vanishes,
and however short the segment, not only where the samples fall.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from functools import cached_property

from .. import geometry as g
from ..errors import IllConditioned
from ..record import Ref
from ..reference.cam_profile import Follower, Station, station
from .extremes import EPS, Extreme, Scan, above, highest, pieces, scan
from .inversion import Layout
from .rounding import join_bound, rounding

__all__ = ["Survey", "Undercut", "survey", "AGREE"]

AGREE = 16.0
"""How many of its rounding bounds a drawn point may stand off the closed form: the bound
is first order, and an act's few roundings are each counted at most once."""


@dataclass(frozen=True)
class Undercut:
    """A span of cam angle where the follower cannot make the profile: from, to (rad, the
    end past 2π where it runs over 0°), and the station there at its worst in the segment
    (from 1) it lies in."""

    start: float
    end: float
    segment: int
    worst: Station


@dataclass
class Survey:
    """The closed form round the turn and the layout's misses from it."""

    follower: Follower
    sigma: float
    scans: list[Scan]
    places: list[Station] = field(default_factory=list)
    """The closed form at each of the layout's stations, in order."""
    misses: list[tuple[int, float]] = field(default_factory=list)
    """Layout stations off the closed form: (station number, miss in m)."""

    @cached_property
    def stations(self) -> list[Station]:
        """The closed form in order round the turn, every ¼° or closer and at each end of
        every piece of a law: the curves a figure draws."""
        return [st for s in self.scans for st, d in zip(s.stations, s.drawn) if d]

    @cached_property
    def steepest_at(self) -> Extreme:
        """Where the pressure angle is greatest in size, and in which segment."""
        return highest(self.scans, lambda s: abs(s.pressure_angle))

    @property
    def steepest(self) -> Station:
        """Where the pressure angle is greatest in size."""
        return self.steepest_at.station

    @cached_property
    def sharpest_at(self) -> Extreme:
        """Where the convex pitch curve bends tightest (its curvature greatest), or a flat
        face's profile has its least radius (concave, below zero, where it cannot be made)."""
        if self.follower.kind == "flat-faced":
            return highest(self.scans, lambda s: -s.rho)
        return highest(self.scans, _curvature)

    @property
    def sharpest(self) -> Station:
        """See :attr:`sharpest_at`."""
        return self.sharpest_at.station

    @cached_property
    def undercut(self) -> list[Undercut]:
        """The spans where the follower cannot make the profile: a roller larger than the
        convex pitch curve's radius, or a flat face on a concave profile."""
        f = self.follower
        if f.kind == "roller":
            key, level = _curvature, 1.0 / f.radius
        elif f.kind == "flat-faced":
            key, level = (lambda s: -s.rho), 0.0
        else:
            return []
        spans: list[list] = []
        for s in self.scans:
            for a, b, v, t in above(s, key, level):
                start, end = s.piece.start + a, s.piece.start + b
                if spans and abs(start - spans[-1][1]) <= _JOIN:
                    spans[-1][1] = end                      # it runs on into this piece
                    if v > spans[-1][2]:
                        spans[-1][2:] = [v, s, t]
                else:
                    spans.append([start, end, v, s, t])
        if len(spans) > 1 and spans[0][0] <= 0.0 and spans[-1][1] >= 2 * math.pi - _JOIN:
            last = spans.pop()                              # over 0°: one span
            first = spans[0]
            first[0], first[1] = last[0], first[1] + 2 * math.pi
            if last[2] > first[2]:
                first[2:] = last[2:]
        return [Undercut(a, b, s.piece.segment, s.at(t)) for a, b, _, s, t in spans]

    @cached_property
    def face(self) -> tuple[float, float]:
        """A flat face: the touch's farthest runs each side of the follower's axis (m)."""
        return (-highest(self.scans, lambda s: -s.face_offset).value,
                highest(self.scans, lambda s: s.face_offset).value)


_JOIN = 1e-10
"""Two spans whose ends are closer than this (rad) are one: the segments' angles are read
to add to 360° within 1e-9°."""


def _curvature(s: Station) -> float:
    """The pitch curve's curvature 1/ρ, positive where convex."""
    return 1.0 / s.rho


def survey(layout: Layout, base_radius: float, segments, sigma: float,
           lifts: dict[Ref, float] | None = None) -> Survey:
    """Survey the closed form round the turn and hold the layout's acts to it.

    ``lifts`` bounds the rounding of the lift each station of the layout took from the
    displacement diagram (m), by the diagram's point; none if they were exact.

    Raises
    ------
    IllConditioned
        If a station's tolerance reaches the cam's own size: a check that could not fail.
    """
    f = layout.follower
    out = Survey(f, sigma, [scan(p, base_radius, f, sigma) for p in pieces(segments)])
    c = layout.construction
    reach = rounding(c)
    size = base_radius + max((p.lift for p in layout.places), default=0.0) + f.radius
    for p in layout.places:
        want = station(segments, base_radius, f, sigma, p.theta)
        out.places.append(want)
        trace = c.output(p.trace)
        # The lift's rounding against its own segment's law, and against the other one the
        # closed form may read where a join lies within the rounding of the station's angle.
        lift = (lifts or {}).get(p.source, 0.0) + join_bound(segments, p.theta)
        # The closed form's own rounding: a few of the cam's size and of the point's reach.
        tol = AGREE * (reach[p.trace].error + lift + 16 * EPS * (size + math.hypot(*want.pitch)))
        checks = [(math.dist(trace.xy, want.pitch), tol)]
        if f.kind == "roller":
            checks.append((abs(math.dist(trace.xy, want.profile) - f.radius), tol))
        elif f.kind == "flat-faced":
            # The touch runs σy′ along the face, far on a steep segment: the face's turn
            # carries its rounding out there.
            far = AGREE * (reach[p.follower].near(want.profile) + lift
                           + 16 * EPS * (size + math.hypot(*want.profile)))
            checks.append((abs(c.output(p.follower).signed_distance(g.Point(*want.profile))),
                           far))
        miss, tol = max(checks, key=lambda mt: mt[0] / mt[1])
        if not tol < size:
            raise IllConditioned(
                f"station {p.number} (θ = {math.degrees(p.theta):.4g}°) of the layout: its "
                f"rounding ({tol:.1e} m) reaches the cam's size ({size:.3g} m), so no check "
                "can be made; give the cam a larger base circle",
                name=f"profile station {p.number}", method="inversion",
                conditioning=size and tol / size, miss=miss)
        if miss > tol:
            out.misses.append((p.number, miss))
    return out
