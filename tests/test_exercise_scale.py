"""An exercise's stated scales ("1 cm = 4 cm", "3 cm = 18 cm/s", "1 cm = 2 m/s²") are the
scales its figures are drawn at: the statement printed on each, and what a ruler measures."""

from __future__ import annotations

import math

import pytest

from tarsim.constructions.reference import solver
from tarsim.constructions.linkages.assembly import assemble
from tarsim.constructions.errors import InputError
from tarsim.constructions.record import Panel, Slice
from tarsim.exercises.linkages.exercise_file import parse_exercise
from tarsim.exercises.linkages.solution import solve_exercise
from tarsim.graphics.linkages.diagram import draw_kinematic_diagram
from tarsim.graphics.linkages.polygon_panel import draw_polygon_panel
from tarsim.graphics.linkages.scene import draw_scene
from tests.common import four_bar_toml


def _with_scale(scale: str) -> str:
    moving = four_bar_toml().replace("[input]\n", "[input]\nomega = 10\n")
    return moving + f'\n[ask]\nfind = ["omega4"]\nscale = "{scale}"\n'


@pytest.mark.parametrize("stated, per_cm_mm, words", [
    ("1 cm = 4 cm", 40.0, "1 cm = 4 cm"), ("1 cm = 50 mm", 50.0, "1 cm = 50 mm"),
    ("1cm=0.2 m", 200.0, "1 cm = 0.2 m"), ("1 cm = 2.5 in", 63.5, "1 cm = 2.5 in")])
def test_the_stated_scale_is_drawn_true(stated, per_cm_mm, words):
    ex = parse_exercise(_with_scale(stated))
    assert ex.mechanism.scale == pytest.approx(per_cm_mm)        # the file's unit is mm
    fig = draw_kinematic_diagram(assemble(ex.mechanism))
    texts = [t.text for t in fig.items if hasattr(t, "text")]
    assert f"Scale {words}" in texts                      # as the exercise words it
    # The crank O2A (100 mm) is drawn 100 / per_cm centimetres long on paper.
    pins = [it.centre for it in fig.items if getattr(it, "style", "") == "pin"]
    lengths = sorted(math.dist(p, q) for p in pins for q in pins if p < q)
    assert any(abs(d - 10 * 100 / per_cm_mm) < 1e-6 for d in lengths)


@pytest.mark.parametrize("bad", ["4 cm", "1 cm = -4 cm", "1 cm = 4 furlongs", "0 cm = 4 cm"])
def test_a_malformed_scale_is_named_at_its_line(bad):
    with pytest.raises(InputError, match=r"ex.toml:\d+: \[ask.scale\] scale must read like "
                                         r"\"1 cm = 4 cm\""):
        parse_exercise(_with_scale(bad), "ex.toml")


# ----- velocity and acceleration scales ---------------------------------------------------
def _with_scales(*stated: str, find='["V_B"]', methods='["radius-rotation"]') -> str:
    listed = ", ".join(f'"{s}"' for s in stated)
    moving = four_bar_toml().replace("[input]\n", "[input]\nomega = 10\n")
    return moving + f'\n[ask]\nfind = {find}\nmethods = {methods}\nscale = [{listed}]\n'


@pytest.mark.parametrize("stated, kind, per_cm", [
    ("1 cm = 50 mm/s", "velocity", 50.0), ("3 cm = 18 cm/s", "velocity", 60.0),
    ("1 in = 1 ft/s", "velocity", 304.8 / 2.54), ("1 cm = 2 m/s²", "acceleration", 2000.0),
    ("2 cm = 1 m/s^2", "acceleration", 500.0), ("10 mm = 5 mm/s2", "acceleration", 5.0)])
def test_the_unit_says_which_scale_is_stated(stated, kind, per_cm):
    ex = parse_exercise(_with_scales(stated))
    got = {"velocity": ex.velocity_per_cm, "acceleration": ex.acceleration_per_cm}
    assert got[kind] == pytest.approx(per_cm, rel=1e-12)          # mm (per s, per s²) per cm
    assert ex.mechanism.scale is None and sum(v is not None for v in got.values()) == 1


def test_a_scale_stated_over_several_centimetres_reads_back_as_stated():
    ex = parse_exercise(_with_scale("7 cm = 500 mm"))
    fig = draw_kinematic_diagram(assemble(ex.mechanism))
    texts = [t.text for t in fig.items if hasattr(t, "text")]
    assert "Scale 7 cm = 500 mm" in texts and "500 mm" in texts
    # The bar is the seven stated centimetres, alternately filled.
    cells = [it for it in fig.items if getattr(it, "style", "") in ("scale", "scale_fill")]
    xs = [x for it in cells for x, _ in it.points]
    assert len(cells) == 7 and max(xs) - min(xs) == pytest.approx(70.0)


@pytest.mark.parametrize("bad, says", [
    ('"1 cm = 50 mm/s", "2 cm = 1 cm/s"', "scale states the velocity scale twice"),
    ("4", "scale must read like"), ('"1 cm = 50 mm/h"', "scale must read like")])
def test_a_bad_scale_list_is_named_at_its_line(bad, says):
    text = four_bar_toml() + f'\n[ask]\nfind = ["omega4"]\nscale = [{bad}]\n'
    with pytest.raises(InputError, match=rf"ex.toml:\d+: \[ask.scale\] {says}"):
        parse_exercise(text.replace("scale = [4]", "scale = 4"), "ex.toml")


def test_a_stated_velocity_scale_sets_the_vectors_drawn_by_centres():
    # With the space scale also stated, the drawing's paper mm per world metre is
    # 10 / (S u) and a vector's is 10 / (V u) per m/s: the vector scale is S / V seconds.
    ex = parse_exercise(_with_scales("1 cm = 40 mm", "1 cm = 20 mm/s"))
    sol = solve_exercise(ex)
    assert sol.work.scales.vector == pytest.approx(40.0 / 20.0, rel=1e-12)
    answers = [a for a in sol.answers if a.figures and a.figures[0].velocity_scale]
    shown = Slice(sol.assembly, tuple(a.refs[-1] for a in answers))
    fig = draw_scene(shown, velocity_scale=sol.work.scales.vector)
    assert "Velocity scale 1 cm = 20 mm/s" in [t.text for t in fig.items if hasattr(t, "text")]


def test_a_stated_velocity_scale_draws_the_polygon_true_to_it():
    ex = parse_exercise(_with_scales("1 cm = 20 mm/s", methods='["polygon"]'))
    sol = solve_exercise(ex)
    vp = sol.velocity_polygon
    fig = draw_polygon_panel(Slice(vp.construction, ("vp:o_v", "vp:tip:B", "vp:V:B")),
                             panel=Panel.VELOCITY, scale=vp.scale, units=ex.mechanism.units,
                             title="V_B", per_cm=ex.velocity_per_cm)
    assert "Velocity scale 1 cm = 20 mm/s" in [t.text for t in fig.items if hasattr(t, "text")]
    shaft = next(p for p in fig.items if getattr(p, "style", "") == "vector_result")
    head = next(p for p in fig.items if getattr(p, "style", "") == "arrowhead")
    speed = math.hypot(*solver.point_velocity(sol.kinematics, ex.mechanism, 3, "B")) * 1000
    assert math.dist(shaft.points[0], head.points[0]) == pytest.approx(10.0 * speed / 20.0,
                                                                        rel=1e-9)


@pytest.mark.slow
def test_the_crank_shaper_is_drawn_at_the_projects_scales(files):
    # 003 steps 3 and 7: 3 cm of polygon for V_A = 18 cm/s, 7 cm of drawing for 500 mm.
    for stem in ("worked-theta2-90", "V_B-radius-rotation-theta2-90"):
        svg = files("crank-shaper")[f"{stem}.svg"]
        assert "Scale 7 cm = 500 mm" in svg and "Velocity scale 3 cm = 18 cm/s" in svg
