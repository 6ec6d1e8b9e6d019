"""The check of every answer: the constructed value beside the analytic one, and how far apart.

A construction's first-order error is about eps over its conditioning, so an
answer passes when its relative error is within :func:`tolerance` of the
conditioning its construction reports. How the error is measured depends on
what the quantity is, so :func:`check` keeps one rule per kind of ask:

* a rate (ω, α) and a vector (V, A, a relative vector, Coriolis) relative to its
  reference, or to the input's own rate where the reference is near zero (a point
  at rest at a dead centre still has a scale);
* an instant centre by distance relative to the mechanism's size, a centre at
  infinity by the angle of its direction;
* the mechanism's DOF and Grashof class exactly, the length ranges relative to
  the longest link, the time ratio and stroke relative to themselves.

A rate or vector within ``NOISE`` of zero beside its scale is reported as zero,
after its error is measured.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field, replace
from typing import Any

from . import asks as A
from .errors import IllConditioned, TarsimError
from .model import Mechanism
from .narration import Phrase
from .record import Panel, Ref
from .reference.centres import centre_error

__all__ = ["Quantity", "Expected", "Answer", "FigureSpec", "FIGURE_KINDS", "WHOLE", "tolerance",
           "check", "vector_value", "grashof_value", "time_ratio_value", "quiet", "NOISE", "EPS",
           "CEILING"]

EPS = 2.220446049250313e-16
"""The unit roundoff of a float."""

NOISE = 1e-12
"""A rate below this fraction of the input's is rounding, not motion: it is said as zero."""

CEILING = 1e-5
"""The loosest a check may be, as a fraction of the quantity's scale. A construction that
meets the independent reference this closely vouches for the figures printed (a drawing's
table gives four; steps.md six, the last of them as sure as this), however ill-conditioned
it is; one that misses by more where its conditioning would allow it vouches for nothing,
and is refused: a tolerance as wide as the quantity never fails."""


@dataclass(frozen=True)
class Quantity:
    """One asked quantity: by construction, by the analytic solver, and how far apart.

    ``value`` and ``reference`` are in results.json's shape (SI units).
    ``alternatives`` are the same quantity found by other methods, by method.
    """

    name: str
    value: dict[str, Any]
    reference: dict[str, Any]
    rel_error: float
    tolerance: float
    conditioning: float
    method: str
    alternatives: dict[str, Quantity] = field(default_factory=dict)
    said: Phrase | None = None
    """The method in words any language can say, where ``method`` is more than a name."""

    @property
    def passed(self) -> bool:
        """Whether the construction agrees with the reference within its tolerance."""
        return self.rel_error <= self.tolerance and all(
            q.passed for q in self.alternatives.values())

    def with_alternatives(self, others: list[Quantity]) -> Quantity:
        """The same answer, with the quantity by other methods beside it."""
        return replace(self, alternatives={**self.alternatives, **{q.method: q for q in others}})

    def in_file_axes(self, mech: Mechanism) -> Quantity:
        """The same answer with its points (a centre, a foot) in the axes of the file
        ``mech`` was read from: a solution works about the frame's first point
        (:meth:`~tarsim.constructions.model.Mechanism.about_its_frame`)."""
        if mech.origin == (0.0, 0.0):
            return self
        return replace(self, value=_in_file_axes(self.value, mech),
                       reference=_in_file_axes(self.reference, mech),
                       alternatives={m: q.in_file_axes(mech)
                                     for m, q in self.alternatives.items()})


def _in_file_axes(value: dict[str, Any], mech: Mechanism) -> dict[str, Any]:
    xy = value.get("point")
    if not isinstance(xy, (list, tuple)):          # a stroke names its point
        return value
    return {**value, "point": list(mech.in_file_axes(xy))}


FIGURE_KINDS: dict[str, str] = {
    "scene": "the space diagram with the answer's construction on it",
    "positions": "the space diagram with the compass work that placed the points",
    "circle diagram": "every instant centre on Kennedy's circle diagram",
    "polygons": "the worked page: the space diagram, the velocity and acceleration "
                "polygons and the results table",
    "limits": "the limit positions, the time ratio and stroke under them",
    "mechanism": "the mechanism alone, where nothing is asked at a position",
    "loads": "the space diagram with the loads on each link",
    "forces": "the force polygons",
    "bodies": "the free-body diagrams",
}
"""Each kind of figure an answer may be drawn in (:attr:`FigureSpec.kind`), and what it
shows. Graphics registers a drawing for each (:mod:`tarsim.graphics.figure_kinds`), and
:class:`FigureSpec`'s docstring lists them from here."""


@dataclass(frozen=True)
class FigureSpec:
    """The figure an answer is drawn in: its file stem, heading, caption, and kind of figure.

    ``kind`` is one of :data:`FIGURE_KINDS`:

    {kinds}

    The figure's title is the mechanism's name and the ``caption``. ``velocity_scale``
    is the scale (drawing metres per m/s) of the velocities a scene draws, which its
    caption states; ``notes`` says the position's notes (an ill-conditioned centre)
    stand under it.
    """

    stem: str
    heading: Phrase | str
    """What steps.md heads the figure's part with: a catalogue phrase ("V_B by radius
    rotation", said in each language), or words each catalogue says whole."""
    caption: Phrase | str = ""
    kind: str = "scene"
    velocity_scale: float | None = None
    notes: bool = False
    velocity_stated: float | None = None
    """The velocity scale the exercise states, per paper cm, worded as it words it."""


if FigureSpec.__doc__:                  # (none under python -OO)
    FigureSpec.__doc__ = FigureSpec.__doc__.replace("{kinds}", "\n    ".join(
        f"* {kind!r}: {shows}." for kind, shows in FIGURE_KINDS.items()))

WHOLE = FigureSpec("mechanism", "The mechanism", kind="mechanism")
"""The figure of a mechanism of which nothing is asked at a position: itself."""


@dataclass(frozen=True)
class Answer:
    """What a method drew for one ask: the value read off the drawing, and where it stands.

    ``value`` is in results.json's shape; ``method`` is how results.json names the
    method. ``refs`` are the steps the answer is (the slice of each of its
    ``figures`` is cut from them) and ``arrows`` the vectors drawn beside it that
    belong to its figure; ``panel`` is the panel it is read in. ``found`` is the
    geometric answer itself where the check compares geometry (a centre, possibly at infinity), and
    ``holds_always`` marks a joint's own centre, true at every instant. ``said`` is the
    method as a phrase, where ``method`` is English made from one (Grashof's sums).
    """

    ask: A.Ask
    value: dict[str, Any]
    conditioning: float
    method: str
    refs: tuple[Ref, ...] = ()
    figures: tuple[FigureSpec, ...] = ()
    panel: Panel = Panel.SPACE
    arrows: tuple[Ref, ...] = ()
    found: Any = None
    holds_always: bool = False
    said: Phrase | None = None


@dataclass(frozen=True)
class Expected:
    """An analytic reference in results.json's shape, with the rounding it carries itself
    (large for a centre where two links turn at nearly the same rate) and, where the check
    compares geometry, the reference's own object (an analytic centre)."""

    value: dict[str, Any]
    rounding: float = 0.0
    exact: Any = None


def tolerance(conditioning: float) -> float:
    """Return the relative tolerance of a result with this compounded conditioning.

    A drafting act's first-order error is about ``eps / conditioning`` relative to
    the figure; 64 ulps cover the few acts chained before the last, and 1e-9 is the
    floor below which nothing is asked.

    Examples
    --------
    >>> tolerance(1.0)
    1e-09
    >>> tolerance(1e-9) == 64 * EPS / 1e-9
    True
    >>> tolerance(0.0)
    inf
    """
    if conditioning <= 0.0:
        return math.inf
    return max(1e-9, 64 * EPS / conditioning)


def vector_value(x: float, y: float) -> dict[str, Any]:
    """A vector in results.json's shape: its magnitude and its components."""
    return {"value": math.hypot(x, y), "vector": [x + 0.0, y + 0.0]}


def grashof_value(kind: str, lengths) -> dict[str, Any]:
    """A four-bar's class in results.json's shape, with the two sums Grashof's rule compares."""
    s, p, q, l_ = sorted(lengths)
    return {"class": kind, "s_plus_l": s + l_, "p_plus_q": p + q}


def time_ratio_value(slow: float, quick: float) -> dict[str, Any]:
    """A time ratio in results.json's shape: slow over quick, and each crank angle (rad in)."""
    return {"value": slow / quick, "slow_deg": math.degrees(slow),
            "quick_deg": math.degrees(quick)}


def quiet(x: float, scale: float) -> float:
    """``x``, or 0 when it is rounding noise beside ``scale`` (what it is measured against).

    >>> quiet(-2.2e-15, 1000.0), quiet(3.5, 1000.0)
    (0.0, 3.5)
    """
    return 0.0 if abs(x) <= NOISE * scale else x + 0.0



def _rate(value: dict, ref: dict, scale: float) -> tuple[dict, dict, float]:
    v, r = value["value"], ref["value"]
    err = abs(v - r) / max(abs(r), scale, 1e-300)
    return {"value": quiet(v, scale)}, {"value": quiet(r, scale)}, err


def _vector(value: dict, ref: dict, scale: float) -> tuple[dict, dict, float]:
    (vx, vy), (rx, ry) = value["vector"], ref["vector"]
    err = math.hypot(vx - rx, vy - ry) / max(math.hypot(rx, ry), scale, 1e-300)
    if math.hypot(vx, vy) <= NOISE * scale:
        vx = vy = 0.0
    if math.hypot(rx, ry) <= NOISE * scale:
        rx = ry = 0.0
    return vector_value(vx, vy), vector_value(rx, ry), err


def _relative(value: dict, ref: dict, scale: float) -> tuple[dict, dict, float]:
    """A positive number relative to itself: the time ratio, the stroke."""
    return value, ref, abs(value["value"] - ref["value"]) / max(abs(ref["value"]), 1e-300)


def _angles(value: dict, ref: dict, scale: float) -> tuple[dict, dict, float]:
    """Angles (a lever's swing, its inclination), each beside half a turn."""
    return value, ref, max(abs(value[k] - ref[k]) for k in ref) / math.pi


def _exact(value: dict, ref: dict, scale: float) -> tuple[dict, dict, float]:
    """Integers that must be the same: the mobility, and at this position where it differs."""
    def here(v: dict) -> int:
        return v.get("here", v["value"])
    return value, ref, float(abs(value["value"] - ref["value"]) + abs(here(value) - here(ref)))


def _point(value: dict, ref: dict, scale: float) -> tuple[dict, dict, float]:
    """A point's place, its miss relative to the mechanism's size (``scale``)."""
    return value, ref, math.dist(value["point"], ref["point"]) / max(scale, 1e-300)


def _point_and_speed(value: dict, ref: dict, scale: float) -> tuple[dict, dict, float]:
    """A point and its speed: the worse of the point's miss beside the mechanism's size
    (``scale``) and the speed's beside the reference's own ``floor`` (the link's |ω| times
    that size: a least velocity may be nil, at a crank's pivot)."""
    miss = max(math.dist(value["point"], ref["point"]),
               abs(value.get("along", 0.0) - ref.get("along", 0.0))) / max(scale, 1e-300)
    slow = abs(value["value"] - ref["value"]) / max(ref["value"], ref["floor"], 1e-300)
    shown = {k: ref[k] for k in ("point", "value", "from", "along") if k in ref}
    return value, shown, max(miss, slow)


def _counts(value: dict, ref: dict, scale: float) -> tuple[dict, dict, float]:
    """Counts that must be the same, every one of them."""
    return value, ref, float(sum(abs(value[k] - ref[k]) for k in ref))


def _same_class(value: dict, ref: dict, scale: float) -> tuple[dict, dict, float]:
    """The Grashof class. A change-point linkage turns like a class it borders, so the
    turning test may name any; it is judged by the inequality alone."""
    same = value["class"] == ref["class"] or value["class"] == "change-point"
    return value, ref, 0.0 if same else 1.0


def _interval(value: dict, ref: dict, scale: float) -> tuple[dict, dict, float]:
    """A range of lengths, its ends relative to the longest link (``scale``)."""
    lo, hi, rlo, rhi = value["low"], value["high"], ref["low"], ref["high"]
    if value["class"] == "change-point" and lo == hi:
        # A change point is where two classes meet: the turning test counts it with the class
        # it turns like, so it stands at one end of that class's range (both, for a
        # parallelogram, whose neighbours on either side turn otherwise).
        err = min(abs(lo - rlo), abs(lo - (math.inf if rhi is None else rhi))) / scale
        return value, ref, err
    far = 0.0 if hi is None and rhi is None else abs((hi or math.inf) - (rhi or math.inf))
    err = max(abs(lo - rlo), far) / scale
    return value, ref, err if math.isfinite(err) else 1.0


def _stroke_event(value: dict, ref: dict, scale: float) -> tuple[dict, dict, float]:
    """A zero acceleration's angles (degrees) beside half a turn; a greatest speed relative
    to itself, and where it is beside half a turn."""
    if "zeros" in ref:
        if len(value["zeros"]) != len(ref["zeros"]):
            return value, ref, 1.0
        return value, ref, max(abs(v - r) for v, r in zip(value["zeros"], ref["zeros"])) / 180
    return value, ref, max(abs(value["value"] - ref["value"]) / max(ref["value"], 1e-300),
                           abs(value["angle"] - ref["angle"]) / 180)


_RULES: dict[type, Callable[[dict, dict, float], tuple[dict, dict, float]]] = {
    A.Position: _point, A.CentreCount: _counts, A.Ratio: _rate, A.MechanicalAdvantage: _rate,
    A.Distance: _rate, A.TransmissionAngle: _rate, A.LeastVelocity: _point_and_speed,
    A.Rubbing: _rate, A.Equivalent: _rate,
    A.AngularVelocity: _rate, A.AngularAcceleration: _rate,
    A.Velocity: _vector, A.Acceleration: _vector, A.Relative: _vector, A.Coriolis: _vector,
    A.Sliding: _vector, A.AccelerationPart: _vector,
    A.TimeRatio: _relative, A.Stroke: _relative, A.Swing: _angles, A.Mobility: _exact,
    A.StrokeEvent: _stroke_event,
    A.GrashofClass: _same_class, A.LengthRange: _interval,
    A.JointForce: lambda v, r, scale: (_vector if "vector" in r else _rate)(v, r, scale),
    A.DrivingTorque: _rate,
    A.Effort: _rate,
}


_EXACT = {A.Mobility: 0.0, A.GrashofClass: 0.0, A.LengthRange: 1e-9, A.CentreCount: 0.0}
"""Tolerances of answers that are counted or found at breakpoints, not drawn."""


def check(answer: Answer, expected: Expected, *, scale: float) -> Quantity:
    """Put a constructed answer beside its analytic ``expected`` one, by the rule for its ask.

    ``scale`` is what an error is relative to where the reference is near zero
    (the input's rate, speed or acceleration; the mechanism's size for a centre;
    the longest link for a range).

    Raises
    ------
    TarsimError
        If the reference is undefined for an answer that needs one.
    """
    ask = answer.ask
    if isinstance(ask, A.Centre):
        return _check_centre(answer, expected, scale)
    rule = _RULES[type(ask)]
    shown, ref, err = rule(answer.value, expected.value, scale)
    tol = _vouched(answer, err, _EXACT.get(type(ask), tolerance(answer.conditioning)))
    if rule in (_rate, _vector) or type(ask) is A.JointForce:
        shown, ref = _resolved(shown, ref, tol * scale)
    return Quantity(ask.name, shown, ref, err, tol, answer.conditioning, answer.method,
                    said=answer.said)


def _resolved(value: dict[str, Any], ref: dict[str, Any], least: float
              ) -> tuple[dict[str, Any], dict[str, Any]]:
    """A rate or a vector and its reference as the check can vouch for them.

    Beside its scale, the check allows an error of ``least`` (its tolerance at that scale).
    A quantity no larger than that could be anything down to 0 by that check, which could
    not fail beside the quantity's own size; it stands only if it meets its reference to
    :data:`CEILING` of itself, and is otherwise said as 0 (a dead centre's V_B that the
    drawing gives as 3e−8 mm/s of the crank pin's 3750).

    >>> _resolved({"value": 3e-12}, {"value": 1e-12}, 1e-9)
    ({'value': 0.0}, {'value': 0.0})
    >>> _resolved({"value": 2.5e-10}, {"value": 2.5e-10}, 1e-9)
    ({'value': 2.5e-10}, {'value': 2.5e-10})
    """
    def size(v: dict[str, Any]) -> float:
        return math.hypot(*v["vector"]) if "vector" in v else abs(v["value"])

    if size(value) > least or size(ref) > least:
        return value, ref
    miss = (math.dist(value["vector"], ref["vector"]) if "vector" in ref
            else abs(value["value"] - ref["value"]))
    if miss <= CEILING * size(ref):
        return value, ref

    def nil(v: dict[str, Any]) -> dict[str, Any]:
        return vector_value(0.0, 0.0) if "vector" in v else {**v, "value": 0.0}
    return nil(value), nil(ref)


def _vouched(answer: Answer, err: float, own: float, rounding: float = 0.0) -> float:
    """The check's tolerance: the construction's ``own``, held to :data:`CEILING`, and the
    reference's ``rounding`` (a centre's, where two links turn at nearly one rate).

    Raises
    ------
    IllConditioned
        If the answer misses the reference by more than the ceiling but within what its
        conditioning allows (the construction cannot be vouched for), or the reference's
        rounding is as wide as the quantity (no check could fail).
    """
    def refused(why: str, *, by_reference: bool = False) -> IllConditioned:
        return IllConditioned(f"{answer.ask.name} by {answer.method} {why}", name=answer.ask.name,
                              method=answer.method, conditioning=answer.conditioning, miss=err,
                              by_reference=by_reference)

    if own > CEILING and CEILING < err <= own + rounding:
        raise refused(f"misses the analytic value by {err:.1e} of its scale, within what its "
                      f"conditioning ({answer.conditioning:.1e}) allows")
    if rounding >= 1.0:
        raise refused("cannot be checked: the analytic reference is itself lost to rounding "
                      "here", by_reference=True)
    return min(own, CEILING) + rounding


def _check_centre(answer: Answer, expected: Expected, size: float) -> Quantity:
    name, found = answer.ask.name, answer.found
    if "undefined" in expected.value:
        if not (answer.holds_always or expected.value.get("anywhere")):
            raise TarsimError(f"{name} has no analytic reference here: "
                              f"{expected.value['undefined']}")
        # A joint's own centre holds at every instant, even one with no relative
        # motion (a block momentarily at rest in its slot), where any point would do; and
        # where two links move together, any point is their centre, the drawn one too.
        return Quantity(name, answer.value, expected.value, 0.0, tolerance(1.0),
                        answer.conditioning, answer.method)
    # A direction is judged by angle alone, so its tolerance does not grow with distance;
    # the reference's own rounding (large when ω_i ≈ ω_j) is added to the tolerance.
    own = tolerance(1.0 if found.is_at_infinity else answer.conditioning)
    err = centre_error(found, expected.exact, size)
    return Quantity(name, answer.value, expected.value, err,
                    _vouched(answer, err, own, expected.rounding), answer.conditioning,
                    answer.method)
