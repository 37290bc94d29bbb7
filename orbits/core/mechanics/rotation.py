"""Section XI of the notes: rotations, inertia tensors and rolling, on float64 arrays.

Rotation matrices are (..., 3, 3) and act on column vectors (v' = R v); axes are (..., 3) unit vectors, angles in
rad; masses in kg, lengths in m, moments of inertia in kg m**2, angular velocities in rad/s. Everything broadcasts.

- Euler's theorem (XI.ii): every rotation is a turn by an angle about an axis. rotation_matrix builds it by
  Rodrigues' formula with 1 - cos a = 2 sin**2(a / 2); axis_angle recovers it through the unit quaternion
  (Shepperd's choice of the largest component, so angles near pi keep their digits).
- Principal rotations (XI.iii): R = Rz(c) Ry(b) Rx(a), turning first about x, then y, then z (fixed axes).
- Inertia (XI.vi): I = sum m (|r|**2 1 - r r^T); the notes' I_xz line repeats I_yz's integrand, the product
  of inertia I_xz is -int rho x z dV. Parallel-axis theorem (XI.xiii) in tensor form.
- Rolling without slipping down an incline: a = g sin(theta) / (1 + I / (m r**2)).
Accuracy (tests/core/test_rotation.py): R^T R = 1 to 2e-15, axis-angle round trips to 1.1e-15 rad for every angle
in [0, pi], principal angles to 4.4e-16 rad, standard bodies' moments equal to mpmath integrals of the definition to
2e-16.
"""

import numpy as np
from numpy.typing import ArrayLike

from orbits.core.errors import OrbitDomainError

#: the principal axes' indices, as the notes name them
AXES = {"x": 0, "y": 1, "z": 2}


def unit_axis(axis: ArrayLike) -> np.ndarray:
    """axis / |axis| (dimensionless, (..., 3)); OrbitDomainError for a zero or non-finite axis."""
    axis = np.asarray(axis, dtype=float)
    if axis.shape[-1:] != (3,):
        raise OrbitDomainError(f"rotation axis must have a last axis of length 3; got shape {axis.shape}")
    size = np.linalg.norm(axis, axis=-1)
    if not np.all(np.isfinite(size) & (size > 0)):
        raise OrbitDomainError("rotation axis must be a finite nonzero vector; got a zero or non-finite one")
    return axis / size[..., None]


def cross_matrix(v: ArrayLike) -> np.ndarray:
    """[v]x (..., 3, 3): the matrix with [v]x w = v x w."""
    v = np.asarray(v, dtype=float)
    zero = np.zeros_like(v[..., 0])
    x, y, z = v[..., 0], v[..., 1], v[..., 2]
    return np.stack([np.stack([zero, -z, y], -1), np.stack([z, zero, -x], -1), np.stack([-y, x, zero], -1)], -2)


def rotation_matrix(axis: ArrayLike, angle: ArrayLike) -> np.ndarray:
    """R = 1 + sin(a) K + 2 sin**2(a / 2) K**2 (..., 3, 3), K = [n]x: the right-handed turn by a (rad) about the
    axis n (normalised here) (XI.ii, Euler's theorem; Rodrigues' formula)."""
    n = unit_axis(axis)
    a = np.asarray(angle, dtype=float)
    k = cross_matrix(n)
    half = np.sin(0.5 * a)
    return np.eye(3) + np.sin(a)[..., None, None] * k + (2.0 * half * half)[..., None, None] * (k @ k)


def principal_rotation(axis: str, angle: ArrayLike) -> np.ndarray:
    """The turn by `angle` (rad) about the x, y or z axis (XI.iii), (..., 3, 3)."""
    if axis not in AXES:
        raise OrbitDomainError(f"principal axis {axis!r} is not one of x, y, z")
    return rotation_matrix(np.eye(3)[AXES[axis]], angle)


def from_principal_angles(ax: ArrayLike, ay: ArrayLike, az: ArrayLike) -> np.ndarray:
    """R = Rz(az) Ry(ay) Rx(ax): turn about x, then about y, then about z, all fixed axes (XI.iii)."""
    return principal_rotation("z", az) @ principal_rotation("y", ay) @ principal_rotation("x", ax)


def principal_angles(matrix: ArrayLike) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(ax, ay, az) (rad) with R = Rz(az) Ry(ay) Rx(ax), ay in [-pi/2, pi/2], ax and az in (-pi, pi] (XI.iii).

    At ay = +-pi/2 (gimbal lock) only ax -+ az is defined; ax = 0 is chosen there.
    """
    r = np.asarray(matrix, dtype=float)
    ay = np.arctan2(-r[..., 2, 0], np.hypot(r[..., 0, 0], r[..., 1, 0]))
    locked = np.hypot(r[..., 0, 0], r[..., 1, 0]) <= 1e-15
    ax = np.where(locked, 0.0, np.arctan2(r[..., 2, 1], r[..., 2, 2]))
    az = np.where(locked, np.arctan2(-r[..., 0, 1], r[..., 1, 1]), np.arctan2(r[..., 1, 0], r[..., 0, 0]))
    return ax, ay, az


def quaternion(matrix: ArrayLike) -> np.ndarray:
    """Unit quaternion (w, x, y, z) with w >= 0 of a rotation matrix (..., 4), by Shepperd's method: the largest
    of 4 w**2, 4 x**2, 4 y**2, 4 z**2 is found from the trace and diagonal, the others from off-diagonal sums."""
    r = np.asarray(matrix, dtype=float)
    d0, d1, d2 = r[..., 0, 0], r[..., 1, 1], r[..., 2, 2]
    squares = np.stack([1 + d0 + d1 + d2, 1 + d0 - d1 - d2, 1 - d0 + d1 - d2, 1 - d0 - d1 + d2], -1)  # 4 q_i**2
    s21, s12 = r[..., 2, 1] - r[..., 1, 2], r[..., 2, 1] + r[..., 1, 2]
    s02, s20 = r[..., 0, 2] - r[..., 2, 0], r[..., 0, 2] + r[..., 2, 0]
    s10, s01 = r[..., 1, 0] - r[..., 0, 1], r[..., 1, 0] + r[..., 0, 1]
    rows = np.stack([  # 4 q_i q_j for the four choices of the largest component i
        np.stack([squares[..., 0], s21, s02, s10], -1),
        np.stack([s21, squares[..., 1], s01, s20], -1),
        np.stack([s02, s01, squares[..., 2], s12], -1),
        np.stack([s10, s20, s12, squares[..., 3]], -1),
    ], -2)
    best = np.argmax(squares, axis=-1)
    chosen = np.take_along_axis(rows, best[..., None, None], axis=-2)[..., 0, :]
    q = chosen / np.linalg.norm(chosen, axis=-1)[..., None]
    return np.where(q[..., :1] < 0, -q, q)


def axis_angle(matrix: ArrayLike) -> tuple[np.ndarray, np.ndarray]:
    """(axis (..., 3), angle (...) in [0, pi] rad) of a rotation matrix (XI.ii, Euler's theorem).

    angle = 2 atan2(|q_vec|, w) from the quaternion; the identity has angle 0 and, by convention, axis z. At
    angle pi the axis's sign is arbitrary (both describe the same turn).
    """
    q = quaternion(matrix)
    vec = q[..., 1:]
    size = np.linalg.norm(vec, axis=-1)
    angle = 2.0 * np.arctan2(size, q[..., 0])
    safe = np.where(size > 0, size, 1.0)
    axis = np.where((size > 0)[..., None], vec / safe[..., None], np.array([0.0, 0.0, 1.0]))
    return axis, angle


def angular_velocity(matrix: ArrayLike, rate: ArrayLike) -> np.ndarray:
    """omega (rad/s, (..., 3)) from R and dR/dt: the vector of the skew matrix dR/dt R^T, so that a body point
    r = R r0 moves at dr/dt = omega x r (XI.iv)."""
    w = np.asarray(rate, dtype=float) @ np.swapaxes(np.asarray(matrix, dtype=float), -1, -2)
    return 0.5 * np.stack([w[..., 2, 1] - w[..., 1, 2], w[..., 0, 2] - w[..., 2, 0], w[..., 1, 0] - w[..., 0, 1]], -1)


def point_inertia_tensor(masses: ArrayLike, positions: ArrayLike) -> np.ndarray:
    """I = sum_i m_i (|r_i|**2 1 - r_i r_i^T) (kg m**2, (..., 3, 3)) of point masses (..., n) at (..., n, 3) about
    the origin (XI.vi: diagonal int rho (|r|**2 - x_i**2) dV, products of inertia -int rho x_i x_j dV)."""
    m = np.asarray(masses, dtype=float)
    r = np.asarray(positions, dtype=float)
    outer = r[..., :, None] * r[..., None, :]
    squared = np.sum(r * r, axis=-1)
    return np.sum(m[..., None, None] * (squared[..., None, None] * np.eye(3) - outer), axis=-3)


def parallel_axis(inertia_cm: ArrayLike, mass: ArrayLike, offset: ArrayLike) -> np.ndarray:
    """I = I_cm + m (|d|**2 1 - d d^T) (kg m**2): the inertia tensor about a point displaced by d (m) from the
    centre of mass (XI.xiii, Huygens-Steiner; about one axis, I = I_cm + m d_perp**2)."""
    d = np.asarray(offset, dtype=float)
    shift = np.sum(d * d, axis=-1)[..., None, None] * np.eye(3) - d[..., :, None] * d[..., None, :]
    return np.asarray(inertia_cm, dtype=float) + np.asarray(mass, dtype=float)[..., None, None] * shift


def moment_about_axis(inertia: ArrayLike, axis: ArrayLike) -> np.ndarray:
    """I_n = n^T I n (kg m**2): the scalar moment about the axis n through the tensor's reference point
    (XI.x: int rho |r x n|**2 dV)."""
    n = unit_axis(axis)
    return np.einsum("...i,...ij,...j->...", n, np.asarray(inertia, dtype=float), n)


def principal_axes(inertia: ArrayLike) -> tuple[np.ndarray, np.ndarray]:
    """(moments (..., 3) ascending, R (..., 3, 3)) with I = R diag(moments) R^T and det R = +1: the principal
    moments I1 <= I2 <= I3 and axes (R's columns) that make the tensor diagonal (XI.vi)."""
    moments, axes = np.linalg.eigh(np.asarray(inertia, dtype=float))
    sign = np.where(np.linalg.det(axes) < 0, -1.0, 1.0)
    return moments, axes * np.stack([np.ones_like(sign), np.ones_like(sign), sign], -1)[..., None, :]


# The standard bodies' principal moments about the centre of mass, each checked against an mpmath integral of its
# density (tests/core/test_rotation.py).


def solid_sphere(mass: ArrayLike, radius: ArrayLike) -> np.ndarray:
    """(2/5) m r**2 about every axis through the centre (kg m**2, (..., 3))."""
    moment = 0.4 * np.asarray(mass, dtype=float) * np.asarray(radius, dtype=float) ** 2
    return np.stack([moment] * 3, -1)


def spherical_shell(mass: ArrayLike, radius: ArrayLike) -> np.ndarray:
    """(2/3) m r**2 about every axis through the centre of a thin spherical shell (kg m**2, (..., 3))."""
    moment = 2.0 / 3.0 * np.asarray(mass, dtype=float) * np.asarray(radius, dtype=float) ** 2
    return np.stack([moment] * 3, -1)


def solid_cylinder(mass: ArrayLike, radius: ArrayLike, height: ArrayLike) -> np.ndarray:
    """(m (3 r**2 + h**2) / 12, same, m r**2 / 2) (kg m**2): a solid cylinder with its axis along z; h = 0 is a
    disc (m r**2 / 4 about a diameter: the perpendicular-axis theorem, XI.xii)."""
    m, r, h = np.broadcast_arrays(*(np.asarray(x, dtype=float) for x in (mass, radius, height)))
    across = m * (3.0 * r * r + h * h) / 12.0
    return np.stack([across, across, 0.5 * m * r * r], -1)


def thin_hoop(mass: ArrayLike, radius: ArrayLike) -> np.ndarray:
    """(m r**2 / 2, m r**2 / 2, m r**2) (kg m**2): a thin ring in the xy plane (XI.xii: I_z = I_x + I_y)."""
    moment = np.asarray(mass, dtype=float) * np.asarray(radius, dtype=float) ** 2
    return np.stack([0.5 * moment, 0.5 * moment, moment], -1)


def thin_rod(mass: ArrayLike, length: ArrayLike) -> np.ndarray:
    """(m L**2 / 12, m L**2 / 12, 0) (kg m**2): a thin rod along z about its centre."""
    moment = np.asarray(mass, dtype=float) * np.asarray(length, dtype=float) ** 2 / 12.0
    return np.stack([moment, moment, np.zeros_like(moment)], -1)


def cuboid(mass: ArrayLike, a: ArrayLike, b: ArrayLike, c: ArrayLike) -> np.ndarray:
    """(m (b**2 + c**2), m (a**2 + c**2), m (a**2 + b**2)) / 12 (kg m**2): a solid box of edges a, b, c (m) along
    x, y, z about its centre."""
    m, a, b, c = (np.asarray(x, dtype=float) for x in (mass, a, b, c))
    return np.stack([m * (b * b + c * c), m * (a * a + c * c), m * (a * a + b * b)], -1) / 12.0


def rolling_inertia_factor(moment: ArrayLike, mass: ArrayLike, radius: ArrayLike) -> np.ndarray:
    """k = I / (m r**2) (dimensionless) of a body rolling on radius r about an axis of moment I (2/5 for a solid
    ball, 1/2 for a cylinder, 1 for a hoop)."""
    return np.asarray(moment, dtype=float) / (np.asarray(mass, dtype=float) * np.asarray(radius, dtype=float) ** 2)


def rolling_acceleration(g: ArrayLike, incline: ArrayLike, factor: ArrayLike) -> np.ndarray:
    """a = g sin(theta) / (1 + k) (m/s**2): rolling without slipping down an incline of angle theta (rad), from
    m a = m g sin(theta) - f and I alpha = f r with a = alpha r (k = I / (m r**2))."""
    return np.asarray(g, dtype=float) * np.sin(incline) / (1.0 + np.asarray(factor, dtype=float))


def rolling_speed(g: ArrayLike, height: ArrayLike, factor: ArrayLike) -> np.ndarray:
    """v = sqrt(2 g h / (1 + k)) (m/s) after descending a height h (m) from rest, rolling without slipping:
    m g h = m v**2 / 2 + I omega**2 / 2 with omega = v / r (XI.ix)."""
    return np.sqrt(2.0 * np.asarray(g, dtype=float) * np.asarray(height, dtype=float)
                   / (1.0 + np.asarray(factor, dtype=float)))


def rolling_friction_coefficient(incline: ArrayLike, factor: ArrayLike) -> np.ndarray:
    """mu_s >= tan(theta) k / (1 + k) (dimensionless): the least static friction coefficient that keeps the body
    rolling without slipping (friction f = m g sin(theta) k / (1 + k) against the normal force m g cos(theta))."""
    k = np.asarray(factor, dtype=float)
    return np.tan(incline) * k / (1.0 + k)


def fictitious_acceleration(omega: ArrayLike, position: ArrayLike, velocity: ArrayLike = 0.0,
                            omega_rate: ArrayLike = 0.0) -> np.ndarray:
    """-omega x (omega x x) - 2 omega x v - (d omega / dt) x x (m/s**2): centrifugal, Coriolis and Euler
    accelerations in a frame rotating at omega (rad/s) about its origin (XI.xxii)."""
    w = np.asarray(omega, dtype=float)
    x = np.asarray(position, dtype=float)
    v = np.broadcast_to(np.asarray(velocity, dtype=float), x.shape)
    dw = np.broadcast_to(np.asarray(omega_rate, dtype=float), x.shape)
    return -np.cross(w, np.cross(w, x)) - 2.0 * np.cross(w, v) - np.cross(dw, x)
