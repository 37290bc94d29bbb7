"""Model scenes: validation problems built from the models' closed forms (no two-body closed form needed).

A model scene is an NBodyProblem in code units plus what the model predicts: positions at the output
times and, optionally, model-specific Measurements (a measured quantity against its prediction). The
problems are built in orbits.validate.builders; this module registers them under scene names, so
`orbits validate` runs them beside the data scenes of orbits/scenes/, and a TOML/JSON file can ask for one
with `model = "<name>"` and a `[parameters]` table passed to the builder.
"""

import time
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from orbits.core.errors import SceneError
from orbits.nbody import NBodyProblem
from orbits.validate.builders import (
    expanding_sphere_problem,
    fitted_growth_rate,
    lagrange_test_particles_problem,
    ring_problem,
)
from orbits.validate.plan import CODE, Measurement, Plan, Trajectory, plan


@dataclass(frozen=True, eq=False)
class ModelScene:
    """A validation problem in code units with the model's predictions.

    `expected` holds (K, N, 3) positions at problem.times (or None); position errors are quoted relative to
    `length`. `checks(times, positions, velocities)` returns the model's Measurements on one backend's trajectory.
    """

    name: str
    description: str
    problem: NBodyProblem
    expected: np.ndarray | None
    length: float
    tolerance: dict
    predict_seconds: float = 0.0
    checks: Callable[[np.ndarray, np.ndarray, np.ndarray], list[Measurement]] | None = None


@plan.register
def _plan_model_scene(model: ModelScene) -> Plan:
    """The Plan of a model scene: its problem as built, residuals against `expected`, its own measurements."""
    residuals = None
    if model.expected is not None:
        def residuals(trajectory: Trajectory) -> np.ndarray:
            return np.max(np.linalg.norm(trajectory.positions - model.expected, axis=-1), axis=-1) / model.length

    def measure(trajectory: Trajectory) -> list[Measurement]:
        if model.checks is None:
            return []
        return model.checks(trajectory.times, trajectory.positions, trajectory.velocities)

    return Plan(
        name=model.name, description=model.description, problem=model.problem, code_units=CODE,
        predict_seconds=model.predict_seconds, residual_times=model.problem.times, residuals=residuals,
        measure=measure, positions_tolerance=model.tolerance.get("positions", 0.0),
    )


def _expanding_universe(n_shells=8, duration=20.0, outputs=40):
    """The notes' sphere of test shells (XXIV) expanding at the zero-energy speed about a unit mass."""
    start = time.perf_counter()
    problem, expected = expanding_sphere_problem(n_shells, duration=duration, n_times=outputs + 1)
    seconds = time.perf_counter() - start
    problem = type(problem)(problem.gm, problem.positions, problem.velocities, problem.n_active, problem.times[1:])
    return ModelScene(
        "expanding_universe",
        f"The notes' Einstein-de Sitter sphere (XXIV): {n_shells} test shells leaving a unit mass at the escape "
        f"speed; r(t) = (9 G M t**2 / 2)**(1/3)",
        problem, expected[1:], float(np.max(np.linalg.norm(expected[-1], axis=-1))),
        {"positions": 1e-12}, seconds,
        checks=_sphere_checks(problem),
    )


def _sphere_checks(problem):
    """Checks of the expanding sphere: each shell's H = v / r against 2 / (3 t) at the last output, t counted
    from the shell's own big bang t0 = (2/3) r0 / v0; and its energy v**2/2 - 1/r, which stays 0."""
    r0 = np.linalg.norm(problem.positions[1:], axis=-1)
    big_bang = (2.0 / 3.0) * r0 / np.linalg.norm(problem.velocities[1:], axis=-1)

    def checks(times, positions, velocities):
        r = np.linalg.norm(positions[:, 1:] - positions[:, :1], axis=-1)
        v = np.linalg.norm(velocities[:, 1:] - velocities[:, :1], axis=-1)
        hubble = np.max(np.abs((v / r) * (1.5 * (big_bang + times[:, None])) - 1))  # |H / (2 / (3t)) - 1|
        energy = np.max(np.abs(0.5 * v * v - 1.0 / r) / (0.5 * v * v + 1.0 / r))
        return [
            Measurement("Hubble parameter: max |(v/r) / (2/(3t)) - 1|", "", 0.0, float(hubble), 1e-12,
                        "relative drift"),
            Measurement("shell energy v**2/2 - GM/r (zero)", "", 0.0, float(energy), 1e-12, "relative drift"),
        ]

    return checks


def _earth_moon_mass_ratio():
    from orbits.constants import BODIES

    moon, earth = BODIES["Moon"].gm, BODIES["Earth"].gm
    return moon / (earth + moon)


def _lagrange_stable(periods=100, outputs=400):
    """Test particles on the Earth-Moon L4 and L5 points (linearly stable: mu < Routh's 0.0385)."""
    mu = _earth_moon_mass_ratio()
    start = time.perf_counter()
    times = np.linspace(0.0, periods * 2 * np.pi, outputs + 1)[1:]
    problem, expectations = lagrange_test_particles_problem(mu, times, ["L4", "L5"])
    seconds = time.perf_counter() - start

    def checks(times, positions, velocities):
        rows = []
        for e in expectations:
            rows.append(Measurement(f"{e.point}: max distance from the point (rotating frame)", "r", 0.0,
                                    float(np.max(e.deviations(positions))), 1e-11, "absolute drift"))
            rows.append(Measurement(f"{e.point}: Jacobi constant", "", e.jacobi_constant,
                                    _jacobi_drift(e, positions, velocities), 1e-12, "relative drift"))
        return rows

    return ModelScene("lagrange_L4_L5", f"Test particles at the Earth-Moon L4 and L5 points (mu = {mu:.6g}) for "
                      f"{periods} periods: they stay put", problem, None, 1.0, {}, seconds, checks)


def _lagrange_unstable(mass_ratio=None, points=("L1", "L2", "L3"), offset=1e-10, outputs=600):
    """Test particles `offset` off unstable points along the growing mode, until 1e-4: the fitted e-folding
    rate against the eigenvalue of the linearised motion."""
    mu = _earth_moon_mass_ratio() if mass_ratio is None else float(mass_ratio)
    start = time.perf_counter()
    _, probes = lagrange_test_particles_problem(mu, [1.0], list(points), offset)
    horizon = max(np.log(1e-4 / offset) / p.growth_rate for p in probes)
    times = np.linspace(0.0, horizon, outputs + 1)[1:]
    problem, expectations = lagrange_test_particles_problem(mu, times, list(points), offset)
    seconds = time.perf_counter() - start

    def checks(times, positions, velocities):
        rows = []
        for e in expectations:
            try:
                rate = fitted_growth_rate(times, e.deviations(positions))
            except ValueError:
                rate = float("nan")  # too few samples in the fitting window: reported as a failure
            rows.append(Measurement(f"{e.point}: e-folding rate vs eigenvalue", "1 / time unit", e.growth_rate,
                                    rate, 0.03, "relative error"))
            rows.append(Measurement(f"{e.point}: Jacobi constant", "", e.jacobi_constant,
                                    _jacobi_drift(e, positions, velocities), 1e-12, "relative drift"))
        return rows

    label = "Earth-Moon" if mass_ratio is None else f"mu = {mu:g}"
    return ModelScene("lagrange_unstable" if mass_ratio is None else "lagrange_beyond_routh",
                      f"Test particles {offset:g} off the {label} {', '.join(points)} points along the growing mode: "
                      f"they depart at the rate of the linearised motion", problem, None, 1.0, {}, seconds, checks)


def _jacobi_drift(expectation, positions, velocities):
    c = expectation.jacobi_constants(positions, velocities)
    return float(np.max(np.abs(c - expectation.jacobi_constant)) / abs(expectation.jacobi_constant))


def _ring(n=5, outputs=400):
    """n equal masses on a circle (no central mass, unstable for n >= 3): round-off grows to a 1e-3 break-up
    at the time the linearised motion predicts."""
    start = time.perf_counter()
    _, probe = ring_problem(n, [1.0])
    times = np.linspace(0.0, 3.0 * probe.breakup_time, outputs + 1)[1:]
    problem, expected = ring_problem(n, times)
    seconds = time.perf_counter() - start

    def checks(times, positions, velocities):
        ratio = expected.measured_breakup_time(times, positions) / expected.breakup_time
        early = times <= expected.breakup_time / 3
        shape = float(np.max(expected.shape_deviations(positions[early])))
        return [
            Measurement("break-up time: |ln(measured / predicted)|", "", 0.0, float(abs(np.log(ratio))),
                        float(np.log(3.0)), "absolute drift"),
            Measurement("shape deviation before a third of the break-up time", "r", 0.0, shape, 1e-9, "absolute drift"),
        ]

    return ModelScene(f"ring_{n}", f"A ring of {n} equal masses (XXIII): round-off (1e-16) grows at the predicted "
                      f"rate {expected.growth_rate:.4g} / time unit to a 1e-3 break-up at t = "
                      f"{expected.breakup_time:.4g}", problem, None, 1.0, {}, seconds, checks)


def _ring_builder(n):
    def build(outputs=400):
        return _ring(n, outputs)

    return build


def _beyond_routh(outputs=600):
    """L4 and L5 of a mu = 0.1 pair, beyond Routh's ratio: unstable, departing at the eigenvalue rate."""
    return _lagrange_unstable(0.1, ("L4", "L5"), outputs=outputs)


MODELS = {
    "expanding_universe": _expanding_universe,
    "lagrange_L4_L5": _lagrange_stable,
    "lagrange_unstable": _lagrange_unstable,
    "lagrange_beyond_routh": _beyond_routh,
    **{f"ring_{n}": _ring_builder(n) for n in range(3, 9)},
}


def builtin_names() -> list[str]:
    """Names of the registered model scenes."""
    return sorted(MODELS)


def build(name: str, parameters: dict[str, object] | None = None, source: str = "<scene>") -> ModelScene:
    """The model scene `name` built with `parameters` (SceneError naming the source if unknown or invalid)."""
    if name not in MODELS:
        raise SceneError(f"{source}: model: unknown model {name!r}; known: {', '.join(builtin_names())}")
    try:
        return MODELS[name](**(parameters or {}))
    except TypeError as err:
        raise SceneError(f"{source}: parameters: {err}") from None


def from_dict(data: dict, source: str = "<scene>") -> ModelScene:
    """The model scene a parsed scene file names with `model = "<name>"` and an optional `[parameters]` table."""
    return build(data["model"], data.get("parameters", {}), source=source)
