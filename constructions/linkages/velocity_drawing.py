"""Velocities drawn on the space diagram: the known input velocity and each method's result.

A velocity is drawn as a segment from its point to its tip, ``scale`` drawing
metres per m/s long (the figure states the scale as "1 cm = … m/s"). Every
method (radius rotation, parallel lines, components) starts from the same input
vector, laid off at the drive link's second point perpendicular to the link, and
ends with a :class:`VelocityResult` whose ``vector`` step is the answer.
"""

from __future__ import annotations

from dataclasses import dataclass

from .assembly_record import Assembly
from ..checks import Answer, FigureSpec, vector_value
from ..narration import Number, Word, phrase
from ..record import Construction, Kind, Ref, Role, slice

__all__ = ["VelocityResult", "velocity_result", "draw_input_velocity", "velocity_value",
           "vector_label", "answer", "method_words"]


def vector_label(point: str) -> str:
    """The label of a velocity vector: ``V_A`` (the figure sets the subscript)."""
    return f"V_{point}"


@dataclass
class VelocityResult:
    """One point's velocity found by one graphical method.

    Its ``answer`` is the ``vector`` it found and the vectors it carried there:
    the given one it started from and any it transferred (a length taken with
    the dividers is a number to the record, not a step). A figure of the method is
    the slice of the answer, ``steps``: the method's lines and the centres they
    rest on, nothing more.
    """

    method: str
    point: str
    link: int
    vector: Ref
    scale: float
    answer: tuple[Ref, ...]
    steps: list[Ref]

    def value(self, construction: Construction) -> tuple[float, float]:
        """The velocity in m/s, read off the drawn vector at the drawing's scale."""
        return velocity_value(construction, self.vector, self.scale)


def velocity_value(construction: Construction, ref: Ref, scale: float) -> tuple[float, float]:
    """Read a drawn velocity segment back as m/s."""
    vx, vy = construction.output(ref).vector
    return vx / scale, vy / scale


def velocity_result(asm: Assembly, method: str, point: str, link: int, vector: Ref,
                    scale: float, carried: tuple[Ref, ...],
                    arrows: tuple[Ref, ...] = ()) -> VelocityResult:
    """The result of a velocity method, with the slice of its answer as its steps.

    ``arrows`` are the vectors the method drew on its way (components of the
    known velocities, the velocities of the points it passed): those standing
    on the points the found vector rests on belong to it.
    """
    c, base = asm, asm.position_steps
    found = slice(c, [vector], base=base, arrows=arrows).refs
    answer = tuple(dict.fromkeys((*carried, *(r for r in found if r in arrows), vector)))
    return VelocityResult(method, point, link, vector, scale, answer,
                          list(slice(c, answer, base=base).refs))


def draw_input_velocity(asm: Assembly, scale: float) -> tuple[str, Ref]:
    """Lay off the known velocity of the input link's point, ⟂ the link, once per construction.

    Returns the point's name and the ref of its vector ``V:<point>``. The length
    is ω·r at ``scale`` and the sense follows ω (counter-clockwise positive).
    """
    m = asm.mechanism
    d = m.drive
    pivot, _, point, arm = asm.input_arm()
    ref = f"V:{point}"
    c = asm
    if ref in c:
        return point, ref
    r = m.input_radius
    speed = m.input_speed
    units = m.units
    sense = "ccw" if d.omega > 0 else "cw"
    perp = c.draw(f"v:perp:{point}", "perpendicular_through", asm.points[point], arm,
                  phrase=phrase("velocity.input_perpendicular", point=point, pivot=pivot))
    tip = c.draw(f"v:tip:{point}", "lay_off", asm.points[point], perp,
                 length=d.omega * r * scale,
                 phrase=phrase("velocity.input_vector", point=point, link=d.link, pivot=pivot,
                               omega=Number(abs(d.omega)), radius=units.length_said(r),
                               speed=units.speed_said(speed), sense=Word(sense)))
    c.draw(ref, "join", asm.points[point], tip, label=vector_label(point), role=Role.GIVEN,
           kind=Kind.VECTOR, phrase=phrase("velocity.known", point=point))
    return point, ref



def method_words(method: str) -> str:
    """A method as the course says it: "radius-rotation" is "radius rotation".

    >>> method_words("parallel-line"), method_words("velocity polygon")
    ('parallel lines', 'velocity polygon')
    """
    return {"radius-rotation": "radius rotation", "parallel-line": "parallel lines"}.get(
        method, method)


def answer(work, ask, result: VelocityResult) -> Answer:
    """A velocity found by a method of the space diagram, as the registry takes it: drawn on
    its own figure, ``V_<point>-<method>``, at the position's velocity scale."""
    c = work.assembly
    said = phrase("md.by", what=f"V_{ask.point}", method=Word(method_words(result.method)))
    spec = FigureSpec(f"V_{ask.point}-{result.method}", said, said, velocity_scale=result.scale,
                      velocity_stated=work.scales.velocity)
    return Answer(ask, vector_value(*result.value(c)),
                  c[result.vector].conditioning * drawn_share(c, result.scale),
                  result.method, refs=result.answer, figures=(spec,))


def drawn_share(asm, scale: float) -> float:
    """The input's vector, drawn at ``scale`` (drawing metres per m/s), as a share of the
    mechanism it is drawn on (at most 1): every vector's tip is placed to the rounding of
    the drawing's coordinates, so one drawn a trillionth of the mechanism long keeps only
    that share of its digits, however cleanly its lines cross.

    >>> from types import SimpleNamespace as N
    >>> asm = N(size=2.0, mechanism=N(input_speed=1e-13))
    >>> drawn_share(asm, 10.0)
    5e-13
    """
    length = abs(asm.mechanism.input_speed) * scale
    return 1.0 if length == 0.0 else min(1.0, length / asm.size)
