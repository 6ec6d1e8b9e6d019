"""English phrases of the cams' constructions: the displacement diagram and the profile by
inversion."""

from __future__ import annotations

__all__ = ["PHRASES"]

PHRASES: dict[str, str] = {
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
    "heading.arc_cam": "The cam's dimensions",
    "heading.arc_motion": "The follower's motion on the flank and the nose",
    "cam.parabolic_part": "Segment {k} is uniform acceleration and retardation in unequal "
                          "parts: for its {half} part, divide its share of the lift, {rise}, on "
                          "its {where} ordinate in the ratio 1 : 3 : 5 … {way} by parallels "
                          "from a line marked at 1, 4, 9 … equal steps ({m} of them), and "
                          "project each division across to its ordinate.",
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
}
