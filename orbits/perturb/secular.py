"""Perturbed orbits with astropy units: an oblate body's secular rates and the orbit designs built on them, drag
decay in an exponential atmosphere, the Kozai-Lidov oscillation and general relativity's periapsis advance.

    >>> import astropy.units as u
    >>> from orbits import Orbit
    >>> from orbits.perturb.secular import SecularOrbit, sun_synchronous
    >>> iss = SecularOrbit.of(Orbit.circular("Earth", 6778 * u.km, inc=51.64 * u.deg))
    >>> iss.node_rate.to(u.deg / u.day).round(3)
    <Quantity -4.998 deg / d>
    >>> sun_synchronous("Earth", altitude=700 * u.km).inclination.to(u.deg).round(2)
    <Quantity 98.19 deg>

Every rate is first order: good to O(J2 (R/p)**2) relative (the `accuracy` of a SecularOrbit), the size of the
short-period terms that separate osculating from mean elements and of the neglected J2**2 and J4 terms. The closed
forms are those of orbits.core.perturb.oblateness, drag, third_body and relativity; `orbits validate` checks each
against
rebound and heyoka integrating the forces themselves (orbits.validate.perturb).
"""

import math
from collections.abc import Iterable
from dataclasses import dataclass
from functools import cached_property

import astropy.units as u
import numpy as np

from orbits._common import display, inputs, units
from orbits._common.constants import SPEED_OF_LIGHT, Body, body, body_with_gm
from orbits._common.tables import quantity_table
from orbits.core.checks import check_finite
from orbits.core.errors import OrbitDomainError
from orbits.core.perturb import drag, oblateness, relativity, third_body
from orbits.twobody.orbit import Orbit

DAY = 86_400.0
CRITICAL_INCLINATIONS = tuple(x * u.rad for x in oblateness.CRITICAL_INCLINATIONS)
KOZAI_CRITICAL_INCLINATION = third_body.CRITICAL_INCLINATION * u.rad


def oblate_body(primary: Body | str) -> Body:
    """The catalogue Body of `primary`, checked to have J2; one-line error naming the bodies that do."""
    named = body(primary) if isinstance(primary, str) else primary
    if not isinstance(named, Body):
        raise TypeError(f"{primary!r} is not a catalogue body; give J2 and its reference radius instead")
    if named.j2 is None:
        having = ", ".join(b.name for b in _bodies_with_j2())
        raise OrbitDomainError(f"{named.name} has no J2 in the catalogue; bodies with J2: {having} (in Python, "
                               f"SecularOrbit.of also takes j2= and radius=)")
    return named


def _bodies_with_j2():
    from orbits._common.constants import BODIES

    return [b for b in BODIES.values() if b.j2 is not None]


def _field(primary, j2, radius):
    """(j2, R (m), Body or None) from a catalogue body or from explicit J2 and radius."""
    if j2 is not None or radius is not None:
        if j2 is None or radius is None:
            raise TypeError("give both j2= and radius= (the reference radius of J2), or neither")
        value = np.asarray(units.to_number(j2, "J2"), dtype=float)
        check_finite(value, "J2", "")
        return value, inputs.positive(radius, units.M, "J2 reference radius R"), None
    named = oblate_body(primary)
    return np.asarray(named.j2), np.asarray(named.j2_radius), named


# ---- secular rates and mean-element propagation -------------------------------------------------------------
@dataclass(frozen=True, eq=False, repr=False)
class SecularOrbit(display.Displayed):
    """An orbit's mean elements about an oblate body and J2's first-order secular rates (float64 SI fields).

    Build it with SecularOrbit.of(orbit) (J2 of the catalogue body the orbit is about) or with j2= and radius=.
    `propagate` advances Omega, omega and M at these rates and keeps a, e, i: it neglects the short-period terms,
    of relative size O(J2 (R/p)**2), so positions drift from a full integration by about that fraction of the
    orbit per revolution's worth of phase; use the orbit's elements as mean elements.
    """

    orbit: Orbit
    j2: np.ndarray
    radius: np.ndarray

    @classmethod
    def of(cls, orbit: Orbit, primary: Body | str | None = None, *, j2=None, radius=None) -> "SecularOrbit":
        """The orbit under J2: of `primary` (default: the catalogue body whose GM the orbit has) or given j2 and
        radius (length). Ellipses only."""
        orbit._require_ellipse("J2's secular rates")
        if primary is None and j2 is None:
            primary = body_with_gm(orbit.mu)
            if primary is None:
                raise OrbitDomainError("the orbit's primary is not a catalogue body: give primary= or j2= and "
                                       "radius=")
        j2_value, r, _ = _field(primary, j2, radius)
        return cls(orbit, j2_value, r)

    @classmethod
    def about(cls, primary: Body | str = "Earth", *, a: u.Quantity | None = None, altitude: u.Quantity | None = None,
              e=0.0, inc: u.Quantity = 0 * u.deg, argp: u.Quantity = 0 * u.deg) -> "SecularOrbit":
        """The orbit of size a (or altitude above the equator: exactly one), eccentricity e, inclination inc and
        argument of periapsis argp about the catalogue body `primary`, under its J2. Refused where the orbit's size
        or periapsis lies inside the body, as every design here is."""
        named = oblate_body(primary)
        size = _size(named, a, altitude)
        eccentricity = _eccentricity(e, named, size)
        orbit = Orbit.from_elements(named, a=size << units.M, e=eccentricity, inc=inc, argp=argp)
        return cls.of(orbit, named)

    @cached_property
    def _a(self):
        return self.orbit.semi_major_axis.to_value(units.M)

    def _args(self):
        o = self.orbit
        return self._a, o.e, o.inc, o.mu, self.j2, self.radius

    @cached_property
    def node_rate(self) -> u.Quantity:
        """dOmega/dt = -(3/2) n J2 (R/p)**2 cos i (rad/s)."""
        return oblateness.node_rate(*self._args()) << units.RAD_PER_S

    @cached_property
    def periapsis_rate(self) -> u.Quantity:
        """domega/dt = (3/4) n J2 (R/p)**2 (4 - 5 sin**2 i) (rad/s)."""
        return oblateness.periapsis_rate(*self._args()) << units.RAD_PER_S

    @cached_property
    def mean_anomaly_rate(self) -> u.Quantity:
        """dM/dt = n [1 + (3/4) J2 (R/p)**2 sqrt(1 - e**2) (2 - 3 sin**2 i)] (rad/s)."""
        return oblateness.mean_anomaly_rate(*self._args()) << units.RAD_PER_S

    @cached_property
    def nodal_period(self) -> u.Quantity:
        """2 pi / (dM/dt + domega/dt) (s): node to node."""
        return oblateness.nodal_period(*self._args()) << units.S

    @cached_property
    def accuracy(self) -> u.Quantity:
        """J2 (R/p)**2 (dimensionless): the relative error order of every rate here."""
        return oblateness.oblateness_factor(self.orbit.p, self.j2, self.radius) << u.one

    def at(self, dt: u.Quantity) -> Orbit:
        """The mean elements a time dt (time, broadcasting) later: Omega, omega and M advanced at their rates."""
        from orbits.core.twobody import anomalies

        dt_si = units.to_si(dt, units.S, "time step dt")
        o = self.orbit
        mean = o.mean_anomaly.to_value(units.RAD) + self.mean_anomaly_rate.to_value(units.RAD_PER_S) * dt_si
        nu = anomalies.true_from_mean(np.remainder(mean + np.pi, 2 * np.pi) - np.pi, o.e)
        return Orbit.from_elements(
            o.mu << units.M3_PER_S2, p=o.p << units.M, e=o.e,
            inc=o.inc << units.RAD,
            raan=np.remainder(o.raan + self.node_rate.to_value(units.RAD_PER_S) * dt_si, 2 * np.pi) << units.RAD,
            argp=np.remainder(o.argp + self.periapsis_rate.to_value(units.RAD_PER_S) * dt_si, 2 * np.pi) << units.RAD,
            nu=nu << units.RAD)

    def propagate(self, dt: u.Quantity) -> tuple[u.Quantity, u.Quantity]:
        """(r, v) on the mean orbit a time dt later (the secular motion only; see the class docstring)."""
        later = self.at(dt)
        return later.r, later.v

    def __repr__(self) -> str:
        rate = display.summary(self.node_rate.to(u.deg / u.day))
        return display.one_line(type(self).__name__, f"dOmega/dt = {rate}", f"J2 = {display.values_text(self.j2)}",
                                repr(self.orbit))

    def quantities(self, only: Iterable[str] | None = None) -> dict[str, u.Quantity]:
        """{name: Quantity}: the three rates, the nodal period and the accuracy J2 (R/p)**2."""
        return quantity_table(lambda name: getattr(self, name), SECULAR_NAMES, only)


SECULAR_NAMES = ["node_rate", "periapsis_rate", "mean_anomaly_rate", "nodal_period", "accuracy"]


# ---- designs ------------------------------------------------------------------------------------------------
@dataclass(frozen=True, eq=False, repr=False)
class Design(display.Displayed):
    """An orbit designed with J2's rates: its primary, semi-major axis, e and i, and the rates they give."""

    what: str
    primary: Body
    semi_major_axis: u.Quantity
    eccentricity: u.Quantity
    inclination: u.Quantity
    extra: dict

    @cached_property
    def secular(self) -> SecularOrbit:
        orbit = Orbit.from_elements(self.primary, a=self.semi_major_axis, e=self.eccentricity.value,
                                    inc=self.inclination)
        return SecularOrbit.of(orbit, self.primary)

    @property
    def altitude(self) -> u.Quantity:
        """a - R_eq (m): the height of a circular orbit above the equator."""
        return (self.semi_major_axis - self.primary.radius * u.m).to(u.m)

    def __repr__(self) -> str:
        return display.one_line(self.what, f"a = {display.summary(self.semi_major_axis)}",
                                f"e = {display.summary(self.eccentricity)}", f"i = {display.summary(self.inclination)}",
                                f"about {self.primary.name}")

    def quantities(self, only: Iterable[str] | None = None) -> dict[str, u.Quantity]:
        """{name: Quantity}: the design's elements, what it was designed for, and its secular rates."""
        table = {"semi_major_axis": self.semi_major_axis, "altitude": self.altitude,
                 "eccentricity": self.eccentricity, "inclination": self.inclination, **self.extra,
                 **self.secular.quantities()}
        names = list(table) if only is None else list(only)
        from orbits._common.tables import check_names

        check_names(names, list(table))
        return {name: table[name] for name in names}


def _size(primary, a, altitude):
    if (a is None) == (altitude is None):
        raise TypeError("give the orbit's size: exactly one of a (the semi-major axis) and altitude")
    size = (inputs.positive(a, units.M, "semi-major axis a") if a is not None
            else primary.radius + inputs.positive(altitude, units.M, "altitude"))
    if np.any(size <= primary.radius):
        raise OrbitDomainError(f"a = {float(np.min(size)) / 1e3:.6g} km lies inside {primary.name} (radius "
                               f"{primary.radius / 1e3:g} km)")
    _within_reach(primary, size)
    return size


def _within_reach(named: Body, size) -> None:
    """Refuse a design whose a lies beyond the body's Hill sphere, r_H = a_body (m / (3 M_parent))**(1/3): there
    the parent pulls harder than the body, and no J2 design holds."""
    from orbits.ephemeris.catalogue import mean_elements

    if named.parent is None:
        return
    try:
        own = mean_elements(named.name)
    except OrbitDomainError:
        return
    hill = own.a * (named.gm / (3.0 * body(named.parent).gm)) ** (1.0 / 3.0)
    if np.any(np.asarray(size) > hill):
        parent = "the Sun" if named.parent == "Sun" else named.parent
        raise OrbitDomainError(f"a = {float(np.max(size)) / 1e3:.6g} km lies beyond {named.name}'s Hill sphere "
                               f"(radius {hill / 1e3:.4g} km), where {parent} pulls harder: no J2 design holds")


def _eccentricity(e, primary, a):
    e = np.asarray(inputs.eccentricity(e), dtype=float)
    if np.any(~(e < 1.0)):
        raise OrbitDomainError(f"eccentricity e = {float(np.max(e))!r} is outside [0, 1): a design needs an ellipse")
    if a is not None and np.any(a * (1.0 - e) <= primary.radius):
        raise OrbitDomainError(f"periapsis a (1 - e) = {float(np.min(a * (1 - e))) / 1e3:.6g} km lies inside "
                               f"{primary.name} (radius {primary.radius / 1e3:g} km): lower e")
    return e


def sun_synchronous(primary: Body | str = "Earth", *, a: u.Quantity | None = None, altitude: u.Quantity | None = None,
                    e: float = 0.0, inc: u.Quantity | None = None, rate: u.Quantity | None = None) -> Design:
    """The sun-synchronous orbit: given a size (a or altitude above the equator) and e, its inclination; given
    inc (and e), its semi-major axis. The node follows `rate` (default: the mean Sun, 360 deg per tropical year)."""
    named = oblate_body(primary)
    node = oblateness.SUN_RATE if rate is None else units.to_si(rate, units.RAD_PER_S, "node rate")
    if inc is not None:
        if a is not None or altitude is not None:
            raise TypeError("give a size (a= or altitude=) or inc=, not both")
        ecc = _eccentricity(e, named, None)
        size = oblateness.sun_synchronous_semi_major_axis(inputs.inclination(inc), ecc, named.gm,
                                                          named.j2, named.j2_radius, node)
        _within_reach(named, size)
        _eccentricity(e, named, size)
        angle = inputs.inclination(inc)
    else:
        size = _size(named, a, altitude)
        ecc = _eccentricity(e, named, size)
        angle = oblateness.sun_synchronous_inclination(size, ecc, named.gm, named.j2, named.j2_radius, node)
    return Design("SunSynchronous", named, size << units.M, ecc << u.one, angle << units.RAD,
                  {"node_rate_target": node << units.RAD_PER_S})


def frozen(primary: Body | str = "Earth", *, a: u.Quantity | None = None, altitude: u.Quantity | None = None,
           inc: u.Quantity, argp: u.Quantity = 90 * u.deg) -> Design:
    """The frozen orbit (J2 with J3): the e at omega = 90 or 270 deg that keeps e and omega fixed."""
    named = oblate_body(primary)
    if named.j3 is None:
        raise OrbitDomainError(f"{named.name} has no J3 in the catalogue, and a frozen orbit needs it (the Earth "
                               f"has one)")
    size = _size(named, a, altitude)
    omega = inputs.angle(argp, "argument of periapsis omega")
    from orbits.core.errors import ConvergenceError

    try:
        e = oblateness.frozen_eccentricity(size, inputs.inclination(inc), named.j2, named.j3,
                                           named.j2_radius, omega)
    except ConvergenceError:
        raise OrbitDomainError(f"no frozen e found at i = {float(np.degrees(inputs.inclination(inc))):.10g}"
                               f" deg: this close to the critical inclination (63.43 or 116.57 deg) J2 barely turns "
                               f"the periapsis and the frozen e is no longer small") from None
    _eccentricity(e, named, size)
    return Design("FrozenOrbit", named, size << units.M, e << u.one, inputs.inclination(inc) << units.RAD,
                  {"argument_of_periapsis": omega << units.RAD})


def repeat_ground_track(primary: Body | str = "Earth", *, revolutions: int, days: int, inc: u.Quantity,
                        e: float = 0.0) -> Design:
    """The orbit making `revolutions` nodal periods in `days` turns of the body under its node, J2 included. Its
    semi_major_axis is the mean a the rates are solved for; osculating_semi_major_axis_at_node is the a to start
    from at the ascending node with periapsis there (Brouwer's short-period term), without which an integrated
    orbit misses the repeat by O(J2 (R/p)**2) of the equator it sweeps."""
    named = oblate_body(primary)
    for value, name in ((revolutions, "revolutions"), (days, "days")):
        if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < 1:
            raise OrbitDomainError(f"{name} = {value!r} must be a whole number >= 1")
    ecc = _eccentricity(e, named, None)
    angle = inputs.inclination(inc)
    if not abs(math.sin(angle)) > 1e-9:
        raise OrbitDomainError(f"i = {math.degrees(angle):g} deg: an equatorial orbit has no node for its ground "
                               f"track to repeat over; give an inclined orbit")
    spin = 2.0 * math.pi / named.rotation_period * (-1.0 if named.retrograde else 1.0)
    try:
        with np.errstate(over="raise", invalid="raise", divide="raise"):
            size = oblateness.repeat_ground_track_semi_major_axis(revolutions, days, ecc, angle, named.gm, named.j2,
                                                                  named.j2_radius, spin)
    except FloatingPointError:  # the rates have no root: say why where it is plain (a periapsis inside the body)
        period = days * named.rotation_period / revolutions  # the nodal period, to J2's share of it
        _eccentricity(e, named, (named.gm * (period / (2.0 * math.pi)) ** 2) ** (1.0 / 3.0))
        raise OrbitDomainError(f"no orbit makes {revolutions} revolutions in {days} days at e = {float(ecc):g}, "
                               f"i = {math.degrees(angle):g} deg about {named.name}: J2's rates have no root "
                               f"there") from None
    _eccentricity(e, named, size)
    _within_reach(named, size)
    osculating = oblateness.osculating_semi_major_axis(size, ecc, angle, 0.0, 0.0, named.j2, named.j2_radius)
    return Design("RepeatGroundTrack", named, size << units.M, ecc << u.one, angle << units.RAD,
                  {"revolutions": revolutions << u.one, "days": days << u.one,
                   "osculating_semi_major_axis_at_node": osculating << units.M})


# ---- drag -----------------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class AtmosphereBand:
    """One band of an exponential atmosphere: rho = density exp(-(h - base) / scale_height) for h from base (m)."""

    base: float
    density: float
    scale_height: float


@dataclass(frozen=True)
class AtmosphereTable:
    """Exponential bands by altitude above the equatorial radius (m), with their source."""

    bands: tuple[AtmosphereBand, ...]
    top: float
    source: str

    def band(self, altitude: float) -> AtmosphereBand:
        """The band an orbit at `altitude` (m) decays through: the one with base < altitude <= its top (at a
        band's base, the band below); OrbitDomainError outside the table."""
        if not self.bands[0].base < altitude <= self.top:
            raise OrbitDomainError(f"altitude {altitude / 1e3:g} km is outside the table, "
                                   f"({self.bands[0].base / 1e3:g}, {self.top / 1e3:g}] km")
        return [b for b in self.bands if b.base < altitude][-1]


#: (base altitude km, density kg/m3, scale height km) from 100 to 1000 km
_VALLADO = [(100, 5.297e-7, 5.877), (110, 9.661e-8, 7.263), (120, 2.438e-8, 9.473), (130, 8.484e-9, 12.636),
            (140, 3.845e-9, 16.149), (150, 2.070e-9, 22.523), (180, 5.464e-10, 29.740), (200, 2.789e-10, 37.105),
            (250, 7.248e-11, 45.546), (300, 2.418e-11, 53.628), (350, 9.518e-12, 53.298), (400, 3.725e-12, 58.515),
            (450, 1.585e-12, 60.828), (500, 6.967e-13, 63.822), (600, 1.454e-13, 71.835), (700, 3.614e-14, 88.667),
            (800, 1.170e-14, 124.64), (900, 5.245e-15, 181.05), (1000, 3.019e-15, 268.00)]
#: the Earth's static exponential atmosphere above 100 km
STANDARD_ATMOSPHERE = AtmosphereTable(
    tuple(AtmosphereBand(h * 1e3, rho, height * 1e3) for h, rho, height in _VALLADO), 1500e3,
    "Vallado, Fundamentals of Astrodynamics and Applications (4th ed., 2013), Table 8-4 (CIRA-72 above 25 km); "
    "the last band is used up to 1500 km")


@dataclass(frozen=True, eq=False, repr=False)
class DragDecay(display.Displayed):
    """A circular orbit of radius a0 decaying in one exponential band: rate, lifetime and validity (SI fields).

    B = C_D A / m (m2/kg); the band's base radius r0, density rho0 and scale height H; mu the primary's GM.
    """

    mu: float
    a0: float
    b: float
    base: float
    density: float
    scale_height: float
    primary: str

    @classmethod
    def of(cls, primary: Body | str = "Earth", *, altitude: u.Quantity, ballistic: u.Quantity,
           density: u.Quantity | None = None, scale_height: u.Quantity | None = None,
           base_altitude: u.Quantity | None = None) -> "DragDecay":
        """From the altitude of a circular orbit and B = C_D A / m (area / mass); the band's density, scale height
        and base altitude are given (all three) or read from STANDARD_ATMOSPHERE (the Earth's)."""
        named = body(primary) if isinstance(primary, str) else primary
        h = inputs.single(inputs.positive, altitude, units.M, "altitude")
        b = inputs.single(inputs.positive, ballistic, units.M**2 / units.KG, "ballistic coefficient C_D A / m")
        given = [x is not None for x in (density, scale_height, base_altitude)]
        if any(given) and not all(given):
            raise TypeError("give the band's density, scale_height and base_altitude together, or none of them")
        if all(given):
            band = AtmosphereBand(inputs.single(inputs.non_negative, base_altitude, units.M, "base altitude"),
                                  inputs.single(inputs.positive, density, units.KG / units.M**3, "density"),
                                  inputs.single(inputs.positive, scale_height, units.M, "scale height H"))
        else:
            if named.name != "Earth":
                raise OrbitDomainError(f"the standard atmosphere is the Earth's; for {named.name} give density, "
                                       f"scale_height and base_altitude")
            band = STANDARD_ATMOSPHERE.band(h)
        if not h > band.base:
            raise OrbitDomainError(f"altitude {h / 1e3:g} km is not above the atmosphere band's base "
                                   f"({band.base / 1e3:g} km): the exponential law holds only above it")
        radius = named.radius
        decay = cls(named.gm, radius + h, b, radius + band.base, band.density, band.scale_height, named.name)
        drag._check_thin(decay.a0, band.scale_height)
        if not decay.end_radius < decay.a0:
            per_revolution = decay.decay_per_revolution.to_value(units.M)
            raise OrbitDomainError(f"at {h / 1e3:g} km the orbit sinks {per_revolution / 1e3:.4g} km a revolution, "
                                   f"more than the scale height H = {band.scale_height / 1e3:g} km: the closed form "
                                   f"(a slowly shrinking circle) does not hold there")
        return decay

    def _model(self):
        return self.mu, self.b, self.density, self.base, self.scale_height

    @cached_property
    def decay_rate(self) -> u.Quantity:
        """da/dt = -B rho(a) sqrt(mu a) (m/s) at the start."""
        mu, b, rho0, base, height = self._model()
        return drag.decay_rate(self.a0, mu, b, rho0, base, height) << units.M_PER_S

    @cached_property
    def decay_per_revolution(self) -> u.Quantity:
        """2 pi B rho(a) a**2 (m) at the start."""
        return drag.decay_per_revolution(self.a0, self.b, self.density, self.base, self.scale_height) << units.M

    @cached_property
    def accuracy(self) -> u.Quantity:
        """(decay per revolution / H)**2: the closed form's relative error order (the e drag keeps)."""
        return (self.decay_per_revolution.to_value(units.M) / self.scale_height) ** 2 << u.one

    @cached_property
    def _radius(self) -> float:
        return float(body(self.primary).radius)

    @cached_property
    def end_radius(self) -> float:
        """The radius (m) where the closed form ends: the band's base, or the breakdown radius if higher."""
        return max(self.base, self._breakdown_radius)

    @cached_property
    def lifetime(self) -> u.Quantity:
        """Time (s) to decay to the band's base (or to the breakdown altitude, if that is higher)."""
        return self.time_to_altitude((self.end_radius - self._radius) * u.m)

    @cached_property
    def _breakdown_radius(self) -> float:
        mu, b, rho0, base, height = self._model()
        return float(drag.breakdown_radius(mu, b, rho0, base, height, self.a0))

    @cached_property
    def breakdown_altitude(self) -> u.Quantity:
        """Altitude (m) where the decay in one revolution reaches H: there the closed form stops holding. Defined
        only where that happens inside the band: below its base the band's exponential law is no law at all, and
        an orbit that keeps its decay per revolution under H down to the base has no breakdown altitude (the
        closed form ends at the base: end_radius). OrbitDomainError then, saying so."""
        if self._breakdown_radius <= self.base:
            raise OrbitDomainError(f"no breakdown altitude: the decay per revolution stays under the scale height "
                                   f"H = {self.scale_height / 1e3:g} km down to the band's base "
                                   f"({(self.base - self._radius) / 1e3:g} km), where the closed form ends")
        return self._breakdown_radius - self._radius << units.M

    def time_to_altitude(self, altitude: u.Quantity) -> u.Quantity:
        """Time (s) to decay to `altitude` (length), between the band's base and the start."""
        target = self._radius + units.to_si(altitude, units.M, "altitude")
        if np.any(target > self.a0) or np.any(target < self.base):
            low, high = (self.base - self._radius) / 1e3, (self.a0 - self._radius) / 1e3
            raise OrbitDomainError(f"the altitude must lie between the band's base ({low:g} km) and the start "
                                   f"({high:g} km)")
        mu, b, rho0, base, height = self._model()
        return drag.decay_time(self.a0, target, mu, b, rho0, base, height) << units.S

    def altitude_after(self, t: u.Quantity) -> u.Quantity:
        """Altitude (m) a time t (time, broadcasting) later; OrbitDomainError past the lifetime."""
        t_si = units.to_si(t, units.S, "time t")
        if np.any(t_si < 0) or np.any(t_si > self.lifetime.to_value(units.S)):
            raise OrbitDomainError(f"t must lie in [0, lifetime = {self.lifetime.to_value(u.day):.6g} d]")
        mu, b, rho0, base, height = self._model()
        return drag.radius_after(t_si, self.a0, mu, b, rho0, base, height) - self._radius << units.M

    def __repr__(self) -> str:
        return display.one_line("DragDecay", f"from {display.summary((self.a0 - self._radius) * u.m)}",
                                f"lifetime {display.summary(self.lifetime)}", f"about {self.primary}")

    def quantities(self, only: Iterable[str] | None = None) -> dict[str, u.Quantity]:
        """{name: Quantity}: the start, the band, the decay rate, the lifetime and where the closed form ends
        (breakdown_altitude left out where there is none: the closed form then holds down to the band's base)."""
        rows = {"altitude": lambda: (self.a0 - self._radius) * u.m,
                "base_altitude": lambda: (self.base - self._radius) * u.m,
                "density_at_base": lambda: self.density * units.KG / units.M**3,
                "scale_height": lambda: self.scale_height * u.m, "decay_rate": lambda: self.decay_rate,
                "decay_per_revolution": lambda: self.decay_per_revolution, "lifetime": lambda: self.lifetime,
                "breakdown_altitude": lambda: self.breakdown_altitude, "accuracy": lambda: self.accuracy}
        from orbits._common.tables import check_names

        if only is None:
            names = [n for n in rows if n != "breakdown_altitude" or self._breakdown_radius > self.base]
        else:
            names = list(only)
            check_names(names, list(rows))
        return {name: rows[name]() for name in names}


# ---- a distant third body ---------------------------------------------------------------------------------------
#: the smallest initial e a Kozai-Lidov table takes: below it e**2 is lost beside 1 in float64, and the period,
#: which grows as ln(1 / e), stops changing; and the least 1 - e_max**2 (a nearly radial orbit)
KOZAI_SMALLEST_E = 1e-6
KOZAI_RADIAL = 1e-8


def _kozai_eccentricity(value: float, name: str, smallest: float) -> float:
    e = inputs.single(units.to_number, value, f"eccentricity {name}")
    if not smallest <= e < 1.0:
        raise OrbitDomainError(f"eccentricity {name} = {e!r} is outside [{smallest:g}, 1)")
    return e


@dataclass(frozen=True, eq=False, repr=False)
class KozaiLidov(display.Displayed):
    """The quadrupole Kozai-Lidov oscillation of a test particle about m0 perturbed by m3 on a wide orbit.

    Fields in SI: a, e, inc, argp of the inner orbit (inc relative to the outer orbit's plane), mu_inner = G m0,
    mass_ratio = m3 / m0, a_out and e_out of the outer orbit.
    """

    a: float
    e: float
    inc: float
    argp: float
    mu_inner: float
    mass_ratio: float
    a_out: float
    e_out: float

    @classmethod
    def of(cls, inner: Body | str | u.Quantity, perturber: Body | str | u.Quantity, *, a: u.Quantity,
           a_out: u.Quantity, inc: u.Quantity, e: float = 0.001, argp: u.Quantity = 90 * u.deg,
           e_out: float = 0.0) -> "KozaiLidov":
        """From the two masses (bodies, masses or GMs), the inner a, e, i, omega and the outer a_out, e_out."""
        mu0 = inputs.single(inputs.gravitational_parameter, inner, "inner mass m0")
        mu3 = inputs.single(inputs.gravitational_parameter, perturber, "perturber mass m3")
        size = inputs.single(inputs.positive, a, units.M, "semi-major axis a")
        outer = inputs.single(inputs.positive, a_out, units.M, "outer semi-major axis a_out")
        if not outer > size:
            raise OrbitDomainError(f"a_out = {outer / 1e3:.6g} km must exceed a = {size / 1e3:.6g} km: the "
                                   f"perturber is distant")
        ecc, ecc_out = _kozai_eccentricity(e, "e", KOZAI_SMALLEST_E), _kozai_eccentricity(e_out, "e_out", 0.0)
        angle = inputs.one(inputs.inclination(inc), "inclination i")
        triple = cls(size, ecc, angle, inputs.single(inputs.angle, argp, "argument of periapsis omega"), mu0, mu3 / mu0,
                     outer, ecc_out)
        triple._require_hierarchical_stability()
        triple._require_non_radial()
        return triple

    def _require_hierarchical_stability(self) -> None:
        """Mardling and Aarseth's (2001) stability limit for the outer orbit, a_out / a > 2.8 (1 + q)**(2/5)
        (1 + e_out)**(2/5) (1 - e_out)**(-6/5) (1 - 0.3 i / 180 deg), q = m3 / m0: closer, the triple is not
        hierarchical and no secular theory applies."""
        limit = (2.8 * (1.0 + self.mass_ratio) ** 0.4 * (1.0 + self.e_out) ** 0.4 * (1.0 - self.e_out) ** -1.2
                 * (1.0 - 0.3 * abs(math.remainder(self.inc, 2.0 * math.pi)) / math.pi))
        if not self.a_out / self.a > limit:
            raise OrbitDomainError(f"a_out / a = {self.a_out / self.a:.4g} is below {limit:.4g}, Mardling and "
                                   f"Aarseth's stability limit for these masses and e_out: the triple is not "
                                   f"hierarchical, and the secular theory does not apply")

    def _require_non_radial(self) -> None:
        """1 - e_max**2 of at least KOZAI_RADIAL, where e**2 near 1 is still resolved in float64."""
        _, high = third_body.eccentricity_range(self.e, self.inc, self.argp)
        if not (1.0 - float(high)) * (1.0 + float(high)) >= KOZAI_RADIAL:
            raise OrbitDomainError(f"e would reach {float(high):.10g}, a radial orbit (1 - e_max**2 below "
                                   f"{KOZAI_RADIAL:g}, as at i = 90 deg): choose i farther from 90 deg")

    @cached_property
    def timescale(self) -> u.Quantity:
        """tau = (m0 / m3) (b / a)**3 / n (s)."""
        return third_body.timescale(self.a, self.mu_inner, self.mass_ratio, self.a_out, self.e_out) << units.S

    @cached_property
    def eccentricity_range(self) -> tuple[u.Quantity, u.Quantity]:
        """(e_min, e_max) of the oscillation through the initial e, i, omega."""
        low, high = third_body.eccentricity_range(self.e, self.inc, self.argp)
        return low << u.one, high << u.one

    @cached_property
    def maximum_eccentricity_from_circular(self) -> u.Quantity:
        """sqrt(1 - (5/3) cos**2 i0): e_max from e0 -> 0 (0 below the critical inclination)."""
        return third_body.maximum_eccentricity_from_circular(self.inc) << u.one

    @cached_property
    def period(self) -> u.Quantity:
        """Period of e's oscillation (s)."""
        return third_body.oscillation_period(self.e, self.inc, self.argp, self.timescale.to_value(units.S)) << units.S

    @cached_property
    def kozai_constant(self) -> u.Quantity:
        """sqrt(1 - e**2) cos i, conserved."""
        return math.sqrt((1.0 - self.e) * (1.0 + self.e)) * math.cos(self.inc) << u.one

    @cached_property
    def inclination_range(self) -> tuple[u.Quantity, u.Quantity]:
        """(i at e_max, i at e_min) (rad), from the conserved sqrt(1 - e**2) cos i."""
        low, high = (x.to_value(u.one) for x in self.eccentricity_range)
        k = self.kozai_constant.to_value(u.one)
        return (np.arccos(np.clip(k / math.sqrt(1 - high * high), -1, 1)) << units.RAD,
                np.arccos(np.clip(k / math.sqrt(1 - low * low), -1, 1)) << units.RAD)

    @cached_property
    def octupole_parameter(self) -> u.Quantity:
        """eps_oct = (a / a_out) e_out / (1 - e_out**2): the neglected octupole's relative size."""
        return third_body.octupole_parameter(self.a, self.a_out, self.e_out) << u.one

    @cached_property
    def averaging_parameter(self) -> u.Quantity:
        """eps_sa: the relative size of what the double average drops."""
        return third_body.averaging_parameter(self.a, self.a_out, self.e_out, self.mass_ratio) << u.one

    def __repr__(self) -> str:
        low, high = self.eccentricity_range
        return display.one_line("KozaiLidov", f"e {display.summary(low)} to {display.summary(high)}",
                                f"period {display.summary(self.period)}")

    def quantities(self, only: Iterable[str] | None = None) -> dict[str, u.Quantity]:
        """{name: Quantity} of the oscillation and its validity."""
        low, high = self.eccentricity_range
        i_high_e, i_low_e = self.inclination_range
        table = {"minimum_eccentricity": low, "maximum_eccentricity": high,
                 "maximum_eccentricity_from_circular": self.maximum_eccentricity_from_circular,
                 "inclination_at_maximum_eccentricity": i_high_e, "inclination_at_minimum_eccentricity": i_low_e,
                 "kozai_constant": self.kozai_constant, "timescale": self.timescale, "period": self.period,
                 "critical_inclination": KOZAI_CRITICAL_INCLINATION, "octupole_parameter": self.octupole_parameter,
                 "averaging_parameter": self.averaging_parameter}
        names = list(table) if only is None else list(only)
        from orbits._common.tables import check_names

        check_names(names, list(table))
        return {name: table[name] for name in names}


# ---- general relativity ---------------------------------------------------------------------------------------------
def relativistic_periapsis_advance(orbit: Orbit) -> tuple[u.Quantity, u.Quantity]:
    """(advance per revolution (rad), rate (rad/s)): 6 pi G M / (c**2 a (1 - e**2)) per orbit, first
    post-Newtonian order (relative error mu / (c**2 p)). Mercury: 42.98 arcsec per Julian century."""
    orbit._require_ellipse("the relativistic periapsis advance")
    a = orbit.semi_major_axis.to_value(units.M)
    per_orbit = relativity.periapsis_advance_per_orbit(orbit.p, orbit.mu, SPEED_OF_LIGHT)
    return per_orbit << units.RAD, relativity.periapsis_advance_rate(a, orbit.e, orbit.mu,
                                                                     SPEED_OF_LIGHT) << units.RAD_PER_S
