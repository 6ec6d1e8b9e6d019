"""A rotor with no balancing plane: its out-of-balance force and couple, read off the force
and couple polygons' closing sides (:mod:`tarsim.constructions.balancing.unbalance`),
beside the vector sums (:mod:`tarsim.constructions.reference.balance`)."""

from __future__ import annotations

import math

from tarsim.constructions.balancing.unbalance import Unbalance, draw_unbalance
from tarsim.constructions.narration import numeral, numerals, unit_words, words
from tarsim.constructions.reference.balance import resultant
from tarsim.graphics.balancing.balance_figures import draw_end_view, draw_polygon, draw_side_view
from tarsim.graphics.figure import Figure
from ..checked import Checked

__all__ = ["about", "unbalance", "unbalance_checked", "unbalance_figures", "unbalance_lines",
           "unbalance_misses"]

AGREE = 1e-12
"""How near (relative to the sizes summed) a closing side must come to its sum."""


def about(r) -> float:
    """The plane couples are taken about: the file's ``about``, else the central plane,
    midway between the outermost masses."""
    planes = [m.plane for m in r.masses]
    return r.about if r.about is not None else (min(planes) + max(planes)) / 2


def unbalance(r) -> Unbalance:
    """The rotor's polygons, drawn."""
    return draw_unbalance(r, about(r))


def _sums(r) -> dict[str, tuple[float, float]]:
    """Σ mᵢrᵢ and Σ mᵢrᵢlᵢ (about the reference plane) by the closed form."""
    z = about(r)
    return {"force": resultant(r.masses),
            "couple": (math.fsum(m.mr[0] * (m.plane - z) for m in r.masses),
                       math.fsum(m.mr[1] * (m.plane - z) for m in r.masses))}


def _sizes(r) -> dict[str, float]:
    z = about(r)
    return {"force": math.fsum(m.mass * m.radius for m in r.masses),
            "couple": math.fsum(m.mass * m.radius * (abs(m.plane) + abs(z)) for m in r.masses)}


def unbalance_checked(r, u: Unbalance) -> dict[str, Checked]:
    """``unbalanced_force`` (N) and, with planes apart, ``unbalanced_couple`` (N·m), each with
    the resultant's angle, beside the sums."""
    w2 = r.speed ** 2
    want = _sums(r)
    q = {}
    for which in u.closing:
        v = u.resultant(which)
        angle = {} if which in u.shut else {
            "angle_deg": math.degrees(math.atan2(v[1], v[0])) % 360.0}
        q[f"unbalanced_{which}"] = Checked(
            {"value": math.hypot(*v) * w2, "unit": "N" if which == "force" else "N·m",
             **angle, **({"about": u.about} if which == "couple" else {})},
            {"value": math.hypot(*want[which]) * w2}, method=f"{which} polygon's closing side")
    return q


def unbalance_misses(r, u: Unbalance) -> list[tuple[str, float]]:
    """Each resultant drawn against its sum, relative to the sizes summed."""
    want, sizes = _sums(r), _sizes(r)
    out = []
    for which in u.closing:
        miss = math.dist(u.resultant(which), want[which]) / sizes[which]
        if miss > AGREE:
            out.append((f"the out-of-balance {which}", miss))
    return out


def unbalance_lines(r, u: Unbalance, length) -> list[str]:
    """The force and couple left, and where the couple is taken about."""
    w2 = r.speed ** 2
    out = []
    for which in u.closing:
        v = u.resultant(which)
        if which in u.shut:
            out.append(words("no out-of-balance {which}: its polygon closes on itself",
                             which=words(which)))
            continue
        out.append(words("out of balance: the {which} {size} {unit} at {angle}° ({product} "
                         "{units} × ω², ω = {speed} rad/s)", which=words(which),
                         size=numeral(math.hypot(*v) * w2),
                         unit="N" if which == "force" else "N·m",
                         angle=numeral(math.degrees(math.atan2(v[1], v[0])) % 360.0, ".2f"),
                         product=numeral(math.hypot(*v)),
                         units="kg·m" if which == "force" else "kg·m²",
                         speed=numeral(r.speed)))
    if "couple" in u.closing:
        out.append(words("couples about the plane at {place}", place=length(u.about)))
    return out


def unbalance_figures(name: str, r, u: Unbalance, unit: str, metre: float,
                      g: float | None = None, clockwise: bool = False) -> dict[str, Figure]:
    """The end view, the side view (planes apart) and the polygons; ``g`` where the file
    gives weights, each then named in N as it was given; ``clockwise`` where its angles
    are."""
    masses = [(m.name, m.radius, words("{name}: {mass} {kg} at {radius} {unit}, {angle}°",
                                       name=m.name, mass=numerals(f"{m.mass * (g or 1):.6g}"),
                                       kg=unit_words("N" if g else "kg"),
                                       radius=numerals(f"{m.radius / metre:g}"),
                                       unit=unit_words(unit),
                                       angle=numerals(f"{math.degrees(m.angle):g}")))
              for m in r.masses]
    out = {"space": draw_end_view(u.construction, masses,
                                  words("{name}: space diagram", name=name), unit, metre, [],
                                  clockwise=clockwise)}
    if "couple" in u.closing:
        out["side"] = draw_side_view([(m.name, m.plane, "link") for m in r.masses],
                                     words("{name}: side view", name=name), unit, metre)
    for which in u.closing:
        if which in u.shut:
            continue
        v = u.resultant(which)
        per = "kg·m" if which == "force" else "kg·m²"
        back = (math.degrees(math.atan2(v[1], v[0])) + 180.0) % 360.0    # the side is −R
        out[f"{which}-polygon"] = draw_polygon(
            u.construction, u.tips[which], u.closing[which],
            words("{name}: force polygon", name=name) if which == "force" else
            words("{name}: couple polygon about the plane at {place} {unit}", name=name,
                  place=numerals(f"{u.about / metre:g}"), unit=unit_words(unit)),
            per, ("−R", "", words(" = {size} {unit} at {angle}°",
                                  size=numerals(f"{math.hypot(*v):.4g}"),
                                  unit=unit_words(per),
                                  angle=numerals(f"{back:.1f}"))), clockwise=clockwise)
    return out
