"""Write graphics/data/sans_advances.json: DejaVu Sans's advance widths (em) for the
characters a right-to-left label is set in (read by graphics/sans_advances.py).

Persian labels are set in DejaVu Sans (graphics/rtl.py); their width on paper is the sum
of the advances of the joined forms they are drawn in. The table is taken once from the
font itself, so that tarsim needs neither fontTools nor the font to lay a figure out.

    python docs/make_sans_advances.py /usr/share/fonts/truetype/dejavu
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

from fontTools.ttLib import TTFont

RANGES = [(0x20, 0x7F), (0xA0, 0x100), (0x370, 0x400), (0x600, 0x700), (0x2000, 0x2070),
          (0x2070, 0x20A0), (0x2190, 0x21A0), (0x2200, 0x2300), (0xFB50, 0xFE00),
          (0xFE70, 0xFF00)]


def advances(font_path: str) -> dict[str, float]:
    """Each character's advance in ``font_path``, in em."""
    font = TTFont(font_path)
    cmap, hmtx = font.getBestCmap(), font["hmtx"]
    em = font["head"].unitsPerEm
    return {chr(c): round(hmtx[cmap[c]][0] / em, 3)
            for lo, hi in RANGES for c in range(lo, hi) if c in cmap}


def main(folder: str) -> None:
    """Write both faces' tables from the DejaVu fonts in ``folder``."""
    tables = {name: advances(f"{folder}/{face}.ttf")
              for name, face in (("ADVANCE", "DejaVuSans"), ("BOLD", "DejaVuSans-Bold"))}
    out = Path(__file__).resolve().parents[1] / "graphics" / "data" / "sans_advances.json"
    out.write_text(json.dumps(tables, ensure_ascii=True, indent=0) + "\n", encoding="utf-8")
    print(f"{sum(map(len, tables.values()))} advances written to {out}")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "/usr/share/fonts/truetype/dejavu")
