"""What an exercise asks of the mechanism as a whole, at no single position.

* ``dof``: Grübler's count, checked against the nullity of the loop equations'
  Jacobian;
* ``grashof``: the four-bar's class by S + L ≤ P + Q, checked by turning each link;
* ``range_AB`` (any link's length, ``range_O2O4`` for the frame): the lengths over
  which the class stays as it is, from the inequalities' breakpoints, checked by
  bisecting the turning test;
* ``time_ratio`` and ``stroke``: from the limit positions drawn by compass,
  checked where the analytic solver's output velocity changes sign.

These land in results.json's top-level ``quantities``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from ..constructions.reference.mobility import mobility_by_rank
from ..constructions.reference.centres import tolerance
from ..constructions.reference.limits import limit_reference
from ..constructions.errors import InputError
from ..constructions.limit_positions import LimitPositions, draw_limit_positions
from ..constructions.model import Mechanism
from ..constructions.reference.rotatability import (class_by_rotation, grashof_class, four_bar_spans, length_range,
                                        length_range_by_rotation)

from .solution import Quantity

__all__ = ["Overall", "solve_overall"]


@dataclass
class Overall:
    """The whole-mechanism answers and the limit-position construction they came from."""

    quantities: dict[str, Quantity] = field(default_factory=dict)
    limits: LimitPositions | None = None


def solve_overall(mech: Mechanism, asked: tuple[str, ...]) -> Overall:
    """Answer each of ``asked`` (``dof``, ``grashof``, ``range_<XY>``, ``time_ratio``, ``stroke``).

    Raises
    ------
    TarsimError
        If the limit positions cannot be drawn or the crank does not turn fully.
    """
    out = Overall()
    q = out.quantities
    if "dof" in asked:
        q["dof"] = _dof(mech)
    if "grashof" in asked:
        q["grashof"] = _grashof(mech)
    for name in asked:
        if name.startswith("range_"):
            q[name] = _range(mech, name[len("range_"):])
    if "time_ratio" in asked or "stroke" in asked:
        lp = out.limits = draw_limit_positions(mech)
        how = ("lever tangent to the crank circle" if lp.kind == "slotted lever"
               else "crank and rod in line")
        method = f"limit positions by compass ({how})"
        ref = limit_reference(mech, point=lp.point, link=lp.output)
        if "time_ratio" in asked:
            value = {"value": lp.time_ratio, "slow_deg": math.degrees(lp.slow),
                     "quick_deg": math.degrees(lp.quick)}
            reference = {"value": ref.time_ratio, "slow_deg": math.degrees(ref.slow),
                         "quick_deg": math.degrees(ref.quick)}
            q["time_ratio"] = Quantity("time_ratio", value, reference,
                                       abs(lp.time_ratio - ref.time_ratio) / ref.time_ratio,
                                       tolerance(lp.conditioning), lp.conditioning, method)
        if "stroke" in asked:
            if lp.stroke is None:
                raise InputError("the stroke is measured on a block that slides on a frame guide "
                                 "and is driven through the limit positions; this mechanism has "
                                 "none")
            q["stroke"] = Quantity("stroke", {"value": lp.stroke, "point": lp.point},
                                   {"value": ref.stroke, "point": lp.point},
                                   abs(lp.stroke - ref.stroke) / max(ref.stroke, 1e-300),
                                   tolerance(lp.conditioning), lp.conditioning, method)
    return out


def _dof(mech: Mechanism) -> Quantity:
    dof, n, f1, f2 = mech.mobility()
    rank = mobility_by_rank(mech)
    return Quantity("dof", {"value": dof}, {"value": rank}, float(abs(dof - rank)), 0.0, 1.0,
                    f"Grübler: 3({n} − 1) − 2·{f1} − {f2}")


def _grashof(mech: Mechanism) -> Quantity:
    gc = grashof_class(mech)
    by_turning = class_by_rotation(gc.lengths)
    s, p, q_, l_ = sorted(gc.lengths)
    value = {"class": gc.kind, "s_plus_l": s + l_, "p_plus_q": p + q_}
    return Quantity("grashof", value, {"class": by_turning, "s_plus_l": s + l_, "p_plus_q": p + q_},
                    0.0 if _same_class(gc.kind, by_turning) else 1.0, 0.0, 1.0,
                    f"Grashof: S + L = {_mm(mech, s + l_)} against P + Q = {_mm(mech, p + q_)}; "
                    "checked by turning each link")


def _mm(mech: Mechanism, metres: float) -> str:
    return mech.units.length_text(metres)


def _same_class(by_rule: str, by_turning: str) -> bool:
    """A change-point linkage turns like a class it borders, so the turning test may name
    any; it is judged by the inequality alone."""
    return by_rule == by_turning or by_rule == "change-point"


def _range(mech: Mechanism, span: str) -> Quantity:
    gc = grashof_class(mech)
    index = four_bar_spans(mech)[span]
    lo, hi = length_range(gc.lengths, index)
    rlo, rhi = length_range_by_rotation(gc.lengths, index)
    size = max(gc.lengths)
    err = max(abs(lo - rlo), 0.0 if hi is None and rhi is None
              else abs((hi or math.inf) - (rhi or math.inf))) / size
    value = {"low": lo, "high": hi, "class": gc.kind, "length": gc.lengths[index]}
    reference = {"low": rlo, "high": rhi, "class": class_by_rotation(gc.lengths)}
    return Quantity(f"range_{span}", value, reference, err if math.isfinite(err) else 1.0,
                    1e-9, 1.0, "Grashof's inequalities, at their breakpoints; checked by bisecting the "
                    "turning test")
