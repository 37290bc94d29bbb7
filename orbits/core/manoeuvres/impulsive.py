"""Impulsive manoeuvres between circular orbits about one primary: Hohmann, bi-elliptic, plane changes, phasing
and a hyperbolic departure (the notes' cosmic velocities, XXI.ix, as a burn from a parking orbit).

Float64 arrays in SI units (radii in m, mu in m**3/s**2, speeds in m/s, times in s, angles in rad); everything
broadcasts. A signed speed change is positive along the motion (prograde) and negative against it.

Every difference of nearly equal speeds is formed without cancellation, from the vis-viva law
v**2 = mu (2 / r - 1 / a): e.g. sqrt(2 r2 / (r1 + r2)) - 1 = ((r2 - r1) / (r1 + r2)) / (1 + sqrt(2 r2 / (r1 + r2))),
so a transfer between radii 1e-9 apart keeps every digit (tests/core/test_manoeuvres.py, <= 4 ulp against
mpmath). ImpulsePlan lays a manoeuvre out as burns at given times for the N-body check in
orbits.validate.manoeuvres, which integrates it with rebound and heyoka and matches the predicted final orbit to
1.5e-13 (tests/validation/test_manoeuvres_integration.py).
"""

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike

from orbits.core.twobody.propagate import propagate
from orbits.core.twobody.twobody import circular_angular_velocity, circular_speed


def half_period(a: ArrayLike, mu: ArrayLike) -> float | np.ndarray:
    """pi sqrt(a**3 / mu) (s): the time from one apsis to the other on an ellipse of semi-major axis a (m)."""
    return np.pi * np.sqrt(a**3 / mu)


def apsis_speed(r: ArrayLike, r_other: ArrayLike, mu: ArrayLike) -> float | np.ndarray:
    """sqrt(2 mu r_other / (r (r + r_other))) (m/s): speed at the apsis r (m) of the ellipse whose other apsis is
    r_other (m) (vis-viva with a = (r + r_other) / 2)."""
    return np.sqrt(2.0 * mu * r_other / (r * (r + r_other)))


def leg_delta_v(r_from: ArrayLike, r_to: ArrayLike, mu: ArrayLike) -> float | np.ndarray:
    """v_c ((r_to - r_from) / (r_from + r_to)) / (1 + sqrt(2 r_to / (r_from + r_to))) (m/s): the signed burn at
    r_from (m) that turns the circular orbit there into the ellipse with its other apsis at r_to (m); equal to
    apsis_speed(r_from, r_to) - v_c without the cancellation."""
    total = r_from + r_to
    return circular_speed(r_from, mu) * ((r_to - r_from) / total) / (1.0 + np.sqrt(2.0 * r_to / total))


def hohmann_delta_v(r1: ArrayLike, r2: ArrayLike, mu: ArrayLike) -> tuple[np.ndarray, np.ndarray]:
    """(dv1, dv2) (m/s), signed: the two tangential burns of the Hohmann transfer from the circular orbit r1 to
    the circular orbit r2 (m); both prograde when raising, both retrograde when lowering."""
    return leg_delta_v(r1, r2, mu), -leg_delta_v(r2, r1, mu)


def hohmann_time(r1: ArrayLike, r2: ArrayLike, mu: ArrayLike) -> float | np.ndarray:
    """pi sqrt(((r1 + r2) / 2)**3 / mu) (s): half the period of the transfer ellipse."""
    return half_period(0.5 * (r1 + r2), mu)


def bielliptic_delta_v(r1: ArrayLike, r2: ArrayLike, rb: ArrayLike,
                       mu: ArrayLike) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(dv1, dv2, dv3) (m/s), signed: out from r1 to the apoapsis rb, the burn at rb that moves the periapsis
    from r1 to r2, and the circularising burn at r2 (radii in m, rb above both).

    dv2 = sqrt(2 mu / rb) (sqrt(r2 / (r2 + rb)) - sqrt(r1 / (r1 + rb))), formed as
    sqrt(2 mu / rb) rb (r2 - r1) / ((r2 + rb)(r1 + rb)(sqrt(r2 / (r2 + rb)) + sqrt(r1 / (r1 + rb)))).
    """
    high, low = np.sqrt(r2 / (r2 + rb)), np.sqrt(r1 / (r1 + rb))
    middle = np.sqrt(2.0 * mu / rb) * (rb * (r2 - r1) / ((r2 + rb) * (r1 + rb))) / (high + low)
    return leg_delta_v(r1, rb, mu), middle, -leg_delta_v(r2, rb, mu)


def bielliptic_time(r1: ArrayLike, r2: ArrayLike, rb: ArrayLike, mu: ArrayLike) -> float | np.ndarray:
    """pi (sqrt(a1**3 / mu) + sqrt(a2**3 / mu)) (s), a1 = (r1 + rb) / 2 and a2 = (r2 + rb) / 2."""
    return half_period(0.5 * (r1 + rb), mu) + half_period(0.5 * (r2 + rb), mu)


def plane_change_delta_v(speed: ArrayLike, angle: ArrayLike) -> float | np.ndarray:
    """2 v sin(di / 2) (m/s): the burn that turns a velocity of speed v (m/s) by di (rad), keeping its speed."""
    return 2.0 * speed * np.sin(0.5 * angle)


def combined_delta_v(v_before: ArrayLike, v_after: ArrayLike, angle: ArrayLike) -> float | np.ndarray:
    """|v_after - v_before| = sqrt((v1 - v2)**2 + 4 v1 v2 sin**2(di / 2)) (m/s) for speeds v1, v2 (m/s) at an
    angle di (rad): the law of cosines sqrt(v1**2 + v2**2 - 2 v1 v2 cos di) without its cancellation."""
    return np.hypot(v_before - v_after, 2.0 * np.sqrt(v_before * v_after) * np.sin(0.5 * angle))


def phasing_fraction(phase: ArrayLike, revolutions: ArrayLike) -> float | np.ndarray:
    """x = phase / (2 pi k): the phasing orbit's period is T (1 - x), for a target `phase` (rad) ahead (< 0:
    behind) to be met after k revolutions."""
    return phase / (2.0 * np.pi * revolutions)


def phasing_semi_major_axis(r: ArrayLike, phase: ArrayLike, revolutions: ArrayLike) -> float | np.ndarray:
    """a = r (1 - x)**(2/3) (m) of the phasing orbit through the burn point of the circular orbit r (m)."""
    return r * np.exp((2.0 / 3.0) * np.log1p(-phasing_fraction(phase, revolutions)))


def phasing_delta_v(r: ArrayLike, phase: ArrayLike, revolutions: ArrayLike,
                    mu: ArrayLike) -> float | np.ndarray:
    """Signed burn (m/s) onto the phasing orbit at r (m); the burn back onto the circle is its negative.

    v - v_c = (v**2 - v_c**2) / (v + v_c) with v**2 - v_c**2 = mu (a - r) / (a r) and
    a - r = r expm1((2/3) log1p(-x)), so a small phase keeps its digits.
    """
    growth = np.expm1((2.0 / 3.0) * np.log1p(-phasing_fraction(phase, revolutions)))
    a = r * (1.0 + growth)
    v_circle = circular_speed(r, mu)
    v = np.sqrt(mu * (2.0 / r - 1.0 / a))
    return (mu * growth / a) / (v + v_circle)


def phasing_time(r: ArrayLike, phase: ArrayLike, revolutions: ArrayLike, mu: ArrayLike) -> float | np.ndarray:
    """k T (1 - x) (s): k revolutions of the phasing orbit, T = 2 pi sqrt(r**3 / mu) the circular period."""
    period = 2.0 * np.pi / circular_angular_velocity(r, mu)
    return revolutions * period * (1.0 - phasing_fraction(phase, revolutions))


def departure_delta_v(r: ArrayLike, v_inf: ArrayLike, mu: ArrayLike) -> float | np.ndarray:
    """sqrt(v_inf**2 + 2 mu / r) - sqrt(mu / r) (m/s): the prograde burn from the circular orbit r (m) onto the
    hyperbola that leaves with speed v_inf (m/s) at infinity (energy conservation, XXI.ix)."""
    return np.sqrt(v_inf**2 + 2.0 * mu / r) - circular_speed(r, mu)


# ---- a manoeuvre as burns at times, for the N-body check ----------------------------------------------------


@dataclass(frozen=True)
class ImpulsePlan:
    """A manoeuvre laid out in space and time (SI, scalars): the start state, each impulse and the prediction.

    The vehicle starts at r0 with v0 about mu; impulse k adds delta_v[k] (m/s) at times[k] (s, increasing, the
    first at 0); at `duration` (s) the closed form predicts the state (final_r, final_v).
    """

    mu: float
    r0: np.ndarray
    v0: np.ndarray
    times: np.ndarray
    delta_v: np.ndarray
    duration: float
    final_r: np.ndarray
    final_v: np.ndarray


def _tilted_basis(inclination):
    """x_hat and y_hat turned by the inclination about the x axis: the plane of an orbit with its node on x."""
    x_hat = np.array([1.0, 0.0, 0.0])
    y_hat = np.array([0.0, np.cos(inclination), np.sin(inclination)])
    return x_hat, y_hat


def _circle_state(r, mu, angle, inclination=0.0):
    """Position and velocity at `angle` (rad from the x axis) on the prograde circle r in the tilted plane."""
    x_hat, y_hat = _tilted_basis(inclination)
    speed = circular_speed(r, mu)
    position = r * (np.cos(angle) * x_hat + np.sin(angle) * y_hat)
    return position, speed * (-np.sin(angle) * x_hat + np.cos(angle) * y_hat)


def _plan(mu, r1, times, kicks, duration, final):
    r0, v0 = _circle_state(r1, mu, 0.0)
    return ImpulsePlan(float(mu), r0, v0, np.asarray(times, float), np.asarray(kicks, float), float(duration),
                       *final)


def hohmann_plan(r1: float, r2: float, mu: float, inclination_change: float = 0.0,
                 coast: float = 0.0) -> ImpulsePlan:
    """Hohmann transfer r1 -> r2 (m) from (r1, 0, 0), the plane turned by `inclination_change` (rad) about the
    line of apsides at the burn at the larger radius (the slower one); `coast` (s) on the final circle."""
    tilt_first = inclination_change if r1 > r2 else 0.0
    transfer_1, transfer_2 = apsis_speed(r1, r2, mu), apsis_speed(r2, r1, mu)
    _, y_start = _tilted_basis(tilt_first)
    _, y_end = _tilted_basis(inclination_change)
    kick_1 = transfer_1 * y_start - circular_speed(r1, mu) * np.array([0.0, 1.0, 0.0])
    kick_2 = -circular_speed(r2, mu) * y_end + transfer_2 * y_start
    t = hohmann_time(r1, r2, mu)
    final = _circle_state(r2, mu, np.pi + circular_angular_velocity(r2, mu) * coast, inclination_change)
    return _plan(mu, r1, [0.0, t], [kick_1, kick_2], t + coast, final)


def bielliptic_plan(r1: float, r2: float, rb: float, mu: float, coast: float = 0.0) -> ImpulsePlan:
    """Bi-elliptic transfer r1 -> rb -> r2 (m) from (r1, 0, 0): out to (-rb, 0, 0), back in to (r2, 0, 0)."""
    dv1, dv2, dv3 = bielliptic_delta_v(r1, r2, rb, mu)
    t1 = half_period(0.5 * (r1 + rb), mu)
    t2 = t1 + half_period(0.5 * (r2 + rb), mu)
    kicks = [[0.0, dv1, 0.0], [0.0, -dv2, 0.0], [0.0, dv3, 0.0]]
    final = _circle_state(r2, mu, circular_angular_velocity(r2, mu) * coast)
    return _plan(mu, r1, [0.0, t1, t2], kicks, t2 + coast, final)


def plane_change_plan(r: float, inclination_change: float, mu: float, coast: float = 0.0) -> ImpulsePlan:
    """A pure plane change on the circle r (m) at (r, 0, 0), by `inclination_change` (rad) about the x axis."""
    speed = circular_speed(r, mu)
    _, y_end = _tilted_basis(inclination_change)
    kick = speed * (y_end - np.array([0.0, 1.0, 0.0]))
    final = _circle_state(r, mu, circular_angular_velocity(r, mu) * coast, inclination_change)
    return _plan(mu, r, [0.0], [kick], coast, final)


def phasing_plan(r: float, phase: float, revolutions: int, mu: float, coast: float = 0.0) -> ImpulsePlan:
    """Phasing on the circle r (m) to meet a target `phase` (rad) ahead after `revolutions`; the prediction is
    the target's own state at the end (the rendezvous)."""
    dv = phasing_delta_v(r, phase, revolutions, mu)
    t = phasing_time(r, phase, revolutions, mu)
    final = _circle_state(r, mu, phase + circular_angular_velocity(r, mu) * (t + coast))
    return _plan(mu, r, [0.0, t], [[0.0, dv, 0.0], [0.0, -dv, 0.0]], t + coast, final)


def departure_plan(r: float, v_inf: float, mu: float, coast: float) -> ImpulsePlan:
    """Departure from the circle r (m) onto the hyperbola with excess speed v_inf (m/s); the state after
    `coast` (s) is predicted by Kepler's equation (orbits.core.twobody.propagate)."""
    r0, v0 = _circle_state(r, mu, 0.0)
    kick = np.array([0.0, departure_delta_v(r, v_inf, mu), 0.0])
    final = propagate(r0, v0 + kick, mu, coast)
    return _plan(mu, r, [0.0], [kick], coast, final)
