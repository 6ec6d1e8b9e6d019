"""The layers' import rules, read off the installed modules' source.

* Dependencies point one way: exercises → graphics → constructions.
* The analytic reference imports no method: only the mechanism model, the errors
  and itself, so a check can never agree with a construction because they share a
  mistake.
* constructions needs nothing outside the standard library but numpy.
* Only the command line (cli and cli_common) imports click; cairosvg is imported lazily,
  inside the function that makes a PDF or PNG, so SVG output needs no system library.
"""

from __future__ import annotations

import ast
import importlib
import importlib.util
import sys
from pathlib import Path

import pytest

from tests.test_doctests import _modules

MODULES = _modules()


def _imports(name: str) -> list[tuple[str, bool]]:
    """(absolute module, at top level?) for every import in module ``name``."""
    module = importlib.import_module(name)
    tree = ast.parse(Path(module.__file__).read_text(encoding="utf-8"))
    package = name if Path(module.__file__).name == "__init__.py" else name.rpartition(".")[0]
    top = {id(n) for n in tree.body}
    out = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            out += [(a.name, id(node) in top) for a in node.names]
        elif isinstance(node, ast.ImportFrom):
            base = package.split(".")
            if node.level:
                base = base[:len(base) - node.level + 1]
                target = ".".join(base + ([node.module] if node.module else []))
            else:
                target = node.module
            out.append((target, id(node) in top))
            # "from . import geometry" imports a module of the package
            if target.startswith("tarsim") and hasattr(importlib.import_module(target), "__path__"):
                out += [(f"{target}.{a.name}", id(node) in top) for a in node.names
                        if importlib.util.find_spec(f"{target}.{a.name}") is not None]
    return out


def _third_party(target: str) -> bool:
    root = target.split(".")[0]
    return root not in sys.stdlib_module_names and root not in ("tarsim", "__future__")


REFERENCE = [m for m in MODULES if m.startswith("tarsim.constructions.reference")]


@pytest.mark.parametrize("name", REFERENCE)
def test_the_reference_imports_no_method(name):
    # the models (a linkage's, with its joints and units, and its loads, a gear train's, a
    # rotor's) and the errors; never a method
    allowed = ("tarsim.constructions.model", "tarsim.constructions.joints",
               "tarsim.constructions.joint_kinds",
               "tarsim.constructions.units", "tarsim.constructions.gears.train",
               "tarsim.constructions.loads", "tarsim.constructions.balancing.rotor",
               "tarsim.constructions.errors", "tarsim.constructions.reference")
    for target, _ in _imports(name):
        if target.startswith("tarsim"):
            assert target.startswith(allowed), f"{name} imports {target}"


@pytest.mark.parametrize("name", MODULES)
def test_dependencies_point_one_way(name):
    below = {"tarsim.constructions": ("tarsim.graphics", "tarsim.exercises"),
             "tarsim.graphics": ("tarsim.exercises",)}
    layer = next((k for k in below if name.startswith(k)), None)
    for target, _ in _imports(name):
        if layer is not None:
            assert not target.startswith(below[layer]), f"{name} imports {target}"


@pytest.mark.parametrize("name", [m for m in MODULES if m.startswith("tarsim.constructions")])
def test_constructions_need_only_numpy(name):
    for target, _ in _imports(name):
        if _third_party(target):
            assert target.split(".")[0] == "numpy", f"{name} imports {target}"


@pytest.mark.parametrize("name", MODULES)
def test_only_the_command_line_imports_click_and_cairo_is_lazy(name):
    for target, at_top in _imports(name):
        root = target.split(".")[0]
        if root == "click":
            assert name in ("tarsim.exercises.cli", "tarsim.exercises.cli_common",
                            "tarsim.exercises.cli_files", "tarsim.exercises.cli_handout",
                            "tarsim.exercises.cli_serve"), \
                f"{name} imports click"
        if root in ("cairosvg", "cairocffi"):
            assert not at_top, f"{name} imports {root} when it loads"


def test_every_package_folder_is_installed():
    """setup.py finds the packages (the layers map onto ``tarsim``): a folder it missed would
    be missing from an install, though an editable one finds it."""
    import runpy
    import tomllib

    root = Path(__file__).resolve().parents[1]
    config = tomllib.loads((root / "pyproject.toml").read_text(encoding="utf-8"))
    listed = set(runpy.run_path(str(root / "setup.py"), run_name="setup")["packages"]())
    mapping = config["tool"]["setuptools"]["package-dir"]
    found = set()
    for package, folder in mapping.items():
        base = root / folder
        for init in base.rglob("__init__.py"):
            rel = init.parent.relative_to(base).parts
            if package == "tarsim" or not any(part == "tarsim" for part in rel):
                found.add(".".join((package, *rel)))
    found = {f for f in found if not f.startswith("tarsim.exercises.tarsim")}
    assert found == listed
