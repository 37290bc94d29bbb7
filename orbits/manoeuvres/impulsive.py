"""Impulsive manoeuvres, with astropy units: Hohmann, bi-elliptic, plane changes, phasing and a hyperbolic
departure (the notes' third cosmic velocity as a burn, XXI.ix).

    >>> import astropy.units as u
    >>> from orbits import BiElliptic, Departure, Hohmann
    >>> geo = Hohmann.between("Earth", 6678 * u.km, 42164 * u.km)
    >>> [round(float(v.to_value(u.km / u.s)), 2) for v in (geo.first_burn, geo.second_burn)]
    [2.43, 1.47]
    >>> geo.transfer_time.to(u.h).round(2)
    <Quantity 5.28 h>
    >>> BiElliptic.between("Earth", 7000 * u.km, 105000 * u.km, 210000 * u.km).saving.to(u.m / u.s).round(1)
    <Quantity 17.8 m / s>
    >>> Departure.third_cosmic().departure_speed.to(u.km / u.s).round(3)  # the notes' 16.7 km/s
    <Quantity 16.648 km / s>

Every burn is instant; a signed speed change counts along the motion. The speed differences are formed without
cancellation (orbits.core.manoeuvres.impulsive, <= 4 ulp against mpmath). Each manoeuvre's `impulse_plan()` lays it
out as
burns at times for orbits.validate.manoeuvres, where rebound and heyoka fly it and land on the predicted orbit to
1.5e-13 (tests/validation/test_manoeuvres_integration.py). Gravity assists live in orbits.manoeuvres.assist.
"""

from collections.abc import Iterable
from dataclasses import dataclass
from functools import cached_property

import astropy.units as u
import numpy as np

from orbits._common import display, inputs, units
from orbits._common.constants import Body, body
from orbits._common.tables import quantity_table
from orbits.core.checks import check_finite, first_where
from orbits.core.errors import OrbitDomainError
from orbits.core.manoeuvres import impulsive as core
from orbits.core.twobody.twobody import circular_angular_velocity, circular_speed
from orbits.encounters.escape import CosmicVelocities
from orbits.ephemeris.catalogue import mean_elements
from orbits.twobody.orbit import PRIMARY, Orbit


def _turn_angle(value, name):
    """An angle (rad) in [0, pi]."""
    return inputs.angle_in(value, name, 0.0, np.pi, "[0, pi]")


def _shape(*arrays):
    return np.broadcast_shapes(*(np.shape(a) for a in arrays))


def _fields(*arrays):
    shape = _shape(*arrays)
    return [np.broadcast_to(a, shape).astype(float) for a in arrays]


def _scalar(obj, what):
    if np.size(obj.mu) != 1 or any(np.size(getattr(obj, f)) != 1 for f in obj.__dataclass_fields__):
        raise OrbitDomainError(f"{what} lays out one manoeuvre: build it from scalars, not arrays")


def _coast(value):
    seconds = units.to_si(value, units.S, "coast")
    check_finite(seconds, "coast", "s")
    if np.any(seconds < 0):
        raise OrbitDomainError(f"coast = {float(seconds)!r} s is outside the allowed range [0, inf) s")
    return float(seconds)


class _Table(display.Displayed):
    """quantities() from the class's NAMES."""

    NAMES: list[str] = []

    def quantities(self, only: Iterable[str] | None = None) -> dict[str, u.Quantity]:
        """{snake_case name: Quantity} (or `only` those)."""
        return quantity_table(lambda name: getattr(self, name), self.NAMES, only)


# ---- Hohmann ---------------------------------------------------------------------------------------------


@dataclass(frozen=True, eq=False, repr=False)
class Hohmann(_Table):
    """Two-burn transfer between circular orbits r1 -> r2 about mu (float64 SI fields that broadcast), the plane
    turned by `inclination` (rad) at the burn at the larger radius (a combined plane change, where it is cheapest).
    """

    mu: np.ndarray
    r1: np.ndarray
    r2: np.ndarray
    inclination: np.ndarray

    NAMES = ["initial_speed", "final_speed", "transfer_semi_major_axis", "transfer_eccentricity",
             "transfer_periapsis_speed", "transfer_apoapsis_speed", "first_burn", "second_burn", "delta_v",
             "transfer_time", "synodic_period", "phase_angle"]

    @classmethod
    def between(cls, primary: Body | str | u.Quantity, r1: u.Quantity, r2: u.Quantity, *,
                inclination_change: u.Quantity = 0 * u.deg) -> "Hohmann":
        """From the circular orbit of radius r1 to that of radius r2 (lengths from the centre) about a primary
        (name, Body, mass or GM), optionally turning the plane by `inclination_change` (angle in [0, 180] deg)."""
        mu = inputs.gravitational_parameter(primary, PRIMARY)
        return cls(*_fields(mu, inputs.orbit_radius(primary, r1, "initial orbit radius r1"),
                            inputs.orbit_radius(primary, r2, "final orbit radius r2"),
                            _turn_angle(inclination_change, "inclination change")))

    @classmethod
    def between_bodies(cls, departure: str, target: str, *,
                       inclination_change: u.Quantity = 0 * u.deg) -> "Hohmann":
        """Between the mean orbits of two catalogue bodies (names) about their common primary, each taken as the
        circle of radius its semi-major axis: the textbook approximation, off by the orbits' eccentricities (Mars's
        distance from the Sun varies by 9 % either side of a) and their mutual inclination (turned only if
        `inclination_change` says so). mu is the primary's GM (the craft's own mass is negligible)."""
        if body(departure).name == body(target).name:  # as lambert and Porkchop refuse it (transfer_ends)
            raise OrbitDomainError(f"Hohmann: both ends are {body(departure).name}; a transfer joins two bodies' "
                                   f"orbits")
        first, second = (mean_elements(name) for name in (departure, target))
        if first.primary != second.primary:
            raise OrbitDomainError(f"{body(departure).name} orbits {first.primary} and {body(target).name} orbits "
                                   f"{second.primary}: a Hohmann transfer joins two orbits about one primary")
        return cls.between(first.primary, first.a << units.M, second.a << units.M,
                           inclination_change=inclination_change)

    @cached_property
    def synodic_period(self) -> u.Quantity:
        """2 pi / |n1 - n2| (s): how often the two circular orbits' bodies line up again, so how often the
        transfer's departure window recurs (n = sqrt(mu / r**3)); undefined for r1 = r2."""
        n1, n2 = circular_angular_velocity(self.r1, self.mu), circular_angular_velocity(self.r2, self.mu)
        if np.any(n1 == n2):
            raise OrbitDomainError("the synodic period needs two different radii r1 != r2: equal orbits never lap")
        return 2.0 * np.pi / np.abs(n1 - n2) << units.S

    @cached_property
    def phase_angle(self) -> u.Quantity:
        """pi - n2 t (rad), wrapped to (-pi, pi]: how far a body on the final circle must lead the departure point
        at the first burn for the transfer to meet it (negative: it trails); n2 = sqrt(mu / r2**3), t the
        transfer time. About 44.3 deg from the Earth's to Mars's orbit."""
        lead = np.pi - circular_angular_velocity(self.r2, self.mu) * core.hohmann_time(self.r1, self.r2, self.mu)
        return np.pi - np.mod(np.pi - lead, 2.0 * np.pi) << units.RAD

    @cached_property
    def initial_speed(self) -> u.Quantity:
        """sqrt(mu / r1) (m/s) on the initial circle."""
        return circular_speed(self.r1, self.mu) << units.M_PER_S

    @cached_property
    def final_speed(self) -> u.Quantity:
        """sqrt(mu / r2) (m/s) on the final circle."""
        return circular_speed(self.r2, self.mu) << units.M_PER_S

    @cached_property
    def transfer_semi_major_axis(self) -> u.Quantity:
        """(r1 + r2) / 2 (m)."""
        return 0.5 * (self.r1 + self.r2) << units.M

    @cached_property
    def transfer_eccentricity(self) -> u.Quantity:
        """|r2 - r1| / (r1 + r2) (dimensionless)."""
        return np.abs(self.r2 - self.r1) / (self.r1 + self.r2) << u.one

    @cached_property
    def transfer_periapsis_speed(self) -> u.Quantity:
        """Speed (m/s) at the lower apsis of the transfer ellipse."""
        low, high = np.minimum(self.r1, self.r2), np.maximum(self.r1, self.r2)
        return core.apsis_speed(low, high, self.mu) << units.M_PER_S

    @cached_property
    def transfer_apoapsis_speed(self) -> u.Quantity:
        """Speed (m/s) at the upper apsis of the transfer ellipse."""
        low, high = np.minimum(self.r1, self.r2), np.maximum(self.r1, self.r2)
        return core.apsis_speed(high, low, self.mu) << units.M_PER_S

    def _burns(self):
        """|dv1|, |dv2| (m/s): tangential, except the one at the larger radius, which also turns the plane."""
        dv1, dv2 = core.hohmann_delta_v(self.r1, self.r2, self.mu)
        v1, v2 = circular_speed(self.r1, self.mu), circular_speed(self.r2, self.mu)
        combined_1 = core.combined_delta_v(v1, v1 + dv1, self.inclination)
        combined_2 = core.combined_delta_v(v2 - dv2, v2, self.inclination)
        first_turns = self.r1 > self.r2
        return np.where(first_turns, combined_1, np.abs(dv1)), np.where(first_turns, np.abs(dv2), combined_2)

    @cached_property
    def first_burn(self) -> u.Quantity:
        """|dv1| (m/s) at r1: prograde when raising, retrograde when lowering (with the plane change if r1 > r2)."""
        return self._burns()[0] << units.M_PER_S

    @cached_property
    def second_burn(self) -> u.Quantity:
        """|dv2| (m/s) at r2, circularising (with the plane change if r2 > r1)."""
        return self._burns()[1] << units.M_PER_S

    @cached_property
    def delta_v(self) -> u.Quantity:
        """|dv1| + |dv2| (m/s): the transfer's budget; 3.893 km/s from 6678 km to GEO."""
        return self.first_burn + self.second_burn

    @cached_property
    def transfer_time(self) -> u.Quantity:
        """pi sqrt(a**3 / mu) (s): half the transfer ellipse; 5.275 h from 6678 km to GEO."""
        return core.hohmann_time(self.r1, self.r2, self.mu) << units.S

    @cached_property
    def transfer_orbit(self) -> Orbit:
        """The transfer ellipse as an Orbit at its lower apsis, in the initial plane."""
        low = np.minimum(self.r1, self.r2) << units.M
        return Orbit.from_elements(self.mu << units.M3_PER_S2, e=self.transfer_eccentricity, q=low)

    def impulse_plan(self, coast: u.Quantity = 0 * u.s) -> core.ImpulsePlan:
        """The burns as velocity kicks at times from (r1, 0, 0), and the predicted state `coast` after the last."""
        _scalar(self, "impulse_plan")
        return core.hohmann_plan(float(self.r1), float(self.r2), float(self.mu), float(self.inclination),
                                 _coast(coast))

    def __repr__(self) -> str:
        """E.g. "Hohmann(6678 -> 42164 km, delta-v = 3.892608 km/s, 5.275014 h, about Earth)"."""
        turn = "" if not np.any(self.inclination) else "turn = " + display.summary(self.inclination << units.RAD)
        return display.one_line("Hohmann", _radii(self.r1, self.r2), turn, "delta-v = " + display.summary(self.delta_v),
                                display.summary(self.transfer_time), f"about {display.body_name(self.mu)}")


def _radii(*radii):
    """E.g. "6678 -> 42164 km": radii (m) in the natural unit of the largest."""
    unit = display.natural_unit(max(np.max(r) for r in radii) << units.M)
    return " -> ".join(display.summary(r << units.M, unit=unit).rsplit(" ", 1)[0] for r in radii) + f" {unit}"


# ---- bi-elliptic -----------------------------------------------------------------------------------------


@dataclass(frozen=True, eq=False, repr=False)
class BiElliptic(_Table):
    """Three-burn transfer r1 -> rb -> r2 between circular orbits about mu, rb at or above both (float64 SI fields).

    rb = max(r1, r2) is the degenerate transfer: one burn is zero and the other two are Hohmann's, with half a
    circle's coast at the larger radius added to the time."""

    mu: np.ndarray
    r1: np.ndarray
    r2: np.ndarray
    rb: np.ndarray

    NAMES = ["first_burn", "second_burn", "third_burn", "delta_v", "transfer_time", "hohmann_delta_v", "saving"]

    @classmethod
    def between(cls, primary: Body | str | u.Quantity, r1: u.Quantity, r2: u.Quantity,
                rb: u.Quantity) -> "BiElliptic":
        """From the circle r1 out to the apoapsis rb >= max(r1, r2) and down to the circle r2 (lengths from the
        centre)."""
        mu = inputs.gravitational_parameter(primary, PRIMARY)
        r1 = inputs.orbit_radius(primary, r1, "initial orbit radius r1")
        r2 = inputs.orbit_radius(primary, r2, "final orbit radius r2")
        rb = inputs.positive(rb, units.M, "intermediate radius rb")
        low = rb < np.maximum(r1, r2)
        if np.any(low):
            bad, one, two = first_where(low, rb, r1, r2)
            raise OrbitDomainError(
                f"intermediate radius rb = {bad!r} m is outside the allowed range [max(r1, r2), inf) m with "
                f"r1 = {one!r} m and r2 = {two!r} m: the bi-elliptic apoapsis must not lie below either orbit")
        return cls(*_fields(mu, r1, r2, rb))

    def _burns(self):
        return core.bielliptic_delta_v(self.r1, self.r2, self.rb, self.mu)

    @cached_property
    def first_burn(self) -> u.Quantity:
        """|dv1| (m/s): prograde at r1, onto the ellipse reaching rb."""
        return np.abs(self._burns()[0]) << units.M_PER_S

    @cached_property
    def second_burn(self) -> u.Quantity:
        """|dv2| (m/s) at rb: moves the periapsis from r1 to r2 (prograde when raising)."""
        return np.abs(self._burns()[1]) << units.M_PER_S

    @cached_property
    def third_burn(self) -> u.Quantity:
        """|dv3| (m/s): retrograde at r2, circularising."""
        return np.abs(self._burns()[2]) << units.M_PER_S

    @cached_property
    def delta_v(self) -> u.Quantity:
        """|dv1| + |dv2| + |dv3| (m/s)."""
        return self.first_burn + self.second_burn + self.third_burn

    @cached_property
    def transfer_time(self) -> u.Quantity:
        """pi (sqrt(a1**3 / mu) + sqrt(a2**3 / mu)) (s): two half ellipses."""
        return core.bielliptic_time(self.r1, self.r2, self.rb, self.mu) << units.S

    @cached_property
    def hohmann_delta_v(self) -> u.Quantity:
        """The Hohmann transfer's budget between the same circles (m/s), for comparison."""
        dv1, dv2 = core.hohmann_delta_v(self.r1, self.r2, self.mu)
        return np.abs(dv1) + np.abs(dv2) << units.M_PER_S

    @cached_property
    def saving(self) -> u.Quantity:
        """Hohmann's budget minus this one (m/s): positive when the bi-elliptic transfer is cheaper, which needs
        r2 / r1 > 11.94 (and holds for every rb once r2 / r1 > 15.58)."""
        return self.hohmann_delta_v - self.delta_v

    def impulse_plan(self, coast: u.Quantity = 0 * u.s) -> core.ImpulsePlan:
        """The three burns as kicks at times from (r1, 0, 0), and the predicted state `coast` after the last."""
        _scalar(self, "impulse_plan")
        return core.bielliptic_plan(float(self.r1), float(self.r2), float(self.rb), float(self.mu), _coast(coast))

    def __repr__(self) -> str:
        """E.g. "BiElliptic(7000 -> 210000 -> 105000 km, delta-v = 3.9 km/s, ..., about Earth)"."""
        return display.one_line("BiElliptic", _radii(self.r1, self.rb, self.r2),
                                "delta-v = " + display.summary(self.delta_v), display.summary(self.transfer_time),
                                f"about {display.body_name(self.mu)}")


# ---- plane change ----------------------------------------------------------------------------------------


@dataclass(frozen=True, eq=False, repr=False)
class PlaneChange(_Table):
    """A burn that turns a circular orbit's plane by `angle` (rad) keeping its radius r (float64 SI fields)."""

    mu: np.ndarray
    r: np.ndarray
    angle: np.ndarray

    NAMES = ["speed", "inclination_change", "delta_v"]

    @classmethod
    def at(cls, primary: Body | str | u.Quantity, radius: u.Quantity, angle: u.Quantity) -> "PlaneChange":
        """On the circle of radius r (length) about a primary, by `angle` (angle in [0, 180] deg) at a node."""
        mu = inputs.gravitational_parameter(primary, PRIMARY)
        return cls(*_fields(mu, inputs.orbit_radius(primary, radius, "orbit radius r"),
                            _turn_angle(angle, "inclination change")))

    @cached_property
    def speed(self) -> u.Quantity:
        """sqrt(mu / r) (m/s), unchanged by the burn."""
        return circular_speed(self.r, self.mu) << units.M_PER_S

    @cached_property
    def inclination_change(self) -> u.Quantity:
        """The angle between the planes (rad)."""
        return self.angle << units.RAD

    @cached_property
    def delta_v(self) -> u.Quantity:
        """2 v sin(di / 2) (m/s)."""
        return core.plane_change_delta_v(circular_speed(self.r, self.mu), self.angle) << units.M_PER_S

    def impulse_plan(self, coast: u.Quantity = 0 * u.s) -> core.ImpulsePlan:
        """The burn as a kick at (r, 0, 0), and the predicted state on the turned circle `coast` later."""
        _scalar(self, "impulse_plan")
        return core.plane_change_plan(float(self.r), float(self.angle), float(self.mu), _coast(coast))

    def __repr__(self) -> str:
        """E.g. "PlaneChange(r = 7000 km, turn = 28.5 deg, delta-v = 3.7 km/s, about Earth)"."""
        return display.one_line("PlaneChange", "r = " + display.summary(self.r << units.M),
                                "turn = " + display.summary(self.inclination_change),
                                "delta-v = " + display.summary(self.delta_v), f"about {display.body_name(self.mu)}")


def combined_plane_change(v_before: u.Quantity, v_after: u.Quantity, angle: u.Quantity) -> u.Quantity:
    """|v_after - v_before| = sqrt(v1**2 + v2**2 - 2 v1 v2 cos di) (m/s): one burn that changes the speed from v1
    to v2 (speeds) and turns the velocity by di (angle), formed without cancellation."""
    v1 = inputs.positive(v_before, units.M_PER_S, "speed before v1")
    v2 = inputs.positive(v_after, units.M_PER_S, "speed after v2")
    return core.combined_delta_v(v1, v2, _turn_angle(angle, "turn angle")) << units.M_PER_S


# ---- phasing ---------------------------------------------------------------------------------------------

#: the phasing orbit needs a > r / 2 (the burn point is an apsis): x = phase / (2 pi k) < 1 - 2**(-3/2)
MAX_PHASING_FRACTION = 1.0 - 2.0**-1.5


@dataclass(frozen=True, eq=False, repr=False)
class Phasing(_Table):
    """Meeting a target on the same circle r: a burn onto a phasing orbit, k revolutions of it, a burn back.

    phase (rad) is how far the target leads (negative: trails); float64 SI fields that broadcast.
    """

    mu: np.ndarray
    r: np.ndarray
    phase: np.ndarray
    revolutions: np.ndarray

    NAMES = ["circular_period", "phasing_period", "phasing_semi_major_axis", "phasing_periapsis",
             "phasing_apoapsis", "burn", "delta_v", "phasing_time"]

    @classmethod
    def to(cls, primary: Body | str | u.Quantity, radius: u.Quantity, phase: u.Quantity,
           revolutions: int = 1) -> "Phasing":
        """Catch a target `phase` (angle) ahead on the circle of radius r (length) after `revolutions` (>= 1) of
        the phasing orbit; a negative phase waits for a target behind on a larger orbit."""
        mu = inputs.gravitational_parameter(primary, PRIMARY)
        r = inputs.orbit_radius(primary, radius, "orbit radius r")
        angle = inputs.angle(phase, "phase")
        k = np.asarray(revolutions)
        if not np.issubdtype(k.dtype, np.integer) or np.any(k < 1):
            raise OrbitDomainError(f"revolutions = {revolutions!r} must be a whole number >= 1")
        mu, r, angle, k = _fields(mu, r, angle, k)
        fraction = core.phasing_fraction(angle, k)
        if np.any(fraction >= MAX_PHASING_FRACTION):
            bad, turns = first_where(fraction >= MAX_PHASING_FRACTION, angle, k)
            raise OrbitDomainError(
                f"phase = {bad!r} rad is outside the allowed range (-inf, {2 * np.pi * turns * MAX_PHASING_FRACTION!r})"
                f" rad for {int(turns)} revolution(s): the phasing orbit would need a < r / 2; use more revolutions")
        phasing = cls(mu, r, angle, k)
        phasing._check_clear_of(inputs.named_body(primary))
        return phasing

    def _check_clear_of(self, named):
        if named is None:
            return
        low = self.phasing_periapsis.to_value(units.M)
        if np.any(low <= named.radius):
            bad, = first_where(low <= named.radius, low)
            raise OrbitDomainError(
                f"phasing periapsis = {bad!r} m is inside {named.name} (allowed: above its radius "
                f"{named.radius!r} m): spread the phase over more revolutions")

    @cached_property
    def circular_period(self) -> u.Quantity:
        """T = 2 pi sqrt(r**3 / mu) (s) of the circle."""
        return 2.0 * np.pi * np.sqrt(self.r**3 / self.mu) << units.S

    @cached_property
    def phasing_period(self) -> u.Quantity:
        """T (1 - phase / (2 pi k)) (s)."""
        return self.phasing_time / self.revolutions

    @cached_property
    def phasing_semi_major_axis(self) -> u.Quantity:
        """a = r (1 - phase / (2 pi k))**(2/3) (m)."""
        return core.phasing_semi_major_axis(self.r, self.phase, self.revolutions) << units.M

    @cached_property
    def phasing_periapsis(self) -> u.Quantity:
        """min(r, 2 a - r) (m): the phasing orbit's lowest point."""
        other = 2.0 * self.phasing_semi_major_axis.to_value(units.M) - self.r
        return np.minimum(self.r, other) << units.M

    @cached_property
    def phasing_apoapsis(self) -> u.Quantity:
        """max(r, 2 a - r) (m): the phasing orbit's highest point."""
        other = 2.0 * self.phasing_semi_major_axis.to_value(units.M) - self.r
        return np.maximum(self.r, other) << units.M

    @cached_property
    def burn(self) -> u.Quantity:
        """Signed speed change (m/s) onto the phasing orbit (negative: retrograde); the burn back is its opposite."""
        return core.phasing_delta_v(self.r, self.phase, self.revolutions, self.mu) << units.M_PER_S

    @cached_property
    def delta_v(self) -> u.Quantity:
        """2 |burn| (m/s)."""
        return 2.0 * np.abs(self.burn)

    @cached_property
    def phasing_time(self) -> u.Quantity:
        """k T (1 - phase / (2 pi k)) (s) from the first burn to the meeting."""
        return core.phasing_time(self.r, self.phase, self.revolutions, self.mu) << units.S

    def impulse_plan(self, coast: u.Quantity = 0 * u.s) -> core.ImpulsePlan:
        """The two burns as kicks at times from (r, 0, 0); the prediction is the target's state `coast` after."""
        _scalar(self, "impulse_plan")
        return core.phasing_plan(float(self.r), float(self.phase), int(self.revolutions), float(self.mu),
                                 _coast(coast))

    def __repr__(self) -> str:
        """E.g. "Phasing(r = 7000 km, phase = 20 deg, 1 rev, delta-v = 0.5 km/s, about Earth)"."""
        return display.one_line("Phasing", "r = " + display.summary(self.r << units.M),
                                "phase = " + display.summary(self.phase << units.RAD),
                                "k = " + display.values_text(self.revolutions),
                                "delta-v = " + display.summary(self.delta_v), f"about {display.body_name(self.mu)}")


# ---- departure on a hyperbola (the third cosmic velocity) ------------------------------------------------


@dataclass(frozen=True, eq=False, repr=False)
class Departure(_Table):
    """One prograde burn from the circle r onto the hyperbola that leaves with v_inf (float64 SI fields)."""

    mu: np.ndarray
    r: np.ndarray
    v_inf: np.ndarray

    NAMES = ["parking_speed", "speed_at_infinity", "departure_speed", "delta_v", "eccentricity"]

    @classmethod
    def to_excess_speed(cls, primary: Body | str | u.Quantity, radius: u.Quantity,
                        v_inf: u.Quantity) -> "Departure":
        """From the circle of radius r (length) about a primary to the speed v_inf (speed) far away."""
        mu = inputs.gravitational_parameter(primary, PRIMARY)
        r = inputs.positive(radius, units.M, "parking orbit radius r")
        return cls(*_fields(mu, r, inputs.positive(v_inf, units.M_PER_S, "speed at infinity v_inf")))

    @classmethod
    def from_cosmic_velocities(cls, planet: CosmicVelocities, radius: u.Quantity | None = None) -> "Departure":
        """Leave the planet's primary for good: v_inf = (sqrt 2 - 1) v_orbit of CosmicVelocities, mu = g R**2,
        from the circle of radius r (length; default the surface R, where departure_speed is the third cosmic
        velocity)."""
        mu = planet.g * planet.radius**2
        r = planet.radius if radius is None else inputs.positive(radius, units.M, "parking orbit radius r")
        return cls(*_fields(mu, r, planet.hyperbolic_excess_speed.to_value(units.M_PER_S)))

    @classmethod
    def third_cosmic(cls, planet: Body | str | None = None, radius: u.Quantity | None = None) -> "Departure":
        """The notes' worked escape from the solar system (XXI.ix): Earth as the notes model it (g0, 6371 km) or a
        catalogued planet, from its surface or from a parking circle of radius r (length)."""
        model = CosmicVelocities.from_surface_gravity() if planet is None else CosmicVelocities.of(planet)
        return cls.from_cosmic_velocities(model, radius)

    @cached_property
    def parking_speed(self) -> u.Quantity:
        """sqrt(mu / r) (m/s) on the parking circle (the first cosmic velocity at the surface)."""
        return circular_speed(self.r, self.mu) << units.M_PER_S

    @cached_property
    def speed_at_infinity(self) -> u.Quantity:
        """v_inf (m/s)."""
        return self.v_inf << units.M_PER_S

    @cached_property
    def departure_speed(self) -> u.Quantity:
        """sqrt(v_inf**2 + 2 mu / r) (m/s) just after the burn (energy conservation)."""
        return np.sqrt(self.v_inf**2 + 2.0 * self.mu / self.r) << units.M_PER_S

    @cached_property
    def delta_v(self) -> u.Quantity:
        """departure_speed - sqrt(mu / r) (m/s): the burn from the parking circle."""
        return core.departure_delta_v(self.r, self.v_inf, self.mu) << units.M_PER_S

    @cached_property
    def eccentricity(self) -> u.Quantity:
        """1 + r v_inf**2 / mu (dimensionless) of the departure hyperbola (periapsis at the burn)."""
        return 1.0 + self.r * self.v_inf**2 / self.mu << u.one

    def impulse_plan(self, coast: u.Quantity = 1 * u.d) -> core.ImpulsePlan:
        """The burn as a kick at (r, 0, 0), and the state `coast` later by Kepler's equation."""
        _scalar(self, "impulse_plan")
        return core.departure_plan(float(self.r), float(self.v_inf), float(self.mu), _coast(coast))

    def __repr__(self) -> str:
        """E.g. "Departure(r = 6678 km, v_inf = 3 km/s, delta-v = 3.6 km/s, about Earth)"."""
        return display.one_line("Departure", "r = " + display.summary(self.r << units.M),
                                "v_inf = " + display.summary(self.speed_at_infinity),
                                "delta-v = " + display.summary(self.delta_v), f"about {display.body_name(self.mu)}")
