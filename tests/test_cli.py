"""Tests for exercises.cli: outputs, one-line errors with exit code 1, nothing half-written.

Errors are checked as sqlite-utils does: the exact ``Error: …\\n`` on stderr, nothing
on stdout, exit code 1 (2 for a usage error). ``catch_exceptions=False`` lets any
exception other than click's own exit escape, so a traceback fails the test rather
than passing as "exit code 1".
"""

import importlib.abc
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest
from click.testing import CliRunner

from tarsim.graphics.export import RenderError
from tarsim.exercises.cli import cli
from tests.common import four_bar_toml
from tarsim.graphics import atomic_files, export

FOUR_BAR = four_bar_toml(coupler=150, angle=180)
# At θ2 = 180° A is at (−100, 0): |O4A| = 400 mm > AB + O4B = 150 + 200 mm.
UNREACHABLE = ("link 3 (AB = 150 mm) cannot reach the circle of B about O4 at "
               "θ2 = 180°: |O4A| = 400 mm > 150 mm + 200 mm\n")


def unreachable(path) -> str:
    """The one line for FOUR_BAR's link 3, led by the line of its [[link]] table."""
    return f"Error: {path}:10: {UNREACHABLE}"

MAGIC = {"svg": b"<svg", "pdf": b"%PDF", "png": b"\x89PNG\r\n\x1a\n"}


def run(*args):
    return CliRunner().invoke(cli, [str(a) for a in args], prog_name="tarsim",
                              catch_exceptions=False)


def assert_one_line_error(result, start: str = "Error: ") -> str:
    assert result.exit_code == 1, result.output
    assert result.stdout == ""
    err = result.stderr
    assert err.startswith(start), err
    assert err.endswith("\n") and err.count("\n") == 1, err
    assert "Traceback" not in err
    return err


@pytest.fixture
def mech_file(tmp_path):
    """Write a mechanism file into tmp_path: FOUR_BAR with ``(old, new)`` edits."""
    def write(*edits, name="mech.toml"):
        text = FOUR_BAR
        for old, new in edits:
            assert text.count(old) == 1, old
            text = text.replace(old, new)
        path = tmp_path / name
        path.write_text(text, encoding="utf-8")
        return path
    return write


def listing(folder):
    return sorted(p.name for p in folder.iterdir())


# ----- draw -----------------------------------------------------------------------------
@pytest.mark.parametrize("fmt", ["svg", "pdf", "png"])
def test_draw_writes_the_figure(tmp_path, fmt):
    out = tmp_path / f"four-bar.{fmt}"
    result = run("draw", "four-bar", "-o", out)
    assert (result.exit_code, result.stdout, result.stderr) == (0, f"wrote {out}\n", "")
    assert out.read_bytes().startswith(MAGIC[fmt])
    assert listing(tmp_path) == [out.name]  # no temporary file left beside it


def test_draw_reads_a_file_and_takes_the_angle_option(mech_file, tmp_path):
    path = mech_file(("angle = 180", "angle = 0"))
    out = tmp_path / "fig.svg"
    assert run("draw", path, "-o", out).exit_code == 0
    first = out.read_bytes()
    assert run("draw", path, "-o", out, "--angle", "90").exit_code == 0
    assert out.read_bytes() != first
    assert "θ₂ = 90°" in out.read_text(encoding="utf-8")


def test_written_figure_honours_the_umask(tmp_path):
    # Like any file the user writes: rw for all less the umask, not mkstemp's 0600.
    out = tmp_path / "fig.svg"
    umask = os.umask(0o022)
    try:
        assert run("draw", "four-bar", "-o", out).exit_code == 0
    finally:
        os.umask(umask)
    assert oct(out.stat().st_mode & 0o777) == oct(0o644)


# ----- errors: one line, exit 1, no traceback -----------------------------------------------
def test_unreachable_position_names_the_dyad(mech_file, tmp_path):
    path = mech_file()
    out = tmp_path / "fig.svg"
    assert assert_one_line_error(run("draw", path, "-o", out)) == unreachable(path)
    assert assert_one_line_error(run("check", path)) == unreachable(path)
    assert not out.exists()


def test_unreachable_position_via_the_angle_option(mech_file):
    path = mech_file(("angle = 180", "angle = 60"))
    assert run("check", path).exit_code == 0
    assert assert_one_line_error(run("check", path, "--angle", "180")) == unreachable(path)


@pytest.mark.parametrize("edit, message", [
    (("O4 = [300, 0]", "O4 = [300; 0]"), "{f}:3:10: not valid TOML: "),
    (("AB = 150", "AB = -150"), "{f}:13: [link 3, AB] length AB of link 3 must be a positive "
                                "length, got -150"),
    (("O4B = 200", "O4B = 0"), "{f}:18: [link 4, O4B] length O4B of link 4 must be a positive "
                               "length, got 0"),
    (("link = 2", "link = 5"),
     "{f}:21: [input.link] unknown link '5'; expected one of: 1, 2, 3, 4"),
    (("link = 2", "# link = 2"), "{f}:20: [input] "),
    (('B = "left"', 'C = "left"'), "{f}:25: [assembly.C] unknown point 'C'; "
                                   "expected one of: A, B, O2, O4"),
    (('B = "left"', 'Bb = "left"'), "{f}:25: [assembly.Bb] unknown point 'Bb'; did you mean 'B'?"),
    (("[input]", '[[link]]\nnumber = 5\npoints = ["B", "C"]\nlengths = { BC = 100 }\n[input]'),
     "{f}:24: [input] the mechanism has 2 degrees of freedom"),
])
def test_bad_file_is_one_line_with_file_and_line(mech_file, tmp_path, edit, message):
    path = mech_file(edit)
    for args in (("draw", path, "-o", tmp_path / "fig.svg"), ("check", path)):
        assert_one_line_error(run(*args), "Error: " + message.format(f=path))
    assert listing(tmp_path) == ["mech.toml"]


@pytest.mark.parametrize("source, message", [
    ("four-barr",
     "Error: no file or bundled example called 'four-barr'; did you mean 'four-bar'?\n"),
    ("nothing-like-it", "Error: no file or bundled example called 'nothing-like-it'; bundled: "
                        "crank-pin-speed, crank-shaper, four-bar, grashof-crank-rocker, "
                        "grashof-double-crank, "
                        "hinkle-four-bar, hinkle-slider-crank, inverted-slider-crank, "
                        "klein-slider-crank, offset-slider-crank, parallelogram-four-bar, "
                        "piston-driven-slider-crank, rolling-wheel, six-link-homework-1, "
                        "six-link-homework-3, slotted-lever-p37, velocity-homework-292, "
                        "wheel-driven-slider, wheel-round-circle, whitworth, "
                        "crank-shaper-forces, crank-shaper-inertia, "
                        "double-acting-engine, engine-forces, "
                        "engine-friction, engine-gas-pressure, "
                        "four-bar-coupler-load, four-bar-forces, car-differential, "
                        "compound-equal-steps, compound-train, "
                        "differential-near-equal, gearbox-power-efficiency, "
                        "involute-pair, output-speed-given, planetary-q1, planetary-q2, "
                        "planetary-q3, planetary-q4, planetary-ratio-least-teeth, "
                        "ratio-least-teeth, ratio-only, reverted-train-design, "
                        "reverted-two-modules, shafts-about-circular-pitch, shafts-apart, "
                        "sun-and-planet, "
                        "teeth-implied, two-planets-listed, two-speeds-arm-and-sun, "
                        "base-circle-for-pressure-angle, circular-arc-flat-face, "
                        "eccentric-flat-face, knife-edge-acceleration-ratio, "
                        "offset-knife-edge, "
                        "oscillating-roller, roller-harmonic-cycloidal, tangent-cam-roller, "
                        "valve-unequal-acceleration, bearing-forces, coupled-locomotive, "
                        "four-mass-shaft, "
                        "four-masses-one-plane, inline-four, inline-three, locomotive, "
                        "notes-example-1, outside-locomotive, primary-balance-unknowns, "
                        "radial-three, "
                        "single-cylinder-balance-mass, "
                        "single-cylinder, static-balance-couple-left, "
                        "three-masses-between, two-stroke-four, unknown-angles, "
                        "unknown-plane-and-angle, unknown-planes, v-twin, weights-one-plane, "
                        "engine-harmonic-torque, flywheel-between-speeds, "
                        "four-stroke-triangles, "
                        "petrol-engine-areas, punch-sheared-area, punching-press, "
                        "single-cylinder-table, steam-engine-energy-coefficient, "
                        "three-cylinder-triangles, rod-equivalent-masses\n"),
    ("missing.toml", "Error: no such file 'missing.toml'\n"),
])
def test_unknown_source_is_one_line(source, message):
    assert assert_one_line_error(run("check", source)) == message


def test_missing_option_is_a_usage_error():
    result = run("draw", "four-bar")
    assert result.exit_code == 2
    assert "Error: Missing option '-o' / '--output'." in result.stderr


# ----- failing draws leave nothing behind ---------------------------------------------------
@pytest.mark.parametrize("name, message", [
    ("fig.txt", "Error: cannot write 'fig.txt': the name must end in .svg, .pdf, .png\n"),
    ("fig", "Error: cannot write 'fig': the name must end in .svg, .pdf, .png\n"),
])
def test_unknown_suffix_writes_nothing(tmp_path, monkeypatch, name, message):
    monkeypatch.chdir(tmp_path)
    assert assert_one_line_error(run("draw", "four-bar", "-o", name)) == message
    assert listing(tmp_path) == []


def test_missing_folder_writes_nothing(tmp_path):
    out = tmp_path / "no" / "such" / "fig.svg"
    err = assert_one_line_error(run("draw", "four-bar", "-o", out))
    assert err == f"Error: cannot write '{out}': the folder '{out.parent}' does not exist\n"
    assert listing(tmp_path) == []


def test_failing_draw_keeps_the_previous_figure(mech_file, tmp_path):
    out = tmp_path / "fig.svg"
    out.write_text("the figure from last time", encoding="utf-8")
    assert_one_line_error(run("draw", mech_file(), "-o", out))
    assert out.read_text(encoding="utf-8") == "the figure from last time"
    assert listing(tmp_path) == ["fig.svg", "mech.toml"]


def test_failure_while_writing_removes_the_temporary_file(tmp_path, monkeypatch):
    def refuse(src, dst):
        raise PermissionError(13, "Permission denied")
    monkeypatch.setattr(atomic_files.os, "replace", refuse)
    out = tmp_path / "fig.svg"
    err = assert_one_line_error(run("draw", "four-bar", "-o", out))
    assert err == f"Error: cannot write '{out}': Permission denied\n"
    assert listing(tmp_path) == []


# ----- no libcairo ----------------------------------------------------------------------------
class _NoCairo(importlib.abc.MetaPathFinder):
    """Make ``import cairosvg`` fail as it does when cffi cannot dlopen libcairo2."""

    def find_spec(self, name, path=None, target=None):
        if name.split(".")[0] in ("cairosvg", "cairocffi"):
            raise OSError("no library called \"cairo-2\" was found")
        return None


@pytest.fixture(params=["ImportError", "OSError"])
def no_cairo(request, monkeypatch):
    """Hide cairo: cairosvg and cairocffi not installed (ImportError), or installed without
    libcairo (OSError)."""
    for mod in list(sys.modules):
        if mod.split(".")[0] in ("cairosvg", "cairocffi"):
            monkeypatch.delitem(sys.modules, mod)
    if request.param == "ImportError":
        monkeypatch.setitem(sys.modules, "cairosvg", None)
        monkeypatch.setitem(sys.modules, "cairocffi", None)
    else:
        monkeypatch.setattr(sys, "meta_path", [_NoCairo(), *sys.meta_path])
    return request.param


def test_svg_to_without_cairo_raises_render_error(no_cairo):
    with pytest.raises(RenderError) as info:
        export.svg_to("<svg/>", "pdf")
    assert str(info.value) == export._NO_CAIRO
    assert "libcairo2" in str(info.value) and "\n" not in str(info.value)


@pytest.mark.parametrize("fmt", ["pdf", "png"])
def test_draw_without_cairo_is_one_line_and_svg_still_works(tmp_path, no_cairo, fmt):
    out = tmp_path / f"fig.{fmt}"
    err = assert_one_line_error(run("draw", "four-bar", "-o", out))
    assert err == ("Error: PDF and PNG output need the cairo library (libcairo2), which is not "
                   "installed: install it (Debian/Ubuntu: apt-get install libcairo2) or write "
                   ".svg instead\n")
    assert listing(tmp_path) == []
    svg = tmp_path / "fig.svg"
    assert run("draw", "four-bar", "-o", svg).exit_code == 0
    assert svg.read_bytes().startswith(b"<svg")


# ----- check and list -------------------------------------------------------------------------
def test_check_four_bar_agrees_with_the_analytic_solution():
    result = run("check", "four-bar")
    assert result.exit_code == 0 and result.stderr == ""
    out = result.stdout
    assert "DOF = 1" in out
    assert "Grashof: crank-rocker" in out
    xy = r"\(([-\d.]+), ([-\d.]+)\)"
    row = re.compile(rf"^(\S+)\s+{xy}\s+{xy}\s+(\S+)\s+(\S+)$", re.M)
    rows = {m.group(1): m.groups()[1:] for m in row.finditer(out)}
    assert sorted(rows) == ["A", "B", "O2", "O4"]
    for name, (*_, rel, cond) in rows.items():
        assert float(rel) < 1e-12, name
        assert 0.0 < float(cond) <= 1.0, name
    # peers.md §4: A = 100 mm at 60°, so (50, 86.602540) mm, printed to 6 decimals.
    assert rows["A"][:2] == ("50.000000", "86.602540")


def test_list_shows_the_bundled_examples():
    result = run("list")
    assert result.exit_code == 0
    ids = [line.split()[0] for line in result.stdout.splitlines() if not line.startswith(" ")]
    assert ids == ["crank-pin-speed", "crank-shaper", "four-bar", "grashof-crank-rocker",
                   "grashof-double-crank",
                   "hinkle-four-bar", "hinkle-slider-crank", "inverted-slider-crank",
                   "klein-slider-crank", "offset-slider-crank", "parallelogram-four-bar",
                   "piston-driven-slider-crank", "rolling-wheel", "six-link-homework-1",
                   "six-link-homework-3", "slotted-lever-p37", "velocity-homework-292",
                   "wheel-driven-slider", "wheel-round-circle", "whitworth",
                   "crank-shaper-forces", "crank-shaper-inertia",
                   "double-acting-engine", "engine-forces",
                   "engine-friction", "engine-gas-pressure",
                   "four-bar-coupler-load", "four-bar-forces", "car-differential",
                   "compound-equal-steps", "compound-train",
                   "differential-near-equal", "gearbox-power-efficiency", "involute-pair",
                   "output-speed-given", "planetary-q1", "planetary-q2", "planetary-q3",
                   "planetary-q4", "planetary-ratio-least-teeth", "ratio-least-teeth",
                   "ratio-only", "reverted-train-design", "reverted-two-modules",
                   "shafts-about-circular-pitch", "shafts-apart",
                   "sun-and-planet",
                   "teeth-implied",
                   "two-planets-listed", "two-speeds-arm-and-sun",
                   "base-circle-for-pressure-angle", "circular-arc-flat-face",
                   "eccentric-flat-face", "knife-edge-acceleration-ratio", "offset-knife-edge",
                   "oscillating-roller", "roller-harmonic-cycloidal", "tangent-cam-roller",
                   "valve-unequal-acceleration", "bearing-forces", "coupled-locomotive",
                   "four-mass-shaft",
                   "four-masses-one-plane", "inline-four", "inline-three", "locomotive",
                   "notes-example-1", "outside-locomotive", "primary-balance-unknowns",
                   "radial-three",
                   "single-cylinder-balance-mass",
                   "single-cylinder", "static-balance-couple-left",
                   "three-masses-between", "two-stroke-four", "unknown-angles",
                   "unknown-plane-and-angle", "unknown-planes", "v-twin",
                   "weights-one-plane",
                   "engine-harmonic-torque", "flywheel-between-speeds", "four-stroke-triangles",
                   "petrol-engine-areas", "punch-sheared-area", "punching-press",
                   "single-cylinder-table", "steam-engine-energy-coefficient",
                   "three-cylinder-triangles", "rod-equivalent-masses"]
    assert "Four-bar crank-rocker" in result.stdout


# ----- help --------------------------------------------------------------------------------------
@pytest.mark.parametrize("command", [[], *([name] for name in sorted(cli.commands))])
def test_every_command_has_help_with_an_example(command):
    result = run(*command, "--help")
    assert result.exit_code == 0
    text = result.stdout
    assert text.startswith(f"Usage: {' '.join(['tarsim', *command])} [OPTIONS]")
    summary = text.split("\n")[2].strip()
    assert summary.endswith(".") and len(summary) > 20, text
    block = re.search(r"^  Example:\n((?:    \S.*\n)+)", text, re.M)
    assert block, text
    for line in block.group(1).splitlines():
        assert (line.strip() + " ").startswith(" ".join(["tarsim", *command]) + " "), line


# ----- the real entry point -------------------------------------------------------------------
def test_installed_tarsim_prints_no_traceback(mech_file, tmp_path):
    exe = shutil.which("tarsim")
    assert exe is not None, "tarsim is not on PATH (pip install -e .)"
    out = tmp_path / "fig.pdf"
    proc = subprocess.run([exe, "draw", str(mech_file()), "-o", str(out)],
                          capture_output=True, text=True, encoding="utf-8", timeout=120)
    assert proc.returncode == 1
    assert proc.stdout == ""
    assert proc.stderr == unreachable(mech_file())
    assert not out.exists()


def test_solve_prints_each_answer_with_its_unit_sense_and_check(tmp_path):
    # peers.md §4 four-bar at θ2 = 60°, ω2 = 10 rad/s ccw: ω3 = −2.57846 (cw), ω4 = 2.91596
    # (ccw), |V_B| = O4B·|ω4| = 200 mm × 2.91596 = 583.192 mm/s (the analytic solver agrees).
    result = run("solve", "four-bar", "-o", tmp_path / "out", "--no-pdf")
    assert result.exit_code == 0, result.output
    lines = result.output.splitlines()
    assert any(line.startswith("ω3 = −2.57846 rad/s (cw) ") and "check ok" in line
               for line in lines)
    assert any(line.startswith("ω4 = 2.91596 rad/s (ccw) ") for line in lines)
    by_method = [line for line in lines if line.startswith("V_B = 583.192 mm/s at −172.4°")]
    assert [line.split("   ")[-1] for line in by_method] == ["radius rotation", "parallel lines",
                                                              "components"]


def test_check_prints_a_true_minus():
    result = run("check", "crank-shaper", "--angle", "-44.072")
    assert result.exit_code == 0, result.output
    assert "θ2 = −44.072°" in result.output
    table = result.output.split("cond.\n")[1].split("largest")[0].splitlines()
    assert "(0.000000, −500.000000)" in table[1]                   # O4
    assert not any("-" in line[:67] for line in table)      # coordinates, before the errors


@pytest.mark.parametrize("edit, line, message", [
    # AB = 150 mm cannot reach: the [[link]] table of link 3 (line 10).
    (dict(coupler=150, angle=180), 10, "link 3 (AB = 150 mm) cannot reach"),
    # No [assembly]: the first [[link]] that lists B, link 3's (line 10).
    (dict(branch=None), 10, "point B has two positions"),
    # Crank, coupler and rocker in line (100 + 200 + 200 = 300 + 200): the input's angle.
    (dict(coupler=200, angle=180), 23, "dead point at input angle 180°"),
])
def test_an_assembly_error_names_its_file_and_line(tmp_path, edit, line, message):
    path = tmp_path / "m.toml"
    path.write_text(four_bar_toml(**edit).replace("[input]\n", "[input]\nomega = 1\n"),
                    encoding="utf-8")
    assert path.read_text().splitlines()[line - 1].startswith(("[[link]]", "angle ="))
    result = run("solve", path, "-o", tmp_path / "out", "--no-pdf")
    text = assert_one_line_error(result)
    assert text.startswith(f"Error: {path}:{line}: {message}")


def test_verbose_says_the_error_an_error_arose_from(tmp_path):
    # O2A = 100 and O2O4 = 50 keep A at least 50 mm from O4, beyond AB + O4B = 20 mm: the
    # mobility is refused in one line, and --verbose tells why on a second, from the first
    # angle tried (θ2 = 0°, where A and O4 are 100 − 50 = 50 mm apart).
    path = Path(__file__).parent / "data" / "edge" / "assembles-nowhere.toml"
    line = (f"Error: {path}: the mechanism assembles at none of 12 input angles spread over a "
            "turn of link 2, so it has no mobility to count\n")
    assert assert_one_line_error(run("solve", path, "-o", tmp_path / "s")) == line
    told = run("--verbose", "solve", path, "-o", tmp_path / "s")
    assert told.exit_code == 1 and not (tmp_path / "s").exists()
    assert told.stderr == line + ("  link 3 with AB = 10 mm and link 4 with O4B = 10 mm cannot "
                                  "reach B: A and O4 are 50 mm apart (short by 30 mm) at "
                                  "input angle 0°\n")
