"""A rolling wheel's acceleration polygon reads: no name over another or over an arrowhead,
and at the worked page's scale none over an arrow's shaft and each by its own arrow or point
or led to it.

A wheel that rolls gives its polygon short arrows beside long ones (the centre's own
acceleration, the tangential components at the rim's point) that crowd at one or two
tips; their names used to stand off in the white, 7 to 16 mm from what they name, or over
the shafts beside them. Checked on the worked page's acceleration panel as solved, and
drawn at the next finer scale (the scale a sheet with room takes), from the Figure model.
"""

from __future__ import annotations

import pytest
from shapely.geometry import LineString, Point, Polygon, box

from tarsim import load, solve
from tarsim.exercises.catalog import resolve
from tarsim.graphics.figure import Circle, Path, Text
from tests.test_label_distance import strays

GRAZE = 0.01
"""mm²: two shapes sharing more than this overlap (a hundredth of a square millimetre: a
name's edge on a shaft's, not white between them)."""

WHEELS = {"wheel-round-circle": "1 cm = 0.25 m/s^2", "wheel-driven-slider": "1 cm = 10 m/s^2"}
"""The bundled rolling wheels asked an acceleration, and each one's next finer scale than
its worked page's (500 mm/s² and 20000 mm/s² to the centimetre)."""


def _panel(fig, heading: str = "Acceleration polygon"):
    """The items inside the worked page's frame that holds ``heading``."""
    at = next(t.at for t in fig.items if isinstance(t, Text) and t.text == heading)
    frame = next(Polygon(p.points) for p in fig.items if isinstance(p, Path)
                 and p.style == "frame" and Polygon(p.points).contains(Point(at)))
    inside = [it for it in fig.items if frame.contains(Point(_where(it)))]
    return inside


def _where(item):
    if isinstance(item, Text):
        return item.at
    if isinstance(item, Circle):
        return item.centre
    return item.points[0]


def _names(items):
    """Each name's box and each step number's disc (its own number is the disc)."""
    discs = [c for c in items if isinstance(c, Circle) and c.style == "badge"]
    centres = {c.centre for c in discs}
    return ([(t.text + t.sub, box(*t.box())) for t in items if isinstance(t, Text)
             and t.text.strip() and t.at not in centres]
            + [(f"({c.centre[0]:.0f}, {c.centre[1]:.0f})", Point(c.centre).buffer(c.radius))
               for c in discs])


def _covered(items) -> list[tuple[str, str]]:
    """Each pair of a name and what it lies over: another name, an arrowhead, a shaft."""
    names = _names(items)
    heads = [Polygon(p.points) for p in items if isinstance(p, Path) and p.closed
             and p.style == "arrowhead"]
    shafts = [LineString(p.points).buffer(0.1) for p in items if isinstance(p, Path)
              and p.style in ("vector", "vector_result")]
    out = [(a, b) for i, (a, ga) in enumerate(names) for b, gb in names[i + 1:]
           if ga.intersection(gb).area > GRAZE]
    out += [(a, "a head") for a, g in names for h in heads if g.intersection(h).area > GRAZE]
    out += [(a, "a shaft") for a, g in names for s in shafts if g.intersection(s).area > GRAZE]
    return out


def _solved(name: str, scale: str | None, tmp_path):
    if scale is None:
        return solve(load(name)).figures["worked"]
    text = resolve(name).read_text(encoding="utf-8")
    assert "\nmethods = " in text
    path = tmp_path / f"{name}.toml"
    path.write_text(text.replace("\nmethods = ", f'\nscale = "{scale}"\nmethods = ', 1),
                    encoding="utf-8")
    return solve(load(str(path))).figures["worked"]


@pytest.mark.parametrize("name", sorted(WHEELS))
@pytest.mark.parametrize("finer", [False, True], ids=["as-solved", "finer"])
def test_rolling_wheel_acceleration_names_read(name, finer, tmp_path):
    fig = _solved(name, WHEELS[name] if finer else None, tmp_path)
    items = _panel(fig)
    assert len(_names(items)) > 20          # the crowded polygon it is
    covered = _covered(items)
    assert [c for c in covered if c[1] != "a shaft"] == []
    if not finer:
        assert covered == []
        assert strays(fig) == []
    else:
        # Finer, the wheel-driven slider's a′, where five arrows end, still lies over two
        # shafts, and a short arrow's name may stand off unled.
        stated = WHEELS[name].split("= ")[1].replace("^2", "²")
        assert any(isinstance(t, Text) and t.text.endswith(stated) for t in items)
