"""The folder ``tarsim serve`` was started in: the only place it reads a file from or
writes one to.

A path a request names is relative to the folder and stays inside it: an absolute path,
a ``..`` part, or a symbolic link that leads out is refused (403) before anything is
opened. A file is written atomically, and one the server did not write itself is kept
unless the request says to overwrite it.
"""

from __future__ import annotations

import os
import threading
from pathlib import Path, PurePosixPath, PureWindowsPath

from tarsim.graphics.atomic_files import RenderError, write_text

from ..toml_source import read_source
from .refusals import Refused

__all__ = ["Folder", "MOST_FILES"]

MOST_FILES = 2000
"""The most .toml files listed: a server started in a home folder lists the first ones
rather than walking the whole disk."""


class Folder:
    """The served folder: its files found, read and written, confined to it.

    Parameters
    ----------
    root : path
        The folder; it must exist.
    """

    def __init__(self, root: str | Path):
        self.root = Path(root).resolve(strict=True)
        self._written: set[Path] = set()
        self._lock = threading.Lock()

    def inside(self, name: object) -> Path:
        """The file ``name`` names, relative to the folder, resolved inside it.

        Raises
        ------
        Refused
            403 if it is not a relative path inside the folder (absolute, with ``..``,
            or through a link that leads out); 400 if it is not a path at all.
        """
        if not isinstance(name, str) or not name.strip() or "\x00" in name:
            raise Refused("a file is named by a path relative to the served folder, such as "
                          "'my.toml'", 400)
        parts = PurePosixPath(name.replace("\\", "/"))
        if parts.is_absolute() or PureWindowsPath(name).drive or ".." in parts.parts:
            raise Refused(f"'{name}' is outside the served folder: name a file inside it, "
                          "relative to it, without '..'", 403)
        path = (self.root / parts).resolve()
        if not path.is_relative_to(self.root):
            raise Refused(f"'{name}' leads outside the served folder (through a link); "
                          "name a file inside it", 403)
        return path

    def read(self, name: object) -> str:
        """The text of the file ``name`` inside the folder.

        Raises
        ------
        Refused
            403 outside the folder (:meth:`inside`), 404 if there is no such file.
        InputError
            If it cannot be read or is not UTF-8 text.
        """
        path = self.inside(name)
        if not path.is_file():
            raise Refused(f"no file '{name}' in the served folder", 404)
        return read_source(path)

    def save(self, name: object, text: str, *, overwrite: bool = False) -> str:
        """Write ``text`` to the .toml file ``name`` inside the folder, atomically; return
        its name relative to the folder.

        Raises
        ------
        Refused
            403 outside the folder, 400 for a name not ending in .toml, 409 for a file
            there that this server did not write (unless ``overwrite``), 404 for a folder
            that does not exist.
        """
        path = self.inside(name)
        if path.suffix.lower() != ".toml":
            raise Refused(f"'{name}' is not a .toml file: an exercise is saved as name.toml",
                          400)
        with self._lock:            # two saves of one file: each whole, the later one kept
            if path.exists() and path not in self._written and not overwrite:
                raise Refused(f"'{name}' is already in the served folder and was not written "
                              "by this app; send \"overwrite\": true to replace it", 409)
            if not path.parent.is_dir():
                raise Refused(f"no folder '{path.parent.relative_to(self.root)}' in the "
                              "served folder to save into", 404)
            try:
                write_text(path, text)
            except RenderError:
                raise Refused(f"cannot write '{name}' in the served folder", 403) from None
            self._written.add(path)
        return path.relative_to(self.root).as_posix()

    def tomls(self) -> list[str]:
        """The .toml files under the folder, relative to it, in order; hidden folders and
        links that lead out are passed by, and no more than :data:`MOST_FILES` listed."""
        found: list[str] = []
        for top, dirs, files in os.walk(self.root):
            dirs[:] = sorted(d for d in dirs if not d.startswith("."))
            for f in sorted(files):
                if f.endswith(".toml") and not f.startswith("."):
                    path = Path(top) / f
                    if path.resolve().is_relative_to(self.root):
                        found.append(path.relative_to(self.root).as_posix())
                        if len(found) >= MOST_FILES:
                            return found
        return found
