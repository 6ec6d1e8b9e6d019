"""The teeth a gear-train file leaves out, found before the speeds: by the diameters, the
coaxial condition and the centre distances, and by the speed ratios ``[ratio]`` (or one
``[[ratio]]`` a pair) with a least tooth count; read by :class:`~.train_file._Reader`,
whose ``fail``, ``exact``, ``integer`` and ``known`` they use."""

from __future__ import annotations

from dataclasses import replace
from fractions import Fraction
from typing import Any

from tarsim.constructions.errors import InputError
from tarsim.constructions.gears.planet_teeth import teeth_from_ratios
from tarsim.constructions.gears.teeth import (coaxial_misfit, coaxial_pairs, imply_teeth,
                                               teeth_from_ratio, unknown_teeth)
from tarsim.constructions.gears.train import GearTrain

__all__ = ["TeethTables"]


class TeethTables:
    """The reader's part for the teeth left out and the ratios that give them."""

    def teeth(self, train: GearTrain, implied: list[int]) -> GearTrain:
        """``train`` with the teeth the data imply (a diameter's, the coaxial condition's),
        found as its first steps; a gear whose teeth nothing gives is refused at its line."""
        coaxial = self.data.get("coaxial")
        if coaxial is not None and not (isinstance(coaxial, list) and len(coaxial) == 2 and all(
                isinstance(g, int) and g in [h.number for h in train.gears] for g in coaxial)):
            raise self.fail("coaxial names the two gears of an ordinary train on one axis, "
                            "coaxial = [2, 5]", key="coaxial")
        train = replace(train, coaxial=tuple(coaxial) if coaxial else None)
        if coaxial and not train.planetary and not coaxial_pairs(train, train.coaxial):
            raise self.fail(f"coaxial = [{coaxial[0]}, {coaxial[1]}] names gears that end no two "
                            "pairs joined by a shaft: name a reverted train's input and output "
                            "gears, coaxial = [1, 4]", key="coaxial")
        train, steps = imply_teeth(train, train.coaxial)
        if "ratio" in self.data:
            ratios, least = self.speed_ratios(train)
            train = replace(train, ratio_given=tuple((*of, value) for of, value in ratios))
            # the coaxial condition or a distance ties counts together: the table's way
            if (train.planetary or len(ratios) > 1 or train.coaxial
                    or any(m.distance for m in train.meshes)):
                train, more = teeth_from_ratios(train, ratios, least)
            else:
                train, more = teeth_from_ratio(train, *ratios[0], least)
            steps = (*steps, *more)
        misfit = coaxial_misfit(train, train.coaxial)
        if misfit is not None:
            raise self.fail(f"gears {train.coaxial[0]} and {train.coaxial[1]} are not on one "
                            f"axis: their pairs stand {misfit} apart; check the teeth and "
                            "modules, or leave coaxial out", key="coaxial")
        for g in unknown_teeth(train):
            raise InputError(f"gear {g} needs its teeth: give teeth = …, or its diameter with "
                             "its module, or mesh it where the coaxial condition gives them",
                             file=self.filename)
        return replace(train, implied=(*self.sized_teeth, *steps),
                       implied_teeth=(*self.from_diameter, *implied))

    def speed_ratios(self, train: GearTrain
                     ) -> tuple[list[tuple[tuple[int, int], Fraction]], int | None]:
        """``[ratio]``, or a ``[[ratio]]`` for each pair the book gives one: the speed
        ratios, and the least tooth count (in any of them) for counts they leave unknown."""
        tables = self.data["ratio"]
        tables = tables if isinstance(tables, list) else [tables]
        found = [self.ratio(train, t, i) for i, t in enumerate(tables)]
        leasts = [least for _, _, least in found if least is not None]
        if len(leasts) > 1:
            raise self.fail("give least_teeth once, in one [[ratio]]", "ratio", "least_teeth",
                            1)
        return [(of, value) for of, value, _ in found], (leasts[0] if leasts else None)

    def ratio(self, train: GearTrain, t: Any, i: int = 0
              ) -> tuple[tuple[int, int], Fraction, int | None]:
        """One ``[ratio]``: a speed ratio the book gives, of = "omega2/omega6", value = 12,
        and least_teeth for counts it leaves unknown."""
        if not isinstance(t, dict):
            raise self.fail('must be a table: [ratio] of = "omega2/omega6", value = 12', "ratio")
        self.known(t, ("of", "value", "least_teeth"), "ratio", i)
        parts = t.get("of", "").split("/") if isinstance(t.get("of"), str) else []
        numbers = [p.removeprefix("omega") for p in parts]
        if len(parts) != 2 or not all(p.startswith("omega") and n.isdigit() and int(n) in
                                      train.members for p, n in zip(parts, numbers)):
            raise self.fail('name the ratio of two members\' speeds: of = "omega2/omega6"',
                            "ratio", "of", i)
        if "value" not in t:
            raise self.fail("give the ratio's value = …", "ratio", index=i)
        value = abs(self.exact(t["value"], "the ratio", "ratio", "value", i))
        if value == 0:
            raise self.fail("a speed ratio of 0 fixes no teeth", "ratio", "value", i)
        least = (self.integer(t["least_teeth"], "the least tooth count", "ratio",
                                "least_teeth", i)
                 if "least_teeth" in t else None)
        return (int(numbers[0]), int(numbers[1])), value, least
