"""The bundled mechanisms and exercises, one TOML file each, found by id."""

from __future__ import annotations

from importlib import resources
from pathlib import Path

from tarsim.constructions.errors import InputError

__all__ = ["bundled", "everything", "resolve", "load"]


def bundled(folder: str = "") -> dict[str, Path]:
    """Map each bundled exercise of one of the catalog's folders to its path, by id (the
    file name without ``.toml``): the linkages' by default, else a chapter's folder
    (``"gears"``, ``"cams"``, ``"balancing"``, ``"forces"``: the loaded linkages, kept apart
    so the kinematics' own stay quick to check)."""
    root = resources.files(__name__)
    return _tomls(root / folder if folder else root)


def everything() -> dict[str, Path]:
    """Every bundled id, chapter by chapter in the registry's order, each chapter's folders
    in its own."""
    from ..chapters import chapters

    return {k: v for c in chapters() for folder in c.folders for k, v in bundled(folder).items()}


def _tomls(root) -> dict[str, Path]:
    return {p.name[:-5]: Path(str(p)) for p in sorted(root.iterdir(), key=lambda p: p.name)
            if p.name.endswith(".toml")}


def resolve(name: str) -> Path:
    """Return the file ``name`` names: a path on disk, or else a bundled id.

    Raises
    ------
    InputError
        If it is neither, with the closest bundled ids.
    """
    path = Path(name)
    if path.is_file():
        return path
    ids = everything()
    if name in ids:
        return ids[name]
    if path.is_dir():
        raise InputError(f"'{name}' is a folder; give a mechanism or exercise file (.toml) "
                         "or a bundled id")
    if path.exists():
        raise InputError(f"'{name}' is not an ordinary file; give a mechanism or exercise "
                         "file (.toml)")
    if path.suffix or "/" in name:
        raise InputError(f"no such file '{name}'")
    import difflib
    close = difflib.get_close_matches(name, list(ids), n=1)
    hint = f"did you mean '{close[0]}'?" if close else f"bundled: {', '.join(ids)}"
    raise InputError(f"no file or bundled example called '{name}'; {hint}")


def load(source: str | Path):
    """Read the exercise ``source`` names: a TOML file's path, or a bundled id.

    An exercise file is a mechanism file with an ``[ask]`` table (see
    docs/howto/linkages.md); without one it asks for every centre and each link's ω. A
    file of another chapter (:mod:`..chapters`) says so by its tables: ``[[gear]]`` a gear
    train, ``[cam]`` a cam, ``[rotor]`` or ``[engine]`` a balancing exercise. Its id is
    the file's stem, or the bundled id.

    Raises
    ------
    InputError
        If it is neither a file nor a bundled id, or the file is not a valid
        exercise (the message names file:line).
    """
    from ..chapters import read_file

    source = str(source)
    return read_file(resolve(source), Path(source).stem if Path(source).suffix else source)
