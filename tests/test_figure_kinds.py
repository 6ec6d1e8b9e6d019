"""The kinds of figure are one list: FIGURE_KINDS documents them on FigureSpec, graphics
registers a drawing for each, and every FigureSpec the package makes names one of them."""

from __future__ import annotations

import ast
import importlib
from pathlib import Path

import pytest

from tarsim.constructions.checks import FIGURE_KINDS, FigureSpec
from tarsim.graphics.figure_kinds import figure_kind, registered
from tests.test_doctests import _modules


def _kinds_made() -> dict[str, set[str]]:
    """Each kind a ``FigureSpec(...)`` in the package's source names (its fourth argument
    or ``kind=``, else the default), with the modules that make it."""
    default = FigureSpec("stem", "heading").kind
    made: dict[str, set[str]] = {}
    for name in _modules():
        path = Path(importlib.import_module(name).__file__)
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if not (isinstance(node, ast.Call) and getattr(node.func, "id", None) == "FigureSpec"):
                continue
            given = [k.value for k in node.keywords if k.arg == "kind"] + node.args[3:4]
            kind = given[0].value if given and isinstance(given[0], ast.Constant) else (
                default if not given else f"<not a literal in {name}>")
            made.setdefault(kind, set()).add(name)
    return made


def test_every_kind_has_a_drawing_registered_and_nothing_else_is():
    assert sorted(registered()) == sorted(FIGURE_KINDS)


def test_every_figure_spec_made_names_a_documented_kind_and_every_kind_is_made():
    made = _kinds_made()
    assert sorted(made) == sorted(FIGURE_KINDS), made
    # the scan reads the modules it should: the worked page's spec and the force figures'
    assert "tarsim.constructions.linkages.velocity_polygon" in made["polygons"]
    assert "tarsim.constructions.forces.answers" in made["forces"]


def test_the_figure_spec_docstring_lists_every_kind_with_what_it_shows():
    for kind, shows in FIGURE_KINDS.items():
        assert f"* {kind!r}: {shows}." in FigureSpec.__doc__


def test_a_kind_outside_the_list_cannot_be_registered():
    with pytest.raises(ValueError, match="'sketch' is no kind of figure; the kinds are 'scene'"):
        figure_kind("sketch")


def test_a_kind_cannot_be_registered_twice():
    registered()
    with pytest.raises(ValueError, match="'scene' is already registered"):
        figure_kind("scene")
