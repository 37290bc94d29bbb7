"""Sections XXI.vi and XXII.vi of the notes: a hyperbolic encounter from speed at infinity and impact parameter.

Float64 arrays in SI units (b, r, R in m; v_inf in m/s; mu in m**3/s**2; angles in rad); everything broadcasts.
For a body passing a fixed star mu = G M (XXI.vi, the notes' u = v_inf); for two finite masses mu = G (m1 + m2)
and v_inf is their relative speed at infinity (XXII.vi: the notes' (m + M) eta), and each star moves on the
relative hyperbola scaled by its share x_j of orbits.core.encounters.binary.mass_fractions.

Every formula goes through k = b v_inf**2 / mu = cot(delta / 2), the ratio of the impact parameter to the
hyperbola's |a| = mu / v_inf**2, so nothing cancels: the notes' R = (sqrt(G**2 M**2 + u**4 b**2) - G M) / u**2
is evaluated as b k / (1 + sqrt(1 + k**2)), exact to a few ulp also for slow close passes (k << 1) where the
difference form loses every digit. tests/core/test_flyby.py measures <= 2.6 ulp against mpmath for k from
1e-8 to 1e8 (R 2.3, w 2.6, e 1.3, p 1.6, delta 1.4, nu_inf 0.8 ulp).
"""

import numpy as np
from numpy.typing import ArrayLike


def focusing_ratio(b: ArrayLike, v_inf: ArrayLike, mu: ArrayLike) -> float | np.ndarray:
    """k = b v_inf**2 / mu = b / |a| = cot(delta / 2) (dimensionless)."""
    return b * v_inf**2 / mu


def eccentricity(b: ArrayLike, v_inf: ArrayLike, mu: ArrayLike) -> float | np.ndarray:
    """e = sqrt(1 + (b v_inf**2 / mu)**2) (dimensionless), the hyperbola's eccentricity."""
    return np.hypot(1.0, focusing_ratio(b, v_inf, mu))


def semi_major_axis(v_inf: ArrayLike, mu: ArrayLike) -> float | np.ndarray:
    """a = -mu / v_inf**2 (m), negative on hyperbolas as in orbits.core.twobody.twobody (the notes' a_h = |a|)."""
    return -mu / v_inf**2


def semilatus_rectum(b: ArrayLike, v_inf: ArrayLike, mu: ArrayLike) -> float | np.ndarray:
    """p = h**2 / mu = (v_inf b)**2 / mu = b k (m)."""
    return b * focusing_ratio(b, v_inf, mu)


def periapsis_distance(b: ArrayLike, v_inf: ArrayLike, mu: ArrayLike) -> float | np.ndarray:
    """Closest approach R = b k / (1 + sqrt(1 + k**2)) = (sqrt(mu**2 + v_inf**4 b**2) - mu) / v_inf**2 (m).

    The notes' closest approach R of a flyby (XXI.vi, XXII.vi) is this periapsis |a| (e - 1) of the hyperbola.
    """
    k = focusing_ratio(b, v_inf, mu)
    return b * k / (1.0 + np.hypot(1.0, k))


def periapsis_speed(b: ArrayLike, v_inf: ArrayLike, mu: ArrayLike) -> float | np.ndarray:
    """Speed at closest approach w = v_inf (1 + sqrt(1 + k**2)) / k = (sqrt(mu**2 + v_inf**4 b**2) + mu) / (v_inf b)
    (m/s), from v_inf b = R w (XXI.vi; XXII.vi's (m + M) zeta)."""
    k = focusing_ratio(b, v_inf, mu)
    return v_inf * (1.0 + np.hypot(1.0, k)) / k


def deflection_angle(b: ArrayLike, v_inf: ArrayLike, mu: ArrayLike) -> float | np.ndarray:
    """Turning angle of the relative velocity delta = 2 atan(mu / (b v_inf**2)) = 2 asin(1 / e) (rad)."""
    return 2.0 * np.arctan2(1.0, focusing_ratio(b, v_inf, mu))


def asymptote_true_anomaly(b: ArrayLike, v_inf: ArrayLike, mu: ArrayLike) -> float | np.ndarray:
    """nu_inf = arccos(-1 / e) = atan2(k, -1) = (pi + delta) / 2 (rad): the true anomaly of the outgoing asymptote."""
    return np.arctan2(focusing_ratio(b, v_inf, mu), -1.0)


def speed_at_distance(r: ArrayLike, v_inf: ArrayLike, mu: ArrayLike) -> float | np.ndarray:
    """v = sqrt(v_inf**2 + 2 mu / r) (m/s) at distance r (m), from E = m v_inf**2 / 2 (XXI.vi)."""
    return np.sqrt(v_inf**2 + 2.0 * mu / r)


def impact_parameter(periapsis: ArrayLike, v_inf: ArrayLike, mu: ArrayLike) -> float | np.ndarray:
    """b = R sqrt(1 + 2 mu / (R v_inf**2)) (m) for a wanted closest approach R (m): the inverse of
    periapsis_distance, from v_inf b = R w and w**2 = v_inf**2 + 2 mu / R (gravitational focusing)."""
    return periapsis * np.sqrt(1.0 + 2.0 * mu / (periapsis * v_inf**2))
