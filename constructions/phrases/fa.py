"""Persian (فارسی): the words of every step as the course's own notes word them.

The terms are the notes' (docs/glossary-fa.md lists each with where the notes use it).
Point and link names stay as the notes write them, in Latin letters and digits (O2, A,
I13); numbers are written in Persian digits (۰–۹, with ٫ for the decimal point), which
keep their left-to-right order inside right-to-left text, as the Unicode bidirectional
algorithm sets Persian digits.
"""

from __future__ import annotations

from . import fa_balancing, fa_cams, fa_forces, fa_grading, fa_trains

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
    "Instant centres": "مراکز آنی", "Centres for the angular velocities":
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
    "any point (no relative motion)": "هر نقطه (بی\u200cحرکت نسبی)",
    "at infinity, direction ({dx}, {dy})": "در بی\u200cنهایت، در راستای ({dx}, {dy})",
    # what a figure shows, after the mechanism's name in its title
    "instant centres": "مراکز آنی", "space diagram": "نمودار فضایی",
    "worked solution": "حل کامل", "limit positions": "وضعیت\u200cهای حدی",
    "loads": "بارها", "free bodies": "نمودارهای جسم آزاد",
    "space diagram with the loads": "نمودار فضایی با بارها",
    "free-body diagrams": "نمودارهای جسم آزاد", "positions by compass": "وضعیت\u200cها با پرگار",
    "equivalent linkage": "مکانیزم معادل",
    "Klein's construction (V = ω·OM)": "ترسیم کلاین (V = ω·OM)",
    "Klein's construction (a = ω²·NO)": "ترسیم کلاین (a = ω²·NO)",
    "circle diagram": "دایرهٔ کمکی",
    # the mechanism as a whole (exercises/linkages/solution_files.py: overall_text)
    "crank-rocker": "لنگ - آونگ", "double-crank": "لنگ - لنگ", "double-rocker": "آونگ - آونگ",
    "triple-rocker": "سه‌آونگی", "change-point": "نقطهٔ تغییر",
    "{span} = {length} only ({kind})": "{span} تنها برابر {length} ({kind})",
    "{value} ({here} at this position)": "{value} ({here} در این وضعیت)",
    "{value} ({inspection} by inspection, {kennedy} by Kennedy)":
        "{value} ({inspection} با مشاهده، {kennedy} با قضیهٔ کندی)",
    "found": "یافته", "Willis": "ویلیس", "the same": "برابر", "yes": "بله", "NO": "خیر",
    "internal": "داخلی", "external": "خارجی", "the same way": "در همان جهت",
    "the other way": "در جهت مخالف", "negative: opposite senses": "منفی: جهت\u200cها مخالف",
    "positive: one sense": "مثبت: یک جهت", "tabular": "جدولی",
    "pitch circle": "دایرهٔ گام", "base circle": "دایرهٔ پایه", "addendum circle": "دایرهٔ سر",
    "root circle": "دایرهٔ ریشه", "no angular acceleration": "بی\u200cشتاب زاویه\u200cای",
    "train value": "مقدار قطار",
    # the interactive page (tarsim view)
    "figure": "شکل", "play": "پخش",
    "download this frame (SVG)": "بارگیری این قاب (SVG)", "Kennedy lines": "خطوط کندی",
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
    "position.at": "در θ{link} = {angle}",
    "position.frame_point": "نقطهٔ {point} روی قاب را در ({x}, {y}) مشخص کنید.",
    "position.frame_guide": "راهنمای {point} را روی قاب با زاویهٔ {angle} رسم کنید.",
    "position.input_ray": "از {pivot} نیم‌خطی با θ{link} = {angle} رسم کنید.",
    "position.input_point": "با مرکز {pivot} و شعاع {pivot}{point} = {radius}، نقطهٔ {point} را "
                            "{at} جدا کنید.",
    "position.on_link_line": "نقطهٔ {point} روی خط {a}{b} از میلهٔ {link} قرار دارد: {a}{point} "
                             "= {length} را از {a} جدا کنید.",
    "position.rigid_point": "نقطهٔ {point} نقطه‌ای از میلهٔ {link} است: با مراکز {a} و {b} و "
                            "شعاع‌های {a}{point} = {ra} و {b}{point} = {rb} دو کمان بزنید تا "
                            "یکدیگر را در {point} قطع کنند.",
    "position.along_link": "در امتداد میلهٔ {link}، {base}{point} = {length} را از {base} جدا "
                           "کنید تا نقطهٔ {point} مشخص شود.",
    "position.square_off": "{length} را از محور و عمود بر آن جدا کنید تا نقطهٔ {point} مشخص شود.",
    "position.radius_span": "{a}{b} = {length}",
    "position.radius_because": "{length}، زیرا {why}",
    "position.why_curved_slot": "{point} در شیار کمانی میلهٔ {link} به مرکز {centre} حرکت می‌کند",
    "position.why_circles_touch": "دایره‌های میله‌های {i} و {j} بر هم مماس‌اند: مراکز آن‌ها، "
                                  "{p} و {q}، همواره به فاصلهٔ r{i} {op} r{j} از یکدیگر می‌مانند",
    "position.swing_arc": "با مرکز {centre} و شعاع {radius} کمانی بزنید.",
    "position.locus": "با مرکز {centre} و شعاع {radius}، مکان هندسی نقطهٔ {point} را رسم کنید.",
    "position.arcs_cut": "دو کمان یکدیگر را در {point} قطع می‌کنند (نقطهٔ سمت {pick} امتداد {a} "
                         "→ {b})؛ {a}{point} و {b}{point} را رسم کنید.",
    "position.arc_cuts_guide": "کمان، راهنما را در {point} قطع می‌کند (نقطهٔ برخورد {pick}).",
    "position.two_guides": "{point} روی دو راهنما حرکت می‌کند: این نقطه محل تقاطع آن دو راهنماست.",
    "position.wheel_rolls": "میلهٔ {link}{name} بدون لغزش می‌غلتد: مرکز آن، {point}، به اندازهٔ "
                            "{rolled} از محل آغاز حرکتش جابه‌جا شده است، پس میله به اندازهٔ "
                            "{turn} در جهت {sense} چرخیده است ({rolled} ÷ r = {radius})؛ محور "
                            "میله را از {point} رسم کنید.",
    "position.wheel_input": "میلهٔ {link}{name}، یعنی میلهٔ ورودی، بدون لغزش روی سطحِ گذرنده از "
                            "{face} می‌غلتد: در θ{link} = {turn} در جهت {sense}، از وضعیتی که "
                            "مرکز آن درست بالای {face} و عمود بر سطح قرار داشت، به اندازهٔ "
                            "r·θ{link} = {rolled} غلتیده است (r = {radius}). از آنجا {rolled} "
                            "را در جهت {way} در امتداد مسیر مرکز میله جدا کنید تا نقطهٔ {point} "
                            "مشخص شود.",
    "position.wheel_axis": "از {point} محور میلهٔ {link} را با θ{link} = {angle} رسم کنید.",
    "position.wheel_arm": "{contact}{point} را رسم کنید: چرخ {link} در این لحظه حول {contact} "
                          "می‌چرخد، یعنی حول نقطه‌ای از آن که روی سطح قرار دارد و ساکن است.",
    "position.wheel_rolls_round": "میلهٔ {link}{name} بدون لغزش روی دایره‌ای به مرکز {centre} "
                                  "می‌غلتد: مرکز آن، {point}، از ابتدا به اندازهٔ {beta} حول "
                                  "{centre} گردیده است، پس میله به اندازهٔ {beta} × {ratio} = "
                                  "{turn} چرخیده است (R = {big}، r = {radius})؛ محور میله را از "
                                  "{point} رسم کنید.",
    "gears.ordinary_start": "{member}، یعنی عضو ورودی، با {speed} می‌چرخد. یک دور چرخش آن را از "
                            "طریق درگیری‌ها به عضوهای دیگر منتقل کنید:",
    "gears.mesh_carries": "{driven} با {driver} درگیری {kind} دارد، پس {way} و با سرعتی "
                          "N{a}/N{b} = {na}/{nb} برابرِ آن می‌چرخد: {turns} → {result}.",
    "gears.shaft_carries": "{member} با {other} روی یک محور قرار دارد: همانند آن می‌چرخد، {turns}.",
    "gears.fixed": "، ثابت",
    "gears.one_planet": "یک چرخ سیاره\u200cای",
    "gears.planets": "{n} چرخ سیاره\u200cای با فاصلهٔ برابر",
    "gears.speed": "{value} {unit}{sense}",
    "gears.sense": " {sense}",
    "kutzbach.planet_centres": "مرکز چرخ\u200cهای سیاره\u200cای",
    "gears.one_shaft": "، هم\u200cمحور با {others}",
    "gears.modules": "{value} مدول",
    "involute.circle_of": "{circle} چرخدندهٔ {gear}",
    "gears.idler": "؛ چرخ هرزگرد {idlers} اثری ندارد",
    "gears.idlers": "؛ چرخ\u200cهای هرزگرد {idlers} اثری ندارند",
    "gears.the_gear": "چرخدندهٔ {number}{name}",
    "gears.the_arm": "بازوی {number}{name}",
    "gears.named": " ({name})",
    "gears.train_value": "ارزش قطار (نسبت دنده) e = ω{last}/ω{first} = ({drivers})/({driven}) = "
                         "{teeth} = {value}: حاصل‌ضرب تعداد دندانه‌های چرخدنده‌های محرک بر "
                         "حاصل‌ضرب تعداد دندانه‌های چرخدنده‌های متحرک؛ {externals} درگیری خارجی "
                         "علامت آن را {sign} می‌کنند{idlers}.",
    "gears.power": "ورودی با {given} رانده می‌شود. چون توانی تلف نمی‌شود، T{i}·ω{i} + T{o}·ω{o} "
                   "= 0، پس T{o} = −T{i}·ω{i}/ω{o} = −T{i} × {ratio} = {value} N·m (جهت "
                   "پادساعتگرد مثبت).",
    "gears.holding": "مجموع گشتاورهای وارد بر قطار چرخدنده صفر است، پس عضو ثابت {fixed} با "
                     "گشتاور T{fixed} = −(T{i} + T{o}) = {value} N·m نگه داشته می‌شود.",
    "kutzbach.radial": "خط شعاعی را از محور اصلی O رو به بالا رسم کنید و شعاع‌ها را با مقیاس "
                       "روی آن جدا کنید: هر نقطهٔ این خط عمود بر آن حرکت می‌کند، پس هر سرعت "
                       "عمود بر این خط رسم می‌شود (سرعت پادساعتگرد به سمت راست)، و سرعت‌های هر "
                       "عضو روی خط راستی قرار می‌گیرند که شیب آن برابر ω همان عضو است.",
    "kutzbach.radius": "{name} = {radius} ({what}) را روی خط شعاعی مشخص کنید و خط تراز را از آن "
                       "رسم کنید.",
    "kutzbach.fixed": "{member} ثابت است: سرعت‌های آن صفرند و خط آن همان خط شعاعی است.",
    "kutzbach.input": "{member} با سرعت زاویه‌ای {omega} rad/s {sense} می‌چرخد: در {name} = "
                      "{radius}، سرعت آن، ω·r، را با مقیاس سرعت روی خط تراز جدا کنید.",
    "kutzbach.main_line": "عضو {member} حول محور اصلی می‌چرخد: خط آن از O و {point} می‌گذرد.",
    "kutzbach.pitch": "{a} و {b} در نقطهٔ گام خود، در {name}، سرعت یکسانی دارند: این سرعت در "
                      "محل برخورد خط {known} با همان تراز به دست می‌آید.",
    "kutzbach.planet_line": "چرخدندهٔ سیاره‌ای {member} یک جسم واحد است: خط آن از {p} و {q} "
                            "می‌گذرد.",
    "kutzbach.centre": "مرکز چرخدنده‌های سیاره‌ای، در R، همراه بازو حرکت می‌کند: سرعت آن در محل "
                       "برخورد خط {known} با همان تراز به دست می‌آید.",
    "kutzbach.read": "ω{member} = Δv/Δr، یعنی شیب خط آن را بخوانید: {omega} rad/s{sense}، {speed}.",
    "kutzbach.input_planet": "{member} با سرعت زاویه‌ای {omega} rad/s {sense} حول {pitch} "
                             "می‌چرخد، یعنی نقطهٔ گام آن با عضو ثابت که ساکن است: در {name} "
                             "سرعت مرکز آن {point}، یعنی ω·({name} − {level})، را با مقیاس "
                             "سرعت روی خط تراز جدا کنید.",
    "kutzbach.trial": "از خط ورودی به‌تنهایی خط دیگری به دست نمی‌آید: نمودار نخست برای {member} "
                      "با سرعت آزمایشی {trial} rad/s {trial_sense} رسم می‌شود و سرعت {drive} "
                      "را {read} rad/s {read_sense} می‌دهد. سرعت واقعی آن {given} rad/s است و "
                      "همهٔ سرعت‌ها به یک نسبت تغییر می‌کنند، پس {member} با سرعت {omega} rad/s "
                      "{sense} می‌چرخد.",
    "kutzbach.planet_centre": "مرکز چرخ سیاره‌ای {member}",
    "kutzbach.centre_at": "مرکز {point} چرخ سیاره‌ای {member}، در {name}، همراه بازو حرکت "
                          "می‌کند: سرعت آن در محل برخورد خط {known} با همان تراز به دست می‌آید.",
    "involute.centres": "مراکز O{a} و O{b} را به فاصلهٔ {distance} از یکدیگر مشخص کنید و آن‌ها "
                        "را به هم وصل کنید: این خط، خط‌المرکزین است.",
    "involute.pitch_point": "طبق قانون اساسی درگیری چرخدنده‌ها، نقطهٔ گام P پاره‌خط O{a}O{b} را "
                            "به نسبت شعاع‌های مبنا، N{a} : N{b} = {na} : {nb}، تقسیم می‌کند: "
                            "O{a}P = {o2p} را جدا کنید.",
    "involute.circle": "{name} را با شعاع {radius} رسم کنید.",
    "involute.thales": "دایره‌ای به قطر {centre}P رسم کنید (قضیهٔ تالس): مماسی که از P بر "
                       "دایره‌ای به مرکز {centre} رسم شود، در نقطه‌ای بر آن مماس است که این "
                       "دایره آن را قطع می‌کند.",
    "involute.tangent_point": "این دایره، {base} را در {point} قطع می‌کند؛ خط عمل در همین نقطه "
                              "بر آن مماس است.",
    "involute.line_of_action": "نقاط تماس را به هم وصل کنید: این خط، خط عمل است، یعنی مماس "
                               "مشترک داخلی دایره‌های مبنای {a} و {b} که از P می‌گذرد.",
    "involute.common_tangent": "از P مماس مشترک دایره‌های گام را عمود بر خط‌المرکزین رسم کنید؛ "
                               "خط عمل به اندازهٔ زاویهٔ فشار نسبت به آن مایل است.",
    "involute.circular_pitch": "P را به اندازهٔ یک دندانه، یعنی 360°/{teeth}، روی دایرهٔ گام "
                               "{a} بچرخانید تا به P′ برسد: کمان PP′ همان گام دایره‌ای است.",
    "involute.start": "دایرهٔ ادندم {b} خط عمل را در A قطع می‌کند: تماس از آنجا آغاز می‌شود.",
    "involute.end": "دایرهٔ ادندم {a} خط عمل را در B قطع می‌کند: تماس در آنجا پایان می‌یابد.",
    "involute.path": "طول مسیر تماس AB = {path} را اندازه بگیرید؛ زاویهٔ فشار {angle} خوانده "
                     "می‌شود، پس کمان تماس برابر AB / cos φ = {arc} است، و با تقسیم بر گام "
                     "مبنای {pitch}، نسبت تماس {ratio} به دست می‌آید.",
    "involute.start_point": "برای دندانهٔ چرخدندهٔ {gear} که از P می‌گذرد: کمان {t}{point} = "
                            "P{t} = {length} را روی دایرهٔ مبنای آن به عقب جدا کنید تا به "
                            "{point} برسید، جایی که ریسمان از آن باز می‌شود.",
    "involute.profile": "دایرهٔ مبنای {gear} را از {point} به {divisions} کمان مساوی {arc} "
                        "تقسیم کنید؛ در هر نقطهٔ تقسیم، طول کمان از {point} تا آن نقطه را روی "
                        "مماس جدا کنید و نقاط به‌دست‌آمده را به هم وصل کنید: این منحنی، اینولوت "
                        "است.",
    "gears.member": "{member}، با {teeth} دندانه، {where}{shaft}{fixed}.",
    "gears.on_axis": "روی محور اصلی",
    "gears.on_own_axis": "روی محور خود در پوسته",
    "gears.on_pin": "روی لولای بازوی {arm}، در شعاع بازو",
    "gears.arm": "بازوی {arm} حول محور اصلی می‌چرخد و لولای چرخدنده‌های سیاره‌ای ({planets}) را "
                 "با خود می‌برد{fixed}.",
    "gears.meshes": "چرخدنده‌های {a} و {b} درگیری {kind} دارند.",
    "cam.axes": "خط مبنا را رسم کنید: زاویهٔ بادامک در امتداد آن و خیز پیرو از آن رو به بالا "
                "اندازه گرفته می‌شود.",
    "cam.ordinates": "بخش {k} ({kind}، {angle}): زاویهٔ بادامکِ این بخش را به {n} قسمت مساوی "
                     "تقسیم کنید و از هر نقطهٔ تقسیم یک خط قائم رسم کنید.",
    "cam.dwell": "بخش {k} یک توقف {angle} است: پیرو ساکن می‌ماند و نمودار، خطی افقی است.",
    "cam.uniform": "بخش {k} با سرعت ثابت است: قطری از ابتدا تا انتهای بخش رسم کنید؛ خطوط قائم، "
                   "آن را در موقعیت‌های پیرو قطع می‌کنند.",
    "cam.harmonic": "بخش {k} هارمونیک ساده است: در ابتدای بخش، نیم‌دایره‌ای به قطر خیز {lift} "
                    "رسم کنید و آن را به {n} کمان مساوی تقسیم کنید؛ هر نقطهٔ تقسیم را با خطی "
                    "افقی به خط قائم نظیرش منتقل کنید.",
    "cam.parabolic": "بخش {k} با شتاب‌گیری و کاهش سرعت یکنواخت (شتاب ثابت) است: برای نیمهٔ "
                     "{half} آن، نصف خیز را روی خط قائم {where} به نسبت ۱ : ۳ : ۵ … {way} تقسیم "
                     "کنید؛ این کار با خطوطی موازی انجام می‌شود که از خطی کمکی با علامت‌های ۱، "
                     "۴، ۹ … گام مساوی ({m} گام) رسم می‌شوند؛ سپس هر نقطهٔ تقسیم را با خطی افقی "
                     "به خط قائم نظیرش منتقل کنید.",
    "cam.blend": "بخش {k} با سرعت ثابت اصلاح‌شده است: برای ناحیهٔ گذار {half} آن، سهم این ناحیه "
                 "از خیز، یعنی {rise}، را روی خط قائم {where} به نسبت ۱ : ۳ : ۵ … {way} تقسیم "
                 "کنید؛ این کار با خطوطی موازی انجام می‌شود که از خطی کمکی با علامت‌های ۱، ۴، ۹ "
                 "… گام مساوی ({m} گام) رسم می‌شوند؛ سپس هر نقطهٔ تقسیم را با خطی افقی به خط "
                 "قائم نظیرش منتقل کنید.",
    "cam.modified": "بخش {k}: انتهای دو سهمی آن را با خطی راست به هم وصل کنید؛ این خط همان سرعت "
                    "ثابتِ میان دو ناحیهٔ گذار است و خطوط قائمِ میانی آن را قطع می‌کنند.",
    "cam.cycloidal": "بخش {k} سیکلوئیدی است: به مرکز ابتدای بخش دایره‌ای به شعاع خیز ÷ 2π = "
                     "{radius} رسم کنید و آن را به {n} کمان مساوی تقسیم کنید؛ هر نقطهٔ تقسیم را "
                     "روی خط قائم ابتدای بخش منتقل کنید و از آنجا خطی موازی قطر بخش تا خط قائم "
                     "نظیرش رسم کنید.",
    "cam.centre": "مرکز بادامک، O، را مشخص کنید؛ بادامک ثابت نگه داشته می‌شود و پیرو در جهت "
                  "مخالف به دور آن چرخانده می‌شود (روش وارون).",
    "cam.base": "دایرهٔ پایه را به مرکز O و شعاع {r} رسم کنید.",
    "cam.prime": "دایرهٔ گام را به مرکز O و شعاع {r} رسم کنید: یعنی دایرهٔ پایه به‌علاوهٔ شعاع "
                 "غلتک، {roller}؛ مرکز غلتک در وضعیت آغازین روی این دایره قرار دارد.",
    "cam.offset": "دایرهٔ انحراف را به مرکز O و شعاع {e} رسم کنید: خط حرکت پیرو همواره بر آن "
                  "مماس می‌ماند.",
    "cam.pivot_circle": "دایرهٔ لولا را به مرکز O و گذرنده از لولای پیرو، A، رسم کنید؛ بازوی "
                        "پیرو به طول {arm} همراه آن چرخانده می‌شود.",
    "cam.stations": "وضعیت آغازین پیرو {follower} را حول O در جهت {turn}، یعنی خلاف جهت چرخش "
                    "بادامک، به اندازهٔ زاویهٔ بادامکِ هر موقعیت بچرخانید و موقعیت‌ها را "
                    "شماره‌گذاری کنید.",
    "cam.lift": "موقعیت {i} ({deg}): در امتداد خط حرکت پیرو، خیز {lift} را که از نمودار "
                "جابه‌جایی گرفته می‌شود جدا کنید{then}.",
    "cam.swing": "موقعیت {i} ({deg}): بازوی پیرو را حول لولای چرخانده‌شده به اندازهٔ {swing}، "
                 "یعنی زاویهٔ پیرو در نمودار جابه‌جایی، بچرخانید{then}.",
    "cam.then.roller": "؛ سپس به مرکز نقطهٔ به‌دست‌آمده دایرهٔ غلتک را با شعاع {r} رسم کنید",
    "cam.then.flat-faced": "؛ سپس از نقطهٔ به‌دست‌آمده سطح پیرو را عمود بر خط حرکت پیرو رسم کنید",
    "cam.profile.knife-edge": "پروفیل بادامک را به‌صورت منحنی همواری رسم کنید که از نقاط لبهٔ "
                              "نوک‌تیز می‌گذرد: برای پیرو نوک‌تیز، این منحنی همان منحنی گام است.",
    "cam.profile.roller": "منحنی گام را از مراکز غلتک‌ها رسم کنید، و پروفیل بادامک را به‌صورت "
                          "منحنی همواری رسم کنید که درون همهٔ دایره‌های غلتک قرار دارد و بر هر "
                          "یک مماس است (پوش داخلی).",
    "cam.profile.flat-faced": "پروفیل بادامک را به‌صورت منحنی همواری رسم کنید که درون همهٔ خطوط "
                              "سطح پیرو قرار دارد و بر هر یک مماس است (پوش خطوط سطح پیرو).",
    "balance.space": "نمای انتهایی را رسم کنید: از مرکز محور، O، برای هر جرم خطی شعاعی با "
                     "زاویهٔ آن جرم رسم کنید.",
    "balance.couple": "چندضلعی کوپل، با صفحهٔ {a} به‌عنوان صفحهٔ مرجع: هر mᵢrᵢlᵢ را، که lᵢ "
                      "فاصله از صفحهٔ {a} است، پشت سر هم (ابتدای هر بردار بر انتهای بردار قبلی) "
                      "جدا کنید؛ هر بردار موازی خط شعاعی جرم خود، و هر جا lᵢ < 0 باشد در جهت "
                      "مخالف آن.",
    "balance.force": "چندضلعی نیرو: هر mᵢrᵢ را پشت سر هم جدا کنید، هر یک موازی خط شعاعی جرم خود "
                     "(ω² در همهٔ جمله‌ها مشترک است، پس کنار گذاشته می‌شود).",
    "balance.close": "چندضلعی را از نوک آخرین بردار تا نقطهٔ شروع آن ببندید: ضلع بسته‌کننده، "
                     "بردار متعادل‌کنندهٔ صفحهٔ {plane} است، یعنی برآیند که به اندازهٔ 180° "
                     "دوران داده شده است.",
    "balance.left": "چندضلعی {plane} را از نوک آخرین بردار تا نقطهٔ شروع آن ببندید: ضلع "
                    "بسته‌کننده، {plane} نامیزانِ باقی‌مانده است؛ اگر ضلع بسته‌کننده‌ای پدید "
                    "نیاید، متوازن است.",
    "balance.closed": "چندضلعی خودبه‌خود بسته است و نوک آخرین بردار بر نقطهٔ شروع آن می‌افتد: "
                      "صفحهٔ {plane} به جرم متعادل‌کننده نیازی ندارد.",
    "balance.point": "همهٔ جرم‌ها در صفحهٔ {a} قرار دارند، پس هر mᵢrᵢlᵢ صفر است و چندضلعی "
                     "کوپل به یک نقطه تبدیل می‌شود: صفحهٔ {plane} به جرم متعادل‌کننده نیازی "
                     "ندارد.",
    "balance.balanced": "چندضلعی {plane} خودبه‌خود بسته است و نوک آخرین بردار بر نقطهٔ شروع "
                        "آن می‌افتد: {plane} متوازن است.",
    "balance.cranks": "نمای انتهایی لنگ‌ها را رسم کنید: از مرکز محور، O، خط هر لنگ را با زاویهٔ "
                      "θᵢ و لنگ‌های ثانویه (مستقیم) را با زاویهٔ 2θᵢ رسم کنید.",
    "balance.engine": "چندضلعی {kind}: بردار هر سیلندر را در امتداد لنگ آن با زاویهٔ {order}، "
                      "پشت سر هم جدا کنید.",
    "force.centre": "مرکز جرم میلهٔ {link}، یعنی G{link}، را مشخص کنید و آن را به {k} وصل کنید.",
    "force.image": "روی چندضلعی شتاب، از {start} مؤلفهٔ عمودی ω²·{k}G{link} = {n} را به سمت {k} "
                   "جدا کنید، سپس مؤلفهٔ مماسی α·{k}G{link} = {t} را عمود بر آن: نقطهٔ "
                   "به‌دست‌آمده، g{link}′، تصویر G{link} است. نیروی اینرسی میلهٔ {link} برابر "
                   "−m·a_G است که a_G از o_a تا g{link}′ خوانده می‌شود؛ کوپل اینرسی آن −I·α است "
                   "(این دو با هم معادل یک نیرو به فاصلهٔ h = I·α/(m·a_G) = {h} از G{link} "
                   "هستند).",
    "force.lay": "{label} = {size} را با مقیاس نیرو، از نوک آخرین بردار جدا کنید.",
    "force.ram": "رام {r}: بارهای وارد بر آن را پشت سر هم جدا کنید؛ شیار میلهٔ {l} و راهنمای "
                 "قاب، هر یک عمود بر خود، بر آن نیرو وارد می‌کنند.",
    "force.ram_close": "چندضلعی رام را ببندید: از انتهای آن خطی عمود بر راهنما و از ابتدای آن "
                       "خطی عمود بر شیار رسم کنید؛ محل تلاقی این دو خط هر دو نیرو را به دست "
                       "می‌دهد. ممان‌های وارد بر رام حول لولای آن، کوپل راهنما را به دست "
                       "می‌دهند.",
    "force.block": "لغزندهٔ {b}: ممان‌های وارد بر آن حول A، کوپل شیار بر لغزنده را به دست "
                   "می‌دهند؛ ممان‌های میلهٔ {l} حول {p}، نیروی شیار، {nu}، را به دست می‌دهند. "
                   "بارهای لغزنده و این نیرو را جدا کنید؛ ضلع بسته‌کننده، نیروی لنگ بر لغزنده "
                   "است.",
    "force.lever": "چندضلعی میلهٔ {l}: بارهای آن، نیروی لغزنده و نیروی رام، که با نیروی قاب در "
                   "{p} بسته می‌شود.",
    "force.piston": "نیروی مؤثر پیستون {j}، یعنی مجموع بارهای آن در امتداد خط کورس به سمت لنگ: "
                    "F_P = {effort}. رانش دیوارهٔ سیلندر بر آن، یعنی مؤلفهٔ نیروی راهنما که "
                    "عمود بر امتداد کورس است: F_N = {thrust}.",
    "force.effort": "{name}، یعنی نیروی وارد بر لولای لنگ {a}، را تجزیه کنید: از ابتدای آن خطی "
                    "در امتداد لنگ {o}{a} و از انتهای آن خطی عمود بر آن رسم کنید؛ در محل تلاقی "
                    "این دو خط، مؤلفهٔ شعاعی پایان می‌یابد و مؤلفهٔ مماسی F_T آغاز می‌شود. "
                    "نیروی مؤثر لنگ F_T = {effort} (پادساعتگرد مثبت) و گشتاور چرخشی F_T·{o}{a} "
                    "= {moment} است.",
    "force.resultant": "بارهای میلهٔ {i} با هم یک نیروی R = {size} می‌سازند: خط عمل آن جایی است "
                       "که ممان R به‌تنهایی حول {b} با ممان مجموع آن بارها برابر باشد.",
    "force.two_force": "میلهٔ {j} باری ندارد: عضوی دونیرویی است و نیروهای لولاهای آن در امتداد "
                       "{c}{b} هستند.",
    "force.massless_block": "لغزندهٔ {j} باری ندارد: راهنما و لولای {b} آن، هر دو عمود بر "
                            "راهنما و در امتداد یک خط گذرنده از {b}، بر آن نیرو وارد می‌کنند.",
    "force.concurrent": "میلهٔ {i} تحت اثر سه نیرو است، پس خطوط عمل آن‌ها در یک نقطه هم‌رس‌اند: "
                        "X، محل تلاقی خط عمل R با خط عمل نیروی میلهٔ خروجی. نیروی لنگ در {a} در "
                        "امتداد {a}X است.",
    "force.three": "چندضلعی نیروی میلهٔ {i}: بارهای آن را پشت سر هم جدا کنید (مجموع آن‌ها R است).",
    "force.close_three": "چندضلعی میلهٔ {i} را ببندید: از انتهای آن خطی موازی خط عمل نیروی "
                         "میلهٔ {j} و از ابتدای آن خطی موازی {a}X رسم کنید؛ محل تلاقی آن‌ها هر "
                         "دو نیرو را به دست می‌دهد.",
    "force.leaning": "{what} همراه با اصطکاک نیرو وارد می‌کند: نیروی آن به اندازهٔ φ = atan μ = "
                     "{phi} نسبت به امتداد عمود (نرمال)، در خلاف جهت لغزش، مایل است. این نیرو "
                     "از {side} وارد می‌شود: با این فرض، چندضلعی با نیرویی در همان سمت بسته "
                     "می‌شود.",
    "force.leaning_block": "لغزندهٔ {j} باری ندارد: نیروی راهنما و نیروی لولای {b} بر آن، در "
                           "امتداد یک خط گذرنده از {b} هستند که به اندازهٔ φ = {phi} نسبت به "
                           "عمود بر راهنما، در خلاف جهت لغزش، مایل است.",
    "force.circles": "دایره‌های اصطکاک به شعاع ρ = {rho} در لولاها: نیروی هر لولا در سمتی بر "
                     "دایرهٔ آن مماس است که با دوران نسبی یک میله نسبت به میلهٔ دیگر مخالفت "
                     "کند؛ بنابراین هر میله در هر لولا کوپلی برابر ρ·|F| در خلاف جهت آن دوران "
                     "تحمل می‌کند. |F| با سعی و خطا به دست می‌آید: چندضلعی‌ها با کوپل‌های "
                     "مرحلهٔ قبل دوباره رسم می‌شوند تا نیروها دیگر تغییر نکنند ({rounds} "
                     "مرحله)؛ آخرین مرحله در اینجا رسم شده است.",
    "force.resting": "{what} میلهٔ {link} را در این وضعیت ساکن نگه می‌دارد: میلهٔ {link} با "
                     "سرعتی برابر {share} بیشترین سرعت روی چندضلعی سرعت روی آن می‌لغزد، یعنی "
                     "در حد خطای گردکردنی که چندضلعی صفر را با آن می‌خواند ({still} آن). "
                     "اصطکاک در حال سکون جهتی ندارد، پس به هیچ سمتی نمی‌افتد: {name} عمود بر "
                     "آن است، همان‌طور که در وضعیت حدی.",
    "force.resting_pin": "لولای {pin} در این وضعیت ساکن است: میلهٔ {on} نسبت به میلهٔ {by} "
                         "با سرعت زاویه‌ای برابر {share} بیشترین سرعت زاویه‌ای روی چندضلعی "
                         "سرعت می‌چرخد، یعنی در حد خطای گردکردنی که چندضلعی صفر را با آن "
                         "می‌خواند ({still} آن). اصطکاک در حال سکون جهتی ندارد، پس دایرهٔ "
                         "اصطکاک آن کوپلی نمی‌دهد.",
    "force.effort_square": "{name}، یعنی نیروی وارد بر لولای لنگ {a}، عمود بر لنگ {o}{a} است: "
                           "تمام آن نیروی مؤثر لنگ است، F_T = {effort} (پادساعتگرد مثبت)، و "
                           "گشتاور چرخشی F_T·{o}{a} = {moment} است.",
    "force.the_guide": "راهنما",
    "force.the_frame_guide": "راهنمای قاب",
    "force.the_slot": "شیار میلهٔ {link}",
    "force.torque": "ممان‌های میلهٔ {d} حول {o}: گشتاور محرک T{d} = {torque}.",
    "force.dyad": "چندضلعی نیروی میله‌های {i} و {j} با هم: همهٔ بارهای معلوم وارد بر آن‌ها "
                  "(وزن‌ها، نیروهای اینرسی، نیروهای خارجی) را با مقیاس نیرو پشت سر هم جدا کنید.",
    "force.tangential": "{name}ᵗ، مؤلفه‌ای از {name} که بر خط واصل {pin} به {about} عمود است: "
                        "ممان‌های میلهٔ {link} حول {about} آن را به دست می‌دهند (حاصل‌ضرب Fᵗ در "
                        "طول برابر −ΣM است)؛ سپس آن را جدا کنید.",
    "force.close": "چندضلعی میله‌های {i} و {j} را ببندید: از انتهای آن خطی در امتداد مؤلفهٔ "
                   "مجهول در لولای دورتر و از ابتدای آن خطی در امتداد میلهٔ رابط رسم کنید؛ محل "
                   "تلاقی آن‌ها هر دو مؤلفه و در نتیجه نیروی هر لولا را به دست می‌دهد.",
    "force.driver": "چندضلعی میلهٔ {d} (لنگ): بارهای خود آن و نیروی میلهٔ {i} بر آن، که با "
                    "نیروی قاب در {o} بسته می‌شود؛ ممان‌های آن حول {o}، گشتاور محرک را به دست "
                    "می‌دهند.",
    "gears.locked": "سطر 1: کل قطار چرخدنده را همراه با {arm} قفل کنید و آن را +1 دور "
                    "(پادساعتگرد) بچرخانید: هر عضو +1 دور می‌چرخد.",
    "gears.held": "سطر 2: {arm} را ثابت نگه دارید و {fixed}، یعنی عضو ثابت، را −1 دور بچرخانید:",
    "gears.added": "سطر 3: سطرها را با هم جمع کنید. {fixed} به اندازهٔ +1 − 1 = 0 دور می‌چرخد، "
                   "همان‌طور که باید؛ هر مجموع، تعداد دورهای آن عضو به ازای یک دور بازو است.",
    "gears.scaled": "{member}، یعنی عضو ورودی، در سطر مجموع {total} دور و در واقع {speed} "
                    "می‌چرخد: سطر را در {scale} {unit} ضرب کنید.",
    "gears.xy_rows": "همین نتیجه با x و y: بازوی {arm} به اندازهٔ y و عضو {fixed} نسبت به آن به "
                     "اندازهٔ x می‌چرخد؛ بنابراین {rows}.",
    "gears.xy_solved": "عضو {fixed} ثابت است، پس y + x = 0؛ و عضو {member} با {speed} می‌چرخد: "
                       "y = {y} {unit} و x = {x} {unit}.",
    "link_name": " ({name})",
    "position.slot_square_to_guide": "از {point} عمودی بر راهنمای {block} رسم کنید: شیار میلهٔ "
                                     "{link}.",
    "position.slot_at_angle": "از {point} خطی با زاویهٔ {angle} نسبت به راهنمای {block} رسم "
                              "کنید: شیار میلهٔ {link}.",
    "position.face_offset": "اندازهٔ {length} را عمود بر شیار جدا کنید: خط موازی شیار که از "
                            "انتهای آن می‌گذرد، {point} را در بر دارد.",
    "position.cut_guide": "{point} محل برخورد این خط با راهنمای {point} است.",
    "position.slot_through_block": "شیار میلهٔ {link} از {pivot} و لغزندهٔ {point} می‌گذرد: خط "
                                   "{pivot}{point} را رسم کنید.",
    "position.bisect": "پاره‌خط {a}{b} را نصف کنید.",
    "position.circle_on_diameter": "دایره‌ای به قطر {a}{b} رسم کنید.",
    "position.offset_arc": "با مرکز {centre} و شعاع {radius} (انحراف شیار) کمانی بزنید.",
    "position.foot_of_slot": "کمان‌ها یکدیگر را در پای شیار قطع می‌کنند.",
    "position.slot_tangent": "شیار را از {point} و مماس بر کمان رسم کنید.",
    "on_frame": "قاب",
    "on_link": "میلهٔ {link}",
    "centres.pin": "لولای {point} میله‌های {i} و {j} را به هم وصل می‌کند، پس همان {centre} است.",
    "centres.curved_block": "لغزندهٔ {point} از میلهٔ {link} روی راهنمای {on} می‌لغزد که حول "
                            "{at} خمیده است، پس {centre} در مرکز انحنا، یعنی {at}، قرار دارد.",
    "centres.straight_block": "لغزندهٔ {point} از میلهٔ {link} روی راهنمای مستقیم {on} می‌لغزد، "
                              "پس {centre} در بی‌نهایت و در امتداد عمود بر راهنما قرار دارد.",
    "centres.common_normal": "{centre} روی عمود مشترک در {point} قرار دارد: از {point} عمودی بر "
                             "{what} میلهٔ {link} رسم کنید.",
    "centres.contact_normal": "{centre} روی عمود مشترک در نقطهٔ تماس، یعنی {what}، قرار دارد: "
                              "خط {a}{b} را رسم کنید.",
    "centres.line_of_centres": "خط مراکز دو دایره",
    "centres.curved_radius": "شعاع شیار خمیدهٔ میلهٔ {link}",
    "centres.face": "از {point} سطح میلهٔ {link} را موازی مسیر {path_of} رسم کنید.",
    "centres.rolling": "میلهٔ {link} بدون لغزش روی میلهٔ {on} می‌غلتد، پس نقطهٔ تماس، یعنی پای "
                       "عمودِ وارد از {point} بر سطح، همان {centre} است.",
    "centres.rolling_round": "میلهٔ {link} بدون لغزش روی دایرهٔ میلهٔ {on} می‌غلتد، پس نقطهٔ "
                             "تماس، که به فاصلهٔ {radius} از {circle} در امتداد {circle}{point} "
                             "است، همان {centre} است.",
    "centres.kennedy_line": "مثلث {triangle}: طبق قضیهٔ کندی، {centre} روی خط گذرنده از {a} و "
                            "{b} قرار دارد.",
    "centres.lines_meet": "{centre} محل تلاقی این دو خط است.",
    "centres.rule2_mark": "همهٔ خطوط کندی برای {centre} بر همین یک خط منطبق‌اند، پس از سرعت‌ها "
                          "استفاده کنید (قاعدهٔ 2): نقطهٔ X را روی آن به فاصلهٔ {length} از "
                          "{start} مشخص کنید.",
    "centres.rule2_tip": "در X و عمود بر خط، سرعتی را که X به‌عنوان نقطه‌ای از میلهٔ {link} "
                         "می‌داشت (از نسبت ω آن) جدا کنید.",
    "centres.rule2_translating": "میلهٔ {link} حرکت انتقالی دارد: پروفیل سرعت آن، خطی موازی این "
                                 "خط است که از نوک بردار می‌گذرد.",
    "centres.rule2_profile": "{centre} را به نوک بردار وصل کنید: این خط، پروفیل سرعت میلهٔ "
                             "{link} است.",
    "centres.rule2_meet": "پروفیل‌ها یکدیگر را در جایی قطع می‌کنند که سرعت میله‌های {i} و {j} "
                          "برابر است.",
    "centres.rule2_centre": "از آنجا عمودی بر خط فرود آورید: پای این عمود، {centre} است.",
    "velocity.input_perpendicular": "در {point} عمودی بر {pivot}{point} رسم کنید.",
    "velocity.input_vector": "V_{point} = ω{link}·{pivot}{point} = {omega} rad/s × {radius} = "
                             "{speed} را روی آن، در جهت ω{link} ({sense})، جدا کنید.",
    "velocity.known": "V_{point} سرعت معلوم است.",
    "velocity.line_of_centres": "خط مراکز را از {a} و {b} رسم کنید؛ {c} نیز روی آن قرار دارد "
                                "(قضیهٔ کندی).",
    "velocity.erect_perpendicular": "در {at} عمودی بر خط مراکز رسم کنید.",
    "velocity.meets_gauge_at_tip": "این عمود، خط سنجهٔ میلهٔ {link} را در نوک V_{centre} قطع "
                                   "می‌کند.",
    "velocity.transfer_point": "V_{centre} = {speed}: {centre} نقطه‌ای مشترک میان میلهٔ {i} و "
                               "میلهٔ {j} است (نقطهٔ انتقال).",
    "velocity.swing_onto_line": "با مرکز {centre} و شعاع {centre}{point}، نقطهٔ {point} را "
                                "دوران دهید تا روی خط مراکز در {point}′ قرار گیرد.",
    "velocity.lay_off_known": "در {point}′، V_{point} = {speed} را عمود بر خط مراکز و در همان "
                              "جهت جدا کنید.",
    "velocity.gauge_line": "خط سنجهٔ میلهٔ {link} را از {centre} و گذرنده از نوک بردار رسم کنید.",
    "velocity.equal_omega_line": "{centre} در بی‌نهایت است: میله‌های {i} و {j} با یک ω با هم "
                                 "می‌چرخند. خط گذرنده از {a} و {b} را رسم کنید.",
    "velocity.equal_omega_gauge": "از {centre} خط سنجهٔ میلهٔ {j} را موازی با خط سنجهٔ میلهٔ "
                                  "{i} رسم کنید: ω یکسان، شیب یکسان.",
    "velocity.equal_omega_point": "در {at}، که نقطه‌ای از میلهٔ {j} در نظر گرفته می‌شود، عمود "
                                  "بر این خط را رسم کنید؛ این عمود، خط سنجهٔ میلهٔ {j} را در "
                                  "نوک سرعت آن نقطه، {speed}، قطع می‌کند.",
    "velocity.translates": "میلهٔ {link} حرکت انتقالی دارد ({centre} در بی‌نهایت است)، پس همهٔ "
                           "نقاط آن سرعت V_{known} دارند: این سرعت را در {point} جدا کنید.",
    "velocity.at_rest": "{point} بر {centre}، یعنی مرکزی که میلهٔ {link} در این لحظه حول آن "
                        "می‌چرخد، منطبق است؛ پس V_{point} = 0.",
    "velocity.line_of_centres_of_link": "خط مراکز میلهٔ {link} را که از {a} و {b} می‌گذرد رسم "
                                        "کنید.",
    "velocity.gauge_line_known": "خط سنجهٔ میلهٔ {link} را از {centre} به نوک سرعت معلوم رسم کنید.",
    "velocity.meets_gauge_length": "این خط، خط سنجهٔ میلهٔ {link} را قطع می‌کند: طول آن تا محل "
                                   "برخورد برابر |V_{point}| است.",
    "velocity.rotate_back": "آن را حول مرکز {centre} دوران دهید تا به {point} بازگردد: "
                            "V_{point} بر {centre}{point} عمود است.",
    "velocity.turn_known": "سرعت معلوم را 90° بچرخانید تا در امتداد شعاع خود و به سمت {centre} "
                           "قرار گیرد.",
    "velocity.turned_arrow": "آن را به‌صورت یک پیکان رسم کنید: سرعت معلوم که 90° چرخانده شده است.",
    "velocity.turned_found": "آن قطعه را به‌صورت پیکانی از {point} رسم کنید: V_{point} که 90° "
                             "چرخانده شده است.",
    "velocity.join": "{a} را به {b} وصل کنید.",
    "velocity.parallel_through_turned": "از نوک سرعت چرخانده‌شده، خطی موازی با آن خط رسم کنید.",
    "velocity.radius": "شعاع {point}–{centre} را رسم کنید.",
    "velocity.parallel_cuts_radius": "خط موازی، شعاع را قطع می‌کند: قطعه‌ای که از {point} آغاز "
                                     "می‌شود، |V_{point}| است که 90° چرخانده شده است.",
    "velocity.turn_back": "آن را 90° در جهت مخالف بازگردانید: V_{point} بر {point}–{centre} "
                          "عمود است.",
    "velocity.result": "V_{point} = {speed}.",
    "components.on_contact": "نقطهٔ {point} از چرخ {link} در این لحظه بر {rest}، یعنی نقطهٔ "
                             "تماس چرخ با سطح، منطبق است که ساکن است: V_{point} = 0.",
    "components.arrow": "{point} را به نوک وصل کنید: V_{point} = {speed}.",
    "components.project_along": "نوک V_{point} را بر {line} تصویر کنید: {component} مؤلفهٔ "
                                "V_{point} در امتداد {line} است.",
    "components.draw_component_along": "{component} را در {point} در امتداد {line} رسم کنید.",
    "components.dividers": "با پرگار، {a} = {b} را در {point} در امتداد {line} جدا کنید.",
    "components.equal_components": "{a} = {b}: نقاط یک میلهٔ صلب در امتداد خط واصل بین خود "
                                   "مؤلفه‌های برابر دارند.",
    "components.line_of_link": "خط {line} از میلهٔ {link} را رسم کنید.",
    "components.perpendicular_from_tip": "از نوک {component}، عمود بر {line} را رسم کنید.",
    "components.say_perpendicular": "عمود بر {line} از نوک {component}",
    "components.radius": "شعاع {pivot}{point} از میلهٔ {link} را حول لولای ثابت آن، {pivot}، "
                         "رسم کنید.",
    "components.path": "در {point}، عمود بر {pivot}{point} را رسم کنید: مسیر {point}.",
    "components.say_path": "مسیر {point} (⟂ {pivot}{point})",
    "components.say_guide": "راهنمای {point}",
    "components.glide": "میلهٔ {link} بدون دوران روی راهنمای قاب می‌لغزد، پس {point} موازی با "
                        "راهنما حرکت می‌کند: خطی موازی با راهنما از {point} رسم کنید.",
    "components.say_glide": "مسیر {point} (∥ راهنمای میلهٔ {link})",
    "components.slot_parallel": "از نوک V_{other} خطی موازی با شیار میلهٔ {link} رسم کنید: "
                                "V_{point} − V_{point}{link} در امتداد شیار است.",
    "components.say_slot": "خط موازی با شیار میلهٔ {link} که از نوک V_{other} می‌گذرد",
    "components.loci_meet": "{first} و {second} یکدیگر را در نوک V_{point}{note} قطع می‌کنند.",
    "components.not_vector_sum": " (نه جمع برداری دو مؤلفه!)",
    "components.perpendicular_at": "در {point}، عمود بر {line} را رسم کنید.",
    "components.project_normal": "نوک V_{point} را بر آن تصویر کنید: {component} مؤلفهٔ "
                                 "V_{point} در راستای ⟂ {line} است.",
    "components.draw_component": "{component} را در {point} رسم کنید.",
    "components.line_carries": "خط {line} از میلهٔ {link} را رسم کنید؛ {point} روی آن قرار دارد.",
    "components.through_rest_and_tip": "{rest} (ساکن) و نوک V_{other}″",
    "components.through_tips": "نوک‌های V_{a}″ و V_{b}″",
    "components.gauge_through": "خط سنجه را طوری رسم کنید که از {through} بگذرد.",
    "components.cuts_gauge": "این خط، خط سنجه را در نوک {component} قطع می‌کند؛ {component} "
                             "مؤلفهٔ V_{point} در راستای ⟂ {line} است.",
    "components.rest_gives": "V_{point}′ = V_{rest}′ = 0 ({rest} ساکن است)، پس V_{point} = "
                             "{component}.",
    "components.pgram_first": "از نوک {a} خطی موازی با {b} (⟂ {line}) رسم کنید.",
    "components.pgram_second": "از نوک {a} خطی موازی با {b} (در امتداد {line}) رسم کنید.",
    "components.pgram_meet": "این دو خط یکدیگر را در نوک V_{point} = {a} + {b} قطع می‌کنند "
                             "(متوازی‌الاضلاع).",
    "components.translate": "میلهٔ {link} بدون دوران روی راهنمای قاب می‌لغزد، پس همهٔ نقاط آن "
                            "سرعت V_{known} دارند: با پرگار آن را در {point} جدا کنید.",
    "then": " {sentences}",
    "polygon.pole": "قطب {noun}، {pole}، را انتخاب کنید: هر برداری که از آن رسم شود، {noun} "
                    "مطلق است.",
    "polygon.relative": "{a} را به {b} وصل کنید: {symbol} = {size}.",
    "apolygon.resolve_relative": "از {a} خطی موازی با {p}{q} رسم کنید: مؤلفهٔ عمودی (نرمال) {a} "
                                 "{b} در امتداد آن است.",
    "apolygon.resolve_absolute": "از {pole} خطی موازی با سرعت {point}، یعنی مماس بر مسیر آن، "
                                 "رسم کنید: مؤلفهٔ مماسی {pole} {tip} در امتداد آن است.",
    "apolygon.resolve_foot": "از {tip} عمودی بر آن فرود آورید: پای عمود، شتاب را به مؤلفه‌های "
                             "عمودی (نرمال) و مماسی آن تجزیه می‌کند.",
    "vpolygon.path": "o_v را به {tip} وصل کنید: راستای سرعت {point}.",
    "readings.link_line": "خط {a}{b} از میلهٔ {link} را رسم کنید.",
    "equivalent.centres": "{a} و {b} مراکز انحنای دو پروفیل در تماس (میله‌های {i} و {j}) هستند؛ "
                          "عمود مشترک از هر دو می‌گذرد.",
    "equivalent.link": "فاصلهٔ آن‌ها همواره {length} می‌ماند ({how})، پس در این لحظه تماس مانند "
                       "میلهٔ {a}{b} عمل می‌کند که در هر دو مرکز لولا شده است: میلهٔ معادل، "
                       "به‌صورت خط‌چین.",
    "equivalent.slot": "مرکز {a} از دایرهٔ میلهٔ {i} همواره به فاصلهٔ {r} از سطح میلهٔ {j} "
                       "می‌ماند، پس در این لحظه تماس مانند لغزنده‌ای در {a} عمل می‌کند که در "
                       "شیاری موازی با این سطح حرکت می‌کند: شیار معادل، به‌صورت خط‌چین.",
    "apolygon.rolling": "{point}، نقطه‌ای از چرخ {link} که روی زمین است، ساکن است اما به سمت "
                        "مرکز {centre} شتاب دارد: از o_a اندازهٔ a_{point} = ω{link}²·r = "
                        "({omega} rad/s)² × {radius} = {accel} را موازی با {point}{centre} و به "
                        "سمت {centre} جدا کنید؛ انتهای آن {tip} است.",
    "apolygon.rolling_round": "{point}، نقطه‌ای از چرخ {link} که روی دایره است، ساکن است اما به "
                              "سمت مرکز {centre} شتاب دارد: از o_a اندازهٔ a_{point} = "
                              "ω{link}²·r·R/(R {op} r) = ({omega} rad/s)² × {radius} × "
                              "{big}/({big} {op} {radius}) = {accel} را موازی با "
                              "{point}{centre} و به سمت {centre} جدا کنید؛ انتهای آن {tip} است.",
    "klein.square": "از {o} خطی عمود بر خط کورس رسم کنید.",
    "klein.produce": "میلهٔ رابط {p}{c} را امتداد دهید.",
    "klein.m": "امتداد آن، خط گذرنده از {o} را در M قطع می‌کند.",
    "klein.velocity": "{o}{c}M همان مثلث سرعت است که 90° چرخانده شده: V_{p} = ω·{o}M، V_{c} = "
                      "ω·{o}{c}، V_{p}{c} = ω·{c}M.",
    "klein.circle_cm": "با مرکز {c} و شعاع {c}M دایره‌ای رسم کنید.",
    "klein.circle_cp": "دایره‌ای به قطر {c}{p} رسم کنید.",
    "klein.kl": "دو دایره یکدیگر را در K و L قطع می‌کنند.",
    "klein.join_kl": "K و L را به هم وصل کنید.",
    "klein.q": "KL خط {c}{p} را در Q قطع می‌کند.",
    "klein.acceleration": "این خط، خط کورس را در N قطع می‌کند: {o}{c}QN همان چندضلعی شتاب است "
                          "که 180° چرخانده شده، پس a_{p} = ω²·N{o}، از N به سمت {o} (a_{c} = "
                          "ω²·{o}{c}، aⁿ_{p}{c} = ω²·{c}Q، aᵗ_{p}{c} = ω²·QN).",
    "readings.least_velocity": "از {centre} عمودی بر {a}{b} فرود آورید: پای عمود، {point}، "
                               "نزدیک‌ترین نقطهٔ این خط به {centre} و کندترین نقطهٔ میلهٔ "
                               "{link} است.",
    "polygon.space_line": "خط {a}{b} از میلهٔ {link} را رسم کنید.",
    "polygon.lines_meet": "دو خط یکدیگر را در {tip} قطع می‌کنند: {pole} {tip} = {symbol}_{point}.",
    "polygon.image_why": "{x} روی خط {a}{b} از میلهٔ {link} قرار دارد، پس {tip} روی {ta} {tb} "
                         "قرار می‌گیرد، به‌طوری‌که {ta} {tip} : {ta} {tb} = {a}{x} : {a}{b} = "
                         "{ratio} (تصویر {noun})",
    "polygon.image_collapsed": "{why}؛ بردار {ta} {tb} طولی ندارد، پس {tip} بر {ta} منطبق است.",
    "polygon.image_lay_off": "{why}: روی {ta} {tb}، پاره‌خط {ta} {tip} = {ratio} × {ta} {tb} را "
                             "جدا کنید.",
    "polygon.translate": "میلهٔ {link} بدون دوران روی راهنمای متصل به قاب می‌لغزد، پس "
                         "{symbol}_{point} = {symbol}_{known}؛ بنابراین {tip} بر {known_tip} "
                         "منطبق است.",
    "polygon.coincide": "نقطهٔ {point} از میلهٔ {link} در این لحظه بر {known} منطبق است: این "
                        "دو، یک نقطه از میله‌اند، پس {symbol}_{point} = {symbol}_{known} و "
                        "{tip} بر {known_tip} منطبق است.",
    "polygon.say_perpendicular": "خط ⟂ {line} گذرنده از {tip}",
    "polygon.say_guide": "خط موازی راهنما گذرنده از {pole}",
    "polygon.say_slot": "خط موازی شیار گذرنده از {tip}",
    "polygon.why_guide": "راهنمای {point}",
    "polygon.why_glide": "راهنمای میلهٔ {link}، که میله بدون دوران روی آن می‌لغزد",
    "vpolygon.input_direction": "از o_v خطی ⟂ {pivot}{p} رسم کنید (راستای V_{point}).",
    "vpolygon.input": "از o_v بردار o_v {tip} = V_{point} = ω{link}·{pivot}{p} = {omega} rad/s "
                      "× {radius} = {speed} را ⟂ {pivot}{p} و در جهت ω{link} ({sense}) جدا کنید.",
    "vpolygon.why_fixed": "V_{point}، زیرا {known} ثابت است",
    "vpolygon.why_relative": "V_{point}/{known}",
    "vpolygon.perpendicular": "از {tip} خطی ⟂ {line} رسم کنید (راستای {why}).",
    "vpolygon.parallel_guide": "از o_v خطی موازی {why} رسم کنید (راستای V_{point}).",
    "vpolygon.slot": "از {tip} خطی موازی شیار میلهٔ {link} رسم کنید (راستای V_{point}/{other}، "
                     "یعنی سرعت لغزش).",
    "vpolygon.curve": "از {tip} خطی ⟂ {line} رسم کنید؛ این خط در نقطهٔ {point} بر شیار منحنی به "
                      "مرکز {centre} مماس است (راستای V_{rel}، یعنی سرعت لغزش).",
    "vpolygon.omega": "ω{link} = {rel} / {line} = {side} / {line} = {speed} ÷ {length} = "
                      "{omega} rad/s ({sense}: جهت گردش {rel} حول {about}).",
    "vpolygon.vector": "بردار o_v {tip} = V_{point} = {speed}.{then}",
    "vpolygon.relative": "بردار {a} {b} نمایانگر {rel} است. {omega}",
    "apolygon.input_normal": "از o_a بردار Aⁿ_{point} = ω{link}²·{pivot}{p} = ({omega} rad/s)² "
                             "× {radius} = {accel} را موازی {p}{pivot} و در جهت از {p} به سوی "
                             "{pivot} جدا کنید (مؤلفهٔ عمودی یا نرمال).",
    "apolygon.wheel_centre_path": "مرکز {point} از چرخ {link} روی مسیری مستقیم و موازی سطح تماس "
                                  "حرکت می‌کند: از o_a خطی ⟂ {contact}{point} رسم کنید (راستای "
                                  "A_{point}).",
    "apolygon.wheel_centre": "روی این خط، A_{point} = α{link}·r = {alpha} rad/s² × {radius} = "
                             "{accel} را در جهت α{link} ({sense}) جدا کنید: مرکز چرخی که روی "
                             "سطحی مستقیم می‌غلتد، شتابی عمود بر آن سطح ندارد. انتهای این بردار "
                             "{tip} است.",
    "apolygon.wheel_centre_still": "α{link} = 0 ({given}) و مرکز {point} از چرخ {link} روی "
                                   "مسیری مستقیم حرکت می‌کند، پس A_{point} = α{link}·r = 0؛ "
                                   "بنابراین {tip} بر o_a منطبق است.",
    "apolygon.given": "داده‌شده",
    "apolygon.not_given": "داده نشده است، پس برابر 0 فرض می‌شود",
    "apolygon.input_no_tangential": "α{link} = 0 ({given})، پس Aᵗ_{point} = α{link}·{pivot}{p} "
                                    "= 0؛ بنابراین {tip} بر انتهای Aⁿ_{point} منطبق است.",
    "apolygon.tangential_direction": "از انتهای آن خطی ⟂ {pivot}{p} رسم کنید (راستای Aᵗ_{point}).",
    "apolygon.input_tangential": "روی این خط، Aᵗ_{point} = α{link}·{pivot}{p} = {alpha} rad/s² "
                                 "× {radius} = {accel} را در جهت α{link} ({sense}) جدا کنید؛ "
                                 "انتهای آن {tip} است.",
    "apolygon.parallel_guide": "از o_a خطی موازی {why} رسم کنید (راستای A_{point}، زیرا راهنما "
                               "مستقیم و ثابت است).",
    "apolygon.no_normal": "ω{link} = 0، پس Aⁿ_{rel} = 0؛ از {tip} خطی ⟂ {line} رسم کنید (راستای "
                          "Aᵗ_{rel}؛ طول آن مجهول است).",
    "apolygon.normal": "از {tip} بردار Aⁿ_{rel} = ω{link}²·{line} = ({omega} rad/s)² × {length} "
                       "= {accel} را موازی {back} و در جهت از {x} به سوی {k} جدا کنید.",
    "apolygon.tangential_line": "از انتهای آن خطی ⟂ {line} رسم کنید (راستای Aᵗ_{rel}؛ طول آن "
                                "مجهول است).",
    "apolygon.say_tangential": "خط ⟂ {line} گذرنده از انتهای Aⁿ_{rel}",
    "apolygon.slot": "از انتهای آن خطی موازی شیار میلهٔ {link} رسم کنید (راستای شتاب لغزش "
                     "Aˢ_{rel}؛ طول آن مجهول است).",
    "apolygon.say_slot": "خط موازی شیار گذرنده از انتهای {component}",
    "apolygon.curve_normal": "از انتهای آن، مؤلفهٔ عمودی ناشی از مسیر نسبی، Aⁿ_{rel} = "
                             "V_{rel}²/ρ = ({speed})² ÷ {radius} = {accel}، را موازی {p}{k} جدا "
                             "کنید، در جهت از {p} به سوی مرکز انحنا {k}{reversed}.",
    "apolygon.reversed": "، ولی با جهت معکوس، زیرا کم می‌شود",
    "apolygon.curve_tangent": "از انتهای آن خطی ⟂ {line}، یعنی مماس بر شیار، رسم کنید (راستای "
                              "Aᵗ_{rel}؛ طول آن مجهول است).",
    "apolygon.still": "ω{link} = 0 (میلهٔ {link} در این لحظه ساکن است)",
    "apolygon.stuck": "V_{rel} = 0 (در این لحظه لغزشی وجود ندارد)",
    "apolygon.coriolis_zero": "مؤلفهٔ کوریولیس 2ω{link}·V_{rel} صفر است، زیرا {why}.",
    "apolygon.coriolis_direction": "از {tip} خطی ⟂ شیار میلهٔ {link} رسم کنید (راستای مؤلفهٔ "
                                   "کوریولیس).",
    "apolygon.along_it": "روی این خط",
    "apolygon.from_along": "از {tip} در امتداد {line}",
    "apolygon.coriolis": "{where}، مؤلفهٔ کوریولیس Aᶜ_{rel} = 2ω{link}·V_{rel} = 2 × {omega} "
                         "rad/s × {speed} = {accel} را در جهت V_{rel} که 90° در جهت گردش "
                         "ω{link} ({sense}) چرخانده شده است، جدا کنید{reversed}.",
    "apolygon.vector": "بردار o_a {tip} = A_{point} = {accel}.{then}",
    "apolygon.what_tangential": "Aᵗ_{rel}",
    "apolygon.what_part": "مؤلفه‌ای از A_{rel} که ⟂ {line} است",
    "apolygon.alpha": "α{link} = {what} / {line} = {accel} ÷ {length} = {alpha} rad/s² "
                      "({sense}: جهت گردش {what} حول {about}).",
    "transmission.line": "خط انتقال {a}{b} را در امتداد میلهٔ رابط (میلهٔ {link}) رسم کنید: "
                         "مؤلفه‌های سرعت {a} و {b} در امتداد این خط برابرند.",
    "transmission.perpendicular": "از {centre} عمودی بر {a}{b} رسم کنید.",
    "transmission.foot": "این عمود، {a}{b} را در {foot} قطع می‌کند.",
    "transmission.measure": "طول {centre}{foot} را اندازه بگیرید: {centre}{foot} = {length}.",
    "transmission.ratio": "طول {o_f}H را اندازه بگیرید: {o_f}H = {length}. سرعت‌های زاویه‌ای با "
                          "این عمودها نسبت عکس دارند: ω{n}/ω{d} = {o_d}G/{o_f}H = {ratio}، و "
                          "مراکز دوران در {sides} خط قرار دارند، پس ω{n} = {omega} rad/s "
                          "({sense}).",
    "limits.join_cranks": "پاره‌خط‌های {pivot}{a} و {pivot}{b} را رسم کنید: لنگ در دو وضعیت حدی "
                          "خود.",
    "limits.measure": "زاویهٔ {a}{pivot}{b} را که لنگ از {a} تا {b} ({sense}، هم‌جهت با "
                      "ω{link}) می‌چرخد اندازه بگیرید: {degrees}°، مربوط به کورس {stroke}.",
    "limits.in_line": "به مرکز {pivot} و شعاع {span} = {radius} کمانی بزنید تا {path} را در "
                      "{point} قطع کند: لنگ و میلهٔ رابط در یک راستا قرار دارند، {how}.",
    "limits.span_sum": "{a}{b} + {pivot}{a}",
    "limits.span_difference": "{a}{b} − {pivot}{a}",
    "limits.path_of": "مسیر {point}",
    "limits.arc_about": "کمان مسیر {point} به مرکز {centre}",
    "limits.crank_along": "نقطهٔ {pivot} را به {point} وصل کنید؛ لنگ روی این خط قرار دارد: "
                          "{pin} به فاصلهٔ {pivot}{crank} = {radius} از {pivot} و به سمت "
                          "{point} است.",
    "limits.crank_beyond": "نقطهٔ {point} را به {pivot} وصل کنید و این خط را از {pivot} به بعد "
                           "امتداد دهید: {pin} به فاصلهٔ {pivot}{crank} = {radius} از {pivot} و "
                           "در طرف مقابل آن است.",
    "limits.bisect": "پاره‌خط {a}{b} را نصف کنید و نقطهٔ وسط آن را M بنامید.",
    "limits.thales": "به مرکز M و شعاع M{a} دایره‌ای به قطر {a}{b} رسم کنید: از هر نقطهٔ این "
                     "دایره، {a} و {b} با زاویهٔ 90° دیده می‌شوند.",
    "limits.crank_circle": "به مرکز {pivot} و شعاع {pivot}{pin} = {radius} دایرهٔ لنگ را رسم کنید.",
    "limits.tangent_cuts": "دو دایره یکدیگر را در {pin}′ و {pin}″ قطع می‌کنند (هر کدام در یک "
                           "طرف {a}{b})، یعنی در نقاطی که {a}{pin} ⟂ {b}{pin}.",
    "limits.second_cut": "نقطهٔ {pin}″ محل تقاطع دوم است.",
    "limits.lever": "نقطهٔ {pivot} را به {pin} وصل کنید: این خط، اهرم مماس بر دایرهٔ لنگ در "
                    "وضعیت حدی {which} آن است.",
    "limits.stroke": "طول {point}″{point}′ را اندازه بگیرید: کورس {point} برابر {length} است.",
    "limits.produce_lever": "خط {pivot}{held} را امتداد دهید تا مسیر {point} را در {end} قطع کند.",
    "limits.rod_cuts_path": "به مرکز {x} و شعاع {span} = {radius} کمانی بزنید تا مسیر {point} "
                            "را در {end} قطع کند.",
    "limits.rod": "نقطهٔ {a} را به {b} وصل کنید: میلهٔ {link} در آن وضعیت حدی.",
    "limits.swing": "به مرکز {pivot}، نقطهٔ {point} را همراه با اهرم به اندازهٔ زاویهٔ "
                    "{held}{pivot}{held_there} بچرخانید تا به {there} برسد.",
}


# The figures' words of each chapter, kept beside the chapter's figures.
for _chapter in (fa_trains, fa_balancing, fa_cams, fa_forces, fa_grading):
    WORDS.update(_chapter.WORDS)
