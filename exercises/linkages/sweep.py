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

import difflib
import math
import re
from collections.abc import Callable
from dataclasses import dataclass, replace

from tarsim.constructions.asks import SYMBOLS, Acceleration, Velocity
from tarsim.constructions.checks import NOISE
from tarsim.constructions.reference import solver
from tarsim.constructions.reference.change_points import change_point_between
from tarsim.constructions.reference.limits import section_zero
from tarsim.constructions.reference.turn import Turn, solve_turn
from tarsim.constructions.linkages.assembly import assemble
from tarsim.constructions.errors import AssemblyError, InputError, TarsimError
from tarsim.constructions.linkages.limit_positions import stroke_point
from tarsim.constructions.joints import Slide
from tarsim.constructions.model import Drive, Mechanism

from .exercise_file import Exercise
from tarsim.constructions.linkages.given_rate import convert
from .solution import solve_positions

__all__ = ["Output", "Sample", "Event", "Check", "Sweep", "output_names", "pick_output",
           "sweep_exercise", "KEYS", "KINDS", "angle_text", "number_text"]

# Column keys by output kind: position, velocity, acceleration (the plotted ones first).
KEYS = {"slider": (("s", "x", "y"), ("v",), ("a",)),
         "point": (("x", "y"), ("v", "vx", "vy"), ("a", "ax", "ay")),
         "link": (("theta",), ("omega",), ("alpha",))}
KINDS = {"x": "length", "y": "length", "s": "length", "v": "velocity", "vx": "velocity",
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
            return SYMBOLS[key] + f"_{self.link}"
        head = {"v": "V", "vx": "V", "vy": "V", "a": "A", "ax": "A", "ay": "A"}.get(key, key)
        axis = {"vx": ",x", "vy": ",y", "ax": ",x", "ay": ",y"}.get(key, "")
        return f"{head}_{self.point}{axis}"

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
        name = next((a.name for a in ex.asks if isinstance(a, (Velocity, Acceleration))
                     and a.point in points), None)
        ram = stroke_point(mech)
        if name is None and ram is not None:
            name = f"V_{ram}"
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
    kin = solver.solve(m)
    if out.kind == "link":
        n = out.link
        return _values(out, kin.angles[n], kin.omegas[n], kin.alphas[n])
    return _values(out, kin.points[out.point], solver.point_velocity(kin, m, out.link, out.point),
                   solver.point_acceleration(kin, m, out.link, out.point), m.origin)


def _turn_values(turn: Turn, out: Output) -> dict[int, dict[str, float]]:
    """The output's values (SI) at each position of ``turn`` that assembles, by index."""
    n, p = out.link, out.point
    columns = ([turn.angles[n], turn.omegas[n], turn.alphas[n]] if out.kind == "link" else
               [turn.points[p], turn.velocity_on(n, p), turn.acceleration_on(n, p)])
    rows = zip(*(c.tolist() for c in columns))
    origin = turn.mechanism.origin
    return {i: _values(out, *row, origin)
            for i, (ok, row) in enumerate(zip(turn.ok.tolist(), rows)) if ok}


def _values(out: Output, position, velocity, acceleration,
            origin: tuple[float, float] = (0.0, 0.0)) -> dict[str, float]:
    """The output's keys from its position, velocity and acceleration (θ, ω, α of a link);
    a point's x and y are said in the file's axes, the model's moved by ``origin``."""
    if out.kind == "link":
        return {"theta": position, "omega": velocity, "alpha": acceleration}
    (x, y), (vx, vy), (ax, ay) = position, velocity, acceleration
    at = {"x": x + origin[0], "y": y + origin[1]}
    if out.kind == "slider":
        (dx, dy), (gx, gy) = out.direction, out.guide.through
        return {**at, "s": (x - gx) * dx + (y - gy) * dy, "v": vx * dx + vy * dy,
                "a": ax * dx + ay * dy}
    return {**at, "v": math.hypot(vx, vy), "vx": vx, "vy": vy,
            "a": math.hypot(ax, ay), "ax": ax, "ay": ay}


def _drive_at(mech: Mechanism, angle: float) -> Drive:
    return replace(mech.drive, angle=angle)


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
    if ex.mechanism.given is not None:
        # An input given by another member: its rates at the stated position, as the
        # solver converts them, held through the turn (the crank at constant ω and α).
        ex = replace(ex, mechanism=convert(ex.mechanism)[1])
    mech = ex.mechanism
    out = pick_output(ex, of)
    d = mech.drive
    step = (-1.0 if d.omega < 0 else 1.0) * math.tau / steps
    angles = [d.angle + i * step for i in range(steps)]
    turn = solve_turn(mech, angles)          # the whole revolution at once
    values, samples = _turn_values(turn, out), []
    for i, angle in enumerate(angles):
        if i in values:
            samples.append(Sample(angle, values[i]))
        else:
            e = turn.refusal(i)
            why = "dead point" if isinstance(e, solver.SingularPosition) else "cannot assemble"
            samples.append(Sample(angle, {}, f"{why}: {e}"))
        if progress is not None:
            progress(1)
    failed = [s for s in samples if not s.values]
    if len(failed) == len(samples):
        first = turn.refusal(0)               # its link is the one to change
        raise AssemblyError(f"no position of the revolution of link {d.link} assembles; at the "
                            f"first, {failed[0].reason}", link=first.link, joint=first.joint)
    rotates = False
    if out.kind == "link":
        samples, rotates = _unwrap(samples)
    sw = Sweep(ex, out, tuple(samples), step, (), (), (), (), rotates)
    events = _events(sw)
    checks, marks, notes = _graphical(replace(sw, events=events))
    notes += _change_point(mech, angles, turn)
    # Rounding noise beside the curve's own size is shown as 0 (errors are taken first).
    solved = sw.solved
    peak = {k: max(map(abs, [s.values[k] for s in solved])) for k in solved[0].values}
    for k in peak:      # y of a ram on a guide along x is noise beside its x
        peak[k] = max(v for j, v in peak.items() if KINDS[j] == KINDS[k])

    floor = {k: NOISE * v for k, v in peak.items()}

    def quiet(key: str, value: float) -> float:
        return 0.0 if abs(value) <= floor[key] else value

    def quiet_all(values: dict[str, float]) -> dict[str, float]:
        return {k: 0.0 if abs(v) <= floor[k] else v for k, v in values.items()}

    # Each of the turn's samples made afresh rather than by dataclasses.replace: thousands of
    # them, where replace's own checks cost more than the quieting.
    return replace(sw, samples=tuple(Sample(s.angle, quiet_all(s.values), s.reason)
                                     for s in samples),
                   events=tuple(replace(e, values=quiet_all(e.values)) for e in events),
                   checks=tuple(replace(c, graphical=quiet(c.key, c.graphical),
                                        curve=quiet(c.key, c.curve)) for c in checks),
                   marks=tuple((k, a, quiet(k, v), t) for k, a, v, t in marks),
                   notes=tuple(notes))


def _change_point(mech: Mechanism, angles: list[float], turn: Turn) -> list[str]:
    """A word where the turn passes a change point: the curves then keep the side their
    [assembly] names, and so go on in the other assembly beyond it, one motion to another."""
    rconds = [c if ok else None for c, ok in zip(turn.conditioning.tolist(), turn.ok.tolist())]
    found = change_point_between(mech, angles, rconds)
    if found is None:
        return []
    d = mech.drive
    return [f"the turn passes a change point at θ{d.link} = {angle_text(mech, found.angle)}, "
            "where the linkage may go on in either assembly: beyond it the curves keep their "
            "[assembly] side, so they may pass from one motion to the other there"]


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
    _, (vkey,), (akey,) = KEYS[sw.output.kind]
    out = [e for key in (vkey, akey) for e in _zeros(sw, key)]
    return tuple(sorted(out, key=lambda e: (e.key, e.angle % math.tau)))


def _zeros(sw: Sweep, key: str) -> list[Event]:
    """Where ``key`` crosses 0 (bisected) or comes to rest at it over the turn.

    A value within rounding of 0 beside the larger of its peak and its scale is 0: a rocker
    held still over part of the turn (a rhombus folded) flickers about 0, and its flicker
    is no reversal to look for.
    """
    peak = max(abs(s.values[key]) for s in sw.solved)
    scale = _scale(sw.exercise.mechanism, KINDS[key])
    if peak <= 1e-9 * scale:
        return []           # identically zero (a crank's ω at constant speed, say)
    floor = NOISE * max(peak, scale)
    out, n = [], len(sw.samples)
    for i, a in enumerate(sw.samples):
        b, before = sw.samples[(i + 1) % n], sw.samples[i - 1]
        if not (a.values and b.values):
            continue
        fa, fb = a.values[key], b.values[key]
        if abs(fa) <= floor:
            if not (before.values and abs(before.values[key]) <= floor):   # at rest from here
                out.append(Event(key, a.angle, a.values))
        elif fa * fb < 0.0 and abs(fb) > floor:
            found = _bisect(sw, key, a.angle, fa, a.angle + sw.step)
            if found is not None:
                out.append(found)
    return out


def _bisect(sw: Sweep, key: str, lo: float, flo: float, hi: float) -> Event | None:
    """The zero of ``key`` between ``lo`` and ``hi`` (narrowed to the last bit, many angles
    a round), or None if a position on the way will not assemble."""
    mech, out = sw.exercise.mechanism, sw.output

    def along(angles):
        values = _turn_values(solve_turn(mech, angles), out)
        if len(values) < len(angles):
            raise AssemblyError(f"a position between {lo} and {hi} rad will not assemble")
        return [values[i][key] for i in range(len(angles))]

    try:
        angle = section_zero(along, lo, hi, flo)
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
        label = _short(p.label) if p else f"θ{d.link} = {angle_text(mech, d.angle)}"
        try:
            curve = _theta_like(sw, _evaluate(mech, out, drive), drive.angle)
        except AssemblyError as e:
            notes.append(f"{label}: not on the curve: {e}")
            continue
        if p is not None and p.drive.omega != d.omega:
            notes.append(f"{label}: ω{d.link} is {number_text(p.drive.omega)} rad/s there, not the "
                         f"sweep's {number_text(d.omega)} rad/s, so its marks stand off the curves")
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
                sol = solve_positions(replace(ex.asking(names), positions=(p,) if p else ()))[0]
            except TarsimError as e:
                notes.append(f"{label}: {', '.join(names)} not constructed: {e}")
                continue
            for name in names:
                q = sol.quantities[name]
                for method, qq in ((q.method, q), *q.alternatives.items()):
                    got = _from_quantity(out, name, qq.value)
                    key = next(iter(got))
                    checks.append(_check(label, drive.angle, key, method, got[key], curve[key],
                                         _scale(sol.exercise.mechanism, KINDS[key]),
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
            dx, dy = asm.output(asm.axes[out.link]).direction   # turned as the curve
            t = math.atan2(dy, dx)
            t += math.pi * round(math.remainder(curve["theta"] - t, math.tau) / math.pi)
        else:
            return {}
        return {"theta": curve["theta"] + math.remainder(t - curve["theta"], math.tau)}
    x, y = asm.xy(out.point)
    if out.kind == "slider":
        (dx, dy), (gx, gy) = out.direction, out.guide.through
        return {"s": (x - gx) * dx + (y - gy) * dy}
    return dict(zip("xy", asm.mechanism.in_file_axes((x, y))))


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


# ----- numbers and angles, as the graphical checks state them ---------------------------
def number_text(value: float, digits: int = 6) -> str:
    """A number as the tables print it: ``digits`` significant figures, a true minus."""
    text = f"{value:.{digits}g}"
    return ("0" if float(text) == 0.0 else text).replace("-", "−")


def angle_text(mech: Mechanism, angle: float) -> str:
    """An input angle in the file's unit, wrapped to one turn: "338.8998°", "90°"."""
    rad = mech.units.angle == "rad"
    value = angle % math.tau if rad else math.degrees(angle) % 360.0
    text = f"{value:.{5 if rad else 4}f}".rstrip("0").rstrip(".")
    text = "0" if float(text) in (0.0, 360.0, float(f"{math.tau:.5f}")) else text
    return f"{text} rad" if rad else f"{text}°"
