"""The force chapter: joint forces, driving torque and efforts by force polygons, the inertia
loads read off the acceleration polygon (kinetostatics). The registry's entry is
:mod:`~.answers`; :mod:`~.polygons` draws a position's analysis."""
