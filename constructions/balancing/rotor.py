"""What a balancing exercise is made of (SI units, angles CCW from the reference radius).

A rotor carries masses, each at a radius and an angle about the shaft and in a plane at
an axial position; balancing masses go in one plane (static balance) or two (dynamic).
An engine has cylinders in line, each with its crank's angle and its plane, the same crank
radius, connecting rod and reciprocating mass.
"""

from __future__ import annotations

from dataclasses import dataclass

__all__ = ["Engine", "Mass", "Plane", "Rotor"]


@dataclass(frozen=True)
class Mass:
    """A mass ``mass`` (kg) at ``radius`` (m) and ``angle`` (rad) in the plane at ``plane``
    (m along the shaft)."""

    name: str
    mass: float
    radius: float
    angle: float
    plane: float = 0.0

    @property
    def mr(self) -> tuple[float, float]:
        """Its mass–radius product as a vector (kg·m)."""
        import math

        return (self.mass * self.radius * math.cos(self.angle),
                self.mass * self.radius * math.sin(self.angle))


@dataclass(frozen=True)
class Plane:
    """A balancing plane at ``position`` (m along the shaft), with the radius its mass goes
    at, or the mass it carries (the other is found)."""

    name: str
    position: float
    radius: float | None = None
    mass: float | None = None


@dataclass(frozen=True)
class Rotor:
    """Masses on a shaft turning at ``speed`` (rad/s), and its balancing planes (none where
    its out-of-balance force and couple are asked)."""

    masses: tuple[Mass, ...]
    planes: tuple[Plane, ...]
    speed: float
    about: float | None = None
    """Where no balancing plane is given, the plane (m) its out-of-balance couple is taken
    about (None: midway between the outermost masses)."""
    bearings: tuple[tuple[str, float], ...] = ()
    """Where no balancing plane is given, two bearings (name, position in m) whose
    out-of-balance forces are asked."""


@dataclass(frozen=True)
class Engine:
    """An in-line engine: each cylinder's crank angle (rad) and plane (m), the crank radius
    and connecting rod (m), the reciprocating mass a cylinder (kg), its speed (rad/s); a
    single cylinder may be partly balanced by a rotating mass opposite its crank, the
    fraction ``balanced`` of the reciprocating mass at the crank radius, and its forces are
    asked at the crank angle ``at`` (rad).

    A single cylinder may carry revolving masses too (crank, crank pin, the rod's revolving
    part), ``revolving`` kg reduced to the crank radius: the balance mass takes them whole
    with the fraction of the reciprocating mass, a product (m_rev + c·m)·r, put at
    ``balance_radius`` (m, its mass found) or of ``balance_mass`` (kg, its radius found).
    ``rod`` is None where no secondary force is asked: the primary forces need no rod."""

    cranks: tuple[float, ...]
    planes: tuple[float, ...]
    crank: float
    rod: float | None
    reciprocating: float
    speed: float | None
    """The speed (rad/s); None where the file gives none and asks only what needs none (a
    locomotive's balance masses), or the lift speed found where ``at_lift``."""
    balanced: float = 0.0
    at: float = 0.0
    revolving: float = 0.0
    balance_radius: float | None = None
    balance_mass: float | None = None
    wheel: float | None = None
    """A locomotive's driving wheels' diameter (m), where its speed is given on them."""
    dead_load: float | None = None
    """The dead load on each driving wheel (N), against which the hammer blow lifts it."""
    at_given: bool = False
    """Whether the file asks the forces at ``at`` (an in-line engine's crank 1 from the
    i.d.c.; a single cylinder's are asked at 0° without it)."""
    masses: tuple[float, ...] = ()
    """Each cylinder's reciprocating mass (kg) where they differ (given one by one, or found
    by a primary balance); empty where every cylinder has ``reciprocating``."""
    vee: float = 0.0
    """A V engine's angle between its two cylinders' lines (rad), both on one crank: 0 for
    cylinders in line."""
    firing_order: tuple[int, ...] = ()
    """The order the cylinders fire in, where the file gives the cranks by it (empty where
    it gives them one by one), and the engine's ``strokes`` a cycle (2 or 4)."""
    strokes: int = 0
    at_lift: bool = False
    """Whether ``speed`` is the lift speed found, the file giving none: a locomotive's
    forces and couples are then asked at the speed at which its wheels lift."""
    radial: int = 0
    """A radial engine's number of cylinders, their lines evenly round the crank shaft and
    every rod on one crank: 0 for cylinders in line or a V."""
    coupled: int = 1
    """How many pairs of coupled wheels share the balanced fraction of the reciprocating
    mass equally, the driving wheels among them (1: the driving wheels take it all)."""
    hammer_blow: float | None = None
    """The greatest hammer blow allowed on a driving wheel (N), where the books ask the speed
    at which it is reached: found as a dead load's lift speed is, but no wheel lifts."""

    @property
    def speed_load(self) -> float | None:
        """The load (N) whose speed is found: the dead load a blow lifts the wheel against,
        or the greatest hammer blow allowed; None where neither is given."""
        return self.dead_load if self.dead_load is not None else self.hammer_blow

    @property
    def balanced_each(self) -> float:
        """The fraction of each cylinder's reciprocating mass one pair of coupled wheels
        balances, ``balanced`` shared equally among the ``coupled`` pairs."""
        return self.balanced / self.coupled

    @property
    def each(self) -> tuple[float, ...]:
        """Each cylinder's reciprocating mass (kg), in the cylinders' order."""
        return self.masses or (self.reciprocating,) * len(self.cranks)
