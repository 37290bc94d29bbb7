"""Section XXI.ix-xi of the notes: cosmic velocities, synchronous orbits, maximum elongation.

Float64 arrays in SI units (r, R in m; mu in m**3/s**2; g in m/s**2; speeds in m/s; T in s; angles in rad);
everything broadcasts. The escape speed sqrt(2 mu / r) itself is orbits.core.twobody.twobody.escape_speed.
Accuracy against mpmath (tests/core/test_escape.py): <= 1 ulp for the cosmic velocities, <= 2 ulp for the
synchronous radius and for the elongation up to r / R = 1 - 1e-12.
"""

import numpy as np
from numpy.typing import ArrayLike

from orbits.core.encounters.binary import semi_major_axis_from_period

#: sqrt(2) - 1 correctly rounded (the literal is exact to 27 digits), so no subtraction is needed.
SQRT2_MINUS_1 = 0.414213562373095048801688724


def surface_gravity(mu: ArrayLike, radius: ArrayLike) -> float | np.ndarray:
    """g = mu / R**2 (m/s**2) at distance R (m) from a body of parameter mu = G M (m**3/s**2)."""
    return mu / radius**2


def first_cosmic_velocity(g: ArrayLike, radius: ArrayLike) -> float | np.ndarray:
    """v1 = sqrt(g R) (m/s): circular speed skimming the surface (XXI.ix); 7.904 km/s for g0 and R = 6371 km."""
    return np.sqrt(g * radius)


def second_cosmic_velocity(g: ArrayLike, radius: ArrayLike) -> float | np.ndarray:
    """v2 = sqrt(2 g R) (m/s): escape speed from the surface, twobody.escape_speed(R, g R**2) (XXI.ix); 11.178 km/s."""
    return np.sqrt(2.0 * g * radius)


def escape_excess_speed(orbital_speed: ArrayLike) -> float | np.ndarray:
    """(sqrt 2 - 1) v (m/s): speed relative to a planet on a circular orbit of speed v (m/s) that, added along its
    motion, reaches the local solar escape speed sqrt(2) v (patched conics, XXI.ix, cosmic velocities)."""
    return SQRT2_MINUS_1 * orbital_speed


def third_cosmic_velocity(orbital_speed: ArrayLike, surface_escape_speed: ArrayLike) -> float | np.ndarray:
    """v3 = sqrt(((sqrt 2 - 1) v_orbit)**2 + v_esc**2) (m/s): launch speed that leaves the planet with the solar
    escape excess (energy conservation in the planet's field, patched conics; XXI.ix, cosmic velocities). For Earth,
    v_orbit = 29.785 km/s and v_esc = 11.178 km/s give 16.648 km/s (the notes' 16.7)."""
    return np.hypot(escape_excess_speed(orbital_speed), surface_escape_speed)


def synchronous_radius(mu: ArrayLike, rotation_period: ArrayLike) -> float | np.ndarray:
    """r = (mu T**2 / (4 pi**2))**(1/3) (m): the circular orbit whose period equals the sidereal rotation period T
    (s) of a body of parameter mu (m**3/s**2) (XXI.x); 42164.17 km for Earth (geostationary when equatorial)."""
    return semi_major_axis_from_period(rotation_period, mu)


def max_elongation(inner_radius: ArrayLike, outer_radius: ArrayLike) -> float | np.ndarray:
    """Greatest angle star-observer-planet arcsin(r / R) (rad) for circular coplanar orbits r < R (m), reached
    when the line of sight is tangent to the inner orbit (XXI.xi). Evaluated as atan2(r, sqrt((R - r)(R + r))),
    well conditioned up to r -> R where arcsin(r / R) would amplify the rounding of r / R."""
    return np.arctan2(inner_radius, np.sqrt((outer_radius - inner_radius) * (outer_radius + inner_radius)))
