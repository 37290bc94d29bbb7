"""Orbit: a Kepler orbit (or an array of them) about a fixed primary, with astropy units.

    >>> import astropy.units as u
    >>> from orbits import Orbit
    >>> leo = Orbit.circular("Earth", radius=6778 * u.km)
    >>> leo.period.to(u.min).round(2)
    <Quantity 92.56 min>

Elements are stored once as float64 SI arrays (mu, p, e, i, Omega, omega, nu); every quantity of
section XXI of the notes is a lazily computed property returning a Quantity. Conventions for
degenerate angles are those of orbits.core.twobody.elements.
"""

import warnings
from collections.abc import Iterable
from dataclasses import dataclass
from functools import cached_property
from typing import TYPE_CHECKING, Any

import astropy.units as u
import numpy as np

from orbits._common import display, inputs, units
from orbits._common.constants import Body, G, body
from orbits._common.tables import quantity_table
from orbits.core.checks import broadcast_shape, check_broadcast, first_where
from orbits.core.errors import ILL_CONDITIONED, IllConditionedWarning, OrbitDomainError
from orbits.core.twobody import anomalies, elements, propagate, transition, twobody
from orbits.ephemeris import catalogue as catalogue_orbits

if TYPE_CHECKING:
    from orbits.ephemeris.positions import BodyState

#: how a primary is named in error messages
PRIMARY = "primary mass or gravitational parameter"
#: the relative slack of speed_at's range [q, Q]: a distance computed another way lands within a few ulp of an apsis
APSIS_SLACK = 1e-12


@dataclass(frozen=True, eq=False)
class Orbit(display.Displayed):
    """Kepler orbit(s) about a fixed primary; fields are float64 SI arrays that broadcast together.

    Build it with Orbit.from_elements, Orbit.from_vectors or Orbit.circular rather than directly.
    `mass` (kg) is the orbiting body's mass, needed only for U, K, E, L and the LRL vector. An orbit about a
    catalogue body (its GM exactly) whose periapsis lies inside the body's equatorial radius gives an
    InsideBodyWarning, whichever constructor built it: it passes through the body.
    """

    mu: np.ndarray
    p: np.ndarray
    e: np.ndarray
    inc: np.ndarray
    raan: np.ndarray
    argp: np.ndarray
    nu: np.ndarray
    mass: np.ndarray | None = None

    def __post_init__(self):
        if self.mass is not None and np.shape(self.mass) != self.p.shape:
            object.__setattr__(self, "mass", _mass_field(self.mass, self.p.shape))
        inputs.warn_if_inside(self.p / (1.0 + self.e), [inputs.exact_body(self.mu)], type(self).__name__)

    # ---- constructors -------------------------------------------------------------------------
    @classmethod
    def from_elements(
        cls,
        primary: Body | str | u.Quantity,
        a: u.Quantity | None = None,
        e: float | np.ndarray | u.Quantity = 0.0,
        *,
        p: u.Quantity | None = None,
        q: u.Quantity | None = None,
        inc: u.Quantity = 0 * u.deg,
        raan: u.Quantity = 0 * u.deg,
        argp: u.Quantity = 0 * u.deg,
        nu: u.Quantity = 0 * u.deg,
        mass: u.Quantity | None = None,
    ) -> "Orbit":
        """Orbit from one size element (a, p or q), e, i, Omega, omega and the true anomaly nu."""
        mass_si = _mass(mass)
        fields = inputs.conic_elements(primary, e, a=a, p=p, q=q, inc=inc, raan=raan, argp=argp, nu=nu)
        return cls(*fields, mass=mass_si)

    @classmethod
    def from_vectors(
        cls, primary: Body | str | u.Quantity, r: u.Quantity, v: u.Quantity, *, mass: u.Quantity | None = None
    ) -> "Orbit":
        """Orbit through the state r (length, shape (..., 3)) and v (speed, shape (..., 3))."""
        mu = inputs.gravitational_parameter(primary, PRIMARY)
        r_si = inputs.position(r)
        v_si = inputs.vector(v, units.M_PER_S, "velocity v")
        broadcast_shape(r=r_si.shape[:-1], v=v_si.shape[:-1], primary=np.shape(mu))
        fields = elements.state_to_elements_unchecked(r_si, v_si, mu)
        shape = fields[0].shape
        return cls(np.broadcast_to(mu, shape).astype(float), *fields, mass=_mass(mass))

    @classmethod
    def circular(
        cls,
        primary: Body | str | u.Quantity,
        radius: u.Quantity,
        *,
        inc: u.Quantity = 0 * u.deg,
        raan: u.Quantity = 0 * u.deg,
        nu: u.Quantity = 0 * u.deg,
        mass: u.Quantity | None = None,
    ) -> "Orbit":
        """Circular orbit of the given radius (e = 0, so nu is the argument of latitude)."""
        inputs.positive(radius, units.M, "orbit radius r")
        return cls.from_elements(primary, p=radius, e=0.0, inc=inc, raan=raan, nu=nu, mass=mass)

    @classmethod
    def from_body(cls, name: str, epoch: Any = None, *, source: str = "auto", scale: str = "utc") -> "Orbit":
        """The catalogue body's orbit about its parent, with the body's mass, in the ecliptic frame of J2000.

        Without `epoch`: the published orbit of orbits.ephemeris.catalogue.mean_elements at its own epoch (Standish's
        J2000 mean elements for the planets, published osculating elements for the asteroids and Eris, JPL's
        satellite mean elements for the moons, turned to the ecliptic of J2000), its mean anomaly turned into the
        true anomaly with Kepler's equation. With `epoch` (astropy
        Time or ISO string, see orbits.ephemeris.positions): the osculating two-body orbit through the ephemeris state
        relative to the parent (the Sun for a planet, the Earth for the Moon), mu = G (M_parent + M_body).
        DE421 gives Jupiter-Pluto as system barycentres, and Standish's mean elements are those of the
        barycentres (the Earth-Moon one for the Earth): such an orbit carries the system's mass
        (Body.barycentre_gm), the planet with its moons.
        """
        target = body(name)
        if epoch is not None:
            return cls._osculating(target, epoch, source, scale)
        el = catalogue_orbits.mean_elements(target.name)
        mass = target.barycentre_gm / G << units.KG
        nu = anomalies.true_from_mean(el.mean_anomaly, el.e)
        if el.pole is None and el.primary == "Sun":
            return cls.from_elements(el.primary, a=el.a << units.M, e=el.e, inc=el.inc << units.RAD,
                                     raan=el.raan << units.RAD, argp=el.argp << units.RAD, nu=nu << units.RAD,
                                     mass=mass)
        mu = body(el.primary).gm + target.gm  # a moon's orbit about its planet: the two masses
        r, v = elements.elements_to_state(el.a * (1 - el.e) * (1 + el.e), el.e, el.inc, el.raan, el.argp, nu, mu)
        return cls.from_vectors(mu << units.M3_PER_S2, catalogue_orbits.reference_to_ecliptic(r, el.pole) << units.M,
                                catalogue_orbits.reference_to_ecliptic(v, el.pole) << units.M_PER_S, mass=mass)

    @classmethod
    def _osculating(cls, target: Body, epoch: Any, source: str, scale: str) -> "Orbit":
        from orbits.ephemeris import positions as ephemeris

        if target.parent is None:
            raise OrbitDomainError(f"{target.name} orbits nothing in the catalogue")
        return cls.from_state(ephemeris.state(target.name, epoch, center=target.parent, source=source, scale=scale))

    @classmethod
    def from_state(cls, seen: "BodyState") -> "Orbit":
        """The osculating orbit through an ephemeris state (orbits.ephemeris.positions.state) of a catalogue body
        about its
        parent, in the ecliptic frame of J2000, mu = G (M_parent + M_body) (the system's mass for a system
        barycentre), with the body's mass."""
        from orbits.ephemeris import positions as ephemeris

        problem = ephemeris.osculating(seen)
        return cls.from_vectors(problem.mu << units.M3_PER_S2, problem.r << units.M, problem.v << units.M_PER_S,
                                mass=problem.gm / G << units.KG)

    # ---- shape ----------------------------------------------------------------------------------
    @property
    def shape(self) -> tuple[int, ...]:
        """Batch shape of the orbits held."""
        return self.p.shape

    def _require_ellipse(self, quantity):
        if (self.e >= 1.0).any():
            bad = float(self.e[self.e >= 1].flat[0])
            raise OrbitDomainError(f"{quantity} is defined for ellipses only (e < 1); this orbit has e = {bad!r}")

    def _require_mass(self, quantity):
        if self.mass is None:
            raise OrbitDomainError(f"{quantity} needs the orbiting body's mass: give it (mass=... in Python, --mass "
                                   f"in the calculator)")
        return self.mass

    # ---- elements -------------------------------------------------------------------------------
    @cached_property
    def eccentricity(self) -> u.Quantity:
        """e (dimensionless)."""
        return self.e << u.one

    @cached_property
    def semilatus_rectum(self) -> u.Quantity:
        """p = h**2 / mu (m); the notes' l."""
        return self.p << units.M

    @cached_property
    def semi_major_axis(self) -> u.Quantity:
        """a = p / (1 - e**2) (m); negative for hyperbolas, inf for the parabola."""
        return twobody.semi_major_axis(self.p, self.e) << units.M

    @cached_property
    def inclination(self) -> u.Quantity:
        """i (rad), in [0, pi]."""
        return self.inc << units.RAD

    @cached_property
    def ascending_node(self) -> u.Quantity:
        """Omega (rad), in [0, 2 pi); 0 for equatorial orbits."""
        return self.raan << units.RAD

    @cached_property
    def argument_of_periapsis(self) -> u.Quantity:
        """omega (rad), in [0, 2 pi); 0 for circular orbits."""
        return self.argp << units.RAD

    @cached_property
    def true_anomaly(self) -> u.Quantity:
        """nu (rad), in (-pi, pi]."""
        return self.nu << units.RAD

    # ---- geometry (XXI.iv) ----------------------------------------------------------------------
    @cached_property
    def periapsis_distance(self) -> u.Quantity:
        """r1 = a - c = p / (1 + e) (m)."""
        return twobody.periapsis_distance(self.p, self.e) << units.M

    @cached_property
    def apoapsis_distance(self) -> u.Quantity:
        """r2 = a + c = p / (1 - e) (m), ellipses only."""
        self._require_ellipse("apoapsis distance")
        return twobody.apoapsis_distance(self.p, self.e) << units.M

    @cached_property
    def focal_distance(self) -> u.Quantity:
        """c = a e (m): centre of the ellipse to the star, ellipses only."""
        self._require_ellipse("focal distance")
        return twobody.focal_distance(self.p, self.e) << units.M

    @cached_property
    def semi_minor_axis(self) -> u.Quantity:
        """b = a sqrt(1 - e**2) (m), ellipses only."""
        self._require_ellipse("semi-minor axis")
        return twobody.semi_minor_axis(self.p, self.e) << units.M

    # ---- speeds ---------------------------------------------------------------------------------
    @cached_property
    def periapsis_speed(self) -> u.Quantity:
        """v1 = sqrt(mu / p) (1 + e) (m/s)."""
        return twobody.periapsis_speed(self.p, self.e, self.mu) << units.M_PER_S

    @cached_property
    def apoapsis_speed(self) -> u.Quantity:
        """v2 = sqrt(mu / p) (1 - e) (m/s), ellipses only."""
        self._require_ellipse("apoapsis speed")
        return twobody.apoapsis_speed(self.p, self.e, self.mu) << units.M_PER_S

    @cached_property
    def covertex_speed(self) -> u.Quantity:
        """v_b = sqrt(mu / a) (m/s) at the ends of the minor axis, ellipses only."""
        self._require_ellipse("co-vertex speed")
        return twobody.covertex_speed(self.p, self.e, self.mu) << units.M_PER_S

    def speed_at(self, r: u.Quantity) -> u.Quantity:
        """Vis-viva speed sqrt(mu (2/r - 1/a)) (m/s) at distance r (length) from the star, where the body gets:
        q <= r <= Q on an ellipse, r >= q on an open orbit, the apsides included to 1e-12 of their distance (an
        apsis computed another way lands within a few ulp of q or Q)."""
        r_si = inputs.positive(r, units.M, "distance r")
        q = twobody.periapsis_distance(self.p, self.e)
        with np.errstate(divide="ignore"):
            far = np.where(self.e < 1.0, self.p / (1.0 - self.e), np.inf)
        outside = (r_si < q * (1.0 - APSIS_SLACK)) | (r_si > far * (1.0 + APSIS_SLACK))
        if np.any(outside):
            bad, low, high = first_where(outside, r_si, q, far)
            low, high = (display.quantity_text(x << units.M) for x in (low, high))
            raise OrbitDomainError(f"distance r = {display.quantity_text(bad << units.M)} is outside [{low}, {high}], "
                                   f"from the periapsis to the apoapsis of this orbit: the body never gets there")
        return twobody.speed_at_radius(r_si, self.p, self.e, self.mu) << units.M_PER_S

    # ---- dynamics (XXI.ii-iv) -------------------------------------------------------------------
    @cached_property
    def specific_energy(self) -> u.Quantity:
        """E / m = -mu / (2 a) (J/kg)."""
        return twobody.specific_energy(self.p, self.e, self.mu) << units.J_PER_KG

    @cached_property
    def specific_angular_momentum(self) -> u.Quantity:
        """h = sqrt(mu p) (m2/s)."""
        return twobody.specific_angular_momentum(self.p, self.mu) << units.M2_PER_S

    @cached_property
    def areal_velocity(self) -> u.Quantity:
        """dA/dt = h / 2 (m2/s), Kepler's second law."""
        return twobody.areal_velocity(self.p, self.mu) << units.M2_PER_S

    @cached_property
    def energy(self) -> u.Quantity:
        """E = -G M m / (2 a) (J)."""
        return self.specific_energy * (self._require_mass("energy E") << units.KG)

    @cached_property
    def angular_momentum(self) -> u.Quantity:
        """L = m sqrt(mu p) (kg m2/s)."""
        return self.specific_angular_momentum * (self._require_mass("angular momentum L") << units.KG)

    @cached_property
    def potential_energy(self) -> u.Quantity:
        """U = -G M m / r (J) at the current position."""
        m = self._require_mass("potential energy U")
        return twobody.potential_energy(self.radius.to_value(units.M), self.mu, m) << units.J

    @cached_property
    def kinetic_energy(self) -> u.Quantity:
        """K = m v**2 / 2 = G M m (1/r - 1/(2a)) (J) at the current position."""
        m = self._require_mass("kinetic energy K")
        return 0.5 * m * self.speed.to_value(units.M_PER_S) ** 2 << units.J

    def potential_energy_at(self, r: u.Quantity) -> u.Quantity:
        """U(r) = -G M m / r (J) at distance r (length) from the star, for the orbiting body of mass m."""
        m = self._require_mass("potential energy U(r)")
        return twobody.potential_energy(inputs.positive(r, units.M, "distance r"), self.mu, m) << units.J

    def kinetic_energy_at(self, r: u.Quantity) -> u.Quantity:
        """K(r) = E - U(r) = m v(r)**2 / 2 (J) at distance r (length), where the body gets (see speed_at)."""
        m = self._require_mass("kinetic energy K(r)")
        return 0.5 * m * self.speed_at(r).to_value(units.M_PER_S) ** 2 << units.J

    @cached_property
    def laplace_runge_lenz_magnitude(self) -> u.Quantity:
        """|A| = m**2 mu e = m k e (kg2 m3/s2), k = G M m: the length of the Laplace-Runge-Lenz vector."""
        m = self._require_mass("the Laplace-Runge-Lenz vector")
        return m * m * self.mu * self.e << (units.KG**2 * units.M3_PER_S2)

    @cached_property
    def laplace_runge_lenz_along_r(self) -> u.Quantity:
        """A . r = L**2 - m k r = m**2 (h**2 - mu r) (kg2 m4/s2) at the current position: the conic's equation
        r = (L**2 / m k) / (1 + e cos nu) in one dot product."""
        m = self._require_mass("the Laplace-Runge-Lenz vector")
        h2 = self.mu * self.p
        return m * m * (h2 - self.mu * self.radius.to_value(units.M)) << (units.KG**2 * units.M**4 / units.S**2)

    def area_swept(self, t1: u.Quantity, t2: u.Quantity) -> u.Quantity:
        """A = (h / 2)(t2 - t1) (m2): the area the radius vector sweeps from time t1 to t2 (time Quantities after
        the current position, broadcasting), Kepler's second law; negative when t2 < t1. Over one period of an
        ellipse it is pi a b."""
        start = units.to_si(t1, units.S, "time t1")
        end = units.to_si(t2, units.S, "time t2")
        return twobody.areal_velocity(self.p, self.mu) * (end - start) << units.M**2

    # ---- time (XXI.iii, XXI.vii) ----------------------------------------------------------------
    @cached_property
    def period(self) -> u.Quantity:
        """T = 2 pi sqrt(a**3 / mu) (s), ellipses only."""
        self._require_ellipse("period T")
        return twobody.period(self.p, self.e, self.mu) << units.S

    @cached_property
    def mean_motion(self) -> u.Quantity:
        """n = sqrt(mu / |a|**3) (rad/s); 2 sqrt(mu / p**3) on the parabola (rate of Barker's W)."""
        return anomalies.mean_motion(self.p, self.e, self.mu) << units.RAD_PER_S

    @cached_property
    def covertex_times(self) -> tuple[u.Quantity, u.Quantity]:
        """(T1, T2) (s): co-vertex to co-vertex through periapsis, T (1/2 - e/pi), and through apoapsis."""
        self._require_ellipse("co-vertex times T1, T2")
        t1, t2 = twobody.covertex_times(self.p, self.e, self.mu)
        return t1 << units.S, t2 << units.S

    @cached_property
    def mean_anomaly(self) -> u.Quantity:
        """M (rad): E - e sin E (ellipse), e sinh H - H (hyperbola), Barker's W (parabola)."""
        return anomalies.mean_from_true_unchecked(self.nu, self.e) << units.RAD

    @cached_property
    def time_since_periapsis(self) -> u.Quantity:
        """t - T_periapsis = M / n (s), negative before the periapsis passage."""
        return anomalies.time_since_periapsis_unchecked(self.nu, self.p, self.e, self.mu) << units.S

    # ---- state and vectors (XXI.viii) -----------------------------------------------------------
    @cached_property
    def _state(self):
        return elements.elements_to_state_unchecked(self.p, self.e, self.inc, self.raan, self.argp, self.nu, self.mu)

    @cached_property
    def r(self) -> u.Quantity:
        """Position vector (m), shape (..., 3)."""
        return self._state[0] << units.M

    @cached_property
    def v(self) -> u.Quantity:
        """Velocity vector (m/s), shape (..., 3)."""
        return self._state[1] << units.M_PER_S

    @cached_property
    def radius(self) -> u.Quantity:
        """|r| = p / (1 + e cos nu) (m)."""
        return self.p / (1.0 + self.e * np.cos(self.nu)) << units.M

    @cached_property
    def speed(self) -> u.Quantity:
        """|v| (m/s) at the current position."""
        return np.sqrt(np.sum(self._state[1] ** 2, axis=-1)) << units.M_PER_S

    @cached_property
    def eccentricity_vector(self) -> u.Quantity:
        """e_vec = (v x h) / mu - r_hat (dimensionless), pointing to periapsis."""
        return elements.eccentricity_vector(*self._state, self.mu) << u.one

    @cached_property
    def angular_momentum_vector(self) -> u.Quantity:
        """h = r x v (m2/s)."""
        return elements.angular_momentum_vector(*self._state) << units.M2_PER_S

    @cached_property
    def laplace_runge_lenz(self) -> u.Quantity:
        """A = p x L - m k r_hat = m**2 mu e_vec (kg2 m3/s2)."""
        m = self._require_mass("Laplace-Runge-Lenz vector")
        return elements.laplace_runge_lenz_vector(*self._state, self.mu, m) << (units.KG**2 * units.M3_PER_S2)

    def propagate(self, dt: u.Quantity, stm: bool = False) -> tuple[u.Quantity, ...]:
        """State vectors (r, v) a time dt (time Quantity, broadcasting) later, on the same Kepler orbit.

        With stm=True also the state-transition matrix Phi = d(r, v) / d(r0, v0), a float array of shape
        (..., 6, 6) in SI units (blocks: 1, s, 1/s, 1), so that a covariance P0 of (r0 [m], v0 [m/s]) becomes
        Phi P0 Phi^T (orbits.core.twobody.transition.propagate_covariance); within 1e-13 of its norm on ordinary
        flights,
        within orbits.core.twobody.transition.relative_error where one grazes the focus or starts nearly radial, with an
        IllConditionedWarning when that passes 1e-8.
        """
        dt_si = units.to_si(dt, units.S, "time step dt")
        check_broadcast("the orbits times the time steps dt", np.shape(self.mu), np.shape(dt_si))
        r, v = propagate.propagate(*self._state, self.mu, dt_si)
        self._warn_if_too_long(dt_si)
        if not stm:
            return r << units.M, v << units.M_PER_S
        phi = transition.transition_matrix(*self._state, self.mu, dt_si)
        worst = float(np.max(transition.relative_error(phi, *self._state, self.mu), initial=0.0))
        if worst > ILL_CONDITIONED:
            digits = f"about {int(-np.log10(worst))} digits of Phi" if worst < 0.1 else "no digit of Phi"
            warnings.warn(f"ill-conditioned state-transition matrix: the flight is very long, grazes the focus or "
                          f"starts nearly radial; {digits} can be trusted (error up to {worst:.2g} of its norm)",
                          IllConditionedWarning, stacklevel=2)
        return r << units.M, v << units.M_PER_S, phi

    def _warn_if_too_long(self, dt: np.ndarray) -> None:
        """IllConditionedWarning when an ellipse is followed so long that float64 rounding alone moves the body
        along its track by more than ILL_CONDITIONED of |r|: about 3 n |dt| 2**-53 (the mean anomaly n dt moves by
        its own rounding, by dt's and by 1.5 times a's: one rounding each), past 1e-8 after some 5 million
        revolutions; 1e80 s of a low Earth orbit leaves no digit."""
        with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
            a = np.where(self.e < 1.0, self.p / (1.0 - self.e * self.e), np.inf)
            drift = np.where(self.e < 1.0, 3.0 * np.sqrt(self.mu / a**3) * np.abs(dt) * 2.0**-53, 0.0)
        worst = float(np.max(drift, initial=0.0))
        if worst > ILL_CONDITIONED:
            digits = f"about {int(-np.log10(worst))} digits of it" if worst < 0.1 else "no digit of it"
            turns = float(np.max(np.abs(dt) * np.sqrt(self.mu / a**3) / (2 * np.pi), initial=0.0))
            warnings.warn(f"ill-conditioned propagation: over {turns:.3g} revolutions the rounding of dt and of the "
                          f"orbit's size alone moves the body along its track by up to {worst:.2g} of |r|; "
                          f"{digits} can be trusted", IllConditionedWarning, stacklevel=3)

    def at(self, dt: u.Quantity) -> "Orbit":
        """The Orbit reached a time dt later (same elements, new true anomaly)."""
        r, v = self.propagate(dt)
        return Orbit.from_vectors(
            self.mu << units.M3_PER_S2, r, v, mass=None if self.mass is None else self.mass << units.KG
        )

    def plot(self, ax: Any = None, projection: str = "xy", **options: Any) -> tuple[Any, Any]:
        """Draw this orbit (each orbit of an array) about its primary, in one frame: orbits.plot.orbits(self, ...)
        with `projection` "xy", "xz", "yz" or "3d"; returns (figure, axes)."""
        from orbits.twobody import plot

        return plot.orbits(self, ax=ax, projection=projection, **options)

    # ---- display --------------------------------------------------------------------------------
    def __repr__(self) -> str:
        """E.g. "Orbit(6778 x 6778 km, e = 0, i = 51.64 deg, about Earth)": periapsis x apoapsis for ellipses,
        the periapsis distance for open orbits, ranges for arrays of orbits."""
        about = self._about()
        e, i = display.summary(self.eccentricity), "i = " + display.summary(self.inclination)
        count = f"{self.e.size} orbits" if self.shape else ""
        if (self.e < 1).all():
            low, high = self.periapsis_distance, self.apoapsis_distance
            unit = display.natural_unit(high)
            low_text = display.summary(low, unit=unit).removesuffix(" " + display.unit_text(unit))
            size = f"{low_text} x {display.summary(high, unit=unit)}"
        else:
            size = "q = " + display.summary(self.periapsis_distance)
        return display.one_line(type(self).__name__, count, size, f"e = {e}", i, about)

    def _about(self) -> str:
        return f"about {display.body_name(self.mu)}"

    # ---- tables ---------------------------------------------------------------------------------
    def quantities(self, only: Iterable[str] | None = None) -> dict[str, u.Quantity]:
        """{snake_case name: Quantity} of the section XXI quantities this orbit has (or `only` those)."""
        return quantity_table(self._table_entry, QUANTITY_NAMES, only)

    def _table_entry(self, name):
        if name == "covertex_times":
            t1, t2 = self.covertex_times
            return {"covertex_time_periapsis_side": t1, "covertex_time_apoapsis_side": t2}
        return getattr(self, name)


def _mass(mass):
    """The orbiting body's mass (kg; None when not given), checked positive; the orbit broadcasts it to its shape."""
    return None if mass is None else inputs.positive(mass, units.KG, "orbiting body mass m")


def _mass_field(mass, shape):
    """The mass (kg) as a float64 array of the orbits' shape; OrbitDomainError if it holds more orbits than that."""
    if broadcast_shape(**{"orbiting body mass m": np.shape(mass), "orbits": shape}) != shape:
        raise OrbitDomainError(f"orbiting body mass m has shape {np.shape(mass)}, more than the orbits' {shape}: "
                               f"give one mass per orbit or one for all")
    return np.broadcast_to(mass, shape).astype(float)


QUANTITY_NAMES = [
    "semi_major_axis",
    "eccentricity",
    "semilatus_rectum",
    "inclination",
    "ascending_node",
    "argument_of_periapsis",
    "true_anomaly",
    "periapsis_distance",
    "apoapsis_distance",
    "focal_distance",
    "semi_minor_axis",
    "periapsis_speed",
    "apoapsis_speed",
    "covertex_speed",
    "radius",
    "speed",
    "specific_energy",
    "specific_angular_momentum",
    "areal_velocity",
    "energy",
    "angular_momentum",
    "potential_energy",
    "kinetic_energy",
    "laplace_runge_lenz_magnitude",
    "laplace_runge_lenz_along_r",
    "period",
    "mean_motion",
    "covertex_times",
    "mean_anomaly",
    "time_since_periapsis",
]
