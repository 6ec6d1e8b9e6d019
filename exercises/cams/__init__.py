"""The cams: a ``[cam]``, its ``[follower]`` and the ``[[segment]]`` tables of its motion,
solved into the follower's motion diagrams by construction and the profile laid out by
inversion."""

from __future__ import annotations

from ..chapters import Chapter

__all__ = ["CHAPTER"]


class Cams(Chapter):
    """The cam chapter (see :class:`~..chapters.Chapter`)."""

    key = "cams"
    kind = "a cam"
    folders = ("cams",)
    tables = ("cam",)
    no_angle = "a cam is drawn and solved over its whole turn: leave out --angle"

    def read(self, text, filename, exercise_id, data):
        from .cam_file import parse_cam
        return parse_cam(text, filename, exercise_id, data)

    def solve(self, exercise, *, allow_undercut=False):
        from .solve import solve
        return solve(exercise, allow_undercut=allow_undercut)

    def drawing(self, exercise):
        # The profile is drawn even where the follower undercuts it, the trouble ringed.
        return self.solve(exercise, allow_undercut=True).figures["profile"]

    def asks(self, exercise) -> str:
        if hasattr(exercise, "cam"):
            return "the cam's dimensions and the follower's motion on its flank and nose"
        return "the follower's motion diagrams and the profile by inversion"


CHAPTER = Cams()
