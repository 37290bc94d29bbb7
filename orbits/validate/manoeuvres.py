"""N-body checks of impulsive manoeuvres and gravity assists: each is posed as an NBodyProblem (the burns as
kicks, orbits.validate.nbody.Kick) and integrated by every registered backend through orbits.validate.backends, like any
scene; the end state is compared with the closed form (orbits.core.manoeuvres.impulsive.ImpulsePlan,
orbits.core.manoeuvres.assist).

Work in code units: the start radius is the unit of length and sqrt(r**3 / mu) the unit of time, so the primary
has GM = 1 and every coordinate is of order 1. The vehicle is a massless test particle.

Measured (tests/validation/test_manoeuvres_integration.py): every manoeuvre's end state matches the prediction
within 1.5e-14 relative in both backends,
1.5e-13 for a bi-elliptic transfer out to 30 start radii.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from orbits.core.encounters.flyby import deflection_angle, impact_parameter
from orbits.core.manoeuvres.assist import outgoing_velocity
from orbits.core.manoeuvres.impulsive import ImpulsePlan
from orbits.core.twobody.elements import state_to_elements
from orbits.core.twobody.propagate import propagate
from orbits.validate import backends
from orbits.validate.nbody import Kick, NBodyProblem
from orbits.validate.plan import CodeUnits

BACKENDS = ("rebound", "heyoka")


@dataclass(frozen=True)
class ImpulseCheck:
    """The end of one integrated manoeuvre against its prediction (SI, angles in rad).

    position_error and velocity_error are |x - x_pred| / |x_pred|; semi_major_axis_error is relative,
    eccentricity_error and inclination_error absolute (the prediction's elements from its own end state).
    """

    backend: str
    version: str
    final_r: np.ndarray
    final_v: np.ndarray
    position_error: float
    velocity_error: float
    semi_major_axis_error: float
    eccentricity_error: float
    inclination_error: float

    @property
    def worst(self) -> float:
        """The largest of the five errors."""
        return max(self.position_error, self.velocity_error, self.semi_major_axis_error, self.eccentricity_error,
                   self.inclination_error)


def plan_problem(plan: ImpulsePlan) -> tuple[NBodyProblem, CodeUnits]:
    """The plan as an NBodyProblem in code units (start radius 1, GM 1): the primary at rest, the vehicle a test
    particle, each burn a kick, one output at the plan's end; and the code units."""
    scale = CodeUnits(float(np.linalg.norm(plan.r0)), plan.mu)
    kicks = tuple(Kick(t / scale.time, 1, dv / scale.speed) for t, dv in zip(plan.times, plan.delta_v, strict=True))
    problem = NBodyProblem(gm=[1.0, 0.0], positions=[np.zeros(3), plan.r0 / scale.length],
                           velocities=[np.zeros(3), plan.v0 / scale.speed], n_active=1,
                           times=[plan.duration / scale.time], kicks=kicks)
    return problem, scale


def _end_state(name: str, problem: NBodyProblem, scale: CodeUnits) -> tuple[np.ndarray, np.ndarray, str]:
    """(r, v) in SI of the vehicle relative to the primary at the problem's last time, and the backend's version."""
    result = backends.integrate(name, problem)
    r = result.positions[-1, 1] - result.positions[-1, 0]
    v = result.velocities[-1, 1] - result.velocities[-1, 0]
    return r * scale.length, v * scale.speed, result.version


def _elements(r, v, mu):
    p, e, inc, *_ = state_to_elements(r, v, mu)
    return p / ((1.0 - e) * (1.0 + e)), e, inc


def check_plan(plan: ImpulsePlan, names: tuple[str, ...] = BACKENDS) -> list[ImpulseCheck]:
    """Integrate `plan` with each backend and compare its end state and orbit with the plan's prediction."""
    a_ref, e_ref, inc_ref = _elements(plan.final_r, plan.final_v, plan.mu)
    problem, scale = plan_problem(plan)
    checks = []
    for name in names:
        r, v, version = _end_state(name, problem, scale)
        a, e, inc = _elements(r, v, plan.mu)
        checks.append(ImpulseCheck(
            backend=name, version=version, final_r=r, final_v=v,
            position_error=float(np.linalg.norm(r - plan.final_r) / np.linalg.norm(plan.final_r)),
            velocity_error=float(np.linalg.norm(v - plan.final_v) / np.linalg.norm(plan.final_v)),
            semi_major_axis_error=float(abs(a / a_ref - 1.0)),
            eccentricity_error=float(abs(e - e_ref)),
            inclination_error=float(abs(inc - inc_ref)),
        ))
    return checks


# ---- gravity assist: Sun, planet and probe -----------------------------------------------------------------


@dataclass(frozen=True)
class AssistCheck:
    """A flyby integrated as three bodies against the patched conic (code units: GM_sun = 1, planet at r = 1).

    delta_v is the integrated change of the probe's heliocentric velocity at the encounter (both legs' osculating
    orbits about the Sun carried back to t = 0), predicted the patched-conic vector; error = |difference| /
    |predicted|.
    """

    backend: str
    version: str
    mass_ratio: float
    delta_v: np.ndarray
    predicted: np.ndarray

    @property
    def error(self) -> float:
        """|delta_v - predicted| / |predicted|."""
        return float(np.linalg.norm(self.delta_v - self.predicted) / np.linalg.norm(self.predicted))


def _turning_angle(speed, periapsis, mu):
    return deflection_angle(impact_parameter(periapsis, speed, mu), speed, mu)


def assist_scene(mass_ratio: float, v_inf: np.ndarray, focusing: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(gm, positions, velocities) of Sun, planet and probe at closest approach, heliocentric, code units.

    The planet (GM = mass_ratio) is on a circular orbit of radius 1 at (1, 0, 0); the probe passes it with the
    planet-frame excess velocity v_inf (3,) turned counterclockwise about +z, at the periapsis
    focusing * mass_ratio / |v_inf|**2 (so the turning angle is the same for every mass ratio).
    """
    planet_r = np.array([1.0, 0.0, 0.0])
    planet_v = np.array([0.0, np.sqrt(1.0 + mass_ratio), 0.0])
    speed = float(np.linalg.norm(v_inf))
    periapsis = focusing * mass_ratio / speed**2
    out = outgoing_velocity(v_inf, np.zeros(3), [0.0, 0.0, 1.0], _turning_angle(speed, periapsis, mass_ratio))
    along = (v_inf + out) / np.linalg.norm(v_inf + out)
    radial = np.cross(along, [0.0, 0.0, 1.0])
    speed_at_periapsis = np.sqrt(speed**2 + 2.0 * mass_ratio / periapsis)
    positions = np.array([np.zeros(3), planet_r, planet_r + periapsis * radial])
    velocities = np.array([np.zeros(3), planet_v, planet_v + speed_at_periapsis * along])
    return np.array([1.0, mass_ratio, 0.0]), positions, velocities


def _probe_at(name: str, gm: np.ndarray, positions: np.ndarray, velocities: np.ndarray,
              duration: float) -> tuple[tuple[np.ndarray, np.ndarray], str]:
    """The probe's heliocentric (r, v) after `duration` (code units; negative: back in time) of the Sun-planet-probe
    problem, and the backend's version. Newtonian gravity is reversible: the state at -t is the state at +t of
    the problem with every velocity reversed, with the velocities reversed back."""
    sign = 1.0 if duration >= 0 else -1.0
    problem = NBodyProblem(gm=gm, positions=positions, velocities=sign * velocities, n_active=2,
                           times=[abs(duration)])
    result = backends.integrate(name, problem)
    r = result.positions[-1]
    v = sign * result.velocities[-1]
    return (r[2] - r[0], v[2] - v[0]), result.version


def check_assist(mass_ratio: float, v_inf: np.ndarray, focusing: float = 1.0, duration: float = 0.3,
                 names: tuple[str, ...] = BACKENDS) -> list[AssistCheck]:
    """Integrate the Sun-planet-probe flyby of assist_scene from t = 0 back and forth by `duration` (code units)
    and compare the change of the probe's heliocentric velocity with the patched conic's v_inf_out - v_inf_in.

    Each leg's end state is carried back to t = 0 on its Kepler orbit about the Sun alone, so the difference is
    what the planet did; the patched conic neglects the Sun during the pass and the planet outside it, errors of
    the order of powers of the mass ratio.
    """
    v_inf = np.asarray(v_inf, dtype=float)
    gm, positions, velocities = assist_scene(mass_ratio, v_inf, focusing)
    speed = float(np.linalg.norm(v_inf))
    angle = _turning_angle(speed, focusing * mass_ratio / speed**2, mass_ratio)
    predicted = outgoing_velocity(v_inf, np.zeros(3), [0.0, 0.0, 1.0], angle) - v_inf
    checks = []
    for name in names:
        before, version = _probe_at(name, gm, positions, velocities, -duration)
        after, _ = _probe_at(name, gm, positions, velocities, duration)
        v_in = propagate(before[0], before[1], 1.0, duration)[1]
        v_out = propagate(after[0], after[1], 1.0, -duration)[1]
        checks.append(AssistCheck(name, version, mass_ratio, v_out - v_in, predicted))
    return checks
