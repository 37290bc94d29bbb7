"""Cross-validation: predict a scene analytically, integrate it with rebound and heyoka, compare.

Every integration runs in scaled code units (G = 1, length unit L = the scene's largest initial
separation, GM unit = the total GM, time unit sqrt(L**3 / GM)), converted in one place (CodeUnits).
Only what the scene asks for is computed: the integrators stop at the last time needed and output
only at the scene's times plus the instants a check needs (t = T for a period, the periapsis time for a
closest approach); test particles are massless in both backends.
"""

import time
from dataclasses import dataclass, field

import numpy as np

from orbits import predict
from orbits.validate import backends
from orbits.validate.problem import NBodyProblem

DEFAULT_SETTINGS = {
    "rebound": {"integrator": "ias15", "epsilon": 1e-9},
    "heyoka": {"tol": 1e-16, "high_accuracy": True},
}


@dataclass(frozen=True)
class CodeUnits:
    """Scale factors from SI to G = 1 code units: length (m), GM (m3/s2), time (s) and speed (m/s)."""

    length: float
    gm: float

    @classmethod
    def for_scene(cls, scene):
        """L = largest distance between two bodies at t = 0; GM unit = total GM of the massive bodies."""
        r = scene.positions
        separations = np.linalg.norm(r[:, None, :] - r[None, :, :], axis=-1)
        return cls(float(separations.max()), float(scene.gm.sum()))

    @property
    def time(self):
        return float(np.sqrt(self.length**3 / self.gm))

    @property
    def speed(self):
        return self.length / self.time

    def problem(self, scene, times):
        """The scene as an NBodyProblem in code units, with output times `times` (s)."""
        return NBodyProblem(
            gm=scene.gm / self.gm,
            positions=scene.positions / self.length,
            velocities=scene.velocities / self.speed,
            n_active=scene.n_active,
            times=np.asarray(times) / self.time,
        )

    def states(self, result):
        """(times s, positions m, velocities m/s) of an NBodyResult."""
        return result.times * self.time, result.positions * self.length, result.velocities * self.speed


@dataclass(frozen=True)
class Check:
    """One compared quantity: the analytic value (or None for drifts), each backend's value and error."""

    quantity: str
    unit: str
    analytic: float | None
    values: dict
    errors: dict
    tolerance: float
    kind: str  # "relative error", "relative drift" or "absolute drift"

    @property
    def passed(self):
        return all(err <= self.tolerance for err in self.errors.values())

    def ulps(self, backend):
        """|error| in ulps of the analytic value, for scalar comparisons (None otherwise)."""
        if self.analytic is None or self.kind != "relative error":
            return None
        return abs(self.values[backend] - self.analytic) / np.spacing(abs(self.analytic))


@dataclass(frozen=True)
class SceneReport:
    """Checks, wall times (s), pinned settings, versions and time bookkeeping of one validated scene."""

    name: str
    description: str
    checks: list
    wall_times: dict
    setup_times: dict
    settings: dict
    versions: dict
    time_modes: dict
    code_units: CodeUnits
    residual_times: np.ndarray = field(default_factory=lambda: np.zeros(0))
    residuals: dict = field(default_factory=dict)  # backend -> |dr| / r_max at each residual time

    @property
    def passed(self):
        return all(check.passed for check in self.checks)


@dataclass
class ValidationReport:
    """All scenes' reports; passed only if every check of every scene passed."""

    scenes: list = field(default_factory=list)

    @property
    def passed(self):
        return all(scene.passed for scene in self.scenes)

    def __repr__(self):
        verdict = "passed" if self.passed else "FAILED"
        return f"ValidationReport({len(self.scenes)} scenes: {', '.join(s.name for s in self.scenes)}; {verdict})"

    def _repr_html_(self):
        from orbits.display import validation_html

        return validation_html(self)

    def to_dict(self):
        """JSON-ready dictionary of the whole report."""
        return {"passed": self.passed, "scenes": [_scene_dict(s) for s in self.scenes]}


def _scene_dict(report):
    checks = []
    for c in report.checks:
        checks.append({
            "quantity": c.quantity, "unit": c.unit, "kind": c.kind, "analytic": c.analytic, "values": c.values,
            "errors": c.errors, "ulps": {b: c.ulps(b) for b in c.values}, "tolerance": c.tolerance,
            "passed": c.passed,
        })
    return {
        "name": report.name, "description": report.description, "passed": report.passed, "checks": checks,
        "wall_time_s": report.wall_times, "setup_time_s": report.setup_times, "settings": report.settings,
        "versions": report.versions, "time_modes": report.time_modes,
        "code_units": {"length_m": report.code_units.length, "gm_m3_s2": report.code_units.gm,
                       "time_s": report.code_units.time},
        "residual_times_s": report.residual_times.tolist(),
        "residuals": {name: series.tolist() for name, series in report.residuals.items()},
    }


def _extra_times(scene, prediction):
    """Instants a check needs besides the scene's output times: {label: t (s)}."""
    extra = {f"period[{i}]": t for i, t in prediction.periods.items()}
    extra.update({f"closest[{i}]": tp for i, (_, tp) in prediction.closest_approaches.items()})
    return extra


def _merge_times(times, extra, time_unit):
    """Sorted union of the output times (s), dropping instants that coincide once scaled to code units."""
    grid = np.unique(np.concatenate([times, extra]))
    scaled = grid / time_unit
    return grid[np.concatenate([[True], np.diff(scaled) > 0])]


def _nearest(grid, t):
    """Index of the grid time nearest to t (the merged grid may hold t only to within an ulp)."""
    return int(np.argmin(np.abs(grid - t)))


def validate_scene(scene, backend_names=("rebound", "heyoka"), settings=None):
    """SceneReport comparing the analytic prediction of `scene` with each named backend."""
    settings = {**DEFAULT_SETTINGS, **(settings or {})}
    prediction = predict.predict(scene)
    extra = _extra_times(scene, prediction)
    units = CodeUnits.for_scene(scene)
    grid = _merge_times(scene.times, list(extra.values()), units.time)
    analytic_inv = None
    if "conserved" in scene.asks and predict.has_closed_form(scene):
        start = time.perf_counter()
        analytic_inv = predict.invariants(scene, *predict.two_body_states(scene, scene.times))
        prediction_time = prediction.wall_time + time.perf_counter() - start
    else:
        prediction_time = prediction.wall_time
    runs = {}
    for name in backend_names:
        result = backends.integrate(name, units.problem(scene, grid), **settings[name])
        runs[name] = (result, *units.states(result))
    checks = _compare(scene, prediction, grid, extra, runs, analytic_inv)
    residuals = _residuals(scene, prediction, grid, runs)
    return SceneReport(
        name=scene.name, description=scene.description, checks=checks,
        wall_times={"analytic": prediction_time, **{n: r[0].wall_time for n, r in runs.items()}},
        setup_times={n: r[0].setup_time for n, r in runs.items()},
        settings={n: r[0].settings for n, r in runs.items()},
        versions={n: r[0].version for n, r in runs.items()},
        time_modes={n: r[0].time_mode for n, r in runs.items()},
        code_units=units,
        residual_times=scene.times if residuals else np.zeros(0),
        residuals=residuals,
    )


def _residuals(scene, prediction, grid, runs):
    """{backend: (K,) max over bodies of |dr| / r_max at each output time} when positions were asked."""
    if prediction.positions is None:
        return {}
    at_scene = np.array([_nearest(grid, t) for t in scene.times])
    scale = predict.length_scale(scene, prediction.positions)
    return {n: np.max(np.linalg.norm(r[2][at_scene] - prediction.positions, axis=-1), axis=-1) / scale
            for n, r in runs.items()}


def _compare(scene, prediction, grid, extra, runs, analytic_inv):
    tol = scene.tolerance
    at_scene = np.array([_nearest(grid, t) for t in scene.times])
    checks = []
    if prediction.positions is not None:
        errors = {n: float(np.max(series)) for n, series in _residuals(scene, prediction, grid, runs).items()}
        label = "positions |dr|/r_max"
        checks.append(Check(label, "", None, errors, errors, tol["positions"], "relative error"))
    for i, period in prediction.periods.items():
        k = _nearest(grid, extra[f"period[{i}]"])
        values = {n: predict.measured_period(scene, i, r[1][k], r[2][k], r[3][k]) for n, r in runs.items()}
        checks.append(_scalar(f"period[{scene.bodies[i].name}]", "s", period, values, tol["period"]))
    for i, (q, tp) in prediction.closest_approaches.items():
        k = _nearest(grid, tp)
        values = {n: predict.measured_closest_approach(scene, i, r[2][k], r[3][k]) for n, r in runs.items()}
        checks.append(_scalar(f"closest_approach[{scene.bodies[i].name}]", "m", q, values, tol["closest_approach"]))
    if "conserved" in scene.asks:
        checks.extend(_conservation(scene, at_scene, runs, analytic_inv))
    return checks


def _scalar(quantity, unit, analytic, values, tolerance):
    errors = {n: abs(v - analytic) / abs(analytic) for n, v in values.items()}
    return Check(quantity, unit, analytic, values, errors, tolerance, "relative error")


def _conservation(scene, at_scene, runs, analytic_inv):
    per_backend = {n: predict.invariants(scene, r[2][at_scene], r[3][at_scene]) for n, r in runs.items()}
    checks = []
    for name in next(iter(per_backend.values())):
        family = name.split("[")[0]
        kind = "absolute drift" if family == "lrl" else "relative drift"
        drifts = {n: predict.drift(*inv[name]) for n, inv in per_backend.items()}
        analytic = None if analytic_inv is None or name not in analytic_inv else predict.drift(*analytic_inv[name])
        checks.append(Check(f"{name} drift", "", analytic, drifts, drifts, scene.tolerance[family], kind))
    return checks


def validate_model_scene(model, backend_names=("rebound", "heyoka"), settings=None):
    """SceneReport comparing a ModelScene's predictions with each named backend (all in code units)."""
    settings = {**DEFAULT_SETTINGS, **(settings or {})}
    runs = {name: backends.integrate(name, model.problem, **settings[name]) for name in backend_names}
    checks, residuals = [], {}
    if model.expected is not None:
        residuals = {n: np.max(np.linalg.norm(r.positions - model.expected, axis=-1), axis=-1) / model.length
                     for n, r in runs.items()}
        errors = {n: float(np.max(series)) for n, series in residuals.items()}
        checks.append(Check("positions |dr|/r_max", "", None, errors, errors, model.tolerance["positions"],
                            "relative error"))
    if model.checks is not None:
        checks.extend(_model_checks(model, runs))
    return SceneReport(
        name=model.name, description=model.description, checks=checks,
        wall_times={"analytic": model.predict_seconds, **{n: r.wall_time for n, r in runs.items()}},
        setup_times={n: r.setup_time for n, r in runs.items()},
        settings={n: r.settings for n, r in runs.items()},
        versions={n: r.version for n, r in runs.items()},
        time_modes={n: r.time_mode for n, r in runs.items()},
        code_units=CodeUnits(1.0, 1.0),
        residual_times=model.problem.times if residuals else np.zeros(0),
        residuals=residuals,
    )


def _model_checks(model, runs):
    """One Check per model-specific quantity, gathering every backend's measurement of it."""
    per_backend = {n: model.checks(r.times, r.positions, r.velocities) for n, r in runs.items()}
    checks = []
    for k, (quantity, unit, predicted, _, tolerance, kind) in enumerate(next(iter(per_backend.values()))):
        values = {n: rows[k][3] for n, rows in per_backend.items()}
        if kind == "relative error":
            errors = {n: abs(v - predicted) / abs(predicted) for n, v in values.items()}
        else:
            errors = dict(values)
        checks.append(Check(quantity, unit, predicted, values, errors, tolerance, kind))
    return checks


def validate(scenes, backend_names=("rebound", "heyoka"), settings=None, progress=None):
    """ValidationReport over data scenes and model scenes; `progress(scene_name)` is called before each."""
    from orbits.validate.models import ModelScene

    report = ValidationReport()
    for scene in scenes:
        if progress:
            progress(scene.name)
        run = validate_model_scene if isinstance(scene, ModelScene) else validate_scene
        report.scenes.append(run(scene, backend_names, settings))
    return report
