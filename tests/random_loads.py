"""Random loaded linkages, degenerate and malformed ones included, each with an oracle of its
own: forces, friction, the turning moment and the flywheel, as the bundled catalog's forces/
exercises pose them.

The contract is tests/random_mechanisms.py's: every file either solves to finite numbers that
pass their checks, or is refused with one ``TarsimError`` line naming the file:line, a link,
a point or a position. A mechanism is drawn by random_mechanisms' builders (a four-bar, a
slider-crank, a slotted lever, now and then a six-bar or a contact the polygons do not take),
then loaded: masses on its links with their centres and inertias, forces at points (or a
resistance on a stroke), couples, gravity or none, friction at its slides and its pins, a
coefficient of speed fluctuation or a flywheel. Its [ask] names joint forces, the driving
torque and the engine's efforts.

The oracle (:func:`oracle`) holds what is printed to the balance of energy, which no joint
force enters and which it finds by its own finite differences of the mechanism's positions:
at each solved position of a frictionless mechanism, the driving torque T satisfies

    T·ω = d(KE)/dt + d(PE)/dt − Σ F·v − Σ M·ω_link,

KE = ½Σ m·v_G² + ½Σ I·ω², PE = Σ m·g·y_G, with KE = K(θ)·ω² and so d(KE)/dt = K′·ω³ +
2K·ω·α. Round a turn (``turning_moment``) it holds each step the same way, and the reading:
the greatest fluctuation of energy must bound the running energy summed here from the same
torques, a torque said steady (ΔE = 0) may swing no more than its loads' rounding, and the
flywheel must be ΔE/(C_s·ω²). A four-bar of S + L = P + Q passes a change point every turn,
where it may go on in either assembly: its turn must not be read at all.

Run ``python tests/random_loads.py --cases 2000 --seed 1`` for the counts by outcome.
"""

from __future__ import annotations

import math
import random
import sys
import zlib
from pathlib import Path
from typing import Any

sys.path.insert(0, str(Path(__file__).resolve().parent))

import random_mechanisms as rm          # noqa: E402
from random_mechanisms import Outcome, run_case as _run_case   # noqa: E402
from random_rotors import run_many      # noqa: E402

__all__ = ["FAMILIES", "generate", "oracle", "run_case"]

FAMILIES = ("four-bar", "slider-crank", "slotted-lever", "unsupported")
"""The mechanisms the force polygons draw, and the ones they refuse (six-bars, contacts)."""

MALFORMED = 0.08
"""The share of cases whose loads are broken on purpose."""

TURN_EVERY = 4
"""One case in this many is also swept round its turn (turning moment and flywheel)."""


# ----- loading a mechanism -------------------------------------------------------------------
def _moving(spec: dict[str, Any]) -> list[dict[str, Any]]:
    return [k for k in spec.get("links", []) if k.get("number") != 1]


def _force_names(spec: dict[str, Any]) -> list[str]:
    """F_ij of each pin (a point two links share, or a link's point on the frame), F and T of
    each slide, and T of the driver, read off the spec."""
    at: dict[str, set[int]] = {}
    for p in spec.get("frame", {}):
        at.setdefault(p, set()).add(1)
    for k in spec.get("links", []):
        for p in k["points"]:
            at.setdefault(p, set()).add(k["number"])
    names = []
    for links in at.values():
        links = sorted(links)
        names += [f"F_{links[0]}{n}" for n in links[1:]]
    for s in spec.get("sliders", []):
        on = s.get("on", 1)
        names.append(f"F_{on}{s['link']}")
        if s.get("kind", "block") == "block":
            names.append(f"T_{on}{s['link']}")
    names.append(f"T{spec['input']['link']}")
    return list(dict.fromkeys(names))


def _loads(c: rm._Case, spec: dict[str, Any]) -> dict[str, Any]:
    """The [forces], [[mass]], [[force]] and [[couple]] tables for ``spec``'s mechanism."""
    r = c.rng
    settings: dict[str, Any] = {}
    if r.random() < 0.8:
        settings["gravity"] = r.random() < 0.7
    roll = r.random()
    if roll < 0.25:
        settings["speed_fluctuation"] = r.choice([0.05, 0.01, 0.2, 1e-4])
    elif roll < 0.35:
        settings["flywheel"] = r.choice([2.5, 0.1, 50.0])
    if r.random() < 0.25:
        settings["friction"] = r.choice([0.1, 0.05, 0.3, 0.0, 1.0])
    if r.random() < 0.15:
        settings["friction_circle"] = c.length(r.choice([0.01, 0.002, 0.05]))
    masses = []
    for k in _moving(spec):
        if r.random() < 0.75:
            t: dict[str, Any] = {"link": k["number"], "mass": round(r.uniform(0.1, 10), 3)}
            points = k["points"]
            t["centre"] = r.choice(["mid"] * (len(points) > 1) + list(points)
                                   + [[c.length(r.uniform(-0.2, 1.0)),
                                       c.length(r.uniform(-0.1, 0.1))]])
            blocked = any(s.get("on", 1) == 1 and s["link"] == k["number"]
                          and s.get("kind", "block") == "block"
                          for s in spec.get("sliders", []))
            if blocked and len(points) < 2 and r.random() < 0.3:
                pass            # a piston or ram: it does not turn, so needs no inertia
            elif r.random() < 0.15:
                t["radius_of_gyration"] = c.length(r.uniform(0.02, 0.3))
            elif len(points) < 2 or r.random() < 0.6:
                t["inertia"] = round(t["mass"] * c.length(r.uniform(0.05, 0.5)) ** 2 / 12, 12) \
                    or 1e-6
            masses.append(t)
    forces = []
    for _ in range(r.choice([0, 1, 1, 2])):
        k = r.choice(_moving(spec))
        t = {"link": k["number"], "name": r.choice(["P", "gas force", "load", ""])}
        guided = [s for s in spec.get("sliders", []) if s.get("on", 1) == 1
                  and s["link"] == k["number"]]
        if guided and r.random() < 0.2:
            # a gas pressure on the piston's bore or area, as the books give it
            t["point"] = guided[0]["point"]
            t["pressure"] = r.choice([f"{round(r.uniform(0.1, 5), 3)} MPa",
                                      f"{round(r.uniform(1, 50), 2)} bar",
                                      round(r.uniform(-2e5, 3e6), 1)])
            bore = c.length(r.uniform(0.02, 0.2))
            if r.random() < 0.5:
                t["bore"] = bore
            else:
                t["area"] = round(math.pi * bore * bore / 4, 6)
        elif guided and r.random() < 0.5:
            t["point"] = guided[0]["point"]
            t["resist"] = round(r.uniform(10, 5000), 1)
            t["stroke"] = r.choice(["both", "slow", "fast"])
        else:
            t["point"] = r.choice(list(k["points"]) + [[c.length(r.uniform(0, 1)),
                                                        c.length(r.uniform(-0.2, 0.2))]])
            t["force"] = [round(r.uniform(-5000, 5000), 1), round(r.uniform(-5000, 5000), 1)]
        forces.append(t)
    couples = [{"link": r.choice(_moving(spec))["number"],
                "moment": round(r.uniform(-50, 50), 2), "name": "load torque"}
               for _ in range(r.choice([0, 0, 1]))]
    if not (masses or forces or couples) and r.random() < 0.8:
        couples = [{"link": _moving(spec)[-1]["number"], "moment": 10.0}]
    return {"forces": settings, "mass": masses, "force": forces, "couple": couples}


def _malform(r: random.Random, spec: dict[str, Any], loads: dict[str, Any]) -> None:
    """Break the loads one way on purpose."""
    how = r.choice(["zero-mass", "negative-inertia", "frame-link", "no-link", "bad-point",
                    "bad-centre", "both-flywheel", "friction-huge", "circle-negative",
                    "resist-and-force", "stroke-off-guide", "bad-stroke", "driver",
                    "gravity-number", "unknown-key", "one-point-no-inertia", "no-loads",
                    "nan-force", "string-moment", "huge-mass"])
    masses, forces = loads["mass"], loads["force"]
    k = _moving(spec)[0]
    if how == "zero-mass":
        masses.append({"link": k["number"], "mass": 0})
    elif how == "negative-inertia":
        masses.append({"link": k["number"], "mass": 1.0, "inertia": -0.1})
    elif how == "frame-link":
        loads["couple"].append({"link": 1, "moment": 5.0})
    elif how == "no-link":
        forces.append({"link": 9, "point": "A", "force": [1.0, 0.0]})
    elif how == "bad-point":
        forces.append({"link": k["number"], "point": "Z9", "force": [1.0, 0.0]})
    elif how == "bad-centre":
        masses.append({"link": k["number"], "mass": 1.0, "centre": r.choice(["Z9", 3, [1]])})
    elif how == "both-flywheel":
        loads["forces"].update(speed_fluctuation=0.05, flywheel=2.0)
    elif how == "friction-huge":
        loads["forces"]["friction"] = r.choice([2.0, 2.5, -0.1])
    elif how == "circle-negative":
        loads["forces"]["friction_circle"] = -1.0
    elif how == "resist-and-force":
        forces.append({"link": k["number"], "point": k["points"][-1], "resist": 10.0,
                       "force": [1.0, 0.0]})
    elif how == "stroke-off-guide":
        forces.append({"link": k["number"], "point": k["points"][-1], "resist": 10.0,
                       "stroke": "slow"})
    elif how == "bad-stroke":
        forces.append({"link": k["number"], "point": k["points"][-1], "resist": 10.0,
                       "stroke": "cutting"})
    elif how == "driver":
        loads["forces"]["driver"] = 3
    elif how == "gravity-number":
        loads["forces"]["gravity"] = 9.81
    elif how == "unknown-key":
        masses.append({"link": k["number"], "mass": 1.0, "colour": "red"})
    elif how == "one-point-no-inertia":
        one = [j for j in _moving(spec) if len(j["points"]) == 1]
        if one:
            masses.append({"link": one[0]["number"], "mass": 1.0})
    elif how == "no-loads":
        loads.update(mass=[], force=[], couple=[])
    elif how == "nan-force":
        forces.append({"link": k["number"], "point": k["points"][0],
                       "force": [float("nan"), 1.0]})
    elif how == "string-moment":
        loads["couple"].append({"link": k["number"], "moment": "5"})
    elif how == "huge-mass":
        masses.append({"link": k["number"], "mass": 1e7})


def _loads_toml(loads: dict[str, Any]) -> str:
    out = []
    if loads["forces"]:
        out += ["", "[forces]"] + [f"{k} = {rm._val(v)}" for k, v in loads["forces"].items()]
    for table in ("mass", "force", "couple"):
        for t in loads[table]:
            out += ["", f"[[{table}]]"] + [f"{rm._key(k)} = {rm._val(v)}" for k, v in t.items()]
    return "\n".join(out) + "\n"


def generate(rng: random.Random, family: str | None = None) -> tuple[str, str]:
    """One random case: ``(family, toml_text)``; ``family`` picks one, else any."""
    family = family or rng.choice(FAMILIES)
    c = rm._Case(rng)
    base = rng.choice(["six-bar", "contact"]) if family == "unsupported" else family
    spec = rm.BUILDERS[base](c)
    names = _force_names(spec)
    efforts = ["piston_effort", "wall_thrust", "crank_effort", "turning_moment"] \
        if family == "slider-crank" else ["crank_effort"]
    roll = rng.random()
    if roll < 0.6:
        find = names + rng.sample(efforts, rng.randint(0, len(efforts)))
    elif roll < 0.9:
        find = rng.sample(names, rng.randint(1, len(names)))
        find.append(f"T{spec['input']['link']}")
    else:
        find = rng.sample(names + efforts + ["F_99", "T7", "piston_effort"], 3)
    ask = spec.get("ask") or {}
    spec["ask"] = {"find": list(dict.fromkeys(find)), "methods": ["polygon"]}
    if "at" in ask and rng.random() < 0.5:
        spec["ask"]["at"] = ask["at"]
    loads = _loads(c, spec)
    if rng.random() < MALFORMED:
        _malform(rng, spec, loads)
    text = rm.to_toml(spec) + _loads_toml(loads)
    if rng.random() < 0.01:
        text = text[:rng.randint(1, len(text) - 1)]
    return family, text


# ----- the oracle ----------------------------------------------------------------------------
AGREE = 1e-6
"""How near, relative to the largest power term, the driving torque must come to the energy
balance: the finite differences (steps of 1e-3 rad, fourth-order stencils) leave some 1e-10,
and a wrong load, sign or lever arm moves it by its own size."""

SMOOTH = 1e-4
"""How near, relative to the largest power term, two step sizes' torques must agree for the
stencil to be trusted: a position within a step of a dead point, a change point or a
branch's end is skipped, not judged."""


def _state(mech, drive, theta: float, loads):
    """What the energy needs at input angle ``theta``: each massive link's centre and angle,
    and each loaded point and couple's link angle, from the reference solver's positions."""
    from tarsim.constructions.model import Drive
    from tarsim.constructions.reference import solver
    from tarsim.constructions.reference.kinetostatics import world_point

    kin = solver.solve(mech.with_drive(Drive(drive.link, theta, drive.omega, drive.alpha)))
    angle = lambda n: kin.angles.get(n, 0.0)       # noqa: E731 - the frame's is 0
    centres = [world_point(kin, mech, m.link, m.centre) for m in loads.masses]
    points = [world_point(kin, mech, f.link, f.point) for f in loads.forces]
    return ([c for xy in centres for c in xy] + [angle(m.link) for m in loads.masses]
            + [c for xy in points for c in xy] + [angle(c.link) for c in loads.couples])


def _derivative(mech, drive, loads, theta: float, h: float) -> tuple[list[float], list[float]]:
    """The state and its θ-derivative by the five-point stencil of step ``h``."""
    s = [_state(mech, drive, theta + k * h, loads) for k in (-2, -1, 0, 1, 2)]
    # The links' angles (after the centres' coordinates, and last) are taken the short way
    # round from the middle sample: one may wrap at ±π between samples.
    n, f = len(loads.masses), len(loads.forces)
    angles = set(range(2 * n, 3 * n)) | set(range(3 * n + 2 * f, len(s[2])))
    for row in s:
        for i in angles:
            row[i] = s[2][i] + math.remainder(row[i] - s[2][i], math.tau)
    d = [(a - 8 * b + 8 * c - e) / (12 * h) for a, b, _, c, e in zip(*s)]
    return s[2], d


def energy_torque(mech, loads, theta: float, omega: float, alpha: float, *,
                  dissipated: float | None = None) -> tuple[float, float] | None:
    """The driving torque (N·m, CCW +) the balance of energy gives at ``theta``, and how far
    from it a torque may be: :data:`AGREE` of the largest power term over ω, or ten times
    what halving or doubling the finite differences' step moves it, if more. With friction
    the driver also makes good what the joints dissipate, ``dissipated`` (W, Σ μ·|N|·|v| of
    their pushes, which no energy gives), a power term of its own. None where ω is 0,
    friction takes power not given, or the positions are not smooth here (the two steps
    disagree by more than :data:`SMOOTH` of the largest term: a dead point or a branch's end
    within reach of the stencil)."""
    from tarsim.constructions.errors import TarsimError

    if omega == 0.0 or (loads.friction or loads.friction_circle) and dissipated is None:
        return None
    lost = dissipated or 0.0
    try:
        (mid, scale), (fine, _), (coarse, _) = (
            _energy_torque(mech, loads, theta, omega, alpha, h, lost)
            for h in (1e-3, 5e-4, 2e-3))
    except TarsimError:
        return None
    # Truncation shrinks as the step does and rounding grows: the three steps' spread
    # bounds what the stencil cannot resolve, once it shrinks as a fourth-order stencil's
    # does (16 times a halving); one that shrinks slower has a dead point within reach.
    spread = max(abs(mid - fine), abs(mid - coarse))
    if not all(map(math.isfinite, (mid, fine, coarse))) or spread > SMOOTH * scale:
        return None
    if spread > 1e-9 * scale and abs(coarse - mid) < 4 * abs(mid - fine):
        return None
    return mid, max(AGREE * scale, 10 * spread)


def _energy_torque(mech, loads, theta: float, omega: float, alpha: float, h: float,
                   lost: float = 0.0) -> tuple[float, float]:
    """The balance of energy's torque with finite differences of step ``h`` and the power
    ``lost`` to friction, and the size of its largest term over ω."""
    drive = mech.drive
    _, d = _derivative(mech, drive, loads, theta, h)
    k = [_kinetic(loads, _derivative(mech, drive, loads, theta + j * h, h)[1])
         for j in (-2, -1, 1, 2)]
    dk = (k[0] - 8 * k[1] + 8 * k[2] - k[3]) / (12 * h)
    n = len(loads.masses)
    # The terms of T·ω: d(KE)/dt, d(PE)/dt, then each external power (forces, couples).
    terms = [dk * omega ** 3 + 2 * _kinetic(loads, d) * omega * alpha]
    terms += [m.mass * loads.gravity * d[2 * i + 1] * omega for i, m in enumerate(loads.masses)]
    base = 3 * n
    for j, f in enumerate(loads.forces):
        vx, vy = d[base + 2 * j] * omega, d[base + 2 * j + 1] * omega
        if f.resist:
            speed = math.hypot(vx, vy)
            moving = speed > 0.0 and (f.along is None or vx * f.along[0] + vy * f.along[1] > 0)
            terms.append(f.resist * speed if moving else 0.0)
        else:
            terms.append(-(f.force[0] * vx + f.force[1] * vy))
    base += 2 * len(loads.forces)
    terms += [-c.moment * d[base + j] * omega for j, c in enumerate(loads.couples)]
    terms.append(lost)
    return math.fsum(terms) / omega, max(abs(t) for t in terms) / abs(omega)


def _loads_scale(mech, loads) -> float:
    """The size of the loads themselves (N): each weight and inertia force, each force."""
    from tarsim.constructions.reference import solver
    from tarsim.constructions.reference.kinetostatics import load_scale

    return load_scale(mech, solver.solve(mech), loads, _size(mech))


def _size(mech) -> float:
    """The mechanism's size at its position (m): its largest distance between two points."""
    from tarsim.constructions.reference import solver

    xy = list(solver.solve(mech).points.values())
    return max([math.dist(p, q) for p in xy for q in xy] + [0.0])


def _kinetic(loads, d: list[float]) -> float:
    """K(θ), the kinetic energy over ω²: ½Σ m·|G′|² + ½Σ I·φ′²."""
    n = len(loads.masses)
    return 0.5 * math.fsum(m.mass * (d[2 * i] ** 2 + d[2 * i + 1] ** 2) + m.inertia
                           * d[2 * n + i] ** 2 for i, m in enumerate(loads.masses))


def oracle(solution, text: str) -> list[str]:
    """What the solved ``solution`` gets wrong by the balance of energy, at its positions and
    (one case in :data:`TURN_EVERY`, or when it asks for a flywheel) round its turn."""
    from tarsim.constructions.model import Drive

    ex = solution.exercise
    mech, loads = ex.mechanism, ex.loads
    if loads is None:
        return []           # a file cut before its loads: a linkage, held by its own checks
    wrong = []
    doc = solution.results
    d = mech.drive.link
    for p in doc.get("positions", []):
        q = p.get("quantities", {}).get(f"T{d}")
        if q is None:
            continue
        i = p["input"]
        theta = math.radians(i["angle_deg"])
        m = mech.with_drive(Drive(d, theta, i["omega"], i.get("alpha") or 0.0))
        got = energy_torque(m, loads, theta, i["omega"], i.get("alpha") or 0.0)
        if got is None:
            continue
        want, slack = got
        # tarsim says a torque within 1e-12 of its scale (the largest joint force, or load,
        # times the mechanism's size) as 0, the rounding of the forces in play.
        if q["value"] == 0:
            forces = [v["value"] for k, v in p["quantities"].items() if k.startswith("F_")]
            slack = max(slack, 1e-12 * max(forces + [_loads_scale(m, loads)]) * _size(m))
        if abs(q["value"] - want) > slack:
            wrong.append(f"T{d} = {q['value']:.9g} N·m at θ{d} = {i['angle_deg']:.6g}°, the "
                         f"balance of energy {want:.9g} (±{slack:.3g})")
    if loads.speed_fluctuation or loads.flywheel or zlib.crc32(text.encode()) % TURN_EVERY == 0:
        wrong += _turn_wrongs(ex)
    return wrong


def _turn_wrongs(ex, steps: int = 72) -> list[str]:
    """The turning moment round the turn: each of a few steps against the energy, the
    reading's ΔE against the running energy, the flywheel against ΔE/(C_s·ω²), and its
    files free of nan and inf."""
    from tarsim.constructions.errors import TarsimError
    from tarsim.constructions.model import Drive
    from tarsim.exercises.forces.turning_moment import POWER_AGREE, moment_files, turning_moment

    try:
        tm = turning_moment(ex, steps)
    except TarsimError as e:
        message = str(e)
        return [] if "\n" not in message else [f"turning moment refused in lines: {message!r}"]
    wrong = []
    if not tm.power_miss <= POWER_AGREE:
        return wrong                 # said: the CLI exits 3 on it
    mech, loads = ex.mechanism, ex.loads
    if not tm.gaps and _change_point_four_bar(mech):
        wrong.append("the turning moment is read round a change-point four-bar (S + L = "
                     "P + Q): its turn passes a change point, where it may go on in either "
                     "assembly")
    drive = mech.drive
    sense = 1.0 if drive.omega >= 0 else -1.0
    for k in range(0, steps, steps // 6):
        t = tm.torques[k]
        if t is None:
            continue
        theta = drive.angle + sense * tm.angles[k]
        m = mech.with_drive(Drive(drive.link, theta, drive.omega, 0.0))     # steady speed
        got = energy_torque(m, loads, theta, drive.omega, 0.0)
        if got is None:
            continue
        want, slack = got
        # A torque rounds at the size of the loads it is made of times the mechanism's.
        slack = max(slack, 64 * sys.float_info.epsilon * _loads_scale(m, loads) * _size(m))
        if abs(sense * t - want) > slack:
            wrong.append(f"turning moment at θ = {math.degrees(theta):.6g}°: "
                         f"{sense * t:.9g} N·m, the balance of energy at steady speed "
                         f"{want:.9g} (±{slack:.3g})")
    r = tm.reading
    if r is not None:
        step = 2 * math.pi / steps
        mean = math.fsum(tm.torques) / steps
        running, energy = [0.0], 0.0
        for a, b in zip(tm.torques, tm.torques[1:] + tm.torques[:1]):
            energy += (a + b - 2 * mean) * step / 2
            running.append(energy)
        spread = max(running) - min(running)
        reach = max(abs(t - mean) for t in tm.torques) * step
        wobble = max(abs(t - mean) for t in tm.torques)
        steady = wobble <= tm.noise                                     # said as ΔE = 0
        if not (steady and r.delta_e == 0.0
                or spread - 1e-9 * (spread + reach) <= r.delta_e <= spread + reach):
            wrong.append(f"ΔE = {r.delta_e:.9g} J, the running energy spans {spread:.9g} J")
        bound = _rounding_bound(ex, tm) if steady and r.delta_e == 0.0 else math.inf
        if wobble > bound:
            wrong.append(f"ΔE = 0, but the torque swings {wobble:.9g} N·m off its mean, "
                         f"beyond the rounding of its loads ({bound:.3g} N·m)")
        if loads.speed_fluctuation and r.delta_e == 0.0:
            if not any(ln.startswith("no flywheel is needed") for ln in tm.lines()):
                wrong.append(f"ΔE = 0, but the flywheel is said as {tm.lines()[1:2]}")
        elif loads.speed_fluctuation:
            want = r.delta_e / (loads.speed_fluctuation * tm.omega ** 2)
            said = [ln for ln in tm.lines() if ln.startswith("flywheel for")]
            if not said or _number_after(said[0], "I = ΔE/(C_s·ω²) = ") != _g(want):
                wrong.append(f"flywheel printed {said}, ΔE/(C_s·ω²) = {want:.6g} kg·m²")
    for name, body in moment_files(tm).items():
        if isinstance(body, str) and rm._NONFINITE.search(body):
            wrong.append(f"{name} prints {rm._NONFINITE.search(body).group(0)!r}")
    for line in tm.lines():
        if rm._NONFINITE.search(line):
            wrong.append(f"the turning moment prints {line!r}")
    return wrong


def _change_point_four_bar(mech) -> bool:
    """True for a four-bar of S + L = P + Q (Grashof's closed form): every turn of its
    input passes the position where its four links lie in one line, a change point."""
    from tarsim.constructions.errors import TarsimError
    from tarsim.constructions.reference.rotatability import grashof_class

    try:
        gc = grashof_class(mech)
    except TarsimError:
        return False
    return gc is not None and gc.kind == "change-point"


def _rounding_bound(ex, tm) -> float:
    """The most a turn's torques may swing by rounding alone (N·m): what its two ways of
    finding the torque disagree by, or what a torque rounds at by this oracle's own rule
    (64 roundings of the loads' size times the mechanism's) at its worst step."""
    from tarsim.constructions.model import Drive

    mech = ex.mechanism
    drive = mech.drive
    sense = 1.0 if drive.omega >= 0 else -1.0
    bound = tm.power_miss * tm.biggest
    for turned in tm.angles:
        m = mech.with_drive(Drive(drive.link, drive.angle + sense * turned, drive.omega, 0.0))
        bound = max(bound, 64 * sys.float_info.epsilon * _loads_scale(m, ex.loads) * _size(m))
    return bound


def _number_after(line: str, lead: str) -> str:
    at = line.find(lead)
    return line[at + len(lead):].split()[0] if at >= 0 else ""


def _g(x: float) -> str:
    return f"{x:.6g}"


# ----- running a case ------------------------------------------------------------------------
PLACES = ()
"""What a loads refusal may name besides a file:line, a link, a point or a position: none."""


def run_case(text: str | bytes, path: str | Path, *, render: bool = False) -> Outcome:
    """Solve ``text`` through the API (random_mechanisms.run_case) with the energy oracle."""
    return _run_case(text, path, render=render, oracle=oracle, places=PLACES)


if __name__ == "__main__":
    sys.exit(run_many(generate, run_case, FAMILIES, "loads"))
