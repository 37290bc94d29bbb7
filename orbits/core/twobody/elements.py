"""State vectors <-> classical elements, and the vectors of the two-body problem (h, e, A).

Float64 arrays, SI units and radians; vectors have shape (..., 3) and everything broadcasts.
The size element is the semi-latus rectum p (finite and well conditioned for every conic, including
e = 1); a = p / (1 - e**2) is derived.

Angle conventions (orientation R = R3(Omega) R1(i) R3(omega), as in Vallado and rebound):
- i in [0, pi]; Omega and omega in [0, 2 pi); nu in (-pi, pi].
- i = 0 or i = pi exactly (h along z): the node is undefined; Omega := 0 and the node line is the x
  axis, so omega is the longitude of periapsis (measured in the direction of motion).
- e = 0 exactly: periapsis is undefined; omega := 0, so nu is the argument of latitude (the true
  longitude when also i = 0).
- h = 0 (radial orbit): the plane is undefined; DegenerateOrbitError. The eccentricity vector is
  still defined (e = 1 along r_hat).
"""

import numpy as np
from numpy.typing import ArrayLike

from orbits.core.checks import broadcast, broadcast_shape, check_finite
from orbits.core.errors import DegenerateOrbitError, OrbitDomainError

TWO_PI = 2.0 * np.pi


def _norm(x):
    return np.sqrt(np.sum(x * x, axis=-1))


def _dot(a, b):
    return np.sum(a * b, axis=-1)


def check_state(r: ArrayLike, v: ArrayLike, mu: ArrayLike) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Validate and broadcast a state (r in m, v in m/s, mu in m**3/s**2) to float arrays."""
    r, v = np.asarray(r, dtype=float), np.asarray(v, dtype=float)
    mu = np.asarray(mu, dtype=float)
    if r.shape[-1:] != (3,) or v.shape[-1:] != (3,):
        raise OrbitDomainError(f"position and velocity must have a last axis of length 3; got {r.shape}, {v.shape}")
    check_finite(r, "position r", "m")
    check_finite(v, "velocity v", "m/s")
    check_finite(mu, "gravitational parameter mu", "m3 / s2")
    if np.any(mu <= 0):
        raise OrbitDomainError(f"gravitational parameter mu = {float(mu[mu <= 0].flat[0])!r} m3 / s2 must be positive")
    if np.any(_norm(r) == 0):
        raise OrbitDomainError("position r = (0, 0, 0) m coincides with the primary; |r| must be positive")
    shape = broadcast_shape(r=r.shape, v=v.shape, mu=mu.shape + (1,))
    return np.broadcast_to(r, shape), np.broadcast_to(v, shape), np.broadcast_to(mu, shape[:-1])


def angular_momentum_vector(r: ArrayLike, v: ArrayLike) -> np.ndarray:
    """Specific angular momentum h = r x v (m**2/s)."""
    return np.cross(r, v)


def eccentricity_vector(r: ArrayLike, v: ArrayLike, mu: ArrayLike) -> np.ndarray:
    """e = (v x h) / mu - r_hat (dimensionless), free of the v**2 - mu/r cancellation."""
    r, v, mu = check_state(r, v, mu)
    h = np.cross(r, v)
    return np.cross(v, h) / mu[..., None] - r / _norm(r)[..., None]


def laplace_runge_lenz_vector(r: ArrayLike, v: ArrayLike, mu: ArrayLike, m: ArrayLike) -> np.ndarray:
    """A = p x L - m k r_hat with p = m v, L = m r x v, k = G M m: A = m**2 mu e (kg**2 m**3 / s**2)."""
    return (
        np.asarray(m, dtype=float)[..., None] ** 2
        * np.asarray(mu, dtype=float)[..., None]
        * eccentricity_vector(r, v, mu)
    )


def _node_frame(h):
    """Unit vectors (n_hat, m_hat, h_hat): n_hat along the ascending node (x axis if equatorial)."""
    h_norm = _norm(h)
    h_hat = h / h_norm[..., None]
    node = np.stack([-h[..., 1], h[..., 0], np.zeros_like(h[..., 0])], axis=-1)
    node_norm = _norm(node)
    equatorial = node_norm == 0
    x_axis = np.broadcast_to(np.array([1.0, 0.0, 0.0]), node.shape)
    n_hat = np.where(equatorial[..., None], x_axis, node / np.where(equatorial, 1.0, node_norm)[..., None])
    return n_hat, np.cross(h_hat, n_hat), h_hat, node_norm


def _in_plane_angle(vec, n_hat, m_hat):
    """Angle of vec from n_hat towards m_hat (rad, in (-pi, pi])."""
    return np.arctan2(_dot(vec, m_hat), _dot(vec, n_hat))


def wrap_two_pi(angle: ArrayLike) -> np.ndarray:
    """Wrap to [0, 2 pi)."""
    wrapped = np.mod(angle, TWO_PI)
    return np.where(wrapped >= TWO_PI, 0.0, wrapped)


def wrap_pi(angle: ArrayLike) -> np.ndarray:
    """Wrap to (-pi, pi]."""
    wrapped = np.pi - np.mod(np.pi - angle, TWO_PI)
    return np.where(wrapped <= -np.pi, wrapped + TWO_PI, wrapped)


def state_to_elements(
    r: ArrayLike, v: ArrayLike, mu: ArrayLike
) -> tuple[float | np.ndarray, float | np.ndarray, float | np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Classical elements (p [m], e, i, Omega, omega, nu [rad]) of the state r [m], v [m/s] about mu.

    Returns a tuple of arrays with the broadcast batch shape. Conventions: see the module docstring.
    Raises DegenerateOrbitError for radial states (r x v = 0).
    """
    return state_to_elements_unchecked(*check_state(r, v, mu))


def state_to_elements_unchecked(
    r: ArrayLike, v: ArrayLike, mu: ArrayLike
) -> tuple[float | np.ndarray, float | np.ndarray, float | np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """state_to_elements for a state that passed check_state's rules (finite, |r| > 0, mu > 0), broadcast here."""
    r, v, mu = (np.asarray(x, dtype=float) for x in (r, v, mu))
    shape = broadcast_shape(r=r.shape, v=v.shape, mu=mu.shape + (1,))
    r, v, mu = np.broadcast_to(r, shape), np.broadcast_to(v, shape), np.broadcast_to(mu, shape[:-1])
    h = np.cross(r, v)
    h2 = _dot(h, h)
    if np.any(h2 == 0):
        raise DegenerateOrbitError(
            "the state is radial (r x v = 0, angular momentum h = 0 m2 / s): the orbital plane, "
            "node and periapsis are undefined; use eccentricity_vector (e = 1 along r_hat) instead"
        )
    e_vec = np.cross(v, h) / mu[..., None] - r / _norm(r)[..., None]
    e = _norm(e_vec)
    n_hat, m_hat, h_hat, node_norm = _node_frame(h)
    inc = np.arctan2(node_norm, h[..., 2])
    raan = wrap_two_pi(np.arctan2(h[..., 0], -h[..., 1]))
    raan = np.where(node_norm == 0, 0.0, raan)
    argp = np.where(e == 0, 0.0, _in_plane_angle(e_vec, n_hat, m_hat))
    latitude = _in_plane_angle(r, n_hat, m_hat)
    nu = wrap_pi(latitude - argp)
    return h2 / mu, e, inc, raan, wrap_two_pi(argp), nu


def _sin_cos(angle):
    """sin and cos, exact (0, -1) at angle == pi so that i = pi gives an exactly equatorial plane."""
    s, c = np.sin(angle), np.cos(angle)
    at_pi = angle == np.pi
    return np.where(at_pi, 0.0, s), np.where(at_pi, -1.0, c)


def check_conic(p: np.ndarray, e: np.ndarray, nu: np.ndarray) -> None:
    """Validate p > 0, e >= 0 and, on open conics, that nu lies strictly inside the asymptotes."""
    check_finite(p, "semi-latus rectum p", "m")
    check_finite(e, "eccentricity e", "(dimensionless)")
    check_finite(nu, "true anomaly nu", "rad")
    if np.any(p <= 0):
        raise OrbitDomainError(f"semi-latus rectum p = {float(p[p <= 0].flat[0])!r} m must be positive")
    if np.any(e < 0):
        raise OrbitDomainError(f"eccentricity e = {float(e[e < 0].flat[0])!r} must be >= 0")
    require_inside_asymptotes(e, nu)


def require_inside_asymptotes(e: ArrayLike, nu: ArrayLike) -> None:
    """Raise unless 1 + e cos nu > 0: on an open conic (e >= 1) the true anomaly lies strictly between the
    asymptotes, |nu| < arccos(-1/e) (mod 2 pi), where the point is at a finite distance (e >= 0 and finite nu are
    the caller's)."""
    _require_inside_asymptotes(*broadcast(e=e, nu=nu))


def _require_inside_asymptotes(e: np.ndarray, nu: np.ndarray) -> None:
    """require_inside_asymptotes on arrays of one shape."""
    denominator = 1.0 + e * np.cos(nu)
    beyond = (e >= 1.0) & (denominator <= 0.0)
    if np.any(beyond):
        i = tuple(np.argwhere(beyond)[0])
        raise OrbitDomainError(
            f"true anomaly nu = {float(nu[i])!r} rad lies on or beyond the asymptote of the conic with "
            f"e = {float(e[i])!r}; allowed |nu| < arccos(-1/e) = {float(np.arccos(-1.0 / e[i]))!r} rad (there "
            f"1 + e cos nu = {float(denominator[i])!r} must be > 0: the point is at infinity)"
        )


#: the largest eccentricity accepted: Kepler's hyperbolic equation is verified up to it (tests/core/test_kepler.py)
MAX_ECCENTRICITY = 1e12


def require_eccentricity(e: np.ndarray) -> None:
    """Raise OrbitDomainError unless every e is finite and in [0, MAX_ECCENTRICITY], where Kepler's equation is
    verified."""
    if not np.isfinite(e).all() or (e < 0).any():
        bad = e[~(np.isfinite(e) & (e >= 0))].flat[0]
        raise OrbitDomainError(f"eccentricity e = {float(bad)!r} is outside [0, inf)")
    if (e > MAX_ECCENTRICITY).any():
        bad = e[e > MAX_ECCENTRICITY].flat[0]
        raise OrbitDomainError(f"eccentricity e = {float(bad)!r} is outside [0, {MAX_ECCENTRICITY:g}], the range "
                               f"where Kepler's equation is verified")


def semi_latus_rectum(element: str, size: np.ndarray, e: np.ndarray) -> np.ndarray:
    """p (m) from e and one size element (m) of the same shape: p as given (element "p"), p = q (1 + e) ("q"), or
    p = a (1 - e) (1 + e) ("a"), with a > 0 for an ellipse, a < 0 for a hyperbola and no finite a on the parabola
    (OrbitDomainError otherwise). The caller has checked size (p, q positive; |a| finite within MAGNITUDE_RANGE or
    0) and e (require_eccentricity): p is then positive and finite, at most 1e60 m times 1e24."""
    if element == "p":
        return size
    if element == "q":
        return size * (1.0 + e)
    p = size * (1.0 - e) * (1.0 + e)
    if not (p > 0.0).all():
        _refuse_semi_major_axis(size, e)
    return p


def _refuse_semi_major_axis(a: np.ndarray, e: np.ndarray) -> None:
    """OrbitDomainError for the first a that does not fit its e: e = 1, or a of the wrong sign (a > 0 iff e < 1)."""
    if (e == 1.0).any():
        raise OrbitDomainError("a parabola (e = 1) has no finite a: give q or p instead of a")
    wrong = np.where(e < 1.0, a <= 0.0, a >= 0.0)
    i = tuple(np.argwhere(wrong)[0])
    rule = "a > 0 for a bound orbit (e < 1)" if e[i] < 1 else "a < 0 for a hyperbola (e > 1)"
    raise OrbitDomainError(f"semi-major axis a = {float(a[i]) / 1e3:.10g} km with e = {float(e[i])!r}: need {rule}")


def conic_fields(
    element: str, e: np.ndarray, size: np.ndarray, inc: np.ndarray, raan: np.ndarray, argp: np.ndarray,
    nu: np.ndarray, mu: np.ndarray
) -> list[np.ndarray]:
    """(mu, p, e, i, Omega, omega, nu): new float64 arrays of one shape, each owning its data, from arrays already
    broadcast together (views allowed) whose own rules hold (size as semi_latus_rectum takes it, i in [0, pi],
    Omega and omega in [0, 2 pi), nu in (-pi, pi], mu > 0). Here e is checked (require_eccentricity), p found from
    the size element and nu kept strictly inside an open conic's asymptotes."""
    require_eccentricity(e)
    p = semi_latus_rectum(element, size, e)
    _require_inside_asymptotes(e, nu)
    return [np.array(x, dtype=float) for x in (mu, p, e, inc, raan, argp, nu)]


def check_elements(p: ArrayLike, e: ArrayLike, inc: ArrayLike, nu: ArrayLike, mu: ArrayLike) -> None:
    """The rules on elements for direct core callers: finite p > 0, e >= 0, nu inside an open conic's
    asymptotes (check_conic), i in [0, pi] and finite mu > 0. The unit-aware API checks each value once at its
    edge (orbits._common.inputs) and calls elements_to_state_unchecked."""
    p, e, inc, nu, mu = broadcast(p=p, e=e, inc=inc, nu=nu, mu=mu)
    check_conic(p, e, nu)
    check_finite(mu, "gravitational parameter mu", "m3 / s2")
    if np.any(mu <= 0):
        raise OrbitDomainError(f"gravitational parameter mu = {float(mu[mu <= 0].flat[0])!r} m3 / s2 must be positive")
    if np.any((inc < 0) | (inc > np.pi)):
        bad = inc[(inc < 0) | (inc > np.pi)].flat[0]
        raise OrbitDomainError(f"inclination i = {float(bad)!r} rad is outside [0, pi] rad")


def elements_to_state(
    p: ArrayLike, e: ArrayLike, inc: ArrayLike, raan: ArrayLike, argp: ArrayLike, nu: ArrayLike, mu: ArrayLike
) -> tuple[np.ndarray, np.ndarray]:
    """State vectors r [m], v [m/s] of checked elements (check_elements, then elements_to_state_unchecked)."""
    check_elements(p, e, inc, nu, mu)
    return elements_to_state_unchecked(p, e, inc, raan, argp, nu, mu)


def elements_to_state_unchecked(
    p: ArrayLike, e: ArrayLike, inc: ArrayLike, raan: ArrayLike, argp: ArrayLike, nu: ArrayLike, mu: ArrayLike
) -> tuple[np.ndarray, np.ndarray]:
    """State vectors r [m], v [m/s] from p [m], e, i, Omega, omega, nu [rad] and mu [m**3/s**2], unchecked (the
    caller has applied check_elements' rules).

    r = p / (1 + e cos nu) (cos u n_hat + sin u m_hat) and
    v = sqrt(mu / p) (-(sin u + e sin omega) n_hat + (cos u + e cos omega) m_hat), u = omega + nu,
    with n_hat = (cos Omega, sin Omega, 0) and m_hat = (-sin Omega cos i, cos Omega cos i, sin i).
    """
    p, e, inc, raan, argp, nu, mu = broadcast(p=p, e=e, inc=inc, raan=raan, argp=argp, nu=nu, mu=mu)
    sin_i, cos_i = _sin_cos(inc)
    sin_o, cos_o = np.sin(raan), np.cos(raan)
    n_hat = np.stack([cos_o, sin_o, np.zeros_like(cos_o)], axis=-1)
    m_hat = np.stack([-sin_o * cos_i, cos_o * cos_i, sin_i], axis=-1)
    u = argp + nu
    radius = p / (1.0 + e * np.cos(nu))
    r = radius[..., None] * (np.cos(u)[..., None] * n_hat + np.sin(u)[..., None] * m_hat)
    speed = np.sqrt(mu / p)[..., None]
    v = speed * (-(np.sin(u) + e * np.sin(argp))[..., None] * n_hat + (np.cos(u) + e * np.cos(argp))[..., None] * m_hat)
    return r, v
