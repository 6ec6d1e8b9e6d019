"""tarsim (ترسیم, "graphical construction"): the compass-and-ruler methods of planar
mechanism kinematics, drawn as textbook figures and checked against an analytic solution.

Installed, this file is the ``tarsim`` package itself; the repository keeps the
three layers in its top-level folders, installed as ``tarsim.constructions``,
``tarsim.graphics`` and ``tarsim.exercises`` (pyproject's ``package-dir``).
"""
