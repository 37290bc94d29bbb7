"""Ring: n equal masses on a regular n-gon, optionally about a central mass (section XXIII of the notes, and
Maxwell's ring), with units.

    >>> import astropy.units as u
    >>> from orbits import Ring
    >>> ring = Ring.from_masses(3, 1 * u.M_sun, 1 * u.AU)
    >>> ring.period.to(u.yr).round(4)  # omega**2 = G m / (sqrt(3) r**3)
    <Quantity 1.3161 yr>

Closed forms come from orbits.core.threebody.rings (each body circles GM_eff = G m S_n / 4 + G M); the linear stability
(growth rate of the most unstable mode, the break-up time of a ring seeded by float64 round-off, the central
mass above which a ring of n >= 7 is stable) from the 4n x 4n rotating-frame linearisation.
The matching N-body problem for rebound and heyoka is built in orbits.validate.builders.
"""

from collections.abc import Iterable
from dataclasses import dataclass
from functools import cached_property

import astropy.units as u
import numpy as np

from orbits._common import display, inputs, units
from orbits._common.constants import Body, G
from orbits._common.tables import quantity_table
from orbits.core.errors import OrbitDomainError
from orbits.core.threebody import rings
from orbits.core.twobody import twobody

#: Relative perturbation that float64 round-off plants in a ring, and the shape deviation called break-up.
ROUND_OFF_SEED = 1e-16
BREAKUP_DEVIATION = 1e-3


@dataclass(frozen=True, eq=False, repr=False)
class Ring(display.Displayed):
    """n bodies of GM `gm` (m3/s2) on a circle of radius `r` (m) about a central `gm_central` (m3/s2, 0 for
    none); gm, r and gm_central are float64 arrays that broadcast together. Build it with Ring.from_masses."""

    n: int
    gm: np.ndarray
    r: np.ndarray
    gm_central: np.ndarray

    @classmethod
    def from_masses(
        cls,
        n: int,
        mass: Body | str | u.Quantity,
        radius: u.Quantity,
        *,
        central_mass: Body | str | u.Quantity | None = None,
    ) -> "Ring":
        """Ring of n (int >= 2) bodies of `mass` each (a mass or GM Quantity, a Body or a name) on a circle of
        `radius` (length), about `central_mass` (same forms, or None).

        TypeError for a non-integer or bool n; OrbitDomainError for n < 2 or a non-positive radius or mass.
        """
        n = rings.check_count(n)
        gm = inputs.gravitational_parameter(mass, "ring body mass m")
        radius_si = inputs.positive(radius, units.M, "ring radius r")
        gm_central = 0.0 if central_mass is None else inputs.gravitational_parameter(central_mass, "central mass M")
        fields = np.broadcast_arrays(gm, radius_si, gm_central)
        return cls(n, *(np.array(x, dtype=float) for x in fields))

    # ---- closed forms (XXIII) -------------------------------------------------------------------
    @cached_property
    def csc_sum(self) -> u.Quantity:
        """S_n = sum_{k=1}^{n-1} csc(pi k / n) (dimensionless), within 3 ulp (math.fsum over k < n/2)."""
        return rings.csc_sum(self.n) << u.one

    @cached_property
    def _gm_eff(self):
        return self.gm * (0.25 * self.csc_sum.value) + self.gm_central

    @cached_property
    def mass(self) -> u.Quantity:
        """m = GM / G (kg) of each ring body."""
        return self.gm / G << units.KG

    @cached_property
    def central_mass_ratio(self) -> u.Quantity:
        """beta = M / m (dimensionless)."""
        return self.gm_central / self.gm << u.one

    @cached_property
    def angular_velocity(self) -> u.Quantity:
        """omega = sqrt((G m S_n / 4 + G M) / r**3) (rad/s)."""
        return twobody.circular_angular_velocity(self.r, self._gm_eff) << units.RAD_PER_S

    @cached_property
    def period(self) -> u.Quantity:
        """T = 2 pi / omega (s)."""
        return 2.0 * np.pi / twobody.circular_angular_velocity(self.r, self._gm_eff) << units.S

    @cached_property
    def speed(self) -> u.Quantity:
        """v = sqrt((G m S_n / 4 + G M) / r) (m/s) of each body about the barycentre."""
        return twobody.circular_speed(self.r, self._gm_eff) << units.M_PER_S

    @cached_property
    def potential_energy(self) -> u.Quantity:
        """U = -n G m**2 S_n / (4 r) - n G M m / r (J): every pair once, zero at infinite separation."""
        return -self.n * self.mass.value * self._gm_eff / self.r << units.J

    @cached_property
    def kinetic_energy(self) -> u.Quantity:
        """K = n m v**2 / 2 = -U / 2 (J)."""
        return 0.5 * self.n * self.mass.value * self._gm_eff / self.r << units.J

    @cached_property
    def energy(self) -> u.Quantity:
        """E = U + K = U / 2 (J), the binding energy."""
        return -0.5 * self.n * self.mass.value * self._gm_eff / self.r << units.J

    @cached_property
    def angular_momentum(self) -> u.Quantity:
        """L = n m v r (kg m2/s) about the barycentre."""
        return self.n * self.mass.value * np.sqrt(self._gm_eff * self.r) << units.KG_M2_PER_S

    def state_vectors(self, phase: u.Quantity = 0 * u.deg) -> tuple[u.Quantity, u.Quantity]:
        """Positions (m) and velocities (m/s) of the n ring bodies, shape (n, 3): body k at angle
        phase + 2 pi k / n in the xy plane, counter-clockwise; the barycentre and central mass at rest at 0."""
        if np.ndim(self.r) != 0:
            raise OrbitDomainError("state_vectors needs a single ring; this object holds an array of them")
        angle = inputs.single(inputs.angle, phase, "phase")
        r, v = rings.state_vectors(self.n, float(self.r), float(self.speed.value), angle)
        return r << units.M, v << units.M_PER_S

    # ---- linear stability -----------------------------------------------------------------------
    @cached_property
    def _beta(self):
        if np.ndim(self.gm_central / self.gm) != 0:
            raise OrbitDomainError("linear stability needs a single ring; this object holds an array of them")
        return float(self.gm_central / self.gm)

    @cached_property
    def _omega(self):
        return float(twobody.circular_angular_velocity(self.r, self._gm_eff))

    @cached_property
    def _growth(self):
        return rings.growth_rate(self.n, self._beta)

    @cached_property
    def eigenvalues(self) -> u.Quantity:
        """Eigenvalues of the 4n x 4n rotating-frame linearisation (1/s), complex, shape (n, 4): row j is the
        Fourier mode j (perturbation of body k proportional to exp(2 pi i j k / n))."""
        return rings.eigenvalues(self.n, self._beta) * self._omega << 1 / u.s

    @cached_property
    def linearly_stable(self) -> bool:
        """True when no mode grows (every |Re lambda| <= 1e-9 omega)."""
        return self._growth[1] is None

    @cached_property
    def growth_rate(self) -> u.Quantity:
        """sigma = largest Re(lambda) (1/s); 0 when linearly stable."""
        return self._growth[0] * self._omega << 1 / u.s

    @cached_property
    def unstable_mode(self) -> u.Quantity:
        """Fourier mode j of the fastest-growing perturbation (dimensionless); OrbitDomainError if stable."""
        self._require_unstable("unstable mode")
        return self._growth[1] << u.one

    @cached_property
    def e_folding_time(self) -> u.Quantity:
        """1 / sigma (s); OrbitDomainError if the ring is linearly stable."""
        self._require_unstable("e-folding time")
        return 1.0 / (self._growth[0] * self._omega) << units.S

    @cached_property
    def breakup_time(self) -> u.Quantity:
        """ln(1e-3 / 1e-16) / sigma (s): the time for float64 round-off (1e-16 relative) to grow to a 1e-3
        deformation at the rate sigma; OrbitDomainError if the ring is linearly stable."""
        self._require_unstable("break-up time")
        return float(rings.breakup_time(self._growth[0], ROUND_OFF_SEED, BREAKUP_DEVIATION)) / self._omega << units.S

    @cached_property
    def central_mass_threshold(self) -> u.Quantity:
        """beta_c m (kg): the smallest central mass that makes this ring linearly stable (n >= 7 only;
        OrbitDomainError otherwise). beta_c / n**3 = 0.4077 (n = 7) ... 0.43504 (n -> infinity)."""
        if np.ndim(self.gm) != 0:
            raise OrbitDomainError("central_mass_threshold needs a single ring; this object holds an array of them")
        return rings.central_mass_threshold(self.n) * float(self.gm) / G << units.KG

    def _require_unstable(self, quantity):
        if self.linearly_stable:
            raise OrbitDomainError(f"{quantity} is defined for unstable rings only; this ring is linearly stable")

    # ---- tables ---------------------------------------------------------------------------------
    def _facts(self) -> list[str]:
        masses = f"{self.n} x " + display.summary(self.gm / G << units.KG)
        central = "" if not np.any(self.gm_central) else "about " + display.summary(self.gm_central / G << units.KG)
        return [masses, central, "r = " + display.summary(self.r << units.M), "T = " + display.summary(self.period)]

    @property
    def title(self) -> str:
        """The ring in words, for a table or a picture: "A ring of 3 x 1 kg: r = 1 m, T = 4.3 h"."""
        masses, central, *rest = self._facts()
        return f"A ring of {masses}{' ' + central if central else ''}: {', '.join(rest)}"

    def __repr__(self) -> str:
        """E.g. "Ring(3 x 1 kg, r = 1 m, T = 4.3 h)", with the central mass when there is one."""
        return display.one_line("Ring", *self._facts())

    def quantities(self, only: Iterable[str] | None = None) -> dict[str, u.Quantity]:
        """{name: Quantity} of the QUANTITY_NAMES this ring has (or `only` those, raising if one is undefined)."""
        return quantity_table(lambda name: getattr(self, name), QUANTITY_NAMES, only)


QUANTITY_NAMES = [
    "csc_sum",
    "central_mass_ratio",
    "angular_velocity",
    "period",
    "speed",
    "potential_energy",
    "kinetic_energy",
    "energy",
    "angular_momentum",
    "growth_rate",
    "unstable_mode",
    "e_folding_time",
    "breakup_time",
    "central_mass_threshold",
]
