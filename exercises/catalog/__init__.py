"""The bundled mechanisms and exercises, one TOML file each, found by id."""

from __future__ import annotations

from importlib import resources
from pathlib import Path

from ...constructions.errors import InputError

__all__ = ["bundled", "bundled_trains", "bundled_cams", "bundled_balancing", "bundled_forces",
           "everything", "resolve", "load"]


def bundled() -> dict[str, Path]:
    """Map each bundled linkage's id (the file name without ``.toml``) to its path."""
    return _tomls(resources.files(__name__))


def bundled_trains() -> dict[str, Path]:
    """Map each bundled gear train's id to its path (the catalog's gears/ folder)."""
    return _tomls(resources.files(__name__) / "gears")


def bundled_cams() -> dict[str, Path]:
    """Map each bundled cam's id to its path (the catalog's cams/ folder)."""
    return _tomls(resources.files(__name__) / "cams")


def bundled_balancing() -> dict[str, Path]:
    """Map each bundled rotor or engine's id to its path (the catalog's balancing/ folder)."""
    return _tomls(resources.files(__name__) / "balancing")


def bundled_forces() -> dict[str, Path]:
    """Map each bundled loaded linkage's id to its path (the catalog's forces/ folder): the
    force analysis's exercises, kept apart so the kinematics' own stay quick to check."""
    return _tomls(resources.files(__name__) / "forces")


def everything() -> dict[str, Path]:
    """Every bundled id, chapter by chapter: the linkages, the loaded linkages, the gear
    trains, the cams, the rotors and engines."""
    return {**bundled(), **bundled_forces(), **bundled_trains(), **bundled_cams(),
            **bundled_balancing()}


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

    An exercise file is a mechanism file with an ``[ask]`` table (see the
    README); without one it asks for every centre and each link's ω. A file that
    lists ``[[gear]]`` tables is a gear train (a :class:`~..train_file.TrainExercise`), one
    with a ``[cam]`` table a cam (a :class:`~..cam_file.CamExercise`), one with a
    ``[rotor]`` or ``[engine]`` table a balancing exercise
    (a :class:`~..rotor_file.BalanceExercise`).
    Its id is the file's stem, or the bundled id.

    Raises
    ------
    InputError
        If it is neither a file nor a bundled id, or the file is not a valid
        exercise (the message names file:line).
    """
    from ..cam_file import is_cam, parse_cam
    from ..exercise_file import load_exercise
    from ..mechanism_file import read_source, read_toml
    from ..rotor_file import is_balance, parse_balance
    from ..train_file import is_train, parse_train

    source = str(source)
    path = resolve(source)
    exercise_id = Path(source).stem if Path(source).suffix else source
    text = read_source(path)
    data = read_toml(text, str(path))
    if is_train(data):
        return parse_train(text, str(path), exercise_id)
    if is_cam(data):
        return parse_cam(text, str(path), exercise_id)
    if is_balance(data):
        return parse_balance(text, str(path), exercise_id)
    return load_exercise(path, exercise_id)
