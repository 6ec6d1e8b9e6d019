"""Persian words on the figures of balancing (graphics/balancing/balance_figures.py).

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
    "end view: each mass on its radial line, angles from the reference radius (the short "
    "dashed one), clockwise":
        "نمای انتهایی: هر جرم روی خط شعاعی خود؛ زاویه\u200cها از شعاع مرجع (خط\u200cچین "
        "کوتاه)، ساعتگرد",
    "angles are measured clockwise from the reference radius, as the file gives them, and "
    "every angle found is read the same way":
        "زاویه\u200cها، چنان که پرونده می\u200cدهد، ساعتگرد از شعاع مرجع اندازه گرفته "
        "می\u200cشوند و هر زاویهٔ یافته\u200cشده نیز همین\u200cگونه خوانده می\u200cشود",
    "m = W/g, g = {g} m/s²": "m = W/g، g = {g} m/s²",
    "a mass": "یک جرم", "a balancing mass found": "جرم متعادل\u200cکنندهٔ به\u200cدست\u200cآمده",
    "side view: the planes along the shaft, positions in {unit}":
        "نمای جانبی: صفحه\u200cها در امتداد محور، موقعیت\u200cها بر حسب {unit}",
    "a mass's plane": "صفحهٔ یک جرم", "a balancing plane": "صفحهٔ متعادل\u200cکننده",
    "head to tail, each parallel to its radial line; the heavy side closes it":
        "پشت سر هم، هر یک موازی خط شعاعی خود؛ ضلع پررنگ آن را می\u200cبندد",
    "head to tail, each parallel to its radial line":
        "پشت سر هم، هر یک موازی خط شعاعی خود",
    "the vectors": "بردارها", "the closing side": "ضلع بسته\u200cکننده",
    "l from the reference plane {plane}; ": "l از صفحهٔ مرجع {plane}؛ ",
    "the rows under the rule are the balancing masses found":
        "سطرهای زیر خط، جرم\u200cهای متعادل\u200cکنندهٔ به\u200cدست\u200cآمده\u200cاند",
    "plane {plane} needs no balancing mass: its polygon closes on itself":
        "صفحهٔ {plane} به جرم متعادل\u200cکننده نیازی ندارد: چندضلعی آن خودبه\u200cخود بسته است",
    " = 0: no mass needed": " = ۰: جرمی لازم نیست",
    # an engine: its four polygons
    "primary force": "نیروی اولیه", "primary couple": "کوپل اولیه",
    "secondary force": "نیروی ثانویه", "secondary couple": "کوپل ثانویه",
    "closed: balanced": "بسته: متوازن",
    "{size} {unit} unbalanced, greatest at θ₁ = {angle}°":
        "{size} {unit} نامیزان، بیشینه در θ₁ = {angle} درجه",
    "couples about the central plane; secondary vectors along the cranks at 2θᵢ, each m·r/n":
        "کوپل\u200cها حول صفحهٔ میانی؛ بردارهای ثانویه در امتداد لنگ\u200cها با زاویهٔ 2θᵢ، "
        "هر یک m·r/n",
    "cyl. {number}": "سیلندر {number}",
    "each vector {product}·ω²": "هر بردار {product}·ω²",
    # the end view of the cranks beside a polygon; an angle after a number said in درجه
    "end view of the cranks, at θᵢ": "نمای انتهایی لنگ\u200cها، با زاویهٔ θᵢ",
    "end view of the secondary cranks, at 2θᵢ":
        "نمای انتهایی لنگ\u200cهای ثانویه، با زاویهٔ 2θᵢ",
    "{cranks}: {angle}°": "{cranks}: {angle} درجه",
    "i.d.c.": "نقطهٔ مرگ داخلی",
    "each vector {product}·ω², ω = {speed} rad/s": "هر بردار {product}·ω²، ω = {speed} rad/s",
    # a single cylinder: its forces against crank angle
    "Unbalanced forces": "نیروهای نامیزان",
    "crank angle θ (°)": "زاویهٔ لنگ θ (°)",
    "primary": "اولیه", "secondary": "ثانویه",
    "left along the stroke": "باقی\u200cمانده در امتداد کورس",
    "left across the stroke": "باقی\u200cمانده عمود بر کورس",
    "resultant left": "برآیند باقی\u200cمانده",
    "mass {name}: {found}": "جرم {name}: {found}",
    "two crossings close the {polygon} polygon: the other, the mirror image, balances the "
    "rotor too":
        "دو نقطهٔ تقاطع چندضلعی {polygon} را می‌بندند: دیگری، قرینهٔ آینه‌ای این یک، روتور را "
        "نیز متعادل می‌کند",
    "taken: mass {name}'s angle between {lo}° and {hi}°, as its between asks":
        "برگزیده: زاویهٔ جرم {name} میان {lo}° و {hi}°، چنان‌که between آن می‌خواهد",
    "taken: the crossing left of the last tip → the pole; between = [from, to] on a mass "
    "with an unknown angle takes the other":
        "برگزیده: نقطهٔ تقاطعِ سمت چپِ نوک آخر ← نقطهٔ شروع؛ between = [from, to] روی جرمی "
        "با زاویهٔ مجهول دیگری را برمی‌گزیند",
    "taken: the first crossing along the line from the last tip; between = [from, to] on a "
    "mass with an unknown angle takes the other":
        "برگزیده: نخستین نقطهٔ تقاطع در امتداد خط از نوک آخر؛ between = [from, to] روی جرمی "
        "با زاویهٔ مجهول دیگری را برمی‌گزیند",
    "firing order {order}, {strokes}-stroke: a cylinder fires every {every}°, each crank set "
    "that far behind the one fired before it: {cranks}":
        "ترتیب احتراق {order}، {strokes}-زمانه: هر {every}° یک سیلندر احتراق می‌کند و هر لنگ "
        "به همان اندازه پشت لنگِ سیلندرِ پیش از خود قرار می‌گیرد: {cranks}",
    "cylinder {number} at {angle}°": "سیلندر {number} در {angle}°",
    "with {share} of the reciprocating mass balanced, {left} of it is left: the primary force "
    "along the stroke at most {force} N (a locomotive's variation of tractive force, ±) and "
    "the primary couple {couple} N·m (its swaying couple, ±)":
        "با متعادل کردن {share} از جرم رفت‌وبرگشتی، {left} آن باقی می‌ماند: نیروی اولیه در "
        "امتداد کورس حداکثر {force} N (تغییر نیروی کششِ لوکوموتیو، ±) و کوپل اولیه {couple} "
        "N·m (کوپل نوسانی آن، ±)",
    "hammer blow in plane {plane}: the balance mass's share for the reciprocating mass "
    "turning, B·ω²·b = {blow} N":
        "ضربهٔ چکشی در صفحهٔ {plane}: سهم جرم متعادل‌کننده برای جرم رفت‌وبرگشتی در حال دوران، "
        "B·ω²·b = {blow} N",
    "Resultant forces of the V engine": "نیروهای برآیند موتور V",
    "{vee}° between the lines, θ from the centre line":
        "{vee} درجه میان خط‌های کورس، θ از خط میانی",
    "V engine, {vee}° between its lines, at θ = {angle}° from the centre line: the {kind} "
    "resultant {size} N ({along} N along the centre line, {across} N across it)":
        "موتور V با {vee}° میان خط‌های کورس، در θ = {angle}° از خط میانی: برآیند {kind} "
        "{size} N ({along} N در امتداد خط میانی و {across} N عمود بر آن)",
    "Resultant forces of the radial engine": "نیروهای برآیند موتور شعاعی",
    "{count} cylinders {pitch}° apart, θ from cylinder 1's line":
        "{count} سیلندر با {pitch} درجه فاصله، θ از خط سیلندر ۱",
    "radial engine, {count} cylinders {pitch}° apart on one crank, at θ = {angle}° from "
    "cylinder 1's line: the {kind} resultant {size} N ({along} N along that line, {across} N "
    "across it)":
        "موتور شعاعی با {count} سیلندر به فاصلهٔ {pitch}° روی یک لنگ، در θ = {angle}° از خط "
        "سیلندر ۱: برآیند {kind} {size} N ({along} N در امتداد آن خط و {across} N عمود بر آن)",
    "the {kind} resultant points {direction}° from cylinder 1's line: {sense}":
        "برآیند {kind} در {direction}° از خط سیلندر ۱ است: {sense}",
    "along the crank, turning with it (the direct cranks)":
        "در امتداد لنگ و همراه آن در گردش (لنگ‌های مستقیم)",
    "at −2θ, turning at twice the crank's speed against it (the reverse cranks)":
        "در −2θ، با دو برابر سرعت لنگ و در خلاف جهت آن در گردش (لنگ‌های معکوس)",
    "the {kind} resultant is {size} N at every crank angle":
        "برآیند {kind} در هر زاویهٔ لنگ {size} N است",
    "the greatest {kind} resultant: {size} N, first at θ = {angle}°":
        "بیشترین برآیند {kind}: {size} N، نخست در θ = {angle}°",
    "the least {kind} resultant: {size} N, first at θ = {angle}°":
        "کمترین برآیند {kind}: {size} N، نخست در θ = {angle}°",
    "with crank 1 at {angle}° from the i.d.c., along the line of stroke: {values}":
        "با لنگ ۱ در {angle}° از نقطهٔ مرگ داخلی، در امتداد خط کورس: {values}",
    "out of balance: the {which} {size} {unit} at {angle}° ({product} {units} × ω², ω = "
    "{speed} rad/s)":
        "نامیزانی: {which} {size} {unit} با زاویهٔ {angle}° ({product} {units} × ω²، ω = "
        "{speed} rad/s)",
    "no out-of-balance {which}: its polygon closes on itself":
        "{which} نامیزانی ندارد: چندضلعی آن خودبه‌خود بسته است",
    "couples about the plane at {place}": "کوپل‌ها حول صفحه‌ای در {place}",
    "polygons closed: {verdict}": "چندضلعی‌ها بسته شدند: {verdict}",
    "{name}: couple polygon about the plane at {place} {unit}":
        "{name}: چندضلعی کوپل حول صفحه‌ای در {place} {unit}",
    "the wheel lifts off the rail where the hammer blow reaches the dead load of {load} N: at "
    "ω = {speed} rad/s":
        "چرخ آنجا از ریل بلند می‌شود که ضربهٔ چکشی به بار مردهٔ {load} N برسد: در ω = {speed} "
        "rad/s",
    "the hammer blow reaches the greatest allowed, {load} N, at ω = {speed} rad/s":
        "ضربهٔ چکشی در ω = {speed} rad/s به بیشترین مقدار مجاز، {load} N، می‌رسد",
    ": the greatest speed": ": بیشترین سرعت",
    ", {road} km/h on the wheels": "، {road} km/h روی چرخ‌ها",
    "force": "نیرو", "couple": "کوپل",
    "each where the algebra puts it": "هر یک همان‌جا که حل جبری نشان می‌دهد",
    ": found": ": یافته‌شده",
    "a mass with unknowns, found": "جرمی با مجهول‌ها، یافته‌شده",
    "a plane found": "صفحهٔ یافته‌شده",
    "the mirror image: {found}": "قرینهٔ آینه‌ای: {found}",
    "{mass} {kg} at {radius} {unit} opposite the crank balances {share} of m_rec and all of "
    "m_rev":
        "{mass} {kg} در شعاع {radius} {unit} روبه‌روی لنگ، {share} از m_rec و همهٔ m_rev را "
        "متعادل می‌کند",
    "{share} of the reciprocating mass balanced by a rotating mass opposite the crank":
        "{share} از جرم رفت\u200cوبرگشتی با جرمی دوار روبه\u200cروی لنگ متعادل شده است",
    "at θ = {angle}°": "در θ = {angle} درجه",
    # the results steps.md lists (exercises/balancing/balance_solution.py): a markdown line,
    # where the degree sign stays by its number
    "ΣF_x = {x}ω², ΣF_y = {y}ω² (kg·m): the resultant {size} kg·m at {angle}° ({force} N at "
    "ω = {speed} rad/s)":
        "ΣF_x = {x}ω²، ΣF_y = {y}ω² (kg·m): برآیند {size} kg·m با زاویهٔ {angle}° ({force} N "
        "در ω = {speed} rad/s)",
    "ΣF_x = {x}ω², ΣF_y = {y}ω² (kg·m): the resultant {size} kg·m at {angle}°":
        "ΣF_x = {x}ω²، ΣF_y = {y}ω² (kg·m): برآیند {size} kg·m با زاویهٔ {angle}°",
    "plane {plane}: balancing m·r = {size} kg·m at {angle}°, so {mass} kg at {radius}":
        "صفحهٔ {plane}: m·r متعادل‌کننده = {size} kg·m با زاویهٔ {angle}°، یعنی جرم {mass} "
        "kg در شعاع {radius}",
    "the weights are in N: each mass is m = W/g, g = {g} m/s², and each balancing mass is "
    "given back as its weight W = m·g":
        "وزن‌ها بر حسب N‌اند: جرم هر یک m = W/g است، با g = {g} m/s²، و هر جرم متعادل‌کننده "
        "با وزن آن، W = m·g، داده می‌شود",
    "the balance weight in plane {plane}: {weight} N at {radius}":
        "وزن متعادل‌کننده در صفحهٔ {plane}: {weight} N در شعاع {radius}",
    "mass {name} is a solid disc of density {density} kg/m³, {diameter} in diameter and "
    "{thickness} thick: m = ρ·πd²/4·t = {mass} kg":
        "جرم {name} دیسکی توپر با چگالی {density} kg/m³، قطر {diameter} و ضخامت {thickness} "
        "است: m = ρ·πd²/4·t = {mass} kg",
    "the out-of-balance force on a bearing in plane {plane}: m·r·ω² = {force} N at "
    "{angle}° (ω = {speed} rad/s)":
        "نیروی نامیزان روی یاتاقانی در صفحهٔ {plane}: m·r·ω² = {force} N با زاویهٔ "
        "{angle}° (ω = {speed} rad/s)",
    "the out-of-balance force in plane {plane}, the masses' force and couple shared between "
    "the two planes: m·r·ω² = {force} N at {angle}° (ω = {speed} rad/s)":
        "نیروی نامیزان در صفحهٔ {plane}، نیرو و کوپل جرم‌ها میان دو صفحه تقسیم شده: m·r·ω² = "
        "{force} N با زاویهٔ {angle}° (ω = {speed} rad/s)",
    "bearing {name} at {place}: the out-of-balance force {force} N at {angle}°, the force and "
    "the couple shared between the bearings by moments":
        "یاتاقان {name} در {place}: نیروی نامیزان {force} N با زاویهٔ {angle}°؛ نیرو و کوپل "
        "با گشتاورگیری میان یاتاقان‌ها تقسیم شده‌اند",
    "2-1, between": "۲-۱، میان", "2-2, outside": "۲-۲، بیرون از",
    "the masses lie in one axial plane: one mass of m·r = {size} kg·m at {angle}° in the plane "
    "at {place} balances force and couple together (the notes' case {case} the masses' planes: "
    "moments about each mass's plane fix it)":
        "جرم‌ها همه در یک صفحهٔ محوری‌اند: یک جرم با m·r = {size} kg·m و زاویهٔ "
        "{angle}° در صفحه‌ای به فاصلهٔ {place}، نیرو و کوپل را با هم متعادل می‌کند "
        "(حالت {case} صفحه‌های جرم‌ها در جزوه: گشتاورگیری حول صفحهٔ هر جرم آن را "
        "معین می‌کند)",
    "at {place} one plane balances the forces only: a couple of {couple} kg·m² (× ω²) at "
    "{angle}° is left, for a second plane to take":
        "یک صفحه در {place} تنها نیروها را متعادل می‌کند: کوپلی به اندازهٔ {couple} kg·m² "
        "(× ω²) با زاویهٔ {angle} درجه باقی می‌ماند که صفحهٔ دومی باید آن را بگیرد",
    "at {place} one plane balances the forces only: a couple of {couple} N·m at {angle}° (at "
    "ω = {speed} rad/s) is left, for a second plane to take":
        "یک صفحه در {place} تنها نیروها را متعادل می‌کند: کوپلی به اندازهٔ {couple} N·m با "
        "زاویهٔ {angle} درجه (در ω = {speed} rad/s) باقی می‌ماند که صفحهٔ دومی باید آن را "
        "بگیرد",
    "ΣF_x = ΣF_y = 0 (kg·m): the masses' forces cancel, with no resultant":
        "ΣF_x = ΣF_y = ۰ (kg·m): نیروهای جرم‌ها یکدیگر را خنثی می‌کنند و برآیندی ندارند",
    "plane {plane}: no balancing mass needed, the force polygon closes on itself (Σ mᵢrᵢ = 0)":
        "صفحهٔ {plane}: جرم متعادل‌کننده لازم نیست، چندضلعی نیرو خودبه‌خود بسته است "
        "(Σ mᵢrᵢ = ۰)",
    "plane {plane}: no balancing mass needed, the couple polygon closes on itself "
    "(Σ mᵢrᵢlᵢ = 0 about plane {a})":
        "صفحهٔ {plane}: جرم متعادل‌کننده لازم نیست، چندضلعی کوپل خودبه‌خود بسته است "
        "(Σ mᵢrᵢlᵢ = ۰ حول صفحهٔ {a})",
    "plane {plane}: no balancing mass needed, the force polygon closes on itself "
    "(Σ mᵢrᵢ + (m r)_{b} = 0)":
        "صفحهٔ {plane}: جرم متعادل‌کننده لازم نیست، چندضلعی نیرو خودبه‌خود بسته است "
        "(Σ mᵢrᵢ + (m r)_{b} = ۰)",
    "each where the vector sum puts it": "هر یک همان‌جا که جمع برداری نشان می‌دهد",
    "polygons closed: {verdict}; the balanced rotor's residual force {residual} kg·m":
        "چندضلعی‌ها بسته شدند: {verdict}؛ نیروی باقی‌ماندهٔ روتور متعادل‌شده "
        "{residual} kg·m",
    "at θ = {angle}°: primary force {primary} N, secondary {secondary} N along the line of "
    "stroke (n = l/r = {n})":
        "در θ = {angle}°: نیروی اولیه {primary} N و نیروی ثانویه {secondary} N در امتداد خط "
        "کورس (n = l/r = {n})",
    "with {share} of the reciprocating mass balanced by a rotating mass: {along} N along the "
    "line of stroke and {across} N across it":
        "با متعادل کردن {share} از جرم رفت‌وبرگشتی به کمک جرمی دوار: {along} N در امتداد "
        "خط کورس و {across} N عمود بر آن",
    "at most {along} N along (θ = 0°, 180°) and {across} N across (θ = 90°, 270°)":
        "حداکثر {along} N در امتداد کورس (θ = ۰°، ۱۸۰°) و {across} N عمود بر آن "
        "(θ = ۹۰°، ۲۷۰°)",
    "at θ = {angle}°: primary force {primary} N along the line of stroke (no rod given: no "
    "secondary force)":
        "در θ = {angle}°: نیروی اولیه {primary} N در امتداد خط کورس (طول شاتون داده نشده: "
        "نیروی ثانویه‌ای خواسته نشده است)",
    "the unbalanced primary force's resultant: {size} N at θ = {angle}°, at most {most} N":
        "برآیند نیروی اولیهٔ نامیزان: {size} N در θ = {angle}°، حداکثر {most} N",
    "the balance mass opposite the crank: B·b = (m_rev + c·m)·r = {product} kg·m, so {mass} "
    "kg at {radius}":
        "جرم متعادل‌کننده روبه‌روی لنگ: B·b = (m_rev + c·m)·r = {product} kg·m، پس {mass} "
        "kg در شعاع {radius}",
    "{kind}: balanced (its polygon closes)": "{kind}: متوازن (چندضلعی آن بسته است)",
    "{kind} greatest with crank 1 at {angle}° from the i.d.c., and every {every}° on":
        "{kind} در بیشترین مقدار خود وقتی لنگ ۱ در {angle}° از نقطهٔ مرگ داخلی است، و هر "
        "{every}° پس از آن",
    "balance masses: each cylinder's revolving mass and {share} of its reciprocating mass, "
    "{mass} kg at the crank radius along its crank, balanced as rotating masses":
        "جرم‌های متعادل‌کننده: جرم دوار هر سیلندر و {share} از جرم رفت‌وبرگشتی آن، {mass} kg "
        "در شعاع لنگ و در امتداد لنگ آن، مانند جرم‌های دوار متعادل می‌شوند",
    "the greatest secondary force: {most} N, at θ = 0°, 90°, 180° and 270°":
        "بیشترین نیروی ثانویه: {most} N، در θ = ۰°، ۹۰°، ۱۸۰° و ۲۷۰°",
    "{kind}: unbalanced, {left} {unit} at most (the vector sum: {value} {unit})":
        "{kind}: نامیزان، حداکثر {left} {unit} (جمع برداری: {value} {unit})",
    "{kind}: unbalanced, {left} {unit} × ω² at most (no speed given)":
        "{kind}: نامیزان، حداکثر {left} {unit} × ω² (سرعتی داده نشده)",
    "no speed is given: every force and couple below is at the lift speed found, ω = {speed} "
    "rad/s":
        "سرعتی داده نشده است: همهٔ نیروها و کوپل‌های زیر در سرعتِ یافته‌شدهٔ بلند شدن چرخ‌اند، "
        "ω = {speed} rad/s",
    "no speed is given: every force and couple below is at the speed found where the hammer "
    "blow reaches the greatest allowed, ω = {speed} rad/s":
        "سرعتی داده نشده است: همهٔ نیروها و کوپل‌های زیر در سرعتی یافته‌شده‌اند که ضربهٔ چکشی "
        "در آن به بیشترین مقدار مجاز می‌رسد، ω = {speed} rad/s",
    "no speed is given: the balance masses need none (m·r); each force and couple is given × "
    "ω² (kg·m, kg·m²), as a rotor's resultant is, and none in N":
        "سرعتی داده نشده است: جرم‌های متعادل‌کننده به آن نیازی ندارند (m·r)؛ هر نیرو و کوپل "
        "مانند برآیند یک روتور × ω² داده می‌شود (kg·m، kg·m²) و هیچ‌کدام بر حسب N نیست",
    "ω = {speed} rad/s (read as rad/s; write [units] speed = \"rpm\" for rpm)":
        "ω = {speed} rad/s (بر حسب rad/s خوانده شد؛ برای rpm بنویسید [units] speed = \"rpm\")",
    "with {share} of the reciprocating mass balanced, {left} of it is left; no speed is given, "
    "so the variation of tractive force, the swaying couple and the hammer blow (each m·r·ω²) "
    "are left out: give speed = … or road_speed = … for them":
        "با متعادل کردن {share} از جرم رفت‌وبرگشتی، {left} آن باقی می‌ماند؛ سرعتی داده نشده "
        "است، پس تغییر نیروی کشش، کوپل نوسانی و ضربهٔ چکشی (هر یک m·r·ω²) آورده نمی‌شوند: "
        "برای آن‌ها speed = … یا road_speed = … بدهید",
    "at the lift speed found, ω = {speed} rad/s":
        "در سرعتِ یافته‌شدهٔ بلند شدن چرخ، ω = {speed} rad/s",
    "at the speed of the greatest hammer blow allowed, ω = {speed} rad/s":
        "در سرعت بیشترین ضربهٔ چکشی مجاز، ω = {speed} rad/s",
    "no speed given: the closing side is m·r (× ω²)":
        "سرعتی داده نشده: ضلع بستن m·r است (× ω²)",
    "no speed is given: the masses and angles found need none (m·r); each force and couple "
    "is given × ω² (kg·m, kg·m²), and none in N":
        "سرعتی داده نشده است: جرم‌ها و زاویه‌های یافته‌شده به آن نیازی ندارند (m·r)؛ هر نیرو و "
        "کوپل × ω² داده می‌شود (kg·m، kg·m²) و هیچ‌یک بر حسب N نیست",
    # a coupled locomotive: the driving and the trailing wheels
    "{name} {mass} kg at {radius}, {angle}°":
        "{name}: {mass} kg در شعاع {radius}، زاویهٔ {angle} درجه",
    "the {share} of the reciprocating mass balanced is shared equally among {pairs} pairs of "
    "coupled wheels: {each} of it in the driving wheels and in each other pair":
        "{share} متعادل‌شدهٔ جرم رفت‌وبرگشتی به‌طور مساوی میان {pairs} جفت چرخ کوپل‌شده تقسیم "
        "می‌شود: {each} آن در چرخ‌های محرک و در هر جفت دیگر",
    "with them, the revolving masses on cranks of their own: {masses}":
        "همراه آن‌ها، جرم‌های دوار روی لنگ‌های خودشان: {masses}",
    "{name}, trailing wheels": "{name}، چرخ‌های دنباله‌رو",
    "the trailing wheels: {share} of each cylinder's reciprocating mass, {mass} kg at the crank "
    "radius along its crank, balanced in the same planes":
        "چرخ‌های دنباله‌رو: {share} از جرم رفت‌وبرگشتی هر سیلندر، {mass} kg در شعاع لنگ و در "
        "امتداد لنگ آن، در همان صفحه‌ها متعادل می‌شود",
    ", with the masses on each pair of coupled wheels: {masses}":
        "، همراه جرم‌های روی هر جفت چرخ کوپل‌شده: {masses}",
}

PHRASES: dict[str, str] = {
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
    "balance.couple.about": "چندضلعی کوپل حول صفحهٔ مرجع: هر mᵢrᵢlᵢ را، که lᵢ فاصله از آن "
                            "صفحه است، پشت سر هم جدا کنید؛ هر بردار موازی خط شعاعی جرم خود، و "
                            "هر جا lᵢ < 0 باشد در جهت مخالف آن.",
    "balance.force.open": "چندضلعی نیرو: هر mᵢrᵢ معلوم را پشت سر هم جدا کنید، هر یک موازی "
                          "خط شعاعی جرم خود؛ مجهول‌ها چندضلعی را می‌بندند.",
    "balance.couple.open": "چندضلعی کوپل، با صفحهٔ {a} به‌عنوان صفحهٔ مرجع (جرم آن حذف "
                           "می‌شود): هر mᵢrᵢlᵢ معلوم را، که lᵢ فاصله از آن صفحه است، پشت سر "
                           "هم جدا کنید؛ مجهول‌ها چندضلعی را می‌بندند.",
    "balance.cut": "حامل‌های دو بردار مجهول را (خطی در امتداد جهتی معلوم، یا کمانی به "
                   "اندازه‌ای معلوم) از نوک آخرین بردار و از نقطهٔ شروع رسم کنید و قطع دهید: "
                   "نقطهٔ تقاطع چندضلعی را می‌بندد.",
    "balance.found": "مجهول‌های جرم {mass} را از ضلع آن بخوانید: اندازهٔ ضلع جرم (یا شعاع، یا "
                     "فاصلهٔ صفحه) و جهت آن زاویه را می‌دهد.",
    "balance.found.product": "m·r·l جرم {mass} را از ضلع آن بخوانید (m·r و صفحهٔ آن هر دو "
                             "مجهول‌اند): اندازهٔ ضلع این حاصل‌ضرب است و جهت آن زاویه را تا "
                             "نیم‌دوری می‌دهد که چندضلعی نیرو معلوم می‌کند.",
    "balance.found.split": "m·r جرم {mass} را از ضلع آن بخوانید، که جهتش نیم‌دور را معلوم "
                           "می‌کند؛ صفحهٔ آن m·r·l چندضلعی کوپل تقسیم بر آن است: "
                           "l = (m·r·l)/(m·r).",
    "balance.cranks": "نمای انتهایی لنگ‌ها را رسم کنید: از مرکز محور، O، خط هر لنگ را با زاویهٔ "
                      "θᵢ و لنگ‌های ثانویه (مستقیم) را با زاویهٔ 2θᵢ رسم کنید.",
    "balance.engine": "چندضلعی {kind}: بردار هر سیلندر را در امتداد لنگ آن با زاویهٔ {order}، "
                      "پشت سر هم جدا کنید.",
}
