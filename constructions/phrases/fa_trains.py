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
    "crown": "چرخدندهٔ تاجی", "cage": "قفسه", "axle P": "چرخدندهٔ محور P",
    "axle Q": "چرخدندهٔ محور Q",
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
    "teeth (found: in brackets)": "تعداد دندانه (یافته‌شده: درون پرانتز)",
    "circular pitch ({unit})": "گام محیطی ({unit})",
    "y × row 1 + x × row 2: speed": "y × سطر 1 + x × سطر 2: سرعت",
    "arm {arm} held, {member} turned {turn}": "بازوی {arm} ثابت، {member} یک دور منفی",
    # a blank column's footnote (exercises/gears/square_axes.py)
    "{mark} Gear {gear} spins about its own axis, square to the main axis, as the arm {arm} "
    "carries it round: its spin is no turn about the main axis, so its cells are blank.":
        "{mark} چرخدندهٔ {gear} حول محور خود، عمود بر محور اصلی، می\u200cچرخد و بازوی {arm} "
        "آن را حول محور اصلی می\u200cگرداند: چرخش آن دوری حول محور اصلی نیست، پس "
        "خانه\u200cهایش خالی است.",
    "{mark} Gear {gear} turns on a fixed axis of its own, square to the main axis, meshing "
    "gear {mate} through bevel teeth: the table, of turns about the main axis, leaves its "
    "cells blank.":
        "{mark} چرخدندهٔ {gear} حول محور ثابت خود، عمود بر محور اصلی، می\u200cچرخد و با "
        "چرخدندهٔ {mate} درگیری مخروطی دارد: جدولِ دورها حول محور اصلی خانه\u200cهای آن را "
        "خالی می\u200cگذارد.",
    "{mark} Gear {gear} turns at {speed} {unit} on a fixed axis of its own, square to the "
    "main axis, meshing gear {mate} through bevel teeth: the table, of turns about the main "
    "axis, leaves its cells blank.":
        "{mark} چرخدندهٔ {gear} با {speed} {unit} حول محور ثابت خود، عمود بر محور اصلی، "
        "می\u200cچرخد و با چرخدندهٔ {mate} درگیری مخروطی دارد: جدولِ دورها حول محور اصلی "
        "خانه\u200cهای آن را خالی می\u200cگذارد.",
    "no member fixed: two speeds given": "هیچ عضوی ثابت نیست: دو سرعت داده شده است",
    "× {scale} {unit}: speed": "× {scale} {unit}: سرعت",
    "turns per turn of {member} (ccw +)": "دور به ازای یک دور {member} (پادساعتگرد +)",
    "speed ({unit}, ccw +)": "سرعت ({unit}، پادساعتگرد +)",
    "Speeds in {unit}, counter-clockwise positive. Each is checked by the Willis equation of "
    "every mesh, solved as one linear system: the same fraction.":
        "سرعت\u200cها بر حسب {unit}، پادساعتگرد مثبت. هر یک با معادلهٔ ویلیس همهٔ "
        "درگیری\u200cها، که با هم به\u200cصورت یک دستگاه خطی حل می\u200cشوند، کنترل شده است: "
        "همان کسر به دست می\u200cآید.",
    "No speed is given: the rows are turns, counter-clockwise positive, and their ratios the "
    "speed ratios, each checked by the Willis equations solved as one linear system.":
        "سرعتی داده نشده است: سطرها تعداد دورها هستند، پادساعتگرد مثبت، و نسبت آن‌ها همان "
        "نسبت سرعت‌هاست که هر یک با معادله‌های ویلیس، حل‌شده به‌صورت یک دستگاه خطی، کنترل "
        "شده است.",
    # the velocity (Kutzbach) diagram
    "{name}: velocity (Kutzbach) diagram": "{name}: نمودار سرعت (کوتزباخ)",
    "{member} fixed; velocities across the radial line, ccw to the right":
        "{member} ثابت است؛ سرعت\u200cها عمود بر خط شعاعی، پادساعتگرد به سمت راست",
    "each member's ω is the slope Δv/Δr of its line": "ω هر عضو، شیب Δv/Δr خط آن است",
    "no member fixed: {a} and {b} given; velocities across the radial line, ccw to the "
    "right": "هیچ عضوی ثابت نیست: {a} و {b} داده شده‌اند؛ سرعت‌ها عمود بر خط شعاعی، "
             "پادساعتگرد به راست",
    "no speed given: drawn for {member} at 1 {unit}, each slope over its slope is a speed "
    "ratio": "سرعتی داده نشده: برای {member} با 1 {unit} رسم شده و شیب هر خط بر شیب آن، یک "
             "نسبت سرعت است",
    # the involute mesh
    "to {centre}": "به سوی {centre}",
    "module {module} {mm}, {z1} and {z2} teeth, pressure angle {angle}°":
        "مدول {module} {mm}، {z1} و {z2} دندانه، زاویهٔ فشار {angle} درجه",
    "path of contact AB = {path} {mm}, contact ratio {ratio}":
        "مسیر تماس AB = {path} {mm}، نسبت تماس {ratio}",
    "pitch circles": "دایره\u200cهای گام", "base circles": "دایره\u200cهای مبنا",
    "addendum and root circles": "دایره\u200cهای ادندم و ریشه", "line of action": "خط عمل",
    "line of centres": "خط\u200cالمرکزین", "common tangent": "مماس مشترک",
    "path of contact": "مسیر تماس", "arc of contact": "کمان تماس",
    "teeth, each flank an involute of its base circle":
        "دندانه\u200cها، هر پهلو اینولوت دایرهٔ مبنای خود",
    "pitch circle {gear}": "دایرهٔ گام {gear}", "base circle {gear}": "دایرهٔ مبنای {gear}",
    "addendum circle {gear}": "دایرهٔ ادندم {gear}",
    # a mesh's results (exercises/gears/train_solution.py)
    "involute mesh": "درگیری اینولوت",
    "involute mesh, drawn with fewer teeth until clear":
        "درگیری اینولوت، ترسیم‌شده با دندانه‌های کمتر تا جایی که تداخل نماند",
    "{n} teeth on the pinion": "{n} دندانه روی پینیون",
    "none": "ندارد", "and": "و",
    "the tips of gear {gears} cut into the other's flank":
        "نوک دندانه‌های چرخدندهٔ {gears} در دامنهٔ دندانه‌های چرخدندهٔ دیگر فرو می‌رود",
}

PHRASES: dict[str, str] = {
    "gears.ordinary_turn": "{member} عضو ورودی است؛ سرعتی داده نشده و برای نسبت سرعت نیازی "
                           "به آن نیست. یک دور چرخش آن را از طریق درگیری‌ها به عضوهای دیگر "
                           "منتقل کنید:",
    "gears.over_input": "{member}، یعنی عضو ورودی، در ردیف مجموع {total} دور می‌چرخد: مجموع "
                        "هر عضو تقسیم بر {total}، نسبت سرعت آن به ω{i} است.",
    "gears.held_given": "سطر 2: {arm} را ثابت نگه دارید و {member} را −1 دور بچرخانید:",
    "gears.two_given": "هر عضو با y·(سطر 1) + x·(سطر 2) می‌چرخد که y سرعت بازو است. دو "
                       "سرعت داده‌شده: ω{a} = y + ({ha})·x = {sa} و ω{b} = y + ({hb})·x = "
                       "{sb}، پس x = {x} {unit} و y = {y} {unit}.",
    "gears.power_efficiency": "عضو ورودی با {given} رانده می‌شود. خروجی η = {eta} از توان آن را "
                              "می‌گیرد: T{o}·ω{o} = −η·T{i}·ω{i}، پس T{o} = −η·T{i}·ω{i}/ω{o} "
                              "= −{eta} × T{i} × {ratio} = {value} N·m (پادساعتگرد +).",
    "gears.power_two": "عضو ورودی با {given} رانده می‌شود و عضو {h} نیز می‌چرخد. جمع گشتاورها "
                       "صفر است، T{i} + T{o} + T{h} = 0، و جمع توان‌ها نیز جز اتلاف‌ها، "
                       "{eta}·T{i}·ω{i} + T{o}·ω{o} + T{h}·ω{h} = 0، پس T{o} = "
                       "T{i}·(ω{h} − {eta}·ω{i})/(ω{o} − ω{h}) = {value} N·m (پادساعتگرد +).",
    "gears.power_in": "توانی که عضو {m} وارد قطار می‌کند: P{m} = |T{m}|·{rpm}|ω{m}| = {t} × "
                      "{rpm}{w} = {value} W.",
    "gears.power_out": "توانی که عضو {m} از قطار می‌گیرد: P{m} = |T{m}|·{rpm}|ω{m}| = {t} × "
                       "{rpm}{w} = {value} W.",
    "gears.holding_two": "باقی گشتاور را عضو {fixed} می‌گیرد: T{fixed} = −(T{i} + T{o}) = "
                         "{value} N·m.",
    "gears.road_car": "خودرو با سرعت v = {kmh} km/h = {v} m/s پیچی به شعاع میانگین R = {R} "
                      "{unit} را دور می‌زند؛ فاصلهٔ دو چرخ t = {t} {unit} و قطر چرخ‌ها {d} "
                      "{unit} است (r = {r} m): خودرو با v/R گرد مرکز پیچ می‌چرخد، پس چرخی که "
                      "مسیرش به شعاع ρ است با سرعت v·ρ/R می‌غلتد.",
    "gears.road_outer": "چرخ بیرونی، روی عضو {n}، مسیری به شعاع R + t/2 = {path} {unit} "
                        "می‌پیماید: ω{n} = v·(R + t/2)/(R·r) {about}{w} {speed} {sense}، "
                        "نخستین سرعت داده‌شده.",
    "gears.road_inner": "چرخ درونی، روی عضو {n}، مسیری به شعاع R − t/2 = {path} {unit} "
                        "می‌پیماید: ω{n} = v·(R − t/2)/(R·r) {about}{w} {speed} {sense}، "
                        "دومین سرعت داده‌شده.",
    "gears.teeth_diameter": "تعداد دندانه‌های چرخدندهٔ {n} از قطر گام و مدول آن: N{n} = d/m "
                            "= {d}/{m} = {teeth}.",
    "gears.teeth_distance": "تعداد دندانه‌های چرخدندهٔ {n} از فاصلهٔ مرکزهای جفت آن و مدول، "
                            "{equation}: N{n} = {teeth}.",
    "gears.teeth_coaxial": "{gear}: شرط هم‌محوری، یعنی فاصلهٔ برابر دو جفت چرخدنده، "
                           "{equation}، نتیجه می‌دهد N{n} = {teeth}.",
    "gears.teeth_chain": "{gear}: شرط هم‌محوری از راه چرخ‌های سیاره‌ای پشت سر هم، یعنی "
                         "فاصلهٔ مرکز آخرین چرخ سیاره‌ای از محور در طول زنجیرش برابر فاصلهٔ "
                         "آن از چرخ حلقوی، {equation}، نتیجه می‌دهد N{n} = {teeth}.",
    "gears.twin": "چرخدندهٔ {copy} یک چرخ سیاره‌ای همانند چرخدندهٔ {first} است: همان تعداد "
                  "دندانه، همان درگیری‌ها، روی همان بازو. مانند چرخدندهٔ {first} می‌چرخد؛ این دو، "
                  "{n} چرخ سیاره‌ای با فاصلهٔ مساوی‌اند و سرعت‌ها همان سرعت‌های یکی از آن‌هاست.",
    "gears.uncoaxial": "چرخ سیاره‌ای با چرخدندهٔ {c0} در فاصلهٔ {r0} مدول از محور اصلی و با "
                       "چرخدندهٔ {c} در فاصلهٔ {r} مدول درگیر است: اندازه‌ها داده نشده‌اند، پس "
                       "مدول چرخدنده‌های کتاب در آنجا متفاوت است (یا دندانه‌ها اصلاح‌شده‌اند) و "
                       "سرعت‌ها تنها از تعداد دندانه‌ها به دست می‌آیند.",
    "gears.teeth_ratio": "نسبت سرعتی که کتاب داده، |ω{x}/ω{y}| = {value}، از طریق درگیری‌ها "
                         "برابر {expr} است: N{g} = {teeth}.",
    "gears.teeth_ratio_table": "نسبت سرعتی که کتاب داده، |ω{x}/ω{y}| = {value}، در قطار با "
                               "N{g} مجهول برابر {expr} است (نسبت هر درگیری N یا 1/N، و "
                               "تعدادی که شرط هم‌محوری یا فاصلهٔ مرکزها به N{g} می‌بندد بر "
                               "حسب آن نوشته شده): N{g} = {teeth}.",
    "gears.teeth_least_set": "چرخدندهٔ {g}، کوچک‌ترین چرخدندهٔ مجهول، کمترین تعداد دندانه یعنی "
                             "{least} را می‌گیرد، یا کمترین تعداد بالاتر از آن که دندانه‌های "
                             "دیگر را درست کند: N{g} = {teeth}.",
    "gears.equal_steps": "کتاب |ω{x}/ω{y}| = {value} را در {k} گام برابر، یک گام برای هر "
                         "جفت میان آن دو، تقسیم می‌کند: نسبت هر جفت {value}^(1/{k}) = {root} "
                         "است ({pairs}).",
    "gears.about_teeth": "مرکزهای چرخدنده‌های {a} و {b} حدود {about} از هم فاصله دارند و "
                         "|ω{x}/ω{y}| = {value}: d{g} {sign} d{s} = 2·{about} و d{g} = "
                         "{k}·d{s}، پس d{s} = {d} و N{s} = {count}: {rounded}.",
    "gears.about_up": "عدد صحیح بعدی رو به بالا گرفته می‌شود، N{n} = {teeth}",
    "gears.about_least": "کمترین تعداد دندانه، {least}، از آن بیشتر است: N{n} = {least}",
    "gears.about_exact": "پس فاصلهٔ دقیق مرکزهای چرخدنده‌های {a} و {b} برابر {equation} = "
                         "{distance} است.",
    "gears.teeth_least": "چرخدندهٔ {g}، کوچک‌تر آن جفت، کمترین تعداد دندانه یعنی {least} را "
                         "می‌گیرد، یا کمترین تعداد بالاتر از آن که دندانه‌های دیگری را درست کند: "
                         "N{g} = {teeth}.",
    "gears.ordinary_start": "{member}، یعنی عضو ورودی، با {speed} می‌چرخد. یک دور چرخش آن را از "
                            "طریق درگیری‌ها به عضوهای دیگر منتقل کنید:",
    "gears.mesh_carries": "{driven} با {driver} درگیری {kind} دارد، پس {way} و با سرعتی "
                          "N{a}/N{b} = {na}/{nb} برابرِ آن می‌چرخد: {turns} → {result}.",
    "gears.bevel_carries": "{driven} با {driver} درگیری مخروطی دارد و محورهایشان بر هم "
                           "عمودند، پس {way} گرفته می‌شود (روی محورهای ثابت هر کدام در "
                           "جهتی که کتاب جلو می‌نامد؛ دو چرخ دو طرف یک چرخ سیاره‌ای مخروطی "
                           "نسبت به بازو در خلاف جهت هم می‌چرخند) و با سرعتی N{a}/N{b} = "
                           "{na}/{nb} برابرِ آن می‌چرخد: {turns} → {result}.",
    "gears.shaft_carries": "{member} با {other} روی یک محور قرار دارد: همانند آن می‌چرخد، {turns}.",
    "gears.fixed": "، ثابت",
    "gears.held_planet": "، که از چرخش بازداشته شده (به میله‌ای بسته شده که جهتش را نگه می‌دارد، "
                         "چنان‌که در چرخدندهٔ خورشید و سیاره) و بازو آن را می‌گرداند",
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
    "kutzbach.two_given": "هیچ عضوی ثابت نیست: هر یک از دو سرعت داده‌شده، خطی از O می‌دهد، "
                          "خط {a} و خط {b}، و خط‌های دیگر از آن‌ها به دست می‌آیند.",
    "kutzbach.read_ratio": "ω{member} = Δv/Δr را از شیب خط آن بخوانید: {omega} rad/s{sense}، "
                           "که برای ورودی با 1 {unit} رسم شده است (سرعتی داده نشده): بر "
                           "شیب ورودی، ω{member}/ω{i} = {ratio}.",
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
    "gears.meshes_bevel": "چرخدنده‌های {a} و {b} درگیری مخروطی دارند و محورهایشان بر هم عمودند.",
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
}
