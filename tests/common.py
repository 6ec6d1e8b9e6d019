"""Canonical mechanisms built once from the model dataclasses, in SI units.

Each builder returns a :class:`~constructions.model.Mechanism` at one input
position; the source of every dimension is cited. Angles are radians,
CCW-positive from +x.
"""

from __future__ import annotations

from pathlib import Path

from click.testing import CliRunner

from tarsim.constructions.joints import Slide, SlideKind
from tarsim.constructions.model import Drive, Link, Mechanism
from tarsim.constructions.units import Units
from tarsim.exercises.cli import cli
from tarsim.graphics.figure import Circle, Text

__all__ = ["four_bar", "offset_slider_crank", "crank_shaper", "slotted_lever_p37", "scotch_yoke"]


def four_bar(theta2: float, *, o2=(0.0, 0.0), o4=(0.3, 0.0), crank=0.1, coupler=0.25,
             rocker=0.2, omega2=0.0, alpha2=0.0, branch="left") -> Mechanism:
    """Return a 4R four-bar O2-A-B-O4; defaults are the benchmark of peers.md §4.

    Links: 1 frame (O2, O4), 2 crank O2A, 3 coupler AB, 4 rocker O4B. ``branch``
    is the side of B from A towards O4 ("left" is the open branch of peers.md).
    """
    return Mechanism(
        (Link(1, (("O2", tuple(o2)), ("O4", tuple(o4)))),
         Link(2, (("O2", (0.0, 0.0)), ("A", (crank, 0.0))), "crank"),
         Link(3, (("A", (0.0, 0.0)), ("B", (coupler, 0.0))), "coupler"),
         Link(4, (("O4", (0.0, 0.0)), ("B", (rocker, 0.0))), "rocker")),
        Drive(2, theta2, omega2, alpha2), branches={"B": branch}, units=Units("m"),
        name="four-bar")


def offset_slider_crank(theta2: float, *, crank=0.30, rod=0.70, offset=0.20, omega2=0.0,
                        alpha2=0.0, branch="forward") -> Mechanism:
    """Return an offset slider-crank; defaults are 000-part2 §3.3 (R 30, L 70, e 20 cm).

    Links: 1 frame (O2 at the origin), 2 crank O2A, 3 rod AC, 4 block at C sliding
    on the frame line y = ``offset`` in +x. ``branch`` "forward" puts C at
    x = R cos θ + √(L² − (R sin θ − e)²).
    """
    return Mechanism(
        (Link(1, (("O2", (0.0, 0.0)),)),
         Link(2, (("O2", (0.0, 0.0)), ("A", (crank, 0.0))), "crank"),
         Link(3, (("A", (0.0, 0.0)), ("C", (rod, 0.0))), "connecting rod"),
         Link(4, (("C", (0.0, 0.0)),), "slider")),
        Drive(2, theta2, omega2, alpha2),
        (Slide(SlideKind.BLOCK, 4, "C", 1, (0.0, offset), (1.0, 0.0)),),
        branches={"C": branch}, units=Units("cm"), name="offset slider-crank")


def crank_shaper(theta2: float, *, omega2=-1.0, alpha2=0.0) -> Mechanism:
    """Return the crank-shaper of seed 003 §2 (r1 500, r2 180, h 380 mm).

    Links: 1 frame (O2 at the origin, O4 500 mm below), 2 crank O2A, 3 block at A
    sliding in the slot of lever 4, 4 slotted lever (only its pivot O4; the slot is
    its axis), 5 ram: a block on the frame line y = 0.38 carrying pin B, which runs
    in the lever's slot. ω2 = −1 rad/s is the seed's MATLAB run (§2).
    """
    return Mechanism(
        (Link(1, (("O2", (0.0, 0.0)), ("O4", (0.0, -0.5)))),
         Link(2, (("O2", (0.0, 0.0)), ("A", (0.18, 0.0))), "crank"),
         Link(3, (("A", (0.0, 0.0)),), "block"),
         Link(4, (("O4", (0.0, 0.0)),), "slotted lever"),
         Link(5, (("B", (0.0, 0.0)),), "ram")),
        Drive(2, theta2, omega2, alpha2),
        (Slide(SlideKind.BLOCK, 3, "A", 4, (0.0, 0.0), (1.0, 0.0)),
         Slide(SlideKind.BLOCK, 5, "B", 1, (0.0, 0.38), (1.0, 0.0)),
         Slide(SlideKind.PIN, 5, "B", 4, (0.0, 0.0), (1.0, 0.0))),
        units=Units("mm"), name="crank shaper")


def slotted_lever_p37(theta2: float, *, omega2=1.0, alpha2=0.0, branch="forward") -> Mechanism:
    """Return the crank and slotted lever of exercise P-37 (000-part2 §3.4), in metres.

    O4 at the origin, O2 0.16 above it; crank O2A 0.06; block 3 at A in the slot of
    lever 4 (axis O4 → B, O4B 0.26); link 5 BC 0.12; ram 6 a block at C on the frame
    line y = 0.25 (⟂ O2O4, 0.25 from O4). ``branch`` is C's side along +x. The
    figure is missing from the notes, so the sides are our reading.
    """
    return Mechanism(
        (Link(1, (("O4", (0.0, 0.0)), ("O2", (0.0, 0.16)))),
         Link(2, (("O2", (0.0, 0.0)), ("A", (0.06, 0.0))), "crank"),
         Link(3, (("A", (0.0, 0.0)),), "block"),
         Link(4, (("O4", (0.0, 0.0)), ("B", (0.26, 0.0))), "slotted lever"),
         Link(5, (("B", (0.0, 0.0)), ("C", (0.12, 0.0))), "link BC"),
         Link(6, (("C", (0.0, 0.0)),), "ram")),
        Drive(2, theta2, omega2, alpha2),
        (Slide(SlideKind.BLOCK, 3, "A", 4, (0.0, 0.0), (1.0, 0.0)),
         Slide(SlideKind.BLOCK, 6, "C", 1, (0.0, 0.25), (1.0, 0.0))),
        branches={"C": branch}, units=Units("cm"), name="P-37 slotted lever")


def scotch_yoke(theta2: float, *, crank=0.1, omega2=0.0, alpha2=0.0) -> Mechanism:
    """Return a Scotch yoke: crank O2A, block 3 at A in the vertical slot of yoke 4.

    The yoke (a single point Y, its local origin) is a block on the frame's x axis;
    its slot runs along its local +y through Y, so x_Y = r cos θ2 exactly.
    """
    return Mechanism(
        (Link(1, (("O2", (0.0, 0.0)),)),
         Link(2, (("O2", (0.0, 0.0)), ("A", (crank, 0.0))), "crank"),
         Link(3, (("A", (0.0, 0.0)),), "block"),
         Link(4, (("Y", (0.0, 0.0)),), "yoke")),
        Drive(2, theta2, omega2, alpha2),
        (Slide(SlideKind.BLOCK, 3, "A", 4, (0.0, 0.0), (0.0, 1.0)),
         Slide(SlideKind.BLOCK, 4, "Y", 1, (0.0, 0.0), (1.0, 0.0))),
        units=Units("m"), name="Scotch yoke")


FOUR_BAR_TOML = """\
[frame]
O2 = [0, 0]
O4 = [{ground}, 0]

[[link]]
number = 2
points = ["O2", "A"]
lengths = {{ O2A = {crank} }}

[[link]]
number = 3
points = ["A", "B"]
lengths = {{ AB = {coupler} }}

[[link]]
number = 4
points = ["O4", "B"]
lengths = {{ O4B = {rocker} }}

[input]
link = 2
angle = {angle}
{assembly}"""


def four_bar_toml(*, ground=300, crank=100, coupler=250, rocker=200, angle=60,
                  branch: str | None = 'B = "left"') -> str:
    """A four-bar mechanism file (mm, deg) as text; ``branch=None`` leaves out [assembly]."""
    assembly = f"\n[assembly]\n{branch}\n" if branch else ""
    return FOUR_BAR_TOML.format(ground=ground, crank=crank, coupler=coupler, rocker=rocker,
                                angle=angle, assembly=assembly)


def coupler_four_bar(theta2, *, omega2=2.0):
    """The peers.md four-bar with a coupler point C off AB and D on AB (beyond B)."""
    m = four_bar(theta2, omega2=omega2)
    coupler = Link(3, (("A", (0.0, 0.0)), ("B", (0.25, 0.0)), ("C", (0.1, 0.08)),
                       ("D", (0.32, 0.0))), "coupler")
    links = tuple(coupler if k.number == 3 else k for k in m.links)
    return Mechanism(links, m.drive, m.slides, dict(m.branches), m.units, "coupler four-bar")


def inverted_slider_crank(theta2: float, *, ground=0.3, crank=0.12, lever=0.5, offset=0.0,
                          omega2=0.0, alpha2=0.0) -> Mechanism:
    """Return an inverted slider-crank: the crank-shaper's driving chain without the ram.

    Links: 1 frame (O2 at the origin, O4 ``ground`` along +x), 2 crank O2A, 3 block
    pinned to the crank at A and sliding in the slot of lever 4, 4 slotted lever
    pivoted at O4 with a point B ``lever`` along its axis. The slot runs along the
    lever's axis, ``offset`` to its left (0: through O4). With ``crank`` < ``ground``
    the lever rocks (the crank-shaper's chain); with ``crank`` > ``ground`` it turns
    fully, the driving chain of a Whitworth quick-return. Dimensions assumed, in
    metres (figures in mm).
    """
    return Mechanism(
        (Link(1, (("O2", (0.0, 0.0)), ("O4", (ground, 0.0)))),
         Link(2, (("O2", (0.0, 0.0)), ("A", (crank, 0.0))), "crank"),
         Link(3, (("A", (0.0, 0.0)),), "block"),
         Link(4, (("O4", (0.0, 0.0)), ("B", (lever, 0.0))), "slotted lever")),
        Drive(2, theta2, omega2, alpha2),
        (Slide(SlideKind.BLOCK, 3, "A", 4, (0.0, offset), (1.0, 0.0)),),
        units=Units("mm"), name="inverted slider-crank")


def badge_numbers(fig) -> list[int]:
    """The circled step numbers on a figure, in ascending order."""
    centres = [it.centre for it in fig.items if isinstance(it, Circle) and it.style == "badge"]
    return sorted(int(t.text) for t in fig.items if isinstance(t, Text) and t.at in centres)


def written_view(page: Path, step: str, exercise: str = "crank-shaper") -> Path:
    """``page``, the page ``tarsim view EXERCISE --step STEP`` writes there, as a user
    would write it; the command must succeed."""
    result = CliRunner().invoke(cli, ["view", exercise, "--step", step, "-o", str(page)])
    assert result.exit_code == 0, result.output
    return page
