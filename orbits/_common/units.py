"""The unit boundary: Quantities are stripped to float64 SI arrays here, once, and put back with `<<`.

Policy: a dimensional argument must be an astropy Quantity; a bare number is a TypeError that says
what to pass (no silent metres). Eccentricities and other pure numbers may be plain floats. Angles
must carry an angle unit. bool, complex numbers and masked arrays are rejected everywhere; ints and
float32 are upcast to float64.
"""

import astropy.units as u
import numpy as np

from orbits.core.checks import check_size

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
ACCELERATION = u.m / u.s**2
RATE = u.s**-1
DIMENSIONLESS = u.one

_EXAMPLE = {
    "m": "7000 * u.km",
    "kg": "5.97e24 * u.kg",
    "s": "3600 * u.s",
    "rad": "30 * u.deg",
    "m / s": "7.5 * u.km / u.s",
    "m3 / s2": "3.986e14 * u.m**3 / u.s**2",
}


def _reject_bool(value, name):
    """TypeError for what a float64 array cannot stand for: booleans, complex numbers (their imaginary part would
    be dropped) and masked arrays (NumPy's or astropy's: the masked elements would be computed and the mask lost)."""
    if isinstance(value, (bool, np.bool_)) or (isinstance(value, np.ndarray) and value.dtype == bool):
        raise TypeError(f"{name} = {value!r} is a boolean; pass a number")
    if hasattr(value, "mask"):
        raise TypeError(f"{name} is a masked array; orbits computes every element, so fill or drop the masked ones "
                        f"first (e.g. value[~value.mask] or value.filled(...))")
    if np.iscomplexobj(value):
        raise TypeError(f"{name} = {value!r} is complex; pass real numbers")


#: Conversion factors already computed, {(from unit, to unit): scale}. Quantity.to_value recomputes the
#: factor on every call; a dictionary lookup here does not.
_SCALES = {}


def to_si(value: u.Quantity, unit: u.UnitBase, name: str) -> np.ndarray:
    """float64 array of `value` (a Quantity) in `unit`; TypeError for bare numbers, UnitConversionError
    naming the argument for incompatible units.

    The value is the one Quantity.to_value gives (the same product value * scale), with the scale
    looked up in _SCALES; units that are not plain scale factors (logarithmic units) go through
    to_value.
    """
    value = joined(value, name)
    _reject_bool(value, name)
    check_size(int(np.size(value)), name)
    if not isinstance(value, u.Quantity):
        example = _EXAMPLE.get(str(unit), f"value * u.Unit('{unit}')")
        raise TypeError(f"{name} = {value!r} has no unit; pass a Quantity such as {example}")
    try:
        scale = _scale(value.unit, unit)
        if scale is None:
            return np.asarray(value.to_value(unit), dtype=float)
    except u.UnitConversionError:
        raise u.UnitConversionError(
            f"{name} = {value} has units of {value.unit.physical_type}, which cannot be converted to {unit} "
            f"({u.Unit(unit).physical_type})"
        ) from None
    array = value.view(np.ndarray)
    if scale == 1.0:
        return np.asarray(array, dtype=float)
    with np.errstate(over="ignore"):
        result = np.asarray(array * scale, dtype=float)
    _refuse_overflow(array, result, value.unit, unit, name)
    return result


def _refuse_overflow(given, result, from_unit, to_unit, name) -> None:
    """OrbitDomainError where a finite value became inf in SI: 1e300 AU is 1.5e311 m, beyond float64 (1.8e308)."""
    beyond = np.isfinite(given) & ~np.isfinite(result)
    if np.any(beyond):
        from orbits.core.errors import OrbitDomainError

        first = np.asarray(given, dtype=float).ravel()[np.flatnonzero(beyond)[0]]
        raise OrbitDomainError(f"{name} = {first:.6g} {from_unit} is beyond float64's range in {to_unit} (at most "
                               f"{np.finfo(float).max:.4g} {to_unit})")


def joined(value, name):
    """A list or tuple of Quantities ([1 * u.min, 60 * u.s]) as one Quantity in its first element's unit, as
    astropy joins them; anything else unchanged. Units that do not convert into one another are a
    UnitConversionError naming the argument."""
    if not isinstance(value, (list, tuple)) or not any(isinstance(x, (u.Quantity, list, tuple)) for x in value):
        return value
    try:
        return u.Quantity(value)
    except u.UnitsError as err:
        raise u.UnitConversionError(f"{name} is a list whose units do not convert into one another ({err})") from None
    except (TypeError, ValueError) as err:  # numbers without a unit among Quantities, nested lists
        raise TypeError(f"{name} is a list that does not join into one Quantity ({err}); pass one Quantity: an "
                        f"array of numbers times a unit") from None


def _scale(from_unit, to_unit):
    """Factor from from_unit to to_unit (cached), None if the conversion is not a plain factor."""
    key = (from_unit, to_unit)
    scale = _SCALES.get(key)
    if scale is None:
        if not isinstance(from_unit, u.UnitBase):
            return None
        scale = _SCALES[key] = from_unit.to(to_unit)
    return scale


def to_number(value: float | np.ndarray | u.Quantity, name: str) -> np.ndarray:
    """float64 array of a dimensionless argument (plain number or dimensionless Quantity)."""
    value = joined(value, name)
    _reject_bool(value, name)
    check_size(int(np.size(value)), name)
    if isinstance(value, u.Quantity):
        try:
            return np.asarray(value.to_value(u.dimensionless_unscaled), dtype=float)
        except u.UnitConversionError:
            raise u.UnitConversionError(f"{name} = {value} must be dimensionless") from None
    return np.asarray(value, dtype=float)
