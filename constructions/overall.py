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

from . import asks as A
from .checks import Answer
from .model import Mechanism
from .reference.rotatability import four_bar_spans, grashof_class, length_range

__all__ = ["answer_mobility", "answer_grashof", "grashof_askable", "GRASHOF_WHY_NOT"]

GRASHOF_WHY_NOT = {A.GrashofClass: "Grashof's rule classifies a four-bar of four pins, and this "
                                   "is not one"}
"""Why a mechanism that is no four-bar has no Grashof class."""


def grashof_askable(mech: Mechanism) -> set[str]:
    """The class and the range of each length, of a four-bar of four pins."""
    spans = four_bar_spans(mech)
    return set() if spans is None else {"grashof"} | {f"range_{s}" for s in spans}


def answer_mobility(work, ask: A.Mobility) -> Answer:
    """Grübler's count."""
    dof, n, f1, f2 = work.mechanism.mobility()
    return Answer(ask, {"value": dof}, 1.0, f"Grübler: 3({n} − 1) − 2·{f1} − {f2}")


def answer_grashof(work, ask: A.GrashofClass | A.LengthRange) -> Answer:
    """The class by S + L against P + Q, or a length's range from the inequalities' breakpoints."""
    m = work.mechanism
    gc = grashof_class(m)
    if isinstance(ask, A.LengthRange):
        index = four_bar_spans(m)[ask.span]
        lo, hi = length_range(gc.lengths, index)
        return Answer(ask, {"low": lo, "high": hi, "class": gc.kind, "length": gc.lengths[index]},
                      1.0, "Grashof's inequalities, at their breakpoints; checked by bisecting "
                           "the turning test")
    s, p, q, l_ = sorted(gc.lengths)
    said = m.units.length_text
    return Answer(ask, {"class": gc.kind, "s_plus_l": s + l_, "p_plus_q": p + q}, 1.0,
                  f"Grashof: S + L = {said(s + l_)} against P + Q = {said(p + q)}; checked by "
                  "turning each link")
