"""The involute mesh's figure draws teeth by the involute's construction and names its
lines: measured on the figure's own paths, each drawn flank is an involute of its base
circle, each tooth is π·m/2 thick on its pitch circle, and the circles, the line of action
and the path and arc of contact are named, no name over another."""

from __future__ import annotations

import math
import re

import pytest

from tarsim.graphics.figure import STYLES, Path, Text
from tests.label_overlaps import count

RESOLUTION = 0.0005
"""Paper mm: the SVG writes coordinates to a micrometre, so a vertex is where it is meant
to be within half of one."""

CHORD = 0.01
"""Paper mm: the polyline between two vertices may leave the curve by this much, a
sixtieth of the 0.6 mm line it is drawn with."""


def _inv(phi: float) -> float:
    return math.tan(phi) - phi


@pytest.fixture(scope="module")
def drawn(solved):
    s = solved("involute-pair")
    fig = s.figures["mesh"]
    scale = next(t.text for t in fig.items if isinstance(t, Text)
                 and t.text.startswith("Scale "))
    k = 10.0 / float(re.fullmatch(r"Scale 1 cm = ([\d.]+) mm", scale).group(1))  # mm/mm
    label = next(t for t in fig.items if isinstance(t, Text) and t.text == "P")
    p = label.owner[0] if label.owner else min(
        (d.centre for d in fig.items if getattr(d, "style", "") == "dot"),
        key=lambda q: math.dist(q, label.at))
    m = s.mesh
    c = m.construction
    px, _ = c.output("P").xy
    (a, (ax, _)), (b, (bx, _)) = m.centres.items()
    # The line of centres stands upright, the pinion below P and the wheel above.
    gears = {a: ((p[0], p[1] + abs(px - ax) * 1e3 * k), "2"),
             b: ((p[0], p[1] - abs(bx - px) * 1e3 * k), "3")}
    return s, fig, k, gears


def _radii(s, tag: str) -> dict[str, float]:
    return {name: s.mesh.radii[f"{name}{tag}"] * 1e3 for name in
            ("pitch", "base", "addendum", "root")}


def _flanks(fig, centre, radii, k):
    """The runs of the gear's outline between its base (or root) and addendum circles, each
    as (r, θ) in world mm and paper radians, θ unwrapped along the run."""
    outline = [p for p in fig.items if isinstance(p, Path) and p.style == "link"
               and all(radii["root"] - 0.01 <= math.dist(q, centre) / k
                       <= radii["addendum"] + 0.01 for q in p.points)]
    assert len(outline) == 1
    low = max(radii["base"], radii["root"]) + 1e-6
    runs, run = [], []
    for q in outline[0].points:
        r = math.dist(q, centre) / k
        if low < r < radii["addendum"] - 1e-6:
            run.append((r, math.atan2(-(q[1] - centre[1]), q[0] - centre[0]), q))
        else:
            if len(run) > 2:
                runs.append(run)
            run = []
    return runs


@pytest.mark.parametrize("which", [0, 1])
def test_each_flank_is_an_involute_of_its_base_circle(drawn, which):
    s, fig, k, gears = drawn
    centre, tag = list(gears.values())[which]
    radii = _radii(s, tag)
    teeth = round(2 * math.pi * radii["pitch"] / (s.mesh.circular_pitch * 1e3))
    runs = _flanks(fig, centre, radii, k)
    assert len(runs) == 2 * 6                 # three teeth either side of P, two flanks each
    thickness = []
    starts = []
    for run in runs:
        rising = run[-1][0] > run[0][0]
        theta = [t for _, t, _ in run]
        for i in range(1, len(theta)):          # unwrap across ±π
            theta[i] = theta[i - 1] + math.remainder(theta[i] - theta[i - 1], 2 * math.pi)
        rs = [r for r, _, _ in run]
        way = 1.0 if (theta[-1] - theta[0]) * (1 if rising else -1) > 0 else -1.0
        # θ(r) = β + way·inv φ, cos φ = r_b / r: one β along the whole flank
        beta = [t - way * _inv(math.acos(radii["base"] / r)) for r, t in zip(rs, theta)]
        for r, b in zip(rs, beta):
            assert abs(b - beta[0]) * r * k <= RESOLUTION
        for (_, _, q0), (_, _, q1) in zip(run, run[1:]):
            mid = ((q0[0] + q1[0]) / 2, (q0[1] + q1[1]) / 2)
            rm = math.dist(mid, centre) / k
            tm = theta[0] + math.remainder(math.atan2(-(mid[1] - centre[1]), mid[0] - centre[0])
                                           - theta[0], 2 * math.pi)
            off = tm - way * _inv(math.acos(radii["base"] / rm)) - beta[0]
            assert abs(off) * rm * k <= CHORD
        # where the flank crosses the pitch circle, from its own β
        starts.append(beta[0] + way * _inv(math.acos(radii["base"] / radii["pitch"])))
        thickness.append(way)
    # Flanks come in pairs round each tooth: the one turning one way, then the other.
    assert thickness == [thickness[0], -thickness[0]] * 6
    for left, right in zip(starts[::2], starts[1::2]):
        width = abs(math.remainder(right - left, 2 * math.pi)) * radii["pitch"]
        m = 2 * radii["pitch"] / teeth
        assert width == pytest.approx(math.pi * m / 2, abs=RESOLUTION / k)
    # and the teeth stand a circular pitch apart
    for one, two in zip(starts[::2], starts[2::2]):
        assert abs(math.remainder(two - one, 2 * math.pi)) == pytest.approx(
            2 * math.pi / teeth, abs=RESOLUTION / (radii["pitch"] * k))


def test_the_circles_and_lines_are_named_and_no_name_covers_another(drawn):
    s, fig, _, _ = drawn
    texts = {t.text for t in fig.items if isinstance(t, Text)}
    for kind in ("pitch", "base", "addendum"):
        for gear in s.mesh.centres:
            assert f"{kind} circle {gear}" in texts
    assert {"line of action", "path of contact", "arc of contact"} <= texts
    assert count(fig)["label-label"] == 0
    assert count(fig)["label-arrowhead"] == 0


def test_each_kind_of_line_has_its_own_style_in_the_legend(drawn):
    _, fig, _, _ = drawn
    texts = {t.text for t in fig.items if isinstance(t, Text)}
    assert {"pitch circles", "base circles", "addendum and root circles", "line of centres",
            "line of action", "path of contact", "arc of contact"} <= texts
    kinds = {"pitch": "construction", "base": "reference", "addendum": "gauge",
             "centres": "centre_line"}
    looks = {(STYLES[s].width, STYLES[s].dash, STYLES[s].stroke) for s in kinds.values()}
    assert len(looks) == len(kinds)
    # the line of centres: chain-dotted and heavier than the thin circles
    centre = STYLES["centre_line"]
    assert len(centre.dash) == 4 and centre.width >= 2 * STYLES["reference"].width
    assert any(isinstance(p, Path) and p.style == "centre_line" for p in fig.items)
