"""Persian (فارسی): the words of every step as the course's own notes word them.

The terms are the notes' (docs/glossary-fa.md lists each with where the notes use it).
Point and link names stay as the notes write them, in Latin letters and digits (O2, A,
I13); numbers are written in Persian digits (۰–۹, with ٫ for the decimal point), which
keep their left-to-right order inside right-to-left text, as the Unicode bidirectional
algorithm sets Persian digits.
"""

from __future__ import annotations

from . import (fa_balancing, fa_cams, fa_forces, fa_grading, fa_handout, fa_positions, fa_rod,
               fa_trains, fa_velocities)

__all__ = ["PHRASES", "WORDS", "UNITS", "digits", "capitalized", "DIGITS", "DIRECTION"]

DIRECTION = "rtl"
"""Persian reads right to left: a figure's caption aligns right, a table's columns mirror."""

DIGITS = str.maketrans("0123456789.", "۰۱۲۳۴۵۶۷۸۹٫")
"""ASCII digits and the decimal point as Persian writes them."""


def digits(text: str) -> str:
    """A number as Persian writes it: Persian digits and decimal point; its sign and
    exponent stay (−۲٫۵e-۷).

    >>> digits("25"), digits("−406.712")
    ('۲۵', '−۴۰۶٫۷۱۲')
    """
    return text.translate(DIGITS)


def capitalized(text: str) -> str:
    """Persian has no capitals: a clause opens a sentence as it is."""
    return text


UNITS: dict[str, str] = {
    "mm": "میلی\u200cمتر", "cm": "سانتی\u200cمتر", "m": "متر", "in": "اینچ",
    "rad": "رادیان", "/s": " بر ثانیه", "/s²": " بر مجذور ثانیه", "/s³": " بر مکعب ثانیه",
    "N": "نیوتن", "N·m": "نیوتن\u200cمتر", "kg": "کیلوگرم", "kg·m": "کیلوگرم\u200cمتر",
    "kg·m²": "کیلوگرم\u200cمترمربع", "rpm": "دور بر دقیقه", "modules": "مدول", "J": "ژول",
    "kJ": "کیلوژول",
}
"""Unit names as Persian says them ("میلی‌متر بر ثانیه"); the degree sign stays."""

WORDS: dict[str, str] = {
    "at rest": "ساکن", "ccw": "پادساعتگرد", "cw": "ساعتگرد",
    "counter-clockwise": "پادساعتگرد", "clockwise": "ساعتگرد", "forward": "جلو",
    "back": "عقب", "first": "اول", "second": "دوم", "the same side": "یک سمت",
    "opposite sides": "دو سمت مخالف", "left": "چپ", "right": "راست",
    "velocity": "سرعت", "acceleration": "شتاب", "slow": "کند", "quick": "تند",
    "fast": "تند", "extended": "در امتداد هم", "folded": "روی هم",
    # figure and section headings (steps.md)
    "Instant centres": "مراکز آنی", "The instant centres asked": "مراکز آنی خواسته\u200cشده",
    "Centres for the angular velocities":
        "مراکز آنی برای سرعت\u200cهای زاویه\u200cای",
    "Circle diagram": "دایرهٔ کمکی", "Equivalent linkage": "مکانیزم معادل",
    "Force polygons": "چندضلعی\u200cهای نیرو", "Free bodies": "نمودارهای جسم آزاد",
    "Klein's construction": "ترسیم کلاین", "Limit positions": "وضعیت\u200cهای حدی",
    "Loads": "بارها", "Positions by compass": "وضعیت\u200cها با پرگار",
    "Worked solution": "حل کامل", "Velocity polygon": "چندضلعی سرعت",
    "Acceleration polygon": "چندضلعی شتاب",
    "Inertia loads read off the acceleration polygon":
        "بارهای اینرسی از روی چندضلعی شتاب",
    "The force polygons": "چندضلعی\u200cهای نیرو",
    "0 (no couple)": "۰ (بدون کوپل)",
    # methods, as the results tables and the headings name them
    "radius rotation": "دوران شعاع", "parallel lines": "خطوط موازی",
    "components": "مؤلفه\u200cها", "the line of transmission": "خط انتقال",
    "force polygons": "چندضلعی\u200cهای نیرو", "inspection (pin)": "مشاهده (لولا)",
    "Kennedy (circle diagram)": "کندی (دایرهٔ کمکی)", "velocity polygon": "چندضلعی سرعت",
    "acceleration polygon": "چندضلعی شتاب",
    "instant centres (ω ratio)": "مراکز آنی (نسبت ω)",
    "inspection (block on a straight guide)": "مشاهده (لغزنده روی راهنمای مستقیم)",
    "acceleration polygon (2ω×v_rel)": "چندضلعی شتاب (2ω×v_rel)",
    "limit positions by compass (lever tangent to the crank circle)":
        "وضعیت\u200cهای حدی با پرگار (اهرم مماس بر دایرهٔ لنگ)",
    "limit positions by compass (crank and rod in line)":
        "وضعیت\u200cهای حدی با پرگار (لنگ و میلهٔ رابط در یک امتداد)",
    "inspection (rolling contact: the contact point)": "مشاهده (تماس غلتشی: نقطهٔ تماس)",
    "Kennedy line and velocity ratio": "خط کندی و نسبت سرعت",
    "the guide's left (a quarter turn counter-clockwise from its direction)":
        "سمت چپ راهنما (یک ربع دور پادساعتگرد از راستای آن)",
    "the guide's right (a quarter turn clockwise from its direction)":
        "سمت راست راهنما (یک ربع دور ساعتگرد از راستای آن)",
    # ----- the figures' own words (graphics/: captions, legends, tables) -----------------
    # A title: the mechanism's name (the file's [names] fa), then what the figure shows.
    "{name}: {what}": "{name}: {what}",
    # A position ("t = 2.34 s (θ2 = −44°)") is embedded left to right (LRE … PDF), so that
    # its brackets pair in the PDF route's bidi as a browser pairs them.
    "{name}: {what} at {where}": "{name}: {what} در \u202a{where}\u202c",
    "{title} (continued)": "{title} (ادامه)",
    "Scale": "مقیاس", "Velocity scale": "مقیاس سرعت", "Acceleration scale": "مقیاس شتاب",
    ", ": "، ",
    "Force scale": "مقیاس نیرو",
    "Kennedy line": "خط کندی", "common normal": "عمود مشترک", "gauge line": "خط سنجه",
    "construction line": "خط ترسیم", "a point": "یک نقطه",
    "to {name}, {length} from {near}": "به سوی {name}، {length} از {near}",
    "stroke": "کورس",
    "Stroke of {point}: {length}.": "کورس {point}: {length}.",
    "n = {n} links, N = n(n−1)/2 = {total} centres: {primaries} by inspection, "
    "{kennedy} by Kennedy":
        "n = {n} میله، N = n(n−1)/2 = {total} مرکز آنی: {primaries} با مشاهده، {kennedy} با "
        "قضیهٔ کندی",
    "Found by Kennedy, in order (dashed chords):":
        "یافته با قضیهٔ کندی، به ترتیب (وترهای خط\u200cچین):",
    "Found by Kennedy, the first {found} of {kennedy}:":
        "یافته با قضیهٔ کندی، {found} مرکز نخست از {kennedy}:",
    # the results tables
    "quantity": "کمیت", "method": "روش", "construction": "ترسیم", "analytic": "تحلیلی",
    "relative error": "خطای نسبی", "answer": "پاسخ", "check": "وارسی",
    "{what} at {where}": "{what} در {where}",
    "{what} at {where}, {along} from {point}": "{what} در {where}، {along} از {point}",
    "any point (no relative motion)": "هر نقطه (بی\u200cحرکت نسبی)",
    "at infinity, direction ({dx}, {dy})": "در بی\u200cنهایت، در راستای ({dx}, {dy})",
    # what a figure shows, after the mechanism's name in its title
    "instant centres": "مراکز آنی", "the instant centres asked": "مراکز آنی خواسته\u200cشده",
    "space diagram": "نمودار فضایی",
    "worked solution": "حل کامل", "limit positions": "وضعیت\u200cهای حدی",
    "loads": "بارها", "free bodies": "نمودارهای جسم آزاد",
    "space diagram with the loads": "نمودار فضایی با بارها",
    "free-body diagrams": "نمودارهای جسم آزاد", "positions by compass": "وضعیت\u200cها با پرگار",
    "equivalent linkage": "مکانیزم معادل",
    "Klein's construction (V = ω·OM)": "ترسیم کلاین (V = ω·OM)",
    "Klein's construction (a = ω²·NO)": "ترسیم کلاین (a = ω²·NO)",
    "Klein's construction (V = ω·Od, d on CM)": "ترسیم کلاین (V = ω·Od، d روی CM)",
    "Klein's construction (a = ω²·d′O, d′ on CN)": "ترسیم کلاین (a = ω²·d′O، d′ روی CN)",
    "Klein's construction (V = ω·Od, CMd similar to the rod)":
        "ترسیم کلاین (V = ω·Od، مثلث روی CM متشابه با میله)",
    "Klein's construction (a = ω²·d′O, CNd′ similar to the rod)":
        "ترسیم کلاین (a = ω²·d′O، مثلث روی CN متشابه با میله)",
    "Klein's construction (ω = ω₂·CM/CP)": "ترسیم کلاین (ω = ω₂·CM/CP)",
    "Klein's construction (α = ω₂²·QN/CP)": "ترسیم کلاین (α = ω₂²·QN/CP)",
    "circle diagram": "دایرهٔ کمکی",
    # the mechanism as a whole (exercises/linkages/solution_files.py: overall_text)
    "crank-rocker": "لنگ - آونگ", "double-crank": "لنگ - لنگ", "double-rocker": "آونگ - آونگ",
    "triple-rocker": "سه‌آونگی", "change-point": "نقطهٔ تغییر",
    "{span} = {length} only ({kind})": "{span} تنها برابر {length} ({kind})",
    "{value} ({here} at this position)": "{value} ({here} در این وضعیت)",
    "{swing} ({tilt} from the line of centres)": "{swing} ({tilt} با خط مراکز)",
    "{angle} from the dead centre (crank at {crank})": "{angle} از نقطهٔ مرگ (لنگ در {crank})",
    "{speed} at {where}": "{speed} در {where}",
    "{value} ({inspection} by inspection, {kennedy} by Kennedy; {far} at infinity)":
        "{value} ({inspection} با مشاهده، {kennedy} با قضیهٔ کندی؛ {far} در بی‌نهایت)",
    "found": "یافته", "Willis": "ویلیس", "the same": "برابر", "yes": "بله", "NO": "خیر",
    "internal": "داخلی", "external": "خارجی", "the same way": "در همان جهت",
    "the other way": "در جهت مخالف", "negative: opposite senses": "منفی: جهت\u200cها مخالف",
    "positive: one sense": "مثبت: یک جهت", "tabular": "جدولی",
    "pitch circle": "دایرهٔ گام", "base circle": "دایرهٔ پایه", "addendum circle": "دایرهٔ سر",
    "root circle": "دایرهٔ ریشه", "no angular acceleration": "بی\u200cشتاب زاویه\u200cای",
    "train value": "مقدار قطار",
    "approximate distance and speed ratio": "فاصلهٔ تقریبی و نسبت سرعت",
    "teeth and circular pitch": "دندانه‌ها و گام محیطی",
    "the pairs' distances added": "جمع فاصله‌های جفت‌ها",
    # the interactive page (tarsim view)
    "figure": "شکل", "play": "پخش",
    "download this frame (SVG)": "بارگیری این قاب (SVG)", "Kennedy lines": "خطوط کندی",
    "reset view": "بازگشت به نمای نخست",
    "labels": "برچسب\u200cها", "step numbers": "شمارهٔ مراحل",
    # a graded drawing's overlay
    "correct": "درست", "wrong magnitude": "اندازهٔ نادرست", "wrong direction": "راستای نادرست",
    "wrong sense": "جهت نادرست", "wrong position": "جای نادرست", "missing": "جاافتاده",
    "extra": "اضافه", "{source}: score {score} %": "{source}: نمره {score}٪",
    "reversed Coriolis": "کوریولیس وارونه", "swapped": "برچسب‌های جابه‌جا",
}
"""Small words and headings as Persian says them."""

PHRASES: dict[str, str] = {
    "note.alpha_not_given": "α{link} داده نشده است، پس صفر گرفته می\u200cشود.",
    "note.ill_conditioned": "{centre} بدوضع است: عدد وضعیت {cond} در ترسیم آن (دو خط خودش "
                            "با زاویهٔ {angle}° یکدیگر را قطع می\u200cکنند)",
    "note.unvouched": "{quantity} به روش {method} آورده نشده است: {why}، پس در این وضعیت "
                      "نمی\u200cتوان درستی آن را تضمین کرد؛ {other} آن را می\u200cدهد.",
    "weak.reference": "مقدار تحلیلی خود در این وضعیت در گردکردن گم می\u200cشود",
    "weak.lines": "دو خط آن با زاویهٔ {angle}° یکدیگر را قطع می\u200cکنند",
    "weak.arcs": "دو کمان آن تقریباً بر هم مماس\u200cاند",
    "weak.line_arc": "خط آن تقریباً بر کمانش مماس است",
    "weak.points": "خطی از دو نقطهٔ تقریباً منطبق می\u200cگذرد",
    "weak.act": "ترسیم آن بدوضع است",
    "weak.short": "بردارهای آن به درازای {share} اندازهٔ مکانیزم رسم می\u200cشوند",
    "note.given_rate": "{what} = {value} داده شده است: چندضلعی سرعتی که با ω{link} = ۱ رادیان "
                       "بر ثانیه رسم شود {target} = {per} می\u200cدهد، پس ω{link} = "
                       "{omega}{sense}{second}.",
    "note.given_alpha": "؛ چندضلعی\u200cهای شتابی که با همان ω و با α{link} = ۰ و ۱ رادیان بر "
                        "مجذور ثانیه رسم شوند α{link} = {alpha} می\u200cدهند",
    "note.along_guide": "V_{point} در امتداد راهنمایش",
    "note.about_pivot": "V_{point} عمود بر {pivot}{point}",
    "note.sense": " ({sense})",
    "md.title": "{name}: حل کامل",
    "md.at": "در {where}",
    "md.position": "وضعیت: θ{link} = {angle}، ω{link} = {omega} rad/s {sense}، α{link} = "
                   "{alpha} rad/s²{given}.",
    "md.not_given": " (داده نشده: ۰)",
    "md.results": "نتایج",
    "md.columns": "| کمیت | ترسیم | تحلیلی | خطای نسبی | روش |",
    "md.whole": "مکانیزم به‌صورت کل",
    "md.whole_columns": "| کمیت | پاسخ | کنترل | خطای نسبی | روش |",
    "stroke.events": "یک دور با سرعت ثابت، صفرهایش تا آخرین بیت تنگ شده",
    "overall.grubler": "گروبلر: 3({n} − 1) − 2·{f1} − {f2}",
    "overall.meeting": "{grubler}؛ در این وضعیت، {points} جایی است که دو حالت مونتاژ مکانیزم "
                       "به هم می‌رسند (نقطهٔ تغییر)، پس درجهٔ آزادی در این لحظه {here} است",
    "overall.meetings": "{grubler}؛ در این وضعیت، {points} جاهایی‌اند که دو حالت مونتاژ "
                        "مکانیزم به هم می‌رسند (نقطهٔ تغییر)، پس درجهٔ آزادی در این لحظه "
                        "{here} است",
    "overall.grashof": "گراشف: S + L = {s_l} در برابر P + Q = {p_q}؛ با چرخاندن هر عضو "
                       "کنترل شده است{which}",
    "overall.range": "نامساوی‌های گراشف، در نقاط مرزی‌شان؛ با تنصیف آزمون چرخش کنترل شده "
                     "است{which}",
    "overall.change_point": "؛ مکانیزم نقطهٔ تغییر (S + L = P + Q): در هر دور دو بار "
                            "عضوهایش در یک راستا قرار می‌گیرند، جایی که دو حالت مونتاژ آن به هم "
                            "می‌رسند و می‌تواند در هر یک ادامه دهد",
    "md.by": "{what} به روش {method}",
    "md.time_ratio": "لنگ در کورس کند {slow}° از {start} تا {end} ({sense}) و در کورس تند "
                     "{quick}° می‌چرخد: نسبت زمانی {slow}/{quick} = {ratio}.",
    "md.heading": "{heading}",
    "md.other_form": "شکل رایج دیگر:",
    "md.chain_rule": "بادامک با سرعت ثابت می\u200cچرخد، پس ẏ = y′ω و ÿ = y″ω² (قاعدهٔ "
                     "زنجیره\u200cای جزوه با α = 0).",
    "md.jumps": "ÿ در θ = {jumps} جهش دارد: جرک در آنجا بی\u200cنهایت است.",
    "heading.train": "قطار چرخدنده",
    "heading.tabular": "روش جدولی",
    "heading.train_value": "مقدار قطار",
    "heading.involute": "درگیری اینولوتی",
    "heading.kutzbach": "نمودار سرعت (کوتزباخ)",
    "heading.displacement": "نمودار جابه\u200cجایی",
    "heading.peaks": "بیشینه\u200cها",
    "heading.profile": "پروفیل به روش وارونگی",
    "heading.construction": "ترسیم",
}


# Each chapter's phrases and its figures' words, kept in a module of the chapter's own.
for _chapter in (fa_positions, fa_velocities, fa_trains, fa_cams, fa_balancing, fa_forces):
    PHRASES.update(_chapter.PHRASES)
for _chapter in (fa_trains, fa_balancing, fa_cams, fa_forces, fa_grading, fa_rod, fa_handout):
    WORDS.update(_chapter.WORDS)
