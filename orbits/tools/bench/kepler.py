"""`orbits bench kepler`: Kepler's equation on three sets ("easy", "hard" near e = 1, "hyperbolic"), throughput
and worst error against mpmath, for orbits (compiled kernels on one thread and on every core, and the NumPy
fallback), heyoka's kepE cfunc (one thread and every core), rebound.M_to_E, a plain NumPy Newton solver,
exoplanet-core and pykep.

heyoka's cfunc splits large batches over its own thread pool, pinned here with heyoka.set_nthreads; orbits'
kernels split over orbits.core._fast.num_threads(). rebound is timed through its per-call Python API, which
measures the Python call overhead as much as the solver.
"""

import dataclasses
import math
import time
from collections.abc import Sequence
from dataclasses import dataclass

import mpmath
import numpy as np

from orbits.tools.bench.harness import (
    NEWTON_MAX_ITER,
    NEWTON_TOL,
    Method,
    best_time,
    check_sizes,
    cores,
    load_methods,
    machine,
    newton_elliptic,
    newton_hyperbolic,
    orbits_name,
    orbits_note,
    orbits_threads,
)
from orbits.tools.bench.table import RATIO_LEGEND, WIDTH, by_dataset, notes, plain_table, sig, wrap
from orbits.validate import peers

#: Pairs on which the per-call rebound API is timed (its throughput is per pair, so it scales).
PER_CALL_SUBSET = 20_000
_REF_DIGITS = 30  # reference digits beyond those lost to cancellation near e = 1 and to reduction


@dataclass(frozen=True)
class BenchRow:
    """One method timed on one data set.

    ``seconds`` is the best of the repeats for ``n`` pairs; errors are the worst over the first
    ``n_ref`` pairs with a finite result (NaN if none); ``n_nan`` counts non-finite results over all
    ``n`` pairs; ``status`` is "ok", "skipped" (package absent or equation not supported) or
    "raised"; ``setup_seconds`` is one-off preparation such as JIT compilation.
    """

    method: str
    dataset: str
    n: int
    seconds: float
    throughput_per_s: float
    max_rel_error: float
    max_ulp: float
    n_nan: int
    status: str
    note: str = ""
    setup_seconds: float = 0.0


@dataclass(frozen=True)
class _Dataset:
    """Benchmark inputs: eccentricities e and mean anomalies M of one equation type."""

    name: str
    hyperbolic: bool
    e: np.ndarray
    M: np.ndarray


# --- data ---------------------------------------------------------------------------------------


def _datasets(n_easy, n_hard, n_hyp, seed):
    """The three benchmark data sets, drawn in order from numpy.random.default_rng(seed)."""
    rng = np.random.default_rng(seed)
    easy = _Dataset("easy", False, rng.uniform(0.0, 0.99, n_easy), rng.uniform(0.0, 2 * np.pi, n_easy))
    e_hard = 1.0 - 10.0 ** rng.uniform(-9.0, -2.0, n_hard)
    offset = 10.0 ** rng.uniform(-12.0, -3.0, n_hard)
    M_hard = np.where(np.arange(n_hard) % 2 == 0, offset, np.pi - offset)  # tiny / near pi, alternating
    hard = _Dataset("hard", False, e_hard, M_hard)
    e_hyp = 1.0 + 10.0 ** rng.uniform(-9.0, 3.0, n_hyp)
    hyp = _Dataset("hyperbolic", True, e_hyp, 10.0 ** rng.uniform(-6.0, 6.0, n_hyp))
    return [easy, hard, hyp]


# --- mpmath reference (independent of orbits.core; cross-checked against tests/mpref.py) ----------


def _extra_digits(distance_from_one):
    """Decimal digits cancelled when forming a quantity at this (float) distance from 1."""
    return max(0, -math.floor(math.log10(distance_from_one))) if distance_from_one > 0 else 0


def _newton_from_above(f, df, x, digits):
    """Root of an increasing convex f by Newton from x >= root; the iterates decrease monotonically."""
    tol = mpmath.mpf(10) ** -digits
    for _ in range(200):
        step = f(x) / df(x)
        x -= step
        if abs(step) <= tol * abs(x):
            return x
    raise ArithmeticError(f"bench reference did not converge at x={x}")


def _reference_elliptic(M, e):
    """(E, M_reduced) as mpf with E - e sin E = M_reduced = M - 2 pi round(M / 2 pi), E in [-pi, pi]."""
    digits = _REF_DIGITS + _extra_digits(1.0 - e) + max(0, math.ceil(math.log10(abs(M) + 1.0)))
    with mpmath.workdps(digits):
        M, e = mpmath.mpf(M), mpmath.mpf(e)
        Mr = M - 2 * mpmath.pi * mpmath.nint(M / (2 * mpmath.pi))
        m = abs(Mr)
        if m == 0 or e == 0:
            return Mr, Mr
        # E - e sin E >= (1 - e) E and >= (1 - e) E + e E^3 / pi^2 on [0, pi]; E <= m + e; E <= pi.
        x = min(mpmath.pi, m + e, m / (1 - e), mpmath.cbrt(mpmath.pi**2 * m / e))
        f, df = lambda E: E - e * mpmath.sin(E) - m, lambda E: 1 - e * mpmath.cos(E)
        E = _newton_from_above(f, df, x, _REF_DIGITS - 5)
        return mpmath.sign(Mr) * E, Mr


def _reference_hyperbolic(M, e):
    """H as mpf with e sinh H - H = M."""
    digits = _REF_DIGITS + _extra_digits(e - 1.0)
    with mpmath.workdps(digits):
        M, e = mpmath.mpf(M), mpmath.mpf(e)
        m = abs(M)
        if m == 0:
            return M
        # e sinh H - H >= (e - 1) H and >= e H^3 / 6, so H <= asinh((m + min(...)) / e).
        x = mpmath.asinh((m + min(m / (e - 1), mpmath.cbrt(6 * m / e))) / e)
        f, df = lambda H: e * mpmath.sinh(H) - H - m, lambda H: e * mpmath.cosh(H) - 1
        H = _newton_from_above(f, df, x, _REF_DIGITS - 5)
        return mpmath.sign(M) * H


def _references(data, n_ref):
    """[(anomaly, M_reduced)] for the first n_ref pairs (M_reduced = 0 for hyperbolic sets)."""
    pairs = zip(data.M[:n_ref].tolist(), data.e[:n_ref].tolist())
    if data.hyperbolic:
        return [(_reference_hyperbolic(M, e), 0) for M, e in pairs]
    return [_reference_elliptic(M, e) for M, e in pairs]


def _worst_errors(x, refs, periodic):
    """(max relative error, max ulp error) of the finite x[i] against refs[i] = (anomaly, M_reduced).

    Relative errors are taken with respect to max(|anomaly|, |M_reduced|), ulps at the float nearest
    the anomaly.  With periodic=True (elliptic) a result on another revolution than the reference
    (some libraries return E in [0, 2 pi)) is compared with the reference shifted by the nearest
    multiple of 2 pi.  NaN if no result is finite."""
    rel, ulp = [], []
    with mpmath.workdps(40):
        for xi, (ref, m) in zip(x.tolist(), refs):
            if not math.isfinite(xi):
                continue
            if periodic:
                ref = ref + 2 * mpmath.pi * round((xi - float(ref)) / (2 * math.pi))
            err = abs(mpmath.mpf(xi) - ref)
            scale = max(abs(ref), abs(m))
            rel.append(float(err / scale) if scale else (0.0 if err == 0 else math.inf))
            ulp.append(float(err / math.ulp(abs(float(ref)))))
    return max(rel, default=math.nan), max(ulp, default=math.nan)


# --- methods --------------------------------------------------------------------------------------


def _orbits_method(threads):
    from orbits.core.twobody.kepler import eccentric_anomaly, hyperbolic_anomaly

    def solve(pair, hyperbolic):
        e, M = pair
        with orbits_threads(threads):
            return hyperbolic_anomaly(M, e) if hyperbolic else eccentric_anomaly(M, e)

    start = time.perf_counter()
    with orbits_threads(threads):  # loads (or compiles) the kernels: the first call's one-off cost
        eccentric_anomaly(0.5, 0.5), hyperbolic_anomaly(0.5, 1.5)
    setup = time.perf_counter() - start
    return Method(orbits_name(threads), solve, setup_seconds=setup, note=orbits_note(threads))


def _heyoka_method(threads):
    start = time.perf_counter()
    kep_e = peers.heyoka_kepler_solver(threads)
    setup = time.perf_counter() - start

    def solve(inputs, hyperbolic):
        return kep_e(inputs)

    name = "heyoka kepE (cfunc)" if threads == 1 else "heyoka kepE (all cores)"
    return Method(
        name,
        solve,
        lambda e, M: np.stack([e, M]),
        setup,
        f"{threads} thread{'s' if threads > 1 else ''}; elliptic only (NaN for e > 1)",
    )


def _rebound_method():
    m_to_e = peers.rebound_kepler_solver()

    def solve(pairs, hyperbolic):
        return m_to_e(pairs)

    return Method(
        "rebound.M_to_E",
        solve,
        lambda e, M: list(zip(e.tolist(), M.tolist())),
        note="per-call Python API, throughput from a subset",
        subset=PER_CALL_SUBSET,
    )


def _numpy_newton_method():
    def solve(pair, hyperbolic):
        return newton_hyperbolic(*pair) if hyperbolic else newton_elliptic(*pair)

    return Method(
        "numpy Newton", solve, note=f"plain baseline: abs step tol {NEWTON_TOL:g}, <= {NEWTON_MAX_ITER} iterations"
    )


def _exoplanet_core_method():
    import exoplanet_core

    def solve(pair, hyperbolic):
        if hyperbolic:
            return None
        e, M = pair
        sin_f, cos_f = exoplanet_core.kepler(M, e)
        with np.errstate(divide="ignore"):  # f = pi gives tan(f/2) = inf and E = pi
            return 2.0 * np.arctan(np.sqrt((1.0 - e) / (1.0 + e)) * sin_f / (1.0 + cos_f))

    return Method("exoplanet-core", solve, note="returns (sin f, cos f); E recovered from tan(f/2)")


def _pykep_method():
    import pykep

    def solve(pair, hyperbolic):
        e, M = pair
        return pykep.n2h_v(M, e) if hyperbolic else pykep.m2e_v(M, e)

    return Method("pykep", solve)


_METHODS = [
    ("orbits", lambda: _orbits_method(1)),
    ("orbits (all cores)", lambda: _orbits_method(cores())),
    ("orbits (NumPy)", lambda: _orbits_method(0)),
    ("heyoka kepE (cfunc)", lambda: _heyoka_method(1)),
    ("heyoka kepE (all cores)", lambda: _heyoka_method(cores())),
    ("rebound.M_to_E", _rebound_method),
    ("numpy Newton", _numpy_newton_method),
    ("exoplanet-core", _exoplanet_core_method),
    ("pykep", _pykep_method),
]


# --- measurement ----------------------------------------------------------------------------------


def _skipped(name, data, note):
    """Row of a method that was not run on data."""
    return BenchRow(name, data.name, 0, math.nan, math.nan, math.nan, math.nan, 0, "skipped", note)


def _measure(method, data, refs, repeats):
    """Time method on data (best of repeats) and compare its first results with refs."""
    n = len(data.e) if method.subset is None else min(len(data.e), method.subset)
    inputs = method.prepare(data.e[:n], data.M[:n])
    try:
        best, result = best_time(lambda: method.solve(inputs, data.hyperbolic), repeats)
    except Exception as exc:  # a peer failing on some input is a benchmark result, not a crash
        note = f"raised {type(exc).__name__}: {exc}".splitlines()[0][:200]
        nan = math.nan
        return BenchRow(method.name, data.name, n, nan, nan, nan, nan, 0, "raised", note, method.setup_seconds)
    if result is None:
        return _skipped(method.name, data, "equation not supported")
    result = np.asarray(result, dtype=float)
    max_rel, max_ulp = _worst_errors(result[: len(refs)], refs, not data.hyperbolic)
    return BenchRow(
        method.name,
        data.name,
        n,
        best,
        n / best,
        max_rel,
        max_ulp,
        int(np.count_nonzero(~np.isfinite(result))),
        "ok",
        method.note,
        method.setup_seconds,
    )


def bench_kepler(
    n_easy: int = 1_000_000,
    n_hard: int = 100_000,
    n_hyp: int = 100_000,
    n_ref: int = 2000,
    seed: int = 0,
    repeats: int = 3,
) -> list[BenchRow]:
    """Time and check every available Kepler solver on the "easy", "hard" and "hyperbolic" sets.

    easy: e ~ U[0, 0.99], M ~ U[0, 2 pi).  hard: e = 1 - 10**U(-9, -2), M alternately
    10**U(-12, -3) and pi - 10**U(-12, -3).  hyperbolic: e = 1 + 10**U(-9, 3), M = 10**U(-6, 6).
    Errors are measured against an mpmath reference on the first n_ref pairs of each set, relative to
    max(|E_ref|, |M reduced to [-pi, pi]|) for elliptic sets and to |H_ref| for the hyperbolic one;
    a method returning E in [0, 2 pi) is compared on its own revolution.  Timings exclude the
    one-off conversion of the inputs to the form each library takes.
    Returns one BenchRow per (method, data set), methods in a fixed order.
    """
    check_sizes(n_easy=n_easy, n_hard=n_hard, n_hyp=n_hyp, n_ref=n_ref, repeats=repeats)
    datasets = _datasets(n_easy, n_hard, n_hyp, seed)
    methods = load_methods(_METHODS)
    rows = []
    for data in datasets:
        refs = _references(data, min(n_ref, len(data.e)))
        for name, method, note in methods:
            row = _skipped(name, data, note) if method is None else _measure(method, data, refs, repeats)
            rows.append(row)
        if data.name == "easy":
            layout_refs = refs
    orbits = next((row for row in rows if row.method == "orbits"), None)
    if orbits is None:  # a benchmark of other methods only
        return rows
    if orbits.status == "skipped":
        return rows + [dataclasses.replace(orbits, dataset=f"easy, {name}") for name, _ in _LAYOUTS]
    return rows + _layout_rows(datasets[0], layout_refs, repeats)


#: (name, element offset of the output after the inputs in one buffer): the output right after an input
#: (consecutive allocations often lie so), one element further, and 64 bytes apart
_LAYOUTS = (("adjacent", 0), ("offset 8 B", 1), ("padded 64 B", 8))


def _layout_rows(data, refs, repeats):
    """orbits on one thread on the easy set with M, e and the output laid end to end in one buffer, as
    _LAYOUTS: the kernels loop over views, so the speed should not depend on where the arrays lie."""
    from orbits.core.twobody import _fast_kepler

    n = len(data.e)
    rows = []
    for name, offset in _LAYOUTS:
        buffer = np.empty(3 * n + 8)
        M, e, out = buffer[:n], buffer[n:2 * n], buffer[2 * n + offset:3 * n + offset]
        M[:], e[:] = data.M, data.e
        with orbits_threads(1):
            seconds, _ = best_time(lambda M=M, e=e, out=out: _fast_kepler.elliptic(0, n, M, e, out), repeats)
        max_rel, max_ulp = _worst_errors(out[: len(refs)], refs, True)
        rows.append(BenchRow("orbits", f"easy, {name}", n, seconds, n / seconds, max_rel, max_ulp,
                             int(np.count_nonzero(~np.isfinite(out))), "ok", "the kernel called directly, 1 thread"))
    return rows


# --- the table ------------------------------------------------------------------------------------


def _solves(row):
    """Whether the row timed a method that returned at least one finite anomaly."""
    return row.status == "ok" and row.n_nan < row.n


def format_rows(rows: Sequence[BenchRow]) -> str:
    """Plain-text table of bench_kepler, at most 80 columns: a section per data set, throughput (M/s), ratio
    to orbits on one thread on the same set (above 1: faster than orbits), worst relative and ulp errors,
    NaN count; the notes in a numbered list under the table."""
    reference = {r.dataset: r.throughput_per_s for r in rows if r.method == "orbits" and _solves(r)}
    table, texts = by_dataset(rows, reference, _kepler_stats)
    lines = plain_table(["method", "M/s", "ratio", "rel err", "ulp", "NaN"], table)
    legend = (
        f"M/s: millions of pairs solved per second. {RATIO_LEGEND} rel err, ulp: worst relative and ulp errors "
        "against mpmath. NaN: non-finite results."
    )
    return "\n".join(lines + [""] + wrap(legend, WIDTH) + notes(texts) + ["", f"Machine: {machine()}"])


def _kepler_stats(row):
    return [f"{row.max_rel_error:.2e}", sig(row.max_ulp)]


