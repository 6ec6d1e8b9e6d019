"""The interactive page's Persian step list keeps each formula on one line: a formula among
Persian words ("V_A = ω2·O2A = ۱ rad/s × ۱۸۰") is isolated left to right and never broken
at its spaces, at any width of the list, in a real browser (Debian's chromium)."""

from __future__ import annotations

import pytest

from tests.common import written_view

_BROKEN = """() => {
  const out = [], pick = document.querySelector('#figure');
  for (let i = 0; i < pick.options.length; i++) {
    pick.value = String(i);
    pick.dispatchEvent(new Event('change'));
    document.querySelectorAll('#steps bdi').forEach(el => {
      // a formula's pieces on more than one line: laid out at more than one height
      const tops = new Set([...el.getClientRects()].map(r => Math.round(r.top)));
      if (tops.size > 1) out.push(el.textContent);
    });
  }
  return [document.querySelectorAll('#steps bdi').length, out];
}"""


@pytest.fixture(scope="module")
def shaper(tmp_path_factory):
    return written_view(tmp_path_factory.mktemp("view") / "shaper.html", "10")


@pytest.mark.slow
@pytest.mark.parametrize("width", [900, 1400])
def test_no_persian_step_breaks_a_formula_across_lines(browser, shaper, width):
    # Today 13 to 15 of the crank-shaper's formulas run over two lines at these widths.
    page = browser.new_page(viewport={"width": width, "height": 900})
    try:
        page.goto(shaper.as_uri())
        page.click("#lang")
        formulas, broken = page.evaluate(_BROKEN)
    finally:
        page.close()
    assert formulas >= 40
    assert broken == []
