"""Input checks shared by the numeric core: each error names the quantity, value and allowed range."""

import numpy as np

from orbits.errors import OrbitDomainError


def check_finite(x, name, unit):
    """Raise OrbitDomainError naming the first non-finite value of x."""
    if not np.all(np.isfinite(x)):
        bad = np.asarray(x)[~np.isfinite(x)].flat[0]
        raise OrbitDomainError(f"{name} = {float(bad)!r} {unit} is not finite; it must be a finite number")


def check_eccentricity(e, low, high, low_open, high_open, conic, hint=""):
    """Raise OrbitDomainError unless every e lies in the given interval (open or closed ends)."""
    check_finite(e, "eccentricity e", "(dimensionless)")
    below = (e <= low) if low_open else (e < low)
    above = (e >= high) if high_open else (e > high)
    bad = below | above
    if np.any(bad):
        value = np.asarray(e)[bad].flat[0]
        lo_br, hi_br = ("(" if low_open else "["), (")" if high_open else "]")
        raise OrbitDomainError(
            f"eccentricity e = {float(value)!r} is outside {lo_br}{low}, {high}{hi_br}, "
            f"where the {conic} Kepler equation is defined{hint}"
        )
