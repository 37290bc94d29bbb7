"""A planet's gravity assist seen from the Sun, with astropy units (patched conics; the notes' IX.vii view of a
flyby as an elastic collision with a moving planet).

The planet-frame hyperbola is an orbits.Flyby, so v_inf keeps its size and turns by the flyby's deflection; the
heliocentric speed changes by what the planet's motion lends. A Sun-planet-probe integration in rebound and heyoka
agrees with the patched conic to the order of the planet's mass ratio (orbits.validate.manoeuvres).
"""

from collections.abc import Iterable
from dataclasses import dataclass
from functools import cached_property

import astropy.units as u
import numpy as np

from orbits._common import display, inputs, units
from orbits._common.constants import Body
from orbits._common.tables import attribute_table
from orbits.core.errors import OrbitDomainError
from orbits.core.manoeuvres import assist as assist_core
from orbits.encounters.flyby import Flyby


@dataclass(frozen=True, eq=False, repr=False)
class GravityAssist(display.Displayed):
    """A planet's flyby seen from the Sun (patched conics): the planet-frame hyperbola is `flyby`, the probe's
    heliocentric velocity v_in (m/s, (..., 3)) meets the planet moving at v_planet (m/s), and the excess
    velocity turns counterclockwise about `normal` (3,) by the flyby's deflection (IX.vii: an elastic collision).
    """

    flyby: Flyby
    v_in: np.ndarray
    v_planet: np.ndarray
    normal: np.ndarray

    NAMES = ["speed_at_infinity", "periapsis_distance", "turning_angle", "incoming_velocity", "outgoing_velocity",
             "incoming_speed", "outgoing_speed", "delta_v", "delta_v_magnitude", "speed_gain",
             "specific_energy_change"]

    @classmethod
    def past(cls, planet: Body | str | u.Quantity, v_in: u.Quantity, v_planet: u.Quantity,
             periapsis: u.Quantity, normal: u.Quantity | np.ndarray | None = None) -> "GravityAssist":
        """A probe at heliocentric velocity v_in (speed vector) passes the planet (name, Body, mass or GM) moving at
        v_planet (speed vector) at closest approach `periapsis` (length), turning counterclockwise about `normal`
        (a direction, default +z: the planet's orbit normal when both velocities lie in the xy plane)."""
        v_in = inputs.vector(v_in, units.M_PER_S, "probe velocity v_in")
        v_planet = inputs.vector(v_planet, units.M_PER_S, "planet velocity v_planet")
        axis = np.array([0.0, 0.0, 1.0]) if normal is None else np.asarray(normal, dtype=float)
        excess = v_in - v_planet
        speed = np.linalg.norm(excess, axis=-1)
        if np.any(speed == 0):
            raise OrbitDomainError("v_in equals v_planet: a probe at rest relative to the planet has no flyby "
                                   "(speed at infinity v_inf = 0 m / s; allowed: > 0)")
        off_plane = np.linalg.norm(np.cross(axis, excess), axis=-1) <= 1e-12 * np.linalg.norm(axis) * speed
        if np.any(off_plane) or axis.shape[-1:] != (3,):
            raise OrbitDomainError(f"normal = {axis.tolist()} must be a 3-vector not parallel to v_in - v_planet: "
                                   "it fixes the plane in which the excess velocity turns")
        # not inside a named planet
        periapsis = inputs.orbit_radius(planet, periapsis, "periapsis distance rp") << units.M
        flyby = Flyby.past(planet, speed << units.M_PER_S, periapsis=periapsis)
        return cls(flyby, v_in, v_planet, axis)

    @cached_property
    def speed_at_infinity(self) -> u.Quantity:
        """|v_in - v_planet| (m/s), kept by the elastic turn."""
        return self.flyby.speed_at_infinity

    @cached_property
    def periapsis_distance(self) -> u.Quantity:
        """Closest approach (m) to the planet's centre."""
        return self.flyby.periapsis_distance

    @cached_property
    def turning_angle(self) -> u.Quantity:
        """delta = 2 asin(1 / e) (rad), from Flyby.deflection_angle."""
        return self.flyby.deflection_angle

    @cached_property
    def incoming_velocity(self) -> u.Quantity:
        """v_in (m/s), heliocentric, before the pass."""
        return self.v_in << units.M_PER_S

    @cached_property
    def outgoing_velocity(self) -> u.Quantity:
        """v_planet + the turned v_inf (m/s), heliocentric, after the pass."""
        angle = self.flyby.deflection_angle.to_value(units.RAD)
        return assist_core.outgoing_velocity(self.v_in, self.v_planet, self.normal, angle) << units.M_PER_S

    @cached_property
    def incoming_speed(self) -> u.Quantity:
        """|v_in| (m/s)."""
        return np.linalg.norm(self.v_in, axis=-1) << units.M_PER_S

    @cached_property
    def outgoing_speed(self) -> u.Quantity:
        """|v_out| (m/s)."""
        return np.linalg.norm(self.outgoing_velocity.to_value(units.M_PER_S), axis=-1) << units.M_PER_S

    @cached_property
    def delta_v(self) -> u.Quantity:
        """v_out - v_in (m/s, vector): the heliocentric velocity change, free of propellant."""
        return self.outgoing_velocity - self.incoming_velocity

    @cached_property
    def delta_v_magnitude(self) -> u.Quantity:
        """2 v_inf / (1 + r_p v_inf**2 / mu) = 2 v_inf sin(delta / 2) (m/s)."""
        fly = self.flyby
        return assist_core.delta_v_magnitude(fly.v_inf, fly.periapsis_distance.to_value(units.M),
                                             fly.mu) << units.M_PER_S

    @cached_property
    def speed_gain(self) -> u.Quantity:
        """|v_out| - |v_in| (m/s): positive when the probe passes behind the planet."""
        return self.outgoing_speed - self.incoming_speed

    @cached_property
    def specific_energy_change(self) -> u.Quantity:
        """V . (v_out - v_in) (J/kg): the heliocentric energy per unit mass taken from the planet's motion."""
        change = np.sum(self.v_planet * self.delta_v.to_value(units.M_PER_S), axis=-1)
        return change << units.J_PER_KG

    def quantities(self, only: Iterable[str] | None = None) -> dict[str, u.Quantity]:
        """{snake_case name: Quantity} (or `only` those)."""
        return attribute_table(self, self.NAMES, only)

    def __repr__(self) -> str:
        """E.g. "GravityAssist(v_inf = 5.6 km/s, turn = 100 deg, dv = 8 km/s, speed gain = 3 km/s, about Jupiter)"."""
        return display.one_line("GravityAssist", "v_inf = " + display.summary(self.speed_at_infinity),
                                "turn = " + display.summary(self.turning_angle),
                                "dv = " + display.summary(self.delta_v_magnitude),
                                "speed gain = " + display.summary(self.speed_gain),
                                f"about {display.body_name(self.flyby.mu)}")
