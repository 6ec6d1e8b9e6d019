"""The registry of dyad rules: the ways position by compass locates a joint.

A rule is a function of the :class:`~.assembly.Assembler` that draws something more
(a joint, a slot, a wheel's axis) from what is already drawn and returns True, or
returns False. :func:`dyad_rule` registers it under a name and an order; the walk tries
the rules in that order, lowest first (equal orders as they registered), and starts
again after each success. The rules live by the joints they close, in
:mod:`.dyad_cuts`, :mod:`.dyad_slots` and :mod:`.dyad_rolling`, which register them as
they load. Each kind of joint names the rules that locate it in
:data:`~.joint_rules.JOINT_RULES`, and the walk tries those of the kinds a mechanism has,
the pin's, and any rule no kind names (:func:`~.joint_rules.dyad_rules_for`).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from .assembly import Assembler

__all__ = ["DyadRule", "DYAD_RULES", "dyad_rule"]


@dataclass(frozen=True)
class DyadRule:
    """One way to locate a joint from what is drawn: ``locate`` draws it and returns True,
    or returns False; ``order`` is its place among the rules (lower is tried first)."""

    name: str
    order: int
    locate: Callable[[Assembler], bool]


DYAD_RULES: dict[str, DyadRule] = {}
"""Every dyad rule of position by compass, by name."""


def dyad_rule(name: str, order: int):
    """Register a function of the assembler as the dyad rule ``name``, tried at ``order``."""
    def register(locate: Callable[[Assembler], bool]) -> Callable[[Assembler], bool]:
        DYAD_RULES[name] = DyadRule(name, order, locate)
        return locate
    return register
