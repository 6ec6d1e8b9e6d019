"""Balancing: nearly balanced rotors, the polygon's closing side tiny beside the others.

Two rotors, each with one mass a part δ heavier than balance needs:

- **static** (one plane): three masses of m·r = 0.1 kg·m at 0°, 120° and 240°, the last
  (1 + δ) times as heavy; the closing side, −Σ mᵢrᵢ, is about 0.1·δ kg·m;
- **dynamic** (two planes A at 0 and B at 0.5 m): four masses whose couples about A
  nearly cancel (two pairs at 0.1 m and 0.3 m, the far one of each pair a part δ heavier),
  so plane B's product, from the couple polygon's closing side, is tiny.

tarsim's polygons (``constructions/balancing/polygons.py``) lay the products head to tail
and read the closing side; the float reference (``constructions/reference/balance.py``)
sums them. Each is measured against the same sums at 50 digits (mpmath) of the masses'
float numbers. The conditioning is the closing side over the perimeter it closes; the
tolerance is the polygon's own rounding bound (``polygons.rounding``: 8 eps·(n + 1)·Σ|mᵢrᵢ|)
over the closing side. Below that bound the polygon closes on itself, and tarsim says the
plane needs no mass: then the row's error is the true product's size against the bound.
"""

from __future__ import annotations

import math
from pathlib import Path

import mpmath

from tarsim.constructions.balancing.polygons import draw_balance, rounding
from tarsim.constructions.balancing.rotor import Mass, Plane, Rotor
from tarsim.constructions.reference.balance import resultant, two_planes

from .chapter_rows import ChapterStudy, Row
from .svgplot import Curve, write_plot
from .timing import median_time

__all__ = ["static_rotor", "dynamic_rotor", "exact_products", "balance_study"]

MR = 0.1
"""Each mass's mass–radius product (kg·m): 1 kg at 100 mm."""


def static_rotor(delta: float) -> Rotor:
    """Three masses at 120°, the last (1 + δ) times as heavy, balanced in one plane."""
    masses = tuple(Mass(str(k + 1), 1.0 + (delta if k == 2 else 0.0), 0.1,
                        2 * math.pi * k / 3) for k in range(3))
    return Rotor(masses, (Plane("A", 0.0, radius=0.1),), speed=100.0)


def dynamic_rotor(delta: float) -> Rotor:
    """Four masses in two pairs, 1 kg at 100 mm, at 0° and 180° (0.1 m) and at 90° and
    270° (0.3 m); the second of each pair (1 + δ) times as heavy: plane B at 0.5 m gets a
    product of about 0.1·δ·(0.1 ... 0.3)/0.5."""
    masses = (Mass("1", 1.0, 0.1, 0.0, 0.1), Mass("2", 1.0 + delta, 0.1, math.pi, 0.1),
              Mass("3", 1.0, 0.1, math.pi / 2, 0.3),
              Mass("4", 1.0 + delta, 0.1, 3 * math.pi / 2, 0.3))
    return Rotor(masses, (Plane("A", 0.0, radius=0.1), Plane("B", 0.5, radius=0.1)),
                 speed=100.0)


def exact_products(rotor: Rotor) -> dict[str, tuple]:
    """Each balancing plane's m·r (kg·m), at 50 digits of the rotor's float numbers."""
    with mpmath.workdps(50):
        mr = [(mpmath.mpf(m.mass) * mpmath.mpf(m.radius) * mpmath.cos(mpmath.mpf(m.angle)),
               mpmath.mpf(m.mass) * mpmath.mpf(m.radius) * mpmath.sin(mpmath.mpf(m.angle)),
               mpmath.mpf(m.plane)) for m in rotor.masses]
        sx, sy = sum(x for x, _, _ in mr), sum(y for _, y, _ in mr)
        if len(rotor.planes) == 1:
            return {rotor.planes[0].name: (-sx, -sy)}
        a, b = (mpmath.mpf(p.position) for p in rotor.planes)
        bx = -sum(x * (z - a) for x, _, z in mr) / (b - a)
        by = -sum(y * (z - a) for _, y, z in mr) / (b - a)
        return {rotor.planes[0].name: (-sx - bx, -sy - by), rotor.planes[1].name: (bx, by)}


def _error(got, want) -> float:
    """|got − want| (kg·m), at the exact value's precision."""
    with mpmath.workdps(50):
        return float(mpmath.hypot(mpmath.mpf(got[0]) - want[0], mpmath.mpf(got[1]) - want[1]))


def balance_study(out: Path, *, quick: bool = False) -> ChapterStudy:
    """Rows for δ from 0.1 to 1e-16, each rotor: the polygon's and the reference's closing
    side against 50 digits, the rounding bound, and the polygon's time."""
    deltas = (1e-1, 1e-5, 1e-10, 1e-14, 1e-16) if quick else \
        (1e-1, 1e-3, 1e-5, 1e-7, 1e-9, 1e-11, 1e-13, 1e-14, 1e-15, 1e-16)
    rows, curves = [], {"static: polygon": [], "static: float reference": [],
                        "dynamic, plane B: polygon": [], "dynamic, plane B: float reference": []}
    for kind, make, plane in (("static", static_rotor, "A"), ("dynamic, plane B", dynamic_rotor,
                                                               "B")):
        for delta in deltas:
            rotor = make(delta)
            want = exact_products(rotor)[plane]
            size = float(mpmath.hypot(*want))
            drawn = draw_balance(rotor)
            sizes = [m.mass * m.radius for m in rotor.masses]
            if plane == "B":
                sizes = [m.mass * m.radius * (abs(m.plane) + abs(rotor.planes[0].position))
                         for m in rotor.masses]
            bound = rounding(sizes) / (rotor.planes[1].position if plane == "B" else 1.0)
            perimeter = math.fsum(m.mass * m.radius for m in rotor.masses)
            t = median_time(lambda r=rotor: draw_balance(r), 5 if quick else 30)
            label = f"{kind}, δ = {delta:.0e}"
            if plane in drawn.none:
                rows.append(Row(label, f"m·r in {plane}: none needed (the polygon closes; "
                                "error: the true |m·r| / perimeter)",
                                size / perimeter, size / perimeter, bound / perimeter, t,
                                "the true product is within the polygon's rounding"
                                if size <= bound else "**a product beyond rounding dropped**"))
            else:
                err = _error(drawn.product(plane), want) / size
                rows.append(Row(label, f"m·r in {plane}, polygon", size / perimeter, err,
                                bound / size, t, f"|m·r| = {size:.2e} kg·m"))
                curves[f"{kind}: polygon"].append((size / perimeter, max(err, 1e-17)))
            ref = (resultant(rotor.masses) if plane == "A" else
                   two_planes(rotor.masses, 0.0, 0.5)[1])
            if plane == "A":
                ref = (-ref[0], -ref[1])
            err = _error(ref, want) / size
            t_ref = median_time(lambda r=rotor, p=plane: resultant(r.masses) if p == "A"
                                else two_planes(r.masses, 0.0, 0.5), 5 if quick else 100)
            rows.append(Row(label, f"m·r in {plane}, float reference", size / perimeter,
                            err, bound / size, t_ref, "" if bound < size else
                            "bound ≥ |m·r|: no digit of it is guaranteed"))
            curves[f"{kind}: float reference"].append((size / perimeter, max(err, 1e-17)))
    path = write_plot(out / "balance-nearly-balanced.svg",
                      "Nearly balanced rotors: the closing side against 50 digits",
                      "closing side / perimeter of the polygon",
                      "relative error of the balancing m·r",
                      [Curve(k, tuple(v)) for k, v in curves.items() if v],
                      note="Below the polygon's rounding bound tarsim says the plane needs "
                           "no mass (not drawn).")
    drawn_rows = [r for r in rows if r.number.endswith("polygon")]
    worst = max(drawn_rows, key=lambda r: r.error)
    closed = [r for r in rows if "none needed" in r.number]
    head = (f"the polygon's closing side keeps a relative error below its bound in "
            f"{sum(r.within for r in drawn_rows)} of {len(drawn_rows)} drawn rows (worst "
            f"{worst.error:.0e} at a closing side {worst.conditioning:.0e} of the perimeter); "
            f"{len(closed)} rows close within rounding, where tarsim says no mass is needed")
    return ChapterStudy("Balancing", "the balancing m·r at 50 digits (mpmath) of the rotor's "
                        "float numbers", "closing side / perimeter", head, tuple(rows), path)
