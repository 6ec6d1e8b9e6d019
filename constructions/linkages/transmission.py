"""Angular velocity by the line of transmission (exam text 001 §2.1, lines 209–247).

Motion passes from a driver to a follower along the *line of transmission*: the
coupler line when an intermediate link joins them (a four-bar's AB). Two points of
one rigid link have equal velocity components along the line joining them, so

    ω_follower / ω_driver = O_d G / O_f H,

where G and H are the feet of the perpendiculars from the driver's and the
follower's fixed centres to the line of transmission: "the angular-velocity ratio
of driver to follower is inversely proportional to the perpendiculars from their
centres to the line of transmission". The two turn the same way when their centres
lie on the same side of the line, opposite ways when it runs between them.

The construction draws the line, drops the two perpendiculars and measures them;
the figure shows them as dimension lines.
"""

from __future__ import annotations

from .. import asks as A
from .. import geometry as g
from ..checks import Answer, FigureSpec
from ..errors import TarsimError
from ..narration import Number, Word, phrase
from ..record import Role

__all__ = ["answer_omega", "transmission_links"]


def transmission_links(mech, follower: int) -> tuple[str, str, str, str, int] | None:
    """The driver's centre and pin, the follower's pin and centre, and the coupler that joins
    them: ``(O_d, A, B, O_f, coupler)``, or None if no single coupler joins the input to
    ``follower`` (each pinned to the frame)."""
    d = mech.link(mech.drive.link)
    frame = set(mech.frame.names)
    o_d = d.names[0]
    o_f = next((n for n in mech.link(follower).names if n in frame), None)
    if follower in (1, d.number) or o_d not in frame or o_f is None:
        return None
    for k in mech.links:
        if k.number in (1, d.number, follower):
            continue
        a = next((n for n in k.names if n in d.names and n != o_d), None)
        b = next((n for n in k.names if n in mech.link(follower).names and n != o_f), None)
        if a is not None and b is not None and a != b:
            return o_d, a, b, o_f, k.number
    return None


def answer_omega(work, ask: A.AngularVelocity) -> Answer:
    """ω of the follower from the perpendiculars on the line of transmission.

    Raises
    ------
    TarsimError
        If no coupler joins the input to the link, or the line of transmission runs
        through the follower's centre (ω unbounded: a dead point).
    """
    m, asm = work.mechanism, work.assembly
    c, d, n = asm, m.drive, ask.link
    found = transmission_links(m, n)
    if found is None:
        raise TarsimError(f"the line-of-transmission method needs link {n} pinned to the frame "
                          f"and joined to the input (link {d.link}) by one coupler")
    o_d, a, b, o_f, coupler = found
    p = asm.points
    tag = f"lt:{n}"
    line = c.draw(f"{tag}:line", "line_through", p[a], p[b], label="line of transmission",
                  phrase=phrase("transmission.line", a=a, b=b, link=coupler))
    feet = {}
    for centre, foot in ((o_d, "G"), (o_f, "H")):
        square = c.draw(f"{tag}:{centre}⟂", "perpendicular_through", p[centre], line,
                        phrase=phrase("transmission.perpendicular", centre=centre, a=a, b=b))
        feet[centre] = c.draw(f"{tag}:{foot}", "intersect_lines", square, line, label=foot,
                              phrase=phrase("transmission.foot", a=a, b=b, foot=foot))
    gd, hf = (c.output(feet[x]) for x in (o_d, o_f))
    lever_d = g.distance(c.output(p[o_d]), gd)
    lever_f = g.distance(c.output(p[o_f]), hf)
    if lever_f <= 1e-12 * asm.size:
        raise TarsimError(f"the line of transmission {a}{b} runs through {o_f}: ω{n} is "
                          f"unbounded at this position (a dead point)")
    side_d = g.side_of(c.output(p[o_d]), c.output(p[a]), c.output(p[b]))
    side_f = g.side_of(c.output(p[o_f]), c.output(p[a]), c.output(p[b]))
    sense = 1.0 if side_d * side_f > 0 else -1.0
    ratio = sense * lever_d / lever_f
    units = m.units
    c.draw(f"{tag}:{o_d}G", "measure", p[o_d], feet[o_d], label=f"{o_d}G",
           phrase=phrase("transmission.measure", centre=o_d, foot="G",
                         length=units.length_said(lever_d)))
    said = phrase("transmission.ratio", n=n, d=d.link, o_d=o_d, o_f=o_f,
                  length=units.length_said(lever_f), ratio=Number(abs(ratio)),
                  sides=Word("the same side" if sense > 0 else "opposite sides"),
                  omega=Number(abs(ratio * d.omega)),
                  sense=Word("ccw" if ratio * d.omega > 0 else "cw"))
    result = c.draw(f"{tag}:{o_f}H", "measure", p[o_f], feet[o_f], label=f"{o_f}H",
                    role=Role.RESULT, phrase=said)
    # The ratio divides by O_f H: a short perpendicular magnifies the drawing's error.
    cond = min(c[result].conditioning, c[line].conditioning) * min(1.0, lever_f / asm.size)
    by = Word("the line of transmission")
    spec = FigureSpec(f"omega{n}-line-of-transmission", phrase("md.by", what=f"ω{n}", method=by),
                      phrase("md.by", what=f"ω_{n}", method=by))
    return Answer(ask, {"value": ratio * d.omega + 0.0}, cond, "line of transmission",
                  refs=(f"{tag}:{o_d}G", result), figures=(spec,))

