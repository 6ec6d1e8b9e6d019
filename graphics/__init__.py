"""Figures: panels, scales, textbook symbols, SVG via svgwrite, PDF/PNG via cairosvg."""
