"""A sweep as ``tarsim sweep`` makes it: the output's curves over a revolution, checked at
the positions solved by construction, and, for a file with loads, the turning-moment
diagram and its flywheel (:mod:`..forces.turning_moment`).

:func:`run_sweep` is the command's one call; what it gives writes its files, says its lines
for the terminal and raises if a constructed value leaves its curve.
"""

from __future__ import annotations

from collections.abc import Callable
from contextlib import AbstractContextManager
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from tarsim.constructions.errors import CheckMismatch

from .exercise_file import Exercise
from .sweep import Sweep, sweep_exercise
from .sweep_files import format_sweep, sweep_to_files, write_sweep

__all__ = ["SweepRun", "run_sweep", "SWEEP_AGREE"]

SWEEP_AGREE = 1e-9
"""The relative distance from its curve within which a constructed value agrees: the
construction and the curve's solver round alike at every position the bundled exercises
sweep (1e-16 to 1e-14), so anything near this is a wrong number, not rounding."""

Bar = Callable[[int, str], AbstractContextManager]
"""A progress bar of a length and a label, whose ``update(n)`` counts steps done (click's)."""


@dataclass
class SweepRun:
    """A sweep, and the turning moment of a file with loads."""

    sweep: Sweep
    moment: Any = None
    """The :class:`~..forces.turning_moment.TurningMoment`, when the file has loads."""

    def files(self, *, pdf: bool = False) -> dict[str, str | bytes]:
        """Every file, in memory: the curves and their tables, the turning moment's."""
        files = sweep_to_files(self.sweep, pdf=pdf)
        if self.moment is not None:
            from ..forces.turning_moment import moment_files

            files |= moment_files(self.moment, pdf=pdf)
        return files

    def write(self, folder: str | Path, *, pdf: bool = False) -> list[Path]:
        """Write every file into ``folder``, all or nothing (see :func:`write_sweep`)."""
        return write_sweep(self.files(pdf=pdf), folder)

    def lines(self) -> list[str]:
        """What the terminal shows: the sweep's report, then the turning moment's."""
        out = format_sweep(self.sweep).split("\n")
        return out + (self.moment.lines() if self.moment is not None else [])

    def check(self) -> None:
        """Raise :class:`CheckMismatch` naming each value off its curve, and the driving
        torque if the balance of power disagrees with it."""
        from ..forces.turning_moment import POWER_AGREE

        apart = [f"{c.key} at {c.position}" for c in self.sweep.checks
                 if not c.rel_error <= SWEEP_AGREE]
        if self.moment is not None and not self.moment.power_miss <= POWER_AGREE:
            apart.append("the driving torque by the balance of power")
        if apart:
            raise CheckMismatch(list(dict.fromkeys(apart)))


def run_sweep(ex: Exercise, steps: int = 360, *, of: str | None = None,
              bar: Bar | None = None) -> SweepRun:
    """Sweep ``ex`` over ``steps`` equal steps of a revolution (:func:`sweep_exercise`),
    and solve its forces round the turn if it has loads, each counted on a ``bar`` if
    given.

    Raises
    ------
    TarsimError
        As :func:`sweep_exercise` and :func:`~..forces.turning_moment.turning_moment` do.
    """
    sweep = _counted(bar, steps, "sweeping",
                     lambda progress: sweep_exercise(ex, steps, of=of, progress=progress))
    if ex.loads is None:
        return SweepRun(sweep)
    from ..forces.turning_moment import turning_moment

    return SweepRun(sweep, _counted(bar, steps, "forces",
                                    lambda progress: turning_moment(ex, steps, progress=progress)))


def _counted(bar: Bar | None, length: int, label: str, run: Callable[[Any], Any]) -> Any:
    """``run(progress)``, counting on a bar of ``length`` called ``label`` if there is one."""
    if bar is None:
        return run(None)
    with bar(length, label) as shown:
        return run(shown.update)
