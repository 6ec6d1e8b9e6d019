"""Nice scales (1, 2 or 5 × 10^k per centimetre) and the scale bar that states them.

The scale is chosen so the panel fits its box; the bar is drawn in paper
millimetres, so on a PDF printed at 100 % it measures true with a ruler.
"""

from __future__ import annotations

import math

from .figure import Figure, Path, Text

__all__ = ["nice_per_cm", "scale_text", "draw_scale_bar", "number_text"]


def nice_per_cm(extent: float, room_mm: float) -> float:
    """Return the smallest nice value N (1, 2, 5 × 10^k) with ``extent`` / N cm ≤ ``room_mm``.

    ``extent`` is in the unit the scale will be stated in; the result is how much
    of that unit one centimetre of paper stands for.

    Examples
    --------
    >>> nice_per_cm(400.0, 150.0)
    50.0
    >>> nice_per_cm(0.7, 100.0)
    0.1
    """
    if extent <= 0 or room_mm <= 0:
        raise ValueError("a scale needs a positive extent and room")
    need = extent * 10.0 / room_mm
    k = math.floor(math.log10(need))
    for base in (1.0, 2.0, 5.0, 10.0):
        value = base * 10.0 ** k
        if value >= need * (1 - 1e-12):
            return float(f"{value:.12g}")
    return float(f"{10.0 ** (k + 1):.12g}")


def number_text(value: float) -> str:
    """Format a scale number without float noise ("0.2", "50", "2000").

    Examples
    --------
    >>> number_text(0.30000000000000004)
    '0.3'
    """
    return f"{value:.6g}"


def scale_text(per_cm: float, unit: str) -> str:
    """Return the statement printed on the figure, e.g. "1 cm = 50 mm"."""
    return f"1 cm = {number_text(per_cm)} {unit}"


def draw_scale_bar(fig: Figure, at: tuple[float, float], per_cm: float, unit: str,
                   cm: int = 4) -> float:
    """Draw a ``cm``-centimetre bar with alternate filled centimetres; return its width.

    ``at`` is the bar's left end on its centre line.
    """
    x0, y0 = at
    h = 1.4
    for i in range(cm):
        style = "scale_fill" if i % 2 == 0 else "scale"
        xa, xb = x0 + 10.0 * i, x0 + 10.0 * (i + 1)
        fig.add(Path(((xa, y0 - h / 2), (xb, y0 - h / 2), (xb, y0 + h / 2), (xa, y0 + h / 2)),
                     style, closed=True))
    for i in range(0, cm + 1, 2 if cm > 3 else 1):
        label = number_text(per_cm * i) + (f" {unit}" if i == cm else "")
        fig.add(Text((x0 + 10.0 * i, y0 + h / 2 + 2.4), label, size=2.6,
                     anchor="middle" if i < cm else "start", italic=False))
    return 10.0 * cm
