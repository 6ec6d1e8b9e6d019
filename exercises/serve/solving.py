"""A request to solve, answered as ``tarsim solve`` answers a file, in JSON.

The TOML text is read as the command line reads a file (its tables parsed once, read by
the chapter they make it), set up as ``solve --angle`` sets it up, solved by its chapter,
and said in the language asked (``speaking`` is a context variable, so two requests in
two languages each speak their own). The answer holds what the page shows: each moving
link's ω and α and each moving point's velocity and acceleration (the analytic solver's,
in the file's units), results.json's document, steps.md's table of each number beside
its analytic check, steps.md as HTML and the figures' SVG, as ``solve`` writes them.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from pathlib import PurePosixPath
from typing import Any

from tarsim.constructions.errors import TarsimError
from tarsim.constructions.narration import LANGUAGES, Word, narrate, render, speaking, spoken

from ..chapters import Chapter, chapter_for
from ..toml_source import read_toml
from .refusals import Refused
from .steps_html import steps_html

__all__ = ["Asked", "read_exercise", "solved_in", "answer", "UNSAVED"]

UNSAVED = "exercise.toml"
"""What an error calls a text sent with no file's name: the page's exercise, unsaved."""


@dataclass(frozen=True)
class Asked:
    """What a request asks solved: the file's text and how (see :meth:`of`)."""

    toml: str
    name: str = UNSAVED
    """The file's name, relative to the served folder, as an error's line names it (a
    bundled exercise's id with .toml); its stem is the exercise's id."""
    lang: str | None = None
    angle: float | None = None
    """The input's angle in degrees, measured as the file's [input] angle is (``--angle``)."""
    figures: bool | tuple[str, ...] = True
    """Draw the figures (and steps): all of them, none, or those named (their stems)."""
    whole: bool = True
    """False leaves out what is asked of the mechanism as a whole (DOF, Grashof class, time
    ratio, stroke), where something is asked at the position too: what turning the input
    does not change, and the most of a solve's time."""
    paper: str = "A4"
    allow_undercut: bool = False

    @classmethod
    def of(cls, body: dict[str, Any]) -> Asked:
        """The request ``body`` as asked: ``toml`` (required), ``file`` or ``id`` (what the
        text was opened from, naming it in an error's line and results.json), ``lang`` (en,
        fa, fa_latn), ``angle`` (degrees), ``figures``, ``whole``, ``paper``,
        ``allow_undercut``.

        Raises
        ------
        Refused
            400, naming the field that is missing or of the wrong type.
        """
        toml = body.get("toml")
        if not isinstance(toml, str):
            raise Refused('the request names no exercise: send its text as "toml"', 400)
        angle = body.get("angle")
        if angle is not None and (isinstance(angle, bool) or not isinstance(angle, (int, float))
                                  or not math.isfinite(angle)):
            raise Refused(f'"angle" is the input\'s angle in degrees, a finite number; got '
                          f'{angle!r:.40}', 400)
        lang = body.get("lang")
        if lang is not None and lang not in LANGUAGES:
            raise Refused(f'"lang" is one of {", ".join(LANGUAGES)}; got {lang!r:.40}', 400)
        paper = body.get("paper", "A4")
        if paper not in ("A4", "A3", "letter"):
            raise Refused(f'"paper" is A4, A3 or letter; got {paper!r:.40}', 400)
        name, key = body.get("file"), body.get("id")
        if not isinstance(name or "", str) or not isinstance(key or "", str):
            raise Refused('"file" is the exercise file\'s name ("my.toml"), "id" the bundled '
                          'exercise it was opened from ("four-bar")', 400)
        name = name or (f"{key}.toml" if key else UNSAVED)
        flags = {k: body.get(k, d) for k, d in (("figures", True), ("whole", True),
                                                ("allow_undercut", False))}
        if isinstance(flags["figures"], list) and all(isinstance(f, str)
                                                      for f in flags["figures"]):
            flags["figures"] = tuple(flags["figures"])
        for k, v in flags.items():
            if not isinstance(v, bool) and not (k == "figures" and isinstance(v, tuple)):
                raise Refused(f'"{k}" is true or false{_NAMES if k == "figures" else ""}; '
                              f'got {v!r:.40}', 400)
        return cls(toml, name, lang, None if angle is None else float(angle), paper=paper,
                   **flags)


_NAMES = ', or the names of the figures to draw (["worked"])'


def read_exercise(text: str, name: str) -> tuple[Any, Chapter]:
    """The exercise of the TOML ``text`` and its chapter, read as ``tarsim solve`` reads the
    file ``name`` (its id the name's stem).

    Raises
    ------
    InputError
        Naming ``name``:line and what to fix.
    """
    data = read_toml(text, name)
    chapter = chapter_for(data)
    return chapter.read(text, name, PurePosixPath(name).stem, data), chapter


def solved_in(asked: Asked) -> tuple[str, Any, Any, Chapter]:
    """Solve what ``asked`` asks: the language spoken, the exercise as set up, its
    solution and its chapter. Call it, and read the solution, inside ``speaking`` of the
    language it returns (its figures are drawn when first wanted).

    Raises
    ------
    TarsimError
        As ``tarsim solve`` raises it for the file.
    """
    loaded, chapter = read_exercise(asked.toml, asked.name)
    if asked.angle is not None and chapter.no_angle:
        raise Refused(chapter.no_angle, 422)          # as solve --angle refuses it
    lang = asked.lang or getattr(loaded, "lang", "en")
    with speaking(lang):
        angle = asked.angle
        units = getattr(getattr(loaded, "mechanism", None), "units", None)
        if angle is not None and units is not None and units.angle == "rad":
            angle = math.radians(angle)              # set_up takes the file's angle unit
        ex = chapter.set_up(loaded.named_in(spoken()), paper=asked.paper, angle=angle)
        if not asked.whole and getattr(ex, "position_asks", ()):    # (none: all are kept)
            ex = replace(ex, asks=ex.position_asks)
        solved = chapter.solve(ex, allow_undercut=asked.allow_undercut)
        if isinstance(asked.figures, tuple) and hasattr(solved, "only"):
            solved = replace(solved, only=frozenset(asked.figures))    # the others not drawn
        return lang, ex, solved, chapter


def answer(asked: Asked) -> dict[str, Any]:
    """The JSON answer to ``asked`` (see docs/howto/app.md).

    Raises
    ------
    TarsimError
        As ``tarsim solve`` raises it for the file.
    """
    lang, ex, solved, chapter = solved_in(asked)
    with speaking(lang):
        out: dict[str, Any] = {"title": chapter.title(ex), "lang": lang,
                               "chapter": chapter.key, **readout(ex, solved),
                               "results": solved.results, "table": table(ex, solved)}
        if asked.figures:
            drawn = figures(solved, asked.figures)
            out["steps"] = steps_html(solved.steps())
            out["figures"] = [{"name": stem, "title": title, "svg": svg}
                              for stem, title, svg, _ in drawn]
        else:
            out["steps"], out["figures"] = None, []
        # every figure the solution has, drawn or not (another chapter's: those drawn)
        out["figure_names"] = (solved.stems() if hasattr(solved, "stems")
                               else [f["name"] for f in out["figures"]])
    return out


def figures(solved, only: bool | tuple[str, ...] = True) -> list[tuple[str, str, str, Any]]:
    """Each figure of ``solved`` as ``solve`` writes it (those ``only`` names, if it names
    some): its stem, its heading in the language spoken, its SVG, and the figure (with its
    sheets, for a PDF or PNG). A linkage's solution draws only those it is asked for."""
    if hasattr(solved, "pages"):                                 # a linkage's
        from ..linkages.worked_steps import heading_in

        return [(f.stem, heading_in(f.heading, spoken()), f.svg, f.figure)
                for f in solved.pages]
    from tarsim.graphics.svg import to_svg

    return [(stem, fig.title or stem, to_svg(fig), fig) for stem, fig in solved.sheets().items()
            if not isinstance(only, tuple) or stem in only]


def readout(ex, solved) -> dict[str, Any]:
    """The input's angle, where each point stands (the file's units and axes), each moving
    link's ω and α (rad/s, rad/s², counter-clockwise positive) and each moving point's
    velocity and acceleration in the file's units, from the analytic solver at the first
    position; empty for a chapter without a linkage."""
    empty = {"angle": None, "points": {}, "omega": {}, "alpha": {}, "velocities": {},
             "accelerations": {}}
    positions = getattr(solved, "positions", None)
    if positions is None:
        return empty
    try:
        kin, mech = _first_position(ex, positions)
    except TarsimError:                 # nothing asked at a position that can be assembled
        return empty
    if kin is None:
        return empty
    units = mech.units
    fixed = {name for name, _ in mech.frame.points}

    def vectors(field: dict[str, tuple[float, float]], per: str) -> dict[str, Any]:
        return {p: {"magnitude": math.hypot(*xy) / units.metres, "unit": f"{units.length}{per}",
                    "angle_deg": math.degrees(math.atan2(xy[1], xy[0])),
                    "x": xy[0] / units.metres, "y": xy[1] / units.metres}
                for p, xy in field.items() if p not in fixed}

    def placed(xy: tuple[float, float]) -> list[float]:
        x, y = mech.in_file_axes(xy)
        return [x / units.metres, y / units.metres]

    return {"angle": float(f"{math.degrees(mech.drive.angle):.12g}"),   # as results.json
            "points": {p: placed(xy) for p, xy in kin.points.items()},
            "omega": {str(k): w for k, w in kin.omegas.items() if k != 1},
            "alpha": {str(k): a for k, a in kin.alphas.items() if k != 1},
            "velocities": vectors(kin.velocities, "/s"),
            "accelerations": vectors(kin.accelerations, "/s²")}


def _first_position(ex, positions):
    """The analytic solution at the exercise's first position and the mechanism there; with
    nothing asked at a position, at the file's own (None where the input's rates are given
    by another member, which only a position's solve converts).

    Raises
    ------
    TarsimError
        If the mechanism cannot be assembled there.
    """
    if positions:
        return positions[0].kinematics, positions[0].exercise.mechanism
    if ex.mechanism.given is not None:
        return None, None
    from tarsim.constructions.reference.solver import solve

    return solve(ex.mechanism), ex.mechanism


def table(ex, solved) -> list[dict[str, Any]]:
    """steps.md's results table: each quantity found, its construction beside its analytic
    value (as steps.md says them, in the language spoken), the relative error and whether
    it passed; with the number and unit of a rate or a vector's size (file units)."""
    if not hasattr(solved, "positions"):                      # another chapter's checks
        return [_checked_row(name, c) for name, c in solved.checked.items()]
    from tarsim.constructions.linkages.velocity_drawing import method_words

    from ..linkages.answer_text import overall_text, show

    def said(x) -> str:                 # as steps.md's method column says it
        return render(x, spoken()) if isinstance(x, Word) else narrate(x, spoken())

    units = ex.mechanism.units
    rows = [_row(name, q, units, overall_text(name, q.value, units),
                 overall_text(name, q.reference, units), said(q.said or Word(q.method)))
            for name, q in solved.overall.quantities.items()]
    for sol in solved.positions:
        m = sol.exercise.mechanism
        for name, q in sol.quantities.items():
            q = q.in_file_axes(m)
            for label, qq in [(name, q)] + [(f"{name} ({k})", a)
                                            for k, a in q.alternatives.items()]:
                row = _row(label, qq, m.units, show(qq.value, m.units, name),
                           show(qq.reference, m.units, name),
                           said(Word(method_words(qq.method))), name=name)
                if len(solved.positions) > 1:
                    row["position"] = sol.position.label
                rows.append(row)
    return rows


def _row(label: str, q, units, construction: str, analytic: str, method: str,
         name: str = "") -> dict[str, Any]:
    """A linkage's row: ``q`` said as ``construction`` and ``analytic``."""
    value, unit = _size(name, q.value, units)
    return {"quantity": label, "construction": construction, "analytic": analytic,
            "error": q.rel_error, "passed": q.passed, "method": method,
            "value": value, "reference": _size(name, q.reference, units)[0], "unit": unit}


def _checked_row(name: str, c) -> dict[str, Any]:
    """Another chapter's row, as its results.json gives it (SI, or the unit it states)."""
    def number(v) -> Any:
        x = (v or {}).get("value")
        return x if isinstance(x, (int, float)) and not isinstance(x, bool) else None

    def text(v) -> str:
        x = (v or {}).get("value")
        return "" if x is None else str(x)

    return {"quantity": name, "construction": text(c.value), "analytic": text(c.reference),
            "error": c.rel_error, "passed": c.passed, "method": c.method,
            "value": number(c.value), "reference": number(c.reference),
            "unit": c.value.get("unit")}


def _size(name: str, v: dict, units) -> tuple[Any, str | None]:
    """A linkage quantity's number in the file's units and its unit: a vector's size, a
    rate; (None, None) for a point or a kind the table says in words only."""
    if not v or "point" in v or "value" not in v:
        return None, None
    if "vector" in v and name[:1] in "VA" and not name.startswith("F_"):
        per = "/s²" if name.startswith("A") else "/s"
        return v["value"] / units.metres, f"{units.length}{per}"
    if name.startswith("omega"):
        return v["value"], "rad/s"
    if name.startswith("alpha"):
        return v["value"], "rad/s²"
    return None, None
