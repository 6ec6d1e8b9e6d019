"""A module binds each of its module-level names once: a constant given again further down
silently changes the first one's every use (the polygon's pole dot was once drawn at the
size of a threshold that reused its name)."""

from __future__ import annotations

import ast
import importlib
from collections import defaultdict
from pathlib import Path

import pytest

from tests.test_doctests import _modules


def _bound_twice(source: str) -> dict[str, list[int]]:
    """Module-level names assigned more than once, with the lines that assign them."""
    lines: dict[str, list[int]] = defaultdict(list)
    for node in ast.parse(source).body:
        targets = node.targets if isinstance(node, ast.Assign) else \
            [node.target] if isinstance(node, ast.AnnAssign) and node.value is not None else []
        for t in targets:
            if isinstance(t, ast.Name):
                lines[t.id].append(node.lineno)
    return {name: at for name, at in lines.items() if len(at) > 1}


@pytest.mark.parametrize("name", _modules())
def test_each_module_level_name_is_bound_once(name):
    path = Path(importlib.import_module(name).__file__)
    assert _bound_twice(path.read_text(encoding="utf-8")) == {}, path


def test_a_name_bound_twice_is_seen():
    assert _bound_twice("_DOT = 0.6\n_ROOM = 16.0\n_DOT = 1.0\n") == {"_DOT": [1, 3]}
