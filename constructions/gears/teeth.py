"""Tooth numbers the data imply, found before the speeds, as the books leave them to find.

A gear may come with no teeth. Its count then follows, exactly, from

- its pitch diameter and module, N = d/m (read with the file: :func:`teeth_from_diameter`);
- a pair's centre distance with its module (:func:`imply_teeth`), C = m(N_a ± N_b)/2;
- the coaxial condition (:func:`imply_teeth`): the arm carries each planet body at one
  radius, so its meshes with the gears on the main axis stand equally far from it,
  m(N_c + N_p)/2 externally and m(N_c − N_p)/2 inside a ring: the notes' N1 = N2 + 2·N4,
  a reverted train's N2 + N3 = N4 + N5. In an ordinary reverted train the file says which
  two gears share an axis (``coaxial = [2, 5]``), and the same holds of its two pairs;
  through planets in series (sun, planet, idler planet, ring, all on one arm) the last
  planet's centre stands as far out along the chain as in from the ring:
  N_ring = N_sun + 2·N_c + 2·N_b (:func:`_chains`);
- an ordinary train's speed ratio, with a least tooth count for a pair both unknown
  (:func:`teeth_from_ratio`); a planetary train's, in :mod:`.planet_teeth`.

Each count found is a step, and must come out whole and positive.
"""

from __future__ import annotations

from dataclasses import replace
from fractions import Fraction

from ..errors import InputError
from ..narration import Phrase, phrase
from .tabular import carry, fraction_text
from .train import GearTrain, Mesh

__all__ = ["coaxial_misfit", "coaxial_pairs", "coaxial_ties", "imply_teeth", "teeth_from_diameter",
           "teeth_from_ratio", "unknown_teeth"]


def teeth_from_diameter(diameter: Fraction, module: Fraction) -> Fraction:
    """N = d/m, exact (whole for a gear; the caller refuses it otherwise)."""
    return diameter / module


def unknown_teeth(train: GearTrain) -> list[int]:
    """The gears whose teeth are still unknown."""
    return [g.number for g in train.gears if g.teeth is None]


def imply_teeth(train: GearTrain, coaxial: tuple[int, int] | None = None
                ) -> tuple[GearTrain, tuple[Phrase, ...]]:
    """``train`` with every tooth count the coaxial condition and the centre distances given
    fix, and its steps.

    Raises
    ------
    InputError
        If a count comes out broken or not positive.
    """
    steps: list[Phrase] = []
    grew = True
    while grew and unknown_teeth(train):
        grew = False
        by_distance = _from_distance(train)
        if by_distance is not None:
            number, teeth, step = by_distance
            train = replace(train, gears=tuple(replace(g, teeth=teeth) if g.number == number
                                               else g for g in train.gears))
            steps.append(step)
            grew = True
            continue
        for pairs in _coaxial_sets(train, coaxial):
            found = _solve(train, pairs)
            if found is None:
                continue
            number, teeth, said = found
            train = replace(train, gears=tuple(replace(g, teeth=teeth) if g.number == number
                                               else g for g in train.gears))
            steps.append(phrase("gears.teeth_coaxial", gear=train.said(number, opening=True),
                                equation=said, n=number, teeth=teeth))
            grew = True
            break
        else:
            for outward, ring in _chains(train):
                found = _solve_chain(train, outward, ring)
                if found is not None:
                    number, teeth, said = found
                    train = _with(train, number, teeth)
                    steps.append(phrase("gears.teeth_chain", gear=train.said(number,
                                                                             opening=True),
                                        equation=said, n=number, teeth=teeth))
                    grew = True
                    break
    return train, tuple(steps)


def _chains(train: GearTrain) -> list[tuple[list[tuple[Mesh, int]], tuple[Mesh, int]]]:
    """Each chain of two or more single planets in series from a gear on the main axis
    (externally) to a ring (internally): the meshes outward, each as (mesh, the gear nearer
    the axis), and the ring's (mesh, ring). The chain is taken along one radius, as the
    books draw it, so the last planet's carrier radius is the sum of the distances out."""
    if not train.planetary:
        return []

    def single(g: int) -> bool:
        return train.carried(g) and len(train.body(g)) == 1

    out = []

    def walk(path: list[tuple[Mesh, int]], at: int, seen: set[int]) -> None:
        for mesh in train.meshes:
            if at not in (mesh.a, mesh.b) or mesh.bevel:
                continue
            other = mesh.b if mesh.a == at else mesh.a
            if other in seen:
                continue
            if single(other) and not mesh.internal:
                walk([*path, (mesh, at)], other, seen | {other})
            elif mesh.internal and not train.carried(other) and len(path) > 1:
                out.append((path, (mesh, other)))

    for mesh in train.meshes:
        for sun, p in ((mesh.a, mesh.b), (mesh.b, mesh.a)):
            if not mesh.internal and not mesh.bevel and not train.carried(sun) and single(p):
                walk([(mesh, sun)], p, {sun, p})
    return out


def _solve_chain(train: GearTrain, outward: list[tuple[Mesh, int]], ring: tuple[Mesh, int]
                 ) -> tuple[int, int, str] | None:
    """The one unknown count of a chain of planets in series: Σ m(N_near + N_far)/2 out
    from the axis = m(N_ring − N_last)/2, linear in the count (a planet's stands in two
    terms); None unless exactly one count is unknown."""
    legs = [*outward, ring]
    missing = {g for mesh, _ in legs for g in (mesh.a, mesh.b) if _teeth(train, g) is None}
    if len(missing) != 1:
        return None
    g = missing.pop()
    sized = all(_module(train, m) is not None for m, _ in legs)
    terms = [_linear(train, m, c, g, sized) for m, c in outward]
    a1, b1 = sum(a for a, _ in terms), sum(b for _, b in terms)
    a2, b2 = _linear(train, *ring, g, sized)
    if b1 == b2:
        return None
    teeth = (a2 - a1) / (b1 - b2)
    said = (" + ".join(_said(train, m, c, sized, g) for m, c in outward)
            + f" = {_said(train, *ring, sized, g)}")
    if teeth.denominator != 1 or teeth <= 0:
        raise InputError(f"the coaxial condition through the planets in series, {said}, "
                         f"gives gear {g} {float(teeth):g} teeth, not a whole number of one "
                         "or more: check the teeth and modules given", file=train.source or None)
    return g, int(teeth), said


def _from_distance(train: GearTrain) -> tuple[int, int, Phrase] | None:
    """The one unknown count of a pair whose centre distance C the file gives, with its
    module m: N = 2C/m − N_other outside, N_other ± 2C/m inside a ring (the ring listed
    second); None where no such pair is left.

    Raises
    ------
    InputError
        If the pair has no module, or the count comes out broken or not positive.
    """
    for mesh in train.meshes:
        missing = [g for g in (mesh.a, mesh.b) if _teeth(train, g) is None]
        if mesh.distance is None or len(missing) != 1:
            continue
        g = missing[0]
        other = mesh.b if g == mesh.a else mesh.a
        m = _module(train, mesh)
        if m is None:
            raise InputError(f"gears {mesh.a} and {mesh.b} are given a centre distance but no "
                             "module: give the module of one of them",
                             file=train.source or None)
        span = 2 * mesh.distance / m
        teeth = (span - _teeth(train, other) if not mesh.internal else
                 _teeth(train, other) + (span if g == mesh.b else -span))
        sign = "−" if mesh.internal else "+"
        a, b = (f"N{n}" if n == g else str(_teeth(train, n)) for n in (mesh.a, mesh.b))
        said = f"{train._length(mesh.distance)} = {train._length(m)}·({a} {sign} {b})/2"
        if teeth.denominator != 1 or teeth <= 0:
            raise InputError(f"the centre distance {said} gives gear {g} {float(teeth):g} "
                             "teeth, not a whole number of one or more: check the distance, "
                             "the module and the teeth", file=train.source or None)
        return g, int(teeth), phrase("gears.teeth_distance", n=g, equation=said,
                                     teeth=int(teeth))
    return None


def _coaxial_sets(train: GearTrain, coaxial: tuple[int, int] | None
                  ) -> list[list[tuple[Mesh, int]]]:
    """Each set of meshes that must stand equally far apart, as (mesh, the gear of the
    pair on the far axis): a planet body's meshes with the main-axis gears; and the two
    pairs between an ordinary train's ``coaxial`` gears and one shaft."""
    out = []
    for body in train.bodies:
        if not (train.planetary and train.carried(body[0])):
            continue
        pairs = [(mesh, c) for mesh in train.meshes for p, c in ((mesh.a, mesh.b),
                                                                 (mesh.b, mesh.a))
                 if p in body and not train.carried(c) and not mesh.bevel]
        if len(pairs) > 1:
            out.append(pairs)
    return out + (coaxial_pairs(train, coaxial) if coaxial is not None else [])


def coaxial_pairs(train: GearTrain, coaxial: tuple[int, int]) -> list[list[tuple[Mesh, int]]]:
    """The pairs an ordinary train's ``coaxial`` gears a and b end, joined by one shaft, as
    [(a's mesh, a), (b's mesh, b)]: the two that must stand equally far apart (none where
    the two gears end no such pairs)."""
    a, b = coaxial
    near = {g: [(m, m.b if m.a == g else m.a) for m in train.meshes if g in (m.a, m.b)]
            for g in (a, b)}
    return [[(ma, a), (mb, b)] for ma, x in near[a] for mb, y in near[b]
            if y in train.body(x) and a not in train.body(x) and b not in train.body(y)]


def _solve(train: GearTrain, pairs: list[tuple[Mesh, int]]
           ) -> tuple[int, int, str] | None:
    """The one unknown count in two pairs of ``pairs`` that must stand equally far apart:
    (gear, teeth, the equation as said); None if no two pairs leave exactly one unknown.
    Each distance is m(N_far ± N_near)/2, linear in the count, so the two give it at once
    (the planet's own count too, in both pairs: N_p = (N_ring − N_sun)/2)."""
    # in length where every mesh of the set gives its module, else in modules alone
    sized = all(_module(train, m) is not None for m, _ in pairs)
    for i, (m1, c1) in enumerate(pairs):
        for m2, c2 in pairs[i + 1:]:
            missing = {g for mesh in (m1, m2) for g in (mesh.a, mesh.b)
                       if _teeth(train, g) is None}
            if len(missing) != 1:
                continue
            g = missing.pop()
            (a1, b1), (a2, b2) = (_linear(train, m, c, g, sized) for m, c in ((m1, c1),
                                                                              (m2, c2)))
            if b1 == b2:
                continue
            teeth = (a2 - a1) / (b1 - b2)
            said = f"{_said(train, m1, c1, sized, g)} = {_said(train, m2, c2, sized, g)}"
            if teeth.denominator != 1 or teeth <= 0:
                raise InputError(f"the coaxial condition {said} gives gear {g} "
                                 f"{float(teeth):g} teeth, not a whole number of one or more: "
                                 "check the teeth and modules given", file=train.source or None)
            return g, int(teeth), said
    return None


def coaxial_misfit(train: GearTrain, coaxial: tuple[int, int] | None) -> str | None:
    """The first pair of meshes ``coaxial`` (an ordinary train's two gears on one axis)
    sets equally far apart that stand at different distances with every count known, as
    said ("4 mm·(20 + 60)/2 ≠ 5 mm·(1 + 3)/2"); None where each such pair agrees. In length
    where every mesh of the pair gives its module, else in modules alone, and then only
    where the two meshes share one module or none is given (pairs of unstated different
    modules are the book's to make good)."""
    if coaxial is None:
        return None
    for pairs in _coaxial_sets(train, coaxial):
        if train.planetary or any(_teeth(train, g) is None for mesh, _ in pairs
                                  for g in (mesh.a, mesh.b)):
            continue
        sized = all(_module(train, m) is not None for m, _ in pairs)
        if not sized and any(_module(train, m) is not None for m, _ in pairs):
            continue
        (a1, _), (a2, _) = (_linear(train, m, c, 0, sized) for m, c in pairs)
        if a1 != a2:
            return " ≠ ".join(_said(train, m, c, sized) for m, c in pairs)
    return None


def coaxial_ties(train: GearTrain) -> int:
    """How many equations among the unknown counts the coaxial condition and the centre
    distances give: one for each mesh beyond the first of a set that must stand equally far
    apart, and one for each distance given, where an unknown count stands in it."""
    unknown = set(unknown_teeth(train))
    ties = sum(len(pairs) - 1 for pairs in _coaxial_sets(train, train.coaxial)
               if unknown & {g for mesh, _ in pairs for g in (mesh.a, mesh.b)})
    ties += sum(1 for outward, ring in _chains(train)
                if unknown & {g for mesh, _ in [*outward, ring] for g in (mesh.a, mesh.b)})
    return ties + sum(1 for m in train.meshes if m.distance and unknown & {m.a, m.b})


def _linear(train: GearTrain, mesh: Mesh, far: int, unknown: int, sized: bool
            ) -> tuple[Fraction, Fraction]:
    """The mesh's centre distance m(N_far ± N_near)/2 (minus inside a ring, the ring on
    the far axis) as α + β·N of the ``unknown`` gear's count."""
    near = mesh.b if far == mesh.a else mesh.a
    m = (_module(train, mesh) if sized else None) or Fraction(1)
    sign = -1 if mesh.internal else 1
    alpha, beta = Fraction(0), Fraction(0)
    for n, k in ((far, 1), (near, sign)):
        if n == unknown:
            beta += k * m / 2
        else:
            alpha += k * m * _teeth(train, n) / 2
    return alpha, beta


def _teeth(train: GearTrain, number: int) -> int | None:
    return train.gear(number).teeth


def _module(train: GearTrain, mesh: Mesh) -> Fraction | None:
    """The mesh's own module: either gear's (they are equal), or None where neither gives
    one."""
    for g in (train.gear(mesh.a), train.gear(mesh.b)):
        if g.module is not None:
            return g.module
    return None


def _said(train: GearTrain, mesh: Mesh, far: int, sized: bool, unknown: int | None = None
          ) -> str:
    """A pair's distance as the step writes it: "(60 + 40)/2", "(N1 − 40)/2", with its
    module where the modules set the sizes: "2 mm·(60 + 40)/2"."""
    near = mesh.b if far == mesh.a else mesh.a
    sign = "−" if mesh.internal else "+"
    text = {n: f"N{n}" if n == unknown else str(train.gear(n).teeth) for n in (far, near)}
    scale = f"{train._length(_module(train, mesh))}·" if sized else ""
    return f"{scale}({text[far]} {sign} {text[near]})/2"


def teeth_from_ratio(train: GearTrain, of: tuple[int, int], value: Fraction,
                     least: int | None) -> tuple[GearTrain, tuple[Phrase, ...]]:
    """The teeth an ordinary train's speed ratio |ω_x/ω_y| = ``value`` leaves to find: one
    unknown gear, whose count enters the ratio as N or 1/N (an idler's cancels); or two, the
    smaller taking the ``least`` count (one more at a time until the other comes out whole).

    Raises
    ------
    InputError
        If the ratio cannot fix them (a planetary train, an idler, more unknowns than it
        gives, or a count that is not whole).
    """
    unknown = unknown_teeth(train)
    if not unknown:
        return train, ()
    if train.planetary:
        raise InputError("a speed ratio gives teeth in an ordinary train only: give the "
                         "planetary train's teeth", file=train.source or None)
    if len(unknown) == 1:
        g = unknown[0]
        n, said = _one_from_ratio(train, of, value, g)
        return _with(train, g, n), (said,)
    if len(unknown) != 2 or least is None:
        raise InputError(f"gears {', '.join(map(str, unknown))} have no teeth and the speed "
                         "ratio fixes one count: give the others, or least_teeth for a pair"
                         + (', or steps = "equal" to share the ratio among the pairs'
                            if len(unknown) > 2 else ""),
                         file=train.source or None)
    for small, big in (unknown, unknown[::-1]):
        for n in range(least, least + 1000):
            try:
                m, said = _one_from_ratio(_with(train, small, n), of, value, big)
            except InputError:
                continue
            if m >= n:
                return _with(_with(train, small, n), big, m), (
                    phrase("gears.teeth_least", g=small, least=least, teeth=n), said)
            break
    raise InputError(f"no whole counts of {least} teeth or more for gears {unknown[0]} and "
                     f"{unknown[1]} give the speed ratio {float(value):g}",
                     file=train.source or None)


def _with(train: GearTrain, number: int, teeth: int) -> GearTrain:
    return replace(train, gears=tuple(replace(g, teeth=teeth) if g.number == number else g
                                      for g in train.gears))


def _one_from_ratio(train: GearTrain, of: tuple[int, int], value: Fraction, g: int
                    ) -> tuple[int, Phrase]:
    """Gear ``g``'s count from |ω_x/ω_y| = ``value``: the ratio is c·N^k, k = ±1."""
    def ratio(n: int) -> Fraction:
        turns = carry(_with(train, g, n), {of[1]: Fraction(1)})
        return abs(turns[of[0]])

    c, twice = ratio(1), ratio(2)
    if c == twice:
        raise InputError(f"gear {g} is an idler of the ratio ω{of[0]}/ω{of[1]}: it cancels, "
                         "so the ratio does not fix its teeth; give them",
                         file=train.source or None)
    n = value / c if twice > c else c / value
    if n.denominator != 1 or not 1 <= n <= 100_000:
        raise InputError(f"the speed ratio ω{of[0]}/ω{of[1]} = {float(value):g} gives gear {g} "
                         f"{float(n):g} teeth, not a whole number: check the ratio and the "
                         "teeth", file=train.source or None)
    expr = f"{fraction_text(c)}·N{g}" if twice > c else f"{fraction_text(c)}/N{g}"
    return int(n), phrase("gears.teeth_ratio", x=of[0], y=of[1], value=fraction_text(value),
                          g=g, expr=expr, teeth=int(n))
