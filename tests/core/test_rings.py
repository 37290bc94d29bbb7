"""Regular-polygon rings (XXIII, Maxwell's ring) against direct N-body sums, mpmath, an independent Cartesian
linearisation, and the published stability results (Routh 1875, Maxwell 1859, Moeckel 1994)."""

import math

import mpmath
import numpy as np
import pytest
from mpmath import mp, mpf

from orbits.core.errors import OrbitDomainError
from orbits.core.threebody import rings


def csc_sum_euler_maclaurin(n, terms=12):
    """S_n from csc t = 1/t + 1/(pi - t) + h(t), h smooth: S_n = (2n/pi)(H_{n-1} + ln(2/pi)) + 1/pi
    - 2 sum_j B_2j / (2j) (pi/n)**(2j-1) (a_j - pi**-2j), with a_j the Taylor coefficients of csc t - 1/t
    (Euler-Maclaurin on h, symmetric about pi/2). Independent of the float64 summation; checked against the
    direct mpmath sum below."""
    with mp.workdps(40):
        n = mpf(n)
        step = mp.pi / n
        total = (2 * n / mp.pi) * (mpmath.harmonic(n - 1) + mpmath.log(2 / mp.pi)) + 1 / mp.pi
        for j in range(1, terms + 1):
            b = mpmath.bernoulli(2 * j)
            a = (-1) ** (j + 1) * 2 * (2 ** (2 * j - 1) - 1) * b / mpmath.factorial(2 * j)
            total -= 2 * (b / (2 * j)) * step ** (2 * j - 1) * (a - mp.pi ** (-2 * j))
        return total


def csc_sum_direct(n):
    with mp.workdps(40):
        return mpmath.fsum(1 / mpmath.sin(mp.pi * k / n) for k in range(1, n))


def test_euler_maclaurin_reference_matches_the_direct_sum():
    for n in (50, 200, 1001):
        with mp.workdps(40):
            assert abs(csc_sum_euler_maclaurin(n) - csc_sum_direct(n)) < mpf(10) ** -33


@pytest.mark.parametrize("n", [2, 3, 4, 5, 6, 7, 8, 9, 10, 16, 17, 100, 257])
def test_csc_sum_against_mpmath(n):
    with mp.workdps(40):
        ref = csc_sum_direct(n)
        assert abs(mpf(rings.csc_sum(n)) - ref) <= 3 * mpf(math.ulp(float(ref)))
    assert rings.csc_sum(2) == 1.0
    assert abs(rings.csc_sum(3) - 4 / math.sqrt(3)) <= 2 * math.ulp(2.3)


@pytest.mark.parametrize("n", [12345, 100_000, 1_000_000])
def test_csc_sum_of_a_million_bodies_keeps_its_digits(n):
    """EDGE 54: n = 1e6 must not lose accuracy (a naive sum over k near n loses 1e-10 relative)."""
    with mp.workdps(40):
        ref = csc_sum_euler_maclaurin(n)
        assert abs(mpf(rings.csc_sum(n)) - ref) <= 3 * mpf(math.ulp(float(ref)))


def test_edge_52_count_checks():
    for bad in (2.5, True, np.bool_(True), "3", 3.0):
        with pytest.raises(TypeError, match="must be an integer"):
            rings.check_count(bad)
    for bad in (1, 0, -3, np.int64(1)):
        with pytest.raises(OrbitDomainError, match=r"outside \[2, inf\)"):
            rings.check_count(bad)
    assert rings.check_count(np.int32(7)) == 7 and type(rings.check_count(np.int64(7))) is int


def test_edge_53_two_bodies_are_the_equal_mass_binary():
    gm, r = 1.2e10, 3.0e6
    assert rings.effective_gm(2, gm) / r == gm / (4 * r)  # v**2 = G m / (4 R) exactly


@pytest.mark.parametrize("n", [2, 3, 4, 5, 6, 7, 8, 64, 1000, 10_000])
@pytest.mark.parametrize("beta", [0.0, 3.0, 1e12])
def test_force_balance_against_a_direct_mpmath_force_sum(n, beta):
    """EDGE 6.3: v**2 / r = a_radial from the vector sum of the attractions on one body at the exact vertices
    (30 digits) equals GM_eff / r**2 to 1e-15 relative (target 1e-14) for n up to 1e4."""
    with mp.workdps(30):
        gm, r = mpf(1.5), mpf(2)
        a_radial = beta * gm / r**2
        for j in range(1, n):
            dx, dy = r * (1 - mpmath.cos(2 * mp.pi * j / n)), r * mpmath.sin(2 * mp.pi * j / n)
            a_radial += gm * dx / mpmath.hypot(dx, dy) ** 3
    assert abs(rings.effective_gm(n, 1.5, beta * 1.5) / 4.0 - float(a_radial)) <= 1e-15 * float(a_radial)


def test_state_vectors_are_the_rounded_polygon():
    for n in (3, 7, 1000):
        positions, velocities = rings.state_vectors(n, 2.0, 3.0, phase=0.25)
        with mp.workdps(30):
            for k in (0, 1, n // 3, n - 1):
                angle = mpf(0.25) + 2 * mp.pi * k / n
                assert abs(positions[k, 0] - 2 * mpmath.cos(angle)) <= 2 * 2.0**-52 * 2
                assert abs(velocities[k, 1] - 3 * mpmath.cos(angle)) <= 2 * 2.0**-52 * 3
        assert np.all(positions[:, 2] == 0.0) and np.all(np.abs(np.sum(positions * velocities, axis=-1)) < 1e-14)


def cartesian_linearisation(n, beta):
    """The full rotating-frame linearisation of the n ring bodies and (beta > 0) the central body, by
    complex-step differentiation of the direct N-body accelerations (omega = 1, r = 1): 4(n + 1) or 4n."""
    g = 1.0 / (beta + rings.csc_sum(n) / 4)
    angles = 2 * np.pi * np.arange(n) / n
    positions, masses = np.stack([np.cos(angles), np.sin(angles)], axis=-1), np.full(n, g)
    if beta > 0:
        positions, masses = np.vstack([positions, [0.0, 0.0]]), np.append(masses, beta * g)
    count = masses.size

    def accelerations(x):
        x = x.reshape(count, 2)
        a = x * (1.0 + 0j)
        for k in range(count):
            for j in range(count):
                if j != k:
                    d = x[j] - x[k]
                    a[k] = a[k] + masses[j] * d / (d[0] ** 2 + d[1] ** 2) ** 1.5
        return a.ravel()

    hessian = np.empty((2 * count, 2 * count))
    for i in range(2 * count):
        x = positions.ravel().astype(complex)
        x[i] += 1e-30j
        hessian[:, i] = accelerations(x).imag / 1e-30
    a = np.zeros((4 * count, 4 * count))
    a[: 2 * count, 2 * count :] = np.eye(2 * count)
    a[2 * count :, : 2 * count] = hessian
    a[2 * count :, 2 * count :] = np.kron(np.eye(count), [[0.0, 2.0], [-2.0, 0.0]])
    return np.linalg.eigvals(a)


@pytest.mark.parametrize("n", range(2, 9))
@pytest.mark.parametrize("beta", [0.0, 1.0, 30.0, 300.0])
def test_mode_eigenvalues_match_the_cartesian_linearisation(n, beta):
    """Every mode eigenvalue is an eigenvalue of the independent Cartesian linearisation (double roots agree
    to 1e-7, their float64 floor); the largest growth rates agree to 1e-12."""
    mine, reference = rings.eigenvalues(n, beta).ravel(), cartesian_linearisation(n, beta)
    assert mine.size == 4 * n
    for value in mine:
        assert np.min(np.abs(reference - value)) < 1e-7
    rate, _ = rings.growth_rate(n, beta)
    assert abs(rate - max(reference.real.max(), 0.0)) < 1e-12 or (rate == 0.0 and reference.real.max() < 1e-7)


def test_three_equal_masses_are_lagrange_triangle_with_routh_rate():
    """n = 3 without central mass is Lagrange's equilateral solution with three equal masses; Routh's quartic
    lambda**4 + lambda**2 + 27 (m1 m2 + m2 m3 + m3 m1)/M**2 / 4 = 0 gives lambda**2 = (-1 +- i sqrt(8)) / 2,
    so Re lambda = 1/sqrt(2) (units of omega)."""
    rate, mode = rings.growth_rate(3, 0.0)
    assert abs(rate - 1 / math.sqrt(2)) < 1e-14 and mode in (1, 2)


def test_exactly_known_modes_are_exact():
    for n, beta in ((2, 0.0), (5, 0.0), (7, 500.0)):
        values = rings.eigenvalues(n, beta)
        assert sorted(values[0], key=lambda z: (z.imag, z.real)) == [-1j, 0j, 0j, 1j]
        raw = np.linalg.eigvals(rings.mode_matrices(n, beta)[0])
        assert all(np.min(np.abs(raw - v)) < 1e-7 for v in values[0])
        if beta == 0.0:
            assert np.sum(values[1] == 1j) == 2 and np.sum(values[-1] == -1j) == 2
    assert rings.growth_rate(2, 0.0) == (0.0, None)  # the circular binary is neutrally stable


@pytest.mark.parametrize("n", range(3, 9))
def test_rings_without_central_mass_are_unstable(n):
    rate, _ = rings.growth_rate(n, 0.0)
    assert rate > 0.5


@pytest.mark.parametrize("n", range(2, 7))
def test_moeckel_rings_of_2_to_6_are_unstable_for_every_central_mass(n):
    """Moeckel 1994, Vanderbei & Kolemen 2007: n <= 6 never stable; the growth falls as sqrt(m / M)."""
    rates = [rings.growth_rate(n, beta)[0] for beta in (1.0, 1e2, 1e4, 1e8, 1e12, 1e16)]
    assert all(r > 0.0 for r in rates)
    assert abs(rates[4] / rates[3] - 1e-2) < 1e-5 and abs(rates[5] / rates[4] - 1e-2) < 1e-4
    with pytest.raises(OrbitDomainError, match="never stable|linearly unstable for every central mass"):
        rings.central_mass_threshold(n)


@pytest.mark.parametrize("n", [7, 8, 9, 12, 20])
def test_threshold_separates_unstable_from_stable(n):
    """Stable iff M / m >= beta_c, which grows like n**3: unstable just below, stable just above and on a
    grid up to 1e16 (no instability window above the threshold)."""
    beta_c = rings.central_mass_threshold(n)
    assert 0.40 * n**3 < beta_c < 0.4351 * n**3
    assert rings.growth_rate(n, beta_c * (1 - 1e-9))[0] > 0.0
    for beta in beta_c * np.array([1 + 1e-9, 1.001, 1.1, 2.0, 10.0, 1e3, 1e6, 1e10, 1e13]):
        assert rings.growth_rate(n, beta) == (0.0, None), beta
    for beta in beta_c * np.array([0.999, 0.9, 0.5, 0.1]):
        assert rings.growth_rate(n, beta)[0] > 0.0


def test_threshold_values_against_the_cartesian_linearisation():
    """beta_c / n**3 = 0.40773 (n = 7), 0.41457 (n = 8), rising monotonically; the independent Cartesian
    linearisation grows at 0.999 beta_c and is neutral (to its 1e-7 floor) at 1.001 beta_c."""
    ratios = [rings.central_mass_threshold(n) / n**3 for n in (7, 8, 9, 10, 16, 32)]
    assert abs(ratios[0] - 0.40773) < 1e-5 and abs(ratios[1] - 0.41457) < 1e-5
    assert all(a < b for a, b in zip(ratios, ratios[1:]))
    for n, ratio in zip((7, 8), ratios):
        assert cartesian_linearisation(n, 0.999 * ratio * n**3).real.max() > 1e-3
        assert cartesian_linearisation(n, 1.001 * ratio * n**3).real.max() < 1e-7


@pytest.mark.slow
def test_maxwell_large_n_limit():
    """Maxwell (1859): a ring of n >> 1 satellites is stable for M > 0.4352 n**3 m. The exact limit, from mode
    j = n/2 whose 2 x 2 matrix tends to diag(3 - x, 2x) with x = 7 zeta(3) n**3 m / (16 pi**3 M), is
    x_c = (13 - 4 sqrt(10)) / 9, i.e. 63 zeta(3) / (16 pi**3 (13 - 4 sqrt(10))) = 0.4350366; Richardson
    extrapolation of n = 100 and 200 (1/n**2 convergence) lands within 2e-5 of it, and Maxwell's hand value
    within 4e-4."""
    with mp.workdps(30):
        limit = float(63 * mpmath.zeta(3) / (16 * mp.pi**3 * (13 - 4 * mpmath.sqrt(10))))
    r100, r200 = (rings.central_mass_threshold(n) / n**3 for n in (100, 200))
    assert abs((4 * r200 - r100) / 3 - limit) < 2e-5
    assert abs(limit - 0.4352) / 0.4352 < 4e-4


def test_breakup_time_and_stability_inputs():
    assert rings.breakup_time(1.0) == pytest.approx(math.log(1e13), rel=1e-15)
    assert rings.breakup_time(0.0) == np.inf
    with pytest.raises(OrbitDomainError, match="central mass ratio"):
        rings.growth_rate(7, -1.0)
    with pytest.raises(OrbitDomainError, match="O\\(n\\*\\*2\\)"):
        rings.eigenvalues(rings.MAX_STABILITY_COUNT + 1)


def test_shape_deviation_measures_distortion():
    positions, _ = rings.state_vectors(7, 2.0, 1.0, phase=0.4)
    assert rings.shape_deviation(positions, 2.0) < 1e-15
    moved = positions.copy()
    moved[3, 0] += 2e-3
    assert abs(rings.shape_deviation(moved, 2.0) - 1e-3) < 1e-4
