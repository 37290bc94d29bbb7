"""Section XXII.viii of the notes: the five Lagrange points of the circular restricted three-body problem.

Dimensionless units throughout: separation r = 1, G (M + m) = 1, so the binary turns at n = 1 rad per time
unit (multiply lengths by r, times by 1/n = sqrt(r**3 / (G (M + m))), speeds by n r). The only parameter is
the mass ratio mu = m / (M + m) in (0, 1/2], with M >= m. Rotating frame: barycentre at the origin, the
primary M at (-mu, 0, 0), the secondary m at (1 - mu, 0, 0), rotation about +z. (The notes put m on the -x
axis; mirror x -> -x to compare.) L1 lies between the stars, L2 beyond m, L3 beyond M, and L4 (L5) leads
(trails) m by 60 degrees, at (1/2 - mu, +-sqrt(3)/2).

Collinear points solve the exact force balance on the x axis, with the signs of x - x_M and x - x_m kept rather
than the notes' +- form. The intervals the notes' proof puts the points in have -x_m where x_m belongs (their L1
interval is empty, their L2 one holds L1); the points lie as placed above. The balance is rewritten as a quintic
in the small offset from the nearer star, so tiny mu keeps full relative accuracy: rho = h u from m for L1 and L2
(h = (mu/3)**(1/3), u -> 1 as mu -> 0), and for L3 the distance from M, s = 1 - mu w (w -> 7/12). Each root comes
from the bracketed Halley solver of orbits.core._roots. Accuracy (tests/core/test_lagrange.py, against mpmath
roots of the raw force balance at >= 50 digits): offsets within 2 ulp (measured 1.3) for mu from 1e-300 to 1/2;
positions within 2**-52 r; for mu >= 1e-15 the rotating-frame force at the returned point is below 1e-15 of the
primaries' gravity there (measured 9.7e-16; below mu ~ 1e-32 rho < 2**-52 and x_L1, x_L2 round onto the secondary:
use the offsets); eigenvalues within 2e-14 of max |lambda| (measured 8e-16) of mpmath's eig of the linearisation.
"""

import numpy as np
from numpy.typing import ArrayLike

from orbits.core._dd import cbrt
from orbits.core._roots import halley_in_bracket
from orbits.core.checks import check_finite
from orbits.core.errors import OrbitDomainError, UnknownNameError

POINTS = ("L1", "L2", "L3", "L4", "L5")


def point_index(point: str) -> int:
    """0..4 for "L1".."L5" (UnknownNameError naming the five otherwise)."""
    if point not in POINTS:
        raise UnknownNameError(f"unknown point {point!r}; choose from {', '.join(POINTS)}")
    return POINTS.index(point)


#: Routh's critical mass ratio mu_R = (1 - sqrt(23/27)) / 2, as a double-double (hi + lo) to decide
#: mu < mu_R exactly; L4 and L5 are linearly stable iff mu < mu_R.
ROUTH_MASS_RATIO = 0.0385208965045514
_ROUTH_LO = -2.49642603804579e-18

_HALF_SQRT3 = 0.8660254037844386  # sqrt(3) / 2, correctly rounded


def check_mass_ratio(mu: ArrayLike) -> np.ndarray:
    """mu as a float64 array; OrbitDomainError unless every 0 < mu <= 1/2 (M >= m > 0)."""
    mu = np.asarray(mu, dtype=float)
    check_finite(mu, "mass ratio mu = m / (M + m)", "(dimensionless)")
    bad = (mu <= 0.0) | (mu > 0.5)
    if np.any(bad):
        value = float(mu[bad].flat[0])
        why = (
            "the secondary is heavier than the primary: pass the heavier body as the primary"
            if value > 0.5
            else "a massless secondary (m = 0) puts L1 and L2 on the secondary itself: give m > 0"
        )
        raise OrbitDomainError(f"mass ratio mu = m / (M + m) = {value!r} is outside (0, 0.5]: {why}")
    return mu


def _horner(coefficients, x):
    """(p, p', p'') at x of the polynomial with the given coefficients (highest degree first)."""
    p, d1, d2 = coefficients[0], np.zeros_like(x), np.zeros_like(x)
    for c in coefficients[1:]:
        d2 = d2 * x + d1
        d1 = d1 * x + p
        p = p * x + c
    return p, d1, 2.0 * d2


def _solve(coefficients, start, lo, hi, what, mu):
    """Root in [lo, hi] of the increasing-through-zero polynomial (coefficient arrays highest first)."""

    def residual(x, idx):
        return _horner([c[idx] for c in coefficients], x)

    return halley_in_bracket(start, lo, hi, residual, what, {"mu": mu})


def _hill_scale(mu):
    """(h, mu / h, mu / h**2, mu / h**3) with h = (mu/3)**(1/3), each quotient rounded once from mu."""
    h = cbrt(mu) / cbrt(3.0)
    q1 = mu / h
    q2 = q1 / h
    return h, q1, q2, q2 / h


def collinear_offsets(mu: ArrayLike) -> tuple[np.ndarray, np.ndarray, float | np.ndarray]:
    """(rho_1, rho_2, s_3): L1 and L2 distances from m, and L3 distance from M (units of r), each within 2 ulp.

    With rho = h u: L1 solves rho**5 - (3 - mu) rho**4 + (3 - 2 mu) rho**3 - mu rho**2 + 2 mu rho - mu = 0,
    L2 solves rho**5 + (3 - mu) rho**4 + (3 - 2 mu) rho**3 - mu rho**2 - 2 mu rho - mu = 0 (divided by h**3,
    u in [0, 1] and [1, 2]); L3 has s = 1 - mu w, w in [1/2, 1], with
    mu**4 w**5 - (7 + mu) mu**3 w**4 + (19 + 6 mu) mu**2 w**3 - (24 + 13 mu) mu w**2 + (12 + 14 mu) w - 7 = 0.
    """
    mu = check_mass_ratio(mu)
    rho_1, rho_2, w = _offsets(mu)
    return rho_1, rho_2, 1.0 - mu * w


def _offsets(mu):
    """(rho_1, rho_2, w) for valid mu of any shape; L3 sits at distance 1 - mu w from M."""
    flat = np.ravel(mu).astype(float)
    return tuple(x.reshape(np.shape(mu)) for x in _solve_offsets(flat))


def _solve_offsets(mu):
    """(rho_1, rho_2, w) for a 1-D array of valid mu."""
    h, q1, q2, q3 = _hill_scale(mu)
    ones, zeros = np.ones_like(mu), np.zeros_like(mu)
    lead = h * h
    l1 = [lead, -(3.0 - mu) * h, 3.0 - 2.0 * mu, -q1, 2.0 * q2, -q3]
    l2 = [lead, (3.0 - mu) * h, 3.0 - 2.0 * mu, -q1, -2.0 * q2, -q3]
    u1 = _solve(l1, 1.0 - h / 3.0, zeros.copy(), ones.copy(), "L1 offset solve", mu)
    u2 = _solve(l2, 1.0 + h / 3.0, ones.copy(), 2.0 * ones, "L2 offset solve", mu)
    m2 = mu * mu
    l3 = [m2 * m2, -(7.0 + mu) * m2 * mu, (19.0 + 6.0 * mu) * m2, -(24.0 + 13.0 * mu) * mu, 12.0 + 14.0 * mu]
    l3.append(-7.0 * ones)
    w = _solve(l3, 7.0 / (12.0 + 14.0 * mu), 0.5 * ones, ones.copy(), "L3 offset solve", mu)
    return h * u1, h * u2, w


def positions(mu: ArrayLike) -> np.ndarray:
    """Rotating-frame positions of L1..L5, shape (..., 5, 3) (units of r), each coordinate within 2**-52 r.

    x_L1 = 1 - (mu + rho_1), x_L2 = 1 + (rho_2 - mu), x_L3 = -(mu + s_3), L4/L5 = (1/2 - mu, +-sqrt(3)/2, 0).
    """
    mu = check_mass_ratio(mu)
    rho_1, rho_2, s_3 = collinear_offsets(mu)
    x = np.stack([1.0 - (mu + rho_1), 1.0 + (rho_2 - mu), -(mu + s_3), 0.5 - mu, 0.5 - mu], axis=-1)
    y = np.broadcast_to(np.array([0.0, 0.0, 0.0, _HALF_SQRT3, -_HALF_SQRT3]), x.shape)
    return np.stack([x, y, np.zeros_like(x)], axis=-1)


def distances(mu: ArrayLike) -> np.ndarray:
    """Distances (r_1 from M, r_2 from m) of L1..L5, shape (..., 5, 2) (units of r), from the offsets."""
    mu = check_mass_ratio(mu)
    rho_1, rho_2, s_3 = collinear_offsets(mu)
    one = np.ones_like(rho_1)
    r_1 = np.stack([1.0 - rho_1, 1.0 + rho_2, s_3, one, one], axis=-1)
    r_2 = np.stack([rho_1, rho_2, 1.0 + s_3, one, one], axis=-1)
    return np.stack([r_1, r_2], axis=-1)


def effective_potential(r: ArrayLike, mu: ArrayLike) -> float | np.ndarray:
    """Phi = -(1 - mu) / r_1 - mu / r_2 - (x**2 + y**2) / 2 per unit mass (units of G (M + m) / r), notes' U / n.

    r has shape (..., 3) in the rotating frame; -inf exactly at a primary.
    """
    mu = check_mass_ratio(mu)
    r = np.asarray(r, dtype=float)
    x, y, z = r[..., 0], r[..., 1], r[..., 2]
    r_1 = np.sqrt((x + mu) ** 2 + y * y + z * z)
    r_2 = np.sqrt((x - (1.0 - mu)) ** 2 + y * y + z * z)
    return -(1.0 - mu) / r_1 - mu / r_2 - 0.5 * (x * x + y * y)


def jacobi_constant(r: ArrayLike, v: ArrayLike, mu: ArrayLike) -> float | np.ndarray:
    """C = -2 Phi(r) - |v|**2 (units of (n r)**2) of a rotating-frame state r, v of shape (..., 3)."""
    v = np.asarray(v, dtype=float)
    return -2.0 * effective_potential(r, mu) - np.sum(v * v, axis=-1)


def jacobi_constant_inertial(
    r: ArrayLike, v: ArrayLike, r_primary: ArrayLike, r_secondary: ArrayLike, mu: ArrayLike
) -> float | np.ndarray:
    """C = 2 (1 - mu) / r_1 + 2 mu / r_2 + 2 (x v_y - y v_x) - |v|**2 from barycentric inertial states.

    The same integral as jacobi_constant (v_rotating = v - z x r), measured with the primaries where an
    integration has them, so it needs no rotating frame; arrays of shape (..., 3), units of r and n r.
    """
    r, v = np.asarray(r, dtype=float), np.asarray(v, dtype=float)
    r_1 = np.linalg.norm(r - r_primary, axis=-1)
    r_2 = np.linalg.norm(r - r_secondary, axis=-1)
    spin = r[..., 0] * v[..., 1] - r[..., 1] * v[..., 0]
    return 2.0 * (1.0 - mu) / r_1 + 2.0 * mu / r_2 + 2.0 * spin - np.sum(v * v, axis=-1)


def _tidal_strength(mu):
    """(A, A - 1) at L1..L3 with A = (1 - mu) / r_1**3 + mu / r_2**3, shape (..., 3), cancellation free.

    A - 1 = -(mu + t (3 + 3t + t**2)) / r_1**3 + mu / r_2**3 with r_1 = 1 + t, which keeps the O(mu) value
    of A - 1 at L3 (t = -mu w) to full relative accuracy.
    """
    mu = check_mass_ratio(mu)
    rho_1, rho_2, w = _offsets(mu)
    t = np.stack([-rho_1, rho_2, -mu * w], axis=-1)
    r_2 = np.stack([rho_1, rho_2, 2.0 - mu * w], axis=-1)
    mu = mu[..., None]
    r_1_cubed = (1.0 + t) ** 3
    a_minus_1 = -(mu + t * (3.0 + t * (3.0 + t))) / r_1_cubed + mu / r_2**3
    return 1.0 + a_minus_1, a_minus_1


def _quadratic_roots(b, c, discriminant):
    """Both roots of L**2 + b L + c = 0 (complex arrays), cancellation free, given b**2 - 4c separately."""
    real = discriminant >= 0.0
    root = np.sqrt(np.where(real, discriminant, 0.0))
    q = -0.5 * (b + np.copysign(root, b))
    with np.errstate(divide="ignore", invalid="ignore"):
        other = np.where(q != 0.0, c / q, 0.0)
    imag = 0.5 * np.sqrt(np.where(real, 0.0, -discriminant))
    first = np.where(real, q + 0j, -0.5 * b + 1j * imag)
    second = np.where(real, other + 0j, -0.5 * b - 1j * imag)
    return first, second


def _routh_margin(mu):
    """27 (mu_R - mu)(1 - mu_R - mu) = 1 - 27 mu (1 - mu), with mu_R - mu formed exactly (double-double)."""
    return 27.0 * (((ROUTH_MASS_RATIO - mu) + _ROUTH_LO) * ((1.0 - ROUTH_MASS_RATIO - mu) - _ROUTH_LO))


def eigenvalues(mu: ArrayLike) -> np.ndarray:
    """Eigenvalues lambda (units of n) of the linearised rotating-frame motion at L1..L5, shape (..., 5, 6).

    Planar, with Omega = -Phi: lambda**4 + (4 - Omega_xx - Omega_yy) lambda**2 + Omega_xx Omega_yy - Omega_xy**2
    = 0, i.e.
    lambda**4 + (2 - A) lambda**2 + (1 + 2A)(1 - A) = 0 at L1..L3 (one real pair: saddle x centre) and
    lambda**4 + lambda**2 + 27 mu (1 - mu) / 4 = 0 at L4 and L5; then the vertical pair +-i sqrt(A) (+-i at
    L4, L5). Order: +-sqrt(L_a), +-sqrt(L_b), vertical, with L_a, L_b the roots in lambda**2.
    """
    mu = check_mass_ratio(mu)
    a, a_minus_1 = _tidal_strength(mu)
    b = np.concatenate([1.0 - a_minus_1, np.ones(mu.shape + (2,))], axis=-1)
    c_col = -(3.0 + 2.0 * a_minus_1) * a_minus_1
    c_tri = np.broadcast_to((6.75 * mu * (1.0 - mu))[..., None], mu.shape + (2,))
    c = np.concatenate([c_col, c_tri], axis=-1)
    disc_tri = np.broadcast_to(_routh_margin(mu)[..., None], mu.shape + (2,))
    disc = np.concatenate([a * (9.0 * a - 8.0), disc_tri], axis=-1)
    first, second = _quadratic_roots(b, c, disc)
    vertical = np.concatenate([np.sqrt(a), np.ones(mu.shape + (2,))], axis=-1)
    la, lb = np.sqrt(first), np.sqrt(second)
    return np.stack([la, -la, lb, -lb, 1j * vertical, -1j * vertical], axis=-1)


def growth_rates(mu: ArrayLike) -> np.ndarray:
    """Largest real part of the eigenvalues at L1..L5 (units of n), shape (..., 5); 0 where linearly stable.

    L1, L2, L3 always grow; L4 and L5 are linearly stable (growth 0) iff mu < mu_R, decided exactly. At
    mu = mu_R itself (not a float64) the double root would grow linearly in time, so the boundary is unstable.
    """
    rates = np.max(eigenvalues(mu).real, axis=-1)
    return np.where(rates > 0.0, rates, 0.0)


def triangular_points_stable(mu: ArrayLike) -> np.bool_ | np.ndarray:
    """True where L4 and L5 are linearly stable: mu < (1 - sqrt(23/27)) / 2 = 0.0385208965..., exactly."""
    mu = check_mass_ratio(mu)
    return _routh_margin(mu) > 0.0


def _hessian(mu):
    """(Omega_xx, Omega_xy) of Omega = -Phi at L1..L5, shape (..., 5) each: (1 + 2A, 0) on the x axis,
    (3/4, +-(3 sqrt(3) / 4)(1 - 2 mu)) at L4 (+) and L5 (-)."""
    a, _ = _tidal_strength(mu)
    mu = np.asarray(mu, dtype=float)[..., None]
    cross = 0.75 * np.sqrt(3.0) * (1.0 - 2.0 * mu) * np.array([1.0, -1.0])
    xx = np.concatenate([1.0 + 2.0 * a, np.full(mu.shape[:-1] + (2,), 0.75)], axis=-1)
    xy = np.concatenate([np.zeros(mu.shape[:-1] + (3,)), np.broadcast_to(cross, mu.shape[:-1] + (2,))], axis=-1)
    return xx, xy


def growing_mode(mu: ArrayLike) -> np.ndarray:
    """Rotating-frame state (dx, dy, dz, dvx, dvy, dvz) of the fastest-growing mode at L1..L5, shape (..., 5, 6),
    scaled to |(dx, dy)| = 1; zero where the point is linearly stable.

    From the planar linearisation: (dx, dy) = (Omega_xy + 2 lambda, lambda**2 - Omega_xx), dv = lambda (dx, dy),
    real part taken for the complex lambda of L4/L5 beyond Routh's ratio.
    """
    values = eigenvalues(mu)
    lam = np.take_along_axis(values, np.argmax(values.real, axis=-1)[..., None], axis=-1)[..., 0]
    xx, xy = _hessian(mu)
    position = np.stack([xy + 2.0 * lam, lam * lam - xx, np.zeros_like(lam)], axis=-1)
    state = np.concatenate([position, lam[..., None] * position], axis=-1).real
    norm = np.linalg.norm(state[..., :2], axis=-1, keepdims=True)
    return np.where(growth_rates(mu)[..., None] > 0.0, state / norm, 0.0)


def rotating_coordinates(r: ArrayLike, r_primary: ArrayLike, r_secondary: ArrayLike, mu: ArrayLike) -> np.ndarray:
    """Rotating-frame position (units of the separation) of r, given where the two primaries are: origin at their
    barycentre, x from M to m, z along the binary's spin (taken as +z); arrays of shape (..., 3)."""
    axis = np.asarray(r_secondary, dtype=float) - r_primary
    separation = np.linalg.norm(axis, axis=-1, keepdims=True)
    x_hat = axis / separation
    y_hat = np.stack([-x_hat[..., 1], x_hat[..., 0], np.zeros_like(x_hat[..., 0])], axis=-1)
    relative = np.asarray(r, dtype=float) - ((1.0 - mu) * np.asarray(r_primary) + mu * np.asarray(r_secondary))
    coordinates = [np.sum(relative * x_hat, axis=-1), np.sum(relative * y_hat, axis=-1), relative[..., 2]]
    return np.stack(coordinates, axis=-1) / separation


def rotating_to_inertial(
    r: ArrayLike, v: ArrayLike, angle: ArrayLike, inc: ArrayLike = 0.0, raan: ArrayLike = 0.0
) -> tuple[np.ndarray, np.ndarray]:
    """Barycentric inertial (r, v) of rotating-frame states, shape (..., 3), when the frame has turned by
    `angle` (rad) in the binary's plane (inclination inc, ascending node raan); v_inertial = v + z x r (n = 1).

    x of the rotating frame is at `angle` from the ascending node, in the plane spanned by
    n_hat = (cos raan, sin raan, 0) and m_hat = (-sin raan cos inc, cos raan cos inc, sin inc).
    """
    r, v = np.asarray(r, dtype=float), np.asarray(v, dtype=float)
    spun = v + np.stack([-r[..., 1], r[..., 0], np.zeros_like(r[..., 0])], axis=-1)
    c, s = np.cos(angle), np.sin(angle)
    basis = _plane_basis(inc, raan)

    def turn(vec):
        x_in = c * vec[..., 0] - s * vec[..., 1]
        y_in = s * vec[..., 0] + c * vec[..., 1]
        return x_in[..., None] * basis[0] + y_in[..., None] * basis[1] + vec[..., 2:3] * basis[2]

    return turn(r), turn(spun)


def _plane_basis(inc, raan):
    """(n_hat, m_hat, h_hat) of the plane with inclination inc and ascending node raan (rad)."""
    si, ci, so, co = np.sin(inc), np.cos(inc), np.sin(raan), np.cos(raan)
    n_hat = np.stack([co, so, np.zeros_like(co)], axis=-1)
    m_hat = np.stack([-so * ci, co * ci, si], axis=-1)
    return n_hat, m_hat, np.cross(n_hat, m_hat)
