"""Persian words on the figures of forces (graphics/forces/force_figure.py, free_body_figure.py,
loads_figure.py, load_marks.py).

Keys are the English words as the figure code says them
(:func:`~tarsim.constructions.narration.words`); the terms are the course notes'
(docs/glossary-fa.md).
"""

from __future__ import annotations

WORDS: dict[str, str] = {
    # the turning-moment diagram (exercises/forces/turning_moment.py)
    "the input turning steadily at ω = {omega} {unit} (α = 0)":
        "ورودی با سرعت ثابت ω = {omega} {unit} می\u200cچرخد (α = ۰)",
    # the force polygons
    "each link's loads head to tail; a polygon closed by two lines crossing at x, or by its "
    "heavy closing side": "بارهای هر میله پشت سر هم؛ هر چندضلعی با دو خطی که یکدیگر را در x "
                          "قطع می\u200cکنند، یا با ضلع بسته\u200cکنندهٔ پررنگ خود بسته "
                          "می\u200cشود",
    "a force": "نیرو", "a closing side": "ضلع بسته\u200cکننده",
    "a line of known direction": "خط با راستای معلوم",
    "link {link}": "میلهٔ {link}", "links {i}, {j}": "میله\u200cهای {i} و {j}",
    # the free bodies
    "each link alone with every force on it; its forces add to nothing":
        "هر میله به\u200cتنهایی با همهٔ نیروهای وارد بر آن؛ برآیند نیروهای آن صفر است",
    # the loads on the space diagram
    "a load": "بار",
    "an inertia force and couple as one force, offset h from G":
        "نیروی اینرسی و کوپل اینرسی به\u200cصورت یک نیرو، به فاصلهٔ h از G",
    # the loads too small to draw, listed under the figure
    "Too small to draw: {items}.": "رسم نشده\u200cاند، چون بسیار کوچک\u200cاند: {items}.",
    "{name} = {size} on link {link}": "{name} = {size} روی میلهٔ {link}",
    # a load, or an inertia force moved off G by h, that would stand beyond the drawing
    "Beyond the drawing, so not drawn: {items}.": "بیرون از نقشه، پس رسم نشده\u200cاند: {items}.",
    "{name} (h = {h}) on link {link}": "{name} (h = {h}) روی میلهٔ {link}",
    # the bundled exercises' loads, by the names their files give them
    "gas force": "نیروی گاز", "cutting force": "نیروی برش", "load torque": "گشتاور بار",
}
