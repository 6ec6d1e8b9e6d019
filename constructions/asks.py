"""What an exercise asks for, typed: each name results.json uses, parsed once into an :class:`Ask`.

An exercise writes its asks as results.json names them (``I13``, ``omega4``,
``V_B``, ``A_B4``, ``V_B/A``, ``A_cor_B``, ``time_ratio`` …). :func:`parse_ask`
reads one into its type, which knows its name, its symbol as the course writes
it (ω4, Aᶜ_B) and its place in a solution's order; the methods that answer it
are found by its type (:mod:`.registry`).

The asks of one position come in the order the course takes them: centres,
angular velocities, velocities, relative vectors, angular accelerations,
accelerations, Coriolis components. Those of the mechanism as a whole (DOF,
Grashof, the length ranges, time ratio, stroke) come first, before any position.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from typing import ClassVar

from .errors import TarsimError
from .model import Mechanism

__all__ = ["Ask", "Position", "Centre", "AngularVelocity", "Velocity", "Relative",
           "AngularAcceleration", "Acceleration", "AccelerationPart", "Coriolis", "Sliding",
           "Ratio", "MechanicalAdvantage", "Distance", "TransmissionAngle", "LeastVelocity",
           "Rubbing", "Equivalent",
           "Mobility",
           "GrashofClass",
           "LengthRange", "TimeRatio", "Stroke", "Swing", "StrokeEvent", "CentreCount",
           "JointForce",
           "DrivingTorque", "Effort", "EFFORTS", "MOMENTS",
           "parse_ask", "ask_names", "on_one_line",
           "SYMBOLS", "symbol", "ordered"]

SYMBOLS = {"omega": "ω", "alpha": "α", "theta": "θ", "A_cor_": "Aᶜ_", "An_": "Aⁿ_",
           "At_": "Aᵗ_", "mu": "μ"}
"""The course's letters for the words results.json spells: omega4 is ω4, A_cor_B is Aᶜ_B,
An_B/A is Aⁿ_B/A."""


def symbol(name: str) -> str:
    """A results.json name as the course writes it.

    Examples
    --------
    >>> symbol("omega4"), symbol("A_cor_B"), symbol("V_B/A"), symbol("omega4/omega2")
    ('ω4', 'Aᶜ_B', 'V_B/A', 'ω4/ω2')
    """
    if "/" in name:
        return "/".join(symbol(part) for part in name.split("/"))
    for word, letter in SYMBOLS.items():
        if name.startswith(word):
            return letter + name[len(word):]
    return name


@dataclass(frozen=True)
class Ask:
    """One quantity asked for. ``scope`` is "position" (found at each position solved) or
    "mechanism" (of the mechanism as a whole); ``order`` places it in a solution."""

    scope: ClassVar[str] = "position"
    order: ClassVar[int] = 0

    @property
    def name(self) -> str:
        """The name results.json and the exercise file use."""
        raise NotImplementedError

    @property
    def symbol(self) -> str:
        """The name as the course writes it: ω4, Aᶜ_B."""
        return symbol(self.name)

    def __str__(self) -> str:
        return self.name


@dataclass(frozen=True)
class Position(Ask):
    """Where point ``point`` is, as the compass put it: position before velocity."""

    point: str
    order: ClassVar[int] = -1

    @property
    def name(self) -> str:
        """``pos_B``."""
        return f"pos_{self.point}"


@dataclass(frozen=True)
class Centre(Ask):
    """An instant centre ``I_ij`` (``pair`` ascending)."""

    pair: tuple[int, int]
    order: ClassVar[int] = 0

    @property
    def name(self) -> str:
        """``I13``; ``I1,10`` past link 9."""
        i, j = self.pair
        return f"I{i}{j}" if j < 10 else f"I{i},{j}"


@dataclass(frozen=True)
class AngularVelocity(Ask):
    """ω of link ``link``."""

    link: int
    order: ClassVar[int] = 1

    @property
    def name(self) -> str:
        """``omega4``."""
        return f"omega{self.link}"


@dataclass(frozen=True)
class Velocity(Ask):
    """The velocity of point ``point`` (``A4``: the point of link 4 under A)."""

    point: str
    order: ClassVar[int] = 2

    @property
    def name(self) -> str:
        """``V_B``."""
        return f"V_{self.point}"


@dataclass(frozen=True)
class Relative(Ask):
    """A relative velocity ``V_P/Q`` or acceleration ``A_P/Q`` (``letter`` V or A)."""

    letter: str
    point: str
    of: str
    order: ClassVar[int] = 3

    @property
    def name(self) -> str:
        """``V_B/A``."""
        return f"{self.letter}_{self.point}/{self.of}"


@dataclass(frozen=True)
class AngularAcceleration(Ask):
    """α of link ``link``."""

    link: int
    order: ClassVar[int] = 4

    @property
    def name(self) -> str:
        """``alpha4``."""
        return f"alpha{self.link}"


@dataclass(frozen=True)
class Acceleration(Ask):
    """The acceleration of point ``point`` (``B4``: the point of link 4 under B)."""

    point: str
    order: ClassVar[int] = 5

    @property
    def name(self) -> str:
        """``A_B``."""
        return f"A_{self.point}"


@dataclass(frozen=True)
class AccelerationPart(Ask):
    """The normal (``part`` "n") or tangential ("t") part of the acceleration of ``point``:
    relative to ``of``, a point of the same link (along and across the line joining them),
    or, with ``of`` None, absolute (across and along the point's path)."""

    part: str
    point: str
    of: str | None = None
    order: ClassVar[int] = 5

    @property
    def name(self) -> str:
        """``An_B/A``, ``At_B``."""
        return f"A{self.part}_{self.point}" + ("" if self.of is None else f"/{self.of}")


@dataclass(frozen=True)
class Coriolis(Ask):
    """The Coriolis component at ``point``, which slides in a slot of a moving link."""

    point: str
    order: ClassVar[int] = 6

    @property
    def name(self) -> str:
        """``A_cor_B``."""
        return f"A_cor_{self.point}"


@dataclass(frozen=True)
class Sliding(Ask):
    """The sliding velocity (``letter`` V) or acceleration (A) of ``point`` along the straight
    slot of a moving link it runs in, relative to the slot."""

    letter: str
    point: str
    order: ClassVar[int] = 6

    @property
    def name(self) -> str:
        """``V_slide_B``."""
        return f"{self.letter}_slide_{self.point}"


@dataclass(frozen=True)
class Ratio(Ask):
    """A ratio of two speeds, ``V_C/V_B`` (``letter`` V, points ``a`` over ``b``), or of two
    angular velocities, ``omega4/omega2`` (``letter`` omega, links), signed."""

    letter: str
    a: str
    b: str
    order: ClassVar[int] = 2

    @property
    def name(self) -> str:
        """``V_C/V_B``, ``omega4/omega2``."""
        sep = "_" if self.letter == "V" else ""
        return f"{self.letter}{sep}{self.a}/{self.letter}{sep}{self.b}"


@dataclass(frozen=True)
class MechanicalAdvantage(Ask):
    """The mechanical advantage at output link ``link``: input ω over output ω, as the
    instant centres give it (friction and inertia left out)."""

    link: int
    order: ClassVar[int] = 2

    @property
    def name(self) -> str:
        """``ma_4``."""
        return f"ma_{self.link}"


@dataclass(frozen=True)
class Distance(Ask):
    """The distance from point ``point`` to the instant centre ``I_pair``."""

    point: str
    pair: tuple[int, int]
    order: ClassVar[int] = 0

    @property
    def name(self) -> str:
        """``dist_B_I13``."""
        return f"dist_{self.point}_{Centre(self.pair).name}"


@dataclass(frozen=True)
class LeastVelocity(Ask):
    """The point of link ``link``'s line with the least velocity, and that velocity: the
    foot of the perpendicular from the link's instant centre I_1k. The line is ``line``,
    two of the link's points, the first the one its distance is measured from; or, with
    None, the line all the link's points lie on (a rod, with any point carried on it), or
    for a plate (points not on one line) the plate their outline bounds."""

    link: int
    line: tuple[str, str] | None = None
    order: ClassVar[int] = 2

    @property
    def name(self) -> str:
        """``Vmin_3``, or ``Vmin_3_A_B`` along the line AB of link 3."""
        return f"Vmin_{self.link}" + ("" if self.line is None else "_{}_{}".format(*self.line))


@dataclass(frozen=True)
class Rubbing(Ask):
    """The rubbing velocity at pin ``point`` of ``diameter`` (m): the relative angular
    velocity of the two links it joins times the pin's radius. The diameter is the
    exercise's (``[ask] pins``); None until it is read."""

    point: str
    diameter: float | None = None
    order: ClassVar[int] = 2

    @property
    def name(self) -> str:
        """``rub_B``."""
        return f"rub_{self.point}"


@dataclass(frozen=True)
class Equivalent(Ask):
    """The equivalent linkage of the contact whose circle is centred at ``point``: the link
    joining the centres of curvature (its length), or the slot parallel to a face (its
    offset)."""

    point: str
    order: ClassVar[int] = 0

    @property
    def name(self) -> str:
        """``equiv_R``."""
        return f"equiv_{self.point}"


@dataclass(frozen=True)
class TransmissionAngle(Ask):
    """A four-bar's transmission angle μ: between the coupler and the output link, at the pin
    that joins them."""

    order: ClassVar[int] = 0

    @property
    def name(self) -> str:
        """``mu``."""
        return "mu"


@dataclass(frozen=True)
class _Whole(Ask):
    """An ask of the mechanism as a whole, named by one word."""

    scope: ClassVar[str] = "mechanism"
    word: ClassVar[str] = ""

    @property
    def name(self) -> str:
        """Its word: ``dof``, ``grashof``."""
        return self.word


@dataclass(frozen=True)
class Mobility(_Whole):
    """The degrees of freedom (Grübler)."""

    word: ClassVar[str] = "dof"
    order: ClassVar[int] = 0


@dataclass(frozen=True)
class GrashofClass(_Whole):
    """The four-bar's Grashof class."""

    word: ClassVar[str] = "grashof"
    order: ClassVar[int] = 1


@dataclass(frozen=True)
class LengthRange(Ask):
    """The lengths of ``span`` (a link's two pins, ``O2O4`` for the frame) that keep the class."""

    span: str
    scope: ClassVar[str] = "mechanism"
    order: ClassVar[int] = 2

    @property
    def name(self) -> str:
        """``range_AB``."""
        return f"range_{self.span}"


@dataclass(frozen=True)
class TimeRatio(_Whole):
    """The quick-return time ratio, from the limit positions."""

    word: ClassVar[str] = "time_ratio"
    order: ClassVar[int] = 3


@dataclass(frozen=True)
class Stroke(_Whole):
    """The stroke of the block driven through the limit positions."""

    word: ClassVar[str] = "stroke"
    order: ClassVar[int] = 4


@dataclass(frozen=True)
class Swing(_Whole):
    """The angle rocker or lever ``link`` swings through between its limit positions (its
    angle of oscillation); a slotted lever's inclination to the line of centres beside it."""

    link: int
    order: ClassVar[int] = 5

    @property
    def name(self) -> str:
        """``swing_4``."""
        return f"swing_{self.link}"


@dataclass(frozen=True)
class StrokeEvent(Ask):
    """Over a turn of the crank at steady speed, of the block ``point`` on a frame guide:
    ``A_P_zero`` where its acceleration is 0 on the out-stroke (from the dead centre where
    it stands farthest from the crank shaft), ``V_P_max`` its greatest speed and where."""

    point: str
    letter: str = "A"
    scope: ClassVar[str] = "mechanism"
    order: ClassVar[int] = 5

    @property
    def name(self) -> str:
        """``A_P_zero`` or ``V_P_max``."""
        return f"{self.letter}_{self.point}_{'zero' if self.letter == 'A' else 'max'}"


@dataclass(frozen=True)
class CentreCount(_Whole):
    """How many instant centres there are, n(n − 1)/2, and how many of them inspection finds
    and how many Kennedy's theorem."""

    word: ClassVar[str] = "n_centres"
    order: ClassVar[int] = 5


@dataclass(frozen=True)
class JointForce(Ask):
    """The force of link ``by`` on link ``on`` at their joint (``F_23``), or, for a block on
    a guide, the guide's couple on it (``T_14``)."""

    by: int
    on: int
    letter: str = "F"
    order: ClassVar[int] = 9

    @property
    def name(self) -> str:
        """``F_23`` or ``T_14``."""
        return f"{self.letter}_{self.by}{self.on}"


@dataclass(frozen=True)
class DrivingTorque(Ask):
    """The torque the driver must put on the input link ``link`` (``T2``)."""

    link: int
    order: ClassVar[int] = 9

    @property
    def name(self) -> str:
        """``T2``."""
        return f"T{self.link}"


@dataclass(frozen=True)
class Effort(Ask):
    """An engine's force as the textbooks name it, from the force polygons: the piston
    effort (its loads along the stroke, + toward the crank), the wall's thrust on the
    piston (the size of its push square to the stroke), the reciprocating parts' inertia
    force (their m·a toward the crank, which the piston effort loses), the crank speed at
    which that inertia grows to the rest of the piston's load (rad/s), the crank effort
    (the rod's push on the crank pin square to the crank, + CCW), the turning moment it
    gives (N·m, CCW +), the thrust on the shaft's bearings (the push along the crank, + toward the
    shaft), the rod's correction couple (N·m: :mod:`~.forces.equivalent`), the turning
    moment of the reciprocating parts' or the rod's inertia loads alone (N·m) and the
    flywheel's angular acceleration (T − T_mean)/I (rad/s², + speeding up)."""

    word: str
    order: ClassVar[int] = 9

    @property
    def name(self) -> str:
        """``piston_effort``, ``wall_thrust``, ``inertia_force``, ``reversal_speed``,
        ``crank_effort``, ``turning_moment``, ``bearing_thrust``, ``correction_couple``,
        ``flywheel_alpha``, ``rod_radius_of_gyration``, ``inertia_torque_reciprocating`` or
        ``inertia_torque_rod``."""
        return self.word


EFFORTS = ("piston_effort", "wall_thrust", "inertia_force", "reversal_speed", "crank_effort",
           "turning_moment", "bearing_thrust", "correction_couple", "flywheel_alpha",
           "rod_radius_of_gyration", "inertia_torque_reciprocating", "inertia_torque_rod")
"""The efforts an exercise may ask: the first four, correction_couple, the rod's radius of
gyration about G (m, from its mass: a pendulum test's, or its given I) and the inertia
torque on the crankshaft split as the books split it, of the reciprocating parts and of the
rod (N·m, CCW +, each part's inertia loads alone), of a slider-crank only; flywheel_alpha,
the flywheel's α (rad/s²) against a mean resisting torque, where [forces] gives the
flywheel and the engine's power or that torque."""

MOMENTS = ("turning_moment", "correction_couple", "inertia_torque_reciprocating",
           "inertia_torque_rod")
"""The efforts that are moments (N·m); reversal_speed is a speed (rad/s), the rest forces
(N)."""


_POINT = r"([A-Za-z][A-Za-z0-9_']*)"
_PLAIN = r"([A-Za-z][A-Za-z0-9']*)"      # a point where an underscore follows
_GRAMMAR: tuple[tuple[re.Pattern, callable], ...] = tuple(
    (re.compile(f"^{pattern}$"), make) for pattern, make in (
        (f"pos_{_POINT}", lambda m: Position(m[1])),
        (f"V_{_PLAIN}/V_{_PLAIN}", lambda m: Ratio("V", m[1], m[2])),
        (r"omega(\d+)/omega(\d+)", lambda m: Ratio("omega", m[1], m[2])),
        (r"ma_(\d+)", lambda m: MechanicalAdvantage(int(m[1]))),
        (fr"Vmin_(\d+)_{_PLAIN}_{_PLAIN}", lambda m: LeastVelocity(int(m[1]), (m[2], m[3]))),
        (r"Vmin_(\d+)", lambda m: LeastVelocity(int(m[1]))),
        (f"rub_{_POINT}", lambda m: Rubbing(m[1])),
        (f"equiv_{_POINT}", lambda m: Equivalent(m[1])),
        (fr"dist_{_PLAIN}_I(\d)(\d)", lambda m: Distance(m[1], (int(m[2]), int(m[3])))),
        (r"mu", lambda m: TransmissionAngle()),
        (r"swing_(\d+)", lambda m: Swing(int(m[1]))),
        (f"A_{_PLAIN}_zero", lambda m: StrokeEvent(m[1], "A")),
        (f"V_{_PLAIN}_max", lambda m: StrokeEvent(m[1], "V")),
        (r"I(\d)(\d)", lambda m: Centre((int(m[1]), int(m[2])))),
        (r"I(\d+),(\d+)", lambda m: Centre((int(m[1]), int(m[2])))),
        (r"omega(\d+)", lambda m: AngularVelocity(int(m[1]))),
        (r"alpha(\d+)", lambda m: AngularAcceleration(int(m[1]))),
        (f"A_cor_{_POINT}", lambda m: Coriolis(m[1])),
        (f"([VA])_slide_{_POINT}", lambda m: Sliding(m[1], m[2])),
        (f"A([nt])_{_POINT}/{_POINT}", lambda m: AccelerationPart(m[1], m[2], m[3])),
        (f"A([nt])_{_POINT}", lambda m: AccelerationPart(m[1], m[2])),
        (f"([VA])_{_POINT}/{_POINT}", lambda m: Relative(m[1], m[2], m[3])),
        (f"V_{_POINT}", lambda m: Velocity(m[1])),
        (f"A_{_POINT}", lambda m: Acceleration(m[1])),
        (r"range_(\w+)", lambda m: LengthRange(m[1])),
        (r"dof", lambda m: Mobility()),
        (r"grashof", lambda m: GrashofClass()),
        (r"time_ratio", lambda m: TimeRatio()),
        (r"stroke", lambda m: Stroke()),
        (r"n_centres", lambda m: CentreCount()),
        (r"([FT])_(\d)(\d)", lambda m: JointForce(int(m[2]), int(m[3]), m[1])),
        (r"T(\d+)", lambda m: DrivingTorque(int(m[1]))),
        ("|".join(EFFORTS), lambda m: Effort(m[0])),
    ))


def parse_ask(name: str) -> Ask:
    """Read one results.json name into its :class:`Ask` ("centres" is every centre: see
    :func:`ask_names`).

    Raises
    ------
    TarsimError
        If the name is none of the grammar's.

    Examples
    --------
    >>> parse_ask("A_B4"), parse_ask("I13").pair, parse_ask("V_B/A").of
    (Acceleration(point='B4'), (1, 3), 'A')
    """
    for pattern, make in _GRAMMAR:
        m = pattern.match(name)
        if m:
            return make(m)
    raise TarsimError(f"'{name}' is not the name of a quantity")


def ask_names(mech: Mechanism) -> set[str]:
    """Every name an exercise on ``mech`` may ask by the grammar of points and links.

    Whether a method can answer it (a four-bar's Grashof class, a quick-return's
    time ratio) is the registry's to say, not the grammar's.
    """
    nums = sorted(mech.numbers)
    out = {"centres", CentreCount.word}
    out |= {Position(p).name for p in mech.point_names}
    out |= {Centre((a, b)).name for i, a in enumerate(nums) for b in nums[i + 1:]}
    out |= {f"{w}{n}" for n in nums if n != 1 for w in ("omega", "alpha")}
    moving = [p for p in mech.point_names if set(mech.links_at(p)) != {1}]
    out |= {f"V_{p}" for p in moving}
    slotted = mech.slotted
    coincident = {f"{s.point}{s.guide_link}" for s in slotted}
    carried = {f"{s.point}{c}" for s in slotted
               for c in set(mech.links_at(s.point)) | {t.link for t in mech.slides
                                                        if t.point == s.point} if c != 1}
    named = set(moving) | coincident | carried
    out |= {f"A_{p}" for p in named}
    out |= {f"{v}_{p}/{q}" for v in "VA" for p in named for q in named if p != q}
    out |= {f"A_cor_{s.point}" for s in slotted}
    out |= {f"A{part}_{p}" for p in named for part in "nt"}
    out |= {f"V_{p}/V_{q}" for p in moving for q in moving if p != q}
    out |= {f"omega{a}/omega{b}" for a in nums for b in nums if a != b and 1 not in (a, b)}
    out |= {f"ma_{n}" for n in nums if n not in (1, mech.drive.link)}
    out |= {f"Vmin_{k.number}" for k in mech.links if k.number != 1}
    out |= {LeastVelocity(k.number, (p, q)).name for k in mech.links if k.number != 1
            for p in k.names for q in k.names if p != q and "_" not in p + q}
    out |= {f"rub_{p}" for p in mech.point_names if len(mech.links_at(p)) == 2}
    out |= {f"dist_{p}_{Centre((a, b)).name}" for p in mech.point_names
            for i, a in enumerate(nums) for b in nums[i + 1:] if b < 10}
    out |= {f"A{part}_{p}/{q}" for k in mech.links if k.number != 1
            for p in k.names for q in k.names if p != q for part in "nt"}
    return out


def on_one_line(points) -> bool:
    """True if a link's points (name, local xy) are two or more on one straight line: a rod,
    with any point it carries on it, to rounding at the link's own size."""
    if len(points) < 2:
        return False
    (_, (x0, y0)), *rest = points
    far = max(rest, key=lambda p: math.hypot(p[1][0] - x0, p[1][1] - y0))[1]
    dx, dy = far[0] - x0, far[1] - y0
    size = math.hypot(dx, dy)
    # a point off the line by a few ulps of the link's size is on it, as drawn
    return size > 0.0 and all(abs((x - x0) * dy - (y - y0) * dx) <= 1e-12 * size * size
                              for _, (x, y) in rest)


def ordered(asks) -> list[Ask]:
    """The asks in a solution's order: the mechanism's first, then a position's by kind, each
    kind in the order the exercise gives them."""
    return sorted(asks, key=lambda a: (a.scope != "mechanism", a.order))
