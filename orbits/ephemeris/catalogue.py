"""Published orbits of the catalogue bodies that the planetary mean elements of orbits._common.constants leave out.

Each set is a MeanElements (orbits._common.constants) with its source, epoch, reference frame and accuracy:

- **Dwarf planets and asteroids**: osculating heliocentric elements at their epoch (ecliptic and equinox of J2000,
  about the Sun alone), as JPL's Horizons and Small-Body Database or the Minor Planet Center publish them.
  Propagated as a two-body orbit they drift from the true path as the planets pull, by up to DRIFT_KM_PER_YEAR[name]
  km per year of distance from the epoch: the worst measured from 0.1 to 25 years before and after it (farther
  away it is not measured) against an integration of the body with the Sun and the eight planets (JPL DE421
  states at the epoch, rebound IAS15), which carries JPL's Ceres of 2020 to within 35 km of Horizons' Ceres
  of 2025 (tests/api/test_catalogue_orbits.py).
- **Moons**: JPL's planetary satellite mean elements, the elements of a precessing ellipse fitted to JPL's
  numerically integrated orbits, referred to each moon's Laplace plane (pole right ascension and declination in
  the ICRF; the node counted from that plane's ascending node on the ICRF equator), or Charon's two-body orbit of
  Buie, Tholen and Grundy (2012) in the equator and equinox of J2000. They describe the orbit's size, shape and
  orientation; not where the moon is at another date (the apsides and nodes precess in months to decades), so
  no ephemeris is made from them.

`mean_elements(name)` is the one place that says which orbit a body has: the planets', Pluto's and the Moon's from
orbits._common.constants, the others from here.
"""

import math

import numpy as np

from orbits._common.constants import AU, MeanElements, body
from orbits.core import frames
from orbits.core.errors import OrbitDomainError
from orbits.core.twobody import anomalies, elements

_DAY = 86_400.0
#: the Sun's GM of JPL's osculating elements (Horizons' "Keplerian GM", k**2 = 2.9591220828411951e-4 au3/d2)
JPL_SUN_GM = 2.9591220828411951e-4 * AU**3 / _DAY**2
#: Julian dates (TDB; the satellite tables' TT differs by under 2 ms) of the epochs used below
_JD_1950 = 2433282.5  # 1950 Jan 1.00
_JD_1997 = 2450464.5  # 1997 Jan 16.00
_JD_2002 = 2452600.5  # 2002 Nov 22.00
_JD_2025 = 2460787.0  # 2025 Apr 21.50
_JD_2014 = 2457000.5  # 2014 Dec 9.00
_JD_2025_NOV = 2461000.5  # 2025 Nov 21.00
_JD_2006 = 2453800.5  # 2006 Mar 6.00

#: how far (km per year from the epoch) each small body's two-body orbit strays from an integration with the planets,
#: the worst over 0.1 to 25 years each way at outputs half a month apart (measured 8.57e5 for Ceres, 7.85 years
#: before its epoch; 5.62e5 Vesta; 7.86e5 Pallas; 2.42e6 Hygiea, whose epoch finds it near Jupiter's longitude;
#: 5.25e5 Eris). Against JPL's other solutions Ceres strays 4.9e5 km after 5.3 yr and 7.6e6 km after 18.5 yr
DRIFT_MEASURED_YEARS = 25.0
DRIFT_KM_PER_YEAR = {"Ceres": 8.6e5, "Vesta": 5.7e5, "Pallas": 7.9e5, "Hygiea": 2.5e6, "Eris": 5.3e5}


def _deg(x: float) -> float:
    return math.radians(x)


def _from_icrf_state(r_au, v_au_per_day, epoch, source, accuracy):
    """The osculating heliocentric elements (ecliptic J2000, about JPL_SUN_GM) of a JPL ICRF state (au, au/d)."""
    r = frames.equatorial_to_ecliptic(np.array(r_au) * AU)
    v = frames.equatorial_to_ecliptic(np.array(v_au_per_day) * AU / _DAY)
    p, e, inc, node, argp, nu = (float(x) for x in elements.state_to_elements(r, v, JPL_SUN_GM))
    mean_anomaly = float(np.mod(anomalies.mean_from_true(nu, e), 2.0 * math.pi))
    return MeanElements("Sun", p / (1.0 - e * e), e, inc, node % (2 * math.pi), argp % (2 * math.pi), mean_anomaly,
                        source, epoch, None, accuracy)


def _from_elements(a_au, e, inc, node, argp, mean_anomaly, epoch, source, accuracy):
    """Published osculating heliocentric elements (a in au, angles in deg; ecliptic J2000, about JPL_SUN_GM)."""
    return MeanElements("Sun", a_au * AU, e, _deg(inc), _deg(node), _deg(argp), _deg(mean_anomaly), source, epoch,
                        None, accuracy)


def _small_body_accuracy(name: str, epoch: str, at_epoch: str = "exact") -> str:
    """How well the two-body orbit of `name` holds: `at_epoch` (what the published digits allow) and its drift."""
    return _SMALL_BODY_ACCURACY.format(at_epoch=at_epoch, epoch=epoch, drift=DRIFT_KM_PER_YEAR[name],
                                       years=DRIFT_MEASURED_YEARS)


def _laplace(primary, a_km, e, argp, mean_anomaly, inc, node, pole_ra, pole_dec, epoch, source, accuracy):
    """JPL satellite mean elements (a in km, angles in deg) on the Laplace plane whose pole is (pole_ra, pole_dec)
    (deg, ICRF) at `epoch` (JD)."""
    return MeanElements(primary, a_km * 1e3, e, _deg(inc), _deg(node), _deg(argp), _deg(mean_anomaly), source, epoch,
                        (_deg(pole_ra), _deg(pole_dec)), accuracy)


_SMALL_BODY_ACCURACY = ("{at_epoch} at {epoch}; away from it off by up to {drift:,.0f} km more per year (the "
                        "planets' pull, measured against an integration with them over {years:g} years each way)")
_MARS_SATS = "JPL satellite mean elements on the Laplace plane, solution MAR080, epoch 1950-01-01 TT"
_JUPITER_SATS = "JPL satellite mean elements on the Laplace plane, epoch 1997-01-16 TT"
_MOON_ACCURACY = ("Kepler period from a and the GMs within {error} of the published {period} d (the planet's "
                  "oblateness, a rounded); the apsides and nodes precess: no position at another date")

_ORBITS = {
    # Horizons' heliocentric ICRF states at 2025-04-21 12:00 TDB (au, au/d): 1 Ceres (solution JPL#48), 4 Vesta
    "Ceres": _from_icrf_state([2.727955368904768, -7.824235389148068e-1, -9.244287343918847e-1],
                              [3.404362861965615e-3, 8.322702821554456e-3, 3.232500291084344e-3], _JD_2025,
                              "the osculating orbit of JPL Horizons' state of 2025-04-21 12:00 TDB (JPL#48)",
                              _small_body_accuracy("Ceres", "2025-04-21 12:00 TDB")),
    # Horizons' heliocentric ICRF state of 4 Vesta at 2025-04-21 12:00 TDB (solution JPL#36), au and au/d
    "Vesta": _from_icrf_state([-1.70317472297052, -1.333843040283118, -3.086709149679688e-1],
                              [7.882762615954012e-3, -8.079478592200335e-3, -4.254433056153772e-3], _JD_2025,
                              "the osculating orbit of JPL Horizons' state of 2025-04-21 12:00 TDB (JPL#36)",
                              _small_body_accuracy("Vesta", "2025-04-21 12:00 TDB")),
    # osculating heliocentric elements (ecliptic J2000): a (au), e, i, node, argument of perihelion, M (deg)
    "Pallas": _from_elements(2.77160611, 0.23127363, 34.840998, 173.096248, 309.930328, 78.228704, _JD_2014,
                             "JPL Small-Body Database osculating elements of 2 Pallas at 2014-12-09.0 TDB",
                             _small_body_accuracy("Pallas", "2014-12-09.0 TDB", "within 10 km (the digits given)")),
    "Hygiea": _from_elements(3.1475914, 0.1082238, 3.83294, 283.12164, 312.60583, 216.69031, _JD_2025_NOV,
                             "Minor Planet Center osculating elements of (10) Hygiea at 2025-11-21.0 TT",
                             _small_body_accuracy("Hygiea", "2025-11-21.0 TT", "within 100 km (the digits given)")),
    "Eris": _from_elements(67.67, 0.44177, 44.187, 35.8696, 151.4305, 197.63427, _JD_2006,
                           "JPL Small-Body Database osculating elements of 136199 Eris at 2006-03-06.0 TDB (a "
                           "to 4 digits)", _small_body_accuracy("Eris", "2006-03-06.0 TDB",
                                                                 "within 1.1 million km (a rounded to 0.01 au)")),
    "Phobos": _laplace("Mars", 9376.0, 0.0151, 150.057, 91.059, 1.075, 207.784, 317.671, 52.893, _JD_1950,
                       _MARS_SATS, _MOON_ACCURACY.format(error="0.05 %", period=0.3189)),
    "Deimos": _laplace("Mars", 23458.0, 0.0002, 260.729, 325.329, 1.788, 24.525, 316.657, 53.529, _JD_1950,
                       _MARS_SATS, _MOON_ACCURACY.format(error="0.05 %", period=1.2624)),
    "Io": _laplace("Jupiter", 421800.0, 0.0041, 84.129, 342.021, 0.036, 43.977, 268.057, 64.495, _JD_1997,
                   _JUPITER_SATS, _MOON_ACCURACY.format(error="0.05 %", period=1.769)),
    "Europa": _laplace("Jupiter", 671100.0, 0.0094, 88.970, 171.016, 0.466, 219.106, 268.084, 64.506, _JD_1997,
                       _JUPITER_SATS, _MOON_ACCURACY.format(error="0.05 %", period=3.551)),
    "Ganymede": _laplace("Jupiter", 1070400.0, 0.0013, 192.417, 317.540, 0.177, 63.552, 268.168, 64.543, _JD_1997,
                         _JUPITER_SATS, _MOON_ACCURACY.format(error="0.05 %", period=7.155)),
    "Callisto": _laplace("Jupiter", 1882700.0, 0.0074, 52.643, 181.408, 0.192, 298.848, 268.639, 64.749, _JD_1997,
                         _JUPITER_SATS, _MOON_ACCURACY.format(error="0.05 %", period=16.69)),
    # e = 0: the argument of periapsis is 0 and the mean anomaly is the mean longitude L less the node; the frame is
    # the equator and equinox of J2000, the pole (270 deg, 90 deg) in the convention of the Laplace planes above
    "Charon": MeanElements("Pluto", 19573e3, 0.0, _deg(96.218), 3.89249, 0.0, (4.50177 - 3.89249) % (2 * math.pi),
                           "Buie, Tholen and Grundy (2012), AJ 144:15, 'The orbit of Charon is circular': P = "
                           "6.3872273 d, a = 19573 km, e = 0, i = 96.218 deg, L = 4.50177 rad, node 3.89249 rad, "
                           "epoch JD 2452600.5 TDB, J2000 equatorial frame",
                           _JD_2002, (_deg(270.0), _deg(90.0)),
                           "a to 2 km, i to 0.008 deg, node and L to 0.0002 rad (the paper's errors); the Kepler "
                           "period from a and the catalogue's GMs within 0.2 % of 6.3872273 d"),
}


def mean_elements(name: str) -> MeanElements:
    """The published orbit of the catalogue body `name` (any case) about its parent: the planets', Pluto's and the
    Moon's J2000 mean elements (orbits._common.constants), or the osculating and satellite mean elements above.
    OrbitDomainError for a body without one (Titan, Triton; the Sun)."""
    named = body(name)
    if named.orbit is not None:
        return named.orbit
    if named.name in _ORBITS:
        return _ORBITS[named.name]
    raise OrbitDomainError(f"{named.name} has no published orbit in the catalogue; give its elements (orbits orbit "
                           f"--primary {named.parent or 'Sun'} --a ... --e ...)" if named.parent else
                           f"{named.name} orbits nothing in the catalogue")


def reference_to_ecliptic(x: np.ndarray, pole: tuple[float, float] | None) -> np.ndarray:
    """Vectors (..., 3) from a MeanElements' reference frame to the ecliptic of J2000: unchanged for the ecliptic
    (pole None); for a plane whose pole is (ra, dec) in the ICRF, x_icrf = R3(ra + 90 deg) R1(90 deg - dec) x, the
    x axis toward the plane's ascending node on the ICRF equator, then frames.equatorial_to_ecliptic."""
    if pole is None:
        return np.asarray(x, dtype=float)
    ra, dec = pole
    node, tilt = ra + 0.5 * math.pi, 0.5 * math.pi - dec
    cn, sn, ct, st = math.cos(node), math.sin(node), math.cos(tilt), math.sin(tilt)
    rotation = np.array([[cn, -sn * ct, sn * st], [sn, cn * ct, -cn * st], [0.0, st, ct]])
    return frames.equatorial_to_ecliptic(np.asarray(x, dtype=float) @ rotation.T)
