"""Rotations between the equatorial (ICRF) and ecliptic frames of J2000, float64, vectors shaped (..., 3).

The JPL ephemerides are referred to the ICRF, whose axes agree with the mean equator and equinox of J2000 to
about 0.02 arcsec. The "ecliptic and mean equinox of J2000" of JPL's Horizons and of Standish's mean elements
is the ICRF rotated about its x axis (the equinox) by the IAU 1976 obliquity of J2000, 84381.448 arcsec.
"""

import math

import numpy as np

#: obliquity of the ecliptic at J2000 (rad): IAU 1976, 84381.448 arcsec, as JPL uses for ecliptic J2000
OBLIQUITY_J2000 = math.radians(84381.448 / 3600.0)


def _about_x(angle: float) -> np.ndarray:
    c, s = math.cos(angle), math.sin(angle)
    return np.array([[1.0, 0.0, 0.0], [0.0, c, s], [0.0, -s, c]])


#: R such that x_ecliptic = R @ x_equatorial
ECLIPTIC_FROM_EQUATORIAL = _about_x(OBLIQUITY_J2000)


def equatorial_to_ecliptic(x: np.ndarray) -> np.ndarray:
    """x_ecl = R1(eps0) x_eq for vectors shaped (..., 3); exact to rounding (|error| <= 2 ulp of |x|)."""
    return np.asarray(x, dtype=float) @ ECLIPTIC_FROM_EQUATORIAL.T


def ecliptic_to_equatorial(x: np.ndarray) -> np.ndarray:
    """x_eq = R1(-eps0) x_ecl for vectors shaped (..., 3), the inverse of equatorial_to_ecliptic."""
    return np.asarray(x, dtype=float) @ ECLIPTIC_FROM_EQUATORIAL
