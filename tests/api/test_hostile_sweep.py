"""A property-based sweep of the public functions with hostile values: every call either answers with finite
numbers or refuses in one line with an error that names what it refused.

Each entry point takes one argument from the sweep (the others are ordinary); the sweep draws its kind (a plain
float, NaN and infinities, 0-d, empty and float16 arrays, masked, complex, object and boolean arrays, a broadcast
beyond the size limit, a list mixing units, a wrong unit, no unit) and its magnitude (1e-300 to 1e300, either
sign). What may happen:

- an answer: every number it is asked for is finite (a float64 that overflowed or a NaN left in is a failure);
- a refusal: an OrbitsError, TypeError, ValueError or astropy UnitsError raised by orbits itself, in one line and in
  its own words (an OrbitsError, or a message naming the argument), never NumPy's or astropy's; never a
  FloatingPointError or a RuntimeWarning (NumPy's word for a float64 that went astray: the conftest turns them into
  errors), never an IndexError, AttributeError or ZeroDivisionError.
"""

import math
import traceback
import warnings

import astropy.units as u
import numpy as np
import pytest
from astropy.utils.masked import Masked
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import orbits
from orbits import OrbitsError
from orbits.core.checks import MAX_ELEMENTS

KINDS = ("scalar", "nan", "inf", "zero_d", "empty", "float16", "masked", "numpy_masked", "complex", "object",
         "boolean", "huge_broadcast", "mixed_list", "wrong_unit", "no_unit")
WRONG = {u.m: u.kg, u.s: u.m, u.kg: u.s, u.deg: u.m, u.one: u.m, u.m / u.s: u.s}


def hostile(kind: str, magnitude: float, unit: u.UnitBase):
    """A value of the kind, near `magnitude`, in `unit` (u.one for a dimensionless argument)."""
    value = {"nan": math.nan, "inf": math.copysign(math.inf, magnitude)}.get(kind, magnitude)
    if kind in ("scalar", "nan", "inf"):
        return value * unit if unit is not u.one else value
    return {
        "zero_d": lambda: np.array(value) * unit,
        "empty": lambda: np.array([]) * unit,
        "float16": lambda: np.array([value, value / 2], dtype=np.float16) * unit,
        "masked": lambda: Masked([value, value] * unit, mask=[False, True]),
        "numpy_masked": lambda: np.ma.MaskedArray([value, value], mask=[0, 1]),
        "complex": lambda: (value + 1j) * unit,
        "object": lambda: np.array([value, None], dtype=object),
        "boolean": lambda: np.array([True, False]),
        "huge_broadcast": lambda: u.Quantity(np.broadcast_to(value, (MAX_ELEMENTS + 1,)), unit, copy=False),
        "mixed_list": lambda: [value * unit, value * WRONG[unit]],
        "wrong_unit": lambda: value * WRONG[unit],
        "no_unit": lambda: np.array([value, value]),
    }[kind]()


def _leo():
    return orbits.Orbit.circular("Earth", radius=7000 * u.km)


#: name -> (the call with the swept argument x, the unit x is given in, the arguments named in a refusal)
ENTRIES = {
    "Orbit.from_elements a": (lambda x: orbits.Orbit.from_elements("Earth", a=x, e=0.1).r, u.m, ("a",)),
    "Orbit.from_elements e": (lambda x: orbits.Orbit.from_elements("Earth", a=42000 * u.km, e=x).r, u.one, ("e",)),
    "Orbit.from_elements inc": (lambda x: orbits.Orbit.from_elements("Earth", a=42000 * u.km, e=0.1, inc=x).r, u.deg,
                                ("inclination", "inc")),
    "Orbit.circular radius": (lambda x: orbits.Orbit.circular("Earth", radius=x).v, u.m, ("radius",)),
    "Orbit.propagate dt": (lambda x: _leo().propagate(x)[0], u.s, ("dt",)),
    "Orbit.propagate dt, stm": (lambda x: _leo().propagate(x, stm=True)[2], u.s, ("dt",)),
    "Orbit.speed_at r": (lambda x: _leo().speed_at(x), u.m, ("distance r",)),
    "escape_speed distance": (lambda x: orbits.escape_speed("Earth", x), u.m, ("distance",)),
    "sun_synchronous altitude": (lambda x: orbits.sun_synchronous("Earth", altitude=x).inclination, u.m,
                                 ("altitude",)),
    "Flyby.past v_inf": (lambda x: orbits.Flyby.past("Earth", v_inf=x, b=20000 * u.km).deflection_angle, u.m / u.s,
                         ("v_inf",)),
    "Binary.from_elements m1": (lambda x: orbits.Binary.from_elements(x, 1 * u.solMass, a=1 * u.AU).period, u.kg,
                                ("m1",)),
    "Pendulum.simple length": (lambda x: orbits.Pendulum.simple(x, 30 * u.deg).period, u.m, ("length",)),
    "Hohmann.between r2": (lambda x: orbits.Hohmann.between("Earth", 7000 * u.km, x).delta_v, u.m,
                           ("r2",)),
    "velocity_change m1": (lambda x: orbits.velocity_change(3 * u.km / u.s, x, 1000 * u.kg), u.kg, ("m1",)),
    "anomalies e": (lambda x: orbits.anomalies(x, mean_anomaly=1 * u.rad)["true_anomaly"], u.one, ("e",)),
    "SecularOrbit.about inc": (lambda x: orbits.SecularOrbit.about("Earth", altitude=700 * u.km, inc=x).node_rate,
                               u.deg, ("inclination", "inc")),
    "SecularOrbit.about e": (lambda x: orbits.SecularOrbit.about("Earth", a=20000 * u.km, e=x).periapsis_rate, u.one,
                             ("e",)),
    "frozen altitude": (lambda x: orbits.frozen("Earth", altitude=x, inc=98 * u.deg).eccentricity, u.m,
                        ("altitude", "periapsis")),
    "DragDecay.of ballistic": (lambda x: orbits.DragDecay.of("Earth", altitude=300 * u.km, ballistic=x).lifetime,
                               u.m**2 / u.kg, ("ballistic",)),
    "KozaiLidov.of a_out": (lambda x: orbits.KozaiLidov.of("Sun", "Jupiter", a=1 * u.AU, a_out=x,
                                                             inc=60 * u.deg).timescale, u.m, ("a_out",)),
    "Ring.from_masses radius": (lambda x: orbits.Ring.from_masses(3, 1 * u.earthMass, x).period, u.m, ("radius",)),
    "lambert tof": (lambda x: orbits.lambert([1, 0, 0] * u.AU, [0, 1, 0] * u.AU, x).v1, u.s, ("time of flight",)),
    "Cosmology.comoving_distance z": (lambda x: orbits.Cosmology(70.0, 0.3, omega_l=0.7).comoving_distance(x),
                                      u.one, ("z", "redshift")),
}
WRONG[u.m**2 / u.kg] = u.kg


#: what NumPy and astropy say when a value reaches them unchecked (raised from orbits' own line by float() or len())
RAW = ("only 0-dimensional", "only dimensionless scalar", "could not convert", "has no attribute", "scaled version",
       "could not be broadcast", "setting an array element", "ufunc", "unsupported operand", "zero-size array",
       "index out of", "object of type")


def _numbers(result) -> np.ndarray:
    """The numbers of an answer: a Quantity, an array or a mapping of them."""
    if isinstance(result, dict):
        return np.concatenate([np.ravel(_numbers(v)) for v in result.values()])
    return np.asarray(getattr(result, "value", result), dtype=float)


@pytest.mark.parametrize("entry", list(ENTRIES))
@settings(max_examples=60, deadline=None, derandomize=False,
          suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow])
@given(kind=st.sampled_from(KINDS), exponent=st.floats(-300, 300), negative=st.booleans())
def test_a_hostile_value_is_answered_finitely_or_refused_in_one_line(entry, kind, exponent, negative):
    call, unit, names = ENTRIES[entry]
    with np.errstate(all="ignore"):  # a float16 of 1e5 is inf: built as NumPy builds it
        value = hostile(kind, (-1.0 if negative else 1.0) * 10.0**exponent, unit)
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", orbits.OrbitsWarning)  # warnings name a result's limits; they are not
            result = call(value)                                  # what is checked here
    except (OrbitsError, TypeError, ValueError, u.UnitsError) as err:
        message = str(err)
        assert message and "\n" not in message, (entry, kind, message)
        assert not isinstance(err, (FloatingPointError, ZeroDivisionError, IndexError)), (entry, kind, message)
        raised_in = traceback.extract_tb(err.__traceback__)[-1].filename
        assert "site-packages" not in raised_in, (entry, kind, message, raised_in)  # NumPy's or astropy's own words
        assert not any(phrase in message for phrase in RAW), (entry, kind, message)
        assert isinstance(err, OrbitsError) or any(name in message for name in names), (entry, kind, message)
        return
    numbers = _numbers(result)
    assert np.all(np.isfinite(numbers)), (entry, kind, exponent, numbers)
