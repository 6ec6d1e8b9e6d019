"""A single-cylinder engine: its primary and secondary forces at a crank angle, what a
rotating balance mass opposite the crank leaves along and across the stroke, and the
balance mass itself (B·b = (m_rev + c·m)·r), as printed and as results.json gives them."""

from __future__ import annotations

import math

from tarsim.constructions.narration import numeral, words
from tarsim.constructions.reference.balance import (balance_product, single_cylinder,
                                                    unbalanced_resultant)
from ..checked import Checked

__all__ = ["cylinder_balance", "cylinder_checked", "cylinder_lines"]


def cylinder_lines(e, length) -> list[str]:
    """A single cylinder's forces at its crank angle, what its balance mass leaves, and
    the balance mass itself; ``length(v)`` writes a length in the file's unit."""
    prim, sec, along, across = single_cylinder(e, e.at)
    f = e.reciprocating * e.speed ** 2 * e.crank
    angle = numeral(math.degrees(e.at), "g")
    out = [words("at θ = {angle}°: primary force {primary} N, secondary {secondary} N "
                 "along the line of stroke (n = l/r = {n})", angle=angle,
                 primary=numeral(prim), secondary=numeral(sec),
                 n=numeral(e.rod / e.crank)) if e.rod is not None else
           words("at θ = {angle}°: primary force {primary} N along the line of stroke (no "
                 "rod given: no secondary force)", angle=angle, primary=numeral(prim)),
           words("with {share} of the reciprocating mass balanced by a rotating mass: "
                 "{along} N along the line of stroke and {across} N across it",
                 share=numeral(e.balanced, "g"), along=numeral(along),
                 across=numeral(across)),
           words("the unbalanced primary force's resultant: {size} N at θ = {angle}°, at "
                 "most {most} N", size=numeral(math.hypot(along, across)), angle=angle,
                 most=numeral(max(1 - e.balanced, e.balanced) * f)),
           words("at most {along} N along (θ = 0°, 180°) and {across} N across "
                 "(θ = 90°, 270°)", along=numeral((1 - e.balanced) * f),
                 across=numeral(e.balanced * f))]
    if e.rod is not None:
        out.append(words("the greatest secondary force: {most} N, at θ = 0°, 90°, 180° "
                         "and 270°", most=numeral(f / (e.rod / e.crank))))
    held = cylinder_balance(e)
    if held is not None:
        product, mass, radius = held
        out.append(words("the balance mass opposite the crank: B·b = (m_rev + c·m)·r = "
                         "{product} kg·m, so {mass} kg at {radius}",
                         product=numeral(product), mass=numeral(mass),
                         radius=length(radius)))
    return out


def cylinder_balance(e) -> tuple[float, float, float] | None:
    """A single cylinder's balance mass: its product (kg·m), mass (kg) and radius (m),
    where the file gives its radius or its mass (None where it gives neither)."""
    product = balance_product(e)
    if e.balance_radius is not None:
        return product, product / e.balance_radius, e.balance_radius
    if e.balance_mass is not None:
        return product, e.balance_mass, product / e.balance_mass
    return None


def cylinder_checked(e) -> dict[str, Checked]:
    """A single cylinder's forces at its crank angle (the secondary only with a rod), the
    resultant left unbalanced (the vector sum of its components, beside the closed form
    m·ω²·r·√((1 − c)² cos² θ + c² sin² θ)) and its greatest, and the balance mass."""
    prim, sec, along, across = single_cylinder(e, e.at)
    f = e.reciprocating * e.speed ** 2 * e.crank
    rows = [("primary_force", prim)] + ([("secondary_force", sec)] if sec is not None
                                        else []) + [
        ("unbalanced_along", along), ("unbalanced_across", across)]
    q = {name: Checked({"value": v}) for name, v in rows}
    q["unbalanced_resultant"] = Checked(
        {"value": math.hypot(along, across), "unit": "N",
         "from_stroke_deg": math.degrees(math.atan2(across, along)) % 360.0},
        {"value": unbalanced_resultant(e, e.at)}, method="components along and across")
    # The greatest over a turn: (1 − c)·m·ω²·r at dead centre, or c·m·ω²·r across.
    c = e.balanced
    at = [0.0, 180.0] if 1 - c >= c else [90.0, 270.0]
    q["unbalanced_max"] = Checked({"value": max(1 - c, c) * f, "unit": "N", "at_deg": at})
    q["unbalanced_max_at"] = Checked({"value": at[0], "unit": "deg", "every_deg": 180.0})
    if e.rod is not None:   # m·ω²·r/n where cos 2θ = ±1
        q["secondary_max"] = Checked({"value": f / (e.rod / e.crank), "unit": "N",
                                      "at_deg": [0.0, 90.0, 180.0, 270.0]})
    if balance_product(e) > 0:
        q["balance_mr"] = Checked({"value": balance_product(e), "unit": "kg·m"})
    held = cylinder_balance(e)
    if held is not None:
        product, mass, radius = held
        key, value = ("balance_mass", {"value": mass, "unit": "kg", "radius": radius}) \
            if e.balance_radius is not None else (
            "balance_radius", {"value": radius, "unit": "m", "mass": mass})
        q[key] = Checked({**value, "angle_deg": 180.0})      # opposite the crank
    return q
