"""Motion under uniform effective gravity (notes XX), with astropy units: effective gravity on a rotating Earth, the
conical pendulum, and projectiles without drag, with linear (Stokes) drag and with quadratic drag.

    >>> import astropy.units as u
    >>> from orbits import Projectile
    >>> ball = Projectile.launch(20 * u.m / u.s, 45 * u.deg)
    >>> ball.range.round(3)  # v**2 sin(2 angle) / g0
    <Quantity 40.789 m>
    >>> ball.with_quadratic_drag(terminal_speed=30 * u.m / u.s).range.round(3)
    <Quantity 30.726 m>

Linear drag is -m b v (b in 1/s, terminal speed g / b); quadratic drag -(1/2) C rho A |v| v with terminal speed
v_t = sqrt(2 m g / (C rho A)) (the notes leave out the mass), given directly or from m, C, rho and A. The numbers
come from orbits.core.mechanics.projectile (accuracy stated there: heyoka agrees to 5e-16 for linear drag, 6e-14 for
quadratic).
"""

from collections.abc import Iterable
from dataclasses import dataclass, replace
from functools import cached_property

import astropy.units as u
import numpy as np

from orbits._common import display, inputs, units
from orbits._common.constants import BODIES, EARTH_MEAN_RADIUS, SIDEREAL_DAY
from orbits._common.inputs import angle_in, gravity, non_negative
from orbits._common.tables import attribute_table
from orbits._common.units import ACCELERATION, RATE
from orbits.core.errors import OrbitDomainError
from orbits.core.mechanics import projectile as core

DRAGS = ("none", "linear", "quadratic")


@dataclass(frozen=True, eq=False, repr=False)
class Projectile(display.Displayed):
    """A launch: float64 SI fields speed (m/s), angle (rad above the horizontal), height (m), g (m/s2), the drag
    law ("none", "linear", "quadratic") and its parameter (b in 1/s, or v_t in m/s)."""

    speed: np.ndarray
    angle: np.ndarray
    height: np.ndarray
    g: np.ndarray
    drag: str = "none"
    parameter: np.ndarray | None = None

    @classmethod
    def launch(cls, speed: u.Quantity, angle: u.Quantity, height: u.Quantity | None = None,
               g: u.Quantity | None = None) -> "Projectile":
        """From (0, h) at `speed` (>= 0) and `angle` in [-90, 90] deg above the horizontal, g default 9.80665 m/s2
        (XX.iii); h >= 0 (default 0)."""
        v = non_negative(speed, units.M_PER_S, "launch speed v")
        theta = angle_in(angle, "launch angle", -np.pi / 2, np.pi / 2, "[-pi/2, pi/2]")
        h = np.zeros(()) if height is None else non_negative(height, units.M, "launch height h")
        return cls(*np.broadcast_arrays(v, theta, h, gravity(g)))

    def with_linear_drag(self, rate: u.Quantity) -> "Projectile":
        """The same launch under drag -m b v (XX.v); b (1/s) >= 0."""
        return replace(self, drag="linear", parameter=non_negative(rate, RATE, "drag rate b"))

    def with_quadratic_drag(self, terminal_speed: u.Quantity | None = None, *, mass: u.Quantity | None = None,
                            drag_coefficient: float | None = None, density: u.Quantity | None = None,
                            area: u.Quantity | None = None) -> "Projectile":
        """The same launch under drag -(1/2) C rho A |v| v (XX.iv): give v_t, or m, C, rho and A, from which
        v_t = sqrt(2 m g / (C rho A)) (the notes leave out the mass)."""
        if terminal_speed is not None:
            v_t = inputs.positive(terminal_speed, units.M_PER_S, "terminal speed v_t")
        else:
            if any(x is None for x in (mass, drag_coefficient, density, area)):
                raise TypeError("give terminal_speed, or all of mass, drag_coefficient, density and area")
            v_t = core.quadratic_drag_terminal_speed(
                inputs.positive(mass, units.KG, "mass m"), self.g,
                inputs.positive(drag_coefficient * u.one, u.one, "drag coefficient C"),
                inputs.positive(density, units.KG / units.M**3, "air density rho"),
                inputs.positive(area, units.M**2, "cross-section A"))
        return replace(self, drag="quadratic", parameter=np.asarray(v_t, dtype=float))

    @property
    def _components(self):
        return self.speed * np.cos(self.angle), self.speed * np.sin(self.angle)

    @cached_property
    def _quadratic(self):
        return core.quadratic_drag_flight(self.speed, self.angle, self.height, self.parameter, self.g)

    @cached_property
    def time_of_flight(self) -> u.Quantity:
        """The time to reach y = 0 (s)."""
        v_x, v_y = self._components
        if self.drag == "none":
            t = core.free_flight_time(v_y, self.height, self.g)
        elif self.drag == "linear":
            t = core.linear_drag_flight_time(v_y, self.height, self.g, self.parameter)
        else:
            t = self._quadratic[0]
        return t << units.S

    @cached_property
    def range(self) -> u.Quantity:
        """x at landing (m) (XX.iii)."""
        if self.drag == "quadratic":
            return self._quadratic[1] << units.M
        return self.position_at(self.time_of_flight)[0]

    @cached_property
    def apex_time(self) -> u.Quantity:
        """When the vertical velocity vanishes (s); 0 when launched level or downward."""
        v_x, v_y = self._components
        if self.drag == "none":
            t = core.free_apex_time(v_y, self.g)
        elif self.drag == "linear":
            t = core.linear_drag_apex_time(v_y, self.g, self.parameter)
        else:
            t = self._quadratic[3]
        return t << units.S

    @cached_property
    def apex_height(self) -> u.Quantity:
        """The greatest height (m)."""
        v_x, v_y = self._components
        if self.drag == "none":
            y = core.free_apex_height(v_y, self.height, self.g)
        elif self.drag == "linear":
            y = core.linear_drag_apex_height(v_y, self.height, self.g, self.parameter)
        else:
            y = self._quadratic[2]
        return y << units.M

    @cached_property
    def apex_distance(self) -> u.Quantity:
        """x at the apex (m)."""
        if self.drag == "quadratic":
            return self._quadratic[4] << units.M
        return self.position_at(self.apex_time)[0]

    @cached_property
    def landing_speed(self) -> u.Quantity:
        """|v| at y = 0 (m/s)."""
        if self.drag == "quadratic":
            return self._quadratic[5] << units.M_PER_S
        v_x, v_y = (q.to_value(units.M_PER_S) for q in self.velocity_at(self.time_of_flight))
        return np.hypot(v_x, v_y) << units.M_PER_S

    @cached_property
    def landing_angle(self) -> u.Quantity:
        """The velocity's angle to the horizontal at landing (rad, negative: downward)."""
        if self.drag == "quadratic":
            return self._quadratic[6] << units.RAD
        v_x, v_y = (q.to_value(units.M_PER_S) for q in self.velocity_at(self.time_of_flight))
        return np.arctan2(v_y, v_x) << units.RAD

    @cached_property
    def terminal_speed(self) -> u.Quantity:
        """g / b (linear drag, XX.v) or sqrt(2 m g / (C rho A)) (quadratic, XX.iv) (m/s); none without drag."""
        if self.drag == "none":
            raise OrbitDomainError("a projectile without drag has no terminal speed: add with_linear_drag(...) or "
                                   "with_quadratic_drag(...)")
        if self.drag == "linear":
            with np.errstate(divide="ignore"):
                return core.linear_drag_terminal_speed(self.g, self.parameter) << units.M_PER_S
        return self.parameter << units.M_PER_S

    def position_at(self, t: u.Quantity) -> tuple[u.Quantity, u.Quantity]:
        """(x, y) (m) at time t (time >= 0); no drag or linear drag only (XX.iii, XX.v)."""
        time = self._times(t)
        v_x, v_y = self._components
        if self.drag == "none":
            x, y = core.free_position(v_x, v_y, self.height, self.g, time)
        else:
            x, y = core.linear_drag_position(v_x, v_y, self.height, self.g, self.parameter, time)
        return x << units.M, y << units.M

    def velocity_at(self, t: u.Quantity) -> tuple[u.Quantity, u.Quantity]:
        """(v_x, v_y) (m/s) at time t; no drag or linear drag only."""
        time = self._times(t)
        v_x, v_y = self._components
        if self.drag == "none":
            vx, vy = core.free_velocity(v_x, v_y, self.g, time)
        else:
            vx, vy = core.linear_drag_velocity(v_x, v_y, self.g, self.parameter, time)
        return vx << units.M_PER_S, vy << units.M_PER_S

    def _acceleration(self, v_x, v_y):
        """(a_x, a_y) (m/s2) of the drag law at velocity (v_x, v_y): (0, -g); -b v added (linear); -(g / v_t**2)
        |v| v added (quadratic, the drag that balances g at v_t)."""
        if self.drag == "none":
            zero = np.zeros(np.broadcast_shapes(np.shape(v_x), np.shape(self.g)))
            return zero, zero - self.g
        if self.drag == "linear":
            return -self.parameter * v_x, -self.g - self.parameter * v_y
        drag = self.g / self.parameter**2 * np.hypot(v_x, v_y)
        return -drag * v_x, -self.g - drag * v_y

    def acceleration_at(self, t: u.Quantity) -> tuple[u.Quantity, u.Quantity]:
        """(a_x, a_y) (m/s2) at time t: (0, -g) without drag, (-b v_x, -g - b v_y) with linear drag; quadratic drag
        has no closed-form v(t) (see launch_acceleration and landing_acceleration)."""
        v_x, v_y = (q.to_value(units.M_PER_S) for q in self.velocity_at(t))
        a_x, a_y = self._acceleration(v_x, v_y)
        return a_x << ACCELERATION, a_y << ACCELERATION

    @cached_property
    def launch_acceleration(self) -> u.Quantity:
        """|a| (m/s2) at launch, under any drag law: g without drag."""
        return np.hypot(*self._acceleration(*self._components)) << ACCELERATION

    @cached_property
    def landing_acceleration(self) -> u.Quantity:
        """|a| (m/s2) at landing, under any drag law, from the landing speed and angle."""
        speed, angle = self.landing_speed.to_value(units.M_PER_S), self.landing_angle.to_value(units.RAD)
        return np.hypot(*self._acceleration(speed * np.cos(angle), speed * np.sin(angle))) << ACCELERATION

    def _times(self, t):
        if self.drag == "quadratic":
            raise OrbitDomainError("quadratic drag has no closed-form x(t): use path() for the trajectory")
        return non_negative(t, units.S, "time t")

    def path(self, samples: int = 200) -> tuple[u.Quantity, u.Quantity]:
        """(x, y) (m) at `samples` points from launch to landing, for one launch (for plots)."""
        if self.speed.shape != ():
            raise OrbitDomainError(f"path() draws one launch; this Projectile holds {self.speed.shape}")
        if self.drag != "quadratic":
            return self.position_at(np.linspace(0.0, 1.0, samples) * self.time_of_flight)
        if abs(float(self.angle)) >= np.pi / 2 or float(self.speed) == 0:
            ys = np.linspace(float(self.apex_height.value), 0.0, samples)
            return np.zeros(samples) << units.M, ys << units.M
        landing = np.tan(float(self.landing_angle.value))
        slopes = np.linspace(np.tan(float(self.angle)), landing, samples)
        points = [core.quadratic_drag_state(float(self.speed), float(self.angle), float(self.height),
                                            float(self.parameter), float(self.g), p) for p in slopes]
        x, y = np.array([p[1] for p in points]), np.array([p[2] for p in points])
        return x << units.M, y << units.M

    def __repr__(self) -> str:
        """E.g. "Projectile(v = 20 m / s, angle = 45 deg, h = 0 m, no drag, range = 40.78876 m)"."""
        drag = {"none": lambda: "no drag",
                "linear": lambda: "linear drag b = " + display.values_text(self.parameter, 6) + " 1 / s",
                "quadratic": lambda: "quadratic drag v_t = " + display.summary(self.terminal_speed, unit=units.M_PER_S)}
        return display.one_line("Projectile", "v = " + display.summary(self.speed << units.M_PER_S,
                                                                          unit=units.M_PER_S),
                                "angle = " + display.summary(self.angle << units.RAD),
                                "h = " + display.summary(self.height << units.M, unit=u.m), drag[self.drag](),
                                "range = " + display.summary(self.range, unit=u.m))

    def quantities(self, only: Iterable[str] | None = None) -> dict[str, u.Quantity]:
        """{snake_case name: Quantity} (or `only` those)."""
        return attribute_table(self, PROJECTILE_NAMES, only)


PROJECTILE_NAMES = ["time_of_flight", "range", "apex_time", "apex_height", "apex_distance", "landing_speed",
                    "landing_angle", "terminal_speed", "launch_acceleration", "landing_acceleration"]


@dataclass(frozen=True, eq=False, repr=False)
class EffectiveGravity(display.Displayed):
    """Gravity plus the centrifugal acceleration at latitude phi (rad) on a sphere of radius R (m) spinning at
    omega (rad/s), gravity a_g (m/s2) toward its centre (XX.i)."""

    latitude: np.ndarray
    a_g: np.ndarray
    omega: np.ndarray
    radius: np.ndarray

    @classmethod
    def on_earth(cls, latitude: u.Quantity, gravity: u.Quantity | None = None, radius: u.Quantity | None = None,
                 rotation_period: u.Quantity | None = None) -> "EffectiveGravity":
        """At `latitude` in [-90, 90] deg; defaults: R = 6371 km (the notes' mean radius), a_g = G M / R**2 with
        the IAU GM of the Earth, one sidereal day (86164.0905 s)."""
        phi = angle_in(latitude, "latitude", -np.pi / 2, np.pi / 2, "[-pi/2, pi/2]")
        r = np.asarray(EARTH_MEAN_RADIUS) if radius is None else inputs.positive(radius, units.M, "radius R")
        a_g = BODIES["Earth"].gm / r**2 if gravity is None else inputs.positive(gravity, ACCELERATION, "gravity a_g")
        period = (np.asarray(SIDEREAL_DAY) if rotation_period is None
                  else inputs.positive(rotation_period, units.S, "rotation period T"))
        return cls(*np.broadcast_arrays(phi, np.asarray(a_g, dtype=float), 2 * np.pi / period, r))

    @cached_property
    def _components(self):
        return core.effective_gravity(self.a_g, self.omega, self.radius, self.latitude)

    @cached_property
    def toward_equator(self) -> u.Quantity:
        """The horizontal component omega**2 R sin(2 phi) / 2 (m/s2), toward the equator (the
        notes' sign points it toward the pole)."""
        return np.abs(self._components[0]) << ACCELERATION

    @cached_property
    def downward(self) -> u.Quantity:
        """The vertical component a_g - omega**2 R cos**2 phi (m/s2): least at the equator (XX.i)."""
        return self._components[1] << ACCELERATION

    @cached_property
    def magnitude(self) -> u.Quantity:
        """|g_eff| (m/s2)."""
        return np.hypot(*self._components) << ACCELERATION

    @cached_property
    def deflection(self) -> u.Quantity:
        """The angle between the plumb line and the direction to the centre (rad)."""
        return np.arctan2(np.abs(self._components[0]), self._components[1]) << units.RAD

    def __repr__(self) -> str:
        """E.g. "EffectiveGravity(latitude = 45 deg, g_eff = 9.8 m / s2, deflection = 0.1 deg)"."""
        return display.one_line("EffectiveGravity", "latitude = " + display.summary(self.latitude << units.RAD),
                                "g_eff = " + display.summary(self.magnitude),
                                "deflection = " + display.summary(self.deflection))

    def quantities(self, only: Iterable[str] | None = None) -> dict[str, u.Quantity]:
        """{snake_case name: Quantity} (or `only` those)."""
        return attribute_table(self, ["toward_equator", "downward", "magnitude", "deflection"], only)


@dataclass(frozen=True, eq=False, repr=False)
class ConicalPendulum(display.Displayed):
    """A bob on a string of length L (m) circling at angle theta (rad) from the vertical (XX.ii); mass (kg) or
    None (no tension then)."""

    length: np.ndarray
    angle: np.ndarray
    g: np.ndarray
    mass: np.ndarray | None = None

    @classmethod
    def at_angle(cls, length: u.Quantity, angle: u.Quantity, g: u.Quantity | None = None,
                 mass: u.Quantity | None = None) -> "ConicalPendulum":
        """String length, cone angle in [0, 90) deg (0: the bob hangs straight down)."""
        theta = angle_in(angle, "cone angle theta", 0.0, np.pi / 2, "[0, pi/2)")
        m = None if mass is None else inputs.positive(mass, units.KG, "mass m")
        return cls(inputs.positive(length, units.M, "string length L"), theta, gravity(g), m)

    @classmethod
    def at_rate(cls, length: u.Quantity, angular_speed: u.Quantity, g: u.Quantity | None = None,
                mass: u.Quantity | None = None) -> "ConicalPendulum":
        """String length and angular speed, which must exceed sqrt(g / L)."""
        big_l = inputs.positive(length, units.M, "string length L")
        omega = inputs.positive(angular_speed, units.RAD_PER_S, "angular speed omega")
        g_si = gravity(g)
        m = None if mass is None else inputs.positive(mass, units.KG, "mass m")
        return cls(big_l, core.conical_pendulum_angle(g_si, big_l, omega), g_si, m)

    @cached_property
    def angular_speed(self) -> u.Quantity:
        """omega = sqrt(g sec(theta) / L) (rad/s) (XX.ii)."""
        return core.conical_pendulum_rate(self.g, self.length, self.angle) << units.RAD_PER_S

    @cached_property
    def period(self) -> u.Quantity:
        """2 pi / omega (s)."""
        return 2 * np.pi / self.angular_speed.to_value(units.RAD_PER_S) << units.S

    @cached_property
    def speed(self) -> u.Quantity:
        """v = sqrt(g L sin(theta) tan(theta)) (m/s) (XX.ii)."""
        return core.conical_pendulum_speed(self.g, self.length, self.angle) << units.M_PER_S

    @cached_property
    def circle_radius(self) -> u.Quantity:
        """L sin(theta) (m)."""
        return self.length * np.sin(self.angle) << units.M

    @cached_property
    def tension(self) -> u.Quantity:
        """N = m g sec(theta) (N) (XX.ii)."""
        if self.mass is None:
            raise OrbitDomainError("the string tension needs the bob's mass: build it with mass=... kg")
        return self.mass * self.g / np.cos(self.angle) << u.N

    def __repr__(self) -> str:
        """E.g. "ConicalPendulum(L = 1 m, angle = 30 deg, omega = 3.365 rad / s)"."""
        return display.one_line("ConicalPendulum", "L = " + display.summary(self.length << units.M, unit=u.m),
                                "angle = " + display.summary(self.angle << units.RAD),
                                "period = " + display.summary(self.period))

    def quantities(self, only: Iterable[str] | None = None) -> dict[str, u.Quantity]:
        """{snake_case name: Quantity} (or `only` those)."""
        return attribute_table(self, ["angular_speed", "period", "speed", "circle_radius", "tension"], only)
