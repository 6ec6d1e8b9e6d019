"""What an instructor hides of a figure (``tarsim solve --hide``): the hidden parts are gone
from the figure and its SVG, and the rest is drawn as it was."""

from __future__ import annotations

import re
from collections import Counter

from click.testing import CliRunner

from tarsim.constructions.narration import speaking
from tarsim.exercises.catalog import load
from tarsim.exercises.cli import cli
from tarsim.exercises.linkages.solution_files import solve_worked
from tarsim.graphics.figure import Circle, Path, Text
from tarsim.graphics.hiding import hiding
from tarsim.graphics.svg import to_svg


def _figures(name: str, hide: frozenset[str] = frozenset()):
    with speaking("en"), hiding(hide):
        worked = solve_worked(load(name))
        return worked, worked.figures


def _svg_texts(fig) -> Counter:
    return Counter(re.sub(r"<[^>]+>", "", m) for m in
                   re.findall(r"<text\b[^>]*>(.*?)</text>", to_svg(fig), re.S))


def _panel_texts(fig) -> Counter:
    """The texts of a worked page's sheets but their titles (4 mm letters and larger) and
    its scales: each statement, and the numbers under its bar (within 6 mm of it)."""
    bars = [p for sheet in (fig.sheets or [fig]) for p in sheet.items
            if isinstance(p, Path) and p.style in ("scale", "scale_fill")]
    out = Counter()
    for sheet in fig.sheets or [fig]:
        for t in sheet.items:
            if not isinstance(t, Text) or t.size >= 4.0 or "scale 1 cm" in t.text.lower():
                continue
            x, y = t.at
            if any(min(q[0] for q in b.points) - 6 <= x <= max(q[0] for q in b.points) + 12
                   and abs(y - b.points[0][1]) <= 6 for b in bars if b in sheet.items):
                continue
            out[t.text] += 1
    return out


def test_hidden_badges_leave_every_other_item_where_it_was():
    _, shown = _figures("four-bar")
    _, bare = _figures("four-bar", frozenset({"badges"}))
    fig, clean = shown["V_B-radius-rotation"], bare["V_B-radius-rotation"]
    badges = [it for it in fig.items if isinstance(it, Circle) and it.style == "badge"]
    assert len(badges) >= 10            # the radius rotation's numbered steps
    centres = {b.centre for b in badges}
    numbers = [it for it in fig.items if isinstance(it, Text) and it.at in centres]
    assert len(numbers) == len(badges)  # a number in each circle
    assert not [it for it in clean.items if getattr(it, "style", "") == "badge"]
    # Every other item is the same, in the same place and order: the labels are placed
    # as before, the badges' room left empty.
    assert clean.items == [it for it in fig.items if it not in badges and it not in numbers]
    assert (clean.width, clean.height) == (fig.width, fig.height)
    assert _svg_texts(fig) - _svg_texts(clean) == Counter(t.text for t in numbers)
    assert to_svg(fig).count("<circle") - to_svg(clean).count("<circle") == len(badges)


def test_hidden_checks_leave_the_table_its_quantities_and_methods():
    worked, shown = _figures("crank-shaper")
    _, bare = _figures("crank-shaper", frozenset({"checks"}))
    fig, clean = shown["worked-theta2-90"], bare["worked-theta2-90"]
    with speaking("en"):
        from tarsim.exercises.linkages.solution_files import _results_table
        table = _results_table(worked.positions[0])
    assert table[0] == ("quantity", "method", "construction", "analytic", "relative error")
    gone = Counter(cell for row in table for cell in row[2:])
    assert gone["232.9 mm/s at 0°"] == 4          # V_B's construction and analytic, twice
    # The texts of the page less the three columns' cells, every other one kept; the
    # narrower table may join the panels on a sheet, a sheet's "(continued)" go, and a
    # panel left alone on a sheet be drawn again at a finer scale: its scale and the
    # sheets' titles are not compared.
    before, after = (Counter({t: n for t, n in _panel_texts(f).items()
                              if not t.endswith("(continued)")}) for f in (fig, clean))
    assert before - after == gone
    assert not after - before
    texts = _svg_texts(clean)
    assert texts["quantity"] == 1 and texts["method"] == 1
    assert not texts["analytic"] and not texts["relative error"]


def test_hidden_answers_leave_the_table_and_the_limits_without_numbers():
    worked, shown = _figures("crank-shaper")
    _, bare = _figures("crank-shaper", frozenset({"answers"}))
    texts = _svg_texts(bare["worked-theta2-90"])
    assert texts["relative error"] == 1 and not texts["construction"]
    assert not texts["232.9 mm/s at 0°"] and not texts["analytic"]
    limits, clean = _svg_texts(shown["limits"]), _svg_texts(bare["limits"])
    # The stroke and the crank's two turns are read off the figure as answers (679.1 mm,
    # 222.20°, 137.80°, as steps.md gives them); hidden, their names stay.
    assert {"stroke 679.1 mm", "222.20° slow", "137.80° quick"} <= set(limits)
    assert {"stroke", "slow", "quick"} <= set(clean)
    assert not [t for t in clean if re.search(r"679\.1|222\.2|137\.8|1\.612", t)]


def test_an_unknown_part_is_a_usage_error(tmp_path):
    got = CliRunner().invoke(cli, ["solve", "four-bar", "--hide", "answers,steps",
                                   "-o", str(tmp_path / "s")])
    assert got.exit_code == 2
    assert ("'steps' is not a part a figure can hide; choose among answers, badges, checks"
            in got.output)
    assert not (tmp_path / "s").exists()
