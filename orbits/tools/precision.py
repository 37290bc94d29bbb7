"""Work-precision: sweep each integrator's accuracy knob on the same problems, error against run time.

Problems are posed in G = 1 code units (total GM 1, orbit size 1): Kepler orbits with e = 0.0167, 0.5,
0.9 and 0.999 over 1e2 and 1e4 periods (a test particle about a unit mass, starting at periapsis), a
close hyperbolic flyby (e = 1.5, from -0.8 to +0.8 of the asymptotic true anomaly), an unequal binary
(mass ratio 0.1, e = 0.6, 100 periods, centre of mass at rest) and a test particle at the L4 point of
the Earth-Moon system (mu = 0.012150585609624, 100 periods).

The error of a run is max over bodies of |r - r_ref| / 1 at the time the run actually reached (steps x
dt for WHFast), where r_ref comes from orbits.tools.reference (mpmath at >= 60 digits) for the Kepler, flyby
and binary problems, and from the exact rigid rotation, evaluated in mpmath, for the L4 problem. It is
never another integrator. Wall times count integration only; compile and setup times are reported apart.
"""

import importlib.util
import time
import warnings
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field

import mpmath
import numpy as np

from orbits.core.twobody import anomalies, elements
from orbits.core.twobody.propagate import propagate
from orbits.tools import reference
from orbits.validate import backends
from orbits.validate.nbody import NBodyProblem

EARTH_MOON_MU = 0.012150585609624  # m / (M + m), JPL DE430 GM values
EXTRA_TURN = 0.37  # runs end 0.37 period past the round number: a whole number of periods would return the
#                    closed form exactly to its initial state and flatter it


@dataclass(frozen=True, eq=False)
class Problem:
    """A work-precision problem in G = 1 code units, with its reference and closed-form solutions."""

    name: str
    gm: np.ndarray
    positions: np.ndarray
    velocities: np.ndarray
    n_active: int
    t_end: float
    period: float  # the orbital time scale WHFast steps are taken as fractions of
    reference: object  # t -> (N, 3) exact positions (mpmath)
    analytic: object  # t -> (N, 3) positions from orbits' closed form

    def nbody(self, t_end: float | None = None) -> NBodyProblem:
        """The problem as an NBodyProblem with a single output time."""
        return NBodyProblem(self.gm, self.positions, self.velocities, self.n_active,
                            np.array([self.t_end if t_end is None else t_end]))


@dataclass(frozen=True)
class Row:
    """One run: method, its knob setting, the problem, error, wall time (s), setup time (s) and a note."""

    method: str
    setting: str
    problem: str
    error: float
    seconds: float
    setup_seconds: float = 0.0
    note: str = ""


def _mp_floats(vectors):
    return np.array([[float(x) for x in v] for v in vectors])


def kepler_problem(e: float, periods: float) -> Problem:
    """A test particle at periapsis of an a = 1 orbit of eccentricity e about a unit mass at the origin."""
    p = 1.0 - e * e
    r0, v0 = elements.elements_to_state(p, e, 0.3, 0.0, 0.0, 0.0, 1.0)
    positions = np.array([np.zeros(3), r0])
    velocities = np.array([np.zeros(3), v0])

    def exact(t):
        return np.array([np.zeros(3), _mp_floats([reference.propagate(r0, v0, 1.0, t)[0]])[0]])

    def analytic(t):
        return np.array([np.zeros(3), propagate(r0, v0, 1.0, t)[0]])

    return Problem(f"e={e:g}, {periods:g} periods", np.array([1.0, 0.0]), positions, velocities, 1,
                   (periods + EXTRA_TURN) * 2 * np.pi, 2 * np.pi, exact, analytic)


def flyby_problem(e: float = 1.5) -> Problem:
    """A test particle on a q = 1 hyperbola about a unit mass, from nu = -0.8 to +0.8 of the asymptote."""
    p = 1.0 + e
    nu0 = -0.8 * np.arccos(-1.0 / e)
    r0, v0 = elements.elements_to_state(p, e, 0.5, 0.0, 0.0, nu0, 1.0)
    t_end = -2.0 * float(anomalies.time_since_periapsis(nu0, p, e, 1.0))
    positions, velocities = np.array([np.zeros(3), r0]), np.array([np.zeros(3), v0])

    def exact(t):
        return np.array([np.zeros(3), _mp_floats([reference.propagate(r0, v0, 1.0, t)[0]])[0]])

    def analytic(t):
        return np.array([np.zeros(3), propagate(r0, v0, 1.0, t)[0]])

    return Problem(f"flyby e={e:g}", np.array([1.0, 0.0]), positions, velocities, 1, t_end, 2 * np.pi, exact,
                   analytic)


def binary_problem(ratio: float = 0.1, e: float = 0.6, periods: float = 100) -> Problem:
    """Two bodies of GM 1/(1+ratio) and ratio/(1+ratio), relative orbit a = 1, e, centre of mass at rest."""
    gm = np.array([1.0, ratio]) / (1.0 + ratio)
    r_rel, v_rel = elements.elements_to_state(1.0 - e * e, e, 0.4, 0.2, 0.1, 0.0, 1.0)
    share = np.array([-gm[1], gm[0]])[:, None]  # body i sits at share_i * r_rel from the centre of mass

    def exact(t):
        rel = _mp_floats([reference.propagate(r_rel, v_rel, 1.0, t)[0]])[0]
        return share * rel

    def analytic(t):
        return share * propagate(r_rel, v_rel, 1.0, t)[0]

    return Problem(f"binary q={ratio:g}, e={e:g}, {periods:g} periods", gm, share * r_rel, share * v_rel, 2,
                   (periods + EXTRA_TURN) * 2 * np.pi, 2 * np.pi, exact, analytic)


def l4_problem(mu: float = EARTH_MOON_MU, periods: float = 100) -> Problem:
    """Earth-Moon on a circular unit orbit (n = 1) and a test particle at L4, all rotating rigidly."""
    gm = np.array([1.0 - mu, mu, 0.0])
    positions = np.array([[-mu, 0.0, 0.0], [1.0 - mu, 0.0, 0.0], [0.5 - mu, np.sqrt(3.0) / 2.0, 0.0]])
    velocities = np.stack([-positions[:, 1], positions[:, 0], np.zeros(3)], axis=1)  # omega x r, omega = z

    def rotate(t, cos, sin):
        c, s = cos(t), sin(t)
        x, y = positions[:, 0], positions[:, 1]
        return np.stack([c * x - s * y, s * x + c * y, np.zeros(3)], axis=1)

    def exact(t):
        with mpmath.workdps(40):
            return rotate(t, lambda a: float(mpmath.cos(mpmath.mpf(a))), lambda a: float(mpmath.sin(mpmath.mpf(a))))

    return Problem(f"Earth-Moon L4, {periods:g} periods", gm, positions, velocities, 2,
                   (periods + EXTRA_TURN) * 2 * np.pi, 2 * np.pi, exact, lambda t: rotate(t, np.cos, np.sin))


def problems(long: bool = True) -> list[Problem]:
    """The problem set: Kepler orbits at e = 0.0167, 0.5, 0.9, 0.999 over 100 and 10**4 periods, a flyby, a binary
    and the Earth-Moon L4 point; long=False leaves out the 1e4-period runs."""
    eccentricities = (0.0167, 0.5, 0.9, 0.999)
    chosen = [kepler_problem(e, 100) for e in eccentricities]
    if long:
        chosen += [kepler_problem(e, 10_000) for e in eccentricities]
    return chosen + [flyby_problem(), binary_problem(), l4_problem()]


@dataclass(frozen=True)
class Method:
    """An integrator and the settings of its accuracy knob, from loose to tight."""

    name: str
    backend: str
    knob: str
    values: tuple
    fixed: dict = field(default_factory=dict)


def methods(quick: bool = False) -> list[Method]:
    """The methods swept: rebound IAS15, WHFast and Gragg-Bulirsch-Stoer; heyoka in float64 with and without
    high_accuracy and in long double; scipy's DOP853 when scipy is installed."""
    thin = (lambda v: v[::2]) if quick else (lambda v: v)
    chosen = [
        Method("rebound IAS15", "rebound", "epsilon", thin((1e-3, 1e-5, 1e-7, 1e-9, 1e-11)), {"integrator": "ias15"}),
        Method("rebound WHFast", "rebound", "steps per period", thin((30, 100, 300, 1000)), {"integrator": "whfast"}),
        Method("rebound BS", "rebound", "epsilon", thin((1e-6, 1e-8, 1e-10, 1e-12)), {"integrator": "bs"}),
        Method("heyoka", "heyoka", "tol", thin((1e-6, 1e-9, 1e-12, 1e-15, 1e-18)), {"high_accuracy": False}),
        Method("heyoka high_accuracy", "heyoka", "tol", thin((1e-6, 1e-9, 1e-12, 1e-15, 1e-18)),
               {"high_accuracy": True}),
        Method("heyoka long double", "heyoka", "tol", thin((1e-12, 1e-15, 1e-18)),
               {"high_accuracy": True, "fp_type": "long double"}),
    ]
    if importlib.util.find_spec("scipy") is not None:
        # DOP853 raises an rtol below 100 eps (2.2e-14) to that, with a warning: 100 eps is its tightest
        chosen.append(Method("scipy DOP853", "scipy", "rtol", thin((1e-6, 1e-9, 1e-12, 100 * np.finfo(float).eps))))
    return chosen


def _error(problem, t, positions):
    return float(np.max(np.linalg.norm(positions - problem.reference(t), axis=-1)))


def _run_backend(method, value, problem):
    settings = dict(method.fixed)
    if method.knob == "steps per period":
        settings["dt"] = problem.period / value
    else:
        settings[method.knob] = value
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        result = backends.integrate(method.backend, problem.nbody(), **settings)
    note = "; ".join(dict.fromkeys(str(w.message).strip() for w in caught))
    t = float(result.times[-1])
    return _error(problem, t, result.positions[-1]), result.wall_time, result.setup_time, note


def _nbody_rhs(gm, n_active):
    """dy/dt of the G = 1 N-body problem for scipy (massless bodies after n_active exert no force)."""
    def rhs(_, y):
        r, v = y.reshape(2, -1, 3)
        d = r[None, :n_active, :] - r[:, None, :]  # (N, n_active, 3): from body i to attractor j
        dist2 = np.sum(d * d, axis=-1)
        inverse_cube = np.zeros_like(dist2)
        apart = dist2 > 0  # a body does not attract itself
        inverse_cube[apart] = dist2[apart] ** -1.5
        acc = np.einsum("j,ij,ijk->ik", gm[:n_active], inverse_cube, d)
        return np.concatenate([v.ravel(), acc.ravel()])
    return rhs


def _run_scipy(value, problem):
    from scipy.integrate import solve_ivp

    y0 = np.concatenate([problem.positions.ravel(), problem.velocities.ravel()])
    start = time.perf_counter()
    solution = solve_ivp(_nbody_rhs(problem.gm, problem.n_active), (0.0, problem.t_end), y0, method="DOP853",
                         rtol=value, atol=value * 1e-3, t_eval=[problem.t_end])
    seconds = time.perf_counter() - start
    positions = solution.y[:, -1].reshape(2, -1, 3)[0]
    return _error(problem, problem.t_end, positions), seconds, 0.0, "" if solution.success else solution.message


def _label(method, value):
    return f"{method.knob}={value:g}"


def run(
    chosen_problems: Sequence[Problem] | None = None,
    chosen_methods: Sequence[Method] | None = None,
    scipy_max_periods: float = 200,
    progress: Callable[[str], object] | None = None,
) -> list[Row]:
    """Rows of every method x setting x problem, plus one "orbits analytic" row per problem.

    scipy's DOP853 evaluates its right-hand side in Python, so it is skipped (with a note) on problems
    longer than `scipy_max_periods` orbital periods.
    """
    rows = []
    for problem in chosen_problems or problems():
        if progress:
            progress(problem.name)
        rows.append(_analytic_row(problem))
        for method in chosen_methods or methods():
            for value in method.values:
                rows.append(_row(method, value, problem, scipy_max_periods))
    return rows


def _analytic_row(problem):
    start = time.perf_counter()
    positions = problem.analytic(problem.t_end)
    seconds = time.perf_counter() - start
    return Row("orbits analytic", "closed form", problem.name, _error(problem, problem.t_end, positions), seconds)


def _row(method, value, problem, scipy_max_periods):
    if method.backend == "scipy":
        if problem.t_end > scipy_max_periods * problem.period:
            return Row(method.name, _label(method, value), problem.name, np.nan, np.nan,
                       note=f"skipped: more than {scipy_max_periods} periods with a Python right-hand side")
        error, seconds, setup, note = _run_scipy(value, problem)
    else:
        error, seconds, setup, note = _run_backend(method, value, problem)
    return Row(method.name, _label(method, value), problem.name, error, seconds, setup, note)


def error_target(target: float) -> float:
    """The error a summary asks each method to reach, checked: a finite number > 0 (relative to the orbit's size);
    OrbitDomainError otherwise (-1 or nan asked nothing that a run could reach)."""
    from orbits.core.checks import require_positive

    require_positive(target, "error target", "")
    return float(target)


def summary(rows: Sequence[Row], target: float = 1e-10) -> list[dict[str, object]]:
    """Per problem and method: the best error reached, and the fastest run reaching `target` (error_target)."""
    target = error_target(target)
    out = []
    for problem in dict.fromkeys(r.problem for r in rows):
        for method in dict.fromkeys(r.method for r in rows if r.problem == problem):
            runs = [r for r in rows if r.problem == problem and r.method == method and np.isfinite(r.error)]
            if not runs:
                continue
            best = min(runs, key=lambda r: r.error)
            good = [r for r in runs if r.error <= target]
            fastest = min(good, key=lambda r: r.seconds) if good else None
            out.append({"problem": problem, "method": method, "best_error": best.error,
                        "best_setting": best.setting, "best_seconds": best.seconds,
                        "fastest_at_target": None if fastest is None else fastest.setting,
                        "fastest_seconds": None if fastest is None else fastest.seconds})
    return out
