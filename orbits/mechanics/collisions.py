"""Collisions of two bodies with a coefficient of restitution (notes IX), with astropy units.

    >>> import astropy.units as u
    >>> from orbits import Collision, energy_transfer
    >>> hit = Collision.head_on(2 * u.kg, 3 * u.m / u.s, 1 * u.kg, 0 * u.m / u.s, restitution=1)
    >>> hit.velocity1_after, hit.velocity2_after
    (<Quantity 1. m / s>, <Quantity 4. m / s>)
    >>> energy_transfer(0.5).round(6)  # elastic: 4 r / (1 + r)**2, 8/9 at r = 1/2
    <Quantity 0.888889>

A head-on collision moves along a line (velocities are signed numbers); an oblique one takes 2-D or 3-D velocity
vectors, and the impulse acts along the relative velocity (the notes' model, IX.xiii, which holds for a head-on
impact of smooth spheres) or along a given contact normal (for an oblique impact, the line of centres). The
numbers come from orbits.core.mechanics.collisions (accuracy stated there).
"""

from collections.abc import Iterable
from dataclasses import dataclass
from functools import cached_property

import astropy.units as u
import numpy as np

from orbits._common import display, inputs, units
from orbits._common.constants import Body
from orbits._common.inputs import planar_vector, signed
from orbits._common.tables import attribute_table
from orbits._common.units import DIMENSIONLESS
from orbits.core.checks import require_positive
from orbits.core.mechanics import collisions as core


def _restitution(value):
    e = units.to_number(value, "coefficient of restitution e")
    core.check_restitution(e)
    return e


def _masses(m1, m2):
    return inputs.positive(m1, units.KG, "mass m1"), inputs.positive(m2, units.KG, "mass m2")


@dataclass(frozen=True, eq=False, repr=False)
class Collision(display.Displayed):
    """A two-body collision: float64 SI fields m1, m2 (kg), v1, v2 (m/s: (...) along a line, or (..., 2|3)
    vectors), e (restitution) and `normal` (the line of impact, None: along the relative velocity)."""

    m1: np.ndarray
    m2: np.ndarray
    v1: np.ndarray
    v2: np.ndarray
    e: np.ndarray
    vectors: bool = False
    normal: np.ndarray | None = None

    @classmethod
    def head_on(cls, m1: u.Quantity, v1: u.Quantity, m2: u.Quantity, v2: u.Quantity,
                restitution: float | u.Quantity = 1.0) -> "Collision":
        """Two bodies on a line (IX.vii-xi): masses (mass), signed velocities (speed), restitution e in [0, 1]."""
        mass1, mass2 = _masses(m1, m2)
        first, second = signed(v1, units.M_PER_S, "velocity v1"), signed(v2, units.M_PER_S, "velocity v2")
        core.require_relative_motion(np.abs(first - second))  # as oblique() refuses it
        return cls(mass1, mass2, first, second, _restitution(restitution))

    @classmethod
    def oblique(cls, m1: u.Quantity, v1: u.Quantity, m2: u.Quantity, v2: u.Quantity,
                restitution: float | u.Quantity = 1.0, normal=None) -> "Collision":
        """Two bodies with 2-D or 3-D velocity vectors (IX.xiii): the impulse acts along `normal` (a direction:
        plain numbers or a Quantity), by default along v1 - v2, the notes' model; raises if they do not approach."""
        mass1, mass2 = _masses(m1, m2)
        a, b = planar_vector(v1, units.M_PER_S, "velocity v1"), planar_vector(v2, units.M_PER_S, "velocity v2")
        if a.shape[-1] != b.shape[-1]:
            raise ValueError(f"velocities v1 and v2 must have the same number of components; got {a.shape[-1]} "
                             f"and {b.shape[-1]}")
        line = None
        if normal is not None:
            line = np.asarray(normal.value if isinstance(normal, u.Quantity) else normal, dtype=float)
            if line.shape[-1:] != a.shape[-1:]:
                raise ValueError(f"normal must have {a.shape[-1]} components like the velocities")
        collision = cls(mass1, mass2, a, b, _restitution(restitution), vectors=True, normal=line)
        _ = collision._after  # check now that the bodies approach along the line of impact
        return collision

    @cached_property
    def _after(self):
        if self.vectors:
            return core.oblique_velocities_after(self.m1, self.v1, self.m2, self.v2, self.e, self.normal)
        return core.velocities_after(self.m1, self.v1, self.m2, self.v2, self.e)

    @cached_property
    def restitution(self) -> u.Quantity:
        """e (dimensionless): (v2' - v1') / (v1 - v2) along the line of impact (IX.vi, which writes it as a
        quotient of two vectors)."""
        return self.e << DIMENSIONLESS

    @cached_property
    def reduced_mass(self) -> u.Quantity:
        """mu = m1 m2 / (m1 + m2) (kg) (IX.iii)."""
        return core.reduced_mass(self.m1, self.m2) << units.KG

    @cached_property
    def center_of_mass_velocity(self) -> u.Quantity:
        """v_c = (m1 v1 + m2 v2) / (m1 + m2) (m/s), unchanged by the collision (IX.ii)."""
        return core.center_of_mass_velocity(self.m1, self.v1, self.m2, self.v2) << units.M_PER_S

    @cached_property
    def velocity1_after(self) -> u.Quantity:
        """v1' (m/s) (IX.xi, xiii)."""
        return self._after[0] << units.M_PER_S

    @cached_property
    def velocity2_after(self) -> u.Quantity:
        """v2' (m/s) (IX.xi, xiii)."""
        return self._after[1] << units.M_PER_S

    @cached_property
    def momentum(self) -> u.Quantity:
        """m1 v1 + m2 v2 (kg m/s), the same before and after."""
        m1, m2 = (self.m1[..., None], self.m2[..., None]) if self.vectors else (self.m1, self.m2)
        return m1 * self.v1 + m2 * self.v2 << units.KG * units.M_PER_S

    def _kinetic(self, m, v):
        return core.kinetic_energy(m, v, self.vectors)

    @cached_property
    def kinetic_energy_before(self) -> u.Quantity:
        """K = m1 |v1|**2 / 2 + m2 |v2|**2 / 2 (J)."""
        return self._kinetic(self.m1, self.v1) + self._kinetic(self.m2, self.v2) << units.J

    @cached_property
    def kinetic_energy_after(self) -> u.Quantity:
        """K' (J), at most K (IX.ii prints the order of before and after the other way round)."""
        return self._kinetic(self.m1, self._after[0]) + self._kinetic(self.m2, self._after[1]) << units.J

    @cached_property
    def kinetic_energy1_before(self) -> u.Quantity:
        """K1 = m1 |v1|**2 / 2 (J), body 1's kinetic energy before."""
        return self._kinetic(self.m1, self.v1) << units.J

    @cached_property
    def kinetic_energy2_before(self) -> u.Quantity:
        """K2 = m2 |v2|**2 / 2 (J), body 2's kinetic energy before."""
        return self._kinetic(self.m2, self.v2) << units.J

    @cached_property
    def kinetic_energy1_after(self) -> u.Quantity:
        """K1' = m1 |v1'|**2 / 2 (J), body 1's kinetic energy after."""
        return self._kinetic(self.m1, self._after[0]) << units.J

    @cached_property
    def kinetic_energy2_after(self) -> u.Quantity:
        """K2' = m2 |v2'|**2 / 2 (J), body 2's kinetic energy after: energy_transfer(m1 / m2, e) of K1 when body 2
        starts at rest."""
        return self._kinetic(self.m2, self._after[1]) << units.J

    @cached_property
    def internal_kinetic_energy_before(self) -> u.Quantity:
        """K_int = mu |v1 - v2|**2 / 2 (J), the kinetic energy in the centre-of-mass frame (IX.iv)."""
        return core.internal_kinetic_energy(self.m1, self.v1, self.m2, self.v2, self.vectors) << units.J

    @cached_property
    def internal_kinetic_energy_after(self) -> u.Quantity:
        """K_int' (J): e**2 K_int for a head-on collision (IX.xi); 0 when completely inelastic."""
        a1, a2 = self._after
        return core.internal_kinetic_energy(self.m1, a1, self.m2, a2, self.vectors) << units.J

    @cached_property
    def energy_lost(self) -> u.Quantity:
        """K - K' = (1 - e**2) mu v_n**2 / 2 (J), v_n the approach speed along the line of impact (0 exactly when
        elastic)."""
        return core.energy_lost(self.m1, self.v1, self.m2, self.v2, self.e, self.normal, self.vectors) << units.J

    def __repr__(self) -> str:
        """E.g. "Collision(m1 = 2 kg, m2 = 1 kg, e = 1, v1' = 1 m / s, v2' = 4 m / s)"."""
        def speed(q):
            return display.values_text(q.to_value(units.M_PER_S), 4) + " m / s"

        return display.one_line(
            "Collision", "m1 = " + display.summary(self.m1 << units.KG, unit=u.kg),
            "m2 = " + display.summary(self.m2 << units.KG, unit=u.kg), "e = " + display.values_text(self.e, 4),
            "v1' = " + speed(self.velocity1_after), "v2' = " + speed(self.velocity2_after))

    def quantities(self, only: Iterable[str] | None = None) -> dict[str, u.Quantity]:
        """{snake_case name: Quantity} (or `only` those)."""
        return attribute_table(self, COLLISION_NAMES, only)


COLLISION_NAMES = [
    "restitution", "reduced_mass", "center_of_mass_velocity", "velocity1_after", "velocity2_after", "momentum",
    "kinetic_energy1_before", "kinetic_energy2_before", "kinetic_energy1_after", "kinetic_energy2_after",
    "kinetic_energy_before", "kinetic_energy_after", "internal_kinetic_energy_before",
    "internal_kinetic_energy_after", "energy_lost",
]


def energy_transfer(mass_ratio: float | u.Quantity, restitution: float | u.Quantity = 1.0) -> u.Quantity:
    """K2' / K1 = (1 + e)**2 r / (1 + r)**2 (dimensionless): the share of its kinetic energy a body of mass m1 gives
    to a body of mass m2 at rest, r = m1 / m2 (IX.viii; elastic: 4 r / (1 + r)**2 = 4 m1 m2 / (m1 + m2)**2,
    where the notes' second form drops the 4)."""
    r = units.to_number(mass_ratio, "mass ratio r = m1 / m2")
    require_positive(r, "mass ratio r = m1 / m2", "(dimensionless)")
    return core.energy_transfer_ratio(r, _restitution(restitution)) << DIMENSIONLESS


def slingshot(planet_velocity: u.Quantity, craft_velocity: u.Quantity,
              restitution: float | u.Quantity = 1.0) -> u.Quantity:
    """v' = (1 + e) U - e v (m/s): a light body bouncing off a planet moving at U, the notes' view of a gravity
    assist as an elastic collision with an infinitely heavy body (IX.vii, m1 >> m2: v' = 2 U - v). Scalars along a
    line or vectors; compare orbits.Flyby, of which this is the limit of a deflection of 180 degrees."""
    planet = signed(planet_velocity, units.M_PER_S, "planet velocity U")
    craft = signed(craft_velocity, units.M_PER_S, "craft velocity v")
    return core.bounce_off_moving_wall(planet, craft, _restitution(restitution)) << units.M_PER_S


def elastic_collision(m1: Body | str | u.Quantity, m2: Body | str | u.Quantity | None, v1: u.Quantity,
                      v2: u.Quantity) -> tuple[u.Quantity, u.Quantity]:
    """(v1', v2') (m/s) after a head-on elastic collision (IX.vii) of masses m1, m2 (names, masses or GMs; m2 =
    None for a massless probe) moving at v1, v2 (speeds along the line, any sign). A planet (m1) meeting a probe
    head on sends it back at 2 v1 - v2: the slingshot."""
    gm1 = inputs.gravitational_parameter(m1, "mass m1")
    gm2 = 0.0 if m2 is None else inputs.gravitational_parameter(m2, "mass m2")
    speeds = [signed(v, units.M_PER_S, name) for v, name in ((v1, "velocity v1"), (v2, "velocity v2"))]
    after_1, after_2 = core.velocities_after(gm1, speeds[0], gm2, speeds[1], 1.0)
    return after_1 << units.M_PER_S, after_2 << units.M_PER_S
