"""Write a figure to .svg, .pdf or .png.

SVG needs no system library. A figure's PDF is drawn straight from it with cairo
(:mod:`.pdf`); PNG, and PDF of SVG text, go through cairosvg. Both are imported only
when asked for; without libcairo2 the user gets one line saying so. Files, and folders
of them, are written all or nothing by :mod:`.atomic_files`, whose names are given here
too.
"""

from __future__ import annotations

import struct
import zlib
from pathlib import Path

from .atomic_files import (MANIFEST, RenderError, check_folder, output_folder, write_folder,
                           write_text)
from .figure import Figure
from .pdf import dated
from .rtl import for_cairo
from .svg import to_svg

__all__ = ["RenderError", "FORMATS", "MANIFEST", "write_figure", "write_text", "write_folder",
           "check_folder", "output_folder", "svg_to", "cairo_missing", "figure_pdf",
           "figure_pngs"]

FORMATS = ("svg", "pdf", "png")

_NO_CAIRO = ("PDF and PNG output need the cairo library (libcairo2), which is not installed: "
             "install it (Debian/Ubuntu: apt-get install libcairo2) or write .svg instead")


def cairo_missing() -> str | None:
    """The one-line reason PDF/PNG cannot be made here, or None when they can; cairo's
    bindings are loaded, for workers forked after this to inherit."""
    try:
        import cairocffi  # noqa: F401, PLC0415  (it loads libcairo2, or fails to)
    except (ImportError, OSError):
        return _NO_CAIRO
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
    data = for_cairo(svg).encode("utf-8")      # Persian shaped: cairosvg cannot shape it
    if fmt == "pdf":
        return _dated(cairosvg.surface.PDFSurface).convert(bytestring=data)
    if fmt == "png":
        return with_dpi(cairosvg.svg2png(bytestring=data, dpi=dpi, background_color="white"),
                        dpi)
    raise RenderError(f"cannot convert to '{fmt}'; choose one of {', '.join(FORMATS)}")


def with_dpi(png: bytes, dpi: float) -> bytes:
    """``png`` with its resolution stated (a pHYs chunk, in pixels a metre), so that a
    program placing it knows its true size: cairosvg draws at ``dpi`` but does not say so."""
    per_metre = round(dpi / 0.0254)
    body = b"pHYs" + struct.pack(">IIB", per_metre, per_metre, 1)
    chunk = struct.pack(">I", 9) + body + struct.pack(">I", zlib.crc32(body))
    end_of_header = 8 + 8 + 13 + 4           # the signature, then IHDR's length, type, data, CRC
    return png[:end_of_header] + chunk + png[end_of_header:]


def figure_pngs(fig: Figure, stem: str, dpi: float) -> dict[str, bytes]:
    """A PNG of each sheet of ``fig`` at ``dpi``, its true size stated: ``stem.png`` for a
    figure of one sheet, ``stem-1.png``, ``stem-2.png`` … for a page that runs on."""
    sheets = fig.sheets or [fig]
    names = [f"{stem}.png"] if len(sheets) == 1 else [f"{stem}-{i}.png"
                                                      for i in range(1, len(sheets) + 1)]
    return {name: svg_to(to_svg(sheet), "png", dpi=dpi) for name, sheet in zip(names, sheets)}


def figure_pdf(pages: list[Figure]) -> bytes:
    """A PDF of ``pages`` (a figure's sheets, or every figure of a solution), a page each
    at its own size and true scale, drawn from the figures themselves
    (:mod:`~graphics.pdf`).

    Raises
    ------
    RenderError
        If libcairo2 is missing.
    """
    if missing := cairo_missing():
        raise RenderError(missing)
    from .pdf import draw_pdf  # noqa: PLC0415

    return draw_pdf(pages)


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
    if fmt == "pdf" and not isinstance(fig, str):
        data = figure_pdf([fig])
    else:
        svg = fig if isinstance(fig, str) else to_svg(fig)
        data = svg.encode("utf-8") if fmt == "svg" else svg_to(svg, fmt)
    return write_text(path, data)




def _dated(surface_class: type) -> type:
    """A subclass of cairosvg's PDF surface ``surface_class`` whose document is dated as
    :func:`~graphics.pdf.dated` dates one, so the same SVG gives the same bytes."""
    class Dated(surface_class):
        def _create_surface(self, width, height):
            cairo_surface, width, height = super()._create_surface(width, height)
            dated(cairo_surface)
            return cairo_surface, width, height
    return Dated
