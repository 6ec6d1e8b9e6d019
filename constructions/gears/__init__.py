"""The gear chapter: gear trains, their speeds by the notes' methods (000-part2 §2.14–2.15)."""
