"""`tarsim new KIND`: each starting file is written as asked, solves as it stands, and its
answers are the closed forms of its own data (so a template that drifts from what its
comments say fails here)."""

import json
import math

import pytest
from click.testing import CliRunner

from tarsim.exercises.cli import cli
from tarsim.exercises.templates import KINDS

RPM = 2 * math.pi / 60


def _solved(tmp_path, kind):
    """results.json's quantities (SI) for ``kind``'s starting file, written and solved by
    the command line."""
    runner = CliRunner()
    path = tmp_path / f"my-{kind}.toml"
    made = runner.invoke(cli, ["new", kind, "-o", str(path)])
    assert made.exit_code == 0, made.output
    out = tmp_path / "out"
    run = runner.invoke(cli, ["solve", str(path), "-o", str(out), "--no-pdf"])
    assert run.exit_code == 0, run.output            # 3 would be a failed check
    results = json.loads((out / "results.json").read_text(encoding="utf-8"))
    found = results["quantities"] or results["positions"][0]["quantities"]
    return {k: v["value"] for k, v in found.items() if "value" in v}


def test_every_kind_has_a_file_and_a_closed_form_below():
    assert set(KINDS) == {"linkage", "train", "cam", "rotor", "engine", "loads", "flywheel",
                          "class", "rod"}


def test_linkage_template_is_the_four_bar_of_its_comments(tmp_path):
    # O2A 100, AB 250, O4B 200, O2O4 300 mm, θ2 60°, ω2 10 rad/s, B left of A → O4.
    q = _solved(tmp_path, "linkage")
    a = 100 * complex(math.cos(math.radians(60)), math.sin(math.radians(60)))
    o4 = complex(300, 0)
    d = abs(o4 - a)
    along = (250**2 - 200**2 + d**2) / (2 * d)
    u = (o4 - a) / d
    b = a + u * (along + 1j * math.sqrt(250**2 - along**2))      # left of A → O4
    # ω2 × O2A + ω3 × AB = ω4 × O4B, in complex form: i(ω2 a + ω3 (b − a) − ω4 (b − o4)) = 0
    m = [[-(b - a).imag, (b - o4).imag], [(b - a).real, -(b - o4).real]]
    r = [10 * a.imag, -10 * a.real]
    det = m[0][0] * m[1][1] - m[0][1] * m[1][0]
    w3 = (r[0] * m[1][1] - m[0][1] * r[1]) / det
    w4 = (m[0][0] * r[1] - r[0] * m[1][0]) / det
    # Well conditioned (the transmission angle is far from 0°): agreement to 1e-9.
    assert q["omega3"] == pytest.approx(w3, rel=1e-9)
    assert q["omega4"] == pytest.approx(w4, rel=1e-9)
    assert q["V_B"] == pytest.approx(abs(w4) * 0.200, rel=1e-9)


def test_train_template_gives_the_arm_and_planet_by_willis(tmp_path):
    q = _solved(tmp_path, "train")
    sun, planet, ring, w_sun = 40, 30, 100, -1000 * RPM          # the sun 1000 rpm cw
    arm = w_sun * sun / (sun + ring)                              # the ring held
    assert q["omega3"] == pytest.approx(arm, rel=1e-12)           # exact fractions, then SI
    assert q["omega4"] == pytest.approx(arm - sun / planet * (w_sun - arm), rel=1e-12)


def test_cam_template_peaks_are_those_of_its_laws(tmp_path):
    q = _solved(tmp_path, "cam")
    w, h = 300 * RPM, 0.030
    rise, ret = math.radians(120), math.radians(90)
    # Simple harmonic: v = π h ω / 2β, a = π² h ω² / 2β²; cycloidal: 2hω/β, 2π h ω²/β².
    assert q["v_max_1"] == pytest.approx(math.pi * h * w / (2 * rise), rel=1e-9)
    assert q["a_max_1"] == pytest.approx(math.pi**2 * h * w**2 / (2 * rise**2), rel=1e-9)
    assert q["v_max_3"] == pytest.approx(2 * h * w / ret, rel=1e-9)
    assert q["a_max_3"] == pytest.approx(2 * math.pi * h * w**2 / ret**2, rel=1e-9)


def test_rotor_template_balance_mass_closes_the_force_polygon(tmp_path):
    q = _solved(tmp_path, "rotor")
    unbalance = sum(m * r * complex(math.cos(math.radians(t)), math.sin(math.radians(t)))
                    for m, r, t in [(10, 0.100, 0), (8, 0.120, 90), (6, 0.150, 210)])
    assert q["mass_B"] == pytest.approx(abs(unbalance) / 0.100, rel=1e-12)


def test_engine_template_balance_mass_and_force_left(tmp_path):
    q = _solved(tmp_path, "engine")
    c, m_rec, m_rev, r, w = 0.5, 30, 15, 0.100, 600 * RPM
    assert q["balance_mass"] == pytest.approx((m_rev + c * m_rec) * r / 0.120, rel=1e-12)
    theta = math.radians(45)                  # along: (1 − c)·cos θ, across: c·sin θ
    left = m_rec * r * w**2 * math.hypot((1 - c) * math.cos(theta), c * math.sin(theta))
    assert q["unbalanced_resultant"] == pytest.approx(left, rel=1e-12)


def test_loads_template_turning_moment_is_the_gas_load_through_the_rod(tmp_path):
    q = _solved(tmp_path, "loads")
    force = 0.5e6 * math.pi * 0.120**2 / 4                     # p on the bore
    r, rod, theta = 0.100, 0.400, math.radians(30)
    phi = math.asin(r * math.sin(theta) / rod)
    # T = F r sin(θ + φ)/cos φ (no masses, no friction): well conditioned, 1e-9.
    assert q["piston_effort"] == pytest.approx(force, rel=1e-12)
    assert q["turning_moment"] == pytest.approx(force * r * math.sin(theta + phi)
                                                / math.cos(phi), rel=1e-9)


def test_flywheel_template_energy_and_inertia(tmp_path):
    q = _solved(tmp_path, "flywheel")
    w, c_s = 300 * RPM, 0.02
    delta_e = 8000            # T − T_mean = 8000 sin 2θ: one lobe's area, ∫ 8000 sin 2θ dθ
    # ΔE is integrated numerically over the cycle: held to the step's 1e-5.
    assert q["delta_E"] == pytest.approx(delta_e, rel=1e-5)
    assert q["inertia"] == pytest.approx(delta_e / (w**2 * c_s), rel=1e-5)
    assert q["rim_mass"] == pytest.approx(delta_e / (w**2 * c_s) / 0.8**2, rel=1e-5)


def test_new_refuses_to_replace_a_file_without_force(tmp_path):
    path = tmp_path / "mine.toml"
    path.write_text("kept", encoding="utf-8")
    runner = CliRunner()
    refused = runner.invoke(cli, ["new", "cam", "-o", str(path)])
    assert refused.exit_code == 1
    assert "exists already" in refused.output and "Traceback" not in refused.output
    assert path.read_text(encoding="utf-8") == "kept"
    assert runner.invoke(cli, ["new", "cam", "-o", str(path), "--force"]).exit_code == 0
    assert path.read_text(encoding="utf-8").startswith("# A cam")


def test_new_to_the_terminal_prints_the_file():
    shown = CliRunner().invoke(cli, ["new", "rotor", "-o", "-"])
    assert shown.exit_code == 0 and "[[balance]]" in shown.output


# The class's drawings are five of the grading corpus's (tests/data/grading/class), each
# with the verdicts its key gives for the slips it was drawn with.
_CLASS = {"ali.svg": "inkscape/inkscape-001.svg", "sara.svg": "libreoffice/libreoffice-012.svg",
          "reza.svg": "cad/cad-024.svg", "maryam.svg": "geogebra/geogebra-006.svg",
          "nima.svg": "hand/hand-003.svg"}


@pytest.mark.slow
def test_the_class_grades_as_its_drawings_were_drawn(tmp_path):
    from pathlib import Path
    data = Path(__file__).parent / "data" / "grading" / "class"
    key = json.loads((data / "key.json").read_text(encoding="utf-8"))["files"]
    runner = CliRunner()
    made = runner.invoke(cli, ["new", "class", "-o", str(tmp_path / "class")])
    assert made.exit_code == 0, made.output
    assert sorted(p.name for p in (tmp_path / "class").iterdir()) == sorted(_CLASS)
    for name, source in _CLASS.items():   # the very files the key describes
        assert (tmp_path / "class" / name).read_bytes() == (data / source).read_bytes()
    graded = runner.invoke(cli, ["grade", "crank-shaper", str(tmp_path / "class"),
                                 "--position", "2", "-o", str(tmp_path / "graded")])
    assert graded.exit_code == 0, graded.output
    for name, source in _CLASS.items():
        grade = json.loads((tmp_path / "graded" / Path(name).stem / "grade.json")
                           .read_text(encoding="utf-8"))
        verdicts = {item["name"]: item["verdict"] for item in grade["items"]}
        expected = key[source]["items"]
        assert {k: verdicts.get(k) for k in expected} == expected, name


def test_the_class_is_a_folder_not_a_page(tmp_path):
    runner = CliRunner()
    result = runner.invoke(cli, ["new", "class", "-o", "-"])
    assert result.exit_code == 1 and "give -o FOLDER" in result.output
    (tmp_path / "class").mkdir()
    (tmp_path / "class" / "mine.svg").write_text("<svg/>")
    again = runner.invoke(cli, ["new", "class", "-o", str(tmp_path / "class")])
    assert again.exit_code == 1 and "holds files already" in again.output


def test_rod_template_is_the_books_rod_of_its_comments(tmp_path):
    # 2 kg, 250 mm between the pins, G 100 mm from P, k = 110 mm, α = 23000 rad/s² cw:
    # l2 = k²/l1 = 121 mm, m·l2/(l1 + l2) at P, (m·l1·l3 − m·k²)·α = 133.4 N·m cw. A few
    # products and quotients of decimals: agreement to 1e-12.
    q = _solved(tmp_path, "rod")
    assert q["l2"] == pytest.approx(0.121, rel=1e-12)
    assert q["mass_at_P"] == pytest.approx(2 * 121 / 221, rel=1e-12)
    assert q["correction_couple"] == pytest.approx(-133.4, rel=1e-12)
