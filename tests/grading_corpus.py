"""A class of students' drawings, made independently of tarsim's grader, with the verdict
each item must get: the measuring stick of ``tarsim grade``.

Run ``python tests/grading_corpus.py`` to write the committed class (seed 1, 60 drawings a
program, into tests/data/grading/class/), or ``--seed 2 --out /tmp/unseen`` for a class not
seen before; ``--where`` adds to key.json where each item is drawn. Score a grader on it
with benchmarks/grading_corpus.py.

**The class.** Drawings of the bundled crank-shaper (both positions it asks), four-bar and
inverted slider-crank, each written the way one program exports SVG
(tests/svg_writers.py): Inkscape 1.2, GeoGebra, LibreOffice Draw 7, a CAD program and by
hand. A drawing is a velocity polygon and, where the exercise has one, an acceleration
polygon; some sheets carry the space diagram with its instant centres beside them, some lay
the space diagram and the polygons out on one sheet as tarsim's worked figure does, labelled
in tarsim's notation. The polygons are at the exercise's scale or the drawing's own (written
on the sheet sometimes), in the sheet's orientation as a set square transfers it, put down
by a hand within 0.15 mm (tests/student_sheets.py).

**The truth** comes from tests/loop_kinematics.py: closed-form loop equations of the three
mechanisms read from their TOML files, sharing nothing with tarsim's constructions.

**The mistakes**, one or two on about half the drawings, with what each item must get:
a tip 2–5 % long or short (one no tip is built from) is ``wrong magnitude``; a reversed
Coriolis component makes its tip ``reversed Coriolis`` and each tip drawn correctly from it
``follows from an earlier error`` (the polygon solved with that Coriolis term's sign
flipped); the crank pin's normal acceleration laid off along its tangent is judged by the
rule below, and the tips built from it follow; two labels swapped are both ``swapped``; a
tip left out is ``missing``; a centre 5–20 mm off is ``wrong position``; a scale written
10–30 % off the drawn input makes the input ``wrong magnitude`` and the rest follow; every
velocity reversed makes the input ``wrong sense`` and the rest follow; a drawing of the
other position than the one asked must be said to match it (``position_matched``).
Everything else is ``correct``; labelled construction points (n′, x′) are no items.

**The rule for a wrong tip**, at the course's drafting precision (a pen of 0.5 mm, a set
square true to 0.5°): within 0.5 mm plus its length times tan 0.5° it is correct;
otherwise ``wrong sense`` if it points the other way from the pole, ``wrong magnitude`` if
its direction is within 0.5° plus the pen over its length, ``wrong direction`` else. A
mistake whose items fall within 0.6–1.6 times a threshold is drawn again, so no verdict
rests on a hair.
"""

from __future__ import annotations

import argparse
import json
import math
import random
import sys
from dataclasses import dataclass, field, replace
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from loop_kinematics import Exercise, Position, read_exercise, solve  # noqa: E402
from student_sheets import Frame, frame_and_title  # noqa: E402
from svg_writers import WRITERS  # noqa: E402
import sheet_layout as layout  # noqa: E402

__all__ = ["PROGRAMS", "EXERCISES", "PEN", "ANGLE", "item_name", "rule", "make_class",
           "make_drawing", "Polygon"]

PROGRAMS = ("inkscape", "geogebra", "libreoffice", "cad", "hand")
EXERCISES = (("crank-shaper", 0.45), ("four-bar", 0.25), ("inverted-slider-crank", 0.30))
PEN, ANGLE = 0.5, math.radians(0.5)
"""The course's drafting precision: a pen of 0.5 mm, a set square true to 0.5°."""

FOLLOWS = "follows from an earlier error"


def item_name(tip: str, kind: str) -> str:
    """A tip's item name, as the key gives it: ``a4`` for V_A4's tip, ``b′`` for A_B's."""
    return tip.lower() + ("′" if kind == "a" else "")


def tolerance(length: float) -> float:
    """How far from its place a tip ``length`` mm from the pole may be drawn."""
    return PEN + length * math.tan(ANGLE)


def rule(expected: tuple[float, float], got: tuple[float, float]) -> tuple[str, bool]:
    """The verdict on a tip drawn at ``got`` (paper mm from the pole) where ``expected``
    belongs, and whether it is clear of every threshold by the factor 0.6–1.6."""
    length = math.hypot(*expected)
    tol = tolerance(length)
    miss = math.dist(expected, got)
    if miss <= tol:
        return "correct", miss <= 0.6 * tol
    if length < PEN or math.hypot(*got) < PEN:
        return "wrong magnitude", miss >= 1.6 * tol
    turn = abs(math.remainder(math.atan2(got[1], got[0]) - math.atan2(*expected[::-1]),
                              2 * math.pi))
    slack = ANGLE + math.atan2(PEN, length)
    clear = miss >= 1.6 * tol
    if abs(turn - math.pi) <= slack:
        return "wrong sense", clear and abs(turn - math.pi) <= 0.6 * slack
    if turn <= slack:
        return "wrong magnitude", clear and turn <= 0.6 * slack
    return "wrong direction", clear and min(turn, math.pi - turn) >= 1.6 * slack


@dataclass
class Polygon:
    """One polygon as the student drew it: its kind, the true tips and those drawn (SI, from
    the pole), the scale drawn at and the one written (paper mm a unit, None if none), the
    labels written at each tip (a swap), the tips left out, the prescribed verdicts and the
    tips whose errors others follow, and the position solved as drawn."""

    kind: str
    true: dict
    drawn: dict
    solved: Position
    built_from: dict
    input_tip: str = "A"
    scale: float = 1.0
    written: float | None = None
    source: str = "own"
    labels: dict = field(default_factory=dict)
    missing: set = field(default_factory=set)
    prescribed: dict = field(default_factory=dict)
    roots: set = field(default_factory=set)
    coriolis: tuple = ()

    def descends(self, tip: str) -> bool:
        """Whether ``tip`` is built, at any remove, from a tip drawn wrong."""
        while tip in self.built_from:
            tip = self.built_from[tip]
            if tip in self.roots:
                return True
        return False


@dataclass
class Drawing:
    """One student's drawing: what it is of and how it was made, and its key entry."""

    exercise: Exercise
    position: int
    drawn_position: int
    program: str
    sheet: str
    polygons: list
    centres: dict
    moved: dict = field(default_factory=dict)
    mistakes: list = field(default_factory=list)
    turn: float = 0.0


class Redraw(Exception):
    """A mistake that leaves some item too near a threshold: draw the sheet again."""


def _pick_exercise(rng: random.Random) -> str:
    names, weights = zip(*EXERCISES)
    return rng.choices(names, weights)[0]


@dataclass(frozen=True)
class Plan:
    """What a drawing is of: the exercise, the position asked (from 0), the sheet (polygons,
    centres beside them, or tarsim's worked page) and the student's mistakes."""

    exercise: str
    position: int
    sheet: str
    mistakes: tuple[str, ...]


def _plan(rng: random.Random) -> Plan:
    ex = read_exercise(_pick_exercise(rng))
    position = rng.randrange(len(ex.angles))
    sheet = rng.choices(["polygons", "centres", "worked"], [0.62, 0.22, 0.16])[0]
    return Plan(ex.name, position, sheet, _mistakes(rng, ex, position, sheet))


def _mistakes(rng: random.Random, ex: Exercise, position: int, sheet: str) -> tuple:
    """One or two mistakes a student could make on this sheet, or none half the time."""
    if rng.random() < 0.5:
        return ()
    kinds = ["magnitude", "swap", "missing", "scale", "reversed"]
    if ex.has_accelerations:
        kinds += ["normal-tangential", "normal-tangential"]
        if any(math.hypot(*c) > 1e-9 for c in solve(ex, position).coriolis.values()):
            kinds += ["coriolis", "coriolis"]
    if sheet != "polygons" and ex.has_centres:
        kinds += ["centre", "centre"]
    if len(ex.angles) > 1:
        kinds += ["position", "position"]
    first = rng.choice(kinds)
    polygons = 2 if ex.has_accelerations else 1
    # A second mistake goes on the other polygon, or on the centres.
    seconds = [k for k in kinds if k not in ("position", "centre") and polygons == 2
               and _ON.get(k, "any") != _ON.get(first, "other")] + \
        [k for k in kinds if k == "centre" != first]
    if first == "position" or not seconds or rng.random() < 0.55:
        return (first,)
    return (first, rng.choice(seconds))


_ON = {"reversed": "v", "coriolis": "a", "normal-tangential": "a", "centre": "centres"}
"""The polygon (or the centres) a mistake can only be made on."""


def make_drawing(rng: random.Random, program: str, where: bool = False) -> tuple[str, dict]:
    """One drawing of the class, written by ``program``: (SVG, its key entry, with where
    each item is drawn if ``where``). A sheet whose mistakes cannot be put on paper clear
    of every threshold, or whose labels cannot be placed fairly, is laid out again; after
    fifteen tries its mistakes are chosen again (the exercise and the sheet stay)."""
    plan = _plan(rng)
    for attempt in range(90):
        if attempt and attempt % 15 == 0:
            ex = read_exercise(plan.exercise)
            plan = replace(plan, mistakes=_mistakes(rng, ex, plan.position, plan.sheet))
        try:
            return _attempt(rng, program, where, plan)
        except Redraw:
            continue
    raise RuntimeError(f"no drawing of {plan} clear of every threshold in 90 tries")


def _attempt(rng: random.Random, program: str, where: bool, plan: Plan) -> tuple[str, dict]:
    ex = read_exercise(plan.exercise)
    position, sheet, mistakes = plan.position, plan.sheet, plan.mistakes
    drawn_position = position
    if "position" in mistakes:
        drawn_position = rng.choice([k for k in range(len(ex.angles)) if k != position])
    truth = solve(ex, drawn_position)
    polygons = [_polygon(ex, truth, "v")]
    if ex.has_accelerations:
        polygons.append(_polygon(ex, truth, "a"))
    d = Drawing(ex, position, drawn_position, program, sheet, polygons,
                truth.centres if sheet != "polygons" else {}, mistakes=[])
    for m in mistakes:
        _solve_wrong(rng, d, m, truth)
    page = layout.lay_out(rng, d)
    for m in list(d.mistakes):
        _on_paper(rng, d, m)
    items = _verdicts(d)
    _apart(d, page)
    marks, ambiguous = layout.marks(rng, d, page)
    if ambiguous:
        raise Redraw
    if program != "geogebra":               # a graphics view exported has no title block
        frame_and_title(rng, marks, page.size, f"{ex.name}: position {position + 1}")
    if program == "geogebra":
        svg = WRITERS[program](rng, marks, page.size,
                               zoom=1.0 if any(p.written for p in polygons) else None)
    elif program == "cad":
        svg = WRITERS[program](rng, marks, page.size, model=page.model)
    else:
        svg = WRITERS[program](rng, marks, page.size)
    key = {"exercise": ex.name, "position": position + 1, "program": program, "sheet": sheet,
           "scales": {p.kind: p.source + (" written" if p.written else "") for p in polygons},
           "mistakes": d.mistakes, "items": items}
    if drawn_position != position:
        key["position_matched"] = drawn_position + 1
    if where:
        key["at"] = _where(d, page)
    return svg, key


def _where(d: Drawing, page) -> dict[str, list[float]]:
    """Where on the paper (mm, y down) each item is drawn, to read a grade against."""
    out = {}
    for poly in d.polygons:
        frame = page.frames[poly.kind]
        for tip, v in poly.drawn.items():
            if tip not in poly.missing:
                out[item_name(tip, poly.kind)] = [round(c, 2) for c in frame.place(v)]
    for name, p in d.centres.items():
        at, off = page.frames["s"].place(p), d.moved.get(name, (0.0, 0.0))
        out[name] = [round(at[0] + off[0], 2), round(at[1] + off[1], 2)]
    return out


def _polygon(ex: Exercise, pos: Position, kind: str) -> Polygon:
    tips = pos.velocity if kind == "v" else pos.acceleration
    return Polygon(kind, dict(tips), dict(tips), pos, dict(pos.built_from))


def _solve_wrong(rng: random.Random, d: Drawing, mistake: str, truth: Position) -> None:
    """Draw the polygons as a student who made ``mistake`` would, before they go on paper."""
    v = d.polygons[0]
    a = d.polygons[1] if len(d.polygons) > 1 else None
    ex, k = d.exercise, d.drawn_position
    if mistake == "coriolis":
        if a is None or a.roots:
            raise Redraw
        at = rng.choice([p for p, c in truth.coriolis.items() if math.hypot(*c) > 1e-9]
                        or [None])
        if at is None:
            raise Redraw
        wrong = solve(ex, k, coriolis=(at,))
        a.drawn, a.solved, a.coriolis = dict(wrong.acceleration), wrong, (at,)
        root = "A4" if at == "A" else "B"
        a.roots.add(root)
        a.prescribed[root] = "reversed Coriolis"
        d.mistakes.append(f"Coriolis component at {at} reversed")
    elif mistake == "normal-tangential":
        if a is None or a.roots:
            raise Redraw
        radius = (truth.points["A"][0] - truth.points["O2"][0],
                  truth.points["A"][1] - truth.points["O2"][1])
        w, e = truth.omega[2], truth.alpha[2]
        r = math.hypot(*radius)
        out = (radius[0] / r, radius[1] / r)
        along = (-out[1] * math.copysign(1, w), out[0] * math.copysign(1, w))
        # ω²r laid off along the tangent, αr along the radius.
        given = (w * w * r * along[0] + e * r * out[0], w * w * r * along[1] + e * r * out[1])
        wrong = solve(ex, k, input_acceleration=given)
        a.drawn, a.solved = dict(wrong.acceleration), wrong
        a.roots.add("A")
        d.mistakes.append("normal and tangential components of A_A confused")
    elif mistake == "reversed":
        if v.roots:
            raise Redraw
        v.drawn = {t: (-x, -y) for t, (x, y) in v.drawn.items()}
        v.roots.add("A")
        v.prescribed["A"] = "wrong sense"
        d.mistakes.append("every velocity reversed")
    elif mistake == "magnitude":
        poly = rng.choice(d.polygons)
        leaves = [t for t in poly.true if t not in poly.built_from.values() and t != "A"
                  and math.hypot(*poly.true[t]) > 0 and t not in poly.roots
                  and not poly.descends(t)]
        if not leaves or poly.roots:
            raise Redraw
        tip = rng.choice(leaves)
        poly.prescribed[tip] = "wrong magnitude"
        poly.roots.add(tip)
        d.mistakes.append(f"magnitude:{poly.kind}:{tip}:{rng.choice((-1, 1)) * rng.uniform(2, 5)}")
    elif mistake in ("swap", "missing", "scale", "centre", "position"):
        d.mistakes.append(mistake)


def _on_paper(rng: random.Random, d: Drawing, mistake: str) -> None:
    """The mistakes made on paper, once the scales are known."""
    if mistake.startswith("magnitude:"):
        _, kind, tip, percent = mistake.split(":")
        poly = next(p for p in d.polygons if p.kind == kind)
        length = math.hypot(*poly.true[tip]) * poly.scale
        percent = float(percent)
        # At least 1.8 pens' tolerance, and within 2–5 %: or draw the sheet again.
        need = 100 * 1.8 * tolerance(length) / length
        if need > 5:
            raise Redraw
        percent = math.copysign(max(abs(percent), need), percent)
        x, y = poly.drawn[tip]
        poly.drawn[tip] = (x * (1 + percent / 100), y * (1 + percent / 100))
        d.mistakes[d.mistakes.index(mistake)] = f"{item_name(tip, kind)} {percent:+.1f} % long"
    elif mistake == "swap":
        poly = rng.choice(d.polygons)
        if poly.roots or poly.labels:
            raise Redraw
        pairs = [(s, t) for s in poly.true for t in poly.true if s < t
                 and min(math.hypot(*poly.drawn[s]), math.hypot(*poly.drawn[t])) * poly.scale > 3
                 and math.dist(poly.drawn[s], poly.drawn[t]) * poly.scale > 6]
        if not pairs:
            raise Redraw
        s, t = rng.choice(pairs)
        poly.labels[s], poly.labels[t] = t, s
        poly.prescribed[s] = poly.prescribed[t] = "swapped"
        d.mistakes[d.mistakes.index(mistake)] = \
            f"labels {item_name(s, poly.kind)} and {item_name(t, poly.kind)} swapped"
    elif mistake == "missing":
        poly = rng.choice(d.polygons)
        left = [t for t in poly.true if t != poly.input_tip and t not in poly.labels
                and t not in poly.prescribed and math.hypot(*poly.drawn[t]) * poly.scale > 3]
        if not left or poly.roots:
            raise Redraw
        tip = rng.choice(left)
        poly.missing.add(tip)
        poly.prescribed[tip] = "missing"
        d.mistakes[d.mistakes.index(mistake)] = f"{item_name(tip, poly.kind)} left out"
    elif mistake == "scale":
        poly = rng.choice(d.polygons)
        if poly.roots or poly.source == "arbitrary":
            raise Redraw
        factor = 1 + rng.choice((-1, 1)) * rng.uniform(0.10, 0.30)
        poly.written = layout.nice_written(poly.scale * factor)
        ratio = poly.written / poly.scale
        if not 1.1 <= max(ratio, 1 / ratio) <= 1.3:
            raise Redraw
        poly.roots.add("A")
        poly.prescribed["A"] = "wrong magnitude"
        d.mistakes[d.mistakes.index(mistake)] = \
            f"{'velocity' if poly.kind == 'v' else 'acceleration'} scale written " \
            f"{100 * (ratio - 1):+.0f} % off the drawn input"
    elif mistake == "centre":
        pins = d.polygons[0].solved.points.values()
        names = [n for n, p in d.centres.items() if not any(math.dist(p, q) < 1e-9 for q in pins)]
        if not names or d.moved:
            raise Redraw
        name = rng.choice(names)
        a, r = rng.uniform(0, 2 * math.pi), rng.uniform(5, 20)
        d.moved[name] = (r * math.cos(a), r * math.sin(a))
        d.mistakes[d.mistakes.index(mistake)] = f"{name} {r:.1f} mm off"
    elif mistake == "position":
        d.mistakes[d.mistakes.index(mistake)] = \
            f"position {d.drawn_position + 1} drawn, {d.position + 1} asked"


def _apart(d: Drawing, page) -> None:
    """Tips a reader can tell apart: any two drawn 4 mm apart at least, or together."""
    for poly in d.polygons:
        frame = page.frames[poly.kind]
        at = [frame.place(v) for t, v in poly.drawn.items() if t not in poly.missing]
        for i, p in enumerate(at + [frame.origin]):
            for q in at[i + 1:] + ([frame.origin] if i < len(at) else []):
                if 0.3 < math.dist(p, q) < 4.0:
                    raise Redraw


def _verdicts(d: Drawing) -> dict[str, str]:
    """Each item's verdict: prescribed for the mistakes, by the rule for the rest."""
    items = {}
    for poly in d.polygons:
        frame = Frame(1.0, (0.0, 0.0), d.turn)
        held = poly.written or poly.scale
        for tip, true in poly.true.items():
            name = item_name(tip, poly.kind)
            exp = frame.vector((true[0] * held, true[1] * held))
            got = frame.vector((poly.drawn[tip][0] * poly.scale,
                                poly.drawn[tip][1] * poly.scale))
            verdict, clear = rule(exp, got)
            if tip in poly.prescribed:
                if poly.prescribed[tip] in ("wrong magnitude", "wrong sense") and \
                        (verdict, clear) != (poly.prescribed[tip], True):
                    raise Redraw
                if poly.prescribed[tip] == "reversed Coriolis" and \
                        (verdict == "correct" or not clear):
                    raise Redraw
                items[name] = poly.prescribed[tip]
            elif not clear:
                raise Redraw
            elif tip in poly.roots:                  # a confusion judged by the rule
                if verdict == "correct":
                    raise Redraw
                items[name] = verdict
            elif poly.descends(tip) and verdict != "correct":
                items[name] = FOLLOWS
            elif verdict != "correct":
                raise Redraw
            else:
                items[name] = "correct"
    for name in d.centres:
        items[name] = "wrong position" if name in d.moved else "correct"
    return items


def make_class(seed: int, out: Path, per_program: int = 60, where: bool = False) -> dict:
    """Write the class of ``seed`` into ``out`` (one folder per program and key.json, with
    where each item is drawn if ``where``); return the key."""
    key = {"seed": seed, "drafting": {"pen_mm": PEN, "angle_deg": math.degrees(ANGLE)},
           "files": {}}
    for program in PROGRAMS:
        (out / program).mkdir(parents=True, exist_ok=True)
        for k in range(1, per_program + 1):
            rng = random.Random(f"{seed}/{program}/{k}")
            svg, entry = make_drawing(rng, program, where)
            name = f"{program}/{program}-{k:03}.svg"
            (out / name).write_bytes(svg.encode("utf-8"))
            key["files"][name] = entry
    # One line a drawing, so a change to the class reads as a diff of the drawings changed.
    head = json.dumps({k: v for k, v in key.items() if k != "files"}, ensure_ascii=False)
    lines = [f"{json.dumps(n)}: {json.dumps(e, ensure_ascii=False, separators=(',', ':'))}"
             for n, e in key["files"].items()]
    (out / "key.json").write_text(head[:-1] + ', "files": {\n' + ",\n".join(lines) + "\n}}\n",
                                  encoding="utf-8")
    return key


def main(argv: list[str] | None = None) -> None:
    """Write a class: ``--seed`` (1 is the committed one), ``--out``, ``--per-program``."""
    args = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    args.add_argument("--seed", type=int, default=1)
    args.add_argument("--out", type=Path, default=Path(__file__).resolve().parent / "data"
                      / "grading" / "class")
    args.add_argument("--per-program", type=int, default=60)
    args.add_argument("--where", action="store_true",
                      help="give in key.json where each item is drawn (paper mm, y down)")
    a = args.parse_args(argv)
    key = make_class(a.seed, a.out, a.per_program, a.where)
    files = key["files"].values()
    wrong = sum(v != "correct" for f in files for v in f["items"].values())
    print(f"{len(key['files'])} drawings, {sum(len(f['items']) for f in files)} items "
          f"({wrong} wrong), {sum(not f['mistakes'] for f in files)} fully correct, in {a.out}")


if __name__ == "__main__":
    main()
