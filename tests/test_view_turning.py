"""The interactive page turning the crank-shaper (``tarsim view``), in a real browser:
Debian's chromium driven by playwright, the page opened from disk.

While the input turns, the construction the exercise asks (V_B by radius rotation) is
redrawn at each frame from the points tarsim's own constructions put there, and each
polygon is drawn at a scale of its own frame's, filling its panel.
"""

from __future__ import annotations

import math
import re
from dataclasses import replace

import pytest

from tarsim.exercises.catalog import load
from tarsim.exercises.linkages.solution import solve_positions
from tarsim.exercises.linkages.view_figures import solved_at
from tarsim.graphics.paper import paper, room

from tests.common import written_view

pytestmark = pytest.mark.slow

ANGLES = (40.0, 200.0, 320.0)
"""Crank angles the page is turned to: frames of a page made every 2.5° from 90°."""

SWUNG = ("rr:B:rot:k", "rr:B:tip:k", "I:25", "rr:B:tip:t", "P:B", "rr:B:tip")
"""The radius rotation's points, by their steps: A swung onto the line of centres (A′),
V_A laid off there, the transfer centre I25 and V_I25's tip on the gauge line, and V_B
laid off at B."""


@pytest.fixture(scope="module")
def shaper(tmp_path_factory):
    """The crank-shaper's page as the command writes it, a frame every 2.5°."""
    return written_view(tmp_path_factory.mktemp("turning") / "shaper.html", "2.5")


@pytest.fixture()
def page(browser, shaper):
    p = browser.new_page(viewport={"width": 1400, "height": 1000})
    p.errors = []
    p.on("pageerror", lambda e: p.errors.append(str(e)))
    p.goto(shaper.as_uri())
    yield p
    assert p.errors == []
    p.close()


def _turn(page, angle: float) -> int:
    """Show the frame at θ2 = ``angle``; its index."""
    k = page.evaluate("""a => tarsimView.data.frames.findIndex(
        f => Math.abs(((f.angle * 180 / Math.PI - a) % 360 + 540) % 360 - 180) < 1e-6)""", angle)
    assert k > 0
    page.evaluate(f"tarsimView.setFrame({k})")
    return k


_SHOWN = """() => {
  const S = tarsimView.state, svg = document.querySelector('#sheet svg');
  const m = svg.getScreenCTM();
  return S.items.map(it => {
    const el = it.el, shown = getComputedStyle(el).display !== 'none';
    let xy = [];
    if (it.kind === 'c') xy = [+el.getAttribute('cx'), +el.getAttribute('cy')];
    else if (it.kind !== 't') xy = (el.getAttribute('d').match(/-?[\\d.]+/g) || []).map(Number);
    const screen = [];
    for (let i = 0; i < xy.length; i += 2) {
      const p = new DOMPoint(xy[i], xy[i + 1]).matrixTransform(m); screen.push(p.x, p.y); }
    return {shown, kind: it.kind, style: el.getAttribute('class'), paper: xy, screen,
            text: it.kind === 't' ? el.textContent : null};
  });
}"""
"""Each primitive of the figure shown, as the browser drew it: shown or not, its points on
the paper (mm) and on the screen (pixels)."""


def _pairs(xy: list[float]) -> list[tuple[float, float]]:
    return list(zip(xy[::2], xy[1::2]))


def test_the_radius_rotation_is_redrawn_where_tarsim_constructs_it_at_each_angle(page):
    """Turned to three crank angles, the radius-rotation figure draws A swung onto the line
    of centres, V_A laid off there, I25 and its velocity, and V_B at B where tarsim's own
    construction puts them at that angle (its record solved there, mapped through the
    figure's scale), and the arc of the swing about I12 from A to A′: each point a vertex
    of a primitive shown, to 0.01 mm of paper (the page writes a coordinate to 1 µm and a
    frame's point to 0.1 µm of the world, 0.014 µm of paper at 7 cm = 500 mm). They stand
    elsewhere on the screen from one angle to another."""
    stem = "V_B-radius-rotation"
    index = page.evaluate(f"tarsimView.data.figures.findIndex(f => f.stem === '{stem}')")
    page.select_option("#figure", str(index))
    ex = load("crank-shaper")
    where = room(paper(ex.paper))
    home = solve_positions(replace(ex, positions=ex.positions[:1]), room=where)[0]
    seen: dict[str, list[tuple[float, float]]] = {}
    for angle in ANGLES:
        _turn(page, angle)
        sol = solved_at(home, math.radians(angle), where)
        s, ox, oy = page.evaluate("tarsimView.data.figures.find(f => f.stem === "
                                  f"'{stem}').drawn.en.turning.views.space")

        def on_paper(ref: str, sol=sol, view=(s, ox, oy)) -> tuple[float, float]:
            x, y = sol.assembly.output(ref).xy
            return view[1] + view[0] * x, view[2] - view[0] * y

        drawn = [it for it in page.evaluate(_SHOWN) if it["shown"]]
        for ref in SWUNG:
            want = on_paper(ref)
            near = min((math.dist(want, p), it["screen"][2 * j:2 * j + 2])
                       for it in drawn for j, p in enumerate(_pairs(it["paper"])))
            assert near[0] <= 0.01, (angle, ref, near[0])
            seen.setdefault(ref, []).append(tuple(near[1]))
        centre, start, end = on_paper("I:12"), on_paper("P:A"), on_paper("rr:B:rot:k")
        arcs = [_pairs(it["paper"]) for it in drawn if "s-compass" in it["style"]]
        arc = next(a for a in arcs if math.dist(a[0], start) <= 0.01)
        assert math.dist(arc[-1], end) <= 0.01
        radius = math.dist(centre, start)
        assert max(abs(math.dist(centre, p) - radius) for p in arc) <= 0.01
    # Redrawn, not left where it was: each point moves between some two of the angles (A′
    # is swung onto the vertical through I12, at I12A above or below it: it may come back).
    for ref, places in seen.items():
        assert max(math.dist(a, b) for i, a in enumerate(places) for b in places[i + 1:]) > 5, ref


def test_the_polygons_are_drawn_at_each_frame_s_own_scale(page):
    """At θ2 = 342.5° (the frame nearest 343°, where one scale for the whole turn shrinks the
    crank-shaper's polygons to a blob), each polygon of the worked solution is drawn at a
    scale of that frame's, stated in its panel: it spans at least 40 % of its panel's
    frame across or down, and the statement is not the exercise's 3 cm = 18 cm/s."""
    index = page.evaluate("tarsimView.data.figures.findIndex(f => f.stem === 'worked')")
    page.select_option("#figure", str(index))
    home = [it["text"] for it in page.evaluate(_SHOWN) if it["text"]]
    assert any("3 cm = 18 cm/s" in t for t in home)
    k = _turn(page, 342.5)
    said = page.evaluate(f"""() => {{ const f = tarsimView.data.figures[{index}].fit;
        return Object.fromEntries(Object.entries(f.at).map(([v, at]) =>
            [v, f.said[v][at[6 * {k} + 3]].en])); }}""")
    items = page.evaluate(_SHOWN)
    views = page.evaluate("tarsimView.state.items.map(it => it.move ? it.move[0] : it.fixed "
                          "|| null)")
    frames = page.evaluate("tarsimView.state.items.map(it => !!it.frame)")
    for view, statement in said.items():
        assert statement not in home
        assert any(it["shown"] and it["text"] == statement for it in items), statement
        panel = next(it for it, v, f in zip(items, views, frames) if f and v == view)
        x0, y0 = min(panel["paper"][::2]), min(panel["paper"][1::2])
        x1, y1 = max(panel["paper"][::2]), max(panel["paper"][1::2])
        shape = [p for it, v in zip(items, views) if it["shown"] and v == view
                 and it["kind"] != "t" for p in _pairs(it["paper"])]
        across = (max(x for x, _ in shape) - min(x for x, _ in shape)) / (x1 - x0)
        down = (max(y for _, y in shape) - min(y for _, y in shape)) / (y1 - y0)
        assert max(across, down) >= 0.4, (view, across, down)
        assert all(x0 <= x <= x1 and y0 <= y <= y1 for x, y in shape), view


def test_a_frame_s_scale_is_a_nice_one_and_said_in_persian(page):
    """Each frame's polygon scale is 1, 2 or 5 × 10^k a paper cm, stated in Persian with
    Persian digits when the page speaks Persian."""
    index = page.evaluate("tarsimView.data.figures.findIndex(f => f.stem === 'worked')")
    page.select_option("#figure", str(index))
    page.click("#lang")
    _turn(page, 342.5)
    texts = [it["text"] for it in page.evaluate(_SHOWN) if it["shown"] and it["text"]]
    stated = [t for t in texts if t.startswith(("مقیاس سرعت", "مقیاس شتاب"))]
    assert len(stated) == 2 and all(re.search("[۰-۹]", t) for t in stated)
    fits = page.evaluate(f"tarsimView.data.figures[{index}].fit.said")
    for said in fits.values():
        for statement in said:
            n = float(re.search(r"= ([\d.]+)", statement["en"]).group(1))
            assert re.fullmatch(r"1 cm", re.search(r"(\d+ cm) =", statement["en"]).group(1))
            assert f"{n / 10 ** math.floor(math.log10(n)):.9g}" in ("1", "2", "5")


def test_what_stands_on_nothing_is_hidden_while_turning(page):
    """Turned to θ2 = 342.5°, the worked solution shows no caption of the drawing it turns
    (drawn at 75°: its sheets' titles, its angle, its results table), placed by the
    drawing's extent and true at 75° alone; the polygons' own captions stay, said at the
    frame's scale."""
    index = page.evaluate("tarsimView.data.figures.findIndex(f => f.stem === 'worked')")
    page.select_option("#figure", str(index))
    assert any("worked solution" in (it["text"] or "") for it in page.evaluate(_SHOWN))
    _turn(page, 342.5)
    shown = [it["text"] for it in page.evaluate(_SHOWN) if it["shown"] and it["text"]]
    assert not [t for t in shown if "worked solution" in t or "75°" in t or "analytic" in t]
    assert {"Velocity polygon", "Acceleration polygon"} <= set(shown)
