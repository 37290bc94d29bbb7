"""What the mechanics objects share: their input rules on top of orbits.inputs, and their quantity tables."""

from collections.abc import Iterable

import astropy.units as u
import numpy as np

from orbits import inputs, units
from orbits.constants import STANDARD_GRAVITY
from orbits.core.checks import check_finite
from orbits.core.errors import OrbitDomainError
from orbits.tables import quantity_table

ACCELERATION = units.M / units.S**2
RATE = units.S**-1
DIMENSIONLESS = u.one


def gravity(g: u.Quantity | None) -> np.ndarray:
    """g (m/s2): the standard 9.80665 m/s2 of the notes (XIX.vii) when None, else a positive acceleration."""
    if g is None:
        return np.asarray(STANDARD_GRAVITY)
    return inputs.positive(g, ACCELERATION, "gravitational acceleration g")


def signed(value: u.Quantity, unit: u.UnitBase, name: str) -> np.ndarray:
    """float64 array of a Quantity in `unit` (SI) of either sign, checked finite."""
    si = units.to_si(value, unit, name)
    check_finite(si, name, unit.to_string())
    return si


def non_negative(value: u.Quantity, unit: u.UnitBase, name: str) -> np.ndarray:
    """float64 array of a Quantity in `unit` (SI), checked finite and >= 0."""
    si = signed(value, unit, name)
    if np.any(si < 0):
        bad = float(np.asarray(si)[np.asarray(si) < 0].flat[0])
        raise OrbitDomainError(f"{name} = {bad!r} {unit.to_string()} is outside the allowed range [0, inf) "
                               f"{unit.to_string()}")
    return si


def planar_vector(value: u.Quantity, unit: u.UnitBase, name: str) -> np.ndarray:
    """float64 array (..., 2) or (..., 3) of a vector Quantity in `unit` (SI), finite: a velocity in a plane or in
    space (orbits.inputs.vector takes 3-vectors only)."""
    si = signed(value, unit, name)
    if si.ndim == 0 or si.shape[-1] not in (2, 3):
        raise OrbitDomainError(f"{name} must have a last axis of length 2 or 3; got shape {si.shape}")
    return si


def angle_in(value: u.Quantity, name: str, low: float, high: float, text: str) -> np.ndarray:
    """float64 array of an angle Quantity in rad (orbits.inputs.angle), checked to lie in the range `text` says:
    "[low, high]", with "(" or ")" for an open end (so "[0, pi/2)" refuses pi/2 itself)."""
    si = inputs.angle(value, name)
    below = (si <= low) if text.startswith("(") else (si < low)
    above = (si >= high) if text.endswith(")") else (si > high)
    bad = below | above
    if np.any(bad):
        value = float(np.asarray(si)[bad].flat[0])
        raise OrbitDomainError(f"{name} = {value!r} rad is outside the allowed range {text} rad")
    return si


def table(obj, names: list[str], only: Iterable[str] | None) -> dict[str, u.Quantity]:
    """{name: Quantity} of the object's cached properties (orbits.tables.quantity_table)."""
    return quantity_table(lambda name: getattr(obj, name), names, only)
