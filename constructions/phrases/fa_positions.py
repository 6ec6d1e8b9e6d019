"""Persian phrases of the linkages' positions: position by compass, the instant centres, the
limit positions, Klein's construction and the equivalent linkage."""

from __future__ import annotations

__all__ = ["PHRASES"]

PHRASES: dict[str, str] = {
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
    "equivalent.centres": "{a} و {b} مراکز انحنای دو پروفیل در تماس (میله‌های {i} و {j}) هستند؛ "
                          "عمود مشترک از هر دو می‌گذرد.",
    "equivalent.link": "فاصلهٔ آن‌ها همواره {length} می‌ماند ({how})، پس در این لحظه تماس مانند "
                       "میلهٔ {a}{b} عمل می‌کند که در هر دو مرکز لولا شده است: میلهٔ معادل، "
                       "به‌صورت خط‌چین.",
    "equivalent.slot": "مرکز {a} از دایرهٔ میلهٔ {i} همواره به فاصلهٔ {r} از سطح میلهٔ {j} "
                       "می‌ماند، پس در این لحظه تماس مانند لغزنده‌ای در {a} عمل می‌کند که در "
                       "شیاری موازی با این سطح حرکت می‌کند: شیار معادل، به‌صورت خط‌چین.",
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
    "klein.point_v": "{c}{x} = {ratio} × {c}M را روی {c}M جدا کنید، چنان‌که روی میله {c}{point} "
                     "= {ratio} × {c}{p} است: {o}{x} همان V_{point} است که 90° چرخانده شده، "
                     "V_{point} = ω·{o}{x}.",
    "klein.point_a": "{c}{x} = {ratio} × {c}N را روی {c}N جدا کنید، چنان‌که روی میله {c}{point} "
                     "= {ratio} × {c}{p} است: a_{point} = ω²·{x}{o}، از {x} به سوی {o}.",
    "klein.plate_v": "روی {c}M مثلث {c}M{x} را متشابه با {c}{p}{point} میله رسم کنید: از {c} "
                     "با زاویهٔ {at_c}° نسبت به {c}M و از M با زاویهٔ {at_p}° نسبت به M{c}؛ "
                     "{o}{x} همان V_{point} است که 90° چرخانده شده، V_{point} = ω·{o}{x}.",
    "klein.plate_a": "روی {c}N مثلث {c}N{x} را متشابه با {c}{p}{point} میله رسم کنید: از {c} "
                     "با زاویهٔ {at_c}° نسبت به {c}N و از N با زاویهٔ {at_p}° نسبت به N{c}؛ "
                     "a_{point} = ω²·{x}{o}، از {x} به سوی {o}.",
    "klein.acceleration": "این خط، خط کورس را در N قطع می‌کند: {o}{c}QN همان چندضلعی شتاب است "
                          "که 180° چرخانده شده، پس a_{p} = ω²·N{o}، از N به سمت {o} (a_{c} = "
                          "ω²·{o}{c}، aⁿ_{p}{c} = ω²·{c}Q، aᵗ_{p}{c} = ω²·QN).",
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
    "limits.swing_angle": "زاویهٔ {a}{pivot}{b} را اندازه بگیرید: میلهٔ {link} میان دو وضعیت حدی "
                          "خود به اندازهٔ {degrees}° نوسان می‌کند.",
    "limits.inclination": "زاویهٔ {c}{pivot}{a} را اندازه بگیرید: اهرم در هر دو وضعیت حدی "
                          "{degrees}° با خط مراکز {pivot}{c} زاویه می‌سازد.",
    "limits.lever_in_line": "به مرکز {pivot} و شعاع {span} = {radius} کمانی بزنید تا {path} را "
                            "در {point} قطع کند: اهرم و میلهٔ رابط در یک راستا قرار دارند، {how}.",
    "limits.lever_along": "نقطهٔ {pivot} را به {point} وصل کنید؛ اهرم روی این خط قرار دارد: "
                          "{end} به فاصلهٔ {pivot}{x} = {radius} از {pivot} و به سمت {point} است.",
    "limits.lever_beyond": "نقطهٔ {point} را به {pivot} وصل کنید و این خط را از {pivot} به بعد "
                           "امتداد دهید: {end} به فاصلهٔ {pivot}{x} = {radius} از {pivot} و در "
                           "طرف مقابل آن است.",
    "limits.slot_cuts_crank": "خط اهرم {pivot}{end} دایرهٔ لنگ را در {pin} قطع می‌کند: پین لنگ در "
                              "شیار.",
    "limits.produce_lever": "خط {pivot}{held} را امتداد دهید تا مسیر {point} را در {end} قطع کند.",
    "limits.rod_cuts_path": "به مرکز {x} و شعاع {span} = {radius} کمانی بزنید تا مسیر {point} "
                            "را در {end} قطع کند.",
    "limits.rod": "نقطهٔ {a} را به {b} وصل کنید: میلهٔ {link} در آن وضعیت حدی.",
    "limits.swing": "به مرکز {pivot}، نقطهٔ {point} را همراه با اهرم به اندازهٔ زاویهٔ "
                    "{held}{pivot}{held_there} بچرخانید تا به {there} برسد.",
}
