"""Persian words of the problem sheet (:mod:`~tarsim.exercises.handout`): its headings, the
data as given and the quantities asked."""

from __future__ import annotations

from .fa_handout_chapters import WORDS as _CHAPTERS

__all__ = ["WORDS"]

WORDS: dict[str, str] = {
    "problem sheet": "صورت مسئله",
    "Given": "داده‌ها",
    "Find": "خواسته‌ها",
    "fixed points: {points}": "نقاط ثابت: {points}",
    "link {link}: {spans}": "میلهٔ {link}: {spans}",
    "{point} slides on the line through {through} at {angle}":
        "{point} روی خطی می‌لغزد که با زاویهٔ {angle} از {through} می‌گذرد",
    "{alpha} not given: taken as 0": "{alpha} داده نشده است: صفر گرفته می‌شود",
    "at {where}:": "در {where}:",
    " and ": " و ",
    "the instant centres {names}": "مراکز آنی {names}",
    "every instant centre": "همهٔ مراکز آنی",
    "the instant centre": "مرکز آنی",
    "the angular velocity of link {link}": "سرعت زاویه‌ای میلهٔ {link}",
    "the velocity of {point}": "سرعت نقطهٔ {point}",
    "the relative velocity": "سرعت نسبی",
    "the angular acceleration of link {link}": "شتاب زاویه‌ای میلهٔ {link}",
    "the acceleration of {point}": "شتاب نقطهٔ {point}",
    "a component of the acceleration of {point}": "مؤلفه‌ای از شتاب نقطهٔ {point}",
    "the Coriolis component at {point}": "مؤلفهٔ کوریولیس در {point}",
    "the degrees of freedom (Grübler)": "درجهٔ آزادی (گروبلر)",
    "the time ratio of the quick return": "نسبت زمانی بازگشت سریع",
    "the stroke": "کورس",
    "by {methods}": "به روش {methods}",
    # a loaded linkage's loads, the forces asked and their polygons' frames
    "{g} midway along the link": "{g} در میانهٔ میله",
    "{g} at {xy} mm in the link's axes": "{g} در {xy} میلی‌متر در محورهای خود میله",
    "slender rod": "میلهٔ باریک",
    "{name} at {point}: {size} N": "{name} در {point}: {size} N",
    "against the motion": "در خلاف جهت حرکت",
    "at {angle}": "با زاویهٔ {angle}",
    "a couple on link {link}: {moment} N·m": "یک کوپل روی میلهٔ {link}: {moment} N·m",
    "coefficient of fluctuation of speed {cs}": "ضریب نوسان سرعت {cs}",
    "flywheel: {i}": "چرخ لنگر: {i}",
    "the force of link {by} on link {on}": "نیروی میلهٔ {by} بر میلهٔ {on}",
    "the couple of link {by} on link {on}": "کوپل میلهٔ {by} بر میلهٔ {on}",
    "the driving torque on link {link}": "گشتاور محرک روی میلهٔ {link}",
    "the piston effort": "نیروی مؤثر پیستون",
    "the thrust on the cylinder wall": "نیروی جانبی بر دیوارهٔ سیلندر",
    "the inertia force of the reciprocating parts": "نیروی اینرسی قطعات رفت‌وبرگشتی",
    "the crank speed at which the inertia force equals the rest of the load":
        "سرعتی از لنگ که در آن نیروی اینرسی با باقی بار برابر می‌شود",
    "the crank effort": "نیروی مؤثر لنگ",
    "the turning moment": "گشتاور چرخشی",
    "the thrust on the crank shaft's bearings": "نیروی وارد بر یاتاقان‌های میل‌لنگ",
    "the correction couple": "کوپل تصحیح",
    "the flywheel's angular acceleration": "شتاب زاویه‌ای چرخ لنگر",
    "the rod's radius of gyration about G": "شعاع ژیراسیون میلهٔ رابط حول G",
    "the inertia torque of the reciprocating parts": "گشتاور اینرسی قطعات رفت‌وبرگشتی",
    "the inertia torque of the connecting rod": "گشتاور اینرسی میلهٔ رابط",
    "{what}, {links}": "{what}، {links}",
    "Force polygon": "چندضلعی نیرو",
    # a gear train's
    "the train": "قطار",
    "the table to fill in": "جدولی برای پر کردن",
    "on arm {arm}": "روی بازوی {arm}",
    "arm {arm}": "بازوی {arm}",
    "member {member} fixed": "عضو {member} ثابت",
    "meshes: {meshes}": "درگیری‌ها: {meshes}",
    "member {member} turns at {speed}": "عضو {member} با سرعت {speed} می‌چرخد",
    "gears {gears} on one shaft": "چرخ‌دنده‌های {gears} روی یک محور",
    "gears {a} and {b} {d} apart": "چرخ‌دنده‌های {a} و {b} به فاصلهٔ {d} از هم",
    "(about)": "(تقریبی)",
    "its rate of change {rate}": "آهنگ تغییر آن {rate}",
    # a rotor's
    "mass {name}: {mass} kg at {radius}, {angle}, plane at {plane}":
        "جرم {name}: {mass} kg در شعاع {radius}، زاویهٔ {angle}، صفحه در {plane}",
    "its mass at {radius}": "جرم آن در شعاع {radius}",
    "its mass {mass} kg": "جرم آن {mass} kg",
    "balancing plane {name} at {plane}, {held}": "صفحهٔ بالانس {name} در {plane}، {held}",
    "speed {speed}": "سرعت {speed}",
    "in plane {name}: the balancing mass and its angle":
        "در صفحهٔ {name}: جرم بالانس و زاویهٔ آن",
    "in plane {name}: the given mass's radius and its angle":
        "در صفحهٔ {name}: شعاع جرم داده‌شده و زاویهٔ آن",
    # a cam's
    "the displacement diagram to draw": "نمودار جابه‌جایی برای رسم",
    "cam angle across, lift up; draw the displacement here":
        "زاویهٔ بادامک در افق، خیز در قائم؛ نمودار جابه‌جایی را اینجا رسم کنید",
    "the base circle and the follower at the start": "دایرهٔ پایه و پیرو در آغاز دور",
    "pivot": "محور لولا",
    "base circle radius {r}": "شعاع دایرهٔ پایه {r}",
    "follower: {kind}": "پیرو: {kind}",
    "roller radius {r}": "شعاع غلتک {r}",
    "offset {e}": "خروج از محور {e}",
    "arm {arm}, pivot at {xy}": "بازوی {arm}، لولا در {xy}",
    "the cam turns at {speed}": "بادامک با سرعت {speed} می‌چرخد",
    "the displacement diagram, by construction": "نمودار جابه‌جایی، با ترسیم",
    "the cam's profile, by inversion": "پروفیل بادامک، به روش وارونگی",
    "the follower's greatest velocity and acceleration": "بیشینهٔ سرعت و شتاب پیرو",
    "the follower's lift at {theta}": "خیز پیرو در {theta}",
    "dwell": "سکون",
    "blended over {blend} of it at each end": "با {blend} آن در هر سر هموار شده",
    "in {n} divisions": "در {n} بخش",
    "a disc of radius {r} turning {e} off its centre":
        "دیسکی به شعاع {r} که با فاصلهٔ {e} از مرکزش می‌چرخد",
    "the disc": "دیسک",
    "the disc and the follower at the start": "دیسک و پیرو در آغاز دور",
}
"""The problem sheet's words as Persian says them."""

WORDS |= _CHAPTERS
