"""The unit boundary: Quantities are stripped to float64 SI arrays here, once, and put back with `<<`.

Policy: a dimensional argument must be an astropy Quantity; a bare number is a TypeError that says
what to pass (no silent metres). Eccentricities and other pure numbers may be plain floats. Angles
must carry an angle unit. bool is rejected everywhere; ints and float32 are upcast to float64.
"""

import astropy.units as u
import numpy as np

M = u.m
S = u.s
KG = u.kg
RAD = u.rad
M_PER_S = u.m / u.s
M3_PER_S2 = u.m**3 / u.s**2
J = u.J
M2_PER_S = u.m**2 / u.s
KG_M2_PER_S = u.kg * u.m**2 / u.s
RAD_PER_S = u.rad / u.s
J_PER_KG = u.J / u.kg

_EXAMPLE = {
    "m": "7000 * u.km",
    "kg": "5.97e24 * u.kg",
    "s": "3600 * u.s",
    "rad": "30 * u.deg",
    "m / s": "7.5 * u.km / u.s",
    "m3 / s2": "3.986e14 * u.m**3 / u.s**2",
}


def _reject_bool(value, name):
    if isinstance(value, (bool, np.bool_)) or (isinstance(value, np.ndarray) and value.dtype == bool):
        raise TypeError(f"{name} = {value!r} is a boolean; pass a number")


def to_si(value, unit, name):
    """float64 array of `value` (a Quantity) in `unit`; TypeError for bare numbers, UnitConversionError
    naming the argument for incompatible units."""
    _reject_bool(value, name)
    if not isinstance(value, u.Quantity):
        example = _EXAMPLE.get(str(unit), f"value * u.Unit('{unit}')")
        raise TypeError(f"{name} = {value!r} has no unit; pass a Quantity such as {example}")
    try:
        return np.asarray(value.to_value(unit), dtype=float)
    except u.UnitConversionError:
        raise u.UnitConversionError(
            f"{name} = {value} has units of {value.unit.physical_type}, which cannot be converted to {unit} "
            f"({u.Unit(unit).physical_type})"
        ) from None


def to_number(value, name):
    """float64 array of a dimensionless argument (plain number or dimensionless Quantity)."""
    _reject_bool(value, name)
    if isinstance(value, u.Quantity):
        try:
            return np.asarray(value.to_value(u.dimensionless_unscaled), dtype=float)
        except u.UnitConversionError:
            raise u.UnitConversionError(f"{name} = {value} must be dimensionless") from None
    return np.asarray(value, dtype=float)
