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

Beside those, a frame sends the points the exercise's own constructions stand on (the
feet of its components, the radius rotated, the tips laid off along a parallel, a
polygon's components: :func:`construction_points`), redone from the solution's record at
the frame's angle, so that the construction asked turns with the mechanism. Where the
record cannot be redone (its acts stop, or a frame is constructed afresh) they are sent
as missing, and the page hides what stands on them.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import replace
from types import SimpleNamespace
from typing import Any

from tarsim.constructions.checks import tolerance
from tarsim.constructions.errors import TarsimError
from tarsim.constructions import geometry as g
from tarsim.constructions.linkages.acceleration_polygon import draw_acceleration_polygon
from tarsim.constructions.linkages.assembly import assemble, input_ray, ray_at
from tarsim.constructions.linkages.kennedy import locate_centres
from tarsim.constructions.linkages.velocity_polygon import draw_velocity_polygon
from tarsim.constructions.model import Mechanism
from tarsim.constructions.record import Kind, Panel
from tarsim.constructions.reference import solver
from tarsim.constructions.reference.centres import (CentreReference, MoveTogether,
                                                    centre_error, shared_pin)
from tarsim.constructions.replay import Replay

__all__ = ["Template", "constructed", "construction_points", "truth_of_turn", "frame_outcomes",
           "FRAME_CHECK", "VIEWS"]

FRAME_CHECK = 1e-9
"""The largest relative distance of a frame's joint or polygon tip from the analytic
solver's, beside the mechanism's size or the polygon's largest vector: the construction
agrees to rounding (1e-15 or so) wherever it is well conditioned, so more than this is a
wrong frame, not noise. A centre is held to the tolerance its own conditioning allows."""

Names = dict[str, list[str]]

VIEWS = {Panel.SPACE: "space", Panel.VELOCITY: "velocity", Panel.ACCELERATION: "acceleration"}
"""The views a frame sends, by the panel their steps are drawn in."""


def construction_points(sol) -> Names:
    """The refs of the points ``sol``'s constructions stand on beyond the mechanism's
    joints, its instant centres and its polygons' poles and tips, by view: each
    constructed point of its record (a foot, a tip, a rotated point), in the record's
    order. A point marked again (``mark``) is the point it marks, and a point at
    infinity is drawn as no point."""
    asm = sol.assembly
    named = set(asm.points.values())
    for poly in (sol.velocity_polygon, sol.acceleration_polygon):
        if poly is not None:
            named |= {*poly.tips.values(), poly.pole}
    out: Names = {view: [] for view in VIEWS.values()}
    for step in asm:
        view = VIEWS.get(step.panel)
        if (view is None or step.id in named or step.verb in ("given", "mark")
                or step.kind in (Kind.JOINT, Kind.CENTRE, Kind.POLE)
                or not isinstance(step.output, g.Point) or step.output.is_at_infinity):
            continue
        out[view].append(step.id)
    return out


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
             names: Names, built: dict[str, dict] | None = None) -> dict[str, Any]:
    """A frame from the named points it found, held to ``truth`` (a solution of ``m`` with
    ``points``, ``velocities`` and ``accelerations``, as :class:`CentreReference` takes):
    ``polys`` gives each polygon's (tips, pole, scale) by view, ``centres`` each centre
    as (label, pair, point, conditioning), ``built`` the points of the exercise's own
    constructions by view and ref (:func:`construction_points`; none: sent as missing)."""
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
    for view, points in (built or {}).items():
        at.setdefault(view, {}).update(points)
    return {"at": {view: _flat(at[view].get(name) for name in names[view]) for view in names},
            **out}


def constructed(mech: Mechanism, angle: float, scales: dict[str, float], names: Names,
                solved: Callable[[float], Any] | None = None) -> dict[str, Any]:
    """One position constructed afresh and checked against the scalar solver: a frame, or
    one that says why the position cannot be drawn. ``solved`` gives the exercise solved
    at an angle (None where it cannot be), whose record gives the points of its own
    constructions there (:func:`construction_points`; none without it)."""
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
    built = _built(solved(angle), names, polys) if solved is not None else None
    checked = _checked(m, at, polys, centres, kin, names, built)
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

    def __init__(self, mech: Mechanism, angle: float, scales: dict[str, float], names: Names,
                 sol=None):
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
        # The exercise's own constructions, from ``sol`` (solved at ``angle``): the points
        # of them the page is sent, redone apart, for acts that stop (a swing that no
        # longer reaches) lose those points alone.
        self.sol = sol
        found = construction_points(sol) if sol is not None else {}
        self.built = {view: [r for r in refs if r in set(names.get(view, ()))]
                      for view, refs in found.items()}
        refs = [r for view in self.built.values() for r in view]
        self.construction = Replay(sol.assembly, _read(sol.assembly, refs)) if refs else None

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
        frame = _checked(m, at, polys, centres, truth, self.names, self.rebuilt(ray))
        return {"angle": angle, **frame} if frame["ok"] else None

    def rebuilt(self, ray: dict) -> dict[str, dict[str, tuple[float, float]]]:
        """The points of the exercise's own constructions redone with the input's ``ray``,
        by view and ref: none where the acts stop, and none at infinity."""
        if self.construction is None:
            return {}
        try:
            out, _ = self.construction.run(ray)
        except (TarsimError, ArithmeticError):
            return {}
        return {view: {r: out[r].xy for r in refs if not out[r].is_at_infinity}
                for view, refs in self.built.items()}

    @classmethod
    def chosen(cls, mech: Mechanism, angles: list[float], scales: dict[str, float],
               names: Names, solved: Callable[[float], Any] | None = None
               ) -> Template | None:
        """The first of a few positions round the turn whose constructions, redone at two
        other positions, agree there with the scalar solver; None if none does (a wheel
        rolling as the input, whose ray is not what turns; a mechanism every position of
        which chose other acts). ``solved`` gives the exercise solved at an angle (None
        where it cannot be): the record the exercise's own constructions are redone from;
        a point of theirs that a solve at any of four positions round the turn puts
        elsewhere is not sent (:meth:`_keep_agreeing`)."""
        if mech.rolling_input is not None:
            return None
        n = len(angles)
        for k in (0, n // 7, 2 * n // 5, 5 * n // 7):
            sol = solved(angles[k]) if solved is not None else None
            try:
                template = cls(mech, angles[k], scales, names, sol)
            except TarsimError:
                continue
            probes = [angles[(k + n // 5) % n], angles[(k + 3 * n // 5) % n]]
            if all(template._holds(a) for a in probes):
                for j in range(1, 5):
                    template._keep_agreeing(angles[(k + j * n // 5) % n], solved)
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

    def _keep_agreeing(self, angle: float, solved: Callable[[float], Any] | None) -> None:
        """Keep, of the points of the exercise's own constructions, those the acts redone
        at ``angle`` put where a solve there puts them (or a solve there does not make):
        an act whose parameter is not read again from the drawing, or a solve that takes
        other acts there, loses its points at every frame rather than show them wrong."""
        sol = solved(angle) if solved is not None and self.construction is not None else None
        if sol is None:
            return
        for view, points in self.rebuilt({self.ray: ray_at(self.pivot, angle)}).items():
            # A polygon's points are read as what they stand for (pole to point over the
            # scale): a solve there may lay its polygons off at another scale.
            mine, theirs = _reading(self.sol, view), _reading(sol, view)
            if mine is None or theirs is None:
                continue
            wrong = set()
            for ref, xy in points.items():
                there = sol.assembly.output(ref) if ref in sol.assembly else None
                if not isinstance(there, g.Point) or there.is_at_infinity:
                    continue
                a, b = mine(xy), theirs(there.xy)
                if math.dist(a, b) > FRAME_CHECK * max(theirs.size, math.hypot(*b)):
                    wrong.add(ref)
            self.built[view] = [r for r in self.built[view] if r not in wrong]


def _built(sol, names: Names, polys: dict) -> dict[str, dict[str, tuple[float, float]]]:
    """The points of ``names`` that ``sol``'s record makes, by view and ref: a polygon's
    laid off again from the frame's pole at the frame's scale (``polys``: each polygon's
    tips, pole and scale by view), for a solve may draw its polygons at scales of its
    own; none if ``sol`` is None."""
    out: dict[str, dict[str, tuple[float, float]]] = {}
    for view, refs in (construction_points(sol).items() if sol is not None else ()):
        read = _reading(sol, view)
        if read is None:
            continue
        (px, py), k = (polys[view][1], polys[view][2]) if view in polys else ((0.0, 0.0), 1.0)
        wanted = set(names.get(view, ()))
        for ref in refs:
            p = sol.assembly.output(ref)
            if ref in wanted and not p.is_at_infinity:
                x, y = read(p.xy)
                out.setdefault(view, {})[ref] = (x, y) if view == "space" else (px + k * x,
                                                                                 py + k * y)
    return out


def _reading(sol, view: str):
    """How a point of ``view`` of ``sol``'s record reads, as a function of the point with
    the size beside which it is judged: a space diagram's as itself beside the
    mechanism, a polygon's as the velocity (acceleration) from its pole; None if ``sol``
    draws no such polygon."""
    if view == "space":
        return _Read(lambda xy: xy, sol.assembly.size)
    poly = sol.velocity_polygon if view == "velocity" else sol.acceleration_polygon
    if poly is None:
        return None
    (px, py), k = sol.assembly.output(poly.pole).xy, poly.scale
    big = max([math.dist(sol.assembly.output(r).xy, (px, py)) for r in poly.tips.values()]
              + [0.0])
    return _Read(lambda xy: ((xy[0] - px) / k, (xy[1] - py) / k), big / k or 1.0)


class _Read:
    """A reading of points (:func:`_reading`): called on a point, and its ``size``."""

    def __init__(self, read, size: float):
        self.read, self.size = read, size

    def __call__(self, xy):
        return self.read(xy)


def _read(record, refs: list[str]) -> list[str]:
    """``refs`` and every step the lengths and angles they read off the drawing
    (:class:`~tarsim.constructions.record.Derived`) read, with theirs: a replay follows
    a step's inputs alone."""
    out, stack = set(), list(refs)
    while stack:
        ref = stack.pop()
        if ref in out or ref not in record:
            continue
        out.add(ref)
        step = record[ref]
        stack.extend(step.inputs)
        if step.derived is not None:
            stack.extend(_refs_in(step.derived.args, record))
    return [step.id for step in record if step.id in out]


def _refs_in(args, record) -> list[str]:
    """The refs of ``record`` among ``args``, however nested in tuples."""
    if isinstance(args, str):
        return [args] if args in record else []
    if isinstance(args, tuple | list):
        return [r for a in args for r in _refs_in(a, record)]
    return []


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
