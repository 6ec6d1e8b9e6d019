"""A class drawing laid out on its page: the page and its regions, each polygon's scale
and pole, the space diagram's scale, and the marks of the whole sheet.

Scales are the exercise's where it states one and the polygon fits, a course's round one
(1, 2, 2.5, 4 or 5 × 10ⁿ a centimetre) or, for a drawing made to fit, any at all (then
nothing can be written of it). A scale is written on the sheet as a course writes it
("1 cm = 0.05 m/s", "3 cm = 18 cm/s", "Velocity scale 1 cm = 50 mm/s").
"""

from __future__ import annotations

import math
import random
from dataclasses import dataclass

from student_sheets import Frame, Guide, Hand, LabelPlacer, draw_polygon, draw_space

__all__ = ["Page", "lay_out", "marks", "nice_written", "scale_text", "written_name"]

Vec = tuple[float, float]
_ROUND = (1.0, 2.0, 2.5, 4.0, 5.0)
_WRITTEN = (1.0, 1.2, 1.25, 1.5, 1.6, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0, 7.5, 8.0)


@dataclass
class Page:
    """A sheet's size (mm), its regions (x0, y0, x1, y1) by what they hold, the frames that
    place each polygon (by kind) and the space diagram ("s"), and a CAD plot's scale."""

    size: Vec
    regions: dict
    frames: dict
    model: float = 1.0
    space_text: str = ""


def _regions(sheet: str, accelerations: bool) -> tuple[Vec, dict]:
    if sheet == "polygons":
        size, space = (210.0, 297.0), None
        v, a = (18, 20, 192, 138), (18, 146, 192, 262)
    elif sheet == "centres":
        size, space = (420.0, 297.0), (16, 20, 206, 262)
        v, a = (220, 20, 404, 138), (220, 146, 404, 262)
    else:                                   # tarsim's worked page: the diagram above
        size, space = (297.0, 420.0), (18, 20, 279, 196)
        v, a = (18, 206, 146, 392), (151, 206, 279, 392)
    if not accelerations:
        v = (v[0], v[1], max(v[2], a[2]), max(v[3], a[3])) if sheet != "worked" else \
            (v[0], v[1], a[2], a[3])
    regions = {"v": v, "a": a} if accelerations else {"v": v}
    if space:
        regions["s"] = space
    return size, regions


def _box(vectors, turn: float) -> tuple[float, float, float, float]:
    frame = Frame(1.0, (0.0, 0.0), turn)
    ps = [frame.vector(v) for v in vectors] + [(0.0, 0.0)]
    return (min(p[0] for p in ps), min(p[1] for p in ps), max(p[0] for p in ps),
            max(p[1] for p in ps))


def _fit(box, region, margin: float = 13.0, below: float = 10.0) -> float:
    w = region[2] - region[0] - 2 * margin
    h = region[3] - region[1] - 2 * margin - below
    return min(w / max(box[2] - box[0], 1e-12), h / max(box[3] - box[1], 1e-12))


def _place(rng: random.Random, box, region, scale: float, margin: float = 13.0,
           below: float = 10.0) -> Vec:
    """Where the origin goes so that the box, at ``scale``, lies inside the region."""
    free_x = region[2] - region[0] - 2 * margin - scale * (box[2] - box[0])
    free_y = region[3] - region[1] - 2 * margin - below - scale * (box[3] - box[1])
    return (region[0] + margin - scale * box[0] + free_x * rng.uniform(0.1, 0.9),
            region[1] + margin - scale * box[1] + free_y * rng.uniform(0.1, 0.9))


def _round_at_least(q: float) -> float:
    """The smallest round scale (1, 2, 2.5, 4, 5 × 10ⁿ) of at least ``q``."""
    k = math.floor(math.log10(q))
    for m in _ROUND + (10.0,):
        if m * 10 ** k >= q * (1 - 1e-12):
            return m * 10 ** k
    return 10.0 ** (k + 1)


def nice_written(scale: float) -> float:
    """The written scale (paper mm a unit) a student who meant ``scale`` puts down, a
    number a course writes (1.2, 1.25, 1.5, … × 10ⁿ a centimetre)."""
    q = 10.0 / scale
    k = math.floor(math.log10(q))
    best = min((m * 10.0 ** j for m in _WRITTEN for j in (k, k + 1)),
               key=lambda x: abs(math.log(x / q)))
    return 10.0 / best


def _number(x: float) -> str:
    return f"{x:.6g}"


def scale_text(rng: random.Random, scale: float, kind: str, worked: bool = False) -> str:
    """A polygon's ``scale`` (paper mm a SI unit) as a course writes it."""
    q = 10.0 / scale                     # SI units a centimetre
    sq = rng.choice(["²", "²", "^2"]) if kind == "a" else ""
    forms = [f"1 cm = {_number(q)} m/s{sq}", f"1 cm = {_number(q * 1000)} mm/s{sq}",
             f"1 cm = {_number(q * 100)} cm/s{sq}", f"1cm = {_number(q)} m/s{sq}"]
    if abs(q * 300 - round(q * 300)) < 1e-9:
        forms.append(f"3 cm = {_number(q * 300)} cm/s{sq}")
    text = rng.choice(forms)
    lead = "Velocity scale " if kind == "v" else "Acceleration scale "
    return (lead if worked else rng.choice(["", "Scale: ", lead, "k: "])) + text


def lay_out(rng: random.Random, d) -> Page:
    """Choose the page, the sheet's turn, each polygon's scale and pole and the space
    diagram's scale for the drawing ``d`` (tests/grading_corpus.py's Drawing)."""
    ex = d.exercise
    size, regions = _regions(d.sheet, len(d.polygons) > 1)
    if d.sheet != "polygons" and rng.random() < 0.1:   # the whole sheet drawn turned
        d.turn = math.radians(rng.choice([90.0, -90.0, 180.0, rng.uniform(-40, 40)]))
    frames = {}
    for poly in d.polygons:
        region = regions[poly.kind]
        box = _box(list(poly.true.values()) + list(poly.drawn.values()), d.turn)
        fit = _fit(box, region)
        stated = ex.velocity_scale if poly.kind == "v" else None
        pick = rng.random()
        if stated and stated <= fit and stated >= 0.3 * fit and pick < 0.5:
            poly.scale, poly.source = stated, "exercise"
        elif pick < (0.75 if d.program == "geogebra" else 0.9):
            poly.scale = 10.0 / _round_at_least(10.0 / (fit * rng.uniform(0.55, 1.0)))
            poly.source = "own"
        else:
            poly.scale, poly.source = fit * rng.uniform(0.5, 0.95), "arbitrary"
        if poly.source != "arbitrary" and (d.program == "cad" or rng.random() < 0.35):
            poly.written = poly.scale
        frames[poly.kind] = Frame(poly.scale, _place(rng, box, region, poly.scale), d.turn)
    space_text = ""
    if "s" in regions:
        pos = d.polygons[0].solved
        world = list(pos.points.values()) + list(d.centres.values())
        box = _box(world, d.turn)
        fit = _fit(box, regions["s"], margin=15.0)
        if ex.space_scale and ex.space_scale <= fit and rng.random() < 0.5:
            s = ex.space_scale
            space_text = "Scale 7 cm = 500 mm" if ex.name == "crank-shaper" else ""
        else:
            k = _round_at_least(1000.0 / (fit * rng.uniform(0.7, 1.0)))
            s = 1000.0 / k
            space_text = rng.choice([f"Scale 1:{_number(k)}", f"1 cm = {_number(10 * k)} mm",
                                     f"Space diagram 1:{_number(k)}", ""])
        frames["s"] = Frame(s, _place(rng, box, regions["s"], s, margin=15.0), d.turn)
    return Page(size, regions, frames, rng.choice([1.0, 2.0, 5.0, 10.0]), space_text)


def written_name(tip: str, hand: Hand, tips) -> str:
    """What a student writes at ``tip`` (A, A4, B4, B): the letter and its subscript, the
    crank pin and the ram named by their links as tarsim names them if the hand does."""
    letter, digits = tip[0].lower(), tip[1:]
    if digits or not hand.links or "A4" not in tips:
        return letter + digits
    if tip == "A":
        return "a2"
    return "b5" if "B4" in tips else "b"


def _guides(poly, frame: Frame) -> tuple[list, dict]:
    """Construction lines through the tips a polygon's construction crosses, from the point
    each was drawn from, and its construction points (n′, x′) on paper."""
    drawn, pos = poly.drawn, poly.solved
    pairs, points = [], {}
    if "A4" in drawn and poly.kind == "v":
        pairs += [("A4", drawn["A"]), ("A4", (0.0, 0.0))]
    elif "A4" in drawn:                                 # n′ and x′ of the acceleration
        o4a = (pos.points["A"][0] - pos.points["O4"][0], pos.points["A"][1]
               - pos.points["O4"][1])
        w4 = pos.omega[4]
        normal = (-w4 * w4 * o4a[0], -w4 * w4 * o4a[1])
        sign = -1.0 if "A" in poly.coriolis else 1.0
        cor = pos.coriolis["A"]
        x = (drawn["A"][0] - sign * cor[0], drawn["A"][1] - sign * cor[1])
        pairs += [("A4", normal), ("A4", x)]
        points = {"n": normal, "x": x}
        if "B4" in drawn:
            sign = -1.0 if "B" in poly.coriolis else 1.0
            cor = pos.coriolis["B"]
            y = (drawn["B4"][0] + sign * cor[0], drawn["B4"][1] + sign * cor[1])
            pairs += [("B", y)]
    if "B4" in drawn:
        pairs += [("B", (0.0, 0.0))] + ([("B", drawn["B4"])] if poly.kind == "v" else [])
    elif "A4" not in drawn:                             # the four-bar's b
        pairs += [("B", drawn["A"]), ("B", (0.0, 0.0))]
    return pairs, {k: frame.place(v) for k, v in points.items()}


def marks(rng: random.Random, d, page: Page) -> tuple[list, int]:
    """The whole sheet's marks, and how many of its labels could not be placed fairly."""
    out: list = []
    placer = LabelPlacer(rng, out)
    hand = Hand.of(rng, d.program, tarsim=d.sheet == "worked")
    apart = hand.sub == "apart"
    if "s" in page.frames:
        _space(rng, out, placer, d, page, hand)
    for poly in d.polygons:
        frame = page.frames[poly.kind]
        region = page.regions[poly.kind]
        tips = {t: frame.place(v) for t, v in poly.drawn.items() if t not in poly.missing}
        labels = {t: written_name(poly.labels.get(t, t), hand, poly.true) for t in tips}
        pairs, points = _guides(poly, frame)
        guides = []
        if rng.random() < 0.6:
            for tip, anchor in pairs:
                if tip not in tips:
                    continue
                a, b = frame.place(anchor), tips[tip]
                if math.dist(a, b) > 3.0:
                    on = rng.uniform(1.0, 3.0) if rng.random() < 0.3 else rng.uniform(4, 14)
                    guides.append(Guide(b, (b[0] - a[0], b[1] - a[1]),
                                        math.dist(a, b) + rng.uniform(2, 8), on))
        shown = {}
        if points and rng.random() < 0.4:
            shown = {name + hand.prime: p for name, p in points.items()
                     if min(math.dist(p, q) for q in list(tips.values()) + [frame.origin]) > 4}
        relative = [("A", "A4"), ("B4", "B")] if poly.kind == "v" else []
        if "A4" not in poly.true and poly.kind == "v":
            relative = [("A", "B")]
        draw_polygon(rng, out, placer, kind=poly.kind, pole=frame.origin, tips=tips,
                     labels=labels, hand=hand,
                     dots=d.program == "geogebra" or rng.random() < 0.3,
                     relative=relative if rng.random() < 0.6 else [], guides=guides,
                     points=shown, apart=apart)
        if d.program != "geogebra" and (d.sheet == "worked" or rng.random() < 0.5):
            out.append(("text", (region[0] + 2, region[1] + 4),
                        [("Velocity polygon" if poly.kind == "v" else "Acceleration polygon",
                          "")], 3.6))
        if poly.written:
            out.append(("text", (region[0] + 2, region[3] - 3),
                        [(scale_text(rng, poly.written, poly.kind, d.sheet == "worked"), "")],
                        3.2))
    if d.program == "cad":
        out.append(("text", (page.size[0] - 106, page.size[1] - 31),
                    [(f"SCALE 1:{page.model:g}", "")], 3.0))
    return out, placer.ambiguous


def _space(rng: random.Random, out: list, placer: LabelPlacer, d, page: Page,
           hand: Hand) -> None:
    pos = d.polygons[0].solved
    ex = d.exercise
    frame, region = page.frames["s"], page.regions["s"]
    points = dict(pos.points)
    if ex.family == "four-bar":
        links, blocks, guides = [("O2", "A"), ("A", "B"), ("B", "O4")], [], []
    else:
        u = (points["A"][0] - points["O4"][0], points["A"][1] - points["O4"][1])
        links, blocks, guides = [("O2", "A"), ("O4", "B")], [("A", u)], []
        if "B4" in pos.velocity:
            blocks.append(("B", (1.0, 0.0)))
            guides.append((points["B"], (1.0, 0.0)))
    centres = d.centres
    kennedy = []
    for name in centres:
        i, j = int(name[1]), int(name[2])
        if any(math.dist(centres[name], p) < 1e-9 for p in points.values()):
            continue
        for k in range(1, 6):
            one, two = f"I{min(i, k)}{max(i, k)}", f"I{min(j, k)}{max(j, k)}"
            if k not in (i, j) and one in centres and two in centres and \
                    math.dist(centres[one], centres[two]) > 1e-6 and len(
                        [t for t in kennedy if t[0] == name]) < 2:
                kennedy.append((name, one, two))
    draw_space(rng, out, placer, frame=frame, points=points, links=links,
               ground=["O2", "O4"], blocks=blocks, guides=guides, centres=centres,
               moved=d.moved, hand=hand, kennedy=kennedy if rng.random() < 0.7 else [])
    if rng.random() < 0.6:                              # the links' numbers
        for number, (a, b) in zip((2, 4), (("O2", "A"), ("O4", "B"))):
            p, q = frame.place(points[a]), frame.place(points[b])
            mid = ((p[0] + q[0]) / 2 + 2.5, (p[1] + q[1]) / 2 - 1.5)
            out.append(("text", mid, [(str(number), "")], 3.2))
    if page.space_text:
        out.append(("text", (region[0] + 2, region[3] - 3), [(page.space_text, "")], 3.2))
    if "I15" not in centres and ex.name == "crank-shaper" and rng.random() < 0.3:
        out.append(("text", (region[0] + 2, region[3] - 9), [("I₁₅ at ∞ (vertical)", "")], 3.0))
