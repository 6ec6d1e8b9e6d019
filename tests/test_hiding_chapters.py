"""``--hide answers`` in the chapters beyond the linkages: the numbers each solution found
leave its gear, cam and balancing figures, and the data the exercise gave stay."""

from __future__ import annotations

import re

import pytest

import tarsim
from tarsim.constructions.narration import speaking
from tarsim.graphics.hiding import hiding
from tarsim.graphics.svg import to_svg

pytestmark = pytest.mark.slow


def _texts(name: str, stem: str, hide: frozenset[str] = frozenset()) -> list[str]:
    """The texts of one figure of a bundled exercise, as its SVG sets them."""
    with speaking("en"), hiding(hide):
        fig = tarsim.solve(tarsim.load(name)).figures[stem]
        svg = to_svg(fig)
    return [re.sub(r"<[^>]+>", "", t) for t in re.findall(r"<text\b[^>]*>(.*?)</text>", svg, re.S)]


ANSWERS = frozenset({"answers"})


def test_a_trains_found_speeds_leave_its_table_and_the_given_speed_stays():
    # compound-train: gear 2 driven at −900 rpm (given), gear 6 found at 100 rpm
    # (−900 × the train value −1/9), the idler 5 at −187.5 rpm.
    shown = _texts("compound-train", "train-value")
    bare = _texts("compound-train", "train-value", ANSWERS)
    assert {"−900", "100", "−187.5"} <= set(shown)
    assert "−900" in bare
    assert not {"100", "−187.5", "300"} & set(bare)


def test_a_planetary_tables_work_leaves_and_its_locked_row_and_givens_stay():
    # planetary-q1: the ring fixed (0), the sun at −80 rpm given; the arm found at −24 × …
    shown = _texts("planetary-q1", "table")
    bare = _texts("planetary-q1", "table", ANSWERS)
    assert bare.count("+1") == 4                     # the locked row, one per member
    assert shown.count("+1") > 4                     # and a +1 of the work below it
    assert {"0", "−80"} <= set(bare)
    assert len(shown) - len(bare) >= 4 + 4 + 2   # the held row, the total, two speeds


def test_teeth_found_in_brackets_are_hidden_and_the_given_teeth_stay():
    shown = _texts("compound-equal-steps", "train-value")
    bare = _texts("compound-equal-steps", "train-value", ANSWERS)
    found = [t for t in shown if re.fullmatch(r"\(\d+\)", t)]
    assert found == ["(16)", "(96)", "(16)", "(96)"]
    assert not [t for t in bare if re.fullmatch(r"\(\d+\)", t)]


def test_a_balancing_mass_found_leaves_the_table_the_end_view_and_the_polygon():
    # four-masses-one-plane: B at the stated 0.2 m is found as 116.1 kg at 201.31°
    # (m·r = 23.22 kg·m), the four given masses' rows unchanged.
    table = _texts("four-masses-one-plane", "table", ANSWERS)
    assert not {"116.1", "201.31°", "23.22"} & set(table)
    assert {"200", "300", "240", "260", "255°", "78"} <= set(table)
    assert table.count("0.2") == 2                 # mass 1's radius, and B's as given
    space = _texts("four-masses-one-plane", "space", ANSWERS)
    assert "B" in space and not [t for t in space if "116.1" in t]
    assert "1: 200 kg at 0.2 m, 0°" in space


def test_an_unknown_angle_is_a_gap_beside_the_given_mass_and_radius():
    shown = _texts("unknown-angles", "space")
    bare = _texts("unknown-angles", "space", ANSWERS)
    assert "C: 5 kg at 200 mm, 242.3°" in shown
    assert "C: 5 kg at 200 mm, …°" in bare
    assert "A: … kg at 100 mm, …°" in bare         # A's mass and angle both found
    assert "B: 10 kg at 125 mm, 0°" in bare        # B's wholly given


def test_a_cams_table_keeps_its_stations_and_angles_only():
    shown = _texts("offset-knife-edge", "profile-table")
    bare = _texts("offset-knife-edge", "profile-table", ANSWERS)
    assert "−14.48°" in shown and "170.3" in shown
    stations = [str(k) for k in range(16)]
    angles = [t for t in shown if t.endswith("°") and not t.startswith(("−", "0.", "1", "2",
                                                                         "3", "4", "5", "6",
                                                                         "7", "8", "9"))]
    assert angles == ["0°"]                          # the first cam angle; the rest start 1–9
    assert not {"−14.48°", "170.3", "2.222", "−34.58°"} & set(bare)
    assert set(stations) <= set(bare)
    assert {"20°", "195°", "270°"} <= set(bare)      # cam angles stay
    profile = _texts("offset-knife-edge", "profile", ANSWERS)
    assert not [t for t in profile if t.startswith("φ max")]
    velocity = _texts("offset-knife-edge", "velocity", ANSWERS)
    assert not {"960", "−640"} & set(velocity)       # the segments' peaks, mm/s


def test_an_involute_pairs_path_and_contact_ratio_leave_its_caption():
    shown = _texts("involute-pair", "mesh")
    bare = _texts("involute-pair", "mesh", ANSWERS)
    assert "path of contact AB = 48.27 mm, contact ratio 1.635" in shown
    assert not [t for t in bare if "contact ratio" in t]
    assert "module 10 mm, 20 and 40 teeth, pressure angle 20°" in bare


def test_a_flywheels_mean_areas_and_energy_leave_its_diagram():
    # punching-press: T_mean = 1000 N·m (the motor's, asked), the two areas ±5236 J, ΔE
    shown = _texts("punching-press", "turning-moment")
    bare = _texts("punching-press", "turning-moment", ANSWERS)
    assert {"+5236 J", "−5236 J", "mean 1000 N·m"} <= set(shown)
    assert not [t for t in bare if "5236" in t or "1000 N" in t]
    assert "mean … N·m" in bare
    assert {"0", "6000"} <= set(bare)                 # the given torque's axis stays


def test_a_flywheel_given_by_its_speeds_keeps_them_and_hides_the_energies():
    shown = _texts("flywheel-between-speeds", "energy")
    bare = _texts("flywheel-between-speeds", "energy", ANSWERS)
    assert "E1 = 789.6 kJ" in shown                   # ½·3600·(200·2π/60)² = 789.6 kJ
    assert not [t for t in bare if "789.6" in t or "758.3" in t or "31267" in t]
    assert {"E1 = … kJ", "E2 = … kJ"} <= set(bare)


def test_a_rods_equivalent_masses_and_couple_leave_its_figure():
    shown = _texts("rod-equivalent-masses", "rod")
    bare = _texts("rod-equivalent-masses", "rod", ANSWERS)
    # 3 kg × 140.833/260.833 = 1.62 kg at P; l2 = k²/l1 = 130²/120 = 140.833 mm
    assert {"1.62 kg", "1.38 kg", "140.833 mm", "1.8 kg", "1.2 kg"} <= set(shown)
    assert not {"1.62 kg", "1.38 kg", "140.833 mm", "1.8 kg", "1.2 kg"} & set(bare)
    assert not [t for t in bare if t.startswith("correction couple")]
    assert {"120 mm", "180 mm", "m = 3 kg, k = 130 mm"} <= set(bare)   # the rod as given


def test_an_engines_unbalanced_reading_leaves_its_polygon():
    shown = _texts("inline-four", "secondary-force")
    bare = _texts("inline-four", "secondary-force", ANSWERS)
    assert [t for t in shown if "unbalanced" in t]
    assert not [t for t in bare if "unbalanced" in t]


def test_the_loads_too_small_to_draw_are_named_without_their_sizes():
    shown = _texts("crank-shaper-forces", "loads-theta2-90")
    bare = _texts("crank-shaper-forces", "loads-theta2-90", ANSWERS)
    assert [t for t in shown if "Fi2 = 0.107 N on link 2" in t]
    note = " ".join(t for t in bare if "on link" in t or "Too small" in t)
    assert "Fi2 = … on link 2" in note and "0.107" not in note
