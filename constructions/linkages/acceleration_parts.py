"""The normal and tangential parts of an acceleration, resolved on the acceleration polygon.

Of a relative acceleration of two points of one link, A_B/A = Aⁿ_B/A + Aᵗ_B/A: the
normal part runs along BA (ω²·AB, toward A), the tangential part across it (α·AB). On
the polygon, the line through a′ parallel to AB and the foot on it of the perpendicular
from b′ part them: a′ to the foot is Aⁿ_B/A, the foot to b′ is Aᵗ_B/A. Of an absolute
acceleration, the parts are along and across the point's path: the tangent is the
direction of its velocity, taken from the velocity polygon (o_v b), so the line through
o_a parallel to o_v b and the foot on it from b′ part A_B into Aᵗ_B (o_a to the foot) and
Aⁿ_B (the foot to b′).
"""

from __future__ import annotations

from .. import asks as A
from .acceleration_polygon import answer as from_acceleration_polygon
from .acceleration_polygon import drawn_acceleration_polygon
from ..checks import Answer, vector_value
from .coincident import taken
from ..errors import InputError
from ..narration import phrase
from ..record import Panel, Role
from .velocity_polygon import drawn_velocity_polygon

__all__ = ["answer_part", "common_link"]


def common_link(m, point: str, of: str) -> int:
    """The moving link that carries both points (each as :func:`.coincident.taken` takes it).

    Raises
    ------
    InputError
        If no one link carries both: their relative acceleration has no normal and
        tangential parts of one ω and α.
    """
    (i, p), (j, q) = taken(m, point), taken(m, of)
    links = ({i} | set(m.links_at(p))) & ({j} | set(m.links_at(q))) - {1}
    if i == j and i != 1:
        return i
    if len(links) == 1:
        return links.pop()
    raise InputError(f"{point} and {of} are not points of one moving link, so A_{point}/{of} "
                     "has no normal and tangential parts of one ω and α; ask them of two "
                     "points of one link")


def answer_part(work, ask: A.AccelerationPart) -> Answer:
    """Resolve the acceleration on the polygon and read the asked part off it."""
    ap = drawn_acceleration_polygon(work)
    c, m = ap.construction, work.mechanism
    whole = from_acceleration_polygon(work, A.Acceleration(ask.point) if ask.of is None
                                      else A.Relative("A", ask.point, ask.of))
    key = ask.point if ask.of is None else f"{ask.point}-{ask.of}"     # both parts share it
    if ask.of is not None:
        k = common_link(m, ask.point, ask.of)
        start, end = ap.tip(ask.of), ap.tip(ask.point)
        (_, p), (_, q) = taken(m, ask.point), taken(m, ask.of)
        if f"s:line:{q}-{p}" not in c:
            c.draw(f"s:line:{q}-{p}", "line_through", work.assembly.points[q],
                   work.assembly.points[p],
                   phrase=phrase("polygon.space_line", a=q, b=p, link=k))
        direction, along = f"s:line:{q}-{p}", "normal"
        said = phrase("apolygon.resolve_relative", a=c[start].label, b=c[end].label, p=q, q=p)
    else:
        vp = drawn_velocity_polygon(work)
        start, end = ap.pole, ap.tip(ask.point)
        v = vp.tip(ask.point)
        if vp.vector(ask.point) == (0.0, 0.0) or c.output(v).xy == c.output(vp.pole).xy:
            raise InputError(f"{ask.point} is at rest at this instant, so its path has no "
                             f"tangent to part A_{ask.point} by; ask A_{ask.point} itself")
        ref = f"vp:path:{ask.point}"
        if ref not in c:
            c.draw(ref, "line_through", vp.pole, v, panel=Panel.VELOCITY,
                   phrase=phrase("vpolygon.path", tip=c[v].label, point=ask.point))
        direction, along = ref, "tangential"
        said = phrase("apolygon.resolve_absolute", pole=c[start].label, tip=c[end].label,
                      point=ask.point)
    line = f"ap:{key}:line"
    if line not in c:
        c.draw(line, "parallel_through", start, direction, panel=Panel.ACCELERATION, phrase=said)
        c.draw(f"ap:{key}:foot", "project_onto", end, line, panel=Panel.ACCELERATION,
               phrase=phrase("apolygon.resolve_foot", tip=c[end].label))
        rel = ask.point if ask.of is None else f"{ask.point}/{ask.of}"
        first, second = (("n", "t") if along == "normal" else ("t", "n"))
        for part, (a, b) in ((first, (start, f"ap:{key}:foot")),
                             (second, (f"ap:{key}:foot", end))):
            c.draw(f"ap:A{part}_{rel}:part", "join", a, b, label=f"A{_MARK[part]}_{rel}",
                   role=Role.RESULT, panel=Panel.ACCELERATION, phrase=None)
    rel = ask.point if ask.of is None else f"{ask.point}/{ask.of}"
    ref = f"ap:A{ask.part}_{rel}:part"
    value = vector_value(*ap.between(*c[ref].inputs))
    return Answer(ask, value, whole.conditioning, f"acceleration polygon (A{_MARK[ask.part]})",
                  refs=(ref,) + whole.refs, arrows=whole.arrows, figures=whole.figures,
                  panel=Panel.ACCELERATION)


_MARK = {"n": "ⁿ", "t": "ᵗ"}
