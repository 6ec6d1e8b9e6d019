"""A cam's figures read as a textbook's: O named clear of the station lines, a flat face
seen at every station, an oscillating arm shown by the arc its end swings through (not by
arms crossing over the profile), and the displacement diagram's cam angle to a stated
scale."""

from __future__ import annotations

import math
import re

import pytest
from shapely.geometry import LineString, Point, box

from tarsim.graphics.figure import Circle, Path, Text

RADIAL = ("roller-harmonic-cycloidal", "eccentric-flat-face", "offset-knife-edge",
          "base-circle-for-pressure-angle", "valve-unequal-acceleration")
DIAGRAMS = RADIAL + ("oscillating-roller",)


_MARGIN = 8.0      # mm: draw_caption's margin round the drawing


def _drawn(fig) -> list:
    """The figure's items within its drawing (the caption's legend samples left out)."""
    bottom = _MARGIN + fig.drawing[1] + 0.5
    return [i for i in fig.items
            if max(y for _, y in (i.points if isinstance(i, Path) else [i.at if isinstance(
                i, Text) else i.centre])) <= bottom]


def _paths(fig, style: str) -> list[Path]:
    return [p for p in _drawn(fig) if isinstance(p, Path) and p.style == style]


@pytest.mark.parametrize("exercise", RADIAL)
def test_the_centre_is_named_clear_of_the_station_lines(solved, exercise):
    fig = solved(exercise).figures["profile"]
    (o,) = [t for t in fig.items if isinstance(t, Text) and t.text == "O"]
    named = box(*o.box())
    lines = [LineString(p.points) for p in _paths(fig, "construction")]
    assert lines
    # clear of every line by more than its half width (0.09 mm), as printed
    assert min(named.distance(line) for line in lines) > 0.09


def test_the_eccentric_cams_face_is_seen_at_every_station(solved):
    fig = solved("eccentric-flat-face").figures["profile"]
    profile = [LineString(p.points) for p in _paths(fig, "link") if len(p.points) > 2]
    faces = [p for p in _paths(fig, "node_circle") if len(p.points) == 2]
    assert len(faces) == 12
    for face in faces:
        # A face along the profile's tangent shows only where it stands off the heavy
        # line (0.6 mm wide): somewhere by a millimetre at least.
        (ax, ay), (bx, by) = face.points
        far = max(min(line.distance(Point(ax + t * (bx - ax), ay + t * (by - ay)))
                      for line in profile) for t in (i / 20 for i in range(21)))
        assert far >= 1.0, face.points


def test_the_oscillating_arms_are_drawn_as_their_ends_arcs(solved):
    fig = solved("oscillating-roller").figures["profile"]
    assert _paths(fig, "construction") == []          # no arm drawn as a line
    pivots = [c.centre for c in fig.items if isinstance(c, Circle) and c.style == "dot"]
    rollers = [c.centre for c in fig.items if isinstance(c, Circle)
               and c.style == "node_circle"]
    arcs = _paths(fig, "compass")
    assert len(arcs) == len(rollers) == 14
    for arc in arcs:
        # about one pivot: every point the arm's length from it (to 1e-9 mm, as drawn)
        centre = min(pivots, key=lambda p: max(abs(math.dist(p, q) - math.dist(p, arc.points[0]))
                                                for q in arc.points))
        r = math.dist(centre, arc.points[0])
        assert all(abs(math.dist(centre, q) - r) < 1e-9 for q in arc.points)
        # through its roller's centre, well within the arc (not at an end)
        line = LineString(arc.points)
        assert min(line.distance(Point(c)) for c in rollers) < 0.01
    # The arcs do not cross one another, as the arms did.
    lines = [LineString(a.points) for a in arcs]
    assert not any(a.crosses(b) for i, a in enumerate(lines) for b in lines[i + 1:])


@pytest.mark.parametrize("exercise", DIAGRAMS)
def test_the_displacement_diagram_states_its_cam_angle_scale(solved, exercise):
    fig = solved(exercise).figures["displacement"]
    texts = [t for t in fig.items if isinstance(t, Text)]
    axis = [t for t in _drawn(fig) if isinstance(t, Text)]
    stated = [m for t in texts
              if (m := re.fullmatch(r"Cam angle scale 1 cm = ([\d.]+)°", t.text))]
    assert len(stated) == 1
    per_cm = float(stated[0].group(1))
    ticks = {t.text: t.at[0] for t in axis if re.fullmatch(r"\d+°", t.text)}
    assert {"0°", "90°", "360°"} <= ticks.keys()
    for name, x in ticks.items():
        # each angle on the axis stands where the stated scale puts it, to the statement's
        # four significant figures
        assert (x - ticks["0°"]) / 10.0 * per_cm == pytest.approx(float(name[:-1]), rel=5e-4)
