"""Persian words of the problem sheets of the flywheel, the connecting rod, the cams given by
their arcs, the rotors with unknowns and the engines (:mod:`~tarsim.exercises.handout`)."""

from __future__ import annotations

__all__ = ["WORDS"]

WORDS: dict[str, str] = {
    # a flywheel's
    "draw the mean line and the areas here": "خط میانگین و مساحت‌ها را اینجا رسم کنید",
    "one cylinder's turning moment": "گشتاور چرخشی یک سیلندر",
    "the strokes' triangles": "مثلث‌های کورس‌ها",
    "T, in the least stroke's peak": "T، بر حسب قلهٔ کوچک‌ترین کورس",
    "each stroke's triangle is drawn to its work's ratio":
        "مثلث هر کورس به نسبت کار آن رسم شده است",
    "the diagram repeats every {cycle}": "نمودار هر {cycle} تکرار می‌شود",
    "the resisting torque steady": "گشتاور مقاوم ثابت",
    "the machine's resisting torque as drawn, the driver's steady":
        "گشتاور مقاوم ماشین چنان‌که رسم شده، گشتاور محرک ثابت",
    "the areas above (+) and below (−) the mean line, in order: {areas}":
        "مساحت‌های بالای (+) و زیر (−) خط میانگین، به ترتیب: {areas}",
    "a unit of the drawing's area is {e} J": "هر واحد مساحت نمودار {e} J است",
    "drawn at 1 {unit} = {torque} and 1 {unit} = {angle}":
        "رسم‌شده با ۱ {unit} = {torque} و ۱ {unit} = {angle}",
    "θ in radians": "θ بر حسب رادیان",
    "T at the crank angles given, straight between:":
        "T در زاویه‌های لنگ داده‌شده، میان آن‌ها خط راست:",
    "{n} cylinders, set equally over the cycle": "{n} سیلندر، یکسان در طول چرخه",
    "{n} cylinders, each lagging the first by {phases}":
        "{n} سیلندر، هر یک به اندازهٔ {phases} پس از نخستین",
    "the strokes' works in the ratio {ratio}, each a triangle":
        "کار کورس‌ها به نسبت {ratio}، هر یک مثلثی",
    "the engine's power {p}": "توان موتور {p}",
    "coefficient of fluctuation of energy {ce}": "ضریب نوسان انرژی {ce}",
    "a cycle of {cycle}": "چرخه‌ای به اندازهٔ {cycle}",
    "mean speed {speed}": "سرعت میانگین {speed}",
    "greatest speed {speed}": "بیشترین سرعت {speed}",
    "least speed {speed}": "کمترین سرعت {speed}",
    "flywheel of {mass} kg": "چرخ طیاری به جرم {mass} kg",
    "radius of gyration {k}": "شعاع ژیراسیون {k}",
    "the rim's mean radius {r} (its diameter {d})": "شعاع میانگین طوقه {r} (قطر آن {d})",
    "the rim gives {share} of I": "طوقه {share} از I را می‌دهد",
    "the rim's mean speed {v}": "سرعت میانگین طوقه {v}",
    "the rim's allowable hoop stress {s}": "تنش محیطی مجاز طوقه {s}",
    "density {rho}": "چگالی {rho}",
    "the rim's section {n} times as wide as it is thick":
        "پهنای مقطع طوقه {n} برابر ضخامت آن",
    "the energy a hole takes {v}": "انرژی هر سوراخ {v}",
    "the energy per unit of sheared area {v}": "انرژی بر واحد سطح برش {v}",
    "the hole's diameter {v}": "قطر سوراخ {v}",
    "the plate's thickness {v}": "ضخامت ورق {v}",
    "{v} holes an hour": "{v} سوراخ در ساعت",
    "{v} holes a minute": "{v} سوراخ در دقیقه",
    "a hole every {v}": "هر {v} یک سوراخ",
    "the motor's power {v}": "توان موتور {v}",
    "each punching takes {v}": "هر سوراخ‌کاری {v} طول می‌کشد",
    "each punching takes {v} of the time between holes":
        "هر سوراخ‌کاری {v} از زمان میان دو سوراخ طول می‌کشد",
    "frictional losses {v} of the punching work": "تلفات اصطکاکی {v} از کار سوراخ‌کاری",
    "the punch's efficiency {v}": "بازده پرس {v}",
    "the mean torque": "گشتاور میانگین",
    "the mean torque and the power": "گشتاور میانگین و توان",
    "the work done in a cycle": "کار انجام‌شده در یک چرخه",
    "the greatest fluctuation of energy ΔE": "بیشترین نوسان انرژی ΔE",
    "the power": "توان",
    "the energy the motor and flywheel supply a hole":
        "انرژی‌ای که موتور و چرخ طیار به هر سوراخ می‌دهند",
    "the flywheel's moment of inertia I": "ممان اینرسی چرخ طیار I",
    "the rim's mass": "جرم طوقه",
    "the rim's mass and its section": "جرم طوقه و مقطع آن",
    "the rim's mean radius": "شعاع میانگین طوقه",
    "the rim's mean speed": "سرعت میانگین طوقه",
    "the rim's section: its thickness and width": "مقطع طوقه: ضخامت و پهنای آن",
    "the mean speed": "سرعت میانگین",
    "the coefficient of fluctuation of speed Cs": "ضریب نوسان سرعت Cs",
    "the greatest and least speeds, and where each is":
        "بیشترین و کمترین سرعت، و جای هر یک",
    "the coefficient of fluctuation of energy CE": "ضریب نوسان انرژی CE",
    "the energy the flywheel stores at its mean speed":
        "انرژی ذخیره‌شده در چرخ طیار در سرعت میانگین",
    "where the speed is greatest and least": "جایی که سرعت بیشترین و کمترین است",
    "the shaft's greatest acceleration and retardation, and where":
        "بیشترین شتاب و کاهش شتاب محور، و جای آن‌ها",
    "the turning moment and the shaft's acceleration at {theta}":
        "گشتاور چرخشی و شتاب محور در {theta}",
    # a connecting rod's
    "mass {m} kg": "جرم {m} kg",
    "{l} between the pins' centres": "{l} میان مرکزهای دو پین",
    "radius of gyration about G: {k}": "شعاع ژیراسیون حول G: {k}",
    "hung from {pin}, it swings with a period of {t} s":
        "آویخته از {pin}، با دورهٔ {t} s نوسان می‌کند",
    "the rod's angular acceleration {alpha}": "شتاب زاویه‌ای میلهٔ رابط {alpha}",
    "the equivalent dynamical system, one mass at {pin}":
        "سیستم دینامیکی معادل، یک جرم در {pin}",
    "the two masses at the pins {p} and {a}": "دو جرم در پین‌های {p} و {a}",
    "their moment of inertia about G, against the rod's":
        "ممان اینرسی آن‌ها حول G، در برابر ممان اینرسی میله",
    # a cam of arcs'
    "the cam": "بادامک",
    "the base circle, the lift and the follower at the apex":
        "دایرهٔ پایه، خیز و پیرو در رأس",
    "a {kind} cam": "بادامک {kind}",
    "tangent": "مماسی",
    "circular arc": "کمان دایره‌ای",
    "eccentric": "خارج از مرکز",
    "nose radius {r}": "شعاع دماغه {r}",
    "lift {h}": "خیز {h}",
    "angle of lift {a}": "زاویهٔ خیز {a}",
    "angle of action {a}": "زاویهٔ عمل {a}",
    "the angle between the tangential faces {a}": "زاویهٔ میان دو وجه مماسی {a}",
    "flank radius {r}": "شعاع پهلو {r}",
    "on a line through the cam's centre": "روی خطی که از مرکز بادامک می‌گذرد",
    "the follower's mass {m} kg": "جرم پیرو {m} kg",
    "the nose's distance OQ from the cam's centre": "فاصلهٔ مرکز دماغه OQ از مرکز بادامک",
    "the nose's radius r₂": "شعاع دماغه r₂",
    "the angle of lift α": "زاویهٔ خیز α",
    "the flank's radius R": "شعاع پهلو R",
    "the cam's turn φ while the follower is on the flank":
        "چرخش بادامک φ در مدتی که پیرو روی پهلوست",
    "the follower's acceleration at the beginning of the lift": "شتاب پیرو در آغاز خیز",
    "the follower's greatest velocity": "بیشترین سرعت پیرو",
    "its acceleration at the end of the flank": "شتاب آن در پایان پهلو",
    "its acceleration at the start of the nose": "شتاب آن در آغاز دماغه",
    "its acceleration at the apex": "شتاب آن در رأس",
    "its greatest acceleration on the flank and on the nose":
        "بیشترین شتاب آن روی پهلو و روی دماغه",
    "its lift, velocity and acceleration {theta} after the lift begins":
        "خیز، سرعت و شتاب آن {theta} پس از آغاز خیز",
    # a rotor's with unknowns, or weights
    "not drawn, its radial line to be found: {names}":
        "رسم‌نشده، خط شعاعی آن باید یافته شود: {names}",
    "the angle of {name} between {lo} and {hi}, counter-clockwise":
        "زاویهٔ {name} میان {lo} و {hi}، پادساعتگرد",
    "for the rotor in static balance": "برای بالانس ایستای روتور",
    "for the engine in primary balance (force and couple)":
        "برای بالانس اولیهٔ موتور (نیرو و کوپل)",
    "for the rotor in complete balance (force and couple)":
        "برای بالانس کامل روتور (نیرو و کوپل)",
    "mass {name}: {what}": "جرم {name}: {what}",
    "its mass": "جرم آن",
    "its radius": "شعاع آن",
    "its angle": "زاویهٔ آن",
    "its plane": "صفحهٔ آن",
    "weight {name}: {mass} N at {radius}, {angle}, plane at {plane}":
        "وزنهٔ {name}: {mass} N در شعاع {radius}، زاویهٔ {angle}، صفحه در {plane}",
    "its weight at {radius}": "وزنهٔ آن در شعاع {radius}",
    "its weight {mass} N": "وزنهٔ آن {mass} N",
    "in plane {name}: the balance weight and its angle":
        "در صفحهٔ {name}: وزنهٔ بالانس و زاویهٔ آن",
    # an engine's
    "the cylinders and the crank": "سیلندرها و لنگ",
    "the cylinders' lines and the crank, θ from {reference}; directions only":
        "خط سیلندرها و لنگ، θ از {reference}؛ تنها جهت‌ها",
    "cylinder 1's line": "خط سیلندر ۱",
    "the centre line": "خط میانی",
    "the line of stroke": "خط کورس",
    "crank radius {r} (stroke {s})": "شعاع لنگ {r} (کورس {s})",
    "connecting rod {l}": "میلهٔ رابط {l}",
    "reciprocating masses {masses} kg": "جرم‌های رفت‌وبرگشتی {masses} kg",
    "reciprocating mass {m} kg a cylinder": "جرم رفت‌وبرگشتی {m} kg برای هر سیلندر",
    "revolving mass at the crank radius {m} kg": "جرم دوار در شعاع لنگ {m} kg",
    "{c} of the reciprocating mass balanced": "{c} از جرم رفت‌وبرگشتی بالانس شده",
    "the balance mass at radius {b}": "جرم بالانس در شعاع {b}",
    "the balance mass {m} kg": "جرم بالانس {m} kg",
    "{n} cylinders, their lines evenly round the crank shaft":
        "{n} سیلندر، خط‌هایشان یکنواخت گرد میل‌لنگ",
    "two cylinders, their lines {angle} apart": "دو سیلندر، خط‌هایشان با زاویهٔ {angle} از هم",
    "cylinder {i}: plane at {plane}": "سیلندر {i}: صفحه در {plane}",
    "cylinder {i}: crank at {angle}, plane at {plane}":
        "سیلندر {i}: لنگ با زاویهٔ {angle}، صفحه در {plane}",
    "a {n}-stroke engine, firing order {order}": "موتور {n}زمانه، ترتیب احتراق {order}",
    "the crank at {theta}": "لنگ در {theta}",
    "the cranks' angles from the firing order": "زاویهٔ لنگ‌ها از ترتیب احتراق",
    "couples about the central plane": "کوپل‌ها حول صفحهٔ میانی",
    "the unbalanced primary force": "نیروی اولیهٔ بالانس‌نشده",
    "the unbalanced primary couple": "کوپل اولیهٔ بالانس‌نشده",
    "the unbalanced secondary force": "نیروی ثانویهٔ بالانس‌نشده",
    "the unbalanced secondary couple": "کوپل ثانویهٔ بالانس‌نشده",
    "the crank angle at which each unbalanced one is greatest":
        "زاویهٔ لنگی که هر یک از بالانس‌نشده‌ها در آن بیشترین است",
    "the resultant primary force, its greatest and least":
        "برایند نیروی اولیه، بیشترین و کمترین آن",
    "the resultant secondary force, its greatest and least, and where":
        "برایند نیروی ثانویه، بیشترین و کمترین آن، و جای آن‌ها",
    "the unbalanced force along and across the line of stroke, and their resultant":
        "نیروی بالانس‌نشده در راستای خط کورس و عمود بر آن، و برایند آن‌ها",
    "the greatest unbalanced force, and where": "بیشترین نیروی بالانس‌نشده، و جای آن",
    "the balance mass": "جرم بالانس",
    "the greatest secondary force": "بیشترین نیروی ثانویه",
    "the out-of-balance force": "نیروی نامتعادل",
    "the out-of-balance couple about the plane at {place}": "کوپل نامتعادل حول صفحهٔ {place}",
    "the load on bearing {name}": "بار روی یاتاقان {name}",
    "bearing {name} at {plane}": "یاتاقان {name} در {plane}",
    "a bearing": "یک یاتاقان",
}
"""These sheets' words as Persian says them."""
