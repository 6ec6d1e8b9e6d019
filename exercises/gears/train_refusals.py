"""The gear trains a solve refuses before it writes anything: one whose tooth ratios carry a
speed beyond what a float holds, and a ratio or a torque asked of a member the train holds
still though it is not fixed.

The tabular method and the Willis system find such speeds exactly (as fractions), so the
refusal is of what the files could not write or what has no meaning, not of the method.
"""

from __future__ import annotations

from fractions import Fraction

from tarsim.constructions.errors import InputError

from .train_file import TrainExercise

__all__ = ["refuse_beyond_floats", "refuse_still_ratios"]

_FASTEST = 100
"""No member turns faster than 1e100 of the file's unit, nor (turning) slower than 1e-100:
beyond, a speed or a ratio of two leaves what a float holds (1e±308)."""


def refuse_beyond_floats(train, speeds: dict[int, Fraction]) -> None:
    """Refuse a train whose tooth ratios carry a speed beyond :data:`_FASTEST`'s range (a
    chain of many stages of 100000 teeth to 1)."""
    for m, w in speeds.items():
        if w and not -_FASTEST <= _exponent(w) <= _FASTEST:
            raise InputError(f"{train.label(m)} would turn about 1e{_exponent(w):+d} "
                             f"{train.units.speed}: the tooth ratios carry its speed beyond "
                             f"1e±{_FASTEST}; no train turns so, check the teeth",
                             file=train.source or None)


def _exponent(x: Fraction) -> int:
    """The power of ten of ``x``'s size, from its digits (it may be beyond a float)."""
    x = abs(x)
    e = len(str(x.numerator)) - len(str(x.denominator))
    return e if x >= Fraction(10) ** e else e - 1


def refuse_still_ratios(ex: TrainExercise, *speeds: dict[int, Fraction]) -> None:
    """Refuse a ratio asked over a member that stands still, though not fixed (a reverted
    train whose tooth products are equal holds its output still), and a torque or power
    asked of such a member as the output (it takes no power, so the balance gives none);
    a member given at rest holds the train, as a fixed one does, and ΣT = 0 gives its."""
    train = ex.train
    for q in ex.asks:
        parts = q.split("/")
        if len(parts) == 2 and parts[1].startswith("omega"):
            m = ex.member(int(parts[1].removeprefix("omega")))
            if any(s[m] == 0 for s in speeds):
                raise InputError(f"{q} divides by the speed of {train.label(m)}, which stands "
                                 "still in this train; ask a ratio over a turning member",
                                 file=train.source or None)
        if q.startswith(("torque", "power")):
            m = int(q.removeprefix("torque").removeprefix("power"))
            held = (train.input_member, train.fixed, train.second and train.second[0])
            if m not in held and any(s[m] == 0 for s in speeds):
                raise InputError(f"{q} is asked of {train.label(m)}, which stands still in "
                                 "this train and takes no power: ask it of a turning member",
                                 file=train.source or None)
