"""A gear-train exercise solved: every speed by the notes' method, each beside the Willis
reference, the steps, results.json and the table as a figure.

The tabular method and the Willis system are both exact, so a speed passes only when the
two are the same fraction: its relative error is 0, or the check fails.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from fractions import Fraction
from functools import cached_property
from typing import Any

from tarsim.constructions.checks import CEILING
from tarsim.constructions.gears.involute import InvoluteMesh, draw_involute_mesh
from tarsim.constructions.gears.kutzbach import Kutzbach, draw_kutzbach, undrawable
from tarsim.constructions.gears.tabular import TrainSpeeds, fraction_text, tabulate
from tarsim.constructions.gears.torques import (balance, holder, implied_output,
                                                input_torque, per_pi, power_text,
                                                say_balance, say_powers, torque_text)
from tarsim.constructions.narration import (numeral, numerals, phrase, significant, unit_words,
                                            words)
from tarsim.constructions.reference.gear_mesh import MeshReference, involute_miss, mesh_reference
from tarsim.constructions.reference.willis import willis_speeds, willis_torques
from tarsim.graphics.gears.involute_figure import draw_involute_figure
from tarsim.graphics.gears.kutzbach_figure import draw_kutzbach_figure
from tarsim.graphics.gears.train_schematic import draw_train_schematic
from tarsim.graphics.hiding import shown_answer
from tarsim.graphics.train_table import draw_train_table
from ..checked import Checked, check_line
from ..solution_folder import ChapterFiles
from ..worked_document import Bullets, Paragraph, Section, Table, numbered, said_steps, title
from .square_axes import square_mark, square_notes
from .train_file import MESH_ASKS, TrainExercise, ask_symbol
from .train_quantities import QuantityParts, TrainQuantity
from .train_refusals import refuse_beyond_floats, refuse_still_ratios

__all__ = ["TrainSolution", "solve_train"]


@dataclass(frozen=True)
class TrainSolution(ChapterFiles, QuantityParts):
    """A solved gear train (see :func:`solve_train`)."""

    exercise: TrainExercise
    found: TrainSpeeds
    reference: dict[int, Fraction]
    diagram: Kutzbach | None = None
    """The velocity diagram, drawn for a planetary train whose meshes all touch the main
    axis: its speeds are read as slopes and checked against the table's."""
    mesh: InvoluteMesh | None = None
    """The involute mesh drawn, when the exercise gives ``[involute]``."""
    mesh_reference: MeshReference | None = None
    @property
    def train(self):
        """The train solved."""
        return self.exercise.train

    @cached_property
    def quantities(self) -> dict[str, TrainQuantity]:
        """Each asked quantity: a member's speed (file units; SI rad/s), or a ratio."""
        out = {}
        per = self.train.units.per_rad_s
        torques, torques_ref = self._torques(self.found.speeds), self._reference_torques()
        pi = per_pi(self.train)
        for name in self.exercise.asks:
            if name in MESH_ASKS:
                out[name] = self._mesh_quantity(name)
                continue
            if name.startswith("teeth"):
                out[name] = self._teeth_quantity(int(name.removeprefix("teeth")))
                continue
            if name.startswith("centre_distance"):
                out[name] = self._distance_quantity(name)
                continue
            if name.startswith("torque"):
                m = int(name.removeprefix("torque"))
                si = float(torques[m]) / (math.pi if pi else 1.0)
                out[name] = TrainQuantity(name, torques[m], torques_ref[m], si,
                                          "balance of power", over_pi=pi)
                continue
            if name.startswith("power"):
                out[name] = self._power_quantity(int(name.removeprefix("power")), torques,
                                                 torques_ref)
                continue
            # (a copy of a planet turns as its planet; the reference solved the copy itself)
            listed = [int(p.removeprefix("omega")) for p in name.split("/")]
            parts = [self.exercise.member(n) for n in listed]
            if len(parts) == 1:
                got, ref = self.found.speeds[parts[0]], self.reference[listed[0]]
                out[name] = TrainQuantity(name, got, ref, float(got) * per, self.found.method)
            else:
                a, b = parts
                got = self.found.speeds[a] / self.found.speeds[b]
                ref = self.reference[listed[0]] / self.reference[listed[1]]
                out[name] = TrainQuantity(name, got, ref, float(got), self.found.method)
        return out

    @property
    def output(self) -> int | None:
        """The member whose torque is asked besides the input's and the fixed one's."""
        t = self.train
        asked = [int(q.removeprefix("torque").removeprefix("power"))
                 for q in self.exercise.asks if q.startswith(("torque", "power"))]
        named = next((m for m in asked if m not in (t.input_member, holder(t))), None)
        if named is None and holder(t) in asked:      # the holding torque asked alone
            return implied_output(t)
        return named

    def _torques(self, speeds: dict[int, Fraction]) -> dict[int, Fraction]:
        return balance(self.train, speeds, self.output)

    def _reference_torques(self) -> dict[int, Fraction]:
        """The torques by the reference: ΣT = 0 and ΣT·ω = losses as a linear system, on
        the Willis speeds."""
        t_in = input_torque(self.train, self.reference)
        if t_in is None:
            return {}
        loads = {self.train.input_member: t_in}
        if self.output is None or self.reference[self.output] == 0:
            return loads
        return willis_torques(self.train, self.reference, loads, self.output,
                              holder(self.train))

    @property
    def passed(self) -> bool:
        """True when every quantity is the Willis fraction itself, and every speed the
        diagram reads agrees with the table's."""
        return (all(q.passed for q in self.quantities.values()) and not self.diagram_misses
                and not self.profile_misses)

    @property
    def profile_misses(self) -> list[str]:
        """The drawn tooth-profile points (by step) off the involute their gear's base circle
        and start give, beyond a drafting act's rounding of the gear's size."""
        if self.mesh is None:
            return []
        out, c = [], self.mesh.construction
        for gear, refs in self.mesh.profiles.items():
            centre = self.mesh.centres[gear]
            base = self.mesh.radii["base2" if gear == self.exercise.involute.pinion
                                   else "base3"]
            for ref in refs:
                if involute_miss(c.output(ref).xy, centre, base, self.mesh.starts[gear]) > \
                        1e-9 * base:
                    out.append(ref)
        return out

    def diagram_check(self, member: int) -> tuple[float, float]:
        """How far the velocity diagram reads ``member``'s ω from the table's, and how far
        the drawing's rounding lets it, both relative to the fastest member the diagram
        draws (its velocities are drawn at that size, so a member at rest has a scale too).

        The rounding is the drawing's coordinates' over the span of radii the line was read
        across (:meth:`~tarsim.constructions.gears.kutzbach.Kutzbach.rounding`), held to
        :data:`~tarsim.constructions.checks.CEILING`: never as wide as the speeds drawn.
        """
        k, per = self.diagram, self.train.units.per_rad_s
        # the input turns (a speed of 0 is refused), so the fastest is no 0
        fastest = max(abs(float(self.found.speeds[m])) for m in k.omegas) * per
        miss = abs(k.omegas[member] - float(self.found.speeds[member]) * per) / fastest
        return miss, min(k.rounding(member, fastest) / fastest, CEILING)

    def diagram_ratio(self, a: int, b: int) -> dict[str, float]:
        """ω_a/ω_b read off the velocity diagram as its two slopes' ratio, how far it lies
        from the table's, and how far the two slopes' roundings let it (each ω off by its
        rounding of the fastest: |δω_a|/|ω_b| + |ω_a/ω_b|·|δω_b|/|ω_b|)."""
        k, per = self.diagram, self.train.units.per_rad_s
        fastest = max(abs(float(self.found.speeds[m])) for m in k.omegas) * per
        w_a, w_b = (float(self.found.speeds[m]) * per for m in (a, b))
        read = k.said(a) / k.said(b)
        allowed = (self.diagram_check(a)[1] + abs(w_a / w_b) * self.diagram_check(b)[1]) * \
            fastest / abs(w_b)
        return {"value": read, "rel_error": abs(read - w_a / w_b), "tolerance": allowed}

    @property
    def diagram_misses(self) -> list[int]:
        """The members whose ω the velocity diagram reads away from the table's, beyond
        its drawing's rounding (:meth:`diagram_check`)."""
        if self.diagram is None:
            return []
        out = []
        for m in self.diagram.omegas:
            miss, allowed = self.diagram_check(m)
            if miss > allowed:
                out.append(m)
        return out

    @property
    def failures(self) -> list[str]:
        """The quantities the Willis system disagrees with, and the speeds the diagram
        reads wrong."""
        return ([q.name for q in self.quantities.values() if not q.passed]
                + [f"omega{m} (velocity diagram)" for m in self.diagram_misses]
                + [f"the involute at {r}" for r in self.profile_misses])

    # ----- the files --------------------------------------------------------------------------
    def lines(self) -> list[str]:
        """What the command line prints: each quantity, exact and checked."""
        unit = self.train.units.speed
        out = []
        for q in self.quantities.values():
            if q.name in MESH_ASKS:
                value = _mesh_text(q.name, float(q.exact), self.mesh)
                reference = _mesh_text(q.name, float(q.reference), self.mesh_reference)
                out.append(check_line(f"{q.name} = {value}", width=36,
                                      passed=q.passed, against=f"(formula: {reference})",
                                      method=q.method))
                continue
            if q.name.startswith("centre_distance"):
                symbol = ask_symbol(q.name)
                found, radii = (self.train._length(x / Fraction(math.pi) if q.over_pi else x)
                                for x in (q.exact, q.reference))
                out.append(check_line(f"{symbol} = {found}", width=36,
                                      passed=q.passed, against=f"(pitch radii: {radii})",
                                      method=q.method))
                continue
            if q.name.startswith("teeth"):
                out.append(check_line(f"N{q.name.removeprefix('teeth')} = {q.exact}",
                                      width=36, passed=q.passed,
                                      against=f"(check: {q.reference})", method=q.method))
                continue
            if q.name.startswith("torque"):
                sense = "" if q.exact == 0 else (" ccw" if q.exact > 0 else " cw")
                value = f"{torque_text(abs(q.exact), q.over_pi)} N·m{sense}"
                symbol = ask_symbol(q.name)
                out.append(check_line(f"{symbol} = {value}", width=36,
                                      passed=q.passed, against="(ΣT = 0, ΣTω = 0: "
                                      f"{torque_text(q.reference, q.over_pi)})",
                                      method=q.method))
                continue
            if q.name.startswith("power"):
                symbol = ask_symbol(q.name)
                out.append(check_line(f"{symbol} = {power_text(q.exact, q.times_pi)} W "
                                      f"{q.flow}", width=36, passed=q.passed,
                                      against="(ΣT = 0, ΣTω = 0: "
                                      f"{power_text(q.reference, q.times_pi)})",
                                      method=q.method))
                continue
            elif "/" in q.name:
                value = f"{fraction_text(q.exact)} ({_signed(q.exact)})"
            else:
                sense = "" if q.exact == 0 else (" ccw" if q.exact > 0 else " cw")
                value = f"{fraction_text(abs(q.exact))} {unit}{sense} ({_signed(q.exact)})"
            symbol = ask_symbol(q.name)
            out.append(check_line(f"{symbol} = {value}", width=36,
                                  passed=q.passed,
                                  against=f"(Willis: {fraction_text(q.reference)})",
                                  method=q.method))
        return out

    def document(self) -> list[Section]:
        """steps.md: the train, the method's steps, the drawn constructions, the table, and
        the results."""
        ex, train = self.exercise, self.train
        unsized = [phrase("gears.uncoaxial", c0=c0, r0=significant(float(r0)), c=c,
                          r=significant(float(r))) for _, c0, r0, c, r in train.uncoaxial()]
        method = [numbered([*train.implied, *unsized, *self.found.steps,
                            *say_balance(self.train, self.found.speeds, self.output),
                            *say_powers(self.train, self.found.speeds, self.output,
                                        [int(q.removeprefix("power")) for q in ex.asks
                                         if q.startswith("power")])])]
        if self.found.xy:
            method += [Paragraph(phrase("md.other_form")), Bullets(self.found.xy)]
        out = [title(train.name, ex.description),
               Section(phrase("heading.train"), (Bullets(tuple(train.describe())),), ("train",)),
               Section(phrase("heading.tabular" if self.found.table else "heading.train_value"),
                       tuple(method), (self._stem,))]
        for key, stem, drawn in (("heading.involute", "mesh", self.mesh),
                                 ("heading.kutzbach", "kutzbach", self.diagram)):
            if drawn is not None:
                out.append(Section(phrase(key), (said_steps(drawn.construction),), (stem,)))
        heads, rows = self._table()
        out.append(Section(blocks=(Table(("", *heads), tuple((name, *cells)
                                                             for name, cells in rows)),
                                   *map(Paragraph, self._square_notes))))
        return out + [Section(phrase("md.results"), (Table(
            tuple(words(c) for c in ("quantity", "found", "Willis", "the same", "method")),
            tuple(self._result_row(q) for q in self.quantities.values())),))]

    def _result_row(self, q: TrainQuantity) -> tuple[str, ...]:
        """A quantity's row of steps.md's results: found, by Willis (or the formula), the
        same or not, and the method."""
        if q.name in MESH_ASKS:         # a length, an angle, a ratio: not a fraction
            found = _mesh_text(q.name, float(q.exact), self.mesh)
            willis = _mesh_text(q.name, float(q.reference), self.mesh_reference)
        elif q.name.startswith("torque"):
            found, willis = torque_text(q.exact, q.over_pi), torque_text(q.reference, q.over_pi)
        elif q.name.startswith("power"):
            found, willis = power_text(q.exact, q.times_pi), power_text(q.reference, q.times_pi)
        elif q.name.startswith("centre_distance"):
            found, willis = (self.train._length(x / Fraction(math.pi) if q.over_pi else x)
                             for x in (q.exact, q.reference))
        else:
            found, willis = fraction_text(q.exact), fraction_text(q.reference)
        return (ask_symbol(q.name), found, willis, words("yes" if q.passed else "NO"),
                words(q.method))

    @property
    def _stem(self) -> str:
        return "table" if self.found.table else "train-value"

    def _table(self) -> tuple[list[str], list[tuple[str, list[str]]]]:
        """The table's heads and rows, as the notes set them (speeds in the file's unit), in
        the language being spoken; led by the teeth where the data implied some."""
        heads, rows = self._speed_table()
        train = self.train
        if not train.implied_teeth:
            return heads, rows
        teeth = [("" if m == train.arm else shown_answer(numerals(f"({train.gear(m).teeth})"))
                  if m in train.implied_teeth else numerals(str(train.gear(m).teeth)))
                 for m in train.members]
        return heads, [(words("teeth (found: in brackets)"), teeth), *self._pitch_row(), *rows]

    def _speed_table(self) -> tuple[list[str], list[tuple[str, list[str]]]]:
        """The table's heads and rows of turns and speeds."""
        train, found, unit = self.train, self.found, self.train.units.speed
        t = found.table
        # a gear turning about an axis square to the main axis has no cell in a table of
        # turns about it: blank, a footnote saying why (:func:`.square_axes.square_notes`)
        heads = [_head(train, m) + (square_mark(train, m) if t is not None else "")
                 for m in train.members]
        given = {train.input_member, train.fixed, train.second and train.second[0]}
        speeds = ["" if t is not None and train.square(m) else
                  (str if m in given else shown_answer)(
                      numerals(significant(float(found.speeds[m]))))
                  for m in train.members]
        if t is None:
            if not train.speed_given:      # the speeds for one turn of the input: its ratios
                return heads, [(words("turns per turn of {member} (ccw +)",
                                      member=str(train.input_member)), speeds)]
            return heads, [(words("speed ({unit}, ccw +)", unit=unit_words(unit)), speeds)]

        def row(turns: dict[int, Fraction]) -> list[str]:
            # a gear on a side shaft has no place in the table: its cell is blank
            return [shown_answer(numerals(fraction_text(turns[m], True)))
                    if m in turns and not train.square(m) else "" for m in train.members]

        locked = [numerals(fraction_text(t.locked[m], True))
                  if m in t.locked and not train.square(m) else "" for m in train.members]
        if t.weights is not None:         # two given speeds: y × row 1 + x × row 2
            return heads, [
                (words("whole train locked, {turn}", turn=numerals("+1")), locked),
                (words("arm {arm} held, {member} turned {turn}", arm=str(train.arm),
                       member=str(t.turned), turn=numerals("−1")), row(t.held)),
                (words("y × row 1 + x × row 2: speed"), speeds)]
        return heads, [
            (words("whole train locked, {turn}", turn=numerals("+1")), locked),
            (words("arm {arm} held, {fixed} turned {turn}", arm=str(train.arm),
                   fixed=str(train.fixed), turn=numerals("−1")), row(t.held)),
            (words("total"), row(t.total)),
            *([(words("× {scale} {unit}: speed", scale=numerals(fraction_text(t.scale)),
                      unit=unit_words(unit)), speeds)] if train.speed_given else [])]

    @property
    def _square_notes(self) -> list[str]:
        """The table's footnotes on its blank columns (none without a table)."""
        return square_notes(self.train, self.found.speeds) if self.found.table else []

    @property
    def figures(self) -> dict[str, Any]:
        """Each figure by its file stem: the table (or the speeds of an ordinary train)."""
        heads, rows = self._table()
        unit = self.train.units.speed
        notes = [words("Speeds in {unit}, counter-clockwise positive. Each is checked by the "
                       "Willis equation of every mesh, solved as one linear system: the same "
                       "fraction.", unit=unit_words(unit)) if self.train.speed_given else
                 words("No speed is given: the rows are turns, counter-clockwise positive, and "
                       "their ratios the speed ratios, each checked by the Willis equations "
                       "solved as one linear system.")]
        notes += self._square_notes
        ruled = (2, 3) if self.found.table else ()
        if self.train.implied_teeth:          # the teeth's row above the rest, ruled off
            lead = 1 + len(self._pitch_row())
            ruled = (lead, *(r + lead for r in ruled))
        title = (words("{name}: the tabular method", name=self.train.name) if self.found.table
                 else self.train.name)
        out = {self._stem: draw_train_table(title, heads, rows, ruled=ruled, notes=notes)}
        # The shafts that leave it: the members a ratio or a torque is asked of.
        ends = {int(n) for q in self.exercise.asks
                if "/" in q or q.startswith(("torque", "power"))
                for n in re.findall(r"\d+", q)}
        out["train"] = draw_train_schematic(self.train, self.train.name, tuple(sorted(ends)))
        if self.diagram is not None:
            out["kutzbach"] = draw_kutzbach_figure(self.train, self.diagram, self.train.name)
        if self.mesh is not None:
            out["mesh"] = draw_involute_figure(self.train, self.mesh, self.train.name)
        return out

    @property
    def checked(self) -> dict[str, Checked]:
        """results.json's quantities: each asked one in SI, with its exact value and the
        reference's, and a speed's reading off the velocity diagram beside it."""
        per = self.train.units.per_rad_s
        out = {}
        for q in self.quantities.values():
            speed = q.name.startswith("omega") and "/" not in q.name
            to_si = per if speed else 1.0          # a speed's exact value is in the file's unit
            entry: dict[str, Any] = {"value": q.si}
            reference: dict[str, Any] = {"value": float(q.reference) * to_si}
            if q.over_pi:                          # a torque (30·P/n)/π: over π exactly
                reference["value"] = float(q.reference) / math.pi
                entry["exact"], reference["exact"] = _plain(q.exact, True), _plain(
                    q.reference, True)
            elif q.times_pi:                       # a power (T·n/30)·π: times π exactly
                reference["value"] = float(q.reference) * math.pi
                entry["exact"] = f"{_plain(q.exact)}*pi"
                reference["exact"] = f"{_plain(q.reference)}*pi"
            elif q.name not in MESH_ASKS:          # drawn lengths and angles are not exact
                entry["exact"] = _plain(q.exact)
                reference["exact"] = _plain(q.reference)
            if q.flow:
                entry["unit"], entry["flow"] = "W", q.flow
            if q.name.startswith("centre_distance"):
                entry["unit"] = "m"
                entry.update(self._pitches(q.name))
            if speed:                              # the value in rad/s, exact as the file's
                unit = self.train.units.speed
                entry["unit"], entry["exact_unit"] = "rad/s", unit
                entry["rpm"] = float(q.exact) if unit == "rpm" else q.si * 60 / (2 * math.pi)
            if q.name == "interference":
                entry["gears"] = list(self.mesh.interference)
                reference["gears"] = list(self.mesh_reference.interference)
            beside = {}
            m = q.name.removeprefix("omega")
            if self.diagram is not None and speed and int(m) in self.diagram.omegas:
                miss, allowed = self.diagram_check(int(m))     # not a side shaft's gear
                beside["velocity_diagram"] = {"value": self.diagram.said(int(m)),
                                              "rel_error": miss, "tolerance": allowed}
            parts = [int(p.removeprefix("omega")) for p in q.name.split("/")
                     if p.startswith("omega")]
            if self.diagram is not None and len(parts) == 2 and all(
                    p in self.diagram.omegas for p in parts):
                beside["velocity_diagram"] = self.diagram_ratio(*parts)
            out[q.name] = Checked(entry, reference, rel_error=q.rel_error, method=q.method,
                                  beside=beside)
        return out


def _plain(x: Fraction, over_pi: bool = False) -> str:
    """An exact value as results.json writes it: "-3/7", ASCII minus; ``over_pi``
    "4500/pi", "-3/(7*pi)"."""
    if over_pi:
        top = str(x.numerator)
        return f"{top}/pi" if x.denominator == 1 else f"{top}/({x.denominator}*pi)"
    return fraction_text(x).replace("−", "-")


def _mesh_text(name: str, value: float, mesh) -> str:
    """A mesh quantity as the command line and steps.md say it, in the language spoken: mm,
    degrees, a ratio, the gears."""
    if name in ("path_of_contact", "arc_of_contact", "circular_pitch"):
        return f"{numeral(value * 1e3)} mm"
    if name == "pressure_angle":
        return f"{numeral(math.degrees(value))}°"
    if name == "least_teeth":
        return words("{n} teeth on the pinion", n=numeral(value, ".0f"))
    if name == "interference":
        gears = mesh.interference
        return (words("none") if not gears else
                words("the tips of gear {gears} cut into the other's flank",
                      gears=f" {words('and')} ".join(map(str, gears))))
    return numeral(value)


def _head(train, m: int) -> str:
    """A column's heading: "2 sun", "3 arm" (the name in the language being spoken, where it
    has a word for it)."""
    name = (train.arm_name or "arm") if m == train.arm else train.gear(m).name
    return f"{m} {words(name)}".strip()


def solve_train(ex: TrainExercise) -> TrainSolution:
    """Every speed of ``ex``'s train by the notes' method, and by the Willis system.

    Raises
    ------
    InputError
        If the train does not hang together or its input cannot drive it.
    """
    found = tabulate(ex.train)
    train = ex.train
    reference = willis_speeds(ex.listed or train)
    refuse_beyond_floats(train, found.speeds)
    refuse_still_ratios(ex, found.speeds, reference)
    # the diagram lays off the input's velocity: with no speed given, for the input at 1
    # of the file's unit, its slopes' ratios the speed ratios; with two given speeds, both
    drawable = found.table is not None and undrawable(train) is None
    diagram = draw_kutzbach(train, found.speeds) if drawable else None
    mesh = ref = None
    if ex.involute is not None:
        d = ex.involute
        mesh = draw_involute_mesh(train, d)
        a, b = train.gear(d.pinion), train.gear(d.wheel)
        ref = mesh_reference(float(a.module), (a.teeth, b.teeth), (a.number, b.number),
                             d.pressure_angle, d.addendum, d.centre_distance)
    return TrainSolution(ex, found, reference, diagram, mesh, ref)


def _signed(x) -> str:
    """An exact speed or ratio as a decimal, with a true minus as every table prints it."""
    return f"{float(x):.6g}".replace("-", "−")
