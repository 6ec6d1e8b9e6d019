"""Solve a cam exercise of either kind, chosen by its type: a cam given by its follower's
motion (:mod:`.cam_solution`) or a cam of arcs (:mod:`.arc_cam_solution`)."""

from __future__ import annotations

from functools import singledispatch
from typing import Any

from .arc_cam_file import ArcCamExercise
from .cam_file import CamExercise

__all__ = ["solve"]


@singledispatch
def solve(exercise: Any, *, allow_undercut: bool = False) -> Any:
    """The solution of ``exercise``; ``allow_undercut`` lets a cam that undercuts be
    drawn."""
    raise TypeError(f"not a cam exercise: {type(exercise).__name__}")


@solve.register
def _(exercise: CamExercise, *, allow_undercut: bool = False) -> Any:
    from .cam_solution import solve_cam
    return solve_cam(exercise, allow_undercut=allow_undercut or exercise.undercut_asked)


@solve.register
def _(exercise: ArcCamExercise, *, allow_undercut: bool = False) -> Any:
    from .arc_cam_solution import solve_arc_cam
    return solve_arc_cam(exercise)
