"""What the analytic solver gives at one position, and how it refuses a dead point.

:class:`Kinematics` holds the positions, velocities and accelerations (SI),
:class:`SlideRate` the relative motion at each slide and :class:`FreeMotion` the motion
with the input let go; :func:`point_velocity` and :func:`point_acceleration` read a
point's motion as a point of a chosen link. Where the loop equations' Jacobian is
singular (its rcond below :data:`SINGULAR_RCOND`), ω and α are undefined and the
position is refused with :class:`SingularPosition`. :mod:`.solver` is the public entry
point for all of these.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..errors import DeadPoint, InputError
from ..joints import Slide
from ..model import Mechanism

__all__ = [
    "Kinematics",
    "FreeMotion",
    "SlideRate",
    "SingularPosition",
    "SINGULAR_RCOND",
    "point_velocity",
    "point_acceleration",
]

SINGULAR_RCOND = 1e-7
"""Below this reciprocal condition number of the scaled Jacobian a position is singular.

A toggle reached through rounding sits about ``sqrt(eps) ≈ 1.5e-8`` from exact
singularity, so a smaller threshold would let dead points through as huge ω.
"""


class SingularPosition(DeadPoint):
    """The position is a dead point: the Jacobian is singular, so ω and α are undefined."""


@dataclass(frozen=True, slots=True)
class SlideRate:
    """Relative motion at one slide, signed along the guide's global direction.

    ``position`` is the coordinate of the sliding point along the guide measured
    from the guide's ``through`` point; ``velocity`` and ``acceleration`` are its
    first and second time derivatives (the sliding velocity and acceleration seen
    from the guide link). ``direction`` is the guide's global unit direction and
    ``coriolis`` is ``2 ω_guide × v_rel``.
    """

    slide: Slide
    position: float
    velocity: float
    acceleration: float
    direction: tuple[float, float]
    coriolis: tuple[float, float]


@dataclass(frozen=True)
class FreeMotion:
    """The mechanism's one motion with the input let go: ω and origin velocities up to scale.

    The null vector of the loop equations without the input's row, unit in the
    length-scaled coordinates. Near a dead point of the input the solved ω and v grow
    without bound and carry an error of ``eps/rcond`` of their size, while this
    direction stays as well conditioned as the free linkage itself (``conditioning``:
    its smallest singular value over its largest). Whatever depends on velocity ratios
    alone, such as the instant centres, is taken from it.
    """

    omegas: dict[int, float]
    origin_velocities: dict[int, tuple[float, float]]
    conditioning: float


@dataclass(frozen=True)
class Kinematics:
    """Positions, velocities and accelerations of a mechanism at one input position (SI).

    A point's position, velocity and acceleration are those of the point as a point
    of the first link (in ``Mechanism.links`` order) that lists it. At a pin every
    carrier agrees to the residual, and a pin on the frame is exactly at rest. Use
    :func:`point_velocity` for a point taken on a particular link. ``slide_rates``
    follows the order of ``Mechanism.slides``. ``residual`` is ``max |Φ|`` (m or
    rad) at the solution and ``conditioning`` the reciprocal condition number of
    the length-scaled Jacobian (1 is ideal, below ``SINGULAR_RCOND`` is raised).
    ``origins`` and their rates are each link's local origin, the frame included.
    Angles are wrapped to ``[−π, π]``. ``free`` is the motion with the input let go
    (see :class:`FreeMotion`).
    """

    points: dict[str, tuple[float, float]]
    angles: dict[int, float]
    omegas: dict[int, float]
    alphas: dict[int, float]
    velocities: dict[str, tuple[float, float]]
    accelerations: dict[str, tuple[float, float]]
    slide_rates: tuple[SlideRate, ...]
    residual: float
    conditioning: float
    origins: dict[int, tuple[float, float]]
    origin_velocities: dict[int, tuple[float, float]]
    origin_accelerations: dict[int, tuple[float, float]]
    free: FreeMotion | None = None


def _dead_point(mech: Mechanism, free: list[int]) -> SingularPosition:
    """The refusal of a dead point, where links ``free`` can move with the input held."""
    who = "link" if len(free) == 1 else "links"
    return SingularPosition(
        f"dead point at input angle {mech.units.angle_brief(mech.drive.angle)}: {who} "
        f"{', '.join(map(str, free))} can move while link {mech.drive.link} is held, so ω and "
        "α are undefined; choose another input angle or another input link", link=free[0],
        angle_deg=math.degrees(mech.drive.angle))


def _velocity(p, origin, v0, omega) -> tuple[float, float]:
    rx, ry = p[0] - origin[0], p[1] - origin[1]
    return (float(v0[0] - omega * ry), float(v0[1] + omega * rx))


def _acceleration(p, origin, a0, omega, alpha) -> tuple[float, float]:
    rx, ry = p[0] - origin[0], p[1] - origin[1]
    return (float(a0[0] - alpha * ry - omega ** 2 * rx),
            float(a0[1] + alpha * rx - omega ** 2 * ry))


def _where(kin: Kinematics, mech: Mechanism, link: int, point) -> tuple[float, float]:
    mech.link(link)
    if isinstance(point, str):
        if point not in kin.points:
            raise InputError(f"there is no point {point}", file=mech.source or None)
        return kin.points[point]
    return (float(point[0]), float(point[1]))


def point_velocity(kin: Kinematics, mech: Mechanism, link: int, point) -> tuple[float, float]:
    """Return the velocity of a point taken as fixed to ``link``: ``v_O + ω × r``.

    Parameters
    ----------
    kin, mech : Kinematics, Mechanism
        A solution and the mechanism it solves.
    link : int
        The link the point is fixed to (1 gives zero).
    point : str or (float, float)
        A point name, or a global position in metres (e.g. a coincident point).

    Raises
    ------
    InputError
        If the link or the point name is unknown.
    """
    return _velocity(_where(kin, mech, link, point), kin.origins[link],
                     kin.origin_velocities[link], kin.omegas[link])


def point_acceleration(kin: Kinematics, mech: Mechanism, link: int,
                       point) -> tuple[float, float]:
    """Return the acceleration of a point fixed to ``link``: ``a_O + α × r − ω² r``.

    See :func:`point_velocity` for the parameters.
    """
    return _acceleration(_where(kin, mech, link, point), kin.origins[link],
                         kin.origin_accelerations[link], kin.omegas[link], kin.alphas[link])
