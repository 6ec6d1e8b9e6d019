"""The force polygons' figure (graphics/forces/force_figure.py, force_key.py): each link's
polygon in a panel of its own at a force scale that fits it, each force named beside its
own arrow in its own polygon, and a key to every name drawn.

The crank-shaper at t = 2.34 s is the case: its forces run from 0.05 N (the ram's inertia)
to 44 N (the lever's weight), so one scale for all drew the ram's polygon as a dot.
"""

from __future__ import annotations

import math
import re

import pytest

from tarsim.constructions.forces.polygons import drawn_forces
from tarsim.graphics.figure import Path, Text

SHAPER = "crank-shaper-forces"
AT = "forces-t-2.34s"

_HEAD = 0.7 * 2.6
"""What a shaft stops short of its arrow's tip (mm): the head's notch (symbols.draw_arrow)."""


def _panels(fig):
    """Each polygon's panel by its mark step: its force arrows' shafts, its names and its
    stated scale (N a paper cm)."""
    panels: dict[str, dict] = {}
    for it in fig.items:
        if not it.steps:
            continue
        p = panels.setdefault(it.steps[0], {"shafts": [], "names": [], "per_cm": None,
                                            "title": None})
        if isinstance(it, Path) and it.style in ("vector", "vector_result"):
            p["shafts"].append(it.points)
        elif isinstance(it, Text) and it.text.startswith("Force scale 1 cm = "):
            p["per_cm"] = float(re.match(r"Force scale 1 cm = ([\d.]+) N", it.text)[1])
        elif isinstance(it, Text) and it.weight == "bold":
            p["title"] = it.text
        elif isinstance(it, Text) and it.owner and len(it.owner) == 2:
            p["names"].append(it)
    return panels


@pytest.fixture(scope="module")
def shaper(solved):
    worked = solved(SHAPER)
    (sol,) = [s for s in worked.positions if s.position and "2.34" in s.position.label]
    return worked.figures[AT], drawn_forces(sol.work)


def test_each_polygon_is_drawn_at_a_scale_that_fits_it(shaper):
    """Link 5's polygon (1 N at most) and link 4's (44 N) each have a longest side of 4 cm
    at least, at a 1-2-5 scale stated on their own panel, and every closing side is as
    long as that scale makes the force the polygons found (the same floats: 1e-9)."""
    fig, forces = shaper
    panels = _panels(fig)
    titles = {p["title"]: p for p in panels.values()}
    assert set(titles) == {"link 5", "link 3", "link 4", "link 2"}
    scales = {t: p["per_cm"] for t, p in titles.items()}
    assert scales == {"link 5": 0.2, "link 3": 2.0, "link 4": 10.0, "link 2": 5.0}
    for title, p in titles.items():
        longest = max(math.dist(s[0], s[-1]) for s in p["shafts"]) + _HEAD
        # 40 mm at least (the next finer 1-2-5 step would overfill the 150 × 110 panel)
        assert 40.0 - 1e-9 <= longest <= 150.0, (title, longest)
        for t in p["names"]:
            name = t.text + "_" + t.sub
            if name in forces.joints:
                drawn = math.dist(*t.owner) / 10.0 * p["per_cm"]
                assert drawn == pytest.approx(math.hypot(*forces.joints[name]), rel=1e-9)
    # no single force scale is claimed for the whole figure any more
    assert not [t for t in fig.items if isinstance(t, Text) and not t.steps
                and t.text.startswith("Force scale")]


def test_each_force_is_named_beside_its_own_arrow_in_its_own_polygon(shaper):
    """Every force's name stands within 3 mm (about a name's height: nearer, it reads as
    that arrow's) of its own shaft and no nearer another, drawn with that shaft's polygon:
    F₃₂ stood 5.7 mm off its arrow and F₄₃ 4.0 mm, each as near another, between
    polygons."""
    fig, _ = shaper
    shafts = [it for it in fig.items if isinstance(it, Path)
              and it.style in ("vector", "vector_result")]
    names = [t for t in fig.items if isinstance(t, Text) and t.owner and len(t.owner) == 2]
    assert len(names) >= 10
    for t in names:
        (own,) = [s for s in shafts if math.dist(s.points[0], t.owner[0]) < 1e-9
                  and _gap(s.points[-1:] * 2, *t.owner) < 1e-6]
        gap = _gap(t.box(), own.points[0], t.owner[1])
        assert gap <= 3.0, (t.text, t.sub, gap)
        others = [_gap(t.box(), s.points[0], s.points[-1]) for s in shafts if s is not own]
        assert gap <= min(others) + 1e-9, (t.text, t.sub)
        assert t.steps == own.steps != (), (t.text, t.sub)


@pytest.mark.parametrize("at, keyed", [
    ("forces-t-2.34s", {("F", "R"), ("F", "T"), ("t", ""), ("x", ""), ("F", "ij"),
                        ("W", "k"), ("F", "ik")}),
    # F_32 is all crank effort at θ2 = 90°: one arrow named "F_32 = F_T", F_T keyed all the same
    ("forces-theta2-90", {("F", "T"), ("t", ""), ("x", ""), ("F", "ij"), ("W", "k")})])
def test_every_name_drawn_is_in_the_key(solved, at, keyed):
    """F_R, F_T, t and x, and each kind of load (F_ij, W_k, F_ik), are keyed under the
    figure's legend, each by its own letter and subscript."""
    fig = solved(SHAPER).figures[at]
    (legend,) = [t.at[1] for t in fig.items if isinstance(t, Text) and t.text == "a force"]
    key = {(t.text, t.sub) for t in fig.items if isinstance(t, Text) and t.at[1] > legend
           and t.italic}
    assert keyed <= key


def _gap(box, a, b) -> float:
    """The least distance (mm) from the box (x0, y0, x1, y1, or a point twice) to the
    segment a–b (0 if they touch)."""
    from shapely.geometry import LineString, box as shapely_box

    if len(box) == 2:
        box = (*box[0], *box[1])
    return shapely_box(*box).distance(LineString([a, b]))
