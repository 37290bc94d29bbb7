"""`orbits bench lambert`: Lambert solvers, orbits against the peers installed, every figure from the same run.

Two data sets, both heliocentric in SI units:
- "random": zero-revolution transfers between random directions at 0.5-3 AU, times of flight 30-500 d.
  Throughput (solves per second, one thread) and the median and worst arrival error |r(tof) - r2| / |r2|,
  where r(tof) is the returned v1 propagated at 60 digits (orbits.tools.reference.propagate, mpmath), on the
  first n_ref transfers.
- "hard" (hard_cases()): transfer angles within 1e-8 of 0, pi and 2 pi, exactly pi (with a plane normal), the
  parabolic time of flight, N = 1 and 5 at their minimum time (both branches), very short and very long
  flights, at unit and SI scale. The times of the parabolic and minimum-time cases are computed here in mpmath
  from Lagrange's equation. A case fails when the solver raises, returns a non-finite v1, or misses r2 by more
  than 1e-13 |r2| (TOLERANCE; one ulp of v1 moves the end point by less than 8e-15 on these cases).

Peers: lamberthub's izzo2015 (numba) and gooding1990, pykep's lambert_problem and hapsira's izzo, each through
its per-call Python API (the way their users call them) and marked "not installed" when absent. orbits runs
vectorised, through orbits.core.manoeuvres.lambert.solve: the compiled kernel on one thread, and the NumPy version.
"""

import math
import statistics
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass

import mpmath
import numpy as np

from orbits.tools.bench.harness import check_sizes, orbits_threads
from orbits.tools.bench.table import WIDTH, mark, mega, notes, plain_table, sig, wrap

AU = 1.495978707e11
MU_SUN = 1.32712440041279419e20  # m3/s2, DE440's GM of the Sun
DAY = 86400.0
#: the acceptance bound on the arrival error, relative to |r2|
TOLERANCE = 1e-13
#: transfers on which a per-call peer is timed (its throughput is per call, so it scales)
PER_CALL_SUBSET = 20_000


@dataclass(frozen=True)
class LambertCase:
    """One Lambert problem: positions (m), time of flight (s), mu (m3/s2) and which solution."""

    name: str
    r1: np.ndarray
    r2: np.ndarray
    tof: float
    mu: float
    revolutions: int = 0
    branch: str = "right"
    prograde: bool = True
    normal: tuple[float, float, float] | None = None


@dataclass(frozen=True)
class LambertRow:
    """One solver: best time of `repeats` for n random transfers, the median and worst arrival errors on the
    first n_ref of them, and the hard cases failed out of hard_total; status "ok", "raised" or "not installed"."""

    method: str
    n: int
    seconds: float
    throughput_per_s: float
    median_error: float
    worst_error: float
    hard_failed: int
    hard_total: int
    status: str
    note: str = ""
    setup_seconds: float = 0.0
    failed_cases: tuple[str, ...] = ()


# --- the data -------------------------------------------------------------------------------------------


def random_transfers(n: int, seed: int = 1) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(r1, r2, tof): n zero-revolution heliocentric transfers (see the module docstring)."""
    rng = np.random.default_rng(seed)
    directions = rng.normal(size=(2, n, 3))
    directions /= np.linalg.norm(directions, axis=-1, keepdims=True)
    radii = rng.uniform(0.5, 3.0, (2, n, 1)) * AU
    return directions[0] * radii[0], directions[1] * radii[1], rng.uniform(30.0, 500.0, n) * DAY


def _turned(angle, radius):
    return np.array([radius * math.cos(angle), radius * math.sin(angle), 0.0])


def _mp_lagrange_time(x, lam, revolutions):
    """Izzo's non-dimensional T(x) from Lagrange's equation, in mpmath (x < 1 ellipses, x > 1 hyperbolas)."""
    if x < 1:
        w = mpmath.sqrt(1 - x * x)
        alpha, beta = 2 * mpmath.acos(x), 2 * mpmath.asin(lam * w)
        return ((alpha - mpmath.sin(alpha)) - (beta - mpmath.sin(beta)) + 2 * mpmath.pi * revolutions) / (2 * w**3)
    w = mpmath.sqrt(x * x - 1)
    alpha, beta = 2 * mpmath.acosh(x), 2 * mpmath.asinh(lam * w)
    return ((mpmath.sinh(alpha) - alpha) - (mpmath.sinh(beta) - beta)) / (2 * w**3)


def _mp_geometry(r1, r2, long_way):
    """(s, lambda) at the working precision, from the float positions' exact values."""
    a, b = [mpmath.mpf(float(v)) for v in r1], [mpmath.mpf(float(v)) for v in r2]
    n1, n2 = mpmath.sqrt(sum(v * v for v in a)), mpmath.sqrt(sum(v * v for v in b))
    c = mpmath.sqrt(sum((p - q) ** 2 for p, q in zip(a, b)))
    s = (n1 + n2 + c) / 2
    return s, (-1 if long_way else 1) * mpmath.sqrt((s - c) / s)


def parabolic_time(r1, r2, mu, long_way=False) -> float:
    """Time of flight (s) of the parabola from r1 to r2 (Euler's equation, T = 2 (1 - lambda**3) / 3), mpmath."""
    with mpmath.workdps(50):
        s, lam = _mp_geometry(r1, r2, long_way)
        return float(2 * (1 - lam**3) / 3 * mpmath.sqrt(s**3 / (2 * mpmath.mpf(mu))))


def minimum_time(r1, r2, mu, revolutions, long_way=False) -> float:
    """Shortest time of flight (s) of `revolutions` complete revolutions: min over x of Lagrange's T, mpmath."""
    with mpmath.workdps(50):
        s, lam = _mp_geometry(r1, r2, long_way)
        x = mpmath.findroot(lambda z: mpmath.diff(lambda q: _mp_lagrange_time(q, lam, revolutions), z), 0)
        return float(_mp_lagrange_time(x, lam, revolutions) * mpmath.sqrt(s**3 / (2 * mpmath.mpf(mu))))


def hard_cases() -> list[LambertCase]:
    """The hard cases (module docstring), at unit scale (mu = 1, |r1| = 1) and at SI scale (1 AU about the Sun)."""
    cases = []
    for scale, mu, unit in ((1.0, 1.0, "unit"), (AU, MU_SUN, "SI")):
        year = 2 * math.pi * math.sqrt(scale**3 / mu)  # the period of the circle of radius `scale`
        r1 = np.array([scale, 0.0, 0.0])
        for label, angle in (("0 + 1e-8", 1e-8), ("pi - 1e-8", math.pi - 1e-8), ("pi + 1e-8", math.pi + 1e-8),
                             ("2 pi - 1e-8", 2 * math.pi - 1e-8), ("0 + 1e-12", 1e-12), ("0 + 1e-15", 1e-15),
                             ("2 pi - 1e-12", 2 * math.pi - 1e-12), ("2 pi - 1e-15", 2 * math.pi - 1e-15)):
            for fraction in (0.05, 0.5):
                cases.append(LambertCase(f"{label}, tof {fraction} T ({unit})", r1, _turned(angle, 1.5 * scale),
                                         fraction * year, mu))
        opposite = np.array([-1.5 * scale, 0.0, 0.0])
        for fraction in (0.1, 0.5, 2.0):
            cases.append(LambertCase(f"exactly pi, tof {fraction} T ({unit})", r1, opposite, fraction * year, mu,
                                     normal=(0.0, 0.0, 1.0)))
        for angle in (1.0, 2.5, 4.0):
            r2 = _turned(angle, 1.3 * scale)
            long_way = angle > math.pi
            cases.append(LambertCase(f"parabolic tof, theta {angle} ({unit})", r1, r2,
                                     parabolic_time(r1, r2, mu, long_way), mu))
            for revolutions in (1, 5):
                tof = minimum_time(r1, r2, mu, revolutions, long_way)
                for branch in ("left", "right"):
                    cases.append(LambertCase(f"N = {revolutions} at T_min, theta {angle}, {branch} ({unit})", r1,
                                             r2, tof, mu, revolutions, branch))
        r2 = _turned(2.0, 1.2 * scale)
        cases.append(LambertCase(f"very short flight, 1e-9 T ({unit})", r1, r2, 1e-9 * year, mu))
        cases.append(LambertCase(f"very long flight, 3 T ({unit})", r1, r2, 3.0 * year, mu))
        cases.append(LambertCase(f"very long flight, N = 3, 4 T ({unit})", r1, r2, 4.0 * year, mu, 3, "left"))
        cases.append(LambertCase(f"very long flight, to 30 r1 in 30 T ({unit})", r1, _turned(2.0, 30.0 * scale),
                                 30.0 * year, mu))
    return cases


# --- the reference ----------------------------------------------------------------------------------------


def arrival_error(r1, v1, r2, tof, mu) -> float:
    """|r(tof) - r2| / |r2| for the orbit through (r1, v1) propagated at 60 digits (NaN for a non-finite v1)."""
    from orbits.tools.reference import propagate

    if not np.all(np.isfinite(v1)):
        return math.nan
    r, _ = propagate(r1, v1, mu, tof)
    with mpmath.workdps(40):
        miss = mpmath.sqrt(sum((a - mpmath.mpf(float(b))) ** 2 for a, b in zip(r, r2)))
        return float(miss / mpmath.sqrt(sum(mpmath.mpf(float(b)) ** 2 for b in r2)))


# --- the solvers ------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class _Solver:
    """A solver adapter: batch(r1, r2, tof, mu) -> v1 (n, 3) for the random set (None: per call, via one);
    one(case) -> v1 for one problem."""

    name: str
    one: Callable[[LambertCase], np.ndarray]
    batch: Callable[[np.ndarray, np.ndarray, np.ndarray, float], np.ndarray] | None = None
    subset: int | None = None
    note: str = ""
    setup_seconds: float = 0.0


def _orbits_solver(threads):
    from orbits.core.manoeuvres.lambert import solve

    def batch(r1, r2, tof, mu):
        with orbits_threads(threads):
            return solve(r1, r2, tof, mu).v1

    def one(case):
        with orbits_threads(threads):
            return solve(case.r1, case.r2, case.tof, case.mu, case.revolutions, case.branch, case.prograde,
                         case.normal).v1

    start = time.perf_counter()
    batch(np.array([[AU, 0, 0]]), np.array([[0, AU, 0]]), np.array([100 * DAY]), MU_SUN)  # loads the kernel
    note = "compiled, 1 thread, vectorised" if threads else "NumPy (ORBITS_JIT=0), vectorised"
    return _Solver("orbits" if threads else "orbits (NumPy)", one, batch, None if threads else 200_000, note,
                   time.perf_counter() - start)


def _lamberthub_solver(name, subset):
    """lamberthub's numba solvers, called as fast as they can be: every argument positional (a keyword argument
    sends each call through numba's slow dispatch path, 20-40 times slower) and at its default tolerances, in a
    plain loop over the prepared arrays."""
    import lamberthub

    function = getattr(lamberthub, name)
    defaults = (35, 1e-5, 1e-7)  # maxiter, atol, rtol: lamberthub's own defaults, passed positionally

    def one(case):
        prograde = bool(case.prograde if case.normal is None else case.normal[2] >= 0)
        return function(float(case.mu), np.asarray(case.r1, dtype=float), np.asarray(case.r2, dtype=float),
                        float(case.tof), int(case.revolutions), prograde, case.branch == "right", *defaults)[0]

    def batch(r1, r2, tof, mu):
        v1 = np.empty_like(r1)
        for i in range(tof.size):
            v1[i] = function(mu, r1[i], r2[i], tof[i], 0, True, True, *defaults)[0]
        return v1

    start = time.perf_counter()
    one(LambertCase("", np.array([AU, 0, 0]), np.array([0, AU, 0]), 100 * DAY, MU_SUN))  # numba compiles here
    return _Solver(f"lamberthub {name}", one, batch, subset, "per-call API, positional arguments, in a loop",
                   time.perf_counter() - start)


def _pykep_solver():
    import pykep

    def one(case):
        clockwise = not (case.prograde if case.normal is None else case.normal[2] >= 0)
        problem = pykep.lambert_problem(list(case.r1), list(case.r2), case.tof, case.mu, clockwise,
                                        case.revolutions)
        solutions = problem.get_v1()
        index = 0 if case.revolutions == 0 else (1 if case.branch == "left" else 2)
        return np.array(solutions[min(index, len(solutions) - 1)])

    return _Solver("pykep lambert_problem", one, None, PER_CALL_SUBSET, "per-call Python API")


def _hapsira_solver():
    import astropy.units as u
    from hapsira.iod import izzo

    def one(case):
        k = case.mu * u.m**3 / u.s**2
        prograde = case.prograde if case.normal is None else case.normal[2] >= 0
        v1, _ = izzo.lambert(k, case.r1 * u.m, case.r2 * u.m, case.tof * u.s, M=case.revolutions,
                             prograde=prograde, lowpath=case.branch == "right")
        return v1.to_value(u.m / u.s)

    return _Solver("hapsira izzo", one, None, PER_CALL_SUBSET, "per-call Python API (astropy units)")


_SOLVERS = [
    ("orbits", lambda: _orbits_solver(1)),
    ("orbits (NumPy)", lambda: _orbits_solver(0)),
    ("pykep lambert_problem", _pykep_solver),
    ("hapsira izzo", _hapsira_solver),
    ("lamberthub izzo2015", lambda: _lamberthub_solver("izzo2015", PER_CALL_SUBSET)),
    ("lamberthub gooding1990", lambda: _lamberthub_solver("gooding1990", 2_000)),
]


# --- measuring --------------------------------------------------------------------------------------------


def _per_call(solver):
    def batch(r1, r2, tof, mu):
        return np.array([solver.one(LambertCase("", a, b, t, mu)) for a, b, t in zip(r1, r2, tof)])

    return batch


def _hard(solver, cases):
    """Names of the hard cases the solver fails (raises, non-finite v1 or misses r2 by more than TOLERANCE)."""
    failed = []
    for case in cases:
        try:
            v1 = np.asarray(solver.one(case), dtype=float)
            error = arrival_error(case.r1, v1, case.r2, case.tof, case.mu)
        except Exception:  # a peer raising on a hard case is a benchmark result
            error = math.nan
        if not error <= TOLERANCE:
            failed.append(case.name)
    return failed


def _measure(solver, data, n_ref, repeats, cases):
    r1, r2, tof = data
    n = tof.size if solver.subset is None else min(tof.size, solver.subset)
    batch = solver.batch or _per_call(solver)
    best = math.inf
    try:
        for _ in range(repeats):
            start = time.perf_counter()
            v1 = batch(r1[:n], r2[:n], tof[:n], MU_SUN)
            best = min(best, time.perf_counter() - start)
    except Exception as exc:  # noqa: BLE001 - reported in the table
        note = f"raised {type(exc).__name__}: {exc}".splitlines()[0][:200]
        return LambertRow(solver.name, n, math.nan, math.nan, math.nan, math.nan, 0, 0, "raised", note)
    errors = [arrival_error(r1[i], v1[i], r2[i], tof[i], MU_SUN) for i in range(min(n_ref, n))]
    finite = [e for e in errors if math.isfinite(e)]
    failed = _hard(solver, cases)
    return LambertRow(solver.name, n, best, n / best, statistics.median(finite) if finite else math.nan,
                      max(finite, default=math.nan), len(failed), len(cases), "ok", solver.note,
                      solver.setup_seconds, tuple(failed))


def bench_lambert(n: int = 1_000_000, n_ref: int = 200, repeats: int = 3, seed: int = 1,
                  solvers: Sequence[str] | None = None) -> list[LambertRow]:
    """Rows of the Lambert benchmark (module docstring): every solver installed, on the same data, in one run.

    `solvers` selects rows by name (default: all of _SOLVERS)."""
    check_sizes(n=n, n_ref=n_ref, repeats=repeats)
    data = random_transfers(n, seed)
    cases = hard_cases()
    rows = []
    for name, factory in _SOLVERS:
        if solvers is not None and name not in solvers:
            continue
        try:
            solver = factory()
        except ImportError:
            rows.append(LambertRow(name, 0, math.nan, math.nan, math.nan, math.nan, 0, 0, "not installed"))
            continue
        rows.append(_measure(solver, data, n_ref, repeats, cases))
    return rows


# --- the table --------------------------------------------------------------------------------------------


def format_lambert(rows: Sequence[LambertRow]) -> str:
    """Plain-text table, at most 80 columns: throughput (M/s), ratio to orbits, median and worst arrival error
    on the random set, hard cases failed; the notes and the failed hard cases under it."""
    reference = next((r.throughput_per_s for r in rows if r.method == "orbits" and r.status == "ok"), math.nan)
    texts, table = {}, []
    for r in rows:
        if r.status == "ok":
            cells = [mega(r.throughput_per_s), sig(r.throughput_per_s / reference, 3), f"{r.median_error:.1e}",
                     f"{r.worst_error:.1e}", f"{r.hard_failed}/{r.hard_total}"]
            note = r.note + (f" (compile/setup {r.setup_seconds:.2f} s)" if r.setup_seconds > 0.05 else "")
        else:
            cells = ["-"] * 5
            note = r.status if r.status == "not installed" else f"{r.status}: {r.note}"
        table.append([r.method + mark(texts, note), *cells])
    lines = plain_table(["method", "M/s", "ratio", "median", "worst", "hard failed"], table)
    legend = ("M/s: millions of Lambert solves per second on one thread (random zero-revolution transfers, "
              "0.5-3 AU, 30-500 d). ratio: throughput over that of orbits. median, worst: arrival error "
              "|r(tof) - r2| / |r2| of v1 propagated at 60 digits (mpmath). hard failed: cases raising, NaN, or "
              f"missing r2 by more than {TOLERANCE:g} |r2|.")
    failures = [f"{r.method} failed: {_grouped(r.failed_cases)}" for r in rows if r.failed_cases]
    return "\n".join(lines + [""] + wrap(legend, WIDTH) + notes(texts, WIDTH)
                     + [line for text in failures for line in wrap(text, WIDTH, subsequent="  ")])


def _grouped(names):
    """Failed case names grouped by kind (the name up to its first comma), with counts: "exactly pi (6), ..."."""
    kinds = {}
    for name in names:
        kind = name.split(",")[0]
        kinds[kind] = kinds.get(kind, 0) + 1
    return ", ".join(f"{kind} ({count})" for kind, count in kinds.items())


__all__ = ["LambertCase", "LambertRow", "bench_lambert", "format_lambert", "hard_cases"]
