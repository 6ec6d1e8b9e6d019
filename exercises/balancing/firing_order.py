"""An in-line engine's cranks from its firing order, as the textbooks give multi-cylinder
engines: "a four-cylinder two-stroke engine fires in the order 1-4-2-3".

The cylinders fire at equal intervals of the crank's turn, δ = 360°·(strokes/2)/N (a
two-stroke cylinder fires once a turn, a four-stroke once in two); the cylinder that fires
next reaches its inner dead centre δ later, so its crank is set δ behind the one before it
in the sense of rotation (counter-clockwise, as every angle of the file). Cylinder 1's
crank is the reference, at 0°.
"""

from __future__ import annotations

import math

from tarsim.constructions.narration import numeral, words

__all__ = ["firing_cranks", "firing_line", "read_firing_order"]


def firing_cranks(order: tuple[int, ...], strokes: int) -> tuple[float, ...]:
    """Each cylinder's crank angle (degrees, in [0, 360)), cylinder 1 first, for the firing
    ``order`` (a permutation of 1..N) of an engine of ``strokes`` strokes a cycle.

    >>> firing_cranks((1, 3, 4, 2), 4)
    (0.0, 180.0, 180.0, 0.0)
    >>> firing_cranks((1, 4, 2, 3), 2)
    (0.0, 180.0, 90.0, 270.0)
    """
    n = len(order)
    first = order.index(1)
    # δ·k for the k-th to fire after cylinder 1, in whole degrees times strokes/2 over n:
    # kept exact in a fraction of a turn before it is made degrees
    turn = {c: ((-(k - first) * strokes * 180) % (360 * n)) / n for k, c in enumerate(order)}
    return tuple(float(turn[c]) for c in range(1, n + 1))


def read_firing_order(t, one: dict, cylinders: list[dict]) -> tuple[tuple[int, ...], int] | None:
    """``[engine]``'s ``firing_order`` and ``strokes``, checked against the ``[[cylinder]]``
    tables (None where the file gives the cranks instead); each failure one line."""
    if "firing_order" not in one:
        if "strokes" in one:
            raise t.fail("strokes goes with firing_order: the cranks follow from the two "
                         "together; give firing_order = [1, 3, 4, 2], or leave strokes out",
                         "engine", "strokes")
        return None
    order = one["firing_order"]
    n = len(cylinders)
    if not (isinstance(order, list) and all(isinstance(c, int) and not isinstance(c, bool)
                                            for c in order)):
        raise t.fail("firing_order is the cylinders' numbers in the order they fire, such as "
                     "[1, 3, 4, 2]", "engine", "firing_order")
    if n < 2 or sorted(order) != list(range(1, n + 1)):
        raise t.fail(f"firing_order must name each of the {n} [[cylinder]] tables once, 1 to "
                     f"{n}, got {order}", "engine", "firing_order")
    given = [i for i, c in enumerate(cylinders) if "crank" in c]
    if given:
        raise t.fail(f"cylinder {given[0] + 1} gives its crank and [engine] its firing order: "
                     "the firing order sets every crank; give one or the other", "cylinder",
                     "crank", given[0])
    strokes = one.get("strokes")
    if strokes not in (2, 4) or isinstance(strokes, bool):
        raise t.fail("with a firing order, give strokes = 4 (a four-stroke engine, firing "
                     "once in two turns) or strokes = 2 (once a turn)", "engine",
                     "strokes" if "strokes" in one else "firing_order")
    return tuple(order), strokes


def firing_line(e) -> str | None:
    """The line that says how an engine's cranks follow from its firing order (None where
    the file gives the cranks)."""
    if not e.firing_order:
        return None
    n = len(e.firing_order)
    return words("firing order {order}, {strokes}-stroke: a cylinder fires every {every}°, "
                 "each crank set that far behind the one fired before it: {cranks}",
                 order="-".join(str(c) for c in e.firing_order), strokes=str(e.strokes),
                 every=numeral(e.strokes * 180 / n, "g"),
                 cranks=", ".join(words("cylinder {number} at {angle}°", number=str(i),
                                        angle=numeral(math.degrees(t) % 360.0, ".4g"))
                                  for i, t in enumerate(e.cranks, start=1)))
