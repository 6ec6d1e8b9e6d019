"""What the polygons read off their own drawing, as functions of the steps they read.

The acceleration polygon lays off lengths it reads from the velocity polygon (a relative
normal ``ω²·r``, a Coriolis component ``2ω·v``) and an image's tip at a share of a side it
reads from the polygon itself. Written as functions of the steps they read (``output``
gives a step's output by its ref), the polygons record them as each step's
:class:`~tarsim.constructions.record.Derived`, and a replay at another position of the
input (:mod:`tarsim.constructions.replay`) reads them again from its own drawing.

A rate is read over ``(p, q, tp, tq, scale)``: the steps of two points of the link on
the space diagram and of their tips, and the polygon's scale. An empty read is a link that
does not turn (a block on a guide of the frame).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

from .polygon import sense_of
from ..record import Ref

__all__ = ["rate", "image_ratio", "image_length", "relative_normal", "velocity", "slide_speed",
           "coriolis_length", "curve_normal_length"]

Output = Callable[[Ref], Any]
Read = tuple
"""How a link's ω is read: ``(p, q, tp, tq, scale)``, or () for a link that does not turn."""


def rate(output: Output, read: Read) -> float:
    """ω of a link read off the velocity polygon: ``(r × v_rel) / r²``."""
    if not read:
        return 0.0
    p, q, tp, tq, scale = read
    (px, py), (qx, qy) = output(p).xy, output(q).xy
    (tpx, tpy), (tqx, tqy) = output(tp).xy, output(tq).xy
    rx, ry, vx, vy = qx - px, qy - py, (tqx - tpx) / scale, (tqy - tpy) / scale
    return (rx * vy - ry * vx) / (rx * rx + ry * ry)


def image_ratio(output: Output, a: Ref, b: Ref, x: Ref) -> float:
    """Where X stands on the line AB of a link, as a share of AB from A (the image's
    ratio): ``AX·AB / AB²``."""
    (ax, ay), (bx, by), (px, py) = output(a).xy, output(b).xy, output(x).xy
    return ((px - ax) * (bx - ax) + (py - ay) * (by - ay)) / ((bx - ax) ** 2 + (by - ay) ** 2)


def image_length(output: Output, ta: Ref, tb: Ref, a: Ref, b: Ref, x: Ref
                 ) -> dict[str, float]:
    """An image's tip laid off from ``ta`` toward ``tb``: X's share of AB
    (:func:`image_ratio`) of the side between the tips."""
    return {"length": image_ratio(output, a, b, x) * math.dist(output(ta).xy, output(tb).xy)}


def relative_normal(output: Output, read: Read, k: Ref, x: Ref, scale: float
                    ) -> dict[str, float]:
    """Aⁿ of X about K on a link turning at the ω ``read`` gives: ``ω²·KX``, toward K."""
    w = rate(output, read)
    r = math.dist(output(k).xy, output(x).xy)
    return {"length": -w * w * r * scale}


def velocity(output: Output, tip: Ref | None, pole: Ref, scale: float) -> tuple[float, float]:
    """A velocity read off the velocity polygon: pole to ``tip`` (None: a point at rest)."""
    if tip is None:
        return (0.0, 0.0)
    (sx, sy), (ex, ey) = output(pole).xy, output(tip).xy
    return (ex - sx) / scale, (ey - sy) / scale


def slide_speed(output: Output, slider: tuple, carried: tuple, tangent: tuple[float, float]
                ) -> float:
    """V_P/Pj along a slot's ``tangent``: the slider's and the slot point's velocities,
    each given as ``(tip, pole, scale)`` for :func:`velocity`."""
    (sx, sy), (cx, cy) = velocity(output, *slider), velocity(output, *carried)
    return (sx - cx) * tangent[0] + (sy - cy) * tangent[1]


def _tangent(output: Output, along: tuple) -> tuple[float, float]:
    """A slot's tangent: a straight slot's guide line ``("guide", ref)``; a slot curved
    about K through P, ``("curve", K, P)``, KP turned +90°."""
    if along[0] == "guide":
        return output(along[1]).direction
    (kx, ky), (px, py) = output(along[1]).xy, output(along[2]).xy
    e = math.hypot(px - kx, py - ky)
    return (-(py - ky) / e, (px - kx) / e)


def coriolis_length(output: Output, read: Read, slider: tuple, carried: tuple, along: tuple,
                    factor: float, scale: float, speed: float, noise: float
                    ) -> dict[str, float]:
    """The Coriolis component ``2ω_j·v_rel`` laid off ``factor`` (±1, its sense along the
    line) times over: 0 where the slot is at rest beside the input's ``speed``, or nothing
    slides beyond ``noise``."""
    w = rate(output, read)
    u = slide_speed(output, slider, carried, _tangent(output, along))
    still = sense_of(w, speed) == "at rest"
    cor = 0.0 if still or abs(u) <= noise else 2.0 * w * u
    return {"length": factor * cor * scale}


def curve_normal_length(output: Output, slider: tuple, carried: tuple, along: tuple,
                        radius: float, factor: float, scale: float) -> dict[str, float]:
    """A curved slot's normal component ``v_rel²/ρ``, laid off ``factor`` times over."""
    u = slide_speed(output, slider, carried, _tangent(output, along))
    return {"length": factor * (u * u / radius) * scale}
