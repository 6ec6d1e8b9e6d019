"""A joint is a type: each kind is declared once and has one entry in each layer's table.

The kinds (constructions/joint_kinds.py) say how many equations a joint adds; the
reference's table (reference/joint_equations.py) writes those equations, the methods'
(linkages/joint_rules.py) locate, inspect and walk the joint, and the figures'
(graphics/linkages/joint_symbols.py) draw it. These tests hold the tables to the same
kinds and to each other, and run every kind through a real mechanism file.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from tarsim.constructions.joint_kinds import JOINT_KINDS, SlideKind, kind_of
from tarsim.constructions.linkages.joint_rules import JOINT_RULES
from tarsim.constructions.reference.joint_equations import JOINT_EQUATIONS
from tarsim.constructions.reference.loop_equations import _System
from tarsim.exercises.linkages.mechanism_file import load_mechanism
from tarsim.graphics.linkages.joint_symbols import JOINT_SYMBOLS, Drawn

DATA = Path(__file__).parent / "data"
CATALOG = Path(__file__).parents[1] / "exercises" / "catalog"

# One file for each kind of joint (a held wheel rolling round a circle is the catalog's
# wheel-round-circle, one an arm does not hold is wheel-in-ring).
FILES = [CATALOG / "offset-slider-crank.toml", CATALOG / "crank-shaper.toml",
         DATA / "offset-cam.toml", CATALOG / "rolling-wheel.toml", DATA / "curved-slot.toml",
         DATA / "curved-guide-slider-crank.toml", DATA / "roller-cam.toml",
         DATA / "wheel-in-ring.toml", CATALOG / "wheel-round-circle.toml"]


@pytest.mark.parametrize("table", [JOINT_EQUATIONS, JOINT_RULES, JOINT_SYMBOLS],
                         ids=["reference", "methods", "figures"])
def test_every_layer_has_one_entry_per_kind(table):
    assert set(table) == set(JOINT_KINDS)


def test_a_kind_is_told_by_its_fields():
    for key, k in JOINT_KINDS.items():
        assert kind_of(k.shape, k.slide, k.contact, k.rolling).key == key


def test_the_reference_writes_as_many_equations_as_grubler_counts():
    # Two equations make a lower pair (F1), one a higher pair (F2): the loop equations and
    # the mobility must count a joint alike, or the Jacobian is not square at DOF 1.
    for key, k in JOINT_KINDS.items():
        assert len(JOINT_EQUATIONS[key].rows) == k.constraints, key


def test_a_contact_is_drawn_and_touches_as_one():
    for key, k in JOINT_KINDS.items():
        symbol, rules = JOINT_SYMBOLS[key], JOINT_RULES[key]
        assert (symbol.drawn in (Drawn.FACE, Drawn.CIRCLES)) == k.contact, key
        assert (rules.touch is not None) == k.contact, key
        assert (rules.rolling is not None) == k.rolling == symbol.ground, key
        assert symbol.block == (k.slide is SlideKind.BLOCK), key
        assert (symbol.drawn in (Drawn.GUIDE, Drawn.FACE)) == (k.shape == "line"), key


def test_the_files_hold_every_kind():
    kinds = {j.type.key for f in FILES for m in [load_mechanism(f)]
             for j in (*m.slides, *m.arcs)}
    assert kinds == set(JOINT_KINDS)


@pytest.mark.parametrize("path", FILES, ids=lambda p: p.stem)
def test_the_loop_equations_are_square_on_each_kind(path):
    # One degree of freedom: with the input's row, as many equations as body coordinates.
    m = load_mechanism(path)
    dof, n, f1, f2 = m.mobility()
    assert dof == 1
    system = _System(m)
    assert len(system.is_len) == 3 * (n - 1)
    rows = 2 * f1 + f2 + 1       # every pin and lower pair two rows, a higher pair one, the input
    assert len(system.is_len) == rows
