"""The interactive page (``tarsim view``), in a real browser: Debian's chromium driven by
playwright, the page opened from disk.

Its figures are held to the SVGs `tarsim solve` writes (element for element, in English
and in Persian), its steps to steps.md (the same numbers, the same words), its frames to
the figures tarsim draws at those angles and to results.json there, and the page to
itself: nothing leaves it, nothing fails in its script, and its script draws no
mechanism of its own.
"""

from __future__ import annotations

import json
import math
import re
import xml.etree.ElementTree as ET
from dataclasses import replace
from pathlib import Path

import pytest
from click.testing import CliRunner

from tarsim.exercises.catalog import load
from tarsim.exercises.cli import cli
from tarsim.exercises.linkages.exercise_file import parse_exercise
from tarsim.exercises.linkages.results_json import results_json
from tarsim.exercises.linkages.solution import solve_positions
from tarsim.exercises.linkages.view import view_data
from tarsim.exercises.linkages.view_figures import solved_at
from tarsim.graphics.paper import paper, room
from tarsim.graphics.view_page import ViewPage, view_html

from tests.common import four_bar_toml, written_view
from tests.figure_leaves import PAGE_LEAVES, SVG, as_tuples, svg_leaves

# One worker runs the whole file (--dist loadfile), so chromium is opened and the pages
# made once.
pytestmark = pytest.mark.slow


@pytest.fixture(scope="module")
def shaper(tmp_path_factory, solved):
    """The crank-shaper's page written by the command, a frame every 2.5° (every angle the
    tests turn to; the default 0.5° is the notebook test's), and its steps.md as `tarsim
    solve` writes it, in both languages."""
    page = written_view(tmp_path_factory.mktemp("view") / "shaper.html", "2.5")
    worked = solved("crank-shaper")
    return page, {lang: worked.steps(lang) for lang in ("en", "fa")}


@pytest.fixture()
def page(browser, shaper):
    """The page opened from disk, with every request and script error it makes kept."""
    p = browser.new_page(viewport={"width": 1400, "height": 1000})
    p.requests, p.errors = [], []
    p.on("request", lambda r: p.requests.append(r.url))
    p.on("pageerror", lambda e: p.errors.append(str(e)))
    p.on("console", lambda m: p.errors.append(m.text) if m.type == "error" else None)
    p.goto(shaper[0].as_uri())
    yield p
    assert p.errors == []
    p.close()


def test_the_page_is_one_file_that_asks_for_nothing(page, shaper):
    html = shaper[0].read_text(encoding="utf-8")
    assert not re.search(r"""(src|href)\s*=\s*["']?(https?:|//)""", html)
    assert "Content-Security-Policy" in html and "default-src 'none'" in html
    page.evaluate("tarsimView.setFrame(40)")
    page.click("#next")
    assert page.requests == [shaper[0].as_uri()]          # the page itself, and no more


def _md_steps(md: str, position: str) -> dict[str, list[tuple[int, str]]]:
    """steps.md's numbered steps of one position, by part heading: [(number, words)]."""
    block = md.split(f"# {position}", 1)[1].split("\n# ", 1)[0]
    parts: dict[str, list[tuple[int, str]]] = {}
    heading = None
    for line in block.splitlines():
        if line.startswith("## "):
            heading = line[3:]
            parts[heading] = []
        elif heading and (m := re.match(r"(\d+)\. (.*)", line)):
            parts[heading].append((int(m.group(1)), m.group(2)))
    return parts


_SHOWN = """() => ({
    current: [...document.querySelectorAll('#steps li.current')].map(li => li.innerText),
    done: document.querySelectorAll('#steps li.done').length,
    marks: document.querySelectorAll('#sheet .cur').length})"""
"""What the page shows of the steps after a click, read in one trip to the browser: the
current step's text (as the reader sees it), how many are done, and how many of the
figure's primitives it marks as the current step's."""


def _tagged(figure: dict, lang: str, part: int, n: int) -> bool:
    """Whether the figure's drawing tags a primitive with step ``n`` of ``part``."""
    for item in figure["drawn"][lang]["items"]:
        tags = item[3].get("s", []) if len(item) > 3 else []
        if any(tags[i] == part and tags[i + 1] == n for i in range(0, len(tags), 2)):
            return True
    return False


@pytest.mark.parametrize("lang", ["en", "fa"])
def test_every_step_is_steps_md_s_and_is_highlighted_in_turn(page, shaper, lang):
    """Step through each figure from before its first step to its last, by the next button
    and then the arrow key: the list's current step has steps.md's number and words, the
    earlier ones are dimmed, and the figure marks what the step draws as current."""
    md = _md_steps(shaper[1][lang], "At θ2 = 90°" if lang == "en" else "در θ2 = 90°")
    if lang == "fa":
        page.click("#lang")
    figures = page.evaluate("tarsimView.data.figures")
    assert page.locator("#figure option").count() == len(figures) >= 3
    clicked = 0
    for i, figure in enumerate(figures):
        page.select_option("#figure", str(i))
        stem = figure["stem"]
        want = [st for heading, sts in md.items()
                if f"`{stem}-theta2-90.svg`" in heading for st in sts]
        parts = figure["parts"]
        mine = [(p, st["n"]) for p, part in enumerate(parts) for st in part["steps"]]
        assert len(mine) == len(want) > 0, stem
        page.click("#first")
        assert page.evaluate(_SHOWN)["marks"] == 0
        for k, ((n, said), (p, n_page)) in enumerate(zip(want, mine)):
            if k == 0:
                page.click("#next")
            else:                               # the arrow key steps as the button does
                page.keyboard.press("ArrowRight")
            shown = page.evaluate(_SHOWN)
            assert len(shown["current"]) == 1
            assert shown["current"][0].split(maxsplit=1) == [f"{n}.", said]
            assert n_page == n and shown["done"] == k
            assert (shown["marks"] > 0) == _tagged(figure, lang, p, n), (stem, n)
            clicked += 1
    assert clicked > 50


@pytest.mark.parametrize("lang", ["en", "fa"])
def test_each_figure_on_the_page_is_the_svg_solve_writes(page, lang):
    """At its last step, every figure on the page is the SVG `tarsim solve` writes for it,
    element for element and character for character (each path's d, circle, text and
    tspan), in English and in Persian, and all of it is shown."""
    from tarsim import solve
    from tarsim.constructions.narration import speaking

    with speaking(lang):                        # as `tarsim solve --lang` names it
        svgs = {f.stem: f.svg for f in solve(load("crank-shaper").named_in(lang)).pages}
    if lang == "fa":
        page.click("#lang")
    figures = page.evaluate("tarsimView.data.figures")
    for i, figure in enumerate(figures):
        page.select_option("#figure", str(i))              # opened at its step 1
        page.evaluate("tarsimView.setStep(1e9)")            # to its last
        drawn = as_tuples(page.evaluate(PAGE_LEAVES))
        assert drawn == svg_leaves(svgs[f"{figure['stem']}-theta2-90"]), figure["stem"]
        hidden = page.evaluate("[...document.querySelectorAll('#sheet [data-i]')]"
                               ".filter(e => getComputedStyle(e).display === 'none').length")
        assert hidden == 0


def _block(page) -> list[list[tuple[float, float]]]:
    """The page's block symbols, each as its paper points."""
    ds = page.evaluate("[...document.querySelectorAll('#sheet path.s-block')]"
                       ".map(e => e.getAttribute('d'))")
    return [[tuple(map(float, xy.split(","))) for xy in re.findall(r"-?[\d.]+,-?[\d.]+", d)]
            for d in ds]


def test_a_joint_the_diagram_draws_is_on_the_page_with_no_script_of_its_own(page):
    """The slider blocks are drawn by the Python diagram alone: on the page, at the
    exercise's position, they are the SVG's, path for path; turned to θ2 = 40° they are the
    blocks tarsim draws at 40°, beside their pins, to the written micrometre. The script
    names no part of a mechanism."""
    from tarsim.graphics.figure_data import number

    page.select_option("#figure", "0")                  # the centres
    svg = _solved_at(90.0)["centres"]
    blocks = [[(float(x), float(y)) for x, y in re.findall(r"(-?[\d.]+),(-?[\d.]+)", d)]
              for g in ET.fromstring(svg).iter(f"{SVG}g") if g.get("class") == "block"
              for d in (p.get("d") for p in g)]
    assert _block(page) == blocks and len(blocks) == 2
    page.evaluate("tarsimView.setFrame(20)")             # θ2 = 90° − 20 × 2.5°
    data = page.evaluate("({f: tarsimView.data.frames[20], v: tarsimView.data.figures[0]"
                         ".drawn.en.views.space, names: tarsimView.data.names.space})")
    s, ox, oy = data["v"]
    at = data["f"]["at"]["space"]
    pins = {n: (ox + s * at[2 * k], oy - s * at[2 * k + 1]) for k, n in enumerate(data["names"])
            if at[2 * k] is not None}
    drawn = _figure_at(40.0, "centres")
    view = drawn.views["space"]
    python = [[tuple(number(v) for v in p) for p in it.points] for it in drawn.items
              if getattr(it, "style", "") == "block"]
    theirs = {n: view(drawn_xy) for n, drawn_xy in _joints_at(40.0).items()}
    for mine, want in zip(_block(page), python):
        pin = min(pins, key=lambda n: math.dist(pins[n], mine[0]))
        for p, q in zip(mine, want):
            # a written coordinate is to 0.5 µm, the frame's point to 0.1 µm of the world
            assert math.dist((p[0] - pins[pin][0], p[1] - pins[pin][1]),
                             (q[0] - theirs[pin][0], q[1] - theirs[pin][1])) <= 2e-3
    script = "".join((Path(__file__).parents[1] / "graphics" / "page" / name).read_text()
                     for name in ("view.js", "view_numbers.js"))
    code = re.sub(r"/\*.*?\*/|//[^\n]*", "", script, flags=re.S).lower()
    code = code.replace('scrollintoview({block: "nearest"})', "")     # the DOM's word
    for word in ("block", "pin", "centre", "kennedy", "polygon", "slide", "guide", "ground",
                 "joint", "link", "tip", "pole", "vector", "crank", "lever", "hatch"):
        assert not re.search(rf"\b{word}", code), word


def _solved_at(angle: float) -> dict[str, str]:
    """The crank-shaper's figures as `tarsim solve` writes them at θ2 = ``angle``, by stem
    (its first position's, when ``angle`` is its own)."""
    from tarsim import solve

    return {f.stem.removesuffix("-theta2-90"): f.svg for f in solve(load("crank-shaper")).pages
            if f.stem.endswith("-theta2-90")} if angle == 90.0 else \
        {f.stem: f.svg for f in solve(_at(angle)).pages}


def _at(angle: float):
    ex = load("crank-shaper")
    return replace(ex, mechanism=ex.mechanism.with_drive(
        replace(ex.mechanism.drive, angle=math.radians(angle))), positions=())


def _figure_at(angle: float, stem: str):
    from tarsim import solve

    return next(f.figure for f in solve(_at(angle)).pages if f.stem == stem)


def _joints_at(angle: float) -> dict[str, tuple[float, float]]:
    from tarsim.constructions.reference import solver

    return solver.solve(_at(angle).mechanism).points


def _results(angle: float) -> dict:
    """results.json of the crank-shaper solved at ``angle``, as `tarsim solve --angle`
    writes it (the same solve and the same writer, without drawing its figures)."""
    ex = load("crank-shaper")
    ex = replace(ex, mechanism=ex.mechanism.with_drive(
        replace(ex.mechanism.drive, angle=math.radians(angle))), positions=())
    return json.loads(results_json(solve_positions(ex), ex))


_READ = """() => {
  const D = tarsimView.data, k = tarsimView.state.frame;
  const shown = d => (k !== 0 && d.turning) || d;
  return {names: D.names, frame: k, scales: D.scales,
          figures: D.figures.map(f => ({stem: f.stem, items: shown(f.drawn.en).items,
                                        views: shown(f.drawn.en).views,
                                        first: shown(f.drawn.en).named || D.frames[0].at,
                                        angle: shown(f.drawn.en).angle ?? D.input.angle,
                                        fit: f.fit ? f.fit.at : null})),
          dom: [...document.querySelectorAll('#sheet [data-i]')].map(e => ({
            cx: e.getAttribute('cx'), cy: e.getAttribute('cy'), d: e.getAttribute('d'),
            transform: e.getAttribute('transform'),
            shown: getComputedStyle(e).display !== 'none'}))};
}"""
"""What a test reads back of the page: the data the figure shown was drawn from (while the
input turns, each figure as drawn farther on, its named points there and the input's
angle, and each frame's polygon scales), and what the browser drew of it, element by
element."""


def _standing(figure: dict, first: dict, view: str, style: str | None, kind: str):
    """Each primitive of ``kind`` (and ``style``) that stands on a named point of ``view``
    with no offset (its first point drawn there at the exercise's position, turning with
    nothing or anything): (its index, the named point's index)."""
    s, ox, oy = figure["views"][view]
    at = first[view]
    for i, item in enumerate(figure["items"]):
        more = item[3] if len(item) > 3 else {}
        if item[0] != kind or (style and item[1] != style) or more.get("m", [None])[0] != view:
            continue
        a = more["m"][1][0]
        here = (ox + s * at[2 * a], oy - s * at[2 * a + 1]) if at[2 * a] is not None else None
        drawn = more.get("at") or item[2][:2]
        if here and math.dist(here, drawn) <= 1e-3:
            yield i, a


@pytest.mark.parametrize("angle", [45.0, 137.5, 250.0])
def test_dragging_the_crank_draws_what_solve_finds_at_that_angle(page, angle):
    """Drag the crank pin round to θ2 on the page, then read back what the browser drew,
    turned back into world units by the figure's view: each pin stands where the analytic
    solver puts its joint; each instant centre's name has moved with its centre from where
    results.json puts it at the angle of the drawing the page turns to where it puts it at
    θ2; and, on the worked page, the velocity polygon's arrow to b runs from the pole's dot
    to results.json's V_B at the frame's own scale. All to what the page writes: a
    coordinate to half a micrometre of paper."""
    from tarsim.constructions.reference import solver

    page.select_option("#figure", "0")                          # the centres
    drag = page.evaluate("tarsimView.data.drag")
    (ax, ay), (ox, oy) = (page.evaluate(f"tarsimView.screen('space', {drag[k]})")
                          for k in ("handle", "about"))
    r = math.hypot(ax - ox, ay - oy)
    page.mouse.move(ax, ay)
    page.mouse.down()
    for t in (0.3, 0.7, 1.0):                            # a drag, not a jump
        a = math.radians(90.0 + t * (angle - 90.0))
        page.mouse.move(ox + r * math.cos(a), oy - r * math.sin(a))
    page.mouse.up()
    read = page.evaluate(_READ)
    shown = page.evaluate(f"tarsimView.data.frames[{read['frame']}].angle")
    assert math.degrees(shown) % 360 == pytest.approx(angle, abs=1e-9)
    names, figure = read["names"]["space"], read["figures"][0]
    s, vx, vy = figure["views"]["space"]
    near = 1e-3 / s                   # two written coordinates, each to half a micrometre

    def world(x, y):
        return ((float(x) - vx) / s, -(float(y) - vy) / s)

    joints = solver.solve(_at(angle).mechanism).points
    pins = [(i, names[a]) for i, a in _standing(figure, figure["first"], "space", "pin", "c")]
    assert len(pins) >= 3
    for i, name in pins:
        assert read["dom"][i]["shown"]
        assert math.dist(world(read["dom"][i]["cx"], read["dom"][i]["cy"]), joints[name]) <= near
    now = _reference(angle)
    then = _reference(math.degrees(figure["angle"]) % 360)   # the drawing the page turns
    compared, centres = 0, 0
    for i, item in enumerate(figure["items"]):
        more = item[3] if len(item) > 3 else {}
        if item[0] != "t" or "m" not in more or len(more["m"][1]) != 3 \
                or more["m"][1][1] != -1:        # a name kept beside a point, not turned
            continue
        name = names[more["m"][1][0]]
        if name not in then or name not in now or not read["dom"][i]["shown"]:
            continue
        dx, dy = map(float, re.findall(r"-?[\d.]+", read["dom"][i]["transform"]))
        moved = (then[name][0] + dx / s, then[name][1] - dy / s)
        assert math.dist(moved, now[name]) <= near, name
        compared += 1
        centres += name.startswith("I")
    assert compared >= 4 and centres >= 1
    worked = next(k for k, f in enumerate(read["figures"]) if f["stem"] == "worked")
    page.select_option("#figure", str(worked))
    read = page.evaluate(_READ)
    figure, tips = read["figures"][worked], read["names"]["velocity"]
    sv = figure["fit"]["velocity"][6 * read["frame"]]      # the frame's own scale, mm a m
    head = next(i for i, a in _standing(figure, figure["first"], "velocity", "arrowhead", "z")
                if tips[a] == "B")
    first = figure["first"]["velocity"]
    o = tips.index("pole")                      # a pivot's tip is the pole: its dot's too
    pole = next(i for i, a in _standing(figure, figure["first"], "velocity", "dot", "c")
                if first[2 * a:2 * a + 2] == first[2 * o:2 * o + 2])
    tip = tuple(map(float, read["dom"][head]["d"][1:].split(" ")[0].split(",")))
    dot = (float(read["dom"][pole]["cx"]), float(read["dom"][pole]["cy"]))
    scale = read["scales"]["v"]                                  # drawing m per m/s
    v = ((tip[0] - dot[0]) / sv / scale, -(tip[1] - dot[1]) / sv / scale)
    want = _results(angle)["positions"][0]["quantities"]["V_B"]["vector"]
    assert math.dist(v, want) <= 1e-3 / sv / scale


def _reference(angle: float) -> dict[str, tuple[float, float]]:
    """Where the crank-shaper's joints (by the analytic solver) and its finite instant
    centres (by results.json) stand at θ2 = ``angle``."""
    from tarsim.constructions.reference import solver

    out = dict(solver.solve(_at(angle).mechanism).points)
    out.update({name: tuple(q["point"]) for name, q in
                _results(angle)["positions"][0]["quantities"].items() if "point" in q})
    return out


def test_a_position_the_mechanism_cannot_reach_is_shown_as_such(browser, tmp_path):
    """A four-bar whose crank cannot turn fully: the frames past its reach say why and hold
    no drawing, the slider marks where the reach ends, and the page says so there."""
    text = four_bar_toml(ground=300, crank=250, coupler=150, rocker=200, angle=30)
    text = text.replace("angle = 30", "angle = 30\nomega = 10") + '\n[ask]\nfind = ["omega4"]\n'
    data = view_data(parse_exercise(text, "rocker.toml", "rocker"), step_deg=2.0)
    lost = [f for f in data["frames"] if "at" not in f]
    assert lost and all(f["why"] for f in lost)
    assert sum(m["kind"] == "dead" for m in data["marks"]) >= 2
    path = tmp_path / "rocker.html"
    path.write_text(view_html(data), encoding="utf-8")
    p = browser.new_page()
    p.goto(path.as_uri())
    shown = ("[...document.querySelectorAll('#sheet [data-i]')]"
             ".filter(e => getComputedStyle(e).display !== 'none').length")
    assert p.evaluate(shown) > 0
    p.evaluate(f"tarsimView.setFrame({data['frames'].index(lost[0])})")
    assert "cannot be assembled" in p.inner_text("#readout")
    assert p.evaluate(shown) == 0
    assert p.locator("#marks span.dead").count() >= 2
    p.close()


def test_a_notebook_shows_the_page_in_a_frame_of_its_own():
    """tarsim.solve(…) in a notebook offers the page, in an iframe of its own so that its
    script and styles stay apart from the notebook's."""
    import tarsim

    shown = tarsim.solve(load("four-bar"))._repr_html_()
    assert shown.startswith("<iframe srcdoc=") and "&lt;script" in shown
    assert "tarsimView" in shown and shown.count("&quot;angle&quot;") >= 720
    assert ViewPage(view_html(view_data(load("four-bar"), step_deg=5.0)))._repr_html_() != shown


def test_layers_zoom_and_the_downloaded_frame(page):
    """Each layer hides what it names; the wheel zooms about the pointer; the download is
    the frame shown, as an SVG file of what the page shows of the figure."""
    page.evaluate("tarsimView.setFrame(20)")      # θ2 = 90° − 20 × 2.5°
    shown = ("s => [...document.querySelectorAll(s)]"
             ".filter(e => getComputedStyle(e).display !== 'none').length")
    for layer in ("kennedy", "labels"):
        page.evaluate("tarsimView.setFrame(0)")
        drawn = f"#sheet .L-{layer}"
        assert page.evaluate(shown, drawn) > 0
        page.uncheck(f"[data-layer='{layer}']")
        assert page.evaluate(shown, drawn) == 0
        page.check(f"[data-layer='{layer}']")
    page.evaluate("tarsimView.setFrame(20)")
    box = page.locator("#sheet svg").bounding_box()
    width = float(page.get_attribute("#sheet svg", "viewBox").split()[2])
    page.mouse.move(box["x"] + box["width"] / 2, box["y"] + box["height"] / 2)
    page.mouse.wheel(0, -300)
    assert float(page.get_attribute("#sheet svg", "viewBox").split()[2]) < width / 1.5
    with page.expect_download() as got:
        page.click("#download")
    svg = Path(got.value.path()).read_text(encoding="utf-8")
    assert got.value.suggested_filename == "centres-theta2-40.0.svg"
    drawn = [el for el in ET.fromstring(svg) if el.tag != f"{SVG}rect"]
    paper = page.evaluate("tarsimView.state.items.filter(it => it.paper"
                          " && getComputedStyle(it.el).display === 'none').length")
    assert len(drawn) == page.evaluate(shown, "#sheet [data-i]") + paper > 20 + paper
    blocks = page.evaluate("[...document.querySelectorAll('#sheet path.s-block')]"
                           ".map(e => e.getAttribute('d'))")
    assert len(blocks) == 2 and set(blocks) <= {el.get("d") for el in drawn}


@pytest.mark.parametrize("require, outcome", [(None, pytest.skip.Exception),
                                              ("0", pytest.skip.Exception),
                                              ("1", pytest.fail.Exception)])
def test_a_missing_browser_skips_unless_it_is_required(monkeypatch, require, outcome):
    """With no chromium on the PATH a browser test skips, saying what to install, so the
    README's test command passes on a machine without one; under TARSIM_REQUIRE_BROWSER
    (set by .ci/run) it fails with that line instead."""
    from tests import browser

    monkeypatch.setattr(browser.shutil, "which", lambda name: None)
    if require is None:
        monkeypatch.delenv(browser.REQUIRE, raising=False)
    else:
        monkeypatch.setenv(browser.REQUIRE, require)
    with pytest.raises(outcome) as info, browser.chromium():
        raise AssertionError("a browser was opened")
    line = str(info.value)
    assert "\n" not in line and line.startswith(browser.NEEDS)


def test_the_command_counts_the_frames_a_crank_can_reach(tmp_path):
    """A triple rocker (ground 200, crank 100, coupler 150, rocker 120 mm: 100 + 200 >
    150 + 120, no Grashof crank) reaches only where A stands within coupler + rocker = 270
    mm of O4: 50000 − 40000 cos θ ≤ 270², so |θ| ≤ acos(−0.5725) = 124.92°. Of 72 frames
    5° apart from θ = 0, those at 0–120° (25) and 240–355° (24) are drawn and checked, the
    other 23 out of reach."""
    reach = math.degrees(math.acos((200 ** 2 + 100 ** 2 - 270 ** 2) / (2 * 200 * 100)))
    drawn = sum(1 for k in range(72) if min(5 * k, 360 - 5 * k) <= reach)
    assert (drawn, round(reach, 2)) == (49, 124.92)
    text = four_bar_toml(ground=200, crank=100, coupler=150, rocker=120, angle=0)
    text = text.replace("angle = 0", "angle = 0\nomega = 10") + '\n[ask]\nfind = ["omega4"]\n'
    (tmp_path / "rocker.toml").write_text(text, encoding="utf-8")
    result = CliRunner().invoke(cli, ["view", str(tmp_path / "rocker.toml"), "--step", "5",
                                      "-o", str(tmp_path / "rocker.html")])
    assert result.exit_code == 0, result.output
    assert (f"72 frames: {drawn} checked, {72 - drawn} out of reach or beyond the "
            "construction, 0 failing their check)") in result.output


@pytest.fixture(scope="module")
def turned():
    """``turned(name)``: the page's data for a bundled exercise, a frame every 10°, and
    the exercise solved at its own position, once per module."""
    cache: dict[str, tuple[dict, object]] = {}

    def get(name: str):
        if name not in cache:
            ex = load(name)
            home = solve_positions(replace(ex, positions=ex.positions[:1]),
                                   room=room(paper(ex.paper)))[0]
            cache[name] = view_data(ex, step_deg=10.0), home
        return cache[name]
    return get


_ASKED = {"crank-shaper": ("rr:B:rot:k", "rr:B:tip:k", "rr:B:tip:t", "rr:B:tip"),
          "four-bar": ("rr:B:rot:d", "rr:B:tip:d", "pl:B:turn:t", "pl:B:cut", "cm:A:foot@A-B",
                       "cm:B:along@A")}
"""Points each exercise's asked constructions stand on: the crank-shaper's V_B by radius
rotation (A swung onto the line of centres, V_A there, V_I25, V_B at B) and the
four-bar's by radius rotation (B swung onto the line of centres and its velocity there),
parallel lines (V_A turned onto its radius, the parallel's cut) and components (the foot
of V_A's component along AB, laid off again at B)."""


@pytest.mark.parametrize("name", sorted(_ASKED))
def test_every_frame_sends_the_points_the_asked_construction_stands_on(turned, name):
    """Each frame the mechanism can be assembled at sends the points the asked
    constructions stand on, and every point a primitive of the drawing the page turns
    stands on (but an instant centre, which may run to infinity): none is left out, so no
    primitive is left at the first position's place or hidden where tarsim constructs
    it."""
    data, _ = turned(name)
    names = data["names"]
    assert set(_ASKED[name]) <= set(names["space"])
    frames = [f for f in data["frames"] if "at" in f]
    assert len(frames) == len(data["frames"]) == 36
    stands = set()
    for figure in data["figures"]:
        for drawing in figure["drawn"].values():
            for item in drawing.get("turning", drawing)["items"]:
                more = item[3] if len(item) > 3 else {}
                for view, triples in (more[k] for k in ("m", "a") if k in more):
                    stands |= {(view, k) for k in triples
                               if k >= 0 and not re.fullmatch(r"I\d+", names[view][k])}
    assert {("space", names["space"].index(ref)) for ref in _ASKED[name]} <= stands
    for f in frames:
        missing = [names[view][k] for view, k in stands if f["at"][view][2 * k] is None]
        assert missing == [], (math.degrees(f["angle"]), missing)


@pytest.mark.parametrize("name", sorted(_ASKED))
def test_a_frame_s_construction_is_tarsim_s_own_at_that_angle(turned, name):
    """The points of the asked constructions a frame sends are where tarsim's solve at
    that frame's angle puts them (its record, at the page's scales): both are the same
    exact construction, so they agree to the page's rounding, 1e-7 m in x and in y."""
    data, home = turned(name)
    where = room(paper(load(name).paper))
    for f in data["frames"][5::11]:
        there = solved_at(home, f["angle"], where)
        at = f["at"]["space"]
        for ref in _ASKED[name]:
            k = data["names"]["space"].index(ref)
            assert math.dist(at[2 * k:2 * k + 2], there.assembly.output(ref).xy) <= 1.5e-7, ref
