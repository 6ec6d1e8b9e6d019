"""A record redone at another position of the input (constructions/replay.py), as the
interactive page turns the mechanism: the same acts, the input's ray laid off anew and the
lengths the polygons read off the drawing read again.

Two oracles: the record itself (redone at its own position, every step's output and every
parameter read off the drawing must come back bit for bit), and a fresh construction at
the new position, which tarsim's solve draws and the analytic solver checks.
"""

from __future__ import annotations

import math
from dataclasses import replace

import pytest

import tarsim
from tarsim.constructions.linkages.acceleration_polygon import draw_acceleration_polygon
from tarsim.constructions.linkages.assembly import assemble, input_ray, ray_at
from tarsim.constructions.linkages.velocity_polygon import draw_velocity_polygon
from tarsim.constructions.reference import solver
from tarsim.constructions.reference.centres import CentreReference, instant_centre
from tarsim.constructions.errors import TarsimError
from tarsim.constructions.replay import Replay
from tarsim.exercises.catalog import bundled
from tarsim.exercises.linkages.solution import solve_positions
from tarsim.exercises.linkages.view import _names, _scales
from tarsim.exercises.linkages.view_frames import Template, constructed

NAMES = sorted(bundled())


def _drawn(name: str, turn: float = 0.0):
    """``name``'s mechanism at its position turned by ``turn`` rad, with both polygons."""
    m = tarsim.load(name).mechanism
    m = m.with_drive(replace(m.drive, angle=m.drive.angle + turn))
    asm = assemble(m)
    draw_acceleration_polygon(asm, draw_velocity_polygon(asm))
    return m, asm


@pytest.mark.parametrize("name", NAMES)
def test_a_record_redone_where_it_was_drawn_is_itself(name):
    """Every step's output and each length read off the drawing come back bit for bit:
    the same verbs on the same inputs in the same order."""
    for turn in (0.0, 0.3, 1.7):
        try:
            _, asm = _drawn(name, turn)
        except TarsimError:
            continue                      # this turn is out of the mechanism's reach
        for step in asm:
            if step.derived is not None:
                assert step.derived(asm.output) == dict(step.params), step.id
        out, cond = Replay(asm, list(asm.steps)).run({})
        for step in asm:
            assert out[step.id] == step.output, step.id
            assert cond[step.id] == step.conditioning, step.id


def _relative(a, b, size):
    return max(math.dist(p, q) for p, q in zip(a, b)) / size


@pytest.mark.parametrize("name", ["four-bar", "crank-shaper", "whitworth", "hinkle-four-bar",
                                  "six-link-homework-3", "slotted-lever-p37"])
def test_a_record_redone_at_another_angle_is_the_construction_there(name):
    """A template redone 40° and 190° on puts the joints and both polygons' tips where a
    fresh construction there puts them: both are exact constructions, so they agree to
    rounding, 1e-12 of the mechanism's size and of the polygons' largest vector."""
    ex = tarsim.load(name)
    sol = solve_positions(replace(ex, positions=ex.positions[:1]))[0]
    mech = sol.assembly.mechanism
    angles = [mech.drive.angle + math.radians(0.5) * k for k in range(720)]
    scales = _scales(mech, sol)
    names = _names(mech, scales)
    template = Template.chosen(mech, angles, scales, names)
    assert template is not None
    compared = 0
    for k in (80, 380):
        fresh = constructed(mech, angles[k], scales, names)
        if "at" not in fresh:
            continue
        kin = solver.solve(mech.with_drive(replace(mech.drive, angle=angles[k])))
        again = template.frame(angles[k], kin)
        assert again is not None and again["ok"]
        for view in ("space", "velocity", "acceleration"):
            a, b = again["at"][view], fresh["at"][view]
            pts = [(x, y) for x, y, u, v in zip(a[::2], a[1::2], b[::2], b[1::2])
                   if None not in (x, y, u, v)]
            ref = [(u, v) for x, y, u, v in zip(a[::2], a[1::2], b[::2], b[1::2])
                   if None not in (x, y, u, v)]
            size = max(math.hypot(x, y) for x, y in ref) or 1.0
            # The page rounds each coordinate to 1e-7 (view_frames._round): two values a
            # hair apart may round a step apart in x and in y, √2·1e-7; a length read off
            # the drawing and not read again would be off by its whole change, 1e-3 or more.
            assert _relative(pts, ref, 1.0) <= 1.5e-7 + 1e-12 * size, view
            compared += 1
    assert compared >= 3


def test_a_ray_at_an_angle_is_the_one_position_by_compass_lays_off():
    """The ray the replay gives is the record's own at the record's angle."""
    m, asm = _drawn("four-bar")
    pivot = asm.point(m.link(m.drive.link).names[0])
    assert ray_at(pivot, m.drive.angle) == asm.output(input_ray(m.drive.link))


@pytest.mark.parametrize("name", ["four-bar", "crank-shaper", "six-link-homework-1"])
def test_the_centres_of_one_solution_are_each_centre_alone(name):
    """CentreReference finds what is shared once; each centre is instant_centre's, to the
    bit."""
    m = tarsim.load(name).mechanism
    kin = solver.solve(m)
    ref = CentreReference(kin)
    links = sorted(m.numbers)
    for i in links:
        for j in links:
            if i < j:
                try:
                    alone = instant_centre(kin, i, j)
                except TarsimError:
                    continue
                assert ref.centre(i, j) == alone
