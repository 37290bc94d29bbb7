"""Scenes for `orbits validate`: the one loader for both kinds, and the plan of a data scene.

`load` reads a scene once: a model name (orbits.validate.models), a built-in data scene name, or a .toml/.json
file, which is a model scene when it names a `model` and a data scene otherwise (orbits.validate.scene). The plan of a
data scene predicts it analytically (orbits.validate.predict), poses it to the integrators in code units (G = 1, length
unit L = the largest initial separation, GM unit = the total GM, time unit sqrt(L**3 / GM)) at the scene's
output times plus the instants a check needs (t = T for a period, the periapsis time for a closest approach),
and measures what the scene asks for on each backend's trajectory.
"""

import difflib
import os
import time
from pathlib import Path

import numpy as np

from orbits.core.errors import SceneError
from orbits.validate import models, predict
from orbits.validate import periodic as _periodic  # noqa: F401  (registers the periodic-orbit model scenes)
from orbits.validate import perturb as _perturbed  # noqa: F401  (registers the perturbed-orbit model scenes)
from orbits.validate import scene as data_scenes
from orbits.validate.nbody import NBodyProblem
from orbits.validate.plan import CodeUnits, Measurement, Plan, Trajectory, plan
from orbits.validate.scene import Scene


def builtin_names() -> list[str]:
    """Names of every built-in scene, data scenes first, in the order `orbits validate` runs them."""
    return data_scenes.builtin_names() + models.builtin_names()


def summaries() -> dict[str, str]:
    """{name: one line} of every built-in scene, in the order `orbits validate` runs them: a data scene's
    description, a model scene's builder's first sentence (nothing is integrated or built)."""
    lines = {name: str(data_scenes.read(name)[0].get("description", "")) for name in data_scenes.builtin_names()}
    return {**lines, **{name: models.summary(name) for name in models.builtin_names()}}


def unavailable_builtins() -> dict[str, str]:
    """{name: reason} of the built-in scenes this install cannot run (an optional extra missing)."""
    return {name: reason for name in models.builtin_names() if (reason := models.missing_extra(name))}


def load(name_or_path: str | os.PathLike[str]) -> "Scene | models.ModelScene":
    """A data Scene or a ModelScene from a built-in name or a .toml/.json file, read and parsed once."""
    if str(name_or_path) in models.MODELS:
        return models.build(str(name_or_path))
    known = builtin_names()
    if not str(name_or_path).strip():
        raise SceneError(f"{str(name_or_path)!r}: empty scene name; give a built-in scene ({', '.join(known)}) "
                         f"or a .toml / .json file")
    if _looks_like_a_name(name_or_path) and str(name_or_path) not in known:
        close = difflib.get_close_matches(str(name_or_path), known, n=1)
        hint = f" (did you mean {close[0]!r}?)" if close else ""
        raise SceneError(f"{name_or_path}: no such scene file, and not a built-in scene{hint}; built-in scenes: "
                         f"{', '.join(known)}")
    data, source = data_scenes.read(name_or_path)
    if "model" in data:
        return models.from_dict(data, source)
    return data_scenes.from_dict(data, source)


def _looks_like_a_name(name_or_path: str | os.PathLike[str]) -> bool:
    """True for a bare word (no suffix, no folder) that names no existing file: meant as a built-in scene."""
    text = str(name_or_path)
    path = Path(text)
    return not path.suffix and path.name == text and not path.exists()


def code_units(scene: Scene) -> CodeUnits:
    """L = largest distance between two bodies at t = 0; GM unit = total GM of the massive bodies."""
    r = scene.positions
    separations = np.linalg.norm(r[:, None, :] - r[None, :, :], axis=-1)
    return CodeUnits(float(separations.max()), float(scene.gm.sum()))


def _merge_times(times, extra, time_unit):
    """Sorted union of the output times (s), dropping instants that coincide once scaled to code units."""
    grid = np.unique(np.concatenate([times, extra]))
    scaled = grid / time_unit
    return grid[np.concatenate([[True], np.diff(scaled) > 0])]


def _nearest(grid, times):
    """Indices of the grid times nearest to each of `times` (the merged grid may hold a time only to an ulp).

    Both are sorted, so a binary search and a look at the two neighbours suffice: O(K log K).
    """
    times = np.atleast_1d(np.asarray(times, dtype=float))
    if len(grid) == 1:
        return np.zeros(times.shape, dtype=int)
    right = np.clip(np.searchsorted(grid, times), 1, len(grid) - 1)
    left = right - 1
    return np.where(np.abs(grid[left] - times) <= np.abs(grid[right] - times), left, right)


@plan.register
def _plan_data_scene(scene: Scene) -> Plan:
    """The Plan of a data scene: closed-form prediction, merged output grid, and its measurements."""
    prediction = predict.predict(scene)
    start = time.perf_counter()
    extra = {f"period[{i}]": t for i, t in prediction.periods.items()}
    extra.update({f"closest[{i}]": tp for i, (_, tp) in prediction.closest_approaches.items()})
    units = code_units(scene)
    grid = _merge_times(scene.times, list(extra.values()), units.time)
    at_scene = _nearest(grid, scene.times)
    at_extra = {label: int(_nearest(grid, t)[0]) for label, t in extra.items()}
    analytic_invariants = None
    if "conserved" in scene.asks and predict.has_closed_form(scene):
        analytic_invariants = predict.invariants(scene, *predict.two_body_states(scene, scene.times))
    predict_seconds = prediction.wall_time + time.perf_counter() - start

    def measure(trajectory: Trajectory) -> list[Measurement]:
        return _measure(scene, prediction, trajectory, at_scene, at_extra, analytic_invariants)

    has_positions = prediction.positions is not None
    period = _first_period(scene)
    return Plan(
        name=scene.name, description=scene.description, problem=_problem(scene, units, grid), code_units=units,
        predict_seconds=predict_seconds, residual_times=scene.times, expected=prediction.positions, measure=measure,
        positions_tolerance=scene.tolerance["positions"],
        length_scale=predict.length_scale(scene, prediction.positions) if has_positions else 1.0,
        outputs=at_scene, period=period, outline=_outline(scene, period) if has_positions else None,
    )


#: samples of the drawn closed form (Plan.outline)
OUTLINE_POINTS = 721


def _outline(scene: Scene, period: float | None) -> np.ndarray:
    """Closed-form (M, N, 3) positions (m): the curve a picture draws the integrated positions on.

    Over one period of the first orbit from a periapsis passage, at evenly spaced eccentric anomalies E (t = t_p +
    (E - e sin E) T / 2 pi), so an e = 0.9 ellipse is as well drawn at periapsis as at apoapsis; a run shorter
    than a period, or of an open orbit, evenly in time over the run."""
    if period is None or scene.times[-1] < period:
        return predict.two_body_states(scene, np.linspace(0.0, scene.times[-1], OUTLINE_POINTS))[0]
    first = scene.orbiting[0]
    e = scene.bodies[first].orbit.e
    periapsis_time = predict.periapsis_time(scene, first)
    anomaly = np.linspace(0.0, 2 * np.pi, OUTLINE_POINTS)
    return predict.two_body_states(scene, periapsis_time + (anomaly - e * np.sin(anomaly)) * period / (2 * np.pi))[0]


def _first_period(scene: Scene) -> float | None:
    """T (s) of the scene's first orbiting body when it is an ellipse (what `periods` counts), else None."""
    first = next(iter(scene.orbiting), None)
    if first is None or scene.bodies[first].orbit.e >= 1:
        return None
    return predict.period_of(scene, first)


def _problem(scene, units, times):
    """The scene as an NBodyProblem in code units, with output times `times` (s)."""
    return NBodyProblem(
        gm=scene.gm / units.gm,
        positions=scene.positions / units.length,
        velocities=scene.velocities / units.speed,
        n_active=scene.n_active,
        times=np.asarray(times) / units.time,
    )


def _measure(scene, prediction, trajectory, at_scene, at_extra, analytic_invariants):
    """Periods, closest approaches and conservation drifts measured on one trajectory, in a fixed order."""
    t, r, v = trajectory.times, trajectory.positions, trajectory.velocities
    tol = scene.tolerance
    rows = []
    for i, period in prediction.periods.items():
        k = at_extra[f"period[{i}]"]
        rows.append(Measurement(f"period[{scene.bodies[i].name}]", "s", period,
                                predict.measured_period(scene, i, t[k], r[k], v[k]), tol["period"], "relative error"))
    for i, (q, _) in prediction.closest_approaches.items():
        k = at_extra[f"closest[{i}]"]
        rows.append(Measurement(f"closest_approach[{scene.bodies[i].name}]", "m", q,
                                predict.measured_closest_approach(scene, i, r[k], v[k]), tol["closest_approach"],
                                "relative error"))
    if "conserved" in scene.asks:
        for name, (series, scale) in predict.invariants(scene, r[at_scene], v[at_scene]).items():
            family = name.split("[")[0]
            kind = "absolute drift" if family == "lrl" else "relative drift"
            analytic = None
            if analytic_invariants is not None and name in analytic_invariants:
                analytic = predict.drift(*analytic_invariants[name])
            rows.append(Measurement(f"{name} drift", "", analytic, predict.drift(series, scale), tol[family], kind))
    return rows
