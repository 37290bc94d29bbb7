"""Section XXIII of the notes: n equal masses m on a regular n-gon of radius r, optionally with a central mass M
(Maxwell's ring), turning rigidly about the barycentre.

Each ring body moves as if it circled a point mass GM_eff = G m S_n / 4 + G M at the centre, where
S_n = sum_{k=1}^{n-1} csc(pi k / n) (the notes' csc sum, correct as printed). Every quantity of the notes is
then a circular-orbit formula in GM_eff: omega = sqrt(GM_eff / r**3), v = omega r, U = -n m GM_eff / r
(ring pairs -n G m**2 S_n / (4 r) plus the central mass -n G M m / r), K = -U / 2, E = U / 2, L = n m v r.

Linear stability is dimensionless: time in units of 1/omega, beta = M / m. Perturbations q_k of body k, in its
own radial/tangential frame, split into n Fourier modes q_k = exp(2 pi i j k / n) Q_j; each mode obeys
Q'' = M_j Q + 2 J Q' with a 2 x 2 matrix M_j, so the 4n x 4n rotating-frame linearisation is n blocks of 4 x 4
(Vanderbei & Kolemen 2007, AJ 133, 656). With a central mass the barycentre is held fixed, which couples the
central mass to modes j = +-1 only. Stability thresholds (ring stable iff n >= 7 and beta above beta_c(n),
beta_c / n**3 -> 0.43504 as n -> infinity; Maxwell 1859 found 0.4352, Moeckel 1994 the n >= 7 condition) are
checked in tests/core/test_rings.py against the full Cartesian linearisation and against N-body integrations.
"""

import math

import numpy as np
from numpy.typing import ArrayLike

from orbits.core.errors import OrbitDomainError

#: Growth rates at or below this fraction of the largest |eigenvalue| (at least 1 omega) count as neutral: the
#: round-off level of the eigenvalues near a collision of two frequencies. Since the growth rises as the square
#: root of the distance to a threshold, thresholds are still located to about 1e-12.
NEUTRAL_GROWTH = 1e-9

#: Largest n for the linear-stability analysis, which costs O(n**2) operations and memory per call.
MAX_STABILITY_COUNT = 4096
#: Largest n of a ring: its csc sum takes O(n) time and memory (80 MB at the limit)
MAX_COUNT = 10_000_000

_J = np.array([[0.0, 1.0], [-1.0, 0.0]])
_CHUNK = 1 << 18  # (mode, pair) elements handled at once when building the mode matrices


def check_count(n: int) -> int:
    """n as a Python int; TypeError unless an integer (bool excluded), OrbitDomainError unless 2 <= n <= MAX_COUNT."""
    if isinstance(n, (bool, np.bool_)) or not isinstance(n, (int, np.integer)):
        kind = type(n).__name__
        raise TypeError(f"number of ring bodies n = {n!r} is a {kind}; it must be an integer (int or numpy integer)")
    if n < 2:
        raise OrbitDomainError(f"number of ring bodies n = {int(n)} is outside [2, inf): a ring needs 2 bodies or more")
    if n > MAX_COUNT:
        raise OrbitDomainError(f"number of ring bodies n = {int(n)} is outside [2, {MAX_COUNT}]: the ring's sum over "
                               f"its bodies takes time and memory in proportion to n")
    return int(n)


def _sin_pi(k, n):
    """sin(pi k / n) for integer arrays k, reduced exactly to an argument in [0, pi/2] (relative error ~1 ulp)."""
    k = np.mod(k, 2 * n)
    sign = np.where(k > n, -1.0, 1.0)
    k = np.where(k > n, k - n, k)
    return sign * np.sin(np.pi * (np.minimum(k, n - k) / n))


def _cos_pi(k, n):
    """cos(pi k / n) = sin(pi (n - 2k) / (2n)) for integer arrays k."""
    return _sin_pi(n - 2 * np.asarray(k), 2 * n)


def csc_sum(n: int) -> float:
    """S_n = sum_{k=1}^{n-1} csc(pi k / n) (dimensionless), within 3 ulp for every n.

    Uses csc(pi k / n) = csc(pi (n - k) / n) to sum k < n/2 only (arguments <= pi/2, where sin is accurate
    to 1 ulp), with math.fsum; O(n) time and memory. S_2 = 1, S_3 = 2 / sqrt(3) (XXIII).
    """
    n = check_count(n)
    k = np.arange(1, (n + 1) // 2)
    return 2.0 * math.fsum(1.0 / _sin_pi(k, n)) + (1.0 if n % 2 == 0 else 0.0)


def effective_gm(n: int, gm: ArrayLike, gm_central: ArrayLike = 0.0) -> float | np.ndarray:
    """GM_eff = G m S_n / 4 + G M (m3/s2): the point mass at the centre that keeps each body on its circle."""
    return np.asarray(gm, dtype=float) * (0.25 * csc_sum(n)) + np.asarray(gm_central, dtype=float)


def state_vectors(n: int, r: float, speed: float, phase: float = 0.0) -> tuple[np.ndarray, np.ndarray]:
    """Positions (m) and velocities (m/s) of the n bodies, shape (n, 3): body k at angle phase + 2 pi k / n in
    the xy plane, moving counter-clockwise; the barycentre (and any central mass) rests at the origin."""
    n = check_count(n)
    k = np.arange(n)
    c, s = _cos_pi(2 * k, n), _sin_pi(2 * k, n)
    cp, sp = np.cos(phase), np.sin(phase)
    x, y = c * cp - s * sp, s * cp + c * sp
    zeros = np.zeros(n)
    return r * np.stack([x, y, zeros], axis=-1), speed * np.stack([-y, x, zeros], axis=-1)


def _pair_tensors(n):
    """Tidal tensors T_d = (3 u u^T - I) / (2 sin(pi d / n))**3 (units of G m / r**3) for d = 1..n-1, with
    u = (-sin, cos)(pi d / n) the direction from a body to its d-th neighbour in the body's (radial,
    tangential) frame; also sin and cos of pi d / n."""
    d = np.arange(1, n)
    s, c = _sin_pi(d, n), _cos_pi(d, n)
    t = np.empty((n - 1, 2, 2))
    t[:, 0, 0] = 3.0 * s * s - 1.0
    t[:, 0, 1] = t[:, 1, 0] = -3.0 * s * c
    t[:, 1, 1] = 3.0 * c * c - 1.0
    return t / (8.0 * s**3)[:, None, None], s, c


def _ring_sums(n):
    """sum_d T_d (I - R(2 pi d / n) exp(2 pi i j d / n)) for every mode j, shape (n, 2, 2), cancellation free:
    I - R E has diagonal (1 - E) + 2 sin**2 E and off-diagonal +-2 sin cos E, with 1 - E = 2 sin**2(pi j d / n)
    - i sin(2 pi j d / n) and all angles reduced exactly as integers modulo 2n."""
    tensors, s, c = _pair_tensors(n)
    d = np.arange(1, n)
    sums = np.empty((n, 2, 2), dtype=complex)
    rows = max(1, _CHUNK // n)
    for start in range(0, n, rows):
        m = np.arange(start, min(start + rows, n))[:, None] * d[None, :]
        e = _cos_pi(2 * m, n) + 1j * _sin_pi(2 * m, n)
        diag = (2.0 * _sin_pi(m, n) ** 2 - 1j * _sin_pi(2 * m, n)) + 2.0 * (s * s) * e
        off = 2.0 * (s * c) * e
        factor = np.stack([np.stack([diag, off], axis=-1), np.stack([-off, diag], axis=-1)], axis=-2)
        sums[start : start + m.shape[0]] = np.einsum("dab,jdbc->jac", tensors, factor)
    return sums


def _central_coupling(n):
    """C_j = sum_d R(2 pi d / n) exp(2 pi i j d / n): (n/2)(I - iJ) at j = 1, (n/2)(I + iJ) at j = n - 1 (their
    sum 2I when n = 2, where the two modes coincide), 0 otherwise."""
    coupling = np.zeros((n, 2, 2), dtype=complex)
    coupling[1] += 0.5 * n * (np.eye(2) - 1j * _J)
    coupling[n - 1] += 0.5 * n * (np.eye(2) + 1j * _J)
    return coupling


def mode_matrices(n: int, central_ratio: float = 0.0) -> np.ndarray:
    """First-order 4 x 4 blocks [[0, I], [M_j, 2J]] of the linearised rotating-frame motion, shape (n, 4, 4).

    M_j = I + beta g diag(2, -1) + g sum_d T_d (I - R_d E_jd) + g diag(2, -1) C_j [beta > 0], with
    g = G m / (r**3 omega**2) = 1 / (beta + S_n / 4); the central mass displacement is -(m/M) sum_k xi_k
    (barycentre fixed), which gives the last term. The 1 - beta g of M_j[1, 1] is formed as g S_n / 4, without
    cancellation when M >> m.
    """
    n, beta = _check_stability_inputs(n, central_ratio)
    quarter_sum = 0.25 * csc_sum(n)
    g = 1.0 / (beta + quarter_sum)
    m = g * _ring_sums(n)
    m[:, 0, 0] += 1.0 + 2.0 * beta * g
    m[:, 1, 1] += g * quarter_sum
    if beta > 0.0:
        m += g * np.diag([2.0, -1.0]) @ _central_coupling(n)
    blocks = np.zeros((n, 4, 4), dtype=complex)
    blocks[:, 0, 2] = blocks[:, 1, 3] = 1.0
    blocks[:, 2:, :2] = m
    blocks[:, 2:, 2:] = 2.0 * _J
    return blocks


def _check_stability_inputs(n, central_ratio):
    n = check_count(n)
    if n > MAX_STABILITY_COUNT:
        raise OrbitDomainError(
            f"number of ring bodies n = {n} is outside [2, {MAX_STABILITY_COUNT}] for the linear-stability analysis, "
            f"which costs O(n**2); the ring's other quantities go up to n = {MAX_COUNT}"
        )
    beta = float(central_ratio)
    if not (np.isfinite(beta) and beta >= 0.0):
        raise OrbitDomainError(f"central mass ratio M / m = {beta!r} is outside [0, inf)")
    return n, beta


def _trivial_modes(n, beta):
    """{mode j: exactly known eigenvalues}: rotation and homothety (0, 0) plus the Kepler epicycle (+-i) in mode 0
    (all forces scale as 1 / r**2); without a central mass, the barycentre's free drift (+i double in mode 1,
    -i double in mode n - 1; both in mode 1 when n = 2). Their computed double roots are only good to 1e-8."""
    known = {0: [0j, 0j, 1j, -1j]}
    if beta == 0.0:
        if n == 2:
            known[1] = [1j, 1j, -1j, -1j]
        else:
            known[1], known[n - 1] = [1j, 1j], [-1j, -1j]
    return known


def _snap(values, exact):
    """values with, for each exact value in turn, the nearest not yet replaced entry set to it."""
    values = values.copy()
    free = np.ones(values.shape, dtype=bool)
    for target in exact:
        k = int(np.argmin(np.where(free, np.abs(values - target), np.inf)))
        values[k], free[k] = target, False
    return values


def eigenvalues(n: int, central_ratio: float = 0.0) -> np.ndarray:
    """Eigenvalues lambda (units of omega) of the 4n x 4n linearisation, shape (n, 4): row j holds Fourier mode j.

    Exactly known modes (see _trivial_modes) are set exactly; the others are within ~1e-12 of the Cartesian
    linearisation (tests/core/test_rings.py). With a central mass the barycentre is held fixed.
    """
    n, beta = _check_stability_inputs(n, central_ratio)
    values = np.linalg.eigvals(mode_matrices(n, beta))
    for j, exact in _trivial_modes(n, beta).items():
        values[j] = _snap(values[j], exact)
    return values


def growth_rate(n: int, central_ratio: float = 0.0) -> tuple[float, int | None]:
    """(sigma, j): the largest Re(lambda) (units of omega) and its Fourier mode j; (0.0, None) when every
    mode is neutral (|Re lambda| <= NEUTRAL_GROWTH times max(1, |lambda|)), i.e. linearly stable."""
    values = eigenvalues(n, central_ratio)
    rates = values.real.max(axis=1)
    j = int(np.argmax(rates))
    if rates[j] <= NEUTRAL_GROWTH * max(1.0, float(np.abs(values).max())):
        return 0.0, None
    return float(rates[j]), j


def central_mass_threshold(n: int) -> float:
    """beta_c = (M / m)_c (dimensionless): the ring is linearly stable iff M / m >= beta_c; n >= 7 only.

    Bisection (in log beta, to 1e-13 relative) between 0.1 n**3 (unstable) and n**3 (stable); beta_c / n**3
    rises from 0.4077 at n = 7 to 0.43504 = 63 zeta(3) / (16 pi**3 (13 - 4 sqrt(10))) as n -> infinity
    (mode j = n/2; tests/core/test_rings.py). n <= 6 raises OrbitDomainError: those rings are never stable.
    """
    n = check_count(n)
    if n <= 6:
        raise OrbitDomainError(
            f"number of ring bodies n = {n} is outside [7, {MAX_STABILITY_COUNT}]: rings of 2 to 6 bodies are linearly "
            "unstable for every central mass (Moeckel 1994), so there is no threshold"
        )
    lo, hi = 0.1 * n**3, 1.0 * n**3
    if growth_rate(n, lo)[0] == 0.0 or growth_rate(n, hi)[0] > 0.0:
        raise OrbitDomainError(f"ring of n = {n}: the stability threshold is not bracketed by [0.1, 1] n**3")
    while hi - lo > 1e-13 * hi:
        mid = math.sqrt(lo * hi)
        lo, hi = (mid, hi) if growth_rate(n, mid)[0] > 0.0 else (lo, mid)
    return hi


def breakup_time(rate: ArrayLike, seed: float = 1e-16, breakup: float = 1e-3) -> np.ndarray:
    """t = ln(breakup / seed) / rate (units of 1/rate): time for a relative perturbation `seed` (float64 round-off
    by default) to grow to `breakup` at the exponential rate `rate`; inf when rate is 0 (linearly stable)."""
    rate = np.asarray(rate, dtype=float)
    with np.errstate(divide="ignore"):
        return np.where(rate > 0.0, math.log(breakup / seed) / rate, np.inf)


def shape_deviation(positions: ArrayLike, r: float) -> float | np.ndarray:
    """max_{k<l} | |x_k - x_l| - 2 r sin(pi |k - l| / n) | / r over the ring bodies' positions (..., n, 3):
    how far the bodies are from a regular n-gon of radius r (rotation and drift of the whole ring ignored)."""
    positions = np.asarray(positions, dtype=float)
    n = positions.shape[-2]
    first, second = np.triu_indices(n, 1)
    chords = np.linalg.norm(positions[..., first, :] - positions[..., second, :], axis=-1)
    ideal = 2.0 * r * _sin_pi(second - first, n)
    return np.max(np.abs(chords - ideal), axis=-1) / r
