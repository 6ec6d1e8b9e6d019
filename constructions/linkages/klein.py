"""Klein's construction: the velocity and acceleration of an in-line slider-crank's piston,
drawn on the mechanism itself (Khurmi, Theory of Machines, ch. 8).

With O the crank's pivot, C the crank pin and P the piston pin:

* **velocity**: produce the rod PC to meet at M the line through O square to the line
  of stroke. Triangle OCM has its sides square to those of the velocity triangle (V_C ⟂
  OC, V_PC ⟂ PC, V_P along the stroke), so it is that triangle turned through 90° at
  the scale 1/ω: V_P = ω·OM, turned a right angle with ω.
* **acceleration**: with centre C and radius CM draw a circle, and the circle on CP as
  diameter; the line KL through their two meeting points cuts CP at Q and the line of
  stroke at N. OCQN is the acceleration polygon, turned through 180° at the scale 1/ω²:
  a_P = ω²·NO, pointing from N toward O.

Both take the crank at constant speed (α = 0), as the construction does.

The rod's own diagram gives the rest. CM is the rod's velocity image (V_PC = ω·CM), so a
point D of the rod's line, CD = t·CP, has its image d on CM with Cd = t·CM, and V_D =
ω·Od; ω of the rod is ω·CM/CP. CN is its acceleration image, so d′ on CN with Cd′ =
t·CN gives a_D = ω²·d′O; α of the rod is ω²·QN/CP, QN being the tangential part.
A point D off the rod's line has its image where the rod's does: the triangle CMd on CM
(CNd′ on CN) is similar to the rod's own CPD, so d is cut by the lines from C and M at the
rod's angles PCD and CPD (Khurmi: "the image of a link is similar to the link").
"""

from __future__ import annotations

import math

from .. import asks as A
from ..checks import Answer, FigureSpec, vector_value
from ..errors import InputError
from ..model import Mechanism, slider_crank
from ..narration import Number, phrase
from ..record import Kind, Role

__all__ = ["answer_klein", "klein_parts", "klein_fits", "KLEIN_FIGURE"]

KLEIN_FIGURE = FigureSpec("klein", "Klein's construction", "Klein's construction")
"""The mechanism with the velocity triangle OCM and the acceleration diagram OCQN on it."""


def klein_parts(m: Mechanism) -> tuple[str, str, str, int]:
    """The crank's pivot O, the crank pin C, the piston pin P and the guide's slide index
    (:func:`~.model.slider_crank`).

    Raises
    ------
    InputError
        If the mechanism is no slider-crank whose crank drives a rod to a block on a frame
        guide.
    """
    parts = slider_crank(m)
    if parts is None:
        raise InputError("Klein's construction is drawn on a slider-crank: a crank, a rod and "
                         "a piston on a frame guide; this mechanism is not one")
    return parts


def rod_of(m: Mechanism, c: str, p: str) -> int:
    """The number of the rod: the link that carries both the crank pin and the piston pin."""
    return next(k.number for k in m.links if c in k.names and p in k.names)


def klein_fits(work, ask) -> bool:
    """Whether Klein's construction answers ``ask`` where the exercise chose it: a point's
    motion always (a point it cannot reach is refused with the reason), the rod's ω and α,
    no other link's."""
    if "klein" not in work.chosen:
        return False
    if isinstance(ask, (A.Velocity, A.Acceleration)):
        return True
    parts = slider_crank(work.mechanism)
    return parts is not None and ask.link == rod_of(work.mechanism, parts[1], parts[2])


def _along_rod(m: Mechanism, c: str, p: str, point: str) -> float | None:
    """CD / CP for a point D of the rod's line (signed: negative beyond C); None for a point
    of the rod off its line.

    Raises
    ------
    InputError
        If the point is not a point of the rod.
    """
    rod = m.link(rod_of(m, c, p))
    if point not in rod.names:
        raise InputError(f"Klein's construction finds the motion of the piston {p} and of the "
                         f"points of the rod ({', '.join(rod.names)}), not {point}'s; ask it "
                         "by the polygons")
    xy = dict(rod.points)
    (cx, cy), (px, py), (dx, dy) = xy[c], xy[p], xy[point]
    ux, uy = px - cx, py - cy
    length2 = ux * ux + uy * uy
    # off the line by more than the rounding of the link's own coordinates
    if abs((dx - cx) * uy - (dy - cy) * ux) > 1e-12 * length2:
        return None
    return ((dx - cx) * ux + (dy - cy) * uy) / length2


def answer_klein(work, ask) -> Answer:
    """The velocity (V_P) or acceleration (A_P) of the piston or of a point of the rod's
    line, or the rod's ω or α, by Klein's construction."""
    m, asm = work.mechanism, work.assembly
    o, c, p, i = klein_parts(m)
    point = getattr(ask, "point", p)
    t = 1.0 if point == p else _along_rod(m, c, p, point)
    d = m.drive
    second = isinstance(ask, (A.Acceleration, A.AngularAcceleration))
    if second and d.alpha != 0.0:
        raise InputError("Klein's construction takes the crank at constant speed; this one "
                         f"has α{d.link} = {d.alpha:g} rad/s²: use the acceleration polygon")
    stroke = asm.guides[i]
    off = abs(asm.output(stroke).signed_distance(asm.output(asm.points[o])))
    if off > 1e-9 * asm.size:
        raise InputError(f"Klein's construction is drawn on an in-line slider-crank; this "
                         f"stroke passes {m.units.length_text(off)} from {o}: use the polygons")
    ref = _draw(asm, o, c, p, stroke, acceleration=second)
    w = d.omega
    if isinstance(ask, (A.AngularVelocity, A.AngularAcceleration)):
        return _rod_rate(asm, ask, w, o, c, p)
    if t is None:
        return _rod_plate_point(asm, ask, w, (o, c, p), point, ref)
    if point != p:
        return _rod_point(asm, ask, w, (o, c, p), point, t, ref)
    (ox, oy) = asm.xy(o)
    (x, y) = asm.output(ref).xy
    if isinstance(ask, A.Velocity):
        value = vector_value(-w * (y - oy), w * (x - ox))          # ω k × OM
        method = "Klein's construction (V = ω·OM)"
    else:
        value = vector_value(-w * w * (x - ox), -w * w * (y - oy))  # ω² NO
        method = "Klein's construction (a = ω²·NO)"
    cond = min(asm[r].conditioning for r in (ref, asm.points[c], asm.points[p]))
    refs = ("kl:OCM", ref) if isinstance(ask, A.Velocity) else ("kl:OCM", "kl:Q", "kl:NO")
    return Answer(ask, value, cond, method, refs=refs, figures=(KLEIN_FIGURE,))


def _rod_rate(asm, ask, w: float, o: str, c: str, p: str) -> Answer:
    """The rod's ω (ω·CM/CP, signed along CP) or α (ω²·QN/CP, signed across it), read off
    its own diagram."""
    (cx, cy), (px, py) = asm.xy(c), asm.xy(p)
    ux, uy = px - cx, py - cy
    length2 = ux * ux + uy * uy
    if isinstance(ask, A.AngularVelocity):
        mx, my = asm.output("kl:M").xy
        value = w * ((mx - cx) * ux + (my - cy) * uy) / length2
        refs, method = ("kl:OCM", "kl:M"), "Klein's construction (ω = ω₂·CM/CP)"
    else:
        (qx, qy), (nx, ny) = asm.output("kl:Q").xy, asm.output("kl:N").xy
        value = w * w * ((qx - nx) * -uy + (qy - ny) * ux) / length2
        refs, method = ("kl:Q", "kl:N", "kl:NO"), "Klein's construction (α = ω₂²·QN/CP)"
    cond = min(asm[r].conditioning for r in (*refs, asm.points[c], asm.points[p]))
    return Answer(ask, {"value": value + 0.0}, cond, method, refs=refs,
                  figures=(KLEIN_FIGURE,))


def _rod_point(asm, ask, w: float, parts: tuple[str, str, str], point: str, t: float,
               image: str) -> Answer:
    """A point D of the rod's line, CD = t·CP: its image on CM (velocity) or CN
    (acceleration) at the same fraction t, laid off from C with the dividers."""
    o, c, p = parts
    velocity = isinstance(ask, A.Velocity)
    x = point.lower() + ("" if velocity else "′")
    ref = f"kl:{x}"
    if ref not in asm:
        end = asm.output(image).xy
        span = math.dist(asm.xy(c), end)
        asm.draw(ref, "lay_off", asm.points[c], image, label=x, length=t * span,
                 phrase=phrase("klein.point_v" if velocity else "klein.point_a", c=c,
                               point=point, x=x, o=o, p=p, ratio=Number(t, ".6g")))
        _join_to_o(asm, ref, o, velocity)
    return _read_image(asm, ask, w, ref, image, o, c, "d on CM" if velocity else "d′ on CN")


def _turn(asm, vertex: str, a: str, b: str) -> float:
    """The signed angle (rad, counter-clockwise) from the ray vertex→a to vertex→b."""
    (vx, vy), (ax, ay), (bx, by) = asm.xy(vertex), asm.xy(a), asm.xy(b)
    ux, uy, wx, wy = ax - vx, ay - vy, bx - vx, by - vy
    return math.atan2(ux * wy - uy * wx, ux * wx + uy * wy)


def _rod_plate_point(asm, ask, w: float, parts: tuple[str, str, str], point: str,
                     image: str) -> Answer:
    """A point D of the rod off its line: its image d on the side CM (velocity) or d′ on
    CN (acceleration) makes the triangle C·M·d similar to the rod's C·P·D, so it lies where
    the line from C at the angle PCD to CM cuts the line from M at the angle CPD to MC.
    When the side CM has shrunk to C (the rod does not turn) d is C itself."""
    o, c, p = parts
    velocity = isinstance(ask, A.Velocity)
    x = point.lower() + ("" if velocity else "′")
    ref, side = f"kl:{x}", "M" if velocity else "N"
    if ref not in asm:
        at_c, at_p = _turn(asm, c, p, point), _turn(asm, p, c, point)
        span = math.dist(asm.xy(c), asm.output(image).xy)
        said = phrase("klein.plate_v" if velocity else "klein.plate_a", c=c, p=p, point=point,
                      x=x, o=o, side=side, at_c=Number(abs(math.degrees(at_c)), ".4g"),
                      at_p=Number(abs(math.degrees(at_p)), ".4g"))
        if span <= 1e-12 * asm.size:
            asm.draw(ref, "mark", asm.points[c], label=x, phrase=said)
        else:
            asm.draw(f"{ref}:c", "rotate_about", image, asm.points[c], angle=at_c)
            asm.draw(f"{ref}:cl", "line_through", asm.points[c], f"{ref}:c")
            asm.draw(f"{ref}:m", "rotate_about", asm.points[c], image, angle=at_p)
            asm.draw(f"{ref}:ml", "line_through", image, f"{ref}:m")
            asm.draw(ref, "intersect_lines", f"{ref}:cl", f"{ref}:ml", label=x, phrase=said)
        _join_to_o(asm, ref, o, velocity)
    return _read_image(asm, ask, w, ref, image, o, c,
                       "CMd similar to the rod" if velocity else "CNd′ similar to the rod")


def _join_to_o(asm, ref: str, o: str, velocity: bool) -> None:
    """Join a point's image to O: Od is its velocity's line, d′O its acceleration's."""
    ends = (asm.points[o], ref) if velocity else (ref, asm.points[o])
    asm.draw(f"{ref}:O", "join", *ends, kind=Kind.LINE, role=Role.RESULT)


def _read_image(asm, ask, w: float, ref: str, image: str, o: str, c: str,
                where: str) -> Answer:
    """A rod point's velocity ω k × Od, or acceleration ω²·d′O, read off its image ``ref``
    (``where`` says how the image was found, for the method's words)."""
    (ox, oy), (x_, y_) = asm.xy(o), asm.output(ref).xy
    if isinstance(ask, A.Velocity):
        value = vector_value(-w * (y_ - oy), w * (x_ - ox))
        method = f"Klein's construction (V = ω·Od, {where})"
    else:
        value = vector_value(-w * w * (x_ - ox), -w * w * (y_ - oy))
        method = f"Klein's construction (a = ω²·d′O, {where})"
    cond = min(asm[r].conditioning for r in (ref, image, asm.points[c]))
    return Answer(ask, value, cond, method, refs=("kl:OCM", ref, f"{ref}:O"),
                  figures=(KLEIN_FIGURE,))


def _draw(asm, o: str, c: str, p: str, stroke: str, *, acceleration: bool) -> str:
    """Draw Klein's lines once; return the ref of M (velocity) or of N (acceleration)."""
    if "kl:M" not in asm:
        po, pc, pp = asm.points[o], asm.points[c], asm.points[p]
        asm.draw("kl:OM", "perpendicular_through", po, stroke,
                 phrase=phrase("klein.square", o=o))
        asm.draw("kl:rod", "line_through", pp, pc, phrase=phrase("klein.produce", p=p, c=c))
        asm.draw("kl:M", "intersect_lines", "kl:OM", "kl:rod", label="M",
                 phrase=phrase("klein.m", o=o, c=c))
        asm.draw("kl:OCM", "join", po, "kl:M", kind=Kind.LINE, role=Role.RESULT,
                 phrase=phrase("klein.velocity", o=o, c=c, p=p))
    if not acceleration:
        return "kl:M"
    if "kl:N" not in asm:
        pc, pp = asm.points[c], asm.points[p]
        asm.draw("kl:c1", "circle_through", pc, "kl:M", phrase=phrase("klein.circle_cm", c=c))
        asm.draw("kl:mid", "midpoint", pc, pp)
        asm.draw("kl:c2", "circle_through", "kl:mid", pc,
                 phrase=phrase("klein.circle_cp", c=c, p=p))
        asm.draw("kl:K", "intersect_circles", "kl:c1", "kl:c2", pick="left", label="K")
        asm.draw("kl:L", "intersect_circles", "kl:c1", "kl:c2", pick="right", label="L",
                 phrase=phrase("klein.kl"))
        asm.draw("kl:KL", "line_through", "kl:K", "kl:L", phrase=phrase("klein.join_kl"))
        asm.draw("kl:Q", "intersect_lines", "kl:KL", "kl:rod", label="Q",
                 phrase=phrase("klein.q", c=c, p=p))
        asm.draw("kl:N", "intersect_lines", "kl:KL", stroke, label="N",
                 phrase=phrase("klein.acceleration", o=o, c=c, p=p))
        asm.draw("kl:NO", "join", "kl:N", asm.points[o], kind=Kind.LINE, role=Role.RESULT)
    return "kl:N"

