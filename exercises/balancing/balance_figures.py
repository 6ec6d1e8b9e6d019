"""A balancing solution's figures: a rotor's space diagram (its end view and, with planes
apart, its side view), its table and its force and couple polygons; an engine's four
polygons, or a single cylinder's unbalanced forces against crank angle.

Each is drawn from what the solution found (:class:`.balance_solution.BalanceSolution`), in
the words of the language being spoken.
"""

from __future__ import annotations

import math
from fractions import Fraction
from typing import TYPE_CHECKING

from tarsim.constructions.balancing.engine import engine_kinds
from tarsim.constructions.narration import numerals, unit_words, words
from tarsim.constructions.reference.balance import single_cylinder, unbalanced_resultant
from tarsim.constructions.units import LENGTH_UNITS
from tarsim.graphics.balancing.balance_figures import draw_end_view, draw_polygon, draw_side_view
from tarsim.graphics.balancing.crank_view import CrankView
from tarsim.graphics.figure import Figure
from tarsim.graphics.hiding import shown_answer
from tarsim.graphics.plot import PlotMark, Series, draw_line_plot
from tarsim.graphics.train_table import draw_train_table
from .open_rotor_solution import open_figures
from .rotor_unbalance import unbalance_figures
from .rotor_weights import GRAVITY
from .vee_engine import vee_figure
from .radial_engine import radial_figure

if TYPE_CHECKING:
    from .balance_solution import BalanceSolution

__all__ = ["balance_figures", "angle_deg"]


def angle_deg(v: tuple[float, float]) -> float:
    """A vector's angle in degrees, counter-clockwise from +x, in [0°, 360°)."""
    return math.degrees(math.atan2(v[1], v[0])) % 360.0


def balance_figures(s: BalanceSolution) -> dict[str, Figure]:
    """The space diagram, the table and the polygons (a rotor's); the polygons or the
    forces against crank angle (an engine's)."""
    ex = s.exercise
    unit, metre = ex.length_unit, LENGTH_UNITS[ex.length_unit]
    if ex.open is not None:     # and an engine's polygons, where its primary balance found it
        return open_figures(ex.name, s.closure, ex.open, unit, ex.clockwise) | (
            _engine_figures(s) if ex.engine else {})
    if ex.engine is None and s.unbalance is not None:
        return unbalance_figures(ex.name, ex.rotor, s.unbalance, unit, metre,
                                 GRAVITY if ex.weights else None, ex.clockwise)
    if ex.engine is None:
        return _rotor_figures(s, unit, metre)
    e = ex.engine
    if e.radial:
        return {"forces": radial_figure(e)}
    if e.vee:
        return {"forces": vee_figure(e)}
    if len(e.cranks) == 1:
        return {"forces": _single_cylinder_plot(e, s.cylinder_balance, unit, metre)}
    # an in-line engine's polygons, then its balance masses' where planes are given
    return _engine_figures(s) | (_rotor_figures(s, unit, metre) if ex.rotor else {})


def _engine_figures(s: BalanceSolution) -> dict[str, Figure]:
    """An in-line engine's four polygons, each closing side what is left unbalanced."""
    ex, e = s.exercise, s.exercise.engine
    out = {}
    p = s.engine_polygons
    for kind in engine_kinds(e):
        # with no speed given the polygon's own m·r (× ω²) is what is left
        left = p.left(kind) * (1.0 if e.speed is None else e.speed ** 2)
        word = ("N·m" if kind.endswith("couple") else "N") if e.speed is not None else (
            "kg·m²" if kind.endswith("couple") else "kg·m")
        reading = (words("closed: balanced"), "", "") if kind in p.balanced else (
            shown_answer(words("{size} {unit} unbalanced, greatest at θ₁ = {angle}°",
                  # four figures, and whole newtons past 9999 rather than an exponent
                  size=numerals(f"{left:.4g}" if left < 1e4 else f"{left:.0f}"),
                  unit=unit_words(word),
                  angle=numerals(f"{s.greatest_at[kind]:.1f}"))), "", "")
        # drawn to the unit its reading is given in, at a round scale of that unit: its
        # m·r (m·r·l) scale, that over ω², would be round only for a round ω²
        own = "kg·m²" if kind.endswith("couple") else "kg·m"
        drawn = dict(unit=own) if e.speed is None else dict(unit=word, per=e.speed ** 2)
        out[kind.replace(" ", "-")] = draw_polygon(
            p.construction, p.tips[kind], p.closing[kind], f"{ex.name}: {words(kind)}",
            reading=reading, **drawn,
            notes=[words("couples about the central plane; secondary vectors along the "
                         "cranks at 2θᵢ, each m·r/n")] + _drawn_notes(e, kind)
            + _speed_notes(e),
            names={str(i): words("cyl. {number}", number=numerals(str(i))) for i in
                   range(1, len(e.cranks) + 1)},
            cranks=_crank_view(p.construction, len(e.cranks), kind.startswith("primary"),
                               frozenset(q.name for q in ex.open.parts if q.angle is None)
                               if ex.open is not None else frozenset()))
    return out


def _crank_view(c, count: int, primary: bool, found: frozenset[str]) -> CrankView:
    """The end view of the cranks (at θᵢ) or of the secondary cranks (at 2θᵢ) a polygon's
    vectors are laid along: step 1's, C1ᵢ and C2ᵢ; ``found``, the cylinders whose angles
    a primary balance found."""
    order = "1" if primary else "2"
    return CrankView(
        words("end view of the cranks, at θᵢ") if primary else
        words("end view of the secondary cranks, at 2θᵢ"),
        tuple((str(i), math.atan2(c.output(f"C{order}{i}").xy[1],
                                  c.output(f"C{order}{i}").xy[0]))
              for i in range(1, count + 1)), found)


def _drawn_notes(e, kind: str) -> list[str]:
    """What a polygon drawn in newtons (newton-metres) lays off for each cylinder: its
    m·r (m·r·l) times ω², at the speed given (the lift speed's note says its own)."""
    if e.speed is None:
        return []
    product = "m·r·l" if kind.endswith("couple") else "m·r"
    if e.at_lift:
        return [words("each vector {product}·ω²", product=product)]
    return [words("each vector {product}·ω², ω = {speed} rad/s", product=product,
                  speed=numerals(f"{e.speed:.6g}"))]


def _speed_notes(e) -> list[str]:
    """The speed a polygon's reading is taken at, where the file gives none: the lift speed
    found, or none (the reading then m·r, × ω²)."""
    if e.at_lift and e.dead_load is None:
        return [words("at the speed of the greatest hammer blow allowed, ω = {speed} rad/s",
                      speed=numerals(f"{e.speed:.6g}"))]
    if e.at_lift:
        return [words("at the lift speed found, ω = {speed} rad/s",
                      speed=numerals(f"{e.speed:.6g}"))]
    return [words("no speed given: the closing side is m·r (× ω²)")] if e.speed is None else []


def _rotor_figures(s: BalanceSolution, unit: str, metre: float) -> dict[str, Figure]:
    ex, r, b = s.exercise, s.exercise.rotor, s.balance
    g = GRAVITY if ex.weights else 1.0      # a file of weights is drawn in N, as it gave them
    masses = [(m.name, m.radius, _mass_words(m.name, f"{m.mass * g:.6g}", f"{m.radius / metre:g}",
                                             unit, f"{math.degrees(m.angle):g}", ex.weights))
              for m in r.masses]
    found = []
    for p in r.planes:
        if p.name in b.none:        # no mass to draw, and a zero product has no angle
            continue
        v, mass, radius = s.placed(p)
        found.append((shown_answer(_mass_words(p.name, f"{mass * g:.4g}", f"{radius / metre:.4g}",
                                               unit, f"{angle_deg(v):.2f}", ex.weights))
                       or p.name, math.atan2(v[1], v[0]), radius))
    out = {"space": draw_end_view(b.construction, masses,
                                  words("{name}: space diagram", name=ex.name),
                                  unit, metre, found, clockwise=ex.clockwise)}
    if len(r.planes) == 2 or len({m.plane for m in r.masses}) > 1:
        planes = [(f"{m.name}", m.plane, "link") for m in r.masses]
        planes += [(p.name, p.position, "normal") for p in r.planes]
        out["side"] = draw_side_view(planes, words("{name}: side view", name=ex.name), unit,
                                     metre)
    out["table"] = _table(s, unit, metre)
    # With every mass in plane A the couple polygon is a point: steps.md says so, and
    # there is nothing to draw.
    if len(r.planes) == 2 and any(m.plane != r.planes[0].position for m in r.masses):
        bname = r.planes[1].name
        v = b.vector(b.closing[f"{bname}·l"])
        out["couple-polygon"] = draw_polygon(
            b.construction, b.couple, b.closing[f"{bname}·l"],
            words("{name}: couple polygon (reference plane {plane})", name=ex.name,
                  plane=r.planes[0].name), "kg·m²",
            ("(m r l)", bname, _none_words() if bname in b.none else shown_answer(_size_words(
                f"{math.hypot(*v):.4g}", "kg·m²", f"{angle_deg(v):.1f}"))),
            clockwise=ex.clockwise)
    a = r.planes[0].name
    v = b.product(a)
    out["force-polygon"] = draw_polygon(
        b.construction, b.force, b.closing[a], words("{name}: force polygon", name=ex.name),
        "kg·m", ("(m r)", a, _none_words() if a in b.none else shown_answer(_size_words(
            f"{math.hypot(*v):.4g}", "kg·m", f"{angle_deg(v):.1f}"))),
        clockwise=ex.clockwise)
    return out

def _table(s: BalanceSolution, unit: str, metre: float) -> Figure:
    r = s.exercise.rotor
    ref = r.planes[0].position
    two = len(r.planes) == 2
    flat = not two and len({m.plane for m in r.masses} | {ref}) == 1   # one plane: no l
    length, kg = unit_words(unit), unit_words("kg")
    g = GRAVITY if s.exercise.weights else 1.0      # weights in N, as the file gave them
    heads = [f"W ({unit_words('N')})" if s.exercise.weights else f"m ({kg})", f"r ({length})",
             "θ"] + ([] if flat else [f"l ({length})"]) + [
        f"m·r ({unit_words('kg·m')})"] + ([f"m·r·l ({unit_words('kg·m²')})"] if two else [])
    rows = []
    for m in r.masses:
        rows.append((m.name, [numerals(t) for t in [
            f"{m.mass * g:.6g}", f"{m.radius / metre:g}", f"{math.degrees(m.angle):g}°"]
            + ([] if flat else [f"{(m.plane - ref) / metre:g}"])
            + [f"{m.mass * m.radius:.4g}"] + (
            [f"{m.mass * m.radius * (m.plane - ref):.4g}"] if two else [])]))
    none = [p for p in r.planes if p.name in s.balance.none]
    for p in r.planes:
        v, mass, radius = s.placed(p)
        size = math.hypot(*v)
        if p in none:       # the given mass or radius stands, the rest is nothing found
            cells = [f"{mass * g:.4g}" if p.mass else "—",
                     f"{radius / metre:.4g}" if p.radius else "—", "—"]
        else:               # the given mass or radius stands, the rest was found
            cells = [f"{mass * g:.4g}" if p.mass else shown_answer(f"{mass * g:.4g}"),
                     f"{radius / metre:.4g}" if p.radius else shown_answer(
                         f"{radius / metre:.4g}"), shown_answer(f"{angle_deg(v):.2f}°")]
        rows.append((p.name, [numerals(t) for t in cells
                              + ([] if flat else [f"{(p.position - ref) / metre:g}"])
                              + [shown_answer(f"{size:.4g}")]
                              + ([shown_answer(f"{size * (p.position - ref):.4g}")]
                                 if two else [])]))
    notes = [("" if flat else words("l from the reference plane {plane}; ",
                                    plane=r.planes[0].name))
             + words("the rows under the rule are the balancing masses found")]
    if s.exercise.weights:
        notes.append(words("m = W/g, g = {g} m/s²", g=numerals(f"{GRAVITY:g}")))
    notes += [words("plane {plane} needs no balancing mass: its polygon closes on itself",
                    plane=p.name) for p in none]
    return draw_train_table(words("{name}: the table", name=s.exercise.name), heads, rows,
                            ruled=[len(r.masses)], notes=notes)

def _single_cylinder_plot(e, held, unit: str, metre: float) -> Figure:
    """The forces against crank angle; ``held``, the balance mass's product, mass and
    radius where the file asks it, is named under the title."""
    xs = [float(d) for d in range(0, 361, 2)]
    values = [single_cylinder(e, math.radians(d)) for d in xs]
    series = [Series(words("primary"), tuple((x, v[0]) for x, v in zip(xs, values)),
                     "plot_curve_dotted")]
    if e.rod is not None:       # no rod given: no secondary force asked
        series.append(Series(words("secondary"), tuple((x, v[1]) for x, v in zip(xs, values)),
                             "plot_curve_dashed"))
    series += [Series(words("left along the stroke"),
                      tuple((x, v[2]) for x, v in zip(xs, values))),
               Series(words("left across the stroke"),
                      tuple((x, v[3]) for x, v in zip(xs, values)), "plot_curve_dash_dot"),
               Series(words("resultant left"), tuple(
                   (x, unbalanced_resultant(e, math.radians(x))) for x in xs),
                   "plot_curve_grey")]
    at = math.degrees(e.at)
    here = single_cylinder(e, e.at)
    whole = unbalanced_resultant(e, e.at)
    newton = unit_words("N")
    marks = [PlotMark(at, here[2], f"{numerals(f'{here[2]:.4g}')} {newton}"),
             PlotMark(at, here[3], f"{numerals(f'{here[3]:.4g}')} {newton}"),
             PlotMark(at, whole, f"{numerals(f'{whole:.4g}')} {newton}")]
    share = Fraction(e.balanced).limit_denominator(12)
    share = share if abs(float(share) - e.balanced) < 1e-9 else f"{e.balanced:g}"
    return draw_line_plot(words("Unbalanced forces"), words("crank angle θ (°)"),
                          f"F ({newton})", series, marks, x_range=(0.0, 360.0),
                          x_ticks=[(float(d), numerals(f"{d}")) for d in range(0, 361, 30)],
                          subtitle=words("{share} of the reciprocating mass balanced by a "
                                         "rotating mass opposite the crank",
                                         share=numerals(str(share))) if held is None else
                          words("{mass} {kg} at {radius} {unit} opposite the crank balances "
                                "{share} of m_rec and all of m_rev",
                                share=numerals(str(share)), mass=numerals(f"{held[1]:.4g}"),
                                kg=unit_words("kg"), radius=numerals(f"{held[2] / metre:.4g}"),
                                unit=unit_words(unit)),
                          mark_legend=words("at θ = {angle}°", angle=numerals(f"{at:g}")))


def _mass_words(name: str, mass: str, radius: str, unit: str, angle: str,
                weight: bool = False) -> str:
    """A mass as the end view names it, "A: 200 kg at 300 mm, 45°" (its weight, "60 N",
    where the file gives weights), in the language being spoken (the numbers come
    formatted)."""
    return words("{name}: {mass} {kg} at {radius} {unit}, {angle}°", name=name,
                 mass=numerals(mass), kg=unit_words("N" if weight else "kg"),
                 radius=numerals(radius),
                 unit=unit_words(unit), angle=numerals(angle))


def _none_words() -> str:
    """What follows a closing side's symbol when its polygon closes on itself."""
    return words(" = 0: no mass needed")


def _size_words(size: str, unit: str, angle: str) -> str:
    """What follows a closing side's symbol: " = 1.39 kg·m at 3.9°"."""
    return words(" = {size} {unit} at {angle}°", size=numerals(size), unit=unit_words(unit),
                 angle=numerals(angle))
