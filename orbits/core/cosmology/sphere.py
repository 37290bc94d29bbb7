"""Section XXIV of the notes: the Newtonian expanding sphere (Einstein-de Sitter).

Float64 arrays in SI units (t in s, r in m, gm = G M in m**3/s**2, H in 1/s) that broadcast. A shell enclosing
the mass M of a uniform, pressureless sphere moves outward at the zero-energy speed v = sqrt(2 G M / r), so
r(t) = (9 G M t**2 / 2)**(1/3), v(t) = (4 G M / (3 t))**(1/3) and H = v / r = 2 / (3 t), with t measured from
the big bang. The relativistic models around it are in orbits.core.cosmology.friedmann.
"""


import numpy as np
from numpy.typing import ArrayLike

from orbits.core._dd import cbrt
from orbits.core.errors import OrbitDomainError


def _check_time(t, allow_zero):
    """Raise OrbitDomainError for t < 0 (before the big bang), NaN, or t = 0 where the quantity is infinite."""
    t = np.asarray(t, dtype=float)
    if np.any(np.isnan(t)):
        raise OrbitDomainError("time since the big bang t = nan s is not a number; allowed [0, inf) s")
    bad = (t < 0) if allow_zero else (t <= 0)
    if np.any(bad):
        value = float(t[bad].flat[0])
        allowed = "[0, inf) s" if allow_zero else "(0, inf) s: v and H are infinite at the big bang"
        raise OrbitDomainError(f"time since the big bang t = {value!r} s is outside {allowed}")
    return t


def sphere_radius(t: ArrayLike, gm: ArrayLike) -> float | np.ndarray:
    """r = (9 G M t**2 / 2)**(1/3) (m) of the shell enclosing G M = gm (m3/s2), t (s) after the big bang.

    XXIV.iii, box 5. Accuracy: within 1 ulp on every CPU (tests/core/test_cosmology.py).
    """
    t = _check_time(t, allow_zero=True)
    return cbrt((4.5 * gm) * t * t)


def sphere_speed(t: ArrayLike, gm: ArrayLike) -> float | np.ndarray:
    """v = (4 G M / (3 t))**(1/3) (m/s) of that shell at t > 0 (s); XXIV.iv, box 6."""
    t = _check_time(t, allow_zero=False)
    return cbrt(gm / (0.75 * t))


def sphere_hubble_parameter(t: ArrayLike) -> float | np.ndarray:
    """H = v / r = 2 / (3 t) (1/s) at t > 0 (s) after the big bang; XXIV.iv (Hubble's law v = H r)."""
    t = _check_time(t, allow_zero=False)
    return 2.0 / (3.0 * t)


def sphere_time(r: ArrayLike, gm: ArrayLike) -> float | np.ndarray:
    """t = sqrt(2 r**3 / (9 G M)) = r sqrt(2 r / (9 G M)) (s) at which the shell reaches r (m); inverse of box 5."""
    return r * np.sqrt((r + r) / (9.0 * gm))


def age_from_hubble(hubble: ArrayLike) -> float | np.ndarray:
    """Einstein-de Sitter age t = 2 / (3 H) (s) for the Hubble parameter H (1/s); XXIV.iv (1.33e10 yr)."""
    return 2.0 / (3.0 * hubble)


def critical_density(hubble: ArrayLike, g: float) -> float | np.ndarray:
    """rho_c = 3 H**2 / (8 pi G) (kg/m3): the density of a flat universe expanding at H (1/s)."""
    return 3.0 * hubble * hubble / (8.0 * np.pi * g)


def sphere_density(t: ArrayLike, g: float) -> float | np.ndarray:
    """rho = M / (4 pi r**3 / 3) = 1 / (6 pi G t**2) (kg/m3) of the uniform sphere at t > 0 (s); equals rho_c."""
    t = _check_time(t, allow_zero=False)
    return 1.0 / (6.0 * np.pi * g * t * t)
