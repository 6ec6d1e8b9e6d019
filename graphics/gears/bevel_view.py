"""Bevel gears in a train's side view, as the textbooks' schematic draws them.

A bevel pair's axes are square, so neither gear is the spur gear's rectangle: each is drawn
as its teeth, a slanted trapezoid on the pitch line the two share, meeting the other's at
45°, tapering toward the cones' apex. A gear on the main axis meets its square mate at its
pitch radius, its two trapezoids (above and below the axis) joined by its web; a square gear
stands on its own axis square to the main one, its trapezoids either end of its pitch
diameter joined by its back. A bevel planet stands on a spindle of the arm (the cage)
between the two gears it meshes, a planet's radius either side of it, drawn above the main
axis and again below; a pinion on a side shaft square to the main axis meets its main-axis
gear's pitch circle, its shaft leaving outward. Radii are to scale, as the spur gears'; the
45° is the schematic's, whatever the pair's true cone angles.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field

from tarsim.constructions.gears.train import GearTrain
from ..figure import Figure, Path

__all__ = ["BevelView", "bevel_view", "draw_bevels"]

_DEPTH = 4.0       # mm a bevel gear's teeth stand off the pitch line
_TEETH = 9.0       # mm the teeth run along the pitch line, at most
_TAPER = 0.6       # the teeth's depth at their inner end, of that at the outer
_GAP = 18.0        # mm between a bevel planet's first gear and the gears before it
_SPINDLE = 2.5     # mm the cage's spindle runs past a planet's back
_SHAFT = 14.0      # mm a square side shaft runs out past its gear
_S = math.sqrt(0.5)


@dataclass
class BevelView:
    """Where the bevel gears stand (paper mm, ``up`` away from the main axis)."""

    x: dict[int, float] = field(default_factory=dict)
    """A main-axis gear's pitch plane; a square gear's axis."""
    toward: dict[int, int] = field(default_factory=dict)
    """A main-axis gear: +1 where its square mate stands to its right, −1 to its left."""
    up: dict[int, tuple[float, float]] = field(default_factory=dict)
    """A square gear: its pitch points' distances from the main axis, left and right (a
    planet between unequal gears meets each at its own radius)."""
    planets: tuple[int, ...] = ()
    """The bevel planets, each on a spindle of the arm through the main axis."""

    def web(self, g: int) -> float:
        """The x of a main-axis bevel gear's web, behind its teeth."""
        return self.x[g] - self.toward[g] * _DEPTH * _S

    def cage(self, g: int) -> float:
        """How far from the main axis the cage holds planet ``g``'s spindle."""
        return max(self.up[g]) + _DEPTH * _S + _SPINDLE


def bevel_view(train: GearTrain, at: dict[int, float],
               radius: Callable[[int], float]) -> BevelView | None:
    """The bevel gears' places, or None where no gear turns square to the main axis.

    ``at`` is each member's x (mm) as the spur layout places it, ``radius`` a gear's pitch
    radius in mm. A bevel planet's spindle stands past every other main-axis gear, its first
    gear a planet's radius before it and its second one after; a square side gear stands a
    radius beside the main-axis gear it meshes, on the side away from the planets.
    """
    squares = [m for m in train.members if train.square(m)]
    if not squares:
        return None
    view = BevelView(planets=tuple(m for m in squares if train.carried(m)))
    mates = {p: [b for mesh in train.meshes if mesh.bevel
                 for a, b in ((mesh.a, mesh.b), (mesh.b, mesh.a)) if a == p]
             for p in view.planets}
    taken = {m for p in view.planets for m in (p, *mates[p])}
    start = max((x for m, x in at.items() if m not in taken and m != train.arm
                 and not train.square(m)), default=0.0)
    for p in view.planets:
        r = radius(p)
        view.x[p] = start + _GAP + r
        view.up[p] = (radius(mates[p][0]), radius(mates[p][-1]))
        for mate, s in zip(mates[p], (1, -1)):
            view.x[mate], view.toward[mate] = view.x[p] - s * r, s
        start = view.x[p] + r
    for g in squares:
        if g in view.planets:
            continue
        main = next(b for mesh in train.meshes if mesh.bevel
                    for a, b in ((mesh.a, mesh.b), (mesh.b, mesh.a))
                    if a in train.body(g) and not train.square(b))
        view.x.setdefault(main, at[main])
        s = view.toward.setdefault(main, -1 if view.planets else 1)
        view.x[g] = view.x[main] + s * radius(g)
        view.up[g] = (radius(main), radius(main))
    return view


def _teeth(p: tuple[float, float], u: tuple[float, float], n: tuple[float, float],
           along: float) -> tuple[tuple[float, float], ...]:
    """A gear's teeth on the pitch line at ``p``: ``along`` mm toward the apex (``u``),
    standing off it toward ``n``, tapering."""
    (px, py), (ux, uy), (nx, ny) = p, u, n
    qx, qy = px + along * ux, py + along * uy
    d, t = _DEPTH, _DEPTH * _TAPER
    return ((px, py), (qx, qy), (qx + t * nx, qy + t * ny), (px + d * nx, py + d * ny))


def draw_bevels(fig: Figure, train: GearTrain, view: BevelView,
                radius: Callable[[int], float], block: Callable[[list], None],
                labels: list[tuple[str, tuple[float, float]]]) -> None:
    """Draw each bevel gear of ``view`` (figure y downward), marking what is drawn taken
    with ``block`` and adding each gear's label place to ``labels``."""

    def shape(points, closed: bool = True) -> None:
        pts = tuple((x, -y) for x, y in points)
        fig.add(Path(pts, "link", closed=closed))
        block([*pts, pts[0]] if closed else list(pts))

    for g, s in view.toward.items():                 # on the main axis: teeth and web
        x, r = view.x[g], radius(g)
        mate = min((radius(m) for m in view.up if abs(view.x[m] - s * radius(m) - x) < 1e-9),
                   default=r)
        along = min(_TEETH, 0.5 * min(r, mate) / _S)
        for side in (1.0, -1.0):
            shape(_teeth((x, side * r), (s * _S, -side * _S), (-s * _S, -side * _S), along))
        back = r - _DEPTH * _S
        shape(((view.web(g), back), (view.web(g), -back)), closed=False)
        labels.append((str(g), (view.web(g), -0.5 * r)))
    for g, up in view.up.items():                    # square to it: teeth, back, spindle
        x, r = view.x[g], radius(g)
        mains = [radius(m) for m in view.toward if abs(abs(view.x[m] - x) - r) < 1e-9]
        along = min(_TEETH, 0.5 * min([r, *mains]) / _S)
        planet = g in view.planets
        for side in ((1.0, -1.0) if planet else (1.0,)):
            for s, h in zip((1.0, -1.0), up):        # its pitch points, either end
                shape(_teeth((x - s * r, side * h), (s * _S, -side * _S),
                             (s * _S, side * _S), along))
            shape(((x - r + _DEPTH * _S, side * (up[0] + _DEPTH * _S)),
                   (x + r - _DEPTH * _S, side * (up[1] + _DEPTH * _S))), closed=False)
        back = up[0] + _DEPTH * _S
        if planet:
            shape(((x, -view.cage(g)), (x, view.cage(g))), closed=False)
        else:
            shape(((x, back), (x, back + _SHAFT)), closed=False)
        labels.append((str(g), (x + r, -max(up) - _DEPTH * _S)))
