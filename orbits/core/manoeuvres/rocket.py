"""Section X of the notes: variable mass and the rocket equation, with the sign of its rocket case corrected.

Float64 arrays in SI units (masses in kg, speeds in m/s, thrust in N, times in s); everything broadcasts, and
the multi-stage functions take the stages along the last axis (bottom stage first).

One law covers both cases of the notes: a body of mass m that takes in (X.i) or throws out (X.ii) mass moving at
v_rel relative to itself changes its velocity by

    v2 - v1 = v_rel ln(m2 / m1)

Gaining mass (m2 > m1) moves it along v_rel; ejecting mass (m2 < m1) moves it against the exhaust. The notes'
X.ii prints -v_rel ln(M2 / M1), which would push a rocket along its exhaust. For a rocket with exhaust speed
v_e = |v_rel| this is Tsiolkovsky's dv = v_e ln(m0 / mf), and at constant thrust F the mass flow is R = F / v_e.

The logarithm of a ratio near 1 is formed as log1p((m2 - m1) / m1), exact to a few ulp for every ratio
(tests/core/test_rocket.py: <= 2 ulp against mpmath); the burns at constant thrust are checked against a heyoka
integration of m dv/dt = -R v_rel, dm/dt = -R, and mass gain likewise with the signs of R and v_rel
(tests/validation/test_manoeuvres_integration.py, 1e-15).
"""

import numpy as np
from numpy.typing import ArrayLike


def log_mass_ratio(m1: ArrayLike, m2: ArrayLike) -> float | np.ndarray:
    """ln(m2 / m1) (dimensionless): log1p((m2 - m1) / m1) where m2 lies within half of m1 (no loss of digits when
    m2 is close to m1), else log(m2 / m1), the ratio exact to half an ulp and far from 1; where that ratio leaves
    float64's normal range (1e-300 kg from 1e300 kg), log(m2) - log(m1), whose terms then differ by more than 1400."""
    m1, m2 = np.asarray(m1, dtype=float), np.asarray(m2, dtype=float)
    with np.errstate(over="ignore", under="ignore", divide="ignore", invalid="ignore"):
        difference = (m2 - m1) / m1
        ratio = m2 / m1
        normal = np.isfinite(ratio) & (ratio >= np.finfo(float).tiny)
        far = np.where(normal, np.log(np.where(normal, ratio, 1.0)), np.log(m2) - np.log(m1))
        return np.where(np.abs(difference) <= 0.5, np.log1p(np.where(np.abs(difference) <= 0.5, difference, 0.0)),
                        far)


def velocity_change(v_rel: ArrayLike, m1: ArrayLike, m2: ArrayLike) -> float | np.ndarray:
    """v2 - v1 = v_rel ln(m2 / m1) (m/s): mass gain (X.i, m2 > m1) and ejection (X.ii, m2 < m1) alike.

    v_rel (m/s) is the velocity of the mass taken in or thrown out relative to the body (a component along any
    axis); m1, m2 (kg) the masses before and after. The notes' rocket case (X.ii) prints the opposite sign, which
    would push a rocket along its exhaust.
    """
    return v_rel * log_mass_ratio(m1, m2)


def ideal_delta_v(exhaust_speed: ArrayLike, initial_mass: ArrayLike, final_mass: ArrayLike) -> float | np.ndarray:
    """Tsiolkovsky's dv = v_e ln(m0 / mf) (m/s) for exhaust speed v_e (m/s) and masses m0 >= mf (kg)."""
    return exhaust_speed * log_mass_ratio(final_mass, initial_mass)


def exhaust_speed(specific_impulse: ArrayLike, g0: ArrayLike) -> float | np.ndarray:
    """v_e = Isp g0 (m/s) from the specific impulse Isp (s) and standard gravity g0 (m/s**2)."""
    return specific_impulse * g0


def propellant_for(delta_v: ArrayLike, exhaust_speed: ArrayLike, initial_mass: ArrayLike) -> float | np.ndarray:
    """Propellant m0 (1 - exp(-dv / v_e)) (kg) that gives dv (m/s) to a vehicle of initial mass m0 (kg),
    as -m0 expm1(-dv / v_e) so that small burns keep their digits."""
    return -initial_mass * np.expm1(-np.divide(delta_v, exhaust_speed))


def mass_flow(thrust: ArrayLike, exhaust_speed: ArrayLike) -> float | np.ndarray:
    """R = F / v_e (kg/s): propellant consumed per second at thrust F (N); the notes' thrust is R v_rel (X.ii)."""
    return np.divide(thrust, exhaust_speed)


def burn_time(thrust: ArrayLike, exhaust_speed: ArrayLike, initial_mass: ArrayLike,
              final_mass: ArrayLike) -> float | np.ndarray:
    """t_b = (m0 - mf) v_e / F (s): the time to burn m0 - mf (kg) of propellant at constant thrust F (N)."""
    return (initial_mass - final_mass) * exhaust_speed / thrust


def speed_during_burn(exhaust_speed: ArrayLike, initial_mass: ArrayLike, flow: ArrayLike,
                      t: ArrayLike) -> float | np.ndarray:
    """v(t) = v_e ln(m0 / (m0 - R t)) (m/s) gained in free space after burning for t (s) at mass flow R (kg/s)."""
    m0 = np.asarray(initial_mass, dtype=float)
    return -exhaust_speed * np.log1p(-flow * t / m0)


def distance_during_burn(exhaust_speed: ArrayLike, initial_mass: ArrayLike, flow: ArrayLike,
                         t: ArrayLike) -> float | np.ndarray:
    """s(t) = v_e (t - (m / R) ln(m0 / m)) (m), m = m0 - R t: distance covered from rest in free space while
    burning at mass flow R (kg/s), the integral of speed_during_burn."""
    m0 = np.asarray(initial_mass, dtype=float)
    mass = m0 - flow * t
    return exhaust_speed * (t + mass / flow * np.log1p(-flow * t / m0))


def stage_masses(structure: ArrayLike, propellant: ArrayLike,
                 payload: ArrayLike) -> tuple[np.ndarray, np.ndarray]:
    """(mass at ignition, mass at burnout) (kg) of each stage of a serial vehicle, stages on the last axis.

    Stage k ignites carrying itself, every stage above it and the payload; it burns out when its propellant is
    gone and drops its structure before stage k + 1 ignites.
    """
    structure, propellant = np.broadcast_arrays(np.asarray(structure, float), np.asarray(propellant, float))
    stage = structure + propellant
    above = np.flip(np.cumsum(np.flip(stage, axis=-1), axis=-1), axis=-1) - stage  # the stages above each one
    ignition = above + stage + np.asarray(payload, dtype=float)[..., None]
    return ignition, ignition - propellant


def staged_delta_v(exhaust_speed: ArrayLike, ignition_mass: ArrayLike,
                   burnout_mass: ArrayLike) -> np.ndarray:
    """Total dv = sum_k v_e,k ln(m0_k / mf_k) (m/s) of a serial vehicle, stages on the last axis."""
    return np.sum(ideal_delta_v(exhaust_speed, ignition_mass, burnout_mass), axis=-1)


def gravity_loss(g: ArrayLike, burn_duration: ArrayLike) -> float | np.ndarray:
    """g t_b (m/s): the speed a vertical ascent in uniform gravity g (m/s**2) loses over a burn of t_b (s),
    from m dv/dt = F - m g; the speed at burnout is v_e ln(m0 / mf) - g t_b."""
    return g * burn_duration
