"""Persian phrases of the linkages' velocities and accelerations: by instant centres, by
components, by the line of transmission, and both polygons."""

from __future__ import annotations

__all__ = ["PHRASES"]

PHRASES: dict[str, str] = {
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
    "apolygon.rolling": "{point}، نقطه‌ای از چرخ {link} که روی زمین است، ساکن است اما به سمت "
                        "مرکز {centre} شتاب دارد: از o_a اندازهٔ a_{point} = ω{link}²·r = "
                        "({omega} rad/s)² × {radius} = {accel} را موازی با {point}{centre} و به "
                        "سمت {centre} جدا کنید؛ انتهای آن {tip} است.",
    "apolygon.rolling_round": "{point}، نقطه‌ای از چرخ {link} که روی دایره است، ساکن است اما به "
                              "سمت مرکز {centre} شتاب دارد: از o_a اندازهٔ a_{point} = "
                              "ω{link}²·r·R/(R {op} r) = ({omega} rad/s)² × {radius} × "
                              "{big}/({big} {op} {radius}) = {accel} را موازی با "
                              "{point}{centre} و به سمت {centre} جدا کنید؛ انتهای آن {tip} است.",
    "readings.least_velocity": "از {centre} عمودی بر {a}{b} فرود آورید: پای عمود، {point}، "
                               "نزدیک‌ترین نقطهٔ این خط به {centre} و کندترین نقطهٔ میلهٔ "
                               "{link} است.",
    "readings.least_side": "از ضلع‌های صفحهٔ {link}، ضلع {a}{b} از همه به {centre} نزدیک‌تر "
                           "است: از {centre} عمودی بر آن فرود آورید؛ پای عمود، {point}، "
                           "نزدیک‌ترین نقطهٔ صفحه به {centre} و کندترین نقطهٔ میلهٔ {link} است.",
    "readings.least_corner": "هیچ عمودی از {centre} بر ضلع‌های صفحهٔ {link} نزدیک‌تر از گوشهٔ "
                             "{a} آن نمی‌افتد: {a} کندترین نقطهٔ میلهٔ {link} است.",
    "readings.least_inside": "{centre} درون صفحهٔ {link} است: نقطهٔ صفحه در آنجا ساکن است و "
                             "کندترین نقطهٔ میلهٔ {link} است.",
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
}
