"""A flywheel file's [units] is read in one place, whatever gives its diagram: length and
speed, and a [punch]'s motor's power; any other unit is refused at its line, the same way."""

from __future__ import annotations

import pytest

from tarsim.constructions.errors import InputError
from tarsim.exercises.forces.flywheel_file import parse_flywheel

DIAGRAMS = {
    "formula": '[turning_moment]\ntorque = "100 + 50*sin(2*theta)"\n',
    "table": "[resisting_torque]\npoints = [[0, 600], [60, 600], [60, 0], [360, 0]]\n",
    "areas": "[turning_moment]\nareas = [10, -10]\nenergy_scale = 1\n",
    "engine and machine": '[turning_moment]\ntorque = "100 + 50*sin(2*theta)"\n'
                          '[resisting_torque]\ntorque = "100 + 20*sin(theta)"\n',
}
WHEEL = "[flywheel]\nspeed = 100\nspeed_fluctuation = 0.02\n"


@pytest.mark.parametrize("diagram", DIAGRAMS)
@pytest.mark.parametrize("unit", ['power = "kW"', 'torque = "kN·m"'])
def test_a_unit_it_would_not_read_is_refused_at_its_line(diagram, unit):
    """Every diagram refuses a power unit (a punch's alone) and a torque unit, at line 3 (the
    unit's own), with the one message naming what [units] takes."""
    text = f'[units]\nspeed = "rpm"\n{unit}\n{DIAGRAMS[diagram]}{WHEEL}'
    with pytest.raises(InputError) as e:
        parse_flywheel(text, "f.toml")
    message = str(e.value)
    assert message.startswith("f.toml:3:") and "\n" not in message
    assert "[units] takes length, speed and, for a [punch]'s motor, power" in message


@pytest.mark.parametrize("diagram", DIAGRAMS)
def test_length_and_speed_units_are_read(diagram):
    """rpm is read as such for every diagram: 100 rpm is 100·2π/60 rad/s."""
    ex = parse_flywheel(f'[units]\nspeed = "rpm"\nlength = "mm"\n{DIAGRAMS[diagram]}{WHEEL}')
    assert ex.speed == pytest.approx(100 * 2 * 3.141592653589793 / 60, rel=1e-15)
    assert (ex.length_unit, ex.speed_unit) == ("mm", "rpm")
