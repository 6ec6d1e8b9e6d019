"""The linkages' figures: the kinematic diagram, the scene each construction is drawn on,
the circle diagram, the polygon panels and the worked page."""
