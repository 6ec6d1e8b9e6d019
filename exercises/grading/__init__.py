"""Grading a student's graphical solution against tarsim's own, item by item.

:mod:`.drawing` reads an SVG drawing safely; :mod:`.polygon` finds its poles and tips by
their labels and grades each against the polygons tarsim draws, at a tolerance the
drafting precision and the construction's conditioning set; :mod:`.answers` grades a table
of numbers; :mod:`.report` writes grade.json, grade.svg and a class's grades.csv.
"""

from .grade import Grade, Item, grade

__all__ = ["Grade", "Item", "grade"]
