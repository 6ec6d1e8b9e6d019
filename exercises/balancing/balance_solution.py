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
from dataclasses import dataclass, replace
from functools import cached_property
from typing import Any

from tarsim.constructions.balancing.engine import EnginePolygons, draw_engine, engine_kinds
from tarsim.constructions.balancing.unknowns import Closure, close_rotor
from tarsim.constructions.balancing.polygons import Balance, draw_balance, rounding
from tarsim.constructions.balancing.unbalance import Unbalance
from tarsim.constructions.units import LENGTH_UNITS
from tarsim.constructions.narration import numeral, phrase, words
from tarsim.constructions.reference.balance import (engine_greatest_at, engine_sums,
                                                    one_axial_plane, quadrant_angle, resultant,
                                                    two_planes)
from ..checked import Checked
from ..solution_folder import ChapterFiles
from ..worked_document import Bullets, Section, said_steps, title
from .balance_figures import angle_deg, balance_figures
from .couple_left import couple_left_checked, couple_left_line
from .coupled_wheels import (trailing_checked, trailing_figures, trailing_lines,
                             trailing_misses, trailing_records, wheel_lines)
from .engine_angle import at_checked, at_lines, at_misses
from .engine_balance import left_checked, left_lines, left_misses, lift_speed
from .engine_speed import at_lift_tagged, per_omega, speed_lines
from .firing_order import firing_line
from .single_cylinder import cylinder_balance, cylinder_checked, cylinder_lines
from .vee_engine import vee_checked, vee_lines, vee_misses
from .radial_engine import radial_checked, radial_lines, radial_misses
from .open_rotor_solution import open_checked, open_lines, open_misses
from .rotor_unbalance import (unbalance, unbalance_checked, unbalance_lines,
                              unbalance_misses)
from .rotor_file import BalanceExercise
from .rotor_discs import disc_lines
from .rotor_weights import weight_checked, weight_line, weights_line
from .bearing_forces import (bearing_checked, bearing_lines, bearing_misses,
                             plane_force_checked, plane_force_lines)

__all__ = ["BalanceSolution", "solve_balance"]

AGREE = 1e-12
"""How near (relative to the sizes of the vectors summed, :meth:`BalanceSolution.scales`) a
closing side must come to its sum: a few roundings of the vectors laid off, for up to a
thousand of them."""


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
        """The rotor's polygons, drawn (None for an engine with no balance planes): the file's
        rotor, or an in-line engine's cylinders as rotating masses."""
        r = self.exercise.rotor
        return draw_balance(r) if r and r.planes else None

    @cached_property
    def unbalance(self) -> Unbalance | None:
        """A rotor's out-of-balance polygons, where it has no balancing plane."""
        r = self.exercise.rotor
        return unbalance(r) if r and not r.planes else None

    @cached_property
    def closure(self) -> Closure | None:
        """A self-balancing rotor's polygons, closed on its unknowns (None otherwise)."""
        o = self.exercise.open
        return close_rotor(o) if o else None

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
        out = [] if self.closure is None else open_misses(self.closure, self.exercise.open)
        if self.unbalance is not None:
            out += unbalance_misses(self.exercise.rotor, self.unbalance)
            out += bearing_misses(self.exercise.rotor, self.unbalance)
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
            sums = engine_sums(per_omega(e))
            w2 = per_omega(e).speed ** 2
            values = dict(zip(engine_kinds(e), (sums.primary_force, sums.primary_couple,
                                                sums.secondary_force, sums.secondary_couple)))
            size = e.reciprocating * e.crank * max(1.0, max(abs(p) for p in e.planes))
            for kind in engine_kinds(e):
                miss = abs(self.engine_polygons.left(kind) * w2 - values[kind]) / (size * w2)
                if miss > AGREE:
                    out.append((kind, miss))
            out += self._greatest_misses(e) + left_misses(self, AGREE) + at_misses(self, AGREE)
        out += trailing_misses(self)
        e = self.exercise.engine
        if e is not None and e.radial:
            return out + radial_misses(e)
        return out + (vee_misses(e) if e is not None and e.vee else [])

    def _greatest_misses(self, e) -> list[tuple[str, float]]:
        """Each drawn crank angle of a greatest force or couple against the reference's
        (a turn's fraction; both or neither where the polygon closes)."""
        out = []
        want = engine_greatest_at(e)
        for kind, got in self.greatest_at.items():
            ref = want[kind]
            period = 180.0 if kind.startswith("primary") else 90.0
            miss = math.inf if ref is None else abs(math.remainder(got - ref, period)) / 360.0
            if miss > AGREE * self.greatest_growth(kind):
                out.append((f"{kind}'s crank angle", miss))
        return out

    def greatest_growth(self, kind: str) -> float:
        """How much a short closing side magnifies the rounding of its angle: its vectors'
        sizes over its length."""
        p, e = self.engine_polygons, self.exercise.engine
        size = max(1.0, max(abs(z) for z in e.planes)) * e.reciprocating * e.crank
        return size / p.left(kind)

    @cached_property
    def greatest_at(self) -> dict[str, float]:
        """Crank 1's angle from the i.d.c. (degrees) where each unbalanced force or couple of
        an in-line engine is greatest, read off its polygon's closing side: the side, from
        the last tip to the pole, is −R of the turning resultant R, and the sum along the
        stroke, |R|·cos(θ + arg R), is greatest at θ = −arg R (secondary: 2θ = −arg S),
        every 180° (90°). The least such angle; none for a polygon that closes."""
        p, e = self.engine_polygons, self.exercise.engine
        out = {}
        for kind in engine_kinds(e):
            if kind in p.balanced:
                continue
            seg = p.construction.output(p.closing[kind])
            (sx, sy), (ex, ey) = seg.start.xy, seg.end.xy
            order = 1 if kind.startswith("primary") else 2
            arg = math.degrees(math.atan2(ey - sy, ex - sx)) - 180.0
            out[kind] = (math.degrees(e.cranks[0]) - arg / order) % (180.0 / order)
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
        return ([words("angles are measured clockwise from the reference radius, as the file "
                       "gives them, and every angle found is read the same way")]
                if self.exercise.clockwise else []) + speed_lines(self.exercise) + self._lines()

    def _lines(self) -> list[str]:
        ex = self.exercise
        if ex.open is not None:     # and an engine's, where its primary balance found them
            return open_lines(self.closure, ex.open, ex.length_unit, self.passed,
                              self.failures) + (self._engine_lines() if ex.engine else [])
        if ex.engine is None:
            return self._rotor_lines()
        out = self._engine_lines()
        if ex.rotor is not None:
            out += wheel_lines(self) + self._rotor_lines() + left_lines(self)
        return out + trailing_lines(self)

    def _rotor_lines(self) -> list[str]:
        """A rotor's resultant, each balancing plane's mass and the check (with no plane,
        its out-of-balance force and couple)."""
        r = self.exercise.rotor
        if self.unbalance is not None:
            verdict = words("each where the vector sum puts it") if self.passed else \
                f"OFF: {', '.join(self.failures)}"
            return disc_lines(self.exercise.discs, self._length) + unbalance_lines(
                r, self.unbalance, self._length) + bearing_lines(
                r, self.unbalance, self._length) + [
                words("polygons closed: {verdict}", verdict=verdict)]
        out = disc_lines(self.exercise.discs, self._length)
        out += [weights_line()] if self.exercise.weights else []
        noise = rounding([m.mass * m.radius for m in r.masses])
        x, y = (_quiet(v, noise) for v in resultant(r.masses))
        if x == y == 0.0:
            out.append(words("ΣF_x = ΣF_y = 0 (kg·m): the masses' forces cancel, with no "
                             "resultant"))
        elif r.speed is None:                   # no speed given: the product alone
            out.append(words("ΣF_x = {x}ω², ΣF_y = {y}ω² (kg·m): the resultant {size} kg·m at "
                             "{angle}°", x=numeral(x), y=numeral(y),
                             size=numeral(math.hypot(x, y)),
                             angle=numeral(quadrant_angle(x, y), ".2f")))
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
                             angle=numeral(angle_deg(v), ".2f"), mass=numeral(mass),
                             radius=self._length(radius)))
            if self.exercise.weights:
                out.append(weight_line(p.name, mass, self._length(radius)))
        out += plane_force_lines(self)
        if len(r.planes) == 1 and len({m.plane for m in r.masses}) > 1:
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
                                 size=numeral(math.hypot(*v)), angle=numeral(angle_deg(v), ".2f"),
                                 place=self._length(place), case=case))
        out += couple_left_line(self)
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
            return self._cylinder_lines(e)
        sums = engine_sums(per_omega(e))
        out = [line for line in (firing_line(e),) if line]
        for kind, value in zip(engine_kinds(e), (sums.primary_force, sums.primary_couple,
                                                 sums.secondary_force, sums.secondary_couple)):
            unit = "N·m" if kind.endswith("couple") else "N"
            balanced = kind in self.engine_polygons.balanced
            if balanced:
                out.append(words("{kind}: balanced (its polygon closes)", kind=words(kind)))
            elif e.speed is None:
                out.append(words("{kind}: unbalanced, {left} {unit} × ω² at most (no speed "
                                 "given)", kind=words(kind),
                                 left=numeral(self.engine_polygons.left(kind)),
                                 unit="kg·m²" if kind.endswith("couple") else "kg·m"))
            else:
                out.append(words("{kind}: unbalanced, {left} {unit} at most (the vector sum: "
                                 "{value} {unit})", kind=words(kind),
                                 left=numeral(self.engine_polygons.left(kind) * e.speed ** 2),
                                 unit=unit, value=numeral(value)))
            if not balanced:
                out.append(words("{kind} greatest with crank 1 at {angle}° from the i.d.c., "
                                 "and every {every}° on", kind=words(kind),
                                 angle=numeral(self.greatest_at[kind], ".2f"),
                                 every=numeral(180 if kind.startswith("primary") else 90)))
        return out + at_lines(self)

    def _cylinder_lines(self, e) -> list[str]:
        """A single cylinder's lines (a V engine's pair on one crank: their resultants)."""
        if e.radial:
            return radial_lines(e)
        return vee_lines(e) if e.vee else cylinder_lines(e, self._length)

    @property
    def cylinder_balance(self) -> tuple[float, float, float] | None:
        """A single cylinder's balance mass (see :func:`.single_cylinder.cylinder_balance`)."""
        return cylinder_balance(self.exercise.engine)

    def document(self) -> list[Section]:
        """steps.md: the construction, numbered, and the results (the lines solve prints,
        with their checks)."""
        ex = self.exercise
        records = [made.construction for made in (self.engine_polygons, self.balance,
                                                   self.closure, self.unbalance)
                   if made is not None] + trailing_records(self)
        out = [title(ex.name, ex.description)]
        out += [Section(phrase("heading.construction"), (said_steps(record),))
                for record in records]
        return out + [Section(phrase("md.results"), (Bullets(tuple(self.lines())),))]

    # ----- numbers and figures ------------------------------------------------------------------
    @property
    def checked(self) -> dict[str, Checked]:
        """results.json's quantities, in SI: a rotor's balancing products beside the closed
        form; an engine's unbalanced forces and couples beside their vector sums (a single
        cylinder's, read off the closed form, stand alone). Where the file measures its
        angles clockwise, each quantity with an angle says so, ``"sense": "cw"``."""
        q = self._checked()
        q = at_lift_tagged(q, self.exercise.engine)
        if not self.exercise.clockwise:
            return q
        return {k: replace(c, value={**c.value, "sense": "cw"})
                if "angle_deg" in c.value or c.value.get("unit") == "deg" else c
                for k, c in q.items()}

    def _checked(self) -> dict[str, Checked]:
        ex = self.exercise
        q: dict[str, Checked] = {}
        if ex.open is not None:
            return open_checked(self.closure) | (self._engine_checked() if ex.engine else {})
        if ex.engine is not None:
            q |= self._engine_checked()
        if self.unbalance is not None:
            return unbalance_checked(ex.rotor, self.unbalance) | bearing_checked(
                ex.rotor, self.unbalance)
        if ex.rotor is not None:
            method = "force polygon" if len(self.expected) == 1 else "couple and force polygons"
            for name, want in self.expected.items():
                got = self.balance.product(name)
                # A plane that needs no mass has a zero product, which has no angle.
                where = {"none_needed": True} if name in self.balance.none else {
                    "angle_deg": angle_deg(got)}
                q[f"mr_{name}"] = Checked({"value": list(got), **where},
                                          {"value": [w + 0.0 for w in want]}, method=method)
            for p in ex.rotor.planes:
                q |= self._balance_mass(p, method)
            q |= plane_force_checked(self) | couple_left_checked(self)
            if ex.engine is not None:
                q |= left_checked(self) | trailing_checked(self)
        return q

    def _engine_checked(self) -> dict[str, Checked]:
        """An engine's forces and couples: a single cylinder's, or the in-line polygons'."""
        ex = self.exercise
        q: dict[str, Checked] = {}
        if ex.engine.radial:
            q |= radial_checked(ex.engine)
        elif ex.engine.vee:
            q |= vee_checked(ex.engine)
        elif len(ex.engine.cranks) == 1:
            q |= cylinder_checked(ex.engine)
        else:
            sums = engine_sums(per_omega(ex.engine))
            for kind, value in zip(engine_kinds(ex.engine), (
                    sums.primary_force, sums.primary_couple, sums.secondary_force,
                    sums.secondary_couple)):
                if ex.engine.speed is None:     # m·r·ω²: none with no speed
                    continue
                q[kind.replace(" ", "_")] = Checked(
                    {"value": self.engine_polygons.left(kind) * ex.engine.speed ** 2},
                    {"value": value}, method=f"{kind} polygon")
            q |= at_checked(self)
            want = engine_greatest_at(ex.engine)
            for kind, got in self.greatest_at.items():
                period = 180.0 if kind.startswith("primary") else 90.0
                q[f"{kind.replace(' ', '_')}_at"] = Checked(
                    {"value": got, "unit": "deg", "every_deg": period},
                    {"value": want[kind]}, method=f"{kind} polygon's closing side")
        return q

    def _balance_mass(self, p, method: str) -> dict[str, Checked]:
        """Plane ``p``'s balancing mass as the books ask it: the mass (kg) at the stated
        radius, ``mass_<plane>``, or the radius (m) for the stated mass, ``radius_<plane>``,
        with its angle; the reference divides the closed form's product by the same given
        number. A plane that needs no mass comes to 0 kg (or a radius of 0), with no angle."""
        v, mass, radius = self.placed(p)
        want = self.expected[p.name]
        none = p.name in self.balance.none
        given = p.radius if p.radius is not None else p.mass
        found, ref = (mass, math.hypot(*want) / given)
        where = {"none_needed": True} if none else {"angle_deg": angle_deg(v)}
        there = {} if none else {"angle_deg": angle_deg(want)}
        # The angle as a quantity of its own, as the books ask "its angular position" (a
        # plane that needs no mass has none).
        angle = {} if none else {f"angle_{p.name}": Checked(
            {"value": angle_deg(v), "unit": "deg"}, {"value": angle_deg(want)}, method=method)}
        if p.radius is not None:
            weight = weight_checked(p.name, found, ref, where, there, method) \
                if self.exercise.weights else {}
            return {f"mass_{p.name}": Checked(
                {"value": found, "unit": "kg", "radius": p.radius, **where},
                {"value": ref, **there}, method=method)} | weight | angle
        return {f"radius_{p.name}": Checked(
            {"value": radius, "unit": "m", "mass": p.mass, **where},
            {"value": ref, **there}, method=method)} | angle

    @property
    def figures(self) -> dict[str, Any]:
        """The space diagram, the table and the polygons (a rotor's); the polygons or the
        forces against crank angle (an engine's)."""
        return balance_figures(self) | trailing_figures(self)


def solve_balance(ex: BalanceExercise) -> BalanceSolution:
    """Solve a balancing exercise by its polygons. A locomotive given no speed but a dead
    load on its wheels is solved again at the lift speed its balance masses give, as the
    books ask its swaying couple "at the speed found"."""
    s = BalanceSolution(ex)
    e = ex.engine
    if e is None or e.speed is not None or ex.rotor is None:
        return s
    lift = lift_speed(s)
    if lift is None:
        return s
    return BalanceSolution(replace(ex, engine=replace(e, speed=lift, at_lift=True),
                                   rotor=replace(ex.rotor, speed=lift),
                                   trailing=ex.trailing and replace(ex.trailing, speed=lift)))
