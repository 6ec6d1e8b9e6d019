"""The analytic reference for instant centres: where two velocity fields agree.

Link ``k`` moves with the velocity field ``v_k(P) = v_Ok + ω_k × (P − O_k)``
(the frame, link 1, has ``v = 0`` everywhere). The instant centre ``I_ij`` is the
point where ``v_i(P) = v_j(P)``. The difference of two fields is the field of a
rigid motion turning at ``Δω = ω_i − ω_j``,

    Δv(P) = Δv(Q) + Δω k × (P − Q),

so ``Δv(P) = 0`` at ``P = Q + k × Δv(Q) / Δω`` for any reference point ``Q``.
When ``Δω`` vanishes the relative motion is a translation and the centre is at
infinity, square to the relative velocity.

The fields are those of the mechanism's free motion (:class:`FreeMotion`, the
motion with the input let go, up to scale) when that is the sharper: centres hang on
velocity ratios alone, and near a dead point of the input the solved ω and v carry an
error of ``eps/rcond`` of their size while that direction stays well conditioned. A pin
two links share is their centre by definition; its reference is where the solver puts
the pin, so that it stays sharp even at a change point, where both motions lose it.

This module is a reference, not a construction: it takes positions, ω and the origins'
velocities from :mod:`.solver` and uses nothing of the graphical methods. It imports
only the standard library, :mod:`constructions.errors`, :mod:`constructions.model` and
:mod:`.solver`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..model import Mechanism
from .solver import Kinematics
from ..errors import DegenerateInput

__all__ = ["AnalyticCentre", "MoveTogether", "instant_centre", "CentreReference", "shared_pin",
           "centre_error", "mechanism_size", "AT_INFINITY", "FAR"]

EPS = 2.220446049250313e-16

AT_INFINITY = 1e-12
"""Relative size of ``|Δω|·L`` against ``|Δv|`` below which ``I_ij`` is at infinity.

The solver's ω carry an absolute rounding error of a few ``eps`` times the
mechanism's angular-velocity scale, of order ``|Δv|/L`` for links whose relative
velocity across a mechanism of size ``L`` is ``|Δv|``. So a ``|Δω|`` below about
``10 eps·|Δv|/L`` (≈ 2e-15·|Δv|/L) cannot be told from 0, and the centre it would
give lies beyond ``1e14·L``, a distance made of rounding. The threshold sits some
500 times above that noise, at 1e-12: a centre beyond ``1e12·L`` is taken as a
direction, whose bearing from any point of the mechanism then differs from the
true one by less than about 1e-12 rad (added to the centre's ``rounding``).
"""

FAR = 1e6
"""A finite point further than ``FAR × size`` may be compared with a direction."""

_STILL = 1e-12  # |Δv| and |Δω|·L both below this times the velocity scale: moving together


class MoveTogether(DegenerateInput):
    """Two links have no relative motion at this instant: every point is their centre."""


@dataclass(frozen=True)
class AnalyticCentre:
    """The analytic instant centre: a ``point`` (m), or a ``direction`` at infinity.

    Exactly one of the two is set. A direction has no sense; it is a unit vector
    normalised as :meth:`constructions.geometry.Point.at_infinity` does (x > 0, or
    x = 0 and y > 0). ``rounding`` is the reference's own error estimate, in the
    measure of :func:`centre_error`: it grows as ``|ω_i − ω_j|`` shrinks against the
    mechanism's ω, where the solver's rounding in ω and v is divided by a small
    difference. A check should allow ``tolerance(conditioning) + rounding``.
    """

    point: tuple[float, float] | None
    direction: tuple[float, float] | None
    rounding: float = 0.0

    @property
    def is_at_infinity(self) -> bool:
        """True when the centre is a direction."""
        return self.point is None


def mechanism_size(kin: Kinematics) -> float:
    """Return the largest distance between two of the mechanism's points (m).

    Examples
    --------
    >>> import types
    >>> kin = types.SimpleNamespace(points={"A": (0.0, 0.0), "B": (3.0, 4.0)})
    >>> mechanism_size(kin)
    5.0
    """
    xy = list(kin.points.values())
    return max([0.0] + [math.dist(p, q) for p in xy for q in xy])


def _canonical(dx: float, dy: float) -> tuple[float, float]:
    """A unit direction without sense: flipped so that x > 0, or x = 0 and y > 0."""
    n = math.hypot(dx, dy)
    x, y = dx / n, dy / n
    if x < 0.0 or (x == 0.0 and y < 0.0):
        x, y = -x, -y
    return (x + 0.0, y + 0.0)


def _omega(motion, k: int) -> float:
    return 0.0 if k == 1 else motion.omegas[k]


def _field(kin: Kinematics, motion, k: int, p: tuple[float, float]) -> tuple[float, float]:
    """Velocity of the point at ``p`` taken as fixed to link ``k`` in ``motion`` (``kin``
    itself, or its free motion)."""
    if k == 1:
        return (0.0, 0.0)
    (ox, oy), (vx, vy), w = kin.origins[k], motion.origin_velocities[k], motion.omegas[k]
    return (vx - w * (p[1] - oy), vy + w * (p[0] - ox))


def _scale(kin: Kinematics, motion, pts, size: float) -> float:
    """The motion's velocity scale: its largest ``|ω|·L`` or point speed."""
    return max([abs(w) * size for w in motion.omegas.values()]
               + [math.hypot(*_field(kin, motion, k, p)) for k in motion.omegas for p in pts])


def instant_centre(kin: Kinematics, i: int, j: int, *, pin: str | None = None) -> AnalyticCentre:
    """Locate ``I_ij`` where the velocity fields of links ``i`` and ``j`` agree.

    Parameters
    ----------
    kin : Kinematics
        A solution from :func:`constructions.analytic.solve` (with a nonzero input ω;
        the centres do not depend on its size).
    i, j : int
        Two link numbers (1 is the frame).
    pin : str, optional
        A point both links carry (see :func:`shared_pin`): a centre by definition, so
        its reference is where the solver puts it, whatever the conditioning of the
        velocities (at a change point, where the free linkage is itself singular, the
        fields lose it by orders of magnitude).

    Returns
    -------
    AnalyticCentre
        A finite point, or, when ``|ω_i − ω_j|·L ≤ AT_INFINITY·|v_i − v_j|``, the
        direction square to the relative velocity.

    Raises
    ------
    DegenerateInput
        If ``i == j``, the mechanism does not move (ω = 0), or links i and j move
        together at this instant (no relative velocity anywhere).

    Examples
    --------
    A link turning at 2 rad/s about (1, 0) against the frame:

    >>> import types
    >>> kin = types.SimpleNamespace(points={"O": (1.0, 0.0), "A": (2.0, 0.0)},
    ...                             origins={2: (2.0, 0.0)}, origin_velocities={2: (0.0, 2.0)},
    ...                             omegas={2: 2.0}, conditioning=1.0)
    >>> ref = instant_centre(kin, 1, 2)
    >>> ref.point, ref.rounding < 1e-14
    ((1.0, 0.0), True)
    """
    if i == j:
        raise DegenerateInput(f"I{i}{j} needs two different links")
    return CentreReference(kin).centre(i, j, pin=pin)


class CentreReference:
    """Every instant centre of one solution ``kin``: what the centres share (the reference
    point, the mechanism's size, each motion's velocity scale) found once.

    Raises
    ------
    DegenerateInput
        If the mechanism does not move (ω = 0).
    """

    def __init__(self, kin: Kinematics):
        self.kin = kin
        pts = list(kin.points.values())
        self.q = (sum(p[0] for p in pts) / len(pts), sum(p[1] for p in pts) / len(pts))
        self.size = max(mechanism_size(kin), 1e-300)
        self.scale = _scale(kin, kin, pts, self.size)
        if self.scale == 0.0:
            raise DegenerateInput("nothing moves (every ω and velocity is 0): give the input a "
                                  "nonzero ω to locate instant centres")
        free = getattr(kin, "free", None)
        self.free = None if free is None else (free, _scale(kin, free, pts, self.size))

    def centre(self, i: int, j: int, *, pin: str | None = None) -> AnalyticCentre:
        """``I_ij``, as :func:`instant_centre` gives it."""
        if i == j:
            raise DegenerateInput(f"I{i}{j} needs two different links")
        kin, q, size = self.kin, self.q, self.size
        # The driven motion first: two links that move together have no centre, pin or not.
        driven = _located(kin, kin, self.scale, i, j, q, size)
        if pin is not None:
            return AnalyticCentre(kin.points[pin], None, 4.0 * EPS)
        # Both motions give the centre, each with its own rounding. Near a dead point of the
        # input the free motion is sharper by orders of magnitude (see the module's
        # docstring), except for a centre of the input and the frame, whose |Δω| the free
        # motion nearly loses there. Elsewhere the two agree to rounding and the driven one,
        # whose zeros are exact (a block's ω), is kept: the free one must be sharper tenfold
        # to be taken.
        if self.free is None:
            return driven
        try:
            sharper = _located(kin, *self.free, i, j, q, size)
        except MoveTogether:
            return driven
        return sharper if 10.0 * sharper.rounding < driven.rounding else driven


def _located(kin: Kinematics, motion, scale: float, i: int, j: int, q: tuple[float, float],
             size: float) -> AnalyticCentre:
    """``I_ij`` from the fields of ``motion``, whose velocity scale is ``scale``, taken
    about the reference point ``q``."""
    (vix, viy), (vjx, vjy) = _field(kin, motion, i, q), _field(kin, motion, j, q)
    dvx, dvy = vix - vjx, viy - vjy
    dv = math.hypot(dvx, dvy)
    dw = _omega(motion, i) - _omega(motion, j)
    if dv <= _STILL * scale and abs(dw) * size <= _STILL * scale:
        raise MoveTogether(f"links {i} and {j} move together at this instant, so I{i}{j} "
                           "is undefined (every point is a centre)")
    # The motion's ω and v each carry about eps/rcond of their scale (rcond: the scaled
    # Jacobian's reciprocal condition number); a difference of two doubles that, and the
    # centre divides it by |Δv| (a direction) or by |Δω| (a point): hence the 4.
    noise = 4.0 * EPS / max(motion.conditioning, EPS)
    if abs(dw) * size <= AT_INFINITY * dv:
        # Taking a point beyond L/AT_INFINITY as a direction turns its bearing from the
        # mechanism by at most |Δω|·(|Q| + L)/|Δv|.
        bend = abs(dw) * (math.hypot(*q) + size) / dv
        return AnalyticCentre(None, _canonical(-dvy, dvx), noise * scale / dv + bend)
    # Δv(P) = Δv(Q) + Δω k × (P − Q) = 0  ⇒  P = Q + k × Δv(Q) / Δω.
    p = (q[0] - dvy / dw, q[1] + dvx / dw)
    reach = math.hypot(p[0] - q[0], p[1] - q[1])
    rounding = noise * scale * (1.0 + reach / size) / (abs(dw) * max(size, math.hypot(*p)))
    return AnalyticCentre(p, None, rounding)


def shared_pin(mech: Mechanism, i: int, j: int) -> str | None:
    """The one point links ``i`` and ``j`` both carry (their pin), or None.

    >>> from tarsim.constructions.model import Drive, Link, Mechanism
    >>> m = Mechanism((Link(1, (("O2", (0, 0)),)), Link(2, (("O2", (0, 0)), ("A", (1, 0)))),
    ...                Link(3, (("A", (0, 0)),))), Drive(2, 0.0))
    >>> shared_pin(m, 2, 1), shared_pin(m, 3, 2), shared_pin(m, 1, 3)
    ('O2', 'A', None)
    """
    both = set(mech.link(i).names) & set(mech.link(j).names)
    return both.pop() if len(both) == 1 else None


def centre_error(found, ref: AnalyticCentre, size: float) -> float:
    """Return the relative error of a constructed centre against the reference.

    - Both finite: ``|P − P_ref| / max(size, |P_ref|)``, so a far centre is judged
      relative to its own distance.
    - Both at infinity: ``|sin|`` of the angle between the directions.
    - One at infinity: if the finite one is further than ``FAR·size`` from the
      origin, the ``|sin|`` of the angle between its position vector and the
      direction; otherwise ``inf``.

    Parameters
    ----------
    found : constructions.geometry.Point
        The constructed centre (any object with ``is_at_infinity``, ``xy`` and
        ``direction``).
    ref : AnalyticCentre
        The analytic centre.
    size : float
        The mechanism's size (m), the scale of a position error.

    Examples
    --------
    >>> from tarsim.constructions.geometry import Point
    >>> centre_error(Point(6.0, 9.0), AnalyticCentre((6.0, 8.0), None), 1.0)
    0.1
    >>> centre_error(Point(0.0, 1.0, 0.0), AnalyticCentre(None, (0.0, 1.0)), 1.0)
    0.0
    >>> centre_error(Point(1.0, 2.0), AnalyticCentre(None, (0.0, 1.0)), 1.0)
    inf
    """
    if not found.is_at_infinity and not ref.is_at_infinity:
        (x, y), (rx, ry) = found.xy, ref.point
        return math.hypot(x - rx, y - ry) / max(size, math.hypot(rx, ry))
    if found.is_at_infinity and ref.is_at_infinity:
        (a, b), (c, d) = found.direction, ref.direction
        return abs(a * d - b * c)
    if found.is_at_infinity:
        (px, py), (dx, dy) = ref.point, found.direction
    else:
        (px, py), (dx, dy) = found.xy, ref.direction
    r = math.hypot(px, py)
    if r <= FAR * size:
        return math.inf
    return abs(px * dy - py * dx) / r
