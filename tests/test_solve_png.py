"""`tarsim solve --format png --dpi N`: a PNG of each sheet, at its true size and saying so.

A figure is drawn to scale on its sheet, so a PNG placed in a slide or a book keeps that
scale only if the program placing it knows the resolution: each PNG's pHYs chunk states
it, and its pixels are the sheet's millimetres at that resolution.
"""

from __future__ import annotations

import re
import struct
import zlib

import pytest
from click.testing import CliRunner

from tarsim.exercises.cli import cli
from tarsim.graphics.export import with_dpi

pytest.importorskip("cairosvg")


def _chunks(png: bytes) -> dict[bytes, bytes]:
    """Each chunk's data by its type, each CRC checked (as a PNG reader does)."""
    assert png[:8] == b"\x89PNG\r\n\x1a\n"
    found, at = {}, 8
    while at < len(png):
        (length,) = struct.unpack(">I", png[at:at + 4])
        kind, data = png[at + 4:at + 8], png[at + 8:at + 8 + length]
        (crc,) = struct.unpack(">I", png[at + 8 + length:at + 12 + length])
        assert crc == zlib.crc32(kind + data), kind
        found.setdefault(kind, data)
        at += 12 + length
    return found


def test_a_png_states_its_resolution_in_pixels_a_metre():
    import cairosvg
    png = cairosvg.svg2png(bytestring=b'<svg xmlns="http://www.w3.org/2000/svg" width="10mm" '
                                      b'height="5mm"><rect width="5" height="5"/></svg>', dpi=300)
    stated = _chunks(with_dpi(png, 300))[b"pHYs"]
    x, y, unit = struct.unpack(">IIB", stated)
    assert (x, y, unit) == (11811, 11811, 1)      # 300 / 0.0254 = 11811.02, the metre unit


@pytest.mark.slow
def test_solve_writes_a_png_of_each_figure_at_the_asked_dpi(tmp_path):
    out = tmp_path / "out"
    run = CliRunner().invoke(cli, ["solve", "four-bar", "-o", str(out), "--format", "png",
                                   "--dpi", "300"])
    assert run.exit_code == 0, run.output
    svgs = sorted(p.stem for p in out.glob("*.svg") if p.stem != "solution")
    assert sorted(p.stem for p in out.glob("*.png")) == svgs
    assert not list(out.glob("*.pdf")), "--format png alone writes no PDF"
    for stem in svgs:
        svg = (out / f"{stem}.svg").read_text(encoding="utf-8")
        w_mm, h_mm = (float(v) for v in re.search(r'height="([\d.]+)mm".*?width="([\d.]+)mm"',
                                                   svg).groups()[::-1])
        header = _chunks((out / f"{stem}.png").read_bytes())
        w_px, h_px = struct.unpack(">II", header[b"IHDR"][:8])
        # the sheet's mm at 300 dpi, to the pixel cairo rounds to
        assert abs(w_px - w_mm / 25.4 * 300) <= 1 and abs(h_px - h_mm / 25.4 * 300) <= 1, stem
        assert struct.unpack(">IIB", header[b"pHYs"]) == (11811, 11811, 1)


def test_png_asked_by_name_is_refused_in_one_line_without_cairo(tmp_path, monkeypatch):
    import tarsim.exercises.solution_folder as folder
    monkeypatch.setattr(folder, "cairo_missing", lambda: "PDF and PNG output need libcairo2")
    run = CliRunner().invoke(cli, ["solve", "four-bar", "-o", str(tmp_path / "o"),
                                   "--format", "png"])
    assert run.exit_code == 1
    assert run.output.strip() == "Error: PDF and PNG output need libcairo2"
    assert not (tmp_path / "o" / "centres.svg").exists(), "nothing half-written"
