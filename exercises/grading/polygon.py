"""A drawn velocity or acceleration polygon, graded tip by tip against tarsim's.

**Matching.** Labels are paired with the points they name (:func:`.matching.match`) and
read as a course writes them (:mod:`.labels`): ``o``, ``o_v`` the velocity pole, ``o′``,
``o_a`` the acceleration pole, ``b``, ``a4``, ``a₄`` velocity tips, ``b′``, ``a′₄``,
``a₄′`` acceleration tips, and tarsim's own ``a₂ ≡ a₄``. A label that names no tip of the
polygon (a construction point, ``n′``) is said in a note and costs nothing.

**The frame.** A polygon is drawn in the space diagram's orientation, its directions taken
from the links with a set square: the space diagram's on the same sheet fixes its turn and
hand, else the sheet's own axes do (x to the right, y up). So a polygon drawn the other way
round (every velocity reversed, as by ω2 taken the wrong way) is wrong, not turned, and so
is one mirrored. Its scale is the one written on the sheet
("1 cm = 0.5 m/s"), or the exercise's where its ``[grading]`` requires it, else the
drawing's own, from the input's tip.

**Tolerance.** One rule for drawings and tables (:func:`.drafting.tolerance`): a pen of
0.5 mm and a set square true to 0.5° (or the exercise's ``[grading]``) over a vector drawn
at the exercise's scale, over the tip's own conditioning, compounded along the acts that
found it; on a drawing at another scale, the same share of the vector.

**Verdicts.** Off by more than its tolerance, a tip is ``reversed Coriolis`` where a
reversed Coriolis component puts it, ``swapped`` where another label's tip belongs and that
label where it belongs, ``wrong sense`` if it points the other way from the pole, ``wrong
magnitude`` if its direction is true to the set square and the pen, ``wrong direction``
otherwise; and ``follows from an earlier error`` where the construction, redone from the
tips drawn wrong before it, puts it (:mod:`.follow`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

from tarsim.constructions.linkages.acceleration_polygon import drawn_acceleration_polygon
from tarsim.constructions.linkages.velocity_polygon import drawn_velocity_polygon
from .drafting import DRAFTING, Drafting, exercise_scale, tolerance
from .drawing import Drawing
from .crossing import bands, reach, within
from .follow import Replay, reversed_coriolis
from .grade import FOLLOWS, Grade, Item
from .labels import read_label, read_names, tip_of
from .matching import LEAST_CONDITIONING, Frame, match, rounded
from .scale_text import stated_scales

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
    polygon: object
    """tarsim's drawn polygon, whose acts :mod:`.follow` redoes."""
    keys: dict[str, str]
    """Each tip (lower case) by the polygon's own name for it (``A4``)."""
    required: frozenset[str] = frozenset()
    """The tips a drawing must show: its moving points and slot points (A4)."""
    gradable: frozenset[str] = frozenset()
    """The tips graded where drawn: all but the frame's points, which stand at the pole."""
    scale: float | None = None
    """Paper mm per SI unit the exercise states its polygon at, if it states one."""
    tip_conditioning: dict[str, float] | None = None
    """Each tip's own conditioning, compounded along the acts that found it."""


def grade_polygons(out: Grade, sol, drawing: Drawing, drafting: Drafting = DRAFTING,
                   orientation: tuple[float, float] | None = None) -> None:
    """Grade the polygons ``drawing`` labels, if any, into ``out``, at ``drafting``'s
    precision; ``orientation`` is the (turn, hand) of the space diagram drawn on the same
    sheet, if one is."""
    lost: list[str] = []
    polygons = _expected(sol)
    mech = sol.work.mechanism
    found: dict[tuple[str, str], Vec] = {}
    unnamed: list[str] = []
    matched = match(drawing, _read, lost)
    if lost:        # two tips at one point (a ≡ a4 at a dead point): a label each, one point
        texts, lost = set(lost), []
        again = replace(drawing, labels=[lb for lb in drawing.labels if lb.text in texts])
        matched.update({k: v for k, v in match(again, _read, lost).items()
                        if k not in matched})
    for (kind, names), at in matched.items():
        kind = kind[0]
        for name in names:
            poly = polygons.get(kind)
            key = "o" if name == "o" else (
                tip_of(name, poly.tips, mech, drafting.aliases) if poly else None)
            if key is None:
                unnamed.append(name + ("′" if kind == "a" else ""))
            else:
                found.setdefault((kind, key), at)
    kinds = {k for k, n in found if n == "o"}
    if not kinds:
        return
    if lost:
        out.notes.append("labels near no line end or dot, not graded: "
                         + ", ".join(sorted(set(lost))))
    if unnamed:
        out.notes.append(f"labels that name no tip of the polygons, taken for construction "
                         f"points and not graded: {', '.join(sorted(set(unnamed)))}")
    stated = stated_scales(drawing, out.notes)
    overlay = []
    for kind in sorted(kinds):
        if kind not in polygons:
            out.notes.append(f"the drawing has {_noun(kind)} polygon labels, which this "
                             "exercise does not draw")
            continue
        overlay.append(_grade_one(polygons[kind], found, stated.get(kind), out, drafting,
                                  orientation))
    out.overlay = (out.overlay[0] if out.overlay else drawing, overlay)


def _read(text: str) -> tuple[str, tuple[str, ...]] | None:
    """A label as :func:`.labels.read_names` reads it, a pole's kind marked apart ("vo"), so
    the pole and a tip at rest there (b′ = o′ when B's acceleration is nil) share a point."""
    read = read_names(text)
    return None if read is None else ((read[0] + "o", read[1]) if "o" in read[1] else read)


def _noun(kind: str) -> str:
    return "a velocity" if kind == "v" else "an acceleration"


def _expected(sol) -> dict[str, _Expected]:
    """The polygons tarsim draws at the position, by kind."""
    work = sol.work
    mech = work.mechanism
    given = mech.link(mech.drive.link).names[-1].lower()
    fixed = {n for n in mech.point_names if 1 in mech.links_at(n)}

    def moving(poly) -> frozenset[str]:
        """The tips a drawing must show: the mechanism's moving points, and a coincident
        point on a slot (A4), which the construction cannot do without; not the frame's
        points (at the pole), nor a helper such as a wheel's contact point."""
        return frozenset(n.lower() for n in poly.tips if n not in fixed and (
            n in mech.point_names or n.rstrip("0123456789") in mech.point_names))

    def gradable(poly) -> frozenset[str]:
        return frozenset(n.lower() for n in poly.tips if n not in fixed)

    def stated(per_cm: float | None) -> float | None:
        """A stated polygon scale (file units per paper cm) as paper mm per SI unit."""
        return None if not per_cm else 10.0 / (per_cm * mech.units.metres)
    c = work.assembly

    def each(poly) -> dict[str, float]:
        return {n.lower(): c[r].conditioning for n, r in poly.tips.items()}

    def keys(poly) -> dict[str, str]:
        return {n.lower(): n for n in poly.tips}
    out = {}
    vp = drawn_velocity_polygon(work)
    out["v"] = _Expected("v", {n.lower(): vp.vector(n) for n in vp.tips}, given, vp.worst(),
                         {}, vp, keys(vp), moving(vp), gradable(vp),
                         stated(work.scales.velocity_polygon), each(vp))
    if work.has("acceleration polygon"):
        ap = drawn_acceleration_polygon(work)
        cor = {}
        for point in ap.coriolis:
            link = next((s.guide_link for s in mech.slides if s.point == point
                         and s.guide_link != 1), None)          # the slot's, which turns
            cor[point.lower()] = (ap.coriolis_of(point), link)
        out["a"] = _Expected("a", {n.lower(): ap.vector(n) for n in ap.tips}, given,
                             ap.worst(), cor, ap, keys(ap), moving(ap), gradable(ap),
                             stated(work.scales.acceleration_polygon), each(ap))
    return out


def _grade_one(poly: _Expected, found, written: float | None, out: Grade, drafting: Drafting,
               orientation: tuple[float, float] | None):
    """Grade one polygon's tips into ``out``; return what its overlay draws: (kind, None,
    pole, each tip expected), in paper mm."""
    mark = "′" if poly.kind == "a" else ""
    pole, given = found.get((poly.kind, "o")), found.get((poly.kind, poly.given))
    e_given = poly.tips.get(poly.given, (0.0, 0.0))
    if pole is None or given is None or math.hypot(*e_given) == 0.0 or given == pole:
        out.notes.append(f"the {_noun(poly.kind)[2:].strip()} polygon needs its pole o{mark} "
                         f"and the input's tip {poly.given}{mark} labelled to be graded")
        return None
    held = written or (poly.scale if drafting.scale_required else None)
    frame, items = _attempt(poly, found, held, drafting, orientation or (0.0, 1.0))
    wrong = sum(i.verdict not in ("correct", FOLLOWS, "missing") for i in items.values())
    if items[poly.given].verdict != "correct" or wrong >= 2:
        frame, items = _input_swapped(poly, found, held, drafting, orientation or (0.0, 1.0),
                                      frame, items)
    out.items += list(items.values())
    names = _names(poly, found)
    # What the overlay draws: the pole and each tip expected (not tarsim's construction,
    # which a worker would send back with every grade).
    return poly.kind, None, pole, {n: frame.place(poly.tips[n]) for n in names}


def _names(poly: _Expected, found) -> list[str]:
    """The tips graded: those required, and any other drawn but the frame's."""
    return sorted(poly.required | {n for (k, n) in found if k == poly.kind and n != "o"
                                   and n in poly.gradable})


def _attempt(poly: _Expected, found, held: float | None, drafting: Drafting,
             orientation: tuple[float, float]) -> tuple[Frame, dict[str, Item]]:
    """The polygon graded with its tips ``found`` where they are: its frame, and each tip's
    item."""
    pole, given = found[(poly.kind, "o")], found[(poly.kind, poly.given)]
    f_given = (given[0] - pole[0], given[1] - pole[1])
    own = math.hypot(*f_given) / math.hypot(*poly.tips[poly.given])
    ex_scale = exercise_scale(poly.scale, poly.tips.values())
    names = _names(poly, found)
    # The input's tip turns the frame by as much as the space diagram's fit may be off.
    turn, hand = orientation
    drift = math.remainder(math.atan2(-f_given[1], f_given[0]) + turn - math.atan2(
        hand * poly.tips[poly.given][1], poly.tips[poly.given][0]), 2 * math.pi)
    orientation = (turn - drift if abs(drift) <= _DRIFT else turn, hand)
    frame = Frame(held or own, *orientation, at=pole)
    items = _graded(poly, names, frame, pole, found, drafting, ex_scale)
    if held and items[poly.given].verdict == "wrong magnitude":
        frame = Frame(own, *orientation, at=pole)
        _at_its_own_scale(poly, items, _graded(poly, names, frame, pole, found, drafting,
                                               ex_scale), own, held, drafting)
    _follow_through(poly, items, frame, found)
    return frame, items


_DRIFT = math.radians(2.0)
"""How far the input's tip may turn a polygon from the orientation it is held to: a space
diagram's fit is true to a pen's width over its size, a degree or so; a polygon turned
further (a quarter, the other way round) is wrong."""


def _input_swapped(poly: _Expected, found, held, drafting: Drafting, orientation, frame,
                   items) -> tuple[Frame, dict[str, Item]]:
    """The input's tip wrong, or others wrong with it (its length sets the scale, so a
    label swapped onto a tip along it reads as a scale): if its label and another tip's are
    swapped, and the polygon is righter with them put back, both of them right, the two are
    "swapped" and the rest graded as put back."""
    k, given = poly.kind, poly.given
    for name in sorted(n for n in items if n != given and (k, n) in found):
        back = {**found, (k, given): found[(k, name)], (k, name): found[(k, given)]}
        if back[(k, given)] == back[(k, "o")]:
            continue
        frame2, items2 = _attempt(poly, back, held, drafting, orientation)
        if items2[given].verdict == "correct" and items2[name].verdict == "correct" and \
                _right(items2) > _right(items) + 1:
            for n in (given, name):
                items2[n].verdict, items2[n].found = "swapped", rounded(found[(k, n)])
                items2[n].message = (f"the labels {items2[given].name} and "
                                     f"{items2[name].name} are swapped")
            return frame2, items2
    return frame, items


def _right(items: dict[str, Item]) -> int:
    """How many of ``items`` are right."""
    return sum(i.verdict == "correct" for i in items.values())


def _graded(poly: _Expected, names: list[str], frame: Frame, pole: Vec, found, drafting: Drafting,
            ex_scale: float) -> dict[str, Item]:
    """Each tip's item, held to where ``frame`` puts it."""
    mark = "′" if poly.kind == "a" else ""
    # The pen at the drawing's scale, and never finer than a pen on the drawing's own paper:
    # a polygon drawn at a third of the course's size cannot part tips closer than that.
    pen = drafting.pen * max(frame.scale / ex_scale, 1.0)
    flips = reversed_coriolis(poly.polygon, frame, poly.keys) if poly.coriolis else {}
    items: dict[str, Item] = {}
    for name in names:
        label = f"{name}{mark}"
        exp = frame.place(poly.tips[name])
        cond = max((poly.tip_conditioning or {}).get(name, poly.conditioning),
                   LEAST_CONDITIONING)
        tol = max(tolerance(math.hypot(*poly.tips[name]) * ex_scale, cond, drafting)
                  * frame.scale / ex_scale, drafting.pen)
        cut = bands(poly.polygon, poly.keys[name], frame, exp, pen, drafting.angle,
                    LEAST_CONDITIONING)
        got = found.get((poly.kind, name))
        if cut is not None:
            tol = reach(cut)
        if got is not None:
            ok = within(got, exp, cut) if cut is not None else math.dist(got, exp) <= tol
            items[name] = _verdict(label, poly, pole, exp, got, tol, pen, drafting.angle,
                                   flips.get(name), ok)
        elif name in poly.required:
            items[name] = Item(label, "missing", rounded(exp), None, round(tol, 3),
                               f"{label} is not labelled on the drawing")
    _name_swaps(items.values())
    return items


def _verdict(label: str, poly: _Expected, pole: Vec, exp: Vec, got: Vec, tol: float,
             pen: float, angle: float, flip: tuple[Vec, str] | None, ok: bool) -> Item:
    """The verdict on one tip found at ``got`` where ``exp`` was expected (``ok``: within its
    tolerance); ``flip`` is where it lands with a Coriolis component drawn into it reversed,
    and that component's point."""
    item = Item(label, "correct", rounded(exp), rounded(got), round(tol, 3))
    miss = math.dist(exp, got)
    if ok:
        return item
    if flip is not None and math.dist(flip[0], got) <= tol:
        point = flip[1]
        item.verdict = "reversed Coriolis"
        item.message = (f"Coriolis component at {point.upper()} drawn opposite: turn "
                        f"V_rel 90° in the sense of ω{poly.coriolis[point.lower()][1]}")
        return item
    e = (exp[0] - pole[0], exp[1] - pole[1])
    f = (got[0] - pole[0], got[1] - pole[1])
    le, lf = math.hypot(*e), math.hypot(*f)
    if le == 0.0 or lf == 0.0:
        item.verdict = "wrong magnitude"
        item.message = f"{label} is {miss:.1f} mm from where it belongs"
        return item
    turn = abs(math.remainder(math.atan2(f[1], f[0]) - math.atan2(e[1], e[0]), 2 * math.pi))
    # True to the set square, and to the pen across the vector's length.
    slack = angle + math.atan2(pen, le)
    if abs(turn - math.pi) <= slack:
        item.verdict = "wrong sense"
        item.message = f"{label} points the other way from the pole"
    elif turn <= slack:
        item.verdict = "wrong magnitude"
        item.message = (f"{label} is {lf - le:+.1f} mm ({100 * (lf - le) / le:+.1f} %) off "
                        "along its direction from the pole")
    else:
        item.verdict = "wrong direction"
        item.message = (f"{label} is {miss:.1f} mm from where it belongs "
                        f"({math.degrees(turn):.1f}° off)")
    return item


def _name_swaps(items) -> None:
    """Two tips each found where the other belongs: their labels are swapped."""
    wrong = [i for i in items if i.verdict not in ("correct", "missing")
             and i.found and i.expected]
    for i in wrong:
        for j in wrong:
            if i is not j and math.dist(i.found, j.expected) <= j.tolerance and \
                    math.dist(j.found, i.expected) <= i.tolerance:
                i.verdict = "swapped"
                i.message = f"the labels {i.name} and {j.name} are swapped"


def _at_its_own_scale(poly: _Expected, items: dict[str, Item], own: dict[str, Item],
                      drawn: float, held: float, drafting: Drafting) -> None:
    """The input's tip is off the scale held to: the other tips are graded at the drawing's
    own scale (``own``), where each one right follows from that error."""
    given = items[poly.given]
    for name, item in own.items():
        if name == poly.given:
            continue
        if item.verdict == "correct":
            item.verdict = FOLLOWS
            item.message = f"{item.name} is right at the scale {given.name} is drawn at"
        items[name] = item
    given.message = (f"{given.name} is drawn at 1 cm = {_per_cm(drawn, poly.kind)}, not the "
                     f"1 cm = {_per_cm(held, poly.kind)} "
                     + ("written on the drawing" if not drafting.scale_required
                        else "the exercise requires"))


def _per_cm(scale: float, kind: str) -> str:
    """Paper mm per SI unit as a course writes it: "0.5 m/s"."""
    return f"{10.0 / scale:.3g} m/s" + ("²" if kind == "a" else "")


def _follow_through(poly: _Expected, items: dict[str, Item], frame: Frame, found) -> None:
    """Each wrong tip that the construction, redone from the tips drawn wrong before it,
    puts where it was drawn follows from an earlier error."""
    replay = Replay(poly.polygon, frame)
    drawn = {n: poly.keys[n] for n, i in items.items() if i.found is not None}
    for name in replay.tips_in_order(drawn):
        item = items[name]
        if item.verdict in ("correct", "missing"):
            continue
        got = found[(poly.kind, name)]
        if item.verdict != FOLLOWS:
            at = replay.where(drawn[name])
            if at is not None and math.dist(at, got) <= item.tolerance:
                item.verdict = FOLLOWS
                item.message = f"{item.name} is drawn rightly from the tips before it"
        replay.move(drawn[name], got)
