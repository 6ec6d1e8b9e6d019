"""A cam's profile solved: laid out by inversion, held to the closed form, surveyed.

The part of a cam solution that is the cam itself rather than its follower's motion: the
layout figure, the table of pressure angle and curvature at each station, the steps of
the layout, and its numbers for the command line and ``results.json``. A roller that
undercuts, or a flat face on a concave profile, is refused in one line naming the cam
angle, unless the caller allows it, when the figure marks it.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property

from tarsim.constructions.cams.displacement import Displacement
from tarsim.constructions.cams.inversion import Layout, lay_out_profile
from tarsim.constructions.cams.rounding import lift_bounds
from tarsim.constructions.cams.survey import Survey, Undercut, survey
from tarsim.constructions.errors import InputError
from tarsim.constructions.reference.cam_profile import Station
from tarsim.constructions.narration import Word, numeral, numerals, phrase, unit_words, words
from tarsim.graphics.cams.cam_layout_figure import draw_cam_layout
from tarsim.graphics.figure import Figure
from tarsim.graphics.hiding import shown_answer
from tarsim.graphics.train_table import draw_train_table
from ..checked import Checked
from ..worked_document import Bullets, Section, numbered
from .cam_file import CamExercise

__all__ = ["CamProfile", "refuse_undercut"]


@dataclass(frozen=True)
class CamProfile:
    """The layout of ``exercise``'s cam from its displacement ``diagram``."""

    exercise: CamExercise
    diagram: Displacement

    @cached_property
    def layout(self) -> Layout:
        """The layout by inversion."""
        ex = self.exercise
        return lay_out_profile(self.diagram, ex.base_radius, ex.follower, ex.sigma)

    @cached_property
    def survey(self) -> Survey:
        """The closed form round the turn, and the layout's misses from it."""
        ex = self.exercise
        return survey(self.layout, ex.base_radius, ex.segments, ex.sigma,
                      lift_bounds(self.diagram, ex.segments))

    @property
    def passed(self) -> bool:
        """Every station of the layout where the closed form puts it."""
        return not self.survey.misses

    # ----- words ----------------------------------------------------------------------------
    def length_text(self, v: float) -> str:
        """A length (m) in the file's unit."""
        return f"{v / self.exercise.metre:.4g} {self.exercise.length_unit}"

    def lines(self) -> list[str]:
        """What the command line prints of the profile, and steps.md lists, in the language
        spoken."""
        s, f = self.survey, self.exercise.follower
        out = []

        def deg(angle: float) -> str:
            return numeral(math.degrees(angle), ".2f")

        def length(v: float) -> str:
            return numerals(_signed(self.length_text(v)))
        if f.kind == "roller":
            ex = self.exercise

            def full(v: float) -> str:                  # as the peaks are printed
                return f"{numeral(v / ex.metre, '.6g')} {ex.length_unit}"
            out.append(words("the prime circle: radius {rp} (the base circle's {rb} and the "
                             "roller's {r})", rp=full(ex.base_radius + f.radius),
                             rb=full(ex.base_radius), r=full(f.radius)))
        if f.kind != "flat-faced":
            at = s.steepest_at
            steep = abs(math.degrees(at.station.pressure_angle))
            out.append(words("pressure angle: greatest {angle}° at θ = {theta}° (segment {k})",
                             angle=numeral(steep, ".2f"), theta=deg(at.station.theta),
                             k=numeral(at.segment, "d")) + (
                words(" (over the 30° a translating follower is usually held to)")
                if steep > 30 and not f.oscillating else ""))
            out += [words("segment {k} ({kind}): greatest pressure angle {angle}° at θ = "
                          "{theta}°", k=numeral(k, "d"), kind=Word(kind),
                          angle=numeral(math.degrees(abs(top.pressure_angle)), ".2f"),
                          theta=deg(top.theta))
                    for k, kind, top in self.steepest_each]
        at = s.sharpest_at
        out.append(words("the profile's least radius of curvature: {rho} at θ = {theta}° "
                         "(segment {k})" if f.kind == "flat-faced" else
                         "the pitch curve's least radius of curvature: {rho} at θ = {theta}° "
                         "(segment {k})", rho=length(at.station.rho),
                         theta=deg(at.station.theta), k=numeral(at.segment, "d")) + (
            words(" (the roller's radius is {radius})", radius=length(f.radius))
            if f.kind == "roller" else ""))
        if f.kind == "flat-faced":
            lo, hi = s.face
            out.append(words("the face is touched from {lo} to {hi} along it from the "
                             "follower's axis: a face at least {width} wide",
                             lo=length(lo), hi=length(hi), width=length(hi - lo)))
        for span in s.undercut:
            out.append(words("UNDERCUT from θ = {start}° to {end}°, worst in segment {k} "
                             "(marked on the layout)", start=_degrees(span.start),
                             end=_degrees(span.end), k=numeral(span.segment, "d")))
        worst = max((m for _, m in s.misses), default=0.0)
        verdict = words("each where the closed form puts it") if not s.misses else \
            f"OFF by {worst:.1e} m"
        out.append(words("profile by inversion: {n} stations laid out, {verdict}",
                         n=numeral(len(self.layout.places), "d"), verdict=verdict))
        return out

    def section(self) -> Section:
        """steps.md's part of the profile: the layout's acts, numbered, the closing curve
        last, then its readings (the lines solve prints)."""
        layout = self.layout
        return Section(phrase("heading.profile"), (
            numbered([*(st for st in layout.construction if st.phrase is not None),
                      layout.closing]), Bullets(tuple(self.lines()))),
            ("profile", "profile-table"))

    # ----- numbers ----------------------------------------------------------------------------
    def checked(self) -> dict[str, Checked]:
        """The profile's numbers for results.json, in SI (angles in rad)."""
        s, f = self.survey, self.exercise.follower
        out: dict[str, Checked] = {}
        if f.kind != "flat-faced":
            st = s.steepest
            m = _textbook_pressure(self.exercise, s.steepest_at.segment, st.theta)
            # The textbook's value follows the method here, as results.json has always
            # written it.
            out["pressure_angle_max"] = Checked(
                _angle(st.pressure_angle) | {"theta": st.theta,
                                             "segment": s.steepest_at.segment},
                method="inversion; normal to the pitch curve against the follower's motion",
                beside={"reference": {"value": abs(m), "method": "tan φ = (y′ − σe)/(s₀ + y)"}}
                if m is not None else {})
            out |= self._steepest_each()
        if f.kind == "roller":
            out["prime_radius"] = self._prime()
        st = s.sharpest
        out["rho_min"] = Checked({"value": st.rho, "theta": st.theta,
                                  "segment": s.sharpest_at.segment},
                                 method="r_b + y + y″" if f.kind == "flat-faced"
                                 else "|q₁|³ / (−σ q₁ × q₂) of the pitch curve")
        if f.kind == "flat-faced":
            lo, hi = s.face
            out["face_width"] = Checked({"value": hi - lo, "from": lo, "to": hi},
                                        method="the touch's run x = σy′ along the face")
        out["undercut"] = Checked({"value": bool(s.undercut), "spans": [
            {"from": span.start, "to": span.end, "segment": span.segment,
             "rho": span.worst.rho, "theta": span.worst.theta} for span in s.undercut]})
        return out

    @cached_property
    def steepest_each(self) -> list[tuple[int, str, Station]]:
        """Each moving segment's station of greatest pressure angle, found between samples,
        as (segment from 1, its kind, the station): the books ask it of the outstroke and
        the return apart."""
        from tarsim.constructions.cams.extremes import highest
        out = []
        for k, seg in enumerate(self.exercise.segments, start=1):
            scans = [sc for sc in self.survey.scans if sc.piece.segment == k]
            if seg.kind != "dwell" and scans:
                out.append((k, seg.kind,
                            highest(scans, lambda st: abs(st.pressure_angle)).station))
        return out

    def _prime(self) -> Checked:
        """The prime circle's radius, r_b + r, beside the nearest the layout's roller
        centres come to the cam's centre: the stations at no lift stand on the prime circle,
        and the lift only takes the roller away. The acts round to a few parts in 10¹⁶ of
        the layout's size; 10⁻¹² of the radius leaves a wide margin and still fails a roller
        left out or counted twice."""
        ex, layout = self.exercise, self.layout
        want = ex.base_radius + ex.follower.radius
        c = layout.construction
        near = min(math.hypot(*c.output(p.trace).xy) for p in layout.places)
        miss = abs(near - want) / want
        return Checked({"value": want}, {"value": near}, rel_error=miss, tolerance=_PRIME,
                       passed=miss <= _PRIME, method="r_b + r; the layout's nearest roller "
                       "centre to the cam's centre")

    def _steepest_each(self) -> dict[str, Checked]:
        """Each moving segment's greatest pressure angle, ``pressure_angle_max_k``, in
        results.json's rows."""
        out = {}
        for k, _, top in self.steepest_each:
            m = _textbook_pressure(self.exercise, k, top.theta)
            out[f"pressure_angle_max_{k}"] = Checked(
                _angle(top.pressure_angle) | {"theta": top.theta},
                method="inversion; normal to the pitch curve against the follower's motion",
                beside={"reference": {"value": abs(m), "method": "tan φ = (y′ − σe)/(s₀ + y)"}}
                if m is not None else {})
        return out

    # ----- figures ----------------------------------------------------------------------------
    def figures(self) -> dict[str, Figure]:
        """The layout and its table."""
        ex = self.exercise
        notes = [words("UNDERCUT in segment {k} from θ = {start}° to {end}°: ringed where the "
                       "follower cannot make the profile", k=numeral(span.segment, "d"),
                       start=_degrees(span.start), end=_degrees(span.end))
                 for span in self.survey.undercut]
        return {"profile": draw_cam_layout(self.layout, self.survey,
                                           words("{name}: profile", name=ex.name),
                                           ex.length_unit, ex.metre,
                                           notes),
                "profile-table": self.table()}

    def table(self) -> Figure:
        """The pressure angle (or a flat face's run) and the curvature at each station."""
        ex, f = self.exercise, self.exercise.follower
        flat, unit = f.kind == "flat-faced", ex.length_unit
        metre = ex.metre

        def length(v: float) -> str:
            return _signed(f"{v / metre:.4g}" if abs(v) > 1e-9 * ex.base_radius else "0")
        said = unit_words(unit)
        heads = [words("station"), words("cam angle"),
                 words("swing (°)") if f.oscillating else words("lift ({unit})", unit=said),
                 words("face run ({unit})", unit=said) if flat else words("pressure angle"),
                 words(f"ρ of the {'profile' if flat else 'pitch curve'} ({{unit}})",
                       unit=said)]
        rows = []
        for p, st in zip(self.layout.places, self.survey.places):
            lift = (f"{math.degrees(p.lift / f.arm):.4g}" if f.oscillating else length(p.lift))
            # the station and its angle are the drawing's grid; the rest is found
            rows.append(("", [numerals(c) for c in (
                str(p.number), f"{math.degrees(p.theta):.4g}°", *map(shown_answer, (
                    lift, length(st.face_offset) if flat
                    else _signed(f"{math.degrees(st.pressure_angle):.2f}") + "°",
                    "∞" if math.isinf(st.rho) else length(st.rho))))]))
        notes = []
        if any(st.rho < 0 for st in self.survey.places):
            notes.append(words("ρ < {zero}: the curve is concave there.", zero=numerals("0")))
        if flat:
            notes.append(words("The face run is where the face touches, from the follower's "
                               "axis: σy′, σ = +1 for a counter-clockwise cam."))
        elif f.oscillating:
            notes.append(words("The pressure angle is between the profile's normal and the "
                               "roller's path, square to the arm."))
        else:
            notes.append(words("The pressure angle is signed as tan φ = (y′ − σe)/(s₀ + y): "
                               "σ = +1 for a counter-clockwise cam, e the offset, "
                               "s₀ = √(R_p² − e²)."))
        notes.append(words("At a join of two segments the values are the second segment's."))
        what = "face run" if flat else "pressure angle"
        # Right to left, the table mirrors itself (its columns from the right, its words
        # flush right).
        return draw_train_table(words("{name}: " + what + " and curvature", name=ex.name),
                                heads, rows, notes=notes)


_PRIME = 1e-12
"""How far (relative) the layout's nearest roller centre may stand from r_b + r (see
:meth:`CamProfile._prime`)."""


def _angle(angle: float) -> dict[str, float | str]:
    """A pressure angle's size as results.json gives it: in rad (SI, the contract), with its
    degrees beside it, as the books ask it."""
    return {"value": abs(angle), "unit": "rad", "deg": math.degrees(abs(angle))}


def _degrees(angle: float) -> str:
    """A cam angle (rad) in degrees to two places, past 360° said from 0° again."""
    return numeral(math.degrees(angle - 2 * math.pi if angle > 2 * math.pi else angle), ".2f")


def _signed(text: str) -> str:
    """A printed number with a true minus, and no minus on a zero."""
    return "0" + text[2:] if text.startswith("-0") and not text.strip("-0.") else \
        text.replace("-", "−")


def _textbook_pressure(ex: CamExercise, segment: int, theta: float) -> float | None:
    """The textbook's formula for a translating follower (None for an oscillating one), at
    ``theta`` in ``segment`` (from 1): that segment's own law, at its ends too."""
    from tarsim.constructions.cams.extremes import pieces
    from tarsim.constructions.reference.cam_profile import pressure_angle_translating

    if ex.follower.oscillating:
        return None
    inside = [p for p in pieces(ex.segments) if p.segment == segment]
    p = min(inside, key=lambda p: max(p.start + p.t0 - theta, theta - p.start - p.t1, 0.0))
    m = p.motion(theta - p.start)
    return pressure_angle_translating(m.y, m.y1, ex.base_radius, ex.follower, ex.sigma)


def refuse_undercut(profile: CamProfile) -> None:
    """Raise if the follower cannot make the profile.

    Raises
    ------
    InputError
        Naming the segment, the cam angle and the radius there, and what to change.
    """
    s, f = profile.survey, profile.exercise.follower
    if not s.undercut:
        return
    worst: Undercut = min(s.undercut, key=lambda span: span.worst.rho)
    st, text = worst.worst, profile.length_text
    at = f"segment {worst.segment} at θ = {math.degrees(st.theta):.2f}°"
    if f.kind == "roller":
        raise InputError(f"the roller (radius {text(f.radius)}) undercuts the cam in {at}, "
                         f"where the pitch curve's radius is {text(st.rho)}; use a smaller "
                         "roller, a larger base circle or a gentler segment, or "
                         "--allow-undercut to draw it marked")
    raise InputError(f"the flat face meets a concave profile in {at} (radius of curvature "
                     f"{text(st.rho)}): a flat face cannot follow it; use a larger base "
                     "circle or a gentler law, or --allow-undercut to draw it marked")
