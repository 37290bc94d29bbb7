"""N-body problems built from the models' closed forms, for the model scenes of `orbits validate`.

Each builder returns an NBodyProblem in G = 1 code units and what the model predicts the integration should do
(an Expectation record, or the analytic positions). The domain objects (RestrictedThreeBody, Ring,
ExpandingSphere) answer in closed form; these builders set the same physics up for rebound and heyoka.
"""

import math
import operator
from collections.abc import Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import ArrayLike

from orbits.core.checks import require_positive
from orbits.core.cosmology import sphere
from orbits.core.errors import OrbitDomainError
from orbits.core.threebody import lagrange, rings
from orbits.threebody.rings import BREAKUP_DEVIATION, ROUND_OFF_SEED
from orbits.validate.nbody import NBodyProblem

if TYPE_CHECKING:
    import astropy.units as u

    from orbits.threebody.lagrange import RestrictedThreeBody

POINTS = lagrange.POINTS


# ---- test particles at the Lagrange points ---------------------------------------------------------------------
@dataclass(frozen=True, eq=False)
class LagrangeExpectation:
    """What the test particle `index` of a lagrange_test_particles_problem should do. Code units: r = 1,
    G (M + m) = 1, so n = 1 and the binary's period is 2 pi.

    `position` is the rotating-frame equilibrium; `offset` the initial displacement along the growing mode
    (0 for linearly stable points, which start on the point); `growth_rate` the predicted e-folding rate
    (0 if linearly stable); `jacobi_constant` that of the initial state, conserved exactly by the motion.
    """

    point: str
    index: int
    mass_ratio: float
    position: np.ndarray
    offset: float
    growth_rate: float
    jacobi_constant: float

    def deviations(self, positions: np.ndarray) -> np.ndarray:
        """|r_rot - position| at each output of integrated (K, N, 3) positions, the rotating frame being the one
        the integrated primaries (bodies 0 and 1) define, so their own phase error does not count."""
        particle, primary, secondary = positions[:, self.index], positions[:, 0], positions[:, 1]
        r_rot = lagrange.rotating_coordinates(particle, primary, secondary, self.mass_ratio)
        return np.linalg.norm(r_rot - self.position, axis=-1)

    def jacobi_constants(self, positions: np.ndarray, velocities: np.ndarray) -> np.ndarray:
        """The particle's Jacobi constant at each output, from inertial (K, N, 3) states about the barycentre."""
        return lagrange.jacobi_constant_inertial(
            positions[:, self.index], velocities[:, self.index], positions[:, 0], positions[:, 1], self.mass_ratio
        )


def lagrange_test_particles_problem(
    mass_ratio: float, times: ArrayLike, points: Sequence[str] = POINTS, offset: float = 0.0
) -> tuple[NBodyProblem, list[LagrangeExpectation]]:
    """(NBodyProblem, [LagrangeExpectation]): a circular binary (G M = 1 - mu at (-mu, 0, 0), G m = mu at
    (1 - mu, 0, 0), n = 1, period 2 pi) with one massless test particle per point of `points`, and what each
    should do. Unstable points start `offset` (units of r) along their growing mode; stable ones on the point.
    `times` are output times in code units."""
    mu = float(lagrange.check_mass_ratio(mass_ratio))
    r_rot, modes = lagrange.positions(mu), lagrange.growing_mode(mu)
    rates = lagrange.growth_rates(mu)
    positions = [[-mu, 0.0, 0.0], [1.0 - mu, 0.0, 0.0]]
    velocities = [[0.0, -mu, 0.0], [0.0, 1.0 - mu, 0.0]]
    expectations = []
    for point in points:
        k = POINTS.index(point)
        r0, v0 = r_rot[k] + offset * modes[k, :3], offset * modes[k, 3:]
        r_in, v_in = lagrange.rotating_to_inertial(r0, v0, 0.0)
        positions.append(r_in)
        velocities.append(v_in)
        jacobi = float(lagrange.jacobi_constant(r0, v0, mu))
        moved = offset if rates[k] > 0.0 else 0.0
        index = len(positions) - 1
        expectations.append(LagrangeExpectation(point, index, mu, r_rot[k], moved, float(rates[k]), jacobi))
    gm = [1.0 - mu, mu] + [0.0] * len(expectations)
    problem = NBodyProblem(gm=gm, positions=positions, velocities=velocities, n_active=2, times=times)
    return problem, expectations


def fitted_growth_rate(times: ArrayLike, amplitudes: ArrayLike, low: float = 1e-9, high: float = 1e-4) -> float:
    """Least-squares slope of ln(amplitude) against time over the samples with low <= amplitude <= high:
    the measured e-folding rate of an exponential departure (units of 1/time)."""
    times, amplitudes = np.asarray(times, dtype=float), np.asarray(amplitudes, dtype=float)
    window = (amplitudes >= low) & (amplitudes <= high)
    if np.count_nonzero(window) < 3:
        raise OrbitDomainError(f"fewer than 3 samples with {low} <= amplitude <= {high}: cannot fit a growth rate")
    slope, _ = np.polyfit(times[window], np.log(amplitudes[window]), 1)
    return float(slope)


# ---- a ring integrated from its exact initial state ---------------------------------------------------------
@dataclass(frozen=True, eq=False)
class RingExpectation:
    """What a ring_problem should do. Code units: r = 1, omega = 1 (period 2 pi). `first_body` is the index of
    ring body 0 (1 when a central mass is body 0); `growth_rate` (0 if stable), `mode` (None if stable) and
    `breakup_time` (inf if stable) are the linear predictions for a round-off seed of ROUND_OFF_SEED."""

    n: int
    first_body: int
    growth_rate: float
    mode: int | None
    breakup_time: float

    def shape_deviations(self, positions: np.ndarray) -> np.ndarray:
        """Largest chord error |d_kl - 2 sin(pi |k - l| / n)| of the ring at each output of (K, N, 3) positions."""
        return rings.shape_deviation(positions[:, self.first_body :], 1.0)

    def measured_breakup_time(
        self, times: np.ndarray, positions: np.ndarray, level: float = BREAKUP_DEVIATION
    ) -> float:
        """First output time at which the shape deviation reaches `level`; inf if it never does."""
        reached = np.flatnonzero(self.shape_deviations(positions) >= level)
        return float(times[reached[0]]) if reached.size else math.inf


def ring_problem(
    n: int, times: ArrayLike, central_ratio: float = 0.0, phase: float = 0.0, extended: bool = False
) -> tuple[NBodyProblem, RingExpectation]:
    """(NBodyProblem, RingExpectation): n bodies of G m = 1 / (beta + S_n / 4) on the unit circle at
    omega = 1 (angle phase + 2 pi k / n), preceded by a central body of G M = beta G m when beta = M / m > 0;
    `times` in code units. The state is exact to rounding, so round-off alone seeds any instability.

    extended=True builds the state in long double (for heyoka's fp_type="long double"): the seed is then
    long double round-off, ROUND_OFF_SEED scaled by the ratio of the two machine epsilons (about 5e-20), and
    the predicted break-up later by ln(1e-16 / 5e-20) / rate."""
    n = rings.check_count(n)
    beta = float(central_ratio)
    rate, mode = rings.growth_rate(n, beta)
    if extended:
        masses, positions, velocities = _long_double_ring(n, beta, phase)
        seed = ROUND_OFF_SEED * float(np.finfo(np.longdouble).eps / np.finfo(np.float64).eps)
        problem = NBodyProblem(gm=masses, positions=positions, velocities=velocities, n_active=masses.size,
                               times=times)
        breakup = float(rings.breakup_time(rate, seed, BREAKUP_DEVIATION))
        return problem, RingExpectation(n, int(beta > 0.0), rate, mode, breakup)
    gm = 1.0 / (beta + 0.25 * rings.csc_sum(n))
    positions, velocities = rings.state_vectors(n, 1.0, 1.0, phase)
    masses = np.full(n, gm)
    if beta > 0.0:
        positions, velocities = np.vstack([np.zeros(3), positions]), np.vstack([np.zeros(3), velocities])
        masses = np.concatenate([[beta * gm], masses])
    problem = NBodyProblem(gm=masses, positions=positions, velocities=velocities, n_active=masses.size, times=times)
    breakup = float(rings.breakup_time(rate, ROUND_OFF_SEED, BREAKUP_DEVIATION))
    return problem, RingExpectation(n, int(beta > 0.0), rate, mode, breakup)


def _long_double_ring(n, beta, phase):
    """(gm, positions, velocities) of ring_problem's state computed in long double (x87: 64-bit mantissa)."""
    one = np.longdouble(1)
    pi = 4 * np.arctan(one)
    k = np.arange(n, dtype=np.longdouble)
    theta = np.longdouble(phase) + 2 * pi * k / n
    csc = np.sort(1 / np.sin(pi * np.arange(1, n, dtype=np.longdouble) / n))
    gm = one / (np.longdouble(beta) + np.sum(csc) / 4)
    zeros = np.zeros(n, dtype=np.longdouble)
    positions = np.stack([np.cos(theta), np.sin(theta), zeros], axis=-1)
    velocities = np.stack([-np.sin(theta), np.cos(theta), zeros], axis=-1)
    masses = np.full(n, gm)
    if beta > 0.0:
        origin = np.zeros((1, 3), dtype=np.longdouble)
        positions, velocities = np.vstack([origin, positions]), np.vstack([origin, velocities])
        masses = np.concatenate([[np.longdouble(beta) * gm], masses])
    return masses, positions, velocities


# ---- the notes' expanding sphere (XXIV) ----------------------------------------------------------------------
def _fibonacci_directions(n):
    """n unit vectors spread evenly over the sphere (golden-angle spiral), shape (n, 3)."""
    k = np.arange(n) + 0.5
    z = 1.0 - 2.0 * k / n
    phi = k * math.pi * (3.0 - math.sqrt(5.0))
    rho = np.sqrt((1.0 - z) * (1.0 + z))
    return np.stack([rho * np.cos(phi), rho * np.sin(phi), z], axis=-1)


def expanding_sphere_problem(
    n_shells: int = 8,
    *,
    inner_radius: float = 1.0,
    outer_radius: float = 4.0,
    duration: float = 20.0,
    n_times: int = 11,
) -> tuple[NBodyProblem, np.ndarray]:
    """(NBodyProblem, analytic positions) for the notes' expanding sphere (XXIV) as a validation scene.

    Code units, G = 1: a central mass gm = 1 at rest at the origin (body 0), and n_shells test particles
    (bodies 1..n) at radii spaced evenly from inner_radius to outer_radius along directions spread over the
    sphere, each moving radially outward at the zero-energy speed sqrt(2 / r). Radial orbits have h = 0,
    which the N-body integrators handle. Shell i started at its own big bang, t0_i = sqrt(2 r_i**3 / 9) before
    the integration starts, so at integration time tau its radius is (9 (t0_i + tau)**2 / 2)**(1/3) and its
    Hubble parameter 2 / (3 (t0_i + tau)). Output times are n_times evenly spaced in [0, duration].

    Returned positions have shape (n_times, n_shells + 1, 3). To read physical units, pick a length L and a
    mass M: lengths scale by L, times by sqrt(L**3 / (G M)) and speeds by sqrt(G M / L).
    """
    n = _count(n_shells, "n_shells", 1)
    steps = _count(n_times, "n_times", 2)
    for value, name in ((inner_radius, "inner_radius"), (outer_radius, "outer_radius"), (duration, "duration")):
        require_positive(np.asarray(value, dtype=float), name, "(code units)")
    if outer_radius < inner_radius:
        raise OrbitDomainError(f"outer_radius = {outer_radius!r} is below inner_radius = {inner_radius!r}")
    radii = np.linspace(inner_radius, outer_radius, n)
    directions = _fibonacci_directions(n)
    times = np.linspace(0.0, duration, steps)
    problem = NBodyProblem(
        gm=np.concatenate(([1.0], np.zeros(n))),
        positions=np.vstack([np.zeros(3), radii[:, None] * directions]),
        velocities=np.vstack([np.zeros(3), np.sqrt(2.0 / radii)[:, None] * directions]),
        n_active=1,
        times=times,
    )
    t_big_bang = sphere.sphere_time(radii, 1.0)
    shells = sphere.sphere_radius(t_big_bang + times[:, None], 1.0)[..., None] * directions
    return problem, np.concatenate([np.zeros((steps, 1, 3)), shells], axis=1)


def _count(value, name, minimum):
    """An integer >= minimum (bool rejected), or OrbitDomainError."""
    try:
        count = operator.index(value)
    except TypeError:
        raise OrbitDomainError(f"{name} = {value!r} is not an integer") from None
    if isinstance(value, bool) or count < minimum:
        raise OrbitDomainError(f"{name} = {value!r} is outside the allowed range [{minimum}, inf) (an integer)")
    return count


# ---- the solar system from the ephemeris -----------------------------------------------------------------------
#: the bodies of the solar_system scene, each a DE421 point with its DE430 GM
SOLAR_SYSTEM = ("Sun", "Mercury", "Venus", "Earth", "Moon", "Mars", "Jupiter", "Saturn", "Uranus", "Neptune", "Pluto")
AU = 149_597_870_700.0
DAY = 86_400.0


def mercury_gr_advance() -> float:
    """Mercury's perihelion advance by general relativity (arcsec per Julian century): the public
    orbits.perturb.secular.relativistic_periapsis_advance, 6 pi G M / (c**2 a (1 - e**2)) per orbit, of Standish's
    mean orbit; 42.98 (Clemence 1947; Will, Living Rev. Relativ. 17, 4, 2014)."""
    import astropy.units as u

    from orbits.perturb.secular import relativistic_periapsis_advance
    from orbits.twobody.orbit import Orbit

    _, rate = relativistic_periapsis_advance(Orbit.from_body("Mercury"))
    return float((rate * 36525 * u.day).to_value(u.arcsec))


@dataclass(frozen=True, eq=False)
class SolarSystemExpectation:
    """What DE421 says the solar_system problem should do: positions (m) of every body at the output times
    (heliocentric for the planets, geocentric for the Moon, barycentric for the Sun), and the osculating
    heliocentric eccentricity vector of Mercury at the last output."""

    names: tuple[str, ...]
    relative: np.ndarray  # (K, N, 3) m: body minus its reference point (the Sun, the Earth or the barycentre)
    mercury_eccentricity: np.ndarray  # (3,)
    mercury_normal: np.ndarray  # (3,) unit orbit normal at the last output
    years: float

    def relative_positions(self, positions: np.ndarray) -> np.ndarray:
        """(K, N, 3) m: each body relative to its reference point, from barycentric positions in metres."""
        return _relative(positions, self.names)

    def perihelion_lag(self, positions: np.ndarray, velocities: np.ndarray, gm_sun_mercury: float) -> float:
        """Angle (arcsec) by which the integrated perihelion of Mercury trails DE421's at the last output (> 0:
        the integration's perihelion is behind)."""
        i, sun = self.names.index("Mercury"), self.names.index("Sun")
        e = _eccentricity_vector(positions[-1, i] - positions[-1, sun], velocities[-1, i] - velocities[-1, sun],
                                 gm_sun_mercury)
        turn = np.cross(e, self.mercury_eccentricity) @ self.mercury_normal
        return math.degrees(math.atan2(turn, e @ self.mercury_eccentricity)) * 3600.0


def _relative(positions, names):
    out = np.array(positions, dtype=float)
    sun, earth = names.index("Sun"), names.index("Earth")
    for i, name in enumerate(names):
        if name == "Moon":
            out[..., i, :] = positions[..., i, :] - positions[..., earth, :]
        elif name != "Sun":
            out[..., i, :] = positions[..., i, :] - positions[..., sun, :]
    return out


def _eccentricity_vector(r, v, mu):
    """e = ((v**2 - mu/r) r - (r . v) v) / mu."""
    return ((v @ v - mu / np.linalg.norm(r)) * r - (r @ v) * v) / mu


def solar_system_problem(epoch, years: float, post_newtonian: bool, outputs: int):
    """The Sun, the planets (Jupiter-Pluto as system barycentres), the Earth and the Moon from DE421 at `epoch`,
    with DE430 GMs, in code units of 1 AU and GM_Sun (time unit 58.13 d), output `outputs` times evenly over
    `years` Julian years; with `post_newtonian`, the Sun's 1PN field (speed_of_light in code units).

    Returns (NBodyProblem, SolarSystemExpectation, CodeUnits-like (length, gm)).
    """
    import astropy.units as u

    from orbits.ephemeris import positions as ephemeris

    when = ephemeris.epoch(epoch, scale="tdb")
    gm_sun = ephemeris.DE430_GM["Sun"]
    time_unit = math.sqrt(AU**3 / gm_sun)
    speed_unit = AU / time_unit
    times = np.linspace(0.0, years * 365.25 * DAY, outputs + 1)[1:]
    start = ephemeris.states(SOLAR_SYSTEM, when, source="de421")
    later = ephemeris.states(SOLAR_SYSTEM, when + times * u.s, source="de421")
    positions = np.array([start[n].r_si for n in SOLAR_SYSTEM]) / AU
    velocities = np.array([start[n].v_si for n in SOLAR_SYSTEM]) / speed_unit
    gm = np.array([ephemeris.DE430_GM[n] for n in SOLAR_SYSTEM]) / gm_sun
    c = 299_792_458.0 / speed_unit if post_newtonian else None
    problem = NBodyProblem(gm, positions, velocities, len(SOLAR_SYSTEM), times / time_unit, c)
    barycentric = np.stack([later[n].r_si for n in SOLAR_SYSTEM], axis=1)  # (K, N, 3) m
    mercury = later["Mercury"].r_si[-1] - later["Sun"].r_si[-1]
    mercury_v = later["Mercury"].v_si[-1] - later["Sun"].v_si[-1]
    normal = np.cross(mercury, mercury_v)
    expectation = SolarSystemExpectation(
        SOLAR_SYSTEM, _relative(barycentric, SOLAR_SYSTEM),
        _eccentricity_vector(mercury, mercury_v, gm_sun + ephemeris.DE430_GM["Mercury"]),
        normal / np.linalg.norm(normal), years)
    return problem, expectation, (AU, gm_sun)


def test_particle_problem(system: "RestrictedThreeBody", r: "u.Quantity", v: "u.Quantity",
                          times: "u.Quantity") -> NBodyProblem:
    """The binary of `system` and one massless particle started at the rotating-frame state r (length), v (speed),
    shape (3,), as an NBodyProblem for orbits.validate.backends.integrate, in code units: G (M + m) = 1, r = 1,
    n = 1 (the binary's period is 2 pi), output at n t for `times` (time Quantity, increasing, > 0).

    Bodies: 0 = M at (-mu, 0, 0), 1 = m at (1 - mu, 0, 0), 2 = the particle; system.rotating_track turns the
    result back into rotating-frame positions.
    """
    from orbits._common import inputs, units

    if np.ndim(system.mu) != 0:
        raise OrbitDomainError("test_particle_problem needs a single binary; this object holds an array of them")
    mu, scale, n = float(system.mu), float(system.r), float(system.angular_velocity.to_value(units.RAD_PER_S))
    speed = n * scale
    r_in, v_in = lagrange.rotating_to_inertial(inputs.vector(r, units.M, "position r") / scale,
                                               inputs.vector(v, units.M_PER_S, "velocity v") / speed, 0.0)
    return NBodyProblem(
        gm=[1.0 - mu, mu, 0.0],
        positions=[[-mu, 0.0, 0.0], [1.0 - mu, 0.0, 0.0], r_in],
        velocities=[[0.0, -mu, 0.0], [0.0, 1.0 - mu, 0.0], v_in],
        n_active=2,
        times=units.to_si(times, units.S, "times") * n,
    )
