"""Persian words on the figures of gear trains (graphics/train_*.py, kutzbach_figure.py,
involute_figure.py).

Keys are the English words as the figure code says them
(:func:`~tarsim.constructions.narration.words`); the terms are the course notes'
(docs/glossary-fa.md).
"""

from __future__ import annotations

WORDS: dict[str, str] = {
    # the scales' names
    "Radius scale": "مقیاس شعاع",
    # the members, as the files name them (a name the catalogue lacks stays as given)
    "sun": "چرخ خورشیدی", "planet": "چرخ سیاره\u200cای", "ring": "چرخ حلقه\u200cای",
    "arm": "بازو", "carrier": "بازو", "idler": "چرخ هرزگرد", "pinion": "پینیون",
    "wheel": "چرخ", "fixed ring": "چرخ حلقه\u200cای ثابت",
    "output ring": "چرخ حلقه\u200cای خروجی", "fixed sun": "چرخ خورشیدی ثابت",
    "output sun": "چرخ خورشیدی خروجی", "input sun": "چرخ خورشیدی ورودی",
    "second planet": "چرخ سیاره\u200cای دوم", "compound planet": "چرخ سیاره\u200cای مرکب",
    "gear {gear}": "چرخدندهٔ {gear}", "gear {gear} ({name})": "چرخدندهٔ {gear} ({name})",
    "the arm {arm}": "بازوی {arm}", "the arm {arm} ({name})": "بازوی {arm} ({name})",
    # the side view (train_schematic.py)
    "{name}: the train": "{name}: قطار چرخدنده",
    "member {member} fixed (hatched)": "عضو {member} ثابت است (هاشورخورده)",
    "every axis fixed in the housing": "همهٔ محورها در پوسته ثابت\u200cاند",
    "radii to scale, the planes apart":
        "شعاع\u200cها با مقیاس؛ صفحه\u200cها فقط جدا از هم، بدون مقیاس",
    # the tabular method (train_table.py)
    "{name}: the tabular method": "{name}: روش جدولی",
    # (a signed count in right-to-left words would carry its sign to its right: said in
    # words, as the notes' table says them)
    "whole train locked, {turn}": "کل قطار قفل\u200cشده، یک دور مثبت",
    "arm {arm} held, {fixed} turned {turn}": "بازوی {arm} ثابت، {fixed} یک دور منفی",
    "total": "مجموع",
    "× {scale} {unit}: speed": "× {scale} {unit}: سرعت",
    "speed ({unit}, ccw +)": "سرعت ({unit}، پادساعتگرد +)",
    "Speeds in {unit}, counter-clockwise positive. Each is checked by the Willis equation of "
    "every mesh, solved as one linear system: the same fraction.":
        "سرعت\u200cها بر حسب {unit}، پادساعتگرد مثبت. هر یک با معادلهٔ ویلیس همهٔ "
        "درگیری\u200cها، که با هم به\u200cصورت یک دستگاه خطی حل می\u200cشوند، کنترل شده است: "
        "همان کسر به دست می\u200cآید.",
    # the velocity (Kutzbach) diagram
    "{name}: velocity (Kutzbach) diagram": "{name}: نمودار سرعت (کوتزباخ)",
    "{member} fixed; velocities across the radial line, ccw to the right":
        "{member} ثابت است؛ سرعت\u200cها عمود بر خط شعاعی، پادساعتگرد به سمت راست",
    "each member's ω is the slope Δv/Δr of its line": "ω هر عضو، شیب Δv/Δr خط آن است",
    # the involute mesh
    "to {centre}": "به سوی {centre}",
    "module {module} {mm}, {z1} and {z2} teeth, pressure angle {angle}°":
        "مدول {module} {mm}، {z1} و {z2} دندانه، زاویهٔ فشار {angle} درجه",
    "path of contact AB = {path} {mm}, contact ratio {ratio}":
        "مسیر تماس AB = {path} {mm}، نسبت تماس {ratio}",
    "pitch circles": "دایره\u200cهای گام", "base circles": "دایره\u200cهای مبنا",
    "addendum and root circles": "دایره\u200cهای ادندم و ریشه", "line of action": "خط عمل",
    "line of centres, common tangent": "خط\u200cالمرکزین، مماس مشترک",
    "path of contact": "مسیر تماس", "tooth profiles": "پروفیل\u200cهای دندانه",
    # a mesh's results (exercises/gears/train_solution.py)
    "involute mesh": "درگیری اینولوت",
    "involute mesh, drawn with fewer teeth until clear":
        "درگیری اینولوت، ترسیم‌شده با دندانه‌های کمتر تا جایی که تداخل نماند",
    "{n} teeth on the pinion": "{n} دندانه روی پینیون",
    "none": "ندارد", "and": "و",
    "the tips of gear {gears} cut into the other's flank":
        "نوک دندانه‌های چرخدندهٔ {gears} در دامنهٔ دندانه‌های چرخدندهٔ دیگر فرو می‌رود",
}
