"""Lagrange points (XXII.viii) against mpmath roots of the raw force balance, published values and identities.

The references never use the quintics of orbits.core.threebody.lagrange: the collinear points are roots of the signed
rotating-frame force x - (1 - mu)(x + mu)/|x + mu|**3 - mu (x - 1 + mu)/|x - 1 + mu|**3 (ERRATA #78), taken
in the offset from the nearer star and solved by mpmath with enough digits for the cancellation at tiny mu;
eigenvalues come from mpmath's eig of the 6 x 6 linearisation built from second derivatives of
Omega = (x**2 + y**2)/2 + (1 - mu)/r_1 + mu/r_2 at those roots.
"""

import math

import mpmath
import numpy as np
import pytest
from mpmath import mp, mpf

from orbits.core.errors import OrbitDomainError
from orbits.core.threebody import lagrange

SUN_EARTH = 3.0034893488507934e-06  # GM_Earth / (GM_Sun + GM_Earth), IAU 2015 nominal values
EARTH_MOON = 0.012150584269940356
MASS_RATIOS = [1e-300, 1e-30, 1e-15, 1e-10, SUN_EARTH, 1e-4, EARTH_MOON, 0.03, 0.0385, 0.1, 0.25, 0.4, 0.499, 0.5]
MASS_RATIOS += list(np.logspace(-15, math.log10(0.5), 25))


def _digits(mu):
    """Working digits: 50 plus those lost to the cancellation 1 - (1 - mu)/(1 - rho)**2 ~ 3 rho at tiny mu."""
    return 50 + math.ceil(-math.log10(float(mu) / 3.0) / 3.0)


def _force_x(mu, x_plus_mu, x_minus_m):
    """Rotating-frame x force on the x axis, from the two signed offsets x + mu and x - (1 - mu)."""
    x = x_plus_mu - mu
    return x - (1 - mu) * x_plus_mu / abs(x_plus_mu) ** 3 - mu * x_minus_m / abs(x_minus_m) ** 3


def _root(f, lo, hi):
    root = mpmath.findroot(f, (lo, hi), solver="anderson", maxsteps=400)
    assert abs(f(root)) < mpf(10) ** (20 - mp.dps) * 10
    return root


def collinear_reference(mu):
    """(rho_1, rho_2, s_3) as mpf: L1, L2 distances from m and L3 distance from M."""
    with mp.workdps(_digits(mu)):
        m = mpf(mu)
        h = mpmath.cbrt(m / 3)
        rho_1 = _root(lambda r: _force_x(m, 1 - r, -r), h / 4, min(2 * h, 1 - mpf(10) ** -9))
        rho_2 = _root(lambda r: _force_x(m, 1 + r, r), h / 2, 3 * h)
        s_3 = _root(lambda s: _force_x(m, -s, -(1 + s)), mpf("0.5"), mpf(1))
        return +rho_1, +rho_2, +s_3


def hessian(mu, x, y):
    """(Omega_xx, Omega_xy, Omega_yy, Omega_zz) at (x, y, 0), mpf."""
    xx, xy, yy, zz = mpf(1), mpf(0), mpf(1), mpf(0)
    for mass, centre in ((1 - mu, -mu), (mu, 1 - mu)):
        dx = x - centre
        r2 = dx * dx + y * y
        r5 = r2 * r2 * mpmath.sqrt(r2)
        xx += mass * (3 * dx * dx - r2) / r5
        xy += 3 * mass * dx * y / r5
        yy += mass * (3 * y * y - r2) / r5
        zz -= mass * r2 / r5
    return xx, xy, yy, zz


def eigenvalues_reference(mu):
    """The six eigenvalues at each of L1..L5 from mpmath.eig of [[0, I], [Hessian, 2J]] at the mp roots."""
    rho_1, rho_2, s_3 = collinear_reference(mu)
    with mp.workdps(_digits(mu)):
        m = mpf(mu)
        points = [(1 - m - rho_1, 0), (1 - m + rho_2, 0), (-m - s_3, 0)]
        points += [(mpf(1) / 2 - m, mpmath.sqrt(3) / 2), (mpf(1) / 2 - m, -mpmath.sqrt(3) / 2)]
        result = []
        for x, y in points:
            xx, xy, yy, zz = hessian(m, mpf(x), mpf(y))
            a = mpmath.zeros(6)
            for i in range(3):
                a[i, i + 3] = 1
            a[3, 0], a[3, 1], a[4, 0], a[4, 1], a[5, 2] = xx, xy, xy, yy, zz
            a[3, 4], a[4, 3] = 2, -2
            result.append([complex(v) for v in mpmath.eig(a, left=False, right=False)])
        return result


@pytest.mark.parametrize("mu", MASS_RATIOS)
def test_collinear_offsets_within_2_ulp_of_mpmath(mu):
    refs = collinear_reference(mu)
    for value, ref in zip(lagrange.collinear_offsets(mu), refs):
        with mp.workdps(_digits(mu)):
            assert abs(mpf(float(value)) - ref) / mpf(math.ulp(float(ref))) <= 2.0, (mu, value, ref)


@pytest.mark.parametrize("mu", MASS_RATIOS)
def test_positions_within_an_ulp_of_r_and_triangles_equilateral(mu):
    rho_1, rho_2, s_3 = collinear_reference(mu)
    positions = lagrange.positions(mu)
    with mp.workdps(_digits(mu)):
        m = mpf(mu)
        for x, ref in zip(positions[:3, 0], (1 - m - rho_1, 1 - m + rho_2, -m - s_3)):
            assert abs(mpf(float(x)) - ref) <= mpf(2.0**-52), (mu, x, ref)  # one ulp of r = 1
        for x, y, _ in positions[3:]:
            for centre in (-m, 1 - m):  # EDGE 6.3: L4/L5 exactly equilateral (<= 2 ulp)
                distance = mpmath.sqrt((mpf(float(x)) - centre) ** 2 + mpf(float(y)) ** 2)
                assert abs(distance - 1) <= 2 * mpf(2.0**-53)
    assert np.all(positions[:, 2] == 0.0) and np.all(positions[:3, 1] == 0.0)


@pytest.mark.parametrize("mu", [m for m in MASS_RATIOS if m >= 1e-15])
def test_force_residual_at_the_returned_points(mu):
    """|rotating-frame force| at the float64 point <= 1e-14 of the primaries' gravity there (measured <= 1e-15)."""
    with mp.workdps(40):
        m = mpf(mu)
        for x, y, _ in lagrange.positions(mu):
            x, y = mpf(float(x)), mpf(float(y))
            r1, r2 = mpmath.sqrt((x + m) ** 2 + y * y), mpmath.sqrt((x - 1 + m) ** 2 + y * y)
            fx = x - (1 - m) * (x + m) / r1**3 - m * (x - 1 + m) / r2**3
            fy = y - (1 - m) * y / r1**3 - m * y / r2**3
            gravity = (1 - m) / r1**2 + m / r2**2
            assert mpmath.sqrt(fx * fx + fy * fy) / gravity <= 1e-15, (mu, x, y)


def test_edge_46_tiny_mass_ratio_offsets_in_hill_units():
    """EDGE 46: at mu = 1e-15, rho/h = 0.99999768879 (L1) and 1.0000023112 (L2), h = (mu/3)**(1/3)."""
    rho_1, rho_2, _ = lagrange.collinear_offsets(1e-15)
    h = (1e-15 / 3) ** (1 / 3)
    assert abs(rho_1 / h - 0.99999768879) < 1e-11
    assert abs(rho_2 / h - 1.0000023112) < 1e-10
    # Hill's series rho/h = 1 -+ h/3 - h**2/9 (EDGE 46), to its next order ~h**3
    assert abs(rho_1 / h - (1 - h / 3 - h * h / 9)) < 10 * h**3
    assert abs(rho_2 / h - (1 + h / 3 - h * h / 9)) < 10 * h**3


def test_edge_48_equal_masses():
    """EDGE 48: mu = 1/2 puts L1 exactly at the barycentre and x_L2 = -x_L3 = 1.19840614455..."""
    x = lagrange.positions(0.5)[:, 0]
    assert x[0] == 0.0
    assert abs(x[1] - 1.19840614455) < 1e-11 and abs(x[2] + 1.19840614455) < 1e-11
    assert abs(x[1] + x[2]) <= math.ulp(x[1])


@pytest.mark.parametrize("mu", [0.0, -1e-3, 0.5000000000000001, 0.7, math.nan, math.inf, -math.inf])
def test_edges_47_49_50_mass_ratio_outside_the_range(mu):
    with pytest.raises(OrbitDomainError, match=r"mass ratio mu = m / \(M \+ m\)") as err:
        lagrange.positions(mu)
    assert "(0, 0.5]" in str(err.value) or "not finite" in str(err.value)


def test_edge_47_massless_secondary_message_and_edge_49_message():
    with pytest.raises(OrbitDomainError, match="massless secondary"):
        lagrange.collinear_offsets(0.0)
    with pytest.raises(OrbitDomainError, match="pass the heavier body as the primary"):
        lagrange.collinear_offsets(0.6)


@pytest.mark.parametrize("mu", [1e-15, 1e-10, SUN_EARTH, EARTH_MOON, 0.0385, 0.03852089650455141, 0.1, 0.3, 0.5])
def test_eigenvalues_against_mpmath(mu):
    mine = lagrange.eigenvalues(mu)
    for k, ref in enumerate(eigenvalues_reference(mu)):
        scale = max(abs(v) for v in ref)
        for value in mine[k]:
            assert min(abs(value - r) for r in ref) <= 2e-14 * scale, (mu, k, value, ref)
        growth = max(v.real for v in ref)
        if growth > 1e-12:
            assert abs(lagrange.growth_rates(mu)[k] - growth) <= 1e-13 * growth


def test_published_earth_moon_values():
    """Earth-Moon (mu = 0.01215): L1, L2 saddle rates 2.932 and 2.159; L4 libration frequencies 0.9545 and
    0.2982 (units of n; e.g. Szebehely 1967, Theory of Orbits, ch. 5) and C(L4) = 3 - mu + mu**2."""
    values = lagrange.eigenvalues(EARTH_MOON)
    assert abs(values[0, 0].real - 2.932) < 1e-3 and abs(values[1, 0].real - 2.159) < 1e-3
    frequencies = sorted(abs(v.imag) for v in values[3, :4])
    assert abs(frequencies[0] - 0.2982) < 1e-4 and abs(frequencies[-1] - 0.9545) < 1e-4
    c4 = lagrange.jacobi_constant(lagrange.positions(EARTH_MOON)[3], np.zeros(3), EARTH_MOON)
    assert abs(c4 - (3 - EARTH_MOON + EARTH_MOON**2)) <= 4 * math.ulp(3.0)


def test_l3_rate_at_tiny_mass_ratio_follows_its_asymptote():
    """lambda_L3**2 = 21 mu / 8 (1 + O(mu)): needs A - 1 = 7 mu / 8 without cancellation."""
    for mu in (1e-300, 1e-200, 1e-15, 1e-10):
        assert abs(lagrange.growth_rates(mu)[2] / math.sqrt(21 * mu / 8) - 1) < 1e-13 + 10 * mu


def test_routh_boundary_is_exact():
    """EDGE 51: L4/L5 stable iff mu < mu_R = (1 - sqrt(23/27))/2 = 0.0385208965046; mu_R is not a float64, so
    the floats on either side of it decide the convention."""
    with mp.workdps(50):
        mu_r = (1 - mpmath.sqrt(mpf(23) / 27)) / 2
        assert abs(mpf(lagrange.ROUTH_MASS_RATIO) + mpf(lagrange._ROUTH_LO) - mu_r) < mpf(10) ** -33
        below = float(mu_r) if mpf(float(mu_r)) < mu_r else math.nextafter(float(mu_r), 0)
    above = math.nextafter(below, 1)
    assert abs(below - 0.0385208965046) < 1e-13
    assert lagrange.triangular_points_stable(below) and not lagrange.triangular_points_stable(above)
    rates_below, rates_above = lagrange.growth_rates(below), lagrange.growth_rates(above)
    assert np.all(rates_below[3:] == 0.0) and np.all(rates_above[3:] > 0.0)
    assert np.all(lagrange.eigenvalues(below)[3:].real == 0.0)


def test_collinear_points_always_unstable_and_triangles_stable_below_routh():
    mu = np.logspace(-15, math.log10(0.5), 200)
    rates = lagrange.growth_rates(mu)
    assert np.all(rates[:, :3] > 0.0)
    stable = mu < lagrange.ROUTH_MASS_RATIO
    assert np.all(rates[stable, 3:] == 0.0) and np.all(rates[~stable, 3:] > 0.0)
    assert np.array_equal(lagrange.triangular_points_stable(mu), stable)


def test_growing_mode_is_an_eigenvector():
    for mu in (EARTH_MOON, 0.1):
        values, modes = lagrange.eigenvalues(mu), lagrange.growing_mode(mu)
        for k in range(5):
            rate = lagrange.growth_rates(mu)[k]
            if rate == 0.0:
                assert np.all(modes[k] == 0.0)
                continue
            lam = values[k][np.argmax(values[k].real)]
            if lam.imag == 0.0:  # real eigenvector: A v = lambda v with A from the float Hessian
                with mp.workdps(30):
                    x, y = (mpf(float(c)) for c in lagrange.positions(mu)[k, :2])
                    xx, xy, yy, _ = (float(c) for c in hessian(mpf(mu), x, y))
                dx, dy, _, vx, vy, _ = modes[k]
                residual = [vx - lam.real * dx, xx * dx + xy * dy + 2 * vy - lam.real * vx]
                residual += [xy * dx + yy * dy - 2 * vx - lam.real * vy]
                assert max(abs(r) for r in residual) < 1e-12
            assert abs(math.hypot(modes[k, 0], modes[k, 1]) - 1) < 1e-15


def test_jacobi_constant_inertial_and_rotating_forms_agree():
    rng = np.random.default_rng(5)
    mu = 0.1
    r_rot, v_rot = rng.normal(size=(50, 3)), rng.normal(size=(50, 3))
    angle = rng.uniform(0, 2 * np.pi, 50)
    r_in, v_in = lagrange.rotating_to_inertial(r_rot, v_rot, angle[:, None])
    primary, _ = lagrange.rotating_to_inertial(np.array([-mu, 0, 0]), np.zeros(3), angle[:, None])
    secondary, _ = lagrange.rotating_to_inertial(np.array([1 - mu, 0, 0]), np.zeros(3), angle[:, None])
    c_rot = lagrange.jacobi_constant(r_rot, v_rot, mu)
    c_in = lagrange.jacobi_constant_inertial(r_in, v_in, primary, secondary, mu)
    assert np.max(np.abs(c_rot - c_in) / np.abs(c_rot)) < 1e-13
    back = lagrange.rotating_coordinates(r_in, primary, secondary, mu)
    assert np.max(np.abs(back - r_rot)) < 1e-14


def test_rotating_to_inertial_in_a_tilted_plane():
    r, v = lagrange.rotating_to_inertial(np.array([1.0, 0, 0]), np.zeros(3), np.pi / 2, inc=np.pi / 2, raan=0.0)
    assert np.allclose(r, [0, 0, 1], atol=1e-16)  # the plane x-z, node on x: the frame's x axis is now up
    assert np.allclose(v, [-1, 0, 0], atol=1e-16)  # h_hat x r with the plane normal h_hat = (0, -1, 0)


def test_effective_potential_and_broadcasting():
    mu = np.array([[1e-6], [0.25]])
    positions = lagrange.positions(mu)
    assert positions.shape == (2, 1, 5, 3)
    phi = lagrange.effective_potential(positions, mu[..., None])
    assert phi.shape == (2, 1, 5)
    with np.errstate(divide="ignore"):
        assert lagrange.effective_potential(np.array([-0.25, 0, 0]), 0.25) == -np.inf


@pytest.mark.slow
def test_collinear_offsets_on_a_broad_random_set(fresh_seed):
    """L1, L2, L3 offsets for random mass ratios, log-uniform over [1e-300, 0.5] and uniform over (0, 0.5), against
    mpmath: within 3 ulp (measured over 12,000 ratios: 2.27 ulp at mu = 0.4984, L3; 2.19 at 0.4045, L1). The count
    scales with ORBITS_SLOW_SCALE (200 at 0.05)."""
    from sizes import slow_scale

    rng = np.random.default_rng(fresh_seed)
    n = max(100, int(4000 * slow_scale()))
    mus = np.concatenate([10 ** rng.uniform(-300, math.log10(0.5), n // 2), rng.uniform(0, 0.5, n - n // 2)])
    worst = 0.0
    for mu in mus:
        for value, ref in zip(lagrange.collinear_offsets(float(mu)), collinear_reference(float(mu))):
            with mp.workdps(_digits(mu)):
                worst = max(worst, float(abs(mpf(float(value)) - ref) / mpf(math.ulp(float(ref)))))
    assert worst <= 3.0, (fresh_seed, worst)
