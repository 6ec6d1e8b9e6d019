"""The teeth a gear-train file leaves out, found before the speeds: by the diameters, the
coaxial condition and the centre distances, and by the speed ratios ``[ratio]`` (or one
``[[ratio]]`` a pair, or one in equal steps) with a least tooth count, a compound train's
pair by pair; read by :class:`~.train_file._Reader`,
whose ``fail``, ``exact``, ``integer`` and ``known`` they use."""

from __future__ import annotations

from dataclasses import replace
from fractions import Fraction
from typing import Any

from tarsim.constructions.errors import InputError
from tarsim.constructions.gears.about_distance import about_design
from tarsim.constructions.gears.pair_teeth import equal_steps, is_pair, pair_teeth
from tarsim.constructions.gears.planet_teeth import teeth_from_ratios
from tarsim.constructions.narration import Phrase
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
            found, shared = self.speed_ratios(train)
            ratios = [(of, value) for of, value, _ in found]
            train = replace(train, ratio_given=tuple((*of, value) for of, value in ratios))
            train, about = self.about_designed(train, found)
            train, least, paired = self.pairs_designed(train, found)
            steps = (*steps, *shared, *about, *paired)
            # the coaxial condition or a distance ties counts together: the table's way
            if (train.planetary or len(ratios) > 1 or train.coaxial
                    or any(m.distance for m in train.meshes)):
                train, more = teeth_from_ratios(train, ratios, least)
            else:
                train, more = teeth_from_ratio(train, *ratios[0], least)
            steps = (*steps, *more)
        if "ratio" not in self.data:     # an approximate distance with no ratio
            self.about_designed(train, [])
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

    def about_designed(self, train: GearTrain,
                       found: list[tuple[tuple[int, int], Fraction, int | None]]
                       ) -> tuple[GearTrain, tuple[Phrase, ...]]:
        """``train`` with each pair given an approximate centre distance designed to it
        (:func:`~tarsim.constructions.gears.about_distance.about_design`), refused at the
        mesh's line."""
        steps: list[Phrase] = []
        for i, mesh in enumerate(train.meshes):
            if mesh.about is not None:
                try:
                    train, said = about_design(train, mesh, found)
                except InputError as e:
                    raise self.fail(e.message, "mesh", "centre_distance", i) from None
                steps += said
        return train, tuple(steps)

    def speed_ratios(self, train: GearTrain
                     ) -> tuple[list[tuple[tuple[int, int], Fraction, int | None]],
                                tuple[Phrase, ...]]:
        """``[ratio]``, or a ``[[ratio]]`` for each pair the book gives one: the speed
        ratios, each with its least tooth count; a ratio in equal steps adds its pairs'
        ratios (each with its least count), and the steps that share it."""
        tables = self.data["ratio"]
        tables = tables if isinstance(tables, list) else [tables]
        found, said = [], []
        for i, t in enumerate(tables):
            of, value, least = self.ratio(train, t, i)
            found.append((of, value, None if "steps" in t else least))
            if "steps" in t:
                if t["steps"] != "equal":
                    raise self.fail('steps = "equal" shares the ratio equally among the pairs '
                                    f"between the two members, got {t['steps']!r}", "ratio",
                                    "steps", i)
                try:
                    pairs, step = equal_steps(train, of, value)
                except InputError as e:
                    raise self.fail(e.message, "ratio", "steps", i) from None
                found += [(p, root, least) for p, root in pairs]
                said.append(step)
        return found, tuple(said)

    def pairs_designed(self, train: GearTrain,
                       found: list[tuple[tuple[int, int], Fraction, int | None]]
                       ) -> tuple[GearTrain, int | None, tuple[Phrase, ...]]:
        """``train`` with the teeth of each pair whose own ratio gives its least count, as a
        compound train is designed pair by pair (one least count in a reverted train, tied
        by the coaxial condition or a distance, is the whole train's); the least count left
        for the rest, and the steps."""
        leasts = [(of, value, least) for of, value, least in found if least is not None]
        tied = train.coaxial or any(m.distance for m in train.meshes)
        if train.planetary or len(found) < 2 or (len(leasts) < 2 and tied):
            return train, (leasts[0][2] if leasts else None), ()
        if len(leasts) > 1 and not all(is_pair(train, of) for of, _, _ in leasts):
            raise self.fail("give least_teeth once, or in each pair's own [[ratio]], of = "
                            '"omega2/omega3" naming two gears that mesh', "ratio",
                            "least_teeth", 0)
        steps: tuple[Phrase, ...] = ()
        for of, value, least in leasts:
            if is_pair(train, of):
                train, more = pair_teeth(train, of, value, least)
                steps = (*steps, *more)
        for (x, y), value, least in found:
            if least is None and is_pair(train, (x, y)) and train.gear(x).teeth is None \
                    and train.gear(y).teeth is None:
                raise InputError(f"gears {x} and {y} have no teeth, and their ratio ω{x}/ω{y} "
                                 f"= {float(value):g} fixes one count: give least_teeth in its "
                                 "[[ratio]] too, or one count", file=self.filename)
        left = [least for of, _, least in leasts if not is_pair(train, of)]
        return train, (left[0] if left else None), steps

    def ratio(self, train: GearTrain, t: Any, i: int = 0
              ) -> tuple[tuple[int, int], Fraction, int | None]:
        """One ``[ratio]``: a speed ratio the book gives, of = "omega2/omega6", value = 12,
        and least_teeth for counts it leaves unknown."""
        if not isinstance(t, dict):
            raise self.fail('must be a table: [ratio] of = "omega2/omega6", value = 12', "ratio")
        self.known(t, ("of", "value", "least_teeth", "steps"), "ratio", i)
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
