"""A linkage's steps.md, as the sections every chapter's is written from.

The mechanism as a whole comes first (its limit positions, then the answers about it),
then each position: the input as drawn, each figure's numbered steps (the slice's own
numbering, which the figure circles), the position's notes and its results. A heading is a
catalogue phrase ("V_B by radius rotation" is ``md.by``, said whole in every language), or
words each catalogue says whole ("Instant centres"): never English cut into a quantity and
a method after the fact.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from tarsim.constructions.linkages.limit_positions import drawn_limits
from tarsim.constructions.linkages.velocity_drawing import method_words
from tarsim.constructions.narration import Number, Phrase, Word, narrate, phrase, significant
from tarsim.constructions.record import Panel

from ..worked_document import Notes, Paragraph, Section, Steps, Table
from .answer_text import overall_text, show

if TYPE_CHECKING:
    from .exercise_file import Exercise
    from .solution import Overall, Solution
    from .solution_files import SolutionFigure

__all__ = ["said_heading", "heading_in", "time_ratio", "overall_sections", "position_sections"]


def said_heading(heading: Phrase | str) -> Phrase:
    """A figure's or a part's heading as a phrase: itself, or ``md.heading`` of the words a
    catalogue says whole ("Instant centres", "Velocity polygon")."""
    return heading if isinstance(heading, Phrase) else phrase("md.heading", heading=Word(heading))


def heading_in(heading: Phrase | str, lang: str) -> str:
    """A figure's or a part's heading in ``lang``.

    >>> heading_in("Positions by compass", "fa")
    'وضعیت\u200cها با پرگار'
    >>> heading_in(phrase("md.by", what="V_B", method=Word("radius rotation")), "fa")
    'V_B به روش دوران شعاع'
    """
    return narrate(said_heading(heading), lang)


def time_ratio(m, lp) -> Phrase:
    """"The crank turns 222.2° (A″ to A′, cw) in the slow stroke and 137.8° in the quick
    one": the limit positions' reading of ``m``'s time ratio."""
    a = m.link(m.drive.link).names[1]
    start, end = (f"{a}′", f"{a}″") if lp.slow_from == 0 else (f"{a}″", f"{a}′")
    sense = "ccw" if m.drive.omega >= 0 else "cw"
    slow, quick = Number(math.degrees(lp.slow), ".2f"), Number(math.degrees(lp.quick), ".2f")
    return phrase("md.time_ratio", slow=slow, quick=quick, start=start, end=end,
                  sense=Word(sense), ratio=Number(lp.time_ratio, ".4f"))


def overall_sections(ex: Exercise, overall: Overall, figures: list[SolutionFigure]
                     ) -> list[Section]:
    """steps.md's part for the mechanism as a whole: the limit positions (with the time
    ratio they give), then the answers about it."""
    out = [Section(phrase("md.whole"), level=1)]
    if overall.work.has("limits"):
        said = Paragraph(time_ratio(ex.mechanism, drawn_limits(overall.work)))
        out += [Section(said_heading(f.heading), (Steps(tuple(f.shown.numbered())), said),
                        (f.stem,)) for f in figures]
    units = ex.mechanism.units
    rows = tuple((name, overall_text(name, q.value, units), overall_text(name, q.reference, units),
                  f"{q.rel_error:.2g}", q.said or Word(q.method))
                 for name, q in overall.quantities.items())
    return out + [Section(phrase("md.results"), (Table(phrase("md.whole_columns"), rows, 5),))]


def position_sections(sol: Solution, figures: list[SolutionFigure], *, heading: bool
                      ) -> list[Section]:
    """One position's part of steps.md: the input as drawn, its figures' numbered steps, its
    notes, then its results. ``heading`` puts the position's own heading first (several
    positions)."""
    m = sol.assembly.mechanism           # with the input's rates as drawn (converted, if given)
    d = m.drive
    drawn = Paragraph(phrase("md.position", link=str(d.link), angle=m.units.angle_brief(d.angle),
                             omega=significant(abs(d.omega)),
                             sense=Word("ccw" if d.omega > 0 else "cw"),
                             alpha=significant(d.alpha),
                             given=None if d.alpha_given else phrase("md.not_given")))
    out = [Section(phrase("md.at", where=sol.position.label) if heading else None, (drawn,),
                   level=1)]
    for f in figures:
        parts = [(f.heading, Panel.SPACE, f.shown)] if f.shown else []
        for title, panel, shown, *elsewhere in parts + list(f.panels):
            steps = Steps(tuple(shown.numbered(panel)))
            if steps.items:          # not a panel the exercise draws nothing in
                # A part drawn in no figure of its own (the inertia loads' images on the
                # acceleration polygon) names no file.
                out.append(Section(said_heading(title), (steps,), () if elsewhere else (f.stem,)))
    out.append(Section(blocks=(Notes(tuple(sol.notes)),)))
    rows = []
    for name, q in sol.quantities.items():
        q = q.in_file_axes(m)
        for label, qq in [(name, q)] + [(f"{name} ({m_})", a) for m_, a in q.alternatives.items()]:
            rows.append((label, show(qq.value, m.units, name), show(qq.reference, m.units, name),
                         f"{qq.rel_error:.2g}", Word(method_words(qq.method))))
    return out + [Section(phrase("md.results"), (Table(phrase("md.columns"), tuple(rows), 5),))]
