"""English: the words of every step, as the lecture notes and Hinkle's chapter word them.

Each template is :meth:`str.format` text whose fields are the phrase's arguments;
a field that is a clause renders as that clause's own template.
"""

from __future__ import annotations

__all__ = ["PHRASES", "WORDS", "UNITS", "digits", "capitalized"]


def digits(text: str) -> str:
    """English writes numbers in ASCII digits, as formatted."""
    return text


def capitalized(text: str) -> str:
    """A clause that opens a sentence takes a capital: "the path of B" → "The path of B"."""
    return text[:1].upper() + text[1:]


UNITS: dict[str, str] = {}
"""Unit names as the language writes them (English: as the file states them)."""

WORDS: dict[str, str] = {"at rest": "at rest"}
"""Small words as the language says them (English: as they are)."""

PHRASES: dict[str, str] = {
    # ----- notes under the figures (assumptions, warnings) -------------------------------------
    "note.alpha_not_given": "α{link} is not given, so it is taken as 0.",
    "note.ill_conditioned": "{centre} is ill-conditioned: conditioning {cond} along its "
                            "construction (its own two lines meet at {angle}°)",
    "note.unvouched": "{quantity} by {method} is left out: {why}, so it cannot be vouched for "
                      "here; {other} gives it.",
    "weak.reference": "the analytic value itself is lost to rounding here",
    "weak.lines": "its two lines meet at {angle}°",
    "weak.arcs": "its two arcs all but touch",
    "weak.line_arc": "its line all but touches its arc",
    "weak.points": "it draws a line through two points all but together",
    "weak.act": "its construction is ill-conditioned",
    "weak.short": "its vectors are drawn {share} of the mechanism long",
    "note.given_rate": "{what} = {value} is given: the velocity polygon drawn at ω{link} = "
                       "1 rad/s gives {target} = {per}, so ω{link} = {omega}{sense}{second}.",
    "note.given_alpha": "; the acceleration polygons drawn at that ω with α{link} = 0 and "
                        "1 rad/s² give α{link} = {alpha}",
    "note.along_guide": "V_{point} along its guide",
    "note.sense": " ({sense})",
    # ----- steps.md's own words (exercises.solution_files) -----------------------------------
    "md.title": "{name}: worked solution",
    "md.at": "At {where}",
    "md.position": "Position: θ{link} = {angle}, ω{link} = {omega} rad/s {sense}, α{link} = "
                   "{alpha} rad/s²{given}.",
    "md.not_given": " (not given: 0)",
    "md.results": "Results",
    "md.columns": "| quantity | construction | analytic | relative error | method |",
    "md.whole": "The mechanism as a whole",
    "md.whole_columns": "| quantity | answer | check | relative error | method |",
    "overall.grubler": "Grübler: 3({n} − 1) − 2·{f1} − {f2}",
    "overall.meeting": "{grubler}; at this position {points} is where two assemblies meet (a "
                       "change point), so the mobility is momentarily {here}",
    "overall.meetings": "{grubler}; at this position {points} are where two assemblies meet "
                        "(a change point), so the mobility is momentarily {here}",
    "overall.grashof": "Grashof: S + L = {s_l} against P + Q = {p_q}; checked by turning each "
                       "link{which}",
    "overall.range": "Grashof's inequalities, at their breakpoints; checked by bisecting the "
                     "turning test{which}",
    "overall.change_point": "; a change-point linkage (S + L = P + Q): twice a revolution its "
                            "links fall in line, where its two assemblies meet and it may go "
                            "on in either",
    "md.by": "{what} by {method}",
    "md.time_ratio": "The crank turns {slow}° from {start} to {end} ({sense}) in the slow stroke "
                     "and {quick}° in the quick one: time ratio {slow}/{quick} = {ratio}.",
    "md.heading": "{heading}",
    "md.other_form": "The other common form:",
    "md.chain_rule": "The cam turns at constant speed, so ẏ = y′ω and ÿ = y″ω² (the notes' "
                     "chain rule with α = 0).",
    "md.jumps": "ÿ jumps at θ = {jumps}: the jerk is infinite there.",
    # ----- steps.md's headings: a figure's or a reading's part -----------------------------
    "heading.train": "The train",
    "heading.tabular": "The tabular method",
    "heading.train_value": "The train value",
    "heading.involute": "The involute mesh",
    "heading.kutzbach": "The velocity (Kutzbach) diagram",
    "heading.displacement": "The displacement diagram",
    "heading.peaks": "Peaks",
    "heading.profile": "The profile by inversion",
    "heading.construction": "The construction",
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
    "gears.ordinary_start": "{member}, the input, turns {speed}. Carry one turn of it through "
                            "the meshes:",
    "gears.mesh_carries": "{driven} meshes {kind}ly with {driver}, so it turns {way}, "
                          "N{a}/N{b} = {na}/{nb} as fast: {turns} → {result}.",
    "gears.shaft_carries": "{member} is on one shaft with {other}: it turns alike, {turns}.",
    "gears.fixed": ", fixed",
    "gears.one_planet": "one planet",
    "gears.planets": "{n} planets, equally spaced",
    "gears.speed": "{value} {unit}{sense}",
    "gears.sense": " {sense}",
    "kutzbach.planet_centres": "the planets' centres",
    "gears.one_shaft": ", on one shaft with {others}",
    "gears.modules": "{value} modules",
    "involute.circle_of": "{circle} of {gear}",
    "gears.idler": "; the idler {idlers} cancels",
    "gears.idlers": "; the idlers {idlers} cancel",
    "gears.the_gear": "gear {number}{name}",
    "gears.the_arm": "the arm {number}{name}",
    "gears.named": " ({name})",
    "gears.train_value": "The train value e = ω{last}/ω{first} = ({drivers})/({driven}) = "
                         "{teeth} = {value}: driver teeth over driven teeth, {externals} "
                         "external meshes making it {sign}{idlers}.",
    "gears.power": "The input is driven by {given}. With no power lost, T{i}·ω{i} + T{o}·ω{o} = "
                   "0, so T{o} = −T{i}·ω{i}/ω{o} = −T{i} × {ratio} = {value} N·m "
                   "(counter-clockwise +).",
    "gears.holding": "The torques on the train sum to zero, so the fixed member {fixed} is "
                     "held by T{fixed} = −(T{i} + T{o}) = {value} N·m.",
    "kutzbach.radial": "Draw the radial line up from the main axis O, radii to scale: every "
                       "point on it moves square to it, so each velocity is laid across it "
                       "(counter-clockwise to the right), and each member's velocities lie on "
                       "a straight line whose slope is its ω.",
    "kutzbach.radius": "Mark {name} = {radius} ({what}) on the radial line and draw the level "
                       "through it.",
    "kutzbach.fixed": "{member} is fixed: its velocities are nil, and its line is the radial "
                      "line itself.",
    "kutzbach.input": "{member} turns {omega} rad/s {sense}: at {name} = {radius} lay off its "
                      "velocity ω·r across the level, at the velocity scale.",
    "kutzbach.main_line": "Member {member} turns about the main axis: its line runs from O "
                          "through {point}.",
    "kutzbach.pitch": "{a} and {b} share the velocity of their pitch point, at {name}: it is "
                      "where the line of {known} crosses that level.",
    "kutzbach.planet_line": "The planet {member} is one body: its line runs through {p} and "
                            "{q}.",
    "kutzbach.centre": "The planets' centre, at R, moves with the arm: it is where the line of "
                       "{known} crosses that level.",
    "kutzbach.read": "Read ω{member} = Δv/Δr, the slope of its line: {omega} rad/s{sense}, "
                     "{speed}.",
    "kutzbach.input_planet": "{member} turns {omega} rad/s {sense} about {pitch}, its pitch "
                             "point with the fixed member, at rest: at {name} lay off its "
                             "centre {point}'s velocity ω·({name} − {level}) across the level, "
                             "at the velocity scale.",
    "kutzbach.trial": "No line follows from the input's alone: drawn first for {member} at a "
                      "trial {trial} rad/s {trial_sense}, the diagram gives {drive} "
                      "{read} rad/s {read_sense}. It turns {given} rad/s, and every velocity "
                      "scales alike, so {member} turns {omega} rad/s {sense}.",
    "kutzbach.planet_centre": "the centre of planet {member}",
    "kutzbach.centre_at": "The centre {point} of the planet {member}, at {name}, moves with the "
                          "arm: it is where the line of {known} crosses that level.",
    "involute.centres": "Mark the centres O{a} and O{b}, {distance} apart, and join them: the "
                        "line of centres.",
    "involute.pitch_point": "By the law of gearing the pitch point P divides O{a}O{b} as the "
                            "base radii, N{a} : N{b} = {na} : {nb}: lay off O{a}P = {o2p}.",
    "involute.circle": "Draw the {name}, radius {radius}.",
    "involute.thales": "Draw the circle on diameter {centre}P (Thales): a tangent from P "
                       "touches a circle about {centre} where this one cuts it.",
    "involute.tangent_point": "It cuts the {base} at {point}, where the line of action touches "
                              "it.",
    "involute.line_of_action": "Join the tangency points: the line of action, the common "
                               "internal tangent of the base circles of {a} and {b}, through P.",
    "involute.common_tangent": "Through P draw the common tangent of the pitch circles, square "
                               "to the line of centres; the line of action leans from it by "
                               "the pressure angle.",
    "involute.circular_pitch": "Step P one tooth round the pitch circle of {a}, 360°/{teeth}, "
                               "to P′: the arc PP′ is the circular pitch.",
    "involute.start": "The addendum circle of {b} cuts the line of action at A: contact "
                      "begins there.",
    "involute.end": "The addendum circle of {a} cuts it at B: contact ends there.",
    "involute.path": "Measure the path of contact AB = {path}; the pressure angle reads "
                     "{angle}, so the arc of contact is AB / cos φ = {arc}, and over the base "
                     "pitch {pitch} the contact ratio is {ratio}.",
    "involute.start_point": "For the tooth of {gear} through P: step the arc {t}{point} = P{t} "
                            "= {length} back along its base circle to {point}, where the "
                            "string starts.",
    "involute.profile": "Divide the base circle of {gear} from {point} into {divisions} equal "
                        "arcs of {arc}; at each division lay off the arc from {point} along "
                        "the tangent, and join the points: the involute.",
    "gears.member": "{member}, {teeth} teeth, {where}{shaft}{fixed}.",
    "gears.on_axis": "on the main axis",
    "gears.on_own_axis": "on its own axis in the housing",
    "gears.on_pin": "on the pin of the arm {arm}, at the carrier radius",
    "gears.arm": "The arm {arm} turns about the main axis and carries the planets' pin "
                 "({planets}){fixed}.",
    "gears.meshes": "Gears {a} and {b} mesh {kind}ly.",
    "cam.axes": "Draw the base line: cam angle across it, the follower's lift up from it.",
    "cam.ordinates": "Segment {k} ({kind}, {angle}): divide its cam angle into {n} equal parts "
                     "and draw an ordinate at each division.",
    "cam.dwell": "Segment {k} is a dwell of {angle}: the follower stands still, a level line.",
    "cam.uniform": "Segment {k} is uniform velocity: the diagonal from its start to its end; "
                   "the ordinates cut it at the follower's places.",
    "cam.harmonic": "Segment {k} is simple harmonic: on the lift of {lift} draw a semicircle "
                    "at the segment's start and divide it into {n} equal arcs; project each "
                    "division across to its ordinate.",
    "cam.parabolic": "Segment {k} is uniform acceleration and retardation: for its {half} half, "
                     "divide half the lift on its {where} ordinate in the ratio 1 : 3 : 5 … "
                     "{way} by parallels from a line marked at 1, 4, 9 … equal steps ({m} of "
                     "them), and project each division across to its ordinate.",
    "cam.blend": "Segment {k} is modified uniform velocity: for its {half} blend, divide its "
                 "share of the lift, {rise}, on its {where} ordinate in the ratio 1 : 3 : 5 … "
                 "{way} by parallels from a line marked at 1, 4, 9 … equal steps ({m} of "
                 "them), and project each division across to its ordinate.",
    "cam.modified": "Segment {k}: join the ends of its two parabolas by a straight line, the "
                    "uniform velocity between the blends; the ordinates between cut it.",
    "cam.cycloidal": "Segment {k} is cycloidal: about its start draw a circle of radius lift/2π "
                     "= {radius} and divide it into {n} equal arcs; project each division onto "
                     "the start ordinate, and from there run a parallel to the segment's "
                     "diagonal to its ordinate.",
    "cam.centre": "Mark the cam's centre O; the cam is held still and the follower turned "
                  "round it the other way (the inversion).",
    "cam.base": "Draw the base circle about O, radius {r}.",
    "cam.prime": "Draw the prime circle about O, radius {r}: the base circle grown by the "
                 "roller's radius {roller}, where the roller's centre rests.",
    "cam.offset": "Draw the offset circle about O, radius {e}: the follower's line stays "
                  "tangent to it.",
    "cam.pivot_circle": "Draw the pivot circle about O through the follower's pivot A; the "
                        "arm, {arm} long, is turned round with it.",
    "cam.stations": "Turn the {follower} follower's rest position {turn} about O, against "
                    "the cam's turning, by each station's cam angle, and number the stations.",
    "cam.lift": "Station {i} ({deg}): along the follower's line lay off the lift {lift}, taken "
                "from the displacement diagram{then}.",
    "cam.swing": "Station {i} ({deg}): about the turned pivot swing the arm through {swing}, "
                 "the follower's angle from the displacement diagram{then}.",
    "cam.then.roller": "; about the point so found draw the roller's circle, radius {r}",
    "cam.then.flat-faced": "; through the point so found draw the face, square to the line",
    "cam.profile.knife-edge": "Draw the profile as the smooth curve through the knife edge's "
                              "points: for a knife edge it is the pitch curve itself.",
    "cam.profile.roller": "Draw the pitch curve through the roller's centres, and the profile "
                          "as the smooth curve inside every roller circle, touching each (the "
                          "inner envelope).",
    "cam.profile.flat-faced": "Draw the profile as the smooth curve inside every face line, "
                              "touching each (the envelope of the face lines).",
    "balance.space": "Draw the end view: from the shaft's centre O a radial line to each "
                     "mass, at its angle.",
    "balance.couple": "The couple polygon, plane {a} the reference: lay off each mᵢrᵢlᵢ, lᵢ "
                      "from {a}, head to tail, each parallel to its mass's radial line (the "
                      "other way where lᵢ < 0).",
    "balance.force": "The force polygon: lay off each mᵢrᵢ head to tail, each parallel to its "
                     "mass's radial line (ω² is common to all, so it is left out).",
    "balance.close": "Close the polygon from its last tip back to its start: the closing side "
                     "is plane {plane}'s balancing vector, the resultant turned through 180°.",
    "balance.left": "Close the {plane} polygon from its last tip back to its start: a "
                    "closing side is the {plane} left unbalanced; none, and it is balanced.",
    "balance.closed": "The polygon closes on itself, its last tip back on its start: plane "
                      "{plane} needs no balancing mass.",
    "balance.point": "Every mass lies in plane {a}, so each mᵢrᵢlᵢ is zero and the couple "
                     "polygon is a point: plane {plane} needs no balancing mass.",
    "balance.balanced": "The {plane} polygon closes on itself, its last tip back on its start: "
                        "the {plane} is balanced.",
    "balance.cranks": "Draw the end view of the cranks: from the shaft's centre O each "
                      "crank's line at θᵢ, and the secondary (direct) cranks at 2θᵢ.",
    "balance.engine": "The {kind} polygon: lay off each cylinder's vector along its crank at "
                      "{order}, head to tail.",
    "force.centre": "Mark link {link}'s centre of mass G{link} and join it to {k}.",
    "force.image": "On the acceleration polygon, from {start} lay off the normal part "
                   "ω²·{k}G{link} = {n} toward {k}, then the tangential part α·{k}G{link} = "
                   "{t} square to it: g{link}′, the image of G{link}. Link {link}'s inertia "
                   "force is −m·a_G, a_G read from o_a to g{link}′; its inertia couple −I·α "
                   "(the two as one force, offset h = I·α/(m·a_G) = {h} from G{link}).",
    "force.lay": "Lay off {label} = {size} at the force scale, from the last tip.",
    "force.ram": "The ram {r}: lay off its loads head to tail; the slot of link {l} and the "
                 "frame's guide each push it square to themselves.",
    "force.ram_close": "Close the ram's polygon: through its end a line square to the guide, "
                       "through its start a line square to the slot; where they cross gives "
                       "both pushes. Its moments about its pin give the guide's couple.",
    "force.block": "The block {b}: its moments about A give the slot's couple on it; link "
                   "{l}'s moments about {p} give the slot's push, {nu}. Lay off the block's "
                   "loads and that push; the closing side is the crank's force on the block.",
    "force.lever": "Link {l}'s polygon: its loads, the block's push and the ram's, closed by "
                   "the frame's force at {p}.",
    "force.piston": "The piston {j}'s effort, its loads along the line of stroke toward the "
                    "crank: F_P = {effort}. The wall's thrust on it, the part of the guide's "
                    "push square to the stroke: F_N = {thrust}.",
    "force.effort": "Split {name}, the push on the crank pin {a}: through its tail a line "
                    "along the crank {o}{a}, through its head a line square to it; where they "
                    "cross the radial part ends and the tangential part F_T begins. The crank "
                    "effort F_T = {effort} (CCW +), and the turning moment F_T·{o}{a} = "
                    "{moment}.",
    "force.resultant": "Link {i}'s loads add to one force R = {size}: its line runs where R "
                       "alone has their moment about {b}.",
    "force.two_force": "Link {j} carries no load: a two-force member, its pins' forces run "
                       "along {c}{b}.",
    "force.massless_block": "The block {j} carries no load: its guide and its pin {b} push it "
                            "square to the guide, along one line through {b}.",
    "force.concurrent": "Link {i} holds three forces, so their lines meet in one point: X, "
                        "where R's line crosses the output's. The crank's force at {a} runs "
                        "along {a}X.",
    "force.three": "Link {i}'s force polygon: lay off its loads head to tail (their sum is R).",
    "force.close_three": "Close link {i}'s polygon: through its end a parallel to the line of "
                         "link {j}'s push, through its start a parallel to {a}X; where they "
                         "cross gives both forces.",
    "force.leaning": "{what} pushes with friction: its push leans φ = atan μ = {phi} off "
                     "the normal, against the sliding. It pushes from {side}: assumed "
                     "there, the polygon closes with the push on that side.",
    "force.leaning_block": "The block {j} carries no load: its guide's push and its pin {b}'s "
                           "run along one line through {b}, leaned φ = {phi} off the normal to "
                           "the guide, against the sliding.",
    "force.circles": "Friction circles of radius ρ = {rho} at the pins: each pin's force "
                     "touches its circle on the side that resists the turning of one link on "
                     "the other, so each link carries a couple ρ·|F| at each pin against that "
                     "turning. |F| is found by trial, the polygons drawn again with the last "
                     "round's couples until the forces settle ({rounds} rounds); the last "
                     "round is drawn here.",
    "force.resting": "{what} holds link {link} at rest here: link {link} slides on it at "
                     "{share} of the fastest speed on the velocity polygon, within the "
                     "rounding of a zero the polygon reads ({still} of it). Friction has no "
                     "direction at rest, so it takes no side: {name} stands square to it, as "
                     "at an extreme position.",
    "force.resting_pin": "The pin {pin} rests here: link {on} turns on link {by} at {share} "
                         "of the fastest rate on the velocity polygon, within the rounding of "
                         "a zero the polygon reads ({still} of it). Friction has no direction "
                         "at rest, so its friction circle gives no couple.",
    "force.effort_square": "{name}, the push on the crank pin {a}, stands square to the crank "
                           "{o}{a}: all of it is crank effort, F_T = {effort} (CCW +), and "
                           "the turning moment F_T·{o}{a} = {moment}.",
    "force.the_guide": "The guide",
    "force.the_frame_guide": "The frame's guide",
    "force.the_slot": "The slot of link {link}",
    "force.torque": "Link {d}'s moments about {o}: the driving torque T{d} = {torque}.",
    "force.dyad": "The force polygon of links {i} and {j} together: lay off every known load "
                  "on them head to tail (weights, inertia forces, external forces), at the "
                  "force scale.",
    "force.tangential": "{name}ᵗ, the part of {name} square to the line from {pin} to {about}: "
                        "link {link}'s moments about {about} give it (Fᵗ·length = −ΣM); lay it "
                        "off next.",
    "force.close": "Close the polygon of links {i} and {j}: through its end a line along the "
                   "unknown part at the far joint, through its start a line along the coupler; "
                   "where they cross gives both parts, and so each joint force.",
    "force.driver": "Link {d}'s polygon (the crank): its own loads and the pull of link {i} on it, "
                    "closed by the frame's force at {o}; its moments about {o} give the "
                    "driving torque.",
    "gears.locked": "Row 1: lock the whole train, {arm} with it, and turn it +1 "
                    "(counter-clockwise): every member turns +1.",
    "gears.held": "Row 2: hold {arm} and turn {fixed}, the fixed member, −1 turn:",
    "gears.added": "Row 3: add the rows. {fixed} turns +1 − 1 = 0, as it must; each total is "
                   "its member's turns for one turn of the arm.",
    "gears.scaled": "{member}, the input, turns {total} in the total row and {speed} in fact: "
                    "multiply the row by {scale} {unit}.",
    "gears.xy_rows": "The same by x and y: the arm {arm} turns y and member {fixed} turns x "
                     "relative to it, so {rows}.",
    "gears.xy_solved": "Member {fixed} is fixed, so y + x = 0, and member {member} turns "
                       "{speed}: y = {y} {unit}, x = {x} {unit}.",
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
    "equivalent.centres": "{a} and {b} are the centres of curvature of the two profiles in "
                          "contact (links {i} and {j}); the common normal runs through both.",
    "equivalent.link": "They stay {length} apart ({how}), so at this instant the contact acts "
                       "as a link {a}{b} pinned at both centres: the equivalent link, dashed.",
    "equivalent.slot": "The centre {a} of the circle of link {i} stays {r} from the face of "
                       "link {j}, so at this instant the contact acts as a block at {a} running "
                       "in a slot parallel to the face: the equivalent slot, dashed.",
    "apolygon.rolling": "{point}, the point of wheel {link} on the ground, is at rest but "
                        "accelerates toward the centre {centre}: from o_a lay off a_{point} = "
                        "ω{link}²·r = ({omega} rad/s)² × {radius} = {accel} parallel to "
                        "{point}{centre}, toward {centre}; its end is {tip}.",
    "apolygon.rolling_round": "{point}, the point of wheel {link} on the circle, is at rest but "
                              "accelerates toward the centre {centre}: from o_a lay off "
                              "a_{point} = ω{link}²·r·R/(R {op} r) = ({omega} rad/s)² × "
                              "{radius} × {big}/({big} {op} {radius}) = {accel} parallel to "
                              "{point}{centre}, toward {centre}; its end is {tip}.",
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
    "klein.acceleration": "It cuts the line of stroke at N: {o}{c}QN is the acceleration "
                          "polygon turned through 180°, so a_{p} = ω²·N{o}, from N toward {o} "
                          "(a_{c} = ω²·{o}{c}, aⁿ_{p}{c} = ω²·{c}Q, aᵗ_{p}{c} = ω²·QN).",
    "readings.least_velocity": "Drop the perpendicular from {centre} onto {a}{b}: its foot "
                               "{point} is the point of the line nearest {centre}, the slowest "
                               "of link {link}.",
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
    "limits.swing": "With centre {pivot} swing {point} with the lever through the angle "
                    "{held}{pivot}{held_there} to {there}.",
}
