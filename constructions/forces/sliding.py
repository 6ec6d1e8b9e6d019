"""How the joints of the group the force polygons draw slide and turn, as the velocity polygon
reads them, or rest.

Friction leans a slide's push against its sliding and sets a pin's friction couple against
its turning, so each needs the way its joint moves. A joint the velocity polygon reads
moving within its rounding of a zero (:func:`~.rounding.speed_rounding`) rests:
friction's direction is undefined there (it flips as the joint passes rest), so friction
takes no side, as at an extreme position or a dead centre, and the polygons say so. One
just past that rounding moves no known way and is refused in one line
(:func:`~.loads.near_rest`): the Newton–Euler reference reads its own rounding, and between
the two a joint could be moving to one and resting to the other.

A slotted lever reads its turning at the block's pin A near its pivot P and lays it off, by
proportion, to its ram's pin far out: the ram's readings carry that gain, |PQ|/|PA|, on
their rounding, which the polygon's conditioning does not show.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from .. import geometry as g
from ..errors import TarsimError
from ..loads import near_rest, near_rest_refusal
from ..narration import Number, Phrase, phrase
from ..record import Panel
from ..linkages.velocity_polygon import drawn_velocity_polygon
from .rounding import rate_roundings, speed_rounding

__all__ = ["Slide", "dyad_slides", "lever_gain", "lever_slides", "link_rates", "pin_rests",
           "pin_roundings", "say_resting", "unit_or_zero"]

Vec = tuple[float, float]


@dataclass(frozen=True)
class Slide:
    """How one slide of the group slides, as the velocity polygon reads it: ``key`` names it
    in the group's slip ("guide", "pin" or "block"), ``link`` the link that slides on link
    ``guide``, ``what`` (a phrase), ``velocity`` its velocity there (m/s) and ``still`` the
    rounding of a zero the polygon reads it to."""

    key: str
    link: int
    guide: int
    what: Phrase
    velocity: Vec
    still: float

    @property
    def joint(self) -> str:
        """Its force's name: F_15, of the guide on the slider."""
        return f"F_{self.guide}{self.link}"

    @property
    def direction(self) -> Vec:
        """Its unit velocity, or nothing where it rests: friction then takes no side."""
        return unit_or_zero(self.velocity, self.still)


def unit_or_zero(v: Vec, still: float) -> Vec:
    """``v`` made a unit vector, or nothing when it is no longer than ``still``, the
    rounding of a zero (a slide at rest: friction takes no side).

    >>> unit_or_zero((3.0, 4.0), 1e-9), unit_or_zero((3e-12, 4e-12), 1e-9)
    ((0.6, 0.8), (0.0, 0.0))
    """
    n = math.hypot(*v)
    return (v[0] / n, v[1] / n) if n > still else (0.0, 0.0)


def lever_gain(at: dict[str, Vec], pivot: str, pin: str, point: str) -> float:
    """How many times a slotted lever carries the rounding of its turning, read at the
    block's ``pin`` near its ``pivot``, out to ``point`` of the lever or its ram: |PX|/|PA|,
    and 1 for a point no farther out."""
    return max(1.0, math.dist(at[pivot], at[point]) / math.dist(at[pivot], at[pin]))


def dyad_slides(work, block: int, point: str) -> list[Slide]:
    """A slider-crank's block on its frame guide, at its pin ``point``.

    Raises
    ------
    TarsimError
        If it slides too near rest to tell which way (:func:`~.loads.near_rest`).
    """
    vp = drawn_velocity_polygon(work)
    return _sure(work, [Slide("guide", block, 1, phrase("force.the_guide"), vp.vector(point),
                              speed_rounding(work))])


def lever_slides(work, at: dict[str, Vec], *, lever: int, block: int, pivot: str, pin: str,
                 ram: int | None = None, ram_pin: str | None = None) -> list[Slide]:
    """A slotted lever's block along the slot and, with a ram, the ram on its frame guide
    and its pin along the slot: each along the slot less the velocity of the lever's own
    point under it (ω × PX), the ram's read to the lever's gain on the rounding.

    Raises
    ------
    TarsimError
        If one slides too near rest to tell which way (:func:`~.loads.near_rest`).
    """
    vp = drawn_velocity_polygon(work)
    w = vp.rates.get(lever, 0.0)

    def on_lever(point: str) -> Vec:
        v = vp.vector(point)
        x, y = at[point][0] - at[pivot][0], at[point][1] - at[pivot][1]
        return (v[0] + w * y, v[1] - w * x)
    slot = phrase("force.the_slot", link=lever)
    out = [Slide("block", block, lever, slot, on_lever(pin), speed_rounding(work))]
    if ram is not None:
        still = speed_rounding(work, lever_gain(at, pivot, pin, ram_pin))
        out += [Slide("guide", ram, 1, phrase("force.the_frame_guide"), vp.vector(ram_pin),
                      still),
                Slide("pin", ram, lever, slot, on_lever(ram_pin), still)]
    return _sure(work, out)


def _sure(work, slides: list[Slide]) -> list[Slide]:
    """``slides``, each resting or sliding past doubt.

    Raises
    ------
    TarsimError
        If one slides too near rest to tell which way (:func:`~.loads.near_rest`).
    """
    fastest = drawn_velocity_polygon(work).extent() or 1.0
    for s in slides:
        speed = math.hypot(*s.velocity)
        if near_rest(speed, s.still):
            raise TarsimError(near_rest_refusal(
                work.mechanism, f"link {s.link} slides on link {s.guide}", speed / fastest))
    return slides


def link_rates(work) -> dict[int, float]:
    """Each link's ω as the velocity polygon reads it, the input's given and the frame's 0."""
    rates = dict(drawn_velocity_polygon(work).rates)
    rates[work.mechanism.drive.link], rates[1] = work.mechanism.drive.omega, 0.0
    return rates


def pin_roundings(work, lever: tuple[int, float] | None = None) -> dict[int, float]:
    """How fast each link may turn and still rest (:func:`~.rounding.rate_roundings`),
    a slotted ``lever``'s (its link and |PA|) read at the block's pin, however far the
    polygon lays it off.

    Raises
    ------
    TarsimError
        If a pin turns too near rest to tell which way (:func:`~.loads.near_rest`).
    """
    still = rate_roundings(work, dict([lever]) if lever else None)
    rates = link_rates(work)
    top = max(abs(w) for w in rates.values()) or 1.0
    for point, by, on in work.mechanism.pin_pairs:
        turning = abs(rates.get(on, 0.0) - rates.get(by, 0.0))
        if near_rest(turning, still.get(on, 0.0) + still.get(by, 0.0)):
            raise TarsimError(near_rest_refusal(work.mechanism, f"link {on} turns on link "
                                                f"{by} at the pin {point}", turning / top,
                                                of="rate"))
    return still


def pin_rests(rates: dict[int, float], still: dict[int, float], by: int, on: int) -> bool:
    """Whether link ``on`` turns on link ``by`` no faster than their rates round at."""
    turning = rates.get(on, 0.0) - rates.get(by, 0.0)
    return abs(turning) <= still.get(on, 0.0) + still.get(by, 0.0)


def say_resting(work, slides: list[Slide], still: dict[int, float] | None) -> None:
    """Say, among the force polygons, each joint friction acts at that rests: each of
    ``slides`` that rests, and with friction circles each pin whose links turn within
    ``still`` of each other. Friction takes no side there; the Newton–Euler reference
    takes the joint at rest to its own rounding."""
    vp = drawn_velocity_polygon(work)
    fastest = vp.extent() or 1.0
    said = [phrase("force.resting", what=s.what, link=s.link, name=s.joint,
                   share=Number(math.hypot(*s.velocity) / fastest, ".2g"),
                   still=Number(s.still / fastest, ".2g"))
            for s in slides if s.direction == (0.0, 0.0)]
    if still is not None:
        rates = link_rates(work)
        top = max(abs(w) for w in rates.values()) or 1.0
        for point, by, on in work.mechanism.pin_pairs:
            if pin_rests(rates, still, by, on):
                said.append(phrase(
                    "force.resting_pin", pin=point, on=on, by=by,
                    share=Number(abs(rates.get(on, 0.0) - rates.get(by, 0.0)) / top, ".2g"),
                    still=Number((still.get(on, 0.0) + still.get(by, 0.0)) / top, ".2g")))
    if not said:
        return
    c = work.assembly
    at_pole = c.give("force:rest:at", g.Point(0.0, 0.0), label="", panel=Panel.FORCE)
    for n, what in enumerate(said):
        c.draw(f"force:say:rest{n}", "mark", at_pole, panel=Panel.FORCE, phrase=what)
