"""Persian words of the problem sheet (:mod:`~tarsim.exercises.handout`): its headings, the
data as given and the quantities asked."""

from __future__ import annotations

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
    "the instant centres ({n} of them)": "مراکز آنی ({n} مرکز)",
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
}
"""The problem sheet's words as Persian says them."""
