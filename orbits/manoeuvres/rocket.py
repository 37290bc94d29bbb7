"""Rockets (notes X): the rocket equation with its sign corrected, mass gain, stages and burns at constant thrust.

    >>> import astropy.units as u
    >>> from orbits import Rocket, velocity_change
    >>> velocity_change(-3 * u.km / u.s, 2 * u.kg, 1 * u.kg).round(1)  # ejecting half the mass backwards
    <Quantity 2079.4 m / s>
    >>> saturn = Rocket.staged(  # roughly the Saturn V stack with Apollo
    ...     propellant=[2.1e6, 4.4e5, 1.1e5] * u.kg, structure=[1.3e5, 4.0e4, 1.3e4] * u.kg, payload=45e3 * u.kg,
    ...     isp=[263, 421, 421] * u.s, thrust=[34e6, 5.1e6, 1.0e6] * u.N)
    >>> saturn.delta_v.to(u.km / u.s).round(2)
    <Quantity 12.46 km / s>

One law serves both cases of X (mass gain and rocket): a body whose mass goes from m1 to m2 by taking in or throwing
out matter at velocity v_rel relative to itself changes its velocity by v_rel ln(m2 / m1). The notes' X.ii
prints -v_rel ln(M2 / M1), which would speed a rocket up along its own exhaust. For a rocket, v_rel points
backwards with the exhaust speed v_e = Isp g0, and the gain is Tsiolkovsky's v_e ln(m0 / mf). The burns at
constant thrust match a heyoka integration of m dv/dt = -R v_rel, dm/dt = -R to 1e-15, gravity loss included
(tests/validation/test_manoeuvres_integration.py).
"""

from collections.abc import Iterable
from dataclasses import dataclass
from functools import cached_property

import astropy.units as u
import numpy as np

from orbits._common import display, inputs, units
from orbits._common.constants import STANDARD_GRAVITY
from orbits._common.tables import quantity_table
from orbits.core.checks import check_finite, first_where
from orbits.core.errors import OrbitDomainError
from orbits.core.manoeuvres import rocket as rocket_core

NEWTON = units.KG * units.M / units.S**2
KG_PER_S = units.KG / units.S


def _mass(value, name):
    return inputs.positive(value, units.KG, name)


def velocity_change(v_rel: u.Quantity, m1: u.Quantity, m2: u.Quantity) -> u.Quantity:
    """v2 - v1 = v_rel ln(m2 / m1) (m/s) when the mass goes from m1 to m2 (kg) by matter moving at v_rel (speed,
    any sign or a vector) relative to the body: gained (X.i, m2 > m1) or ejected (X.ii, m2 < m1).

    The same law for both; the notes' rocket case (X.ii) prints the opposite sign, which would push a rocket along
    its exhaust. <= 2 ulp against mpmath (tests/core/test_rocket.py).
    """
    v = units.to_si(v_rel, units.M_PER_S, "relative velocity v_rel")
    check_finite(v, "relative velocity v_rel", "m / s")
    return rocket_core.velocity_change(v, _mass(m1, "mass before m1"), _mass(m2, "mass after m2")) << units.M_PER_S


def propellant_mass(delta_v: u.Quantity, initial_mass: u.Quantity, *, exhaust_speed: u.Quantity | None = None,
                    isp: u.Quantity | None = None) -> u.Quantity:
    """m0 (1 - exp(-dv / v_e)) (kg): the propellant that gives dv (speed) to a vehicle of mass m0 (mass), with the
    exhaust speed or the specific impulse Isp (time, v_e = Isp g0)."""
    dv = inputs.positive(delta_v, units.M_PER_S, "delta-v")
    m0 = _mass(initial_mass, "initial mass m0")
    return rocket_core.propellant_for(dv, _exhaust(exhaust_speed, isp), m0) << units.KG


def _exhaust(exhaust_speed, isp):
    """v_e (m/s) from exactly one of the exhaust speed and the specific impulse (v_e = Isp g0)."""
    if (exhaust_speed is None) == (isp is None):
        raise TypeError("give exactly one of exhaust_speed (e.g. 3 * u.km / u.s) and isp (e.g. 300 * u.s)")
    if isp is not None:
        return rocket_core.exhaust_speed(inputs.positive(isp, units.S, "specific impulse Isp"), STANDARD_GRAVITY)
    return inputs.positive(exhaust_speed, units.M_PER_S, "exhaust speed v_e")


@dataclass(frozen=True, eq=False, repr=False)
class Rocket(display.Displayed):
    """A serial vehicle: float64 SI arrays with the stages on the last axis, bottom stage first.

    exhaust (m/s) is each stage's exhaust speed, ignition and burnout (kg) the whole vehicle's mass when the stage
    lights and when its propellant is gone, thrust (N) each stage's constant thrust or None.
    """

    exhaust: np.ndarray
    ignition: np.ndarray
    burnout: np.ndarray
    thrust: np.ndarray | None = None

    @classmethod
    def single_stage(cls, initial_mass: u.Quantity, final_mass: u.Quantity, *,
                     exhaust_speed: u.Quantity | None = None, isp: u.Quantity | None = None,
                     thrust: u.Quantity | None = None) -> "Rocket":
        """One stage from its initial (wet) and final (dry) masses, exhaust speed or Isp, and optional thrust (N)."""
        m0, mf = _mass(initial_mass, "initial mass m0"), _mass(final_mass, "final mass mf")
        _require_burn(m0, mf)
        force = _thrust(thrust)
        return cls._build(_exhaust(exhaust_speed, isp)[..., None], m0[..., None], mf[..., None],
                          None if force is None else force[..., None])

    @classmethod
    def staged(cls, propellant: u.Quantity, structure: u.Quantity, payload: u.Quantity, *,
               exhaust_speed: u.Quantity | None = None, isp: u.Quantity | None = None,
               thrust: u.Quantity | None = None) -> "Rocket":
        """Stages from their propellant and structure (dry) masses (last axis: bottom stage first), the payload,
        and per-stage (or common) exhaust speed or Isp and thrust; each stage drops its structure at burnout."""
        fuel = np.atleast_1d(_mass(propellant, "stage propellant mass"))  # a scalar is one stage
        dry = np.atleast_1d(_mass(structure, "stage structure mass"))
        ignition, burnout = rocket_core.stage_masses(dry, fuel, _mass(payload, "payload mass"))
        return cls._build(_exhaust(exhaust_speed, isp), ignition, burnout, _thrust(thrust))

    @classmethod
    def _build(cls, exhaust, ignition, burnout, force):
        shape = np.broadcast_shapes(np.shape(exhaust), ignition.shape, np.shape(burnout), np.shape(force))
        exhaust, ignition, burnout = (np.broadcast_to(x, shape).astype(float) for x in (exhaust, ignition, burnout))
        force = None if force is None else np.broadcast_to(force, shape).astype(float)
        return cls(exhaust, ignition, burnout, force)

    @property
    def stages(self) -> int:
        """The number of stages."""
        return self.ignition.shape[-1]

    @cached_property
    def initial_mass(self) -> u.Quantity:
        """m0 (kg): the whole vehicle at lift-off."""
        return self.ignition[..., 0] << units.KG

    @cached_property
    def final_mass(self) -> u.Quantity:
        """mf (kg): what is left when the last stage burns out (its structure and the payload)."""
        return self.burnout[..., -1] << units.KG

    @cached_property
    def exhaust_speed(self) -> u.Quantity:
        """v_e (m/s) of each stage."""
        return self.exhaust << units.M_PER_S

    @cached_property
    def stage_ignition_mass(self) -> u.Quantity:
        """Vehicle mass (kg) as each stage lights."""
        return self.ignition << units.KG

    @cached_property
    def stage_burnout_mass(self) -> u.Quantity:
        """Vehicle mass (kg) as each stage burns out, before it is dropped."""
        return self.burnout << units.KG

    @cached_property
    def stage_mass_ratio(self) -> u.Quantity:
        """m0 / mf (dimensionless) of each stage."""
        return self.ignition / self.burnout << u.one

    @cached_property
    def stage_delta_v(self) -> u.Quantity:
        """v_e ln(m0 / mf) (m/s) of each stage (Tsiolkovsky; X.ii of the notes prints the opposite sign)."""
        return rocket_core.ideal_delta_v(self.exhaust, self.ignition, self.burnout) << units.M_PER_S

    @cached_property
    def delta_v(self) -> u.Quantity:
        """Total sum_k v_e,k ln(m0_k / mf_k) (m/s) in free space."""
        return rocket_core.staged_delta_v(self.exhaust, self.ignition, self.burnout) << units.M_PER_S

    @cached_property
    def stage_mass_flow(self) -> u.Quantity:
        """R = F / v_e (kg/s) of each stage: the notes' rate of fuel consumption (X.ii)."""
        return rocket_core.mass_flow(self._require_thrust("mass flow"), self.exhaust) << KG_PER_S

    @cached_property
    def stage_burn_time(self) -> u.Quantity:
        """(m0 - mf) v_e / F (s) of each stage at its constant thrust."""
        seconds = rocket_core.burn_time(self._require_thrust("burn time"), self.exhaust, self.ignition, self.burnout)
        return seconds << units.S

    @cached_property
    def burn_time(self) -> u.Quantity:
        """The stages' burn times added (s), staging taken as instant."""
        return np.sum(self.stage_burn_time.to_value(units.S), axis=-1) << units.S

    def gravity_loss(self, g: u.Quantity | None = None) -> u.Quantity:
        """g t_b (m/s) lost by a vertical ascent in uniform gravity g (acceleration; default g0 = 9.80665 m/s2).

        Raises OrbitDomainError if a stage's thrust does not exceed the vehicle's weight when it lights."""
        gravity = STANDARD_GRAVITY if g is None else inputs.positive(g, units.M / units.S**2, "gravity g")
        weight = self.ignition * np.asarray(gravity)[..., None]
        thrust = self._require_thrust("gravity loss")
        low = thrust <= weight
        if np.any(low):
            stage = np.argwhere(low)[0][-1] + 1
            force, heavy = first_where(low, thrust, weight)
            raise OrbitDomainError(
                f"stage {stage} thrust F = {force!r} N is not above its weight at ignition m0 g = {heavy!r} N: a "
                f"vertical ascent needs F > m0 g, so the rocket would not lift off")
        return rocket_core.gravity_loss(gravity, self.burn_time.to_value(units.S)) << units.M_PER_S

    def vertical_ascent_speed(self, g: u.Quantity | None = None) -> u.Quantity:
        """v_e ln(m0 / mf) summed, minus g t_b (m/s): the speed at burnout of a vertical climb in uniform g
        (acceleration, default g0), no drag."""
        return self.delta_v - self.gravity_loss(g)

    def _require_thrust(self, quantity):
        if self.thrust is None:
            raise OrbitDomainError(f"{quantity} needs the thrust: build the rocket with thrust=... N")
        return self.thrust

    def __repr__(self) -> str:
        """E.g. "Rocket(3 stages, delta-v = 12.45 km/s, m0 = 2878 t, mf = 58000 kg)"."""
        stages = f"{self.stages} stage" + ("s" if self.stages > 1 else "")
        burn = "" if self.thrust is None else "burn = " + display.summary(self.burn_time)
        return display.one_line("Rocket", stages, "delta-v = " + display.summary(self.delta_v, unit=u.km / u.s),
                                "m0 = " + display.summary(self.initial_mass),
                                "mf = " + display.summary(self.final_mass), burn)

    def quantities(self, only: Iterable[str] | None = None) -> dict[str, u.Quantity]:
        """{snake_case name: Quantity} (or `only` those); without `only`, the thrust-dependent ones are left out
        when there is no thrust."""
        return quantity_table(lambda name: getattr(self, name), ROCKET_NAMES, only)


def _thrust(thrust):
    return None if thrust is None else inputs.positive(thrust, NEWTON, "thrust F")


def _require_burn(m0, mf):
    """Raise unless every initial mass exceeds its final mass (something is burnt)."""
    bad = np.asarray(mf) >= np.asarray(m0)
    if np.any(bad):
        final, initial = first_where(bad, mf, m0)
        raise OrbitDomainError(
            f"final mass mf = {final!r} kg is outside the allowed range (0, m0) kg with the initial mass "
            f"m0 = {initial!r} kg: a rocket ends lighter than it starts")


ROCKET_NAMES = [
    "initial_mass",
    "final_mass",
    "exhaust_speed",
    "stage_ignition_mass",
    "stage_burnout_mass",
    "stage_mass_ratio",
    "stage_delta_v",
    "delta_v",
    "stage_mass_flow",
    "stage_burn_time",
    "burn_time",
]
