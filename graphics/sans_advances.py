"""DejaVu Sans advance widths (em), regular and bold, the face right-to-left labels are
set in: a table taken once from the font by docs/make_sans_advances.py and kept as data
(graphics/data/sans_advances.json), so that tarsim needs neither fontTools nor the font to
lay a figure out.

>>> ADVANCE["a"], BOLD["a"]
(0.613, 0.675)
"""

from __future__ import annotations

import json
from pathlib import Path

__all__ = ["ADVANCE", "BOLD", "TABLE", "HINTING"]

TABLE = Path(__file__).with_name("data") / "sans_advances.json"
"""Where the table is kept, beside this module."""

_tables = json.loads(TABLE.read_text(encoding="utf-8"))

ADVANCE: dict[str, float] = _tables["ADVANCE"]
"""Each character's advance in DejaVu Sans, in em."""

BOLD: dict[str, float] = _tables["BOLD"]
"""Each character's advance in DejaVu Sans Bold, in em."""

HINTING = 0.02
"""What a right-to-left line's width is allowed over its advances. cairo's own extents, as
tarsim's PDF sets a label (a glyph at a time, on a surface in mm), match the advances to
0.03 mm; cairosvg's PNG rounds each glyph's advance to whole pixels, and at 200 dpi, its
default, a Persian line ran up to 1.8 % wider (3.5 mm on a 194 mm note; a line of
Persian digits 2.5 %). 2 % covers every bundled label to a pixel and half a percent
(tests/test_persian_widths.py) and keeps within the 3 % a browser sets a line to
(tests/test_persian_browser.py)."""
