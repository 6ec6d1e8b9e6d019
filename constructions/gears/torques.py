"""Torques on a gear train by the balance of power and of torques (no losses).

The input's torque (or power over its speed) drives; with nothing lost, the output takes
T_out = −T_in·ω_in/ω_out, and since the torques on the whole train sum to zero the fixed
member is held by −(T_in + T_out). Exact where the input's torque is given; through the
speed in rad/s (so through π) where its power is.
"""

from __future__ import annotations

from fractions import Fraction

from ..narration import Phrase, phrase, significant
from .tabular import fraction_text
from .train import GearTrain

__all__ = ["balance", "say_balance"]


def balance(train: GearTrain, speeds: dict[int, Fraction], output: int | None
            ) -> dict[int, Fraction]:
    """The torques (N·m, CCW-positive) on the input, ``output`` and the fixed member; none
    without the input's torque or power, the input's alone without an output (or with one
    that stands still, which takes no power)."""
    if train.input_torque is None and train.input_power is None:
        return {}
    w_in = speeds[train.input_member]
    if train.input_torque is not None:
        t_in = train.input_torque if w_in > 0 else -train.input_torque
    else:
        t_in = Fraction(float(train.input_power) / (float(w_in) * train.units.per_rad_s))
    if output is None or speeds[output] == 0:
        return {train.input_member: t_in}
    t_out = -t_in * w_in / speeds[output]
    found = {train.input_member: t_in, output: t_out}
    if train.fixed is not None:
        found[train.fixed] = -(t_in + t_out)
    return found


def say_balance(train: GearTrain, speeds: dict[int, Fraction], output: int | None
                ) -> list[Phrase]:
    """The steps of :func:`balance`, with the numbers."""
    torques = balance(train, speeds, output)
    if output not in torques:
        return []
    i, o, w = train.input_member, output, speeds
    given = (f"T{i} = {float(train.input_torque):g} N·m" if train.input_torque is not None
             else f"T{i} = P/ω{i} = {float(train.input_power):g} W / "
                  f"{float(w[i]) * train.units.per_rad_s:.6g} rad/s")
    out = [phrase("gears.power", given=given, i=i, o=o, ratio=fraction_text(w[i] / w[o]),
                  value=significant(float(torques[o])))]
    if train.fixed is not None:
        out.append(phrase("gears.holding", fixed=train.fixed, i=i, o=o,
                          value=significant(float(torques[train.fixed]))))
    return out
