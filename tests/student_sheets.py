"""What a student draws on a sheet, as marks in paper mm (tests/svg_writers.py's vocabulary):
polygons and space diagrams placed by a :class:`Frame`, their points labelled as a course
writes them (:class:`Hand`), each point put down by a hand that lands within 0.15 mm.

Labels stand beside the point they name, on the side away from the pole or the middle of
the figure, clear of the other points and labels near them; points drawn together (a₂ ≡ a₄)
get their labels on different sides.
"""

from __future__ import annotations

import math
import random
from dataclasses import dataclass, field

__all__ = ["Frame", "Hand", "JITTER", "jitter", "LabelPlacer", "draw_polygon", "draw_space",
           "frame_and_title"]

Vec = tuple[float, float]

JITTER = 0.15
"""The farthest a hand puts a point from where it means to (mm)."""

_SUBSCRIPT = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")


def jitter(rng: random.Random, p: Vec, r: float = JITTER) -> Vec:
    """``p`` put down by hand: anywhere within ``r`` of it."""
    a, d = rng.uniform(0, 2 * math.pi), r * math.sqrt(rng.random())
    return (p[0] + d * math.cos(a), p[1] + d * math.sin(a))


@dataclass(frozen=True)
class Frame:
    """World (SI, y up) to paper (mm, y down): ``scale`` mm a unit, turned ``turn`` rad
    counter-clockwise as seen on the paper, the world's origin at ``origin``."""

    scale: float
    origin: Vec
    turn: float = 0.0

    def vector(self, v: Vec) -> Vec:
        """A world vector's paper vector."""
        c, s = math.cos(self.turn), math.sin(self.turn)
        x, y = c * v[0] - s * v[1], s * v[0] + c * v[1]
        return (self.scale * x, -self.scale * y)

    def place(self, p: Vec) -> Vec:
        """A world point's place on paper."""
        v = self.vector(p)
        return (self.origin[0] + v[0], self.origin[1] + v[1])


@dataclass
class Hand:
    """How one student writes labels: the forms of subscripts, primes, poles and centres.

    ``sub`` is "digits" (a4), "unicode" (a₄), "underscore" (a_4), "set" (a subscript the
    program sets) or "apart" (a smaller text of its own); ``prime`` the mark and
    ``prime_first`` whether it goes before the subscript (a′₄); ``links`` whether the crank
    pin and the ram are named by their links as tarsim names them (a₂, b₅)."""

    sub: str = "digits"
    prime: str = "′"
    prime_first: bool = False
    links: bool = False
    pole_v: tuple = (("o", ""),)
    pole_a: tuple = (("o′", ""),)
    centre: str = "I13"
    size: float = 4.0

    @classmethod
    def of(cls, rng: random.Random, program: str, tarsim: bool = False) -> Hand:
        """A student's hand, as the program lets them write."""
        subs = {"inkscape": ["digits", "unicode", "set", "apart", "underscore"],
                "libreoffice": ["digits", "unicode", "set", "apart"],
                "geogebra": ["set", "digits", "digits", "digits"],
                "cad": ["digits", "underscore", "digits"],
                "hand": ["digits", "unicode", "set", "underscore", "apart"]}[program]
        primes = ["'"] if program in ("geogebra", "cad") else ["′", "'", "’", "′"]
        sub = "set" if tarsim and program != "cad" else rng.choice(subs)
        prime = rng.choice(primes)
        if tarsim:
            pole_v, pole_a = (("o", ""), ("v", "sub")), (("o", ""), ("a", "sub"))
        else:
            pole_v = rng.choice([(("o", ""),), (("o_v", ""),), (("o", ""), ("v", "sub")),
                                 (("ov", ""),)])
            pole_a = rng.choice([(("o" + prime, ""),), (("o_a", ""),),
                                 (("o", ""), ("a", "sub")), (("o" + prime, ""),)])
        centre = rng.choice(["I13", "13"] if program == "geogebra" else
                            ["I13", "13", "I₁₃", "I_13", "I sub"])
        # GeoGebra names a point a'_4: the prime goes with the letter, before the subscript.
        first = program == "geogebra" or rng.random() < 0.3
        return cls(sub, prime, first, tarsim or rng.random() < 0.25,
                   pole_v, pole_a, centre, rng.uniform(3.4, 4.6))

    def tip(self, written: str, kind: str) -> list[tuple[str, str]]:
        """The runs a tip's label is written in: ``written`` is the letter and its
        subscript digits (``a4``, ``b5``), ``kind`` "v" or "a"."""
        letter, digits = written[:1], written[1:]
        prime = self.prime if kind == "a" else ""
        if not digits:
            return [(letter + prime, "")]
        if self.sub in ("set", "apart"):
            return ([(letter + prime, ""), (digits, "sub")] if self.prime_first
                    else [(letter, ""), (digits, "sub")] + ([(prime, "")] if prime else []))
        form = {"digits": digits, "unicode": digits.translate(_SUBSCRIPT),
                "underscore": "_" + digits}[self.sub]
        return [(letter + prime + form if self.prime_first else letter + form + prime, "")]

    def pole(self, kind: str) -> list[tuple[str, str]]:
        """The pole's runs."""
        return list(self.pole_v if kind == "v" else self.pole_a)

    def centre_runs(self, name: str) -> list[tuple[str, str]]:
        """A centre's runs (``name`` as I13)."""
        digits = name[1:]
        return {"I13": [(name, "")], "13": [(digits, "")],
                "I₁₃": [("I" + digits.translate(_SUBSCRIPT), "")],
                "I_13": [("I_" + digits, "")],
                "I sub": [("I", ""), (digits, "sub")]}[self.centre]

    def point_runs(self, name: str) -> list[tuple[str, str]]:
        """A mechanism point's runs (O2, A), as the exercise names it."""
        letter, digits = name[:1], name[1:]
        if not digits:
            return [(name, "")]
        if self.sub in ("set", "apart"):
            return [(letter, ""), (digits, "sub")]
        return [(letter + {"digits": digits, "unicode": digits.translate(_SUBSCRIPT),
                           "underscore": "_" + digits}[self.sub], "")]


def _extent(runs, size: float) -> tuple[float, float]:
    """A label's width and height on paper (mm), about."""
    wide = sum((0.4 if role else 0.58) * size * len(t) for t, role in runs)
    return wide, 0.72 * size


@dataclass
class LabelPlacer:
    """Places labels on a sheet clear of one another and fair to a reader: the point a label
    names is nearer its letters, by a millimetre at least, than any other point, line end
    or dot drawn so far more than 2 mm from it (``ambiguous`` counts the labels that could
    not be so placed)."""

    rng: random.Random
    marks: list
    points: list[Vec] = field(default_factory=list)
    boxes: list[tuple[float, float, float, float]] = field(default_factory=list)
    ambiguous: int = 0

    def _obstacles(self, at: Vec) -> list[Vec]:
        """The points, line ends and dots drawn so far that a label of ``at`` must stand
        farther from than from ``at``: not those within 2 mm of it (a construction line
        ending just past a tip, the trap a grader must see through), nor the corners of
        blocks, hatches and frames, which name nothing."""
        ends: list[Vec] = list(self.points)
        for m in self.marks:
            if m[0] in ("line", "arrow"):
                ends += [m[1], m[2]]
            elif m[0] in ("dot", "circle"):
                ends.append(m[1])
        return [p for p in ends if math.dist(p, at) > 2.0]

    def put(self, at: Vec, runs, size: float, away: Vec = (1.0, -1.0),
            apart: bool = False) -> None:
        """Write ``runs`` beside the point ``at``, towards ``away`` if it is clear."""
        w, h = _extent(runs, size)
        base = math.atan2(away[1], away[0]) if math.hypot(*away) > 1e-9 else -math.pi / 4
        others = self._obstacles(at)
        best, best_score, fair = None, -math.inf, False
        first = self.rng.uniform(0.7, 2.2)
        turns = (0, 40, -40, 80, -80, 120, -120, 160, -160, 200, 20, -20, 60, -60, 100, -100,
                 140, -140, 180)
        for ring, gap in enumerate((first, first + 1.2, first + 2.4)):
            for k, turn in enumerate(turns):
                a = base + math.radians(turn + self.rng.uniform(-10, 10))
                ux, uy = math.cos(a), math.sin(a)
                # The box's centre, far enough along a that the box clears the point by gap.
                reach = gap + min(w / 2 / max(abs(ux), 1e-9), h / 2 / max(abs(uy), 1e-9))
                c = (at[0] + ux * reach, at[1] + uy * reach)
                box = (c[0] - w / 2, c[0] + w / 2, c[1] - h / 2, c[1] + h / 2)
                clear = min([_box_distance(box, p) for p in others] + [9.0])
                overlap = any(_overlap(box, b) for b in self.boxes)
                ok = clear >= gap + 1.0 and not overlap
                score = min(clear - gap, 3.0) - 10.0 * overlap - 0.02 * k - 2.0 * ring + 5.0 * ok
                if score > best_score:
                    best, best_score, fair = box, score, ok
                if ok and clear >= max(3.0, gap + 1.5):
                    break
            if fair:
                break
        self.ambiguous += not fair
        self.boxes.append(best)
        anchor = (best[0], best[3] - 0.12 * h)
        if apart and len(runs) > 1:               # a subscript typed as its own text
            main = [r for r in runs if not r[1]][:1]
            head = main[0][0] if main else runs[0][0]
            self.marks.append(("text", anchor, [(head, "")], size))
            rest = "".join(t for t, _ in runs[1:] if t != head)
            shift = _extent([(head, "")], size)[0]
            self.marks.append(("text", (anchor[0] + shift, anchor[1] + 0.3 * size),
                               [(rest, "")], 0.65 * size))
        else:
            self.marks.append(("text", anchor, list(runs), size))


def _box_distance(box, p: Vec) -> float:
    dx = max(box[0] - p[0], 0.0, p[0] - box[1])
    dy = max(box[2] - p[1], 0.0, p[1] - box[3])
    return math.hypot(dx, dy)


def _overlap(a, b) -> bool:
    return a[0] < b[1] + 0.4 and b[0] < a[1] + 0.4 and a[2] < b[3] + 0.4 and b[2] < a[3] + 0.4


@dataclass
class Guide:
    """A construction line on paper: through ``at`` along ``direction``; it runs ``back``
    mm behind the point and ``on`` mm past it."""

    at: Vec
    direction: Vec
    back: float
    on: float


def draw_polygon(rng: random.Random, marks: list, placer: LabelPlacer, *, kind: str,
                 pole: Vec, tips: dict[str, Vec], labels: dict[str, str], hand: Hand,
                 dots: bool, relative: list[tuple[str, str]] = (),
                 guides: list[Guide] = (), points: dict[str, Vec] | None = None,
                 apart: bool = False) -> None:
    """One polygon: an arrow from the pole to each tip drawn (``tips``, paper), its label
    ``labels[tip]`` (the name written there; a tip with none is unlabelled), a dot at each
    tip if ``dots``, the ``relative`` vectors between tips, the construction ``guides``, and
    labelled construction points ``points`` (n′, x′)."""
    o = jitter(rng, pole)
    drawn: list[Vec] = []
    for p in tips.values():
        if math.dist(p, pole) < 0.5 or any(math.dist(p, q) < 0.05 for q in drawn):
            continue
        drawn.append(p)
        marks.append(("arrow", o, jitter(rng, p)))
        if dots:
            marks.append(("dot", jitter(rng, p), rng.uniform(0.35, 0.7)))
    for a, b in relative:
        if a in tips and b in tips and math.dist(tips[a], tips[b]) > 2.0:
            marks.append(("arrow" if rng.random() < 0.5 else "line", jitter(rng, tips[a]),
                          jitter(rng, tips[b])))
    for g in guides:
        d = math.hypot(*g.direction)
        ux, uy = g.direction[0] / d, g.direction[1] / d
        marks.append(("line", (g.at[0] - g.back * ux, g.at[1] - g.back * uy),
                      (g.at[0] + g.on * ux, g.at[1] + g.on * uy), "thin"))
    if dots:
        marks.append(("dot", o, 0.5))
    placer.points += [pole] + list(tips.values()) + list((points or {}).values())
    centre = _middle([pole] + list(tips.values()))
    for name, p in tips.items():
        if name in labels:
            runs = hand.tip(labels[name], kind)
            away = (p[0] - centre[0], p[1] - centre[1]) if math.dist(p, pole) < 0.5 else \
                (p[0] - pole[0], p[1] - pole[1])
            placer.put(p, runs, hand.size, away, apart)
    outward = (pole[0] - centre[0], pole[1] - centre[1])
    placer.put(pole, hand.pole(kind), hand.size, outward, apart)
    for text, p in (points or {}).items():
        marks.append(("dot", jitter(rng, p), 0.4))
        placer.put(p, [(text, "")], hand.size * 0.9, (p[0] - centre[0], p[1] - centre[1]))


def _middle(ps: list[Vec]) -> Vec:
    return (sum(p[0] for p in ps) / len(ps), sum(p[1] for p in ps) / len(ps))


def draw_space(rng: random.Random, marks: list, placer: LabelPlacer, *, frame: Frame,
               points: dict[str, Vec], links: list[tuple[str, str]], ground: list[str],
               blocks: list[tuple[str, Vec]], guides: list[tuple[Vec, Vec]],
               centres: dict[str, Vec], moved: dict[str, Vec], hand: Hand,
               kennedy: list[tuple[str, str, str]]) -> None:
    """The space diagram: links between points, pins as small circles (a block with no dot
    at its pin), hatched ground pivots, slide guides, the link numbers, and the instant
    ``centres`` (SI) as dots, each labelled; ``moved`` shifts a centre on paper (mm).
    ``kennedy`` lines (centre, through, through) are drawn thin and unlabelled."""
    at = {n: frame.place(p) for n, p in points.items()}
    blocked = {n for n, _ in blocks}
    for a, b in links:
        marks.append(("line", jitter(rng, at[a]), jitter(rng, at[b])))
    for name, p in at.items():
        if name not in blocked:
            marks.append(("circle", jitter(rng, p), 1.2))
    for name in ground:
        x, y = at[name]
        teeth = [(x + 4 - k - (k % 2), y + 3 + 2.5 * (k % 2)) for k in range(9)]
        marks.append(("poly", [(x - 4, y + 3), (x + 4, y + 3)] + teeth, False))
    for name, direction in blocks:
        d = frame.vector(direction)
        n = math.hypot(*d)
        ux, uy = d[0] / n, d[1] / n
        c = at[name]
        corners = [(c[0] + sx * 4 * ux - sy * 2.2 * uy, c[1] + sx * 4 * uy + sy * 2.2 * ux)
                   for sx, sy in ((-1, -1), (1, -1), (1, 1), (-1, 1))]
        marks.append(("poly", corners, True))
    for p, direction in guides:
        d = frame.vector(direction)
        n = math.hypot(*d)
        c = frame.place(p)
        marks.append(("line", (c[0] - 45 * d[0] / n, c[1] - 45 * d[1] / n),
                      (c[0] + 45 * d[0] / n, c[1] + 45 * d[1] / n)))
    paper = {n: (frame.place(p)[0] + moved.get(n, (0, 0))[0],
                 frame.place(p)[1] + moved.get(n, (0, 0))[1]) for n, p in centres.items()}
    for name, through, other in kennedy:
        if name in paper and through in paper and other in paper:
            a, b = paper[through], paper[other]
            d = math.dist(a, b)
            if d > 1.0:
                u = ((b[0] - a[0]) / d, (b[1] - a[1]) / d)
                far = max(math.dist(a, paper[name]), math.dist(b, paper[name])) + \
                    rng.uniform(4, 12)
                marks.append(("line", a, (a[0] + far * u[0], a[1] + far * u[1]), "thin"))
    placer.points += list(at.values()) + list(paper.values())
    middle = _middle(list(at.values()))
    for name, p in at.items():
        placer.put(p, hand.point_runs(name), hand.size, (p[0] - middle[0], p[1] - middle[1]))
    for name, p in sorted(paper.items()):
        if not any(math.dist(p, q) < 0.3 for q in at.values()):
            marks.append(("dot", jitter(rng, p), 0.6))
        placer.put(p, hand.centre_runs(name), hand.size * 0.9,
                   (p[0] - middle[0] + rng.uniform(-5, 5), p[1] - middle[1]),
                   apart=hand.sub == "apart")


def frame_and_title(rng: random.Random, marks: list, page: Vec, title: str) -> None:
    """A border 10 mm in and a title block, as a course's sheets have (sometimes)."""
    w, h = page
    if rng.random() < 0.5:
        marks.append(("poly", [(10, 10), (w - 10, 10), (w - 10, h - 10), (10, h - 10)], True))
        marks.append(("poly", [(w - 110, h - 10), (w - 110, h - 28), (w - 10, h - 28),
                               (w - 10, h - 10)], False))
    marks.append(("text", (w - 106, h - 21), [(title, "")], 3.5))
    marks.append(("text", (w - 106, h - 14), [(f"Student no. {rng.randint(1000, 9999)}", "")],
                  3.0))
