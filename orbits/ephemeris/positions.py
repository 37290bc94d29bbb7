"""Where the Sun, the planets and the Moon are at a date: JPL DE421, or astropy's approximate built-in ephemeris.

    >>> from orbits import ephemeris
    >>> mars = ephemeris.state("Mars", "2026-11-25", center="Sun")      # an ISO date is read as UTC
    >>> mars.source
    'JPL DE421 (skyfield-data, read by jplephem)'
    >>> round(float(mars.distance.to_value("AU")), 6)
    1.61835

Sources, tried in this order by `source="auto"`:

- **JPL DE421** (Folkner et al. 2008, 1899-07-29 to 2053-10-09 TDB), the file `de421.bsp` shipped by the PyPI
  package skyfield-data and read by jplephem: the extra `orbits[ephemeris]` (in `orbits[test]`). DE421 gives the
  centres of Mercury, Venus, Earth, Moon and Mars and the *system barycentres* of Jupiter, Saturn, Uranus,
  Neptune and Pluto (the planet and its moons); a state says so (`BodyState.point`). Read here to the last bit
  jplephem returns: astropy reading the same file agrees to 1 mm and 1e-9 m/s (tests/api/test_ephemeris.py).
- **astropy's built-in ephemeris** (ERFA's epv00 for the Earth and the Sun, plan94 for the planets, moon98
  for the Moon) when the extra is not installed, or with `source="builtin"`. Against DE421, 1900-2050, measured
  every 1.37 d: Earth 4.2 km median (12.9 km worst), Mars 5,500 km (27,000 km), Jupiter 55,000 km
  (244,000 km); no Pluto. BUILTIN_ACCURACY_KM states the bound each body is tested against; outside 1900-2050
  a state says its accuracy was not measured.

Epochs: an astropy `Time` in any scale (converted to TDB), or ISO strings ("2026-11-25", "2026-11-25T06:00")
read as UTC unless they end in a scale ("2026-11-25 12:00 TDB"; TDB, TT, TAI, TCB, TCG, UTC, UT1), or "J2000".
UT1 needs UT1 - UTC from the IERS table installed with astropy (nothing is downloaded): a UT1 date outside it
is refused. A date is
carried as a two-part Julian date (jd1 + jd2), which keeps it to 20 microseconds over 1900-2050. Vectors are
ICRF (equatorial J2000) in metres and m/s; `orbits.core.frames` turns them to the ecliptic of J2000.
"""

import atexit
import contextlib
import functools
import importlib.util
import os
import re
import warnings
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from typing import Any

import astropy.units as u
import numpy as np
from astropy.time import Time

from orbits._common import display, units
from orbits._common.constants import BODIES, SPEED_OF_LIGHT, body
from orbits._common.tables import quantity_table
from orbits.core import frames
from orbits.core.errors import OrbitDomainError, UnknownNameError

#: DE421's span, Julian dates TDB (the kernel's segments all cover it)
DE421_SPAN = (2414864.5, 2471184.5)
DE421 = "JPL DE421 (skyfield-data, read by jplephem)"
BUILTIN = "astropy built-in (ERFA epv00, plan94, moon98)"
SOURCES = ("auto", "de421", "builtin")

#: point name -> NAIF id chain from the solar-system barycentre (0) in DE421; each pair is one kernel segment
_CHAINS = {
    "solar system barycentre": (),
    "Sun": ((0, 10),),
    "Mercury": ((0, 1), (1, 199)),
    "Venus": ((0, 2), (2, 299)),
    "Earth-Moon barycentre": ((0, 3),),
    "Earth": ((0, 3), (3, 399)),
    "Moon": ((0, 3), (3, 301)),
    "Mars": ((0, 4), (4, 499)),
    "Jupiter": ((0, 5),),
    "Saturn": ((0, 6),),
    "Uranus": ((0, 7),),
    "Neptune": ((0, 8),),
    "Pluto": ((0, 9),),
}
#: bodies whose DE421 point is the barycentre of the planet and its moons, not the planet's centre
SYSTEM_BARYCENTRES = ("Jupiter", "Saturn", "Uranus", "Neptune", "Pluto")
#: bodies outside DE421 whose heliocentric state is their published osculating orbit (orbits.ephemeris.catalogue)
#: carried to the epoch by two-body propagation about the Sun, the accuracy its MeanElements states
PROPAGATED = ("Ceres", "Vesta", "Pallas", "Hygiea", "Eris")
_ALIASES = {"ssb": "solar system barycentre", "solar system barycenter": "solar system barycentre",
            "barycentre": "solar system barycentre", "barycenter": "solar system barycentre",
            "emb": "Earth-Moon barycentre", "earth-moon barycenter": "Earth-Moon barycentre"}
#: astropy's names for the points its built-in ephemeris has
_BUILTIN_NAMES = {"Sun": "sun", "Mercury": "mercury", "Venus": "venus",
                  "Earth-Moon barycentre": "earth-moon-barycenter",
                  "Earth": "earth", "Moon": "moon", "Mars": "mars", "Jupiter": "jupiter", "Saturn": "saturn",
                  "Uranus": "uranus", "Neptune": "neptune"}
#: years over which the built-in ephemeris was measured against DE421
BUILTIN_SPAN = (1900, 2050)
#: the built-in ephemeris against DE421 (km), barycentric: 1.5 times the worst on a grid of 40,001 TDB epochs
#: every 1.37 d over 1900-2050 (measured median / worst: Sun 2.3 / 5.7, Mercury 243 / 1,474, Venus 822 / 3,577,
#: Earth-Moon barycentre 1,596 / 5,727, Earth 4.2 / 12.9, Moon 6.5 / 35.7, Mars 5,453 / 26,857, Jupiter
#: 55,467 / 243,795, Saturn 151,591 / 584,273, Uranus 405,306 / 1,173,224, Neptune 193,265 / 276,883);
#: tests/api/test_ephemeris.py holds each body to it on a coarser grid
BUILTIN_ACCURACY_KM = {"Sun": 9.0, "Mercury": 2.3e3, "Venus": 5.4e3, "Earth-Moon barycentre": 8.6e3, "Earth": 20.0,
                       "Moon": 54.0, "Mars": 4.1e4, "Jupiter": 3.7e5, "Saturn": 8.8e5, "Uranus": 1.8e6,
                       "Neptune": 4.2e5}

#: GM (m3/s2) of each DE421 point that carries mass, from JPL DE430 (Folkner et al. 2014, IPN Progress Report
#: 42-196, Table 8, to the digits of JPL Horizons' gm_Horizons.pck): the masses an N-body model of these points
#: uses. Jupiter-Pluto are whole systems, as their DE421 points are system barycentres; Mars's point is the
#: planet's centre but carries the system's mass too (its moons add 4e-8); the Moon's is 4902.8000661637961
#: km3/s2 (DE421's own: 4902.800076).
DE430_GM = {name: gm * 1e9 for name, gm in {
    "Sun": 132_712_440_041.93938, "Mercury": 22_031.78, "Venus": 324_858.592, "Earth": 398_600.43543609598,
    "Moon": 4_902.8000661637961, "Mars": 42_828.375214, "Jupiter": 126_712_764.8, "Saturn": 37_940_585.2,
    "Uranus": 5_794_548.6, "Neptune": 6_836_527.10058, "Pluto": 977.0}.items()}

_SCALE_SUFFIX = re.compile(r"^(?P<date>.*?)\s+(?P<scale>tdb|tt|tai|utc|ut1|tcb|tcg)$", re.IGNORECASE)
_KM_PER_DAY = 1e3 / 86400.0


def point_name(name: str) -> str:
    """The ephemeris' name for a body or barycentre given in any case ("mars", "SSB", "Earth-Moon barycenter")."""
    key = str(name).strip().lower()
    if key in _ALIASES:
        return _ALIASES[key]
    for known in _CHAINS:
        if known.lower() == key:
            return known
    for known in PROPAGATED:
        if known.lower() == key:
            return known
    catalogued = " (it is in the catalogue, but not in the ephemeris)" if key in (b.lower() for b in BODIES) else ""
    raise UnknownNameError.among("no ephemeris for", name, [*_CHAINS, *PROPAGATED], catalogued)


def epoch(value: Any, scale: str = "utc") -> Time:
    """An astropy Time in TDB from a Time (any scale), an ISO string or list of them (in `scale` unless the string
    ends with one), or "J2000" (2000-01-01 12:00 TT). The conversion to TDB happens here, once: everything after
    reads the two-part TDB Julian date as it is."""
    if isinstance(value, Time):
        return _in_tdb(value)
    texts = [value] if isinstance(value, str) else list(value)
    if not texts or not all(isinstance(t, str) for t in texts):
        raise OrbitDomainError(f"epoch: {value!r} is neither an astropy Time nor ISO date strings")
    parsed = [_one_epoch(t, scale) for t in texts]
    if isinstance(value, str):
        return _in_tdb(parsed[0])
    jd1, jd2 = np.array([tdb_julian_dates(p) for p in parsed]).T  # each through the offline, quiet conversion
    return Time(jd1, jd2, format="jd", scale="tdb")


def _in_tdb(when: Time) -> Time:
    """The same instant(s) as a TDB Time (the Time itself when it is in TDB already)."""
    if when.scale == "tdb":
        return when
    return Time(*tdb_julian_dates(when), format="jd", scale="tdb")


@contextlib.contextmanager
def _quiet_erfa():
    """Silence ERFA's "dubious year" warnings: UTC before 1960 or after its leap-second table (future leap seconds
    are unknown, so a future UTC date is read with none added); DE421's span check says what is out of range."""
    from erfa import ErfaWarning

    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ErfaWarning)
        yield


def _one_epoch(text: str, scale: str) -> Time:
    text = text.strip()
    if text.upper() in ("J2000", "J2000.0"):
        return Time(2451545.0, format="jd", scale="tt")
    match = _SCALE_SUFFIX.match(text)
    if match:
        text, scale = match["date"], match["scale"].lower()
    try:
        with _quiet_erfa():
            when = Time(text, scale=scale)
    except ValueError:
        raise OrbitDomainError(f"epoch: {text!r} is not a date; give an ISO date such as '2026-11-25' or "
                               f"'2026-11-25T06:00', optionally followed by a scale (UTC, TT, TDB, TAI, TCB, TCG, "
                               f"UT1)") from None
    _require_seconds_in_the_minute(text, scale, when)
    return when


_SECONDS = re.compile(r"\d:\d\d:(?P<seconds>\d+(?:\.\d*)?)$")


def _require_seconds_in_the_minute(text: str, scale: str, when: Time) -> None:
    """OrbitDomainError for seconds of 60 or more, unless the minute is a UTC minute that ends with a leap second
    (astropy carries the date over: 12:00:99 became 12:01:39, and :60 was taken on any day)."""
    match = _SECONDS.search(text)
    if match is None or float(match["seconds"]) < 60:
        return
    if scale == "utc" and when.ymdhms.second >= 60:  # kept as a leap second: the day had one
        return
    leap = "; 60 only in a UTC leap second (e.g. 2016-12-31T23:59:60)" if float(match["seconds"]) < 61 else ""
    raise OrbitDomainError(f"epoch: {text!r} has {match['seconds']} seconds, past the end of its minute{leap}")


def tdb_julian_dates(when: Time) -> tuple[np.ndarray, np.ndarray]:
    """The epoch as a two-part TDB Julian date (jd1, jd2), float64 arrays (ERFA's "dubious year" warnings for
    dates outside its leap-second table are silenced: DE421's span check says what is wrong)."""
    if when.scale == "tdb":
        return np.asarray(when.jd1, dtype=float), np.asarray(when.jd2, dtype=float)
    with _quiet_erfa(), _offline_iers():
        if when.scale == "ut1":
            _require_earth_orientation(when)
        tdb = when.tdb
    return np.asarray(tdb.jd1, dtype=float), np.asarray(tdb.jd2, dtype=float)


def tdb_iso(when: Time) -> str:
    """The epoch in TDB to the second ("2026-11-25 00:01:09"), or "N epochs from ... to ..." for an array."""
    with _quiet_erfa(), _offline_iers():
        if when.isscalar:
            return when.tdb.iso[:19]
        return f"{when.size} epochs from {when.tdb.min().iso[:19]} to {when.tdb.max().iso[:19]}"


@contextlib.contextmanager
def _offline_iers():
    """astropy's Earth-orientation tables as installed (astropy-iers-data), never a download: nothing here reads the
    network. Only UT1 needs them; predictions in the installed table are taken as they are."""
    from astropy.utils import iers

    with iers.conf.set_temp("auto_download", False), iers.conf.set_temp("auto_max_age", None):
        yield


def _require_earth_orientation(when: Time) -> None:
    """A UT1 epoch needs UT1 - UTC from the installed IERS table; outside it astropy would hold the table's edge
    value, off by up to 0.9 s (20 km along Mars's orbit), so such an epoch is refused."""
    from astropy.utils import iers

    _, status = when.get_delta_ut1_utc(return_status=True)
    outside = np.asarray(status) < 0
    if outside.any():
        table = iers.earth_orientation_table.get()
        first, last = (Time(table["MJD"][i], format="mjd").strftime("%Y-%m-%d") for i in (0, -1))
        bad = np.atleast_1d(when.iso)[np.atleast_1d(outside)][0]
        raise OrbitDomainError(f"epoch {bad} UT1 is outside the installed Earth-orientation table ({first} to "
                               f"{last}, astropy-iers-data): UT1 - UTC is unknown there and orbits downloads "
                               f"nothing; give the date in UTC, TT or TDB")


def available_source() -> str:
    """The source `source="auto"` picks: DE421 when skyfield-data and jplephem are installed."""
    have = all(importlib.util.find_spec(m) is not None for m in ("skyfield_data", "jplephem"))
    return "de421" if have else "builtin"


@functools.cache
def kernel_path() -> str:
    """Path of de421.bsp inside the skyfield-data package."""
    import skyfield_data

    path = os.path.join(os.path.dirname(skyfield_data.__file__), "data", "de421.bsp")
    if not os.path.exists(path):
        raise OrbitDomainError(f"skyfield-data is installed but has no DE421 kernel at {path}")
    return path


@functools.cache
def _kernel():
    from jplephem.spk import SPK

    kernel = SPK.open(kernel_path())  # memory-maps the file; closed when the interpreter exits
    atexit.register(kernel.close)
    return kernel


def _require_de421_span(jd1: np.ndarray, jd2: np.ndarray) -> None:
    jd = jd1 + jd2
    outside = (jd < DE421_SPAN[0]) | (jd > DE421_SPAN[1])
    if outside.any():
        first = (np.asarray(jd1)[outside].flat[0], np.asarray(jd2)[outside].flat[0])
        bad, start, end = (Time(*pair, format="jd", scale="tdb").iso[:19]
                           for pair in (first, (DE421_SPAN[0], 0.0), (DE421_SPAN[1], 0.0)))
        raise OrbitDomainError(f"epoch {bad} TDB is outside DE421, which covers {start} to {end} TDB (to the "
                               f"second: a UTC date is about a minute later in TDB)")


def _de421_from_ssb(point: str, jd1: np.ndarray, jd2: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Barycentric ICRF position (m) and velocity (m/s) of a DE421 point, each shaped jd1.shape + (3,)."""
    kernel = _kernel()
    r = np.zeros((3,) + jd1.shape)  # summed in jplephem's (3, n) layout, turned to (n, 3) once at the end
    v = np.zeros((3,) + jd1.shape)
    for center, target in _CHAINS[point]:
        position, velocity = kernel[center, target].compute_and_differentiate(jd1, jd2)
        r += position
        v += velocity
    return np.moveaxis(r * 1e3, 0, -1), np.moveaxis(v * _KM_PER_DAY, 0, -1)  # scaled first: contiguous


def _builtin_from_ssb(point: str, when: Time) -> tuple[np.ndarray, np.ndarray]:
    from astropy.coordinates import get_body_barycentric_posvel

    if point == "solar system barycentre":
        zeros = np.zeros(np.shape(when.jd1) + (3,))
        return zeros, zeros.copy()
    if point not in _BUILTIN_NAMES:
        raise OrbitDomainError(f"astropy's built-in ephemeris has no {point}; install the extra orbits[ephemeris] "
                               f"for JPL DE421")
    if when.scale == "ut1":
        with _offline_iers():
            _require_earth_orientation(when)
    with _quiet_erfa(), _offline_iers():
        position, velocity = get_body_barycentric_posvel(_BUILTIN_NAMES[point], when, ephemeris="builtin")
    return (np.moveaxis(position.xyz.to_value(u.m), 0, -1), np.moveaxis(velocity.xyz.to_value(u.m / u.s), 0, -1))


def barycentric(point: str, when: Time, source: str = "auto") -> tuple[np.ndarray, np.ndarray]:
    """ICRF position (m) and velocity (m/s) of `point` relative to the solar-system barycentre, float64 arrays
    shaped epoch shape + (3,), from the resolved `source` ("de421" or "builtin")."""
    return _read([point], when, source)[point]


def _read(points: Sequence[str], when: Time, source: str) -> dict[str, tuple[np.ndarray, np.ndarray]]:
    """Barycentric (r, v) of each distinct point at one epoch from the resolved `source`: the epoch checked against
    the source's span once, each point read once."""
    wanted = list(dict.fromkeys(points))
    read_from_source = [p for p in dict.fromkeys([*wanted, *(["Sun"] if set(wanted) & set(PROPAGATED) else [])])
                        if p not in PROPAGATED]
    if source == "de421":
        jd1, jd2 = tdb_julian_dates(when)
        _require_de421_span(jd1, jd2)
        read = {point: _de421_from_ssb(point, jd1, jd2) for point in read_from_source}
    else:
        read = {point: _builtin_from_ssb(point, when) for point in read_from_source}
    for point in set(wanted) & set(PROPAGATED):
        r, v = _propagated_heliocentric(point, when)
        read[point] = (read["Sun"][0] + r, read["Sun"][1] + v)
    return read


def _propagated_heliocentric(name: str, when: Time) -> tuple[np.ndarray, np.ndarray]:
    """ICRF heliocentric (r, v) (m, m/s) of a PROPAGATED body: its osculating orbit (orbits.ephemeris.catalogue)
    carried from its epoch to `when` by Kepler's equation (orbits.core.twobody.propagate)."""
    from orbits.core import frames
    from orbits.core.twobody import anomalies, elements, propagate
    from orbits.ephemeris.catalogue import JPL_SUN_GM, mean_elements

    el = mean_elements(name)
    nu = anomalies.true_from_mean(el.mean_anomaly, el.e)
    r0, v0 = elements.elements_to_state(el.a * (1 - el.e) * (1 + el.e), el.e, el.inc, el.raan, el.argp, nu,
                                        JPL_SUN_GM)
    jd1, jd2 = tdb_julian_dates(when)
    dt = ((jd1 - el.epoch) + jd2) * 86_400.0
    r, v = propagate.propagate(r0, v0, JPL_SUN_GM, dt)
    return frames.ecliptic_to_equatorial(r), frames.ecliptic_to_equatorial(v)


_OTHERS = "; other bodies: "


def _drift_here(name: str, epoch_jd: float, when: Time) -> str:
    """'; here 1.1 yr from it: up to 2,750,000 km': the stated drift carried to the farthest of the epochs (and
    whether that lies beyond the span the drift was measured over)."""
    from orbits.ephemeris.catalogue import DRIFT_KM_PER_YEAR, DRIFT_MEASURED_YEARS

    jd1, jd2 = tdb_julian_dates(when)
    years = float(np.max(np.abs((np.asarray(jd1) - epoch_jd) + np.asarray(jd2)))) / 365.25
    beyond = f", beyond the {DRIFT_MEASURED_YEARS:g} years measured" if years > DRIFT_MEASURED_YEARS else ""
    return f"; here {years:.3g} yr from it: up to {float(f'{DRIFT_KM_PER_YEAR[name] * years:.2g}'):,.0f} km{beyond}"


def provenance(*parts: "BodyState") -> tuple[str, str]:
    """(source, stated accuracy) of what is built from several states (a transfer's two ends, a body seen from
    another): each propagated body's published orbit and accuracy named once, then the ephemeris of the rest, with
    the built-in ephemeris's accuracy against DE421 for the parts it gives (DE421 itself states none: it is the
    reference, read exactly)."""
    propagated, ephemerides, stated, builtin = [], [], [], []
    for part in parts:
        head, _, rest = part.source.rpartition(_OTHERS)
        if head and head not in propagated:
            propagated.append(head)
        if rest not in ephemerides:
            ephemerides.append(rest)
        if part.stated_accuracy and part.stated_accuracy not in stated:
            stated.append(part.stated_accuracy)
        elif not part.stated_accuracy and part.source == BUILTIN:
            builtin.append(part)
    if builtin:
        stated.append(_builtin_accuracy(builtin))
    named = "; ".join(ephemerides)
    return ("; ".join(propagated) + _OTHERS + named if propagated else named), "; ".join(stated)


def _builtin_accuracy(parts: "Sequence[BodyState]") -> str:
    """How far the built-in ephemeris may put what the states give from DE421: the sum of the worst offsets
    measured for each body and centre (BUILTIN_ACCURACY_KM, each counted once) over BUILTIN_SPAN, or that it was
    not measured where an epoch lies outside that span."""
    years = [2000.0 + (np.asarray(jd1 - 2451545.0) + jd2) / 365.25
             for jd1, jd2 in (tdb_julian_dates(part.epoch) for part in parts)]
    if any(np.any((year < BUILTIN_SPAN[0]) | (year > BUILTIN_SPAN[1])) for year in years):
        return (f"approximate; not measured against DE421 outside {BUILTIN_SPAN[0]}-{BUILTIN_SPAN[1]}, where "
                f"this epoch lies")
    points = dict.fromkeys(name for part in parts for name in (part.body, part.center))
    worst = sum(BUILTIN_ACCURACY_KM.get(name, 0.0) for name in points)
    return f"approximate: within {worst:,.0f} km of DE421 over {BUILTIN_SPAN[0]}-{BUILTIN_SPAN[1]}"


def _relative(read: dict, target: str, origin: str, when: Time, source: str) -> "BodyState":
    """The BodyState of `target` about `origin` from barycentric states already read."""
    r, v = read[target]
    if origin != "solar system barycentre":
        r, v = r - read[origin][0], v - read[origin][1]
    named = DE421 if source == "de421" else BUILTIN
    propagated = [p for p in (target, origin) if p in PROPAGATED]
    if not propagated:
        return BodyState(target, origin, when, r, v, named)
    from orbits.ephemeris.catalogue import mean_elements

    orbits_used = [mean_elements(p) for p in propagated]
    about = "; ".join(f"{p} by two-body propagation of {el.source}" for p, el in zip(propagated, orbits_used))
    accuracy = "; ".join(f"{p} {el.accuracy}{_drift_here(p, el.epoch, when)}" for p, el in zip(propagated, orbits_used))
    return BodyState(target, origin, when, r, v, f"{about}{_OTHERS}{named}", accuracy)


def resolve_source(source: str) -> str:
    """The ephemeris that answers for `source` ("auto", "de421" or "builtin"): "de421" or "builtin"; a one-line
    OrbitDomainError for an unknown source or for DE421 without its extra."""
    if source not in SOURCES:
        raise OrbitDomainError(f"source: {source!r} is not one of {', '.join(SOURCES)}")
    if source == "auto":
        return available_source()
    if source == "de421" and available_source() != "de421":
        raise OrbitDomainError("source 'de421' needs the extra orbits[ephemeris] (skyfield-data and jplephem)")
    return source


@dataclass(frozen=True, eq=False)
class BodyState(display.Displayed):
    """Position and velocity of `body` relative to `center` at `epoch`, ICRF (equatorial J2000), SI arrays."""

    body: str
    center: str
    epoch: Time
    r_si: np.ndarray
    v_si: np.ndarray
    source: str
    #: the accuracy of a state that is not the ephemeris' own (a PROPAGATED body), said by its orbit's source
    stated_accuracy: str = ""

    @property
    def r(self) -> u.Quantity:
        """Position (m), shape epoch shape + (3,)."""
        return self.r_si << units.M

    @property
    def v(self) -> u.Quantity:
        """Velocity (m/s), shape epoch shape + (3,)."""
        return self.v_si << units.M_PER_S

    @property
    def distance(self) -> u.Quantity:
        """|r| (m)."""
        return np.linalg.norm(self.r_si, axis=-1) << units.M

    @property
    def speed(self) -> u.Quantity:
        """|v| (m/s)."""
        return np.linalg.norm(self.v_si, axis=-1) << units.M_PER_S

    @property
    def light_time(self) -> u.Quantity:
        """|r| / c (s): how long light takes from the body to the centre (geometric distance)."""
        return np.linalg.norm(self.r_si, axis=-1) / SPEED_OF_LIGHT << units.S

    @property
    def point(self) -> str:
        """What the body's position refers to: the body's centre or its system's barycentre (DE421)."""
        return self._named(self.body)

    @property
    def center_point(self) -> str:
        """What the centre's position refers to, named as `point` is."""
        return self._named(self.center)

    def _named(self, name):
        if self.source == DE421 and name in SYSTEM_BARYCENTRES:
            return f"{name} system barycentre (planet and moons)"
        return name

    @property
    def accuracy(self) -> str:
        """The source's accuracy against DE421 for this body and centre (exact for DE421 itself), or what the
        published orbit of a PROPAGATED body states."""
        if self.stated_accuracy:
            return self.stated_accuracy
        if self.source == DE421:
            return "DE421 as read by jplephem (astropy reading the same kernel agrees to 1 mm)"
        return _builtin_accuracy([self])

    @property
    def provenance(self) -> str:
        """Where the state comes from, as a title says it once: the source, and its accuracy unless it is DE421
        itself (exact as read)."""
        if self.source == DE421 and not self.stated_accuracy:
            return self.source
        return f"{self.source}; {self.accuracy}"

    def quantities(self, only: Iterable[str] | None = None) -> dict[str, u.Quantity]:
        """{name: Quantity}: distance, speed, light time and the ICRF components (or `only` those)."""
        return quantity_table(lambda name: getattr(self, name), STATE_NAMES, only)

    @property
    def x(self) -> u.Quantity:
        return self.r[..., 0]

    @property
    def y(self) -> u.Quantity:
        return self.r[..., 1]

    @property
    def z(self) -> u.Quantity:
        return self.r[..., 2]

    @property
    def vx(self) -> u.Quantity:
        return self.v[..., 0]

    @property
    def vy(self) -> u.Quantity:
        return self.v[..., 1]

    @property
    def vz(self) -> u.Quantity:
        return self.v[..., 2]

    def __repr__(self) -> str:
        """E.g. "BodyState(Mars from Sun, 2026-11-25 00:01:09.184 TDB, distance = 1.398717 AU, JPL DE421 ...)"."""
        when = f"{self.epoch.tdb.iso} TDB" if self.epoch.isscalar else f"{self.epoch.size} epochs"
        return display.one_line("BodyState", f"{self.point} from {self.center}", when,
                                "distance = " + display.summary(self.distance), self.source)


#: what BodyState.quantities() lists
STATE_NAMES = ("distance", "speed", "light_time", "x", "y", "z", "vx", "vy", "vz")


def state(body: str, when: Any, center: str = "Sun", *, source: str = "auto", scale: str = "utc") -> BodyState:
    """Position and velocity of `body` relative to `center` at `when` (Time, ISO strings or "J2000").

    Parameters
    ----------
    body, center : a planet, "Sun", "Moon", "Earth-Moon barycentre" or "solar system barycentre" (any case), or
        Ceres, Vesta, Pallas, Hygiea or Eris (PROPAGATED: the published osculating orbit carried to the epoch,
        with its accuracy).
    when : astropy Time (any scale, any shape) or ISO string(s) in `scale` (default UTC).
    source : "auto" (DE421 when installed, else the built-in), "de421" or "builtin".

    Returns a BodyState in ICRF (equatorial J2000), metres and m/s. Accuracy: see the module docstring.
    """
    target, origin = point_name(body), point_name(center)
    resolved = resolve_source(source)
    when = epoch(when, scale)
    return _relative(_read([target, origin], when, resolved), target, origin, when, resolved)


def states(bodies: Sequence[str], when: Any, center: str = "solar system barycentre", *,
           source: str = "auto", scale: str = "utc") -> dict[str, BodyState]:
    """state() of several bodies relative to one centre at the same epoch(s), by name: the epoch converted and
    checked once, each body read once."""
    targets, origin = [point_name(b) for b in bodies], point_name(center)
    resolved = resolve_source(source)
    when = epoch(when, scale)
    read = _read([*targets, origin], when, resolved)
    return {target: _relative(read, target, origin, when, resolved) for target in targets}


@dataclass(frozen=True, eq=False)
class Osculating:
    """The two-body problem of a state of a catalogue body about its parent: its position r (m) and velocity v
    (m/s) in the ecliptic frame of J2000, the GM of the point whose position that is (m3/s2; for Jupiter-Pluto,
    which DE421 gives as system barycentres, the system's: Body.barycentre_gm) and mu = GM_parent + gm (m3/s2)."""

    r: np.ndarray
    v: np.ndarray
    gm: float
    mu: float


def osculating(seen: BodyState) -> Osculating:
    """The osculating two-body problem through a state already read (state, states) of a catalogue body about its
    parent (the Sun for a planet, the Earth for the Moon): the one home of what Orbit.from_state and the
    solar-system picture draw. OrbitDomainError for a state about anything but the body's parent."""
    target = body(seen.body)
    if target.parent is None or body(target.parent).name != seen.center:
        raise OrbitDomainError(f"an orbit needs {seen.body}'s state about its parent "
                               f"({target.parent or 'none in the catalogue'}), not about {seen.center}")
    gm = target.barycentre_gm if target.name in SYSTEM_BARYCENTRES else target.gm
    return Osculating(frames.equatorial_to_ecliptic(seen.r_si), frames.equatorial_to_ecliptic(seen.v_si), gm,
                      body(target.parent).gm + gm)


def points() -> tuple[str, ...]:
    """The names the ephemeris knows."""
    return tuple(_CHAINS)


@dataclass(frozen=True, eq=False)
class Sighting(display.Displayed):
    """Where a body is as seen from an observer (default the Earth), geometric (no light-time or aberration
    correction), at one or more epochs: distances from the Sun and the observer, elongation from the Sun (the
    angle Sun-observer-body, notes XXI.xi), phase angle (Sun-body-observer), light time, ICRF right ascension
    and declination. SI arrays; `heliocentric` and `from_observer` are the two BodyStates."""

    heliocentric: BodyState
    from_observer: BodyState
    sun_from_observer: BodyState

    @property
    def sun_distance(self) -> u.Quantity:
        """|r_body - r_Sun| (m)."""
        return self.heliocentric.distance

    @property
    def observer_distance(self) -> u.Quantity:
        """|r_body - r_observer| (m)."""
        return self.from_observer.distance

    @property
    def light_time(self) -> u.Quantity:
        """|r_body - r_observer| / c (s)."""
        return self.from_observer.light_time

    @property
    def elongation(self) -> u.Quantity:
        """Angle at the observer between the Sun and the body (rad), in [0, pi]."""
        return _angle_between(self.sun_from_observer.r_si, self.from_observer.r_si) << units.RAD

    @property
    def phase_angle(self) -> u.Quantity:
        """Angle at the body between the Sun and the observer (rad), in [0, pi]."""
        return _angle_between(-self.heliocentric.r_si, -self.from_observer.r_si) << units.RAD

    @property
    def right_ascension(self) -> u.Quantity:
        """atan2(y, x) of the body from the observer, ICRF (rad), in [0, 2 pi)."""
        r = self.from_observer.r_si
        return np.mod(np.arctan2(r[..., 1], r[..., 0]), 2.0 * np.pi) << units.RAD

    @property
    def declination(self) -> u.Quantity:
        """atan2(z, sqrt(x^2 + y^2)) of the body from the observer, ICRF (rad)."""
        r = self.from_observer.r_si
        return np.arctan2(r[..., 2], np.hypot(r[..., 0], r[..., 1])) << units.RAD

    def quantities(self, only: Iterable[str] | None = None) -> dict[str, u.Quantity]:
        """{name: Quantity} of SIGHTING_NAMES (or `only` those)."""
        return quantity_table(lambda name: getattr(self, name), SIGHTING_NAMES, only)

    def __repr__(self) -> str:
        """E.g. "Sighting(Mars from Earth, ..., distance = 2.43 AU, elongation = 21.3 deg)"."""
        seen = self.from_observer
        when = f"{seen.epoch.tdb.iso} TDB" if seen.epoch.isscalar else f"{seen.epoch.size} epochs"
        return display.one_line("Sighting", f"{seen.point} from {seen.center}", when,
                                "distance = " + display.summary(self.observer_distance),
                                "elongation = " + display.summary(self.elongation.to(u.deg), digits=4))


#: what Sighting.quantities() lists
SIGHTING_NAMES = ("sun_distance", "observer_distance", "light_time", "elongation", "phase_angle",
                  "right_ascension", "declination")


def _angle_between(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Angle between vectors (rad) by atan2(|a x b|, a . b): accurate at 0 and pi, unlike arccos."""
    return np.arctan2(np.linalg.norm(np.cross(a, b), axis=-1), np.sum(a * b, axis=-1))


def where(body: str, when: Any, observer: str = "Earth", *, source: str = "auto", scale: str = "utc") -> Sighting:
    """Where `body` is at `when` as seen from `observer`: see Sighting. The body may not be the Sun or the
    observer itself."""
    target, seer = _sighting_points(body, observer)
    return sighting(states([target, seer], when, "Sun", source=source, scale=scale), target, seer)


def _sighting_points(body: str, observer: str) -> tuple[str, str]:
    target, seer = point_name(body), point_name(observer)
    if target in ("Sun", seer):
        raise OrbitDomainError(f"where: the body ({target}) must differ from the Sun and from the observer ({seer})")
    if seer == "Sun":
        raise OrbitDomainError("where: the observer must not be the Sun (elongation and phase angle are measured "
                               "from the Sun's direction); for heliocentric states use ephemeris.state(body, when, "
                               "center='Sun')")
    return target, seer


def sighting(heliocentric: dict[str, BodyState], body: str, observer: str = "Earth") -> Sighting:
    """The Sighting of `body` from `observer` out of heliocentric states already read (`states(..., center="Sun")`
    holding both), without reading the ephemeris again: body - observer and Sun - observer."""
    target, seer = _sighting_points(body, observer)
    missing = [p for p in (target, seer) if p not in heliocentric]
    if missing:
        raise OrbitDomainError(f"sighting: no heliocentric state of {', '.join(missing)} among "
                               f"{', '.join(heliocentric)}")
    body_state, seer_state = heliocentric[target], heliocentric[seer]
    if body_state.center != "Sun" or seer_state.center != "Sun":
        raise OrbitDomainError("sighting: the states must be about the Sun (ephemeris.states(..., center='Sun'))")
    when = body_state.epoch
    source, stated = provenance(body_state, seer_state)
    return Sighting(body_state,
                    BodyState(target, seer, when, body_state.r_si - seer_state.r_si,
                              body_state.v_si - seer_state.v_si, source, stated),
                    BodyState("Sun", seer, when, -seer_state.r_si, -seer_state.v_si, source, stated))
