"""A frame guide laid "through the extreme positions of Q", as the books lay a shaper's ram
line: through = { extremes = "Q" } places it where the lever's limit positions put Q."""

import json
import math
from pathlib import Path

import pytest
from click.testing import CliRunner

from tarsim.constructions.errors import InputError
from tarsim.exercises.linkages.mechanism_file import load_mechanism

HERE = Path(__file__).parent / "reproducers"


def test_l3_ram_line_extremes(tmp_path):
    """O 240 mm above C, OP 120, CQ 450, QR 150: the lever swings ±30° from the vertical
    (sin = OP/OC = 1/2), so Q's extremes stand CQ·cos 30° = 389.711 mm above C, and the ram
    line through them carries the stroke 2·CQ·sin 30° = 450 mm."""
    from tarsim.exercises.cli import cli
    path = HERE / "l3-ram-line-extremes.toml"
    mech = load_mechanism(path)
    (ram,) = [s for s in mech.slides if s.guide_link == 1]
    # the limit positions are bisected to the last bit: the height to a few ulps of CQ
    assert ram.through[1] == pytest.approx(0.450 * math.cos(math.pi / 6), abs=1e-12)
    assert ram.direction == pytest.approx((1.0, 0.0))
    run = CliRunner().invoke(cli, ["solve", str(path), "-o", str(tmp_path / "o"), "--no-pdf"])
    assert run.exit_code == 0, run.output
    results = json.loads((tmp_path / "o" / "results.json").read_text())
    assert results["quantities"]["stroke"]["value"] == pytest.approx(0.450, rel=1e-12)


def test_a_guide_at_another_angle_than_the_extremes_is_refused(tmp_path):
    text = (HERE / "l3-ram-line-extremes.toml").read_text(encoding="utf-8")
    bad = tmp_path / "l3.toml"
    bad.write_text(text.replace("angle = 0\n\n[input]", "angle = 10\n\n[input]"),
                   encoding="utf-8")
    with pytest.raises(InputError, match=r"l3.toml:\d+: .*extreme positions of Q lie on a line "
                                         r"at 0° from \+x"):
        load_mechanism(bad)


def test_extremes_of_a_point_the_file_has_not_are_refused(tmp_path):
    text = (HERE / "l3-ram-line-extremes.toml").read_text(encoding="utf-8")
    bad = tmp_path / "l3.toml"
    bad.write_text(text.replace('{ extremes = "Q" }', '{ extremes = "Z" }'), encoding="utf-8")
    with pytest.raises(InputError, match=r"needs a point Z of a moving link"):
        load_mechanism(bad)
