"""Persian words on the figures of balancing (graphics/balance_figures.py).

Keys are the English words as the figure code says them
(:func:`~tarsim.constructions.narration.words`); the terms are the course notes'
(docs/glossary-fa.md).
"""

from __future__ import annotations

WORDS: dict[str, str] = {
    # An angle after Persian words is said in درجه: a degree sign closing a right-to-left
    # line is set left of its number by the shaping the PDF takes (python-bidi).
    # a rotor: the space diagram, the table, the polygons
    "{name}: space diagram": "{name}: نمودار فضایی",
    "{name}: side view": "{name}: نمای جانبی",
    "{name}: the table": "{name}: جدول",
    "{name}: force polygon": "{name}: چندضلعی نیرو",
    "{name}: couple polygon (reference plane {plane})":
        "{name}: چندضلعی کوپل (صفحهٔ مرجع {plane})",
    "{name}: {mass} {kg} at {radius} {unit}, {angle}°":
        "{name}: {mass} {kg} در شعاع {radius} {unit}، زاویهٔ {angle} درجه",
    " = {size} {unit} at {angle}°": " = {size} {unit} با زاویهٔ {angle} درجه",
    "end view: each mass on its radial line, angles from the reference radius (the short "
    "dashed one), counter-clockwise":
        "نمای انتهایی: هر جرم روی خط شعاعی خود؛ زاویه\u200cها از شعاع مرجع (خط\u200cچین "
        "کوتاه)، پادساعتگرد",
    "a mass": "یک جرم", "a balancing mass found": "جرم متعادل\u200cکنندهٔ به\u200cدست\u200cآمده",
    "side view: the planes along the shaft, positions in {unit}":
        "نمای جانبی: صفحه\u200cها در امتداد محور، موقعیت\u200cها بر حسب {unit}",
    "a mass's plane": "صفحهٔ یک جرم", "a balancing plane": "صفحهٔ متعادل\u200cکننده",
    "head to tail, each parallel to its radial line; the heavy side closes it":
        "پشت سر هم، هر یک موازی خط شعاعی خود؛ ضلع پررنگ آن را می\u200cبندد",
    "the vectors": "بردارها", "the closing side": "ضلع بسته\u200cکننده",
    "l from the reference plane {plane}; ": "l از صفحهٔ مرجع {plane}؛ ",
    "the rows under the rule are the balancing masses found":
        "سطرهای زیر خط، جرم\u200cهای متعادل\u200cکنندهٔ به\u200cدست\u200cآمده\u200cاند",
    # an engine: its four polygons
    "primary force": "نیروی اولیه", "primary couple": "کوپل اولیه",
    "secondary force": "نیروی ثانویه", "secondary couple": "کوپل ثانویه",
    "closed: balanced": "بسته: متوازن",
    "{size} {unit} unbalanced": "{size} {unit} نامیزان",
    "couples about the central plane; secondary vectors along the cranks at 2θᵢ, each m·r/n":
        "کوپل\u200cها حول صفحهٔ میانی؛ بردارهای ثانویه در امتداد لنگ\u200cها با زاویهٔ 2θᵢ، "
        "هر یک m·r/n",
    "cyl. {number}": "سیلندر {number}",
    # a single cylinder: its forces against crank angle
    "Unbalanced forces": "نیروهای نامیزان",
    "crank angle θ (°)": "زاویهٔ لنگ θ (°)",
    "primary": "اولیه", "secondary": "ثانویه",
    "left along the stroke": "باقی\u200cمانده در امتداد کورس",
    "left across the stroke": "باقی\u200cمانده عمود بر کورس",
    "{share} of the reciprocating mass balanced by a rotating mass opposite the crank":
        "{share} از جرم رفت\u200cوبرگشتی با جرمی دوار روبه\u200cروی لنگ متعادل شده است",
    "at θ = {angle}°": "در θ = {angle} درجه",
}
