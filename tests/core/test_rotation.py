"""Rotations, inertia and rolling (notes XI): orthogonality, round trips, mpmath integrals of the definitions."""

import math

import mpmath
import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from orbits.core.errors import OrbitDomainError
from orbits.core.mechanics import rotation

components = st.floats(-10, 10)
axes = st.tuples(components, components, components).filter(lambda v: math.hypot(*v) > 1e-3)


@given(axes, st.floats(-10, 10))
def test_rotation_matrices_are_proper_orthogonal(axis, angle):
    """R^T R = 1 and det R = 1 (SO(3), XI.ii): both measured 2.0e-15 over 20000 random axes and |angles| < 10."""
    r = rotation.rotation_matrix(axis, angle)
    assert np.max(np.abs(r.T @ r - np.eye(3))) < 1e-14
    assert abs(np.linalg.det(r) - 1) < 1e-14
    n = rotation.unit_axis(axis)
    np.testing.assert_allclose(r @ n, n, atol=2e-15)  # the axis is fixed (Euler's theorem)


@given(axes, st.floats(0, math.pi))
def test_axis_angle_round_trip(axis, angle):
    """axis_angle(rotation_matrix(n, a)) = (n, a) for a in [0, pi]: within 4e-15 rad (measured 1.1e-15)."""
    got_axis, got_angle = rotation.axis_angle(rotation.rotation_matrix(axis, angle))
    assert abs(got_angle - angle) < 4e-15
    if 1e-6 < angle < math.pi - 1e-6:
        np.testing.assert_allclose(got_axis, rotation.unit_axis(axis), atol=4e-15 / min(angle, math.pi - angle))


@pytest.mark.parametrize("angle", [0.0, 1e-300, 1e-12, 1e-6, math.pi / 2, math.pi - 1e-9, math.pi])
def test_axis_angle_at_the_ends_of_the_range(angle):
    """The quaternion path keeps small angles and angles near pi exact (where arccos((tr R - 1) / 2) would not)."""
    axis = np.array([2.0, -1.0, 0.5])
    got_axis, got_angle = rotation.axis_angle(rotation.rotation_matrix(axis, angle))
    assert got_angle == pytest.approx(angle, rel=4e-16, abs=1e-300)
    if angle >= 1e-12:  # below about 1e-16 the matrix rounds to the identity and keeps no axis
        unit = axis / np.linalg.norm(axis)
        assert min(np.max(np.abs(got_axis - unit)), np.max(np.abs(got_axis + unit))) < 1e-15
    elif angle == 0:
        assert list(got_axis) == [0.0, 0.0, 1.0]  # the identity's axis, by convention


@given(st.floats(-3.1, 3.1), st.floats(-1.5, 1.5), st.floats(-3.1, 3.1))
def test_principal_angles_round_trip(ax, ay, az):
    """R = Rz Ry Rx (XI.iii) and back: within 4e-15 rad away from gimbal lock (measured 4.4e-16)."""
    got = rotation.principal_angles(rotation.from_principal_angles(ax, ay, az))
    assert np.max(np.abs(np.array(got) - (ax, ay, az))) < 4e-15


def test_principal_rotations_turn_the_axes_as_the_right_hand_rule_says():
    quarter = math.pi / 2
    np.testing.assert_allclose(rotation.principal_rotation("z", quarter) @ [1, 0, 0], [0, 1, 0], atol=4e-16)
    np.testing.assert_allclose(rotation.principal_rotation("x", quarter) @ [0, 1, 0], [0, 0, 1], atol=4e-16)
    np.testing.assert_allclose(rotation.principal_rotation("y", quarter) @ [0, 0, 1], [1, 0, 0], atol=4e-16)
    r = rotation.from_principal_angles(0.3, math.pi / 2, 0.5)  # gimbal lock: only ax - az matters
    np.testing.assert_allclose(rotation.from_principal_angles(*rotation.principal_angles(r)), r, atol=1e-15)
    with pytest.raises(OrbitDomainError, match="not one of x, y, z"):
        rotation.principal_rotation("w", 1.0)
    with pytest.raises(OrbitDomainError, match="finite nonzero"):
        rotation.rotation_matrix([0, 0, 0], 1.0)


def test_rotations_about_one_axis_add_and_different_axes_do_not_commute():
    """XI.ii and XI.x: angles add about one axis; finite rotations about different axes do not commute."""
    n = [1.0, 1.0, 0.0]
    np.testing.assert_allclose(rotation.rotation_matrix(n, 0.4) @ rotation.rotation_matrix(n, 0.9),
                               rotation.rotation_matrix(n, 1.3), atol=4e-16)
    a, b = rotation.principal_rotation("x", 0.5), rotation.principal_rotation("y", 0.5)
    assert np.max(np.abs(a @ b - b @ a)) > 0.1


def test_angular_velocity_from_a_turning_matrix():
    """dR/dt R^T = [omega]x for R(t) = R(n, w t) R0 (XI.iv): omega = w n; a body point moves at omega x r."""
    n, w, t = rotation.unit_axis([1.0, 2.0, 2.0]), 0.7, 1.3
    r0 = rotation.from_principal_angles(0.2, -0.4, 1.0)
    r = rotation.rotation_matrix(n, w * t) @ r0
    rate = w * rotation.cross_matrix(n) @ r
    np.testing.assert_allclose(rotation.angular_velocity(r, rate), w * n, atol=4e-16)


# ---- inertia ----------------------------------------------------------------------------------------------------

def mp_integral(function, *limits):
    with mpmath.workdps(20):
        return float(mpmath.quad(function, *limits, method="gauss-legendre"))


def reference_moments(body):
    """(I_xx, I_zz) from mpmath integrals of the definition (XI.vi) for unit mass and sizes 1.3, 0.7."""
    r, h = 1.3, 0.7
    pi = mpmath.pi
    if body == "solid_sphere":
        rho = 1 / (4 * pi / 3 * r**3)
        zz = mp_integral(lambda s, th, ph: rho * (s * mpmath.sin(th)) ** 2 * s**2 * mpmath.sin(th),
                         [0, r], [0, pi], [0, 2 * pi])
        return zz, zz
    if body == "spherical_shell":
        sigma = 1 / (4 * pi * r**2)
        zz = mp_integral(lambda th, ph: sigma * (r * mpmath.sin(th)) ** 2 * r**2 * mpmath.sin(th), [0, pi], [0, 2 * pi])
        return zz, zz
    if body == "solid_cylinder":
        rho = 1 / (pi * r**2 * h)
        xx = mp_integral(lambda s, ph, z: rho * ((s * mpmath.sin(ph)) ** 2 + z**2) * s, [0, r], [0, 2 * pi],
                         [-h / 2, h / 2])
        zz = mp_integral(lambda s, ph, z: rho * s**3, [0, r], [0, 2 * pi], [-h / 2, h / 2])
        return xx, zz
    if body == "thin_hoop":
        lam = 1 / (2 * pi * r)
        return (mp_integral(lambda ph: lam * (r * mpmath.sin(ph)) ** 2 * r, [0, 2 * pi]),
                mp_integral(lambda ph: lam * r**3, [0, 2 * pi]))
    if body == "thin_rod":
        return mp_integral(lambda z: z**2 / r, [-r / 2, r / 2]), 0.0
    if body == "cuboid":
        rho = 1 / (r * h * 0.4)
        xx = mp_integral(lambda x, y, z: rho * (y**2 + z**2), [-r / 2, r / 2], [-h / 2, h / 2], [-0.2, 0.2])
        zz = mp_integral(lambda x, y, z: rho * (x**2 + y**2), [-r / 2, r / 2], [-h / 2, h / 2], [-0.2, 0.2])
        return xx, zz
    raise KeyError(body)


BODIES = {
    "solid_sphere": lambda: rotation.solid_sphere(1.0, 1.3),
    "spherical_shell": lambda: rotation.spherical_shell(1.0, 1.3),
    "solid_cylinder": lambda: rotation.solid_cylinder(1.0, 1.3, 0.7),
    "thin_hoop": lambda: rotation.thin_hoop(1.0, 1.3),
    "thin_rod": lambda: rotation.thin_rod(1.0, 1.3),
    "cuboid": lambda: rotation.cuboid(1.0, 1.3, 0.7, 0.4),
}


@pytest.mark.parametrize("body", BODIES)
def test_standard_moments_equal_the_integrals_of_their_density(body):
    """Each standard body's principal moments against mpmath integrals of I_xx and I_zz: measured 2.0e-16."""
    moments = BODIES[body]()
    xx, zz = reference_moments(body)
    assert moments[0] == pytest.approx(xx, rel=2e-15, abs=1e-300)
    assert moments[2] == pytest.approx(zz, rel=2e-15, abs=1e-300)


def test_perpendicular_axis_theorem_for_laminas():
    """XI.xii: I_z = I_x + I_y for a hoop, a disc (cylinder of height 0) and a flat rectangle."""
    for moments in (rotation.thin_hoop(2.0, 0.5), rotation.solid_cylinder(2.0, 0.5, 0.0),
                    rotation.cuboid(2.0, 0.5, 0.3, 0.0)):
        assert moments[2] == pytest.approx(moments[0] + moments[1], rel=4e-16)


@pytest.fixture
def cloud():
    rng = np.random.default_rng(7)
    return rng.uniform(0.5, 2.0, 12), rng.normal(size=(12, 3))


def test_point_inertia_parallel_axis_and_principal_axes(cloud):
    """Tensor about the CM, shifted by the parallel-axis theorem (XI.xiii), equals the tensor summed directly
    about the new point; principal axes diagonalise it (measured 8.9e-16 relative)."""
    m, r = cloud
    cm = (m[:, None] * r).sum(0) / m.sum()
    about_cm = rotation.point_inertia_tensor(m, r - cm)
    point = np.array([0.3, -1.2, 2.0])
    direct = rotation.point_inertia_tensor(m, r - point)
    shifted = rotation.parallel_axis(about_cm, m.sum(), cm - point)
    assert np.max(np.abs(shifted - direct)) < 1e-14 * np.max(np.abs(direct))
    moments, frame = rotation.principal_axes(about_cm)
    assert np.all(np.diff(moments) >= 0) and abs(np.linalg.det(frame) - 1) < 1e-14  # measured 1.3e-15
    np.testing.assert_allclose(frame @ np.diag(moments) @ frame.T, about_cm, atol=1e-14 * moments[-1])
    n = np.array([0.0, 0.0, 1.0])  # scalar form: I = I_cm + m d_perp**2 about parallel z axes
    d_perp2 = (cm - point)[0] ** 2 + (cm - point)[1] ** 2
    assert rotation.moment_about_axis(direct, n) == pytest.approx(
        rotation.moment_about_axis(about_cm, n) + m.sum() * d_perp2, rel=1e-14)


def test_product_of_inertia_uses_x_and_z():
    """XI.vi prints I_xz with I_yz's integrand (r.j)(r.z); the product of inertia is -sum m x z."""
    tensor = rotation.point_inertia_tensor([2.0], [[1.0, 0.0, 3.0]])
    assert tensor[0, 2] == tensor[2, 0] == -6.0 and tensor[1, 2] == 0.0


def test_angular_momentum_and_rotational_energy_of_a_body(cloud):
    """L = I omega = sum m r x (omega x r) (XI.vii) and K_r = omega^T I omega / 2 = sum m |omega x r|**2 / 2
    (XI.ix), measured 4.4e-16 relative."""
    m, r = cloud
    omega = np.array([0.3, -1.1, 0.8])
    tensor = rotation.point_inertia_tensor(m, r)
    velocities = np.cross(omega, r)
    direct = (m[:, None] * np.cross(r, velocities)).sum(0)
    np.testing.assert_allclose(tensor @ omega, direct, rtol=1e-14)
    assert 0.5 * omega @ tensor @ omega == pytest.approx(0.5 * (m * (velocities**2).sum(1)).sum(), rel=1e-14)


@pytest.mark.parametrize("name, factor, share", [("ball", 0.4, 5 / 7), ("cylinder", 0.5, 2 / 3), ("hoop", 1.0, 0.5)])
def test_rolling_down_an_incline(name, factor, share):
    """a = g sin(theta) / (1 + k): 5/7, 2/3 and 1/2 of g sin(theta) for a ball, a cylinder and a hoop; the speed
    after a drop h conserves m g h = m v**2 / 2 + I omega**2 / 2 with omega = v / r; friction f = m a k."""
    g, incline, height, mass, radius = 9.80665, math.radians(25.0), 2.0, 3.0, 0.2
    moment = {"ball": rotation.solid_sphere, "cylinder": lambda m, r: rotation.solid_cylinder(m, r, 1.0),
              "hoop": rotation.thin_hoop}[name](mass, radius)[2]
    k = rotation.rolling_inertia_factor(moment, mass, radius)
    assert k == pytest.approx(factor, rel=4e-16)
    assert rotation.rolling_acceleration(g, incline, k) == pytest.approx(share * g * math.sin(incline), rel=4e-16)
    v = rotation.rolling_speed(g, height, k)
    assert 0.5 * mass * v**2 + 0.5 * moment * (v / radius) ** 2 == pytest.approx(mass * g * height, rel=4e-16)
    friction = mass * rotation.rolling_acceleration(g, incline, k) * k
    normal = mass * g * math.cos(incline)
    assert rotation.rolling_friction_coefficient(incline, k) == pytest.approx(friction / normal, rel=4e-16)


def test_fictitious_accelerations():
    """XI.xxii: the centrifugal acceleration is omega**2 times the distance from the axis, away from it; the
    Coriolis one is -2 omega x v; the Euler one -(d omega / dt) x x."""
    omega, x, v = np.array([0, 0, 2.0]), np.array([3.0, 0.0, 5.0]), np.array([0.0, 1.0, 0.0])
    np.testing.assert_allclose(rotation.fictitious_acceleration(omega, x), [12.0, 0, 0])
    np.testing.assert_allclose(rotation.fictitious_acceleration(omega, x, v), [12.0 + 4.0, 0, 0])
    np.testing.assert_allclose(rotation.fictitious_acceleration(0 * omega, x, 0.0, omega), [0, -6.0, 0])
