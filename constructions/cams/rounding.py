"""How far rounding can move each point a cam's construction draws.

A check whose tolerance is a fixed fraction of the drawing fails a large cam for nothing
and passes a small one whatever it draws. Here each act's rounding is bounded from the
sizes of the numbers it adds and subtracts and from its conditioning, and carried to the
acts drawn from it, to first order:

- a point given, rotated about another, or laid off along a line carries its inputs' error,
  a few roundings of the coordinates it adds, and, laid off a length L along a line, that
  line's error of direction times L;
- a line through two points d apart is off in direction by their errors over d, and in
  position by the cancellation of its offset c = pₓq_y − qₓp_y: a few roundings of |p||q|
  over d (a short line far from the origin is poorly placed);
- a parallel or perpendicular through a point keeps its line's error of direction;
- two lines meeting at an angle whose sine is s put their meet off by the sum of their
  errors there, over s.

A line's error at a point is its error at the point it was drawn through plus its error of
direction times the distance along it: a cam's construction uses each line near where it
was drawn, and the chain of acts adds the errors where the record's conditioning, made for
lines used anywhere in a drawing, multiplies them.

A station of the layout read against the closed form carries besides the rounding of its
cam angle times the slope of whichever law the closed form reads there: across a join, the
next segment's (:func:`join_bound`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from .. import geometry as g
from ..record import Construction, Ref
from .displacement import Displacement

__all__ = ["EPS", "Reach", "rounding", "lift_bounds", "join_bound"]

EPS = 2.220446049250313e-16
"""The unit roundoff of a float."""

_FEW = 4.0
"""Roundings an act makes of each number it adds or subtracts: two products and a sum."""


@dataclass(frozen=True)
class Reach:
    """How far rounding can have moved a drawn object (m): a point, a circle's centre, a
    line at the point it was drawn through (``at``); a line's error of direction (rad) and a
    circle's error of radius (m)."""

    error: float
    turn: float = 0.0
    at: tuple[float, float] = (0.0, 0.0)
    radius: float = 0.0

    def near(self, xy: tuple[float, float]) -> float:
        """A line's error at ``xy``: its error where it was drawn plus its turn along it."""
        return self.error + self.turn * math.dist(self.at, xy)


def _size(*xys: tuple[float, float]) -> float:
    return max((math.hypot(*xy) for xy in xys), default=0.0)


def rounding(c: Construction) -> dict[Ref, Reach]:
    """Bound the rounding of every step of ``c``, in record order (inputs first).

    An act this module does not model is bounded by the record's own conditioning, relative
    to the largest coordinate drawn.

    Examples
    --------
    >>> c = Construction()
    >>> _ = c.give("p", g.Point(1e3, 0.0), label="")
    >>> _ = c.give("q", g.Point(1e3, 1e-3), label="")
    >>> _ = c.draw("pq", "line_through", "p", "q")
    >>> r = rounding(c)["pq"]
    >>> 1e-7 < r.error < 1e-6       # four roundings of |p||q|/d = 1e3 × 1e3 / 1e-3
    True
    """
    out: dict[Ref, Reach] = {}
    whole = max((_extent(s.output) for s in c), default=0.0)
    for step in c:
        obj, ins = step.output, [out[r] for r in step.inputs]
        args = [c.output(r) for r in step.inputs]
        params = dict(step.params)
        rule = _RULES.get(step.verb)
        reach = rule(obj, args, ins, params) if rule else None
        if reach is None:
            # An act not modelled: the record's conditioning, relative to the drawing.
            cond = step.conditioning
            reach = Reach(_FEW * EPS * whole / cond if cond > 0 else math.inf, math.inf)
        out[step.id] = reach
    return out


def _extent(obj) -> float:
    if isinstance(obj, g.Point):
        return 0.0 if obj.is_at_infinity else obj.size()
    if isinstance(obj, g.Line):
        return 0.0 if obj.is_at_infinity else abs(obj.c)
    if isinstance(obj, g.Circle):
        return obj.centre.size() + obj.radius
    return 0.0


def _given(obj, args, ins, params) -> Reach | None:
    if isinstance(obj, g.Point) and not obj.is_at_infinity:
        return Reach(EPS * obj.size())
    if isinstance(obj, g.Line) and not obj.is_at_infinity:
        return Reach(EPS * abs(obj.c), EPS, obj.anchor())
    if isinstance(obj, g.Circle):
        return Reach(EPS * obj.centre.size(), radius=EPS * obj.radius)
    return None


def _line_through(obj, args, ins, params) -> Reach | None:
    p, q = args
    if p.is_at_infinity or q.is_at_infinity:
        return None
    d, big = math.dist(p.xy, q.xy), _size(p.xy, q.xy)
    return Reach(max(ins[0].error, ins[1].error) + _FEW * EPS * big * (big / d + 1),
                 (ins[0].error + ins[1].error + _FEW * EPS * big) / d, p.xy)


def _through_point(obj, args, ins, params) -> Reach | None:
    """A parallel or perpendicular through a point: its line's turn, the point's error."""
    p, line = args
    if p.is_at_infinity:
        return None
    return Reach(ins[0].error + _FEW * EPS * p.size(), ins[1].turn, p.xy)


def _meet(obj, args, ins, params) -> Reach | None:
    if obj.is_at_infinity:
        return None
    gl, hl = args
    sine = abs(gl.a * hl.b - gl.b * hl.a)
    if sine == 0.0:
        return None
    xy = obj.xy
    own = _FEW * EPS * (abs(gl.c) + abs(hl.c) + math.hypot(*xy))
    return Reach((ins[0].near(xy) + ins[1].near(xy) + own) / sine)


def _rotate(obj, args, ins, params) -> Reach | None:
    p, centre = args
    if p.is_at_infinity:
        return None
    return Reach(ins[0].error + 2 * ins[1].error
                 + _FEW * EPS * (p.size() + centre.size() + obj.size()))


def _lay_off(obj, args, ins, params) -> Reach | None:
    start, toward = args
    length = abs(params["length"])
    own = _FEW * EPS * (start.size() + length + obj.size())
    if isinstance(toward, g.Line):
        return Reach(ins[0].error + ins[1].turn * length + own)
    if toward.is_at_infinity:
        return Reach(ins[0].error + own)
    n = math.dist(start.xy, toward.xy)
    turn = (ins[0].error + ins[1].error + _FEW * EPS * _size(start.xy, toward.xy)) / n
    return Reach(ins[0].error + turn * length + own)


def _swing(obj, args, ins, params) -> Reach | None:
    return Reach(ins[0].error, radius=_FEW * EPS * obj.radius)


def _circle_through(obj, args, ins, params) -> Reach | None:
    centre, p = args
    return Reach(ins[0].error, radius=ins[0].error + ins[1].error
                 + _FEW * EPS * (centre.size() + p.size()))


_RULES = {"given": _given, "line_through": _line_through, "parallel_through": _through_point,
          "perpendicular_through": _through_point, "intersect_lines": _meet,
          "rotate_about": _rotate, "lay_off": _lay_off, "swing_arc": _swing,
          "circle_through": _circle_through}
"""Each drafting verb a cam draws with, by name."""


def lift_bounds(d: Displacement, segments) -> dict[Ref, float]:
    """Bound how far each point the diagram ``d`` of ``segments`` draws can stand off its
    law by rounding, in lift (m).

    The point's own error, and its error across the page times the slope there (a law's
    steepest is at most twice its segment's mean, 2h/β), since the law is read at the cam
    angle the point is drawn at; and the law's own rounding: a few of the lift it starts
    from and of its own, and its slope times the rounding of that cam angle.
    """
    reach = rounding(d.construction)
    out: dict[Ref, float] = {}
    height = 0.0
    for s, curve, start in zip(segments, d.curves, d.starts):
        h = 0.0 if s.kind == "dwell" else s.lift
        slope = 2 * h / s.angle                      # lift per radian, at most
        steep = slope / d.per_rad                    # on paper
        law = _FEW * EPS * (abs(height) + h + slope * (start + s.angle))
        for _, ref in curve:
            out[ref] = reach[ref].error * (1 + steep) + law
        height += h if s.kind == "rise" else -h
    return out


def join_bound(segments, theta: float) -> float:
    """Bound how far the closed form read at a station's cam angle ``theta`` (rad) can stand
    off the lift the station carries (m), because a join of two segments lies within the
    rounding of that angle.

    A station's angle is the sum start + i·β/n, so the one meant for a segment's end J lands
    a hair to either side of it (6·(β/6) is not β): the quotient and the product each round
    by half an EPS of β, the sum by half an EPS of θ, so |θ − J| ≤ 1.5·EPS·θ, which
    δθ = 4·EPS·θ allows for. There the closed form may read the other segment: the later
    one past J, as the profile's table reports a join. Both laws meet at J with the lift
    y(J) the station carries, so what it reads is off by at most the steeper side's |y′|
    (≤ 2h/β, as in :func:`lift_bounds`) times δθ. Away from a join the law read is the
    station's own, whose slope times the angle's rounding its lift's bound holds already:
    then this is 0.

    Examples
    --------
    A 5 cm return over 0.0157° after a 5 cm rise over 92.91°, read at the join:

    >>> from .displacement import Segment
    >>> rise = Segment("rise", 1.6215854080279315, 0.05)
    >>> back = Segment("return", 0.00027423299655240105, 0.05)
    >>> b = join_bound([rise, back], 6 * (rise.angle / 6))   # a hair past the join
    >>> 4e-14 < b < 1e-12       # the return's 2h/β = 365 m/rad, times 4 roundings of θ
    True
    >>> join_bound([rise, back], rise.angle / 2)
    0.0
    """
    window = _FEW * EPS * abs(theta)
    joins, start = [], 0.0
    for s in segments:
        joins.append(start)
        start += s.angle
    joins.append(start)                                  # 360°, which is 0° again
    slopes = [0.0 if s.kind == "dwell" else 2 * s.lift / s.angle for s in segments]
    steepest = 0.0
    for k, at in enumerate(joins):
        if abs(theta - at) <= window:
            # The segments meeting at this join: the one ending and the one starting here
            # (at 0° and 360°, the last and the first).
            steepest = max(steepest, slopes[k - 1], slopes[k % len(slopes)])
    return steepest * window
