"""Cross-validation: every scene's prediction against rebound and heyoka, through one path for both scene kinds.

A scene (data or model) is turned into a Plan (orbits.validate.plan); each backend integrates the plan's
problem once, in code units, converted back in one place (CodeUnits.trajectory); the position residuals are
computed once per backend and feed both the positions check and the residual plot; every other check gathers
the backends' Measurements of one quantity into a Check. Only what the scene asks for is computed: the
integrators stop at the last time needed and output only at the times the checks use; test particles are
massless in both backends.
"""

import math
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np

from orbits.validate import backends
from orbits.validate import models as _models  # noqa: F401  (registers the planner of model scenes)
from orbits.validate import scenes as _scenes  # noqa: F401  (registers the planner of data scenes)
from orbits.validate.plan import CodeUnits, Measurement, plan

if TYPE_CHECKING:
    from orbits.validate.models import ModelScene
    from orbits.validate.scene import Scene

DEFAULT_SETTINGS = {
    "rebound": {"integrator": "ias15", "epsilon": 1e-9},
    "heyoka": {"tol": 1e-16, "high_accuracy": True},
}


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
    def passed(self) -> bool:
        return all(err <= self.tolerance for err in self.errors.values())

    def ulps(self, backend: str) -> float | None:
        """|error| in ulps of the analytic value, for scalar comparisons (None otherwise)."""
        if self.analytic is None or self.kind != "relative error":
            return None
        return abs(self.values[backend] - self.analytic) / np.spacing(abs(self.analytic))


@dataclass(frozen=True)
class SceneReport:
    """Checks, wall times (s), pinned settings, versions and time bookkeeping of one validated scene.

    Where positions are predicted: `residual_times` (the scene's units: s for a data scene, code units for a
    model scene), each backend's position error |dr| / length_scale there, the predicted positions `expected`
    and each backend's `positions` (K, N, 3) at those times, in the scene's units, for pictures, with a dense
    closed-form `outline` of one period (Plan.outline); `period` is the
    scene's own orbital period in the units of `residual_times` (None for open orbits); `in_code_units` says a
    model scene's lengths and times are G = 1 code units, not SI. The positions stay out of
    to_dict (they are the scene's to recompute); everything else is in it.
    """

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
    period: float | None = None
    in_code_units: bool = False
    expected: np.ndarray | None = None
    outline: np.ndarray | None = None
    positions: dict = field(default_factory=dict)  # backend -> (K, N, 3) positions at the residual times

    @property
    def passed(self) -> bool:
        return all(check.passed for check in self.checks)


@dataclass
class ValidationReport:
    """All scenes' reports; passed only if every check of every scene passed."""

    scenes: list = field(default_factory=list)

    @property
    def passed(self) -> bool:
        return all(scene.passed for scene in self.scenes)

    def __repr__(self):
        verdict = "passed" if self.passed else "FAILED"
        return f"ValidationReport({len(self.scenes)} scenes: {', '.join(s.name for s in self.scenes)}; {verdict})"

    def _repr_html_(self):
        from orbits._common.display import validation_html

        return validation_html(self)

    def to_dict(self) -> dict[str, object]:
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
        "time_unit": "code time unit sqrt(L**3 / GM), G = 1" if report.in_code_units else "s",
        "residual_times": report.residual_times.tolist(), "period": report.period,
        "residuals": {name: series.tolist() for name, series in report.residuals.items()},
    }


def validate_scene(
    scene: "Scene | ModelScene",
    backend_names: Sequence[str] = ("rebound", "heyoka"),
    settings: dict[str, dict[str, object]] | None = None,
) -> SceneReport:
    """SceneReport comparing the predictions of `scene` (a data Scene or a ModelScene) with each named backend."""
    settings = {**DEFAULT_SETTINGS, **(settings or {})}
    the_plan = plan(scene)
    results, failures = {}, {}
    for name in backend_names:
        try:
            results[name] = backends.integrate(name, the_plan.problem, **settings[name])
        except (RuntimeError, FloatingPointError, OverflowError, MemoryError) as err:  # a run that blew up
            failures[name] = f"{type(err).__name__}: {err}".splitlines()[0]
    trajectories = {name: the_plan.code_units.trajectory(result) for name, result in results.items()}
    checks = [_failed_run(name, reason, backend_names) for name, reason in failures.items()]
    residuals, positions = {}, {}
    if the_plan.expected is not None and trajectories:
        positions = {name: the_plan.positions_at_residual_times(t) for name, t in trajectories.items()}
        residuals = {name: the_plan.residuals(p) for name, p in positions.items()}
        errors = {name: float(np.max(series)) for name, series in residuals.items()}
        checks.append(Check("positions |dr|/r_max", "", None, errors, errors, the_plan.positions_tolerance,
                            "relative error"))
    if trajectories:
        checks.extend(_gather({name: the_plan.measure(t) for name, t in trajectories.items()}))
    if the_plan.agreement_tolerance is not None and len(trajectories) >= 2:
        checks.append(_agreement(trajectories, the_plan.agreement_tolerance))
    return SceneReport(
        name=the_plan.name, description=the_plan.description, checks=checks,
        wall_times={"analytic": the_plan.predict_seconds, **{n: r.wall_time for n, r in results.items()},
                    **{n: math.nan for n in failures}},
        setup_times={n: r.setup_time for n, r in results.items()},
        settings={**{n: r.settings for n, r in results.items()}, **{n: settings[n] for n in failures}},
        versions={**{n: r.version for n, r in results.items()}, **{n: "-" for n in failures}},
        time_modes={**{n: r.time_mode for n, r in results.items()}, **{n: f"failed: {failures[n]}" for n in failures}},
        code_units=the_plan.code_units,
        residual_times=the_plan.residual_times if residuals else np.zeros(0),
        residuals=residuals, period=the_plan.period, in_code_units=the_plan.in_code_units,
        expected=the_plan.expected if residuals else None, outline=the_plan.outline if residuals else None,
        positions=positions,
    )


def _failed_run(name: str, reason: str, backend_names: Sequence[str]) -> Check:
    """A failed check saying why backend `name` gave no trajectory (the other backends' columns read 0)."""
    errors = {n: (math.inf if n == name else 0.0) for n in backend_names}
    return Check(f"{name} integration failed: {reason}", "", None, errors, errors, 0.0, "absolute drift")


def _agreement(trajectories: dict, tolerance: float) -> Check:
    """The backends' mutual agreement: the largest |r_a - r_b| / |r_b| of any body at any output, between each
    backend and the first; each backend's column holds the same figure."""
    names = list(trajectories)
    first = trajectories[names[0]].positions
    worst = max(float(np.max(np.linalg.norm(trajectories[n].positions - first, axis=-1)
                             / np.linalg.norm(first, axis=-1))) for n in names[1:])
    errors = {n: worst for n in names}
    return Check(f"mutual agreement of {' and '.join(names)}: max |dr| / r", "", None, errors, errors, tolerance,
                 "relative drift")


def _gather(per_backend: dict[str, list[Measurement]]) -> list[Check]:
    """One Check per measured quantity, from each backend's Measurements (listed in the same order)."""
    checks = []
    for k, first in enumerate(next(iter(per_backend.values()), [])):
        rows = {name: measurements[k] for name, measurements in per_backend.items()}
        checks.append(Check(first.quantity, first.unit, first.predicted, {n: m.measured for n, m in rows.items()},
                            {n: m.error for n, m in rows.items()}, first.tolerance, first.kind))
    return checks


def validate(
    scenes: "Iterable[Scene | ModelScene]",
    backend_names: Sequence[str] = ("rebound", "heyoka"),
    settings: dict[str, dict[str, object]] | None = None,
    progress: Callable[[str], object] | None = None,
) -> ValidationReport:
    """ValidationReport over scenes of either kind; `progress(scene_name)` is called before each."""
    report = ValidationReport()
    for scene in scenes:
        if progress:
            progress(scene.name)
        report.scenes.append(validate_scene(scene, backend_names, settings))
    return report
