"""The turning-moment diagram and the flywheel, against closed forms.

- A torque T_m + A·sin kθ swings the energy through 2A/k (E = −(A/k)·cos kθ); the
  trapezoid and straight-line intercepts are good to (2π/N)² relative.
- The crank-shaper cutting 1000 N on its slow stroke: over a turn the driver does the
  cut's work and nothing else (weight and inertia give back what they take), so the mean
  torque is 1000 N × stroke / 2π, the stroke 2·880·tan(asin 0.36) mm by the lever's limits.
  The cut switches on and off between samples, an error of at most the jump times a step
  over the turn: 1e-3 at 360 steps.
- A crank of mass m whose centre G is r_G from its pivot, turning at ω in a pin with a
  friction circle ρ: the pivot carries m·ω²·r_G and takes ρ·m·ω²·r_G of torque, the same
  at every step; at ω = 1e25 rad/s nothing else the loads do reaches the torque's rounding.
- A four-bar of S + L = P + Q lies flat twice a turn, a change point; a parallelogram's
  four pivots line up where the crank lies along the frame.
"""

from __future__ import annotations

import math
import re
import sys
from pathlib import Path

import pytest
from click.testing import CliRunner
from hypothesis import example, given, settings
from hypothesis import strategies as st

import tarsim
from tarsim.constructions.errors import InputError
from tarsim.constructions.reference.flywheel import fluctuation, flywheel_inertia, speed_fluctuation
from tarsim.exercises.catalog import bundled
from tarsim.exercises.cli import cli
from tarsim.exercises.linkages.exercise_file import load_exercise, parse_exercise
from tarsim.exercises.forces.turning_moment import turning_moment

FORCES = {name: Path(path) for name, path in bundled("forces").items()}
SHAPER = FORCES["crank-shaper-forces"]
RHOMBUS = Path(__file__).parent / "reproducers" / "wrong-flywheel-rhombus-change-point.toml"


@pytest.mark.parametrize("k", [1, 2, 3])
def test_a_sine_torque_swings_the_energy_by_2a_over_k(k):
    n = 3600
    angles = [2 * math.pi * i / n for i in range(n)]
    r = fluctuation(angles, [80.0 + 25.0 * math.sin(k * t + 0.3) for t in angles])
    assert r.mean == pytest.approx(80.0, rel=1e-14)
    assert r.delta_e == pytest.approx(2 * 25.0 / k, rel=1e-5)
    assert len(r.intercepts) == len(r.areas) == 2 * k
    assert sum(r.areas) == pytest.approx(0.0, abs=1e-9)
    assert all(abs(a) == pytest.approx(2 * 25.0 / k, rel=1e-5) for a in r.areas)


def test_the_flywheel_formulas_invert_each_other():
    i = flywheel_inertia(300.0, 20.0, 0.02)
    assert i == pytest.approx(300.0 / (0.02 * 400.0), rel=1e-15)
    assert speed_fluctuation(300.0, 20.0, i) == pytest.approx(0.02, rel=1e-15)


def test_the_shapers_mean_torque_pays_for_the_cut():
    tm = turning_moment(load_exercise(SHAPER), 360)
    stroke = 2 * 0.880 * math.tan(math.asin(0.36))
    r = tm.reading
    assert r.mean == pytest.approx(1000.0 * stroke / (2 * math.pi), rel=1e-3)
    assert tm.power_miss < 1e-12
    # one rise above the mean while the ram returns, one fall while it cuts
    assert len(r.areas) == 2 and r.areas[0] == pytest.approx(-r.areas[1], rel=1e-12)
    assert r.delta_e == pytest.approx(max(abs(a) for a in r.areas), rel=1e-12)


def test_sweep_writes_the_turning_moment_and_sizes_the_flywheel(tmp_path):
    out = tmp_path / "sw"
    result = CliRunner().invoke(cli, ["sweep", str(SHAPER), "-o", str(out), "--no-pdf",
                                      "--steps", "120"])
    assert result.exit_code == 0, result.output
    assert {"turning-moment.svg", "turning-moment.csv"} <= {p.name for p in out.iterdir()}
    assert "flywheel for C_s = 0.05 at ω = 1 rad/s: I = ΔE/(C_s·ω²) = " in result.output
    assert "balance of power agrees at every step" in result.output
    rows = (out / "turning-moment.csv").read_text(encoding="utf-8").splitlines()
    assert rows[0].startswith("turned_deg,theta_deg,T_Nm,F_12_N") and len(rows) == 121


@pytest.mark.parametrize("old, new, words", [
    ("speed_fluctuation = 0.05", "speed_fluctuation = 0.05\nflywheel = 2",
     "give speed_fluctuation (the flywheel is found) or flywheel"),
    ("speed_fluctuation = 0.05", "speed_fluctuation = -0.05",
     "a coefficient of speed fluctuation must be positive"),
    ("resist = 1000\nstroke = \"slow\"", "resist = 1000\nstroke = \"cutting\"",
     "stroke is both, slow or fast, not 'cutting'"),
    ("link = 5\npoint = \"B\"\nresist", "link = 3\npoint = \"A\"\nresist",
     "a slow stroke belongs to a point on a frame guide"),
    ("resist = 1000", "resist = 1000\nforce = [1, 0]", "in place of force = [x, y]"),
])
def test_bad_flywheel_and_cut_settings_are_refused_in_one_line(old, new, words):
    text = SHAPER.read_text(encoding="utf-8")
    assert old in text
    with pytest.raises(InputError) as e:
        parse_exercise(text.replace(old, new, 1), "cs.toml", "cs")
    message = str(e.value)
    assert "\n" not in message and message.startswith("cs.toml:") and words in message, message


def test_the_force_polygons_fall_on_the_turning_moment_curve():
    """The driving torque the force polygons draw at the exercise's two positions stands on
    the curve (the Newton–Euler torque at the same angle), to a few roundings."""
    tm = turning_moment(load_exercise(SHAPER), 36)
    assert [label.split(" (")[0] for *_, label in tm.marks] == ["θ2 = 90°", "t = 2.34 s"]
    for _, drawn, curve, _ in tm.marks:
        assert drawn == pytest.approx(curve, rel=1e-12)
    assert tm.marks[0][1] == pytest.approx(232.941176, rel=1e-8)    # clockwise positive


def test_the_diagram_is_drawn_at_steady_speed():
    """The loaded four-bar's file gives α2 = 5 rad/s² at its one position; round the turn
    the input runs steadily (α = 0), so weight, inertia and a couple on a rocker (which
    swings back over its own path) do no net work: the mean torque is 0, and the drawn
    position, which speeds up, is no mark on the steady curve."""
    tm = turning_moment(load_exercise(FORCES["four-bar-forces"]), 72)
    assert tm.reading.mean == 0.0
    assert tm.marks == []
    assert tm.lines()[0].startswith("at steady speed, mean driving torque 0 N·m")


def test_a_constant_gas_force_does_no_net_work():
    """engine-forces: 5 kN of gas all round the turn, weight and inertia: all conservative
    or periodic at steady speed, so the mean is 0, said as 0 and not as its rounding."""
    tm = turning_moment(load_exercise(FORCES["engine-forces"]), 72)
    assert tm.reading.mean == 0.0 and tm.reading.delta_e > 100.0


def test_a_flywheel_for_a_standing_input_is_refused():
    text = SHAPER.read_text(encoding="utf-8").replace("omega = -1 ", "omega = 0 ", 1)
    with pytest.raises(InputError, match=r"cs.toml:\d+: a flywheel holds a speed, but link "
                                         r"2's ω is 0 in \[input\]"):
        parse_exercise(text, "cs.toml", "cs")


def _crank_friction_torque(text: str) -> float:
    """ρ·m·ω²·r_G (N·m) of the rhombus file's crank: 1e-5 cm of friction circle, 7.461 kg
    at the middle of its 1e-3 cm, 1e25 rad/s."""
    assert "friction_circle = 1e-05" in text and "mass = 7.461" in text
    return 1e-7 * 7.461 * 1e25 ** 2 * 0.5e-5


def test_wrong_flywheel_rhombus_change_point():
    """A rhombus 1e-3 cm long at ω2 = 1e25 rad/s with its B "right": the folded assembly
    (B on O2) from θ2 = 90° to 270° and the parallelogram beyond, so a turn at that side
    hops from one motion to the other (the 1.94e24 J "fluctuation" it read was rounding).
    Its turn is refused at the first change point it meets from 105° counter-clockwise,
    θ2 = 3π/2, where A, B = O2 and O4 lie in line; the drawn position's torque is the
    crank's pin friction (the gas force's 3.3 kN on a 2e-5 m lever is 1e-40 of it; the
    torque rounds at eps·m·ω²·r_G², 5e-14 of it: 1e-12)."""
    text = RHOMBUS.read_text(encoding="utf-8")
    ex = load_exercise(RHOMBUS)
    solution = tarsim.solve(ex)
    assert solution.passed
    t2 = solution.results["positions"][0]["quantities"]["T2"]["value"]
    assert t2 == pytest.approx(_crank_friction_torque(text), rel=1e-12)
    with pytest.raises(InputError) as e:
        turning_moment(ex, 72)
    message = str(e.value)
    assert "\n" not in message and message.startswith(f"{RHOMBUS}: no turning-moment diagram")
    assert f"passes a change point at θ2 = {3 * math.pi / 2:.6g} rad" in message, message
    result = CliRunner().invoke(cli, ["sweep", str(RHOMBUS), "--no-pdf", "--steps", "72",
                                      "-o", str(RHOMBUS.parent / "never-written")])
    assert result.exit_code == 1 and result.output == f"Error: {message}\n"
    assert not (RHOMBUS.parent / "never-written").exists()


def test_a_torque_steady_to_its_rounding_needs_no_flywheel():
    """The rhombus's loads on a crank-rocker (frame 3e-3, crank 1e-3, coupler 3e-3, rocker
    2.5e-3 cm), which has no change point: the torque is ρ·m·ω²·r_G at every step. By the
    balance of energy the rest swings the energy by less than 0.2 J (3.3 kN of gas force
    over B's 5e-5 m, the crank's weight over 1e-5 m, friction at the light pins), while the
    torque rounds at eps·m·ω²·r_G², 1e24 N·m: the diagram is steady to its rounding, ΔE = 0,
    and no flywheel is needed."""
    text = RHOMBUS.read_text(encoding="utf-8")
    for old, new in (("O4 = [6.123233995736766e-20, 0.001]", "O4 = [0.003, 0.0]"),
                     ("AB = 1e-3", "AB = 3e-3"), ("O4B = 1e-3", "O4B = 2.5e-3")):
        assert old in text
        text = text.replace(old, new)
    tm = turning_moment(parse_exercise(text, "cr.toml", "cr"), 72)
    want = _crank_friction_torque(text)
    rounding = sys.float_info.epsilon * 7.461 * 1e25 ** 2 * 0.5e-5 * 0.5e-5
    assert all(t == pytest.approx(want, rel=1e-12) for t in tm.torques)
    assert 0.2 < 2 * math.pi * tm.noise < 1e3 * rounding
    r = tm.reading
    assert r.delta_e == 0.0 and r.areas == () and r.mean == pytest.approx(want, rel=1e-12)
    assert tm.lines()[1] == ("no flywheel is needed for C_s = 0.01: the torque does not "
                             "fluctuate beyond its rounding")


_PARALLELOGRAM = """\
name = "parallelogram"
[units]
length = "mm"
angle = "deg"
[frame]
O2 = [0.0, 0.0]
O4 = [{x!r}, {y!r}]
[[link]]
number = 2
points = ["O2", "A"]
lengths = {{ O2A = {a!r} }}
[[link]]
number = 3
points = ["A", "B"]
lengths = {{ AB = {g!r} }}
[[link]]
number = 4
points = ["O4", "B"]
lengths = {{ O4B = {a!r} }}
[input]
link = 2
angle = {theta!r}
omega = {omega!r}
[assembly]
B = "{side}"
[ask]
find = ["T2"]
methods = ["polygon"]
[forces]
gravity = true
speed_fluctuation = 0.05
[[mass]]
link = 3
mass = 2.0
centre = "mid"
inertia = 0.01
"""


@settings(max_examples=12, deadline=None, derandomize=True)
@given(a=st.sampled_from([20.0, 50.0, 100.0]), g=st.sampled_from([50.0, 100.0, 150.0]),
       phi=st.floats(-180.0, 180.0), offset=st.floats(20.0, 160.0),
       side=st.sampled_from(["left", "right"]), omega=st.sampled_from([10.0, -3.0]),
       steps=st.sampled_from([36, 72, 180]))
# A rhombus whose 3rd step lands on θ2 = 0°, A on O4: the circles that place B coincide,
# and the solver refused it as no assembly, so the turn ran on to 180°.
@example(a=50.0, g=50.0, phi=0.0, offset=20.0, side="left", omega=-3.0, steps=36)
def test_a_parallelogram_s_turn_is_refused_where_its_pivots_line_up(a, g, phi, offset, side,
                                                                    omega, steps):
    """A parallelogram (a rhombus where a = g) of frame at φ, started off the frame's line:
    its turn is refused at the first change point it meets, where the crank lies along the
    frame (θ2 = φ or φ + 180°), to the 6 figures the line gives."""
    theta = phi + offset
    text = _PARALLELOGRAM.format(x=g * math.cos(math.radians(phi)),
                                 y=g * math.sin(math.radians(phi)), a=a, g=g,
                                 theta=theta, omega=omega, side=side)
    with pytest.raises(InputError) as e:
        turning_moment(parse_exercise(text, "p.toml", "p"), steps)
    found = re.search(r"passes a change point at θ2 = (−?[\d.]+(e[−-]?\d+)?)°", str(e.value))
    assert found, str(e.value)
    at = float(found.group(1).replace("−", "-"))
    # the first of φ + k·180° the turn meets, the way it turns
    sense = 1.0 if omega > 0 else -1.0
    ahead = min((sense * (phi + k * 180.0 - theta)) % 360.0 for k in (0, 1))
    assert math.remainder(at - (theta + sense * ahead), 360.0) == pytest.approx(0.0, abs=2e-3)


@pytest.mark.slow
def test_solve_and_sweep_sign_a_torque_one_way(tmp_path):
    """T2 and the turning moment are both CCW +, each with its sense said; the sweep's T2
    at the exercise's angle is solve's, sign and all (engine-forces: the piston's load turns
    the crank CCW, so the torque that holds it steady is CW)."""
    from tarsim.exercises.cli import cli
    solved = CliRunner().invoke(cli, ["solve", "engine-forces", "-o", str(tmp_path / "s"),
                                      "--no-pdf"]).output
    swept = CliRunner().invoke(cli, ["sweep", "engine-forces", "-o", str(tmp_path / "w"),
                                     "--no-pdf"]).output
    t2 = re.search(r"^T2 = (−?[\d.]+) N·m \((cw|ccw)\)", solved, re.M)
    moment = re.search(r"^turning_moment = (−?[\d.]+) N·m \((cw|ccw)\)", solved, re.M)
    by_sweep = re.search(r"^T2 by the force polygons at .*?: (−?[\d.]+) N·m \((cw|ccw)\)",
                         swept, re.M)
    assert t2 and moment and by_sweep
    assert (t2[2], moment[2]) == ("cw", "ccw")
    assert by_sweep.groups() == t2.groups()
    assert "-" not in by_sweep[0]                 # a true minus, as every table prints it


@pytest.fixture(scope="module")
def engine_diagram():
    """engine-forces' diagram round 360 steps, as `tarsim sweep engine-forces` draws it:
    two loops of 600 J, one wrapped across 360°/0°, and two slivers of −0.48 J and +1.03 J
    a quarter of a millimetre thick by 310°–335°."""
    tm = turning_moment(load_exercise(FORCES["engine-forces"]), 360)
    return tm, tm.figure()


def test_each_area_is_labelled_once_inside_its_loop_or_beside_it_with_a_leader(
        engine_diagram):
    """Each of the 4 areas has one label (the wrapped one too): inside its own loop where
    its words fit, else beside it with a leader from the words' box into the loop; no
    label on another loop (more than 0.01 mm², a graze) or on another label. The slivers'
    labels stood 2 mm off theirs with nothing joining them."""
    from shapely.geometry import Point, Polygon, box
    from shapely.ops import unary_union

    from tarsim.graphics.figure import Path as Stroke, Text

    tm, fig = engine_diagram
    _, tags = tm._areas(tm.reading)
    assert len(tags) == len(tm.reading.areas) == 4
    fills = [p for p in fig.items if isinstance(p, Stroke) and p.style.startswith("triangle")]
    loops, k = [], 0
    for tag in tags:                   # the figure's outlines, in the order drawn, by area
        loops.append(unary_union([Polygon(p.points).buffer(0)
                                  for p in fills[k:k + len(tag[3])]]))
        k += len(tag[3])
    assert k == len(fills)
    leaders = [p.points for p in fig.items if isinstance(p, Stroke) and p.style == "plot_leader"]
    words = {t.text: box(*t.box()) for t in fig.items if isinstance(t, Text)
             and t.text.endswith(" J") and t.text[:1] in "+−"}
    assert sorted(words) == sorted(tag[2] for tag in tags)       # each area labelled once
    for n, tag in enumerate(tags):
        mine, loop = words[tag[2]], loops[n]
        if not loop.contains(mine):
            # the leader starts at the words (a gap of 0.3 mm, as a mark's does) and ends
            # inside the loop
            assert any(mine.exterior.distance(Point(a)) < 0.5 and loop.distance(Point(b))
                       < 1e-6 for a, b in leaders), tag[2]
        for j, other in enumerate(loops):
            if j != n:
                assert mine.intersection(other).area <= 0.01, (tag[2], tags[j][2])
        for text, theirs in words.items():
            if text != tag[2]:
                assert not mine.intersects(theirs), (tag[2], text)


def test_the_position_drawn_is_marked_with_its_value(engine_diagram):
    """The force polygons' position on the curve is named with its angle: θ2 = 40°, the
    file's [input] angle, where it read θ2 alone."""
    from tarsim.graphics.figure import Text

    _, fig = engine_diagram
    assert [t.text for t in fig.items if isinstance(t, Text) and t.text.startswith("θ2")
            and t.size < 3.0] == ["θ2 = 40°"]


@pytest.mark.parametrize("offset, said", [(0.01, "mean 0 N·m"), (5.0, "mean 5 N·m")])
def test_a_mean_the_drawing_cannot_show_off_zero_is_stated_as_0(engine_diagram, offset, said):
    """engine-forces' torque moved up by 0.01 N·m has that mean, beyond its rounding, but on
    a diagram of ±400 N·m over 82 mm a tenth of a millimetre is 0.98 N·m: its mean line
    cannot be drawn off zero, and is stated as 0; one of 5 N·m can, and is stated."""
    import copy

    from tarsim.graphics.figure import Text

    tm = copy.copy(engine_diagram[0])
    tm.torques = [t + offset for t in tm.torques]
    assert tm.reading.mean == pytest.approx(offset, rel=1e-6)
    fig = tm.figure()
    assert [t.text for t in fig.items if isinstance(t, Text) and t.text.startswith("mean")] \
        == [said]
