"""The frames of the interactive page: the mechanism turned through a revolution by
construction, each frame checked against the analytic solution.

A frame sends the named points of each view: the joints and instant centres, and each
polygon's pole and tips. They are not found by solving every frame afresh. The
constructions are drawn once, at one position (:class:`Template`), and redone at each
frame (:class:`~tarsim.constructions.replay.Replay`): the same acts, with the input's ray
laid off at the frame's angle and every length the polygons read off the drawing read
again. The analytic solution of the whole turn is solved at once, vectorised
(:func:`~tarsim.constructions.reference.turn.solve_turn`), and each replayed frame is held
to it. Acts chosen at one position can be the wrong ones at another (a component that
was zero there, lines that turn parallel): a frame whose replay fails its check, or
stops, is constructed afresh (:func:`constructed`), and says why if it cannot be.
"""

from __future__ import annotations

import math
from dataclasses import replace
from types import SimpleNamespace
from typing import Any

from tarsim.constructions.checks import tolerance
from tarsim.constructions.errors import TarsimError
from tarsim.constructions.linkages.acceleration_polygon import draw_acceleration_polygon
from tarsim.constructions.linkages.assembly import assemble, input_ray, ray_at
from tarsim.constructions.linkages.kennedy import locate_centres
from tarsim.constructions.linkages.velocity_polygon import draw_velocity_polygon
from tarsim.constructions.model import Mechanism
from tarsim.constructions.reference import solver
from tarsim.constructions.reference.centres import (CentreReference, MoveTogether,
                                                    centre_error, shared_pin)
from tarsim.constructions.replay import Replay

__all__ = ["Template", "constructed", "truth_of_turn", "frame_outcomes", "FRAME_CHECK"]

FRAME_CHECK = 1e-9
"""The largest relative distance of a frame's joint or polygon tip from the analytic
solver's, beside the mechanism's size or the polygon's largest vector: the construction
agrees to rounding (1e-15 or so) wherever it is well conditioned, so more than this is a
wrong frame, not noise. A centre is held to the tolerance its own conditioning allows."""

Names = dict[str, list[str]]


def _drawn(mech: Mechanism, angle: float, scales: dict[str, float]):
    """The constructions of one position: the mechanism by compass with both polygons in
    one record, and the instant centres by Kennedy's theorem in another."""
    m = mech.with_drive(replace(mech.drive, angle=angle))
    asm = assemble(m)
    vp = draw_velocity_polygon(asm, scales["v"])
    ap = draw_acceleration_polygon(asm, vp, scales["a"])
    try:
        cs, lost = locate_centres(assemble(m)), None
    except TarsimError as e:     # Kennedy cannot reach a centre here: the rest still stands
        cs, lost = None, str(e).split("\n")[0]
    return m, asm, vp, ap, cs, lost


def _checked(m: Mechanism, at: dict[str, dict], polys: dict, centres: list, truth,
             names: Names) -> dict[str, Any]:
    """A frame from the named points it found, held to ``truth`` (a solution of ``m`` with
    ``points``, ``velocities`` and ``accelerations``, as :class:`CentreReference` takes):
    ``polys`` gives each polygon's (tips, pole, scale) by view, ``centres`` each centre
    as (label, pair, point, conditioning)."""
    joints = at["space"]
    size = max(math.dist(a, b) for a in joints.values() for b in joints.values()) or 1.0
    worst = max(math.dist(joints[p], truth.points[p]) for p in joints) / size
    for view, known in (("velocity", truth.velocities), ("acceleration", truth.accelerations)):
        tips, pole, scale = polys[view]
        read = {n: ((x - pole[0]) / scale, (y - pole[1]) / scale)
                for n, (x, y) in tips.items() if n in known}
        big = max([math.hypot(*v) for v in known.values()] + [1e-300])
        worst = max([worst] + [math.dist(read[n], known[n]) / big for n in read])
        at[view] = {**tips, "pole": pole}
    miss = 0.0
    reference = CentreReference(truth) if centres else None
    for label, pair, p, conditioning in centres:
        at["space"][label] = None if p.is_at_infinity else p.xy
        try:
            ref = reference.centre(*pair, pin=shared_pin(m, *pair))
        except MoveTogether:        # every point is a centre of the two: nothing to check
            continue
        err = centre_error(p, ref, size)
        if err > tolerance(conditioning):
            miss = max(miss, err)
    out: dict[str, Any] = {"ok": worst <= FRAME_CHECK and miss == 0.0}
    if not out["ok"]:
        out["why"] = (f"its construction is {worst:.1g} off the analytic solution"
                      if worst > FRAME_CHECK else
                      f"an instant centre is {miss:.1g} off its analytic position")
    return {"at": {view: _flat(at[view].get(name) for name in names[view]) for view in names},
            **out}


def constructed(mech: Mechanism, angle: float, scales: dict[str, float], names: Names
                ) -> dict[str, Any]:
    """One position constructed afresh and checked against the scalar solver: a frame, or
    one that says why the position cannot be drawn."""
    try:
        m, asm, vp, ap, cs, lost = _drawn(mech, angle, scales)
        kin = solver.solve(m)
    except (TarsimError, ArithmeticError) as e:       # a position not reached, a dead point
        return {"angle": angle, "why": str(e).split("\n")[0]}
    at = {"space": {p: asm.point(p).xy for p in m.point_names}}
    polys = {view: ({n: asm.output(r).xy for n, r in poly.tips.items()},
                    asm.output(poly.pole).xy, poly.scale)
             for view, poly in (("velocity", vp), ("acceleration", ap))}
    centres = [(c.label, c.pair, cs.point(*c.pair), cs.conditioning(*c.pair))
               for c in (cs.secondaries + cs.primaries)] if cs is not None else []
    checked = _checked(m, at, polys, centres, kin, names)
    frame = {"angle": angle, "at": checked.pop("at")}
    if lost is not None:
        frame["lost"] = lost
    return {**frame, **checked}


class Template:
    """The constructions of one position, to be redone at each frame (:meth:`frame`).

    Raises
    ------
    TarsimError
        If the position cannot be constructed, or Kennedy's theorem cannot reach every
        centre there.
    """

    def __init__(self, mech: Mechanism, angle: float, scales: dict[str, float], names: Names):
        m, asm, vp, ap, cs, lost = _drawn(mech, angle, scales)
        if cs is None:
            raise TarsimError(lost)
        self.mech, self.names = mech, names
        self.ray = input_ray(mech.drive.link)
        self.pivot = asm.point(mech.link(mech.drive.link).names[0])
        self.joints = {p: asm.points[p] for p in m.point_names}
        self.polys = {view: (dict(poly.tips), poly.pole, poly.scale)
                      for view, poly in (("velocity", vp), ("acceleration", ap))}
        self.centres = [(c.label, c.pair, c.ref) for c in (cs.secondaries + cs.primaries)]
        self.drawing = Replay(asm, [*self.joints.values(), *(
            r for tips, pole, _ in self.polys.values() for r in (*tips.values(), pole))])
        self.kennedy = Replay(cs.assembly, [ref for _, _, ref in self.centres])

    def frame(self, angle: float, truth) -> dict[str, Any] | None:
        """The frame at ``angle``, redone and held to ``truth`` (the analytic solution
        there); None where the redone acts stop or miss (the frame is then constructed
        afresh)."""
        ray = {self.ray: ray_at(self.pivot, angle)}
        try:
            out, _ = self.drawing.run(ray)
            found, cond = self.kennedy.run(ray)
        except (TarsimError, ArithmeticError):
            return None
        m = self.mech.with_drive(replace(self.mech.drive, angle=angle))
        at = {"space": {p: out[r].xy for p, r in self.joints.items()}}
        polys = {view: ({n: out[r].xy for n, r in tips.items()}, out[pole].xy, scale)
                 for view, (tips, pole, scale) in self.polys.items()}
        centres = [(label, pair, found[ref], cond[ref]) for label, pair, ref in self.centres]
        frame = _checked(m, at, polys, centres, truth, self.names)
        return {"angle": angle, **frame} if frame["ok"] else None

    @classmethod
    def chosen(cls, mech: Mechanism, angles: list[float], scales: dict[str, float],
               names: Names) -> Template | None:
        """The first of a few positions round the turn whose constructions, redone at two
        other positions, agree there with the scalar solver; None if none does (a wheel
        rolling as the input, whose ray is not what turns; a mechanism every position of
        which chose other acts)."""
        if mech.rolling_input is not None:
            return None
        n = len(angles)
        for k in (0, n // 7, 2 * n // 5, 5 * n // 7):
            try:
                template = cls(mech, angles[k], scales, names)
            except TarsimError:
                continue
            probes = [angles[(k + n // 5) % n], angles[(k + 3 * n // 5) % n]]
            if all(template._holds(a) for a in probes):
                return template
        return None

    def _holds(self, angle: float) -> bool:
        """True if the redone frame at ``angle`` passes its check, or the position cannot
        be solved (nothing to hold it to)."""
        try:
            kin = solver.solve(self.mech.with_drive(replace(self.mech.drive, angle=angle)))
        except (TarsimError, ArithmeticError):
            return True
        return self.frame(angle, kin) is not None


def truth_of_turn(turn, i: int) -> SimpleNamespace:
    """Position ``i`` of a solved turn as the checks read a solution (points, velocities,
    accelerations, and what :class:`CentreReference` takes)."""
    row = {}
    for key in ("points", "velocities", "accelerations", "origins", "origin_velocities"):
        row[key] = {k: (float(v[i, 0]), float(v[i, 1])) for k, v in getattr(turn, key).items()}
    row["omegas"] = {k: float(v[i]) for k, v in turn.omegas.items()}
    return SimpleNamespace(**row, conditioning=float(turn.conditioning[i]))


def frame_outcomes(frames: list[dict]) -> dict[str, list[dict]]:
    """The frames by what became of them: ``checked`` (constructed and agreeing with the
    analytic solver), ``lost`` (out of reach, or beyond the construction: a frame that
    only says why) and ``failing`` (constructed, and off the solver)."""
    out: dict[str, list[dict]] = {"checked": [], "lost": [], "failing": []}
    for f in frames:
        out["lost" if "at" not in f else "checked" if f["ok"] else "failing"].append(f)
    return out


def _round(xy: tuple[float, float]) -> list[float]:
    """A point as the page keeps it: a tenth of a micrometre of the drawing, far below what
    a screen shows, and few enough digits to keep 720 frames small."""
    return [round(xy[0], 7) + 0.0, round(xy[1], 7) + 0.0]


def _flat(points) -> list[float | None]:
    """Points as one list, x and y in turn; a point not found (at infinity) as two nulls."""
    return [v for xy in points for v in (_round(xy) if xy is not None else (None, None))]
