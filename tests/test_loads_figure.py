"""The space diagram with its loads (graphics/forces/loads_figure.py): each load an arrow from where
it acts, and each inertia force drawn a second time as the one force that does the work of
it and its couple, h = I·α/(m·a_G) off G; a load or an offset force that would stand beyond
the frame a scene grows to is named under the figure instead of stretching the page to reach
it. h is the reference solver's, not the drawing's.
"""

from __future__ import annotations

import math
import re
from pathlib import Path

import pytest

import tarsim
from tarsim.constructions.reference import solver
from tarsim.constructions.reference.kinetostatics import world_point
from tarsim.constructions.reference.solver import point_acceleration
from tarsim.graphics.figure import Path as Stroke
from tarsim.graphics.figure import Text

NANO = Path(__file__).parent / "data" / "nanometre-slider-crank-couple.toml"


def _h_mm(ex, link: int) -> float:
    """h = I·|α|/(m·|a_G|) of ``link``'s mass (mm), by the reference solver."""
    mech = ex.mechanism
    kin = solver.solve(mech)
    m = ex.loads.mass_of(link)
    a_g = point_acceleration(kin, mech, link, world_point(kin, mech, link, m.centre))
    return m.inertia * abs(kin.alphas[link]) / (m.mass * math.hypot(*a_g)) * 1e3


def test_an_offset_inertia_force_beyond_the_drawing_is_named_under_it():
    """tests/data/nanometre-slider-crank-couple.toml: the rod's couple of 3e41 N·m over its
    force of 3.5e39 N puts the one force 87 m off G on a mechanism 1e-9 m long, 8.7e10
    times over; drawn there, it stretched the page to 758151294215 × 420665442737 mm. Only
    its force at G and its couple are drawn, the page is A4, and the note under the figure
    gives h to the 3 figures it prints."""
    worked = tarsim.solve(tarsim.load(str(NANO)))
    fig = worked.figures["loads"]
    assert worked.oversize() == {}
    assert sorted((fig.width, fig.height)) == [210.0, 297.0]
    assert not any(isinstance(p, Stroke) and p.style == "vector_dashed" for p in fig.items)
    (note,) = [t.text for t in fig.items
               if isinstance(t, Text) and "Beyond the drawing" in t.text]
    (h,) = re.findall(r"Fi3′ \(h = ([0-9.e+]+) mm\) on link 3", note)
    # Printed to 3 figures: within half a unit of the third.
    assert float(h) == pytest.approx(_h_mm(worked.exercise, 3), rel=5e-3)


def test_an_offset_inertia_force_on_the_drawing_is_drawn_dashed_at_h():
    """The bundled engine's rod: its one force stands h = I·α/(m·a_G) = 14.7 mm off G on a
    mechanism of 300 mm, drawn dashed and named with h, and no note names it."""
    worked = tarsim.solve(tarsim.load("engine-forces"))
    fig = worked.figures["loads"]
    assert any(isinstance(p, Stroke) and p.style == "vector_dashed" for p in fig.items)
    (named,) = [t for t in fig.items if isinstance(t, Text) and t.sub == "i3"
                and t.tail.startswith("′ (h = ")]
    h = float(named.tail.split("= ")[1].split(" mm")[0])
    assert h == pytest.approx(_h_mm(worked.exercise, 3), rel=5e-3)
    assert not any(isinstance(t, Text) and "Beyond the drawing" in t.text for t in fig.items)


def _force_scale(fig) -> float:
    """The newtons a paper cm the caption states."""
    (per_cm,) = [float(t.text.split("= ")[1].split(" N")[0]) for t in fig.items
                 if isinstance(t, Text) and t.text.startswith("Force scale 1 cm")]
    return per_cm


def test_a_force_far_off_its_link_is_named_under_the_drawing():
    """The bundled loaded four-bar (300 mm across) with 500 N more on its crank at a point
    30 m along it: drawn there, the point would shrink the mechanism to a dot or stretch
    the page 100 times. It is named under the figure, and the figure, its force scale and
    its sheet are the bundled four-bar's own."""
    from tarsim.exercises.catalog import bundled
    from tarsim.exercises.linkages.exercise_file import parse_exercise

    text = Path(bundled("forces")["four-bar-forces"]).read_text(encoding="utf-8")
    far = text.replace("[[couple]]", '[[force]]\nlink = 2\nname = "P"\npoint = [30000, 0]\n'
                                     "force = [0, -500]\n\n[[couple]]")
    plain = tarsim.solve(parse_exercise(text, "four-bar.toml")).figures["loads"]
    worked = tarsim.solve(parse_exercise(far, "four-bar.toml"))
    fig = worked.figures["loads"]
    assert worked.oversize() == {}
    assert (fig.width, fig.height) == (plain.width, plain.height)
    assert _force_scale(fig) == _force_scale(plain)
    notes = [t.text for t in fig.items if isinstance(t, Text) and "Beyond the drawing" in t.text]
    assert notes == ["Beyond the drawing, so not drawn: P = 500 N on link 2."]
