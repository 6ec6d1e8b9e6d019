"""English: the words of every step, as the lecture notes and Hinkle's chapter word them.

Each template is :meth:`str.format` text whose fields are the phrase's arguments;
a field that is a clause renders as that clause's own template.
"""

from __future__ import annotations

from . import en_balancing, en_cams, en_forces, en_positions, en_trains, en_velocities

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
    "note.about_pivot": "V_{point} square to {pivot}{point}",
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
    "stroke.events": "a turn at steady speed, its zeros narrowed to the last bit",
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
}


# Each chapter's phrases, kept in a module of the chapter's own.
for _chapter in (en_positions, en_trains, en_cams, en_balancing, en_forces, en_velocities):
    PHRASES.update(_chapter.PHRASES)
