"""English phrases of the force analysis: the inertia loads, the force polygons and the turning
moment."""

from __future__ import annotations

__all__ = ["PHRASES"]

PHRASES: dict[str, str] = {
    "force.pendulum": "Link {link}, hung from {about} (h = {h} from G{link} to it), swings "
                      "as a compound pendulum in T = {period}: T = 2π·√((k² + h²)/(g·h)), so "
                      "its radius of gyration about G{link} is k = √(g·h·T²/(4π²) − h²) = {k} "
                      "and I = m·k² = {inertia}.",
    "force.pendulum_knife": "Link {link}, hung on a knife edge in the bore at {about}, swings "
                            "about the bore's top (h = {h} from G{link}, the pin's distance "
                            "and half the bore) as a compound pendulum in T = {period}: T = "
                            "2π·√((k² + h²)/(g·h)), so its radius of gyration about G{link} is "
                            "k = √(g·h·T²/(4π²) − h²) = {k} and I = m·k² = {inertia}.",
    "force.flywheel": "The flywheel, I = {inertia}, against the mean resisting torque "
                      "T_mean = {mean}: its angular acceleration α = (T − T_mean)/I = "
                      "{alpha}, T = {torque} the turning moment along the rotation (+ the "
                      "shaft speeding up).",
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
                    "crank: F_P = {effort}, the reciprocating parts' inertia force F_I = "
                    "{inertia} (m·a toward the crank) taken off. The wall's thrust on it, the "
                    "part of the guide's push square to the stroke: F_N = {thrust}.",
    "force.effort": "Split {name}, the push on the crank pin {a}: through its tail a line "
                    "along the crank {o}{a}, through its head a line square to it; where they "
                    "cross the radial part ends and the tangential part F_T begins. The crank "
                    "effort F_T = {effort} (CCW +), and the turning moment F_T·{o}{a} = "
                    "{moment}; the radial part, the thrust on the shaft's bearings, F_R = "
                    "{radial} (+ toward the shaft).",
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
                           "the turning moment F_T·{o}{a} = {moment}; the bearings take no "
                           "thrust along it, F_R = {radial}.",
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
}
