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

__all__ = ["ADVANCE", "BOLD", "TABLE"]

TABLE = Path(__file__).with_name("data") / "sans_advances.json"
"""Where the table is kept, beside this module."""

_tables = json.loads(TABLE.read_text(encoding="utf-8"))

ADVANCE: dict[str, float] = _tables["ADVANCE"]
"""Each character's advance in DejaVu Sans, in em."""

BOLD: dict[str, float] = _tables["BOLD"]
"""Each character's advance in DejaVu Sans Bold, in em."""
