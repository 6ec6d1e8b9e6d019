"""Random gear-train exercise files, posed as the textbooks pose them, with an exact oracle.

The contract under test is tests/random_mechanisms.py's: every file either solves to finite
numbers that all pass their check, or is refused in one ``TarsimError`` line that says what
is wrong and where (file:line, a gear, a member, a mesh). Here each answer is also held to
the closed form the generator knows from the tooth numbers it chose, so a number printed as
"check ok" that contradicts it is caught (``wrong``), and so is an answer to a file that
must be refused.

The families: a simple train with idlers (an internal mesh now and then), a compound train,
a reverted one (its first pair's involute mesh drawn now and then), a planetary train (sun,
planet, ring, arm; the ring, the sun or the arm fixed; some without a ring), a compound
planet between two main-axis gears (Q3, Q4), planets at two or three carrier radii, and an
involute pair with its module and pressure angle. The input is any member but the fixed
one; now and then it carries a torque, and the output's and the holding torque are asked.
Some cases are degenerate on purpose (a ratio asked over the fixed member or over one that
stands still, a planet or the input held, planets that cannot be spaced or do not fit,
gears pulled apart or jammed) and must be refused; some are broken as a hand-written file
is (zero teeth, a gear meshing itself, a shaft naming no member, a missing table, absurd
numbers, a truncated file).

The oracle: with the arm held, member k turns e_k times the reference gear (the product of
driver over driven teeth along the meshes, − for each external one; the arm 0), so
ω_k = ω_arm + e_k·x (Willis); the fixed member's 0 and the input's speed give ω_arm and x.
It is written into the file as comments, ``# oracle omega4 = -3/2``, so a saved case
carries its own answer. ``python -m tests.random_trains --cases 3000 --seed 1`` runs a
batch and prints the counts by outcome; benchmarks/robustness.py runs ``run_train_case``
with the other chapters'.
"""

from __future__ import annotations

import argparse
import json
import math
import random
import re
import tempfile
import time
from collections import Counter
from dataclasses import dataclass, field
from fractions import Fraction
from pathlib import Path
from typing import Any

try:
    from tests.random_mechanisms import OUTCOMES, Lit, Outcome, _key, _val, run_case
except ImportError:                      # run from tests/ itself, as benchmarks/ import it
    from random_mechanisms import OUTCOMES, Lit, Outcome, _key, _val, run_case

__all__ = ["FAMILIES", "TRAIN_OUTCOMES", "PLACES", "Train", "build", "generate", "oracle",
           "expectations", "contradictions", "oracle_wrongs", "train_toml", "run_train_case"]

FAMILIES = ("simple", "compound", "reverted", "planetary", "compound-planet", "carrier-radii",
            "involute")
TRAIN_OUTCOMES = (*dict.fromkeys((*OUTCOMES, "wrong", "refused-valid")),)
"""The outcomes of tests/random_mechanisms.py; ``wrong``, an answer the oracle contradicts
or an answer to a file that must be refused; ``refused-valid``, a refusal of a file the
closed form answers."""
MALFORMED = 0.1
DEGENERATE = 0.08
MODULES = (1, 1.25, 1.5, 2, 2.5, 3, 4, 5, 6, 8, 10, 12, 16, 20)


@dataclass
class Train:
    """A case before it is written: its tables, each member's turns ``e`` relative to the
    reference gear with the arm held (the arm 0), the arm, what the file must give
    (``"answer"``, or ``"refused"`` for a degenerate one), and an involute mesh's numbers
    by the textbook formulas."""

    spec: dict[str, Any]
    e: dict[int, Fraction]
    arm: int | None = None
    expect: str = "answer"
    mesh: dict[str, float] = field(default_factory=dict)
    side: dict[int, tuple[int, Fraction]] = field(default_factory=dict)
    """Gears on side shafts: each turns a ratio times the main-axis gear it meshes."""

    @property
    def members(self) -> list[int]:
        """Every member: the gears and the arm, then the side shafts' gears."""
        return [*self.e, *self.side]


# ----- the file ----------------------------------------------------------------------------
def train_toml(spec: dict[str, Any], comments: list[str] = ()) -> str:
    """The gear-train file of ``spec``: its comments, the top keys, then each table."""
    out = [f"# {c}" for c in comments]
    for k in ("name", "description", "fixed"):
        if k in spec:
            out.append(f"{k} = {_val(spec[k])}")
    for k, v in spec.items():
        if k in ("name", "description", "fixed"):
            continue
        for t in (v if isinstance(v, list) else [v]):
            out += ["", f"[[{k}]]" if isinstance(v, list) else f"[{k}]"]
            out += [f"{_key(a)} = {_val(b)}" for a, b in t.items()]
    return "\n".join(out) + "\n"


def _gear(number: int, teeth: int, name: str = "", carrier: int | None = None,
          module: float | None = None) -> dict[str, Any]:
    g: dict[str, Any] = {"number": number, "teeth": teeth}
    if name:
        g["name"] = name
    if module is not None:
        g["module"] = module
    if carrier is not None:
        g["carrier"] = carrier
    return g


def _mesh(a: int, b: int, internal: bool = False) -> dict[str, Any]:
    return {"gears": [a, b], **({"kind": "internal"} if internal else {})}


def _turns(e: dict[int, Fraction], a: int, b: int, teeth: dict[int, int], internal: bool):
    """Carry the arm-held turns from gear ``a`` to gear ``b`` through their mesh."""
    e[b] = e[a] * Fraction(teeth[a], teeth[b]) * (1 if internal else -1)


# ----- the families ------------------------------------------------------------------------
def simple(r: random.Random) -> Train:
    """Gears 2, 3, … each on its own axis, each meshing the next (idlers between)."""
    n = r.randint(2, 5)
    teeth = {k: r.randint(10, 120) if r.random() < 0.95 else r.choice((1, 2, 100_000))
             for k in range(2, n + 2)}
    gears, meshes, e = [], [], {2: Fraction(1)}
    for k in range(2, n + 2):
        gears.append(_gear(k, teeth[k], "idler" if 2 < k < n + 1 else ""))
        if k > 2:
            internal = r.random() < 0.2 and teeth[k] != teeth[k - 1]
            meshes.append(_mesh(k - 1, k, internal))
            _turns(e, k - 1, k, teeth, internal)
    return Train({"name": "A simple train", "gear": gears, "mesh": meshes}, e)


def compound(r: random.Random, stages: int | None = None, total: int | None = None) -> Train:
    """Stages of a driver and a driven gear, each driven gear on one shaft with the next
    driver; ``total`` teeth a stage (a reverted train: input and output coaxial)."""
    steep = stages is None and r.random() < 0.03        # dozens of stages of 100000 to 1
    stages = stages or (r.randint(15, 60) if steep else r.randint(2, 4))
    gears, meshes, shafts, e, teeth = [], [], [], {2: Fraction(1)}, {}
    for s in range(stages):
        a, b = 2 + 2 * s, 3 + 2 * s
        teeth[a] = r.randint(10, 40) if total is None else r.randint(10, total - 10)
        teeth[b] = r.randint(20, 100) if total is None else total - teeth[a]
        if steep:
            teeth[a], teeth[b] = 100_000, 1
        gears += [_gear(a, teeth[a]), _gear(b, teeth[b])]
        meshes.append(_mesh(a, b))
        _turns(e, a, b, teeth, False)
        if s < stages - 1:
            shafts.append({"members": [b, b + 1]})
            e[b + 1] = e[b]
    spec = {"name": "A compound train", "gear": gears, "mesh": meshes, "shaft": shafts}
    return Train(spec, e)


def reverted(r: random.Random) -> Train:
    """Two stages of one centre distance: the output coaxial with the input."""
    t = compound(r, 2, r.randint(40, 160))
    t.spec["name"] = "A reverted train"
    if r.random() < 0.3:
        _involute(r, t, 2, 3)             # and its first pair's mesh drawn
    else:
        module = r.choice(MODULES)
        for g in t.spec["gear"]:
            g["module"] = module
    return t


def _planets(r: random.Random, spec: dict[str, Any], sun: int, ring: int, planet: int,
             centre: Fraction) -> str:
    """Sometimes more than one planet, equally spaced (the expected verdict)."""
    k = r.choice((1, 1, 2, 3, 4))
    if k == 1:
        return "answer"
    spec["arm"]["planets"] = k
    fits = 2 * float(centre) * math.sin(math.pi / k) > planet + 2
    spaced = (sun + ring) % k == 0 if ring else True
    return "answer" if fits and spaced else "refused"


def planetary(r: random.Random) -> Train:
    """A sun, a planet on the arm and (mostly) a ring about the sun, as the notes' Q1; now
    and then a second planet in series, meshing the first further out (Q2), the ring then
    meshing it."""
    sun, planet = r.randint(12, 80), r.randint(12, 60)
    nr, ns, na, npl, n2 = r.sample(range(1, 10), 5)
    series = r.randint(12, 40) if r.random() < 0.2 else 0
    outer = n2 if series else npl                     # the planet the ring meshes
    ring = (sun + 2 * planet + 2 * series) if r.random() < 0.85 else 0
    teeth = {ns: sun, npl: planet, nr: ring, n2: series}
    gears = [_gear(ns, sun, "sun"), _gear(npl, planet, "planet", na)]
    meshes = [_mesh(ns, npl)]
    e = {ns: Fraction(1), na: Fraction(0)}
    _turns(e, ns, npl, teeth, False)
    if series:
        gears.append(_gear(n2, series, "second planet", na))
        meshes.append(_mesh(npl, n2))
        _turns(e, npl, n2, teeth, False)
    if ring:
        gears.insert(0, _gear(nr, ring, "ring"))
        meshes.append(_mesh(outer, nr, True))
        _turns(e, outer, nr, teeth, True)
    spec = {"name": "A planetary train", "gear": gears, "arm": {"number": na},
            "mesh": meshes}
    t = Train(spec, e, na)
    if not series:
        t.expect = _planets(r, spec, sun, ring, planet, Fraction(sun + planet, 2))
    if r.random() < 0.25:                 # a pinion on a side shaft drives the sun, or
        side = next(k for k in range(10, 20) if k not in teeth)
        teeth[side] = r.randint(12, 60)
        gears.append(_gear(side, teeth[side], "pinion"))
        mate = ns
        if r.random() < 0.4:              # a gear keyed to the arm's hub (it turns with it)
            mate = side + 1
            teeth[mate] = r.randint(40, 120)
            gears.append(_gear(mate, teeth[mate], "arm gear"))
            spec["shaft"] = [{"members": [na, mate]}]
            e[mate] = Fraction(0)
        meshes.append(_mesh(side, mate))
        t.side[side] = (mate, Fraction(-teeth[mate], teeth[side]))
    return t


def compound_planet(r: random.Random) -> Train:
    """A compound planet p–q on the arm, p meshing a sun or a ring X (and now and then the
    other kind too), q meshing a sun or a ring Y, all at one carrier radius (Q3, Q4)."""
    p, q = r.randint(12, 50), r.randint(12, 50)
    span = r.randint(max(p, q) + 10, max(p, q) + 60)          # twice the carrier radius
    numbers = r.sample(range(1, 10), 6)
    nx, ny, nz, np_, nq, na = numbers
    teeth = {np_: p, nq: q}
    kinds = {nx: r.random() < 0.5, ny: r.random() < 0.5}      # True: a ring
    gears = [_gear(np_, p, "planet", na), _gear(nq, q, "planet", na)]
    meshes, e = [], {nx: Fraction(1), na: Fraction(0)}
    for g, planet in ((nx, np_), (ny, nq)):
        teeth[g] = span + teeth[planet] if kinds[g] else span - teeth[planet]
        gears.append(_gear(g, teeth[g], "ring" if kinds[g] else "sun"))
        meshes.append(_mesh(planet, g, kinds[g]))
    _turns(e, nx, np_, teeth, kinds[nx])
    e[nq] = e[np_]
    _turns(e, nq, ny, teeth, kinds[ny])
    if r.random() < 0.4:                  # Q4: the other kind meshing p as well
        teeth[nz] = span - p if kinds[nx] else span + p
        gears.append(_gear(nz, teeth[nz], "sun" if kinds[nx] else "ring"))
        meshes.append(_mesh(np_, nz, not kinds[nx]))
        _turns(e, np_, nz, teeth, not kinds[nx])
    spec = {"name": "A compound planet", "gear": gears, "arm": {"number": na},
            "mesh": meshes, "shaft": [{"members": [np_, nq]}]}
    return Train(spec, e, na)


def carrier_radii(r: random.Random) -> Train:
    """Planets at several carrier radii on one arm: two or three sets sharing a ring (each
    with its own sun) or a sun (each with its own ring), or a compound planet and a second
    planet on the sun it drives."""
    how = r.choice(("ring", "sun", "compound"))
    k = r.choice((2, 2, 3))
    n = r.sample(range(1, 13), 2 * k + 2)
    arm, shared = n[-1], n[0]
    e: dict[int, Fraction] = {shared: Fraction(1), arm: Fraction(0)}
    pairs, shafts, carried = [], [], set()
    if how in ("ring", "sun"):            # the shared gear n0; planets n1…nk; their mates after
        sizes = r.sample(range(12, 40), k)
        big = 2 * max(sizes) + r.randint(12, 60) if how == "ring" else r.randint(12, 60)
        teeth = {shared: big}
        names = {shared: how}
        for j, p in enumerate(sizes):
            planet, mate = n[1 + j], n[1 + k + j]
            teeth[planet] = p
            teeth[mate] = big - 2 * p if how == "ring" else big + 2 * p
            names[planet] = "planet"
            names[mate] = "sun" if how == "ring" else "ring"
            pairs += [(shared, planet, how == "ring"), (planet, mate, how == "sun")]
            carried.add(planet)
    else:                                 # sun n0 – planet n1 = n2 – sun n3 – planet n4 – ring n5
        n = r.sample(range(1, 10), 7)
        arm, shared = n[6], n[0]
        e = {shared: Fraction(1), arm: Fraction(0)}
        a, p, q = r.randint(16, 60), r.randint(12, 50), r.randint(12, 50)
        b = a + p - q                     # one carrier radius for the compound planet
        if b < 10:
            a, b = a + 10 - b, 10
        w = r.choice([j for j in range(10, 40) if j != q])      # another for the second
        teeth = {n[0]: a, n[1]: p, n[2]: q, n[3]: b, n[4]: w, n[5]: b + 2 * w}
        names = {n[0]: "sun", n[1]: "planet", n[2]: "planet", n[3]: "second sun",
                 n[4]: "second planet", n[5]: "ring"}
        pairs = [(n[0], n[1], False), (n[2], n[3], False), (n[3], n[4], False),
                 (n[4], n[5], True)]
        shafts = [{"members": [n[1], n[2]]}]
        carried = {n[1], n[2], n[4]}
    gears = [_gear(j, teeth[j], names[j], arm if j in carried else None) for j in names]
    meshes = []
    for a, b, internal in pairs:
        meshes.append(_mesh(a, b, internal))
        _turns(e, a, b, teeth, internal)
        for shaft in shafts:
            if b in shaft["members"]:
                e.update({j: e[b] for j in shaft["members"]})
    spec = {"name": f"Planets at several carrier radii ({how})", "gear": gears,
            "arm": {"number": arm}, "mesh": meshes, "shaft": shafts}
    return Train(spec, e, arm)


def involute(r: random.Random) -> Train:
    """A spur pair drawn by construction: its module (or diametral pitch), pressure angle,
    tooth form and, now and then, a centre distance off the standard one (pulled apart or
    jammed on purpose, a few)."""
    z1 = r.randint(6, 40)
    z2 = r.randint(z1, 120)
    t = Train({"name": "A spur pair", "gear": [_gear(2, z1, "pinion"), _gear(3, z2, "wheel")],
               "mesh": [_mesh(2, 3)]}, {2: Fraction(1), 3: Fraction(-z1, z2)})
    _involute(r, t, 2, 3)
    return t


def _involute(r: random.Random, t: Train, a: int, b: int) -> None:
    """Give gears ``a`` (the driver) and ``b`` a module and an [involute] table, and the
    mesh's numbers by the textbook formulas as the oracle (or a verdict to refuse it)."""
    z1, z2 = (next(g["teeth"] for g in t.spec["gear"] if g["number"] == n) for n in (a, b))
    m, angle = r.choice(MODULES), r.choice((14.5, 20, 20, 25))
    inches = r.random() < 0.1
    for g in t.spec["gear"]:
        if inches:
            g.pop("module", None)
            g["diametral_pitch"] = round(25.4 / m, 4)
        else:
            g["module"] = m
    if inches:
        m = 25.4 / round(25.4 / m, 4)
    add, ded = (1.0, 1.25) if r.random() < 0.8 else r.choice(((0.8, 1.0), (1.0, 1.157),
                                                               (1.2, 1.5)))
    table: dict[str, Any] = {"gears": [a, b], "pressure_angle": angle}
    if (add, ded) != (1.0, 1.25):
        table |= {"addendum": add, "dedendum": ded}
    phi = math.radians(angle)
    rb = [m * z * math.cos(phi) / 2 for z in (z1, z2)]
    ra = [m * z / 2 + add * m for z in (z1, z2)]
    rf = [m * z / 2 - ded * m for z in (z1, z2)]
    reach = sum(math.sqrt(x * x - y * y) for x, y in zip(ra, rb))
    c = m * (z1 + z2) / 2
    edges = (sum(rb), ra[0] + rf[1], ra[1] + rf[0], math.hypot(sum(rb), reach))
    if r.random() < 0.3:                  # near the standard distance, or anywhere between
        low, high = max(edges[:3]), edges[3]          # the closest and the widest it meshes
        off = round(c + r.choice((0.05, 0.2, 0.5, 1.0, 3.0, -0.1, -0.3)) * m, 3) \
            if r.random() < 0.6 else round(low + r.uniform(-0.2, 1.2) * (high - low), 4)
        if all(abs(off - x) > 1e-9 * x for x in edges):      # not on an edge, to rounding
            c = table["centre_distance"] = off
    t.spec["involute"] = table
    if min(rf) <= 0 or c <= sum(rb) or c < max(ra[0] + rf[1], ra[1] + rf[0]) \
            or c >= math.hypot(sum(rb), reach):
        t.expect = "refused"
        return
    working = math.acos(sum(rb) / c)
    path = reach - c * math.sin(working)
    t.mesh = {"path_of_contact": path * 1e-3, "contact_ratio": path / (math.pi * m * math.cos(phi)),
              "pressure_angle": working, "circular_pitch": math.pi * m * 1e-3}


BUILDERS = {"simple": simple, "compound": compound, "reverted": reverted,
            "planetary": planetary, "compound-planet": compound_planet,
            "carrier-radii": carrier_radii, "involute": involute}


# ----- the input, the fixed member and the asks ---------------------------------------------
def _carried(spec: dict[str, Any]) -> set[int]:
    planets = {g["number"] for g in spec["gear"] if "carrier" in g}
    for shaft in spec.get("shaft", []):
        if planets & set(shaft["members"]):
            planets |= set(shaft["members"])
    return planets


def _body(spec: dict[str, Any], m: int) -> set[int]:
    body = {m}
    for shaft in spec.get("shaft", []):
        if body & set(shaft["members"]):
            body |= set(shaft["members"])
    return body


def oracle(t: Train) -> dict[int, Fraction] | None:
    """Every member's speed (the file's unit, ccw +) by Willis from the arm-held turns: each
    member turns a·ω_arm + b·x (a = 1 and b = e_k on the main axis and the arm, a side
    gear its ratio times its mate's; a = 0 in an ordinary train), and the fixed member's 0
    and the input's speed fix ω_arm and x. None if the input cannot drive (it turns with
    the fixed member)."""
    spec = t.spec
    v = Fraction(repr(spec["input"]["speed"])) * (-1 if spec["input"]["sense"] == "cw" else 1)
    turning = t.arm is not None and "fixed" in spec       # else every axis stands still
    coef = {m: (Fraction(int(turning)), k) for m, k in t.e.items()}
    for gear, (mate, ratio) in t.side.items():
        coef[gear] = (ratio * coef[mate][0], ratio * coef[mate][1])
    a_in, b_in = coef[spec["input"]["member"]]
    a_fix, b_fix = coef[spec["fixed"]] if turning else (Fraction(1), Fraction(0))
    det = a_fix * b_in - b_fix * a_in
    if det == 0:
        return None
    arm, x = -b_fix * v / det, a_fix * v / det
    return {m: a * arm + b * x for m, (a, b) in coef.items()}


def _pose(r: random.Random, t: Train, family: str) -> None:
    """Choose the fixed member, the input (any other member), its speed and the asks."""
    spec = t.spec
    members = t.members
    if t.arm is not None:
        spec["fixed"] = r.choice([m for m in members if m not in _carried(spec)
                                  and m not in t.side])
    free = [m for m in members if "fixed" not in spec or m not in _body(spec, spec["fixed"])]
    speed = r.choice((r.randint(1, 3000), r.randint(1, 3000), round(r.uniform(0.1, 500), 2),
                      r.choice((1e-6, 1e-3, 1e6, 1e12, 7.5e28))))
    spec["units"] = {"speed": r.choice(("rpm", "rpm", "rad/s"))}
    spec["input"] = {"member": r.choice(free), "speed": speed, "sense": r.choice(("cw", "ccw"))}
    names = [f"omega{m}" for m in members]
    find = r.sample(names, r.randint(1, len(names)))
    for _ in range(r.randint(0, 3)):
        a, b = r.sample(free, 2) if len(free) > 1 else (free[0], free[0])
        find.append(f"omega{a}/omega{b}")
    out = [m for m in free if m not in _body(spec, spec["input"]["member"])]
    if out and r.random() < 0.25:
        spec["input"]["torque"] = r.choice((1, 20, 12.5, 1000))
        o = r.choice(out)
        how = r.choice(("all", "output", "input"))
        if how != "input":
            find += [f"torque{o}"] + ([f"torque{spec['fixed']}"]
                                      if "fixed" in spec and how == "all" else [])
        if how != "output":
            find.append(f"torque{spec['input']['member']}")
    if family == "involute" or "involute" in spec:
        find += r.sample(["contact_ratio", "path_of_contact", "arc_of_contact",
                          "pressure_angle", "circular_pitch", "interference", "least_teeth"],
                         r.randint(1, 7))
    spec["ask"] = {"find": list(dict.fromkeys(find))}


def _degenerate(r: random.Random, t: Train) -> None:
    """Make a case that must be refused: a ratio over the fixed member, a gear of an
    ordinary train held, the input held (or, answered, a planet held from turning)."""
    spec = t.spec
    how = r.choice(("over-fixed", "fixed-planet", "fixed-gear", "input-fixed", "fixed-side"))
    if how == "over-fixed" and "fixed" in spec:
        spec["ask"]["find"].append(f"omega{spec['input']['member']}/omega{spec['fixed']}")
    elif how == "fixed-planet" and _carried(spec):
        # a planet held from turning (Watt's sun and planet) is a train like any other:
        # the oracle's Willis turns hold it at 0; only its input held with it is refused
        spec["fixed"] = r.choice(sorted(_carried(spec)))
        if spec["input"]["member"] not in _body(spec, spec["fixed"]):
            return
    elif how == "fixed-gear" and t.arm is None:
        spec["fixed"] = r.choice(t.members)
    elif how == "fixed-side" and t.side and "fixed" in spec:
        spec["fixed"] = r.choice(list(t.side))
        if spec["input"]["member"] in _body(spec, spec["fixed"]):
            spec["input"]["member"] = spec["fixed"]
    elif how == "input-fixed" and "fixed" in spec:
        spec["input"]["member"] = spec["fixed"]
    else:
        return
    t.expect = "refused"


def build(r: random.Random, family: str) -> Train:
    """A posed train of ``family`` with its expected verdict."""
    t = BUILDERS[family](r)
    _pose(r, t, family)
    return t


def _comments(t: Train) -> list[str]:
    """The oracle as the file's comments; a ratio or a torque over a still member, or an
    input that cannot drive, makes it a file to refuse."""
    speeds = oracle(t) if t.expect == "answer" else None
    expect = t.expect if speeds is not None else "refused"
    if speeds and any(w and not Fraction(1, 10**100) <= abs(w) < 10**101
                      for w in speeds.values()):
        expect = "refused"                # no train turns beyond 1e±100 (rpm or rad/s)
    lines = []
    if speeds is not None:
        spec = t.spec
        for q in spec["ask"]["find"]:
            parts = q.split("/")
            if len(parts) == 2 and speeds[int(parts[1].removeprefix("omega"))] == 0:
                expect = "refused"
            if q.startswith("torque") and speeds[int(q.removeprefix("torque"))] == 0 \
                    and int(q.removeprefix("torque")) != spec.get("fixed"):
                expect = "refused"
        lines += [f"oracle omega{m} = {w}" for m, w in speeds.items()]
        if "torque" in spec["input"]:
            i = spec["input"]["member"]
            t_in = Fraction(repr(spec["input"]["torque"])) * (1 if speeds[i] > 0 else -1)
            loads = [int(q.removeprefix("torque")) for q in spec["ask"]["find"]
                     if q.startswith("torque")]
            o = next((m for m in loads if m not in (i, spec.get("fixed"))), None)
            if o is not None and speeds[o] != 0:
                t_out = -t_in * speeds[i] / speeds[o]
                lines += [f"oracle torque{i} = {t_in}", f"oracle torque{o} = {t_out}"]
                if "fixed" in spec:
                    lines.append(f"oracle torque{spec['fixed']} = {-(t_in + t_out)}")
        lines += [f"oracle {k} = {v!r}" for k, v in t.mesh.items()]
    return [f"oracle expect = {expect}", *lines]


ABSURD = (("teeth", Lit("10000000")), ("speed", 1e300), ("speed", Lit("inf")),
          ("speed", Lit("nan")), ("speed", 5e-324), ("speed", Lit("1" + "0" * 40)),
          ("speed", Lit("1" + "0" * 400)), ("module", 1e300), ("module", 1e-300),
          ("module", -2), ("module", Lit("1" + "0" * 400)), ("angle", 90),
          ("planets", 1000), ("centre", -5.0), ("centre", 1e12), ("fixed", 99),
          ("member", 99))
"""Numbers no train has, and where they go."""


def _malform(r: random.Random, t: Train) -> str:
    """The file broken in one of the ways a hand-written one is (no oracle: it must be
    answered or refused cleanly)."""
    spec = json.loads(json.dumps(t.spec))
    gear = r.choice(spec["gear"])
    how = r.choice(("zero-teeth", "self-mesh", "drop", "absurd", "string", "float-teeth",
                    "typo", "unknown-gear", "twice", "truncate", "kind", "bool", "shaft"))
    if how == "zero-teeth":
        gear["teeth"] = r.choice((0, -12))
    elif how == "self-mesh":
        spec["mesh"][0]["gears"] = [gear["number"]] * 2
    elif how == "drop":
        key = r.choice(("input", "mesh", "gear", "arm", "ask", "teeth", "number"))
        (gear if key in ("teeth", "number") else spec).pop(key, None)
    elif how == "absurd":
        where, value = r.choice(ABSURD)
        if where in ("teeth", "module"):
            gear[where] = value
        elif where in ("speed", "member"):
            spec["input"][where] = value
        elif where == "angle":
            spec.setdefault("involute", {"gears": [gear["number"]] * 2})["pressure_angle"] = value
        elif where == "centre":
            spec.setdefault("involute", {"gears": [gear["number"]] * 2})["centre_distance"] = value
        elif where == "planets" and "arm" in spec:
            spec["arm"]["planets"] = value
        else:
            spec["fixed"] = value
    elif how == "string":
        gear["teeth"] = str(gear["teeth"])
    elif how == "float-teeth":
        gear["teeth"] = gear["teeth"] + 0.5
    elif how == "typo":
        gear["teeht"] = gear.pop("teeth")
    elif how == "unknown-gear":
        spec["mesh"][-1]["gears"] = [spec["mesh"][-1]["gears"][0], 99]
    elif how == "twice":
        spec["gear"].append(dict(gear))
    elif how == "truncate":
        text = train_toml(spec)
        return text[:r.randint(1, len(text) - 1)]
    elif how == "shaft":                  # a shaft naming no member, or both gears of a mesh
        members = r.choice(([gear["number"], 99], spec["mesh"][0]["gears"],
                            [gear["number"], gear["number"]]))
        spec.setdefault("shaft", []).append({"members": list(members)})
    elif how == "kind":
        spec["mesh"][0]["kind"] = r.choice(("helical", "Internal", ""))
    else:
        spec["input"]["sense"] = True
    return train_toml(spec)


def generate(rng: random.Random, family: str | None = None) -> tuple[str, str]:
    """One random case: ``(family, toml_text)``; ``family`` picks one, else any."""
    family = family or rng.choice(FAMILIES)
    t = build(rng, family)
    if rng.random() < MALFORMED:
        return family, _malform(rng, t)
    if rng.random() < DEGENERATE:
        _degenerate(rng, t)
    return family, train_toml(t.spec, _comments(t))


# ----- running a case -----------------------------------------------------------------------
def expectations(text: str) -> dict[str, Any]:
    """The oracle a file's comments carry: ``expect``, each member's exact speed and
    torque, each mesh number (a float); empty for a file with none."""
    out: dict[str, Any] = {}
    for m in re.finditer(r"^# oracle (\S+) = (\S+)$", text, re.M):
        key, value = m.groups()
        if key == "expect":
            out[key] = value
        elif key.startswith(("omega", "torque")):
            out[key] = Fraction(value)
        else:
            out[key] = float(value)
    return out


def _want(name: str, o: dict[str, Any]) -> Fraction | None:
    parts = name.split("/")
    if len(parts) == 2:
        return o[parts[0]] / o[parts[1]] if parts[0] in o and parts[1] in o else None
    return o.get(name)


def contradictions(doc: dict[str, Any], o: dict[str, Any]) -> list[str]:
    """The quantities of a results document the oracle contradicts."""
    bad = []
    speeds = [abs(v) for k, v in o.items() if k.startswith("omega")]
    for name, q in doc["quantities"].items():
        if name in o and not name.startswith(("omega", "torque")):
            want = o[name]           # a drawn length or angle: a few roundings of its size
            if abs(q["value"] - want) > 1e-9 * max(abs(want), 1e-300):
                bad.append(f"{name} = {q['value']!r}, the formula gives {want!r}")
            continue
        want = _want(name, o)
        if want is None:
            continue
        if Fraction(q["exact"]) != want:
            bad.append(f"{name} = {q['exact']}, the closed form gives {want}")
        if "velocity_diagram" in q:
            # read as a slope off drawn lines: a few roundings of the fastest's size (rad/s),
            # or of a ratio's own size (two slopes' quotient)
            per = 2 * math.pi / 60 if q.get("exact_unit", q.get("unit")) == "rpm" else 1.0
            size = max(abs(q["value"]), 1.0) if "/" in name else float(max(speeds)) * per
            if abs(q["velocity_diagram"]["value"] - q["value"]) > 1e-9 * size:
                bad.append(f"{name} by the velocity diagram = {q['velocity_diagram']['value']!r}")
    return bad


PLACES = (r"\bgears? \d+", r"\bmembers? \d+", r"\bthe arm \d+")
"""What a train's refusal may name to say where its fault is, besides the file:line."""


def oracle_wrongs(solution, text: str) -> list[str]:
    """What a solution that passed its checks still gets wrong by the file's oracle (none
    for a file without one); its terminal lines are made too, as the CLI prints them."""
    o = expectations(text)
    if o.get("expect") != "answer":
        return []
    solution.lines()
    return contradictions(solution.results, o)


def run_train_case(text: str | bytes, path: str | Path, *, render: bool = False) -> Outcome:
    """Run one case through tests/random_mechanisms.py's :func:`run_case` with the train's
    oracle and places: besides its outcomes, an answer to a file that must be refused is
    ``wrong``, and a refusal of a file the closed form answers ``refused-valid``."""
    got = run_case(text, path, render=render, oracle=oracle_wrongs, places=PLACES)
    words = text if isinstance(text, str) else text.decode("utf-8", "replace")
    expect = expectations(words).get("expect")
    if expect == "refused" and got.outcome == "ok":
        return Outcome("wrong", "answered a file that must be refused")
    if expect == "answer" and got.outcome == "refused":
        return Outcome("refused-valid", got.message)
    return got


def main(argv: list[str] | None = None) -> int:
    """Run a batch in this process; print the counts by outcome and family, and each case
    neither ok nor refused (kept in ``--keep``). Case n of seed s is
    ``generate(random.Random(f"{s}:{n}"))``, as benchmarks/robustness.py makes it."""
    ap = argparse.ArgumentParser(description=main.__doc__)
    ap.add_argument("--cases", type=int, default=2000)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--keep", type=Path, default=None, help="folder for the odd cases")
    ap.add_argument("--no-render", action="store_true")
    args = ap.parse_args(argv)
    counts, by_family = Counter(), Counter()
    start = time.perf_counter()
    with tempfile.TemporaryDirectory() as folder:
        for k in range(args.cases):
            family, text = generate(random.Random(f"{args.seed}:{k}"))
            got = run_train_case(text, Path(folder) / f"case-{k}.toml",
                                 render=not args.no_render)
            counts[got.outcome] += 1
            by_family[family, got.outcome] += 1
            if got.outcome not in ("ok", "refused"):
                print(f"case {k} ({family}): {got.outcome}: {got.message} {got.detail[-300:]}")
                if args.keep:
                    args.keep.mkdir(parents=True, exist_ok=True)
                    (args.keep / f"{got.outcome}-{k}.toml").write_text(
                        f"# {got.outcome}: {got.message}\n{text}", encoding="utf-8")
    print(f"{args.cases} cases, seed {args.seed}, {time.perf_counter() - start:.0f} s")
    for outcome in TRAIN_OUTCOMES:
        print(f"  {outcome:16} {counts[outcome]}")
    for family in FAMILIES:
        print(f"  {family:16} " + ", ".join(f"{o} {by_family[family, o]}"
                                            for o in TRAIN_OUTCOMES if by_family[family, o]))
    return 0 if set(counts) <= {"ok", "refused"} else 1


if __name__ == "__main__":
    raise SystemExit(main())
