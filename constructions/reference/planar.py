"""Planar algebra the reference's modules share: rotations, the 2-D cross product, angle
wrapping, unit directions, and each link's points in its own frame.

Every name here serves the reference's own modules (the closed-form assembly, the loop
equations, the solver and their batch twins over a turn), so none is public.
"""

from __future__ import annotations

import math

import numpy as np

from ..errors import InputError
from ..model import Mechanism

__all__: list[str] = []

_EPS = float(np.finfo(float).eps)
_SLACK = 64 * _EPS  # rounding slack for a tangency: below it, a cut is taken as exact
_S = np.array([[0.0, -1.0], [1.0, 0.0]])  # rotation by +90°: d/dφ R(φ) = S R(φ)


def _rot(phi: float) -> np.ndarray:
    c, s = math.cos(phi), math.sin(phi)
    return np.array([[c, -s], [s, c]])


def _cross(a, b) -> float:
    return float(a[0] * b[1] - a[1] * b[0])


def _wrap(angle: float) -> float:
    return math.remainder(angle, math.tau)


def _round_angle(angle: float) -> float:
    """The angle a wheel's centre has gone round its circle, in [−π, π): one half-open
    wrap, the same as the sweeps' vectorised one, so both turn the wheel alike at ±π."""
    return (angle + math.pi) % math.tau - math.pi


def _locals(mech: Mechanism) -> dict[tuple[int, str], np.ndarray]:
    return {(k.number, n): np.array(xy, dtype=float) for k in mech.links for n, xy in k.points}


def _unit(v) -> np.ndarray:
    v = np.asarray(v, dtype=float)
    n = math.hypot(v[0], v[1])
    if n == 0.0:
        raise InputError("a slide has a zero direction vector")
    return v / n
