"""The linkages' constructions: position by compass, the instant centres, the velocity
methods, both polygons, the limit positions and the readings taken off them."""
