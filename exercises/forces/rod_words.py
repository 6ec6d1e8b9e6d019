"""A connecting rod's equivalent dynamical system in numbered steps, as the books work it,
in the language spoken."""

from __future__ import annotations

from tarsim.constructions.narration import numeral, words

__all__ = ["steps"]


def steps(sol) -> list[str]:
    """How the rod is drawn and its masses found, one sentence a step."""
    ex, rod = sol.exercise, sol.exercise.rod
    p, a = ex.ends
    out = [words("Draw the rod's line of centres to scale: the gudgeon pin {p}, the crank pin "
                 "{a} {length} from it, and G {gp} from {p} ({ga} from {a}).", p=p, a=a,
                 length=sol.length(rod.length), gp=sol.length(rod.to_gudgeon),
                 ga=sol.length(rod.to_crank))]
    if ex.pendulum is not None and ex.find != ("pin_masses",):
        period, h, about, bore = ex.pendulum
        out.append(words("Hung from {about}" + (" on a knife edge in its bore" if bore else "")
                         + ", G {h} below, it swings once in T = {t} s: as a compound "
                         "pendulum T = 2π·√((k² + h²)/(g·h)), so k = √(g·h·T²/(4π²) − h²).",
                         about=about, h=sol.length(h), t=numeral(period)))
    if ex.find != ("pin_masses",):
        out.append(words("The rod's moment of inertia about G: I_G = m·k² = {i} kg·m², k = "
                         "{k}.", i=numeral(rod.inertia),
                         k=sol.length((rod.inertia / rod.mass) ** 0.5)))
    if "equivalent_masses" in ex.find:
        e, pin, d = sol.equivalent, ex.one_mass_at, ex.second
        out.append(words("With one mass at {pin}, l1 = G{pin} = {l1}; the other stands at "
                         "l2 = k²/l1 = {l2} on the far side of G, at {d}, {far} from {pin}.",
                         pin=pin, l1=sol.length(e.l1), l2=sol.length(e.l2), d=d,
                         far=sol.length(e.l1 + e.l2)))
        out.append(words("They keep the rod's mass and its G: m·l2/(l1 + l2) = {m1} kg at "
                         "{pin} and m·l1/(l1 + l2) = {m2} kg at {d}; and since l1·l2 = k², "
                         "its moment of inertia about G too.", m1=numeral(e.at_pin), pin=pin,
                         m2=numeral(e.beyond), d=d))
    if {"pin_masses", "equivalent_inertia", "correction_couple"} & set(ex.find):
        out.append(words("With the two masses at the pins, l1 = G{p} and l3 = G{a}: "
                         "m·l3/(l1 + l3) = {mp} kg at {p} and m·l1/(l1 + l3) = {ma} kg at "
                         "{a} keep the mass and G.", p=p, a=a, mp=numeral(sol.at_pins[0]),
                         ma=numeral(sol.at_pins[1])))
    if {"equivalent_inertia", "correction_couple"} & set(ex.find):
        over = sol.pins_inertia - rod.inertia
        out.append(words("Their moment of inertia about G is m·l1·l3 = {ieq} kg·m², "
                         "the rod's m·k² = {i} kg·m²: {diff} kg·m² too much." if over >= 0
                         else "Their moment of inertia about G is m·l1·l3 = {ieq} kg·m², "
                         "the rod's m·k² = {i} kg·m²: {diff} kg·m² too little.",
                         ieq=numeral(sol.pins_inertia), i=numeral(rod.inertia),
                         diff=numeral(abs(over))))
    if "correction_couple" in ex.find:
        out.append(words("The two masses' inertia couple differs from the rod's by the "
                         "correction couple (m·l1·l3 − m·k²)·α = {couple} N·m, {sense} with "
                         "α = {alpha} rad/s² {asense}: set it beside them to make the system "
                         "dynamically equivalent.", couple=numeral(abs(sol.couple)),
                         sense=sol.sense(sol.couple), alpha=numeral(abs(ex.alpha), "g"),
                         asense=sol.sense(ex.alpha)))
    return out
