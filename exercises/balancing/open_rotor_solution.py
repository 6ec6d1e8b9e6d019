"""A rotor that balances itself, its unknowns read off the polygons: what is printed, what
results.json gives, the checks and the figures.

Each unknown read off the drawing is set beside the reference's algebra
(:func:`~tarsim.constructions.reference.balance.open_rotor_roots`, the same polygons closed
by Cramer's rule, the law of cosines or a quadratic, every real root), and the rotor with
its unknowns filled in must leave no force and no couple
(:func:`~tarsim.constructions.reference.balance.open_residual`).
"""

from __future__ import annotations

import math

from tarsim.constructions.balancing.unknowns import SHIFT, Closure, OpenRotor, growth
from tarsim.constructions.narration import numeral, numerals, unit_words, words
from tarsim.constructions.reference.balance import open_residual, open_rotor_roots
from tarsim.constructions.units import LENGTH_UNITS
from tarsim.graphics.balancing.balance_figures import draw_end_view, draw_polygon, draw_side_view
from tarsim.graphics.figure import Figure
from tarsim.graphics.hiding import shown_answer
from ..checked import Checked

__all__ = ["open_checked", "open_figures", "open_lines", "open_misses", "tolerance"]

AGREE = 1e-9
"""How near (relative to the sizes summed) the drawn unknowns must come to the algebra's,
and the balanced rotor to no force and couple, where the carriers cross well."""


def tolerance(closure: Closure) -> float:
    """What a found unknown may miss the algebra by, relative: :data:`AGREE`, and what the
    crossings let rounding move it (:func:`~tarsim.constructions.balancing.unknowns.growth`)."""
    return AGREE + SHIFT * growth(closure)


_FIELDS = ("mass", "radius", "angle", "plane")


def _scales(closure: Closure) -> tuple[float, float]:
    """Σ|mᵢrᵢ| (kg·m) and Σ|mᵢrᵢ|·|lᵢ| + the same at the reference (kg·m²)."""
    z = abs(closure.reference[1]) if closure.reference else 0.0
    ps = closure.parts.values()
    return (math.fsum(p.mass * p.radius for p in ps),
            math.fsum(p.mass * p.radius * (abs(p.plane) + z) for p in ps))


def _roots(closure: Closure) -> list[dict]:
    """The reference's roots, the one nearest the drawing first."""
    z = closure.reference[1] if closure.reference else 0.0
    roots = open_rotor_roots(tuple(closure.given.values()), closure.order, z)

    def gap(root) -> float:
        return sum(abs(math.remainder(root[n][2] - p.angle, 2 * math.pi)) + abs(
            root[n][0] * root[n][1] - p.mass * p.radius) for n, p in closure.parts.items())

    def refused(root) -> bool:       # a root some mass's between does not admit goes last
        return not all(p.admits(root[n][2]) for n, p in closure.given.items())
    return sorted(roots, key=lambda root: (refused(root), gap(root)))


def _root(closure: Closure) -> dict | None:
    """The reference's root nearest the drawing (None if it has none)."""
    roots = _roots(closure)
    return roots[0] if roots else None


def open_misses(closure: Closure, rotor: OpenRotor) -> list[tuple[str, float]]:
    """What disagrees: each unknown against the algebra's, and the balanced rotor."""
    force, couple = _scales(closure)
    tol = tolerance(closure)
    out = []
    root = _root(closure)
    if root is None:
        return [("the reference's roots", math.inf)]
    for name, p in closure.given.items():
        if not p.unknowns():
            continue
        got, (m, r, a, z) = closure.parts[name], root[name]
        # each mass's vector m·r·e^{iθ} (its mass, radius and angle at once), and its
        # couple's arm, against the sizes they were summed with
        u = got.mass * got.radius * complex(math.cos(got.angle), math.sin(got.angle))
        w = m * r * complex(math.cos(a), math.sin(a))
        miss = abs(u - w) / force
        if p.plane is None:
            miss = max(miss, abs(got.plane - z) * got.mass * got.radius / couple)
        if miss > tol:
            out.append((f"mass {name}", miss))
    f, c = open_residual(tuple(closure.parts.values()))
    miss = max(f / force, 0.0 if rotor.static else c / couple)
    if miss > AGREE:
        out.append(("the balanced rotor", miss))
    return out


def _value(key: str, v: float) -> float:
    return math.degrees(v) % 360.0 if key == "angle" else v


def open_checked(closure: Closure) -> dict[str, Checked]:
    """Each unknown as results.json gives it, in SI (an angle in degrees), beside the
    reference's root: ``mass_1``, ``radius_1``, ``angle_1``, ``plane_1``."""
    roots = _roots(closure)
    root = roots[0] if roots else {}
    # The other crossing's answer, where the polygons close twice: a mirror image that
    # balances the rotor as well (the books draw one of the two).
    other = roots[1] if len(roots) > 1 and closure.mirrored else None
    method = " and ".join(f"{w} polygon" for w in closure.order)
    q = {}
    for name, p in closure.given.items():
        for i, key in enumerate(_FIELDS):
            if getattr(p, key) is None:
                got = _value(key, getattr(closure.parts[name], key))
                ref = {"value": _value(key, root[name][i])} if name in root else None
                unit = {"mass": "kg", "radius": "m", "angle": "deg", "plane": "m"}[key]
                beside = {"mirror": _value(key, other[name][i])} if other else {}
                q[f"{key}_{name}"] = Checked({"value": got, "unit": unit}, ref, method=method,
                                             beside=beside)
    return q


def open_lines(closure: Closure, rotor: OpenRotor, length_unit: str, passed: bool,
               failures: list[str]) -> list[str]:
    """What is found, mass by mass, and the check."""
    metre = LENGTH_UNITS[length_unit]
    out = []
    for name, p in closure.given.items():
        got = closure.parts[name]
        said = []
        for key in _FIELDS:
            if getattr(p, key) is None:
                v = getattr(got, key)
                said.append({"mass": f"m = {numeral(v)} kg",
                             "radius": f"r = {numeral(v / metre)} {length_unit}",
                             "angle": f"θ = {numeral(math.degrees(v) % 360.0, '.2f')}°",
                             "plane": f"l = {numeral(v / metre)} {length_unit}"}[key])
        if said:
            out.append(words("mass {name}: {found}", name=name, found=", ".join(said)))
    if closure.mirrored:
        out.append(words("two crossings close the {polygon} polygon: the other, the mirror "
                         "image, balances the rotor too", polygon=words(closure.mirrored[0])))
        out.append(_choice(closure, closure.mirrored[0]))
        roots = _roots(closure)
        if len(roots) > 1:
            out.append(words("the mirror image: {found}", found=", ".join(
                f"θ_{n} = {numeral(math.degrees(roots[1][n][2]) % 360.0, '.2f')}°"
                for n, p in closure.given.items() if p.angle is None)))
    verdict = words("each where the algebra puts it") if passed else \
        f"OFF: {', '.join(failures)}"
    f, c = open_residual(tuple(closure.parts.values()))
    out.append(words("polygons closed: {verdict}; the balanced rotor's residual force "
                     "{residual} kg·m", verdict=verdict, residual=numeral(f, ".1e")))
    return out


def _choice(closure: Closure, which: str) -> str:
    """Which of the two crossings was taken, and why: a mass's ``between``, or the rule."""
    name = closure.chosen.get(which)
    if name is not None:
        lo, hi = (numeral(math.degrees(a) % 360.0, "g") for a in closure.given[name].between)
        return words("taken: mass {name}'s angle between {lo}° and {hi}°, as its between "
                     "asks", name=name, lo=lo, hi=hi)
    tag = "fp" if which == "force" else "cp"
    if closure.construction[f"{tag}:x"].verb == "intersect_circles":
        return words("taken: the crossing left of the last tip → the pole; between = [from, "
                     "to] on a mass with an unknown angle takes the other")
    return words("taken: the first crossing along the line from the last tip; between = "
                 "[from, to] on a mass with an unknown angle takes the other")


def open_figures(name: str, closure: Closure, rotor: OpenRotor,
                 length_unit: str, clockwise: bool = False) -> dict[str, Figure]:
    """The end view (the found masses dashed), the side view, and the polygons (their
    angles ``clockwise`` where the file's are)."""
    metre = LENGTH_UNITS[length_unit]
    unit = length_unit
    c = closure.construction
    known = [(p.name, closure.parts[p.name].radius, _label(closure.parts[p.name], unit, metre))
             for p in closure.given.values() if p.angle is not None and p.size is not None]
    found = [(_label(closure.parts[p.name], unit, metre, p.unknowns()),
              closure.parts[p.name].angle, closure.parts[p.name].radius)
             for p in closure.given.values() if p.angle is None or p.size is None]
    out = {"space": draw_end_view(c, known, words("{name}: space diagram", name=name), unit,
                                  metre, found, found_word="a mass with unknowns, found",
                                  clockwise=clockwise)}
    if not rotor.static:
        planes = [(p.name, p.plane, "link" if closure.given[p.name].plane is not None
                   else "normal") for p in closure.parts.values()]
        out["side"] = draw_side_view(planes, words("{name}: side view", name=name), unit,
                                     metre, found="a plane found")
    for which in closure.order:
        tips = closure.force if which == "force" else closure.couple
        title = words("{name}: force polygon", name=name) if which == "force" else words(
            "{name}: couple polygon (reference plane {plane})", name=name,
            plane=closure.reference[0])
        out[f"{which}-polygon"] = draw_polygon(
            c, tips, closure.closing[which], title, "kg·m" if which == "force" else "kg·m²",
            (closure.last[which], "", words(": found")), clockwise=clockwise)
    return out


def _label(p, unit: str, metre: float, found: tuple[str, ...] = ()) -> str:
    """A mass as the end view names it; what was ``found`` of it ("mass", "angle"…) is
    left blank where the answers are hidden."""
    def told(what: str, text: str) -> str:
        return shown_answer(text, "…") if what in found else text
    return words("{name}: {mass} {kg} at {radius} {unit}, {angle}°", name=p.name,
                 mass=told("mass", numerals(f"{p.mass:.4g}")), kg=unit_words("kg"),
                 radius=told("radius", numerals(f"{p.radius / metre:.4g}")),
                 unit=unit_words(unit),
                 angle=told("angle", numerals(f"{math.degrees(p.angle) % 360.0:.4g}")))
