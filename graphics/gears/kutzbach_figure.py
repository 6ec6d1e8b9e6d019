"""The velocity (Kutzbach) diagram of a planetary train as a figure.

It renders the record :func:`~tarsim.constructions.gears.kutzbach.draw_kutzbach` drew:
the radial line up from the main axis O (heavy), each level a dashed line across it,
named at its left (r2, R), each member's velocity line (thin, named at its upper end with
its ω), and the points the lines were drawn through (dots). Radii stand at the radius
scale and velocities across at the velocity scale, both stated with their bars.
"""

from __future__ import annotations

import math

from tarsim.constructions import geometry as g
from tarsim.constructions.gears.kutzbach import Kutzbach
from tarsim.constructions.gears.train import GearTrain
from tarsim.constructions.narration import numeral, unit_words, words
from ..figure import Circle, Figure, Path
from ..fitting import DRAFTING, held_by
from ..labels import LabelPlacer
from ..paper import sheet_drawn_on
from ..scales import draw_caption
from ..typeset import subscript

__all__ = ["draw_kutzbach_figure", "member_words"]

_OVER = 8.0        # how far (mm) a line runs past the points it was drawn through
_GROWN = (10.0, 5.0, 4.0, 2.5, 2.0)
"""How many times as big a diagram drawn for a sheet may be tried, the biggest first: at
one that leaves both its scales drafting scales (:data:`~tarsim.graphics.fitting.DRAFTING`)."""


def drafting(per_cm: float) -> bool:
    """Whether ``per_cm`` is a drafting scale, 1, 2, 2.5, 4 or 5 × 10ᵏ.

    >>> drafting(2.5), drafting(12.5), drafting(0.4)
    (True, False, True)
    """
    k = math.floor(math.log10(per_cm))
    return any(math.isclose(per_cm, m * 10.0 ** k, rel_tol=1e-9) for m in DRAFTING)


def draw_kutzbach_figure(train: GearTrain, k: Kutzbach, title: str,
                         notes: tuple[str, ...] = (), grown: float | None = None) -> Figure:
    """The diagram ``k`` of ``train`` on a page, with its caption and both scales, drawn
    ``grown`` times as big as ``k``'s scales say (each scale then that many times finer);
    by default as many of :data:`_GROWN` times as the sheet it is drawn on holds, else 1."""
    if grown is None:
        sheet = sheet_drawn_on()
        for times in _GROWN if sheet is not None else ():
            if not (drafting(k.per_cm / times) and drafting(k.velocity_per_cm / times)):
                continue
            fig = draw_kutzbach_figure(train, k, title, notes, times)
            if held_by(sheet)(fig):
                return fig
        return draw_kutzbach_figure(train, k, title, notes, 1.0)
    mm = 10.0 * grown / (k.per_cm * k.stated)          # paper mm per drawing metre

    def paper(p: g.Point) -> tuple[float, float]:
        x, y = p.xy
        return x * mm, -y * mm

    c = k.construction
    fig = Figure(0.0, 0.0, title=title)
    placer = LabelPlacer(fig)
    points = {ref: paper(c.output(ref)) for ref in c.steps
              if isinstance(c.output(ref), g.Point) and ref.startswith(("kz:v", "kz:pitch",
                                                                         "kz:centre", "kz:r:"))}
    top = min(y for _, y in points.values()) - _OVER
    xs = [x for x, _ in points.values()] + [0.0]
    left, right = min(xs) - _OVER, max(xs) + _OVER
    # The radial line, and each level across the whole width.
    fig.add(Path(((0.0, 0.0), (0.0, top)), "link"))
    placer.block_segment((0.0, 0.0), (0.0, top), 1.0)
    fig.add(Path(((left, 0.0), (right, 0.0)), "dimension"))
    # Levels at one radius (a ring's pitch circle where the arm carries a planet) are one
    # line, named "r₈ = R".
    at: dict[float, list[str]] = {}
    for name in k.levels:
        y = points[f"kz:r:{name}"][1]
        same = next((h for h in at if abs(h - y) < 1e-6), None)
        at.setdefault(y if same is None else same, []).append(subscript(name))
    for y in at:
        fig.add(Path(((left, y), (right, y)), "construction"))
        placer.block_segment((left, y), (right, y), 0.3)
    for y, names in at.items():
        placer.place(" = ".join(names), (left, y), prefer=3.1416, spread=0.3, gap=1.5,
                     size=3.2)
    # Each member's line, from its lower point past its upper one.
    # Every line and dot first, then the names: a name must clear the lines drawn after
    # the one it names as well.
    named: list[tuple[str, tuple[float, float]]] = []
    for body, ref in k.lines.items():
        if ref == "kz:radial":
            continue
        # From the lowest to the highest of its points: the two it was drawn through and
        # those read off it later (a planet's pitch point beyond its centre).
        ends = [paper(c.output(r)) for r in k.through[body]] + [
            points[r] for r, step in c.steps.items() if ref in step.inputs and r in points]
        lo = max(ends, key=lambda p: p[1])
        hi = min(ends, key=lambda p: p[1])
        d = (hi[0] - lo[0], hi[1] - lo[1])
        n = (d[0] ** 2 + d[1] ** 2) ** 0.5 or 1.0
        end = (hi[0] + _OVER * d[0] / n, hi[1] + _OVER * d[1] / n)
        fig.add(Path((lo, end), "vector"))
        placer.block_segment(lo, end, 0.6)
        w = k.said(body[0]) / train.units.per_rad_s        # nil to the drawing's rounding
        sense = "" if w == 0 else " " + words("ccw" if w > 0 else "cw")
        names = ", ".join(subscript(f"ω{m}") for m in body)
        if train.speed_given:
            named.append((f"{names} = {numeral(abs(w), '.4g')} "
                          f"{unit_words(train.units.speed)}{sense}", lo, end))
        else:                    # drawn for the input at 1: each slope over the input's
            i = train.input_member
            ratio = k.said(body[0]) / k.said(i)
            names = ", ".join(subscript(f"ω{m}") + "/" + subscript(f"ω{i}") for m in body)
            named.append((f"{names} = {numeral(ratio, '.4g').replace('-', '−')}", lo, end))
    dots: list[tuple[float, float]] = []
    for ref, p in points.items():
        if ref.startswith("kz:r:") or any(abs(p[0] - q[0]) + abs(p[1] - q[1]) < 0.1
                                          for q in dots):
            continue              # one dot, one name, where two points coincide
        dots.append(p)
        fig.add(Circle(p, 0.7, "dot"))
        placer.block(g_point_box(p))
    # Each ω is read off its own line: its name stands nearer that line than any other.
    placer.name_vectors((lo, end) for _, lo, end in named)
    for text, lo, end in named:
        placer.place(text, end, prefer=(1.57, 0.0, 3.1416), gap=1.5, size=3.0, italic=False,
                     rings=(1.0, 1.6, 2.3, 3.2, 4.5, 6.0), own=(lo, end))
    for ref, p in points.items():
        if not ref.startswith("kz:r:") and p in dots:      # each dot's first name, once
            dots.remove(p)
            placer.place(subscript(c[ref].label), p, prefer=(0.8, 2.4), gap=1.2, size=3.2)
    placer.place("O", (0.0, 0.0), prefer=-1.57, gap=1.5, size=3.2)
    draw_caption(fig, words("{name}: velocity (Kutzbach) diagram", name=train.name),
                 [words("{member} fixed; velocities across the radial line, ccw to the right",
                        member=member_words(train, train.fixed)) if train.fixed is not None
                  else words("no member fixed: {a} and {b} given; velocities across the "
                             "radial line, ccw to the right", a=member_words(
                                 train, train.input_member), b=member_words(
                                 train, train.second[0])),
                  words("each member's ω is the slope Δv/Δr of its line")
                  if train.speed_given else
                  words("no speed given: drawn for {member} at 1 {unit}, each slope over "
                        "its slope is a speed ratio", member=member_words(
                            train, train.input_member), unit=unit_words(train.units.speed))],
                 per_cm=k.per_cm / grown, unit=k.unit, scale_name="Radius scale",
                 second=("Velocity scale", k.velocity_per_cm / grown, f"{k.unit}/s"),
                 notes=notes)
    return fig


def member_words(train: GearTrain, member: int) -> str:
    """A member as a figure names it in the language being spoken: "gear 1 (ring)", "the
    arm 3" in English, as the steps do (:meth:`GearTrain.label`); its name translated where
    the language has a word for it, else as the file gives it."""
    if member == train.arm:
        name = train.arm_name if train.arm_name and train.arm_name != "arm" else ""
        return (words("the arm {arm} ({name})", arm=str(member), name=words(name)) if name
                else words("the arm {arm}", arm=str(member)))
    name = train.gear(member).name
    return (words("gear {gear} ({name})", gear=str(member), name=words(name)) if name
            else words("gear {gear}", gear=str(member)))


def g_point_box(p: tuple[float, float]):
    """The room a dot takes."""
    from shapely.geometry import Point

    return Point(p).buffer(1.2)
