"""The Friedmann models around section XXIV of the notes (the expanding universe).

Float64 arrays in SI units (t in s, r in m, gm = G M in m**3/s**2, H in 1/s) that broadcast.

Friedmann: E(z) = H(z) / H0 = sqrt(Omega_r x**4 + Omega_m x**3 + Omega_k x**2 + Omega_Lambda), x = 1 + z.
Friedmann picks its method once, at construction: a closed form when one exists (a single component,
among them Einstein-de Sitter and de Sitter, and flat matter + Lambda), tanh-sinh quadrature otherwise.
With the scale factor a = 1 / x and P(a) = a**4 E**2 = Omega_r + Omega_m a + Omega_k a**2 + Omega_Lambda a**4,
    age         t(a) = t_H int_0^a a' da' / sqrt(P(a')),
    lookback    t0 - t(a),
    comoving    D_C = d_H int_a^1 da' / sqrt(P(a')),
where t_H = 1 / H0 (s) and d_H = c / H0 (m) are passed in as `hubble_time` and `hubble_distance`. From D_C follow
the transverse comoving distance D_M (sin or sinh of D_C / R in a curved universe, R = d_H / sqrt|Omega_k|) and
the comoving volume. A universe that stops expanding at a_max recollapses symmetrically: a(t) = a(t_crunch - t)
after the turnaround, and the big crunch comes at t_crunch = 2 t(a_max).

Accuracy (tests/core/test_cosmology.py, against mpmath): Einstein-de Sitter age, lookback time and comoving
distance within 4 ulp for every z from 1e-300 to 1e300 and inf (measured worst 1.57 ulp); below the smallest
normal z, 2.2e-308, the lookback time and distance lose the bits the subnormal z lacks (27 ulp at 1e-309); the
other closed forms within 4 ulp or 4e-16; quadrature within 2e-15 relative (measured 4e-16).
"""

import functools
import math
from dataclasses import dataclass, field

import numpy as np
from numpy.typing import ArrayLike

from orbits.core._dd import cbrt, two_product, two_sum
from orbits.core._roots import newton_in_bracket
from orbits.core.checks import check_finite
from orbits.core.cosmology.quadrature import tanh_sinh
from orbits.core.errors import OrbitDomainError

#: Exponent k of E = x**k for each single-component universe (x = 1 + z).
SINGLE_COMPONENT = {"radiation_only": 2.0, "matter_only": 1.5, "curvature_only": 1.0, "lambda_only": 0.0}
METHODS = (*SINGLE_COMPONENT, "flat_matter_lambda", "quadrature")
_FIELDS = ("omega_r", "omega_m", "omega_k", "omega_l")
_NAMES = {"omega_m": "Omega_m", "omega_r": "Omega_r", "omega_k": "Omega_k", "omega_l": "Omega_Lambda"}
_SUM_TOLERANCE = 1e-12  # |Omega_m + Omega_r + Omega_k + Omega_Lambda - 1| allowed (typed decimals)
_LOG_MAX = math.log(np.finfo(float).max)  # y = ln a beyond which a overflows
_LOG_TINY = math.log(5e-324)  # y = ln a below which a underflows to 0
_CRUNCH_ULPS = 4  # t within this many ulp of the big crunch (the rounding of t_crunch = t_crunch H0 / H0) is it


@dataclass(frozen=True, eq=False)
class Friedmann:
    """A Friedmann universe: density parameters today (dimensionless, summing to 1) and its chosen method.

    Omega_m, Omega_r and Omega_Lambda must be >= 0; Omega_k (curvature) may have either sign. The model must
    expand from a big bang (H**2 > 0 for every a in (0, 1]). `method` is chosen here, once: a single
    component (EdS is "matter_only", de Sitter "lambda_only"), "flat_matter_lambda", or "quadrature".
    `max_scale_factor` is the turnaround a of a universe that recollapses (inf otherwise).
    """

    omega_m: float
    omega_r: float = 0.0
    omega_k: float = 0.0
    omega_l: float = 0.0
    method: str = field(init=False)
    max_scale_factor: float = field(init=False)

    def __post_init__(self):
        values = {name: float(getattr(self, name)) for name in _FIELDS}
        _check_densities(values)
        for name, value in values.items():
            object.__setattr__(self, name, value)
        object.__setattr__(self, "method", _choose_method(**values))
        _check_big_bang(**values)
        object.__setattr__(self, "max_scale_factor", _turnaround_scale_factor(**values))

    # ---- the polynomial P(a) = a**4 E(a)**2 and its relatives -------------------------------------------
    @functools.cached_property
    def _leading_power(self):
        """m = 0, 1 or 2: the power of a that P(a) starts with (Omega_r, Omega_m or Omega_k is its first term)."""
        return 0 if self.omega_r > 0 else (1 if self.omega_m > 0 else 2)

    def _p_reduced(self, a):
        """P(a) / a**m for a <= 1, positive at a = 0 (so tiny a neither underflows nor divides by zero)."""
        coefficients = (self.omega_r, self.omega_m, self.omega_k, 0.0, self.omega_l)[self._leading_power :]
        value = np.zeros_like(a)
        for c in reversed(coefficients):
            value = value * a + c
        return value

    def _power_over_sqrt_p(self, a, power):
        """a**power / sqrt(P(a)) for 0 <= a <= 1, as a**(power - m/2) / sqrt(P(a) / a**m)."""
        return a ** (power - 0.5 * self._leading_power) / np.sqrt(self._p_reduced(a))

    def _e2_at_inverse(self, b):
        """E**2 at a = 1 / b: Omega_Lambda + Omega_k b**2 + Omega_m b**3 + Omega_r b**4, for b <= 1."""
        return self.omega_l + b * b * (self.omega_k + b * (self.omega_m + b * self.omega_r))

    @functools.cached_property
    def _deflated(self):
        """Coefficients (highest first) of D(a) = P(a) / (a_max - a), a cubic positive on [1, a_max)."""
        r3 = self.omega_l
        r2 = self.max_scale_factor * r3
        r1 = self.omega_k + self.max_scale_factor * r2
        r0 = self.omega_m + self.max_scale_factor * r1
        return -r3, -r2, -r1, -r0

    def _inverse_e_future(self, y, gap):
        """1 / E at a = e**y >= 1; gap = ln a_max - y, exact near the turnaround, gives P = (a_max - a) D(a)."""
        a = np.exp(y)
        if math.isinf(self.max_scale_factor):
            return 1.0 / np.sqrt(self._e2_at_inverse(1.0 / a))
        d3, d2, d1, d0 = self._deflated
        distance = -self.max_scale_factor * np.expm1(-gap)
        with np.errstate(divide="ignore"):
            return a * a / np.sqrt(distance * (((d3 * a + d2) * a + d1) * a + d0))

    def _log_slope(self, y, age):
        """d ln t / d ln a = 1 / (E t) at a = e**y, given t(a) H0 = age; written so that tiny a does not underflow."""
        a = np.exp(np.minimum(y, 0.0))
        top = math.log(self.max_scale_factor) if math.isfinite(self.max_scale_factor) else math.inf
        with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
            past = (a / age) * self._power_over_sqrt_p(a, 1.0)
            future = self._inverse_e_future(np.maximum(y, 0.0), top - np.maximum(y, 0.0)) / age
        return np.where(y > 0, future, past)

    # ---- public quantities ------------------------------------------------------------------------------
    def efunc(self, z: ArrayLike) -> np.ndarray:
        """E(z) = H(z) / H0 (dimensionless): x**(2 - m/2) sqrt(P(a) / a**m) for x = 1 + z >= 1; inf beyond float64."""
        z = self._redshift(z)
        k = SINGLE_COMPONENT.get(self.method)
        if k is not None:
            return _power_of_one_plus(z, k)
        a, b = _scale_factor_and_inverse(z)
        with np.errstate(over="ignore"):
            past = b ** (2.0 - 0.5 * self._leading_power) * np.sqrt(self._p_reduced(a))
        future = np.sqrt(np.maximum(self._e2_at_inverse(np.minimum(b, 1.0)), 0.0))  # 0 at a turnaround, not -0.0
        return np.where(np.isinf(z), np.inf, np.where(z >= 0, past, future))

    def efunc_at_scale_factor(self, a: ArrayLike) -> np.ndarray:
        """E = H / H0 (dimensionless) at scale factor a > 0: efunc(1 / a - 1) for a <= 1, and for a > 1 from 1 / a
        itself, never through z = 1 / a - 1, which rounds to -1 from a = 2**53 on (E**2 = P(a) / a**4 either way)."""
        a = np.asarray(a, dtype=float)
        with np.errstate(divide="ignore"):
            inverse = 1.0 / a
        past = self.efunc(np.where(a <= 1.0, inverse - 1.0, 0.0))
        future = np.sqrt(np.maximum(self._e2_at_inverse(np.minimum(inverse, 1.0)), 0.0))
        return np.where(a <= 1.0, past, future)

    def matter_density_parameter(self, z: ArrayLike) -> np.ndarray:
        """Omega_m(z) = Omega_m x**3 / E(z)**2 = Omega_m a / P(a) (dimensionless); 1 for Einstein-de Sitter."""
        z = self._redshift(z)
        if self.method == "matter_only":
            return np.ones(z.shape)
        a, b = _scale_factor_and_inverse(z)
        past = self.omega_m * a ** (1 - self._leading_power) / self._p_reduced(a) if self.omega_m > 0 else 0.0
        future = np.minimum(b, 1.0)  # the branch np.where discards must not overflow either (b = 1 + z > 1e103)
        return np.where(z >= 0, past, self.omega_m * future**3 / self._e2_at_inverse(future))

    def age(self, z: ArrayLike, hubble_time: float) -> float | np.ndarray:
        """t(z) (s): time from the big bang to redshift z, for t_H = 1 / H0 = hubble_time (s).

        Einstein-de Sitter: t = (2/3) t_H (1 + z)**-1.5, within 4 ulp for every z >= 0, inf included
        (tests/core/test_cosmology.py). de Sitter has no big bang: inf. z = inf gives 0.
        """
        z = self._redshift(z)
        k = SINGLE_COMPONENT.get(self.method)
        if k is not None:
            return _power_age(z, k, hubble_time)
        if self.method == "flat_matter_lambda":
            return _flat_age(z, self.omega_m, self.omega_l, hubble_time)
        return hubble_time * self._quadrature_age(z)

    def lookback_time(self, z: ArrayLike, hubble_time: float) -> float | np.ndarray:
        """t0 - t(z) (s), for t_H = hubble_time (s); negative in the future (-1 < z < 0).

        Einstein-de Sitter: (2/3) t_H (-expm1(-1.5 log1p z)), within 4 ulp for every z >= 0.
        """
        z = self._redshift(z)
        k = SINGLE_COMPONENT.get(self.method)
        if k is not None:
            return _power_lookback(z, k, hubble_time)
        if self.method == "flat_matter_lambda":
            return _flat_lookback(z, self.omega_m, self.omega_l, hubble_time)
        return hubble_time * self._quadrature_lookback(z)

    def comoving_distance(self, z: ArrayLike, hubble_distance: float) -> float | np.ndarray:
        """Line-of-sight comoving distance D_C = d_H int_0^z dz' / E(z') (m), for d_H = c / H0 = hubble_distance.

        Einstein-de Sitter: D_C = 2 d_H (-expm1(-log1p(z) / 2)), within 4 ulp for every z >= 0; z = inf
        gives 2 d_H. inf where the integral diverges (no matter or radiation, z = inf).
        """
        z = self._redshift(z)
        k = SINGLE_COMPONENT.get(self.method)
        if k is not None:
            return _power_comoving(z, k, hubble_distance)
        return hubble_distance * self._quadrature_comoving(z)

    def transverse_comoving_distance(self, z: ArrayLike, hubble_distance: float) -> float | np.ndarray:
        """D_M (m): D_C if flat; R sinh(D_C / R) if open, R sin(D_C / R) if closed, R = d_H / sqrt(|Omega_k|).

        The angular size of a proper length l at z is l (1 + z) / D_M (Hogg 1999, astro-ph/9905116, eq. 16).
        Accuracy: that of D_C and one sin or sinh, within 2e-15 (tests/core/test_cosmology.py, mpmath).
        """
        chi = self.comoving_distance(z, hubble_distance)
        if self.omega_k == 0:
            return chi
        radius = hubble_distance / math.sqrt(abs(self.omega_k))
        with np.errstate(over="ignore"):
            return radius * (np.sinh(chi / radius) if self.omega_k > 0 else np.sin(chi / radius))

    def comoving_volume(self, z: ArrayLike, hubble_distance: float) -> float | np.ndarray:
        """V_C (m**3) inside redshift z over the whole sky: 4 pi D_C**3 / 3 if flat, else pi R**3 (sinh y - y) (open)
        or pi R**3 (y - sin y) (closed) with y = 2 D_C / R, R = d_H / sqrt(|Omega_k|).

        Written in D_C (not in D_M as in Hogg 1999, eq. 29) so that a closed universe's volume keeps growing past
        its equator (D_C > pi R / 2) up to the whole 3-sphere, 2 pi**2 R**3. Within 1e-14 of mpmath.
        """
        chi = self.comoving_distance(z, hubble_distance)
        with np.errstate(over="ignore"):
            if self.omega_k == 0:
                return (4.0 * math.pi / 3.0) * chi**3
            radius = hubble_distance / math.sqrt(abs(self.omega_k))
            return math.pi * radius**3 * _sine_excess(2.0 * chi / radius, self.omega_k > 0)

    def scale_factor(self, t: ArrayLike, hubble_time: float) -> float | np.ndarray:
        """a(t) (dimensionless) at t (s) after the big bang, for t_H = hubble_time (s); inf beyond float64.

        Closed forms: a = (k t / t_H)**(1/k) for E = x**k (EdS: (1.5 t / t_H)**(2/3)); flat matter + Lambda:
        a = (Omega_m / Omega_Lambda)**(1/3) sinh(1.5 sqrt(Omega_Lambda) t / t_H)**(2/3). Otherwise the age
        integral is inverted by Newton's method in ln a inside a bracket. A universe that recollapses does so
        symmetrically (H**2 depends on a alone): a(t) = a(t_crunch - t) after the turnaround, and 0 at the
        big crunch t_crunch = 2 t_turnaround.
        """
        tau = self._cosmic_time(t, hubble_time)
        k = SINGLE_COMPONENT.get(self.method)
        with np.errstate(over="ignore"):
            if k is not None:
                return _power_scale_factor(tau, k)
            if self.method == "flat_matter_lambda":
                return _flat_scale_factor(tau, self.omega_m, self.omega_l)
        return self._quadrature_scale_factor(tau)

    @functools.cached_property
    def present_age(self) -> float:
        """t0 H0 (dimensionless): the age today in Hubble times; inf for de Sitter."""
        if self.method == "quadrature":
            return float(self._from_big_bang(1, np.ones(1))[0])
        return float(self.age(0.0, 1.0))

    @functools.cached_property
    def turnaround_age(self) -> float:
        """t H0 (dimensionless) at the turnaround a = max_scale_factor; inf if the universe never recollapses."""
        if math.isinf(self.max_scale_factor):
            return math.inf
        if self.omega_r == 0 and self.omega_l == 0:  # matter and curvature: the cycloid's eta = pi, in closed form
            return 0.5 * math.pi * self.omega_m / (-self.omega_k) ** 1.5
        top = np.array([math.log(self.max_scale_factor)])
        return self.present_age + float(tanh_sinh(lambda y, d, hi: self._inverse_e_future(y, d), np.zeros(1), top)[0])

    @functools.cached_property
    def crunch_age(self) -> float:
        """t H0 (dimensionless) of the big crunch, 2 turnaround_age (the collapse mirrors the expansion); inf if the
        universe never recollapses. Omega_m > 1 alone with curvature: pi Omega_m / (-Omega_k)**1.5, in closed form
        (within 1.7e-16 for Omega_m from 1 + 1e-4 to 1e6, tests/core/test_cosmology.py)."""
        return 2.0 * self.turnaround_age

    # ---- domain checks ----------------------------------------------------------------------------------
    def _redshift(self, z):
        """z as a float array; OrbitDomainError for NaN, z <= -1, or z beyond a recollapsing universe's turnaround."""
        z = np.asarray(z, dtype=float)
        if np.any(np.isnan(z)):
            raise OrbitDomainError("redshift z = nan is not a number; allowed (-1, inf] (dimensionless)")
        if np.any(z <= -1.0):
            value = float(z[z <= -1.0].flat[0])
            why = "a = 1 / (1 + z) would be infinite" if value == -1.0 else "a = 1 / (1 + z) would be negative"
            raise OrbitDomainError(f"redshift z = {value!r} is outside (-1, inf] (dimensionless): {why}")
        z_min = 1.0 / self.max_scale_factor - 1.0
        if np.any(z < z_min):
            value = float(z[z < z_min].flat[0])
            raise OrbitDomainError(
                f"redshift z = {value!r} is outside [{z_min!r}, inf] (dimensionless): this universe stops "
                f"expanding at a = {self.max_scale_factor!r} and recollapses"
            )
        return z

    def _cosmic_time(self, t, hubble_time):
        """t / t_H as a float array; OrbitDomainError for NaN, t < 0, no big bang, or t after the big crunch."""
        t = np.asarray(t, dtype=float)
        if np.any(np.isnan(t)) or np.any(t < 0):
            value = float(t[np.isnan(t) | (t < 0)].flat[0])
            raise OrbitDomainError(
                f"time since the big bang t = {value!r} s is outside [0, inf) s (negative t is before the big bang)"
            )
        if self.method == "lambda_only":
            raise OrbitDomainError(
                "a de Sitter universe (Omega_Lambda = 1) has no big bang, so a(t) with t measured from it is "
                "undefined; give a model with matter, radiation or curvature"
            )
        tau = t / hubble_time
        # the crunch time given in seconds comes back within a few ulp of crunch_age: it is the crunch (a = 0)
        if math.isfinite(self.crunch_age):
            near = np.abs(tau - self.crunch_age) <= _CRUNCH_ULPS * np.spacing(self.crunch_age)
            tau = np.where(near, self.crunch_age, tau)
        if np.any(tau > self.crunch_age):
            value = float(t[tau > self.crunch_age].flat[0])
            raise OrbitDomainError(
                f"time since the big bang t = {value!r} s is outside [0, {self.crunch_age * hubble_time!r}] s: "
                f"this universe stops expanding at a = {self.max_scale_factor!r} and recollapses to a big crunch"
            )
        return tau

    # ---- quadrature -------------------------------------------------------------------------------------
    def _from_big_bang(self, j, a_hi):
        """int_0^a_hi a**j da / sqrt(P(a)) for 0 < a_hi <= 1 (1-D): j = 1 is t H0, j = 0 is D_C / d_H from z = inf.

        Nodes that underflow to a = 0 contribute nothing (the integrand is integrable there).
        """

        def integrand(a, d, hi):
            with np.errstate(divide="ignore", invalid="ignore"):
                return np.where(a > 0, self._power_over_sqrt_p(a, j), 0.0)

        return tanh_sinh(integrand, np.zeros_like(a_hi), a_hi)

    def _past(self, j, y_lo):
        """int_{y_lo}^0 a**(j+1) dy / sqrt(P(a)), a = e**y, for finite y_lo < 0 (1-D)."""

        def integrand(y, d, hi):
            a = np.exp(y)
            return self._power_over_sqrt_p(a, j + 1)

        return tanh_sinh(integrand, y_lo, np.zeros_like(y_lo))

    def _future(self, j, y_hi):
        """int_0^{y_hi} a**(j-1) dy / E(a), a = e**y, for 0 < y_hi <= ln a_max (1-D)."""
        top = math.log(self.max_scale_factor) if math.isfinite(self.max_scale_factor) else math.inf

        def integrand(y, d, hi):
            return np.exp((j - 1) * y) * self._inverse_e_future(y, (top - hi) + d)

        return tanh_sinh(integrand, np.zeros_like(y_hi), y_hi)

    def _quadrature_age(self, z):
        """t(z) H0 by quadrature, any valid z."""
        z = np.asarray(z, dtype=float)
        out = np.zeros(z.shape)
        past = (z >= 0) & np.isfinite(z)
        out[past] = self._from_big_bang(1, 1.0 / (1.0 + z[past]))
        future = z < 0
        out[future] = self.present_age + self._future(1, -np.log1p(z[future]))
        return out

    def _quadrature_lookback(self, z):
        """(t0 - t(z)) H0 by quadrature, any valid z."""
        z = np.asarray(z, dtype=float)
        out = np.zeros(z.shape)
        past = (z > 0) & np.isfinite(z)
        out[past] = self._past(1, -np.log1p(z[past]))
        out[np.isinf(z)] = self.present_age
        future = z < 0
        out[future] = -self._future(1, -np.log1p(z[future]))
        return out

    def _quadrature_comoving(self, z):
        """D_C / d_H by quadrature, any valid z."""
        z = np.asarray(z, dtype=float)
        out = np.zeros(z.shape)
        past = (z > 0) & np.isfinite(z)
        out[past] = self._past(0, -np.log1p(z[past]))
        if np.any(np.isinf(z)):
            diverges = self.omega_m == 0 and self.omega_r == 0
            out[np.isinf(z)] = np.inf if diverges else self._from_big_bang(0, np.ones(1))[0]
        future = z < 0
        out[future] = -self._future(0, -np.log1p(z[future]))
        return out

    def _age_at_log_scale_factor(self, y):
        """t(a) H0 at a = e**y for finite y <= ln a_max (1-D)."""
        out = np.empty(y.shape)
        past = y <= 0
        out[past] = self._from_big_bang(1, np.exp(y[past]))
        out[~past] = self.present_age + self._future(1, y[~past])
        return out

    def _quadrature_scale_factor(self, tau):
        """a with t(a) H0 = tau: Newton's method on ln t(e**y) = ln tau in y = ln a, inside a bracket.

        0 at tau = 0 and at the big crunch; inf where a exceeds float64. After the turnaround, tau is mirrored
        to crunch_age - tau (exact there, by Sterbenz's lemma).
        """
        tau = np.asarray(tau, dtype=float)
        tau = np.where(tau > self.turnaround_age, self.crunch_age - tau, tau)
        out = np.zeros(tau.shape)
        out[np.isinf(tau)] = np.inf
        solve = (tau > 0) & np.isfinite(tau)
        if np.any(solve):
            out[solve] = self._solve_scale_factor(tau[solve])
        return out

    def _solve_scale_factor(self, tau):
        """a for finite tau > 0 (1-D); 0 where a underflows, inf where it overflows float64."""
        lo, hi = self._bracket(tau)
        # no bracket above: a overflows float64, or, in a universe that recollapses, tau sits within rounding of the
        # turnaround (the closed form's, when the quadrature's own t(a_max) falls an ulp short of it): a = a_max
        top = self.max_scale_factor if math.isfinite(self.max_scale_factor) else np.inf
        out = np.where(np.isinf(hi), top, 0.0)
        rows = np.flatnonzero(np.isfinite(lo) & np.isfinite(hi))
        target = tau[rows]
        start = np.clip(np.log(target / self.present_age) / 1.5, lo[rows], hi[rows])

        def residual(y, i):  # ln(t(e**y) / tau), nearly linear in y since t ~ a**k early on
            age = self._age_at_log_scale_factor(y)
            with np.errstate(divide="ignore"):
                return np.log(age / target[i]), self._log_slope(y, age)

        y = newton_in_bracket(start, lo[rows], hi[rows], residual)
        # ln a carries only |y| ulp(1) of a's precision: a last Newton step is applied to a itself.
        f, slope = residual(y, np.arange(y.size))
        with np.errstate(all="ignore"):
            step = f / slope
        out[rows] = np.exp(y) * np.where(np.isfinite(step), 1.0 - step, 1.0)
        return out

    def _bracket(self, tau):
        """(lo, hi) in y = ln a with t(e**lo) <= tau <= t(e**hi); lo = -inf if a underflows, hi = inf if it overflows.

        Past (tau <= t0): hi = 0, lo found stepping down from the matter-era guess. Future: lo = 0 and
        t(a) - t0 >= ln(a) / E_max with E_max**2 = sum of the positive Omegas bounds hi.
        """
        lo, hi = np.zeros(tau.shape), np.zeros(tau.shape)
        past = tau <= self.present_age
        lo[past] = self._lower_bracket(tau[past])
        e_max = math.sqrt(self.omega_r + self.omega_m + max(self.omega_k, 0.0) + self.omega_l)
        cap = math.log(self.max_scale_factor) if math.isfinite(self.max_scale_factor) else _LOG_MAX
        hi[~past] = np.minimum(e_max * (tau[~past] - self.present_age), cap)
        at_cap = np.flatnonzero(~past & (hi == cap))
        if at_cap.size:
            hi[at_cap[self._age_at_log_scale_factor(hi[at_cap]) < tau[at_cap]]] = np.inf
        return lo, hi

    def _lower_bracket(self, tau):
        """y with t(e**y) <= tau, stepping down by doubling from (2/3) ln(tau / t0); -inf if a underflows."""
        y = np.minimum(np.log(tau / self.present_age) / 1.5, 0.0)
        step = np.ones(y.shape)
        pending = np.ones(y.shape, dtype=bool)
        while np.any(pending):
            rows = np.flatnonzero(pending)
            too_late = self._age_at_log_scale_factor(y[rows]) > tau[rows]
            pending[rows[~too_late]] = False
            rows = rows[too_late]
            y[rows] -= step[rows]
            step[rows] *= 2.0
            floor = y[rows] < _LOG_TINY
            y[rows[floor]] = -np.inf
            pending[rows[floor]] = False
        return y


# ---- construction checks -------------------------------------------------------------------------------


def _check_densities(values):
    """Raise OrbitDomainError for non-finite or negative densities, or a sum that is not 1."""
    for name, value in values.items():
        check_finite(value, f"density parameter {_NAMES[name]}", "(dimensionless)")
        if name != "omega_k" and value < 0:
            raise OrbitDomainError(
                f"density parameter {_NAMES[name]} = {value!r} is outside [0, inf) (dimensionless): "
                "densities cannot be negative (only the curvature term Omega_k can)"
            )
    total = math.fsum(values.values())
    if abs(total - 1.0) > _SUM_TOLERANCE:
        raise OrbitDomainError(
            f"density parameters sum to {total!r}, not 1 (within {_SUM_TOLERANCE:g}): Friedmann's equation at z = 0 "
            "needs Omega_m + Omega_r + Omega_k + Omega_Lambda = 1; leave Omega_k out to derive it"
        )


def _choose_method(omega_r, omega_m, omega_k, omega_l):
    """The cheapest exact method for these densities (see METHODS)."""
    nonzero = [name for name, value in zip(SINGLE_COMPONENT, (omega_r, omega_m, omega_k, omega_l)) if value != 0]
    if len(nonzero) == 1:
        return nonzero[0]
    if omega_r == 0 and omega_k == 0 and omega_m > 0 and omega_l > 0:
        return "flat_matter_lambda"
    return "quadrature"


def _p_coefficients(omega_r, omega_m, omega_k, omega_l):
    """P(a) coefficients, highest power first."""
    return [omega_l, 0.0, omega_k, omega_m, omega_r]


def _sign_of_p(coefficients, a):
    """The sign of P(a), > 0 or not; for a > 1 through E**2 = P(a) / a**4, which cannot overflow."""
    if a <= 1:
        return np.polyval(coefficients, a) > 0
    return np.polyval(coefficients[::-1], 1.0 / a) > 0


def _positive_critical_points(omega_r, omega_m, omega_k, omega_l):
    """Sorted a > 0 where P'(a) = 4 Omega_Lambda a**3 + 2 Omega_k a + Omega_m = 0, in closed form.

    Positive roots need Omega_k < 0. With Omega_Lambda > 0 the depressed cubic a**3 + p a + q = 0 (p < 0,
    q >= 0) has them as 2 m cos(theta / 3) and, by Vieta, -q / (a0 a2), where m = sqrt(-p / 3) and
    cos(theta) = -q / (2 m**3), evaluated as ratios of square roots so that extreme densities (a subnormal
    Omega_Lambda, say) overflow only to roots that are dropped.
    """
    if omega_k >= 0:
        return []
    if omega_l == 0:
        return [omega_m / (-2.0 * omega_k)] if omega_m > 0 else []
    with np.errstate(all="ignore"):
        k6, ol = np.float64(-omega_k / 6.0), np.float64(omega_l)
        m = np.sqrt(k6) / np.sqrt(ol)
        cosine = -(omega_m / 8.0) * (np.sqrt(ol) / np.sqrt(k6)) / k6
        if not cosine >= -1.0:
            return []
        third = np.arccos(cosine) / 3.0
        largest, negative = 2.0 * m * np.cos(third), 2.0 * m * np.cos(third - 4.0 * np.pi / 3.0)
        middle = -(omega_m / 4.0) / ol / (largest * negative)
    return sorted(float(a) for a in (largest, middle) if np.isfinite(a) and a > 0)


def _check_big_bang(omega_r, omega_m, omega_k, omega_l):
    """Raise OrbitDomainError unless P(a) > 0 on (0, 1]: the universe expanded from a = 0 (no bounce)."""
    if omega_r == 0 and omega_m == 0 and omega_k < 0:
        raise OrbitDomainError(
            f"with Omega_m = Omega_r = 0 and Omega_k = {omega_k!r} < 0 the universe bounces and has no big bang; "
            "orbits needs H**2 > 0 for every scale factor a in (0, 1]"
        )
    coefficients = _p_coefficients(omega_r, omega_m, omega_k, omega_l)
    for a in _positive_critical_points(omega_r, omega_m, omega_k, omega_l):
        if a < 1 and not _sign_of_p(coefficients, a):
            raise OrbitDomainError(
                f"H**2 <= 0 at scale factor a = {float(a)!r} (z = {float(1 / a - 1)!r}): with these densities "
                "(Omega_m, Omega_r, Omega_k, Omega_Lambda) = "
                f"({omega_m!r}, {omega_r!r}, {omega_k!r}, {omega_l!r}) the universe bounces and has no big bang; "
                "orbits needs H**2 > 0 for every a in (0, 1]"
            )


def _turnaround_scale_factor(omega_r, omega_m, omega_k, omega_l):
    """Smallest a > 1 with P(a) = 0 (the universe stops expanding and recollapses), or inf."""
    if omega_l == 0:
        if omega_k >= 0:
            return math.inf
        # Or + Om a + Ok a**2 = 0: the positive root, written without cancellation.
        return (omega_m + math.sqrt(omega_m * omega_m - 4.0 * omega_k * omega_r)) / (-2.0 * omega_k)
    coefficients = _p_coefficients(omega_r, omega_m, omega_k, omega_l)
    start = 1.0
    for a in _positive_critical_points(omega_r, omega_m, omega_k, omega_l):
        if a > 1 and not _sign_of_p(coefficients, a):
            return _decreasing_root(coefficients, start, float(a))
        start = max(start, float(a))
    return math.inf


def _decreasing_root(coefficients, lo, hi):
    """Root of P in [lo, hi] (1 <= lo), where P falls from > 0 to <= 0: bisection, geometric while hi > 2 lo."""
    for _ in range(2200):
        mid = math.sqrt(lo * hi) if hi > 2.0 * lo else 0.5 * (lo + hi)
        if mid in (lo, hi):
            break
        if _sign_of_p(coefficients, mid):
            lo = mid
        else:
            hi = mid
    return hi


# ---- single-component closed forms (E = x**k) ----------------------------------------------------------


def _scale_factor_and_inverse(z):
    """(a, x): a = 1 / (1 + z) for z >= 0 (0 at z = inf) and 1 for z < 0; x = 1 + z (1 at z = inf)."""
    x = 1.0 + z
    a = np.where(x >= 1.0, 1.0 / np.where(x >= 1.0, x, 1.0), 1.0)
    return a, np.where(np.isinf(x), 1.0, x)


def _one_plus(z):
    """x = 1 + z as an exact double-double (hi, lo); z = inf gives (inf, 0)."""
    finite = np.isfinite(z)
    hi, lo = two_sum(1.0, np.where(finite, z, 0.0))
    return np.where(finite, hi, np.inf), np.where(finite, lo, 0.0)


def _power_of_one_plus(z, k):
    """(1 + z)**k, corrected for the rounding of 1 + z."""
    hi, lo = _one_plus(z)
    with np.errstate(over="ignore", invalid="ignore"):
        return np.where(np.isinf(hi), np.inf if k > 0 else 1.0, hi**k * (1.0 + k * (lo / hi)))


def _scaled(hi, lo, scale, k):
    """(hi + lo) scale / k with about one rounding (hi + lo is a double-double)."""
    with np.errstate(over="ignore", invalid="ignore"):
        p, e = two_product(hi, scale)
        q = p / k
        qh, ql = two_product(q, k)
        accurate = q + (((p - qh) - ql) + (e + lo * scale)) / k
    return np.where(np.isfinite(accurate), accurate, hi * scale / k)


def _one_minus_power(z, k):
    """1 - (1 + z)**-k = -expm1(-k log1p z) as a double-double (hi, lo); z = inf gives 1 (k > 0).

    For z <= -1/2, 1 + z is exact (Sterbenz) and the power form has no cancellation; elsewhere the product
    k log1p(z) is kept exact, so only log1p and expm1 round.
    """
    finite = np.isfinite(z)
    zz = np.where(finite, z, 0.0)
    y_hi, y_lo = two_product(k, np.log1p(zz))
    m = np.expm1(-y_hi)
    near = zz > -0.5
    with np.errstate(over="ignore"):
        far = 1.0 - np.where(near, 1.0, 1.0 + zz) ** -k
    hi = np.where(finite, np.where(near, -m, far), 1.0)
    lo = np.where(finite & near, y_lo * (1.0 + m), 0.0)
    return hi, lo


def _power_age(z, k, hubble_time):
    """t = t_H (1 + z)**-k / k; the power is split as m**-k 2**(-2 k j) so no intermediate underflows."""
    if k == 0:
        return np.full(z.shape, np.inf)
    x_hi, x_lo = _one_plus(z)
    finite = np.isfinite(x_hi)
    mantissa, exponent = np.frexp(np.where(finite, x_hi, 1.0))
    odd = exponent % 2
    half = (exponent - odd) // 2  # x_hi = (mantissa 2**odd) 2**(2 half), mantissa 2**odd in [1/2, 2)
    p = np.ldexp(mantissa, odd) ** -k
    correction = -k * (x_lo / np.where(finite, x_hi, 1.0)) * p
    scaled = _scaled(p, correction, hubble_time, k)
    with np.errstate(under="ignore"):
        return np.where(finite, np.ldexp(scaled, (-2 * k * half).astype(int)), 0.0)


def _power_lookback(z, k, hubble_time):
    """t0 - t = t_H (-expm1(-k log1p z)) / k; t_H log1p(z) for de Sitter (k = 0)."""
    if k == 0:
        return hubble_time * np.log1p(z)
    return _scaled(*_one_minus_power(z, k), hubble_time, k)


def _power_scale_factor(tau, k):
    """a = (k tau)**(1/k): tau, sqrt(2 tau) or cbrt(1.5 tau)**2 (a rounded exponent 2/3 would cost |ln a| ulp)."""
    if k == 1:
        return tau
    return np.sqrt(2.0 * tau) if k == 2 else cbrt(1.5 * tau) ** 2


def _power_comoving(z, k, hubble_distance):
    """D_C = d_H int_0^z x**-k dz: d_H (1 - x**(1-k)) / (k - 1); d_H log1p z (k = 1); d_H z (k = 0)."""
    if k == 0:
        return hubble_distance * z
    if k == 1:
        return hubble_distance * np.log1p(z)
    return _scaled(*_one_minus_power(z, k - 1.0), hubble_distance, k - 1.0)


def _sine_excess(y, hyperbolic):
    """sinh(y) - y (hyperbolic) or y - sin(y), y >= 0: the Taylor series y**3 / 3! +- y**5 / 5! + ... below y = 2
    (15 terms reach 1e-25 there), the difference above it (which cancels at most one bit)."""
    y = np.asarray(y, dtype=float)
    small = np.where(y < 2.0, y, 0.0)
    sign = 1.0 if hyperbolic else -1.0
    term = small**3 / 6.0
    series = term
    for n in range(5, 33, 2):
        term = sign * term * small * small / ((n - 1) * n)
        series = series + term
    with np.errstate(over="ignore"):
        direct = np.sinh(y) - y if hyperbolic else y - np.sin(y)
    return np.where(y < 2.0, series, direct)


# ---- flat matter + Lambda closed forms -----------------------------------------------------------------


def _a_to_the_1_5(z):
    """a**1.5 = (1 + z)**-1.5 as (p, e) with a**1.5 = ldexp(p, e): no intermediate underflow; a = 0 at z = inf."""
    x_hi, _ = _one_plus(z)
    finite = np.isfinite(x_hi)
    mantissa, exponent = np.frexp(np.where(finite, x_hi, 1.0))
    odd = exponent % 2
    half = (exponent - odd) // 2  # x = (mantissa 2**odd) 4**half
    return np.where(finite, np.ldexp(mantissa, odd) ** -1.5, 0.0), -3 * half


def _flat_age(z, omega_m, omega_l, hubble_time):
    """t = t_H (2 / (3 sqrt(Omega_Lambda))) asinh(u), u = sqrt(Omega_Lambda / Omega_m) a**1.5.

    For u < 2**-26, asinh u = u to rounding and t = t_H (2 / (3 sqrt(Omega_m))) a**1.5, scaled last.
    """
    p, e = _a_to_the_1_5(z)
    with np.errstate(under="ignore"):
        u = np.ldexp(math.sqrt(omega_l / omega_m) * p, e)
        small = np.ldexp(hubble_time * (2.0 / (3.0 * math.sqrt(omega_m))) * p, e)
    large = hubble_time * (2.0 / (3.0 * math.sqrt(omega_l))) * np.arcsinh(u)
    return np.where(u < 2.0**-26, small, large)


def _flat_lookback(z, omega_m, omega_l, hubble_time):
    """t0 - t = t_H (2 / (3 sqrt(Omega_Lambda))) asinh(D): asinh(u0) - asinh(u) without cancellation, where
    D = u0**2 (1 - a**3) / (u0 sqrt(1 + u**2) + u sqrt(1 + u0**2)), u0 = sqrt(Omega_Lambda / Omega_m), u = u0 a**1.5."""
    u0 = math.sqrt(omega_l / omega_m)
    p, e = _a_to_the_1_5(z)
    with np.errstate(under="ignore"):
        u = u0 * np.ldexp(p, e)
    one_minus_a3, _ = _one_minus_power(z, 3.0)
    d = u0 * u0 * one_minus_a3 / (u0 * np.sqrt(1.0 + u * u) + u * math.sqrt(1.0 + u0 * u0))
    return hubble_time * (2.0 / (3.0 * math.sqrt(omega_l))) * np.arcsinh(d)


def _flat_scale_factor(tau, omega_m, omega_l):
    """a = (Omega_m / Omega_Lambda)**(1/3) sinh(w)**(2/3), w = 1.5 sqrt(Omega_Lambda) tau; exp form for w > 20."""
    w = 1.5 * math.sqrt(omega_l) * tau
    ratio = cbrt(omega_m / omega_l)
    large = w > 20.0
    small = ratio * cbrt(np.sinh(np.where(large, 0.0, w))) ** 2
    return np.where(large, ratio * np.exp((2.0 / 3.0) * (w - math.log(2.0))), small)
