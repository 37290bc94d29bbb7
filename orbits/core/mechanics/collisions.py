"""Section IX of the notes: collisions of two bodies with a coefficient of restitution, on float64 arrays.

Masses in kg, velocities in m/s (scalars along a line, or vectors with the components on the last axis),
energies in J, spring constants in N/m; the restitution e is dimensionless in [0, 1] (e = 1 elastic, e = 0
completely inelastic). Everything broadcasts. The velocities after are written through the mass fractions
x1 = m1 / (m1 + m2), x2 = m2 / (m1 + m2) (orbits.core.encounters.binary, each within 0.5 ulp) and the relative velocity,

    v1' = v1 - (1 + e) x2 (v1 - v2),        v2' = v2 + (1 + e) x1 (v1 - v2),

which is the notes' (1 + e) v_c - e v_i (IX.xi) without forming v_c: a light body bouncing off a heavy one
keeps its digits. Oblique collisions (IX.xiii) change only the components along the line of impact.
Accuracy: within 10 ulp (of the larger speed) of the notes' formula at 50 digits (measured 8), momentum conserved
to 8 ulp (tests/core/test_collisions.py); a heyoka integration of a spring-dashpot contact gives the same velocities
after to 4.4e-16 of |v1 - v2| (tests/validation/test_mechanics_integration.py).
"""

import numpy as np
from numpy.typing import ArrayLike

from orbits.core.checks import check_finite
from orbits.core.encounters.binary import mass_fractions, reduced_mass
from orbits.core.errors import OrbitDomainError

__all__ = [
    "reduced_mass",
    "check_restitution",
    "center_of_mass_velocity",
    "internal_kinetic_energy",
    "kinetic_energy",
    "velocities_after",
    "line_of_impact",
    "require_relative_motion",
    "oblique_velocities_after",
    "energy_lost",
    "perpendicular_foot",
    "energy_transfer_ratio",
    "energy_kept_ratio",
    "spring_compression",
    "restitution_of_spring_dashpot",
    "bounce_off_moving_wall",
]


def check_restitution(e: ArrayLike) -> None:
    """Raise OrbitDomainError unless every coefficient of restitution e is finite and in [0, 1]."""
    check_finite(e, "coefficient of restitution e", "(dimensionless)")
    e = np.asarray(e, dtype=float)
    bad = (e < 0) | (e > 1)
    if np.any(bad):
        value = float(e[bad].flat[0])
        raise OrbitDomainError(
            f"coefficient of restitution e = {value!r} is outside the allowed range [0, 1] (dimensionless): "
            "1 is elastic, 0 completely inelastic"
        )


def _dot(a, b):
    return np.sum(np.asarray(a) * np.asarray(b), axis=-1)


def center_of_mass_velocity(m1: ArrayLike, v1: ArrayLike, m2: ArrayLike, v2: ArrayLike) -> np.ndarray:
    """v_c = (m1 v1 + m2 v2) / (m1 + m2) = x1 v1 + x2 v2 (m/s) (IX.vii); scalars, or vectors on the last axis
    with masses of shape (...)."""
    x1, x2 = mass_fractions(m1, m2)
    if np.ndim(v1) > np.ndim(x1) or np.ndim(v2) > np.ndim(x1):
        x1, x2 = np.asarray(x1)[..., None], np.asarray(x2)[..., None]
    return x1 * np.asarray(v1, dtype=float) + x2 * np.asarray(v2, dtype=float)


def internal_kinetic_energy(m1: ArrayLike, v1: ArrayLike, m2: ArrayLike, v2: ArrayLike, vectors: bool = False):
    """K_int = mu |v1 - v2|**2 / 2 (J), mu = m1 m2 / (m1 + m2): the kinetic energy in the centre-of-mass frame
    (IX.iv). With vectors=True, v1 and v2 carry components on the last axis."""
    dv = np.asarray(v1, dtype=float) - np.asarray(v2, dtype=float)
    squared = _dot(dv, dv) if vectors else dv * dv
    return 0.5 * reduced_mass(m1, m2) * squared


def kinetic_energy(m: ArrayLike, v: ArrayLike, vectors: bool = False):
    """K = m |v|**2 / 2 (J); with vectors=True, v carries components on the last axis."""
    v = np.asarray(v, dtype=float)
    return 0.5 * np.asarray(m, dtype=float) * (_dot(v, v) if vectors else v * v)


def velocities_after(m1: ArrayLike, v1: ArrayLike, m2: ArrayLike, v2: ArrayLike, e: ArrayLike = 1.0):
    """(v1', v2') (m/s) of a head-on collision along a line with restitution e (IX.vii, ix, xi: e = 1, 0, between).

    v1' = (1 + e) v_c - e v1 = v1 - (1 + e) x2 (v1 - v2), v2' = (1 + e) v_c - e v2 = v2 + (1 + e) x1 (v1 - v2);
    the relative velocity reverses and shrinks by e, momentum is conserved and K_int' = e**2 K_int. The formula
    holds whatever the signs; that the bodies approach (v1 > v2 with body 1 behind) is the caller's business.
    """
    x1, x2 = mass_fractions(m1, m2)
    v1, v2 = np.asarray(v1, dtype=float), np.asarray(v2, dtype=float)
    kick = (1.0 + np.asarray(e, dtype=float)) * (v1 - v2)
    return v1 - kick * x2, v2 + kick * x1


def line_of_impact(v1: ArrayLike, v2: ArrayLike) -> np.ndarray:
    """n = (v1 - v2) / |v1 - v2| (dimensionless): the notes' line of impact, along the relative velocity
    (IX.xiii). Raises OrbitDomainError where v1 = v2 (the bodies never meet)."""
    dv = np.asarray(v1, dtype=float) - np.asarray(v2, dtype=float)
    size = np.linalg.norm(dv, axis=-1)
    require_relative_motion(size)
    return dv / size[..., None]


def require_relative_motion(speed: ArrayLike) -> None:
    """OrbitDomainError where the relative speed |v1 - v2| is 0: bodies at one velocity never meet, on a line as in
    a plane (a head-on collision of equal velocities would report a collision that did not happen)."""
    if np.any(np.asarray(speed) == 0):
        raise OrbitDomainError("relative velocity v1 - v2 = 0 m/s: the bodies do not approach, so they never collide")


def oblique_velocities_after(
    m1: ArrayLike, v1: ArrayLike, m2: ArrayLike, v2: ArrayLike, e: ArrayLike = 1.0, normal: ArrayLike | None = None
):
    """(v1', v2') (m/s, vectors on the last axis) when the impulse acts along the unit vector `normal` (IX.xiii).

    v1' = v1 - (1 + e) x2 ((v1 - v2) . n) n, v2' = v2 + (1 + e) x1 ((v1 - v2) . n) n: the components along n
    collide as in velocities_after, the others are unchanged. Without `normal`, n is the relative velocity's
    direction (the notes' model: a head-on impact of smooth spheres); for an oblique impact of smooth spheres
    pass the line of centres at contact. Raises OrbitDomainError if the bodies separate along n.
    """
    v1, v2 = np.asarray(v1, dtype=float), np.asarray(v2, dtype=float)
    n = line_of_impact(v1, v2) if normal is None else _unit(normal)
    approach = _dot(v1 - v2, n)
    if np.any(approach <= 0):
        value = float(np.asarray(approach)[approach <= 0].flat[0]) if np.ndim(approach) else float(approach)
        raise OrbitDomainError(
            f"approach speed (v1 - v2) . n = {value!r} m/s is outside the allowed range (0, inf) m/s: the bodies "
            "do not approach along the line of impact, so they do not collide"
        )
    x1, x2 = mass_fractions(m1, m2)
    kick = ((1.0 + np.asarray(e, dtype=float)) * approach)[..., None] * n
    return v1 - np.asarray(x2)[..., None] * kick, v2 + np.asarray(x1)[..., None] * kick


def energy_lost(m1: ArrayLike, v1: ArrayLike, m2: ArrayLike, v2: ArrayLike, e: ArrayLike = 1.0,
                normal: ArrayLike | None = None, vectors: bool = False) -> np.ndarray:
    """K - K' = (1 - e**2) mu v_n**2 / 2 (J) (IX.xi): only the approach speed v_n along the line of impact
    (v1 - v2 on a line; along `normal`, or the relative velocity, for vectors) gives up energy. Formed so rather
    than as the difference of the kinetic energies, so that an elastic collision loses exactly 0."""
    e = np.asarray(e, dtype=float)
    if vectors:
        dv = np.asarray(v1, dtype=float) - np.asarray(v2, dtype=float)
        n = line_of_impact(v1, v2) if normal is None else _unit(normal)
        approach = _dot(dv, n)
    else:
        approach = np.asarray(v1, dtype=float) - np.asarray(v2, dtype=float)
    return 0.5 * (1.0 - e) * (1.0 + e) * reduced_mass(m1, m2) * approach * approach


def _unit(n):
    n = np.asarray(n, dtype=float)
    size = np.linalg.norm(n, axis=-1)
    if np.any(size == 0) or not np.all(np.isfinite(size)):
        raise OrbitDomainError("line of impact n must be a finite nonzero vector")
    return n / size[..., None]


def perpendicular_foot(v1: ArrayLike, v2: ArrayLike) -> np.ndarray:
    """v_t = ((|v2|**2 - v1.v2) v1 + (|v1|**2 - v1.v2) v2) / |v1 - v2|**2 (m/s): the foot of the perpendicular
    from the origin to the line through v1 and v2 (IX.xiii, oblique collisions), the velocity both keep across the
    line of impact, so that v_i = v_t + (v_i . n) n."""
    v1, v2 = np.asarray(v1, dtype=float), np.asarray(v2, dtype=float)
    cross = _dot(v1, v2)
    dv = v1 - v2
    weight1, weight2 = _dot(v2, v2) - cross, _dot(v1, v1) - cross
    return (weight1[..., None] * v1 + weight2[..., None] * v2) / _dot(dv, dv)[..., None]


def energy_transfer_ratio(mass_ratio: ArrayLike, e: ArrayLike = 1.0):
    """K2' / K1 = (1 + e)**2 r / (1 + r)**2 (dimensionless), r = m1 / m2: the share of a moving body's kinetic
    energy given to a body at rest (IX.viii). Elastic: 4 r / (1 + r)**2 = 4 m1 m2 / (m1 + m2)**2 (the
    notes' second form drops the 4); 1 at r = 1, 8/9 at r = 1/2 and 2."""
    r = np.asarray(mass_ratio, dtype=float)
    share = r / (1.0 + r)  # m1 / (m1 + m2)
    return (1.0 + np.asarray(e, dtype=float)) ** 2 * share / (1.0 + r)


def energy_kept_ratio(mass_ratio: ArrayLike, e: ArrayLike = 1.0):
    """K1' / K1 = ((r - e) / (1 + r))**2 (dimensionless), r = m1 / m2: what the moving body keeps (IX.viii);
    elastic: ((1 - r) / (1 + r))**2."""
    r = np.asarray(mass_ratio, dtype=float)
    return ((r - np.asarray(e, dtype=float)) / (1.0 + r)) ** 2


def spring_compression(m1: ArrayLike, v1: ArrayLike, m2: ArrayLike, v2: ArrayLike, k: ArrayLike):
    """x = |v1 - v2| sqrt(mu / k) (m): the greatest compression of a massless spring of constant k (N/m) between
    the bodies, from k x**2 / 2 = K_int (IX.xii)."""
    dv = np.abs(np.asarray(v1, dtype=float) - np.asarray(v2, dtype=float))
    return dv * np.sqrt(reduced_mass(m1, m2) / np.asarray(k, dtype=float))


def restitution_of_spring_dashpot(damping_ratio: ArrayLike):
    """e = exp(-pi zeta / sqrt(1 - zeta**2)) (dimensionless) of a linear spring-dashpot contact with damping ratio
    zeta = c / (2 sqrt(k mu)) < 1: the relative motion during contact is an underdamped oscillation (XXV.v) that
    leaves contact after half a damped period. The contact model the integration tests collide with."""
    zeta = np.asarray(damping_ratio, dtype=float)
    return np.exp(-np.pi * zeta / np.sqrt((1.0 - zeta) * (1.0 + zeta)))


def bounce_off_moving_wall(wall_velocity: ArrayLike, velocity: ArrayLike, e: ArrayLike = 1.0):
    """v' = (1 + e) U - e v (m/s): a body bouncing off an infinitely heavy one moving at U, the m1 >> m2 limit of
    velocities_after (IX.xi). Elastic: v' = 2 U - v, the notes' view of a gravitational slingshot."""
    u = np.asarray(wall_velocity, dtype=float)
    v = np.asarray(velocity, dtype=float)
    e = np.asarray(e, dtype=float)
    return u + e * (u - v)
