"""The independent analytic reference every construction is checked against.

It shares nothing with the graphical methods but the mechanism model
(:mod:`..model`) and the error classes: a check can never agree with a
construction because the two share a mistake. A test of the import graph holds
it to that (``tests/test_import_graph.py``).

* :mod:`.solver`: positions in closed form polished by Newton, and exact
  velocities and accelerations from the differentiated loop equations; what it gives,
  and its refusal at a dead point, are in :mod:`.kinematics`, the closed form in
  :mod:`.dyad_assembly`, the equations in :mod:`.loop_equations`;
* :mod:`.centres`: instant centres where two links' velocity fields agree;
* :mod:`.limits`: the limit positions, where the output's velocity changes sign;
* :mod:`.rotatability`: Grashof's rule, and which links turn fully by turning them;
* :mod:`.mobility`: the mobility as the nullity of the loop equations' Jacobian, and where
  a position adds to it (a change point).
"""
