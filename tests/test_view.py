"""The interactive page (``tarsim view``), in a real browser: Debian's chromium driven by
playwright, the page opened from disk.

Its steps are held to steps.md (the same numbers, the same words, in English and in
Persian), its frames to tarsim's own results.json at those angles, and the page to
itself: nothing leaves it, nothing fails in its script.
"""

from __future__ import annotations

import json
import math
import re
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
from tarsim.graphics.view_page import ViewPage, view_html

from tests.common import four_bar_toml

# One worker runs the whole file (--dist loadfile), so chromium is opened and the pages
# made once.
pytestmark = pytest.mark.slow


@pytest.fixture(scope="module")
def shaper(tmp_path_factory, solved):
    """The crank-shaper's page written by the command, a frame every 2.5° (every angle the
    tests turn to; the default 0.5° is the notebook test's), and its steps.md as `tarsim
    solve` writes it, in both languages."""
    out = tmp_path_factory.mktemp("view")
    page = out / "shaper.html"
    result = CliRunner().invoke(cli, ["view", "crank-shaper", "--step", "2.5", "-o", str(page)])
    assert result.exit_code == 0, result.output
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
    marks: document.querySelectorAll('svg .step.current').length})"""
"""What the page shows of the steps after a click, read in one trip to the browser: the
current step's text (as the reader sees it), how many are done, and how many marks the
figure draws as current."""


@pytest.mark.parametrize("lang", ["en", "fa"])
def test_every_step_is_steps_md_s_and_is_highlighted_in_turn(page, shaper, lang):
    """Step through each figure from before its first step to its last, by the next button
    and then the arrow key: the list's current
    step has steps.md's number and words, the earlier ones are dimmed, and the figure
    marks what the step draws as current."""
    md = _md_steps(shaper[1][lang], "At θ2 = 90°" if lang == "en" else "در θ2 = 90°")
    if lang == "fa":
        page.click("#lang")
    figures = page.evaluate("tarsimView.data.figures")
    clicked = 0
    for i, figure in enumerate(figures):
        if not any(part["steps"] for part in figure["parts"]):
            assert page.locator(f"#figure option[value='{i}']").count() == 0   # not offered
            continue
        page.select_option("#figure", str(i))
        stem = figure["stem"]
        want = [st for heading, sts in md.items()
                if f"`{stem}-theta2-90.svg`" in heading for st in sts]
        parts = figure["parts"]
        mine = [(p, st["n"]) for p, part in enumerate(parts) for st in part["steps"]
                if st["said"]]
        assert len(mine) == len(want), stem
        page.click("#first")
        for k, ((n, said), (p, n_page)) in enumerate(zip(want, mine)):
            if k == 0:
                page.click("#next")
            else:                               # the arrow key steps as the button does
                page.keyboard.press("ArrowRight")
            shown = page.evaluate(_SHOWN)
            assert len(shown["current"]) == 1
            assert shown["current"][0].split(maxsplit=1) == [f"{n}.", said]
            assert n_page == n and shown["done"] == k
            draws = any(st["draw"] for st in parts[p]["steps"] if st["n"] == n)
            assert (shown["marks"] > 0) == draws, (stem, n)
            clicked += 1
    assert clicked > 50


def _results(angle: float) -> dict:
    """results.json of the crank-shaper solved at ``angle``, as `tarsim solve --angle`
    writes it (the same solve and the same writer, without drawing its figures)."""
    ex = load("crank-shaper")
    ex = replace(ex, mechanism=ex.mechanism.with_drive(
        replace(ex.mechanism.drive, angle=math.radians(angle))), positions=())
    return json.loads(results_json(solve_positions(ex), ex))


@pytest.mark.parametrize("angle", [45.0, 137.5, 250.0])
def test_dragging_the_crank_draws_what_solve_finds_at_that_angle(page, angle):
    """Drag the crank pin to θ2 on the page, then read back what it drew: each instant
    centre and the velocity polygon's tip b, turned back into world units from the
    drawing, are tarsim's results.json at that angle to the drawing's precision (half a
    pixel, the marks being placed to a hundredth of one)."""
    pin, pivot = (page.locator(f"#space circle[data-point='{p}']").bounding_box()
                  for p in ("A", "O2"))
    centre = lambda b: (b["x"] + b["width"] / 2, b["y"] + b["height"] / 2)  # noqa: E731
    (ax, ay), (ox, oy) = centre(pin), centre(pivot)
    r = math.hypot(ax - ox, ay - oy)
    page.mouse.move(ax, ay)
    page.mouse.down()
    for t in (0.3, 0.7, 1.0):                            # a drag, not a jump
        a = math.radians(90.0 + t * (angle - 90.0))
        page.mouse.move(ox + r * math.cos(a), oy - r * math.sin(a))
    page.mouse.up()
    shown = page.evaluate("tarsimView.data.frames[tarsimView.state.frame].angle")
    assert math.degrees(shown) % 360 == pytest.approx(angle, abs=1e-9)
    want = _results(angle)["positions"][0]["quantities"]
    k = page.evaluate("tarsimView.state.views.turn.space.k")      # px per metre
    compared = 0
    for name, q in want.items():
        if not name.startswith("I") or "point" not in q:      # at infinity, or undefined
            continue
        dot = page.locator(f"#space circle[data-centre='{name}']")
        if not dot.count():                                 # off the panel
            continue
        x, y = centre(dot.bounding_box())
        box = page.locator("#space svg").bounding_box()
        wx, wy = page.evaluate(f"tarsimView.world('space', {x - box['x']}, {y - box['y']})")
        assert math.dist((wx, wy), q["point"]) <= 0.5 / k, name
        compared += 1
    assert compared >= 6
    tip = page.locator("#velocity circle.tip[data-tip='B']")
    pole = page.locator("#velocity circle.pole")
    (tx, ty), (px_, py_) = centre(tip.bounding_box()), centre(pole.bounding_box())
    kv = page.evaluate("tarsimView.state.views.turn.velocity.k")
    scale = page.evaluate("tarsimView.data.scales.v")          # drawing m per m/s
    v = ((tx - px_) / kv / scale, -(ty - py_) / kv / scale)
    assert math.dist(v, want["V_B"]["vector"]) <= 0.5 / kv / scale


def test_a_position_the_mechanism_cannot_reach_is_shown_as_such(browser, tmp_path):
    """A four-bar whose crank cannot turn fully: the frames past its reach say why and hold
    no drawing, the slider marks where the reach ends, and the page says so there."""
    text = four_bar_toml(ground=300, crank=250, coupler=150, rocker=200, angle=30)
    text = text.replace("angle = 30", "angle = 30\nomega = 10") + '\n[ask]\nfind = ["omega4"]\n'
    data = view_data(parse_exercise(text, "rocker.toml", "rocker"), step_deg=2.0)
    lost = [f for f in data["frames"] if "p" not in f]
    assert lost and all(f["why"] for f in lost)
    assert sum(m["kind"] == "dead" for m in data["marks"]) >= 2
    path = tmp_path / "rocker.html"
    path.write_text(view_html(data), encoding="utf-8")
    p = browser.new_page()
    p.goto(path.as_uri())
    p.evaluate(f"tarsimView.setFrame({data['frames'].index(lost[0])})")
    assert "cannot be assembled" in p.inner_text("#readout")
    assert p.locator("#space circle.joint").count() == 0
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
    the frame shown, as an SVG file with its joints and polygons."""
    page.evaluate("tarsimView.setFrame(20)")      # θ2 = 90° − 20 × 2.5°
    for layer, drawn in (("kennedy", "#space .kennedy"), ("labels", "#space text.name")):
        assert page.locator(drawn).count() > 0
        page.uncheck(f"[data-layer='{layer}']")
        assert page.locator(drawn).count() == 0
        page.check(f"[data-layer='{layer}']")
    k = page.evaluate("tarsimView.state.views.turn.space.k")
    box = page.locator("#space svg").bounding_box()
    page.mouse.move(box["x"] + box["width"] / 2, box["y"] + box["height"] / 2)
    page.mouse.wheel(0, -300)
    assert page.evaluate("tarsimView.state.views.turn.space.k") > 1.5 * k
    with page.expect_download() as got:
        page.click("#download")
    svg = Path(got.value.path()).read_text(encoding="utf-8")
    assert got.value.suggested_filename == "frame-theta2-40.0.svg"
    assert svg.startswith("<svg") and svg.count("data-point=") == 4 and "data-tip=" in svg


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
