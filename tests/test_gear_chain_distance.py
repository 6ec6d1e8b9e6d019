"""The distance between a simple train's end gears, as the books ask it: "A and D, their
centres in one straight line" is the pairs' distances added along the idlers."""

import json
import math
from fractions import Fraction
from pathlib import Path

import pytest
from click.testing import CliRunner

from tarsim.exercises.cli import cli

HERE = Path(__file__).parent / "reproducers"


def _solved(path: Path, tmp_path: Path) -> dict:
    out = tmp_path / "out"
    run = CliRunner().invoke(cli, ["solve", str(path), "-o", str(out), "--no-pdf"])
    assert run.exit_code == 0, run.output
    return json.loads((out / "results.json").read_text(encoding="utf-8"))["quantities"]


def test_g1_simple_idlers(tmp_path):
    q = _solved(HERE / "g1-simple-idlers.toml", tmp_path)
    # m/2·(N_A + 2N_B + 2N_C + N_D) = 2.5·(20 + 80 + 60 + 50) mm: exact in fractions
    assert q["centre_distance1_4"]["exact"] == "21/40"
    assert q["centre_distance1_4"]["reference"]["exact"] == "21/40"
    assert q["centre_distance1_4"]["method"] == "the pairs' distances added"
    assert Fraction(q["omega4/omega1"]["exact"]) == Fraction(-20, 50)


def _train(tmp_path, gears: str, meshes: str, find: str) -> Path:
    path = tmp_path / "t.toml"
    path.write_text(f'name = "t"\n[units]\nspeed = "rpm"\nlength = "mm"\n{gears}{meshes}'
                    f'[input]\nmember = 1\nspeed = 100\n[ask]\nfind = [{find}]\n',
                    encoding="utf-8")
    return path


def _gear(n: int, teeth: int, size: str) -> str:
    return f"[[gear]]\nnumber = {n}\nteeth = {teeth}\n{size}\n"


@pytest.mark.parametrize("teeth", [(17, 43, 29), (20, 20, 80), (31, 12, 97)])
def test_a_circular_pitch_chain_is_its_pitch_diameters_over_pi(tmp_path, teeth):
    gears = "".join(_gear(n, t, "circular_pitch = 12") for n, t in enumerate(teeth, 1))
    path = _train(tmp_path, gears, "[[mesh]]\ngears = [1, 2]\n[[mesh]]\ngears = [2, 3]\n",
                  '"centre_distance1_3"')
    q = _solved(path, tmp_path)["centre_distance1_3"]
    # r = N·p/(2π) for each: N1/2 + N2 + N3/2 pitches over π (mm → m)
    want = 12e-3 * (teeth[0] / 2 + teeth[1] + teeth[2] / 2) / math.pi
    assert q["value"] == pytest.approx(want, rel=1e-15)


def test_gears_not_joined_through_idlers_are_refused_naming_the_pairs(tmp_path):
    gears = "".join(_gear(n, t, "module = 2") for n, t in [(1, 20), (2, 40), (3, 15), (4, 45)])
    shafts = "[[shaft]]\nmembers = [2, 3]\n"      # a compound pair: no one line to lay out
    path = _train(tmp_path, gears + shafts, "[[mesh]]\ngears = [1, 2]\n[[mesh]]\ngears = [3, 4]\n",
                  '"omega4", "centre_distance1_4"')
    run = CliRunner().invoke(cli, ["solve", str(path), "-o", str(tmp_path / "o")])
    assert run.exit_code == 1
    assert "cannot find 'centre_distance1_4'" in run.output
    assert "centre_distance1_2, centre_distance3_4" in run.output
    assert len(run.output.strip().splitlines()) == 1
