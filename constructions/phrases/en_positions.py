"""English phrases of the linkages' positions: position by compass, the instant centres, the
limit positions, Klein's construction and the equivalent linkage."""

from __future__ import annotations

__all__ = ["PHRASES"]

PHRASES: dict[str, str] = {
    # ----- position by compass (constructions.assembly) -----------------------------------
    "position.at": "at θ{link} = {angle}",
    "position.frame_point": "Mark the frame point {point} at ({x}, {y}).",
    "position.frame_guide": "Draw the guide of {point} on the frame at {angle}.",
    "position.input_ray": "Through {pivot} draw the ray at θ{link} = {angle}.",
    "position.input_point": "With centre {pivot} and radius {pivot}{point} = {radius}, lay off "
                            "{point} {at}.",
    "position.on_link_line": "{point} lies on line {a}{b} of link {link}: lay off {a}{point} = "
                             "{length} from {a}.",
    "position.rigid_point": "{point} is a point of link {link}: with centres {a} and {b} and "
                            "radii {a}{point} = {ra} and {b}{point} = {rb}, cut arcs at {point}.",
    "position.along_link": "Along link {link}, lay off {base}{point} = {length} from {base} to "
                           "mark {point}.",
    "position.square_off": "Square off {length} from the axis to mark {point}.",
    "position.radius_span": "{a}{b} = {length}",
    "position.radius_because": "{length}, as {why}",
    "position.why_curved_slot": "{point} runs in the curved slot of link {link} about {centre}",
    "position.why_circles_touch": "the circles of links {i} and {j} touch: their centres {p} and "
                                  "{q} stay r{i} {op} r{j} apart",
    "position.swing_arc": "With centre {centre} and radius {radius}, swing an arc.",
    "position.locus": "With centre {centre} and radius {radius}, draw the locus of {point}.",
    "position.arcs_cut": "The arcs cut at {point} ({pick} of {a} → {b}); join {a}{point} and "
                         "{b}{point}.",
    "position.arc_cuts_guide": "The arc cuts the guide at {point} (the {pick} cut).",
    "position.two_guides": "{point} runs on two guides: it is where they cross.",
    "position.wheel_rolls": "Link {link}{name} rolls without slip: its centre {point} stands "
                            "{rolled} from where it started, so it has turned {turn} {sense} "
                            "({rolled} ÷ r = {radius}); draw its axis through {point}.",
    "position.wheel_input": "Link {link}{name}, the input, rolls without slip along the face "
                            "through {face}: at θ{link} = {turn} {sense} from where its centre "
                            "stood square over {face}, it has rolled r·θ{link} = {rolled} "
                            "(r = {radius}). Lay off {rolled} {way} along the path of its centre "
                            "from there to mark {point}.",
    "position.wheel_axis": "Through {point} draw the axis of link {link} at θ{link} = {angle}.",
    "position.wheel_arm": "Join {contact}{point}: wheel {link} turns, at the instant, about "
                          "{contact}, its point on the face, which is at rest.",
    "position.wheel_rolls_round": "Link {link}{name} rolls round the circle about {centre} "
                                 "without slip: its centre {point} has gone {beta} round "
                                 "{centre} from the start, so it has turned {beta} × {ratio} "
                                 "= {turn} (R = {big}, r = {radius}); draw its axis through "
                                 "{point}.",
    "link_name": " ({name})",
    "position.slot_square_to_guide": "Through {point} draw the perpendicular to the guide of "
                                     "{block}: the slot of link {link}.",
    "position.slot_at_angle": "Through {point} draw the line at {angle} to the guide of {block}: "
                              "the slot of link {link}.",
    "position.face_offset": "Lay off {length} square to the slot: the parallel through it "
                            "carries {point}.",
    "position.cut_guide": "{point} is where that line cuts the guide of {point}.",
    "position.slot_through_block": "The slot of link {link} passes through {pivot} and the block "
                                   "{point}: draw line {pivot}{point}.",
    "position.bisect": "Bisect {a}{b}.",
    "position.circle_on_diameter": "Draw the circle on diameter {a}{b}.",
    "position.offset_arc": "With centre {centre} and radius {radius} (the slot's offset), swing "
                           "an arc.",
    "position.foot_of_slot": "The arcs cut at the foot of the slot.",
    "position.slot_tangent": "Draw the slot through {point}, tangent to the arc.",
    # ----- instant centres (constructions.centres) ----------------------------------------
    "on_frame": "the frame",
    "on_link": "link {link}",
    "centres.pin": "The pin {point} joins links {i} and {j}, so it is {centre}.",
    "centres.curved_block": "Block {point} of link {link} slides on a guide of {on} curved about "
                            "{at}, so {centre} is at the centre of curvature {at}.",
    "centres.straight_block": "Block {point} of link {link} slides on a straight guide of {on}, "
                              "so {centre} is at infinity, perpendicular to the guide.",
    "centres.common_normal": "{centre} lies on the common normal at {point}: through {point} "
                             "draw the perpendicular to the {what} of link {link}.",
    "centres.contact_normal": "{centre} lies on the common normal at the contact, {what}: draw "
                              "line {a}{b}.",
    "centres.line_of_centres": "the line of centres of the two circles",
    "centres.curved_radius": "the radius of the curved slot of link {link}",
    "centres.face": "Through {point} draw the face of link {link}, parallel to the path of "
                    "{path_of}.",
    "centres.rolling": "Link {link} rolls on link {on} without slip, so the contact point, the "
                       "foot of {point} on the face, is {centre}.",
    "centres.rolling_round": "Link {link} rolls round the circle of link {on} without slip, so "
                             "the contact point, {radius} from {circle} along {circle}{point}, "
                             "is {centre}.",
    "centres.kennedy_line": "Triangle {triangle}: by Kennedy, {centre} lies on the line through "
                            "{a} and {b}.",
    "centres.lines_meet": "{centre} is where the two lines meet.",
    "centres.rule2_mark": "Every Kennedy line for {centre} is this one line, so use the "
                          "velocities (rule 2): mark X on it, {length} from {start}.",
    "centres.rule2_tip": "Square to the line at X lay off the velocity X would have as a point "
                         "of link {link} (from its ω ratio).",
    "centres.rule2_translating": "Link {link} translates: its velocity profile is the parallel "
                                 "to the line through the tip.",
    "centres.rule2_profile": "Join {centre} to the tip: the velocity profile of link {link}.",
    "centres.rule2_meet": "The profiles cross where links {i} and {j} have equal velocities.",
    "centres.rule2_centre": "Square back onto the line: that point is {centre}.",
    "equivalent.centres": "{a} and {b} are the centres of curvature of the two profiles in "
                          "contact (links {i} and {j}); the common normal runs through both.",
    "equivalent.link": "They stay {length} apart ({how}), so at this instant the contact acts "
                       "as a link {a}{b} pinned at both centres: the equivalent link, dashed.",
    "equivalent.slot": "The centre {a} of the circle of link {i} stays {r} from the face of "
                       "link {j}, so at this instant the contact acts as a block at {a} running "
                       "in a slot parallel to the face: the equivalent slot, dashed.",
    "klein.square": "Through {o} draw the line square to the line of stroke.",
    "klein.produce": "Produce the rod {p}{c}.",
    "klein.m": "It meets the line through {o} at M.",
    "klein.velocity": "{o}{c}M is the velocity triangle turned through 90°: V_{p} = ω·{o}M, "
                      "V_{c} = ω·{o}{c}, V_{p}{c} = ω·{c}M.",
    "klein.circle_cm": "With centre {c} and radius {c}M draw a circle.",
    "klein.circle_cp": "Draw the circle on {c}{p} as diameter.",
    "klein.kl": "The two circles meet at K and L.",
    "klein.join_kl": "Join K and L.",
    "klein.q": "KL cuts {c}{p} at Q.",
    "klein.point_v": "Lay off {c}{x} = {ratio} × {c}M along {c}M, as {c}{point} = {ratio} × "
                     "{c}{p} on the rod: {o}{x} is V_{point} turned through 90°, V_{point} = "
                     "ω·{o}{x}.",
    "klein.point_a": "Lay off {c}{x} = {ratio} × {c}N along {c}N, as {c}{point} = {ratio} × "
                     "{c}{p} on the rod: a_{point} = ω²·{x}{o}, from {x} toward {o}.",
    "klein.plate_v": "On {c}M draw {c}M{x} similar to the rod's {c}{p}{point}: from {c} at "
                     "{at_c}° to {c}M, from M at {at_p}° to M{c}; {o}{x} is V_{point} turned "
                     "through 90°, V_{point} = ω·{o}{x}.",
    "klein.plate_a": "On {c}N draw {c}N{x} similar to the rod's {c}{p}{point}: from {c} at "
                     "{at_c}° to {c}N, from N at {at_p}° to N{c}; a_{point} = ω²·{x}{o}, from "
                     "{x} toward {o}.",
    "klein.acceleration": "It cuts the line of stroke at N: {o}{c}QN is the acceleration "
                          "polygon turned through 180°, so a_{p} = ω²·N{o}, from N toward {o} "
                          "(a_{c} = ω²·{o}{c}, aⁿ_{p}{c} = ω²·{c}Q, aᵗ_{p}{c} = ω²·QN).",
    # ----- limit positions (constructions.limit_positions) ---------------------------------
    "limits.join_cranks": "Join {pivot}{a} and {pivot}{b}: the crank at its two limit positions.",
    "limits.measure": "Measure the angle {a}{pivot}{b} the crank turns from {a} to {b} ({sense}, "
                      "with ω{link}): {degrees}°, the {stroke} stroke.",
    "limits.in_line": "With centre {pivot} and radius {span} = {radius} draw an arc to cut "
                      "{path} at {point}: crank and rod in line, {how}.",
    "limits.span_sum": "{a}{b} + {pivot}{a}",
    "limits.span_difference": "{a}{b} − {pivot}{a}",
    "limits.path_of": "the path of {point}",
    "limits.arc_about": "the arc of {point} about {centre}",
    "limits.crank_along": "Join {pivot}{point}; the crank lies along it: {pin} is {pivot}{crank} "
                          "= {radius} from {pivot} toward {point}.",
    "limits.crank_beyond": "Join {point}{pivot} and produce it beyond {pivot}: {pin} is "
                           "{pivot}{crank} = {radius} from {pivot} on the far side.",
    "limits.bisect": "Bisect {a}{b} at M.",
    "limits.thales": "With centre M and radius M{a} draw the circle on {a}{b} as diameter: from "
                     "any point of it {a} and {b} are seen at 90°.",
    "limits.crank_circle": "With centre {pivot} and radius {pivot}{pin} = {radius} draw the crank "
                           "circle.",
    "limits.tangent_cuts": "The two circles cut at {pin}′ and {pin}″ (one each side of {a}{b}), "
                           "where {a}{pin} ⟂ {b}{pin}.",
    "limits.second_cut": "{pin}″ is the second cut.",
    "limits.lever": "Join {pivot}{pin}: the lever tangent to the crank circle, its {which} limit "
                    "position.",
    "limits.stroke": "Measure {point}″{point}′: the stroke of {point}, {length}.",
    "limits.produce_lever": "Produce {pivot}{held} to cut the path of {point} at {end}.",
    "limits.rod_cuts_path": "With centre {x} and radius {span} = {radius} cut the path of {point} "
                            "at {end}.",
    "limits.rod": "Join {a}{b}: link {link} in that limit position.",
    "limits.swing_angle": "Measure the angle {a}{pivot}{b}: link {link} swings through "
                          "{degrees}° between its limit positions.",
    "limits.inclination": "Measure the angle {c}{pivot}{a}: at either limit the lever stands "
                          "{degrees}° from the line of centres {pivot}{c}.",
    "limits.lever_in_line": "With centre {pivot} and radius {span} = {radius} draw an arc to cut "
                            "{path} at {point}: lever and rod in line, {how}.",
    "limits.lever_along": "Join {pivot}{point}; the lever lies along it: {end} is {pivot}{x} = "
                          "{radius} from {pivot} toward {point}.",
    "limits.lever_beyond": "Join {point}{pivot} and produce it beyond {pivot}: {end} is "
                           "{pivot}{x} = {radius} from {pivot} on the far side.",
    "limits.slot_cuts_crank": "The lever's line {pivot}{end} cuts the crank circle at {pin}: "
                              "the crank pin in the slot.",
    "limits.swing": "With centre {pivot} swing {point} with the lever through the angle "
                    "{held}{pivot}{held_there} to {there}.",
}
