"""A balancing exercise solved: a rotor by the force (and couple) polygon, or an engine's
unbalanced forces and couples, every closing side checked against the vector sums.

A rotor's balancing products, drawn as the polygons' closing sides, are checked against the
closed form (:mod:`..constructions.reference.balance`), and the balanced rotor's residual
force and couple (its masses and the balancing masses summed) must vanish to a few
roundings of the largest product. An engine's four polygons are checked the same way, each
closing side against the sum of its cylinders' vectors.
"""

from __future__ import annotations

import math
from fractions import Fraction
from dataclasses import dataclass
from functools import cached_property
from typing import Any

from tarsim.constructions.balancing.engine import KINDS, EnginePolygons, draw_engine
from tarsim.constructions.balancing.polygons import Balance, draw_balance, rounding
from tarsim.constructions.units import LENGTH_UNITS
from tarsim.constructions.narration import numeral, numerals, phrase, unit_words, words
from tarsim.constructions.reference.balance import (engine_sums, one_axial_plane, quadrant_angle,
                                                    resultant, single_cylinder, two_planes)
from tarsim.graphics.balancing.balance_figures import draw_end_view, draw_polygon, draw_side_view
from tarsim.graphics.plot import PlotMark, Series, draw_line_plot
from tarsim.graphics.train_table import draw_train_table
from ..checked import Checked
from ..solution_folder import ChapterFiles
from ..worked_document import Bullets, Section, said_steps, title
from .rotor_file import BalanceExercise

__all__ = ["BalanceSolution", "solve_balance"]

AGREE = 1e-12
"""How near (relative to the sizes of the vectors summed, :meth:`BalanceSolution.scales`) a
closing side must come to its sum: a few roundings of the vectors laid off, for up to a
thousand of them."""


def _angle(v: tuple[float, float]) -> float:
    return math.degrees(math.atan2(v[1], v[0])) % 360.0


def _quiet(x: float, noise: float) -> float:
    """``x``, or 0 where it is no more than the rounding ``noise`` of the sum it came from."""
    return 0.0 if abs(x) <= noise else x


@dataclass(frozen=True)
class BalanceSolution(ChapterFiles):
    """A solved balancing exercise (see :func:`solve_balance`)."""

    exercise: BalanceExercise

    # ----- a rotor ------------------------------------------------------------------------------
    @cached_property
    def balance(self) -> Balance | None:
        """The rotor's polygons, drawn (None for an engine)."""
        r = self.exercise.rotor
        return draw_balance(r) if r else None

    @cached_property
    def expected(self) -> dict[str, tuple[float, float]]:
        """Each balancing plane's product by the closed form (kg·m)."""
        r = self.exercise.rotor
        if len(r.planes) == 1:
            x, y = resultant(r.masses)
            return {r.planes[0].name: (-x, -y)}
        a, b = r.planes
        in_a, in_b = two_planes(r.masses, a.position, b.position)
        return {a.name: in_a, b.name: in_b}

    @cached_property
    def engine_polygons(self) -> EnginePolygons | None:
        """The engine's four polygons, drawn (None for a rotor, or a single cylinder)."""
        e = self.exercise.engine
        return draw_engine(e) if e and len(e.cranks) > 1 else None

    # ----- checks -------------------------------------------------------------------------------
    @cached_property
    def scales(self) -> tuple[float, float, float]:
        """The sizes the rotor's sums round at: Σ|mᵢrᵢ| (kg·m) and Σ|mᵢrᵢ|·(|zᵢ| + |z_A|)
        (kg·m²: an arm lᵢ = zᵢ − z_A rounds at the size of the planes it is taken between),
        the balancing products included, and the size a balancing product's own rounding
        follows, the first plus the second over l_B: a product found from the couples is
        divided by the planes' distance apart."""
        r = self.exercise.rotor
        ref = r.planes[0].position
        vectors = [(m.mass * m.radius, m.plane) for m in r.masses]
        vectors += [(math.hypot(*self.balance.product(p.name)), p.position) for p in r.planes]
        force = math.fsum(size for size, _ in vectors)
        couple = math.fsum(size * (abs(z) + abs(ref)) for size, z in vectors)
        lever = abs(r.planes[-1].position - ref) if len(r.planes) == 2 else 0.0
        return force, couple, force + (couple / lever if lever else 0.0)

    @cached_property
    def misses(self) -> list[tuple[str, float]]:
        """What disagrees: (name, miss relative to the size its sums round at)."""
        out = []
        if self.balance is not None:
            force_scale, couple_scale, product_scale = self.scales
            for name, want in self.expected.items():
                got = self.balance.product(name)
                miss = math.dist(got, want) / product_scale
                if miss > AGREE:
                    out.append((f"plane {name}", miss))
            force, couple = self.residual
            miss = max(force / force_scale, couple / couple_scale if couple_scale else 0.0)
            if miss > AGREE:
                out.append(("the balanced rotor", miss))
        if self.engine_polygons is not None:
            e = self.exercise.engine
            sums = engine_sums(e)
            w2 = e.speed ** 2
            values = dict(zip(KINDS, (sums.primary_force, sums.primary_couple,
                                      sums.secondary_force, sums.secondary_couple)))
            size = e.reciprocating * e.crank * max(1.0, max(abs(p) for p in e.planes))
            for kind in KINDS:
                miss = abs(self.engine_polygons.left(kind) * w2 - values[kind]) / (size * w2)
                if miss > AGREE:
                    out.append((kind, miss))
        return out

    def placed(self, p) -> tuple[tuple[float, float], float, float]:
        """Plane ``p``'s balancing product as drawn (kg·m), and the mass (kg) and radius (m)
        it comes to: the file gives one, the product the other (a plane that needs no mass
        comes to 0 kg, or to its mass on the shaft's axis)."""
        v = self.balance.product(p.name)
        size = math.hypot(*v)
        if p.radius is not None:
            return v, size / p.radius, p.radius
        return v, p.mass, size / p.mass

    @cached_property
    def residual(self) -> tuple[float, float]:
        """The balanced rotor's leftover force and couple (kg·m, kg·m²): its masses and the
        drawn balancing products summed; the couple about the first balancing plane."""
        r = self.exercise.rotor
        vectors = [(m.mr, m.plane) for m in r.masses]
        vectors += [(self.balance.product(p.name), p.position) for p in r.planes]
        ref = r.planes[0].position
        fx = math.fsum(v[0] for v, _ in vectors)
        fy = math.fsum(v[1] for v, _ in vectors)
        cx = math.fsum(v[0] * (z - ref) for v, z in vectors)
        cy = math.fsum(v[1] * (z - ref) for v, z in vectors)
        return math.hypot(fx, fy), (math.hypot(cx, cy) if len(r.planes) == 2 else 0.0)

    @property
    def passed(self) -> bool:
        """Every closing side where the vector sum puts it."""
        return not self.misses

    @property
    def failures(self) -> list[str]:
        """What disagrees, by name."""
        return [name for name, _ in self.misses]

    # ----- words --------------------------------------------------------------------------------
    def _length(self, v: float) -> str:
        unit = self.exercise.length_unit
        return f"{numeral(v / LENGTH_UNITS[unit])} {unit}"

    def lines(self) -> list[str]:
        """What the command line prints, and steps.md lists, in the language spoken."""
        ex = self.exercise
        if ex.engine is not None:
            return self._engine_lines()
        out = []
        r = ex.rotor
        noise = rounding([m.mass * m.radius for m in r.masses])
        x, y = (_quiet(v, noise) for v in resultant(r.masses))
        if x == y == 0.0:
            out.append(words("ΣF_x = ΣF_y = 0 (kg·m): the masses' forces cancel, with no "
                             "resultant"))
        else:
            out.append(words("ΣF_x = {x}ω², ΣF_y = {y}ω² (kg·m): the resultant {size} kg·m at "
                             "{angle}° ({force} N at ω = {speed} rad/s)", x=numeral(x),
                             y=numeral(y), size=numeral(math.hypot(x, y)),
                             angle=numeral(quadrant_angle(x, y), ".2f"),
                             force=numeral(math.hypot(x, y) * r.speed ** 2),
                             speed=numeral(r.speed)))
        for p in r.planes:
            if p.name in self.balance.none:
                out.append(self._none_line(p))
                continue
            v, mass, radius = self.placed(p)
            out.append(words("plane {plane}: balancing m·r = {size} kg·m at {angle}°, so {mass} "
                             "kg at {radius}", plane=p.name, size=numeral(math.hypot(*v)),
                             angle=numeral(_angle(v), ".2f"), mass=numeral(mass),
                             radius=self._length(radius)))
        if len(r.planes) == 1 and len({m.plane for m in r.masses}) > 1:
            arms = [(m, m.plane - r.planes[0].position) for m in r.masses]
            couple = math.hypot(*(math.fsum(m.mr[i] * arm for m, arm in arms) for i in (0, 1)))
            single = one_axial_plane(r.masses)
            if single is not None:
                v, place = single
                planes = [m.plane for m in r.masses]
                case = words("2-1, between") if min(planes) <= place <= max(planes) else \
                    words("2-2, outside")
                out.append(words("the masses lie in one axial plane: one mass of m·r = {size} "
                                 "kg·m at {angle}° in the plane at {place} balances force and "
                                 "couple together (the notes' case {case} the masses' planes: "
                                 "moments about each mass's plane fix it)",
                                 size=numeral(math.hypot(*v)), angle=numeral(_angle(v), ".2f"),
                                 place=self._length(place), case=case))
            if couple > rounding([m.mass * m.radius * (abs(m.plane) + abs(r.planes[0].position))
                                  for m in r.masses]):
                out.append(words("at {place} one plane balances the forces only: a couple of "
                                 "{couple} kg·m² (× ω²) is left, for a second plane to take",
                                 place=self._length(r.planes[0].position), couple=numeral(couple)))
        verdict = words("each where the vector sum puts it") if self.passed else \
            f"OFF: {', '.join(self.failures)}"
        out.append(words("polygons closed: {verdict}; the balanced rotor's residual force "
                         "{residual} kg·m", verdict=verdict,
                         residual=numeral(self.residual[0], ".1e")))
        return out

    def _none_line(self, p) -> str:
        """Why plane ``p`` needs no mass: its polygon closes on itself."""
        r = self.exercise.rotor
        if len(r.planes) == 1:
            return words("plane {plane}: no balancing mass needed, the force polygon closes on "
                         "itself (Σ mᵢrᵢ = 0)", plane=p.name)
        a, b = r.planes
        if p is b:
            return words("plane {plane}: no balancing mass needed, the couple polygon closes on "
                         "itself (Σ mᵢrᵢlᵢ = 0 about plane {a})", plane=p.name, a=a.name)
        return words("plane {plane}: no balancing mass needed, the force polygon closes on "
                     "itself (Σ mᵢrᵢ + (m r)_{b} = 0)", plane=p.name, b=b.name)

    def _engine_lines(self) -> list[str]:
        e = self.exercise.engine
        if len(e.cranks) == 1:
            prim, sec, along, across = single_cylinder(e, e.at)
            f = e.reciprocating * e.speed ** 2 * e.crank
            return [words("at θ = {angle}°: primary force {primary} N, secondary {secondary} N "
                          "along the line of stroke (n = l/r = {n})",
                          angle=numeral(math.degrees(e.at), "g"), primary=numeral(prim),
                          secondary=numeral(sec), n=numeral(e.rod / e.crank)),
                    words("with {share} of the reciprocating mass balanced by a rotating mass: "
                          "{along} N along the line of stroke and {across} N across it",
                          share=numeral(e.balanced, "g"), along=numeral(along),
                          across=numeral(across)),
                    words("at most {along} N along (θ = 0°, 180°) and {across} N across "
                          "(θ = 90°, 270°)", along=numeral((1 - e.balanced) * f),
                          across=numeral(e.balanced * f))]
        sums = engine_sums(e)
        out = []
        for kind, value in zip(KINDS, (sums.primary_force, sums.primary_couple,
                                       sums.secondary_force, sums.secondary_couple)):
            unit = "N·m" if kind.endswith("couple") else "N"
            left = self.engine_polygons.left(kind) * e.speed ** 2
            balanced = kind in self.engine_polygons.balanced
            out.append(words("{kind}: balanced (its polygon closes)", kind=words(kind))
                       if balanced else
                       words("{kind}: unbalanced, {left} {unit} at most (the vector sum: "
                             "{value} {unit})", kind=words(kind), left=numeral(left), unit=unit,
                             value=numeral(value)))
        return out

    def document(self) -> list[Section]:
        """steps.md: the construction, numbered, and the results (the lines solve prints,
        with their checks)."""
        ex = self.exercise
        record = self.balance.construction if self.balance else (
            self.engine_polygons.construction if self.engine_polygons else None)
        out = [title(ex.name, ex.description)]
        if record is not None:
            out.append(Section(phrase("heading.construction"), (said_steps(record),)))
        return out + [Section(phrase("md.results"), (Bullets(tuple(self.lines())),))]

    # ----- numbers and figures ------------------------------------------------------------------
    @property
    def checked(self) -> dict[str, Checked]:
        """results.json's quantities, in SI: a rotor's balancing products beside the closed
        form; an engine's unbalanced forces and couples beside their vector sums (a single
        cylinder's, read off the closed form, stand alone)."""
        ex = self.exercise
        q: dict[str, Checked] = {}
        if ex.rotor is not None:
            method = "force polygon" if len(self.expected) == 1 else "couple and force polygons"
            for name, want in self.expected.items():
                got = self.balance.product(name)
                # A plane that needs no mass has a zero product, which has no angle.
                where = {"none_needed": True} if name in self.balance.none else {
                    "angle_deg": _angle(got)}
                q[f"mr_{name}"] = Checked({"value": list(got), **where},
                                          {"value": [w + 0.0 for w in want]}, method=method)
        elif len(ex.engine.cranks) == 1:
            prim, sec, along, across = single_cylinder(ex.engine, ex.engine.at)
            q |= {name: Checked({"value": v}) for name, v in (
                ("primary_force", prim), ("secondary_force", sec),
                ("unbalanced_along", along), ("unbalanced_across", across))}
        else:
            sums = engine_sums(ex.engine)
            for kind, value in zip(KINDS, (sums.primary_force, sums.primary_couple,
                                           sums.secondary_force, sums.secondary_couple)):
                q[kind.replace(" ", "_")] = Checked(
                    {"value": self.engine_polygons.left(kind) * ex.engine.speed ** 2},
                    {"value": value}, method=f"{kind} polygon")
        return q

    @property
    def figures(self) -> dict[str, Any]:
        """The space diagram, the table and the polygons (a rotor's); the polygons or the
        forces against crank angle (an engine's)."""
        ex = self.exercise
        unit, metre = ex.length_unit, LENGTH_UNITS[ex.length_unit]
        if ex.rotor is not None:
            return self._rotor_figures(unit, metre)
        e = ex.engine
        if len(e.cranks) == 1:
            return {"forces": self._single_cylinder_plot()}
        out = {}
        p = self.engine_polygons
        for kind in KINDS:
            left = p.left(kind) * e.speed ** 2
            word = "N·m" if kind.endswith("couple") else "N"
            reading = (words("closed: balanced"), "", "") if kind in p.balanced else (
                words("{size} {unit} unbalanced", size=numerals(f"{left:.4g}"),
                      unit=unit_words(word)), "", "")
            out[kind.replace(" ", "-")] = draw_polygon(
                p.construction, p.tips[kind], p.closing[kind], f"{ex.name}: {words(kind)}",
                "kg·m²" if kind.endswith("couple") else "kg·m", reading,
                notes=[words("couples about the central plane; secondary vectors along the "
                             "cranks at 2θᵢ, each m·r/n")],
                names={str(i): words("cyl. {number}", number=str(i)) for i in
                       range(1, len(e.cranks) + 1)})
        return out

    def _rotor_figures(self, unit: str, metre: float) -> dict[str, Any]:
        ex, r, b = self.exercise, self.exercise.rotor, self.balance
        masses = [(m.name, m.radius, _mass_words(m.name, f"{m.mass:g}", f"{m.radius / metre:g}",
                                                 unit, f"{math.degrees(m.angle):g}"))
                  for m in r.masses]
        found = []
        for p in r.planes:
            if p.name in b.none:        # no mass to draw, and a zero product has no angle
                continue
            v, mass, radius = self.placed(p)
            found.append((_mass_words(p.name, f"{mass:.4g}", f"{radius / metre:.4g}", unit,
                                      f"{_angle(v):.2f}"), math.atan2(v[1], v[0]), radius))
        out = {"space": draw_end_view(b.construction, masses,
                                      words("{name}: space diagram", name=ex.name),
                                      unit, metre, found)}
        if len(r.planes) == 2 or len({m.plane for m in r.masses}) > 1:
            planes = [(f"{m.name}", m.plane, "link") for m in r.masses]
            planes += [(p.name, p.position, "normal") for p in r.planes]
            out["side"] = draw_side_view(planes, words("{name}: side view", name=ex.name), unit,
                                         metre)
        out["table"] = self._table(unit, metre)
        # With every mass in plane A the couple polygon is a point: steps.md says so, and
        # there is nothing to draw.
        if len(r.planes) == 2 and any(m.plane != r.planes[0].position for m in r.masses):
            bname = r.planes[1].name
            v = b.vector(b.closing[f"{bname}·l"])
            out["couple-polygon"] = draw_polygon(
                b.construction, b.couple, b.closing[f"{bname}·l"],
                words("{name}: couple polygon (reference plane {plane})", name=ex.name,
                      plane=r.planes[0].name), "kg·m²",
                ("(m r l)", bname, _none_words() if bname in b.none else _size_words(
                    f"{math.hypot(*v):.4g}", "kg·m²", f"{_angle(v):.1f}")))
        a = r.planes[0].name
        v = b.product(a)
        out["force-polygon"] = draw_polygon(
            b.construction, b.force, b.closing[a], words("{name}: force polygon", name=ex.name),
            "kg·m", ("(m r)", a, _none_words() if a in b.none else _size_words(
                f"{math.hypot(*v):.4g}", "kg·m", f"{_angle(v):.1f}")))
        return out

    def _table(self, unit: str, metre: float):
        r = self.exercise.rotor
        ref = r.planes[0].position
        two = len(r.planes) == 2
        flat = not two and len({m.plane for m in r.masses} | {ref}) == 1   # one plane: no l
        length, kg = unit_words(unit), unit_words("kg")
        heads = [f"m ({kg})", f"r ({length})", "θ"] + ([] if flat else [f"l ({length})"]) + [
            f"m·r ({unit_words('kg·m')})"] + ([f"m·r·l ({unit_words('kg·m²')})"] if two else [])
        rows = []
        for m in r.masses:
            rows.append((m.name, [numerals(t) for t in [
                f"{m.mass:g}", f"{m.radius / metre:g}", f"{math.degrees(m.angle):g}°"]
                + ([] if flat else [f"{(m.plane - ref) / metre:g}"])
                + [f"{m.mass * m.radius:.4g}"] + (
                [f"{m.mass * m.radius * (m.plane - ref):.4g}"] if two else [])]))
        none = [p for p in r.planes if p.name in self.balance.none]
        for p in r.planes:
            v, mass, radius = self.placed(p)
            size = math.hypot(*v)
            if p in none:       # the given mass or radius stands, the rest is nothing found
                cells = [f"{mass:.4g}" if p.mass else "—",
                         f"{radius / metre:.4g}" if p.radius else "—", "—"]
            else:
                cells = [f"{mass:.4g}", f"{radius / metre:.4g}", f"{_angle(v):.2f}°"]
            rows.append((p.name, [numerals(t) for t in cells
                                  + ([] if flat else [f"{(p.position - ref) / metre:g}"])
                                  + [f"{size:.4g}"]
                                  + ([f"{size * (p.position - ref):.4g}"] if two else [])]))
        notes = [("" if flat else words("l from the reference plane {plane}; ",
                                        plane=r.planes[0].name))
                 + words("the rows under the rule are the balancing masses found")]
        notes += [words("plane {plane} needs no balancing mass: its polygon closes on itself",
                        plane=p.name) for p in none]
        return draw_train_table(words("{name}: the table", name=self.exercise.name), heads, rows,
                                ruled=[len(r.masses)], notes=notes)

    def _single_cylinder_plot(self):
        e = self.exercise.engine
        xs = [float(d) for d in range(0, 361, 2)]
        values = [single_cylinder(e, math.radians(d)) for d in xs]
        series = [Series(words("primary"), tuple((x, v[0]) for x, v in zip(xs, values)),
                         "plot_curve_dotted"),
                  Series(words("secondary"), tuple((x, v[1]) for x, v in zip(xs, values)),
                         "plot_curve_dashed"),
                  Series(words("left along the stroke"),
                         tuple((x, v[2]) for x, v in zip(xs, values))),
                  Series(words("left across the stroke"),
                         tuple((x, v[3]) for x, v in zip(xs, values)), "plot_curve_dash_dot")]
        at = math.degrees(e.at)
        here = single_cylinder(e, e.at)
        newton = unit_words("N")
        marks = [PlotMark(at, here[2], f"{numerals(f'{here[2]:.4g}')} {newton}"),
                 PlotMark(at, here[3], f"{numerals(f'{here[3]:.4g}')} {newton}")]
        share = Fraction(e.balanced).limit_denominator(12)
        share = share if abs(float(share) - e.balanced) < 1e-9 else f"{e.balanced:g}"
        return draw_line_plot(words("Unbalanced forces"), words("crank angle θ (°)"),
                              f"F ({newton})", series, marks, x_range=(0.0, 360.0),
                              x_ticks=[(float(d), numerals(f"{d}")) for d in range(0, 361, 30)],
                              subtitle=words("{share} of the reciprocating mass balanced by a "
                                             "rotating mass opposite the crank",
                                             share=numerals(str(share))),
                              mark_legend=words("at θ = {angle}°", angle=numerals(f"{at:g}")))



def _mass_words(name: str, mass: str, radius: str, unit: str, angle: str) -> str:
    """A mass as the end view names it, "A: 200 kg at 300 mm, 45°", in the language being
    spoken (the numbers come formatted)."""
    return words("{name}: {mass} {kg} at {radius} {unit}, {angle}°", name=name,
                 mass=numerals(mass), kg=unit_words("kg"), radius=numerals(radius),
                 unit=unit_words(unit), angle=numerals(angle))


def _none_words() -> str:
    """What follows a closing side's symbol when its polygon closes on itself."""
    return words(" = 0: no mass needed")


def _size_words(size: str, unit: str, angle: str) -> str:
    """What follows a closing side's symbol: " = 1.39 kg·m at 3.9°"."""
    return words(" = {size} {unit} at {angle}°", size=numerals(size), unit=unit_words(unit),
                 angle=numerals(angle))


def solve_balance(ex: BalanceExercise) -> BalanceSolution:
    """Solve a balancing exercise by its polygons."""
    return BalanceSolution(ex)
