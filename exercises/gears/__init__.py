"""The gear trains: a file of ``[[gear]]`` tables, its speeds found by the notes' tabular
method (or through an ordinary train) in exact fractions, each checked by the Willis
equations."""

from __future__ import annotations

from ..chapters import Chapter

__all__ = ["CHAPTER"]


class GearTrains(Chapter):
    """The gear-train chapter (see :class:`~..chapters.Chapter`)."""

    key = "gears"
    kind = "a gear train"
    folders = ("gears",)
    # Gears, meshes, shafts or an arm, not links: a train that lost its [[gear]] tables is
    # told so, not read as a linkage.
    tables = ("gear", "mesh", "shaft", "arm", "involute")
    no_angle = "a gear train has no input angle: leave out --angle"

    def read(self, text, filename, exercise_id, data):
        from .train_file import parse_train
        return parse_train(text, filename, exercise_id, data)

    def solve(self, exercise, *, allow_undercut=False):
        from .train_solution import solve_train
        return solve_train(exercise)

    def drawing(self, exercise):
        from tarsim.graphics.gears.train_schematic import draw_train_schematic
        return draw_train_schematic(exercise.train, exercise.train.name)

    def asks(self, exercise) -> str:
        from .train_file import ask_symbol
        return ", ".join(ask_symbol(q) for q in exercise.asks)


CHAPTER = GearTrains()
