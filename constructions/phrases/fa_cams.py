"""Persian words on the figures of cams (graphics/cams/cam_layout_figure.py,
displacement_figure.py) and the plots of sweeps and turning moments (graphics/plot.py).

Keys are the English words as the figure code says them
(:func:`~tarsim.constructions.narration.words`); the terms are the course notes'
(docs/glossary-fa.md). A term a cam says otherwise than a gear is keyed "cam: <term>"
(a cam's base circle is دایرهٔ پایه, a gear's دایرهٔ مبنا).
"""

from __future__ import annotations

WORDS: dict[str, str] = {
    # ----- cams: the displacement diagram (graphics/cams/displacement_figure.py) ----------------
    "{name}: displacement": "{name}: نمودار جابه‌جایی",
    "cam angle across, lift up; each segment's construction":
        "زاویهٔ بادامک در راستای افقی و خیز پیرو رو به بالا؛ ترسیم هر بخش",
    "cam angle across, the arc the arm's end swings up ({arm} {unit} × the swing)":
        "زاویهٔ بادامک در راستای افقی و کمانی که انتهای بازو می‌پیماید رو به بالا "
        "({arm} {unit} × زاویهٔ نوسان)",
    "(a swing of {angle}°)": "(نوسانی به اندازهٔ {angle}°)",
    "Lift scale": "مقیاس خیز", "Cam angle scale": "مقیاس زاویهٔ بادامک",
    "displacement": "جابه‌جایی",
    "construction lines": "خطوط ترسیم",
    "ordinates": "خطوط قائم",
    # ----- cams: the follower's motion against cam angle (exercises/cams/cam_solution.py) ---------
    "{name}: velocity": "{name}: سرعت",
    "{name}: acceleration": "{name}: شتاب",
    "{name}: jerk": "{name}: جرک",
    "{name}: the arm's angular velocity": "{name}: سرعت زاویه‌ای بازو",
    "{name}: the arm's angular acceleration": "{name}: شتاب زاویه‌ای بازو",
    "jerk": "جرک",
    "the arm's angular velocity": "سرعت زاویه‌ای بازو",
    "the arm's angular acceleration": "شتاب زاویه‌ای بازو",
    "cam angle θ (°)": "زاویهٔ بادامک θ (°)",
    "jerk ({unit})": "جرک ({unit})",
    "each segment's peak": "بیشینهٔ هر بخش",
    "the cam at {speed} {unit}, {sense}": "بادامک با سرعت {speed} {unit}، {sense}",
    "ÿ jumps at θ = {angles}: the jerk is infinite there, which no curve can draw":
        "ÿ در θ = {angles} ناگهان تغییر می‌کند: جرک در این نقاط بی‌نهایت است و هیچ منحنی‌ای "
        "آن را نشان نمی‌دهد",
    # ----- cams: the profile by inversion (graphics/cams/cam_layout_figure.py) --------------------
    "{name}: profile": "{name}: پروفیل بادامک",
    "cam: profile": "پروفیل بادامک",
    "cam: profile (the pitch curve)": "پروفیل بادامک (همان منحنی گام)",
    "cam: base circle": "دایرهٔ پایه",
    "pitch curve": "منحنی گام",
    "prime circle": "دایرهٔ گام",
    "offset circle": "دایرهٔ انحراف",
    "pivot circle": "دایرهٔ لولا",
    "the arc of the arm's end at each station": "کمان انتهای بازو در هر موقعیت",
    "the follower's line at each station": "خط حرکت پیرو در هر موقعیت",
    "the roller at each station": "غلتک در هر موقعیت",
    "the face at each station": "سطح پیرو در هر موقعیت",
    "the cam held still, the follower turned the other way":
        "بادامک ثابت نگه داشته شده و پیرو در جهت مخالف به دور آن چرخانده شده است (روش وارون)",
    "φ max = {phi}° at θ = {theta}°": "بیشینهٔ φ = {phi}° در θ = {theta}°",
    "UNDERCUT in segment {k} from θ = {start}° to {end}°: ringed where the follower cannot "
    "make the profile":
        "زیربرش در بخش {k} از θ = {start}° تا {end}°: جاهایی که پیرو نمی‌تواند پروفیل را "
        "بسازد با دایره مشخص شده‌اند",
    # ----- cams: the profile's table (exercises/cams/cam_layout.py) -------------------------------
    "{name}: pressure angle and curvature": "{name}: زاویهٔ فشار و انحنا",
    "{name}: face run and curvature": "{name}: محل تماس و انحنا",
    "station": "موقعیت",
    "cam angle": "زاویهٔ بادامک",
    "swing (°)": "زاویهٔ نوسان (°)",
    "lift ({unit})": "خیز ({unit})",
    "face run ({unit})": "محل تماس ({unit})",
    "pressure angle": "زاویهٔ فشار",
    "ρ of the profile ({unit})": "ρ پروفیل ({unit})",
    "ρ of the pitch curve ({unit})": "ρ منحنی گام ({unit})",
    "ρ < {zero}: the curve is concave there.": "ρ < {zero}: منحنی در آن‌جا مقعر است.",
    "The face run is where the face touches, from the follower's axis: σy′, σ = +1 for a "
    "counter-clockwise cam.":
        "محل تماس، فاصلهٔ نقطهٔ تماس روی سطح پیرو از محور پیرو است: σy′\u200e، که در آن σ = +1 "
        "برای بادامک پادساعتگرد.",
    "The pressure angle is between the profile's normal and the roller's path, square to the "
    "arm.":
        "زاویهٔ فشار، زاویهٔ میان عمود بر پروفیل و مسیر غلتک است؛ مسیر غلتک بر بازو عمود است.",
    "The pressure angle is signed as tan φ = (y′ − σe)/(s₀ + y): σ = +1 for a counter-clockwise "
    "cam, e the offset, s₀ = √(R_p² − e²).":
        "زاویهٔ فشار با علامتش از tan φ = (y′ − σe)/(s₀ + y)\u200e به دست می‌آید: σ = +1 برای "
        "بادامک پادساعتگرد، e انحراف، و s₀ = √(R_p² − e²)\u200e.",
    "At a join of two segments the values are the second segment's.":
        "در محل اتصال دو بخش، مقادیر مربوط به بخش دوم است.",
    # ----- sweeps (exercises/linkages/sweep_files.py) ---------------------------------------------
    "Position of {who}{along} over one turn of {link}": "مکان {who}{along} در یک دور {link}",
    "Velocity of {who}{along} over one turn of {link}": "سرعت {who}{along} در یک دور {link}",
    "Acceleration of {who}{along} over one turn of {link}": "شتاب {who}{along} در یک دور {link}",
    "Angle of {who}{along} over one turn of {link}": "زاویهٔ {who}{along} در یک دور {link}",
    "Angular velocity of {who}{along} over one turn of {link}":
        "سرعت زاویه‌ای {who}{along} در یک دور {link}",
    "Angular acceleration of {who}{along} over one turn of {link}":
        "شتاب زاویه‌ای {who}{along} در یک دور {link}",
    " along its guide ({way})": " در امتداد راهنمایش ({way})",
    "link {n}": "میلهٔ {n}",
    "link {n} ({name})": "میلهٔ {n} ({name})",
    "{n} positions from θ_{link} = {angle}, {w}, {a}": "{n} وضعیت از θ_{link} = {angle}، {w}، {a}",
    "ω_{link} = {value} {unit} {sense}": "ω_{link} = {value} {unit} {sense}",
    "{turning}; curves by the analytic (vector-loop) solver":
        "{turning}؛ منحنی‌ها از حل تحلیلی (حلقهٔ برداری)",
    "{p} stays {value}": "{p} ثابت می‌ماند: {value}",
    "{p} from {low} to {high}{where}: {what} {span}":
        "{p} از {low} تا {high}{where}: {what} {span}",
    ", where {v} = {zero}": "، که در آن‌ها {v} = {zero}",
    "swing": "دامنهٔ نوسان",
    "{v} = {zero} at {where}, where {p} is extreme":
        "{v} = {zero} در {where}، جایی که {p} بیشینه یا کمینه است",
    "{v} peaks at {low} and {high}, where {a} = {zero}":
        "{v} در {low} و {high} به اوج می‌رسد، جایی که {a} = {zero}",
    "{a} = {zero} at {where}, where {v} peaks":
        "{a} = {zero} در {where}، جایی که {v} به اوج می‌رسد",
    "θ_{link} = {span} ({n} skipped): {reason}": "θ_{link} = {span} ({n} وضعیت بی‌جواب): {reason}",
    "gap at {gap}": "گسستگی در {gap}",
    "x component": "مؤلفهٔ x",
    "y component": "مؤلفهٔ y",
    "solved by construction (off the curve by {error} at most)":
        "حل ترسیمی (دست‌بالا {error} دور از منحنی)",
    "solved by construction (on the curve exactly)": "حل ترسیمی (دقیقاً روی منحنی)",
    # the links' names as the exercises give them
    "crank": "لنگ", "coupler": "میلهٔ رابط", "connecting rod": "میلهٔ رابط",
    "rod": "میلهٔ رابط", "slotted lever": "اهرم شیاردار", "lever": "اهرم",
    "rocker": "میلهٔ خروجی", "block": "لغزنده", "slider": "لغزنده", "ram": "رام",
    "piston": "پیستون", "follower": "پیرو",
    # ----- the turning-moment diagram (exercises/forces/turning_moment.py) ------------------------
    "Turning-moment diagram": "نمودار گشتاور چرخشی",
    "driving torque": "گشتاور محرک",
    "mean {value} {unit}": "میانگین {value} {unit}",
    "ΔE = {energy} {unit}, the greatest fluctuation of energy: the highest energy less the "
    "lowest, adding the areas in turn (shaded light where the driver gives more than the mean, "
    "dark where less)":
        "ΔE = {energy} {unit}، بیشترین نوسان انرژی: بیشترین انرژی منهای کمترین آن، با جمع "
        "مساحت‌ها به ترتیب (روشن جایی که گشتاور محرک از میانگین بیشتر است، تیره جایی که کمتر)",
    "The energy is lowest at {low}° turned (θ = {theta_low}°) and highest at {high}° "
    "(θ = {theta_high}°).":
        "انرژی پس از {low}° چرخش (θ = {theta_low}°) کمترین و پس از {high}° "
        "(θ = {theta_high}°) بیشترین است.",
    "input turned {sense} from θ = {angle}° (°)": "چرخش ورودی در جهت {sense} از θ = {angle}° (°)",
    "by the force polygons": "با چندضلعی‌های نیرو",
    "{name}: the driving torque, positive {sense}": "{name}: گشتاور محرک، مثبت در جهت {sense}",
    # ----- cams: the results steps.md lists (exercises/cams/cam_solution.py, cam_layout.py) ------
    "rise": "صعود", "return": "بازگشت",
    # the steps' small words (constructions/cams/displacement.py, inversion.py)
    "start": "ابتدای بخش", "end": "انتهای بخش",
    "up from the foot": "از پای آن رو به بالا", "down from the top": "از بالای آن رو به پایین",
    "flat-faced": "تخت", "knife-edge": "نوک‌تیز", "roller": "غلتکی",
    "uniform velocity": "سرعت ثابت", "modified uniform velocity": "سرعت ثابت اصلاح‌شده",
    "simple harmonic": "هارمونیک ساده", "parabolic": "شتاب ثابت", "cycloidal": "سیکلوئیدی",
    "segment {k} ({kind}, {law}): v_max = {v} {unit}/s, a_max = {a}{swing}   {check}":
        "بخش {k} ({kind}، {law}): v_max = {v} {unit}/s، a_max = {a}{swing}   {check}",
    "∞ (at its ends)": "∞ (در دو سر بخش)",
    "∞ (where ÿ jumps)": "∞ (جایی که ÿ جهش دارد)",
    " (the arm: {w} rad/s, {a} rad/s²)": " (بازو: {w} rad/s، {a} rad/s²)",
    "check ok": "کنترل: درست", "check FAILED": "کنترل: نادرست",
    "at θ = {theta}° (segment {k}): y = {y} {unit}, v = {v} {unit}/s, a = {a} m/s²   {check}":
        "در θ = {theta}° (بخش {k}): y = {y} {unit}، v = {v} {unit}/s، a = {a} m/s²   {check}",
    "at θ = {theta}° (segment {k}): ψ = {psi}°, ω = {w} rad/s, α = {a} rad/s²   {check}":
        "در θ = {theta}° (بخش {k}): ψ = {psi}°، ω = {w} rad/s، α = {a} rad/s²   {check}",
    "segment {k}: uniform acceleration {a} m/s² over {first}°, retardation {r} m/s² over "
    "{rest}°": "بخش {k}: شتاب یکنواخت {a} m/s² در {first}° و کاهش سرعت یکنواخت {r} m/s² در "
               "{rest}°",
    "θ = {theta}°": "θ = {theta}°",
    "the nose's centre {d} from the cam's, the lift {h}, the angle of lift {alpha}°":
        "مرکز دماغه به فاصلهٔ {d} از مرکز بادامک، خیز {h}، زاویهٔ صعود {alpha}°",
    "the nose's radius {r}; the roller leaves the flank {phi}° after the lift begins":
        "شعاع دماغه {r}؛ غلتک {phi}° پس از آغاز صعود از یال جدا می‌شود",
    "segment {k} is given by its time, {t} s: at {n} {unit} the cam turns β = ωt = {angle}° in "
    "it": "بخش {k} با زمانش داده شده است، {t} ثانیه: بادامک با سرعت {n} {unit} در این مدت "
          "β = ωt = {angle}° می‌چرخد",
    "the nose's radius {r}; the knife edge leaves the flank {phi}° after the lift begins":
        "شعاع دماغه {r}؛ لبهٔ نوک‌تیز پیرو {phi}° پس از آغاز صعود از یال جدا می‌شود",
    "the flank's radius {R}; the knife edge leaves the flank {phi}° after the lift begins":
        "شعاع یال {R}؛ لبهٔ نوک‌تیز پیرو {phi}° پس از آغاز صعود از یال جدا می‌شود",
    "the flank's radius {R}; the face leaves the flank {phi}° after the lift begins":
        "شعاع یال {R}؛ سطح تخت پیرو {phi}° پس از آغاز صعود از یال جدا می‌شود",
    "{what}: {name} = {value} {unit} at θ = {theta}°   {check}":
        "{what}: {name} = {value} {unit} در θ = {theta}°   {check}",
    "the acceleration as the lift begins": "شتاب در آغاز صعود",
    "the greatest velocity, where the follower leaves the flank":
        "بیشترین سرعت، جایی که پیرو از یال جدا می‌شود",
    "the acceleration where the follower leaves the flank": "شتاب جایی که پیرو از یال جدا می‌شود",
    "the acceleration as the follower comes onto the nose": "شتاب هنگام رسیدن پیرو به دماغه",
    "the acceleration at the apex of the nose": "شتاب در رأس دماغه",
    "the motion at {theta}°": "حرکت در {theta}°",
    "the outline read at every asked angle: {ok}": "پیرامون بادامک در هر زاویهٔ خواسته‌شده: {ok}",
    "r₁ = {r1}, r₂ = {r2}, OQ = {d}, α = {alpha}°": "r₁ = {r1}، r₂ = {r2}، OQ = {d}، α = {alpha}°",
    "the flank's radius R = {R}": "شعاع یال R = {R}",
    "the cam's outline": "پیرامون بادامک",
    "the follower at the apex": "پیرو در رأس دماغه",
    "{name}: the cam": "{name}: بادامک",
    "{name}: lift": "{name}: خیز",
    "lift": "خیز",
    "the motions asked": "حرکت‌های خواسته‌شده",
    "the disc's centre {d} from the shaft, the disc's radius {r}: the lift {h}":
        "مرکز دیسک به فاصلهٔ {d} از محور، شعاع دیسک {r}: خیز {h}",
    "the acceleration at the lowest place": "شتاب در پایین‌ترین موقعیت",
    "the greatest velocity": "بیشترین سرعت",
    "the flank's radius {R}; the roller leaves the flank {phi}° after the lift begins":
        "شعاع یال {R}؛ غلتک {phi}° پس از آغاز صعود از یال جدا می‌شود",
    "the greatest acceleration on the flank": "بیشترین شتاب روی یال",
    "the greatest retardation on the nose": "بیشترین کاهش سرعت روی دماغه",
    "the least base circle for a least radius of curvature of {limit}: {r} {unit} (the "
    "layout's least: {got})   {check}": "کوچک‌ترین دایرهٔ پایه برای کمترین شعاع انحنای {limit}: "
                                        "{r} {unit} (کمترین شعاع انحنا در ترسیم: {got})   "
                                        "{check}",
    "the spring must hold the follower ({m} kg) to the nose against its greatest retardation, "
    "at θ = {theta}°: at least {force} N": "فنر باید پیرو ({m} کیلوگرم) را در برابر بیشترین "
                                           "کاهش سرعتش، در θ = {theta}°، روی دماغه نگه دارد: "
                                           "دست‌کم {force} N",
    "the disc's radius {r2}, its eccentricity OQ = {d}": "شعاع دیسک {r2}، خروج از مرکز OQ = {d}",
    "the least base circle for a greatest pressure angle of {limit}°: {r} {unit} (the "
    "layout's greatest: {got}°)   {check}": "کوچک‌ترین دایرهٔ پایه برای بیشترین زاویهٔ فشار "
                                           "{limit}°: {r} {unit} (بیشترین زاویهٔ فشار در "
                                           "ترسیم: {got}°)   {check}",
    "all on their laws": "همه بر قانون حرکت خود",
    "displacement diagram: {n} points constructed, {verdict}":
        "نمودار جابه‌جایی: {n} نقطه ترسیم شد، {verdict}",
    "pressure angle: greatest {angle}° at θ = {theta}° (segment {k})":
        "زاویهٔ فشار: بیشینه {angle}° در θ = {theta}° (بخش {k})",
    "segment {k} ({kind}): greatest pressure angle {angle}° at θ = {theta}°":
        "بخش {k} ({kind}): بیشترین زاویهٔ فشار {angle}° در θ = {theta}°",
    "the prime circle: radius {rp} (the base circle's {rb} and the roller's {r})":
        "دایرهٔ گام: شعاع {rp} (شعاع دایرهٔ پایه {rb} به‌علاوهٔ شعاع غلتک {r})",
    " (over the 30° a translating follower is usually held to)":
        " (بیش از ۳۰°، که زاویهٔ فشار پیروِ انتقالی معمولاً زیر آن نگه داشته می‌شود)",
    "the profile's least radius of curvature: {rho} at θ = {theta}° (segment {k})":
        "کمترین شعاع انحنای پروفیل: {rho} در θ = {theta}° (بخش {k})",
    "the pitch curve's least radius of curvature: {rho} at θ = {theta}° (segment {k})":
        "کمترین شعاع انحنای منحنی گام: {rho} در θ = {theta}° (بخش {k})",
    " (the roller's radius is {radius})": " (شعاع غلتک {radius} است)",
    "the face is touched from {lo} to {hi} along it from the follower's axis: a face at least "
    "{width} wide":
        "نقطهٔ تماس روی سطح پیرو از {lo} تا {hi} از محور پیرو جابه‌جا می‌شود: پهنای "
        "سطح دست‌کم {width}",
    "UNDERCUT from θ = {start}° to {end}°, worst in segment {k} (marked on the layout)":
        "زیربرش از θ = {start}° تا {end}°، بدترین نقطه در بخش {k} (روی ترسیم مشخص شده است)",
    "each where the closed form puts it": "هر یک همان‌جا که رابطهٔ بسته نشان می‌دهد",
    "profile by inversion: {n} stations laid out, {verdict}":
        "پروفیل به روش وارونگی: {n} موقعیت ترسیم شد، {verdict}",
}

PHRASES: dict[str, str] = {
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
    "heading.arc_cam": "ابعاد بادامک",
    "heading.arc_motion": "حرکت پیرو روی یال و دماغهٔ بادامک",
    "cam.parabolic_part": "بخش {k} با شتاب‌گیری و کاهش سرعت یکنواخت در دو بخش نابرابر است: "
                          "برای بخش {half} آن، سهم این بخش از خیز، یعنی {rise}، را روی خط قائم "
                          "{where} به نسبت ۱ : ۳ : ۵ … {way} تقسیم کنید؛ این کار با خطوطی موازی "
                          "انجام می‌شود که از خطی کمکی با علامت‌های ۱، ۴، ۹ … گام مساوی ({m} "
                          "گام) رسم می‌شوند؛ سپس هر نقطهٔ تقسیم را با خطی افقی به خط قائم نظیرش "
                          "منتقل کنید.",
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
}
