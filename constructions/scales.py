"""The scales of a solution, chosen once: the space diagram's, and the velocities' drawn on it.

A figure states each scale as the course does, "1 cm = N unit" with N = 1, 2 or
5 × 10^k (:func:`nice`, the one rule for such numbers), or as the exercise
states it. The space scale fits the mechanism, its cams and faces included, in
the page's drawing area; a velocity drawn on the space diagram is laid off at the
scale that draws every vector a method may draw there big enough to read: the input
at least 20 mm, the shortest at least 8 mm, the longest within half the diagram
(:func:`readable_per_cm`). Both are fixed here,
before anything is drawn, so the construction and its figure agree and nothing
is laid out twice. (A polygon's paper scale is its panel's own: a polygon is
drawn at any construction scale and then fitted to its panel.)
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

from .linkages.assembly_record import Assembly
from .errors import TarsimError

__all__ = ["nice", "nice_per_cm", "Scales", "Stated", "choose_scales", "space_per_cm",
           "velocity_per_cm", "readable_per_cm", "SHORTEST_MM", "READABLE_MM",
           "drawing_extent", "face_ends", "ROOM", "FACE_REACH"]

ROOM = (150.0, 130.0)
"""The largest drawing area of the space diagram on A4, paper mm wide × high (a larger sheet
scales it: ``graphics.paper.room``)."""

FACE_REACH = 0.8
"""A flat face is drawn this many of its circle's radii either side of the contact point."""

_VECTOR_MM = (20.0, 35.0)   # the input's speed is drawn this long on the space diagram

SHORTEST_MM = 8.0
"""The shortest vector a velocity construction draws, on paper (mm), where it can."""

LONGEST_MM = (75.0, 0.5)
"""The longest vector on the space diagram: this many mm, or this part of the diagram's
larger side, whichever is longer."""

READABLE_MM = 30.0
"""The longest vector a velocity construction draws is at least this long on paper (mm),
where it can be: a construction of components whose longest arrow is 2 cm fits in one,
its perpendiculars and tips crowded together. A nice scale puts it below 75 mm
(:data:`LONGEST_MM`), as 1-2-5 steps are at most 2.5 apart."""


def nice(raw: float, *, up: bool = True) -> float:
    """The nearest 1, 2 or 5 × 10^k at or above ``raw`` (``up``), or at or below it.

    A value within a billionth of a nice one is taken as that one.

    Examples
    --------
    >>> nice(2.6), nice(0.037), nice(4.0, up=False), nice(0.037, up=False)
    (5.0, 0.05, 2.0, 0.02)
    """
    if not (math.isfinite(raw) and raw > 0.0):
        raise ValueError(f"a nice number needs a positive raw value, got {raw}")
    k = math.floor(math.log10(raw))
    ladder = [b * 10.0 ** e for e in (k - 1, k, k + 1) for b in (1.0, 2.0, 5.0)]
    if up:
        value = min(v for v in ladder if v >= raw * (1 - 1e-9))
    else:
        value = max(v for v in ladder if v <= raw * (1 + 1e-9))
    return float(f"{value:.12g}")


def nice_per_cm(extent: float, room_mm: float) -> float:
    """Return the smallest nice value N (1, 2, 5 × 10^k) with ``extent`` / N cm ≤ ``room_mm``.

    ``extent`` is in the unit the scale will be stated in; the result is how much
    of that unit one centimetre of paper stands for.

    Examples
    --------
    >>> nice_per_cm(400.0, 150.0)
    50.0
    >>> nice_per_cm(0.7, 100.0)
    0.1
    """
    if extent <= 0 or room_mm <= 0:
        raise ValueError("a scale needs a positive extent and room")
    return nice(extent * 10.0 / room_mm)


class Stated(float):
    """A scale as the exercise states it: its value (file units per paper cm), with the
    statement itself, which every figure sets as given ("3 cm = 18 cm/s", not the "1 cm =
    60 mm/s" it comes to). Its sides are ``paper`` (as written, "3 cm"; ``paper_cm`` in
    centimetres) and ``amount`` in ``unit``.

    >>> s = Stated(60.0, paper="3 cm", paper_cm=3.0, amount=18.0, unit="cm/s")
    >>> s * 2, s.words
    (120.0, '3 cm = 18 cm/s')
    """

    paper: str
    paper_cm: float
    amount: float
    unit: str

    def __new__(cls, per_cm: float, *, paper: str, paper_cm: float, amount: float,
                unit: str) -> Stated:
        """A float, the scale's value, that keeps the statement it came from."""
        scale = super().__new__(cls, per_cm)
        scale.paper, scale.paper_cm, scale.amount, scale.unit = paper, paper_cm, amount, unit
        return scale

    def __reduce__(self):
        return _stated, (float(self), self.paper, self.paper_cm, self.amount, self.unit)

    @property
    def words(self) -> str:
        """The statement as the exercise words it: "3 cm = 18 cm/s"."""
        return f"{self.paper} = {self.amount:g} {self.unit}"


def _stated(per_cm: float, paper: str, paper_cm: float, amount: float, unit: str) -> Stated:
    return Stated(per_cm, paper=paper, paper_cm=paper_cm, amount=amount, unit=unit)


@dataclass(frozen=True)
class Scales:
    """The scales of one position's figures, in the file's units per paper centimetre.

    ``space`` is the space diagram's ("1 cm = 40 mm"); ``velocity`` the vectors'
    drawn on it ("1 cm = 20 mm/s"), and ``vector`` the same as the construction
    lays them off, drawing metres per m/s. ``velocity_polygon`` and
    ``acceleration_polygon`` are the polygon panels' scales when the exercise
    states them, else None (a panel then fits its polygon).
    """

    space: float
    velocity: float | None = None
    velocity_polygon: float | None = None
    acceleration_polygon: float | None = None

    @property
    def vector(self) -> float | None:
        """Drawing metres per m/s of a velocity drawn on the space diagram: the space scale
        over the velocity scale (both per paper cm, in the same unit), in seconds."""
        return None if self.velocity is None else self.space / self.velocity


def drawing_extent(asm: Assembly) -> tuple[float, float]:
    """Width and height (m) of what the kinematic diagram draws: the points, each cam and
    roller circle, and each flat face as far as it is drawn (:data:`FACE_REACH`)."""
    m = asm.mechanism
    pts = [asm.xy(n) for n in m.point_names]
    for joint, ref in asm.contacts.items():
        c = joint.contact
        for profile in (c.circle, c.face):
            if profile.is_circle:
                (x, y), r = asm.xy(profile.centre), profile.radius
                pts += [(x - r, y - r), (x + r, y + r)]
        if not c.face.is_circle:
            pts += list(face_ends(asm, joint, ref))
    xs, ys = [p[0] for p in pts], [p[1] for p in pts]
    return max(max(xs) - min(xs), 1e-9), max(max(ys) - min(ys), 1e-9)


def face_ends(asm: Assembly, joint, contact: str, margin: float = 0.0):
    """The two ends (m) a flat face is drawn between: :data:`FACE_REACH` radii either side of
    its contact point, and at least ``margin`` past its own point."""
    i = asm.mechanism.slides.index(joint)
    (fx, fy), (dx, dy) = asm.xy(joint.contact.face.through), asm.guide(i).direction
    n = math.hypot(dx, dy)
    dx, dy = dx / n, dy / n
    px, py = asm.output(contact).xy
    r = joint.contact.circle.radius
    t = (px - fx) * dx + (py - fy) * dy
    lo, hi = min(t - FACE_REACH * r, -margin), max(t + FACE_REACH * r, margin)
    return (fx + lo * dx, fy + lo * dy), (fx + hi * dx, fy + hi * dy)


def space_per_cm(asm: Assembly, room: tuple[float, float] = ROOM) -> float:
    """The space scale (file units per paper cm): the exercise's, or the nice one that fits
    the drawing in ``room`` (paper mm, wide × high; :data:`ROOM` on A4)."""
    m = asm.mechanism
    if m.scale:
        return m.scale
    w, h = (e / m.units.metres for e in drawing_extent(asm))
    return max(nice(w * 10.0 / room[0]), nice(h * 10.0 / room[1]))


def velocity_per_cm(speed: float) -> float:
    """The nice N of "1 cm = N unit/s" that draws ``speed`` (unit/s) 20–35 mm long, or
    else nearest that by ratio (27 mm when several do).

    Raises
    ------
    TarsimError
        If ``speed`` is not positive and finite.

    Examples
    --------
    >>> velocity_per_cm(1000.0)
    500.0
    """
    if not (math.isfinite(speed) and speed > 0.0):
        raise TarsimError(f"a velocity scale needs a positive speed, got {speed}")
    k = math.floor(math.log10(speed / 3.0))
    best = None
    for e in range(k - 1, k + 2):
        for base in (1.0, 2.0, 5.0):
            n = float(f"{base * 10.0 ** e:.12g}")
            mm = 10.0 * speed / n
            lo, hi = _VECTOR_MM
            miss = 0.0 if lo <= mm <= hi else abs(math.log(mm / (lo if mm < lo else hi)))
            key = (miss, abs(math.log(mm / 27.0)))
            if best is None or key < best[0]:
                best = (key, n)
    return best[1]


def readable_per_cm(speed: float, others: Sequence[float], longest: float) -> float:
    """The nice N of "1 cm = N unit/s" that draws a construction big enough to read.

    ``speed`` is the input's (unit/s), drawn at least 20 mm long; ``others`` are the
    magnitudes of every other vector a method may draw, the shortest of which is
    drawn at least :data:`SHORTEST_MM` long and the longest at least
    :data:`READABLE_MM`; none may pass ``longest`` (mm). The
    largest N that does all this is taken, so the construction is no bigger than it
    need be. Where a vector is too short beside the longest for both, the longest is
    drawn ``longest`` mm long; with no other vector, this is :func:`velocity_per_cm`.

    >>> readable_per_cm(360.0, [360.0, 92.0], 80.0)        # 36 mm, the shortest 9.2 mm
    100.0
    >>> readable_per_cm(1000.0, [1000.0, 800.0], 80.0)     # 50 mm: at 500, only 20 mm
    200.0
    >>> readable_per_cm(360.0, [360.0, 10.0], 60.0)        # 10 mm/s cannot be 8 mm here
    100.0
    """
    others = [v for v in others if v > 1e-9 * speed]
    if not others:
        return velocity_per_cm(speed)
    high = max(max(others), speed)
    readable = nice(10.0 * min(min(others) / SHORTEST_MM, speed / _VECTOR_MM[0],
                               high / READABLE_MM), up=False)
    roomy = nice(10.0 * high / longest)
    return readable if readable >= roomy else roomy


def choose_scales(asm: Assembly, *, velocity: float | None = None,
                  velocity_polygon: float | None = None,
                  acceleration_polygon: float | None = None,
                  speeds: Sequence[float] = (), room: tuple[float, float] = ROOM) -> Scales:
    """The scales of a position of ``asm``: those the exercise states, the rest chosen.

    ``velocity`` is a stated velocity scale for the vectors drawn on the space
    diagram (file units per second per paper cm); without one, and with the input
    moving, a nice one is chosen that draws the input and every one of ``speeds``
    (the magnitudes, unit/s, of the vectors the methods may draw there) readably
    (:func:`readable_per_cm`). The stated velocity scale also states the velocity
    polygon's, as the exercise words it once for both. ``room`` is the space diagram's
    drawing area (:func:`space_per_cm`).
    """
    speed = asm.mechanism.input_speed / asm.mechanism.units.metres
    space = space_per_cm(asm, room)
    if velocity is None and speed > 0.0:
        extent = max(drawing_extent(asm)) / asm.mechanism.units.metres * 10.0 / space
        velocity = readable_per_cm(speed, speeds, max(LONGEST_MM[0], LONGEST_MM[1] * extent))
    return Scales(space, velocity, velocity_polygon, acceleration_polygon)
