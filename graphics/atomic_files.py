"""Write a file, or a folder of files, all or nothing, and never through a link or over
a file tarsim did not write.

A file is written to a temporary name beside the target and renamed into place, so a
failure leaves nothing half-written. A folder's files (:func:`write_folder`) are all
staged first, in a hidden folder inside it, and moved in under a lock only when every one
is written; a hidden manifest names what tarsim wrote there, so that the next run removes
what it does not write again and nothing else. Nothing is written through a symbolic link
found inside an output folder.
"""

from __future__ import annotations

import errno
import json
import os
import re
import shutil
import stat
import tempfile
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

try:
    import fcntl
except ImportError:               # not on Windows: folders are then written unlocked
    fcntl = None

from tarsim.constructions.errors import TarsimError

__all__ = ["RenderError", "MANIFEST", "write_text", "write_folder", "check_folder",
           "output_folder"]

MANIFEST = ".tarsim-manifest.json"
"""The hidden file in an output folder naming the files tarsim wrote there (a JSON list)."""

_STAGE = ".tarsim-"
_STAGED = re.compile(r"\.tarsim-[a-z0-9_]{8}")
"""A staging folder's name: what :func:`tempfile.mkdtemp` makes of the prefix."""
_FOLDER = os.O_RDONLY | getattr(os, "O_DIRECTORY", 0)
_NOFOLLOW = getattr(os, "O_NOFOLLOW", 0)


class RenderError(TarsimError):
    """A figure or file cannot be written: an unknown format, no libcairo, a folder that fails."""


def write_text(path: str | Path, data: str | bytes) -> Path:
    """Write text (UTF-8) or bytes to one file ``path`` atomically (a folder's set of files
    goes through :func:`write_folder`).

    Raises
    ------
    RenderError
        If the path cannot be written.
    """
    path = Path(path)
    _write_atomically(path, data.encode("utf-8") if isinstance(data, str) else data)
    return path


def _write_atomically(path: Path, data: bytes) -> None:
    folder = path.parent if str(path.parent) else Path(".")
    if not folder.is_dir():
        raise RenderError(f"cannot write '{path}': the folder '{folder}' does not exist")
    try:
        fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", dir=folder)
    except OSError as e:
        raise RenderError(f"cannot write '{path}': {e.strerror}") from None
    try:
        with os.fdopen(fd, "wb") as f:
            f.write(data)
        mask = os.umask(0)
        os.umask(mask)
        os.chmod(tmp, 0o666 & ~mask)  # mkstemp makes 0600; a figure is an ordinary file
        os.replace(tmp, path)
    except OSError as e:
        Path(tmp).unlink(missing_ok=True)
        raise RenderError(f"cannot write '{path}': {e.strerror}") from None


# ----- a folder of files: all or nothing, and never the user's ---------------------------
def check_folder(path: str | Path) -> None:
    """Make the folder ``path`` (parents too) and prove it writable, before a long solve.

    Raises
    ------
    RenderError
        If the folder cannot be made or written, or ``path`` is a file.
    """
    _prepare(Path(path))


@contextmanager
def output_folder(path: str | Path) -> Iterator[Path]:
    """Check the folder ``path`` as :func:`check_folder` does; if the body then fails, remove
    the folders the check made while they are still empty, so a failed solve leaves none.

    Raises
    ------
    RenderError
        If the folder cannot be made or written, or ``path`` is a file.
    """
    path = Path(path)
    made = _prepare(path)
    try:
        yield path
    except BaseException:
        _remove_empty(made)
        raise


def write_folder(files: dict[str, str | bytes], out_dir: str | Path) -> list[Path]:
    """Write ``files`` (name: text or bytes) into ``out_dir`` as one set; return their paths.

    A name may lead through folders ("ali/grade.svg"), which are made inside ``out_dir``.
    All are written to a hidden staging folder inside ``out_dir`` first, so a full disk
    leaves the folder as it was. Under an exclusive lock on the folder, staging folders
    that runs killed before they finished left behind are removed, the files are renamed
    into place, those the previous run listed in :data:`MANIFEST` and this one does not
    write are removed, and the manifest is rewritten: the folder holds one solution, the
    last run's whole. A file of the same name that tarsim did not write is never replaced,
    and a symbolic link inside ``out_dir`` is never written through: the run is refused
    before anything moves.

    Raises
    ------
    RenderError
        If the folder cannot be made or written, holds a file of one of these names that
        tarsim did not write, or a symbolic link where one of these folders would be.
    """
    out = Path(out_dir)
    names = list(files)
    for name in names:
        parts = _parts(name)
        if parts is None:
            raise RenderError(f"cannot write '{name}': not a plain file name")
        for i in range(1, len(parts)):
            if "/".join(parts[:i]) in files:
                raise RenderError(f"cannot write '{name}': '{parts[i - 1]}' is one of the "
                                  "files, so it cannot be a folder too")
    _prepare(out, probe=False)
    with _locked(out):
        stage, hold = _new_stage(out)
    try:
        for name, data in files.items():
            try:
                (stage / name).parent.mkdir(parents=True, exist_ok=True)
                _put(stage / name, data.encode("utf-8") if isinstance(data, str) else data)
            except OSError as e:
                raise RenderError(f"cannot write '{out / name}': {e.strerror}") from None
        with _locked(out):
            _remove_stale_stages(out, stage)
            _commit(stage, out, names)
    finally:
        shutil.rmtree(stage, ignore_errors=True)
        if hold is not None:
            os.close(hold)
    return [out / name for name in names]


def _new_stage(out: Path) -> tuple[Path, int | None]:
    """A new staging folder in ``out``, and a descriptor holding a lock on it for as long as
    the run lives, which tells :func:`_remove_stale_stages` it is in use. The caller holds
    the folder's lock, so no other run sees the staging folder before it is locked."""
    try:
        stage = Path(tempfile.mkdtemp(prefix=_STAGE, dir=out))
    except OSError as e:
        raise RenderError(f"cannot write into the folder '{out}': {e.strerror}") from None
    if fcntl is None:
        return stage, None
    try:
        hold = os.open(stage, _FOLDER)
    except OSError as e:
        shutil.rmtree(stage, ignore_errors=True)
        raise RenderError(f"cannot write into the folder '{out}': {e.strerror}") from None
    fcntl.flock(hold, fcntl.LOCK_EX | fcntl.LOCK_NB)   # new, so no other run holds it
    return stage, hold


def _remove_stale_stages(out: Path, own: Path) -> None:
    """Remove the staging folders in ``out``, but this run's ``own``, of runs that were
    killed before they could: a folder named as :func:`tempfile.mkdtemp` names one, of its
    mode 0700 and owner, whose lock no live run holds. The caller holds the folder's lock."""
    if fcntl is None:                          # no locks: a live run's cannot be told apart
        return
    try:
        entries = [e for e in os.scandir(out)
                   if _STAGED.fullmatch(e.name) and e.name != own.name]
    except OSError:
        return
    for entry in entries:
        try:
            st = entry.stat(follow_symlinks=False)
            if not (stat.S_ISDIR(st.st_mode) and stat.S_IMODE(st.st_mode) == 0o700
                    and st.st_uid == os.geteuid()):
                continue
            fd = os.open(entry.path, _FOLDER | _NOFOLLOW)
        except OSError:
            continue
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
            shutil.rmtree(entry.path, ignore_errors=True)
        except OSError:                        # locked: a live run is filling it
            pass
        finally:
            os.close(fd)


def _commit(stage: Path, out: Path, names: list[str]) -> None:
    """Move the staged files into ``out``; the caller holds the folder's lock."""
    old = _read_manifest(out)
    folders = sorted({"/".join(p[:i]) for p in map(_parts, names) for i in range(1, len(p))})
    for folder in folders:
        try:
            st = os.lstat(out / folder)
        except FileNotFoundError:
            continue
        except OSError as e:
            raise RenderError(f"cannot write into '{out / folder}': {e.strerror}") from None
        if stat.S_ISLNK(st.st_mode):
            raise RenderError(f"cannot write into '{out / folder}': it is a symbolic link, and "
                              "tarsim writes only inside the output folder; remove it")
        if not stat.S_ISDIR(st.st_mode):
            raise RenderError(f"cannot write into '{out / folder}': it is a file, not a folder;"
                              " move it or choose another folder with -o")
    for name in names:
        if name not in old and os.path.lexists(out / name):
            raise RenderError(f"cannot write '{out / name}': a file of that name is already "
                              "there and tarsim did not write it; move it or choose another "
                              "folder with -o")
    # The manifest first lists old and new, so a run killed halfway leaves every file it
    # moved known as tarsim's; the one listing this run's files alone comes last.
    _write_manifest(stage / f"{_STAGE}both", out, [*old, *names])
    for name in names:
        *inside, last = _parts(name)
        try:
            with _folder(out, inside, make=True) as fd:
                os.replace(stage / name, last if inside else out / last,
                           dst_dir_fd=fd if inside else None)
        except OSError as e:
            raise RenderError(f"cannot write '{out / name}': {_why(e)}") from None
    kept = []
    for name in sorted(old.difference(names)):
        *inside, last = _parts(name)
        try:
            with _folder(out, inside, make=False) as fd:
                os.unlink(last if inside else out / last, dir_fd=fd if inside else None)
        except (FileNotFoundError, NotADirectoryError):
            pass                               # gone, or a file now: not tarsim's
        except OSError as e:
            if e.errno != errno.ELOOP:         # a link on the way: not tarsim's either
                kept.append(name)              # a folder now, say: listed, a later run retries
    _remove_emptied(out, old, folders)
    _write_manifest(stage / f"{_STAGE}new", out, [*names, *kept])


@contextmanager
def _folder(out: Path, inside: list[str], *, make: bool) -> Iterator[int | None]:
    """A descriptor of the folder ``out``/``inside``…, reached without following a link
    (made, with ``make``); None for ``out`` itself. An OSError if it cannot be reached:
    ELOOP for a link on the way, NotADirectoryError for a file."""
    if not inside:
        yield None
        return
    fds = [os.open(out, _FOLDER)]
    try:
        for part in inside:
            if make:
                try:
                    os.mkdir(part, dir_fd=fds[-1])
                except FileExistsError:
                    pass
            fds.append(os.open(part, _FOLDER | _NOFOLLOW, dir_fd=fds[-1]))
        yield fds[-1]
    finally:
        for fd in fds:
            os.close(fd)


def _remove_emptied(out: Path, old: set[str], keep: list[str]) -> None:
    """Remove the folders the last run's files were in that this run's are not (``keep``),
    innermost first, while empty; a link is never followed, nor removed."""
    gone = {"/".join(p[:i]) for p in map(_parts, old) for i in range(1, len(p))}
    for folder in sorted(gone.difference(keep), key=lambda f: -f.count("/")):
        *inside, last = folder.split("/")
        try:
            with _folder(out, inside, make=False) as fd:
                os.rmdir(last if inside else out / last, dir_fd=fd if inside else None)
        except OSError:                        # the user's files in it, or not a folder
            pass


def _why(e: OSError) -> str:
    """An OSError's reason; a link met on the way is named so."""
    if e.errno == errno.ELOOP:
        return "a folder on the way is a symbolic link, which tarsim does not write through"
    return e.strerror or str(e)


def _write_manifest(tmp: Path, out: Path, names: list[str]) -> None:
    """Replace the manifest atomically with the sorted ``names``, written first to ``tmp``."""
    try:
        _put(tmp, (json.dumps(sorted(set(names)), indent=0) + "\n").encode("utf-8"))
        os.replace(tmp, out / MANIFEST)
    except OSError as e:
        raise RenderError(f"cannot write '{out / MANIFEST}': {e.strerror}") from None


def _put(path: Path, data: bytes) -> None:
    """Write a new file (mode 0666 less the umask, as any file the user makes)."""
    with open(path, "xb") as f:
        f.write(data)


def _read_manifest(out: Path) -> set[str]:
    """The names the last run wrote; none if there is no manifest or it cannot be read
    (then every file there counts as the user's, which is the safe side)."""
    try:
        names = json.loads((out / MANIFEST).read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return set()
    if not isinstance(names, list):
        return set()
    return {n for n in names if isinstance(n, str) and _parts(n) is not None}


def _parts(name: str) -> list[str] | None:
    """The folders and file of a name within an output folder ("ali/grade.svg"), or None
    if it could reach outside it ("..", "/x", "a//b") or is tarsim's own (the manifest, a
    staging folder)."""
    parts = name.split("/")
    if any(p in ("", ".", "..") or os.sep in p or (os.altsep and os.altsep in p)
           for p in parts) or parts[0] == MANIFEST or parts[0].startswith(_STAGE):
        return None
    return parts


@contextmanager
def _locked(out: Path) -> Iterator[None]:
    """Hold an exclusive lock on the folder itself: concurrent runs commit one at a time."""
    if fcntl is None:
        yield
        return
    try:
        fd = os.open(out, os.O_RDONLY)
    except OSError as e:
        raise RenderError(f"cannot write into the folder '{out}': {e.strerror}") from None
    try:
        fcntl.flock(fd, fcntl.LOCK_EX)
        yield
    finally:
        os.close(fd)                           # closing the last fd releases the lock


def _prepare(out: Path, *, probe: bool = True) -> list[Path]:
    """Make ``out`` and any missing parents, and with ``probe`` create and remove a file in
    it; return the folders made, outermost first."""
    try:
        if out.exists() and not out.is_dir():
            raise RenderError(f"cannot write into '{out}': it is a file, not a folder")
        missing = []
        folder = out
        while not folder.is_dir() and folder != folder.parent:
            missing.append(folder)
            folder = folder.parent
    except OSError as e:                       # a parent that may not be searched
        raise RenderError(f"cannot make the folder '{out}': {e.strerror}") from None
    made: list[Path] = []
    try:
        for folder in reversed(missing):
            try:
                folder.mkdir()
            except FileExistsError:
                if not folder.is_dir():
                    raise RenderError(f"cannot make the folder '{out}': '{folder}' is a file"
                                      ) from None
                continue                       # made meanwhile by someone else: not ours
            except OSError as e:
                raise RenderError(f"cannot make the folder '{out}': {e.strerror}") from None
            made.append(folder)
        if probe:
            try:
                fd, tmp = tempfile.mkstemp(prefix=_STAGE, dir=out)
                os.close(fd)
                os.unlink(tmp)
            except OSError as e:
                raise RenderError(f"cannot write into the folder '{out}': {e.strerror}"
                                  ) from None
    except RenderError:
        _remove_empty(made)
        raise
    return made


def _remove_empty(made: list[Path]) -> None:
    """Remove the folders ``made`` (outermost first) while empty: a filled one is kept."""
    for folder in reversed(made):
        try:
            folder.rmdir()
        except OSError:
            break
