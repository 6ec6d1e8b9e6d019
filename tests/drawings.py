"""Students' drawings made from tarsim's own polygons, written as Inkscape writes SVG
(mm units and a viewBox, nested groups with transforms, text in tspans) or as GeoGebra
does (a pixel page, a path per vector, labels as plain text), and perturbed as students
err: a tip moved, the drawing turned or mirrored, drawn at another scale (and saying so),
a label swapped or left off, a Coriolis component reversed."""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from xml.sax.saxutils import escape

from tarsim.constructions.linkages.acceleration_polygon import drawn_acceleration_polygon
from tarsim.constructions.linkages.velocity_polygon import drawn_velocity_polygon


@dataclass
class Style:
    """How a drawing departs from tarsim's: ``kind`` "v" or "a", paper mm per SI unit,
    a turn (degrees), a mirror, tips moved (name → paper mm), tips left out, labels
    swapped, a scale written on it, a Coriolis component reversed at a point, and the
    program that wrote it ("inkscape" or "geogebra")."""

    kind: str = "v"
    scale: float | None = None
    turn: float = 0.0
    mirror: bool = False
    moved: dict[str, tuple[float, float]] = field(default_factory=dict)
    left_out: tuple[str, ...] = ()
    swapped: tuple[str, str] | None = None
    stated: str = ""
    reversed_coriolis: str = ""
    writer: str = "inkscape"


def polygon_of(sol, kind: str):
    """tarsim's polygon of ``kind`` at the position: (tips' SI vectors, Coriolis by point)."""
    if kind == "v":
        vp = drawn_velocity_polygon(sol.work)
        return {n: vp.vector(n) for n in vp.tips}, {}
    ap = drawn_acceleration_polygon(sol.work)
    return {n: ap.vector(n) for n in ap.tips}, {p: ap.coriolis_of(p) for p in ap.coriolis}


def drawing(sol, style: Style) -> str:
    """The SVG of the polygon drawn in ``style``."""
    tips, _ = polygon_of(sol, style.kind)
    biggest = max(math.hypot(*v) for v in tips.values())
    per_cm = (sol.work.scales.velocity_polygon if style.kind == "v"
              else sol.work.scales.acceleration_polygon)
    # At the scale the exercise states, else the polygon some 8 cm across.
    stated = 10.0 / (per_cm * sol.work.mechanism.units.metres) if per_cm else None
    scale = style.scale or stated or 80.0 / biggest
    prime = "′" if style.kind == "a" else ""
    pole = (100.0, 140.0)
    turn = math.radians(style.turn)

    def place(v):
        x, y = v[0] * scale, (v[1] if style.mirror else -v[1]) * scale
        c, s = math.cos(turn), math.sin(turn)
        return (pole[0] + c * x - s * y, pole[1] + s * x + c * y)

    if style.reversed_coriolis:
        tips = {**tips, **_reversed_coriolis(sol, style.reversed_coriolis)}
    pts = {}
    for name, v in tips.items():
        p = place(v)
        dx, dy = style.moved.get(name, (0.0, 0.0))
        pts[name] = (p[0] + dx, p[1] + dy)
    labels = {n: n.lower() for n in pts}
    if style.swapped:
        a, b = style.swapped
        labels[a], labels[b] = labels[b], labels[a]
    body = []
    for name, p in pts.items():
        if name in style.left_out or math.dist(p, pole) < 0.5:
            continue
        body.append(_vector(pole, p, style.writer))
        letters, digits = labels[name].rstrip("0123456789"), labels[name][
            len(labels[name].rstrip("0123456789")):]
        body.append(_text((p[0] + 1.5, p[1] - 1.5), letters, digits + prime, style.writer))
    body.append(_text((pole[0] - 5.0, pole[1] + 4.0), "o", ("a" if style.kind == "a" else "v"),
                      style.writer))
    if style.stated:
        body.append(_text((20.0, 270.0), style.stated, "", style.writer))
    return _page(body, style.writer)


def _reversed_coriolis(sol, point: str) -> dict[str, tuple[float, float]]:
    """The acceleration polygon's tips as a student draws them with the Coriolis component at
    ``point`` reversed: the loop equations solved with its sign flipped
    (tests/loop_kinematics.py, not tarsim's construction)."""
    from tests.loop_kinematics import read_exercise, solve

    ex = read_exercise(sol.exercise.id)
    angle = sol.work.mechanism.drive.angle
    position = min(range(len(ex.angles)), key=lambda k: abs(math.remainder(
        ex.angles[k] - angle, 2 * math.pi)))
    return solve(ex, position, coriolis=(point,)).acceleration


def _vector(a, b, writer: str) -> str:
    if writer == "geogebra":
        return (f'<path d="M {a[0] * _PX:.3f} {a[1] * _PX:.3f} L {b[0] * _PX:.3f} '
                f'{b[1] * _PX:.3f}" stroke="#000" fill="none"/>')
    return (f'<g transform="translate(2,3)"><line x1="{a[0] - 2:.4f}" y1="{a[1] - 3:.4f}" '
            f'x2="{b[0] - 2:.4f}" y2="{b[1] - 3:.4f}" style="stroke:#000;stroke-width:0.3"/>'
            '</g>')


def _text(at, text: str, sub: str, writer: str) -> str:
    if writer == "geogebra":
        return (f'<text x="{at[0] * _PX:.3f}" y="{at[1] * _PX:.3f}" font-size="14">'
                f'{escape(text + sub)}</text>')
    tail = f'<tspan style="font-size:65%;baseline-shift:sub">{escape(sub)}</tspan>' if sub \
        else ""
    return (f'<text xml:space="preserve" x="{at[0]:.4f}" y="{at[1]:.4f}" '
            f'style="font-size:4px"><tspan x="{at[0]:.4f}" y="{at[1]:.4f}">{escape(text)}'
            f'{tail}</tspan></text>')


_PX = 96.0 / 25.4


def _page(body: list[str], writer: str) -> str:
    if writer == "geogebra":
        return ('<?xml version="1.0" encoding="UTF-8"?>\n<svg xmlns="http://www.w3.org/2000/svg" '
                'width="794" height="1123">' + "".join(body) + "</svg>\n")
    return ('<?xml version="1.0" encoding="UTF-8"?>\n<svg xmlns="http://www.w3.org/2000/svg" '
            'xmlns:inkscape="http://www.inkscape.org/namespaces/inkscape" width="210mm" '
            'height="297mm" viewBox="0 0 210 297"><g inkscape:groupmode="layer" '
            'transform="translate(0,0)"><g transform="matrix(1,0,0,1,0,0)">'
            + "".join(body) + "</g></g></svg>\n")


def centres_drawing(sol, *, turn: float = 0.0, mirror: bool = False, scale: float = 0.3,
                    moved: dict[str, tuple[float, float]] | None = None,
                    plain: bool = False) -> str:
    """A space diagram of the mechanism's points and its finite instant centres, each a dot
    with its label (``I13``, or ``13`` when ``plain``), at ``scale`` paper mm per file mm,
    turned and mirrored as asked, centres moved by paper mm."""
    metres = sol.work.mechanism.units.metres
    k = scale / metres
    c, s = math.cos(math.radians(turn)), math.sin(math.radians(turn))

    def place(p):
        x, y = p[0] * k, (p[1] if mirror else -p[1]) * k
        return (105.0 + c * x - s * y, 150.0 + s * x + c * y)
    body = []
    for name, p in sol.work.kinematics.points.items():
        at = place(p)
        body.append(f'<circle cx="{at[0]:.4f}" cy="{at[1]:.4f}" r="0.8"/>')
        body.append(_text((at[0] + 1.2, at[1] - 1.2), name, "", "inkscape"))
    for name, q in sol.quantities.items():
        if name.startswith("I") and "point" in q.reference:
            at = place(q.reference["point"])
            dx, dy = (moved or {}).get(name, (0.0, 0.0))
            at = (at[0] + dx, at[1] + dy)
            body.append(f'<circle cx="{at[0]:.4f}" cy="{at[1]:.4f}" r="0.6"/>')
            body.append(_text((at[0] + 1.2, at[1] - 1.2), name[1:] if plain else name, "",
                              "inkscape"))
    return _page(body, "inkscape")
