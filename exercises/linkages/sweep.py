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

import math
from collections.abc import Callable
from dataclasses import dataclass, field, replace
from functools import cached_property
from itertools import repeat

import numpy as np

from tarsim.constructions.checks import NOISE
from tarsim.constructions.reference import solver
from tarsim.constructions.reference.change_points import change_point_between
from tarsim.constructions.reference.limits import section_zero
from tarsim.constructions.reference.turn import Turn, TurnSolver
from tarsim.constructions.linkages.assembly import assemble
from tarsim.constructions.errors import AssemblyError, InputError, TarsimError
from tarsim.constructions.model import Mechanism

from .exercise_file import Exercise
from tarsim.constructions.linkages.given_rate import convert
from .solution import solve_positions
from .sweep_output import (KEYS, KINDS, Output, curves_of, drive_at, evaluate, output_names,
                           pick_output, scale_of)

__all__ = ["Output", "Sample", "Event", "Check", "Sweep", "output_names", "pick_output",
           "sweep_exercise", "KEYS", "KINDS", "angle_text", "number_text"]


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
    """A revolution of the input: its curves, refined zeros, and the graphical checks.

    The curves are columns, one array a key over the steps (SI; NaN at a step that did not
    assemble, whose reason is in ``reasons``): a turn of thousands of steps is a few array
    operations. :attr:`samples` gives the same steps one by one, made when first read.
    """

    exercise: Exercise
    output: Output
    angles: tuple[float, ...]
    """The input angle at each step (rad)."""
    curves: dict[str, np.ndarray] = field(compare=False)
    """Each key's values over the steps, in :func:`.sweep_output.values_of`' order of keys."""
    reasons: tuple[str, ...]
    """Why each step has no values ("dead point: …", "cannot assemble: …"); "" if it has."""
    step: float
    events: tuple[Event, ...]
    checks: tuple[Check, ...]
    marks: tuple[tuple[str, float, float, str], ...]
    """(key, input angle, SI value, label) of each graphical value drawn on a curve."""
    notes: tuple[str, ...]
    rotates: bool = False
    """For a link: whether it turns fully (θ is then shown in [0°, 360°))."""

    @cached_property
    def samples(self) -> tuple[Sample, ...]:
        """Each step of the revolution: its angle and values, or why it has none."""
        rows = zip(*(c.tolist() for c in self.curves.values()))
        values = list(map(dict, map(zip, repeat(tuple(self.curves)), rows)))
        for i, why in enumerate(self.reasons):
            if why:
                values[i] = {}
        return tuple(map(Sample, self.angles, values, self.reasons))

    @property
    def solved(self) -> list[Sample]:
        """The samples that assembled."""
        return [s for s in self.samples if s.values]

    def extent(self, key: str) -> tuple[float, float]:
        """Least and greatest value of ``key`` over the revolution, refined zeros included."""
        vals = [s.values[key] for s in self.solved] + [e.values[key] for e in self.events]
        return min(vals), max(vals)

    def values_at(self, i: int) -> dict[str, float]:
        """The values at step ``i`` (one that assembled)."""
        return {k: c[i].item() for k, c in self.curves.items()}


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
    turned = d.angle + np.arange(steps) * step       # as d.angle + i * step in floats
    turns = TurnSolver(mech)              # the turn, then its zeros' bisections
    turn = turns.solve(turned)              # the whole revolution at once
    curves, ok = curves_of(turn, out), turn.ok
    reasons = [""] * steps
    for i in np.flatnonzero(~ok).tolist():
        reasons[i] = _refusal(turn.refusal(i))
    angles = tuple(turned.tolist())
    if progress is not None:
        for _ in angles:
            progress(1)
    if not ok.any():
        first = turn.refusal(0)               # its link is the one to change
        raise AssemblyError(f"no position of the revolution of link {d.link} assembles; at the "
                            f"first, {reasons[0]}", link=first.link, joint=first.joint)
    rotates = False
    if out.kind == "link":
        curves["theta"], rotates = _unwrap(curves["theta"], ok)
    sw = Sweep(ex, out, angles, curves, tuple(reasons), step, (), (), (), (), rotates)
    events = _events(sw, turns)
    checks, marks, notes = _graphical(replace(sw, events=events))
    notes += _change_point(mech, list(angles), turn)
    # Rounding noise beside the curve's own size is shown as 0 (errors are taken first).
    peak = {k: float(np.max(np.abs(c if ok.all() else c[ok]))) for k, c in curves.items()}
    for k in peak:      # y of a ram on a guide along x is noise beside its x
        peak[k] = max(v for j, v in peak.items() if KINDS[j] == KINDS[k])

    floor = {k: NOISE * v for k, v in peak.items()}

    def quiet(key: str, value: float) -> float:
        return 0.0 if abs(value) <= floor[key] else value

    def quiet_all(values: dict[str, float]) -> dict[str, float]:
        return {k: 0.0 if abs(v) <= floor[k] else v for k, v in values.items()}

    return replace(sw, curves={k: np.where(np.abs(c) <= floor[k], 0.0, c)
                               for k, c in curves.items()},
                   events=tuple(replace(e, values=quiet_all(e.values)) for e in events),
                   checks=tuple(replace(c, graphical=quiet(c.key, c.graphical),
                                        curve=quiet(c.key, c.curve)) for c in checks),
                   marks=tuple((k, a, quiet(k, v), t) for k, a, v, t in marks),
                   notes=tuple(notes))


def _refusal(e: AssemblyError) -> str:
    """Why a step has no values, as its row says it."""
    why = "dead point" if isinstance(e, solver.SingularPosition) else "cannot assemble"
    return f"{why}: {e}"


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


def _unwrap(theta: np.ndarray, ok: np.ndarray) -> tuple[np.ndarray, bool]:
    """Make θ continuous over the revolution; a link that turns fully is put in [0, 2π).
    Step by step in floats, each step's turn taken from the last's."""
    at = np.flatnonzero(ok).tolist()
    prev, total, out = None, 0.0, []
    for t in theta[at].tolist():
        if prev is not None:
            t = prev + math.remainder(t - prev, math.tau)
            total += t - prev
        prev = t
        out.append(t)
    rotates = abs(total + math.remainder(out[0] - prev, math.tau)) > math.pi   # over the cycle
    shift = -math.tau * round(sum(out) / len(out) / math.tau)
    fixed = theta.copy()
    fixed[at] = [t % math.tau if rotates else t + shift for t in out]
    return fixed, rotates


def _theta_like(sw: Sweep, values: dict[str, float], angle: float) -> dict[str, float]:
    """Put a θ found off the grid in the curve's representation (nearest sample's turn)."""
    if sw.output.kind != "link":
        return values
    t = values["theta"]
    if sw.rotates:
        return {**values, "theta": t % math.tau}
    far = [abs(math.remainder(a - angle, math.tau)) if not why else math.inf
           for a, why in zip(sw.angles, sw.reasons)]
    ref = sw.curves["theta"][far.index(min(far))].item()
    return {**values, "theta": ref + math.remainder(t - ref, math.tau)}


# ----- refined zeros -----------------------------------------------------------------------
def _events(sw: Sweep, turns: TurnSolver) -> tuple[Event, ...]:
    """Zeros of the velocity and of the acceleration (scalar outputs), refined by bisection."""
    if sw.output.kind == "point":
        return ()
    _, (vkey,), (akey,) = KEYS[sw.output.kind]
    out = [e for key in (vkey, akey) for e in _zeros(sw, key, turns)]
    return tuple(sorted(out, key=lambda e: (e.key, e.angle % math.tau)))


def _zeros(sw: Sweep, key: str, turns: TurnSolver) -> list[Event]:
    """Where ``key`` crosses 0 (bisected) or comes to rest at it over the turn.

    A value within rounding of 0 beside the larger of its peak and its scale is 0: a rocker
    held still over part of the turn (a rhombus folded) flickers about 0, and its flicker
    is no reversal to look for. The steps are compared all at once with the next and the
    last (the turn closes on itself); only those that cross or come to rest are refined.
    """
    f = sw.curves[key]
    solved = np.array([not why for why in sw.reasons])
    peak = float(np.max(np.abs(f[solved])))
    scale = scale_of(sw.exercise.mechanism, KINDS[key])
    if peak <= 1e-9 * scale:
        return []           # identically zero (a crank's ω at constant speed, say)
    floor = NOISE * max(peak, scale)
    after, ok_after = np.roll(f, -1), np.roll(solved, -1)
    still = np.abs(f) <= floor
    rests = solved & ok_after & still & ~(np.roll(solved, 1) & np.roll(still, 1))
    crosses = (solved & ok_after & ~still & (f * after < 0.0)
               & (np.abs(after) > floor))
    out = []
    for i in np.flatnonzero(rests | crosses).tolist():
        a = sw.angles[i]
        if rests[i]:
            out.append(Event(key, a, sw.values_at(i)))
            continue
        found = _bisect(sw, key, a, f[i].item(), a + sw.step, turns)
        if found is not None:
            out.append(found)
    return out


def _bisect(sw: Sweep, key: str, lo: float, flo: float, hi: float,
            turns: TurnSolver) -> Event | None:
    """The zero of ``key`` between ``lo`` and ``hi`` (narrowed to the last bit, many angles
    a round), or None if a position on the way will not assemble."""
    mech, out = sw.exercise.mechanism, sw.output

    def along(angles):
        turn = turns.solve(angles)
        if not turn.ok.all():
            raise AssemblyError(f"a position between {lo} and {hi} rad will not assemble")
        return curves_of(turn, out)[key]

    try:
        angle = section_zero(along, lo, hi, flo)
        values = evaluate(mech, out, drive_at(mech, angle))
    except AssemblyError:
        return None
    return Event(key, angle, _theta_like(sw, values, angle))


# ----- the graphical positions -------------------------------------------------------------
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
            curve = _theta_like(sw, evaluate(mech, out, drive), drive.angle)
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
        # A point's V and A asked at once draw the polygons once, not once each, and are
        # answered as alone: the methods of a velocity do not hang on what else is asked
        # (a link's ω does: the velocity polygon drawn for its α answers it too).
        try:
            together = _constructed(ex, p, sum(groups, ())) if out.kind != "link" else None
        except TarsimError:
            together = None     # each alone then: keep what constructs, say why the rest not
        for names in groups:
            try:
                sol = together or _constructed(ex, p, names)
            except TarsimError as e:
                notes.append(f"{label}: {', '.join(names)} not constructed: {e}")
                continue
            for name in names:
                q = sol.quantities[name]
                for method, qq in ((q.method, q), *q.alternatives.items()):
                    got = _from_quantity(out, name, qq.value)
                    key = next(iter(got))
                    checks.append(_check(label, drive.angle, key, method, got[key], curve[key],
                                         scale_of(sol.exercise.mechanism, KINDS[key]),
                                         vector=_vector_pair(out, got, curve)))
                    if qq is q:
                        marks += [(k, drive.angle, v, label) for k, v in got.items()]
    return checks, marks, notes


def _constructed(ex: Exercise, position, names: tuple[str, ...]):
    """The solution by construction of ``names`` at ``position`` (None: the [input] angle)."""
    return solve_positions(replace(ex.asking(names), positions=(position,) if position
                                   else ()))[0]


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
