"""An engine's problem sheet (:mod:`.handout`)."""

from __future__ import annotations

from tarsim.constructions.errors import InputError

__all__ = ["engine_sheets"]


def engine_sheets(ex, sheet):
    """Refused: an engine has no sheet yet."""
    raise InputError(f"{ex.id}: a problem sheet is written for a rotor whose masses are all "
                     "given in kg and whose balancing masses are asked; this one has none yet")
