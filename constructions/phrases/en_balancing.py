"""English phrases of the balancing polygons."""

from __future__ import annotations

__all__ = ["PHRASES"]

PHRASES: dict[str, str] = {
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
    "balance.couple.about": "The couple polygon about the reference plane: lay off each "
                            "mᵢrᵢlᵢ, lᵢ from that plane, head to tail, each parallel to its "
                            "mass's radial line (the other way where lᵢ < 0).",
    "balance.force.open": "The force polygon: lay off each known mᵢrᵢ head to tail, each "
                          "parallel to its mass's radial line; what is unknown closes it.",
    "balance.couple.open": "The couple polygon, the plane of {a} the reference (its mass "
                           "drops out): lay off each known mᵢrᵢlᵢ head to tail, lᵢ from that "
                           "plane; what is unknown closes it.",
    "balance.cut": "Cut the carriers of the two unknown vectors (a line along a known "
                   "direction, an arc of a known size) from the last tip and from the start: "
                   "the crossing closes the polygon.",
    "balance.found": "Read mass {mass}'s unknowns off its side: its size gives the mass (or "
                     "radius, or the plane's distance), its direction the angle.",
    "balance.found.product": "Read mass {mass}'s m·r·l off its side (its m·r and plane both "
                             "unknown): its size is the product, its direction the angle, "
                             "to a half turn the force polygon settles.",
    "balance.found.split": "Read mass {mass}'s m·r off its side, its sense settling the half "
                           "turn; its plane is the couple polygon's m·r·l over it: "
                           "l = (m·r·l)/(m·r).",
    "balance.cranks": "Draw the end view of the cranks: from the shaft's centre O each "
                      "crank's line at θᵢ, and the secondary (direct) cranks at 2θᵢ.",
    "balance.engine": "The {kind} polygon: lay off each cylinder's vector along its crank at "
                      "{order}, head to tail.",
}
