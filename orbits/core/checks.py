"""Input rules on float64 arrays, the one home of finiteness and positivity: every layer above calls these.

Each error is an OrbitDomainError naming the quantity, its first offending value, the allowed range and the unit.
The unit-aware rules (quantities, strings, primaries, size elements) build on these in orbits._common.inputs.
"""

import math

import numpy as np
from numpy.typing import ArrayLike

from orbits.core.errors import OrbitDomainError


def check_finite(x: ArrayLike, name: str, unit: str) -> None:
    """Raise OrbitDomainError naming the first non-finite value of x."""
    if not np.all(np.isfinite(x)):
        bad = np.asarray(x)[~np.isfinite(x)].flat[0]
        raise OrbitDomainError(f"{name} = {float(bad)!r}{_spaced(unit)} is not finite; it must be a finite number")


def require_no_underflow(literal: str, value: ArrayLike, name: str) -> None:
    """OrbitDomainError when a number written nonzero ("1e-330") reads as 0 in float64 (below 5e-324): it would
    be taken for an exact zero (a position on the primary, a zero mass)."""
    mantissa = literal.lower().split("e")[0]
    if np.all(np.asarray(value) == 0) and any(digit in mantissa for digit in "123456789"):
        raise OrbitDomainError(f"{name}: {literal!r} is below the smallest float64 (5e-324) and would read as 0")


def check_eccentricity(
    e: ArrayLike, low: float, high: float, low_open: bool, high_open: bool, conic: str, hint: str = ""
) -> None:
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


#: the most elements one argument, or one broadcast of several, may hold in a call: 2**25 (33.5 million), 268 MB
#: as one float64 array and a few GB with the temporaries of the heaviest solver; a larger batch is split by its
#: caller (orbits.tools.distributed runs one in chunks). Checked before anything of that size is made.
MAX_ELEMENTS = 2**25


def check_size(count: int, name: str) -> None:
    """OrbitDomainError when `count` elements exceed MAX_ELEMENTS, naming what holds them."""
    if count > MAX_ELEMENTS:
        raise OrbitDomainError(f"{name}: {count:,} elements, more than the {MAX_ELEMENTS:,} one call takes; split "
                               f"the batch into chunks")


def check_broadcast(name: str, *shapes: tuple[int, ...]) -> tuple[int, ...]:
    """The broadcast of `shapes`, checked against MAX_ELEMENTS before any array of it exists."""
    shape = np.broadcast_shapes(*shapes)
    check_size(math.prod(shape), name)
    return shape


def broadcast_shape(**shapes: tuple[int, ...]) -> tuple[int, ...]:
    """The shape the named shapes broadcast to; OrbitDomainError naming every argument with its shape otherwise
    (NumPy's own message says only "arg 0" and "arg 1")."""
    try:
        return np.broadcast_shapes(*shapes.values())
    except ValueError:
        listing = ", ".join(f"{name} {tuple(shape)}" for name, shape in shapes.items())
        raise OrbitDomainError(f"argument shapes do not broadcast together: {listing}") from None


def broadcast(**arrays: ArrayLike) -> list[np.ndarray]:
    """The named values as float64 arrays broadcast together, in order: each value itself where its shape is the
    broadcast's, else a read-only view (a compiled kernel copies it to the writable array it takes).
    broadcast_shape's error names them, and a broadcast of more than MAX_ELEMENTS is refused before anything of its
    size is made."""
    values = [np.asarray(value, dtype=float) for value in arrays.values()]
    shapes = [value.shape for value in values]
    if all(shape == shapes[0] for shape in shapes):  # nothing to broadcast (one value per call, the common case)
        return values
    shape = broadcast_shape(**dict(zip(arrays, shapes)))
    check_size(math.prod(shape), f"the broadcast of {', '.join(arrays)}")
    views = np.broadcast_arrays(*values)
    for view, value in zip(views, values):
        if view.shape != value.shape:  # a broadcast view: one element stands for many, so it is read-only
            view.flags.writeable = False
    return views


def first_where(mask: ArrayLike, *arrays: ArrayLike) -> list[float]:
    """The values of `arrays` (floats) at the first True of `mask`, all broadcast together: what an error message
    quotes for the first offending element of a batch."""
    mask, *arrays = np.broadcast_arrays(mask, *arrays)
    k = tuple(np.argwhere(mask)[0])
    return [float(a[k]) for a in arrays]


def require_positive(x: ArrayLike, name: str, unit: str) -> None:
    """Raise OrbitDomainError unless every x is finite and > 0; the message names x, its value, (0, inf) and unit."""
    x = np.asarray(x, dtype=float)
    bad = ~(np.isfinite(x) & (x > 0))
    if np.any(bad):
        value = float(x[bad].flat[0])
        if not np.isfinite(value):
            raise OrbitDomainError(f"{name} = {value!r}{_spaced(unit)} is not finite: it must be positive, in (0, inf)"
                                   f"{_spaced(unit)}")
        raise OrbitDomainError(
            f"{name} = {value!r}{_spaced(unit)} is outside the allowed range (0, inf){_spaced(unit)}: it must be "
            f"positive"
        )


#: the magnitudes, in SI units, that every positive dimensional input must lie within: products and quotients of
#: a few of them (energies, periods, speeds) then stay inside float64 (about 1e-308 to 1e308)
MAGNITUDE_RANGE = (1e-60, 1e60)


def require_magnitude(x: ArrayLike, name: str, unit: str) -> None:
    """Raise OrbitDomainError unless every positive x lies in MAGNITUDE_RANGE; the message says why it matters."""
    x = np.asarray(x, dtype=float)
    low, high = MAGNITUDE_RANGE
    bad = (x < low) | (x > high)
    if np.any(bad):
        value = float(x[bad].flat[0])
        raise OrbitDomainError(
            f"{name} = {value!r}{_spaced(unit)} is outside the range orbits computes in, [{low:g}, {high:g}]"
            f"{_spaced(unit)}: "
            f"quantities derived from it would overflow or underflow float64"
        )


def _spaced(unit: str) -> str:
    """" m / s" for a unit, "" for none (a dimensionless quantity reads "e = 1.5 is outside ...")."""
    return f" {unit}" if unit else ""
