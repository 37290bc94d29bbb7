"""Analytic answers for a scene, computing only what the scene asks for.

A scene has a closed form when it is a two-body problem: one massive body with any number of test
particles (each an independent Kepler orbit about a uniformly moving primary), or two massive bodies
and nothing else (the relative Kepler orbit with mu = G (m1 + m2) about a uniformly moving centre of
mass). States then come from the universal-variable propagator (orbits.core.twobody.propagate); periods from
Kepler's third law; closest approaches from the periapsis distance q = p / (1 + e) and the time of
periapsis passage. Conserved quantities need no closed form: they are measured on any trajectory
(see invariants).
"""

import time
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np

from orbits.core.errors import SceneError
from orbits.core.twobody import anomalies, elements, propagate, twobody

if TYPE_CHECKING:
    from orbits.validate.scene import Scene

CLOSED_FORM = "two-body closed form (universal variables)"


@dataclass(frozen=True, eq=False)
class Prediction:
    """Analytic answers (SI): states at the scene's times, periods and closest approaches per orbiting body."""

    positions: np.ndarray | None
    velocities: np.ndarray | None
    periods: dict = field(default_factory=dict)
    closest_approaches: dict = field(default_factory=dict)  # body index -> (q [m], t_periapsis [s])
    wall_time: float = 0.0
    method: str = CLOSED_FORM


def has_closed_form(scene: "Scene") -> bool:
    """True for one massive body plus test particles, or exactly two massive bodies."""
    n_active, n = scene.n_active, len(scene.bodies)
    return n_active == 1 or (n_active == 2 and n == 2)


def predict(scene: "Scene") -> Prediction:
    """The analytic Prediction of every ask of the scene that needs one (SceneError if none exists)."""
    needs = {"positions", "period", "closest_approach"} & set(scene.asks)
    if needs and not has_closed_form(scene):
        raise SceneError(
            f"scene {scene.name!r}: {', '.join(sorted(needs))} need a closed form, which exists for one massive "
            f"body with test particles or for exactly two massive bodies; this scene has {scene.n_active} massive "
            f"bodies and {len(scene.bodies) - scene.n_active} test particles"
        )
    start = time.perf_counter()
    positions = velocities = None
    if "positions" in scene.asks:
        positions, velocities = two_body_states(scene, scene.times)
    periods = {i: period_of(scene, i) for i in scene.orbiting} if "period" in scene.asks else {}
    closest = {i: closest_approach_of(scene, i) for i in scene.orbiting} if "closest_approach" in scene.asks else {}
    return Prediction(positions, velocities, periods, closest, time.perf_counter() - start)


def _pair(scene, i):
    """(primary index, mu of the relative orbit, body i's mass fraction m_i / (m_primary + m_i))."""
    j = scene.bodies[i].orbit.primary if scene.bodies[i].orbit else 0
    gm_i, gm_j = scene.bodies[i].gm, scene.bodies[j].gm
    return j, gm_j + gm_i, gm_i / (gm_j + gm_i)


def two_body_states(scene: "Scene", times: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(K, N, 3) positions (m) and velocities (m/s) of every body at `times` (s), from the closed form."""
    times = np.asarray(times, dtype=float)
    r0, v0 = scene.positions, scene.velocities
    positions = np.empty((times.size, len(scene.bodies), 3))
    velocities = np.empty_like(positions)
    if scene.n_active == 1:
        centre_r = r0[0] + times[:, None] * v0[0]
        positions[:, 0], velocities[:, 0] = centre_r, v0[0]
        for i in range(1, len(scene.bodies)):
            r, v = propagate.propagate(r0[i] - r0[0], v0[i] - v0[0], scene.bodies[0].gm, times)
            positions[:, i], velocities[:, i] = centre_r + r, v0[0] + v
        return positions, velocities
    mu = scene.gm.sum()
    fraction = scene.gm[1] / mu  # m2 / (m1 + m2), formed without cancellation
    com_r = (1 - fraction) * r0[0] + fraction * r0[1]
    com_v = (1 - fraction) * v0[0] + fraction * v0[1]
    r, v = propagate.propagate(r0[1] - r0[0], v0[1] - v0[0], mu, times)
    centre = com_r + times[:, None] * com_v
    positions[:, 0], velocities[:, 0] = centre - fraction * r, com_v - fraction * v
    positions[:, 1], velocities[:, 1] = centre + (1 - fraction) * r, com_v + (1 - fraction) * v
    return positions, velocities


def period_of(scene: "Scene", i: int) -> float:
    """T = 2 pi sqrt(a**3 / mu) (s) of body i's relative orbit (SceneError for open orbits)."""
    orbit = scene.bodies[i].orbit
    if orbit.e >= 1:
        raise SceneError(f"scene {scene.name!r}: body {scene.bodies[i].name!r} is on an open orbit (e = {orbit.e})")
    return float(twobody.period(orbit.p, orbit.e, _pair(scene, i)[1]))


def periapsis_time(scene: "Scene", i: int) -> float:
    """t_p (s): when body i passes the periapsis of its relative orbit nearest to t = 0 (within half a period on an
    ellipse; an open orbit has one), minus the time since periapsis at t = 0: negative when the body starts past
    periapsis (nu > 0), positive when before it."""
    orbit = scene.bodies[i].orbit
    return -float(anomalies.time_since_periapsis(orbit.nu, orbit.p, orbit.e, _pair(scene, i)[1]))


def closest_approach_of(scene: "Scene", i: int) -> tuple[float, float]:
    """(q, t_p): periapsis distance (m) and the time (s) of the next periapsis passage of body i."""
    orbit = scene.bodies[i].orbit
    t_p = periapsis_time(scene, i)
    if t_p < 0 and orbit.e < 1:
        t_p += period_of(scene, i)
    if t_p <= 0 or t_p > scene.times[-1]:
        raise SceneError(
            f"scene {scene.name!r}: body {scene.bodies[i].name!r} passes periapsis at t = {t_p:.6g} s, outside the "
            f"scene's span (0, {scene.times[-1]:.6g}] s; start before periapsis (nu < 0) or lengthen the span"
        )
    return float(twobody.periapsis_distance(orbit.p, orbit.e)), t_p


def relative_state(
    scene: "Scene", i: int, positions: np.ndarray, velocities: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """Body i's state relative to its primary, (..., 3) each, from full (..., N, 3) states."""
    j = _pair(scene, i)[0]
    return positions[..., i, :] - positions[..., j, :], velocities[..., i, :] - velocities[..., j, :]


def osculating(scene: "Scene", i: int, positions: np.ndarray, velocities: np.ndarray) -> tuple[np.ndarray, ...]:
    """Osculating (p, e, i, Omega, omega, nu) of body i's relative orbit at each of the given states."""
    r, v = relative_state(scene, i, positions, velocities)
    return elements.state_to_elements(r, v, _pair(scene, i)[1])


def measured_period(scene: "Scene", i: int, t: float, position: np.ndarray, velocity: np.ndarray) -> float:
    """Period (s) implied by the phase body i reaches at t ~ T: T_num = 2 pi t / (2 pi + wrap(l(t) - l0)).

    The phase is the mean longitude l = Omega + omega + M, which stays well defined on circular and
    equatorial orbits where omega or Omega alone are not.
    """
    orbit = scene.bodies[i].orbit
    _, e, _, raan, argp, nu = osculating(scene, i, position, velocity)
    l0 = orbit.raan + orbit.argp + float(anomalies.mean_from_true(orbit.nu, orbit.e))
    l1 = float(raan + argp + anomalies.mean_from_true(nu, e))
    turn = 2 * np.pi
    advance = (l1 - l0 + np.pi) % turn - np.pi
    return t * turn / (turn + advance)


def measured_closest_approach(scene: "Scene", i: int, position: np.ndarray, velocity: np.ndarray) -> float:
    """The separation |r_i - r_primary| (m) of the integrated state at the predicted periapsis time: the distance
    actually reached there (an osculating p / (1 + e) would be conserved, and the initial state would pass)."""
    r, _ = relative_state(scene, i, position, velocity)
    return float(np.linalg.norm(r))


def length_scale(scene: "Scene", positions: np.ndarray) -> float:
    """Largest separation (m) of an orbiting body from its primary along the (K, N, 3) trajectory
    `positions` (the largest distance between two bodies if none has an orbit); position errors are
    quoted relative to it."""
    if not scene.orbiting:
        return float(np.max(np.linalg.norm(positions[:, :, None] - positions[:, None, :], axis=-1)))
    return max(float(np.max(np.linalg.norm(relative_state(scene, i, positions, positions)[0], axis=-1)))
               for i in scene.orbiting)


def invariants(
    scene: "Scene", positions: np.ndarray, velocities: np.ndarray
) -> dict[str, tuple[np.ndarray, float | None]]:
    """{name: (series, scale)} of quantities conserved along an exact trajectory, with the scale their
    drift is measured against (None: absolute).

    For every body with an orbit: its relative orbit's specific energy v**2/2 - mu/r (J/kg, against
    v0**2/2 + mu/r0, the size of the terms it is the sum of, so near-parabolic orbits with energy ~ 0
    are measured fairly), specific angular momentum h (m2/s, against |h0|) and eccentricity vector e
    (absolute). With two or more massive bodies also the system's energy sum(GM_i v_i**2)/2 -
    sum GM_i GM_j / r_ij (G J) and angular momentum sum GM_i r_i x v_i (G kg m2/s), which hold for any N.
    """
    result = {}
    for i in scene.orbiting:
        name = scene.bodies[i].name
        r, v = relative_state(scene, i, positions, velocities)
        mu = _pair(scene, i)[1]
        kinetic, potential = 0.5 * np.sum(v * v, -1), mu / np.linalg.norm(r, axis=-1)
        h = np.cross(r, v)
        result[f"energy[{name}]"] = (kinetic - potential, kinetic[0] + potential[0])
        result[f"angular_momentum[{name}]"] = (h, np.linalg.norm(h[0]))
        result[f"lrl[{name}]"] = (elements.eccentricity_vector(r, v, mu), None)
    if scene.n_active >= 2:
        gm = scene.gm[: scene.n_active]
        pos, vel = positions[:, : scene.n_active], velocities[:, : scene.n_active]
        kinetic = 0.5 * np.einsum("j,kjd,kjd->k", gm, vel, vel)
        potential = np.zeros(len(pos))
        for a in range(scene.n_active):
            for b in range(a + 1, scene.n_active):
                potential += gm[a] * gm[b] / np.linalg.norm(pos[:, a] - pos[:, b], axis=-1)
        moment = np.einsum("j,kjd->kd", gm, np.cross(pos, vel))
        result["energy[system]"] = (kinetic - potential, kinetic[0] + potential[0])
        result["angular_momentum[system]"] = (moment, np.linalg.norm(moment[0]))
    return result


def drift(series: np.ndarray, scale: float | None) -> float:
    """Largest change from the initial value, divided by `scale` (absolute change if scale is None)."""
    series = np.asarray(series)
    change = series - series[0]
    size = np.linalg.norm(change, axis=-1) if series.ndim == 2 else np.abs(change)
    return float(np.max(size) / (1.0 if scale is None else scale))
