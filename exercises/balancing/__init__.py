"""Balancing: a ``[rotor]`` balanced by its force (and couple) polygon, or an ``[engine]``'s
primary and secondary forces and couples by theirs."""

from __future__ import annotations

from ..chapters import Chapter

__all__ = ["CHAPTER"]


class Balancing(Chapter):
    """The balancing chapter (see :class:`~..chapters.Chapter`)."""

    key = "balancing"
    kind = "a balancing exercise"
    folders = ("balancing",)
    tables = ("rotor", "engine")
    no_angle = ("a balancing exercise has no input angle: leave out --angle (an engine's "
                "crank angle is its [engine] at)")

    def read(self, text, filename, exercise_id, data):
        from .rotor_file import parse_balance
        return parse_balance(text, filename, exercise_id, data)

    def solve(self, exercise, *, allow_undercut=False):
        from .balance_solution import solve_balance
        return solve_balance(exercise)

    def drawing(self, exercise):
        # a rotor's space diagram; an engine's primary force polygon, or a single
        # cylinder's forces against crank angle
        return next(iter(self.solve(exercise).figures.values()))

    def asks(self, exercise) -> str:
        if exercise.open is not None and exercise.engine is not None:
            return ("the cylinders' unknowns by their primary balance, then the secondary "
                    "forces and couples by their polygons")
        if exercise.open is not None:
            return "the unknowns of the masses by the force and couple polygons"
        if exercise.rotor is not None and not exercise.rotor.planes:
            return "the out-of-balance force and couple by the force and couple polygons"
        if exercise.rotor is not None and exercise.engine is None:
            return ("the balancing mass by the force polygon" if len(exercise.rotor.planes) == 1
                    else "the two balancing masses by the couple and force polygons")
        if exercise.engine.radial:
            return ("the resultant primary and secondary forces of a radial engine's cylinders "
                    "by direct and reverse cranks")
        if exercise.engine.vee:
            return "the resultant primary and secondary forces of a V engine's two cylinders"
        if len(exercise.engine.cranks) == 1:
            return "the primary and secondary forces, partly balanced"
        if exercise.rotor is not None:
            return ("the primary and secondary forces and couples by their polygons, and the "
                    "balance masses by the couple and force polygons")
        return "the primary and secondary forces and couples by their polygons"


CHAPTER = Balancing()
