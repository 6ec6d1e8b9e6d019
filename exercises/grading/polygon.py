"""A drawn velocity or acceleration polygon, graded tip by tip against tarsim's.

**Matching.** Labels are paired with line ends and dots (:func:`.matching.match`). They
are read as a course writes them, whatever the case, the subscripts
or the prime: ``o``, ``ov``, ``o_v`` is the velocity pole and ``o'``, ``oa``, ``o_a`` the
acceleration pole; ``b``, ``a4`` (or ``a₄``) a velocity tip, ``b'`` or ``b′`` an
acceleration tip.

**The frame.** A drawing may be turned, mirrored and drawn at its own scale. The pole and
the input's tip (the crank pin's, whose vector the data give) fix all three: the scale from
the statement written on the drawing ("1 cm = 0.5 m/s") if there is one, else the one the
exercise states, else from the input's vector; its turn from that vector; the mirror by
whichever of the two hands puts the other tips nearer.

**Tolerance.** A tip is held to the drafting precision (:class:`~.drafting.Drafting`: a
pen of 0.5 mm and a set square true to 0.5° unless the exercise's ``[grading]`` says
otherwise) over the vector's length, over the tip's own conditioning, compounded along
the acts that found it (a tip found by crossing near-parallel lines gets the slack its
conditioning implies), never less than the pen.

**Verdicts.** Off by more than its tolerance, a tip's vector from the pole is ``wrong
sense`` if it points the other way, ``wrong magnitude`` if only its length is off, ``wrong
direction`` otherwise. A tip that lands where a reversed Coriolis component would put it
is named as such: the classic error.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass

from ...constructions.acceleration_polygon import drawn_acceleration_polygon
from ...constructions.velocity_polygon import drawn_velocity_polygon
from .drafting import DRAFTING, Drafting
from .drawing import Drawing
from .matching import LEAST_CONDITIONING, Frame, match, rounded
from .grade import Grade, Item

__all__ = ["grade_polygons", "read_label"]

Vec = tuple[float, float]


@dataclass
class _Expected:
    """One polygon as tarsim draws it: its kind ("v" or "a"), its tips' vectors from the
    pole (SI), the input's tip, its conditioning, and each slot point's Coriolis component."""

    kind: str
    tips: dict[str, Vec]
    given: str
    conditioning: float
    coriolis: dict[str, tuple[Vec, int]]
    required: frozenset[str] = frozenset()
    """The tips a drawing must show: the mechanism's own moving points (a coincident point
    on a slot is a helper the drawing may show or not)."""
    scale: float | None = None
    """Paper mm per SI unit the exercise states its polygon at, if it states one."""
    tip_conditioning: dict[str, float] | None = None
    """Each tip's own conditioning, compounded along the acts that found it."""


def read_label(text: str) -> tuple[str, str] | None:
    """A label as (kind, tip): ("v", "b"), ("a", "b4"), ("v", "o") for a pole; None if it
    names no polygon point.

    >>> read_label("B₄′"), read_label("o_v"), read_label("oa"), read_label("V_B")
    (('a', 'b4'), ('v', 'o'), ('a', 'o'), None)
    """
    t = text.strip().translate(_PLAIN).lower().replace("_", "").replace(" ", "")
    prime = t.endswith("'")
    t = t.rstrip("'")
    if t in ("o", "ov", "oa"):
        return ("a" if prime or t == "oa" else "v"), "o"
    if re.fullmatch(r"[a-z]\d*", t):
        return ("a" if prime else "v"), t
    return None


_PLAIN = str.maketrans({**{chr(0x2080 + d): str(d) for d in range(10)},
                        "′": "'", "’": "'", "ʹ": "'", "`": "'"})


def grade_polygons(out: Grade, sol, drawing: Drawing, drafting: Drafting = DRAFTING) -> None:
    """Grade the polygons ``drawing`` labels, if any, into ``out``, at ``drafting``'s
    precision."""
    lost: list[str] = []
    found = match(drawing, read_label, lost)
    # A polygon is drawn where its pole is; point names alone (A, B) are a space diagram's.
    kinds = {k for k, n in found if n == "o"}
    if not kinds:
        return
    if lost:
        out.notes.append(f"labels near no line end or dot, not graded: {', '.join(lost)}")
    polygons = _expected(sol)
    stated = _stated_scales(drawing, out.notes)
    overlay = []
    for kind in sorted(kinds):
        if kind not in polygons:
            out.notes.append(f"the drawing has {_noun(kind)} polygon labels, which this "
                             "exercise does not draw")
            continue
        overlay.append(_grade_one(polygons[kind], found, stated.get(kind), out, drafting))
    out.overlay = (drawing, overlay)


def _noun(kind: str) -> str:
    return "a velocity" if kind == "v" else "an acceleration"


def _expected(sol) -> dict[str, _Expected]:
    """The polygons tarsim draws at the position, by kind."""
    work = sol.work
    mech = work.mechanism
    given = mech.link(mech.drive.link).names[-1].lower()
    moving = frozenset(n.lower() for n in mech.point_names if 1 not in mech.links_at(n))

    def stated(per_cm: float | None) -> float | None:
        """A stated polygon scale (file units per paper cm) as paper mm per SI unit."""
        return None if not per_cm else 10.0 / (per_cm * mech.units.metres)
    out = {}
    vp = drawn_velocity_polygon(work)
    c = work.assembly

    def each(poly) -> dict[str, float]:
        return {n.lower(): c[r].conditioning for n, r in poly.tips.items()}
    out["v"] = _Expected("v", {n.lower(): vp.vector(n) for n in vp.tips}, given,
                         vp.worst(), {}, moving, stated(work.scales.velocity_polygon), each(vp))
    if work.has("acceleration polygon"):
        ap = drawn_acceleration_polygon(work)
        cor = {}
        for point, (_, _, _) in ap.coriolis.items():
            link = next((s.guide_link for s in work.mechanism.slides if s.point == point),
                        None)
            cor[point.lower()] = (ap.coriolis_of(point), link)
        out["a"] = _Expected("a", {n.lower(): ap.vector(n) for n in ap.tips}, given,
                             ap.worst(), cor, moving, stated(work.scales.acceleration_polygon),
                             each(ap))
    return out


# A number starts where no digit stands before it, so a long run of digits is tried once.
_SCALE = re.compile(r"(?<![\d.,])(\d+(?:[.,]\d+)?)\s*cm\s*=\s*(\d+(?:[.,]\d+)?)\s*"
                    r"(mm|cm|m)\s*/\s*s\s*(²|\^2|2)?", re.IGNORECASE)
_UNIT = {"mm": 1e-3, "cm": 1e-2, "m": 1.0}


_SCALES = (1e-9, 1e9)
"""The scales a drawing may state, paper mm per SI unit: beyond them a statement is a slip
of the pen, not a scale, and is not held to."""


def _stated_scales(drawing: Drawing, notes: list[str]) -> dict[str, float]:
    """Scales written on the drawing, paper mm per SI unit, by kind ("1 cm = 0.5 m/s",
    "3 cm = 18 cm/s", "1 cm = 2 m/s²"); one no drawing is drawn at is said in ``notes``."""
    out = {}
    for label in drawing.labels:
        m = _SCALE.search(label.text.replace(" ", " "))
        if m:
            cm, amount = float(m[1].replace(",", ".")), float(m[2].replace(",", "."))
            scale = 10.0 * cm / (amount * _UNIT[m[3].lower()]) if amount > 0 else math.inf
            if _SCALES[0] <= scale <= _SCALES[1]:
                out["a" if m[4] else "v"] = scale
            else:
                notes.append(f"the scale written '{m[0][:40]}' is no scale a drawing is drawn "
                             "at, so it was not held to")
    return out


def _grade_one(poly: _Expected, found, stated: float | None, out: Grade, drafting: Drafting):
    """Grade one polygon's tips into ``out``; return what its overlay draws."""
    mark = "′" if poly.kind == "a" else ""
    pole, given = found.get((poly.kind, "o")), found.get((poly.kind, poly.given))
    e_given = poly.tips.get(poly.given, (0.0, 0.0))
    if pole is None or given is None or math.hypot(*e_given) == 0.0:
        out.notes.append(f"the {_noun(poly.kind)[2:].strip()} polygon needs its pole o{mark} "
                         f"and the input's tip {poly.given}{mark} labelled to be graded")
        return None
    f_given = (given[0] - pole[0], given[1] - pole[1])
    # The scale written on the drawing, else the exercise's, else the input's vector's.
    stated = stated or poly.scale
    frames = [Frame.fitted(e_given, f_given, hand, stated, at=pole) for hand in (1.0, -1.0)]
    others = [n for (k, n) in found if k == poly.kind and n not in ("o", poly.given)
              and n in poly.tips]

    def residual(frame):
        return sum(math.dist(found[(poly.kind, n)], frame.place(poly.tips[n]))
                   for n in others)
    frame = min(frames, key=residual)
    names = sorted(set(poly.tips) | {n for (k, n) in found if k == poly.kind} - {"o"})
    expected_at = {}
    for name in names:
        label = f"{name}{mark}"
        if name not in poly.tips:
            out.items.append(Item(label, "extra", None, list(found[(poly.kind, name)]), None,
                                  f"{label} names no point of this polygon"))
            continue
        exp = frame.place(poly.tips[name])
        expected_at[name] = exp
        if name == poly.given and stated is None:
            continue                              # it set the scale: nothing to grade
        length = math.dist(exp, pole)
        # The tip's own conditioning: a tip found by a clean cut is held tight, one by a
        # near-parallel crossing gets the slack that crossing implies.
        cond = max((poly.tip_conditioning or {}).get(name, poly.conditioning),
                   LEAST_CONDITIONING)
        tol = max(drafting.pen, (drafting.pen + length * math.tan(drafting.angle)) / cond)
        got = found.get((poly.kind, name))
        if got is None:
            if name in poly.required:
                out.items.append(Item(label, "missing", rounded(exp), None, round(tol, 3),
                                      f"{label} is not labelled on the drawing"))
            continue
        out.items.append(_verdict(label, name, poly, frame, pole, exp, got, tol))
    _name_swaps(out.items)
    return poly, frame, pole, expected_at


def _verdict(label: str, name: str, poly: _Expected, frame, pole: Vec, exp: Vec, got: Vec,
             tol: float) -> Item:
    """The verdict on one tip found at ``got`` where ``exp`` was expected."""
    item = Item(label, "correct", rounded(exp), rounded(got), round(tol, 3))
    miss = math.dist(exp, got)
    if miss <= tol:
        return item
    for point, (cor, link) in poly.coriolis.items():
        for sign in (2.0, -2.0):
            flipped = frame.place((poly.tips[name][0] + sign * cor[0],
                                   poly.tips[name][1] + sign * cor[1]))
            if math.hypot(*cor) > 0 and math.dist(flipped, got) <= tol:
                item.verdict = "wrong sense"
                item.message = (f"Coriolis component at {point.upper()} drawn opposite: turn "
                                f"V_rel 90° in the sense of ω{link}")
                return item
    e = (exp[0] - pole[0], exp[1] - pole[1])
    f = (got[0] - pole[0], got[1] - pole[1])
    le, lf = math.hypot(*e), math.hypot(*f)
    turn = abs(math.remainder(math.atan2(f[1], f[0]) - math.atan2(e[1], e[0]), 2 * math.pi))
    slack = math.atan2(tol, max(le, tol))
    if abs(turn - math.pi) <= slack and abs(lf - le) <= tol:
        item.verdict = "wrong sense"
        item.message = f"{label} points the other way from the pole"
    elif turn <= slack:
        item.verdict = "wrong magnitude"
        item.message = f"{label} is {lf - le:+.1f} mm off along its direction from the pole"
    else:
        item.verdict = "wrong direction"
        item.message = (f"{label} is {miss:.1f} mm from where it belongs "
                        f"({math.degrees(turn):.1f}° off)")
    return item


def _name_swaps(items: list[Item]) -> None:
    """Two tips each found where the other belongs: say their labels are swapped."""
    wrong = [i for i in items if i.verdict not in ("correct", "missing", "extra")
             and i.found and i.expected]
    for i in wrong:
        for j in wrong:
            if i is not j and math.dist(i.found, j.expected) <= j.tolerance and \
                    math.dist(j.found, i.expected) <= i.tolerance:
                i.message = f"the labels {i.name} and {j.name} are swapped"
