"""N-body checks of impulsive manoeuvres and gravity assists: rebound (IAS15) and heyoka (Taylor) integrate the
coast arcs between the burns, the burns are applied as instant velocity changes, and the end state is compared
with the closed form (orbits.core.manoeuvres.ImpulsePlan, orbits.core.assist).

Work in code units: the start radius is the unit of length and sqrt(r**3 / mu) the unit of time, so the primary
has GM = 1 and every coordinate is of order 1. rebound starts a new simulation for every arc (IAS15 keeps
predictor state that a hand-made kick would invalidate); heyoka keeps one Taylor integrator and has its state
kicked between propagate_until calls. rebound and heyoka are imported inside the functions that integrate.

Measured (tests/validation/test_manoeuvres_integration.py): every manoeuvre's end state matches the prediction
within 1.5e-14 relative in both backends,
1.5e-13 for a bi-elliptic transfer out to 30 start radii.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from orbits.core.assist import outgoing_velocity
from orbits.core.elements import state_to_elements
from orbits.core.flyby import deflection_angle, impact_parameter
from orbits.core.manoeuvres import ImpulsePlan
from orbits.core.propagate import propagate

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


def _scales(plan: ImpulsePlan) -> tuple[float, float, float]:
    """(length, time, speed) units in which the plan's primary has GM = 1 and the start radius is 1."""
    length = float(np.linalg.norm(plan.r0))
    time = float(np.sqrt(length**3 / plan.mu))
    return length, time, length / time


def _arcs(plan: ImpulsePlan, time_unit: float) -> list[float]:
    """The code-unit end times of the coast arcs: each burn after the first, then the end of the plan."""
    return [t / time_unit for t in (*plan.times[1:], plan.duration)]


def _kicks(plan: ImpulsePlan, speed_unit: float) -> np.ndarray:
    return plan.delta_v / speed_unit


def integrate_plan_rebound(plan: ImpulsePlan, epsilon: float = 1e-9) -> tuple[np.ndarray, np.ndarray, str]:
    """(r, v) in SI at the end of the plan, and rebound's version: IAS15 with accuracy `epsilon` on each arc."""
    import rebound

    length, time_unit, speed = _scales(plan)
    r, v = plan.r0 / length, plan.v0 / speed
    start = 0.0
    for kick, end in zip(_kicks(plan, speed), _arcs(plan, time_unit), strict=True):
        v = v + kick
        sim = rebound.Simulation()
        sim.G = 1.0
        sim.integrator = "ias15"
        sim.integrator.epsilon = epsilon
        sim.add(m=1.0)
        sim.add(m=0.0, x=r[0], y=r[1], z=r[2], vx=v[0], vy=v[1], vz=v[2])
        sim.N_active = 1
        sim.integrate(end - start, exact_finish_time=1)
        probe, centre = sim.particles[1], sim.particles[0]
        r = np.array(probe.xyz) - np.array(centre.xyz)
        v = np.array(probe.vxyz) - np.array(centre.vxyz)
        start = end
    return r * length, v * speed, rebound.__version__


_KEPLER = {}  # the compiled heyoka integrators, by name


def _kepler_integrator(heyoka):
    """One compiled Taylor integrator of r'' = -r / |r|**3 (GM = 1), kept for the process."""
    if "ta" not in _KEPLER:
        x, y, z, vx, vy, vz = heyoka.make_vars("x", "y", "z", "vx", "vy", "vz")
        inv_r3 = (x * x + y * y + z * z) ** -1.5
        system = [(x, vx), (y, vy), (z, vz), (vx, -x * inv_r3), (vy, -y * inv_r3), (vz, -z * inv_r3)]
        _KEPLER["ta"] = heyoka.taylor_adaptive(system, [1.0, 0.0, 0.0, 0.0, 1.0, 0.0], high_accuracy=True)
    return _KEPLER["ta"]


def integrate_plan_heyoka(plan: ImpulsePlan) -> tuple[np.ndarray, np.ndarray, str]:
    """(r, v) in SI at the end of the plan, and heyoka's version: taylor_adaptive at its default tolerance
    (machine epsilon) with high_accuracy, the state kicked between propagate_until calls."""
    import copy

    import heyoka

    length, time_unit, speed = _scales(plan)
    ta = copy.copy(_kepler_integrator(heyoka))
    ta.time = 0.0
    ta.state[:] = np.concatenate([plan.r0 / length, plan.v0 / speed])
    for kick, end in zip(_kicks(plan, speed), _arcs(plan, time_unit), strict=True):
        ta.state[3:] += kick
        outcome = ta.propagate_until(end)[0]
        if outcome != heyoka.taylor_outcome.time_limit:
            raise RuntimeError(f"heyoka stopped at t = {ta.time} with outcome {outcome}; it must reach t = {end}")
    return ta.state[:3] * length, ta.state[3:] * speed, heyoka.__version__


_INTEGRATORS = {"rebound": integrate_plan_rebound, "heyoka": integrate_plan_heyoka}


def _elements(r, v, mu):
    p, e, inc, *_ = state_to_elements(r, v, mu)
    return p / ((1.0 - e) * (1.0 + e)), e, inc


def check_plan(plan: ImpulsePlan, backends: tuple[str, ...] = BACKENDS) -> list[ImpulseCheck]:
    """Integrate `plan` with each backend and compare its end state and orbit with the plan's prediction."""
    a_ref, e_ref, inc_ref = _elements(plan.final_r, plan.final_v, plan.mu)
    checks = []
    for name in backends:
        r, v, version = _INTEGRATORS[name](plan)
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


def _three_body_rebound(gm, positions, velocities, duration):
    """Heliocentric probe states at -duration and +duration (IAS15, test-particle probe)."""
    import rebound

    ends = []
    for sign in (-1.0, 1.0):
        sim = rebound.Simulation()
        sim.G = 1.0
        sim.integrator = "ias15"
        for m, r, v in zip(gm, positions, velocities, strict=True):
            sim.add(m=m, x=r[0], y=r[1], z=r[2], vx=v[0], vy=v[1], vz=v[2])
        sim.N_active = 2
        sim.integrate(sign * duration, exact_finish_time=1)
        sun, probe = sim.particles[0], sim.particles[2]
        ends.append((np.array(probe.xyz) - sun.xyz, np.array(probe.vxyz) - sun.vxyz))
    return ends, rebound.__version__


def _three_body_integrator(heyoka):
    """One compiled Taylor integrator of Sun, planet (masses as parameters) and a massless probe, kept."""
    if "three" not in _KEPLER:
        system = heyoka.model.nbody(3, masses=[heyoka.par[0], heyoka.par[1]], Gconst=1.0)
        _KEPLER["three"] = heyoka.taylor_adaptive(system, np.zeros(18), pars=[1.0, 0.0], high_accuracy=True)
    return _KEPLER["three"]


def _three_body_heyoka(gm, positions, velocities, duration):
    """Heliocentric probe states at -duration and +duration (taylor_adaptive, the probe massless)."""
    import copy

    import heyoka

    ta = copy.copy(_three_body_integrator(heyoka))
    ta.pars[:] = gm[:2]
    ends = []
    for sign in (-1.0, 1.0):
        ta.time = 0.0
        ta.state[:] = np.hstack([positions, velocities]).ravel()
        ta.propagate_until(sign * duration)
        s = ta.state.reshape(3, 6)
        ends.append((s[2, :3] - s[0, :3], s[2, 3:] - s[0, 3:]))
    return ends, heyoka.__version__


_THREE_BODY = {"rebound": _three_body_rebound, "heyoka": _three_body_heyoka}


def check_assist(mass_ratio: float, v_inf: np.ndarray, focusing: float = 1.0, duration: float = 0.3,
                 backends: tuple[str, ...] = BACKENDS) -> list[AssistCheck]:
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
    for name in backends:
        (before, after), version = _THREE_BODY[name](gm, positions, velocities, duration)
        v_in = propagate(before[0], before[1], 1.0, duration)[1]
        v_out = propagate(after[0], after[1], 1.0, -duration)[1]
        checks.append(AssistCheck(name, version, mass_ratio, v_out - v_in, predicted))
    return checks
