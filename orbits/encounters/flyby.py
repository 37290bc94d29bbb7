"""Flyby: a hyperbolic encounter from the speed at infinity and the impact parameter (XXI.vi, XXII.vi).

    >>> import astropy.units as u
    >>> from orbits import Flyby
    >>> pass_ = Flyby.past("Jupiter", v_inf=5.6 * u.km / u.s, periapsis=200_000 * u.km)
    >>> pass_.impact_parameter.to(u.km).round(0)
    <Quantity 1286818. km>
    >>> pass_.deflection_angle.to(u.deg).round(2)
    <Quantity 144.66 deg>

Flyby.past is a body passing a fixed star or planet (XXI.vi: mu = G M, the notes' u = v_inf); Flyby.between is
two finite masses meeting from infinity (XXII.vi: mu = G (m1 + m2), v_inf their relative speed, the notes'
(m + M) eta), whose stars `star1`, `star2` move on the relative hyperbola scaled by m_j / (m1 + m2) about the
centre of mass (each itself a Flyby with the fixed-centre parameter G m_j**3 / (m1 + m2)**2, so its speeds,
distances and angular momentum are the star's own; the notes' M zeta and m zeta are their periapsis speeds).
Give the impact parameter b, or the wanted closest approach (`periapsis`) and b is solved for. Every formula
is cancellation-free (orbits.core.encounters.flyby); IAS15 and heyoka integrations from 2000 b agree to 1e-10
(tests/api/test_flyby_api.py).
"""

import warnings
from collections.abc import Iterable
from dataclasses import dataclass
from functools import cached_property

import astropy.units as u
import numpy as np

from orbits._common import display, inputs, units
from orbits._common.constants import Body, G
from orbits._common.tables import quantity_table
from orbits.core.encounters import binary as binary_core
from orbits.core.encounters import flyby as flyby_core
from orbits.core.errors import InsideBodyWarning, OrbitDomainError
from orbits.twobody.orbit import PRIMARY, Orbit


def _impact_parameter(b, periapsis, v_inf, mu):
    """b (m) from exactly one of b and the wanted closest approach `periapsis` (length Quantities)."""
    if (b is None) == (periapsis is None):
        raise TypeError("give exactly one of the impact parameter b and the closest approach periapsis")
    if b is not None:
        return inputs.positive(b, units.M, "impact parameter b")
    value = inputs.positive(periapsis, units.M, "closest approach periapsis")
    return flyby_core.impact_parameter(value, v_inf, mu)


def _speed_at_infinity(v_inf):
    value = inputs.positive(v_inf, units.M_PER_S, "speed at infinity v_inf")
    return value


@dataclass(frozen=True, eq=False, repr=False)
class Flyby(display.Displayed):
    """Hyperbolic encounter(s): float64 SI fields mu (m3/s2), v_inf (m/s), b (m) that broadcast together.

    `mass` (kg) is the moving body's mass (Flyby.past, optional) or the reduced mass (Flyby.between), used by
    the energies and the angular momentum; gm1, gm2 (m3/s2) are the two masses of Flyby.between (else None).
    """

    mu: np.ndarray
    v_inf: np.ndarray
    b: np.ndarray
    mass: np.ndarray | None = None
    gm1: np.ndarray | None = None
    gm2: np.ndarray | None = None

    def __post_init__(self):
        """An InsideBodyWarning when the closest approach is inside the catalogue body passed (its GM exactly), or
        inside the two bodies' radii added for Flyby.between: a collision, not a flyby."""
        bodies = [self.mu] if self.gm1 is None else [self.gm1, self.gm2]
        q = flyby_core.periapsis_distance(self.b, self.v_inf, self.mu)
        inputs.warn_if_inside(q, [inputs.exact_body(gm) for gm in bodies], "Flyby")

    # ---- constructors -------------------------------------------------------------------------
    @classmethod
    def past(
        cls,
        primary: Body | str | u.Quantity,
        v_inf: u.Quantity,
        b: u.Quantity | None = None,
        *,
        periapsis: u.Quantity | None = None,
        mass: Body | str | u.Quantity | None = None,
    ) -> "Flyby":
        """A body passing a fixed primary (name, Body, mass or GM) at v_inf (speed) with impact parameter b
        (length), or with the closest approach `periapsis` (length) (XXI.vi). `mass` (kg) enables E, L, U, K."""
        mu = inputs.gravitational_parameter(primary, PRIMARY)
        speed = _speed_at_infinity(v_inf)
        impact = _impact_parameter(b, periapsis, speed, mu)
        shape = np.broadcast_shapes(np.shape(mu), speed.shape, impact.shape)
        moving = None if mass is None else inputs.gravitational_parameter(mass, "moving body's mass m") / G
        fields = (np.broadcast_to(x, shape).astype(float) for x in (mu, speed, impact))
        return cls(*fields, mass=_broadcast(moving, shape))

    @classmethod
    def between(
        cls,
        m1: Body | str | u.Quantity,
        m2: Body | str | u.Quantity,
        v_inf: u.Quantity,
        b: u.Quantity | None = None,
        *,
        periapsis: u.Quantity | None = None,
    ) -> "Flyby":
        """Two finite masses (names, Bodies, masses or GMs) meeting at relative speed v_inf with impact parameter b
        or closest approach `periapsis` (XXII.vi); the energies use the reduced mass."""
        gm1, gm2 = inputs.gravitational_parameter(m1, "mass m1"), inputs.gravitational_parameter(m2, "mass m2")
        speed = _speed_at_infinity(v_inf)
        impact = _impact_parameter(b, periapsis, speed, gm1 + gm2)
        shape = np.broadcast_shapes(gm1.shape, gm2.shape, speed.shape, impact.shape)
        gm1, gm2 = np.broadcast_to(gm1, shape).astype(float), np.broadcast_to(gm2, shape).astype(float)
        return cls(
            gm1 + gm2,
            np.broadcast_to(speed, shape).astype(float),
            np.broadcast_to(impact, shape).astype(float),
            mass=binary_core.reduced_mass(gm1, gm2) / G,
            gm1=gm1,
            gm2=gm2,
        )

    # ---- the hyperbola --------------------------------------------------------------------------
    @property
    def shape(self) -> tuple[int, ...]:
        """Batch shape of the encounters held."""
        return self.b.shape

    @cached_property
    def impact_parameter(self) -> u.Quantity:
        """b (m): distance from the attracting centre to the incoming asymptote."""
        return self.b << units.M

    @cached_property
    def speed_at_infinity(self) -> u.Quantity:
        """v_inf (m/s): relative speed far away (the notes' u; (m + M) eta for two masses)."""
        return self.v_inf << units.M_PER_S

    @cached_property
    def eccentricity(self) -> u.Quantity:
        """e = sqrt(1 + (b v_inf**2 / mu)**2) (dimensionless)."""
        return flyby_core.eccentricity(self.b, self.v_inf, self.mu) << u.one

    @cached_property
    def semi_major_axis(self) -> u.Quantity:
        """a = -mu / v_inf**2 (m), negative as for every hyperbola in orbits (the notes' a_h = |a|)."""
        return flyby_core.semi_major_axis(self.v_inf, self.mu) << units.M

    @cached_property
    def semilatus_rectum(self) -> u.Quantity:
        """p = (v_inf b)**2 / mu (m)."""
        return flyby_core.semilatus_rectum(self.b, self.v_inf, self.mu) << units.M

    @cached_property
    def periapsis_distance(self) -> u.Quantity:
        """Closest approach R = (sqrt(mu**2 + v_inf**4 b**2) - mu) / v_inf**2 (m), formed without cancellation."""
        return flyby_core.periapsis_distance(self.b, self.v_inf, self.mu) << units.M

    @cached_property
    def periapsis_speed(self) -> u.Quantity:
        """Speed at closest approach w = (sqrt(mu**2 + v_inf**4 b**2) + mu) / (v_inf b) (m/s)."""
        return flyby_core.periapsis_speed(self.b, self.v_inf, self.mu) << units.M_PER_S

    @cached_property
    def deflection_angle(self) -> u.Quantity:
        """Turning angle of the relative velocity, 2 atan(mu / (b v_inf**2)) (rad)."""
        return flyby_core.deflection_angle(self.b, self.v_inf, self.mu) << units.RAD

    @cached_property
    def asymptote_true_anomaly(self) -> u.Quantity:
        """nu_inf = arccos(-1 / e) (rad): true anomaly of the outgoing asymptote."""
        return flyby_core.asymptote_true_anomaly(self.b, self.v_inf, self.mu) << units.RAD

    @cached_property
    def specific_energy(self) -> u.Quantity:
        """E / m = v_inf**2 / 2 (J/kg)."""
        return 0.5 * self.v_inf**2 << units.J_PER_KG

    @cached_property
    def specific_angular_momentum(self) -> u.Quantity:
        """h = L / m = v_inf b = R w (m2/s)."""
        return self.v_inf * self.b << units.M2_PER_S

    @cached_property
    def energy(self) -> u.Quantity:
        """E = m v_inf**2 / 2 (J) (XXI.vi), or mu_red v_inf**2 / 2 = m M (m + M) eta**2 / 2 for two masses (XXII.vi)."""
        return self.specific_energy * (self._require_mass("energy E") << units.KG)

    @cached_property
    def angular_momentum(self) -> u.Quantity:
        """L = m v_inf b (kg m2/s) (XXI.vi), or mu_red v_inf b = m M b eta for two masses (XXII.vi)."""
        return self.specific_angular_momentum * (self._require_mass("angular momentum L") << units.KG)

    def speed_at(self, r: u.Quantity) -> u.Quantity:
        """v = sqrt(v_inf**2 + 2 mu / r) (m/s) at distance r (length) (XXI.vi; (m + M) sigma in XXII.vi)."""
        r_si = inputs.positive(r, units.M, "distance r")
        return flyby_core.speed_at_distance(r_si, self.v_inf, self.mu) << units.M_PER_S

    def potential_energy_at(self, r: u.Quantity) -> u.Quantity:
        """U = -mu m / r (J) at distance r (length): -G M m / r, or -G m1 m2 / r for two masses."""
        r_si = inputs.positive(r, units.M, "distance r")
        return -self.mu * self._require_mass("potential energy U") / r_si << units.J

    def kinetic_energy_at(self, r: u.Quantity) -> u.Quantity:
        """K = E - U = m v_inf**2 / 2 + mu m / r (J) at distance r (length)."""
        return self.energy - self.potential_energy_at(r)

    @cached_property
    def orbit(self) -> Orbit:
        """The relative hyperbola as an Orbit at closest approach (nu = 0), in the xy plane, for state vectors."""
        mass = None if self.mass is None else self.mass << units.KG
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", InsideBodyWarning)  # said once, by the Flyby
            return Orbit.from_elements(self.mu << units.M3_PER_S2, p=self.semilatus_rectum, e=self.eccentricity,
                                       mass=mass)

    # ---- the two stars of Flyby.between (XXII.vi) -----------------------------------------------
    @cached_property
    def star1(self) -> "Flyby":
        """Star 1's hyperbola about the centre of mass (the relative one scaled by m2 / (m1 + m2))."""
        return self._star(self._require_pair("star1")[1], self.gm2, self.gm1)

    @cached_property
    def star2(self) -> "Flyby":
        """Star 2's hyperbola about the centre of mass (the relative one scaled by m1 / (m1 + m2))."""
        return self._star(self._require_pair("star2")[0], self.gm1, self.gm2)

    def _star(self, share, gm_other, gm_own):
        mu = binary_core.star_parameter(gm_other, self.mu)
        return Flyby(mu, share * self.v_inf, share * self.b, mass=gm_own / G)

    def _require_pair(self, quantity):
        if self.gm1 is None:
            raise OrbitDomainError(
                f"{quantity} exists for two finite masses only: build the encounter with Flyby.between(m1, m2, ...)"
            )
        return binary_core.mass_fractions(self.gm1, self.gm2)

    def _require_mass(self, quantity):
        if self.mass is None:
            raise OrbitDomainError(f"{quantity} needs the moving body's mass: build the flyby with mass=... kg")
        return self.mass

    # ---- tables ---------------------------------------------------------------------------------
    def __repr__(self) -> str:
        """E.g. "Flyby(v_inf = 5 km/s, b = 10000 km, deflection = 23.1 deg, q = 6500 km, about Earth)"."""
        return display.one_line(
            "Flyby", "v_inf = " + display.summary(self.speed_at_infinity),
            "b = " + display.summary(self.impact_parameter), "deflection = " + display.summary(self.deflection_angle),
            "q = " + display.summary(self.periapsis_distance), f"about {display.body_name(self.mu)}")

    def quantities(self, only: Iterable[str] | None = None) -> dict[str, u.Quantity]:
        """{snake_case name: Quantity} of the encounter (or `only` those); `star1_<name>`, `star2_<name>` for the
        stars of Flyby.between. Without `only`, quantities this encounter lacks (no mass, no pair) are left out."""
        return quantity_table(self._lookup, QUANTITY_NAMES, only)

    def _lookup(self, name):
        for prefix in ("star1", "star2"):
            if name.startswith(prefix + "_"):
                return getattr(getattr(self, prefix), name[len(prefix) + 1 :])
        return getattr(self, name)


def _broadcast(value, shape):
    return None if value is None else np.broadcast_to(value, shape).astype(float)


FLYBY_NAMES = [
    "impact_parameter",
    "speed_at_infinity",
    "eccentricity",
    "semi_major_axis",
    "semilatus_rectum",
    "periapsis_distance",
    "periapsis_speed",
    "deflection_angle",
    "asymptote_true_anomaly",
    "specific_energy",
    "specific_angular_momentum",
    "energy",
    "angular_momentum",
]

STAR_NAMES = ["impact_parameter", "speed_at_infinity", "periapsis_distance", "periapsis_speed", "angular_momentum"]

QUANTITY_NAMES = FLYBY_NAMES + [f"star1_{n}" for n in STAR_NAMES] + [f"star2_{n}" for n in STAR_NAMES]
