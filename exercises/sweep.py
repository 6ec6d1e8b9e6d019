"""The whole-cycle check: one output over a revolution of the input, beside the graphical answers.

The course project (seed 003 §4) checked its drawing against MATLAB and Adams
curves over a crank revolution. Here the curves come from the independent
analytic solver, one position per step of the input angle, and the positions the
exercise solves by construction are marked on them with the constructed values,
so a student sees the drawing's answer sit on the curve. The table of those
values against the curve's is the check; a position that cannot be assembled, or
is a dead point, is a gap in the curves and a row that says why.

The output is a point (its position, velocity and acceleration; along its guide
when it slides on the frame, like a ram or a piston) or a link (θ, ω, α). Each
position is solved at the [input] ω and α; the sweep turns the way ω does.
Extremes are refined: where the velocity (or ω) is zero the position is extreme
(the stroke, the lever's swing), and where the acceleration is zero the velocity
peaks (seed 003 §4: "where position is extremal the velocity is 0").
"""

from __future__ import annotations

import csv
import difflib
import io
import math
import re
from collections.abc import Callable
from dataclasses import dataclass, replace
from pathlib import Path

from constructions import analytic
from constructions.assembly import assemble
from constructions.errors import AssemblyError, InputError, RenderError, TarsimError
from constructions.model import Drive, Mechanism, Slide
from graphics.export import svg_to, write_text
from graphics.figure import Figure
from graphics.plot import CURVE_STYLES, PlotMark, Series, draw_line_plot
from graphics.svg import to_svg

from .exercise_file import Exercise
from .solution import solve_positions

__all__ = ["Output", "Sample", "Event", "Check", "Sweep", "output_names", "pick_output",
           "sweep_exercise", "sweep_figures", "sweep_csv", "points_csv", "sweep_to_files",
           "write_sweep", "format_sweep"]

# Column keys by output kind: position, velocity, acceleration (the plotted ones first).
_KEYS = {"slider": (("s", "x", "y"), ("v",), ("a",)),
         "point": (("x", "y"), ("v", "vx", "vy"), ("a", "ax", "ay")),
         "link": (("theta",), ("omega",), ("alpha",))}
_KIND = {"x": "length", "y": "length", "s": "length", "v": "velocity", "vx": "velocity",
         "vy": "velocity", "a": "acceleration", "ax": "acceleration", "ay": "acceleration",
         "theta": "angle", "omega": "omega", "alpha": "alpha"}


@dataclass(frozen=True)
class Output:
    """What is swept: point ``point`` taken on link ``link``, or link ``link`` itself.

    ``kind`` is ``"slider"`` (a point on a straight frame guide: its values are
    signed along ``guide``'s direction), ``"point"`` (vectors) or ``"link"``.
    """

    kind: str
    link: int
    point: str = ""
    guide: Slide | None = None

    def symbol(self, key: str) -> str:
        """The column's symbol, ``X_Y`` for a subscript: "V_B", "x_B", "ω_4"."""
        if self.kind == "link":
            return {"theta": "θ", "omega": "ω", "alpha": "α"}[key] + f"_{self.link}"
        head = {"v": "V", "vx": "V", "vy": "V", "a": "A", "ax": "A", "ay": "A"}.get(key, key)
        return f"{head}_{self.point}" + {"vx": ",x", "vy": ",y", "ax": ",x", "ay": ",y"}.get(key, "")

    @property
    def direction(self) -> tuple[float, float]:
        """Unit direction of the frame guide (slider only)."""
        dx, dy = self.guide.direction
        n = math.hypot(dx, dy)
        return dx / n, dy / n


@dataclass(frozen=True)
class Sample:
    """One step of the revolution: the input angle (rad) and the values (SI), or why none."""

    angle: float
    values: dict[str, float]
    reason: str = ""


@dataclass(frozen=True)
class Event:
    """A refined zero: ``key`` ("v", "omega", "a", "alpha") is 0 at ``angle``; ``values`` there."""

    key: str
    angle: float
    values: dict[str, float]


@dataclass(frozen=True)
class Check:
    """One graphical value against the curve's at its position (SI)."""

    position: str
    angle: float
    key: str
    method: str
    graphical: float
    curve: float
    rel_error: float


@dataclass(frozen=True)
class Sweep:
    """A revolution of the input: the samples, refined zeros, and the graphical checks."""

    exercise: Exercise
    output: Output
    samples: tuple[Sample, ...]
    step: float
    events: tuple[Event, ...]
    checks: tuple[Check, ...]
    marks: tuple[tuple[str, float, float, str], ...]
    """(key, input angle, SI value, label) of each graphical value drawn on a curve."""
    notes: tuple[str, ...]
    rotates: bool = False
    """For a link: whether it turns fully (θ is then shown in [0°, 360°))."""

    @property
    def solved(self) -> list[Sample]:
        """The samples that assembled."""
        return [s for s in self.samples if s.values]

    def extent(self, key: str) -> tuple[float, float]:
        """Least and greatest value of ``key`` over the revolution, refined zeros included."""
        vals = [s.values[key] for s in self.solved] + [e.values[key] for e in self.events]
        return min(vals), max(vals)


# ----- which output ------------------------------------------------------------------------
def _moving_points(mech: Mechanism) -> list[str]:
    """Points not on the frame (a frame pivot is at rest)."""
    return [p for p in mech.point_names if 1 not in mech.links_at(p)]


def output_names(mech: Mechanism) -> list[str]:
    """The names ``--of`` takes: ``V_P``/``A_P`` of each moving point, ``omega<n>``/``alpha<n>``/
    ``theta<n>`` of each moving link."""
    points = [f"{h}_{p}" for p in _moving_points(mech) for h in "VA"]
    links = [f"{w}{n}" for n in sorted(mech.numbers) if n != 1
             for w in ("omega", "alpha", "theta")]
    return points + links


def pick_output(ex: Exercise, name: str | None = None) -> Output:
    """The output ``name`` names, or by default the exercise's first ``V_P``/``A_P``, else the
    point on a frame slider guide (a ram, a piston), else the highest-numbered link's ω.

    Raises
    ------
    InputError
        For a name that is not a point's velocity or acceleration nor a link's θ, ω
        or α, with the closest valid name.
    """
    mech = ex.mechanism
    valid = output_names(mech)
    if name is None:
        points = _moving_points(mech)
        name = next((q for q in ex.find if q[:2] in ("V_", "A_") and q[2:] in points), None)
        frame_slides = [s for s in mech.slides if s.guide_link == 1]
        if name is None and frame_slides:
            name = f"V_{frame_slides[0].point}"
        if name is None:
            name = f"omega{max(mech.numbers)}"
    if name not in valid:
        close = difflib.get_close_matches(name, valid, n=1, cutoff=0.0)
        raise InputError(f"cannot sweep '{name}': not a point's V_/A_ nor a link's "
                         f"omega/alpha/theta here; did you mean '{close[0]}'?")
    if name[:2] in ("V_", "A_"):
        p = name[2:]
        carrier = next(k for k in mech.links_at(p) if k != 1)
        guide = next((s for s in mech.slides if s.point == p and s.guide_link == 1), None)
        return Output("slider" if guide else "point", carrier, p, guide)
    return Output("link", int(re.sub(r"^\D+", "", name)))


# ----- the analytic values -----------------------------------------------------------------
def _evaluate(mech: Mechanism, out: Output, drive: Drive) -> dict[str, float]:
    """The output's values (SI) with the input at ``drive``; AssemblyError if it will not go."""
    m = mech.with_drive(drive)
    kin = analytic.solve(m)
    if out.kind == "link":
        n = out.link
        return {"theta": kin.angles[n], "omega": kin.omegas[n], "alpha": kin.alphas[n]}
    x, y = kin.points[out.point]
    vx, vy = analytic.point_velocity(kin, m, out.link, out.point)
    ax, ay = analytic.point_acceleration(kin, m, out.link, out.point)
    if out.kind == "slider":
        (dx, dy), (gx, gy) = out.direction, out.guide.through
        return {"x": x, "y": y, "s": (x - gx) * dx + (y - gy) * dy, "v": vx * dx + vy * dy,
                "a": ax * dx + ay * dy}
    return {"x": x, "y": y, "v": math.hypot(vx, vy), "vx": vx, "vy": vy,
            "a": math.hypot(ax, ay), "ax": ax, "ay": ay}


def _drive_at(mech: Mechanism, angle: float) -> Drive:
    d = mech.drive
    return Drive(d.link, angle, d.omega, d.alpha, d.alpha_given)


def sweep_exercise(ex: Exercise, steps: int = 360, *, of: str | None = None,
                   progress: Callable[[int], None] | None = None) -> Sweep:
    """Sweep ``ex``'s output over one revolution of its input and check its graphical positions.

    Parameters
    ----------
    ex : Exercise
        The exercise; its [input] angle is the first step, and its positions
        (``[ask] at``, or the [input] angle) are solved by construction and marked.
    steps : int
        Equal steps of the input angle over the revolution, in the sense of ω.
    of : str, optional
        The output (see :func:`pick_output`).
    progress : callable, optional
        Called with 1 after each step (a progress bar's ``update``).

    Raises
    ------
    InputError
        For an unknown output or a bad file (a missing branch).
    AssemblyError
        If not one position of the revolution assembles.
    """
    if steps < 4:
        raise InputError(f"a sweep needs at least 4 steps, got {steps}")
    mech = ex.mechanism
    out = pick_output(ex, of)
    d = mech.drive
    step = (-1.0 if d.omega < 0 else 1.0) * math.tau / steps
    samples = []
    for i in range(steps):
        angle = d.angle + i * step
        try:
            samples.append(Sample(angle, _evaluate(mech, out, _drive_at(mech, angle))))
        except analytic.SingularPosition as e:
            samples.append(Sample(angle, {}, f"dead point: {e}"))
        except AssemblyError as e:
            samples.append(Sample(angle, {}, f"cannot assemble: {e}"))
        if progress is not None:
            progress(1)
    failed = [s for s in samples if not s.values]
    if len(failed) == len(samples):
        raise AssemblyError(f"no position of the revolution of link {d.link} assembles; at the "
                            f"first, {failed[0].reason}", link=d.link)
    rotates = False
    if out.kind == "link":
        samples, rotates = _unwrap(samples)
    sw = Sweep(ex, out, tuple(samples), step, (), (), (), (), rotates)
    events = _events(sw)
    checks, marks, notes = _graphical(replace(sw, events=events))
    # Rounding noise beside the curve's own size is shown as 0 (errors are taken first).
    peak = {k: max(abs(s.values[k]) for s in sw.solved) for k in sw.solved[0].values}
    for k in peak:      # y of a ram on a guide along x is noise beside its x
        peak[k] = max(v for j, v in peak.items() if _KIND[j] == _KIND[k])

    def quiet(key: str, value: float) -> float:
        return 0.0 if abs(value) <= 1e-12 * peak[key] else value

    def quiet_all(values: dict[str, float]) -> dict[str, float]:
        return {k: quiet(k, v) for k, v in values.items()}

    return replace(sw, samples=tuple(replace(s, values=quiet_all(s.values)) for s in samples),
                   events=tuple(replace(e, values=quiet_all(e.values)) for e in events),
                   checks=tuple(replace(c, graphical=quiet(c.key, c.graphical),
                                        curve=quiet(c.key, c.curve)) for c in checks),
                   marks=tuple((k, a, quiet(k, v), t) for k, a, v, t in marks),
                   notes=tuple(notes))


def _unwrap(samples: list[Sample]) -> tuple[list[Sample], bool]:
    """Make θ continuous over the revolution; a link that turns fully is put in [0, 2π)."""
    prev, total, out = None, 0.0, []
    for s in samples:
        if not s.values:
            out.append(s)
            continue
        t = s.values["theta"]
        if prev is not None:
            t = prev + math.remainder(t - prev, math.tau)
            total += t - prev
        prev = t
        out.append(Sample(s.angle, {**s.values, "theta": t}))
    first = next(s.values["theta"] for s in out if s.values)
    rotates = abs(total + math.remainder(first - prev, math.tau)) > math.pi   # over the cycle
    mean = sum(s.values["theta"] for s in out if s.values) / sum(1 for s in out if s.values)
    shift = -math.tau * round(mean / math.tau)
    fixed = [Sample(s.angle, {**s.values, "theta": (s.values["theta"] % math.tau if rotates
                                                    else s.values["theta"] + shift)})
             if s.values else s for s in out]
    return fixed, rotates


def _theta_like(sw: Sweep, values: dict[str, float], angle: float) -> dict[str, float]:
    """Put a θ found off the grid in the curve's representation (nearest sample's turn)."""
    if sw.output.kind != "link":
        return values
    t = values["theta"]
    if sw.rotates:
        return {**values, "theta": t % math.tau}
    near = min(sw.solved, key=lambda s: abs(math.remainder(s.angle - angle, math.tau)))
    ref = near.values["theta"]
    return {**values, "theta": ref + math.remainder(t - ref, math.tau)}


# ----- refined zeros -----------------------------------------------------------------------
def _events(sw: Sweep) -> tuple[Event, ...]:
    """Zeros of the velocity and of the acceleration (scalar outputs), refined by bisection."""
    if sw.output.kind == "point":
        return ()
    _, (vkey,), (akey,) = _KEYS[sw.output.kind]
    out = []
    for key in (vkey, akey):
        peak = max(abs(s.values[key]) for s in sw.solved)
        if peak <= 1e-9 * _scale(sw.exercise.mechanism, _KIND[key]):
            continue        # identically zero (a crank's ω at constant speed, say)
        n = len(sw.samples)
        for i, a in enumerate(sw.samples):
            b = sw.samples[(i + 1) % n]
            if not (a.values and b.values):
                continue
            fa, fb = a.values[key], b.values[key]
            if fa == 0.0:
                out.append(Event(key, a.angle, a.values))
            elif fa * fb < 0.0:
                found = _bisect(sw, key, a.angle, fa, a.angle + sw.step)
                if found is not None:
                    out.append(found)
    return tuple(sorted(out, key=lambda e: (e.key, e.angle % math.tau)))


def _bisect(sw: Sweep, key: str, lo: float, flo: float, hi: float) -> Event | None:
    mech, out = sw.exercise.mechanism, sw.output
    for _ in range(60):
        if abs(hi - lo) < 1e-13:
            break
        mid = 0.5 * (lo + hi)
        try:
            fm = _evaluate(mech, out, _drive_at(mech, mid))[key]
        except AssemblyError:
            return None
        if fm == 0.0:
            lo = hi = mid
        elif (fm > 0.0) == (flo > 0.0):
            lo, flo = mid, fm
        else:
            hi = mid
    angle = 0.5 * (lo + hi)
    try:
        values = _evaluate(mech, out, _drive_at(mech, angle))
    except AssemblyError:
        return None
    return Event(key, angle, _theta_like(sw, values, angle))


# ----- the graphical positions -------------------------------------------------------------
def _scale(mech: Mechanism, kind: str) -> float:
    """The scale an error is taken relative to where the value itself is near 0."""
    d = mech.drive
    return {"velocity": mech.input_speed, "acceleration": mech.input_acceleration,
            "omega": abs(d.omega), "alpha": math.hypot(d.omega ** 2, d.alpha),
            "angle": 1.0}.get(kind, 1.0)


def _short(label: str) -> str:
    """"t = 2.34 s (θ2 = −44.07°)" → "t = 2.34 s"."""
    return label.split(" (")[0]


def _graphical(sw: Sweep) -> tuple[list[Check], list[tuple], list[str]]:
    """Solve each position by construction; put its values beside the curve's."""
    ex, out = sw.exercise, sw.output
    mech = ex.mechanism
    d = mech.drive
    positions = ex.positions or (None,)
    if out.kind == "link":
        groups = [] if out.link == d.link else [(f"omega{out.link}",), (f"alpha{out.link}",)]
    else:
        groups = [(f"V_{out.point}",), (f"A_{out.point}",)]
    checks: list[Check] = []
    marks: list[tuple] = []
    notes: list[str] = []
    if out.kind == "link" and out.link == d.link:
        notes.append(f"link {d.link} is the input: its θ, ω and α are given, so only its "
                     f"angle is marked")
    for p in positions:
        drive = p.drive if p else d
        label = _short(p.label) if p else f"θ{d.link} = {_angle_text(mech, d.angle)}"
        try:
            curve = _theta_like(sw, _evaluate(mech, out, drive), drive.angle)
        except AssemblyError as e:
            notes.append(f"{label}: not on the curve: {e}")
            continue
        if p is not None and p.drive.omega != d.omega:
            notes.append(f"{label}: ω{d.link} is {_number(p.drive.omega)} rad/s there, not the "
                         f"sweep's {_number(d.omega)} rad/s, so its marks stand off the curves")
        try:
            asm = assemble(mech.with_drive(drive))
        except TarsimError as e:
            notes.append(f"{label}: not constructed: {e}")
            continue
        for key, value in _compass_position(sw, asm, curve).items():
            checks.append(_check(label, drive.angle, key, "compass (position)", value,
                                 curve[key], asm.size))
            marks.append((key, drive.angle, value, label))
        for names in groups:
            try:
                sol = solve_positions(replace(ex, find=names, positions=(p,) if p else ()))[0]
            except TarsimError as e:
                notes.append(f"{label}: {', '.join(names)} not constructed: {e}")
                continue
            for name in names:
                q = sol.quantities[name]
                for method, qq in ((q.method, q), *q.alternatives.items()):
                    got = _from_quantity(out, name, qq.value)
                    key = next(iter(got))
                    checks.append(_check(label, drive.angle, key, method, got[key], curve[key],
                                         _scale(sol.exercise.mechanism, _KIND[key]),
                                         vector=_vector_pair(out, got, curve)))
                    if qq is q:
                        marks += [(k, drive.angle, v, label) for k, v in got.items()]
    return checks, marks, notes


def _compass_position(sw: Sweep, asm, curve: dict[str, float]) -> dict[str, float]:
    """Where the compass construction put the output (SI), keyed like the curve."""
    out = sw.output
    if out.kind == "link":
        k = asm.mechanism.link(out.link)
        if len(k.names) >= 2:
            (ax, ay), (bx, by) = asm.xy(k.names[0]), asm.xy(k.names[1])
            (lx, ly), (mx, my) = k.local(k.names[0]), k.local(k.names[1])
            t = math.atan2(by - ay, bx - ax) - math.atan2(my - ly, mx - lx)
        elif out.link in asm.axes:   # a lever carrying only its pivot: its slot's line,
            dx, dy = asm.construction.output(asm.axes[out.link]).direction   # turned as the curve
            t = math.atan2(dy, dx)
            t += math.pi * round(math.remainder(curve["theta"] - t, math.tau) / math.pi)
        else:
            return {}
        return {"theta": curve["theta"] + math.remainder(t - curve["theta"], math.tau)}
    x, y = asm.xy(out.point)
    if out.kind == "slider":
        (dx, dy), (gx, gy) = out.direction, out.guide.through
        return {"s": (x - gx) * dx + (y - gy) * dy}
    return {"x": x, "y": y}


def _from_quantity(out: Output, name: str, value: dict) -> dict[str, float]:
    """A solution's value (results.json shape, SI) as the curve's keys; the checked key first."""
    if name.startswith(("omega", "alpha")):
        return {name[:5]: value["value"]}
    key = "v" if name.startswith("V_") else "a"
    vx, vy = value["vector"]
    if out.kind == "slider":
        dx, dy = out.direction
        return {key: vx * dx + vy * dy}
    return {key: math.hypot(vx, vy), key + "x": vx, key + "y": vy}


def _vector_pair(out: Output, got: dict, curve: dict):
    if out.kind != "point" or len(got) < 3:
        return None
    k = next(iter(got))
    return (got[k + "x"], got[k + "y"]), (curve[k + "x"], curve[k + "y"])


def _check(label, angle, key, method, value, ref, scale, vector=None) -> Check:
    if vector is not None:
        (gx, gy), (cx, cy) = vector
        err = math.hypot(gx - cx, gy - cy) / max(math.hypot(cx, cy), scale, 1e-300)
    else:
        err = abs(value - ref) / max(abs(ref), scale, 1e-300)
    return Check(label, angle, key, method, value, ref, err)


# ----- units and words ---------------------------------------------------------------------
def _unit(mech: Mechanism, kind: str) -> tuple[float, str, str]:
    """(SI per unit, unit for people, unit for a CSV header) of a kind of value."""
    u = mech.units
    length = u.length
    return {"length": (u.metres, length, length),
            "velocity": (u.metres, f"{length}/s", f"{length}/s"),
            "acceleration": (u.metres, f"{length}/s²", f"{length}/s^2"),
            "angle": (1.0, "rad", "rad") if u.angle == "rad" else (math.pi / 180, "°", "deg"),
            "omega": ((math.tau / 60, "rpm", "rpm") if u.angular_velocity == "rpm"
                      else (1.0, "rad/s", "rad/s")),
            "alpha": (1.0, "rad/s²", "rad/s^2")}[kind]


def _in_units(mech: Mechanism, key: str, value: float) -> float:
    return value / _unit(mech, _KIND[key])[0] + 0.0


def _number(value: float, digits: int = 6) -> str:
    text = f"{value:.{digits}g}"
    return ("0" if float(text) == 0.0 else text).replace("-", "−")


def _angle_text(mech: Mechanism, angle: float) -> str:
    """An input angle in the file's unit, wrapped to one turn: "338.8998°", "90°"."""
    rad = mech.units.angle == "rad"
    value = angle % math.tau if rad else math.degrees(angle) % 360.0
    text = f"{value:.{5 if rad else 4}f}".rstrip("0").rstrip(".")
    text = "0" if float(text) in (0.0, 360.0, float(f"{math.tau:.5f}")) else text
    return f"{text} rad" if rad else f"{text}°"


def _shown(mech: Mechanism, key: str, value: float) -> str:
    """A value in the file's unit with its unit: "679.134 mm", "42.2004°"."""
    unit = _unit(mech, _KIND[key])[1]
    return f"{_number(_in_units(mech, key, value))}{'' if unit == '°' else ' '}{unit}"


def _words(sw: Sweep) -> tuple[str, str]:
    """What the output is, in words: ("B", " along its guide (+x)") or ("link 4 (lever)", "")."""
    out, mech = sw.output, sw.exercise.mechanism
    if out.kind == "link":
        return mech.link(out.link).label, ""
    if out.kind == "point":
        return out.point, ""
    dx, dy = out.direction
    named = {(1.0, 0.0): "+x", (-1.0, 0.0): "−x", (0.0, 1.0): "+y", (0.0, -1.0): "−y"}
    way = named.get((round(dx, 12) + 0.0, round(dy, 12) + 0.0))
    return out.point, f" along its guide ({way or _number(math.degrees(math.atan2(dy, dx))) + '°'})"


def _turning(sw: Sweep) -> str:
    """"360 positions from θ2 = 90°, ω2 = 1 rad/s cw, α2 = 0"."""
    mech = sw.exercise.mechanism
    d = mech.drive
    factor, unit, _ = _unit(mech, "omega")
    sense = "cw" if d.omega < 0 else "ccw"
    w = f"ω_{d.link} = {_number(abs(d.omega) / factor)} {unit} {sense}" if d.omega else \
        f"ω_{d.link} = 0"
    a = f"α_{d.link} = {_number(d.alpha)} rad/s²" if d.alpha else f"α_{d.link} = 0"
    return (f"{len(sw.samples)} positions from θ_{d.link} = {_angle_text(mech, d.angle)}, "
            f"{w}, {a}")


def _event_lines(sw: Sweep, figure: int) -> list[str]:
    """What a figure says of the refined zeros: 0 position, 1 velocity, 2 acceleration."""
    if sw.output.kind == "point" or sw.rotates:
        return []
    mech = sw.exercise.mechanism
    (pkey, *_), (vkey,), (akey,) = _KEYS[sw.output.kind]
    p, v, a = (sw.output.symbol(k) for k in (pkey, vkey, akey))
    th = f"θ_{mech.drive.link}"

    def at(e: Event, key: str) -> str:
        return f"{_shown(mech, key, e.values[key])} ({th} = {_angle_text(mech, e.angle)})"

    def where(events: list[Event]) -> str:
        return f"{th} = " + ", ".join(_angle_text(mech, e.angle) for e in events)

    v_zero = [e for e in sw.events if e.key == vkey]
    a_zero = [e for e in sw.events if e.key == akey]
    lines = []
    if figure == 0:
        items = [(e.angle, e.values) for e in v_zero] + [(s.angle, s.values) for s in sw.solved]
        low, high = (f(items, key=lambda it: it[1][pkey]) for f in (min, max))
        both = all(any(e.angle == it[0] for e in v_zero) for it in (low, high))
        what = "stroke" if sw.output.kind == "slider" else "swing"
        if high[1][pkey] - low[1][pkey] <= 1e-12 * max(1.0, abs(high[1][pkey])):
            return [f"{p} stays {_shown(mech, pkey, high[1][pkey])}"]
        lines.append(f"{p} from {at(Event(vkey, *low), pkey)} to {at(Event(vkey, *high), pkey)}"
                     f"{f', where {v} = 0' if both else ''}: "
                     f"{what} {_shown(mech, pkey, high[1][pkey] - low[1][pkey])}")
    if v_zero and figure == 1:
        lines.append(f"{v} = 0 at {where(v_zero)}, where {p} is extreme")
    if a_zero and figure == 1:
        low, high = (f(a_zero, key=lambda e: e.values[vkey]) for f in (min, max))
        lines.append(f"{v} peaks at {at(low, vkey)} and {at(high, vkey)}, where {a} = 0")
    if a_zero and figure == 2:
        lines.append(f"{a} = 0 at {where(a_zero)}, where {v} peaks")
    return lines


def _gaps(sw: Sweep) -> list[str]:
    """Runs of skipped positions as "θ2 = 170°…190°: cannot assemble: …" (the first reason)."""
    mech = sw.exercise.mechanism
    out, run = [], []
    for s in (*sw.samples, Sample(0.0, {"end": 0.0})):
        if not s.values:
            run.append(s)
            continue
        if run:
            span = _angle_text(mech, run[0].angle)
            if len(run) > 1:
                span += f"…{_angle_text(mech, run[-1].angle)}"
            out.append(f"θ_{mech.drive.link} = {span} ({len(run)} skipped): {run[0].reason}")
            run = []
    return out


# ----- figures -------------------------------------------------------------------------------
def sweep_figures(sw: Sweep) -> dict[str, Figure]:
    """The position, velocity and acceleration plots: ``{file stem: figure}``."""
    mech = sw.exercise.mechanism
    out = sw.output
    deg = mech.units.angle != "rad"
    full = 360.0 if deg else math.tau
    link = mech.drive.link
    if deg:
        ticks = [(float(a), str(a)) for a in range(0, 361, 30)]
    else:
        names = ["0", "π/4", "π/2", "3π/4", "π", "5π/4", "3π/2", "7π/4", "2π"]
        ticks = [(i * math.pi / 4, t) for i, t in enumerate(names)]

    def x_of(angle: float) -> float:
        return (math.degrees(angle) % 360.0) if deg else angle % math.tau

    order = sorted(sw.samples, key=lambda s: x_of(s.angle))
    who, along = _words(sw)
    title = mech.name or sw.exercise.id
    stems = ("sweep-position", "sweep-velocity", "sweep-acceleration")
    quantity = ("position", "velocity", "acceleration")
    if out.kind == "link":
        quantity = ("angle", "angular velocity", "angular acceleration")
    figures = {}
    for i, keys in enumerate(_KEYS[out.kind]):
        if out.kind == "slider":
            keys = keys[:1]
        series = []
        for j, key in enumerate(keys):
            pts = [(x_of(s.angle), _in_units(mech, key, s.values[key])) if s.values else None
                   for s in order]
            first, last = pts[0], pts[-1]       # one turn: run a step past each end
            pts = ([(last[0] - full, last[1])] if last else []) + pts + \
                  ([(first[0] + full, first[1])] if first else [])
            if key == "theta" and sw.rotates:
                pts = _break_jumps(pts, full / 2)
            label = out.symbol(key)
            if out.kind == "point" and i > 0:
                label = {0: f"|{label}|", 1: "x component", 2: "y component"}[j]
            series.append(Series(label, tuple(pts), CURVE_STYLES[j % len(CURVE_STYLES)]))
        marks, labelled = [], set()
        for key, angle, value, text in sw.marks:
            if key in keys:
                first = text not in labelled
                labelled.add(text)
                marks.append(PlotMark(x_of(angle), _in_units(mech, key, value),
                                      re.sub(r"θ(\d+)", r"θ_\1", text) if first else ""))
        unit = _unit(mech, _KIND[keys[0]])[1]
        y_label = ", ".join(out.symbol(k) for k in keys[:1 if out.kind != "point" or i else 2])
        sub = (f"{quantity[i].capitalize()} of {who}{along} over one turn of "
               f"{mech.link(link).label}")
        notes = [_turning(sw) + "; curves by the analytic (vector-loop) solver"]
        notes += _event_lines(sw, i)
        notes += [f"gap at {g}" for g in _gaps(sw)][:3]
        worst = max((c.rel_error for c in sw.checks if c.key in keys), default=None)
        legend = "" if worst is None else "solved by construction" + (
            f" (off the curve by {worst:.0e} at most)" if worst else " (on the curve exactly)")
        figures[stems[i]] = draw_line_plot(
            title, f"θ_{link} ({'°' if deg else 'rad'})", f"{y_label} ({unit})", series, marks,
            x_range=(0.0, full), x_ticks=ticks, subtitle=sub, notes=notes, mark_legend=legend,
            include_zero=i > 0, y_ticks=[k * full / 4 for k in range(5)] if i == 0 and sw.rotates
            else ())
    return figures


def _break_jumps(pts, jump: float):
    """Break a curve where it jumps by more than ``jump`` (θ wrapping past 360°)."""
    out = []
    for p in pts:
        if p is not None and out and out[-1] is not None and abs(p[1] - out[-1][1]) > jump:
            out.append(None)
        out.append(p)
    return out


# ----- files ---------------------------------------------------------------------------------
def _ascii(out: Output, key: str) -> str:
    """A column's name for a CSV header: "V_B", "Vx_B", "omega4"."""
    if out.kind == "link":
        return f"{key}{out.link}"
    head = {"v": "V", "vx": "Vx", "vy": "Vy", "a": "A", "ax": "Ax", "ay": "Ay"}.get(key, key)
    return f"{head}_{out.point}"


def _csv(rows: list[list[str]]) -> str:
    buf = io.StringIO()
    csv.writer(buf, lineterminator="\n").writerows(rows)
    return buf.getvalue()


def _cell(value: float) -> str:
    text = f"{value:.10g}"
    return "0" if float(text) == 0.0 else text


def sweep_csv(sw: Sweep) -> str:
    """The table, one row per step in the sweep's order, in the file's units."""
    mech = sw.exercise.mechanism
    out = sw.output
    d = mech.drive
    keys = [k for group in _KEYS[out.kind] for k in group]
    if out.kind == "slider":
        keys = ["x", "y", "s", "v", "a"]
    elif out.kind == "point":
        keys = ["x", "y", "vx", "vy", "v", "ax", "ay", "a"]
    timed = d.omega != 0.0 and d.alpha == 0.0
    head = [f"theta{d.link} ({_unit(mech, 'angle')[2]})"] + (["t (s)"] if timed else [])
    head += [f"{_ascii(out, k)} ({_unit(mech, _KIND[k])[2]})" for k in keys]
    rows = [head + ["note"]]
    a_unit = _unit(mech, "angle")[0]
    for i, s in enumerate(sw.samples):
        angle = (s.angle % math.tau) / a_unit
        row = [_cell(float(f"{angle:.10g}") % (math.tau / a_unit))]
        if timed:
            row.append(_cell(i * abs(sw.step) / abs(d.omega)))
        if s.values:
            row += [_cell(_in_units(mech, k, s.values[k])) for k in keys] + [""]
        else:
            row += [""] * len(keys) + [s.reason]
        rows.append(row)
    return _csv(rows)


def points_csv(sw: Sweep) -> str:
    """The graphical values against the curve's, one row per position, quantity and method."""
    mech = sw.exercise.mechanism
    rows = [["position", f"theta{mech.drive.link} ({_unit(mech, 'angle')[2]})", "quantity",
             "method", "unit", "graphical", "curve", "rel_error"]]
    for c in sw.checks:
        unit = _unit(mech, _KIND[c.key])
        rows.append([c.position, _cell((c.angle % math.tau) / _unit(mech, "angle")[0]),
                     _ascii(sw.output, c.key), c.method, unit[2],
                     _cell(_in_units(mech, c.key, c.graphical)),
                     _cell(_in_units(mech, c.key, c.curve)), f"{c.rel_error:.2e}"])
    return _csv(rows)


def sweep_to_files(sw: Sweep, *, pdf: bool = False) -> dict[str, str | bytes]:
    """Render everything in memory: ``{file name: text or bytes}``.

    Raises
    ------
    RenderError
        If ``pdf`` is asked and libcairo2 is missing.
    """
    files: dict[str, str | bytes] = {"sweep.csv": sweep_csv(sw)}
    if sw.checks:
        files["sweep-points.csv"] = points_csv(sw)
    for stem, fig in sweep_figures(sw).items():
        svg = to_svg(fig)
        files[f"{stem}.svg"] = svg
        if pdf:
            files[f"{stem}.pdf"] = svg_to(svg, "pdf")
    return files


def write_sweep(files: dict[str, str | bytes], out_dir: str | Path) -> list[Path]:
    """Write the rendered files into ``out_dir`` (made if missing), each atomically.

    Raises
    ------
    RenderError
        If the folder cannot be made or a file written.
    """
    out = Path(out_dir)
    try:
        out.mkdir(parents=True, exist_ok=True)
    except OSError as e:
        raise RenderError(f"cannot make the folder '{out}': {e.strerror}") from None
    return [write_text(out / name, data) for name, data in files.items()]


# ----- the report ----------------------------------------------------------------------------
def format_sweep(sw: Sweep) -> str:
    """What the command line prints: the turn, the refined extremes, the checks, the gaps."""
    mech = sw.exercise.mechanism
    who, along = _words(sw)
    solved = len(sw.solved)
    lines = [f"{mech.name or sw.exercise.id}: {who}{along}",
             _plain(_turning(sw)) + f"; {solved} solved, {len(sw.samples) - solved} skipped"]
    lines += [_plain(line) for i in range(3) for line in _event_lines(sw, i)]
    lines += [f"gap at {_plain(g)}" for g in _gaps(sw)]
    if sw.checks:
        lines.append("")
        lines.append(f"{'position':<14}{'quantity':<10}{'method':<28}{'graphical':<18}"
                     f"{'curve':<18}rel. error")
        for c in sw.checks:
            lines.append(f"{c.position:<14}{_plain(sw.output.symbol(c.key)):<10}"
                         f"{c.method:<28}{_shown(mech, c.key, c.graphical):<18}"
                         f"{_shown(mech, c.key, c.curve):<18}{c.rel_error:.1e}")
    lines += [f"note: {n}" for n in sw.notes]
    return "\n".join(lines)


def _plain(text: str) -> str:
    """Drop the subscript marks for the terminal: "θ_2" → "θ2", "V_B" stays "V_B"."""
    return re.sub(r"([θωα])_(\d+)", r"\1\2", text)
