"""Torques on a gear train by the balance of torques and of power, with an efficiency.

The input's torque (or its power over its speed) drives. Three members take torque from
outside: the input i, the output o and the holder h (the fixed member, or, with two given
speeds, the second given member). They sum to zero, T_i + T_o + T_h = 0, and so do their
powers but for the losses, η·T_i·ω_i + T_o·ω_o + T_h·ω_h = 0. So

    T_o = T_i·(ω_h − η·ω_i)/(ω_o − ω_h),   T_h = −(T_i + T_o),

which with the holder fixed (ω_h = 0) is the books' T_o = −η·T_i·ω_i/ω_o.

Every torque is exact: a fraction of the data's decimals where the input's torque is given,
or where its power is and speeds are in rad/s; with the power and speeds in rpm,
T_i = P/(2π·n/60) = (30·P/n)/π, and every torque is a fraction of the data over π
(:func:`per_pi`): its coefficient is kept, never a float's binary fraction.
"""

from __future__ import annotations

import math
from fractions import Fraction

from ..narration import Phrase, phrase, significant
from .tabular import fraction_text
from .train import GearTrain

__all__ = ["balance", "say_balance", "per_pi", "torque_text", "holder", "power_at",
           "power_text", "say_powers", "implied_output"]

_DIGITS = 16
"""The most digits (numerator and denominator) a torque's fraction is said with."""


def per_pi(train: GearTrain) -> bool:
    """True where the torques are fractions over π: a power given, speeds in rpm."""
    return train.input_power is not None and train.units.speed == "rpm"


def holder(train: GearTrain) -> int | None:
    """The member that holds the train against the input and the output: the fixed one,
    or the second given speed's member."""
    return train.fixed if train.second is None else train.second[0]


def implied_output(train: GearTrain) -> int | None:
    """The output a holding torque asked alone implies: the one body besides the input's
    and the holder's that the arm does not carry (the arm, where the books ask "the torque
    to hold the annulus"), named by the arm or its first member; None if there are more."""
    h = holder(train)
    ends = [body for body in train.bodies if not train.carried(body[0])
            and train.input_member not in body and (h is None or h not in body)]
    if len(ends) != 1:
        return None
    return train.arm if train.arm in ends[0] else ends[0][0]


def input_torque(train: GearTrain, speeds: dict[int, Fraction]) -> Fraction | None:
    """The input's torque (N·m, its sense the input's); over π where :func:`per_pi`."""
    if train.input_torque is None and train.input_power is None:
        return None
    w_in = speeds[train.input_member]
    if train.input_torque is not None:
        return train.input_torque if w_in > 0 else -train.input_torque
    # P = T·ω, ω in rad/s: 2π·n/60 for n in rpm, so T = (30·P/n)/π
    return train.input_power * (30 if per_pi(train) else 1) / w_in


def balance(train: GearTrain, speeds: dict[int, Fraction], output: int | None
            ) -> dict[int, Fraction]:
    """The torques (N·m, CCW-positive; coefficients of 1/π where :func:`per_pi`) on the
    input, ``output`` and the holder; none without the input's torque or power, the
    input's alone without an output (or with one that stands still, which takes no
    power)."""
    t_in = input_torque(train, speeds)
    if t_in is None:
        return {}
    i, h = train.input_member, holder(train)
    if output is None or speeds[output] == 0:
        return {i: t_in}
    w_h = speeds[h] if h is not None else Fraction(0)
    t_out = t_in * (w_h - train.efficiency * speeds[i]) / (speeds[output] - w_h)
    found = {i: t_in, output: t_out}
    if h is not None:
        found[h] = -(t_in + t_out)
    return found


def power_at(train: GearTrain, torque: Fraction, speed: Fraction) -> tuple[Fraction, bool]:
    """The power (W) that flows through a member, |T·ω|, exact: (P, True) for P·π.

    ``torque`` is :func:`balance`'s (over π where :func:`per_pi`) and ``speed`` in the
    file's unit. With speeds in rpm, ω = 2π·n/60: against a torque over π the π cancels,
    P = T·n/30 (the books' η·P_in, a fraction of the data); against a torque given in N·m
    it stays, P = (T·n/30)·π.
    """
    if train.units.speed != "rpm":
        return abs(torque * speed), False
    return abs(torque * speed) / 30, not per_pi(train)


def power_text(value: Fraction, times_pi: bool) -> str:
    """A power as the steps say it, in W: "7125", "500π = 1570.8"."""
    if not times_pi:
        return torque_text(value, False)
    exact = ("π" if value == 1 else f"{fraction_text(value)}π" if value.denominator == 1
             else f"({fraction_text(value)})π")
    return f"{exact} = {significant(float(value) * math.pi)}"


def torque_text(value: Fraction, over_pi: bool) -> str:
    """A torque as the steps say it: "−150", "4500/π", "−3/(7π)"; with its float where it
    is not whole, and the float alone where the fraction runs past :data:`_DIGITS` digits
    (a power written to 16 figures: results.json keeps the fraction)."""
    shown = float(value) / (math.pi if over_pi else 1.0)
    if len(str(value.numerator).lstrip("-")) + len(str(value.denominator)) > _DIGITS:
        return significant(shown)
    exact = fraction_text(value)
    if over_pi:
        exact = (f"{fraction_text(value.numerator)}/π" if value.denominator == 1 else
                 f"{fraction_text(value.numerator)}/({value.denominator}π)")
    elif value.denominator == 1:
        return exact
    return f"{exact} = {significant(shown)}"


def say_balance(train: GearTrain, speeds: dict[int, Fraction], output: int | None
                ) -> list[Phrase]:
    """The steps of :func:`balance`, with the numbers."""
    torques = balance(train, speeds, output)
    if output not in torques:
        return []
    i, o, h, w, eta = train.input_member, output, holder(train), speeds, train.efficiency
    said_eta = significant(float(eta))           # as the data writes it: 0.95
    pi = per_pi(train)
    if train.input_torque is not None:
        given = f"T{i} = {fraction_text(train.input_torque)} N·m"
    else:
        rad = "(2π/60)·" if pi else ""
        given = (f"P = {fraction_text(train.input_power)} W, T{i} = P/ω{i} = "
                 f"{fraction_text(train.input_power)}/({rad}{fraction_text(abs(w[i]))}) = "
                 f"{torque_text(abs(torques[i]), pi)} N·m")
    value = torque_text(torques[o], pi)
    if h is None or w[h] == 0:
        if eta == 1:
            out = [phrase("gears.power", given=given, i=i, o=o,
                          ratio=fraction_text(w[i] / w[o]), value=value)]
        else:
            out = [phrase("gears.power_efficiency", given=given, i=i, o=o,
                          eta=said_eta, ratio=fraction_text(w[i] / w[o]),
                          value=value)]
    else:
        out = [phrase("gears.power_two", given=given, i=i, o=o, h=h, eta=said_eta,
                      value=value)]
    if h is not None:
        out.append(phrase("gears.holding" if h == train.fixed else "gears.holding_two",
                          fixed=h, i=i, o=o, value=torque_text(torques[h], pi)))
    return out


def say_powers(train: GearTrain, speeds: dict[int, Fraction], output: int | None,
               members: list[int]) -> list[Phrase]:
    """The steps of each asked member's power, |T·ω|: into the train where T and ω agree
    in sense (the input's), out of it where they oppose (the output's, η·P_in)."""
    torques = balance(train, speeds, output)
    rpm = "(2π/60)·" if train.units.speed == "rpm" else ""
    out = []
    for m in members:
        value, times_pi = power_at(train, torques[m], speeds[m])
        key = "gears.power_in" if torques[m] * speeds[m] > 0 else "gears.power_out"
        out.append(phrase(key, m=m, rpm=rpm, w=fraction_text(abs(speeds[m])),
                          t=torque_text(abs(torques[m]), per_pi(train)).split(" = ")[0],
                          value=power_text(value, times_pi)))
    return out
