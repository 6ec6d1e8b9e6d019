"""The settings a balancing file may hold that the kind of exercise it turns out to be has no
use for: each is refused in one line at its file:line, never read and dropped.

A balancing file's tables and keys are all known to the reader, but which are used depends
on the exercise: a rotor balanced by planes, a rotor balancing itself (unknowns "?"), a
single cylinder, a V or radial engine on one crank, cylinders in line, or cylinders whose
unknowns a primary balance finds. A setting known but not used would leave the answer that
of another problem (an engine's ``[[mass]]`` tables dropped gave a locomotive's balance
masses without its coupling rods), so each kind names what it refuses.
"""

from __future__ import annotations

from ..table_file import Tables

__all__ = ["refuse_idle_wheel", "refuse_unused"]

_KINDS = {
    "rotor": "a rotor",
    "open": "a rotor whose masses hold unknowns (\"?\")",
    "single": "a single cylinder",
    "one crank": "an engine on one crank",
    "in line": "cylinders in line",
    "unknowns": "cylinders whose unknowns (\"?\") a primary balance finds",
}


def refuse_unused(t: Tables, kind: str, one: dict | None = None) -> None:
    """Refuse, at its line, the first setting ``kind`` of exercise has no use for (``one``,
    the file's [engine] table, for an engine)."""
    what = _KINDS[kind]
    if kind in ("rotor", "open"):
        if "cylinder" in t.data:
            raise t.fail("[[cylinder]] tables are an [engine]'s: a rotor's masses are [[mass]] "
                         "tables; leave them out, or make the file an [engine]", "cylinder",
                         None, 0)
        for i, m in enumerate(t.entries("mass")):
            if "wheels" in m:
                raise t.fail("wheels puts a locomotive's revolving mass on its coupled wheels, "
                             f"in an [engine] file; it is not taken for {what}: leave it out",
                             "mass", "wheels", i)
    if kind == "open":
        rotor = t.entries("rotor")[0] if "rotor" in t.data else {}
        for key in ("about", "bearings"):
            if key in rotor:
                raise t.fail(f"{key} is for a rotor's out-of-balance force and couple; not "
                             f"taken for {what}, which balances itself: leave it out",
                             "rotor", key)
        if "speed" in rotor:
            raise t.fail(f"speed is not taken for {what}: it balances itself, and its masses, "
                         "angles and planes found need none (nothing asked is a force); leave "
                         "it out", "rotor", "speed")
        return
    if one is None:
        return
    if kind in ("single", "one crank", "unknowns") and t.entries("mass"):
        raise t.fail(f"[[mass]] tables are revolving masses balanced in an in-line engine's "
                     f"[[balance]] planes (a locomotive's wheels); not taken for {what}: "
                     "leave them out", "mass", None, 0)
    refused = {"single": ("coupled",), "one crank": ("coupled", "dead_load", "hammer_blow"),
               "unknowns": ("coupled", "dead_load", "hammer_blow", "strokes"),
               "in line": ()}[kind]
    for key in refused:
        if key in one:
            raise t.fail(f"{key} is not taken for {what}: leave it out", "engine", key)


def refuse_idle_wheel(t: Tables, one: dict) -> None:
    """Refuse a ``wheel_diameter`` nothing uses: it turns a road speed into the cranks'
    speed, or a lift speed into km/h. Asked once the speed is read, so a file with no
    speed hears first that it needs one."""
    if "wheel_diameter" in one and not {"road_speed", "dead_load", "hammer_blow"} & set(one):
        raise t.fail("wheel_diameter goes with road_speed (km/h), the speed on the wheels, or "
                     "with dead_load or hammer_blow, the speed found in km/h: give one, or "
                     "leave it out",
                     "engine", "wheel_diameter")
