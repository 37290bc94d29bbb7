"""The circular restricted three-body problem in the rotating frame: equations of motion and variational equations.

Units and frame as orbits.core.threebody.lagrange: separation r = 1, G (M + m) = 1, so n = 1 (the binary's period is
2 pi);
the primary M at (-mu, 0, 0), the secondary m at (1 - mu, 0, 0), rotation about +z. A state is (x, y, z, vx, vy, vz)
in the rotating frame. With Omega = (x**2 + y**2) / 2 + (1 - mu) / r_1 + mu / r_2 (the notes' -Phi):

    x'' - 2 y' = Omega_x,    y'' + 2 x' = Omega_y,    z'' = Omega_z,

and the Jacobi constant C = 2 Omega - |v|**2 is conserved. The state transition matrix Phi(t) = d state(t) /
d state(0) obeys Phi' = A Phi, Phi(0) = I, with

    A = [[0, I], [Omega_rr, 2 K]],    K = [[0, 1, 0], [-1, 0, 0], [0, 0, 0]],

Omega_rr the symmetric Hessian of Omega. Phi preserves the form W of `symplectic_form` (Phi^T W Phi = W: the
canonical momenta are p = v + z_hat x r), so its inverse is W^-1 Phi^T W.

Two reversing symmetries map solutions to solutions with time reversed (t -> -t): the reflection in the x-z plane,
(x, y, z, vx, vy, vz) -> (x, -y, z, -vx, vy, -vz), and the half turn about the x axis, (x, y, z, vx, vy, vz) ->
(x, -y, -z, -vx, vy, vz). A state left unchanged by one of them (a perpendicular crossing) that returns to such a
state after a time tau starts a periodic orbit of period 2 tau (orbits.core.periodic.shooting).
"""

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike

from orbits.core.errors import OrbitDomainError
from orbits.core.threebody import lagrange

#: The reversing symmetries as sign patterns on the state: +1 where a component is kept, -1 where it is reversed.
#: A fixed state has zero in every reversed component.
XZ_PLANE = np.array([1.0, -1.0, 1.0, -1.0, 1.0, -1.0])
X_AXIS = np.array([1.0, -1.0, -1.0, -1.0, 1.0, 1.0])

#: the Coriolis block K of A (the x-y rotation of the velocity)
_K = np.array([[0.0, 1.0, 0.0], [-1.0, 0.0, 0.0], [0.0, 0.0, 0.0]])


def acceleration(r: ArrayLike, v: ArrayLike, mu: float) -> np.ndarray:
    """Rotating-frame acceleration (Omega_x + 2 vy, Omega_y - 2 vx, Omega_z) of states r, v of shape (..., 3)."""
    r, v = np.asarray(r, dtype=float), np.asarray(v, dtype=float)
    x, y, z = r[..., 0], r[..., 1], r[..., 2]
    d1 = np.stack([x + mu, y, z], axis=-1)
    d2 = np.stack([x - (1.0 - mu), y, z], axis=-1)
    g1 = (1.0 - mu) / np.sum(d1 * d1, axis=-1) ** 1.5
    g2 = mu / np.sum(d2 * d2, axis=-1) ** 1.5
    gravity = -(g1[..., None] * d1 + g2[..., None] * d2)
    spin = np.stack([x + 2.0 * v[..., 1], y - 2.0 * v[..., 0], np.zeros_like(x)], axis=-1)
    return gravity + spin


def field(state: ArrayLike, mu: float) -> np.ndarray:
    """The vector field (v, acceleration) at states of shape (..., 6)."""
    state = np.asarray(state, dtype=float)
    return np.concatenate([state[..., 3:], acceleration(state[..., :3], state[..., 3:], mu)], axis=-1)


def jacobi_constant(state: ArrayLike, mu: float) -> float | np.ndarray:
    """C = 2 Omega - |v|**2 (units of (n r)**2) of rotating-frame states of shape (..., 6)."""
    state = np.asarray(state, dtype=float)
    x, y, z = state[..., 0], state[..., 1], state[..., 2]
    r1 = np.sqrt((x + mu) ** 2 + y * y + z * z)
    r2 = np.sqrt((x - (1.0 - mu)) ** 2 + y * y + z * z)
    omega = 0.5 * (x * x + y * y) + (1.0 - mu) / r1 + mu / r2
    return 2.0 * omega - np.sum(state[..., 3:] ** 2, axis=-1)


def jacobi_gradient(state: ArrayLike, mu: float) -> np.ndarray:
    """dC / d(state) = (2 Omega_x, 2 Omega_y, 2 Omega_z, -2 vx, -2 vy, -2 vz), shape (..., 6)."""
    state = np.asarray(state, dtype=float)
    r, v = state[..., :3], state[..., 3:]
    spin_free = acceleration(r, np.zeros_like(v), mu)  # Omega_r itself: the Coriolis term vanishes at v = 0
    return np.concatenate([2.0 * spin_free, -2.0 * v], axis=-1)


def rotating_state(r, v, r_primary, v_primary, r_secondary, v_secondary, mu: float) -> np.ndarray:
    """Rotating-frame states (..., 6) of inertial states r, v (..., 3) in the frame the primaries' own states define:
    origin at their barycentre, x from M to m, z along their orbital spin, lengths in units of their separation d and
    speeds in units of n d, n = |d x d'| / d**2 their instantaneous angular velocity (code units of an integration
    in which G (M + m) = 1 and d = 1 give n = 1)."""
    r, v = np.asarray(r, dtype=float), np.asarray(v, dtype=float)
    d = np.asarray(r_secondary, dtype=float) - r_primary
    d_dot = np.asarray(v_secondary, dtype=float) - v_primary
    separation = np.linalg.norm(d, axis=-1, keepdims=True)
    spin = np.cross(d, d_dot) / separation**2
    rate = np.linalg.norm(spin, axis=-1, keepdims=True)
    x_hat, z_hat = d / separation, spin / rate
    y_hat = np.cross(z_hat, x_hat)
    relative = r - ((1.0 - mu) * np.asarray(r_primary) + mu * np.asarray(r_secondary))
    moving = v - ((1.0 - mu) * np.asarray(v_primary) + mu * np.asarray(v_secondary)) - np.cross(spin, relative)
    basis = np.stack([x_hat, y_hat, z_hat], axis=-2)
    position = np.einsum("...ij,...j->...i", basis, relative) / separation
    velocity = np.einsum("...ij,...j->...i", basis, moving) / (rate * separation)
    return np.concatenate([position, velocity], axis=-1)


def symplectic_form() -> np.ndarray:
    """W = [[K^T - K, I], [-I, 0]] (6, 6): Phi^T W Phi = W for every state transition matrix Phi of these equations.

    It is the canonical J = [[0, I], [-I, 0]] pulled back through p = v + z_hat x r, i.e. (r, p) = P (r, v) with
    P = [[I, 0], [S, I]], S = [[0, -1, 0], [1, 0, 0], [0, 0, 0]]: W = P^T J P = [[S - S^T, I], [-I, 0]]."""
    w = np.zeros((6, 6))
    w[:3, :3] = _K.T - _K
    w[:3, 3:] = np.eye(3)
    w[3:, :3] = -np.eye(3)
    return w


def transition_inverse(phi: ArrayLike) -> np.ndarray:
    """Phi^-1 = W^-1 Phi^T W for state transition matrices of shape (..., 6, 6), exact for a symplectic Phi."""
    w = symplectic_form()
    return np.linalg.inv(w) @ np.swapaxes(np.asarray(phi, dtype=float), -1, -2) @ w


#: the points about which a flow may write its states: where the forces balance in the rotating frame
ORIGINS = ("L1", "L2", "L3", "primary", "secondary")


@dataclass(frozen=True)
class Origin:
    """A point of the x axis about which states are written as offsets (local coordinates): the state is
    (x, 0, 0, 0, 0, 0) + (xi, v). `from_primary` and `from_secondary` are x - x_M and x - x_m, each to full relative
    accuracy (one of them 0 at a primary); `scale` is the length of the motions about it (the distance of a collinear
    point from its nearer primary, the secondary's Hill radius (mu / 3)**(1/3), or r about the primary), which
    sets an integration's absolute tolerance."""

    name: str
    x: float
    from_primary: float
    from_secondary: float
    scale: float


def origin(mu: float, name: str) -> Origin:
    """The Origin `name` (one of ORIGINS) of the binary of mass ratio mu."""
    if name not in ORIGINS:
        raise OrbitDomainError(f"unknown origin {name!r}; choose from {', '.join(ORIGINS)}")
    rho_1, rho_2, s_3 = (float(x) for x in lagrange.collinear_offsets(mu))
    x = {"L1": 1.0 - (mu + rho_1), "L2": 1.0 + (rho_2 - mu), "L3": -(mu + s_3), "primary": -mu,
         "secondary": 1.0 - mu}[name]
    offsets = {"L1": (1.0 - rho_1, -rho_1), "L2": (1.0 + rho_2, rho_2), "L3": (-s_3, -(1.0 + s_3)),
               "primary": (0.0, -1.0), "secondary": (1.0, 0.0)}[name]
    scale = {"L1": rho_1, "L2": rho_2, "L3": s_3, "primary": 1.0, "secondary": (mu / 3.0) ** (1.0 / 3.0)}[name]
    return Origin(name, x, offsets[0], offsets[1], scale)


def to_barycentric(states, place: Origin) -> np.ndarray:
    """States (..., 6) about the barycentre from states about `place`."""
    out = np.array(states, dtype=float)
    out[..., 0] += place.x
    return out


def from_barycentric(states, place: Origin) -> np.ndarray:
    """States (..., 6) about `place` from states about the barycentre (exact to the rounding of the subtraction)."""
    out = np.array(states, dtype=float)
    out[..., 0] -= place.x
    return out


def _pull(a: float, x: float, y: float, z: float):
    """(d / |d|**3 - a x_hat / |a|**3, d = (a + x, y, z), and |d|**2): a primary's pull at the offset (x, y, z) from
    an origin at distance a from it, less its pull at the origin, free of cancellation: with
    delta = |d|**2 - a**2 = x (2 a + x) + y**2 + z**2, 1 / |d|**3 - 1 / |a|**3 = -delta (|d|**2 + |d| |a| + a**2) /
    ((|d| + |a|) |d|**3 |a|**3). At a = 0 (the origin on the primary) it is the pull d / |d|**3 itself."""
    dx = a + x
    rho = y * y + z * z
    s = dx * dx + rho
    d = math.sqrt(s)
    inverse_cube = 1.0 / (s * d)
    if a == 0.0:
        return x * inverse_cube, y * inverse_cube, z * inverse_cube, s
    span = abs(a)
    delta = x * (2.0 * a + x) + rho
    change = -delta * (s + d * span + a * a) / ((d + span) * s * d * a * a * span)
    return x * inverse_cube + a * change, y * inverse_cube, z * inverse_cube, s


def vector_field(mu: float, place: Origin, with_transition: bool = False) -> Callable[[np.ndarray], np.ndarray]:
    """f(y) for the integrator in coordinates about `place`: y' of a state (6,) or, with_transition, of a state
    followed by Phi (42,) row by row.

    The forces balance at the origin (x_o = (1 - mu) a_1 / |a_1|**3 + mu a_2 / |a_2|**3 with a_i its offsets from the
    primaries), so the acceleration about it is (xi + 2 vy, eta - 2 vx, 0) - sum_i G m_i (d_i / |d_i|**3 - a_i x_hat /
    |a_i|**3): every term is of the size of the offset, and an orbit small beside the separation (a Sun-Earth halo is
    1e-3 r) keeps its full relative accuracy. Written for one trajectory at a time in scalar arithmetic: it is the
    integrator's inner loop.
    """
    mu = float(mu)
    one_minus = 1.0 - mu
    a1, a2 = place.from_primary, place.from_secondary

    def accelerations(y):
        x, yy, z, vx, vy, vz = y[:6].tolist()
        p1x, p1y, p1z, s1 = _pull(a1, x, yy, z)
        p2x, p2y, p2z, s2 = _pull(a2, x, yy, z)
        ax = x + 2.0 * vy - one_minus * p1x - mu * p2x
        ay = yy - 2.0 * vx - one_minus * p1y - mu * p2y
        az = -one_minus * p1z - mu * p2z
        return (x, yy, z, s1, s2), (vx, vy, vz, ax, ay, az)

    if not with_transition:
        def state_field(y):
            return np.array(accelerations(y)[1])

        return state_field

    def transition_field(y):
        (x, yy, z, s1, s2), head = accelerations(y)
        dx1, dx2 = x + a1, x + a2
        g1, g2 = one_minus / (s1 * math.sqrt(s1)), mu / (s2 * math.sqrt(s2))
        g = g1 + g2
        h1, h2 = 3.0 * g1 / s1, 3.0 * g2 / s2
        hx = h1 * dx1 + h2 * dx2
        hh = h1 + h2
        uxx = 1.0 - g + h1 * dx1 * dx1 + h2 * dx2 * dx2
        uyy = 1.0 - g + hh * yy * yy
        uzz = -g + hh * z * z
        uxy, uxz, uyz = hx * yy, hx * z, hh * yy * z
        phi = y[6:].reshape(6, 6)
        top, bottom = phi[:3], phi[3:]
        hess = np.array([[uxx, uxy, uxz], [uxy, uyy, uyz], [uxz, uyz, uzz]])
        lower = hess @ top
        lower[0] += 2.0 * bottom[1]
        lower[1] -= 2.0 * bottom[0]
        out = np.empty(42)
        out[:6] = head
        out[6:24] = bottom.ravel()
        out[24:] = lower.ravel()
        return out

    return transition_field
