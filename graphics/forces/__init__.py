"""The force analysis's figures: the loads on the space diagram, the force polygons and the
free bodies."""
