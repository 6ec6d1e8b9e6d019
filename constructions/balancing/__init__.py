"""Balancing: rotating masses by the force and couple polygons, and the reciprocating
engine (001 ch. 7)."""
