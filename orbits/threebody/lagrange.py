"""RestrictedThreeBody: the Lagrange points of a circular binary (section XXII.viii of the notes), with units.

    >>> from orbits import RestrictedThreeBody
    >>> em = RestrictedThreeBody.from_primaries("Earth", "Moon")
    >>> round(float(em.distances_to_secondary[0].to_value("km")))  # L1, on the Earth side of the Moon
    58019

The binary (GM_1 >= GM_2 at separation r) turns at n = sqrt(G (M + m) / r**3) about its barycentre; every
quantity is the dimensionless one of orbits.core.threebody.lagrange times r, n or (n r)**2. Rotating frame: origin at
the barycentre, x from M towards m, z along the orbital angular momentum; the inertial frame has the same
origin, with the binary in the plane of inclination `inc` and ascending node `raan`, and m at the argument of
latitude `phase` at t = 0.

The matching N-body problem for rebound and heyoka is built in orbits.validate.builders.
"""

from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from functools import cached_property

import astropy.units as u
import numpy as np

from orbits._common import display, inputs, units
from orbits._common.constants import Body, body
from orbits.core.errors import OrbitDomainError, UnknownNameError
from orbits.core.threebody import lagrange

POINTS = lagrange.POINTS
PER_SECOND = 1 / u.s


def _separation(primary, secondary, separation):
    """r (m): the given length, or the catalogued mean distance a of a named secondary about that primary."""
    if separation is not None:
        value = inputs.positive(separation, units.M, "separation r")
        return value
    target = body(secondary) if isinstance(secondary, str) else secondary
    centre = body(primary).name if isinstance(primary, str) else getattr(primary, "name", None)
    if not isinstance(target, Body) or target.orbit is None or target.orbit.primary != centre:
        raise OrbitDomainError("separation r is needed: the secondary is not a catalogued body orbiting the primary")
    return np.asarray(target.orbit.a)


@dataclass(frozen=True, eq=False, repr=False)
class RestrictedThreeBody(display.Displayed):
    """Circular restricted three-body problem of a binary; fields are float64 SI arrays that broadcast together.

    Build it with RestrictedThreeBody.from_primaries. `gm_primary` >= `gm_secondary` (m3/s2), the separation
    `r` (m), and the binary's orientation `inc`, `raan` and `phase` (rad).
    """

    gm_primary: np.ndarray
    gm_secondary: np.ndarray
    r: np.ndarray
    inc: np.ndarray
    raan: np.ndarray
    phase: np.ndarray

    @classmethod
    def from_primaries(
        cls,
        primary: Body | str | u.Quantity,
        secondary: Body | str | u.Quantity,
        separation: u.Quantity | None = None,
        *,
        inc: u.Quantity = 0 * u.deg,
        raan: u.Quantity = 0 * u.deg,
        phase: u.Quantity = 0 * u.deg,
    ) -> "RestrictedThreeBody":
        """Binary of `primary` and `secondary` (each a Body, a name, a mass or a GM Quantity) at `separation`
        (length; default: the secondary's catalogued mean distance a from the primary, e.g. Earth-Moon).

        mu = m / (M + m) must lie in (0, 1/2]: OrbitDomainError otherwise, naming the value.
        """
        gm_1 = inputs.gravitational_parameter(primary, "primary mass M")
        gm_2 = inputs.gravitational_parameter(secondary, "secondary mass m")
        lagrange.check_mass_ratio(gm_2 / (gm_1 + gm_2))
        distance = _separation(primary, secondary, separation)
        angles = [
            inputs.angle(x, name)
            for x, name in ((inc, "inclination i"), (raan, "ascending node Omega"), (phase, "phase"))
        ]
        fields = np.broadcast_arrays(gm_1, gm_2, distance, *angles)
        return cls(*(np.array(x, dtype=float) for x in fields))

    # ---- the binary -------------------------------------------------------------------------------
    @cached_property
    def mu(self) -> np.ndarray:
        """mu = m / (M + m) (float64 array), the only parameter of the dimensionless problem."""
        return self.gm_secondary / (self.gm_primary + self.gm_secondary)

    @cached_property
    def mass_ratio(self) -> u.Quantity:
        """mu = m / (M + m) (dimensionless)."""
        return self.mu << u.one

    @cached_property
    def separation(self) -> u.Quantity:
        """r (m), the distance between the primaries."""
        return self.r << units.M

    @cached_property
    def _n(self):
        return np.sqrt((self.gm_primary + self.gm_secondary) / self.r**3)

    @cached_property
    def angular_velocity(self) -> u.Quantity:
        """n = sqrt(G (M + m) / r**3) (rad/s) of the binary and of the rotating frame."""
        return self._n << units.RAD_PER_S

    @cached_property
    def period(self) -> u.Quantity:
        """T = 2 pi / n (s)."""
        return 2.0 * np.pi / self._n << units.S

    # ---- the points -----------------------------------------------------------------------------
    @cached_property
    def positions(self) -> u.Quantity:
        """Rotating-frame positions of L1..L5 (m), shape (..., 5, 3); each coordinate within 2**-52 r."""
        return lagrange.positions(self.mu) * self.r[..., None, None] << units.M

    @cached_property
    def _distances(self):
        return lagrange.distances(self.mu) * self.r[..., None, None]

    @cached_property
    def distances_to_primary(self) -> u.Quantity:
        """|L_k - M| (m), shape (..., 5)."""
        return self._distances[..., 0] << units.M

    @cached_property
    def distances_to_secondary(self) -> u.Quantity:
        """|L_k - m| (m), shape (..., 5); for L1 and L2 the offset rho, to 2 ulp even for mu = 1e-15."""
        return self._distances[..., 1] << units.M

    @cached_property
    def jacobi_constants(self) -> u.Quantity:
        """C(L_k) = -2 Phi(L_k) (m2/s2), shape (..., 5): the Jacobi constant of a particle at rest at each point."""
        c = lagrange.jacobi_constant(lagrange.positions(self.mu), np.zeros(3), self.mu[..., None])
        return c * self._scale_squared[..., None] << units.M_PER_S**2

    @cached_property
    def _scale_squared(self):
        return (self._n * self.r) ** 2

    @cached_property
    def eigenvalues(self) -> u.Quantity:
        """Eigenvalues of the linearised rotating-frame motion at L1..L5 (1/s), complex, shape (..., 5, 6)."""
        return lagrange.eigenvalues(self.mu) * self._n[..., None, None] << PER_SECOND

    @cached_property
    def growth_rates(self) -> u.Quantity:
        """Largest Re(eigenvalue) at L1..L5 (1/s), shape (..., 5); 0 where linearly stable."""
        return lagrange.growth_rates(self.mu) * self._n[..., None] << PER_SECOND

    @cached_property
    def e_folding_times(self) -> u.Quantity:
        """1 / growth rate (s), shape (..., 5); inf where linearly stable."""
        rates = lagrange.growth_rates(self.mu)
        with np.errstate(divide="ignore"):
            return np.where(rates > 0.0, 1.0 / rates, np.inf) / self._n[..., None] << units.S

    @cached_property
    def triangular_points_stable(self) -> np.ndarray | np.bool_:
        """True where L4 and L5 are linearly stable: mu < Routh's (1 - sqrt(23/27)) / 2 = 0.0385208965..., strictly."""
        return lagrange.triangular_points_stable(self.mu)

    # ---- states and fields ------------------------------------------------------------------------
    def inertial_states(self, t: u.Quantity) -> tuple[u.Quantity, u.Quantity]:
        """Barycentric inertial positions (m) and velocities (m/s) of L1..L5 at time t (time, broadcasting):
        shape (..., 5, 3), the frame having turned by phase + n t."""
        t_si = units.to_si(t, units.S, "time t")
        angle = (self.phase + self._n * t_si)[..., None]
        r_rot = lagrange.positions(self.mu)
        r, v = lagrange.rotating_to_inertial(r_rot, 0.0 * r_rot, angle, self.inc[..., None], self.raan[..., None])
        speed = (self._n * self.r)[..., None, None]
        return r * self.r[..., None, None] << units.M, v * speed << units.M_PER_S

    def effective_potential(self, r: u.Quantity) -> u.Quantity:
        """Phi = -G M / r_1 - G m / r_2 - n**2 (x**2 + y**2) / 2 (J/kg) at rotating-frame positions r (length)."""
        r_si = units.to_si(r, units.M, "position r") / self.r[..., None]
        return lagrange.effective_potential(r_si, self.mu) * self._scale_squared << units.J_PER_KG

    def jacobi_constant(self, r: u.Quantity, v: u.Quantity) -> u.Quantity:
        """C = -2 Phi - |v|**2 (m2/s2) of a rotating-frame state r (length) and v (speed), shape (..., 3)."""
        r_si = units.to_si(r, units.M, "position r") / self.r[..., None]
        v_si = units.to_si(v, units.M_PER_S, "velocity v") / (self._n * self.r)[..., None]
        return lagrange.jacobi_constant(r_si, v_si, self.mu) * self._scale_squared << units.M_PER_S**2

    def zero_velocity_grid(self, extent: float = 1.5, points: int = 401, center: tuple[float, float] = (0.0, 0.0)
                           ) -> tuple[u.Quantity, u.Quantity, u.Quantity]:
        """(x, y, C) for plotting zero-velocity curves: a points x points grid (m) over |x - x_c|, |y - y_c| <=
        extent r in the rotating plane about `center` (x_c, y_c) (units of r; the barycentre by default), and
        C = -2 Phi (m2/s2), the Jacobi constant of a particle at rest there (+inf on a primary). A particle of
        Jacobi constant C_0 cannot enter where C < C_0; contour C at C(L1), C(L2), ..."""
        if np.ndim(self.mu) != 0:
            raise OrbitDomainError("zero_velocity_grid needs a single binary; this object holds an array of them")
        x, y = np.meshgrid(center[0] + np.linspace(-extent, extent, points),
                           center[1] + np.linspace(-extent, extent, points))
        grid = np.stack([x, y, np.zeros_like(x)], axis=-1)
        with np.errstate(divide="ignore"):
            c = lagrange.jacobi_constant(grid, np.zeros(3), self.mu)
        r = float(self.r)
        return x * r << units.M, y * r << units.M, c * float(self._scale_squared) << units.M_PER_S**2

    def departure_state(self, point: str = "L1", offset: u.Quantity | None = None) -> tuple[u.Quantity, u.Quantity]:
        """Rotating-frame state (r in m, v in m/s, shape (3,) each) `offset` (length; 1e-6 r by default) from the
        unstable `point` along its growing mode: the linearised motion carries it off as offset * exp(lambda t),
        lambda = growth_rates of the point (orbits.core.threebody.lagrange.growing_mode: the planar eigenvector of the
        largest real eigenvalue, dv = lambda dr). OrbitDomainError for a linearly stable point."""
        if np.ndim(self.mu) != 0:
            raise OrbitDomainError("departure_state needs a single binary; this object holds an array of them")
        k = lagrange.point_index(point)
        mu, r = float(self.mu), float(self.r)
        rates = lagrange.growth_rates(mu)
        if not rates[k] > 0.0:
            unstable = ", ".join(name for name, rate in zip(POINTS, rates, strict=True) if rate > 0.0)
            raise OrbitDomainError(f"{POINTS[k]} is linearly stable at mu = {mu:.6g}: nothing departs from it "
                                   f"(unstable points there: {unstable})")
        size = 1e-6 if offset is None else inputs.single(inputs.positive, offset, units.M, "offset") / r
        if not size <= 0.01:
            raise OrbitDomainError(f"offset = {size:.3g} r: the linear departure holds only near the point; "
                                   f"give at most 0.01 r ({0.01 * r:.6g} m)")
        mode = lagrange.growing_mode(mu)[k]
        position = lagrange.positions(mu)[k] + size * mode[:3]
        return position * r << units.M, size * mode[3:] * float(self._n * self.r) << units.M_PER_S

    # ---- a test particle's integrated track -------------------------------------------------------
    def rotating_track(self, positions: np.ndarray) -> u.Quantity:
        """Rotating-frame positions (m), shape (K, 3), of the particle of
        orbits.validate.builders.test_particle_problem from the integrated
        code-unit positions (K, 3, 3), in the frame the integrated primaries define (x from M to m)."""
        positions = np.asarray(positions, dtype=float)
        mu = float(self.mu)
        track = lagrange.rotating_coordinates(positions[:, 2], positions[:, 0], positions[:, 1], mu)
        return track * float(self.r) << units.M

    # ---- tables ---------------------------------------------------------------------------------
    def __repr__(self) -> str:
        """E.g. "RestrictedThreeBody(Earth + Moon, mu = 0.01215059, r = 384399 km, T = 27.2845 d)"."""
        pair = f"{display.body_name(self.gm_primary)} + {display.body_name(self.gm_secondary)}"
        return display.one_line("RestrictedThreeBody", pair, "mu = " + display.summary(self.mass_ratio),
                                "r = " + display.summary(self.separation), "T = " + display.summary(self.period))

    def quantities(
        self, only: Iterable[str] | None = None, points: Sequence[str] = POINTS
    ) -> dict[str, u.Quantity]:
        """{name: Quantity}: BINARY_NAMES, then "<point>_<name>" for each of `points` and POINT_NAMES (the
        e-folding time only where the point is unstable). `only` takes full names ("L4_growth_rate") or
        POINT_NAMES, which expand over `points`."""
        unknown = [p for p in points if p not in POINTS]
        if unknown:
            raise UnknownNameError(f"unknown points {unknown}; choose from {', '.join(POINTS)}")
        names = []
        for name in BINARY_NAMES + [f"{p}_{n}" for p in points for n in POINT_NAMES] if only is None else only:
            if name in POINT_NAMES:
                names += [f"{p}_{name}" for p in points]
            elif name in QUANTITY_NAMES:
                names.append(name)
            else:
                allowed = ", ".join(BINARY_NAMES + list(POINT_NAMES))
                raise UnknownNameError(f"unknown quantity {name!r}; choose from {allowed}")
        result = {}
        for name in names:
            value = getattr(self, name) if name in BINARY_NAMES else self._point_quantity(*name.split("_", 1))
            if value is not None:
                result[name] = value
        return result

    def _point_quantity(self, point, name):
        """One point's value of a POINT_NAMES entry (None for the e-folding time of a stable point)."""
        k = POINTS.index(point)
        if name == "eigenvalues":
            values = self.eigenvalues[..., k, :]
            return np.stack([values.real, values.imag], axis=-1)
        table = getattr(self, POINT_NAMES[name])
        value = table[..., k, :] if name == "position" else table[..., k]
        return None if name == "e_folding_time" and not np.all(np.isfinite(value)) else value


BINARY_NAMES = ["mass_ratio", "separation", "angular_velocity", "period"]
#: Per-point names and the (..., 5)-shaped property each one reads (eigenvalues come as (re, im) pairs).
POINT_NAMES = {
    "position": "positions",
    "distance_to_primary": "distances_to_primary",
    "distance_to_secondary": "distances_to_secondary",
    "jacobi_constant": "jacobi_constants",
    "growth_rate": "growth_rates",
    "e_folding_time": "e_folding_times",
    "eigenvalues": "eigenvalues",
}
QUANTITY_NAMES = BINARY_NAMES + [f"{p}_{n}" for p in POINTS for n in POINT_NAMES]
