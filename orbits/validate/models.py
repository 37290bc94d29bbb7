"""Model scenes: validation problems built by the domain models (no two-body closed form needed).

A model scene is an NBodyProblem in code units plus what the model predicts: positions at the output
times and, optionally, model-specific checks (a measured quantity against its prediction). The builders
live with the models (e.g. orbits.cosmology.expanding_sphere_problem); this module registers them under
scene names, so `orbits validate` runs them beside the data scenes of orbits/scenes/, and a TOML/JSON file
can ask for one with `model = "<name>"` and a `[parameters]` table passed to the builder.
"""

import json
import time
import tomllib
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from orbits import scene as data_scenes
from orbits.scene import SceneError


@dataclass(frozen=True, eq=False)
class ModelScene:
    """A validation problem in code units with the model's predictions.

    `expected` holds (K, N, 3) positions at problem.times (or None); position errors are quoted relative to
    `length`. `checks(times, positions, velocities)` returns extra Check-like tuples
    (quantity, unit, predicted, measured, tolerance, kind) for each backend's trajectory.
    """

    name: str
    description: str
    problem: object
    expected: np.ndarray | None
    length: float
    tolerance: dict
    predict_seconds: float = 0.0
    checks: object = None


def _expanding_universe(n_shells=8, duration=20.0, outputs=40):
    """The notes' sphere of test shells (XXIV) expanding at the zero-energy speed about a unit mass."""
    from orbits.cosmology import expanding_sphere_problem

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
            ("Hubble parameter: max |(v/r) / (2/(3t)) - 1|", "", 0.0, float(hubble), 1e-12, "relative deviation"),
            ("shell energy v**2/2 - GM/r (zero)", "", 0.0, float(energy), 1e-12, "relative deviation"),
        ]

    return checks


MODELS = {"expanding_universe": _expanding_universe}


def builtin_names():
    """Names of the registered model scenes."""
    return sorted(MODELS)


def build(name, parameters=None, source="<scene>"):
    """The model scene `name` built with `parameters` (SceneError naming the source if unknown or invalid)."""
    if name not in MODELS:
        raise SceneError(f"{source}: model: unknown model {name!r}; known: {', '.join(builtin_names())}")
    try:
        return MODELS[name](**(parameters or {}))
    except TypeError as err:
        raise SceneError(f"{source}: parameters: {err}") from None


def load_any(name_or_path):
    """A data Scene or a ModelScene from a built-in name or a .toml/.json file (which may name a model)."""
    if str(name_or_path) in MODELS:
        return build(str(name_or_path))
    path = Path(name_or_path)
    if path.suffix in (".toml", ".json") and path.exists():
        text = path.read_text()
        try:
            data = json.loads(text) if path.suffix == ".json" else tomllib.loads(text)
        except (json.JSONDecodeError, tomllib.TOMLDecodeError) as err:
            raise SceneError(f"{path}: not valid {path.suffix[1:].upper()}: {err}") from None
        if "model" in data:
            return build(data["model"], data.get("parameters", {}), source=str(path))
    return data_scenes.load(name_or_path)
