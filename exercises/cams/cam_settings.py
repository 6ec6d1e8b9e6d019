"""What each table of a cam file may hold, and the names the books give followers and laws.

A setting a table does not know is refused at its line, never read and dropped: a
``[[segment]]``'s ``acceleration_ratio`` ignored once gave an equal split and every number
of the rise wrong with no word said. The refusal names the known setting nearest the
unknown one, as a spelling slip or a near name (``acceleraton``, ``base``) usually is.

The books name a follower and a law in several ways ("flat-faced", "flat face",
"mushroom"; "uniform acceleration and retardation", "parabolic"; "SHM"): each is read as
the one name the solution uses (:data:`FOLLOWER_KINDS`, :data:`~tarsim.constructions.
reference.cam_laws.LAWS`), so the outputs read the same however the file says it.
"""

from __future__ import annotations

import difflib
import re
from typing import Any

from tarsim.constructions.reference.cam_laws import LAWS

__all__ = ["CAM_KEYS", "FOLLOWER_KEYS", "FOLLOWER_KINDS", "SEGMENT_KEYS", "UNIT_KEYS",
           "book_follower", "book_law", "refuse_unknown"]

CAM_KEYS = ("base_radius", "base_diameter", "pressure_angle", "rho_min", "disc_radius",
            "disc_diameter", "eccentricity", "speed", "sense", "kind")
"""A ``[cam]`` given by its follower's motion (``kind`` makes it a cam of arcs)."""

FOLLOWER_KEYS = ("kind", "radius", "diameter", "motion", "offset", "pivot", "arm")
"""A ``[follower]`` under a cam given by its follower's motion."""

SEGMENT_KEYS = ("kind", "angle", "time", "lift", "law", "divisions", "blend", "accelerating",
                "acceleration_ratio")
"""A ``[[segment]]`` of the follower's motion (its ``time`` in s in its angle's place)."""

UNIT_KEYS = ("length", "speed")
"""A cam file's ``[units]``."""

FOLLOWER_KINDS = ("knife-edge", "roller", "flat-faced")
"""The followers, by the names the solution uses."""

_FOLLOWER_NAMES = {
    "knife-edge": "knife-edge", "knife-edged": "knife-edge", "knife": "knife-edge",
    "roller": "roller",
    "flat-faced": "flat-faced", "flat-face": "flat-faced", "flat": "flat-faced",
    "mushroom": "flat-faced",
}
"""Each follower as the books name it, spaces and underscores read as hyphens and a
trailing "follower" left off ("knife edge follower", "flat faced")."""

_LAW_NAMES = {
    "uniform velocity": "uniform velocity", "constant velocity": "uniform velocity",
    "modified uniform velocity": "modified uniform velocity",
    "simple harmonic": "simple harmonic", "shm": "simple harmonic",
    "harmonic": "simple harmonic",
    "parabolic": "parabolic", "uniform acceleration": "parabolic",
    "uniform acceleration and retardation": "parabolic",
    "uniform acceleration and deceleration": "parabolic",
    "constant acceleration": "parabolic", "uarm": "parabolic",
    "cycloidal": "cycloidal", "cycloid": "cycloidal",
}
"""Each law as the books name it, case and a trailing "motion" aside ("Simple Harmonic
Motion", "uniform acceleration and retardation motion")."""


def book_follower(name: Any) -> str | None:
    """The follower ``name`` (a string as the file gives it) names, or None.

    Examples
    --------
    >>> book_follower("Flat face"), book_follower("knife edge follower"), book_follower("x")
    ('flat-faced', 'knife-edge', None)
    """
    if not isinstance(name, str):
        return None
    key = re.sub(r"[\s_-]+", "-", name.strip().lower()).removesuffix("-follower")
    return _FOLLOWER_NAMES.get(key)


def book_law(name: Any) -> str | None:
    """The law ``name`` (a string as the file gives it) names, one of
    :data:`~tarsim.constructions.reference.cam_laws.LAWS`, or None.

    Examples
    --------
    >>> book_law("SHM"), book_law("Uniform acceleration and retardation motion")
    ('simple harmonic', 'parabolic')
    """
    if not isinstance(name, str):
        return None
    key = re.sub(r"[\s_-]+", " ", name.strip().lower()).removesuffix(" motion").strip()
    law = _LAW_NAMES.get(key)
    return law if law in LAWS else None


_BOOK_NAMES = {"duration": "time", "seconds": "time", "period": "time", "interval": "time"}
"""Settings the books' words suggest, each read as the known one it means for the hint
("rises in 0.05 s": a segment's duration is its ``time``)."""


def refuse_unknown(t: dict[str, Any], keys: tuple[str, ...], where: str, fail,
                   table: str, index: int = 0, otherwise: str = "") -> None:
    """Refuse the first setting of ``t`` not in ``keys`` at its line (``table``'s
    ``index``-th entry; ``where`` names it in the message), naming the known setting
    nearest it, or all of them (or saying ``otherwise``) where none is near.

    Raises
    ------
    InputError
        Through ``fail``, for the first unknown setting.
    """
    for k in t:
        if k not in keys:
            book = _BOOK_NAMES.get(str(k))
            close = [book] if book in keys else difflib.get_close_matches(
                str(k), keys, n=1, cutoff=0.6) or [
                known for known in keys if known.startswith(f"{k}_")]
            if not close and otherwise:
                raise fail(otherwise, table, k, index)
            hint = f"did you mean '{close[0]}'?" if close else f"expected {', '.join(keys)}"
            raise fail(f"unknown setting '{k}' in {where}; {hint}", table, k, index)
