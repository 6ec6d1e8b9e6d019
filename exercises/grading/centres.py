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
from .labels import plain, read_centre
from .marks import Kind
from .matching import LEAST_CONDITIONING, Frame, match, rounded

__all__ = ["grade_centres", "read_centre", "space_frame"]

Vec = tuple[float, float]


PINS = {Kind.DOT: 0.0, Kind.BLOCK: 0.0, Kind.TIP: 4.0, Kind.JUNCTION: 4.0, Kind.END: 5.0}
"""What a space diagram's label costs to put on each kind of mark (mm, beside its
distance): a pin is drawn as a circle, a block as a box, so a hatching's corner or a link's
end by the label loses to the pin four millimetres farther (a label stands a few
millimetres from what it names)."""


def space_frame(sol, drawing: Drawing, notes: list[str]) -> tuple[Frame | None, dict]:
    """How the space diagram ``drawing`` labels lays the mechanism on paper (None if it does
    not: fewer than two of its points labelled apart, said in ``notes`` when it labels
    centres), and the centres it labels, by name."""
    points = {n.lower(): n for n in sol.work.mechanism.point_names}

    def read(text: str):
        name = read_centre(text)
        if name is not None:
            return ("I", name)
        t = plain(text).lower()
        return ("P", points[t]) if t in points else None
    lost: list[str] = []
    found = match(drawing, read, lost, PINS)
    centres = {name: p for (kind, name), p in found.items() if kind == "I"}
    if lost and centres:
        notes.append(f"labels near no point, not graded: {', '.join(lost)}")
    true = sol.work.kinematics.points
    pins = [(name, p) for (kind, name), p in found.items() if kind == "P"]
    if len(pins) < 2:
        if centres:
            notes.append("the space diagram needs two of the mechanism's points labelled "
                         "(O2, A, …) to grade its centres")
        return None, centres
    apart = [(p, q) for p in pins for q in pins
             if p[0] < q[0] and math.dist(true[p[0]], true[q[0]]) > 0]
    if not apart:                           # points that lie together fix no scale or turn
        if centres:
            named = ", ".join(sorted(n for n, _ in pins))
            notes.append(f"the space diagram's labelled points ({named}) lie together in the "
                         "mechanism here: label two apart to grade its centres")
        return None, centres
    a, b = max(apart, key=lambda pq: math.dist(pq[0][1], pq[1][1]))
    world = (true[b[0]][0] - true[a[0]][0], true[b[0]][1] - true[a[0]][1])
    paper = (b[1][0] - a[1][0], b[1][1] - a[1][1])
    frames = [Frame.fitted(world, paper, hand, origin=true[a[0]], at=a[1])
              for hand in (1.0, -1.0)]
    # Points all on one line (the crank-shaper at θ2 = 90°) leave the hand open: the
    # labelled centres, where they stand off it, settle it, else the sheet's own hand.
    known = {n: q.reference["point"] for n, q in sol.quantities.items()
             if n in centres and "point" in q.reference}

    def pinned(f: Frame) -> float:
        return sum(math.dist(f.place(true[n]), p) for n, p in pins)

    def centred(f: Frame) -> float:
        return sum(min(math.dist(f.place(tuple(w)), centres[n]), _OPEN) for n, w in known.items())
    if abs(pinned(frames[0]) - pinned(frames[1])) >= _OPEN:
        return min(frames, key=pinned), centres
    if abs(centred(frames[0]) - centred(frames[1])) >= _OPEN:
        return min(frames, key=centred), centres
    return frames[0], centres


_OPEN = 1.0
"""Paper (mm): two hands whose points' misses differ by less are told apart by the
centres."""


def grade_centres(out: Grade, sol, frame: Frame | None, centres: dict,
                  drafting: Drafting = DRAFTING) -> None:
    """Grade the ``centres`` a space diagram labels, laid by ``frame``, into ``out``, at
    ``drafting``'s precision. A centre not asked here is said in a note and costs nothing."""
    quantities = sol.quantities
    asked = {n for n, q in quantities.items() if re.fullmatch(r"I\d\d", n)
             and "point" in q.reference}
    if frame is None or not asked & set(centres):
        if centres and frame is not None:
            out.notes.append(f"centres not asked here, or at infinity, not graded: "
                             f"{', '.join(sorted(centres))}")
        return
    unasked = []
    for name in sorted(set(centres) | {q for q in quantities if re.fullmatch(r"I\d\d", q)}):
        q = quantities.get(name)
        got = centres.get(name)
        if q is None or "point" not in q.reference:
            if got is not None:
                unasked.append(name)
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
    if unasked:
        out.notes.append(f"centres not asked here, or at infinity, not graded: "
                         f"{', '.join(unasked)}")
