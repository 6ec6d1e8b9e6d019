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
    # the key to the names on a force figure (graphics/forces/force_key.py)
    "the force of link i on link j": "نیروی میلهٔ i بر میلهٔ j",
    "its part square to link j": "مؤلفهٔ آن عمود بر میلهٔ j",
    "its part along link j": "مؤلفهٔ آن در امتداد میلهٔ j",
    "the inertia force of link k": "نیروی اینرسی میلهٔ k",
    "the inertia couple of link k": "کوپل اینرسی میلهٔ k",
    "the friction couple of link i on link j at their pin":
        "کوپل اصطکاک میلهٔ i بر میلهٔ j در لولای آن\u200cها",
    "the weight of link k": "وزن میلهٔ k",
    "the force given on link k": "نیروی داده\u200cشده بر میلهٔ k",
    "the couple of link i on link j": "کوپل میلهٔ i بر میلهٔ j",
    "the torque that drives link k": "گشتاور محرک میلهٔ k",
    "the push on the crank pin's part along the crank":
        "مؤلفهٔ نیروی وارد بر لولای لنگ در امتداد لنگ",
    "its part square to the crank: the crank effort": "مؤلفهٔ آن عمود بر لنگ: نیروی مؤثر لنگ",
    "where the push on the crank pin parts along the crank and square to it":
        "محل تجزیهٔ نیروی وارد بر لولای لنگ در امتداد لنگ و عمود بر آن",
    "where the two lines that close a polygon cross":
        "محل تلاقی دو خطی که چندضلعی را می\u200cبندند",
    "where a three-force member's lines of action meet": "محل تلاقی خطوط عمل عضو سه\u200cنیرویی",
    "a load the exercise gives": "باری که مسئله می\u200cدهد",
    # the free bodies
    "each link alone with every force on it; its forces add to nothing":
        "هر میله به\u200cتنهایی با همهٔ نیروهای وارد بر آن؛ برآیند نیروهای آن صفر است",
    "a force, at its body's force scale": "نیرو، با مقیاس نیروی همان میله",
    "a force too small for that scale, drawn 10 mm long":
        "نیرویی کوچک\u200cتر از آن مقیاس، به طول ۱۰ میلی\u200cمتر رسم\u200cشده",
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
    # the flywheel (exercises/forces/flywheel_solution.py, graphics/forces/flywheel_figure.py)
    "Add the areas in turn from the first intercept: the energy's highest less its lowest is "
    "the greatest fluctuation ΔE.":
        "مساحت‌ها را از نخستین تقاطع به ترتیب جمع کنید: بیشترین انرژی منهای کمترین آن، "
        "بیشترین نوسان انرژی ΔE است.",
    "mean turning moment T_mean = {mean} N·m over a cycle of {cycle}°":
        "گشتاور چرخشی میانگین T_mean = {mean} N·m در یک چرخهٔ {cycle}°",
    "between θ = {low}° and {high}°": "میان θ = {low}° و {high}°",
    "the energy highest after area {high} and lowest after area {low}":
        "انرژی پس از مساحت {high} بیشترین و پس از مساحت {low} کمترین است",
    "greatest fluctuation of energy ΔE = {energy} J, {where}":
        "بیشترین نوسان انرژی ΔE = {energy} J، {where}",
    "the turning moment is steady: ΔE = 0 and no flywheel is needed":
        "گشتاور چرخشی ثابت است: ΔE = ۰ و چرخ طیار لازم نیست",
    "flywheel for C_s = {cs} at ω = {omega} rad/s: I = ΔE/(C_s·ω²) = {inertia} kg·m²":
        "چرخ طیار برای C_s = {cs} در ω = {omega} rad/s: I = ΔE/(C_s·ω²) = {inertia} kg·m²",
    "a rim of mean radius {radius}: m = I/r² = {mass} kg":
        "طوقه‌ای به شعاع میانگین {radius}: m = I/r² = {mass} kg",
    "a flywheel whose radius of gyration is {radius}: its mass m = I/k² = {mass} kg":
        "چرخ طیاری با شعاع ژیراسیون {radius}: جرم آن m = I/k² = {mass} kg",
    "a rim of {mass} kg: its mean radius r = √(I/m) = {radius}":
        "طوقه‌ای به جرم {mass} kg: شعاع میانگین آن r = √(I/m) = {radius}",
    "a flywheel of I = {inertia} kg·m² holds the speed within C_s = ΔE/(I·ω²) = {cs} "
    "({percent} % of the mean, ±{half} %)":
        "چرخ طیاری با I = {inertia} kg·m² سرعت را در C_s = ΔE/(I·ω²) = {cs} نگه می‌دارد "
        "({percent} ٪ میانگین، ±{half} ٪)",
    "its section at {density} kg/m³, the width {ratio} times the thickness: b·t = m/(ρ·2πr), "
    "t = {thickness}, b = {width}":
        "مقطع آن با چگالی {density} kg/m³ و پهنای {ratio} برابر ضخامت: b·t = m/(ρ·2πr)، "
        "t = {thickness}، b = {width}",
    "the greatest and least speeds ω(1 ± C_s/2): {high} and {low} {unit}":
        "بیشترین و کمترین سرعت ω(1 ± C_s/2): {high} و {low} {unit}",
    "the machine's resisting torque averages T_mean = {mean} N·m over a cycle of {cycle}°: "
    "the steady driving torque":
        "میانگین گشتاور مقاوم ماشین در یک چرخهٔ {cycle}° برابر T_mean = {mean} N·m است: "
        "گشتاور محرک ثابت",
    "Draw the table's points joined by straight lines, each jump upright; its mean is the area "
    "under it over the cycle.":
        "نقطه‌های جدول را با خط‌های راست به هم وصل کنید و هر جهش را قائم رسم کنید؛ میانگین آن "
        "مساحت زیر منحنی تقسیم بر طول چرخه است.",
    "With the driving torque steady at the mean, α = (T_mean − T)/I: greatest where the "
    "resisting torque is lowest over the whole cycle, most negative where it is highest.":
        "با گشتاور محرک ثابت و برابر میانگین، α = (T_mean − T)/I: در جایی که گشتاور مقاوم در "
        "کل چرخه کمینه است بیشترین، و جایی که بیشینه است منفی‌ترین است.",
    "greatest acceleration {alpha} rad/s², held from θ = {start}° to {end}°":
        "بیشترین شتاب {alpha} rad/s²، از θ = {start}° تا {end}°",
    "greatest retardation {alpha} rad/s², held from θ = {start}° to {end}°":
        "بیشترین کاهش شتاب {alpha} rad/s²، از θ = {start}° تا {end}°",
    "resisting torque": "گشتاور مقاوم",
    "Resisting-torque diagram": "نمودار گشتاور مقاوم",
    "ΔE = {energy} {unit}, the greatest fluctuation of energy: the highest energy less the "
    "lowest, adding the areas in turn (shaded light where the machine takes more than the "
    "mean, dark where less)":
        "ΔE = {energy} {unit}، بیشترین نوسان انرژی: بیشترین انرژی منهای کمترین آن، با جمع "
        "مساحت‌ها به ترتیب (روشن جایی که ماشین بیش از میانگین می‌گیرد، تیره جایی که کمتر)",
    "α max and α min: the shaft's greatest acceleration and retardation, where the resisting "
    "torque is lowest and highest over the whole cycle":
        "α max و α min: بیشترین شتاب و کاهش شتاب محور، جایی که گشتاور مقاوم در کل چرخه کمینه "
        "و بیشینه است",
    "a rim whose mean speed is {speed} m/s: m = ΔE/(C_s·v²) = {mass} kg":
        "طوقه‌ای با سرعت میانگین {speed} m/s: m = ΔE/(C_s·v²) = {mass} kg",
    "a rim whose mean speed is {speed} m/s: its radius r = v/ω = {radius}, its mass m = "
    "{share}/r² = {mass} kg":
        "طوقه‌ای با سرعت میانگین {speed} m/s: شعاع آن r = v/ω = {radius} و جرم آن m = "
        "{share}/r² = {mass} kg",
    "a rim whose hoop stress is {stress} MPa at {density} kg/m³: its speed v = √(σ/ρ) = "
    "{speed} m/s":
        "طوقه‌ای با تنش محیطی {stress} MPa و چگالی {density} kg/m³: سرعت آن v = √(σ/ρ) = "
        "{speed} m/s",
    "a motor of {power} kW gives a hole's E = {energy} J in T = E/P = {period} s, the hole "
    "taking {time} s: {rate} holes a minute":
        "موتوری با توان {power} kW انرژی E = {energy} J هر سوراخ را در T = E/P = {period} s "
        "می‌دهد و سوراخ‌کاری {time} s طول می‌کشد: {rate} سوراخ در دقیقه",
    "a flywheel of I = {inertia} kg·m² giving up ΔE = ½·I·(ω1² − ω2²): the greatest speed "
    "{high} {unit}, the least {low} {unit}; their mean {mean} {unit}, C_s = (ω1 − ω2)/ω = {cs}":
        "چرخ طیاری با I = {inertia} kg·m² که ΔE = ½·I·(ω1² − ω2²) را پس می‌دهد: بیشترین "
        "سرعت {high} {unit}، کمترین {low} {unit}؛ میانگین آن دو {mean} {unit}، "
        "C_s = (ω1 − ω2)/ω = {cs}",
    "a flywheel of {mass} kg at {radius} from the axis: I = m·{k}² = {inertia} kg·m²":
        "چرخ طیاری به جرم {mass} kg در فاصلهٔ {radius} از محور: I = m·{k}² = {inertia} kg·m²",
    "a hole's punching work {work} J at an efficiency of {eta}: the motor and flywheel give "
    "E = {work} J/η = {energy} J a hole":
        "کار سوراخ‌کاری هر سوراخ {work} J با بازده {eta}: موتور و چرخ طیار برای هر سوراخ "
        "E = {work} J/η = {energy} J می‌دهند",
    "a hole's punching work {work} J and the frictional losses, {share} of it: the motor and "
    "flywheel give E = {work} J × {supply} = {energy} J a hole":
        "کار سوراخ‌کاری هر سوراخ {work} J و اتلاف اصطکاکی، {share} آن: موتور و چرخ طیار "
        "برای هر سوراخ E = {work} J × {supply} = {energy} J می‌دهند",
    "a hole takes E = {energy} J in {time} s of every {period} s: the motor's power P = E/T = "
    "{power} kW":
        "هر سوراخ E = {energy} J را در {time} s از هر {period} s می‌گیرد: توان موتور "
        "P = E/T = {power} kW",
    "While it punches, the steady motor gives E·t/T = {given} J of the {energy} J a hole takes; "
    "the flywheel gives up the rest, E·(1 − t/T) = {delta} J, and takes it back before the "
    "next hole.":
        "در زمان سوراخ‌کاری، موتور با گشتاور ثابت E·t/T = {given} J از {energy} J لازم برای هر "
        "سوراخ را می‌دهد؛ باقی، E·(1 − t/T) = {delta} J، را چرخ طیار می‌دهد و پیش از سوراخ "
        "بعدی آن را بازمی‌گیرد.",
    "the shaft runs fastest at θ = {high}° and slowest at θ = {low}°, where the energy it "
    "holds is highest and lowest":
        "محور در θ = {high}° تندترین و در θ = {low}° کندترین است، جایی که انرژی آن بیشینه و "
        "کمینه است",
    "the coefficient of fluctuation of energy C_E = ΔE/(work done in a cycle) = {ce}":
        "ضریب نوسان انرژی C_E = ΔE/(کار انجام‌شده در یک چرخه) = {ce}",
    "the flywheel stores ½·I·ω² = {energy} J at the mean speed":
        "چرخ طیار در سرعت میانگین ½·I·ω² = {energy} J انرژی ذخیره می‌کند",
    "a rim of mean radius {radius} that gives {share} of I: m = {share}·I/r² = {mass} kg":
        "طوقه‌ای به شعاع میانگین {radius} که {share} از I را می‌دهد: m = {share}·I/r² = "
        "{mass} kg",
    "every number agrees with its reference": "همهٔ اعداد با مرجع خود سازگارند",
    "Each area times the diagram's scale ({scale} J per unit of area) is an energy: "
    "{energies} J.":
        "هر مساحت ضرب در مقیاس نمودار ({scale} J بر واحد مساحت) یک انرژی است: {energies} J.",
    "Draw T(θ) at {n} equal steps of {step}° over the cycle; its mean is the area under it "
    "over the cycle.":
        "T(θ) را در {n} گام برابر {step}° در طول چرخه رسم کنید؛ میانگین آن مساحت زیر منحنی "
        "تقسیم بر طول چرخه است.",
    "The drawn areas give ΔE = {drawn} J. To the data's precision, the intercepts are the "
    "roots of T(θ) − T_mean found on the formula, and each area is T − T_mean integrated "
    "between two of them by Gauss–Legendre quadrature.":
        "مساحت‌های رسم‌شده ΔE = {drawn} J می‌دهند. با دقت خود داده‌ها، نقاط تقاطع ریشه‌های "
        "T(θ) − T_mean‌اند که روی خود فرمول یافته می‌شوند، و هر مساحت انتگرال T − T_mean "
        "میان دو نقطهٔ تقاطع همسایه به روش گاوس–لژاندر است.",
    "The curve crosses the mean at {n} intercepts; between them lie the areas {energies} J.":
        "منحنی خط میانگین را در {n} نقطه قطع می‌کند؛ میان آن‌ها مساحت‌های {energies} J "
        "قرار دارند.",
    "With the resistance steady at the mean, α = (T − T_mean)/I: greatest where T is highest "
    "over the whole cycle, most negative where it is lowest.":
        "با گشتاور مقاوم ثابت و برابر میانگین، α = (T − T_mean)/I: در جایی که T در کل چرخه "
        "بیشینه است بیشترین، و جایی که کمینه است منفی‌ترین است.",
    "power at the mean speed: P = T_mean·ω = {power} kW":
        "توان در سرعت میانگین: P = T_mean·ω = {power} kW",
    "at θ = {at}°: T = {torque} N·m, α = {alpha} rad/s²":
        "در θ = {at}°: T = {torque} N·m، α = {alpha} rad/s²",
    "Energy at the intercepts": "انرژی در نقاط تقاطع",
    "intercept, in order": "نقطهٔ تقاطع، به ترتیب",
    "turning moment": "گشتاور چرخشی",
    "α max and α min: the shaft's greatest acceleration and retardation, where T is highest "
    "and lowest over the whole cycle":
        "α max و α min: بیشترین شتاب و کاهش شتاب محور، جایی که T در کل چرخه بیشینه و "
        "کمینه است",
    "highest": "بیشینه", "lowest": "کمینه",
    "excess torque T_e − T_m": "گشتاور اضافی T_e − T_m",
    "engine's turning moment T_e": "گشتاور چرخشی موتور T_e",
    "machine's resisting torque T_m": "گشتاور مقاوم ماشین T_m",
    "Excess-torque diagram": "نمودار گشتاور اضافی",
    "ΔE = {energy} {unit}, the greatest fluctuation of energy: the highest energy less the "
    "lowest, adding the areas of T_e − T_m in turn (shaded light where the engine gives more "
    "than the machine takes, dark where less)":
        "ΔE = {energy} {unit}، بیشترین نوسان انرژی: بیشترین انرژی منهای کمترین آن، با جمع "
        "مساحت‌های T_e − T_m به ترتیب (روشن جایی که موتور بیش از نیاز ماشین می‌دهد، تیره "
        "جایی که کمتر)",
    "α max and α min: the shaft's greatest acceleration and retardation, where T_e − T_m is "
    "highest and lowest over the whole cycle":
        "α max و α min: بیشترین شتاب و کاهش شتاب محور، جایی که T_e − T_m در کل چرخه بیشینه و "
        "کمینه است",
    "the highest and lowest energy": "بیشترین و کمترین انرژی",
    "the shaft's extremes": "بیشینه و کمینهٔ شتاب محور",
    "energy above the first intercept's": "انرژی نسبت به نخستین تقاطع",
    "ΔE = {energy} {unit}, the greatest fluctuation of energy: the highest energy less the "
    "lowest":
        "ΔE = {energy} {unit}، بیشترین نوسان انرژی: بیشترین انرژی منهای کمترین آن",
    "greatest acceleration {alpha} rad/s² at θ = {at}°":
        "بیشترین شتاب {alpha} rad/s² در θ = {at}°",
    "greatest retardation {alpha} rad/s² at θ = {at}°":
        "بیشترین کاهش شتاب {alpha} rad/s² در θ = {at}°",
    # a flywheel with no diagram, an engine by its power, strokes and cylinders
    # (exercises/forces/flywheel_words.py, graphics/forces/flywheel_figure.py)
    "between the greatest and least speeds, {high} and {low} {unit}: the mean ω = (ω1 + ω2)/2 "
    "= {mean} {unit}, C_s = (ω1 − ω2)/ω = {cs}":
        "میان بیشترین و کمترین سرعت، {high} و {low} {unit}: میانگین ω = (ω1 + ω2)/2 = {mean} "
        "{unit}، C_s = (ω1 − ω2)/ω = {cs}",
    "the greatest fluctuation of energy is given: ΔE = {energy} J":
        "بیشترین نوسان انرژی داده شده است: ΔE = {energy} J",
    "the engine's {power} kW do W = P·t = {work} J in a cycle of {cycle}° (t = {time} s at "
    "the mean speed); ΔE = C_E·W = {ce} × {work} J = {energy} J":
        "موتور با {power} kW در یک چرخهٔ {cycle}° کار W = P·t = {work} J انجام می‌دهد "
        "(t = {time} s در سرعت میانگین)؛ ΔE = C_E·W = {ce} × {work} J = {energy} J",
    "a flywheel of I = {inertia} kg·m² between {high} and {low} {unit}: ΔE = ½·I·(ω1² − ω2²) "
    "= I·ω²·C_s = {energy} J":
        "چرخ طیاری با I = {inertia} kg·m² میان {high} و {low} {unit}: ΔE = ½·I·(ω1² − ω2²) "
        "= I·ω²·C_s = {energy} J",
    "At {power} kW the engine does P·t = {work} J in a cycle of {cycle}°, t = cycle/ω; shared "
    "in the ratio given, its strokes' works are {works} J.":
        "موتور با {power} kW در یک چرخهٔ {cycle}° کار P·t = {work} J انجام می‌دهد، "
        "t = cycle/ω؛ این کار به نسبت داده‌شده میان کورس‌ها بخش می‌شود: "
        "{works} J.",
    "Each stroke's diagram is a triangle on its base of {span}°, its apex at mid-stroke 2W/s "
    "high so that its area is its work W: {heights} N·m.":
        "نمودار هر کورس مثلثی بر قاعدهٔ {span}° است با رأسی در میانهٔ کورس به ارتفاع 2W/s، "
        "تا مساحتش کار آن W باشد: {heights} N·m.",
    "Add the {n} cylinders' diagrams, each set behind the first by {lags}°: T(θ) = "
    "ΣT₁(θ − φ).":
        "نمودارهای {n} سیلندر را جمع کنید، هر یک به اندازهٔ {lags}° پس از نخستین: T(θ) = "
        "ΣT₁(θ − φ).",
    "The flywheel's energy against its speed": "انرژی چرخ طیار بر حسب سرعت آن",
    "speed ({unit})": "سرعت ({unit})",
    "½·I·ω², I = {inertia} kg·m²": "½·I·ω²، I = {inertia} kg·m²",
    "{name} = {energy} {unit}": "{name} = {energy} {unit}",
    "ΔE = ½·I·(ω1² − ω2²) = {energy} {unit}: the energy the flywheel gives up from its "
    "greatest speed ω1 to its least ω2":
        "ΔE = ½·I·(ω1² − ω2²) = {energy} {unit}: انرژی‌ای که چرخ طیار از بیشترین "
        "سرعتش ω1 تا کمترین آن ω2 پس می‌دهد",
    "the greatest and least speeds": "بیشترین و کمترین سرعت",
    "one cylinder's, {n} added": "نمودار یک سیلندر، {n} تا جمع شده",
    # the bundled exercises' loads, by the names their files give them
    "gas force": "نیروی گاز", "cutting force": "نیروی برش", "load torque": "گشتاور بار",
    "steam on the cover side": "بخار در سمت درپوش", "back pressure": "پس‌فشار",
}

PHRASES: dict[str, str] = {
    "force.pendulum": "میلهٔ {link} که از {about} آویخته شده است (h = {h} از G{link} تا آن)، "
                      "چون آونگ مرکب در T = {period} نوسان می‌کند: T = 2π·√((k² + h²)/(g·h))، "
                      "پس شعاع ژیراسیون آن حول G{link} برابر k = √(g·h·T²/(4π²) − h²) = {k} "
                      "و I = m·k² = {inertia} است.",
    "force.pendulum_knife": "میلهٔ {link} که روی لبهٔ چاقویی در سوراخ {about} آویخته شده است، "
                            "حول بالای سوراخ (h = {h} از G{link}، فاصلهٔ لولا به‌اضافهٔ نصف "
                            "قطر سوراخ) چون آونگ مرکب در T = {period} نوسان می‌کند: T = "
                            "2π·√((k² + h²)/(g·h))، پس شعاع ژیراسیون آن حول G{link} برابر "
                            "k = √(g·h·T²/(4π²) − h²) = {k} و I = m·k² = {inertia} است.",
    "force.flywheel": "چرخ طیار با I = {inertia} در برابر گشتاور مقاوم میانگین T_mean = {mean}: "
                      "شتاب زاویه‌ای آن α = (T − T_mean)/I = {alpha} است، T = {torque} گشتاور "
                      "چرخشی در جهت دوران (+ یعنی محور تندتر می‌شود).",
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
                    "F_P = {effort}، پس از کسر نیروی اینرسی قطعات رفت‌وبرگشتی F_I = {inertia} "
                    "(m·a به سمت لنگ). رانش دیوارهٔ سیلندر بر آن، یعنی مؤلفهٔ نیروی راهنما که "
                    "عمود بر امتداد کورس است: F_N = {thrust}.",
    "force.effort": "{name}، یعنی نیروی وارد بر لولای لنگ {a}، را تجزیه کنید: از ابتدای آن خطی "
                    "در امتداد لنگ {o}{a} و از انتهای آن خطی عمود بر آن رسم کنید؛ در محل تلاقی "
                    "این دو خط، مؤلفهٔ شعاعی پایان می‌یابد و مؤلفهٔ مماسی F_T آغاز می‌شود. "
                    "نیروی مؤثر لنگ F_T = {effort} (پادساعتگرد مثبت) و گشتاور چرخشی F_T·{o}{a} "
                    "= {moment} است؛ مؤلفهٔ شعاعی، یعنی رانش بر یاتاقان‌های محور، F_R = "
                    "{radial} است (به سمت محور مثبت).",
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
                           "گشتاور چرخشی F_T·{o}{a} = {moment} است؛ یاتاقان‌ها در امتداد آن "
                           "رانشی نمی‌گیرند، F_R = {radial}.",
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
}
