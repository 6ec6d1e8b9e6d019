"""A pair of gears designed to an approximate centre distance, as the books design it: "two
parallel shafts, about 600 mm apart, run at 360 and 120 rpm; the circular pitch is 25 mm".

The pitch diameters share out twice the distance by the ratio, d_s + d_b = 2a with
d_b = k·d_s (d_b − d_s = 2a inside a ring), so d_s = 2a/(1 + k); the smaller gear's count
d_s/m = π·d_s/p is rounded up to the next whole count (never below a least count given),
as the books take "37.7, say 38", so the gears stand no nearer than the book asked; the
other's is k times it, and the pair then stands exactly m(N_s ± N_b)/2 apart.
"""

from __future__ import annotations

import math
from dataclasses import replace
from fractions import Fraction

from ..errors import InputError
from ..narration import Phrase, phrase
from .tabular import fraction_text
from .train import GearTrain, Mesh

__all__ = ["about_design", "teeth_about"]

Ratio = tuple[tuple[int, int], Fraction, int | None]
"""A speed ratio the book gives, ((x, y), |ω_x/ω_y|, its least tooth count or None)."""


def teeth_about(about: Fraction, module: Fraction, k: Fraction, internal: bool,
                least: int | None = None) -> tuple[Fraction, int]:
    """The smaller gear's count d_s/m as the distance gives it, and the whole count taken:
    the next one up, or ``least`` where that is more.

    Examples
    --------
    >>> teeth_about(Fraction(600), Fraction(5), Fraction(3), False)
    (Fraction(60, 1), 60)
    >>> teeth_about(Fraction(600), Fraction(8), Fraction(3), False)
    (Fraction(75, 2), 38)
    """
    raw = 2 * about / ((k - 1 if internal else k + 1) * module)
    return raw, max(math.ceil(raw), least or 1)


def about_design(train: GearTrain, mesh: Mesh, ratios: list[Ratio]
                 ) -> tuple[GearTrain, list[Phrase]]:
    """``train`` with the teeth of ``mesh``'s pair designed to its approximate centre
    distance and its own speed ratio (``ratios`` as ((x, y), |ω_x/ω_y|, least count)), and
    the steps: the diameters shared out, the rounding, the other count, the exact distance.

    Raises
    ------
    InputError
        If the pair has a count given, no ratio of its own or no module, meshes inside a
        ring at a ratio of 1, or its ratio makes the rounded count's partner broken (the
        nearest whole choices named); no line (the reader gives the mesh's).
    """
    a, b = mesh.a, mesh.b
    where = f"gears {a} and {b}, about {train._length(mesh.about)} apart"
    if any(train.gear(g).teeth is not None for g in (a, b)):
        raise _fail(train, f"{where}: an approximate distance designs both counts; leave "
                    "their teeth out, or give the exact centre_distance")
    given = [r for r in ratios if set(r[0]) == {a, b}]
    if not given:
        raise _fail(train, f"{where}, need their own speed ratio to share it: give [ratio] "
                    f'of = "omega{a}/omega{b}" and its value')
    (x, y), value, least = given[0]
    m = next((g.module for g in (train.gear(a), train.gear(b)) if g.module is not None), None)
    if m is None:
        raise _fail(train, f"{where}, need a tooth size: give module = … or circular_pitch "
                    f"= … in gear {a}'s [[gear]] table")
    k = value if value >= 1 else 1 / value        # N_big/N_small = |ω_small/ω_big|
    small, big = (x, y) if value >= 1 else (y, x)
    if mesh.internal and k == 1:
        raise _fail(train, f"{where}, mesh inside a ring at a speed ratio of 1: a ring has "
                    "more teeth than the gear in it")
    raw, n = teeth_about(mesh.about, m, k, mesh.internal, least)
    if (n * k).denominator != 1:
        q = k.denominator                   # N_small must be a multiple of it
        choices = [c for c in (n // q * q, n // q * q + q) if c >= max(1, least or 1)]
        raise _fail(train, f"{where} at ω{x}/ω{y} = {fraction_text(value)}: N{small} = {n} "
                    f"gives gear {big} {float(n * k):.4g} teeth, not whole; nearest: N{small} "
                    f"= {' or '.join(map(str, choices))} (N{big} = "
                    f"{' or '.join(str(int(c * k)) for c in choices)}): give gear {small} "
                    "one as its teeth in place of the distance")
    pitch = train.gear(a).circular_pitch or train.gear(b).circular_pitch
    d = 2 * mesh.about / ((k - 1) if mesh.internal else (k + 1))
    count = (f"π·{train._length(d)}/{train._length(pitch)}" if pitch else
             f"{train._length(d)}/{train._length(m)}")
    rounded = (phrase("gears.about_up", n=small, teeth=n) if n == math.ceil(raw) else
               phrase("gears.about_least", n=small, least=least))
    sign = "−" if mesh.internal else "+"
    steps = [phrase("gears.about_teeth", a=a, b=b, about=train._length(mesh.about), x=x, y=y,
                    value=fraction_text(value), s=small, g=big, k=fraction_text(k),
                    sign=sign, d=train._length(d), count=f"{count} = {float(raw):.5g}",
                    rounded=rounded)]
    teeth = {small: n, big: int(n * k)}
    steps.append(phrase("gears.teeth_ratio", x=x, y=y, value=fraction_text(value), g=big,
                        expr=f"N{y}/{teeth[x]}" if big == y else f"{teeth[y]}/N{x}",
                        teeth=teeth[big]))
    na, nb = teeth[a], teeth[b]
    counts = f"({max(na, nb)} − {min(na, nb)})" if mesh.internal else f"({na} + {nb})"
    exact = (f"{train._length(pitch)}·{counts}/(2π)" if pitch else
             f"{train._length(m)}·{counts}/2")
    span = m * (abs(na - nb) if mesh.internal else na + nb) / 2     # m = p/π
    steps.append(phrase("gears.about_exact", a=a, b=b, equation=exact,
                        distance=train._length(span)))
    return replace(train, gears=tuple(replace(g, teeth=teeth[g.number]) if g.number in teeth
                                      else g for g in train.gears),
                   meshes=tuple(replace(e, least=least) if e is mesh else e
                                for e in train.meshes)), steps


def _fail(train: GearTrain, message: str) -> InputError:
    return InputError(message, file=train.source or None)
