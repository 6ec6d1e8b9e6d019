"""The units a file states its numbers in, and how a number of the SI model is said in them.

The model keeps every number in SI (metres, radians, seconds); :class:`Units` remembers
the file's length, angle and rate units, so that figures, steps and error messages give
lengths, speeds and angles as the file does ("250 mm", "60°").
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from .narration import Quantity, fixed, significant

__all__ = ["Units", "LENGTH_UNITS"]

LENGTH_UNITS = {"mm": 1e-3, "cm": 1e-2, "m": 1.0, "in": 0.0254}
"""Length units a file may state, with their size in metres."""


@dataclass(frozen=True, slots=True)
class Units:
    """How the source file states its numbers; figures and text speak in these."""

    length: str = "mm"
    angle: str = "deg"
    angular_velocity: str = "rad/s"

    @property
    def metres(self) -> float:
        """Size of one length unit in metres."""
        return LENGTH_UNITS[self.length]

    def length_text(self, metres: float, digits: int = 4) -> str:
        """Format a length given in metres in the file's unit ("250 mm")."""
        return f"{fixed(metres / self.metres, digits)} {self.length}"

    def length_drawn(self, metres: float) -> str:
        """A length (m) as a figure sets it, to drafting precision: four significant
        figures, in the file's unit ("679.1 mm")."""
        return f"{significant(metres / self.metres, 4)} {self.length}"

    def length_brief(self, metres: float) -> str:
        """A length (m) as an error message gives it: six significant figures, in the
        file's unit ("264.575 mm")."""
        return f"{significant(metres / self.metres)} {self.length}"

    def angle_brief(self, rad: float) -> str:
        """An angle (rad) as an error message gives it, in the file's angle unit, to six
        significant figures: "−100.335°", "1.0472 rad"."""
        if self.angle == "rad":
            return f"{significant(rad)} rad"
        return f"{significant(math.degrees(rad))}°"

    def length_said(self, metres: float) -> Quantity:
        """A length (m) as a step says it, in the file's unit: "250 mm"."""
        return Quantity(metres / self.metres, self.length)

    def speed_said(self, v: float) -> Quantity:
        """A speed (m/s) as a step says it: "406.712 mm/s"."""
        return Quantity(v / self.metres, self.length, "/s", "rate")

    def acceleration_said(self, a: float) -> Quantity:
        """An acceleration (m/s²) as a step says it: "535.64 mm/s²"."""
        return Quantity(a / self.metres, self.length, "/s²", "rate")

    def angle_said(self, rad: float) -> Quantity:
        """An angle (rad) as a step says it, in the file's angle unit: "60°" or "1.0472 rad"."""
        if self.angle == "rad":
            return Quantity(rad, "rad", style="fixed")
        return Quantity(math.degrees(rad), "°")
