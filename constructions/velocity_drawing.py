"""Velocities drawn on the space diagram: the known input velocity and each method's result.

A velocity is drawn as a segment from its point to its tip, ``scale`` drawing
metres per m/s long (the figure states the scale as "1 cm = … m/s"). Every
method (radius rotation, parallel lines, components) starts from the same input
vector, laid off at the drive link's second point perpendicular to the link, and
ends with a :class:`VelocityResult` whose ``vector`` step is the answer.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from .assembly import Assembly
from .record import Construction, Ref, Role

__all__ = ["VelocityResult", "draw_input_velocity", "velocity_value", "vector_label", "speed_text"]


def vector_label(point: str) -> str:
    """The label of a velocity vector: ``V_A`` (the figure sets the subscript)."""
    return f"V_{point}"


@dataclass
class VelocityResult:
    """One point's velocity found by one graphical method.

    ``steps`` are the refs the method drew, in order (the input vector first); a
    figure of the method draws these and the centres they rest on, nothing more.
    """

    method: str
    point: str
    link: int
    vector: Ref
    scale: float
    steps: list[Ref] = field(default_factory=list)

    def value(self, construction: Construction) -> tuple[float, float]:
        """The velocity in m/s, read off the drawn vector at the drawing's scale."""
        return velocity_value(construction, self.vector, self.scale)


def velocity_value(construction: Construction, ref: Ref, scale: float) -> tuple[float, float]:
    """Read a drawn velocity segment back as m/s."""
    vx, vy = construction.output(ref).vector
    return vx / scale, vy / scale


def draw_input_velocity(asm: Assembly, scale: float) -> tuple[str, Ref]:
    """Lay off the known velocity of the input link's point, ⟂ the link, once per construction.

    Returns the point's name and the ref of its vector ``V:<point>``. The length
    is ω·r at ``scale`` and the sense follows ω (counter-clockwise positive).
    """
    m = asm.mechanism
    d = m.drive
    k = m.link(d.link)
    pivot, point = k.names[0], k.names[1]
    ref = f"V:{point}"
    c = asm.construction
    if ref in c:
        return point, ref
    r = k.span(pivot, point)
    speed = m.input_speed
    units = m.units
    sense = "ccw" if d.omega > 0 else "cw"
    perp = c.draw(f"v:perp:{point}", "perpendicular_through", asm.points[point],
                  asm.axes[d.link],
                  sentence=f"At {point} draw the perpendicular to {pivot}{point}.")
    tip = c.draw(f"v:tip:{point}", "lay_off", asm.points[point], perp,
                 length=d.omega * r * scale,
                 sentence=f"Lay off V_{point} = ω{d.link}·{pivot}{point} = {abs(d.omega):.6g} "
                          f"rad/s × {units.length_text(r)} = {speed_text(speed, units)} along it, "
                          f"in the sense of ω{d.link} ({sense}).")
    c.draw(ref, "join", asm.points[point], tip, label=vector_label(point), role=Role.GIVEN,
           sentence=f"V_{point} is the known velocity.")
    return point, ref


def speed_text(v: float, units) -> str:
    """A speed (m/s) in the file's length unit per second: "250 mm/s"."""
    return f"{v / units.metres:.6g} {units.length}/s"
