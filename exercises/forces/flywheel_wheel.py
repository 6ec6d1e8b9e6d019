"""A flywheel file's ``[flywheel]`` table: the speeds it holds (the mean, the greatest and
least, C_s as the books write it, "±1 %") and the wheel given or asked (its moment of
inertia, a rim's mass, radius, section and share, a radius of gyration), in SI, each
failure one line at its file:line. :mod:`.flywheel_file` reads the diagram around it."""

from __future__ import annotations

import math
import re
from typing import Any

from tarsim.constructions.errors import InputError
from tarsim.constructions.units import LENGTH_UNITS

from ..table_file import Tables
from .loads_file import PRESSURES

__all__ = ["PERCENT", "speeds", "read_given_wheel", "read_length", "read_wheel"]

_WITH_UNIT = re.compile(r"\s*([-+]?(?:\d+(?:\.\d*)?|\.\d+)(?:[eE][-+]?\d+)?)\s*(\S+)\s*")
"""A number and its unit as the books write them: "0.6 m", "600 mm", "6 MPa"."""


def read_length(t: Tables, d: dict, key: str, table: str, what: str, metre: float,
                into: float = 1.0) -> float:
    """``d[key]``, a positive length in units of ``into`` m (metres unless told): a number
    in the file's length unit (``metre`` m each), or text with its own unit ("0.6 m",
    "600 mm"), as a book mixes a punch's holes in mm with its flywheel's radius in m. A
    length already in the unit asked is returned as given, not rounded through metres."""
    raw = d[key]
    m = _WITH_UNIT.fullmatch(raw) if isinstance(raw, str) else None
    if m is not None and m[2] in LENGTH_UNITS:
        v, size = t.number({key: m[1]}, key, table, what), LENGTH_UNITS[m[2]]
    else:
        try:
            v, size = t.number(d, key, table, what), metre
        except InputError:
            if not isinstance(raw, str):
                raise
            raise t.fail(f"{what} is a number in the file's length unit or a length with its "
                         f"unit ({', '.join(LENGTH_UNITS)}): \"0.6 m\"; got {raw!r:.40}",
                         table, key) from None
    if not v > 0 or not math.isfinite(v):
        raise t.fail(f"{what} must be positive, got {raw!r:.40}", table, key)
    return v if size == into else v * size / into


def _stress(t: Tables, fw: dict) -> float:
    """The rim's allowable hoop stress in Pa: a number in Pa, or "6 MPa" as the books give
    it (any unit a gas pressure takes)."""
    raw = fw["hoop_stress"]
    m = _WITH_UNIT.fullmatch(raw) if isinstance(raw, str) else None
    if isinstance(raw, str) and (m is None or m[2] not in PRESSURES):
        raise t.fail(f"the hoop stress is a number in Pa or a stress with its unit "
                     f"({', '.join(PRESSURES)}): \"6 MPa\"; got {raw!r:.40}",
                     "flywheel", "hoop_stress")
    if m is None and (isinstance(raw, bool) or not isinstance(raw, (int, float))):
        raise t.fail(f"the hoop stress is a number in Pa or \"6 MPa\"; got {raw!r:.40}",
                     "flywheel", "hoop_stress")
    # a number is in Pa, so a book's 6e6 is past a plain number's 1e6: read as it stands,
    # below 1e10 Pa (10 GPa, past any metal's strength)
    v = float(m[1]) * PRESSURES[m[2]] if m else float(raw)
    if not 0 < v < 1e10:
        raise t.fail(f"the hoop stress must be positive and below 1e10 Pa, got {raw!r:.40}",
                     "flywheel", "hoop_stress")
    return v


PERCENT = re.compile(r"\s*(±|\+/-|\+-)?\s*(\d+(?:\.\d*)?|\.\d+)\s*%\s*")
"""A speed's fluctuation as the books write it: "±1 %" (either way of the mean, 2 % in all)
or "3 %" (the total, (ω_max − ω_min)/ω)."""


def speeds(t: Tables, fw: dict, rad_s: float) -> dict[str, float]:
    """The mean speed and C_s as ``[flywheel]`` gives them: ``speed`` and ``speed_fluctuation``
    (a number, or "±1 %" or "2 %"), or two of the mean, greatest and least speeds, the mean
    the average of the other two as the books take it: C_s = (ω_max − ω_min)/ω."""
    out: dict[str, float] = {}
    given = {k: t.number(fw, k, "flywheel", what) * rad_s
             for k, what in (("speed", "the mean speed"), ("speed_max", "the greatest speed"),
                             ("speed_min", "the least speed")) if k in fw}
    for k, v in given.items():
        if not v > 0:
            raise t.fail(f"{k} must be positive, got {fw[k]:g}", "flywheel", k)
    if len(given) == 1 and "speed" not in given and "speed_fluctuation" not in fw:
        # The books' "300 rpm before riveting": one extreme alone, with the flywheel given,
        # the other follows from the energy it gives up, ΔE = ½·I·(ω1² − ω2²).
        (key,) = given
        if not ("inertia" in fw or "radius_of_gyration" in fw and "mass" in fw):
            raise t.fail(f"{key} alone needs the flywheel (inertia, or mass with "
                         "radius_of_gyration): the other speed follows from ΔE = ½I(ω1² − ω2²);"
                         " or give two of speed, speed_max and speed_min", "flywheel", key)
        return dict(given)
    if "speed_max" in given or "speed_min" in given:
        if len(given) != 2 or "speed_fluctuation" in fw:
            raise t.fail("the greatest and least speeds give the mean and C_s: give two of speed, "
                         "speed_max and speed_min, and no speed_fluctuation", "flywheel",
                         "speed_fluctuation" if len(given) == 2 else
                         ("speed_max" if "speed_max" in given else "speed_min"))
        mean = given.get("speed")
        if mean is None:
            high, low = given["speed_max"], given["speed_min"]
        elif "speed_max" in given:
            high, low = given["speed_max"], 2 * mean - given["speed_max"]
        else:
            high, low = 2 * mean - given["speed_min"], given["speed_min"]
        if not 0 < low < high:
            raise t.fail("the least speed must be positive and below the greatest, the mean "
                         "between them", "flywheel", "speed_min" if "speed_min" in given
                         else "speed_max")
        out["speed"] = (high + low) / 2
        out["speed_fluctuation"] = (high - low) / out["speed"]
        out["extremes_given"] = (high, low)
        return out
    if "speed" in given:
        out["speed"] = given["speed"]
    if "speed_fluctuation" in fw:
        raw = fw["speed_fluctuation"]
        m = PERCENT.fullmatch(raw) if isinstance(raw, str) else None
        if m is not None:
            cs = float(m[2]) / 100 * (2 if m[1] else 1)
        else:
            try:
                cs = t.number(fw, "speed_fluctuation", "flywheel",
                              "the coefficient of fluctuation of speed")
            except InputError:
                if not isinstance(raw, str):
                    raise
                raise t.fail(f"the fluctuation of speed is a number (C_s) or a percentage of "
                             f"the mean, \"±1 %\" or \"2 %\" (the total); got {raw!r:.40}",
                             "flywheel", "speed_fluctuation") from None
        if not 0 < cs < 2:
            raise t.fail(f"C_s = (ω_max − ω_min)/ω is positive and below 2 (a speed that "
                         f"stops), got {cs:g}", "flywheel", "speed_fluctuation")
        out["speed_fluctuation"] = cs
    return out


_GIVEN = ("speed", "speed_max", "speed_min", "speed_fluctuation", "inertia", "mass",
          "radius_of_gyration", "radius", "diameter")
"""What ``[flywheel]`` may hold with no diagram and no ΔE: the flywheel and its speeds."""


def read_given_wheel(t: Tables, fw: dict, metre: float, rad_s: float) -> dict[str, Any]:
    """A file with no diagram and no ΔE: the flywheel given (``inertia``, ``mass`` with
    ``radius_of_gyration``, or a rim's ``mass`` at its mean ``radius`` or ``diameter``) and
    the speeds it runs between, for ΔE = ½·I·(ω1² − ω2²), as the books' simplest flywheel
    is posed; in SI."""
    out = speeds(t, fw, rad_s)
    if "speed" not in out or "speed_fluctuation" not in out:
        raise t.fail("a flywheel file with no diagram gives the flywheel with its greatest and "
                     "least speeds (or the mean and speed_fluctuation), ΔE itself (delta_E = "
                     "…, J), or [turning_moment] power with energy_fluctuation (C_E)",
                     "flywheel", None)
    extra = [k for k in fw if k not in _GIVEN]
    if extra:
        raise t.fail(f"{extra[0]} needs ΔE from a diagram (or delta_E); with the flywheel and "
                     "its speeds alone, ΔE and C_s are what is found", "flywheel", extra[0])

    def positive(key: str, what: str) -> float:
        v = t.number(fw, key, "flywheel", what)
        if not v > 0:
            raise t.fail(f"{what} must be positive, got {v:g}", "flywheel", key)
        return v
    ways = [k for k in ("inertia", "radius_of_gyration", "radius", "diameter") if k in fw]
    if len(ways) != 1 or ("inertia" in fw) == ("mass" in fw):
        raise t.fail("give the flywheel once: inertia (kg·m²), or mass with radius_of_gyration,"
                     " or a rim's mass with its mean radius (or diameter)", "flywheel",
                     ways[1] if len(ways) > 1 else None)
    (way,) = ways
    if way == "inertia":
        out["inertia"] = positive("inertia", "the flywheel's moment of inertia")
        return out
    out["mass"] = positive("mass", "the flywheel's mass")
    k = read_length(t, fw, way, "flywheel", "the radius of gyration" if way ==
                    "radius_of_gyration" else "the rim's mean radius", metre) / (
                        2 if way == "diameter" else 1)
    out["radius_of_gyration" if way == "radius_of_gyration" else "radius"] = k
    out["inertia"] = out["mass"] * k * k
    return out


def read_wheel(t: Tables, fw: dict, metre: float, rad_s: float,
               diagram: dict) -> dict[str, Any]:
    """What the ``[flywheel]`` table ``fw`` gives and asks, in SI; ``diagram`` says how the
    turning moment was given (one given by its areas has no T(θ) to read at an angle)."""
    out: dict[str, Any] = {}

    def positive(key: str, what: str) -> float:
        v = t.number(fw, key, "flywheel", what)
        if not v > 0:
            raise t.fail(f"{what} must be positive, got {v:g}", "flywheel", key)
        return v

    out |= speeds(t, fw, rad_s)
    if "speed_fluctuation" in out and "radius_of_gyration" in fw and "mass" not in fw:
        # The books' "its radius of gyration is 0.5 m" with C_s: the flywheel is found, and
        # k is where its mass sits, m = I/k², as a rim's at its mean radius.
        clash = [k for k in ("radius", "diameter", "rim_speed", "rim_share", "hoop_stress")
                 if k in fw]
        if clash:
            raise t.fail(f"the radius of gyration places the flywheel's mass (m = I/k²): "
                         f"leave {clash[0]} out", "flywheel", clash[0])
        out["radius_of_gyration"] = read_length(t, fw, "radius_of_gyration", "flywheel",
                                                "the radius of gyration", metre)
        out["radius"] = out["radius_of_gyration"]
        fw = {k: v for k, v in fw.items() if k != "radius_of_gyration"}
    ways = [k for k in ("speed_fluctuation", "inertia", "radius_of_gyration") if k in fw]
    if "speed_fluctuation" not in fw and "speed_fluctuation" in out:
        ways.insert(0, "speed_max" if "speed_max" in fw else "speed_min")
    if len(ways) > 1:
        raise t.fail("give speed_fluctuation (or the greatest and least speeds: the flywheel is "
                     "found) or the flywheel (inertia, or mass with radius_of_gyration: its C_s "
                     "is found), one of them", "flywheel", ways[1])
    extreme = "speed_max" in out or "speed_min" in out
    rimmed = "rim_speed" in fw or "hoop_stress" in fw
    if ways and "speed" not in out and not extreme and not (rimmed and "speed_fluctuation" in fw):
        raise t.fail("a flywheel holds a speed: give the mean speed, speed = 300 with [units] "
                     "speed = \"rpm\" (or the rim's speed in m/s, rim_speed = 25, for its mass "
                     "alone)", "flywheel", None)
    rim = [k for k in ("diameter", "rim_speed", "rim_share", "density", "width_to_thickness",
                       "hoop_stress") if k in fw]
    if "speed_fluctuation" in out:
        if "hoop_stress" in fw:
            # The books' "the hoop stress is not to exceed 6 MPa": a thin rim's stress is
            # ρ·v², so its speed is v = √(σ/ρ), and its radius v/ω as a rim_speed's.
            clash = [k for k in ("rim_speed", "radius", "diameter", "mass") if k in fw]
            if clash:
                raise t.fail(f"the hoop stress fixes the rim's speed √(σ/ρ) and so its radius "
                             f"(v/ω) and mass: leave {clash[0]} out", "flywheel", clash[0])
            if "density" not in fw:
                raise t.fail("the hoop stress σ gives the rim's speed v = √(σ/ρ) with its "
                             "density: give density (kg/m³)", "flywheel", "hoop_stress")
            out["hoop_stress"] = _stress(t, fw)
            out["density"] = positive("density", "the rim's density (kg/m³)")
            out["rim_speed"] = math.sqrt(out["hoop_stress"] / out["density"])
        if "rim_speed" in fw or "hoop_stress" in fw:
            # The rim's speed v = ω·r gives its radius, and m·v² = I·ω² its mass.
            clash = [k for k in ("radius", "diameter", "mass") if k in fw]
            if clash:
                raise t.fail(f"the rim's speed fixes its radius (v/ω) and mass (ΔE/(C_s·v²)): "
                             f"leave {clash[0]} out", "flywheel", clash[0])
            if "hoop_stress" not in fw:
                out["rim_speed"] = positive("rim_speed", "the rim's mean speed (m/s)")
            if "speed" in out:
                out["radius"] = out["rim_speed"] / out["speed"]
            elif "width_to_thickness" in fw:
                raise t.fail("a rim's section needs its radius: give the mean speed too, its "
                             "radius v/ω", "flywheel", "width_to_thickness")
        if "radius" in fw and "diameter" in fw:
            raise t.fail("give the rim's mean radius or its diameter, not both", "flywheel",
                         "diameter")
        if "mass" in fw and ("radius" in fw or "diameter" in fw):
            raise t.fail("the rim's mass is found for a stated radius, or its radius for a "
                         "stated mass: give one", "flywheel",
                         "radius" if "radius" in fw else "diameter")
        if "mass" in fw:
            out["mass"] = positive("mass", "the rim's mass")
        for key, what, half in (("radius", "the rim's mean radius", 1),
                                ("diameter", "the rim's mean diameter", 2)):
            if key in fw:
                out["radius"] = read_length(t, fw, key, "flywheel", what, metre) / half
        if ("density" in fw) != ("width_to_thickness" in fw) and "hoop_stress" not in fw or (
                "density" in fw and "mass" not in out and "radius" not in out):
            raise t.fail("a rim's section comes from its density and width_to_thickness (b/t), "
                         "with its mass or mean radius: give them all", "flywheel",
                         "density" if "density" in fw else "width_to_thickness")
        if "rim_share" in fw:
            out["rim_share"] = positive("rim_share", "the rim's share of the flywheel's I")
            if out["rim_share"] > 1 or "rim_speed" in out and "speed" not in out:
                raise t.fail("rim_share is the part of I the rim gives (0.9 when the hub and arms "
                             "give a tenth), at most 1, with a radius, a mass, or a rim speed "
                             "with the mean speed", "flywheel", "rim_share")
        if "density" in fw and "width_to_thickness" in fw:
            out["density"] = positive("density", "the rim's density (kg/m³)")
            out["width_to_thickness"] = positive("width_to_thickness",
                                                 "the rim's width over its thickness")
        rim = []
    elif "inertia" in fw:
        out["inertia"] = positive("inertia", "the flywheel's moment of inertia")
    elif "radius_of_gyration" in fw:
        if "mass" not in fw:
            raise t.fail("a radius of gyration k needs the flywheel's mass: I = m·k²",
                         "flywheel", "radius_of_gyration")
        out["mass"] = positive("mass", "the flywheel's mass")
        out["radius_of_gyration"] = read_length(t, fw, "radius_of_gyration", "flywheel",
                                                "the radius of gyration", metre)
        out["inertia"] = out["mass"] * out["radius_of_gyration"] ** 2
    else:
        for key in ("mass", "radius"):
            if key in fw:
                raise t.fail(f"{key} is the rim's, for a flywheel found from speed_fluctuation "
                             "(or mass with radius_of_gyration); give that too", "flywheel", key)
    if rim:
        raise t.fail(f"{rim[0]} is the rim's, for a flywheel found from speed_fluctuation; give "
                     "that too", "flywheel", rim[0])
    if "at" in fw:
        raw = fw["at"] if isinstance(fw["at"], list) else [fw["at"]]
        out["at"] = tuple(math.radians(t.number({"at": a}, "at", "flywheel",
                                                "a crank angle (degrees)")) for a in raw)
        if "formula" not in diagram and "points" not in diagram:
            raise t.fail("a diagram given by its areas (or a punch) has no T(θ) to read at a "
                         "crank angle: "
                         "give torque = \"…\" or points, or leave at out", "flywheel", "at")
    return out
