"""The gear trains' figures: the train in side view, the velocity (Kutzbach) diagram and
the involute mesh."""
