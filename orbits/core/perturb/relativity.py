"""General relativity's secular turn of an orbit's periapsis (float64, SI, radians).

At first post-Newtonian order (1PN, Schwarzschild field of a mass with G M = mu), the periapsis advances each
revolution by

    delta omega = 6 pi mu / (c**2 a (1 - e**2)) = 6 pi mu / (c**2 p),

in the orbit's plane and the sense of its motion; node and inclination stay put. The neglected 2PN terms are
smaller by mu / (c**2 p) (2.6e-8 for Mercury), and the osculating periapsis oscillates within each revolution by a
term of that relative size, which averages out over whole revolutions. Mercury: 42.98 arcsec per Julian century.
"""

import numpy as np
from numpy.typing import ArrayLike


def periapsis_advance_per_orbit(p: ArrayLike, mu: ArrayLike, c: ArrayLike) -> np.ndarray:
    """delta omega = 6 pi mu / (c**2 p) (rad per revolution), p = a (1 - e**2) (m), mu (m**3/s**2), c (m/s)."""
    return 6.0 * np.pi * np.asarray(mu, dtype=float) / (np.asarray(c, dtype=float) ** 2 * np.asarray(p, dtype=float))


def periapsis_advance_rate(a: ArrayLike, e: ArrayLike, mu: ArrayLike, c: ArrayLike) -> np.ndarray:
    """domega/dt = 3 n mu / (c**2 a (1 - e**2)) (rad/s): the advance per orbit over the period 2 pi / n."""
    a = np.asarray(a, dtype=float)
    e = np.asarray(e, dtype=float)
    n = np.sqrt(np.asarray(mu, dtype=float) / a**3)
    return n * periapsis_advance_per_orbit(a * (1.0 - e) * (1.0 + e), mu, c) / (2.0 * np.pi)
