"""Gravity assists: the notes' elastic collision with a moving planet (IX.vii) and its patched-conic form.

Float64 arrays in SI units (speeds in m/s, periapsis in m, mu in m**3/s**2, angles in rad); vectors are (..., 3)
and everything broadcasts.

In the planet's frame a flyby is an elastic collision (IX.vii, restitution e = 1; the collision itself, with any
e, is orbits.core.mechanics.collisions.velocities_after): the probe leaves with the
speed it came with, v_inf, turned by the deflection delta = 2 asin(1 / e_h) of orbits.core.encounters.flyby, e_h =
1 + r_p v_inf**2 / mu the hyperbola's eccentricity. Back in the Sun's frame the probe's velocity has changed by
the vector v_inf_out - v_inf_in, of length 2 v_inf sin(delta / 2) = 2 v_inf / e_h, and its energy per unit mass by
V . (v_out - v_in), V the planet's velocity. The head-on limit (delta = pi) is the notes' m1 >> m2 case,
v2' = 2 v1 - v2. A Sun-planet-probe integration agrees to the order of the planet's mass ratio
(tests/validation/test_manoeuvres_integration.py).
"""

import numpy as np
from numpy.typing import ArrayLike


def focusing(v_inf: ArrayLike, periapsis: ArrayLike, mu: ArrayLike) -> float | np.ndarray:
    """k = r_p v_inf**2 / mu = e_h - 1 (dimensionless): how far the hyperbola is from a parabola."""
    return periapsis * v_inf**2 / mu


def delta_v_magnitude(v_inf: ArrayLike, periapsis: ArrayLike, mu: ArrayLike) -> float | np.ndarray:
    """|v_out - v_in| = 2 v_inf sin(delta / 2) = 2 v_inf / (1 + k) (m/s): the velocity change, the same in the
    planet's and the Sun's frame."""
    return 2.0 * v_inf / (1.0 + focusing(v_inf, periapsis, mu))


def _unit(x):
    return x / np.linalg.norm(x, axis=-1, keepdims=True)


def turn(v_inf: ArrayLike, normal: ArrayLike, angle: ArrayLike) -> np.ndarray:
    """v_inf (..., 3) turned by `angle` (rad) counterclockwise about `normal` (..., 3), taken perpendicular to
    v_inf (its component along v_inf is dropped): v cos(angle) + (n_hat x v) sin(angle) (Rodrigues)."""
    v_inf = np.asarray(v_inf, dtype=float)
    normal = np.asarray(normal, dtype=float)
    along = np.sum(normal * v_inf, axis=-1, keepdims=True) / np.sum(v_inf * v_inf, axis=-1, keepdims=True)
    n_hat = _unit(normal - along * v_inf)
    angle = np.asarray(angle, dtype=float)[..., None]
    return v_inf * np.cos(angle) + np.cross(n_hat, v_inf) * np.sin(angle)


def outgoing_velocity(v_in: ArrayLike, v_planet: ArrayLike, normal: ArrayLike,
                      angle: ArrayLike) -> np.ndarray:
    """v_out = V + turn(v_in - V) (m/s, (..., 3)): the heliocentric velocity after an elastic turn by `angle`
    (rad) in the planet's frame (IX.vii); v_in, v_planet the heliocentric velocities before."""
    v_planet = np.asarray(v_planet, dtype=float)
    return v_planet + turn(np.asarray(v_in, dtype=float) - v_planet, normal, angle)
