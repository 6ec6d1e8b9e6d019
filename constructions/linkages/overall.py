"""The mechanism as a whole, by count and inequality: Grübler's DOF and Grashof's class.

* ``dof``: Grübler's count 3(n − 1) − 2F1 − F2, checked against the nullity of
  the loop equations' Jacobian;
* ``grashof``: the four-bar's class by S + L against P + Q, checked by turning
  each link;
* ``range_AB`` (any link's pins, ``range_O2O4`` for the frame): the lengths over
  which the class holds, from the inequalities' breakpoints, checked by bisecting
  the turning test.

They draw nothing: their answers stand in results.json's top-level quantities.
"""

from __future__ import annotations

from .. import asks as A
from ..checks import Answer, grashof_value
from ..errors import AssemblyError
from ..model import Mechanism
from ..narration import Number, Phrase, Word, narrate, phrase
from ..reference.rotatability import four_bar_spans, grashof_class, length_range

__all__ = ["answer_mobility", "answer_grashof", "grashof_askable", "GRASHOF_WHY_NOT"]

GRASHOF_WHY_NOT = {A.GrashofClass: "Grashof's rule classifies a four-bar of four pins, and this "
                                   "is not one"}
"""Why a mechanism that is no four-bar has no Grashof class."""


def grashof_askable(mech: Mechanism) -> set[str]:
    """The class and the range of each length, of a four-bar of four pins."""
    spans = four_bar_spans(mech)
    return set() if spans is None else {"grashof"} | {f"range_{s}" for s in spans}


def answer_mobility(work, ask: A.Mobility) -> Answer:
    """Grübler's count, and the freedom the position adds where two assemblies meet in it."""
    dof, n, f1, f2 = work.mechanism.mobility()
    said = phrase("overall.grubler", n=n, f1=f1, f2=f2)
    try:
        meeting = work.assembly.meetings
    except AssemblyError:   # not at this position: Grübler's count stands alone
        meeting = ()
    if not meeting:
        return _answer(ask, {"value": dof}, said)
    points = [meeting[0]]                   # "B", or "A and B", said in any language
    for point in meeting[1:]:
        points += [Word("and"), point]
    return _answer(ask, {"value": dof, "here": dof + len(meeting)},
                   phrase("overall.meeting" if len(meeting) == 1 else "overall.meetings",
                          grubler=said, points=points, here=Number(dof + len(meeting), "d")))


def answer_grashof(work, ask: A.GrashofClass | A.LengthRange) -> Answer:
    """The class by S + L against P + Q, or a length's range from the inequalities' breakpoints."""
    m = work.mechanism
    gc = grashof_class(m)
    which = phrase("overall.change_point") if gc.kind == "change-point" else None
    if isinstance(ask, A.LengthRange):
        index = four_bar_spans(m)[ask.span]
        lo, hi = length_range(gc.lengths, index)
        return _answer(ask, {"low": lo, "high": hi, "class": gc.kind,
                             "length": gc.lengths[index]},
                       phrase("overall.range", which=which))
    value, said = grashof_value(gc.kind, gc.lengths), m.units.length_said
    return _answer(ask, value, phrase("overall.grashof", s_l=said(value["s_plus_l"]),
                                      p_q=said(value["p_plus_q"]), which=which))


def _answer(ask: A.Ask, value: dict, said: Phrase) -> Answer:
    """An answer by count or inequality (exact: conditioning 1), its method said in English
    for results.json and kept as a phrase for steps.md in any language."""
    return Answer(ask, value, 1.0, narrate(said), said=said)
