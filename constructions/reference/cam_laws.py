"""The independent reference for cam follower motion: each law in closed form.

A segment rises (or returns) through ``lift`` h over the cam angle β. With u = θ/β in
[0, 1], the follower's displacement y and its kinematic coefficients y′ = dy/dθ,
y″ = d²y/dθ², y‴ = d³y/dθ³ are:

- uniform velocity: y = h·u;
- simple harmonic: y = h/2·(1 − cos πu);
- uniform acceleration and retardation (parabolic): y = 2h·u² to u = ½, then
  h − 2h·(1 − u)²; split unequally at u = k (acceleration over the first fraction k of the
  segment), y = h·u²/k to u = k, then h − h·(1 − u)²/(1 − k): the velocity 2h/β at the
  split whatever k, the acceleration 2h/kβ², the retardation 2h/(1 − k)β²;
- cycloidal: y = h·(u − sin 2πu / 2π);
- modified uniform velocity: uniform velocity V = h/(1 − b)β, its corners blended by
  parabolas (uniform acceleration V/bβ) over the first and last fraction b of the segment,
  so y′ is continuous: y = Vθ²/2bβ to θ = bβ, then straight, then h − V(β − θ)²/2bβ.

A return is the rise mirrored: y = h − y_rise. Time derivatives follow by the chain rule
(notes 000-part2 §2.16): ẏ = y′ω, ÿ = y″ω² + y′α, y⃛ = y‴ω³ + 3y″ωα + y′α̇ (the notes
print the last term y′α², which is wrong).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

__all__ = ["LAWS", "Motion", "jerk_peak", "motion", "peaks", "pieces", "time_rates"]

LAWS = ("uniform velocity", "modified uniform velocity", "simple harmonic", "parabolic",
        "cycloidal")
"""The laws the reference knows, by the names the files use."""


@dataclass(frozen=True)
class Motion:
    """y and its kinematic coefficients at one cam angle (m, m/rad, m/rad², m/rad³)."""

    y: float
    y1: float
    y2: float
    y3: float


BLEND = 0.25
"""The fraction of a modified-uniform-velocity segment blended at each end, unless given."""


def pieces(law: str, blend: float = BLEND, split: float = 0.5) -> tuple[float, ...]:
    """The fractions of a segment that bound the pieces of its law, 0 and 1 included: y″
    jumps between two pieces (at a parabolic segment's ``split``, its middle unless given,
    at the ends of a modified uniform velocity's blends), and within one the law is
    analytic.

    Examples
    --------
    >>> pieces("parabolic"), pieces("cycloidal")
    ((0.0, 0.5, 1.0), (0.0, 1.0))
    """
    inner = {"parabolic": (split,), "modified uniform velocity": (blend, 1 - blend)}.get(law, ())
    return tuple(sorted({0.0, *inner, 1.0}))


def motion(law: str, lift: float, beta: float, theta: float, *, rise: bool = True,
           blend: float = BLEND, split: float = 0.5, piece: int | None = None) -> Motion:
    """The follower's motion ``theta`` (rad) into a segment of ``beta`` lifting ``lift``
    (``blend``: the modified uniform velocity's blended fraction at each end; ``split``:
    the fraction of a parabolic segment that accelerates).

    ``piece`` (an index into :func:`pieces`) evaluates that piece's formula whatever
    ``theta`` is, so a piece's end gives its own one-sided limit where y″ jumps; by default
    the piece ``theta`` falls in (the earlier one at a break).

    Raises
    ------
    ValueError
        For a law it does not know.
    """
    u = min(max(theta / beta, 0.0), 1.0)
    h, b = lift, beta
    if law == "uniform velocity":
        m = Motion(h * u, h / b, 0.0, 0.0)
    elif law == "modified uniform velocity":
        v, t, edge = h / ((1 - blend) * b), u * b, blend * b
        if piece is None:
            piece = 0 if t <= edge else 2 if t >= b - edge and blend < 0.5 else 1
        if piece == 0:
            m = Motion(v * t * t / (2 * edge), v * t / edge, v / edge, 0.0)
        elif piece == 2 or blend == 0.5:
            m = Motion(h - v * (b - t) ** 2 / (2 * edge), v * (b - t) / edge, -v / edge, 0.0)
        else:
            m = Motion(v * edge / 2 + v * (t - edge), v, 0.0, 0.0)
    elif law == "simple harmonic":
        k = math.pi / b
        m = Motion(h / 2 * (1 - math.cos(math.pi * u)), h / 2 * k * math.sin(math.pi * u),
                   h / 2 * k * k * math.cos(math.pi * u), -h / 2 * k ** 3 * math.sin(math.pi * u))
    elif law == "parabolic":
        k = split
        if (u <= k) if piece is None else piece == 0:
            m = Motion(h * u * u / k, 2 * h * u / (k * b), 2 * h / (k * b * b), 0.0)
        else:
            m = Motion(h - h * (1 - u) ** 2 / (1 - k), 2 * h * (1 - u) / ((1 - k) * b),
                       -2 * h / ((1 - k) * b * b), 0.0)
    elif law == "cycloidal":
        w = 2 * math.pi * u
        m = Motion(h * (u - math.sin(w) / (2 * math.pi)), h / b * (1 - math.cos(w)),
                   2 * math.pi * h / b ** 2 * math.sin(w),
                   4 * math.pi ** 2 * h / b ** 3 * math.cos(w))
    else:
        raise ValueError(f"unknown law '{law}'; the laws are {', '.join(LAWS)}")
    if rise:
        return m
    # A return is the rise run backwards in lift: y = h − y_rise, each coefficient negated.
    return Motion(h - m.y, -m.y1, -m.y2, -m.y3)


def peaks(law: str, lift: float, beta: float, blend: float = BLEND, split: float = 0.5
          ) -> tuple[float, float]:
    """The textbook maxima of |y′| and |y″| over a segment (per rad, per rad²):
    uniform velocity h/β and — (infinite at the ends, given as inf); modified uniform
    velocity h/(1 − b)β and h/b(1 − b)β²; simple harmonic πh/2β and π²h/2β²; parabolic 2h/β
    and 4h/β² (split at k, 2h/β and 2h/kβ² or 2h/(1 − k)β², the shorter part's);
    cycloidal 2h/β and 2πh/β²."""
    h, b = lift, beta
    return {"uniform velocity": (h / b, math.inf),
            "modified uniform velocity": (h / ((1 - blend) * b),
                                          h / (blend * (1 - blend) * b * b)),
            "simple harmonic": (math.pi * h / (2 * b), math.pi ** 2 * h / (2 * b * b)),
            "parabolic": (2 * h / b, 2 * h / (min(split, 1 - split) * b * b)),
            "cycloidal": (2 * h / b, 2 * math.pi * h / b ** 2)}[law]


def jerk_peak(law: str, lift: float, beta: float) -> float:
    """The textbook maximum of |y‴| (per rad³): simple harmonic π³h/2β³, cycloidal
    4π²h/β³; infinite (given as inf) where y″ jumps, as it does at the ends and joins of the
    uniform velocity, parabolic and modified uniform velocity laws."""
    h, b = lift, beta
    return {"simple harmonic": math.pi ** 3 * h / (2 * b ** 3),
            "cycloidal": 4 * math.pi ** 2 * h / b ** 3}.get(law, math.inf)


def time_rates(m: Motion, omega: float, alpha: float = 0.0, alpha_dot: float = 0.0
               ) -> tuple[float, float, float]:
    """The follower's velocity, acceleration and jerk from the kinematic coefficients by the
    chain rule: ẏ = y′ω, ÿ = y″ω² + y′α, y⃛ = y‴ω³ + 3y″ωα + y′α̇."""
    return (m.y1 * omega, m.y2 * omega ** 2 + m.y1 * alpha,
            m.y3 * omega ** 3 + 3 * m.y2 * omega * alpha + m.y1 * alpha_dot)
