"""Velocity and acceleration polygons and instant centres of the class's mechanisms, in
closed form from their loop equations, independent of tarsim's constructions and grader.

Two families, read from an exercise's TOML with tomllib:

- the four-bar (crank 2, coupler 3, rocker 4): B by cutting two circles on the side the
  file's ``[assembly]`` names, ω3 and ω4 from ``V_A + ω3 × AB = ω4 × O4B`` by Cramer's rule;
- the slotted lever (crank 2, block 3 pinned at A and sliding in the slot of lever 4 about
  O4), with or without a ram 5 whose pin B runs in the same slot and which slides on a
  straight guide (the crank-shaper). Projecting ``A_A2 = A_A4 + 2ω4 × v_rel + a_rel`` on
  the slot's normal gives α4 in one line; the ram's ``aB d − a_rel u = …`` is two
  equations in two unknowns, solved by cross products.

Vectors are SI (m, m/s, m/s²), x right and y up, angles counter-clockwise. The tips are
named as tarsim's polygons name them (``A``, ``A4``, ``B4``, ``B``) and each knows the tips
it is built from, so a student's earlier error can be followed forward.

A student's wrong polygon is the same solve with one input changed: ``coriolis`` flips the
sign of the Coriolis term at a slide point, ``input_acceleration`` replaces the crank pin's
acceleration (normal and tangential components confused).
"""

from __future__ import annotations

import math
import tomllib
from dataclasses import dataclass, field
from pathlib import Path

__all__ = ["Exercise", "Position", "read_exercise", "solve", "CATALOG"]

CATALOG = Path(__file__).resolve().parents[1] / "exercises" / "catalog"

Vec = tuple[float, float]
_LENGTH = {"mm": 1e-3, "cm": 1e-2, "m": 1.0, "in": 0.0254}
_RATE = {"rad/s": 1.0, "rpm": 2 * math.pi / 60, "deg/s": math.pi / 180}


def _add(*vs: Vec) -> Vec:
    return (sum(v[0] for v in vs), sum(v[1] for v in vs))


def _sub(a: Vec, b: Vec) -> Vec:
    return (a[0] - b[0], a[1] - b[1])


def _mul(k: float, v: Vec) -> Vec:
    return (k * v[0], k * v[1])


def _perp(v: Vec) -> Vec:
    """``v`` turned 90° counter-clockwise: ω × v is ``ω * _perp(v)``."""
    return (-v[1], v[0])


def _dot(a: Vec, b: Vec) -> float:
    return a[0] * b[0] + a[1] * b[1]


def _cross(a: Vec, b: Vec) -> float:
    return a[0] * b[1] - a[1] * b[0]


@dataclass(frozen=True)
class Exercise:
    """What the class needs of an exercise file: its points (m), links, slides, input and
    the input angles (rad) of the positions it asks."""

    name: str
    family: str
    frame: dict[str, Vec]
    lengths: dict[str, float]
    links: dict[int, tuple[str, ...]]
    slides: tuple[dict, ...]
    omega: float
    alpha: float
    angles: tuple[float, ...]
    assembly: dict[str, str]
    space_scale: float | None
    """The drawing's stated length scale (paper mm per m), if it states one."""
    velocity_scale: float | None
    """The stated velocity-polygon scale (paper mm per m/s), if it states one."""
    has_centres: bool
    has_accelerations: bool


def read_exercise(name: str, folder: Path = CATALOG) -> Exercise:
    """The exercise ``name`` of ``folder`` (the bundled catalog by default)."""
    data = tomllib.loads((folder / f"{name}.toml").read_text(encoding="utf-8"))
    units = data.get("units", {})
    metres = _LENGTH[units.get("length", "mm")]
    rate = _RATE[units.get("angular_velocity", "rad/s")]
    degrees = units.get("angle", "deg") == "deg"
    frame = {k: (v[0] * metres, v[1] * metres) for k, v in data["frame"].items()}
    links, lengths = {}, {}
    for link in data["link"]:
        links[link["number"]] = tuple(link["points"])
        lengths.update({k: v * metres for k, v in link.get("lengths", {}).items()})
    slides = tuple({**s, "through": tuple(x * metres for x in s.get("through", ()))}
                   for s in data.get("slider", ()))
    inp = data["input"]
    omega, alpha = inp["omega"] * rate, inp.get("alpha", 0.0) * rate
    start = math.radians(inp["angle"]) if degrees else inp["angle"]
    angles = []
    for at in data.get("ask", {}).get("at", [{}]):
        if "time" in at:
            angles.append(start + omega * at["time"] + 0.5 * alpha * at["time"] ** 2)
        else:
            angles.append(math.radians(at["angle"]) if "angle" in at and degrees
                          else at.get("angle", start))
    finds = set(data.get("ask", {}).get("find", ()))
    scales = data.get("ask", {}).get("scale", [])
    space = velocity = None
    for text in scales:
        paper, world = (t.strip() for t in text.split("="))
        cm = float(paper.split()[0])
        amount, unit = world.split()
        if unit.endswith("/s"):
            velocity = 10 * cm / (float(amount) * _LENGTH[unit[:-2]])
        else:
            space = 10 * cm / (float(amount) * _LENGTH[unit])
    family = "four-bar" if not slides else "slotted lever"
    return Exercise(name, family, frame, lengths, links, slides, omega, alpha, tuple(angles),
                    data.get("assembly", {}), space, velocity,
                    "centres" in finds or any(f.startswith("I") for f in finds),
                    any(f.startswith(("A_", "alpha")) for f in finds))


@dataclass
class Position:
    """One position, solved: the mechanism's points, each link's ω and α, the polygons'
    tips from their poles, the Coriolis components, the finite instant centres, and for
    each tip the tips it is built from."""

    angle: float
    points: dict[str, Vec]
    omega: dict[int, float]
    alpha: dict[int, float]
    velocity: dict[str, Vec]
    acceleration: dict[str, Vec]
    coriolis: dict[str, Vec] = field(default_factory=dict)
    relative: dict[str, Vec] = field(default_factory=dict)
    """Each slide point's velocity relative to the link it slides on (V_A2/A4)."""
    centres: dict[str, Vec] = field(default_factory=dict)
    built_from: dict[str, str] = field(default_factory=dict)
    input_tip: str = "A"


def solve(ex: Exercise, position: int, *, coriolis: tuple[str, ...] = (),
          input_acceleration: Vec | None = None) -> Position:
    """Solve ``ex`` at its ``position``-th position (from 0), with the Coriolis term's sign
    flipped at each slide point named in ``coriolis`` and, if given, the crank pin's
    acceleration replaced by ``input_acceleration``."""
    theta = ex.angles[position]
    o2 = ex.frame["O2"]
    a = _add(o2, _mul(ex.lengths["O2A"], (math.cos(theta), math.sin(theta))))
    w2, e2 = ex.omega, ex.alpha
    v_a = _mul(w2, _perp(_sub(a, o2)))
    a_a = _add(_mul(-w2 * w2, _sub(a, o2)), _mul(e2, _perp(_sub(a, o2))))
    if input_acceleration is not None:
        a_a = input_acceleration
    solver = _four_bar if ex.family == "four-bar" else _slotted_lever
    pos = solver(ex, theta, a, v_a, a_a, coriolis)
    pos.centres = _centres(pos, ex)
    return pos


def _four_bar(ex: Exercise, theta: float, a: Vec, v_a: Vec, a_a: Vec, coriolis) -> Position:
    o2, o4 = ex.frame["O2"], ex.frame["O4"]
    r3, r4 = ex.lengths["AB"], ex.lengths["O4B"]
    d = math.dist(a, o4)
    u = _mul(1 / d, _sub(o4, a))
    along = (r3 * r3 - r4 * r4 + d * d) / (2 * d)
    side = 1.0 if ex.assembly.get("B", "left") == "left" else -1.0
    b = _add(a, _mul(along, u), _mul(side * math.sqrt(r3 * r3 - along * along), _perp(u)))
    # ω3 (B − A) − ω4 (B − O4) = ⟂V_A: the loop V_A + ω3 × AB = ω4 × O4B, turned by −90°.
    p, q, rhs = _sub(b, a), _mul(-1, _sub(b, o4)), _perp(v_a)
    det = _cross(p, q)
    w3, w4 = _cross(rhs, q) / det, _cross(p, rhs) / det
    v_b = _mul(w4, _perp(_sub(b, o4)))
    # The same loop differentiated once more, for α3 and α4.
    known = _add(a_a, _mul(-w3 * w3, _sub(b, a)), _mul(w4 * w4, _sub(b, o4)))
    rhs = _perp(known)
    e3, e4 = _cross(rhs, q) / det, _cross(p, rhs) / det
    a_b = _add(_mul(-w4 * w4, _sub(b, o4)), _mul(e4, _perp(_sub(b, o4))))
    return Position(theta, {"O2": o2, "O4": o4, "A": a, "B": b},
                    {1: 0.0, 2: ex.omega, 3: w3, 4: w4}, {1: 0.0, 2: ex.alpha, 3: e3, 4: e4},
                    {"A": v_a, "B": v_b}, {"A": a_a, "B": a_b}, built_from={"B": "A"})


def _slotted_lever(ex: Exercise, theta: float, a: Vec, v_a: Vec, a_a: Vec,
                   coriolis) -> Position:
    o2, o4 = ex.frame["O2"], ex.frame["O4"]
    r = math.dist(a, o4)
    u = _mul(1 / r, _sub(a, o4))                      # the slot, from O4 through A
    n = _perp(u)
    w4 = _dot(v_a, n) / r
    slide = _dot(v_a, u)                               # V_A2/A4 = slide u
    cor_a = _mul(2 * w4 * slide, n)
    sign_a = -1.0 if "A" in coriolis else 1.0
    e4 = (_dot(a_a, n) - sign_a * _dot(cor_a, n)) / r
    v_a4 = _mul(w4, _perp(_sub(a, o4)))
    a_a4 = _add(_mul(-w4 * w4, _sub(a, o4)), _mul(e4, _perp(_sub(a, o4))))
    points = {"O2": o2, "O4": o4, "A": a}
    velocity = {"A": v_a, "A4": v_a4}
    acceleration = {"A": a_a, "A4": a_a4}
    built = {"A4": "A"}
    omega = {1: 0.0, 2: ex.omega, 3: w4, 4: w4}
    alpha = {1: 0.0, 2: ex.alpha, 3: e4, 4: e4}
    cor, rel = {"A": cor_a}, {"A": _mul(slide, u)}
    ram = next((s for s in ex.slides if s["link"] == 5 and s["on"] == 1), None)
    if ram is None:                                    # B is the lever's own point
        b = _add(o4, _mul(ex.lengths["O4B"], u))
        points["B"] = b
        velocity["B"] = _mul(w4, _perp(_sub(b, o4)))
        acceleration["B"] = _add(_mul(-w4 * w4, _sub(b, o4)), _mul(e4, _perp(_sub(b, o4))))
        built["B"] = "A4"
    else:                                              # the ram's pin B in the same slot
        g = (math.cos(math.radians(ram["angle"])), math.sin(math.radians(ram["angle"])))
        b = _add(o4, _mul(_cross(_sub(ram["through"], o4), g) / _cross(u, g), u))
        points["B"] = b
        v_b4 = _mul(w4, _perp(_sub(b, o4)))
        a_b4 = _add(_mul(-w4 * w4, _sub(b, o4)), _mul(e4, _perp(_sub(b, o4))))
        # vB g − w u = V_B4: the ram's speed and the pin's slide in the slot.
        vb, w = _cross(v_b4, u) / _cross(g, u), _cross(v_b4, g) / _cross(g, u)
        cor_b = _mul(2 * w4 * w, n)
        sign_b = -1.0 if "B" in coriolis else 1.0
        rhs = _add(a_b4, _mul(sign_b, cor_b))
        ab = _cross(rhs, u) / _cross(g, u)
        velocity.update({"B4": v_b4, "B": _mul(vb, g)})
        acceleration.update({"B4": a_b4, "B": _mul(ab, g)})
        built.update({"B4": "A4", "B": "B4"})
        omega[5], alpha[5] = 0.0, 0.0
        cor["B"], rel["B"] = cor_b, _mul(w, u)
    return Position(theta, points, omega, alpha, velocity, acceleration, cor, rel,
                    built_from=built)


def _centres(pos: Position, ex: Exercise) -> dict[str, Vec]:
    """Every finite instant centre I_ij: where links i and j move alike. Link k moves as
    ``v_k + ω_k × (P − p_k)``, so ``P = (ω_i p_i − ω_j p_j + ⟂(v_i − v_j)) / (ω_i − ω_j)``;
    links turning together (a slider's pair) have theirs at infinity, or none at all."""
    if not ex.has_centres:
        return {}
    fields = {1: ((0.0, 0.0), (0.0, 0.0)), 2: (pos.points["O2"], (0.0, 0.0))}
    if ex.family == "four-bar":
        fields[3] = (pos.points["A"], pos.velocity["A"])
        fields[4] = (pos.points["O4"], (0.0, 0.0))
    else:
        fields[3] = (pos.points["A"], pos.velocity["A"])
        fields[4] = (pos.points["O4"], (0.0, 0.0))
        if "B4" in pos.velocity:
            fields[5] = (pos.points["B"], pos.velocity["B"])
    out = {}
    for i in fields:
        for j in fields:
            wi, wj = pos.omega[i], pos.omega[j]
            if i < j and abs(wi - wj) > 1e-12 * (abs(wi) + abs(wj)):
                (pi, vi), (pj, vj) = fields[i], fields[j]
                top = _add(_mul(wi, pi), _mul(-wj, pj), _perp(_sub(vi, vj)))
                out[f"I{i}{j}"] = _mul(1 / (wi - wj), top)
    return out
