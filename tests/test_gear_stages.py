"""A train of two arms (a two-stage epicyclic, as the books print it) is refused in one line
that says how it is solved: a stage a file, the first stage's output the second's input."""

from pathlib import Path

from click.testing import CliRunner

from tarsim.exercises.cli import cli

HERE = Path(__file__).parent / "reproducers"


def test_g4_two_stage_arms_attempt(tmp_path):
    out = tmp_path / "out"
    run = CliRunner().invoke(cli, ["solve", str(HERE / "g4-two-stage-arms-attempt.toml"),
                                   "-o", str(out)])
    assert run.exit_code == 1
    lines = run.output.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("Error: ")
    assert "g4-two-stage-arms-attempt.toml:23:" in lines[0]      # the first [[arm]]
    assert "one arm" in lines[0] and "a stage a file" in lines[0]
    assert not out.exists()
