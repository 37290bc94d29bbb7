"""What every scene hands to the validation run: one interface for data scenes and model scenes.

A scene of either kind is turned into a Plan by `plan(scene)`, a single-dispatch function: each kind registers
its own planner where it is defined (orbits.validate.scenes for data scenes, orbits.validate.models for model
scenes). The run then treats every plan alike: integrate `problem` with each backend, convert the states back
with `code_units`, compute the position residuals once, and gather each backend's Measurements into Checks.
"""

import functools
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from orbits.validate.nbody import NBodyProblem, NBodyResult

#: how a check's error is formed from its measured value: |measured - predicted| / |predicted| ("relative error"),
#: or the measured value itself, which is already a drift from an initial value ("relative drift", "absolute drift")
KINDS = ("relative error", "relative drift", "absolute drift")


@dataclass(frozen=True)
class CodeUnits:
    """Scale factors from the scene's units to G = 1 code units: length (m), GM (m3/s2), time (s), speed (m/s)."""

    length: float
    gm: float

    @property
    def time(self) -> float:
        """Time unit sqrt(length**3 / gm) (s)."""
        return float(np.sqrt(self.length**3 / self.gm))

    @property
    def speed(self) -> float:
        """Speed unit length / time (m/s)."""
        return self.length / self.time

    def trajectory(self, result: NBodyResult) -> "Trajectory":
        """The states of an NBodyResult in the scene's units."""
        return Trajectory(result.times * self.time, result.positions * self.length, result.velocities * self.speed)


#: model scenes are posed in code units already
CODE = CodeUnits(1.0, 1.0)


@dataclass(frozen=True, eq=False)
class Trajectory:
    """States from one backend in the scene's units: times (K,), positions and velocities (K, N, 3)."""

    times: np.ndarray
    positions: np.ndarray
    velocities: np.ndarray


@dataclass(frozen=True)
class Measurement:
    """One quantity measured on one backend's trajectory, with its prediction and how it is judged.

    `predicted` is the analytic value (a "relative error" check) or the drift of the closed-form states (None if
    the scene has none); `measured` is the backend's value, or its drift for the two drift kinds.
    """

    quantity: str
    unit: str
    predicted: float | None
    measured: float
    tolerance: float
    kind: str

    def __post_init__(self) -> None:
        if self.kind not in KINDS:
            raise ValueError(f"kind = {self.kind!r}; allowed: {', '.join(KINDS)}")

    @property
    def error(self) -> float:
        """|measured - predicted| / |predicted| for a relative error; the measured drift otherwise."""
        if self.kind == "relative error":
            return abs(self.measured - self.predicted) / abs(self.predicted)
        return self.measured


@dataclass(frozen=True, eq=False)
class Plan:
    """Everything the run needs to validate one scene.

    `problem` is posed in code units. When positions are predicted, `expected` holds them (K, N, 3) at
    `residual_times`, in the scene's units (those of CodeUnits.trajectory), `outputs` the indices of those times
    among the problem's outputs (None: all of them), and position errors are quoted relative to `length_scale`.
    `measure(trajectory)` gives the scene's other Measurements, in the same order for every backend;
    `agreement_tolerance` asks for the backends' mutual agreement to be checked too. `period` is the scene's own
    orbital period in the units of `residual_times` (None for a scene of open orbits): pictures count time in it.
    """

    name: str
    description: str
    problem: NBodyProblem
    code_units: CodeUnits
    predict_seconds: float
    residual_times: np.ndarray
    expected: np.ndarray | None
    measure: Callable[[Trajectory], list[Measurement]]
    positions_tolerance: float
    length_scale: float = 1.0
    outputs: np.ndarray | None = None
    period: float | None = None
    #: predicted (M, N, 3) positions densely over one period of the first orbit (or the whole run, if shorter or
    #: open), in the scene's units, to draw the closed form as a curve (None: `expected` is dense enough)
    outline: np.ndarray | None = None
    #: True when the scene is posed in code units already (model scenes): its lengths and times carry no SI unit
    in_code_units: bool = False
    #: when set, the backends' trajectories are also compared with each other: the largest |r_a - r_b| / |r_b|
    #: of any body at any output must stay below it
    agreement_tolerance: float | None = None

    def positions_at_residual_times(self, trajectory: Trajectory) -> np.ndarray:
        """A backend's (K, N, 3) positions at `residual_times`, in the scene's units."""
        return trajectory.positions if self.outputs is None else trajectory.positions[self.outputs]

    def residuals(self, positions: np.ndarray) -> np.ndarray:
        """(K,) position error max_bodies |r - r_expected| / length_scale of positions at `residual_times`."""
        return np.max(np.linalg.norm(positions - self.expected, axis=-1), axis=-1) / self.length_scale


@functools.singledispatch
def plan(scene: object) -> Plan:
    """The Plan of a scene; each scene kind registers its planner with `@plan.register`."""
    raise TypeError(
        f"cannot validate a {type(scene).__name__}: pass a scene from orbits.validate.scenes.load "
        f"(a data scene or a model scene)"
    )
