"""Oscillations (notes XXV), with astropy units: pendulums with their exact large-amplitude period, damped and driven
oscillators, and motion on a vertical circle.

    >>> import astropy.units as u
    >>> from orbits import Pendulum, VerticalCircle
    >>> swing = Pendulum.simple(1 * u.m, 170 * u.deg)
    >>> swing.period.round(6), swing.small_angle_period.round(6)
    (<Quantity 4.89436 s>, <Quantity 2.006409 s>)
    >>> VerticalCircle.of(1 * u.m, 7 * u.m / u.s).regime  # on a 1 m string sqrt(5 g R) = 7.002 m/s
    'leaves the circle'

The numbers come from orbits.core.mechanics.oscillations: K(m) by the arithmetic-geometric mean (within 1 ulp of
mpmath),
motions checked against heyoka integrations of their equations (accuracy stated there).
"""

from collections.abc import Iterable
from dataclasses import dataclass
from functools import cached_property

import astropy.units as u
import numpy as np

from orbits._common import display, inputs, units
from orbits._common.inputs import gravity, non_negative, signed
from orbits._common.tables import attribute_table
from orbits._common.units import ACCELERATION, DIMENSIONLESS, RATE
from orbits.core.errors import OrbitDomainError
from orbits.core.mechanics import oscillations as core


@dataclass(frozen=True, eq=False, repr=False)
class Pendulum(display.Displayed):
    """A pendulum: small-angle frequency omega0 (rad/s) and amplitude theta0 in [0, pi) (rad) (XXV.iv)."""

    omega0: np.ndarray
    amplitude: np.ndarray

    @classmethod
    def simple(cls, length: u.Quantity, amplitude: u.Quantity, g: u.Quantity | None = None) -> "Pendulum":
        """A bob on a string of `length` released from rest at `amplitude`: omega0 = sqrt(g / L) of
        L theta'' = -g sin(theta) (the notes drop the minus)."""
        omega0 = core.simple_pendulum_frequency(gravity(g), inputs.positive(length, units.M, "length L"))
        return cls(*np.broadcast_arrays(omega0, _amplitude(amplitude)))

    @classmethod
    def physical(cls, mass: u.Quantity, inertia: u.Quantity, distance: u.Quantity, amplitude: u.Quantity,
                 g: u.Quantity | None = None) -> "Pendulum":
        """A rigid body of `mass` and moment `inertia` about the pivot, its centre of mass `distance` below it:
        omega0 = sqrt(m g L / I) (the notes print sqrt(I / (m g L)), which is a time)."""
        omega0 = core.physical_pendulum_frequency(
            inputs.positive(mass, units.KG, "mass m"), gravity(g), inputs.positive(distance, units.M, "distance L"),
            inputs.positive(inertia, units.KG * units.M**2, "moment of inertia I"))
        return cls(*np.broadcast_arrays(omega0, _amplitude(amplitude)))

    @cached_property
    def small_angle_frequency(self) -> u.Quantity:
        """omega0 (rad/s)."""
        return self.omega0 << units.RAD_PER_S

    @cached_property
    def small_angle_period(self) -> u.Quantity:
        """2 pi / omega0 (s)."""
        return 2 * np.pi / self.omega0 << units.S

    @cached_property
    def period(self) -> u.Quantity:
        """T = 4 K(sin**2(theta0 / 2)) / omega0 (s), exact at any amplitude below pi."""
        return core.pendulum_period(self.omega0, self.amplitude) << units.S

    @cached_property
    def period_ratio(self) -> u.Quantity:
        """T / T0 (dimensionless): 1 + theta0**2 / 16 + ... ; 2.439 at 170 degrees."""
        return (self.period / self.small_angle_period).to(DIMENSIONLESS)

    @cached_property
    def amplitude_angle(self) -> u.Quantity:
        """theta0 (rad)."""
        return self.amplitude << units.RAD

    def angle_at(self, t: u.Quantity) -> u.Quantity:
        """theta(t) (rad) released from rest at theta0 at t = 0, exact (Jacobi elliptic functions)."""
        time = signed(t, units.S, "time t")
        return core.pendulum_angle(self.omega0, self.amplitude, time) << units.RAD

    def __repr__(self) -> str:
        """E.g. "Pendulum(amplitude = 170 deg, T = 4.89436 s, T / T0 = 2.439362)"."""
        return display.one_line("Pendulum", "amplitude = " + display.summary(self.amplitude_angle),
                                "T = " + display.summary(self.period, unit=u.s),
                                "T / T0 = " + display.values_text(self.period_ratio.value, 7))

    def quantities(self, only: Iterable[str] | None = None) -> dict[str, u.Quantity]:
        """{snake_case name: Quantity} (or `only` those)."""
        return attribute_table(self, ["amplitude_angle", "small_angle_frequency", "small_angle_period", "period",
                            "period_ratio"], only)


def _amplitude(value):
    """|theta0| (rad) of an amplitude given on either side; refused, as given, unless |theta0| < pi."""
    theta = inputs.angle(value, "amplitude theta0")
    bad = ~(np.abs(theta) < np.pi)
    if np.any(bad):
        given = float(np.asarray(theta)[bad].flat[0])
        raise OrbitDomainError(f"amplitude theta0 = {given!r} rad ({np.degrees(given):.6g} deg) is outside the "
                               f"allowed range (-pi, pi) rad: at pi the pendulum balances upside down and never swings")
    return np.abs(theta)


@dataclass(frozen=True, eq=False, repr=False)
class DampedOscillator(display.Displayed):
    """x'' = -k x - b x' from x(0) = x0, x'(0) = v0: k (1/s2), b (1/s), x0 (m), v0 (m/s) (XXV.v)."""

    k: np.ndarray
    b: np.ndarray
    x0: np.ndarray
    v0: np.ndarray

    @classmethod
    def of(cls, natural_frequency: u.Quantity, damping_rate: u.Quantity, x0: u.Quantity,
           v0: u.Quantity | None = None) -> "DampedOscillator":
        """From omega0 = sqrt(k) (rad/s or 1/s), b (1/s, the notes' b: force -m b x'), x0 and v0 (default 0)."""
        omega0 = inputs.positive(natural_frequency.to(RATE, u.dimensionless_angles())
                                 if isinstance(natural_frequency, u.Quantity) else natural_frequency,
                                 RATE, "natural frequency omega0")
        b = non_negative(damping_rate, RATE, "damping rate b")
        start = signed(x0, units.M, "x0")
        speed = np.zeros(()) if v0 is None else signed(v0, units.M_PER_S, "v0")
        return cls(*np.broadcast_arrays(omega0**2, b, start, speed))

    @cached_property
    def regime(self) -> str:
        """"underdamped" (b**2 < 4k), "critically damped" or "overdamped" (XXV.v); for one oscillator."""
        kinds = np.atleast_1d(core.damping_regime(self.k, self.b))
        return ", ".join(core.REGIMES[int(k)] for k in kinds)

    @cached_property
    def natural_frequency(self) -> u.Quantity:
        """omega0 = sqrt(k) (rad/s)."""
        return np.sqrt(self.k) << units.RAD_PER_S

    @cached_property
    def damped_frequency(self) -> u.Quantity:
        """omega_d = sqrt(4k - b**2) / 2 (rad/s) when underdamped, else 0."""
        return core.damped_frequency(self.k, self.b) << units.RAD_PER_S

    @cached_property
    def quality_factor(self) -> u.Quantity:
        """Q = omega0 / b (dimensionless)."""
        with np.errstate(divide="ignore"):
            return np.sqrt(self.k) / self.b << DIMENSIONLESS

    def position_at(self, t: u.Quantity) -> u.Quantity:
        """x(t) (m), the same formula in every regime."""
        return core.damped_motion(self.k, self.b, self.x0, self.v0, signed(t, units.S, "time t"))[0] << units.M

    def velocity_at(self, t: u.Quantity) -> u.Quantity:
        """x'(t) (m/s)."""
        return core.damped_motion(self.k, self.b, self.x0, self.v0, signed(t, units.S, "time t"))[1] << units.M_PER_S

    def acceleration_at(self, t: u.Quantity) -> u.Quantity:
        """x''(t) = -k x - b x' (m/s2), the equation of motion evaluated on the solution."""
        x, v = core.damped_motion(self.k, self.b, self.x0, self.v0, signed(t, units.S, "time t"))
        return -self.k * x - self.b * v << ACCELERATION

    @cached_property
    def initial_acceleration(self) -> u.Quantity:
        """x''(0) = -k x0 - b v0 (m/s2)."""
        return -self.k * self.x0 - self.b * self.v0 << ACCELERATION

    def specific_energy_at(self, t: u.Quantity) -> u.Quantity:
        """(K + U) / m = x'**2 / 2 + k x**2 / 2 (J/kg), the notes' damped energy per unit mass."""
        x, v = core.damped_motion(self.k, self.b, self.x0, self.v0, signed(t, units.S, "time t"))
        return 0.5 * v * v + 0.5 * self.k * x * x << units.J_PER_KG

    def __repr__(self) -> str:
        """E.g. "DampedOscillator(underdamped, omega0 = 1.732051 rad / s, b = 1.1 1 / s)"."""
        return display.one_line("DampedOscillator", self.regime,
                                "omega0 = " + display.values_text(np.sqrt(self.k), 7) + " rad / s",
                                "b = " + display.values_text(self.b, 7) + " 1 / s")

    def quantities(self, only: Iterable[str] | None = None) -> dict[str, u.Quantity]:
        """{snake_case name: Quantity} (or `only` those)."""
        return attribute_table(self, ["natural_frequency", "damped_frequency", "quality_factor",
                                      "initial_acceleration"], only)


@dataclass(frozen=True, eq=False, repr=False)
class DrivenOscillator(display.Displayed):
    """x'' + b x' + omega0**2 x = (F0 / m) cos(w t): omega0, w (rad/s), b (1/s), F0 / m (m/s2) (XXV.vii)."""

    omega0: np.ndarray
    b: np.ndarray
    force_per_mass: np.ndarray
    drive: np.ndarray

    @classmethod
    def of(cls, natural_frequency: u.Quantity, damping_rate: u.Quantity, force_per_mass: u.Quantity,
           drive_frequency: u.Quantity) -> "DrivenOscillator":
        """From omega0, b, F0 / m (acceleration) and the driving frequency w."""
        def frequency(value, name):
            if isinstance(value, u.Quantity):
                value = value.to(RATE, u.dimensionless_angles())
            return inputs.positive(value, RATE, name)

        return cls(*np.broadcast_arrays(
            frequency(natural_frequency, "natural frequency omega0"), non_negative(damping_rate, RATE, "damping b"),
            inputs.positive(force_per_mass, ACCELERATION, "force per mass F0 / m"),
            frequency(drive_frequency, "driving frequency w")))

    @cached_property
    def amplitude(self) -> u.Quantity:
        """A = (F0 / m) / sqrt((omega0**2 - w**2)**2 + b**2 w**2) (m)."""
        with np.errstate(divide="ignore"):
            return core.driven_amplitude(self.omega0, self.b, self.force_per_mass, self.drive) << units.M

    @cached_property
    def phase_lag(self) -> u.Quantity:
        """delta (rad) in [0, pi]: x = A cos(w t - delta); pi/2 at w = omega0."""
        return core.driven_phase_lag(self.omega0, self.b, self.drive) << units.RAD

    @cached_property
    def velocity_amplitude(self) -> u.Quantity:
        """w A (m/s): largest at w = omega0 (XXV.vii)."""
        return self.drive * self.amplitude.to_value(units.M) << units.M_PER_S

    @cached_property
    def resonance_frequency(self) -> u.Quantity:
        """sqrt(omega0**2 - b**2 / 2) (rad/s), where A peaks (0: no peak)."""
        return core.displacement_resonance(self.omega0, self.b) << units.RAD_PER_S

    @cached_property
    def quality_factor(self) -> u.Quantity:
        """Q = omega0 / b (dimensionless)."""
        with np.errstate(divide="ignore"):
            return self.omega0 / self.b << DIMENSIONLESS

    @cached_property
    def acceleration_amplitude(self) -> u.Quantity:
        """w**2 A (m/s2), the steady state's largest acceleration."""
        return self.drive**2 * self.amplitude.to_value(units.M) << ACCELERATION

    def position_at(self, t: u.Quantity) -> u.Quantity:
        """The steady state A cos(w t - delta) (m)."""
        time = signed(t, units.S, "time t")
        return core.driven_steady_state(self.omega0, self.b, self.force_per_mass, self.drive, time)[0] << units.M

    def velocity_at(self, t: u.Quantity) -> u.Quantity:
        """The steady state's velocity -w A sin(w t - delta) (m/s)."""
        time = signed(t, units.S, "time t")
        return core.driven_steady_state(self.omega0, self.b, self.force_per_mass, self.drive, time)[1] << \
            units.M_PER_S

    def acceleration_at(self, t: u.Quantity) -> u.Quantity:
        """The steady state's acceleration -w**2 A cos(w t - delta) (m/s2), which with the velocity and position
        satisfies x'' + b x' + omega0**2 x = (F0 / m) cos(w t)."""
        time = signed(t, units.S, "time t")
        x, _ = core.driven_steady_state(self.omega0, self.b, self.force_per_mass, self.drive, time)
        return -self.drive**2 * x << ACCELERATION

    def __repr__(self) -> str:
        """E.g. "DrivenOscillator(w = 2 rad / s, A = 3.4 m, lag = 90 deg)"."""
        return display.one_line("DrivenOscillator", "w = " + display.values_text(self.drive, 7) + " rad / s",
                                "A = " + display.summary(self.amplitude, unit=u.m),
                                "lag = " + display.summary(self.phase_lag))

    def quantities(self, only: Iterable[str] | None = None) -> dict[str, u.Quantity]:
        """{snake_case name: Quantity} (or `only` those)."""
        return attribute_table(self, ["amplitude", "phase_lag", "velocity_amplitude", "acceleration_amplitude",
                                      "resonance_frequency", "quality_factor"], only)


SUPPORTS = ("string", "rod")


@dataclass(frozen=True, eq=False, repr=False)
class VerticalCircle(display.Displayed):
    """A body on a vertical circle of radius R (m) with speed u (m/s) at the lowest point, gravity g (m/s2), held by
    a string or the inside of a track (N >= 0) or by a rod (N of either sign); mass (kg) or None (XXV.vi)."""

    radius: float
    u: float
    g: float
    mass: float | None = None
    support: str = "string"

    @classmethod
    def of(cls, radius: u.Quantity, bottom_speed: u.Quantity, g: u.Quantity | None = None,
           mass: u.Quantity | None = None, support: str = "string") -> "VerticalCircle":
        """From R, u (>= 0), g (default 9.80665 m/s2), the mass (for forces) and the support, string or rod."""
        if support not in SUPPORTS:
            raise OrbitDomainError(f"support {support!r} is not one of {', '.join(SUPPORTS)}")
        r = inputs.single(inputs.positive, radius, units.M, "radius R")
        speed = float(non_negative(bottom_speed, units.M_PER_S, "bottom speed u"))
        m = None if mass is None else inputs.single(inputs.positive, mass, units.KG, "mass m")
        return cls(r, speed, float(gravity(g)), m, support)

    @property
    def _gr(self):
        return self.g * self.radius

    @cached_property
    def regime(self) -> str:
        """"loops", "leaves the circle" (string only), "swings", "reaches the top" (rod at u = 2 sqrt(g R)) or
        "at rest". A string loops from u = sqrt(5 g R) and leaves the circle above sqrt(2 g R), a rod loops above
        2 sqrt(g R); at 2 sqrt(g R) exactly the rod creeps up to the top, which the notes count as swinging."""
        u2, gr = self.u * self.u, self._gr
        if self.u == 0:
            return "at rest"
        if self.support == "string":
            if u2 >= 5 * gr:
                return "loops"
            return "leaves the circle" if u2 > 2 * gr else "swings"
        if u2 > 4 * gr:
            return "loops"
        return "reaches the top" if u2 == 4 * gr else "swings"

    @cached_property
    def turning_angle(self) -> u.Quantity:
        """theta_m = arccos(1 - u**2 / (2 g R)) (rad), where a swinging body stops (the notes print
        arccos(u**2 / (2 g R)))."""
        if self.regime not in ("swings", "reaches the top", "at rest"):
            raise OrbitDomainError(f"the body {self.regime}: it has no turning angle")
        return core.turning_angle(self.u, self.g, self.radius) << units.RAD

    @cached_property
    def leaving_angle(self) -> u.Quantity:
        """theta with N = 0, cos(theta) = (2 g R - u**2) / (3 g R) (rad), where a string slackens: beyond the
        horizontal diameter, where the notes place it."""
        if self.regime != "leaves the circle":
            raise OrbitDomainError(f"the body {self.regime}: it does not leave the circle")
        return core.leaving_angle(self.u, self.g, self.radius) << units.RAD

    @cached_property
    def period(self) -> u.Quantity:
        """T1 once round (looping) or T2 (swinging) (s), by the AGM (XXV.vi)."""
        if self.regime == "loops":
            return core.loop_period(self.u, self.g, self.radius) << units.S
        if self.regime == "swings":
            return core.swing_period(self.u, self.g, self.radius) << units.S
        raise OrbitDomainError(f"the body {self.regime}: its motion is not periodic")

    def _require_top(self):
        if self.regime not in ("loops", "reaches the top"):
            raise OrbitDomainError(f"the body {self.regime}: it never reaches the top of the circle")

    @cached_property
    def speed_at_top(self) -> u.Quantity:
        """sqrt(u**2 - 4 g R) (m/s), for a body that gets there."""
        self._require_top()
        return core.circle_speed(self.u, self.g, self.radius, np.pi) << units.M_PER_S

    @cached_property
    def normal_force_at_top(self) -> u.Quantity:
        """N = m (u**2 - 5 g R) / R (N) toward the centre, for a body that gets there."""
        self._require_top()
        return self.normal_force_at(np.pi << units.RAD)

    @cached_property
    def normal_force_at_bottom(self) -> u.Quantity:
        """N = m (u**2 + g R) / R (N)."""
        return self.normal_force_at(0.0 << units.RAD)

    def speed_at(self, theta: u.Quantity) -> u.Quantity:
        """v = sqrt(u**2 - 2 g R (1 - cos(theta))) (m/s) at angle theta from the bottom (NaN beyond reach)."""
        return core.circle_speed(self.u, self.g, self.radius, inputs.angle(theta, "angle theta")) << units.M_PER_S

    def acceleration_at(self, theta: u.Quantity) -> tuple[u.Quantity, u.Quantity]:
        """(centripetal v**2 / R toward the centre, tangential -g sin(theta) along the motion) (m/s2) at angle theta
        from the bottom (NaN beyond reach); |a| = hypot of the two."""
        angle = inputs.angle(theta, "angle theta")
        v = core.circle_speed(self.u, self.g, self.radius, angle)
        return v * v / self.radius << ACCELERATION, -self.g * np.sin(angle) << ACCELERATION

    @cached_property
    def acceleration_at_bottom(self) -> u.Quantity:
        """u**2 / R (m/s2), all centripetal."""
        return self.u * self.u / self.radius << ACCELERATION

    @cached_property
    def acceleration_at_top(self) -> u.Quantity:
        """(u**2 - 4 g R) / R (m/s2), all centripetal, for a body that gets there."""
        self._require_top()
        return self.acceleration_at(np.pi << units.RAD)[0]

    def normal_force_at(self, theta: u.Quantity) -> u.Quantity:
        """N = (m / R)(u**2 - 2 g R + 3 g R cos(theta)) (N), toward the centre (the
        notes print - m g cos(theta) and 1 g R cos(theta))."""
        if self.mass is None:
            raise OrbitDomainError("the normal force needs the body's mass: build it with mass=... kg")
        angle = inputs.angle(theta, "angle theta")
        return core.circle_normal_force(self.mass, self.u, self.g, self.radius, angle) << u.N

    def __repr__(self) -> str:
        """E.g. "VerticalCircle(R = 1 m, u = 7 m / s, string, leaves the circle)"."""
        return display.one_line("VerticalCircle", f"R = {display.number(self.radius)} m",
                                f"u = {display.number(self.u)} m / s", self.support, self.regime)

    def quantities(self, only: Iterable[str] | None = None) -> dict[str, u.Quantity]:
        """{snake_case name: Quantity} (or `only` those); without `only`, what this motion lacks is left out."""
        return attribute_table(self, ["turning_angle", "leaving_angle", "period", "speed_at_top",
                                      "acceleration_at_bottom", "acceleration_at_top", "normal_force_at_bottom",
                                      "normal_force_at_top"], only)
