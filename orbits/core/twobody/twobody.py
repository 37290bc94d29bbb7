"""Section XXI of the notes: a body of mass m on a Kepler orbit about a fixed star (mu = G M).

Float64 arrays in SI units (p, a, r in m; mu in m**3/s**2; m in kg; times in s; angles in rad).
The orbit is described by its semi-latus rectum p and eccentricity e, which stay finite and well
conditioned for every conic; a = p / (1 - e**2) is derived (the notes' r1 = a - c, r2 = a + c,
c = a e; e = c / a, where XXI.iv prints the inverse a / c). Functions that only make sense on an ellipse say so.
"""

import numpy as np
from numpy.typing import ArrayLike


def semi_major_axis(p: ArrayLike, e: ArrayLike) -> float | np.ndarray:
    """a = p / ((1 - e)(1 + e)) (m); negative on hyperbolas, inf on the parabola."""
    with np.errstate(divide="ignore"):
        return p / ((1.0 - e) * (1.0 + e))


def periapsis_distance(p: ArrayLike, e: ArrayLike) -> float | np.ndarray:
    """r1 = q = p / (1 + e) = a - c (m)."""
    return p / (1.0 + e)


def apoapsis_distance(p: ArrayLike, e: ArrayLike) -> float | np.ndarray:
    """r2 = p / (1 - e) = a + c (m), ellipses only."""
    return p / (1.0 - e)


def focal_distance(p: ArrayLike, e: ArrayLike) -> float | np.ndarray:
    """c = a e = p e / (1 - e**2) (m): centre of the ellipse to the star."""
    return semi_major_axis(p, e) * e


def semi_minor_axis(p: ArrayLike, e: ArrayLike) -> float | np.ndarray:
    """b = a sqrt(1 - e**2) = p / sqrt((1 - e)(1 + e)) (m), ellipses only."""
    return p / np.sqrt((1.0 - e) * (1.0 + e))


def specific_angular_momentum(p: ArrayLike, mu: ArrayLike) -> float | np.ndarray:
    """h = sqrt(mu p) = L / m (m**2/s)."""
    return np.sqrt(mu * p)


def areal_velocity(p: ArrayLike, mu: ArrayLike) -> float | np.ndarray:
    """dA/dt = h / 2 (m**2/s), Kepler's second law."""
    return 0.5 * np.sqrt(mu * p)


def specific_energy(p: ArrayLike, e: ArrayLike, mu: ArrayLike) -> float | np.ndarray:
    """E / m = -mu (1 - e**2) / (2 p) = -mu / (2 a) (J/kg); zero on the parabola."""
    return -mu * ((1.0 - e) * (1.0 + e)) / (2.0 * p)


def speed_at_radius(r: ArrayLike, p: ArrayLike, e: ArrayLike, mu: ArrayLike) -> float | np.ndarray:
    """Vis-viva v = sqrt(mu (2 / r - (1 - e**2) / p)) (m/s)."""
    return np.sqrt(mu * (2.0 / r - ((1.0 - e) * (1.0 + e)) / p))


def periapsis_speed(p: ArrayLike, e: ArrayLike, mu: ArrayLike) -> float | np.ndarray:
    """v1 = sqrt(mu / p) (1 + e) (m/s), the fastest point."""
    return np.sqrt(mu / p) * (1.0 + e)


def apoapsis_speed(p: ArrayLike, e: ArrayLike, mu: ArrayLike) -> float | np.ndarray:
    """v2 = sqrt(mu / p) (1 - e) (m/s), ellipses only."""
    return np.sqrt(mu / p) * (1.0 - e)


def covertex_speed(p: ArrayLike, e: ArrayLike, mu: ArrayLike) -> float | np.ndarray:
    """v_b = sqrt(mu / a) (m/s): speed at the ends of the minor axis (distance a from the star)."""
    return np.sqrt(mu / semi_major_axis(p, e))


def period(p: ArrayLike, e: ArrayLike, mu: ArrayLike) -> float | np.ndarray:
    """T = 2 pi sqrt(a**3 / mu) (s), ellipses only: Kepler's third law a**3 / T**2 = mu / (4 pi**2)."""
    return 2.0 * np.pi * np.sqrt(semi_major_axis(p, e) ** 3 / mu)


def covertex_times(p: ArrayLike, e: ArrayLike, mu: ArrayLike) -> tuple[float | np.ndarray, float | np.ndarray]:
    """(T1, T2) (s): co-vertex to co-vertex through periapsis T (1/2 - e/pi), through apoapsis T (1/2 + e/pi)."""
    t = period(p, e, mu)
    return t * (0.5 - e / np.pi), t * (0.5 + e / np.pi)


def potential_energy(r: ArrayLike, mu: ArrayLike, m: ArrayLike) -> float | np.ndarray:
    """U = -G M m / r = -mu m / r (J)."""
    return -mu * m / r


def circular_speed(r: ArrayLike, mu: ArrayLike) -> float | np.ndarray:
    """v = sqrt(mu / r) (m/s) on a circular orbit of radius r."""
    return np.sqrt(mu / r)


def circular_angular_velocity(r: ArrayLike, mu: ArrayLike) -> float | np.ndarray:
    """omega = sqrt(mu / r**3) (rad/s) on a circular orbit of radius r."""
    return np.sqrt(mu / r**3)


def escape_speed(r: ArrayLike, mu: ArrayLike) -> float | np.ndarray:
    """v_esc = sqrt(2 mu / r) (m/s)."""
    return np.sqrt(2.0 * mu / r)
