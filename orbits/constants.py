"""Physical constants and a few named bodies, each value with its source.

G is astropy's CODATA 2018 value. Gravitational parameters are the IAU 2015 nominal values
(Resolution B3) where one exists, otherwise the JPL planetary ephemeris value; masses are GM / G.
Heliocentric elements are the J2000 mean elements of Standish (1992), "Keplerian Elements for
Approximate Positions of the Major Planets", Table 1 (ecliptic and equinox of J2000).
"""

import math
from dataclasses import dataclass

import astropy.constants as const

from orbits.core.errors import UnknownNameError

#: Newtonian constant of gravitation (m3 / (kg s2)), CODATA 2018 via astropy.
G = const.G.si.value

#: Astronomical unit (m), IAU 2012 Resolution B2 (exact).
AU = 149_597_870_700.0

#: Sidereal day (s), IERS Conventions (2010).
SIDEREAL_DAY = 86_164.0905

#: Standard gravity (m / s2), CGPM 1901 (exact), as in the notes (XIX.vii).
STANDARD_GRAVITY = 9.80665

#: Speed of light in vacuum (m / s), exact by the SI definition of the metre (astropy.constants.c).
SPEED_OF_LIGHT = const.c.si.value

#: Earth's mean radius (m) as the notes use it (XXI.ix, R = 6371 km): the IUGG mean radius R1 = 6371.0088 km
#: of the GRS 80 ellipsoid (Moritz, Geodetic Reference System 1980, J. Geodesy 74, 2000) rounded to 1 km.
EARTH_MEAN_RADIUS = 6_371_000.0


@dataclass(frozen=True)
class MeanElements:
    """Osculating-like mean elements of a body about its primary (SI, radians)."""

    primary: str
    a: float
    e: float
    inc: float
    raan: float
    argp: float
    mean_anomaly: float
    source: str


@dataclass(frozen=True)
class Body:
    """A named body: GM (m3/s2), mass (kg), equatorial radius (m), sidereal rotation (s), each sourced."""

    name: str
    gm: float
    radius: float
    rotation_period: float
    source: str
    orbit: MeanElements | None = None

    @property
    def mass(self) -> float:
        """M = GM / G (kg)."""
        return self.gm / G


def _deg(x):
    return math.radians(x)


_STANDISH = "Standish (1992) J2000 mean elements, Table 1"

BODIES = {
    "Sun": Body(
        "Sun",
        1.3271244e20,
        6.957e8,
        25.38 * 86400.0,
        "GM and radius: IAU 2015 Resolution B3 nominal values; rotation: Carrington period 25.38 d",
    ),
    "Earth": Body(
        "Earth",
        3.986004e14,
        6.3781e6,
        SIDEREAL_DAY,
        "GM and equatorial radius: IAU 2015 Resolution B3 nominal values; rotation: IERS sidereal day",
        MeanElements(
            "Sun",
            1.00000261 * AU,
            0.01671123,
            _deg(0.00001531),
            _deg(180.0),
            _deg(102.93768193 - 180.0 + 360.0),
            _deg(100.46457166 - 102.93768193),
            _STANDISH,
        ),
    ),
    "Moon": Body(
        "Moon",
        4.9028000661e12,
        1.7374e6,
        27.321661 * 86400.0,
        "GM: JPL DE421 (Folkner et al. 2008); radius and sidereal month: NASA Moon fact sheet",
        MeanElements(
            "Earth",
            3.84399e8,
            0.0549,
            _deg(5.145),
            0.0,
            0.0,
            0.0,
            "NASA Moon fact sheet mean orbit (node and periapsis precess; set to 0)",
        ),
    ),
    "Jupiter": Body(
        "Jupiter",
        1.2668653e17,
        7.1492e7,
        9.925 * 3600.0,
        "GM and equatorial radius: IAU 2015 Resolution B3 nominal values; rotation: System III 9.925 h",
        MeanElements(
            "Sun",
            5.20288700 * AU,
            0.04838624,
            _deg(1.30439695),
            _deg(100.47390909),
            _deg(14.72847983 - 100.47390909 + 360.0),
            _deg(34.39644051 - 14.72847983),
            _STANDISH,
        ),
    ),
}


def body(name: str) -> Body:
    """The named body (case-insensitive); KeyError listing the known names otherwise."""
    for key, value in BODIES.items():
        if key.lower() == str(name).lower():
            return value
    raise UnknownNameError(f"unknown body {name!r}; known bodies: {', '.join(BODIES)}")
