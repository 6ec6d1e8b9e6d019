"""The package list, found rather than kept by hand: each layer's folder is installed as
``tarsim.<layer>`` (pyproject.toml's package-dir), and every package inside it with it, so
a new chapter's package needs no edit here or in pyproject.toml."""

from pathlib import Path

from setuptools import find_packages, setup

LAYERS = ("constructions", "graphics", "exercises")


def packages() -> list[str]:
    """``tarsim``, each layer, and every package in a layer's folder but the one that is
    ``tarsim`` itself (exercises/tarsim)."""
    here = Path(__file__).resolve().parent
    return ["tarsim"] + [f"tarsim.{layer}" for layer in LAYERS] + [
        f"tarsim.{layer}.{found}" for layer in LAYERS
        for found in find_packages(str(here / layer), exclude=["tarsim", "tarsim.*"])]


if __name__ == "__main__":
    setup(packages=packages())
