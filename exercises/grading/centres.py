"""Instant centres on a drawn space diagram, graded against tarsim's.

The drawing's mechanism points, labelled as the file names them (O2, A, B), fix its frame:
the two found farthest apart give its scale and turn, and the others its hand. Each centre
labelled ``I13``, ``13`` or ``I₁₃`` is then held to the pen of the exercise's drafting
precision (:class:`~.drafting.Drafting`) over its construction's conditioning: a centre
found by crossing near-parallel Kennedy lines gets the slack the crossing implies. A centre
at infinity is not graded on paper.
"""

from __future__ import annotations

import math
import re

from .drafting import DRAFTING, Drafting
from .drawing import Drawing
from .grade import Grade, Item
from .matching import LEAST_CONDITIONING, Frame, match, rounded

__all__ = ["grade_centres", "read_centre"]

Vec = tuple[float, float]


def read_centre(text: str) -> str | None:
    """A centre's name as results.json spells it, or None.

    >>> read_centre("I13"), read_centre("13"), read_centre("I₂₄"), read_centre("I1,3")
    ('I13', 'I13', 'I24', 'I13')
    """
    t = text.strip().translate(_DIGITS).replace(",", "").replace(" ", "").replace("_", "")
    m = re.fullmatch(r"[Ii]?(\d)(\d)", t)
    if m is None or m[1] == m[2]:
        return None
    i, j = sorted((int(m[1]), int(m[2])))
    return f"I{i}{j}"


_DIGITS = str.maketrans({chr(0x2080 + d): str(d) for d in range(10)})


def grade_centres(out: Grade, sol, drawing: Drawing, drafting: Drafting = DRAFTING) -> None:
    """Grade the centres ``drawing`` labels, if any, into ``out``, at ``drafting``'s
    precision."""
    points = {n.lower(): n for n in sol.work.mechanism.point_names}

    def read(text: str):
        name = read_centre(text)
        if name is not None:
            return ("I", name)
        t = text.strip().translate(_DIGITS).replace("_", "").lower()
        return ("P", points[t]) if t in points else None
    lost: list[str] = []
    found = match(drawing, read, lost)
    if lost:
        out.notes.append(f"labels near no point, not graded: {', '.join(lost)}")
    centres = {name for kind, name in found if kind == "I"}
    if not centres:
        return
    true = sol.work.kinematics.points
    pins = [(name, p) for (kind, name), p in found.items() if kind == "P"]
    if len(pins) < 2:
        out.notes.append("the space diagram needs two of the mechanism's points labelled "
                         "(O2, A, …) to grade its centres")
        return
    apart = [(p, q) for p in pins for q in pins
             if p[0] < q[0] and math.dist(true[p[0]], true[q[0]]) > 0]
    if not apart:                           # points that lie together fix no scale or turn
        named = ", ".join(sorted(n for n, _ in pins))
        out.notes.append(f"the space diagram's labelled points ({named}) lie together in the "
                         "mechanism here: label two apart to grade its centres")
        return
    a, b = max(apart, key=lambda pq: math.dist(pq[0][1], pq[1][1]))
    world = (true[b[0]][0] - true[a[0]][0], true[b[0]][1] - true[a[0]][1])
    paper = (b[1][0] - a[1][0], b[1][1] - a[1][1])
    frames = [Frame.fitted(world, paper, hand, origin=true[a[0]], at=a[1])
              for hand in (1.0, -1.0)]
    frame = min(frames, key=lambda f: sum(math.dist(f.place(true[n]), p) for n, p in pins))
    quantities = sol.quantities
    for name in sorted(centres | {q for q in quantities if re.fullmatch(r"I\d\d", q)}):
        q = quantities.get(name)
        got = found.get(("I", name))
        if q is None or "point" not in q.reference:
            if got is not None:
                out.items.append(Item(name, "extra", None, rounded(got), None,
                                      f"{name} is not asked here, or lies at infinity"))
            continue
        exp = frame.place(tuple(q.reference["point"]))
        tol = drafting.pen / max(q.conditioning, LEAST_CONDITIONING)
        if got is None:
            out.items.append(Item(name, "missing", rounded(exp), None, round(tol, 3),
                                  f"{name} is not labelled on the drawing"))
            continue
        miss = math.dist(exp, got)
        item = Item(name, "correct", rounded(exp), rounded(got), round(tol, 3))
        if miss > tol:
            item.verdict = "wrong position"
            item.message = f"{name} is {miss:.1f} mm from where Kennedy's lines cross"
        out.items.append(item)
