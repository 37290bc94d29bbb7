"""Physical constants and a few named bodies, each value with its source.

G is astropy's CODATA 2018 value. Gravitational parameters are the IAU 2015 nominal values
(Resolution B3) where one exists, otherwise a JPL value (planetary ephemeris, satellite ephemerides, Horizons'
mass file, Small-Body Database) or, for Vesta, Dawn's gravity field; masses are GM / G.
Heliocentric elements are the J2000 mean elements of Standish (1992), "Keplerian Elements for
Approximate Positions of the Major Planets", Table 1 (ecliptic and equinox of J2000).
"""

import math
from dataclasses import dataclass
from typing import Any

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
    """Osculating-like mean elements of a body about its primary (SI, radians) at `epoch` (Julian date, TDB), in
    the ecliptic and equinox of J2000, or (`pole` = (ra, dec), rad) in the plane with that ICRF pole, the node
    counted from its ascending node on the ICRF equator (orbits.ephemeris.catalogue); `accuracy` says how well."""

    primary: str
    a: float
    e: float
    inc: float
    raan: float
    argp: float
    mean_anomaly: float
    source: str
    epoch: float = 2451545.0
    pole: tuple[float, float] | None = None
    accuracy: str = ""


@dataclass(frozen=True)
class Body:
    """A named body: GM (m3/s2), mass (kg), equatorial radius (m), sidereal rotation period (s), each sourced.

    `gm` is the body alone (what an orbit about it feels); `system_gm` the body with its moons (what its
    barycentre carries, and what DE421's Jupiter-Pluto points stand for), where it differs. Eris is the one
    exception: only its system's mass is published (Dysnomia's is not separated), so both are that mass. `parent` is the
    body it orbits (None for the Sun), `kind` one of KINDS, `j2` the unnormalised second zonal harmonic at the
    reference radius `j2_radius` (m) where one is published, `orbit` J2000 mean elements where the catalogue has
    them. A retrograde rotator (Venus, Uranus, Pluto, Triton's primary aside) has `retrograde=True`; the period
    is always positive.
    """

    name: str
    gm: float
    radius: float
    rotation_period: float
    source: str
    orbit: MeanElements | None = None
    parent: str | None = None
    kind: str = "planet"
    j2: float | None = None
    j2_radius: float | None = None
    retrograde: bool = False
    system_gm: float | None = None
    #: the third to sixth zonal harmonics at j2_radius, where the catalogue has them (the Earth)
    j3: float | None = None
    j4: float | None = None
    j5: float | None = None
    j6: float | None = None

    @property
    def mass(self) -> float:
        """M = GM / G (kg)."""
        return self.gm / G

    @property
    def barycentre_gm(self) -> float:
        """GM (m3/s2) of the body and its moons: system_gm where the catalogue has one, else gm."""
        return self.gm if self.system_gm is None else self.system_gm


#: the kinds of body in the catalogue
KINDS = ("star", "planet", "dwarf planet", "asteroid", "moon")

_DAY = 86_400.0
_KM = 1e3
_KM3 = 1e9  # km3/s2 -> m3/s2

_IAU2015 = "IAU 2015 Resolution B3 nominal value"
_DE430 = "JPL DE430, Folkner et al. (2014), IPN Progress Report 42-196, Table 8"
_WGCCRE = "IAU WGCCRE 2015, Archinal et al. (2018), Celest. Mech. Dyn. Astr. 130:22"
_HORIZONS = ("JPL Horizons mass file gm_Horizons.pck, version 3.0 of 2017-05-09 (J. Giorgini): planets alone from "
             "the satellite ephemerides MAR097, JUP340, SAT393, URA111, NEP081, PLU055")
_HORIZONS_MOON = _HORIZONS.replace("planets alone", "moons")
#: the later mass file, read in two copies: JPL's gm_Horizons.pck revision of 2025-01-29 and the 2021-09-30 one
#: that REBOUND 5.2.2 carries (rebound/horizons.py, HORIZONS_MASS_DATA); its asteroids 2000001-2000704 are
#: "SB441-N16 small-body integration perturber file (DE441 masses)", the masses DE440 uses too
_HORIZONS_2025 = ("JPL Horizons mass file gm_Horizons.pck, version 4 (J. Giorgini), revision of 2025-01-29: "
                  "{what}")
_DE441_ASTEROID = _HORIZONS_2025.format(what="DE440/DE441 small-body perturber mass (SB441-N16)")
_STANDISH = "Standish (1992) J2000 mean elements, Table 1 (valid 1800-2050)"


def _deg(x):
    return math.radians(x)


def _standish(a_au, e, inc, mean_longitude, perihelion_longitude, node):
    """Mean elements about the Sun from Standish's a (AU), e, I, L, long. perihelion and long. node (deg),
    ecliptic and equinox of J2000: argp = varpi - Omega, M = L - varpi."""
    return MeanElements("Sun", a_au * AU, e, _deg(inc), _deg(node % 360.0),
                        _deg((perihelion_longitude - node) % 360.0),
                        _deg((mean_longitude - perihelion_longitude) % 360.0),
                        _STANDISH)


def _planet(name, gm, gm_source, radius_km, rotation_days, rotation_source, orbit, *, j2=None, j2_radius_km=None,
            j2_source="", retrograde=False, kind="planet", system_gm_km3=None):
    source = f"GM: {gm_source}; radius: {_WGCCRE if name != 'Earth' else _IAU2015}; rotation: {rotation_source}"
    if j2 is not None:
        source += f"; J2: {j2_source}"
    if system_gm_km3 is not None:
        source += f"; system GM: {_DE430}"
    return Body(name, gm, radius_km * _KM, rotation_days * _DAY, source, orbit, "Sun", kind, j2,
                None if j2_radius_km is None else j2_radius_km * _KM, retrograde,
                None if system_gm_km3 is None else system_gm_km3 * _KM3)


def _moon(name, parent, gm_km3, radius_km, rotation_days, gm_source=_HORIZONS_MOON, kind="moon"):
    """A synchronously rotating moon (rotation period = orbital period), GM in km3/s2, mean radius in km."""
    source = f"GM: {gm_source}; mean radius: {_WGCCRE}; rotation: synchronous, the sidereal orbital period"
    return Body(name, gm_km3 * _KM3, radius_km * _KM, rotation_days * _DAY, source, None, parent, kind)


_CATALOGUE = [
    Body("Sun", 1.3271244e20, 6.957e8, 25.38 * _DAY,
         f"GM and radius: {_IAU2015}; rotation: Carrington period 25.38 d", None, None, "star"),
    _planet("Mercury", 22_031.78 * _KM3, _DE430, 2440.53, 58.6462, "WGCCRE 2015 (6.1385108 deg/d)",
            _standish(0.38709927, 0.20563593, 7.00497902, 252.25032350, 77.45779628, 48.33076593)),
    _planet("Venus", 324_858.592 * _KM3, _DE430, 6051.8, 243.0185, "WGCCRE 2015 (-1.4813688 deg/d)",
            _standish(0.72333566, 0.00677672, 3.39467605, 181.97909950, 131.60246718, 76.67984255), retrograde=True,
            # J2 = -sqrt(5) C20 from the normalised C20 = -.1969723357760000E-05 of the file, at its 6051 km
            j2=math.sqrt(5.0) * 1.969723357760e-6, j2_radius_km=6051.0,
            j2_source="MGNP180U, Konopliv et al. (1999), Icarus 139; PDS MGN-V-RSS-5-GRAVITY-L2-V1.0 file SHGJ180U.A01 "
                      "(normalised C20 = -1.96972335776e-6 at the 6051.0 km reference radius; J2 = -sqrt(5) C20)"),
    Body("Earth", 3.986004e14, 6.3781e6, SIDEREAL_DAY,
         f"GM and equatorial radius: {_IAU2015}; rotation: IERS sidereal day; J2: IERS Conventions (2010), Table 1.1; "
         "J3 to J6: EGM2008 (Pavlis et al. 2012, JGR 117, B04406), J_n = -sqrt(2n + 1) C_n0 from its normalised "
         "C30 = 9.57161207093473e-7, C40 = 5.39965866638991e-7, C50 = 6.86702913736681e-8 and "
         "C60 = -1.49953927978527e-7 at 6378136.3 m, rescaled to 6378136.6 m; "
         f"system GM (Earth and Moon): {_DE430}",
         MeanElements("Sun", 1.00000261 * AU, 0.01671123, _deg(0.00001531), _deg(180.0),
                      _deg(102.93768193 - 180.0 + 360.0), _deg(100.46457166 - 102.93768193),
                      _STANDISH + ", Earth-Moon barycentre (I = -0.00001531 deg written as +I with the node at 180)"),
         "Sun", "planet", 1.0826359e-3, 6_378_136.6, system_gm=403_503.235502259810 * _KM3,
         j3=-math.sqrt(7.0) * 9.57161207093473e-7 * (6_378_136.3 / 6_378_136.6) ** 3,
         j4=-3.0 * 5.39965866638991e-7 * (6_378_136.3 / 6_378_136.6) ** 4,
         j5=-math.sqrt(11.0) * 6.86702913736681e-8 * (6_378_136.3 / 6_378_136.6) ** 5,
         j6=math.sqrt(13.0) * 1.49953927978527e-7 * (6_378_136.3 / 6_378_136.6) ** 6),
    _planet("Mars", 42_828.37362069909 * _KM3, _HORIZONS, 3396.19, 1.02595676,
            "WGCCRE 2015 (350.891982 deg/d)",
            _standish(1.52371034, 0.09339410, 1.84969142, -4.55343205, -23.94362959, 49.55953891),
            j2=1.95545e-3, j2_radius_km=3396.0, j2_source="Konopliv et al. (2016), MRO120D, Icarus 274",
            system_gm_km3=42_828.375214),
    Body("Jupiter", 1.2668653e17, 7.1492e7, 9.925 * 3600.0,
         f"GM and equatorial radius: {_IAU2015}; rotation: System III 9.925 h; J2: Iess et al. (2018), Nature 555; "
         f"system GM: {_DE430}",
         _standish(5.20288700, 0.04838624, 1.30439695, 34.39644051, 14.72847983, 100.47390909),
         "Sun", "planet", 14_696.572e-6, 71_492e3, system_gm=126_712_764.8 * _KM3),
    _planet("Saturn", 37_931_207.23493890 * _KM3, _HORIZONS, 60268.0, 10.656222 / 24.0,
            "WGCCRE 2015 System III (810.7939024 deg/d)",
            _standish(9.53667594, 0.05386179, 2.48599187, 49.95424423, 92.59887831, 113.66242448),
            j2=16_290.573e-6, j2_radius_km=60330.0, j2_source="Iess et al. (2019), Science 364",
            system_gm_km3=37_940_585.2),
    _planet("Uranus", 5_793_951.322279009 * _KM3, _HORIZONS, 25559.0, 17.24 / 24.0,
            "WGCCRE 2015 (-501.1600928 deg/d)",
            _standish(19.18916464, 0.04725744, 0.77263783, 313.23810451, 170.95427630, 74.01692503),
            j2=3510.68e-6, j2_radius_km=25559.0, j2_source="Jacobson (2014), AJ 148:76 (URA111), at 25,559 km",
            retrograde=True,
            system_gm_km3=5_794_548.6),
    _planet("Neptune", 6_835_099.502439672 * _KM3, _HORIZONS, 24764.0, 16.11 / 24.0,
            "WGCCRE 2015 (536.3128492 deg/d)",
            _standish(30.06992276, 0.00859048, 1.77004347, -55.12002969, 44.96476227, 131.78422574),
            j2=3408.43e-6, j2_radius_km=25225.0,
            j2_source="Jacobson (2009), AJ 137:4322 (NEP081), at 25,225 km, not the 24,764 km equatorial radius",
            system_gm_km3=6_836_527.10058),
    _planet("Pluto", 869.3390780381926 * _KM3, _HORIZONS, 1188.3, 6.3872273,
            "WGCCRE 2015 (-56.3625225 deg/d)",
            _standish(39.48211675, 0.24882730, 17.14001206, 238.92903833, 224.06891629, 110.30393684),
            retrograde=True, kind="dwarf planet",
            system_gm_km3=977.0),
    # 62.6284 was cited to Park et al. (2016), Nature 537 (Dawn) before; that attribution is not re-checked here
    Body("Ceres", 62.6284 * _KM3, 469.7e3, 9.074170 / 24.0 * _DAY,
         "GM: the JPL Small-Body Database value as JPL Horizons prints it for 1 Ceres ('GM= 62.6284', with "
         "'RAD= 469.7', 'ROTPER= 9.07417'; Horizons output of 2022-07-07); mean radius and rotation "
         f"(952.1532635 deg/d): {_WGCCRE}",
         None, "Sun", "dwarf planet"),
    # VESTA20H's GM to all its digits; the catalogue had 17.288245 km3/s2, 1.8e-9 from it
    Body("Vesta", 17.2882449693 * _KM3, 262.7e3, 5.342128 / 24.0 * _DAY,
         "GM: Konopliv et al. (2014), Icarus 240 (Dawn), the VESTA20H gravity field's GM, 17,288,244,969.3 m3/s2 "
         f"(as pyshtools.constants.Vesta carries it); mean radius and rotation (1617.3329428 deg/d): {_WGCCRE}",
         None, "Sun", "asteroid"),
    # the largest asteroids after Ceres and Vesta; radii are volume-equivalent, like Ceres' and Vesta's mean radii
    Body("Pallas", 13.665878145967422 * _KM3, (275.0 * 258.0 * 238.0) ** (1.0 / 3.0) * _KM, 360.0 / 1105.8036 * _DAY,
         f"GM: {_DE441_ASTEROID}, BODY2000002_GM; radius: volume-equivalent (abc)**(1/3) = 256.6 km of the "
         "triaxial-ellipsoid radii a = 275, b = 258, c = 238 km of Carry et al. (2010), Icarus 205 (arXiv:0912.3626); "
         "rotation: the IAU WGCCRE prime meridian W = 38 + 1105.8036 d deg (a 7.8132 h period), as a port of NAIF's "
         "T_PCKANG test routine codes it",
         None, "Sun", "asteroid"),
    Body("Hygiea", 5.6251476453852289 * _KM3, 217e3, 13.8 / 24.0 * _DAY,
         f"GM: {_DE441_ASTEROID}, BODY2000010_GM; volume-equivalent radius 217 +- 7 km and rotation period 13.8 h "
         "(half the earlier 27.6 h; sense of rotation not checked): Vernazza et al. (2020), Nature Astronomy, "
         "doi:10.1038/s41550-019-0915-8 (VLT/SPHERE)",
         None, "Sun", "asteroid"),
    # gm_Horizons.pck gives Eris the whole system mass (Dysnomia's GM set to 0 there)
    Body("Eris", 1098.9 * _KM3, 1163e3, 15.786 * _DAY,
         "GM: " + _HORIZONS_2025.format(what="BODY920136199_GM = 1.0989E+03, the Eris system mass of Brozovic, JPL "
                                             "IOM 392R-22-003 (2022-09-01), all given to Eris (Dysnomia's GM 0)")
         + "; radius: Sicardy et al. (2011), Nature 478; rotation: Szakats et al. (2023), A&A 669 (synchronous with "
         "Dysnomia)", None, "Sun", "dwarf planet", system_gm=1098.9 * _KM3),
    Body("Moon", 4_902.8000661637961 * _KM3, 1.7374e6, 27.321661 * _DAY,
         f"GM: {_DE430}; radius: {_WGCCRE}; rotation: synchronous, the sidereal month 27.321661 d; J2: the Lunar "
         "Prospector field LP150Q, Konopliv et al. (2001), Icarus 150; PDS LP-L-RSS-5-GRAVITY-V1 file JGL150Q1 "
         "(normalised C20 = -9.09010949481e-5 at the 1738 km reference radius; J2 = -sqrt(5) C20)",
         MeanElements("Earth", 3.84399e8, 0.0549, _deg(5.145), 0.0, 0.0, 0.0,
                      "NASA Moon fact sheet mean orbit (node and periapsis precess; set to 0)",
                     accuracy="Kepler period from a and the two GMs 0.14 % short of the sidereal month, 27.3217 "
                              "d (the Sun's pull lengthens it)"),
         # J2 = -sqrt(5) C20 from the normalised C20 = -.9090109494810000E-04 of JGL150Q1, at its 1738 km
         "Earth", "moon", math.sqrt(5.0) * 9.09010949481e-5, 1_738e3),
    _moon("Phobos", "Mars", 7.087546066894452e-4, 11.08, 0.31891023),
    _moon("Deimos", "Mars", 9.615569648120313e-5, 6.2, 1.26244),
    _moon("Io", "Jupiter", 5959.924010272514, 1821.49, 1.769137786),
    _moon("Europa", "Jupiter", 3202.739815114734, 1560.8, 3.551181041),
    _moon("Ganymede", "Jupiter", 9887.819980080976, 2631.2, 7.15455296),
    _moon("Callisto", "Jupiter", 7179.304867611079, 2410.3, 16.6890184),
    _moon("Titan", "Saturn", 8978.137030983542, 2575.0, 15.945421),
    _moon("Triton", "Neptune", 1427.598140725034, 1352.6, 5.876854),
    _moon("Charon", "Pluto", 106.2509269522026, 606.0, 6.3872273),
]

#: the catalogue, by name: the Sun, the planets, dwarf planets and large asteroids, the Moon and major moons
BODIES = {b.name: b for b in _CATALOGUE}


def body(name: str) -> Body:
    """The named body (case-insensitive); UnknownNameError (a KeyError) naming the close matches otherwise."""
    key = str(name).strip().lower()
    for known, value in BODIES.items():
        if known.lower() == key:
            return value
    raise UnknownNameError.among("unknown body", name, list(BODIES))


def body_with_gm(gm: Any, tolerance: float = 0.0) -> Body | None:
    """The catalogue body whose GM is `gm` (m3/s2, every element the same) within the relative `tolerance`, the
    closest if several, else None. tolerance 0 names a body only for its own GM (a repr's "about Earth"); 0.02
    also finds the primary of a two-body mu such as G (M_Sun + M_Jupiter) (no two catalogue GMs lie within 10 %
    of each other)."""
    import numpy as np

    values = np.unique(np.asarray(gm, dtype=float))
    if values.size != 1 or not np.isfinite(values[0]) or values[0] <= 0:
        return None
    value = float(values[0])
    misses = {name: abs(value / known.gm - 1.0) for name, known in BODIES.items()}
    name = min(misses, key=misses.get)
    return BODIES[name] if misses[name] <= tolerance else None


def pair_with_gm(gm: Any) -> tuple[Body, Body] | None:
    """(parent, body) of the catalogue pair whose two GMs sum to `gm` exactly (every element the same): the mu of a
    moon's two-body orbit about its planet, G (M_parent + M_body); else None."""
    import numpy as np

    values = np.unique(np.asarray(gm, dtype=float))
    if values.size != 1:
        return None
    for known in BODIES.values():
        if known.parent is not None and BODIES[known.parent].gm + known.gm == values[0]:
            return BODIES[known.parent], known
    return None
