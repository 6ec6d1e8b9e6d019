"""The meshes and shafts of a gear-train file: ``[[mesh]]`` (external, internal or bevel, a
centre distance if the book gives one) and ``[[shaft]]``; read by
:class:`~.train_file._Reader`, whose ``fail``, ``exact`` and ``known`` they use."""

from __future__ import annotations

from dataclasses import replace
from fractions import Fraction

from tarsim.constructions.gears.train import Gear, Mesh, SpeedUnits
from tarsim.constructions.units import LENGTH_UNITS

__all__ = ["MeshTables"]


class MeshTables:
    """The reader's part for the meshes and the shafts."""

    def compound_bevel(self, planet: int, meshes: list[Mesh]) -> bool:
        """True where a gear on ``planet``'s shaft has bevel meshes of its own (a
        Humpage's gear's compound bevel planet)."""
        spindle = {m for shaft in self.data.get("shaft") or [] if isinstance(shaft, dict)
                   for m in (shaft.get("members") or []) if planet in (shaft.get("members")
                                                                        or [])} - {planet}
        return any(mesh.bevel and {mesh.a, mesh.b} & spindle for mesh in meshes)

    def meshes(self, units: SpeedUnits, gears: tuple[Gear, ...]) -> tuple[Mesh, ...]:
        """Each ``[[mesh]]``: its two gears, its kind, and its centre distance (in m) where
        the file gives one; a bevel planet's senses set (:meth:`bevel_senses`)."""
        out = []
        for i, t in enumerate(self.data.get("mesh") or []):
            pair = t.get("gears") if isinstance(t, dict) else None
            if not (isinstance(pair, list) and len(pair) == 2 and all(
                    isinstance(g, int) and not isinstance(g, bool) for g in pair)):
                raise self.fail("a mesh names its two gears, gears = [2, 4]", "mesh", "gears", i)
            self.known(t, ("gears", "kind", "centre_distance"), "mesh", i)
            kind = t.get("kind", "external")
            if kind not in ("external", "internal", "bevel"):
                raise self.fail(f"unknown mesh kind '{kind}'; use external, internal or bevel",
                                "mesh", "kind", i)
            if pair[0] == pair[1]:
                raise self.fail(f"gear {pair[0]} cannot mesh with itself", "mesh", "gears", i)
            distance, about = self.centre_distance(t, i, units, pair, gears)
            out.append(Mesh(pair[0], pair[1], kind == "internal", distance, about,
                            bevel=-1 if kind == "bevel" else 0))
        if not out:
            raise self.fail("list the meshes as [[mesh]] tables, gears = [2, 4]", key="mesh")
        return self.bevel_senses(out, gears)

    def centre_distance(self, t: dict, i: int, units: SpeedUnits, pair: list[int],
                        gears: tuple[Gear, ...]) -> tuple[Fraction | None, Fraction | None]:
        """A ``[[mesh]]``'s centre distance (m), exact, ``centre_distance = 600``, or
        approximate, ``centre_distance = { about = 600 }`` (the teeth designed to it), as
        (exact, about). A circular pitch puts whole teeth p(N_a ± N_b)/(2π) apart, never a
        whole distance, so it takes the approximate one."""
        if "centre_distance" not in t:
            return None, None
        v = t["centre_distance"]
        about = isinstance(v, dict)
        if about:
            if set(v) != {"about"}:
                raise self.fail("an approximate centre distance is written centre_distance = "
                                "{ about = … } (in the file's length unit)", "mesh",
                                "centre_distance", i)
            v = v["about"]
        distance = self.exact(v, "a centre distance", "mesh", "centre_distance", i)
        if distance <= 0:
            raise self.fail("a centre distance must be positive", "mesh", "centre_distance", i)
        pitched = [g.number for g in gears if g.number in pair and g.circular_pitch]
        if pitched and not about:
            raise self.fail(f"gear {pitched[0]}'s circular pitch puts whole teeth p(N{pair[0]} "
                            f"± N{pair[1]})/(2π) apart, never exactly {float(distance):g} "
                            f"{units.length}: give centre_distance = {{ about = "
                            f"{float(distance):g} }}", "mesh", "centre_distance", i)
        distance *= Fraction(repr(LENGTH_UNITS[units.length]))
        return (None, distance) if about else (distance, None)

    def bevel_senses(self, meshes: list[Mesh], gears: tuple[Gear, ...]) -> tuple[Mesh, ...]:
        """A bevel planet's meshes with the gears beside it: the first listed +1, the
        second −1, so the two turn opposite ways relative to the arm (a differential); a
        third is refused. A bevel pair on fixed axes, square to each other, turns +1: each
        turns in the sense the book takes as its forward one (a propeller shaft and the
        crown it drives)."""
        carried = {g.number for g in gears if g.carrier is not None}
        seen: dict[int, int] = {}
        out = []
        for i, mesh in enumerate(meshes):
            planet = next((g for g in (mesh.a, mesh.b) if g in carried), None)
            if mesh.bevel and planet is not None and self.compound_bevel(planet, meshes):
                raise self.fail(f"gear {planet}'s bevel meshes and another gear's on its "
                                "spindle: which side of the spindle each main-axis gear "
                                "stands cannot be told from the file; a bevel planet is one "
                                "gear meshing the gears either side of it", "mesh", "kind", i)
            if mesh.bevel and planet is not None:
                seen[planet] = seen.get(planet, 0) + 1
                if seen[planet] > 2:
                    raise self.fail(f"gear {planet} has a third bevel mesh: a bevel planet "
                                    "meshes the two gears either side of it", "mesh", "kind", i)
                mesh = replace(mesh, bevel=1 if seen[planet] == 1 else -1)
            elif mesh.bevel:                # on fixed axes: the senses as the book takes them
                mesh = replace(mesh, bevel=1)
            out.append(mesh)
        return tuple(out)

    def shafts(self) -> tuple[tuple[int, ...], ...]:
        """Each ``[[shaft]]``: the members that turn together."""
        out = []
        for i, t in enumerate(self.data.get("shaft") or []):
            members = t.get("members") if isinstance(t, dict) else None
            if not (isinstance(members, list) and len(members) >= 2 and all(
                    isinstance(m, int) and not isinstance(m, bool) for m in members)):
                raise self.fail("a shaft names the members that turn together, members = "
                                "[3, 4]", "shaft", "members", i)
            self.known(t, ("members",), "shaft", i)
            if len(set(members)) < len(members):
                raise self.fail("a shaft names a member twice", "shaft", "members", i)
            out.append(tuple(members))
        return tuple(out)
