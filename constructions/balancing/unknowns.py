"""A rotor balanced by its own masses, some of whose mass, radius, angle or plane are
unknown, read off the force and couple polygons as the textbooks set such problems.

Complete balance asks Σ mᵢrᵢ e^{iθᵢ} = 0 (the force polygon closes) and, with the masses in
planes apart, Σ mᵢrᵢ(lᵢ − z) e^{iθᵢ} = 0 about any reference plane z (the couple polygon
closes): two real equations a polygon, so two unknowns each. A polygon closes on its two
unknowns in one of four ways, each a drafting act:

- one vector unknown in size and direction: the closing side, from the last tip back to
  the pole;
- two sizes, along known directions: a line through the last tip parallel to one, a line
  through the pole parallel to the other, cut;
- two directions, of known sizes: an arc of each size about the last tip and the pole, cut
  (two crossings, mirror images: the left one of tip → pole is taken);
- a size along a known direction and a direction of known size: the line cut by the arc
  (of the two crossings, the one that gives a positive mass, else the forward one).

The couple polygon is taken about a known plane of a mass with unknowns, which drops that
mass out of it (the reference-plane method); the polygons are drawn in whichever order
leaves each two unknowns. What is found is read off: a mass (or radius) from its vector's
size, an angle from its direction, a plane from its couple vector's size over m·r.

A mass whose m·r and plane are both unknown shows in the couple polygon as one size,
m·r·(l − z), as the books take it ("the couple polygon closes on m_D·r_D·l_D"): read off
there (with its direction, where that is unknown too, to a half turn: l − z may be
negative), then m·r from the force polygon, which settles the half turn by its sign, and
the plane l = z + (m·r·(l − z))/(m·r).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace

from .. import geometry as g
from ..errors import TarsimError
from ..narration import phrase
from ..record import Construction, Kind, Panel, Ref, Role

__all__ = ["OpenRotor", "Part", "Closure", "close_rotor", "count_unknowns", "growth", "SHIFT"]


@dataclass(frozen=True)
class Part:
    """A mass: its mass (kg), radius (m), angle (rad) and plane (m), None where unknown."""

    name: str
    mass: float | None
    radius: float | None
    angle: float | None
    plane: float | None
    between: tuple[float, float] | None = None
    """Where an unknown angle must come out (rad, counter-clockwise from the first to the
    second): the file's choice between the mirror images a polygon closes on."""

    def admits(self, angle: float) -> bool:
        """Whether ``angle`` (rad) lies in :attr:`between` (any angle does without one)."""
        if self.between is None:
            return True
        lo, hi = self.between
        return (angle - lo) % math.tau <= (hi - lo) % math.tau

    @property
    def size(self) -> float | None:
        """m·r (kg·m), None while either is unknown."""
        return None if self.mass is None or self.radius is None else self.mass * self.radius

    def unknowns(self) -> tuple[str, ...]:
        """The names of what is unknown of it, in the file's order."""
        return tuple(k for k in ("mass", "radius", "angle", "plane") if getattr(self, k) is None)


@dataclass(frozen=True)
class OpenRotor:
    """Masses some of whose data are unknown, to be balanced by themselves: in force alone
    (``static``, every mass in one plane) or in force and couple."""

    parts: tuple[Part, ...]
    speed: float
    static: bool


class CannotClose(TarsimError):
    """The polygons cannot close on these unknowns (one line, naming the masses)."""


@dataclass
class Closure:
    """The drawn polygons and what they found: each part with its unknowns filled in, the
    polygons' tips (name, tip) from their poles, the couple polygon's reference plane, the
    order they were drawn in, and where a crossing of two was chosen."""

    construction: Construction
    parts: dict[str, Part]
    given: dict[str, Part]
    force: list[tuple[str, Ref]] = field(default_factory=list)
    couple: list[tuple[str, Ref]] = field(default_factory=list)
    closing: dict[str, Ref] = field(default_factory=dict)
    last: dict[str, str] = field(default_factory=dict)
    """Each polygon's closing side's mass: the one found last, drawn heavy."""
    reference: tuple[str, float] | None = None
    order: list[str] = field(default_factory=list)
    mirrored: list[str] = field(default_factory=list)
    """The polygons that close on two crossings, mirror images of each other."""
    chosen: dict[str, str] = field(default_factory=dict)
    """Each such polygon's mass whose ``between`` chose the crossing taken; a mirrored
    polygon missing here took the rule's (the left crossing of tip → pole, or the forward
    one along a line)."""
    moments: dict[str, float] = field(default_factory=dict)
    """A mass's m·r·(l − z) read off the couple polygon (kg·m², signed along its angle)
    where its m·r and plane were both unknown: the force polygon's m·r splits it."""
    loose: set[str] = field(default_factory=set)
    """The masses whose angle the couple polygon read to a half turn (m·r and plane
    unknown too): the sign of m·r along it in the force polygon settles it."""
    turned: set[str] = field(default_factory=set)
    """Of :attr:`loose`, those the force polygon turned half round: their radial line
    points away from them."""


def count_unknowns(rotor: OpenRotor) -> int:
    """The unknowns' number, a mass's m and r counting once (only their product shows)."""
    return sum((p.size is None) + (p.angle is None) + (p.plane is None and not rotor.static)
               for p in rotor.parts)


def close_rotor(rotor: OpenRotor) -> Closure:
    """Draw the end view of the known radial lines, then close the force polygon and (for a
    complete balance) the couple polygon on their unknowns, each when it has two left.

    Raises
    ------
    CannotClose
        Where neither polygon has two unknowns left to close on, or a crossing is missing
        (sizes that cannot reach), or a mass comes out negative.
    """
    c = Construction()
    parts = {p.name: p for p in rotor.parts}
    out = Closure(c, parts, dict(parts))
    c.give("O", g.Point(0.0, 0.0), label="O", phrase=phrase("balance.space"))
    for p in rotor.parts:
        if p.angle is not None:
            _radial(c, p.name, p.angle)
    wanted = ["force"] if rotor.static else ["force", "couple"]
    while wanted:
        for which in wanted:
            tried = _try_polygon(out, which, rotor)
            if tried:
                wanted.remove(which)
                break
        else:
            left = [f"{p.name} ({', '.join(p.unknowns())})" for p in out.parts.values()
                    if p.unknowns() and not (rotor.static and p.unknowns() == ("plane",))]
            raise CannotClose(f"neither polygon has just two unknowns to close on "
                              f"({'; '.join(left)}): each closes on two, a mass's m·r and "
                              "plane counting as one in the couple polygon (m·r·l)")
    for p in out.parts.values():
        if f"P{p.name}" not in c:
            c.draw(f"P{p.name}", "lay_off", "O", f"radial{p.name}",
                   length=-p.radius if p.name in out.turned else p.radius, label=p.name)
    return out


SHIFT = 1e-12
"""How far (relative to the sizes summed) rounding may shift a carrier: a few thousand
roundings, for polygons of up to some hundreds of sides."""

SHAKY = 1e-4
"""The relative error past which the unknowns are not read to four figures: refused."""


def growth(out: Closure) -> float:
    """How much the crossings magnify a shift of their carriers: each by 1/sin φ at the
    angle φ it is cut at, and a crossing of an arc, whose point slides along the other
    carrier, by no more than 1/√(2·SHIFT) however shallow (two carriers that touch: a rotor
    balanced with masses along one line); a second polygon drawn from what the first
    found multiplies its own in."""
    c = out.construction
    total = 1.0
    for ref in ("fp:x", "cp:x"):
        if ref in c:
            step = c[ref]
            cond = step.conditioning
            grow = 1.0 / cond if cond > 0 else math.inf
            if step.verb != "intersect_lines":
                grow = min(grow, 1.0 / math.sqrt(2 * SHIFT))
            total *= grow
    return total


def _radial(c: Construction, name: str, angle: float) -> Ref:
    at = c.give(f"R{name}", g.Point(math.cos(angle), math.sin(angle)), label="")
    return c.draw(f"radial{name}", "line_through", "O", at, kind=Kind.LINE)


def _couple_reference(out: Closure) -> list[tuple[str, float]]:
    """The known planes to take couples about, those of masses with the most unknowns
    first: such a plane drops its mass out of the couple polygon."""
    known = [(len(p.unknowns()), p.name, p.plane) for p in out.parts.values()
             if p.plane is not None]
    seen, refs = set(), []
    for _, name, z in sorted(known, key=lambda k: -k[0]):
        if z not in seen:
            seen.add(z)
            refs.append((name, z))
    return refs


def _vectors(out: Closure, which: str, z: float):
    """The polygon's vectors: (name, signed size or None, angle or None, what each unknown
    stands for); a vector with an unknown that cannot be read off alone is 'tangled'."""
    vs = []
    for p in out.parts.values():
        if which == "force":
            vs.append((p.name, p.size, p.angle))
            continue
        if p.plane is not None and p.plane == z:
            continue                            # in the reference plane: no couple
        # m·r·(l − z) is one unknown size where m·r or l is (both: read as the product)
        size = None if p.size is None or p.plane is None else p.size * (p.plane - z)
        vs.append((p.name, size, p.angle))
    return vs


def _try_polygon(out: Closure, which: str, rotor: OpenRotor) -> bool:
    refs = [(None, 0.0)] if which == "force" else _couple_reference(out)
    for ref_name, z in refs:
        vs = _vectors(out, which, z)
        if vs is None:
            continue
        unknown = [v for v in vs if v[1] is None or v[2] is None]
        count = sum((v[1] is None) + (v[2] is None) for v in unknown)
        if count != 2 or (which == "couple" and not _readable(out, unknown)):
            continue
        if which == "couple":
            out.reference = (ref_name, z)
        try:
            _close(out, which, z, [v for v in vs if v not in unknown], unknown)
        except CannotClose:
            raise
        except TarsimError as e:
            # two sizes along one line, or a side of no length: nothing to cut
            names = " and ".join(f"{v[0]}" for v in unknown)
            raise CannotClose(f"the {which} polygon cannot close on the unknowns of {names}: "
                              f"{e}; their directions must differ") from None
        out.order.append(which)
        return True
    return False


def _readable(out: Closure, unknown) -> bool:
    """A couple vector wholly unknown can be read as m·r and θ at a known plane, or as
    m·r·(l − z) and θ (to a half turn) where m·r and l are both unknown; not as l and θ
    for a known m·r, whose half turn nothing settles."""
    def readable(name: str) -> bool:
        p = out.parts[name]
        return p.plane is not None or p.size is None
    return all(not (v[1] is None and v[2] is None) or readable(v[0]) for v in unknown)


def _close(out: Closure, which: str, z: float, known, unknown) -> None:
    """Lay the known vectors head to tail, then close the polygon on its two unknowns."""
    c = out.construction
    panel = Panel.FORCE if which == "force" else Panel.COUPLE
    tag = "fp" if which == "force" else "cp"
    tips = out.force if which == "force" else out.couple
    said = phrase("balance.force.open") if which == "force" else phrase(
        "balance.couple.open", a=out.reference[0])
    pole = c.give(f"{tag}:o", g.Point(0.0, 0.0), label="o", panel=panel, phrase=said)
    tip = pole
    for name, size, _ in known:
        along = c.draw(f"{tag}:par:{name}", "parallel_through", tip, f"radial{name}",
                       kind=Kind.LINE, panel=panel)
        nxt = c.draw(f"{tag}:tip:{name}", "lay_off", tip, along, length=size, label=name,
                     panel=panel)
        c.draw(f"{tag}:v:{name}", "join", tip, nxt, panel=panel)
        tips.append((name, nxt))
        tip = nxt
    if len(unknown) == 1:                       # the closing side is the vector
        (name, _, _), = unknown
        c.draw(f"{tag}:v:{name}", "join", tip, pole, panel=panel, role=Role.RESULT,
               phrase=_found(out, which, name))
        out.closing[which] = f"{tag}:v:{name}"
        out.last[which] = name
        _read(out, which, z, name, tip, pole)
        return
    (n1, s1, a1), (n2, s2, a2) = unknown
    if a1 is None and a2 is not None:           # the known direction first
        (n1, s1, a1), (n2, s2, a2) = (n2, s2, a2), (n1, s1, a1)
    if a1 is not None and a2 is not None:       # two sizes along known directions
        la = c.draw(f"{tag}:par:{n1}", "parallel_through", tip, f"radial{n1}",
                    kind=Kind.LINE, panel=panel)
        lb = c.draw(f"{tag}:par:{n2}", "parallel_through", pole, f"radial{n2}",
                    kind=Kind.LINE, panel=panel)
        x = c.draw(f"{tag}:x", "intersect_lines", la, lb, label="x", panel=panel,
                   phrase=phrase("balance.cut"))
    elif a1 is not None:                        # a size along n1, n2's direction
        la = c.draw(f"{tag}:par:{n1}", "parallel_through", tip, f"radial{n1}",
                    kind=Kind.LINE, panel=panel)
        arc = c.draw(f"{tag}:arc:{n2}", "swing_arc", pole, radius=abs(s2), panel=panel)
        x = _cross(out, which, tag, panel, "intersect_line_circle", (la, arc),
                   ("forward", "backward"), lambda at: _positive(out, which, z, n1, tip, at),
                   _sides(out, which, z, ((n1, tip, None), (n2, None, pole))))
    else:                                       # two directions of known sizes
        a = c.draw(f"{tag}:arc:{n1}", "swing_arc", tip, radius=abs(s1), panel=panel)
        b = c.draw(f"{tag}:arc:{n2}", "swing_arc", pole, radius=abs(s2), panel=panel)
        x = _cross(out, which, tag, panel, "intersect_circles", (a, b), ("left", "right"),
                   lambda at: True, _sides(out, which, z, ((n1, tip, None), (n2, None, pole))))
    if SHIFT * growth(out) > SHAKY:
        raise CannotClose("the polygons' carriers cross too shallowly (nearly parallel "
                          "lines or arcs): the data fix the unknowns to fewer than four "
                          "figures; state the problem with better-spread masses")
    for name, start, end in ((n1, tip, x), (n2, x, pole)):
        c.draw(f"{tag}:v:{name}", "join", start, end, panel=panel, role=Role.RESULT,
               phrase=_found(out, which, name))
        _read(out, which, z, name, start, end)
    tips.append((n1, x))                        # the closing side, x to the pole, is n2
    out.closing[which] = f"{tag}:v:{n2}"
    out.last[which] = n2


def _found(out: Closure, which: str, name: str):
    """What reading ``name``'s side says: its unknowns, or, where its m·r and plane are both
    unknown, the couple polygon's product and the force polygon's split of it."""
    p = out.parts[name]
    if which == "couple" and p.size is None and p.plane is None:
        return phrase("balance.found.product", mass=name)
    if which == "force" and name in out.moments:
        return phrase("balance.found.split", mass=name)
    return phrase("balance.found", mass=name)


def _cross(out: Closure, which: str, tag: str, panel: Panel, verb: str, inputs,
           picks: tuple[str, str], good, sides) -> Ref:
    """Cut two carriers, taking the first crossing that ``good`` accepts; where both are,
    the polygon closes twice (mirror images), and that is told. ``sides(at)`` gives, for a
    crossing, the masses whose angle it finds: (name, angle, whether their ``between``
    admits it); a mass's ``between`` chooses between the mirror images, and a crossing it
    does not admit is not taken."""
    c = out.construction
    taken, found = [], []
    for pick in picks:
        trial = c.scratch()
        try:
            at = trial.draw("x", verb, *inputs, pick=pick)
        except TarsimError as e:
            raise CannotClose(f"the {which} polygon cannot close: the sizes given cannot "
                              f"reach across it ({e})") from None
        if good(trial.output(at)):
            taken.append(pick)
            found.append(sides(trial.output(at)))
    if not taken:
        raise CannotClose(f"the {which} polygon closes only with a negative mass: no mass at "
                          "the angle given balances it")
    if len(taken) == 2:
        out.mirrored.append(which)
    kept = [(pick, side) for pick, side in zip(taken, found) if all(ok for _, _, ok in side)]
    if not kept:
        name = next(n for side in found for n, _, ok in side if not ok)
        p = out.parts[name]
        angles = " or ".join(f"{math.degrees(a) % 360:.2f}°" for side in found
                             for n, a, _ in side if n == name)
        raise CannotClose(f"mass {name}'s angle comes out {angles}, none between "
                          f"{math.degrees(p.between[0]):g}° and {math.degrees(p.between[1]):g}° "
                          "as its between asks")
    if len(taken) == 2 and len(kept) == 1:
        out.chosen[which] = next(n for n, _, _ in kept[0][1] if out.parts[n].between)
    return c.draw(f"{tag}:x", verb, *inputs, pick=kept[0][0], label="x", panel=panel,
                  phrase=phrase("balance.cut"))


def _sides(out: Closure, which: str, z: float, vectors):
    """For a crossing ``at``: each of ``vectors`` (name, start or None for ``at``, end or
    None for ``at``) whose mass's angle is unknown (or known to a half turn), that angle as
    :func:`_read` would read it, and whether the mass's ``between`` admits it."""
    c = out.construction

    def sides(at) -> list[tuple[str, float, bool]]:
        got = []
        for name, start, end in vectors:
            p = out.parts[name]
            if p.angle is not None and name not in out.loose:
                continue
            (x0, y0) = at.xy if start is None else c.output(start).xy
            (x1, y1) = at.xy if end is None else c.output(end).xy
            if p.angle is None:
                angle = _angle_of(out, which, z, name, (x1 - x0, y1 - y0))
            else:                               # the half turn its sense along it gives
                along = (x1 - x0) * math.cos(p.angle) + (y1 - y0) * math.sin(p.angle)
                angle = p.angle if along >= 0 else (p.angle + math.pi) % (2 * math.pi)
            got.append((name, angle, p.admits(angle)))
        return got
    return sides


def _angle_of(out: Closure, which: str, z: float, name: str, v) -> float:
    """The angle (rad, in [0, 2π)) of mass ``name`` whose vector in the polygon is ``v``:
    its direction, turned half round where its couple's arm is negative."""
    p = out.parts[name]
    lever = 1.0 if which == "force" else (None if p.plane is None else p.plane - z)
    turn = math.atan2(v[1], v[0]) + (math.pi if lever is not None and lever < 0 else 0.0)
    return math.remainder(turn, 2 * math.pi) % (2 * math.pi)


def _positive(out: Closure, which: str, z: float, name: str, tip: Ref, at) -> bool:
    """Whether the vector from ``tip`` to ``at``, along ``name``'s line, gives a positive
    mass (or any plane: a plane may lie either side)."""
    p = out.parts[name]
    x0, y0 = out.construction.output(tip).xy
    along = (at.xy[0] - x0) * math.cos(p.angle) + (at.xy[1] - y0) * math.sin(p.angle)
    if (which == "couple" and p.plane is None) or name in out.loose:
        return True                             # a plane either side; a half turn open
    lever = 1.0 if which == "force" else p.plane - z
    return along * lever > 0


def _read(out: Closure, which: str, z: float, name: str, start: Ref, end: Ref) -> None:
    """Read the unknowns of ``name`` off its drawn vector, from ``start`` to ``end``."""
    c = out.construction
    (x0, y0), (x1, y1) = c.output(start).xy, c.output(end).xy
    v = (x1 - x0, y1 - y0)
    p = out.parts[name]
    lever = 1.0 if which == "force" else (None if p.plane is None else p.plane - z)
    product = which == "couple" and p.size is None and p.plane is None
    if p.angle is None:
        p = replace(p, angle=_angle_of(out, which, z, name, v))
        if product:
            out.loose.add(name)                 # l − z may be negative: a half turn open
        else:
            _admitted(p)
        _radial(c, name, p.angle)
    along = v[0] * math.cos(p.angle) + v[1] * math.sin(p.angle)
    if product:
        out.moments[name] = along
        out.parts[name] = p
        return
    if name in out.loose and along < 0:         # the force polygon settles the half turn
        p = replace(p, angle=(p.angle + math.pi) % (2 * math.pi))
        out.moments[name] = -out.moments[name]
        out.turned.add(name)
        along = -along
    if name in out.loose:
        _admitted(p)
    if p.size is None:
        size = along / lever
        if not size > 0:
            raise CannotClose(f"mass {name} comes out negative ({size:.4g} kg·m) from the "
                              f"{which} polygon: no mass at the angle given balances it")
        p = replace(p, mass=size / p.radius) if p.mass is None else replace(
            p, radius=size / p.mass)
        if name in out.moments:                 # the couple polygon's m·r·(l − z) split
            p = replace(p, plane=out.reference[1] + out.moments[name] / size)
    elif p.plane is None and which == "couple":
        p = replace(p, plane=z + along / p.size)
    out.parts[name] = p


def _admitted(p: Part) -> None:
    """Refuse an angle found outside the mass's ``between``."""
    if not p.admits(p.angle):
        raise CannotClose(f"mass {p.name}'s angle comes out {math.degrees(p.angle):.2f}°, not "
                          f"between {math.degrees(p.between[0]):g}° and "
                          f"{math.degrees(p.between[1]):g}° as its between asks")
