"""Figures: panels, scales, textbook symbols, SVG, PDF/PNG via cairosvg."""
