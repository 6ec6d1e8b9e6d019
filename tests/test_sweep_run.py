"""A sweep as the command runs it: with loads, the turning moment is solved with it, said
after it and checked by the balance of power, which shares no joint force with it."""

from __future__ import annotations

import pytest

from tarsim.constructions.errors import CheckMismatch
from tarsim.exercises.catalog import load
from tarsim.exercises.forces.turning_moment import POWER_AGREE
from tarsim.exercises.linkages.sweep_run import SWEEP_AGREE, run_sweep


def test_a_sweep_with_loads_checks_its_driving_torque_by_the_balance_of_power():
    run = run_sweep(load("four-bar-coupler-load"), 24)
    # both torques round alike, near 1e-16 of the greatest (POWER_AGREE's note)
    assert run.moment.power_miss <= POWER_AGREE
    assert run.lines()[-1].startswith("driving torque by the balance of power agrees")
    assert "turning-moment.csv" in run.files() and "sweep.csv" in run.files()
    run.check()
    run.moment.power_miss = 10 * POWER_AGREE
    with pytest.raises(CheckMismatch, match="^the driving torque by the balance of power "
                                            "disagree"):
        run.check()


def test_a_sweep_without_loads_has_no_turning_moment_and_checks_its_positions():
    run = run_sweep(load("four-bar"), 24)
    assert run.moment is None and not any("turning" in name for name in run.files())
    assert run.sweep.checks and all(c.rel_error <= SWEEP_AGREE for c in run.sweep.checks)
    run.check()
