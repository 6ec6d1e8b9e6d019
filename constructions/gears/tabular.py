"""Speeds of a gear train as the notes find them (000-part2 §2.14–2.15), exactly.

An **ordinary train** (every axis fixed) carries the input's speed from gear to gear: a
mesh turns the driven gear N_driver/N_driven as fast, the other way round if the mesh is
external and the same way if internal; gears on one shaft turn alike. The train value is
the product of driver teeth over driven teeth with the sign of the external meshes, and
an idler cancels from it.

A **planetary train** by the tabular (superposition) method:

1. the whole train, locked, with the arm, turned +1 (counter-clockwise);
2. the arm held and the fixed member turned −1, carried to every gear by the tooth ratios
   as in an ordinary train (the arm is held, so its axes are fixed);
3. the two rows added: the fixed member stands still, and each member's total is its turns
   for one turn of the arm. The input's real speed over its total scales the row.

The other common form writes the arm's speed y and the fixed member's, relative to the
arm, x: each member turns y + k·x, its k from the second row; the fixed member's 0 and
the input's speed give x and y.

Every number is a :class:`~fractions.Fraction`; each step is a :class:`Phrase`.
"""

from __future__ import annotations

from collections.abc import Callable

from dataclasses import dataclass, field, replace
from fractions import Fraction

from ..errors import InputError
from ..narration import Phrase, Word, phrase
from .train import GearTrain, Mesh

__all__ = ["Table", "TrainSpeeds", "tabulate", "carry", "fraction_text", "main_axis_train"]


@dataclass(frozen=True)
class Table:
    """The tabular method's rows, each member's turns: ``locked`` (+1 each), ``held``
    (the arm held, the fixed member −1), ``total`` (their sum), and the factor ``scale``
    (the input's real speed over its total) that makes the totals speeds."""

    members: tuple[int, ...]
    locked: dict[int, Fraction]
    held: dict[int, Fraction]
    total: dict[int, Fraction]
    scale: Fraction
    weights: tuple[Fraction, Fraction] | None = None
    """With two given speeds (no member fixed): y and x, the speed is y·locked + x·held,
    and ``total`` is the speeds themselves."""
    turned: int | None = None
    """The member turned −1 in the held row, where no member is fixed."""


@dataclass(frozen=True)
class TrainSpeeds:
    """Every member's speed (exact, CCW-positive, in the file's unit), the steps that found
    them, and the table when the tabular method did."""

    speeds: dict[int, Fraction]
    steps: tuple[Phrase, ...]
    table: Table | None = None
    method: str = "tabular"
    xy: tuple[Phrase, ...] = field(default=())


def fraction_text(x: Fraction, signed: bool = False) -> str:
    """An exact number as the notes set it: "7/3", "−5/2", "24"; ``signed`` writes "+1"."""
    sign = "−" if x < 0 else ("+" if signed and x > 0 else "")
    x = abs(x)
    return sign + (str(x.numerator) if x.denominator == 1 else f"{x.numerator}/{x.denominator}")


def carry(train: GearTrain, start: dict[int, Fraction], held: tuple[int, ...] = (),
          steps: list[Phrase] | None = None,
          via: dict[int, tuple[int, Mesh | None]] | None = None, *,
          said: Callable[[Fraction], str | Phrase] = fraction_text,
          whole: bool = True) -> dict[int, Fraction]:
    """Turns of every member, carried from ``start`` (member: turns) through the shafts and
    meshes with every axis fixed; ``held`` members stand at 0 and carry nothing. ``via``
    is filled with the member each was reached from, and the mesh (None: a shaft).
    ``said`` is how the steps say a number of turns (as turns, or as a speed, where the
    numbers are speeds already); a shaft is narrated only for turns.

    Raises
    ------
    InputError
        If ``whole`` and a member is reached by no mesh or shaft (the train does not hang
        together).
    """
    out: dict[int, Fraction] = {}
    for m, v in start.items():
        for k in train.body(m):
            out[k] = v
    for m in held:
        for k in train.body(m):
            out.setdefault(k, Fraction(0))
    steps = steps if steps is not None else []
    grew = True
    while grew:
        grew = False
        for mesh in train.meshes:
            for a, b in ((mesh.a, mesh.b), (mesh.b, mesh.a)):
                if a in out and b not in out:
                    ga, gb = train.gear(a), train.gear(b)
                    ratio = Fraction(ga.teeth, gb.teeth) * mesh.sign
                    out[b] = out[a] * ratio
                    if via is not None:
                        via[b] = (a, mesh)
                    steps.append(phrase(
                        "gears.bevel_carries" if mesh.bevel else "gears.mesh_carries",
                        driven=train.said(b, opening=True),
                        driver=train.said(a),
                        kind=Word(mesh.word),
                        way=Word("the same way" if mesh.sign > 0 else "the other way"),
                        a=a, b=b, na=ga.teeth, nb=gb.teeth, turns=said(out[a]),
                        result=said(out[b])))
                    for k in train.body(b):
                        if k != b:
                            out[k] = out[b]
                            if via is not None:
                                via[k] = (b, None)
                            if said is fraction_text:
                                steps.append(phrase("gears.shaft_carries",
                                                    member=train.said(k, opening=True),
                                                    other=train.said(b),
                                                    turns=said(out[b])))
                    grew = True
    lost = [m for m in train.members if m not in out]
    if whole and lost:
        raise InputError(f"{train.label(lost[0])} is joined to the rest of the train by no "
                         "mesh or shaft", file=train.source or None)
    return out


def tabulate(train: GearTrain) -> TrainSpeeds:
    """Every member's speed: by the tabular method in a planetary train, by carrying the
    input's speed through the meshes in an ordinary one. Gears on side shafts of a
    planetary train (:attr:`GearTrain.off_axis`) turn as an ordinary train with the
    main-axis gear they mesh: carried to it before the table, or from it after.

    Raises
    ------
    InputError
        If a member is reached by no mesh, the input cannot drive, or the fixed member
        turns on a side shaft.
    """
    if train.second is None and (not train.planetary or train.fixed is None
                                 or train.arm in train.body(train.fixed)):
        return _ordinary(train)
    if not train.off_axis:
        return _planetary(train) if train.second is None else _two_given(train)
    steps: list[Phrase] = []
    core, speeds = main_axis_train(train, steps)
    table = _planetary(core) if train.second is None else _two_given(core)
    after: list[Phrase] = []
    speeds = _carry_speeds(_side_meshes(train), {**speeds, **table.speeds}, after)
    return TrainSpeeds({m: speeds[m] for m in train.members},
                       (*steps, *table.steps, *after), table.table, table.method, table.xy)


def main_axis_train(train: GearTrain, steps: list[Phrase]
                    ) -> tuple[GearTrain, dict[int, Fraction]]:
    """The planetary part of a train with gears on side shafts: its members on the main
    axis and the planets, driven by the first of them the input reaches (at the speed the
    side shafts' meshes carry to it, each step appended to ``steps``); and the speeds so
    carried.

    Raises
    ------
    InputError
        If the fixed member turns on a side shaft.
    """
    side = train.off_axis
    if train.fixed in side:
        raise InputError(f"{train.label(train.fixed)}, the fixed member, turns on a side shaft "
                         "beside the main axis: fix the arm or a gear on the main axis",
                         file=train.source or None)
    speeds = _carry_speeds(_side_meshes(train), {train.input_member: train.input_speed}, steps)
    first = next(m for m in (train.input_member, *speeds) if m not in side)
    second = train.second
    if second is not None:          # the second given speed, carried to the main axis too
        more = _carry_speeds(_side_meshes(train), dict([second]), steps)
        reached = next(m for m in (second[0], *more) if m not in side)
        speeds = {**more, **speeds}
        second = (reached, more[reached])
    core = replace(train, gears=tuple(g for g in train.gears if g.number not in side),
                   meshes=tuple(m for m in train.meshes if m.a not in side and m.b not in side),
                   shafts=tuple(sh for sh in train.shafts if not set(sh) & set(side)),
                   input_member=first, input_speed=speeds[first], second=second)
    return core, speeds


def _side_meshes(train: GearTrain) -> GearTrain:
    """``train`` with only the meshes of its gears on side shafts."""
    side = train.off_axis
    return replace(train, meshes=tuple(m for m in train.meshes if m.a in side or m.b in side))


def _carry_speeds(train: GearTrain, known: dict[int, Fraction], steps: list[Phrase]
                  ) -> dict[int, Fraction]:
    """The speeds ``known``, carried through ``train``'s meshes (every axis fixed) and
    shafts as far as they reach."""
    return carry(train, known, steps=steps, said=lambda v: _speed(train, v), whole=False)


def _ordinary(train: GearTrain) -> TrainSpeeds:
    first = train.input_member
    steps = [phrase("gears.ordinary_start", member=train.said(first, opening=True),
                    speed=_speed(train, train.input_speed)) if train.speed_given else
             phrase("gears.ordinary_turn", member=train.said(first, opening=True))]
    via: dict[int, tuple[int, Mesh | None]] = {}
    # A fixed arm (the planetary train held as an ordinary one) stands still.
    held = (train.fixed,) if train.fixed is not None else ()
    if held:
        locked = next((b for m in train.meshes for a, b in ((m.a, m.b), (m.b, m.a))
                       if a in train.body(first) and b in train.body(train.fixed)), None)
        if locked is not None:
            raise InputError(f"the input, {train.label(first)}, meshes {train.label(locked)}, "
                             "which is held with the fixed member: it cannot turn",
                             file=train.source or None)
    turns = carry(train, {first: Fraction(1)}, held=held, steps=steps, via=via)
    # the train value runs to the last gear the input drives (not one the fixed member holds)
    last = next((m for m in reversed(via) if _driven(via, m, train.body(first))), first)
    steps.append(_train_value(train, first, last, via, turns[last]))
    speeds = {m: turns[m] * train.input_speed for m in train.members}
    return TrainSpeeds(speeds, tuple(steps), None, "train value")


def _driven(via: dict[int, tuple[int, Mesh | None]], m: int, start: tuple[int, ...]) -> bool:
    """True if ``m`` was reached from the input's body, through meshes and shafts."""
    while m not in start:
        if m not in via:
            return False
        m = via[m][0]
    return True


def _planetary(train: GearTrain) -> TrainSpeeds:
    arm, fixed, first = train.arm, train.fixed, train.input_member
    members = train.members
    steps = [phrase("gears.locked", arm=train.said(arm))]
    locked = {m: Fraction(1) for m in members}
    steps.append(phrase("gears.held", arm=train.said(arm), fixed=train.said(fixed)))
    held = carry(train, {fixed: Fraction(-1)}, held=(arm,), steps=steps)
    total = {m: locked[m] + held[m] for m in members}
    steps.append(phrase("gears.added", fixed=train.said(fixed)))
    if total[first] == 0:
        raise InputError(f"the input, {train.label(first)}, turns 0 in the table: it stands "
                         "still with the fixed member, so it cannot drive the train",
                         file=train.source or None)
    scale = train.input_speed / total[first]
    if train.speed_given:
        steps.append(phrase("gears.scaled", member=train.said(first, opening=True),
                            total=fraction_text(total[first]),
                            speed=_speed(train, train.input_speed), scale=fraction_text(scale),
                            unit=train.units.speed))
    else:               # no speed given: the totals over the input's are the ratios asked
        steps.append(phrase("gears.over_input", member=train.said(first, opening=True),
                            total=fraction_text(total[first]), i=first))
    speeds = {m: total[m] * scale for m in members}
    xy = _xy(train, held, speeds) if train.speed_given else ()
    return TrainSpeeds(speeds, tuple(steps), Table(members, locked, held, total, scale),
                       "tabular", xy)


def _two_given(train: GearTrain) -> TrainSpeeds:
    """The tabular method with two given speeds and no member fixed: every member turns
    y·(row 1) + x·(row 2), the arm held in row 2 while a given gear turns −1; the two
    given speeds are two equations in y (the arm's speed) and x."""
    arm, members = train.arm, train.members
    (a, sa), (b, sb) = (train.input_member, train.input_speed), train.second
    turned = b if a in train.body(arm) else a        # a given member that is not the arm
    steps = [phrase("gears.locked", arm=train.said(arm)),
             phrase("gears.held_given", arm=train.said(arm), member=train.said(turned))]
    locked = {m: Fraction(1) for m in members}
    held = carry(train, {turned: Fraction(-1)}, held=(arm,), steps=steps)
    if held[a] == held[b]:
        raise InputError(f"{train.label(a)} and {train.label(b)} turn alike whatever the arm "
                         "does, so their two speeds cannot both be given: give another "
                         "member's", file=train.source or None)
    x = (sa - sb) / (held[a] - held[b])
    y = sa - x * held[a]
    steps.append(phrase("gears.two_given", a=a, b=b, ha=fraction_text(held[a]),
                        hb=fraction_text(held[b]), sa=fraction_text(sa), sb=fraction_text(sb),
                        x=fraction_text(x), y=fraction_text(y), unit=train.units.speed))
    speeds = {m: y * locked[m] + x * held[m] for m in members}
    return TrainSpeeds(speeds, tuple(steps),
                       Table(members, locked, held, speeds, Fraction(1), (y, x), turned), "tabular")


def _train_value(train: GearTrain, first: int, last: int,
                 via: dict[int, tuple[int, Mesh | None]], value: Fraction) -> Phrase:
    """The notes' train value from ``first`` to ``last``: driver teeth over driven teeth
    along the meshes between, the sign of the external ones; a gear that is driven and
    then drives (an idler) cancels."""
    drivers, driven, external = [], [], 0
    m, start = last, train.body(first)
    while m not in start:               # back to the input, or to a gear on its shaft
        prev, mesh = via[m]
        if mesh is not None:
            drivers.insert(0, prev)
            driven.insert(0, m)
            external += mesh.sign < 0
        m = prev
    idlers = [g for g in driven if g in drivers]
    return phrase("gears.train_value", last=last, first=first,
                  drivers="·".join(f"N{g}" for g in drivers),
                  driven="·".join(f"N{g}" for g in driven),
                  teeth=f"({'·'.join(str(train.gear(g).teeth) for g in drivers)})/"
                        f"({'·'.join(str(train.gear(g).teeth) for g in driven)})",
                  value=fraction_text(value), externals=external,
                  sign=Word("negative: opposite senses" if value < 0 else "positive: one sense"),
                  idlers=phrase("gears.idlers" if len(idlers) > 1 else "gears.idler",
                                idlers=", ".join(map(str, idlers))) if idlers else None)


def _xy(train: GearTrain, held: dict[int, Fraction], speeds: dict[int, Fraction]
        ) -> tuple[Phrase, ...]:
    """The x/y form of the same table: each member y + k·x, k from the held row over the
    fixed member's (so the fixed member is y + x and the arm y)."""
    k = {m: held[m] / held[train.fixed] for m in train.members}
    y = speeds[train.arm]
    x = -y
    def term(m: int) -> str:
        if not k[m]:
            return f"ω{m} = y"
        size = "" if abs(k[m]) == 1 else f"{fraction_text(abs(k[m]))}·"
        return f"ω{m} = y {'+' if k[m] > 0 else '−'} {size}x"
    rows = ", ".join(term(m) for m in train.members)
    return (phrase("gears.xy_rows", rows=rows, arm=train.arm, fixed=train.fixed),
            phrase("gears.xy_solved", fixed=train.fixed, member=train.input_member,
                   speed=_speed(train, train.input_speed), x=fraction_text(x),
                   y=fraction_text(y), unit=train.units.speed))


def _speed(train: GearTrain, v: Fraction) -> Phrase:
    """A speed as the steps say it: "80 rpm cw"."""
    return phrase("gears.speed", value=fraction_text(abs(v)), unit=train.units.speed,
                  sense=phrase("gears.sense", sense=Word("ccw" if v > 0 else "cw")) if v else None)
