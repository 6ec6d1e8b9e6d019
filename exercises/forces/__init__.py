"""The force analysis's files and sweeps: a linkage's loads read from its file, and the
turning-moment diagram over a turn (their exercises are the linkages'); and the flywheel
chapter's own files, a ``[turning_moment]`` given as T(θ) or by its areas, whose flywheel
is asked; and a connecting rod given alone (``[rod]``), whose equivalent dynamical system
is asked."""

from __future__ import annotations

from ..chapters import Chapter

__all__ = ["CHAPTER"]


class Flywheel(Chapter):
    """The flywheel chapter (see :class:`~..chapters.Chapter`)."""

    key = "forces"
    kind = "a flywheel or connecting rod exercise"
    folders = ("flywheel", "rod")
    tables = ("turning_moment", "resisting_torque", "punch", "flywheel", "rod")
    no_angle = ("a flywheel or connecting rod exercise has no input angle: leave out --angle "
                "(a flywheel's [flywheel] at lists the crank angles asked)")

    def read(self, text, filename, exercise_id, data):
        if "rod" in data:
            from .rod_file import parse_rod
            return parse_rod(text, filename, exercise_id, data)
        from .flywheel_file import parse_flywheel
        return parse_flywheel(text, filename, exercise_id, data)

    def solve(self, exercise, *, allow_undercut=False):
        from .rod_file import RodExercise
        if isinstance(exercise, RodExercise):
            from .rod_solution import solve_rod
            return solve_rod(exercise)
        from .flywheel_solution import solve_flywheel
        return solve_flywheel(exercise)

    def drawing(self, exercise):
        return next(iter(self.solve(exercise).figures.values()))

    def asks(self, exercise) -> str:
        if hasattr(exercise, "rod"):
            return "the connecting rod's equivalent dynamical system"
        if exercise.speed_fluctuation is not None:
            return "the greatest fluctuation of energy and the flywheel"
        if exercise.inertia is not None:
            return "the coefficient of fluctuation of speed a flywheel allows"
        return "the greatest fluctuation of energy"


CHAPTER = Flywheel()
