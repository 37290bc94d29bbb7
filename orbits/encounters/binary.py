"""Binary: two finite masses moving about their centre of mass (section XXII of the notes), with astropy units.

    >>> import astropy.units as u
    >>> from orbits import Binary
    >>> earth_moon = Binary.from_elements("Earth", "Moon", a=384399 * u.km, e=0.0549)
    >>> earth_moon.period.to(u.day).round(3)
    <Quantity 27.285 d>
    >>> earth_moon.star1.semi_major_axis.to(u.km).round(1)  # the Earth's orbit about the barycentre
    <Quantity 4670.7 km>

Labels: star 1 (mass m1) is the notes' M and star 2 (m2) the notes' m, so `mass_fraction` m2 / (m1 + m2) is
the notes' mu = m / (M + m), `star2.semi_major_axis` is the notes' a and `star1.semi_major_axis` their q.
The relative orbit r = r2 - r1 (`relative`, an Orbit with mu = G (m1 + m2) and the reduced mass) carries the
pair's energy, angular momentum and the joining line's areal rate L / (2 mu_red) (the notes' (h + H) / 2 in
XXII.ii is not that rate). Each star (`star1`, `star2`) is a Star: the relative conic scaled by m_j / (m1 + m2)
about the CM, a Kepler orbit with the fixed-centre parameter G m_j**3 / (m1 + m2)**2 (XXII.iii), so every Orbit
quantity applies to it. Its co-vertex speed is the notes' M sigma_b or m sigma_b with sigma_b =
sqrt(G / alpha) / (m + M); the notes print sqrt(G / ((m + M) alpha)), which is off by sqrt(m + M). As
m2 / m1 -> 0, star 2 becomes section XXI's planet about a fixed star: within 2e-15 at m2 / m1 = 1e-15
(tests/core/test_binary.py, tests/api/test_binary_api.py).

What an observer measures (beyond the notes, which end with the Lagrange points of XXII.viii): the elements are
read in the sky frame of visual and spectroscopic binaries, x toward the north, y toward the east, z along the line
of sight away from the observer. Omega is then the position angle of the ascending node (where star 2 recedes),
omega star 2's argument of periastron and i < 90 deg a position angle that increases (north through east).
`sky_position` gives the apparent orbit of star 2 about star 1 (separation and position angle), `radial_velocities`
both stars' line-of-sight velocities (> 0 receding, including the centre of mass's, the systemic velocity), and
`rv_semi_amplitude1`, `rv_semi_amplitude2` and `mass_function` what a spectrum gives back. From the other end,
SpectroscopicBinary turns a measured period, semi-amplitude and eccentricity into the mass function and the
companion's (minimum) mass: the round trip through an N-body integration whose radial velocity is then measured
agrees to 1e-9 (tests/api/test_binary_observables.py).
"""

from collections.abc import Iterable
from dataclasses import dataclass
from functools import cached_property

import astropy.units as u
import numpy as np

from orbits._common import display, inputs, units
from orbits._common.constants import Body, G
from orbits._common.tables import quantity_table
from orbits.core.encounters import binary as binary_core
from orbits.core.errors import OrbitDomainError
from orbits.core.twobody import twobody
from orbits.twobody.orbit import Orbit


def _vector(value, unit, name, shape):
    """Float64 SI vector of shape shape + (3,) from a Quantity (zeros when value is None)."""
    if value is None:
        return np.zeros(shape + (3,))
    vector = units.to_si(value, unit, name)
    if vector.shape[-1:] != (3,):
        raise OrbitDomainError(f"{name} must have a last axis of length 3; got shape {vector.shape}")
    return np.broadcast_to(vector, shape + (3,)).astype(float)


@dataclass(frozen=True, eq=False, repr=False)
class Star(Orbit):
    """One star's orbit about the binary's centre of mass, as a Kepler orbit about a fixed centre at the CM.

    mu = G m_j**3 / (m1 + m2)**2 (m_j: the other star), p = p_rel m_j / (m1 + m2), e and the plane of the
    relative orbit (XXII.i-iii); `mass` is the star's own mass. Speeds, distances, angular momentum
    (m_j L / (m1 + m2), the notes' I and J), areal rate (the notes' h / 2 and H / 2), period and T1 / T2 are
    the star's own. Its energy, potential energy and kinetic energy are its share m_j / (m1 + m2) of the
    binary's; K is exactly the star's kinetic energy in the CM frame.
    """

    @cached_property
    def kepler_constant(self) -> u.Quantity:
        """a**3 / T**2 = G m_j**3 / ((m1 + m2)**2 4 pi**2) (m3/s2), Kepler's third law for this star (XXII.iii)."""
        return binary_core.kepler_constant(self.mu) << units.M3_PER_S2

    def _about(self) -> str:
        return "about the centre of mass"


@dataclass(frozen=True, eq=False, repr=False)
class Binary(display.Displayed):
    """Two finite masses (or arrays of pairs) on a Kepler orbit about their centre of mass.

    Fields are float64 SI: the stars' parameters gm1 = G m1 and gm2 = G m2 (m3/s2), the relative Orbit, and the
    centre of mass's position com_r (m) and velocity com_v (m/s) at the epoch (zeros: the CM frame). Build it
    with Binary.from_elements, Binary.circular or Binary.from_vectors. `oriented` is False when the inclination
    was not given: the relative orbit then lies in the reference plane, and the quantities that need its tilt to
    the sky (K1, K2, f(M), radial velocities, apparent orbit) raise instead of answering for a face-on orbit.
    """

    gm1: np.ndarray
    gm2: np.ndarray
    relative: Orbit
    com_r: np.ndarray
    com_v: np.ndarray
    oriented: bool = True

    # ---- constructors -------------------------------------------------------------------------
    @classmethod
    def from_elements(
        cls,
        m1: Body | str | u.Quantity,
        m2: Body | str | u.Quantity,
        a: u.Quantity | None = None,
        e: float | np.ndarray | u.Quantity = 0.0,
        *,
        p: u.Quantity | None = None,
        q: u.Quantity | None = None,
        period: u.Quantity | None = None,
        inc: u.Quantity | None = None,
        raan: u.Quantity = 0 * u.deg,
        argp: u.Quantity = 0 * u.deg,
        nu: u.Quantity = 0 * u.deg,
        com_r: u.Quantity | None = None,
        com_v: u.Quantity | None = None,
    ) -> "Binary":
        """Binary from the masses (body names, masses or GMs) and the relative orbit r2 - r1.

        Give one size of the relative orbit: a = a1 + a2 (the notes' a + q = (m + M) alpha), p, q (periapsis
        separation) or the period T (then a = (G (m1 + m2) T**2 / (4 pi**2))**(1/3), e < 1). Angles orient
        the relative orbit; star 2 shares its periapsis direction, star 1 is opposite. Without `inc` the orbit
        lies in the reference plane (i = 0) and its tilt to the sky is unknown: what needs sin i (K1, K2, f(M), the
        radial velocities and the apparent orbit) raises, asking for it (90 deg is edge-on, 0 face-on).
        """
        gm1, gm2 = inputs.gravitational_parameter(m1, "mass m1"), inputs.gravitational_parameter(m2, "mass m2")
        if period is not None:
            a = _semi_major_axis_from_period(period, e, gm1 + gm2, given=(a, p, q))
        relative = Orbit.from_elements(
            (gm1 + gm2) << units.M3_PER_S2,
            a,
            e,
            p=p,
            q=q,
            inc=0 * u.deg if inc is None else inc,
            raan=raan,
            argp=argp,
            nu=nu,
            mass=binary_core.reduced_mass(gm1, gm2) / G << units.KG,
        )
        return cls._assemble(gm1, gm2, relative, com_r, com_v, oriented=inc is not None)

    @classmethod
    def circular(
        cls,
        m1: Body | str | u.Quantity,
        m2: Body | str | u.Quantity,
        separation: u.Quantity,
        *,
        inc: u.Quantity | None = None,
        raan: u.Quantity = 0 * u.deg,
        nu: u.Quantity = 0 * u.deg,
        com_r: u.Quantity | None = None,
        com_v: u.Quantity | None = None,
    ) -> "Binary":
        """Circular binary (XXII.v): stars at separation m2 r / (m1 + m2) and m1 r / (m1 + m2) from the CM."""
        return cls.from_elements(m1, m2, p=separation, e=0.0, inc=inc, raan=raan, nu=nu, com_r=com_r, com_v=com_v)

    @classmethod
    def from_vectors(
        cls,
        m1: Body | str | u.Quantity,
        m2: Body | str | u.Quantity,
        r1: u.Quantity,
        v1: u.Quantity,
        r2: u.Quantity,
        v2: u.Quantity,
    ) -> "Binary":
        """Binary from both stars' positions (length) and velocities (speed), shape (..., 3), in any inertial frame."""
        gm1, gm2 = inputs.gravitational_parameter(m1, "mass m1"), inputs.gravitational_parameter(m2, "mass m2")
        r1, r2 = units.to_si(r1, units.M, "position r1"), units.to_si(r2, units.M, "position r2")
        v1, v2 = units.to_si(v1, units.M_PER_S, "velocity v1"), units.to_si(v2, units.M_PER_S, "velocity v2")
        relative = Orbit.from_vectors(
            (gm1 + gm2) << units.M3_PER_S2,
            (r2 - r1) << units.M,
            (v2 - v1) << units.M_PER_S,
            mass=binary_core.reduced_mass(gm1, gm2) / G << units.KG,
        )
        x1, x2 = binary_core.mass_fractions(gm1, gm2)
        com_r, com_v = binary_core.center_of_mass(r1, r2, x1, x2), binary_core.center_of_mass(v1, v2, x1, x2)
        return cls._assemble(gm1, gm2, relative, com_r << units.M, com_v << units.M_PER_S)

    @classmethod
    def _assemble(cls, gm1, gm2, relative, com_r, com_v, oriented=True):
        shape = relative.shape
        return cls(
            np.broadcast_to(gm1, shape).astype(float),
            np.broadcast_to(gm2, shape).astype(float),
            relative,
            _vector(com_r, units.M, "centre-of-mass position com_r", shape),
            _vector(com_v, units.M_PER_S, "centre-of-mass velocity com_v", shape),
            oriented,
        )

    # ---- shape and masses (XXII.i) --------------------------------------------------------------
    @property
    def shape(self) -> tuple[int, ...]:
        """Batch shape of the binaries held."""
        return self.relative.shape

    @cached_property
    def _fractions(self):
        return binary_core.mass_fractions(self.gm1, self.gm2)

    @cached_property
    def mass1(self) -> u.Quantity:
        """m1 = G m1 / G (kg), the notes' M."""
        return self.gm1 / G << units.KG

    @cached_property
    def mass2(self) -> u.Quantity:
        """m2 = G m2 / G (kg), the notes' m."""
        return self.gm2 / G << units.KG

    @cached_property
    def total_mass(self) -> u.Quantity:
        """m1 + m2 (kg)."""
        return (self.gm1 + self.gm2) / G << units.KG

    @cached_property
    def reduced_mass(self) -> u.Quantity:
        """m1 m2 / (m1 + m2) (kg): correctly rounded in G m units (double-double), then divided by G (<= 1 ulp)."""
        return binary_core.reduced_mass(self.gm1, self.gm2) / G << units.KG

    @cached_property
    def mass_fraction(self) -> u.Quantity:
        """mu = m2 / (m1 + m2) (dimensionless), the notes' m / (M + m), correctly rounded (double-double)."""
        return self._fractions[1] << u.one

    @cached_property
    def gravitational_parameter(self) -> u.Quantity:
        """G (m1 + m2) (m3/s2), the parameter of the relative orbit."""
        return self.relative.mu << units.M3_PER_S2

    # ---- the stars ------------------------------------------------------------------------------
    @cached_property
    def star1(self) -> Star:
        """Star 1's orbit about the CM (the notes' M, semi-major axis q = m2 a / (m1 + m2))."""
        return self._star(self.gm2, self._fractions[1], self.gm1, opposite=True)

    @cached_property
    def star2(self) -> Star:
        """Star 2's orbit about the CM (the notes' m, semi-major axis a = m1 a_rel / (m1 + m2))."""
        return self._star(self.gm1, self._fractions[0], self.gm2, opposite=False)

    def _star(self, gm_other, share, gm_own, opposite):
        rel = self.relative
        argp, nu = binary_core.star_angles(rel.e, rel.argp, rel.nu, opposite)
        mu = binary_core.star_parameter(gm_other, gm_other + gm_own)
        return Star(mu, rel.p * share, rel.e, rel.inc, rel.raan, argp, nu, mass=gm_own / G)

    # ---- the pair (XXII.ii-v, vii) --------------------------------------------------------------
    @cached_property
    def eccentricity(self) -> u.Quantity:
        """e (dimensionless), common to the relative orbit and both stars' orbits (XXII.i): focal
        distance over semi-major axis, the notes' gamma / alpha (XXII.iv prints the inverse, alpha / gamma)."""
        return self.relative.eccentricity

    @cached_property
    def period(self) -> u.Quantity:
        """T = 2 pi sqrt(a**3 / (G (m1 + m2))) (s), ellipses only: all three forms of Kepler's third law agree."""
        return self.relative.period

    @cached_property
    def mean_motion(self) -> u.Quantity:
        """n = 2 pi / T = sqrt(G (m1 + m2) / a**3) (rad/s)."""
        return self.relative.mean_motion

    @cached_property
    def covertex_times(self) -> tuple[u.Quantity, u.Quantity]:
        """(T1, T2) (s): co-vertex to co-vertex through periapsis T (1/2 - e/pi) and through apoapsis, the same for
        both stars (XXII.vii), ellipses only."""
        return self.relative.covertex_times

    @cached_property
    def time_since_periapsis(self) -> u.Quantity:
        """t - T_periapsis (s) of the pair (both stars pass their periapses together)."""
        return self.relative.time_since_periapsis

    @cached_property
    def kepler_constant(self) -> u.Quantity:
        """(a1 + a2)**3 / T**2 = G (m1 + m2) / (4 pi**2) (m3/s2), Kepler's third law for the relative orbit."""
        return binary_core.kepler_constant(self.relative.mu) << units.M3_PER_S2

    @cached_property
    def energy(self) -> u.Quantity:
        """E = -G m1 m2 / (2 a) (J), the binding energy (XXII.iv: -G m M / (2 (m + M) alpha))."""
        return self.relative.energy

    @cached_property
    def angular_momentum(self) -> u.Quantity:
        """L = m1 m2 sqrt(G p / (m1 + m2)) (kg m2/s) about the CM (XXII.iv)."""
        return self.relative.angular_momentum

    @cached_property
    def joining_line_areal_velocity(self) -> u.Quantity:
        """Area swept by the line joining the stars per unit time, L / (2 mu_red) = sqrt(G (m1 + m2) p) / 2 (m2/s)
        (XXII.ii prints (h + H) / 2 for this rate, which it is not)."""
        return self.relative.areal_velocity

    @cached_property
    def separation(self) -> u.Quantity:
        """|r2 - r1| (m) now."""
        return self.relative.radius

    @cached_property
    def relative_speed(self) -> u.Quantity:
        """|v2 - v1| (m/s) now: vis-viva with G (m1 + m2) (the notes' (m + M) sigma)."""
        return self.relative.speed

    @cached_property
    def angular_velocity(self) -> u.Quantity:
        """Rate of turn of the joining line h / r**2 (rad/s) now; sqrt(G (m1 + m2) / r**3) on a circle (XXII.v)."""
        h = twobody.specific_angular_momentum(self.relative.p, self.relative.mu)
        return h / self.separation.to_value(units.M) ** 2 << units.RAD_PER_S

    @cached_property
    def potential_energy(self) -> u.Quantity:
        """U = -G m1 m2 / r (J) now."""
        return self.relative.potential_energy

    @cached_property
    def kinetic_energy(self) -> u.Quantity:
        """K = m1 v1**2 / 2 + m2 v2**2 / 2 = mu_red |v2 - v1|**2 / 2 (J) now, in the CM frame."""
        return self.relative.kinetic_energy

    def speeds_at(self, separation: u.Quantity) -> tuple[u.Quantity, u.Quantity]:
        """(v1, v2) (m/s): the stars' speeds in the CM frame when they are `separation` (length) apart.

        v_i = m_j / (m1 + m2) sqrt(G (m1 + m2) (2 / r - 1 / a)) (XXII.iv's M sigma and m sigma; the
        square root covers the whole bracket, which the notes' printing leaves outside it).
        """
        relative = self.relative.speed_at(separation)
        x1, x2 = self._fractions
        return x2 * relative, x1 * relative

    def escape_speed(self, distance: u.Quantity) -> u.Quantity:
        """sqrt(2 G (m1 + m2) / r) (m/s) at distance r (length) from the CM, the pair seen as one point mass.

        Exact to 1 ulp for that model. The pair's quadrupole changes v**2 by at most m1 m2 / (m1 + m2)**2 (d / r)**2
        relative to leading order in d / r, d the separation (tests/api/test_binary_api.py checks this against
        the two-star potential).
        """
        r = inputs.positive(distance, units.M, "distance r")
        return twobody.escape_speed(r, self.relative.mu) << units.M_PER_S

    # ---- what an observer measures (the sky frame: x north, y east, z away from the observer) -------------
    @cached_property
    def rv_semi_amplitude1(self) -> u.Quantity:
        """K1 = 2 pi a1 sin i / (P sqrt(1 - e**2)) (m/s), star 1's radial-velocity semi-amplitude, a1 = m2 a / (m1 + m2)
        its semi-major axis about the centre of mass; ellipses only."""
        return self._semi_amplitude(self.star1)

    @cached_property
    def rv_semi_amplitude2(self) -> u.Quantity:
        """K2 = 2 pi a2 sin i / (P sqrt(1 - e**2)) (m/s), star 2's radial-velocity semi-amplitude
        (K1 / K2 = m2 / m1)."""
        return self._semi_amplitude(self.star2)

    def _require_inclination(self, quantity):
        if not self.oriented:
            raise OrbitDomainError(f"{quantity} needs the inclination i of the orbit to the sky (sin i), which was "
                                   f"not given: build the binary with inc=... (90 deg: edge-on, 0: face-on)")

    def _semi_amplitude(self, star):
        self._require_inclination("a radial-velocity semi-amplitude")
        self.relative._require_ellipse("a radial-velocity semi-amplitude")
        a = star.semi_major_axis.to_value(units.M)
        k = binary_core.radial_velocity_semi_amplitude(a, self.period.to_value(units.S), self.relative.inc,
                                                       self.relative.e)
        return k << units.M_PER_S

    @cached_property
    def mass_function(self) -> u.Quantity:
        """f(M) = (m2 sin i)**3 / (m1 + m2)**2 (kg): what star 1's radial velocities give, P K1**3 (1 - e**2)**(3/2)
        / (2 pi G) (tests/api/test_binary_observables.py: the two agree to 1e-15)."""
        self._require_inclination("the mass function f(M)")
        gm2_sin_i = self.gm2 * np.sin(self.relative.inc)
        total = self.gm1 + self.gm2
        return gm2_sin_i * (gm2_sin_i / total) ** 2 / G << units.KG

    def radial_velocities(self, dt: u.Quantity = 0 * u.s) -> tuple[u.Quantity, u.Quantity]:
        """(v1, v2) (m/s): both stars' line-of-sight velocities (> 0 receding) a time dt (time Quantity,
        broadcasting) after the epoch, the centre of mass's (the systemic velocity gamma = com_v z) included.

        The z components of `propagate`; equal to gamma + K_i (cos(omega_i + nu) + e cos omega_i) to 1e-15 of K
        (tests/api/test_binary_observables.py)."""
        self._require_inclination("the radial velocities")
        _, v1, _, v2 = self.propagate(dt)
        return v1[..., 2], v2[..., 2]

    def sky_position(self, dt: u.Quantity = 0 * u.s) -> tuple[u.Quantity, u.Quantity]:
        """(rho, theta): the apparent separation of star 2 from star 1 on the sky (m, projected; divide by the
        distance for an angle) and its position angle (rad, from the north through the east, in [0, 2 pi)), a time
        dt (time Quantity, broadcasting) after the epoch."""
        self._require_inclination("the apparent orbit on the sky")
        r1, _, r2, _ = self.propagate(dt, barycentric=True)
        north, east = (r2 - r1)[..., 0].to_value(units.M), (r2 - r1)[..., 1].to_value(units.M)
        return np.hypot(north, east) << units.M, np.mod(np.arctan2(east, north), 2 * np.pi) << units.RAD

    # ---- state vectors --------------------------------------------------------------------------
    @cached_property
    def center_of_mass(self) -> u.Quantity:
        """Position of the CM (m) at the epoch, shape (..., 3)."""
        return self.com_r << units.M

    @cached_property
    def center_of_mass_velocity(self) -> u.Quantity:
        """Velocity of the CM (m/s), shape (..., 3)."""
        return self.com_v << units.M_PER_S

    def propagate(
        self, dt: u.Quantity, *, barycentric: bool = False
    ) -> tuple[u.Quantity, u.Quantity, u.Quantity, u.Quantity]:
        """(r1, v1, r2, v2) of both stars a time dt (time Quantity, broadcasting) after the epoch.

        In the frame of com_r and com_v (the CM moving uniformly), or in the CM frame with barycentric=True.
        The relative orbit goes through the universal-variable propagator (orbits.core.twobody.propagate).
        """
        dt_si = units.to_si(dt, units.S, "time step dt")
        frame = 0.0 if barycentric else 1.0
        r1, v1, r2, v2 = binary_core.propagate(
            self.relative.r.to_value(units.M),
            self.relative.v.to_value(units.M_PER_S),
            frame * self.com_r,
            frame * self.com_v,
            self.gm1,
            self.gm2,
            dt_si,
        )
        return r1 << units.M, v1 << units.M_PER_S, r2 << units.M, v2 << units.M_PER_S

    @cached_property
    def states(self) -> tuple[u.Quantity, u.Quantity, u.Quantity, u.Quantity]:
        """(r1, v1, r2, v2) of both stars at the epoch, in the frame of com_r and com_v."""
        return self.propagate(0 * u.s)

    # ---- tables ---------------------------------------------------------------------------------
    def __repr__(self) -> str:
        """E.g. "Binary(Earth + Moon, a = 384399 km, e = 0.0549, T = 27.28 d)"."""
        pair = f"{display.body_name(self.gm1)} + {display.body_name(self.gm2)}"
        size = ("a = " + display.summary(self.relative.semi_major_axis) if (self.relative.e < 1).all()
                else "q = " + display.summary(self.relative.periapsis_distance))
        period = "T = " + display.summary(self.period) if (self.relative.e < 1).all() else ""
        count = f"{self.relative.e.size} pairs" if self.relative.shape else ""
        return display.one_line("Binary", count, pair, size, "e = " + display.summary(self.eccentricity), period)

    def quantities(self, only: Iterable[str] | None = None) -> dict[str, u.Quantity]:
        """{snake_case name: Quantity} of the section XXII quantities (or `only` those).

        Names are the pair's own (BINARY_NAMES), `relative_<name>` for the relative orbit and `star1_<name>`,
        `star2_<name>` for each star's orbit about the CM (RELATIVE_NAMES, STAR_NAMES). Without `only`,
        quantities undefined for this binary (e.g. the period of an unbound pair) are left out.
        """
        return quantity_table(self._lookup, QUANTITY_NAMES, only)

    def _lookup(self, name):
        if name == "relative_inclination":
            self._require_inclination("the inclination to the sky")
        for prefix in ("relative", "star1", "star2"):
            if name.startswith(prefix + "_"):
                return getattr(getattr(self, prefix), name[len(prefix) + 1 :])
        if name.startswith("covertex_time_"):
            return self.covertex_times[0 if name.endswith("periapsis_side") else 1]
        return getattr(self, name)


def _semi_major_axis_from_period(period, e, mu, given):
    """a (Quantity, m) of the relative orbit from its period; TypeError if a size was given as well."""
    if any(x is not None for x in given):
        raise TypeError("give exactly one size of a, p, q, period; got period and another")
    t = inputs.positive(period, units.S, "period T")
    binary_core.require_bound(units.to_number(e, "eccentricity e"), "a period")
    return binary_core.semi_major_axis_from_period(t, mu) << units.M


BINARY_NAMES = [
    "mass1",
    "mass2",
    "total_mass",
    "reduced_mass",
    "mass_fraction",
    "gravitational_parameter",
    "eccentricity",
    "period",
    "mean_motion",
    "covertex_time_periapsis_side",
    "covertex_time_apoapsis_side",
    "time_since_periapsis",
    "kepler_constant",
    "energy",
    "angular_momentum",
    "joining_line_areal_velocity",
    "separation",
    "relative_speed",
    "angular_velocity",
    "potential_energy",
    "kinetic_energy",
    "rv_semi_amplitude1",
    "rv_semi_amplitude2",
    "mass_function",
]

RELATIVE_NAMES = [
    "semi_major_axis",
    "semilatus_rectum",
    "semi_minor_axis",
    "focal_distance",
    "periapsis_distance",
    "apoapsis_distance",
    "periapsis_speed",
    "apoapsis_speed",
    "covertex_speed",
    "inclination",
    "ascending_node",
    "argument_of_periapsis",
    "true_anomaly",
]

STAR_NAMES = [
    "semi_major_axis",
    "semilatus_rectum",
    "semi_minor_axis",
    "focal_distance",
    "periapsis_distance",
    "apoapsis_distance",
    "periapsis_speed",
    "apoapsis_speed",
    "covertex_speed",
    "kepler_constant",
    "angular_momentum",
    "areal_velocity",
    "radius",
    "speed",
]

QUANTITY_NAMES = (
    BINARY_NAMES
    + [f"relative_{n}" for n in RELATIVE_NAMES]
    + [f"star1_{n}" for n in STAR_NAMES]
    + [f"star2_{n}" for n in STAR_NAMES]
)


@dataclass(frozen=True, eq=False, repr=False)
class SpectroscopicBinary(display.Displayed):
    """What one star's radial-velocity curve gives: its period P, semi-amplitude K and eccentricity e, and, when
    known, the star's own mass m1 and the inclination i (the orbit of a single-lined spectroscopic binary).

    Fields are float64 SI (s, m/s, m3/s2 for G m1; rad), NaN where not given. Build it with `from_curve`.
    """

    period_s: np.ndarray
    k: np.ndarray
    e: np.ndarray
    gm1: np.ndarray
    inc: np.ndarray

    @classmethod
    def from_curve(
        cls,
        period: u.Quantity,
        semi_amplitude: u.Quantity,
        e: float | np.ndarray | u.Quantity = 0.0,
        *,
        primary_mass: Body | str | u.Quantity | None = None,
        inc: u.Quantity | None = None,
    ) -> "SpectroscopicBinary":
        """From the measured period P (time), semi-amplitude K (speed) and eccentricity e of the star's radial
        velocity, with its mass (a body, mass or GM) for the companion's mass and the inclination (angle in
        (0, 180) deg; default: none, so only the minimum mass sin i = 1)."""
        period_s = inputs.positive(period, units.S, "period P")
        k = inputs.positive(semi_amplitude, units.M_PER_S, "semi-amplitude K")
        ecc = inputs.eccentricity(e)
        binary_core.require_bound(ecc, "a radial-velocity orbit")
        gm1 = np.nan if primary_mass is None else inputs.gravitational_parameter(primary_mass, "primary mass m1")
        incl = np.nan if inc is None else inputs.angle(inc, "inclination i")
        if inc is not None and np.any((incl <= 0) | (incl >= np.pi)):
            bad = float(np.asarray(incl)[(incl <= 0) | (incl >= np.pi)].flat[0])
            raise OrbitDomainError(f"inclination i = {float(np.degrees(bad))!r} deg is outside (0, 180) deg: sin i = 0 "
                                   f"would hide the orbit from the radial velocities")
        arrays = np.broadcast_arrays(*(np.asarray(x, dtype=float) for x in (period_s, k, ecc, gm1, incl)))
        return cls(*(a.copy() for a in arrays))

    @property
    def shape(self) -> tuple[int, ...]:
        """Batch shape."""
        return self.k.shape

    @cached_property
    def mass_function(self) -> u.Quantity:
        """f(M) = P K**3 (1 - e**2)**(3/2) / (2 pi G) = (m2 sin i)**3 / (m1 + m2)**2 (kg)."""
        return binary_core.mass_function_parameter(self.period_s, self.k, self.e) / G << units.KG

    @cached_property
    def projected_semi_major_axis(self) -> u.Quantity:
        """a1 sin i = K P sqrt(1 - e**2) / (2 pi) (m): the star's orbit about the centre of mass, foreshortened."""
        return self.k * self.period_s * np.sqrt((1 - self.e) * (1 + self.e)) / (2 * np.pi) << units.M

    @cached_property
    def minimum_companion_mass(self) -> u.Quantity:
        """The companion's mass for sin i = 1 (kg), the root of m2**3 = f(M) (m1 + m2)**2: a lower bound on its mass
        (m2 grows as sin i falls). Needs the primary's mass."""
        return self._companion(1.0)

    @cached_property
    def companion_mass(self) -> u.Quantity:
        """The companion's mass m2 (kg), the root of (m2 sin i)**3 = f(M) (m1 + m2)**2. Needs the primary's mass and
        the inclination."""
        if np.isnan(self.inc).any():
            raise OrbitDomainError("the companion mass needs the inclination i (from an eclipse or the apparent "
                                   "orbit); without it, minimum_companion_mass is the bound for sin i = 1")
        return self._companion(np.sin(self.inc))

    def _companion(self, sin_i):
        if np.isnan(self.gm1).any():
            raise OrbitDomainError("the companion mass needs the primary's mass m1 (primary_mass=...)")
        gm_f = binary_core.mass_function_parameter(self.period_s, self.k, self.e)
        return binary_core.companion_parameter(gm_f, self.gm1, sin_i) / G << units.KG

    def _facts(self) -> list[str]:
        return ["P = " + display.summary(self.period_s << units.S, "period"),
                "K = " + display.summary(self.k << units.M_PER_S), "e = " + display.summary(self.e << u.one),
                "f(M) = " + display.summary(self.mass_function, "mass_function")]

    @property
    def title(self) -> str:
        """The measurement in words: "Star 1's radial velocities: P = 4.23 d, K = 56 m/s, e = 0, f(M) = ..."."""
        return "Star 1's radial velocities: " + ", ".join(self._facts())

    def __repr__(self) -> str:
        """E.g. "SpectroscopicBinary(P = 4.23 d, K = 56 m/s, e = 0, f(M) = 3.5e-11 solMass)"."""
        return display.one_line("SpectroscopicBinary", *self._facts())

    def quantities(self, only: Iterable[str] | None = None) -> dict[str, u.Quantity]:
        """{name: Quantity}: the mass function, a1 sin i and, with the masses known, the companion's mass
        (SPECTROSCOPIC_NAMES, or `only` those)."""
        return quantity_table(lambda name: getattr(self, name), SPECTROSCOPIC_NAMES, only)


SPECTROSCOPIC_NAMES = ["mass_function", "projected_semi_major_axis", "minimum_companion_mass", "companion_mass"]
