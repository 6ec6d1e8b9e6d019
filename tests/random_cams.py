"""Random cam exercises as the textbooks pose them, degenerate and malformed ones included,
each held to an oracle of its own.

The contract is tests/random_mechanisms.py's: every file either solves to finite numbers
that pass their checks, or is refused with one ``TarsimError`` line naming the file:line,
a segment or a cam angle θ. ``generate(rng)`` makes one case as TOML text and ``run_case``
solves and judges it. A solved cam is held besides to :func:`oracle`, which reads the file
itself and finds the greatest pressure angle, the pitch curve's least radius of curvature
(a flat face's profile's), the face's run and whether the follower undercuts, by a dense
grid over each piece of each law zoomed in on its best points, in formulas written here: an
answer that passes tarsim's own checks and is still wrong is a ``wrong`` case.

A cam refused for undercutting is held to the oracle too (it must undercut), and solved
again as ``--allow-undercut`` solves it, whose numbers must be the oracle's as well.

Run ``python tests/random_cams.py --cases 3000 --seed 1`` for the counts by outcome.
"""

from __future__ import annotations

import math
import random
import sys
import tomllib
import traceback
from pathlib import Path
from typing import Any

import numpy as np

from tarsim.exercises.file_numbers import arithmetic

sys.path.insert(0, str(Path(__file__).resolve().parent))

from random_mechanisms import _NONFINITE, Lit, Outcome, _nonfinite  # noqa: E402
from random_mechanisms import _val as _value  # noqa: E402
from random_mechanisms import run_case as _run_case  # noqa: E402

__all__ = ["FAMILIES", "generate", "oracle", "Extremes", "extremes", "places", "run_case"]

FAMILIES = ("knife-edge", "roller", "flat-faced", "offset", "oscillating")
"""A radial knife edge, a radial roller, a flat face, an offset knife edge or roller, and an
arm swinging a roller or a knife edge on a pivot."""

LAWS = ("uniform velocity", "modified uniform velocity", "simple harmonic", "parabolic",
        "cycloidal")

MALFORMED = 0.07
"""The share of cases broken on purpose after they are made."""

_METRE = {"mm": 1e-3, "cm": 1e-2, "m": 1.0, "in": 0.0254}


# ----- TOML text ---------------------------------------------------------------------------
def to_toml(spec: dict[str, Any]) -> str:
    """The cam file a spec describes: name, [units], [cam], [follower], [ask], [[segment]]."""
    out = [f"name = {_value(spec['name'])}"] if "name" in spec else []
    for table in ("units", "cam", "follower", "ask"):
        if table in spec:
            out += ["", f"[{table}]"] + [f"{k} = {_value(v)}" for k, v in spec[table].items()]
    for t in spec.get("segment", []):
        out += ["", "[[segment]]"] + [f"{k} = {_value(v)}" for k, v in t.items()]
    return "\n".join(out) + "\n"


# ----- a cam as a textbook poses it --------------------------------------------------------
def _angles(r: random.Random, n: int) -> list[float]:
    """``n`` segment angles adding to 360°: the textbook's round ones, odd ones, now and
    then a very short one, or one that starts or ends a hair off a ¼° sample."""
    roll = r.random()
    if roll < 0.4:
        parts = [r.choice([30, 45, 60, 90, 120, 150, 180]) for _ in range(n - 1)]
    elif roll < 0.75:
        parts = [round(r.uniform(5, 200), r.choice([0, 1, 3])) for _ in range(n - 1)]
    else:
        parts = [r.choice([round(r.uniform(0.05, 3), 3), 10 ** r.uniform(-4, 0),
                           0.25 * r.randint(1, 400) + r.choice([1e-7, -1e-7, 1e-4]),
                           round(r.uniform(5, 120), 2)]) for _ in range(n - 1)]
    total = sum(parts)
    if total >= 359.0:
        parts = [p * 300.0 / total for p in parts]
    parts = [float(p) for p in parts]
    return parts + [360.0 - sum(parts)]


def _segments(r: random.Random, lift: float, swing: bool) -> list[dict[str, Any]]:
    """Rises, dwells and returns that come back to the base circle."""
    n = r.choice([2, 3, 4, 4, 4, 5, 6])
    kinds = ["rise"] + [r.choice(["rise", "dwell", "return", "dwell"]) for _ in range(n - 2)] \
        + ["return"]
    if n > 2 and r.random() < 0.3:                 # at rest first, as many books begin
        kinds = ["dwell", "rise"] + kinds[2:]
    out, height = [], 0.0
    for kind, angle in zip(kinds, _angles(r, n)):
        t: dict[str, Any] = {"kind": kind, "angle": angle}
        if kind != "dwell":
            law = r.choice(LAWS)
            t["law"] = law
            if kind == "rise":
                h = lift * r.choice([1.0, 0.5, r.uniform(0.01, 1), 10 ** r.uniform(-6, 0)])
                height += h
            else:
                h = height * r.choice([1.0, 0.5, r.uniform(0, 1)])
                height -= h
            t["lift"] = h
            if law == "modified uniform velocity":
                m, parts = r.choice([(1, 4), (2, 8), (3, 12), (1, 2), (2, 6), (4, 8)])
                t["divisions"], t["blend"] = parts, m / parts
            elif r.random() < 0.5:
                t["divisions"] = r.choice([2, 4, 6, 8, 12, 18, 24]) if law == "parabolic" \
                    else r.randint(2, 24)
        out.append(t)
    # The last return takes the follower down to the base circle.
    last = next(t for t in reversed(out) if t["kind"] == "return")
    last["lift"] = last["lift"] + height
    return out


def _units(r: random.Random) -> tuple[dict[str, str], str]:
    units: dict[str, str] = {}
    if r.random() < 0.85:
        units["length"] = r.choice(["mm", "mm", "cm", "m", "in"])
    if r.random() < 0.8:
        units["speed"] = r.choice(["rpm", "rad/s"])
    return units, units.get("length", "mm")


def cam(r: random.Random, family: str) -> dict[str, Any]:
    """A cam of ``family`` at a size from a textbook's to a tiny or a huge one."""
    units, unit = _units(r)
    per = {"mm": 1000.0, "cm": 100.0, "m": 1.0, "in": 39.37}[unit]
    scale = per * r.choice([0.04, 0.04, 0.05, 0.1, 10 ** r.uniform(-5, 2)])
    base = scale * r.choice([1.0, 1.0, r.uniform(0.2, 3)])
    speed = r.choice([100, 240, 300, 1000, round(r.uniform(1, 1e4), 1), 1e-3])
    spec: dict[str, Any] = {"name": f"random cam ({family})", "units": units,
                            "cam": {"base_radius": base, "speed": speed,
                                    "sense": r.choice(["cw", "ccw"])}}
    follower: dict[str, Any] = {"kind": "knife-edge"}
    swing = family == "oscillating"
    if family in ("roller", "flat-faced"):
        follower = {"kind": family}
    elif family == "offset":
        follower = {"kind": r.choice(["knife-edge", "roller"])}
    elif swing:
        follower = {"kind": r.choice(["roller", "roller", "knife-edge"]), "motion": "oscillating"}
    if follower["kind"] == "roller":
        follower["radius"] = base * r.choice([0.25, 0.5, r.uniform(0.05, 1.5)])
    prime = base + follower.get("radius", 0.0)
    if family == "offset":
        follower["offset"] = prime * r.choice([0.25, -0.3, r.uniform(-0.99, 0.99)])
    if swing:
        d = prime * r.uniform(1.2, 3.0)
        at = r.uniform(0, 2 * math.pi)
        pivot = (d * math.cos(at), d * math.sin(at))
        rest = r.uniform(0.3, 2.8)                 # where on the prime circle the arm rests
        tip = (prime * math.cos(at + rest), prime * math.sin(at + rest))
        follower["pivot"] = [pivot[0], pivot[1]]
        follower["arm"] = math.dist(pivot, tip)
    spec["follower"] = follower
    if r.random() < 0.4:
        spec["ask"] = {"jerk": True}
    lift = r.choice([20.0, 30.0, 5.0, r.uniform(2, 45)]) if swing else \
        scale * r.choice([0.5, 1.0, r.uniform(0.05, 3), 10 ** r.uniform(-4, 2)])
    spec["segment"] = _segments(r, lift, swing)
    return spec


def _malform(r: random.Random, spec: dict[str, Any]) -> str:
    """The spec's file, broken one way on purpose."""
    how = r.choice(["short", "negative-lift", "unknown-law", "odd-parabolic", "bad-blend",
                    "unbalanced", "below-base", "no-cam", "no-radius", "offset-clear",
                    "arm-short", "string-number", "nan", "inf", "zero-base", "huge-base",
                    "typo-key", "no-segments", "truncate", "flat-oscillating", "bad-kind",
                    "divisions-bool", "blend-elsewhere", "ask-other"])
    segs = spec["segment"]
    moving = [t for t in segs if t["kind"] != "dwell"]
    t = r.choice(moving)
    if how == "short":
        segs[0]["angle"] = segs[0]["angle"] - r.choice([1.0, 1e-6])
    elif how == "negative-lift":
        t["lift"] = -t["lift"]
    elif how == "unknown-law":
        t["law"] = r.choice(["cubic", "", "polynomial", "sine"])   # "SHM", "Cycloidal" are read
    elif how == "odd-parabolic":
        t["law"], t["divisions"] = "parabolic", r.choice([3, 5, 7])
        t.pop("blend", None)
    elif how == "bad-blend":
        t["law"], t["divisions"], t["blend"] = "modified uniform velocity", 8, \
            r.choice([0.3, 0.0, 0.75, -0.25])
    elif how == "unbalanced":
        t["lift"] = t["lift"] * 1.5 + 1.0
    elif how == "below-base":
        segs.insert(0, {"kind": "return", "angle": 0.0, "lift": 1.0, "law": "cycloidal"})
        segs[1]["angle"] -= 10.0
        segs[0]["angle"] = 10.0
    elif how == "no-cam":
        spec.pop("cam")
    elif how == "no-radius":
        spec["follower"] = {"kind": "roller"}
    elif how == "offset-clear":
        spec["follower"]["offset"] = spec["cam"]["base_radius"] * 5
    elif how == "arm-short" and "arm" in spec["follower"]:
        spec["follower"]["arm"] = spec["follower"]["arm"] * 1e-3
    elif how in ("string-number", "nan", "inf"):
        table = r.choice([spec["cam"], t])
        key = r.choice([k for k in table if k in ("base_radius", "speed", "angle", "lift")])
        table[key] = {"string-number": "12", "nan": float("nan"), "inf": float("inf")}[how]
    elif how == "zero-base":
        spec["cam"]["base_radius"] = r.choice([0, 0.0, -5.0])
    elif how == "huge-base":
        spec["cam"]["base_radius"] = r.choice([1e6, 1e300, Lit("1" + "0" * 300)])
    elif how == "typo-key":
        spec["cam"]["sped"] = spec["cam"].pop("speed")
    elif how == "no-segments":
        spec.pop("segment")
    elif how == "truncate":
        text = to_toml(spec)
        return text[:r.randint(1, len(text) - 1)]
    elif how == "flat-oscillating":
        spec["follower"] = {"kind": "flat-faced", "motion": "oscillating", "pivot": [70, 0],
                            "arm": 50}
    elif how == "bad-kind":
        t["kind"] = r.choice(["fall", "Rise", ""])
    elif how == "divisions-bool":
        t["divisions"] = r.choice([True, 1, 25, 6.5])
    elif how == "blend-elsewhere":
        t["law"], t["blend"] = "cycloidal", 0.25
    elif how == "ask-other":
        spec["ask"] = {"find": ["V_B"]}
    return to_toml(spec)


def generate(rng: random.Random, family: str | None = None) -> tuple[str, str]:
    """One random case: ``(family, toml_text)``; ``family`` picks one, else any."""
    family = family or rng.choice(FAMILIES)
    spec = cam(rng, family)
    if rng.random() < MALFORMED:
        return family, _malform(rng, spec)
    return family, to_toml(spec)


# ----- the oracle ----------------------------------------------------------------------------
def _law(law: str, piece: int, u, h: float, beta: float, blend: float):
    """A rise's y, y′, y″ by ``law``'s formula on its ``piece`` (numpy arrays in u = θ/β)."""
    one, zero = np.ones_like(u), np.zeros_like(u)
    if law == "uniform velocity":
        return h * u, h / beta * one, zero
    if law == "simple harmonic":
        return (h / 2 * (1 - np.cos(np.pi * u)), h * np.pi / (2 * beta) * np.sin(np.pi * u),
                h * np.pi ** 2 / (2 * beta ** 2) * np.cos(np.pi * u))
    if law == "cycloidal":
        w = 2 * np.pi * u
        return (h * (u - np.sin(w) / (2 * np.pi)), h / beta * (1 - np.cos(w)),
                2 * np.pi * h / beta ** 2 * np.sin(w))
    if law == "parabolic":
        if piece == 0:
            return 2 * h * u * u, 4 * h * u / beta, 4 * h / beta ** 2 * one
        return h - 2 * h * (1 - u) ** 2, 4 * h * (1 - u) / beta, -4 * h / beta ** 2 * one
    c = h / (blend * (1 - blend))                    # modified uniform velocity
    if piece == 0:
        return c * u * u / 2, c * u / beta, c / beta ** 2 * one
    if piece == 1:
        return h * (u - blend / 2) / (1 - blend), h / ((1 - blend) * beta) * one, zero
    return h - c * (1 - u) ** 2 / 2, c * (1 - u) / beta, -c / beta ** 2 * one


def _pieces(law: str, blend: float) -> list[tuple[int, float, float]]:
    if law == "parabolic":
        return [(0, 0.0, 0.5), (1, 0.5, 1.0)]
    if law == "modified uniform velocity":
        return [(0, 0.0, blend), (1, blend, 1 - blend), (2, 1 - blend, 1.0)] if blend < 0.5 \
            else [(0, 0.0, 0.5), (2, 0.5, 1.0)]
    return [(0, 0.0, 1.0)]


class Extremes:
    """What the oracle finds round a cam: the greatest pressure angle (rad), the greatest
    convex curvature of the pitch curve (1/m), a flat face's least radius and the face's
    run each side (m)."""

    def __init__(self) -> None:
        self.pressure = 0.0
        self.curvature = -math.inf
        self.flat_rho = math.inf
        self.run = (math.inf, -math.inf)


def _read(text: str) -> dict[str, Any]:
    data = tomllib.loads(text)
    for table in [data.get("cam", {}), data.get("follower", {}), *data.get("segment", [])]:
        for k, v in table.items():        # "12" is the number tarsim reads it as
            if isinstance(v, str) and arithmetic(v) is not None:
                table[k] = float(arithmetic(v))
    metre = _METRE[data.get("units", {}).get("length", "mm")]
    c, f = data["cam"], data.get("follower", {})
    sigma = 1.0 if c.get("sense", "ccw") == "ccw" else -1.0
    swing = f.get("motion") == "oscillating"
    segs = []
    for t in data["segment"]:
        lift = t.get("lift", 0.0)
        segs.append((t["kind"], math.radians(t["angle"]),
                     math.radians(lift) if swing else lift * metre,
                     t.get("law", "simple harmonic"), t.get("blend", 0.25)))
    return {"base": c["base_radius"] * metre, "sigma": sigma, "kind": f.get("kind", "knife-edge"),
            "radius": f.get("radius", 0.0) * metre, "offset": f.get("offset", 0.0) * metre,
            "pivot": [v * metre for v in f["pivot"]] if swing else None,
            "arm": f.get("arm", 0.0) * metre, "segments": segs}


def _still(cam: dict[str, Any], y, y1, y2):
    """The trace point Z, Z′, Z″ (complex) and its way of moving u, in the still frame."""
    prime = cam["base"] + (cam["radius"] if cam["kind"] == "roller" else 0.0)
    if cam["pivot"] is None:
        e = cam["offset"]
        s0 = math.sqrt(prime ** 2 - e ** 2)
        return e + 1j * (s0 + y), 1j * y1, 1j * y2, 1j * np.ones_like(y)
    a = complex(*cam["pivot"])
    arm = cam["arm"]
    # The arm rests where its circle cuts the prime circle, counter-clockwise of O → A; it
    # swings (kappa) the way that carries the roller away from the cam.
    d = abs(a)
    along = (d * d + prime * prime - arm * arm) / (2 * d)
    rest = (a / d) * complex(along, math.sqrt(max(prime ** 2 - along ** 2, 0.0)))
    psi0 = np.angle(rest - a)
    kappa = 1.0 if (rest * np.conj(1j * (rest - a))).real > 0 else -1.0
    psi = psi0 + kappa * y
    e = np.exp(1j * psi)
    return (a + arm * e, arm * kappa * y1 * 1j * e,
            arm * (kappa * y2 * 1j * e - y1 * y1 * e), kappa * 1j * e)


def _evaluate(cam: dict[str, Any], piece, u):
    """Pressure angle, convex curvature, flat ρ and face run at the fractions ``u`` of one
    piece's segment (numpy). None depends on how far the cam has turned, only on the
    follower's motion there: so they are read by the fraction, which a tiny segment's end
    keeps exact where a cam angle would round it."""
    kind, start, height, h, beta, law, blend, index = piece
    if kind == "dwell":
        y, y1, y2 = height + 0 * u, 0 * u, 0 * u
    else:
        y, y1, y2 = _law(law, index, u, h, beta, blend)
        if kind == "return":
            y, y1, y2 = height - y, -y1, -y2
        else:
            y = height + y
    sigma = cam["sigma"]
    if cam["kind"] == "flat-faced":
        return None, None, cam["base"] + y + y2, sigma * y1
    z, z1, z2, way = _still(cam, y, y1, y2)
    # Held in the cam's frame the point is e^{−iσθ} Z: its velocity and acceleration there
    # turned back to the still frame.
    w1 = z1 - 1j * sigma * z
    w2 = z2 - 2j * sigma * z1 - z
    turning = (np.conj(w1) * w2).imag / np.abs(w1) ** 3
    along = (np.conj(w1) * way).real
    across = (np.conj(w1) * way).imag
    return np.arctan2(np.abs(along), np.abs(across)), -sigma * turning, None, None


def _pieces_of(cam: dict[str, Any]) -> list[tuple]:
    out, start, height = [], 0.0, 0.0
    for kind, beta, h, law, blend in cam["segments"]:
        if kind == "dwell":
            out.append(("dwell", start, height, 0.0, beta, "", 0.0, 0, 0.0, 1.0))
        else:
            top = height if kind == "rise" else height
            for index, a, b in _pieces(law, blend):
                out.append((kind, start, top, h, beta, law, blend, index, a, b))
        start += beta
        height += h if kind == "rise" else -h if kind == "return" else 0.0
    return out


_GRID = np.concatenate([np.linspace(0.0, 1.0, 2001), 4.0 ** -np.arange(1, 27),
                        1 - 4.0 ** -np.arange(1, 27)])
_GRID.sort()


def _best(f, a: float, b: float) -> float:
    """The greatest of ``f`` over a–b: the grid's, then around its best few points a grid
    2000 times finer, three times over."""
    ts = a + (b - a) * _GRID
    vs = f(ts)
    top = []
    for i in np.argsort(vs)[-4:]:
        lo, hi = ts[max(i - 1, 0)], ts[min(i + 1, len(ts) - 1)]
        v = vs[i]
        for _ in range(3):
            fine = np.linspace(lo, hi, 2001)
            fv = f(fine)
            j = int(np.argmax(fv))
            v = max(v, fv[j])
            lo, hi = fine[max(j - 1, 0)], fine[min(j + 1, 2000)]
        top.append(v)
    return float(max(top))


def extremes(text: str) -> Extremes:
    """The oracle's extremes of the cam file ``text`` (see the module's docstring)."""
    cam = _read(text)
    out = Extremes()
    for p in _pieces_of(cam):
        kind, start, height, h, beta, law, blend, index, a, b = p
        piece = p[:8]

        def part(which, sign=1.0, piece=piece):
            return lambda ts: sign * _evaluate(cam, piece, ts)[which]
        lo, hi = a, b
        if cam["kind"] == "flat-faced":
            out.flat_rho = min(out.flat_rho, -_best(part(2, -1.0), lo, hi))
            out.run = (min(out.run[0], -_best(part(3, -1.0), lo, hi)),
                       max(out.run[1], _best(part(3), lo, hi)))
        else:
            out.pressure = max(out.pressure, _best(part(0), lo, hi))
            out.curvature = max(out.curvature, _best(part(1), lo, hi))
    return out


AGREE = 1e-9
"""How near (relative) tarsim's extremes must come to the oracle's. Both evaluate closed forms
in doubles, to a few roundings amplified by the pitch curve's own conditioning (its speed
|Z′ − iσZ| small beside the terms it is made of); the oracle's zoomed grid finds a maximum's
place to 1e-12 of its piece, its value to that squared. 1e-9 leaves room for the first and
none for a value read off the wrong sample."""


def _near(got: float, want: float, scale: float) -> bool:
    return abs(got - want) <= AGREE * max(abs(want), scale)


def undercut_by(text: str, ext: Extremes) -> bool | None:
    """Whether the oracle finds the follower undercutting (None: too near to tell)."""
    cam = _read(text)
    if cam["kind"] == "roller":
        margin = ext.curvature * cam["radius"] - 1.0
    elif cam["kind"] == "flat-faced":
        margin = -ext.flat_rho / max(cam["base"], 1e-300)
    else:
        return False
    return None if abs(margin) <= AGREE else margin > 0


def oracle(solution, text: str) -> list[str]:
    """What a solved cam gets wrong by the oracle's own reading of its file."""
    q = solution.results["quantities"]
    ext = extremes(text)
    cam = _read(text)
    wrong = []
    if cam["kind"] == "flat-faced":
        size = cam["base"] + max((s[2] for s in cam["segments"]), default=0.0)
        if not _near(q["rho_min"]["value"], ext.flat_rho, size):
            wrong.append(f"rho_min = {q['rho_min']['value']:.10g} m, the oracle's "
                         f"{ext.flat_rho:.10g} m")
        width = ext.run[1] - ext.run[0]
        if not _near(q["face_width"]["value"], width, size):
            wrong.append(f"face_width = {q['face_width']['value']:.10g} m, the oracle's "
                         f"{width:.10g} m")
    else:
        got = q["pressure_angle_max"]["value"]
        if not _near(got, ext.pressure, 1e-6):
            wrong.append(f"pressure_angle_max = {math.degrees(got):.10g}°, the oracle's "
                         f"{math.degrees(ext.pressure):.10g}°")
        rho = q["rho_min"]["value"]
        if not _near(1.0 / rho, ext.curvature, 0.0):
            wrong.append(f"rho_min = {rho:.10g} m, the oracle's {1 / ext.curvature:.10g} m")
    under = undercut_by(text, ext)
    if under is not None and under != q["undercut"]["value"]:
        wrong.append(f"undercut is {q['undercut']['value']}, the oracle finds {under}")
    return wrong


# ----- running a case ------------------------------------------------------------------------
PLACES = (r"\bsegments? \d+", r"θ = ", r"\bstation \d+")
"""What a cam's refusal may name to say where its fault is."""


def places(text: str = "") -> tuple[str, ...]:
    """What a refusal may name besides the file:line: a segment, a cam angle, a station."""
    return PLACES


def run_case(text: str | bytes, path: str | Path, *, render: bool = False) -> Outcome:
    """Solve ``text`` through the API (random_mechanisms.run_case) with this file's oracle; a
    cam refused for undercutting must undercut by the oracle, and solved as
    ``--allow-undercut`` solves it must give the oracle's numbers."""
    got = _run_case(text, path, render=render, oracle=oracle, places=PLACES)
    words = text if isinstance(text, str) else text.decode("utf-8", "replace")
    if got.outcome != "refused" or not ("undercuts the cam" in got.message
                                        or "concave profile" in got.message):
        return got
    try:
        from tarsim.exercises.cams.cam_solution import solve_cam
        from tarsim.exercises.catalog import load

        if undercut_by(words, extremes(words)) is False:
            return Outcome("wrong", f"refused as undercut, the oracle finds none: "
                           f"{got.message}")
        solution = solve_cam(load(str(path)), allow_undercut=True)
        doc = solution.results
        bad = _nonfinite(doc)
        if bad:
            return Outcome("other", f"--allow-undercut: results{bad} is not finite")
        files = solution.files() if render else {}
        for name, body in files.items():
            if name.endswith((".svg", ".md")) and _NONFINITE.search(body):
                return Outcome("other", f"--allow-undercut: {name} prints nan or inf")
        if not solution.passed:
            return Outcome("check-failed", f"--allow-undercut: {solution.failures[:3]}")
        wrongs = oracle(solution, words)
        if not doc["quantities"]["undercut"]["spans"]:
            wrongs.append("--allow-undercut gives no undercut span")
        if wrongs:
            return Outcome("wrong", "--allow-undercut: " + wrongs[0], "\n".join(wrongs))
    except Exception as e:   # noqa: BLE001 - anything else breaks the contract
        return Outcome("other", f"--allow-undercut: {type(e).__name__}: {e}".splitlines()[0],
                       traceback.format_exc())
    return got


if __name__ == "__main__":
    from random_rotors import run_many

    sys.exit(run_many(generate, run_case, FAMILIES, "cams"))
