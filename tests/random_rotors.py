"""Random rotors and reciprocating engines, degenerate and malformed ones included, each with
an oracle of its own.

The contract is tests/random_mechanisms.py's: every file either solves to finite numbers that
pass their checks, or is refused with one ``TarsimError`` line naming the file:line, a mass,
a plane or a cylinder. ``generate(rng)`` makes one case as TOML text, ``run_case`` solves it
and judges it, and, unlike a linkage, a solved case is held besides to an oracle that reads
the file itself (:func:`oracle`), so an answer that is wrong but passes tarsim's own check is
caught:

- a rotor: the balancing products results.json gives, added to the masses, must leave no
  force and, with two planes, no couple, Σ m r = 0 and Σ m r l = 0 summed here as complex
  numbers; a plane said to need no mass must need none, and the printed masses and angles
  must be the products' to their printed digits;
- an engine: the primary and secondary forces and couples from the closed forms, m·ω²·r·cos θ
  and m·ω²·r·cos 2θ / n for one cylinder, |Σ e^{iθ}| and |Σ aᵢ·e^{iθ}| for cylinders in line.

Run ``python tests/random_rotors.py --cases 3000 --seed 1`` for the counts by outcome.
"""

from __future__ import annotations

import cmath
import math
import random
import re
import sys
import tomllib
from pathlib import Path
from typing import Any

sys.path.insert(0, str(Path(__file__).resolve().parent))

from random_mechanisms import Lit, Outcome, run_case as _run_case   # noqa: E402

__all__ = ["FAMILIES", "generate", "oracle", "places", "run_case"]

FAMILIES = ("static-rotor", "two-plane-rotor", "open-rotor", "single-cylinder",
            "inline-engine")
"""A rotor balanced in one plane or in two, or by its own masses, some of their data
unknown; an engine of one cylinder, or of several in line with the cranks of a firing
order."""

MALFORMED = 0.08
"""The share of cases broken on purpose after they are made."""

_METRE = {"mm": 1e-3, "cm": 1e-2, "m": 1.0, "in": 0.0254}
_RATE = {"rpm": math.pi / 30, "rad/s": 1.0}

FIRING = {2: [(1, 2)], 3: [(1, 3, 2), (1, 2, 3)], 4: [(1, 3, 4, 2), (1, 2, 4, 3)],
          5: [(1, 2, 4, 5, 3)], 6: [(1, 5, 3, 6, 2, 4), (1, 4, 2, 6, 3, 5)],
          8: [(1, 6, 2, 5, 8, 3, 7, 4), (1, 3, 6, 8, 4, 2, 7, 5)]}
"""Firing orders of in-line engines, as the textbooks give them."""


# ----- TOML text ---------------------------------------------------------------------------
def _val(v: Any) -> str:
    if isinstance(v, Lit):
        return v.text
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, float):
        return "nan" if math.isnan(v) else ("inf" if v > 0 else "-inf") if math.isinf(v) \
            else repr(v)
    if isinstance(v, str):
        return '"' + v.replace("\\", "\\\\").replace('"', '\\"') + '"'
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(_val(x) for x in v) + "]"
    return str(v)


def to_toml(spec: dict[str, Any]) -> str:
    """The balancing file a spec describes: name, [units], [rotor] or [engine], then each
    [[mass]], [[balance]] and [[cylinder]] in order."""
    out = [f"name = {_val(spec['name'])}"] if "name" in spec else []
    for table in ("units", "rotor", "engine"):
        if table in spec:
            out += ["", f"[{table}]"] + [f"{k} = {_val(v)}" for k, v in spec[table].items()]
    for many in ("mass", "balance", "cylinder"):
        for t in spec.get(many, []):
            out += ["", f"[[{many}]]"] + [f"{k} = {_val(v)}" for k, v in t.items()]
    return "\n".join(out) + "\n"


# ----- rotors --------------------------------------------------------------------------------
def _units(r: random.Random) -> dict[str, str]:
    units = {}
    if r.random() < 0.9:
        units["length"] = r.choice(["mm", "mm", "cm", "m", "in"])
    if r.random() < 0.8:
        units["speed"] = r.choice(["rpm", "rad/s"])
    return units


def _angle(r: random.Random) -> float:
    """A textbook angle (a multiple of 15°), a plain one, or one past a turn or negative."""
    roll = r.random()
    if roll < 0.6:
        return float(15 * r.randint(0, 23))
    if roll < 0.9:
        return round(r.uniform(0, 360), 2)
    return r.choice([360.0, 720.0, -90.0, -45.0, 1e5 + 30, 359.999999])


def _size(r: random.Random, unit: str) -> float:
    """A length scale in the file's unit: a textbook rotor's (metres of it), or a tiny or a
    huge one within what a file may give."""
    per = {"mm": 1000.0, "cm": 100.0, "m": 1.0, "in": 39.37}[unit]
    return per * r.choice([1.0, 1.0, 1.0, 0.01, 100.0, 10 ** r.uniform(-2, 2)])


def rotor(r: random.Random, planes: int) -> dict[str, Any]:
    """A rotor of 1–6 masses and ``planes`` balancing planes, in a textbook layout or one of
    the degenerate ones: every mass in one balancing plane, masses that balance already
    (a symmetric star, opposite pairs, or two found to cancel the rest), masses in one
    axial plane, a mass in a balancing plane, the planes given B before A, or close
    together."""
    units = _units(r)
    unit = units.get("length", "m")
    scale = _size(r, unit)
    kind = r.choice(["textbook"] * 6 + ["all-in-A", "all-in-B", "star", "pairs", "cancelled",
                                        "axial", "mass-in-plane", "reversed", "close",
                                        "far", "one-mass"])
    n = 1 if kind == "one-mass" else r.randint(2, 6)
    span = scale * r.choice([1.0, 0.5, 2.0])
    masses = []
    for i in range(n):
        masses.append({"name": str(i + 1), "mass": round(r.choice([r.uniform(0.5, 50),
                                                                    r.uniform(1, 500)]), 2),
                       "radius": round(r.uniform(0.02, 0.3) * scale, 6), "angle": _angle(r),
                       "plane": round(r.uniform(0.1, 0.9) * span, 6)})
    a, b = 0.0, round(span, 6)
    if kind == "star":                  # equal m·r at equal angles: balanced in force
        for i, m in enumerate(masses):
            m.update(mass=masses[0]["mass"], radius=masses[0]["radius"],
                     angle=masses[0]["angle"] + 360.0 * i / n)
        if r.random() < 0.5:
            for m in masses:
                m["plane"] = masses[0]["plane"]
    elif kind == "pairs":               # opposite equal masses, each pair in one plane
        for i in range(0, n - 1, 2):
            masses[i + 1].update(mass=masses[i]["mass"], radius=masses[i]["radius"],
                                 angle=masses[i]["angle"] + 180.0, plane=masses[i]["plane"])
    elif kind == "cancelled" and n >= 3:
        _cancel(masses, r)
    elif kind == "axial":               # one axial plane: θ or θ + 180°
        for m in masses[1:]:
            m["angle"] = masses[0]["angle"] + r.choice([0.0, 180.0])
    elif kind in ("all-in-A", "all-in-B"):
        for m in masses:
            m["plane"] = a if kind == "all-in-A" else b
    elif kind == "mass-in-plane":
        r.choice(masses)["plane"] = r.choice([a, b])
    elif kind == "close":
        b = round(a + span * r.choice([1e-3, 1e-6, 1e-9]), 12)
    elif kind == "far":
        masses[0]["plane"] = round(span * r.choice([1e3, -1e3, 1e5]), 6)
    spec: dict[str, Any] = {"name": f"random rotor ({kind})", "units": units,
                            "rotor": {"speed": r.choice([300, 1500, 3000, 50.0, 1e-3, 1e5])}}
    if r.random() < 0.1:
        for m in masses:
            m.pop("plane")            # the default, plane 0
    spec["mass"] = masses
    placed = [("A", a), ("B", b)][:planes]
    if kind == "reversed" and planes == 2:
        placed = [("A", b), ("B", a)]
    if planes == 1 and r.random() < 0.5:
        placed = [("B", round(r.uniform(0, 1) * span, 6))]
    spec["balance"] = []
    for name, z in placed:
        t: dict[str, Any] = {"name": name, "plane": z}
        if r.random() < 0.8:
            t["radius"] = round(r.uniform(0.05, 0.3) * scale, 6)
        else:
            t["mass"] = round(r.uniform(0.5, 50), 3)
        spec["balance"].append(t)
    return spec


def _cancel(masses: list[dict], r: random.Random) -> None:
    """Make the last two masses cancel the force and couple of the others (a rotor that is
    balanced already), by the two-plane closed form with their planes as A and B."""
    rest = masses[:-2]
    za, zb = masses[-2]["plane"], masses[-1]["plane"]
    if za == zb:
        return
    f = sum(m["mass"] * m["radius"] * cmath.exp(1j * _rad(m["angle"])) for m in rest)
    c = sum(m["mass"] * m["radius"] * (m["plane"] - za)
            * cmath.exp(1j * _rad(m["angle"])) for m in rest)
    in_b = -c / (zb - za)
    in_a = -f - in_b
    for m, v in ((masses[-2], in_a), (masses[-1], in_b)):
        if abs(v) == 0:
            return
        m.update(mass=abs(v) / m["radius"], angle=math.degrees(cmath.phase(v)))


def open_rotor(r: random.Random) -> dict[str, Any]:
    """A rotor balanced already (its last two masses cancel the rest), with four of its
    data (two in one plane) marked "?": in the textbooks' patterns (two masses' mass and
    angle; a mass's mass, angle and plane with another's plane, or with another's mass; a
    mass and three angles), or any four."""
    while True:
        spec = rotor(r, 2)
        masses = spec["mass"]
        if len(masses) >= 3 and len({m.get("plane", 0.0) for m in masses}) == len(masses):
            break
    static = r.random() < 0.2
    if static:                          # one plane: the force polygon alone
        for m in masses:
            m.pop("plane", None)
    _cancel(masses, r) if not static else _cancel_force(masses)
    spec.pop("balance")
    # the unknowns are the masses' own, which need no speed: a rotor that balances itself
    # refuses one given (and a couple's axis or bearings), as nothing would use them
    spec["rotor"] = {k: v for k, v in spec.get("rotor", {}).items()
                     if k not in ("speed", "about", "bearings")}
    spec["name"] = "random rotor (open)"
    i, j = r.sample(range(len(masses)), 2)
    others = [k for k in range(len(masses)) if k != i]
    pattern = r.choice(["two-masses", "planes", "plane-and-angle", "angles", "any"])
    if static:
        hide = r.choice([[(i, "mass"), (i, "angle")], [(i, "mass"), (j, "angle")],
                         [(i, "angle"), (j, "angle")], [(i, "radius"), (j, "mass")]])
    elif pattern == "two-masses":
        hide = [(i, "mass"), (i, "angle"), (j, "mass"), (j, "angle")]
    elif pattern == "planes":
        hide = [(i, "mass"), (i, "angle"), (i, "plane"), (j, "plane")]
    elif pattern == "plane-and-angle":  # the couple polygon closes on i's m·r·l first
        hide = [(i, "mass"), (i, "angle"), (i, "plane"), (j, "mass")]
    elif pattern == "angles":
        hide = [(i, "mass"), (i, "angle")] + [(k, "angle") for k in
                                             r.sample(others, min(2, len(others)))]
    else:
        keys = [(k, key) for k in range(len(masses)) for key in ("mass", "angle", "plane")]
        hide = r.sample(keys, 4)
    for k, key in hide:
        masses[k][key] = "?"
    return spec


def _cancel_force(masses: list[dict]) -> None:
    """Make the last mass cancel the others' force (one plane)."""
    f = sum(m["mass"] * m["radius"] * cmath.exp(1j * _rad(m["angle"])) for m in masses[:-1])
    if abs(f) > 0:
        masses[-1].update(mass=abs(f) / masses[-1]["radius"],
                          angle=math.degrees(cmath.phase(-f)))


# ----- engines -------------------------------------------------------------------------------
def engine(r: random.Random, cylinders: int) -> dict[str, Any]:
    """An engine: one cylinder, partly balanced, its forces asked at a crank angle; or
    ``cylinders`` in line, the cranks of a firing order (four-stroke or two-stroke), equally
    pitched or not."""
    units = _units(r)
    unit = units.get("length", "m")
    scale = _size(r, unit)
    crank = round(r.uniform(0.03, 0.1) * scale, 6)
    ratio = r.choice([4.0, 3.5, 5.0, r.uniform(3, 6)] * 4 + [1.0 + 1e-6, 1.0, 0.5])
    spec: dict[str, Any] = {"name": f"random engine ({cylinders} cylinders)", "units": units}
    e: dict[str, Any] = {"speed": r.choice([1800, 3000, 600.0, 6000, 1e-3, 1e5]),
                         "crank": crank, "rod": round(crank * ratio, 6),
                         "reciprocating": round(r.uniform(0.2, 5), 3)}
    if r.random() < 0.2:                # the primary forces alone: no rod given
        e.pop("rod")
    if r.random() < 0.2:                # the stroke, twice the crank, given instead
        e["stroke"] = round(2 * e.pop("crank"), 6)
    if cylinders == 1:
        e["balanced"] = r.choice([0, 0.5, 2 / 3, 1, 0.6666666666666666] * 3 + [1.5, -0.1])
        e["at"] = r.choice([0, 30, 90, 180, 270, 45.5, -30, 1e5, _angle(r)])
        if r.random() < 0.4:            # crank, crank pin, the rod's revolving part
            e["revolving"] = r.choice([round(r.uniform(0.1, 5), 3),
                                       [round(r.uniform(0.1, 3), 3) for _ in range(3)]])
        roll = r.random()
        if roll < 0.3:
            e["balance_radius"] = round(r.uniform(0.5, 3) * crank, 6)
        elif roll < 0.45:
            e["balance_mass"] = round(r.uniform(0.2, 20), 3)
        spec["engine"] = e
        if r.random() < 0.2:
            spec["cylinder"] = [{"crank": r.choice([0, 0, 90]), "plane": 0}]
        return spec
    spec["engine"] = e
    order = r.choice(FIRING.get(cylinders, [tuple(range(1, cylinders + 1))]))
    cycle = 720.0 if r.random() < 0.7 else 360.0           # four-stroke or two-stroke
    pitch = round(r.uniform(0.8, 2.5) * crank * 2, 6)
    planes = [pitch * k for k in range(cylinders)]
    how = r.choice(["even"] * 6 + ["uneven", "same-plane", "no-planes", "shifted"])
    if how == "uneven":
        planes = sorted(round(r.uniform(0, pitch * cylinders), 6) for _ in range(cylinders))
    elif how == "same-plane":
        planes[1] = planes[0]
    elif how == "shifted":
        planes = [p + round(r.uniform(-5, 5) * pitch, 6) for p in planes]
    spec["cylinder"] = []
    for k in range(1, cylinders + 1):
        t = {"crank": (order.index(k) * cycle / cylinders) % 360.0}
        if how != "no-planes":
            t["plane"] = round(planes[k - 1], 6)
        spec["cylinder"].append(t)
    return spec


# ----- breaking a case -----------------------------------------------------------------------
def _malform(r: random.Random, spec: dict[str, Any]) -> str:
    """The spec's file, broken one way on purpose."""
    how = r.choice(["missing-key", "zero", "negative", "string-number", "nan", "huge",
                    "typo-key", "both", "three-planes", "no-balance", "no-mass", "truncate",
                    "array-table", "units-string", "duplicate-name", "name-clash",
                    "bool", "tiny", "unknown-unit", "empty-name"])
    many = spec.get("mass") or spec.get("cylinder") or []
    item = r.choice(many) if many else spec.get("engine", {})
    top = "rotor" if "rotor" in spec else "engine"
    if how == "missing-key" and item:
        item.pop(r.choice(list(item)))
    elif how in ("zero", "negative", "string-number", "nan", "huge", "bool", "tiny") and item:
        key = r.choice([k for k in item if k != "name"] or ["mass"])
        item[key] = {"zero": 0, "negative": -1.5, "string-number": "12", "nan": float("nan"),
                     "huge": 1e7, "bool": True, "tiny": 1e-7}[how]
    elif how == "typo-key":
        spec[top]["sped"] = spec[top].pop("speed", 1)
    elif how == "both":
        spec["engine" if top == "rotor" else "rotor"] = {"speed": 100}
    elif how == "three-planes" and "rotor" in spec:
        spec["balance"] = spec.get("balance", []) + [{"name": "C", "plane": 7, "radius": 1}] * 2
    elif how == "no-balance":
        spec.pop("balance", None)
    elif how == "no-mass":
        spec.pop("mass", None)
    elif how == "truncate":
        text = to_toml(spec)
        return text[:r.randint(1, len(text) - 1)]
    elif how == "array-table":
        return to_toml(spec).replace(f"[{top}]", f"[[{top}]]", 1) + (
            f"\n[[{top}]]\nspeed = 1\n" if r.random() < 0.5 else "")
    elif how == "units-string":
        return 'units = "mm"\n' + to_toml({k: v for k, v in spec.items() if k != "units"})
    elif how == "duplicate-name" and len(spec.get("mass", [])) > 1:
        spec["mass"][1]["name"] = spec["mass"][0]["name"]
    elif how == "name-clash" and spec.get("mass") and spec.get("balance"):
        spec["mass"][0]["name"] = spec["balance"][-1].get("name", "A")
    elif how == "unknown-unit":
        spec["units"] = {"length": r.choice(["km", "ft", ""]), "speed": "rps"}
    elif how == "empty-name" and spec.get("mass"):
        spec["mass"][0]["name"] = r.choice(["", " ", "a\u202eb", "x" * 300])
    return to_toml(spec)


def generate(rng: random.Random, family: str | None = None) -> tuple[str, str]:
    """One random case: ``(family, toml_text)``; ``family`` picks one, else any."""
    family = family or rng.choice(FAMILIES)
    if family == "static-rotor":
        spec = rotor(rng, 1)
    elif family == "two-plane-rotor":
        spec = rotor(rng, 2)
    elif family == "open-rotor":
        spec = open_rotor(rng)
    elif family == "single-cylinder":
        spec = engine(rng, 1)
    else:
        spec = engine(rng, rng.choice([2, 3, 4, 4, 5, 6, 6, 8]))
    if rng.random() < MALFORMED:
        return family, _malform(rng, spec)
    return family, to_toml(spec)


# ----- the oracle ----------------------------------------------------------------------------
AGREE = 1e-9
"""How near, relative to the sizes its sums are made of, a result must come to the oracle's:
far looser than rounding (1e-15), far tighter than any error a reader could see."""


def _rad(degrees: float) -> float:
    """Degrees as radians, whole turns off first (exact in binary): 100030° is 310°."""
    return math.radians(math.fmod(degrees, 360.0))


def _read(text: str) -> tuple[dict[str, Any], float, float]:
    """The file's tables, a number written as a string ("12", which tarsim reads as its
    value) taken as the number, with its length and speed units' sizes."""
    data = tomllib.loads(text)
    for table in ("rotor", "engine", "mass", "balance", "cylinder"):
        rows = data.get(table, [])
        for row in [rows] if isinstance(rows, dict) else rows:
            for k, v in row.items():
                if k != "name" and isinstance(v, str) and _NUMBER.fullmatch(v.strip()):
                    row[k] = float(v)
    units = data.get("units", {})
    return data, _METRE[units.get("length", "m")], _RATE[units.get("speed", "rad/s")]


_NUMBER = re.compile(r"[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?")


def oracle(solution, text: str) -> list[str]:
    """What the solved ``solution`` of the file ``text`` gets wrong, by the closed forms
    summed here from the file's own numbers (an empty list if nothing)."""
    data, metre, rate = _read(text)
    doc = solution.results["quantities"]
    lines = solution.lines()
    if "rotor" in data and any(v == "?" for m in data["mass"] for v in m.values()):
        return _open_wrongs(data, metre, doc)
    if "rotor" in data and not data.get("balance"):
        return _unbalance_wrongs(data, metre, rate, doc)
    if "rotor" in data:
        return _rotor_wrongs(data, metre, doc, lines)
    return _engine_wrongs(data, metre, rate, doc, lines)


def _unbalance_wrongs(data, metre: float, rate: float, doc: dict) -> list[str]:
    """A rotor with no balancing plane: its out-of-balance force |Σ m r| ω² and couple
    |Σ m r (l − l₀)| ω², l₀ midway between the outermost masses (or the file's about)."""
    w2 = (data["rotor"]["speed"] * rate) ** 2
    planes = [m.get("plane", 0.0) * metre for m in data["mass"]]
    l0 = data["rotor"]["about"] * metre if "about" in data["rotor"] else \
        (min(planes) + max(planes)) / 2
    mr = [m["mass"] * m["radius"] * metre * cmath.exp(1j * _rad(m["angle"]))
          for m in data["mass"]]
    force = abs(sum(mr)) * w2
    couple = abs(sum(v * (z - l0) for v, z in zip(mr, planes))) * w2
    f_scale = sum(abs(v) for v in mr) * w2
    c_scale = sum(abs(v) * (abs(z) + abs(l0)) for v, z in zip(mr, planes)) * w2
    wrong = []
    for name, want, scale in (("unbalanced_force", force, f_scale),
                              ("unbalanced_couple", couple, c_scale)):
        q = doc.get(name)
        if name == "unbalanced_couple" and q is None and max(planes) == min(planes):
            continue                          # one plane: no couple to give
        if q is None:
            wrong.append(f"results.json has no {name}")
        elif abs(q["value"] - want) > AGREE * scale:
            wrong.append(f"{name} = {q['value']:.9g}, the closed form {want:.9g}")
    return wrong


def _rotor_wrongs(data, metre: float, doc: dict, lines: list[str]) -> list[str]:
    masses = [(m["mass"] * m["radius"] * metre * cmath.exp(1j * _rad(m["angle"])),
               m.get("plane", 0.0) * metre) for m in data["mass"]]
    planes = [(t.get("name", "AB"[i]), t.get("plane", 0.0) * metre, t)
              for i, t in enumerate(data["balance"])]
    za = planes[0][1]
    force = sum(v for v, _ in masses)
    couple = sum(v * (z - za) for v, z in masses)
    want = {planes[0][0]: -force}
    lever = 0.0
    if len(planes) == 2:
        lever = planes[1][1] - za
        want[planes[1][0]] = -couple / lever
        want[planes[0][0]] = -force + couple / lever
    # The sizes the sums round at; an arm z − z_A rounds at the size of z and z_A themselves.
    f_scale = sum(abs(v) for v, _ in masses) + sum(abs(w) for w in want.values())
    c_scale = sum(abs(v) * (abs(z) + abs(za)) for v, z in masses) + (
        abs(want[planes[1][0]]) * (abs(planes[1][1]) + abs(za)) if lever else 0.0)
    p_scale = f_scale + (c_scale / abs(lever) if lever else 0.0)
    wrong = []
    got = {}
    for name, z, t in planes:
        q = doc.get(f"mr_{name}")
        if q is None:
            wrong.append(f"results.json has no mr_{name}")
            continue
        g = complex(*q["value"])
        got[name] = (g, z)
        if abs(g - want[name]) > AGREE * p_scale:
            wrong.append(f"mr_{name} = {g:.6g}, the closed form {want[name]:.6g}")
        none = q.get("none_needed", False)
        if none and abs(want[name]) > AGREE * p_scale:
            wrong.append(f"plane {name} said to need no mass, but needs {abs(want[name]):.6g}")
        if not none and abs(want[name]) <= 1e-13 * p_scale:
            wrong.append(f"plane {name} given a mass at {q.get('angle_deg')}°, where none is "
                         "needed (the product is rounding)")
        if none == ("angle_deg" in q):
            wrong.append(f"mr_{name}: none_needed and angle_deg disagree")
        wrong += _printed(name, t, metre, want[name], none, lines, p_scale)
        wrong += _balance_mass(name, t, metre, want[name], doc, p_scale)
    # The balanced rotor: its masses and the products found leave no force, and no couple.
    left_f = force + sum(g for g, _ in got.values())
    left_c = couple + sum(g * (z - za) for g, z in got.values())
    if abs(left_f) > AGREE * f_scale:
        wrong.append(f"the balanced rotor keeps a force of {abs(left_f):.3g} kg·m")
    if lever and abs(left_c) > AGREE * c_scale:
        wrong.append(f"the balanced rotor keeps a couple of {abs(left_c):.3g} kg·m²")
    return wrong


def _open_wrongs(data, metre: float, doc: dict) -> list[str]:
    """The masses with results.json's unknowns filled in must leave no force and, with
    their planes apart, no couple: Σ m r e^{iθ} and Σ m r l e^{iθ} summed here."""
    static = not any("plane" in m for m in data["mass"])
    force = couple = 0j
    f_scale = c_scale = 0.0
    for i, m in enumerate(data["mass"]):
        name = str(m.get("name", i + 1))
        got = {}
        for key in ("mass", "radius", "angle", "plane"):
            v = m.get(key, 0.0)
            if v == "?":
                q = doc.get(f"{key}_{name}")
                if q is None:
                    return [f"results.json has no {key}_{name}"]
                v = q["value"]
            elif key in ("radius", "plane"):
                v *= metre
            got[key] = v
        u = got["mass"] * got["radius"] * cmath.exp(1j * _rad(got["angle"]))
        force += u
        couple += u * got["plane"]
        f_scale += abs(u)
        c_scale += abs(u) * abs(got["plane"])
    wrong = []
    if abs(force) > AGREE * f_scale:
        wrong.append(f"the rotor keeps a force of {abs(force):.3g} kg·m")
    if not static and abs(couple) > AGREE * (c_scale or 1.0):
        wrong.append(f"the rotor keeps a couple of {abs(couple):.3g} kg·m²")
    return wrong


_PLACED = re.compile(r"^plane (?P<name>.+?): balancing m·r = (?P<size>\S+) kg·m at "
                     r"(?P<angle>\S+)°, so (?P<mass>\S+) kg at (?P<radius>\S+) (?P<unit>\S+)$")


def _printed(name, t, metre, want: complex, none: bool, lines: list[str],
             scale: float) -> list[str]:
    """What the printed line says of plane ``name``, against the closed form, to the digits
    it prints (six significant figures, angles to 0.01°)."""
    said = [ln for ln in lines if ln.startswith(f"plane {name}:")]
    if len(said) != 1:
        return [f"{len(said)} lines for plane {name}"]
    if none:
        return [] if "no balancing mass needed" in said[0] else [f"plane {name}: {said[0]}"]
    m = _PLACED.match(said[0])
    if m is None:
        return [f"plane {name} printed as {said[0]!r}"]
    out = []
    size = float(m["size"])
    if abs(size - abs(want)) > 1e-5 * abs(want) + 1e-12 * scale:
        out.append(f"plane {name}: m·r printed {size}, the closed form {abs(want):.6g}")
    turn = math.degrees(cmath.phase(want)) % 360.0
    miss = abs((float(m["angle"]) - turn + 180.0) % 360.0 - 180.0)
    if abs(want) > 1e-6 * scale and miss > 0.006:
        out.append(f"plane {name}: angle printed {m['angle']}°, the closed form {turn:.4f}°")
    radius = t["radius"] * metre if "radius" in t else abs(want) / t["mass"]
    mass = t["mass"] if "mass" in t else abs(want) / radius
    if abs(float(m["mass"]) - mass) > 1e-5 * mass + 1e-300:
        out.append(f"plane {name}: mass printed {m['mass']} kg, the closed form {mass:.6g}")
    return out


def _balance_mass(name, t, metre, want: complex, doc: dict, scale: float) -> list[str]:
    """results.json's balancing mass (at the stated radius) or radius (for the stated mass),
    against the closed form's product over the given number."""
    key, given = (f"mass_{name}", t["radius"] * metre) if "radius" in t else (
        f"radius_{name}", t.get("mass"))
    q = doc.get(key)
    if q is None:
        return [f"results.json has no {key}"]
    if abs(q["value"] * given - abs(want)) > AGREE * scale:
        return [f"{key} = {q['value']:.6g}, the closed form {abs(want) / given:.6g}"]
    return []


def _engine_wrongs(data, metre: float, rate: float, doc: dict, lines: list[str]) -> list[str]:
    e = data["engine"][0] if isinstance(data["engine"], list) else data["engine"]
    crank = e["crank"] if "crank" in e else e["stroke"] / 2
    m, r, w = e["reciprocating"], crank * metre, e["speed"] * rate
    n = e["rod"] / crank if "rod" in e else None
    f = m * w * w * r
    cylinders = data.get("cylinder") or [{"crank": 0.0, "plane": 0.0}]
    wrong = []
    if len(cylinders) == 1:
        theta = _rad(e.get("at", 0.0))
        c = e.get("balanced", 0.0)
        along, across = (1 - c) * f * math.cos(theta), c * f * math.sin(theta)
        want = {"primary_force": f * math.cos(theta),
                "unbalanced_along": along, "unbalanced_across": across,
                "unbalanced_resultant": abs(complex(along, across)),
                "unbalanced_max": max(abs(1 - c), abs(c)) * f}
        if n is not None:
            want["secondary_force"] = f * math.cos(2 * theta) / n
        elif "secondary_force" in doc:
            wrong.append("a secondary force with no rod given")
        revolving = e.get("revolving", 0.0)
        product = (sum(revolving) if isinstance(revolving, list) else revolving) + c * m
        product *= r
        for k, v in want.items():
            got = doc[k]["value"]
            if abs(got - v) > AGREE * f:
                wrong.append(f"{k} = {got:.6g} N, the closed form {v:.6g} N")
        if "balance_radius" in e:
            got = doc["balance_mass"]["value"] * e["balance_radius"] * metre
        elif "balance_mass" in e:
            got = doc["balance_radius"]["value"] * e["balance_mass"]
        else:
            got = product
        if abs(got - product) > AGREE * (product + m * r):
            wrong.append(f"the balance mass's B·b = {got:.6g} kg·m, the closed form "
                         f"{product:.6g}")
        return wrong
    cranks = [_rad(t.get("crank", 0.0)) for t in cylinders]
    planes = [t.get("plane", 0.0) * metre for t in cylinders]
    ref = (min(planes) + max(planes)) / 2
    arms = [p - ref for p in planes]
    reach = max(abs(p) for p in planes)       # an arm rounds at the planes' own size
    want = {"primary_force": (f * abs(sum(cmath.exp(1j * t) for t in cranks)), f),
            "primary_couple": (f * abs(sum(a * cmath.exp(1j * t) for a, t in zip(arms, cranks))),
                               f * reach)}
    if n is not None:
        want |= {"secondary_force": (f / n * abs(sum(cmath.exp(2j * t) for t in cranks)), f / n),
                 "secondary_couple": (f / n * abs(sum(a * cmath.exp(2j * t)
                                                      for a, t in zip(arms, cranks))),
                                      f / n * reach)}
    elif "secondary_force" in doc:
        wrong.append("a secondary force with no rod given")
    for k, (v, size) in want.items():
        got = doc[k]["value"]
        scale = size * len(cranks)
        if abs(got - v) > AGREE * scale:
            wrong.append(f"{k} = {got:.6g}, the closed form {v:.6g}")
        said = next((ln for ln in lines if ln.startswith(k.replace("_", " ") + ":")), "")
        if ("balanced (its polygon closes)" in said) != (v <= 1e-13 * scale):
            if v > AGREE * scale or "balanced" in said:
                wrong.append(f"{k}: printed {said!r}, the closed form {v:.6g}")
    return wrong


# ----- running a case ------------------------------------------------------------------------
def places(text: str) -> tuple[str, ...]:
    """What a refusal may name to say where its fault is: a mass, a balancing plane or a
    cylinder of the file, by name or number."""
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError:
        return ()
    out = [r"\bcylinders? \d+", r"\bcyl\. \d+"]
    for table, word in (("mass", "mass(es)?"), ("balance", "(balancing )?planes?")):
        many = data.get(table)
        if isinstance(many, list):
            out += [rf"\b{word} {re.escape(str(t.get('name')))}(?!\w)" for t in many
                    if isinstance(t, dict) and t.get("name") is not None]
    return tuple(out)


def run_case(text: str | bytes, path: str | Path, *, render: bool = False) -> Outcome:
    """Solve ``text`` through the API (random_mechanisms.run_case) with this file's oracle and
    the places a balancing refusal may name."""
    words = text if isinstance(text, str) else text.decode("utf-8", "replace")
    return _run_case(text, path, render=render, oracle=oracle, places=places(words))


def run_many(generate, run, families, what: str, argv: list[str] | None = None) -> int:
    """Run random cases one after another in this process and print the counts by outcome
    and family, with the distinct messages of every outcome but ok; 1 if any is wrong or
    other. A case past ``--timeout`` seconds is a hang (an ``other``)."""
    import argparse
    import signal
    import tempfile
    import time
    from collections import Counter, defaultdict

    from random_mechanisms import OUTCOMES

    outcomes = OUTCOMES if "wrong" in OUTCOMES else (*OUTCOMES, "wrong")
    ap = argparse.ArgumentParser(description=f"Random {what} through tarsim.")
    ap.add_argument("--cases", type=int, default=1000)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--render-every", type=int, default=10,
                    help="draw every N-th case's files to look for nan/inf (0: never)")
    ap.add_argument("--timeout", type=int, default=120)
    ap.add_argument("--save", default="", help="folder to save the cases not ok or refused")
    args = ap.parse_args(argv)

    def hang(*_):
        raise TimeoutError(f"hangs: over {args.timeout} s")

    signal.signal(signal.SIGALRM, hang)
    counts: Counter = Counter()
    by_family: dict[str, Counter] = defaultdict(Counter)
    seen: dict[tuple[str, str], list[int]] = defaultdict(list)
    start = time.monotonic()
    with tempfile.TemporaryDirectory(prefix=f"tarsim-{what}-") as folder:
        for n in range(args.cases):
            family, text = generate(random.Random(f"{args.seed}:{n}"))
            render = args.render_every > 0 and n % args.render_every == 0
            signal.alarm(args.timeout)
            try:
                got = run(text, Path(folder) / f"case-{n}.toml", render=render)
            except TimeoutError as e:
                got = Outcome("other", str(e))
            finally:
                signal.alarm(0)
            counts[got.outcome] += 1
            by_family[family][got.outcome] += 1
            if got.outcome != "ok":
                key = re.sub(r"\S*case-\d+\.toml(:\d+)*", "FILE", got.message)
                key = re.sub(r"[-+−]?\d[\d,]*(\.\d+)?([eE][-+−]?\d+)?", "#", key)
                seen[got.outcome, key].append(n)
            if args.save and got.outcome not in ("ok", "refused"):
                out = Path(args.save) / got.outcome
                out.mkdir(parents=True, exist_ok=True)
                (out / f"{n}.toml").write_text(text if isinstance(text, str) else "", "utf-8")
                (out / f"{n}.txt").write_text(f"{family}\n{got.message}\n\n{got.detail}\n",
                                              "utf-8")
    print(f"{args.cases} {what} in {time.monotonic() - start:.0f} s (seed {args.seed})")
    print(f"{'':<18}" + "".join(f"{k:>16}" for k in outcomes))
    for family in sorted(by_family):
        print(f"{family:<18}" + "".join(f"{by_family[family][k]:>16}" for k in outcomes))
    print(f"{'all':<18}" + "".join(f"{counts[k]:>16}" for k in outcomes))
    for (outcome, key), cases in sorted(seen.items(), key=lambda kv: (kv[0][0], -len(kv[1]))):
        print(f"{outcome:<16}{len(cases):>6}  {key[:160]}  (e.g. {cases[0]})")
    return 1 if counts["wrong"] or counts["other"] else 0


if __name__ == "__main__":
    sys.exit(run_many(generate, run_case, FAMILIES, "rotors"))
