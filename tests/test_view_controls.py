"""The interactive page's controls and readouts (``tarsim view``), in a real browser: it
opens on step 1, reads out every link's ω and α and the asked rates in the figures'
units, plots a signed rate against a ticked angle axis, keeps every label inside the
view, resets its view, downloads a turned frame with its caption, and shows inline in a
notebook.
"""

from __future__ import annotations

import json
import math
import re
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
from click.testing import CliRunner

from tarsim.exercises.cli import cli

from tests.common import written_view
from tests.figure_leaves import SVG

pytestmark = pytest.mark.slow


@pytest.fixture(scope="module")
def made(tmp_path_factory):
    """The crank-shaper's page, a frame every 2.5°, and its results.json as `tarsim solve`
    writes it."""
    out = tmp_path_factory.mktemp("controls")
    page = written_view(out / "shaper.html", "2.5")
    result = CliRunner().invoke(cli, ["solve", "crank-shaper", "--no-pdf", "-o", str(out / "s")])
    assert result.exit_code == 0, result.output
    return page, json.loads((out / "s" / "results.json").read_text(encoding="utf-8"))


@pytest.fixture()
def page(browser, made):
    p = browser.new_page(viewport={"width": 1400, "height": 1000})
    p.errors = []
    p.on("pageerror", lambda e: p.errors.append(str(e)))
    p.goto(made[0].as_uri())
    yield p
    assert p.errors == []
    p.close()


def test_the_page_opens_on_step_1_and_a_new_figure_starts_there(page):
    """The first figure's first step is the current one, nothing after it shown; choosing
    another figure starts it at its step 1 too."""
    for figure in ("0", "2", "1"):
        if figure != "0":
            page.select_option("#figure", figure)
        current = page.locator("#steps li.current").inner_text()
        assert current.split(".")[0] == "1"
        assert page.locator("#stepper").input_value() == "0"
        assert page.locator("#steps li.done").count() == 0


def _value(text: str) -> float:
    """A number as the readout sets it (a true minus)."""
    return float(text.replace("−", "-"))


def test_the_readout_gives_every_link_s_omega_and_alpha_in_the_figures_units(page, made):
    """At the exercise's position (frame 1) the readout says ω and α of links 2 to 5 and
    V_B and A_B, in rad/s, rad/s², mm/s and mm/s²: each the number results.json gives (SI,
    ×1000 for a length a second) to the six significant figures it is printed to, and a
    rate's sense as its sign says it."""
    read = dict(page.evaluate("[...document.querySelectorAll('#readout [data-q]')]"
                              ".map(e => [e.dataset.q, e.innerText])"))
    assert {f"{w}{n}" for w in ("omega", "alpha") for n in (2, 3, 4, 5)} | {"V_B", "A_B"} \
        <= set(read)
    quantities = made[1]["positions"][0]["quantities"]
    inp = made[1]["positions"][0]["input"]
    want = {"omega4": quantities["omega4"]["value"], "alpha4": quantities["alpha4"]["value"],
            "omega2": inp["omega"], "alpha2": inp["alpha"]}
    for name, value in want.items():
        text = read[name]
        unit = "rad/s²" if name.startswith("alpha") else "rad/s"
        m = re.fullmatch(rf"[ωα]\d = (\S+) {unit}( \((cw|ccw)\))?", text)
        assert m, text
        # printed to six significant figures: within half a unit of the sixth
        assert _value(m.group(1)) == pytest.approx(value, abs=5e-6 * max(abs(value), 1e-12))
        assert (m.group(3) or "") == ("ccw" if value > 0 else "cw" if value < 0 else "")
    v = quantities["V_B"]["vector"]
    m = re.fullmatch(r"V_B = (\S+) mm/s at (\S+)°", read["V_B"])
    assert m, read["V_B"]
    assert _value(m.group(1)) == pytest.approx(1000 * math.hypot(*v), rel=5e-6)
    assert _value(m.group(2)) == pytest.approx(math.degrees(math.atan2(v[1], v[0])), abs=0.05)
    assert read["A_B"] == "A_B = 0 mm/s²"                    # results.json's 0 at 90°
    assert read["omega5"] == "ω5 = 0 rad/s"                  # the ram translates


def test_the_readout_turns_with_the_crank_and_speaks_persian(page, made):
    """Turned to results.json's second position's angle's nearest frame the readout moves
    with it; in Persian the same numbers are set in Persian digits with Persian senses."""
    page.evaluate("tarsimView.setFrame(10)")         # θ2 = 90° − 25° = 65°
    read = dict(page.evaluate("[...document.querySelectorAll('#readout [data-q]')]"
                              ".map(e => [e.dataset.q, e.innerText])"))
    assert read["omega4"] != "ω4 = −0.264706 rad/s (cw)"
    page.click("#lang")
    fa = dict(page.evaluate("[...document.querySelectorAll('#readout [data-q]')]"
                            ".map(e => [e.dataset.q, e.innerText])"))
    latin = str.maketrans("۰۱۲۳۴۵۶۷۸۹٫", "0123456789.")
    assert fa["omega4"].translate(latin).replace("(ساعتگرد)", "(cw)") \
        .replace("(پادساعتگرد)", "(ccw)") == read["omega4"]
    assert "در" in fa["V_B"]


def test_the_plot_has_a_ticked_angle_axis_and_a_signed_rate_with_its_unit(page):
    """The plot says what it plots and in which unit (V_B in mm/s, signed along the ram's
    guide: it runs below 0 on the return stroke), and ticks θ2 every 45°: eight ticks over
    the turn, each at the x where the frames' angles pass it."""
    assert page.text_content("#plot #value-axis") == "V_B (mm/s)"
    assert page.text_content("#plot #angle-axis") == "θ2 (°)"
    values = page.evaluate("tarsimView.data.plot.values")
    assert min(values) < -400 and max(values) == pytest.approx(232.941176, abs=1e-6)
    ticks = page.evaluate("[...document.querySelectorAll('#plot line.tick')]"
                          ".map(e => [+e.getAttribute('x1'), e.nextSibling.textContent])")
    labels = [t for _, t in ticks]
    assert len(labels) >= 7 and set(labels) <= {f"{a}°" for a in range(0, 360, 45)}
    width = page.evaluate("document.getElementById('plot').getBoundingClientRect().width")
    for x, label in ticks:                # frame k at 8 + k/(n−1)·(w−16); θ2 = 90° − 2.5° k
        k = (x - 8) / (width - 16) * 143
        off = (90 - 2.5 * k - float(label[:-1]) + 180) % 360 - 180
        assert off == pytest.approx(0, abs=0.01)       # to a hundredth of a degree


_CLIPPED = """joints => {
  const svg = document.querySelector('#sheet svg'), v = svg.viewBox.baseVal, out = [];
  for (const it of tarsimView.state.items) {
    const e = it.el;
    if (it.kind !== 't' || getComputedStyle(e).display === 'none') continue;
    if (joints && !(it.move && tarsimView.data.home.points.includes(it.move[1][0]))) continue;
    const b = e.getBBox(), t = e.transform.baseVal.consolidate();
    const x = b.x + (t ? t.matrix.e : 0), y = b.y + (t ? t.matrix.f : 0);
    if (x < v.x || y < v.y || x + b.width > v.x + v.width || y + b.height > v.y + v.height)
      out.push(e.textContent);
  }
  return out;
}"""
"""The texts the view cuts at its edge (any part of them outside the viewBox): all of
them, or (``joints``) those that stand on a joint of the mechanism."""


@pytest.mark.parametrize("lang", ["en", "fa"])
def test_no_label_is_cut_at_the_edge_of_the_view(page, lang):
    """At the exercise's position every text of the space diagrams is inside the view (a
    Persian caption runs wider in the browser than the box the figure was laid out in),
    and turned round, every name on a joint of the mechanism is (the crank swings it past
    the drawing's box; a centre running off toward infinity is the reader's to pan to)."""
    if lang == "fa":
        page.click("#lang")
    for figure in ("0", "1"):                    # the centres, V_B by radius rotation
        page.select_option("#figure", figure)
        page.evaluate("tarsimView.setStep(100)")
        assert page.evaluate(_CLIPPED, False) == [], figure
        for frame in (30, 50, 101, 130):
            page.evaluate(f"tarsimView.setFrame({frame})")
            assert page.evaluate(_CLIPPED, True) == [], (figure, frame)
        page.evaluate("tarsimView.setFrame(0)")
        assert page.evaluate(_CLIPPED, False) == [], figure


_OVER = """() => {
  const shown = e => getComputedStyle(e).display !== 'none';
  const box = e => { const b = e.getBBox(), t = e.transform.baseVal.consolidate();
    const x = b.x + (t ? t.matrix.e : 0), y = b.y + (t ? t.matrix.f : 0);
    return [x, y, x + b.width, y + b.height]; };
  const names = [...document.querySelectorAll('#sheet g.L-labels')].filter(shown);
  const out = [];
  for (const c of [...document.querySelectorAll('#sheet circle.s-badge')].filter(shown))
    for (const n of names) {
      const [a, b] = [box(c), box(n)];
      const across = Math.min(a[2], b[2]) - Math.max(a[0], b[0]);
      if (across > 0.3 && Math.min(a[3], b[3]) - Math.max(a[1], b[1]) > 0.3)
        out.push(n.textContent);
    }
  return out;
}"""
"""The names a step number's ring stands over, by more than 0.3 mm each way."""


def test_no_step_number_stands_over_a_name(page):
    """Turned round, the step numbers (which number the steps drawn at the exercise's
    position) are hidden, so that none stands over a name carried another way (the worked
    page's ⑥ came over "b₄ ≡ b₅" at θ2 = −35°); at the position none does on the space
    diagrams. (The worked page is the SVG `tarsim solve` writes, element for element: its
    ⑥ grazes "b₄ ≡ b₅" by 0.5 mm in the browser's letters, as its figure sets them.)"""
    for figure in ("0", "1", "2"):
        page.select_option("#figure", figure)
        page.evaluate("tarsimView.setStep(100)")
        if figure != "2":
            assert page.evaluate(_OVER) == [], figure
        for frame in (30, 50, 101):
            page.evaluate(f"tarsimView.setFrame({frame})")
            assert page.evaluate(_OVER) == [], (figure, frame)
            assert page.evaluate("[...document.querySelectorAll('#sheet .L-numbers')]"
                                 ".filter(e => getComputedStyle(e).display !== 'none')"
                                 ".length") == 0
        page.evaluate("tarsimView.setFrame(0)")


def test_reset_view_undoes_zoom_and_pan(page):
    """Zoomed with the wheel and panned by a drag, the view box is another; the reset
    button puts it back exactly."""
    box = page.get_attribute("#sheet svg", "viewBox")
    area = page.locator("#sheet svg").bounding_box()
    page.mouse.move(area["x"] + 100, area["y"] + area["height"] - 60)
    page.mouse.wheel(0, -400)
    page.mouse.down()
    page.mouse.move(area["x"] + 160, area["y"] + area["height"] - 20)
    page.mouse.up()
    assert page.get_attribute("#sheet svg", "viewBox") != box
    page.click("#reset")
    assert page.get_attribute("#sheet svg", "viewBox") == box


def test_a_turned_frame_downloads_with_its_caption_and_scale(page):
    """Turned to θ2 = 40°, the downloaded SVG carries the figure's title, its scale bar
    and the caption, the caption saying θ₂ = 40°, not the exercise's 90°."""
    page.evaluate("tarsimView.setStep(100)")
    page.evaluate("tarsimView.setFrame(20)")
    with page.expect_download() as got:
        page.click("#download")
    svg = Path(got.value.path()).read_text(encoding="utf-8")
    words = ["".join(t.itertext()) for t in ET.fromstring(svg).iter(f"{SVG}text")]
    assert "Scale 7 cm = 500 mm" in words and "500 mm" in words
    assert any(w.startswith("θ₂ = 40°") for w in words)
    assert not any("90°" in w for w in words)
    bars = page.evaluate("tarsimView.state.items.filter(it => it.paper === 1 && it.kind === 'z')"
                         ".map(it => it.el.getAttribute('d'))")
    assert len(bars) >= 4 and set(bars) <= {e.get("d") for e in ET.fromstring(svg).iter()}


def test_a_notebook_shows_the_page_running_in_its_frame(browser):
    """What a notebook shows of ``tarsim.solve(…)`` is the page itself in an iframe's
    srcdoc: loaded so in chromium, its script runs there (the figure drawn, the readout
    set) with no error."""
    import tarsim

    shown = tarsim.solve(tarsim.load("four-bar")).view(step_deg=10.0)._repr_html_()
    p = browser.new_page(viewport={"width": 1200, "height": 1000})
    errors = []
    p.on("pageerror", lambda e: errors.append(str(e)))
    p.set_content(f"<!DOCTYPE html><html><body>{shown}</body></html>")
    frame = p.frame_locator("iframe")
    assert "ω4 = 2.91596 rad/s (ccw)" in frame.locator("#readout").inner_text()
    assert frame.locator("#sheet [data-i]").count() > 50
    assert errors == []
    p.close()
