"""Section XXV of the notes: oscillators and pendulums, on float64 arrays.

SI units: lengths in m, times in s, angles in rad, g in m/s**2, masses in kg, moments of inertia in kg m**2,
frequencies in rad/s; a damped oscillator x'' = -k (x - C) - b x' (XXV.v) takes k in 1/s**2 and b in 1/s (force
per unit mass). Everything broadcasts.

- Pendulums (XXV.iv): theta'' = -(g / L) sin(theta), I theta'' = -m g L sin(theta), with the minus sign of a
  restoring torque that the notes leave out; small-angle frequency sqrt(g / L), sqrt(m g L / I) (the notes'
  sqrt(I / (m g L)) is a time). The exact period at amplitude theta0 is
  4 K(sin**2(theta0 / 2)) / omega0 = 2 pi / (omega0 AGM(1, cos(theta0 / 2))), the complete elliptic integral of
  the first kind by the arithmetic-geometric mean, with no cancellation up to theta0 -> pi.
- Damped oscillators (XXV.v): the initial-value solution in one form for all three regimes, continuous across
  critical damping; and the notes' parametrisations with their derivatives, corrected where the notes' underdamped
  x' has the opposite sign and x'' the wrong phase, and where their critically damped x' and x'' are wrong.
- Driven oscillator (XXV.vii): the steady state's amplitude and phase lag, resonance.
- Vertical circle (XXV.vi): speed, normal force, turning and leaving angles, the periods T1 (looping) and T2
  (swinging) by the AGM; where the notes' signs or angles differ, each function says how.
Accuracy (tests/core/test_oscillations.py): K(m) within 1 ulp and the pendulum period within 2 ulp of mpmath up to
theta0 = 180 - 1e-6 degrees; damped motion within 1.2e-16 (of the initial scale) of a 50-digit solution in every
regime. Against heyoka integrations of the same equations (tests/validation/test_mechanics_integration.py): periods
to 9e-15 relative (to 170 degrees), damped and driven motion to 7e-15 and 4e-14, vertical-circle angles to 1.4e-15.
"""

import numpy as np
from numpy.typing import ArrayLike

from orbits.core.errors import ConvergenceError, OrbitDomainError

# ---- the arithmetic-geometric mean and K(m) -------------------------------------------------------------------


def agm(a: ArrayLike, b: ArrayLike) -> np.ndarray:
    """AGM(a, b) of positive numbers: a, b <- (a + b) / 2, sqrt(a b) until they agree; quadratic convergence, at
    most 6 steps for b / a >= 1e-16 and within 2 ulp (tests/core/test_oscillations.py)."""
    a, b = np.broadcast_arrays(np.asarray(a, dtype=float), np.asarray(b, dtype=float))
    a, b = a.copy(), b.copy()
    for _ in range(64):
        if np.all(np.abs(a - b) <= 2.0**-52 * a):
            return 0.5 * (a + b)
        a, b = 0.5 * (a + b), np.sqrt(a * b)
    raise ConvergenceError("arithmetic-geometric mean did not converge in 64 steps (inputs not positive?)")


def ellipk_from_complement(complement_root: ArrayLike) -> np.ndarray:
    """K(m) = pi / (2 AGM(1, k')) (dimensionless), given k' = sqrt(1 - m) in (0, 1]: the complete elliptic integral
    of the first kind, int_0^(pi/2) d phi / sqrt(1 - m sin**2 phi) (parameter m = k**2, as in mpmath.ellipk)."""
    return 0.5 * np.pi / agm(1.0, complement_root)


def ellipk(m: ArrayLike) -> np.ndarray:
    """K(m) (dimensionless) for m < 1 (parameter convention of mpmath.ellipk); for m near 1 pass the complement
    to ellipk_from_complement instead, as 1 - m loses digits."""
    m = np.asarray(m, dtype=float)
    if np.any(m >= 1):
        raise OrbitDomainError(f"elliptic parameter m = {float(m.max())!r} is outside the allowed range (-inf, 1)")
    return ellipk_from_complement(np.sqrt(1.0 - m))


# ---- pendulums (XXV.i-iv) -------------------------------------------------------------------------------------


def simple_pendulum_frequency(g: ArrayLike, length: ArrayLike) -> np.ndarray:
    """omega0 = sqrt(g / L) (rad/s): small oscillations of L theta'' = -g sin(theta) (XXV.iv, where the notes
    drop the minus)."""
    return np.sqrt(np.asarray(g, dtype=float) / np.asarray(length, dtype=float))


def physical_pendulum_frequency(mass: ArrayLike, g: ArrayLike, distance: ArrayLike, inertia: ArrayLike):
    """omega0 = sqrt(m g L / I) (rad/s): I theta'' = -m g L sin(theta), L the pivot-to-centre-of-mass distance and
    I the moment about the pivot (XXV.iv, where the notes print sqrt(I / (m g L)), which is a time)."""
    return np.sqrt(np.asarray(mass, dtype=float) * np.asarray(g) * np.asarray(distance) / np.asarray(inertia))


def torsion_frequency(kappa: ArrayLike, inertia: ArrayLike) -> np.ndarray:
    """Omega = sqrt(kappa / I) (rad/s) of a torsion pendulum tau = -kappa theta (XXV.ii): kappa = I
    Omega**2, where the notes print m Omega**2."""
    return np.sqrt(np.asarray(kappa, dtype=float) / np.asarray(inertia, dtype=float))


def spring_pair_frequency(k: ArrayLike, m1: ArrayLike, m2: ArrayLike) -> np.ndarray:
    """omega = sqrt(k / mu) (rad/s), mu = m1 m2 / (m1 + m2): two bodies on a spring of constant k (N/m) (XXV.iii)."""
    m1, m2 = np.asarray(m1, dtype=float), np.asarray(m2, dtype=float)
    return np.sqrt(np.asarray(k, dtype=float) * (1.0 / m1 + 1.0 / m2))


def pendulum_period(omega0: ArrayLike, amplitude: ArrayLike) -> np.ndarray:
    """T = 4 K(sin**2(theta0 / 2)) / omega0 = 2 pi / (omega0 AGM(1, cos(theta0 / 2))) (s): the exact period at
    amplitude theta0 in [0, pi) (XXV.vi's T2 with u = 2 sqrt(g R) sin(theta0 / 2))."""
    return 2.0 * np.pi / (np.asarray(omega0, dtype=float) * agm(1.0, np.cos(0.5 * np.asarray(amplitude))))


def pendulum_period_series(amplitude: ArrayLike, terms: int = 4) -> np.ndarray:
    """T / T0 = sum_n ((2n)! / (2**(2n) (n!)**2))**2 sin**(2n)(theta0 / 2) (dimensionless), the first `terms`
    terms: 1 + theta0**2 / 16 + ... for small amplitudes (the textbook correction)."""
    k2 = np.sin(0.5 * np.asarray(amplitude, dtype=float)) ** 2
    total, coefficient, power = np.zeros_like(k2), 1.0, np.ones_like(k2)
    for n in range(terms):
        total = total + coefficient**2 * power
        coefficient *= (2 * n + 1) / (2 * n + 2)
        power = power * k2
    return total


def pendulum_angle(omega0: ArrayLike, amplitude: ArrayLike, t: ArrayLike) -> np.ndarray:
    """theta(t) (rad) of a pendulum released from rest at theta0 (|theta0| < pi) at t = 0, exactly:
    sin(theta / 2) = k cd(omega0 t, k), k = sin(theta0 / 2), with the Jacobi function evaluated by the descending
    Landen (AGM) transformation. Used by the plots and checked against heyoka."""
    k = np.sin(0.5 * np.asarray(amplitude, dtype=float))
    u = np.asarray(omega0, dtype=float) * np.asarray(t, dtype=float)
    complement = np.cos(0.5 * np.asarray(amplitude, dtype=float))
    quarter = ellipk_from_complement(complement)
    sn, cn, dn = _jacobi_sn_cn_dn(u + quarter, k, complement)  # cd(u) = sn(u + K)
    return 2.0 * np.arcsin(np.clip(k * sn, -1.0, 1.0))


def _jacobi_sn_cn_dn(u, k, complement):
    """(sn, cn, dn)(u | k**2) by the AGM sequence a_n, b_n, c_n and the backward recurrence for the amplitude
    phi (Abramowitz and Stegun 16.4)."""
    u, k, complement = np.broadcast_arrays(*(np.asarray(x, dtype=float) for x in (u, k, complement)))
    a, b, cs = [np.ones_like(k)], [complement.copy()], [k.copy()]
    for _ in range(64):
        if np.all(np.abs(cs[-1]) <= 2.0**-53 * a[-1]):
            break
        a_new, b_new = 0.5 * (a[-1] + b[-1]), np.sqrt(a[-1] * b[-1])
        cs.append(0.5 * (a[-1] - b[-1]))
        a.append(a_new)
        b.append(b_new)
    n = len(a) - 1
    phi = 2.0**n * a[-1] * u
    for j in range(n, 0, -1):
        phi = 0.5 * (phi + np.arcsin(np.clip(cs[j] / a[j] * np.sin(phi), -1.0, 1.0)))
    sn, cn = np.sin(phi), np.cos(phi)
    return sn, cn, np.sqrt(1.0 - (k * sn) ** 2)


# ---- damped oscillators (XXV.v) -------------------------------------------------------------------------------

REGIMES = ("underdamped", "critically damped", "overdamped")


def damping_regime(k: ArrayLike, b: ArrayLike) -> np.ndarray:
    """0, 1 or 2 for b**2 < 4k (underdamped), = 4k (critically damped), > 4k (overdamped) (XXV.v)."""
    k, b = np.asarray(k, dtype=float), np.asarray(b, dtype=float)
    return np.where(b * b < 4 * k, 0, np.where(b * b == 4 * k, 1, 2))


def damped_frequency(k: ArrayLike, b: ArrayLike) -> np.ndarray:
    """omega_d = sqrt(4k - b**2) / 2 (rad/s) when underdamped, else 0 (XXV.v)."""
    k, b = np.asarray(k, dtype=float), np.asarray(b, dtype=float)
    return 0.5 * np.sqrt(np.maximum((2 * np.sqrt(k) - b) * (2 * np.sqrt(k) + b), 0.0))


def _expm1_ratio(z):
    """expm1(z) / z, 1 at z = 0."""
    safe = np.where(z == 0, 1.0, z)
    return np.where(z == 0, 1.0, np.expm1(safe) / safe)


def _basis(k, b, t):
    """(e^(-bt/2) C, e^(-bt/2) S, and their time derivatives): the basis of x'' + b x' + k x = 0 in which
    x = e^(-bt/2) [x0 C + (v0 + b x0 / 2) S], with C(0) = 1, C'(0) = 0, S(0) = 0, S'(0) = 1.

    Underdamped C = cos(w t), S = sin(w t) / w; overdamped C = cosh(g t), S = sinh(g t) / g formed as
    e^(-bt/2) sinh(g t) / g = e^(-(b/2 + g) t) t expm1(2 g t) / (2 g t), free of cancellation near critical
    damping (g -> 0) and of overflow for long times; critical S = t.
    """
    k, b, t = np.broadcast_arrays(*(np.asarray(x, dtype=float) for x in (k, b, t)))
    root_k = np.sqrt(k)
    delta = (2 * root_k - b) * (2 * root_k + b) / 4.0  # k - b**2 / 4, factored
    half = 0.5 * b
    w = np.sqrt(np.abs(delta))
    under = delta > 0
    decay = np.exp(-half * t)
    wt = w * t
    safe_w = np.where(w > 0, w, 1.0)
    c_under = decay * np.cos(wt)
    s_under = decay * np.where(w > 0, np.sin(wt) / safe_w, t)
    fast = np.exp(-(half + w) * t)
    near = 2.0 * wt <= 30.0  # expm1 form near critical damping; two exponentials, no overflow, further out
    ratio = _expm1_ratio(np.where(near, 2.0 * wt, 0.0))
    slow = np.exp(np.where(under, 0.0, -k / (half + w)) * t)  # e^((w - b/2) t), the rate formed without cancelling
    s_over = np.where(near, fast * t * ratio, (slow - fast) / (2.0 * np.where(near, 1.0, w)))
    c_over = np.where(near, fast * (1.0 + wt * ratio), 0.5 * (slow + fast))
    c = np.where(under, c_under, c_over)
    s = np.where(under, s_under, s_over)
    # derivatives: (e C)' = -half e C + e C', C' = -w**2 S (under) or +w**2 S (over); (e S)' = -half e S + e C
    c_dot = -half * c - delta * s
    s_dot = c - half * s
    return c, s, c_dot, s_dot


def damped_motion(k: ArrayLike, b: ArrayLike, x0: ArrayLike, v0: ArrayLike, t: ArrayLike):
    """(x, v) (m, m/s) of x'' = -k x - b x' from x(0) = x0, x'(0) = v0, in every regime (XXV.v, C = 0):
    x = e^(-bt/2) [x0 C(t) + (v0 + b x0 / 2) S(t)]; see _basis. Continuous across b**2 = 4k."""
    c, s, c_dot, s_dot = _basis(k, b, t)
    x0, v0 = np.asarray(x0, dtype=float), np.asarray(v0, dtype=float)
    drive = v0 + 0.5 * np.asarray(b) * x0
    return x0 * c + drive * s, x0 * c_dot + drive * s_dot


def underdamped_notes(amplitude, phase, k, b, t):
    """(x, x', x'') of the notes' x = A e^(-bt/2) sin(psi), psi = omega_d t + phi (XXV.v, C = 0), with the
    corrected derivatives x' = A sqrt(k) e^(-bt/2) sin(psi + delta), x'' = A k e^(-bt/2) sin(psi + 2 delta),
    delta = arccos(-b / (2 sqrt(k))). The notes' phase arctan(-sqrt(4k - b**2) / b) is delta - pi, which flips the
    sign of their x'; their x'' has delta where 2 delta belongs."""
    k, b, t = (np.asarray(x, dtype=float) for x in (k, b, t))
    psi = damped_frequency(k, b) * t + phase
    delta = np.arccos(-b / (2.0 * np.sqrt(k)))
    envelope = amplitude * np.exp(-0.5 * b * t)
    return envelope * np.sin(psi), envelope * np.sqrt(k) * np.sin(psi + delta), envelope * k * np.sin(psi + 2 * delta)


def underdamped_energy_notes(mass, amplitude, phase, k, b, t):
    """K + U = (m A**2 k / 2) e^(-bt) [1 + (b / (2 sqrt(k))) cos(2 psi + delta)] (J), exactly; the notes'
    (m A**2 k / 2) e^(-bt) holds only for b << 2 sqrt(k)."""
    k, b, t = (np.asarray(x, dtype=float) for x in (k, b, t))
    psi = damped_frequency(k, b) * t + phase
    delta = np.arccos(-b / (2.0 * np.sqrt(k)))
    return 0.5 * mass * amplitude**2 * k * np.exp(-b * t) * (1.0 + b / (2.0 * np.sqrt(k)) * np.cos(2 * psi + delta))


def critically_damped_notes(amplitude, rate, b, t):
    """(x, x', x'') of the notes' x = A (1 + B t) e^(-bt/2) (XXV.v, k = b**2 / 4, C = 0), corrected:
    x' = A (2B - b (1 + B t)) / 2 e^(-bt/2), x'' = A b (b (1 + B t) - 4B) / 4 e^(-bt/2); the notes print B for 2B
    in x' and a wrong x''."""
    b, t = np.asarray(b, dtype=float), np.asarray(t, dtype=float)
    decay = amplitude * np.exp(-0.5 * b * t)
    line = 1.0 + rate * t
    return decay * line, decay * (2 * rate - b * line) / 2, decay * b * (b * line - 4 * rate) / 4


def overdamped_notes(amplitude, ratio, k, b, t):
    """(x, x', x'') of the notes' x = A e^(-bt/2) (e^(gt) + B e^(-gt)), g = sqrt(b**2 - 4k) / 2 (XXV.v, C = 0),
    with the notes' derivatives, which are correct."""
    k, b, t = (np.asarray(x, dtype=float) for x in (k, b, t))
    root = np.sqrt(b * b - 4 * k)
    slow, fast = np.exp((-b + root) / 2 * t), ratio * np.exp((-b - root) / 2 * t)
    x = amplitude * (slow + fast)
    v = amplitude * ((-b + root) / 2 * slow + (-b - root) / 2 * fast)
    a = amplitude * ((b * b - 2 * k - b * root) / 2 * slow + (b * b - 2 * k + b * root) / 2 * fast)
    return x, v, a


# ---- driven oscillator (XXV.vii) ------------------------------------------------------------------------------


def driven_amplitude(omega0: ArrayLike, b: ArrayLike, force_per_mass: ArrayLike, drive: ArrayLike) -> np.ndarray:
    """A = (F0 / m) / sqrt((omega0**2 - w**2)**2 + b**2 w**2) (m): steady state of x'' + b x' + omega0**2 x =
    (F0 / m) cos(w t), x = A cos(w t - delta) (XXV.vii)."""
    w0, b, w = (np.asarray(x, dtype=float) for x in (omega0, b, drive))
    return np.asarray(force_per_mass, dtype=float) / np.hypot((w0 - w) * (w0 + w), b * w)


def driven_phase_lag(omega0: ArrayLike, b: ArrayLike, drive: ArrayLike) -> np.ndarray:
    """delta = atan2(b w, omega0**2 - w**2) (rad) in [0, pi]: pi/2 at resonance w = omega0 (XXV.vii), also
    without damping, as its limit b -> 0 (atan2(0, 0) would say 0)."""
    w0, b, w = (np.asarray(x, dtype=float) for x in (omega0, b, drive))
    return np.where((w == w0) & (w0 != 0), 0.5 * np.pi, np.arctan2(b * w, (w0 - w) * (w0 + w)))[()]


def driven_velocity_amplitude(omega0, b, force_per_mass, drive) -> np.ndarray:
    """w A (m/s): largest at w = omega0 for every damping (XXV.vii), where it is F0 / (m b)."""
    return np.asarray(drive, dtype=float) * driven_amplitude(omega0, b, force_per_mass, drive)


def displacement_resonance(omega0: ArrayLike, b: ArrayLike) -> np.ndarray:
    """w_r = sqrt(omega0**2 - b**2 / 2) (rad/s), where A peaks; 0 when b**2 >= 2 omega0**2 (no peak)."""
    w0, b = np.asarray(omega0, dtype=float), np.asarray(b, dtype=float)
    root2 = np.sqrt(2.0)
    return np.sqrt(np.maximum((w0 - b / root2) * (w0 + b / root2), 0.0))


def driven_steady_state(omega0, b, force_per_mass, drive, t):
    """(x, v) (m, m/s) of the steady state A cos(w t - delta) (XXV.vii)."""
    amplitude = driven_amplitude(omega0, b, force_per_mass, drive)
    phase = np.asarray(drive) * np.asarray(t, dtype=float) - driven_phase_lag(omega0, b, drive)
    return amplitude * np.cos(phase), -np.asarray(drive) * amplitude * np.sin(phase)


# ---- the vertical circle (XXV.vi) -----------------------------------------------------------------------------


def circle_speed(u: ArrayLike, g: ArrayLike, radius: ArrayLike, theta: ArrayLike) -> np.ndarray:
    """v = sqrt(u**2 - 2 g R (1 - cos(theta))) = sqrt(u**2 - 4 g R sin**2(theta / 2)) (m/s) at angle theta (rad)
    from the lowest point, for bottom speed u (XXV.vi); NaN where the bead cannot reach theta."""
    s = np.sin(0.5 * np.asarray(theta, dtype=float))
    squared = np.asarray(u, dtype=float) ** 2 - 4.0 * np.asarray(g) * np.asarray(radius) * s * s
    with np.errstate(invalid="ignore"):
        return np.where(squared >= 0, np.sqrt(np.maximum(squared, 0.0)), np.nan)


def circle_normal_force(mass, u, g, radius, theta) -> np.ndarray:
    """N = m v**2 / R + m g cos(theta) = (m / R)(u**2 - 2 g R + 3 g R cos(theta)) (N), the force toward the centre
    (string tension, track push) (XXV.vi, where the notes print - m g cos(theta) and 1 g R cos(theta))."""
    g, radius = np.asarray(g, dtype=float), np.asarray(radius, dtype=float)
    return np.asarray(mass) / radius * (np.asarray(u) ** 2 - 2 * g * radius + 3 * g * radius * np.cos(theta))


def circle_angular_acceleration(g, radius, theta) -> np.ndarray:
    """theta'' = -(g / R) sin(theta) (rad/s**2) (XXV.vi): restoring, with the minus
    the notes leave out."""
    return -np.asarray(g, dtype=float) / np.asarray(radius) * np.sin(theta)


def turning_angle(u, g, radius) -> np.ndarray:
    """theta_m = arccos(1 - u**2 / (2 g R)) = 2 asin(u / (2 sqrt(g R))) (rad), where v = 0, for u <= 2 sqrt(g R)
    (the notes print arccos(u**2 / (2 g R))); the asin form keeps small angles' digits."""
    ratio = np.asarray(u, dtype=float) / (2.0 * np.sqrt(np.asarray(g) * np.asarray(radius)))
    return 2.0 * np.arcsin(np.minimum(ratio, 1.0))


def leaving_angle(u, g, radius) -> np.ndarray:
    """theta with cos(theta) = (2 g R - u**2) / (3 g R) (rad): where N = 0 and a string slackens or a bead on the
    outside of a track leaves it, between pi/2 and pi for sqrt(2 g R) < u < sqrt(5 g R) (beyond the
    horizontal diameter, where the notes place it); NaN outside that range."""
    gr = np.asarray(g, dtype=float) * np.asarray(radius)
    cos_theta = (2.0 * gr - np.asarray(u) ** 2) / (3.0 * gr)
    inside = (cos_theta > -1) & (cos_theta < 0)
    return np.where(inside, np.arccos(np.clip(cos_theta, -1.0, 1.0)), np.nan)


def loop_period(u, g, radius) -> np.ndarray:
    """T1 = R int_0^2pi d theta / v = 4 R K(4 g R / u**2) / u = 2 pi R / (u AGM(1, sqrt(1 - 4 g R / u**2))) (s) for
    u > 2 sqrt(g R) (XXV.vi); the complement formed as (u - 2 sqrt(gR))(u + 2 sqrt(gR)) / u**2."""
    u, g, radius = (np.asarray(x, dtype=float) for x in (u, g, radius))
    edge = 2.0 * np.sqrt(g * radius)
    complement = np.sqrt((u - edge) * (u + edge)) / u
    return 2.0 * np.pi * radius / (u * agm(1.0, complement))


def swing_period(u, g, radius) -> np.ndarray:
    """T2 = 4 R int_0^theta_m d theta / v = 4 K(u**2 / (4 g R)) sqrt(R / g) = 2 pi sqrt(R / g) / AGM(1,
    sqrt(1 - u**2 / (4 g R))) (s) for u < 2 sqrt(g R) (XXV.vi): the pendulum of amplitude theta_m."""
    u, g, radius = (np.asarray(x, dtype=float) for x in (u, g, radius))
    edge = 2.0 * np.sqrt(g * radius)
    complement = np.sqrt((edge - u) * (edge + u)) / edge
    return 2.0 * np.pi * np.sqrt(radius / g) / agm(1.0, complement)
