"""Model scenes of periodic orbits of the restricted problem: each orbit flown in rebound and heyoka as a test particle
of the two primaries, which move as real bodies on their circular orbit about the barycentre (inertial frame, G = 1,
r = 1, n = 1).

What a scene measures, in the rotating frame the integrated primaries define (so their own phase error does not
count): the closure after one period and, for orbits not too unstable to keep, after `periods` periods, as the
largest |r(kT) - r(0)| over the orbit's size (its largest amplitude); the drift of the Jacobi constant; the period
itself, from the last output before it and the Newton step t = T - y / y' to the crossing of the x-z plane; and for an
unstable orbit the growth per period of a second particle started `offset` off the orbit along the monodromy's
unstable eigenvector (unit position part), against the eigenvalue lambda: |dr(kT)| = offset |lambda|**k while the
departure is linear.

The scenes register themselves with orbits.validate.models when this module is imported, which
orbits.validate.scenes does.
"""

import math
import time
from dataclasses import dataclass

import astropy.units as u
import numpy as np

from orbits.core.periodic import cr3bp
from orbits.core.threebody import lagrange
from orbits.validate import models
from orbits.validate.models import ModelScene
from orbits.validate.nbody import NBodyProblem
from orbits.validate.plan import Measurement

#: the departure is followed from its offset until the particles are DEPARTURE_END apart (units of r), its growth
#: read at the last whole period before
DEPARTURE_END = 1e-5
#: an orbit whose largest eigenvalue exceeds this is followed over one period only: ten periods would amplify the
#: trajectory's own error (1e-13) past the orbit's size
KEEPABLE_GROWTH = 10.0
MAX_PERIODS = 100


@dataclass(frozen=True, eq=False)
class PeriodicExpectation:
    """What a periodic_orbit_problem should do (code units). Body 2 is the orbit's particle, body 3 (if any) the
    particle started `offset` along the unstable eigenvector; output k is at times[k] = k_periods[k] T, with an extra
    output a period fraction before T where the period is measured."""

    mu: float
    state: np.ndarray
    period: float
    size: float
    jacobi: float
    growth: float
    offset: float
    periods: np.ndarray

    def rotating(self, positions: np.ndarray, velocities: np.ndarray, index: int) -> np.ndarray:
        """(K, 6) rotating-frame states of body `index` from integrated (K, N, 3) inertial states."""
        return cr3bp.rotating_state(positions[:, index], velocities[:, index], positions[:, 0], velocities[:, 0],
                                    positions[:, 1], velocities[:, 1], self.mu)

    def closure(self, positions, velocities, periods: int) -> float:
        """|r(kT) - r(0)| / size after `periods` periods."""
        k = int(np.flatnonzero(self.periods == periods)[0])
        state = self.rotating(positions[k: k + 1], velocities[k: k + 1], 2)[0]
        return float(np.linalg.norm(state[:3] - self.state[:3])) / self.size

    def measured_period(self, times, positions, velocities) -> float:
        """T + dt where dt = -q / q' at the output t = T, q the coordinate the orbit crosses fastest at t = 0 (y, or
        z for an orbit starting on the x axis): the crossing of that plane nearest the period."""
        k = int(np.flatnonzero(self.periods == 1)[0])
        state = self.rotating(positions[k: k + 1], velocities[k: k + 1], 2)[0]
        axis = 2 if self.state[2] == 0.0 and abs(self.state[5]) > abs(self.state[4]) else 1
        return float(times[k]) - state[axis] / state[3 + axis]

    def jacobi_drift(self, positions, velocities) -> float:
        c = lagrange.jacobi_constant_inertial(positions[:, 2], velocities[:, 2], positions[:, 0], positions[:, 1],
                                              self.mu)
        return float(np.max(np.abs(c - self.jacobi)) / abs(self.jacobi))

    def measured_growth(self, positions, velocities) -> float:
        """|lambda| per period from the separation d_k of the two particles at the integer periods k:
        (d_k / offset)**(1 / k) at the last k whose separation is still below DEPARTURE_END (the linear regime)."""
        whole = np.flatnonzero(self.periods == np.round(self.periods))
        orbit = self.rotating(positions[whole], velocities[whole], 2)
        shifted = self.rotating(positions[whole], velocities[whole], 3)
        separation = np.linalg.norm(shifted[:, :3] - orbit[:, :3], axis=-1)
        linear = np.flatnonzero(separation <= DEPARTURE_END)
        if linear.size == 0:
            return math.nan
        last = linear[-1]
        return float((separation[last] / self.offset) ** (1.0 / self.periods[whole][last]))


def periodic_orbit_problem(orbit, periods: int = 10, offset: float | None = None
                           ) -> tuple[NBodyProblem, PeriodicExpectation]:
    """(NBodyProblem, PeriodicExpectation) of a PeriodicOrbit (orbits.periodic.family): the binary (G M = 1 - mu at
    (-mu, 0, 0), G m = mu at (1 - mu, 0, 0), n = 1) and the orbit's particle, output at 1 .. `periods` periods and
    just before the first; with `offset` (units of r) a second particle that far along the unstable eigenvector,
    output at every period until the predicted separation passes DEPARTURE_END."""
    mu = float(orbit.system.mu)
    state = np.asarray(orbit.dimensionless_state, dtype=float)
    period = float(orbit.dimensionless_period)
    growth = float(np.max(np.abs(orbit.eigenvalues))) if offset is not None else 1.0
    if offset is not None:
        last = math.ceil(math.log(DEPARTURE_END / offset) / math.log(growth)) + 1
        periods = max(periods, last)
    k = np.concatenate([[1.0 - 1e-3], np.arange(1, periods + 1, dtype=float)])
    positions = [[-mu, 0.0, 0.0], [1.0 - mu, 0.0, 0.0]]
    velocities = [[0.0, -mu, 0.0], [0.0, 1.0 - mu, 0.0]]
    starts = [state]
    if offset is not None:
        starts.append(state + offset * _unstable_direction(orbit.monodromy))
    for s in starts:
        r, v = lagrange.rotating_to_inertial(s[:3], s[3:], 0.0)
        positions.append(r)
        velocities.append(v)
    problem = NBodyProblem(gm=[1.0 - mu, mu] + [0.0] * len(starts), positions=positions, velocities=velocities,
                           n_active=2, times=k * period)
    size = float(np.max(orbit.amplitudes.to_value(u.m))) / float(orbit.system.r)
    jacobi = float(cr3bp.jacobi_constant(state, mu))
    return problem, PeriodicExpectation(mu, state, period, size, jacobi, growth, offset or 0.0, k)


def _unstable_direction(monodromy) -> np.ndarray:
    """The real eigenvector of the largest |eigenvalue|, scaled to a unit position part."""
    values, vectors = np.linalg.eig(monodromy)
    k = int(np.argmax(np.abs(values)))
    vector = np.real(vectors[:, k])
    return vector / np.linalg.norm(vector[:3])


#: tolerances, about ten times the worst of rebound's and heyoka's errors measured on the built-in scenes and on the
#: Earth-Moon and Sun-Earth orbits of tests/validation/test_periodic_scenes.py: closure after one period 9.1e-11 of
#: the size (a Sun-Earth vertical orbit), after ten 3.0e-10 (the 9:2 NRHO, whose eigenvalue -2.18 amplifies the
#: first period's error 2.18**9 times), the period 5.7e-12, the Jacobi constant 5.3e-14 (the NRHO's perilune
#: passages), the departure per period 4.8e-5 of |lambda_max| (the NRHO)
TOLERANCES = {"closure": 1e-9, "closure_kept": 3e-9, "jacobi": 6e-13, "period": 6e-11, "growth": 5e-4}


def periodic_scene(name: str, description: str, orbit, periods: int = 10, offset: float = 1e-11,
                   predict_seconds: float = 0.0) -> ModelScene:
    """The ModelScene of a PeriodicOrbit: closure after one period (and `periods` periods for an orbit whose
    eigenvalues stay below KEEPABLE_GROWTH), Jacobi constant and period; an unstable orbit departs at its
    eigenvalue's rate from `offset`."""
    start = time.perf_counter()
    growth = float(np.max(np.abs(orbit.eigenvalues)))
    unstable = not orbit.stable
    kept = periods if growth <= KEEPABLE_GROWTH else 1
    problem, expected = periodic_orbit_problem(orbit, kept, offset if unstable else None)
    seconds = predict_seconds + time.perf_counter() - start

    def checks(times, positions, velocities):
        rows = [Measurement("closure after one period: |dr| / size", "", 0.0,
                            expected.closure(positions, velocities, 1), TOLERANCES["closure"], "absolute drift")]
        if kept > 1:
            rows.append(Measurement(f"closure after {kept} periods: |dr| / size", "", 0.0,
                                    expected.closure(positions, velocities, kept), TOLERANCES["closure_kept"],
                                    "absolute drift"))
        rows.append(Measurement("period from the next crossing of the starting plane", "time unit", expected.period,
                                expected.measured_period(times, positions, velocities), TOLERANCES["period"],
                                "relative error"))
        rows.append(Measurement("Jacobi constant", "", expected.jacobi, expected.jacobi_drift(positions, velocities),
                                TOLERANCES["jacobi"], "relative drift"))
        if unstable:
            rows.append(Measurement("departure per period vs |largest eigenvalue|", "", expected.growth,
                                    expected.measured_growth(positions, velocities), TOLERANCES["growth"],
                                    "relative error"))
        return rows

    return ModelScene(name, description, problem, None, 1.0, {}, seconds, checks, period=expected.period)


def _earth_moon():
    from orbits import RestrictedThreeBody

    return RestrictedThreeBody.from_primaries("Earth", "Moon")


def _timed(build):
    start = time.perf_counter()
    orbit = build()
    return orbit, time.perf_counter() - start


def lyapunov_scene(periods: int = 10) -> ModelScene:
    """The Earth-Moon L1 planar Lyapunov orbit of Ax = 20,000 km."""
    from orbits.periodic.family import PeriodicOrbit

    orbit, seconds = _timed(lambda: PeriodicOrbit.lyapunov(_earth_moon(), "L1", ax=20_000 * u.km))
    return periodic_scene("periodic_lyapunov", f"The {orbit.describe()} orbit of Ax = 20,000 km (T = "
                          f"{orbit.period.to_value(u.d):.4f} d) flown around the moving primaries", orbit, periods,
                          predict_seconds=seconds)


def halo_scene(periods: int = 10) -> ModelScene:
    """The Earth-Moon L2 southern halo orbit of Az = 20,000 km."""
    from orbits.periodic.family import PeriodicOrbit

    orbit, seconds = _timed(lambda: PeriodicOrbit.halo(_earth_moon(), "L2", az=20_000 * u.km, branch="southern"))
    return periodic_scene("periodic_halo", f"The {orbit.describe()} orbit of Az = 20,000 km (T = "
                          f"{orbit.period.to_value(u.d):.4f} d) flown around the moving primaries", orbit, periods,
                          predict_seconds=seconds)


def dro_scene(periods: int = 10) -> ModelScene:
    """The Earth-Moon distant retrograde orbit of Ax = 70,000 km."""
    from orbits.periodic.family import PeriodicOrbit

    orbit, seconds = _timed(lambda: PeriodicOrbit.distant_retrograde(_earth_moon(), ax=70_000 * u.km))
    return periodic_scene("periodic_dro", f"The {orbit.describe()} orbit of Ax = 70,000 km (T = "
                          f"{orbit.period.to_value(u.d):.4f} d) flown around the moving primaries", orbit, periods,
                          predict_seconds=seconds)


def nrho_scene(periods: int = 10) -> ModelScene:
    """The Earth-Moon L2 southern 9:2 synodic-resonant near-rectilinear halo orbit."""
    from orbits.periodic.family import PeriodicOrbit

    orbit, seconds = _timed(lambda: PeriodicOrbit.near_rectilinear(_earth_moon(), resonance="9:2"))
    perilune = orbit.closest_approaches[1].to_value(u.km)
    return periodic_scene("periodic_nrho", f"The {orbit.describe()} orbit in 9:2 synodic resonance (T = "
                          f"{orbit.period.to_value(u.d):.4f} d, perilune {perilune:.0f} km) flown around the moving "
                          f"primaries", orbit, periods, predict_seconds=seconds)


SCENES = {"periodic_lyapunov": lyapunov_scene, "periodic_halo": halo_scene, "periodic_dro": dro_scene,
          "periodic_nrho": nrho_scene}
models.register(SCENES, {name: {"periods": models._count(1, MAX_PERIODS)} for name in SCENES})
