"""Write a figure to .svg, .pdf or .png, all or nothing.

SVG needs no system library. PDF and PNG go through cairosvg, imported only here
and only when asked for; without libcairo2 the user gets one line saying so. The
file is written to a temporary name beside the target and renamed into place, so
a failure leaves nothing half-written.
"""

from __future__ import annotations

import os
import tempfile
from pathlib import Path

from ..constructions.errors import TarsimError

from .figure import Figure
from .svg import to_svg

__all__ = ["RenderError", "FORMATS", "write_figure", "write_text", "svg_to", "cairo_missing",
           "pdf_pages"]

FORMATS = ("svg", "pdf", "png")


class RenderError(TarsimError):
    """A figure or file cannot be written: an unknown format, no libcairo, a folder that fails."""

_NO_CAIRO = ("PDF and PNG output need the cairo library (libcairo2), which is not installed: "
             "install it (Debian/Ubuntu: apt-get install libcairo2) or write .svg instead")


def cairo_missing() -> str | None:
    """The one-line reason PDF/PNG cannot be made here, or None when they can."""
    try:
        import cairosvg  # noqa: PLC0415
    except (ImportError, OSError):
        return _NO_CAIRO
    del cairosvg                  # imported only to learn that it loads
    return None


def svg_to(svg: str, fmt: str, *, dpi: float = 200.0) -> bytes:
    """Convert SVG text to PDF or PNG bytes with cairosvg.

    Raises
    ------
    RenderError
        If cairosvg or libcairo2 is missing.
    """
    try:
        import cairosvg  # noqa: PLC0415  (lazy: SVG output must not need libcairo)
    except (ImportError, OSError):
        raise RenderError(_NO_CAIRO) from None
    data = svg.encode("utf-8")
    if fmt == "pdf":
        return cairosvg.svg2pdf(bytestring=data)
    if fmt == "png":
        return cairosvg.svg2png(bytestring=data, dpi=dpi, background_color="white")
    raise RenderError(f"cannot convert to '{fmt}'; choose one of {', '.join(FORMATS)}")


def pdf_pages(pdfs: list[bytes]) -> bytes:
    """Join one-page PDFs into one document, a page each, in order (pypdf copies the pages
    as they are, so every page keeps its own size and true scale)."""
    import io

    from pypdf import PdfWriter  # noqa: PLC0415  (only PDF output needs it)

    writer = PdfWriter()
    for data in pdfs:
        writer.append(io.BytesIO(data))
    out = io.BytesIO()
    writer.write(out)
    return out.getvalue()


def write_figure(fig: Figure | str, path: str | Path) -> Path:
    """Write ``fig`` (a Figure or SVG text) to ``path``; the suffix picks the format.

    Raises
    ------
    RenderError
        For an unknown suffix, a missing libcairo2, or a path that cannot be written.
    """
    path = Path(path)
    fmt = path.suffix.lower().lstrip(".")
    if fmt not in FORMATS:
        raise RenderError(f"cannot write '{path.name}': the name must end in "
                          f"{', '.join('.' + f for f in FORMATS)}")
    svg = fig if isinstance(fig, str) else to_svg(fig)
    data = svg.encode("utf-8") if fmt == "svg" else svg_to(svg, fmt)
    _write_atomically(path, data)
    return path


def write_text(path: str | Path, data: str | bytes) -> Path:
    """Write text (UTF-8) or bytes to ``path`` atomically: results.json, steps.md, a PDF.

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
