"""The gear-train model: gears, meshes, shafts, the arm, the fixed member and the input.

A **member** is a gear or the arm (the carrier), numbered as the notes number them. Members
on one shaft turn together: they are one **body**. A gear with a ``carrier`` is a planet:
its axis is carried round by the arm; every other gear turns about a fixed axis (the main
axis, in a planetary train). A **mesh** joins two gears, externally (senses opposite) or
internally (a planet in a ring: senses alike). One member is **fixed**; in an ordinary
train (no arm) the housing is, and no gear is.

Speeds and tooth ratios are exact :class:`~fractions.Fraction`: a Ferguson paradox or a
reverted train with 425/426 has ratios that floating point blurs. :meth:`GearTrain.check`
refuses a train that cannot be built, each failure in one line that names the gears.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from fractions import Fraction

from ..errors import InputError
from ..units import LENGTH_UNITS
from ..narration import Capitalized, Phrase, Word, phrase

__all__ = ["Gear", "Mesh", "GearTrain", "SpeedUnits"]


@dataclass(frozen=True, slots=True)
class Gear:
    """Gear ``number`` with ``teeth``; ``module`` (m, exact) if given; ``carrier`` the arm
    that carries its axis (a planet), else None (a fixed axis)."""

    number: int
    teeth: int | None
    """None while the data leave it to be found (:mod:`.teeth`)."""
    module: Fraction | None = None
    carrier: int | None = None
    name: str = ""
    diameter: Fraction | None = None
    """The pitch diameter (m) the file gives, where it does."""
    circular_pitch: Fraction | None = None
    """The circular pitch p = π·m (m, exact) where the file gives it: ``module`` is then
    p/π at the float value of π, and a distance p·N/(2π) is said over π exactly."""

    @property
    def label(self) -> str:
        """"gear 4 (planet)"."""
        return f"gear {self.number}" + (f" ({self.name})" if self.name else "")


@dataclass(frozen=True, slots=True)
class Mesh:
    """Gears ``a`` and ``b`` in mesh; ``internal`` for a gear inside a ring (the ring is
    the one with more teeth)."""

    a: int
    b: int
    internal: bool = False
    distance: Fraction | None = None
    """The centre distance (m) the file gives the pair, where it does: it fixes their
    teeth with their module, m(N_a ± N_b)/2 (:mod:`.teeth`)."""
    about: Fraction | None = None
    """The approximate centre distance (m) the book gives, "about 600 mm apart": the pair's
    teeth are designed to it and to their ratio, and stand at the exact distance their
    whole counts give (:mod:`.about_distance`)."""
    least: int | None = None
    """The least count the book allows the smaller gear designed to ``about``, if any."""
    bevel: int = 0
    """For a bevel pair, the sense one gear turns the other in, +1 or −1 (0: a spur pair).
    A bevel planet's axis is square to the main axis, so the two gears it meshes there turn
    opposite ways relative to the arm (a differential): its first bevel mesh is taken +1,
    its second −1; a bevel pair on fixed axes +1, each turning the way the book calls
    forward."""

    @property
    def sign(self) -> int:
        """The sense the mesh turns ``b`` in for a turn of ``a``: −1 external, +1 internal,
        a bevel pair's own."""
        return self.bevel or (1 if self.internal else -1)

    @property
    def word(self) -> str:
        """"internal", "external" or "bevel", as a step says the mesh."""
        return "bevel" if self.bevel else "internal" if self.internal else "external"


@dataclass(frozen=True, slots=True)
class SpeedUnits:
    """How the file states speeds: ``rpm`` or ``rad/s``; lengths (the module) in ``length``."""

    speed: str = "rpm"
    length: str = "mm"

    @property
    def per_rad_s(self) -> float:
        """One unit of speed in rad/s."""
        return 2 * math.pi / 60 if self.speed == "rpm" else 1.0


@dataclass(frozen=True)
class GearTrain:
    """A gear train: its gears, meshes, shafts, arm and fixed member, and the input's speed
    (``input_speed``, exact, CCW-positive, in ``units.speed``) on member ``input_member``."""

    gears: tuple[Gear, ...]
    meshes: tuple[Mesh, ...]
    shafts: tuple[tuple[int, ...], ...] = ()
    arm: int | None = None
    arm_name: str = ""
    fixed: int | None = None
    input_member: int = 0
    input_speed: Fraction = Fraction(0)
    units: SpeedUnits = SpeedUnits()
    planets: int = 1
    input_torque: Fraction | None = None
    """The torque (N·m) driving the input, its sense the input's; or else ``input_power``
    (W): the torques then follow from the balance of power."""
    input_power: Fraction | None = None
    name: str = ""
    source: str = ""
    speed_given: bool = True
    """False where the file gives no speed (only ratios or torques are asked): the input
    then turns 1 of the file's unit, and only what does not depend on it is said."""
    implied: tuple[Phrase, ...] = ()
    """The steps that found the teeth the file leaves out (a diameter over its module, the
    coaxial condition), before the speeds."""
    implied_teeth: tuple[int, ...] = ()
    """The gears whose teeth those steps found."""
    coaxial: tuple[int, int] | None = None
    """An ordinary reverted train's two gears on one axis, where the file names them."""
    ratio_given: tuple[tuple[int, int, Fraction], ...] = ()
    """The speed ratios |ω_x/ω_y| the file gives to find teeth by, each (x, y, value)."""
    efficiency: Fraction = Fraction(1)
    """The share of the input's power the output takes (1: no losses)."""
    second: tuple[int, Fraction] | None = None
    """A second member's given speed (member, exact speed), where no member is fixed: a
    planetary train's two degrees of freedom, the arm and a gear both turning, or a sun
    and a ring both driven."""

    # ----- the members ----------------------------------------------------------------------
    def gear(self, number: int) -> Gear:
        """Gear ``number``."""
        return next(g for g in self.gears if g.number == number)

    @property
    def members(self) -> tuple[int, ...]:
        """Every member's number: the gears, then the arm."""
        return tuple(g.number for g in self.gears) + ((self.arm,) if self.arm else ())

    def label(self, member: int, *, opening: bool = False) -> str:
        """How the steps name a member: "gear 4 (planet)", "the arm 3"; ``opening`` a
        sentence, with a capital."""
        if member == self.arm:
            text = f"the arm {member}" + (f" ({self.arm_name})" if self.arm_name and
                                          self.arm_name != "arm" else "")
        else:
            text = self.gear(member).label
        return text[:1].upper() + text[1:] if opening else text

    def said(self, member: int, *, opening: bool = False) -> Phrase | Capitalized:
        """How a step names a member, for each language to say in its own words: "gear 4
        (planet)", "the arm 3" (:meth:`label` in English); ``opening`` a sentence."""
        if member == self.arm:
            named = self.arm_name if self.arm_name and self.arm_name != "arm" else ""
            said = phrase("gears.the_arm", number=member,
                          name=phrase("gears.named", name=Word(named)) if named else None)
        else:
            g = self.gear(member)
            said = phrase("gears.the_gear", number=member,
                          name=phrase("gears.named", name=Word(g.name)) if g.name else None)
        return Capitalized(said) if opening else said

    def body(self, member: int) -> tuple[int, ...]:
        """The members that turn with ``member`` (itself and those on its shafts)."""
        seen, todo = {member}, [member]
        while todo:
            m = todo.pop()
            for shaft in self.shafts:
                if m in shaft:
                    for other in shaft:
                        if other not in seen:
                            seen.add(other)
                            todo.append(other)
        return tuple(sorted(seen))

    @property
    def bodies(self) -> tuple[tuple[int, ...], ...]:
        """The bodies, each once, in the order of their first member."""
        out: list[tuple[int, ...]] = []
        for m in self.members:
            b = self.body(m)
            if b not in out:
                out.append(b)
        return tuple(out)

    def carried(self, member: int) -> bool:
        """True for a member whose axis the arm carries (a planet, or one on its shaft)."""
        return any(m != self.arm and self.gear(m).carrier is not None for m in self.body(member))

    @property
    def planetary(self) -> bool:
        """True if an arm carries any gear."""
        return self.arm is not None and any(g.carrier is not None for g in self.gears)

    @property
    def off_axis(self) -> tuple[int, ...]:
        """In a planetary train, the gears on fixed axes of their own beside the main axis
        (a pinion on a side shaft driving the sun): on the main axis are the arm's body and
        each body with a gear that meshes a planet; every other body not carried is off it.
        """
        if not self.planetary:
            return ()
        main = set(self.body(self.arm))
        for mesh in self.meshes:
            for a, b in ((mesh.a, mesh.b), (mesh.b, mesh.a)):
                if self.carried(a) and not self.carried(b):
                    main.update(self.body(b))
        return tuple(m for m in self.members if m not in main and not self.carried(m))

    def square(self, member: int) -> bool:
        """True for a gear turning about an axis square to the main axis: a bevel planet
        spinning on the arm, or a gear on a side shaft meshing the main axis through bevel
        teeth (a car's pinion). Its turns are no turns about the main axis."""
        if not self.planetary or member == self.arm or not (
                self.carried(member) or member in self.off_axis):
            return False
        body = set(self.body(member))
        return any(m.bevel and {m.a, m.b} & body for m in self.meshes)

    def mobility(self) -> tuple[int, int, int, int]:
        """Grübler's count ``(dof, n, f1, f2)``: the bodies and the frame (the fixed member
        is the frame, or the housing when no member is fixed) are the links; each moving
        body turns on one pin (about the frame, or about the arm for a planet), and each
        mesh is a higher pair (the notes' Q1: 3(4 − 1) − 2·3 − 2 = 1)."""
        moving = [b for b in self.bodies if self.fixed is None or self.fixed not in b]
        n, f1, f2 = len(moving) + 1, len(moving), len(self.meshes)
        return 3 * (n - 1) - 2 * f1 - f2, n, f1, f2

    def describe(self) -> list[Phrase]:
        """The train as its side view shows it, a sentence a member and a mesh."""
        out = []
        side = self.off_axis
        for g in self.gears:
            if self.planetary and self.carried(g.number):
                where = phrase("gears.on_pin", arm=self.arm)
            else:
                where = phrase("gears.on_axis" if self.planetary and g.number not in side
                               else "gears.on_own_axis")
            others = [m for m in self.body(g.number) if m != g.number]
            out.append(phrase("gears.member", member=self.said(g.number, opening=True),
                              teeth=g.teeth, where=where,
                              shaft=phrase("gears.one_shaft", others=", ".join(map(str, others)))
                              if others else None,
                              fixed=(phrase("gears.held_planet") if self.carried(g.number)
                                     else phrase("gears.fixed")) if self.fixed == g.number
                              else None))
        if self.arm is not None:
            out.append(phrase("gears.arm", arm=self.arm,
                              planets=phrase("gears.one_planet") if self.planets == 1 else
                              phrase("gears.planets", n=self.planets),
                              fixed=phrase("gears.fixed") if self.fixed == self.arm else None))
        for m in self.meshes:
            out.append(phrase("gears.meshes_bevel", a=m.a, b=m.b) if m.bevel else
                       phrase("gears.meshes", a=m.a, b=m.b, kind=Word(m.word)))
        return out

    # ----- the checks ---------------------------------------------------------------------
    def check(self) -> None:
        """Refuse a train that cannot be built, in one line naming the gears.

        Raises
        ------
        InputError
            For a mesh between gears of different module, coaxial members at different
            centre distances, planets that do not fit round the sun or cannot be spaced
            equally, a fixed member or input that is not a member, a planet fixed, or a
            Grübler count other than 1.
        """
        self.check_names()
        for m in (self.fixed, self.input_member, self.second and self.second[0]):
            if m is not None and m not in self.members:
                raise self._fail(f"there is no member {m}; the members are "
                                 f"{', '.join(map(str, self.members))}")
        for mesh in self.meshes:
            a, b = self.gear(mesh.a), self.gear(mesh.b)
            if a.module is not None and b.module is not None and a.module != b.module:
                raise self._fail(f"{a.label} (module {self._length(a.module)}) and "
                                 f"{b.label} (module {self._length(b.module)}) mesh but "
                                 "their modules differ")
            if mesh.b in self.body(mesh.a):
                raise self._fail(f"{a.label} and {b.label} turn together on one shaft, so "
                                 "they cannot mesh; take one off the shaft or the mesh")
            if mesh.internal and a.teeth == b.teeth:
                raise self._fail(f"{a.label} and {b.label} mesh internally but have the same "
                                 f"{a.teeth} teeth: a ring has more than the gear inside it")
            if mesh.distance is not None and self._mesh_length(mesh) != mesh.distance:
                raise self._fail(f"{a.label} and {b.label} stand "
                                 f"{self._length(self._mesh_length(mesh))} apart by their "
                                 f"teeth and module, not the centre distance "
                                 f"{self._length(mesh.distance)} given: check the teeth")
        if self.fixed is not None and self.input_member in self.body(self.fixed):
            raise self._fail(f"the input, member {self.input_member}, is the fixed member; "
                             "drive another")
        if self.second is not None:
            self._check_second()
        if self.planetary and self.fixed is None and self.second is None:
            raise self._fail("the arm carries planets but no member is fixed: say which, "
                             "fixed = <number> (before the first table), or give a second "
                             "member's speed in a second [[input]]")
        self._check_joined()
        if self.planetary:
            self._check_coaxial()
        dof, n, f1, f2 = self.mobility()
        given = 1 if self.second is None else 2
        if dof != given:
            if given == 2 and dof == 1:
                raise self._fail(f"the train has 1 degree of freedom by Grübler (3({n} − 1) − "
                                 f"2·{f1} − {f2} = 1), so one speed sets it: give one "
                                 "[[input]], not two")
            raise self._fail(f"the train has {dof} degrees of freedom by Grübler (3({n} − 1) − "
                             f"2·{f1} − {f2} = {dof}), not {given}: "
                             + ("a member turns freely: mesh it, put it on a shaft or fix it"
                                if dof > given else "a member is held twice over"))

    def check_names(self) -> None:
        """Refuse a shaft, a mesh or a carrier that names what is not listed: the first
        of :meth:`check`, run before the teeth are found (they look the gears up)."""
        numbers = [g.number for g in self.gears]
        for shaft in self.shafts:
            for m in shaft:
                if m not in self.members:
                    raise self._fail(f"a shaft names member {m}, which is not listed; the "
                                     f"members are {', '.join(map(str, self.members))}")
        for mesh in self.meshes:
            for k in (mesh.a, mesh.b):
                if k not in numbers:
                    raise self._fail(f"a mesh names gear {k}, which is not listed; the gears "
                                     f"are {', '.join(map(str, numbers))}")
        for g in self.gears:
            if g.carrier is not None and g.carrier != self.arm:
                raise self._fail(f"{g.label} is carried by member {g.carrier}, which is not "
                                 "the arm; name the arm in [arm]")

    def _check_second(self) -> None:
        """Two given speeds need a free arm and two members that do not turn together."""
        m = self.second[0]
        if self.fixed is not None:
            raise self._fail(f"member {self.fixed} is fixed and two speeds are given: that "
                             "holds the train three times over; leave out fixed or one speed")
        if m in self.body(self.input_member):
            raise self._fail(f"two speeds are given to member {self.input_member} and member "
                             f"{m}, which turn together: give the second to another member")

    def _check_joined(self) -> None:
        """Every member hangs together with the input through meshes, shafts and the arm's
        planets."""
        joined, todo = set(self.body(self.input_member)), list(self.body(self.input_member))
        while todo:
            m = todo.pop()
            near = [b for mesh in self.meshes for a, b in ((mesh.a, mesh.b), (mesh.b, mesh.a))
                    if a == m]
            near += [g.number for g in self.gears if g.carrier == m]
            if m != self.arm and self.gear(m).carrier is not None:
                near.append(self.gear(m).carrier)
            for n in near:
                for k in self.body(n):
                    if k not in joined:
                        joined.add(k)
                        todo.append(k)
        lost = [m for m in self.members if m not in joined]
        if lost:
            raise self._fail(f"{self.label(lost[0])} is joined to the rest of the train by no "
                             "mesh or shaft")

    def _check_coaxial(self) -> None:
        """Every planet body stands as far from the main axis by each of its meshes with a
        gear on that axis (a reverted train: N2 + N3 = N4 + N5), in length, each mesh at
        its own module, where every such mesh gives one; equally spaced planets clear one
        another and satisfy the assembly condition. Where the sizes are not given, meshes
        that differ in modules alone are the book's to make good (different modules, or
        corrected teeth): :meth:`uncoaxial` names them, and they are not refused."""
        for body, radii in self._planet_meshes():
            lengths = [(self._mesh_length(mesh), p, c) for mesh, p, c in radii]
            if all(r is not None for r, _, _ in lengths):
                for (r0, p0, c0), (r, p, c) in zip(lengths, lengths[1:]):
                    if r != r0:
                        both = (self.gear(p0).label if p == p0 else
                                f"{self.gear(p0).label} and {self.gear(p).label} on one axis")
                        raise self._fail(
                            f"the arm cannot carry {both}: meshing with {self.gear(c0).label} "
                            f"puts it {self._length(r0)} from the main axis, with "
                            f"{self.gear(c).label} {self._length(r)}")
            self._check_planets(body, [(self._centre_distance(mesh), p, c)
                                       for mesh, p, c in radii])

    def _planet_meshes(self):
        """Each planet body, with its meshes with main-axis gears as (mesh, planet gear,
        main-axis gear)."""
        for body in self.bodies:
            if not self.carried(body[0]):
                continue
            yield body, [(mesh, p, c) for mesh in self.meshes
                         for p, c in ((mesh.a, mesh.b), (mesh.b, mesh.a))
                         if p in body and not self.carried(c) and not mesh.bevel]

    def uncoaxial(self, sized_too: bool = False) -> list[tuple[int, int, Fraction, int,
                                                             Fraction]]:
        """The planet meshes whose centre distances differ at :meth:`_module`'s sizes (in
        modules unless every gear gives one) where the sizes are not all given (or, with
        ``sized_too``, where each mesh's own module makes them agree), as (planet gear,
        first main-axis gear, its distance, the other, its distance)."""
        out = []
        for _, radii in self._planet_meshes():
            if not sized_too and all(self._mesh_length(mesh) is not None
                                     for mesh, _, _ in radii):
                continue
            found = [(self._centre_distance(mesh), p, c) for mesh, p, c in radii]
            for r, p, c in found[1:]:
                if r != found[0][0]:
                    out.append((p, found[0][2], found[0][0], c, r))
        return out

    def _mesh_length(self, mesh: Mesh) -> Fraction | None:
        """The mesh's centre distance in length at its own module, m(N_a ± N_b)/2; None
        where neither gear gives its module."""
        a, b = self.gear(mesh.a), self.gear(mesh.b)
        m = a.module if a.module is not None else b.module
        if m is None:
            return None
        return m * (abs(a.teeth - b.teeth) if mesh.internal else a.teeth + b.teeth) / 2

    def _centre_distance(self, mesh: Mesh) -> Fraction:
        """Half the sum (external) or difference (internal) of the pitch diameters, m·N; in
        teeth (a common module of 1) where no module is given."""
        a, b = self.gear(mesh.a), self.gear(mesh.b)
        da, db = (g.teeth * self._module(g) for g in (a, b))
        return Fraction(abs(da - db), 2) if mesh.internal else Fraction(da + db, 2)

    def _check_planets(self, body: tuple[int, ...], radii) -> None:
        """With k equally spaced planets: each planet's tip circle clears its neighbours',
        and the sun and ring teeth sum to a multiple of k (the assembly condition)."""
        k = self.planets
        if k < 2 or not radii:
            return
        arm_r = radii[0][0]
        for p in body:
            g = self.gear(p) if p != self.arm else None
            if g is None:
                continue
            tip = (g.teeth + 2) * self._module(g)   # an addendum of one module each side
            if 2 * arm_r * math.sin(math.pi / k) <= tip:
                raise self._fail(f"{k} planets {g.label} do not fit round the sun: their tip "
                                 f"circles ({self._span(tip)} across) overlap on a "
                                 f"circle of radius {self._span(arm_r)}")
        suns = [c for _, p, c in radii if not any(m.internal and c in (m.a, m.b) and
                                                   p in (m.a, m.b) for m in self.meshes)]
        rings = [c for _, p, c in radii if c not in suns]
        if len(body) == 1 and suns and rings:
            total = self.gear(suns[0]).teeth + self.gear(rings[0]).teeth
            if total % k:
                raise self._fail(f"{k} planets cannot be spaced equally: the sun's and the "
                                 f"ring's teeth, {self.gear(suns[0]).teeth} + "
                                 f"{self.gear(rings[0]).teeth} = {total}, are not a multiple "
                                 f"of {k}")

    def _module(self, g: Gear) -> Fraction:
        """The module the sizes are taken at: the gear's, where every gear gives one; else
        1 for all (the sizes in modules, the teeth alone deciding)."""
        return g.module if all(h.module is not None for h in self.gears) else Fraction(1)

    def size_text(self, value: Fraction) -> str | Phrase:
        """A size as the steps say it (see :meth:`_span`): "50 mm", or "50 modules"."""
        if any(g.module is None for g in self.gears):
            return phrase("gears.modules", value=_text(value))
        return self._span(value)

    @property
    def sized(self) -> bool:
        """True if every gear gives its module (sizes in metres); else sizes are in modules."""
        return all(g.module is not None for g in self.gears)

    def pitch_radius(self, number: int) -> Fraction:
        """Gear ``number``'s pitch radius, m·N/2 (in modules where a gear gives none)."""
        return self.gear(number).teeth * self._module(self.gear(number)) / 2

    def _span(self, value: Fraction) -> str:
        """A distance the checks found: in the file's length unit, or in modules where a
        gear gives none (the teeth then set the sizes, one module a tooth)."""
        if any(g.module is None for g in self.gears):
            return f"{_text(value)} modules"
        return self._length(value)

    def _length(self, metres: Fraction) -> str:
        return f"{float(metres) / LENGTH_UNITS[self.units.length]:g} {self.units.length}"

    def _fail(self, message: str) -> InputError:
        return InputError(message, file=self.source or None)


def _text(x: Fraction) -> str:
    return str(x.numerator) if x.denominator == 1 else f"{float(x):g}"
