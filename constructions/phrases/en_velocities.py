"""English phrases of the linkages' velocities and accelerations: by instant centres, by
components, by the line of transmission, and both polygons."""

from __future__ import annotations

__all__ = ["PHRASES"]

PHRASES: dict[str, str] = {
    # ----- velocities by instant centres (velocity_drawing, velocity_by_centres) -----------
    "velocity.input_perpendicular": "At {point} draw the perpendicular to {pivot}{point}.",
    "velocity.input_vector": "Lay off V_{point} = ω{link}·{pivot}{point} = {omega} rad/s × "
                             "{radius} = {speed} along it, in the sense of ω{link} ({sense}).",
    "velocity.known": "V_{point} is the known velocity.",
    "velocity.line_of_centres": "Draw the line of centres through {a} and {b}; {c} lies on it "
                                "too (Kennedy).",
    "velocity.erect_perpendicular": "At {at} erect the perpendicular to the line of centres.",
    "velocity.meets_gauge_at_tip": "It meets the gauge line of link {link} at the tip of "
                                   "V_{centre}.",
    "velocity.transfer_point": "V_{centre} = {speed}: {centre} is a point of both link {i} and "
                               "link {j}.",
    "velocity.swing_onto_line": "With centre {centre} and radius {centre}{point} swing {point} "
                                "onto the line of centres at {point}′.",
    "velocity.lay_off_known": "At {point}′ lay off V_{point} = {speed} perpendicular to the line "
                              "of centres, in the same sense.",
    "velocity.gauge_line": "Draw the gauge line of link {link} from {centre} through the tip.",
    "velocity.equal_omega_line": "{centre} is at infinity: links {i} and {j} turn together, "
                                 "with one ω. Draw the line through {a} and {b}.",
    "velocity.equal_omega_gauge": "Through {centre} draw the gauge line of link {j} parallel to "
                                  "that of link {i}: one ω, one slope.",
    "velocity.equal_omega_point": "At {at}, taken as a point of link {j}, erect the "
                                  "perpendicular to the line; it meets the gauge line of link "
                                  "{j} at the tip of that point's velocity, {speed}.",
    "velocity.translates": "Link {link} translates ({centre} is at infinity), so every point of "
                           "it has V_{known}: lay it off at {point}.",
    "velocity.at_rest": "{point} is at {centre}, the centre link {link} turns about at this "
                        "instant, so V_{point} = 0.",
    "velocity.line_of_centres_of_link": "Draw the line of centres of link {link} through {a} and "
                                        "{b}.",
    "velocity.gauge_line_known": "Draw the gauge line of link {link} from {centre} through the "
                                 "tip of the known velocity.",
    "velocity.meets_gauge_length": "It meets the gauge line of link {link}: its length there is "
                                   "|V_{point}|.",
    "velocity.rotate_back": "With centre {centre} rotate it back to {point}: V_{point} is "
                            "perpendicular to {centre}{point}.",
    "velocity.turn_known": "Turn the known velocity through 90° so that it lies along its radius "
                           "towards {centre}.",
    "velocity.turned_arrow": "Draw it as an arrow: the known velocity turned through 90°.",
    "velocity.turned_found": "Draw that piece as an arrow from {point}: V_{point} turned "
                             "through 90°.",
    "velocity.join": "Join {a} to {b}.",
    "velocity.parallel_through_turned": "Through the tip of the turned velocity draw the "
                                        "parallel to that line.",
    "velocity.radius": "Draw the radius {point}–{centre}.",
    "velocity.parallel_cuts_radius": "The parallel cuts the radius: the piece from {point} is "
                                     "|V_{point}| turned through 90°.",
    "velocity.turn_back": "Turn it back through 90° the other way: V_{point} is perpendicular "
                          "to {point}–{centre}.",
    "velocity.result": "V_{point} = {speed}.",
    # ----- velocities by components (constructions.velocity_by_components) -----------------
    "components.on_contact": "{point} of wheel {link} stands, at this instant, on {rest}, the "
                             "wheel's point on the face, which is at rest: V_{point} = 0.",
    "components.arrow": "Join {point} to the tip: V_{point} = {speed}.",
    "components.project_along": "Project the tip of V_{point} onto {line}: {component} is the "
                                "component of V_{point} along {line}.",
    "components.draw_component_along": "Draw {component} at {point} along {line}.",
    "components.dividers": "With dividers lay off {a} = {b} at {point} along {line}.",
    "components.equal_components": "{a} = {b}: points of a rigid link have equal components "
                                   "along the line joining them.",
    "components.line_of_link": "Draw line {line} of link {link}.",
    "components.perpendicular_from_tip": "From the tip of {component} draw the perpendicular to "
                                         "{line}.",
    "components.say_perpendicular": "the perpendicular to {line} from the tip of {component}",
    "components.radius": "Draw the radius {pivot}{point} of link {link} about its fixed pivot "
                         "{pivot}.",
    "components.path": "At {point} draw the perpendicular to {pivot}{point}: the path of {point}.",
    "components.say_path": "the path of {point} (⟂ {pivot}{point})",
    "components.say_guide": "the guide of {point}",
    "components.glide": "Link {link} slides on a frame guide without turning, so {point} moves "
                        "parallel to the guide: draw it through {point}.",
    "components.say_glide": "the path of {point} (∥ the guide of link {link})",
    "components.slot_parallel": "Through the tip of V_{other} draw the parallel to the slot of "
                                "link {link}: V_{point} − V_{point}{link} lies along the slot.",
    "components.say_slot": "the parallel to the slot of link {link} through the tip of V_{other}",
    "components.loci_meet": "{first} meets {second} at the tip of V_{point}{note}.",
    "components.not_vector_sum": " (not the vector sum of the two components!)",
    "components.perpendicular_at": "At {point} draw the perpendicular to {line}.",
    "components.project_normal": "Project the tip of V_{point} onto it: {component} is the "
                                 "component of V_{point} ⟂ {line}.",
    "components.draw_component": "Draw {component} at {point}.",
    "components.line_carries": "Draw line {line} of link {link}; {point} lies on it.",
    "components.through_rest_and_tip": "{rest} (at rest) and the tip of V_{other}″",
    "components.through_tips": "the tips of V_{a}″ and V_{b}″",
    "components.gauge_through": "Draw the gauge line through {through}.",
    "components.cuts_gauge": "It cuts the gauge line at the tip of {component}, the component "
                              "of V_{point} ⟂ {line}.",
    "components.rest_gives": "V_{point}′ = V_{rest}′ = 0 ({rest} is at rest), so V_{point} = "
                             "{component}.",
    "components.pgram_first": "Through the tip of {a} draw the parallel to {b} (⟂ {line}).",
    "components.pgram_second": "Through the tip of {a} draw the parallel to {b} (along {line}).",
    "components.pgram_meet": "They meet at the tip of V_{point} = {a} + {b} (the parallelogram).",
    "components.translate": "Link {link} slides on a frame guide without turning, so all its "
                            "points have V_{known}: with dividers lay it off at {point}.",
    # ----- both polygons (constructions.polygon_walk) --------------------------------------
    "then": " {sentences}",
    "polygon.pole": "Choose the {noun} pole {pole}: every vector drawn from it is an absolute "
                    "{noun}.",
    "polygon.relative": "Join {a} to {b}: {symbol} = {size}.",
    "apolygon.resolve_relative": "Through {a} draw the parallel to {p}{q}: the normal part of "
                                 "{a} {b} runs along it.",
    "apolygon.resolve_absolute": "Through {pole} draw the parallel to the velocity of {point}, "
                                 "the tangent to its path: the tangential part of {pole} {tip} "
                                 "runs along it.",
    "apolygon.resolve_foot": "Drop the perpendicular from {tip} onto it: its foot parts the "
                             "acceleration into its normal and tangential parts.",
    "vpolygon.path": "Join o_v to {tip}: the direction of the velocity of {point}.",
    "readings.link_line": "Draw the line {a}{b} of link {link}.",
    "apolygon.rolling": "{point}, the point of wheel {link} on the ground, is at rest but "
                        "accelerates toward the centre {centre}: from o_a lay off a_{point} = "
                        "ω{link}²·r = ({omega} rad/s)² × {radius} = {accel} parallel to "
                        "{point}{centre}, toward {centre}; its end is {tip}.",
    "apolygon.rolling_round": "{point}, the point of wheel {link} on the circle, is at rest but "
                              "accelerates toward the centre {centre}: from o_a lay off "
                              "a_{point} = ω{link}²·r·R/(R {op} r) = ({omega} rad/s)² × "
                              "{radius} × {big}/({big} {op} {radius}) = {accel} parallel to "
                              "{point}{centre}, toward {centre}; its end is {tip}.",
    "readings.least_velocity": "Drop the perpendicular from {centre} onto {a}{b}: its foot "
                               "{point} is the point of the line nearest {centre}, the slowest "
                               "of link {link}.",
    "readings.least_side": "Of the sides of plate {link}, {a}{b} passes nearest {centre}: drop "
                           "the perpendicular from {centre} onto it; its foot {point} is the "
                           "plate's point nearest {centre}, the slowest of link {link}.",
    "readings.least_corner": "No perpendicular from {centre} falls on a side of plate {link} "
                             "nearer than its corner {a}: {a} is the slowest point of link "
                             "{link}.",
    "readings.least_inside": "{centre} lies within plate {link}: the plate's point there is at "
                             "rest, the slowest of link {link}.",
    "polygon.space_line": "Draw line {a}{b} of link {link}.",
    "polygon.lines_meet": "The two lines meet at {tip}: {pole} {tip} = {symbol}_{point}.",
    "polygon.image_why": "{x} lies on line {a}{b} of link {link}, so {tip} lies on {ta} {tb} with "
                         "{ta} {tip} : {ta} {tb} = {a}{x} : {a}{b} = {ratio} (the {noun} image)",
    "polygon.image_collapsed": "{why}; {ta} {tb} has no length, so {tip} is at {ta}.",
    "polygon.image_lay_off": "{why}: lay off {ta} {tip} = {ratio} × {ta} {tb} along {ta} {tb}.",
    "polygon.translate": "Link {link} slides on a frame guide without turning, so {symbol}_{point} "
                         "= {symbol}_{known}: {tip} is at {known_tip}.",
    "polygon.coincide": "{point} of link {link} stands, at this instant, on {known}: they are "
                        "one point of the link, so {symbol}_{point} = {symbol}_{known} and "
                        "{tip} is at {known_tip}.",
    "polygon.say_perpendicular": "the line ⟂ {line} through {tip}",
    "polygon.say_guide": "the parallel to the guide through {pole}",
    "polygon.say_slot": "the parallel to the slot through {tip}",
    "polygon.why_guide": "the guide of {point}",
    "polygon.why_glide": "the guide of link {link}, which slides on it without turning",
    # ----- the velocity polygon (constructions.velocity_polygon) ---------------------------
    "vpolygon.input_direction": "Through o_v draw a line ⟂ {pivot}{p} (the direction of "
                                "V_{point}).",
    "vpolygon.input": "From o_v lay off o_v {tip} = V_{point} = ω{link}·{pivot}{p} = {omega} "
                      "rad/s × {radius} = {speed} ⟂ {pivot}{p}, in the sense of ω{link} ({sense}).",
    "vpolygon.why_fixed": "V_{point}, as {known} is fixed",
    "vpolygon.why_relative": "V_{point}/{known}",
    "vpolygon.perpendicular": "Through {tip} draw a line ⟂ {line} (the direction of {why}).",
    "vpolygon.parallel_guide": "Through o_v draw the parallel to {why} (the direction of "
                               "V_{point}).",
    "vpolygon.slot": "Through {tip} draw the parallel to the slot of link {link} (the direction "
                     "of V_{point}/{other}, the sliding velocity).",
    "vpolygon.curve": "Through {tip} draw a line ⟂ {line}, the tangent at {point} of the curved "
                      "slot about {centre} (the direction of V_{rel}, the sliding velocity).",
    "vpolygon.omega": "ω{link} = {rel} / {line} = {side} / {line} = {speed} ÷ {length} = {omega} "
                      "rad/s ({sense}: the sense of {rel} about {about}).",
    "vpolygon.vector": "o_v {tip} = V_{point} = {speed}.{then}",
    "vpolygon.relative": "{a} {b} is {rel}. {omega}",
    # ----- the acceleration polygon (constructions.acceleration_polygon) -------------------
    "apolygon.input_normal": "From o_a lay off Aⁿ_{point} = ω{link}²·{pivot}{p} = ({omega} "
                             "rad/s)² × {radius} = {accel} parallel to {p}{pivot}, pointing from "
                             "{p} toward {pivot} (the normal component).",
    "apolygon.wheel_centre_path": "The centre {point} of wheel {link} runs along a straight "
                                  "path, parallel to the face: through o_a draw a line ⟂ "
                                  "{contact}{point} (the direction of A_{point}).",
    "apolygon.wheel_centre": "Along it lay off A_{point} = α{link}·r = {alpha} rad/s² × {radius} "
                             "= {accel}, in the sense of α{link} ({sense}): the centre of a "
                             "wheel rolling on a straight face has no acceleration across it. "
                             "Its end is {tip}.",
    "apolygon.wheel_centre_still": "α{link} = 0 ({given}), and the centre {point} of wheel "
                                   "{link} runs along a straight path, so A_{point} = "
                                   "α{link}·r = 0: {tip} is at o_a.",
    "apolygon.given": "given",
    "apolygon.not_given": "not given, so taken as 0",
    "apolygon.input_no_tangential": "α{link} = 0 ({given}), so Aᵗ_{point} = α{link}·{pivot}{p} = "
                                    "0: {tip} is at the end of Aⁿ_{point}.",
    "apolygon.tangential_direction": "Through its end draw a line ⟂ {pivot}{p} (the direction "
                                     "of Aᵗ_{point}).",
    "apolygon.input_tangential": "Along it lay off Aᵗ_{point} = α{link}·{pivot}{p} = {alpha} "
                                 "rad/s² × {radius} = {accel}, in the sense of α{link} ({sense}); "
                                 "its end is {tip}.",
    "apolygon.parallel_guide": "Through o_a draw the parallel to {why} (the direction of "
                               "A_{point}, as the guide is straight and fixed).",
    "apolygon.no_normal": "ω{link} = 0, so Aⁿ_{rel} = 0: through {tip} draw a line ⟂ {line} "
                          "(the direction of Aᵗ_{rel}, length unknown).",
    "apolygon.normal": "From {tip} lay off Aⁿ_{rel} = ω{link}²·{line} = ({omega} rad/s)² × "
                       "{length} = {accel} parallel to {back}, pointing from {x} toward {k}.",
    "apolygon.tangential_line": "Through its end draw a line ⟂ {line} (the direction of "
                                "Aᵗ_{rel}, length unknown).",
    "apolygon.say_tangential": "the line ⟂ {line} through the end of Aⁿ_{rel}",
    "apolygon.slot": "Through its end draw the parallel to the slot of link {link} (the "
                     "direction of the sliding acceleration Aˢ_{rel}, length unknown).",
    "apolygon.say_slot": "the parallel to the slot through the end of {component}",
    "apolygon.curve_normal": "From its end lay off the normal component of the relative path "
                             "Aⁿ_{rel} = V_{rel}²/ρ = ({speed})² ÷ {radius} = {accel} parallel to "
                             "{p}{k}, pointing from {p} toward the centre of curvature "
                             "{k}{reversed}.",
    "apolygon.reversed": ", reversed, as it is subtracted",
    "apolygon.curve_tangent": "Through its end draw a line ⟂ {line}, the tangent of the slot "
                              "(the direction of Aᵗ_{rel}, length unknown).",
    "apolygon.still": "ω{link} = 0 (link {link} is at rest for this instant)",
    "apolygon.stuck": "V_{rel} = 0 (no sliding at this instant)",
    "apolygon.coriolis_zero": "The Coriolis component 2ω{link}·V_{rel} is zero, as {why}.",
    "apolygon.coriolis_direction": "Through {tip} draw a line ⟂ the slot of link {link} (the "
                                   "direction of the Coriolis component).",
    "apolygon.along_it": "Along it",
    "apolygon.from_along": "From {tip} along {line}",
    "apolygon.coriolis": "{where} lay off the Coriolis component Aᶜ_{rel} = 2ω{link}·V_{rel} = "
                         "2 × {omega} rad/s × {speed} = {accel}, in the direction of V_{rel} "
                         "turned 90° the way ω{link} turns ({sense}){reversed}.",
    "apolygon.vector": "o_a {tip} = A_{point} = {accel}.{then}",
    "apolygon.what_tangential": "Aᵗ_{rel}",
    "apolygon.what_part": "the part of A_{rel} ⟂ {line}",
    "apolygon.alpha": "α{link} = {what} / {line} = {accel} ÷ {length} = {alpha} rad/s² "
                      "({sense}: the sense of {what} about {about}).",
    # ----- ω by the line of transmission (constructions.transmission) ---------------------
    "transmission.line": "Draw the line of transmission {a}{b}, along the coupler (link {link}): "
                         "{a} and {b} have equal velocity components along it.",
    "transmission.perpendicular": "From {centre} draw the perpendicular to {a}{b}.",
    "transmission.foot": "It meets {a}{b} at {foot}.",
    "transmission.measure": "Measure {centre}{foot} = {length}.",
    "transmission.ratio": "Measure {o_f}H = {length}. The angular velocities are inversely as "
                          "these perpendiculars: ω{n}/ω{d} = {o_d}G/{o_f}H = {ratio}, and the "
                          "centres lie on {sides} of the line, so ω{n} = {omega} rad/s ({sense}).",
}
