"""Every figure fills at least half its sheet's usable area (the box of its ink over the
sheet less a 10 mm margin round it, :func:`~tarsim.graphics.paper.filled`), or is listed
here with the reason it does not. A figure is drawn at the finest of the course's scales
(1, 2, 2.5, 4, 5 × 10ᵏ to the centimetre) its sheet holds, in every chapter; the circle
diagram and the plots, which have no scale, are drawn to fill the floor."""

from __future__ import annotations

import pytest

from tarsim import solve
from tarsim.constructions.narration import speaking
from tarsim.exercises.catalog import everything, load
from tarsim.graphics.figure import Figure, Path
from tarsim.graphics.paper import filled

FLOOR = 0.5
"""The least share of its sheet's usable area a figure fills."""

TABLE = ("a table: its type is set at the size it is read at, and a sheet is not filled by "
         "setting it bigger")
SIDE = ("a rotor's side view: the planes along the shaft to scale, each drawn 24 mm tall at "
        "any scale, a strip the next finer step runs past the sheet's length")
STRIP = ("a strip to scale along its length (a cam's turn across at its lift's scale, a rod "
         "and its masses along it): the next finer step runs past the sheet's length")
KUTZBACH = ("a velocity diagram's two scales, radius and velocity, grow together, only by as "
            "much as leaves both drafting scales (2, 2.5, 4, 5 or 10 times), and the least "
            "such growth is more than A4 holds")
VELOCITIES = ("its velocities are drawn on the space diagram at a scale of their own, tied to "
              "the space scale the solve chose, which is therefore not grown")
NEXT_STEP = "the next finer of the course's scales draws it bigger than its sheet holds"
STATED = "drawn at the scale its exercise states"
FORCES = ("force polygons at the force scales they state, or loads and free bodies at the "
          "space scale the solve chose (not grown: their force arrows keep their own scale)")
SHEET = "a worked page's sheet: the next panel or the results table does not fit beside these"

EXCEPTIONS: dict[tuple[str, str], str] = {
    # Measured 2026-11-29: the next step's size on A4 given where it was checked.
    ("hinkle-slider-crank", "centres"): NEXT_STEP + " (1 cm = 5 mm: 378 × 164 mm)",
    ("offset-slider-crank", "centres"): NEXT_STEP + " (1 cm = 5 cm: 328 × 183 mm)",
    ("offset-slider-crank", "limits"): NEXT_STEP + " (1 cm = 5 cm: 328 × 183 mm)",
    ("parallelogram-four-bar", "centres"): NEXT_STEP + " (1 cm = 10 mm: 387 × 144 mm)",
    ("six-link-homework-3", "centres"): NEXT_STEP + " (1 cm = 25 mm: 219 × 221 mm)",
    ("wheel-round-circle", "centres"): NEXT_STEP + " (1 cm = 10 mm: 296 × 261 mm)",
    ("grashof-crank-rocker", "limits"): NEXT_STEP + " (1 cm = 5 mm: 324 × 236 mm)",
    ("slotted-lever-p37", "limits"): STATED + " (1 cm = 4 cm)",
    ("klein-slider-crank", "klein"): STATED + " (1 cm = 35 mm)",
    ("rolling-wheel", "worked"): SHEET,
    # Its Persian results stand alone on the third sheet (0.46), set from the right margin
    # under a title that is too: before, measured from that title to the table at the
    # left margin, the box of its ink was the sheet's width.
    ("klein-slider-crank", "worked"): SHEET,
    **{(e, s): VELOCITIES for e, stems in {
        "hinkle-four-bar": ("V_B-components", "V_D-components", "V_E-components"),
        "hinkle-slider-crank": ("V_C-components", "V_C-parallel-line", "V_C-radius-rotation",
                                "V_D-components"),
        "offset-slider-crank": ("V_B-parallel-line", "V_B-radius-rotation"),
        "parallelogram-four-bar": ("V_B-components",),
        "rolling-wheel": ("V_B-components", "V_B-parallel-line", "V_B-radius-rotation",
                          "V_M-components"),
        "wheel-driven-slider": ("V_A-components", "V_A-parallel-line", "V_A-radius-rotation",
                                "V_B-radius-rotation"),
    }.items() for s in stems},
    **{(e, "forces"): FORCES for e in ("crank-shaper-forces", "crank-shaper-inertia",
                                       "double-acting-engine", "engine-forces", "engine-friction",
                                       "engine-gas-pressure", "four-bar-coupler-load",
                                       "four-bar-forces")},
    **{(e, "loads"): FORCES for e in ("double-acting-engine", "engine-forces", "engine-friction",
                                      "engine-gas-pressure", "four-bar-coupler-load")},
    **{(e, "free-bodies"): FORCES for e in ("double-acting-engine", "engine-forces",
                                            "four-bar-coupler-load")},
    **{(e, s): TABLE for s, ids in {
        "table": ("car-differential", "differential-near-equal", "gearbox-power-efficiency",
                  "output-speed-given", "planetary-q1", "planetary-q2", "planetary-q3",
                  "planetary-q4", "planetary-ratio-least-teeth", "ratio-only", "sun-and-planet",
                  "teeth-implied", "two-planets-listed", "two-speeds-arm-and-sun",
                  "bearing-forces", "coupled-locomotive", "four-mass-shaft",
                  "four-masses-one-plane", "locomotive", "notes-example-1",
                  "outside-locomotive", "static-balance-couple-left", "weights-one-plane"),
        "table-trailing": ("coupled-locomotive",),
        "train-value": ("compound-equal-steps", "compound-train", "involute-pair",
                        "ratio-least-teeth", "reverted-train-design", "reverted-two-modules",
                        "shafts-about-circular-pitch", "shafts-apart"),
        "profile-table": ("base-circle-for-pressure-angle", "eccentric-flat-face",
                          "knife-edge-acceleration-ratio", "offset-knife-edge",
                          "oscillating-roller", "roller-harmonic-cycloidal",
                          "valve-unequal-acceleration"),
    }.items() for e in ids},
    **{(e, "side"): SIDE for e in ("bearing-forces", "coupled-locomotive", "four-mass-shaft",
                                   "locomotive", "outside-locomotive", "primary-balance-unknowns",
                                   "static-balance-couple-left", "unknown-angles",
                                   "unknown-plane-and-angle", "unknown-planes")},
    ("coupled-locomotive", "side-trailing"): SIDE,
    **{(e, "displacement"): STRIP for e in (
        "base-circle-for-pressure-angle", "eccentric-flat-face", "knife-edge-acceleration-ratio",
        "offset-knife-edge", "oscillating-roller", "roller-harmonic-cycloidal",
        "valve-unequal-acceleration")},
    ("rod-equivalent-masses", "rod"): STRIP,
    **{(e, "kutzbach"): KUTZBACH for e in ("gearbox-power-efficiency", "output-speed-given",
                                          "teeth-implied", "two-planets-listed",
                                          "two-speeds-arm-and-sun")},
    # The gear trains', cams' and rotors' drawings at the course's scales, on A4.
    ("ratio-least-teeth", "train"): NEXT_STEP,
    ("roller-harmonic-cycloidal", "profile"): NEXT_STEP,
    **{(e, s): NEXT_STEP for s, ids in {
        "space": ("bearing-forces", "coupled-locomotive", "four-mass-shaft", "locomotive",
                  "outside-locomotive", "three-masses-between", "unknown-plane-and-angle",
                  "unknown-planes"),
        "space-trailing": ("coupled-locomotive",),
        "force-polygon": ("coupled-locomotive", "notes-example-1", "static-balance-couple-left",
                          "unknown-angles"),
        "couple-polygon": ("primary-balance-unknowns",),
        "primary-force": ("inline-four", "primary-balance-unknowns"),
        "primary-couple": ("inline-four", "inline-three"),
        "secondary-force": ("inline-four", "two-stroke-four"),
        "secondary-couple": ("inline-four", "inline-three", "two-stroke-four"),
    }.items() for e in ids},
}
"""The figures below the floor, by (exercise, figure stem without its position)."""


def _stem(stem: str) -> str:
    """A figure's stem without the position it is drawn at ("forces-t-2.34s" → "forces")."""
    for tail in ("-t-", "-theta2-"):
        stem = stem.split(tail)[0]
    return stem


def fills(lang: str) -> dict[tuple[str, str, int], tuple[float, str | None]]:
    """Each bundled figure's sheets' fill, by (exercise, stem, sheet), with the reason it may
    fall short: an entry of :data:`EXCEPTIONS`."""
    out = {}
    for exercise_id in everything():
        with speaking(lang):
            done = solve(load(exercise_id))
            # a gear train's, a cam's, a rotor's figures are drawn for their sheet there
            figures = done.sheets() if hasattr(done, "sheets") else done.figures
            for stem, fig in figures.items():
                why = EXCEPTIONS.get((exercise_id, _stem(stem)))
                for k, s in enumerate(fig.sheets or [fig]):
                    out[(exercise_id, stem, k)] = (filled(s), why)
    return out


def test_the_fill_is_the_inks_box_over_the_usable_area():
    half = Figure(210.0, 297.0, [Path(((10.0, 10.0), (200.0, 10.0), (200.0, 148.5),
                                       (10.0, 148.5)), "link", closed=True)])
    assert filled(half) == pytest.approx(0.5, abs=1e-9)


@pytest.mark.slow
def test_every_figure_fills_half_its_sheet_or_says_why():
    # Before: the four-bar's centres filled 0.32 of A4 (1 cm = 50 mm; 40 and 25 untried),
    # the circle diagrams 0.30, the parallelogram four-bar's centres 0.19, the Grashof
    # double-crank's mechanism 0.26.
    short, stale = [], set(EXCEPTIONS)
    for lang in ("en", "fa"):
        for (exercise_id, stem, k), (share, why) in fills(lang).items():
            if share < FLOOR:
                stale.discard((exercise_id, _stem(stem)))
                if why is None:
                    short.append((lang, exercise_id, stem, k, round(share, 2)))
    assert not short, short
    # Each exception still falls short in one language at least: the list only shrinks.
    assert not stale, sorted(stale)


@pytest.mark.slow
def test_the_figures_the_review_named_fill_half_their_sheet():
    got = fills("en")
    for key in (("four-bar", "centres", 0), ("four-bar", "circle-diagram", 0),
                ("grashof-double-crank", "mechanism", 0), ("rolling-wheel", "centres", 0)):
        assert got[key][0] >= FLOOR, (key, got[key][0])
