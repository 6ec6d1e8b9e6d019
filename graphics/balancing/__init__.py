"""The balancing figures: a rotor's end and side views and the force and couple polygons."""
