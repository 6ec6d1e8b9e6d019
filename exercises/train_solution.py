"""A gear-train exercise solved: every speed by the notes' method, each beside the Willis
reference, the steps, results.json and the table as a figure.

The tabular method and the Willis system are both exact, so a speed passes only when the
two are the same fraction: its relative error is 0, or the check fails.
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass
from fractions import Fraction
from functools import cached_property
from pathlib import Path
from typing import Any

from ..constructions.gears.tabular import TrainSpeeds, fraction_text, tabulate
from ..constructions.narration import narrate, phrase, significant
from ..constructions.reference.willis import willis_speeds
from ..graphics.svg import to_svg
from ..graphics.train_table import draw_train_table
from .solution_files import write_solution
from .train_file import TrainExercise, ask_symbol

__all__ = ["TrainSolution", "solve_train"]


@dataclass(frozen=True)
class TrainQuantity:
    """One asked speed or ratio: exact by the method and by Willis, and in SI."""

    name: str
    exact: Fraction
    reference: Fraction
    si: float
    method: str

    @property
    def passed(self) -> bool:
        """True when the method's fraction is the reference's."""
        return self.exact == self.reference

    @property
    def rel_error(self) -> float:
        """0 when the two fractions are one; else how far apart, relative."""
        if self.passed:
            return 0.0
        return float(abs(self.exact - self.reference) / max(abs(self.reference), 1))


@dataclass(frozen=True)
class TrainSolution:
    """A solved gear train (see :func:`solve_train`)."""

    exercise: TrainExercise
    found: TrainSpeeds
    reference: dict[int, Fraction]

    @property
    def train(self):
        """The train solved."""
        return self.exercise.train

    @cached_property
    def quantities(self) -> dict[str, TrainQuantity]:
        """Each asked quantity: a member's speed (file units; SI rad/s), or a ratio."""
        out = {}
        per = self.train.units.per_rad_s
        torques, torques_ref = self._torques(self.found.speeds), self._torques(self.reference)
        for name in self.exercise.asks:
            if name.startswith("torque"):
                m = int(name.removeprefix("torque"))
                out[name] = TrainQuantity(name, torques[m], torques_ref[m], float(torques[m]),
                                          "balance of power")
                continue
            parts = [int(p.removeprefix("omega")) for p in name.split("/")]
            if len(parts) == 1:
                got, ref = self.found.speeds[parts[0]], self.reference[parts[0]]
                out[name] = TrainQuantity(name, got, ref, float(got) * per, self.found.method)
            else:
                a, b = parts
                got = self.found.speeds[a] / self.found.speeds[b]
                ref = self.reference[a] / self.reference[b]
                out[name] = TrainQuantity(name, got, ref, float(got), self.found.method)
        return out

    @property
    def output(self) -> int | None:
        """The member whose torque is asked besides the input's and the fixed one's."""
        t = self.train
        return next((int(q.removeprefix("torque")) for q in self.exercise.asks
                     if q.startswith("torque")
                     and int(q.removeprefix("torque")) not in (t.input_member, t.fixed)), None)

    def _torques(self, speeds: dict[int, Fraction]) -> dict[int, Fraction]:
        """The torques (N·m, CCW-positive) on the input, the output and the fixed member,
        with no power lost: T_in·ω_in + T_out·ω_out = 0, and the three sum to nothing."""
        t, out = self.train, self.output
        if out is None or (t.input_torque is None and t.input_power is None):
            return {}
        w_in = speeds[t.input_member]
        if t.input_torque is not None:
            t_in = t.input_torque if w_in > 0 else -t.input_torque
        else:
            t_in = Fraction(float(t.input_power) / (float(w_in) * t.units.per_rad_s))
        t_out = -t_in * w_in / speeds[out]
        found = {t.input_member: t_in, out: t_out}
        if t.fixed is not None:
            found[t.fixed] = -(t_in + t_out)
        return found

    @property
    def passed(self) -> bool:
        """True when every quantity is the Willis fraction itself."""
        return all(q.passed for q in self.quantities.values())

    @property
    def failures(self) -> list[TrainQuantity]:
        """The quantities the Willis system disagrees with."""
        return [q for q in self.quantities.values() if not q.passed]

    # ----- the files --------------------------------------------------------------------------
    def lines(self) -> list[str]:
        """What the command line prints: each quantity, exact and checked."""
        unit = self.train.units.speed
        out = []
        for q in self.quantities.values():
            if q.name.startswith("torque"):
                sense = "" if q.exact == 0 else (" ccw" if q.exact > 0 else " cw")
                value = f"{float(abs(q.exact)):.6g} N·m{sense}"
            elif "/" in q.name:
                value = f"{fraction_text(q.exact)} ({float(q.exact):.6g})"
            else:
                sense = "" if q.exact == 0 else (" ccw" if q.exact > 0 else " cw")
                value = f"{fraction_text(abs(q.exact))} {unit}{sense} ({float(q.exact):.6g})"
            verdict = "check ok" if q.passed else "check FAILED"
            out.append(f"{ask_symbol(q.name)} = {value:<28} {verdict} (Willis: "
                       f"{fraction_text(q.reference)})   {q.method}")
        return out

    def steps(self) -> str:
        """steps.md: the method's steps, the table, and the results."""
        ex, train = self.exercise, self.train
        lines = [f"# {train.name}: worked solution", ""]
        if ex.description:
            lines += [ex.description, ""]
        lines += [f"## {'The tabular method' if self.found.table else 'The train value'} "
                  f"(`{self._stem}.svg`)", ""]
        steps = list(self.found.steps) + self._torque_steps()
        lines += [f"{k}. {narrate(p)}" for k, p in enumerate(steps, 1)]
        if self.found.xy:
            lines += ["", "The other common form:", ""]
            lines += [f"- {narrate(p)}" for p in self.found.xy]
        heads, rows = self._table()
        lines += ["", "| | " + " | ".join(heads) + " |",
                  "|---|" + "---|" * len(heads)]
        lines += [f"| {name} | " + " | ".join(cells) + " |" for name, cells in rows]
        lines += ["", "## Results", "", "| quantity | found | Willis | the same | method |",
                  "|---|---|---|---|---|"]
        for q in self.quantities.values():
            lines.append(f"| {ask_symbol(q.name)} | {fraction_text(q.exact)} | "
                         f"{fraction_text(q.reference)} | {'yes' if q.passed else 'NO'} | "
                         f"{q.method} |")
        return "\n".join(lines) + "\n"

    def _torque_steps(self) -> list:
        """The balance of power and of torques, said with the numbers."""
        t, torques = self.train, self._torques(self.found.speeds)
        if not torques:
            return []
        i, o, w = t.input_member, self.output, self.found.speeds
        given = (f"T{i} = {float(t.input_torque):g} N·m" if t.input_torque is not None else
                 f"T{i} = P/ω{i} = {float(t.input_power):g} W / "
                 f"{float(w[i]) * t.units.per_rad_s:.6g} rad/s")
        out = [phrase("gears.power", given=given, i=i, o=o, ratio=fraction_text(w[i] / w[o]),
                      value=significant(float(torques[o])))]
        if t.fixed is not None:
            out.append(phrase("gears.holding", fixed=t.fixed, i=i, o=o,
                              value=significant(float(torques[t.fixed]))))
        return out

    @property
    def _stem(self) -> str:
        return "table" if self.found.table else "train-value"

    def _table(self) -> tuple[list[str], list[tuple[str, list[str]]]]:
        """The table's heads and rows, as the notes set them (speeds in the file's unit)."""
        train, found, unit = self.train, self.found, self.train.units.speed
        heads = [_head(train, m) for m in train.members]
        speeds = [fraction_text(found.speeds[m]) for m in train.members]
        t = found.table
        if t is None:
            return heads, [(f"speed ({unit}, ccw +)", speeds)]
        return heads, [
            ("whole train locked, +1", [fraction_text(t.locked[m], True) for m in t.members]),
            (f"arm {train.arm} held, {train.fixed} turned −1",
             [fraction_text(t.held[m], True) for m in t.members]),
            ("total", [fraction_text(t.total[m], True) for m in t.members]),
            (f"× {fraction_text(t.scale)} {unit}: speed", speeds)]

    def figures(self) -> dict[str, Any]:
        """Each figure by its file stem: the table (or the speeds of an ordinary train)."""
        heads, rows = self._table()
        unit = self.train.units.speed
        notes = [f"Speeds in {unit}, counter-clockwise positive; each is the same fraction "
                 "by the Willis equations solved as a linear system."]
        ruled = (2, 3) if self.found.table else ()
        title = f"{self.train.name}: " + ("the tabular method" if self.found.table
                                          else "speeds through the train")
        return {self._stem: draw_train_table(title, heads, rows, ruled=ruled, notes=notes)}

    def results(self) -> dict[str, Any]:
        """results.json: every asked quantity in SI with its exact value and reference."""
        per = self.train.units.per_rad_s
        qs = {}
        for q in self.quantities.values():
            ratio = "/" in q.name
            ref_si = float(q.reference) * (1.0 if ratio else per)
            entry = {"value": q.si, "exact": fraction_text(q.exact).replace("−", "-")}
            if not ratio:       # the exact value is in the file's unit; rpm for display
                entry["unit"] = self.train.units.speed
                entry["rpm"] = (float(q.exact) if entry["unit"] == "rpm"
                                else q.si * 60 / (2 * math.pi))
            qs[q.name] = {**entry, "reference": {
                "value": ref_si, "exact": fraction_text(q.reference).replace("−", "-")},
                "rel_error": q.rel_error, "method": q.method}
        return {"exercise": self.exercise.id, "positions": [], "quantities": qs}

    def files(self) -> dict[str, str]:
        """Every file as text, by name: the figures' SVG, steps.md and results.json."""
        figures = self.figures()
        files = {f"{stem}.svg": to_svg(fig) for stem, fig in figures.items()}
        files["steps.md"] = self.steps()
        files["results.json"] = json.dumps(self.results(), indent=2, ensure_ascii=False) + "\n"
        return files

    def write(self, folder: str | Path, *, pdf: bool = True) -> list[Path]:
        """Write the files into ``folder`` (with a PDF of each figure when ``pdf``), all or
        nothing, as a linkage's solution is written."""
        return write_solution(self.files(), folder, pdf=pdf)


def _head(train, m: int) -> str:
    """A column's heading: "2 sun", "3 arm"."""
    name = (train.arm_name or "arm") if m == train.arm else train.gear(m).name
    return f"{m} {name}".strip()


def solve_train(ex: TrainExercise) -> TrainSolution:
    """Every speed of ``ex``'s train by the notes' method, and by the Willis system.

    Raises
    ------
    InputError
        If the train does not hang together or its input cannot drive it.
    """
    return TrainSolution(ex, tabulate(ex.train), willis_speeds(ex.train))
