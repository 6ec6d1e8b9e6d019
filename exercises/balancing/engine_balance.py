"""What an in-line engine's balance masses leave, and what they add, as the books ask it of
a locomotive: the primary force and couple left along the line of stroke, and the hammer
blow.

With the fraction c of each cylinder's reciprocating mass m balanced by rotating masses,
(1 − c)·m is left reciprocating: the primary force along the stroke is at most (1 − c) times
the whole engine's, (1 − c)·m·ω²·r·|Σ e^{iθᵢ}| (a locomotive's variation of tractive force,
±√2·(1 − c)·m·ω²·r for cranks at 90°), and the primary couple (1 − c) times its whole
(the swaying couple, ±(a/√2)·(1 − c)·m·ω²·r). The balance masses' share for c·m turns with
the wheels and presses on the rails across the stroke: the hammer blow, B·ω²·b with B·b
that share of each plane's balancing product. Every cylinder counts the same m_rev + c·m,
so the share is c·m/(m_rev + c·m) of the product drawn; the reference balances c·m alone.
"""

from __future__ import annotations

import math

from tarsim.constructions.narration import numeral, words
from tarsim.constructions.reference.balance import engine_sums, two_planes
from tarsim.constructions.balancing.polygons import draw_balance
from tarsim.constructions.balancing.rotor import Mass, Rotor
from ..checked import Checked

__all__ = ["left_checked", "left_lines", "left_misses", "lift_speed"]


def _share(e) -> float:
    """The reciprocating part of each cylinder's balanced mass, c·m/(m_rev + c·m) (c the
    share of one pair of coupled wheels)."""
    c = e.balanced_each
    return c * e.reciprocating / (e.revolving + c * e.reciprocating)


def _blows(s) -> dict[str, tuple[float, float]]:
    """Each balancing plane's hammer blow (N): as drawn, and by the reference's two planes
    of c·m alone (one plane: its force alone)."""
    w2 = s.exercise.engine.speed ** 2
    return {name: (got * w2, want * w2) for name, (got, want) in _products(s).items()}


def _products(s) -> dict[str, tuple[float, float]]:
    """Each balancing plane's B·b (kg·m), the share of its product for c·m, free of ω: as
    drawn, and by the reference's two planes of c·m alone (one plane: its force alone).
    Where other revolving masses (coupling rods) share the wheels, the product is no
    multiple of c·m's, and c·m's own polygons are drawn for it."""
    e, r = s.exercise.engine, s.exercise.rotor
    alone = [Mass(str(i), e.balanced_each * e.reciprocating, e.crank, theta, z)
             for i, (theta, z) in enumerate(zip(e.cranks, e.planes), start=1)]
    if len(r.planes) == 2:
        want = dict(zip((p.name for p in r.planes),
                        two_planes(alone, r.planes[0].position, r.planes[1].position)))
    else:
        want = {r.planes[0].name: (-math.fsum(m.mr[0] for m in alone),
                                   -math.fsum(m.mr[1] for m in alone))}
    if len(r.masses) == len(alone):     # the cylinders alone: c·m's share of the product
        drawn = {p.name: _share(e) * math.hypot(*s.balance.product(p.name)) for p in r.planes}
    else:
        b = draw_balance(Rotor(tuple(alone), r.planes, e.speed))
        drawn = {p.name: math.hypot(*b.product(p.name)) for p in r.planes}
    return {p.name: (drawn[p.name], math.hypot(*want[p.name])) for p in r.planes}


def left_checked(s) -> dict[str, Checked]:
    """results.json's ``primary_force_left``, ``primary_couple_left`` and each plane's
    ``hammer_blow_A``, where an in-line engine balances a fraction of its reciprocating
    mass (none where it balances only revolving masses)."""
    e = s.exercise.engine
    if not e.balanced > 0 or e.speed is None:       # each is m·r·ω²: none with no speed
        return {}
    sums = engine_sums(e)
    left = 1.0 - e.balanced
    w2 = e.speed ** 2
    q = {}
    for kind, whole in (("primary force", sums.primary_force),
                        ("primary couple", sums.primary_couple)):
        q[f"{kind.replace(' ', '_')}_left"] = Checked(
            {"value": left * s.engine_polygons.left(kind) * w2,
             "unit": "N·m" if kind.endswith("couple") else "N"},
            {"value": left * whole}, method=f"{kind} polygon, (1 − c) of it")
    for name, (got, want) in _blows(s).items():
        q[f"hammer_blow_{name}"] = Checked({"value": got, "unit": "N"}, {"value": want},
                                           method="couple and force polygons, c·m's share")
    return q | _lift_checked(s)


def _lift(s) -> tuple[float, float] | None:
    """The speed (rad/s) at which the greatest hammer blow equals the dead load on a wheel,
    or the greatest blow allowed, ω = √(P/(B·b)): as drawn, and by the reference's B·b
    (None with no load given)."""
    load = s.exercise.engine.speed_load
    if load is None:
        return None
    got, want = (max(v[i] for v in _products(s).values()) for i in (0, 1))
    return math.sqrt(load / got), math.sqrt(load / want)


def lift_speed(s) -> float | None:
    """The lift speed as drawn (rad/s), where the file gives a dead load on the wheels: a
    locomotive with no speed given has its forces and couples asked at it."""
    lift = _lift(s)
    return None if lift is None else lift[0]


def _lift_checked(s) -> dict[str, Checked]:
    """``lift_speed`` (rad/s) and, on wheels of a given diameter, ``lift_road_speed``
    (km/h, v = ω·D/2); ``speed_at_hammer_blow`` and ``road_speed_at_hammer_blow`` where the
    load is the greatest hammer blow allowed, not a dead load."""
    lift, e = _lift(s), s.exercise.engine
    if lift is None:
        return {}
    blow = e.dead_load is None
    method = f"√({'hammer blow allowed' if blow else 'dead load'} / the greatest B·b of c·m)"
    speed, road = ("speed_at_hammer_blow", "road_speed_at_hammer_blow") if blow else \
        ("lift_speed", "lift_road_speed")
    q = {speed: Checked({"value": lift[0], "unit": "rad/s"}, {"value": lift[1]},
                        method=method)}
    if e.wheel is not None:
        q[road] = Checked({"value": lift[0] * e.wheel / 2 * 3.6, "unit": "km/h"},
                          {"value": lift[1] * e.wheel / 2 * 3.6}, method=method)
    return q


def left_lines(s) -> list[str]:
    """The lines that say what the balance masses leave and add."""
    e = s.exercise.engine
    if not e.balanced > 0:
        return []
    left = 1.0 - e.balanced
    if e.speed is None:
        return [words("with {share} of the reciprocating mass balanced, {left} of it is left; "
                      "no speed is given, so the variation of tractive force, the swaying "
                      "couple and the hammer blow (each m·r·ω²) are left out: give speed = … "
                      "or road_speed = … for them", share=numeral(e.balanced, "g"),
                      left=numeral(left, "g"))]
    w2 = e.speed ** 2
    p = s.engine_polygons
    out = [words("with {share} of the reciprocating mass balanced, {left} of it is left: the "
                 "primary force along the stroke at most {force} N (a locomotive's variation "
                 "of tractive force, ±) and the primary couple {couple} N·m (its swaying "
                 "couple, ±)", share=numeral(e.balanced, "g"), left=numeral(left, "g"),
                 force=numeral(left * p.left("primary force") * w2),
                 couple=numeral(left * p.left("primary couple") * w2))]
    for name, (blow, _) in _blows(s).items():
        out.append(words("hammer blow in plane {plane}: the balance mass's share for the "
                         "reciprocating mass turning, B·ω²·b = {blow} N", plane=name,
                         blow=numeral(blow)))
    lift = _lift(s)
    if lift is not None:
        road = words(", {road} km/h on the wheels", road=numeral(lift[0] * e.wheel / 2 * 3.6)) \
            if e.wheel is not None else ""
        if e.dead_load is not None:
            out.append(words("the wheel lifts off the rail where the hammer blow reaches the "
                             "dead load of {load} N: at ω = {speed} rad/s",
                             load=numeral(e.dead_load), speed=numeral(lift[0])) + road)
        else:
            out.append(words("the hammer blow reaches the greatest allowed, {load} N, at ω = "
                             "{speed} rad/s", load=numeral(e.hammer_blow),
                             speed=numeral(lift[0])) + road + words(": the greatest speed"))
    return out


def left_misses(s, agree: float) -> list[tuple[str, float]]:
    """Each hammer blow's B·b drawn against the reference's, relative to the engine's whole
    primary m·r·N (the size its products round at); free of ω, so checked with no speed."""
    e = s.exercise.engine
    if s.exercise.rotor is None or not e.balanced > 0:
        return []
    size = e.reciprocating * e.crank * len(e.cranks)
    return [(f"hammer blow {name}", abs(got - want) / size)
            for name, (got, want) in _products(s).items() if abs(got - want) > agree * size]
