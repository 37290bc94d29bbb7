"""State-transition matrix of two-body motion: Phi = d(r, v) / d(r0, v0) at t0 + dt, on every conic.

Float64 arrays, SI units; r0, v0 of shape (..., 3), mu and dt broadcast against the batch shape; Phi has shape
(..., 6, 6), rows (r, v) and columns (r0, v0), so that a covariance P of (r0, v0) becomes Phi P Phi^T.

Method: closed form in the universal variables, one formula through e = 1 (no special case for parabolas). The
propagator's scaled problem (orbits.core.twobody.propagate.scaled_problem: |r0| = 1, mu = 1, dt reduced by whole
periods,
time reversal for dt < 0) and its universal anomaly chi give r = f r0 + g v0, v = f' r0 + g' v0 with
    f = 1 - G2 / R,  g = R G1 + sigma G2,  f' = -G1 / (r R),  g' = 1 - G2 / r,  r = R G0 + sigma G1 + G2,
G_k = chi**k c_k(alpha chi**2), R = |r0|, sigma = r0 . v0, alpha = 2 / R - |v0|**2. These four depend on the
initial state only through (R, sigma, alpha) and chi, which Kepler's equation R G1 + sigma G2 + G3 = tau ties to
them: d chi / dp = -(dF / dp) / r. With dG_k / dchi = G_(k-1) (dG_0 / dchi = -alpha G_1) and
dG_k / dalpha = -(chi G_(k+1) - k G_(k+2)) / 2, every total derivative Dq_p (p in R, sigma, alpha) is a short
sum of G_0 .. G_5, and the gradients follow from dR / dr0 = r0 / R, dsigma = v0 . dr0 + r0 . dv0,
dalpha = -2 r0 . dr0 / R**3 - 2 v0 . dv0:
    Phi_rr = f I + r0 grad_r0(f)^T + v0 grad_r0(g)^T,     Phi_rv = g I + r0 grad_v0(f)^T + v0 grad_v0(g)^T,
and likewise for v with f' and g'. Back in SI units the off-diagonal blocks take the scales |r0| / speed and
speed / |r0| (speed = sqrt(mu / |r0|)); time reversal negates them; the whole periods k P taken off dt add
-k (v, a) grad(P)^T, P = 2 pi / sqrt(mu alpha**3) (the secular drift along the track).

Accuracy (tests/core/test_transition.py): within 1e-13 of mpmath central differences at 50 digits relative to
the matrix's norm on ellipses, hyperbolas and near-parabolic orbits on both paths (measured 5.7e-15), except over
whole periods of near-parabolic ellipses, where it is held to eps / (1 - e) (2e-13 measured at 1 - e = 1.2e-4),
and where a flight grazes the focus or starts nearly radial: relative_error bounds it there;
symplectic (Phi^T J Phi = J) to the same level; and it agrees with heyoka's variational equations. Batches from
orbits.core._fast.AUTO_MIN_BATCH states on run the compiled port (orbits/core/twobody/_fast_transition.py).
"""

import numpy as np
from numpy.typing import ArrayLike

from orbits.core import _fast
from orbits.core.checks import check_finite
from orbits.core.errors import DegenerateOrbitError, OrbitDomainError
from orbits.core.series import horner
from orbits.core.twobody._propagate_shared import C4_SERIES, C5_SERIES, C45_SERIES_LIMIT
from orbits.core.twobody.elements import check_state
from orbits.core.twobody.propagate import Scaled, scaled_problem, stumpff, universal_anomaly


def transition_matrix(r0: ArrayLike, v0: ArrayLike, mu: ArrayLike, dt: ArrayLike) -> np.ndarray:
    """Phi = d(r, v) / d(r0, v0) (shape (..., 6, 6); blocks dimensionless, s, 1/s, dimensionless) of the Kepler
    orbit through r0 [m], v0 [m/s] about mu [m**3/s**2], a time dt [s] later. Radial states raise
    DegenerateOrbitError, as in orbits.core.twobody.propagate.propagate; a matrix that leaves float64 (a flight that all
    but hits the focus) raises OrbitDomainError. Its error: relative_error(phi, r0, v0, mu)."""
    r0, v0, mu, dt, batch = _checked(r0, v0, mu, dt)
    phi = _compiled(r0, v0, mu, dt) if _fast.use(dt.size, "twobody._fast_transition.transition") else None
    if phi is None:
        with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
            phi = _transition_numpy(r0, v0, mu, dt)
    if not np.all(np.isfinite(phi)):
        bad = int(np.flatnonzero(~np.all(np.isfinite(phi), axis=(-2, -1)))[0])
        start = ", ".join(f"{x:.6g}" for x in r0[bad]), ", ".join(f"{x:.6g}" for x in v0[bad])
        raise OrbitDomainError(f"the state-transition matrix of the flight from r0 = [{start[0]}] m, v0 = "
                               f"[{start[1]}] m/s over dt = {float(dt[bad]):.6g} s leaves float64: its entries grow "
                               f"with the flight's length and near the focus, beyond 1.8e308 here")
    return phi.reshape(batch + (6, 6))


#: relative_error's terms: the error of Phi against its norm is at most ERROR_FLOOR on ordinary flights; it grows
#: as |Phi~|**2 where the flight bends sharply past the focus and as |r0| |v0| / |h| where the start is nearly
#: radial (the formulas' terms cancel there): measured at most 1.5 eps (|Phi~|**2 + |r0| |v0| / |h|) over 300
#: grazing and near-radial flights on both paths (tests/core/test_transition.py)
ERROR_FLOOR = 1e-13
ERROR_GROWTH = 10.0 * 2.0**-53


def relative_error(phi: ArrayLike, r0: ArrayLike, v0: ArrayLike, mu: ArrayLike) -> np.ndarray:
    """A bound on the error of transition_matrix's Phi relative to its Frobenius norm (the batch's shape):

        ERROR_FLOOR + ERROR_GROWTH (|Phi~|**2 + |r0| |v0| / |r0 x v0|),

    Phi~ the matrix in the orbit's own units (positions in |r0|, velocities in sqrt(mu / |r0|)), whose norm grows
    where the flight bends sharply near the focus (2.4e5 for an e = 1.2 hyperbola through its periapsis at 1e-4 of
    r0, whose Phi is good to 5e-7), and the second term where the start is nearly radial."""
    r0, v0 = np.asarray(r0, dtype=float), np.asarray(v0, dtype=float)
    scaled = np.array(phi, dtype=float)
    size = np.sqrt(np.sum(r0**2, axis=-1))
    rate = (np.sqrt(np.asarray(mu, dtype=float) / size) / size)[..., None, None]  # speed / size (1/s)
    scaled[..., :3, 3:] *= rate
    scaled[..., 3:, :3] /= rate
    radial = size * np.sqrt(np.sum(v0**2, axis=-1)) / np.sqrt(np.sum(np.cross(r0, v0) ** 2, axis=-1))
    with np.errstate(over="ignore"):  # a Phi~ beyond 1e154 (a flight of 1e80 s) has an infinite bound: no digit
        return ERROR_FLOOR + ERROR_GROWTH * (np.sum(scaled**2, axis=(-2, -1)) + radial)


def _checked(r0, v0, mu, dt):
    """Flat (n, 3) r0, v0 and (n,) mu, dt, checked as the propagator checks them, and the batch shape."""
    r0, v0, mu = check_state(r0, v0, mu)
    dt = np.asarray(dt, dtype=float)
    check_finite(dt, "time step dt", "s")
    batch = np.broadcast_shapes(mu.shape, dt.shape)
    r0, v0 = np.broadcast_to(r0, batch + (3,)).reshape(-1, 3), np.broadcast_to(v0, batch + (3,)).reshape(-1, 3)
    mu, dt = np.broadcast_to(mu, batch).reshape(-1), np.broadcast_to(dt, batch).reshape(-1)
    h = np.cross(r0, v0)
    if np.any(np.sum(h * h, axis=-1) == 0):
        raise DegenerateOrbitError(
            "the state is radial (r x v = 0): the propagator does not regularise the collision with "
            "the primary; give the orbit a non-zero angular momentum"
        )
    return r0, v0, mu, dt, batch


def _compiled(r0, v0, mu, dt):
    """Phi by the compiled kernel, (n, 6, 6); None if it left a state unsolved (the NumPy version then raises)."""
    _fast.announce("_fast_transition")
    from orbits.core.twobody import _fast_transition

    r0, v0, mu, dt = (_fast.kernel_array(x) for x in (r0, v0, mu, dt))
    phi = np.empty((dt.size, 6, 6))
    if _fast.run(_fast_transition.transition, dt.size, r0, v0, mu, dt, phi):
        return None
    return phi


def g_functions(chi: np.ndarray, alpha: np.ndarray) -> tuple[np.ndarray, ...]:
    """(G0, .., G5) with G_k = chi**k c_k(alpha chi**2): c0 .. c3 from orbits.core.twobody.propagate.stumpff, c4 and c5
    from their series for |z| <= C45_SERIES_LIMIT and from c_k = (1 / k! - c_(k-2)) / z beyond (which then
    cancels by less than 2 bits)."""
    z = alpha * chi * chi
    c0, c1, c2, c3 = stumpff(z)
    small = np.abs(z) <= C45_SERIES_LIMIT
    with np.errstate(divide="ignore", invalid="ignore"):
        c4 = np.where(small, horner(C4_SERIES, z), (0.5 - c2) / z)
        c5 = np.where(small, horner(C5_SERIES, z), (1.0 / 6.0 - c3) / z)
    chi2 = chi * chi
    return c0, chi * c1, chi2 * c2, chi2 * chi * c3, chi2 * chi2 * c4, chi2 * chi2 * chi * c5


def scaled_coefficients(chi, R, sigma, alpha):
    """(f, g, f', g') and their gradients for the scaled problem (mu = 1): the 4 x 4 array K, in the basis
    (r0, v0), of grad(q)^T for q = f, g, f', g' along rows and (grad_r0 along r0, along v0, grad_v0 along r0,
    along v0) along columns, so that dq = K[q, 0] r0.dr0 + K[q, 1] v0.dr0 + K[q, 2] r0.dv0 + K[q, 3] v0.dv0.
    Arrays over the states; returns ((f, g, fd, gd), K)."""
    G0, G1, G2, G3, G4, G5 = g_functions(chi, alpha)
    r = R * G0 + sigma * G1 + G2
    # d G_k / d alpha
    A0, A1, A2, A3 = -0.5 * chi * G1, -0.5 * (chi * G2 - G3), -0.5 * (chi * G3 - 2.0 * G4), -0.5 * (chi * G4 - 3.0 * G5)
    # chi from Kepler's equation: d chi / dp = -(dF / dp) / r
    chi_R, chi_s, chi_a = -G1 / r, -G2 / r, -(R * A1 + sigma * A2 + A3) / r
    r_chi = sigma * G0 + (1.0 - alpha * R) * G1
    Dr = (G0 + r_chi * chi_R, G1 + r_chi * chi_s, (R * A0 + sigma * A1 + A2) + r_chi * chi_a)
    f, g, fd, gd = 1.0 - G2 / R, R * G1 + sigma * G2, -G1 / (r * R), 1.0 - G2 / r
    # total derivatives of G1 and G2 along R, sigma, alpha
    DG1 = (G0 * chi_R, G0 * chi_s, A1 + G0 * chi_a)
    DG2 = (G1 * chi_R, G1 * chi_s, A2 + G1 * chi_a)
    Df = (G2 / (R * R) - DG2[0] / R, -DG2[1] / R, -DG2[2] / R)
    Dg = (G1 + R * DG1[0] + sigma * DG2[0], G2 + R * DG1[1] + sigma * DG2[1], R * DG1[2] + sigma * DG2[2])
    inverse_r = 1.0 / r
    Dfd = tuple(-DG1[k] * inverse_r / R - fd * (Dr[k] * inverse_r + (1.0 / R if k == 0 else 0.0))
                for k in range(3))
    Dgd = tuple(-DG2[k] * inverse_r + G2 * Dr[k] * inverse_r * inverse_r for k in range(3))
    rows = []
    for D in (Df, Dg, Dfd, Dgd):
        rows.append((D[0] / R - 2.0 * D[2] / R**3, D[1], D[1], -2.0 * D[2]))
    return (f, g, fd, gd), np.stack([np.stack(row, axis=-1) for row in rows], axis=-2)


def _assemble(x, w, coefficients, K):
    """Phi of the scaled problem, (n, 6, 6), from the state (x, w) and scaled_coefficients."""
    f, g, fd, gd = coefficients
    eye = np.eye(3)
    basis = np.stack([x, w], axis=-1)  # (n, 3, 2): columns r0, v0

    def block(q_row, p_row, diagonal, gradient):
        # diagonal I + r0 grad(q)^T + v0 grad(p)^T with grad = K[., gradient] r0 + K[., gradient + 1] v0
        outer = np.stack([K[:, q_row, gradient:gradient + 2], K[:, p_row, gradient:gradient + 2]], axis=-2)
        return diagonal[:, None, None] * eye + basis @ outer @ np.swapaxes(basis, -1, -2)

    top = np.concatenate([block(0, 1, f, 0), block(0, 1, g, 2)], axis=-1)
    bottom = np.concatenate([block(2, 3, fd, 0), block(2, 3, gd, 2)], axis=-1)
    return np.concatenate([top, bottom], axis=-2)


def _to_si(phi, s: Scaled, coefficients, r0, v0, mu):
    """Phi of the SI problem from the scaled one: time reversal, the units of the off-diagonal blocks, and the
    secular term -k (v, a) grad(P)^T of the periods taken off dt, with (v, a) at the end of the flight from the
    Lagrange coefficients (Phi (v0, a0), equal in exact arithmetic, cancels near apoapsis: 1e-12 at e = 0.95)."""
    phi = phi.copy()
    sign = np.where(s.backwards, -1.0, 1.0)
    phi[:, :3, 3:] *= (sign * s.length / s.speed)[:, None, None]
    phi[:, 3:, :3] *= (sign * s.speed / s.length)[:, None, None]
    bound = s.turns != 0
    if np.any(bound):
        f, g, fd, gd = (q[bound, None] for q in coefficients)
        x, w, length, speed = s.x[bound], s.w[bound], s.length[bound, None], s.speed[bound, None]
        r = (f * x + g * w) * length
        v = (fd * x + gd * w) * (sign[bound, None] * speed)
        a = -mu[bound, None] * r / np.sum(r * r, axis=-1, keepdims=True) ** 1.5
        alpha = s.alpha[bound] / s.length[bound]  # 2 / |r0| - |v0|**2 / mu [1/m], from double-double arithmetic
        grad_alpha = np.concatenate([-2.0 * r0[bound] / s.length[bound, None] ** 3, -2.0 * v0[bound] / mu[bound, None]],
                                    axis=-1)
        grad_period = (-1.5 * s.period[bound] / alpha)[:, None] * grad_alpha
        rate = np.concatenate([v, a], axis=-1)
        phi[bound] -= s.turns[bound, None, None] * rate[:, :, None] * grad_period[:, None, :]
    return phi


def _transition_numpy(r0, v0, mu, dt):
    """transition_matrix in NumPy for flat, checked inputs: (n, 6, 6)."""
    s = scaled_problem(r0, v0, mu, dt)
    chi = universal_anomaly(s)
    coefficients, K = scaled_coefficients(chi, s.r0, s.sigma0, s.alpha)
    return _to_si(_assemble(s.x, s.w, coefficients, K), s, coefficients, r0, v0, mu)


def propagate_covariance(phi: ArrayLike, covariance: ArrayLike) -> np.ndarray:
    """P(t) = Phi P0 Phi^T for a covariance P0 of (r0 [m], v0 [m/s]) (shape (..., 6, 6), broadcasting with phi):
    the linear map of the initial uncertainty along the flight (valid while it stays small against the orbit)."""
    phi, covariance = np.asarray(phi, dtype=float), np.asarray(covariance, dtype=float)
    return phi @ covariance @ np.swapaxes(phi, -1, -2)
