"""Read a mechanism file (TOML) into the SI model, with errors that say file:line.

The format is documented in docs/howto/linkages.md. Lengths are keyed by the two point names
run together, as a textbook writes them (``O2A = 100``, ``AB = 250``).

It reads the top level and the ``[assembly]`` branches here, and the other tables by
subject: the values and units (:mod:`~.mechanism_values`), the frame and links
(:mod:`~.mechanism_links`), the sliders and contacts (:mod:`~.mechanism_joints`) and
the input (:mod:`~.mechanism_input`).
"""

from __future__ import annotations

from pathlib import Path

from tarsim.constructions.errors import AssemblyError, BranchError, DeadPoint, InputError
from tarsim.constructions.joints import Arc, Slide, contact_arc, contact_slide
from tarsim.constructions.model import Link, Mechanism
from tarsim.constructions.reference.solver import follow_branches
from .mechanism_input import read_input
from .extremes import through_extremes
from .mechanism_joints import read_contact, read_slider
from .mechanism_links import read_frame, read_links
from .mechanism_values import TableReader
# read_source and read_toml stay importable here, where a file's reading starts.
from ..toml_source import SourceMap, read_source, read_toml

__all__ = ["load_mechanism", "parse_mechanism", "line_of", "read_source", "read_toml",
           "MOST_POINTS"]

MOST_POINTS = 100
"""The most points a mechanism may name. Every point is constructed, labelled and placed
clear of the others on each figure, and that placing grows faster than the count."""

_EXERCISE = ("ask", "lang", "names", "grading", "forces", "mass", "force", "couple")
"""What an exercise file adds to its mechanism, read by exercise_file, loads_file and
names: a mechanism read alone (load_mechanism) leaves it be."""
_TOP = ("name", "source", "description", "units", "frame", "link", "slider", "contact", "input",
        "assembly") + _EXERCISE
_BRANCHES = ("left", "right", "forward", "backward")


def load_mechanism(path: str | Path) -> Mechanism:
    """Read ``path`` and return the mechanism it describes.

    Raises
    ------
    InputError
        If the file cannot be read, is not valid TOML, or describes an
        impossible or incomplete mechanism; the message names file:line.
    """
    return parse_mechanism(read_source(path), str(path))


def line_of(error: AssemblyError, path: str | Path, text: str | None = None) -> int | None:
    """The line of the file at ``path`` where what ``error`` says is stated, or None.

    A dead point is the input's angle; a missing or unfit branch, the point's key in
    [assembly] (or that table, or with none the first [[link]] that lists the point);
    anything else about a link, that link's [[link]] table. Assembly errors arise after
    the file is read, so it is read again to find the line, unless its ``text`` is given
    (a file sent to ``tarsim serve``, which is on no disk).
    """
    try:
        text = read_source(path) if text is None else text
        data = read_toml(text, str(path))
    except InputError:
        return None
    where = SourceMap(text)
    if isinstance(error, DeadPoint):
        return where.key("angle", "input")
    raw = data.get("link")
    links = [k if isinstance(k, dict) else {} for k in raw] if isinstance(raw, list) else []

    def table_of(wanted) -> int | None:
        index = next((i for i, k in enumerate(links) if wanted(k)), None)
        return where.header("link", index) if index is not None else None

    if isinstance(error, BranchError):
        if "assembly" in data:
            return where.key(error.joint, "assembly")
        return table_of(lambda k: error.joint in (k.get("points") or ()))
    if error.link is not None:
        return table_of(lambda k: k.get("number") == error.link)
    return None


def parse_mechanism(text: str, filename: str = "<string>") -> Mechanism:
    """Parse TOML text into a :class:`Mechanism` (see :func:`load_mechanism`)."""
    return _Reader(read_toml(text, filename), SourceMap(text), filename).mechanism()


class _Reader(TableReader):
    """Reads a whole mechanism file: the top level, then each table by its subject."""

    def mechanism(self) -> Mechanism:
        for k in self.d:
            if k not in _TOP:
                raise self.unknown(k, _TOP, "setting", key=k)
        for k in ("source", "description"):
            if k in self.d:
                self.text(self.d[k], k, lines=True, key=k)
        name = self.text(self.d.get("name", Path(self.file).stem), "name", key="name")
        self.units = self.read_units()
        frame = read_frame(self)
        # A curved block gains its pin at the centre of curvature while the sliders
        # are read, so the links are final only after them.
        self.links = {k.number: k for k in [frame] + read_links(self, frame)}
        slides: list[Slide] = []
        arcs: list[Arc] = []
        self.extremes: list[tuple[int, str, dict]] = []   # guides laid through extremes
        for i, t in enumerate(self.list_of("slider")):
            joint = read_slider(self, i, t)
            (arcs if isinstance(joint, Arc) else slides).append(joint)
        for i, t in enumerate(self.list_of("contact")):
            c = read_contact(self, i, t)
            if c.face.is_circle:
                arcs.append(contact_arc(c))
            else:
                slides.append(contact_slide(c, self.links[c.face.link]))
        mech_links = tuple(self.links.values())
        named = {n for k in mech_links for n in k.names}
        if len(named) > MOST_POINTS:
            raise self.fail(f"names {len(named):,} points; a mechanism may have at most "
                            f"{MOST_POINTS}, each drawn and labelled on every figure")
        self.slides = tuple(slides)
        drive = read_input(self)
        branches = self.read_assembly(mech_links, tuple(slides))
        ox, oy = self.file_origin
        mech = Mechanism(mech_links, drive, tuple(slides), branches, self.units,
                         name, self.file, tuple(arcs), given=self.given,
                         origin=(ox * self.units.metres + 0.0, oy * self.units.metres + 0.0),
                         angle_from=self.angle_from)
        if self.extremes:
            mech = through_extremes(mech, self.extremes, self.fail)
        mech = follow_branches(mech)
        dof, n, f1, f2 = mech.mobility()
        if dof != 1:
            raise self.fail(
                f"the mechanism has {dof} degrees of freedom (Grübler: 3({n} − 1) − 2·{f1} − {f2}"
                f" = {dof}) but [input] drives one link; "
                + ("add a link or joint to constrain it" if dof > 1 else
                   "it cannot move: check the links and joints"), table="input")
        return mech

    def read_assembly(self, links: tuple[Link, ...], slides: tuple[Slide, ...]) -> dict:
        t = self.table("assembly", False)
        names = {n for k in links for n in k.names}
        out: dict[str, str | tuple[float, float]] = {}
        for k, v in t.items():
            if k not in names:
                raise self.unknown(k, sorted(names), "point", table="assembly", key=k)
            if isinstance(v, str):
                if v not in _BRANCHES:
                    raise self.unknown(v, _BRANCHES, "branch", table="assembly", key=k)
                out[k] = v
            else:
                out[k] = self.xy(v, f"the point {k} should be near", table="assembly", key=k)
        return out
