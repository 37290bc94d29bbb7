"""Escape speed, cosmic velocities, synchronous orbits and maximum elongation (XXI.ix-xi), with astropy units.

    >>> import astropy.units as u
    >>> from orbits import CosmicVelocities, SynchronousOrbit, escape_speed, max_elongation
    >>> notes = CosmicVelocities.from_surface_gravity()  # g0 = 9.80665 m/s2 and R = 6371 km, as in the notes
    >>> speeds = notes.first_cosmic_velocity, notes.second_cosmic_velocity, notes.third_cosmic_velocity
    >>> [round(float(v.to_value(u.km / u.s)), 3) for v in speeds]
    [7.904, 11.178, 16.648]
    >>> SynchronousOrbit.of("Earth").altitude.to(u.km).round(1)
    <Quantity 35786.1 km>
    >>> escape_speed("Earth").to(u.km / u.s).round(4)  # at the equatorial radius
    <Quantity 11.1799 km / s>
    >>> max_elongation(0.723 * u.AU, 1 * u.AU).to(u.deg).round(1)
    <Quantity 46.3 deg>

The notes' 7.9, 11.2 and 16.7 km/s are the first three rounded (7.904, 11.178 and 16.65 km/s by patched
conics); their fourth, "at least 525 km/s", is an empirical estimate of the Galactic escape speed and
has no formula here. The geosynchronous and the geostationary orbit share one radius (the latter is the
equatorial one); 35786.1 km above Earth's IAU 2015 equatorial radius, the notes' 35786 km.
"""

import warnings
from collections.abc import Iterable
from dataclasses import dataclass
from functools import cached_property

import astropy.units as u
import numpy as np

from orbits._common import display, inputs, units
from orbits._common.constants import BODIES, EARTH_MEAN_RADIUS, STANDARD_GRAVITY, Body, body
from orbits._common.tables import quantity_table
from orbits.core.checks import first_where
from orbits.core.encounters import escape as escape_core
from orbits.core.errors import InsideBodyWarning, OrbitDomainError
from orbits.core.twobody import twobody
from orbits.encounters.binary import Binary


def _named(primary):
    """The Body for a name or Body, else None (a bare mass or GM has no radius, rotation or orbit)."""
    if isinstance(primary, str):
        return body(primary)
    return primary if isinstance(primary, Body) else None


def _length(value, name):
    result = inputs.positive(value, units.M, name)
    return result


def _speed(value, name):
    result = inputs.positive(value, units.M_PER_S, name)
    return result


def escape_speed(primary: Body | str | u.Quantity | Binary, distance: u.Quantity | None = None) -> u.Quantity:
    """v_esc = sqrt(2 mu / r) (m/s) at distance r (length) from a body (name, Body, mass or GM) or a Binary's CM.

    Without `distance`, at a named body's equatorial radius (its surface). A Binary counts as one point mass
    G (m1 + m2) at its centre of mass (Binary.escape_speed). Exact to 1 ulp (tests/core/test_escape.py).
    """
    if isinstance(primary, Binary):
        if distance is None:
            raise TypeError("give the distance from the binary's centre of mass, e.g. distance=1 * u.AU")
        return primary.escape_speed(distance)
    named = _named(primary)
    if distance is None:
        if named is None:
            raise TypeError("a mass or GM has no surface: give the distance, e.g. distance=7000 * u.km")
        r = np.asarray(named.radius)
    else:
        r = _length(distance, "distance r")
    mu = np.asarray(named.gm) if named is not None else inputs.gravitational_parameter(primary, "primary mass M")
    return twobody.escape_speed(r, mu) << units.M_PER_S


@dataclass(frozen=True, eq=False, repr=False)
class CosmicVelocities(display.Displayed):
    """First, second and third cosmic velocities of a planet (XXI.ix); float64 SI fields that broadcast.

    g (m/s2) and radius (m) are the surface gravity and radius; v_orbit (m/s) is the planet's circular speed
    about its own primary (the Sun for a planet), or None when it has none (no third velocity then).
    """

    g: np.ndarray
    radius: np.ndarray
    v_orbit: np.ndarray | None = None

    @classmethod
    def from_surface_gravity(
        cls, g: u.Quantity | None = None, radius: u.Quantity | None = None, orbital_speed: u.Quantity | None = None
    ) -> "CosmicVelocities":
        """The notes' model from g (acceleration) and R (length); defaults: g0 = 9.80665 m/s2, R = 6371 km and
        Earth's circular heliocentric speed sqrt(G M_sun / a_earth) = 29.785 km/s (Standish mean a)."""
        g = (np.asarray(STANDARD_GRAVITY) if g is None
             else inputs.positive(g, units.M_PER_S / units.S, "surface gravity g"))
        radius = np.asarray(EARTH_MEAN_RADIUS) if radius is None else _length(radius, "radius R")
        speed = _orbital_speed(BODIES["Earth"]) if orbital_speed is None else _speed(orbital_speed, "orbital speed")
        return cls(g, radius, speed)

    @classmethod
    def of(cls, planet: Body | str) -> "CosmicVelocities":
        """From a named body's GM and equatorial radius (g = G M / R**2) and its mean orbit about its primary."""
        named = _named(planet)
        if named is None:
            raise TypeError(
                f"{planet!r} is not a catalogued body; for any other planet use "
                "CosmicVelocities.from_surface_gravity(g, radius, orbital_speed)"
            )
        g = escape_core.surface_gravity(named.gm, named.radius)
        speed = None if named.orbit is None else _orbital_speed(named)
        return cls(np.asarray(g), np.asarray(named.radius), speed)

    @cached_property
    def surface_gravity(self) -> u.Quantity:
        """g (m/s2)."""
        return self.g << units.M_PER_S / units.S

    @cached_property
    def surface_radius(self) -> u.Quantity:
        """R (m)."""
        return self.radius << units.M

    @cached_property
    def first_cosmic_velocity(self) -> u.Quantity:
        """v1 = sqrt(g R) (m/s): the circular speed at the surface; 7.904 km/s for the notes' Earth."""
        return escape_core.first_cosmic_velocity(self.g, self.radius) << units.M_PER_S

    @cached_property
    def second_cosmic_velocity(self) -> u.Quantity:
        """v2 = sqrt(2 g R) (m/s): the escape speed from the surface; 11.178 km/s for the notes' Earth."""
        return escape_core.second_cosmic_velocity(self.g, self.radius) << units.M_PER_S

    @cached_property
    def orbital_speed(self) -> u.Quantity:
        """v_orbit (m/s): the planet's circular speed about its primary (29.785 km/s for Earth about the Sun)."""
        return self._require_orbit("orbital speed") << units.M_PER_S

    @cached_property
    def hyperbolic_excess_speed(self) -> u.Quantity:
        """(sqrt 2 - 1) v_orbit (m/s): the speed left after escaping the planet that reaches the primary's escape
        speed sqrt(2) v_orbit along the planet's motion; 12.337 km/s for Earth."""
        return escape_core.escape_excess_speed(self._require_orbit("hyperbolic excess speed")) << units.M_PER_S

    @cached_property
    def third_cosmic_velocity(self) -> u.Quantity:
        """v3 = sqrt(((sqrt 2 - 1) v_orbit)**2 + v2**2) (m/s), patched conics; 16.648 km/s for the notes' Earth."""
        v2 = escape_core.second_cosmic_velocity(self.g, self.radius)
        return escape_core.third_cosmic_velocity(self._require_orbit("third cosmic velocity"), v2) << units.M_PER_S

    def _require_orbit(self, quantity):
        if self.v_orbit is None:
            raise OrbitDomainError(f"{quantity} needs the planet's orbital speed about its primary; this body has none")
        return self.v_orbit

    def __repr__(self) -> str:
        """E.g. "CosmicVelocities(7.904, 11.17799, 16.64822 km/s, g = 9.80665 m / s2, R = 6371 km)"."""
        speeds = [self.first_cosmic_velocity, self.second_cosmic_velocity]
        if self.v_orbit is not None:
            speeds.append(self.third_cosmic_velocity)
        shown = ", ".join(display.summary(v, unit=u.km / u.s).removesuffix(" km / s") for v in speeds)
        gravity = "g = " + display.summary(self.g << units.M / units.S**2)
        radius = "R = " + display.summary(self.radius << units.M)
        return display.one_line("CosmicVelocities", shown + " km / s", gravity, radius)

    def quantities(self, only: Iterable[str] | None = None) -> dict[str, u.Quantity]:
        """{snake_case name: Quantity} (or `only` those); without `only`, the third velocity is left out when the
        body has no orbit."""
        return _table(self, COSMIC_NAMES, only)


def _orbital_speed(named):
    """Circular speed sqrt(G M_primary / a) (m/s) of a catalogued body on its mean orbit."""
    return twobody.circular_speed(named.orbit.a, BODIES[named.orbit.primary].gm)


@dataclass(frozen=True, eq=False, repr=False)
class SynchronousOrbit(display.Displayed):
    """The circular orbit whose period equals a body's sidereal rotation period (XXI.x); float64 SI fields.

    mu (m3/s2), rotation_period (s) and body_radius (m, or None: no altitude then). Any inclination gives a
    geosynchronous orbit of this radius; the equatorial one is geostationary.
    """

    mu: np.ndarray
    rotation_period: np.ndarray
    body_radius: np.ndarray | None = None

    @classmethod
    def of(
        cls,
        primary: Body | str | u.Quantity = "Earth",
        period: u.Quantity | None = None,
        radius: u.Quantity | None = None,
    ) -> "SynchronousOrbit":
        """For a named body (its GM, sidereal rotation period and equatorial radius) or a mass or GM; `period`
        (time) and `radius` (length) override or supply the rotation period and the body's radius."""
        named = _named(primary)
        mu = np.asarray(named.gm) if named is not None else inputs.gravitational_parameter(primary, "primary mass M")
        if period is None and named is None:
            raise TypeError("a mass or GM has no rotation: give period=..., e.g. period=23.93 * u.h")
        t = (np.asarray(named.rotation_period) if period is None
             else inputs.positive(period, units.S, "rotation period T"))
        size = None if named is None else np.asarray(named.radius)
        size = size if radius is None else _length(radius, "body radius R")
        synchronous = cls(mu, t, size)
        synchronous._warn_if_inside()
        return synchronous

    def _warn_if_inside(self) -> None:
        """InsideBodyWarning when the radius lies inside the body: the period has an orbit radius, but nothing can
        circle there (the altitude, r - R, is then refused)."""
        if self.body_radius is None:
            return
        r, radius = np.broadcast_arrays(self.orbit_radius.to_value(units.M), self.body_radius)
        if np.any(r <= radius):
            bad, body_radius = first_where(r <= radius, r, radius)
            warnings.warn(f"the synchronous orbit radius r = {bad / 1e3:.7g} km lies inside the body (radius "
                          f"{body_radius / 1e3:.7g} km): no orbit of this period exists above its surface",
                          InsideBodyWarning, stacklevel=3)

    @cached_property
    def orbit_radius(self) -> u.Quantity:
        """r = (mu T**2 / (4 pi**2))**(1/3) (m) from the body's centre; 42164.17 km for Earth."""
        return escape_core.synchronous_radius(self.mu, self.rotation_period) << units.M

    @cached_property
    def altitude(self) -> u.Quantity:
        """r - R (m) above the body's radius; 35786.1 km for Earth's equatorial radius 6378.1 km."""
        if self.body_radius is None:
            raise OrbitDomainError("altitude needs the body's radius: build it with radius=... km")
        r, radius = np.broadcast_arrays(self.orbit_radius.to_value(units.M), self.body_radius)
        inside = r <= radius
        if np.any(inside):
            bad, body_radius = first_where(inside, r, radius)
            raise OrbitDomainError(
                f"synchronous orbit radius r = {bad!r} m lies inside the body (radius R = {body_radius!r} m): the "
                f"altitude r - R must be > 0 m, so there is no synchronous orbit"
            )
        return r - radius << units.M

    @cached_property
    def orbital_speed(self) -> u.Quantity:
        """v = 2 pi r / T = sqrt(mu / r) (m/s); 3.0747 km/s for Earth."""
        return twobody.circular_speed(self.orbit_radius.to_value(units.M), self.mu) << units.M_PER_S

    @cached_property
    def angular_velocity(self) -> u.Quantity:
        """omega = 2 pi / T (rad/s), the body's rotation rate."""
        return 2.0 * np.pi / self.rotation_period << units.RAD_PER_S

    @cached_property
    def period(self) -> u.Quantity:
        """T (s), the sidereal rotation period."""
        return self.rotation_period << units.S

    def __repr__(self) -> str:
        """E.g. "SynchronousOrbit(r = 42164.17 km, altitude = 35786.03 km, T = 23.93447 h, about Earth)"."""
        inside = self.body_radius is None or np.any(self.orbit_radius.to_value(units.M) <= self.body_radius)
        altitude = "" if inside else "altitude = " + display.summary(self.altitude)
        return display.one_line("SynchronousOrbit", "r = " + display.summary(self.orbit_radius), altitude,
                                "T = " + display.summary(self.period), f"about {display.body_name(self.mu)}")

    def quantities(self, only: Iterable[str] | None = None) -> dict[str, u.Quantity]:
        """{snake_case name: Quantity} (or `only` those); without `only`, altitude is left out when undefined."""
        return _table(self, SYNCHRONOUS_NAMES, only)


def max_elongation(inner: Body | str | u.Quantity, outer: Body | str | u.Quantity) -> u.Quantity:
    """Greatest angle arcsin(r / R) (rad) between the star and an inner planet seen from an outer one (XXI.xi).

    inner and outer are orbit radii (lengths) of circular coplanar orbits, or catalogued body names (their
    mean semi-major axes). Reached when the sight line is tangent to the inner orbit; within 2 ulp of mpmath.
    """
    r = _orbit_radius(inner, "inner orbit radius r")
    big_r = _orbit_radius(outer, "outer orbit radius R")
    outside = np.asarray(r) >= np.asarray(big_r)
    if np.any(outside):
        inner_r, outer_r = first_where(outside, r, big_r)
        raise OrbitDomainError(
            f"inner orbit radius r = {inner_r!r} m is outside the allowed range (0, R) m with the outer "
            f"radius R = {outer_r!r} m: the inner planet must orbit inside the observer's orbit"
        )
    return escape_core.max_elongation(r, big_r) << units.RAD


def _orbit_radius(value, name):
    named = _named(value)
    if named is None:
        return _length(value, name)
    if named.orbit is None:
        raise OrbitDomainError(f"{name}: {named.name} has no orbit in the catalogue; give a length instead")
    return np.asarray(named.orbit.a)


def _table(obj, all_names, only):
    return quantity_table(lambda name: getattr(obj, name), all_names, only)


COSMIC_NAMES = [
    "surface_gravity",
    "surface_radius",
    "orbital_speed",
    "first_cosmic_velocity",
    "second_cosmic_velocity",
    "hyperbolic_excess_speed",
    "third_cosmic_velocity",
]

SYNCHRONOUS_NAMES = ["period", "angular_velocity", "orbit_radius", "altitude", "orbital_speed"]
