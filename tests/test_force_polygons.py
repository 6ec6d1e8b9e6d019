"""The force polygons, drawn link by link with the inertia loads read off the acceleration
polygon, against every link's Newton–Euler equations and against closed forms.

- The engine (the bundled engine-forces) and the loaded four-bar: every joint force and
  the driving torque as constructed, beside the analytic system: a few roundings of the
  largest force (the checks' own tolerance, from the drawing's conditioning).
- With only a piston mass and a gas force, the rod is a two-force member, and the driving
  torque is the textbook's F_P·r·sin(θ + φ)/cos φ.
- The image g′ of each centre of mass gives the solver's a_G.
"""

from __future__ import annotations

import math
from pathlib import Path

import pytest
from click.testing import CliRunner

import tarsim
from tarsim.constructions.errors import InputError, TarsimError
from tarsim.constructions.forces.polygons import drawn_forces
from tarsim.constructions.reference import solver
from tarsim.exercises.catalog import bundled
from tarsim.exercises.cli import cli
from tarsim.exercises.linkages.exercise_file import load_exercise, parse_exercise

FORCES = {name: Path(path) for name, path in bundled("forces").items()}


@pytest.mark.parametrize("name", ["engine-forces", "four-bar-forces"])
def test_every_force_drawn_is_the_newton_euler_one(name):
    worked = tarsim.solve(load_exercise(FORCES[name]))
    assert worked.passed
    (sol,) = worked.positions
    asked = {q for q in sol.quantities}
    assert {"F_12", "F_23", "F_34", "F_14", "T2"} <= asked
    for q in sol.quantities.values():
        assert q.rel_error <= 1e-13, (q.name, q.rel_error)


@pytest.mark.parametrize("deg", [30, 75, 140, 250])
def test_the_engines_efforts_are_the_textbooks(deg):
    """Only the piston's 1.2 kg and 5 kN of gas, no weight: the piston effort toward the
    crank is F_P = F_gas + m·ẍ_P (the gas less the piston's inertia), the wall's thrust
    F_P·tan φ, the force along the rod F_P/cos φ, the crank effort F_P·sin(θ + φ)/cos φ,
    the turning moment that times r, and the driving torque holds it."""
    text = (FORCES["engine-forces"]).read_text(encoding="utf-8")
    text = text.replace("angle = 40", f"angle = {deg}").replace("gravity = true",
                                                                  "gravity = false")
    cut = text.index("[[mass]]")
    text = text[:cut] + "[[mass]]\nlink = 4\nmass = 1.2\ncentre = \"P\"\ninertia = 1e-3\n" + \
        text[text.index("[[force]]"):]
    ex = parse_exercise(text, "engine.toml")
    (sol,) = tarsim.solve(ex).positions
    kin = solver.solve(ex.mechanism)
    th, r, rod = math.radians(deg), 0.060, 0.240
    phi = math.asin(r * math.sin(th) / rod)
    f_p = 5000.0 + 1.2 * kin.accelerations["P"][0]
    f_t = f_p * math.sin(th + phi) / math.cos(phi)
    got = {name: q.value["value"] for name, q in sol.quantities.items()}
    assert got["piston_effort"] == pytest.approx(f_p, rel=1e-12)
    assert got["wall_thrust"] == pytest.approx(abs(f_p * math.tan(phi)), rel=1e-12)
    assert got["crank_effort"] == pytest.approx(f_t, rel=1e-12)
    assert got["turning_moment"] == pytest.approx(f_t * r, rel=1e-12)
    assert got["T2"] == pytest.approx(-f_t * r, rel=1e-12)


def test_the_image_of_each_centre_gives_the_solvers_acceleration():
    ex = load_exercise(FORCES["four-bar-forces"])
    worked = tarsim.solve(ex)
    (sol,) = worked.positions
    forces = drawn_forces(sol.work)
    kin = sol.work.kinematics
    for m in ex.loads.masses:
        o, a = kin.origins[m.link], kin.angles[m.link]
        g = (o[0] + math.cos(a) * m.centre[0] - math.sin(a) * m.centre[1],
             o[1] + math.sin(a) * m.centre[0] + math.cos(a) * m.centre[1])
        a_g = solver.point_acceleration(kin, ex.mechanism, m.link, g)
        force, couple = forces.inertia[m.link]
        assert force == pytest.approx((-m.mass * a_g[0], -m.mass * a_g[1]), rel=1e-12)
        assert couple == pytest.approx(-m.inertia * kin.alphas[m.link], rel=1e-12)


def test_forces_asked_without_loads_are_refused_at_the_ask():
    text = (FORCES["four-bar-forces"]).read_text(encoding="utf-8")
    text = text[:text.index("[forces]")]
    with pytest.raises(InputError, match=r"fb.toml:\d+: \[ask.find\] forces are asked, but "
                                         "the file gives no loads"):
        parse_exercise(text, "fb.toml")


def test_a_mechanism_the_polygons_do_not_cover_is_refused_in_one_line(tmp_path):
    """A six-bar's forces are asked: refused in one line at its ask, naming what is drawn."""
    from tarsim.exercises.catalog import bundled

    text = Path(bundled()["six-link-homework-1"]).read_text(encoding="utf-8")
    text = text.replace("find = [", 'find = ["T2", ', 1) + (
        "\n[[couple]]\nlink = 4\nmoment = 1\n")
    path = tmp_path / "six.toml"
    path.write_text(text, encoding="utf-8")
    result = CliRunner().invoke(cli, ["solve", str(path), "-o", str(tmp_path / "o"),
                                      "--no-pdf"])
    assert result.exit_code == 1, result.output
    line = result.output.strip()
    assert line.startswith(f"Error: {path}:") and "[ask.find] cannot find 'T2'" in line, line
    assert "the force polygons draw a four-bar, a slider-crank or a slotted lever" in line
    assert "\n" not in line and len(line) - len(str(path)) < 200, line


def test_solve_writes_the_force_polygons_and_their_steps(tmp_path):
    out = tmp_path / "f"
    result = CliRunner().invoke(cli, ["solve", str(FORCES["engine-forces"]), "-o",
                                      str(out), "--no-pdf"])
    assert result.exit_code == 0, result.output
    assert "T2 = −64.9688 N·m (cw)" in result.output
    assert (out / "forces.svg").exists()
    steps = (out / "steps.md").read_text(encoding="utf-8")
    assert "link 3's moments about P give it" in steps
    assert "the driving torque T2 = -64.9688 N·m" in steps


def test_the_course_projects_crank_shaper_by_its_force_polygons():
    """003 §9's crank-shaper: at θ2 = 90° (the cutting stroke) 1000 N against the ram, held
    by the slot at B (F_45 = 1000 N) and by the crank, T2 = −1000 N × 232.941 mm/s / 1 rad/s;
    at t = 2.34 s (the return: no cut) the torque from 4 on 3 is I3·α4 = 3.32e-4 N·m and
    the slot's push on the ram's pin 0.0567 N, the project's orders of magnitude."""
    worked = tarsim.solve(load_exercise(FORCES["crank-shaper-forces"]))
    assert worked.passed
    cut, back = worked.positions
    assert cut.quantities["F_45"].value["value"] == pytest.approx(1000.0, rel=1e-12)
    assert cut.quantities["T2"].value["value"] == pytest.approx(-232.941176, rel=1e-8)
    assert back.quantities["T_43"].value["value"] == pytest.approx(3.31954e-4, rel=1e-5)
    assert back.quantities["F_45"].value["value"] == pytest.approx(0.0566625, rel=1e-5)
    for sol in (cut, back):
        for name, q in sol.quantities.items():
            if name.startswith(("F_", "T")):
                assert q.rel_error <= 1e-13, (name, q.rel_error)


def test_the_cut_adds_its_own_power_to_the_crank_shapers_torque():
    """The project's run once without and once with the cut: the two bundled crank-shapers
    differ only by 1000 N against the ram, so by superposition and the balance of power
    their driving torques differ by F·V_B/ω2, V_B from the analytic velocities. With no cut
    the return at t = 2.34 s is the same in both."""
    cut = tarsim.solve(tarsim.load("crank-shaper-forces")).positions
    bare = tarsim.solve(tarsim.load("crank-shaper-inertia")).positions
    assert all(q.rel_error <= 1e-13 for sol in bare for q in sol.quantities.values())
    sol = cut[0]
    (vx, vy), omega = sol.work.kinematics.velocities["B"], sol.work.mechanism.drive.omega
    # The cut resists the ram's motion: the driver puts in F·|V_B| more, T2·ω2 of it.
    extra = 1000.0 * math.hypot(vx, vy) / omega
    assert cut[0].quantities["T2"].value["value"] - bare[0].quantities["T2"].value["value"] \
        == pytest.approx(extra, rel=1e-12)
    for name, q in bare[1].quantities.items():
        same = cut[1].quantities[name].value
        for key in q.value:
            assert q.value[key] == pytest.approx(same[key], rel=1e-12, abs=1e-15), name


@pytest.mark.parametrize("name", ["engine-forces", "four-bar-forces", "crank-shaper-forces",
                                  "four-bar-coupler-load"])
def test_every_free_body_is_in_balance(name):
    """Each link drawn alone with its loads and the joint forces the polygons found: its
    forces add to nothing and so do their moments, to a few roundings of the largest."""
    worked = tarsim.solve(load_exercise(FORCES[name]))
    for sol in worked.positions:
        bodies = drawn_forces(sol.work).bodies
        biggest = max(math.hypot(*f) for b in bodies.values() for _, f, _, _ in b)
        for link, forces in bodies.items():
            fx = math.fsum(f[0] for _, f, _, _ in forces)
            fy = math.fsum(f[1] for _, f, _, _ in forces)
            m = math.fsum(w[0] * f[1] - w[1] * f[0] + c for w, f, c, _ in forces)
            assert abs(fx) < 1e-12 * biggest and abs(fy) < 1e-12 * biggest, (link, fx, fy)
            assert abs(m) < 1e-12 * biggest, (link, m)


def test_a_piston_effort_asked_of_a_four_bar_is_refused_at_its_line():
    text = FORCES["four-bar-forces"].read_text(encoding="utf-8")
    text = text.replace('find = ["F_12", "F_23", "F_34", "F_14", "T2"]',
                        'find = ["F_12", "piston_effort"]')
    line = text[:text.index('find = ["F_12", "piston_effort"]')].count("\n") + 1
    with pytest.raises(InputError, match=rf"four-bar.toml:{line}: .*cannot find "
                                         r"'piston_effort' for this mechanism"):
        parse_exercise(text, "four-bar.toml")


@pytest.mark.parametrize("name", ["engine-forces", "four-bar-forces"])
def test_the_loads_are_drawn_to_the_force_scale_the_caption_states(name):
    """Every load named on the space diagram is an arrow as long as the stated force scale
    makes it (to the 4 figures its name prints), and each inertia force drawn as one force
    stands h = I·α/(m·a_G) off G, to the side whose moment about G is the couple."""
    from tarsim.graphics.figure import Text
    from tarsim.graphics.forces.loads_figure import _offset

    worked = tarsim.solve(tarsim.load(name))
    fig = worked.figures["loads"]
    (per_cm,) = [float(t.text.split("= ")[1].split(" N")[0]) for t in fig.items
                 if isinstance(t, Text) and t.text.startswith("Force scale 1 cm")]
    named = [t for t in fig.items if isinstance(t, Text) and t.owner and t.tail.endswith(" N")]
    assert len(named) >= 3
    for t in named:
        (a, b) = t.owner
        said = float(t.tail.split("= ")[1][:-2])
        assert math.dist(a, b) / 10.0 * per_cm == pytest.approx(said, rel=1e-3), t.text + t.sub
    (sol,) = worked.positions
    for force, couple in drawn_forces(sol.work).inertia.values():
        d = _offset(force, couple)
        if d is None:
            continue
        assert d[0] * force[1] - d[1] * force[0] == pytest.approx(couple, rel=1e-12)
        assert math.hypot(*d) == pytest.approx(abs(couple) / math.hypot(*force), rel=1e-12)


def test_a_three_force_coupler_is_solved_by_its_forces_meeting_in_one_point():
    """The coupler of four-bar-coupler-load holds P and the pins' forces at A and B; the
    rocker carries nothing, so its pull runs along O4B. The three lines meet at X, drawn
    where P's line crosses O4B: the crank's force runs along AX, and P has no moment
    about X. Every force agrees with the Newton–Euler system."""
    (sol,) = tarsim.solve(tarsim.load("four-bar-coupler-load")).positions
    assert all(q.rel_error <= 1e-13 for q in sol.quantities.values())
    c = sol.work.assembly
    x = c.output("force:cc:X").xy
    at = {n: c.point(n).xy for n in ("A", "B", "O4")}
    forces = drawn_forces(sol.work)
    f23, f34 = forces.joints["F_23"], forces.joints["F_34"]

    def across(u, v):
        return (u[0] * v[1] - u[1] * v[0]) / (math.hypot(*u) * math.hypot(*v))
    assert abs(across(f23, (x[0] - at["A"][0], x[1] - at["A"][1]))) < 1e-12
    assert abs(across(f34, (at["B"][0] - at["O4"][0], at["B"][1] - at["O4"][1]))) < 1e-12
    ((p, force, _, _),) = forces.loads[3]
    moment = (p[0] - x[0]) * force[1] - (p[1] - x[1]) * force[0]
    assert abs(moment) < 1e-12 * math.hypot(*force) * math.dist(p, x)


def test_a_massless_block_makes_the_rod_a_three_force_member():
    """The engine with only its rod's mass and inertia: the piston carries nothing, so the
    guide and the rod push it across the guide along one line through P, the rod's forces
    meet on it, and the guide's couple is nothing. Against the Newton–Euler system."""
    text = FORCES["engine-forces"].read_text(encoding="utf-8")
    keep = text[:text.index("[[mass]]")]
    keep = keep.replace('"piston_effort", ', "")
    text = keep + "[[mass]]\nlink = 3\nmass = 1.0\ninertia = 4.8e-3\n"
    (sol,) = tarsim.solve(parse_exercise(text, "engine.toml")).positions
    assert "force:cc:X" in [s.id for s in sol.work.assembly]
    for name, q in sol.quantities.items():
        assert q.rel_error <= 1e-13, (name, q.rel_error)
    assert sol.quantities["T_14"].value["value"] == 0.0


def _engine_with_friction(deg: float, mu: float) -> str:
    """The bundled engine at ``deg`` with only its 5 kN of gas (massless links, no weight)
    and friction μ at the piston's guide."""
    text = FORCES["engine-forces"].read_text(encoding="utf-8")
    text = text.replace("angle = 40", f"angle = {deg}")
    text = text.replace("gravity = true", f"gravity = false\nfriction = {mu}")
    return text[:text.index("[[mass]]")] + text[text.index("[[force]]"):]


@pytest.mark.parametrize("deg, mu", [(40, 0.1), (130, 0.15), (220, 0.1), (300, 0.3)])
def test_friction_leans_the_guides_push_by_the_friction_angle(deg, mu):
    """With massless links the rod pushes along itself, q·e, and the piston holds
    G + q·e + N·(n − s·μ·v̂) = 0, s the side N comes out on: a 2 × 2 solve, the side
    checked, gives q and T2 = (A − O) × q·e, independently of both the polygon and the
    Newton–Euler system. The guide's push leans atan μ off the normal."""
    ex = parse_exercise(_engine_with_friction(deg, mu), "engine.toml")
    (sol,) = tarsim.solve(ex).positions
    kin = solver.solve(ex.mechanism)
    a, p = kin.points["A"], kin.points["P"]
    e = ((p[0] - a[0]) / math.dist(a, p), (p[1] - a[1]) / math.dist(a, p))
    v = 1.0 if kin.velocities["P"][0] > 0 else -1.0
    for s in (1.0, -1.0):
        u = (-s * mu * v, 1.0)                     # n − s·μ·v̂, the guide along x
        det = e[0] * u[1] - e[1] * u[0]
        q = (5000.0 * u[1]) / det                  # (−5000, 0) + q·e + N·u = 0
        n = -(q * e[1]) / u[1]
        if n * s >= 0:
            break
    torque = a[0] * q * e[1] - a[1] * q * e[0]
    got = {name: q_.value for name, q_ in sol.quantities.items()}
    assert got["T2"]["value"] == pytest.approx(torque, rel=1e-12)
    f14 = got["F_14"]["vector"]
    assert abs(f14[0]) == pytest.approx(mu * abs(f14[1]), rel=1e-12)   # tan φ = μ
    assert f14[0] * v <= 0.0                       # against the sliding
    assert got["wall_thrust"]["value"] == pytest.approx(abs(n), rel=1e-12)
    assert all(q_.rel_error <= 1e-13 for q_ in sol.quantities.values())


def test_the_crank_shapers_slides_lean_with_friction_in_its_polygons():
    """The course project's crank-shaper with μ = 0.1 at its three slides (the ram on its
    guide, its pin and the block in the lever's slot): every force the polygons draw is
    the Newton–Euler one, and each slide's push leans atan μ off its normal, against its
    sliding."""
    text = FORCES["crank-shaper-forces"].read_text(encoding="utf-8")
    ex = parse_exercise(text.replace("gravity = true", "gravity = true\nfriction = 0.1", 1),
                        "shaper.toml")
    for sol in tarsim.solve(ex).positions:
        for name, q in sol.quantities.items():
            if name.startswith(("F_", "T")):
                assert q.rel_error <= 1e-13, (name, q.rel_error)
        kin, joints = sol.work.kinematics, drawn_forces(sol.work).joints
        fastest = max(math.hypot(*v) for v in kin.velocities.values())
        for slide in ex.mechanism.slides:
            (rate,) = [r for r in kin.slide_rates if r.slide is slide]
            f = joints[f"F_{slide.guide_link}{slide.link}"]
            if abs(rate.velocity) <= 1e-9 * fastest:
                # At rest in its slot (the block at θ2 = 90°): friction takes no side.
                along = f[0] * rate.direction[0] + f[1] * rate.direction[1]
                assert abs(along) <= 1e-12 * math.hypot(*f)
                continue
            d = rate.direction
            along, across = f[0] * d[0] + f[1] * d[1], -f[0] * d[1] + f[1] * d[0]
            assert abs(along) == pytest.approx(0.1 * abs(across), rel=1e-9, abs=1e-12)
            assert along * rate.velocity <= 0.0


def test_a_friction_coefficient_out_of_range_is_refused_at_its_line():
    text = _engine_with_friction(40, 3)
    line = text[:text.index("friction = 3")].count("\n") + 1
    with pytest.raises(InputError, match=rf"engine.toml:{line}: .*friction is the "
                                         r"coefficient μ"):
        parse_exercise(text, "engine.toml")


@pytest.mark.parametrize("name", ["engine-forces", "four-bar-forces", "crank-shaper-forces"])
def test_friction_circles_at_the_pins_agree_with_newton_euler(name):
    """With a friction circle at every pin, the polygons drawn by trial until the pins'
    forces settle give what the Newton–Euler system, iterated the same way, gives; and the
    balance of power closes with the pins' dissipation Σ ρ·|F|·|ω_rel|."""
    text = FORCES[name].read_text(encoding="utf-8")
    text = text.replace("gravity = true", "gravity = true\nfriction_circle = 4", 1)
    for sol in tarsim.solve(parse_exercise(text, f"{name}.toml")).positions:
        assert any(s.id == "force:say:circles" for s in sol.work.assembly)
        for q in sol.quantities.values():
            if q.name.startswith(("F_", "T")):
                assert q.rel_error <= 1e-13, (q.name, q.rel_error)


@pytest.mark.parametrize("deg", [35, 120, 250])
def test_a_two_force_rod_runs_tangent_to_both_friction_circles(deg):
    """The engine with massless links and only its gas force: the rod is a two-force
    member, and with friction circles of ρ = 5 mm its force's line touches both: it runs
    ρ from A and ρ from B (the force at each pin with its friction couple is one force,
    moved |M|/|F| = ρ off the pin)."""
    text = _engine_with_friction(deg, 0).replace("friction = 0", "friction_circle = 5")
    ex = parse_exercise(text, "engine.toml")
    (sol,) = tarsim.solve(ex).positions
    forces = drawn_forces(sol.work)
    rod = forces.bodies[3]
    force = next(f for w, f, m, name in rod if name == "F_23")
    a, b = sol.work.kinematics.points["A"], sol.work.kinematics.points["P"]
    # The rod's loads at A: its pin force and the friction couple there, as one line.
    at_a = math.fsum(m for w, f, m, name in rod if name == "Mf_23")
    size = math.hypot(*force)
    assert abs(at_a) == pytest.approx(0.005 * size, rel=1e-12)
    # The line's foot off A, to the side whose moment about A is the couple.
    k = at_a / size ** 2
    foot = (a[0] + k * force[1], a[1] - k * force[0])
    from_b = abs((b[0] - foot[0]) * force[1] - (b[1] - foot[1]) * force[0]) / size
    assert from_b == pytest.approx(0.005, rel=1e-9)
    assert all(q.rel_error <= 1e-13 for q in sol.quantities.values())


def test_a_negative_friction_circle_is_refused_at_its_line():
    text = _engine_with_friction(40, 0).replace("friction = 0", "friction_circle = -2")
    line = text[:text.index("friction_circle = -2")].count("\n") + 1
    with pytest.raises(InputError, match=rf"engine.toml:{line}: friction_circle is the "
                                         r"radius ρ = μ·r"):
        parse_exercise(text, "engine.toml")


def test_friction_circles_too_big_to_settle_are_refused_in_one_line(tmp_path):
    """A friction circle larger than the links would lock the engine everywhere (or let the
    trial settle, now and then, on forces 1e5 times its loads): the solve and the sweep
    each refuse it in one line at its setting, with no traceback and no files."""
    text = FORCES["engine-forces"].read_text(encoding="utf-8").replace(
        "gravity = true", "gravity = true\nfriction_circle = 50000")
    path = tmp_path / "locked.toml"
    path.write_text(text, encoding="utf-8")
    for command, more in (("solve", []), ("sweep", ["--steps", "36"])):
        out = tmp_path / command
        result = CliRunner().invoke(cli, [command, str(path), "-o", str(out), *more])
        assert result.exit_code != 0
        (line,) = result.output.strip().splitlines()
        assert f"{path}:" in line and "a friction circle of 50000 mm is as long as link 2 " \
            "(crank), 60 mm:" in line, line
        assert not out.exists()


# ----- frames, shapes and places the random loads found -----------------------------------------
@pytest.mark.parametrize("branch, sign", [("forward", 1.0), ("backward", -1.0)])
def test_a_point_of_a_block_in_a_swinging_slot_turns_with_the_slot(branch, sign):
    """A force on the block at [10, 0] mm of its own frame, whose +x runs along the slot the
    way the slot runs (toward A's side of O4 forward, away from it backward): it acts at
    A ± 10 mm·(A − O4)/|A − O4|, and the polygons agree with Newton–Euler there."""
    text = FORCES["crank-shaper-inertia"].read_text(encoding="utf-8") + (
        '\n[[force]]\nlink = 3\npoint = [10, 0]\nforce = [0, -500]\nname = "P"\n')
    text = text.replace("[input]", f'[assembly]\nA = "{branch}"\n\n[input]')
    worked = tarsim.solve(parse_exercise(text, "cs.toml", "cs"))
    assert worked.passed
    for pos in worked.positions:
        c = pos.work.assembly
        (ax, ay), (ox, oy) = c.point("A").xy, c.point("O4").xy
        n = math.hypot(ax - ox, ay - oy)
        at = next(w for w, _, _, name in drawn_forces(pos.work).loads[3] if name == "P")
        want = (ax + sign * 0.010 * (ax - ox) / n, ay + sign * 0.010 * (ay - oy) / n)
        assert at == pytest.approx(want, abs=1e-15)


ISOSCELES = """\
name = "an isosceles engine whose piston stays on the crank's pivot"
[units]
length = "mm"
[frame]
O = [0, 0]
[[link]]
number = 2
points = ["O", "A"]
lengths = { OA = 100 }
[[link]]
number = 3
points = ["A", "P"]
lengths = { AP = 100 }
[[link]]
number = 4
points = ["P"]
[[slider]]
link = 4
point = "P"
on = 1
through = "O"
angle = 0
[input]
link = 2
angle = 60
omega = 10
[assembly]
P = [0, 0]
[ask]
find = ["T2", "piston_effort"]
methods = ["polygon"]
[[force]]
link = 4
point = "P"
force = [-1000, 0]
"""


def test_a_piston_on_the_cranks_pivot_has_no_effort_toward_the_crank():
    # Crank = rod = 100 mm, the folded branch: P = O at every angle, so "toward the crank"
    # along the stroke has no sense, and its sign would be the rounding's.
    with pytest.raises(TarsimError) as e:
        tarsim.solve(parse_exercise(ISOSCELES, "iso.toml"))
    message = str(e.value)
    assert "\n" not in message and len(message) < 200, message
    assert message.startswith("piston_effort at θ2 = 60°: the piston P stands level with the "
                              "crank's pivot O along its stroke"), message


def test_a_coupler_point_leaves_the_forces_as_they_were():
    """A point C on the coupler (only a point: nothing acts there) changes no force."""
    plain = tarsim.solve(load_exercise(FORCES["four-bar-forces"]))
    text = FORCES["four-bar-forces"].read_text(encoding="utf-8").replace(
        'points = ["A", "B"]\nlengths = { AB = 250 }',
        'points = ["A", "B", "C"]\nlengths = { AB = 250, AC = 150, BC = 150 }\n'
        'sides = { C = "left" }')
    with_c = tarsim.solve(parse_exercise(text, "fb.toml"))
    assert with_c.passed
    (a,), (b,) = plain.positions, with_c.positions
    for name, q in a.quantities.items():
        assert b.quantities[name].value["value"] == pytest.approx(q.value["value"], rel=1e-12)


def test_a_slotted_lever_may_carry_a_point_of_its_own():
    """An inverted slider-crank's lever O4B with B free (no joint there) is drawn as the
    lever of the crank-shaper is. With only 200 N at B, the driver's power pays B's:
    T2·ω2 = −F·v_B."""
    text = """\
name = "inverted slider-crank"
[units]
length = "mm"
[frame]
O4 = [0, 0]
O2 = [0, 300]
[[link]]
number = 2
points = ["O2", "A"]
lengths = { O2A = 120 }
[[link]]
number = 3
points = ["A"]
[[link]]
number = 4
points = ["O4", "B"]
lengths = { O4B = 500 }
[[slider]]
link = 3
point = "A"
on = 4
[input]
link = 2
angle = 30
omega = 5
[ask]
find = ["F_12", "F_23", "F_43", "T_43", "F_14", "T2"]
methods = ["polygon"]
[forces]
gravity = false
[[force]]
link = 4
point = "B"
force = [-200, 0]
"""
    ex = parse_exercise(text, "inv.toml")
    worked = tarsim.solve(ex)
    assert worked.passed
    (sol,) = worked.positions
    v_b = solver.solve(ex.mechanism).velocities["B"]
    assert sol.quantities["T2"].value["value"] == pytest.approx(-(-200.0 * v_b[0]) / 5.0,
                                                                rel=1e-12)


def test_loads_settings_with_nothing_to_load_are_refused():
    text = FORCES["four-bar-forces"].read_text(encoding="utf-8")
    text = text[:text.index("[[mass]]")]
    with pytest.raises(InputError, match=r"fb.toml:\d+: nothing loads the mechanism"):
        parse_exercise(text, "fb.toml")


MICRO = """\
name = "a nanometre four-bar loaded by a couple alone"
[units]
length = "mm"
angular_velocity = "rpm"
[frame]
O2 = [0.0, 0.0]
O4 = [3.0592382824665125e-23, 4.996115262941892e-07]
[[link]]
number = 2
points = ["O2", "A"]
lengths = { O2A = 5.362072065857125e-06 }
[[link]]
number = 3
points = ["A", "B"]
lengths = { AB = 7.160793437782403e-06 }
[[link]]
number = 4
points = ["O4", "B"]
lengths = { O4B = 3.713609321277906e-06 }
[input]
link = 2
angle = 166.64440073894997
omega = 38.286900621653565
[assembly]
B = [4.089460164529954e-07, -3.1914123623726634e-06]
[ask]
find = ["F_12", "T2"]
methods = ["polygon"]
at = [{ angle = 90.62137551508198 }]
[forces]
gravity = false
[[couple]]
link = 3
moment = -7.98
"""


def test_a_couple_alone_gets_a_force_scale():
    """Loads of a couple alone once gave the polygons a scale of 8e298 drawing metres a
    newton, and a 1e10 N force overflowed them. The couple's power is the driver's:
    T2·ω2 = −M·ω3."""
    ex = parse_exercise(MICRO, "micro.toml")
    (sol,) = tarsim.solve(ex).positions
    kin = solver.solve(sol.assembly.mechanism)
    want = 7.98 * kin.omegas[3] / kin.omegas[2]
    assert sol.quantities["T2"].value["value"] == pytest.approx(want, rel=1e-9)
    assert math.isfinite(sol.quantities["F_12"].value["value"])


def _rod_alone(deg: float, mass: float, inertia: float) -> str:
    """The bundled engine at ``deg`` on a guide turned 30° about O, loaded by its rod alone:
    ``mass`` at the crank pin A and ``inertia`` about it, no weight and no gas."""
    text = FORCES["engine-forces"].read_text(encoding="utf-8")
    text = text.replace("angle = 40", f"angle = {deg}").replace("angle = 0\n", "angle = 30\n")
    text = text.replace("gravity = true", "gravity = false")
    return (text[:text.index("[[mass]]")]
            + f'[[mass]]\nlink = 3\nmass = {mass}\ncentre = "A"\ninertia = {inertia}\n')


def _couple_torque(theta: float, r: float, rod: float, omega: float, inertia: float,
                   offset: float = 0.0) -> float:
    """The driving torque at steady ω that turns a rod of moment of inertia I alone, crank
    ``theta`` from its guide (which runs ``offset`` off the crank's pivot): T = I·ω²·φ′·φ″,
    the rod's angle φ from r·sin θ + l·sin φ = offset, cos φ·φ′ = −(r/l)·cos θ and
    cos φ·φ″ = (r/l)·sin θ + sin φ·φ′²."""
    lam = r / rod
    phi = math.asin((offset - r * math.sin(theta)) / rod)
    d1 = -lam * math.cos(theta) / math.cos(phi)
    d2 = (lam * math.sin(theta) + math.sin(phi) * d1 * d1) / math.cos(phi)
    return inertia * omega * omega * d1 * d2


@pytest.mark.parametrize("mass", [1e-6, 1.0])
@pytest.mark.parametrize("deg", [40, 75, 140, 250])
def test_a_rods_couple_that_dwarfs_its_force_is_split_not_met_in_one_point(deg, mass):
    """A rod of 1e6 kg·m² on a guide at 30°, its mass at the crank pin: its inertia couple
    throws the line of its one equivalent force 1e12 m (mass 1e-6 kg) or 1e6 m (1 kg) off,
    so the three-force construction's AX all but runs with the guide's normal through B and
    the forces are lost to X's rounding (it missed by 1e-9 of T2, or was refused as beyond
    vouching). The split along and across AB draws them; T2 = I·ω²·φ′·φ″ (the mass at A
    keeps its speed r·ω), to the few roundings its lines, crossing at over 75°, allow."""
    (sol,) = tarsim.solve(parse_exercise(_rod_alone(deg, mass, 1e6), "engine.toml")).positions
    assert "force:cc:X" not in [s.id for s in sol.work.assembly]
    want = _couple_torque(math.radians(deg - 30), 0.060, 0.240, 200.0, 1e6)
    assert sol.quantities["T2"].value["value"] == pytest.approx(want, rel=1e-13)


def test_a_rod_of_ordinary_inertia_is_still_a_three_force_member():
    """The same rod of 4.8e-3 kg·m² and 1 kg: its one force stands 3.3 mm off A, X within
    the mechanism's reach, and the course's three-force construction draws it."""
    (sol,) = tarsim.solve(parse_exercise(_rod_alone(40, 1.0, 4.8e-3), "engine.toml")).positions
    assert "force:cc:X" in [s.id for s in sol.work.assembly]
    want = _couple_torque(math.radians(10), 0.060, 0.240, 200.0, 4.8e-3)
    assert sol.quantities["T2"].value["value"] == pytest.approx(want, rel=1e-13)


NANO = Path(__file__).parent / "data" / "nanometre-slider-crank-couple.toml"


def test_a_nanometre_slider_crank_at_1e25_rpm_draws_its_torque_right():
    """tests/data/nanometre-slider-crank-couple.toml: a crank of 0.999e-6 mm, a rod of 1e-6
    mm at 77° to its guide, 1e25 rpm. The three-force construction met at X 130 m off and
    printed T2 = −2.89636e41 N·m "check ok", 3.3e-5 off the truth (its check's scale, the
    loads' inertia couples over a link times its size, was 16 times T2). The rod's inertia
    couple makes all but 4e-13 of T2 (the rest: its 3.8 kg moving 1e-9 m, the gas force
    and the load torque), so I·ω²·φ′·φ″ holds it to 1e-11; the Newton–Euler system to
    1e-12 of T2 itself."""
    (sol,) = tarsim.solve(tarsim.load(str(NANO))).positions
    mm, gamma = 1e-3, -2.9134897197607037
    n = (-math.sin(gamma), math.cos(gamma))            # the guide's normal
    through = (5.930301337045002e-07 * mm, 1.3766790057475362e-07 * mm)
    offset = through[0] * n[0] + through[1] * n[1] - 7.901964746079631e-10 * mm
    want = _couple_torque(math.pi / 2 - gamma, 9.989999999999999e-07 * mm, 1e-06 * mm,
                          1e25 * math.tau / 60, 1e-6, offset)
    q = sol.quantities["T2"]
    assert q.value["value"] == pytest.approx(want, rel=1e-11)
    assert q.value["value"] == pytest.approx(q.reference["value"], rel=1e-12)
