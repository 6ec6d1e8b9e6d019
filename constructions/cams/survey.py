"""The laid-out profile held to the closed form, and surveyed round the turn.

The checks are the layout's own acts against :mod:`..reference.cam_profile`: each trace
point drawn where the closed form puts it, each roller circle touching the closed-form
profile (its centre one roller radius off the touch), each face line through its touch.
The survey samples the closed form finely round the turn: the pressure angle and its
greatest size, the least radius of curvature, where a roller undercuts (the pitch curve
convex and sharper than the roller) or a flat face meets a concave profile, and how far
along a flat face the touch runs.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from functools import cached_property

from .. import geometry as g
from ..reference.cam_profile import Follower, Station, station
from .inversion import Layout

__all__ = ["Survey", "survey"]

SAMPLES = 1440
"""Closed-form stations round the turn (every ¼°) for the survey and the drawn curves."""

AGREE = 1e-12
"""How far (relative to the cam's size) a drawn point may stand off the closed form: a few
roundings of the lengths laid off."""


@dataclass
class Survey:
    """The closed form round the turn and the layout's misses from it."""

    follower: Follower
    sigma: float
    stations: list[Station]
    places: list[Station] = field(default_factory=list)
    """The closed form at each of the layout's stations, in order."""
    misses: list[tuple[int, float]] = field(default_factory=list)
    """Layout stations off the closed form: (station number, miss in m)."""

    @cached_property
    def steepest(self) -> Station:
        """Where the pressure angle is greatest in size."""
        return max(self.stations, key=lambda s: abs(s.pressure_angle))

    @cached_property
    def sharpest(self) -> Station:
        """Where the convex pitch curve (a flat face's profile) bends tightest, or, if it is
        nowhere convex enough to matter, the least radius in size."""
        convex = [s for s in self.stations if s.rho > 0]
        return min(convex or self.stations, key=lambda s: abs(s.rho))

    @cached_property
    def undercut(self) -> list[Station]:
        """Stations where the follower cannot make the profile: a roller larger than the
        convex pitch curve's radius, or a flat face on a concave profile."""
        if self.follower.kind == "roller":
            return [s for s in self.stations if 0 < s.rho < self.follower.radius]
        if self.follower.kind == "flat-faced":
            return [s for s in self.stations if s.rho <= 0]
        return []

    @property
    def face(self) -> tuple[float, float]:
        """A flat face: the touch's farthest runs each side of the follower's axis (m)."""
        offsets = [s.face_offset for s in self.stations]
        return min(offsets), max(offsets)


def survey(layout: Layout, base_radius: float, segments, sigma: float) -> Survey:
    """Sample the closed form round the turn and hold the layout's acts to it."""
    f = layout.follower
    thetas = [2 * math.pi * i / SAMPLES for i in range(SAMPLES)]
    out = Survey(f, sigma, [station(segments, base_radius, f, sigma, t) for t in thetas])
    c = layout.construction
    size = base_radius + max((p.lift for p in layout.places), default=0.0)
    for p in layout.places:
        want = station(segments, base_radius, f, sigma, p.theta)
        out.places.append(want)
        trace = c.output(p.trace)
        miss = math.dist(trace.xy, want.pitch)
        if f.kind == "roller":
            miss = max(miss, abs(math.dist(trace.xy, want.profile) - f.radius))
        elif f.kind == "flat-faced":
            line = c.output(p.follower)
            miss = max(miss, abs(line.signed_distance(g.Point(*want.profile))))
        if miss > AGREE * size:
            out.misses.append((p.number, miss))
    return out
