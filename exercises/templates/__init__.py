"""Starting files, one for each kind of exercise: ``tarsim new linkage -o my.toml``.

Each is a small, commented file that solves as it stands, so that a user edits a working
exercise rather than writing one from the README's fragments. tests/test_templates.py
solves every one and holds a number of each to its closed form.
"""

from __future__ import annotations

from importlib import resources

__all__ = ["KINDS", "FOLDERS", "template", "folder"]

KINDS = {
    "linkage": "a four-bar crank-rocker: instant centres, velocities and accelerations",
    "train": "a planetary gear train with its ring held: each member's speed",
    "cam": "a roller follower's cam: the motion diagrams and the profile",
    "rotor": "masses on a shaft balanced by one mass in their plane",
    "engine": "a single-cylinder engine's reciprocating masses, partly balanced",
    "loads": "a horizontal engine's gas load: pin forces and the crank's torque",
    "flywheel": "a turning moment as a formula: the flywheel that holds the speed",
    "rod": "a connecting rod alone: its equivalent masses and correction couple",
    "class": "a folder of five students' drawings of the crank-shaper's polygons, to grade",
}
"""Each kind of starting file, with what it holds."""

FOLDERS = {"class"}
"""The kinds that are a folder of files rather than one file."""


def template(kind: str) -> str:
    """The text of ``kind``'s starting file (a key of :data:`KINDS`)."""
    return resources.files(__name__).joinpath(f"{kind}.toml").read_text(encoding="utf-8")


def folder(kind: str) -> dict[str, bytes]:
    """The files of ``kind``'s starting folder (a member of :data:`FOLDERS`), by name.

    The class is five drawings of the crank-shaper's polygons at its position 2, as
    Inkscape, LibreOffice Draw, a CAD program and GeoGebra export them, and one drawn by
    hand and traced: one right throughout, the others with a student's usual slips (a Coriolis
    component reversed, every velocity reversed, a vector a few per cent long, a tip left
    out), so that a first ``tarsim grade`` shows each verdict.
    """
    files = resources.files(__name__).joinpath(kind)
    return {f.name: f.read_bytes() for f in sorted(files.iterdir(), key=lambda f: f.name)
            if f.name.endswith(".svg")}
