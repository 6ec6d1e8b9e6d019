"""Closed forms a random linkage's printed answers are held to, apart from tarsim's reference.

tarsim checks every answer against its own analytic solver; a wrong answer that both agree
on (a shared model, a branch taken by both the wrong way, a check too loose to fail) would
pass. These are the textbook's loop equations, written out here by hand for the two
commonest linkages, a 4R four-bar and a slider-crank on a straight frame guide, and solved
by Cramer's rule from the positions tarsim reports (which the compass check already holds
to its analytic solution). An answer tarsim prints as checked that they contradict is a
wrong answer.
"""

from __future__ import annotations

import math
from typing import Any

__all__ = ["contradictions"]

EPS = 2.220446049250313e-16

AGREE = 1e-5
"""How far a printed answer may stand from the closed form, beside its scale: the loosest
tarsim's own checks may be (``checks.CEILING``)."""


def _cross(u, v) -> float:
    return u[0] * v[1] - u[1] * v[0]


def _sub(p, q) -> tuple[float, float]:
    return (p[0] - q[0], p[1] - q[1])


def _perp(r, w: float) -> tuple[float, float]:
    """ω × r in the plane: r turned +90° and scaled by ω."""
    return (-w * r[1], w * r[0])


def _chain(mech) -> dict[str, Any] | None:
    """The input, coupler and output of a four-bar or a slider-crank: link numbers and point
    names; None for any other mechanism."""
    if mech.arcs or len(mech.links) != 4:
        return None
    drive = mech.link(mech.drive.link)
    frame = set(mech.frame.names)
    if len(drive.names) != 2 or drive.names[0] not in frame:
        return None
    pivot, pin = drive.names
    coupler = next((k for k in mech.links if k.number not in (1, drive.number)
                    and pin in k.names and len(k.names) == 2), None)
    if coupler is None:
        return None
    end = next(n for n in coupler.names if n != pin)
    output = next(k for k in mech.links if k.number not in (1, drive.number, coupler.number))
    if not mech.slides and len(output.names) == 2 and end in output.names:
        ground = next(n for n in output.names if n != end)
        if ground in frame:
            return {"kind": "four-bar", "pivot": pivot, "pin": pin, "end": end, "ground": ground,
                    "coupler": coupler.number, "output": output.number}
    if len(mech.slides) == 1:
        s = mech.slides[0]
        if (s.guide_link == 1 and s.link == output.number and s.point == end
                and output.names == (end,) and s.contact is None):
            return {"kind": "slider-crank", "pivot": pivot, "pin": pin, "end": end,
                    "coupler": coupler.number, "output": output.number,
                    "direction": s.direction}
    return None


def _solve(a, b, rhs) -> tuple[float, float, float]:
    """x, y with x·a + y·b = rhs (2-vectors), and |sin| of the angle between a and b."""
    det = _cross(a, b)
    size = math.hypot(*a) * math.hypot(*b)
    return _cross(rhs, b) / det, _cross(a, rhs) / det, abs(det) / size


def _closed_form(mech, points, chain) -> tuple[dict[str, Any], float] | None:
    """The rates and the end point's motion by the loop equations, and the conditioning of
    their 2 × 2 system (None at a dead point)."""
    d = mech.drive
    w2, a2 = d.omega, d.alpha
    p0, a, b = points[chain["pivot"]], points[chain["pin"]], points[chain["end"]]
    ra, rab = _sub(a, p0), _sub(b, a)
    va = _perp(ra, w2)
    aa = (-a2 * ra[1] - w2 * w2 * ra[0], a2 * ra[0] - w2 * w2 * ra[1])
    if chain["kind"] == "four-bar":
        rqb = _sub(b, points[chain["ground"]])
        # ω3 k×AB − ω4 k×O4B = −V_A, then the same with the accelerations' known parts.
        w3, w4, sine = _solve(_perp(rab, 1.0), _perp(rqb, -1.0), (-va[0], -va[1]))
        if sine < 1e-8:
            return None
        known = (aa[0] - w3 * w3 * rab[0] + w4 * w4 * rqb[0],
                 aa[1] - w3 * w3 * rab[1] + w4 * w4 * rqb[1])
        al3, al4, _ = _solve(_perp(rab, 1.0), _perp(rqb, -1.0), (-known[0], -known[1]))
        vb = _perp(rqb, w4)
        ab = (-al4 * rqb[1] - w4 * w4 * rqb[0], al4 * rqb[0] - w4 * w4 * rqb[1])
        rates = {f"omega{chain['coupler']}": w3, f"omega{chain['output']}": w4,
                 f"alpha{chain['coupler']}": al3, f"alpha{chain['output']}": al4}
    else:
        u = chain["direction"]
        # ω3 k×AB − v u = −V_A: the block's speed v along its guide.
        w3, v, sine = _solve(_perp(rab, 1.0), (-u[0], -u[1]), (-va[0], -va[1]))
        if sine < 1e-8:
            return None
        known = (aa[0] - w3 * w3 * rab[0], aa[1] - w3 * w3 * rab[1])
        al3, acc, _ = _solve(_perp(rab, 1.0), (-u[0], -u[1]), (-known[0], -known[1]))
        vb, ab = (v * u[0], v * u[1]), (acc * u[0], acc * u[1])
        rates = {f"omega{chain['coupler']}": w3, f"alpha{chain['coupler']}": al3}
    return {**rates, f"V_{chain['pin']}": va, f"A_{chain['pin']}": aa,
            f"V_{chain['end']}": vb, f"A_{chain['end']}": ab}, sine


def contradictions(solution) -> list[str]:
    """The answers ``solution`` prints as checked that the loop equations contradict, each
    said as "position: name by method: got …, closed form …"; none for a mechanism they do
    not cover."""
    out = []
    for sol in getattr(solution, "positions", ()):
        mech = sol.work.mechanism               # its input's rates as solved
        chain = _chain(mech)
        if chain is None:
            return []
        found = _closed_form(mech, sol.kinematics.points, chain)
        if found is None:
            continue
        truth, sine = found
        d = mech.drive
        r2 = math.dist(sol.kinematics.points[chain["pivot"]], sol.kinematics.points[chain["pin"]])
        scales = {"omega": abs(d.omega), "alpha": math.hypot(d.omega ** 2, d.alpha),
                  "V": abs(d.omega) * r2, "A": math.hypot(d.omega ** 2, d.alpha) * r2}
        # The closed form's own rounding grows as its two unknowns' directions close up.
        allowed = AGREE + 1e3 * EPS / sine
        for name, q in sol.quantities.items():
            if name not in truth:
                continue
            scale = scales[name.split("_")[0].rstrip("0123456789")]
            for qq in (q, *q.alternatives.values()):
                if not qq.passed or scale == 0.0:
                    continue
                got, want = qq.value.get("vector", qq.value["value"]), truth[name]
                # Beside its scale, or itself where it is larger (α3 of a rod near its
                # toggle, 2e4 times ω2²), as tarsim's own check and its six figures say it.
                size = math.hypot(*want) if isinstance(want, tuple) else abs(want)
                miss = (math.dist(got, want) if isinstance(want, tuple)
                        else abs(got - want)) / max(scale, size, 1e-300)
                if miss > allowed:
                    where = sol.position.label if sol.position else f"θ{d.link} input"
                    out.append(f"{where}: {name} by {qq.method}: got {got}, closed form {want} "
                               f"({miss:.1e} of its scale)")
    return out
