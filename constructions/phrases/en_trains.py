"""English phrases of the gear trains' constructions: the tabular method, the train value, the
Kutzbach diagram and the involute mesh."""

from __future__ import annotations

__all__ = ["PHRASES"]

PHRASES: dict[str, str] = {
    "gears.ordinary_start": "{member}, the input, turns {speed}. Carry one turn of it through "
                            "the meshes:",
    "gears.ordinary_turn": "{member} is the input; no speed is given, and none is needed for "
                           "a ratio. Carry one turn of it through the meshes:",
    "gears.over_input": "{member}, the input, turns {total} in the total row: each total "
                        "over {total} is its member's speed over ω{i}.",
    "gears.held_given": "Row 2: hold {arm} and turn {member} −1 turn:",
    "gears.two_given": "Each member turns y·(row 1) + x·(row 2), y the arm's speed. The two "
                       "given speeds: ω{a} = y + ({ha})·x = {sa} and ω{b} = y + ({hb})·x = "
                       "{sb}, so x = {x} {unit} and y = {y} {unit}.",
    "gears.power_efficiency": "The input is driven by {given}. The output takes η = {eta} of "
                              "its power: T{o}·ω{o} = −η·T{i}·ω{i}, so T{o} = −η·T{i}·ω{i}/ω{o} "
                              "= −{eta} × T{i} × {ratio} = {value} N·m (counter-clockwise +).",
    "gears.power_two": "The input is driven by {given}, and member {h} turns too. The torques "
                       "sum to zero, T{i} + T{o} + T{h} = 0, and so do the powers but for the "
                       "losses, {eta}·T{i}·ω{i} + T{o}·ω{o} + T{h}·ω{h} = 0, so T{o} = "
                       "T{i}·(ω{h} − {eta}·ω{i})/(ω{o} − ω{h}) = {value} N·m "
                       "(counter-clockwise +).",
    "gears.power_in": "The power member {m} puts in: P{m} = |T{m}|·{rpm}|ω{m}| = {t} × "
                      "{rpm}{w} = {value} W.",
    "gears.power_out": "The power member {m} takes out: P{m} = |T{m}|·{rpm}|ω{m}| = {t} × "
                       "{rpm}{w} = {value} W.",
    "gears.holding_two": "Member {fixed} takes the rest: T{fixed} = −(T{i} + T{o}) = {value} "
                         "N·m.",
    "gears.road_car": "The car runs at v = {kmh} km/h = {v} m/s round a curve of mean radius "
                      "R = {R} {unit}, its track t = {t} {unit} and its road wheels {d} {unit} "
                      "across (r = {r} m): it turns about the curve's centre at v/R, so a road "
                      "wheel whose path has radius ρ rolls at v·ρ/R.",
    "gears.road_outer": "The outer road wheel, on member {n}, runs round R + t/2 = {path} "
                        "{unit}: ω{n} = v·(R + t/2)/(R·r) {about}{w} {speed} {sense}, the first "
                        "given speed.",
    "gears.road_inner": "The inner road wheel, on member {n}, runs round R − t/2 = {path} "
                        "{unit}: ω{n} = v·(R − t/2)/(R·r) {about}{w} {speed} {sense}, the second "
                        "given speed.",
    "gears.teeth_diameter": "Gear {n}'s teeth from its pitch diameter and module: N{n} = d/m "
                            "= {d}/{m} = {teeth}.",
    "gears.teeth_distance": "Gear {n}'s teeth from its pair's centre distance and module, "
                            "{equation}: N{n} = {teeth}.",
    "gears.teeth_coaxial": "{gear}: the coaxial condition, the two pairs equally far apart, "
                           "{equation}, gives N{n} = {teeth}.",
    "gears.teeth_chain": "{gear}: the coaxial condition through the planets in series, the "
                         "last planet's centre as far out along its chain as in from the "
                         "ring, {equation}, gives N{n} = {teeth}.",
    "gears.twin": "Gear {copy} is a planet like gear {first}: the same teeth, the same meshes, "
                  "on the same arm. It turns as gear {first} does; the two are {n} planets, "
                  "equally spaced, and the speeds are those of one.",
    "gears.uncoaxial": "The planet meshes gear {c0} {r0} modules from the main axis "
                       "and gear {c} {r} modules from it: with no sizes given, the book's "
                       "gears differ in module there (or are corrected), and the speeds follow "
                       "from the teeth alone.",
    "gears.teeth_ratio": "The speed ratio the book gives, |ω{x}/ω{y}| = {value}, is {expr} "
                         "through the meshes: N{g} = {teeth}.",
    "gears.teeth_ratio_table": "The speed ratio the book gives, |ω{x}/ω{y}| = {value}, is "
                               "{expr} through the train with N{g} unknown (each mesh N or "
                               "1/N, a count the coaxial condition or a centre distance ties "
                               "to N{g} written through it): N{g} = {teeth}.",
    "gears.teeth_least_set": "Gear {g}, the smallest of the gears left unknown, takes the "
                             "least count, {least} teeth, or the fewest above it that make "
                             "the others whole: N{g} = {teeth}.",
    "gears.equal_steps": "The book shares |ω{x}/ω{y}| = {value} in {k} equal steps, one a "
                         "pair between them: each pair's ratio is {value}^(1/{k}) = {root} "
                         "({pairs}).",
    "gears.about_teeth": "Gears {a} and {b} stand about {about} apart and |ω{x}/ω{y}| = "
                         "{value}: d{g} {sign} d{s} = 2·{about} with d{g} = {k}·d{s}, so d{s} "
                         "= {d}, and N{s} = {count}: {rounded}.",
    "gears.about_up": "take the next whole count up, N{n} = {teeth}",
    "gears.about_least": "the least count, {least}, is more than that: N{n} = {least}",
    "gears.about_exact": "Gears {a} and {b} then stand exactly {equation} = {distance} apart.",
    "gears.teeth_least": "Gear {g}, the smaller of the pair, takes the least count, {least} "
                         "teeth, or the fewest above it that make the other whole: N{g} = "
                         "{teeth}.",
    "gears.mesh_carries": "{driven} meshes {kind}ly with {driver}, so it turns {way}, "
                          "N{a}/N{b} = {na}/{nb} as fast: {turns} → {result}.",
    "gears.bevel_carries": "{driven} meshes with {driver} through bevel teeth, their axes "
                           "square, so it is taken to turn {way} (on fixed axes each the way "
                           "the book calls forward; about a bevel planet the gears either "
                           "side turn opposite ways relative to the arm), N{a}/N{b} = "
                           "{na}/{nb} as fast: {turns} → {result}.",
    "gears.shaft_carries": "{member} is on one shaft with {other}: it turns alike, {turns}.",
    "gears.fixed": ", fixed",
    "gears.held_planet": ", held from turning (fast to a rod that keeps its direction, as in "
                         "the sun-and-planet gear) while the arm carries it round",
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
    "kutzbach.two_given": "No member is fixed: the two given speeds each give a line through "
                          "O, {a}'s and {b}'s, and every other line follows from them.",
    "kutzbach.read_ratio": "Read ω{member} = Δv/Δr, the slope of its line: {omega} rad/s"
                           "{sense}, drawn for the input at 1 {unit} (no speed is given): "
                           "over the input's slope, ω{member}/ω{i} = {ratio}.",
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
    "gears.meshes_bevel": "Gears {a} and {b} mesh through bevel teeth, their axes square.",
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
}
