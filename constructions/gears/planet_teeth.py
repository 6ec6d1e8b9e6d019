"""A train's teeth from the speed ratios the book gives, and a least tooth count.

The books design an epicyclic gear to a ratio: "the carrier turns at 1/5 of the sun's speed,
no wheel has fewer than 16 teeth"; or a reverted train to its pairs' ratios and modules, or
two shafts a given distance apart. Through the table, the ratio ω_x/ω_y is a bilinear
(Möbius) function of any one count, (a·N + b)/(c·N + d) (each mesh's ratio is N or 1/N,
and the table adds the arm's turn), so three trial counts fix it and the count the ratio
asks follows at once: for the sun-and-ring train with the ring fixed, ω_s/ω_a = 1 + N_r/N_s.
The coaxial condition and the centre distances given (:func:`~.teeth.imply_teeth`) give
the rest, and a count they tie to the one tried follows it. With several counts
unknown, the smallest takes the least count, or the fewest above it that make every
other count whole, as the books choose it.
"""

from __future__ import annotations

from dataclasses import replace
from fractions import Fraction

from ..errors import InputError
from ..narration import Phrase, phrase
from .tabular import fraction_text, tabulate
from .teeth import coaxial_misfit, coaxial_ties, imply_teeth, unknown_teeth
from .train import GearTrain

__all__ = ["teeth_from_ratios"]

Ratio = tuple[tuple[int, int], Fraction]
"""A speed ratio the book gives: ((x, y), |ω_x/ω_y|)."""

_TRIALS = (*range(2, 14), *range(1001, 1013))
"""The trial counts the Möbius function is fixed by (any three that make a train do): small
ones, so that a count a given distance ties to them stays positive, then large ones, so
that one the coaxial condition takes from them beside a ring does; a dozen of each, so
that whole ones come among them whatever their parity."""
_STAND_INS = ((1009, 1013), (2003, 2011))
"""Two sets of counts for the other unknowns: a count the ratio fixes alone comes out the
same with either."""
_SEARCH = 300
"""How far above the least count the search goes before it gives up."""


def teeth_from_ratios(train: GearTrain, ratios: list[Ratio], least: int | None
                      ) -> tuple[GearTrain, tuple[Phrase, ...]]:
    """The teeth the speed ratios |ω_x/ω_y| leave to find, and the steps: a count from
    each ratio, or, with ``least``, the smallest of those left at the least count and the
    rest by the ratios, the coaxial condition and the centre distances.

    Raises
    ------
    InputError
        If the ratio and the coaxial condition cannot fix the counts, or no whole counts
        of ``least`` or more give the ratio.
    """
    unknown = unknown_teeth(train)
    if not unknown:
        return train, ()
    found = _fill(train, ratios)
    if found is not None:
        done, _ = found
        few = [g for g in unknown if least is not None and done.gear(g).teeth < least]
        if few:
            raise InputError(f"the speed ratios and the coaxial condition give gear {few[0]} "
                             f"{done.gear(few[0]).teeth} teeth, fewer than least_teeth = "
                             f"{least}: check the ratios and the teeth given, or lower it",
                             file=train.source or None)
        return found
    said = ", ".join(f"ω{x}/ω{y} = {float(v):g}" for (x, y), v in ratios)
    gears = ", ".join(map(str, unknown))
    # each ratio and each tie fixes one count, the least count one more
    spare = len(unknown) - len(ratios) - coaxial_ties(train) - (least is not None)
    if least is None and spare <= 0:
        raise InputError(f"the speed ratio{'s' * (len(ratios) > 1)} {said}, the coaxial "
                         f"condition and the centre distances give gears {gears} no whole "
                         "counts: check the ratios, the teeth and the modules"
                         + (", or say centre_distance = { about = … }" if any(
                             m.distance for m in train.meshes) else ""),
                         file=train.source or None)
    if least is None or spare > 0:
        raise InputError(f"gears {gears} have no teeth, and the speed ratios, the coaxial "
                         "condition and the centre distances leave them open: give "
                         + ("each pair's ratio in a [[ratio]] of its own, or more teeth"
                            if least is not None else "least_teeth = … in [ratio], or more "
                            "teeth"), file=train.source or None)
    for n in range(least, least + _SEARCH):
        for g in unknown:
            found = _fill(_with(train, g, n), ratios)
            if found is None:
                continue
            done, steps = found
            if all(done.gear(h).teeth >= n for h in unknown):
                return done, (phrase("gears.teeth_least_set", g=g, least=least, teeth=n),
                              *steps)
    raise InputError(f"no whole counts of {least} teeth or more for gears "
                     f"{gears} give the speed ratio"
                     f"{'s' * (len(ratios) > 1)} {said}", file=train.source or None)


def _fill(train: GearTrain, ratios: list[Ratio]
          ) -> tuple[GearTrain, tuple[Phrase, ...]] | None:
    """``train`` with every count the coaxial condition, the distances and the ratios give
    in turn, and the steps; None where they leave a count unknown or give one that is not
    whole and positive, or a ratio does not hold."""
    steps: list[Phrase] = []
    while True:
        try:
            train, said = imply_teeth(train, train.coaxial)
        except InputError:
            return None
        steps += said
        unknown = unknown_teeth(train)
        if not unknown:
            try:
                holds = all(abs(_ratio(train, of)) == value for of, value in ratios)
            except (InputError, ZeroDivisionError):
                return None
            holds = holds and coaxial_misfit(train, train.coaxial) is None
            return (train, tuple(steps)) if holds else None
        got = next((found for g in unknown for of, value in ratios
                    if (found := _one(train, of, value, g)) is not None), None)
        if got is None:
            return None
        g, n, step = got
        train = _with(train, g, n)
        steps.append(step)


def _one(train: GearTrain, of: tuple[int, int], value: Fraction, g: int
         ) -> tuple[int, int, Phrase] | None:
    """Gear ``g``'s count from the ratio, the counts the coaxial condition ties to it
    following it, whatever the other unknowns' counts (two sets of stand-ins must give it
    alike); None where they do not, or it is not whole."""
    answers = [_solve(train, of, value, g, stand_in) for stand_in in _STAND_INS]
    if None in answers or answers[0][0] != answers[1][0]:
        return None
    n, expr = answers[0]
    return g, n, phrase("gears.teeth_ratio_table", x=of[0], y=of[1],
                        value=fraction_text(value), g=g, expr=expr, teeth=n)


def _trial(train: GearTrain, of: tuple[int, int], g: int, n: int,
           stand_in: tuple[int, int]) -> Fraction | None:
    """ω_x/ω_y with gear ``g`` at ``n`` teeth, the coaxial condition's counts from it, and
    the ``stand_in`` counts for the rest; None where they do not make a train."""
    try:
        t, _ = imply_teeth(_with(train, g, n), train.coaxial)
        for h, k in zip(unknown_teeth(t), stand_in * len(train.gears)):
            t = _with(t, h, k)
        return _ratio(t, of)
    except (InputError, ZeroDivisionError):
        return None


def _solve(train: GearTrain, of: tuple[int, int], value: Fraction, g: int,
           stand_in: tuple[int, int]) -> tuple[int, str] | None:
    """The whole positive count N of gear ``g`` for which ω_x/ω_y = ±``value``, and the
    ratio as said, "(N1 + 16)/16"; None if there is none (or the ratio does not hang on
    N)."""
    samples = []
    for n in _TRIALS:
        r = _trial(train, of, g, n, stand_in)
        if r is not None:
            samples.append((Fraction(n), r))
            if len(samples) == 3:
                break
    coefficients = _moebius(samples) if len(samples) == 3 else None
    if coefficients is None:
        return None
    a, b, c, d = coefficients
    for target in (value, -value):
        if a == target * c:
            continue
        n = (target * d - b) / (a - target * c)
        if n.denominator == 1 and 0 < n <= 100_000 and _trial(
                train, of, g, int(n), stand_in) == target:
            return int(n), _said(a, b, c, d, g)
    return None


def _moebius(samples: list[tuple[Fraction, Fraction]]
             ) -> tuple[Fraction, Fraction, Fraction, Fraction] | None:
    """(a, b, c, d) with s = (a·N + b)/(c·N + d) through the three (N, s), scaled to a
    whole form; None where s does not hang on N."""
    if len({s for _, s in samples}) == 1:
        return None
    for fixed in ("d", "c"):       # d = 1 unless the form is (a·N + b)/N
        rows = []
        for n, s in samples:      # a·N + b − s·c·N = s  or  a·N + b − s·d = s·N
            rows.append([n, Fraction(1), -s * n, s] if fixed == "d" else
                        [n, Fraction(1), -s, s * n])
        x = _cramer(rows)
        if x is not None:
            a, b, other = x
            c, d = (other, Fraction(1)) if fixed == "d" else (Fraction(1), other)
            scale = _common(a, b, c, d)
            return a * scale, b * scale, c * scale, d * scale
    return None


def _cramer(rows: list[list[Fraction]]) -> tuple[Fraction, Fraction, Fraction] | None:
    """The 3×3 system's solution by Cramer's rule, exact; None if it is singular."""
    def det(m: list[list[Fraction]]) -> Fraction:
        return (m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
                - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
                + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]))

    matrix = [r[:3] for r in rows]
    whole = det(matrix)
    if whole == 0:
        return None
    return tuple(det([[r[3] if j == k else r[j] for j in range(3)] for r in rows]) / whole
                 for k in range(3))


def _common(*xs: Fraction) -> Fraction:
    """The factor that makes ``xs`` whole numbers with no common divisor."""
    from math import gcd, lcm
    den = lcm(*(x.denominator for x in xs))
    top = gcd(*(int(x * den) for x in xs)) or 1
    return Fraction(den, top)


def _said(a: Fraction, b: Fraction, c: Fraction, d: Fraction, g: int) -> str:
    """(a·N + b)/(c·N + d) as a step writes it: "(N1 + 16)/16", "N1/(N1 − 20)"."""
    def linear(p: Fraction, q: Fraction) -> str:
        term = "" if p == 0 else f"N{g}" if p == 1 else f"−N{g}" if p == -1 else \
            f"{fraction_text(p)}·N{g}"
        if q == 0:
            return term or "0"
        if not term:
            return fraction_text(q)
        return f"{term} {'+' if q > 0 else '−'} {fraction_text(abs(q))}"

    def wrap(s: str) -> str:
        return f"({s})" if " " in s or "·" in s else s

    top, bottom = linear(a, b), linear(c, d)
    return top if bottom == "1" else f"{wrap(top)}/{wrap(bottom)}"


def _ratio(train: GearTrain, of: tuple[int, int]) -> Fraction:
    """ω_x/ω_y by the table, its speeds as the train's own (any given speed scales both)."""
    speeds = tabulate(train).speeds
    return speeds[of[0]] / speeds[of[1]]


def _with(train: GearTrain, number: int, teeth: int) -> GearTrain:
    return replace(train, gears=tuple(replace(g, teeth=teeth) if g.number == number else g
                                      for g in train.gears))
