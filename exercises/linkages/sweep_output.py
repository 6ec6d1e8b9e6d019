"""What a sweep follows: a point, a ram on its guide or a link, and its values (SI).

A point gives its position, velocity and acceleration as vectors; a point on a straight
frame guide (a ram, a piston) its values along the guide; a link θ, ω and α. They are
taken at one position from the scalar solver (:func:`evaluate`) and over a whole turn
from the vectorised one (:func:`curves_of`), with the same formulas, so a curve's step
and the same position solved alone agree to the bit where the solvers do.
"""

from __future__ import annotations

import difflib
import math
import re
from dataclasses import dataclass, replace

import numpy as np

from tarsim.constructions.asks import SYMBOLS, Acceleration, Velocity
from tarsim.constructions.errors import InputError
from tarsim.constructions.joints import Slide
from tarsim.constructions.linkages.limit_positions import stroke_point
from tarsim.constructions.model import Drive, Mechanism
from tarsim.constructions.reference import solver
from tarsim.constructions.reference.turn import Turn

from .exercise_file import Exercise

__all__ = ["Output", "KEYS", "KINDS", "output_names", "pick_output", "evaluate", "curves_of",
           "values_of", "drive_at", "scale_of"]

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
def evaluate(mech: Mechanism, out: Output, drive: Drive) -> dict[str, float]:
    """The output's values (SI) with the input at ``drive``; AssemblyError if it will not go."""
    m = mech.with_drive(drive)
    kin = solver.solve(m)
    if out.kind == "link":
        n = out.link
        return values_of(out, kin.angles[n], kin.omegas[n], kin.alphas[n])
    return values_of(out, kin.points[out.point],
                     solver.point_velocity(kin, m, out.link, out.point),
                     solver.point_acceleration(kin, m, out.link, out.point), m.origin)


def curves_of(turn: Turn, out: Output) -> dict[str, np.ndarray]:
    """The output's values (SI) at each position of ``turn``, by key as :func:`values_of` gives
    them and in its order, each computed as it computes it; NaN where it did not assemble."""
    n, p = out.link, out.point
    if out.kind == "link":
        return {"theta": turn.angles[n], "omega": turn.omegas[n], "alpha": turn.alphas[n]}
    (x, y), origin = turn.points[p].T, turn.mechanism.origin
    (vx, vy), (ax, ay) = (rate.T for rate in turn.rates_on(n, p))
    at = {"x": x + origin[0], "y": y + origin[1]}
    if out.kind == "slider":
        (dx, dy), (gx, gy) = out.direction, out.guide.through
        return {**at, "s": (x - gx) * dx + (y - gy) * dy, "v": vx * dx + vy * dy,
                "a": ax * dx + ay * dy}

    def size(u, w):     # math.hypot, as values_of takes it, not numpy's to another rounding
        return np.array(list(map(math.hypot, u.tolist(), w.tolist())))

    return {**at, "v": size(vx, vy), "vx": vx, "vy": vy, "a": size(ax, ay), "ax": ax, "ay": ay}


def values_of(out: Output, position, velocity, acceleration,
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


def drive_at(mech: Mechanism, angle: float) -> Drive:
    """The mechanism's input with its angle set to ``angle`` (rad), its ω and α kept."""
    return replace(mech.drive, angle=angle)


# ----- the scale of an error ---------------------------------------------------------------
def scale_of(mech: Mechanism, kind: str) -> float:
    """The scale an error is taken relative to where the value itself is near 0."""
    d = mech.drive
    return {"velocity": mech.input_speed, "acceleration": mech.input_acceleration,
            "omega": abs(d.omega), "alpha": math.hypot(d.omega ** 2, d.alpha),
            "angle": 1.0}.get(kind, 1.0)
