"""Persian words of a connecting rod given alone: its equivalent dynamical system's steps,
results and figure (:mod:`~tarsim.exercises.forces.rod_solution`)."""

from __future__ import annotations

__all__ = ["WORDS"]

WORDS: dict[str, str] = {
    "equivalent dynamical system: {m1} kg at {pin} and {m2} kg at {d}, l2 = {l2} from G "
    "({far} from {pin})":
        "سیستم دینامیکی معادل: {m1} kg در {pin} و {m2} kg در {d}، l2 = {l2} از G "
        "({far} از {pin})",
    "the masses at the pins: {mp} kg at {p}, {ma} kg at {a}":
        "جرم‌ها در دو پین: {mp} kg در {p}، {ma} kg در {a}",
    "the pin masses' moment of inertia about G m·l1·l3 = {ieq} kg·m², the rod's m·k² = {i} "
    "kg·m²":
        "ممان اینرسی جرم‌های دو پین حول G برابر m·l1·l3 = {ieq} kg·m²، و ممان اینرسی میله "
        "m·k² = {i} kg·m²",
    "correction couple (m·l1·l3 − m·k²)·α = {couple} N·m {sense}":
        "کوپل تصحیح (m·l1·l3 − m·k²)·α = {couple} N·m {sense}",
    "radius of gyration about G k = √(I/m) = {k}":
        "شعاع ژیراسیون حول G برابر k = √(I/m) = {k}",
    "Draw the rod's line of centres to scale: the gudgeon pin {p}, the crank pin {a} {length} "
    "from it, and G {gp} from {p} ({ga} from {a}).":
        "خط مراکز میلهٔ رابط را به مقیاس رسم کنید: گژن‌پین {p}، پین لنگ {a} به فاصلهٔ {length} "
        "از آن، و G به فاصلهٔ {gp} از {p} ({ga} از {a}).",
    "Hung from {about}, G {h} below, it swings once in T = {t} s: as a compound pendulum "
    "T = 2π·√((k² + h²)/(g·h)), so k = √(g·h·T²/(4π²) − h²).":
        "آویخته از {about}، با G به فاصلهٔ {h} زیر آن، هر نوسان را در T = {t} ثانیه می‌زند: "
        "چون آونگ مرکب T = 2π·√((k² + h²)/(g·h))، پس k = √(g·h·T²/(4π²) − h²).",
    "Hung from {about} on a knife edge in its bore, G {h} below, it swings once in T = {t} s: "
    "as a compound pendulum T = 2π·√((k² + h²)/(g·h)), so k = √(g·h·T²/(4π²) − h²).":
        "آویخته از {about} روی لبهٔ چاقویی در سوراخ آن، با G به فاصلهٔ {h} زیر آن، هر نوسان را "
        "در T = {t} ثانیه می‌زند: چون آونگ مرکب T = 2π·√((k² + h²)/(g·h))، پس "
        "k = √(g·h·T²/(4π²) − h²).",
    "The rod's moment of inertia about G: I_G = m·k² = {i} kg·m², k = {k}.":
        "ممان اینرسی میله حول G: I_G = m·k² = {i} kg·m²، k = {k}.",
    "With one mass at {pin}, l1 = G{pin} = {l1}; the other stands at l2 = k²/l1 = {l2} on the "
    "far side of G, at {d}, {far} from {pin}.":
        "با یک جرم در {pin}، l1 = G{pin} = {l1}؛ جرم دیگر به فاصلهٔ l2 = k²/l1 = {l2} در سوی "
        "دیگر G، در {d}، به فاصلهٔ {far} از {pin} قرار می‌گیرد.",
    "They keep the rod's mass and its G: m·l2/(l1 + l2) = {m1} kg at {pin} and "
    "m·l1/(l1 + l2) = {m2} kg at {d}; and since l1·l2 = k², its moment of inertia about G "
    "too.":
        "این دو جرم، جرم میله و G آن را نگه می‌دارند: m·l2/(l1 + l2) = {m1} kg در {pin} و "
        "m·l1/(l1 + l2) = {m2} kg در {d}؛ و چون l1·l2 = k²، ممان اینرسی آن حول G را نیز.",
    "With the two masses at the pins, l1 = G{p} and l3 = G{a}: m·l3/(l1 + l3) = {mp} kg at "
    "{p} and m·l1/(l1 + l3) = {ma} kg at {a} keep the mass and G.":
        "با دو جرم در دو پین، l1 = G{p} و l3 = G{a}: جرم m·l3/(l1 + l3) = {mp} kg در {p} و "
        "m·l1/(l1 + l3) = {ma} kg در {a}، جرم و G را نگه می‌دارند.",
    "Their moment of inertia about G is m·l1·l3 = {ieq} kg·m², the rod's m·k² = {i} kg·m²: "
    "{diff} kg·m² too much.":
        "ممان اینرسی آن‌ها حول G برابر m·l1·l3 = {ieq} kg·m² است و ممان اینرسی میله "
        "m·k² = {i} kg·m²: {diff} kg·m² بیشتر.",
    "Their moment of inertia about G is m·l1·l3 = {ieq} kg·m², the rod's m·k² = {i} kg·m²: "
    "{diff} kg·m² too little.":
        "ممان اینرسی آن‌ها حول G برابر m·l1·l3 = {ieq} kg·m² است و ممان اینرسی میله "
        "m·k² = {i} kg·m²: {diff} kg·m² کمتر.",
    "The two masses' inertia couple differs from the rod's by the correction couple "
    "(m·l1·l3 − m·k²)·α = {couple} N·m, {sense} with α = {alpha} rad/s² {asense}: set it "
    "beside them to make the system dynamically equivalent.":
        "کوپل اینرسی دو جرم با کوپل اینرسی میله به اندازهٔ کوپل تصحیح "
        "(m·l1·l3 − m·k²)·α = {couple} N·m، {sense}، تفاوت دارد، با α = {alpha} rad/s² "
        "{asense}: آن را کنار دو جرم بگذارید تا سیستم از نظر دینامیکی معادل شود.",
    "Connecting rod and its equivalent masses": "میلهٔ رابط و جرم‌های معادل آن",
    "equivalent dynamical system": "سیستم دینامیکی معادل",
    "two masses at the pins": "دو جرم در دو پین",
    "m = {mass} kg, k = {k}": "جرم {mass} کیلوگرم، شعاع ژیراسیون {k}",
    "m = {mass} kg": "جرم {mass} کیلوگرم",
    "correction couple {couple} N·m {sense}":
        "کوپل تصحیح {couple} نیوتن\u200cمتر {sense}",
}
"""A connecting rod's words, by their English."""
