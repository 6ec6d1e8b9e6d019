"""A cam's part of its problem sheet (:mod:`.handout`): the displacement diagram's axes, empty,
at the scales the solution draws the diagram at, and the base circle with the follower at
its start, to scale; nothing the construction finds."""

from __future__ import annotations

import math
from collections.abc import Sequence

from tarsim.constructions.errors import TarsimError
from tarsim.constructions.narration import numerals, unit_words, words

from .figure import Circle, Figure, Path, Text, text_width
from .scales import draw_caption, nice_per_cm

__all__ = ["draw_empty_displacement", "draw_base_circle", "draw_given_arcs", "DISPLACEMENT_ROOM"]

DISPLACEMENT_ROOM = (165.0, 60.0)
"""Paper (mm) a turn and the greatest lift are fitted to, as the solution's diagram is."""


def draw_empty_displacement(title: str, *, lift: float, segments: Sequence[tuple[str, float]],
                            per_rad: float, unit: str, metre: float,
                            lift_given: bool = True) -> Figure:
    """Draw the displacement diagram's axes with nothing on them: the base line over a turn,
    the cam angle every 30°, the lift axis up to the greatest lift (a dashed line across
    there), and each segment's span named ("rise 120°"), at the scales the solution's
    diagram is drawn at, each stated.

    Parameters
    ----------
    title
        The caption's heading.
    lift
        The greatest lift, metres (the file gives it).
    segments
        Each segment's name as said and its angle (rad), in order round the turn.
    per_rad
        Drawing metres a radian of cam angle, as the solution's construction lays it off.
    unit, metre
        The length unit the lift is stated in, and its size in metres.
    lift_given
        Whether the file gives the lift (a segment's), so that the axis may state it; a
        disc's lift is found, and the axis is drawn to hold it but not numbered.

    Raises
    ------
    TarsimError
        If the lift is not a positive number.

    Examples
    --------
    A rise of 40 mm over 120°, a dwell of 240°, a turn laid off over 2π × 40 mm: the turn
    needs 1 cm a 20 mm of drawing to fit 16.5 cm, so the lift is at 1 cm = 20 mm too:

    >>> fig = draw_empty_displacement("Cam", lift=0.04, unit="mm", metre=1e-3, per_rad=0.04,
    ...                               segments=[("rise", 2 * math.pi / 3),
    ...                                         ("dwell", 4 * math.pi / 3)])
    >>> texts = [getattr(t, "text", "") for t in fig.items]
    >>> "Lift scale 1 cm = 20 mm" in texts, "Cam angle scale 1 cm = 28.6479°" in texts
    (True, True)
    """
    if not (lift > 0.0 and math.isfinite(lift)):
        raise TarsimError(f"a displacement diagram's greatest lift must be positive; got {lift}")
    width = 2 * math.pi * per_rad
    per_cm = max(nice_per_cm(width / metre, DISPLACEMENT_ROOM[0]),
                 nice_per_cm(lift / metre, DISPLACEMENT_ROOM[1]))
    k = 10.0 / (per_cm * metre)                      # paper mm a drawing metre
    right, top = width * k, lift * k
    fig = Figure(0.0, 0.0, title=title)
    fig.add(Path(((0.0, 0.0), (right, 0.0)), "link"))
    fig.add(Path(((0.0, 0.0), (0.0, -top - 4.0)), "dimension"))
    if lift_given:
        fig.add(Path(((0.0, -top), (right, -top)), "reference"))
        fig.add(Text((-1.5, -top), numerals(f"{lift / metre:g}") + f" {unit_words(unit)}",
                     2.8, "end", False))
    for deg in range(0, 361, 30):
        x = math.radians(deg) * per_rad * k
        fig.add(Path(((x, 0.0), (x, 1.5)), "dimension"))
        fig.add(Text((x, 4.5), numerals(f"{deg}°"), 2.8, "middle", False))
    at, raised = 0.0, False
    for name, angle in segments:
        x0, x1 = at * per_rad * k, (at + angle) * per_rad * k
        fig.add(Path(((x1, 0.0), (x1, -top - 4.0)), "construction"))
        said = f"{name} {numerals(f'{math.degrees(angle):g}')}°"
        # A span too narrow for its name sets it a row higher than the one before it.
        raised = text_width(said, 2.8) + 2.0 > x1 - x0 and not raised
        fig.add(Text(((x0 + x1) / 2, -top - (6.5 if raised else 2.5)), said, 2.8, "middle",
                     False))
        at += angle
    draw_caption(fig, title, [words("cam angle across, lift up; draw the displacement here")],
                 per_cm=per_cm, unit=unit, scale_name="Lift scale",
                 second=("Cam angle scale", 360.0 / (right / 10.0), "°"))
    return fig


def draw_base_circle(title: str, *, base: float, offset: float, roller: float, flat: bool,
                     pivot: tuple[float, float] | None, unit: str, metre: float,
                     arm: float = 0.0, disc: tuple[float, float] | None = None,
                     room: float = 110.0) -> Figure:
    """Draw the base circle about the cam's centre O and the follower at the start of the
    turn (its line of stroke ``offset`` to the right, a roller of radius ``roller`` on the
    circle, or a flat face across its top; an oscillating ``arm`` from its pivot to the
    roller on the circle, above the line of centres), at a 1-2-5 scale that fits ``room``
    mm; a ``disc`` (its radius and the distance its centre stands off the shaft) is drawn
    itself, its centre below O, the flat face on its top. Lengths in metres.

    Examples
    --------
    >>> fig = draw_base_circle("Cam", base=0.05, offset=0.0125, roller=0.0, flat=False,
    ...                        pivot=None, unit="mm", metre=1e-3)
    >>> circle = next(c for c in fig.items if getattr(c, "style", "") == "link")
    >>> round(circle.radius, 9)                # 50 mm at 1 cm = 20 mm
    25.0
    """
    reach = max(base + 2 * roller, abs(offset) + roller, *(abs(v) for v in pivot or ()),
                sum(disc or ())) * 1.3
    per_cm = nice_per_cm(2 * reach / metre, room)
    k = 10.0 / (per_cm * metre)
    fig = Figure(0.0, 0.0, title=title)
    if disc is not None:
        fig.add(Circle((0.0, disc[1] * k), disc[0] * k, "link"))
        fig.add(Circle((0.0, disc[1] * k), 0.8, "dot"))
    else:
        fig.add(Circle((0.0, 0.0), base * k, "link"))
    fig.add(Circle((0.0, 0.0), 0.8, "dot"))
    fig.add(Text((-2.0, 3.0), "O", 3.5, "end"))
    span = reach * k
    fig.add(Path(((-span, 0.0), (span, 0.0)), "construction"))
    fig.add(Path(((0.0, -span), (0.0, span)), "construction"))
    if pivot is not None:
        p = (pivot[0] * k, -pivot[1] * k)
        end = _arm_end(pivot, arm, base + roller)
        if end is not None:
            q = (end[0] * k, -end[1] * k)
            fig.add(Path((p, q), "link"))
            if roller:
                fig.add(Circle(q, roller * k, "link"))
        fig.add(Circle(p, 1.0, "pin"))
        fig.add(Text((p[0] + 2.0, p[1] + 4.0), words("pivot"), 3.0, "start", False))
    elif flat:
        y = -base * k
        fig.add(Path(((-0.6 * span, y), (0.6 * span, y)), "link"))
    else:
        x = offset * k
        height = math.sqrt(max((base + roller) ** 2 - offset ** 2, 0.0)) * k
        fig.add(Path(((x, -height), (x, -span)), "link"))
        if roller:
            fig.add(Circle((x, -height), roller * k, "link"))
    draw_caption(fig, title, [words("the disc and the follower at the start") if disc else
                              words("the base circle and the follower at the start")],
                 per_cm=per_cm, unit=unit)
    return fig


def _arm_end(pivot: tuple[float, float], arm: float, reach: float
             ) -> tuple[float, float] | None:
    """Where an arm of ``arm`` about ``pivot`` meets the circle of ``reach`` about O, on the
    upper side (the follower's start on the base circle); None if they do not meet."""
    d = math.hypot(*pivot)
    if not (d > 0.0 and abs(arm - reach) <= d <= arm + reach):
        return None
    a = (reach ** 2 - arm ** 2 + d ** 2) / (2 * d)
    h = math.sqrt(max(reach ** 2 - a ** 2, 0.0))
    ux, uy = pivot[0] / d, pivot[1] / d
    first = (a * ux - h * uy, a * uy + h * ux)
    second = (a * ux + h * uy, a * uy - h * ux)
    return max(first, second, key=lambda p: p[1])


def draw_given_arcs(title: str, cam, given: Sequence[str], *, unit: str,
                    metre: float) -> Figure:
    """Draw a cam of arcs as its file gives it, laid as the solution lays it (the axis of
    symmetry OQ along x, at the scale the solution's outline is drawn at): the base circle,
    the lift laid off along the axis to the apex, the nose where its radius is given (inside
    the apex), the angle of lift from the axis where it is given, and the follower at the
    apex; no flank, and no size the construction finds.

    Parameters
    ----------
    title
        The caption's heading.
    cam
        The :class:`~tarsim.constructions.cams.arc_cam.ArcCam` (m, rad).
    given
        The file's keys for the sizes it gives (``"nose_radius"``, ``"angle"``, …).
    unit, metre
        The length unit the sizes are stated in, and its size in metres.

    Examples
    --------
    >>> from tarsim.constructions.cams.arc_cam import ArcCam
    >>> cam = ArcCam("circular arc", 0.04, 0.01, 0.01, math.pi / 3, flat=True)
    >>> fig = draw_given_arcs("Cam", cam, ("nose_radius", "lift", "angle"), unit="mm",
    ...                       metre=1e-3)
    >>> sorted(round(c.radius, 6) for c in fig.items if getattr(c, "style", "") == "link")
    [10.0, 40.0]
    """
    from .cams.arc_cam_figure import _ROOM
    from .symbols import draw_dimension, mark_angle

    reach = cam.d + cam.nose + 2 * cam.roller          # as the solution's outline is fitted
    per_cm = nice_per_cm(2 * reach / metre, _ROOM)
    k = 10.0 / (per_cm * metre)
    apex = (cam.base + cam.lift) * k
    fig = Figure(0.0, 0.0, title=title)
    fig.add(Circle((0.0, 0.0), cam.base * k, "link"))
    fig.add(Circle((0.0, 0.0), 0.6, "dot"))
    fig.add(Text((-1.5, 4.0), "O", 3.2, "end"))
    fig.add(Path(((-cam.base * k * 1.15, 0.0), (apex + 2 * cam.roller * k + 6.0, 0.0)),
                 "construction"))
    fig.add(Circle((apex, 0.0), 0.6, "dot"))
    mid = draw_dimension(fig, (cam.base * k, 0.0), (apex, 0.0), (0.0, 1.0),
                         offset=cam.base * k * 0.35)
    fig.add(Text((mid[0], mid[1] + 4.2), "h", 3.2))
    if "nose_radius" in given:
        fig.add(Circle((cam.d * k, 0.0), cam.nose * k, "link"))
        fig.add(Circle((cam.d * k, 0.0), 0.6, "dot"))
        fig.add(Text((cam.d * k - 1.5, -2.0), "Q", 3.2, "end"))
    if {"angle", "action_angle"} & set(given):
        r = cam.base * k
        fig.add(Path(((0.0, 0.0), (r * math.cos(cam.alpha), -r * math.sin(cam.alpha))),
                     "construction"))
        at = mark_angle(fig, (0.0, 0.0), 0.45 * r, 0.0, cam.alpha)
        fig.add(Text((at[0] + 2.0, at[1]), "α", 3.2, "start"))
    if cam.flat:
        fig.add(Path(((apex, -0.6 * cam.base * k), (apex, 0.6 * cam.base * k)), "reference"))
    elif cam.roller > 0:
        fig.add(Circle((apex + cam.roller * k, 0.0), cam.roller * k, "reference"))
    else:
        fig.add(Path(((apex, 0.0), (apex + 0.4 * cam.base * k, 0.0)), "reference"))
    draw_caption(fig, title, [words("the base circle, the lift and the follower at the apex")],
                 per_cm=per_cm, unit=unit)
    return fig
