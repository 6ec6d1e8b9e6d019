"""Random mechanisms of every family tarsim reads, degenerate and malformed ones included.

The contract under test: every input either solves to finite numbers that all pass
their check against the analytic solver, or is refused with one ``TarsimError`` line
that says what is wrong and where. ``generate(rng)`` makes one case as TOML text;
``run_case`` loads and solves it and ``classify_error`` judges a refusal's line.
benchmarks/robustness.py runs thousands of them and tests/test_robustness.py a few
under hypothesis, so both share this file.

Each family is built in a canonical pose from a textbook layout (the bundled catalog
and tests/data), then scaled over twelve decades, turned, and given its units. The
input angle is often a special one, worked out here from the lengths: a dead point
(coupler and rocker in line), a limit position (crank and rod in line, the lever
tangent to the crank circle), a change point, 0, 90 or 180, or ±1e9. A case is
sometimes broken on purpose (a zero or out-of-range length, a coincident frame, a
misspelt key, a truncated file): those must be refused cleanly, never crash.
"""

from __future__ import annotations

import json
import math
import random
import re
import sys
import tomllib
import traceback
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

sys.path.insert(0, str(Path(__file__).resolve().parent))

from closed_forms import contradictions  # noqa: E402

__all__ = ["FAMILIES", "OUTCOMES", "HOSTILE", "FOUR_BAR", "generate", "to_toml", "run_case",
           "classify_error", "Outcome", "point_names", "edited"]

FAMILIES = ("four-bar", "slider-crank", "slotted-lever", "six-bar", "contact")
"""The families, equally likely: a four-bar of every Grashof class; a slider-crank (in-line,
offset, curved guide); an inverted slider-crank or slotted lever (quick return, Whitworth,
P-37 with its ram, the crank-shaper); a Watt or Stephenson six-bar; and cams, rollers, a
rolling wheel and a curved slot."""

MALFORMED = 0.06
"""The share of cases broken on purpose after they are made."""

METHODS = ("radius-rotation", "parallel-line", "components", "polygon", "line-of-transmission")


# ----- TOML text --------------------------------------------------------------------------
@dataclass(frozen=True)
class Lit:
    """A value written into the file as it is (``300e-3``, a 300-digit integer, ``nan``)."""

    text: str


def _key(k: str) -> str:
    return k if re.fullmatch(r"[A-Za-z0-9_-]+", k) else json.dumps(k, ensure_ascii=False)


def _val(v: Any) -> str:
    if isinstance(v, Lit):
        return v.text
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        if math.isnan(v):
            return "nan"
        if math.isinf(v):
            return "inf" if v > 0 else "-inf"
        return repr(v)
    if isinstance(v, str):
        return json.dumps(v, ensure_ascii=False)
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(_val(x) for x in v) + "]"
    if isinstance(v, dict):
        return "{ " + ", ".join(f"{_key(k)} = {_val(x)}" for k, x in v.items()) + " }"
    raise TypeError(f"cannot write {v!r} as TOML")


def to_toml(spec: dict[str, Any]) -> str:
    """The mechanism file a spec describes: top-level text, [units], [frame], [[link]],
    [[slider]], [[contact]], [input], [assembly], [ask], each table's keys in order."""
    out: list[str] = []
    for k in ("name", "source", "description"):
        if k in spec:
            out.append(f"{k} = {_val(spec[k])}")
    for table in ("units", "frame"):
        if table in spec:
            out += ["", f"[{table}]"] + [f"{_key(k)} = {_val(v)}" for k, v in spec[table].items()]
    for many, header in (("links", "link"), ("sliders", "slider"), ("contacts", "contact")):
        for t in spec.get(many, []):
            out += ["", f"[[{header}]]"] + [f"{_key(k)} = {_val(v)}" for k, v in t.items()]
    for table in ("input", "assembly", "ask"):
        if spec.get(table):
            out += ["", f"[{table}]"] + [f"{_key(k)} = {_val(v)}" for k, v in spec[table].items()]
    return "\n".join(out) + "\n"


# ----- geometry the generator needs (special angles, near points) ----------------------------
def _circles(c0, r0, c1, r1):
    """The two cuts of two circles (left, right of c0 → c1), or None if they miss."""
    dx, dy = c1[0] - c0[0], c1[1] - c0[1]
    d = math.hypot(dx, dy)
    if d == 0 or d > r0 + r1 or d < abs(r0 - r1):
        return None
    a = (r0 * r0 - r1 * r1 + d * d) / (2 * d)
    h = math.sqrt(max(r0 * r0 - a * a, 0.0))
    mx, my = c0[0] + a * dx / d, c0[1] + a * dy / d
    return (mx - h * dy / d, my + h * dx / d), (mx + h * dy / d, my - h * dx / d)


def _acos(x: float) -> float | None:
    return math.acos(x) if -1.0 <= x <= 1.0 else None


def _polar(p, r, deg):
    t = math.radians(deg)
    return (p[0] + r * math.cos(t), p[1] + r * math.sin(t))


def _turn(p, deg):
    c, s = math.cos(math.radians(deg)), math.sin(math.radians(deg))
    return (p[0] * c - p[1] * s, p[0] * s + p[1] * c)


# ----- one case ----------------------------------------------------------------------------
@dataclass
class _Case:
    """The choices one case shares: its units, its size and its pose."""

    rng: random.Random
    units: dict[str, str] = field(default_factory=dict)
    size: float = 1.0
    pose: float = 0.0
    """The canonical layout is turned through this many degrees."""
    unfit: tuple[str, ...] = ()
    """Methods that cannot answer this family's velocities, asked for now and then only."""

    def __post_init__(self) -> None:
        r = self.rng
        if r.random() < 0.85:
            self.units = {"length": r.choice(["mm", "cm", "m", "in"])}
            if r.random() < 0.8:
                self.units["angle"] = r.choice(["deg", "deg", "rad"])
            if r.random() < 0.5:
                self.units["angular_velocity"] = r.choice(["rad/s", "rpm"])
        self.size = r.choice([1.0, 10.0, 100.0, 10 ** r.uniform(-6, 6),
                              10 ** r.choice([-6, -3, 3, 6])])
        self.pose = r.choice([0.0, 0.0, 0.0, 90.0, 180.0, -45.0, r.uniform(-180, 180)])

    @property
    def rad(self) -> bool:
        """Whether the file's angles are in radians."""
        return self.units.get("angle") == "rad"

    def length(self, x: float) -> float:
        """A canonical length at this case's size."""
        return x * self.size

    def point(self, p) -> list[float]:
        """A canonical point turned into this case's pose and scaled, as [x, y]."""
        q = _turn(p, self.pose)
        return [q[0] * self.size, q[1] * self.size]

    def angle(self, deg: float, *, posed: bool = True) -> float:
        """A canonical angle (degrees) in this pose, in the file's unit; huge ones kept huge."""
        if abs(deg) >= 1e6:
            return deg
        a = deg + (self.pose if posed else 0.0)
        return math.radians(a) if self.rad else a

    def input_angle(self, specials: list[float]) -> float:
        """The input angle: often one of ``specials`` (canonical degrees), else a plain one."""
        r = self.rng
        roll = r.random()
        if specials and roll < 0.3:
            return self.angle(r.choice(specials))
        if roll < 0.45:
            return self.angle(r.choice([0.0, 90.0, 180.0, 270.0, -90.0, 360.0]), posed=False)
        if roll < 0.5:
            return r.choice([1e9, -1e9, 1e9 + 0.5, 123456789.0, 1e15])
        return self.angle(r.uniform(-360, 360))

    def rate(self) -> float:
        """An ω or α: ordinary, zero, 1e-25, 1e25, either sign."""
        r = self.rng
        if r.random() < 0.03:
            return 0.0
        v = r.choice([r.uniform(0.1, 50), 1.0, 10.0, 1e-25, 1e25, 10 ** r.uniform(-25, 25)])
        return -v if r.random() < 0.4 else v

    def drive(self, link: int, specials: list[float]) -> dict[str, Any]:
        """The [input] table of a crank ``link``."""
        t: dict[str, Any] = {"link": link, "angle": self.input_angle(specials)}
        if self.rng.random() < 0.98:
            t["omega"] = self.rate()
        if self.rng.random() < 0.6:
            t["alpha"] = self.rate()
        return t

    def ask(self, mechanism: list[str], position: list[str],
            specials: list[float]) -> dict[str, Any]:
        """An [ask] table: mostly everything the family supports, sometimes a part of it, with
        a choice of methods, listed positions and stated scales."""
        r = self.rng
        roll = r.random()
        if roll < 0.4:
            find = mechanism + position
        elif roll < 0.5:
            find = mechanism or position
        elif roll < 0.85:
            find = position
        else:
            find = r.sample(mechanism + position, r.randint(1, len(mechanism + position)))
        t: dict[str, Any] = {"find": find}
        methods = [m for m in METHODS if m not in self.unfit or r.random() < 0.2]
        t["methods"] = r.sample(methods, r.randint(1, len(methods)))
        if r.random() < 0.3:
            at = []
            for _ in range(r.randint(1, 3)):
                if r.random() < 0.6:
                    at.append({"angle": self.input_angle(specials)})
                else:
                    at.append({"time": r.choice([0.0, 2.34, 1e-25, 0.5, 10 ** r.uniform(-6, 6),
                                                 1e6])})
            if r.random() < 0.9:
                at = list({json.dumps(p): p for p in at}.values())
            t["at"] = at
        if r.random() < 0.1:
            unit = self.units.get("length", "mm")
            scales = [f"1 cm = {self.length(r.choice([1, 2, 5])):.3g} {unit}",
                      f"3 cm = {10 ** r.uniform(-3, 3):.3g} {unit}/s",
                      f"1 cm = {10 ** r.uniform(-3, 3):.3g} m/s²"]
            t["scale"] = r.sample(scales, r.randint(1, 3))
        return t

    def branch(self, words: tuple[str, str], near: tuple[float, float] | None) -> Any:
        """An assembly branch: a word, or a point near the wanted cut."""
        if near is not None and self.rng.random() < 0.25:
            jitter = 1.0 + self.rng.choice([0.0, 1e-9, 1e-3, 0.1])
            return self.point((near[0] * jitter, near[1] * jitter))
        return self.rng.choice(words)


def _spec(c: _Case, name: str) -> dict[str, Any]:
    spec: dict[str, Any] = {"name": name}
    if c.units:
        spec["units"] = dict(c.units)
    return spec


# ----- four-bar ----------------------------------------------------------------------------
def _grashof_lengths(r: random.Random, kind: str) -> tuple[float, float, float, float] | None:
    """(crank, coupler, rocker, frame) of a Grashof class; None for "wide" (any lengths)."""
    if kind == "parallelogram":
        a, g = r.choice([(1, 3), (2, 3), (1, 1.5), (100, 300)])
        return (a, g, a, g)
    if kind == "kite":
        a, b = r.choice([(1, 3), (1, 2), (2, 5)])
        return r.choice([(a, b, b, a), (a, a, b, b)])
    if kind == "rhombus":
        return (1, 1, 1, 1)
    if kind == "change-point":
        s, p, long = sorted(r.randint(1, 20) for _ in range(3))
        q = s + long - p
        if q <= 0:
            return None
        lengths = [s, p, q, long]
        r.shuffle(lengths)
        return tuple(lengths)
    if kind not in ("crank-rocker", "double-crank", "double-rocker", "rocker-crank",
                    "non-grashof"):
        return None
    for _ in range(1000):
        s, p, q, long = sorted(10 ** r.uniform(-1, 1) for _ in range(4))
        grashof = s + long < p + q
        if kind == "non-grashof" and not grashof:
            rest = [p, q, long]
            r.shuffle(rest)
            return (rest[0], rest[1], rest[2], s) if r.random() < 0.5 else (s, *rest)
        if kind != "non-grashof" and grashof:
            rest = [p, q, long]
            r.shuffle(rest)
            slot = {"crank-rocker": 0, "double-crank": 3, "double-rocker": 1,
                    "rocker-crank": 2}[kind]
            lengths = rest[:]
            lengths.insert(slot, s)
            return tuple(lengths)
    return None


def four_bar(c: _Case) -> dict[str, Any]:
    """A four-bar O2-A-B-O4 of a chosen Grashof class, sometimes with a coupler point."""
    r = c.rng
    kind = r.choice(["crank-rocker", "crank-rocker", "double-crank", "double-rocker",
                     "rocker-crank", "non-grashof", "change-point", "parallelogram", "kite",
                     "rhombus", "wide", "degenerate"])
    lengths = _grashof_lengths(r, kind)
    if lengths is None:
        lengths = tuple(10 ** r.uniform(-3, 3) for _ in range(4))
    a, b, cc, g = (float(x) for x in lengths)
    literal = kind in ("change-point", "parallelogram", "kite", "rhombus")
    if kind == "degenerate":
        which = r.choice(["zero", "coincident", "unreachable", "tiny"])
        if which == "zero":
            a, b, cc = r.choice([(0.0, b, cc), (a, 0.0, cc), (a, b, 0.0)])
        elif which == "coincident":
            g = 0.0
        elif which == "unreachable":
            b, cc = 0.1 * g, 0.1 * g
            a = 2 * g
        else:
            a = g * 1e-12
    o2, o4 = (0.0, 0.0), (g, 0.0)
    specials = [0.0, 180.0]                  # a change point lines all four pins up here
    for d in (b + cc, abs(b - cc)):          # dead points: coupler and rocker in line
        x = _acos((a * a + g * g - d * d) / (2 * a * g)) if a * g else None
        if x is not None:
            specials += [math.degrees(x), -math.degrees(x)]
    for d, folded in ((b + a, False), (abs(b - a), True)):   # limits: crank and rod in line
        x = _acos((d * d + g * g - cc * cc) / (2 * d * g)) if d * g else None
        if x is not None:
            for s in (1, -1):
                specials.append(math.degrees(s * x) + (180.0 if folded and b > a else 0.0))
    spec = _spec(c, f"random four-bar ({kind})")

    def length(x: float) -> Any:
        if literal and x == int(x) and c.size == 10 ** round(math.log10(c.size)):
            return Lit(f"{int(x)}e{round(math.log10(c.size))}")
        return c.length(x)

    spec["frame"] = {"O2": c.point(o2), "O4": c.point(o4)}
    spec["links"] = [{"number": 2, "name": "crank", "points": ["O2", "A"],
                      "lengths": {"O2A": length(a)}}]
    coupler: dict[str, Any] = {"number": 3, "points": ["A", "B"], "lengths": {"AB": length(b)}}
    points = ["O2", "A", "B", "O4"]
    if r.random() < 0.25:
        ac = b * r.uniform(0.2, 1.5)
        bc = r.uniform(abs(b - ac), b + ac)         # a triangle that closes
        if r.random() < 0.2:
            ac, bc = 0.5 * b, 0.5 * b          # on the line AB: no side needed
        coupler["points"].append("C")
        coupler["lengths"].update(AC=length(ac), BC=length(bc))
        coupler["sides"] = {"C": r.choice(["left", "right"])}
        points.append("C")
    spec["links"] += [coupler, {"number": 4, "name": "rocker", "points": ["O4", "B"],
                                "lengths": {"O4B": length(cc)}}]
    spec["input"] = c.drive(2, specials)
    theta = spec["input"]["angle"]
    theta_deg = (math.degrees(theta) if c.rad else theta) - c.pose
    near = None
    cuts = _circles(_polar(o2, a, theta_deg), b, o4, cc)
    if cuts:
        near = r.choice(cuts)
    if r.random() < 0.97:
        spec["assembly"] = {"B": c.branch(("left", "right"), near)}
    mech = ["dof", "grashof", "range_AB", "range_O2A", "range_O4B", "range_O2O4", "time_ratio"]
    pos = ["centres", "omega2", "omega3", "omega4"]
    pos += [f"V_{p}" for p in points] + ["V_B/A", "alpha3", "alpha4"]
    pos += [f"A_{p}" for p in points[1:]] + ["A_B/A"]
    spec["ask"] = c.ask(mech, pos, specials)
    return spec


# ----- slider-crank ------------------------------------------------------------------------
def slider_crank(c: _Case) -> dict[str, Any]:
    """A crank O2A, rod AB and block B on a frame guide: in-line, offset, tilted or curved."""
    r = c.rng
    rod = 1.0
    ratio = r.choice([10 ** r.uniform(-4, 0), r.uniform(0.1, 0.9), 0.999, 1 - 1e-9, 1.0,
                      r.uniform(1.0, 1.5), 1e-4])
    crank = rod * ratio
    offset = r.choice([0.0, 0.0, r.uniform(-1, 1) * max(rod - crank, 0.0),
                       r.uniform(-1.2, 1.2) * rod, rod - crank])
    guide = r.choice([0.0, 0.0, 90.0, r.uniform(-180, 180)])
    curved = r.random() < 0.15
    specials = [0.0, 180.0, guide, guide + 180.0]
    # Crank and rod in line (limit positions): B on the guide at rod ± crank from O2.
    for d, folded in ((rod + crank, False), (abs(rod - crank), True)):
        if abs(offset) <= d:
            along = math.sqrt(d * d - offset * offset)
            for s in (1, -1):
                bx, by = _turn((s * along, offset), guide)
                deg = math.degrees(math.atan2(by, bx))
                specials.append(deg + (180.0 if folded and rod > crank else 0.0))
    # The rod square to the guide (the arc touches the guide): the two branches meet.
    for side in (1, -1):
        x = _acos((offset + side * rod) / crank) if crank else None
        if x is not None:
            specials += [guide + 90.0 + math.degrees(x), guide + 90.0 - math.degrees(x)]
    spec = _spec(c, "random slider-crank" + (" on a curved guide" if curved else ""))
    spec["frame"] = {"O2": c.point((0.0, 0.0))}
    rod_link: dict[str, Any] = {"number": 3, "name": "connecting rod", "points": ["A", "B"],
                                "lengths": {"AB": c.length(rod)}}
    points = ["O2", "A", "B"]
    if r.random() < 0.25:
        rod_link["points"].append("D")
        rod_link["lengths"].update(AD=c.length(0.5 * rod), BD=c.length(r.uniform(0.5, 1.2) * rod))
        rod_link["sides"] = {"D": r.choice(["left", "right"])}
        points.append("D")
    spec["links"] = [{"number": 2, "name": "crank", "points": ["O2", "A"],
                      "lengths": {"O2A": c.length(crank)}},
                     rod_link, {"number": 4, "name": "block", "points": ["B"]}]
    if curved:
        radius = r.choice([r.uniform(1.0, 3.0), 1e3, r.uniform(0.2, 1.0)]) * rod
        centre = _turn((rod, offset - radius), guide)
        spec["frame"]["K"] = c.point(centre)
        spec["sliders"] = [{"link": 4, "point": "B", "centre": "K",
                            "radius": c.length(radius), "side": r.choice(["left", "right"])}]
    else:
        slider: dict[str, Any] = {"link": 4, "point": "B", "on": 1}
        if r.random() < 0.6:
            slider["through"] = "O2"
        else:
            shift = r.uniform(-1, 1)
            slider["through"] = c.point(_turn((shift, 0.0), guide))
        slider["angle"] = c.angle(guide)
        if offset or r.random() < 0.3:
            slider["offset"] = c.length(offset)
        spec["sliders"] = [slider]
    spec["input"] = c.drive(2, specials)
    theta = spec["input"]["angle"]
    theta_deg = (math.degrees(theta) if c.rad else theta) - c.pose
    ax, ay = _turn(_polar((0.0, 0.0), crank, theta_deg), -guide)
    near = None
    if abs(ay - offset) <= rod:
        near = _turn((ax + math.sqrt(rod * rod - (ay - offset) ** 2), offset), guide)
    if r.random() < 0.97:
        words = ("left", "right") if curved else ("forward", "backward")
        spec["assembly"] = {"B": c.branch(words, near)}
    mech = ["dof"]
    if crank < rod or r.random() < 0.1:      # else there are no limit positions to ask of
        mech += ["time_ratio"] if curved else ["time_ratio", "stroke"]
    pos = ["centres", "omega2", "omega3", "omega4"] + [f"V_{p}" for p in points]
    pos += ["V_B/A", "alpha3", "alpha4"] + [f"A_{p}" for p in points[1:]] + ["A_B/A"]
    spec["ask"] = c.ask(mech, pos, specials)
    return spec


# ----- inverted slider-crank and slotted levers ----------------------------------------------
def slotted_lever(c: _Case) -> dict[str, Any]:
    """A crank driving a block in the slot of a lever: oscillating (quick return), turning
    fully (Whitworth), with a rod to a ram (P-37) or the ram's pin in the slot (crank-shaper).

    Canonical pose: O4 at the origin, O2 straight above it at the distance between pivots.
    """
    r = c.rng
    kind = r.choice(["inverted", "whitworth", "p37", "shaper"])
    d = 1.0
    crank = r.choice([r.uniform(0.05, 0.95), 10 ** r.uniform(-4, 0), 0.999, 1.0])
    if kind == "whitworth":
        crank = r.choice([r.uniform(1.05, 3.0), 1.0 + 1e-9, 1.0])
    lever = r.choice([r.uniform(1.0, 2.5), 1.0 + crank, 0.0 if r.random() < 0.1 else 1.6])
    spec = _spec(c, f"random slotted lever ({kind})")
    o4, o2 = (0.0, 0.0), (0.0, d)
    spec["frame"] = {"O4": c.point(o4), "O2": c.point(o2)}
    if r.random() < 0.05:
        spec["frame"]["O2"] = spec["frame"]["O4"]                # coincident pivots
    x = _acos(crank / d)
    specials = [90.0, -90.0]                 # the crank on the line of centres: v_rel = 0
    if x is not None:                        # the lever tangent to the crank circle
        specials += [-90.0 + math.degrees(x), -90.0 - math.degrees(x)]
    if crank == d:
        specials.append(-90.0)               # A on the lever's pivot: its slot has no line
    links: list[dict[str, Any]] = [
        {"number": 2, "name": "crank", "points": ["O2", "A"], "lengths": {"O2A": c.length(crank)}},
        {"number": 3, "name": "block", "points": ["A"]}]
    sliders: list[dict[str, Any]] = [{"link": 3, "point": "A", "on": 4}]
    if r.random() < 0.15:
        sliders[0]["offset"] = c.length(r.uniform(-0.3, 0.3) * crank)
    if r.random() < 0.05:
        sliders[0]["offset"] = c.length(d)                       # a slot the crank never reaches
    points = ["O2", "A", "O4"]
    asks_pos = ["centres", "omega3", "omega4", "V_A", "V_A2/A4", "V_A3/A4", "alpha4", "A_A",
                "A_A4", "A_A2/A4", "A_cor_A"]
    limits = (crank < d and kind != "whitworth") or r.random() < 0.1
    mech = ["dof", "time_ratio"] if limits else ["dof"]
    assembly: dict[str, Any] = {}
    if r.random() < 0.1:
        assembly["A"] = r.choice(["forward", "backward"])
    if kind == "shaper":
        h = r.choice([r.uniform(0.2, 1.5), 0.0, -0.5])
        links.append({"number": 4, "name": "slotted lever", "points": ["O4"]})
        links.append({"number": 5, "name": "ram", "points": ["B"]})
        sliders.append({"link": 5, "point": "B", "on": 1, "through": c.point((0.0, d + h)),
                        "angle": c.angle(0.0)})
        sliders.append({"kind": "pin", "link": 5, "point": "B", "on": 4})
        points.append("B")
        asks_pos += ["omega5", "V_B", "V_B5/B4", "A_B", "A_B4", "A_cor_B", "alpha5"]
        mech += ["stroke"] if limits else []
    else:
        lever_pts = ["O4", "B"] if lever else ["O4"]
        lever_link: dict[str, Any] = {"number": 4, "name": "slotted lever", "points": lever_pts}
        if lever:
            lever_link["lengths"] = {"O4B": c.length(lever)}
        links.append(lever_link)
        points += ["B"] if lever else []
        asks_pos += ["V_B", "A_B"] if lever else []
    if kind in ("p37", "whitworth") and lever:
        rod = r.uniform(0.3, 1.5) * lever
        if kind == "p37":
            swing = math.asin(min(crank / d, 1.0))
            height = lever * (1 + math.cos(swing)) / 2 + r.uniform(-0.5, 0.5) * rod
            through = (0.0, height)
        else:
            through = (0.0, 0.0)
        links += [{"number": 5, "name": "link BC", "points": ["B", "C"],
                   "lengths": {"BC": c.length(rod)}},
                  {"number": 6, "name": "ram", "points": ["C"]}]
        sliders.append({"link": 6, "point": "C", "on": 1,
                        "through": "O4" if through == (0.0, 0.0) else c.point(through),
                        "angle": c.angle(0.0)})
        if r.random() < 0.97:
            assembly["C"] = c.branch(("forward", "backward"), None)
        points.append("C")
        asks_pos += ["omega5", "omega6", "V_C", "V_C/B", "alpha5", "A_C", "A_C/B"]
        mech += ["stroke"] if limits else []
    spec["links"], spec["sliders"] = links, sliders
    spec["input"] = c.drive(2, specials)
    if assembly:
        spec["assembly"] = assembly
    spec["ask"] = c.ask(mech, asks_pos, specials)
    return spec


# ----- templates: six-bars, contacts, curved slots ------------------------------------------
_TEMPLATES: dict[str, dict[str, Any]] = {
    "watt-homework-3": {
        "family": "six-bar",
        "frame": {"O2": (0, 0), "O3": (220, 0), "O6": (-170, 160)},
        "links": [{"number": 2, "points": ["O2", "A", "C"],
                   "lengths": {"O2A": 100, "O2C": 60, "AC": 60}, "sides": {"C": "left"}},
                  {"number": 3, "points": ["O3", "B"], "lengths": {"O3B": 120}},
                  {"number": 4, "points": ["A", "B"], "lengths": {"AB": 250}},
                  {"number": 5, "points": ["C", "D"], "lengths": {"CD": 200}},
                  {"number": 6, "points": ["O6", "D"], "lengths": {"O6D": 170}}],
        "assembly": {"B": "left", "D": "right"},
        "input": 2, "angle": 45,
        "mechanism": ["dof", "time_ratio"],
    },
    "watt-test-data": {
        "family": "six-bar",
        "frame": {"O2": (0, 0), "O3": (250, 0), "O6": (-220, 40)},
        "links": [{"number": 2, "points": ["O2", "A", "C"],
                   "lengths": {"O2A": 80, "O2C": 70, "AC": 110}, "sides": {"C": "left"}},
                  {"number": 4, "points": ["A", "B"], "lengths": {"AB": 200}},
                  {"number": 3, "points": ["O3", "B"], "lengths": {"O3B": 150}},
                  {"number": 5, "points": ["C", "D"], "lengths": {"CD": 180}},
                  {"number": 6, "points": ["O6", "D"], "lengths": {"O6D": 120}}],
        "assembly": {"B": "left", "D": "right"},
        "input": 2, "angle": 60,
        "mechanism": ["dof", "time_ratio"],
    },
    "stephenson": {
        "family": "six-bar",
        "frame": {"O2": (0, 0), "O4": (300, 0), "O6": (420, 180)},
        "links": [{"number": 2, "points": ["O2", "A"], "lengths": {"O2A": 100}},
                  {"number": 3, "points": ["A", "B", "C"],
                   "lengths": {"AB": 250, "AC": 170, "BC": 130}, "sides": {"C": "left"}},
                  {"number": 4, "points": ["O4", "B"], "lengths": {"O4B": 200}},
                  {"number": 5, "points": ["C", "D"], "lengths": {"CD": 160}},
                  {"number": 6, "points": ["O6", "D"], "lengths": {"O6D": 150}}],
        "assembly": {"B": "left", "D": "left"},
        "input": 2, "angle": 60,
        "mechanism": ["dof"],
    },
    "multiple-pin": {
        "family": "six-bar",
        "frame": {"O2": (0, 0), "O4": (230, 0), "O6": (270, 180)},
        "links": [{"number": 2, "points": ["O2", "A"], "lengths": {"O2A": 85}},
                  {"number": 3, "points": ["A", "P"], "lengths": {"AP": 130}},
                  {"number": 4, "points": ["O4", "P"], "lengths": {"O4P": 170}},
                  {"number": 5, "points": ["P", "Q"], "lengths": {"PQ": 170}},
                  {"number": 6, "points": ["O6", "Q"], "lengths": {"O6Q": 150}}],
        "assembly": {"P": "left", "Q": "right"},
        "input": 2, "angle": 30,
        "mechanism": ["dof", "time_ratio"],
    },
    "six-bar-slider": {
        "family": "six-bar",
        "frame": {"O2": (0, 0), "O4": (190, 0)},
        "links": [{"number": 2, "points": ["O2", "A"], "lengths": {"O2A": 76.2}},
                  {"number": 3, "points": ["A", "B"], "lengths": {"AB": 178}},
                  {"number": 4, "points": ["O4", "B", "C"],
                   "lengths": {"O4B": 110, "BC": 152, "O4C": 262},
                   "sum": {"O4C": ("O4B", "BC")}},     # C on O4B produced
                  {"number": 5, "points": ["C", "D"], "lengths": {"CD": 305}},
                  {"number": 6, "points": ["D"]}],
        "sliders": [{"link": 6, "point": "D", "on": 1, "through": (0, 25), "angle": 0}],
        "assembly": {"B": "left", "D": "forward"},
        "input": 2, "angle": 285,
        "mechanism": ["dof", "time_ratio", "stroke"],
    },
    "circular-cam": {
        "family": "contact",
        "frame": {"O2": (0, 0)},
        "links": [{"number": 2, "points": ["O2", "C"], "lengths": {"O2C": 25}},
                  {"number": 3, "points": ["F"]}],
        "sliders": [{"link": 3, "point": "F", "through": "O2", "angle": 90, "offset": 0}],
        "contacts": [{"circle": {"link": 2, "centre": "C", "radius": 40},
                      "face": {"link": 3, "through": "F", "angle": -90}, "side": "right"}],
        "input": 2, "angle": 30,
        "mechanism": ["dof"],
        "extra": ["A_cor_C", "V_C2/C3", "A_C3"],
    },
    "roller-cam": {
        "family": "contact",
        "frame": {"O2": (0, 0), "O3": (120, 40)},
        "links": [{"number": 2, "points": ["O2", "C"], "lengths": {"O2C": 20}},
                  {"number": 3, "points": ["O3", "R"], "lengths": {"O3R": 90}}],
        "contacts": [{"circle": {"link": 3, "centre": "R", "radius": 15},
                      "face": {"link": 2, "centre": "C", "radius": 50}, "side": "outside"}],
        "assembly": {"R": "left"},
        "input": 2, "angle": 40,
        "mechanism": ["dof"],
        "extra": ["A_cor_R", "V_R3/R2", "A_R2"],
    },
    "rolling-wheel": {
        "family": "contact",
        "frame": {"O2": (0, 60), "G": (0, 0)},
        "links": [{"number": 2, "points": ["O2", "A"], "lengths": {"O2A": 40}},
                  {"number": 3, "points": ["A", "B"], "lengths": {"AB": 150}},
                  {"number": 4, "points": ["B", "M"], "lengths": {"BM": 30}}],
        "contacts": [{"circle": {"link": 4, "centre": "B", "radius": 30},
                      "face": {"link": 1, "through": "G", "angle": 0}, "side": "left",
                      "rolling": True}],
        "assembly": {"B": "forward"},
        "input": 2, "angle": 70,
        "mechanism": ["dof"],
        "extra": [],
    },
    "curved-slot": {
        "family": "contact",
        "frame": {"O2": (0, 0), "O4": (100, 0)},
        "links": [{"number": 2, "points": ["O2", "A"], "lengths": {"O2A": 50}},
                  {"number": 4, "points": ["O4", "K"], "lengths": {"O4K": 80}}],
        "sliders": [{"kind": "pin", "link": 2, "point": "A", "on": 4, "centre": "K",
                     "radius": 110}],
        "assembly": {"K": "left"},
        "input": 2, "angle": 60,
        "mechanism": ["dof"],
        "extra": ["A_cor_A", "V_A2/A4", "A_A4"],
    },
}

_LENGTH_KEYS = ("lengths", "radius", "offset")


def _perturbed(c: _Case, x: float, sigma: float) -> float:
    return x * (1.0 + sigma * c.rng.gauss(0.0, 1.0)) if sigma else float(x)


def template(c: _Case, family: str) -> dict[str, Any]:
    """A textbook layout of ``family`` with its lengths and pivots shaken, flipped and scaled."""
    r = c.rng
    name = r.choice([k for k, t in _TEMPLATES.items() if t["family"] == family])
    t = _TEMPLATES[name]
    sigma = r.choice([0.0, 0.0, 0.01, 0.05, 0.2])
    spec = _spec(c, f"random {name}" + (f" (±{sigma:g})" if sigma else ""))
    spec["frame"] = {k: c.point((_perturbed(c, x, sigma), _perturbed(c, y, sigma)))
                     for k, (x, y) in t["frame"].items()}
    if r.random() < 0.03:
        a, b = r.sample(list(spec["frame"]), 2) if len(spec["frame"]) > 1 else ("O2", "O2")
        spec["frame"][b] = spec["frame"][a]                 # coincident frame points
    links = []
    for k in t["links"]:
        k = dict(k)
        if "lengths" in k:
            k["lengths"] = {n: c.length(_perturbed(c, v, sigma)) for n, v in k["lengths"].items()}
            for n, (p, q) in k.pop("sum", {}).items():
                k["lengths"][n] = k["lengths"][p] + k["lengths"][q]
            if r.random() < 0.02:
                k["lengths"][r.choice(list(k["lengths"]))] = 0.0
        if "sides" in k and r.random() < 0.3:
            k["sides"] = {p: r.choice(["left", "right"]) for p in k["sides"]}
        links.append(k)
    spec["links"] = links
    for many in ("sliders", "contacts"):
        if many in t:
            spec[many] = [_posed_joint(c, j, sigma) for j in t[many]]
    spec["input"] = c.drive(t["input"], [0.0, 90.0, 180.0, t["angle"]])
    assembly = {}
    for p, w in t.get("assembly", {}).items():
        pair = ("left", "right") if w in ("left", "right") else ("forward", "backward")
        if r.random() < 0.97:
            assembly[p] = w if r.random() < 0.6 else c.branch(pair, None)
    if assembly:
        spec["assembly"] = assembly
    if "contacts" in t and t["contacts"][0]["side"] in ("outside", "inside") and r.random() < 0.3:
        spec["contacts"][0]["side"] = "inside"
    pts = list(dict.fromkeys(p for k in t["links"] for p in k["points"]))
    moving = [k["number"] for k in t["links"]]
    pos = ["centres"] + [f"omega{n}" for n in moving] + [f"V_{p}" for p in pts]
    pos += [f"alpha{n}" for n in moving if n != t["input"]] + [f"A_{p}" for p in pts]
    pos += t.get("extra", [])
    spec["ask"] = c.ask(list(t["mechanism"]), pos, [0.0, 90.0, 180.0])
    return spec


def _posed_joint(c: _Case, j: dict[str, Any], sigma: float, *,
                 profile: bool = False) -> dict[str, Any]:
    """A template's slider or contact (or a contact's ``profile``), in this case's pose and
    size."""
    carrier = j.get("link", 1) if profile else j.get("on", 1)
    out: dict[str, Any] = {}
    for k, v in j.items():
        if k in ("radius", "offset"):
            out[k] = c.length(_perturbed(c, v, sigma))
        elif k == "through" and isinstance(v, tuple):
            out[k] = c.point(v)
        elif k == "angle":
            # A guide on the frame, or a face on it, turns with the pose; a face on a moving
            # link is given in that link's own frame.
            out[k] = c.angle(v, posed=carrier == 1)
        elif isinstance(v, dict):
            out[k] = _posed_joint(c, v, sigma, profile=True)
        else:
            out[k] = v
    return out


def six_bar(c: _Case) -> dict[str, Any]:
    """A Watt or Stephenson six-bar (or a six-bar with a slider), as the catalog writes them."""
    return template(c, "six-bar")


def contact(c: _Case) -> dict[str, Any]:
    """A cam on a flat-faced follower, a roller on a circular cam, a rolling wheel or a pin in a
    curved slot (the components method reaches no point across these, as the README says)."""
    c.unfit = ("components",)
    return template(c, "contact")


BUILDERS = {"four-bar": four_bar, "slider-crank": slider_crank, "slotted-lever": slotted_lever,
            "six-bar": six_bar, "contact": contact}


# ----- malformed on purpose --------------------------------------------------------------------
def _malform(r: random.Random, spec: dict[str, Any]) -> str:
    """The spec's file, broken in one of the ways a hand-written file is."""
    how = r.choice(["drop-table", "typo-key", "string-number", "out-of-range", "truncate",
                    "unknown-ask", "no-branch", "zero-length", "negative-length", "bad-unit",
                    "unknown-point", "control-char", "big-integer"])
    spec = json.loads(json.dumps(spec, default=lambda v: v.text))     # a deep copy
    link = r.choice(spec["links"])
    if how == "drop-table":
        spec.pop(r.choice(["frame", "input", "links"]), None)
    elif how == "typo-key":
        spec["input"]["omgea"] = spec["input"].pop("omega", 1.0)
    elif how == "string-number":
        spec["input"]["angle"] = str(spec["input"]["angle"])
    elif how == "out-of-range":
        value = r.choice([1e31, 1e-31, 1e300, -1e300, 5e-324, float("inf"), float("nan")])
        where = r.choice(["omega", "alpha", "length", "frame"])
        if where in ("omega", "alpha"):
            spec["input"][where] = value
        elif where == "length" and link.get("lengths"):
            link["lengths"][next(iter(link["lengths"]))] = value
        else:
            spec["frame"][next(iter(spec["frame"]))] = [value, 0.0]
    elif how == "truncate":
        text = to_toml(spec)
        return text[:r.randint(1, len(text) - 1)]
    elif how == "unknown-ask":
        spec.setdefault("ask", {"find": []})["find"].append(r.choice(["omgea4", "V_Z", "I99",
                                                                      "A_cor_O2", "stroke"]))
    elif how == "no-branch":
        spec.pop("assembly", None)
    elif how in ("zero-length", "negative-length") and link.get("lengths"):
        link["lengths"][next(iter(link["lengths"]))] = 0.0 if how == "zero-length" else -1.0
    elif how == "bad-unit":
        spec["units"] = {"length": r.choice(["km", "ft", "MM", ""])}
    elif how == "unknown-point" and link.get("lengths"):
        link["lengths"]["XY"] = 1.0
    elif how == "control-char":
        spec["name"] = "bad\u202ename\x07"
    elif how == "big-integer":
        spec["input"]["omega"] = Lit("1" + "0" * 300)
    return to_toml(spec)


def generate(rng: random.Random, family: str | None = None) -> tuple[str, str]:
    """One random case: ``(family, toml_text)``; ``family`` picks one, else any."""
    family = family or rng.choice(FAMILIES)
    c = _Case(rng)
    spec = BUILDERS[family](c)
    if rng.random() < MALFORMED:
        return family, _malform(rng, spec)
    return family, to_toml(spec)


# ----- hostile files ------------------------------------------------------------------------
FOUR_BAR = """\
name = "Four-bar crank-rocker"
description = "the bundled four-bar"

[units]
length = "mm"
angle = "deg"

[frame]
O2 = [0, 0]
O4 = [300, 0]

[[link]]
number = 2
name = "crank"
points = ["O2", "A"]
lengths = { O2A = 100 }

[[link]]
number = 3
name = "coupler"
points = ["A", "B"]
lengths = { AB = 250 }

[[link]]
number = 4
name = "rocker"
points = ["O4", "B"]
lengths = { O4B = 200 }

[input]
link = 2
angle = 60
omega = 10

[assembly]
B = "left"

[ask]
find = ["centres", "omega3", "omega4", "V_B", "A_B"]
"""
"""The bundled four-bar, the file every hostile one is made from."""


def edited(old: str, new: str, text: str = FOUR_BAR) -> str:
    """``text`` with its one ``old`` replaced by ``new``."""
    assert text.count(old) == 1, old
    return text.replace(old, new)


def _nested(depth: int, kind: str) -> str:
    if kind == "array":
        return "[" * depth + "1" + "]" * depth
    return "{ a = " * depth + "1" + " }" * depth


def _many_points(count: int) -> str:
    frame = "\n".join(f"P{i} = [{i}, 0]" for i in range(count))
    return edited("O4 = [300, 0]\n", f"O4 = [300, 0]\n{frame}\n")


HOSTILE: dict[str, dict[str, bytes]] = {
    "not-utf8": {
        "binary": bytes(range(256)) * 4,
        "utf16-bom": FOUR_BAR.encode("utf-16"),
        "latin1-byte": FOUR_BAR.replace("the bundled", "the caf\u00e9").encode("latin-1"),
    },
    "empty": {"empty": b"", "blank": b"\n\n   \n"},
    "not-toml": {"prose": b"A four-bar with a 100 mm crank.\n",
                 "json": b'{"frame": {"O2": [0, 0]}}\n',
                 "broken-table": edited("[input]", "[input").encode()},
    "deep-nesting": {
        "arrays-500": edited("O2A = 100", "O2A = " + _nested(500, "array")).encode(),
        "tables-500": edited("O2A = 100", "O2A = " + _nested(500, "table")).encode(),
        "dotted-500": (FOUR_BAR + "\n[" + ".".join(["t"] * 500) + "]\nx = 1\n").encode(),
    },
    "huge": {"comment": (FOUR_BAR + "#" + "x" * 1_000_100 + "\n").encode(),
             "description": edited('description = "the bundled four-bar"',
                                   'description = "' + "x" * 1_000_100 + '"').encode()},
    "too-many-points": {"frame-150": _many_points(150).encode()},
    "control-characters": {
        "name-bell": edited('name = "Four-bar crank-rocker"', 'name = "Four\\u0007bar"').encode(),
        "name-bidi": edited('name = "Four-bar crank-rocker"',
                            'name = "Four\\u202ebar"').encode(),
        "description-nul": edited('description = "the bundled four-bar"',
                                  'description = "the\\u0000four-bar"').encode(),
        "description-isolate": edited('description = "the bundled four-bar"',
                                      'description = "the\\u2067four-bar"').encode(),
        "link-name-bidi": edited('name = "crank"', 'name = "cr\\u202eank"').encode(),
        "point-name-bidi": edited('O4 = [300, 0]', '"O\\u202e4" = [300, 0]').encode(),
    },
    "unknown-keys": {
        "top-table": (FOUR_BAR + "\n[extras]\nx = 1\n").encode(),
        "input-key": edited("omega = 10", "omega = 10\nomgea = 3").encode(),
        "link-key": edited('name = "crank"', 'name = "crank"\nlenghts = { O2A = 1 }').encode(),
        "ask-key": edited('find = [', 'fnd = ["dof"]\nfind = [').encode(),
        "units-key": edited('length = "mm"', 'length = "mm"\ntime = "s"').encode(),
    },
    "wrong-types": {
        "string-length": edited("O2A = 100", 'O2A = "100 mm"').encode(),
        "string-angle": edited("angle = 60", 'angle = "60°"').encode(),
        "bool-omega": edited("omega = 10", "omega = true").encode(),
        "array-frame": ("frame = [[0, 0], [300, 0]]\n"
                        + edited("[frame]\nO2 = [0, 0]\nO4 = [300, 0]\n", "")).encode(),
        "table-points": edited('points = ["O2", "A"]', 'points = { first = "O2" }').encode(),
        "array-input": ("input = [2, 60, 10]\n"
                        + edited("[input]\nlink = 2\nangle = 60\nomega = 10\n", "")).encode(),
        "string-link-number": edited("number = 2", 'number = "2"').encode(),
    },
    "numbers-out-of-range": {
        "1e308-length": edited("O2A = 100", "O2A = 1e308").encode(),
        "1e-320-length": edited("O2A = 100", "O2A = 1e-320").encode(),
        "nan-angle": edited("angle = 60", "angle = nan").encode(),
        "inf-omega": edited("omega = 10", "omega = inf").encode(),
        "minus-inf-x": edited("O4 = [300, 0]", "O4 = [-inf, 0]").encode(),
        "300-digit-length": edited("O2A = 100", "O2A = 1" + "0" * 299).encode(),
        "300-digit-omega": edited("omega = 10", "omega = 1" + "0" * 299).encode(),
        "1e308-omega": edited("omega = 10", "omega = 1e308").encode(),
        "1e308-x": edited("O4 = [300, 0]", "O4 = [1e308, 0]").encode(),
    },
    "point-twice": {
        "frame-key": edited("O4 = [300, 0]", "O4 = [300, 0]\nO4 = [310, 0]").encode(),
        "link-points": edited('points = ["O2", "A"]', 'points = ["O2", "A", "A"]').encode(),
    },
    "link-twice": {"number-3": edited("number = 4", "number = 3").encode()},
    "missing-frame": {"no-frame": edited("[frame]\nO2 = [0, 0]\nO4 = [300, 0]\n", "").encode()},
    "input-on-frame": {"link-1": edited("link = 2\nangle", "link = 1\nangle").encode()},
}
"""Files no mechanism file should be, by class and variant: each must be refused in one line."""


# ----- running and judging a case ----------------------------------------------------------------
OUTCOMES = ("ok", "refused", "refused-unclear", "check-failed", "wrong", "other")


@dataclass
class Outcome:
    """What one case gave: its class, the line or traceback, and what failed its check."""

    outcome: str
    message: str = ""
    detail: str = ""
    failures: list[dict[str, Any]] = field(default_factory=list)


_NUMBER = re.compile(r"(?<![\w.])(\d+(?:,\d{3})*)(?:\.(\d+))?(?:[eE]([-+−]?\d+))?")
_NONFINITE = re.compile(r"(?i)(?<![a-z])[-+]?(nan|inf)(?![a-z])")


def unclear_numbers(message: str) -> list[str]:
    """The numbers in ``message`` a reader cannot take in: more than 6 significant figures
    (1.23456789, a 300-digit integer). An exponent is readable at any size (1e+31)."""
    bad = []
    for m in _NUMBER.finditer(message):
        digits = (m.group(1).replace(",", "") + (m.group(2) or "")).lstrip("0")
        if len(digits) > 6:
            bad.append(m.group(0))
    return bad


def point_names(text: str) -> set[str]:
    """The names of the frame's and links' points in a mechanism file (none if unreadable)."""
    try:
        data = tomllib.loads(text)
    except Exception:   # noqa: BLE001 - a malformed file names nothing
        return set()
    names = set(data.get("frame", {})) if isinstance(data.get("frame"), dict) else set()
    for k in data.get("link", []) if isinstance(data.get("link"), list) else []:
        if isinstance(k, dict) and isinstance(k.get("points"), list):
            names |= {p for p in k["points"] if isinstance(p, str)}
    return names


def classify_error(message: str, path: str, names: set[str] = frozenset(),
                   places: tuple[str, ...] = ()) -> tuple[str, str]:
    """Judge a refusal's line: ``("refused", "")`` if it locates the fault and its numbers are
    readable, else ``("refused-unclear", why)``.

    It locates the fault if it names the file as ``file:line`` (or ``file:`` alone, for a
    fault of the whole file: too large, too deeply nested), a link (``link 3``), a point of
    the mechanism by name, or a position (``θ2 = 90°``, ``t = 2 s``); or if it matches one
    of ``places``, patterns a chapter's file gives for what it names (``mass 2``, ``plane
    B``, ``cylinder 3``).
    """
    if "\n" in message.strip():
        return "other", "the message runs over several lines"
    where = re.search(re.escape(path) + r":(\d+|\s)", message) is not None
    where = where or re.search(r"\blinks? \d+", message) is not None
    where = where or re.search(r"θ\d+ = |\bt = ", message) is not None
    where = where or any(re.search(p, message) for p in places)
    # A point by its name, alone or in a quantity's (V_B, A_cor_A).
    where = where or any(re.search(rf"(?<![A-Za-z0-9′″']){re.escape(n)}(?![\w′″'])", message)
                         for n in names)
    bare = re.sub(re.escape(path) + r"(:\d+)*", "FILE", message)
    bare = bare.replace(Path(path).name, "FILE")
    # Text quoted from the file ('1.2879943258571858' for a number written as a string) is
    # the user's own, echoed so it can be found.
    bad = unclear_numbers(re.sub(r"'[^']*'|\"[^\"]*\"", "TEXT", bare))
    why = []
    if not where:
        why.append("names no file:line, link, point or position")
    if bad:
        why.append("prints unclear numbers: " + ", ".join(bad[:3]))
    return ("refused", "") if not why else ("refused-unclear", "; ".join(why))


def _nonfinite(x: Any, where: str = "") -> str | None:
    """The path of the first non-finite number in a results document, if any."""
    if isinstance(x, float) and not math.isfinite(x):
        return where or "(top)"
    if isinstance(x, dict):
        for k, v in x.items():
            hit = _nonfinite(v, f"{where}.{k}")
            if hit:
                return hit
    if isinstance(x, list):
        for i, v in enumerate(x):
            hit = _nonfinite(v, f"{where}[{i}]")
            if hit:
                return hit
    return None


def _failed(doc: dict[str, Any]) -> list[dict[str, Any]]:
    """Every quantity (or alternative method) of a results document that failed its check."""
    out = []

    def walk(quantities: dict[str, Any], position: str) -> None:
        for name, q in quantities.items():
            for method, qq in [(None, q), *q.get("by_method", {}).items()]:
                if not qq.get("passed", True):
                    out.append({"quantity": name, "position": position,
                                "method": method or qq.get("method"),
                                "rel_error": qq.get("rel_error"),
                                "tolerance": qq.get("tolerance"),
                                "conditioning": qq.get("conditioning")})
    walk(doc.get("quantities", {}), "mechanism")
    for p in doc.get("positions", []):
        walk(p.get("quantities", {}), p.get("position", "input angle"))
    return out


def linkage_oracle(solution, text: str) -> list[str]:
    """What a linkage prints as checked that the textbook's loop equations contradict (a
    four-bar's and a slider-crank's, in tests/closed_forms.py)."""
    return contradictions(solution)


def run_case(text: str | bytes, path: str | Path, *, render: bool = False,
             oracle=linkage_oracle, places: tuple[str, ...] = ()) -> Outcome:
    """Write ``text`` to ``path``, load and solve it through the Python API, and classify it.

    With ``render`` every file of the solution is made as text too, and an SVG or steps.md
    that prints nan or inf is an ``other``. ``oracle(solution, text)`` lists what a solution
    that passed its checks still gets wrong (an outcome ``wrong``: solved and passed, but a
    closed form disagrees; a linkage's by default, each chapter's generator gives its own);
    ``places`` are what a refusal may name besides (:func:`classify_error`).
    """
    import tarsim
    from tarsim.constructions.errors import CheckMismatch, TarsimError

    path = str(path)
    Path(path).write_bytes(text if isinstance(text, bytes) else text.encode("utf-8"))
    text = text if isinstance(text, str) else text.decode("utf-8", "replace")
    try:
        solution = tarsim.solve(tarsim.load(path))
        doc = solution.results
        passed = solution.passed
        files = solution.files() if render else {}
    except CheckMismatch as e:
        return Outcome("check-failed", str(e))
    except TarsimError as e:
        message = str(e)
        outcome, why = classify_error(message, path, point_names(text), places)
        return Outcome(outcome, message, why)
    except Exception as e:   # noqa: BLE001 - anything else breaks the contract
        return Outcome("other", f"{type(e).__name__}: {e}".splitlines()[0],
                       traceback.format_exc())
    bad = _nonfinite(doc)
    if bad:
        return Outcome("other", f"results{bad} is not finite")
    for name, body in files.items():
        if name.endswith((".svg", ".md")):
            hit = _NONFINITE.search(body)
            if hit:
                start = max(hit.start() - 60, 0)
                return Outcome("other", f"{name} prints {hit.group(0)!r}",
                               body[start:hit.end() + 60])
    failures = _failed(doc)
    if not passed or failures:
        names = ", ".join(sorted({f["quantity"] for f in failures})) or "(passed is False)"
        return Outcome("check-failed", f"failed its check: {names}", failures=failures)
    try:
        wrongs = oracle(solution, text) if oracle else []
    except Exception as e:   # noqa: BLE001 - the oracle's own fault, reported, not raised
        return Outcome("other", f"the oracle failed: {type(e).__name__}: {e}".splitlines()[0],
                       traceback.format_exc())
    if wrongs:
        return Outcome("wrong", wrongs[0], "\n".join(wrongs))
    return Outcome("ok")
