"""What loads a mechanism carries, for its force analysis (SI units, CCW-positive).

Each moving link may have a mass at a centre of mass (a point of the link in its own
coordinates) and a moment of inertia about it; external forces act at points of links,
couples on links; gravity pulls along −y. One link, the input, carries the unknown driving
torque that keeps the motion as given.
"""

from __future__ import annotations

import math
import sys
from collections.abc import Callable
from dataclasses import dataclass

__all__ = ["Couple", "Loads", "Mass", "PointForce", "GRAVITY", "ROUNDINGS", "UNSURE",
           "crank_tangent", "leaning", "made_of", "near_rest", "near_rest_refusal",
           "resting_speed", "stroke_axis"]

GRAVITY = 9.81
"""m/s², the value the course project uses."""

ROUNDINGS = 64
"""How many roundings of a zero a speed may stand at and still be one: the checks allow a
construction as many (:func:`~.checks.tolerance`)."""


def resting_speed(fastest: float, conditioning: float) -> float:
    """The fastest a slide may slide, a pin turn or a resisted point move and still rest (m/s,
    or rad/s for a pin): :data:`ROUNDINGS` times eps of the ``fastest`` speed (or rate) its
    reading is made of, over the ``conditioning`` it is read at.

    A speed read as the difference of speeds of size ``fastest`` carries their rounding,
    magnified as the reading is ill-conditioned: below that it is the rounding of a zero,
    and its sign is no direction, so it must not choose friction's side or a resistance's
    way. Each reading passes its own rounding: the force polygons the velocity polygon's
    extent and worst conditioning (times what a lever multiplies a reading by beyond it),
    the Newton–Euler reference the solver's fastest speed and its Jacobian's conditioning.
    Where a joint's speed is below this, friction's direction is undefined at the data's
    precision (it flips as the joint passes rest); the joint is taken at rest, as one
    exactly at rest is (an extreme position, a dead centre), friction taking no side, and
    the force polygons say so. Just past it the way is still in doubt (:func:`near_rest`).

    >>> resting_speed(2.0, 0.5) == 64 * 2.0**-52 * 2.0 / 0.5
    True
    """
    if not conditioning > 0.0:
        return math.inf                 # read with no digit: no speed is known to move
    return ROUNDINGS * sys.float_info.epsilon * fastest / conditioning


UNSURE = 64
"""How many times its rounding of a zero a speed must pass before its way is read. Each method
estimates its own rounding (the polygons from their crossings and a lever's gain, the
reference from its Jacobian), and the two estimates differ, 2 to 20 times in the course's
mechanisms: a speed past one method's rounding but within this many of it may be motion to
it and rest to the other, and is refused by both rather than read either way."""


def near_rest(speed: float, still: float) -> bool:
    """Whether ``speed`` is past the rounding of a zero ``still`` but within :data:`UNSURE`
    times it: too near rest to tell which way it moves, so friction's side, or whether a
    resistance on a stroke acts, is not known.

    >>> near_rest(1.0, 1.0), near_rest(2.0, 1.0), near_rest(65.0, 1.0)
    (False, True, False)
    """
    return still < speed <= UNSURE * still


def near_rest_refusal(mech, moving: str, share: float, *, of: str = "speed",
                      acting: str = "friction") -> str:
    """The one line that refuses a speed :func:`near_rest` at ``mech``'s position: what is
    ``moving`` ("link 5 slides on link 1"), its ``share`` of the fastest ``of`` (speed or
    rate), and what it would choose the way of."""
    d = mech.drive
    return (f"at θ{d.link} = {mech.units.angle_brief(d.angle)}: {moving} at {share:.1e} of "
            f"the fastest {of}, too near rest to tell which way {acting} acts; choose one "
            "farther from rest")


@dataclass(frozen=True)
class Mass:
    """Link ``link``'s mass (kg), its centre ``centre`` in the link's own coordinates (m)
    and its moment of inertia about that centre (kg·m²). ``assumed`` says how the inertia
    was come by when the file did not give it ("slender rod, (1/12)mL²")."""

    link: int
    mass: float
    centre: tuple[float, float]
    inertia: float
    assumed: str = ""
    centre_name: str = ""
    """How the file named the centre: a point ("A"), "mid" or ""."""
    swing: tuple[float, float, str, bool] | None = None
    """A pendulum test the inertia comes from: its period (s), the distance h (m) from the
    point of suspension to G, that point as the file names it, and whether it hung on a
    knife edge in that pin's bore."""


def pendulum_radius(period: float, h: float, g: float = GRAVITY) -> float:
    """The radius of gyration about G (m) of a body that swings as a compound pendulum with
    ``period`` (s) hung ``h`` (m) from G: T = 2π·√((k² + h²)/(g·h)), so k = √(g·h·T²/(4π²)
    − h²); 0 where the period is too short for a body hung there.

    >>> round(pendulum_radius(22 / 8, 1.2), 9)           # the books' rod, h = 2 − 0.8 m
    0.902800416
    """
    return math.sqrt(max(g * h * period ** 2 / (4 * math.pi ** 2) - h * h, 0.0))


@dataclass(frozen=True)
class PointForce:
    """A force (N, world components) on link ``link`` at ``point``: a point name, or a point
    in the link's own coordinates (m).

    A resisting force (a cutting force) is given instead by ``resist``, its size against
    the point's velocity; with ``along`` it acts only while the point moves that way (the
    cutting stroke), and not at all while the point stands still."""

    link: int
    point: str | tuple[float, float]
    force: tuple[float, float] = (0.0, 0.0)
    name: str = ""
    resist: float = 0.0
    along: tuple[float, float] | None = None


@dataclass(frozen=True)
class Couple:
    """A couple (N·m, CCW +) on link ``link``."""

    link: int
    moment: float
    name: str = ""


@dataclass(frozen=True)
class Loads:
    """Everything that loads the mechanism; ``gravity`` is g (0 for none)."""

    masses: tuple[Mass, ...] = ()
    forces: tuple[PointForce, ...] = ()
    couples: tuple[Couple, ...] = ()
    gravity: float = GRAVITY
    speed_fluctuation: float | None = None
    """The coefficient C_s a flywheel is to hold the speed within, if given."""
    flywheel: float | None = None
    """A flywheel's inertia (kg·m²) whose C_s is asked, if given."""
    resisting: float | None = None
    """The mean resisting torque (N·m) the engine works against, given or its power over ω:
    with ``flywheel``, the flywheel's α at the position is (T − T_mean)/I."""
    friction: float = 0.0
    """μ at every sliding pair: a slide's push leans φ = atan μ off the normal to its guide,
    against the sliding (0: frictionless)."""
    friction_circle: float = 0.0
    """ρ (m), the friction circle's radius at every pin (μ times the pin's radius): a pin's
    force touches it on the side that resists the turning, a couple ρ·|F| (0: none)."""

    def mass_of(self, link: int) -> Mass | None:
        """The mass on ``link``, if it has one."""
        return next((m for m in self.masses if m.link == link), None)


def made_of(loads: Loads, motion: Callable[[Mass], tuple[float, float, float]], *,
            size: float, a_in: float) -> float:
    """The force (N) the joint forces are made of, and so round at.

    Each mass's weight and inertia force, m·(g + |a_G| + ω²·size + a_in), and its inertia
    couple over ``size`` (the mechanism's, m), I·(|α| + ω² + a_in/size)/size: an
    acceleration is found from the ω² terms and the input's acceleration ``a_in``, and
    rounds at their size even where they cancel; each external force's size, and each
    couple over ``size``. ``motion`` gives a mass's link's ω, α and its centre's |a_G|. A
    joint force is a sum of these, turned and levered; where they nearly cancel, this, not
    the joint force itself, is what its rounding is relative to.

    >>> made_of(Loads(masses=(Mass(2, 2.0, (0.0, 0.0), 0.0),), gravity=10.0),
    ...         lambda m: (3.0, 0.0, 4.0), size=1.0, a_in=5.0)
    56.0
    """
    size = size or 1.0
    terms = []
    for m in loads.masses:
        w, a, a_g = motion(m)
        terms.append(m.mass * (loads.gravity + a_g + w * w * size + a_in)
                     + m.inertia * (abs(a) + w * w + a_in / size) / size)
    terms += [math.hypot(*f.force) + f.resist for f in loads.forces]
    terms += [abs(c.moment) / size for c in loads.couples]
    return math.fsum(terms)


def stroke_axis(pivot, pin, stroke) -> tuple[float, float]:
    """The direction a piston effort is measured along, as the textbooks sign it: the line
    of stroke ``stroke`` (a unit vector) turned toward the crank's ``pivot`` from the
    piston's ``pin`` (world points, m)."""
    if stroke[0] * (pivot[0] - pin[0]) + stroke[1] * (pivot[1] - pin[1]) < 0.0:
        return (-stroke[0], -stroke[1])
    return stroke


def crank_tangent(pivot, crank_pin) -> tuple[float, float]:
    """The CCW unit tangent of the crank's pin circle at ``crank_pin``: a crank effort along
    it is positive."""
    dx, dy = crank_pin[0] - pivot[0], crank_pin[1] - pivot[1]
    r = (dx * dx + dy * dy) ** 0.5
    return (-dy / r, dx / r)


def leaning(normal, sliding, mu: float, side: float) -> tuple[float, float]:
    """The direction u of a slide's push with friction μ: a push N·u has the normal part N
    (along the guide's unit ``normal``) and, when N has the sign ``side``, the part μ·|N|
    against ``sliding`` (the unit velocity of the slider on its guide; zero when it rests,
    and friction then takes no side): u = n − side·μ·v̂, leaned φ = atan μ off the normal."""
    return (normal[0] - side * mu * sliding[0], normal[1] - side * mu * sliding[1])
