"""Model scenes: validation problems built from the models' closed forms (no two-body closed form needed).

A model scene is an NBodyProblem in code units plus what the model predicts: positions at the output
times and, optionally, model-specific Measurements (a measured quantity against its prediction). The
problems are built in orbits.validate.builders; this module registers them under scene names, so
`orbits validate` runs them beside the data scenes of orbits/validate/scene_files/, and a TOML/JSON file can ask for one
with `model = "<name>"` and a `[parameters]` table passed to the builder. Every parameter is checked against
PARAMETER_RULES (type and range, with upper bounds that keep a run bounded) before the builder runs.
"""

import difflib
import importlib.util
import inspect
import math
import time
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from orbits.core.errors import OrbitsError, ParameterError, SceneError
from orbits.core.threebody import lagrange
from orbits.validate.builders import (
    POINTS,
    expanding_sphere_problem,
    fitted_growth_rate,
    lagrange_test_particles_problem,
    mercury_gr_advance,
    ring_problem,
    solar_system_problem,
)
from orbits.validate.nbody import NBodyProblem, check_states
from orbits.validate.plan import CODE, CodeUnits, Measurement, Plan, Trajectory, plan
from orbits.validate.scene import MODEL_KEYS, show, unknown_keys


@dataclass(frozen=True, eq=False)
class ModelScene:
    """A validation problem in code units with the model's predictions.

    `expected` holds (K, N, 3) positions at problem.times (or None); position errors are quoted relative to
    `length`; `period` is the period of the scene's motion in code time units (None when nothing orbits).
    `checks(times, positions, velocities)` returns the model's Measurements on one backend's trajectory.
    """

    name: str
    description: str
    problem: NBodyProblem
    expected: np.ndarray | None
    length: float
    tolerance: dict
    predict_seconds: float = 0.0
    checks: Callable[[np.ndarray, np.ndarray, np.ndarray], list[Measurement]] | None = None
    code_units: CodeUnits = CODE
    #: the orbital period of the scene's motion in code time units (None when nothing orbits)
    period: float | None = None


@plan.register
def _plan_model_scene(model: ModelScene) -> Plan:
    """The Plan of a model scene: its problem as built, residuals against `expected`, its own measurements."""
    def measure(trajectory: Trajectory) -> list[Measurement]:
        if model.checks is None:
            return []
        return model.checks(trajectory.times, trajectory.positions, trajectory.velocities)

    return Plan(
        name=model.name, description=model.description, problem=model.problem, code_units=model.code_units,
        predict_seconds=model.predict_seconds, residual_times=model.problem.times, expected=model.expected,
        measure=measure, positions_tolerance=model.tolerance.get("positions", 0.0), length_scale=model.length,
        period=model.period, in_code_units=model.code_units == CODE,
        agreement_tolerance=model.tolerance.get("agreement"),
    )


def _expanding_universe(n_shells=8, duration=20.0, outputs=40):
    """The notes' sphere of test shells (XXIV) expanding at the zero-energy speed about a unit mass."""
    try:
        check_states(outputs, n_shells + 1)
    except OrbitsError as err:
        raise ParameterError(None, f"{err}, or lower n_shells") from None
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
    from orbits._common.constants import BODIES

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
                      f"{periods} periods: they stay put", problem, None, 1.0, {}, seconds, checks,
                      period=2 * np.pi)


def _lagrange_unstable(mass_ratio=None, points=("L1", "L2", "L3"), offset=1e-10, outputs=600):
    """Test particles `offset` off unstable points along the growing mode, until 1e-4: the fitted e-folding
    rate against the eigenvalue of the linearised motion."""
    mu = _earth_moon_mass_ratio() if mass_ratio is None else float(mass_ratio)
    rates = dict(zip(POINTS, lagrange.growth_rates(mu), strict=True))
    stable = [p for p in points if not rates[p] > 0.0]
    if stable:
        unstable = [p for p in POINTS if rates[p] > 0.0]
        raise ParameterError("points", f"{stable[0]!r} is linearly stable at mu = {mu:.6g} and would not depart; "
                             f"the unstable points there are {', '.join(unstable)}")
    slowest = min(points, key=rates.get)
    horizon = math.log(MAX_OFFSET / offset) / rates[slowest]
    if not horizon <= MAX_HORIZON:
        raise ParameterError(None, f"{slowest} departs at {rates[slowest]:.4g} / time unit at mu = {mu:.6g}: growing "
                             f"from offset = {offset:g} to {MAX_OFFSET:g} takes t = {horizon:.4g} time units, more "
                             f"than {MAX_HORIZON:.4g} ({MAX_PERIODS} binary periods); raise offset or mass_ratio")
    start = time.perf_counter()
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
                      f"they depart at the rate of the linearised motion", problem, None, 1.0, {}, seconds, checks,
                      period=2 * np.pi)


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
                      f"{expected.breakup_time:.4g}", problem, None, 1.0, {}, seconds, checks, period=2 * np.pi)


def _ring_builder(n):
    def build(outputs=400):
        return _ring(n, outputs)

    build.__doc__ = (f"A ring of {n} equal masses on one circle, perturbed by float64 round-off: it breaks up at the "
                     f"rate of its fastest unstable mode.")
    return build


def _beyond_routh(outputs=600):
    """L4 and L5 of a mu = 0.1 pair, beyond Routh's ratio: unstable, departing at the eigenvalue rate."""
    return _lagrange_unstable(0.1, ("L4", "L5"), outputs=outputs)


# Largest distance (km) from DE421 over 10 years of monthly outputs, measured with both integrators (they agree
# to 4.5e-12) from 2000-01-01 12:00 and 1950-01-01 TDB: planets heliocentric, the Moon geocentric, the Sun about
# the barycentre. With the Sun's 1PN term the floor is set by what the model leaves out: the asteroids (DE421
# carries 343 of them; Mars 4.6-5.8 km, the Sun's barycentric wobble 3-3.6 km, and so every heliocentric outer
# planet), the Moon's and Earth's figures and tides (Moon 180-197 km), and for Jupiter the Galilean moons' system
# being a point (0.9-21 km). Without it, general relativity's absence dominates the inner planets (Mercury
# 1,820 km, Venus 915 km, Earth 612 km). Tolerances are 3x the larger of the two epochs, times (years / 10)**2
# beyond 10 years (the 30-year run from 2020 stays within them: Jupiter 53 km, Moon 595 km).
SOLAR_SYSTEM_FLOOR_KM = {
    True: {"Sun": 3.6, "Mercury": 1.2, "Venus": 0.39, "Earth": 3.3, "Moon": 197.0, "Mars": 5.8, "Jupiter": 20.7,
           "Saturn": 4.7, "Uranus": 3.6, "Neptune": 3.8, "Pluto": 4.1},
    False: {"Sun": 3.5, "Mercury": 1820.0, "Venus": 915.0, "Earth": 612.0, "Moon": 159.0, "Mars": 443.0,
            "Jupiter": 68.9, "Saturn": 18.2, "Uranus": 3.2, "Neptune": 3.6, "Pluto": 3.8},
}
#: Mercury's integrated perihelion against DE421's at the end (arcsec): 0.0026-0.0027 after 10 years, 0.008
#: after 30 with the 1PN term; without it the lag is GR's advance, measured 4.2982 against 4.298 in 10 years
PERIHELION_TOLERANCE_ARCSEC = 0.01
PERIHELION_LAG_TOLERANCE = 5e-4
#: the two integrators' largest relative difference of a body's position (measured 4.5e-12 from J2000)
SOLAR_SYSTEM_AGREEMENT = 1e-11


def _solar_system(epoch="2000-01-01 12:00", years=10.0, post_newtonian=True, outputs=120):
    """The Sun, planets, Earth and Moon from DE421 at `epoch` (TDB), integrated `years` against DE421."""
    from orbits.ephemeris import positions as ephemeris

    start = time.perf_counter()
    problem, expected, (length, gm) = solar_system_problem(epoch, years, post_newtonian, outputs)
    seconds = time.perf_counter() - start
    growth = max(1.0, (years / 10.0) ** 2)
    floors = SOLAR_SYSTEM_FLOOR_KM[post_newtonian]
    mu_mercury = ephemeris.DE430_GM["Sun"] + ephemeris.DE430_GM["Mercury"]
    per_century = mercury_gr_advance()
    advance = per_century * years / 100.0

    def checks(times, positions, velocities):
        miss = np.linalg.norm(expected.relative_positions(positions) - expected.relative, axis=-1).max(axis=0) / 1e3
        rows = [Measurement(f"{name}: max km from DE421 ({_reference(name)})", "km", 0.0, float(km),
                            3.0 * floors[name] * growth, "absolute drift") for name, km in zip(expected.names, miss)]
        lag = expected.perihelion_lag(positions, velocities, mu_mercury)
        if post_newtonian:
            rows.append(Measurement("Mercury perihelion: arcsec from DE421", "arcsec", 0.0, abs(lag),
                                    PERIHELION_TOLERANCE_ARCSEC * max(1.0, years / 10.0), "absolute drift"))
        else:
            rows.append(Measurement(f"Mercury perihelion lag behind DE421 vs GR ({per_century:.2f} arcsec/cy)",
                                    "arcsec", advance, lag, PERIHELION_LAG_TOLERANCE, "relative error"))
        return rows

    physics = "with the Sun's 1PN term (REBOUNDx gr)" if post_newtonian else "Newtonian point masses"
    return ModelScene(
        "solar_system",
        f"The Sun, Mercury-Pluto (Jupiter on: system barycentres), Earth and Moon from JPL DE421 at {epoch} TDB, "
        f"DE430 masses, {physics}, {years:g} years against DE421",
        problem, None, length, {"agreement": SOLAR_SYSTEM_AGREEMENT}, seconds, checks, CodeUnits(length, gm))


def _reference(name):
    return {"Sun": "about the barycentre", "Moon": "geocentric"}.get(name, "heliocentric")


MODELS = {
    "expanding_universe": _expanding_universe,
    "solar_system": _solar_system,
    "lagrange_L4_L5": _lagrange_stable,
    "lagrange_unstable": _lagrange_unstable,
    "lagrange_beyond_routh": _beyond_routh,
    **{f"ring_{n}": _ring_builder(n) for n in range(3, 9)},
}


def builtin_names() -> list[str]:
    """Names of the registered model scenes."""
    return sorted(MODELS)


def summary(name: str) -> str:
    """The model scene's one-line summary: its builder's first sentence (nothing is built)."""
    doc = " ".join((MODELS[name].__doc__ or "").split())
    return doc.split(". ")[0].rstrip(".") + "." if doc else ""


#: model scenes registered by other modules whose rebound run needs REBOUNDx (its effects or forces)
NEEDS_REBOUNDX: set[str] = set()


def register(builders: dict[str, Callable[..., ModelScene]], rules: dict[str, dict[str, Callable[[object], object]]],
             needs_reboundx: set[str] = frozenset()) -> None:
    """Add model scenes defined in another module (orbits.validate.perturb): their builders, the rules of their
    parameters (as PARAMETER_RULES) and which of them need REBOUNDx."""
    MODELS.update(builders)
    PARAMETER_RULES.update(rules)
    NEEDS_REBOUNDX.update(needs_reboundx)


def missing_extra(name: str) -> str | None:
    """Why the built-in model scene `name` cannot run on this install, or None: solar_system needs JPL DE421
    (skyfield-data and jplephem) and, for rebound's 1PN term, REBOUNDx, all in the extra orbits[ephemeris]; the
    scenes in NEEDS_REBOUNDX need REBOUNDx."""
    if name in NEEDS_REBOUNDX and importlib.util.find_spec("reboundx") is None:
        return "needs REBOUNDx: pip install 'orbits[ephemeris]'"
    if name != "solar_system":
        return None
    from orbits.ephemeris import positions as ephemeris

    needs = [] if ephemeris.available_source() == "de421" else ["JPL DE421 (skyfield-data, jplephem)"]
    if importlib.util.find_spec("reboundx") is None:
        needs.append("REBOUNDx")
    return f"needs {' and '.join(needs)}: pip install 'orbits[ephemeris]'" if needs else None


# ---- parameters of a model scene ------------------------------------------------------------------------------
MAX_OUTPUTS = 1_000_000
MAX_SHELLS = 1000
#: code units; the shells then reach r ~ 1e4, and runs stay short (a millisecond per 1e5 time units)
MAX_DURATION = 1e6
#: binary periods (2 pi code units each) of a Lagrange-point run, and so the longest departure of unstable points
MAX_PERIODS = 10_000
MAX_HORIZON = 2 * math.pi * MAX_PERIODS
#: the unstable points are followed until their deviation reaches this (units of the binary's separation)
MAX_OFFSET = 1e-4
#: below this (Sun-Earth is 3e-6) the secondary's Hill sphere shrinks towards the 1e-4 departure threshold
MIN_MASS_RATIO = 1e-7
#: a smaller offset is lost in the round-off (1e-16) of positions of order 1
MIN_OFFSET = 1e-14


def _number(value: object) -> float | None:
    """The float value of an int or float (bool refused: None); inf for an int too large for a float."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, float, np.integer, np.floating)):
        return None
    try:
        return float(value)
    except OverflowError:
        return math.inf


def _count(low: int, high: int, why: str = "") -> Callable[[object], int]:
    """Rule of a count: an integer (bool refused) in [low, high]."""

    def check(value):
        if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, np.integer)):
            raise ValueError(f"{show(value)} must be an integer in [{low}, {high}]")
        if not low <= value <= high:
            raise ValueError(f"{show(value)} is outside [{low}, {high}]{why}")
        return int(value)

    return check


def _positive(high: float, unit: str, high_open: bool = False, low: float = 0.0) -> Callable[[object], float]:
    """Rule of a duration, a number of periods or an offset: a finite number in (0, high], or [low, high] for
    low > 0; high_open excludes high."""
    allowed = f"{f'[{low:g}' if low > 0 else '(0'}, {high:g}{')' if high_open else ']'} {unit}"

    def check(value):
        x = _number(value)
        if x is None:
            raise ValueError(f"{show(value)} must be a number in {allowed}")
        if not (x >= low if low > 0 else x > 0.0) or not (x < high if high_open else x <= high):
            raise ValueError(f"{show(value)} is outside {allowed}")
        return x

    return check


def _mass_ratio(value: object) -> float | None:
    """Rule of a mass ratio mu = m / (M + m) in [MIN_MASS_RATIO, 0.5] (None: the Earth-Moon value)."""
    if value is None:
        return None
    x = _number(value)
    if x is None or not MIN_MASS_RATIO <= x <= 0.5:
        raise ValueError(f"{show(value)} must be a number in [{MIN_MASS_RATIO:g}, 0.5]: mu = m / (M + m), m the "
                         f"lighter of the pair")
    return x


def _points(value: object) -> tuple[str, ...]:
    """Rule of a list of Lagrange points: a non-empty list of distinct names among L1 ... L5."""
    allowed = ", ".join(POINTS)
    if not isinstance(value, (list, tuple)) or not value:
        raise ValueError(f'{show(value)} must be a non-empty list of Lagrange points like ["L1", "L2"]; '
                         f"allowed: {allowed}")
    for point in value:
        if not isinstance(point, str) or point not in POINTS:
            close = difflib.get_close_matches(str(point).upper(), POINTS, n=1)
            hint = f" (did you mean {close[0]!r}?)" if close else ""
            raise ValueError(f"{show(point)} is not a Lagrange point{hint}; allowed: {allowed}")
    if len(set(value)) != len(value):
        raise ValueError(f"{show(value)} names a point twice; give each point once")
    return tuple(value)


def _de421_epoch(value: object) -> str:
    """Rule of an epoch: a date string (TDB) inside DE421 (1899-07-29 to 2053-10-09)."""
    from orbits.ephemeris import positions as ephemeris

    if not isinstance(value, str):
        raise ValueError(f"{show(value)} must be a date string such as '2000-01-01 12:00' (TDB)")
    when = ephemeris.epoch(value, scale="tdb")
    jd = float(when.tdb.jd1 + when.tdb.jd2)
    if not ephemeris.DE421_SPAN[0] <= jd <= ephemeris.DE421_SPAN[1]:
        raise ValueError(f"{show(value)} is outside DE421, which covers 1899-07-29 to 2053-10-09 TDB")
    return value


def _boolean(value: object) -> bool:
    if not isinstance(value, bool):
        raise ValueError(f"{show(value)} must be true or false")
    return value


#: Julian years of a solar_system run (its end must also lie inside DE421)
MAX_SOLAR_SYSTEM_YEARS = 100.0
_OUTPUTS = _count(1, MAX_OUTPUTS)
#: what each parameter of each model accepts (the names are those of the builder's signature)
PARAMETER_RULES: dict[str, dict[str, Callable[[object], object]]] = {
    "expanding_universe": {"n_shells": _count(1, MAX_SHELLS), "duration": _positive(MAX_DURATION, "time units"),
                           "outputs": _OUTPUTS},
    "lagrange_L4_L5": {"periods": _positive(MAX_PERIODS, "binary periods"), "outputs": _OUTPUTS},
    "lagrange_unstable": {"mass_ratio": _mass_ratio, "points": _points,
                          "offset": _positive(MAX_OFFSET, "(units of the separation)", high_open=True, low=MIN_OFFSET),
                          "outputs": _OUTPUTS},
    "lagrange_beyond_routh": {"outputs": _OUTPUTS},
    "solar_system": {"epoch": _de421_epoch, "years": _positive(MAX_SOLAR_SYSTEM_YEARS, "years"),
                     "post_newtonian": _boolean, "outputs": _count(1, 100_000)},
    **{f"ring_{n}": {"outputs": _count(10, MAX_OUTPUTS, ": the shape check needs outputs before a third of the "
                                      "break-up time")} for n in range(3, 9)},
}


def parameters_of(name: str) -> tuple[str, ...]:
    """The parameters the model scene `name` takes (those of its builder's signature)."""
    return tuple(inspect.signature(MODELS[name]).parameters)


def build(name: str, parameters: dict[str, object] | None = None, source: str = "<scene>") -> ModelScene:
    """The model scene `name` built with `parameters`, each checked first against PARAMETER_RULES.

    Every refusal is a SceneError naming the source and the field: an unknown model, an unknown parameter
    (with the nearest and the allowed ones) or a value out of type or range.
    """
    if not isinstance(name, str) or name not in MODELS:
        close = difflib.get_close_matches(str(name), builtin_names(), n=1)
        hint = f" (did you mean {close[0]!r}?)" if close else ""
        raise SceneError(f"{source}: model: unknown model {show(name)}{hint}; known: {', '.join(builtin_names())}")
    allowed = parameters_of(name)
    if parameters is None:
        parameters = {}
    if not isinstance(parameters, dict):
        raise SceneError(f"{source}: parameters: {show(parameters)} must be a table of {name}'s parameters "
                         f"({', '.join(allowed)})")
    for key in parameters:
        if key not in allowed:
            close = difflib.get_close_matches(str(key), allowed, n=1)
            hint = f"; did you mean {close[0]!r}?" if close else ";"
            raise SceneError(f"{source}: parameters: unknown parameter {show(key)} of model {name!r}{hint} "
                             f"allowed: {', '.join(allowed) or 'none'}")
    checked = {}
    for key, value in parameters.items():
        try:
            checked[key] = PARAMETER_RULES[name][key](value)
        except ValueError as err:
            raise SceneError(f"{source}: parameters.{key}: {err}") from None
    try:
        return MODELS[name](**checked)
    except ParameterError as err:
        raise SceneError(f"{source}: parameters{'.' + err.name if err.name else ''}: {err}") from None
    except (OrbitsError, ValueError, TypeError) as err:  # a rule the table above missed: still one line
        raise SceneError(f"{source}: parameters: {err}") from None


def from_dict(data: dict, source: str = "<scene>") -> ModelScene:
    """The model scene a parsed scene file names with `model = "<name>"` and an optional `[parameters]` table.

    The file may hold only MODEL_KEYS (name and description are accepted and, as ever, the model names the scene).
    """
    model = data.get("model")
    known = isinstance(model, str) and model in MODELS
    misplaced = {key: f"a parameter of {model}: put it under [parameters]" for key in parameters_of(model)} if known \
        else {}
    unknown_keys(data, MODEL_KEYS, "", source, misplaced)
    if not isinstance(model, str):
        raise SceneError(f"{source}: model: {show(model)} must be a string naming a model; "
                         f"known: {', '.join(builtin_names())}")
    for key in ("name", "description"):
        if key in data and not isinstance(data[key], str):
            raise SceneError(f"{source}: {key}: {show(data[key])} must be a string")
    if "parameters" in data and not isinstance(data["parameters"], dict):
        raise SceneError(f"{source}: parameters: {show(data['parameters'])} must be a table")
    return build(model, data.get("parameters", {}), source=source)
