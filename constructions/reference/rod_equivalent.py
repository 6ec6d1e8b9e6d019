"""The reference for a connecting rod's equivalent dynamical system: the conditions solved
as equations, not the books' closed forms.

Two point masses m1 at x1 and m2 at x2 (along the line of centres, from G) stand for the
rod when they keep its mass, its centre of mass and its moment of inertia about G:

    m1 + m2 = m,   m1·x1 + m2·x2 = 0,   m1·x1² + m2·x2² = I_G.

Given x1 (a pin), the first two are linear in the masses for any x2, and the third then
reads −m·x1·x2 = I_G, which places x2; the masses come from the 2×2 system by
``numpy.linalg.solve``. Two masses at both pins keep the first two only, and their
moment of inertia is the sum m1·x1² + m2·x2², whose excess over I_G times α is the
correction couple. The closed forms of :mod:`~tarsim.constructions.forces.equivalent`
(l2 = k²/l1, m·l2/(l1 + l2), m·l1·l3) are checked against these sums.
"""

from __future__ import annotations

import numpy as np

__all__ = ["two_masses", "second_point", "second_moment", "pendulum_period"]


def two_masses(mass: float, x1: float, x2: float) -> tuple[float, float]:
    """The masses at ``x1`` and ``x2`` (m from G, on opposite sides) that keep ``mass`` and
    G: the solution of m1 + m2 = m, m1·x1 + m2·x2 = 0.

    >>> [round(v, 12) for v in two_masses(2.0, -0.1, 0.15)]
    [1.2, 0.8]
    """
    m1, m2 = np.linalg.solve(np.array([[1.0, 1.0], [x1, x2]]), np.array([mass, 0.0]))
    return float(m1), float(m2)


def second_point(mass: float, x1: float, inertia: float) -> float:
    """Where (m from G) the second mass stands, given the first at ``x1``: the root of
    m1(x2)·x1² + m2(x2)·x2² = I_G, which with the masses of :func:`two_masses` is
    −m·x1·x2 = I_G.

    >>> round(second_point(2.0, -0.1, 2.0 * 0.11 ** 2), 12)
    0.121
    """
    return -inertia / (mass * x1)


def second_moment(masses: tuple[float, float], points: tuple[float, float]) -> float:
    """Σ m·x² of point masses about G (kg·m²).

    >>> round(second_moment((1.2, 0.8), (-0.1, 0.15)), 12)
    0.03
    """
    return float(sum(m * x * x for m, x in zip(masses, points)))


def pendulum_period(radius_of_gyration: float, h: float, g: float = 9.81) -> float:
    """The period (s) of a body of ``radius_of_gyration`` about G hung ``h`` (m) from G: a
    compound pendulum's, equal to a simple one of length (k² + h²)/h, 2π·√((k² + h²)/(g·h)).

    >>> round(pendulum_period(0.0, 1.0), 9) == round(2 * 3.141592653589793 / 9.81 ** 0.5, 9)
    True
    """
    return 2.0 * float(np.pi) * float(np.sqrt((radius_of_gyration ** 2 + h * h) / (g * h)))
