"""Rotors whose polygons close on themselves, and the files that must be refused, each held to
its closed form solved by hand.

A rotor balanced in planes A and B needs (m r)_B = −Σ mᵢrᵢlᵢ / l_B (lᵢ from A) and
(m r)_A = −Σ mᵢrᵢ − (m r)_B. Where a sum vanishes, its polygon closes on itself and its plane
needs no mass: that must be said ("none needed"), given as a zero product with no angle in
results.json, and drawn with no closing side and no balancing mass in the end view.
The sums here are a few products of order 0.1–1 kg·m, so the polygons' answers agree with
the hand's to a few roundings: 1e-12 relative, 1e-15 kg·m absolute for a zero.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest
from click.testing import CliRunner

import tarsim
from tarsim.constructions.errors import InputError
from tarsim.exercises.balancing.balance_solution import solve_balance
from tarsim.exercises.cli import cli
from tarsim.exercises.balancing.rotor_file import parse_balance

HERE = Path(__file__).parent / "reproducers"

ZERO = 1e-15
"""kg·m: a product that is zero by hand, left by rounding at 0.1–1 kg·m (a few 1e-17)."""


def _mr(m: float, r: float, degrees: float) -> tuple[float, float]:
    """m·r (kg·m) at its angle, as a vector."""
    t = math.radians(degrees)
    return (m * r * math.cos(t), m * r * math.sin(t))


def _rotor(masses, planes) -> str:
    """A rotor file in mm and rpm: masses (name, kg, mm, °, plane mm), planes (name, mm,
    radius mm)."""
    out = ['name = "rotor"', "[units]", 'length = "mm"', 'speed = "rpm"', "[rotor]",
           "speed = 300"]
    for name, m, r, a, z in masses:
        out += ["[[mass]]", f'name = "{name}"', f"mass = {m}", f"radius = {r}", f"angle = {a}",
                f"plane = {z}"]
    for name, z, r in planes:
        out += ["[[balance]]", f'name = "{name}"', f"plane = {z}", f"radius = {r}"]
    return "\n".join(out) + "\n"


def _solve(masses, planes):
    s = solve_balance(parse_balance(_rotor(masses, planes), "rotor.toml"))
    assert s.passed, s.failures
    return s


def _arrows(fig) -> list:
    """The polygon's drawn vectors and closing side, each a shaft with its head (a legend's
    sample has none): (style, length of the shaft on paper, mm)."""
    items = list(fig.items)
    return [(p.style, math.dist(p.points[0], p.points[-1]))
            for p, head in zip(items, items[1:])
            if getattr(p, "style", "") in ("vector", "vector_result")
            and getattr(head, "style", "") == "arrowhead"]


def _legend(fig) -> list[str]:
    """The styles the caption's legend shows a sample of."""
    items = list(fig.items)
    return [p.style for p, after in zip(items, items[1:] + [None])
            if getattr(p, "style", "") in ("vector", "vector_result")
            and getattr(after, "style", "") != "arrowhead"]


def _says_none(s, plane: str) -> None:
    """Plane ``plane`` needs no mass, and every output says so honestly."""
    q = s.results["quantities"][f"mr_{plane}"]
    assert q["value"] == [0.0, 0.0] and q["none_needed"] is True and "angle_deg" not in q
    assert math.hypot(*q["reference"]["value"]) < ZERO            # the closed form agrees
    line = next(t for t in s.lines() if t.startswith(f"plane {plane}:"))
    assert "no balancing mass needed" in line, line
    # No balancing mass drawn for it in the end view: its label would start with its name.
    space = s.figures["space"]
    assert not any(getattr(t, "text", "").startswith(f"{plane}:") for t in space.items)


# ----- the reproducer -------------------------------------------------------------------------
def test_refused_balance_all_masses_in_plane_A(tmp_path):
    # 10 kg at 100 mm, 30°, in plane A (0 mm); B at 500 mm. Every lᵢ = 0, so Σ mᵢrᵢlᵢ = 0 and
    # (m r)_B = 0: B needs no mass. (m r)_A = −Σ mᵢrᵢ = −1 kg·m at 30° = 1 kg·m at 210°, which
    # at A's 100 mm is 10 kg.
    out = tmp_path / "out"
    result = CliRunner().invoke(cli, ["solve", str(HERE / "refused-balance-all-masses-in-plane-A"
                                                   ".toml"), "-o", str(out), "--no-pdf"])
    assert result.exit_code == 0, result.output
    assert "plane B: no balancing mass needed" in result.output
    assert "plane A: balancing m·r = 1 kg·m at 210.00°, so 10 kg at 100 mm" in result.output
    q = json.loads((out / "results.json").read_text(encoding="utf-8"))["quantities"]
    assert q["mr_A"]["value"] == pytest.approx([-math.sqrt(3) / 2, -0.5], rel=1e-12)
    assert q["mr_A"]["angle_deg"] == pytest.approx(210.0, rel=1e-12)
    assert q["mr_B"] == {"value": [0.0, 0.0], "none_needed": True,
                         "reference": {"value": [0.0, 0.0]},
                         "method": "couple and force polygons"}
    # The couple polygon is a point: steps.md says so and there is no figure of it.
    steps = (out / "steps.md").read_text(encoding="utf-8")
    assert "the couple polygon is a point: plane B needs no balancing mass" in steps
    assert not (out / "couple-polygon.svg").exists()
    s = tarsim.solve(tarsim.load(str(HERE / "refused-balance-all-masses-in-plane-A.toml")))
    _says_none(s, "B")
    # The force polygon: one vector out and its closing side back, both 1 kg·m long.
    assert [style for style, _ in _arrows(s.figures["force-polygon"])] == ["vector",
                                                                            "vector_result"]


# ----- the family of polygons that close on themselves ------------------------------------------
def test_every_mass_in_plane_B_leaves_plane_A_nothing():
    # Both masses in B (500 mm): Σ mᵢrᵢlᵢ = 0.5·Σ mᵢrᵢ, so (m r)_B = −Σ mᵢrᵢ and (m r)_A = 0.
    s = _solve([("1", 10, 100, 30, 500), ("2", 5, 80, 100, 500)],
               [("A", 0, 100), ("B", 500, 100)])
    f = [a + b for a, b in zip(_mr(10, 0.1, 30), _mr(5, 0.08, 100))]
    assert s.results["quantities"]["mr_B"]["value"] == pytest.approx([-f[0], -f[1]], rel=1e-12)
    _says_none(s, "A")
    # Closed on itself: no closing side drawn, and the caption does not point to one.
    fig = s.figures["force-polygon"]
    assert "vector_result" not in [style for style, _ in _arrows(fig)]
    assert _legend(fig) == ["vector"]
    assert "(m r)_A" not in s.steps() and "plane A needs no balancing mass" in s.steps()


def test_masses_that_balance_already_need_nothing_in_either_plane():
    # 2 kg at 100 mm, 0° and 180°, both at 200 mm: Σ mᵢrᵢ = 0 and Σ mᵢrᵢlᵢ = 0.
    s = _solve([("1", 2, 100, 0, 200), ("2", 2, 100, 180, 200)],
               [("A", 0, 100), ("B", 500, 100)])
    _says_none(s, "A")
    _says_none(s, "B")
    assert s.lines()[0] == "ΣF_x = ΣF_y = 0 (kg·m): the masses' forces cancel, with no resultant"
    for name in ("force-polygon", "couple-polygon"):
        styles = [style for style, _ in _arrows(s.figures[name])]
        assert styles == ["vector", "vector"], (name, styles)


def test_a_star_of_equal_masses_needs_no_static_balance():
    # Three 2 kg masses at 100 mm, 120° apart, one plane: Σ mᵢrᵢ = 0.2·(1 + e^{i2π/3} +
    # e^{i4π/3}) = 0, to the rounding of cos 120° and sin 240°.
    s = _solve([("1", 2, 100, 0, 0), ("2", 2, 100, 120, 0), ("3", 2, 100, 240, 0)],
               [("A", 0, 100)])
    _says_none(s, "A")
    assert "vector_result" not in [style for style, _ in _arrows(s.figures["force-polygon"])]


def test_couples_that_cancel_about_A_leave_B_nothing():
    # 1 kg at 100 mm, 0°, at 100 mm; 0.5 kg at 100 mm, 180°, at 200 mm: Σ mᵢrᵢlᵢ = 0.1·0.1 −
    # 0.05·0.2 = 0, so B needs none; Σ mᵢrᵢ = 0.05 kg·m at 0°, so (m r)_A = 0.05 kg·m at 180°,
    # 0.5 kg at 100 mm.
    s = _solve([("1", 1, 100, 0, 100), ("2", 0.5, 100, 180, 200)],
               [("A", 0, 100), ("B", 500, 100)])
    _says_none(s, "B")
    assert s.results["quantities"]["mr_A"]["value"] == pytest.approx([-0.05, 0.0], abs=ZERO)
    assert "plane A: balancing m·r = 0.05 kg·m at 180.00°, so 0.5 kg at 100 mm" in s.lines()
    # Its two vectors are drawn, and no closing side: the polygon closes on itself.
    assert [style for style, _ in _arrows(s.figures["couple-polygon"])] == ["vector", "vector"]


def test_masses_centred_on_plane_B_leave_A_nothing():
    # 1 kg at 100 mm, 0°, at 400 and 600 mm, B at 500: Σ mᵢrᵢlᵢ = 0.1·(0.4 + 0.6) = 0.1, so
    # (m r)_B = −0.1/0.5 = 0.2 kg·m at 180° (2 kg); (m r)_A = −0.2 + 0.2 = 0.
    s = _solve([("1", 1, 100, 0, 400), ("2", 1, 100, 0, 600)], [("A", 0, 100), ("B", 500, 100)])
    assert s.results["quantities"]["mr_B"]["value"] == pytest.approx([-0.2, 0.0], abs=ZERO)
    _says_none(s, "A")


def test_a_mass_in_the_reference_plane_lays_no_couple():
    # 1 kg at 100 mm, 0°, in A itself (l = 0); 1 kg at 100 mm, 90°, at 300 mm: Σ mᵢrᵢlᵢ =
    # (0, 0.03), (m r)_B = (0, −0.06), (m r)_A = −(0.1, 0.1) − (0, −0.06) = (−0.1, −0.04).
    s = _solve([("1", 1, 100, 0, 0), ("2", 1, 100, 90, 300)], [("A", 0, 100), ("B", 500, 100)])
    q = s.results["quantities"]
    assert q["mr_B"]["value"] == pytest.approx([0.0, -0.06], abs=ZERO)
    assert q["mr_A"]["value"] == pytest.approx([-0.1, -0.04], abs=ZERO)
    # Mass 1's m·r·l is zero: the couple polygon draws mass 2's vector and the closing side.
    arrows = _arrows(s.figures["couple-polygon"])
    assert [style for style, _ in arrows] == ["vector", "vector_result"]
    assert all(length > 1.0 for _, length in arrows)


def test_plane_B_may_stand_before_A():
    # A at 500 mm, B at 0: lᵢ = −400 and −200 mm, lever −500 mm. Σ mᵢrᵢlᵢ = (−0.04, −0.02),
    # (m r)_B = −(−0.04, −0.02)/(−0.5) = (−0.08, −0.04); (m r)_A = −(0.1, 0.1) − (m r)_B =
    # (−0.02, −0.06).
    s = _solve([("1", 1, 100, 0, 100), ("2", 1, 100, 90, 300)], [("A", 500, 100), ("B", 0, 100)])
    q = s.results["quantities"]
    assert q["mr_B"]["value"] == pytest.approx([-0.08, -0.04], abs=ZERO)
    assert q["mr_A"]["value"] == pytest.approx([-0.02, -0.06], abs=ZERO)


# ----- refused, in one line naming the place ----------------------------------------------------
def test_two_balancing_planes_at_one_place_are_refused_naming_both(tmp_path):
    path = tmp_path / "rotor.toml"
    path.write_text(_rotor([("1", 1, 100, 0, 100)], [("A", 250, 100), ("B", 250, 100)]),
                    encoding="utf-8")
    out = tmp_path / "out"
    result = CliRunner().invoke(cli, ["solve", str(path), "-o", str(out), "--no-pdf"])
    assert result.exit_code == 1
    line = result.output.strip()
    # one line, short beside the path it names (pytest's folder is of any length)
    assert "\n" not in line and len(line.replace(str(path), "")) < 200, line
    # Line 19 is plane B's "plane = 250", the second of the two.
    assert line.startswith(f"Error: {path}:19: ") and "planes A and B" in line, line
    assert not out.exists()


@pytest.mark.parametrize("old, new, words", [
    ('name = "2"', 'name = "1"', "two masses are named 1"),
    ('name = "2"', 'name = "B"', "balancing plane B has the name of mass B"),
    ('name = "2"', 'name = ""', "mass 2's name must be a short word"),
    ("[rotor]", "[[rotor]]", "[rotor] is one table, not a list of 2"),
])
def test_a_rotor_that_names_two_things_alike_is_refused(old, new, words):
    text = _rotor([("1", 1, 100, 0, 100), ("2", 1, 100, 90, 300)],
                  [("A", 0, 100), ("B", 500, 100)])
    if old == "[rotor]":
        text = text.replace(old, new) + "[[rotor]]\nspeed = 1\n"
    else:
        text = text.replace(old, new)
    with pytest.raises(InputError) as e:
        parse_balance(text, "rotor.toml")
    message = str(e.value)
    assert "\n" not in message and message.startswith("rotor.toml:") and words in message, \
        message


ENGINE = """\
name = "engine"
[units]
length = "mm"
speed = "rpm"
[engine]
speed = 1800
crank = 50
rod = 200
reciprocating = 1.5
"""


def test_cylinders_in_one_plane_are_refused_naming_both():
    text = ENGINE + "[[cylinder]]\ncrank = 0\nplane = 0\n[[cylinder]]\ncrank = 180\nplane = 0\n"
    # Line 15 is the second cylinder's "plane = 0".
    with pytest.raises(InputError, match=r"^engine.toml:15: cylinders 1 and 2 stand in the "
                                         r"same plane"):
        parse_balance(text, "engine.toml")


def test_a_three_cylinder_engine_says_its_forces_are_balanced():
    # Cranks 0°, 120°, 240°: Σ e^{iθ} = 0 and Σ e^{i2θ} = 0, so both force polygons close on
    # themselves; the couples about the central plane (±100 mm) do not: the primary one is
    # m·ω²·r·|−0.1 + 0.1·e^{i240°}| = m·ω²·r·0.1·√3.
    cylinders = "".join(f"[[cylinder]]\ncrank = {c}\nplane = {p}\n"
                        for c, p in ((0, 0), (120, 100), (240, 200)))
    s = solve_balance(parse_balance(ENGINE + cylinders, "engine.toml"))
    assert s.passed, s.failures
    q = s.results["quantities"]
    f = 1.5 * (60 * math.pi) ** 2 * 0.05
    assert q["primary_force"]["value"] == 0.0 and q["secondary_force"]["value"] == 0.0
    assert q["primary_couple"]["value"] == pytest.approx(f * 0.1 * math.sqrt(3), rel=1e-12)
    lines = s.lines()
    assert "primary force: balanced (its polygon closes)" in lines
    assert "secondary force: balanced (its polygon closes)" in lines
    assert "The primary force polygon closes on itself" in s.steps()
    styles = [style for style, _ in _arrows(s.figures["primary-force"])]
    assert styles == ["vector"] * 3
