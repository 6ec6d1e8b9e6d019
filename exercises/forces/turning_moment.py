"""The turning-moment diagram of a loaded mechanism over a turn, and its flywheel.

At equal steps of the input's turn, the input turning steadily at its ω (α = 0, as the
diagram and the flywheel assume: an α the file gives belongs to its one position), the
analytic solver gives the motion and the force reference
(:mod:`..constructions.reference.kinetostatics`) the driving torque and every joint force;
the torque is checked at each step by the balance of power, which shares no joint force
with it. The diagram is read as the textbooks read it
(:mod:`..constructions.reference.flywheel`): the mean torque, the energy areas between
curve and mean, the greatest fluctuation of energy, and the flywheel for a coefficient of
speed fluctuation (or the coefficient a given flywheel allows).
"""

from __future__ import annotations

import dataclasses
import math
import sys
from collections.abc import Callable
from dataclasses import dataclass, field

from tarsim.constructions.errors import AssemblyError, InputError, TarsimError
from tarsim.constructions.model import Drive
from tarsim.constructions.narration import Word, numerals, unit_words, words
from tarsim.constructions.reference import solver
from tarsim.constructions.reference.change_points import change_point_between
from tarsim.constructions.reference.flywheel import (Fluctuation, fluctuation, flywheel_inertia,
                                                     speed_fluctuation)
from tarsim.constructions.reference.kinetostatics import balance, power_torque, torque_rounding
from tarsim.graphics.figure import Figure
from tarsim.graphics.plot import PlotMark, Series, draw_line_plot, smallest_shown
from ..linkages.exercise_file import Exercise

__all__ = ["POWER_AGREE", "TurningMoment", "moment_files", "turning_moment"]

POWER_AGREE = 1e-9
"""How near (relative to the greatest torque of the turn) the balance of power must come to
the joint-force system's torque: both round alike, near 1e-14."""


@dataclass
class TurningMoment:
    """The driving torque and joint forces round a turn, read for the flywheel."""

    exercise: Exercise
    angles: list[float]
    """How far the input has turned at each step (rad), from its [input] angle the way
    it turns."""
    torques: list[float | None]
    """The driving torque at each step (N·m), positive in the way the input turns: the
    driver's work over a step is its torque times the step."""
    forces: dict[str, list[float | None]] = field(default_factory=dict)
    """Each joint force's size (N, or N·m for a couple) at each step."""
    gaps: list[tuple[float, str]] = field(default_factory=list)
    power_miss: float = 0.0
    """The worst disagreement of the balance of power, relative to the greatest torque."""
    biggest: float = 0.0
    """The greatest torque of the turn (N·m)."""
    rounding: float = 0.0
    """The greatest size the torque is made of at a step (N·m), its loads' powers each at
    full size over ω: a torque that is the small rest of large moments rounds at this."""
    marks: list[tuple[float, float, float, str]] = field(default_factory=list)
    """The driving torque by the force polygons at the positions the exercise solves:
    (turned angle in rad, its torque and the curve's there, both positive the way the input
    turns, N·m; the position's label)."""

    @property
    def noise(self) -> float:
        """The torque's rounding (N·m): what its two ways of finding it (the joint forces
        and the balance of power) disagree by, and never less than a few roundings of the
        greatest torque or of the size it is made of (a crank's own inertia force, square
        to its path, is cancelled by a moment of its full size at every step)."""
        return max(self.power_miss * self.biggest,
                   16 * sys.float_info.epsilon * max(self.biggest, self.rounding))

    @property
    def reading(self) -> Fluctuation | None:
        """The diagram read for its mean and energy areas; None if the turn has gaps. A
        mean within the torque's rounding is 0 (the loads do no net work over a turn), and
        a torque that stays within its rounding of its mean is steady: no areas, ΔE = 0."""
        if self.gaps:
            return None
        r = fluctuation(self.angles, self.torques)
        mean = 0.0 if abs(r.mean) <= self.noise else r.mean
        if max(abs(t - r.mean) for t in self.torques) <= self.noise:
            return Fluctuation(mean, (), (), 0.0, self.angles[0], self.angles[0])
        return dataclasses.replace(r, mean=mean) if mean != r.mean else r

    @property
    def turning(self) -> str:
        """The way the input turns, as the figures say it."""
        return "clockwise" if self.exercise.mechanism.drive.omega < 0 else "counter-clockwise"

    def theta(self, turned: float) -> float:
        """The input's angle (degrees, 0–360) after it has turned ``turned`` (rad)."""
        drive = self.exercise.mechanism.drive
        sense = -1.0 if drive.omega < 0 else 1.0
        return math.degrees(drive.angle + sense * turned) % 360.0

    @property
    def omega(self) -> float:
        """The input's mean speed (rad/s)."""
        return abs(self.exercise.mechanism.drive.omega)

    def lines(self) -> list[str]:
        """What the command line prints."""
        r, loads = self.reading, self.exercise.loads
        if r is None:
            return [f"turning moment: {len(self.gaps)} positions could not be solved "
                    f"({self.gaps[0][1]}), so the diagram is not read"]
        if r.areas:
            out = [f"at steady speed, mean driving torque {r.mean:.6g} N·m ({self.turning}); "
                   f"greatest fluctuation of energy ΔE = {r.delta_e:.6g} J (between θ = "
                   f"{self.theta(r.lowest):.2f}° and {self.theta(r.highest):.2f}°), from "
                   f"{len(r.areas)} areas"]
        else:
            out = [f"at steady speed, the driving torque is steady at {r.mean:.6g} N·m "
                   f"({self.turning}) round the turn, to its rounding (±{self.noise:.2g} "
                   "N·m): ΔE = 0"]
        if loads.speed_fluctuation and not r.delta_e:
            out.append(f"no flywheel is needed for C_s = {loads.speed_fluctuation:g}: the "
                       "torque does not fluctuate beyond its rounding")
        elif loads.speed_fluctuation:
            i = flywheel_inertia(r.delta_e, self.omega, loads.speed_fluctuation)
            out.append(f"flywheel for C_s = {loads.speed_fluctuation:g} at ω = "
                       f"{self.omega:.6g} rad/s: I = ΔE/(C_s·ω²) = {i:.6g} kg·m²")
        if loads.flywheel:
            cs = speed_fluctuation(r.delta_e, self.omega, loads.flywheel)
            out.append(f"a flywheel of {loads.flywheel:g} kg·m² holds the speed within "
                       f"C_s = ΔE/(I·ω²) = {cs:.6g}")
        for _, drawn, curve, label in self.marks:      # signed as solve's T2: CCW +
            out.append(f"T{self.exercise.mechanism.drive.link} by the force polygons at "
                       f"{label}: {_torque(drawn)}, the curve's {_torque(curve)} (relative "
                       f"error {abs(drawn - curve) / max(abs(curve), 1e-300):.1e})")
        verdict = "agrees" if self.power_miss <= POWER_AGREE else "DISAGREES"
        out.append(f"driving torque by the balance of power {verdict} at every step "
                   f"(worst {self.power_miss:.1e} of the greatest torque)")
        return out

    def figure(self) -> Figure:
        """The turning-moment diagram: the torque against the input's turn, its mean, the
        energy areas shaded and each labelled with its joules."""
        degrees = [math.degrees(a) for a in self.angles]
        curve = Series(words("driving torque"), tuple(
            (d, t) if t is not None else None for d, t in zip(degrees, self.torques)) + (
            (360.0, self.torques[0]) if self.torques[0] is not None else None,))
        r = self.reading
        series, fills, tags = [curve], [], []
        notes = [words("the input turning steadily at ω = {omega} {unit} (α = 0)",
                       omega=numerals(f"{self.omega:.4g}"), unit=unit_words("rad/s"))]
        torque = unit_words("N·m")
        if r is not None:
            series.append(Series(words("mean {value} {unit}", value=numerals(
                f"{self._mean_shown(r.mean):.4g}"), unit=torque), ((0.0, r.mean), (360.0, r.mean)),
                "plot_curve_dashed"))
            fills, tags = self._areas(r)
            notes.append(words("ΔE = {energy} {unit}, the greatest fluctuation of energy: the "
                               "highest energy less the lowest, adding the areas in turn (shaded "
                               "light where the driver gives more than the mean, dark where "
                               "less)", energy=numerals(f"{r.delta_e:.4g}"),
                               unit=unit_words("J")))
        ticks = [(k * 30.0, numerals(f"{k * 30}")) for k in range(13)]
        name = self.exercise.mechanism.name
        marks = [PlotMark(math.degrees(turned), drawn, _said_value(label.split(" (")[0]))
                 for turned, drawn, _, label in self.marks]
        if r is not None:           # where the energy is highest and lowest, on this axis
            notes.append(words("The energy is lowest at {low}° turned (θ = {theta_low}°) and "
                               "highest at {high}° (θ = {theta_high}°).",
                               low=numerals(f"{math.degrees(r.lowest) % 360:.4g}"),
                               theta_low=numerals(f"{self.theta(r.lowest):.4g}"),
                               high=numerals(f"{math.degrees(r.highest) % 360:.4g}"),
                               theta_high=numerals(f"{self.theta(r.highest):.4g}")))
        return draw_line_plot(
            words("Turning-moment diagram"),
            words("input turned {sense} from θ = {angle}° (°)", sense=Word(self.turning),
                  angle=numerals(f"{self.theta(0.0):g}")), f"T ({torque})", series,
            x_range=(0.0, 360.0),
            x_ticks=ticks, notes=notes, fills=fills, tags=tags, marks=marks,
            mark_legend=words("by the force polygons") if marks else "",
            subtitle=words("{name}: the driving torque, positive {sense}", name=name,
                           sense=Word(self.turning)))

    def _mean_shown(self, mean: float) -> float:
        """The mean as the diagram states it: 0 where its line would stand nearer the zero
        line than the drawing shows (a mean of 1e-14 N·m is the rounding of no net work,
        and one of 0.01 N·m on a diagram of ±400 N·m cannot be drawn off zero either)."""
        ys = [t for t in self.torques if t is not None] + [t for _, t, _, _ in self.marks]
        return 0.0 if abs(mean) < smallest_shown(min(ys), max(ys)) else mean

    def _areas(self, r: Fluctuation):
        """Each energy area's outline (between curve and mean) and its label."""
        from tarsim.graphics.forces.flywheel_figure import energy_fills

        return energy_fills([math.degrees(a) for a in self.angles], list(self.torques), r.mean,
                            [math.degrees(c) for c in r.intercepts], 360.0, lambda area: (
                                f"{numerals(f'{area:+.4g}'.replace('-', '−'))} "
                                f"{unit_words('J')}"))

    def csv(self) -> str:
        """One row a step: the angle, the torque and each joint force's size."""
        names = list(self.forces)
        rows = ["turned_deg,theta_deg,T_Nm," + ",".join(f"{n}_N" for n in names)]
        for k, a in enumerate(self.angles):
            t = self.torques[k]
            cells = [f"{math.degrees(a):.6f}", f"{self.theta(a):.6f}",
                     "" if t is None else repr(t)]
            cells += ["" if self.forces[n][k] is None else repr(self.forces[n][k])
                      for n in names]
            rows.append(",".join(cells))
        return "\n".join(rows) + "\n"


def _said_value(label: str) -> str:
    """A position's name with its value in the digits of the language being spoken, as the
    axes give theirs: "θ2 = ۴۰°" (the symbol's own digit kept)."""
    name, equals, value = label.partition(" = ")
    return name + equals + numerals(value)


def turning_moment(ex: Exercise, steps: int = 360,
                   progress: Callable[[int], None] | None = None) -> TurningMoment:
    """Solve the forces at ``steps`` equal steps round the input's turn.

    Raises
    ------
    TarsimError
        If they are solved at none of them (the friction locks it everywhere), or the turn
        passes a change point (:mod:`..constructions.reference.change_points`): beyond it
        the linkage may go on in either assembly, and the branch the file names by a side
        is the other one, so the steps are no one motion's.
    """
    if ex.loads_at:
        raise InputError("a pressure given per position loads the engine at [ask] at's "
                         "positions alone: a turning moment round the turn needs one pressure "
                         "for every position", file=ex.mechanism.source or None)
    mech, loads = ex.mechanism, ex.loads
    drive = mech.drive
    sense = 1.0 if drive.omega >= 0 else -1.0
    out = TurningMoment(ex, [], [])
    biggest = rounding = 0.0
    misses, inputs, conditioning = [], [], []
    for k in range(steps):
        turned = 2 * math.pi * k / steps
        angle = drive.angle + sense * turned
        out.angles.append(turned)
        inputs.append(angle)
        conditioning.append(None)
        try:
            m = mech.with_drive(Drive(drive.link, angle, drive.omega, 0.0))
            kin = solver.solve(m)
            conditioning[-1] = kin.conditioning
            s = balance(m, kin, loads)
            vw = power_torque(m, kin, loads, s)
            rounding = max(rounding, torque_rounding(m, kin, loads, s))
        except TarsimError as e:
            out.torques.append(None)
            out.gaps.append((angle, str(e)))
            for values in out.forces.values():
                values.append(None)
            continue
        out.torques.append(sense * s.torque)
        biggest = max(biggest, abs(s.torque))
        misses.append(abs(vw - s.torque))
        for j in s.joints:
            out.forces.setdefault(j.name, [None] * k).append(j.size)
        if progress:
            progress(1)
    if not misses:
        where, why = out.gaps[0]
        raise TarsimError(f"the forces are solved at no position of the turn, so there is no "
                          f"turning-moment diagram: {why}")
    _refuse_change_point(mech, inputs, conditioning)
    out.power_miss = max(misses, default=0.0) / (biggest or 1.0)
    out.biggest = biggest
    out.rounding = rounding
    out.marks = _drawn_marks(ex)
    return out


def _refuse_change_point(mech, inputs: list[float], conditioning: list[float | None]) -> None:
    """Raise if the turn passes a change point between two of its steps or lands on one,
    or cannot be assembled somewhere between two steps it solved: its reading would hide
    either."""
    found = change_point_between(mech, inputs, conditioning)
    if found is None:
        return
    at = f"θ{mech.drive.link} = {mech.units.angle_brief(found.angle % math.tau)}"
    if found.refusal is not None:
        error = AssemblyError(f"no turning-moment diagram: between two steps of the turn, at "
                              f"{at}, the linkage cannot be assembled; solve its forces at "
                              "single positions", link=found.refusal.link,
                              angle_deg=math.degrees(found.angle))
        error.because(found.refusal)
        raise error.in_file(mech.source) if mech.source else error
    raise InputError(f"no turning-moment diagram: the turn passes a change point at {at}, "
                     "where the linkage may go on in either assembly; solve its forces at "
                     "single positions", file=mech.source or None)


def _drawn_marks(ex: Exercise) -> list[tuple[float, float, float, str]]:
    """The driving torque the force polygons give at each position the exercise solves, if
    it asks for it, beside the curve's at the same angle."""
    from tarsim.constructions.asks import DrivingTorque
    from ..linkages.solution_files import solve_worked

    if not any(isinstance(a, DrivingTorque) for a in ex.asks):
        return []
    drive = ex.mechanism.drive
    sense = 1.0 if drive.omega >= 0 else -1.0
    try:
        worked = solve_worked(ex)
    except TarsimError:
        # Positions the polygons do not draw (a slotted lever with friction): the curve
        # stands alone, and `tarsim solve` says why.
        return []
    out = []
    for sol in worked.positions:
        q = sol.quantities.get(f"T{drive.link}")
        if q is None or sol.assembly.mechanism.drive.alpha:
            continue        # not asked, or a position that speeds up: off the steady curve
        theta = sol.assembly.mechanism.drive.angle
        turned = (sense * (theta - drive.angle)) % (2 * math.pi)
        # a position of its own is named with its value ("t = 2.34 s"), the file's own angle
        # by it ("θ2 = 40°")
        label = sol.position.label if sol.position else \
            f"θ{drive.link} = {math.degrees(theta) % 360:.6g}°"
        out.append((turned, sense * q.value["value"], sense * q.reference["value"], label))
    return out


def moment_files(tm: TurningMoment, *, pdf: bool = False) -> dict[str, str | bytes]:
    """The diagram (SVG, and PDF if asked) and its table, by file name."""
    from tarsim.graphics.export import figure_pdf
    from tarsim.graphics.svg import to_svg

    fig = tm.figure()
    files: dict[str, str | bytes] = {"turning-moment.svg": to_svg(fig),
                                     "turning-moment.csv": tm.csv()}
    if pdf:
        files["turning-moment.pdf"] = figure_pdf([fig])
    return files


def _torque(t: float) -> str:
    """A driving torque as solve prints T2: a true minus, CCW +, and its sense."""
    text = f"{t:.6g}".replace("-", "−")
    return f"{text} N·m" + (f" ({'ccw' if t > 0 else 'cw'})" if t else "")
