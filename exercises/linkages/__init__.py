"""The linkages: a mechanism file and its ``[ask]``, solved by construction at each position
it asks (with its loads, the force analysis too), every number checked by the analytic
solver. A file of no other chapter is a linkage's."""

from __future__ import annotations

from dataclasses import replace

from ..chapters import Chapter

__all__ = ["CHAPTER"]


class Linkages(Chapter):
    """The linkage chapter (see :class:`~..chapters.Chapter`); the loaded linkages of the
    force analysis are its exercises too, bundled in a folder of their own."""

    key = "linkages"
    kind = "a linkage"
    folders = ("", "forces")

    def read(self, text, filename, exercise_id, data):
        from .exercise_file import parse_exercise
        return parse_exercise(text, filename, exercise_id, data)

    def set_up(self, exercise, *, paper, angle=None):
        if angle is not None:                 # one angle, instead of the file's positions
            from .mechanism_input import file_angle

            mech = exercise.mechanism        # turned as [input]'s angle is, from its centre
            drive = replace(mech.drive, angle=file_angle(mech.angle_from, angle,
                                                         mech.units.angle))
            exercise = replace(exercise, mechanism=mech.with_drive(drive), positions=())
        return replace(exercise, paper=paper)

    def solve(self, exercise, *, allow_undercut=False):
        from .solution_files import solve_worked
        return solve_worked(exercise)

    def drawing(self, exercise):
        from tarsim.constructions.linkages.assembly import assemble
        from tarsim.constructions.scales import space_per_cm
        from tarsim.graphics.linkages.diagram import draw_kinematic_diagram
        from tarsim.graphics.paper import paper, room

        asm = assemble(exercise.mechanism)
        return draw_kinematic_diagram(asm, per_cm=space_per_cm(asm, room(paper(exercise.paper))))

    def title(self, exercise) -> str:
        return exercise.mechanism.name

    def asks(self, exercise) -> str:
        """The find list as a textbook writes it, then the positions: "ω4, V_B at θ2 = 90°"."""
        from tarsim.constructions.asks import symbol

        names = ", ".join(symbol(q) for q in exercise.find)
        at = ", ".join(p.label.split(" (")[0] for p in exercise.positions)
        return f"{names} at {at}" if at else names


CHAPTER = Linkages()
